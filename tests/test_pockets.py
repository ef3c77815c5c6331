"""Pockets (``coverage``'s ``pocket_depth``): what hangs beyond one node of the graph, within the depth of it, holds
no cover terminal; that node, its mouth, stands for it. A corridor with three cabins, each behind a door one sample
wide, keeps one terminal per cabin: its door."""

from __future__ import annotations

import math

import networkx as nx
import numpy as np
import pytest

from g2s_core.model import RunContext
from g2s_plugins import traffic
from g2s_plugins.terminals import coverage

CABINS = (15, 30, 45)
"""The x of each cabin's door, metres."""

LENGTH = 60
"""The corridor's length, metres: long enough that its ends and the cabins are the quiet places the walking flow
ranks lowest, and each door stands for its cabin's rank (:data:`~g2s_plugins.heat_guarantee.FLOOR`)."""


def corridor_with_cabins() -> nx.Graph:
    """A grid of samples 1 m apart: a corridor two samples wide (z = -1, 0; x = 0-60), and off it at each x of
    :data:`CABINS` a door (x, 1) and a cabin of three samples (x - 1 .. x + 1, 2). Links as the sampling builder makes
    them, to every sample within 2 m (twice the spacing) but for the slanted ones from a cabin to the corridor: the
    straight 2 m links from a cabin's samples to the corridor pass by its door sample."""
    points = [(x, z) for x in range(LENGTH + 1) for z in (-1, 0)]
    for door in CABINS:
        points += [(door, 1)] + [(door + dx, 2) for dx in (-1, 0, 1)]
    graph = nx.Graph(sampling_stats={"spacing": 1.0})
    for k, (x, z) in enumerate(points):
        graph.add_node(k, pos=np.array([x, 0.0, z], dtype=np.float64), area=1.0)
    for a, (xa, za) in enumerate(points):
        for b in range(a + 1, len(points)):
            xb, zb = points[b]
            length = math.hypot(xa - xb, za - zb)
            through_wall = (za == 2 and zb <= 0 or zb == 2 and za <= 0) and (xa != xb)
            if length <= 2.0 and not through_wall:
                graph.add_edge(a, b, weight=length)
    return graph


def positions(graph: nx.Graph, nodes) -> list[tuple[int, int]]:
    return sorted((int(graph.nodes[n]["pos"][0]), int(graph.nodes[n]["pos"][2])) for n in nodes)


def cabin_terminals(pocket_depth: float) -> dict[int, list[tuple[int, int]]]:
    graph = corridor_with_cabins()
    context = RunContext(mesh=None, agent=None, centre=np.zeros(3), graph=graph)
    params = coverage.Params(radius=1.5, min_area=0.0, pocket_depth=pocket_depth)
    chosen = positions(graph, coverage.g2s_select_terminals(graph, params, context).nodes)
    return {door: [(x, z) for x, z in chosen if z >= 1 and abs(x - door) <= 1] for door in CABINS}


def test_the_cabins_behind_one_sample_doors_are_pockets():
    graph = corridor_with_cabins()
    arrays = traffic.surface_arrays(graph)
    pocket, mouth = coverage.pockets(arrays.adjacency, arrays.area, 1.5, 1.5)
    assert positions(graph, [arrays.nodes[m] for m in mouth.tolist()]) == [(door, 1) for door in CABINS]
    for p, m in enumerate(mouth.tolist()):
        door = int(graph.nodes[arrays.nodes[m]]["pos"][0])
        held = positions(graph, [arrays.nodes[i] for i in np.flatnonzero(pocket == p).tolist()])
        assert held == [(door + dx, 2) for dx in (-1, 0, 1)]  # the cabin; its door opens it and is in none
    # the cabin's corners lie 1.41 m from the door: a shallower depth holds no pocket
    assert (coverage.pockets(arrays.adjacency, arrays.area, 1.4, 1.5)[0] < 0).all()
    # with every link, the 2 m link from a cabin's middle past the door to the corridor: no door is a cut vertex
    assert (coverage.pockets(arrays.adjacency, arrays.area, 1.5)[0] < 0).all()


def test_a_cabin_keeps_one_terminal_its_door():
    without = cabin_terminals(0.0)
    assert all(any(z == 2 for _, z in cabin) for cabin in without.values())  # the cover reaches into each cabin
    assert cabin_terminals(1.5) == {door: [(door, 1)] for door in CABINS}


@pytest.mark.parametrize("depth", [0.0, 1.5, 6.0])
def test_every_sample_stays_within_the_radius(depth):
    graph = corridor_with_cabins()
    context = RunContext(mesh=None, agent=None, centre=np.zeros(3), graph=graph)
    terminals = coverage.g2s_select_terminals(graph, coverage.Params(radius=1.5, min_area=0.0, pocket_depth=depth),
                                              context)
    reach = nx.multi_source_dijkstra_path_length(graph, set(terminals.nodes), weight="weight")
    assert max(reach.values()) <= 1.5 + 1e-9
