"""What the answers that need no computation import (docs/performance.md, "Start-up"): `g2s --version` no plugin
and no heavy library; `--help`, a config error and `g2s presets` only the plugins they name, none of trimesh, scipy,
networkx, numpy; `g2s plugins --stage KEY` only that stage's plugins. Each case runs in a fresh interpreter, so the
test sees exactly what that command imported."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

from tests.conftest import PROJECT

COMMANDS_AND_WRITERS = {"g2s_plugins.batch", "g2s_plugins.batch.command", "g2s_plugins.batch.runner", "g2s_plugins.demo",
                        "g2s_plugins.plugin_list", "g2s_plugins.preset_list",
                        "g2s_plugins.outputs", "g2s_plugins.outputs.writers"}
"""The plugin modules the parser needs: the commands it offers and the writers `g2s run --help` names."""
HEAVY = ("trimesh", "scipy", "networkx", "numpy", "pymeshlab", "rustworkx", "igraph", "plotly", "matplotlib", "PIL")

PROBE = """
import contextlib, io, json, sys
from g2s_core import cli
watched, argv = sys.argv[1].split(","), sys.argv[2:]
with contextlib.redirect_stdout(io.StringIO()) as out, contextlib.redirect_stderr(io.StringIO()) as err:
    try:
        code = cli.main(argv)
    except SystemExit as exit:
        code = exit.code
print(json.dumps({"code": code, "out": out.getvalue(), "err": err.getvalue(),
                  "modules": sorted(name for name in sys.modules if name.partition(".")[0] in watched)}))
"""


def imported(*argv: str) -> dict:
    """Exit code, output and the top-level packages of :data:`HEAVY` and ``g2s_plugins`` that ``g2s *argv`` imported."""
    proc = subprocess.run([sys.executable, "-c", PROBE, ",".join((*HEAVY, "g2s_plugins")), *argv],
                          capture_output=True, text=True, cwd=PROJECT, check=True)
    return json.loads(proc.stdout)


def test_version_loads_no_plugin_and_no_heavy_library():
    answer = imported("--version")
    assert answer["code"] == 0 and answer["out"].startswith("g2s ")
    assert answer["modules"] == []


@pytest.mark.parametrize("argv", [["--help"], ["run", "--help"], ["presets"]])
def test_help_and_presets_load_only_the_commands_and_writers_they_show(argv):
    answer = imported(*argv)
    assert answer["code"] == 0 and answer["out"]
    plugins = {name for name in answer["modules"] if name.startswith("g2s_plugins.")}
    assert plugins <= COMMANDS_AND_WRITERS
    assert not [name for name in answer["modules"] if not name.startswith("g2s_plugins")]


def test_a_config_error_is_found_before_any_heavy_library_loads(tmp_path):
    config = tmp_path / "typo.yaml"
    config.write_text("extends: map_piece\nagnet: {radius: 0.4}\n")
    answer = imported("run", str(config), "level.obj", "-o", str(tmp_path / "out"))
    assert answer["code"] == 2 and "agnet: unknown key" in answer["err"]
    assert not [name for name in answer["modules"] if not name.startswith("g2s_plugins")]


@pytest.mark.parametrize(("stage", "modules"), [
    ("outputs", set()),
    ("executors", {"g2s_plugins.executors", "g2s_plugins.executors.dask_cluster", "g2s_plugins.executors.process_pool",
                   "g2s_plugins.executors.serial"}),
])
def test_plugins_of_one_stage_load_that_stage_alone(stage, modules):
    """The broken plugins it lists are that stage's too, so no other stage (trimesh and scipy with them) loads."""
    answer = imported("plugins", "--stage", stage)
    assert answer["code"] == 0 and answer["out"].startswith(f"{stage}\n")
    assert {name for name in answer["modules"] if name.startswith("g2s_plugins.")} == COMMANDS_AND_WRITERS | modules
    assert not [name for name in answer["modules"] if not name.startswith("g2s_plugins")]


def test_the_sample_levels_are_listed_without_trimesh_or_scipy():
    """Their parameters are their factories' signatures; the sample modules import trimesh and scipy where they build."""
    answer = imported("plugins", "--stage", "levels")
    assert answer["code"] == 0 and "\n  dungeon  (graph2structure)\n" in answer["out"]
    assert {name.partition(".")[0] for name in answer["modules"]} == {"g2s_plugins", "numpy"}


def test_listing_every_plugin_loads_numpy_alone_of_the_heavy_libraries():
    """Every plugin module is imported for its parameters; the modules that listing imports bind scipy, trimesh,
    rustworkx and networkx with :func:`g2s_core.lazy.lazy_module` (and the shared modules that import them at their
    top, where they call them), so none of those loads: the sample levels' numpy alone."""
    answer = imported("plugins")
    assert answer["code"] == 0 and "\n  sampling  (graph2structure)\n" in answer["out"] and "failed to load" not in answer["out"]
    assert {name.partition(".")[0] for name in answer["modules"]} == {"g2s_plugins", "numpy"}
