"""Rooted trees from an unrooted forest (the paper's Algorithm 3).

Each connected component of the forest is rooted at its best-scoring node and
oriented by a depth-first traversal from that root, visiting neighbours in
ascending id order so that the result is deterministic. The paper selects a
root among the *unvisited* nodes repeatedly; since a traversal visits a whole
component, that is one root per component, which is what is done here.

Complexity: O(n log n) for n nodes (sorting the scores and neighbour lists).
"""

from __future__ import annotations

from collections.abc import Mapping

import networkx as nx
import numpy as np

SCORE_DIGITS = 12
"""Scores are compared after rounding to this many significant digits, so that
values equal but for floating-point noise count as ties."""


def _rounded(score: float) -> float:
    return float(f"{score:.{SCORE_DIGITS}g}")


def choose_root(nodes: list[int], scores: Mapping[int, float], positions: Mapping[int, tuple], centre: np.ndarray) -> int:
    """The node with the highest score; ties go to the node nearest ``centre``, then to the lowest id."""

    def key(node: int) -> tuple[float, float, int]:
        distance = float(np.linalg.norm(np.asarray(positions[node]) - centre))
        return (-_rounded(scores[node]), _rounded(distance), node)

    return min(nodes, key=key)


def root_forest(forest: nx.Graph, scores: Mapping[int, float], centre: np.ndarray) -> nx.DiGraph:
    """Orient every tree of ``forest`` away from its chosen root.

    Args:
        forest: an undirected acyclic graph whose nodes carry ``pos``.
        scores: the RootSelector's score of every node (higher = better root).
        centre: (3,) geometric centre used to break ties, metres.

    Returns:
        A DiGraph with edges parent -> child (edge attributes kept), node
        attributes copied plus ``depth`` and ``root``; ``graph["roots"]``
        lists the roots in component order (by smallest node id).
    """
    missing = [n for n in forest.nodes if n not in scores]
    if missing:
        raise ValueError(f"the root selector gave no score for nodes {missing[:5]}")
    positions = nx.get_node_attributes(forest, "pos")
    rooted = nx.DiGraph()
    roots: list[int] = []
    components = sorted((sorted(c) for c in nx.connected_components(forest)), key=lambda c: c[0])
    for component in components:
        root = choose_root(component, scores, positions, centre)
        roots.append(root)
        rooted.add_node(root, **forest.nodes[root], depth=0, root=root)
        stack = [root]
        while stack:
            parent = stack.pop()
            depth = rooted.nodes[parent]["depth"] + 1
            children = sorted(n for n in forest.adj[parent] if n not in rooted)
            for child in children:
                rooted.add_node(child, **forest.nodes[child], depth=depth, root=root)
                rooted.add_edge(parent, child, **forest.edges[parent, child])
            stack.extend(reversed(children))
    rooted.graph["roots"] = roots
    return rooted
