"""Views of a run's result shared by the CLI and the output writers: its final graph, its stage table, its measures."""

from __future__ import annotations

import math
from collections.abc import Sequence

from g2s_core.lazy import lazy_module
from g2s_core.model import RunResult, StageStats
from g2s_core.stages import PIPELINE

nx = lazy_module("networkx")  # a result holds graphs only once it is loaded; the CLI imports this module for every command



def final_graph(result: RunResult) -> tuple[str | None, nx.Graph | None]:
    """``(stage, graph)`` of the most processed graph the run produced (the last pipeline stage whose result is a graph)."""
    for stage in reversed(PIPELINE):
        graph = getattr(result, stage.result)
        if isinstance(graph, nx.Graph):
            return stage.key, graph
    return None, None


def roots_of(graph: nx.Graph | None) -> list[int]:
    """The roots of a rooted forest (``graph.graph["roots"]``), else ``[]``."""
    if graph is None or not graph.is_directed():
        return []
    roots = graph.graph.get("roots")
    return [int(r) for r in (roots if roots is not None else (n for n, degree in graph.in_degree if degree == 0))]


def stage_rows(stages: Sequence[StageStats]) -> list[tuple[str, str, str, str, str]]:
    """The per-stage table as strings: (step, label, t (ms), #N, #E), then the total row.

    #N is the terminal count for step 2, the node count otherwise, as in the paper.
    """
    by_name = {s.stage: s for s in stages}
    rows = []
    for stage in PIPELINE:
        stats = by_name.get(stage.timing)
        if stats is None:
            continue
        nodes = stats.terminals if stage.key == "terminals" else stats.nodes
        rows.append((stage.step, stage.label, milliseconds(stats.seconds), _count(nodes), _count(stats.edges)))
    rows.append(("total", "", milliseconds(sum(s.seconds for s in stages)), "", ""))
    return rows


def outcome(result: RunResult) -> str:
    """What came out, in a designer's words: ``12 structure nodes, 7 openings`` (a map piece's), then each
    analyzer's records (``9 regions, 6 chokepoints``); ``83 graph nodes`` when the run stopped after step 1 (no
    structure was made); empty when the run stopped before a graph."""
    stage, graph = final_graph(result)
    counts = [(graph.number_of_nodes(), "graph nodes" if stage == "graph" else "structure nodes")] if graph is not None else []
    counts += [(len(result.terminals.openings), "openings")] if result.terminals is not None and result.terminals.openings else []
    counts += [(len(records), name) for features in result.features.values() for name, records in features.items() if isinstance(records, list)]
    return ", ".join(f"{count} {name[:-1] if count == 1 and name.endswith('s') else name}" for count, name in counts)


def metric_lines(result: RunResult) -> list[tuple[str, str]]:
    """``("evaluation (KEY)", "name value, ...")`` for each evaluator's measures, values to 4 significant digits."""
    return [(f"evaluation ({key})", ", ".join(f"{name} {value:.4g}" for name, value in measures.items()))
            for key, measures in result.metrics.items()]


def milliseconds(seconds: float | None) -> str:
    """``seconds`` in milliseconds to 0.1 ms, for the stage tables; empty when unknown (None, NaN, inf)."""
    return "" if seconds is None or not math.isfinite(seconds) else f"{seconds * 1000:.1f}"


def _count(value: int | None) -> str:
    return "" if value is None else str(value)
