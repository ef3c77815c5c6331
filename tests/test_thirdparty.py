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
def installed_plugin():
    pip = [sys.executable, "-m", "pip", "--disable-pip-version-check", "-q"]
    subprocess.run([*pip, "install", str(PLUGIN_DIR)], check=True, capture_output=True)
    yield
    subprocess.run([*pip, "uninstall", "-y", "g2s-example-plugin"], check=True, capture_output=True)


def g2s(*args):
    return subprocess.run([sys.executable, "-m", "g2s_core.cli", *args], capture_output=True, text=True,
                          cwd=PROJECT, env={**os.environ, "COLUMNS": "200"})


def test_third_party_plugin_is_listed_and_runs(installed_plugin, tmp_path):
    listing = g2s("plugins", "--stage", "analyzers")
    assert listing.returncode == 0, listing.stderr
    assert "analyzers\n" in listing.stdout and "  root_distance  (g2s-example-plugin)\n" in listing.stdout
    assert "hops:  true or false, default False" in listing.stdout

    out = tmp_path / "out"
    proc = g2s("run", str(PLUGIN_DIR / "root_distance.yaml"), "sample:cross_hub", "-o", str(out), "--json")
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
    proc = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, cwd=PROJECT)
    assert proc.returncode == 0, proc.stderr
    assert int(proc.stdout) >= 4
