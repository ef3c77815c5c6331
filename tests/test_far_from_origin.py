"""A level far from the origin gives the navmesh and structure of the same level at the origin, translated.

Recast and Embree work in single precision; the navmesh is built, and the rays are cast, in a local frame
(g2s_plugins/local_frame.py); NavMesh and RayCaster take and return world coordinates (docs/navmesh.md, "Levels
far from the origin").
"""

from __future__ import annotations

import types

import numpy as np
import pytest
import trimesh
from scipy.spatial import cKDTree

import g2s_core
from g2s_core.mesh import generate_level, load_mesh
from g2s_plugins._raycasting import RayCaster
from g2s_plugins.local_frame import NEAR_ORIGIN, local_origin
from g2s_plugins.recast import RecastParams, SettingsError, build_navmesh, resolve_settings
from g2s_plugins.recast.build import check_grid

AGENT = types.SimpleNamespace(radius=0.3, height=2.0, max_climb=0.4, max_slope=45.0)
MM = 1e-3


def moved(mesh: trimesh.Trimesh, shift) -> trimesh.Trimesh:
    return trimesh.Trimesh(vertices=mesh.vertices + np.asarray(shift, dtype=np.float64), faces=mesh.faces,
                           process=False)


def positions(graph) -> np.ndarray:
    return np.array([p for _, p in graph.nodes(data="pos")], dtype=np.float64)


def farthest_unmatched(a: np.ndarray, b: np.ndarray) -> float:
    """The largest distance from a point of either set to the nearest point of the other, m."""
    return float(max(cKDTree(a).query(b)[0].max(), cKDTree(b).query(a)[0].max()))


@pytest.mark.parametrize("roundness, centre, expected", [
    ("near the origin: untranslated", 1024.0, 0.0),
    ("just beyond: whole kilometres", 1025.0, 1000.0),
    ("a round move of a level centred at 16.8 m", 10016.8, 10000.0),
    ("the same below the origin", -9983.2, -10000.0),
    ("no multiple of 10 km within 1,024 m", 12345.678, 12000.0),
    ("two kilometres as near: the lower", 15500.0, 15000.0),
    ("a multiple of 100 km beats a nearer whole kilometre", 99_100.0, 100_000.0),
    ("UTM-like", 5_412_345.0, 5_412_000.0),
])
def test_local_origin_is_the_roundest_whole_number_near_the_centre(roundness, centre, expected):
    lo, hi = np.array([centre - 30.0, 0.0, 0.0]), np.array([centre + 30.0, 0.0, 0.0])
    assert local_origin(lo, hi).tolist() == [expected, 0.0, 0.0]


def test_a_level_near_the_origin_is_built_untranslated():
    level = generate_level("sample:dungeon")
    nm = build_navmesh(level.vertices, level.faces, AGENT, RecastParams())
    assert np.abs(level.vertices).max() > 50 and nm.local_origin.tolist() == [0.0, 0.0, 0.0]
    assert "local_origin" not in nm.stats()  # structure.json of such a level is unchanged
    shifted = build_navmesh(level.vertices + [0.0, 3 * NEAR_ORIGIN, 0.0], level.faces, AGENT, RecastParams())
    assert shifted.local_origin.tolist() == [0.0, 3000.0, 0.0]
    assert shifted.stats()["local_origin"] == [0.0, 3000.0, 0.0]


@pytest.fixture(scope="module")
def dungeon_runs():
    level = generate_level("sample:dungeon")
    shifts = [(0.0, 0.0, 0.0), (1e4, 0.0, 1e4), (1e6, 0.0, 1e6), (1e7, 0.0, -1e7), (1e6, 1e6, 1e6)]
    return [(np.array(shift), g2s_core.run(moved(level, shift), "map_analysis")) for shift in shifts]


def test_a_generated_level_moved_far_gives_the_same_navmesh(dungeon_runs):
    (_, at_origin), *far = dungeon_runs
    reference = at_origin.context.navmesh
    for shift, result in far:
        navmesh = result.context.navmesh
        assert navmesh.local_origin.tolist() == shift.tolist()  # the move is round: Recast sees the origin's level
        assert navmesh.polygon_count == reference.polygon_count
        assert np.abs(navmesh.centres - shift - reference.centres).max() < MM
        assert np.abs(navmesh.vertices - shift - reference.vertices).max() < MM
        assert np.abs(navmesh.portals().endpoints - shift - reference.portals().endpoints).max() < MM


def test_a_generated_level_moved_far_gives_the_same_structure(dungeon_runs):
    (_, at_origin), *far = dungeon_runs
    reference = at_origin.structure
    for shift, result in far:
        structure = result.structure
        assert (structure.number_of_nodes(), structure.number_of_edges()) == \
               (reference.number_of_nodes(), reference.number_of_edges())
        assert farthest_unmatched(positions(structure) - shift, positions(reference)) < MM


def test_a_level_moved_by_a_non_round_distance_is_built_as_its_copy_near_the_origin():
    # 12,345.678 m out, the local origin is 12,000 m: Recast sees the level moved by 345.678 m, as a copy of it
    # moved by 345.678 m is built (untranslated: it is near the origin)
    level = generate_level("sample:dungeon")
    far = build_navmesh(level.vertices + [12345.678, 0.0, 12345.678], level.faces, AGENT, RecastParams())
    near = build_navmesh(level.vertices + [345.678, 0.0, 345.678], level.faces, AGENT, RecastParams())
    assert far.local_origin.tolist() == [12000.0, 0.0, 12000.0] and not near.local_origin.any()
    assert far.polygon_count == near.polygon_count
    assert np.abs(far.centres - [12000.0, 0.0, 12000.0] - near.centres).max() < 1e-6


def test_queries_take_and_return_world_coordinates():
    """A 20 x 10 m floor with a wall across its middle, at the origin and 10,000 km out (x, y and z)."""
    shift = np.array([1e7, 1e4, -1e7])
    floor = trimesh.creation.box(extents=(20.0, 0.2, 10.0))
    floor.apply_translation((0.0, -0.1, 0.0))
    wall = trimesh.creation.box(extents=(0.5, 3.0, 6.0))
    wall.apply_translation((0.0, 1.5, 0.0))
    level = trimesh.util.concatenate([floor, wall])
    near = build_navmesh(level.vertices, level.faces, AGENT, RecastParams())
    far = build_navmesh(level.vertices + shift, level.faces, AGENT, RecastParams())
    assert far.local_origin.tolist() == shift.tolist()

    A = np.array([[-8, 0, -4.2], [-8, 0, 0], [-8, 0, 4.2], [100, 0, 100]], dtype=float)
    B = np.array([[8, 0, -4.2], [8, 0, 0], [-2, 0, 2.0], [0, 0, 0]], dtype=float)
    assert far.raycast_many(A + shift, B + shift).tolist() == near.raycast_many(A, B).tolist() == \
        [True, False, True, False]
    assert far.raycast(A[1] + shift, B[1] + shift) == near.raycast(A[1], B[1])  # the same hit parameter t

    index, point = far.nearest_poly(np.array([-8.0, 0.05, -4.0]) + shift)
    assert index >= 0 and np.abs(point - shift - [-8.0, 0.0, -4.0]).max() < 0.3  # on the floor, under the point
    assert (index, (point - shift).tolist()) == (near.nearest_poly((-8.0, 0.05, -4.0))[0],
                                                 near.nearest_poly((-8.0, 0.05, -4.0))[1].tolist())
    up = np.array([0.0, 0.3, 0.0])  # 0.3 m above the floor
    gaps = far.segment_surface_gaps(A[:2] + shift + up, B[:2] + shift + up, step=0.25, reach=1.0)
    assert gaps.tolist() == near.segment_surface_gaps(A[:2] + up, B[:2] + up, step=0.25, reach=1.0).tolist()
    assert gaps[0] == pytest.approx(0.3, abs=0.05)
    assert far.segment_surface_gap(A[0] + shift + up, B[0] + shift + up, step=0.25, reach=1.0) == gaps[0]

    config, reference = far.config(), near.config()
    assert np.asarray(config["bmin"]) - shift == pytest.approx(reference["bmin"], abs=1e-9)
    assert np.asarray(config["bmax"]) - shift == pytest.approx(reference["bmax"], abs=1e-9)
    assert np.abs(far.detail_vertices - shift - near.detail_vertices).max() < 1e-6


def test_a_level_too_long_for_single_precision_is_refused_by_its_size():
    # 8.4e6 m long: Recast's coordinates reach 4.2e6 m from the local origin, where single precision keeps 0.5 m
    strip = np.array([[-4.2e6, 0.0, 0.0], [4.2e6, 1.0, 2.0]])
    with pytest.raises(SettingsError, match=r"^mesh: the level \(8\.4e\+06 x 2 m \(x, z\), 1 m tall\) reaches "
                                            r"4\.2e\+06 m from its local origin .* keeps only 0\.5 m between values"):
        check_grid(strip, resolve_settings(AGENT))


def test_nav_test_moved_by_10_km_keeps_its_105_structure_nodes(shared_data):
    level = load_mesh(shared_data / "nav_test.obj")[0]
    counts = [g2s_core.run(moved(level, (d, 0.0, d)), "map_analysis").structure.number_of_nodes()
              for d in (0.0, 1e4)]
    # 96 before map_analysis merged a dead end's leaves (dead_end_radii), 91 with Recast's ledge filter (before
    # map_analysis took ledge_filter: drops), 93 before the local frame (docs/navmesh.md), 94 before the low-height
    # filter kept a gap of the agent's height (docs/navmesh.md, "Head room a little over the agent's height"), 95
    # before every area under the cover's min_area got its centre (13 crate tops without a leaf one node each, 3
    # with two leaves one instead of two: docs/analysis_quality.md, "Small areas on both routes")
    assert counts == [105, 105]


@pytest.mark.parametrize("shift", [(0.0, 0.0, 0.0), (100_000.0, 5.0, 100_000.0), (-3e6, 0.0, 7e6)])
def test_region_vertex_keys_count_from_the_level_s_own_corner(shift):
    """The chokepoints/regions analyzers key vertices to 1 cm in 21 bits from the level's corner, not the origin:
    a level 10 m across keys alike wherever it lies (it used to be refused beyond about 21 km when every
    coordinate was positive)."""
    from g2s_plugins.decomposition import _point_keys

    points = np.array([[0.0, 0.0, 0.0], [10.0, 0.0, 0.0], [10.0, 0.0, 10.0], [10.004, 0.0, 10.0], [0.0, 3.0, 5.0]])
    _, groups = np.unique(_point_keys(points + np.asarray(shift)), return_inverse=True)
    assert groups.reshape(-1).tolist() == [0, 2, 3, 3, 1]


# --- the ray caster (sampling route, entry_exit openings, mesh_los) ------------------------------------------


def test_the_ray_caster_answers_in_world_coordinates_from_its_local_frame():
    """A 20 x 10 m floor with a 0.5 m wall across its middle: rays along the wall's end and down through the floor,
    near the origin and 1,000 km out (where float32 keeps 6 cm between world coordinates)."""
    floor = trimesh.creation.box(extents=(20.0, 0.2, 10.0))
    floor.apply_translation((0.0, -0.1, 0.0))
    wall = trimesh.creation.box(extents=(0.5, 3.0, 6.0))
    wall.apply_translation((0.0, 1.5, 0.0))
    level = trimesh.util.concatenate([floor, wall])
    shift = np.array([1e6, 30.0, -1e6])
    near, far = RayCaster(level), RayCaster(moved(level, shift))
    assert near.local_origin.tolist() == [0.0, 0.0, 0.0] and far.local_origin.tolist() == [1e6, 0.0, -1e6]
    assert np.abs(far.triangles - shift - near.triangles).max() < 1e-9  # the public arrays: world coordinates

    # towards the wall from x = -5 at 1 m height, passing 1 mm inside or outside its end (z = 3)
    origins = np.array([[-5.0, 1.0, 2.999], [-5.0, 1.0, 3.001], [-5.0, 1.0, -2.999], [-5.0, 1.0, -3.001]])
    for caster, offset in ((near, 0.0), (far, shift)):
        hits = caster.first_hits(origins + offset, np.array([1.0, 0.0, 0.0]))
        assert hits.hit.tolist() == [True, False, True, False]
        assert hits.distance[hits.hit] == pytest.approx([4.75, 4.75], abs=1e-6)
        assert np.abs(hits.points[hits.hit] - offset - [[-0.25, 1.0, 2.999], [-0.25, 1.0, -2.999]]).max() < 1e-6
    column, distance, face, points = far.all_hits(np.array([[-5.0, 5.0, 1.0]]) + shift, np.array([0.0, -1.0, 0.0]))
    assert np.sort(points[:, 1] - shift[1]) == pytest.approx([-0.2, 0.0], abs=1e-6)  # the floor's top and bottom
    assert np.sort(distance) == pytest.approx([5.0, 5.2], abs=1e-6)


@pytest.mark.parametrize("shift", [(1e4, 0.0, 1e4), (1e6, 0.0, -1e6)])
def test_the_sampling_route_moved_far_gives_the_same_structure(shift):
    # Before the ray caster's local frame: 118 nodes (4.3 m apart) at 10 km, 128 (5.2 m) at 1,000 km, not 124
    level = generate_level("sample:dungeon")
    shift = np.array(shift)
    reference, result = (g2s_core.run(moved(level, s), "map_analysis_sampling").structure
                         for s in (0 * shift, shift))
    assert (result.number_of_nodes(), result.number_of_edges()) == \
           (reference.number_of_nodes(), reference.number_of_edges())
    assert farthest_unmatched(positions(result) - shift, positions(reference)) < MM


def test_a_sampled_level_moved_far_ranks_its_walking_flows_as_at_the_origin():
    # sample:building's sampled graph is the same 10 km out, but flows equal in exact arithmetic (samples placed
    # symmetrically) differ there in other last bits; ranked as ties only when bit-equal (before ties within
    # rounding, traffic.percentile) they gave the traffic-aware cover other terminals: 388 structure nodes, 2.6 m
    # from the origin's 387
    level = generate_level("sample:building")
    shift = np.array([1e4, 0.0, -1e4])
    reference, result = (g2s_core.run(moved(level, s), "map_analysis_sampling").structure
                         for s in (0 * shift, shift))
    assert (result.number_of_nodes(), result.number_of_edges()) == \
           (reference.number_of_nodes(), reference.number_of_edges())
    assert farthest_unmatched(positions(result) - shift, positions(reference)) < MM


@pytest.mark.parametrize("piece", ["Ramp.obj", "Hallway.obj"])
def test_entry_exit_openings_moved_far_are_the_same_openings(shared_data, piece):
    # Before: Ramp.obj's openings moved by 23 cm at 1,000 km; Hallway.obj kept 6 of its 7
    level = load_mesh(shared_data / "pieces" / piece)[0]
    shift = np.array([1e6, 0.0, 1e6])
    runs = [g2s_core.run(moved(level, s), "map_piece", stop_after="terminals") for s in (0 * shift, shift)]
    openings = [np.array([run.graph.nodes[n]["pos"] for n in run.terminals.nodes]) for run in runs]
    assert len(openings[1]) == len(openings[0]) > 0
    assert farthest_unmatched(openings[1] - shift, openings[0]) < MM
