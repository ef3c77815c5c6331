"""Array helpers shared by the Steiner solvers: graph -> CSR, spanning trees, paths, pruning.

Everything here works on *node indices*: position ``i`` in :attr:`CSRGraph.nodes`,
the graph's node ids sorted ascending. Working on a canonical, sorted layout is
what makes the solvers deterministic: the CSR matrix built from a graph depends
only on its node ids, edges and weights, never on insertion order, so scipy's
Dijkstra (a deterministic routine) sees the same input every time.

Tie-breaking rule used throughout: edges are totally ordered by
``(weight, lo, hi)`` where ``lo < hi`` are the endpoint indices. A minimum
spanning tree under a strict total order is unique, so spanning trees never
depend on how a library breaks ties.

The solvers' shared contract, ``solver(graph, terminals) -> tree``:

* ``graph``: undirected networkx graph with integer node ids; edge attribute
  ``weight`` (missing means 1), finite and non-negative;
* ``terminals``: node ids to join, in any order; duplicates are ignored;
* the tree (``networkx.Graph``) has edges of ``graph``, each with its
  ``weight``; it holds every terminal and has no non-terminal leaf; one
  terminal gives a single-node graph;
* ``ValueError``: no terminals, a terminal not in the graph, terminals in
  different components, or a negative or non-finite weight; ``TypeError``: a
  directed graph, or node ids that are not integers.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Iterable
from dataclasses import dataclass

import networkx as nx
import numpy as np
from scipy.sparse import csr_matrix

from g2s_core.model import graph_of
from g2s_plugins import _trees
from g2s_plugins.surface_arrays import MIN_LENGTH, SurfaceArrays, surface_arrays

NO_PREDECESSOR = -9999
"""What scipy.sparse.csgraph writes in a predecessor array for "none"."""

_EDGE_RECORD = np.dtype([("u", np.int64), ("v", np.int64), ("w", np.float64)])


@dataclass(frozen=True)
class CSRGraph:
    """An undirected weighted graph in compressed sparse row form.

    Attributes:
        nodes: (n,) int64, the graph's node ids sorted ascending; index ``i``
            stands for node ``nodes[i]``.
        matrix: (n, n) symmetric ``csr_matrix`` of float64 weights, rows and
            column indices sorted, no duplicates, no self-loops. Zero weights
            are stored explicitly (csgraph's Dijkstra treats them as edges).
        lo, hi, weight: (m,) the undirected edges once each, ``lo < hi``,
            sorted by ``(lo, hi)``; ``weight`` is the minimum over parallel edges.
    """

    nodes: np.ndarray
    matrix: csr_matrix
    lo: np.ndarray
    hi: np.ndarray
    weight: np.ndarray

    @property
    def n(self) -> int:
        return int(self.nodes.shape[0])

    def indices_of(self, ids: Iterable[int]) -> np.ndarray:
        """Node indices of the node ids ``ids`` (int64); ValueError for ids not in the graph."""
        wanted = np.asarray(list(ids))
        if wanted.size == 0:
            return np.empty(0, dtype=np.int64)
        if wanted.ndim != 1 or wanted.dtype.kind not in "iu":
            raise ValueError("terminals must be integer node ids")
        wanted = wanted.astype(np.int64)
        if self.n == 0:
            where = np.zeros(wanted.shape, dtype=np.int64)
            bad = np.ones(wanted.shape, dtype=bool)
        else:
            where = np.minimum(np.searchsorted(self.nodes, wanted), self.n - 1)
            bad = self.nodes[where] != wanted
        if np.any(bad):
            raise ValueError(f"nodes not in the graph: {wanted[bad][:5].tolist()}")
        return where.astype(np.int64)

    def edge_weights(self, u: np.ndarray, v: np.ndarray) -> np.ndarray:
        """Weights of the edges ``(u[i], v[i])`` (node indices, either orientation)."""
        lo = np.minimum(u, v).astype(np.int64)
        hi = np.maximum(u, v).astype(np.int64)
        keys = self.lo * self.n + self.hi
        wanted = lo * self.n + hi
        where = np.searchsorted(keys, wanted)
        where = np.minimum(where, max(keys.shape[0] - 1, 0))
        if keys.shape[0] == 0 or np.any(keys[where] != wanted):
            raise ValueError("asked for the weight of a pair that is not an edge")
        return self.weight[where]


def distinct(values: np.ndarray) -> np.ndarray:
    """(k,) the distinct values of the 1-D ``values``, ascending (``np.unique(values)``), by one sort.

    numpy 2.3 and later answer a bare ``np.unique`` of integers from a hash table, which measured 5-10 times
    slower than a sort on the 70-150k node indices of a 100k-polygon level (4 December 2026). O(n log n).
    """
    ordered = np.sort(values)
    first = np.ones(ordered.shape[0], dtype=bool)
    first[1:] = ordered[1:] != ordered[:-1]
    return ordered[first]


def lightest_per_key(keys: np.ndarray, values: np.ndarray, tiebreak: np.ndarray | None = None) -> np.ndarray:
    """For each distinct key, the index of its element with the smallest value.

    Equal values are decided by the smallest ``tiebreak`` (distinct integers,
    default: the position). The indices come out in ascending key order.
    One quicksort of the keys plus linear passes (numpy's stable sorts are
    several times slower than its default sort, so none is used here).
    """
    order = np.argsort(keys)
    sorted_keys = keys[order]
    first = np.ones(sorted_keys.shape[0], dtype=bool)
    first[1:] = sorted_keys[1:] != sorted_keys[:-1]
    if first.all():
        return order
    starts = np.flatnonzero(first)
    run = np.cumsum(first) - 1
    sorted_values = values[order]
    is_lightest = sorted_values == np.minimum.reduceat(sorted_values, starts)[run]
    if tiebreak is None:
        tiebreak = np.arange(keys.shape[0], dtype=np.int64)
    ties = np.where(is_lightest, tiebreak[order], np.iinfo(np.int64).max)
    chosen = is_lightest & (ties == np.minimum.reduceat(ties, starts)[run])
    return order[chosen]


def graph_to_csr(graph: nx.Graph, weight: str = "weight") -> CSRGraph:
    """Convert an undirected networkx graph with integer node ids to a :class:`CSRGraph`.

    Edges without the ``weight`` attribute weigh 1. Parallel edges (multigraphs)
    keep their minimum weight; self-loops are dropped (they never lie on a
    shortest path or in a tree).

    Raises:
        TypeError: a node id is not an integer, or the graph is directed.
        ValueError: a weight is negative or not finite.
    """
    if graph.is_directed():
        raise TypeError("the Steiner solvers need an undirected graph")
    if weight == "weight" and not graph.is_multigraph():
        arrays = surface_arrays(graph)  # cached per graph: the coverage selector and the loop adder read it too
        ready = from_surface_arrays(arrays)
        if ready is not None:
            return ready
    nodes = np.array(list(graph.nodes))
    if nodes.size and (nodes.ndim != 1 or nodes.dtype.kind not in "iu"):
        raise TypeError("the Steiner solvers need integer node ids")
    nodes = np.sort(nodes.astype(np.int64))
    if graph.is_multigraph():
        edges = graph.edges(data=weight, default=1.0)
    else:
        # Each undirected edge once, read straight from the adjacency (about
        # twice as fast as the EdgeView, which tracks the nodes it has seen).
        edges = (
            (u, v, data.get(weight, 1.0))
            for u, neighbours in graph.adjacency()
            for v, data in neighbours.items()
            if u <= v
        )
    records = np.fromiter(edges, dtype=_EDGE_RECORD)
    u = np.searchsorted(nodes, records["u"])
    v = np.searchsorted(nodes, records["v"])
    return edges_to_csr(nodes, u, v, records["w"])


def from_surface_arrays(arrays: SurfaceArrays) -> CSRGraph | None:
    """The :class:`CSRGraph` of a simple graph already indexed as ``arrays``, or ``None`` when its rows are not
    the sorted integer ids or a weight is not a finite number above
    :data:`~g2s_plugins.surface_arrays.MIN_LENGTH` (which the arrays store for a zero, a negative or a tiny
    weight, each of which :func:`graph_to_csr` keeps or refuses as it is).

    The same arrays :func:`graph_to_csr` builds, without reading the graph's 100k dicts again: on a graph whose
    node ids were inserted in ascending order the arrays' rows already are the sorted ids. O(n + m).
    """
    nodes = np.asarray(arrays.nodes)
    if nodes.ndim != 1 or nodes.dtype.kind not in "iu" or np.any(nodes[1:] <= nodes[:-1]):
        return None
    matrix = arrays.adjacency
    if not (np.all(np.isfinite(matrix.data)) and np.all(matrix.data > MIN_LENGTH)):
        return None
    if not matrix.has_sorted_indices:
        matrix = matrix.sorted_indices()
    n = arrays.n
    rows = np.repeat(np.arange(n, dtype=np.int64), np.diff(matrix.indptr))
    cols = matrix.indices.astype(np.int64)
    upper = cols > rows  # each edge once, in (lo, hi) order: rows ascend, columns ascend within a row
    index_dtype = np.int32 if max(n, cols.shape[0]) < 2**31 - 1 else np.int64
    csr = csr_matrix((matrix.data, matrix.indices.astype(index_dtype), matrix.indptr.astype(index_dtype)), shape=(n, n))
    return CSRGraph(nodes=nodes.astype(np.int64), matrix=csr, lo=rows[upper], hi=cols[upper], weight=matrix.data[upper])


def edges_to_csr(nodes: np.ndarray, u: np.ndarray, v: np.ndarray, w: np.ndarray) -> CSRGraph:
    """Build a :class:`CSRGraph` over ``nodes`` from edge arrays of node indices.

    Orientation is ignored, self-loops dropped, parallel edges reduced to the
    lightest; the result does not depend on the order of the input edges.
    """
    n = int(nodes.shape[0])
    w = np.asarray(w, dtype=np.float64)
    if not np.all(np.isfinite(w)):
        raise ValueError("edge weights must be finite numbers")
    if np.any(w < 0):
        raise ValueError("edge weights must not be negative")
    u = np.asarray(u, dtype=np.int64)
    v = np.asarray(v, dtype=np.int64)
    keep = u != v
    lo = np.minimum(u, v)[keep]
    hi = np.maximum(u, v)[keep]
    w = w[keep]
    # One edge per (lo, hi), the lightest, in (lo, hi) order.
    key = lo * n + hi
    chosen = lightest_per_key(key, w)
    lo, hi, w = lo[chosen], hi[chosen], w[chosen]
    # Both orientations, rows then columns ascending.
    rows = np.concatenate([lo, hi])
    cols = np.concatenate([hi, lo])
    data = np.concatenate([w, w])
    order = np.argsort(rows * n + cols)  # distinct keys
    indptr = np.zeros(n + 1, dtype=np.int64)
    np.cumsum(np.bincount(rows, minlength=n), out=indptr[1:])
    index_dtype = np.int32 if max(n, rows.shape[0]) < 2**31 - 1 else np.int64
    matrix = csr_matrix(
        (data[order], cols[order].astype(index_dtype), indptr.astype(index_dtype)), shape=(n, n)
    )
    return CSRGraph(nodes=nodes, matrix=matrix, lo=lo, hi=hi, weight=w)


def spanning_tree(size: int, a: np.ndarray, b: np.ndarray, w: np.ndarray) -> np.ndarray:
    """Indices of the edges ``(a[i], b[i], w[i])`` that form the minimum spanning forest.

    Vertices are ``0 .. size-1``; weights are numbers (no NaN). Ties are broken by the total order
    ``(w, min(a, b), max(a, b), i)``, so the spanning forest is unique (and, depending only on the order of the
    weights, a minimum spanning forest for ``w``); of parallel edges only the lightest, then the first, can be
    in it. Kruskal's algorithm in C++ (``g2s_plugins._trees.spanning_forest``: one sort of the edges in that
    order, a union-find), O(m log m); scipy's ``minimum_spanning_tree`` on the edges' ranks in that order, as
    before, took two and a half times as long on the 100k-polygon level. The result is sorted ascending.
    """
    a, b = np.ascontiguousarray(a, dtype=np.int64), np.ascontiguousarray(b, dtype=np.int64)
    return _trees.spanning_forest(size, a, b, np.ascontiguousarray(w, dtype=np.float64))


def dense_spanning_tree(weights: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Minimum spanning tree of the complete graph with symmetric weight matrix ``weights``.

    Prim's algorithm on the dense matrix, O(k^2) time for k vertices, one numpy
    pass per added vertex. Ties follow the same total order as
    :func:`spanning_tree`, ``(w, min(i, j), max(i, j))``, so the tree is unique.
    An infinite weight means "no edge"; ValueError when the vertices cannot
    all be joined.

    Returns:
        ``(a, b)``: the k-1 tree edges with ``a < b``, sorted by ``(a, b)``.
    """
    k = int(weights.shape[0])
    in_tree = np.zeros(k, dtype=bool)
    in_tree[0] = True
    key = weights[0].astype(np.float64, copy=True)  # best weight joining j to the tree
    via = np.zeros(k, dtype=np.int64)  # tree end of that best edge
    key[0] = np.inf
    tree_a = np.empty(max(k - 1, 0), dtype=np.int64)
    tree_b = np.empty(max(k - 1, 0), dtype=np.int64)
    for step in range(k - 1):
        candidates = np.where(in_tree, np.inf, key)
        best = candidates.min()
        if not np.isfinite(best):
            raise ValueError("the terminals are not all connected")
        tied = np.flatnonzero(candidates == best)
        if tied.shape[0] == 1:
            j = int(tied[0])
        else:  # smallest (min(via, j), max(via, j)) among equal weights
            lo_end = np.minimum(via[tied], tied)
            hi_end = np.maximum(via[tied], tied)
            j = int(tied[np.lexsort((hi_end, lo_end))[0]])
        tree_a[step], tree_b[step] = min(int(via[j]), j), max(int(via[j]), j)
        in_tree[j] = True
        row = weights[j]
        better = (row < key) & ~in_tree
        equal = (row == key) & ~in_tree
        if np.any(equal):
            # Equal weight: the edge (j, x) wins if (min, max) is smaller than (via[x], x)'s.
            idx = np.flatnonzero(equal)
            new_lo, new_hi = np.minimum(j, idx), np.maximum(j, idx)
            old_lo, old_hi = np.minimum(via[idx], idx), np.maximum(via[idx], idx)
            wins = (new_lo < old_lo) | ((new_lo == old_lo) & (new_hi < old_hi))
            better[idx[wins]] = True
        key[better] = row[better]
        via[better] = j
    order = np.lexsort((tree_b, tree_a))
    return tree_a[order], tree_b[order]


def walk_to_sources(
    predecessors: np.ndarray, starts: np.ndarray, rows: np.ndarray | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """Edges of the shortest paths from ``starts`` back to their Dijkstra sources.

    All paths are followed at once, one vectorised predecessor step per hop.
    With a 1-D ``predecessors`` (a shortest-path forest, e.g. scipy's
    ``min_only=True`` output) a walk stops where it meets a node already
    walked, so the work is bounded by the size of the union of the paths.
    With a 2-D array, ``rows[i]`` picks the predecessor row of ``starts[i]``.

    Returns:
        ``(child, parent)`` node indices of the path edges, possibly repeated
        (2-D case) and in no particular order.
    """
    current = np.asarray(starts, dtype=np.int64)
    children: list[np.ndarray] = []
    parents: list[np.ndarray] = []
    if rows is None:
        seen = np.zeros(predecessors.shape[0], dtype=bool)
        current = distinct(current)
        while current.size:
            seen[current] = True
            step = predecessors[current].astype(np.int64)
            live = step != NO_PREDECESSOR
            current, step = current[live], step[live]
            children.append(current)
            parents.append(step)
            current = distinct(step[~seen[step]])
    else:
        line = np.asarray(rows, dtype=np.int64)
        while current.size:
            step = predecessors[line, current].astype(np.int64)
            live = step != NO_PREDECESSOR
            current, step, line = current[live], step[live], line[live]
            children.append(current)
            parents.append(step)
            current = step
    if not children:
        empty = np.empty(0, dtype=np.int64)
        return empty, empty
    return np.concatenate(children), np.concatenate(parents)


def unique_edges(u: np.ndarray, v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The distinct undirected edges among ``(u[i], v[i])`` as ``(lo, hi)``, sorted."""
    lo = np.minimum(u, v).astype(np.int64)
    hi = np.maximum(u, v).astype(np.int64)
    if lo.size == 0:
        return lo, hi
    span = int(hi.max()) + 1
    keys = distinct(lo * span + hi)
    return keys // span, keys % span


def prune_nonterminal_leaves(
    u: np.ndarray, v: np.ndarray, is_terminal: np.ndarray
) -> np.ndarray:
    """Mask of the edges of forest ``(u, v)`` that survive repeated removal of non-terminal leaves.

    ``is_terminal`` is a boolean array over all node indices. Only nodes that
    are removed are visited one at a time; finding the first leaves is vectorised.
    """
    m = u.shape[0]
    alive = np.ones(m, dtype=bool)
    if m == 0:
        return alive
    n = is_terminal.shape[0]
    degree = np.bincount(u, minlength=n) + np.bincount(v, minlength=n)
    leaves = np.flatnonzero((degree == 1) & ~is_terminal)
    if leaves.size == 0:
        return alive
    # Incidence lists: edges touching each node.
    ends = np.concatenate([u, v])
    edge_of = np.concatenate([np.arange(m), np.arange(m)])
    order = np.argsort(ends)  # the pruned set does not depend on the order of incidences
    start = np.zeros(n + 1, dtype=np.int64)
    np.cumsum(np.bincount(ends, minlength=n), out=start[1:])
    incident = edge_of[order].tolist()
    start_l = start.tolist()
    u_l, v_l = u.tolist(), v.tolist()
    terminal_l = is_terminal.tolist()
    degree_l = degree.tolist()
    alive_l = [True] * m
    stack = leaves.tolist()
    while stack:
        node = stack.pop()
        if degree_l[node] != 1:
            continue
        for e in incident[start_l[node] : start_l[node + 1]]:
            if not alive_l[e]:
                continue
            alive_l[e] = False
            other = v_l[e] if u_l[e] == node else u_l[e]
            degree_l[node] -= 1
            degree_l[other] -= 1
            if degree_l[other] == 1 and not terminal_l[other]:
                stack.append(other)
    return np.array(alive_l, dtype=bool)


def finish_tree(csr: CSRGraph, lo: np.ndarray, hi: np.ndarray, terminals: np.ndarray) -> nx.Graph:
    """Steps 4 and 5 shared by both solvers, then conversion to networkx.

    ``(lo, hi)``: distinct edges (node indices) of a connected subgraph that
    spans ``terminals``. Takes its minimum spanning tree (ties as in
    :func:`spanning_tree`), removes non-terminal leaves until none is left,
    and returns the tree with node ids and a ``weight`` on every edge (see
    :func:`to_networkx` for the insertion order).
    """
    weights = csr.edge_weights(lo, hi)
    local = distinct(ends := np.concatenate([lo, hi]))
    inverse = np.searchsorted(local, ends)  # np.unique's inverse, without its second sort
    a, b = inverse[: lo.shape[0]], inverse[lo.shape[0] :]
    chosen = spanning_tree(local.shape[0], a, b, weights)
    if chosen.shape[0] != local.shape[0] - 1:
        raise ValueError("the terminals are not all connected")
    lo, hi, weights = lo[chosen], hi[chosen], weights[chosen]
    is_terminal = np.zeros(csr.n, dtype=bool)
    is_terminal[terminals] = True
    keep = prune_nonterminal_leaves(lo, hi, is_terminal)
    return to_networkx(csr, lo[keep], hi[keep], weights[keep], terminals)


def to_networkx(
    csr: CSRGraph, lo: np.ndarray, hi: np.ndarray, weights: np.ndarray, terminals: np.ndarray
) -> nx.Graph:
    """A networkx graph of the edges ``(lo, hi)`` (node indices) with node ids and weights.

    Edges are inserted in ascending ``(lo, hi)`` order, which is ascending node-id
    order since indices follow the sorted ids; with no edges, the terminals alone.
    """
    tree = nx.Graph()
    if lo.shape[0] == 0:
        tree.add_nodes_from(csr.nodes[terminals].tolist())
        return tree
    order = np.argsort(lo * csr.n + hi)
    u, v = csr.nodes[lo[order]].tolist(), csr.nodes[hi[order]].tolist()
    # add_weighted_edges_from's graph (nodes as the edges first name them), without its checks per edge
    nodes = itertools.chain.from_iterable(zip(u, v))
    return graph_of(tree, {node: {} for node in nodes}, ((a, b, {"weight": w}) for a, b, w in zip(u, v, weights[order].tolist())))


def prepare(graph: nx.Graph, terminals: Iterable[int]) -> tuple[CSRGraph, np.ndarray]:
    """The graph as CSR and the distinct terminals as sorted node indices.

    Raises:
        ValueError: no terminals given.
    """
    csr = graph_to_csr(graph)
    terms = distinct(csr.indices_of(terminals))
    if terms.shape[0] == 0:
        raise ValueError("no terminals given")
    return csr, terms


def solve(
    graph: nx.Graph, terminals: Iterable[int], algorithm: Callable[[CSRGraph, np.ndarray], nx.Graph]
) -> nx.Graph:
    """The solvers' shared frame (see the module doc for the contract): :func:`prepare`, a lone
    terminal as a single-node tree, else ``algorithm(csr, terms)`` for two or more sorted terminal indices."""
    csr, terms = prepare(graph, terminals)
    if terms.shape[0] == 1:
        return to_networkx(csr, terms[:0], terms[:0], np.empty(0), terms)
    return algorithm(csr, terms)
