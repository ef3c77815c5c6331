"""Kou, Markowsky & Berman (1981) Steiner tree: MST of the terminals' metric closure, expanded.

This is the solver of the paper's Algorithm 2 ("Compute Steiner Tree",
structural-tree-extraction.tex, after L. Kou, G. Markowsky and L. Berman,
"A fast algorithm for Steiner trees", Acta Informatica 15(2):141-145, 1981):

1. the metric closure over the terminals: one Dijkstra per terminal
   (``scipy.sparse.csgraph.dijkstra`` with predecessors), giving the complete
   graph G1 whose edge (s, t) weighs the shortest-path distance d(s, t);
2. a minimum spanning tree T1 of G1 (dense Prim, O(|S|^2));
3. G_s: every edge of T1 replaced by its shortest path in G;
4. a minimum spanning tree T_s of G_s;
5. removal of non-terminal leaves, repeated until there is none.

Step 5 differs from the paper's pseudocode, which only removes isolated
(degree 0) nodes: the MST of step 4 can drop a path edge and leave a branch
that ends in a non-terminal node. Such a dead end joins no terminal, so it
only adds weight and spurious corridors. (Kou et al.'s own step 5 does the
same: it deletes edges until every leaf belongs to the given set S, which
they call the "Steiner points", i.e. the terminals.)

Quality: the tree weighs at most 2(1 - 1/l) times the optimum, l being the
number of leaves of an optimal tree. Running time O(|S| (m + n log n)) for
|S| terminals, n nodes and m edges (the |S| Dijkstras dominate; the closure
MST adds O(|S|^2)). Memory is bounded: when |S| x n distances would not fit
in the working budget the closure is computed in blocks of terminals and the
few sources the tree needs are searched again for their paths.

Determinism: the graph is converted to a CSR matrix in sorted node order,
terminals are sorted and de-duplicated, closure entry (s, t) is always taken
from the search of the smaller terminal, and both spanning trees break ties by
``(weight, smaller index, larger index)``; see ``g2s_plugins.steiner._paths``.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence

import numpy as np

from g2s_core.lazy import lazy_module
from g2s_core.model import RunContext
from g2s_core.plugin import PluginParams, hookimpl

csgraph = lazy_module("scipy.sparse.csgraph")
_paths = lazy_module("g2s_plugins.steiner._paths")  # it imports scipy
nx = lazy_module("networkx")

NAME = "kou"

DISTANCE_BUDGET = 1 << 24
"""Most distances (terminals x nodes) held at once: 16 Mi entries, 128 MiB of float64
(plus 64 MiB of int32 predecessors when the closure is computed in one pass)."""

SLOW_COST = 2e9
"""Kou's cost, terminals x (edges + nodes log2 nodes), from which a run is warned before the metric closure: at the
10-50 ns per unit measured on sampled levels (docs/steiner.md, "When kou is slow") 20 s to 2 minutes, and minutes
beyond. Every kou run of the presets on the sample levels and shared pieces stays under 8e8 (the most:
map_piece_sampling on a 400-room dungeon, 7.6e8, 25 s); a map-piece preset on a whole level with a 0.1 m agent
reached 2.2e10 in its largest area (688 s)."""

NS_PER_UNIT = (10.0, 50.0)
"""Nanoseconds per unit of :data:`SLOW_COST`'s measure, fastest and slowest measured (docs/steiner.md)."""


class Params(PluginParams):
    """This plugin takes no parameters."""


def kou_steiner_tree(graph: nx.Graph, terminals: Iterable[int]) -> nx.Graph:
    """An approximate minimum Steiner tree of ``graph`` joining ``terminals`` (Kou et al.).

    Arguments, result and errors: the solvers' shared contract in
    :mod:`g2s_plugins.steiner._paths`.
    """
    return _paths.solve(graph, terminals, _kou)


def _kou(csr: _paths.CSRGraph, terms: np.ndarray) -> nx.Graph:
    k = terms.shape[0]
    rows_per_search = max(1, DISTANCE_BUDGET // max(csr.n, 1))
    predecessors = None
    if k <= rows_per_search:
        distances, predecessors = csgraph.dijkstra(csr.matrix, directed=True, indices=terms, return_predecessors=True)
        closure = distances[:, terms]
    else:
        closure = np.empty((k, k), dtype=np.float64)
        for start in range(0, k, rows_per_search):
            block = terms[start : start + rows_per_search]
            closure[start : start + block.shape[0]] = csgraph.dijkstra(csr.matrix, directed=True, indices=block)[:, terms]

    # d(s, t) for s < t from the search of s, mirrored: an exactly symmetric G1.
    upper = np.triu(closure, 1)
    a, b = _paths.dense_spanning_tree(upper + upper.T)

    # Each closure-MST edge (a, b) becomes the shortest path found by the search from a.
    if predecessors is not None:
        child, parent = _paths.walk_to_sources(predecessors, terms[b], rows=a)
    else:
        child, parent = _walk_in_blocks(csr, terms, a, b, rows_per_search)
    lo, hi = _paths.unique_edges(child, parent)
    return _paths.finish_tree(csr, lo, hi, terms)


def _walk_in_blocks(
    csr: _paths.CSRGraph, terms: np.ndarray, a: np.ndarray, b: np.ndarray, rows_per_search: int
) -> tuple[np.ndarray, np.ndarray]:
    """Path edges of the closure-MST edges ``(a, b)``, searching again from the sources ``a`` in blocks."""
    sources = _paths.distinct(a)
    children, parents = [], []
    for start in range(0, sources.shape[0], rows_per_search):
        block = sources[start : start + rows_per_search]
        _, predecessors = csgraph.dijkstra(csr.matrix, directed=True, indices=terms[block], return_predecessors=True)
        mine = np.isin(a, block)
        rows = np.searchsorted(block, a[mine])
        child, parent = _paths.walk_to_sources(predecessors, terms[b[mine]], rows=rows)
        children.append(child)
        parents.append(parent)
    return np.concatenate(children), np.concatenate(parents)


def slow_closure_warning(terminals: int, nodes: int, edges: int) -> str | None:
    """The warning for a metric closure of ``terminals`` searches over a graph of ``nodes`` and ``edges`` that
    predicts 20 s or more (cost at least :data:`SLOW_COST`), naming the counts and what to use instead;
    ``None`` below that."""
    cost = terminals * (edges + nodes * math.log2(max(nodes, 2)))
    if cost < SLOW_COST:
        return None
    fast, slow = (f"{m:.0f}" if m >= 1 else f"{m:.1f}" for m in (cost * ns * 1e-9 / 60.0 for ns in NS_PER_UNIT))
    return (
        f"steiner: kou searches the graph once per terminal: {terminals:,} terminals on {nodes:,} nodes and "
        f"{edges:,} edges predict about {fast}-{slow} min (docs/steiner.md); the mehlhorn solver gives a "
        "tree of the same approximation bound in one search (steiner: {plugin: mehlhorn}); for a whole level "
        "rather than a map piece, the map_analysis preset is made for it"
    )


@hookimpl
def g2s_steiner_tree(graph: nx.Graph, terminals: Sequence[int], params: Params, context: RunContext) -> nx.Graph:
    """SteinerSolver: Kou et al.'s tree over ``graph`` joining ``terminals``; warns first when it will be slow."""
    if warning := slow_closure_warning(len(set(terminals)), graph.number_of_nodes(), graph.number_of_edges()):
        context.warn(warning)
    return kou_steiner_tree(graph, terminals)
