"""A graph's nodes renumbered along a space-filling curve for the walking flow's kernel (the sampled split flows of
:mod:`g2s_plugins.traffic`).

Why. Each source of a walking flow is one Dijkstra search and two passes over
the nodes it settles, in the order it settles them: ring by ring round the
source. In the numbering a graph builder gives (a sampled graph's samples in
x-major order), the nodes of one neighbourhood lie far apart in the arrays
(a sample's neighbours across a column sit a column's length away), so the
kernel spends most of its time waiting for memory (docs/performance.md,
"the sampling route's two walking flows", samp45). Renumbered along the
Hilbert curve over the nodes in plan that a ``spread`` sample already draws
along (:func:`g2s_plugins.traffic.plan_order`), a node's neighbours lie a few
places from it: on the sampling route's 100k-polygon level the median gap
between the two ends of an edge falls from 366 to 4 places, and the kernel's
CPU a source by about a tenth (docs/performance.md, locality48).

Same bits. Only the arrays' layout changes: the kernel reads the renumbered
CSR arrays, takes the sources and values and writes its result in the
caller's numbering (``original``), breaks ties between equally near nodes by
the caller's index, and each renumbered row keeps its entries in their order,
so every node settles, and every sum is added, in the same order as on the
graph as numbered (``src/trees_module.cpp``, ``Renumbering``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from g2s_core.lazy import lazy_module

sp = lazy_module("scipy.sparse")


@dataclass(frozen=True)
class FlowLayout:
    """A CSR graph of n nodes and m stored edges renumbered: node v here is node ``original[v]`` of the graph.

    Attributes:
        indptr: (n + 1,) int32, the rows' starts.
        indices: (m,) int32, each entry's other end, renumbered.
        lengths: (m,) float64, each entry's length, m.
        original: (n,) int32, each node's row in the graph as numbered.
    """

    indptr: np.ndarray
    indices: np.ndarray
    lengths: np.ndarray
    original: np.ndarray


def renumbered(adjacency: sp.csr_array, order: np.ndarray) -> FlowLayout:
    """``adjacency`` (n, n) with its rows taken in ``order`` (n,) (every row once): row v of the result is row
    ``order[v]``, its entries in their order there, each pointing at its other end's place in ``order``. O(n + m)."""
    csr = sp.csr_array(adjacency)
    n = csr.shape[0]
    order = np.asarray(order, dtype=np.int64)
    place = np.empty(n, dtype=np.int64)
    place[order] = np.arange(n)
    degree = np.diff(csr.indptr).astype(np.int64)[order]
    indptr = np.zeros(n + 1, dtype=np.int64)
    np.cumsum(degree, out=indptr[1:])
    # each new entry's position among the old ones: its old row's start, then its place within the row
    taken = np.repeat(csr.indptr[order].astype(np.int64) - indptr[:-1], degree) + np.arange(indptr[-1])
    return FlowLayout(indptr.astype(np.int32), place[csr.indices[taken]].astype(np.int32),
                      np.ascontiguousarray(csr.data[taken], dtype=np.float64), order.astype(np.int32))
