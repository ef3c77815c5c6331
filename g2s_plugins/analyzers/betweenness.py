"""Betweenness: the share of shortest paths through each node, the paper's indicator of likely traffic.

On a tree or forest (the usual structure) the exact O(n) subtree-size
formula is used; on a graph with cycles, Brandes' algorithm (rustworkx
unweighted; igraph, or networkx without it, weighted). See
:mod:`g2s_plugins.centrality`.

``weight_by_area`` counts each pair of nodes in proportion to the product
of the walkable areas they stand for (:func:`g2s_plugins.traffic.represented_area`),
so a big room weighs more than a corridor cut into many small polygons:
O(n) on trees (subtree area sums), shortest-path trees from every node (or
sampled sources above 256 nodes) on structures with loops.
"""

from __future__ import annotations

from collections.abc import Mapping

from pydantic import Field

from g2s_core.lazy import lazy_module
from g2s_core.model import RunContext
from g2s_core.plugin import PluginParams, hookimpl
from g2s_plugins import centrality, traffic

nx = lazy_module("networkx")

NAME = "betweenness"


class Params(PluginParams):
    """Path lengths and scaling."""

    weighted: bool = Field(False, description="shortest paths by edge length (metres) instead of hop count; no effect on trees")
    normalized: bool = Field(True, description="divide by (n-1)(n-2)/2, the number of pairs of other nodes (area weighting: by the total pair weight)")
    weight_by_area: bool = Field(False, description="count each pair in proportion to the product of the walkable areas its two nodes stand for")


@hookimpl
def g2s_analyze(structure: nx.Graph, params: Params, context: RunContext) -> Mapping[int, float]:
    """Betweenness of every node of the structure."""
    areas = traffic.represented_area(context.graph, structure) if params.weight_by_area else None
    return centrality.betweenness(structure, weighted=params.weighted, normalized=params.normalized, node_weight=areas)
