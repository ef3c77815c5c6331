"""The loop adder's bounded search along the structure, on a hand-checkable path."""

from __future__ import annotations

import networkx as nx

from g2s_plugins.loops.spanner import _within


def test_within_follows_the_structure_and_the_joined_paths_up_to_the_limit():
    structure = nx.Graph()
    structure.add_weighted_edges_from([(0, 1, 1.0), (1, 2, 2.0)])
    joined = {2: [(3, 1.5)], 3: [(2, 1.5)]}  # a path 2 - 3 added after the structure was built
    assert _within(structure._adj, joined, 0, 3, 4.5)
    assert _within(structure._adj, joined, 3, 0, 4.5)  # from a joined node back onto the structure
    assert not _within(structure._adj, joined, 0, 3, 4.4)
    assert not _within(structure._adj, {}, 0, 3, 100.0)  # 3 is on no structure edge
