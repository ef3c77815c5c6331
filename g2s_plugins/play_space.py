"""The play space (``graph.params.play_points``): the initial graph cut to the connected walkable areas holding a
play point, right where it is built, so that the later stages see that space alone.

A level's file often holds more walkable ground than its play space: a
backdrop of terrain round a town square, roofs, ground outside the walls.
Left in the graph, that ground weighs on everything measured over the graph,
not only on where terminals go: the walking flow draws its sources in
proportion to area (on the ``backdrop`` level kind, benchmarks/level_kinds.py,
4-7 % of 256 draws fell on the square), and a percentile ranks the play
space's polygons among the background's (the square's spanned 6-32 to
10-57 points of the level's 0-100 on the navmesh route, 1-15 to 2-45 on the
sampling route), so that every threshold in percentile points
(``traffic_weight``, ``quiet_step``, ``max_traffic_step``) and the ``flow``
analyzer's heat map meant something else on a level with a background
(docs/plugins.md, "The play space"). Cut once where the graph is built, every
stage of a run after the graph builder reads the play space by construction,
where a rule per stage would have to be repeated in each and kept alike:

* ``terminals``: every selector picks among the graph's nodes; ``entry_exit``
  takes the boundary of the surface the graph covers (on the navmesh route
  the polygons the graph holds, :func:`held_polygons`; on the sampling
  route the graph's own faces), so the background holds no opening and
  weighs on no floor of its reachability prior, and casts its rays and
  measures the piece's extent over the parts of the mesh the play space
  stands on and those touching them (:func:`play_space_faces`), so a
  backdrop apart from the piece hides none of its openings;
* ``steiner``, ``loops``, ``roots``: over the graph and the terminals;
* ``simplify``: the predicates' rules over the structure, the walking flows
  and percentiles of ``max_traffic_step`` and the heat guarantee over the
  graph;
* ``analyzers``: ``flow`` (and its cross sections) over the graph, the
  others over the structure; ``regions`` and ``chokepoints`` split the
  whole navmesh once and report the regions holding one of the graph's
  polygons (:func:`held_polygons`, :func:`g2s_plugins.decomposition.shared_decomposition`)
  and the chokepoints between them;
* ``evaluators``: ``traffic`` measures over the graph, and its reference
  navmesh graph is cut by the same rule;
* ``outputs``: the graph and the structure, over the level's whole surface
  (``context.navmesh``, or the mesh), drawn as the level.

What reads the whole level: the source mesh as geometry (``mesh_los``'s
sight lines; ``coverage``'s default cover radius, from the mesh's bounds;
``entry_exit`` reads the parts touching the play space, a backdrop touching
the piece among them: docs/entry_exit.md, Limits) and Detour's queries (``surface_los``'s raycast,
which never leaves the connected area it starts in). Both graph
builders (``navmesh``, ``sampling``) call :func:`cut_to_play_space` last, after
their own checks of the whole level's walkable surface. The navmesh itself
(``context.navmesh``) stays whole: its polygon ids are the nodes' ``polygon``
attributes, which every stage looks up per node, and the background's
polygons are out of reach of the play space's (another connected area), so a
Detour raycast from the play space never enters them.

A point belongs to the area of its nearest node within the agent's height in
3D: a node's distance is to its navmesh polygon where it has one (Detour's
nearest point on it: a polygon of a hall may be 20 m across, its centre far
from the point), to its position otherwise (a sample). A point with no node
that near (in mid-air, inside a wall, in the wrong frame) is bad input; the
message tells one on the mesh's walkable ground apart (an area the graph
builder dropped, too small or too narrow for the agent) and names the
builder's setting that drops small areas.

Complexity: a k-d tree of the nodes, a Detour look-up per point and one
connected-components pass, O(n log n + p log n + m), plus the subgraph's copy,
O(n + m).
"""

from __future__ import annotations

from collections.abc import Collection, Hashable
from dataclasses import dataclass
from typing import Annotated

import numpy as np
import numpy.typing as npt
from pydantic import Field, Strict

from g2s_core.errors import G2SError
from g2s_core.lazy import lazy_module
from g2s_core.model import NavMesh, RunContext
from g2s_core.plugin import PluginParams
from g2s_plugins import traffic
from g2s_plugins._raycasting import UP, RayCaster

trimesh, spatial = lazy_module("trimesh"), lazy_module("scipy.spatial")
sparse, csgraph = lazy_module("scipy.sparse"), lazy_module("scipy.sparse.csgraph")
nx = lazy_module("networkx")

KEY = "graph.params.play_points"
"""Where a config names the play points: in messages, and where :func:`play_points` reads them."""


class PlaySpaceParams(PluginParams):
    """The play points, a parameter of every graph builder."""

    play_points: list[Annotated[tuple[float, float, float], Strict(False)]] | None = Field(
        None, min_length=1, strict=False,
        description="points [x, y, z] in the play space (mesh frame, metres): the initial graph keeps only the "
                    "connected walkable areas holding a node within the agent's height of one (3D; a navmesh node's "
                    "distance is to its polygon), so every later stage (terminals, entry_exit's openings among them, the "
                    "tree, loops, roots, simplification, walking flows and their percentiles, the heat guarantee, "
                    "analyzers, regions and chokepoints, evaluators) sees those areas alone (entry_exit's rays read the "
                    "mesh's parts the play space stands on and those touching them; the mesh's other readers and the "
                    "drawn navmesh stay whole), and a warning says how much was left out; null: every area")


def play_points(config: dict) -> list[list[float]] | None:
    """The play points a run's recorded ``config`` names (:data:`KEY`), None when it names none."""
    return ((config.get("graph") or {}).get("params") or {}).get("play_points")


def held_polygons(graph: nx.Graph, polygon_count: int) -> np.ndarray:
    """(polygon_count,) bool: the navmesh polygons that are nodes of ``graph`` (a node's ``polygon`` attribute):
    every one of a navmesh graph's, but those :func:`cut_to_play_space` left out. O(n)."""
    held = np.zeros(polygon_count, dtype=bool)
    polygons = node_polygons(graph, graph.nodes)
    held[polygons[polygons >= 0]] = True
    return held


def node_polygons(graph: nx.Graph, nodes: Collection[Hashable]) -> np.ndarray:
    """(len(nodes),) int64: the navmesh polygon of each of ``nodes`` (its ``polygon`` attribute), -1 for a node with
    none (a portal node, a sample). O(n)."""
    return np.fromiter((graph.nodes[node].get("polygon", -1) for node in nodes), dtype=np.int64, count=len(nodes))


def play_space(graph: nx.Graph, navmesh: NavMesh | None, points: npt.ArrayLike, reach: float) -> np.ndarray:
    """(n,) bool per row of :func:`g2s_plugins.traffic.surface_arrays` of ``graph``: the nodes of the connected
    areas that hold one of the (p, 3) ``points`` (mesh frame, metres) (:func:`_areas_held`)."""
    labels, held = _areas_held(graph, navmesh, points, reach)
    return np.isin(labels, held)


def _areas_held(graph: nx.Graph, navmesh: NavMesh | None, points: npt.ArrayLike, reach: float,
                ground: Ground | None = None) -> tuple[np.ndarray, np.ndarray]:
    """(n,) each row's connected area (:func:`g2s_plugins.traffic.surface_arrays` of ``graph``) and the areas that
    hold one of the (p, 3) ``points`` (mesh frame, metres).

    A point belongs to the area of its nearest node within ``reach`` metres
    in 3D (the agent's height): a node's distance is to its ``navmesh``
    polygon where it has one (``polygon`` >= 0; Detour's nearest point on it,
    looked for within ``reach`` each way), to its ``pos`` otherwise.

    Raises:
        G2SError: a point has no node within ``reach``; the message names ``graph.params.play_points[i]``, and,
            with ``ground``, whether the point stands on the mesh's walkable ground all the same (:func:`_no_node`).
    O(n log n + p log n + m).
    """
    arrays = traffic.surface_arrays(graph)
    points = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    positions = np.array([graph.nodes[node]["pos"] for node in arrays.nodes], dtype=np.float64).reshape(-1, 3)
    distance, nearest = spatial.cKDTree(positions).query(points, distance_upper_bound=reach)
    if navmesh is not None:
        row_of_polygon = np.full(navmesh.polygon_count, -1, dtype=np.int64)
        polygons = node_polygons(graph, arrays.nodes)
        row_of_polygon[polygons[polygons >= 0]] = np.flatnonzero(polygons >= 0)
        for i, point in enumerate(points):
            polygon, on = navmesh.nearest_poly(point, (reach, reach, reach))
            gap = float(np.linalg.norm(on - point))
            if polygon >= 0 and row_of_polygon[polygon] >= 0 and gap < distance[i]:
                distance[i], nearest[i] = gap, row_of_polygon[polygon]
    for i, point in enumerate(points):
        if not distance[i] <= reach:
            raise _no_node(i, point, reach, ground)
    _, labels = csgraph.connected_components(arrays.adjacency, directed=False)
    return labels, labels[nearest]


@dataclass(frozen=True)
class Ground:
    """The level a graph was built on, to tell a play point on its ground from one off it: ``mesh`` (metres, Y up),
    the agent's ``max_slope`` (degrees) and ``setting``, the graph builder's key that drops the smallest areas."""

    mesh: trimesh.Trimesh
    max_slope: float
    setting: str


def _no_node(i: int, point: np.ndarray, reach: float, ground: Ground | None) -> G2SError:
    """The error of play point ``i`` (3,) with no node within ``reach`` metres: off the walkable ground (in mid-air,
    inside a solid, another frame), or on ``ground``'s walkable faces where the graph builder kept no area (one too
    small or too narrow for the agent: Recast's ``region_min_size``, the sampling builder's ``min_region_area``).

    On the ground: the first face a ray straight down from ``reach`` above the point meets lies within ``reach`` of
    it and no steeper than ``max_slope``. One ray, cast only on this error's path.
    """
    x, y, z = point.tolist()
    where = f"{KEY}[{i}]: ({x:g}, {y:g}, {z:g}) has no walkable node within {reach:g} m (the agent's height)"
    bounds = None if ground is None or len(ground.mesh.faces) == 0 else ground.mesh.bounds
    if bounds is not None and np.all(point >= bounds[0] - reach) and np.all(point <= bounds[1] + reach):
        caster = RayCaster(ground.mesh)
        hits = caster.first_hits((point + reach * UP)[None, :], -UP)
        if hits.distance[0] <= 2 * reach and caster.walkable_faces(hits.face, ground.max_slope)[0]:
            return G2SError(
                f"{where}, though it stands on the mesh's walkable ground (at y = {float(hits.points[0, 1]):g}): "
                f"the graph builder kept no area there, one too small or too narrow for the agent "
                f"({ground.setting}, agent.radius); put the point on an area the graph holds, or lower "
                f"{ground.setting}")
    return G2SError(f"{where}; expected a point on the play space's walkable ground, mesh frame, Y up, metres")


def play_space_graph(graph: nx.Graph, navmesh: NavMesh | None, points: npt.ArrayLike, reach: float) -> nx.Graph:
    """A copy of ``graph`` (its graph attributes too) cut to the connected areas holding one of ``points``
    (:func:`play_space`)."""
    return _subgraph(graph, play_space(graph, navmesh, points, reach))


def _subgraph(graph: nx.Graph, keep: np.ndarray) -> nx.Graph:
    """A copy of ``graph`` with the nodes whose rows (:func:`g2s_plugins.traffic.surface_arrays`) ``keep`` holds."""
    nodes = traffic.surface_arrays(graph).nodes
    return graph.subgraph([nodes[i] for i in np.flatnonzero(keep)]).copy()


def cut_to_play_space(graph: nx.Graph, points: npt.ArrayLike | None, context: RunContext) -> nx.Graph:
    """A graph builder's ``graph`` cut to its play space (:func:`play_space_graph`, reach: the agent's height;
    ``context.navmesh`` where the builder set one), with one warning saying how many areas and how much area were
    left out; ``graph`` itself when ``points`` is None."""
    if points is None:
        return graph
    setting = "graph.params.region_min_size" if context.navmesh is not None else "graph.params.min_region_area"
    labels, held = _areas_held(graph, context.navmesh, points, context.agent.height,
                               Ground(context.mesh, context.agent.max_slope, setting))
    keep = np.isin(labels, held)
    if not keep.all():  # the areas and their area from the labels the cut was made by, not searched again
        area = traffic.surface_arrays(graph).area[~keep].sum()
        context.warn(f"graph: {np.unique(labels[~keep]).size} walkable area(s) ({area:.3g} m² in all) hold no "
                     f"play point ({KEY}) and are left out")
    cut = _subgraph(graph, keep)
    cut.graph[PLAY_POINTS] = np.asarray(points, dtype=np.float64).reshape(-1, 3).tolist()
    return cut


PLAY_POINTS = "play_points"
"""The graph attribute (``graph.graph[PLAY_POINTS]``) holding the play points of a graph :func:`cut_to_play_space` cut:
what tells the stages after it that the graph is a play space, not the whole level."""

_WELD = 1e-6
"""Metres: vertices this close (on a grid of this step) are one where :func:`mesh_parts` joins faces into parts."""

_PAIR_BATCH = 200_000
"""Face pairs tested at once by :func:`play_space_faces` (each pair holds 6 corner and 6 edge tests)."""

_QUERY_BATCH = 50_000
"""Kept faces whose neighbours :func:`play_space_faces` asks the R-tree for at once (a welded level's floor of a
million faces would otherwise return tens of millions of pairs in one array)."""


def mesh_parts(mesh: trimesh.Trimesh) -> np.ndarray:
    """(F,) int64: each face's part, the connected components of the faces joined by shared corners (corners on one
    :data:`_WELD` grid point are shared, whether the file welded them or not). O(F + V log V)."""
    faces = np.asarray(mesh.faces, dtype=np.int64)
    if len(faces) == 0:
        return np.zeros(0, dtype=np.int64)
    _, vertex = np.unique(np.round(np.asarray(mesh.vertices, dtype=np.float64) / _WELD).astype(np.int64), axis=0,
                          return_inverse=True)
    corner = vertex.reshape(-1)[faces]
    count = len(faces) + int(corner.max()) + 1
    rows = np.repeat(np.arange(len(faces)), 3)
    links = sparse.coo_matrix((np.ones(rows.size, dtype=np.int8), (rows, len(faces) + corner.reshape(-1))), (count, count))
    return csgraph.connected_components(links, directed=False)[1][: len(faces)].astype(np.int64)


def _segments_cross(triangles: np.ndarray, p: np.ndarray, q: np.ndarray) -> np.ndarray:
    """(n,) bool: segment ``p[i]``-``q[i]`` ((n, 3) each) crosses triangle ``triangles[i]`` ((n, 3, 3)), ends included
    (Moller and Trumbore, "Fast, minimum storage ray-triangle intersection", 1997, over the segment). O(n)."""
    a, e1, e2 = triangles[:, 0], triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0]
    d = q - p
    h = np.cross(d, e2)
    det = np.einsum("ij,ij->i", e1, h)
    ok = np.abs(det) > 1e-12 * np.maximum(1.0, np.linalg.norm(d, axis=1)) ** 3
    inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
    s = p - a
    u = np.einsum("ij,ij->i", s, h) * inv
    r = np.cross(s, e1)
    v = np.einsum("ij,ij->i", d, r) * inv
    t = np.einsum("ij,ij->i", e2, r) * inv
    return ok & (u >= 0) & (v >= 0) & (u + v <= 1) & (t >= 0) & (t <= 1)


def _touching(first: np.ndarray, second: np.ndarray, gap: float) -> np.ndarray:
    """(n,) bool: triangle ``first[i]`` touches ``second[i]`` ((n, 3, 3) each, metres): a corner of either lies within
    ``gap`` m of the other, or an edge of either crosses the other. Two triangles crossing edge to edge within ``gap``
    with no corner that near, or crossing within one plane, do not touch by this test. O(n)."""
    near = np.zeros(len(first), dtype=bool)
    for this, that in ((first, second), (second, first)):
        for k in range(3):
            closest = trimesh.triangles.closest_point(this, that[:, k])
            near |= np.linalg.norm(closest - that[:, k], axis=1) <= gap
            near |= _segments_cross(this, that[:, k], that[:, (k + 1) % 3])
    return near


def play_space_faces(mesh: trimesh.Trimesh, footing: np.ndarray, reach: float, gap: float) -> np.ndarray:
    """(F,) bool: the faces of the piece the play space is: the parts of ``mesh`` (:func:`mesh_parts`) the play space
    stands on, and every part touching a kept one, in turn (:func:`_touching` within ``gap`` m).

    ``footing``: (n, 3) points on the play space's walkable surface (metres, mesh frame); the parts of the faces
    within ``reach`` m of one are stood on (a face, not the face straight below: under a node over a grating's slot
    there is none). A backdrop or a skybox the play space
    leaves out, apart from the piece, is dropped; a piece built of separate parts (walls standing on a slab, a lintel
    between walls, a canopy on its posts) is kept whole, as are parts laid a crack apart (floor tiles, planks) up to
    ``gap``. A backdrop touching the piece (terrain it stands on) is kept, and so is whatever touches that; a part of
    the piece touching nothing kept within ``gap`` (a canopy on posts ending in the air, farther off the walls) is
    dropped.

    Cost: an R-tree of the faces' boxes (Guttman, "R-trees: a dynamic index structure for spatial searching", 1984),
    queried once per footing point with a box ``reach`` m round it and once per kept face with its box widened by
    ``gap``, and the distance, corner and edge tests of each pair so found, O((F + n) log F + pairs).
    """
    faces = np.asarray(mesh.faces)
    kept_faces = np.zeros(len(faces), dtype=bool)
    footing = np.asarray(footing, dtype=np.float64).reshape(-1, 3)
    if len(faces) == 0 or len(footing) == 0:
        return kept_faces
    part = mesh_parts(mesh)
    triangles = np.asarray(mesh.triangles, dtype=np.float64)
    low, high = triangles.min(axis=1), triangles.max(axis=1)
    tree = trimesh.util.bounds_tree(np.hstack([low, high]))
    kept = np.zeros(int(part.max()) + 1, dtype=bool)
    for start in range(0, len(footing), _QUERY_BATCH):
        points = footing[start: start + _QUERY_BATCH]
        found, counts = tree.intersection_v(points - reach, points + reach)
        found = np.asarray(found, dtype=np.int64)
        point = np.repeat(points, np.asarray(counts, dtype=np.int64), axis=0)
        near = np.linalg.norm(trimesh.triangles.closest_point(triangles[found], point) - point, axis=1) <= reach
        kept[part[found[near]]] = True
    frontier = np.flatnonzero(kept[part])
    while len(frontier):
        joined = np.zeros_like(kept)
        for start in range(0, len(frontier), _QUERY_BATCH):
            asked = frontier[start: start + _QUERY_BATCH]
            found, counts = tree.intersection_v(low[asked] - gap, high[asked] + gap)
            found = np.asarray(found, dtype=np.int64)
            mine = np.repeat(asked, np.asarray(counts, dtype=np.int64))
            other = ~kept[part[found]] & ~joined[part[found]]
            mine, found = mine[other], found[other]
            for first in range(0, len(found), _PAIR_BATCH):
                batch = slice(first, first + _PAIR_BATCH)
                touch = _touching(triangles[mine[batch]], triangles[found[batch]], gap)
                joined[part[found[batch][touch]]] = True
        kept |= joined
        frontier = np.flatnonzero(joined[part])
    kept_faces[:] = kept[part]
    return kept_faces
