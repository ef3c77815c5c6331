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

1. **The way's axis at v** (:func:`flow_axes`): the principal axis, in plan,
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

import networkx as nx
import numpy as np
from scipy.spatial import cKDTree

from g2s_plugins import traffic

__all__ = ["flow_axes", "section_flow", "walking_section_flow"]


def flow_axes(arrays: traffic.SurfaceArrays, plan: np.ndarray, max_sources: int | None, seed: int = 0) -> np.ndarray:
    """(n, 2) unit vectors in plan (x, z): the principal axis of the walking trips through each node.

    Args:
        arrays: the surface graph.
        plan: (n, 2) each node's position in plan (x, z), m.
        max_sources: the walking flow's sample (:func:`g2s_plugins.traffic.walking_sources`); ``None``: every node
            with a weight is a source.
        seed: its seed.

    A node no trip passes gets the axis (1, 0). The trees are ``ties: first``'s whatever the flow's ties: the
    axis only orients the section.
    """
    weight = traffic.origin_weight(arrays)
    sources, factor, _ = traffic.walking_sources(weight, max_sources, seed)
    n = arrays.n
    tensor = np.zeros((3, n))  # xx, xz, zz
    block = max(1, traffic.BLOCK_ENTRIES // max(n, 1))
    for lo in range(0, len(sources), block):
        predecessors, through = traffic.shortest_path_flow(arrays.adjacency, sources[lo:lo + block], weight)
        rows, nodes = np.nonzero(predecessors >= 0)
        before = predecessors[rows, nodes]
        carried = factor[lo:lo + block][rows] * (through[rows, nodes] + weight[nodes])
        step = plan[nodes] - plan[before]
        length = np.hypot(step[:, 0], step[:, 1])
        level = length > 0  # a vertical edge has no direction in plan
        unit = step[level] / length[level, None]
        carried, ends = carried[level], (nodes[level], before[level])
        for k, term in enumerate((unit[:, 0] ** 2, unit[:, 0] * unit[:, 1], unit[:, 1] ** 2)):
            for end in ends:
                tensor[k] += np.bincount(end, weights=carried * term, minlength=n)
    angle = 0.5 * np.arctan2(2.0 * tensor[1], tensor[0] - tensor[2])
    return np.stack([np.cos(angle), np.sin(angle)], axis=1)


def section_flow(positions: np.ndarray, normals: np.ndarray, area: np.ndarray, flow: np.ndarray, axes: np.ndarray,
                 gap: float, reach: float, height: float) -> np.ndarray:
    """(n,) the flow across each node's section (module docs, step 2), in units of ``flow``.

    Args:
        positions: (n, 3) node positions, m (y up).
        normals: (n, 3) unit surface normals (y up), for each node's tangent plane.
        area: (n,) node areas, m²; nodes of no area (portal nodes) add to no other node's section.
        flow: (n,) the walking flow of each node.
        axes: (n, 2) each node's way axis in plan (:func:`flow_axes`).
        gap: stretches of the section at most this far apart are one run, m.
        reach: the section reaches at most this far either side of the node, m.
        height: a node lies on the section within this height of the node's tangent plane, m.
    """
    n = len(flow)
    plan = positions[:, [0, 2]]
    half = np.sqrt(np.maximum(area, 0.0)) / 2.0
    counted = np.flatnonzero(area > 0)
    result = np.asarray(flow, dtype=np.float64).copy()
    if len(counted) == 0:
        return result
    tree = cKDTree(plan[counted])
    slope = -normals[:, [0, 2]] / np.maximum(normals[:, [1]], 1e-6)  # dy per m along x and z on the tangent plane
    for v, near in enumerate(tree.query_ball_point(plan, reach + half.max())):
        near = counted[np.asarray(near, dtype=np.int64)]
        near = near[near != v]
        offset = plan[near] - plan[v]
        across = offset @ np.array([-axes[v, 1], axes[v, 0]])
        along = offset @ axes[v]
        rise = positions[near, 1] - positions[v, 1] - offset @ slope[v]
        on = (np.abs(along) <= half[near]) & (np.abs(rise) <= height) & (np.abs(across) <= reach)
        near, across = near[on], across[on]
        run = _run_members(across - half[near], across + half[near], half[v], gap)
        result[v] += flow[near[run]].sum()
    return result


def _run_members(starts: np.ndarray, ends: np.ndarray, own: float, gap: float) -> np.ndarray:
    """(k,) bool: which of k stretches ``[starts, ends]`` along a line lie in the run (stretches at most ``gap``
    apart joined) that holds the node's own stretch ``[-own, own]``. O(k log k)."""
    lo, hi = np.append(starts, -own), np.append(ends, own)
    order = np.argsort(lo, kind="stable")
    reached = np.maximum.accumulate(hi[order])
    run = np.empty(len(lo), dtype=np.int64)
    run[order] = np.cumsum(np.r_[True, lo[order][1:] > reached[:-1] + gap])
    return run[:-1] == run[-1]


def walking_section_flow(graph: nx.Graph, flow: np.ndarray, max_sources: int | None, seed: int, gap: float,
                         reach: float, height: float) -> np.ndarray:
    """(n,) :func:`section_flow` of ``graph``'s walking ``flow`` (:func:`g2s_plugins.traffic.walking_flow` order),
    with the axes of the same sample (:func:`flow_axes`). Nodes without a ``normal`` are taken as flat."""
    arrays = traffic.surface_arrays(graph)
    data = graph.nodes
    positions = np.array([data[node]["pos"] for node in arrays.nodes], dtype=np.float64).reshape(-1, 3)
    normals = np.array([data[node].get("normal", (0.0, 1.0, 0.0)) for node in arrays.nodes],
                       dtype=np.float64).reshape(-1, 3)
    exact = traffic.is_exact(arrays, max_sources)
    axes = flow_axes(arrays, positions[:, [0, 2]], None if exact else max_sources, seed)
    return section_flow(positions, normals, arrays.area, flow, axes, gap, reach, height)
