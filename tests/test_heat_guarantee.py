"""The guaranteed heat map (``min_heat_rho``): on a hand-checkable corridor, and through the pipeline."""

from __future__ import annotations

import math
import types

import networkx as nx
import numpy as np
import pytest
import scipy.stats

from g2s_core import pipeline
from g2s_core.config import PRESETS_DIR, AgentConfig, load_raw_config, parse_config
from g2s_core.mesh import load_mesh, mesh_sha256
from g2s_core.model import RunContext
from g2s_core.plugin import PluginParams, hookimpl
from g2s_core.registry import Registry
from g2s_core.rooted import root_forest
from g2s_core.simplify import simplify_forest
from g2s_plugins import evaluation, heat_guarantee, traffic
from g2s_plugins._surface import CollapseParams, collapse_rule


def corridor(n: int = 9) -> nx.Graph:
    """A straight corridor of n polygons of 1 m², 1 m apart, flat and all on the navmesh."""
    graph = nx.path_graph(n)
    for i in graph:
        graph.nodes[i].update(pos=(float(i), 0.0, 0.0), area=1.0, normal=(0.0, 1.0, 0.0), on_navmesh=True)
    nx.set_edge_attributes(graph, 1.0, "weight")
    return graph


def simplified(graph: nx.Graph, params: CollapseParams) -> tuple[nx.DiGraph, list[float]]:
    """The structure of the corridor rooted at 0, simplified as the pipeline does it (line of sight everywhere),
    and the rho of each structure the loop made."""
    forest = root_forest(graph, {i: -i for i in graph}, centre=np.zeros(3))
    context = RunContext(mesh=None, agent=AgentConfig(), centre=np.zeros(3), graph=graph)
    flow = traffic.walking_flow(graph, max_sources=traffic.WALKING_SOURCES)
    structure, rhos = None, []
    while (predicate := heat_guarantee.guaranteed(lambda: collapse_rule(params, lambda start, end: True, graph),
                                                  params, context, forest, structure)) is not None:
        structure = simplify_forest(forest, predicate)
        rhos.append(evaluation.placement_rho(graph, structure, flow))
    return structure, rhos


def test_the_corridor_by_hand():
    # ordered pairs through node i of a corridor of nine 1 m² polygons: 2 i (8 - i)
    graph = corridor()
    flow = traffic.walking_flow(graph, max_sources=traffic.WALKING_SOURCES)
    assert flow.tolist() == [0, 14, 24, 30, 32, 30, 24, 14, 0]
    # the step of 60 percentile points keeps 3 (77.8 against the root's 11.1) and lets every other node go
    structure, rhos = simplified(graph, CollapseParams(max_traffic_step=60.0))
    assert sorted(structure) == [0, 3, 8]
    # nearest structure node: 0, 1 -> 0; 2-5 -> 3; 6-8 -> 8 (ranks 1.5, 3.5, 5.5, 7.5, 9 of the five flows)
    heat = [22.2, 22.2, 76.4, 76.4, 76.4, 76.4, 33.3, 33.3, 33.3]
    assert evaluation.placement_heat(graph, structure, flow) == pytest.approx(heat, abs=0.05)
    assert rhos == [pytest.approx(scipy.stats.spearmanr(heat, flow).statistic)]
    assert rhos[0] == pytest.approx(0.8291, abs=1e-4)


def test_a_fixed_step_under_the_target_gets_its_nodes_back_until_it_holds():
    graph = corridor()
    structure, rhos = simplified(graph, CollapseParams(max_traffic_step=60.0, min_heat_rho=0.9))
    # one node a round (ceil of 2 % of 9), of the removed nodes more than 10 points off their heat the one whose
    # return lowers the squared error most: {0, 3, 8} gives cells {0, 1}, {2-5}, {6-8} (percentiles 11.1 33.3 55.6
    # 77.8 94.4 77.8 55.6 33.3 11.1; heat 22.2, 76.4, 33.3). 6 differs most (55.6 against 33.3) but would take 5
    # (77.8) from 3's cell too: the squares fall by 495.9; 2 (55.6 against 76.4) takes itself alone, 4/3 x 20.8² =
    # 578.7, so 2 comes back; then 6 (66.7 and 33.3 for {5, 6} against 77.8 / 55.6); rho 0.829 -> 0.872 -> 0.935
    assert sorted(structure) == [0, 2, 3, 6, 8]
    assert rhos == pytest.approx([0.8291, 0.8725, 0.9353], abs=1e-4)
    heat = [11.1, 44.4, 44.4, 86.1, 86.1, 66.7, 66.7, 22.2, 22.2]
    assert evaluation.placement_heat(graph, structure, traffic.walking_flow(graph)) == pytest.approx(heat, abs=0.05)


def test_a_round_restores_only_as_many_of_its_nodes_as_reach_the_target(monkeypatch):
    # the corridor kept at {0, 3, 8} (rho 0.8291), a round of half the forest's nodes (ceil(0.5 x 9) = 5): the four
    # removed nodes more than 10 points off their heat rank 2, 6, 4, 1 (the test above: 2 gains most, then 6). All
    # four read 0.9573, so the round stops short: 2 and 6 read 0.9353 >= 0.9, 2 alone 0.8725 (the bisection's two
    # readings after the first); without the rule the round gives back 1, 2, 4 and 6
    monkeypatch.setattr(heat_guarantee, "RESTORED_SHARE", 0.5)
    graph = corridor()
    flow = traffic.walking_flow(graph)
    assert evaluation.placement_rho(graph, {0, 1, 2, 3, 4, 6, 8}, flow) == pytest.approx(0.9573, abs=1e-4)
    assert evaluation.placement_rho(graph, {0, 2, 3, 6, 8}, flow) == pytest.approx(0.9353, abs=1e-4)
    assert evaluation.placement_rho(graph, {0, 2, 3, 8}, flow) == pytest.approx(0.8725, abs=1e-4)
    context = RunContext(mesh=None, agent=AgentConfig(), centre=np.zeros(3), graph=graph)
    for target, kept in ((0.9, {0, 2, 3, 6, 8}), (0.96, {0, 1, 2, 3, 4, 6, 8})):  # 0.96: all four read under it
        forest = root_forest(graph, {i: -i for i in graph}, centre=np.zeros(3))  # a first round of its own
        assert heat_guarantee.restored(graph, forest, forest.subgraph({0, 3, 8}), target, context) == kept


def test_a_later_round_keeps_the_restored_nodes_not_the_nodes_only_line_of_sight_kept(monkeypatch):
    # a corner at 4: no walk from 0-2 to 5-8, so Algorithm 4 keeps 4 ({0, 4, 8}); once 3 is restored it ends the
    # chain from 0 and sees 5, so with heat_rounds_keep: restored the next round lets 4 go ({0, 3, 8}) and the third
    # keeps 3 and 6 only; heat_rounds_keep: structure (the default) keeps every node of the last structure
    graph = corridor()
    context = RunContext(mesh=None, agent=AgentConfig(), centre=np.zeros(3), graph=graph)

    def sees(start, end):
        return not (min(start[0], end[0]) <= 2 and max(start[0], end[0]) >= 5)

    def rounds(keep: str) -> list[list[int]]:
        forest = root_forest(graph, {i: -i for i in graph}, centre=np.zeros(3))
        params = CollapseParams(min_heat_rho=0.9, heat_rounds_keep=keep)
        given = iter([{3}, {6}, None])  # the guarantee gives back 3, then 6, then holds
        monkeypatch.setattr(heat_guarantee, "restored", lambda graph, forest, simplified, *rest: (
            None if (back := next(given)) is None else set(simplified) | back))
        structures, structure = [], None
        while (predicate := heat_guarantee.guaranteed(lambda: collapse_rule(params, sees, graph), params, context,
                                                      forest, structure)) is not None:
            structure = simplify_forest(forest, predicate)
            structures.append(sorted(structure))
        return structures

    assert rounds("restored") == [[0, 4, 8], [0, 3, 8], [0, 3, 6, 8]]
    assert rounds("structure") == [[0, 4, 8], [0, 3, 4, 8], [0, 3, 4, 6, 8]]


def test_within_areas_the_islands_lend_the_corridor_no_rho():
    # the corridor and 12 polygons apart, each an area of its own: their flow is 0 and so is their heat's rank,
    # which the level-wide rho counts as agreement (0.937 after one round, {0, 4, 8} and 1) while the corridor's own
    # order reads 0.8725; read within areas (where an area of one node weighs nothing) the guarantee restores 6,
    # then 2, as on the corridor alone (the percentiles within its area are the corridor's own)
    graph = corridor()
    for island in range(9, 21):
        graph.add_node(island, pos=(float(island), 0.0, 5.0), area=1.0, normal=(0.0, 1.0, 0.0), on_navmesh=True)
    flow = traffic.walking_flow(graph, max_sources=traffic.WALKING_SOURCES)
    areas = evaluation.area_labels(graph)
    level, level_rhos = simplified(graph, CollapseParams(max_traffic_step=60.0, min_heat_rho=0.9))
    within, within_rhos = simplified(graph, CollapseParams(max_traffic_step=60.0, min_heat_rho=0.9,
                                                           heat_rho_within_areas=True))
    assert level_rhos == pytest.approx([0.8874, 0.9371], abs=1e-4)
    assert evaluation.within_area_rho(evaluation.placement_heat(graph, level, flow), flow, areas) == pytest.approx(
        0.8725, abs=1e-4)
    assert sorted(node for node in level if node < 9) == [0, 1, 4, 8]
    assert sorted(node for node in within if node < 9) == [0, 2, 4, 6, 8] and len(within_rhos) == 3
    assert evaluation.within_area_rho(evaluation.placement_heat(graph, within, flow), flow, areas) == pytest.approx(
        0.9353, abs=1e-4)


def two_corridors() -> nx.Graph:
    """Corridors of 7 and 5 polygons of 1 m², 1 m apart, 5 m from each other: two connected areas, rows 0-6 and
    7-11."""
    graph = nx.disjoint_union(corridor(7), corridor(5))
    for i in range(7, 12):
        graph.nodes[i]["pos"] = (float(i - 7), 0.0, 5.0)
    return graph


def test_within_areas_the_node_restored_is_the_one_its_area_ranks_worst():
    # flow 2 i (n - 1 - i) in each corridor: 0 10 16 18 16 10 0 and 0 6 8 6 0. Kept {0, 3, 6} and {7, 8, 11}: node
    # 1 has the heat of 0 (mean of 0 and 1), node 10 that of 11. Level-wide the short corridor's flows all sit low,
    # so its errors look small: 1 is 25 points off its heat (66.7 against 41.7), 10 only 12.5 (41.7 against 29.2),
    # and 1 comes back. With percentiles within each area (the scale rho within areas ranks the flow on) 1 is 14.3
    # points off (42.9 against 28.6), 10 is 20 off (60 against 40, the mean of 60 and 20), and 10 comes back: it lifts
    # rho within areas from 0.8526 to 0.9000, the most any one node does, where 1 lifts it to 0.8756
    graph = two_corridors()
    areas = evaluation.area_labels(graph)
    forest = nx.DiGraph([(i, i + 1) for i in range(11) if i != 6])
    kept = {0, 3, 6, 7, 8, 11}
    flow = traffic.walking_flow(graph)
    assert evaluation.within_area_percentiles(flow, areas) == pytest.approx(
        [14.29, 42.86, 71.43, 92.86, 71.43, 42.86, 14.29, 20, 60, 90, 60, 20], abs=0.01)
    assert evaluation.placement_heat(graph, kept, flow, areas=areas) == pytest.approx(
        [28.57, 28.57, 78.57, 78.57, 78.57, 28.57, 28.57, 20, 75, 75, 40, 40], abs=0.01)
    context = RunContext(mesh=None, agent=AgentConfig(), centre=np.zeros(3), graph=graph)
    level = heat_guarantee.restored(graph, forest, forest.subgraph(kept), 0.95, context)
    within = heat_guarantee.restored(graph, forest, forest.subgraph(kept), 0.95, context, within_areas=True)
    assert level == kept | {1} and within == kept | {10}
    rho_within = {node: evaluation.within_area_rho(evaluation.placement_heat(graph, kept | {node}, flow), flow, areas)
                  for node in set(graph) - kept}
    assert evaluation.within_area_rho(evaluation.placement_heat(graph, kept, flow), flow, areas) == pytest.approx(
        0.8526, abs=1e-4)
    assert rho_within[10] == pytest.approx(0.9, abs=1e-4) and rho_within[1] == pytest.approx(0.8756, abs=1e-4)
    assert max(rho_within, key=rho_within.get) == 10


def test_on_one_area_within_areas_restores_what_the_level_wide_rule_does():
    # within each area of a graph of one area the percentiles are the level-wide ones bit for bit, so the rule picks
    # the same nodes: on the corridor, kept {0, 3, 8}, node 2 (the test above)
    graph = corridor()
    flow = traffic.walking_flow(graph)
    areas = evaluation.area_labels(graph)
    assert np.array_equal(evaluation.within_area_percentiles(flow, areas), traffic.percentile(flow))
    forest = root_forest(graph, {i: -i for i in graph}, centre=np.zeros(3))
    context = RunContext(mesh=None, agent=AgentConfig(), centre=np.zeros(3), graph=graph)
    structure = forest.subgraph({0, 3, 8})
    level = heat_guarantee.restored(graph, forest, structure, 0.9, context)
    assert level == {0, 2, 3, 8} == heat_guarantee.restored(graph, forest, structure, 0.9, context, within_areas=True)


def test_the_restore_choice_counts_the_samples_a_node_would_take_over():
    # a corridor 0-21 and an alcove 22 off node 0, the structure {0} standing for all 23 nodes; percentiles 90 on
    # 0 and 1, 0 on the alcove, 20 on 2-21: the heat 580 / 23 = 25.2 everywhere. The alcove differs most (25.2
    # points; 2 only 5.2) but stands for itself alone: restoring it lowers the squared error by
    # 580² (1/22 - 1/23) = 664.8. Node 2 would take 2-21 (1 is as near 0 as 2, so it stays): 400² / 20 + 180² / 3
    # - 580² / 23 = 4,173.9
    graph = corridor(22)
    graph.add_edge(0, 22, weight=1.0)
    graph.nodes[22].update(pos=(-1.0, 0.0, 0.0), area=1.0, normal=(0.0, 1.0, 0.0), on_navmesh=True)
    arrays = traffic.surface_arrays(graph)
    own = np.array([90.0 if node in (0, 1) else 0.0 if node == 22 else 20.0 for node in arrays.nodes])
    distance, nearest = traffic.distance_to(arrays, arrays.rows([0]))
    gains = heat_guarantee.restore_gains(arrays, distance, nearest, own, arrays.rows([22, 2]))
    assert gains == pytest.approx([664.8, 4173.9], abs=0.05)


def test_a_structure_that_holds_is_kept_as_it_is():
    graph = corridor()
    plain, _ = simplified(graph, CollapseParams(max_traffic_step=60.0))
    held, rhos = simplified(graph, CollapseParams(max_traffic_step=60.0, min_heat_rho=0.8))
    assert rhos == [pytest.approx(0.8291, abs=1e-4)]
    assert sorted(held.edges) == sorted(plain.edges)


def test_a_target_out_of_reach_stops_at_the_floor_and_says_so():
    graph = corridor()
    context = RunContext(mesh=None, agent=AgentConfig(), centre=np.zeros(3), graph=graph)
    forest = root_forest(graph, {i: -i for i in graph}, centre=np.zeros(3))
    # every node kept: rho 1, kept without a word
    assert heat_guarantee.restored(graph, forest, forest, 1.0, context) is None and not context.warnings
    # all but 4 (94.4): its nearest node stands for both, heat 86.1, 8.3 points off: under the floor of 10
    assert heat_guarantee.restored(graph, forest, forest.subgraph(set(graph) - {4}), 1.0, context) is None
    assert "rho 0.987" in context.warnings[0] and "under min_heat_rho 1" in context.warnings[0]


def predicate_plugin(asked: list, takes_simplified: bool) -> types.ModuleType:
    """A SimplifyPredicate that lets every node go first; when it takes ``simplified``, it then keeps the smallest
    node that went, and keeps the structure that holds it."""
    module = types.ModuleType("plugin_rounds")
    module.NAME = "rounds"

    class Params(PluginParams):
        """No parameters."""

    module.Params = Params
    kept: list = []
    if takes_simplified:
        @hookimpl
        def g2s_simplify_predicate(params, context, forest, simplified):
            asked.append(simplified if simplified is None else set(simplified))
            if simplified is None:
                return lambda tree, a, b, c: True
            if kept:
                return None if kept[0] in simplified else lambda tree, a, b, c: True
            kept.append(min(set(forest) - set(simplified)))
            return lambda tree, a, b, c: b != kept[0]
    else:
        @hookimpl
        def g2s_simplify_predicate(params, context):
            asked.append("once")
            return lambda tree, a, b, c: True
    module.g2s_simplify_predicate = g2s_simplify_predicate
    module.kept = kept
    return module


@pytest.mark.parametrize("takes", [True, False])
def test_the_pipeline_asks_again_only_a_predicate_that_takes_simplified(shared_data, takes):
    registry = Registry.from_entry_points()
    asked: list = []
    plugin = predicate_plugin(asked, takes)
    registry.register(plugin, package="test", entry_point="simplify.rounds")
    raw = load_raw_config(PRESETS_DIR / "map_analysis_paper.yaml")
    raw["simplify"] = {"plugin": "rounds"}
    raw["analyzers"] = []
    mesh = load_mesh(shared_data / "nav_test.obj")[0]
    result = pipeline.run(pipeline.plan(parse_config(raw), registry), registry, mesh, "nav_test", mesh_sha256(mesh))
    if takes:
        (node,) = plugin.kept
        assert asked[0] is None and node not in asked[1] and node in asked[2] and len(asked) == 3
        assert set(result.structure) == asked[2]
    else:
        assert asked == ["once"]


def test_map_analysis_on_a_level_that_holds_measures_once_and_changes_nothing(shared_data, monkeypatch):
    registry = Registry.from_entry_points()
    mesh = load_mesh(shared_data / "nav_test.obj")[0]
    measured = []
    restored = heat_guarantee.restored
    monkeypatch.setattr(heat_guarantee, "restored", lambda *args: measured.append(1) or restored(*args))
    structures = []
    for rho in (0.9, None):
        raw = load_raw_config(PRESETS_DIR / "map_analysis.yaml")
        raw["simplify"]["params"]["min_heat_rho"] = rho
        result = pipeline.run(pipeline.plan(parse_config(raw), registry), registry, mesh, "nav_test", mesh_sha256(mesh))
        structures.append((sorted(result.structure.nodes), sorted(result.structure.edges)))
    assert measured == [1]  # nav_test's heat map holds 0.967: one measure, no second simplification
    assert structures[0] == structures[1]


def test_none_keeps_a_structure_only_once_one_was_given():
    from g2s_core.errors import PluginFailure

    @hookimpl
    def g2s_simplify_predicate(params, context, forest, simplified):
        return None

    module = types.ModuleType("plugin_nothing")
    module.NAME, module.g2s_simplify_predicate = "nothing", g2s_simplify_predicate
    registry = Registry()
    info = registry.register(module, package="test", entry_point="simplify.nothing")
    with pytest.raises(PluginFailure, match="returned NoneType, not a callable P"):
        registry.call(info, params=info.params_model(), context=None, forest=None, simplified=None)
    assert registry.call(info, params=info.params_model(), context=None, forest=None, simplified=nx.DiGraph()) is None


def bumpy_grid() -> nx.Graph:
    """A 20 x 15 grid of polygons of 0.5-2 m², 0.8-1.2 m apart (seeded): 300 nodes with an area, more than the
    256 sources of the run's walking flow, so that flow is a sample."""
    rng = np.random.default_rng(0)
    graph = nx.convert_node_labels_to_integers(nx.grid_2d_graph(20, 15), ordering="sorted")
    for i in graph:
        graph.nodes[i].update(pos=(float(i // 15), 0.0, float(i % 15)), area=float(rng.uniform(0.5, 2.0)),
                              normal=(0.0, 1.0, 0.0), on_navmesh=True)
    for a, b in graph.edges:
        graph.edges[a, b]["weight"] = float(rng.uniform(0.8, 1.2))
    return graph


def test_the_guarantee_follows_the_exact_flow_where_the_sample_says_otherwise():
    graph = bumpy_grid()
    forest = nx.DiGraph(nx.bfs_tree(graph, 0))
    structure = forest.subgraph(np.random.default_rng(0).choice(300, size=200, replace=False).tolist())
    context = RunContext(mesh=None, agent=AgentConfig(), centre=np.zeros(3), graph=graph)
    sampled = traffic.walking_flow(graph, max_sources=traffic.WALKING_SOURCES)
    exact, _ = traffic.od_flow(traffic.surface_arrays(graph).adjacency, traffic.surface_arrays(graph).area)
    heat = evaluation.placement_heat(graph, structure, sampled)  # the heat map the run shows
    # the run's own 256-source flow says the heat map holds 0.9; against the exact flow it does not
    assert evaluation.spearman(heat, sampled) == pytest.approx(0.9093, abs=1e-4)
    assert evaluation.spearman(heat, exact) == pytest.approx(0.8962, abs=1e-4)
    kept = heat_guarantee.restored(graph, forest, structure, 0.9, context)
    # of the round's ceil(0.02 x 300) = 6 nodes, the first already takes the heat map over 0.9 against the exact flow
    assert kept is not None and set(structure) < kept and len(kept) == 201
    assert evaluation.spearman(evaluation.placement_heat(graph, kept, sampled), exact) >= 0.9
    # a target both flows meet keeps the structure
    assert heat_guarantee.restored(graph, forest, structure, 0.89, context) is None and not context.warnings


def test_above_the_exact_size_the_sampled_measure_must_clear_the_margin(monkeypatch):
    graph = bumpy_grid()
    forest = nx.DiGraph(nx.bfs_tree(graph, 0))
    structure = forest.subgraph(np.random.default_rng(0).choice(300, size=200, replace=False).tolist())
    context = RunContext(mesh=None, agent=AgentConfig(), centre=np.zeros(3), graph=graph)
    monkeypatch.setattr(traffic, "EXACT_NODES", 256)  # the grid's 300 nodes are above it: the sample decides
    # 0.9093 by the sample: it meets 0.86 + 0.04, not 0.88 + 0.04
    assert heat_guarantee.MARGINS["none"] == 0.04
    assert heat_guarantee.restored(graph, forest, structure, 0.86, context) is None
    assert heat_guarantee.restored(graph, forest, structure, 0.88, context) is not None
    # the structure that met 0.86 + 0.04 was confirmed by another sample: 0.8857 against it, and the two samples
    # rank each other at 0.9770, so the estimate is 0.8857 / sqrt(0.9770) = 0.8961 (the exact flow's: 0.8962), over
    # 0.86, so without a word
    shown = traffic.walking_flow(graph, max_sources=traffic.WALKING_SOURCES)
    other = traffic.walking_flow(graph, max_sources=traffic.WALKING_SOURCES, seed=heat_guarantee.CONFIRMING_SEED)
    heat = evaluation.placement_heat(graph, structure, shown)
    assert evaluation.spearman(heat, other) == pytest.approx(0.8857, abs=1e-4) and not context.warnings
    estimate = evaluation.spearman(heat, other) / math.sqrt(evaluation.spearman(shown, other))
    assert estimate == pytest.approx(0.8961, abs=1e-4)


def test_a_linearly_scaled_sample_needs_the_smaller_margin_it_measured(monkeypatch):
    graph = bumpy_grid()
    forest = nx.DiGraph(nx.bfs_tree(graph, 0))
    structure = forest.subgraph(np.random.default_rng(0).choice(300, size=200, replace=False).tolist())
    monkeypatch.setattr(traffic, "EXACT_NODES", 256)  # the grid's 300 nodes are above it: the sample decides
    exact = traffic.walking_flow(graph)
    # the same 256 sources counted plain read the heat map 0.0132 above the exact flow, linearly scaled 0.0021
    plain = traffic.walking_flow(graph, max_sources=traffic.WALKING_SOURCES)
    linear = traffic.walking_flow(graph, max_sources=traffic.WALKING_SOURCES, scaling="linear")
    heat = evaluation.placement_heat(graph, structure, linear)
    assert evaluation.spearman(heat, linear) == pytest.approx(0.9065, abs=1e-4)
    assert evaluation.spearman(heat, exact) == pytest.approx(0.9044, abs=1e-4)
    plain_heat = evaluation.placement_heat(graph, structure, plain)
    assert evaluation.spearman(plain_heat, plain) - evaluation.spearman(plain_heat, exact) == pytest.approx(0.0132, abs=1e-4)
    assert heat_guarantee.MARGINS == {"none": 0.04, "linear": 0.02}
    # for 0.88 the plain sample's 0.9093 is under 0.88 + 0.04 (nodes come back; 0.8962 exact), the linear sample's
    # 0.9065 over 0.88 + 0.02 (kept as it is; 0.9044 exact); for 0.8866 it is under 0.8866 + 0.02
    context = RunContext(mesh=None, agent=AgentConfig(), centre=np.zeros(3), graph=graph)
    assert heat_guarantee.restored(graph, forest, structure, 0.88, context) is not None
    assert heat_guarantee.restored(graph, forest, structure, 0.88, context, scaling="linear") is None
    assert heat_guarantee.restored(graph, forest, structure, 0.8866, context, scaling="linear") is not None
    # kept for 0.88 without a word: the confirming sample gives 0.9020, the two samples rank each other at 0.9948,
    # so the estimate is 0.9020 / sqrt(0.9948) = 0.9044, over 0.88
    assert not context.warnings


def test_a_sampled_heat_map_that_meets_its_target_is_confirmed_by_another_sample(monkeypatch):
    graph = corridor()
    forest = root_forest(graph, {i: -i for i in graph}, centre=np.zeros(3))
    monkeypatch.setattr(traffic, "EXACT_NODES", 1)  # the corridor's nine nodes are above it: samples decide
    # one source, drawn by area (all 1 m²): seed 0 draws polygon 5, the confirming seed 1 polygon 4; its walkers to
    # the other eight polygons weigh 9 (all the weight over one source) at each polygon between
    shown = traffic.walking_flow(graph, max_sources=1)
    other = traffic.walking_flow(graph, max_sources=1, seed=heat_guarantee.CONFIRMING_SEED)
    exact = traffic.walking_flow(graph)  # 2 i (8 - i): every source
    assert shown.tolist() == [0, 9, 18, 27, 36, 0, 18, 9, 0]
    assert other.tolist() == [0, 9, 18, 27, 0, 27, 18, 9, 0]
    # every node kept: the heat map is the sample's own percentiles, which that sample ranks at rho 1 (over 0.7 +
    # the margin), the exact flow at 0.696 (under 0.7) and the other sample at 0.194
    heat = evaluation.placement_heat(graph, forest, shown)
    assert evaluation.spearman(heat, shown) == pytest.approx(1.0)
    assert evaluation.spearman(heat, exact) == pytest.approx(scipy.stats.spearmanr(shown, exact).statistic)
    assert evaluation.spearman(heat, exact) == pytest.approx(0.6957, abs=1e-4)
    assert evaluation.spearman(heat, other) == pytest.approx(scipy.stats.spearmanr(shown, other).statistic)
    assert evaluation.spearman(heat, other) == pytest.approx(0.1938, abs=1e-4)
    context = RunContext(mesh=None, agent=AgentConfig(), centre=np.zeros(3), graph=graph)
    assert heat_guarantee.restored(graph, forest, forest, 0.7, context, sources=1) is None
    (warning,) = context.warnings
    assert "rho 1.000 against the walking flow of the sample of 1 sources" in warning
    # the two samples rank each other at 0.194 too (the heat map is the first's percentiles): corrected for the
    # second's errors, 0.194 / sqrt(0.194) = 0.440, under 0.7
    assert "but 0.194 against another sample of 1, whose own rho with the first is 0.194: about 0.440" in warning
    assert warning.endswith("under min_heat_rho 0.7")
    # a target the estimate meets (0.440), though not the other sample's own figure (0.194): kept without a word
    context = RunContext(mesh=None, agent=AgentConfig(), centre=np.zeros(3), graph=graph)
    assert heat_guarantee.restored(graph, forest, forest, 0.4, context, sources=1) is None and not context.warnings
    # up to the exact size the exact flow decides alone: 0.696 meets 0.6, and the other sample (0.194) is not asked
    monkeypatch.setattr(traffic, "EXACT_NODES", 9)
    assert heat_guarantee.restored(graph, forest, forest, 0.6, context, sources=1) is None and not context.warnings


def test_the_confirming_sample_is_begun_with_the_first_structure_only_above_the_exact_size(monkeypatch):
    graph = corridor()
    forest = root_forest(graph, {i: -i for i in graph}, centre=np.zeros(3))
    context = RunContext(mesh=None, agent=AgentConfig(), centre=np.zeros(3), graph=graph)
    begun = []
    monkeypatch.setattr(traffic, "start_walking_flow", lambda arrays, *args, **kwargs: begun.append((args, kwargs)))
    params = CollapseParams(min_heat_rho=0.7, heat_sources=1, heat_ties="split", heat_scaling="linear")
    heat_guarantee.guaranteed(lambda: None, params, context, forest, None)
    assert not begun  # nine nodes with an area, within the exact size: the exact flow decides, no sample to confirm
    monkeypatch.setattr(traffic, "EXACT_NODES", 1)
    heat_guarantee.guaranteed(lambda: None, params, context, None, None)
    assert not begun  # asked outside the pipeline, for one predicate: no rounds follow
    heat_guarantee.guaranteed(lambda: None, params.model_copy(update={"min_heat_rho": None}), context, forest, None)
    assert not begun  # no guarantee, no confirmation
    heat_guarantee.guaranteed(lambda: None, params, context, forest, None)
    assert begun == [((1,), {"seed": heat_guarantee.CONFIRMING_SEED, "ties": "split", "scaling": "linear"})]
    # a spread heat map's second sample is the independent one of seed 0
    heat_guarantee.guaranteed(lambda: None, params.model_copy(update={"heat_sampling": "spread"}), context, forest, None)
    assert begun[1] == ((1,), {"seed": 0, "ties": "split", "scaling": "linear"})


def test_the_pipeline_begins_the_confirming_sample_once_step_2_has_run(shared_data, monkeypatch):
    # so that it runs beside the one-core Python of steps 3-4 (docs/performance.md, "the confirming walking flow begun beside steps 3-4")
    registry = Registry.from_entry_points()
    mesh = load_mesh(shared_data / "nav_test.obj")[0]
    events: list = []
    start = traffic.start_walking_flow
    monkeypatch.setattr(traffic, "EXACT_NODES", 1)  # nav_test's heat map read as a sample's, and confirmed
    monkeypatch.setattr(traffic, "start_walking_flow", lambda arrays, *args, **kwargs: events.append(
        ("begun", args, kwargs)) or start(arrays, *args, **kwargs))
    raw = load_raw_config(PRESETS_DIR / "map_analysis.yaml")
    raw["simplify"]["params"]["heat_sources"] = 16
    pipeline.run(pipeline.plan(parse_config(raw), registry), registry, mesh, "nav_test", mesh_sha256(mesh),
                 progress=lambda message: events.append(message) if isinstance(message, str) else None)
    steps = [event for event in events if isinstance(event, str) and event.startswith("Step ")]  # not warnings
    confirming = ("begun", (16,), {"seed": heat_guarantee.CONFIRMING_SEED, "ties": "first", "scaling": "none"})
    # first asked after step 2, before step 3 (the first simplification asks again and finds it begun)
    assert events.index(steps[1]) < events.index(confirming) < events.index(steps[2])
    assert steps[1].startswith("Step 2:") and steps[2].startswith("Step 3:")


def test_the_benchmark_reference_is_exact_up_to_the_guarantee_size():
    graph = nx.convert_node_labels_to_integers(nx.grid_2d_graph(30, 20), ordering="sorted")  # 600 > 512 sources
    for i in graph:
        graph.nodes[i].update(pos=(float(i // 20), 0.0, float(i % 20)), area=1.0 + (i % 7) / 7)
    nx.set_edge_attributes(graph, 1.0, "weight")
    result = types.SimpleNamespace(graph=graph)
    arrays = traffic.surface_arrays(graph)
    exact, sampled = traffic.od_flow(arrays.adjacency, arrays.area, ties="split")
    assert sampled is None and np.array_equal(evaluation.reference_flow(result), exact)
    # the reference splits each pair over its tied paths: on this unit grid not the first-path flow
    assert not np.array_equal(exact, traffic.od_flow(arrays.adjacency, arrays.area)[0])


def test_the_guarantee_measures_the_flow_of_its_heat_settings(monkeypatch):
    # heat_sources, heat_ties and heat_scaling (set as the flow analyzer's max_sources, ties and scaling) choose the
    # flow it measures: the heat map's sample and the exact reference, both of those ties (an exact flow is not scaled)
    graph = bumpy_grid()
    forest = nx.DiGraph(nx.bfs_tree(graph, 0))
    structure = forest.subgraph(np.random.default_rng(0).choice(300, size=200, replace=False).tolist())
    context = RunContext(mesh=None, agent=AgentConfig(), centre=np.zeros(3), graph=graph)
    asked, walking = [], traffic.arrays_walking_flow
    monkeypatch.setattr(traffic, "arrays_walking_flow",
                        lambda *args, **kwargs: asked.append((args[1:], kwargs)) or walking(*args, **kwargs))
    params = CollapseParams(min_heat_rho=0.5, heat_sources=64, heat_ties="split", heat_scaling="linear")
    assert heat_guarantee.guaranteed(lambda: None, params, context, forest, structure) is None
    assert asked == [((64,), {"ties": "split", "scaling": "linear", "order": None}),
                     ((64,), {"exact_up_to": traffic.EXACT_NODES, "ties": "split", "scaling": "linear"})]


def test_an_exact_reference_splits_ties_whatever_the_heat_maps_ties_are(monkeypatch):
    # map_analysis's heat map takes the first of tied paths; the exact flow it is ranked against splits them, as the
    # evaluation's reference does: on a unit grid, whose lengths tie, the reading is the rho against the split flow
    graph = nx.convert_node_labels_to_integers(nx.grid_2d_graph(12, 10), ordering="sorted")
    for i in graph:
        graph.nodes[i].update(pos=(float(i // 10), 0.0, float(i % 10)), area=1.0)
    nx.set_edge_attributes(graph, 1.0, "weight")
    structure = list(range(0, 120, 3))
    asked, walking = [], traffic.arrays_walking_flow
    monkeypatch.setattr(traffic, "arrays_walking_flow",
                        lambda *args, **kwargs: asked.append((args[1:], kwargs)) or walking(*args, **kwargs))
    reading = heat_guarantee.heat_reading(graph, structure, 64, "first", "none", "independent")
    assert asked[1] == ((64,), {"exact_up_to": traffic.EXACT_NODES, "ties": "split", "scaling": "none"})
    split = traffic.walking_flow(graph, exact_up_to=traffic.EXACT_NODES, ties="split")
    first = traffic.walking_flow(graph, exact_up_to=traffic.EXACT_NODES, ties="first")
    assert not np.array_equal(split, first) and reading.exact
    assert reading.rho == evaluation.spearman(reading.heat, split) != evaluation.spearman(reading.heat, first)


def test_above_the_guarantee_size_the_benchmark_reference_is_a_linearly_scaled_sample(monkeypatch):
    graph = nx.convert_node_labels_to_integers(nx.grid_2d_graph(30, 20), ordering="sorted")
    for i in graph:
        graph.nodes[i].update(pos=(float(i // 20), 0.0, float(i % 20)), area=1.0 + (i % 7) / 7)
    nx.set_edge_attributes(graph, 1.0, "weight")
    monkeypatch.setattr(traffic, "EXACT_NODES", 100)
    result = types.SimpleNamespace(graph=graph)
    arrays = traffic.surface_arrays(graph)
    reference = evaluation.reference_flow(result, max_sources=64, seed=3)
    linear, _ = traffic.od_flow(arrays.adjacency, arrays.area, 64, 3, ties="split", scaling="linear")
    plain, _ = traffic.od_flow(arrays.adjacency, arrays.area, 64, 3, ties="split")
    assert np.array_equal(reference, linear) and not np.array_equal(reference, plain)
