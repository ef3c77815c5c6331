"""Distance along the structure from each node to its tree's root, in metres (or hops)."""

import networkx as nx
from pydantic import Field

from g2s_core.plugin import PluginParams, hookimpl

NAME = "root_distance"


class Params(PluginParams):
    hops: bool = Field(False, description="count edges instead of metres")


@hookimpl
def g2s_analyze(structure, params):
    values = {}
    weight = None if params.hops else "weight"
    for component in nx.connected_components(structure):
        root = next(n for n in component if structure.nodes[n].get("depth") == 0)
        values.update(nx.single_source_dijkstra_path_length(structure, root, weight=weight))
    return values
