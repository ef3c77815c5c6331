"""Spread sources (``sampling: spread``): a systematic sample along a Hilbert curve over the nodes in plan, and the
guarantee's pooled reading of a heat map drawn from one."""

from __future__ import annotations

import networkx as nx
import numpy as np
import pytest

from g2s_core.config import AgentConfig, find_config, load_raw_config
from g2s_core.model import RunContext
from g2s_plugins import evaluation, heat_guarantee, traffic
from g2s_plugins._surface import CollapseParams
from g2s_plugins.analyzers import flow as flow_analyzer
from tests.test_heat_guarantee import bumpy_grid  # 300 polygons of 0.5-2 m², 0.8-1.2 m apart


def test_the_curve_visits_the_quadrants_in_order_and_steps_to_a_neighbour():
    corners = np.array([[0.0, 0.0], [0.0, 1.0], [1.0, 1.0], [1.0, 0.0]])
    assert traffic.hilbert_index(corners, 1).tolist() == [0, 1, 2, 3]
    # every cell of an 8 x 8 grid once, and each cell along the curve next to the one before it
    cells = np.array([(x, y) for x in range(8) for y in range(8)], dtype=np.float64)
    index = traffic.hilbert_index(cells, 3)
    assert sorted(index.tolist()) == list(range(64))
    along = cells[np.argsort(index)]
    assert np.all(np.abs(np.diff(along, axis=0)).sum(axis=1) == 1)


def test_the_order_depends_only_on_where_the_nodes_lie_relative_to_each_other():
    points = np.random.default_rng(1).uniform(0, 50, size=(200, 2))
    moved = points * 3.0 + np.array([1e4, -2e3])
    assert np.array_equal(np.argsort(traffic.hilbert_index(points, 16), kind="stable"),
                          np.argsort(traffic.hilbert_index(moved, 16), kind="stable"))


def test_a_spread_sample_draws_each_node_as_often_as_its_area_says_within_one():
    weight = np.random.default_rng(2).uniform(0.5, 2.0, size=300)
    order = np.random.default_rng(3).permutation(300)
    expected = 64 * weight / weight.sum()
    for seed in range(5):
        sources, factor, sampled = traffic.walking_sources(weight, 64, seed, order)
        counts = np.zeros(300)
        counts[sources] = factor / (weight.sum() / 64)
        assert sampled == 64 and counts.sum() == pytest.approx(64)
        assert np.all(counts >= np.floor(expected)) and np.all(counts <= np.ceil(expected))  # independent: not so
    # unbiased: over many starts each node is drawn 64 a / A times on average
    mean = np.zeros(300)
    for seed in range(400):
        sources, factor, _ = traffic.walking_sources(weight, 64, seed, order)
        mean[sources] += factor / (weight.sum() / 64) / 400
    assert mean == pytest.approx(expected, abs=0.06)


def test_spread_sources_give_a_flow_closer_to_the_exact_one_than_as_many_independent_ones():
    graph = bumpy_grid()
    arrays = traffic.surface_arrays(graph)
    exact = traffic.arrays_walking_flow(arrays, ties="split")
    order = traffic.plan_order(graph)
    assert sorted(order.tolist()) == list(range(arrays.n)) and traffic.plan_order(graph) is order  # cached

    def error(sampling_order: np.ndarray | None) -> float:
        return sum(float(np.sum((traffic.od_flow(arrays.adjacency, arrays.area, 32, seed, "split", "linear",
                                                 sampling_order)[0] - exact) ** 2)) for seed in range(4))

    assert error(order) < 0.5 * error(None)
    # a graph with no more weighted nodes than sources is exact whatever the order
    assert np.array_equal(traffic.od_flow(arrays.adjacency, arrays.area, 300, ties="split", order=order)[0], exact)


def test_a_spread_heat_map_is_read_against_the_pool_with_the_independent_sample(monkeypatch):
    graph = bumpy_grid()
    forest = nx.DiGraph(nx.bfs_tree(graph, 0))
    structure = forest.subgraph(np.random.default_rng(0).choice(300, size=200, replace=False).tolist())
    monkeypatch.setattr(traffic, "EXACT_NODES", 256)  # the grid's 300 nodes are above it: samples decide
    context = RunContext(mesh=None, agent=AgentConfig(), centre=np.zeros(3), graph=graph)
    asked, walking = [], traffic.arrays_walking_flow
    monkeypatch.setattr(traffic, "arrays_walking_flow",
                        lambda *args, **kwargs: asked.append((args[1:], kwargs)) or walking(*args, **kwargs))
    params = CollapseParams(min_heat_rho=0.5, heat_sources=64, heat_ties="split", heat_scaling="linear",
                            heat_sampling="spread")
    assert heat_guarantee.guaranteed(lambda: None, params, context, forest, structure) is None
    order = traffic.plan_order(graph)
    # the heat map's spread sample, then the independent sample of seed 0 to pool and confirm with (no exact
    # reference above the exact size, no sample of the confirming seed)
    assert [(args, {k: v for k, v in kwargs.items() if k != "order"}) for args, kwargs in asked] == [
        ((64,), {"ties": "split", "scaling": "linear"}),
        ((64,), {"seed": 0, "ties": "split", "scaling": "linear"}),
        ((64,), {"seed": 0, "ties": "split", "scaling": "linear"}),
    ]
    assert asked[0][1]["order"] is order and "order" not in asked[1][1]


def test_the_pooled_margin_decides_above_the_exact_size(monkeypatch):
    graph = bumpy_grid()
    forest = nx.DiGraph(nx.bfs_tree(graph, 0))
    structure = forest.subgraph(np.random.default_rng(0).choice(300, size=200, replace=False).tolist())
    monkeypatch.setattr(traffic, "EXACT_NODES", 256)
    arrays = traffic.surface_arrays(graph)
    order = traffic.plan_order(graph)
    shown = traffic.arrays_walking_flow(arrays, 256, ties="split", scaling="linear", order=order)
    other = traffic.arrays_walking_flow(arrays, 256, ties="split", scaling="linear")
    rho = evaluation.spearman(evaluation.placement_heat(graph, structure, shown), (shown + other) / 2)
    margin = heat_guarantee.POOLED_MARGINS["linear"]
    context = RunContext(mesh=None, agent=AgentConfig(), centre=np.zeros(3), graph=graph)
    below, above = rho - margin - 1e-4, rho - margin + 1e-4
    assert heat_guarantee.restored(graph, forest, structure, below, context, 256, "split", "linear", "spread") is None
    assert heat_guarantee.restored(graph, forest, structure, above, context, 256, "split", "linear", "spread") is not None


def test_the_settings_that_choose_it():
    # independent by default; the sampling preset spreads the analyzer's and the guarantee's sample alike
    assert traffic.WALKING_SAMPLING == "independent"
    assert flow_analyzer.Params().sampling == CollapseParams().heat_sampling == "independent"
    raw = load_raw_config(find_config("map_analysis_sampling"))
    (analyzer,) = (a for a in raw["analyzers"] if a["plugin"] == "flow")
    assert analyzer["params"]["sampling"] == raw["simplify"]["params"]["heat_sampling"] == "spread"
    # a spread heat map's pooled margin is measured for linear scaling alone
    with pytest.raises(ValueError, match="heat_scaling linear"):
        CollapseParams(min_heat_rho=0.9, heat_sampling="spread")
    assert CollapseParams(heat_sampling="spread").heat_scaling == "none"  # no guarantee, no margin asked
