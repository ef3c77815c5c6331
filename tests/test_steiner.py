"""Tests of the SteinerSolver plugins ``kou`` and ``mehlhorn`` and their shared helpers."""

from __future__ import annotations

import itertools
import random

import networkx as nx
import numpy as np
import pytest
from networkx.algorithms.approximation import steiner_tree as nx_steiner_tree

from g2s_plugins import _trees
from g2s_plugins.steiner import _paths, kou, mehlhorn
from g2s_plugins.steiner.kou import kou_steiner_tree
from g2s_plugins.steiner.mehlhorn import mehlhorn_steiner_tree

SOLVERS = {"kou": kou_steiner_tree, "mehlhorn": mehlhorn_steiner_tree}
solvers = pytest.mark.parametrize("method", sorted(SOLVERS))


def weighted(edges) -> nx.Graph:
    graph = nx.Graph()
    graph.add_weighted_edges_from(edges)
    return graph


def edge_list(tree: nx.Graph) -> list[tuple[int, int, float]]:
    return sorted((min(u, v), max(u, v), w) for u, v, w in tree.edges(data="weight"))


def edge_set(tree: nx.Graph) -> set[tuple[int, int]]:
    return {(min(u, v), max(u, v)) for u, v in tree.edges}


def tree_weight(tree: nx.Graph) -> float:
    return sum(w for _, _, w in tree.edges(data="weight"))


def assert_valid_steiner_tree(tree: nx.Graph, graph: nx.Graph, terminals) -> None:
    """A tree holding every terminal, made of graph edges with their weights, no non-terminal leaf."""
    assert nx.is_tree(tree)
    assert set(terminals) <= set(tree.nodes)
    for u, v, w in tree.edges(data="weight"):
        assert graph.has_edge(u, v)
        assert w == graph.edges[u, v]["weight"]
    leaves = {n for n in tree if tree.degree(n) == 1}
    assert leaves <= set(terminals)


def random_connected_graph(rng: random.Random, n: int, extra: int) -> nx.Graph:
    """A random spanning tree plus ``extra`` random chords, weights uniform in [1, 10)."""
    graph = nx.Graph()
    graph.add_nodes_from(range(n))
    order = list(range(n))
    rng.shuffle(order)
    for i in range(1, n):
        graph.add_edge(order[i], order[rng.randrange(i)])
    pairs = [p for p in itertools.combinations(range(n), 2) if not graph.has_edge(*p)]
    for u, v in rng.sample(pairs, min(extra, len(pairs))):
        graph.add_edge(u, v)
    for u, v in graph.edges:
        graph.edges[u, v]["weight"] = rng.uniform(1.0, 10.0)
    return graph


def optimal_steiner_tree(graph: nx.Graph, terminals) -> nx.Graph:
    """The exact optimum by brute force: over all sets of Steiner nodes, the lightest MST
    of the subgraph induced by terminals + that set, when it is connected."""
    others = sorted(set(graph) - set(terminals))
    best, best_weight = None, float("inf")
    for size in range(len(others) + 1):
        for extra in itertools.combinations(others, size):
            induced = graph.subgraph([*terminals, *extra])
            if not nx.is_connected(induced):
                continue
            mst = nx.minimum_spanning_tree(induced)
            weight = mst.size(weight="weight")
            if weight < best_weight:
                best, best_weight = mst, weight
    return best


def random_cases(seed: int, count: int):
    rng = random.Random(seed)
    for _ in range(count):
        n = rng.randint(6, 10)
        graph = random_connected_graph(rng, n, extra=rng.randint(1, n))
        terminals = sorted(rng.sample(range(n), rng.randint(3, 5)))
        yield graph, terminals


def grid(width: int, height: int, rng: random.Random | None = None) -> nx.Graph:
    graph = nx.convert_node_labels_to_integers(nx.grid_2d_graph(width, height), ordering="sorted")
    for u, v in graph.edges:
        graph.edges[u, v]["weight"] = 1.0 if rng is None else rng.uniform(0.5, 1.5)
    return graph


# --- hand-computed trees -----------------------------------------------------------------------


@solvers
def test_star_steiner_point_is_the_centre(method):
    # Terminals 1, 2, 3 pairwise joined by 2.5, each 1 from the centre 0: the optimum
    # uses the Steiner point 0 (weight 3), while the MST of the terminals alone weighs 5.
    graph = weighted([(0, 1, 1.0), (0, 2, 1.0), (0, 3, 1.0), (1, 2, 2.5), (2, 3, 2.5), (1, 3, 2.5)])
    tree = SOLVERS[method](graph, [1, 2, 3])
    assert edge_list(tree) == [(0, 1, 1.0), (0, 2, 1.0), (0, 3, 1.0)]
    terminal_only_mst = nx.minimum_spanning_tree(graph.subgraph([1, 2, 3]))
    assert terminal_only_mst.size(weight="weight") == 5.0


@solvers
def test_star_with_cheap_chords_keeps_the_chords_ties_by_smallest_ends(method):
    # Chords of 1.9 are shorter than the 2.0 through the centre, so G1's MST uses two chords
    # (the approximation, 3.8 against the optimum 3). All three chords tie: the documented
    # order (weight, smaller end, larger end) picks (1, 2) then (1, 3).
    graph = weighted([(0, 1, 1.0), (0, 2, 1.0), (0, 3, 1.0), (1, 2, 1.9), (2, 3, 1.9), (1, 3, 1.9)])
    tree = SOLVERS[method](graph, [3, 1, 2])
    assert edge_list(tree) == [(1, 2, 1.9), (1, 3, 1.9)]


@solvers
def test_path_inner_terminals(method):
    graph = weighted([(0, 1, 1.0), (1, 2, 2.0), (2, 3, 3.0), (3, 4, 4.0)])
    assert edge_list(SOLVERS[method](graph, [1, 3])) == [(1, 2, 2.0), (2, 3, 3.0)]
    assert edge_list(SOLVERS[method](graph, [4, 0])) == [(0, 1, 1.0), (1, 2, 2.0), (2, 3, 3.0), (3, 4, 4.0)]
    assert edge_list(SOLVERS[method](graph, [2, 1])) == [(1, 2, 2.0)]


@solvers
def test_square_with_diagonal(method):
    # Unit square 0-1-2-3-0 with diagonal 0-2 of 1.2.
    graph = weighted([(0, 1, 1.0), (1, 2, 1.0), (2, 3, 1.0), (3, 0, 1.0), (0, 2, 1.2)])
    assert edge_list(SOLVERS[method](graph, [0, 2])) == [(0, 2, 1.2)]
    assert edge_list(SOLVERS[method](graph, [0, 1, 2])) == [(0, 1, 1.0), (1, 2, 1.0)]
    # All four corners: three sides (the diagonal would cost more than a side).
    tree = SOLVERS[method](graph, [0, 1, 2, 3])
    assert tree_weight(tree) == 3.0 and (0, 2) not in edge_set(tree)


@solvers
def test_zero_weight_edges_are_edges(method):
    # scipy's minimum_spanning_tree drops explicit zeros; the solvers must not lose them.
    graph = weighted([(0, 1, 0.0), (1, 2, 1.0), (2, 3, 0.0), (0, 3, 5.0)])
    assert edge_list(SOLVERS[method](graph, [0, 3])) == [(0, 1, 0.0), (1, 2, 1.0), (2, 3, 0.0)]
    assert edge_list(SOLVERS[method](graph, [0, 1])) == [(0, 1, 0.0)]


@solvers
def test_large_sparse_node_ids(method):
    graph = weighted([(10**12, 7, 1.0), (7, 3 * 10**12, 1.0), (3 * 10**12, 10**12, 3.0)])
    assert edge_list(SOLVERS[method](graph, [10**12, 3 * 10**12])) == [(7, 10**12, 1.0), (7, 3 * 10**12, 1.0)]


# --- approximation bound against the exact optimum -----------------------------------------------


@pytest.mark.parametrize("case", range(30))
def test_within_bound_of_exact_optimum(case):
    graph, terminals = list(random_cases(seed=1981, count=30))[case]
    optimum = optimal_steiner_tree(graph, terminals)
    opt_weight = optimum.size(weight="weight")
    leaves = sum(1 for n in optimum if optimum.degree(n) == 1)
    bound = 2.0 * (1.0 - 1.0 / leaves) * opt_weight
    for method, solve in SOLVERS.items():
        tree = solve(graph, terminals)
        assert_valid_steiner_tree(tree, graph, terminals)
        weight = tree_weight(tree)
        assert opt_weight - 1e-9 <= weight <= bound + 1e-9, (method, weight, opt_weight, bound)


def test_bound_check_is_not_vacuous():
    # On these graphs the approximation is sometimes strictly worse than the optimum,
    # and the brute force finds Steiner points: the bound test above does exercise something.
    strictly_worse = uses_steiner_points = 0
    for graph, terminals in random_cases(seed=1981, count=30):
        optimum = optimal_steiner_tree(graph, terminals)
        uses_steiner_points += len(optimum) > len(terminals)
        strictly_worse += tree_weight(kou_steiner_tree(graph, terminals)) > optimum.size(weight="weight") + 1e-9
    assert uses_steiner_points > 0
    assert strictly_worse > 0


# --- against networkx's implementations of the same algorithms -----------------------------------


@solvers
def test_no_heavier_than_networkx(method):
    # Random real weights make shortest paths and spanning trees unique, so both
    # implementations follow the same algorithm on the same choices; ours adds the
    # final MST and leaf pruning, so it may only be lighter.
    rng = random.Random(88)
    for _ in range(40):
        n = rng.randint(8, 40)
        graph = random_connected_graph(rng, n, extra=rng.randint(n // 2, 2 * n))
        terminals = sorted(rng.sample(range(n), rng.randint(2, max(2, n // 3))))
        ours = SOLVERS[method](graph, terminals)
        theirs = nx_steiner_tree(graph, terminals, weight="weight", method=method)
        assert_valid_steiner_tree(ours, graph, terminals)
        assert tree_weight(ours) <= theirs.size(weight="weight") + 1e-9


# --- determinism -------------------------------------------------------------------------------


def shuffled_copy(graph: nx.Graph, rng: random.Random) -> nx.Graph:
    nodes = list(graph.nodes)
    edges = [(u, v, w) if rng.random() < 0.5 else (v, u, w) for u, v, w in graph.edges(data="weight")]
    rng.shuffle(nodes)
    rng.shuffle(edges)
    copy = nx.Graph()
    copy.add_nodes_from(nodes)
    copy.add_weighted_edges_from(edges)
    return copy


@solvers
@pytest.mark.parametrize("equal_weights", [False, True])
def test_same_input_same_tree(method, equal_weights):
    rng = random.Random(5)
    graph = grid(24, 20, None if equal_weights else rng)
    terminals = sorted(rng.sample(list(graph.nodes), 60))
    first = edge_list(SOLVERS[method](graph, terminals))
    assert first == edge_list(SOLVERS[method](graph, terminals))
    # The tree depends on the graph's content, not on the order nodes and edges were added.
    assert first == edge_list(SOLVERS[method](shuffled_copy(graph, rng), terminals))
    assert_valid_steiner_tree(SOLVERS[method](graph, terminals), graph, terminals)


@solvers
def test_terminal_order_does_not_matter(method):
    rng = random.Random(11)
    graph = grid(15, 15)  # all weights equal: ties everywhere
    terminals = rng.sample(list(graph.nodes), 25)
    expected = edge_list(SOLVERS[method](graph, sorted(terminals)))
    for _ in range(5):
        rng.shuffle(terminals)
        assert edge_list(SOLVERS[method](graph, terminals)) == expected
    assert edge_list(SOLVERS[method](graph, terminals + terminals[:7])) == expected


def test_kou_in_blocks_equals_kou_at_once(monkeypatch):
    rng = random.Random(3)
    for weights in (rng, None):
        graph = grid(20, 20, weights)
        terminals = rng.sample(list(graph.nodes), 40)
        at_once = edge_list(kou_steiner_tree(graph, terminals))
        monkeypatch.setattr(kou, "DISTANCE_BUDGET", 7 * graph.number_of_nodes())  # blocks of 7 terminals
        assert edge_list(kou_steiner_tree(graph, terminals)) == at_once
        monkeypatch.undo()


def test_medium_grid_both_solvers_valid_and_close():
    rng = random.Random(21)
    graph = grid(40, 40, rng)
    terminals = rng.sample(list(graph.nodes), 400)
    trees = {m: SOLVERS[m](graph, terminals) for m in SOLVERS}
    for tree in trees.values():
        assert_valid_steiner_tree(tree, graph, terminals)
    # Both are minimum spanning trees of the same distance graph, expanded: equal weight here.
    assert tree_weight(trees["kou"]) == pytest.approx(tree_weight(trees["mehlhorn"]), rel=1e-12)


# --- inputs at the edges of the contract --------------------------------------------------------


@solvers
def test_single_and_duplicate_terminals(method):
    graph = weighted([(0, 1, 1.0), (1, 2, 1.0)])
    tree = SOLVERS[method](graph, [2, 2])
    assert list(tree.nodes) == [2] and tree.number_of_edges() == 0


@solvers
def test_bad_inputs_raise(method):
    graph = weighted([(0, 1, 1.0), (1, 2, 1.0), (5, 6, 1.0)])
    solve = SOLVERS[method]
    with pytest.raises(ValueError, match="not in the graph"):
        solve(graph, [0, 9])
    with pytest.raises(ValueError, match="not all connected"):
        solve(graph, [0, 5])
    with pytest.raises(ValueError, match="no terminals"):
        solve(graph, [])
    with pytest.raises(ValueError, match="negative"):
        solve(weighted([(0, 1, -1.0), (1, 2, 1.0)]), [0, 2])
    with pytest.raises(ValueError, match="finite"):
        solve(weighted([(0, 1, float("nan")), (1, 2, 1.0)]), [0, 2])
    with pytest.raises(TypeError, match="integer node ids"):
        solve(nx.path_graph(["a", "b", "c"]), ["a", "c"])
    with pytest.raises(TypeError, match="undirected"):
        solve(nx.DiGraph([(0, 1)]), [0, 1])


@solvers
def test_unreached_components_without_terminals_are_ignored(method):
    graph = weighted([(0, 1, 1.0), (1, 2, 1.0), (5, 6, 1.0)])
    assert edge_list(SOLVERS[method](graph, [0, 2])) == [(0, 1, 1.0), (1, 2, 1.0)]


# --- helpers ----------------------------------------------------------------------------------


def test_graph_to_csr_is_canonical_and_symmetric():
    graph = nx.MultiGraph()
    graph.add_edge(30, 10, weight=4.0)
    graph.add_edge(10, 30, weight=2.5)  # parallel: the lighter one counts
    graph.add_edge(20, 20, weight=1.0)  # self-loop: dropped
    graph.add_edge(20, 30)  # no weight: 1
    csr = _paths.graph_to_csr(graph)
    assert csr.nodes.tolist() == [10, 20, 30]
    dense = csr.matrix.toarray()
    assert np.array_equal(dense, dense.T)
    assert dense.tolist() == [[0.0, 0.0, 2.5], [0.0, 0.0, 1.0], [2.5, 1.0, 0.0]]
    assert (csr.lo.tolist(), csr.hi.tolist(), csr.weight.tolist()) == ([0, 1], [2, 2], [2.5, 1.0])
    assert csr.edge_weights(np.array([2, 1]), np.array([0, 2])).tolist() == [2.5, 1.0]
    # A multigraph tree uses the lighter parallel edge.
    assert edge_list(mehlhorn_steiner_tree(graph, [10, 30])) == [(10, 30, 2.5)]


def test_distinct_gives_the_sorted_distinct_values():
    assert _paths.distinct(np.array([5, 3, 5, 1, 3], dtype=np.int64)).tolist() == [1, 3, 5]
    assert _paths.distinct(np.empty(0, dtype=np.int64)).tolist() == []


def test_the_csr_of_a_graph_read_from_its_surface_arrays_when_they_fit():
    from g2s_plugins.surface_arrays import surface_arrays

    graph = nx.Graph()
    graph.add_edge(10, 30, weight=2.5)
    graph.add_edge(20, 30)  # no weight: 1
    graph.add_edge(10, 20, weight=4.0)
    # ids inserted out of order (10, 30, 20): rows are not the sorted ids, so not read from the arrays
    assert _paths.from_surface_arrays(surface_arrays(graph)) is None
    ordered = nx.Graph()
    ordered.add_nodes_from([10, 20, 30])
    ordered.add_edges_from(graph.edges(data=True))
    csr = _paths.from_surface_arrays(surface_arrays(ordered))
    assert csr.matrix.toarray().tolist() == [[0.0, 4.0, 2.5], [4.0, 0.0, 1.0], [2.5, 1.0, 0.0]]
    assert (csr.nodes.tolist(), csr.lo.tolist(), csr.hi.tolist(), csr.weight.tolist()) == ([10, 20, 30], [0, 0, 1], [1, 2, 2], [4.0, 2.5, 1.0])
    # a zero weight (stored as MIN_LENGTH by the arrays) is kept as it is by the graph's own reading
    ordered.add_edge(30, 40, weight=0.0)
    assert _paths.from_surface_arrays(surface_arrays(ordered)) is None
    assert _paths.graph_to_csr(ordered).weight.tolist() == [4.0, 2.5, 1.0, 0.0]


def test_spanning_tree_breaks_ties_by_ends_and_keeps_zeros():
    # A 4-cycle of equal weights: the order (w, lo, hi) drops the largest pair (2, 3).
    a = np.array([2, 0, 1, 3])
    b = np.array([3, 1, 2, 0])
    chosen = _paths.spanning_tree(4, a, b, np.ones(4))
    assert sorted(zip(np.minimum(a, b)[chosen].tolist(), np.maximum(a, b)[chosen].tolist())) == [(0, 1), (0, 3), (1, 2)]
    # Zero weights are kept, and (0, 1) < (0, 2) < (1, 2) among equals.
    chosen = _paths.spanning_tree(3, np.array([0, 1, 0]), np.array([1, 2, 2]), np.array([0.0, 0.0, 0.0]))
    assert chosen.tolist() == [0, 2]


def test_spanning_forest_takes_the_lightest_first_of_parallel_edges_and_no_self_loop():
    """Edges 0: (0, 1), 1: (1, 2), 2: (0, 2), all 1; 3: (2, 3) 5; 4: (3, 2) 2; 5: (3, 3) 0; 6: (2, 3) 2; 7: (4, 5) 3.
    Kruskal in the order (w, lo, hi, i): 5 is a self-loop; 0 and 2 join 0, 1, 2 ((0, 1) < (0, 2) < (1, 2)), 1 closes
    a cycle; 4 and 6 tie with the same ends, 4 comes first; 7 is a tree of its own; 3 joins nothing new."""
    a = np.array([0, 1, 0, 2, 3, 3, 2, 4])
    b = np.array([1, 2, 2, 3, 2, 3, 3, 5])
    w = np.array([1.0, 1.0, 1.0, 5.0, 2.0, 0.0, 2.0, 3.0])
    assert _trees.spanning_forest(6, a, b, w).tolist() == [0, 2, 4, 7]
    with pytest.raises(ValueError, match="NaN"):
        _trees.spanning_forest(6, a, b, np.where(w == 5.0, np.nan, w))


def test_dense_spanning_tree_matches_sparse_one():
    rng = np.random.default_rng(2)
    for integer_weights in (False, True):
        k = 30
        w = rng.integers(1, 4, (k, k)).astype(float) if integer_weights else rng.random((k, k))
        w = np.triu(w, 1) + np.triu(w, 1).T
        a, b = _paths.dense_spanning_tree(w)
        ia, ib = np.triu_indices(k, 1)
        chosen = _paths.spanning_tree(k, ia, ib, w[ia, ib])
        assert list(zip(a.tolist(), b.tolist())) == sorted(zip(ia[chosen].tolist(), ib[chosen].tolist()))


def test_prune_nonterminal_leaves():
    # Terminals 0 and 3 on the path 0-1-2-3; a dead-end chain 2-4-5 and a branch 1-6.
    u = np.array([0, 1, 2, 2, 4, 1])
    v = np.array([1, 2, 3, 4, 5, 6])
    terminal = np.zeros(7, dtype=bool)
    terminal[[0, 3]] = True
    assert _paths.prune_nonterminal_leaves(u, v, terminal).tolist() == [True, True, True, False, False, False]
    terminal[5] = True
    assert _paths.prune_nonterminal_leaves(u, v, terminal).tolist() == [True, True, True, True, True, False]


def test_finish_tree_takes_the_mst_then_prunes_dead_ends():
    # Steps 4 and 5 on a union of paths with a cycle 0-1-2-3-0 and a tail 3-4, terminals 0, 2:
    # the MST drops the heavy 3-0, which leaves the dead end 2-3-4; pruning removes it.
    graph = weighted([(0, 1, 1.0), (1, 2, 1.0), (2, 3, 1.0), (3, 0, 2.5), (3, 4, 1.0)])
    csr = _paths.graph_to_csr(graph)
    lo, hi = _paths.unique_edges(csr.lo, csr.hi)
    tree = _paths.finish_tree(csr, lo, hi, csr.indices_of([0, 2]))
    assert edge_list(tree) == [(0, 1, 1.0), (1, 2, 1.0)]
    # Same union, terminals 0 and 4: nothing to prune, the MST alone decides.
    tree = _paths.finish_tree(csr, lo, hi, csr.indices_of([0, 4]))
    assert edge_list(tree) == [(0, 1, 1.0), (1, 2, 1.0), (2, 3, 1.0), (3, 4, 1.0)]


def test_walk_to_sources_forest_and_rows():
    # Forest 0 <- 1 <- 2 <- 3 and 5 <- 4 (5 is a source); 2-D rows pick a predecessor row each.
    none = _paths.NO_PREDECESSOR
    forest = np.array([none, 0, 1, 2, 5, none])
    child, parent = _paths.walk_to_sources(forest, np.array([3, 2, 4]))
    assert sorted(zip(child.tolist(), parent.tolist())) == [(1, 0), (2, 1), (3, 2), (4, 5)]
    rows = np.array([[none, 0, 1], [1, none, 1]])
    child, parent = _paths.walk_to_sources(rows, np.array([2, 0]), rows=np.array([0, 1]))
    assert sorted(zip(child.tolist(), parent.tolist())) == [(0, 1), (1, 0), (2, 1)]


# --- plugin contract ----------------------------------------------------------------------------


@pytest.mark.parametrize("module", [kou, mehlhorn], ids=["kou", "mehlhorn"])
def test_plugin_module_through_registry_and_pipeline(module):
    from g2s_core.model import RunContext
    from g2s_core.pipeline import steiner_forest
    from g2s_core.registry import Registry

    registry = Registry()
    info = registry.register(module, package="graph2structure", entry_point=f"steiner.{module.NAME}")
    assert (info.stage, info.name) == ("steiner", module.NAME)
    params = registry.validate_params(info, {}, key="steiner.params")
    with pytest.raises(Exception):
        registry.validate_params(info, {"unknown": 1}, key="steiner.params")

    graph = weighted([(0, 1, 1.0), (0, 2, 1.0), (0, 3, 1.0), (1, 2, 2.5), (2, 3, 2.5), (1, 3, 2.5), (7, 8, 1.0)])
    context = RunContext(mesh=None, agent=None, centre=np.zeros(3))
    forest = steiner_forest(
        graph, [3, 1, 2, 8], lambda sub, terms: registry.call(info, graph=sub, terminals=terms, params=params, context=context), context
    )
    assert edge_set(forest) == {(0, 1), (0, 2), (0, 3)}
    assert 8 in forest and forest.degree(8) == 0


def test_the_disconnected_areas_warning_counts_the_terminals_without_the_waypoints():
    """Terminals 1 and 8 and the coverage waypoints 2 and 7 in two components: the forest joins all four, the warning
    counts the terminals and the waypoints apart, as the outputs do (it said "854 terminals" of 39 terminals and 815
    waypoints on a generated level); without terminals, the waypoints alone."""
    from g2s_core.model import RunContext
    from g2s_core.pipeline import steiner_forest

    graph = weighted([(0, 1, 1.0), (0, 2, 1.0), (7, 8, 1.0), (8, 9, 1.0)])
    context = RunContext(mesh=None, agent=None, centre=np.zeros(3))
    forest = steiner_forest(graph, [1, 2, 7, 8], lambda sub, terms: mehlhorn.mehlhorn_steiner_tree(sub, terms), context,
                            waypoints=[2, 7])
    assert edge_set(forest) == {(0, 1), (0, 2), (7, 8)}
    steiner_forest(graph, [2, 7], lambda sub, terms: mehlhorn.mehlhorn_steiner_tree(sub, terms), context, waypoints=[2, 7])
    assert context.warnings == [f"{joined} lie in 2 disconnected areas, so they are joined by one tree per area (the "
                                f"largest have 3, 3 nodes)." for joined in ("2 terminals and 2 waypoints", "2 waypoints")]


def test_the_steiner_forest_shares_the_graphs_attribute_dicts():
    """The forest's nodes and edges hold the graph's own attribute dicts, in the graph's key order, as a subgraph
    view would; one lone terminal of another component as well."""
    from g2s_core.model import RunContext
    from g2s_core.pipeline import steiner_forest

    graph = weighted([(0, 1, 1.0), (0, 2, 1.0), (1, 2, 2.5), (7, 8, 1.0)])
    for node in graph:
        graph.nodes[node].update(pos=(float(node), 0.0, 0.0), area=1.0 + node)
    graph.edges[0, 1]["portal"] = 3
    context = RunContext(mesh=None, agent=None, centre=np.zeros(3))
    forest = steiner_forest(graph, [1, 2, 8], lambda sub, terms: mehlhorn.mehlhorn_steiner_tree(sub, terms), context)
    assert list(forest) == [0, 1, 2, 8] and edge_set(forest) == {(0, 1), (0, 2)}
    assert all(forest.nodes[node] is graph.nodes[node] for node in forest)
    assert all(forest.edges[u, v] is graph.edges[u, v] for u, v in forest.edges)
    assert list(forest.edges[0, 1].items()) == [("weight", 1.0), ("portal", 3)]
