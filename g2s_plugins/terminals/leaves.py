"""Leaves: every node of degree 1 (the graph's dead ends), as in the paper's map analysis.

Dead ends of a navigation graph cover the whole level, so joining them all
gives a structure that reaches every part of the map (paper, Sec. 3.3.2).
Complexity: O(n).
"""

from __future__ import annotations

from g2s_core.lazy import lazy_module
from g2s_core.model import RunContext, Terminals
from g2s_core.plugin import PluginParams, hookimpl

nx = lazy_module("networkx")

NAME = "leaves"


class Params(PluginParams):
    """This plugin takes no parameters."""


@hookimpl
def g2s_select_terminals(graph: nx.Graph, params: Params, context: RunContext) -> Terminals:
    """The nodes of degree 1 (networkx degree: a self-loop counts 2), by ascending id.

    One leaf makes a structure of one node, whatever the level's size (a street grid has almost no dead end):
    the run says so (none at all stops the run, with the pipeline's own warning).
    """
    leaves = tuple(sorted(node for node, degree in graph.degree() if degree == 1))
    if len(leaves) == 1:
        context.warn(f"leaves: the graph's {graph.number_of_nodes()} nodes have one dead end, so the structure is "
                     "that node; a level of loops has almost none, and the coverage terminal selector (the "
                     "map_analysis preset) reaches every area")
    return Terminals(nodes=leaves)
