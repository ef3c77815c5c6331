"""The disconnected-areas warning on hand-made graphs and navmeshes whose separation is known."""

from __future__ import annotations

import re
from types import SimpleNamespace

import networkx as nx
import numpy as np
import pytest
import trimesh

from g2s_core.api import run
from g2s_core.config import AgentConfig
from g2s_core.disconnected import LISTED_AREAS, area_summary, disconnected_warning
from g2s_plugins._raycasting import RayCaster
from g2s_plugins.area_gaps import likely_cause_of, shut_in
from g2s_plugins.recast import RecastParams, resolve_settings

SAMPLED = likely_cause_of(AgentConfig())
"""The cause over nodes that each stand for a square of their area, none eroded."""


def slab(graph: nx.Graph, x0: float, y: float, cells: int, first: int, z: float = 0.5) -> list[int]:
    """A row of ``cells`` 1 m x 1 m nodes at height ``y`` starting at ``x0``, their middles at ``z``, joined in a line."""
    nodes = list(range(first, first + cells))
    for i, node in enumerate(nodes):
        graph.add_node(node, pos=(x0 + i + 0.5, y, z), area=1.0)
    nx.add_path(graph, nodes)
    return nodes


def areas(graph: nx.Graph) -> dict[int, list[int]]:
    return {i: sorted(c) for i, c in enumerate(nx.connected_components(graph))}


def navmesh_of(rectangles: list[tuple[float, float, float, float, float]],
               params: RecastParams | None = None) -> tuple[SimpleNamespace, nx.Graph]:
    """A navmesh of one polygon per rectangle (x0, x1, z0, z1, y; none joined) and its graph, with the settings
    ``params`` resolve to for the default agent (None: ``map_analysis``'s cells, 0.25 x 0.125 m)."""
    vertices = np.array([[x, y, z] for x0, x1, z0, z1, y in rectangles for x, z in ((x0, z0), (x0, z1), (x1, z1), (x1, z0))])
    polygons = np.arange(len(vertices)).reshape(-1, 4)
    navmesh = SimpleNamespace(vertices=vertices, polygons=polygons, neighbours=np.full(polygons.shape, -1),
                              settings=resolve_settings(AgentConfig(), params))
    graph = nx.Graph()
    for i, (x0, x1, z0, z1, y) in enumerate(rectangles):
        graph.add_node(i, pos=((x0 + x1) / 2, y, (z0 + z1) / 2), area=(x1 - x0) * (z1 - z0), polygon=i)
    return navmesh, graph


@pytest.mark.parametrize("rise, cause", [
    (0.6, "a step of about 0.6 m, higher than agent.max_climb (0.4 m)"),  # a step the agent cannot climb
    (4.0, "separate floors (4.0 m apart)"),                                 # a floor above the other
    (0.0, "a gap or passage too narrow for the agent (agent.radius 0.5 m), or a wall, where their ground lies about 1.0 m apart"),
])
def test_the_likely_cause_follows_the_step_between_the_closest_areas(rise, cause):
    graph = nx.Graph()
    slab(graph, 0.0, 0.0, 10, 0)
    slab(graph, 11.0 if rise == 0.0 else 10.0, rise, 4, 100)
    message = disconnected_warning(graph, areas(graph), 5, SAMPLED)
    assert message.startswith("5 terminals lie in 2 disconnected areas")
    assert "Largest areas: 10 m² near (4.5, 0.0, 0.5 m); 4 m²" in message
    assert cause in message


def test_a_jump_gap_reads_the_gap_between_the_platforms_edges():
    """Platforms 10 m long 0.8 m apart, each eroded by the agent's 0.5 m (two cells) as Recast erodes: the navmesh's
    edges are 1.8 m apart, its polygons' centres 10.8 m (what the warning read before)."""
    navmesh, graph = navmesh_of([(0.5, 9.5, 0.5, 5.5, 8.0), (11.3, 20.3, 0.5, 5.5, 8.0)])
    message = disconnected_warning(graph, areas(graph), 2, likely_cause_of(AgentConfig(), navmesh))
    assert "or a wall, where their ground lies about 0.8 m apart, e.g. between (9.5, 8.0, " in message


def test_a_narrow_door_reads_the_wall_between_the_rooms():
    """Two rooms 9 m deep on either side of a wall 0.2 m thick whose door the agent does not fit: the ground of
    the rooms meets across the wall's thickness, not the 10.3 m between the rooms' middles."""
    navmesh, graph = navmesh_of([(0.5, 9.4, 0.5, 9.5, 0.0), (10.6, 19.5, 0.5, 9.5, 0.0)])
    message = disconnected_warning(graph, areas(graph), 2, likely_cause_of(AgentConfig(), navmesh))
    assert "a gap or passage too narrow for the agent (agent.radius 0.5 m), or a wall, where their ground lies " \
           "about 0.2 m apart, e.g. between (9.4, 0.0, " in message


def test_the_floor_inside_a_closed_box_is_named_as_such():
    """A box 6 m square and 3 m high standing closed on a floor: Recast keeps the floor inside it (head room 3 m),
    an area of its own 1 m of eroded ground from the floor outside."""
    floor = trimesh.creation.box((30, 0.3, 30), trimesh.transformations.translation_matrix((15, -0.15, 15)))
    box = trimesh.creation.box((6, 3, 6), trimesh.transformations.translation_matrix((13, 1.5, 13)))
    mesh = trimesh.util.concatenate([floor, box])
    navmesh, graph = navmesh_of([(0.5, 9.5, 0.5, 29.5, 0.0), (10.5, 15.5, 10.5, 15.5, 0.0)])
    message = disconnected_warning(graph, areas(graph), 2, likely_cause_of(AgentConfig(), navmesh, mesh=mesh))
    assert "Likely cause: from the largest area to the nearest area of 25 m², a floor shut inside a closed solid (a box or " \
           "collision hull exported with the level), at the same height, its ground about 0.0 m from the other's, " \
           "e.g. between (9.5, 0.0, " in message
    top, graph = navmesh_of([(0.5, 9.5, 0.5, 29.5, 0.0), (10.5, 15.5, 10.5, 15.5, 3.0)])  # the box's top instead
    message = disconnected_warning(graph, areas(graph), 2, likely_cause_of(AgentConfig(), top, mesh=mesh))
    assert "Likely cause: from the largest area to the nearest area of 25 m², separate floors (3.0 m apart)" in message


def boxes(*extents: tuple[float, float, float, float, float, float]) -> trimesh.Trimesh:
    """Closed boxes over [x0, x1] x [y0, y1] x [z0, z1] each, wound outward, in one mesh."""
    return trimesh.util.concatenate([trimesh.creation.box(bounds=[(x0, y0, z0), (x1, y1, z1)])
                                     for x0, x1, y0, y1, z0, z1 in extents])


def flipped(mesh: trimesh.Trimesh) -> trimesh.Trimesh:
    """``mesh`` with every face wound the other way, as an export with flipped normals."""
    return trimesh.Trimesh(mesh.vertices, mesh.faces[:, ::-1], process=False)


def rooms_either_side_of(wall: list[tuple[float, float]]) -> tuple[trimesh.Trimesh, SimpleNamespace, nx.Graph]:
    """Two rooms 20 x 10 m on a floor, parted by a wall 0.2 m thick and 3 m high along z = 10 over the x ranges
    ``wall``; the navmesh of each room eroded by the agent's 0.5 m, as Recast leaves it when the door is too narrow."""
    mesh = boxes((-1, 21, -0.3, 0, -1, 21), *((x0, x1, 0, 3, 9.9, 10.1) for x0, x1 in wall))
    navmesh, graph = navmesh_of([(0.5, 19.5, 0.5, 9.4, 0.0), (0.5, 19.5, 10.6, 19.5, 0.0)])
    return mesh, navmesh, graph


def test_a_narrow_door_is_named_where_it_is_not_at_a_corner_of_the_wall():
    """A door 0.8 m wide (x 16.1-16.9) in the wall between two rooms, too narrow for the agent's 1 m: every edge
    point along the wall is as close to the other room as the door's, and the closest pair alone was the first of
    them, at the wall's end 16 m from the door. The pair named now faces the door."""
    mesh, navmesh, graph = rooms_either_side_of([(-1, 16.1), (16.9, 21)])
    message = disconnected_warning(graph, areas(graph), 2, likely_cause_of(AgentConfig(), navmesh, mesh=mesh))
    named = re.search(r"or a wall, where their ground lies about 0\.2 m apart, e\.g\. between \((.*) m\) and \((.*) m\)\.$", message)
    assert named and "\n" not in message
    here, there = (np.array(place.split(", "), dtype=float) for place in named.groups())
    for point in (here, there):
        assert np.hypot(point[0] - 16.5, point[2] - 10.0) < 1.0
    assert here[2] == 9.4 and there[2] == 10.6  # across the wall


def test_a_wall_with_no_door_is_named_along_its_run():
    """The same rooms with no door: no pair faces an opening, so none is named as if it were the way through;
    the warning names the wall's run between the rooms' ground, 19 m."""
    mesh, navmesh, graph = rooms_either_side_of([(-1, 21)])
    message = disconnected_warning(graph, areas(graph), 2, likely_cause_of(AgentConfig(), navmesh, mesh=mesh))
    assert "or a wall, where their ground lies about 0.2 m apart, along 19.0 m from (0.5, 0.0, 10.0 m) to (19.5, 0.0, " in message
    assert "e.g." not in message


def test_a_plank_narrower_than_the_agent_is_named_over_the_chasm():
    """Platforms 2 m apart at 8 m over a void, joined by a plank 0.6 m wide (z 14.0-14.6): the pair named crosses
    the plank, not the void beside it."""
    mesh = boxes((0, 10, 7.7, 8, 0, 20), (12, 22, 7.7, 8, 0, 20), (10, 12, 7.8, 8, 14.0, 14.6))
    navmesh, graph = navmesh_of([(0.5, 9.5, 0.5, 19.5, 8.0), (12.5, 21.5, 0.5, 19.5, 8.0)])
    message = disconnected_warning(graph, areas(graph), 2, likely_cause_of(AgentConfig(), navmesh, mesh=mesh))
    assert "where their ground lies about 2.0 m apart, e.g. between (9.5, 8.0, 14.5 m) and (12.5, 8.0, 14.5 m)" in message
    chasm = boxes((0, 10, 7.7, 8, 0, 20), (12, 22, 7.7, 8, 0, 20))
    message = disconnected_warning(graph, areas(graph), 2, likely_cause_of(AgentConfig(), navmesh, mesh=chasm))
    assert message.endswith("about 2.0 m apart, along 19.0 m from (11.0, 8.0, 19.5 m) to (10.9, 8.0, 0.5 m).")


def test_winding_tells_closed_bodies_wound_outward_and_inside_out_from_open_ones():
    box = boxes((0, 1, 0, 1, 0, 1))
    plane = trimesh.Trimesh([[0, 0, 0], [1, 0, 0], [0, 0, 1]], [[0, 2, 1]])
    split = trimesh.Trimesh(box.triangles.reshape(-1, 3), np.arange(36).reshape(-1, 3), process=False)  # OBJ seams
    winding = {name: RayCaster(mesh).scene.winding.tolist() for name, mesh in
               (("box", box), ("flipped", flipped(box)), ("plane", plane), ("split", split))}
    assert winding == {"box": [1] * 12, "flipped": [-1] * 12, "plane": [0], "split": [1] * 12}


def test_a_mesh_wound_inside_out_reads_as_wound_right():
    """A point on the floor inside a closed box is shut in; one in a room with a roof, walls and a door is not.
    With every face wound the other way the first faces each ray meets are seen from the other side, which read
    the room as shut and the box as open; the bodies' own winding reads both as the mesh wound right."""
    agent = AgentConfig()
    box = boxes((-5, 25, -0.3, 0, -5, 25), (10, 16, 0, 3, 10, 16))
    room = boxes((-5, 25, -0.3, 0, -5, 25), (0, 10, 3, 3.3, 0, 10), (-0.2, 0, 0, 3, 0, 10), (10, 10.2, 0, 3, 0, 10),
                 (0, 10, 0, 3, -0.2, 0), (0, 4.5, 0, 3, 10, 10.2), (5.5, 10, 0, 3, 10, 10.2))
    for mesh, point, inside in ((box, (13.0, 0.0, 13.0), True), (room, (5.0, 0.0, 5.0), False)):
        for wound in (mesh, flipped(mesh)):
            assert shut_in(RayCaster(wound), np.array([point]), agent).tolist() == [inside]
    floor, box_only = navmesh_of([(0.5, 9.5, 0.5, 24.5, 0.0), (10.5, 15.5, 10.5, 15.5, 0.0)])
    message = disconnected_warning(box_only, areas(box_only), 2, likely_cause_of(AgentConfig(), floor, mesh=flipped(box)))
    assert "Likely cause: from the largest area to the nearest area of 25 m², a floor shut inside a closed solid" in message


def test_a_room_shut_above_a_deck_is_named_by_its_door_not_the_storeys():
    """A car park: an office floor over a deck (joined by a ramp) and a room on the office's level, shut by a
    narrow door 4 m from the office floor and 3.5 m above the deck. The closest nodes are the room and the
    deck under it, but the designer's cause is the door on the office's level."""
    graph = nx.Graph()
    deck = slab(graph, 0.0, 0.0, 20, 0)
    office = slab(graph, 0.0, 3.5, 10, 100)
    graph.add_edge(deck[0], office[0])  # the ramp
    slab(graph, 14.0, 3.5, 4, 200)
    message = disconnected_warning(graph, areas(graph), 5, SAMPLED)
    assert "a gap or passage too narrow for the agent (agent.radius 0.5 m), or a wall, where their ground lies about 4.0 m apart" in message
    assert "between (9.5, 3.5, 0.5 m) and (14.5, 3.5, 0.5 m)" in message


def test_hundreds_of_areas_give_one_short_line():
    graph = nx.Graph()
    for index in range(600):
        slab(graph, 3.0 * index, 0.0, 1 + index % 3, 10 * index)
    message = disconnected_warning(graph, areas(graph), 600, SAMPLED)
    assert len(message) < 500 and "\n" not in message
    assert message.count("m² near") == LISTED_AREAS
    assert f"; {600 - LISTED_AREAS} more with" in message


def test_area_summary_places_the_area_inside_it():
    graph = nx.Graph()
    nodes = slab(graph, 0.0, 0.0, 3, 0)
    graph.nodes[2]["area"] = 10.0  # most of the surface is at the last node
    total, where = area_summary(graph, nodes)
    assert total == 12.0 and tuple(where) == (2.5, 0.0, 0.5)


def test_an_abstract_graph_gets_the_counts_only():
    graph = nx.Graph([(0, 1), (1, 2), (7, 8)])
    message = disconnected_warning(graph, areas(graph), 3, None)
    assert message == ("3 terminals lie in 2 disconnected areas, so they are joined by one tree per area "
                       "(the largest have 3, 2 nodes).")


def test_places_near_zero_print_without_a_minus_sign():
    graph = nx.Graph()
    slab(graph, -0.54, -0.04, 1, 0)  # its one node at (-0.04, -0.04, 0.5)
    slab(graph, 5.0, 0.0, 2, 100)
    message = disconnected_warning(graph, areas(graph), 2, SAMPLED)
    assert "-0.0" not in message and "(0.0, 0.0, 0.5 m)" in message


def test_a_rise_far_from_the_areas_edges_is_no_step():
    """The archipelago of benchmarks/level_kinds.py (seed 0): islands at heights 0.5-2 m, a bridge too narrow for
    the agent. The closest places, on two islands 18.6 m apart, differ by 0.6 m, which the warning called a step
    higher than max_climb; over 18 m that rise is a slope the agent walks: what parts them lies between them."""
    graph = nx.Graph()
    slab(graph, 0.0, 0.0, 10, 0)
    slab(graph, 28.0, 0.6, 4, 100)
    message = disconnected_warning(graph, areas(graph), 5, SAMPLED)
    assert "Likely cause: from the largest area to the nearest area of 4 m², a gap or passage too narrow for the agent " \
           "(agent.radius 0.5 m), or a wall, where their ground lies about 18.0 m apart, e.g. between (9.5, 0.0, 0.5 m) " \
           "and (28.5, 0.6, 0.5 m)." in message


def test_a_small_area_beside_the_largest_does_not_hide_the_gap_to_a_large_one():
    """A floor of 20 m², a crumb of 1 m² (a crate's top, under a tenth of it) 0.5 m from its end, and a second floor
    of 15 m² alongside it 3 m away: the cause is the 3 m between the floors a designer would join, not the crumb, which
    is named after it as a smaller area nearer (within the agent's width of 1 m)."""
    graph = nx.Graph()
    slab(graph, 0.0, 0.0, 20, 0)
    slab(graph, 20.5, 0.0, 1, 100)
    slab(graph, 0.0, 0.0, 15, 200, z=4.5)
    message = disconnected_warning(graph, areas(graph), 3, SAMPLED)
    assert "Largest areas: 20 m² near (9.5, 0.0, 0.5 m); 15 m² near (7.5, 0.0, 4.5 m); 1 m² near (21.0, 0.0, 0.5 m)." in message
    assert message.endswith("Likely cause: from the largest area to the nearest area of 15 m², a gap or passage too narrow for the "
                            "agent (agent.radius 0.5 m), or a wall, where their ground lies about 3.0 m apart, "
                            "e.g. between (0.5, 0.0, 0.5 m) and (0.5, 0.0, 4.5 m); and a smaller area of 1 m² lies nearer, "
                            "its ground about 0.5 m from the largest's, at (21.0, 0.0, 0.5 m).")


def test_the_floe_across_a_crack_is_named_not_the_next_in_size_beyond_it():
    """Ice floes: the largest (20 m²), four larger floes far off (8-5 m², 30 m away) and a floe of 3 m² (over a tenth
    of the largest) across a crack 0.3 m wide. The core hands every area; the fifth after the largest in size is
    the one across the crack, which the four next in size left out (a gap of 26 m named)."""
    graph = nx.Graph()
    slab(graph, 0.0, 0.0, 20, 0)
    for index, cells in enumerate((8, 7, 6, 5)):
        slab(graph, 10.0 * index, 0.0, cells, 100 * (index + 1), z=30.5)
    slab(graph, 20.3, 0.0, 3, 1000)
    message = disconnected_warning(graph, areas(graph), 6, SAMPLED)
    assert message.endswith("Likely cause: from the largest area to the nearest area of 3 m², a gap or passage too narrow for the "
                            "agent (agent.radius 0.5 m), or a wall, where their ground lies about 0.3 m apart, "
                            "e.g. between (19.5, 0.0, 0.5 m) and (20.8, 0.0, 0.5 m).")


def test_crumbs_alone_name_the_nearest_of_them():
    """A floor of 30 m² and only crumbs (four of 2 m² 10-40 m away, one of 1 m² 1 m away, all under a tenth of it):
    the nearest crumb is measured, the fifth after the largest in size, which the four next in size left out."""
    graph = nx.Graph()
    slab(graph, 0.0, 0.0, 30, 0)
    for index in range(4):
        slab(graph, 40.0 + 10.0 * index, 0.0, 2, 100 * (index + 1))
    slab(graph, 31.0, 0.0, 1, 1000)
    message = disconnected_warning(graph, areas(graph), 6, SAMPLED)
    assert "Likely cause: from the largest area to the nearest area of 1 m², " in message and "about 1.0 m apart" in message


@pytest.mark.parametrize("closet, said", [
    ((-2.8, -0.8, 8.5, 10.5, 0.0), "; and a smaller area of 4 m² lies nearer, its ground about 0.3 m from the largest's, "
                                   "at (-0.8, 0.0, "),                            # a closet behind a wall 0.3 m thick
    ((-1.5, 0.5, 20.5, 22.5, 0.6), "; and a smaller area of 4 m² lies nearer, its ground about 0.0 m from the largest's, "
                                   "0.6 m higher, at ("),                         # a ledge 0.6 m up, over the climb
    ((-4.0, -2.0, 8.5, 10.5, 0.0), None),                                         # 1.5 m away: over the agent's width
])
def test_a_smaller_area_nearer_than_the_named_one_is_named_after_it(closet, said):
    """A room of 361 m² (ground x 0-20), another of 304 m² whose ground lies 3 m from it (the area named) and a closet
    of 4 m² (under a tenth): beside the room within the agent's 1 m it is named after the cause, with its place."""
    navmesh, graph = navmesh_of([(0.5, 19.5, 0.5, 19.5, 0.0), (23.5, 39.5, 0.5, 19.5, 0.0), closet])
    message = disconnected_warning(graph, areas(graph), 3, likely_cause_of(AgentConfig(), navmesh))
    assert "Likely cause: from the largest area to the nearest area of 304 m², a gap or passage too narrow for the agent " \
           "(agent.radius 0.5 m), or a wall, where their ground lies about 3.0 m apart, e.g. between (19.5, 0.0, " in message
    assert "\n" not in message and message.endswith(".")
    if said is None:
        assert "smaller area" not in message
    else:
        assert said in message and message.count("; and a smaller area") == 1


@pytest.mark.parametrize("beam, cause", [
    ((1.4, 1.7), "head room too low: a ceiling about 1.4 m over the floor, under agent.height (2 m), where their ground "
                 "lies about 1.0 m apart, at ("),                                      # a low beam
    ((2.5, 2.8), "a gap or passage too narrow for the agent (agent.radius 0.5 m), or a wall, where their ground lies "
                 "about 1.0 m apart"),                                                 # over the agent: not the cause
    ((0.0, 1.7), "a gap or passage too narrow for the agent (agent.radius 0.5 m), or a wall, where their ground lies "
                 "about 1.0 m apart, along "),                                          # a wall, not a ceiling
])
def test_a_beam_lower_than_the_agent_across_a_floor_is_named_as_head_room(beam, cause):
    """A floor 20 x 10 m cut in two by a beam 1 m wide (x 9.5-10.5) across it: under it (1.4 m of head room, under the
    agent's 2 m) the navmesh keeps no floor, and each half's polygon stops the agent's 0.5 m short of the beam. The
    warning names the head room and a place on the floor under the beam; a beam over the agent or a wall is not."""
    bottom, top = beam
    mesh = boxes((-1, 21, -0.3, 0, -1, 11), (9.5, 10.5, bottom, top, -1, 11))
    navmesh, graph = navmesh_of([(0.5, 9.0, 0.5, 9.5, 0.0), (11.0, 19.5, 0.5, 9.5, 0.0)])
    message = disconnected_warning(graph, areas(graph), 2, likely_cause_of(AgentConfig(), navmesh, mesh=mesh))
    assert cause in message and "\n" not in message
    if beam == (1.4, 1.7):
        place = np.array(message.rsplit("at (", 1)[1].removesuffix(" m).").split(", "), dtype=float)
        assert 9.5 <= place[0] <= 10.5 and place[1] == 0.0 and 0.5 <= place[2] <= 9.5


@pytest.mark.parametrize("preset", ["map_analysis", "map_analysis_sampling"])
def test_a_low_beam_parts_the_floor_on_either_route(preset):
    """A floor 42 x 22 m with a beam 1 m wide across it, 1.4 m over it: either builder keeps no floor under the beam
    (under the agent's 2 m), so the run warns of two areas, and the cause is the beam's head room, not a gap."""
    mesh = boxes((-1, 41, -0.3, 0, -1, 21), (19.5, 20.5, 1.4, 1.7, -1, 21))
    warned = [w for w in run(mesh, preset, mesh_name="beam").warnings if "disconnected areas" in str(w)]
    assert len(warned) == 1 and "lie in 2 disconnected areas" in str(warned[0])
    assert "Likely cause: from the largest area to the nearest area of " in str(warned[0])
    assert "head room too low: a ceiling about 1.4 m over the floor, under agent.height (2 m)" in str(warned[0])


HEAD_ROOM_TOO_LOW = "head room too low for the navmesh: a ceiling 2.05 m over the floor, about the agent's height: " \
    "the navmesh needs up to {} m (agent.height 2 m, read in cells of graph.params.cell_height)"


@pytest.mark.parametrize("params, door, cause", [
    (None, None, HEAD_ROOM_TOO_LOW.format("2.125")),                        # map_analysis's cells of 0.125 m
    (RecastParams(head_room="recast"), None, HEAD_ROOM_TOO_LOW.format("2.25")),  # Recast's filter: a cell more
    (RecastParams(cell_height=0.025), None, "or a wall"),                   # walked from 2.025 m on these cells
    (None, 0.8, "or a wall"),                                               # a door too narrow under the lintel
])
def test_a_ceiling_a_little_over_the_agent_is_named_as_the_navmeshs_head_room(params, door, cause):
    """A floor 20 x 10 m cut in two by a beam 1 m wide whose underside is 2.05 m over the floor (x 9.5-10.5), or by a
    wall under it with a door 0.8 m wide: the agent (2 m) fits under it, but Recast reads head room in cells of the
    cell height, and over a floor on a cell boundary it keeps floor from (walkableHeight + 1) cells (2.125 m on 0.125 m
    cells; docs/navmesh.md, "Head room a little over the agent's height"), so the navmesh's areas stop either side.
    The warning named a gap or a wall there; it names the head room and what the navmesh needs, derived from its
    settings (not under 0.025 m cells, where it needs 2.025 m; not where the door is the narrower cause)."""
    walls = [] if door is None else [(9.5, 10.5, 0, 2.05, -1, 5 - door / 2), (9.5, 10.5, 0, 2.05, 5 + door / 2, 11)]
    mesh = boxes((-1, 21, -0.3, 0, -1, 11), (9.5, 10.5, 2.05, 2.35, -1, 11), *walls)
    navmesh, graph = navmesh_of([(0.5, 9.0, 0.5, 9.5, 0.0), (11.0, 19.5, 0.5, 9.5, 0.0)], params)
    message = disconnected_warning(graph, areas(graph), 2, likely_cause_of(AgentConfig(), navmesh, mesh=mesh))
    assert cause in message and "\n" not in message
    if cause.startswith("head room"):
        place = np.array(message.rsplit("at (", 1)[1].removesuffix(" m).").split(", "), dtype=float)
        assert 9.5 <= place[0] <= 10.5 and place[1] == 0.0 and 0.5 <= place[2] <= 9.5
    else:
        assert "head room" not in message
    # the sampling route tests head room at its points exactly: a ceiling over the agent is no cause there
    graph = nx.Graph()
    sampled_rows(graph, [(0.5, 9, 0), (11.5, 9, 100)])
    assert "head room" not in disconnected_warning(graph, areas(graph), 2, likely_cause_of(AgentConfig(), mesh=mesh))


def test_awnings_either_side_of_an_open_middle_are_named_as_the_navmeshs_head_room():
    """An aisle whose middle (z 1.7-2.3) is open to the sky between two awnings 2.05 m up (z 0.9-1.7 and 2.3-3.1,
    x 8-12): Recast keeps no floor under the awnings' cells and erodes the agent's 0.5 m round them, so only a strip
    of the middle is left either side and the two pieces of aisle are apart, their edges under open sky (the awning
    market of round 37). Head room read straight up from the floor between them found none; it is read to the
    agent's radius round it too."""
    mesh = boxes((-1, 21, -0.3, 0, -1, 5), (8, 12, 2.05, 2.15, 0.9, 1.7), (8, 12, 2.05, 2.15, 2.3, 3.1))
    navmesh, graph = navmesh_of([(0.5, 8.6, 1.8, 2.2, 0.0), (11.4, 19.5, 1.8, 2.2, 0.0)])
    message = disconnected_warning(graph, areas(graph), 2, likely_cause_of(AgentConfig(), navmesh, mesh=mesh))
    assert HEAD_ROOM_TOO_LOW.format("2.125") in message
    place = np.array(message.rsplit("at (", 1)[1].removesuffix(" m).").split(", "), dtype=float)
    assert 8 <= place[0] <= 12 and (0.9 <= place[2] <= 1.7 or 2.3 <= place[2] <= 3.1)


def sampled_rows(graph: nx.Graph, rows: list[tuple[float, int, int]], z: float = 0.5) -> None:
    """Rows of 1 m samples (``slab``) at height 0 given as (first middle's x, cells, first node), each row joined."""
    for x0, cells, first in rows:
        slab(graph, x0 - 0.5, 0.0, cells, first, z)


@pytest.mark.parametrize("route", ["navmesh", "sampling"])
def test_a_partition_hung_low_over_the_floor_reads_as_a_wall_on_either_route(route):
    """A partition 0.2 m thick (x 9.9-10.1) whose underside is 0.45 m over the floor, up to 3 m: under half the
    agent's height and standing past its head, a wall to the agent, not a ceiling to raise. The navmesh's edges lie
    0.1 m over the floor (Recast's heights), the samples on it: the segment lifted the climb (0.4 m) passed under the
    partition from the samples only, which read "head room too low ... 0.5 m". The samples' squares (0.5 m and the
    clearance of 0.3 m past each) reached across the partition: their gap read 0.0 m, now its thickness."""
    mesh = boxes((-1, 21, -0.3, 0, -1, 11), (9.9, 10.1, 0.45, 3.0, -1, 11))
    if route == "navmesh":
        navmesh, graph = navmesh_of([(0.5, 9.4, 0.5, 9.5, 0.1), (10.6, 19.5, 0.5, 9.5, 0.1)])
        cause = likely_cause_of(AgentConfig(), navmesh, mesh=mesh)
    else:
        graph = nx.Graph()
        sampled_rows(graph, [(0.4, 10, 0), (10.6, 10, 100)])
        cause = likely_cause_of(AgentConfig(), clearance=0.3, mesh=mesh)
    message = disconnected_warning(graph, areas(graph), 2, cause)
    assert "head room" not in message
    assert "or a wall, where their ground lies about 0.2 m apart, " in message


def test_a_closet_behind_a_wall_reads_the_walls_thickness_on_the_sampling_route():
    """A room's samples (x 0.4-9.4), another room's 4 m beyond it in z and a closet of 4 m² behind a wall 0.3 m thick
    (x 9.7-10.0): the closet is named after the cause, its ground the wall's 0.3 m from the room's, not the 0.0 m
    the samples' squares (half a metre and the clearance of 0.3 m past each) made of it."""
    mesh = boxes((-1, 21, -0.3, 0, -1, 21), (9.7, 10.0, 0.0, 3.0, -1, 3))
    graph = nx.Graph()
    for row in range(5):  # the room: 50 m², the closet under a tenth of it
        sampled_rows(graph, [(0.4, 10, 10 * row)], z=0.5 + row)
    graph.add_edges_from((10 * row, 10 * row + 10) for row in range(4))
    sampled_rows(graph, [(0.4, 9, 100)], z=8.5)
    sampled_rows(graph, [(10.3, 4, 300)], z=0.5)
    message = disconnected_warning(graph, areas(graph), 3, likely_cause_of(AgentConfig(), clearance=0.3, mesh=mesh))
    assert "; and a smaller area of 4 m² lies nearer, its ground about 0.3 m from the largest's, at (10.3, 0.0, 0.5 m)." \
        in message


def test_the_nearest_area_is_found_past_four_nearer_by_edge_points():
    """A floor of 50 samples of 1 m², four crumbs of 0.01 m² 1.6 m from its edge points (their ground 1.05 m off)
    and an area of one sample of 4 m² 1.9 m from them (its square reaches 1 m: its ground 0.4 m off), all under a
    tenth of the floor: the area 0.4 m away is fifth by the straight-line distance of edge points, and was left out
    when only the four nearest that way were measured."""
    graph = nx.Graph()
    slab(graph, 0.0, 0.0, 50, 0)
    for index, x in enumerate((10.5, 20.5, 30.5, 40.5)):
        graph.add_node(100 + index, pos=(x, 0.0, 2.1), area=0.01)
    graph.add_node(200, pos=(5.5, 0.0, 2.4), area=4.0)
    message = disconnected_warning(graph, areas(graph), 6, SAMPLED)
    assert "Likely cause: from the largest area to the nearest area of 4 m², a gap or passage too narrow for the agent " \
           "(agent.radius 0.5 m), or a wall, where their ground lies about 0.4 m apart" in message


def test_a_low_beam_beside_a_wall_is_named_though_the_wall_comes_closer():
    """A floor parted by a wall 0.2 m thick (z up to 6.5) and on from it by a beam 1 m wide whose underside is 1.4 m up
    (z from 5.5): the navmesh's edges lie 1.2 m apart across the wall, 2 m across the beam. The head room was asked
    only of the pairs within a cell of the closest, all across the wall, and the warning named the wall; the pairs up
    to the agent's height farther are asked too when those find none."""
    mesh = boxes((-1, 21, -0.3, 0, -1, 11), (9.9, 10.1, 0, 3, -1, 6.5), (9.5, 10.5, 1.4, 1.7, 5.5, 11))
    navmesh, graph = navmesh_of([(0.5, 9.4, 0.5, 6.0, 0.0), (0.5, 9.0, 6.0, 9.5, 0.0),
                                 (10.6, 19.5, 0.5, 6.0, 0.0), (11.0, 19.5, 6.0, 9.5, 0.0)])
    graph.add_edges_from([(0, 1), (2, 3)])
    message = disconnected_warning(graph, areas(graph), 2, likely_cause_of(AgentConfig(), navmesh, mesh=mesh))
    assert "head room too low: a ceiling about 1.4 m over the floor, under agent.height (2 m)" in message
    place = np.array(message.rsplit("at (", 1)[1].removesuffix(" m).").split(", "), dtype=float)
    assert 9.0 <= place[0] <= 11.0 and place[2] >= 6.5


def terrace(way: str) -> trimesh.Trimesh:
    """A yard (y = 0, x < 4) beside a terrace 3 m high (x 4-14, z 2-8), a wall 6 m high along z = 8, and between yard
    and terrace, against the wall: ``stair``, treads 1.2 m wide between the wall and a drop (17 risers of 0.176 m on
    0.28 m, cantilevered, 0.25 m thick); ``wide``, the same 2.5 m wide; ``cut``, that with a riser of 0.8 m halfway; ``steep``, a
    ramp 2.5 m wide at 52 degrees; ``ladder``, rungs every 0.3 m up the terrace's face; ``none``, nothing
    (benchmarks/lost_stairs.py's cases, square to the grid)."""
    solids = [(-10, 4, -0.3, 0, -8, 8), (4, 14, -0.3, 3, 2, 8), (-10, 14, -0.3, 6, 8, 8.3)]
    risers = {"stair": [3 / 17] * 17, "wide": [3 / 17] * 17, "cut": [2.2 / 12] * 6 + [0.8] + [2.2 / 12] * 6}.get(way, [])
    width = 1.2 if way == "stair" else 2.5
    for i, height in enumerate(np.cumsum(risers)[:-1]):
        x = 4 - 0.28 * (len(risers) - 1 - i)
        solids.append((x, x + 0.28, height - 0.25, height, 8 - width, 8))
    if way == "ladder":
        solids += [(3.75, 3.8, y - 0.02, y + 0.02, 6.5, 7.1) for y in np.arange(0.3, 3, 0.3)]
    mesh = boxes(*solids)
    if way == "steep":
        run = 3 / np.tan(np.radians(52))
        corners = [[x, y + dy, z] for x, y in ((4 - run, 0.0), (4, 3.0)) for dy in (0.0, -0.3) for z in (5.5, 8)]
        mesh = trimesh.util.concatenate([mesh, trimesh.convex.convex_hull(np.array(corners))])
    return mesh


@pytest.mark.parametrize("way, cause", [
    # walkable ground climbs: the navmesh's erosion and ledge rule took the stair, the warning names it
    ("stair", "a stair or ramp between them about 1.2 m wide at its narrowest, narrower than the navmesh keeps for this "
              "agent (agent.radius 0.5 m; beside a drop the navmesh keeps floor from about 1.8 m), at ("),
    ("cut", "a step of about 0.8 m, higher than agent.max_climb (0.4 m), at ("),  # a flight cut by a step: the step
    ("none", "separate floors (3.0 m apart) with no walkable stairs or ramp"),   # no way up
    ("steep", "separate floors (3.0 m apart) with no walkable stairs or ramp"),  # a ramp steeper than the agent climbs
    ("ladder", "separate floors (3.0 m apart) with no walkable stairs or ramp"),  # rungs: no head room over each
])
def test_separate_floors_are_named_only_where_no_walkable_ground_climbs_between_them(way, cause):
    """The navmesh route's yard and terrace, eroded by the agent's radius (the stair lost, as Recast loses a walkway
    under about 1.8 m between a wall and a drop), over the meshes of :func:`terrace`."""
    navmesh, graph = navmesh_of([(-9.5, 3.5, -7.5, 7.5, 0.0), (4.5, 13.5, 2.5, 7.5, 3.0)])
    message = disconnected_warning(graph, areas(graph), 2, likely_cause_of(AgentConfig(), navmesh, mesh=terrace(way)))
    assert f"Likely cause: from the largest area to the nearest area of 45 m², {cause}" in message


def test_a_flight_wider_than_the_navmesh_needs_is_read_across_not_along_its_run():
    """The 2.5 m flight of :func:`terrace` (``wide``) lost on the navmesh route (Recast's ledge filter cuts treads, as
    on ``map_analysis_paper``'s stair_deck): its width is read across the flight, within a column spacing or so of
    2.5 m; rays along its run meet the risers at the knee and read 1.4 m, "narrower than the navmesh keeps"."""
    navmesh, graph = navmesh_of([(-9.5, 3.5, -7.5, 7.5, 0.0), (4.5, 13.5, 2.5, 7.5, 3.0)])
    message = disconnected_warning(graph, areas(graph), 2, likely_cause_of(AgentConfig(), navmesh, mesh=terrace("wide")))
    width = float(re.search(r"a stair or ramp between them about ([0-9.]+) m wide at its narrowest that the navmesh "
                            r"keeps no floor on for this agent", message).group(1))
    assert 2.1 <= width <= 2.7


def test_a_stair_the_sampled_graph_does_not_walk_is_named_on_the_sampling_route():
    """The sampling route's yard and terrace (1 m squares, clearance 0.3 m) with the 1.2 m stair between them: the
    stair is named without the navmesh's widths."""
    graph = nx.Graph()
    for k, (x, y, z) in enumerate([(x + 0.5, 0.0, z + 0.5) for x in range(-10, 3) for z in range(-8, 8)]
                                  + [(x + 0.5, 3.0, z + 0.5) for x in range(5, 14) for z in range(3, 8)]):
        graph.add_node(k, pos=(x, y, z), area=1.0)
    for u in graph:
        for v in graph:
            if u < v and np.linalg.norm(np.subtract(graph.nodes[u]["pos"], graph.nodes[v]["pos"])) <= 1.0:
                graph.add_edge(u, v)
    message = disconnected_warning(graph, areas(graph), 2, likely_cause_of(AgentConfig(), clearance=0.3, mesh=terrace("stair")))
    assert "Likely cause: from the largest area to the nearest area of 45 m², a stair or ramp between them about 1.2 m " \
           "wide at its narrowest that the sampled graph does not walk for this agent (agent.radius 0.5 m, " \
           "agent.max_climb 0.4 m), at (" in message


def far_stair(going: float) -> trimesh.Trimesh:
    """A yard (y = 0, x < 4, z -8 to 8) beside a deck 3 m high (x 4-14), a stair 1.4 m wide up the deck's face at its
    south end (z -8 to -6.6) of 14 risers of 3 / 14 m on treads ``going`` m deep (0.28: a stair; 0.16: a ship's
    companionway, two tread edges in a 0.25 m cell), cantilevered, 0.05 m thick."""
    solids = [(-10, 4, -0.3, 0, -8, 8), (4, 14, -0.3, 3, -8, 8)]
    for i, height in enumerate(np.cumsum([3 / 14] * 14)[:-1]):
        x = 4 - going * (13 - i)
        solids.append((x, x + going, height - 0.05, height, -8, -6.6))
    return boxes(*solids)


@pytest.mark.parametrize("going, cause", [
    (0.28, "a stair or ramp between them about 1.2 m wide at its narrowest, narrower than the navmesh keeps"),
    (0.16, "a stair between them about 1.2 m wide at its narrowest whose treads are shorter than a cell (agent.radius "
           "/ 2, 0.25 m): neighbouring cells' ground differs by two risers, about 0.43 m, over agent.max_climb (0.4 m)"),
])
def test_a_stair_14_m_from_the_closest_pair_is_found_and_read_by_its_treads(going, cause):
    """Round 38's coaming deck: the navmesh's yard juts to 0.5 m from the deck's edge at its north end (z 6.5-7.5),
    where the pair the warning measures lies, 14 m from the stair; the disc searched (10 m round the pair for a rise of
    3 m) did not reach it. A companionway's treads (0.16 m) put two risers (0.43 m) between columns 0.25 m apart.
    The drawn 1.4 m reads 1.2 m, as the coaming deck's companionways (the level's edge at one side)."""
    navmesh, graph = navmesh_of([(-9.5, 3.5, -7.5, 7.5, 0.0), (3.5, 4.0, 6.5, 7.5, 0.0), (4.5, 13.5, -7.5, 7.5, 3.0)])
    graph.add_edge(0, 1)
    message = disconnected_warning(graph, areas(graph), 2, likely_cause_of(AgentConfig(), navmesh, mesh=far_stair(going)))
    assert f"Likely cause: from the largest area to the nearest area of 135 m², {cause}" in message
    place = np.array(message.rsplit("at (", 1)[1].removesuffix(" m).").split(", "), dtype=float)
    assert 1.0 <= place[0] <= 4.0 and -8.0 <= place[2] <= -6.6


@pytest.mark.parametrize("north, cause", [
    # a gallery over its aisle, 8 m across the nave from the other: reached up from the aisle (a ramp 4 m in plan)
    (11.0, "separate floors (4.0 m apart) with no walkable stairs or ramp between them for this agent (agent.max_climb "
           "0.4 m, agent.max_slope 45°), e.g. between ("),
    # a roof 2 m across a street from another: a gap to bridge (shorter than the ramp)
    (5.0, "a gap or passage too narrow for the agent (agent.radius 0.5 m), or a wall, where their ground lies about "
          "2.0 m apart"),
])
def test_a_gallery_over_its_aisle_is_named_by_the_drop_not_the_gap_across_the_nave(north, cause):
    """Round 38's rubble nave: a floor (y = 0, z 0-14) under two galleries 4 m up, the south one (z 0-3) joined to the
    floor, the north one (z from ``north`` to 14) apart. Across the nave the one-floor pair (no ground under it) was
    named, "about 8.0 m apart" in mid-air; a ramp at the agent's 45 degrees down the 4 m drop is shorter."""
    mesh = boxes((0, 20, -0.3, 0, 0, 14), (0, 20, 3.7, 4, 0, 3), (0, 20, 3.7, 4, north, 14))
    navmesh, graph = navmesh_of([(0.5, 19.5, 0.5, 13.5, 0.0), (0.5, 19.5, 0.5, 2.5, 4.0),
                                 (0.5, 19.5, north + 0.5, 13.5, 4.0)])
    graph.add_edge(0, 1)
    message = disconnected_warning(graph, areas(graph), 2, likely_cause_of(AgentConfig(), navmesh, mesh=mesh))
    assert cause in message
    if north == 11.0:  # the pair names the north gallery's edge and the aisle under it
        places = re.findall(r"\(([-\d.]+), ([-\d.]+), ([-\d.]+) m\)", message.split("e.g. between", 1)[1])
        assert sorted(float(y) for _, y, _ in places) == [0.0, 4.0] and all(float(z) >= 11.0 for _, _, z in places)
