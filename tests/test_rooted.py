"""Algorithm 3 (rooted trees) on hand-checkable forests."""

from __future__ import annotations

import networkx as nx
import numpy as np
import pytest

from g2s_core.rooted import root_forest


def path_forest(positions: dict[int, tuple[float, float, float]], edges) -> nx.Graph:
    graph = nx.Graph()
    for node, pos in positions.items():
        graph.add_node(node, pos=pos)
    graph.add_edges_from(edges, weight=1.0)
    return graph


def test_highest_score_is_root_and_depths_follow():
    # path 0-1-2-3-4 with the middle node scoring highest
    graph = path_forest({i: (float(i), 0.0, 0.0) for i in range(5)}, [(0, 1), (1, 2), (2, 3), (3, 4)])
    rooted = root_forest(graph, {0: 0, 1: 3, 2: 4, 3: 3, 4: 0}, centre=np.zeros(3))
    assert rooted.graph["roots"] == [2]
    assert sorted(rooted.edges) == [(1, 0), (2, 1), (2, 3), (3, 4)]
    assert {n: d["depth"] for n, d in rooted.nodes(data=True)} == {0: 2, 1: 1, 2: 0, 3: 1, 4: 2}
    assert all(d["root"] == 2 for _, d in rooted.nodes(data=True))


def test_ties_go_to_the_node_nearest_the_centre_then_lowest_id():
    graph = path_forest({0: (0.0, 0, 0), 1: (1.0, 0, 0), 2: (2.0, 0, 0)}, [(0, 1), (1, 2)])
    equal = {0: 1.0, 1: 1.0, 2: 1.0}
    assert root_forest(graph, equal, centre=np.array([2.2, 0, 0])).graph["roots"] == [2]
    assert root_forest(graph, equal, centre=np.array([1.0, 0, 0])).graph["roots"] == [1]
    # 0 and 2 equally far from the centre: the lower id wins
    tie = {0: 1.0, 1: 0.0, 2: 1.0}
    assert root_forest(graph, tie, centre=np.array([1.0, 0, 0])).graph["roots"] == [0]
    # scores equal but for floating-point noise count as ties
    noisy = {0: 0.3, 1: 0.1 + 0.2, 2: 0.0}
    assert root_forest(graph, noisy, centre=np.array([1.0, 0, 0])).graph["roots"] == [1]


def test_one_tree_per_component_and_isolated_nodes():
    graph = path_forest({i: (float(i), 0, 0) for i in range(6)}, [(0, 1), (1, 2), (3, 4)])
    rooted = root_forest(graph, {i: float(i % 2) for i in range(6)}, centre=np.zeros(3))
    assert rooted.graph["roots"] == [1, 3, 5]
    assert rooted.number_of_edges() == 3
    assert nx.is_forest(rooted.to_undirected())


def test_each_component_is_rooted_at_the_first_of_all_its_nodes_ranked():
    # every node ranked by (rounded score, rounded distance to the centre, id), as the paper's rule reads, against
    # the roots found by measuring only each component's best-scored nodes; scores and positions tie often
    from g2s_core.ties import tie_value

    rng = np.random.default_rng(5)
    for _ in range(200):
        n = int(rng.integers(1, 40))
        ids = rng.choice(1000, size=n, replace=False).tolist()
        positions = {i: tuple(float(v) for v in rng.choice([-1.0, 0.0, 1.0, 0.5], size=3)) for i in ids}
        edges = [(ids[k], ids[int(rng.integers(k))]) for k in range(1, n) if rng.random() < 0.8]
        graph = path_forest(positions, edges)
        scores = {i: float(rng.choice([0.0, 1.0, 0.1 + 0.2, 0.3, -np.inf])) for i in ids}
        centre = rng.choice([-0.5, 0.0, 0.5], size=3)
        ranked = sorted(ids, key=lambda i: (-tie_value(scores[i]), tie_value(np.linalg.norm(np.subtract(positions[i], centre))), i))
        components = sorted((sorted(c) for c in nx.connected_components(graph)), key=lambda c: c[0])
        expected = [min(component, key=ranked.index) for component in components]
        assert root_forest(graph, scores, centre).graph["roots"] == expected


def test_missing_scores_are_an_error():
    graph = path_forest({0: (0, 0, 0), 1: (1, 0, 0)}, [(0, 1)])
    with pytest.raises(ValueError, match="no score"):
        root_forest(graph, {0: 1.0}, centre=np.zeros(3))


def test_deep_tree_does_not_recurse():
    n = 20000
    graph = path_forest({i: (float(i), 0, 0) for i in range(n)}, [(i, i + 1) for i in range(n - 1)])
    rooted = root_forest(graph, {i: -i for i in range(n)}, centre=np.zeros(3))
    assert rooted.nodes[n - 1]["depth"] == n - 1


def test_search_order_loop_edges_and_component_order_follow_the_ids():
    # inserted out of order: component {7, 8, 9} (a triangle) before component {2, 3, 4, 5}
    graph = path_forest({n: (float(n), 0.0, 0.0) for n in (9, 7, 8, 5, 2, 4, 3)},
                        [(9, 7), (8, 9), (7, 8), (5, 2), (2, 4), (4, 3)])
    rooted = root_forest(graph, {9: 1.0, 7: 0.0, 8: 0.0, 5: 0.0, 2: 0.0, 4: 1.0, 3: 0.0}, centre=np.zeros(3))
    # components by smallest id; depth first from each root, neighbours by ascending id
    assert rooted.graph["roots"] == [4, 9]
    assert list(rooted.nodes) == [4, 2, 5, 3, 9, 7, 8]
    assert [(u, v) for u, v, d in rooted.edges(data=True) if not d.get("loop")] == [(4, 2), (4, 3), (2, 5), (9, 7), (7, 8)]
    # the triangle's third edge is a loop edge, from the shallower end
    assert [(u, v) for u, v, d in rooted.edges(data=True) if d.get("loop")] == [(9, 8)]
    assert [rooted.nodes[n]["depth"] for n in rooted] == [0, 1, 2, 1, 0, 1, 2]
    assert [rooted.nodes[n]["root"] for n in rooted] == [4, 4, 4, 4, 9, 9, 9]


def test_components_reads_every_edge_once_and_numbers_components_by_smallest_id():
    from g2s_core.rooted import components

    # inserted out of order, with a lone node 8: rows 2->0, 3->1, 4->2, 5->3, 7->4, 8->5, 9->6
    graph = path_forest({n: (0.0, 0.0, 0.0) for n in (9, 7, 8, 5, 2, 4, 3)}, [(9, 7), (5, 2), (4, 3), (3, 2)])
    lo, hi, count, label = components(graph, np.array([2, 3, 4, 5, 7, 8, 9]))
    assert sorted(zip(lo.tolist(), hi.tolist())) == [(0, 1), (0, 3), (1, 2), (4, 6)]
    assert count == 3
    assert label.tolist() == [0, 0, 0, 0, 1, 2, 1]
