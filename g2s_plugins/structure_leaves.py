"""Structure leaves that no terminal needs: a cover's waypoints at the ends of its paths, dropped where the cover holds.

Algorithm 4 never removes a leaf of the tree. A terminal selector that
covers the level (``coverage``) adds *waypoints*, the farthest uncovered
node and its path back, which simplification may remove like any node on a
path (``Terminals.waypoints``); but a waypoint at the end of its path is a
leaf of the Steiner forest, and Algorithm 4 keeps it. :func:`pruned` drops
such leaves after Algorithm 4 where what they were added for still holds
without them.

The structure *stands for* the forest nodes on the forest paths between its
kept nodes (:func:`represented`): a forest node whose forest subtree holds
a kept node or the end of a loop edge (the loop paths, which the loop pass
of :mod:`g2s_core.simplify` shortens, stay whole). Dropping a leaf B takes
its *branch* out of that set: B and its forest ancestors up to the first
that still stands for something. B goes when

1. it is kept, no terminal (``fixed``: the selector's terminals and the
   nodes the heat guarantee restored), no root, has no kept node below it
   in its forest subtree and no loop edge (of the forest or added);
2. with ``max_step`` set, its walking-flow percentile differs from that of
   its nearest kept ancestor A (the node its edge joins) by no more than
   ``max_step``: the traffic step of Algorithm 5's rule, for the chain
   A -> B that has no C;
3. every node of the initial graph within ``radius`` metres (along the
   graph) of the nodes the structure stands for stays within ``radius``,
   and every one within ``near`` stays within ``near``: the cover's radius
   and the distance at which the traffic measure counts a walk as passing
   the structure (:func:`g2s_plugins.evaluation.evaluate`'s
   ``off_distance``).

Candidates are taken by ascending node id; when B goes, A is examined in
turn (it may have become such a leaf). Test 3 is local: only the nodes
whose nearest represented node lay in B's branch (its cell of the graph's
Voronoi partition) can move, and their new distances come from a Dijkstra
(``scipy.sparse.csgraph``) seeded at the cell's boundary. The line of sight asks nothing: no edge is
added.

Complexity: O(n) for the subtree counts (n forest nodes), one multi-source
Dijkstra over the initial graph, O(m + N log N), then per candidate its
branch and a Dijkstra over its cell, O(c log c) with c the cell's nodes and
edges.
"""

from __future__ import annotations

import heapq
from collections.abc import Hashable

import networkx as nx
import numpy as np
from scipy import sparse
from scipy.sparse import csgraph

from g2s_core.simplify import ForestArrays, forest_arrays
from g2s_plugins.traffic import SurfaceArrays


def represented(parent: np.ndarray, depth: np.ndarray, anchors: np.ndarray) -> np.ndarray:
    """(n,) bool: the forest nodes whose subtree (``parent`` (n,) rows, -1 for a root; ``depth`` (n,)) holds one of
    ``anchors`` (n,) bool. Bottom-up, a level of depth at a time: O(n + depth levels)."""
    holds = anchors.copy()
    order = np.argsort(-depth, kind="stable")
    levels = np.split(order, np.flatnonzero(np.diff(depth[order])) + 1)
    for level in levels:  # deepest first: a level's answers are final before its parents' are read
        up = level[holds[level] & (parent[level] >= 0)]
        holds[parent[up]] = True
    return holds


def standing_for(forest: nx.DiGraph, structure: nx.Graph) -> list[Hashable]:
    """The nodes of a rooted ``forest`` (:mod:`g2s_core.rooted`) that its simplified ``structure`` stands for
    (:func:`represented`, anchored at the structure's nodes and the forest's loop ends), in the forest's order: the
    whole forest unless :func:`pruned` dropped leaves. O(n log n)."""
    arrays = forest_arrays(forest)
    anchors = np.isin(arrays.ids, np.fromiter(structure, np.int64, structure.number_of_nodes()))
    anchors[arrays.loops.ravel()] = True
    holds = represented(arrays.parent, arrays.depth, anchors)
    return arrays.ids[holds].tolist()


def loop_ends(forest: ForestArrays, added: np.ndarray, loop: np.ndarray, kept: np.ndarray) -> np.ndarray:
    """(n,) bool: the rows at an end of a forest loop edge or of a loop edge the simplification added between two
    kept nodes."""
    ends = np.zeros(len(forest.ids), dtype=bool)
    ends[forest.loops.ravel()] = True
    made = added[loop]
    ends[made[kept[made].all(axis=1)].ravel()] = True
    return ends


def pruned(
    forest: ForestArrays, kept: np.ndarray, added: np.ndarray, loop: np.ndarray, arrays: SurfaceArrays,
    radius: float, near: float, rank: np.ndarray | None = None, max_step: float | None = None,
) -> np.ndarray:
    """``kept`` (n,) bool, Algorithm 4's answer for ``forest`` (with ``added``/``loop`` its added edges), less the
    leaves the module docs drop; ``arrays`` the initial graph the forest's ids are nodes of, ``rank`` (n,) each
    row's walking-flow percentile (NaN: none, not compared) for ``max_step``."""
    kept = kept.copy()
    parent, n = forest.parent, len(forest.ids)
    looped = loop_ends(forest, added, loop, kept)
    holds = represented(parent, forest.depth, kept | looped)
    # per node: itself an anchor (kept or a loop end) plus its forest children that stand for something
    count = (kept | looped).astype(np.int64)
    up = np.flatnonzero(holds & (parent >= 0))
    np.add.at(count, parent[up], 1)
    root = np.zeros(n, dtype=bool)
    root[forest.roots] = True
    held = forest.fixed | root | looped

    rows = arrays.rows(forest.ids.tolist())
    adjacency = arrays.adjacency
    distance, _, nearest = csgraph.dijkstra(adjacency, directed=False, indices=rows[holds], min_only=True,
                                            return_predecessors=True)
    owner = np.full(arrays.n, -1, dtype=np.int64)  # the forest row of each graph node's nearest represented node
    row_of = np.full(arrays.n, -1, dtype=np.int64)
    row_of[rows] = np.arange(n)
    reached = nearest >= 0
    owner[reached] = row_of[nearest[reached]]
    members: dict[int, list[int]] = {}  # each forest row's cell, with stale entries (nodes since moved to another)
    by_owner = np.argsort(owner, kind="stable")
    starts = np.searchsorted(owner[by_owner], np.arange(n + 1))
    for row in range(n):
        members[row] = by_owner[starts[row]:starts[row + 1]].tolist()

    def leaf(b: int) -> bool:
        return bool(kept[b] and not held[b] and count[b] == 1)

    pending = sorted((int(forest.ids[b]), int(b)) for b in np.flatnonzero(kept & ~held & (count == 1)).tolist())
    heapq.heapify(pending)
    while pending:
        _, b = heapq.heappop(pending)
        if not leaf(b):
            continue
        branch, a = [b], int(parent[b])
        while a >= 0 and count[a] == 1 and not kept[a]:  # a stands for b's branch alone
            branch.append(a)
            a = int(parent[a])
        above = a  # the first ancestor still standing for something: a kept node or a loop path's
        while above >= 0 and not kept[above]:
            above = int(parent[above])
        if max_step is not None and rank is not None and above >= 0:
            step = abs(rank[b] - rank[above])
            if step > max_step:  # NaN is not compared
                continue
        cell = np.array(sorted({node for row in branch for node in members[row] if owner[node] == row}), np.int64)
        moved = _moved(cell, owner, distance, adjacency, radius, near)
        if moved is None:
            continue
        new_distance, new_owner = moved
        distance[cell], owner[cell] = new_distance, new_owner
        for node, row in zip(cell.tolist(), new_owner.tolist()):
            members[row].append(node)
        kept[b] = False
        count[branch] = 0
        if a >= 0:
            count[a] -= 1
            if leaf(a):
                heapq.heappush(pending, (int(forest.ids[a]), a))
    return kept


def _moved(
    cell: np.ndarray, owner: np.ndarray, distance: np.ndarray, adjacency: sparse.csr_array, radius: float, near: float,
) -> tuple[np.ndarray, np.ndarray] | None:
    """The distances and nearest represented nodes (forest rows) of the graph nodes of ``cell`` (those whose nearest
    represented node lies in a branch) once the branch stands for nothing; ``None`` when one of them would leave
    ``radius`` or ``near``. One multi-source Dijkstra (``csgraph.dijkstra``) over the cell's subgraph of
    ``adjacency`` and one source node per represented node next to it, joined to the cell's nodes by their
    distance (which stays) plus the edge into the cell."""
    c = len(cell)
    inside = np.full(adjacency.shape[0], -1, dtype=np.int64)
    inside[cell] = np.arange(c)
    edges = adjacency[cell].tocoo()
    into, other, length = edges.row, edges.col, edges.data
    within = inside[other] >= 0
    seeds = ~within & (owner[other] >= 0)
    origins, origin_of = np.unique(owner[other[seeds]], return_inverse=True)
    rows = np.concatenate([into[within], c + origin_of.reshape(-1)])
    cols = np.concatenate([inside[other[within]], into[seeds]])
    weights = np.concatenate([length[within], distance[other[seeds]] + length[seeds]])
    order = np.lexsort((weights, cols, rows))  # the shortest of parallel seed edges, which a sparse matrix would sum
    first = np.ones(len(order), dtype=bool)
    first[1:] = (np.diff(rows[order]) != 0) | (np.diff(cols[order]) != 0)
    order = order[first]
    graph = sparse.csr_array((weights[order], (rows[order], cols[order])), shape=(c + len(origins),) * 2)
    reach, _, source = csgraph.dijkstra(graph, directed=True, indices=np.arange(c, c + len(origins)), min_only=True,
                                       return_predecessors=True)
    best, nearest = reach[:c], np.full(c, -1, dtype=np.int64)
    seeded = source[:c] >= c
    nearest[seeded] = origins[source[:c][seeded] - c]
    before = distance[cell]
    if np.any((before <= radius) & ~(best <= radius)) or np.any((before <= near) & ~(best <= near)):
        return None
    return best, nearest
