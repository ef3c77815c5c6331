"""``structure.glb``: the level, its navmesh and the structure as one binary glTF scene.

Scene nodes (names are stable, so scripts can find them):

``mesh``
    The input mesh, grey.
``navmesh``
    The navmesh's detail triangles, translucent green (only with a navmesh).
``structure``
    The final structure's edges as glTF LINES, one colour per edge: the
    colour of the child's tree depth (red = depth 1, yellow = 2, green, cyan,
    blue, magenta, orange, violet, repeating), or, when the run has analysis
    values, the child's first analysis value on the green -> yellow -> red
    scale (min-max over the structure). Undirected graphs (runs stopped
    before step 4) are drawn grey. Loop edges (structures with loops, see
    :mod:`g2s_core.loops`) are near-black whatever the colouring. Its extras
    list the edges ``[u, v]`` in the order of the line segments, what the
    colours show and, when there are any, the ``loop_edges``.
``root_<id>``
    A red sphere on each root.
``terminal_<id>``
    A blue sphere on each terminal (smaller than a root's).
``node_<id>``
    With analysis values only: a small sphere on every structure node in its
    value's colour.

Every sphere node's extras hold ``id``, ``depth``, ``root``, ``terminal`` and
``values`` (analysis key -> value). Sphere radii follow the agent radius
(root 0.6 r, terminal 0.45 r, node 0.3 r). Coordinates are metres, Y up,
which is glTF's convention.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import networkx as nx
import numpy as np
import trimesh
from trimesh.path.entities import Line
from trimesh.visual.material import PBRMaterial
from trimesh.visual.texture import TextureVisuals

from g2s_core.model import RunResult
from g2s_plugins.outputs import colours
from g2s_plugins.outputs.common import agent_value, edge_list, final_graph, is_loop_edge, number, roots_of, terminal_ids
from g2s_plugins.outputs.files import atomic_write

GLB_FILE = "structure.glb"
HEAT_LEVELS = 32
"""Analysis colours are quantised to this many steps so that node spheres share geometry."""


def write(result: RunResult, outdir: Path) -> list[Path]:
    scene = build_scene(result)
    data = scene.export(file_type="glb")
    return [atomic_write(outdir / GLB_FILE, data)]


def build_scene(result: RunResult) -> trimesh.Scene:
    """The scene described in the module doc."""
    scene = trimesh.Scene()
    scene.metadata["g2s"] = {"mesh_name": result.mesh_name, "mesh_sha256": result.mesh_sha256}
    mesh = result.context.mesh
    if mesh is not None and len(mesh.faces):
        level = trimesh.Trimesh(np.asarray(mesh.vertices), np.asarray(mesh.faces), process=False)
        level.visual = _material("mesh", colours.MESH_COLOUR)
        scene.add_geometry(level, node_name="mesh", geom_name="mesh")
    navmesh = result.context.navmesh
    if navmesh is not None and len(navmesh.detail_triangles):
        surface = trimesh.Trimesh(
            np.asarray(navmesh.detail_vertices, dtype=np.float64),
            np.asarray(navmesh.detail_triangles, dtype=np.int64),
            process=False,
        )
        surface.visual = _material("navmesh", colours.NAVMESH_COLOUR, alpha=colours.NAVMESH_ALPHA)
        scene.add_geometry(surface, node_name="navmesh", geom_name="navmesh")

    _, graph = final_graph(result)
    if graph is None:
        return scene
    radius = agent_value(result, "radius", 0.5)
    keys = list(result.analysis)
    heat = _heat_levels(graph, result.analysis[keys[0]]) if keys else {}
    edges = edge_list(graph)
    if edges:
        metadata: dict[str, Any] = {"edges": [list(e) for e in edges], "colour_by": keys[0] if keys else
                                    ("depth" if graph.is_directed() else "none")}
        loops = [list(e) for e in edges if graph.is_directed() and is_loop_edge(graph, *e)]
        if loops:
            metadata["loop_edges"] = loops
        scene.add_geometry(_lines(graph, edges, heat), node_name="structure", geom_name="structure", metadata=metadata)

    def info(node: int) -> dict[str, Any]:
        attrs = graph.nodes[node] if node in graph else {}
        return {
            "id": int(node),
            "depth": None if attrs.get("depth") is None else int(attrs["depth"]),
            "root": None if attrs.get("root") is None else int(attrs["root"]),
            "terminal": int(node) in terminal_set,
            "values": {k: number(result.analysis[k][node]) for k in keys if node in result.analysis[k]},
        }

    terminal_set = set(terminal_ids(result))
    spheres: dict[str, trimesh.Trimesh] = {}

    def sphere(kind: str, size: float, colour: colours.RGB) -> str:
        name = f"sphere_{kind}"
        if name not in spheres:
            ball = trimesh.creation.icosphere(subdivisions=2, radius=size)
            ball.visual = _material(name, colour)
            spheres[name] = ball
        return name

    placements: list[tuple[str, str, np.ndarray, dict[str, Any]]] = []
    if heat:
        for node in sorted(graph.nodes):
            level = heat[node]
            geom = sphere(f"heat_{level:02d}", 0.3 * radius, colours.heat_colour(level / (HEAT_LEVELS - 1)))
            placements.append((f"node_{node}", geom, np.asarray(graph.nodes[node]["pos"]), info(node)))
    source = result.graph if result.graph is not None else graph
    for node in sorted(terminal_set):
        if node in source:
            geom = sphere("terminal", 0.45 * radius, colours.TERMINAL_COLOUR)
            placements.append((f"terminal_{node}", geom, np.asarray(source.nodes[node]["pos"]), info(node)))
    for node in roots_of(graph):
        geom = sphere("root", 0.6 * radius, colours.ROOT_COLOUR)
        placements.append((f"root_{node}", geom, np.asarray(graph.nodes[node]["pos"]), info(node)))
    for name, ball in spheres.items():
        scene.geometry[name] = ball
    for node_name, geom, position, extras in placements:
        transform = np.eye(4)
        transform[:3, 3] = np.asarray(position, dtype=np.float64)
        scene.graph.update(frame_to=node_name, frame_from=scene.graph.base_frame, matrix=transform,
                           geometry=geom, metadata=extras)
    return scene


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


def _lines(graph: nx.Graph, edges: list[tuple[int, int]], heat: dict[int, int]) -> trimesh.path.Path3D:
    index = {node: i for i, node in enumerate(sorted(graph.nodes))}
    vertices = np.asarray([graph.nodes[n]["pos"] for n in sorted(graph.nodes)], dtype=np.float64)
    entities = [Line(points=[index[u], index[v]]) for u, v in edges]
    line_colours = []
    for parent, child in edges:
        if graph.is_directed() and is_loop_edge(graph, parent, child):
            rgb = colours.LOOP_COLOUR
        elif heat:
            rgb = colours.heat_colour(heat[child] / (HEAT_LEVELS - 1))
        elif graph.is_directed():
            rgb = colours.depth_colour(int(graph.nodes[child].get("depth", 1)))
        else:
            rgb = colours.GRAPH_COLOUR
        line_colours.append([*rgb, 255])
    return trimesh.path.Path3D(entities=entities, vertices=vertices,
                               colors=np.asarray(line_colours, dtype=np.uint8), process=False)
