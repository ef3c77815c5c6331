"""What several writers share: numbers, floors, edges; the final graph and stage table come from core."""

from __future__ import annotations

import math
from collections.abc import Sequence
from itertools import repeat
from typing import Any

import numpy as np

from g2s_core.lazy import lazy_module
from g2s_core.model import RunResult
from g2s_core.summary import final_graph, metric_lines, roots_of, stage_rows

nx = lazy_module("networkx")

__all__ = ["agent_value", "coordinate", "coordinates", "edge_list", "edges_with_data", "final_graph", "floors", "is_loop_edge",
           "metric_lines", "number", "numbers", "positions", "roots_of", "stage_rows", "terminal_ids", "tree_parents",
           "vector", "vectors"]

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


def numbers(values: Sequence[Any]) -> list[float | None]:
    """:func:`number` of each of ``values`` (``None`` stays ``None``), rounded by C loops instead of a call each."""
    return _rounded(values, coordinates=False)


def coordinates(values: Sequence[Any]) -> list[float | None]:
    """:func:`coordinate` of each of ``values`` (``None`` stays ``None``), as :func:`numbers` does."""
    return _rounded(values, coordinates=True)


def _rounded(values: Sequence[Any], coordinates: bool) -> list[float | None]:
    missing = [value is None for value in values]
    if any(missing):
        rounded = iter(_rounded([v for v, absent in zip(values, missing) if not absent], coordinates))
        return [None if absent else next(rounded) for absent in missing]
    floats = np.array(list(map(float, values)), dtype=np.float64)
    result: list[float | None] = (significant_digits(floats) + 0.0).tolist()  # + 0.0: -0.0 -> 0.0
    if coordinates:
        with np.errstate(invalid="ignore"):
            far = np.flatnonzero(np.abs(floats) >= _FINE_FROM)  # not nan; infinities are left to the next line
        for index in far.tolist():
            result[index] = coordinate(float(floats[index]))
    if not np.isfinite(floats).all():
        result = [x if x is not None and math.isfinite(x) else None for x in result]
    return result


_POWERS_OF_TEN = np.array([float(f"1e{k}") for k in range(23)])
"""10^0 .. 10^22, the powers of ten a float64 holds exactly."""


def significant_digits(values: np.ndarray) -> np.ndarray:
    """``float(format(x, '.9g'))`` of each float64 of ``values``, the same floats, without a string each.

    The nearest integer to x * 10^k (k = 8 - exponent, at most 22 either way) is its
    9-digit decimal, rounded half to even as ``format`` does, unless the
    product lies within its rounding error (1e-7 at most) of a half; then
    m / 10^k (or m * 10^-k), one correctly rounded operation on exact
    operands, is the float nearest that decimal, which is what ``float()``
    parses. The values this cannot settle (near a half, tiny, huge, zero,
    not finite: a few in a million) go through ``format``.
    """
    values = np.asarray(values, dtype=np.float64)
    result = values.copy()
    magnitude = np.abs(values)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        shift = (FLOAT_DIGITS - 1) - np.floor(np.log10(magnitude))
        usable = np.isfinite(shift) & (np.abs(shift) <= 22)
        k = np.where(usable, shift, 0).astype(np.int64)
        scale = _POWERS_OF_TEN[np.abs(k)]
        scaled = np.where(k >= 0, values * scale, values / scale)
        digits = np.rint(scaled)
        # 9 digits, or 10^9 when x rounds up to the next power of ten (a wrong exponent gives 8 or 10 digits)
        nine_digits = (np.abs(digits) >= 10.0 ** (FLOAT_DIGITS - 1)) & (np.abs(digits) <= 10.0 ** FLOAT_DIGITS)
        settled = usable & nine_digits & (np.abs(np.abs(scaled - digits) - 0.5) > 1e-6)
        result[settled] = np.where(k >= 0, digits / scale, digits * scale)[settled]
    for index in np.flatnonzero(~settled).tolist():
        result[index] = float(format(values[index], _ROUNDED))
    return result


def vectors(values: Sequence[Any]) -> list[list[float | None] | None]:
    """:func:`vector` of each of ``values``: their components rounded together by :func:`coordinates`."""
    present = [value for value in values if value is not None]
    try:
        array = np.asarray(present, dtype=np.float64)
    except (TypeError, ValueError):  # ragged or not numbers: one by one, as vector() takes (or refuses) them
        array = None
    if array is None or array.ndim != 2 or not array.shape[1]:
        return [vector(value) for value in values]
    flat = coordinates(array.reshape(-1).tolist())
    rows = iter(list(map(list, zip(*[iter(flat)] * array.shape[1]))))
    return [None if value is None else next(rows) for value in values]


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
    return sorted(_oriented(graph, graph.edges))


def edges_with_data(graph: nx.Graph) -> list[tuple[int, int, dict[str, Any]]]:
    """:func:`edge_list`'s edges, in its order, each with its attribute dict (read as the edges are listed:
    looking each up again costs a networkx view per edge)."""
    edges = list(graph.edges(data=True))
    pairs = _oriented(graph, edges)
    return [(*pairs[i], edges[i][2]) for i in sorted(range(len(pairs)), key=pairs.__getitem__)]


def _oriented(graph: nx.Graph, edges: Sequence[tuple]) -> list[tuple[int, int]]:
    """``(u, v)`` of each edge as ints: (parent, child) in a directed graph, (low id, high id) otherwise."""
    pairs = [(int(edge[0]), int(edge[1])) for edge in edges]
    return pairs if graph.is_directed() else [(u, v) if u <= v else (v, u) for u, v in pairs]


def is_loop_edge(graph: nx.Graph, u: int, v: int) -> bool:
    """Whether (u, v) is a loop edge of a rooted structure with loops (see :mod:`g2s_core.rooted`)."""
    return bool(graph.edges[u, v].get("loop", False))


STOREY_BIN = 0.1
"""Height bins (m) in which :func:`floors` sums the walkable area. A flat floor's navmesh lies in one or two
bins; a ramp, a stair or a hill spreads its area over many (measured on the generated levels, docs/outputs.md)."""

BIN_SLACK = 1e-3
"""Share of a :data:`STOREY_BIN` (0.1 mm) under a bin's lower edge that still counts in it: more than the
rounding of single-precision heights of levels up to a few kilometres high, less than any modelled offset."""

STOREY_SHARE = 0.01
"""The share of the walkable area a height bin holds (a sloped triangle counted over the bins it spans) for
:func:`floors` to see a storey there. Measured on 20 levels (docs/outputs.md): the smallest storey holds 1.05 %
(the castle's tower tops); a bin more than 0.2 m from every storey at most 0.23 % on the built levels (stairs,
ramps, stadium tiers), 0.60 % on three terrains, 0.70 % on nav_test.obj and the market kind, 0.88 % on the
village's rolling ground; the forest's hills reach 1.10 % in one bin, one band."""


def floors(heights: Sequence[float], gap: float, ground: np.ndarray | None = None) -> list[np.ndarray]:
    """Group indices of ``heights`` (m) into floors, lowest first, as index arrays.

    Without ``ground`` (or with none of it), sorted heights are split where two neighbours differ by more
    than ``gap`` (the agent height, m). With ``ground``, (T, 3, 3) walkable triangles (m, Y up), they are also
    split between storeys: the area of each triangle is summed in :data:`STOREY_BIN` height bins at its
    centre's height, a sloped one counting only the share that falls in one bin (``STOREY_BIN`` over its
    height span, up to 1); a bin holding :data:`STOREY_SHARE` of the whole area is part of a storey, and
    storey bins at least ``gap`` apart (bin to bin) belong to different storeys, so a storey is a band of
    dense area whatever stairs or ramps join it to the next, and hills spread thinly over many heights hold
    none or one. The floors of the gap rule are then split between the storey bands within ``gap`` of their
    span, each height going to the nearest such band (the lower on a tie).

    Complexity: O(T log T + N log N + N K) for T triangles, N heights and K storey bands.
    """
    heights = np.asarray(heights, dtype=np.float64)
    if len(heights) == 0:
        return []
    order = np.argsort(heights, kind="stable")
    y_sorted = heights[order]
    run = np.concatenate([[0], np.cumsum(np.diff(y_sorted) > gap)])  # the gap rule's floor of each sorted height
    band = np.zeros(len(heights), dtype=np.int64)
    triangles = np.zeros((0, 3, 3)) if ground is None else np.asarray(ground, dtype=np.float64).reshape(-1, 3, 3)
    area = 0.5 * np.linalg.norm(np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0]), axis=1)
    if area.sum() > 0:
        y = triangles[:, :, 1]
        span = y.max(axis=1) - y.min(axis=1)
        counted = area * STOREY_BIN / np.maximum(span, STOREY_BIN)
        # a storey at a round height (5.0 m) whose single-precision navmesh height reads 4.9999998 stays in the bin
        # of 5.0: without the slack, storeys exactly an agent height apart fell one bin short of it and merged
        bins, which = np.unique(np.floor(y.mean(axis=1) / STOREY_BIN + BIN_SLACK).astype(np.int64), return_inverse=True)
        dense = bins[np.bincount(which.reshape(-1), weights=counted) >= STOREY_SHARE * area.sum()]
        if len(dense):
            parts = np.split(dense, np.flatnonzero(np.diff(dense) >= round(gap / STOREY_BIN)) + 1)
            low = np.array([p[0] for p in parts])[None, :] * STOREY_BIN
            high = (np.array([p[-1] for p in parts])[None, :] + 1) * STOREY_BIN
            lowest = y_sorted[np.searchsorted(run, run, side="left")][:, None]  # the span of each height's floor
            highest = y_sorted[np.searchsorted(run, run, side="right") - 1][:, None]
            # only the bands within an agent height of a floor's span split it: a landing or a platform that is
            # a floor by the gap rule alone, far from every storey, stays whole
            inside = np.maximum(np.maximum(low - highest, lowest - high), 0.0) <= gap
            distance = np.maximum(np.maximum(low - y_sorted[:, None], y_sorted[:, None] - high), 0.0)
            band = np.where(inside, distance, np.inf).argmin(axis=1)
    breaks = np.nonzero((np.diff(run) != 0) | (np.diff(band) != 0))[0] + 1
    return [np.sort(part) for part in np.split(order, breaks)]


def whole_numbers(values: Sequence[float]) -> bool:
    """Whether every one of ``values`` (finite) is a whole number, as depth and degree are: a colour bar of them
    ticks whole numbers only, a tick at 0.5 naming a value no node can have."""
    return bool(values) and all(float(v).is_integer() for v in values)


def value_title(result: RunResult, key: str) -> str:
    """The analysis value ``key`` as a colour bar names it: the ``flow`` analyzer's ``aggregate: percentile``
    (the map-analysis presets' heat map) gives ranks 0-100, which read as counts of walkers without the unit."""
    for entry in result.config.get("analyzers") or ():
        if not isinstance(entry, dict) or (entry.get("key") or entry.get("plugin")) != key:
            continue
        if entry.get("plugin") == "flow" and (entry.get("params") or {}).get("aggregate") == "percentile":
            return f"{key}, percentile rank 0-100"
    return key


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
