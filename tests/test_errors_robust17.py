"""Inputs robust17 (5 December 2026) found ending in an internal error: a level or config whose file name is not
UTF-8 (bytes Python keeps as lone surrogates, ``'m\\udcff.obj'``), which no UTF-8 output can hold. The name is
made text once, where the core reads the mesh file, with such bytes as ``\\xNN`` escapes (``m\\xff.obj``), the file
itself read as any other. Assertion messages show such names through ``ascii`` so that a failure prints."""

from __future__ import annotations

import json
import os
import shutil

import pytest

from g2s_core.mesh import text_of_name
from tests.reliability.checks import CORRIDOR, run_g2s

NOT_UTF8 = os.fsdecode(b"level\xff")
"""A file stem holding the byte 0xFF, which starts no UTF-8 character (Linux file names are bytes)."""


@pytest.fixture
def level_not_utf8(tmp_path):
    """The straight corridor sample as an OBJ file whose name is not UTF-8."""
    from g2s_core.mesh import generate_level

    path = tmp_path / f"{NOT_UTF8}.obj"
    generate_level(CORRIDOR).export(path)
    return path


def test_a_name_that_is_not_utf8_becomes_escaped_text_and_others_stay_as_they_are():
    assert text_of_name(os.fsdecode(b"m\xff.obj")) == "m\\xff.obj"
    assert text_of_name("lévél ✓.obj") == "lévél ✓.obj"


def test_a_level_whose_name_is_not_utf8_runs_and_its_results_name_it(level_not_utf8, tmp_path, capsys):
    # json alone: every writer gets the name from the result, and the others' imports cost seconds
    out = tmp_path / "out"
    outcome = run_g2s(capsys, "run", "map_analysis", level_not_utf8, "-o", out, "--format", "json", "--json")
    assert outcome.code == 0, ascii(outcome.stderr)
    names = [json.loads((out / name).read_text(encoding="utf-8"))["mesh"]["name"] for name in ("structure.json", "run.json")]
    assert names == ["level\\xff.obj"] * 2, ascii(names)
    printed = json.loads(outcome.stdout)["mesh"]
    assert printed == names[0], ascii(printed)


def test_the_python_api_names_such_a_level_as_its_outputs_do(level_not_utf8):
    from g2s_core import api

    result = api.run(level_not_utf8, "graph_only")
    assert result.mesh_name == "level\\xff.obj", ascii(result.mesh_name)


def test_a_batch_over_a_level_and_a_config_whose_names_are_not_utf8_writes_its_summary(level_not_utf8, tmp_path, capsys):
    config = tmp_path / f"{NOT_UTF8}.yaml"
    config.write_text("extends: graph_only\n")
    out = tmp_path / "out"
    outcome = run_g2s(capsys, "batch", config, level_not_utf8, "-o", out, "--executor", "serial", "-q")
    assert outcome.code == 0, ascii(outcome.stderr)
    row = (out / "summary.csv").read_text(encoding="utf-8").splitlines()[1]
    assert row.startswith("level\\xff,level\\xff,") and "ok" in row.split(","), ascii(row)
    shutil.rmtree(out)
