"""The play space (``graph.params.play_points``): the initial graph cut to the areas holding a play point where it is
built, so terminals, walking-flow percentiles and the ``traffic`` evaluator's measures see those areas alone, and a
point off the walkable ground refused."""

from __future__ import annotations

import dataclasses
import types

import networkx as nx
import numpy as np
import pytest
import trimesh

from g2s_core import pipeline
from g2s_core.config import AgentConfig, parse_config
from g2s_core.errors import ConfigError, G2SError
from g2s_core.mesh import mesh_sha256
from g2s_core.model import RunContext, RunResult
from g2s_core.registry import Registry
from g2s_plugins import evaluation, play_space, traffic
from g2s_plugins.play_space import cut_to_play_space
from g2s_plugins.terminals import entry_exit
from tests.conftest import box
from tests.test_analysis_quality import preset
from tests.test_cli import assert_user_error, g2s

ROOM_CENTRE = [10.0, 0.0, 10.0]


def room_and_platform() -> trimesh.Trimesh:
    """A room 20 m x 20 m (floor at y 0, walls 3 m high, two pillars) and, 10 m beyond its wall, a platform
    10 m x 10 m whose top is 3 m up with no way onto it: ground no one in the room reaches."""
    parts = [box(0, 20, -0.2, 0, 0, 20), box(-0.2, 0, 0, 3, 0, 20), box(20, 20.2, 0, 3, 0, 20),
             box(0, 20, 0, 3, -0.2, 0), box(0, 20, 0, 3, 20, 20.2), box(6, 7, 0, 3, 6, 7), box(13, 14, 0, 3, 12, 13),
             box(30, 40, 0, 3, 0, 10)]
    return trimesh.util.concatenate(parts)


@pytest.fixture(scope="module")
def registry() -> Registry:
    return Registry.from_entry_points()


def run(registry: Registry, mesh: trimesh.Trimesh, name: str = "map_analysis", **graph_params) -> RunResult:
    raw = preset(name, evaluators=[{"plugin": "traffic"}])
    raw["graph"] = {**raw["graph"], "params": {**(raw["graph"].get("params") or {}), **graph_params}}
    return pipeline.run(pipeline.plan(parse_config(raw), registry), registry, mesh, "level", mesh_sha256(mesh))


def on_platform(result: RunResult, nodes) -> list:
    return [node for node in nodes if result.graph.nodes[node]["pos"][1] > 2.5]


def test_play_points_cut_the_platform_from_the_graph_and_say_so(registry):
    mesh = room_and_platform()
    everywhere = run(registry, mesh)
    assert on_platform(everywhere, everywhere.terminals.nodes) and on_platform(everywhere, everywhere.structure)
    played = run(registry, mesh, play_points=[ROOM_CENTRE])
    assert not on_platform(played, played.graph) and played.terminals.nodes and played.structure.number_of_nodes() > 0
    platform = on_platform(everywhere, everywhere.graph)
    assert played.graph.number_of_nodes() == everywhere.graph.number_of_nodes() - len(platform)
    platform_area = sum(everywhere.graph.nodes[node]["area"] for node in platform)
    assert [w for w in played.warnings if "play point" in w] == [
        f"graph: 1 walkable area(s) ({platform_area:.3g} m² in all) hold no play point (graph.params.play_points) "
        "and are left out"]
    # the room is measured alone: the structure's share of its polygons, not of the level's
    assert played.metrics["traffic"]["structure_share"] == played.structure.number_of_nodes() / len(played.graph)


def test_regions_and_chokepoints_are_the_play_space_s(registry):
    def platform_regions(result: RunResult) -> list:
        return [r for r in result.features["regions"]["regions"] if r["centroid"][1] > 2.5]

    mesh = room_and_platform()
    everywhere = run(registry, mesh, "level_regions")
    assert platform_regions(everywhere)
    played = run(registry, mesh, "level_regions", play_points=[ROOM_CENTRE])
    regions = played.features["regions"]["regions"]
    assert regions and not platform_regions(played)
    assert len(regions) == len(everywhere.features["regions"]["regions"]) - len(platform_regions(everywhere))
    kept = {r["id"] for r in regions}
    assert all(set(k["regions"]) <= kept for k in played.features["chokepoints"]["chokepoints"])


def test_the_sampling_route_s_reference_navmesh_is_cut_by_the_same_rule(registry):
    played = run(registry, room_and_platform(), "map_analysis_sampling", play_points=[ROOM_CENTRE])
    assert played.graph.number_of_nodes() > 0 and not on_platform(played, played.graph)
    reference = evaluation.reference_flow(played)
    cut = evaluation.navmesh_surface(played, reference)
    # the same run read without its play points: the level's navmesh graph keeps the platform, on which no sample of
    # the run stands, so its area would count as left out of the heat map
    whole = evaluation.navmesh_surface(dataclasses.replace(played, config={**played.config, "graph": {
        "plugin": "sampling"}}), reference)
    platform = [node for node, pos in whole.graph.nodes(data="pos") if pos[1] > 2.5]
    assert platform and not [node for node, pos in cut.graph.nodes(data="pos") if pos[1] > 2.5]
    assert cut.graph.number_of_nodes() == whole.graph.number_of_nodes() - len(platform)
    assert played.metrics["traffic"]["navmesh_area_left_out"] == 0.0


def room_with_two_doors() -> list[trimesh.Trimesh]:
    """A room 8 m x 6 m (floor at y 0, walls 0.3 m thick and 3 m high) with a 1.6 m doorway (z 2.2-3.8) in the middle of
    its west and east walls, open to the walls' top: its slab and six walls, each a box of its own (unwelded)."""
    return [box(0, 8, -0.2, 0, 0, 6), box(-0.3, 0, 0, 3, 0, 2.2), box(-0.3, 0, 0, 3, 3.8, 6), box(8, 8.3, 0, 3, 0, 2.2),
            box(8, 8.3, 0, 3, 3.8, 6), box(-0.3, 8.3, 0, 3, -0.3, 0), box(-0.3, 8.3, 0, 3, 6, 6.3)]


def room_beside_lower_ground() -> trimesh.Trimesh:
    """:func:`room_with_two_doors` and, 4 m north of it, ground 8 m x 20 m 1 m lower that no one in the room reaches: a
    backdrop larger than the piece, whose own edges read as openings."""
    return trimesh.util.concatenate(room_with_two_doors() + [box(0, 8, -1.2, -1, 10, 30)])


@pytest.mark.parametrize("name", ["map_piece", "map_piece_sampling"])
def test_entry_exit_finds_the_play_space_s_openings(registry, name):
    mesh = room_beside_lower_ground()
    everywhere = run(registry, mesh, name)
    # the whole level: the ground is the main floor (the larger), its west, east and north edges the openings
    assert sorted(round(o.width) for o in everywhere.terminals.openings) == [8, 20, 20]
    assert all(o.position[1] == pytest.approx(-1, abs=0.01) for o in everywhere.terminals.openings)
    played = run(registry, mesh, name, play_points=[[4, 0, 3]])
    # the room's boundary alone: its two doorways, each the width of the doorway, at its middle
    doors = sorted(played.terminals.openings, key=lambda o: o.position[0])
    assert [round(o.position[0]) for o in doors] == [0, 8] and all(o.width == pytest.approx(1.6, abs=0.06) for o in doors)
    assert all(o.position[1] == pytest.approx(0, abs=0.01) and o.position[2] == pytest.approx(3, abs=0.05) for o in doors)


def inward_skybox() -> trimesh.Trimesh:
    """A box 40 x 35.2 x 40 m round the room, its faces turned inward (its floor's top 5 m under the room's)."""
    sky = box(-16, 24, -5.2, 30, -17, 23)
    sky.invert()
    return sky


BACKDROPS = {
    # ground 1 m lower reaching 9.7 m past each doorway's wall: the piece's extent along the doors' headings
    "ground_past_the_doors": [box(-10, 18, -1.2, -1, 10, 30)],
    # ground 10 x 26 m 1 m lower on either side of the room, 1.7 m beyond its west and east walls
    "ground_beside": [box(-12, -2, -1.2, -1, -10, 16), box(10, 20, -1.2, -1, -10, 16)],
    # ground 5 m straight below beyond each doorway: "the piece below" to leave_footprint
    "inward_skybox": [inward_skybox()],
}


@pytest.mark.parametrize("backdrop", sorted(BACKDROPS))
@pytest.mark.parametrize("name", ["map_piece", "map_piece_sampling"])
def test_a_backdrop_apart_from_the_play_space_hides_none_of_its_doors(registry, name, backdrop):
    mesh = trimesh.util.concatenate(room_with_two_doors() + BACKDROPS[backdrop])
    played = run(registry, mesh, name, play_points=[[4, 0, 3]])
    # before, the backdrop counted in the outer extent or as the piece below: no opening
    doors = sorted(played.terminals.openings, key=lambda o: o.position[0])
    assert [round(o.position[0]) for o in doors] == [0, 8] and all(o.width == pytest.approx(1.6, abs=0.06) for o in doors)


UNWELDED = {
    # a lintel 1.9-2.9 m up (under the agent's height less a search step), a box of its own between the west door's
    # walls sharing no corner with them
    "lintel_west": ([box(-0.3, 0, 1.9, 2.9, 2.2, 3.8)], [8]),
    # a canopy 1.8 m up and 2 m deep against the east wall's outer face over its doorway: no way out under it
    "canopy_east": ([box(8.3, 10.3, 1.8, 1.9, 1.8, 4.2)], [0]),
    # the same canopy 0.4 m off the east wall on two posts ending 0.3 m over nothing: closer than the agent's diameter
    # to the wall, one piece with it (two search steps apart dropped it, and the east doorway was found)
    "canopy_on_posts_in_the_air": ([box(8.7, 10.7, 1.8, 1.9, 1.8, 4.2), box(10.5, 10.7, 0.3, 1.8, 1.8, 2.0),
                                    box(10.5, 10.7, 0.3, 1.8, 4.0, 4.2)], [0]),
}


@pytest.mark.parametrize("extra", sorted(UNWELDED))
@pytest.mark.parametrize("name", ["map_piece", "map_piece_sampling"])
def test_the_piece_s_own_unwelded_parts_still_close_its_doors(registry, name, extra):
    parts, doors = UNWELDED[extra]
    played = run(registry, trimesh.util.concatenate(room_with_two_doors() + parts), name, play_points=[[4, 0, 3]])
    assert [round(o.position[0]) for o in played.terminals.openings] == doors


def test_the_play_space_s_faces_are_the_parts_it_stands_on_and_those_touching_them():
    # a slab; a wall standing on it (unwelded); a beam through the wall, no corner of it on any face of the wall;
    # a post 0.05 m off the beam's end; a block 0.2 m off the slab's side; a floor 3 m under all of them
    parts = [box(0, 4, -0.2, 0, 0, 4), box(0.1, 0.4, 0, 3, 0, 4), box(-0.5, 0.8, 2, 2.2, 1.9, 2.1),
             box(-0.6, -0.55, 0, 2.2, 1.9, 2.1), box(4.2, 5, -0.2, 1, 0, 4), box(-10, 10, -3.2, -3, -10, 10)]
    mesh = trimesh.util.concatenate(parts)
    part = play_space.mesh_parts(mesh)
    assert [len(set(part[12 * i: 12 * i + 12])) for i in range(6)] == [1] * 6 and len(set(part)) == 6
    keep = play_space.play_space_faces(mesh, np.array([[2.0, 0.0, 2.0]]), 0.4, 0.1)
    assert keep.reshape(6, 12).all(axis=1).tolist() == [True, True, True, True, False, False]
    assert not keep.reshape(6, 12)[4:].any()
    # a point 0.3 m beyond the slab's side, over nothing within reach straight below (a node over a grating's slot):
    # the slab is the face within reach
    assert (play_space.play_space_faces(mesh, np.array([[2.0, 0.0, 4.3]]), 0.4, 0.1) == keep).all()
    # a point with no face within reach keeps nothing, and the selector then reads the whole mesh
    assert not play_space.play_space_faces(mesh, np.array([[2.0, 5.0, 2.0]]), 0.4, 0.1).any()
    graph = nx.Graph()
    graph.add_node(0, pos=(2.0, 5.0, 2.0))
    assert entry_exit.play_space_piece(mesh, graph, AgentConfig(), entry_exit.Params()) is mesh


def test_the_cut_graph_names_its_play_points(registry):
    played = run(registry, room_beside_lower_ground(), "map_piece", play_points=[[4, 0, 3]])
    assert played.graph.graph[play_space.PLAY_POINTS] == [[4.0, 0.0, 3.0]]
    assert play_space.PLAY_POINTS not in run(registry, room_beside_lower_ground(), "map_piece").graph.graph


def test_the_held_navmesh_is_the_graph_s_polygons_alone():
    # three unit squares in a row along x (polygons 0, 1, 2), two detail triangles each; the graph holds 1 and 2
    vertices = np.array([[x, 0.0, z] for x in range(4) for z in (0.0, 1.0)])
    polygons = np.array([[2 * i, 2 * i + 1, 2 * i + 3, 2 * i + 2] for i in range(3)], dtype=np.int32)
    neighbours = np.array([[-1, 1, -1, -1], [-1, 2, -1, 0], [-1, -1, -1, 1]], dtype=np.int32)
    navmesh = types.SimpleNamespace(
        vertices=vertices, polygons=polygons, neighbours=neighbours, normals=np.tile([0.0, 1.0, 0.0], (3, 1)),
        areas=np.ones(3), detail_vertices=vertices, detail_triangles=np.concatenate([p[[[0, 1, 2], [0, 2, 3]]] for p in polygons]),
        detail_polygon=np.repeat(np.arange(3, dtype=np.int32), 2), polygon_count=3)
    graph = nx.Graph([(1, 2), (2, 3)])
    nx.set_node_attributes(graph, {1: 1, 2: 2, 3: -1}, "polygon")  # node 3: a portal node, no polygon
    held = entry_exit.held_navmesh(navmesh, graph)
    assert held.ids.tolist() == [1, 2] and held.polygons.tolist() == polygons[1:].tolist()
    # polygon 1's neighbour 0 is not held: a boundary edge now; 1 and 2 are rows 0 and 1
    assert held.neighbours.tolist() == [[-1, 1, -1, -1], [-1, -1, -1, 0]]
    assert held.detail_polygon.tolist() == [0, 0, 1, 1] and held.detail_triangles.tolist() == \
        navmesh.detail_triangles[2:].tolist()


def test_a_play_point_in_mid_air_is_bad_input(tmp_path):
    mesh = tmp_path / "level.obj"
    room_and_platform().export(mesh)
    proc = g2s("run", "map_analysis", str(mesh), "-o", str(tmp_path / "out"),
               "--set", "graph.params.play_points=[[10, 0, 10], [10, 8, 10]]")
    assert_user_error(proc, "graph.params.play_points[1]: (10, 8, 10) has no walkable node within 2 m (the agent's "
                            "height); expected a point on the play space's walkable ground")


def test_the_coverage_selector_takes_no_play_points_and_says_where_they_went(registry):
    raw = preset("map_analysis")
    raw["terminals"] = {**raw["terminals"], "params": {**raw["terminals"]["params"], "play_points": [ROOM_CENTRE]}}
    with pytest.raises(ConfigError, match=r"terminals\.params: play_points is a parameter of the graph builder now: "
                                          r"set graph\.params\.play_points$"):
        pipeline.plan(parse_config(raw), registry)


def two_paths() -> nx.Graph:
    """A play path of 5 nodes 1 m apart (0-4, 1 m² each) and, 90 m beyond it, a bigger background path of 9 (100-108):
    on a path of unit areas the exact walking flow through a node is 2 x (nodes left of it) x (nodes right of it)."""
    graph = nx.Graph()
    for first, x0, count in ((0, 0.0, 5), (100, 100.0, 9)):
        for i in range(count):
            graph.add_node(first + i, pos=(x0 + i + 0.5, 0.0, 2.0), area=1.0)
        nx.add_path(graph, range(first, first + count), weight=1.0)
    graph.graph["sampling_stats"] = {"spacing": 1.0}
    return graph


def test_the_play_space_s_busiest_node_tops_its_percentiles():
    graph = two_paths()
    context = RunContext(mesh=trimesh.Trimesh(), agent=AgentConfig(), centre=np.zeros(3))
    whole = traffic.walking_flow(graph, exact_up_to=traffic.EXACT_NODES)
    # flows 0, 6, 8, 6, 0 on the play path, 0, 14, 24, 30, 32, ... on the background's: among all 14 nodes the play
    # path's busiest (8) ranks 7th, above the four zeros and the two 6s, below every background node with flow:
    # 100 (7 - 0.5) / 14
    assert traffic.percentile(whole)[2] == pytest.approx(100 * 6.5 / 14)
    played = cut_to_play_space(graph, [[0.5, 0.0, 2.0]], context)
    assert list(played) == [0, 1, 2, 3, 4] and played.graph["sampling_stats"] == {"spacing": 1.0}
    assert context.warnings == ["graph: 1 walkable area(s) (9 m² in all) hold no play point (graph.params.play_points) "
                                "and are left out"]
    # over the play space alone it is the top of 5: 100 (5 - 0.5) / 5
    assert traffic.percentile(traffic.walking_flow(played, exact_up_to=traffic.EXACT_NODES)).tolist() == \
        [20.0, 60.0, 90.0, 60.0, 20.0]
    assert cut_to_play_space(graph, None, context) is graph


def test_a_play_point_on_ground_the_graph_builder_dropped_names_the_setting_that_dropped_it():
    """A point on the mesh's floor where the graph holds no node (an area too small for the builder) is told apart
    from one in mid-air: the first names the builder's setting, the second asks for a point on the ground."""
    graph = two_paths()  # nodes along z = 2 at x 0.5-4.5 and 100.5-108.5, y = 0
    pad = trimesh.Trimesh([[50, 0, 0], [52, 0, 0], [52, 0, 2], [50, 0, 2]], [[0, 2, 1], [0, 3, 2]])  # faces up
    context = RunContext(mesh=pad, agent=AgentConfig(), centre=np.zeros(3))
    with pytest.raises(G2SError, match=r"^graph\.params\.play_points\[1\]: \(51, 0\.5, 1\) has no walkable node within "
                                       r"2 m \(the agent's height\), though it stands on the mesh's walkable ground "
                                       r"\(at y = 0\): .*lower graph\.params\.min_region_area$"):
        cut_to_play_space(graph, [[0.5, 0.0, 2.0], [51.0, 0.5, 1.0]], context)
    for off_ground in ([51.0, 8.0, 1.0], [51.0, -3.0, 1.0], [60.0, 0.0, 1.0], [1e308, 0.0, 1.0]):
        with pytest.raises(G2SError, match=r"; expected a point on the play space's walkable ground"):
            cut_to_play_space(graph, [off_ground], context)
