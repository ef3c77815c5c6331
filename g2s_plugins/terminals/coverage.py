"""Coverage: leaves, then the farthest uncovered nodes, until every walkable node lies within ``radius`` of a terminal.

The paper's leaves reach every dead end, but a room with no degree-1 polygon
(a dead-end room split into polygons around a pillar, a ring corridor) gets
no terminal and no structure. This selector keeps the leaves and then covers
the rest greedily, farthest first (a farthest-point cover, as in Gonzalez's
k-center heuristic):

1. distances from the leaves along the graph (one multi-source Dijkstra);
   an area without leaves is seeded with its node farthest from its
   lowest-id node;
2. while some node is farther than ``radius`` from the set, the farthest
   one and its shortest path back to the set join it (an incremental
   Steiner tree grown farthest first), and the distances are updated by a
   Dijkstra from the new path bounded by the old farthest distance.

The nodes added in step 2 are terminals, so the Steiner structure contains
them all and every node of an area with terminals ends up within
``radius`` of the structure along the graph. They are *waypoints*:
simplification may drop them like any node on a path (the structure's
straight edges still pass there), so they do not bloat the final structure.
Areas (connected components) smaller than ``min_area`` are reported in a
warning and get no extra terminals (their leaves stay, as with ``leaves``).

Default ``radius``: 12 agent radii (6 m for the default 0.5 m agent), but
no more than a tenth of the level's horizontal extent so that small levels
get more than one terminal. Measured on a 115-room generated dungeon
(docs/analysis_quality.md): 4 m gives a structure of 61 % of the polygons,
6 m 52 % and 8 m 50 %, with 100 %, 100 % and 99.8 % of the area within 6 m;
the heat map's agreement with walking flow drops at 8 m (rho 0.76, 0.76,
0.70). Default ``min_area``: the area of a disc of ``radius``.

Complexity: O(m + n log n) for step 1 plus, per added path, a bounded
Dijkstra over the part of the graph farther than ``radius / 2`` from the
leaves (scipy: O(size of that part) each).
"""

from __future__ import annotations

import math

import networkx as nx
import numpy as np
from pydantic import Field
from scipy.sparse import csgraph

from g2s_core.model import RunContext, Terminals
from g2s_core.plugin import PluginParams, hookimpl
from g2s_plugins import traffic

NAME = "coverage"

AGENT_RADII = 12.0
"""Default cover radius in agent radii."""

EXTENT_SHARE = 0.1
"""Default cover radius at most this share of the level's horizontal extent."""


class Params(PluginParams):
    """Cover radius and the smallest area that is forced in."""

    radius: float | None = Field(None, gt=0, description="every walkable node within this many metres (along the graph) of a terminal; default 12 agent radii, at most 1/10 of the level's extent")
    min_area: float | None = Field(None, ge=0, description="walkable areas smaller than this (m²) are reported, not covered; default pi radius²")


def default_radius(context: RunContext) -> float:
    """The default cover radius for the agent and level of ``context``, metres."""
    extent = np.ptp(np.asarray(context.mesh.bounds, dtype=np.float64)[:, [0, 2]], axis=0)
    return float(min(AGENT_RADII * context.agent.radius, EXTENT_SHARE * float(np.hypot(*extent)) or math.inf))


@hookimpl
def g2s_select_terminals(graph: nx.Graph, params: Params, context: RunContext) -> Terminals:
    """Leaves plus the farthest-first cover paths, by ascending id."""
    radius = params.radius if params.radius is not None else default_radius(context)
    min_area = params.min_area if params.min_area is not None else math.pi * radius**2
    arrays = traffic.surface_arrays(graph)
    adjacency = arrays.adjacency
    degree = np.diff(adjacency.indptr)
    count, labels = csgraph.connected_components(adjacency, directed=False)
    component_area = np.bincount(labels, weights=arrays.area, minlength=count)
    small = component_area < min_area
    if small.any():
        context.warn(
            f"coverage: {int(small.sum())} walkable area(s) smaller than {min_area:.3g} m² "
            f"({component_area[small].sum():.3g} m² in all) are not covered"
        )
    leaves = np.flatnonzero(degree == 1)
    seeds = np.concatenate([leaves, _seeds(adjacency, labels, count, leaves, small)])
    cover = _cover(adjacency, seeds, ~small[labels], radius)
    waypoints = np.setdiff1d(cover, leaves)
    rows = np.union1d(leaves, waypoints)
    return Terminals(
        nodes=tuple(sorted(arrays.nodes[i] for i in rows.tolist())),
        waypoints=tuple(sorted(arrays.nodes[i] for i in waypoints.tolist())),
    )


def _seeds(adjacency, labels: np.ndarray, count: int, leaves: np.ndarray, small: np.ndarray) -> np.ndarray:
    """One node per big enough area without leaves: the farthest from its lowest-id node."""
    has_leaf = np.zeros(count, dtype=bool)
    has_leaf[labels[leaves]] = True
    firsts = np.unique(labels, return_index=True)[1]
    lonely = firsts[~has_leaf & ~small]
    if lonely.size == 0:
        return np.zeros(0, dtype=np.int64)
    distance = csgraph.dijkstra(adjacency, directed=False, indices=lonely, min_only=True)
    seeds = []
    for first in lonely.tolist():
        members = np.flatnonzero(labels == labels[first])
        seeds.append(int(members[np.argmax(distance[members])]))
    return np.asarray(seeds, dtype=np.int64)


def _cover(adjacency, seeds: np.ndarray, eligible: np.ndarray, radius: float) -> np.ndarray:
    """The seeds plus, farthest node first, shortest paths to the growing set until all is within ``radius``.

    Distances are updated on the part of the graph farther than ``radius / 2``
    from the seeds (the rest is covered for good); distances measured there
    are >= the true ones, so the cover holds on the whole graph.
    """
    distance, predecessor, _ = csgraph.dijkstra(
        adjacency, directed=False, indices=seeds, min_only=True, return_predecessors=True
    )
    predecessor = predecessor.astype(np.int64)
    region = np.flatnonzero((distance > radius / 2) & eligible)
    local = np.full(len(distance), -1, dtype=np.int64)
    local[region] = np.arange(region.size)
    sub = adjacency[region][:, region]
    near = distance[region].copy()
    chosen = [seeds]
    while region.size:
        at = int(np.argmax(near))
        if not near[at] > radius:
            break
        path = [int(region[at])]
        while predecessor[path[-1]] >= 0:
            path.append(int(predecessor[path[-1]]))
        path = np.asarray(path[:-1], dtype=np.int64)  # the last node is already in the set
        chosen.append(path)
        predecessor[path] = -1
        inside = local[path][local[path] >= 0]
        reach, via, _ = csgraph.dijkstra(
            sub, directed=False, indices=inside, limit=float(near[at]), min_only=True, return_predecessors=True
        )
        better = reach < near
        near[better] = reach[better]
        predecessor[region[better]] = np.where(via[better] >= 0, region[np.maximum(via[better], 0)], -1)
    return np.unique(np.concatenate(chosen))
