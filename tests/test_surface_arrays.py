"""surface_arrays: the graph as arrays, and when its cache is read again or rebuilt."""

from __future__ import annotations

import networkx as nx
import numpy as np

from g2s_plugins.surface_arrays import MIN_LENGTH, surface_arrays


def test_arrays_are_the_graphs_lengths_areas_and_rows():
    rng = np.random.default_rng(4)
    graph = nx.gnm_random_graph(60, 150, seed=4)
    nx.relabel_nodes(graph, {n: 1000 - 7 * n for n in graph}, copy=False)  # ids not rows
    for u, v in graph.edges:
        graph.edges[u, v]["weight"] = float(rng.uniform(0.0, 3.0)) if (u + v) % 5 else 0.0
    for n in graph:
        graph.nodes[n]["area"] = float(rng.uniform(0.0, 2.0))
    graph.add_edge(1000, 1000, weight=1.0)  # a self-loop is no edge of the arrays
    arrays = surface_arrays(graph)
    assert arrays.nodes == list(graph) and all(arrays.index[n] == i for i, n in enumerate(graph))
    expected = np.zeros((len(graph), len(graph)))
    for u, v, length in graph.edges(data="weight"):
        if u != v:  # a zero length is kept as the shortest length scipy sees
            expected[arrays.index[u], arrays.index[v]] = expected[arrays.index[v], arrays.index[u]] = max(length, MIN_LENGTH)
    assert np.array_equal(arrays.adjacency.toarray(), expected) and arrays.adjacency.nnz == 2 * 150
    assert arrays.area.tolist() == [graph.nodes[n]["area"] for n in graph]
    assert arrays.rows([979, 1000]).tolist() == [3, 0]
    hops = surface_arrays(graph, weighted=False).adjacency
    assert set(hops.data.tolist()) == {1.0} and hops.nnz == arrays.adjacency.nnz


def test_the_cache_is_rebuilt_when_an_edge_or_node_comes_or_goes():
    graph = nx.path_graph(5)
    arrays = surface_arrays(graph)
    assert surface_arrays(graph) is arrays
    graph.nodes[0]["area"] = 1.0  # attributes are not watched
    assert surface_arrays(graph) is arrays
    for change in (lambda: graph.add_edge(0, 4), lambda: graph.add_edge(2, 2), lambda: graph.remove_edge(2, 2),
                   lambda: graph.add_node(9), lambda: graph.remove_edge(0, 1)):
        change()
        rebuilt = surface_arrays(graph)
        assert rebuilt is not arrays and rebuilt.adjacency.nnz == 2 * sum(u != v for u, v in graph.edges)
        arrays = rebuilt
    multi = nx.MultiGraph([(0, 1)])
    first = surface_arrays(multi)
    multi.add_edge(0, 1)  # a parallel edge leaves the adjacency dicts' sizes as they were
    assert surface_arrays(multi) is not first
