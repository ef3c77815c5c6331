"""Closeness: root each tree at the node with the smallest total distance to the other nodes.

Closeness of the Steiner forest (Wasserman-Faust form, per tree), in O(n)
by rerooting (:func:`g2s_plugins.centrality.tree_closeness`). With
``weighted`` distances are edge lengths in metres (the tree's metric
centre, its median); without, hop counts.
"""

from __future__ import annotations

from collections.abc import Mapping

from g2s_core.lazy import lazy_module
from g2s_core.model import RunContext
from g2s_core.plugin import hookimpl
from g2s_plugins import centrality

nx = lazy_module("networkx")

NAME = "closeness"
Params = centrality.ClosenessParams


@hookimpl
def g2s_root_scores(tree: nx.Graph, params: Params, context: RunContext) -> Mapping[int, float]:
    """Closeness of every node of the forest."""
    return centrality.closeness(tree, weighted=params.weighted)
