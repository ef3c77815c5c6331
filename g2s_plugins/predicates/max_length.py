"""Max length: remove B only when the new edge A -> C would be at most ``max_length`` metres long.

A purely geometric predicate for graphs without a navigation mesh, or to
cap the length of the structure's edges. Cost per call: O(1).
"""

from __future__ import annotations

import math
from collections.abc import Callable

from pydantic import Field

from g2s_core.lazy import lazy_module
from g2s_core.model import RunContext
from g2s_core.plugin import PluginParams, hookimpl

nx = lazy_module("networkx")

NAME = "max_length"


class Params(PluginParams):
    """The longest edge simplification may create."""

    max_length: float = Field(10.0, gt=0, description="longest allowed edge A -> C, metres")


@hookimpl
def g2s_simplify_predicate(params: Params, context: RunContext) -> Callable[[nx.DiGraph, int, int, int], bool]:
    """``P(tree, a, b, c)`` = |pos(a) - pos(c)| <= max_length."""
    limit = params.max_length

    def predicate(tree: nx.DiGraph, a: int, b: int, c: int) -> bool:
        return math.dist(tree.nodes[a]["pos"], tree.nodes[c]["pos"]) <= limit

    return predicate
