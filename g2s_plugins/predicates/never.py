"""Never: remove nothing; the structure is the rooted Steiner forest itself.

Cost per call: O(1).
"""

from __future__ import annotations

from collections.abc import Callable

from g2s_core.lazy import lazy_module
from g2s_core.model import RunContext
from g2s_core.plugin import PluginParams, hookimpl

nx = lazy_module("networkx")

NAME = "never"


class Params(PluginParams):
    """This plugin takes no parameters."""


def _never(tree: nx.DiGraph, a: int, b: int, c: int) -> bool:
    return False


@hookimpl
def g2s_simplify_predicate(params: Params, context: RunContext) -> Callable[[nx.DiGraph, int, int, int], bool]:
    """A predicate that is always false."""
    return _never
