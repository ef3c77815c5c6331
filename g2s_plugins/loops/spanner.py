"""Bounded redundancy (a greedy spanner): loops of the walkable graph added back to the Steiner forest.

A tree loses every loop of the level, so two places side by side across a
loop look far apart along the structure. This step adds back the shortest
initial-graph path between two structure nodes a, b whenever

    d_S(a, b) > stretch * L(a, b)   and   d_S(a, b) - L(a, b) > min_gain

(d_S: distance along the current structure, L: the path's length),
greedily, shortest path first, re-checking d_S after every addition: a
greedy spanner (I. Althoefer, G. Das, D. Dobkin, D. Joseph and J. Soares,
"On sparse spanners of weighted graphs", Discrete & Computational Geometry
9(1):81-100, 1993) over the structure's candidate pairs. ``stretch = inf`` keeps the
paper's tree (as does a config without a ``loops:`` section). ``min_gain``
keeps the small loops around pillars out.

Candidate pairs: each initial-graph node is assigned to its nearest
structure node (Voronoi cells along the graph, one multi-source Dijkstra,
as in Mehlhorn's Steiner approximation); every graph edge (x, y) whose ends
lie in different cells gives the pair (cell(x), cell(y)) with the path
cell(x) ~> x - y ~> cell(y); the shortest such path is kept per pair. So
there are at most m candidates, whatever the level's size (the bound used
on big levels), and each candidate path leaves the structure only once.

Complexity (n nodes and m edges of the graph, s structure nodes, q
candidate pairs <= m, v candidates that violate the bound on the tree):
O(m + n log n) for the cells, O(q log q) to sort, O((s + q) log s) for the
tree distances of all candidates at once (lowest common ancestors by binary
lifting), then, once a path has been added, one Dijkstra on the structure
bounded by ``max(stretch L, L + min_gain)`` per remaining violator, which
visits only the structure nodes within that distance: O(v b log b) for v
violators and b nodes in such a ball, independent of the level's size. That
loop runs in C++ (``g2s_plugins._trees.greedy_loops``, src/trees_module.cpp).
"""

from __future__ import annotations

import itertools
import math

import numpy as np
from pydantic import Field

from g2s_core.lazy import lazy_module
from g2s_core.model import RunContext, graph_of
from g2s_core.plugin import hookimpl
from g2s_plugins import _trees, heat_guarantee
from g2s_plugins._surface import HeatFlowParams
from g2s_plugins.surface_arrays import MIN_LENGTH, SurfaceArrays, surface_arrays

sp, csgraph = lazy_module("scipy.sparse"), lazy_module("scipy.sparse.csgraph")
rooted = lazy_module("g2s_core.rooted")  # it imports scipy too
nx = lazy_module("networkx")

NAME = "spanner"

HEAT_HEADROOM = 0.03
"""Default ``heat_headroom``: on the platform towers of ``benchmarks/level_kinds.py`` (seeds 0-2, the levels whose
looped forest read under the target) 0.01 / 0.02 / 0.03 / 0.04 / 0.06 left 37.3-40.1 / 35.7-38.5 / 35.0-37.3 /
35.0-37.0 / 35.2-36.7 % of the samples in the structure at rho 0.910-0.918 (docs/analysis_quality.md, "Spurs where
the heat map ranks worst"): less headroom leaves the guarantee to restore more nodes, more adds spurs for little."""


class Params(HeatFlowParams):
    """When a loop path is worth adding, and the heat map's target the looped forest must be able to meet."""

    stretch: float = Field(1.5, ge=1, description="add a path when the structure is more than this many times longer between its ends")
    min_gain: float = Field(3.0, ge=0, description="and the structure is longer by more than this, metres")
    min_heat_rho: float | None = Field(
        None, ge=-1, le=1, description="when the heat map of the looped forest, every node kept, ranks the nodes under "
        "this (plus the sampled flow's margin) plus heat_headroom against walking flow, join the nodes it ranks worst "
        "to it by their shortest paths until it reaches that (g2s_plugins/heat_guarantee.py, spurs); set as the "
        "simplification's min_heat_rho; null: no such paths"
    )
    heat_headroom: float = Field(
        HEAT_HEADROOM, ge=0, le=1, description="rho over that target under which the paths are added and to which they "
        "lift the looped forest's heat map, so that simplification can remove nodes and still meet it"
    )


@hookimpl
def g2s_add_loops(graph: nx.Graph, forest: nx.Graph, params: Params, context: RunContext) -> nx.Graph:
    """LoopAdder: greedy spanner paths between the forest's nodes (Althoefer et al. 1993), then, with
    ``min_heat_rho``, the heat guarantee's spurs (:func:`g2s_plugins.heat_guarantee.spurs`)."""
    looped = add_loops(graph, forest, params.stretch, params.min_gain)
    if params.min_heat_rho is None:
        return looped
    paths = heat_guarantee.spurs(graph, looped, params.min_heat_rho, params.heat_headroom, params.heat_sources,
                                 params.heat_ties, params.heat_scaling, params.heat_sampling)
    return with_paths(looped, paths) if paths else looped


def add_loops(graph: nx.Graph, structure: nx.Graph, stretch: float, min_gain: float) -> nx.Graph:
    """``structure`` (a forest whose edges are edges of ``graph``) with loop paths added.

    Args:
        graph: the initial graph, edges with ``weight`` (metres).
        structure: the Steiner forest (its edges measured by their ``weight`` in ``graph``).
        stretch: >= 1; ``inf`` returns ``structure`` itself.
        min_gain: metres a path must save along the structure to be added.

    Returns:
        A new graph (or ``structure`` when nothing is added) with the added
        paths' nodes and edges; a new graph's nodes and edges carry no
        attributes (the pipeline copies ``graph``'s, see
        :func:`g2s_core.hookspecs.g2s_add_loops`).
    """
    if math.isinf(stretch) or nx.is_empty(structure):
        return structure
    arrays = surface_arrays(graph)
    ids = np.array(sorted(structure), dtype=np.int64)
    rows = arrays.rows(ids.tolist())
    distance, predecessor, cell = csgraph.dijkstra(
        arrays.adjacency, directed=False, indices=rows, min_only=True, return_predecessors=True
    )
    ends = rows[np.column_stack(rooted.components(structure, ids)[:2])]  # (e, 2) rows of its edges' ends, in no set order
    stored = np.asarray(arrays.adjacency[ends[:, 0], ends[:, 1]]).ravel()  # their lengths as the arrays hold them
    pairs, paths = _candidates(arrays, structure, ends, distance, cell)
    if len(pairs) == 0:
        return structure
    along_tree = _tree_distances(arrays, structure, ends, stored, pairs)
    bound = np.maximum(stretch * paths, paths + min_gain)
    violating = np.flatnonzero(along_tree > bound)  # candidates are sorted by path length
    if violating.size == 0:
        return structure
    # the structure's edges (the graph's, with its lengths) both ways, then the graph's, for the greedy loop
    lengths = np.tile(_lengths(arrays, graph, ends[:, 0], ends[:, 1], stored), 2)
    along = sp.csr_array((lengths, (np.concatenate([ends[:, 0], ends[:, 1]]), np.concatenate([ends[:, 1], ends[:, 0]]))),
                         shape=(arrays.n, arrays.n))
    adjacency = arrays.adjacency
    tails = np.repeat(np.arange(arrays.n), np.diff(adjacency.indptr))
    a, b, x, y = (np.ascontiguousarray(column) for column in pairs[violating].T)
    _, rows_of_paths, offsets = _trees.greedy_loops(
        along.indptr.astype(np.int32), along.indices.astype(np.int32), along.data, adjacency.indptr.astype(np.int32),
        adjacency.indices.astype(np.int32), _lengths(arrays, graph, tails, adjacency.indices, adjacency.data),
        predecessor.astype(np.int32), a, b, x, y, bound[violating],
    )
    on_paths = list(map(arrays.nodes.__getitem__, rows_of_paths.tolist()))
    return with_paths(structure, [on_paths[start:end] for start, end in itertools.pairwise(offsets.tolist())])


def with_paths(structure: nx.Graph, paths: list[list[int]]) -> nx.Graph:
    """A new graph: ``structure``'s nodes and edges, then every path's nodes, then every path's edges (the insertion
    order of adding them path by path), without attributes: the pipeline copies the graph's onto them all at once."""
    nodes = itertools.chain(structure, (node for path in paths for node in path))
    edges = itertools.chain(structure.edges, ((u, v) for path in paths for u, v in zip(path, path[1:])))
    return graph_of(nx.Graph(**structure.graph), {node: {} for node in nodes}, ((u, v, {}) for u, v in edges))


def _candidates(
    arrays: SurfaceArrays, structure: nx.Graph, ends: np.ndarray, distance: np.ndarray, cell: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """(q, 4) rows (a, b, x, y) and (q,) path lengths, shortest first, one per cell pair."""
    upper = sp.triu(arrays.adjacency, k=1).tocoo()
    x, y, w = upper.row.astype(np.int64), upper.col.astype(np.int64), upper.data
    ok = np.isfinite(distance[x]) & np.isfinite(distance[y]) & (cell[x] != cell[y])
    x, y, w = x[ok], y[ok], w[ok]
    a, b = cell[x].astype(np.int64), cell[y].astype(np.int64)
    in_structure = np.zeros(arrays.n, dtype=bool)
    in_structure[arrays.rows(structure)] = True
    # an edge of the structure itself joins two cells but is no shortcut
    tree_edge = in_structure[x] & in_structure[y]
    if tree_edge.any():
        key = np.minimum(x, y) * arrays.n + np.maximum(x, y)
        tree_edge[tree_edge] = np.isin(key[tree_edge], ends.min(axis=1) * arrays.n + ends.max(axis=1))
    x, y, w, a, b = x[~tree_edge], y[~tree_edge], w[~tree_edge], a[~tree_edge], b[~tree_edge]
    length = distance[x] + w + distance[y]
    swap = a > b
    a, b, x, y = np.where(swap, b, a), np.where(swap, a, b), np.where(swap, y, x), np.where(swap, x, y)
    order = np.lexsort((y, x, b, a, length))
    a, b, x, y, length = a[order], b[order], x[order], y[order], length[order]
    _, first = np.unique(a * arrays.n + b, return_index=True)
    first = np.sort(first)  # keeps the shortest-first order
    return np.column_stack([a, b, x, y])[first], length[first]


def _tree_distances(
    arrays: SurfaceArrays, forest: nx.Graph, edge_rows: np.ndarray, lengths: np.ndarray, pairs: np.ndarray
) -> np.ndarray:
    """Distance along ``forest`` (its edges' rows ``edge_rows``, their ``lengths``) between the ends of each pair
    (inf across trees), by binary lifting."""
    n = arrays.n
    tree = sp.csr_array(
        (np.concatenate([lengths, lengths]), (np.concatenate(edge_rows.T[::-1]), np.concatenate(edge_rows.T))), shape=(n, n)
    )
    _, labels = csgraph.connected_components(tree, directed=False)
    members = arrays.rows(forest)
    firsts = members[np.unique(labels[members], return_index=True)[1]]
    # from the first node of every tree: each node's parent and its distance (metres, hops) from that node; a
    # tree's paths are unique, so Dijkstra sums the lengths root first, parent by parent
    metres, parent, _ = csgraph.dijkstra(tree, directed=False, indices=firsts, min_only=True, return_predecessors=True)
    hops = csgraph.dijkstra(tree, directed=False, indices=firsts, min_only=True, unweighted=True)
    reached = np.isfinite(metres)  # not the nodes of no tree
    metres, hops, parent = np.where(reached, metres, 0.0), np.where(reached, hops, 0).astype(np.int64), parent.astype(np.int64)
    ancestors = [np.where(parent >= 0, parent, np.arange(n))]
    while (1 << len(ancestors)) <= max(int(hops.max()), 1):
        ancestors.append(ancestors[-1][ancestors[-1]])
    a, b = pairs[:, 0].copy(), pairs[:, 1].copy()
    deeper = hops[a] < hops[b]
    a, b = np.where(deeper, b, a), np.where(deeper, a, b)
    lift = hops[a] - hops[b]
    for k, table in enumerate(ancestors):
        step = ((lift >> k) & 1).astype(bool)
        a[step] = table[a[step]]
    for table in reversed(ancestors):
        differ = table[a] != table[b]
        a[differ], b[differ] = table[a[differ]], table[b[differ]]
    lca = np.where(a == b, a, ancestors[0][a])
    result = metres[pairs[:, 0]] + metres[pairs[:, 1]] - 2 * metres[lca]
    return np.where(labels[pairs[:, 0]] == labels[pairs[:, 1]], result, np.inf)


def _lengths(arrays: SurfaceArrays, graph: nx.Graph, tails: np.ndarray, heads: np.ndarray, stored: np.ndarray) -> np.ndarray:
    """(e,) the ``weight`` in ``graph`` of the edges ``tails`` - ``heads`` (rows of ``arrays``, (e,) each) whose
    lengths the arrays hold as ``stored``: those, but for a length the arrays store as
    :data:`~g2s_plugins.surface_arrays.MIN_LENGTH` or less (a zero, a negative or a tiny one), read again."""
    lengths = np.array(stored, dtype=np.float64)
    odd = np.flatnonzero(~(lengths > MIN_LENGTH))
    lengths[odd] = [graph._adj[arrays.nodes[p]][arrays.nodes[q]]["weight"] for p, q in zip(tails[odd].tolist(), heads[odd].tolist())]
    return lengths
