"""The surface graph as scipy arrays, for the stages and analyses that search it as a whole.

Built once per graph object (cached while its node and edge counts are
unchanged): the ``spanner`` loop adder, the coverage selector and the area/flow
analyses all read the same arrays.
"""

from __future__ import annotations

import weakref
from collections.abc import Callable, Hashable, Iterable
from concurrent.futures import Future
from dataclasses import dataclass, field
from itertools import chain, repeat

import numpy as np

from g2s_core.lazy import lazy_module

sp = lazy_module("scipy.sparse")
nx = lazy_module("networkx")

MIN_LENGTH = 1e-12
"""Zero-length edges (coincident points) are stored with this length: scipy's
graph searches read a stored zero as no edge."""


@dataclass(frozen=True)
class SurfaceArrays:
    """A graph as arrays: node i is ``nodes[i]``.

    Attributes:
        nodes: (n,) the node ids, in graph order.
        index: node id -> row.
        adjacency: (n, n) symmetric CSR matrix of edge lengths, metres.
        area: (n,) float64 ``area`` attribute of each node, m² (0 when absent).
        derived: results computed from these arrays, kept with them (so they
            are dropped when the graph changes size), e.g. the walking flows
            of :func:`g2s_plugins.traffic.walking_flow`.
        begun: results of ``derived`` being computed on a thread of their own,
            under the same keys, until the first caller that wants one takes
            it (:func:`g2s_plugins.traffic.start_walking_flow`; each a
            :class:`g2s_plugins.traffic.BegunFlow`, whose ``taken`` it sets).
        graph: the graph the arrays were made from, while it lives (a weak
            reference; ``None`` when made without one): what a result derived
            from the nodes' attributes reads them from (the walking flow's
            :func:`g2s_plugins.traffic.flow_layout`).
    """

    nodes: list[Hashable]
    index: dict[Hashable, int]
    adjacency: sp.csr_array
    area: np.ndarray
    derived: dict[Hashable, np.ndarray] = field(default_factory=dict, compare=False, repr=False)
    begun: dict[Hashable, Future[np.ndarray]] = field(default_factory=dict, compare=False, repr=False)
    graph: Callable[[], nx.Graph | None] = field(default=lambda: None, compare=False, repr=False)

    @property
    def n(self) -> int:
        return len(self.nodes)

    def rows(self, nodes: Iterable[Hashable]) -> np.ndarray:
        """The rows of ``nodes``, as an int64 array."""
        # map over the dict's own look-up, no generator frame per node: the stages ask for 50-100k rows at a time
        return np.fromiter(map(self.index.__getitem__, nodes), dtype=np.int64)


_CACHE: weakref.WeakKeyDictionary[nx.Graph, tuple[tuple[int, int, bool], SurfaceArrays]] = weakref.WeakKeyDictionary()


def surface_arrays(graph: nx.Graph, weighted: bool = True) -> SurfaceArrays:
    """``graph`` indexed as arrays (cached per graph object while its size is unchanged: its node count and the
    sizes of its adjacency dicts, which every edge added or removed changes; a multigraph's edge count).

    With ``weighted=False`` every edge has length 1 (hop count).
    """
    # the sizes summed in a C loop: 2-3 ms on a 100k-polygon graph, whose arrays a map_analysis run looks up 8
    # times, where len(graph.edges) takes 11-28 ms (a Python generator over the nodes)
    size = len(graph.edges) if graph.is_multigraph() else sum(map(len, graph._adj.values()))
    signature = (graph.number_of_nodes(), size, weighted)
    cached = _CACHE.get(graph)
    if cached is not None and cached[0] == signature:
        return cached[1]
    nodes = list(graph.nodes)
    index = dict(zip(nodes, range(len(nodes))))
    n = len(nodes)
    if type(graph._adj) is dict and not graph.is_directed() and not graph.is_multigraph():
        u, v, w = _both_ways(graph, nodes, index)
    else:  # a view, a directed or a multigraph: each edge once from its edge view, then both ways
        u, v, w = _once(graph, index)
        u, v, w = np.concatenate([u, v]), np.concatenate([v, u]), np.concatenate([w, w])
    w = w if weighted else np.ones(len(w), dtype=np.float64)
    keep = u != v
    # the matrix is canonical (rows' columns sorted, one entry each) whatever order its entries come in
    adjacency = sp.csr_array((np.maximum(w[keep], MIN_LENGTH), (u[keep], v[keep])), shape=(n, n))
    area = np.fromiter(map(dict.get, map(graph._node.__getitem__, nodes), repeat("area"), repeat(0.0)), np.float64, n)
    arrays = SurfaceArrays(nodes, index, adjacency, area, graph=weakref.ref(graph))
    _CACHE[graph] = (signature, arrays)
    return arrays


def _both_ways(graph: nx.Graph, nodes: list[Hashable], index: dict[Hashable, int]) -> tuple[np.ndarray, ...]:
    """(2m,) rows ``u``, ``v`` and ``weight`` (1.0 when absent) of each edge of a plain undirected ``graph``, from
    both ends (a self-loop once): its adjacency dicts, which hold each edge's one dict at both ends, read by
    numpy's and map's C loops (an edge view's Python generator took 4 times as long on a 100k-polygon level)."""
    rows = list(map(graph._adj.__getitem__, nodes))
    u = np.repeat(np.arange(len(nodes)), np.fromiter(map(len, rows), np.int64, len(nodes)))
    v = np.fromiter(map(index.__getitem__, chain.from_iterable(rows)), np.int64, len(u))
    w = np.fromiter(map(dict.get, chain.from_iterable(map(dict.values, rows)), repeat("weight"), repeat(1.0)), np.float64, len(u))
    return u, v, w


def _once(graph: nx.Graph, index: dict[Hashable, int]) -> tuple[np.ndarray, ...]:
    """(m,) rows ``u``, ``v`` and ``weight`` (1.0 when absent) of each edge of ``graph``'s edge view."""
    m = len(graph.edges)
    # the edges' ends and lengths as three columns, each converted at once (not three numpy stores per edge)
    ends, lengths = [], []
    for a, b, length in graph.edges(data="weight", default=1.0):
        ends += (a, b)
        lengths.append(length)
    u, v = np.fromiter(map(index.__getitem__, ends), dtype=np.int64, count=2 * m).reshape(m, 2).T
    return u, v, np.fromiter(lengths, dtype=np.float64, count=m)
