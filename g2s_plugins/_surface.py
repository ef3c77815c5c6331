"""The walkable surface as the built-in plugins share it: on-navmesh points and Algorithm 5's collapse rule.

* :func:`on_navmesh`: the one rule deciding whether a point stands on the
  navigation mesh (terminal selectors use it to set a node's ``on_navmesh``).
* :func:`collapse_rule`: the paper's Algorithm 5 (Sec. 3.1.5) as both line-of-
  sight predicates (``surface_los`` over the navmesh, ``mesh_los`` over the
  level mesh) apply it; they differ only in the line-of-sight test they pass.
* :func:`normals_angle_deg`, :func:`chain_bend_deg`: the normal test.
* :class:`NavmeshSurface`: how far points lie above or below the navmesh's
  detail surface, the check ``surface_los`` adds to Algorithm 5 (``mesh_los``
  makes it against the level mesh); :func:`edge_surface_gaps` measures it for
  every edge of a structure.

Conventions: metres, degrees, Y up.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import Any

import networkx as nx
import numpy as np
from pydantic import Field

from g2s_core.config import AgentConfig
from g2s_core.model import NavMesh
from g2s_core.plugin import PluginParams

Vec = Sequence[float]
LineOfSight = Callable[[tuple[float, ...], tuple[float, ...]], bool]

MAX_SURFACE_GAP = 0.4
"""Metres a collapsed edge may pass above or below the walkable surface (default of both LoS predicates).

Measured with ``benchmarks/piece_quality.py`` (docs/entry_exit.md): the edges
simplification makes on the generated pieces, stairs with 0.25 m risers
included, stay within 0.01 m of the surface; the shortcut under the shared
Ramp's ramp strayed 2.42 m. 0.4 m lies between and under the 0.5 m the
structures must never exceed.
"""


class CollapseParams(PluginParams):
    """Algorithm 5's tolerances, the same for both line-of-sight predicates.

    ``max_surface_gap: null`` with ``whole_chain_normals: false`` is the
    paper's Algorithm 5 exactly (configs/map_analysis_paper.yaml).
    """

    normal_tolerance_deg: float = Field(
        10.0, ge=0, le=180, description="largest angle between the normals of A, B and C that still lets B go, degrees"
    )
    whole_chain_normals: bool = Field(
        True, description="compare the normals of A, B and C pairwise; false: A and B only, as the paper does"
    )
    max_surface_gap: float | None = Field(
        MAX_SURFACE_GAP,
        gt=0,
        description="largest height between the segment A -> C and the walkable surface, m; null: no such check (the paper)",
    )
    probe_step: float | None = Field(
        None, gt=0, le=100, description="surface probes along A -> C at most this far apart, m; default agent radius / 2"
    )


def on_navmesh(navmesh: NavMesh | None, point: Vec, agent: AgentConfig) -> bool:
    """Whether ``point`` stands on ``navmesh``: a polygon within one cell horizontally and the climb vertically.

    One cell (the navmesh's ``cell_size``) is the resolution of the navmesh: a point on its boundary is on it, a point on the
    floor's real edge (about one agent radius outside, where Recast eroded it)
    is not. ``False`` when ``navmesh`` is ``None``.
    """
    if navmesh is None:
        return False
    horizontal = float(navmesh.settings["cell_size"])
    vertical = max(float(agent.max_climb), 1e-3)
    p = np.asarray(point, dtype=np.float64)
    index, nearest = navmesh.nearest_poly(p, extents=(horizontal, vertical, horizontal))
    if int(index) < 0:
        return False
    offset = np.asarray(nearest, dtype=np.float64) - p
    return bool(math.hypot(offset[0], offset[2]) <= horizontal + 1e-9 and abs(offset[1]) <= vertical + 1e-9)


def normals_angle_deg(a: Vec, b: Vec) -> float:
    """Angle between two normals in degrees; ``inf`` when either has zero length.

    Plain floats rather than numpy: it runs once per predicate call, on 3-vectors.
    """
    lengths = math.hypot(*a) * math.hypot(*b)
    if not lengths > 0:
        return math.inf
    cosine = (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / lengths
    return math.degrees(math.acos(min(1.0, max(-1.0, cosine))))


def chain_bend_deg(tree: nx.DiGraph, a: int, b: int, c: int) -> float:
    """The largest angle between the normals of the chain A -> B -> C (the pairs AB, BC and AC)."""
    na, nb, nc = (tree.nodes[n]["normal"] for n in (a, b, c))
    return max(normals_angle_deg(na, nb), normals_angle_deg(nb, nc), normals_angle_deg(na, nc))


def segment_points(start: Vec, end: Vec, step: float) -> np.ndarray:
    """(k + 1, 3) points from ``start`` to ``end`` (both included), at most ``step`` apart horizontally."""
    a = np.asarray(start, dtype=np.float64)
    b = np.asarray(end, dtype=np.float64)
    horizontal = math.hypot(b[0] - a[0], b[2] - a[2])
    k = max(1, math.ceil(horizontal / step - 1e-9))
    t = np.arange(k + 1) / k
    return a[None, :] + t[:, None] * (b - a)[None, :]


class NavmeshSurface:
    """The navmesh's detail surface (Recast's height-accurate triangles), for vertical distances to it.

    The detail triangles are bucketed once on a square grid in the XZ plane
    (``bucket`` metres); a query tests each point against the triangles of its
    bucket (barycentric coordinates in XZ, all points of a query in one numpy
    pass) and takes the surface nearest in height. A point over no triangle
    (a crack between detail triangles) falls back to Detour's nearest polygon
    within one cell horizontally.

    Cost: O(T * covered buckets) to build; O(points * triangles per bucket) per query.
    """

    def __init__(self, navmesh: NavMesh, bucket: float = 1.0) -> None:
        self.navmesh = navmesh
        self.cell = float(navmesh.settings["cell_size"])
        self.bucket = float(bucket)
        vertices = np.asarray(navmesh.detail_vertices, dtype=np.float64)
        tri = vertices[np.asarray(navmesh.detail_triangles, dtype=np.int64)]  # (T, 3, 3)
        x, y, z = tri[:, :, 0], tri[:, :, 1], tri[:, :, 2]
        # Per triangle: three edge functions e(x, z) = u x + v z + w, >= 0 inside (any winding),
        # and the plane y = alpha x + beta z + gamma; vertical triangles are left out.
        nxt = [1, 2, 0]
        u, v = z - z[:, nxt], x[:, nxt] - x
        w = -(u * x + v * z)
        area = (x[:, 1] - x[:, 0]) * (z[:, 2] - z[:, 0]) - (x[:, 2] - x[:, 0]) * (z[:, 1] - z[:, 0])
        flat = np.abs(area) > 1e-12
        sign = np.where(area < 0, -1.0, 1.0)[:, None]
        self.edges = (np.stack([u, v, w], axis=2) * sign[:, :, None])[flat]  # (T', 3, 3)
        normal = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])[flat]
        point = tri[flat, 0]
        alpha, beta = -normal[:, 0] / normal[:, 1], -normal[:, 2] / normal[:, 1]
        self.plane = np.stack([alpha, beta, point[:, 1] - alpha * point[:, 0] - beta * point[:, 2]], axis=1)
        xz = tri[flat][:, :, [0, 2]]
        self.origin = xz.reshape(-1, 2).min(axis=0) if len(xz) else np.zeros(2)
        lo = np.floor((xz.min(axis=1) - self.origin) / self.bucket).astype(np.int64)
        span = np.floor((xz.max(axis=1) - self.origin) / self.bucket).astype(np.int64) - lo + 1
        self.columns = int((lo[:, 1] + span[:, 1]).max()) if len(lo) else 1
        # Every (triangle, bucket) its XZ box covers, enumerated without a loop.
        count = span[:, 0] * span[:, 1]
        owner = np.repeat(np.arange(len(lo)), count)
        k = np.arange(len(owner)) - np.repeat(np.cumsum(count) - count, count)
        gx = lo[owner, 0] + k // span[owner, 1]
        gz = lo[owner, 1] + k % span[owner, 1]
        key = gx * self.columns + gz
        order = np.argsort(key, kind="stable")
        self.keys, self.owners = key[order], owner[order]

    def gaps(self, points: np.ndarray, reach: float) -> np.ndarray:
        """(n,) vertical distance from each point to the surface above or below it, m (``inf``: none within ``reach``)."""
        points = np.asarray(points, dtype=np.float64).reshape(-1, 3)
        cell = np.floor((points[:, [0, 2]] - self.origin) / self.bucket).astype(np.int64)
        key = cell[:, 0] * self.columns + cell[:, 1]
        start = np.searchsorted(self.keys, key, side="left")
        counts = np.where((cell >= 0).all(axis=1), np.searchsorted(self.keys, key, side="right") - start, 0)
        point = np.repeat(np.arange(len(points)), counts)
        first = np.repeat(start - (np.cumsum(counts) - counts), counts) + np.arange(len(point))
        tri = self.owners[first]
        p = points[point]
        xz1 = np.stack([p[:, 0], p[:, 2], np.ones(len(p))], axis=1)
        inside = (np.einsum("tkj,tj->tk", self.edges[tri], xz1) >= -1e-9).all(axis=1)
        height = np.einsum("tj,tj->t", self.plane[tri], xz1)
        gap = np.full(len(points), math.inf)
        np.minimum.at(gap, point[inside], np.abs(height[inside] - p[inside, 1]))
        for i in np.flatnonzero(~np.isfinite(gap)):  # a crack between detail triangles
            index, nearest = self.navmesh.nearest_poly(points[i], extents=(self.cell, reach, self.cell))
            if index >= 0:
                gap[i] = abs(float(nearest[1]) - points[i, 1])
        return np.where(gap <= reach, gap, math.inf)


def edge_surface_gaps(structure: nx.Graph, navmesh: NavMesh, agent: AgentConfig, step: float = 0.1) -> dict[tuple[int, int], float]:
    """How far each edge between two on-navmesh nodes strays from the navmesh surface, m (``inf``: leaves it).

    Edges to a node off the navmesh (an opening on the floor's real edge) are left out: their far
    end lies where Recast eroded the surface away.
    """
    surface = NavmeshSurface(navmesh)
    reach = 2.0 * float(agent.height)
    gaps = {}
    for a, b in structure.edges:
        if not (structure.nodes[a].get("on_navmesh") and structure.nodes[b].get("on_navmesh")):
            continue
        points = segment_points(structure.nodes[a]["pos"], structure.nodes[b]["pos"], step)
        gaps[(a, b)] = float(np.max(surface.gaps(points, reach)))
    return gaps


def collapse_rule(
    tolerance_deg: float, line_of_sight: LineOfSight, whole_chain: bool = True
) -> Callable[[nx.DiGraph, int, int, int], bool]:
    """``P(tree, A, B, C)`` of the paper's Algorithm 5: True when B may be removed.

    B is kept (False) when

    1. C is a leaf not on the walkable surface (``on_navmesh`` false): a line
       of sight to a point off the surface means nothing;
    2. the normals of the chain bend by more than ``tolerance_deg``
       (:func:`chain_bend_deg`; with ``whole_chain`` false the normals of A and
       B only, as the paper does, which lets a collapse cut across a change of
       slope at C);
    3. ``line_of_sight(A.pos, C.pos)`` is false: the straight segment is not
       walkable on the surface (each predicate's test, which also rejects a
       segment straying from the surface by more than its gap tolerance).

    The paper's pseudocode writes test 3 backwards (it sets ``canCollapse =
    false`` when there *is* line of sight, and its last line sets it true
    unconditionally); its text states the intent implemented here: collapse
    only when A and C see each other on the surface.
    """

    def predicate(tree: nx.DiGraph, a: int, b: int, c: int) -> bool:
        node_c = tree.nodes[c]
        if tree.out_degree(c) == 0 and not node_c.get("on_navmesh", False):
            return False
        nodes = tree.nodes
        bend = chain_bend_deg(tree, a, b, c) if whole_chain else normals_angle_deg(nodes[a]["normal"], nodes[b]["normal"])
        if bend > tolerance_deg:
            return False
        start = tuple(float(v) for v in tree.nodes[a]["pos"])
        end = tuple(float(v) for v in node_c["pos"])
        return line_of_sight(start, end)

    return predicate
