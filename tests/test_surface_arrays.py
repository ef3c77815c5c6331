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


def test_a_graph_read_from_its_adjacency_gives_the_arrays_of_its_edge_view():
    """A plain graph is read from its adjacency dicts, a view through its edge view: the same matrix, entry for
    entry (a missing weight 1.0, a zero one MIN_LENGTH, a self-loop none), rows and areas."""
    graph = nx.Graph()
    graph.add_edge((2, "b"), (0, "a"), weight=2.5)
    graph.add_edge((0, "a"), (1, "c"))  # no weight: 1.0
    graph.add_edge((1, "c"), (2, "b"), weight=0.0)
    graph.add_edge((1, "c"), (1, "c"), weight=4.0)
    graph.add_node((3, "d"), area=2)
    plain, view = surface_arrays(graph), surface_arrays(graph.subgraph(list(graph)))
    assert plain.nodes == view.nodes == list(graph) and plain.index == view.index
    for name in ("indptr", "indices", "data"):
        assert np.array_equal(getattr(plain.adjacency, name), getattr(view.adjacency, name))
    # rows (2, "b"), (0, "a"), (1, "c"), (3, "d"): the order the nodes came in
    assert plain.adjacency.toarray().tolist() == [[0, 2.5, MIN_LENGTH, 0], [2.5, 0, 1.0, 0], [MIN_LENGTH, 1.0, 0, 0],
                                                  [0, 0, 0, 0]]
    assert plain.area.tolist() == view.area.tolist() == [0.0, 0.0, 0.0, 2.0]
