"""RootSelector plugins: scores on small forests, and the roots the pipeline picks from them."""

from __future__ import annotations

import networkx as nx
import numpy as np
import pytest

from g2s_core.config import AgentConfig
from g2s_core.model import RunContext
from g2s_core.rooted import root_forest
from g2s_plugins.roots import betweenness, center, closeness, degree, point


def context(centre=(0.0, 0.0, 0.0)) -> RunContext:
    return RunContext(mesh=None, agent=AgentConfig(), centre=np.asarray(centre, dtype=np.float64))


def forest_on_a_line(edges, lengths=None) -> nx.Graph:
    """Nodes at x = cumulative edge lengths along each path; weight = length."""
    graph = nx.Graph()
    for i, (u, v) in enumerate(edges):
        graph.add_edge(u, v, weight=(lengths[i] if lengths else 1.0))
    for component in nx.connected_components(graph):
        start = min(component)
        for node, distance in nx.single_source_dijkstra_path_length(graph, start).items():
            graph.nodes[node]["pos"] = (float(distance), 0.0, float(start))
    return graph


def scores(module, tree, ctx=None, **params):
    return module.g2s_root_scores(tree=tree, params=module.Params(**params), context=ctx or context())


def roots(module, tree, ctx=None, **params):
    ctx = ctx or context()
    return root_forest(tree, scores(module, tree, ctx, **params), ctx.centre).graph["roots"]


def test_betweenness_scores_and_root_of_a_path_and_a_star():
    path = forest_on_a_line([(0, 1), (1, 2), (2, 3), (3, 4)])
    values = scores(betweenness, path)
    assert values == pytest.approx({0: 0.0, 1: 0.5, 2: 4 / 6, 3: 0.5, 4: 0.0})
    assert roots(betweenness, path) == [2]


def test_betweenness_one_root_per_tree():
    forest = forest_on_a_line([(0, 1), (1, 2), (2, 3), (3, 4), (10, 11), (11, 12)])
    assert roots(betweenness, forest) == [2, 11]


def test_betweenness_ties_go_to_the_node_nearest_the_centre():
    path = forest_on_a_line([(0, 1), (1, 2), (2, 3)])  # 1 and 2 tie; x = 1 and x = 2
    assert roots(betweenness, path, context(centre=(0.0, 0.0, 0.0))) == [1]
    assert roots(betweenness, path, context(centre=(3.0, 0.0, 0.0))) == [2]


def test_closeness_scores_by_length_and_by_hops():
    # 0 -1m- 1 -1m- 2 -10m- 3
    path = forest_on_a_line([(0, 1), (1, 2), (2, 3)], lengths=[1.0, 1.0, 10.0])
    weighted = scores(closeness, path)
    assert weighted == pytest.approx({0: 3 / 15, 1: 3 / 13, 2: 3 / 13, 3: 3 / 33})
    hops = scores(closeness, path, weighted=False)
    assert hops == pytest.approx({0: 3 / 6, 1: 3 / 4, 2: 3 / 4, 3: 3 / 6})
    # on a tree the total distance is smallest at the centroid whatever the lengths;
    # 1 and 2 tie and the one nearer the centre (origin) wins
    assert roots(closeness, path) == [1]
    assert roots(closeness, path, weighted=False) == [1]


def test_closeness_root_of_a_broom_is_its_centroid():
    # 0-1-2-3 with leaves 4, 5, 6 on 3: removing 3 leaves parts of at most 3 of 7 nodes
    broom = forest_on_a_line([(0, 1), (1, 2), (2, 3), (3, 4), (3, 5), (3, 6)], lengths=[5, 5, 5, 1, 1, 1])
    assert roots(closeness, broom) == [3]
    assert roots(betweenness, broom) == [3]


def test_degree_root_is_the_hub():
    star = forest_on_a_line([(0, 5), (5, 1), (5, 2), (2, 3)])
    assert scores(degree, star) == {0: 1.0, 5: 3.0, 1: 1.0, 2: 2.0, 3: 1.0}
    assert roots(degree, star) == [5]
    weighted = forest_on_a_line([(0, 1), (1, 2)], lengths=[1.0, 5.0])
    assert scores(degree, weighted, weighted=True) == {0: 1.0, 1: 6.0, 2: 5.0}


def test_center_scores_are_minus_distances_to_the_centre():
    path = forest_on_a_line([(0, 1), (1, 2), (2, 3)])
    values = scores(center, path, context(centre=(2.0, 0.0, 0.0)))
    assert values == pytest.approx({0: -2.0, 1: -1.0, 2: 0.0, 3: -1.0})
    assert roots(center, path, context(centre=(2.0, 0.0, 0.0))) == [2]


def test_point_scores_are_minus_distances_to_the_point():
    path = forest_on_a_line([(0, 1), (1, 2), (2, 3)])
    values = scores(point, path, point=(3.0, 4.0, 0.0))
    assert values == pytest.approx({0: -5.0, 1: -np.hypot(2, 4), 2: -np.hypot(1, 4), 3: -4.0})
    assert roots(point, path, point=(3.0, 4.0, 0.0)) == [3]
    assert point.Params().point == (0.0, 0.0, 0.0)


def test_register_as_root_selectors_and_run_through_pluggy():
    from g2s_core.registry import Registry

    registry = Registry()
    for module in (betweenness, closeness, degree, center, point):
        info = registry.register(module, package="graph2structure", entry_point=f"roots.{module.NAME}")
        assert (info.stage, info.name) == ("roots", module.NAME)
    path = forest_on_a_line([(0, 1), (1, 2)])
    info = registry.get("roots", "betweenness")
    assert registry.call(info, tree=path, params=betweenness.Params(), context=context()) == {0: 0.0, 1: 1.0, 2: 0.0}
