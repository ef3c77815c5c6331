"""GraphBuilder ``sampling``: the agent steps over a gap between floors narrower than ``step_gap`` (default its max
climb), at any angle, and never over one as wide or wider, nor between floors further apart in height than its climb."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
import trimesh
from scipy.sparse import coo_matrix, csgraph
from scipy.spatial import cKDTree

from g2s_plugins._raycasting import AgentShape, RayCaster
from g2s_plugins.graph_builders import sampling

AGENT = AgentShape(radius=0.5, height=2.0, max_climb=0.4, max_slope_deg=45.0)


def two_slabs(gap: float, yaw: float, rise: float = 0.0, shift: float = 0.0) -> tuple[trimesh.Trimesh, np.ndarray]:
    """Two slabs 6 x 6 m, ``gap`` m apart along x, the second ``rise`` m higher, over ground 3 m lower, turned ``yaw``
    degrees and moved (shift, 0.6 shift) m; and the slabs' top middles (2, 3)."""
    boxes, middles = [], []
    for sign, top in ((-1.0, 0.0), (1.0, rise)):
        x0, x1 = sorted((sign * gap / 2, sign * (gap / 2 + 6.0)))
        boxes.append(trimesh.creation.box(extents=(6.0, 0.3, 6.0),
                                          transform=trimesh.transformations.translation_matrix(((x0 + x1) / 2, top - 0.15, 0.0))))
        middles.append(((x0 + x1) / 2, top, 0.0))
    boxes.append(trimesh.creation.box(extents=(16.0, 0.5, 8.0),
                                      transform=trimesh.transformations.translation_matrix((0.0, -3.25, 0.0))))
    mesh = trimesh.util.concatenate(boxes)
    turn = trimesh.transformations.rotation_matrix(math.radians(yaw), (0.0, 1.0, 0.0))
    turn[:3, 3] = (shift, 0.0, 0.6 * shift)
    mesh.apply_transform(turn)
    return mesh, np.asarray(middles) @ turn[:3, :3].T + turn[:3, 3]


def joined(mesh: trimesh.Trimesh, middles: np.ndarray, **params) -> bool:
    graph = sampling.build_sampled_graph(mesh, sampling.Params(method="grid", **params), AGENT)
    nodes = sorted(graph.nodes)
    index = {v: i for i, v in enumerate(nodes)}
    pos = np.array([graph.nodes[v]["pos"] for v in nodes])
    pairs = np.array([(index[a], index[b]) for a, b in graph.edges()]).reshape(-1, 2)
    _, part = csgraph.connected_components(coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])),
                                                      shape=(len(nodes), len(nodes))), directed=False)
    ends = cKDTree(pos).query(middles)[1]
    return bool(part[ends[0]] == part[ends[1]])


@pytest.mark.parametrize(("yaw", "shift"), [(0.0, 0.0), (20.0, 0.08), (45.0, 0.16)])
def test_a_gap_narrower_than_the_climb_is_stepped_over_at_any_angle(yaw: float, shift: float):
    # 0.3 m: under step_gap cos 11.25 degrees (0.39 m), so every turn steps over it; before step_gap none did.
    assert joined(*two_slabs(0.3, yaw, shift=shift))
    assert joined(*two_slabs(0.3, yaw, rise=0.2, shift=shift))


def test_a_gap_just_under_step_gap_is_stepped_over_off_the_axes():
    # 0.38 m turned 20 degrees: 2.5 degrees off the nearest of the rule's axes (every 22.5), read 0.381 m across.
    assert joined(*two_slabs(0.38, 20.0, shift=0.08))


@pytest.mark.parametrize(("yaw", "shift"), [(0.0, 0.0), (20.0, 0.08), (45.0, 0.16)])
def test_a_gap_as_wide_as_step_gap_or_between_floors_over_the_climb_apart_is_never_crossed(yaw: float, shift: float):
    assert not joined(*two_slabs(0.4, yaw, shift=shift))
    assert not joined(*two_slabs(0.45, yaw, shift=shift))
    assert not joined(*two_slabs(0.2, yaw, rise=0.5, shift=shift))


def test_step_gap_zero_keeps_the_crack_rule_alone():
    # The paper preset's setting: a gap of 0.3 m parts the slabs, as before the rule.
    assert not joined(*two_slabs(0.3, 20.0), step_gap=0.0)
    assert joined(*two_slabs(0.3, 20.0), step_gap=None)


def slabs_over_a_floor(gap: float, depth: float, yaw: float = 20.0, shift: float = 0.08) -> tuple[trimesh.Trimesh, np.ndarray]:
    """:func:`two_slabs` with a floor ``depth`` m under their tops in place of the ground 3 m down."""
    mesh, middles = two_slabs(gap, 0.0)
    slabs = [part for part in mesh.split(only_watertight=False) if part.bounds[0][1] > -1.0]
    below = trimesh.creation.box(extents=(16.0, 0.2, 8.0),
                                 transform=trimesh.transformations.translation_matrix((0.0, -depth - 0.1, 0.0)))
    mesh = trimesh.util.concatenate([*slabs, below])
    turn = trimesh.transformations.rotation_matrix(math.radians(yaw), (0.0, 1.0, 0.0))
    turn[:3, 3] = (shift, 0.0, 0.6 * shift)
    mesh.apply_transform(turn)
    return mesh, middles @ turn[:3, :3].T + turn[:3, 3]


@pytest.mark.parametrize("depth", [0.42, 0.45, 0.5])
def test_a_gap_under_step_gap_is_stepped_over_however_deep_the_floor_under_it(depth: float):
    # review54 MED 2: a floor deeper than the climb but within the ground probes' reach kept the probes over the gap
    # on it, and the rise failed the step rule (parted at 0.42-0.5 m down, joined at 0.52 m and 3 m).
    assert joined(*slabs_over_a_floor(0.3, depth))
    assert not joined(*slabs_over_a_floor(0.45, depth))


def test_a_floor_within_the_climb_under_a_channel_wider_than_step_gap_is_walked_as_a_step():
    assert joined(*slabs_over_a_floor(0.6, 0.3))


@pytest.mark.parametrize("depth", [0.45, 3.0])
def test_a_point_beside_a_gap_under_step_gap_fits_however_deep_the_floor_under_it(depth: float):
    # The ledge probes (agent_fits) follow the same rule: a point 0.3 m from a 0.3 m gap's edge fits over a floor
    # 0.45 m down as over one 3 m down; beside a 0.45 m gap it is at a ledge.
    agent = replace(AGENT, step_gap=AGENT.max_climb)
    for gap, fits in ((0.3, True), (0.45, False)):
        mesh, _ = slabs_over_a_floor(gap, depth, yaw=0.0, shift=0.0)
        point = np.array([[-gap / 2 - 0.3, 0.0, 0.0]])
        assert bool(sampling.agent_fits(RayCaster(mesh), point, agent, clearance=0.5)[0]) is fits
