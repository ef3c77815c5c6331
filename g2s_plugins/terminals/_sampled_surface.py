"""The walkable surface a sampled graph covers, as polygons: what ``entry_exit`` needs without a navmesh.

The ``sampling`` graph builder leaves no navigation mesh, only samples of the
walkable surface (eroded by the agent's clearance, as Recast erodes by its
radius) joined where the agent walks between them. The surface they cover is
the union of the graph's small faces; its boundary, the rims of that union,
plays the navmesh boundary's part for the entry/exit method.

1. *Plan-planar edges*: an edge ``a-b`` stays when the widest angle at which
   a common neighbour on its left sees it and the widest on its right sum to
   less than 180 degrees (the local Delaunay test: B. Delaunay, "Sur la
   sphere vide", 1934; C. L. Lawson's edge-flip criterion, 1977). Only graph
   neighbours count, so a floor over another (not joined to it) never
   removes its edges. Of two edges crossing in plan whose four ends are
   joined, the one whose opposite angles sum to more than 180 degrees goes,
   so what is left is planar where the neighbours are joined; a thin band of
   samples (a corridor two or three samples wide) keeps its triangles.
2. *Faces*: the edges seen from above, each node's neighbours in angle order;
   a face is the cycle of directed edges each followed by the one leaving
   its end next clockwise (the face on their left: counter-clockwise seen
   from above, the outside of a part clockwise).
3. *Filled faces*: counter-clockwise faces no larger than
   ``FACE_AREA_SPACINGS`` squared sample spacings; the others (each part's
   outside, holes round pillars and wells) are the open ones. An edge with
   no filled face on either side (samples in single file) is a polygon of
   two corners, whose boundary runs along both its sides.

The polygons are the filled faces (their nodes in walking order), neighbours
across each edge the filled face on its other side (-1: a boundary edge),
normals the mean of their nodes' ``normal``, areas their surface area (a
polygon of two corners: half the ``area`` each of its nodes stands for),
``joined`` the polygons of one connected part of the graph. They
have the fields of :class:`g2s_core.model.NavMesh` that
:func:`g2s_plugins.terminals._boundary.boundary_loops` and
``entry_exit.main_floor`` read.

Complexity, for n samples and m edges with d neighbours a node: O(m d) for
the common neighbours (one sorted look-up each), O(m log m) to sort the
directed edges, O(m) to trace the faces.
"""

from __future__ import annotations

from dataclasses import dataclass
from collections.abc import Hashable

import numpy as np

from g2s_core.lazy import lazy_module

sparse, csgraph = lazy_module("scipy.sparse"), lazy_module("scipy.sparse.csgraph")
nx = lazy_module("networkx")

FACE_AREA_SPACINGS = 2.0
"""A counter-clockwise face of at most this many squared sample spacings (in plan) is walkable surface.

A maximal Poisson-disk pick leaves no empty disk wider than the spacing among its samples: a
Delaunay triangle between them covers at most 1.3 spacings squared, a square of four on one
circle 2. Measured on the sampled graphs of every generated piece kind (docs/entry_exit.md,
"Openings on the sampling route"): 3,995 counter-clockwise faces, median 0.79, 99 % at most 3.7;
the larger are holes (the ring corridor's island, 156) or places where the graph lacks an edge
(up to 10.2 on ``big_hall``'s open floor). A face taken for a hole costs rays only (the floor
goes on all round it: no way out); one taken for surface could hide a boundary, so the bound is
the tight one."""


@dataclass(frozen=True)
class SampledSurface:
    """The filled faces of a sampled graph as polygons (the fields of a navmesh ``entry_exit`` reads).

    Attributes:
        vertices: (n,3) sample positions, metres (row i is graph node ``nodes[i]``).
        polygons: (P,k) int64 rows of ``vertices`` per face in walking order (interior on the left
            seen from above), padded with -1.
        neighbours: (P,k) int64 face across edge j (vertex j -> j+1), -1 at the boundary.
        normals: (P,3) unit mean of the face's nodes' normals.
        areas: (P,) surface area of each face, m².
        joined: (k,2) pairs of polygons the graph joins (through faces or single-file samples): a
            polygon reaches every other of its connected part of the graph through them.
        nodes: the graph node of each row of ``vertices``.
    """

    vertices: np.ndarray
    polygons: np.ndarray
    neighbours: np.ndarray
    normals: np.ndarray
    areas: np.ndarray
    joined: np.ndarray
    nodes: tuple[Hashable, ...]


def _plan(v: np.ndarray) -> np.ndarray:
    """(..., 2) plan coordinates (x, -z) of (..., 3) vectors: seen from above with Y up, counter-clockwise is positive."""
    return np.stack([v[..., 0], -v[..., 2]], axis=-1)


def _locally_delaunay(points: np.ndarray, edges: np.ndarray) -> np.ndarray:
    """(m,) bool: the edges ((m,2) ascending pairs, sorted) that are Delaunay among their common neighbours, in plan.

    An edge ``a-b`` stays when the widest angle ``a-c-b`` of a common neighbour ``c`` on its left and
    the widest on its right sum to less than 180 degrees (a side with none counts 0): the circle
    through ``a``, ``b`` and the one side's ``c`` holds no such point of the other side.
    """
    n = len(points)
    links = sparse.csr_array((np.ones(len(edges), dtype=np.int8), (edges[:, 0], edges[:, 1])), shape=(n, n))
    links = (links + links.T).tocsr()
    key = edges[:, 0] * n + edges[:, 1]
    # Every (edge a-b, neighbour c of a) at once; c is common when the pair b-c is an edge too.
    degree = np.diff(links.indptr)[edges[:, 0]]
    which = np.repeat(np.arange(len(edges)), degree)
    offset = np.arange(len(which)) - np.repeat(np.cumsum(degree) - degree, degree)
    c = links.indices[np.repeat(links.indptr[edges[:, 0]], degree) + offset]
    b = edges[which, 1]
    lo, hi = np.minimum(b, c), np.maximum(b, c)
    at = np.minimum(np.searchsorted(key, lo * n + hi), len(key) - 1)
    common = (key[at] == lo * n + hi) & (c != b)
    which, c = which[common], c[common]
    plan = _plan(points)
    ca, cb = plan[edges[which, 0]] - plan[c], plan[edges[which, 1]] - plan[c]
    cross = ca[:, 0] * cb[:, 1] - ca[:, 1] * cb[:, 0]
    angle = np.arctan2(np.abs(cross), np.einsum("ij,ij->i", ca, cb))
    widest = np.zeros((2, len(edges)))
    np.maximum.at(widest, ((cross > 0).astype(np.int64), which), angle)
    return widest.sum(axis=0) < np.pi


def sampled_surface(graph: nx.Graph, spacing: float) -> SampledSurface:
    """The walkable surface the samples of ``graph`` cover (see the module doc); ``spacing``: the samples', m."""
    nodes = tuple(n for n, data in graph.nodes(data=True) if "pos" in data)
    row = {node: i for i, node in enumerate(nodes)}
    points = np.array([graph.nodes[n]["pos"] for n in nodes], dtype=np.float64).reshape(-1, 3)
    node_normals = np.array([graph.nodes[n].get("normal", (0.0, 1.0, 0.0)) for n in nodes], dtype=np.float64)
    node_normals = node_normals.reshape(-1, 3)
    pairs = [(row[a], row[b]) for a, b in graph.edges if a in row and b in row and a != b]
    edges = np.unique(np.sort(np.array(pairs, dtype=np.int64).reshape(-1, 2), axis=1), axis=0)
    empty = np.zeros((0, 3), dtype=np.int64)
    if len(edges) == 0:
        return SampledSurface(points, empty, empty.copy(), np.zeros((0, 3)), np.zeros(0), np.zeros((0, 2), np.int64), nodes)
    edges = edges[_locally_delaunay(points, edges)]

    # Directed edges sorted by start, then by angle: the next edge of a face leaves the end of
    # the current one just clockwise of the way back.
    start = np.r_[edges[:, 0], edges[:, 1]]
    end = np.r_[edges[:, 1], edges[:, 0]]
    d = _plan(points[end] - points[start])
    angle = np.arctan2(d[:, 1], d[:, 0])
    order = np.lexsort((angle, start))
    start, end = start[order], end[order]
    h = len(start)
    first = np.searchsorted(start, np.arange(len(points)))
    count = np.bincount(start, minlength=len(points))
    rank = np.arange(h) - first[start]
    key = start * len(points) + end
    by_key = np.argsort(key, kind="stable")
    twin = by_key[np.searchsorted(key[by_key], end * len(points) + start)]
    nxt = first[end] + (rank[twin] - 1) % count[end]  # the edge leaving ``end`` one step clockwise of the way back

    # Faces: the cycles of ``nxt`` (one connected component each).
    cycles = sparse.csr_array((np.ones(h, dtype=np.int8), (np.arange(h), nxt)), shape=(h, h))
    n_faces, face = csgraph.connected_components(cycles, directed=True, connection="weak")
    ref = points[start[np.unique(face, return_index=True)[1]]]  # a corner of each face: areas stay exact far from the origin
    a, b = _plan(points[start] - ref[face]), _plan(points[end] - ref[face])
    signed = 0.5 * np.bincount(face, weights=a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0], minlength=n_faces)
    filled = (signed > 0.0) & (signed <= FACE_AREA_SPACINGS * spacing * spacing)

    # Each filled face's directed edges in walking order, from its lowest one.
    ids = -np.ones(n_faces, dtype=np.int64)
    ids[filled] = np.arange(int(filled.sum()))
    faces: list[list[int]] = []
    lowest = np.full(n_faces, h, dtype=np.int64)
    np.minimum.at(lowest, face, np.arange(h))
    for f in np.flatnonzero(filled).tolist():
        e = int(lowest[f])
        cycle = [e]
        while (e := int(nxt[e])) != cycle[0]:
            cycle.append(e)
        faces.append(cycle)
    # An edge with no filled face on either side (samples in single file through a doorway or a
    # narrow passage) is a polygon of two corners: its boundary runs along both sides.
    bare = np.flatnonzero((start < end) & ~filled[face] & ~filled[face[twin]])
    faces += [[int(e), int(twin[e])] for e in bare]
    width = max(3, max((len(c) for c in faces), default=3))
    polygons = -np.ones((len(faces), width), dtype=np.int64)
    neighbours = -np.ones((len(faces), width), dtype=np.int64)
    for slot, cycle in enumerate(faces):
        polygons[slot, : len(cycle)] = start[cycle]
        neighbours[slot, : len(cycle)] = ids[face[twin[cycle]]]
    valid = polygons >= 0
    safe = np.where(valid, polygons, 0)
    normals = (node_normals[safe] * valid[..., None]).sum(axis=1)
    normals /= np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-12)
    corners = points[safe]
    fan = np.cross(corners[:, 1:-1] - corners[:, :1], corners[:, 2:] - corners[:, :1])
    fan *= (valid[:, 2:])[..., None]
    areas = 0.5 * np.linalg.norm(fan, axis=2).sum(axis=1)
    # A polygon of two corners covers no area, yet its samples stand for the surface round them (a walkway
    # sampled in single file weighed nothing against the roof over it: docs/entry_exit.md, "A fifteenth round of
    # piece kinds"): half of each corner's, a sample inside a line sharing its own between its two polygons.
    bare_rows = np.flatnonzero(polygons[:, 2] < 0)
    node_areas = np.array([graph.nodes[n].get("area", spacing * spacing) for n in nodes], dtype=np.float64)
    areas[bare_rows] = 0.5 * node_areas[polygons[bare_rows, :2]].sum(axis=1)
    # Polygons the agent walks between, in pairs: faces apart along single-file samples are one floor.
    links = sparse.coo_array((np.ones(len(edges)), (edges[:, 0], edges[:, 1])), shape=(len(points), len(points)))
    part = csgraph.connected_components(links, directed=False)[1][polygons[:, 0]]
    order = np.argsort(part, kind="stable")
    same = part[order[1:]] == part[order[:-1]]
    joined = np.stack([order[:-1][same], order[1:][same]], axis=1)
    return SampledSurface(points, polygons, neighbours, normals, areas, joined, nodes)
