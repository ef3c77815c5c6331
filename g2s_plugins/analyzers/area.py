"""Area: the walkable area each structure node stands for, m².

Every node of the initial graph gives its area to its nearest structure node
along the graph, so nodes removed by simplification count for the node that
absorbed them (:func:`g2s_plugins.traffic.represented_area`).
Cost: one multi-source Dijkstra, O(m + n log n).
"""

from __future__ import annotations

from collections.abc import Mapping

from g2s_core.lazy import lazy_module
from g2s_core.model import RunContext
from g2s_core.plugin import PluginParams, hookimpl
from g2s_plugins import traffic

nx = lazy_module("networkx")

NAME = "area"


class Params(PluginParams):
    """This plugin takes no parameters."""


@hookimpl
def g2s_analyze(structure: nx.Graph, params: Params, context: RunContext) -> Mapping[int, float]:
    """Represented walkable area of every structure node."""
    return traffic.represented_area(context.graph, structure)
