"""Algorithm 4 (simplification) on hand-checkable rooted trees."""

from __future__ import annotations

import math

import networkx as nx
import numpy as np

from g2s_core.rooted import root_forest
from g2s_core.simplify import simplify_forest


def rooted_path(n: int) -> nx.DiGraph:
    graph = nx.path_graph(n)
    nx.set_node_attributes(graph, {i: (float(i), 0.0, 0.0) for i in range(n)}, "pos")
    nx.set_edge_attributes(graph, 1.0, "weight")
    return root_forest(graph, {i: -i for i in range(n)}, centre=np.zeros(3))


def test_always_collapses_a_chain_to_root_and_leaf():
    structure = simplify_forest(rooted_path(6), lambda tree, a, b, c: True)
    assert sorted(structure.edges) == [(0, 5)]
    assert structure.edges[0, 5]["weight"] == 5.0
    assert structure.nodes[5]["depth"] == 1


def test_never_keeps_everything():
    forest = rooted_path(6)
    structure = simplify_forest(forest, lambda tree, a, b, c: False)
    assert sorted(structure.edges) == sorted(forest.edges)
    assert forest is not structure


def test_predicate_sees_every_child_of_b():
    # 0 -> 1 -> {2, 3}: 1 may go only if P holds for both children
    forest = nx.DiGraph(roots=[0])
    for node, pos in {0: (0, 0, 0), 1: (1, 0, 0), 2: (2, 1, 0), 3: (2, -1, 0)}.items():
        forest.add_node(node, pos=pos, depth=0)
    forest.add_edges_from([(0, 1), (1, 2), (1, 3)], weight=1.0)
    calls = []

    def only_upper(tree, a, b, c):
        calls.append((a, b, c))
        return tree.nodes[c]["pos"][1] > 0

    kept = simplify_forest(forest, only_upper)
    assert sorted(kept.edges) == [(0, 1), (1, 2), (1, 3)]
    assert (0, 1, 2) in calls and (0, 1, 3) in calls
    removed = simplify_forest(forest, lambda tree, a, b, c: True)
    assert sorted(removed.edges) == [(0, 2), (0, 3)]
    assert math.isclose(removed.edges[0, 2]["weight"], math.sqrt(5))


def test_max_length_rule_matches_a_hand_computed_result():
    # path of 7 unit steps; collapsing allowed while the new edge is at most 3 long
    structure = simplify_forest(rooted_path(8), lambda tree, a, b, c: math.dist(tree.nodes[a]["pos"], tree.nodes[c]["pos"]) <= 3)
    # from 0: 1 goes (0-2), 2 goes (0-3), 3 cannot (0-4 = 4); then from 3: 4, 5 go (3-6), 6 cannot (3-7 = 4)
    assert sorted(structure.edges) == [(0, 3), (3, 6), (6, 7)]
    assert [structure.nodes[n]["depth"] for n in (0, 3, 6, 7)] == [0, 1, 2, 3]


def test_leaves_and_roots_are_never_removed():
    structure = simplify_forest(rooted_path(2), lambda tree, a, b, c: True)
    assert sorted(structure.nodes) == [0, 1]


def test_terminals_are_never_removed():
    forest = rooted_path(5)
    forest.nodes[2]["terminal"] = True
    structure = simplify_forest(forest, lambda tree, a, b, c: True)
    assert sorted(structure.edges) == [(0, 2), (2, 4)]
