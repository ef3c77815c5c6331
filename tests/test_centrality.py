"""Centrality metrics: hand-checked small cases and cross-checks against networkx."""

from __future__ import annotations

import networkx as nx
import numpy as np
import pytest

from g2s_core.errors import G2SError
from g2s_plugins.terminals.metric import rank_key
from g2s_plugins import centrality, traffic


def assert_close(ours: dict, reference: dict, tol: float = 1e-9) -> None:
    assert list(ours) == list(reference) or set(ours) == set(reference)
    worst = max((abs(ours[n] - reference[n]) for n in reference), default=0.0)
    assert worst <= tol, f"largest difference {worst}"


def random_weights(graph: nx.Graph, seed: int, integer: bool = False) -> nx.Graph:
    rng = np.random.default_rng(seed)
    for u, v in sorted(graph.edges):
        graph.edges[u, v]["weight"] = float(rng.integers(1, 4)) if integer else float(rng.uniform(0.1, 3.0))
    return graph


def random_forest(sizes: list[int], seed: int) -> nx.Graph:
    """Disjoint random labelled trees of the given sizes, ids shuffled across trees."""
    forest = nx.Graph()
    offset = 0
    for i, size in enumerate(sizes):
        tree = nx.random_labeled_tree(size, seed=seed + i) if size > 1 else nx.empty_graph(1)
        forest.update(nx.relabel_nodes(tree, {n: n + offset for n in tree}))
        offset += size
    order = np.random.default_rng(seed).permutation(offset).tolist()
    return nx.relabel_nodes(forest, dict(zip(range(offset), order)))


def mixed_graph(seed: int) -> nx.Graph:
    """A graph with cycles, three components (one a tree) and an isolated node."""
    graph = nx.connected_watts_strogatz_graph(40, 4, 0.3, seed=seed)
    graph.add_edges_from([(100, 101), (101, 102), (102, 100), (102, 103), (103, 104)])
    graph.add_edges_from([(200, 201), (201, 202)])
    graph.add_node(300)
    return graph


# --- tree betweenness ----------------------------------------------------------------


def test_tree_betweenness_path_of_five_by_hand():
    path = nx.path_graph(5)
    # node 2 separates {0,1} from {3,4}: 2*2 pairs; node 1 separates {0} from {2,3,4}: 3 pairs
    assert centrality.tree_betweenness(path, normalized=False) == {0: 0.0, 1: 3.0, 2: 4.0, 3: 3.0, 4: 0.0}
    normalized = centrality.tree_betweenness(path)
    assert normalized[2] == pytest.approx(4 / 6)  # (n-1)(n-2)/2 = 6 pairs of other nodes
    assert normalized[1] == pytest.approx(3 / 6)


def test_tree_betweenness_star_centre_is_on_every_path():
    star = nx.star_graph(5)  # centre 0, leaves 1..5
    raw = centrality.tree_betweenness(star, normalized=False)
    assert raw[0] == 10.0  # C(5, 2)
    assert all(raw[leaf] == 0.0 for leaf in range(1, 6))
    assert centrality.tree_betweenness(star)[0] == pytest.approx(1.0)


def test_tree_betweenness_two_components_normalised_over_whole_forest():
    forest = nx.union(nx.path_graph(3), nx.path_graph(range(10, 14)))
    raw = centrality.tree_betweenness(forest, normalized=False)
    assert raw == {0: 0.0, 1: 1.0, 2: 0.0, 10: 0.0, 11: 2.0, 12: 2.0, 13: 0.0}
    normalized = centrality.tree_betweenness(forest)
    assert normalized[11] == pytest.approx(2.0 / 15.0)  # n = 7: (6 * 5) / 2 pairs
    assert_close(normalized, nx.betweenness_centrality(forest))


@pytest.mark.parametrize("size,seed", [(2, 0), (3, 1), (10, 2), (57, 3), (250, 4)])
def test_tree_betweenness_matches_networkx_on_random_trees(size, seed):
    tree = random_weights(nx.random_labeled_tree(size, seed=seed), seed)
    ours = centrality.tree_betweenness(tree)
    assert_close(ours, nx.betweenness_centrality(tree))
    assert_close(ours, nx.betweenness_centrality(tree, weight="weight"))  # weights cannot change tree paths
    assert_close(centrality.tree_betweenness(tree, normalized=False), nx.betweenness_centrality(tree, normalized=False))


@pytest.mark.parametrize("sizes,seed", [([1, 1, 1], 0), ([5, 1, 30, 2], 1), ([120, 80, 1, 1, 3, 40], 2)])
def test_tree_betweenness_matches_networkx_on_random_forests(sizes, seed):
    forest = random_forest(sizes, seed)
    assert_close(centrality.tree_betweenness(forest), nx.betweenness_centrality(forest))
    assert_close(centrality.tree_betweenness(forest, normalized=False), nx.betweenness_centrality(forest, normalized=False))


def test_tree_betweenness_rejects_a_cycle():
    with pytest.raises(ValueError, match="not a forest"):
        centrality.tree_betweenness(nx.cycle_graph(4))


def test_tree_functions_handle_empty_and_tiny_graphs():
    assert centrality.tree_betweenness(nx.Graph()) == {}
    assert centrality.tree_betweenness(nx.empty_graph(1)) == {0: 0.0}
    assert centrality.tree_betweenness(nx.path_graph(2)) == {0: 0.0, 1: 0.0}
    assert centrality.tree_closeness(nx.path_graph(2)) == {0: 1.0, 1: 1.0}


# --- closeness -------------------------------------------------------------------------


def test_tree_closeness_weighted_path_by_hand():
    path = nx.Graph()
    path.add_edge(0, 1, weight=1.0)
    path.add_edge(1, 2, weight=3.0)
    # node 1: distances 1 and 3 -> 2 / 4; node 0: 1 and 4 -> 2 / 5; node 2: 3 and 4 -> 2 / 7
    assert_close(centrality.tree_closeness(path), {0: 2 / 5, 1: 2 / 4, 2: 2 / 7})
    assert_close(centrality.tree_closeness(path, weighted=False), {0: 2 / 3, 1: 1.0, 2: 2 / 3})


@pytest.mark.parametrize("sizes,seed", [([40], 0), ([200], 1), ([60, 1, 25, 2], 2)])
def test_tree_closeness_matches_networkx(sizes, seed):
    forest = random_weights(random_forest(sizes, seed), seed)
    assert_close(centrality.tree_closeness(forest), nx.closeness_centrality(forest, distance="weight"))
    assert_close(centrality.tree_closeness(forest, weighted=False), nx.closeness_centrality(forest))
    assert_close(centrality.closeness(forest, weighted=True), nx.closeness_centrality(forest, distance="weight"))


@pytest.mark.parametrize("seed", [0, 1])
def test_closeness_on_graphs_matches_networkx(seed):
    graph = random_weights(mixed_graph(seed), seed)
    assert_close(centrality.closeness(graph), nx.closeness_centrality(graph))
    assert_close(centrality.closeness(graph, weighted=True), nx.closeness_centrality(graph, distance="weight"))


# --- graph betweenness -----------------------------------------------------------------


def test_betweenness_cycle_by_hand():
    # in C4 each pair of opposite nodes has two shortest paths, one through each other node
    assert centrality.betweenness(nx.cycle_graph(4), normalized=False) == pytest.approx({0: 0.5, 1: 0.5, 2: 0.5, 3: 0.5})


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_graph_betweenness_matches_networkx(seed):
    graph = random_weights(mixed_graph(seed), seed)
    assert_close(centrality.betweenness(graph), nx.betweenness_centrality(graph))
    assert_close(centrality.betweenness(graph, normalized=False), nx.betweenness_centrality(graph, normalized=False))
    weighted = centrality.betweenness(graph, weighted=True)
    assert_close(weighted, nx.betweenness_centrality(graph, weight="weight"))
    assert_close(centrality.graph_betweenness(graph, weighted=False), nx.betweenness_centrality(graph))


def test_weighted_betweenness_with_equal_length_paths_matches_networkx():
    graph = random_weights(nx.grid_2d_graph(6, 5), 3, integer=True)
    graph = nx.convert_node_labels_to_integers(graph, ordering="sorted")
    assert_close(centrality.betweenness(graph, weighted=True), nx.betweenness_centrality(graph, weight="weight"))


def test_sampled_brandes_within_its_bound_above_the_exact_size(monkeypatch):
    # a looped graph above the exact size: the estimate from sampled sources is within the Hoeffding bound of
    # the exact values (nodes and edges, hops and lengths), the same on every call, and exact below the size
    monkeypatch.setattr(centrality, "BRANDES_EXACT", 300)
    monkeypatch.setattr(centrality, "BRANDES_SOURCES", 128)
    graph = random_weights(nx.connected_watts_strogatz_graph(600, 4, 0.2, seed=5), 5)
    bound = traffic.flow_error_bound(128) * 600 / 599
    for weighted in (False, True):
        estimate = centrality.betweenness(graph, weighted=weighted)
        exact = nx.betweenness_centrality(graph, weight="weight" if weighted else None)
        assert max(abs(estimate[node] - exact[node]) for node in graph) <= bound
        assert estimate != pytest.approx(exact, abs=1e-12)  # sampled, not exact
        assert centrality.betweenness(graph, weighted=weighted) == estimate
    edges = centrality.edge_betweenness(graph)
    exact_edges = nx.edge_betweenness_centrality(graph)
    assert max(abs(edges[edge] - exact_edges[edge]) for edge in graph.edges) <= bound
    small = nx.convert_node_labels_to_integers(nx.cycle_graph(300))
    assert_close(centrality.betweenness(small), nx.betweenness_centrality(small))


def test_weighted_betweenness_networkx_fallback(monkeypatch):
    graph = random_weights(mixed_graph(4), 4)
    graph.edges[100, 101]["weight"] = 0.0  # igraph refuses zero weights: networkx is used
    expected = nx.betweenness_centrality(graph, weight="weight")
    assert_close(centrality.betweenness(graph, weighted=True), expected)
    monkeypatch.setattr(centrality, "_igraph", lambda: None)  # igraph not installed
    graph.edges[100, 101]["weight"] = 1.0
    assert_close(centrality.betweenness(graph, weighted=True), nx.betweenness_centrality(graph, weight="weight"))


def test_weighted_metrics_reject_bad_weights():
    graph = nx.path_graph(4)
    graph.add_edge(3, 0, weight=-1.0)
    with pytest.raises(G2SError, match=r"edge \(.*\) has weight -1.0"):
        centrality.betweenness(graph, weighted=True)
    graph.edges[3, 0]["weight"] = float("nan")
    with pytest.raises(G2SError, match="finite weights"):
        centrality.closeness(graph, weighted=True)


def test_directed_input_is_read_as_undirected():
    digraph = nx.DiGraph([(2, 1), (2, 3), (3, 4)])
    assert_close(centrality.betweenness(digraph), nx.betweenness_centrality(digraph.to_undirected()))


# --- degree, eigenvector, katz -----------------------------------------------------


def test_degree_matches_networkx_and_weighted_sums_lengths():
    graph = random_weights(mixed_graph(5), 5)
    assert_close(centrality.degree(graph), nx.degree_centrality(graph))
    strength = dict(graph.degree(weight="weight"))
    assert_close(centrality.degree(graph, weighted=True, normalized=False), strength)
    assert centrality.degree(nx.star_graph(3), normalized=False) == {0: 3.0, 1: 1.0, 2: 1.0, 3: 1.0}


@pytest.mark.parametrize("graph_factory", [
    lambda: nx.connected_watts_strogatz_graph(50, 4, 0.2, seed=1),   # dense solver
    lambda: nx.connected_watts_strogatz_graph(600, 6, 0.2, seed=2),  # ARPACK
])
def test_eigenvector_matches_networkx_on_connected_graphs(graph_factory):
    graph = random_weights(graph_factory(), 7)
    assert_close(centrality.eigenvector(graph), nx.eigenvector_centrality_numpy(graph), tol=1e-8)
    assert_close(
        centrality.eigenvector(graph, weighted=True), nx.eigenvector_centrality_numpy(graph, weight="weight"), tol=1e-8
    )


def test_eigenvector_is_per_component_unit_norm():
    graph = nx.union(nx.star_graph(3), nx.path_graph(range(10, 13)))
    graph.add_node(20)
    values = centrality.eigenvector(graph)
    star = {n: values[n] for n in range(4)}
    assert_close(star, nx.eigenvector_centrality_numpy(graph.subgraph(range(4))), tol=1e-9)
    path = np.array([values[10], values[11], values[12]])
    assert np.linalg.norm(path) == pytest.approx(1.0)
    assert path == pytest.approx(np.array([0.5, 0.5 * np.sqrt(2), 0.5]))  # Perron vector of P3
    assert values[20] == 1.0


@pytest.mark.parametrize("alpha", [0.05, 0.15])
def test_katz_matches_networkx(alpha):
    graph = mixed_graph(6)
    assert_close(centrality.katz(graph, alpha), nx.katz_centrality_numpy(graph, alpha, weight=None), tol=1e-10)
    weighted = random_weights(graph, 6)
    assert_close(
        centrality.katz(weighted, alpha / 3, weighted=True),
        nx.katz_centrality_numpy(weighted, alpha / 3, weight="weight"),
        tol=1e-10,
    )


def test_katz_path_of_three_by_hand():
    # x = 1 + alpha A x on P3: ends e = 1 + a m, middle m = 1 + 2 a e
    alpha = 0.25
    raw = centrality.katz(nx.path_graph(3), alpha, normalized=False)
    middle = (1 + 2 * alpha) / (1 - 2 * alpha**2)
    assert raw[1] == pytest.approx(middle)
    assert raw[0] == pytest.approx(1 + alpha * middle)


def test_katz_refuses_an_attenuation_that_diverges():
    cycle = nx.cycle_graph(8)  # lambda_max = 2, bound 0.5
    assert centrality.largest_eigenvalue(cycle) == pytest.approx(2.0)
    centrality.katz(cycle, 0.49)
    with pytest.raises(G2SError, match=r"does not converge for attenuation 0.5: it must be below 1/lambda_max = 0.5"):
        centrality.katz(cycle, 0.5)
    big = nx.connected_watts_strogatz_graph(400, 6, 0.1, seed=1)  # eigenvalue by ARPACK
    bound = 1.0 / max(np.linalg.eigvalsh(nx.to_numpy_array(big)))
    centrality.katz(big, bound * 0.99)
    with pytest.raises(G2SError, match="does not converge"):
        centrality.katz(big, bound * 1.01)


def test_compute_dispatches_and_rejects_unknown_metric():
    path = nx.path_graph(5)
    assert centrality.compute(path, "betweenness") == centrality.betweenness(path)
    assert centrality.compute(path, "katz", attenuation=0.2) == centrality.katz(path, 0.2)
    with pytest.raises(ValueError, match="unknown metric"):
        centrality.compute(path, "pagerank")


def test_rank_key_orders_by_value_then_id_and_ignores_float_noise():
    values = {3: 0.5, 1: 0.5 + 1e-16, 2: 0.7, 0: 0.1}
    assert sorted(values, key=lambda n: rank_key(n, values[n])) == [2, 1, 3, 0]
    values[1] = 0.5 - 1e-16
    assert sorted(values, key=lambda n: rank_key(n, values[n])) == [2, 1, 3, 0]


def test_tree_formulas_on_a_deep_path_need_no_recursion():
    n = 20_000  # a recursive traversal would exceed Python's recursion limit
    path = nx.path_graph(n)
    raw = centrality.tree_betweenness(path, normalized=False)
    # node i splits the path into i and n-1-i nodes
    assert all(raw[i] == i * (n - 1 - i) for i in (0, 1, 777, n // 2, n - 2, n - 1))
    close = centrality.tree_closeness(path, weighted=False)
    # total hop distance from i: i(i+1)/2 + (n-1-i)(n-i)/2
    for i in (0, 5000, n - 1):
        assert close[i] == pytest.approx((n - 1) / (i * (i + 1) / 2 + (n - 1 - i) * (n - i) / 2))


def test_betweenness_on_a_graph_with_cycles_is_bitwise_the_same_on_every_run():
    # a grid with chords: many equal-length paths, values summed from many sources
    graph = nx.grid_2d_graph(30, 30)
    graph.add_edges_from(((i, 0), (0, i)) for i in range(1, 30, 3))
    node_runs = [centrality.graph_betweenness(graph, weighted=False) for _ in range(4)]
    edge_runs = [centrality.edge_betweenness(graph) for _ in range(4)]
    assert all(run == node_runs[0] for run in node_runs)
    assert all(run == edge_runs[0] for run in edge_runs)
