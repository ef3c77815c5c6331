"""What several writers share: the final graph of a run, numbers, floors, the stage table."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import networkx as nx
import numpy as np

from g2s_core.model import RunResult, StageStats

FLOAT_DIGITS = 9
"""Floats in the written files keep this many significant digits (``format(x, '.9g')``)."""

FINAL_STAGES = (("simplify", "structure"), ("roots", "forest"), ("steiner", "steiner"), ("graph", "graph"))
"""Where the "final structure" of a run comes from: the last of these that ran."""

STEP_ROWS = (
    ("graph", "Step 1", "initial graph"),
    ("terminals", "Step 2", "terminals"),
    ("steiner", "Step 3", "Steiner tree"),
    ("loops", "Step 3", "loops kept"),
    ("roots", "Step 4", "rooted trees"),
    ("simplify", "Step 5", "simplification"),
    ("analysis", "Post-process", "analysis"),
)
"""The paper's per-stage table rows: (stage, step, label)."""


def number(value: Any) -> float | None:
    """``value`` as a float rounded to :data:`FLOAT_DIGITS` significant digits; ``None`` if not finite.

    ``-0.0`` becomes ``0.0`` so that the sign of a zero never differs between runs.
    """
    x = float(value)
    if not math.isfinite(x):
        return None
    return float(format(x, f".{FLOAT_DIGITS}g")) + 0.0


def vector(value: Any) -> list[float | None] | None:
    """A 3-vector as a list of rounded floats (``None`` when absent)."""
    if value is None:
        return None
    return [number(v) for v in np.asarray(value, dtype=np.float64).reshape(-1)]


def final_graph(result: RunResult) -> tuple[str | None, nx.Graph | None]:
    """``(stage, graph)`` of the most processed graph the run produced (see :data:`FINAL_STAGES`)."""
    for stage, attribute in FINAL_STAGES:
        graph = getattr(result, attribute)
        if graph is not None:
            return stage, graph
    return None, None


def roots_of(graph: nx.Graph | None) -> list[int]:
    """The roots of a rooted forest (``graph.graph["roots"]``), else ``[]``."""
    if graph is None or not graph.is_directed():
        return []
    roots = graph.graph.get("roots")
    if roots is None:
        roots = [n for n in graph.nodes if graph.in_degree(n) == 0]
    return [int(r) for r in roots]


def terminal_ids(result: RunResult) -> list[int]:
    """The terminals in the selector's order (``[]`` before step 2)."""
    return [int(t) for t in result.terminals.nodes] if result.terminals is not None else []


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


def stage_rows(stages: Sequence[StageStats]) -> list[tuple[str, str, str, str, str]]:
    """The per-stage table as strings: (step, label, t (ms), #N, #E), then the total row.

    #N is the terminal count for step 2, the node count otherwise, as in the paper.
    """
    by_name = {s.stage: s for s in stages}
    rows = []
    for stage, step, label in STEP_ROWS:
        stats = by_name.get(stage)
        if stats is None:
            continue
        nodes = stats.terminals if stage == "terminals" else stats.nodes
        rows.append((step, label, milliseconds(stats.seconds), _count(nodes), _count(stats.edges)))
    total = sum(s.seconds for s in stages)
    rows.append(("total", "", milliseconds(total), "", ""))
    return rows


def milliseconds(seconds: float) -> str:
    return "" if seconds is None or not math.isfinite(seconds) else f"{seconds * 1000:.1f}"


def _count(value: int | None) -> str:
    return "" if value is None else str(value)
