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


# --- meshes whose arrays are damaged, and what a mesh file names (found by fuzzing with a scratch script, 3 December 2026) ---

PLY_HEAD = ("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
            "element face 2\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n0 0 10\n10 0 10\n10 0 0\n3 0 1 2\n")


@pytest.mark.parametrize("face, says", [
    ("3 0 2 9", "line 15: a face refers to vertex 9; the file has 4 vertices (numbered from 0)"),
    ("3 0 2 -1", "line 15: face corner '-1' is not a vertex index"),
    ("3 0 -5 2", "line 15: face corner '-5' is not a vertex index")])
def test_a_face_naming_a_vertex_the_file_lacks_is_refused(face, says, tmp_path, quick_config, capsys):
    # were "internal error: IndexError" (9, -5), or a failure blamed on the navmesh plugin (-1, read by numpy as
    # the last vertex, by Recast as out of range); then "a face names vertex 9, but the mesh has 4", without the line
    mesh = tmp_path / "bad.ply"
    mesh.write_text(PLY_HEAD + face + "\n")
    outcome = run_g2s(capsys, "run", quick_config, mesh, "-o", tmp_path / "out")
    assert_clean_error(outcome, f"{mesh}: {says}")
    assert tree(tmp_path / "out") == []


def test_a_face_naming_a_vertex_the_binary_file_lacks_is_refused(tmp_path):
    # no line to name in a binary file: the index, as the mesh's arrays have it
    mesh = tmp_path / "bad.ply"
    _floor(tmp_path, ".ply").rename(mesh)
    data = mesh.read_bytes()
    mesh.write_bytes(data[:-4] + (9).to_bytes(4, "little"))
    with pytest.raises(MeshError, match=r"bad.ply: a face names vertex 9, but the mesh has 4 \(numbered from 0\)$"):
        load_mesh(mesh)


def test_vertices_of_two_coordinates_are_refused(tmp_path, quick_config, capsys):
    # "v x y" lines: the graph builders failed on the (N, 2) array, blamed as their own failure; then
    # "expected vertices of 3 coordinates x, y, z, got 2", without the line
    mesh = tmp_path / "flat.obj"
    mesh.write_text("v 0 0\nv 0 10\nv 10 10\nf 1 2 3\n")
    outcome = run_g2s(capsys, "run", quick_config, mesh, "-o", tmp_path / "out")
    assert_clean_error(outcome, f"{mesh}: line 1: a vertex of 2 coordinates (expected x y z)")


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
    assert_clean_error(outcome, f"{gltf}: {buffer}: expected a file, got a FIFO")


def _glb(document: dict, binary: bytes) -> bytes:
    """A GLB file of ``document`` (the JSON chunk) and the binary chunk ``binary``."""
    chunk = json.dumps(document).encode()
    chunk += b" " * (-len(chunk) % 4)
    body = len(chunk).to_bytes(4, "little") + b"JSON" + chunk + len(binary).to_bytes(4, "little") + b"BIN\0" + binary
    return b"glTF" + (2).to_bytes(4, "little") + (12 + len(body)).to_bytes(4, "little") + body


def _glb_parts(tmp_path: Path) -> tuple[bytes, dict, bytes]:
    """floor.glb's bytes, its JSON document and its binary chunk's data."""
    data = _floor(tmp_path, ".glb").read_bytes()
    length = int.from_bytes(data[12:16], "little")
    return data, json.loads(data[20:20 + length]), data[20 + length + 8:]


def _ascii_stl() -> str:
    """The floor of FLOOR_OBJ (two triangles) as trimesh writes it in ASCII STL: solid, then per facet a normal,
    outer loop, 3 vertex lines, endloop, endfacet; endsolid."""
    import trimesh

    floor = trimesh.Trimesh([[-10, 0, -10], [10, 0, -10], [10, 0, 10], [-10, 0, 10]], [[0, 3, 2], [0, 2, 1]])
    return floor.export(file_type="stl_ascii")


def _line_changed(text: str, number: int, new: str | None) -> str:
    """``text`` with its line ``number`` (from 1) replaced by ``new``, written twice (``new`` ``"twice"``) or deleted."""
    lines = text.splitlines()
    lines[number - 1:number] = [] if new is None else [lines[number - 1]] * 2 if new == "twice" else [new]
    return "\n".join(lines) + "\n"


@pytest.mark.parametrize("number, new, says", [
    # were "cannot read mesh (ValueError: cannot reshape array of size 17 into shape (3))" (robust5, 4 December 2026)
    (5, None, "line 6: a facet of 2 vertices (expected 3)"),
    (5, "twice", "line 8: a facet of 4 vertices (expected 3)"),
    (5, "vertex 10 0", "line 5: a vertex of 2 coordinates (expected x y z)"),
    (5, "vertex 10 0 10 1", "line 5: a vertex of 4 coordinates (expected x y z)"),
    # was "cannot read mesh (ValueError: string or file could not be read to its end due to unmatched data)"
    (5, "vertex 10 0 1,5", "line 5: vertex coordinate '1,5' is not a number"),
    (5, "VeXtex 10 0 10", "line 5: a line starts with 'VeXtex' (expected one of solid, facet, outer, vertex, endloop, endfacet, endsolid)"),
    # was "cannot read mesh (ValueError: `endsolid` precedes `solid`!)"
    (17, "twice", "line 18: endsolid without a solid before it"),
    # was "the mesh has NaN or infinite vertex coordinates", without the line
    (5, "vertex 10 nan 10", "line 5: vertex coordinate 'nan' is not a finite number"),
])
def test_a_damaged_ascii_stl_is_named_by_its_line(number, new, says, tmp_path, quick_config, capsys):
    text = _ascii_stl()
    assert text.splitlines()[4].startswith("vertex") and text.splitlines()[16].startswith("endsolid")
    stl = _damaged(tmp_path, "bad.stl", _line_changed(text, number, new).encode())
    outcome = run_g2s(capsys, "run", quick_config, stl, "-o", tmp_path / "out")
    assert_clean_error(outcome, f"{stl}: {says}")
    assert tree(tmp_path / "out") == []


def test_the_ascii_stl_the_damage_tests_change_is_read_and_a_binary_stls_nan_is_not_taken_for_text(tmp_path):
    (tmp_path / "floor.stl").write_text(_ascii_stl())
    assert load_mesh(tmp_path / "floor.stl")[1].faces == 2
    data = bytearray(_floor(tmp_path, ".stl").read_bytes())
    data[84 + 12:84 + 16] = bytes.fromhex("0000c07f")  # the first vertex's x, a float32 NaN
    (tmp_path / "nan.stl").write_bytes(data)
    with pytest.raises(MeshError, match=r"nan\.stl: the mesh has NaN or infinite vertex coordinates$"):
        load_mesh(tmp_path / "nan.stl")


@pytest.mark.parametrize("change, says", [
    # were "cannot read mesh (KeyError: 'POSITION')", "(TypeError: 'NoneType' object is not subscriptable)" (robust5)
    ({"meshes": [{"primitives": [{"attributes": {"NORMAL": 0}, "indices": 0}]}]},
     "meshes[0].primitives[0] has no attributes.POSITION, the accessor of its vertices, which g2s needs"),
    ({"meshes": [{"primitives": [{"attributes": None}]}]},
     "meshes[0].primitives[0] has no attributes.POSITION, the accessor of its vertices, which g2s needs"),
    ({"meshes": [{"primitives": [{"attributes": {"POSITION": 9}}]}]},
     "meshes[0].primitives[0].attributes.POSITION is 9; expected the index of one of the file's 2 accessors"),
    # was "cannot read mesh (KeyError: 'primitives')"
    ({"meshes": [{"name": "floor"}]}, "meshes[0].primitives is missing; expected a list of objects"),
    # were "cannot read mesh (TypeError: list indices must be integers or slices, not str)"
    ({"scene": "0"}, "scene is '0'; expected the index of one of the file's 1 scene"),
    ({"scenes": [{"nodes": "0"}]}, "scenes[0].nodes is '0'; expected a list of indices of the file's 1 node"),
    ({"scenes": [{"nodes": [4]}]}, "scenes[0].nodes is [4]; expected a list of indices of the file's 1 node"),
    # were "(AttributeError: 'str' object has no attribute 'get')", "(TypeError: object of type 'int' has no len())"
    ({"nodes": "x"}, "nodes is 'x'; expected a list of objects"),
    ({"accessors": 3}, "accessors is 3; expected a list of objects"),
    ({"bufferViews": [None]}, "bufferViews[0] is missing; expected an object"),
    ({"meshes": [[]]}, "meshes[0] is []; expected an object"),
])
def test_a_glb_whose_scene_meshes_or_lists_are_of_another_kind_names_the_key(change, says, tmp_path, quick_config, capsys):
    _, document, binary = _glb_parts(tmp_path)
    assert len(document["scenes"]) == len(document["nodes"]) == 1 and len(document["accessors"]) == 2
    glb = _damaged(tmp_path, "bad.glb", _glb({**document, **change}, binary))
    outcome = run_g2s(capsys, "run", quick_config, glb, "-o", tmp_path / "out")
    assert_clean_error(outcome, f"{glb}: {says}")
    assert tree(tmp_path / "out") == []


def test_a_gltf_buffer_that_is_a_device_is_named_in_g2s_words(tmp_path, quick_config, capsys):
    # was "cannot read mesh (MeshError: /dev/zero: expected a file, got a character device)"
    gltf = _gltf_with_buffer(tmp_path)
    document = json.loads(gltf.read_text())
    document["buffers"][0]["uri"] = "/dev/zero"
    gltf.write_text(json.dumps(document))
    outcome = run_g2s(capsys, "run", quick_config, gltf, "-o", tmp_path / "out")
    assert_clean_error(outcome, f"{gltf}: /dev/zero: expected a file, got a character device")


@pytest.mark.parametrize("damage, says", [
    # were "cannot read mesh (JSONDecodeError: Expecting value: line 1 column 2 (char 1))" ...
    (lambda data, document, binary: data[:21] + b"@" + data[22:], "the GLB's JSON chunk is not valid JSON (line 1, column 2: Expecting property name enclosed in double quotes)"),
    (lambda data, document, binary: data[:16] + b"JSOX" + data[20:], "the GLB's first chunk is of type 'JSOX', expected 'JSON'"),
    (lambda data, document, binary: data[:12] + (len(data)).to_bytes(4, "little") + data[16:],
     "the GLB's JSON chunk announces {size} bytes, the file has {rest} after the chunk's header"),
    # was "cannot read mesh (IndexError: list index out of range)"
    (lambda data, document, binary: _glb({**document, "accessors": [{**document["accessors"][0], "bufferView": 7}]}, binary),
     "accessors[0].bufferView is 7; the file lists 2 bufferViews"),
    (lambda data, document, binary: _glb({**document, "bufferViews": [{**view, "buffer": 3} for view in document["bufferViews"]]}, binary),
     "bufferViews[0].buffer is 3; the file lists 1 buffer"),
])
def test_a_glb_whose_json_chunk_is_damaged_says_what_is_wrong(damage, says, tmp_path, quick_config, capsys):
    data, document, binary = _glb_parts(tmp_path)
    glb = _damaged(tmp_path, "bad.glb", damage(data, document, binary))
    outcome = run_g2s(capsys, "run", quick_config, glb, "-o", tmp_path / "out")
    assert_clean_error(outcome, f"{glb}: {says.format(size=len(data), rest=len(data) - 20)}")
    assert tree(tmp_path / "out") == []


def _with_accessor(document: dict, **changes: object) -> dict:
    """``document`` with its first accessor (the floor's face indices) changed: a key None is taken out."""
    accessor = {key: value for key, value in {**document["accessors"][0], **changes}.items() if value is not None}
    return {**document, "accessors": [accessor, *document["accessors"][1:]]}


@pytest.mark.parametrize("changes, says", [
    # were "cannot read mesh (TypeError: unsupported operand type(s) for +: 'int' and 'str')", "(TypeError: slice
    # indices must be integers ...)", "(OverflowError: Python int too large to convert to C long)", "(KeyError:
    # '5126')", "(KeyError: 'VEC7')", "(TypeError: can only concatenate str (not "numpy.int64") to str)"
    ({"count": "6"}, "accessors[0].count is '6'; expected an integer >= 1"),
    ({"count": 6.5}, "accessors[0].count is 6.5; expected an integer >= 1"),
    ({"count": 2**63}, "accessors[0] ends at byte 36893488147419103232 of bufferViews[0], past its 24 bytes"),
    ({"componentType": 1234}, "accessors[0].componentType is 1234; expected one of 5120, 5121, 5122, 5123, 5125, 5126"),
    ({"type": "VEC7"}, "accessors[0].type is 'VEC7'; expected one of SCALAR, VEC2, VEC3, VEC4, MAT2, MAT3, MAT4"),
    ({"byteOffset": "0"}, "accessors[0].byteOffset is '0'; expected an integer >= 0"),
    # was read silently: trimesh reads the data under a sparse accessor's values (zeros without a bufferView)
    ({"sparse": {"count": 1, "indices": {"bufferView": 0, "componentType": 5125}, "values": {"bufferView": 0}}},
     "accessors[0] is sparse, which g2s cannot read (its values would be read as zeros or the data under them)"),
    ({"bufferView": None, "sparse": {"count": 1, "indices": {"bufferView": 0, "componentType": 5125}, "values": {"bufferView": 0}}},
     "accessors[0] is sparse, which g2s cannot read (its values would be read as zeros or the data under them)"),
])
def test_a_glb_accessor_of_the_wrong_kind_names_its_key(changes, says, tmp_path, quick_config, capsys):
    _, document, binary = _glb_parts(tmp_path)
    glb = _damaged(tmp_path, "bad.glb", _glb(_with_accessor(document, **changes), binary))
    outcome = run_g2s(capsys, "run", quick_config, glb, "-o", tmp_path / "out")
    assert_clean_error(outcome, f"{glb}: {says}")
    assert tree(tmp_path / "out") == []


@pytest.mark.parametrize("buffer, says", [
    # was "cannot read mesh (FileNotFoundError: missing.bin)"
    ({"uri": "missing.bin"}, "buffers[0]: cannot read its file 'missing.bin' beside the glTF file (No such file or directory)"),
    # were "cannot read mesh (AssertionError: )"
    ({"uri": "short.bin"}, "buffers[0]: byteLength is {length} bytes, its data holds 3"),
    ({"uri": "data:application/octet-stream;base64,@@@"}, "buffers[0]: its data URI is not valid base64"),
])
def test_a_gltf_whose_buffer_cannot_be_read_names_it(buffer, says, tmp_path, quick_config, capsys):
    gltf = _gltf_with_buffer(tmp_path)
    (tmp_path / "short.bin").write_bytes(b"abc")
    document = json.loads(gltf.read_text())
    length = document["buffers"][0]["byteLength"]
    document["buffers"][0].update(buffer)
    gltf.write_text(json.dumps(document))
    outcome = run_g2s(capsys, "run", quick_config, gltf, "-o", tmp_path / "out")
    assert_clean_error(outcome, f"{gltf}: {says.format(length=length)}")
    assert tree(tmp_path / "out") == []


def test_a_gltf_whose_buffer_uri_is_url_encoded_is_read(tmp_path):
    # exporters write a file "floor part.bin" as the uri "floor%20part.bin"; trimesh looked for "floor%20part.bin"
    # ("buffers[0]: cannot read its file 'floor%20part.bin' ...")
    gltf = _gltf_with_buffer(tmp_path)
    document = json.loads(gltf.read_text())
    for number, buffer in enumerate(document["buffers"]):
        (tmp_path / buffer["uri"]).rename(tmp_path / f"floor part {number}.bin")
        buffer["uri"] = f"floor%20part%20{number}.bin"
    gltf.write_text(json.dumps(document))
    mesh, _ = load_mesh(gltf)
    assert len(mesh.faces) == 2 and mesh.area == pytest.approx(400)
    (tmp_path / "floor part 0.bin").unlink()
    with pytest.raises(MeshError) as missing:
        load_mesh(gltf)
    assert str(missing.value) == f"{gltf}: buffers[0]: cannot read its file 'floor part 0.bin' beside the glTF file (No such file or directory)"


def test_a_gltf_whose_buffer_lies_in_another_folder_is_read(tmp_path):
    # a glTF may name its buffer by a relative path out of its folder ("../buffers/floor.bin"); trimesh 5 refused it:
    # "cannot read mesh (ValueError: '../buffers/floor.bin' escapes resolver root ... pass `FilePathResolver(path,
    # allow_anywhere=True)` to allow it)"
    (tmp_path / "level").mkdir()
    (tmp_path / "buffers").mkdir()
    gltf = _gltf_with_buffer(tmp_path / "level")
    document = json.loads(gltf.read_text())
    for buffer in document["buffers"]:
        (tmp_path / "level" / buffer["uri"]).rename(tmp_path / "buffers" / buffer["uri"])
        buffer["uri"] = f"../buffers/{buffer['uri']}"
    gltf.write_text(json.dumps(document))
    mesh, _ = load_mesh(gltf)
    assert len(mesh.faces) == 2 and mesh.area == pytest.approx(400)


@pytest.mark.parametrize("config, vertices", [
    ("map_piece", "v 0 0 0\nv 5 0 5\nv 10 0 10\n"),  # on a line across the plan: the navmesh's grid is not empty
    ("map_piece_sampling", "v 0 0 0\nv 5 0 5\nv 10 0 10\n"),
    ("map_piece_sampling", "v 3 1 2\nv 3 1 2\nv 3 1 2\n"),
])
def test_a_mesh_of_zero_area_is_named_so_not_taken_for_z_up(config, vertices, tmp_path, capsys):
    # a mesh whose triangles all have their corners on a line or at one point (a glTF accessor without its
    # bufferView reads as zeros) was "no walkable surface ...; most flat faces face along z, not y: if the file is
    # Z-up, set mesh: {up_axis: z}": no face has area along y, so the flat-area ratio along z was taken as infinite
    mesh = _damaged(tmp_path / "x", "degenerate.obj", (vertices + "f 1 2 3\nf 3 2 1\n").encode())
    outcome = run_g2s(capsys, "run", config, mesh, "-o", tmp_path / "out")
    assert_clean_error(outcome, "every face has zero area (its corners on a line or at one point): the file holds no surface")
    assert "up_axis" not in outcome.stderr
    assert tree(tmp_path / "out") == []


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
    # Poisson samples (the paper preset's): the grid of map_analysis_sampling is refused before, for its 1e6 x 11 points
    outcome = run_g2s(capsys, "run", "map_analysis_sampling_paper", mesh, "-o", tmp_path / "out")
    assert_clean_error(outcome, "far.obj: sampling: the level is too large for the ray caster: rays on it are precise to")


# --- damaged text meshes: the line at fault, in words (were numpy's and trimesh's own texts; robust, 3 December 2026)

OBJ = "v 0 0 0\nv 0 0 10\nv 10 0 10\nv 10 0 0\nf 1 2 3\nf 1 3 4\n"
OFF = "OFF\n4 2 0\n0 0 0\n0 0 10\n10 0 10\n10 0 0\n3 0 1 2\n3 0 2 3\n"
PLY = PLY_HEAD + "3 0 2 3\n"


def _cut(text: str, marker: str) -> str:
    """``text`` up to (without) the first ``marker``."""
    return text[:text.index(marker)]


@pytest.mark.parametrize("name, data, says", [
    # was "cannot read mesh (ValueError: string or file could not be read to its end due to unmatched data)"
    ("abc.obj", OBJ.replace("v 0 0 10", "v 0 0 abc"), "line 2: vertex coordinate 'abc' is not a number"),
    ("vt.obj", OBJ + "vt 0 x\n", "line 7: texture coordinate 'x' is not a number"),
    ("corner.obj", OBJ + "f 1 x 3\n", "line 7: face corner 'x' is not a vertex index (expected v, v/vt, v//vn or v/vt/vn)"),
    # was "cannot read mesh (IndexError: index 8 is out of bounds for axis 0 with size 4)"
    ("past.obj", OBJ + "f 1 2 9\n", "line 7: a face refers to vertex 9; the file has 4 vertices"),
    ("back.obj", OBJ + "f -1 -2 -5\n", "line 7: a face refers to vertex -5, counted back from its line, but the file "
                                        "lists 4 vertices before it"),
    # were "the mesh has NaN or infinite vertex coordinates", without the line
    ("nan.obj", OBJ.replace("v 10 0 10", "v 10 nan 10"), "line 3: vertex coordinate 'nan' is not a finite number"),
    ("inf.obj", OBJ.replace("v 10 0 10", "v 1e999 0 10"), "line 3: vertex coordinate '1e999' is not a finite number"),
    # were "the mesh is empty (no triangles)": trimesh drops a face of fewer than 3 corners
    ("two.obj", OBJ.replace("f 1 2 3\nf 1 3 4\n", "f 1 2\n"), "line 5: a face of 2 corners (at least 3 make a face)"),
    ("one.obj", OBJ.replace("f 1 2 3\nf 1 3 4\n", "f 1\n"), "line 5: a face of 1 corner (at least 3 make a face)"),
    ("none.obj", OBJ.replace("f 1 2 3\nf 1 3 4\n", "f\n"), "line 5: a face of 0 corners (at least 3 make a face)"),
    ("empty.obj", "", "the file is empty (0 bytes)"),
    ("comments.obj", "# nothing\n# here\n", "the mesh is empty (no triangles)"),
    # was "cannot read mesh (ValueError: cannot reshape array of size 6 into shape (3,3))"
    ("cut.off", _cut(OFF, "10 0 10"), "the header declares 4 vertices, the file has 2"),
    # was "the mesh is empty (no triangles)"
    ("faceless.off", _cut(OFF, "3 0 1 2"), "the header declares 2 faces, the file has 0"),
    # was "cannot read mesh (ValueError: could not convert string to float: 'q')"
    ("q.off", OFF.replace("0 0 10", "0 q 10", 1), "line 4: vertex coordinate 'q' is not a number"),
    # was "cannot read mesh (ValueError: OFF file has a face index outside the range of its vertices)"
    ("past.off", OFF.replace("3 0 2 3", "3 0 2 7"), "line 8: a face refers to vertex 7; the file has 4 vertices (numbered from 0)"),
    # was "cannot read mesh (ValueError: invalid literal for int() with base 10: 'x')"
    ("counts.off", OFF.replace("4 2 0", "4 x 0"), "line 2: expected the counts of vertices and faces, got '4 x 0'"),
    # was "cannot read mesh (ValueError: not enough values to unpack (expected 3, got 1))"
    ("notoff.off", "# nothing\n", "expected OFF on the first line, got 'only comments'"),
    # was "cannot read mesh (ValueError: setting an array element with a sequence.)"
    ("short.ply", PLY.replace("10 0 10\n", "10 0\n"), "line 12: 2 values, the header declares 3 for each vertex"),
    # was "the mesh is empty (no triangles)"
    ("cut.ply", _cut(PLY, "10 0 10"), "the header declares 4 vertices, the file has 2"),
    # was "cannot read mesh (ValueError: string or file could not be read to its end due to unmatched data)"
    ("x.ply", PLY.replace("0 0 10", "0 x 10"), "line 11: value 'x' is not a number"),
    # was "cannot read mesh (IndexError: list index out of range)"
    ("header.ply", _cut(PLY, "end_header"), "the PLY header has no end_header line"),
    # was "cannot read mesh (IndexError: index 0 is out of bounds for axis 0 with size 0)"
    ("empty.glb", "", "the file is empty (0 bytes)"),
    # were read silently as vertex 1: trimesh subtracts 1 from positive indices only (robust2, 3 December 2026)
    ("zero.obj", OBJ.replace("f 1 3 4", "f 0 3 4"), "line 6: a face refers to vertex 0; OBJ numbers vertices from 1"),
    ("zero_last.obj", OBJ + "f 2 3 0", "line 7: a face refers to vertex 0; OBJ numbers vertices from 1"),
    ("zero_vt.obj", OBJ.replace("f 1 2 3", "vt 0 0\nf 1/1 0/1 3/1"), "line 6: a face refers to vertex 0; OBJ numbers vertices from 1"),
    # was "cannot read mesh (OverflowError: Python int too large to convert to C long)"
    ("vn.obj", OBJ.replace("f 1 2 3\nf 1 3 4\n", "vt 0 0\nvn 0 1 0\nf 1/1/1 2/1/99999999999999999999 3/1/1\nf 1//1 3//1 4//1\n"),
     "line 7: a face refers to normal 99999999999999999999; the file has 1 normal"),
    # were read silently with the faces before the cut
    ("cut_faces.off", _cut(OFF, "3 0 2 3"), "the header declares 2 faces, the file has 1"),
    ("cut_faces.ply", _cut(PLY, "3 0 2 3"), "the header declares 2 faces, the file has 1"),
    # was "cannot read mesh (KeyError: 'double64')"
    ("type.ply", PLY.replace("property float z", "property double64 z"), "header line 6: unknown property type 'double64' "
     "(expected one of char, uchar, short, ushort, int, uint, float, double, int8, uint8, int16, uint16, int32, uint32, "
     "int64, uint64, float16, float32, float64)"),
])
def test_a_damaged_text_mesh_is_named_by_its_line(name, data, says, tmp_path, quick_config, capsys):
    mesh = tmp_path / name
    mesh.write_text(data)
    outcome = run_g2s(capsys, "run", quick_config, mesh, "-o", tmp_path / "out")
    assert_clean_error(outcome, f"{mesh}: {says}")
    assert tree(tmp_path / "out") == []


def test_the_intact_text_meshes_the_damage_tests_change_are_read(tmp_path):
    for name, data in (("floor.obj", OBJ), ("floor.off", OFF), ("floor.ply", PLY)):
        (tmp_path / name).write_text(data)
        assert load_mesh(tmp_path / name)[1].faces == 2


@pytest.mark.parametrize("cut, says", [
    (10, "the header declares 4 vertices, the file holds 0"),
    (-20, "the header declares 2 faces, the file holds 0"),
    (-1, "the header declares 2 faces, the file holds 1"),
])
def test_a_binary_ply_cut_short_says_where_its_data_ends(cut, says, tmp_path, quick_config, capsys):
    # was "cannot read mesh (ValueError: PLY is unexpected length!)"
    data = _floor(tmp_path, ".ply").read_bytes()
    body = data.index(b"end_header\n") + len(b"end_header\n")
    damaged = _damaged(tmp_path, "cut.ply", data[:body + cut] if cut > 0 else data[:cut])
    outcome = run_g2s(capsys, "run", quick_config, damaged, "-o", tmp_path / "out")
    assert_clean_error(outcome, f"{damaged}: binary PLY ends early: {says}")
    longer = _damaged(tmp_path, "long.ply", data + bytes(3))
    outcome = run_g2s(capsys, "run", quick_config, longer, "-o", tmp_path / "out")
    assert_clean_error(outcome, f"{longer}: binary PLY has 3 bytes more than its header declares")


def test_obj_faces_with_relative_indices_name_the_vertices_before_them(tmp_path):
    # negative indices count back from the face's line (the OBJ format); trimesh counted them back from the file's
    # end, so in a file of objects each written with its faces the first object's faces took the last one's vertices
    objects = [("v -10 0 -10\nv 10 0 -10\nv 10 0 10\n", "1 3 2"), ("v -10 3 -10\nv -10 3 10\nv 10 3 10\n", "4 5 6")]
    relative = "".join(vertices + "f -3 -1 -2\n" if n == 0 else vertices + "f -3/-1 -2/-1 -1/-1\nvt 0 0\n"
                       for n, (vertices, _) in enumerate(objects))
    relative = relative.replace("v -10 3 -10", "vt 0 0\nv -10 3 -10")
    absolute = "".join(vertices + f"f {faces}\n" for vertices, faces in objects)
    (tmp_path / "relative.obj").write_text(relative)
    (tmp_path / "absolute.obj").write_text(absolute)
    read = [load_mesh(tmp_path / f"{name}.obj")[0] for name in ("relative", "absolute")]
    assert sorted(map(tuple, read[0].vertices[read[0].faces].reshape(-1, 9).tolist())) == \
        sorted(map(tuple, read[1].vertices[read[1].faces].reshape(-1, 9).tolist()))
    assert len(read[0].faces) == 2


def test_a_mesh_file_the_system_refuses_to_read_is_named(tmp_path, monkeypatch):
    # was "cannot read mesh (PermissionError: [Errno 13] Permission denied: '...')"; the tests run as root here,
    # which chmod cannot keep out, so the refusal is the operating system's error raised where the file is read
    mesh = tmp_path / "locked.obj"
    mesh.write_text(OBJ)

    def refused(self: Path) -> bytes:
        raise PermissionError(13, "Permission denied", str(self))

    monkeypatch.setattr(Path, "read_bytes", refused)
    with pytest.raises(MeshError, match=r"locked.obj: cannot read mesh file \(Permission denied\)$"):
        load_mesh(mesh)


def test_obj_lines_indented_are_read(tmp_path):
    # trimesh reads a line only from its first column: an indented "v" line was lost, the faces after it shifted
    # ("cannot read mesh (IndexError: index 3 is out of bounds ...)", or silently other triangles)
    (tmp_path / "plain.obj").write_text(OBJ)
    (tmp_path / "indented.obj").write_text("o floor\n" + "".join("  " + line + "\n" for line in OBJ.splitlines()))
    plain, indented = (load_mesh(tmp_path / name)[0] for name in ("plain.obj", "indented.obj"))
    assert indented.vertices.tolist() == plain.vertices.tolist() and indented.faces.tolist() == plain.faces.tolist()


def test_a_mesh_that_cleaning_empties_is_named(tmp_path, quick_config, capsys):
    # was "cleaning removed every triangle of the mesh", without the file (robust2 sweep, 3 December 2026)
    mesh = tmp_path / "collinear.obj"
    mesh.write_text("v 0 0 0\nv 1 0.5 2\nv 2 1 4\nf 1 2 3\n")
    outcome = run_g2s(capsys, "run", quick_config, mesh, "-o", tmp_path / "out", "--set", "mesh.clean=true")
    assert_clean_error(outcome, f"{mesh}: mesh.clean removed every triangle (each had zero area, or corners merged into one)")


def test_what_cleaning_removed_follows_a_run_and_never_precedes_its_error(tmp_path, quick_config, capsys):
    # "cleaning: ..." was printed on stderr before the run, so that a failing run's error was its second line
    small = tmp_path / "small.obj"
    small.write_text("v 0 0 0\nv 0 0 0.5\nv 0.5 0 0\nv 0.5 0 0\nf 1 2 3\nf 1 2 4\n")
    outcome = run_g2s(capsys, "run", quick_config, small, "-o", tmp_path / "out", "--set", "mesh.clean=true")
    assert_clean_error(outcome, "small.obj: no walkable surface for the agent")
    floor = tmp_path / "floor.obj"
    floor.write_text(FLOOR_OBJ.format(comment="floor", name="floor") + "f 1 4 3\n")
    outcome = run_g2s(capsys, "run", quick_config, floor, "-o", tmp_path / "out", "--set", "mesh.clean=true")
    assert outcome.code == 0 and "cleaning: 0 merged vertices, 1 duplicate faces" in outcome.stderr, outcome.stderr


def test_an_off_file_of_triangles_quads_and_a_pentagon_is_read_whole(tmp_path):
    # trimesh fanned the pentagon from its text values: "cannot read mesh (TypeError: The 'out' kwarg is necessary
    # when using the string multiply ufunc directly ...)"
    mesh_file = tmp_path / "mixed.off"
    mesh_file.write_text("OFF\n# a square of two triangles, a square quad, a pentagon\n9 4 0\n"
                         "0 0 0\n0 0 4\n4 0 4\n4 0 0\n8 0 4\n8 0 0\n12 0 4\n12 0 0\n14 0 2\n"
                         "3 0 1 2\n3 0 2 3\n4 3 2 4 5\n5 5 4 6 8 7\n")
    mesh, info = load_mesh(mesh_file)
    assert (info.faces, mesh.area) == (7, pytest.approx(16 + 16 + 20))  # 2 + 2 + 3 triangles
    assert (mesh.face_normals[:, 1] > 0.99).all()  # fanned with the polygons' winding: every face up
    mesh_file.write_text(mesh_file.read_text().replace("5 5 4 6 8 7", "5 5 4 6 9 7"))
    with pytest.raises(MeshError) as wrong:
        load_mesh(mesh_file)
    assert str(wrong.value) == f"{mesh_file}: line 16: a face refers to vertex 9; the file has 9 vertices (numbered from 0)"


@pytest.mark.parametrize("text", ["garbage\n", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n"])
def test_a_ply_pymeshlab_cannot_read_leaves_the_working_folder_where_it_was(text, tmp_path, monkeypatch):
    # pymeshlab moved the process into the file's folder and stayed there when it failed: a caller's relative paths
    # then named other files, and once that folder was deleted every relative path failed (found by the mesh fuzzer)
    from g2s_core.mesh import _read_polygons

    work = tmp_path / "work"
    work.mkdir()
    monkeypatch.chdir(work)
    (tmp_path / "level.ply").write_text(text)
    with pytest.raises(MeshError, match="trimesh failed"):
        _read_polygons(tmp_path / "level.ply", text.encode(), "trimesh failed")
    assert Path.cwd() == work
