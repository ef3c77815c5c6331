"""Walking flow across a way's cross-section (g2s_plugins.cross_sections, the flow analyzer's ``across: section``)."""

from __future__ import annotations

import networkx as nx
import numpy as np
import pytest
import trimesh

from g2s_core.config import AgentConfig
from g2s_core.errors import PluginError
from g2s_core.model import RunContext
from g2s_plugins import cross_sections, traffic
from g2s_plugins.analyzers import flow as flow_analyzer
from g2s_plugins.graph_builders.navmesh import navmesh_graph
from g2s_plugins.recast import build_navmesh

LANE_AREA = 1e-6
"""The lane nodes' area: pairs with an end in a lane weigh next to nothing, so every trip across is a room's."""


def two_rooms(lanes: list[float]) -> nx.Graph:
    """Rooms of 3 x 3 samples (1 m apart, 1 m² each) at x = -3..-1 and x = 1..3, joined only by lane nodes at x = 0
    and the plan z of ``lanes``, each linked to its three neighbours on either side (4 and 8 neighbours)."""
    graph = nx.Graph()
    room = [(x, z) for x in (-3, -2, -1, 1, 2, 3) for z in (0, 1, 2)]
    for x, z in room:
        graph.add_node((x, z), pos=(float(x), 0.0, float(z)), normal=(0.0, 1.0, 0.0), area=1.0)
    for z in lanes:
        graph.add_node((0, z), pos=(0.0, 0.0, float(z)), normal=(0.0, 1.0, 0.0), area=LANE_AREA)
    for a in graph:
        for b in graph:
            length = float(np.hypot(a[0] - b[0], a[1] - b[1]))
            if a < b and length < 1.5:
                graph.add_edge(a, b, weight=length)
    return graph


def section(graph: nx.Graph) -> tuple[dict, dict]:
    """Per node of ``graph``: the trips across its section (gap 2.5 m, reach 30 m) and its own walking flow."""
    flow = traffic.walking_flow(graph)
    values = cross_sections.walking_across(graph, flow, None, 0, gap=2.5, reach=30.0, height=2.0)
    return dict(zip(traffic.surface_arrays(graph).nodes, values)), dict(zip(traffic.surface_arrays(graph).nodes, flow))


@pytest.mark.parametrize("lanes", [[0.0, 1.0], [0.0, 2.0]])  # one lane two samples wide; two lanes a sample apart
def test_two_lanes_read_as_hot_as_one_of_double_width(lanes):
    across, own = section(two_rooms(lanes))
    trips = 2 * 9 * 9  # ordered pairs of the two rooms' samples, each of weight 1 x 1; every one crosses x = 0
    for z in lanes:
        assert across[(0, z)] == pytest.approx(trips, rel=1e-5)
        assert own[(0, z)] < 0.9 * trips  # one lane alone carries a share of them
    assert own[(0, lanes[0])] + own[(0, lanes[1])] == pytest.approx(trips, rel=1e-5)


def test_lanes_further_apart_than_the_gap_are_ways_of_their_own():
    graph = two_rooms([0.0, 2.0])
    flow = traffic.walking_flow(graph)
    values = cross_sections.walking_across(graph, flow, None, 0, gap=0.5, reach=30.0, height=2.0)
    rows = traffic.surface_arrays(graph).index
    for z in (0.0, 2.0):
        assert values[rows[(0, z)]] == pytest.approx(flow[rows[(0, z)]])


def test_a_way_one_node_across_keeps_its_own_flow():
    graph = nx.Graph()
    for i in range(5):  # a corridor of five 1 m² samples along x
        graph.add_node(i, pos=(float(i), 0.0, 0.0), normal=(0.0, 1.0, 0.0), area=1.0)
    graph.add_edges_from(((i, i + 1, {"weight": 1.0}) for i in range(4)))
    flow = traffic.walking_flow(graph)
    values = cross_sections.walking_across(graph, flow, None, 0, gap=2.5, reach=30.0, height=2.0)
    # the mean of the trips into and out of each sample: its through-flow and its own 4 trips either way
    assert values.tolist() == (flow + 4.0).tolist()
    trips = cross_sections.walking_trips(traffic.surface_arrays(graph), np.array([[i, 0.0] for i in range(5)]), None)
    axes = cross_sections.principal_axes(trips.tensors)
    assert np.allclose(np.abs(axes[1:4]), [[1.0, 0.0]] * 3)  # the trips run along x


def test_a_floor_above_is_not_on_the_section():
    graph = two_rooms([0.0, 2.0])
    graph.nodes[(0, 2.0)]["pos"] = (0.0, 3.0, 2.0)  # the second lane 3 m up: another floor, over the height
    flow = traffic.walking_flow(graph)
    values = cross_sections.walking_across(graph, flow, None, 0, gap=2.5, reach=30.0, height=2.0)
    row = traffic.surface_arrays(graph).index[(0, 0.0)]
    assert values[row] == pytest.approx(flow[row])


def test_the_analyzer_sums_a_section_only_when_asked():
    graph = two_rooms([0.0, 2.0])
    context = RunContext(mesh=None, agent=AgentConfig(), centre=np.zeros(3), graph=graph)
    structure = nx.Graph()
    structure.add_nodes_from(graph)
    plain = flow_analyzer.g2s_analyze(structure, flow_analyzer.Params(aggregate="sum"), context)
    summed = flow_analyzer.g2s_analyze(structure, flow_analyzer.Params(aggregate="sum", across="section"), context)
    assert summed[(0, 0.0)] == pytest.approx(summed[(0, 2.0)]) and summed[(0, 0.0)] > plain[(0, 0.0)]
    assert summed[(0, 0.0)] == pytest.approx(2 * 9 * 9 / 18.0**2, rel=1e-5)  # a share of all pair weight
    alone = two_rooms([0.0, 2.0])  # sections overwrite every node's own flow: it is not computed at all
    flow_analyzer.g2s_analyze(structure, flow_analyzer.Params(across="section"),
                              RunContext(mesh=None, agent=AgentConfig(), centre=np.zeros(3), graph=alone))
    assert not any(key[0] == "walking_flow" for key in traffic.surface_arrays(alone).derived)
    with pytest.raises(ValueError):
        flow_analyzer.Params(across="lane")
    with pytest.raises(PluginError, match="needs a navmesh"):  # a graph without one: exit 2, not a crash
        flow_analyzer.g2s_analyze(structure, flow_analyzer.Params(across="lanes"), context)


def rooms_through_a_thick_wall(gaps: list[tuple[float, float]]) -> trimesh.Trimesh:
    """Two rooms 10 x 10 m (z 0-10) at x -12..-2 and 2..12, parted by a wall 4 m thick (x -2..2) with ``gaps`` (z
    from, to), and walled round."""
    boxes = [trimesh.creation.box(bounds=[[-12.0, -0.2, 0.0], [12.0, 0.0, 10.0]])]
    edges = [0.0] + [z for gap in gaps for z in gap] + [10.0]
    boxes += [trimesh.creation.box(bounds=[[-2.0, 0.0, z0], [2.0, 2.5, z1]]) for z0, z1 in zip(edges[::2], edges[1::2])
              if z1 > z0]
    boxes += [trimesh.creation.box(bounds=b) for b in ([[-12.3, 0.0, -0.3], [12.3, 2.5, 0.0]],
                                                       [[-12.3, 0.0, 10.0], [12.3, 2.5, 10.3]],
                                                       [[-12.3, 0.0, 0.0], [-12.0, 2.5, 10.0]],
                                                       [[12.0, 0.0, 0.0], [12.3, 2.5, 10.0]])]
    return trimesh.util.concatenate(boxes)


def lane_values(gaps: list[tuple[float, float]]) -> tuple[np.ndarray, np.ndarray, np.ndarray, float]:
    """The plain and the ``lanes`` walking flow of the level's navmesh graph, the nodes in the gaps, and the pair
    weight of the trips between the rooms (ordered pairs of their polygons, by area)."""
    agent = AgentConfig()
    mesh = rooms_through_a_thick_wall(gaps)
    navmesh = build_navmesh(mesh.vertices, mesh.faces, agent)
    graph = navmesh_graph(navmesh)
    arrays = traffic.surface_arrays(graph)
    positions = np.array([graph.nodes[node]["pos"] for node in arrays.nodes])
    flow = traffic.walking_flow(graph)
    lanes = cross_sections.walking_across(graph, flow, None, 0, 2.5, 30.0, agent.height, navmesh, 1.4)
    area = traffic.origin_weight(arrays)
    rooms = [area[positions[:, 0] < -2.0].sum(), area[positions[:, 0] > 2.0].sum()]
    # the gaps' floor (not the wall's top or the floor shut inside it, which no trip reaches)
    return flow, lanes, (np.abs(positions[:, 0]) < 2.0) & (flow > 0), 2.0 * rooms[0] * rooms[1]


def test_two_lanes_of_a_navmesh_read_as_hot_as_one_of_double_width():
    # one gap 2.2 m wide (1.2 m walkable: a lane), or two of 1.6 m (0.6 m walkable) 1 m apart (2 m with clearance)
    _, wide, in_wide, wide_trips = lane_values([(4.0, 6.2)])
    two_flow, two, in_two, two_trips = lane_values([(3.2, 4.8), (5.8, 7.4)])
    assert in_wide.any() and in_two.sum() >= 2
    # every trip between the rooms crosses the wall in one of the lanes; the lanes' nodes read all of them (and the
    # few that start or end in the gaps)
    assert wide[in_wide].min() == pytest.approx(wide_trips, rel=0.1)
    assert two[in_two].min() == pytest.approx(two_trips, rel=0.1)
    assert two[in_two].min() == pytest.approx(wide[in_wide].min(), rel=0.05)
    assert two_flow[in_two].max() < 0.8 * two_trips  # each lane's own flow is a share of them
    assert (two[~in_two] == two_flow[~in_two]).mean() > 0.5  # the rooms' wide floor keeps its own flow


def test_a_small_area_no_draw_falls_on_has_its_trips():
    graph = nx.Graph()
    for first, z, count in ((0, 0.0, 20), (100, 50.0, 3)):  # a corridor of 20 samples, 50 m away one of 3, 1 m² each
        for i in range(count):
            graph.add_node(first + i, pos=(float(i), 0.0, z), normal=(0.0, 1.0, 0.0), area=1.0)
        nx.add_path(graph, range(first, first + count), weight=1.0)
    arrays = traffic.surface_arrays(graph)
    small = arrays.rows([100, 101, 102])
    # 4 draws over the whole level in proportion to area, seed 0: none on the small corridor (3 of 23 m²)
    assert not np.isin(traffic.walking_sources(arrays.area, 4, 0)[0], small).any()
    # the walking flow's stratified sample walks it exactly (3² <= 4 x 23 nodes²; the long one's 20² is over):
    # its trips across are its through-flow (0, 2, 0) plus half its own 4 trips to and from each sample
    values = cross_sections.walking_across(graph, None, 4, 0, gap=2.5, reach=30.0, height=2.0)
    assert values[small].tolist() == pytest.approx([2.0, 4.0, 2.0])
    assert (values[arrays.rows(range(1, 19))] > 0).all()  # the long one from its 4 draws
