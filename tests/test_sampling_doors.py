"""The sampling builder's edges keep the agent's width: a door or a slot narrower than the agent is not crossed."""

from __future__ import annotations

import networkx as nx
import numpy as np
import pytest
import trimesh

from g2s_core.config import AgentConfig
from g2s_core.model import RunContext
from g2s_plugins._raycasting import (AgentShape, RayCaster, _slices_meet_bands, bands_meet_walls, box_pairs,
                                     walks_in_batch)
from g2s_plugins.graph_builders import sampling

AGENT = AgentConfig(radius=0.5, height=2.0, max_climb=0.4, max_slope=45.0)
"""The presets' agent: 1.0 m wide; spacing 1 m, clearance 0.5 m, side lines 0.45 m out by default."""


def box(lo, hi) -> trimesh.Trimesh:
    lo, hi = np.asarray(lo, dtype=float), np.asarray(hi, dtype=float)
    return trimesh.creation.box(extents=hi - lo, transform=trimesh.transformations.translation_matrix((lo + hi) / 2))


def two_rooms(door: float) -> trimesh.Trimesh:
    """A 16 x 12 m floor split at x = 0 by a 0.2 m wall, 3 m high, that runs past the floor (no way round), with one
    door ``door`` m wide centred on z = 0."""
    return trimesh.util.concatenate([
        box((-8, -0.2, -6), (8, 0, 6)),
        box((-0.1, 0, -7), (0.1, 3, -door / 2)),
        box((-0.1, 0, door / 2), (0.1, 3, 7)),
    ])


def rooms_joined(mesh: trimesh.Trimesh) -> bool:
    """The samples nearest the two rooms' middles, (-4, 0, 0) and (4, 0, 0), are in one part of the preset's graph."""
    context = RunContext(mesh=mesh, agent=AGENT, centre=np.asarray(mesh.bounds).mean(axis=0))
    graph = sampling.g2s_build_graph(mesh=mesh, params=sampling.Params(method="grid"), context=context)
    pos = np.array([graph.nodes[n]["pos"] for n in graph])
    nodes = list(graph)
    west, east = (nodes[int(np.argmin(np.linalg.norm(pos - (x, 0.0, 0.0), axis=1)))] for x in (-4.0, 4.0))
    return nx.has_path(graph, west, east)


@pytest.mark.parametrize("door, joined", [(0.8, False), (1.2, True)])
def test_a_door_narrower_than_the_agent_splits_the_rooms(door: float, joined: bool) -> None:
    # Before the side lines a 2 m grid edge crossed the 0.8 m door 0.33 m from its jambs: one area, no warning,
    # where the navmesh route gives two (docs/sampling.md, "Doors narrower than the agent").
    assert rooms_joined(two_rooms(door)) is joined


def test_the_side_lines_stop_a_walk_through_a_slot_and_not_beside_rising_ground() -> None:
    # Hand-checkable: walks along x through the 0.8 m and 1.2 m doors' middles, 1 m either side of the wall.
    agent = AgentShape.from_config(AGENT)
    starts, ends = np.array([[-1.0, 0.0, 0.0]]), np.array([[1.0, 0.0, 0.0]])
    narrow, wide = RayCaster(two_rooms(0.8)), RayCaster(two_rooms(1.2))
    assert walks_in_batch(narrow, starts, ends, agent, 0.25)[0].tolist() == [True]  # a line passes 0.4 m from a jamb
    assert walks_in_batch(narrow, starts, ends, agent, 0.25, half_width=0.45)[0].tolist() == [False]
    assert walks_in_batch(wide, starts, ends, agent, 0.25, half_width=0.45)[0].tolist() == [True]  # 0.6 m from each
    # A walk towards the foot of a 44-degree slope, ending 2 cm from it, for an agent 0.8 m tall: its side line
    # 0.45 m out, 0.4 m up, meets the slope near its end (0.415 m high 0.43 m past the foot): walkable ground rising
    # beside the walk, not a wall, as the agent checks' wall rays take it.
    low = AgentShape(radius=0.5, height=0.8, max_climb=0.2, max_slope_deg=45.0)
    rise = 3.0 * np.tan(np.radians(44.0))
    slope = trimesh.Trimesh(vertices=[[-3, 0, 0.3], [3, 0, 0.3], [3, rise, 3.3], [-3, rise, 3.3]],
                            faces=[[0, 2, 1], [0, 3, 2]])
    hillside = RayCaster(trimesh.util.concatenate([box((-3, -0.2, -3), (3, 0, 0.3)), slope]))
    starts, ends = np.array([[-2.0, 0.0, 0.0]]), np.array([[2.0, 0.0, 0.28]])
    side = 0.45 * np.array([-0.28, 0.0, 4.0]) / np.hypot(0.28, 4.0)
    hits = hillside.first_hits(starts + side + [0.0, 0.4, 0.0], ends - starts)
    assert hits.distance[0] < np.linalg.norm(ends - starts) and hillside.walkable_faces(hits.face, 45.0).tolist() == [True]
    assert walks_in_batch(hillside, starts, ends, low, 0.25, half_width=0.45)[0].tolist() == [True]


def opening_with_post(slot: float, post: float) -> trimesh.Trimesh:
    """:func:`two_rooms`' wall with an opening of two ``slot`` m slots either side of a ``post`` m square post at
    the origin."""
    half = slot + post / 2
    return trimesh.util.concatenate([
        box((-8, -0.2, -6), (8, 0, 6)),
        box((-0.1, 0, -7), (0.1, 3, -half)),
        box((-0.1, 0, half), (0.1, 3, 7)),
        box((-post / 2, 0, -post / 2), (post / 2, 3, post / 2)),
    ])


@pytest.mark.parametrize("slot, post, joined", [(0.8, 0.2, False), (0.8, 0.1, False), (1.4, 0.2, True)])
def test_a_post_between_the_edge_lines_splits_slots_narrower_than_the_agent(slot: float, post: float,
                                                                             joined: bool) -> None:
    # Before the band test the 0.8 m slots' grid edges passed the post between two of their lines 0.45 m apart:
    # one area (docs/sampling.md, "A post between the edge's lines").
    assert rooms_joined(opening_with_post(slot, post)) is joined


def test_the_band_test_finds_a_post_that_no_line_meets() -> None:
    # Hand-checkable: a walk along x at z = 0.25 past the 0.2 m post (z -0.1 to 0.1): its line at z = 0.25 and side
    # lines at -0.2 and 0.7 all pass through the 0.8 m slots (jambs at z = +-0.9); the post lies between two of them.
    agent = AgentShape.from_config(AGENT)
    caster = RayCaster(opening_with_post(0.8, 0.2))
    starts, ends = np.array([[-1.0, 0.0, 0.25]]), np.array([[1.0, 0.0, 0.25]])
    lifted, along, side = starts + [0.0, 1.0, 0.0], ends - starts, np.array([[0.0, 0.0, 0.45]])
    for offset in (0.0, 0.45, -0.45):
        assert caster.first_hits(lifted + [0.0, 0.0, offset], along).distance[0] > 2.0
    assert bands_meet_walls(caster, lifted, along, side, 45.0).tolist() == [True]
    assert walks_in_batch(caster, starts, ends, agent, 0.25, half_width=0.45)[0].tolist() == [False]
    through_wall = starts + [0.0, 0.0, 3.0], ends + [0.0, 0.0, 3.0]  # the lines find the wall, and so does the band
    assert walks_in_batch(caster, *through_wall, agent, 0.25, half_width=0.45)[0].tolist() == [False]
    assert bands_meet_walls(caster, through_wall[0] + [0.0, 1.0, 0.0], along, side, 45.0).tolist() == [True]
    # along the wall in the west room, the band's near side 0.5 m from its face
    beside, north, east = np.array([[-1.0, 1.0, -3.0]]), np.array([[0.0, 0.0, 2.0]]), np.array([[0.4, 0.0, 0.0]])
    assert bands_meet_walls(caster, beside, north, east, 45.0).tolist() == [False]


def test_a_face_meets_the_band_only_passing_through_it() -> None:
    # The band: 2 m along x from the origin, 0.45 m either side, in the plane y = 0; a thin vertical triangle at
    # (x, z) spanning y -1..1 meets it inside the rectangle; one whose top edge lies in the plane (a box's side
    # under a walkable top at the lifted height) does not pass through it.
    origin, along, side = np.zeros((1, 3)), np.array([[2.0, 0.0, 0.0]]), np.array([[0.0, 0.0, 0.45]])

    def upright(x: float, z: float, top: float = 1.0) -> np.ndarray:
        return np.array([[[x, -1.0, z], [x, top, z], [x, -1.0, z + 0.1]]])

    for x, z, meets in [(1.0, 0.0, True), (1.0, 0.3, True), (0.05, -0.3, True), (1.0, 0.5, False), (2.1, 0.0, False),
                        (-0.1, 0.0, False), (1.0, -0.6, False)]:
        assert _slices_meet_bands(upright(x, z), origin, along, side, 1e-4).tolist() == [meets]
    assert _slices_meet_bands(upright(1.0, 0.0, top=0.0), origin, along, side, 1e-4).tolist() == [False]


def test_box_pairs_finds_every_overlapping_pair_in_2d_and_3d():
    # 2-D: unit squares at x = 0, 2, 4 against one box spanning x 1.5..2.5 and one far away
    lo = np.array([[0.0, 0.0], [2.0, 0.0], [4.0, 0.0]])
    other_lo, other_hi = np.array([[1.5, 0.2], [9.0, 9.0]]), np.array([[2.5, 0.8], [9.5, 9.5]])
    pairs = set(zip(*box_pairs(lo, lo + 1.0, other_lo, other_hi, cell=1.0)))
    assert (1, 0) in pairs and (0, 1) not in pairs and (2, 1) not in pairs
    # 3-D: boxes apart in height only share no cell; a box reaching into the grid from outside it (clipped to
    # the grid) still meets the box it overlaps, and one wholly outside it meets none, whatever the cell
    lo3, other3 = np.array([[0.0, 0.0, 0.0]]), np.array([[0.0, 5.0, 0.0]])
    assert len(box_pairs(lo3, lo3 + 1.0, other3, other3 + 1.0, cell=1.0)[0]) == 0
    assert len(box_pairs(lo3, lo3 + 1.0, other3, other3 + 1.0, cell=16.0)[0]) == 0
    reaching = np.array([[-10.0, -10.0, -10.0]]), np.array([[0.5, 5.5, 0.5]])
    assert set(zip(*box_pairs(*reaching, other3, other3 + 1.0, cell=1.0))) == {(0, 0)}
    # boxes sharing six cells (3 x 2 of 1 m) make one pair, not six
    wide = np.array([[0.5, 0.5]]), np.array([[2.5, 1.5]])
    assert [pair.tolist() for pair in box_pairs(*wide, *wide, cell=1.0)] == [[0], [0]]
