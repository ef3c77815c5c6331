"""Structure leaves that no terminal needs (g2s_plugins/structure_leaves.py), on a hand-built tree of 1 m edges.

The graph and the forest are the same tree: a line 0-1-2-3-4 along x and a spur 2-5-6 along z, every edge 1 m,
rooted at 0. Nodes 0 and 4 are terminals; 6 is a waypoint at the end of its path.
"""

from __future__ import annotations

import math

import networkx as nx
import numpy as np

from g2s_core.simplify import forest_arrays
from g2s_plugins import traffic
from g2s_plugins.structure_leaves import pruned, represented, standing_for

POSITIONS = {0: (0, 0, 0), 1: (1, 0, 0), 2: (2, 0, 0), 3: (3, 0, 0), 4: (4, 0, 0), 5: (2, 0, 1), 6: (2, 0, 2)}
EDGES = [(0, 1), (1, 2), (2, 3), (3, 4), (2, 5), (5, 6)]


def tree(loop: tuple[int, int] | None = None) -> tuple[nx.DiGraph, nx.Graph]:
    """The rooted forest (terminals 0 and 4) and its initial graph; ``loop``: an extra graph edge that is a loop
    edge of the forest."""
    graph = nx.Graph()
    for node, pos in POSITIONS.items():
        graph.add_node(node, pos=pos, area=1.0)
    edges = EDGES + ([loop] if loop else [])
    graph.add_edges_from((u, v, {"weight": math.dist(POSITIONS[u], POSITIONS[v])}) for u, v in edges)
    forest = nx.DiGraph(roots=[0])
    depth = {0: 0, 1: 1, 2: 2, 3: 3, 4: 4, 5: 3, 6: 4}
    for node, pos in POSITIONS.items():
        forest.add_node(node, pos=pos, depth=depth[node], terminal=node in (0, 4))
    forest.add_edges_from(EDGES)
    if loop:
        forest.add_edge(*loop, loop=True)
    return forest, graph


def prune(kept: list[int], near: float, loop: tuple[int, int] | None = None, rank: np.ndarray | None = None,
          max_step: float | None = None) -> list[int]:
    forest, graph = tree(loop)
    arrays = forest_arrays(forest)
    answer = pruned(arrays, np.isin(arrays.ids, kept), np.zeros((0, 2), np.int64), np.zeros(0, bool),
                    traffic.surface_arrays(graph), radius=6.0, near=near, rank=rank, max_step=max_step)
    return sorted(arrays.ids[answer].tolist())


def test_a_spur_within_reach_goes_node_by_node():
    # 6 goes (1 m from 5), then 5, now a leaf (6 is 2 m from 2): the spur is within 5 m of the line
    assert prune([0, 1, 2, 3, 4, 5, 6], near=5.0) == [0, 1, 2, 3, 4]


def test_a_spur_stays_where_a_node_would_leave_near():
    # without 6, node 6 is 1 m from 5; without 5 as well it would be 2 m from 2, more than 1.5
    assert prune([0, 1, 2, 3, 4, 5, 6], near=1.5) == [0, 1, 2, 3, 4, 5]


def test_a_leaf_takes_the_removed_nodes_of_its_branch():
    # Algorithm 4 removed 1, 3 and 5: the edge 2 -> 6 stands for 5, so without 6, node 5 is 1 m and 6 2 m away
    assert prune([0, 2, 4, 6], near=1.5) == [0, 2, 4, 6]
    assert prune([0, 2, 4, 6], near=2.0) == [0, 2, 4]


def test_terminals_loop_ends_and_traffic_steps_stay():
    assert prune([0, 1, 2, 3, 4], near=5.0) == [0, 1, 2, 3, 4]  # 4 is a terminal
    assert prune([0, 2, 4, 6], near=5.0, loop=(6, 3)) == [0, 2, 4, 6]  # 6 ends a loop edge
    rank = np.array([50, 50, 10, 50, 50, 50, 90], dtype=np.float64)  # rows in the forest's order, ids 0-6
    assert prune([0, 2, 4, 6], near=5.0, rank=rank, max_step=60.0) == [0, 2, 4, 6]  # 90 against 2's 10
    assert prune([0, 2, 4, 6], near=5.0, rank=rank, max_step=80.0) == [0, 2, 4]


def test_represented_holds_the_branches_with_an_anchor_below():
    parent = np.array([-1, 0, 1, 2, 3, 2, 5])
    depth = np.array([0, 1, 2, 3, 4, 3, 4])
    anchors = np.zeros(7, dtype=bool)
    anchors[[0, 4]] = True
    assert np.flatnonzero(represented(parent, depth, anchors)).tolist() == [0, 1, 2, 3, 4]


def test_standing_for_is_the_whole_forest_until_a_leaf_goes():
    forest, _ = tree()
    assert standing_for(forest, forest.subgraph([0, 2, 4, 6])) == [0, 1, 2, 3, 4, 5, 6]
    assert standing_for(forest, forest.subgraph([0, 2, 4])) == [0, 1, 2, 3, 4]
    looped, _ = tree(loop=(6, 3))
    assert standing_for(looped, looped.subgraph([0, 2, 4])) == [0, 1, 2, 3, 4, 5, 6]  # the loop path stays
