"""Depth: each node's number of edges from the root of its tree (root = 0).

The pipeline stores ``depth`` on every node of the simplified structure, and
this analyzer reports it. For a structure without those attributes the hop
depth is found by breadth-first search from ``structure.graph["roots"]``.
Complexity: O(n).
"""

from __future__ import annotations

from collections.abc import Mapping

from g2s_core.errors import PluginError
from g2s_core.lazy import lazy_module
from g2s_core.model import RunContext
from g2s_core.plugin import PluginParams, hookimpl

nx = lazy_module("networkx")

NAME = "depth"


class Params(PluginParams):
    """This plugin takes no parameters."""


@hookimpl
def g2s_analyze(structure: nx.Graph, params: Params, context: RunContext) -> Mapping[int, float]:
    """Hop depth of every node from its root.

    Raises:
        PluginError: the structure has neither ``depth`` on every node nor
            ``graph["roots"]``, or a node is not reachable from any root.
    """
    depths = nx.get_node_attributes(structure, "depth")
    if len(depths) == structure.number_of_nodes():
        return {node: float(depths[node]) for node in structure}
    roots = structure.graph.get("roots")
    if not roots:
        raise PluginError('the depth analyzer needs node attributes "depth" or graph["roots"]; the structure has neither')
    depth: dict[int, int] = {}
    for root in roots:  # one tree per root, so the searches do not overlap
        for node, hops in nx.single_source_shortest_path_length(structure, root).items():
            depth[node] = min(hops, depth.get(node, hops))
    missing = sorted(node for node in structure if node not in depth)
    if missing:
        raise PluginError(f"the depth analyzer found nodes not reachable from any root: {missing[:5]}")
    return {node: float(depth[node]) for node in structure}
