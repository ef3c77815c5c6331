"""Walking flow across a way's cross-section: the trips that pass a section of a way, whichever lane they take.

The walking flow of :mod:`g2s_plugins.traffic` counts the trips through one
node (a navmesh polygon, a surface sample). Where a way is split into lanes
side by side (the gaps of a gate line, the ramps of an escalator bank) each
lane carries a share of the way's trips, so a way everyone walks can read
colder than a corridor that carries fewer (docs/analysis_quality.md,
"Parallel lanes in the heat map"). Here a node's value is the pair weight
of the trips that cross a section of the way through it instead:

1. **The way's axis** (:func:`walking_trips`, :func:`principal_axes`): each
   shortest-path tree of the walking flow's sources (the same sample,
   stratified alike: the smallest areas walked exactly beside the draws,
   their trees on their own areas, so that an area no draw falls on has
   its trips too: :func:`g2s_plugins.traffic.stratified_sources`; ``ties:
   first``) sends the pair weight ``f_s A_w`` (f_s: the source's factor,
   A_w: the weight of w's subtree, w included) along the edge from w's
   predecessor to w. Summed over the sources that is the edge's load; a
   node's orientation tensor sums its edges' loads times ``u u^T`` (u: the
   edge's unit direction in plan), and the axis is the tensor's principal
   eigenvector (the orientation tensor of directional statistics: N. I.
   Fisher, T. Lewis and B. J. J. Embleton, Statistical Analysis of Spherical
   Data, Cambridge University Press, 1987, section 3.2.4). The section is
   the line through the node square to its axis, in plan.
2. **The section's edges**. ``across: section`` (:func:`section_edges`): the
   nodes with an area whose centre lies within their half-size
   (``sqrt(area) / 2``, a square's: exact for a grid of samples) of the line
   and within ``height`` of the node's tangent plane (its own floor; on a
   slope the section follows the slope) each cover their centre plus or
   minus their half-size along it; the run of covered stretches that holds
   the node, stretches at most ``gap`` apart joined (the barriers of a gate
   line, the balustrades between escalators, with the agent's clearance
   round them) and at most ``reach`` either side, is the section, and its
   edges are the graph edges that cross the line within it.
   ``across: lanes`` (:func:`lane_edges`, the navmesh route): Detour's
   raycast along the line finds where the node's floor ends either side;
   floor narrower than ``lane_width`` is a lane (else the node keeps its own
   flow); the next lane either side is the nearest crossing edge beyond the
   last lane's end, when its own floor (raycast again) is a lane too and
   starts at most ``gap`` beyond; the section's edges are those crossing the
   line within the lanes.
3. **The trips across** (:func:`trips_across`): a trip that crosses the
   section once in one lane counts once, whichever lane; one that crosses it
   back and forth (a queue folded into lanes side by side, a path zig-zagging
   between polygon centres either side of the line) counts by its net
   crossing. Per source s and node v the signed sum over the section's edges
   of the pair weight the tree sends across (+ along the axis, - against):
   from one source every trip that ends across the section crosses it the
   same way, net, so its absolute value is the pair weight from s to the
   far side; the node's value is the sum over the sources, with their
   factors; the mean of two such sums, with the node taken ahead of the
   line and behind it (they differ on its own edges only): on a corridor
   one node across, the mean of the trips into and out of the node (its
   through-flow and half the trips that start or end in it).

Cost: the trees twice, O(k (m + n log n)) each for k sources (and the exact
areas' as :func:`g2s_plugins.traffic.od_flow` walks them), plus per node a
ball query and a sort of the q nodes and edges within ``reach``,
O(n q log q) (and four raycasts per lane for ``lanes``), and one sparse
product of the sources' edge loads with the sections' edges.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

import networkx as nx
import numpy as np
import scipy.sparse as sp
from scipy.spatial import cKDTree

from g2s_plugins import traffic
from g2s_plugins.recast import NavMesh

__all__ = ["Trips", "lane_edges", "principal_axes", "section_edges", "trips_across", "walking_across", "walking_trips"]


@dataclass(frozen=True)
class Trips:
    """The walking flow's sample and where its trips go, edge by edge (module docs, step 1).

    Attributes:
        sources: (k,) rows of the sample's sources (:func:`g2s_plugins.traffic.stratified_sources`).
        factor: (k,) their factors.
        ends: (m, 2) rows of each edge some tree uses, the lower row first.
        tensors: (n, 3) each node's orientation tensor of the trips along its edges, in plan: xx, xz, zz.
        area: (n,) the areas walked exactly beside the draws (:func:`g2s_plugins.traffic.exact_areas`), whose
            sources' trees span their own area alone; ``None``: none.
        group_nodes: those areas are walked in groups of about this many nodes
            (:func:`g2s_plugins.traffic.exact_area_groups`).
    """

    sources: np.ndarray
    factor: np.ndarray
    ends: np.ndarray
    tensors: np.ndarray
    area: np.ndarray | None = None
    group_nodes: int = 0


def _tree_steps(arrays: traffic.SurfaceArrays, sources: np.ndarray, factor: np.ndarray, weight: np.ndarray,
                area: np.ndarray | None, group_nodes: int) -> Iterator[tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]]:
    """Per block of the (k,) ``sources`` with ``factor`` (k,), per step of their trees: (source's row in the block,
    predecessor, node, the pair weight walking from the predecessor to the node, with the source's factor). The
    sources in the exact ``area`` (:class:`Trips`) come last, their trees on their group of areas' graph alone
    (:func:`g2s_plugins.traffic.exact_area_groups`), as :func:`g2s_plugins.traffic.od_flow` walks them."""
    alone = np.zeros(len(sources), dtype=bool) if area is None else area[sources] >= 0
    drawn = np.flatnonzero(~alone)
    for lo, block in traffic.source_blocks(sources[drawn], arrays.n):
        yield _steps(arrays.adjacency, block, weight, factor[drawn[lo:lo + len(block)]])
    if alone.any():
        walked = np.flatnonzero(alone)
        for rows, graph, which, local in traffic.exact_area_groups(arrays.adjacency, area, sources[walked], group_nodes):
            for lo, block in traffic.source_blocks(local, len(rows)):
                block_rows, before, nodes, carried = _steps(graph, block, weight[rows],
                                                            factor[walked[which[lo:lo + len(block)]]])
                yield block_rows, rows[before], rows[nodes], carried


def _steps(adjacency: sp.csr_array, block: np.ndarray, weight: np.ndarray,
           factor: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The steps of the trees of the (b,) ``block`` of sources with ``factor`` (b,) on ``adjacency`` (n, n) for
    ``weight`` (n,): :func:`_tree_steps`' tuple, rows of ``adjacency``."""
    predecessors, through = traffic.shortest_path_flow(adjacency, block, weight)
    rows, nodes = np.nonzero(predecessors >= 0)
    before = predecessors[rows, nodes].astype(np.int64)
    # the edge into a node carries every pair whose target lies in the node's subtree
    return rows, before, nodes, factor[rows] * (through[rows, nodes] + weight[nodes])


def walking_trips(arrays: traffic.SurfaceArrays, plan: np.ndarray, max_sources: int | None, seed: int = 0) -> Trips:
    """The :class:`Trips` of the walking flow's sample (``None``: every node with a weight is a source).

    Args:
        arrays: the surface graph.
        plan: (n, 2) each node's position in plan (x, z), m.

    The sample is the walking flow's (:func:`g2s_plugins.traffic.stratified_sources`): the smallest areas walked
    exactly beside the draws, so an area no draw falls on has its trips too. The trees are ``ties: first``'s
    (scipy's predecessor trees), whatever ties the flow takes. A vertical edge adds to no tensor (it has no
    direction in plan).
    """
    weight = traffic.origin_weight(arrays)
    sources, factor, _, area = traffic.stratified_sources(
        arrays.adjacency, weight, max_sources, seed, areas=None if max_sources is None else traffic.arrays_exact_areas(
            arrays, max_sources))
    n = arrays.n
    load = sp.csr_array((n, n))
    for _, before, nodes, carried in _tree_steps(arrays, sources, factor, weight, area, max_sources or 0):
        pairs = (np.minimum(before, nodes), np.maximum(before, nodes))
        load = load + sp.coo_array((carried, pairs), shape=(n, n)).tocsr()
    edges = sp.coo_array(load)
    ends = np.stack([edges.row, edges.col], axis=1).astype(np.int64)
    order = np.lexsort((ends[:, 1], ends[:, 0]))
    ends, carried = ends[order], edges.data[order]
    step = plan[ends[:, 1]] - plan[ends[:, 0]]
    length = np.hypot(step[:, 0], step[:, 1])
    unit = np.divide(step, length[:, None], out=np.zeros_like(step), where=length[:, None] > 0)
    tensors = np.zeros((n, 3))
    for k, term in enumerate((unit[:, 0] ** 2, unit[:, 0] * unit[:, 1], unit[:, 1] ** 2)):
        for end in ends.T:
            tensors[:, k] += np.bincount(end, weights=carried * term, minlength=n)
    return Trips(sources, factor, ends, tensors, area, max_sources or 0)


def principal_axes(tensors: np.ndarray) -> np.ndarray:
    """(n, 2) unit vectors in plan (x, z): the principal eigenvector of each of the (n, 3) ``tensors`` (xx, xz, zz);
    (1, 0) where a tensor is 0 or isotropic."""
    angle = 0.5 * np.arctan2(2.0 * tensors[:, 1], tensors[:, 0] - tensors[:, 2])
    return np.stack([np.cos(angle), np.sin(angle)], axis=1)


class _Crossings:
    """The edges of ``trips`` near each node that cross the line through it square to its axis, and where."""

    def __init__(self, positions: np.ndarray, trips: Trips, reach: float):
        self.positions, self.plan = positions, positions[:, [0, 2]]
        self.axes = principal_axes(trips.tensors)
        self.a, self.b = trips.ends[:, 0], trips.ends[:, 1]
        middles = (self.plan[self.a] + self.plan[self.b]) / 2.0
        half_length = np.hypot(*(self.plan[self.b] - self.plan[self.a]).T) / 2.0 if len(self.a) else np.zeros(0)
        self.near = (cKDTree(middles).query_ball_point(self.plan, reach + half_length.max()) if len(self.a)
                     else [[]] * len(positions))

    def of(self, v: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """The edges crossing v's line, their signs with v taken ahead of the line and behind it ((k, 2): +1 where
        ends[0] -> ends[1] runs along the axis, -1 against, 0 where it does not cross; the two differ only on v's own
        edges), their crossing points' distance along the section (+ to the axis's left) and height, m."""
        axis, side = self.axes[v], np.array([-self.axes[v, 1], self.axes[v, 0]])
        edges = np.asarray(self.near[v], dtype=np.int64)
        start, end = self.plan[self.a[edges]] - self.plan[v], self.plan[self.b[edges]] - self.plan[v]
        s0, s1 = start @ axis, end @ axis
        crosses = np.stack([(s0 >= 0) != (s1 >= 0), (s0 > 0) != (s1 > 0)], axis=1)
        cross = crosses.any(axis=1)
        edges, start, end, crosses = edges[cross], start[cross], end[cross], crosses[cross]
        s0, s1 = s0[cross], s1[cross]
        t = s0 / (s0 - s1)
        at = start + t[:, None] * (end - start)
        y = self.positions[self.a[edges], 1] + t * (self.positions[self.b[edges], 1] - self.positions[self.a[edges], 1])
        return edges, crosses * np.sign(s1 - s0)[:, None], at @ side, y


def section_edges(positions: np.ndarray, normals: np.ndarray, area: np.ndarray, trips: Trips, gap: float,
                  reach: float, height: float) -> list[tuple[np.ndarray, np.ndarray]]:
    """Per node, the edges of its section (``across: section``, module docs, step 2) and their (k, 2) signs
    (:class:`_Crossings`).

    Args:
        positions: (n, 3) node positions, m (y up).
        normals: (n, 3) unit surface normals (y up), for each node's tangent plane.
        area: (n,) node areas, m²; nodes of no area (portal nodes) do not widen a section.
        trips: the sample's trips (:func:`walking_trips`).
        gap: stretches of the section at most this far apart are one run, m.
        reach: the section reaches at most this far either side of the node, m.
        height: a node or a crossing lies on the section within this height of the node's tangent plane, m.
    """
    crossings = _Crossings(positions, trips, reach)
    plan = crossings.plan
    half = np.sqrt(np.maximum(area, 0.0)) / 2.0
    counted = np.flatnonzero(area > 0)
    nodes_near = cKDTree(plan[counted]).query_ball_point(plan, reach + half.max()) if len(counted) else [[]] * len(area)
    slope = -normals[:, [0, 2]] / np.maximum(normals[:, [1]], 1e-6)  # dy per m along x and z on the tangent plane
    result = []
    for v in range(len(area)):
        axis = crossings.axes[v]
        side = np.array([-axis[1], axis[0]])
        near = counted[np.asarray(nodes_near[v], dtype=np.int64)]
        near = near[near != v]
        offset = plan[near] - plan[v]
        across = offset @ side
        rise = positions[near, 1] - positions[v, 1] - offset @ slope[v]
        on = (np.abs(offset @ axis) <= half[near]) & (np.abs(rise) <= height) & (np.abs(across) <= reach)
        near, across = near[on], across[on]
        run = _run_members(across - half[near], across + half[near], half[v], gap)
        low = min(-half[v], float((across - half[near])[run].min(initial=0.0)))
        high = max(half[v], float((across + half[near])[run].max(initial=0.0)))
        edges, signs, along, y = crossings.of(v)
        rise = y - positions[v, 1] - (along[:, None] * side) @ slope[v] if len(edges) else y
        keep = (along >= low) & (along <= high) & (np.abs(rise) <= height)
        result.append((edges[keep], signs[keep]))
    return result


def lane_edges(navmesh: NavMesh, positions: np.ndarray, trips: Trips, lane_width: float, gap: float, reach: float,
               height: float) -> list[tuple[np.ndarray, np.ndarray] | None]:
    """Per node, the edges of its lanes' section (``across: lanes``, module docs, step 2) and their (k, 2) signs;
    ``None`` for a node whose own floor along its section is ``lane_width`` or wider (it keeps its own flow).

    Args:
        navmesh: the navmesh ``positions`` stand on.
        positions: (n, 3) node positions, m (y up).
        trips: the sample's trips (:func:`walking_trips`).
        lane_width: floor along the section narrower than this is a lane, m (walkable).
        gap: lanes at most this far apart (walkable floor to walkable floor) are side by side, m.
        reach: lanes are looked for at most this far either side of the node, m.
        height: a crossing lies on the section within this height of the node, m.
    """
    crossings = _Crossings(positions, trips, reach)
    result: list[tuple[np.ndarray, np.ndarray] | None] = []
    for v in range(len(positions)):
        side = np.array([-crossings.axes[v, 1], 0.0, crossings.axes[v, 0]])
        behind, ahead = _floor_either_side(navmesh, positions[v], side, reach)
        if behind + ahead >= lane_width:
            result.append(None)
            continue
        edges, signs, along, y = crossings.of(v)
        level = np.abs(y - positions[v, 1]) <= height
        edges, signs, along, y = edges[level], signs[level], along[level], y[level]
        lanes = (along >= -behind) & (along <= ahead)
        for sign, own_end in ((1.0, ahead), (-1.0, behind)):
            out = sign * along  # distance outward along the section
            reached = own_end
            for nearest in np.argsort(out, kind="stable"):
                if out[nearest] <= reached:
                    continue
                if out[nearest] > reach:
                    break
                point = positions[v] + sign * out[nearest] * side
                point[1] = y[nearest]
                back, forth = _floor_either_side(navmesh, point, sign * side, reach)
                if back + forth >= lane_width or out[nearest] - back - reached > gap:
                    break  # a wide floor beside the lanes, or the next floor too far off: the way ends
                lanes |= (out > out[nearest] - back) & (out <= out[nearest] + forth)
                reached = out[nearest] + forth
        result.append((edges[lanes], signs[lanes]))
    return result


def trips_across(arrays: traffic.SurfaceArrays, trips: Trips, sections: list[tuple[np.ndarray, np.ndarray] | None],
                 own: np.ndarray | None) -> np.ndarray:
    """(n,) per node, the pair weight of the trips across its section (module docs, step 3), or ``own`` (n,) where
    its section is ``None`` (``own`` ``None``: no section is; 0 where no trip crosses any)."""
    n, m = arrays.n, len(trips.ends)
    result = np.zeros(n) if own is None else np.asarray(own, dtype=np.float64).copy()
    with_section = [v for v, section in enumerate(sections) if section is not None]
    if not with_section or m == 0:
        return result
    columns = np.concatenate([np.full(len(sections[v][0]), j) for j, v in enumerate(with_section)])
    rows = np.concatenate([sections[v][0] for v in with_section])
    signs = np.concatenate([sections[v][1] for v in with_section]).astype(np.float64)
    edge_signs = [sp.csr_array((signs[:, k], (rows, columns)), shape=(m, len(with_section))) for k in (0, 1)]
    index = sp.csr_array((np.arange(1, m + 1), (trips.ends[:, 0], trips.ends[:, 1])), shape=(n, n))
    across = np.zeros(len(with_section))
    weight = traffic.origin_weight(arrays)
    for block_rows, before, nodes, carried in _tree_steps(arrays, trips.sources, trips.factor, weight, trips.area,
                                                          trips.group_nodes):
        edge = np.asarray(index[np.minimum(before, nodes), np.maximum(before, nodes)]).reshape(-1) - 1
        used = edge >= 0  # a step that carries nothing may have left its edge out of the loads
        block_rows, edge, before, nodes, carried = block_rows[used], edge[used], before[used], nodes[used], carried[used]
        forward = np.where(before < nodes, 1.0, -1.0)  # the tree walks the edge from ends[0] to ends[1]
        count = int(block_rows.max()) + 1 if len(block_rows) else 0
        steps = sp.csr_array((carried * forward, (block_rows, edge)), shape=(count, m))
        for signed in edge_signs:  # v ahead of its line, then behind it
            across += 0.5 * np.abs((steps @ signed).toarray()).sum(axis=0)
    result[with_section] = across
    return result


def _floor_either_side(navmesh: NavMesh, point: np.ndarray, direction: np.ndarray, reach: float) -> tuple[float, float]:
    """How far the floor under ``point`` (3,) runs against and along the plan unit vector ``direction`` (3,) before a
    wall, each at most ``reach``, m (Detour's raycast; 0 when ``point`` stands on no polygon)."""
    lengths = []
    for sign in (-1.0, 1.0):
        _, t = navmesh.raycast(point, point + sign * reach * direction)
        lengths.append(reach * min(t, 1.0))
    return lengths[0], lengths[1]


def _run_members(starts: np.ndarray, ends: np.ndarray, own: float, gap: float) -> np.ndarray:
    """(k,) bool: which of k stretches ``[starts, ends]`` along a line lie in the run (stretches at most ``gap``
    apart joined) that holds the node's own stretch ``[-own, own]``. O(k log k)."""
    lo, hi = np.append(starts, -own), np.append(ends, own)
    order = np.argsort(lo, kind="stable")
    reached = np.maximum.accumulate(hi[order])
    run = np.empty(len(lo), dtype=np.int64)
    run[order] = np.cumsum(np.r_[True, lo[order][1:] > reached[:-1] + gap])
    return run[:-1] == run[-1]


def walking_across(graph: nx.Graph, flow: np.ndarray | None, max_sources: int | None, seed: int, gap: float,
                   reach: float, height: float, navmesh: NavMesh | None = None,
                   lane_width: float | None = None) -> np.ndarray:
    """(n,) the trips across each node's section (:func:`section_edges`; with ``navmesh`` and ``lane_width``, its
    lanes': :func:`lane_edges`, ``flow`` (n,) kept off lanes) in ``graph``'s
    :func:`g2s_plugins.traffic.surface_arrays` order, for the walking flow's sample (exact up to ``max_sources``
    nodes with an area, as :func:`g2s_plugins.traffic.walking_flow`). Nodes without a ``normal`` are taken as flat.

    ``flow`` is read only for lanes: every node has a section, so a caller of sections need not compute it
    (``None``; a graph on which no tree uses an edge then reads 0 everywhere, as its walking flow does)."""
    arrays = traffic.surface_arrays(graph)
    data = graph.nodes
    positions = np.array([data[node]["pos"] for node in arrays.nodes], dtype=np.float64).reshape(-1, 3)
    trips = walking_trips(arrays, positions[:, [0, 2]], None if traffic.is_exact(arrays, max_sources) else max_sources,
                          seed)
    if navmesh is not None and lane_width is not None:
        sections = lane_edges(navmesh, positions, trips, lane_width, gap, reach, height)
    else:
        normals = np.array([data[node].get("normal", (0.0, 1.0, 0.0)) for node in arrays.nodes],
                           dtype=np.float64).reshape(-1, 3)
        sections = section_edges(positions, normals, arrays.area, trips, gap, reach, height)
    return trips_across(arrays, trips, sections, flow)
