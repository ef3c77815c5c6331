"""Point: root each tree at its node nearest a given point (e.g. a spawn or an objective).

Score = minus the Euclidean distance from the node's ``pos`` to ``point``.
Complexity: O(n).
"""

from __future__ import annotations

from collections.abc import Mapping

from pydantic import Field

from g2s_core.lazy import lazy_module
from g2s_core.model import RunContext
from g2s_core.plugin import PluginParams, hookimpl
from g2s_plugins.roots._nearness import nearness

nx = lazy_module("networkx")

NAME = "point"


class Params(PluginParams):
    """The point the roots should be near."""

    point: tuple[float, float, float] = Field(
        (0.0, 0.0, 0.0), strict=False, description="[x, y, z] in metres, mesh frame (default: the origin)"
    )


@hookimpl
def g2s_root_scores(tree: nx.Graph, params: Params, context: RunContext) -> Mapping[int, float]:
    """Minus each node's distance to ``point``."""
    return nearness(tree, params.point)
