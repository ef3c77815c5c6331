"""Inputs robust45 (6 December 2026) found breaking docs/errors.md's rules: OBJ text under another format's suffix
named in that format's words (``binary STL ends early: the header announces 808464432 triangles``), and ``-o /proc/x``
refused in the kernel's words ("No such file or directory", of a folder whose parent exists), and a level whose faces
are wound against their neighbours (normals a modeller left flipped) refused without naming ``mesh.clean``, and
not mended by it; from an installed package, ``g2s run configs/map_analysis.yaml`` (the docs' form) found no config."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import trimesh

from g2s_core.config import PRESETS_DIR, find_config
from g2s_core.errors import ConfigError, MeshError
from g2s_core.mesh import clean_mesh, load_mesh
from g2s_plugins.walkable_check import MAX_AGAINST_NEIGHBOURS, wound_against_neighbours
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


def test_an_output_folder_under_a_deleted_working_folder_keeps_the_kernels_words(tmp_path, capsys, monkeypatch):
    # mkdtemp in a working folder removed under the shell also answers "No such file or directory": that folder is on
    # a disk, so the /proc words would blame it wrongly
    (level := tmp_path / "room.obj").write_bytes(FLOOR_OBJ)
    (gone := tmp_path / "gone").mkdir()
    monkeypatch.chdir(gone)
    gone.rmdir()
    outcome = run_g2s(capsys, "run", "graph_only", level, "-o", "out")
    assert assert_clean_error(outcome) == "g2s: error: out: cannot write results there (No such file or directory)"


def _every_other_face_flipped(mesh: trimesh.Trimesh) -> trimesh.Trimesh:
    faces = mesh.faces.copy()
    faces[::2] = faces[::2, ::-1]
    return trimesh.Trimesh(mesh.vertices, faces, process=False)


SLAB = trimesh.creation.box(extents=(10, 0.2, 10)).subdivide()
"""A closed floor slab 10 m square, its top at y = 0.1, wound outwards: 48 faces, 8 of them its top."""


def test_cleaning_winds_each_body_one_way(tmp_path):
    # a closed slab with every other face flipped: clean_mesh's inside-out test needs one winding to weigh a volume
    cleaned, counts = clean_mesh(_every_other_face_flipped(SLAB))
    assert counts["rewound_faces"] == 24  # then, wound one way, its volume tells its outside (a tie of areas here)
    assert np.allclose(np.sort(cleaned.face_normals[:, 1]), np.sort(SLAB.face_normals[:, 1]))
    assert cleaned.volume == pytest.approx(SLAB.volume)


def test_an_open_floor_is_wound_as_most_of_its_area():
    # four triangles of a floor, one wound down: no volume tells its up, the file's majority does
    floor = trimesh.Trimesh(vertices=[[0, 0, 0], [0, 0, 10], [10, 0, 10], [10, 0, 0], [5, 0, 5]],
                            faces=[[4, 0, 1], [4, 1, 2], [4, 3, 2], [4, 3, 0]], process=False)
    assert (floor.face_normals[:, 1] > 0).sum() == 3
    cleaned, counts = clean_mesh(floor)
    assert counts["rewound_faces"] == 1 and (cleaned.face_normals[:, 1] > 0.99).all()


def test_faces_wound_against_their_neighbours_are_counted():
    assert wound_against_neighbours(SLAB) == 0.0
    assert wound_against_neighbours(_every_other_face_flipped(SLAB)) > MAX_AGAINST_NEIGHBOURS


def test_a_level_of_flipped_faces_names_mesh_clean(tmp_path, capsys):
    # was silent: half the slab's top walkable (45.6 % of the footprint), no warning, no key named
    (level := tmp_path / "slab.obj").write_text(trimesh.exchange.obj.export_obj(_every_other_face_flipped(SLAB)))
    outcome = run_g2s(capsys, "run", "graph_only", level, "-o", tmp_path / "out", "--format", "json")
    assert outcome.code == 0
    assert "% of the edges between two faces join faces wound opposite ways" in outcome.stderr
    assert "set `mesh: {clean: true}` to wind each body one way" in outcome.stderr
    mended = run_g2s(capsys, "run", "graph_only", level, "-o", tmp_path / "mended", "--format", "json", "--set", "mesh.clean=true")
    assert mended.code == 0 and "warning" not in mended.stderr


def test_the_repositorys_configs_path_names_the_preset_where_no_such_file_is(tmp_path, monkeypatch):
    # an installed package has no configs/ folder: the docs' `g2s run configs/map_analysis.yaml ...` was
    # "configs/map_analysis.yaml: no such config file or preset" outside a clone
    monkeypatch.chdir(tmp_path)
    assert find_config("configs/map_analysis.yaml") == PRESETS_DIR / "map_analysis.yaml"
    assert find_config("configs/map_piece") == PRESETS_DIR / "map_piece.yaml"
    (tmp_path / "configs").mkdir()
    (mine := tmp_path / "configs" / "map_analysis.yaml").write_text("extends: map_analysis\n")
    assert find_config("configs/map_analysis.yaml") == Path("configs/map_analysis.yaml")  # a file there wins
    with pytest.raises(ConfigError, match="configs/nosuch.yaml: no such config file or preset"):
        find_config("configs/nosuch.yaml")
    with pytest.raises(ConfigError, match="no such config file or preset"):  # a user's own configs/ elsewhere: no stand-in
        find_config(tmp_path / "project" / "configs" / "map_analysis.yaml")
    assert mine.read_text() == "extends: map_analysis\n"
