"""Issue 9: coverage terminals, loops kept, area weighting, OD flow, presets."""

from __future__ import annotations

import hashlib
import heapq
import json
import math
import os
import threading
from types import SimpleNamespace

import networkx as nx
import numpy as np
import pytest
import scipy
import scipy.sparse as sp
from scipy.sparse import csgraph

from g2s_core import pipeline
from g2s_core.config import PRESETS_DIR, load_raw_config, parse_config
from g2s_core.errors import ConfigError
from g2s_plugins.loops.spanner import add_loops
from g2s_core.mesh import load_mesh, mesh_sha256
from g2s_core.model import RunContext
from g2s_core.registry import Registry
from g2s_core.rooted import root_forest
from g2s_core.simplify import simplify_forest
from g2s_plugins import _trees, centrality, evaluation, traffic
from g2s_plugins.analyzers import betweenness as betweenness_analyzer
from g2s_plugins.analyzers import flow as flow_analyzer
from g2s_plugins.outputs import gltf, heatmap, html_report
from g2s_plugins.outputs.structure_json import structure_document
from g2s_plugins.samples import levels as samples
from g2s_plugins.terminals import coverage


@pytest.fixture(scope="module")
def registry() -> Registry:
    return Registry.from_entry_points()


def run(registry: Registry, mesh, raw: dict, name: str = "level"):
    plan = pipeline.plan(parse_config(raw), registry)
    return pipeline.run(plan, registry, mesh, name, mesh_sha256(mesh))


def preset(name: str, **overrides) -> dict:
    raw = load_raw_config(PRESETS_DIR / f"{name}.yaml")
    raw.update(overrides)
    return raw


def ring(nodes: int = 24, length: float = 1.0) -> nx.Graph:
    """A ring corridor: a cycle of nodes ``length`` metres apart, each 1 m² of floor."""
    radius = nodes * length / (2 * math.pi)
    graph = nx.cycle_graph(nodes)
    for node in graph:
        angle = 2 * math.pi * node / nodes
        graph.nodes[node].update(pos=(radius * math.cos(angle), 0.0, radius * math.sin(angle)), area=1.0)
    for u, v in graph.edges:
        graph.edges[u, v]["weight"] = float(np.linalg.norm(np.subtract(graph.nodes[u]["pos"], graph.nodes[v]["pos"])))
    return graph


def corridor(nodes: int) -> nx.Graph:
    """A straight corridor 0 - 1 - ... of 1 m² polygons 1 m apart."""
    graph = nx.path_graph(nodes)
    for node in graph:
        graph.nodes[node].update(pos=(float(node), 0.0, 0.0), area=1.0)
    for u, v in graph.edges:
        graph.edges[u, v]["weight"] = 1.0
    return graph


def test_ring_corridor_keeps_its_loop_with_stretch_and_loses_it_with_inf():
    graph = ring()
    tree = graph.copy()
    tree.remove_edge(23, 0)  # the Steiner tree of a ring is the ring minus one edge
    looped = add_loops(graph, tree, stretch=1.5, min_gain=3.0)
    assert nx.cycle_basis(looped) and looped.has_edge(23, 0)
    assert add_loops(graph, tree, stretch=math.inf, min_gain=3.0) is tree
    # the gain of closing the ring (23 m - 1 m) is below a min_gain of 30 m
    assert not nx.cycle_basis(add_loops(graph, tree, stretch=1.5, min_gain=30.0))


def test_loop_edges_survive_rooting_and_simplification():
    graph = ring()
    rooted = root_forest(graph, {n: 0.0 for n in graph}, np.zeros(3))
    loops = [(u, v) for u, v, loop in rooted.edges(data="loop") if loop]
    assert len(loops) == 1
    simplified = simplify_forest(rooted, lambda tree, a, b, c: True)
    assert nx.cycle_basis(simplified.to_undirected()), "simplification broke the loop"
    assert any(loop for _, _, loop in simplified.edges(data="loop"))


def test_ring_around_a_square_block_keeps_only_its_four_corners():
    # eight nodes around a square block: corners and middles of its sides; two nodes see each other on a common side
    corners_and_middles = [(-1, -1), (0, -1), (1, -1), (1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0)]
    graph = nx.cycle_graph(8)
    for node, (x, z) in enumerate(corners_and_middles):
        graph.nodes[node]["pos"] = (float(x), 0.0, float(z))
    rooted = root_forest(graph, {n: float(n == 0) for n in graph}, np.zeros(3))
    assert rooted.has_edge(0, 7) and rooted.edges[0, 7]["loop"]  # the depth-first tree cut the ring at 7

    def same_side(tree, a, b, c):
        pa, pc = tree.nodes[a]["pos"], tree.nodes[c]["pos"]
        return any(pa[i] == pc[i] and abs(pa[i]) == 1 for i in (0, 2))

    simplified = simplify_forest(rooted, same_side)
    # Algorithm 4 drops the middles 1, 3, 5; the loop pass drops 7, which Algorithm 4 cannot (a leaf of the tree)
    assert sorted(simplified) == [0, 2, 4, 6]
    assert sorted(map(sorted, simplified.edges)) == [[0, 2], [0, 6], [2, 4], [4, 6]]
    assert simplified.edges[0, 6]["loop"] and simplified.edges[0, 6]["weight"] == pytest.approx(2.0)
    assert len(nx.cycle_basis(simplified.to_undirected())) == 1


def test_loop_pass_keeps_terminals_and_never_shrinks_a_loop_below_a_triangle():
    graph = ring(6)
    rooted = root_forest(graph, {n: float(n == 0) for n in graph}, np.zeros(3))
    simplified = simplify_forest(rooted, lambda tree, a, b, c: True)
    assert simplified.number_of_nodes() == 3 and len(nx.cycle_basis(simplified.to_undirected())) == 1
    graph.nodes[5]["terminal"] = True
    graph.nodes[3]["terminal"] = True
    rooted = root_forest(graph, {n: float(n == 0) for n in graph}, np.zeros(3))
    assert {3, 5} <= set(simplify_forest(rooted, lambda tree, a, b, c: True))


def test_two_floors_loop_around_the_central_block_is_kept(registry):
    mesh = samples.two_floors().mesh
    new = run(registry, mesh, preset("map_analysis"))
    paper = run(registry, mesh, preset("map_analysis_paper"))
    assert nx.cycle_basis(new.structure.to_undirected())
    assert not nx.cycle_basis(paper.structure.to_undirected())


def test_loops_are_an_optional_stage_of_their_own(registry):
    mesh = samples.two_floors().mesh
    looped = run(registry, mesh, preset("map_analysis", stop_after="loops"))
    assert [s.stage for s in looped.stages] == ["graph", "terminals", "steiner", "loops"]
    assert nx.cycle_basis(looped.looped) and not nx.cycle_basis(looped.steiner)
    assert all("pos" in looped.looped.nodes[n] for n in looped.looped)  # the graph's attributes, copied by the pipeline
    tree = run(registry, mesh, preset("map_analysis", loops=None))
    assert tree.looped is None and "loops" not in tree.config and tree.stage("loops") is None
    assert not nx.cycle_basis(tree.structure.to_undirected())


def test_loop_edges_appear_in_every_output(registry, tmp_path):
    from tests.test_gltf import _children, assert_khronos_valid, read_glb

    result = run(registry, samples.two_floors().mesh, preset("map_analysis"))
    loops = sorted((u, v) for u, v, loop in result.structure.edges(data="loop") if loop)
    assert loops
    document = structure_document(result)
    assert sorted((e["source"], e["target"]) for e in document["edges"] if e["extra"].get("loop")) == loops
    traces = [t for t in html_report.build_figure(result).data if t.name == html_report.LAYER_LOOPS]
    assert len(traces) == 1 and traces[0].showlegend and traces[0].line.dash == "dot"
    assert np.count_nonzero(np.isnan(np.asarray(traces[0].x, dtype=float))) == len(loops)  # one gap per segment
    groups = heatmap.floor_groups(result.structure, 2.0)
    labels = [h.get_label() for h in heatmap._legend_handles(result, result.structure, groups)]
    assert "loop edge" in labels
    path, = gltf.write(result, tmp_path)
    assert_khronos_valid(path)
    header, _ = read_glb(path)
    assert _children(header, "loops") == ["loop_edges"]
    extras = next(n.get("extras", {}) for n in header["nodes"] if n.get("name") == "loop_edges")
    assert sorted(map(tuple, extras["edges"])) == loops


def test_dead_end_room_with_a_central_pillar_is_covered(registry):
    # one room with a pillar in its centre: no polygon of the room has one neighbour
    level = samples.dungeon(seed=0, rooms=1, room_min=7.0, room_max=7.0, obstacles=1.0, pillar_gap=2.0)
    assert level.metadata["pillars"] >= 1
    result = run(registry, level.mesh, preset("map_analysis"))
    graph = result.graph
    assert not [n for n, d in graph.degree() if d == 1], "the room should have no leaf polygon"
    radius = 12 * 0.5
    arrays = traffic.surface_arrays(graph)
    distance, _ = traffic.distance_to(arrays, arrays.rows(result.steiner))
    assert result.structure.number_of_nodes() >= 2
    assert distance.max() <= radius + 1e-9


def spine_and_side_room() -> nx.Graph:
    """A busy spine 0 - 1 - 2 - 3 (leaves 0 and 3) and a quiet side room off 2: a triangle 4, 5, 6 (no leaf).

    Edges 1 m, but 4 - 6 1.2 m (so that 6 alone is the farthest node); every node 1 m².
    """
    graph = nx.Graph()
    graph.add_weighted_edges_from([(0, 1, 1.0), (1, 2, 1.0), (2, 3, 1.0), (2, 4, 1.0), (4, 5, 1.0), (5, 6, 1.0),
                                   (4, 6, 1.2)])
    for node in graph:
        graph.nodes[node]["area"] = 1.0
    return graph


def select_cover(graph: nx.Graph, **params) -> tuple[tuple, tuple]:
    context = RunContext(mesh=None, agent=None, centre=np.zeros(3), graph=graph)
    terminals = coverage.g2s_select_terminals(graph, coverage.Params(min_area=0.0, **params), context)
    assert not context.warnings
    return terminals.nodes, terminals.waypoints


def test_areas_under_min_area_are_seeded_at_their_centre_and_those_under_place_area_left_out():
    # radius 2 m: the default min_area is pi (2 / 2)² = 3.14 m². Three areas, each a ring of four 1 m edges (no
    # leaf, every node within 2 m of every other): 12 m², 4 m² (above min_area) and 2 m² (below it), and a path of
    # three 0.5 m² nodes (1.5 m², two leaves) under place_area, 1.6 m²
    graph = nx.Graph()
    for first, size, area in ((0, 4, 3.0), (10, 4, 1.0), (20, 4, 0.5)):
        ring = [first + k for k in range(size)]
        graph.add_weighted_edges_from((a, b, 1.0) for a, b in zip(ring, ring[1:] + ring[:1]))
        for node in ring:
            graph.nodes[node]["area"] = area
    graph.add_weighted_edges_from([(30, 31, 1.0), (31, 32, 1.0)])
    for node in (30, 31, 32):
        graph.nodes[node]["area"] = 0.5
    context = RunContext(mesh=None, agent=None, centre=np.zeros(3), graph=graph)
    terminals = coverage.g2s_select_terminals(graph, coverage.Params(radius=2.0, place_area=1.6), context)
    # the big rings get one seed each, the node farthest from their lowest id (2 and 12); the small ring its
    # centre: every node 2 m from its farthest, the lowest (20); the path is left out whatever its leaves
    assert terminals.nodes == (2, 12, 20)
    assert context.warnings == ["coverage: 1 walkable area(s) smaller than 1.6 m² (1.5 m² in all) are not covered: "
                                "smaller than a part the graph builders keep (place_area), too small to be a place"]


@pytest.mark.parametrize("rows, columns", [(1, 9), (5, 7)])
def test_a_large_area_s_centre_by_landmarks_is_the_exact_centre_on_strips_and_grids(monkeypatch, rows, columns):
    # unit-edge grids: a strip's centre is its middle (4), a 5 x 7 grid's its middle node (2, 3) = row 17, whose
    # farthest nodes, the four corners, lie 5 edges away; the landmarks (the far corner from node 0, then the corner
    # farthest from those before) find the same node as a Dijkstra from every node
    grid = nx.convert_node_labels_to_integers(nx.grid_2d_graph(rows, columns), ordering="sorted")
    adjacency = nx.to_scipy_sparse_array(grid, nodelist=range(rows * columns), format="csr")
    labels, chosen = np.zeros(rows * columns, dtype=np.int64), np.array([True])
    exact = coverage.area_centres(adjacency, labels, chosen)
    monkeypatch.setattr(coverage, "CENTRE_EXACT_NODES", 4)
    assert coverage.area_centres(adjacency, labels, chosen).tolist() == exact.tolist() == [rows * columns // 2]


def test_a_small_area_is_seeded_at_its_centre_not_at_its_leaves():
    # radius 2 m, min_area 3.14 m²: a path of three 0.5 m² nodes (1.5 m², two leaves) and a strip of seven 0.4 m²
    # nodes 1 m apart (2.8 m², leaves 40 and 46), both below min_area, no agent (place_area 0). Each is seeded at
    # its centre (1: 1 m from both ends; 43: 3 m from both), not at its leaves, and the cover reaches the strip's
    # ends (3 m > 2 m) by a path to the farthest first, 40 (ties: lowest row), then 46
    graph = nx.Graph()
    graph.add_weighted_edges_from([(0, 1, 1.0), (1, 2, 1.0)])
    strip = list(range(40, 47))
    graph.add_weighted_edges_from((a, b, 1.0) for a, b in zip(strip, strip[1:]))
    for node in graph.nodes:
        graph.nodes[node]["area"] = 0.5 if node < 40 else 0.4
    context = RunContext(mesh=None, agent=None, centre=np.zeros(3), graph=graph)
    terminals = coverage.g2s_select_terminals(graph, coverage.Params(radius=2.0), context)
    assert terminals.nodes == (1, 40, 41, 42, 43, 44, 45, 46) and not context.warnings
    cover = coverage.cover(graph, coverage.Params(radius=2.0), context)
    assert cover.leaves.size == 0 and [cover.arrays.nodes[i] for i in cover.traffic] == [1, 43]


def test_traffic_weight_zero_is_the_plain_cover():
    # plain distances from the leaves 0 and 3: 1 m to 1 and 2, 2 m to 4, 3 m to 5, 3.2 m to 6
    graph = spine_and_side_room()
    assert select_cover(graph, radius=4.0) == ((0, 3), ())
    assert select_cover(graph, radius=3.0) == ((0, 2, 3, 4, 6), (2, 4, 6))  # 6 and its path 6 - 4 - 2
    for radius in (4.0, 3.0, 0.5):
        assert select_cover(graph, radius=radius, traffic_weight=0.0, traffic_radius=1.0) == select_cover(
            graph, radius=radius)


def reference_cover(adjacency: sp.csr_array, seeds: np.ndarray, eligible: np.ndarray, radius: float) -> np.ndarray:
    """cover_paths as plain Python with heapq: the farthest uncovered node (ties: lowest row) and its path
    back to the set join it, then a Dijkstra from the path lowers the distances, until all is within radius."""
    start, predecessor, _ = csgraph.dijkstra(adjacency, directed=False, indices=seeds, min_only=True,
                                             return_predecessors=True)
    distance, parent = start.tolist(), predecessor.tolist()
    heap = [(-start[node], node) for node in np.flatnonzero((start > radius) & eligible).tolist()]
    heapq.heapify(heap)
    chosen = [seeds]
    while heap:
        negative, node = heapq.heappop(heap)
        if distance[node] <= radius:
            continue
        if -negative > distance[node]:  # came closer since: back in at its new distance
            heapq.heappush(heap, (-distance[node], node))
            continue
        path = [node]
        while parent[path[-1]] >= 0:
            path.append(parent[path[-1]])
        path.pop()
        chosen.append(np.asarray(path, dtype=np.int64))
        for member in path:
            distance[member], parent[member] = 0.0, -1
        pending = [(0.0, member) for member in path]  # not a heap: heapq's order decides equal ways
        while pending:
            reached, here = heapq.heappop(pending)
            if reached > distance[here]:
                continue
            for k in range(adjacency.indptr[here], adjacency.indptr[here + 1]):
                other, through = int(adjacency.indices[k]), reached + float(adjacency.data[k])
                if through < distance[other]:
                    distance[other], parent[other] = through, here
                    heapq.heappush(pending, (through, other))
    return np.unique(np.concatenate(chosen))


def test_cover_paths_is_the_plain_python_cover():
    # a path 0 - 1 - ... - 9 of unit steps from seed 0, radius 2.5: the farthest node 9 and its path back to
    # 0 (nodes 1-9) join, so all is covered
    path = lengths(10, [(i, i + 1, 1.0) for i in range(9)])
    assert coverage.cover_paths(path, np.array([0]), np.ones(10, bool), 2.5).tolist() == list(range(10))
    # random graphs of equal lengths, full of equally short ways, and of random lengths: the same cover
    rng = np.random.default_rng(8)
    for _ in range(60):
        n = int(rng.integers(5, 120))
        edges = [(int(a), int(b), float(rng.choice([1.0, 2.0])) if rng.random() < 0.7 else float(rng.random()) + 0.1)
                 for a, b in rng.integers(0, n, (2 * n, 2)) if a != b]
        graph = lengths(n, edges)
        graph.sum_duplicates()
        seeds = rng.choice(n, int(rng.integers(1, 4)), replace=False).astype(np.int64)
        eligible, radius = rng.random(n) < 0.9, float(rng.choice([0.5, 1.5, 3.0]))
        assert np.array_equal(coverage.cover_paths(graph, seeds, eligible, radius),
                              reference_cover(graph, seeds, eligible, radius))


def test_traffic_aware_cover_adds_a_waypoint_where_traffic_steps_down():
    graph = spine_and_side_room()
    # through-flow (ordered pairs, ends excluded): 1 parts {0} | 5 others: 10; 2 parts {0, 1} | {3} | {4, 5, 6}:
    # 2 (2 + 6 + 3) = 22; 4 parts {5, 6} | 4 others: 16 (5 - 6 is direct); 0, 3, 5, 6: 0. Ranks 2.5 (the four
    # zeros), 5, 7, 6: percentiles 100 (rank - 0.5) / 7
    flow = traffic.walking_flow(graph, max_sources=traffic.WALKING_SOURCES)
    assert flow.tolist() == [0, 10, 22, 0, 16, 0, 0]
    # weight 0.07 m per point: 1 m per rank step, so length + |rank difference|
    arrays = traffic.surface_arrays(graph)
    lengths = coverage.traffic_lengths(arrays, coverage.walking_percentile(arrays), 0.07)
    expected = {(0, 1): 3.5, (1, 2): 3.0, (2, 3): 5.5, (2, 4): 2.0, (4, 5): 4.5, (5, 6): 1.0, (4, 6): 4.7}
    assert {edge: lengths[edge] for edge in expected} == pytest.approx(expected)
    # weighted distances from 0 and 3: 1 3.5, 2 5.5, 4 7.5, 5 12, 6 12.2; radius 6: 6 is farthest, its path
    # 6 - 4 - 2 joins; then 5 is 1 away, 1 3 away. The plain pass (4 m) adds nothing: the plain cover alone has
    # no waypoint, the traffic-aware one marks the quiet room's far corner and the step into the room
    assert select_cover(graph, radius=4.0) == ((0, 3), ())
    assert select_cover(graph, radius=4.0, traffic_weight=0.07, traffic_radius=6.0) == ((0, 2, 3, 4, 6), (2, 4, 6))
    # the plain pass still guarantees its radius: at 0.5 m it adds 1 and 5, each 1 m from that cover
    nodes, _ = select_cover(graph, radius=0.5, traffic_weight=0.07, traffic_radius=6.0)
    assert nodes == tuple(range(7))


def test_selector_and_flow_analyzer_share_one_flow_and_leave_it_intact(monkeypatch):
    def level() -> nx.Graph:  # 300 nodes: the flow is sampled
        graph = nx.convert_node_labels_to_integers(nx.grid_2d_graph(20, 15))
        for node in graph:
            graph.nodes[node]["area"] = 1.0 + node % 7
        for u, v in graph.edges:
            graph.edges[u, v]["weight"] = 1.0 + (u * v) % 5 / 10
        return graph

    structure = nx.path_graph(range(0, 300, 25))
    alone = level()
    context = RunContext(mesh=None, agent=None, centre=np.zeros(3), graph=alone)
    before = {aggregate: flow_analyzer.g2s_analyze(structure, flow_analyzer.Params(aggregate=aggregate), context)
              for aggregate in ("mean", "sum", "percentile")}
    original, calls = traffic.od_flow, []

    def counted(*args, **kwargs):
        calls.append(1)
        return original(*args, **kwargs)

    monkeypatch.setattr(traffic, "od_flow", counted)
    graph = level()
    context = RunContext(mesh=None, agent=None, centre=np.zeros(3), graph=graph)
    coverage.g2s_select_terminals(graph, coverage.Params(radius=3.0, traffic_weight=0.1), context)
    after = {aggregate: flow_analyzer.g2s_analyze(structure, flow_analyzer.Params(aggregate=aggregate), context)
             for aggregate in ("mean", "sum", "percentile")}
    assert after == before
    assert len(calls) == 1  # computed by the selector, reused three times by the analyzer
    shared = traffic.walking_flow(graph, max_sources=traffic.WALKING_SOURCES)
    assert not shared.flags.writeable
    # another seed is another flow; a graph that changed size gets a new one
    assert traffic.walking_flow(graph, max_sources=traffic.WALKING_SOURCES, seed=1) is not shared
    graph.add_edge(0, 299, weight=1.0)
    assert traffic.walking_flow(graph, max_sources=traffic.WALKING_SOURCES) is not shared


def test_the_exact_flow_is_computed_once_whatever_seed_its_callers_give(monkeypatch):
    # the exact flow draws no sample: its cache key held the seed, so two callers of other seeds computed it twice
    original, calls = traffic.od_flow, []
    monkeypatch.setattr(traffic, "od_flow", lambda *args, **kwargs: calls.append(1) or original(*args, **kwargs))
    graph = spine_and_side_room()
    exact = traffic.walking_flow(graph, max_sources=traffic.WALKING_SOURCES, seed=0)
    assert traffic.walking_flow(graph, max_sources=traffic.WALKING_SOURCES, seed=7) is exact
    assert traffic.walking_flow(graph, max_sources=None, seed=3) is exact
    assert len(calls) == 1
    sampled = traffic.walking_flow(graph, max_sources=2, seed=0)  # 7 nodes of weight > 2 sources: sampled
    assert traffic.walking_flow(graph, max_sources=2, seed=1) is not sampled and len(calls) == 3


def test_a_walking_flow_begun_ahead_is_the_one_the_caller_would_have_computed(monkeypatch):
    original, calls = traffic.od_flow, []
    monkeypatch.setattr(traffic, "od_flow", lambda *args, **kwargs: calls.append(1) or original(*args, **kwargs))
    arrays = traffic.surface_arrays(spine_and_side_room())
    traffic.start_walking_flow(arrays, max_sources=2, seed=1)  # 7 nodes of weight > 2 sources: a sample
    traffic.start_walking_flow(arrays, max_sources=2, seed=1)  # begun already: nothing
    begun = traffic.arrays_walking_flow(arrays, max_sources=2, seed=1)
    assert len(calls) == 1 and not arrays.begun and not begun.flags.writeable
    assert traffic.arrays_walking_flow(arrays, max_sources=2, seed=1) is begun  # kept as any computed flow
    traffic.start_walking_flow(arrays, max_sources=2, seed=1)  # computed already: nothing
    assert len(calls) == 1 and not arrays.begun
    here = traffic.arrays_walking_flow(traffic.surface_arrays(spine_and_side_room()), max_sources=2, seed=1)
    assert begun.tobytes() == here.tobytes()
    # an error on the flow's thread reaches the caller that takes the flow
    monkeypatch.setattr(traffic, "od_flow", lambda *args, **kwargs: 1 / 0)
    traffic.start_walking_flow(arrays, max_sources=2, seed=2)
    with pytest.raises(ZeroDivisionError):
        traffic.arrays_walking_flow(arrays, max_sources=2, seed=2)


def test_a_flow_begun_ahead_walks_on_one_thread_until_a_caller_waits_for_it(monkeypatch):
    # one thread beside the caller's Python, which holds the other core; both once the caller waits (traffic.py)
    monkeypatch.setattr(traffic, "THREADS", 2)
    monkeypatch.setattr(traffic, "BLOCK_ENTRIES", 1)  # one source a block: seven blocks on these seven nodes
    arrays = traffic.surface_arrays(spine_and_side_room())
    through, threads, second = traffic._through, [], threading.Event()

    def recording(*args):
        threads.append(traffic.tree_threads())
        if len(threads) == 2:  # the second block goes on once the caller waits for the flow
            second.set()
            assert traffic._AHEAD.flow.taken.wait(30)  # this thread's flow
        return through(*args)

    monkeypatch.setattr(traffic, "_through", recording)
    traffic.start_walking_flow(arrays)  # the exact flow: every node a source
    assert traffic.tree_threads() == 2  # the caller's own thread
    assert second.wait(30)
    flow = traffic.arrays_walking_flow(arrays)
    # the block under way when the caller came was begun on one thread (the extension's call then takes a second
    # from its next source on: the test below); the next blocks begin on two
    assert threads == [1, 1, 2, 2, 2, 2, 2]
    arrays = traffic.surface_arrays(spine_and_side_room())
    assert flow.tobytes() == traffic.arrays_walking_flow(arrays).tobytes() and threads[7:] == [2] * 7


def _threads_of_a_call(call) -> int:
    """The most threads of this process seen at once while ``call`` runs on a thread of its own (Linux's
    /proc/self/task, polled while the call has let go of the GIL), less the threads there were before it."""
    before = len(os.listdir("/proc/self/task"))
    thread = threading.Thread(target=call)
    thread.start()
    most = 0
    while thread.is_alive():
        most = max(most, len(os.listdir("/proc/self/task")))
    thread.join()
    return most - before


@pytest.mark.skipif(not os.path.isdir("/proc/self/task"), reason="counts threads in /proc/self/task")
def test_a_flow_call_on_one_thread_takes_a_second_once_its_waiting_flag_is_set():
    # a flow begun ahead runs on one thread; once a caller waits for it, the extension's call under way takes a
    # second thread from its next source on (traffic.waiting_flag), the same bits as on one or two threads
    graph = grid_lengths(40, 40, np.random.default_rng(3))
    sources, values = np.arange(0, 1600, 2), np.random.default_rng(4).uniform(0.0, 1.0, 1600)
    one = traffic.shortest_path_flow(graph, sources, values)
    out = {}
    waiting = _trees.Waiting()
    csr = traffic.extension_csr(graph)
    sources32 = sources.astype(np.int32)

    def flow(name, threads, flag):
        return lambda: out.setdefault(name, _trees.shortest_path_flow(*csr, sources32, values, threads, flag))

    assert _threads_of_a_call(flow("unset", 1, waiting)) == 1  # the caller's thread alone: nobody waits
    assert not waiting.is_set()
    waiting.set()
    # set before the call: the second thread starts at its first source; the call lasts long enough to be seen
    # (800 searches), else the poll is tried again
    assert any(_threads_of_a_call(flow(f"set {attempt}", 1, waiting)) == 2 for attempt in range(5))
    for name, (predecessors, through) in out.items():
        assert predecessors.tobytes() == one[0].tobytes() and through.tobytes() == one[1].tobytes(), name


def test_the_coverage_selector_begins_its_walking_flow_before_its_leaves(monkeypatch):
    begun = []
    monkeypatch.setattr(traffic, "start_walking_flow", lambda arrays, **kwargs: begun.append(kwargs))
    graph = spine_and_side_room()
    context = RunContext(mesh=None, agent=None, centre=np.zeros(3), graph=graph)
    coverage.g2s_select_terminals(graph, coverage.Params(radius=3.0), context)
    assert not begun  # a cover that reads no traffic walks no flow
    coverage.g2s_select_terminals(graph, coverage.Params(radius=3.0, traffic_weight=0.1, traffic_sources=2), context)
    assert begun == [{"max_sources": 2, "ties": traffic.WALKING_TIES, "scaling": traffic.WALKING_SCALING}]


def test_coverage_traffic_parameters_are_validated(registry):
    for params, key in (({"traffic_weight": -0.1}, "terminals.params.traffic_weight"),
                        ({"traffic_weight": 0.1, "traffic_radius": 0}, "terminals.params.traffic_radius")):
        raw = preset("map_analysis", terminals={"plugin": "coverage", "params": params})
        with pytest.raises(ConfigError, match=f"{key}: expected a number"):
            pipeline.plan(parse_config(raw), registry)


def room_with_sliver_and_alcove(tile_border: bool = False) -> tuple[nx.Graph, SimpleNamespace]:
    """A 10 m square room R (node 0) with, beyond its east wall, a sliver S (1) 0.4 m deep, a triangle over the
    whole wall, and beyond its north wall a 2 m wide alcove A (2) 2 m deep. Plan coordinates (x, z), y = 0.

    ``tile_border``: S lies in the next tile (its own copies of the wall's two vertices) and touches R only
    from z = 2 to z = 8, the portal Detour gives for that part of the border.
    """
    plan = [(0, 0), (10, 0), (10, 10), (6, 10), (4, 10), (0, 10), (10.4, 5), (6, 12), (4, 12), (10, 0), (10, 10)]
    vertices = np.array([(x, 0.0, z) for x, z in plan])
    east = (9, 6, 10) if tile_border else (1, 6, 2)
    polygons = np.array([(0, 1, 2, 3, 4, 5), (*east, -1, -1, -1), (4, 3, 7, 8, -1, -1)])
    neighbours = np.array([(-1, 1, -1, 2, -1, -1), (-1, -1, 0, -1, -1, -1), (0, -1, -1, -1, -1, -1)])
    navmesh = SimpleNamespace(vertices=vertices, polygons=polygons, neighbours=neighbours)
    graph = nx.Graph()
    for node, area in ((0, 100.0), (1, 2.0), (2, 4.0)):
        corners = vertices[polygons[node][polygons[node] >= 0]]
        graph.add_node(node, pos=tuple(corners.mean(axis=0)), area=area, polygon=node)
    east_portal = ((10.0, 0.0, 2.0), (10.0, 0.0, 8.0)) if tile_border else (tuple(vertices[1]), tuple(vertices[2]))
    for other, portal in ((1, east_portal), (2, (tuple(vertices[3]), tuple(vertices[4])))):
        graph.add_edge(0, other, portal=portal, weight=float(np.linalg.norm(
            np.subtract(graph.nodes[0]["pos"], graph.nodes[other]["pos"]))))
    return graph, navmesh


def test_leaf_depth_is_how_far_its_polygon_reaches_beyond_the_shared_edge():
    graph, navmesh = room_with_sliver_and_alcove()
    assert coverage.leaf_depths(graph, navmesh, [1, 2]) == pytest.approx([0.4, 2.0])
    # across a tile border the way in is only the part Detour links: the sliver's corners are 2 m beyond it
    graph, navmesh = room_with_sliver_and_alcove(tile_border=True)
    assert coverage.leaf_depths(graph, navmesh, [1, 2]) == pytest.approx([2.0, 2.0])
    # without polygons (the sampling route) the depth is unknown: every leaf counts as deep
    assert coverage.leaf_depths(graph, None, [1, 2]).tolist() == [math.inf, math.inf]
    del graph.nodes[1]["polygon"]
    assert coverage.leaf_depths(graph, navmesh, [1, 2]).tolist() == [math.inf, 2.0]


def test_leaf_min_depth_drops_the_sliver_and_keeps_the_alcove():
    graph, navmesh = room_with_sliver_and_alcove()

    def terminals(**params) -> tuple:
        context = RunContext(mesh=None, agent=None, centre=np.zeros(3), navmesh=navmesh, graph=graph)
        return coverage.g2s_select_terminals(graph, coverage.Params(radius=50.0, min_area=0.0, **params),
                                             context).nodes

    assert terminals() == terminals(leaf_min_depth=0.0) == terminals(leaf_min_depth=0.4) == (1, 2)
    assert terminals(leaf_min_depth=1.0) == terminals(leaf_min_depth=2.0) == (2,)
    # no leaf deep enough: the area is seeded as one without leaves, at its node farthest from node 0 (the
    # centroids: R (5, 6.67), S (10.13, 5), 5.4 m away, A (5, 11), 4.3 m away)
    assert terminals(leaf_min_depth=2.5) == (1,)
    # a graph without a navmesh keeps every leaf
    assert select_cover(spine_and_side_room(), radius=3.0, leaf_min_depth=5.0) == select_cover(
        spine_and_side_room(), radius=3.0)


def test_leaf_min_depth_is_validated(registry):
    raw = preset("map_analysis", terminals={"plugin": "coverage", "params": {"leaf_min_depth": -1}})
    with pytest.raises(ConfigError, match="terminals.params.leaf_min_depth: expected a number"):
        pipeline.plan(parse_config(raw), registry)


def test_weighted_spearman_by_hand_and_against_scipy():
    rng = np.random.default_rng(3)
    x = rng.integers(0, 6, 40).astype(float)
    y = x + rng.normal(size=40)
    # equal weights: Spearman's rho with mid-ranks for ties
    assert evaluation.weighted_spearman(x, y, np.full(40, 2.5)) == pytest.approx(scipy.stats.spearmanr(x, y).statistic)
    # a whole-number weight counts as that many copies of the observation; weight 0 as none
    weight = rng.integers(0, 4, 40)
    assert evaluation.weighted_spearman(x, y, weight.astype(float)) == pytest.approx(
        scipy.stats.spearmanr(np.repeat(x, weight), np.repeat(y, weight)).statistic)
    # by hand: one big polygon that agrees outweighs two small ones that disagree
    x, y = np.array([1.0, 2.0, 3.0]), np.array([1.0, 3.0, 2.0])
    assert scipy.stats.spearmanr(x, y).statistic == pytest.approx(0.5)
    # weights 8, 1, 1: mid-ranks x 4, 8.5, 9.5 and y 4, 9.5, 8.5 (weighted mean 5): covariance
    # (8 + 3.5 x 4.5 + 4.5 x 3.5) / 10 = 3.95, variances (8 + 3.5² + 4.5²) / 10 = 4.05
    assert evaluation.weighted_spearman(x, y, np.array([8.0, 1.0, 1.0])) == pytest.approx(3.95 / 4.05)
    assert math.isnan(evaluation.weighted_spearman(x, np.ones(3), np.ones(3)))
    assert math.isnan(evaluation.weighted_spearman(x, y, np.zeros(3)))


def test_big_room_beside_a_many_polygon_corridor_swaps_rank_with_area_weighting():
    # A - H - B; A leads to a one-polygon room R of 100 m², B to a corridor of four 1 m² polygons
    graph = nx.Graph()
    graph.add_edges_from([("R", "A"), ("A", "H"), ("H", "B"), ("B", "C1"), ("C1", "C2"), ("C2", "C3"), ("C3", "C4")])
    area = {n: 1.0 for n in graph}
    area["R"] = 100.0
    plain = centrality.betweenness(graph)
    weighted = centrality.betweenness(graph, node_weight=area)
    assert plain["B"] > plain["A"]
    assert weighted["A"] > weighted["B"]
    # by hand: branches of A are {R} and the other 6 nodes: 100 * 6; of B, {C1..C4} and {H, A, R}: 4 * 102
    total = (sum(area.values()) ** 2 - sum(a * a for a in area.values())) / 2
    assert weighted["A"] == pytest.approx(600 / total) and weighted["B"] == pytest.approx(408 / total)
    # the analyzer takes the areas from the initial graph
    for node in graph:
        graph.nodes[node].update(area=area[node])
    for u, v in graph.edges:
        graph.edges[u, v]["weight"] = 1.0
    context = RunContext(mesh=None, agent=None, centre=np.zeros(3), graph=graph)
    values = betweenness_analyzer.g2s_analyze(graph, betweenness_analyzer.Params(weight_by_area=True), context)
    assert values == pytest.approx(weighted)


def test_flow_analyzer_mean_and_sum_by_hand():
    # structure nodes 1 (cell 0, 1, 2) and 4 (cell 3, 4)
    graph = corridor(5)
    structure = nx.Graph([(1, 4)])
    context = RunContext(mesh=None, agent=None, centre=np.zeros(3), graph=graph)
    # ordered pairs through node i: 2 i (4 - i), i.e. 0, 6, 8, 6, 0; all pair weight 5² = 25
    total = flow_analyzer.g2s_analyze(structure, flow_analyzer.Params(aggregate="sum"), context)
    assert total == pytest.approx({1: 14 / 25, 4: 6 / 25})
    mean = flow_analyzer.g2s_analyze(structure, flow_analyzer.Params(), context)
    assert mean == pytest.approx({1: 14 / 3 / 25, 4: 3 / 25})
    # flows 0, 6, 8, 6, 0 rank 1.5, 3.5, 5, 3.5, 1.5 of 5: percentiles 100 (rank - 0.5) / 5 = 20, 60, 90, 60, 20
    ranked = flow_analyzer.g2s_analyze(structure, flow_analyzer.Params(aggregate="percentile"), context)
    assert ranked == pytest.approx({1: (20 + 60 + 90) / 3, 4: (60 + 20) / 2})


def test_percentile_keeps_one_busy_polygon_from_lifting_its_node():
    # node 1 stands for 0, 1, 2 (one busy polygon), node 4 for 3, 4, 5 (all fairly busy)
    graph = corridor(6)
    flow = np.array([0.0, 0.0, 100.0, 10.0, 11.0, 12.0])
    mean = traffic.gather(graph, [1, 4], flow, mean=True)
    assert mean[1] > mean[4]  # 33.3 against 11
    # ranks 1.5, 1.5, 6, 3, 4, 5 of 6
    assert traffic.percentile(flow) == pytest.approx(100 * (np.array([1.5, 1.5, 6, 3, 4, 5]) - 0.5) / 6)
    ranked = traffic.gather(graph, [1, 4], traffic.percentile(flow), mean=True)
    assert ranked[4] > ranked[1]


def test_placement_heat_searches_the_nearest_structure_nodes_once(monkeypatch):
    """Corridor 0 - 5 and structure nodes 1 and 4: node 1 stands for 0, 1, 2, node 4 for 3, 4, 5; flows 0, 0,
    100, 10, 11, 12 rank 1.5, 1.5, 6, 3, 4, 5 (percentiles 100 (rank - 0.5) / 6). The heat map gives each node
    its structure node's mean percentile, after one search from the structure (gather takes its result
    instead of searching again)."""
    graph = corridor(6)
    flow = np.array([0.0, 0.0, 100.0, 10.0, 11.0, 12.0])
    searches = []
    search = traffic.distance_to
    monkeypatch.setattr(traffic, "distance_to", lambda *args: searches.append(args) or search(*args))
    heat = evaluation.placement_heat(graph, [4, 1], flow)
    near, far = 100 * (1 + 1 + 5.5) / 6 / 3, 100 * (2.5 + 3.5 + 4.5) / 6 / 3
    assert heat == pytest.approx([near, near, near, far, far, far]) and len(searches) == 1


@pytest.mark.parametrize("values", [
    [], [3.0], [0.0, -0.0, 0.0], [1.0, float("nan"), 2.0], [float("inf"), -float("inf"), 1.0, float("inf")], [0.0] * 7,
    np.random.default_rng(1).integers(0, 5, 1000).astype(float), np.round(np.random.default_rng(2).random(5000), 2),
    np.random.default_rng(3).random(5000),
], ids=range(9))
def test_percentile_ranks_are_scipys_to_the_bit(values):
    # the ranks are computed without scipy.stats (its import is slow); they must stay rankdata's, ties and nan included,
    # where no distinct values lie within the tie tolerance (here every gap between distinct values is over 1e-9)
    from scipy.stats import rankdata

    values = np.asarray(values, dtype=np.float64)
    expected = 100.0 * (rankdata(values) - 0.5) / max(values.size, 1)
    assert traffic.percentile(values).tobytes() == expected.tobytes()


EPS = float(np.finfo(np.float64).eps)


def test_values_one_unit_in_the_last_place_apart_are_tied():
    values = np.array([2.0, 1.0, np.nextafter(1.0, 2.0)])  # tolerance 2 n eps max = 2 * 3 * eps * 2 = 12 eps
    assert traffic.tie_tolerance(values) == 12 * EPS
    assert traffic.percentile(values).tolist() == pytest.approx([100 * 2.5 / 3, 100 * 1.0 / 3, 100 * 1.0 / 3])


def test_values_farther_apart_than_the_tolerance_are_not_tied():
    at_tolerance, beyond = np.array([1.0, 1.0 + 12 * EPS, 2.0]), np.array([1.0, 1.0 + 14 * EPS, 2.0])
    assert traffic.percentile(at_tolerance).tolist() == pytest.approx([100 * 1.0 / 3, 100 * 1.0 / 3, 100 * 2.5 / 3])
    assert traffic.percentile(beyond).tolist() == pytest.approx([100 * 0.5 / 3, 100 * 1.5 / 3, 100 * 2.5 / 3])


def test_a_chain_of_near_ties_is_one_run():
    # tolerance 2 * 4 * eps * 2 = 16 eps: each step of 10 eps ties, so the three are one run though its ends lie
    # 20 eps apart; 2 stands alone
    values = np.array([1.0 + 20 * EPS, 2.0, 1.0, 1.0 + 10 * EPS])
    assert traffic.percentile(values).tolist() == pytest.approx([100 * 1.5 / 4, 100 * 3.5 / 4, 100 * 1.5 / 4, 100 * 1.5 / 4])


def test_the_tolerance_scales_with_the_largest_finite_magnitude():
    assert traffic.tie_tolerance(np.array([-4.0, 1.0, np.inf, np.nan])) == 2 * 4 * EPS * 4.0
    assert traffic.tie_tolerance(np.array([0.0, 0.0])) == 0.0
    assert traffic.tie_tolerance(np.array([np.nan])) == traffic.tie_tolerance(np.array([])) == 0.0


def test_area_weighted_betweenness_with_a_loop_matches_brute_force():
    graph = ring(7, 1.0)
    graph.add_edge(0, 10, weight=2.4)  # unequal, so that no two paths tie
    graph.add_edge(10, 3, weight=2.6)
    rng = np.random.default_rng(4)
    area = {n: float(rng.uniform(1, 5)) for n in graph}
    values = centrality.betweenness(graph, weighted=True, normalized=False, node_weight=area)
    expected = dict.fromkeys(graph, 0.0)
    for s, paths in nx.all_pairs_dijkstra_path(graph):
        for t, path in paths.items():
            if s < t:
                for v in path[1:-1]:
                    expected[v] += area[s] * area[t]
    assert values == pytest.approx(expected)


def random_surface(n: int, seed: int) -> nx.Graph:
    """A random geometric graph with areas and Euclidean lengths (no equal path lengths)."""
    rng = np.random.default_rng(seed)
    graph = nx.random_geometric_graph(n, 0.25, seed=seed)
    graph = graph.subgraph(max(nx.connected_components(graph), key=len)).copy()
    for node in graph:
        graph.nodes[node]["area"] = float(rng.uniform(0.5, 3.0))
    for u, v in graph.edges:
        graph.edges[u, v]["weight"] = float(np.linalg.norm(np.subtract(graph.nodes[u]["pos"], graph.nodes[v]["pos"])))
    return graph


@pytest.mark.parametrize("seed", [1, 2])
def test_flow_is_exact_on_small_graphs_and_sampled_flow_within_its_bound(seed):
    graph = random_surface(60, seed)
    arrays = traffic.surface_arrays(graph)
    exact, sampled = traffic.od_flow(arrays.adjacency, arrays.area)
    assert sampled is None
    brute = np.zeros(arrays.n)
    for s, paths in nx.all_pairs_dijkstra_path(graph):
        for t, path in paths.items():
            for v in path[1:-1]:
                brute[arrays.index[v]] += graph.nodes[s]["area"] * graph.nodes[t]["area"]
    assert np.allclose(exact, brute)
    total = arrays.area.sum() ** 2
    for sources in (8, 24):
        estimate, sampled = traffic.od_flow(arrays.adjacency, arrays.area, max_sources=sources, seed=seed)
        assert sampled == sources
        # delta = 0.01 per node; the largest error over ~60 nodes stays well inside
        assert np.abs(estimate - exact).max() / total <= traffic.flow_error_bound(sources)


@pytest.mark.parametrize("kept", [1, 5 * 30, 1 << 25])
def test_flow_keeping_tree_blocks_before_summing_them_gives_the_same_bits(monkeypatch, kept):
    graph = random_surface(200, 3)
    arrays = traffic.surface_arrays(graph)
    monkeypatch.setattr(traffic, "BLOCK_ENTRIES", 5 * arrays.n)  # blocks of 5 sources
    monkeypatch.setattr(traffic, "KEPT_ENTRIES", kept * arrays.n)  # the products after every block, every 30, at the end
    flow, _ = traffic.od_flow(arrays.adjacency, arrays.area, max_sources=64, seed=4)
    # the sum block by block, each block's product as soon as its trees are made
    draws = np.random.default_rng(4).choice(np.flatnonzero(arrays.area > 0), size=64, replace=True,
                                            p=arrays.area / arrays.area.sum())
    sources, counts = np.unique(draws, return_counts=True)
    factor, expected = counts * (arrays.area.sum() / 64), np.zeros(arrays.n)
    assert len(sources) > 10
    for lo in range(0, len(sources), 5):
        expected += factor[lo:lo + 5] @ traffic.shortest_path_flow(arrays.adjacency, sources[lo:lo + 5], arrays.area)[1]
    assert flow.tobytes() == expected.tobytes()


PAPER_STRUCTURE_SHA256 = "7d0d88e6c161dcabe593221c3aa90c695d68052702a23e6388e8b1038faa89c0"
"""sha256 of the structure parts (below) of ``structure.json`` that the former ``map_analysis`` preset wrote for
nav_test.obj before issue 9 (55 nodes, 45 edges); later stronger line-of-sight tests must not move it."""


def test_paper_preset_reproduces_the_former_map_analysis(registry, shared_data):
    mesh, _ = load_mesh(shared_data / "nav_test.obj")
    document = structure_document(run(registry, mesh, preset("map_analysis_paper"), "nav_test.obj"))
    part = {key: document[key] for key in ("nodes", "edges", "roots", "trees", "graphs", "terminals", "analysis_keys")}
    assert (len(part["nodes"]), len(part["edges"])) == (55, 45)
    assert hashlib.sha256(json.dumps(part, sort_keys=True).encode()).hexdigest() == PAPER_STRUCTURE_SHA256
    # the defaults' stronger line-of-sight tests do change it: the parameters are what keeps the paper
    default = preset("map_analysis_paper", simplify={"plugin": "surface_los"})
    assert len(structure_document(run(registry, mesh, default, "nav_test.obj"))["nodes"]) != 55


def test_new_preset_covers_nav_test_and_keeps_a_skeleton(registry, shared_data):
    mesh, _ = load_mesh(shared_data / "nav_test.obj")
    result = run(registry, mesh, preset("map_analysis"))
    quality = evaluation.evaluate(result)
    assert quality.area_within[6.0] > 0.95
    assert quality.structure_share < 0.7  # nav_test has big polygons: 179 for 4,265 m²
    # the heat map is walking flow, exact on 179 polygons as the reference is: its rho is the ceiling by construction
    assert quality.rho == pytest.approx(quality.rho_ceiling)
    assert -1.0 <= quality.rho_area_betweenness < quality.rho


def lengths(n: int, edges: list[tuple[int, int, float]]) -> sp.csr_array:
    """Symmetric CSR edge lengths of an undirected graph on nodes 0..n-1."""
    u, v, w = (np.array(column) for column in zip(*edges))
    return sp.csr_array((np.concatenate([w, w]), (np.concatenate([u, v]), np.concatenate([v, u]))), shape=(n, n))


def grid_lengths(width: int, height: int, rng: np.random.Generator | None = None, diagonals: bool = False) -> sp.csr_array:
    """A grid of unit steps (random lengths 1 or 2 with ``rng``): full of equally short paths."""
    steps = [(1, 0), (0, 1)] + ([(1, 1), (1, -1)] if diagonals else [])
    edges = [
        (y * width + x, (y + dy) * width + x + dx, math.hypot(dx, dy) if rng is None else float(rng.integers(1, 3)))
        for y in range(height) for x in range(width) for dx, dy in steps
        if 0 <= x + dx < width and 0 <= y + dy < height
    ]
    return lengths(width * height, edges)


def test_shortest_path_flow_by_hand():
    # tree 0 - 1 - 2 and 0 - 3, a lone node 4; values 1, 2, 4, 8, 16
    graph = lengths(5, [(0, 1, 1.0), (1, 2, 1.0), (0, 3, 1.0)])
    values = np.array([1.0, 2.0, 4.0, 8.0, 16.0])
    predecessors, through = traffic.shortest_path_flow(graph, np.array([0, 1]), values)
    assert predecessors.tolist() == [[-9999, 0, 1, 0, -9999], [1, -9999, 1, 0, -9999]]
    # from 0, node 1 carries node 2's value; from 1, node 0 carries node 3's; sources, leaves and node 4 nothing
    assert through.tolist() == [[0.0, 4.0, 0.0, 0.0, 0.0], [8.0, 0.0, 0.0, 0.0, 0.0]]
    # a square 0 - 1 - 3 - 2 - 0: node 3 is as near through 1 as through 2; as in scipy, the higher index settles
    # first and keeps it
    square = lengths(4, [(0, 1, 1.0), (0, 2, 1.0), (1, 3, 1.0), (2, 3, 1.0)])
    predecessors, through = traffic.shortest_path_flow(square, np.array([0]), values[:4])
    assert predecessors.tolist() == [[-9999, 0, 0, 2]]
    assert through.tolist() == [[0.0, 0.0, 8.0, 0.0]]
    # the same square with every row's entries stored in reverse: the same trees and sums
    reversed_rows = np.concatenate([np.arange(a, b)[::-1] for a, b in zip(square.indptr, square.indptr[1:])])
    unsorted = sp.csr_array((square.data[reversed_rows], square.indices[reversed_rows], square.indptr), shape=square.shape)
    assert [a.tolist() for a in traffic.shortest_path_flow(unsorted, np.array([0, 3]), values[:4])] == \
        [a.tolist() for a in traffic.shortest_path_flow(square, np.array([0, 3]), values[:4])]
    with pytest.raises(ValueError, match="negative"):
        traffic.shortest_path_flow(lengths(2, [(0, 1, -1.0)]), np.array([0]), values[:2])
    with pytest.raises(ValueError, match="source"):
        traffic.shortest_path_flow(square, np.array([4]), values[:4])


@pytest.mark.skipif(
    tuple(int(part) for part in scipy.__version__.split(".")[:2]) < (1, 15),
    reason="scipy before 1.15 searched with a Fibonacci heap, which breaks ties in another order",
)
@pytest.mark.parametrize("name", ["grid", "grid of lengths 1 and 2", "grid with diagonals", "random"])
def test_shortest_path_trees_are_scipys_to_the_last_tie(name):
    rng = np.random.default_rng(5)
    graph = {
        "grid": grid_lengths(23, 17),
        "grid of lengths 1 and 2": grid_lengths(19, 19, rng),
        "grid with diagonals": grid_lengths(15, 21, diagonals=True),
        "random": lengths(300, [(int(a), int(b), float(rng.integers(1, 4))) for a, b in rng.integers(0, 300, (600, 2)) if a != b]),
    }[name]
    sources = rng.choice(graph.shape[0], 40, replace=False)
    _, expected = csgraph.dijkstra(graph, directed=True, indices=sources, return_predecessors=True)
    predecessors, _ = traffic.shortest_path_flow(graph, sources, rng.random(graph.shape[0]))
    assert np.array_equal(predecessors, expected)


def corridor_lengths(rng: np.random.Generator, junctions: int, corridors: int) -> sp.csr_array:
    """Random junctions joined by corridors of 0-5 passage nodes (two neighbours each), lengths 1 or 2:
    corridors as in a navmesh graph, full of equally short paths."""
    edges, node = [], junctions
    for _ in range(corridors):
        previous, end = (int(v) for v in rng.integers(0, junctions, 2))
        for _ in range(int(rng.integers(0, 6))):
            edges.append((previous, node, float(rng.integers(1, 3))))
            previous, node = node, node + 1
        if previous != end:
            edges.append((previous, end, float(rng.integers(1, 3))))
    graph = lengths(node, edges)
    graph.sum_duplicates()
    return graph


@pytest.mark.skipif(
    tuple(int(part) for part in scipy.__version__.split(".")[:2]) < (1, 15),
    reason="scipy before 1.15 searched with a Fibonacci heap, which breaks ties in another order",
)
def test_shortest_path_trees_through_corridors_are_scipys():
    # the search walks through passage nodes instead of queueing them and applies scipy's tie rule itself:
    # the same trees, sources inside corridors included
    rng = np.random.default_rng(11)
    for junctions, corridors in [(3, 8), (10, 30), (40, 120)]:
        graph = corridor_lengths(rng, junctions, corridors)
        sources = rng.choice(graph.shape[0], 20, replace=False)
        _, expected = csgraph.dijkstra(graph, directed=True, indices=sources, return_predecessors=True)
        predecessors, _ = traffic.shortest_path_flow(graph, sources, rng.random(graph.shape[0]))
        assert np.array_equal(predecessors, expected)
    # a triangle 0 - 1 (length 0), 0 - 2 and 1 - 2 (length 1), searched from 0: 1 is as near as 0 but settles
    # after it, so 2 stays with 0, the first to reach it (the tie rule's order would give it to 1)
    flat = lengths(3, [(0, 1, 0.0), (0, 2, 1.0), (1, 2, 1.0)])
    assert traffic.shortest_path_flow(flat, np.array([0]), np.ones(3))[0].tolist() == [[-9999, 0, 0]]


def test_shortest_path_flow_adds_as_numpy_does(monkeypatch):
    # a star of 300 leaves and random graphs with values over six orders of magnitude: each node's children
    # summed in numpy's pairwise order, to the bit (the flow values, and so the structure output, must not
    # move with the implementation), on one thread or two alike
    rng = np.random.default_rng(3)
    star = lengths(301, [(0, leaf, 1.0) for leaf in range(1, 301)])
    tree = lengths(301, [(node, int(rng.integers(0, node)), float(rng.random())) for node in range(1, 301)])
    loops = lengths(301, [(int(a), int(b), float(rng.random())) for a, b in rng.integers(0, 301, (900, 2)) if a != b])
    values = rng.random(301) * 10.0 ** rng.uniform(-3, 3, 301)
    for graph in (star, tree, loops):
        sources = np.array([0, 7, 300])
        predecessors, through = traffic.shortest_path_flow(graph, sources, values)
        for row, source in enumerate(sources):
            distance = csgraph.dijkstra(graph, indices=int(source))
            totals = values.copy()
            for node in np.argsort(-distance, kind="stable"):  # farthest first: children before parents
                children = np.flatnonzero(predecessors[row] == node)
                if children.size:
                    totals[node] = values[node] + np.add.reduceat(totals[children], [0])[0]
            expected = np.where(np.isfinite(distance), totals - values, 0.0)
            expected[source] = 0.0
            assert np.array_equal(through[row], expected)
        with monkeypatch.context() as one_thread:
            one_thread.setattr(traffic, "THREADS", 1)
            assert np.array_equal(traffic.shortest_path_flow(graph, sources, values)[1], through)


def test_the_traffic_evaluator_puts_the_evaluation_in_the_run_result(registry):
    mesh = samples.dungeon(seed=2, rooms=10).mesh
    evaluated = preset("map_analysis", evaluators=[{"plugin": "traffic", "params": {"radii": [2.5, 6]}}])
    result = run(registry, mesh, evaluated)
    quality = evaluation.evaluate(result, radii=(2.5, 6.0))
    assert result.metrics == {"traffic": {
        "area_within_2_5m": quality.area_within[2.5], "area_within_6m": quality.area_within[6.0],
        "rho": quality.rho, "rho_area": quality.rho_area, "rho_area_betweenness": quality.rho_area_betweenness, "rho_ceiling": quality.rho_ceiling,
        "rho_within": quality.rho_within, "rho_within_ceiling": quality.rho_within_ceiling,
        "structure_share": quality.structure_share, "traffic_off": quality.traffic_off,
        "rho_navmesh": quality.rho, "rho_navmesh_ceiling": quality.rho_ceiling,
        "navmesh_area_left_out": quality.navmesh_area_left_out}}
    assert [s.stage for s in result.stages][-2:] == ["analysis", "evaluation"]
    # without an analyzer there is no heat map: rho is left out, the rest is measured
    bare = run(registry, mesh, {**evaluated, "analyzers": []})
    assert sorted(bare.metrics["traffic"]) == ["area_within_2_5m", "area_within_6m", "navmesh_area_left_out",
                                               "rho_area_betweenness", "rho_ceiling", "rho_navmesh_ceiling",
                                               "rho_within_ceiling", "structure_share", "traffic_off"]
    assert bare.stages[-1].stage == "evaluation" and not bare.analysis
    assert not run(registry, mesh, {**evaluated, "stop_after": "analyzers"}).metrics
