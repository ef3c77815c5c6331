"""Dead-end places (``coverage``'s ``dead_end_radii``): the leaves of one dead end reached through one way are one
terminal, the farthest from its way in; the cover still reaches the others."""

from __future__ import annotations

import math

import networkx as nx
import numpy as np
import pytest
import trimesh

from g2s_core import pipeline
from g2s_core.config import find_config, load_raw_config, parse_config
from g2s_core.errors import ConfigError
from g2s_core.model import RunContext
from g2s_core.registry import Registry
from g2s_plugins import traffic
from g2s_plugins.terminals import coverage


@pytest.fixture(scope="module")
def registry() -> Registry:
    return Registry.from_entry_points()


def hall_stair_and_roof(rim: float = 3.0) -> nx.Graph:
    """A hall (a ring of 8 nodes 2 m apart, 10 m² each, one leaf 8 off it), a stair 0 - 20 - 21 - 22 (2 m steps)
    up to a roof centre 30 and five rim polygons 31-35 ``rim`` metres from it (leaves), each 5 m²."""
    graph = nx.Graph()
    graph.add_weighted_edges_from([(k, (k + 1) % 8, 2.0) for k in range(8)] + [(4, 8, 3.0)])
    graph.add_weighted_edges_from([(0, 20, 2.0), (20, 21, 2.0), (21, 22, 2.0), (22, 30, 2.0)])
    graph.add_weighted_edges_from([(30, 31 + k, rim + 0.1 * k) for k in range(5)])
    for node in graph:
        graph.nodes[node]["area"] = 10.0 if node < 9 else 5.0
    return graph


def places(graph: nx.Graph, reach: float) -> list:
    arrays = traffic.surface_arrays(graph)
    leaves = np.flatnonzero(np.diff(arrays.adjacency.indptr) == 1)
    kept = coverage.dead_end_places(arrays.adjacency, arrays.area, leaves, reach)
    return sorted(arrays.nodes[i] for i in kept.tolist())


def test_the_rim_of_a_roof_up_one_stair_is_one_place():
    graph = hall_stair_and_roof()
    # the piece beyond the bridge 0 - 20 reaches 6 m from 20 to the roof centre and 3.4 m more to rim 35, the
    # farthest (9.4 m); the roof beyond 22 - 30 reaches 3.4 m from 30
    assert places(graph, 0.0) == [8, 31, 32, 33, 34, 35]
    assert places(graph, 9.45) == [8, 35]
    # short of the whole piece: the largest piece within reach is the roof, still one place
    assert places(graph, 9.35) == places(graph, 3.45) == [8, 35]
    # shorter than the roof's own reach: each rim polygon is a piece of its own
    assert places(graph, 3.35) == [8, 31, 32, 33, 34, 35]
    # the hall's leaf is a piece of one polygon: it stays whatever the reach
    assert 8 in places(graph, 100.0)


def test_two_dead_ends_off_one_hall_stay_two_places():
    graph = hall_stair_and_roof()
    graph.add_weighted_edges_from([(4, 40, 2.0), (40, 41, 2.0), (40, 42, 2.0)])  # a second dead end, two leaves
    for node in (40, 41, 42):
        graph.nodes[node]["area"] = 5.0
    # 41 and 42 are as far from the hall (4 m): the lower row, 41, stays
    assert places(graph, 12.0) == [8, 35, 41]


def test_an_area_of_one_edge_keeps_both_leaves():
    graph = nx.Graph()
    graph.add_weighted_edges_from([(0, 1, 1.0)])
    graph.nodes[0]["area"], graph.nodes[1]["area"] = 2.0, 1.0  # the larger one is the root, the other its piece
    # the root's own leaf is in no piece: both stay
    assert places(graph, 5.0) == [0, 1]


def test_the_cover_still_reaches_the_rim_left_out():
    graph = hall_stair_and_roof(rim=4.0)
    context = RunContext(mesh=None, agent=None, centre=np.zeros(3), graph=graph)
    terminals = coverage.g2s_select_terminals(graph, coverage.Params(radius=3.0, min_area=0.0, dead_end_radii=4.0),
                                              context)
    assert set(terminals.without_waypoints) == {8, 35}
    # rims 31-34 are 8 m from 35 through the roof centre: the cover adds them back, as waypoints
    assert {31, 32, 33, 34} <= set(terminals.waypoints)


def tank_yard(radius: float = 6.0, height: float = 1.8, sides: int = 16) -> trimesh.Trimesh:
    """A yard 40 m square with a round tank (``sides``-gon of ``radius``) whose flat roof, ``height`` up (too low to
    stand inside), is reached by one ramp 2 m wide at 25 degrees along +x."""
    yard = trimesh.creation.box(extents=(40.0, 0.2, 40.0)).apply_translation((0.0, -0.1, 0.0))
    angles = 2 * math.pi * np.arange(sides) / sides
    rim = np.column_stack([radius * np.cos(angles), np.zeros(sides), radius * np.sin(angles)])
    tank = trimesh.convex.convex_hull(np.concatenate([rim, rim + [0.0, height, 0.0]]))
    start, run = radius - 0.3, height / math.tan(math.radians(25.0))
    ramp = trimesh.convex.convex_hull(np.array([[start, 0, -1], [start, 0, 1], [start + run, 0, -1],
                                                [start + run, 0, 1], [start, height, -1], [start, height, 1]]))
    return trimesh.util.concatenate([yard, tank, ramp])


@pytest.mark.parametrize("radius", [5.0, 6.0])
def test_a_tank_roof_gets_one_terminal(registry, radius):
    def roof_terminals(dead_end_radii: float, quiet_step: float = 0.0, waypoints: bool = False) -> list:
        raw = load_raw_config(find_config("map_analysis"))
        raw["stop_after"] = "terminals"
        raw["terminals"]["params"].update(dead_end_radii=dead_end_radii, quiet_step=quiet_step)
        result = pipeline.run(pipeline.plan(parse_config(raw), registry), registry, tank_yard(radius), "tank", "-")
        nodes = result.terminals.nodes if waypoints else result.terminals.without_waypoints
        return [n for n in nodes if result.graph.nodes[n]["pos"][1] > 1.5]

    assert len(roof_terminals(0.0)) >= 3  # Recast cuts the round roof into several rim polygons, each a leaf
    assert len(roof_terminals(2.0)) == 1
    # map_analysis's quiet_step: the rim's leaves are as quiet as the roof they open onto, so none is a terminal of
    # its own, but the cover still holds the roof
    assert roof_terminals(2.0, 30.0) == [] and roof_terminals(2.0, 30.0, waypoints=True)


def test_dead_end_radii_is_validated(registry):
    raw = load_raw_config(find_config("map_analysis"))
    raw["terminals"]["params"]["dead_end_radii"] = -1
    with pytest.raises(ConfigError, match="terminals.params.dead_end_radii: expected a number"):
        pipeline.plan(parse_config(raw), registry)
