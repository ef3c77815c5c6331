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

Complexity: O((n + m) log n) for n nodes and m edges (sorting the scores and
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


def components(graph: nx.Graph, ids: np.ndarray) -> tuple[np.ndarray, np.ndarray, int, np.ndarray]:
    """The undirected ``graph`` (integer ids, ``ids`` (n,) sorted) as arrays: each edge's rows ``lo`` <= ``hi``
    (m,) in no set order, the number of connected components and (n,) each node's, numbered by smallest id.

    The edges are read from networkx's adjacency dicts by numpy's C loops, each seen from both ends and kept
    from its lower one (an edge view's Python generator took 40-70 ms on the 77-105k edges of a 100k-polygon
    level, networkx's connected components 85 ms on its 105k-node graph). O(m + n log n).
    """
    adjacency, n = graph._adj, len(ids)
    ends = np.repeat(np.fromiter(adjacency, np.int64, n), np.fromiter(map(len, adjacency.values()), np.int64, n))
    others = np.fromiter(itertools.chain.from_iterable(adjacency.values()), np.int64, len(ends))
    lo, hi = np.searchsorted(ids, ends[ends <= others]), np.searchsorted(ids, others[ends <= others])
    count, label = csgraph.connected_components(sp.csr_array((np.ones(len(lo)), (lo, hi)), shape=(n, n)), directed=False)
    return lo, hi, count, np.argsort(np.argsort(np.unique(label, return_index=True)[1]))[label]


def component_roots(
    forest: nx.Graph, nodes: list[int], label: np.ndarray, count: int, scores: Mapping[int, float], centre: np.ndarray
) -> np.ndarray:
    """(count,) the position in ``nodes`` (``sorted(forest)``) of each component's root, ``label`` (n,) numbering
    the components 0 .. count-1.

    The root is the node with the highest score; ties (see :mod:`g2s_core.ties`) go to the node nearest
    ``centre``, then to the lowest id. Only the nodes with their component's highest score are measured.
    """
    missing = list(itertools.filterfalse(scores.__contains__, nodes))  # the look-ups in map's C loops, as below
    if missing:
        raise ValueError(f"the root selector gave no score for nodes {missing[:5]}")
    distinct, inverse = np.unique(np.fromiter(map(scores.__getitem__, nodes), np.float64, len(nodes)), return_inverse=True)
    score, top = tie_values(distinct)[inverse], np.full(count, -np.inf)  # each distinct score rounded once
    np.maximum.at(top, label, score)
    rows = np.flatnonzero(score == top[label])  # a few per component: their distances alone are rounded
    positions = np.array([forest._node[nodes[i]]["pos"] for i in rows.tolist()], dtype=np.float64).reshape(-1, 3)
    order = np.lexsort((rows, tie_values(np.linalg.norm(positions - centre, axis=1)), label[rows]))
    return rows[order[np.searchsorted(label[rows][order], np.arange(count))]]


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
    nodes, node_data, adjacency = sorted(forest), forest._node, forest._adj
    # rows of the (integer, g2s_core.model) ids by one binary search, not a dict look-up per edge end
    n, (lo, hi, count, label) = len(nodes), components(forest, ids := np.array(nodes, dtype=np.int64))
    best = component_roots(forest, nodes, label, count, scores, centre)  # each component rooted at its best node
    # the forest as an (n+1, n+1) CSR matrix (columns ascending in each row) with a lone virtual node n
    matrix = sp.csr_array((np.ones(2 * len(lo)), (np.r_[lo, hi], np.r_[hi, lo])), shape=(n + 1, n + 1))
    # one depth-first search (neighbours by ascending id) from the virtual node, joined to every root
    start = sp.csr_array((np.ones(count), (np.full(count, n), best)), shape=matrix.shape)
    order, parent = csgraph.depth_first_order(matrix + start, n, return_predecessors=True)
    order, parent = order[1:][np.argsort(label[order[1:]], kind="stable")], parent.astype(np.int64)
    depth, parents = [-1] * (n + 1), parent.tolist()
    for node in order.tolist():
        depth[node] = depth[parents[node]] + 1
    # ids and values in bulk (tolist), networkx's own dicts read by map's C loop (as g2s_core.model.graph_of writes
    # them): an index or a view object per node and edge looked up cost about 30 ms more on a 100k-polygon level
    child, visited = order[parent[order] != n], ids[order].tolist()
    tails, heads = ids[parent[child]].tolist(), ids[child].tolist()
    edges = list(zip(tails, heads, map(dict, map(dict.__getitem__, map(adjacency.__getitem__, tails), heads))))
    loop = (parent[lo] != hi) & (parent[hi] != lo)  # the loop edges: a tree edge joins a node to its parent
    for u, v in (divmod(k, n) for k in np.sort(lo[loop] * n + hi[loop]).tolist()):
        first, second = (u, v) if depth[u] <= depth[v] else (v, u)
        edges.append((nodes[first], nodes[second], {**adjacency[nodes[u]][nodes[v]], "loop": True}))
    records = zip(visited, map(node_data.__getitem__, visited), np.array(depth)[order].tolist(), ids[best[label[order]]].tolist())
    return graph_of(nx.DiGraph(roots=[nodes[i] for i in best.tolist()]),
                    {node: dict(data, depth=d, root=root) for node, data, d, root in records}, edges)


def tree_parent(forest: nx.DiGraph, node: int) -> int | None:
    """The parent of ``node`` in its rooted tree (``None`` for a root)."""
    return next((p for p, data in forest.pred[node].items() if not data.get("loop", False)), None)

