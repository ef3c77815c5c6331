"""Walking flow across a way's cross-section: the trips that pass a section of a way, whichever lane they take.

The walking flow of :mod:`g2s_plugins.traffic` counts the trips through one
node (a navmesh polygon, a surface sample). Where a way is split into lanes
side by side (the gaps of a gate line, the ramps of an escalator bank) or
into many polygons across (a wide slope), each lane or polygon carries a
share of the way's trips, so a way everyone walks reads colder than a
corridor of one polygon across that carries fewer trips
(docs/analysis_quality.md, "Parallel lanes in the heat map").

The flow across the section of node v sums the flow of the nodes the
section crosses:

1. **The way's axis at v** (:func:`flow_tensors`, :func:`principal_axes`): the principal axis, in plan,
   of the walking trips through v. Each shortest-path tree of the walking
   flow's sources (the same sources, ``ties: first``) sends the pair weight
   ``a_s (A_w)`` (A_w: the weight of w's subtree, w included) along the edge
   from w's predecessor p to w; the edge adds that weight times ``u u^T``
   (u: the edge's unit direction in plan) to the 2 x 2 tensors of p and w.
   The axis is the tensor's principal eigenvector (the orientation tensor
   of directional statistics; N. I. Fisher, T. Lewis and B. J. J. Embleton,
   Statistical Analysis of Spherical Data, Cambridge University Press,
   1987, section 3.2.4), the section its perpendicular.
2. **The section** (:func:`section_flow`): the line through v across that
   axis, in plan. A node u with an area lies on it when its centre is within
   its half-size (``sqrt(area) / 2``, a square's: exact for a grid of
   samples) of the line, and within ``height`` of v's tangent plane (its own
   floor, not a floor above or below; a slope's section follows the slope).
   Along the line each such node covers its centre plus or minus its
   half-size; the section is the run of covered stretches that holds v,
   stretches at most ``gap`` apart counting as one run (the barriers of a
   gate line, the balustrades between escalators, with the agent's
   clearance round them), and reaching at most ``reach`` either side of v.
   Its value is the flow of v plus that of every other node of the run.

On a corridor one polygon across, the section is the polygon: its value is
its own flow. Cost: the trees again, O(k (m + n log n)), and per node a
ball query and a sort of the nodes within ``reach``, O(n (log n + q log q))
for q nodes within ``reach``.
"""

from __future__ import annotations

from dataclasses import dataclass

import networkx as nx
import numpy as np
import scipy.sparse as sp
from scipy.spatial import cKDTree

from g2s_plugins import traffic
from g2s_plugins.recast import NavMesh

__all__ = ["Trips", "lane_flow", "principal_axes", "section_flow", "walking_lane_flow", "walking_section_flow", "walking_trips"]


@dataclass(frozen=True)
class Trips:
    """Where the walking trips of a sample go, edge by edge (module docs, step 1).

    Attributes:
        ends: (m, 2) rows of each edge's two nodes (the edges some tree uses), the lower row first.
        carried: (m,) the pair weight walking along each edge, both ways.
        tensors: (n, 3) each node's orientation tensor of the trips along its edges, in plan: xx, xz, zz.
    """

    ends: np.ndarray
    carried: np.ndarray
    tensors: np.ndarray


def walking_trips(arrays: traffic.SurfaceArrays, plan: np.ndarray, max_sources: int | None, seed: int = 0) -> Trips:
    """The :class:`Trips` of the walking flow's sample (:func:`g2s_plugins.traffic.walking_sources`).

    Args:
        arrays: the surface graph.
        plan: (n, 2) each node's position in plan (x, z), m.
        max_sources: the sample; ``None``: every node with a weight is a source.
        seed: its seed.

    The trees are ``ties: first``'s (scipy's predecessor trees), whatever ties the flow takes. A vertical edge adds
    its weight to no tensor (it has no direction in plan).
    """
    weight = traffic.origin_weight(arrays)
    sources, factor, _ = traffic.walking_sources(weight, max_sources, seed)
    n = arrays.n
    carried = sp.csr_array((n, n))
    block = max(1, traffic.BLOCK_ENTRIES // max(n, 1))
    for lo in range(0, len(sources), block):
        predecessors, through = traffic.shortest_path_flow(arrays.adjacency, sources[lo:lo + block], weight)
        rows, nodes = np.nonzero(predecessors >= 0)
        before = predecessors[rows, nodes].astype(np.int64)
        # the edge from a node's predecessor carries every pair whose target lies in the node's subtree
        weights = factor[lo:lo + block][rows] * (through[rows, nodes] + weight[nodes])
        carried = carried + sp.coo_array((weights, (np.minimum(before, nodes), np.maximum(before, nodes))),
                                         shape=(n, n)).tocsr()
    edges = sp.coo_array(carried)
    ends, load = np.stack([edges.row, edges.col], axis=1).astype(np.int64), edges.data
    step = plan[ends[:, 1]] - plan[ends[:, 0]]
    length = np.hypot(step[:, 0], step[:, 1])
    unit = np.divide(step, length[:, None], out=np.zeros_like(step), where=length[:, None] > 0)
    tensors = np.zeros((n, 3))
    for k, term in enumerate((unit[:, 0] ** 2, unit[:, 0] * unit[:, 1], unit[:, 1] ** 2)):
        for end in ends.T:
            tensors[:, k] += np.bincount(end, weights=load * term, minlength=n)
    return Trips(ends, load, tensors)


def principal_axes(tensors: np.ndarray) -> np.ndarray:
    """(n, 2) unit vectors in plan (x, z): the principal eigenvector of each of the (n, 3) ``tensors`` (xx, xz, zz);
    (1, 0) where a tensor is 0 or isotropic."""
    angle = 0.5 * np.arctan2(2.0 * tensors[:, 1], tensors[:, 0] - tensors[:, 2])
    return np.stack([np.cos(angle), np.sin(angle)], axis=1)


def section_flow(positions: np.ndarray, normals: np.ndarray, area: np.ndarray, trips: Trips, gap: float,
                 reach: float, height: float) -> np.ndarray:
    """(n,) the pair weight crossing each node's section (module docs, step 2).

    Args:
        positions: (n, 3) node positions, m (y up).
        normals: (n, 3) unit surface normals (y up), for each node's tangent plane.
        area: (n,) node areas, m²; nodes of no area (portal nodes) do not widen another node's section.
        trips: the trips along the edges (:func:`walking_trips`).
        gap: stretches of the section at most this far apart are one run, m.
        reach: the section reaches at most this far either side of the node, m.
        height: a node or a crossing lies on the section within this height of the node's tangent plane, m.

    A node on the line itself is taken on either side in turn and the two sums averaged: on a corridor one
    node across, the mean of the trips into and out of the node.
    """
    n = len(area)
    plan = positions[:, [0, 2]]
    half = np.sqrt(np.maximum(area, 0.0)) / 2.0
    counted = np.flatnonzero(area > 0)
    axes = principal_axes(trips.tensors)
    a, b = trips.ends[:, 0], trips.ends[:, 1]
    middles = (plan[a] + plan[b]) / 2.0
    half_length = np.hypot(*(plan[b] - plan[a]).T) / 2.0 if len(a) else np.zeros(0)
    nodes_near = cKDTree(plan[counted]).query_ball_point(plan, reach + half.max()) if len(counted) else [[]] * n
    edges_near = cKDTree(middles).query_ball_point(plan, reach + half_length.max()) if len(a) else [[]] * n
    slope = -normals[:, [0, 2]] / np.maximum(normals[:, [1]], 1e-6)  # dy per m along x and z on the tangent plane
    result = np.zeros(n)
    for v in range(n):
        axis, side = axes[v], np.array([-axes[v, 1], axes[v, 0]])
        near = counted[np.asarray(nodes_near[v], dtype=np.int64)]
        near = near[near != v]
        offset = plan[near] - plan[v]
        across, along = offset @ side, offset @ axis
        rise = positions[near, 1] - positions[v, 1] - offset @ slope[v]
        on = (np.abs(along) <= half[near]) & (np.abs(rise) <= height) & (np.abs(across) <= reach)
        near, across = near[on], across[on]
        run = _run_members(across - half[near], across + half[near], half[v], gap)
        low = min(-half[v], float((across - half[near])[run].min(initial=0.0)))
        high = max(half[v], float((across + half[near])[run].max(initial=0.0)))
        edges = np.asarray(edges_near[v], dtype=np.int64)
        start, end = plan[a[edges]] - plan[v], plan[b[edges]] - plan[v]
        s0, s1 = start @ axis, end @ axis
        t = np.divide(s0, s0 - s1, out=np.zeros(len(edges)), where=s0 != s1)
        at = start + t[:, None] * (end - start)
        rise = positions[a[edges], 1] + t * (positions[b[edges], 1] - positions[a[edges], 1]) - positions[v, 1] - at @ slope[v]
        # an edge crossing at a glancing angle is a step of a path along the section (centres staggered either
        # side of it), not a trip across: only edges within 45 degrees of the axis count
        steep = np.abs(s1 - s0) >= np.abs((end - start) @ side)
        inside = (at @ side >= low) & (at @ side <= high) & (np.abs(rise) <= height) & steep
        total = 0.0
        for on_line_ahead in (True, False):  # a node on the line counted ahead of it, then behind it
            ahead0, ahead1 = (s0 >= 0, s1 >= 0) if on_line_ahead else (s0 > 0, s1 > 0)
            total += float(trips.carried[edges[(ahead0 != ahead1) & inside]].sum())
        result[v] = total / 2.0
    return result


def lane_flow(navmesh: NavMesh, positions: np.ndarray, flow: np.ndarray, trips: Trips, lane_width: float,
              gap: float, reach: float, height: float) -> np.ndarray:
    """(n,) each node's own walking flow plus the trips across the lanes side by side with its own (module docs,
    ``across: lanes``), in units of ``flow``.

    Args:
        navmesh: the navmesh ``positions`` stand on (Detour's raycast finds where a lane's floor ends).
        positions: (n, 3) node positions, m (y up).
        flow: (n,) each node's walking flow.
        trips: the trips along the edges (:func:`walking_trips`) of the same sample.
        lane_width: a stretch of floor along the section narrower than this is a lane, m (walkable).
        gap: lanes at most this far apart (wall to wall, walkable) are side by side, m.
        reach: lanes are looked for at most this far either side of the node, m.
        height: a crossing lies on the section within this height of the node, m.

    A node whose own floor along its section is ``lane_width`` wide or wider keeps its own flow.
    """
    plan = positions[:, [0, 2]]
    axes = principal_axes(trips.tensors)
    a, b = trips.ends[:, 0], trips.ends[:, 1]
    middles = (plan[a] + plan[b]) / 2.0
    half_length = np.hypot(*(plan[b] - plan[a]).T) / 2.0 if len(a) else np.zeros(0)
    edges_near = cKDTree(middles).query_ball_point(plan, reach + half_length.max()) if len(a) else [[]] * len(flow)
    result = np.asarray(flow, dtype=np.float64).copy()
    for v in range(len(flow)):
        axis, side = axes[v], np.array([-axes[v, 1], axes[v, 0]])
        across3 = np.array([side[0], 0.0, side[1]])
        behind, ahead = _floor_either_side(navmesh, positions[v], across3, reach)
        if behind + ahead >= lane_width:
            continue
        edges = np.asarray(edges_near[v], dtype=np.int64)
        start, end = plan[a[edges]] - plan[v], plan[b[edges]] - plan[v]
        s0, s1 = start @ axis, end @ axis
        t = np.divide(s0, s0 - s1, out=np.zeros(len(edges)), where=s0 != s1)
        at = start + t[:, None] * (end - start)
        y = positions[a[edges], 1] + t * (positions[b[edges], 1] - positions[a[edges], 1])
        steep = np.abs(s1 - s0) >= np.abs((end - start) @ side)  # a trip across, not a step along the section
        keep = ((s0 >= 0) != (s1 >= 0)) & steep & (np.abs(y - positions[v, 1]) <= height)
        edges, at, y = edges[keep], at[keep], y[keep]
        for sign, edge_of_own in ((1.0, ahead), (-1.0, behind)):
            out = sign * (at @ side)  # distance outward along the section
            reached = edge_of_own
            for nearest in np.argsort(out, kind="stable"):
                if out[nearest] <= reached:
                    continue
                if out[nearest] > reach:
                    break
                point = np.array([plan[v, 0] + at[nearest, 0], y[nearest], plan[v, 1] + at[nearest, 1]])
                back, forth = _floor_either_side(navmesh, point, sign * across3, reach)
                if back + forth >= lane_width or out[nearest] - back - reached > gap:
                    break  # a wide floor beside the lanes, or floor too far off: the way ends
                lane = (out > out[nearest] - back) & (out <= out[nearest] + forth)
                result[v] += float(trips.carried[edges[lane]].sum())
                reached = out[nearest] + forth
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


def walking_section_flow(graph: nx.Graph, max_sources: int | None, seed: int, gap: float, reach: float,
                         height: float) -> np.ndarray:
    """(n,) :func:`section_flow` of ``graph`` (:func:`g2s_plugins.traffic.surface_arrays` order) for the walking
    flow's sample (exact up to ``max_sources`` nodes with an area, as :func:`g2s_plugins.traffic.walking_flow`).
    Nodes without a ``normal`` are taken as flat."""
    arrays = traffic.surface_arrays(graph)
    data = graph.nodes
    positions = np.array([data[node]["pos"] for node in arrays.nodes], dtype=np.float64).reshape(-1, 3)
    normals = np.array([data[node].get("normal", (0.0, 1.0, 0.0)) for node in arrays.nodes],
                       dtype=np.float64).reshape(-1, 3)
    exact = traffic.is_exact(arrays, max_sources)
    trips = walking_trips(arrays, positions[:, [0, 2]], None if exact else max_sources, seed)
    return section_flow(positions, normals, arrays.area, trips, gap, reach, height)


def walking_lane_flow(graph: nx.Graph, navmesh: NavMesh, flow: np.ndarray, max_sources: int | None, seed: int,
                      lane_width: float, gap: float, reach: float, height: float) -> np.ndarray:
    """(n,) :func:`lane_flow` of ``graph`` (a navmesh graph of ``navmesh``) and its walking ``flow``
    (:func:`g2s_plugins.traffic.walking_flow`, the same sample)."""
    arrays = traffic.surface_arrays(graph)
    positions = np.array([graph.nodes[node]["pos"] for node in arrays.nodes], dtype=np.float64).reshape(-1, 3)
    trips = walking_trips(arrays, positions[:, [0, 2]], None if traffic.is_exact(arrays, max_sources) else max_sources,
                          seed)
    return lane_flow(navmesh, positions, flow, trips, lane_width, gap, reach, height)
