"""g2s_core.run / RunResult.write / load_result: the guarantees of the command line, from Python."""

from __future__ import annotations

import networkx as nx
import pytest

import g2s_core
from g2s_core.config import RunConfig, find_config, load_config, resolve_config
from g2s_core.errors import ConfigError, G2SError
from g2s_plugins.samples import levels as samples


def test_config_forms_and_overrides_agree():
    by_name, source = resolve_config("map_piece", {"agent.radius": 0.3, "terminals": {"params": {"sample_step": 0.2}}})
    assert source == "map_piece"
    assert by_name.agent.radius == 0.3 and by_name.agent.max_slope == 60  # merged, not replaced
    assert by_name.terminals.plugin == "entry_exit" and by_name.terminals.params == {"sample_step": 0.2}
    from_file, _ = resolve_config(find_config("map_piece"), {"agent": {"radius": 0.3}, "terminals.params.sample_step": 0.2})
    from_mapping, _ = resolve_config({"extends": "map_piece", "agent": {"radius": 0.3}},
                                     {"terminals.params": {"sample_step": 0.2}})
    from_model, _ = resolve_config(load_config(find_config("map_piece")), {"agent.radius": 0.3,
                                                                          "terminals.params.sample_step": 0.2})
    assert by_name == from_file == from_mapping == from_model
    plain = load_config(find_config("map_piece"))
    assert resolve_config(plain)[0] is plain
    with pytest.raises(ConfigError, match=r"^override agent\.radiuss: unknown key 'radiuss'"):
        resolve_config("map_piece", {"agent.radiuss": 1})


def test_run_write_and_load_keep_the_command_line_guarantees(tmp_path):
    level = samples.cross_hub()
    mesh_file = tmp_path / "structure.glb"  # an input named like a result file
    level.mesh.export(mesh_file)
    result = g2s_core.run(str(mesh_file), "map_analysis", stop_after="analyzers")
    assert isinstance(result.structure.graph["roots"], list) and result.mesh_path == mesh_file
    assert all(isinstance(flag, bool) for _, flag in result.graph.nodes(data="terminal"))
    assert {n for n, flag in result.structure.nodes(data="terminal") if flag} <= set(result.terminals.nodes)
    assert all(data["values"] == {"flow": result.analysis["flow"][n]}
               for n, data in result.structure.nodes(data=True))

    with pytest.raises(G2SError, match="has the name of a result file"):
        result.write(tmp_path, formats=["glb"], force=True)
    before = mesh_file.read_bytes()
    outdir = tmp_path / "new" / "folder"
    written = result.write(str(outdir), formats="json")
    assert [p.name for p in written] == ["structure.json", "run.json"]
    with pytest.raises(G2SError, match="already holds results"):
        result.write(str(outdir), formats="json")
    assert result.write(outdir, formats="json", force=True) == written
    assert mesh_file.read_bytes() == before

    loaded = g2s_core.load_result(str(outdir))
    assert sorted(loaded.structure.edges) == sorted(result.structure.edges)
    for node, data in loaded.structure.nodes(data=True):
        assert data["terminal"] == result.structure.nodes[node]["terminal"]
        assert data["values"] == pytest.approx(result.structure.nodes[node]["values"])


def test_waypoints_are_plain_nodes_in_the_run_and_in_its_files(tmp_path):
    """The coverage selector's waypoints are no terminals of the run, and its files say the same."""
    result = g2s_core.run("sample:dungeon?rooms=6&seed=0", "map_analysis")
    terminals = result.terminals
    assert set(terminals.waypoints) & set(result.structure)  # some waypoints stay in the structure
    flags = dict(result.structure.nodes(data="terminal"))
    assert {n for n, flag in flags.items() if flag} == set(terminals.without_waypoints) & set(result.structure)
    result.write(tmp_path / "out", formats=["json", "graphml"])
    loaded = g2s_core.load_result(tmp_path / "out")
    assert dict(loaded.structure.nodes(data="terminal")) == flags
    assert loaded.terminals.without_waypoints == terminals.without_waypoints
    assert loaded.terminals.waypoints == terminals.waypoints
    assert sorted(loaded.terminals.nodes) == sorted(terminals.nodes)
    graphml = nx.read_graphml(tmp_path / "out" / "structure.graphml", node_type=int)
    assert dict(graphml.nodes(data="terminal")) == flags


def test_the_same_run_from_python_and_from_the_command_line_writes_the_same_structure(tmp_path):
    from g2s_core.cli import main

    assert main(["run", "map_piece", "sample:t_hub", "-o", str(tmp_path / "cli"), "--format", "json", "--quiet"]) == 0
    g2s_core.run("sample:t_hub", "map_piece").write(tmp_path / "api", formats="json")
    assert (tmp_path / "cli" / "structure.json").read_bytes() == (tmp_path / "api" / "structure.json").read_bytes()


def test_bad_inputs_raise_one_line_errors():
    with pytest.raises(G2SError, match="unknown sample 'nope'"):
        g2s_core.run("sample:nope")
    with pytest.raises(ConfigError, match="no such config file or preset"):
        g2s_core.run("sample:t_hub", "no_such_preset")
    with pytest.raises(ConfigError, match=r"^override analyzers\.2\.key: analyzers has no item 2 \(it lists 1\)$"):
        g2s_core.run("sample:t_hub", load_config(find_config("map_analysis")), **{"analyzers.2.key": "x"})
    # robust6: was "RunConfig: analyzers: expected a list of mappings, got a mapping" (the index made a mapping)
    with pytest.raises(ConfigError, match=r"^override analyzers\.0\.key: analyzers has no item 0 \(it lists 0\)$"):
        g2s_core.run("sample:t_hub", RunConfig(), **{"analyzers.0.key": "x"})


def test_errors_met_while_running_name_the_level_once():
    """The stages do not know the file: their errors (a graph builder's, the pipeline's empty-graph one) are led by
    the level's name once, as the mesh's own are."""
    import types

    from g2s_core import api, hookimpl, pipeline
    from g2s_core.registry import Registry

    with pytest.raises(G2SError, match=r"^straight_corridor: mesh: the level is less than one 0\.25 m cell across"):
        g2s_core.run("sample:straight_corridor", "graph_only", mesh={"scale": 0.01})
    registry = Registry.from_entry_points()
    plugin = types.ModuleType("nothing", "a graph builder that finds no node")
    plugin.NAME, plugin.g2s_build_graph = "nothing", hookimpl(lambda mesh, params, context: nx.Graph())
    registry.register(plugin, package="tests", entry_point="graph_builders.nothing")
    config, _ = resolve_config("graph_only", {"graph": {"plugin": "nothing"}})
    level = api.open_mesh("sample:straight_corridor", config, registry=registry)
    with pytest.raises(G2SError, match=r"^straight_corridor: no walkable surface found for the agent \(the initial"):
        api.execute(pipeline.plan(config, registry), registry, level)


@pytest.mark.parametrize("collecting", [True, False])
def test_the_cyclic_collector_is_left_as_it_was_after_a_run_and_its_writing(tmp_path, monkeypatch, collecting):
    # the run and the writers pause the collector (and a big run's objects are collected once at its end);
    # a caller's choice stands afterwards, also when the run fails
    import gc

    seen: list[bool] = []
    monkeypatch.setattr(gc, "collect", lambda *args: seen.append(gc.isenabled()) or 0)
    was = gc.isenabled()
    (gc.enable if collecting else gc.disable)()
    try:
        result = g2s_core.run("sample:cross_hub", "map_analysis")
        assert gc.isenabled() == collecting
        result.write(tmp_path / "out", formats="json,graphml")
        assert gc.isenabled() == collecting
        with pytest.raises(G2SError):
            g2s_core.run("sample:closed_room", "map_analysis", **{"agent.radius": 50.0})
        assert gc.isenabled() == collecting
    finally:
        (gc.enable if was else gc.disable)()
    assert seen == []  # a small level's objects are left to the collector's own pace
