"""Chokepoints: the narrow passages between regions, scored by the structure's traffic through them per metre of width.

See :mod:`g2s_plugins.decomposition` for the method. Needs the navmesh graph
builder. Value per structure node: the largest score of the chokepoints its
structure edges cross (0 elsewhere). Features: ``chokepoints``, a list of
records sorted by score (``id``, ``position``, ``portal``, ``width``,
``regions``, ``floors``, ``articulation``, ``traffic``, ``score``,
``polygons``). Cost: that of :func:`g2s_plugins.decomposition.decompose`
(one split per run for this analyzer and ``regions`` given the same split
settings: :func:`~g2s_plugins.decomposition.shared_decomposition`) plus the
structure's edge betweenness.
"""

from __future__ import annotations

from pydantic import Field

from g2s_core.lazy import lazy_module
from g2s_core.model import AnalyzerResult, RunContext
from g2s_core.plugin import hookimpl
from g2s_plugins import decomposition

nx = lazy_module("networkx")

NAME = "chokepoints"


class Params(decomposition.DecompositionParams):
    """Region split settings (shared with ``regions``) and how many chokepoints to report."""

    top_k: int | None = Field(None, ge=1, description="report only the k highest-scoring chokepoints (null: all)")


@hookimpl
def g2s_analyze(structure: nx.Graph, params: Params, context: RunContext) -> AnalyzerResult:
    """Chokepoint records and the score near every structure node."""
    navmesh = decomposition.require_navmesh(context, NAME)
    split = decomposition.shared_decomposition(navmesh, context.agent, params, context.mesh, context.graph)
    chokepoints, values = decomposition.score(split, structure)
    if params.top_k is not None:
        chokepoints = chokepoints[: params.top_k]
    return AnalyzerResult(values, {"chokepoints": chokepoints})
