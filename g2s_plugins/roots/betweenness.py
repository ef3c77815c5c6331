"""Betweenness: root each tree at the node on the most paths between other nodes (the paper's choice).

The score is the exact betweenness of the Steiner forest, computed in O(n)
from subtree sizes (:func:`g2s_plugins.centrality.tree_betweenness`); edge
lengths do not matter on a tree. The paper found this gives the most
balanced, structurally meaningful roots (Sec. 3.1.4); equal scores are
broken by the pipeline (nearest to the mesh centre, then lowest id).
"""

from __future__ import annotations

from collections.abc import Mapping

from g2s_core.lazy import lazy_module
from g2s_core.model import RunContext
from g2s_core.plugin import PluginParams, hookimpl
from g2s_plugins import centrality

nx = lazy_module("networkx")

NAME = "betweenness"


class Params(PluginParams):
    """This plugin takes no parameters."""


@hookimpl
def g2s_root_scores(tree: nx.Graph, params: Params, context: RunContext) -> Mapping[int, float]:
    """Normalised betweenness of every node of the forest."""
    return centrality.betweenness(tree, weighted=False, normalized=True)
