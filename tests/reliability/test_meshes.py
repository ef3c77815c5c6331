"""Mesh paths that are not regular files, and OBJ text that is not UTF-8."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from g2s_core.errors import MeshError
from g2s_core.mesh import load_mesh
from tests.reliability.checks import assert_clean_error, run_g2s, run_g2s_process, snapshot, tree

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


# --- damaged STL, GLB and glTF files: what is wrong, in words (trimesh's own errors misled) ------------------


def _floor(tmp_path: Path, suffix: str) -> Path:
    """The 20 x 20 m floor of FLOOR_OBJ (two triangles) written by trimesh as ``floor<suffix>``."""
    import trimesh

    path = tmp_path / f"floor{suffix}"
    trimesh.Trimesh([[-10, 0, -10], [10, 0, -10], [10, 0, 10], [-10, 0, 10]], [[0, 3, 2], [0, 2, 1]]).export(path)
    return path


def _damaged(path: Path, name: str, data: bytes) -> Path:
    damaged = path.with_name(name)
    damaged.write_bytes(data)
    return damaged


@pytest.mark.parametrize("suffix", [".stl", ".glb"])
def test_the_intact_files_the_damage_tests_cut_are_read(suffix, tmp_path, quick_config, capsys):
    outcome = run_g2s(capsys, "run", quick_config, _floor(tmp_path, suffix), "-o", tmp_path / "out", "-q")
    assert outcome.code == 0, outcome.stderr


def test_a_binary_stl_cut_short_says_how_many_triangles_it_holds(tmp_path, quick_config, capsys):
    # was "the mesh is empty (no triangles)": trimesh reads a binary STL of the wrong size as ASCII STL
    data = _floor(tmp_path, ".stl").read_bytes()
    assert len(data) == 84 + 2 * 50
    cut = _damaged(tmp_path, "trunc.stl", data[:84 + 50 + 20])
    outcome = run_g2s(capsys, "run", quick_config, cut, "-o", tmp_path / "out")
    assert_clean_error(outcome, f"{cut}: binary STL ends early: the header announces 2 triangles, the file holds 1")
    assert tree(tmp_path / "out") == []


def test_a_binary_stl_with_bytes_past_its_triangles_says_so(tmp_path, quick_config, capsys):
    longer = _damaged(tmp_path, "long.stl", _floor(tmp_path, ".stl").read_bytes() + bytes(30))
    outcome = run_g2s(capsys, "run", quick_config, longer, "-o", tmp_path / "out")
    assert_clean_error(outcome, f"{longer}: binary STL has 30 bytes more than the 2 triangles its header announces")


def test_a_binary_stl_whose_header_starts_with_solid_is_still_binary(tmp_path, quick_config, capsys):
    # some exporters write "solid" in a binary STL's free header, which is how ASCII STL begins
    data = _floor(tmp_path, ".stl").read_bytes()
    data = b"solid exported".ljust(80, b" ") + data[80:]
    whole = _damaged(tmp_path, "solid.stl", data)
    assert run_g2s(capsys, "run", quick_config, whole, "-o", tmp_path / "whole", "-q").code == 0
    cut = _damaged(tmp_path, "solid_cut.stl", data[:-10])
    outcome = run_g2s(capsys, "run", quick_config, cut, "-o", tmp_path / "out")
    assert_clean_error(outcome, f"{cut}: binary STL ends early: the header announces 2 triangles, the file holds 1")


def test_an_empty_ascii_stl_is_still_an_empty_mesh(tmp_path, quick_config, capsys):
    empty = _damaged(tmp_path, "empty.stl", b"solid nothing\nendsolid nothing\n")
    outcome = run_g2s(capsys, "run", quick_config, empty, "-o", tmp_path / "out")
    assert_clean_error(outcome, f"{empty}: the mesh is empty (no triangles)")


def test_a_glb_cut_short_says_how_long_it_should_be(tmp_path, quick_config, capsys):
    # was "cannot read mesh (JSONDecodeError: Unterminated string ...)": the JSON chunk was cut
    data = _floor(tmp_path, ".glb").read_bytes()
    cut = _damaged(tmp_path, "trunc.glb", data[:len(data) // 2])
    outcome = run_g2s(capsys, "run", quick_config, cut, "-o", tmp_path / "out")
    assert_clean_error(outcome, f"{cut}: the GLB file ends early (its header announces {len(data)} bytes, "
                                f"the file has {len(data) // 2})")
    assert tree(tmp_path / "out") == []


@pytest.mark.parametrize("data, says", [
    (b'{"asset": {"version": "2.0"}, "meshes": [', "not valid glTF JSON (line 1, column 42: Expecting value)"),
    (b'{"asset": {"version": "2.0"},\n "meshes": [}', "not valid glTF JSON (line 2, column 13: Expecting value)"),
    (b'{"asset": {"version": "2.0", "generator": "caf\xe9"}}', "not valid glTF JSON (not UTF-8 text)"),
])
def test_gltf_whose_json_is_broken_says_where(data, says, tmp_path, quick_config, capsys):
    # was "cannot read mesh (FileNotFoundError: model.gltf)": trimesh then looks for a zip archive
    bad = _damaged(tmp_path, "bad.gltf", data)
    outcome = run_g2s(capsys, "run", quick_config, bad, "-o", tmp_path / "out")
    assert_clean_error(outcome, f"{bad}: {says}")
    assert tree(tmp_path / "out") == []


# --- meshes whose arrays are damaged, and what a mesh file names (found by fuzzing, /tmp/fuzz, 3 December 2026) ---

PLY_HEAD = ("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
            "element face 2\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n0 0 10\n10 0 10\n10 0 0\n3 0 1 2\n")


@pytest.mark.parametrize("face, vertex", [("3 0 2 9", 9), ("3 0 2 -1", -1), ("3 0 -5 2", -5)])
def test_a_face_naming_a_vertex_the_file_lacks_is_refused(face, vertex, tmp_path, quick_config, capsys):
    # were "internal error: IndexError" (9, -5), or a failure blamed on the navmesh plugin (-1, read by numpy as
    # the last vertex, by Recast as out of range)
    mesh = tmp_path / "bad.ply"
    mesh.write_text(PLY_HEAD + face + "\n")
    outcome = run_g2s(capsys, "run", quick_config, mesh, "-o", tmp_path / "out")
    assert_clean_error(outcome, f"{mesh}: a face names vertex {vertex}, but the mesh has 4 (numbered from 0)")
    assert tree(tmp_path / "out") == []


def test_vertices_of_two_coordinates_are_refused(tmp_path, quick_config, capsys):
    # "v x y" lines: the graph builders failed on the (N, 2) array, blamed as their own failure
    mesh = tmp_path / "flat.obj"
    mesh.write_text("v 0 0\nv 0 10\nv 10 10\nf 1 2 3\n")
    outcome = run_g2s(capsys, "run", quick_config, mesh, "-o", tmp_path / "out")
    assert_clean_error(outcome, f"{mesh}: expected vertices of 3 coordinates x, y, z, got 2")


def _gltf_with_buffer(folder: Path) -> Path:
    """floor.gltf as trimesh writes it, its buffers in files beside it."""
    import trimesh

    floor = trimesh.Trimesh([[-10, 0, -10], [10, 0, -10], [10, 0, 10], [-10, 0, 10]], [[0, 3, 2], [0, 2, 1]])
    for name, data in trimesh.exchange.gltf.export_gltf(floor).items():
        (folder / name).write_bytes(data)
    return folder / "model.gltf"


def test_a_gltf_buffer_that_is_a_fifo_is_refused_not_waited_on(tmp_path):
    # trimesh opened the FIFO and waited forever for a writer
    gltf = _gltf_with_buffer(tmp_path)
    buffer = tmp_path / json.loads(gltf.read_text())["buffers"][0]["uri"]
    buffer.unlink()
    os.mkfifo(buffer)
    outcome = run_g2s_process("run", "graph_only", gltf, "-o", tmp_path / "out", timeout=60)
    assert_clean_error(outcome, f"{gltf}: cannot read mesh (MeshError: {buffer}: expected a file, got a FIFO)")


def test_a_gltf_nested_too_deeply_is_a_clean_error(tmp_path, quick_config, capsys):
    # the damage report's own json.loads raised RecursionError: an internal error
    gltf = _damaged(tmp_path, "deep.gltf", b"[" * 100_000 + b"]" * 100_000)
    outcome = run_g2s(capsys, "run", quick_config, gltf, "-o", tmp_path / "out")
    assert_clean_error(outcome, f"{gltf}: not valid glTF JSON (nested too deeply)")


def test_numpy_warnings_of_a_broken_glb_stay_off_the_error_line(tmp_path):
    # a node matrix of NaN: numpy's "RuntimeWarning: invalid value encountered in det" printed two more lines
    data = _floor(tmp_path, ".glb").read_bytes()
    length = int.from_bytes(data[12:16], "little")
    document = json.loads(data[20:20 + length])
    document["nodes"][0]["matrix"] = [float("nan")] * 16
    chunk = json.dumps(document).encode()
    chunk += b" " * (-len(chunk) % 4)
    body = len(chunk).to_bytes(4, "little") + b"JSON" + chunk + data[20 + length:]
    glb = _damaged(tmp_path, "nan.glb", b"glTF" + (2).to_bytes(4, "little") + (12 + len(body)).to_bytes(4, "little") + body)
    outcome = run_g2s_process("run", "graph_only", glb, "-o", tmp_path / "out")
    assert_clean_error(outcome, f"{glb}: ")


def test_a_level_too_large_for_the_ray_caster_is_refused_by_the_sampling_builder(tmp_path, capsys):
    # two floors 1000 km apart: the rays' precision exceeded the ledge test's reach and a negative cell size made
    # a complex number ("TypeError: '>' not supported between instances of 'complex' and 'float'")
    mesh = tmp_path / "far.obj"
    square = "v {x} 0 0\nv {x} 0 10\nv {x2} 0 10\nv {x2} 0 0\n"
    mesh.write_text(square.format(x=0, x2=10) + square.format(x=1e6, x2=1e6 + 10) + "f 1 2 3\nf 1 3 4\nf 5 6 7\nf 5 7 8\n")
    outcome = run_g2s(capsys, "run", "map_analysis_sampling", mesh, "-o", tmp_path / "out")
    assert_clean_error(outcome, "far.obj: sampling: the level is too large for the ray caster: rays on it are precise to")
