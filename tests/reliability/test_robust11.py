"""Inputs robust11 (4-5 December 2026) found ending in an internal error, a hang, a library's words or read silently
wrong, each test failing on the code before its fix (docs/errors.md, "The hostile-user pass of robust11")."""

from __future__ import annotations

import base64
import json
import os
import signal
import struct
import types

import numpy as np
import pytest

from g2s_core import load_result
from g2s_core.cli import main
from g2s_core.errors import G2SError, MeshError, PluginError
from g2s_core.mesh import load_mesh
from g2s_core.registry import Registry

from tests.reliability.checks import CORRIDOR, run_g2s, tree


def test_an_interrupt_that_trimesh_swallows_and_then_fails_on_is_an_interrupt(tmp_path, monkeypatch, capsys):
    # SIGTERM 2.2 s into `g2s run` (trimesh loading, load 10 on 2 cores): trimesh caught the KeyboardInterrupt while it
    # imported its optional parts, kept it as a placeholder, and failed on it a line later (`Path3D | None`:
    # TypeError); the run ended `g2s: internal error: TypeError: unsupported operand type(s) for |: 'ExceptionWrapper'
    # and 'NoneType'`, exit 1, blaming g2s for the user's own interrupt
    from g2s_core import cli

    class Importing:  # a module whose loading swallows the interrupt, then fails as trimesh's does
        def __getattr__(self, attribute: str) -> object:
            try:
                os.kill(os.getpid(), signal.SIGTERM)
            except BaseException:  # as trimesh's imports do
                pass
            raise TypeError("unsupported operand type(s) for |: 'ExceptionWrapper' and 'NoneType'")

    monkeypatch.setattr(cli, "api", Importing())
    outcome = run_g2s(capsys, "run", "graph_only", CORRIDOR, "-o", tmp_path / "out", "-q")
    assert (outcome.code, outcome.stderr) == (130, "g2s: interrupted\n")
    assert tree(tmp_path / "out") == []


def _gltf_floor(nodes: list[dict]) -> dict:
    """A glTF document of a 10 m square floor (mesh 0) under ``nodes``, the first the scene's root."""
    positions = np.array([(0, 0, 0), (10, 0, 0), (10, 0, 10), (0, 0, 10)], "<f4").tobytes()
    indices = np.array([0, 2, 1, 0, 3, 2], "<u2").tobytes()
    data = positions + indices
    return {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": nodes,
        "buffers": [{"byteLength": len(data), "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
        "bufferViews": [{"buffer": 0, "byteLength": len(positions)},
                        {"buffer": 0, "byteOffset": len(positions), "byteLength": len(indices)}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0, 0, 0], "max": [10, 0, 10]},
                      {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
    }


def _chain(count: int, transformed: int) -> list[dict]:
    """``count`` nodes each the child of the one before, the last holding the mesh; the last ``transformed`` scaled."""
    nodes = [{"children": [number + 1]} for number in range(count - 1)] + [{"mesh": 0}]
    for node in nodes[count - transformed:]:
        node["scale"] = [1.001, 1.001, 1.001]
    return nodes


@pytest.mark.parametrize("suffix", [".gltf", ".glb"])
def test_a_mesh_under_1000_nested_transforms_is_refused_in_words(suffix, tmp_path):
    # trimesh multiplies a mesh's transforms with numpy's multi_dot, which orders the product in time of the cube of
    # their number, recursing as deep: 1,000 nested were `cannot read mesh (RecursionError: maximum recursion depth
    # exceeded in comparison)`, 10,000 ran for hours (killed after 120 s)
    path = tmp_path / f"deep{suffix}"
    document = _gltf_floor(_chain(1000, 1000))
    if suffix == ".glb":  # the same document in a GLB's JSON chunk (its buffer stays a data URI)
        chunk = json.dumps(document).encode().ljust(-(-len(json.dumps(document)) // 4) * 4)
        path.write_bytes(b"glTF" + struct.pack("<II", 2, 20 + len(chunk)) + struct.pack("<I", len(chunk)) + b"JSON" + chunk)
    else:
        path.write_text(json.dumps(document))
    with pytest.raises(MeshError, match=r"deep\.gl(tf|b): nodes\[999\], a mesh's node, sits under 1,000 nested transforms; "
                                        r"g2s reads at most 256 \("):
        load_mesh(path)


def test_nested_nodes_without_transforms_and_200_transforms_are_read(tmp_path):
    # only the transforms count, as only they are multiplied: 10,000 nested nodes of identity transforms are read
    path = tmp_path / "deep.gltf"
    chain = _chain(10_000, 200)
    chain[0]["translation"] = [0, 0, 0]  # written, but the identity
    path.write_text(json.dumps(_gltf_floor(chain)))
    mesh, _ = load_mesh(path)
    assert mesh.area == pytest.approx(100 * 1.001 ** 400, rel=1e-4)


def _analyzer_module(name: str, source: str) -> types.ModuleType:
    module = types.ModuleType(name)
    exec(source, module.__dict__)  # noqa: S102 - a plugin module of the test's own text
    return module


TWIN = '''"""Twin: one value for every node."""
from g2s_core.plugin import hookimpl
NAME = "twin"

@hookimpl
def g2s_analyze(structure):
    return {node: 1.0 for node in structure}
'''


def test_a_plugin_named_by_two_entry_points_is_told_in_one_short_line():
    # a package's two entry points naming one module: pluggy's ValueError listed every plugin registered (4 kB in
    # the run's one line: `Plugin already registered under a different name: ... {'graph2structure:outputs.glb:glb':
    # LazyWriter(...), ...}`)
    registry = Registry()
    module = _analyzer_module("twin_mod", TWIN)
    registry.register(module, package="twin-plug", entry_point="analyzers.twin")
    with pytest.raises(PluginError) as raised:
        registry.register(module, package="twin-plug", entry_point="analyzers.twin2")
    assert str(raised.value) == ("entry point 'analyzers.twin2' of package 'twin-plug': its plugin is also that of entry "
                                 "point 'analyzers.twin'; each entry point names a plugin of its own")


def test_a_hook_of_a_wrong_argument_is_told_in_one_line():
    # pluggy's three lines were one line holding two written `\n`
    module = _analyzer_module("sig_mod", TWIN.replace("(structure)", "(graph)").replace("in structure", "in graph"))
    with pytest.raises(PluginError) as raised:
        Registry().register(module, package="sig-plug", entry_point="analyzers.twin")
    assert "\n" not in str(raised.value) and " / hookimpl definition: g2s_analyze(graph) / Argument(s) {'graph'} are " \
        "declared in the hookimpl but can not be found in the hookspec" in str(raised.value)


@pytest.fixture(scope="module")
def structure_document(tmp_path_factory) -> dict:
    """A real structure.json of a whole run, with edges."""
    out = tmp_path_factory.mktemp("result")
    assert main(["run", "map_analysis", "sample:cross_hub", "-o", str(out), "--format", "json", "-q"]) == 0
    return json.loads((out / "structure.json").read_text())


@pytest.mark.parametrize("change, says", [
    (lambda edges: edges.append({**edges[0], "weight": 99.0}), r"edges\[\d+\]: the edge (\d+) -> (\d+) is given twice \(first at edges\[0\]\)"),
    (lambda edges: edges.append({**edges[0], "target": edges[0]["source"]}), r"edges\[\d+\]: an edge from node (\d+) to itself"),
], ids=["given twice", "to itself"])
def test_a_structure_edge_given_twice_or_to_its_own_node_is_refused(structure_document, change, says, tmp_path):
    # a tampered structure.json: the second record of an edge replaced the first's weight, and an edge from a node to
    # itself was read as a loop of it, silently (a node id given twice has been refused since robust6)
    document = json.loads(json.dumps(structure_document))
    change(document["edges"])
    (tmp_path / "structure.json").write_text(json.dumps(document))
    with pytest.raises(G2SError, match=f"structure.json: {says}$"):
        load_result(tmp_path)
    assert load_result_of(structure_document, tmp_path / "sound").structure.number_of_edges() == len(structure_document["edges"])


def load_result_of(document: dict, folder):
    folder.mkdir()
    (folder / "structure.json").write_text(json.dumps(document))
    return load_result(folder)
