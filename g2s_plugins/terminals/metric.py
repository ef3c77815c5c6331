"""Metric: the nodes that rank highest by a centrality metric, optionally among nodes of a given degree.

The paper's graph-metric terminals (Sec. 3.1.2, Table 1): degree,
betweenness, closeness, eigenvector or Katz centrality (see
:mod:`g2s_plugins.centrality` for the definitions, normalisation and cost).
``min_degree``/``max_degree`` first keep only nodes whose number of
neighbours lies in that range, then the metric ranks them: the paper's
"hybrid" strategy (filter by degree, rank by centrality).

Selection, with exactly one of

* ``top_k``: the k best nodes *of each connected component*,
* ``top_fraction``: the best ceil(f * c) nodes of each component, c being the
  number of nodes of that component that pass the degree filter,
* ``threshold``: every node whose value is >= the threshold (values as
  :mod:`g2s_plugins.centrality` returns them, i.e. normalised over the whole
  graph as networkx does).

A disconnected graph (several walkable areas) gets terminals in every
component: the metrics are computed without paths between components and
the selection is made within each component. Equal values (to 12
significant digits) are ranked by ascending node id. The terminals are
returned by ascending id.

Complexity: the metric's (the table in :mod:`g2s_plugins.centrality`), plus
O(n log n) to split the graph into components and rank each one's nodes.
"""

from __future__ import annotations

import math
from typing import Literal

from pydantic import Field, model_validator
from pydantic_core import PydanticCustomError

from g2s_core.lazy import lazy_module
from g2s_core.model import RunContext, Terminals
from g2s_core.plugin import PluginParams, hookimpl
from g2s_core.ties import tie_value
from g2s_plugins import centrality

nx = lazy_module("networkx")

NAME = "metric"


class Params(PluginParams):
    """Metric, selection rule (exactly one of top_k, top_fraction, threshold) and degree filter."""

    metric: Literal["degree", "betweenness", "closeness", "eigenvector", "katz"] = Field(
        "betweenness", description="centrality that ranks the nodes"
    )
    attenuation: float = Field(
        0.1, gt=0, description="Katz attenuation alpha; must be below 1/largest adjacency eigenvalue"
    )
    weighted: bool = Field(
        False, description="use edge lengths (weight) as distances (betweenness, closeness) or strengths (others)"
    )
    top_k: int | None = Field(None, ge=1, description="select the k best nodes of each connected component")
    top_fraction: float | None = Field(
        None, gt=0, le=1, description="select this fraction (rounded up) of each component's candidate nodes"
    )
    threshold: float | None = Field(None, description="select every node whose metric value is >= this")
    min_degree: int | None = Field(None, ge=0, description="only nodes with at least this many neighbours")
    max_degree: int | None = Field(None, ge=0, description="only nodes with at most this many neighbours")

    @model_validator(mode="after")
    def _one_selection(self) -> Params:
        chosen = [name for name in ("top_k", "top_fraction", "threshold") if getattr(self, name) is not None]
        if len(chosen) != 1:
            got = "none of them" if not chosen else " and ".join(chosen)
            raise PydanticCustomError(
                "selection", "give exactly one of top_k, top_fraction, threshold (got {got})", {"got": got}
            )
        if self.min_degree is not None and self.max_degree is not None and self.min_degree > self.max_degree:
            raise PydanticCustomError(
                "degree_range",
                "min_degree ({low}) is larger than max_degree ({high}); no node can pass",
                {"low": self.min_degree, "high": self.max_degree},
            )
        return self


def rank_key(node: int, value: float) -> tuple[float, int]:
    """Sort key that ranks higher ``value`` first and breaks ties (:func:`~g2s_core.ties.tie_value`) by lower node id."""
    return (-tie_value(value), node)


def _passes_degree(degree: int, params: Params) -> bool:
    if params.min_degree is not None and degree < params.min_degree:
        return False
    return params.max_degree is None or degree <= params.max_degree


@hookimpl
def g2s_select_terminals(graph: nx.Graph, params: Params, context: RunContext) -> Terminals:
    """Rank the (degree-filtered) nodes of each component by the metric and keep the best.

    Raises:
        G2SError: the metric does not converge (Katz attenuation too large,
            eigenvector solver failure).
    """
    values = centrality.compute(
        graph, params.metric, weighted=params.weighted, normalized=True, attenuation=params.attenuation
    )
    degrees = dict(graph.degree())
    chosen: list[int] = []
    for component in centrality.components(graph):
        candidates = [node for node in component if _passes_degree(degrees[node], params)]
        if params.threshold is not None:
            chosen.extend(node for node in candidates if values[node] >= params.threshold)
            continue
        ranked = sorted(candidates, key=lambda node: rank_key(node, values[node]))
        if params.top_k is not None:
            count = params.top_k
        else:
            # rounded first so that e.g. 0.3 * 10 (= 3.0000000000000004) gives 3
            count = math.ceil(round(params.top_fraction * len(candidates), 9))
        chosen.extend(ranked[:count])
    return Terminals(nodes=tuple(sorted(chosen)))
