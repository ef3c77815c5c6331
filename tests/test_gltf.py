"""structure.glb: reloaded with trimesh and read chunk by chunk, names, colours, counts and extras are checked."""

from __future__ import annotations

import json
import struct
from pathlib import Path

import numpy as np
import pytest
import trimesh

from g2s_plugins.outputs import colours, gltf
from tests.test_outputs import make_result, real_navmesh, two_floor_mesh

_COMPONENTS = {5121: np.uint8, 5123: np.uint16, 5125: np.uint32, 5126: np.float32}
_WIDTH = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}


def read_glb(path: Path) -> tuple[dict, bytes]:
    """The JSON header and the binary chunk of a GLB file."""
    data = path.read_bytes()
    magic, version, length = struct.unpack("<4sII", data[:12])
    assert magic == b"glTF" and version == 2 and length == len(data)
    json_length, json_kind = struct.unpack("<I4s", data[12:20])
    assert json_kind == b"JSON"
    header = json.loads(data[20:20 + json_length])
    offset = 20 + json_length
    bin_length, bin_kind = struct.unpack("<I4s", data[offset:offset + 8])
    assert bin_kind == b"BIN\x00"
    return header, data[offset + 8:offset + 8 + bin_length]


def accessor(header: dict, blob: bytes, index: int) -> np.ndarray:
    acc = header["accessors"][index]
    view = header["bufferViews"][acc["bufferView"]]
    dtype = _COMPONENTS[acc["componentType"]]
    width = _WIDTH[acc["type"]]
    start = view.get("byteOffset", 0) + acc.get("byteOffset", 0)
    count = acc["count"] * width
    return np.frombuffer(blob, dtype=dtype, count=count, offset=start).reshape(acc["count"], width)


def _node_extras(scene: trimesh.Scene, name: str) -> dict:
    return scene.graph.transforms.edge_data[(scene.graph.base_frame, name)]["metadata"]


def _colour(scene: trimesh.Scene, name: str) -> tuple[int, ...]:
    _, geometry = scene.graph[name]
    return tuple(int(c) for c in scene.geometry[geometry].visual.material.baseColorFactor)


def _line_colours(path: Path) -> tuple[np.ndarray, np.ndarray, list]:
    """(segment end points (E, 2, 3), segment colours (E, 4), the structure node's edges) of the LINES primitive."""
    header, blob = read_glb(path)
    mesh = next(m for m in header["meshes"] if m["name"] == "structure")
    primitive = mesh["primitives"][0]
    assert primitive["mode"] == 1  # GL_LINES
    points = accessor(header, blob, primitive["attributes"]["POSITION"]).reshape(-1, 2, 3)
    rgba = accessor(header, blob, primitive["attributes"]["COLOR_0"]).reshape(-1, 2, 4)
    assert (rgba[:, 0] == rgba[:, 1]).all()  # one colour per segment
    node = next(n for n in header["nodes"] if n.get("name") == "structure")
    return points, rgba[:, 0], node["extras"]["edges"]


def test_scene_nodes_colours_and_extras(tmp_path):
    result = make_result()
    path, = gltf.write(result, tmp_path)
    assert path.name == "structure.glb"
    scene = trimesh.load(path)
    structure = result.structure
    roots = structure.graph["roots"]
    names = set(scene.graph.nodes_geometry)
    expected = ({"mesh", "structure"} | {f"root_{r}" for r in roots} |
                {f"terminal_{t}" for t in result.terminals.nodes} | {f"node_{n}" for n in structure.nodes})
    assert names == expected
    assert "navmesh" not in names  # no navmesh in this run

    level = scene.geometry[scene.graph["mesh"][1]]
    assert len(level.faces) == len(result.context.mesh.faces)
    assert _colour(scene, "mesh") == (*colours.MESH_COLOUR, 255)
    for root in roots:
        transform, _ = scene.graph[f"root_{root}"]
        assert np.allclose(transform[:3, 3], structure.nodes[root]["pos"])
        assert _colour(scene, f"root_{root}") == (*colours.ROOT_COLOUR, 255)
        assert _node_extras(scene, f"root_{root}")["depth"] == 0
    for terminal in result.terminals.nodes:
        transform, _ = scene.graph[f"terminal_{terminal}"]
        assert np.allclose(transform[:3, 3], result.graph.nodes[terminal]["pos"])
        assert _colour(scene, f"terminal_{terminal}") == (*colours.TERMINAL_COLOUR, 255)
        assert _node_extras(scene, f"terminal_{terminal}")["terminal"] is True

    values = result.analysis["betweenness"]
    coldest, hottest = min(values, key=values.get), max(values, key=values.get)
    assert _colour(scene, f"node_{coldest}") == (*colours.heat_colour(0.0), 255)  # green
    assert _colour(scene, f"node_{hottest}") == (*colours.heat_colour(1.0), 255)  # red
    extras = _node_extras(scene, f"node_{hottest}")
    assert extras["id"] == hottest and extras["depth"] == structure.nodes[hottest]["depth"]
    assert extras["values"]["betweenness"] == pytest.approx(values[hottest], rel=1e-8)
    assert extras["values"]["degree"] == result.analysis["degree"][hottest]

    # the structure survives as line segments, one per edge, coloured by the child's value
    points, rgba, edges = _line_colours(path)
    assert sorted(map(tuple, edges)) == sorted(structure.edges) and len(points) == structure.number_of_edges()
    low, high = min(values.values()), max(values.values())
    for (u, v), segment, colour in zip(edges, points, rgba):
        assert np.allclose(segment, [structure.nodes[u]["pos"], structure.nodes[v]["pos"]], atol=1e-6)
        level_ = round((values[v] - low) / (high - low) * (gltf.HEAT_LEVELS - 1))
        assert tuple(colour) == (*colours.heat_colour(level_ / (gltf.HEAT_LEVELS - 1)), 255)


def test_without_analysis_lines_show_the_tree_depth(tmp_path):
    result = make_result(analysis=False)
    path, = gltf.write(result, tmp_path)
    scene = trimesh.load(path)
    assert not [n for n in scene.graph.nodes_geometry if n.startswith("node_")]
    points, rgba, edges = _line_colours(path)
    depths = {tuple(colour[:3]): result.structure.nodes[v]["depth"] for (_, v), colour in zip(edges, rgba)}
    assert depths[colours.depth_colour(1)] == 1 and depths[colours.depth_colour(2)] == 2  # red = 1, yellow = 2
    for (_, v), colour in zip(edges, rgba):
        assert tuple(colour) == (*colours.depth_colour(result.structure.nodes[v]["depth"]), 255)
    assert len(set(map(tuple, rgba))) == max(d for _, d in result.structure.nodes(data="depth"))


def test_navmesh_is_a_translucent_green_layer(tmp_path):
    mesh = two_floor_mesh()
    navmesh = real_navmesh(mesh)
    result = make_result(navmesh=navmesh)
    path, = gltf.write(result, tmp_path)
    scene = trimesh.load(path)
    surface = scene.geometry[scene.graph["navmesh"][1]]
    assert len(surface.faces) == len(navmesh.detail_triangles) > 0
    assert np.allclose(np.sort(surface.vertices, axis=0), np.sort(np.asarray(navmesh.detail_vertices), axis=0), atol=1e-5)
    colour = _colour(scene, "navmesh")
    assert colour[:3] == colours.NAVMESH_COLOUR and colour[3] < 255
    header, _ = read_glb(path)
    material = next(m for m in header["materials"] if m.get("name") == "navmesh")
    assert material["alphaMode"] == "BLEND"
