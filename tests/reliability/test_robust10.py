"""Inputs robust10 (4 December 2026) found read silently wrong, told in other words or ending in a traceback, each
test failing on the code before its fix (docs/errors.md, "The hostile-user pass of robust10")."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys

import numpy as np
import pytest

from g2s_core.errors import MeshError
from g2s_core.mesh import load_mesh
from g2s_core.mesh_damage import describe_damage
from tests.reliability.checks import CORRIDOR, Outcome, assert_clean_error, run_g2s, tree

FLOOR = "v 0 0 0\nv 10 0 0\nv 10 0 10\nv 0 0 10\nf 1 3 2\nf 1 4 3\n"
"""A 10 m square floor of two triangles."""


@pytest.mark.parametrize("text", [
    FLOOR.replace("v 10 0 0", "v 10 0 0 # x").replace("f 1 4 3", "f 1 4 3#floor"),  # after values
    "o room # c\ng floor # c\nusemtl stone # c\ns 1 # c\nmtllib a#b.mtl\n" + FLOOR + "l 1 2 # edge\n",  # other lines
    FLOOR.replace("f 1 3 2", "f 1 3 2\ng floor # walls and \\"),  # a comment ending in a backslash ...
    FLOOR.replace("f 1 3 2", "f 1 3 2\nusemtl stone # \\"),
    FLOOR.replace("f 1 3 2", "f 1 3 2\n# a note \\"),  # ... on a comment line too
    FLOOR.replace("f 1 4 3", "f 1 4 3 # f 1 2 99").replace("\n", "\r\n"),  # a face inside a comment, CRLF
])
def test_an_obj_comment_is_one_rule_for_the_check_and_the_reading(text, tmp_path):
    # the check cut every line at its "#", the reading only a v, vt, vn or f line's: trimesh joins a line ending in
    # "\" to the next, so a comment ending in one on another line hid the face after it (read: half the floor, exit 0)
    path = tmp_path / "level.obj"
    path.write_text(text, newline="")
    mesh, _ = load_mesh(path)
    assert describe_damage(path, path.read_bytes()) is None
    assert len(mesh.faces) == 2 and mesh.area == pytest.approx(100.0)
    np.testing.assert_array_equal(np.unique(mesh.vertices, axis=0), [[0, 0, 0], [0, 0, 10], [10, 0, 0], [10, 0, 10]])


def test_a_face_hidden_in_a_comment_is_not_checked(tmp_path):
    # the same rule for the check: a face past the vertices inside a comment is no face, one outside it is named
    path = _written(tmp_path, FLOOR + "f 1 2 9 # f 1 2 3\n")
    with pytest.raises(MeshError, match=r"line 7: a face refers to vertex 9; the file has 4 vertices"):
        load_mesh(path)
    assert load_mesh(_written(tmp_path, FLOOR + "# f 1 2 9\n"))[0].faces.shape == (2, 3)


def _written(folder, text: str, name: str = "floor.obj"):
    path = folder / name
    path.write_text(text)
    return path


@pytest.mark.parametrize("config, level", [
    ("...yaml", "floor.obj"),  # its results went to OUTDIR/../floor, beside the batch folder
    ("..yaml", "floor.obj"),  # into OUTDIR itself
    ("summary.csv.yaml", "floor.obj"),  # internal error (IsADirectoryError) once every pair had run
    ("summary.parquet.yaml", "floor.obj"),
    (".g2s-batch.yaml", "floor.obj"),  # its results among the batch's records
    ("graph_only", "...obj"),  # the level's results in OUTDIR, beside its config's folder
    ("graph_only", "..obj"),
])
def test_a_batch_refuses_a_name_that_cannot_name_a_results_folder(config, level, tmp_path, capsys):
    (tmp_path / level).write_text(FLOOR)
    if config.endswith(".yaml"):
        (tmp_path / config).write_text("extends: graph_only\n")
        config = str(tmp_path / config)
    before = sorted(os.listdir(tmp_path))
    outcome = run_g2s(capsys, "batch", config, tmp_path / level, "-o", tmp_path / "out", "--executor", "serial")
    assert "cannot name the folder of its results (not '.', '..'" in assert_clean_error(outcome)
    assert tree(tmp_path / "out") == [] and sorted(os.listdir(tmp_path)) == before


def _bad_level(folder, name: str):
    path = folder / name
    path.write_text("v 0 0 0\nf 1 2 9\n")
    return path


def test_a_line_break_in_a_file_name_keeps_the_error_one_line(tmp_path, capsys):
    # "g2s: error: .../bad" and "level.obj: line 2: ..." were two lines (three in g2s batch's line of a failed pair)
    mesh = _bad_level(tmp_path, "bad\nlevel.obj")
    line = assert_clean_error(run_g2s(capsys, "run", "graph_only", mesh, "-o", tmp_path / "out"))
    assert "bad\\nlevel.obj: line 2: a face refers to vertex 2" in line
    outcome = run_g2s(capsys, "batch", "graph_only", mesh, _bad_level(tmp_path, "cr\rlevel.obj"),
                      "-o", tmp_path / "batch", "--executor", "serial", "-q")
    assert outcome.code == 4 and "Traceback" not in outcome.stderr
    assert outcome.stderr.splitlines() == [
        f"g2s: graph_only on bad\\nlevel failed: {tmp_path}/bad\\nlevel.obj: line 2: a face refers to vertex 2; the file has 1 vertex",
        f"g2s: graph_only on cr\\rlevel failed: {tmp_path}/cr\\rlevel.obj: line 2: a face refers to vertex 2; the file has 1 vertex"]


def _as_a_user(*args: str, **kwargs) -> subprocess.CompletedProcess:
    """``g2s ARGS`` in a child process where file modes apply: as root, without the capabilities that override them."""
    command = [sys.executable, "-c", "from g2s_core.entry import main; raise SystemExit(main())", *args]
    if os.geteuid() == 0:
        if not shutil.which("setpriv"):
            pytest.skip("running as root without setpriv, which file modes do not stop")
        command = ["setpriv", "--bounding-set=-dac_override,-dac_read_search", *command]
    return subprocess.run(command, capture_output=True, text=True, timeout=120, **kwargs)


def test_a_batch_folder_holding_a_folder_it_cannot_read_is_refused(tmp_path):
    # rglob leaves an unreadable folder out without a word: its levels were missing from the summary (exit 0)
    (tmp_path / "levels" / "act2").mkdir(parents=True)
    (tmp_path / "levels" / "good.obj").write_text(FLOOR)
    (tmp_path / "levels" / "act2" / "cave.obj").write_text(FLOOR)
    (tmp_path / "levels" / "act2").chmod(0)
    try:
        done = _as_a_user("batch", "graph_only", str(tmp_path / "levels"), "-o", str(tmp_path / "out"), "--executor", "serial")
    finally:
        (tmp_path / "levels" / "act2").chmod(0o755)
    assert_clean_error(Outcome(done.returncode, done.stdout, done.stderr),
                       f"{tmp_path}/levels/act2: cannot read this folder (permission denied): its levels would be left out")
    assert tree(tmp_path / "out") == []


def test_a_full_standard_output_is_one_line(tmp_path):
    # "g2s: internal error: OSError: [Errno 28] No space left on device" and the --verbose hint, exit 1
    (tmp_path / "floor.obj").write_text(FLOOR)
    with open("/dev/full", "w") as full:
        for args in (["plugins"], ["run", "graph_only", str(tmp_path / "floor.obj"), "-o", str(tmp_path / "out")]):
            done = subprocess.run([sys.executable, "-m", "g2s_core.cli", *args], stdout=full, stderr=subprocess.PIPE, text=True,
                                  timeout=120)
            assert_clean_error(Outcome(done.returncode, "", done.stderr), "cannot write to standard output (No space left on device)")
    assert tree(tmp_path / "out") == ["graph.json"]  # the run's results are whole: only the list of them was lost


def test_a_name_the_terminal_cannot_encode_is_escaped_not_an_internal_error(tmp_path):
    # "g2s: internal error: UnicodeEncodeError: 'ascii' codec can't encode character '\xf6'" as the finished run
    # printed "wrote ..." (LANG of an encoding without the character, or PYTHONIOENCODING=ascii)
    (tmp_path / "fl\u00f6or.obj").write_text(FLOOR)
    done = _as_a_user("run", "graph_only", str(tmp_path / "fl\u00f6or.obj"), "-o", str(tmp_path / "\u00fcber"),
                      env={**os.environ, "PYTHONIOENCODING": "ascii"})
    assert (done.returncode, done.stderr) == (0, "")
    assert f"wrote {tmp_path}/\\xfcber/graph.json" in done.stdout


def test_a_librarys_logged_warning_does_not_reach_stderr(tmp_path):
    # matplotlib, whose config folder cannot be made (a HOME without write access), logged two warnings of several
    # lines on stderr ("mkdir -p failed for path ...", "Matplotlib created a temporary cache directory ...")
    (tmp_path / "not_a_folder").write_text("")
    env = {**os.environ, "MPLCONFIGDIR": str(tmp_path / "not_a_folder")}
    done = subprocess.run([sys.executable, "-m", "g2s_core.cli", "run", "map_analysis", CORRIDOR, "-o", str(tmp_path / "out"),
                           "--format", "png"], capture_output=True, text=True, timeout=300, env=env)
    assert (done.returncode, done.stderr) == (0, "")
    assert tree(tmp_path / "out") == ["heatmap.png"]
