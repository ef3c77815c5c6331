"""Inputs robust9 (4 December 2026) found told in other words or refused wrongly: ``g2s batch --format`` named the
Python API's ``formats``; a plugin's own failure was exit 2, the code of bad input; damaged or unusual mesh files
(a binary PLY of triangles and quads, a PLY without z, an ASCII STL cut short, glTF nodes and primitive modes of
another kind, an OBJ comment after a line's values) were a library's words, a false cause or refused."""

from __future__ import annotations

import pytest

from tests.reliability.checks import assert_clean_error, run_g2s, tree

FLOOR = "v 0 0 0\nv 10 0 0\nv 10 0 10\nv 0 0 10\nf 1 3 2\nf 1 4 3\n"


@pytest.fixture
def floor(tmp_path):
    path = tmp_path / "floor.obj"
    path.write_text(FLOOR)
    return path


@pytest.mark.parametrize("given, says", [("jsno", "--format: unknown output format 'jsno' (expected some of: "),
                                         ("", "--format: no output format given (expected some of: ")])
def test_batch_names_its_format_option(given, says, floor, tmp_path, capsys):
    # was "formats: ...", the Python API's parameter, since robust8 named write()'s own
    outcome = run_g2s(capsys, "batch", "graph_only", floor, "--format", given, "-o", tmp_path / "out")
    assert assert_clean_error(outcome).startswith(f"g2s: error: {says}")
    assert tree(tmp_path / "out") == []
