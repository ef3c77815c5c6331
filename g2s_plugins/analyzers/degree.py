"""Degree: the number of structure edges at each node (junctions > 2, dead ends = 1).

Complexity: O(n + m).
"""

from __future__ import annotations

from collections.abc import Mapping

from pydantic import Field

from g2s_core.lazy import lazy_module
from g2s_core.model import RunContext
from g2s_core.plugin import PluginParams, hookimpl
from g2s_plugins import centrality

nx = lazy_module("networkx")

NAME = "degree"


class Params(PluginParams):
    """Count or length, raw or scaled."""

    weighted: bool = Field(False, description="sum the lengths (metres) of the node's edges instead of counting them")
    normalized: bool = Field(False, description="divide by n-1, as networkx's degree_centrality does")


@hookimpl
def g2s_analyze(structure: nx.Graph, params: Params, context: RunContext) -> Mapping[int, float]:
    """Degree of every node of the structure."""
    return centrality.degree(structure, weighted=params.weighted, normalized=params.normalized)
