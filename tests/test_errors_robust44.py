"""Inputs robust44 (6 December 2026) found breaking docs/errors.md's rules: a mesh file whose suffix is not its
format (a binary or ASCII STL, a PLY, an OFF or a GLB named ``.obj``) refused as "the mesh is empty (no triangles)",
and ``g2s batch`` with a networkx setting of the environment that networkx refuses, an internal error (exit 1)."""

from __future__ import annotations

import pytest
import trimesh

from g2s_core.errors import MeshError
from g2s_core.mesh import load_mesh
from tests.reliability.checks import CORRIDOR, assert_clean_error, run_g2s, run_g2s_process, tree

FLOOR = trimesh.Trimesh(vertices=[[0, 0, 0], [0, 0, 10], [10, 0, 10], [10, 0, 0]], faces=[[0, 1, 2], [0, 2, 3]])
"""A 10 m square floor, Y up, wound to face up."""

CONTENTS = {
    "binary STL": (FLOOR.export(file_type="stl"), ".stl", "a binary STL, by its size: an 80-byte header, then the 2 triangles it announces"),
    "ASCII STL": (FLOOR.export(file_type="stl_ascii").encode(), ".stl", "ASCII STL, by its first bytes b'solid'"),
    "binary PLY": (FLOOR.export(file_type="ply"), ".ply", "PLY, by its first bytes b'ply\\nf'"),
    "ASCII PLY": (FLOOR.export(file_type="ply", encoding="ascii"), ".ply", "PLY, by its first bytes b'ply\\nf'"),
    "OFF": (FLOOR.export(file_type="off").encode(), ".off", "OFF, by its first bytes b'OFF\\n4'"),
    "GLB": (FLOOR.export(file_type="glb"), ".glb", "GLB (binary glTF), by its first bytes b'glTF\\x02'"),
}
"""Each format's file of the floor: its bytes, its own suffix and how the message names it."""

NAMES = {".obj": "OBJ", ".glb": "GLB (binary glTF)", ".gltf": "glTF JSON", ".ply": "PLY", ".stl": "STL", ".off": "OFF"}


@pytest.mark.parametrize("kind", CONTENTS)
def test_each_format_named_obj_is_named_by_its_content(kind, tmp_path, capsys):
    # was "the mesh is empty (no triangles)": read as OBJ text, the file holds no `v` or `f` line
    data, suffix, named = CONTENTS[kind]
    (level := tmp_path / "level.obj").write_bytes(data)
    outcome = run_g2s(capsys, "run", "graph_only", level, "-o", tmp_path / "out")
    assert assert_clean_error(outcome) == f"g2s: error: {level}: the file's content is not OBJ but {named}; rename it level{suffix}"
    assert tree(tmp_path / "out") == []


@pytest.mark.parametrize("kind", CONTENTS)
@pytest.mark.parametrize("given", [".obj", ".glb", ".gltf", ".ply", ".stl", ".off"])
def test_a_file_whose_suffix_is_another_format_is_named_by_its_content(kind, given, tmp_path):
    # were the suffix's own reader's words: OBJ's "the mesh is empty", PLY's "the PLY header has no end_header line",
    # STL's "binary STL ends early: the header announces 1313818956 triangles", glTF's "not valid glTF JSON (not UTF-8 text)"
    data, suffix, named = CONTENTS[kind]
    (level := tmp_path / f"level{given}").write_bytes(data)
    if given == suffix:  # its own suffix: read
        assert len(load_mesh(level)[0].faces) == 2
        return
    with pytest.raises(MeshError) as refused:
        load_mesh(level)
    assert str(refused.value) == f"{level}: the file's content is not {NAMES[given]} but {named}; rename it level{suffix}"


def test_a_file_of_its_own_format_cut_short_is_still_named_by_its_damage(tmp_path):
    # the content check names another format only: a binary STL cut short is no STL of another size
    (level := tmp_path / "level.stl").write_bytes(CONTENTS["binary STL"][0][:-10])
    with pytest.raises(MeshError, match="binary STL ends early: the header announces 2 triangles, the file holds 1"):
        load_mesh(level)


@pytest.mark.parametrize("name, value, says", [
    ("NETWORKX_BACKEND_PRIORITY", "nosuch", "Unknown backend when setting 'algos': 'nosuch'"),
    ("NETWORKX_WARNINGS_TO_IGNORE", "nosuch", "Unknown warning when setting 'warnings_to_ignore': 'nosuch'"),
])
def test_a_batch_with_networkx_settings_that_it_refuses_names_them(name, value, says, monkeypatch, tmp_path):
    # was exit 1, "internal error: ValueError: ...": the batch runner imported networkx through g2s_core.pipeline,
    # unguarded, before the API's import that names them (a child process, where networkx is not loaded yet)
    monkeypatch.setenv(name, value)
    outcome = run_g2s_process("batch", "graph_only", CORRIDOR, "-o", tmp_path / "out", "--executor", "serial")
    assert_clean_error(outcome, f"{name}={value!r}: networkx refused the environment's setting as it loaded ({says}")
    assert tree(tmp_path / "out") == []


@pytest.mark.parametrize("kind, cut, says", [
    ("binary STL", 1, "binary STL ends early: the file has 1 byte, its header alone takes 84"),
    ("binary STL", 12, "binary STL ends early: the file has 12 bytes, its header alone takes 84"),
    ("binary STL", 83, "binary STL ends early: the file has 83 bytes, its header alone takes 84"),
    ("GLB", 1, "the GLB file ends early (its header is 12 bytes, the file has 1)"),
    ("GLB", 3, "the GLB file ends early (its header is 12 bytes, the file has 3)"),
])
def test_a_binary_file_cut_inside_its_header_says_so(kind, cut, says, tmp_path):
    # found by this pass's fuzzing (cuts at random offsets of each format): a binary STL cut inside its 84-byte header
    # was read as ASCII STL, "line 1: a line starts with '\x00\x00' (expected one of solid, ...)"; a GLB cut inside its
    # first 4 bytes "not a GLB file: it starts with b'gl', not b'glTF'"
    data, suffix, _ = CONTENTS[kind]
    (level := tmp_path / f"level{suffix}").write_bytes(data[:cut])
    with pytest.raises(MeshError) as refused:
        load_mesh(level)
    assert str(refused.value) == f"{level}: {says}"


def test_an_ascii_stl_cut_inside_its_first_word_is_read_as_ascii(tmp_path):
    (level := tmp_path / "level.stl").write_bytes(b"so")
    with pytest.raises(MeshError, match="line 1: a line starts with 'so'"):
        load_mesh(level)


def test_a_tiny_ascii_stl_after_blank_space_is_not_called_a_cut_binary_stl(tmp_path):
    # review: the cut-header rule read the first five bytes as they were, so " solid x" (a leading space) was told
    # "binary STL ends early"; the ASCII STL reader, which skips that space, says what is wrong with it
    (level := tmp_path / "level.stl").write_bytes(b" solid x\nendsolid x\n")
    with pytest.raises(MeshError) as refused:
        load_mesh(level)
    assert "binary STL" not in str(refused.value)


def test_a_dangling_link_as_the_output_folder_says_where_it_points(tmp_path):
    # was "dangling: exists and is not a folder": the link exists, the folder it names does not
    (link := tmp_path / "dangling").symlink_to(tmp_path / "gone")
    outcome = run_g2s_process("run", "graph_only", CORRIDOR, "-o", link)
    assert_clean_error(outcome, f"{link}: a link to {tmp_path / 'gone'}, which does not exist")
    assert link.is_symlink() and not (tmp_path / "gone").exists()
