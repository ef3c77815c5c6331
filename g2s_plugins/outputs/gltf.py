"""``structure.glb``: the level, its navmesh and the structure as one binary glTF scene.

The scene is a handful of named group nodes (names are stable, so scripts and
viewers' outliners find them), each holding its objects:

``level``
    ``level_mesh``: the input mesh, grey.
``navmesh``
    ``navmesh_surface``: the navmesh's detail triangles, translucent green
    (empty without a navmesh).
``regions``
    With the ``regions`` analyzer, ``region_<id>``: the navmesh triangles of
    each region in its colour (:func:`colours.region_colours`: neighbouring
    regions differ), the group raised :data:`REGION_LIFT` above the navmesh;
    extras ``id``, ``area``, ``floor``, ``centroid``, ``neighbours``.
``structure``
    The final structure's edges as thin tubes (radius 0.2 r, eight sides), so
    they render in every viewer and engine (glTF lines are one pixel wide and
    Blender drops loose edges). One mesh per colour, ``edges_<colour>``: the
    child's first analysis value on viridis in :data:`HEAT_LEVELS` steps
    (``edges_value_07``), else the child's tree depth (``edges_depth_1``: red
    = depth 1, yellow = 2, green, cyan, blue, magenta, orange, violet,
    repeating), else one grey (``edges``, runs stopped before step 4). Each
    mesh node's extras list its ``edges`` ``[u, v]`` in the order of its tubes
    and ``colour_by``. With analysis values, ``node_<id>`` is a sphere
    (radius 0.4 r) on every structure node in its value's colour.
``roots``
    ``root_<id>``: a black cone pointing down at each root, floating above the
    node so that the node's sphere stays visible.
``terminals``
    ``terminal_<id>``: a vermilion ring lying flat around each terminal, wider
    than the node's sphere, which shows through it.
``chokepoints``
    With the ``chokepoints`` analyzer, ``chokepoint_<id>``: a near-black bar
    (radius 0.3 r) across each chokepoint's portal, placed at the
    chokepoint's position; extras its record (``width``, ``score``,
    ``traffic``, ``regions``, ``articulation``, ``portal`` ...).
``loops``
    The loop edges of a structure with loops (config ``loops:``, see
    :mod:`g2s_plugins.loops.spanner`): near-black tubes, mesh ``loop_edges`` whose extras
    list its ``edges``; empty for a tree.

Groups of analyzers that did not run are empty.
*r* is the agent radius. The ``structure``, ``roots``, ``terminals``,
``chokepoints`` and ``loops`` groups are raised by 0.4 r (a node sphere's radius) so that nothing
sinks into the floor; their objects sit at the nodes' exact positions inside
the group. Every ``node_``, ``root_`` and ``terminal_`` node's extras hold ``id``,
``depth``, ``root``, ``terminal`` and ``values`` (analysis key -> value).
Coordinates are metres, Y up, which is glTF's convention. glTF holds vertices
in single precision, so a level far from the origin keeps its meshes (level,
navmesh, regions, tubes) in its local frame (:mod:`g2s_plugins.local_frame`,
the navmesh's rule; 0 near the origin) and their nodes carry the local origin
as their translation, which glTF writes in double precision like every node's.
"""

from __future__ import annotations

import functools
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import networkx as nx
import numpy as np
import trimesh
from trimesh.visual.material import PBRMaterial
from trimesh.visual.texture import TextureVisuals

from g2s_core.model import RunResult
from g2s_plugins.local_frame import LocalFrame
from g2s_plugins.outputs import colours
from g2s_plugins.outputs.common import (
    agent_value,
    edge_list,
    feature_records,
    final_graph,
    is_loop_edge,
    number,
    roots_of,
    terminal_ids,
    triangle_regions,
)
from g2s_plugins.outputs.files import atomic_write

GLB_FILE = "structure.glb"
GROUPS = ("level", "navmesh", "regions", "structure", "roots", "terminals", "chokepoints", "loops")
"""The scene's group nodes, in order."""
LIFTED_GROUPS = ("structure", "roots", "terminals", "chokepoints", "loops")
REGION_LIFT = 0.02
"""The regions group sits this far (m) above the navmesh so that both stay visible."""
HEAT_LEVELS = 32
"""Analysis colours are quantised to this many steps so that edges and spheres share meshes."""
TUBE_RADIUS, TUBE_SIDES = 0.2, 8
NODE_RADIUS = 0.4
RING_RADIUS, RING_THICKNESS = 0.65, 0.08
BAR_RADIUS = 0.3
CONE_RADIUS, CONE_HEIGHT, CONE_GAP = 0.5, 1.4, 0.1
"""Sizes in agent radii."""
MIN_SEGMENT = 1e-9
"""An edge shorter than this (m) gets no tube, and a chokepoint's portal shorter than this a short upright bar."""


def write(result: RunResult, outdir: Path) -> list[Path]:
    """``structure.glb`` in ``outdir``: :func:`build_scene` as binary glTF."""
    scene = build_scene(result)
    data = scene.export(file_type="glb")
    return [atomic_write(outdir / GLB_FILE, data)]


def build_scene(result: RunResult) -> trimesh.Scene:
    """The scene described in the module doc."""
    scene = trimesh.Scene()
    scene.metadata["g2s"] = {"mesh_name": result.mesh_name, "mesh_sha256": result.mesh_sha256}
    radius = agent_value(result, "radius", 0.5)
    for group in GROUPS:
        lift = NODE_RADIUS * radius if group in LIFTED_GROUPS else REGION_LIFT if group == "regions" else 0.0
        scene.graph.update(frame_to=group, frame_from=scene.graph.base_frame, matrix=_translation((0.0, lift, 0.0)))
    mesh = result.context.mesh
    frame = LocalFrame(() if mesh is None else mesh.vertices)
    _add_surfaces(scene, result, frame)
    _add_regions(scene, result, frame)
    _add_chokepoints(scene, result, radius)
    _, graph = final_graph(result)
    if graph is None:
        return scene
    keys = list(result.analysis)
    heat = _heat_levels(graph, result.analysis[keys[0]]) if keys else {}
    colour_by = keys[0] if keys else ("depth" if graph.is_directed() else "none")
    loops = [e for e in edge_list(graph) if graph.is_directed() and is_loop_edge(graph, *e)]
    for name, (rgb, edges) in _edge_classes(graph, heat, set(loops)).items():
        tubes = _tubes(graph, edges, TUBE_RADIUS * radius)
        tubes.visual = _material(name, rgb)
        _place(scene, "structure", name, tubes, _in_frame(tubes, frame),
               {"edges": [list(e) for e in edges], "colour_by": colour_by})
    if loops:
        tubes = _tubes(graph, loops, TUBE_RADIUS * radius)
        tubes.visual = _material("loop_edges", colours.LOOP_COLOUR)
        _place(scene, "loops", "loop_edges", tubes, _in_frame(tubes, frame), {"edges": [list(e) for e in loops]})
    _add_markers(scene, result, graph, heat, radius)
    return scene


def _in_frame(geometry: trimesh.Trimesh, frame: LocalFrame) -> np.ndarray:
    """Moves ``geometry``'s world-coordinate vertices into ``frame``; returns where its node goes (the frame's
    origin). Near the origin the vertices are left as they are."""
    if frame.shifted:
        geometry.vertices = frame.to_local(np.asarray(geometry.vertices, dtype=np.float64))
    return frame.origin


def _add_surfaces(scene: trimesh.Scene, result: RunResult, frame: LocalFrame) -> None:
    mesh = result.context.mesh
    if mesh is not None and len(mesh.faces):
        level = trimesh.Trimesh(np.asarray(mesh.vertices), np.asarray(mesh.faces), process=False)
        level.visual = _material("level_mesh", colours.MESH_COLOUR)
        _place(scene, "level", "level_mesh", level, _in_frame(level, frame))
    navmesh = result.context.navmesh
    if navmesh is not None and len(navmesh.detail_triangles):
        surface = trimesh.Trimesh(np.asarray(navmesh.detail_vertices, dtype=np.float64),
                                  np.asarray(navmesh.detail_triangles, dtype=np.int64), process=False)
        surface.visual = _material("navmesh_surface", colours.NAVMESH_COLOUR, alpha=colours.NAVMESH_ALPHA)
        _place(scene, "navmesh", "navmesh_surface", surface, _in_frame(surface, frame))


def _add_regions(scene: trimesh.Scene, result: RunResult, frame: LocalFrame) -> None:
    """``region_<id>`` under ``regions``: each region's navmesh detail triangles in its colour."""
    regions = triangle_regions(result)
    if regions is None:
        return
    navmesh = result.context.navmesh
    vertices = np.asarray(navmesh.detail_vertices, dtype=np.float64)
    triangles = np.asarray(navmesh.detail_triangles, dtype=np.int64)
    records = feature_records(result, "regions")
    palette = colours.region_colours(records)
    for record in records:
        faces = triangles[regions == record["id"]]
        if not len(faces):
            continue
        used, local = np.unique(faces, return_inverse=True)
        part = trimesh.Trimesh(vertices[used], local.reshape(-1, 3), process=False)
        name = f"region_{record['id']}"
        part.visual = _material(name, palette[record["id"]])
        extras = {k: record[k] for k in ("id", "area", "floor", "centroid", "neighbours")}
        _place(scene, "regions", name, part, _in_frame(part, frame), extras)


def _add_chokepoints(scene: trimesh.Scene, result: RunResult, radius: float) -> None:
    """``chokepoint_<id>`` under ``chokepoints``: a bar across each chokepoint's portal, its record in the extras."""
    records = feature_records(result, "chokepoints")
    if not records:
        return
    positions = np.asarray([record["position"] for record in records], dtype=np.float64).reshape(-1, 3)
    portals = np.asarray([record["portal"] for record in records], dtype=np.float64) - positions[:, None]
    points = np.linalg.norm(portals[:, 1] - portals[:, 0], axis=1) <= MIN_SEGMENT
    portals[points] = [[0.0, -BAR_RADIUS * radius, 0.0], [0.0, BAR_RADIUS * radius, 0.0]]  # a short upright bar each
    bars, faces = _cylinders(portals, BAR_RADIUS * radius)
    for record, position, vertices in zip(records, positions, bars):
        bar = trimesh.Trimesh(vertices, faces, process=False)
        bar.visual = _material("chokepoint", colours.CHOKEPOINT_COLOUR)
        name = f"chokepoint_{record['id']}"
        _place(scene, "chokepoints", name, bar, position, dict(record), geometry_name=name)


def _add_markers(scene: trimesh.Scene, result: RunResult, graph: nx.Graph, heat: dict[int, int], radius: float) -> None:
    """Value spheres on the structure's nodes, cones over the roots, rings around the terminals."""
    terminals = set(terminal_ids(result))
    shapes: dict[str, trimesh.Trimesh] = {}

    def shape(name: str, make, rgb: colours.RGB) -> trimesh.Trimesh:
        if name not in shapes:
            shapes[name] = make()
            shapes[name].visual = _material(name, rgb)
        return shapes[name]

    def info(node: int) -> dict[str, Any]:
        attrs = graph.nodes[node] if node in graph else {}
        return {
            "id": int(node),
            "depth": None if attrs.get("depth") is None else int(attrs["depth"]),
            "root": None if attrs.get("root") is None else int(attrs["root"]),
            "terminal": int(node) in terminals,
            "values": {k: number(v[node]) for k, v in result.analysis.items() if node in v},
        }

    for node in sorted(graph.nodes) if heat else ():
        level = heat[node]
        ball = shape(f"sphere_value_{level:02d}", lambda: trimesh.creation.icosphere(2, NODE_RADIUS * radius),
                     _step_colour(level))
        _place(scene, "structure", f"node_{node}", ball, graph.nodes[node]["pos"], info(node))
    source = result.graph if result.graph is not None else graph
    for node in sorted(t for t in terminals if t in source):
        ring = shape("ring_terminal", lambda: _ring(radius), colours.TERMINAL_COLOUR)
        _place(scene, "terminals", f"terminal_{node}", ring, source.nodes[node]["pos"], info(node))
    for node in roots_of(graph):
        cone = shape("cone_root", lambda: _cone(radius), colours.ROOT_COLOUR)
        _place(scene, "roots", f"root_{node}", cone, graph.nodes[node]["pos"], info(node))


def _place(scene: trimesh.Scene, group: str, name: str, geometry: trimesh.Trimesh, position: Sequence[float],
           extras: dict[str, Any] | None = None, geometry_name: str | None = None) -> None:
    """A node ``name`` under ``group`` at ``position`` showing ``geometry``, shared by ``geometry_name``
    (default: its material's name)."""
    geometry_name = geometry_name or geometry.visual.material.name
    scene.geometry[geometry_name] = geometry
    scene.graph.update(frame_to=name, frame_from=group, matrix=_translation(position), geometry=geometry_name,
                       metadata=extras or {})


def _translation(position: Sequence[float]) -> np.ndarray:
    matrix = np.eye(4)
    matrix[:3, 3] = np.asarray(position, dtype=np.float64)
    return matrix


def _ring(radius: float) -> trimesh.Trimesh:
    """A torus lying flat (in the XZ plane) around the origin."""
    lying = trimesh.transformations.rotation_matrix(np.pi / 2, (1.0, 0.0, 0.0))
    return trimesh.creation.torus(RING_RADIUS * radius, RING_THICKNESS * radius, 24, 8, transform=lying)


def _cone(radius: float) -> trimesh.Trimesh:
    """A cone pointing down (-Y) whose tip floats just above a node sphere at the origin."""
    cone = trimesh.creation.cone(CONE_RADIUS * radius, CONE_HEIGHT * radius, sections=16)
    flip = trimesh.transformations.rotation_matrix(np.pi / 2, (1.0, 0.0, 0.0))  # +Z tip -> -Y tip
    cone.apply_transform(flip)
    cone.apply_translation((0.0, (CONE_HEIGHT + NODE_RADIUS + CONE_GAP) * radius, 0.0))
    return cone


def _material(name: str, rgb: colours.RGB, alpha: float = 1.0) -> TextureVisuals:
    factor = [int(rgb[0]), int(rgb[1]), int(rgb[2]), int(round(alpha * 255))]
    material = PBRMaterial(
        name=name,
        baseColorFactor=factor,
        metallicFactor=0.0,
        roughnessFactor=0.9,
        alphaMode="BLEND" if alpha < 1.0 else "OPAQUE",
        doubleSided=True,
    )
    return TextureVisuals(material=material)


def _heat_levels(graph: nx.Graph, values: dict[int, float]) -> dict[int, int]:
    """Each node's analysis value as a colour step 0 .. HEAT_LEVELS - 1."""
    nodes = sorted(graph.nodes)
    t = colours.normalise(values.get(n, float("nan")) for n in nodes)
    return {n: int(round(x * (HEAT_LEVELS - 1))) for n, x in zip(nodes, t)}


@functools.cache
def _step_colour(level: int) -> colours.RGB:
    """The colour of analysis step ``level`` (0 .. HEAT_LEVELS - 1), asked of the colour map once per step
    rather than once per edge and node (that took most of the writer's time on a 100k-polygon level)."""
    return colours.heat_colour(level / (HEAT_LEVELS - 1))


def _edge_classes(
    graph: nx.Graph, heat: dict[int, int], loops: set[tuple[int, int]]
) -> dict[str, tuple[colours.RGB, list[tuple[int, int]]]]:
    """Mesh name -> (colour, edges) of the structure's edges but ``loops``, by the child's value step, depth, or all grey."""
    classes: dict[str, tuple[colours.RGB, list[tuple[int, int]]]] = {}
    for edge in edge_list(graph):
        if edge in loops:
            continue
        child = edge[1]
        if heat:
            name, rgb = f"edges_value_{heat[child]:02d}", _step_colour(heat[child])
        elif graph.is_directed():
            depth = (max(int(graph.nodes[child].get("depth", 1)), 1) - 1) % len(colours.DEPTH_COLOURS) + 1
            name, rgb = f"edges_depth_{depth}", colours.depth_colour(depth)
        else:
            name, rgb = "edges", colours.GRAPH_COLOUR
        classes.setdefault(name, (rgb, []))[1].append(edge)
    return dict(sorted(classes.items()))


def _tubes(graph: nx.Graph, edges: list[tuple[int, int]], radius: float) -> trimesh.Trimesh:
    """One closed tube per edge (edges shorter than :data:`MIN_SEGMENT` give none), as one mesh."""
    segments = np.asarray([(graph.nodes[u]["pos"], graph.nodes[v]["pos"]) for u, v in edges], dtype=np.float64)
    segments = segments.reshape(-1, 2, 3)
    segments = segments[np.linalg.norm(segments[:, 1] - segments[:, 0], axis=1) > MIN_SEGMENT]
    if not len(segments):
        return trimesh.Trimesh()
    vertices, faces = _cylinders(segments, radius)
    numbered = faces + vertices.shape[1] * np.arange(len(segments))[:, None, None]  # each tube into its own vertices
    return trimesh.Trimesh(vertices.reshape(-1, 3), numbered.reshape(-1, 3), process=False)


def _cylinders(segments: np.ndarray, radius: float) -> tuple[np.ndarray, np.ndarray]:
    """Closed cylinders of ``radius`` (m) and :data:`TUBE_SIDES` sides along ``segments`` ((n, 2, 3) m, none
    shorter than :data:`MIN_SEGMENT`): their vertices (n, V, 3) m and the faces (F, 3) that index each one's V.

    Each is the mesh ``trimesh.creation.cylinder(radius, sections=TUBE_SIDES, segment=...)`` makes (the same
    vertices in the same order, the same faces), built for all segments at once: one call of it per
    segment took more than half the writer's time on a 100k-polygon level.
    """
    vertices, faces = _unit_cylinder()
    axes = segments[:, 1] - segments[:, 0]
    scale = np.empty((len(segments), 1, 3))
    scale[:, :, :2] = radius
    scale[:, :, 2] = np.linalg.norm(axes, axis=1)[:, None]
    rotated = (vertices * scale) @ _rotations_from_z(axes).transpose(0, 2, 1)
    return rotated + (segments[:, 0] + axes * 0.5)[:, None], faces


@functools.cache
def _unit_cylinder() -> tuple[np.ndarray, np.ndarray]:
    """The vertices (V, 3) and faces (F, 3) of trimesh's cylinder of radius 1 and height 1 with
    :data:`TUBE_SIDES` sides, its axis Z, centred on the origin."""
    cylinder = trimesh.creation.cylinder(1.0, 1.0, sections=TUBE_SIDES)
    vertices, faces = np.array(cylinder.vertices), np.array(cylinder.faces)
    vertices.flags.writeable = faces.flags.writeable = False  # shared by every call, and by every bar's mesh
    return vertices, faces


def _rotations_from_z(vectors: np.ndarray) -> np.ndarray:
    """(n, 3, 3) rotations taking +Z onto the directions of ``vectors`` (n, 3).

    Built as ``trimesh.geometry.align_vectors`` builds its rotation (from the two vectors' SVD bases, each
    made right-handed), so that each tube is turned about its axis as trimesh's own cylinder would be.
    """
    bases = np.linalg.svd(np.concatenate([[[0.0, 0.0, 1.0]], vectors])[:, :, None])[0]
    bases[np.linalg.det(bases) < 0, :, -1] *= -1.0
    return bases[1:] @ bases[0].T
