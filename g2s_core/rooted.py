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

One depth-first search of scipy (``scipy.sparse.csgraph.depth_first_order``,
on the forest as a CSR matrix over the sorted ids) from a virtual node joined
to every root roots all components at once.

Complexity: O((n + m) log n) for n nodes and m edges (ranking the nodes and
sorting the edges).
"""

from __future__ import annotations

import itertools
from collections.abc import Mapping

import networkx as nx
import numpy as np
import scipy.sparse as sp
from scipy.sparse import csgraph

from g2s_core.model import graph_of
from g2s_core.ties import tie_values


def root_ranks(forest: nx.Graph, scores: Mapping[int, float], centre: np.ndarray) -> np.ndarray:
    """(n,) rank as a root of each node of ``sorted(forest)``: 0 is best.

    Order: highest score first; ties (see :mod:`g2s_core.ties`) go to the
    node nearest ``centre``, then to the lowest id.
    """
    nodes = sorted(forest)
    missing = [n for n in nodes if n not in scores]
    if missing:
        raise ValueError(f"the root selector gave no score for nodes {missing[:5]}")
    data = dict(forest.nodes(data=True))
    positions = np.fromiter(itertools.chain.from_iterable(data[n]["pos"] for n in nodes), dtype=np.float64).reshape(-1, 3)
    distinct, inverse = np.unique(np.array([scores[n] for n in nodes], dtype=np.float64), return_inverse=True)
    score = tie_values(distinct)[inverse]  # each distinct score rounded once
    distance = tie_values(np.linalg.norm(positions - centre, axis=1))
    return np.argsort(np.lexsort((np.arange(len(nodes)), distance, -score)))


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
    nodes = sorted(forest)
    n, ends = len(nodes), np.fromiter(itertools.chain.from_iterable(forest.edges), dtype=np.int64).reshape(-1, 2)
    # rows of the (integer, g2s_core.model) ids by one binary search, not a dict look-up per edge end
    lo, hi = np.sort(np.searchsorted(np.array(nodes, dtype=np.int64), ends), axis=1).T
    # the forest as an (n+1, n+1) CSR matrix (columns ascending in each row) with a lone virtual node n
    matrix = sp.csr_array((np.ones(2 * len(lo)), (np.r_[lo, hi], np.r_[hi, lo])), shape=(n + 1, n + 1))
    count, label = csgraph.connected_components(matrix, directed=False)
    # components numbered by their smallest node (the virtual node's comes last), each rooted at its best rank
    label = np.argsort(np.argsort(np.unique(label, return_index=True)[1]))[label[:n]]
    by_rank = np.lexsort((rank, label))
    best = by_rank[np.searchsorted(label[by_rank], np.arange(count - 1))]
    # one depth-first search (neighbours by ascending id) from the virtual node, joined to every root
    start = sp.csr_array((np.ones(count - 1), (np.full(count - 1, n), best)), shape=matrix.shape)
    order, parent = csgraph.depth_first_order(matrix + start, n, return_predecessors=True)
    order, parent = order[1:][np.argsort(label[order[1:]], kind="stable")], parent.astype(np.int64)
    depth, parents = [-1] * (n + 1), parent.tolist()
    for node in order.tolist():
        depth[node] = depth[parents[node]] + 1
    # networkx's own dicts: a view object per node and edge looked up cost more than copying them
    node_data, adjacency, root_of, visited = dict(forest.nodes(data=True)), dict(forest.adjacency()), best[label].tolist(), order.tolist()
    child = order[parent[order] != n]
    edges = [(nodes[p], nodes[c], dict(adjacency[nodes[p]][nodes[c]])) for p, c in zip(parent[child].tolist(), child.tolist())]
    loop = (parent[lo] != hi) & (parent[hi] != lo)  # the loop edges: a tree edge joins a node to its parent
    for u, v in (divmod(k, n) for k in np.sort(lo[loop] * n + hi[loop]).tolist()):
        first, second = (u, v) if depth[u] <= depth[v] else (v, u)
        edges.append((nodes[first], nodes[second], {**adjacency[nodes[u]][nodes[v]], "loop": True}))
    return graph_of(nx.DiGraph(roots=[nodes[i] for i in best.tolist()]),
                    {nodes[i]: {**node_data[nodes[i]], "depth": depth[i], "root": nodes[root_of[i]]} for i in visited}, edges)


def tree_parent(forest: nx.DiGraph, node: int) -> int | None:
    """The parent of ``node`` in its rooted tree (``None`` for a root)."""
    return next((p for p, data in forest.pred[node].items() if not data.get("loop", False)), None)

