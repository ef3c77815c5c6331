"""The Recast/Detour extension and its Python wrapper (g2s_plugins.recast)."""

from __future__ import annotations

import math
import time
import types

import networkx as nx
import numpy as np
import pydantic
import pytest
import trimesh

from g2s_plugins.recast import FLT_MAX, NavMesh, RecastParams, SettingsError, _recast, build_navmesh, resolve_settings
from g2s_plugins.samples.buildings import building
from g2s_plugins.samples.maze import maze

AGENT = types.SimpleNamespace(radius=0.3, height=2.0, max_climb=0.4, max_slope=45.0)


def slab(extents, centre) -> trimesh.Trimesh:
    """A box of the given extents whose centre is at ``centre``."""
    box = trimesh.creation.box(extents=extents)
    box.apply_translation(centre)
    return box


def floor(size_x, size_z, x=0.0, y=0.0, z=0.0) -> trimesh.Trimesh:
    """A 0.2 m thick slab whose top face is at height ``y``."""
    return slab((size_x, 0.2, size_z), (x, y - 0.1, z))


def build(mesh: trimesh.Trimesh, agent=AGENT, **params) -> NavMesh:
    return build_navmesh(mesh.vertices, mesh.faces, agent, RecastParams(**params))


def adjacency_components(nm: NavMesh) -> int:
    g = nx.Graph()
    g.add_nodes_from(range(nm.polygon_count))
    g.add_edges_from(nm.portals().pairs.tolist())
    return nx.number_connected_components(g)


# ------------------------------------------------------------------ build


def test_flat_floor_area_and_arrays():
    nm = build(floor(10, 10))
    r = AGENT.radius
    expected = (10 - 2 * r) ** 2
    assert nm.polygon_count >= 1
    assert adjacency_components(nm) == 1
    assert abs(nm.areas.sum() - expected) / expected < 0.10
    # array shapes and dtypes
    P, nvp = nm.polygons.shape
    assert P == nm.polygon_count and nvp == 6
    assert nm.polygons.dtype == np.int32 and nm.neighbours.dtype == np.int32
    assert nm.vertices.shape[1] == 3 and nm.vertices.dtype == np.float64
    assert nm.detail_triangles.dtype == np.int32 and nm.detail_triangles.max() < len(nm.detail_vertices)
    assert nm.detail_polygon.shape == (len(nm.detail_triangles),)
    assert set(np.unique(nm.detail_polygon)) == set(range(P))
    # vertices eroded by about the radius (plus at most ~one cell) from the 5 m edges
    assert np.all(np.abs(nm.vertices[:, [0, 2]]) <= 5 - r + 1e-6)
    assert np.all(np.abs(nm.vertices[:, [0, 2]]).max(axis=0) >= 5 - r - 0.5)
    # flat: normals up, centres on the surface (within a cell height or two)
    assert np.allclose(nm.normals, [0, 1, 0], atol=1e-6)
    assert np.all(np.abs(nm.centres[:, 1]) < 0.3)
    assert np.all(nm.area_ids == 63)
    s = nm.stats()
    assert s["polygons"] == P and s["cell_size"] == pytest.approx(0.15) and s["cell_height"] == pytest.approx(0.075)
    assert s["build_seconds"] >= 0


def test_float32_and_int32_inputs_give_the_same_mesh():
    mesh = floor(10, 10)
    a = build_navmesh(mesh.vertices, mesh.faces, AGENT)
    b = build_navmesh(mesh.vertices.astype(np.float32), mesh.faces.astype(np.int32), AGENT)
    assert np.array_equal(a.polygons, b.polygons)
    assert np.allclose(a.vertices, b.vertices)


def test_neighbours_are_symmetric_and_match_shared_vertices():
    nm = build(floor(40, 2))
    P = nm.polygon_count
    assert P >= 2
    for i in range(P):
        row = nm.polygons[i]
        n = int((row >= 0).sum())
        for j in range(n):
            k = nm.neighbours[i, j]
            if k < 0:
                continue
            edge = {int(row[j]), int(row[(j + 1) % n])}
            assert edge <= set(nm.polygons[k][nm.polygons[k] >= 0].tolist())
            assert i in nm.neighbours[k]


def test_corridor_is_a_chain_spanning_end_to_end():
    nm = build(floor(40, 2))
    g = nx.Graph()
    g.add_nodes_from(range(nm.polygon_count))
    g.add_edges_from(nm.portals().pairs.tolist())
    assert nx.is_connected(g)
    assert g.number_of_edges() <= nm.polygon_count  # tree-like
    assert max(d for _, d in g.degree) <= 3
    xs = nm.vertices[:, 0]
    assert xs.min() < -20 + 1.0 and xs.max() > 20 - 1.0
    west, east = int(np.argmin(nm.centres[:, 0])), int(np.argmax(nm.centres[:, 0]))
    assert nx.has_path(g, west, east)


def test_separate_floors_connect_only_through_a_ramp():
    lower = floor(10, 4, x=0.0, y=0.0)  # x in [-5, 5]
    upper = floor(10, 4, x=16.0, y=2.0)  # x in [11, 21], 2 m higher
    apart = build(trimesh.util.concatenate([lower, upper]))
    assert adjacency_components(apart) == 2

    # ramp from (5, 0) up to (11, 2): 6 m run, 2 m rise (about 18 degrees)
    run, rise = 6.0, 2.0
    angle = math.atan2(rise, run)
    ramp = trimesh.creation.box(extents=(math.hypot(run, rise) + 0.2, 0.2, 4.0))
    ramp.apply_transform(trimesh.transformations.rotation_matrix(angle, (0, 0, 1)))
    normal = np.array([-math.sin(angle), math.cos(angle), 0.0])
    ramp.apply_translation(np.array([8.0, 1.0, 0.0]) - 0.1 * normal)
    joined = build(trimesh.util.concatenate([lower, upper, ramp]))
    assert adjacency_components(joined) == 1
    # polygons over the ramp are tilted (at most by the ramp angle) and sit between the floors
    tilt = np.degrees(np.arccos(np.clip(joined.normals[:, 1], -1, 1)))
    assert 5.0 < tilt.max() < math.degrees(angle) + 2.0
    dv = joined.detail_vertices
    over = (dv[:, 0] > 5.5) & (dv[:, 0] < 10.5)
    assert over.sum() >= 2
    assert np.allclose(dv[over, 1], (dv[over, 0] - 5.0) * rise / run, atol=0.35)


def test_too_steep_ramp_is_not_walkable():
    ramp = trimesh.creation.box(extents=(6.0, 0.2, 4.0))
    ramp.apply_transform(trimesh.transformations.rotation_matrix(math.radians(60), (0, 0, 1)))
    with pytest.raises(RuntimeError, match="Recast: no walkable polygons"):
        build(ramp)


def test_no_walkable_surface_raises():
    wall = slab((0.1, 3.0, 5.0), (0, 1.5, 0))  # only vertical faces wider than the agent
    wall.update_faces(np.abs(wall.face_normals[:, 1]) < 0.5)
    with pytest.raises(RuntimeError, match="Recast: no walkable polygons"):
        build(wall)


def test_erosion_can_remove_everything():
    # a 0.5 m wide strip and a 1 m agent radius: nothing left after erosion
    with pytest.raises(RuntimeError, match="Recast: no walkable polygons"):
        build(floor(10, 0.5), agent=types.SimpleNamespace(radius=1.0, height=2.0, max_climb=0.4, max_slope=45))


def test_bad_inputs_raise_value_errors():
    mesh = floor(10, 10)
    bad = mesh.faces.copy()
    bad[0, 0] = len(mesh.vertices)
    with pytest.raises(ValueError, match="face index out of range"):
        build_navmesh(mesh.vertices, bad, AGENT)
    with pytest.raises(ValueError):
        build_navmesh(mesh.vertices[:, :2], mesh.faces, AGENT)
    nan = mesh.vertices.copy()
    nan[0, 0] = np.nan
    with pytest.raises(ValueError, match="finite"):
        build_navmesh(nan, mesh.faces, AGENT)


def test_grid_guard_names_the_problem():
    with pytest.raises(SettingsError, match="graph.params.max_cells: a tile of 256 cells .* more than "
                       "graph.params.max_cells=100"):
        build(floor(10, 10), max_cells=100)
    with pytest.raises(SettingsError, match="graph.params.tile_size: a solo grid of 67 x 67 cells"):
        build(floor(10, 10), max_cells=100, tile_size=0)
    # the automatic mode tiles a level whose solo grid exceeds the guard
    assert build(floor(60, 60), max_cells=100_000).tile_size == 256  # 400 x 400 cells
    # the extension refuses the same on its own, computed without int overflow
    with pytest.raises(RuntimeError, match="Recast: grid of 67 x 67 cells exceeds max_cells=100"):
        _recast.build(floor(10, 10).vertices, floor(10, 10).faces, **{**resolve_settings(AGENT), "max_cells": 100,
                                                                     "tile_size": 0})


# ------------------------------------------------------------------ parameters


def test_params_validation():
    with pytest.raises(pydantic.ValidationError):
        RecastParams(cell_size=-0.1)
    with pytest.raises(pydantic.ValidationError):
        RecastParams(cell_height=0)
    with pytest.raises(pydantic.ValidationError):
        RecastParams(verts_per_poly=7)
    with pytest.raises(pydantic.ValidationError):
        RecastParams(agent_max_slope=90)
    with pytest.raises(pydantic.ValidationError):
        RecastParams(not_a_parameter=1)
    for name, field in RecastParams.model_fields.items():
        assert field.description, name


def test_cell_size_rule():
    s = resolve_settings(types.SimpleNamespace(radius=0.6, height=2.0, max_climb=0.9, max_slope=45))
    assert s["cell_size"] == pytest.approx(0.3) and s["cell_height"] == pytest.approx(0.15)
    s = resolve_settings(types.SimpleNamespace(radius=0.6, height=2.0, max_climb=0.1, max_slope=45))
    assert s["cell_height"] == pytest.approx(0.05)  # capped at max_climb / 2
    s = resolve_settings(types.SimpleNamespace(radius=0.0, height=2.0, max_climb=0.0, max_slope=45))
    assert s["cell_size"] == pytest.approx(0.05) and s["cell_height"] == pytest.approx(0.025)
    s = resolve_settings(AGENT, RecastParams(cell_size=0.3, cell_height=0.2, agent_radius=0.6))
    assert (s["cell_size"], s["cell_height"], s["agent_radius"]) == (0.3, 0.2, 0.6)


def test_voxel_config_derived_like_recast_demo():
    agent = types.SimpleNamespace(radius=0.6, height=2.0, max_climb=0.9, max_slope=45.0)
    mesh = floor(20, 20)
    nm = build_navmesh(mesh.vertices, mesh.faces, agent, RecastParams(cell_size=0.3, cell_height=0.2))
    c = nm.config()
    assert c["walkableHeight"] == 10  # ceil(2.0 / 0.2)
    assert c["walkableClimb"] == 4  # floor(0.9 / 0.2)
    assert c["walkableRadius"] == 2  # ceil(0.6 / 0.3)
    assert c["maxEdgeLen"] == 40  # int(12 / 0.3)
    assert c["minRegionArea"] == 64 and c["mergeRegionArea"] == 400
    assert c["detailSampleDist"] == pytest.approx(1.8) and c["detailSampleMaxError"] == pytest.approx(0.2)


# ------------------------------------------------------------------ queries


@pytest.fixture(scope="module")
def walled():
    """A 20 x 10 m floor with a 0.5 x 3 x 6 m wall across its middle (z in [-3, 3])."""
    return build(trimesh.util.concatenate([floor(20, 10), slab((0.5, 3.0, 6.0), (0.0, 1.5, 0.0))]))


def test_raycast_open_and_blocked(walled):
    clear, t = walled.raycast((-8, 0, -4.2), (8, 0, -4.2))
    assert clear and t == FLT_MAX
    clear, t = walled.raycast((-8, 0, 0), (8, 0, 0))
    assert not clear and 0.0 < t < 1.0
    # hit near the wall's eroded face: x = -0.25 - radius
    x_hit = -8 + t * 16
    assert -0.25 - AGENT.radius - 0.3 < x_hit < -0.25
    # start far from any polygon
    assert walled.raycast((100, 0, 100), (0, 0, 0)) == (False, 0.0)


def test_raycast_many_matches_raycast(walled):
    A = np.array([[-8, 0, -4.2], [-8, 0, 0], [-8, 0, 4.2], [100, 0, 100]], dtype=float)
    B = np.array([[8, 0, -4.2], [8, 0, 0], [-2, 0, 2.0], [0, 0, 0]], dtype=float)
    many = walled.raycast_many(A, B)
    assert many.dtype == np.bool_ and many.shape == (4,)
    assert many.tolist() == [walled.raycast(a, b)[0] for a, b in zip(A, B)]
    assert many.tolist() == [True, False, True, False]


def test_raycast_to_a_floor_stacked_above_is_not_clear():
    lower = floor(12, 12)
    upper = floor(6, 6, y=3.0)  # over the centre, 3 m up (room for the 2 m agent below)
    nm = build(trimesh.util.concatenate([lower, upper]))
    assert adjacency_components(nm) == 2
    a = (-5.0, 0.0, -5.0)
    assert nm.raycast(a, (0.0, 0.0, 0.0))[0]  # under the upper floor, same level
    clear, t = nm.raycast(a, (0.0, 3.0, 0.0))  # same x,z, on the upper floor
    assert t == FLT_MAX and not clear  # Detour reaches b in 2D; the height check refuses
    # on the upper floor itself
    assert nm.raycast((-1.5, 3.0, -1.5), (1.5, 3.0, 1.5))[0]


def test_nearest_poly_and_refs(walled):
    idx, point = walled.nearest_poly((-8, 0.05, -4))
    assert 0 <= idx < walled.polygon_count
    assert point.shape == (3,) and abs(point[0] + 8) < 1e-4 and abs(point[2] + 4) < 1e-4
    assert abs(point[1]) < 0.3
    idx_far, p_far = walled.nearest_poly((500, 0, 500))
    assert idx_far == -1
    # small extents do not reach a floor 5 m below, larger ones do
    assert walled.nearest_poly((-8, 5, -4), extents=(0.5, 1.0, 0.5))[0] == -1
    assert walled.nearest_poly((-8, 5, -4), extents=(0.5, 6.0, 0.5))[0] == idx
    for i in range(walled.polygon_count):
        ref = walled.poly_ref(i)
        assert ref != 0 and walled.poly_index(ref) == i
    assert walled.poly_index(0) == -1
    with pytest.raises(IndexError):
        walled.poly_ref(walled.polygon_count)


def test_centres_lie_inside_their_polygons(walled):
    from matplotlib.path import Path

    for i in range(walled.polygon_count):
        row = walled.polygons[i][walled.polygons[i] >= 0]
        ring = walled.vertices[row][:, [0, 2]]
        assert Path(ring).contains_point(walled.centres[i, [0, 2]], radius=-1e-6) or Path(
            ring
        ).contains_point(walled.centres[i, [0, 2]], radius=1e-6)


# ------------------------------------------------------------------ tiled builds


def ramp_level() -> trimesh.Trimesh:
    """30 x 20 m floor, two walls, a 0.3 m step platform and a ramp up to a 2 m high floor."""
    run, rise = 6.0, 2.0
    angle = math.atan2(rise, run)
    ramp = trimesh.creation.box(extents=(math.hypot(run, rise) + 0.2, 0.2, 4.0))
    ramp.apply_transform(trimesh.transformations.rotation_matrix(angle, (0, 0, 1)))
    normal = np.array([-math.sin(angle), math.cos(angle), 0.0])
    ramp.apply_translation(np.array([18.0, 1.0, 6.0]) - 0.1 * normal)  # x 15 -> 21 at z = 6
    return trimesh.util.concatenate(
        [
            floor(30, 20),  # x, z in [-15, 15] x [-10, 10]
            slab((0.5, 3, 12), (-5, 1.5, -4)),
            slab((0.5, 3, 12), (5, 1.5, 4)),
            slab((6, 0.3, 6), (11, 0.15, -6)),
            ramp,
            floor(8, 8, x=25.0, y=2.0, z=6.0),  # x in [21, 29]
        ]
    )


@pytest.fixture(scope="module")
def solo_and_tiled():
    mesh = ramp_level()
    return build(mesh, tile_size=0), build(mesh, tile_size=32)


def tile_of(nm: NavMesh) -> np.ndarray:
    """(P,) index of each polygon's tile (0 .. tile_count - 1)."""
    return np.searchsorted(nm.tile_first_polygon, np.arange(nm.polygon_count), side="right") - 1


def xz_distance_to_edges(nm: NavMesh, poly: int, p: np.ndarray) -> float:
    """Smallest xz distance from ``p`` to an edge of polygon ``poly``."""
    row = nm.polygons[poly][nm.polygons[poly] >= 0]
    a = nm.vertices[row][:, [0, 2]]
    b = np.roll(a, -1, axis=0)
    d = b - a
    t = np.clip(np.einsum("ij,ij->i", p[[0, 2]] - a, d) / np.maximum(np.einsum("ij,ij->i", d, d), 1e-300), 0, 1)
    return float(np.min(np.linalg.norm(a + t[:, None] * d - p[[0, 2]], axis=1)))


def test_tiling_configuration(solo_and_tiled):
    solo, tiled = solo_and_tiled
    assert solo.tile_size == 0 and solo.tile_count == 1 and solo.tile_first_polygon.tolist() == [0]
    c = tiled.config()
    assert tiled.tile_size == c["tileSize"] == 32
    assert c["borderSize"] == c["walkableRadius"] + 3
    assert c["tileGrid"] == (math.ceil(c["width"] / 32), math.ceil(c["height"] / 32))
    assert tiled.tile_count == c["tiles"] > 20
    assert (c["width"], c["height"]) == (solo.config()["width"], solo.config()["height"])
    first = tiled.tile_first_polygon
    assert first[0] == 0 and np.all(np.diff(first) > 0) and first[-1] < tiled.polygon_count
    s = tiled.stats()
    assert s["tiles"] == tiled.tile_count and s["tile_size"] == 32 and s["polygons"] == tiled.polygon_count


def test_tiled_build_agrees_with_solo(solo_and_tiled):
    solo, tiled = solo_and_tiled
    assert adjacency_components(solo) == 1 and adjacency_components(tiled) == 1
    assert tiled.areas.sum() == pytest.approx(solo.areas.sum(), rel=0.03)
    # the upper floor is reached in both (polygons about 2 m up)
    assert np.any(np.abs(tiled.centres[:, 1] - 2.0) < 0.3) and np.any(np.abs(solo.centres[:, 1] - 2.0) < 0.3)
    # hand-picked rays: open floor across many tiles, a wall, the step, up the ramp
    pairs = [
        ((-13, 0, 3), (4, 0, 3), True),  # between the walls' ends
        ((-13, 0, -9), (-13, 0, 9), True),
        ((-8, 0, -4), (-2, 0, -4), False),  # through the wall at x = -5
        ((2, 0, 4), (8, 0, 4), False),  # through the wall at x = 5
        ((8, 0, -6), (11, 0.3, -6), True),  # onto the step
        ((14, 0, 6), (25, 2, 6), True),  # up the ramp onto the upper floor
        ((14, 0, 6), (25, 0, 6), False),  # under the upper floor: not on the mesh there
    ]
    for a, b, expected in pairs:
        assert solo.raycast(a, b)[0] == expected, (a, b)
        assert tiled.raycast(a, b)[0] == expected, (a, b)
    # random rays on the ground floor: the answers agree
    rng = np.random.default_rng(7)
    A = np.column_stack([rng.uniform(-14, 14, 400), np.zeros(400), rng.uniform(-9, 9, 400)])
    B = np.column_stack([rng.uniform(-14, 14, 400), np.zeros(400), rng.uniform(-9, 9, 400)])
    s, t = solo.raycast_many(A, B), tiled.raycast_many(A, B)
    assert 50 < s.sum() < 350 and np.mean(s == t) >= 0.97


def test_tiled_queries_work_in_every_tile(solo_and_tiled):
    _, nm = solo_and_tiled
    tiles = tile_of(nm)
    assert set(tiles.tolist()) == set(range(nm.tile_count))
    for t in range(nm.tile_count):
        members = np.nonzero(tiles == t)[0]
        i = int(members[np.argmax(nm.areas[members])])
        idx, point = nm.nearest_poly(nm.centres[i])
        assert tiles[idx] == t, (t, i, idx)
        assert np.allclose(point[[0, 2]], nm.centres[i, [0, 2]], atol=1e-4)
    refs = [nm.poly_ref(i) for i in range(nm.polygon_count)]
    assert len(set(refs)) == nm.polygon_count
    assert [nm.poly_index(r) for r in refs] == list(range(nm.polygon_count))
    with pytest.raises(IndexError):
        nm.poly_ref(nm.polygon_count)
    with pytest.raises(ValueError):
        nm.poly_index(2**40)


def test_tiled_neighbours_and_portals(solo_and_tiled):
    _, nm = solo_and_tiled
    tiles = tile_of(nm)
    portals = nm.portals()
    pairs = portals.pairs
    assert pairs.dtype == np.int64 and np.all(pairs[:, 0] < pairs[:, 1])
    assert len({tuple(p) for p in pairs.tolist()}) == len(pairs)
    assert [tuple(p) for p in pairs.tolist()] == sorted(tuple(p) for p in pairs.tolist())
    cross = tiles[pairs[:, 0]] != tiles[pairs[:, 1]]
    assert cross.sum() > 20 and (~cross).sum() > 0
    partners: dict[int, set[int]] = {}
    for a, b in pairs.tolist():
        partners.setdefault(a, set()).add(b)
        partners.setdefault(b, set()).add(a)
    # neighbours: every entry is a portal pair; symmetric, except on a tile-border
    # edge touching several polygons, where only the longest contact is listed
    asymmetric = 0
    for i, j in zip(*np.nonzero(nm.neighbours >= 0)):
        k = int(nm.neighbours[i, j])
        assert k in partners[int(i)]
        if i not in nm.neighbours[k]:
            asymmetric += 1
            assert tiles[i] != tiles[k]
            assert len([q for q in partners[k] if tiles[q] == tiles[i]]) >= 2
    assert asymmetric <= 0.05 * len(pairs)
    # portal ends: mesh vertices on an edge of both polygons (xz), at the same height
    verts = {tuple(v) for v in nm.vertices.tolist()}
    for (a, b), ends, width, is_cross in zip(pairs.tolist(), portals.endpoints, portals.widths, cross):
        assert width > 0 and width == pytest.approx(np.linalg.norm(ends[1] - ends[0]))
        for p in ends:
            assert tuple(p.tolist()) in verts
            assert xz_distance_to_edges(nm, a, p) < 1e-6
            assert xz_distance_to_edges(nm, b, p) < 1e-4
        if not is_cross:  # inside a tile both polygons hold the two vertices
            for poly in (a, b):
                ring = {tuple(nm.vertices[v]) for v in nm.polygons[poly] if v >= 0}
                assert {tuple(ends[0]), tuple(ends[1])} <= ring


def test_solo_neighbours_and_portals_match_the_poly_mesh(walled):
    """Solo: Detour's links give Recast's neighbour table, and the portals are its shared edges."""
    nm = walled
    P = nm.polygon_count
    counts = (nm.polygons >= 0).sum(axis=1)
    expected = []
    for i in range(P):
        for j in range(counts[i]):
            k = int(nm.neighbours[i, j])
            if k < 0:
                continue
            edge = {int(nm.polygons[i, j]), int(nm.polygons[i, (j + 1) % counts[i]])}
            assert edge <= set(nm.polygons[k][nm.polygons[k] >= 0].tolist()) and i in nm.neighbours[k]
            if i < k and (i, k) not in [e[0] for e in expected]:
                va, vb = nm.polygons[i, j], nm.polygons[i, (j + 1) % counts[i]]
                expected.append(((i, k), (nm.vertices[va], nm.vertices[vb])))
    expected.sort(key=lambda e: e[0])  # by (a, b); the first shared edge of a kept
    portals = nm.portals()
    assert [tuple(p) for p in portals.pairs.tolist()] == [e[0] for e in expected]
    assert np.array_equal(portals.endpoints, np.array([np.stack(e[1]) for e in expected]).reshape(-1, 2, 3))


def test_automatic_tiling_rule():
    small = build(floor(10, 10))  # 67 x 67 cells: solo
    assert small.tile_size == 0 and small.config()["autoTiled"] is False
    # 601 x 21 cells: longer than 512, tiles of 256 cells. (The far edges are kept off
    # cell boundaries: a solo grid ends there, a tile goes on and may count the next cell.)
    long = build(floor(90.1, 3.1))
    assert long.tile_size == 256 and long.tile_count == 3 and long.config()["tileGrid"] == (3, 1)
    assert adjacency_components(long) == 1
    assert long.raycast((-44, 0, 0), (44, 0, 0))[0]
    assert set(tile_of(long)[[long.nearest_poly((x, 0, 0))[0] for x in (-40, 0, 40)]]) == {0, 1, 2}
    solo = build(floor(90.1, 3.1), tile_size=0)
    assert solo.tile_size == 0 and solo.areas.sum() == pytest.approx(long.areas.sum(), rel=0.01)
    assert resolve_settings(AGENT, RecastParams(tile_size=64))["tile_size"] == 64
    assert resolve_settings(AGENT)["tile_size"] is None


def test_tile_size_validation_and_empty_tiles():
    with pytest.raises(pydantic.ValidationError):
        RecastParams(tile_size=8)
    with pytest.raises(pydantic.ValidationError):
        RecastParams(tile_size=-1)

    mesh = floor(10, 10)
    with pytest.raises(ValueError, match="tile_size"):
        _recast.build(mesh.vertices, mesh.faces, **{**resolve_settings(AGENT), "tile_size": 8})
    wall = slab((0.1, 3.0, 5.0), (0, 1.5, 0))
    wall.update_faces(np.abs(wall.face_normals[:, 1]) < 0.5)
    with pytest.raises(RuntimeError, match="Recast: no walkable polygons"):
        build(wall, tile_size=16)
    # two floors far apart: the tiles between them hold no triangle and are skipped
    apart = build(trimesh.util.concatenate([floor(4, 4), floor(4, 4, x=40.0)]), tile_size=16)
    assert apart.tile_count < apart.config()["tileGrid"][0] * apart.config()["tileGrid"][1]
    assert adjacency_components(apart) == 2


def test_tiled_build_drops_the_small_islands_a_solo_build_drops():
    """A plinth whose top (3.1 m², 49 cells, after the ledge filter and the erosion: under region_min_size² = 64) straddles
    a tile border: Recast keeps each half in its tile (a region at a tile border is never dropped), the join drops
    them as a solo build does; a larger plinth's top cut by two borders (225 cells) stays in both."""
    # 0.25 m cells, tiles of 32 cells: the grid starts at x = -12, so tile borders run along x = -4 and x = 4
    level = trimesh.util.concatenate([floor(24, 24), slab((3, 1.5, 3), (4, 0.75, 2)), slab((5, 1.5, 5), (-4, 0.75, -5))])
    solo, tiled = build(level, cell_size=0.25, tile_size=0), build(level, cell_size=0.25, tile_size=32)
    assert adjacency_components(solo) == adjacency_components(tiled) == 2  # the floor and the larger plinth's top
    assert tiled.config()["borderIslandPolygons"] > 0 and solo.config()["borderIslandPolygons"] == 0
    for nm in (solo, tiled):
        tops = nm.centres[:, 1] > 1.0
        assert np.all(np.abs(nm.centres[tops, 0] + 4) < 2.5)  # only the larger plinth's top is floor up there
        assert nm.areas[tops].sum() > 4.0
        assert nm.nearest_poly((4, 1.5, 2), extents=(0.5, 0.2, 0.5))[0] == -1  # no polygon of the small top for a query
    tiles = tile_of(tiled)
    # the larger top lies in four tiles (borders x = -4, z = -4), some under 64 cells, 225 in all: kept
    assert len(set(tiles[tiled.centres[:, 1] > 1.0].tolist())) == 4
    assert tiled.tile_first_polygon[0] == 0 and np.all(np.diff(tiled.tile_first_polygon) > 0)
    refs = [tiled.poly_ref(i) for i in range(tiled.polygon_count)]
    assert [tiled.poly_index(r) for r in refs] == list(range(tiled.polygon_count))
    assert np.all(tiled.polygons[tiled.polygons >= 0] < len(tiled.vertices))
    assert set(np.unique(tiled.polygons[tiled.polygons >= 0]).tolist()) == set(range(len(tiled.vertices)))
    assert set(tiled.detail_polygon.tolist()) == set(range(tiled.polygon_count))


def test_tiled_build_keeps_a_top_whose_strip_at_a_tile_border_makes_no_polygon():
    """A dumbbell's top (two 2.24 m squares and a 1.55 m bar, 1.5 m high, turned 90 degrees) that a solo build keeps
    (5.5 m²) lies across the tile border x = -4 of tiles of 16 and 32 cells; in the tile on its +x side its cells form
    a strip one cell wide, a region that makes no polygon. Summed over the regions with polygons only, the top had 56
    cells, under region_min_size² = 64, and both tiled builds dropped all of it (main at 328e52a); the strip's cells,
    joined across the border, count, and the top stays (its polygons without the strip)."""
    bars = [slab((2.24, 1.5, 2.24), (-2.24, 0.75, 0)), slab((2.24, 1.5, 2.24), (2.24, 0.75, 0)),
            slab((4.48, 1.5, 1.55), (0, 0.75, 0))]
    top = trimesh.util.concatenate(bars)
    top.apply_transform(trimesh.transformations.rotation_matrix(math.pi / 2, (0, 1, 0)))
    top.apply_translation((-3.73, 0, 4.59))
    level = trimesh.util.concatenate([floor(24, 24), top])
    solo = build(level, cell_size=0.25, tile_size=0)
    assert solo.areas[solo.centres[:, 1] > 1.0].sum() == pytest.approx(5.5)
    for tile_size in (16, 32):
        tiled = build(level, cell_size=0.25, tile_size=tile_size)
        assert tiled.config()["borderIslandPolygons"] == 0
        assert tiled.areas[tiled.centres[:, 1] > 1.0].sum() > 3.0
        assert adjacency_components(tiled) == adjacency_components(solo) == 2


def boxes(lo: np.ndarray, hi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Vertices (8k,3) and faces (12k,3) of k axis-aligned boxes with corners lo, hi (k,3)."""
    corner = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=float)
    verts = lo[:, None, :] + corner[None] * (hi - lo)[:, None, :]
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    tri = np.array([t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))])
    faces = tri[None] + 8 * np.arange(len(lo))[:, None, None]
    return verts.reshape(-1, 3), faces.reshape(-1, 3)


def room_grid(n: int, pitch: float = 8.0, wall: float = 0.3, door: float = 1.6) -> tuple[np.ndarray, np.ndarray]:
    """n x n rooms ``pitch`` m wide on one floor, a door in every inner wall, 4 pillars per room."""
    height, pillar, offset = 3.0, 0.6, 1.8
    size = n * pitch
    lo, hi = [[0.0, -0.2, 0.0]], [[size, 0.0, size]]
    for i, line in enumerate(np.arange(n + 1) * pitch):
        for start in np.arange(n) * pitch:
            if i in (0, n):
                parts = [(start, start + pitch)]
            else:
                parts = [(start, start + (pitch - door) / 2), (start + (pitch + door) / 2, start + pitch)]
            for a, b in parts:
                lo += [[a, -0.2, line - wall / 2], [line - wall / 2, -0.2, a]]
                hi += [[b, height, line + wall / 2], [line + wall / 2, height, b]]
    centres = (np.arange(n) + 0.5) * pitch
    x, z = (c.ravel() for c in np.meshgrid(centres, centres))
    for dx in (-offset, offset):
        for dz in (-offset, offset):
            lo += np.column_stack([x + dx - pillar / 2, np.full(x.size, -0.2), z + dz - pillar / 2]).tolist()
            hi += np.column_stack([x + dx + pillar / 2, np.full(x.size, height), z + dz + pillar / 2]).tolist()
    return boxes(np.array(lo), np.array(hi))


def test_level_too_big_for_solo_is_tiled_automatically(capsys):
    vertices, faces = room_grid(44)  # 352 x 352 m, 1936 rooms, 7744 pillars
    t0 = time.perf_counter()
    nm = build_navmesh(vertices, faces, AGENT)
    seconds = time.perf_counter() - t0
    with capsys.disabled():
        print(f"\nroom grid 44 x 44: {nm.polygon_count} polygons, {len(nm.vertices)} vertices, "
              f"{nm.tile_count} tiles of {nm.tile_size} cells, {seconds:.2f} s")
    assert nm.tile_size == 256 and nm.tile_count == nm.config()["tileGrid"][0] ** 2
    assert len(nm.vertices) > 65535  # more than one Recast poly mesh can index
    assert nm.polygon_count > 30000
    assert adjacency_components(nm) == 1
    # a ray along a row of doors stays clear from end to end; one into a wall is not
    door_row = 4.0 + 8.0 * 20
    assert nm.raycast((1.0, 0, door_row), (351.0, 0, door_row))[0]
    assert not nm.raycast((1.0, 0, 1.0), (351.0, 0, 1.0 + 8.0))[0]


# ------------------------------------------------------------------ Recast's arithmetic and filters


@pytest.mark.parametrize("ch", [0.05, 0.1, 0.15, 0.2, 0.03])
@pytest.mark.parametrize("cs", [0.133, 0.15, 0.3, 0.1])
def test_voxel_values_match_recasts_single_precision(cs, ch):
    f = np.float32
    agent = types.SimpleNamespace(radius=0.4, height=2.0, max_climb=0.4, max_slope=45.0)
    for climb in (0.4, 0.5, 0.3, 0.45, 0.6):
        agent.max_climb = climb
        params = RecastParams(cell_size=cs, cell_height=ch)
        c = build_navmesh(floor(6, 6).vertices, floor(6, 6).faces, agent, params).config()
        # RecastDemo's Sample_SoloMesh: every conversion in float
        assert c["walkableClimb"] == int(np.floor(f(climb) / f(ch))), (cs, ch, climb)
        assert c["walkableHeight"] == max(int(np.ceil(f(2.0) / f(ch))), 3)
        assert c["walkableRadius"] == int(np.ceil(f(0.4) / f(cs)))
        assert c["maxEdgeLen"] == int(f(12.0) / f(cs))
        assert c["minRegionArea"] == int(f(8.0) * f(8.0)) and c["mergeRegionArea"] == int(f(20.0) * f(20.0))
        assert c["detailSampleDist"] == pytest.approx(float(f(cs) * f(6.0)), rel=1e-7)
        assert c["detailSampleMaxError"] == pytest.approx(float(f(ch) * f(1.0)), rel=1e-7)
    # the cases that double arithmetic got wrong: 0.4 / 0.05 and 0.5 / 0.05
    assert int(np.floor(f(0.4) / f(0.05))) == 8 and int(np.floor(f(0.5) / f(0.05))) == 10


def stairs(riser: float, steps: int = 10, tread: float = 0.25, width: float = 1.6) -> tuple[trimesh.Trimesh, float, float]:
    """A lower floor (x < 0), ``steps`` solid steps up along +x, an upper deck; (mesh, deck height, deck start x)."""
    parts = [slab((6.0, 0.2, width), (-3.0, -0.1, width / 2))]
    for i in range(steps):
        top = (i + 1) * riser
        parts.append(slab((tread, top + 0.2, width), ((i + 0.5) * tread, top / 2 - 0.1, width / 2)))
    deck, start = steps * riser, steps * tread
    parts.append(slab((6.0, 0.2, width), (start + 3.0, deck - 0.1, width / 2)))
    return trimesh.util.concatenate(parts), deck, start


def floors_joined(mesh: trimesh.Trimesh, deck: float, start: float, width: float, **params) -> bool:
    agent = types.SimpleNamespace(radius=0.4, height=2.0, max_climb=0.4, max_slope=60.0)
    try:
        nm = build(mesh, agent, cell_size=0.133, cell_height=0.05, **params)
    except RuntimeError:  # nothing walkable left
        return False
    g = nx.Graph()
    g.add_nodes_from(range(nm.polygon_count))
    g.add_edges_from(nm.portals().pairs.tolist())
    a, b = nm.nearest_poly((-3.0, 0.0, width / 2))[0], nm.nearest_poly((start + 3.0, deck, width / 2))[0]
    return a >= 0 and b >= 0 and nx.has_path(g, a, b)


@pytest.mark.parametrize("riser", [0.245, 0.25])
def test_ledge_filter_cuts_stairs_and_can_be_switched_off(riser):
    # map-piece agent and grid (configs/map_piece.yaml); measured on 40 stair cases
    # in docs/navmesh.md: Recast's ledge filter cuts most narrow ones, its first rule alone (drops) none
    mesh, deck, start = stairs(riser)
    assert not floors_joined(mesh, deck, start, 1.6, ledge_filter="recast")
    assert floors_joined(mesh, deck, start, 1.6, ledge_filter="drops")
    assert floors_joined(mesh, deck, start, 1.6, ledge_filter="off")
    # neither makes a step higher than max_climb walkable
    high, deck, start = stairs(0.45)
    assert not floors_joined(high, deck, start, 1.6, ledge_filter="drops")
    assert not floors_joined(high, deck, start, 1.6, ledge_filter="off")


def test_filter_switches_reach_recast():
    # a floor with a 0.3 m box: the ledge filter trims the box top and the floor's rim
    mesh = trimesh.util.concatenate([floor(10, 10), slab((3.0, 0.3, 3.0), (0.0, 0.15, 0.0))])
    on = build(mesh)
    off = build(mesh, filter_low_hanging_obstacles=False, ledge_filter="off", filter_low_height_spans=False)
    assert off.areas.sum() > on.areas.sum() * 1.02


# ------------------------------------------------------------------ region partitions

PARTITIONS = ("auto", "watershed", "monotone", "layers")


@pytest.mark.parametrize("partition", PARTITIONS)
def test_every_partition_builds_a_walkable_navmesh(partition):
    mesh = trimesh.util.concatenate([floor(10, 10), slab((0.5, 3, 6), (0, 1.5, -2))])
    nm = build(mesh, partition=partition)
    walkable = 10 * 10 - 0.5 * 6
    assert adjacency_components(nm) == 1
    assert walkable * 0.75 < nm.areas.sum() < walkable
    assert len(nm.region_overlaps) == 0


@pytest.fixture(scope="module")
def three_storeys():
    level = building()  # 3 storeys, one switchback stairwell
    return level, level.metadata["design_agent"]


def centre_height_jumps(nm: NavMesh) -> np.ndarray:
    """(E,) |dy| between the centres (on the detail surface) of each pair of neighbour polygons, m."""
    pairs = nm.portals().pairs
    return np.abs(nm.centres[pairs[:, 0], 1] - nm.centres[pairs[:, 1], 1])


@pytest.mark.parametrize("tile_size", [None, 128])
def test_layers_and_monotone_do_not_join_storeys_of_a_stairwell(three_storeys, tile_size):
    level, design = three_storeys
    agent = types.SimpleNamespace(radius=design["radius"], height=design["height"],
                                  max_climb=design["max_climb"], max_slope=design["max_slope_deg"])
    meshes = {p: build(level.mesh, agent, partition=p, tile_size=tile_size) for p in PARTITIONS}
    assert meshes["watershed"].tile_count == (1 if tile_size is None else 2)
    # watershed: one region of the stairwell overlaps itself, polygons 5 m apart are neighbours
    (overlap,) = meshes["watershed"].region_overlaps
    (well,) = level.metadata["stairwells"]
    assert well["x0"] < overlap[0] < well["x1"] and well["z0"] < overlap[2] < well["z1"]
    # Recast's detail mesh read three of that region's polygons (storey 2's floor over flight 0) from
    # the flight below: their centres sat 5.17 m under their neighbours' (measured before the detail
    # rule); the extension rebuilt them from their own storey
    assert len(meshes["watershed"].detail_redone_polygons) == 3
    for partition in PARTITIONS:
        nm = meshes[partition]
        assert adjacency_components(nm) == 1 and centre_height_jumps(nm).max() <= agent.height, partition
    for partition in ("auto", "monotone", "layers"):
        nm = meshes[partition]
        assert len(nm.region_overlaps) == 0 and len(nm.detail_redone_polygons) == 0, partition
    # the stairwell lies in the first tile of the tiled build: auto redid that one only
    assert meshes["auto"].repartitioned_tiles.tolist() == [[0, 0]]


MESH_ARRAYS = ("vertices", "polygons", "neighbours", "area_ids", "region_ids",
               "detail_vertices", "detail_triangles", "detail_polygon")


def same_arrays(a: NavMesh, b: NavMesh) -> bool:
    return all(np.array_equal(getattr(a, name), getattr(b, name)) for name in MESH_ARRAYS)


def test_auto_without_overlaps_is_watershed(shared_data):
    from g2s_core.mesh import load_mesh
    nav_test, _ = load_mesh(shared_data / "nav_test.obj")
    for mesh, tile_size in ((nav_test, None), (ramp_level(), 32)):
        auto, watershed = build(mesh, partition="auto", tile_size=tile_size), build(mesh, partition="watershed",
                                                                                  tile_size=tile_size)
        assert len(watershed.region_overlaps) == 0 and len(auto.repartitioned_tiles) == 0
        assert same_arrays(auto, watershed)
        assert np.array_equal(auto.portals().endpoints, watershed.portals().endpoints)


def test_auto_fallback_on_the_same_heightfield_is_a_fresh_fallback_build(three_storeys):
    # the watershed pass (its distance field and regions) leaves nothing that changes the fallback's result
    level, design = three_storeys
    agent = types.SimpleNamespace(radius=design["radius"], height=design["height"],
                                  max_climb=design["max_climb"], max_slope=design["max_slope_deg"])
    auto, monotone = build(level.mesh, agent, partition="auto"), build(level.mesh, agent, partition="monotone")
    assert auto.tile_count == 1 and auto.repartitioned_tiles.tolist() == [[0, 0]]
    assert same_arrays(auto, monotone)


def tile_polygons(nm: NavMesh, k: int) -> np.ndarray:
    """(n, nvp, 3) world vertices of the polygons of the ``k``-th tile holding polygons, NaN padded."""
    first = nm.tile_first_polygon
    end = first[k + 1] if k + 1 < len(first) else nm.polygon_count
    polygons = nm.polygons[first[k]:end]
    return np.where((polygons >= 0)[..., None], nm.vertices[polygons], np.nan)


def test_tiled_auto_redoes_only_the_tiles_that_overlap(three_storeys):
    level, design = three_storeys
    agent = types.SimpleNamespace(radius=design["radius"], height=design["height"],
                                  max_climb=design["max_climb"], max_slope=design["max_slope_deg"])
    meshes = {p: build(level.mesh, agent, partition=p, tile_size=128) for p in ("auto", "watershed", "monotone")}
    # watershed overlaps in tile (0, 0) only; auto takes that tile from monotone, the other from watershed
    watershed = meshes["watershed"]
    (overlap,) = watershed.region_overlaps
    config = watershed.config()
    assert config["tileGrid"] == (2, 1) and (overlap[0] - config["bmin"][0]) // (128 * config["cs"]) == 0
    assert meshes["auto"].repartitioned_tiles.tolist() == [[0, 0]]
    assert np.array_equal(tile_polygons(meshes["auto"], 0), tile_polygons(meshes["monotone"], 0), equal_nan=True)
    assert np.array_equal(tile_polygons(meshes["auto"], 1), tile_polygons(meshes["watershed"], 1), equal_nan=True)
    assert not np.array_equal(tile_polygons(meshes["monotone"], 1), tile_polygons(meshes["watershed"], 1),
                              equal_nan=True)


MAP_AGENT = types.SimpleNamespace(radius=0.5, height=2.0, max_climb=0.4, max_slope=45.0)


def test_auto_redoes_a_maze_whose_watershed_region_winds_through_it():
    # watershed makes one region of most of the maze's corridors, a contour of 1483 vertices that
    # rcBuildPolyMesh took 14 s over (docs/navmesh.md, "Slow case"); auto takes the tile from monotone
    level = maze(seed=0, cells=32)
    auto, monotone = (build(level.mesh, MAP_AGENT, partition=p) for p in ("auto", "monotone"))
    assert auto.tile_count == 1 and auto.repartitioned_tiles.tolist() == [[0, 0]]
    assert len(auto.region_overlaps) == 0 and same_arrays(auto, monotone)
    assert adjacency_components(auto) == 1


def test_watershed_keeps_its_long_region_on_a_small_maze():
    # 303 contour vertices on a 16-cell maze (0.16 s): past the bound, so auto redoes it, but watershed
    # is watershed whatever the contour
    level = maze(seed=0, cells=16)
    meshes = {p: build(level.mesh, MAP_AGENT, partition=p) for p in ("auto", "watershed", "monotone")}
    assert meshes["auto"].repartitioned_tiles.tolist() == [[0, 0]] and same_arrays(meshes["auto"], meshes["monotone"])
    assert len(meshes["watershed"].repartitioned_tiles) == 0
    assert not same_arrays(meshes["watershed"], meshes["monotone"])
    regions, counts = np.unique(meshes["watershed"].region_ids, return_counts=True)
    assert counts.max() > meshes["watershed"].polygon_count / 2  # one region holds most of the maze


def spiral_tower(turns: int = 3, steps_per_turn: int = 16, storey: float = 3.6, inner: float = 1.0,
                 outer: float = 3.0) -> trimesh.Trimesh:
    """A round tower (centred on the y axis): ground floor, central newel post, outer wall, and a spiral
    stair of ``turns`` full turns winding anticlockwise up between them, one ``storey`` per turn; each
    step a 0.2 m thick slab (four flat pieces of the annulus sector), risers ``storey / steps_per_turn``."""
    height = turns * storey + 3.0
    upright = trimesh.transformations.rotation_matrix(-math.pi / 2, (1, 0, 0))  # trimesh's z axis -> y

    def column(mesh: trimesh.Trimesh, bottom: float, top: float) -> trimesh.Trimesh:
        mesh.apply_transform(upright)
        return mesh.apply_translation((0.0, (bottom + top) / 2, 0.0))

    parts = [
        column(trimesh.creation.cylinder(radius=outer + 0.3, height=0.2, sections=48), -0.2, 0.0),
        column(trimesh.creation.cylinder(radius=inner, height=height, sections=32), 0.0, height),
        column(trimesh.creation.annulus(r_min=outer, r_max=outer + 0.3, height=height, sections=48), 0.0, height),
    ]
    step = 2 * math.pi / steps_per_turn
    for i in range(turns * steps_per_turn):
        top = (i + 1) * storey / steps_per_turn
        angles = np.linspace(i * step, (i + 1) * step, 5)
        for a0, a1 in zip(angles[:-1], angles[1:]):
            corners = [(r * math.cos(a), y, r * math.sin(a)) for r in (inner, outer) for a in (a0, a1)
                       for y in (top - 0.2, top)]
            parts.append(trimesh.convex.convex_hull(np.array(corners)))
    return trimesh.util.concatenate(parts)


def test_auto_keeps_the_turns_of_a_spiral_stair_apart():
    # the map-analysis agent; turns 3.6 m apart, the agent 2 m tall
    agent = types.SimpleNamespace(radius=0.5, height=2.0, max_climb=0.4, max_slope=45.0)
    tower = spiral_tower()
    # watershed makes a region of the stair that winds over itself: Recast then gets no polygon at all
    with pytest.raises(RuntimeError, match=r"no walkable polygons \(1 region\(s\) overlap themselves in plan"):
        build(tower, agent, partition="watershed")
    nm = build(tower, agent)
    assert nm.repartitioned_tiles.tolist() == [[0, 0]] and len(nm.region_overlaps) == 0
    assert adjacency_components(nm) == 1 and centre_height_jumps(nm).max() <= agent.height
    assert nm.centres[:, 1].min() < 0.5 and nm.centres[:, 1].max() > 3 * 3.6 - 1.0  # the ground to the top step
    assert len(nm.detail_redone_polygons) == 0  # no detail read from another turn here


def test_tiled_records_and_parts_follow_the_solo_build_on_a_spiral_tower():
    """The spiral tower beside a floor, cells of 0.25 m. Watershed makes one region of the stair that overlaps itself
    and no polygon of it, which a solo build reports. In 2 tiles of 48 cells the tower's tile holds no polygon and was
    left out with its record (main at 328e52a: no overlap reported); it is reported now. With region_min_size 40
    (1,600 cells, more than the tower's floor) a solo build drops the tower and reports nothing; in tiles of 32 cells
    main dropped some of its polygons and kept the overlap record of a dropped region (and 5 pieces of the stair
    that no tile border touches); the tower's regions, joined by their spans across the tiles, are one group under
    1,600 cells, dropped whole with their record. With region_min_size 20 a solo build keeps the stair (auto redoes
    the tower's tile); main dropped it in tiles of 32 cells, as the group of polygons Detour links, and with it the
    tile's repartitioned record."""
    agent = types.SimpleNamespace(radius=0.5, height=2.0, max_climb=0.4, max_slope=45.0)
    level = trimesh.util.concatenate([spiral_tower(), floor(12, 12, x=16.0)])
    for tile_size, min_size, overlaps in ((48, 8, 1), (32, 40, 0)):
        solo, tiled = (build(level, agent, partition="watershed", tile_size=ts, region_min_size=min_size, cell_size=0.25)
                       for ts in (0, tile_size))
        assert len(solo.region_overlaps) == len(tiled.region_overlaps) == overlaps
        assert np.all(np.abs(tiled.region_overlaps[:, [0, 2]]) < 3.3)  # in the tower
        assert not np.any(tiled.centres[:, 1] > 1.0) and adjacency_components(tiled) == 1
    solo, tiled = (build(level, agent, tile_size=ts, region_min_size=20, cell_size=0.25) for ts in (0, 32))
    assert solo.repartitioned_tiles.tolist() == tiled.repartitioned_tiles.tolist() == [[0, 0]]
    assert tiled.config()["borderIslandPolygons"] == 0 and np.sum(tiled.centres[:, 1] > 3 * 3.6 - 1.0) > 0
    assert adjacency_components(solo) == adjacency_components(tiled) == 2


def detail_overshoot(nm: NavMesh) -> np.ndarray:
    """(P,) metres by which each polygon's detail vertices leave the height range of its own vertices."""
    vy = np.where(nm.polygons >= 0, nm.vertices[np.maximum(nm.polygons, 0), 1], np.nan)
    owner = np.repeat(nm.detail_polygon, 3)
    y = nm.detail_vertices[nm.detail_triangles.ravel(), 1]
    out = np.zeros(nm.polygon_count)
    np.maximum.at(out, owner, np.maximum(np.nanmin(vy, 1)[owner] - y, y - np.nanmax(vy, 1)[owner]))
    return out


def test_detail_heights_stay_on_the_polygons_own_turn_of_a_spiral_stair():
    # The tower with a 3 m wide stair. Its monotone region 3 winds round the newel and comes back one
    # turn (3.6 m) lower beside the triangle of stair at (1.7, 0.7), (0.7, 1.7), (2.7, 1.7), vertices
    # 7.68-8.18 m high: Recast's detail mesh read that triangle's heights over its bounding box from
    # its region, and its sample at the box corner (1.7, 1.7) from the turn below, 4.43 m, which put
    # the polygon's centre at 5.55 m (measured before the rule). Rebuilt with the turn below hidden,
    # the detail is the triangle itself (+ Recast's one cell height), its centre on the stair.
    # Since the low-height filter keeps a gap of the agent's height (branch lowceil47), the ground
    # under the first turn holds 0.7 m² more floor, the regions are cut otherwise, and the triangle
    # (region 3 still) is read from its own turn without a rebuild; the polygon rebuilt is one of the
    # first turn's, 2.3-2.55 m high in region 2, its centre on it.
    agent = types.SimpleNamespace(radius=0.5, height=2.0, max_climb=0.4, max_slope=45.0)
    nm = build(spiral_tower(outer=4.0), agent)
    triangle = np.array([[1.7, 7.68, 0.7], [0.7, 8.18, 1.7], [2.7, 7.68, 1.7]])
    corners_of = [nm.vertices[nm.polygons[p][nm.polygons[p] >= 0]] for p in range(nm.polygon_count)]
    (kept,) = [p for p, c in enumerate(corners_of) if c.shape == triangle.shape and np.allclose(c, triangle, atol=0.01)]
    assert nm.region_ids[kept] == 3
    assert 7.68 <= nm.centres[kept, 1] <= 8.18 + agent.max_climb
    (lifted,) = nm.detail_redone_polygons
    corners = nm.vertices[nm.polygons[lifted][nm.polygons[lifted] >= 0]]
    np.testing.assert_allclose(corners, [[-2.3, 2.55, -2.55], [-2.8, 2.3, -1.55], [-1.05, 2.55, -1.55]], atol=0.01)
    assert nm.region_ids[lifted] == 2
    assert 2.3 <= nm.centres[lifted, 1] <= 2.55 + agent.max_climb
    # every polygon's detail stays within a cell height or two of its own vertices
    assert detail_overshoot(nm).max() < 2 * 0.125


def test_partition_is_validated():
    with pytest.raises(pydantic.ValidationError):
        RecastParams(partition="spiral")
    assert resolve_settings(AGENT, RecastParams(partition="layers"))["partition"] == "layers"
    assert RecastParams().partition == "auto"
    with pytest.raises(ValueError, match="partition must be"):
        _recast.build(floor(4, 4).vertices, floor(4, 4).faces, **{**resolve_settings(AGENT), "partition": "spiral"})


def detail_surface_points(nm: NavMesh, polygons: np.ndarray, divisions: int = 4) -> np.ndarray:
    """(N,3) points on the detail triangles of ``polygons``: a barycentric grid of ``divisions`` per edge on each."""
    u, v = np.meshgrid(np.arange(divisions + 1), np.arange(divisions + 1))
    keep = (u + v) <= divisions
    u, v = u[keep] / divisions, v[keep] / divisions
    corners = nm.detail_vertices[nm.detail_triangles[np.isin(nm.detail_polygon, polygons)]]
    a, b, c = corners[:, None, 0], corners[:, None, 1], corners[:, None, 2]
    return (a + u[None, :, None] * (b - a) + v[None, :, None] * (c - a)).reshape(-1, 3)


def test_detail_triangles_left_off_the_floor_are_rebuilt_onto_the_hills():
    # Generated terrain, 80 m: Recast triangulates polygons too narrow for inside samples from their
    # edge samples alone, and some triangles there pass over a trough or under a crest by more than
    # the climb. Those polygons are rebuilt (finer samples, a triangulation whose diagonals cross the
    # polygon); their detail then follows the hills: within the climb of the terrain's own triangles,
    # plus Recast's offsets (one cell height up, heights rounded up to a cell height).
    from g2s_plugins.samples.outdoor import terrain

    agent = types.SimpleNamespace(radius=0.5, height=2.0, max_climb=0.4, max_slope=45.0)
    mesh = terrain(size=80.0, seed=0).mesh
    nm = build(mesh, agent)
    resampled = nm.detail_resampled_polygons
    assert len(resampled) > 0 and np.all(np.diff(resampled) > 0)
    _, gap, _ = trimesh.proximity.ProximityQuery(mesh).on_surface(detail_surface_points(nm, resampled))
    assert gap.max() <= agent.max_climb + 2 * 0.125
    # the rebuilt polygons still bend with the hills rather than lying flat
    rise = np.ptp(nm.detail_vertices[np.unique(nm.detail_triangles[np.isin(nm.detail_polygon, resampled)])][:, 1])
    assert rise > 1.0


def test_best_triangle_per_polygon_is_the_sorts_last_of_the_highest():
    # owners in runs (as the extension writes them): the highest score of each, the later of equal ones (-0.0
    # equals 0.0), -1 for polygons 2 and 4, which own no triangle
    from g2s_plugins.recast.navmesh import _best_per_owner

    owner = np.array([0, 0, 0, 1, 1, 3, 3, 3])
    score = np.array([0.5, -np.inf, 0.5, 0.0, -0.0, -np.inf, -np.inf, 0.2])
    assert _best_per_owner(score, owner, 5).tolist() == [2, 4, -1, 7, -1]
    # out of order or with a NaN (the highest, as a sort puts it): the same rule
    assert _best_per_owner(score[::-1], owner[::-1], 5).tolist() == [7, 4, -1, 0, -1]
    assert _best_per_owner(np.array([np.nan, 1.0, 0.0]), np.array([0, 0, 1]), 2).tolist() == [0, 2]
    assert _best_per_owner(np.zeros(0), np.zeros(0, dtype=np.int32), 2).tolist() == [-1, -1]
    rng = np.random.default_rng(4)
    for _ in range(50):
        owner = np.sort(rng.integers(0, 9, 40))
        score = rng.choice([-np.inf, -1.0, 0.0, 0.25, 0.25], 40)
        order = np.lexsort((score, owner))
        last = np.r_[owner[order][1:] != owner[order][:-1], True]
        expected = np.full(9, -1)
        expected[owner[order][last]] = order[last]
        assert _best_per_owner(score, owner, 9).tolist() == expected.tolist()


def test_bounds_are_each_columns_extremes():
    from g2s_plugins.recast.build import bounds

    points = np.array([[1.0, -2.0, 3.0], [-4.0, 5.0, 0.5], [2.0, 0.0, -6.0]], dtype=np.float32)
    lo, hi = bounds(points)
    assert lo.tolist() == [-4.0, -2.0, -6.0] and hi.tolist() == [2.0, 5.0, 3.0]
    assert lo.dtype == hi.dtype == np.float32


def test_surface_of_a_polygon_without_area_in_plan_or_without_triangles_is_its_vertex_mean():
    """Polygon 0: the unit square at height 1, one triangle (0,1,0)-(1,1,0)-(0,1,1) under it: centre x, z from
    the triangle's centroid (1/3, 1/3), lifted to 1. Polygon 1: a wall x = 5, its triangle upright (no area in
    plan): x, z the mean of its 4 vertices (5, 0.5), the height read off its triangle (no barycentric weights in
    plan: its third vertex, 1). Polygon 2: no triangle: the mean of its 3 vertices (7, 2/3, 1/3)."""
    from g2s_plugins.recast.navmesh import _surface

    verts = np.array([[0, 1, 0], [1, 1, 0], [1, 1, 1], [0, 1, 1], [5, 0, 0], [5, 0, 1], [5, 1, 1], [5, 1, 0],
                      [6, 0, 0], [8, 1, 0], [7, 1, 1]], dtype=np.float64)
    polys = np.array([[0, 1, 2, 3], [4, 5, 6, 7], [8, 9, 10, -1]])
    dverts = np.array([[0, 1, 0], [1, 1, 0], [0, 1, 1], [5, 0, 0], [5, 0, 1], [5, 1, 0]], dtype=np.float64)
    dtris = np.array([[0, 1, 2], [3, 4, 5]])
    centres, normals, areas = _surface(3, verts, polys, dverts, dtris, np.array([0, 1]))
    np.testing.assert_allclose(centres, [[1 / 3, 1, 1 / 3], [5, 1, 0.5], [7, 2 / 3, 1 / 3]], rtol=0, atol=1e-15)
    assert normals.tolist() == [[0, 1, 0], [-1, 0, 0], [0, 1, 0]] and areas.tolist() == [0.5, 0.5, 0]
