"""What several writers share: numbers, floors, edges; the final graph and stage table come from core."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import networkx as nx
import numpy as np

from g2s_core.model import RunResult
from g2s_core.summary import final_graph, metric_lines, roots_of, stage_rows

__all__ = ["agent_value", "coordinate", "edge_list", "final_graph", "floors", "is_loop_edge", "metric_lines", "number", "positions",
           "roots_of", "stage_rows", "terminal_ids", "tree_parents", "vector"]

FLOAT_DIGITS = 9
"""Floats in the written files keep this many significant digits (``format(x, '.9g')``); coordinates also keep
at least :data:`COORDINATE_DECIMALS` decimals."""
_ROUNDED = f".{FLOAT_DIGITS}g"

COORDINATE_DECIMALS = 5
"""Decimals a coordinate keeps at the least: 10 µm. From 10^4 m out, 9 significant digits alone would be coarser:
a level 1,000 km from the origin would be written to the centimetre (docs/navmesh.md, "Levels far from the
origin")."""
_FINE_FROM = 10.0 ** (FLOAT_DIGITS - COORDINATE_DECIMALS)


def number(value: Any) -> float | None:
    """``value`` as a float rounded to :data:`FLOAT_DIGITS` significant digits; ``None`` if not finite.

    ``-0.0`` becomes ``0.0`` so that the sign of a zero never differs between runs.
    """
    x = float(value)
    if not math.isfinite(x):
        return None
    return float(format(x, _ROUNDED)) + 0.0


def coordinate(value: Any) -> float | None:
    """:func:`number`, or ``value`` rounded to :data:`COORDINATE_DECIMALS` decimals where that is finer (from
    10^4 m out); ``None`` if not finite."""
    x = float(value)
    if -_FINE_FROM < x < _FINE_FROM or not math.isfinite(x):
        return number(x)
    return round(x, COORDINATE_DECIMALS) + 0.0


def vector(value: Any) -> list[float | None] | None:
    """A 3-vector (a position, a direction) as a list of :func:`coordinate` values (``None`` when absent)."""
    if value is None:
        return None
    if type(value) is tuple and all(type(v) is float for v in value):  # a node's position: no array needed
        return [coordinate(v) for v in value]
    return [coordinate(v) for v in np.asarray(value, dtype=np.float64).reshape(-1).tolist()]


def terminal_ids(result: RunResult) -> list[int]:
    """The terminals every output shows and records, in the selector's order (``[]`` before step 2); the
    selector's waypoints are plain structure nodes (``Terminals.without_waypoints``)."""
    return [int(t) for t in result.terminals.without_waypoints] if result.terminals is not None else []


def agent_value(result: RunResult, name: str, default: float) -> float:
    """An agent setting (``radius``, ``height`` ...) of the run."""
    agent = getattr(result.context, "agent", None)
    if agent is not None and hasattr(agent, name):
        return float(getattr(agent, name))
    return float(result.config.get("agent", {}).get(name, default))


def positions(graph: nx.Graph, nodes: Sequence[int]) -> np.ndarray:
    """(len(nodes), 3) float64 positions of ``nodes``."""
    if not len(nodes):
        return np.zeros((0, 3))
    return np.asarray([graph.nodes[n]["pos"] for n in nodes], dtype=np.float64).reshape(-1, 3)


def edge_list(graph: nx.Graph) -> list[tuple[int, int]]:
    """Edges sorted; (parent, child) for a rooted forest, (low id, high id) otherwise."""
    if graph.is_directed():
        return sorted((int(u), int(v)) for u, v in graph.edges)
    return sorted(tuple(sorted((int(u), int(v)))) for u, v in graph.edges)  # type: ignore[misc]


def is_loop_edge(graph: nx.Graph, u: int, v: int) -> bool:
    """Whether (u, v) is a loop edge of a rooted structure with loops (see :mod:`g2s_core.rooted`)."""
    return bool(graph.edges[u, v].get("loop", False))


def floors(heights: Sequence[float], gap: float) -> list[np.ndarray]:
    """Group indices of ``heights`` into floors: sorted heights split where two neighbours differ by more than ``gap``.

    Returns index arrays, lowest floor first.
    """
    heights = np.asarray(heights, dtype=np.float64)
    if len(heights) == 0:
        return []
    order = np.argsort(heights, kind="stable")
    breaks = np.nonzero(np.diff(heights[order]) > gap)[0] + 1
    return [np.sort(part) for part in np.split(order, breaks)]


def feature_records(result: RunResult, kind: str) -> list[dict[str, Any]]:
    """The records named ``kind`` (``"chokepoints"``, ``"regions"``) that the first analyzer
    returning them gave (``[]`` when none did)."""
    for features in result.features.values():
        if kind in features:
            return list(features[kind])
    return []


def triangle_regions(result: RunResult) -> np.ndarray | None:
    """(DT,) int64, the region of each navmesh detail triangle (-1 outside every region);
    ``None`` when the run has no navmesh or no regions."""
    navmesh = result.context.navmesh
    records = feature_records(result, "regions")
    if navmesh is None or not records or not len(getattr(navmesh, "detail_triangles", ())):
        return None
    labels = np.full(navmesh.polygon_count, -1, dtype=np.int64)
    for record in records:
        labels[np.asarray(record["polygons"], dtype=np.int64)] = int(record["id"])
    return labels[np.asarray(navmesh.detail_polygon, dtype=np.int64)]


def tree_parents(graph: nx.Graph) -> dict[int, int]:
    """Each node's parent in its rooted tree: :func:`g2s_core.rooted.tree_parent` of every node of a directed
    graph, in one pass over the in-edges (the writers list every node); ``{}`` for an undirected graph."""
    parents: dict[int, int] = {}
    if graph.is_directed():
        # in-edges come per node in the order of its predecessors, as tree_parent reads them: the first
        # predecessor that is not a loop partner is the parent
        for parent, child, loop in graph.in_edges(data="loop", default=False):
            if not loop and child not in parents:
                parents[child] = parent
    return parents
