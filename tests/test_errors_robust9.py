"""Inputs robust9 (4 December 2026) found told in other words, refused wrongly or ending g2s silently: ``g2s batch
--format`` named the Python API's ``formats``; a plugin's own failure was exit 2, the code of bad input, and a hook
that called ``sys.exit`` ended g2s with its code; damaged or unusual mesh files (a binary PLY of triangles and quads,
a PLY without z, an ASCII STL cut short, glTF nodes, primitive modes, indices and compression of another kind, an OBJ
comment after a line's values) were a library's words, a false cause or refused; a preset extended through two files
was a cycle; an output path too long was an internal error; ``g2s run MESH CONFIG`` read the mesh as YAML;
``load_result`` showed a ``schema_version`` as Python writes it."""

from __future__ import annotations

import base64
import json
import struct
import types

import pytest

import g2s_core
from g2s_core.config import PRESETS_DIR, load_config
from g2s_core.errors import ConfigError, G2SError, MeshError, PluginFailure
from g2s_core.mesh import load_mesh
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


def binary_ply(faces, vertices=((0, 0, 0), (10, 0, 0), (10, 0, 10), (0, 0, 10)), xyz="x y z") -> bytes:
    """A binary little-endian PLY of ``vertices`` (float) and ``faces`` (a uchar count, then uint indices each)."""
    properties = "".join(f"property float {axis}\n" for axis in xyz.split())
    header = (f"ply\nformat binary_little_endian 1.0\nelement vertex {len(vertices)}\n{properties}element face {len(faces)}\n"
              "property list uchar uint vertex_indices\nend_header\n")
    return header.encode() + b"".join(struct.pack(f"<{len(v)}f", *v) for v in vertices) + \
        b"".join(struct.pack(f"<B{len(f)}I", len(f), *f) for f in faces)


def test_a_binary_ply_of_triangles_and_quads_is_read(tmp_path):
    # Blender writes a face element of triangles and quads; trimesh reads every row as long as the first ("PLY is
    # unexpected length!"), and g2s said "binary PLY ends early: the header declares 2 faces, the file holds 1"
    path = tmp_path / "mixed.ply"
    path.write_bytes(binary_ply([(0, 2, 1), (0, 3, 2, 1)], vertices=((0, 0, 0), (10, 0, 0), (10, 0, 10), (0, 0, 10))))
    mesh, info = load_mesh(path)
    assert len(mesh.faces) == 3 and info.faces == 3
    assert mesh.area == pytest.approx(150.0) and (mesh.face_normals[:, 1] > 0.99).all()  # the quad fanned as trimesh fans one
    # and a pentagon beside them, fanned from its first corner over the file's own vertex numbers (pymeshlab reads an
    # OFF pentagon's corners as 0-4 instead, which is why OFF files keep a reader of their own)
    path.write_bytes(binary_ply([(0, 1, 2), (0, 2, 3), (3, 2, 4, 5), (5, 4, 6, 8, 7)], vertices=(
        (0, 0, 0), (0, 0, 4), (4, 0, 4), (4, 0, 0), (8, 0, 4), (8, 0, 0), (12, 0, 4), (12, 0, 0), (14, 0, 2))))
    mesh, info = load_mesh(path)
    assert (info.faces, mesh.area) == (7, pytest.approx(16 + 16 + 20)) and (mesh.face_normals[:, 1] > 0.99).all()


@pytest.mark.parametrize("data, says", [
    (binary_ply([(0, 2, 1), (0, 2)]), "face 1 (counted from 0) has 2 corners (at least 3 make a face)"),
    (binary_ply([(0, 2, 1), ()]), "face 1 (counted from 0) has 0 corners (at least 3 make a face)"),
    (binary_ply([(0, 2, 1), (0, 3, 2, 1)])[:-3], "binary PLY ends early: the header declares 2 faces, the file holds 1"),
    (binary_ply([(0, 2, 1)], vertices=((0, 0), (10, 0), (10, 10)), xyz="x y"), "the vertex element has no property z (expected x, y and z)"),
])
def test_a_damaged_ply_names_what_is_wrong(data, says, tmp_path):
    # were "binary PLY ends early ..., the file holds 1" for whole files, and "cannot read mesh (KeyError: 'z')"
    path = tmp_path / "damaged.ply"
    path.write_bytes(data)
    with pytest.raises(MeshError) as caught:
        load_mesh(path)
    assert str(caught.value) == f"{path}: {says}"


def test_an_ascii_stl_cut_short_says_so(tmp_path):
    # was "the mesh is empty (no triangles)": trimesh reads a solid without its endsolid as nothing
    path = tmp_path / "cut.stl"
    path.write_text("solid a\nfacet normal 0 1 0\nouter loop\nvertex 0 0 0\nvertex 0 0 10\nvertex 10 0 0\nendloop\nendfacet\n")
    with pytest.raises(MeshError, match="the file ends inside a solid, without its endsolid line"):
        load_mesh(path)


def gltf(modes=(4,), nodes=None) -> str:
    """A glTF of the 10 m floor, one primitive of each of ``modes`` over the same data, in ``nodes`` (default: one)."""
    data = b"".join(struct.pack("<3f", *v) for v in ((0, 0, 0), (10, 0, 0), (10, 0, 10), (0, 0, 10))) + \
        struct.pack("<6I", 0, 2, 1, 0, 3, 2)
    return json.dumps({
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": nodes or [{"mesh": 0}],
        "buffers": [{"uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode(), "byteLength": len(data)}],
        "bufferViews": [{"buffer": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 24}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "max": [10, 0, 10], "min": [0, 0, 0]},
                      {"bufferView": 1, "componentType": 5125, "count": 6, "type": "SCALAR"}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": mode} for mode in modes]}]})


@pytest.mark.parametrize("text, says", [
    # trimesh's words, or a false cause
    (gltf(nodes=[{"mesh": 0, "matrix": [1, 0, 0]}]), "nodes[0].matrix is [1, 0, 0]; expected a list of 16 finite numbers"),
    (gltf(nodes=[{"mesh": 0, "translation": "x"}]), "nodes[0].translation is 'x'; expected a list of 3 finite numbers"),
    (gltf(nodes=[{"mesh": 0, "children": [7]}]), "nodes[0].children is [7]; expected a list of indices of the file's 1 node"),
    (gltf(nodes=[{"mesh": 3}]), "nodes[0].mesh is 3; expected the index of one of the file's 1 mesh"),  # "the mesh is empty"
    (gltf(modes=[6]), "meshes[0].primitives[0].mode is 6; expected one of 0-5 ("),  # "the mesh is empty"
    (gltf(modes=["4"]), "meshes[0].primitives[0].mode is '4'; expected one of 0-5 ("),
    (gltf(modes=[4, 6]), "meshes[0].primitives[1].mode is 6; expected one of 0-5 ("),  # read without the fan, silently
    (gltf(modes=[4, 12]), "meshes[0].primitives[1].mode is 12; expected one of 0-5 ("),  # read without it, silently
])
def test_a_gltf_node_or_primitive_of_another_kind_is_named(text, says, tmp_path):
    path = tmp_path / "level.gltf"
    path.write_text(text)
    with pytest.raises(MeshError) as caught:
        load_mesh(path)
    assert str(caught.value).startswith(f"{path}: {says}")


def test_valid_gltf_nodes_and_modes_are_read(tmp_path):
    path = tmp_path / "level.gltf"
    path.write_text(gltf(modes=[4, 1], nodes=[{"mesh": 0, "translation": [1, 2, 3], "rotation": [0, 0, 0, 1], "scale": [2, 1, 1],
                                               "children": [1]}, {"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]}]))
    mesh, _ = load_mesh(path)
    assert len(mesh.faces) == 2 and mesh.area == pytest.approx(200.0)  # the lines primitive left out, as before


@pytest.mark.parametrize("line, commented", [("v 0 0 0", "v 0 0 0 # origin"), ("f 1 3 2", "f 1 3 2 # floor"),
                                             ("f 1 3 2", "f 1 3 2#floor")])
def test_an_obj_comment_after_values_is_read_as_a_comment(line, commented, tmp_path):
    # trimesh read it as values: "cannot read mesh (ValueError: string or file could not be read to its end ...)",
    # and g2s's check said "line 5: face corner '#' is not a vertex index"
    path = tmp_path / "commented.obj"
    path.write_text(FLOOR.replace(line, commented))
    mesh, _ = load_mesh(path)
    assert len(mesh.faces) == 2 and mesh.area == pytest.approx(100.0)
    path.write_text(FLOOR.replace(line, commented).replace("f 1 4 3", "f 1 4 9 # past"))
    with pytest.raises(MeshError, match="line 6: a face refers to vertex 9; the file has 4 vertices"):
        load_mesh(path)


def test_a_file_named_after_a_preset_extends_it_through_another_file(tmp_path):
    # was "map_analysis.yaml: extends: cycle map_analysis.yaml -> shared.yaml -> map_analysis.yaml", where the file
    # extending its own name alone extends the preset
    (tmp_path / "map_analysis.yaml").write_text("extends: shared.yaml\nagent: {height: 1.5}\n")
    (tmp_path / "shared.yaml").write_text("extends: map_analysis\nagent: {radius: 0.3}\n")
    config = load_config(tmp_path / "map_analysis.yaml")
    assert (config.agent.radius, config.agent.height) == (0.3, 1.5)
    assert config.terminals.plugin == load_config(PRESETS_DIR / "map_analysis.yaml").terminals.plugin
    (tmp_path / "a.yaml").write_text("extends: b.yaml\n")
    (tmp_path / "b.yaml").write_text("extends: a\n")  # no preset of that name: still a cycle
    with pytest.raises(ConfigError, match=r"a.yaml: extends: cycle a.yaml -> b.yaml -> a.yaml"):
        load_config(tmp_path / "a.yaml")


class _Unprintable(Exception):
    def __str__(self) -> str:
        raise RuntimeError("no text")


# each exception made as the test runs: one made at import kept the traceback of its raise, and with it the frames of
# that run (its navmesh, a NavMeshCore) to the interpreter's exit, where nanobind reported 4 of them leaked (robust10)
@pytest.mark.parametrize("raising, says", [
    (lambda: SystemExit(0), "raised SystemExit: 0"),  # exit 0, nothing written, no word: g2s ended where the hook called sys.exit
    (lambda: ValueError("first\nsecond\n"), "raised ValueError: first / second"),  # two lines on stderr
    (lambda: ValueError("x" * 100_000), f"raised ValueError: {'x' * 300}... (100,000 characters)"),  # a line of 100 kB
    (_Unprintable, "raised _Unprintable: (its message cannot be shown: its str() raised)"),  # internal error: RuntimeError
])
def test_a_plugin_raising_in_its_hook_is_one_line_naming_it_and_its_package(raising, says, floor, tmp_path, monkeypatch, capsys):
    from g2s_core import cli, hookimpl
    from g2s_core.registry import Registry

    def analyze(structure):
        raise raising()

    registry = Registry.from_entry_points()
    plugin = types.ModuleType("hostile", "an analyzer that raises")
    plugin.NAME, plugin.g2s_analyze = "hostile", hookimpl(analyze)
    registry.register(plugin, package="hostile-pkg", entry_point="analyzers.hostile")
    monkeypatch.setattr(cli, "installed", lambda: registry)
    config = tmp_path / "hostile.yaml"
    config.write_text("extends: map_piece\nanalyzers: [{plugin: hostile}]\n")
    outcome = run_g2s(capsys, "run", config, floor, "-o", tmp_path / "out", "--format", "json")
    assert assert_clean_error(outcome, code=1) == f"g2s: error: Analyzer plugin 'hostile' (package 'hostile-pkg') failed: {says}"
    assert tree(tmp_path / "out") == []


def test_a_plugin_that_exits_as_it_loads_is_listed_broken(capsys):
    # a module calling sys.exit() (argparse at import) ended every g2s command that loaded its stage
    from g2s_core.registry import Registry

    class Quits:
        name, value = "analyzers.quits", "quits:plugin"

        def load(self):
            raise SystemExit(2)

    registry = Registry()
    registry._unloaded[None] = [(0, "quitting-pkg", Quits())]
    assert [(b.package, b.reason) for b in registry.broken()] == [("quitting-pkg", "SystemExit: 2")]
    with pytest.raises(PluginFailure, match=r"^Analyzer plugin 'quits' \(package 'quitting-pkg'\) failed to load: SystemExit: 2$"):
        registry.get("analyzers", "quits")


@pytest.mark.parametrize("change, says", [
    # a compressed mesh: trimesh reads the data under it (none: "every face has zero area", or read wrong)
    (lambda g: g.update(extensionsUsed=["KHR_draco_mesh_compression"], extensionsRequired=["KHR_draco_mesh_compression"]),
     "extensionsRequired lists KHR_draco_mesh_compression: the mesh is compressed, which g2s cannot read"),
    (lambda g: g.update(asset={"version": "1.0"}),  # "cannot read mesh (NotImplementedError: only GLTF 2 is supported not `1.0`)"
     "asset.version is '1.0'; g2s reads glTF 2.0"),
    (lambda g: g["accessors"][1].update(count=5),  # "cannot read mesh (ValueError: cannot reshape array of size 5 into shape (3))"
     "meshes[0].primitives[0].indices is 1; expected the index of an accessor of SCALAR unsigned integers"),
])
def test_a_gltf_g2s_cannot_read_says_why(change, says, tmp_path):
    document = json.loads(gltf())
    change(document)
    path = tmp_path / "level.gltf"
    path.write_text(json.dumps(document))
    with pytest.raises(MeshError) as caught:
        load_mesh(path)
    assert str(caught.value).startswith(f"{path}: {says}")


@pytest.mark.parametrize("required", [5, "KHR_draco_mesh_compression"])
def test_extensions_required_of_another_kind_are_read_as_trimesh_reads_them(required, tmp_path):
    # an extensionsRequired that is not a list (not valid glTF, ignored by trimesh) was an internal error:
    # "TypeError: 'int' object is not iterable" (exit 1)
    document = json.loads(gltf())
    document["extensionsRequired"] = required
    path = tmp_path / "level.gltf"
    path.write_text(json.dumps(document))
    mesh, _ = load_mesh(path)
    assert len(mesh.faces) == 2


def test_an_output_folder_whose_path_is_too_long_is_refused(floor, tmp_path, capsys):
    # was "internal error: OSError: [Errno 36] File name too long" (exit 1), or, a little shorter, the writer's failure
    outdir = tmp_path.joinpath(*["d" * 200] * 20)
    outcome = run_g2s(capsys, "run", "graph_only", floor, "-o", outdir)
    assert assert_clean_error(outcome).endswith("bytes is too long for the files in it)")
    assert tree(tmp_path / ("d" * 200)) == []


@pytest.mark.parametrize("version, says", [
    (None, "schema_version null is not supported (this g2s reads 1, 2, 3)"),  # Python's None
    (4, "schema_version 4 is not supported (this g2s reads 1, 2, 3); a newer g2s wrote it: upgrade g2s to read it"),
    ("missing", "schema_version: required key is missing (this g2s reads 1, 2, 3)"),  # "schema_version None"
])
def test_load_result_names_a_schema_version_it_cannot_read(version, says, tmp_path):
    document = {"format": "g2s-structure", "schema_version": version}
    if version == "missing":
        del document["schema_version"]
    (tmp_path / "structure.json").write_text(json.dumps(document))
    with pytest.raises(G2SError) as caught:
        g2s_core.load_result(tmp_path)
    assert str(caught.value) == f"{tmp_path / 'structure.json'}: {says}"


@pytest.mark.parametrize("suffix", [".obj", ".GLB"])
def test_a_mesh_given_as_the_config_says_the_config_comes_first(suffix, tmp_path, capsys):
    # the mesh read as YAML: "floor.obj: expected a mapping of settings at the top level, got 'v 0 0 0 v 10 0 0 ...'",
    # "level.gltf: asset: unknown key ...", "level.glb: line 1: byte 0xe7 is not UTF-8 (save the config file as UTF-8 text)"
    mesh = tmp_path / f"floor{suffix}"
    mesh.write_text(FLOOR)
    outcome = run_g2s(capsys, "run", mesh, "map_analysis", "-o", tmp_path / "out")
    assert assert_clean_error(outcome) == (f"g2s: error: {mesh}: expected a preset name or a config file, got a mesh file: "
                                           "g2s run takes the config first, then the mesh")
