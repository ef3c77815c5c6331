"""GraphBuilder ``sampling``: walkable surface, samples, edges; and the two routes compared end to end."""

from __future__ import annotations

import gc
import importlib
import math
import sys
import types
import weakref
from pathlib import Path

import networkx as nx
import numpy as np
import pytest
import trimesh
from scipy.spatial import cKDTree

from g2s_core import pipeline
from g2s_plugins.samples import levels as samples
from g2s_core.config import AgentConfig, MeshConfig, load_config, load_raw_config, parse_config
from g2s_core.errors import G2SError
from g2s_core.mesh import generate_level, load_mesh, mesh_sha256
from g2s_core.model import RunContext
from g2s_core.registry import Registry
from g2s_plugins._raycasting import (
    COMPASS,
    CRACK_STEPS,
    EPSILON,
    GROUND_MARGIN,
    UP,
    AgentShape,
    BoxOccupancy,
    FloorTriangles,
    RayCaster,
    _SCENES,
    _row_starts,
    clear_above,
    crack_sides,
    disk_inside,
    ground_across_crack,
    head_room,
    walks_in_batch,
)
from g2s_plugins.graph_builders import sampling
from tests.conftest import benchmark

AGENT = AgentConfig(radius=0.5, height=2.0, max_climb=0.4, max_slope=45.0)
CONFIGS = Path(__file__).resolve().parents[1] / "configs"


def box(lo, hi) -> trimesh.Trimesh:
    """An axis-aligned box with outward faces from corner ``lo`` to corner ``hi``."""
    lo, hi = np.asarray(lo, dtype=float), np.asarray(hi, dtype=float)
    return trimesh.creation.box(extents=hi - lo, transform=trimesh.transformations.translation_matrix((lo + hi) / 2))


def floor(x0=-5.0, x1=5.0, z0=-5.0, z1=5.0, top=0.0) -> trimesh.Trimesh:
    """A 0.2 m thick slab whose top is at ``top``."""
    return box((x0, top - 0.2, z0), (x1, top, z1))


def level(*parts: trimesh.Trimesh) -> trimesh.Trimesh:
    return trimesh.util.concatenate(list(parts))


def build(mesh, agent=AGENT, **params) -> nx.Graph:
    context = RunContext(mesh=mesh, agent=agent, centre=np.asarray(mesh.bounds).mean(axis=0))
    graph = sampling.g2s_build_graph(mesh=mesh, params=sampling.Params(**params), context=context)
    assert context.navmesh is None  # no Recast on this route
    return graph


def positions(graph: nx.Graph) -> np.ndarray:
    return np.array([graph.nodes[n]["pos"] for n in sorted(graph)], dtype=float).reshape(-1, 3)


def component_of(graph: nx.Graph) -> dict[int, int]:
    return {n: i for i, c in enumerate(nx.connected_components(graph)) for n in c}


# --- plugin contract and graph conventions ---------------------------------------------


def test_flat_floor_is_covered_at_the_requested_spacing():
    spacing = 0.8
    graph = build(floor(), spacing=spacing)
    p = positions(graph)
    assert nx.is_connected(graph)
    # On the floor and eroded by the agent radius from its free edges.
    assert np.allclose(p[:, 1], 0.0, atol=1e-6)
    assert np.all(np.abs(p[:, [0, 2]]) <= 4.5 + 1e-6)
    # Poisson disk: no two samples closer than the spacing, none far from the next.
    nearest = cKDTree(p).query(p, k=2)[0][:, 1]
    assert nearest.min() >= spacing - 1e-9
    assert nearest.mean() < 1.6 * spacing
    # Coverage: every point of the eroded square is within ~spacing of a sample.
    gx, gz = np.meshgrid(np.linspace(-4.4, 4.4, 45), np.linspace(-4.4, 4.4, 45))
    grid = np.column_stack([gx.ravel(), np.zeros(gx.size), gz.ravel()])
    assert cKDTree(p).query(grid)[0].max() < spacing + 0.2
    # Node attributes follow g2s_core.model; areas add up to the eroded square (9 x 9 m).
    for node, data in graph.nodes(data=True):
        assert data["on_navmesh"] is True and data["polygon"] == -1
        assert np.allclose(data["normal"], (0.0, 1.0, 0.0))
        assert len(data["pos"]) == 3 and all(isinstance(v, float) for v in data["pos"])
    assert sum(nx.get_node_attributes(graph, "area").values()) == pytest.approx(81.0, rel=0.08)
    for a, b, data in graph.edges(data=True):
        assert data["weight"] == pytest.approx(math.dist(graph.nodes[a]["pos"], graph.nodes[b]["pos"]))
        assert data["weight"] <= 2 * spacing + 1e-9
    assert sorted(graph) == list(range(graph.number_of_nodes()))


def test_grid_method_is_a_regular_grid():
    spacing = 1.0
    graph = build(floor(), method="grid", spacing=spacing)
    p = positions(graph)
    assert nx.is_connected(graph)
    # Grid points differ by whole multiples of the spacing in x and z.
    offsets = (p[:, [0, 2]] - p[0, [0, 2]]) / spacing
    assert np.allclose(offsets, np.round(offsets), atol=1e-6)
    assert 64 <= len(p) <= 100  # 9 x 9 m eroded square
    assert sum(nx.get_node_attributes(graph, "area").values()) == pytest.approx(len(p) * spacing**2)


def test_grid_gives_one_sample_per_floor_in_a_cell():
    # A second floor 3 m up over the same footprint (on pillars): every grid
    # line crosses both floors.
    upper = floor(-5, 5, -5, 5, top=3.0)
    pillars = [box((x - 0.2, 0.0, z - 0.2), (x + 0.2, 2.8, z + 0.2)) for x in (-4.8, 4.8) for z in (-4.8, 4.8)]
    graph = build(level(floor(), upper, *pillars), method="grid", spacing=1.0)
    p = positions(graph)
    low, high = p[np.abs(p[:, 1]) < 1e-6], p[np.abs(p[:, 1] - 3.0) < 1e-6]
    assert len(low) > 30 and len(high) > 30
    shared = {tuple(np.round(q[[0, 2]], 6)) for q in low} & {tuple(np.round(q[[0, 2]], 6)) for q in high}
    assert len(shared) >= 30
    # The floors are 3 m apart: nothing joins them.
    comp = component_of(graph)
    assert not any(abs(graph.nodes[a]["pos"][1] - graph.nodes[b]["pos"][1]) > 1 for a, b in graph.edges)
    assert {comp[n] for n in graph if graph.nodes[n]["pos"][1] < 1} .isdisjoint({comp[n] for n in graph if graph.nodes[n]["pos"][1] > 1})


def test_deterministic():
    mesh = samples.two_floors(ramp=True).mesh
    first, second = build(mesh), build(mesh)
    assert list(first.nodes(data="pos")) == list(second.nodes(data="pos"))
    assert list(first.edges(data="weight")) == list(second.edges(data="weight"))
    other_seed = build(mesh, seed=1)
    assert list(other_seed.nodes(data="pos")) != list(first.nodes(data="pos"))


# --- walls, boxes, floors, ceilings -----------------------------------------------------


def test_wall_across_the_floor_splits_it():
    wall = box((-0.1, -0.2, -5.0), (0.1, 3.0, 5.0))
    graph = build(level(floor(), wall))
    comp = component_of(graph)
    west = {comp[n] for n in graph if graph.nodes[n]["pos"][0] < 0}
    east = {comp[n] for n in graph if graph.nodes[n]["pos"][0] > 0}
    assert west and east and west.isdisjoint(east)
    assert not any(graph.nodes[a]["pos"][0] * graph.nodes[b]["pos"][0] < 0 for a, b in graph.edges)
    # The agent keeps its radius from the wall.
    assert np.all(np.abs(positions(graph)[:, 0]) >= 0.1 + 0.5 - 1e-6)


def test_wall_with_a_gap_connects_only_around_its_end():
    wall = box((-0.1, -0.2, -5.0), (0.1, 3.0, 2.5))  # leaves z in [2.5, 5] open
    graph = build(level(floor(), wall))
    assert nx.is_connected(graph)
    crossing = [(a, b) for a, b in graph.edges if graph.nodes[a]["pos"][0] * graph.nodes[b]["pos"][0] < 0]
    assert crossing
    for a, b in crossing:
        pa, pb = np.array(graph.nodes[a]["pos"]), np.array(graph.nodes[b]["pos"])
        t = pa[0] / (pa[0] - pb[0])
        assert pa[2] + t * (pb[2] - pa[2]) > 2.5  # crosses x = 0 beyond the wall's end


def test_box_taller_than_max_climb_is_not_climbed():
    tall = box((-1.0, 0.0, -1.0), (1.0, 1.0, 1.0))  # 1 m > max climb 0.4
    graph = build(level(floor(-6, 6, -6, 6), tall))
    p = positions(graph)
    on_floor = np.abs(p[:, 1]) < 1e-6
    assert not any(abs(graph.nodes[a]["pos"][1] - graph.nodes[b]["pos"][1]) > 0.4 for a, b in graph.edges)
    # Its 2 x 2 m top, eroded by the radius, is too small to keep (min_region_area).
    assert np.all(on_floor)
    # Nothing under or beside the box: the radius is kept from its sides (rays in
    # 8 directions: near its corners a little less).
    x, z = np.abs(p[:, 0]), np.abs(p[:, 2])
    assert np.all(x[z <= 1.0] >= 1.5 - 1e-6) and np.all(z[x <= 1.0] >= 1.5 - 1e-6)
    assert np.all(np.hypot(np.maximum(x - 1.0, 0), np.maximum(z - 1.0, 0)) >= 0.35)
    assert nx.is_connected(graph)


def test_box_lower_than_max_climb_is_stepped_onto():
    low = box((-1.0, 0.0, -1.0), (1.0, 0.3, 1.0))  # 0.3 m <= max climb 0.4
    graph = build(level(floor(-6, 6, -6, 6), low))
    on_top = [n for n in graph if abs(graph.nodes[n]["pos"][1] - 0.3) < 1e-6]
    assert on_top
    assert any(abs(graph.nodes[m]["pos"][1]) < 1e-6 for n in on_top for m in graph[n])
    assert nx.is_connected(graph)


def test_low_ceiling_removes_samples_below_it():
    low_ceiling = box((-5.0, 1.5, -5.0), (0.0, 1.7, 5.0))  # 1.5 m < agent height, over x < 0
    high_ceiling = box((0.0, 2.5, -5.0), (5.0, 2.7, 5.0))  # 2.5 m, over x > 0
    graph = build(level(floor(), low_ceiling, high_ceiling))
    p = positions(graph)
    ground = p[np.abs(p[:, 1]) < 1e-6]
    assert len(ground) > 10
    assert np.all(ground[:, 0] > 0.0)  # nothing on the floor under the low ceiling
    # ... but the floor under the high ceiling is kept, up to the radius from the low one's edge.
    assert np.any(ground[:, 0] < 1.5)
    # No edge sneaks under the low ceiling either.
    assert not any(min(graph.nodes[a]["pos"][0], graph.nodes[b]["pos"][0]) < 0 and abs(graph.nodes[a]["pos"][1]) < 1e-6 for a, b in graph.edges)


def quad(corners) -> trimesh.Trimesh:
    """One single-sided quad, its normal by the right-hand rule over ``corners`` (4, in order)."""
    return trimesh.Trimesh(np.asarray(corners, dtype=float), [[0, 1, 2], [0, 2, 3]], process=False)


@pytest.mark.parametrize("method", ["poisson", "grid"])
@pytest.mark.parametrize("single_sided_floor, height", [(False, 3.0), (True, 4.0)])
def test_no_sample_inside_a_closed_box_standing_on_the_floor(method, single_sided_floor, height):
    # 8 m wide, taller than the agent: no clearance ray from its middle reaches a wall. Its
    # bottom lies in the floor's plane, and which of the two a ledge ray meets there is
    # Embree's tie: at these heights 34 (poisson) and 49 (grid) samples stood inside before the solids rule.
    ground = quad([(-10, 0, -10), (-10, 0, 10), (10, 0, 10), (10, 0, -10)]) if single_sided_floor else floor(-10, 10, -10, 10)
    graph = build(level(ground, box((-4.0, 0.0, -4.0), (4.0, height, 4.0))), method=method)
    p = positions(graph)
    inside = (np.abs(p[:, 0]) < 4.0) & (np.abs(p[:, 2]) < 4.0) & (p[:, 1] < height - 0.1)
    assert not inside.any()
    assert np.any(np.abs(p[:, 1] - height) < 1e-6) and np.any(np.abs(p[:, 1]) < 1e-6)  # its roof and the floor around stay
    assert graph.graph["sampling_stats"]["candidates_inside_solids"] > 0


def _room(ceiling: str, walls: str) -> trimesh.Trimesh:
    """A 10 x 3 x 10 m room on a slab, of single-sided quads: ceiling facing ``up``/``down``, walls ``in``/``out``."""
    corners = [(-5, 3, -5), (-5, 3, 5), (5, 3, 5), (5, 3, -5)]
    parts = [floor(-8, 8, -8, 8), quad(corners if ceiling == "up" else corners[::-1])]
    ring = [(-5, -5), (5, -5), (5, 5), (-5, 5)]
    for (x0, z0), (x1, z1) in zip(ring, ring[1:] + ring[:1]):
        wall = [(x0, 0, z0), (x1, 0, z1), (x1, 3, z1), (x0, 3, z0)]  # faces into the room
        parts.append(quad(wall if walls == "in" else wall[::-1]))
    return level(*parts)


@pytest.mark.parametrize("ceiling", ["up", "down"])
def test_room_with_single_sided_ceiling_and_walls_keeps_its_floor(ceiling):
    # An upper floor seen from below is a back face when it faces up, but the walls face into the room.
    graph = build(_room(ceiling, "in"))
    p = positions(graph)
    assert np.count_nonzero((np.abs(p[:, 0]) < 5) & (np.abs(p[:, 2]) < 5) & (np.abs(p[:, 1]) < 1e-6)) > 40
    assert graph.graph["sampling_stats"]["candidates_inside_solids"] == 0


def test_inside_closed_solids_needs_back_faces_all_round():
    agent = AgentShape.from_config(AGENT)
    solid = level(floor(-10, 10, -10, 10), box((-4.0, 0.0, -4.0), (4.0, 3.0, 4.0)))
    inverted = solid.copy()
    inverted.invert()  # wound inside out: seen from the front everywhere
    bridge = level(floor(-10, 10, -10, 10), box((-4.0, 2.5, -4.0), (4.0, 2.7, 4.0)))  # a closed deck overhead
    shell = _room("up", "out")  # outward quads all round: a closed body, as far as winding tells
    points = np.array([[0.0, 0.0, 0.0], [7.0, 0.0, 0.0]])
    expected = {solid: [True, False], inverted: [False, False], bridge: [False, False], shell: [True, False]}
    for mesh, answer in expected.items():
        np.testing.assert_array_equal(sampling.inside_closed_solids(RayCaster(mesh), points, agent), answer)


def test_closed_solid_overlapping_a_wall_a_ceiling_or_another_is_inside():
    # The box's own face lies buried in the other solid, so along that way the first face met is the other solid's,
    # seen from the front: only the crossings beyond it tell that the point is inside.
    agent = AgentShape.from_config(AGENT)
    ground = floor(-10, 10, -10, 10)
    shaft = box((0.0, 0.0, 0.0), (4.0, 3.0, 4.0))
    wall = box((-10.0, 0.0, -0.25), (10.0, 3.2, 0.1))  # overlaps the shaft's south 0.1 m
    pillar = box((0.0, -0.1, 0.0), (4.0, 3.3, 4.0))  # through the floor and the ceiling slab
    ceiling = box((-10.0, 3.2, -10.0), (10.0, 3.4, 10.0))
    crate = box((3.0, 0.0, 3.0), (7.0, 3.0, 7.0))  # overlaps the shaft's north-east corner
    points = np.array([[2.0, 0.0, 2.0], [2.0, 0.0, 6.0], [-5.0, 0.0, 5.0], [5.0, 0.0, 5.0]])
    expected = {
        level(ground, shaft, wall): [True, False, False, False],
        level(ground, pillar, ceiling): [True, False, False, False],
        level(ground, shaft, wall, ceiling): [True, False, False, False],
        level(ground, shaft, crate): [True, False, False, True],
    }
    for mesh, answer in expected.items():
        np.testing.assert_array_equal(sampling.inside_closed_solids(RayCaster(mesh), points, agent), answer)


def test_closed_bodies_are_welded_closed_and_wound_one_way():
    crate = box((0.0, 0.0, 0.0), (1.0, 1.0, 1.0))  # 12 triangles, welded
    unwelded = trimesh.Trimesh(crate.triangles.reshape(-1, 3), np.arange(36).reshape(12, 3), process=False)
    lidless = trimesh.Trimesh(crate.vertices, crate.faces[crate.face_normals[:, 1] < 0.5], process=False)
    flipped = crate.copy()
    flipped.faces[0] = flipped.faces[0][::-1]  # one triangle wound the wrong way
    sheet = trimesh.Trimesh([[0, 2, 0], [1, 2, 0], [1, 2, 1], [0, 2, 1]], [[0, 2, 1], [0, 3, 2]], process=False)
    two_sided = trimesh.Trimesh(sheet.vertices, np.vstack([sheet.faces, sheet.faces[:, ::-1]]), process=False)
    for mesh, closed in [(crate, 12), (unwelded, 12), (lidless, 0), (flipped, 0), (sheet, 0), (two_sided, 0)]:
        assert int(RayCaster(mesh).scene.closed.sum()) == closed
    both = level(crate, sheet)  # a closed body and an open quad in one mesh
    np.testing.assert_array_equal(RayCaster(both).scene.closed, [True] * 12 + [False] * 2)


def test_box_overlapping_a_wall_keeps_no_sample_inside():
    overlaps = benchmark("closed_solid_overlaps")
    for case in ("overlapping a wall", "pillar, floor to ceiling"):
        assert overlaps.measure(case, 0.0)["inside"] == 0, case


def test_hole_in_the_floor_is_not_crossed():
    # Without erosion samples lie right at the edges of the 1.2 m wide hole, well
    # within connect_radius (2 m) of each other across it.
    graph = build(level(floor(-5, -0.6, -5, 5), floor(0.6, 5, -5, 5)), clearance=0.0)
    p = positions(graph)
    assert np.any(np.abs(p[:, 0] + 0.6) < 0.3) and np.any(np.abs(p[:, 0] - 0.6) < 0.3)
    assert not any(graph.nodes[a]["pos"][0] * graph.nodes[b]["pos"][0] < 0 for a, b in graph.edges)
    assert nx.number_connected_components(graph) == 2
    # The same floor without the hole is one piece.
    assert nx.is_connected(build(floor(), clearance=0.0))


def test_two_floors_are_joined_by_the_ramp_only():
    with_ramp = build(samples.two_floors(ramp=True).mesh)
    without = build(samples.two_floors(ramp=False).mesh)
    for graph, joined in ((with_ramp, True), (without, False)):
        comp = component_of(graph)
        ground = {comp[n] for n in graph if abs(graph.nodes[n]["pos"][1]) < 1e-6}
        upper = {comp[n] for n in graph if abs(graph.nodes[n]["pos"][1] - 4.0) < 1e-6}
        assert ground and upper
        assert bool(ground & upper) is joined
    assert nx.number_connected_components(with_ramp) == 1
    assert nx.number_connected_components(without) == 2
    # On the ramp (20 degrees) the normals tilt; wall tops (0.2 m wide) carry no sample.
    ramp_nodes = [n for n in with_ramp if 0.05 < with_ramp.nodes[n]["pos"][1] < 3.95]
    assert ramp_nodes
    for n in ramp_nodes:
        assert math.degrees(math.acos(with_ramp.nodes[n]["normal"][1])) == pytest.approx(20.0, abs=0.5)
    assert max(p[1] for _, p in with_ramp.nodes(data="pos")) == pytest.approx(4.0)


def test_slope_penalty_adds_weight_for_climbing():
    mesh = samples.corridor_with_ramp().mesh
    plain, penalised = build(mesh), build(mesh, slope_penalty=2.0)
    assert list(plain.edges) == list(penalised.edges)
    for a, b, w in penalised.edges(data="weight"):
        dy = abs(penalised.nodes[a]["pos"][1] - penalised.nodes[b]["pos"][1])
        assert w == pytest.approx(plain.edges[a, b]["weight"] + 2.0 * dy)


def test_steep_slope_is_not_walkable():
    # A 60 degree ramp is steeper than the agent's 45: no sample on it, floors not joined.
    run = 2.0 / math.tan(math.radians(60))
    ramp = trimesh.Trimesh(
        vertices=[[0, 0, -2], [run, 2, -2], [run, 2, 2], [0, 0, 2]], faces=[[0, 2, 1], [0, 3, 2]], process=False
    )
    assert ramp.face_normals[0][1] > 0
    graph = build(level(floor(-6, 0, -2, 2), ramp, floor(run, run + 6, -2, 2, top=2.0)), clearance=0.0)
    heights = positions(graph)[:, 1]
    assert not np.any((heights > 0.05) & (heights < 1.95))
    assert nx.number_connected_components(graph) == 2


def test_walks_in_batch_on_a_floor_with_a_wall():
    mesh = level(floor(), box((-0.1, -0.2, -5.0), (0.1, 3.0, 0.0)))
    caster = RayCaster(mesh)
    agent = AgentShape.from_config(AGENT)
    starts = np.array([[-3.0, 0.0, 2.0], [-3.0, 0.0, -2.0], [-3.0, 0.0, 2.0]])
    ends = np.array([[3.0, 0.0, 2.0], [3.0, 0.0, -2.0], [-3.0, 0.0, 7.0]])  # clear, wall, off the floor
    ok, rise = walks_in_batch(caster, starts, ends, agent, probe_step=0.25)
    assert ok.tolist() == [True, False, False]
    assert rise[0] == pytest.approx(0.0, abs=1e-6) and math.isinf(rise[2])
    hits = caster.first_hits(np.array([[0.0, 4.0, -3.0], [0.0, 1.0, 3.0], [0.0, 1.0, 9.0]]), np.array([0.0, -2.0, 0.0]))
    assert hits.distance[0] == pytest.approx(1.0, abs=1e-5)  # down onto the wall's top (y = 3)
    assert hits.distance[1] == pytest.approx(1.0, abs=1e-5)  # down onto the floor (y = 0)
    assert hits.face[2] == -1 and math.isinf(hits.distance[2])  # beside the level
    assert caster.backend in ("embree", "python")


def test_python_intersector_gives_the_embree_answers(monkeypatch: pytest.MonkeyPatch):
    pytest.importorskip("embreex")
    mesh = level(floor(), box((-0.1, -0.3, -5.0), (0.1, 3.0, 0.0)), box((2.0, -0.1, 1.0), (3.0, 0.3, 4.0)))  # no coplanar faces (the floor is at y = -0.2)
    rng = np.random.default_rng(0)
    starts = np.column_stack([rng.uniform(-5, 5, 60), np.zeros(60), rng.uniform(-5, 5, 60)])
    ends = np.column_stack([rng.uniform(-5, 5, 60), np.zeros(60), rng.uniform(-5, 5, 60)])
    origins = np.column_stack([rng.uniform(-6, 6, 80), rng.uniform(-1, 4, 80), rng.uniform(-6, 6, 80)])
    directions = rng.normal(size=(80, 3))
    agent = AgentShape.from_config(AGENT)

    def answers(caster: RayCaster) -> list[np.ndarray]:
        down, sideways = caster.first_hits(origins, [0.0, -1.0, 0.0]), caster.first_hits(origins, directions)
        ok, rise = walks_in_batch(caster, starts, ends, agent, probe_step=0.25)
        return [down.face, down.distance, sideways.face, sideways.distance, ok, rise]

    with_embree = RayCaster(mesh)
    assert with_embree.backend == "embree"
    other = mesh.copy()  # another mesh object: a caster of ``mesh`` would share the Embree scene
    monkeypatch.delattr(trimesh.ray, "ray_pyembree")  # as if embreex failed to import
    monkeypatch.setitem(sys.modules, "trimesh.ray.ray_pyembree", None)
    python = RayCaster(other)
    assert python.backend == "python"
    for a, b in zip(answers(with_embree), answers(python)):
        np.testing.assert_allclose(a, b, atol=1e-6)


def test_casters_of_one_mesh_share_its_scene_and_count_their_own_rays():
    mesh = level(floor(), box((-0.1, 0.0, -5.0), (0.1, 3.0, 0.0)))
    origins = np.array([[1.0, 2.0, 1.0], [-3.0, 2.0, -2.0], [0.0, 5.0, -1.0]])
    first, second = RayCaster(mesh), RayCaster(mesh)
    assert first.triangles is second.triangles and first.intersector is second.intersector  # built once
    before = first.first_hits(origins, -UP)
    np.testing.assert_allclose(before.distance, [2.0, 2.0, 2.0], atol=1e-5)  # the floor, the floor, the wall's top
    assert (first.rays_cast, second.rays_cast) == (3, 0)
    assert RayCaster(mesh.copy()).triangles is not first.triangles  # keyed by the object, not its content

    mesh.vertices[:, 1] -= 1.0  # changed in place: a new scene, with the new answers
    moved = RayCaster(mesh)
    assert moved.triangles is not first.triangles
    np.testing.assert_allclose(moved.first_hits(origins, -UP).distance, [3.0, 3.0, 3.0], atol=1e-5)
    assert RayCaster(mesh).triangles is moved.triangles

    gone, key = weakref.ref(mesh), id(mesh)
    del mesh, first, second, moved
    gc.collect()  # trimesh's meshes hold reference cycles of their own
    assert gone() is None and key not in _SCENES  # the cache kept neither the mesh nor its scene


def test_sampling_stats_do_not_depend_on_other_casters_of_the_mesh():
    mesh = samples.two_floors(ramp=True).mesh
    alone = build(mesh.copy()).graph["sampling_stats"]
    RayCaster(mesh).first_hits(np.zeros((5, 3)), UP)  # another plugin casting on the same mesh first
    assert build(mesh).graph["sampling_stats"] == alone
    assert build(mesh).graph["sampling_stats"] == alone  # and a second run on the same mesh object


def test_nothing_walkable_is_reported_not_an_empty_graph():
    wall_only = box((-0.1, 0.0, -5.0), (0.1, 3.0, 5.0))
    upside_down = trimesh.Trimesh(vertices=[[0, 0, 0], [1, 0, 0], [0, 0, 1]], faces=[[0, 1, 2]], process=False)
    assert upside_down.face_normals[0][1] < 0
    # A 0.2 m wide wall top is eroded away entirely.
    for mesh in (upside_down, wall_only):
        assert sampling.build_sampled_graph(mesh, sampling.Params(), AgentShape.from_config(AGENT)).number_of_nodes() == 0
        with pytest.raises(G2SError, match="no walkable surface for the agent"):
            build(mesh)


# --- the two routes through the whole pipeline -------------------------------------------

_ROUTE_MODULES = {
    ("graph", "navmesh"): "g2s_plugins.graph_builders.navmesh",
    ("graph", "sampling"): "g2s_plugins.graph_builders.sampling",
    ("terminals", "points"): "g2s_plugins.terminals.points",
    ("terminals", "metric"): "g2s_plugins.terminals.metric",
    ("terminals", "leaves"): "g2s_plugins.terminals.leaves",
    ("steiner", "kou"): "g2s_plugins.steiner.kou",
    ("roots", "betweenness"): "g2s_plugins.roots.betweenness",
    ("simplify", "surface_los"): "g2s_plugins.predicates.surface_los",
    ("simplify", "mesh_los"): "g2s_plugins.predicates.mesh_los",
    ("analyzers", "betweenness"): "g2s_plugins.analyzers.betweenness",
    ("analyzers", "depth"): "g2s_plugins.analyzers.depth",
}


@pytest.fixture(scope="module")
def registry() -> Registry:
    """The installed plugins; those not registered as entry points are added from their modules."""
    reg = Registry.from_entry_points()
    for (stage, name), module in _ROUTE_MODULES.items():
        try:
            reg.get(stage, name)
        except Exception:
            reg.register(importlib.import_module(module), package="g2s-tests", entry_point=f"{stage}.{name}")
    return reg


def run_route(registry: Registry, preset: str, mesh, points) -> types.SimpleNamespace:
    """Run ``preset`` with ``points`` as terminals (the same question for both routes)."""
    raw = load_raw_config(CONFIGS / f"{preset}.yaml")
    raw["agent"] = {"radius": 0.5, "height": 2.0, "max_climb": 0.4, "max_slope": 45.0}
    # Replaced, not merged: the preset's terminal parameters belong to another selector.
    raw["terminals"] = {"plugin": "points", "params": {"points": [list(map(float, p)) for p in points], "max_distance": 5.0}}
    raw["analyzers"] = []
    plan = pipeline.plan(parse_config(raw, source=preset), registry, source=preset)
    result = pipeline.run(plan, registry, mesh, preset, mesh_sha256(mesh))
    structure = result.structure.to_undirected()
    length = sum(math.dist(structure.nodes[a]["pos"], structure.nodes[b]["pos"]) for a, b in structure.edges)
    joined = any(set(result.terminals.nodes) <= c for c in nx.connected_components(structure))
    return types.SimpleNamespace(result=result, length=length, joined=joined)


def test_routes_agree_on_the_cross_hub(registry):
    lvl = samples.cross_hub()
    openings = [o.position for o in lvl.openings]
    navmesh = run_route(registry, "map_piece", lvl.mesh, openings)
    sampled = run_route(registry, "map_piece_sampling", lvl.mesh, openings)
    assert navmesh.result.context.navmesh is not None and sampled.result.context.navmesh is None
    # The same four openings are joined into one tree by both routes ...
    assert navmesh.joined and sampled.joined
    assert len(sampled.result.terminals.nodes) == 4
    # ... with a similar total length.
    assert sampled.length == pytest.approx(navmesh.length, rel=0.25)


def test_routes_agree_on_two_floors(registry):
    lvl = samples.two_floors(ramp=True)
    upper = lvl.metadata["upper"]
    ends = [(1.5, 0.0, 1.5), (upper["x1"] - 1.5, 4.0, (upper["z0"] + upper["z1"]) / 2)]
    navmesh = run_route(registry, "map_piece", lvl.mesh, ends)
    sampled = run_route(registry, "map_piece_sampling", lvl.mesh, ends)
    # Both routes join the ground floor to the upper one, through the ramp.
    for route in (navmesh, sampled):
        assert route.joined
        heights = [p[1] for _, p in route.result.structure.nodes(data="pos")]
        assert min(heights) < 0.5 and max(heights) > 3.5
    ramp = lvl.metadata["ramp"]
    through_ramp = [
        n
        for n, p in sampled.result.steiner.nodes(data="pos")
        if ramp["x0"] <= p[0] <= ramp["x1"] and ramp["z0"] <= p[2] <= ramp["z1"]
    ]
    assert through_ramp
    assert sampled.length == pytest.approx(navmesh.length, rel=0.25)
    # Without the ramp neither route can join them.
    closed = samples.two_floors(ramp=False)
    for preset in ("map_piece", "map_piece_sampling"):
        assert not run_route(registry, preset, closed.mesh, ends).joined


def test_sampling_presets_run(registry):
    lvl = samples.t_hub()
    for preset in ("map_analysis_sampling", "map_piece_sampling"):
        config = load_config(CONFIGS / f"{preset}.yaml")
        assert config.graph.plugin == "sampling" and config.simplify.plugin == "mesh_los"
        plan = pipeline.plan(config, registry, source=preset)
        result = pipeline.run(plan, registry, lvl.mesh, preset, mesh_sha256(lvl.mesh))
        assert result.terminals.nodes, preset
        assert result.structure is not None and result.structure.number_of_nodes() >= 2
        assert result.analysis
        # The structure reaches the end of every arm (the openings).
        p = np.array([pos for _, pos in result.structure.nodes(data="pos")])
        for opening in lvl.openings:
            assert cKDTree(p).query(opening.position)[0] < 2.0, (preset, opening.position)


def test_embree_caster_without_trimeshs_private_scene_takes_the_public_call():
    pytest.importorskip("embreex")
    mesh = level(floor(), box((-0.1, -0.2, -5.0), (0.1, 3.0, 0.0)))
    rng = np.random.default_rng(1)
    origins = np.column_stack([rng.uniform(-6, 6, 40), rng.uniform(-1, 4, 40), rng.uniform(-6, 6, 40)])
    directions = rng.normal(size=(40, 3))
    direct = RayCaster(mesh)
    public = RayCaster(mesh)
    public.intersector = types.SimpleNamespace(intersects_first=public.intersector.intersects_first)
    a, b = direct.first_hits(origins, directions), public.first_hits(origins, directions)
    assert public._embree is False
    np.testing.assert_array_equal(a.face, b.face)
    np.testing.assert_array_equal(a.distance, b.distance)


# --- rays saved without changing an answer ------------------------------------------------


def test_box_occupancy_never_frees_a_column_that_meets_a_widened_box():
    rng = np.random.default_rng(3)
    corners = rng.uniform(-5, 5, (40, 3, 3)) * np.array([1.0, 0.3, 1.0])
    widen = np.array([0.5, 0.01, 0.5])
    grid = BoxOccupancy(corners, widen, cell=0.25)
    points = rng.uniform(-7, 7, (4000, 3)) * np.array([1.0, 0.3, 1.0])
    low, high = -0.4, 1.2
    lo, hi = corners.min(axis=1) - widen, corners.max(axis=1) + widen
    meets = (
        (points[:, None, 0] >= lo[:, 0]) & (points[:, None, 0] <= hi[:, 0])
        & (points[:, None, 2] >= lo[:, 2]) & (points[:, None, 2] <= hi[:, 2])
        & (points[:, None, 1] + high >= lo[:, 1]) & (points[:, None, 1] + low <= hi[:, 1])
    ).any(axis=1)
    free = grid.columns_free(points, low, high)
    assert not np.any(free & meets)
    assert free.sum() > 0.2 * len(points)  # and it does free the columns far from every box
    assert BoxOccupancy(np.zeros((0, 3, 3)), widen, cell=0.25).columns_free(points, low, high).all()


def test_surroundings_are_built_once_per_caster_agent_and_clearance():
    mesh = generate_level("sample:two_rooms_one_door")
    agent = AgentShape.from_config(AGENT)
    caster = RayCaster(mesh)
    first = sampling._Surroundings.of(caster, agent, 0.5)
    assert sampling._Surroundings.of(caster, agent, 0.5) is first
    assert sampling._Surroundings.of(caster, agent, 0.25) is not first
    assert sampling._Surroundings.of(RayCaster(mesh), agent, 0.5) is not first  # another caster, its own
    other = AgentShape(0.5, 2.0, 0.4, 30.0)
    assert sampling._Surroundings.of(caster, other, 0.5).steep.occupied.sum() >= first.steep.occupied.sum()
    kept = len(sampling._SURROUNDINGS)
    del caster
    gc.collect()
    assert len(sampling._SURROUNDINGS) == kept - 1  # the entry leaves with its caster


@pytest.mark.parametrize("name", ["building", "stair_deck", "cluttered_room"])
def test_open_floors_neighbours_are_the_floors_and_triangles_whose_grown_boxes_overlap(name):
    from g2s_plugins._raycasting import OpenFloors

    caster = RayCaster(generate_level(f"sample:{name}"))
    floors = OpenFloors(caster, AgentShape.from_config(AGENT))
    asked = np.flatnonzero(caster.walkable_faces(np.arange(len(caster.triangles)), AGENT.max_slope))[::3]
    floor, other = floors._neighbours(asked)
    xz = caster.triangles[:, :, [0, 2]]
    lo, hi = xz.min(axis=1) - floors.margin, xz.max(axis=1) + floors.margin
    overlap = np.all((lo[None, :] <= hi[asked][:, None]) & (lo[asked][:, None] <= hi[None, :]), axis=2)
    expected = set(zip(*np.nonzero(overlap)))
    assert len(expected) > len(asked)  # each floor with itself and its neighbours at least
    assert sorted(zip(floor.tolist(), other.tolist())) == sorted((int(i), int(j)) for i, j in expected)


def test_disk_inside_its_triangle():
    triangle = np.array([[0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [0.0, 0.0, 4.0]])
    points = np.array([[1.0, 0.0, 1.0], [0.4, 0.0, 1.0], [1.0, 0.0, 0.4], [1.8, 0.0, 1.8], [5.0, 0.0, 5.0]])
    for corners in (triangle, triangle[::-1]):  # either winding
        inside = disk_inside(points, np.broadcast_to(corners, (len(points), 3, 3)), 0.5)
        assert inside.tolist() == [True, False, False, False, False]
    edge_on = np.array([[0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [4.0, 3.0, 0.0]])  # a wall: no area seen from above
    assert not disk_inside(points[:1], edge_on[None], 0.0).any()


@pytest.mark.parametrize(
    "name, scale",
    [("building", 1.0), ("two_storey", 1.0), ("bridge", 1.0), ("terrain", 1.0), ("stair_deck", 1.0), ("catwalk", 1.0),
     ("wall_tops", 1.0), ("building", 4.0)],
)
def test_agent_fits_saves_rays_not_answers(name, scale):
    mesh = generate_level(f"sample:{name}", MeshConfig(scale=scale))
    agent = AgentShape.from_config(AGENT)
    surface = sampling.walkable_surface(mesh, agent)
    points, faces, _ = sampling._poisson_candidates(surface, 1.0 * scale, sampling.Params())
    shortcuts, walls_only, every_ray = RayCaster(mesh), RayCaster(mesh), RayCaster(mesh)
    across = RayCaster(mesh)
    fits = sampling.agent_fits(shortcuts, points, agent, 0.5, surface.triangles[faces])
    np.testing.assert_array_equal(fits, sampling.agent_fits(walls_only, points, agent, 0.5))
    np.testing.assert_array_equal(fits, _agent_fits_with_every_ray(every_ray, points, agent, 0.5))
    np.testing.assert_array_equal(fits, sampling.agent_fits(across, points, agent, 0.5, surface.triangles, faces))
    np.testing.assert_array_equal(fits, sampling.agent_fits(RayCaster(mesh), points, agent, 0.5, surface, faces))
    assert across.rays_cast <= shortcuts.rays_cast <= walls_only.rays_cast < every_ray.rays_cast
    if scale > 1:  # 0.8 m thick floors, large rooms: ground all around is known for most candidates
        assert shortcuts.rays_cast < 0.5 * walls_only.rays_cast


def test_agent_fits_far_from_the_origin_saves_no_ray_it_needs(shared_data):
    # 10,000 km out a ray reaches Embree with its origin rounded to float32 (up to
    # half a metre): candidates that close to a wall must still cast their rays.
    mesh = load_mesh(shared_data / "nav_test.obj")[0]
    mesh.vertices = mesh.vertices + np.array([1e7, 50.0, -3e6])
    agent = AgentShape.from_config(AGENT)
    surface = sampling.walkable_surface(mesh, agent)
    points, faces, _ = sampling._poisson_candidates(surface, 1.0, sampling.Params())
    fits = sampling.agent_fits(RayCaster(mesh), points, agent, 0.5, surface.triangles[faces])
    np.testing.assert_array_equal(fits, _agent_fits_with_every_ray(RayCaster(mesh), points, agent, 0.5))
    np.testing.assert_array_equal(fits, sampling.agent_fits(RayCaster(mesh), points, agent, 0.5, surface.triangles, faces))


def test_clearance_disk_may_reach_across_to_the_neighbouring_triangle():
    # A quad floor of two triangles, x and z in [0, 4]: a disk crossing the diagonal lies in the pair,
    # one crossing the outer edge does not; a neighbour folded back over its triangle does not count.
    quad = np.array([[[0, 0, 0], [4, 0, 4], [4, 0, 0]], [[0, 0, 0], [0, 0, 4], [4, 0, 4]]], dtype=float)
    floor = FloorTriangles(quad)
    assert floor.neighbour.tolist() == [[1, -1, -1], [-1, -1, 0]]
    points = np.array([[2.2, 0, 1.9], [3.8, 0, 1.0], [2.2, 0, 1.9]])
    inside, drop = floor.disk_inside(points, np.array([0, 0, 0]), 0.5, 0.5)
    assert inside.tolist() == [True, False, True] and np.allclose(drop[inside], 0.0)
    alone, _ = FloorTriangles(quad, across=False).disk_inside(points, np.array([0, 0, 0]), 0.5, 0.5)
    assert not alone.any()
    folded = quad.copy()
    folded[1] = [[0, 0, 0], [4, 0, 4], [3, 0, 1]][::-1]  # shares the diagonal, lies on the first one's side
    assert (FloorTriangles(folded).neighbour == -1).all()


def _agent_fits_with_every_ray(caster: RayCaster, points: np.ndarray, agent: AgentShape, clearance: float) -> np.ndarray:
    """agent_fits without any broad phase: 24 wall rays (up to two downward rays more for each steep face they meet,
    the riser rule) and 24 ledge rays per point (two probes a direction and an upward ray over the outer one; 2 to 8 more for each ledge probe that finds no ground: the crack rule, 2 to 4 a
    side)."""
    ok = head_room(caster, points, agent)
    levels = sorted({round(min(agent.max_climb + GROUND_MARGIN, agent.height - EPSILON), 6),
                     round(0.5 * agent.height, 6), round(agent.height - 5 * EPSILON, 6)})
    for level in levels:
        for direction in COMPASS:
            hits = caster.first_hits(points + level * UP, direction)
            ok &= ~sampling.walls_met(caster, hits, agent, clearance)  # a steep face but a riser within the climb
    step = clearance / 2.0  # two probes a direction, half the clearance apart; the point itself the first
    reach = 2.0 * float(agent.max_rise(step)) + GROUND_MARGIN
    walkable = lambda faces: caster.walkable_faces(faces, agent.max_slope_deg)  # noqa: E731
    heights = [np.zeros(len(points) * len(COMPASS))]
    ground = np.ones(len(points) * len(COMPASS), dtype=bool)
    for j in (1, 2):
        probe = (points[:, None, :] + j * step * COMPASS[None, :, :]).reshape(-1, 3)
        down = caster.first_hits(probe + reach * UP, -UP)
        found = (down.distance <= 2.0 * reach) & walkable(down.face)
        distance = np.where(found, down.distance, 0.0)
        missing = np.flatnonzero(~found)  # a probe over a crack stands on the ground beside it
        crack, beside = ground_across_crack(caster, probe[missing] + reach * UP, -UP, crack_sides(agent), 2.0 * reach,
                                            walkable, CRACK_STEPS)
        found[missing[crack]], distance[missing[crack]] = True, beside[crack]
        ground &= found & (np.abs(reach - distance - heights[-1]) <= agent.max_rise(step) + 1e-6)
        heights.append(reach - distance)
    ground &= clear_above(caster, probe + reach * UP, agent.height - distance)
    return ok & ground.reshape(len(points), len(COMPASS)).all(axis=1)


def test_small_regions_are_summed_as_networkx_orders_them():
    # 0.1 + 0.2 + 0.3 rounds to 0.6000000000000001 in this order, to 0.6 in another:
    # a part standing for "0.6" m² is dropped or kept by its order of summing.
    areas = np.array([0.1, 0.2, 0.3, 0.3, 0.2, 0.1, 5.0, 0.05])
    edges = np.array([[0, 1], [1, 2], [3, 4], [4, 5], [6, 7]])
    for min_area in (0.6, 0.6000000000000001, 1.0, 5.06, 0.0):
        graph = nx.Graph()
        graph.add_nodes_from((i, {"area": a}) for i, a in enumerate(areas.tolist()))
        graph.add_edges_from(edges.tolist())
        expected = np.zeros(len(areas), dtype=bool)
        parts = 0
        if min_area > 0:
            for component in nx.connected_components(graph):
                if sum(graph.nodes[n]["area"] for n in component) < min_area:
                    expected[list(component)] = True
                    parts += 1
        small, dropped = sampling._small_regions(len(areas), edges, areas, min_area)
        assert small.tolist() == expected.tolist() and dropped == parts, min_area


def test_joint_ray_call_gives_the_separate_calls_answers():
    mesh = level(floor(), box((-0.1, -0.3, -5.0), (0.1, 3.0, 0.0)), box((2.0, -0.1, 1.0), (3.0, 0.3, 4.0)))
    caster = RayCaster(mesh)
    rng = np.random.default_rng(5)
    for count in (5, 2000):  # one call, then one call per batch
        origins = np.column_stack([rng.uniform(-6, 6, count), rng.uniform(-1, 4, count), rng.uniform(-6, 6, count)])
        batches = [(origins, rng.normal(size=(count, 3))), (origins, np.array([0.0, -1.0, 0.0])), (origins[:3], np.array([0.0, 1.0, 0.0]))]
        for hits, (o, d) in zip(caster.first_hits_of(batches), batches):
            alone = caster.first_hits(o, d)
            np.testing.assert_array_equal(hits.face, alone.face)
            np.testing.assert_array_equal(hits.distance, alone.distance)
            np.testing.assert_array_equal(hits.points, alone.points)


def _poisson_disk_subset_one_by_one(points: np.ndarray, radius: float, seed: int) -> np.ndarray:
    """The dart throwing of ``poisson_disk_subset`` without its parts: every point in the seeded order, every pair."""
    from scipy import sparse

    pairs = cKDTree(points).query_pairs(radius, output_type="ndarray")
    heads, tails = np.concatenate([pairs[:, 0], pairs[:, 1]]), np.concatenate([pairs[:, 1], pairs[:, 0]])
    rows = sparse.csr_array((np.ones(len(heads), dtype=np.int8), (heads, tails)), shape=(len(points), len(points)))
    free = np.ones(len(points), dtype=bool)
    taken = []
    for i in np.random.default_rng(seed).permutation(len(points)).tolist():
        if free[i]:
            taken.append(i)
            free[rows.indices[rows.indptr[i] : rows.indptr[i + 1]]] = False
    return np.sort(np.asarray(taken, dtype=np.int64))


def test_poisson_disk_subset_in_parts_is_the_one_by_one_pick():
    rng = np.random.default_rng(5)
    clouds = {
        "floor": np.column_stack([rng.uniform(0, 40, 30_000), np.zeros(30_000), rng.uniform(0, 40, 30_000)]),
        "box": rng.uniform(0, 12, (10_000, 3)),
        "floors": np.column_stack([rng.uniform(0, 30, 30_000), rng.integers(0, 3, 30_000) * 0.7, rng.uniform(0, 30, 30_000)]),
        "clusters": (rng.normal(size=(10_000, 3)) * 0.3 + rng.integers(0, 6, (10_000, 1)) * 3.0),
        "few": rng.uniform(0, 3, (9, 3)),
        "grid": np.stack(np.meshgrid(np.arange(40.0), [0.0], np.arange(40.0)), axis=-1).reshape(-1, 3),  # ties at the radius
    }
    mesh = generate_level("sample:building?seed=1", MeshConfig(scale=2.0))
    clouds["building"] = trimesh.sample.sample_surface(mesh, 40_000, seed=1)[0]
    for name, points in clouds.items():
        for radius, seed in [(1.0, 0), (0.45, 3)]:
            assert np.array_equal(
                sampling.poisson_disk_subset(points, radius, seed), _poisson_disk_subset_one_by_one(points, radius, seed)
            ), (name, radius, seed)


@pytest.mark.parametrize("name", ["building", "terrain", "stair_deck"])
def test_floor_neighbours_from_shared_vertices_are_those_from_corners(name):
    # near() tells corners apart by the mesh's vertices: the same neighbours as sorting all corners, also where
    # the mesh repeats a vertex (every face its own three vertices, as an unwelded export has them); a disk of
    # radius 0 fits in every triangle, so it keeps them all
    surface = sampling.walkable_surface(generate_level(f"sample:{name}", MeshConfig()), AgentShape.from_config(AGENT))
    corners = np.asarray(surface.triangles)
    unwelded = trimesh.Trimesh(corners.reshape(-1, 3), np.arange(3 * len(corners)).reshape(-1, 3), process=False)
    expected = FloorTriangles(corners)
    assert (expected.neighbour >= 0).any()  # some edges are shared: the test looks at something
    for mesh in (surface, unwelded):
        floor, on = FloorTriangles.near(mesh, np.arange(len(corners)), 0.0)
        np.testing.assert_array_equal(on, np.arange(len(corners)))
        np.testing.assert_array_equal(floor.neighbour, expected.neighbour)
        np.testing.assert_array_equal(floor.neighbour_edge, expected.neighbour_edge)


@pytest.mark.parametrize("radius", [0.2, 0.35, 0.6, 1.0])
def test_floor_triangles_near_points_give_disk_inside_the_whole_floors_answers(radius):
    # a floor cut into 4 m triangles beside one cut into 0.2 m triangles (as artists' exports often are), sharing
    # the corners along x = 4: near() leaves out the small triangles no disk fits in, and answers as the whole
    # floor's neighbours do
    parts = [trimesh.Trimesh(*trimesh.remesh.subdivide_to_size(quad(corners).vertices, quad(corners).faces, max_edge=edge))
             for corners, edge in ((((-4, 0, -4), (-4, 0, 4), (4, 0, 4), (4, 0, -4)), 4.0),
                                   (((4, 0, -4), (4, 0, 4), (12, 0, 4), (12, 0, -4)), 0.2))]
    # and a sliver 0.4 m high between three large triangles: a disk on it fits only across its long edge
    sliver = [[20, 0, 0], [24, 0, 0.4], [28, 0, 0], [24, 0, -8], [20, 0, 8], [28, 0, 8]]
    parts.append(trimesh.Trimesh(sliver, [[0, 1, 2], [0, 2, 3], [0, 4, 1], [1, 5, 2]], process=False))
    surface = level(*parts)
    points, on_face = trimesh.sample.sample_surface(surface, 3000, seed=5)
    weights = np.random.default_rng(5).dirichlet(np.ones(3), 300)  # points on the sliver
    points = np.concatenate([points, weights @ np.asarray(sliver, dtype=float)[[0, 1, 2]]])
    on_face = np.concatenate([on_face, np.full(300, len(surface.faces) - 4)])
    whole = FloorTriangles(np.asarray(surface.triangles))  # every triangle, neighbours by sorting the corners
    near, on = FloorTriangles.near(surface, on_face, radius)
    expected, expected_drop = whole.disk_inside(points, on_face, radius, radius)
    inside = on >= 0
    assert not expected[~inside].any()  # no triangle left out holds a disk
    got, drop = near.disk_inside(points[inside], on[inside], radius, radius)
    np.testing.assert_array_equal(got, expected[inside])
    np.testing.assert_array_equal(drop, expected_drop[inside])
    assert expected.any()  # some disks fit: the test looks at something
    if radius == 0.6:
        assert expected[-300:].any()  # and on the sliver, across its edges
    if radius >= 0.35:  # 0.2 m triangles hold no such disk, and their neighbours are not looked for
        assert len(near.corners) < 0.1 * len(whole.corners)


def test_row_starts_pick_each_distinct_row_once():
    rows = np.random.default_rng(3).integers(-2, 3, (5000, 6))
    np.testing.assert_array_equal(rows[_row_starts(rows)], np.unique(rows, axis=0))
    assert len(_row_starts(rows[:0])) == 0


def test_batches_on_two_threads_build_the_graph_of_one(monkeypatch: pytest.MonkeyPatch):
    """The candidates' wall and ledge rays, the stranded candidates' ledge rays and the edges' walk tests, cast in
    batches by two threads (``sampling._each_batch``), give the graph and the ray count of one thread and of one
    batch each."""
    mesh = samples.dungeon(seed=1, rooms=12).mesh

    def graph_with(threads: int, batch: int | None) -> tuple[list, list, list, dict]:
        monkeypatch.setattr(sampling, "RAY_THREADS", threads)
        if batch is not None:  # many small batches: each thread takes several, in whatever order they come
            for name in ("MAX_WALL_BATCH", "MAX_LEDGE_BATCH", "MAX_EDGE_BATCH", "MAX_ROOM_BATCH"):
                monkeypatch.setattr(sampling, name, batch)
        graph = build(mesh)
        return (list(graph.nodes(data=True)), list(graph.edges(data=True)), [list(graph.adj[n]) for n in graph],
                graph.graph["sampling_stats"])

    whole = graph_with(1, None)
    # several batches of 97 below
    assert min(whole[3][name] for name in ("candidates", "candidate_edges", "candidates_stranded")) > 8 * 97
    assert graph_with(2, 97) == whole
    assert graph_with(1, 97) == whole
