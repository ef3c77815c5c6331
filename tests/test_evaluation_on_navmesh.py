"""rho_navmesh: the heat map measured against the walking flow on the level's navmesh graph, whatever the route."""

from __future__ import annotations

import math

import networkx as nx
import numpy as np
import pytest
import trimesh

from g2s_core import pipeline
from g2s_core.config import PRESETS_DIR, AgentConfig, load_raw_config, parse_config
from g2s_core.mesh import load_mesh, mesh_sha256
from g2s_core.registry import Registry
from g2s_plugins import evaluation, traffic
from g2s_plugins._raycasting import AgentShape
from g2s_plugins.graph_builders import sampling
from g2s_plugins.graph_builders import navmesh as navmesh_builder
from g2s_plugins.recast import build_navmesh
from g2s_plugins.samples import levels as samples


@pytest.fixture(scope="module")
def registry() -> Registry:
    return Registry.from_entry_points()


def run(registry: Registry, mesh, preset: str):
    plan = pipeline.plan(parse_config(load_raw_config(PRESETS_DIR / f"{preset}.yaml")), registry)
    return pipeline.run(plan, registry, mesh, "level", mesh_sha256(mesh))


@pytest.mark.parametrize("preset", ["map_analysis", "map_analysis_paper"])
def test_on_the_navmesh_route_the_mapping_is_the_identity(registry, preset, shared_data):
    # map_analysis's graph has portal nodes (179 nodes for 173 polygons); the paper's heat map is not its ceiling
    result = run(registry, load_mesh(shared_data / "nav_test.obj")[0], preset)
    quality = evaluation.evaluate(result)
    assert math.isfinite(quality.rho) and math.isfinite(quality.rho_ceiling)
    assert quality.rho_navmesh == quality.rho and quality.rho_navmesh_ceiling == quality.rho_ceiling
    # left out: exactly the nodes that reach no structure: nav_test's crate and pillar tops under the paper's leaves;
    # none in map_analysis, whose cover seeds every area of a place's size at its centre
    arrays = traffic.surface_arrays(result.graph)
    unreached = evaluation.nearest_structure_rows(result) < 0
    assert unreached.any() == (preset == "map_analysis_paper")
    assert quality.navmesh_area_left_out == pytest.approx(arrays.area[unreached].sum() / arrays.area.sum())


def test_a_navmesh_node_takes_the_area_weighted_mean_of_its_samples_else_the_nearest_within_reach():
    # navmesh nodes: polygon 0 at x = 0, polygon 1 at x = 4, a portal node at x = 2, polygon 3 far away at x = 50
    graph = nx.Graph()
    for node, x in enumerate([0.0, 4.0, 2.0, 50.0]):
        graph.add_node(node, pos=(x, 0.0, 0.0), area=0.0 if node == 2 else 4.0)
    graph.add_edges_from([(0, 2, {"weight": 2.0}), (2, 1, {"weight": 2.0}), (1, 3, {"weight": 46.0})])
    # samples: two on polygon 0 (values 1 and 4, areas 1 and 2), one on no polygon at x = 3 (value 7),
    # one that reaches no structure (NaN) on polygon 1, one on polygon 3 with no value either
    values = np.array([1.0, 4.0, 7.0, np.nan, np.nan])
    area = np.array([1.0, 2.0, 1.0, 1.0, 1.0])
    positions = np.array([[-0.5, 0, 0], [0.5, 0, 0], [3.0, 0, 0], [4.0, 0, 0], [50.0, 0, 0]])
    surface = evaluation.NavmeshSurface(graph, np.zeros(4), owner=np.array([0, 0, -1, 1, 3]), reach=2.0)
    carried = evaluation.carry(values, area, positions, surface)
    # polygon 0: (1 x 1 + 4 x 2) / 3; polygon 1 and the portal node: the sample at x = 3 (1 m from both; the next
    # is 1.5 m from the portal node);
    # polygon 3: its only sample has no value and the nearest valued one is 47 m away: left out
    assert carried[:3].tolist() == [3.0, 7.0, 7.0] and np.isnan(carried[3])
    # equal values give that value exactly (0.1 x 3 / 3 is not 0.1 in floating point), zero areas a plain mean
    equal = evaluation.carry(np.full(5, 0.1), np.array([3.0, 3.0, 1.0, 0.0, 0.0]), positions, surface)
    assert equal.tolist() == [0.1] * 4
    zero = evaluation.carry(np.array([1.0, 2.0, 0.0, 6.0, 8.0]), np.array([0.0, 0.0, 1.0, 0.0, 0.0]), positions, surface)
    assert zero[[0, 1, 3]].tolist() == [1.5, 6.0, 8.0]


def test_a_navmesh_island_no_sample_stands_on_is_left_out():
    # polygon 0 with a sample on it; polygon 1, 1 m away, an island (inside a crate, say) with none: the sample
    # is within reach, but across the crate's wall
    graph = nx.Graph()
    graph.add_node(0, pos=(0.0, 0.0, 0.0), area=4.0)
    graph.add_node(1, pos=(1.0, 0.0, 0.0), area=1.0)
    surface = evaluation.NavmeshSurface(graph, np.zeros(2), owner=np.array([0]), reach=2.0)
    carried = evaluation.carry(np.array([5.0]), np.array([1.0]), np.array([[0.2, 0.0, 0.0]]), surface)
    assert carried[0] == 5.0 and np.isnan(carried[1])
    graph.add_edge(0, 1, weight=1.0)  # joined: the polygon takes the sample's value
    assert evaluation.carry(np.array([5.0]), np.array([1.0]), np.array([[0.2, 0.0, 0.0]]), surface).tolist() == [5.0, 5.0]


def inside(point: np.ndarray, outline: np.ndarray) -> bool:
    """Whether ``point`` lies in the convex ``outline`` (k,3) in plan (x, z), 1 mm of slack."""
    a, b = outline[:, [0, 2]], np.roll(outline[:, [0, 2]], -1, axis=0)
    cross = (b[:, 0] - a[:, 0]) * (point[2] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (point[0] - a[:, 0])
    slack = 1e-3 * np.linalg.norm(b - a, axis=1)
    return bool((cross >= -slack).all() or (cross <= slack).all())


def test_the_sampling_route_is_carried_to_the_polygons_the_samples_stand_on(registry):
    # a flat level of one floor: a sample stands on the polygon whose outline holds it in plan
    mesh = samples.load_sample("two_rooms_one_door").mesh
    result = run(registry, mesh, "map_analysis_sampling")
    assert result.context.navmesh is None
    surface = evaluation.navmesh_surface(result, evaluation.reference_flow(result))
    navmesh = build_navmesh(mesh.vertices, mesh.faces, result.context.agent,
                            navmesh_builder.Params(ledge_filter=evaluation.REFERENCE_LEDGE_FILTER))
    assert traffic.surface_arrays(surface.graph).n == navmesh.polygon_count  # no crest: no portal node
    positions = np.array([result.graph.nodes[n]["pos"] for n in traffic.surface_arrays(result.graph).nodes])
    outlines = [navmesh.vertices[row[row >= 0]] for row in navmesh.polygons]
    for point, owner in zip(positions, surface.owner):
        holders = [p for p, outline in enumerate(outlines) if inside(point, outline)]
        assert (owner in holders) if owner >= 0 else not holders
    assert 0 < (surface.owner < 0).mean() < 0.3  # Recast erodes a little more than the sampler's clearance
    # known polygon values: each sample's heat is its x; a polygon gets the area-weighted mean x of its samples,
    # one without a sample the x of the nearest sample (all within 2 spacings here)
    area = traffic.surface_arrays(result.graph).area
    heat = positions[:, 0]
    carried = evaluation.carry(heat, area, positions, surface)
    for polygon in range(navmesh.polygon_count):
        on = surface.owner == polygon
        if on.any():
            assert carried[polygon] == pytest.approx(np.average(heat[on], weights=area[on]), abs=1e-12)
        else:
            nearest = np.argmin(np.linalg.norm(positions - surface.graph.nodes[polygon]["pos"], axis=1))
            assert carried[polygon] == heat[nearest]
    quality = evaluation.evaluate(result)
    assert -1 <= quality.rho_navmesh <= 1 and -1 <= quality.rho_navmesh_ceiling <= 1
    assert quality.navmesh_area_left_out == 0.0  # every polygon has a sample on or near it


def floors_joined_by_a_ramp(degrees: float) -> tuple[trimesh.Trimesh, np.ndarray]:
    """Two floors 6 x 4 m (slabs with tops at y = 0 and y = 2 m) joined along x by a 4 m wide ramp of ``degrees``,
    and the (2,3) middles of the two floors."""
    run = 2.0 / math.tan(math.radians(degrees))
    middles = np.array([[-3.0, 0.0, 0.0], [run + 3.0, 2.0, 0.0]])
    slabs = [trimesh.creation.box(extents=(6.0, 0.2, 4.0), transform=trimesh.transformations.translation_matrix(m - [0, 0.1, 0]))
             for m in middles]
    ramp = trimesh.Trimesh(vertices=[[0, 0, -2], [run, 2, -2], [run, 2, 2], [0, 0, 2]], faces=[[0, 2, 1], [0, 3, 2]])
    return trimesh.util.concatenate([*slabs, ramp]), middles


@pytest.mark.parametrize("degrees, default_grid_joins", [(33.0, True), (40.0, False), (44.0, False)])
def test_the_default_grid_cuts_slopes_under_max_slope_that_the_sampler_walks(degrees, default_grid_joins):
    # Recast's ledge filter drops a span whose walkable neighbours differ in height by more than the climb: on the
    # navmesh builder's default grid (cells 0.25 m, climb 3 cells of 0.125 m) a slope that rises more than 0.375 m
    # across two cells, steeper than atan(0.375 / 0.5) = 36.9 degrees (where the cells' rounding falls worst),
    # under the presets' 45. The sampler walks up to the agent's 45 degrees, and so does a grid of 0.125 m cells
    # (limit atan(0.375 / 0.25) = 56.3 degrees), and the default grid with the filter's first rule alone
    # (ledge_filter: drops, which the evaluator's reference navmesh takes: the test below). docs/analysis_quality.md,
    # "The sampling route on slopes"; docs/navmesh.md, "The drops-only ledge filter".
    mesh, ends = floors_joined_by_a_ramp(degrees)
    agent = AgentConfig()
    assert agent.max_slope == 45.0 and agent.radius == 0.5 and agent.max_climb == 0.4
    sampled = sampling.build_sampled_graph(mesh, sampling.Params(), AgentShape.from_config(agent))
    nearest = [min(sampled, key=lambda n: math.dist(sampled.nodes[n]["pos"], end)) for end in ends]
    assert [sampled.nodes[n]["pos"][1] for n in nearest] == pytest.approx(ends[:, 1])  # one on each floor
    assert nx.has_path(sampled, *nearest)
    for params, joins in ((navmesh_builder.Params(), default_grid_joins), (navmesh_builder.Params(cell_size=0.125), True),
                          (navmesh_builder.Params(ledge_filter="drops"), True)):
        navmesh = build_navmesh(mesh.vertices, mesh.faces, agent, params)
        polygons = evaluation.polygons_under(navmesh, ends)
        assert (polygons >= 0).all()
        graph = navmesh_builder.navmesh_graph(navmesh, agent, params.max_edge_gap)
        assert nx.has_path(graph, *polygons.tolist()) is joins, params.cell_size


@pytest.mark.parametrize("degrees", [33.0, 40.0, 44.0])
def test_the_reference_navmesh_walks_the_slopes_the_sampler_walks(registry, degrees):
    # the sampling route's reference navmesh takes the ledge filter's first rule alone (REFERENCE_LEDGE_FILTER, as
    # map_analysis), so the ramps the builder's default cuts above join its floors, as on the sampled graph
    mesh, ends = floors_joined_by_a_ramp(degrees)
    result = run(registry, mesh, "map_analysis_sampling")
    assert result.context.navmesh is None
    surface = evaluation.navmesh_surface(result, evaluation.reference_flow(result))
    params = navmesh_builder.Params(ledge_filter=evaluation.REFERENCE_LEDGE_FILTER)
    navmesh = build_navmesh(mesh.vertices, mesh.faces, result.context.agent, params)
    assert nx.utils.graphs_equal(surface.graph, navmesh_builder.navmesh_graph(navmesh, result.context.agent,
                                                                              params.max_edge_gap))
    polygons = evaluation.polygons_under(navmesh, ends)  # a polygon node's id is its polygon's index
    assert (polygons >= 0).all()
    assert nx.has_path(surface.graph, *polygons.tolist())
