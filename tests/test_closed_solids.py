"""Ground inside closed solids, and open ground beside them, by the one rule the sampling builder and the
disconnected-areas warning share (:func:`g2s_plugins._raycasting.closed_solid_holds`): one hand-checkable level of
each kind of ``benchmarks/closed_solid_kinds.py``, faces in one plane included."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh

from g2s_core.config import AgentConfig
from g2s_plugins._raycasting import AgentShape, RayCaster, _flush_pairs, _flush_pairs_of
from g2s_plugins.area_gaps import shut_in
from g2s_plugins.graph_builders.sampling import inside_closed_solids
from g2s_plugins.samples.castle import castle
from tests.conftest import benchmark
from tests.test_families import SMALL_CASTLE

AGENT = AgentConfig()


def boxes(*extents: tuple[float, float, float, float, float, float]) -> list[trimesh.Trimesh]:
    """Closed boxes over [x0, x1] x [y0, y1] x [z0, z1], wound outward."""
    return [trimesh.creation.box(bounds=[(x0, y0, z0), (x1, y1, z1)]) for x0, x1, y0, y1, z0, z1 in extents]


def cavity(x0: float, x1: float, y0: float, y1: float, z0: float, z1: float, wall: float) -> list[trimesh.Trimesh]:
    """A closed room with no way in: the outer box and, ``wall`` metres inside it, the cavity wound inward."""
    inner = trimesh.creation.box(bounds=[(x0 + wall, y0 + wall, z0 + wall), (x1 - wall, y1 - wall, z1 - wall)])
    return [*boxes((x0, x1, y0, y1, z0, z1)), trimesh.Trimesh(inner.vertices, inner.faces[:, ::-1])]


FLOOR = (-10.0, 10.0, -0.3, 0.0, -10.0, 10.0)
WALL = (-10.0, 10.0, 0.0, 3.2, -0.3, 0.0)
"""A wall slab along x whose north face is z = 0."""

CRATE, OPEN, BESIDE = (1.5, 0.0, 1.5), (1.5, 0.0, 5.0), (-4.0, 0.0, 2.0)
"""A point on the floor inside the 3 x 3 m crate at x, z in [0, 3] (when there is one), one north of it and one
west of it, both in the open."""

LEVELS = {
    "touching a wall (one plane)": (boxes(FLOOR, WALL, (0, 3, 0, 2.5, 0, 3)),
                                    {CRATE: True, (1.5, 0.0, 0.25): True, OPEN: False, BESIDE: False}),
    "a quarter in a wall": (boxes(FLOOR, WALL, (0, 3, 0, 2.5, -0.75, 2.25)), {(1.5, 0.0, 1.0): True, OPEN: False}),
    "flush with the wall's back": (boxes(FLOOR, WALL, (0, 3, 0, 2.5, -0.3, 3)), {CRATE: True, OPEN: False}),
    "through the floor, bottoms flush": (boxes(FLOOR, (0, 3, -0.3, 2.5, 0, 3)), {CRATE: True, OPEN: False}),
    "crate on a crate, flush": (boxes(FLOOR, (0, 3, 0, 2.5, 0, 3), (0, 3, 2.5, 5, 0, 3)),
                                {CRATE: True, (1.5, 2.5, 1.5): True, OPEN: False}),
    "crate on a crate, shifted": (boxes(FLOOR, (0, 3, 0, 2.5, 0, 3), (1, 4, 2.5, 5, 1, 4)),
                                  {CRATE: True, (2.5, 2.5, 2.5): True, (0.5, 2.5, 0.5): False, OPEN: False}),
    "pillar in a wall under a ceiling": (boxes(FLOOR, WALL, (-10, 10, 3.2, 3.5, -10, 10), (0, 3, 0, 3.2, -0.3, 2.7)),
                                         {CRATE: True, OPEN: False, BESIDE: False}),
    "room in a room": ([*boxes(FLOOR), *cavity(-8, 8, 0, 6, -8, 8, 0.2), *cavity(-3, 3, 0.2, 3.5, -3, 3, 0.2)],
                       {(0.0, 0.4, 0.0): False, (5.0, 0.2, 5.0): False}),
    "four thin walls, flush at the corners, a crate against one": (
        boxes(FLOOR, (0, 0.1, 0, 3, 0, 10), (9.9, 10, 0, 3, 0, 10), (0, 10, 0, 3, 0, 0.1), (0, 10, 0, 3, 9.9, 10),
              (3, 6, 0, 2.5, 0.1, 3)),
        {(5.0, 0.0, 6.0): False, (1.0, 0.0, 5.0): False, (0.05, 0.0, 5.0): True, (4.5, 0.0, 1.5): True}),
}
"""Level -> (its closed parts, ground points (x, y, z) and whether each lies inside a solid)."""


def turned(name: str, yaw_deg: float) -> tuple[list[trimesh.Trimesh], dict[tuple[float, ...], bool]]:
    """Level ``name`` turned by ``yaw_deg`` about the vertical through the origin, points and all."""
    parts, answers = LEVELS[name]
    turn = trimesh.transformations.rotation_matrix(np.radians(yaw_deg), [0.0, 1.0, 0.0])
    points = trimesh.transform_points(np.array(list(answers), dtype=np.float64), turn)
    return [part.copy().apply_transform(turn) for part in parts], dict(zip(map(tuple, points), answers.values()))


for yaw in (22.0, 45.0):  # which of two faces in one plane the intersector reports first changes with the turn
    LEVELS[f"touching a wall, turned {yaw:g}"] = turned("touching a wall (one plane)", yaw)


@pytest.mark.parametrize("name", list(LEVELS))
def test_both_rules_tell_ground_inside_solids_from_open_ground(name):
    parts, answers = LEVELS[name]
    points = np.array(list(answers), dtype=np.float64)
    expected = list(answers.values())
    caster = RayCaster(trimesh.util.concatenate(parts))
    assert inside_closed_solids(caster, points, AgentShape.from_config(AGENT)).tolist() == expected
    assert shut_in(caster, points, AGENT).tolist() == expected


def test_a_building_entered_by_a_door_is_open_inside():
    # walls one closed body (a ring cut by a door 1.2 m wide) under a roof slab resting on them, flush outside
    kinds = benchmark("closed_solid_kinds")
    walls = kinds.ring(0.0, 10.0, 0.0, 10.0, 0.3, 0.0, 3.0, door=(4.0, 5.2))
    caster = RayCaster(trimesh.util.concatenate([*boxes(FLOOR, (0, 10, 3, 3.3, 0, 10)), walls]))
    points = np.array([(5.0, 0.0, 5.0), (4.6, 0.0, 0.15), (0.15, 0.0, 5.0), (5.0, 0.0, 12.0)])
    expected = [False, False, True, False]  # the room, the doorway, under the west wall, outside
    assert inside_closed_solids(caster, points, AgentShape.from_config(AGENT)).tolist() == expected
    assert shut_in(caster, points, AGENT).tolist() == expected


@pytest.mark.parametrize("yaw_deg", [0.0, 22.0, 45.0])
def test_a_building_with_a_crate_flush_with_a_wall_and_a_pillar_flush_with_the_roof(yaw_deg):
    # the building above, a crate in its north-west corner against two walls' inner faces and a pillar from the
    # floor to the roof's bottom: faces in one plane at both, seen along rays turned off the axes
    kinds = benchmark("closed_solid_kinds")
    walls = kinds.ring(0.0, 10.0, 0.0, 10.0, 0.3, 0.0, 3.0, door=(4.0, 5.2))
    parts = [*boxes(FLOOR, (0, 10, 3, 3.3, 0, 10), (0.3, 3.3, 0, 2.5, 6.7, 9.7), (6, 7, 0, 3, 6, 7)), walls]
    turn = trimesh.transformations.rotation_matrix(np.radians(yaw_deg), [0.0, 1.0, 0.0])
    caster = RayCaster(trimesh.util.concatenate([part.apply_transform(turn) for part in parts]))
    points = trimesh.transform_points(np.array(
        [(5.0, 0.0, 4.0), (1.8, 0.0, 8.2), (0.4, 0.0, 9.6), (6.5, 0.0, 6.5), (6.1, 0.0, 6.9), (4.6, 0.0, 0.15)]), turn)
    expected = [False, True, True, True, True, False]  # the room, the crate (middle, corner), the pillar (middle,
    # corner), the doorway
    assert inside_closed_solids(caster, points, AgentShape.from_config(AGENT)).tolist() == expected
    assert shut_in(caster, points, AGENT).tolist() == expected


def test_bodies_touching_along_an_edge_or_in_a_plane_stay_closed_and_apart():
    stacked = boxes((0, 1, 0, 1, 0, 1), (0, 1, 1, 2, 0, 1))  # the whole face shared, corner for corner
    side_by_side = boxes((0, 1, 0, 1, 0, 1), (1, 2, 0, 1, 0, 1))
    corner = boxes((-0.2, 0, 0, 3, -0.2, 10), (-0.2, 10, 0, 3, -0.2, 0))  # wall slabs overlapping, outer faces flush
    for parts in (stacked, side_by_side, corner):
        scene = RayCaster(trimesh.util.concatenate(parts)).scene
        assert scene.bodies.reshape(2, 12).min(axis=1).tolist() == scene.bodies.reshape(2, 12).max(axis=1).tolist()
        assert len(set(scene.bodies.tolist())) == 2 and scene.closed.all()
        starts, partner = scene.flush.whole
        face = np.repeat(np.arange(24), np.diff(starts))
        assert len(face) and (face // 12 != partner // 12).all()  # faces in one plane paired across the bodies only


def single_sided_wall_with_a_crate() -> list[trimesh.Trimesh]:
    """A wall quad of two triangles with no back (no closed body) along z = 0 and a crate whose side touches it."""
    quad = trimesh.Trimesh([(-5, 0, 0), (5, 0, 0), (5, 3, 0), (-5, 3, 0)], [(0, 2, 1), (0, 3, 2)], process=False)
    return [*boxes(FLOOR, (0, 3, 0, 2.5, 0, 3)), quad]


def flush_meshes() -> dict[str, trimesh.Trimesh]:
    """Meshes with faces in one plane of every kind :func:`_flush_pairs` pairs: crates on walls, crates on crates,
    turned walls, a roof on walls, a single-sided quad, the castle sample."""
    kinds = benchmark("closed_solid_kinds")
    walls = kinds.ring(0.0, 10.0, 0.0, 10.0, 0.3, 0.0, 3.0, door=(4.0, 5.2))
    meshes = {name: trimesh.util.concatenate(parts) for name, (parts, _) in LEVELS.items()}
    meshes["roof on walls, crate in a corner"] = trimesh.util.concatenate(
        [*boxes(FLOOR, (0, 10, 3, 3.3, 0, 10), (0.3, 3.3, 0, 2.5, 6.7, 9.7), (6, 7, 0, 3, 6, 7)), walls])
    meshes["single-sided quad"] = trimesh.util.concatenate(single_sided_wall_with_a_crate())
    meshes["castle"] = castle(seed=1, **SMALL_CASTLE).mesh
    return meshes


@pytest.mark.parametrize("name, mesh", list(flush_meshes().items()))
def test_the_flush_partners_of_a_few_faces_are_the_whole_meshs(name, mesh):
    # the partners found for the faces asked alone (the warning's few rays) against the whole mesh's pairs, for
    # every paired face and others in random groups, and with every plane's sum colliding (planes told apart by keys)
    scene = RayCaster(mesh).scene
    triangles, bodies = scene.triangles, scene.bodies
    face, partner = _flush_pairs(triangles, bodies)
    assert len(face), name  # every mesh here has faces in one plane to pair
    key, length, hashed = scene.flush.plane_keys
    rng = np.random.default_rng(0)
    paired, anyone = rng.permutation(np.unique(face)), rng.permutation(len(triangles))
    groups = [*np.array_split(paired, min(24, len(paired))), *np.array_split(anyone, min(8, len(anyone)))]
    for asked in [np.sort(group) for group in groups]:
        for sums in (hashed, np.zeros_like(hashed)):
            alone = _flush_pairs_of(asked, triangles, bodies, key, length, sums, budget=len(triangles) ** 2)
            wanted = np.isin(face, asked)
            assert np.array_equal(alone[0], face[wanted]) and np.array_equal(alone[1], partner[wanted]), name
    # the scene's answer, one face at a time while the budget lasts, then from the whole mesh's pairs once built:
    # the same partners and patches
    flush = RayCaster(mesh.copy()).scene.flush
    asked = np.unique(face[:: max(1, len(face) // 20)])
    read = [flush.of(asked[i : i + 1]) for i in range(len(asked))]
    assert 0 < flush.spent <= len(triangles) or "whole" in flush.__dict__
    assert len(flush.whole[1]) == len(partner)
    for one, first in zip(asked, read):
        for part, from_whole in zip(first, flush.of(np.array([one]))):
            assert np.array_equal(part, from_whole), name


def test_a_few_faces_do_not_build_the_whole_meshs_pairs():
    # a crate against each of 40 wall slabs along a floor: one crate's side asked pairs with its wall's face alone
    slabs = [(10 * i, 10 * i + 8, 0, 3, -0.3, 0) for i in range(40)]
    crates = [(10 * i + 2, 10 * i + 5, 0, 2.5, 0, 3) for i in range(40)]
    flush = RayCaster(trimesh.util.concatenate(boxes(*slabs, *crates))).scene.flush
    side = np.flatnonzero(np.isclose(flush.triangles[:, :, 2], 0).all(axis=1) & (flush.bodies >= 40))[:1]
    starts, partner, patch = flush.of(side)
    assert "whole" not in flush.__dict__ and 0 < flush.spent <= len(flush.triangles)
    assert starts.tolist() == [0, 2] and (flush.bodies[partner] == flush.bodies[side] - 40).all()
