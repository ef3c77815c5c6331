"""Inputs robust20 (6 December 2026) found breaking docs/errors.md's rules: ``g2s --help`` and ``--version`` with
both standard streams closed (exit 0, the help sent to the closed standard error's stream); a glTF file of no scene
(trimesh's ``IndexError``, or "the mesh is empty" for a file holding a mesh); ``FORCE_COLOR`` drawing the spinner on
a standard error that is no terminal; an ``MPLBACKEND`` that matplotlib does not know, blamed on the writers."""

from __future__ import annotations

import base64
import json
import struct
import sys
from pathlib import Path

import pytest

from g2s_core.cli import main
from g2s_core.errors import MeshError
from g2s_core.mesh import load_mesh
from tests.reliability.checks import CORRIDOR, assert_clean_error, run_g2s_process


def exit_code(args: list[str]) -> int:
    try:
        return main(args)
    except SystemExit as stopped:
        return stopped.code


@pytest.mark.parametrize("args", [["--help"], ["run", "--help"], ["--version"]])
def test_help_and_version_with_both_streams_closed_are_not_a_success(args, monkeypatch):
    # `g2s --help >&- 2>&-`: sys.stdout and sys.stderr are both None, and argparse's help, meant for standard output,
    # was taken for standard error's (`file is sys.stderr`), whose failed write is dropped: exit 0, nothing written
    monkeypatch.setattr(sys, "stdout", None)
    monkeypatch.setattr(sys, "stderr", None)
    assert exit_code(args) == 2
    assert exit_code(["run"]) == 2  # a usage error's line, meant for standard error, is dropped and its code stands


def test_help_with_standard_error_closed_is_written_and_a_usage_error_is_not(monkeypatch, capsys):
    monkeypatch.setattr(sys, "stderr", None)
    assert exit_code(["--help"]) == 0
    assert capsys.readouterr().out.startswith("usage: g2s ")
    assert exit_code(["run"]) == 2
    assert capsys.readouterr().out == ""  # the error line does not go to standard output


def gltf_of_one_triangle(path: Path, **document: object) -> Path:
    """A glTF file of one triangle (its buffer a data URI), one node placing it, and ``document``'s keys over those."""
    corners = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 0, 1)
    path.write_text(json.dumps({
        "asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 0, 1]}],
        "bufferViews": [{"buffer": 0, "byteLength": len(corners)}],
        "buffers": [{"byteLength": len(corners), "uri": "data:application/octet-stream;base64," + base64.b64encode(corners).decode()}],
        **document}))
    return path


@pytest.mark.parametrize("scenes", [[], None])
def test_a_gltf_of_no_scene_is_named_so(scenes, tmp_path):
    # `scenes: []` was "cannot read mesh (IndexError: list index out of range)", trimesh's words; no `scenes` at all (a
    # valid glTF: a library of meshes) "the mesh is empty (no triangles)", though the file holds a mesh
    path = gltf_of_one_triangle(tmp_path / "level.gltf", scenes=scenes)
    if scenes is None:
        path.write_text(json.dumps({key: value for key, value in json.loads(path.read_text()).items() if key != "scenes"}))
    with pytest.raises(MeshError) as raised:
        load_mesh(path)
    assert str(raised.value) == f"{path}: the file lists no scene, so none of its 1 mesh is placed; expected a scene of the level's nodes"
    assert load_mesh(gltf_of_one_triangle(tmp_path / "sound.gltf"))[1].faces == 1


def test_force_color_shows_no_spinner_on_a_standard_error_that_is_no_terminal(monkeypatch, capsys, tmp_path):
    # rich takes FORCE_COLOR (colours, as CI logs ask for) for a terminal: the spinner's frames, in escape codes, came
    # before the error's line (two lines in a file)
    monkeypatch.setenv("FORCE_COLOR", "1")
    assert exit_code(["run", "graph_only", "sample:straight_corridor", "-o", str(tmp_path / "out"), "--set", "agent.radius=50"]) == 2
    said = capsys.readouterr().err
    assert said.startswith("g2s: error: straight_corridor: no walkable surface for the agent") and said.count("\n") == 1, said


def test_an_mplbackend_matplotlib_does_not_know_is_named_not_blamed_on_the_writer(monkeypatch, tmp_path):
    # was exit 1, "OutputWriter plugin 'png' (package 'graph2structure') failed: raised ValueError: Key backend:
    # 'nosuch' is not a valid value for backend; ...": matplotlib refuses it as it loads (a child process, where
    # matplotlib is not loaded yet)
    monkeypatch.setenv("MPLBACKEND", "nosuch")
    outcome = run_g2s_process("run", "graph_only", CORRIDOR, "-o", tmp_path / "out", "--format", "json,png")
    assert_clean_error(outcome, "MPLBACKEND: expected a backend matplotlib knows (e.g. agg), got 'nosuch'", "png output")
    assert not (tmp_path / "out").exists()


def test_networkx_settings_in_the_environment_that_it_refuses_are_named(monkeypatch, tmp_path):
    # was exit 1, "internal error: ValueError: Unknown backend when setting 'algos': 'nosuch'": networkx refuses them as
    # the Python API imports it (a child process, where networkx is not loaded yet)
    monkeypatch.setenv("NETWORKX_BACKEND_PRIORITY", "nosuch")
    outcome = run_g2s_process("run", "graph_only", CORRIDOR, "-o", tmp_path / "out")
    assert_clean_error(outcome, "NETWORKX_BACKEND_PRIORITY='nosuch': networkx refused the environment's setting as it loaded "
                       "(Unknown backend when setting 'algos': 'nosuch')")
