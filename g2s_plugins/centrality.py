"""Node centrality metrics shared by the terminal selectors, root selectors and analyzers.

One implementation per metric; every function takes an undirected
:class:`networkx.Graph` (a directed graph is read as its undirected view),
returns ``{node: float}`` for every node in the graph's node order, handles
disconnected graphs component by component and gives the same answer on
every run. Self-loops are ignored. When ``weighted`` is true the edge
attribute ``weight`` (default 1.0; the surface graph stores metres) is used;
it must be finite and >= 0.

=============  =================================================  ==========================
metric         algorithm                                          cost (n nodes, m edges)
=============  =================================================  ==========================
betweenness    forest: subtree-size formula (ours, exact)          O(n)
               graph, unweighted: Brandes, rustworkx               O(nm), one thread
               graph, weighted: Brandes, igraph (networkx if       O(nm + n² log n)
               igraph does not import or a weight is 0)
               graph above 2,048 nodes: Brandes from 256 sampled   O(km + kn log n)
               sources (Brandes and Pich), igraph
closeness      forest: sum-of-distances rerooting (ours, exact)    O(n)
               graph, unweighted: rustworkx (BFS from every node)  O(nm), parallel
               graph, weighted: scipy Dijkstra from every node     O(nm + n² log n)
degree         neighbour count or sum of edge weights              O(m)
eigenvector    scipy ``eigsh`` (ARPACK) per component              iterative
katz           scipy sparse LU solve of (I - alpha A) x = 1        sparse direct
=============  =================================================  ==========================

Besides these node metrics, :func:`edge_betweenness` (the chokepoints'
traffic, unweighted): s (N - s) pairs across each edge of a forest, O(n);
on a graph with cycles Brandes' algorithm by rustworkx, O(nm), and from 256
sampled sources by igraph above 2,048 nodes, O(km).

Sources: betweenness, L. C. Freeman, "A set of measures of centrality based
on betweenness", Sociometry 40(1):35-41, 1977, computed by U. Brandes' "A
faster algorithm for betweenness centrality", Journal of Mathematical
Sociology 25(2):163-177, 2001; closeness in the form of S. Wasserman and
K. Faust, Social Network Analysis: Methods and Applications, Cambridge
University Press, 1994; eigenvector centrality, P. Bonacich, "Factoring and
weighting approaches to status scores and clique identification", Journal
of Mathematical Sociology 2(1):113-120, 1972; L. Katz, "A new status index
derived from sociometric analysis", Psychometrika 18(1):39-43, 1953.

Normalisation follows networkx for undirected graphs, over the *whole*
graph's n (not per component): betweenness is divided by (n-1)(n-2)/2, the
number of node pairs that exclude the node; closeness is Wasserman-Faust's
``(r-1)/S * (r-1)/(n-1)`` for a node that reaches r nodes at total distance
S; degree is divided by n-1. Eigenvector centrality is the unit-norm
positive Perron vector of each component separately (the eigenvector of a
disconnected graph is not unique); Katz centrality has a unique solution
for the whole graph and is scaled to unit norm over the whole graph.
"""

from __future__ import annotations

import itertools
from collections.abc import Hashable, Mapping
from dataclasses import dataclass
from typing import Literal

import numpy as np
from pydantic import Field

from g2s_core.errors import G2SError
from g2s_core.lazy import lazy_module
from g2s_core.plugin import PluginParams
from g2s_plugins import traffic

rx = lazy_module("rustworkx")
sp, csgraph, linalg = lazy_module("scipy.sparse"), lazy_module("scipy.sparse.csgraph"), lazy_module("scipy.sparse.linalg")
nx = lazy_module("networkx")


class ClosenessParams(PluginParams):
    """Distances in metres or in hops (the closeness analyzer's and root selector's parameters)."""

    weighted: bool = Field(True, description="measure distances by edge length (metres) instead of hop count")


Metric = Literal["degree", "betweenness", "closeness", "eigenvector", "katz"]
"""The metric names accepted by :func:`compute`."""

METRICS: tuple[str, ...] = ("degree", "betweenness", "closeness", "eigenvector", "katz")

WEIGHTED_PAIRS_EXACT = 256
"""Node-weighted betweenness on a graph with cycles is exact up to this many nodes, sampled above."""

BRANDES_EXACT = 2048
"""Betweenness of nodes and edges on a graph with cycles is exact (Brandes from every node) up to this many
nodes: under a second of CPU (a 9,811-node looped structure took 10.6 s for nodes and 15.8 s for edges, and the
cost grows as n m); above it, it is estimated from :data:`BRANDES_SOURCES` sampled sources."""

BRANDES_SOURCES = 256
"""Sources of the estimate above :data:`BRANDES_EXACT` nodes (see :func:`_brandes_sources`)."""

_DENSE_EIGEN_LIMIT = 256
"""Components up to this size use a dense symmetric eigen-solver."""

_DIJKSTRA_BLOCK = 1 << 22
"""Distance-matrix entries computed at once by weighted closeness (32 MB)."""

_ONE_THREAD = 1 << 62
"""rustworkx's ``parallel_threshold`` that keeps Brandes on one thread: its parallel version adds the sources'
contributions in thread order, so the last bits (and the ranks of near-equal values) changed from run to run."""


# --- graph as arrays ---------------------------------------------------------------


@dataclass(frozen=True)
class _Arrays:
    """A graph as index arrays: node i is ``nodes[i]``; edges (u, v, w) with u != v, once each."""

    nodes: list[Hashable]
    u: np.ndarray
    v: np.ndarray
    w: np.ndarray

    @property
    def n(self) -> int:
        return len(self.nodes)

    def adjacency(self, weights: np.ndarray | None = None) -> sp.csr_array:
        """Symmetric n x n adjacency; explicit zero weights stay stored (csgraph reads them as edges)."""
        data = self.w if weights is None else weights
        rows = np.concatenate([self.u, self.v])
        cols = np.concatenate([self.v, self.u])
        return sp.csr_array((np.concatenate([data, data]), (rows, cols)), shape=(self.n, self.n))

    def components(self) -> tuple[int, np.ndarray]:
        """(number of components, component label of each node index)."""
        if self.n == 0:
            return 0, np.zeros(0, dtype=np.int64)
        count, labels = csgraph.connected_components(self.adjacency(np.ones_like(self.w)), directed=False)
        return int(count), labels.astype(np.int64)

    def is_forest(self, count: int) -> bool:
        return len(self.u) == self.n - count

    def dict(self, values: np.ndarray) -> dict[Hashable, float]:
        return dict(zip(self.nodes, np.asarray(values, dtype=np.float64).tolist()))


def _undirected(graph: nx.Graph) -> nx.Graph:
    return graph.to_undirected(as_view=True) if graph.is_directed() else graph


def _arrays(graph: nx.Graph, weighted: bool) -> _Arrays:
    """Index the graph; with ``weighted``, check the weights."""
    graph = _undirected(graph)
    nodes = list(graph.nodes)
    index = dict(zip(nodes, range(len(nodes))))
    # Each undirected edge once, from its lower-index end (self-loops skipped), in the adjacency's order: the
    # ends looked up by map's C loop, not an index and a list append per edge in Python (half the time)
    adjacency = graph._adj
    ends = np.repeat(np.fromiter(map(index.__getitem__, adjacency), np.int64, len(adjacency)),
                     np.fromiter(map(len, adjacency.values()), np.int64, len(adjacency)))
    others = np.fromiter(map(index.__getitem__, itertools.chain.from_iterable(adjacency.values())), np.int64, len(ends))
    kept = others > ends
    u, v = ends[kept], others[kept]
    if weighted:
        weights = list(itertools.compress(
            (data.get("weight", 1.0) for neighbours in adjacency.values() for data in neighbours.values()), kept.tolist()
        ))
        try:
            w = np.asarray(weights, dtype=np.float64).reshape(len(u))
        except (TypeError, ValueError):
            at = next((i for i, x in enumerate(weights) if not isinstance(x, (int, float))), 0)
            raise G2SError(
                f"edge ({nodes[u[at]]}, {nodes[v[at]]}) has weight {weights[at]!r}; a weighted metric needs numbers"
            ) from None
        bad = np.flatnonzero(~np.isfinite(w) | (w < 0))
        if bad.size:
            at = int(bad[0])
            raise G2SError(
                f"edge ({nodes[u[at]]}, {nodes[v[at]]}) has weight {weights[at]!r}; "
                "a weighted metric needs finite weights >= 0"
            )
    else:
        w = np.ones(len(u), dtype=np.float64)
    return _Arrays(nodes, u, v, w)


def _blocks(adjacency: sp.csr_array, labels: np.ndarray, count: int, batch: int = 1):
    """Yield (node indices, adjacency block) for the components, in label order.

    The matrix is permuted once so that every component is a contiguous
    block. Consecutive components are merged into one block-diagonal block
    while their total size stays <= ``batch`` (``batch=1``: one component per
    block); a lone one-node component yields ``None`` for its block.
    """
    order = np.argsort(labels, kind="stable")
    sizes = np.bincount(labels, minlength=count)
    starts = np.concatenate([[0], np.cumsum(sizes)]).tolist()
    permuted = adjacency[order][:, order].tocsr()
    label = 0
    while label < count:
        end = label + 1
        while end < count and starts[end + 1] - starts[label] <= batch:
            end += 1
        lo, hi = starts[label], starts[end]
        yield order[lo:hi], (permuted[lo:hi, lo:hi] if hi - lo > 1 else None)
        label = end


def _rx_graph(arrays: _Arrays) -> rx.PyGraph:
    graph = rx.PyGraph(multigraph=False)
    graph.add_nodes_from(range(arrays.n))
    graph.add_edges_from_no_data(list(zip(arrays.u.tolist(), arrays.v.tolist())))
    return graph


# --- forests: the O(n) formulas ---------------------------------------------------------


@dataclass(frozen=True)
class _Rooted:
    """Each tree of a forest hung from its first node: BFS order, parent, subtree size."""

    order: list[int]
    parent: list[int]
    size: list[int]
    component_size: np.ndarray


def _rooted(arrays: _Arrays, count: int, labels: np.ndarray, weights: np.ndarray | None = None) -> _Rooted:
    """``size`` sums ``weights`` (default 1 per node) over each subtree."""
    n = arrays.n
    # One breadth-first traversal from a virtual node n joined to the first node
    # of every component visits the whole forest in a single library call.
    firsts = np.unique(labels, return_index=True)[1].astype(np.int64)
    rows = np.concatenate([arrays.u, np.full(count, n, dtype=np.int64)])
    cols = np.concatenate([arrays.v, firsts])
    augmented = sp.csr_array((np.ones(len(rows)), (rows, cols)), shape=(n + 1, n + 1))
    order_array, predecessors = csgraph.breadth_first_order(augmented, n, directed=False, return_predecessors=True)
    parent_array = predecessors[:n].astype(np.int64)
    parent_array[parent_array == n] = -1
    order = order_array[1:].tolist()
    parent = parent_array.tolist()
    size = [1] * n if weights is None else weights.tolist()
    for node in reversed(order):  # children before parents
        p = parent[node]
        if p >= 0:
            size[p] += size[node]
    component_size = np.bincount(labels, weights=weights, minlength=count)[labels]
    return _Rooted(order, parent, size, component_size)


def _require_forest(arrays: _Arrays) -> tuple[int, np.ndarray]:
    count, labels = arrays.components()
    if not arrays.is_forest(count):
        raise ValueError(
            f"not a forest: {len(arrays.u)} edges on {arrays.n} nodes in {count} components "
            f"(a forest has {arrays.n - count})"
        )
    return count, labels


def _tree_betweenness(
    arrays: _Arrays, count: int, labels: np.ndarray, normalized: bool, node_weight: np.ndarray | None = None
) -> np.ndarray:
    n = arrays.n
    if n == 0:
        return np.zeros(0)
    rooted = _rooted(arrays, count, labels, node_weight)
    size = np.asarray(rooted.size, dtype=np.float64)
    parent = np.asarray(rooted.parent, dtype=np.int64)
    has_parent = parent >= 0
    # Sum of squared child-subtree sizes, per parent (exact in float64 below 2^53).
    child_squares = np.bincount(parent[has_parent], weights=size[has_parent] ** 2, minlength=n)
    total = rooted.component_size.astype(np.float64)
    above = total - size  # the branch through the parent (0 at a tree's first node)
    own = 1.0 if node_weight is None else node_weight
    values = ((total - own) ** 2 - child_squares - above**2) / 2.0
    if node_weight is not None:
        if normalized:
            values /= _pair_weight(node_weight)
    elif normalized and n > 2:
        values /= (n - 1) * (n - 2) / 2.0
    return values


def _pair_weight(node_weight: np.ndarray) -> float:
    """Total weight of the unordered node pairs, sum_{s<t} w_s w_t (1 when there is none)."""
    total = (node_weight.sum() ** 2 - (node_weight**2).sum()) / 2.0
    return float(total) if total > 0 else 1.0


def tree_betweenness(tree: nx.Graph, normalized: bool = True) -> dict[Hashable, float]:
    """Exact betweenness of every node of a forest, in O(n).

    In a tree there is exactly one path between two nodes, so a node v lies on
    the path of the pair (s, t) iff s and t lie in different branches of v.
    With branch sizes s_1..s_k (the child subtrees and the part above v) in a
    component of N nodes, ``sum(s_i) = N - 1`` and

        betweenness(v) = sum_{i<j} s_i s_j = ((N - 1)^2 - sum s_i^2) / 2.

    Edge weights do not change which path is shortest in a tree, so this is
    the weighted and the unweighted betweenness alike. Normalised like
    networkx for undirected graphs: divided by (n-1)(n-2)/2 with n the number
    of nodes of the whole forest (no scaling when n <= 2). The traversal is a
    single scipy breadth-first search plus two linear passes (no recursion).

    Raises:
        ValueError: ``tree`` has a cycle.
    """
    arrays = _arrays(tree, weighted=False)
    count, labels = _require_forest(arrays)
    return arrays.dict(_tree_betweenness(arrays, count, labels, normalized))


def _tree_closeness(arrays: _Arrays, count: int, labels: np.ndarray) -> np.ndarray:
    n = arrays.n
    if n == 0:
        return np.zeros(0)
    rooted = _rooted(arrays, count, labels)
    order, parent, size = rooted.order, rooted.parent, rooted.size
    nodes_with_parent = np.flatnonzero(np.asarray(parent) >= 0)
    # Length of the edge to the parent, read from the weighted adjacency.
    up_length = [0.0] * n
    if nodes_with_parent.size:
        lengths = arrays.adjacency()[nodes_with_parent, np.asarray(parent)[nodes_with_parent]]
        for node, length in zip(nodes_with_parent.tolist(), np.asarray(lengths).ravel().tolist()):
            up_length[node] = length
    # Distance from each tree's first node, then its total.
    depth = [0.0] * n
    for node in order:
        p = parent[node]
        if p >= 0:
            depth[node] = depth[p] + up_length[node]
    first_total = np.bincount(labels, weights=np.asarray(depth), minlength=count)
    # Rerooting: moving from p to its child c brings the size(c) nodes of c's
    # subtree one edge closer and the other N - size(c) one edge farther.
    component_size = rooted.component_size.tolist()
    total = [0.0] * n
    for node in order:
        p = parent[node]
        if p < 0:
            total[node] = float(first_total[labels[node]])
        else:
            total[node] = total[p] + up_length[node] * (component_size[node] - 2 * size[node])
    return _closeness_from_totals(np.asarray(total), rooted.component_size, n)


def _closeness_from_totals(total: np.ndarray, reach: np.ndarray, n: int) -> np.ndarray:
    """Wasserman-Faust closeness from total distances and component sizes (networkx's formula)."""
    values = np.zeros(len(total))
    if n <= 1:
        return values
    reach = reach.astype(np.float64)
    ok = total > 0
    values[ok] = (reach[ok] - 1.0) / total[ok] * (reach[ok] - 1.0) / (n - 1)
    return values


def tree_closeness(tree: nx.Graph, weighted: bool = True) -> dict[Hashable, float]:
    """Exact closeness of every node of a forest, in O(n).

    The total distance S(v) from v to the other nodes of its tree is found for
    one node by a traversal, then for every child c of p as
    ``S(c) = S(p) + w(p, c) * (N - 2 size(c))`` (size(c) = nodes of c's
    subtree, N = nodes of the tree). Closeness is then networkx's
    Wasserman-Faust form, see the module docs.

    Raises:
        ValueError: ``tree`` has a cycle.
    """
    arrays = _arrays(tree, weighted=weighted)
    count, labels = _require_forest(arrays)
    return arrays.dict(_tree_closeness(arrays, count, labels))


# --- general graphs --------------------------------------------------------------------


def _igraph():
    try:
        import igraph
    except ImportError:
        return None
    return igraph


def _brandes_sources(n: int) -> np.ndarray | None:
    """The sources of Brandes' algorithm on an n-node graph with cycles: ``None`` (every node, exact) up to
    :data:`BRANDES_EXACT` nodes, else :data:`BRANDES_SOURCES` nodes drawn uniformly without replacement (seed 0,
    so every run draws the same).

    Brandes and Pich's pivot estimate (Centrality estimation in large networks, Int. J. Bifurcation and Chaos
    17(7), 2007): the dependencies of the sampled sources, scaled by n / k, are an unbiased estimate of the
    betweenness. Each source's share of a normalised value lies in [0, n / (n - 1)], so by Hoeffding's
    inequality a node's (or an edge's) normalised estimate is within ``sqrt(ln(2 / delta) / (2 k))`` n / (n - 1)
    of the exact value with probability at least 1 - delta: 0.10 for k = 256, delta = 0.01
    (:func:`g2s_plugins.traffic.flow_error_bound`).
    """
    if n <= BRANDES_EXACT:
        return None
    return np.sort(np.random.default_rng(0).choice(n, size=BRANDES_SOURCES, replace=False))


def _sampled_brandes(arrays: _Arrays, sources: np.ndarray, weighted: bool, edges: bool) -> np.ndarray | None:
    """Node (or, with ``edges``, edge) betweenness estimated from ``sources`` (see :func:`_brandes_sources`),
    unnormalised, in ``arrays``' node (edge) order; ``None`` when igraph does not import or a weight is 0."""
    igraph = _igraph()
    if igraph is None or (weighted and not bool(np.all(arrays.w > 0))):
        return None
    g = igraph.Graph(n=arrays.n, edges=list(zip(arrays.u.tolist(), arrays.v.tolist())), directed=False)
    measure = g.edge_betweenness if edges else g.betweenness
    values = measure(directed=False, weights=arrays.w.tolist() if weighted else None,
                     sources=sources.tolist(), targets=range(arrays.n))
    return np.asarray(values, dtype=np.float64) * (arrays.n / len(sources))


def graph_betweenness(graph: nx.Graph, weighted: bool, normalized: bool = True) -> dict[Hashable, float]:
    """Brandes betweenness of any undirected graph, by a library.

    Unweighted: :func:`rustworkx.betweenness_centrality` (on one thread, see
    :data:`_ONE_THREAD`). Weighted:
    igraph's ``Graph.betweenness(weights=...)`` when igraph imports and every
    weight is > 0 (igraph refuses zero weights), else networkx's (same
    result, pure Python, about 60x slower on a 900-node grid). Above
    :data:`BRANDES_EXACT` nodes, estimated from sampled sources by igraph
    (:func:`_brandes_sources`). Normalised as in the module docs.
    """
    arrays = _arrays(graph, weighted=weighted)
    return arrays.dict(_graph_betweenness(arrays, weighted, normalized))


def _graph_betweenness(arrays: _Arrays, weighted: bool, normalized: bool) -> np.ndarray:
    n = arrays.n
    if n == 0:
        return np.zeros(0)
    sources = _brandes_sources(n)
    values = None if sources is None else _sampled_brandes(arrays, sources, weighted, edges=False)
    if values is not None:
        return values / ((n - 1) * (n - 2) / 2.0) if normalized else values
    if not weighted:
        result = rx.betweenness_centrality(_rx_graph(arrays), normalized=normalized, parallel_threshold=_ONE_THREAD)
        return np.array([result[i] for i in range(n)], dtype=np.float64)
    igraph = _igraph()
    if igraph is not None and bool(np.all(arrays.w > 0)):
        g = igraph.Graph(n=n, edges=list(zip(arrays.u.tolist(), arrays.v.tolist())), directed=False)
        values = np.asarray(g.betweenness(directed=False, weights=arrays.w.tolist()), dtype=np.float64)
    else:
        g = nx.Graph()
        g.add_nodes_from(range(n))
        g.add_weighted_edges_from(zip(arrays.u.tolist(), arrays.v.tolist(), arrays.w.tolist()))
        result = nx.betweenness_centrality(g, normalized=False, weight="weight")
        values = np.array([result[i] for i in range(n)], dtype=np.float64)
    if normalized and n > 2:
        values /= (n - 1) * (n - 2) / 2.0
    return values


def betweenness(
    graph: nx.Graph,
    weighted: bool = False,
    normalized: bool = True,
    node_weight: Mapping[Hashable, float] | None = None,
) -> dict[Hashable, float]:
    """Betweenness centrality: the O(n) tree formula on a forest, Brandes otherwise.

    See :func:`tree_betweenness` and :func:`graph_betweenness`; on a forest
    ``weighted`` makes no difference.

    With ``node_weight`` (e.g. the area each node stands for) the pair (s, t)
    counts w_s w_t instead of 1: on a forest the subtree formula with
    weighted branch sizes, ``((W - w_v)^2 - sum W_i^2) / 2``, O(n); on a
    graph with cycles, shortest-path trees from every node
    (:func:`g2s_plugins.traffic.od_flow`; equal-length paths are not split),
    exact up to :data:`WEIGHTED_PAIRS_EXACT` nodes and from that many
    weight-sampled sources above (error bound in :mod:`g2s_plugins.traffic`).
    Normalised by the total pair weight ``sum_{s<t} w_s w_t``.
    """
    arrays = _arrays(graph, weighted=weighted)
    count, labels = arrays.components()
    weights = None if node_weight is None else np.array([node_weight[node] for node in arrays.nodes], dtype=np.float64)
    if arrays.is_forest(count):
        return arrays.dict(_tree_betweenness(arrays, count, labels, normalized, weights))
    if weights is None:
        return arrays.dict(_graph_betweenness(arrays, weighted, normalized))
    flow, _ = traffic.od_flow(arrays.adjacency(), weights, max_sources=WEIGHTED_PAIRS_EXACT)
    values = flow / 2.0  # od_flow counts ordered pairs
    return arrays.dict(values / _pair_weight(weights) if normalized else values)


def closeness(graph: nx.Graph, weighted: bool = False) -> dict[Hashable, float]:
    """Closeness centrality (networkx's Wasserman-Faust form, per component).

    Forests: the O(n) rerooting formula (:func:`tree_closeness`). Other
    graphs: rustworkx breadth-first searches when unweighted; scipy Dijkstra
    from every node, in blocks of sources, when weighted (distance = weight).
    """
    arrays = _arrays(graph, weighted=weighted)
    n = arrays.n
    if n == 0:
        return {}
    count, labels = arrays.components()
    if arrays.is_forest(count):
        return arrays.dict(_tree_closeness(arrays, count, labels))
    if not weighted:
        result = rx.closeness_centrality(_rx_graph(arrays), wf_improved=True)
        return arrays.dict(np.array([result[i] for i in range(n)], dtype=np.float64))
    adjacency = arrays.adjacency()
    total = np.zeros(n)
    # Small components are batched into block-diagonal blocks of up to 2048
    # nodes (one Dijkstra call each); unreachable entries are inf and skipped.
    for members, sub in _blocks(adjacency, labels, count, batch=2048):
        if sub is None:
            continue
        block = max(1, _DIJKSTRA_BLOCK // members.size)
        for start in range(0, members.size, block):
            sources = np.arange(start, min(start + block, members.size))
            distances = csgraph.dijkstra(sub, directed=False, indices=sources)
            total[members[sources]] = np.where(np.isfinite(distances), distances, 0.0).sum(axis=1)
    reach = np.bincount(labels, minlength=count)[labels]
    return arrays.dict(_closeness_from_totals(total, reach, n))


def degree(graph: nx.Graph, weighted: bool = False, normalized: bool = True) -> dict[Hashable, float]:
    """Degree centrality: number of neighbours, or with ``weighted`` the sum of incident edge weights.

    ``normalized`` divides by n-1 (the largest possible neighbour count), as
    networkx's ``degree_centrality`` does; a one-node graph gets 1.0 when
    unweighted and normalised, as in networkx.
    """
    arrays = _arrays(graph, weighted=weighted)
    n = arrays.n
    if n == 0:
        return {}
    values = np.bincount(arrays.u, weights=arrays.w, minlength=n) + np.bincount(arrays.v, weights=arrays.w, minlength=n)
    if normalized:
        if n == 1:
            return arrays.dict(np.zeros(1) if weighted else np.ones(1))
        values = values / (n - 1)
    return arrays.dict(values)


def _perron_vector(matrix: sp.csr_array) -> np.ndarray:
    """Unit-norm eigenvector of the largest eigenvalue of a symmetric non-negative matrix, signed positive."""
    size = matrix.shape[0]
    if size == 1:
        return np.ones(1)
    if size <= _DENSE_EIGEN_LIMIT:
        _, vectors = np.linalg.eigh(matrix.toarray())
        vector = vectors[:, -1]
    else:
        try:
            _, vectors = linalg.eigsh(matrix, k=1, which="LA", v0=np.ones(size), maxiter=max(10 * size, 10_000), tol=1e-12)
        except linalg.ArpackNoConvergence:
            raise G2SError(
                f"eigenvector centrality did not converge on a component of {size} nodes "
                "(ARPACK found no leading eigenvector); use another metric"
            ) from None
        vector = vectors[:, 0]
    vector = vector * (1.0 if vector.sum() >= 0 else -1.0)
    vector = np.abs(vector)  # the Perron vector is non-negative; drop rounding noise below zero
    return vector / np.linalg.norm(vector)


def eigenvector(graph: nx.Graph, weighted: bool = False) -> dict[Hashable, float]:
    """Eigenvector centrality: the leading eigenvector of the adjacency matrix of each component.

    ``A x = lambda_max x`` is solved per component (ARPACK's ``eigsh`` with a
    fixed start vector, or a dense solver for small components), signed
    positive and scaled to unit Euclidean norm within the component, which
    matches networkx on a connected graph. With ``weighted`` the edge weight
    is the connection strength; since surface-graph weights are lengths, the
    unweighted form is usually the meaningful one.

    Raises:
        G2SError: ARPACK did not converge.
    """
    arrays = _arrays(graph, weighted=weighted)
    n = arrays.n
    if n == 0:
        return {}
    count, labels = arrays.components()
    adjacency = arrays.adjacency()
    values = np.zeros(n)
    for members, block in _blocks(adjacency, labels, count):
        values[members] = 1.0 if block is None else _perron_vector(block)
    return arrays.dict(values)


def largest_eigenvalue(graph: nx.Graph, weighted: bool = False) -> float:
    """lambda_max of the (symmetric, non-negative) adjacency matrix: the largest over the components."""
    arrays = _arrays(graph, weighted=weighted)
    return _largest_eigenvalue(arrays.adjacency())


def _largest_eigenvalue(adjacency: sp.csr_array) -> float:
    size = adjacency.shape[0]
    if adjacency.nnz == 0:
        return 0.0
    if size <= _DENSE_EIGEN_LIMIT:
        return float(np.linalg.eigvalsh(adjacency.toarray())[-1])
    try:
        values = linalg.eigsh(adjacency, k=1, which="LA", v0=np.ones(size), maxiter=max(10 * size, 10_000), tol=1e-10,
                       return_eigenvectors=False)
    except linalg.ArpackNoConvergence:
        raise G2SError(
            f"the largest adjacency eigenvalue of a graph of {size} nodes did not converge (ARPACK); "
            "Katz centrality cannot check its attenuation bound: use a smaller attenuation or another metric"
        ) from None
    return float(values[0])


def katz(graph: nx.Graph, alpha: float, weighted: bool = False, normalized: bool = True) -> dict[Hashable, float]:
    """Katz centrality x = sum_{i>=1} alpha^i A^i 1 + 1, i.e. the solution of (I - alpha A) x = 1.

    The series converges only for ``0 < alpha < 1/lambda_max`` (lambda_max:
    largest eigenvalue of the adjacency matrix). The bound is checked first
    (the maximum weighted degree bounds lambda_max, so the eigenvalue is only
    computed when that cheap test fails). The system is block-diagonal by
    component, so one sparse LU solve (scipy ``spsolve``) solves each
    component independently. ``normalized`` scales x to unit Euclidean norm
    over the whole graph, as networkx does (beta = 1).

    Raises:
        G2SError: ``alpha`` is not below 1/lambda_max (the series diverges).
    """
    if not alpha > 0:
        raise G2SError(f"Katz attenuation must be > 0, got {alpha}")
    arrays = _arrays(graph, weighted=weighted)
    n = arrays.n
    if n == 0:
        return {}
    adjacency = arrays.adjacency()
    row_sums = np.asarray(adjacency.sum(axis=1)).ravel()
    if alpha * float(row_sums.max(initial=0.0)) >= 1.0:
        lambda_max = _largest_eigenvalue(adjacency)
        if lambda_max > 0 and alpha >= 1.0 / lambda_max * (1.0 - 1e-9):
            raise G2SError(
                f"Katz centrality does not converge for attenuation {alpha:g}: it must be below "
                f"1/lambda_max = {1.0 / lambda_max:.6g} (lambda_max = {lambda_max:.6g}, the largest "
                "eigenvalue of this graph's adjacency matrix)"
            )
    system = (sp.identity(n, format="csc") - alpha * adjacency.tocsc()).tocsc()
    x = np.atleast_1d(linalg.spsolve(system, np.ones(n)))
    if not np.all(np.isfinite(x)):
        raise G2SError(f"Katz centrality does not converge for attenuation {alpha:g} (singular system)")
    if normalized:
        x = x / np.linalg.norm(x)
    return arrays.dict(x)


def compute(
    graph: nx.Graph,
    metric: str,
    *,
    weighted: bool = False,
    normalized: bool = True,
    attenuation: float = 0.1,
) -> dict[Hashable, float]:
    """The named metric (one of :data:`METRICS`) of every node; ``attenuation`` is Katz's alpha."""
    if metric == "degree":
        return degree(graph, weighted=weighted, normalized=normalized)
    if metric == "betweenness":
        return betweenness(graph, weighted=weighted, normalized=normalized)
    if metric == "closeness":
        return closeness(graph, weighted=weighted)
    if metric == "eigenvector":
        return eigenvector(graph, weighted=weighted)
    if metric == "katz":
        return katz(graph, attenuation, weighted=weighted, normalized=normalized)
    raise ValueError(f"unknown metric {metric!r}; expected one of {', '.join(METRICS)}")


def components(graph: nx.Graph) -> list[list[Hashable]]:
    """Connected components as sorted node lists, ordered by their smallest node."""
    return sorted((sorted(c) for c in nx.connected_components(_undirected(graph))), key=lambda c: c[0])


__all__ = [
    "METRICS",
    "Metric",
    "betweenness",
    "closeness",
    "components",
    "compute",
    "degree",
    "edge_betweenness",
    "eigenvector",
    "graph_betweenness",
    "katz",
    "largest_eigenvalue",
    "tree_betweenness",
    "tree_closeness",
]


def edge_betweenness(graph: nx.Graph, normalized: bool = True) -> dict[tuple[Hashable, Hashable], float]:
    """Unweighted edge betweenness: the number of node pairs whose shortest paths cross each edge.

    On a forest the edge from a subtree of s nodes to the rest of its tree of
    N nodes is crossed by exactly ``s (N - s)`` pairs (one O(n) pass, the
    subtree sizes of :func:`tree_betweenness`); on a graph with cycles,
    Brandes' algorithm (``rustworkx.edge_betweenness_centrality``), above
    :data:`BRANDES_EXACT` nodes from sampled sources (igraph,
    :func:`_brandes_sources`). Normalised like networkx for undirected
    graphs: divided by n(n-1)/2. Keys are the edges as ``graph.edges`` lists
    them.
    """
    arrays = _arrays(graph, weighted=False)
    count, labels = arrays.components()
    if arrays.is_forest(count):
        rooted = _rooted(arrays, count, labels)
        parent = np.asarray(rooted.parent, dtype=np.int64)
        size = np.asarray(rooted.size, dtype=np.float64)
        # each edge joins a child (its lower end in the hanging) to its parent
        child = np.where(parent[arrays.v] == arrays.u, arrays.v, arrays.u)
        values = size[child] * (rooted.component_size[child] - size[child])
    else:
        sources = _brandes_sources(arrays.n)
        values = None if sources is None else _sampled_brandes(arrays, sources, weighted=False, edges=True)
        if values is None:
            result = rx.edge_betweenness_centrality(_rx_graph(arrays), normalized=False,
                                                     parallel_threshold=_ONE_THREAD)
            values = np.array([result[i] for i in range(len(arrays.u))], dtype=np.float64)
    n = arrays.n
    if normalized and n > 1:
        values = values / (n * (n - 1) / 2.0)
    index = {(arrays.nodes[a], arrays.nodes[b]): float(x) for a, b, x in zip(arrays.u.tolist(), arrays.v.tolist(), values)}
    return {(u, v): index[(u, v)] if (u, v) in index else index[(v, u)] for u, v in _undirected(graph).edges}
