"""GraphBuilder ``sampling``: the ledge test steps over cracks (gratings' slots) as the walk test does, not over gaps."""

from __future__ import annotations

import math

import networkx as nx
import numpy as np
import pytest
import trimesh

from g2s_plugins._raycasting import AgentShape, RayCaster, all_hits_down
from g2s_plugins.graph_builders import sampling

AGENT = AgentShape(radius=0.5, height=2.0, max_climb=0.4, max_slope_deg=45.0)
CRACK_STEP = AGENT.radius / 8.0  # 0.0625 m: a gap narrower than twice this is a crack


def box(x0: float, x1: float, y0: float, y1: float, z0: float, z1: float) -> trimesh.Trimesh:
    return trimesh.creation.box(
        extents=(x1 - x0, y1 - y0, z1 - z0),
        transform=trimesh.transformations.translation_matrix(((x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2)),
    )


def split_floor(gap: float) -> trimesh.Trimesh:
    """Two 0.2 m slabs, 10 x 10 m in all, ``gap`` m apart along x = 0, over nothing."""
    return trimesh.util.concatenate([box(-5.0, -gap / 2, -0.2, 0.0, -5.0, 5.0), box(gap / 2, 5.0, -0.2, 0.0, -5.0, 5.0)])


def fits(mesh: trimesh.Trimesh, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    rejected = np.zeros(len(points), dtype=np.int8)
    ok = sampling.agent_fits(RayCaster(mesh), points, AGENT, AGENT.radius, rejected=rejected)
    return ok, rejected


@pytest.mark.parametrize(("gap", "crossed"), [(0.02, True), (0.05, True), (0.11, True), (0.15, False), (0.4, False)])
def test_a_ledge_probe_over_a_crack_stands_on_the_floor_beside_it(gap: float, crossed: bool):
    # Points a clearance west of the gap's middle: their east ledge probe falls into it.
    points = np.array([[-AGENT.radius, 0.0, z] for z in (-1.0, 0.0, 1.3)])
    ok, rejected = fits(split_floor(gap), points)
    assert ok.tolist() == [crossed] * 3
    assert gap < 2 * CRACK_STEP if crossed else gap > 2 * CRACK_STEP
    expected = 0 if crossed else sampling.REJECTED_BY.index("ledge")
    assert rejected.tolist() == [expected] * 3


def test_a_crack_beside_a_step_is_no_floor_to_stand_on():
    # A 2 cm crack whose far side is 1 m lower (beyond what the ledge test takes for ground at the clearance: a
    # step or the max slope, 0.5 m here): the probe's two sides do not both find ground, so the edge stays a ledge.
    mesh = trimesh.util.concatenate([box(-5.0, -0.01, -0.2, 0.0, -5.0, 5.0), box(0.01, 5.0, -1.2, -1.0, -5.0, 5.0)])
    ok, rejected = fits(mesh, np.array([[-AGENT.radius, 0.0, 0.0]]))
    assert not ok[0] and rejected[0] == sampling.REJECTED_BY.index("ledge")


def grating(degrees: float, slot: float = 0.02, slat: float = 0.08, size: float = 4.0) -> trimesh.Trimesh:
    """A square grating ``size`` m across over nothing: slats ``slat`` m wide, ``slot`` m apart, turned by ``degrees``."""
    slats = []
    z = -size / 2
    while z < size / 2 - 1e-9:
        slats.append(box(-size / 2, size / 2, -0.05, 0.0, z, min(z + slat, size / 2)))
        z += slat + slot
    mesh = trimesh.util.concatenate(slats)
    mesh.apply_transform(trimesh.transformations.rotation_matrix(math.radians(degrees), [0.0, 1.0, 0.0]))
    return mesh


@pytest.mark.parametrize("degrees", [0.0, 22.0, 45.0])
@pytest.mark.parametrize("slot", [0.02, 0.03])
def test_every_point_of_a_turned_grating_a_clearance_inside_its_outline_fits(degrees: float, slot: float):
    mesh = grating(degrees, slot)
    xz = np.stack(np.meshgrid(np.linspace(-1.9, 1.9, 23), np.linspace(-1.9, 1.9, 23)), axis=-1).reshape(-1, 2)
    _, points, _ = all_hits_down(RayCaster(mesh), xz, 1.0)
    points = points[points[:, 1] > -0.01]  # the slats' tops, not their undersides
    turn = math.radians(degrees)
    # The points' place in the grating's own frame, and their distance to its outline.
    own = np.column_stack([points[:, 0] * math.cos(turn) - points[:, 2] * math.sin(turn),
                           points[:, 0] * math.sin(turn) + points[:, 2] * math.cos(turn)])
    inside = 2.0 - np.abs(own).max(axis=1)
    ok, _ = fits(mesh, points)
    assert len(points) > 250
    assert ok[inside > AGENT.radius + 0.05].all()
    assert not ok[inside < AGENT.radius - 0.05].any()


def test_rejected_names_the_first_check_a_point_failed():
    # A low slab over one part of the floor (head room) and a wall (clearance); the open middle fits.
    mesh = trimesh.util.concatenate([box(-5, 5, -0.2, 0.0, -5, 5), box(-5, -3, 1.5, 1.7, -5, 5), box(3, 3.2, 0.0, 3.0, -5, 5)])
    points = np.array([[-4.0, 0.0, 0.0], [2.8, 0.0, 0.0], [0.0, 0.0, 0.0], [-0.5, 0.0, 4.7]])
    ok, rejected = fits(mesh, points)
    assert ok.tolist() == [False, False, True, False]
    assert [sampling.REJECTED_BY[code] for code in rejected] == ["head room", "wall", "fits", "ledge"]


@pytest.mark.parametrize(("slat", "slot", "degrees"), [(0.03, 0.025, 0.0), (0.03, 0.025, 30.0), (0.04, 0.043, 0.0),
                                                      (0.04, 0.043, 15.0), (0.04, 0.043, 45.0), (0.05, 0.06, 0.0)])
def test_every_grid_line_over_a_grating_takes_a_candidate_on_its_bars(slat: float, slot: float, degrees: float):
    # Round 36's gratings (bars 30-50 mm, gaps 25-60 mm): a line through a slot meets no bar, and before the crack
    # lines a whole row of lines met slots alike. Slots the crack rule crosses along x or z: every line over the
    # grating's inside takes a candidate on its top (y = 0), and no other candidate is added.
    mesh = trimesh.util.concatenate([grating(degrees, slot, slat, size=8.0), box(-6.0, 6.0, -4.7, -4.5, -6.0, 6.0)])
    surface = sampling.walkable_surface(mesh, AGENT)
    plain, _ = sampling._grid_candidates(surface, 1.0)
    with_cracks, _ = sampling._grid_candidates(surface, 1.0, AGENT)
    lines = np.unique(np.round(with_cracks[:, [0, 2]], 6), axis=0)
    turn = math.radians(degrees)
    own = np.column_stack([lines[:, 0] * math.cos(turn) - lines[:, 1] * math.sin(turn),
                           lines[:, 0] * math.sin(turn) + lines[:, 1] * math.cos(turn)])
    inside = int((np.abs(own).max(axis=1) < 4.0 - 0.1).sum())
    on_top = lambda points: int((np.abs(points[:, 1]) < 0.01).sum())
    assert on_top(plain) < 0.8 * inside
    assert on_top(with_cracks) >= inside
    assert len(with_cracks) - len(plain) == on_top(with_cracks) - on_top(plain)


@pytest.mark.parametrize(("gap", "bridged"), [(0.1, True), (0.4, False)])
def test_a_grid_line_in_a_gap_wider_than_a_crack_takes_no_candidate(gap: float, bridged: bool):
    # Two slabs 10 m in all, apart along x: the grid, centred and moved by its offset, has a column of lines at
    # x = 0.2549 in the gap, 10 of them over the slabs' z extent. A gap under twice the crack step (0.125 m) is a crack; the ledge probes decide the rest.
    offset = sampling.GRID_OFFSET[0]
    mesh = trimesh.util.concatenate([box(-5.0, offset - gap / 2, -0.2, 0.0, -5.0, 5.0),
                                     box(offset + gap / 2, 5.0, -0.2, 0.0, -5.0, 5.0)])
    surface = sampling.walkable_surface(mesh, AGENT)
    plain, _ = sampling._grid_candidates(surface, 1.0)
    with_cracks, _ = sampling._grid_candidates(surface, 1.0, AGENT)
    in_gap = lambda points: int((np.abs(points[:, 0] - offset) < gap / 2).sum())
    assert in_gap(plain) == 0
    assert in_gap(with_cracks) == (10 if bridged else 0)


@pytest.mark.parametrize("depth", [0.45, 0.6, 0.9, 4.5])
def test_a_grating_bridge_over_a_floor_within_the_max_slope_takes_its_samples(depth: float):
    # A 10 x 4 m bridge of 50 mm bars and 50 mm slots along x, every grid line through a slot, between two decks
    # level with it, over a floor `depth` m down. Before the slope of the neighbour's own floor set how far a line's
    # floor may lie from it, a floor 0.4-1 m under the grating (within the max slope over the spacing) passed for the
    # grating's own and no line was asked: no samples on the bridge, the decks apart (the review's MED 1).
    bars = [box(-5.0, 5.0, -0.05, 0.0, z, z + 0.05) for z in np.arange(-2.0, 1.96, 0.1)]
    decks = [box(-12.0, -5.0, -0.05, 0.0, -2.0, 2.0), box(5.0, 12.0, -0.05, 0.0, -2.0, 2.0)]
    mesh = trimesh.util.concatenate([*bars, *decks, box(-12.0, 12.0, -depth - 0.2, -depth, -6.0, 6.0)])
    graph = sampling.build_sampled_graph(mesh, sampling.Params(method="grid"), AGENT)
    top = [n for n in graph if graph.nodes[n]["pos"][1] > -0.3]
    on_bridge = [n for n in top if abs(graph.nodes[n]["pos"][0]) < 4.5]
    assert len(on_bridge) >= 20
    assert nx.number_connected_components(graph.subgraph(top)) == 1
