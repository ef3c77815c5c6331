"""Nearness to a point as a root score, shared by the ``center`` and ``point`` root selectors."""

from __future__ import annotations

import numpy as np

from g2s_core.lazy import lazy_module

nx = lazy_module("networkx")


def nearness(tree: nx.Graph, target: np.ndarray) -> dict[int, float]:
    """Minus the distance from every node's ``pos`` to ``target`` (higher = nearer), metres. O(n)."""
    nodes = list(tree.nodes)
    if not nodes:
        return {}
    positions = np.asarray([tree.nodes[node]["pos"] for node in nodes], dtype=np.float64)
    offsets = positions - np.asarray(target, dtype=np.float64)
    distances = np.linalg.norm(offsets, axis=1)
    if not np.isfinite(distances).all():  # the squares overflow for a target 1e155 m away or more: hypot does not
        distances = np.hypot(np.hypot(offsets[:, 0], offsets[:, 1]), offsets[:, 2])
    return dict(zip(nodes, (-distances).tolist()))
