"""structure.glb: names, colours, counts and extras (reloaded with trimesh and read chunk by chunk), tubes, bytes."""

from __future__ import annotations

import json
import os
import shutil
import struct
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import trimesh

from g2s_core import pipeline
from g2s_core.config import PRESETS_DIR, load_config
from g2s_core.mesh import generate_level, mesh_sha256
from g2s_core.registry import installed
from g2s_plugins.outputs import colours, gltf
from tests.conftest import PROJECT
from tests.test_outputs import TERMINALS, WAYPOINTS, make_result, real_navmesh, two_floor_mesh

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
    return scene.graph.transforms.edge_data[(scene.graph.transforms.parents[name], name)]["metadata"]


def _colour(scene: trimesh.Scene, name: str) -> tuple[int, ...]:
    _, geometry = scene.graph[name]
    return tuple(int(c) for c in scene.geometry[geometry].visual.material.baseColorFactor)


def _tube_edges(scene: trimesh.Scene) -> dict[str, list[tuple[int, int]]]:
    """Edge mesh name -> the edges its tubes draw, in order."""
    return {name: [tuple(e) for e in _node_extras(scene, name)["edges"]]
            for name in scene.graph.nodes_geometry if name.startswith("edges")}


def _children(header: dict, name: str) -> list[str]:
    node = next(n for n in header["nodes"] if n.get("name") == name)
    return [header["nodes"][i]["name"] for i in node.get("children", [])]


def test_scene_groups_colours_and_extras(tmp_path):
    result = make_result()
    path, = gltf.write(result, tmp_path)
    assert path.name == "structure.glb"
    header, _ = read_glb(path)
    assert [header["nodes"][i]["name"] for i in header["scenes"][0]["nodes"]] == list(gltf.GROUPS)
    structure = result.structure
    roots = structure.graph["roots"]
    assert _children(header, "level") == ["level_mesh"]
    assert _children(header, "navmesh") == [] and _children(header, "loops") == []  # no navmesh; a tree has no loops
    assert _children(header, "regions") == [] and _children(header, "chokepoints") == []  # their analyzers did not run
    assert sorted(_children(header, "roots")) == sorted(f"root_{r}" for r in roots)
    assert sorted(_children(header, "terminals")) == sorted(f"terminal_{t}" for t in result.terminals.nodes)
    assert {n for n in _children(header, "structure") if n.startswith("node_")} == {f"node_{n}" for n in structure}

    scene = trimesh.load(path)
    level = scene.geometry[scene.graph["level_mesh"][1]]
    assert len(level.faces) == len(result.context.mesh.faces)
    assert _colour(scene, "level_mesh") == (*colours.MESH_COLOUR, 255)
    lift = np.asarray([0.0, gltf.NODE_RADIUS * 0.5, 0.0])  # default agent radius 0.5 m
    for root in roots:
        transform, _ = scene.graph[f"root_{root}"]
        assert np.allclose(transform[:3, 3], np.add(structure.nodes[root]["pos"], lift))
        assert _colour(scene, f"root_{root}") == (*colours.ROOT_COLOUR, 255)
        assert _node_extras(scene, f"root_{root}")["depth"] == 0
    for terminal in result.terminals.nodes:
        transform, _ = scene.graph[f"terminal_{terminal}"]
        assert np.allclose(transform[:3, 3], np.add(result.graph.nodes[terminal]["pos"], lift))
        assert _colour(scene, f"terminal_{terminal}") == (*colours.TERMINAL_COLOUR, 255)
        assert _node_extras(scene, f"terminal_{terminal}")["terminal"] is True

    values = result.analysis["betweenness"]
    coldest, hottest = min(values, key=values.get), max(values, key=values.get)
    assert _colour(scene, f"node_{coldest}") == (*colours.heat_colour(0.0), 255)  # viridis' dark purple
    assert _colour(scene, f"node_{hottest}") == (*colours.heat_colour(1.0), 255)  # viridis' yellow
    extras = _node_extras(scene, f"node_{hottest}")
    assert extras["id"] == hottest and extras["depth"] == structure.nodes[hottest]["depth"]
    assert extras["values"]["betweenness"] == pytest.approx(values[hottest], rel=1e-8)
    assert extras["values"]["degree"] == result.analysis["degree"][hottest]

    # every edge is one closed tube, in the colour of its child's value
    tubes = _tube_edges(scene)
    assert sorted(e for edges in tubes.values() for e in edges) == sorted(structure.edges)
    low, high = min(values.values()), max(values.values())
    for name, edges in tubes.items():
        mesh = scene.geometry[scene.graph[name][1]]
        assert mesh.is_watertight and len(mesh.split(only_watertight=False)) == len(edges)
        for _, v in edges:
            level_ = round((values[v] - low) / (high - low) * (gltf.HEAT_LEVELS - 1))
            assert name == f"edges_value_{level_:02d}"
            assert _colour(scene, name) == (*colours.heat_colour(level_ / (gltf.HEAT_LEVELS - 1)), 255)


def test_root_and_terminal_markers_leave_the_value_spheres_visible(tmp_path):
    result = make_result()
    path, = gltf.write(result, tmp_path)
    scene = trimesh.load(path)
    root, terminal = result.structure.graph["roots"][0], result.terminals.nodes[0]
    sphere = scene.geometry[scene.graph[f"node_{root}"][1]]
    sphere_top = sphere.vertices[:, 1].max()
    cone = scene.geometry[scene.graph[f"root_{root}"][1]]
    assert cone.vertices[:, 1].min() > sphere_top  # the cone floats above the sphere
    ring = scene.geometry[scene.graph[f"terminal_{terminal}"][1]]
    inner = np.hypot(ring.vertices[:, 0], ring.vertices[:, 2]).min()
    assert inner > np.hypot(sphere.vertices[:, 0], sphere.vertices[:, 2]).max()  # the sphere shows through the ring


def test_waypoints_get_no_ring(tmp_path):
    result = make_result(waypoints=WAYPOINTS)
    header, _ = read_glb(gltf.write(result, tmp_path)[0])
    assert sorted(_children(header, "terminals")) == sorted(f"terminal_{t}" for t in TERMINALS)
    scene = trimesh.load(tmp_path / "structure.glb")
    kept = [w for w in WAYPOINTS if w in result.structure]
    assert kept and all(_node_extras(scene, f"node_{w}")["terminal"] is False for w in kept)


def test_without_analysis_edges_show_the_tree_depth(tmp_path):
    result = make_result(analysis=False)
    path, = gltf.write(result, tmp_path)
    scene = trimesh.load(path)
    assert not [n for n in scene.graph.nodes_geometry if n.startswith("node_")]
    tubes = _tube_edges(scene)
    for name, edges in tubes.items():
        depths = {result.structure.nodes[v]["depth"] for _, v in edges}
        assert len(depths) == 1 and name == f"edges_depth_{depths.pop()}"
        assert _colour(scene, name) == (*colours.depth_colour(result.structure.nodes[edges[0][1]]["depth"]), 255)
    assert len(tubes) == max(d for _, d in result.structure.nodes(data="depth"))


def test_navmesh_is_a_translucent_green_layer(tmp_path):
    mesh = two_floor_mesh()
    navmesh = real_navmesh(mesh)
    result = make_result(navmesh=navmesh)
    path, = gltf.write(result, tmp_path)
    scene = trimesh.load(path)
    surface = scene.geometry[scene.graph["navmesh_surface"][1]]
    assert len(surface.faces) == len(navmesh.detail_triangles) > 0
    assert np.allclose(np.sort(surface.vertices, axis=0), np.sort(np.asarray(navmesh.detail_vertices), axis=0), atol=1e-5)
    colour = _colour(scene, "navmesh_surface")
    assert colour[:3] == colours.NAVMESH_COLOUR and colour[3] < 255
    header, _ = read_glb(path)
    material = next(m for m in header["materials"] if m.get("name") == "navmesh_surface")
    assert material["alphaMode"] == "BLEND"


def test_regions_and_chokepoints_groups(tmp_path):
    from tests.test_regions import chokepoints, regions, sample_run

    _, result = sample_run("two_rooms_one_door")
    path, = gltf.write(result, tmp_path)
    header, _ = read_glb(path)
    rooms, doors = regions(result), chokepoints(result)
    assert _children(header, "regions") == [f"region_{r['id']}" for r in rooms]
    assert _children(header, "chokepoints") == [f"chokepoint_{c['id']}" for c in doors]
    scene = trimesh.load(path)
    palette = colours.region_colours(rooms)
    navmesh = result.context.navmesh
    for record in rooms:
        name = f"region_{record['id']}"
        assert _colour(scene, name) == (*palette[record["id"]], 255)
        assert _node_extras(scene, name)["area"] == pytest.approx(record["area"])
        transform, geometry = scene.graph[name]
        assert np.allclose(transform[:3, 3], [0.0, gltf.REGION_LIFT, 0.0])  # just above the navmesh
        assert len(scene.geometry[geometry].faces) == int(np.isin(navmesh.detail_polygon, record["polygons"]).sum())
    assert _colour(scene, "region_0") != _colour(scene, "region_1")  # neighbours differ
    (door,) = doors
    bar = scene.geometry[scene.graph["chokepoint_0"][1]]
    transform, _ = scene.graph["chokepoint_0"]
    lift = gltf.NODE_RADIUS * 0.5
    assert np.allclose(transform[:3, 3], np.add(door["position"], [0.0, lift, 0.0]))
    portal = np.asarray(door["portal"])
    length = np.ptp(bar.vertices @ (portal[1] - portal[0]) / np.linalg.norm(portal[1] - portal[0]))
    assert length == pytest.approx(np.linalg.norm(portal[1] - portal[0]), rel=1e-6)  # the bar spans the portal
    assert _colour(scene, "chokepoint_0") == (*colours.CHOKEPOINT_COLOUR, 255)
    assert _node_extras(scene, "chokepoint_0")["width"] == pytest.approx(door["width"])


VALIDATOR_MODULES = PROJECT / ".venv" / "node" / "node_modules"
"""Where `make test` installs the Khronos glTF validator (npm package gltf-validator)."""


def assert_khronos_valid(path: Path) -> None:
    """The Khronos validator finds no error and no warning in ``path`` (skips when it is not installed)."""
    node = shutil.which("node")
    if node is None or not (VALIDATOR_MODULES / "gltf-validator").is_dir():
        pytest.skip("the Khronos glTF validator is not installed (node and npm's gltf-validator in "
                    f"{VALIDATOR_MODULES}): `make test` installs it, or run "
                    f"npm install --prefix {VALIDATOR_MODULES.parent} gltf-validator")
    report = subprocess.run([node, str(PROJECT / "tests" / "validate_gltf.js"), str(path)],
                            capture_output=True, text=True, env={**os.environ, "NODE_PATH": str(VALIDATOR_MODULES)})
    assert report.returncode == 0, report.stderr
    issues = json.loads(report.stdout)["issues"]
    serious = [m for m in issues["messages"] if m["severity"] <= 1]  # 0 error, 1 warning
    assert issues["numErrors"] == 0 and issues["numWarnings"] == 0, serious


def test_demo_glb_passes_the_khronos_validator(tmp_path):
    out = tmp_path / "demo"
    done = subprocess.run([sys.executable, "-m", "g2s_core.cli", "demo", "-o", str(out), "--format", "glb", "--quiet"],
                          capture_output=True, text=True, cwd=PROJECT)
    assert done.returncode == 0, done.stderr
    assert_khronos_valid(out / "structure.glb")
    header, _ = read_glb(out / "structure.glb")
    assert [header["nodes"][i]["name"] for i in header["scenes"][0]["nodes"]] == list(gltf.GROUPS)
    for group in ("level", "navmesh", "structure", "roots", "terminals", "loops"):  # the demo keeps loops
        assert _children(header, group), f"the demo's {group} group is empty"


def test_regions_glb_passes_the_khronos_validator(tmp_path):
    from tests.test_regions import sample_run

    _, result = sample_run("loop_of_four_rooms")
    path, = gltf.write(result, tmp_path)
    assert_khronos_valid(path)
    header, _ = read_glb(path)
    assert len(_children(header, "regions")) == 4 and len(_children(header, "chokepoints")) == 4


TUBE_SEGMENTS = {
    "up": [(0.0, 0.0, 0.0), (0.0, 2.5, 0.0)],
    "down": [(0.0, 2.5, 0.0), (0.0, 0.0, 0.0)],
    "along +z, the cylinders' own axis": [(1.0, 2.0, 3.0), (1.0, 2.0, 7.0)],
    "along -z": [(1.0, 2.0, 7.0), (1.0, 2.0, 3.0)],
    "along +x": [(-3.0, 0.5, 0.0), (4.0, 0.5, 0.0)],
    "along -x": [(4.0, 0.5, 0.0), (-3.0, 0.5, 0.0)],
    "a ramp": [(10.0, 0.0, -4.0), (13.5, 1.2, -1.0)],
    "the same ramp down": [(13.5, 1.2, -1.0), (10.0, 0.0, -4.0)],
    "long, far from the origin": [(-812.25, 31.0, 640.5), (377.0, -12.75, -95.125)],
    "a micrometre": [(5.0, 1.0, 5.0), (5.0, 1.0, 5.000001)],
}


def test_tubes_are_the_cylinders_trimesh_makes():
    """Built together with numpy, each tube has trimesh.creation.cylinder's vertices (in its order) and faces."""
    segments = np.asarray(list(TUBE_SEGMENTS.values()))
    vertices, faces = gltf._cylinders(segments, 0.1)
    assert vertices.shape[0] == len(segments)
    for (label, segment), tube in zip(TUBE_SEGMENTS.items(), vertices):
        expected = trimesh.creation.cylinder(0.1, sections=gltf.TUBE_SIDES, segment=segment)
        assert tube.shape == expected.vertices.shape and np.array_equal(faces, expected.faces), label
        assert np.allclose(tube, expected.vertices, rtol=0.0, atol=1e-5), label
        assert trimesh.Trimesh(tube, faces).is_volume, label  # closed, faces pointing out


def test_one_tube_per_edge_of_nonzero_length():
    import networkx as nx

    graph = nx.DiGraph()
    for node, segment in enumerate(TUBE_SEGMENTS.values()):
        graph.add_node(2 * node, pos=segment[0])
        graph.add_node(2 * node + 1, pos=segment[1])
    graph.add_node(99, pos=graph.nodes[4]["pos"])
    edges = [(0, 1), (4, 99), (2, 3), (6, 7), (99, 4)]  # 4 and 99 are the same point
    tubes = gltf._tubes(graph, edges, 0.1)
    drawn = [(0, 1), (2, 3), (6, 7)]
    expected = trimesh.util.concatenate([
        trimesh.creation.cylinder(0.1, sections=gltf.TUBE_SIDES, segment=[graph.nodes[u]["pos"], graph.nodes[v]["pos"]])
        for u, v in drawn])
    assert np.array_equal(tubes.faces, expected.faces)
    assert np.allclose(tubes.vertices, expected.vertices, rtol=0.0, atol=1e-5)
    assert len(tubes.split(only_watertight=True)) == len(drawn)
    assert gltf._tubes(graph, [(4, 99)], 0.1).is_empty


def test_two_runs_write_the_same_glb_bytes(tmp_path):
    from g2s_plugins.samples.levels import load_sample
    from tests.test_regions import run

    level = load_sample("loop_of_four_rooms")
    for name in ("a", "b"):
        (tmp_path / name).mkdir()
    written = [gltf.write(run(level), tmp_path / name)[0] for name in ("a", "b")]
    assert written[0].read_bytes() == written[1].read_bytes()
    header, _ = read_glb(written[0])
    assert _children(header, "chokepoints") and [m for m in header["meshes"] if m["name"].startswith("edges")]


def test_a_level_far_from_the_origin_keeps_its_detail_in_the_glb(tmp_path):
    """glTF vertices are single precision (6 cm steps 1,000 km out): the level's meshes are written in its local
    frame and their nodes carry the local origin, which glTF writes in double precision."""
    move = np.array([1_000_123.456, 7.0, -2_000_456.789])
    mesh = generate_level("sample:loop_of_four_rooms")
    mesh.vertices = mesh.vertices + move
    registry = installed()
    plan = pipeline.plan(load_config(PRESETS_DIR / "demo.yaml"), registry, "demo")
    result = pipeline.run(plan, registry, mesh, "far", mesh_sha256(mesh))
    gltf.write(result, tmp_path)
    header, blob = read_glb(tmp_path / gltf.GLB_FILE)
    node = next(n for n in header["nodes"] if n.get("name") == "level_mesh")
    origin = np.array(node["matrix"][12:15])
    assert origin.tolist() == [1_000_000.0, 0.0, -2_000_000.0]
    positions = header["meshes"][node["mesh"]]["primitives"][0]["attributes"]["POSITION"]
    written = accessor(header, blob, positions).astype(np.float64) + origin
    assert np.abs(written - mesh.vertices).max() < 1e-4
    tubes = [n for n in header["nodes"] if n.get("name", "").startswith("edges")]
    assert tubes and all(n["matrix"][12:15] == origin.tolist() for n in tubes)
    assert_khronos_valid(tmp_path / gltf.GLB_FILE)
