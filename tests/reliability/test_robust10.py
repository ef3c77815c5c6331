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


@pytest.mark.parametrize("level", ["act1/...obj", "act1/..obj"])
def test_a_batch_refuses_a_folders_level_whose_path_holds_a_dot_part(level, tmp_path, capsys):
    # a folder's level is named by its path in the folder: act1/...obj, named "act1/..", wrote its results into its
    # config's folder itself (review29)
    (tmp_path / "levels" / "act1").mkdir(parents=True)
    (tmp_path / "levels" / level).write_text(FLOOR)
    outcome = run_g2s(capsys, "batch", "graph_only", tmp_path / "levels", "-o", tmp_path / "out", "--executor", "serial")
    assert "cannot name the folder of its results (not '.', '..'" in assert_clean_error(outcome)
    assert tree(tmp_path / "out") == []


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


def _gltf(stride: object) -> str:
    """A glTF of the 10 m floor whose positions' buffer view has the byte stride ``stride``, each vertex padded to it."""
    import base64
    import json
    import struct

    step = stride if isinstance(stride, int) and stride > 12 else 12
    positions = b"".join(struct.pack("<3f", *v) + b"\0" * (step - 12) for v in ((0, 0, 0), (10, 0, 0), (10, 0, 10), (0, 0, 10)))
    data = positions + struct.pack("<6I", 0, 2, 1, 0, 3, 2)
    return json.dumps({
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "buffers": [{"uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode(), "byteLength": len(data)}],
        "bufferViews": [{"buffer": 0, "byteLength": len(positions), "byteStride": stride},
                        {"buffer": 0, "byteOffset": len(positions), "byteLength": 24}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
                      {"bufferView": 1, "componentType": 5125, "count": 6, "type": "SCALAR"}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}]})


@pytest.mark.parametrize("stride", [4, 0, -12, "12", 12.5])
def test_a_gltf_stride_shorter_than_its_elements_is_named(stride, tmp_path):
    # a stride of 4 read each vertex overlapping the next (refused as "most flat faces face along z, not y"); 0 and -12
    # were trimesh's "cannot read mesh (AssertionError: byteStride should be positive)"
    path = tmp_path / "level.gltf"
    path.write_text(_gltf(stride))
    with pytest.raises(MeshError, match=rf"bufferViews\[0\]\.byteStride is {stride!r}; expected an integer >= 12, the bytes of one "
                                        r"element of accessors\[0\] \(VEC3 of 4-byte numbers\)"):
        load_mesh(path)


@pytest.mark.parametrize("stride", [12, 16, 13, 256])  # a multiple of 4 up to 252 in the specification; read right all the same
def test_a_gltf_stride_of_whole_elements_is_read(stride, tmp_path):
    path = tmp_path / "level.gltf"
    path.write_text(_gltf(stride))
    assert load_mesh(path)[0].area == pytest.approx(100.0)


def test_a_glb_of_another_version_is_named(tmp_path):
    # trimesh's "cannot read mesh (NotImplementedError: only GLTF 2 is supported not `1`)"
    path = tmp_path / "level.glb"
    path.write_bytes(b"glTF" + (1).to_bytes(4, "little") + (12).to_bytes(4, "little"))
    with pytest.raises(MeshError, match=r"the GLB header's version is 1; g2s reads GLB version 2 \(glTF 2.0\)"):
        load_mesh(path)


@pytest.mark.parametrize("size", [4, 7, 11])
def test_a_glb_cut_inside_its_header_is_named_cut(size, tmp_path):
    # was named by its version (4 bytes: "version is 0") or its first chunk ("of type ''"), both read from the cut
    path = tmp_path / "level.glb"
    path.write_bytes((b"glTF" + (2).to_bytes(4, "little") + (100).to_bytes(4, "little"))[:size])
    with pytest.raises(MeshError, match=rf"the GLB file ends early \(its header is 12 bytes, the file has {size}\)"):
        load_mesh(path)


def test_a_snap_ray_longer_than_any_level_is_refused_by_its_key(tmp_path, capsys):
    # 1e308 m overflowed the rays' ends to inf: "entry_exit failed: raised LinAlgError", exit 1
    config = tmp_path / "long_snap.yaml"
    config.write_text("extends: map_piece\nterminals:\n  params:\n    snap_distance: 1.0e308\n")
    assert_clean_error(run_g2s(capsys, "run", config, CORRIDOR, "-o", tmp_path / "out"),
                       "terminals.params.snap_distance: expected a number or null > 0 and <= 1000000.0, got 1e+308")
    assert not (tmp_path / "out").exists()
