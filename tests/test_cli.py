"""The g2s command line: exit codes, one-line errors, outputs, plugin listing."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from tests.conftest import PROJECT

G2S = [sys.executable, "-m", "g2s_core.cli"]


def g2s(*args: str, cwd: Path = PROJECT) -> subprocess.CompletedProcess:
    return subprocess.run([*G2S, *args], capture_output=True, text=True, cwd=cwd, env={**os.environ, "COLUMNS": "200"})


def assert_user_error(proc: subprocess.CompletedProcess, fragment: str) -> None:
    assert proc.returncode == 2, proc.stderr
    assert "Traceback" not in proc.stderr
    lines = [line for line in proc.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("g2s: error: ") and fragment in lines[0], proc.stderr


def test_help_lists_the_commands():
    proc = g2s("--help")
    assert proc.returncode == 0
    for command in ("run", "plugins", "demo"):
        assert command in proc.stdout


def test_bad_config_value(tmp_path):
    config = tmp_path / "bad.yaml"
    config.write_text("extends: graph_only\nagent: {radius: ten}\n")
    assert_user_error(g2s("run", str(config), "sample:straight_corridor", "-o", str(tmp_path / "out")),
                      "bad.yaml: agent.radius: expected a number > 0, got 'ten'")
    assert not (tmp_path / "out").exists()


def test_plugin_not_installed(tmp_path):
    config = tmp_path / "c.yaml"
    config.write_text("extends: graph_only\ngraph: {plugin: voxels}\n")
    assert_user_error(g2s("run", str(config), "sample:straight_corridor", "-o", str(tmp_path / "out")),
                      "graph.plugin: GraphBuilder plugin 'voxels' is not installed (installed: ")


def test_bad_plugin_parameter(tmp_path):
    config = tmp_path / "c.yaml"
    config.write_text("extends: graph_only\ngraph: {plugin: navmesh, params: {cell_size: -1}}\n")
    assert_user_error(g2s("run", str(config), "sample:straight_corridor", "-o", str(tmp_path / "out")),
                      "graph.params.cell_size: expected")


def test_missing_mesh_and_unknown_sample(tmp_path):
    assert_user_error(g2s("run", "configs/graph_only.yaml", str(tmp_path / "nope.obj"), "-o", str(tmp_path / "o")), "no such mesh file")
    assert_user_error(g2s("run", "configs/graph_only.yaml", "sample:nope", "-o", str(tmp_path / "o")), "unknown sample 'nope'")


def test_argument_errors_exit_2():
    proc = g2s("run")
    assert proc.returncode == 2 and "Traceback" not in proc.stderr


def test_graph_only_run_writes_the_graph_and_refuses_to_overwrite(tmp_path):
    out = tmp_path / "out"
    proc = g2s("run", "configs/graph_only.yaml", "sample:straight_corridor", "-o", str(out))
    assert proc.returncode == 0, proc.stderr
    assert "Step 1" in proc.stdout and "initial graph" in proc.stdout
    graph = json.loads((out / "graph.json").read_text())
    assert len(graph["nodes"]) >= 1 and graph["mesh"]["name"] == "straight_corridor"
    before = (out / "graph.json").read_bytes()
    assert_user_error(g2s("run", "configs/graph_only.yaml", "sample:straight_corridor", "-o", str(out)), "use --force")
    assert (out / "graph.json").read_bytes() == before
    again = g2s("run", "configs/graph_only.yaml", "sample:straight_corridor", "-o", str(out), "--force")
    assert again.returncode == 0 and (out / "graph.json").read_bytes() == before


def test_json_summary_is_the_only_stdout(tmp_path):
    proc = g2s("run", "configs/graph_only.yaml", "sample:straight_corridor", "-o", str(tmp_path / "o"), "--json")
    assert proc.returncode == 0, proc.stderr
    summary = json.loads(proc.stdout)
    assert [s["stage"] for s in summary["stages"]] == ["graph"]


def test_real_level_graph(tmp_path, shared_data):
    config = tmp_path / "recast_demo.yaml"
    config.write_text("extends: graph_only\nagent: {radius: 0.6, height: 2.0, max_climb: 0.9, max_slope: 45}\n"
                      "graph: {plugin: navmesh, params: {cell_size: 0.3, cell_height: 0.2}}\n")
    proc = g2s("run", str(config), str(shared_data / "nav_test.obj"), "-o", str(tmp_path / "out"), "--quiet")
    assert proc.returncode == 0, proc.stderr
    graph = json.loads((tmp_path / "out" / "graph.json").read_text())
    assert 100 <= len(graph["nodes"]) <= 220 and graph["mesh"]["name"] == "nav_test.obj"


def test_plugins_lists_stage_name_package_and_parameters():
    proc = g2s("plugins", "--stage", "graph")
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.startswith("graph\n  navmesh  (graph2structure)\n")
    assert "cell_size:" in proc.stdout
