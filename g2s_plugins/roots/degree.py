"""Degree: root each tree at its node with the most branches (or the most edge length when weighted).

Complexity: O(n). Many nodes of a tree share the highest degree; the
pipeline then takes the one nearest the mesh centre, then the lowest id.
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
    """Count neighbours or sum edge lengths."""

    weighted: bool = Field(False, description="score by the summed length of the node's edges instead of their number")


@hookimpl
def g2s_root_scores(tree: nx.Graph, params: Params, context: RunContext) -> Mapping[int, float]:
    """Number of neighbours (or summed edge lengths) of every node."""
    return centrality.degree(tree, weighted=params.weighted, normalized=False)
