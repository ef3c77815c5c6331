"""Closeness: how near each node is to the rest of its structure (reciprocal mean distance).

Wasserman-Faust closeness as networkx defines it, per component; O(n) on
trees and forests, one shortest-path search per node otherwise. See
:mod:`g2s_plugins.centrality`.
"""

from __future__ import annotations

from collections.abc import Mapping

import networkx as nx
from pydantic import Field

from g2s_core.model import RunContext
from g2s_core.plugin import PluginParams, hookimpl
from g2s_plugins import centrality

NAME = "closeness"


class Params(PluginParams):
    """Distances in metres or in hops."""

    weighted: bool = Field(True, description="measure distances by edge length (metres) instead of hop count")


@hookimpl
def g2s_analyze(structure: nx.Graph, params: Params, context: RunContext) -> Mapping[int, float]:
    """Closeness of every node of the structure."""
    return centrality.closeness(structure, weighted=params.weighted)
