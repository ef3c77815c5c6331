"""Mesh input: formats, up axis, scale, cleaning, and bad files."""

from __future__ import annotations

import codecs
import hashlib
import io

import numpy as np
import pytest
import trimesh

from g2s_core import DISTRIBUTION
from g2s_core.config import MeshConfig
from g2s_core.errors import ConfigError, MeshError
from g2s_core.mesh import SUPPORTED_SUFFIXES, clean_mesh, generate_level, load_mesh
from g2s_core.registry import installed
from g2s_plugins.samples import levels


def floor_box() -> trimesh.Trimesh:
    return trimesh.creation.box(extents=(4.0, 0.2, 2.0))


@pytest.mark.parametrize("suffix", [".obj", ".ply", ".stl", ".off", ".glb"])
def test_formats_load_to_the_same_geometry(tmp_path, suffix):
    path = tmp_path / f"floor{suffix}"
    floor_box().export(path)
    before = path.read_bytes()
    mesh, info = load_mesh(path)
    assert np.allclose(mesh.bounds, floor_box().bounds)
    assert info.faces == 12 and info.sha256 == hashlib.sha256(path.read_bytes()).hexdigest()
    assert path.read_bytes() == before


def test_gltf_scene_is_flattened_with_node_transforms(tmp_path):
    scene = trimesh.Scene()
    scene.add_geometry(floor_box(), transform=trimesh.transformations.translation_matrix((10, 0, 0)))
    scene.add_geometry(floor_box(), transform=trimesh.transformations.translation_matrix((-10, 0, 0)))
    path = tmp_path / "two.glb"
    scene.export(path)
    mesh, info = load_mesh(path)
    assert info.faces == 24
    assert np.allclose(mesh.bounds[:, 0], [-12, 12])


def test_z_up_and_scale(tmp_path):
    tall_in_z = trimesh.creation.box(extents=(1.0, 2.0, 30.0))
    path = tmp_path / "z.obj"
    tall_in_z.export(path)
    mesh, _ = load_mesh(path, MeshConfig(up_axis="z", scale=0.1))
    assert np.allclose(mesh.extents, [0.1, 3.0, 0.2])


def test_cleaning_reports_what_it_removed(tmp_path):
    box = floor_box()
    doubled = trimesh.Trimesh(np.vstack([box.vertices, box.vertices]), np.vstack([box.faces, box.faces + 8]), process=False)
    path = tmp_path / "doubled.ply"
    doubled.export(path)
    mesh, info = load_mesh(path, MeshConfig(clean=True))
    assert len(mesh.faces) == 12
    assert info.cleaning["merged_vertices"] == 8 and info.cleaning["duplicate_faces"] == 12



def test_cleaning_keeps_the_up_facing_side_of_two_sided_floors():
    """Floors exported two-sided (each top also wound the other way, listed before or after it): of each pair,
    cleaning drops the down-facing face, so every floor stays walkable (pymeshlab's own filter kept either)."""
    dungeon = levels.dungeon(seed=0, rooms=20).mesh
    up = dungeon.face_normals[:, 1] > 0.99
    for faces in (np.vstack([dungeon.faces, dungeon.faces[up][:, ::-1]]), np.vstack([dungeon.faces[up][:, ::-1], dungeon.faces])):
        cleaned, removed = clean_mesh(trimesh.Trimesh(dungeon.vertices, faces, process=False))
        assert removed["duplicate_faces"] == up.sum() and len(cleaned.faces) == len(dungeon.faces)
        assert (cleaned.face_normals[:, 1] > 0.99).sum() == up.sum()

@pytest.mark.parametrize(
    "name, content, message",
    [
        ("missing.obj", None, "no such mesh file"),
        ("level.fbx", b"x", "unsupported mesh type '.fbx'"),
        ("empty.obj", b"", "the file is empty (0 bytes)"),
        ("points.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\n", "no triangles"),
        ("nan.obj", b"v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", "line 2: vertex coordinate 'nan' is not a finite number"),
        ("junk.glb", b"not a glb file at all", "not a GLB file: it starts with b'not ', not b'glTF'"),
    ],
)
def test_bad_meshes_are_one_line_errors(tmp_path, name, content, message):
    path = tmp_path / name
    if content is not None:
        path.write_bytes(content)
    with pytest.raises(MeshError) as caught:
        load_mesh(path)
    assert message in str(caught.value) and str(path) in str(caught.value)
    assert "\n" not in str(caught.value)


def test_supported_suffixes_are_documented_in_the_error(tmp_path):
    path = tmp_path / "a.dae"
    path.write_text("x")
    with pytest.raises(MeshError, match=", ".join(SUPPORTED_SUFFIXES)):
        load_mesh(path)


@pytest.mark.parametrize("suffix, encoding", [(".ply", "binary"), (".ply", "ascii"), (".stl", None), (".off", None)])
def test_single_mesh_files_skip_the_scene_and_read_the_same_arrays(tmp_path, suffix, encoding):
    source = trimesh.creation.icosphere(subdivisions=2)
    path = tmp_path / f"m{suffix}"
    source.export(path, **({"encoding": encoding} if encoding else {}))
    mesh, info = load_mesh(path)
    reference = trimesh.load(path, force="mesh", process=False)
    assert np.array_equal(mesh.vertices, reference.vertices) and np.array_equal(mesh.faces, reference.faces)
    assert info.faces == len(source.faces)


@pytest.mark.parametrize("options, mark", [({}, b""), ({"include_normals": True, "include_texture": True}, b""),
                                           ({}, codecs.BOM_UTF8)])
def test_an_obj_of_one_material_skips_the_scene_and_reads_the_same_arrays(tmp_path, options, mark):
    source = levels.two_floors().mesh
    path = tmp_path / "level.obj"
    path.write_bytes(mark + source.export(file_type="obj", **options).encode())
    mesh, info = load_mesh(path)
    with path.open("rb") as handle:
        handle.seek(len(mark))
        reference = trimesh.load(io.BytesIO(handle.read()), "obj", force="mesh", process=False)
    assert np.array_equal(mesh.vertices, reference.vertices) and np.array_equal(mesh.faces, reference.faces)
    assert info.faces == len(source.faces) and info.sha256 == hashlib.sha256(path.read_bytes()).hexdigest()


@pytest.mark.parametrize("edit", [lambda text: text.replace(" ", "\t"), lambda text: text.replace("\n", "\r")],
                         ids=["tabs", "old Mac line ends"])
def test_an_obj_with_tabs_or_lone_carriage_returns_reads_as_the_plain_file(tmp_path, edit):
    text = levels.two_floors().mesh.export(file_type="obj")
    plain, edited = tmp_path / "plain.obj", tmp_path / "edited.obj"
    plain.write_text(text)
    edited.write_bytes(edit(text).encode())
    (mesh, _), (reference, _) = load_mesh(edited), load_mesh(plain)
    assert len(mesh.faces) and np.array_equal(mesh.vertices, reference.vertices) and np.array_equal(mesh.faces, reference.faces)


def test_an_obj_of_several_materials_is_read_as_one_mesh(tmp_path):
    path = tmp_path / "two.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nusemtl a\nf 1 2 3\nusemtl b\nf 1 3 4\n")
    mesh, info = load_mesh(path)
    reference = trimesh.load(path, force="mesh", process=False)
    assert info.faces == 2 and np.array_equal(mesh.faces, reference.faces)


def test_a_ply_point_cloud_is_still_refused(tmp_path):
    path = tmp_path / "points.ply"
    trimesh.PointCloud(np.random.default_rng(0).random((10, 3))).export(path)
    with pytest.raises(MeshError, match="points.ply: the mesh is empty"):
        load_mesh(path)


# --- sample:NAME?param=value levels, from the installed level generators ---------------


def test_sample_levels_come_from_the_level_generators_with_their_parameters():
    builtin = {p.name for p in installed().plugins("levels") if p.package == DISTRIBUTION}
    assert builtin == set(levels.SAMPLES)  # every sample level is a generator
    mesh = generate_level("sample:dungeon?rooms=3&seed=2&loops=0.5")
    expected = levels.dungeon(rooms=3, seed=2, loops=0.5).mesh
    assert np.array_equal(mesh.vertices, expected.vertices) and np.array_equal(mesh.faces, expected.faces)
    for spec, message in [
        ("sample:nope", "sample:nope: unknown sample 'nope' (expected one of: "),
        ("sample:dungeon?rooms=many", "sample:dungeon.rooms: expected an integer >= 1 and <= 100000, got 'many'"),
        ("sample:cross_hub?arms=3", "sample:cross_hub.arms: unknown key (expected one of: hub_size, arm_length, arm_width)"),
        ("sample:cross_hub?hub_size", "sample:cross_hub?hub_size: expected sample:NAME?param=value&param=value"),
    ]:
        with pytest.raises(ConfigError) as caught:
            generate_level(spec)
        assert str(caught.value).startswith(message)
