"""A plugin from another distribution, found through the same entry-point group."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

from tests.conftest import PROJECT

PLUGIN_DIR = PROJECT / "tests" / "thirdparty_plugin"


@pytest.fixture(scope="module")
def installed_plugin(tmp_path_factory):
    """The example distribution installed into a folder of its own, seen by the subprocesses only.

    Each test worker has its own copy, so nothing is installed into (or removed
    from) the environment the other tests run in.
    """
    site = tmp_path_factory.mktemp("site")
    pip = [sys.executable, "-m", "pip", "--disable-pip-version-check", "-q"]
    subprocess.run([*pip, "install", "--no-deps", "--target", str(site), str(PLUGIN_DIR)], check=True, capture_output=True)
    return {**os.environ, "COLUMNS": "200", "PYTHONPATH": os.pathsep.join(filter(None, [str(site), os.environ.get("PYTHONPATH")]))}


def g2s(env, *args):
    return subprocess.run([sys.executable, "-m", "g2s_core.cli", *args], capture_output=True, text=True,
                          cwd=PROJECT, env=env)


def test_third_party_plugin_is_listed_and_runs(installed_plugin, tmp_path):
    listing = g2s(installed_plugin, "plugins", "--stage", "analyzers")
    assert listing.returncode == 0, listing.stderr
    assert "analyzers\n" in listing.stdout and "  root_distance  (g2s-example-plugin)\n" in listing.stdout
    assert "hops:  true or false, default False" in listing.stdout

    out = tmp_path / "out"
    proc = g2s(installed_plugin, "run", str(PLUGIN_DIR / "root_distance.yaml"), "sample:cross_hub", "-o", str(out), "--json")
    assert proc.returncode == 0, proc.stderr
    stages = [s["stage"] for s in json.loads(proc.stdout)["stages"]]
    assert stages[-1] == "analysis"


def test_third_party_values_reach_the_result(installed_plugin):
    # in a fresh interpreter, so that the newly installed distribution's entry points are seen
    script = """
from g2s_core import pipeline
from g2s_plugins.samples import levels as samples
from g2s_core.config import load_config
from g2s_core.mesh import mesh_sha256
from g2s_core.registry import Registry
registry = Registry.from_entry_points()
plan = pipeline.plan(load_config(%r), registry)
mesh = samples.cross_hub().mesh
result = pipeline.run(plan, registry, mesh, "cross_hub", mesh_sha256(mesh))
values = result.analysis["root_distance"]
assert values and all(values[n] == d for n, d in result.structure.nodes(data="depth")), values
print(len(values))
""" % str(PLUGIN_DIR / "root_distance.yaml")
    proc = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, cwd=PROJECT, env=installed_plugin)
    assert proc.returncode == 0, proc.stderr
    assert int(proc.stdout) >= 4


def test_third_party_writer_and_level_generator(installed_plugin, tmp_path):
    listing = g2s(installed_plugin, "plugins")
    assert listing.returncode == 0, listing.stderr
    assert "outputs\n" in listing.stdout and "  csv  (g2s-example-plugin)\n" in listing.stdout
    assert "levels\n" in listing.stdout and "  plaza  (g2s-example-plugin)\n" in listing.stdout
    assert "size:  a number > 0, default 20.0" in listing.stdout

    out = tmp_path / "out"
    proc = g2s(installed_plugin, "run", str(PLUGIN_DIR / "root_distance.yaml"), "sample:plaza?size=40", "-o", str(out),
               "--format", "csv,json", "--json")
    assert proc.returncode == 0, proc.stderr
    assert sorted(p.name for p in out.iterdir()) == ["nodes.csv", "run.json", "structure.json"]
    rows = (out / "nodes.csv").read_text().splitlines()
    structure = json.loads((out / "structure.json").read_text())
    assert rows[0] == "id,x,y,z,depth" and len(rows) - 1 == len(structure["nodes"]) >= 2
    # the plaza is 40 m wide: every node lies on it
    assert all(abs(float(x)) <= 20 and abs(float(z)) <= 20 for _, x, _, z, _ in (r.split(",") for r in rows[1:]))

    bad = g2s(installed_plugin, "run", str(PLUGIN_DIR / "root_distance.yaml"), "sample:plaza?size=-1", "-o", str(tmp_path / "bad"))
    assert bad.returncode == 2 and bad.stderr.strip() == (
        "g2s: error: sample:plaza.size: expected a number > 0, got '-1'")


def test_a_broken_plugin_is_listed_and_stops_only_the_runs_that_use_it(installed_plugin, tmp_path):
    listing = g2s(installed_plugin, "plugins", "--stage", "analyzers")
    assert listing.returncode == 0, listing.stderr
    assert "broken analyzers.broken  (g2s-example-plugin)" in listing.stdout
    assert "No module named" in listing.stdout or "cannot import name" in listing.stdout

    config = tmp_path / "broken.yaml"
    config.write_text(f"extends: {PLUGIN_DIR / 'root_distance.yaml'}\nanalyzers: [{{plugin: broken}}]\n")
    proc = g2s(installed_plugin, "run", str(config), "sample:cross_hub", "-o", str(tmp_path / "out"))
    assert proc.returncode == 1 and "Traceback" not in proc.stderr  # a plugin's bug, not bad input (exit 2 before robust9)
    assert proc.stderr.splitlines()[0].startswith(
        "g2s: error: Analyzer plugin 'broken' (package 'g2s-example-plugin') failed to load: ")
    assert not (tmp_path / "out").exists()


def test_an_exception_inside_a_plugin_names_the_plugin_and_its_package(installed_plugin, tmp_path):
    config = tmp_path / "explodes.yaml"
    config.write_text(f"extends: {PLUGIN_DIR / 'root_distance.yaml'}\nanalyzers: [{{plugin: explodes}}]\n")
    proc = g2s(installed_plugin, "run", str(config), "sample:cross_hub", "-o", str(tmp_path / "out"))
    assert proc.returncode == 1, proc.stderr  # a plugin's bug, not bad input (exit 2 before robust9)
    assert proc.stderr.strip() == (
        "g2s: error: Analyzer plugin 'explodes' (package 'g2s-example-plugin') failed: raised KeyError: 'height'")
    assert not (tmp_path / "out").exists()


def test_third_party_command_runs_through_g2s(installed_plugin, tmp_path):
    helped = g2s(installed_plugin, "--help")
    assert helped.returncode == 0, helped.stderr
    assert "    level        write a level of an installed level generator to a mesh file" in helped.stdout
    assert "batch" in helped.stdout  # the built-in command plugin stays
    listing = g2s(installed_plugin, "plugins", "--stage", "commands")
    assert "  level  (g2s-example-plugin)\n" in listing.stdout and "  batch  (graph2structure)\n" in listing.stdout

    level = tmp_path / "plaza.obj"
    proc = g2s(installed_plugin, "level", "sample:plaza?size=40", str(level))
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout == f"wrote {level}: 12 triangles\n"
    run = g2s(installed_plugin, "run", "graph_only", str(level), "-o", str(tmp_path / "out"), "--json")
    assert run.returncode == 0, run.stderr  # the written level is a mesh g2s reads

    again = g2s(installed_plugin, "level", "sample:plaza", str(level))
    assert again.returncode == 2 and again.stderr.strip() == f"g2s: error: {level}: exists already; choose another file name"
    bad = g2s(installed_plugin, "level", "sample:plaza?size=-1", str(tmp_path / "bad.obj"))
    assert bad.returncode == 2 and bad.stderr.strip() == "g2s: error: sample:plaza.size: expected a number > 0, got '-1'"


def test_a_command_without_an_exit_code_is_that_plugins_failure(installed_plugin):
    proc = g2s(installed_plugin, "generators")
    assert proc.returncode == 1 and "Traceback" not in proc.stderr
    assert proc.stderr.strip() == ("g2s: error: Command plugin 'generators' (package 'g2s-example-plugin') failed: "
                                   "its function returned NoneType, not an exit code")
