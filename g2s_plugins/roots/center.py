"""Center: root each tree at its node nearest the centre of the mesh's bounding box.

Score = minus the Euclidean distance from the node's ``pos`` to
``context.centre``. Complexity: O(n).
"""

from __future__ import annotations

from collections.abc import Mapping

from g2s_core.lazy import lazy_module
from g2s_core.model import RunContext
from g2s_core.plugin import PluginParams, hookimpl
from g2s_plugins.roots._nearness import nearness

nx = lazy_module("networkx")

NAME = "center"


class Params(PluginParams):
    """This plugin takes no parameters."""


@hookimpl
def g2s_root_scores(tree: nx.Graph, params: Params, context: RunContext) -> Mapping[int, float]:
    """Minus each node's distance to the mesh centre."""
    return nearness(tree, context.centre)
