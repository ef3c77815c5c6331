"""Tests of the procedural sample levels (g2s_plugins.samples.levels)."""

from __future__ import annotations

import math
import time
import types

import numpy as np
import pytest
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

from g2s_plugins.samples import levels as samples
from g2s_plugins.samples.levels import SAMPLES, SampleLevel, load_sample

UP = np.array([0.0, 1.0, 0.0])
DOWN = -UP

# (factory name, kwargs, expected number of openings)
CASES = [
    ("straight_corridor", {}, 2),
    ("straight_corridor", {"length": 20.0, "width": 4.0}, 2),
    ("corridor_with_ramp", {}, 2),
    ("corridor_with_ramp", {"rise": 3.0, "slope_deg": 30.0}, 2),
    ("cross_hub", {}, 4),
    ("t_hub", {}, 3),
    ("two_floors", {}, 0),
    ("two_floors", {"ramp": False}, 0),
    ("closed_room", {}, 0),
    ("room_with_window", {}, 1),
    ("dungeon", {}, 0),
    ("dungeon", {"seed": 3, "rooms": 30, "exits": 3}, 3),
    ("maze", {}, 0),
    ("maze", {"seed": 2, "cells": 12, "loops": 0.2}, 0),
]
CASE_IDS = [f"{name}-{i}" for i, (name, _, _) in enumerate(CASES)]
NOT_DUNGEON = [i for i, (name, _, _) in enumerate(CASES) if name != "dungeon"]

_cache: dict[int, SampleLevel] = {}


def level(index: int) -> SampleLevel:
    """The level of CASES[index], built once per test session."""
    if index not in _cache:
        name, kwargs, _ = CASES[index]
        _cache[index] = load_sample(name, **kwargs)
    return _cache[index]


def first_hits(mesh, origins, directions):
    """First hit of each ray: (locations (n, 3) with NaN rows for misses, face normals (n, 3))."""
    origins = np.atleast_2d(np.asarray(origins, dtype=np.float64))
    directions = np.broadcast_to(np.asarray(directions, dtype=np.float64), origins.shape)
    tri, ray, loc = mesh.ray.intersects_id(origins, directions, multiple_hits=False, return_locations=True)
    out = np.full(origins.shape, np.nan)
    normals = np.full(origins.shape, np.nan)
    out[ray] = loc
    normals[ray] = mesh.face_normals[tri]
    return out, normals


def floor_below(mesh, point, above=1.0):
    """(height, normal) of the first surface hit straight below ``point`` from ``above`` m over it."""
    loc, nrm = first_hits(mesh, np.asarray(point, dtype=np.float64) + above * UP, DOWN)
    return loc[0, 1], nrm[0]


# ---------------------------------------------------------------- registry


def test_registry_names_and_load():
    assert set(SAMPLES) == {
        "straight_corridor",
        "corridor_with_ramp",
        "cross_hub",
        "t_hub",
        "two_floors",
        "closed_room",
        "room_with_window",
        "dungeon",
        "two_rooms_one_door",
        "room_with_two_doors",
        "loop_of_four_rooms",
        "floors_joined_by_ramp",
        "lecture_hall",
        "ring_corridor",
        "catwalk",
        "offices",
        "dead_end_corridor",
        "pilaster_corridor",
        "bent_corridor",
        "door_in_corridor",
        "gallery",
        "two_doors_to_a_corridor",
        "shelving_warehouse",
        "doorway_room",
        "curb_platform",
        "wall_tops",
        "stair_deck",
        "cross_platform",
        "chamfered_platform",
        "sloped_corridor",
        "roofed_corridor",
        "twin_doors",
        "stair_exit",
        "corner_corridor",
        "t_junction",
        "bridge",
        "windowed_room",
        "threshold_door",
        "open_side_room",
        "thick_wall_door",
        "two_storey",
        "cluttered_room",
        "narrow_door_room",
        "terrain",
        "building",
        "castle",
        "maze",
    }
    lvl = load_sample("straight_corridor", length=5.0)
    assert isinstance(lvl, SampleLevel) and lvl.name == "straight_corridor"
    assert lvl.metadata["params"]["length"] == 5.0


def test_unknown_sample_lists_names():
    with pytest.raises(KeyError) as err:
        load_sample("no_such_level")
    for name in SAMPLES:
        assert name in str(err.value)


@pytest.mark.parametrize(
    "name, kwargs",
    [
        ("straight_corridor", {"width": 0.0}),
        ("corridor_with_ramp", {"slope_deg": 90.0}),
        ("cross_hub", {"arm_width": 9.0}),
        ("room_with_window", {"sill_height": 2.5, "window_top": 2.0}),
        ("two_floors", {"block": 20.0}),
        ("dungeon", {"rooms": 0}),
        ("dungeon", {"room_min": 3.0}),
        ("dungeon", {"rooms": 2, "exits": 50}),
        ("maze", {"cells": 1}),
        ("maze", {"loops": 1.5}),
    ],
)
def test_bad_arguments_raise(name, kwargs):
    with pytest.raises(ValueError):
        load_sample(name, **kwargs)


# ---------------------------------------------------------------- geometry helpers


def test_hexahedra_face_outwards():
    box = samples._box_corners(np.array([[1.0, 2.0, 3.0]]), np.array([[2.0, 4.0, 7.0]]))
    wedge = samples._sloped_blocks(0.0, 5.0, -1.0, 1.0, -0.2, 0.0, 2.0)
    for corners, volume in ((box, 8.0), (wedge, 5.0 * 2.0 * (0.2 + 1.0))):
        mesh = samples._hexahedra_mesh(corners)
        assert mesh.is_watertight and mesh.is_winding_consistent
        assert mesh.volume == pytest.approx(volume)
        # Every face normal points away from the solid's centre.
        to_face = mesh.triangles_center - corners[0].mean(axis=0)
        assert np.all(np.einsum("ij,ij->i", mesh.face_normals, to_face) > 0)


# ---------------------------------------------------------------- every sample


@pytest.mark.parametrize("index", range(len(CASES)), ids=CASE_IDS)
def test_mesh_is_valid(index):
    mesh = level(index).mesh
    v, f = np.asarray(mesh.vertices), np.asarray(mesh.faces)
    assert len(v) > 0 and f.ndim == 2 and f.shape[1] == 3 and len(f) > 0
    assert np.all(np.isfinite(v))
    assert f.min() >= 0 and f.max() < len(v)
    assert np.all(mesh.area_faces > 1e-9), "degenerate triangle"
    assert len(np.unique(np.round(v, 9), axis=0)) == len(v), "duplicate vertices"


@pytest.mark.parametrize("index", range(len(CASES)), ids=CASE_IDS)
def test_horizontal_faces_face_the_right_way(index):
    """Flat up-facing triangles are floor tops (at a floor height) or solid tops (wall height),
    down-facing ones slab bottoms; a window's sill faces up, lintels face down."""
    lvl = level(index)
    meta = lvl.metadata
    mesh = lvl.mesh
    normals, centres = mesh.face_normals, mesh.triangles_center
    allowed = [y for h in meta["floor_heights"] for y in (h, h + samples.WALL_HEIGHT)]
    bottoms = [h - samples.SLAB_THICKNESS for h in meta["floor_heights"]]
    if "window" in meta:
        allowed.append(meta["window"]["sill_height"])
        bottoms += [meta["window"]["top"], meta["door"]["height"]]
    up = normals[:, 1] > 0.999
    assert np.any(up)
    assert np.all(np.min(np.abs(centres[up, 1][:, None] - np.array(allowed)[None]), axis=1) < 1e-9)
    down = normals[:, 1] < -0.999
    assert np.all(np.min(np.abs(centres[down, 1][:, None] - np.array(bottoms)[None]), axis=1) < 1e-9)


@pytest.mark.parametrize("index", range(len(CASES)), ids=CASE_IDS)
def test_openings_count_and_shape(index):
    lvl = level(index)
    assert len(lvl.openings) == CASES[index][2]
    assert lvl.metadata["closed"] == (len(lvl.openings) == 0)
    for op in lvl.openings:
        h, pos, p0, p1 = (np.array(x) for x in (op.heading, op.position, op.p0, op.p1))
        assert np.linalg.norm(h) == pytest.approx(1.0)
        assert h[1] == 0.0
        assert np.allclose((p0 + p1) / 2, pos)
        assert np.linalg.norm(p1 - p0) == pytest.approx(op.width)
        assert abs(np.dot(p1 - p0, h)) < 1e-9
        # p0 is on the left when facing along the heading (Y up, right-handed).
        assert np.dot(p0 - pos, np.cross(UP, h)) > 0
        assert pos[1] in lvl.metadata["floor_heights"]


@pytest.mark.parametrize("index", range(len(CASES)), ids=CASE_IDS)
def test_openings_lie_on_open_floor_edges(index):
    lvl = level(index)
    mesh = lvl.mesh
    climb = samples.DESIGN_AGENT["max_climb"]
    for op in lvl.openings:
        h, pos, p0, p1 = (np.array(x) for x in (op.heading, op.position, op.p0, op.p1))
        y = pos[1]
        # Just inside the edge, at the middle and near both ends: floor top at the opening's height.
        near_ends = [e + 0.05 * (pos - e) / np.linalg.norm(pos - e) for e in (p0, p1)]
        for p in [pos, *near_ends]:
            hit_y, normal = floor_below(mesh, p - 0.05 * h)
            assert hit_y == pytest.approx(y, abs=1e-4)
            assert normal[1] > 0.999
        # Just outside: no floor the agent could step onto.
        hit_y, _ = floor_below(mesh, pos + 0.05 * h)
        assert np.isnan(hit_y) or hit_y < y - climb
        # The opening is exactly as wide as the gap between the walls beside it (for a
        # doorway, the jambs are in the wall, just beyond the floor edge).
        inside = pos + (samples.WALL_THICKNESS / 2 if "door" in lvl.metadata else -0.05) * h + UP
        for end in (p0, p1):
            lateral = (end - pos) / np.linalg.norm(end - pos)
            loc, _ = first_hits(mesh, inside, lateral)
            assert np.linalg.norm(loc[0] - inside) == pytest.approx(op.width / 2, abs=1e-4)


@pytest.mark.parametrize("index", NOT_DUNGEON, ids=lambda i: CASE_IDS[i])
def test_headings_point_away_from_the_centre(index):
    lvl = level(index)
    centre = lvl.mesh.bounds.mean(axis=0)
    for op in lvl.openings:
        assert np.dot(np.array(op.heading), np.array(op.position) - centre) > 0


@pytest.mark.parametrize("index", range(len(CASES)), ids=CASE_IDS)
def test_deterministic(index):
    name, kwargs, _ = CASES[index]
    a, b = level(index), load_sample(name, **kwargs)
    assert np.array_equal(a.mesh.vertices, b.mesh.vertices)
    assert np.array_equal(a.mesh.faces, b.mesh.faces)
    assert a.openings == b.openings


# ---------------------------------------------------------------- sample specifics


def test_straight_corridor_is_walled_on_both_sides():
    lvl = samples.straight_corridor(length=10.0, width=3.0)
    loc, _ = first_hits(lvl.mesh, [[5.0, 1.0, 0.0], [5.0, 1.0, 0.0]], [[0.0, 0.0, 1.0], [0.0, 0.0, -1.0]])
    assert np.allclose(loc[:, 2], [1.5, -1.5])
    assert lvl.metadata["floor_area"] == pytest.approx(30.0)


def test_corridor_with_ramp_surface():
    lvl = samples.corridor_with_ramp(rise=2.0, slope_deg=20.0)
    ramp = lvl.metadata["ramp"]
    assert ramp["x1"] - ramp["x0"] == pytest.approx(2.0 / math.tan(math.radians(20.0)))
    y, normal = floor_below(lvl.mesh, [(ramp["x0"] + ramp["x1"]) / 2, 1.0, 0.0], above=3.0)
    assert y == pytest.approx(1.0, abs=1e-4)
    assert math.degrees(math.acos(normal[1])) == pytest.approx(20.0, abs=1e-3)
    assert [op.position[1] for op in lvl.openings] == [0.0, 2.0]
    # The ramp's side walls stay a full wall height above its surface.
    loc, _ = first_hits(lvl.mesh, [[(ramp["x0"] + ramp["x1"]) / 2, 3.5, 0.0]], [0.0, 0.0, 1.0])
    assert loc[0, 2] == pytest.approx(1.5)


def test_hubs_have_arms_on_the_declared_sides():
    for factory, arms in ((samples.cross_hub, ("+X", "+Z", "-X", "-Z")), (samples.t_hub, ("+X", "-X", "-Z"))):
        lvl = factory()
        assert lvl.metadata["arms"] == arms
        headings = {tuple(np.round(op.heading).astype(int)) for op in lvl.openings}
        assert len(headings) == len(arms)
    # The t_hub's +Z side is a wall 4 m from the hub centre.
    loc, _ = first_hits(samples.t_hub().mesh, [[0.0, 1.0, 0.0]], [0.0, 0.0, 1.0])
    assert loc[0, 2] == pytest.approx(4.0)


def test_two_floors_ramp_ring_and_block():
    with_ramp, without = samples.two_floors(), samples.two_floors(ramp=False)
    ramp = with_ramp.metadata["ramp"]
    assert without.metadata["ramp"] is None
    assert (with_ramp.metadata["components"], without.metadata["components"]) == (1, 2)
    mid = [(ramp["x0"] + ramp["x1"]) / 2, 2.0, (ramp["z0"] + ramp["z1"]) / 2]
    assert floor_below(with_ramp.mesh, mid, above=3.0)[0] == pytest.approx(2.0, abs=1e-4)
    assert np.isnan(floor_below(without.mesh, mid, above=3.0)[0])
    up = with_ramp.metadata["upper"]
    centre_up = [(up["x0"] + up["x1"]) / 2, 4.0, (up["z0"] + up["z1"]) / 2]
    assert floor_below(with_ramp.mesh, centre_up)[0] == pytest.approx(4.0)
    # The ground floor is a ring: floor on all four sides of the block, none inside it.
    blk = with_ramp.metadata["block"]
    c, r = (blk["x0"] + blk["x1"]) / 2, (blk["x1"] - blk["x0"]) / 2 + 2.0
    for dx, dz in ((r, 0.0), (-r, 0.0), (0.0, r), (0.0, -r)):
        assert floor_below(with_ramp.mesh, [c + dx, 0.0, c + dz])[0] == pytest.approx(0.0)
    assert np.isnan(floor_below(with_ramp.mesh, [c, 0.0, c])[0])
    # From the ring, the block is a wall.
    loc, _ = first_hits(with_ramp.mesh, [[c - r, 1.0, c]], [1.0, 0.0, 0.0])
    assert loc[0, 0] == pytest.approx(blk["x0"])


def test_room_with_window_door_and_window():
    lvl = samples.room_with_window(width=8.0, depth=6.0)
    win = lvl.metadata["window"]
    assert lvl.openings[0].position == (4.0, 0.0, 0.0)
    mesh = lvl.mesh
    towards_window = [0.0, 0.0, 1.0]
    # Through the window (between sill and top) nothing is hit; below and above it the wall is.
    loc, _ = first_hits(mesh, [[0.0, 1.5, 0.0], [0.0, 0.5, 0.0], [0.0, 2.5, 0.0]], towards_window)
    assert np.isnan(loc[0, 2]) and np.allclose(loc[1:, 2], 3.0)
    assert (win["sill_height"], win["top"]) == (1.0, 2.0)
    # Through the door at body height nothing is hit; the lintel closes it above 2.5 m.
    loc, _ = first_hits(mesh, [[0.0, 1.5, 0.0], [0.0, 2.7, 0.0], [0.0, 1.5, 2.0]], [1.0, 0.0, 0.0])
    assert np.isnan(loc[0, 0]) and np.allclose(loc[1:, 0], 4.0)
    # The other walls are closed.
    loc, _ = first_hits(mesh, [[0.0, 1.5, 0.0], [0.0, 1.5, 0.0]], [[-1.0, 0.0, 0.0], [0.0, 0.0, -1.0]])
    assert np.allclose(loc[:, [0, 2]], [[-4.0, 0.0], [0.0, -3.0]])


def test_closed_room_is_closed():
    mesh = samples.closed_room(width=8.0, depth=6.0).mesh
    angles = np.linspace(0.0, 2.0 * np.pi, 72, endpoint=False)
    dirs = np.column_stack([np.cos(angles), np.zeros_like(angles), np.sin(angles)])
    loc, _ = first_hits(mesh, np.tile([0.0, 1.0, 0.0], (len(dirs), 1)), dirs)
    assert not np.any(np.isnan(loc))


# ---------------------------------------------------------------- dungeon


def test_dungeon_seeds_differ_and_size_grows():
    a, b = samples.dungeon(seed=0), samples.dungeon(seed=1)
    assert not np.array_equal(a.mesh.vertices, b.mesh.vertices)
    small, big = samples.dungeon(rooms=12), samples.dungeon(rooms=60)
    assert len(big.mesh.faces) > len(small.mesh.faces)
    bare, busy = samples.dungeon(rooms=30, obstacles=0.0), samples.dungeon(rooms=30, obstacles=1.0)
    assert bare.metadata["pillars"] == 0 < busy.metadata["pillars"]
    assert len(busy.mesh.faces) > len(bare.mesh.faces)


def test_dungeon_ground_truth():
    lvl = samples.dungeon(seed=5, rooms=40)
    meta = lvl.metadata
    n = meta["params"]["rooms"]
    centres, bounds = np.array(meta["room_centres"]), np.array(meta["room_bounds"])
    assert centres.shape == (n, 3) and bounds.shape == (n, 4)
    assert len(set(meta["slots"])) == n
    # Corridors: a spanning tree plus loops, joining every room.
    pairs = np.array(meta["corridors"])
    assert len(pairs) == meta["tree_corridors"] + meta["loops"] == n - 1 + meta["loops"]
    assert meta["loops"] >= 1
    graph = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(n, n))
    assert connected_components(graph, directed=False)[0] == 1
    assert meta["cycles"] == meta["loops"] + meta["pillars"]
    # Room floors are where the metadata says.
    probes = bounds[:, [0, 2]] + 0.3  # near each room's (-X, -Z) corner, clear of pillars
    loc, nrm = first_hits(lvl.mesh, np.column_stack([probes[:, 0], np.ones(n), probes[:, 1]]), DOWN)
    assert np.allclose(loc[:, 1], 0.0) and np.all(nrm[:, 1] > 0.999)
    # Pillars stand inside their room, pillar_gap clear of the walls.
    gap, size = meta["params"]["pillar_gap"], meta["params"]["pillar_size"]
    for x, _, z in meta["pillar_centres"]:
        inside = (bounds[:, 0] + gap + size / 2 <= x + 1e-9) & (x <= bounds[:, 1] - gap - size / 2 + 1e-9)
        inside &= (bounds[:, 2] + gap + size / 2 <= z + 1e-9) & (z <= bounds[:, 3] - gap - size / 2 + 1e-9)
        assert inside.sum() == 1


def test_maze_ground_truth():
    import networkx as nx

    def cell_graph(meta, cells):
        east, south = meta["east_walls"], meta["south_walls"]
        graph = nx.grid_2d_graph(cells, cells)
        graph.remove_edges_from(((i, j), (i + 1, j)) for i, j in np.argwhere(east))
        graph.remove_edges_from(((i, j), (i, j + 1)) for i, j in np.argwhere(south))
        return graph

    perfect = load_sample("maze", seed=1, cells=10, loops=0.0)
    graph = cell_graph(perfect.metadata, 10)
    assert nx.is_tree(graph)  # one path between any two cells
    assert perfect.metadata["loops"] == perfect.metadata["cycles"] == 0
    assert perfect.metadata["dead_ends"] == sum(1 for _, d in graph.degree if d == 1) > 0
    looped = load_sample("maze", seed=1, cells=10, loops=0.3)
    graph = cell_graph(looped.metadata, 10)
    assert nx.is_connected(graph) and graph.number_of_edges() - graph.number_of_nodes() + 1 == looped.metadata["loops"] > 0
    assert 0 < looped.metadata["cycles"] <= looped.metadata["loops"]
    # every corridor is `width` wide between walls centred on the cell boundaries
    width = 3.0
    lvl = load_sample("maze", cells=6, width=width)
    assert lvl.metadata["pitch"] == pytest.approx(width + lvl.metadata["wall_thickness"])
    assert np.allclose(lvl.mesh.bounds[:, [0, 2]], [[-0.1, -0.1], [6 * 3.2 + 0.1, 6 * 3.2 + 0.1]])
    assert load_sample("maze", seed=0).metadata["east_walls"].tolist() != load_sample("maze", seed=1).metadata["east_walls"].tolist()


def test_dungeon_corridors_have_floor():
    """Across the gap between two joined rooms there is one strip of floor, a corridor wide."""
    lvl = samples.dungeon(seed=2, rooms=25)
    bounds = np.array(lvl.metadata["room_bounds"])
    slots = lvl.metadata["slots"]
    width = lvl.metadata["params"]["corridor_width"]
    step = 0.05
    for a, b in lvl.metadata["corridors"]:
        (ia, ja), (ib, jb) = slots[a], slots[b]
        along_x = ja == jb  # neighbours in a row: the corridor runs along X
        if (ib, jb) < (ia, ja):
            a, b = b, a
        ra, rb = bounds[a], bounds[b]  # b is a's +X (or +Z) neighbour
        gap = (ra[1] + rb[0]) / 2 if along_x else (ra[3] + rb[2]) / 2
        lo, hi = (max(ra[2], rb[2]), min(ra[3], rb[3])) if along_x else (max(ra[0], rb[0]), min(ra[1], rb[1]))
        t = np.arange(lo + step / 2, hi, step)
        g = np.full_like(t, gap)
        probes = np.column_stack([g, np.ones_like(t), t] if along_x else [t, np.ones_like(t), g])
        hits, _ = first_hits(lvl.mesh, probes, DOWN)
        on_floor = np.nonzero(np.isclose(hits[:, 1], 0.0))[0]
        assert len(on_floor) > 0, (a, b)
        assert np.all(np.diff(on_floor) == 1), (a, b)  # one contiguous strip
        assert len(on_floor) * step == pytest.approx(width, abs=step), (a, b)


def test_dungeon_exits_lead_out_of_their_rooms():
    lvl = samples.dungeon(seed=3, rooms=30, exits=3)
    centres = np.array(lvl.metadata["room_centres"])
    assert len(lvl.metadata["exit_rooms"]) == 3
    for op, (room, side) in zip(lvl.openings, lvl.metadata["exit_rooms"]):
        assert np.dot(np.array(op.heading), np.array(op.position) - centres[room]) > 0
        assert side in ("-X", "+X", "-Z", "+Z")


def test_big_dungeon_generates():
    # its generation time is a benchmark figure (docs/performance.md), not a test
    lvl = samples.dungeon(rooms=5000)
    assert len(lvl.metadata["room_centres"]) == 5000
    assert len(lvl.mesh.faces) > 500_000


# ---------------------------------------------------------------- with Recast (optional)


def _navmesh_topology(lvl):
    recast = pytest.importorskip("g2s_plugins.recast")
    agent = types.SimpleNamespace(
        radius=samples.DESIGN_AGENT["radius"],
        height=samples.DESIGN_AGENT["height"],
        max_climb=samples.DESIGN_AGENT["max_climb"],
        max_slope=samples.DESIGN_AGENT["max_slope_deg"],
    )
    start = time.perf_counter()
    nav = recast.build_navmesh(lvl.mesh.vertices, lvl.mesh.faces, agent)
    seconds = time.perf_counter() - start
    p = nav.polygon_count
    i, j = np.nonzero(nav.neighbours >= 0)
    k = nav.neighbours[i, j]
    keep = i < k  # every shared polygon edge once (a pair may share several)
    graph = coo_matrix((np.ones(int(keep.sum())), (i[keep], k[keep])), shape=(p, p))
    components = connected_components(graph, directed=False)[0]
    return nav, components, int(keep.sum()) - p + components, seconds


@pytest.mark.parametrize("index", NOT_DUNGEON, ids=lambda i: CASE_IDS[i])
def test_recast_agrees_with_ground_truth(index):
    lvl = level(index)
    nav, components, cycles, _ = _navmesh_topology(lvl)
    assert components == lvl.metadata["components"]
    assert cycles == lvl.metadata["cycles"]
    # The walkable surface is at the floor heights (Recast's cell height is 0.125 m here).
    heights = np.array(lvl.metadata["floor_heights"])
    flat = nav.normals[:, 1] > 0.999
    assert np.all(np.min(np.abs(nav.centres[flat, 1][:, None] - heights[None]), axis=1) < 0.3)


def test_recast_dungeon_calibration(capsys):
    rows = []
    for rooms in (4, 50, 200):
        lvl = samples.dungeon(rooms=rooms)
        nav, components, cycles, seconds = _navmesh_topology(lvl)
        truth = lvl.metadata["cycles"]
        rows.append((rooms, len(lvl.mesh.faces), nav.polygon_count, components, cycles, truth, seconds))
    with capsys.disabled():
        print("\nrooms faces polygons components cycles(navmesh) cycles(truth) seconds")
        for row in rows:
            print(" ".join(f"{v:.2f}" if isinstance(v, float) else str(v) for v in row))
    polygons = [r[2] for r in rows]
    assert polygons == sorted(polygons) and polygons[0] < polygons[-1]
    assert rows[0][3] == rows[1][3] == 1
