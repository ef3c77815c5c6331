"""The play space (``coverage``'s ``play_points``): terminals only in the areas holding a play point, the ``traffic``
evaluator's measures over those areas only, and a point off the walkable ground refused."""

from __future__ import annotations

import networkx as nx
import numpy as np
import pytest
import trimesh

from g2s_core import pipeline
from g2s_core.config import AgentConfig, parse_config
from g2s_core.mesh import mesh_sha256
from g2s_core.model import RunContext, RunResult
from g2s_core.registry import Registry
from g2s_plugins import evaluation
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


def run(registry: Registry, mesh: trimesh.Trimesh, **terminal_params) -> RunResult:
    raw = preset("map_analysis", evaluators=[{"plugin": "traffic"}])
    raw["terminals"] = {**raw["terminals"], "params": {**raw["terminals"]["params"], **terminal_params}}
    return pipeline.run(pipeline.plan(parse_config(raw), registry), registry, mesh, "level", mesh_sha256(mesh))


def on_platform(result: RunResult, nodes) -> list:
    return [node for node in nodes if result.graph.nodes[node]["pos"][1] > 2.5]


def test_play_points_leave_the_platform_without_terminals_and_say_so(registry):
    mesh = room_and_platform()
    everywhere = run(registry, mesh)
    assert on_platform(everywhere, everywhere.terminals.nodes) and on_platform(everywhere, everywhere.structure)
    played = run(registry, mesh, play_points=[ROOM_CENTRE])
    assert not on_platform(played, played.terminals.nodes) and not on_platform(played, played.structure)
    assert played.terminals.nodes and played.structure.number_of_nodes() > 0
    left_out = [w for w in played.warnings if "play point" in w]
    platform_area = sum(a for _, a in played.graph.nodes(data="area") if _ in on_platform(played, played.graph))
    assert left_out == [f"coverage: 1 walkable area(s) ({platform_area:.3g} m² in all) hold no play point "
                        "(terminals.params.play_points) and get no terminals"]
    # the room is measured alone: the structure's share of its polygons, not of the level's
    room = [node for node in played.graph if node not in on_platform(played, played.graph)]
    assert played.metrics["traffic"]["structure_share"] == played.structure.number_of_nodes() / len(room)


def test_a_play_point_in_mid_air_is_bad_input(tmp_path):
    mesh = tmp_path / "level.obj"
    room_and_platform().export(mesh)
    proc = g2s("run", "map_analysis", str(mesh), "-o", str(tmp_path / "out"),
               "--set", "terminals.params.play_points=[[10, 0, 10], [10, 8, 10]]")
    assert_user_error(proc, "terminals.params.play_points[1]: (10, 8, 10) has no walkable node within 2 m (the agent's "
                            "height); expected a point on the play space's walkable ground")


def two_paths() -> tuple[nx.Graph, trimesh.Trimesh]:
    """A play path of 10 nodes 1 m apart (rows 0-9, 1 m² each) on a slab 10 m x 4 m, and a background path of 10
    more (100-109) on a slab 90 m beyond it."""
    graph = nx.Graph()
    for first, x0 in ((0, 0.0), (100, 100.0)):
        for i in range(10):
            graph.add_node(first + i, pos=(x0 + i + 0.5, 0.0, 2.0), area=1.0)
        nx.add_path(graph, range(first, first + 10), weight=1.0)
    mesh = trimesh.util.concatenate([box(0, 10, -0.2, 0, 0, 4), box(100, 110, -0.2, 0, 0, 4)])
    return graph, mesh


def evaluated(graph: nx.Graph, mesh: trimesh.Trimesh, play_points) -> evaluation.Quality:
    """The measures of a run whose structure is nodes 0 -> 1 (heat 1 and 2) on ``graph``."""
    params = {} if play_points is None else {"play_points": play_points}
    result = RunResult(config={"terminals": {"plugin": "coverage", "params": params}}, mesh_name="level",
                       mesh_sha256="", context=RunContext(mesh=mesh, agent=AgentConfig(), centre=np.zeros(3)),
                       graph=graph, steiner=nx.Graph([(0, 1)]), structure=nx.DiGraph([(0, 1)]),
                       analysis={"flow": {0: 1.0, 1: 2.0}})
    return evaluation.evaluate(result, radii=(3.0,))


def test_the_shares_are_the_play_space_s_when_the_run_names_one():
    graph, mesh = two_paths()
    level, played = evaluated(graph, mesh, None), evaluated(graph, mesh, [[0.5, 0.0, 2.0]])
    # nodes 0-4 lie within 3 m of the structure (node 4 is 3 m from node 1): 5 m² of the level's 20, of the play
    # path's 10; the structure's 2 nodes of 20 and of 10
    assert (level.area_within[3.0], level.structure_share) == (0.25, 0.1)
    assert (played.area_within[3.0], played.structure_share) == (0.5, 0.2)
    # the background path carried flow of its own, all more than 5 m from the structure; over the play space the
    # shares and rho are those of the play path alone
    alone = graph.subgraph(range(10)).copy()
    path_only = evaluated(alone, mesh, None)
    assert level.traffic_off > played.traffic_off == path_only.traffic_off > 0
    assert played.rho == path_only.rho
