"""Mehlhorn (1988) Steiner tree: Kou et al.'s bound from one multi-source Dijkstra, O(m log m + n log n) here.

After K. Mehlhorn, "A faster approximation algorithm for the Steiner problem
in graphs", Information Processing Letters 27(3):125-128, 1988:

1. one Dijkstra from all terminals at once (``scipy.sparse.csgraph.dijkstra``
   with ``min_only=True, return_predecessors=True``) gives every node v its
   nearest terminal s(v), the distance d(v) and a predecessor; the
   predecessors form a shortest-path forest whose trees are the terminals'
   Voronoi regions;
2. the auxiliary graph G1' over the terminals: every edge (u, v) of G with
   s(u) != s(v) proposes the edge (s(u), s(v)) with weight
   d(u) + w(u, v) + d(v); each terminal pair keeps its lightest proposal
   (vectorised with numpy, no Python loop over edges);
3. a minimum spanning tree of G1' (Mehlhorn shows it is also a minimum
   spanning tree of Kou et al.'s complete distance graph G1);
4. each chosen edge expanded into the path u -> s(u), the bridging edge
   (u, v) and the path v -> s(v), all read from the forest of step 1;
5. a minimum spanning tree of that union, then removal of non-terminal
   leaves until there is none (as in ``g2s_plugins.steiner.kou``).

Quality: the same bound as Kou et al., at most 2(1 - 1/l) times the optimum
for l leaves of an optimal tree. Running time O(m log m + n log n): the one
Dijkstra is O(m + n log n), Mehlhorn's bound for the whole algorithm, but here
the m candidate edges are sorted (the lightest proposal per terminal pair,
:func:`~g2s_plugins.steiner._paths.lightest_per_key`) and the spanning trees
of steps 3 and 5 sort their at most m edges (Kruskal's, in C++), O(m log m).

Determinism: the graph is converted to a CSR matrix in sorted node order and
the terminals are sorted, so the multi-source search is the same for the same
input. A terminal pair keeps the proposal that is smallest by
``(weight, u, v)``; spanning trees break ties by ``(weight, smaller end,
larger end)`` (see ``g2s_plugins.steiner._paths``).
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

import numpy as np

from g2s_core.lazy import lazy_module
from g2s_core.model import RunContext
from g2s_core.plugin import PluginParams, hookimpl

csgraph = lazy_module("scipy.sparse.csgraph")
_paths = lazy_module("g2s_plugins.steiner._paths")  # it imports scipy
nx = lazy_module("networkx")

NAME = "mehlhorn"


class Params(PluginParams):
    """This plugin takes no parameters."""


def mehlhorn_steiner_tree(graph: nx.Graph, terminals: Iterable[int]) -> nx.Graph:
    """An approximate minimum Steiner tree of ``graph`` joining ``terminals`` (Mehlhorn).

    Arguments, result and errors: the solvers' shared contract in
    :mod:`g2s_plugins.steiner._paths`.
    """
    return _paths.solve(graph, terminals, _mehlhorn)


def _mehlhorn(csr: _paths.CSRGraph, terms: np.ndarray) -> nx.Graph:
    k = terms.shape[0]
    distance, predecessor, source = csgraph.dijkstra(
        csr.matrix, directed=True, indices=terms, min_only=True, return_predecessors=True
    )
    # Edges joining two Voronoi regions (unreached nodes share source -9999, so never qualify).
    s_lo, s_hi = source[csr.lo], source[csr.hi]
    crossing = s_lo != s_hi
    u, v = csr.lo[crossing], csr.hi[crossing]
    cost = distance[u] + csr.weight[crossing] + distance[v]
    ta = np.searchsorted(terms, np.minimum(s_lo[crossing], s_hi[crossing]))
    tb = np.searchsorted(terms, np.maximum(s_lo[crossing], s_hi[crossing]))

    # Lightest proposal per terminal pair; equal costs go to the first, i.e. the smallest
    # (u, v), since the CSR edge list is in (u, v) order.
    best = _paths.lightest_per_key(ta * k + tb, cost)
    ta, tb, cost, u, v = ta[best], tb[best], cost[best], u[best], v[best]

    chosen = _paths.spanning_tree(k, ta, tb, cost)
    if chosen.shape[0] != k - 1:
        raise ValueError("the terminals are not all connected")
    bridge_u, bridge_v = u[chosen], v[chosen]
    child, parent = _paths.walk_to_sources(predecessor, np.concatenate([bridge_u, bridge_v]))
    lo, hi = _paths.unique_edges(np.concatenate([child, bridge_u]), np.concatenate([parent, bridge_v]))
    return _paths.finish_tree(csr, lo, hi, terms)


@hookimpl
def g2s_steiner_tree(graph: nx.Graph, terminals: Sequence[int], params: Params, context: RunContext) -> nx.Graph:
    """SteinerSolver: Mehlhorn's tree over ``graph`` joining ``terminals``."""
    return mehlhorn_steiner_tree(graph, terminals)
