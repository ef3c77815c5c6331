"""Nearness to a point as a root score, shared by the ``center`` and ``point`` root selectors."""

from __future__ import annotations

import networkx as nx
import numpy as np


def nearness(tree: nx.Graph, target: np.ndarray) -> dict[int, float]:
    """Minus the distance from every node's ``pos`` to ``target`` (higher = nearer), metres. O(n)."""
    nodes = list(tree.nodes)
    if not nodes:
        return {}
    positions = np.asarray([tree.nodes[node]["pos"] for node in nodes], dtype=np.float64)
    distances = np.linalg.norm(positions - np.asarray(target, dtype=np.float64), axis=1)
    return dict(zip(nodes, (-distances).tolist()))
