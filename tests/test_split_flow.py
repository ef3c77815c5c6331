"""Walking flow that splits each pair's weight over all its shortest paths (``ties: split``)."""

from __future__ import annotations

import itertools
import math

import networkx as nx
import numpy as np
import pytest
import scipy.sparse as sp

from g2s_plugins import traffic
from g2s_plugins.analyzers import flow as flow_analyzer


def lengths(n: int, edges: list[tuple[int, int, float]]) -> sp.csr_array:
    """Symmetric CSR edge lengths of an undirected graph on nodes 0..n-1."""
    u, v, w = (np.array(column) for column in zip(*edges))
    return sp.csr_array((np.concatenate([w, w]), (np.concatenate([u, v]), np.concatenate([v, u]))), shape=(n, n))


VALUES = np.array([1.0, 2.0, 4.0, 8.0, 16.0])


def test_a_square_splits_its_two_tied_paths_in_half():
    # 0 - 1 - 3 and 0 - 2 - 3, unit steps: node 3's value 8 reaches 0 half through 1, half through 2; from 3, node
    # 0's value 1 likewise; the first-path flow gives it all to one
    square = lengths(4, [(0, 1, 1.0), (0, 2, 1.0), (1, 3, 1.0), (2, 3, 1.0)])
    through = traffic.split_path_flow(square, np.array([0, 3]), VALUES[:4])
    assert through.tolist() == [[0.0, 4.0, 4.0, 0.0], [0.0, 0.5, 0.5, 0.0]]
    assert traffic.shortest_path_flow(square, np.array([0]), VALUES[:4])[1].tolist() == [[0.0, 0.0, 8.0, 0.0]]


def test_a_diamond_of_unequal_lengths_does_not_split():
    # 0 - 1 - 3 is 2 m, 0 - 2 - 3 is 2.5 m: all of node 3's value passes 1; a lone node 4 carries nothing
    diamond = lengths(5, [(0, 1, 1.0), (0, 2, 1.5), (1, 3, 1.0), (2, 3, 1.0)])
    assert traffic.split_path_flow(diamond, np.array([0]), VALUES).tolist() == [[0.0, 8.0, 0.0, 0.0, 0.0]]


def test_lengths_equal_but_for_rounding_tie():
    # 0.1 + 0.2 + 0.3 and 0.3 + 0.2 + 0.1 are the same length, 0.6000000000000001 and 0.6 in floats
    assert (0.1 + 0.2) + 0.3 != (0.3 + 0.2) + 0.1
    graph = lengths(6, [(0, 1, 0.1), (1, 2, 0.2), (2, 5, 0.3), (0, 3, 0.3), (3, 4, 0.2), (4, 5, 0.1)])
    through = traffic.split_path_flow(graph, np.array([0]), np.array([0.0, 0.0, 0.0, 0.0, 0.0, 1.0]))
    assert through[0].tolist() == pytest.approx([0.0, 0.5, 0.5, 0.5, 0.5, 0.0])
    # a real difference, one part in a thousand, does not tie
    longer = lengths(6, [(0, 1, 0.1), (1, 2, 0.2), (2, 5, 0.3006), (0, 3, 0.3), (3, 4, 0.2), (4, 5, 0.1)])
    through = traffic.split_path_flow(longer, np.array([0]), np.array([0.0, 0.0, 0.0, 0.0, 0.0, 1.0]))
    assert through[0].tolist() == [0.0, 0.0, 0.0, 1.0, 1.0, 0.0]


def random_graph(seed: int, n: int = 30, m: int = 60) -> nx.Graph:
    """A connected-or-not random graph with integer lengths 1-3 (many equally short paths) and random areas."""
    rng = np.random.default_rng(seed)
    graph = nx.gnm_random_graph(n, m, seed=seed)
    for a, b in graph.edges:
        graph.edges[a, b]["weight"] = float(rng.integers(1, 4))
    for node in graph:
        graph.nodes[node]["area"] = float(rng.uniform(0.5, 5.0))
    return graph


@pytest.mark.parametrize("seed", range(6))
def test_the_split_flow_is_networkx_betweenness_with_unit_weights(seed):
    # with every value 1 the flow through v is the number of ordered pairs' shortest paths through it, each pair's
    # split over its paths: twice networkx's unnormalised betweenness of the undirected graph
    graph = random_graph(seed)
    adjacency = nx.to_scipy_sparse_array(graph, nodelist=range(len(graph)), weight="weight", format="csr")
    flow, sampled = traffic.od_flow(adjacency, np.ones(len(graph)), ties="split")
    betweenness = nx.betweenness_centrality(graph, normalized=False, weight="weight")
    assert sampled is None
    assert flow == pytest.approx([2.0 * betweenness[v] for v in range(len(graph))], rel=1e-12, abs=1e-12)


@pytest.mark.parametrize("seed", range(4))
def test_the_split_flow_counts_every_shortest_path_with_area_weights(seed):
    # brute force: every ordered pair (s, t), every shortest path between them, a_s a_t shared evenly
    graph = random_graph(seed + 10, n=16, m=30)
    area = np.array([graph.nodes[v]["area"] for v in range(len(graph))])
    expected = np.zeros(len(graph))
    for s, t in itertools.permutations(graph, 2):
        if not nx.has_path(graph, s, t):
            continue
        paths = list(nx.all_shortest_paths(graph, s, t, weight="weight"))
        for path in paths:
            for v in path[1:-1]:
                expected[v] += area[s] * area[t] / len(paths)
    adjacency = nx.to_scipy_sparse_array(graph, nodelist=range(len(graph)), weight="weight", format="csr")
    flow, _ = traffic.od_flow(adjacency, area, ties="split")
    assert flow == pytest.approx(expected, rel=1e-12, abs=1e-12)


def test_path_counts_past_a_doubles_range_still_split():
    # 1,100 diamonds in a row: 2^1100 shortest paths from one end to the other, more than a double holds; each
    # middle node of a diamond carries half of everything beyond it
    diamonds = 1100
    edges = []
    for i in range(diamonds):
        a = 3 * i
        edges += [(a, a + 1, 1.0), (a, a + 2, 1.0), (a + 1, a + 3, 1.0), (a + 2, a + 3, 1.0)]
    n = 3 * diamonds + 1
    through = traffic.split_path_flow(lengths(n, edges), np.array([0]), np.ones(n))[0]
    beyond = n - 3 * np.arange(1, diamonds + 1)  # nodes from each diamond's far end on
    assert np.isfinite(through).all()
    assert through[1::3].tolist() == (beyond / 2).tolist() and through[2::3].tolist() == (beyond / 2).tolist()


def test_the_same_bits_on_one_thread_or_two_in_any_source_order(monkeypatch):
    # a grid with diagonals of lengths 1 and sqrt 2, areas over six orders of magnitude
    rng = np.random.default_rng(7)
    width, height = 17, 13
    steps = [(1, 0), (0, 1), (1, 1), (1, -1)]
    edges = [(y * width + x, (y + dy) * width + x + dx, math.hypot(dx, dy))
             for y in range(height) for x in range(width) for dx, dy in steps
             if 0 <= x + dx < width and 0 <= y + dy < height]
    graph = lengths(width * height, edges)
    values = rng.random(width * height) * 10.0 ** rng.uniform(-3, 3, width * height)
    sources = rng.choice(width * height, 40, replace=False)
    through = traffic.split_path_flow(graph, sources, values)
    monkeypatch.setattr(traffic, "THREADS", 1)
    assert np.array_equal(traffic.split_path_flow(graph, sources, values), through)
    assert np.array_equal(traffic.split_path_flow(graph, sources[::-1], values), through[::-1])


def test_bad_input_is_refused():
    square = lengths(4, [(0, 1, 1.0), (0, 2, 1.0), (1, 3, 1.0), (2, 3, 1.0)])
    with pytest.raises(ValueError, match="negative"):
        traffic.split_path_flow(lengths(2, [(0, 1, -1.0)]), np.array([0]), VALUES[:2])
    with pytest.raises(ValueError, match="source"):
        traffic.split_path_flow(square, np.array([4]), VALUES[:4])


def test_walking_flow_caches_each_tie_rule_apart():
    graph = nx.Graph()
    for i, (a, b) in enumerate([(0, 1), (0, 2), (1, 3), (2, 3)]):
        graph.add_edge(a, b, weight=1.0)
    nx.set_node_attributes(graph, 1.0, "area")
    for node in graph:
        graph.nodes[node]["pos"] = (0.0, 0.0, 0.0)
    first = traffic.walking_flow(graph)
    split = traffic.walking_flow(graph, ties="split")
    assert split is not first and split is traffic.walking_flow(graph, ties="split")
    # ordered pairs (0, 3), (3, 0) split over 1 and 2; (1, 2), (2, 1) over 0 and 3: 1 each
    assert split.tolist() == [1.0, 1.0, 1.0, 1.0] and first.sum() == split.sum()


def test_the_flow_analyzer_takes_ties_from_yaml():
    assert flow_analyzer.Params().ties == "first" and flow_analyzer.Params(ties="split").ties == "split"
    with pytest.raises(ValueError):
        flow_analyzer.Params(ties="all")
