"""Mesh paths that are not regular files, and OBJ text that is not UTF-8."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from g2s_core.errors import MeshError
from g2s_core.mesh import load_mesh
from tests.reliability.checks import assert_clean_error, run_g2s, snapshot, tree

FLOOR_OBJ = """# {comment}
o {name}
v -10 0 -10
v 10 0 -10
v 10 0 10
v -10 0 10
f 1 4 3
f 1 3 2
"""


@pytest.mark.parametrize("encoding", ["latin-1", "cp1252", "utf-16", "utf-8-sig"])
def test_obj_in_another_encoding_runs(encoding, tmp_path, quick_config, capsys):
    mesh = tmp_path / "floor.obj"
    mesh.write_bytes(FLOOR_OBJ.format(comment="salle à manger « sol »", name="étage").encode(encoding))
    before = snapshot([mesh])
    outcome = run_g2s(capsys, "run", quick_config, mesh, "-o", tmp_path / "out", "-q")
    assert outcome.code == 0, outcome.stderr
    assert tree(tmp_path / "out") == ["graph.json"]
    assert snapshot([mesh]) == before


def test_obj_with_a_byte_order_mark_before_its_first_vertex_is_read_whole(tmp_path, quick_config, capsys):
    # trimesh took the mark for part of the first line: the first vertex was lost and the faces pointed past the
    # end ("cannot read mesh (IndexError: index 3 is out of bounds ...)"); CRLF line ends as Windows writes them
    body = "\r\n".join(FLOOR_OBJ.splitlines()[2:]) + "\r\n"
    (tmp_path / "plain.obj").write_text(body)
    (tmp_path / "marked.obj").write_bytes(b"\xef\xbb\xbf" + body.encode())
    graphs = []
    for name in ("plain", "marked"):
        outcome = run_g2s(capsys, "run", quick_config, tmp_path / f"{name}.obj", "-o", tmp_path / name, "-q")
        assert outcome.code == 0, outcome.stderr
        written = json.loads((tmp_path / name / "graph.json").read_text())
        graphs.append((written["nodes"], written["edges"]))
    assert graphs[0] == graphs[1] and graphs[0][0]


def _symlink_to_zero(folder: Path) -> Path:
    path = folder / "zero.obj"
    path.symlink_to("/dev/zero")
    return path


def _fifo(folder: Path) -> Path:
    path = folder / "pipe.obj"
    os.mkfifo(path)
    return path


def _folder(folder: Path) -> Path:
    path = folder / "level.obj"
    path.mkdir()
    return path


@pytest.mark.parametrize(
    "make, says",
    [(_symlink_to_zero, "got a character device"), (_fifo, "got a FIFO"), (_folder, "got a folder"),
     (lambda folder: Path("/dev/zero"), "got a character device")],
    ids=["link-to-dev-zero", "fifo", "folder", "dev-zero"],
)
def test_mesh_that_is_not_a_regular_file(make, says, tmp_path, quick_config, capsys):
    mesh = make(tmp_path)
    out = tmp_path / "out"
    assert_clean_error(run_g2s(capsys, "run", quick_config, mesh, "-o", out), str(mesh), says)
    assert tree(out) == []
    with pytest.raises(MeshError, match=says):
        load_mesh(mesh)
