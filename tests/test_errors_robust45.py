"""Inputs robust45 (6 December 2026) found breaking docs/errors.md's rules: OBJ text under another format's suffix
named in that format's words (``binary STL ends early: the header announces 808464432 triangles``), and ``-o /proc/x``
refused in the kernel's words ("No such file or directory", of a folder whose parent exists)."""

from __future__ import annotations

from pathlib import Path

import pytest

from g2s_core.errors import MeshError
from g2s_core.mesh import load_mesh
from tests.reliability.checks import assert_clean_error, run_g2s, tree

FLOOR_OBJ = b"v 0 0 0\nv 0 0 10\nv 10 0 10\nv 10 0 0\nf 1 2 3 4\n"
"""A 10 m square floor as one quad, Y up, facing up."""

EXPORTED_OBJ = b"# Blender 4.2\nmtllib room.mtl\no Floor\n" + FLOOR_OBJ.replace(b"f ", b"usemtl Stone\ns 0\nf ")
"""The same floor as an exporter writes it: a comment, a material library, an object, a material, smoothing off."""

NAMES = {".glb": "GLB (binary glTF)", ".gltf": "glTF JSON", ".ply": "PLY", ".stl": "STL", ".off": "OFF"}


@pytest.mark.parametrize("suffix", NAMES)
@pytest.mark.parametrize("data, statements", [(FLOOR_OBJ, "f, v"), (EXPORTED_OBJ, "f, mtllib, o, s, usemtl, v")])
def test_obj_text_under_another_suffix_is_named_obj(suffix, data, statements, tmp_path):
    # was the suffix's reader's words: ".stl" "binary STL ends early: the header announces 808464432 triangles",
    # ".ply" "the PLY header has no end_header line", ".off" "expected OFF on the first line, got 'v 0 0 0'"
    (level := tmp_path / f"room{suffix}").write_bytes(data)
    with pytest.raises(MeshError) as refused:
        load_mesh(level)
    assert str(refused.value) == (f"{level}: the file's content is not {NAMES[suffix]} but OBJ text, by the statements "
                                  f"its lines start with ({statements}); rename it room.obj")
    (level.with_suffix(".obj")).write_bytes(data)
    assert len(load_mesh(level.with_suffix(".obj"))[0].faces) == 2


@pytest.mark.parametrize("data", [
    b"3 2 0\n0 0 0\n0 0 1\n1 0 0\n3 0 1 2\n",  # an OFF file whose "OFF" line is lost: numbers, no statement
    b"solid x\nfacet normal 0 1 0\n",  # ASCII STL cut short
    b"v 0 0 0\nv 0 0 1\nv 1 0 0\n",  # vertices without a face
    b"v 0 0 0\nf 1 2 3\nfoo 1\n",  # a line no OBJ statement starts
])
def test_text_that_is_not_an_obj_is_not_called_one(data, tmp_path):
    (level := tmp_path / "room.stl").write_bytes(data)
    with pytest.raises(MeshError) as refused:
        load_mesh(level)
    assert "OBJ" not in str(refused.value)


@pytest.mark.skipif(not Path("/proc/self").is_dir(), reason="needs Linux's /proc")
@pytest.mark.parametrize("outdir", ["/proc/x", "/proc/x/y"])
def test_an_output_folder_in_proc_is_refused_in_our_words(outdir, tmp_path, capsys):
    # was "/proc/x: cannot write results there (No such file or directory)": /proc exists, the kernel makes nothing in it
    (level := tmp_path / "room.obj").write_bytes(FLOOR_OBJ)
    outcome = run_g2s(capsys, "run", "graph_only", level, "-o", outdir)
    assert assert_clean_error(outcome) == f"g2s: error: {outdir}: cannot write results there (/proc takes no new folders; give a folder on a disk)"
    assert tree(Path(outdir)) == []
