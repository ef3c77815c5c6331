"""Rooted trees from an unrooted forest (the paper's Algorithm 3).

Each connected component of the forest is rooted at its best-scoring node and
oriented by a depth-first traversal from that root, visiting neighbours in
ascending id order so that the result is deterministic. The paper selects a
root among the *unvisited* nodes repeatedly; since a traversal visits a whole
component, that is one root per component, which is what is done here.

A structure with loops (the optional ``loops`` stage) is rooted the same way:
the depth-first traversal gives a rooted spanning tree of each component,
and every other edge is kept as a *loop edge* (``loop=True``), directed from
its shallower end to its deeper one (equal depths: lower id first). Tree
edges carry no ``loop`` attribute, so a forest is rooted exactly as before.

Complexity: O((n + m) log n) for n nodes and m edges (ranking the nodes and
sorting neighbours).
"""

from __future__ import annotations

from collections.abc import Mapping

import networkx as nx
import numpy as np

from g2s_core.ties import tie_values


def root_ranks(forest: nx.Graph, scores: Mapping[int, float], centre: np.ndarray) -> dict[int, int]:
    """Rank of every node as a root: 0 is best.

    Order: highest score first; ties (see :mod:`g2s_core.ties`) go to the
    node nearest ``centre``, then to the lowest id.
    """
    nodes = sorted(forest)
    missing = [n for n in nodes if n not in scores]
    if missing:
        raise ValueError(f"the root selector gave no score for nodes {missing[:5]}")
    positions = np.array([forest.nodes[n]["pos"] for n in nodes], dtype=np.float64).reshape(-1, 3)
    score = tie_values([scores[n] for n in nodes])
    distance = tie_values(np.linalg.norm(positions - centre, axis=1))
    order = np.lexsort((np.asarray(nodes), distance, -score))
    return {nodes[i]: rank for rank, i in enumerate(order.tolist())}


def root_forest(forest: nx.Graph, scores: Mapping[int, float], centre: np.ndarray) -> nx.DiGraph:
    """Orient every tree of ``forest`` away from its chosen root.

    Args:
        forest: an undirected graph whose nodes carry ``pos`` (a forest,
            or a forest plus loop paths).
        scores: the RootSelector's score of every node (higher = better root).
        centre: (3,) geometric centre used to break ties, metres.

    Returns:
        A DiGraph with edges parent -> child (edge attributes kept) plus the
        loop edges (``loop=True``), node attributes copied plus ``depth`` and
        ``root``; ``graph["roots"]`` lists the roots in component order (by
        smallest node id).
    """
    rank = root_ranks(forest, scores, centre)
    components = sorted((min(c), c) for c in nx.connected_components(forest))
    roots = [min(c, key=rank.__getitem__) for _, c in components]
    rooted = nx.DiGraph(roots=roots)
    for root in roots:
        depth = {root: 0}
        rooted.add_node(root, **forest.nodes[root], depth=0, root=root)
        for parent, child in nx.dfs_edges(forest, root, sort_neighbors=sorted):
            depth[child] = depth[parent] + 1
            rooted.add_node(child, **forest.nodes[child], depth=depth[child], root=root)
            rooted.add_edge(parent, child, **forest.edges[parent, child])
    loop_edges = [(u, v) for u, v in forest.edges if not rooted.has_edge(u, v) and not rooted.has_edge(v, u)]
    for u, v in sorted(loop_edges, key=lambda e: sorted(e)):
        first, second = sorted((u, v), key=lambda node: (rooted.nodes[node]["depth"], node))
        rooted.add_edge(first, second, **forest.edges[u, v], loop=True)
    return rooted


def tree_parent(forest: nx.DiGraph, node: int) -> int | None:
    """The parent of ``node`` in its rooted tree (``None`` for a root)."""
    return next((p for p, data in forest.pred[node].items() if not data.get("loop", False)), None)

