"""Center: root each tree at its node nearest the centre of the mesh's bounding box.

Score = minus the Euclidean distance from the node's ``pos`` to
``context.centre``. Complexity: O(n).
"""

from __future__ import annotations

from collections.abc import Mapping

import networkx as nx
import numpy as np

from g2s_core.model import RunContext
from g2s_core.plugin import PluginParams, hookimpl

NAME = "center"


class Params(PluginParams):
    """This plugin takes no parameters."""


def nearness(tree: nx.Graph, target: np.ndarray) -> dict[int, float]:
    """Minus the distance from every node's ``pos`` to ``target`` (higher = nearer)."""
    nodes = list(tree.nodes)
    if not nodes:
        return {}
    positions = np.asarray([tree.nodes[node]["pos"] for node in nodes], dtype=np.float64)
    distances = np.linalg.norm(positions - np.asarray(target, dtype=np.float64), axis=1)
    return dict(zip(nodes, (-distances).tolist()))


@hookimpl
def g2s_root_scores(tree: nx.Graph, params: Params, context: RunContext) -> Mapping[int, float]:
    """Minus each node's distance to the mesh centre."""
    return nearness(tree, context.centre)
