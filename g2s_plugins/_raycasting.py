"""Batched ray casting over a triangle mesh, and the agent walk tests built on it.

The one ray caster of the built-in plugins: the ``sampling`` graph builder,
the ``entry_exit`` selector and the ``mesh_los`` predicate use it; any
plugin that needs many rays against the level may.

Rays go through trimesh's Embree wrapper (:mod:`trimesh.ray.ray_pyembree`)
when ``embreex`` imports, else through trimesh's pure-Python intersector
(same answers, much slower). Every function here takes whole arrays of rays
and makes one intersector call per batch, never one per ray.

Conventions: metres, Y up, directions need not be unit length (they are
normalised). A ray "hits" the first triangle along it, front or back face;
of a down-facing triangle and an up-facing one on the same three corners
(a two-sided floor) it hits the up-facing one, whichever is listed first.
Distances are measured along the normalised direction; "no hit" is ``inf``.

Frame: Embree computes in single precision, so the caster works in the
level's local frame (:mod:`g2s_plugins.local_frame`, the navmesh's rule):
the mesh it hands to the intersector is translated in double precision by
the local origin of its bounds, every ray origin likewise before the cast,
and every crossing back. Callers see world coordinates only; a level near
the origin has a local origin of exactly 0 and is cast against as it is.
"""

from __future__ import annotations

import math
import weakref
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

import numpy as np

from g2s_core.lazy import lazy_module
from g2s_core.mesh import body_nesting
from g2s_plugins import _slabs, _walks
from g2s_plugins.local_frame import LocalFrame

trimesh, util = lazy_module("trimesh"), lazy_module("trimesh.util")
sparse, csgraph = lazy_module("scipy.sparse"), lazy_module("scipy.sparse.csgraph")

UP = np.array([0.0, 1.0, 0.0])
"""The up direction of every g2s mesh."""

EPSILON = 0.01
"""Metres a ray origin is moved off the surface it starts from."""

HEIGHT_TOLERANCE = 0.01
"""Metres of head room an agent may lack and still fit (float noise, exact-height doors)."""

GROUND_MARGIN = 0.1
"""Metres the ground may lie below the straight line between two points, on top of the agent's climb."""

RISE_TOLERANCE = 1e-6
"""Metres a rise between neighbouring ground probes may pass the agent's step or slope over their distance
(:meth:`AgentShape.max_rise`): the walk test's (``src/walks_module.cpp``) and the sampling builder's ledge probes'."""

MAX_OCCUPANCY_CELLS = 1 << 25
"""Cells (bytes) at most in a :class:`BoxOccupancy` grid; a larger level gets larger cells."""

JOINT_CALL_MAX_RAYS = 2048
"""Rays up to which :meth:`RayCaster.first_hits_of` casts its batches in one call (about where
the per-call cost saved, ~70 µs, matches the cost of a direction per ray, ~0.1 µs a ray)."""

SAME_PLACE = 1e-6
"""Metres along a ray within which crossings are one place (:func:`back_face_lead`): two faces in one plane, a crate's
side against a wall's face, are crossed at distances equal to about 1e-12 m."""

TOUCHING = 1e-3
"""Metres: triangles with faces in one plane (to this) whose boxes come this close are flush (:func:`_flush_pairs`);
far above the intersector's step past a crossing (a millionth of the level's size) for levels up to a kilometre
across."""

GRAZE_NUDGE = 1e-4
"""Metres a ray that grazes a triangle is moved aside before it is cast again."""

_SKEW = np.array([0.2672612419124244, 0.5345224838248488, 0.8017837257372732])
"""A direction no axis-aligned ray is parallel to (crossed with a ray to move it aside)."""

COMPASS = np.array(
    [[math.cos(a), 0.0, math.sin(a)] for a in np.arange(8) * (math.pi / 4)],
    dtype=np.float64,
)
"""Eight horizontal unit directions, 45 degrees apart."""


def _make_intersector(mesh: trimesh.Trimesh) -> tuple[Any, str]:
    """The Embree intersector of ``mesh`` when embreex imports, else trimesh's Python one."""
    try:
        from trimesh.ray import ray_pyembree

        return ray_pyembree.RayMeshIntersector(mesh), "embree"
    except ImportError:  # embreex missing or broken: correct but slow
        from trimesh.ray import ray_triangle

        return ray_triangle.RayMeshIntersector(mesh), "python"


@dataclass(frozen=True)
class _Scene:
    """What every :class:`RayCaster` of one mesh shares (read-only arrays, (m, ...) per triangle, and the intersector).

    Attributes:
        triangles: (m, 3, 3) float64, the corners, world coordinates.
        frame: the local frame of the corners (see the module docs).
        intersector: trimesh's intersector over a Trimesh of its own (the
            corners in ``frame``): it holds no reference to the caller's mesh,
            so the cache of :func:`_scene_of` does not keep that mesh alive.
        backend: ``"embree"`` or ``"python"``.
        plane_points: (m, 3) float64, each triangle's first corner, local frame.
        centroids: (m, 3) float64, each triangle's centroid, local frame.
        face_normals: (m, 3) float64, unit normals.
        twin: (m,) int64, :func:`_reversed_twins`.
        steep: max slope (degrees) -> :class:`SteepFaces`, filled on first use (:meth:`RayCaster.steep_faces`).
        open_floors: (agent, least inradius) -> :attr:`OpenFloors.open`, filled on first use.
    """

    triangles: np.ndarray
    frame: LocalFrame
    intersector: Any
    backend: str
    plane_points: np.ndarray
    centroids: np.ndarray
    face_normals: np.ndarray
    twin: np.ndarray
    steep: dict[float, SteepFaces] = field(default_factory=dict, compare=False)
    open_floors: dict[tuple[AgentShape, float], np.ndarray] = field(default_factory=dict, compare=False)

    @cached_property
    def extent(self) -> tuple[float, float]:
        """Metres: the corners' largest extent along an axis, and their largest coordinate (absolute) in
        :attr:`frame` (for :func:`ray_margin`; from the corners' bounds, once per mesh)."""
        if len(self.triangles) == 0:
            return 0.0, 0.0
        corners = self.triangles.reshape(-1, 3)
        bounds = np.stack([corners.min(axis=0), corners.max(axis=0)])
        # the frame's shift is monotonic, so the bounds' extreme in it is the extreme of the shifted corners
        return float((bounds[1] - bounds[0]).max()), float(np.abs(self.frame.to_local(bounds)).max())

    @cached_property
    def normal_y(self) -> np.ndarray:
        """(m,) float64, contiguous: the normals' y, which :func:`walks_in_batch`'s extension reads per call."""
        return np.ascontiguousarray(self.face_normals[:, 1])

    @cached_property
    def bodies(self) -> np.ndarray:
        """(m,) int64: :func:`_closed_bodies` of the triangles (once per mesh, on first use)."""
        return _closed_bodies(self.triangles, self.twin)

    @cached_property
    def closed(self) -> np.ndarray:
        """(m,) bool: the triangle belongs to a closed body (:attr:`bodies`)."""
        return self.bodies >= 0

    @cached_property
    def winding(self) -> np.ndarray:
        """(m,) int8: +1 on a closed body (:attr:`bodies`) wound as its nesting wants it, -1 on one wound against it
        (a solid exported with flipped normals), 0 on triangles of no closed body. The nesting is the core's, the rule
        ``mesh.clean`` turns bodies by (:func:`g2s_core.mesh.body_nesting`): a body inside an even number of others is
        a solid, wound outward (positive signed volume), inside an odd number a hollow (a closed room's inner shell),
        wound inward, whose faces already face out of the solid. The bodies are this scene's, so that bodies touching
        along an edge (paired round it) count as the closed bodies they are. O(m) over :attr:`bodies`, then
        :func:`~g2s_core.mesh.body_nesting`'s cost."""
        closed = np.flatnonzero(self.closed)
        sign = np.zeros(len(self.triangles), dtype=np.int8)
        if len(closed):
            _, body = np.unique(self.bodies[closed], return_inverse=True)
            inward, depth = body_nesting(self.triangles, np.split(closed[np.argsort(body, kind="stable")], np.cumsum(np.bincount(body))[:-1]))
            sign[closed] = np.where(inward == depth % 2, 1, -1)[body]
        return sign

    @cached_property
    def flush(self) -> FlushPartners:
        """The triangles' flush partners (:class:`FlushPartners`), found on the first crossing
        :func:`back_face_lead` meets (a level whose rays cross nothing, the dungeon open to the sky, asks none)."""
        return FlushPartners(self.triangles, self.bodies, self.frame)

    @classmethod
    def of_mesh(cls, mesh: trimesh.Trimesh) -> _Scene:
        """Built from ``mesh``: O(m log m) for the twin pairing; Embree's own build waits for the first ray."""
        triangles = np.asarray(mesh.triangles, dtype=np.float64).reshape(-1, 3, 3)
        frame = LocalFrame(triangles)
        # use_embree=False: trimesh's own intersector of ``local`` (``local.ray``) is never asked
        local = trimesh.Trimesh(frame.to_local(np.asarray(mesh.vertices)), mesh.faces, process=False, use_embree=False)
        intersector, backend = _make_intersector(local)
        local_triangles = frame.to_local(triangles)
        return cls(
            triangles, frame, intersector, backend, np.ascontiguousarray(local_triangles[:, 0, :]), local_triangles.mean(axis=1),
            np.asarray(mesh.face_normals, dtype=np.float64), _reversed_twins(triangles),
        )


_SCENES: dict[int, tuple[int, _Scene]] = {}
"""``id(mesh)`` -> (the mesh's content hash when its scene was built, the scene); an entry leaves with its mesh."""


def _scene_of(mesh: trimesh.Trimesh) -> _Scene:
    """The :class:`_Scene` of ``mesh``, built on first use and again after its vertices or faces change.

    Keyed by the object, not by its content (two equal meshes get two
    scenes): trimesh's hash of the mesh, kept up to date as its tracked
    arrays change and cached while they do not, only tells a changed mesh.
    """
    key, version = id(mesh), hash(mesh)
    entry = _SCENES.get(key)
    if entry is not None and entry[0] == version:
        return entry[1]
    if entry is None:  # an id is reused only after its object is gone, and the entry goes first
        weakref.finalize(mesh, _SCENES.pop, key, None)
    scene = _Scene.of_mesh(mesh)
    _SCENES[key] = (version, scene)
    return scene


@dataclass(frozen=True)
class Hits:
    """First hits of a batch of rays.

    Attributes:
        face: (n,) int64, index of the triangle hit, -1 for no hit.
        distance: (n,) float64, metres along the ray, ``inf`` for no hit.
        origins: (n, 3) float64, the rays' starts.
        unit: (n, 3) float64, the rays' unit directions.
    """

    face: np.ndarray
    distance: np.ndarray
    origins: np.ndarray
    unit: np.ndarray

    @cached_property
    def points(self) -> np.ndarray:
        """(n, 3) float64, where each ray hits, NaN for no hit (worked out on first use: most callers need none)."""
        return self.origins + self.unit * np.where(self.face >= 0, self.distance, np.nan)[:, None]

    @property
    def hit(self) -> np.ndarray:
        return self.face >= 0


class RayCaster:
    """Batched first-hit queries against one triangle mesh.

    Args:
        mesh: the triangles rays may hit (metres, Y up, world coordinates).

    Attributes:
        backend: ``"embree"`` or ``"python"``.
        rays_cast: how many rays this caster has cast (for statistics).
        frame: the :class:`~g2s_plugins.local_frame.LocalFrame` the
            intersector works in (see the module docs; not shifted for a
            level near the origin).
        triangles: (m, 3, 3) float64, the mesh's corners, world coordinates.
        scene: what it shares with every caster of the same mesh (below).

    Every caster of one mesh object shares that mesh's arrays above and its
    intersector (:func:`_scene_of`: built on the first caster, in seconds
    for millions of triangles, and kept while the mesh lives); each counts
    its own :attr:`rays_cast`. So plugins of one run (the ``sampling``
    builder, ``mesh_los``) each make a caster of ``context.mesh`` and build
    the scene once, and their statistics do not depend on each other.
    """

    def __init__(self, mesh: trimesh.Trimesh) -> None:
        self.mesh = mesh
        self.scene = scene = _scene_of(mesh)
        self.triangles, self.frame, self.face_normals = scene.triangles, scene.frame, scene.face_normals
        self.intersector, self.backend = scene.intersector, scene.backend
        self._plane_points, self._centroids, self._twin = scene.plane_points, scene.centroids, scene.twin
        self._embree: Any = None
        self.rays_cast = 0

    @property
    def local_origin(self) -> np.ndarray:
        """(3,) float64, whole metres: the origin of :attr:`frame` (all zero for a level near the origin)."""
        return self.frame.origin

    def first_hits(self, origins: np.ndarray, directions: np.ndarray) -> Hits:
        """The first triangle each ray hits and how far along the ray.

        A ray that only grazes a triangle (runs in its plane, e.g. a vertical
        ray along a box's side) is cast again from ``GRAZE_NUDGE`` metres to
        either side, and the farther of the two hits is kept: a ray lined up
        with a face sees what lies on the open side of it, not the face's edge.

        Args:
            origins: (n, 3) ray starts.
            directions: (n, 3) or (3,) directions (any non-zero length).
        """
        origins = np.asarray(origins, dtype=np.float64).reshape(-1, 3)
        n = len(origins)
        if n == 0 or len(self.mesh.faces) == 0:
            return Hits(np.full(n, -1, dtype=np.int64), np.full(n, np.inf), origins, np.zeros((n, 3)))
        directions = np.asarray(directions, dtype=np.float64)
        if directions.ndim == 1:  # one direction for every ray: normalised once, as a row
            directions = directions[None, :]
        elif directions.shape != origins.shape:
            directions = np.broadcast_to(directions, origins.shape)
        # numpy.linalg.norm's sum of squares along the rows, without its Python-level dispatch (a walk test's
        # rays go through here in batches of about a thousand, where that dispatch is a tenth of the cost)
        unit = directions / np.sqrt(np.add.reduce(directions * directions, axis=1, keepdims=True))
        if unit.shape != origins.shape:
            unit = np.broadcast_to(unit, origins.shape)
        local = self.frame.to_local(origins)
        face, distance, grazing = self._cast(local, unit)
        if np.any(grazing):
            face[grazing], distance[grazing] = self._cast_aside(local[grazing], unit[grazing])
        return Hits(face, distance, origins, unit)

    def _cast_aside(self, local: np.ndarray, unit: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(face, distance) of rays that grazed a triangle (``local`` (g, 3) origins in the local frame, ``unit``
        (g, 3)), each cast again ``GRAZE_NUDGE`` to either side of it: the farther hit (:meth:`first_hits`)."""
        aside = np.cross(unit, _SKEW)
        aside /= np.linalg.norm(aside, axis=1, keepdims=True)
        face_a, distance_a, _ = self._cast(local + GRAZE_NUDGE * aside, unit)
        face_b, distance_b, _ = self._cast(local - GRAZE_NUDGE * aside, unit)
        take_b = distance_b > distance_a
        return np.where(take_b, face_b, face_a), np.where(take_b, distance_b, distance_a)

    def first_hits_of(self, batches: list[tuple[np.ndarray, np.ndarray]]) -> list[Hits]:
        """:meth:`first_hits` of several ``(origins, directions)`` batches, in that order.

        Together they are cast in one call when they hold at most
        ``JOINT_CALL_MAX_RAYS`` rays (a small batch costs mostly per call),
        else one call each (a batch sharing one direction normalises it once).
        Each ray is cast on its own either way: the answers are the same.
        """
        sizes = [len(origins) for origins, _ in batches]
        if sum(sizes) > JOINT_CALL_MAX_RAYS:
            return [self.first_hits(origins, directions) for origins, directions in batches]
        origins = np.concatenate([np.asarray(o, dtype=np.float64).reshape(-1, 3) for o, _ in batches])
        ends = np.cumsum(sizes).tolist()
        directions = np.empty(origins.shape)
        for start, end, (_, direction) in zip([0, *ends[:-1]], ends, batches):
            directions[start:end] = direction  # a row or one per ray
        hits = self.first_hits(origins, directions)
        return [
            Hits(hits.face[a:b], hits.distance[a:b], hits.origins[a:b], hits.unit[a:b])
            for a, b in zip([0, *ends[:-1]], ends)
        ]

    def all_hits(
        self, origins: np.ndarray, directions: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Every crossing along each ray (one multiple-hit intersector call).

        Returns:
            ``(ray, distance, face, points)``: (m,) the ray's index, (m,)
            metres along it, (m,) the triangle crossed, (m, 3) the crossing;
            in the intersector's order.
        """
        origins = np.ascontiguousarray(origins, dtype=np.float64).reshape(-1, 3)
        directions = np.broadcast_to(np.asarray(directions, dtype=np.float64), origins.shape)
        if len(origins) == 0 or len(self.mesh.faces) == 0:
            return np.zeros(0, np.int64), np.zeros(0), np.zeros(0, np.int64), np.zeros((0, 3))
        unit = np.ascontiguousarray(directions / np.linalg.norm(directions, axis=1, keepdims=True))
        local = self.frame.to_local(origins)
        locations, ray, face = self.intersector.intersects_location(local, unit, multiple_hits=True)
        self.rays_cast += len(origins)
        ray = np.asarray(ray, dtype=np.int64)
        locations = np.asarray(locations, dtype=np.float64).reshape(-1, 3)
        distance = np.einsum("ij,ij->i", locations - local[ray], unit[ray])
        return ray, distance, np.asarray(face, dtype=np.int64), self.frame.to_world(locations)

    def _first_faces(self, origins: np.ndarray, unit: np.ndarray) -> np.ndarray:
        """(n,) int64: the intersector's ``intersects_first`` answer for these rays (``origins`` in the local frame).

        With Embree, the rays go straight to the scene trimesh's intersector
        built (scaled and float32, :class:`trimesh.ray.ray_pyembree._EmbreeWrap`),
        after the same float32 rounding and re-normalisation ``intersects_first``
        applies: the same bits reach Embree without its per-call copies. A batch
        sharing one direction (``unit`` a broadcast row) re-normalises that row once.
        """
        if self._embree is None and self.backend == "embree":
            # a private attribute of trimesh's intersector: without it (another trimesh), take the public call
            self._embree = getattr(self.intersector, "_scene", False)
        if not self._embree:
            return np.asarray(self.intersector.intersects_first(origins, np.ascontiguousarray(unit)), dtype=np.int64)
        one_direction = unit.strides[0] == 0
        directions = util.unitize(np.array(unit[:1] if one_direction else unit, dtype=np.float32))
        face = self._embree.run(origins.astype(np.float32), np.broadcast_to(directions, unit.shape) if one_direction else directions)
        return np.asarray(face, dtype=np.int64)

    def _cast(self, origins: np.ndarray, unit: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """One intersector call: (face, distance, grazing) per ray; ``origins`` local, ``unit`` normalised."""
        n = len(origins)
        face = self._first_faces(origins, unit).reshape(n)
        self.rays_cast += n
        distance = np.full(n, np.inf)
        grazing = np.zeros(n, dtype=bool)
        hit = face >= 0
        if hit.any():
            f, o, d = face[hit], origins[hit], unit[hit]
            normal = self.face_normals[f]
            denominator = np.einsum("ij,ij->i", d, normal)
            along_plane = np.einsum("ij,ij->i", self._plane_points[f] - o, normal)
            flat = np.abs(denominator) < 1e-9
            if flat.any():
                t = np.where(flat, 0.0, along_plane / np.where(flat, 1.0, denominator))
                # A ray in a triangle's plane (or a degenerate triangle) has no plane
                # crossing: take the distance to the triangle's centroid instead.
                t = np.where(flat, np.einsum("ij,ij->i", self._centroids[f] - o, d), t)
            else:
                t = along_plane / denominator
            distance[hit] = np.maximum(t, 0.0)
            grazing[hit] = flat
            # Of a face and its reversed twin (a two-sided floor) the intersector returns either (the one listed
            # last): take the up-facing one, the floor, as the level would be read with single-sided faces.
            face[hit] = np.where(self._twin[f] >= 0, self._twin[f], f)
        return face, distance, grazing

    def walkable_faces(self, faces: np.ndarray, max_slope_deg: float) -> np.ndarray:
        """(n,) bool: ``faces`` (indices, -1 = none) are at most ``max_slope_deg`` from horizontal."""
        faces = np.asarray(faces, dtype=np.int64)
        ok = faces >= 0
        ok[ok] = self.face_normals[faces[ok], 1] >= math.cos(math.radians(max_slope_deg)) - 1e-9
        return ok

    def steep_faces(self, max_slope_deg: float) -> SteepFaces:
        """The mesh's triangles steeper than ``max_slope_deg``, binned once per mesh and max slope (kept in
        :attr:`scene`, which every caster of the mesh shares)."""
        found = self.scene.steep.get(max_slope_deg)
        if found is None:
            found = self.scene.steep[max_slope_deg] = SteepFaces.of(self, max_slope_deg)
        return found


class BoxOccupancy:
    """The cells of a regular 3-D grid that the widened bounding boxes of some triangles touch.

    A broad phase for rays that only matter when they pass near those
    triangles: a point in no touched cell lies farther than ``widen`` from
    every one of them along each axis, so a ray from it shorter than that
    cannot reach them, and need not be cast. Conservative: a touched cell
    only means "maybe near" (the box of a long diagonal triangle touches
    cells far from it).

    Args:
        triangles: (m, 3, 3) corners, metres.
        widen: (3,) metres each box grows by on both sides, per axis.
        cell: edge of a cell, metres, or (3,) its edges along x, y, z; grown
            (all edges in proportion) until the grid has at most
            ``MAX_OCCUPANCY_CELLS`` cells.
    """

    def __init__(self, triangles: np.ndarray, widen: np.ndarray, cell: float | np.ndarray) -> None:
        triangles = np.asarray(triangles, dtype=np.float64).reshape(-1, 3, 3)
        lo = triangles.min(axis=1) - widen
        hi = triangles.max(axis=1) + widen
        self.origin = lo.min(axis=0) if len(triangles) else np.zeros(3)
        extent = (hi.max(axis=0) - self.origin) if len(triangles) else np.zeros(3)
        cell = np.broadcast_to(np.asarray(cell, dtype=np.float64), (3,))
        self.cell = cell * max(1.0, float(np.prod((extent + cell) / cell) / MAX_OCCUPANCY_CELLS) ** (1 / 3))
        self.occupied = np.zeros(tuple(self._cell_of(self.origin + extent) + 1), dtype=bool)
        # Many small triangles share their cell ranges: fill each range once.
        ranges = np.hstack([self._cell_of(lo), self._cell_of(hi)])
        for i0, j0, k0, i1, j1, k1 in ranges[_row_starts(ranges)].tolist():
            self.occupied[i0 : i1 + 1, j0 : j1 + 1, k0 : k1 + 1] = True

    def _cell_of(self, points: np.ndarray) -> np.ndarray:
        """(..., 3) int64 cell indices (floor is monotonic: a point inside a box gets a cell of its range)."""
        return np.floor((points - self.origin) / self.cell).astype(np.int64)

    def columns_free(self, points: np.ndarray, low: np.ndarray | float, high: np.ndarray | float) -> np.ndarray:
        """(n,) bool: the vertical segment from ``points[i]`` raised by ``low`` to it raised by ``high``
        (metres; scalars or (n,)) meets no touched cell."""
        points = np.asarray(points, dtype=np.float64).reshape(-1, 3)
        shape = np.array(self.occupied.shape)
        bottom = self._cell_of(points + np.multiply.outer(low, UP))
        top = self._cell_of(points + np.multiply.outer(high, UP))[:, 1]
        inside = np.all((bottom[:, [0, 2]] >= 0) & (bottom[:, [0, 2]] < shape[[0, 2]]), axis=1)
        free = np.ones(len(points), dtype=bool)
        rows, i, j, k, top = np.nonzero(inside)[0], bottom[inside, 0], bottom[inside, 1], bottom[inside, 2], top[inside]
        for step in range(int(np.max(top - j, initial=-1)) + 1):
            level = j + step
            touched = (level <= top) & (level >= 0) & (level < shape[1])
            touched[touched] = self.occupied[i[touched], level[touched], k[touched]]
            free[rows[touched]] = False
        return free


_TWIN_HASH = np.random.default_rng(0).uniform(0.5, 1.5, 9)
"""Weights of the 9 sorted coordinates a triangle is sorted by in :func:`_reversed_twins` (distinct triangles rarely
share the sum; twins always do)."""


def _reversed_twins(triangles: np.ndarray) -> np.ndarray:
    """(m,) int64: for a triangle facing down, another on the same three corners wound the other way (its up-facing
    side, as a two-sided face is exported), else -1. Cost: one sort of the m triangles (about 1 s for 2 M)."""
    twin = np.full(len(triangles), -1, dtype=np.int64)
    # each coordinate's three values in order: the same for a triangle and its twin, whatever their corners' order
    key = np.sort(triangles, axis=1).reshape(-1, 9)
    hashed = key @ _TWIN_HASH
    order = np.argsort(hashed, kind="stable")  # equal keys hash equal: neighbours in this order
    pair = np.flatnonzero(hashed[order[1:]] == hashed[order[:-1]])
    first, second = order[pair], order[pair + 1]
    corner_found = (triangles[first][:, :, None, :] == triangles[second][:, None, :, :]).all(axis=3).any(axis=2)
    same_corners = (key[first] == key[second]).all(axis=1) & corner_found.all(axis=1)
    # the normals' Y of the paired triangles only (most triangles have no twin)
    normal_first, normal_second = (
        np.cross(triangles[rows, 1] - triangles[rows, 0], triangles[rows, 2] - triangles[rows, 0])[:, 1] for rows in (first, second)
    )
    # a two-sided wall has no up-facing side: the intersector's answer stands there
    facing = same_corners & (np.sign(normal_first) == -np.sign(normal_second)) & (normal_first != 0)
    down = np.where(normal_first < 0, first, second)[facing]
    twin[down] = np.where(normal_first < 0, second, first)[facing]
    return twin


def _closed_bodies(triangles: np.ndarray, twin: np.ndarray) -> np.ndarray:
    """(m,) int64: the label of the closed body each triangle belongs to, -1 for a triangle of none. A closed body
    is wound one way: a set of triangles joined along shared edges (corners at the same coordinates, welded or
    not) in which every edge is walked once each way, by two triangles.

    A crate, a wall slab or a pillar exported as a closed solid is one; a single-sided quad, an open-ended tube, a
    box missing a face, a body with a triangle wound the wrong way, a degenerate triangle's body and a two-sided
    face (:func:`_reversed_twins`, a flat "body" of two) are not. Where closed bodies touch along an edge (more
    than two triangles walk it) its triangles are paired round it (:func:`_paired_round_edges`), so that each body
    stays closed. Cost: sorts of the 3m corners and edges, O(m log m), two connected-components passes (scipy's
    union-find over the edges, O(m)), and the pairing's loop over the edges bodies share.
    """
    m = len(triangles)
    if m == 0:
        return np.zeros(0, dtype=np.int64)
    # one id per distinct corner position (a lexicographic sort: several times faster than numpy's unique rows)
    corners = triangles.reshape(-1, 3)
    by_position = np.lexsort(corners.T[::-1])
    ordered = corners[by_position]
    corner = np.empty(3 * m, dtype=np.int64)
    corner[by_position] = np.cumsum(np.r_[True, (ordered[1:] != ordered[:-1]).any(axis=1)]) - 1
    corner = corner.reshape(m, 3)
    start, end = corner.reshape(-1), corner[:, [1, 2, 0]].reshape(-1)  # edge k of face k // 3, walked start -> end
    low, high = np.minimum(start, end), np.maximum(start, end)
    _, edge, count = np.unique(low * (int(corner.max()) + 1) + high, return_inverse=True, return_counts=True)
    forward = np.bincount(edge, weights=start < end, minlength=len(count))
    good = (count == 2) & (forward == 1)  # two triangles, one walking it each way
    # the two triangles on each good edge: neighbours in the edges' order
    order = np.argsort(edge, kind="stable")
    at = np.flatnonzero((edge[order[1:]] == edge[order[:-1]]) & good[edge[order[1:]]])
    face = np.arange(3 * m) // 3
    join = sparse.coo_matrix((np.ones(len(at)), (face[order[at]], face[order[at + 1]])), shape=(m, m))
    _, piece = csgraph.connected_components(join, directed=False)
    # an edge walked by more than two triangles, as many each way: bodies touching along it (a crate on a crate,
    # a roof slab flush with a wall's outer face, wall modules corner to corner), its triangles paired round it
    shared = np.flatnonzero(((count > 2) & (2 * forward == count))[edge])
    one, other, sound = _paired_round_edges(triangles, shared, edge[shared], start[shared] < end[shared], piece[face[shared]])
    good[np.unique(edge[shared])] = sound
    join = sparse.coo_matrix((np.ones(len(at) + len(one)), (np.r_[face[order[at]], face[one]], np.r_[face[order[at + 1]], face[other]])), shape=(m, m))
    _, body = csgraph.connected_components(join, directed=False)
    bad_face = np.zeros(m, dtype=bool)
    bad_face[face[~good[edge]]] = True
    bad_face[twin >= 0] = True
    bad_face[twin[twin >= 0]] = True
    open_body = np.zeros(body.max() + 1, dtype=bool)
    open_body[body[bad_face]] = True
    return np.where(open_body[body], -1, body).astype(np.int64)


def _paired_round_edges(triangles: np.ndarray, sides: np.ndarray, edge: np.ndarray, forward: np.ndarray,
                        piece: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The triangle sides on edges walked by more than two triangles paired as the bodies they close: turning about
    the edge from a triangle towards its back (the inside of an outward-wound body), the first triangle met that
    walks the edge the other way is the other face of its body there (a wedge of solid lies between the two). Of
    triangles met at one angle (two bodies overlapping with faces flush: wall slabs overlapping at a corner) the
    one joined to it by ordinary edges (``piece``) is taken first.

    Args:
        triangles: (m, 3, 3) corners; ``sides``: (u,) sides (side k of triangle k // 3, from its corner k % 3 to
            the next) on such edges; ``edge``: (u,) their edge; ``forward``: (u,) the side walks it from the lower
            corner id; ``piece``: (u,) the triangle's piece joined by edges two triangles walk.

    Returns:
        ``(one, other, sound)``: (p,) sides paired with (p,) sides, and for each edge (in ``np.unique(edge)``'s
        order) whether every side on it is its partner's partner (else the edge leaves its bodies open).
        O(u log u), and a Python loop over the edges.
    """
    edges, group = np.unique(edge, return_inverse=True)
    if len(sides) == 0:
        return np.zeros(0, np.int64), np.zeros(0, np.int64), np.zeros(0, dtype=bool)
    tri, corner = sides // 3, sides % 3
    a, b = triangles[tri, corner], triangles[tri, (corner + 1) % 3]
    a, b = np.where(forward[:, None], a, b), np.where(forward[:, None], b, a)  # every side from the lower id
    axis = (b - a) / np.linalg.norm(b - a, axis=1, keepdims=True)
    away = triangles[tri, (corner + 2) % 3] - a
    away -= np.einsum("ij,ij->i", away, axis)[:, None] * axis
    away /= np.linalg.norm(away, axis=1, keepdims=True)
    normal = np.cross(triangles[tri, 1] - triangles[tri, 0], triangles[tri, 2] - triangles[tri, 0])
    turn = np.where(np.einsum("ij,ij->i", np.cross(axis, away), normal) < 0, 1.0, -1.0)  # the back's way round
    by_group = np.argsort(group, kind="stable")
    starts = np.searchsorted(group[by_group], np.arange(len(edges)))
    reference = away[by_group[starts]][group]
    angle = np.arctan2(np.einsum("ij,ij->i", away, np.cross(axis, reference)), np.einsum("ij,ij->i", away, reference))
    mate = np.full(len(sides), -1, dtype=np.int64)
    for lo, hi in zip(starts, np.r_[starts[1:], len(sides)]):
        rows = by_group[lo:hi]
        for row in rows:
            others = rows[forward[rows] != forward[row]]
            ahead = np.round((turn[row] * (angle[others] - angle[row])) % (2 * np.pi), 9)
            ahead[ahead == 0] = 2 * np.pi  # the same angle: a face of another body lying on this one
            mate[row] = others[np.lexsort((piece[others] != piece[row], ahead))[0]] if len(others) else -1
    mutual = (mate >= 0) & (mate[np.maximum(mate, 0)] == np.arange(len(sides)))
    sound = np.bincount(group, weights=~mutual, minlength=len(edges)) == 0
    keep = mutual & (np.arange(len(sides)) < mate)
    return sides[keep], sides[mate[keep]], sound


def _plane_keys(triangles: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(key (m, 4) float64, length (m,) float64)``: each triangle's plane as :func:`_flush_pairs` tells planes
    apart (its unit normal, turned so that its first component over a millionth is positive, in millionths, and its
    offset from the origin in ``TOUCHING`` steps, all rounded to integers) and its normal's length before it was made
    a unit (0: a degenerate triangle, in no plane). O(m), one row at a time: a row's key does not depend on the
    other rows, so :func:`_flush_pairs_of` reads the very keys :func:`_flush_pairs` compares."""
    normal = np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0])
    length = np.linalg.norm(normal, axis=1)
    normal /= np.maximum(length, 1e-300)[:, None]
    leading = normal[np.arange(len(normal)), np.argmax(np.abs(normal) > 1e-6, axis=1)]
    normal *= np.where(leading < 0, -1.0, 1.0)[:, None]
    key = np.column_stack([np.round(normal / 1e-6), np.round(np.einsum("ij,ij->i", normal, triangles[:, 0]) / TOUCHING)])
    return key, length


def _flush_pairs(triangles: np.ndarray, bodies: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(face, partner)``, (p,) int64 each, sorted by face: every ordered pair of triangles ((m, 3, 3) corners, m) in
    one plane whose boxes come within ``TOUCHING`` of each other, of two closed bodies (``bodies`` (m,), < 0 for a
    triangle of none) or of a closed body and of none: a crate's side on a wall's face, a roof's bottom on a wall's
    top, a crate's side against a single-sided wall quad. Two triangles of no closed body are not paired (the
    multiple-hit query reports one of them, as it always did).

    A plane is a face's unit normal (either way round) to a millionth and its offset to ``TOUCHING``. Broad phase:
    each triangle's box seen along the axis its normal leans most along (grown by half ``TOUCHING``), its plane's index
    as a third coordinate, paired in a :class:`BoxGrid` of cells of the boxes' median extent; only planes holding
    a closed triangle and triangles of two bodies are binned. Narrow phase: the same plane, two bodies, the 3-D
    boxes within ``TOUCHING``. O(E log E + P) for the E (box, cell) entries and P pairs sharing a cell.
    """
    key, length = _plane_keys(triangles)
    plane = np.unique(key, axis=0, return_inverse=True)[1].reshape(-1)
    owners = np.unique(np.column_stack([plane, bodies]), axis=0)
    shared = np.bincount(owners[:, 0], minlength=plane.max(initial=-1) + 1) >= 2
    holds_closed = np.zeros(len(shared), dtype=bool)
    holds_closed[plane[bodies >= 0]] = True
    shared &= holds_closed
    kept = np.flatnonzero((length > 0) & shared[plane])
    if len(kept) == 0:
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    low, high = triangles[kept].min(axis=1) - 0.5 * TOUCHING, triangles[kept].max(axis=1) + 0.5 * TOUCHING
    # the plane's two other axes, from its rounded normal: the same for all its triangles (a turned wall's normal,
    # x and z equal to float noise, leans most along x in one triangle and along z in the next)
    seen = np.array([[1, 2], [0, 2], [0, 1]])[np.argmax(np.abs(key[kept, :3]), axis=1)]
    rows = np.arange(len(kept))[:, None]
    flat_low, flat_high = low[rows, seen], high[rows, seen]
    extent = (flat_high - flat_low).max(axis=1)
    cell = max(float(np.median(extent)), float(extent.max()) / 4096.0)
    level = plane[kept, None] * (4.0 * cell)  # planes' boxes cells apart (a grid that doubles its cell pairs a few)
    flat_low, flat_high = np.hstack([flat_low, level]), np.hstack([flat_high, level])
    a, b = box_pairs(flat_low, flat_high, flat_low, flat_high, cell)
    near = (plane[kept[a]] == plane[kept[b]]) & (bodies[kept[a]] != bodies[kept[b]])
    a, b = a[near], b[near]
    near = ((low[a] <= high[b]) & (low[b] <= high[a])).all(axis=1)
    face, partner = kept[a[near]], kept[b[near]]
    order = np.lexsort((partner, face))
    return face[order], partner[order]


_PLANE_HASH = np.random.default_rng(1).uniform(0.5, 1.5, 4)
"""Weights of a triangle's four plane key numbers (:func:`_plane_keys`) summed into one: one plane's triangles share
the sum (the same arithmetic on the same numbers), distinct planes rarely do (and are told apart by their keys)."""


def _flush_pairs_of(faces: np.ndarray, triangles: np.ndarray, bodies: np.ndarray, key: np.ndarray, length: np.ndarray,
                    hashed: np.ndarray, budget: int) -> tuple[np.ndarray, np.ndarray, int] | None:
    """:func:`_flush_pairs` of the (k,) distinct triangles ``faces`` alone: ``(face, partner, spent)``, (p,) int64
    each, sorted by face, every pair of the whole mesh's answer whose face is one of ``faces`` and no other, and the
    triangles gathered plus the pairs compared on the way; None when more than
    ``budget`` triangles would be gathered from the asked planes and (face, triangle in its plane) pairs compared.

    The same rule read for the asked planes only: ``key`` and ``length`` (m, 4) and (m,) of :func:`_plane_keys`,
    ``hashed`` (m,) ``key @ _PLANE_HASH``; the triangles of an asked face's plane are those whose sum is one of the
    asked planes' and whose key is its key (all of them: so whether the plane holds two owners, one of them a closed
    body, is the whole mesh's answer); each asked face is compared with every triangle of its plane, owner and
    grown boxes as :func:`_flush_pairs`' narrow phase. O(m log k) for the sums' look-up among the asked planes'
    sorted sums (no sort, no grid of the m triangles), a stable sort of the M triangles of the asked planes by
    plane (O(M log M) on integers; a sort of their keys only where two planes' sums collide) and O(P) for the P
    pairs compared, M + P <= ``budget``.
    """
    sums = np.unique(hashed[faces])
    at = np.minimum(np.searchsorted(sums, hashed), len(sums) - 1)
    members = np.flatnonzero(sums[at] == hashed)  # every triangle of an asked plane, and any whose sum collides
    if len(members) > budget:
        return None
    # one plane a sum unless two keys share it (then the keys' ranks tell the planes apart)
    plane = at[members]
    one_of = np.zeros(len(sums), dtype=np.int64)
    one_of[plane] = members  # a triangle of each sum, whichever the assignment keeps
    if not (key[members] == key[one_of[plane]]).all():
        plane = _row_ranks(key[members])
    by_plane = np.argsort(plane, kind="stable")
    begin = np.searchsorted(plane[by_plane], np.arange(plane.max(initial=-1) + 2))
    # pairs are of two owners, one a closed body: the faces of a plane of one owner, or of none closed, pair nothing
    # and are not compared (as _flush_pairs bins none of them); every plane here holds a triangle
    owner = bodies[members[by_plane]]
    low_owner, high_owner = np.minimum.reduceat(owner, begin[:-1]), np.maximum.reduceat(owner, begin[:-1])
    shared = (low_owner != high_owner) & (high_owner >= 0)
    asked = np.searchsorted(members, faces)  # members is sorted and holds every asked face
    asked = asked[(length[faces] > 0) & shared[plane[asked]]]
    count = begin[plane[asked] + 1] - begin[plane[asked]]
    spent = len(members) + int(count.sum())
    if spent > budget:
        return None
    row = np.repeat(asked, count)
    other = by_plane[np.arange(len(row)) + np.repeat(begin[plane[asked]] - (np.cumsum(count) - count), count)]
    # the grown boxes of _flush_pairs (each row's as there), once per triangle of the asked planes
    corners = triangles[members]
    low, high = corners.min(axis=1) - 0.5 * TOUCHING, corners.max(axis=1) + 0.5 * TOUCHING
    near = (length[members[other]] > 0) & (bodies[members[row]] != bodies[members[other]])
    row, other = row[near], other[near]
    near = ((low[row] <= high[other]) & (low[other] <= high[row])).all(axis=1)
    face, partner = members[row[near]], members[other[near]]
    order = np.lexsort((partner, face))
    return face[order], partner[order], spent


class FlushPartners:
    """The partners of :func:`_flush_pairs` of one mesh's triangles, for the faces a query's rays cross.

    The disconnected-areas warning asks for the faces crossed by its rays from two ground points, a few dozen:
    :func:`_flush_pairs_of` finds those alone. Asking for a whole mesh's worth (the sampling builder's rule over
    every sample) builds the whole mesh's pairs once and reads them after. The two meet at ``m`` (the triangles)
    gathered or compared in all: the queries answered alone may spend that much between them, the first one that
    would go past it builds the whole (O(m log m) with a grid of boxes, several times the cost of those m steps:
    docs/performance.md, "7 December 2026: the warning's closed-solid test on big meshes"). The same pairs either
    way (tests/test_closed_solids.py compares them).

    Args:
        triangles: (m, 3, 3) corners, world coordinates, metres.
        bodies: (m,) :attr:`_Scene.bodies`.
        frame: the frame the patches are given in (:attr:`_Scene.frame`).
    """

    def __init__(self, triangles: np.ndarray, bodies: np.ndarray, frame: LocalFrame) -> None:
        self.triangles, self.bodies, self.frame = triangles, bodies, frame
        self.spent = 0
        """Triangles gathered and pairs compared by the queries answered alone so far (at most m)."""

    @cached_property
    def plane_keys(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(key (m, 4), length (m,), hashed (m,))`` float64: :func:`_plane_keys` of the triangles and each key
        summed with :data:`_PLANE_HASH` (for :func:`_flush_pairs_of`; O(m), once per mesh)."""
        key, length = _plane_keys(self.triangles)
        return key, length, key @ _PLANE_HASH

    @cached_property
    def whole(self) -> tuple[np.ndarray, np.ndarray]:
        """``(starts (m + 1,) int64, partner (p,) int64)``: :func:`_flush_pairs` of all the triangles in CSR form,
        triangle ``f``'s partners ``partner[starts[f]:starts[f + 1]]``."""
        face, partner = _flush_pairs(self.triangles, self.bodies)
        return np.r_[0, np.cumsum(np.bincount(face, minlength=len(self.triangles)))], partner

    def of(self, faces: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(starts (k + 1,) int64, partner (p,) int64, patch (p, 2, 3) float64)``: the partners of the (k,) distinct
        triangles ``faces`` (ascending) in CSR form, ``faces[i]``'s ``partner[starts[i]:starts[i + 1]]`` (ascending),
        and the boxes (local frame) where it and each lie within ``TOUCHING`` of each other. O(m log k) and what
        is left of the budget, or O(k + p) once :attr:`whole` is built."""
        faces = np.asarray(faces, dtype=np.int64)
        alone = None
        if len(faces) == 0:
            alone = np.zeros(0, np.int64), np.zeros(0, np.int64), 0
        elif "whole" not in self.__dict__:  # cached_property keeps its value in the instance's dict
            alone = _flush_pairs_of(faces, self.triangles, self.bodies, *self.plane_keys, budget=len(self.triangles) - self.spent)
        if alone is None:
            starts, partners = self.whole
            count = starts[faces + 1] - starts[faces]
            partner = partners[np.arange(int(count.sum())) + np.repeat(starts[faces] - (np.cumsum(count) - count), count)]
            face = np.repeat(faces, count)
        else:
            face, partner, spent = alone
            self.spent += spent
            count = np.bincount(np.searchsorted(faces, face), minlength=len(faces))
        face_corners, partner_corners = self.frame.to_local(self.triangles[face]), self.frame.to_local(self.triangles[partner])
        patch = np.stack([np.maximum(face_corners.min(axis=1), partner_corners.min(axis=1)) - TOUCHING,
                          np.minimum(face_corners.max(axis=1), partner_corners.max(axis=1)) + TOUCHING], axis=1)
        return np.r_[0, np.cumsum(count)].astype(np.int64), partner, patch


def ray_margin(caster: RayCaster, reach: float) -> float:
    """Metres by which Embree may see a ray away from where it is cast.

    :data:`EPSILON`, plus 1e-6 of the level's size (the level is scaled in
    float32), plus 2^-22 (twice float32's relative rounding: at most half an
    ulp per coordinate) of the farthest coordinate a ray starts at in the
    caster's local frame: the mesh's, plus ``reach`` metres.
    """
    size, farthest = caster.scene.extent
    return EPSILON + 1e-6 * size + 2.0**-22 * (farthest + reach)


def disk_inside(points: np.ndarray, triangles: np.ndarray, radius: float) -> np.ndarray:
    """(n,) bool: the XZ disk of ``radius`` around each point lies inside its triangle's XZ projection.

    Each edge's line must lie at least ``radius`` from the point, on the
    triangle's side (:meth:`FloorTriangles.edge_room`); a triangle seen
    edge-on (no XZ area) contains nothing. ``points`` (n, 3), ``triangles``
    (n, 3, 3), metres.
    """
    room = FloorTriangles(triangles, across=False).edge_room(points, np.arange(len(points)))
    return (room >= radius).all(axis=1)


def _lexsorted(rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(order, starts)``: (n,) the lexicographic order of ``rows`` (n, d), and (n,) bool, where in that order a
    row differs from the one before (the first of each distinct row). numpy's row unique sorts rows as records,
    5 times slower than this one lexsort on millions of triangle corners (7.5 s against 1.5 s for 2.5 M)."""
    order = np.lexsort(rows.T[::-1])
    ordered = rows[order]
    return order, (np.r_[True, (ordered[1:] != ordered[:-1]).any(axis=1)] if len(rows) else np.zeros(0, dtype=bool))


def _row_starts(rows: np.ndarray) -> np.ndarray:
    """(k,) int64: the index of a row of each distinct row of ``rows``, in lexicographic order
    (``rows[_row_starts(rows)]`` is ``np.unique(rows, axis=0)``)."""
    order, starts = _lexsorted(rows)
    return order[starts]


def _row_ranks(rows: np.ndarray) -> np.ndarray:
    """(n,) int64, ``np.unique(rows, axis=0, return_inverse=True)[1]``: each row's rank among the distinct rows
    in lexicographic order."""
    order, starts = _lexsorted(rows)
    ranks = np.empty(len(rows), dtype=np.int64)
    ranks[order] = np.cumsum(starts) - 1
    return ranks


class FloorTriangles:
    """Walkable triangles (m, 3, 3) seen from above, and which one lies across each edge (``across``: computed
    from shared corners; off: none). ``vertex``, when given: (m, 3) int, an id per corner, equal exactly where the
    corners' coordinates are (as :meth:`near` gives them); else found by sorting the 3 m corners."""

    def __init__(self, corners: np.ndarray, across: bool = True, vertex: np.ndarray | None = None) -> None:
        self.corners = corners
        u, v = corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]
        normal_x, normal_y, normal_z = (u[:, 1] * v[:, 2] - u[:, 2] * v[:, 1], u[:, 2] * v[:, 0] - u[:, 0] * v[:, 2],
                                        u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0])
        with np.errstate(divide="ignore", invalid="ignore"):
            self.gradient = np.hypot(normal_x, normal_z) / np.abs(normal_y)
            """(m,) rise per metre of the steepest horizontal direction (inf: a vertical triangle)."""
            # height at (x, z): height0 - (slope_x (x - x0) + slope_z (z - z0))
            self.slope = np.column_stack([normal_x / normal_y, normal_z / normal_y])
        corner_x, corner_z = corners[:, :, 0], corners[:, :, 2]
        self._edge_x = np.roll(corner_x, -1, axis=1) - corner_x
        self._edge_z = np.roll(corner_z, -1, axis=1) - corner_z
        area = self._edge_x[:, 0] * self._edge_z[:, 1] - self._edge_z[:, 0] * self._edge_x[:, 1]
        with np.errstate(divide="ignore", invalid="ignore"):
            # metres inside an edge per unit of the cross product; nan for a triangle with no XZ area
            self._inward = np.where(area != 0, np.sign(area), np.nan)[:, None] / np.hypot(self._edge_x, self._edge_z)
        self.neighbour = np.full((len(corners), 3), -1, dtype=np.int64)
        """(m, 3): the triangle sharing edge i (corner i to corner i + 1), -1 for none (or more than one)."""
        self.neighbour_edge = np.zeros((len(corners), 3), dtype=np.int64)
        """(m, 3): which edge of that triangle it is."""
        if across and len(corners):
            if vertex is None:
                vertex = _row_ranks(corners.reshape(-1, 3)).reshape(-1, 3)
            start, end = vertex, np.roll(vertex, -1, axis=1)
            # an edge's key: its two corner ids, the lower first, as one integer (equal for the edge either way round)
            key = (np.minimum(start, end) * (int(vertex.max()) + 1) + np.maximum(start, end)).reshape(-1)
            order = np.argsort(key, kind="stable")
            group = np.cumsum(np.r_[True, np.diff(key[order]) != 0]) - 1
            pair = np.bincount(group)[group] == 2
            first, second = order[pair][0::2], order[pair][1::2]  # edges 3 f + i sharing their two corners
            self.neighbour_edge.reshape(-1)[first], self.neighbour_edge.reshape(-1)[second] = second % 3, first % 3
            # A neighbour folded back over the triangle (seen from above) does not extend it: none.
            edge, other = np.concatenate([first, second]), np.concatenate([second, first])
            apex = corners.reshape(-1, 3)[other - other % 3 + (other + 2) % 3]  # the other's corner off the edge
            extends = self.edge_room_of(apex, edge) < 0.0
            self.neighbour.reshape(-1)[edge[extends]] = other[extends] // 3

    @classmethod
    def near(cls, mesh: trimesh.Trimesh, faces: np.ndarray, radius: float) -> tuple[FloorTriangles, np.ndarray]:
        """What :meth:`disk_inside` needs for XZ disks of ``radius`` around points on the triangles ``faces`` (n,)
        of ``mesh``: the triangles that may hold such a disk, with every triangle sharing a corner with them (all
        that can lie across their edges), and (n,) each of ``faces`` among them, -1 for a triangle that holds no
        such disk (:meth:`disk_inside` would answer False). Corners are told apart by sorting the mesh's vertices
        (fewer than its 3 m corners: a mesh whose vertices are shared by about 6 triangles has about m / 2).

        A disk nearer than ``radius`` to an edge's line fits only if the triangle across that edge holds a point
        ``radius - room`` beyond the line (``room``: the disk centre's distance inside it, at most the triangle's
        height over that edge), so reaches that far from both of the edge's corners: a triangle with an edge whose
        corners have no triangle with a side that long holds no disk. On a finely tessellated floor (0.2 m
        triangles under a 0.5 m disk) that is every triangle: the neighbours of a few triangles are found, not of
        all m (O(m) to pick them, O(k log k) for the k picked).
        """
        rank = _row_ranks(np.asarray(mesh.vertices, dtype=np.float64))[np.asarray(mesh.faces)]
        triangles = np.asarray(mesh.triangles, dtype=np.float64).reshape(-1, 3, 3)
        xz = triangles[:, :, [0, 2]]
        side = np.roll(xz, -1, axis=1) - xz
        length = np.hypot(side[:, :, 0], side[:, :, 1])  # (m, 3), edge i from corner i to corner i + 1
        with np.errstate(divide="ignore", invalid="ignore"):
            height = np.abs(side[:, 0, 0] * side[:, 1, 1] - side[:, 0, 1] * side[:, 1, 0])[:, None] / length
        reach = np.zeros(int(rank.max(initial=-1)) + 1)
        np.maximum.at(reach, rank.reshape(-1), np.repeat(length.max(axis=1), 3))
        across = np.minimum(reach[rank], reach[np.roll(rank, -1, axis=1)])
        # a millimetre kept for rounding: a triangle kept in vain costs time, one dropped in error a ray
        holds = ((height >= radius) | (across + 1e-3 >= radius - height)).all(axis=1)
        touched = np.zeros(len(reach), dtype=bool)
        touched[rank[holds]] = True
        picked = np.flatnonzero(touched[rank].any(axis=1))
        return cls(triangles[picked], vertex=rank[picked]), np.where(holds[faces], np.searchsorted(picked, faces), -1)

    def edge_room_of(self, points: np.ndarray, edges: np.ndarray) -> np.ndarray:
        """(n,): how far each point lies inside one edge line, ``edges[i]`` = 3 x its triangle + the edge, seen
        from above (metres; nan for a triangle with no XZ area, which no comparison passes)."""
        face, side = np.divmod(edges, 3)
        corner_x, corner_z = self.corners[face, side, 0], self.corners[face, side, 2]
        cross = self._edge_x[face, side] * (points[:, 2] - corner_z) - self._edge_z[face, side] * (points[:, 0] - corner_x)
        return cross * self._inward[face, side]

    def edge_room(self, points: np.ndarray, faces: np.ndarray) -> np.ndarray:
        """(n, 3): :meth:`edge_room_of` each point for each edge of its triangle ``faces[i]``."""
        edges = (3 * np.asarray(faces)[:, None] + np.arange(3)).reshape(-1)
        return self.edge_room_of(np.repeat(points, 3, axis=0), edges).reshape(-1, 3)

    def _drop(self, points: np.ndarray, faces: np.ndarray, clearance: float) -> np.ndarray:
        """(n,): metres the triangle's plane lies farthest above or below the point's height within ``clearance``
        of it horizontally."""
        corner = self.corners[faces, 0]
        offset = points[:, [0, 2]] - corner[:, [0, 2]]
        height = corner[:, 1] - (self.slope[faces] * offset).sum(axis=1)
        return np.abs(height - points[:, 1]) + clearance * self.gradient[faces]

    def disk_inside(self, points: np.ndarray, faces: np.ndarray, radius: float, clearance: float) -> tuple[np.ndarray, np.ndarray]:
        """``(inside, drop)``: (n,) bool, the XZ disk of ``radius`` around each point lies inside its triangle
        ``faces[i]``, or inside it and, for each edge whose line is nearer than ``radius``, the triangle across
        that edge (every point of the disk beyond that edge is then inside that triangle); (n,) metres, the
        largest :meth:`_drop` of those triangles over ``clearance``. Seen from above."""
        room = self.edge_room(points, faces)
        inside = (room >= 0.0).all(axis=1)  # nan (no XZ area) compares false
        drop = np.where(inside, self._drop(points, faces, clearance), np.inf)
        for edge in range(3):
            rows = np.nonzero(inside & (room[:, edge] < radius))[0]
            other = self.neighbour[faces[rows], edge]
            beyond = np.full((len(rows), 3), np.nan)
            beyond[other >= 0] = self.edge_room(points[rows[other >= 0]], other[other >= 0])
            # the shared edge bounds the own triangle's side: only the other two count
            beyond[np.arange(len(rows)), self.neighbour_edge[faces[rows], edge]] = np.inf
            fits = (other >= 0) & (beyond >= radius).all(axis=1)
            inside[rows[~fits]] = False
            drop[rows[fits]] = np.maximum(drop[rows[fits]], self._drop(points[rows[fits]], other[fits], clearance))
        return inside, drop


MAX_FLOOR_CELL_ENTRIES = 4_000_000
"""(triangle, cell) pairs at most in :class:`OpenFloors`' broad phase; more and the cells are made larger."""


class BoxGrid:
    """Boxes ``lo[j]..hi[j]`` ((m, d) m) binned once into the cells of a d-dimensional grid of cubes, for a broad
    phase asked many times (:meth:`pairs`): every box overlapping one of them shares a cell with it.

    Args:
        lo, hi: (m, d) metres, the boxes' lowest and highest corners.
        cell: edge of a cell, metres; doubled while the boxes would fill more than ``MAX_FLOOR_CELL_ENTRIES``
            cells.

    Only the occupied cells are kept (their keys sorted, and each one's boxes, in CSR form: offsets into one array
    of box indices): built in O(E log E) for the E (box, cell) entries, whatever the grid's extent.
    """

    def __init__(self, lo: np.ndarray, hi: np.ndarray, cell: float) -> None:
        self.origin = lo.min(axis=0) if len(lo) else np.zeros(lo.shape[1])
        while True:
            first, last = self._span(lo, hi, cell)
            if int(np.prod(last - first + 1, axis=1).sum()) <= MAX_FLOOR_CELL_ENTRIES:
                break
            cell *= 2.0
        self.cell = cell
        """Metres, the cells' edge after doubling."""
        self.shape = tuple(int(size) for size in last.max(axis=0, initial=0) + 1)
        owner, key, at_first = self._cells_of(first, last)
        self._keys, column = np.unique(key, return_inverse=True)
        column = column.reshape(-1)
        order = np.argsort(column, kind="stable")
        self._boxes, self._at_first = owner[order], at_first[order]
        """(E,) int64 and uint8: the boxes of occupied cell k are ``_boxes[_offsets[k]:_offsets[k + 1]]``, with
        :meth:`_cells_of`'s bits of the axes along which that cell is the box's first."""
        self._offsets = np.concatenate([[0], np.cumsum(np.bincount(column, minlength=len(self._keys)))])

    def _span(self, lo: np.ndarray, hi: np.ndarray, cell: float) -> tuple[np.ndarray, np.ndarray]:
        """(n, d) int64 each: the first and last cell each box covers along each axis."""
        return tuple(np.floor((corner - self.origin) / cell).astype(np.int64) for corner in (lo, hi))

    def _cells_of(self, first: np.ndarray, last: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(owner, key, at_first)``: one row per (box, cell) it covers, the box's index, the cell's flat index and
        a uint8 with bit ``axis`` set where the cell is the box's first along that axis."""
        spans = last - first + 1
        total = np.prod(spans, axis=1)
        owner = np.repeat(np.arange(len(first)), total)
        k = np.arange(int(total.sum())) - np.repeat(np.cumsum(total) - total, total)
        index = np.empty((len(owner), len(self.shape)), dtype=np.int64)
        at_first = np.zeros(len(owner), dtype=np.uint8)
        for axis in reversed(range(len(self.shape))):  # k counts the box's cells with the last axis fastest
            step = k % spans[owner, axis]
            index[:, axis] = first[owner, axis] + step
            at_first |= (step == 0).astype(np.uint8) << axis
            k = k // spans[owner, axis]
        return owner, np.ravel_multi_index(tuple(index.T), self.shape), at_first

    def pairs(self, lo: np.ndarray, hi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``(i, j)`` int64 arrays: the pairs of a box ``lo[i]..hi[i]`` ((n, d) m) and a binned box ``j`` that share
        a cell, each once, in no particular order; every overlapping pair is among them. The boxes are clipped to
        the grid (the binned boxes lie within it), their cells looked up among the occupied ones and each such
        cell's boxes gathered; a pair is kept in one cell of the several it may share, the one with the lowest
        index along every axis (the larger of the two boxes' first cells: along each axis the cell is one box's
        first or the other's). O(C log K + P) for the C cells the clipped boxes cover, the K occupied cells and the
        P (box, binned box) entries sharing a cell, whatever the number of binned boxes (a sparse product of cells
        x boxes matrices would allocate a row of all of them per call)."""
        if len(self._keys) == 0:
            return np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64)
        first, last = self._span(lo, hi, self.cell)
        inside = np.flatnonzero(np.all((last >= 0) & (first < self.shape), axis=1))
        top = np.array(self.shape) - 1
        owner, key, at_first = self._cells_of(np.clip(first[inside], 0, top), np.clip(last[inside], 0, top))
        column = np.minimum(np.searchsorted(self._keys, key), len(self._keys) - 1)
        occupied = self._keys[column] == key
        owner, at_first, column = owner[occupied], at_first[occupied], column[occupied]
        begin, count = self._offsets[column], self._offsets[column + 1] - self._offsets[column]
        entry = np.arange(int(count.sum())) + np.repeat(begin - (np.cumsum(count) - count), count)
        once = (np.repeat(at_first, count) | self._at_first[entry]) == (1 << len(self.shape)) - 1
        return inside[np.repeat(owner, count)[once]], self._boxes[entry[once]]


def box_pairs(lo: np.ndarray, hi: np.ndarray, other_lo: np.ndarray, other_hi: np.ndarray,
              cell: float) -> tuple[np.ndarray, np.ndarray]:
    """``(i, j)`` int64 arrays: :meth:`BoxGrid.pairs` of the boxes ``lo..hi`` ((n, d) m) with a :class:`BoxGrid`
    of ``other_lo..other_hi`` ((m, d) m) and ``cell`` metres, for a single query."""
    return BoxGrid(other_lo, other_hi, cell).pairs(lo, hi)


class OpenFloors:
    """Walkable triangles with nothing else near them up to the agent's height: open floor, where a walk needs no ray.

    A triangle T is open when every other triangle of the caster's mesh
    either lies outside the height range from T's lowest corner down by
    ``EPSILON`` to its highest corner up by the agent's height plus
    ``2 EPSILON`` (both grown by :attr:`margin`), or does not overlap, seen
    from above, T shrunk by :attr:`margin` (an exact separating-axis test of
    the two XZ projections). A point stands on T (:meth:`faces_under`) when
    it lies at least ``2 margin`` inside T's edges seen from above and within
    ``max_offset`` (at most ``EPSILON``) of T's plane. Only triangles whose
    XZ inradius exceeds ``min_inradius`` (metres) are looked at: a caller
    whose walks are longer than that skips the many small triangles that
    would seldom hold both ends of one (a level of 1 m floor tiles).

    For two points A, C on the same open T, every ray of
    :func:`walks_in_batch` (lifted by half the agent height, more than
    ``2 (EPSILON + margin)``) between them stays at least a margin away from
    every other triangle over T, and from T itself: the lifted segment meets
    nothing within its length, each downward ray lands on T (walkable), at
    ``line height + half the agent height - ground`` where the ground is T's
    plane, and each upward ray finds at least the agent's height of room over
    that ground. The ground under the line then lies within ``max_offset``
    of it, and rises along it no faster than T, a walkable slope: the walk
    passes whenever ``max_offset`` is within the climb plus the ground margin
    and the surface-gap tolerance (:meth:`certain_offset`).
    """

    def __init__(self, caster: RayCaster, agent: AgentShape, min_inradius: float = 0.0) -> None:
        self.caster, self.agent, self.min_inradius = caster, agent, min_inradius
        self.margin = ray_margin(caster, agent.height + 2.0 * EPSILON)
        """Metres (:func:`ray_margin` over the highest ray start, the agent's height over the floor)."""
        self.open = caster.scene.open_floors.get((agent, min_inradius))
        """(m,) bool per triangle of the caster's mesh, read-only: found once per mesh, agent and ``min_inradius``
        (kept in :attr:`RayCaster.scene`; the sampling builder's and the ``mesh_los`` predicate's are the same with
        the builder's default spacing, and the predicate took 0.9 s of CPU to find them again on a 20k-polygon
        level and a transient 0.22-0.31 GiB: docs/performance.md, samp5_48 and mem48)."""
        if self.open is None:
            walkable = np.nonzero(caster.walkable_faces(np.arange(len(caster.triangles)), agent.max_slope_deg))[0]
            tall_enough = 0.5 * agent.height > 2.0 * (EPSILON + self.margin)
            found = np.zeros(len(caster.triangles), dtype=bool)
            if tall_enough and len(walkable):
                found[walkable[~self._crowded(walkable)]] = True
            found.flags.writeable = False
            self.open = caster.scene.open_floors[(agent, min_inradius)] = found

    def _crowded(self, floors: np.ndarray) -> np.ndarray:
        """(k,) bool: the walkable triangles ``floors`` that are too small or that another triangle comes near."""
        corners, margin = self.caster.triangles, self.margin
        # Shrunk by the margin: towards the incentre, by the margin over the inradius.
        xz = corners[floors][:, :, [0, 2]]
        sides = np.linalg.norm(np.roll(xz, -1, axis=1) - np.roll(xz, 1, axis=1), axis=2)
        u, v = xz[:, 1] - xz[:, 0], xz[:, 2] - xz[:, 0]
        perimeter = sides.sum(axis=1)
        with np.errstate(divide="ignore", invalid="ignore"):
            inradius = np.abs(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]) / perimeter
        crowded = ~(inradius > max(2.0 * margin, self.min_inradius))
        roomy = np.nonzero(~crowded)[0]
        if len(roomy) == 0:
            return crowded
        xz, sides, perimeter, inradius = xz[roomy], sides[roomy], perimeter[roomy], inradius[roomy]
        centre = np.einsum("ki,kij->kj", sides, xz) / perimeter[:, None]
        shrunk = centre[:, None, :] + (xz - centre[:, None, :]) * ((inradius - margin) / inradius)[:, None, None]
        low = corners[floors[roomy], :, 1].min(axis=1) - EPSILON
        high = corners[floors[roomy], :, 1].max(axis=1) + self.agent.height + 2.0 * EPSILON
        floor, other = self._neighbours(floors[roomy])
        others = corners[other]
        near = (floors[roomy][floor] != other) & (others[:, :, 1].min(axis=1) - margin <= high[floor])
        near &= others[:, :, 1].max(axis=1) + margin >= low[floor]
        floor, other = floor[near], other[near]
        overlapping = ~_separated(shrunk[floor], others[near][:, :, [0, 2]])
        crowded[roomy[floor[overlapping]]] = True
        return crowded

    def _neighbours(self, floors: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``(floor, other)``: the pairs of an index into ``floors`` and a triangle whose XZ boxes, grown by the
        margin, overlap (a broad phase: a triangle whose box lies apart from a floor's lies farther than two margins
        from it, and from the floor shrunk by the margin, which :func:`_separated` tells too).

        The floors are binned, in cells of half their boxes' median larger side, every triangle's box looked up and
        the pairs sharing a cell kept where the boxes overlap: the floors asked about are the few large ones (on the
        2,000-room dungeon 8,578 of 280,704 triangles), and binning all the triangles in cells of their own median
        size cost 0.49 s of CPU there against 0.08 s."""
        xz = self.caster.triangles[:, :, [0, 2]]
        lo, hi = xz.min(axis=1) - self.margin, xz.max(axis=1) + self.margin
        extent = float((hi.max(axis=0) - lo.min(axis=0)).max())
        cell = max(0.5 * float(np.median((hi[floors] - lo[floors]).max(axis=1))), extent / 4096.0, 1e-6)
        other, floor = box_pairs(lo, hi, lo[floors], hi[floors], cell)
        overlap = np.all((lo[other] <= hi[floors[floor]]) & (lo[floors[floor]] <= hi[other]), axis=1)
        return floor[overlap], other[overlap]

    def faces_under(self, points: np.ndarray, max_offset: float = EPSILON, room: float = 0.0) -> np.ndarray:
        """(n,) int64: the open triangle each point stands on (see the class; ``max_offset`` in metres, at most
        ``EPSILON``), -1 where there is none; with ``room`` (metres), only where the point lies that much farther
        inside the triangle's edges, so that a walk of :func:`walks_in_batch` with ``half_width`` up to ``room``
        between two such points also passes (its side lines stay over the triangle). One downward ray per point,
        from ``2 EPSILON`` above it."""
        points = np.asarray(points, dtype=np.float64).reshape(-1, 3)
        faces = np.full(len(points), -1, dtype=np.int64)
        if not self.open.any() or len(points) == 0:
            return faces
        face = self.caster.first_hits(points + 2.0 * EPSILON * UP, -UP).face
        on = (face >= 0) & self.open[np.maximum(face, 0)]
        rows, face = np.nonzero(on)[0], face[on]
        triangles = self.caster.triangles[face]
        normal = self.caster.face_normals[face]
        offset = points[rows] - triangles[:, 0]
        # Height above the plane: the normal's Y is positive (a walkable triangle).
        above = np.einsum("ij,ij->i", offset, normal) / normal[:, 1]
        good = disk_inside(points[rows], triangles, 2.0 * self.margin + room) & (np.abs(above) <= min(max_offset, EPSILON))
        faces[rows[good]] = face[good]
        return faces

    def certain_offset(self, margin: float, max_gap: float | None) -> float:
        """Metres a point may lie off its open triangle's plane for :func:`walks_in_batch` (``margin``, ``max_gap``)
        to pass between any two such points on it (a millionth of a metre kept for rounding)."""
        limit = min(EPSILON, self.agent.max_climb + margin, max_gap if max_gap is not None else math.inf)
        return limit - 1e-6


def _separated(first: np.ndarray, second: np.ndarray) -> np.ndarray:
    """(n,) bool: the 2-D triangles ``first[i]`` and ``second[i]`` ((n, 3, 2) each; the second may be degenerate)
    have a separating line along one of their six edges (for two convex polygons, exactly when they do not meet)."""
    corners = np.concatenate([first, second], axis=1).transpose(1, 2, 0)  # (6 corners, 2, n)
    apart = np.zeros(len(first), dtype=bool)
    for triangle in (0, 3):
        for i in range(3):
            start, end = corners[triangle + i], corners[triangle + (i + 1) % 3]
            dx, dz = end[0] - start[0], end[1] - start[1]
            # every corner projected on the edge's normal (-dz, dx)
            along = [dx * corner[1] - dz * corner[0] for corner in corners]
            a_low, a_high = np.minimum(np.minimum(along[0], along[1]), along[2]), np.maximum(np.maximum(along[0], along[1]), along[2])
            b_low, b_high = np.minimum(np.minimum(along[3], along[4]), along[5]), np.maximum(np.maximum(along[3], along[4]), along[5])
            apart |= (a_high < b_low) | (b_high < a_low)
    return apart


def all_hits_down(caster: RayCaster, xz: np.ndarray, top: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Every point where vertical lines through ``xz`` cross the caster's mesh, from ``top`` down.

    One batched multiple-hit query (Embree when available).

    Returns:
        ``(column, point, face)``: (m,) index into ``xz``, (m, 3) crossing
        points, (m,) triangle indices. Order: by column, then from the top down.
    """
    xz = np.asarray(xz, dtype=np.float64).reshape(-1, 2)
    origins = np.column_stack([xz[:, 0], np.full(len(xz), top), xz[:, 1]])
    column, _, face, locations = caster.all_hits(origins, -UP)
    order = np.lexsort((-locations[:, 1], column))
    return column[order], locations[order], face[order]


@dataclass(frozen=True)
class AgentShape:
    """The agent settings the walk tests use (metres, degrees)."""

    radius: float
    height: float
    max_climb: float
    max_slope_deg: float
    step_gap: float | None = None
    """Metres: a probe over a gap narrower than this between walkable ground on both sides stands on the nearer
    side's ground (:func:`ground_beside`); ``None`` or 0: the crack rule alone (:func:`crack_sides`)."""
    body_walls: bool = True
    """The sampling builder's clearance check also finds walls between its three wall rays, in the agent's body slab
    (:attr:`body`; ``sampling.curtains_crossed``); False: at the three rays only (the paper preset)."""

    @classmethod
    def from_config(cls, agent: Any) -> AgentShape:
        """From a :class:`g2s_core.config.AgentConfig` (or anything with the same attributes)."""
        return cls(float(agent.radius), float(agent.height), float(agent.max_climb), float(agent.max_slope))

    @property
    def tan_slope(self) -> float:
        return math.tan(math.radians(self.max_slope_deg))

    def max_rise(self, horizontal: np.ndarray | float) -> np.ndarray | float:
        """Largest height change over ``horizontal`` metres: a step (max climb) or the steepest slope."""
        return np.maximum(self.max_climb, self.tan_slope * np.asarray(horizontal))

    @property
    def body(self) -> tuple[float, float]:
        """``(knee, head)``, metres above the agent's ground: the slab in which a steep face stops it, from above its
        step (max climb + ``GROUND_MARGIN``) to just under its height (5 ``EPSILON``); the lowest and highest of the
        sampling builder's wall rays."""
        return min(self.max_climb + GROUND_MARGIN, self.height - EPSILON), self.height - 5 * EPSILON


def clear_above(caster: RayCaster, origins: np.ndarray, needed: np.ndarray | float) -> np.ndarray:
    """(n,) bool: nothing lies within ``needed`` metres straight above each origin (one upward ray each)."""
    origins = np.asarray(origins, dtype=np.float64).reshape(-1, 3)
    return has_room(caster.first_hits(origins, UP).distance, needed)


def hit_from_behind(caster: RayCaster, hits: Hits) -> np.ndarray:
    """(n,) bool: each ray of ``hits`` met its first triangle on the back side (the triangle's normal points
    along the ray, as a closed body's outward-wound walls do seen from inside); False where it met nothing."""
    behind = hits.hit
    behind[behind] = np.einsum("ij,ij->i", caster.face_normals[hits.face[behind]], hits.unit[behind]) > 0.0
    return behind


def back_face_lead(caster: RayCaster, origins: np.ndarray, direction: np.ndarray,
                   winding: np.ndarray | None = None) -> np.ndarray:
    """(n,) int64: along each ray, the most by which the triangles met on their back side outnumber those met from
    the front, over its first k crossings (:meth:`RayCaster.all_hits` and :func:`flush_crossings`), k from 1 up to
    and including the first crossing of a triangle of no closed body (:func:`_closed_bodies`; the ray's end if
    none); 0 when they never do.

    Seen from inside outward-wound closed bodies, a crossing from behind leaves one and one from the front enters
    one, so the count after k crossings is how many bodies the start lies in less how many the k-th crossing's far
    side lies in: it reaches 1 where the ray leaves a body holding its start, whatever other bodies it entered and
    left on the way (the first crossing is that body's own face unless the face lies buried in another body: a
    wall, a floor, a ceiling, a crate it overlaps). A triangle of no closed body (a single-sided quad, a flight of
    open risers) pairs with nothing, so the count stops at the first one: its side is its answer, as for a first
    hit. Of a two-sided face the up-facing side counts (:meth:`RayCaster.first_hits`' rule); a triangle the ray
    runs along counts 0.

    Faces in one plane (a crate against a wall, a crate on a crate, a pillar's top in a ceiling's bottom) are all
    crossed (:func:`flush_crossings` adds those the multiple-hit query stepped past), and crossings within
    ``SAME_PLACE`` of each other are one place, at which back faces count first, and of one side closed bodies'
    faces before a face of none: leaving a body there means the ray's start lies in at least one, whatever is
    entered at the same place (a count of n bodies at the start less n - 1 past the face), so the answer does not
    hang on which face the intersector reports, or lists, first.

    Args:
        origins: (n, 3) ray starts, metres.
        direction: (3,) the rays' direction (any non-zero length).
        winding: (m,) :attr:`_Scene.winding` to read closed bodies wound inside out as if wound outward (a face's
            side times its body's sign; a triangle of no closed body, sign 0, then ends the count at 0: its side
            tells nothing once the mesh's winding is not trusted); none: each face's side as it is wound.

    Cost: one multiple-hit query (one intersector pass per crossing depth), :func:`flush_crossings`, and an
    O(c log c) sort of the c crossings; a batch that crosses nothing costs the query alone.
    """
    origins = np.asarray(origins, dtype=np.float64).reshape(-1, 3)
    ray, distance, face, points = caster.all_hits(origins, direction)
    lead = np.zeros(len(origins), dtype=np.int64)
    if len(ray) == 0:
        return lead
    unit = np.asarray(direction, dtype=np.float64) / np.linalg.norm(direction)
    more = flush_crossings(caster, origins, unit, ray, face, points)
    stepped_past = np.r_[np.zeros(len(ray), dtype=bool), np.ones(len(more[0]), dtype=bool)]
    ray, distance, face = (np.concatenate(pair) for pair in zip((ray, distance, face), more))
    owner = caster.scene.bodies[face]
    face = np.where(caster.scene.twin[face] >= 0, caster.scene.twin[face], face)
    # each face's side as its corners are wound, the order the closed bodies and their winding are read from (a
    # mesh's stored normals can disagree: trimesh's invert() leaves them as they were)
    corners = caster.triangles[face]
    wound = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    wound /= np.maximum(np.linalg.norm(wound, axis=1, keepdims=True), 1e-300)
    sign = np.where(np.abs(wound @ unit) < 1e-9, 0, np.sign(wound @ unit)).astype(np.int64)
    if winding is not None:
        sign = sign * winding[face]
    order = np.lexsort((distance, ray))
    place = np.cumsum(np.r_[True, (ray[order][1:] != ray[order][:-1]) | (np.diff(distance[order]) > SAME_PLACE)])
    # a body (or the triangles of none) crossed once a place: of a flush face's two triangles met on the edge
    # between them, or a face the query did report, the one crossing counts
    by_owner = np.lexsort((stepped_past[order], owner[order], place))
    first = np.r_[True, (place[by_owner][1:] != place[by_owner][:-1]) | (owner[order][by_owner][1:] != owner[order][by_owner][:-1])]
    keep = np.ones(len(order), dtype=bool)
    keep[by_owner] = first | ~stepped_past[order][by_owner]
    order, place = order[keep], place[keep]
    unpaired = ~caster.scene.closed[face]
    order = order[np.lexsort((unpaired[order], -sign[order], place))]  # in each place, back faces first
    ray, sign, unpaired = ray[order], sign[order], unpaired[order]
    starts = np.flatnonzero(np.r_[True, ray[1:] != ray[:-1]])
    lengths = np.diff(np.r_[starts, len(ray)])

    def running(values: np.ndarray) -> np.ndarray:
        """Each ray's running sum of ``values`` (one a crossing, in order along the ray)."""
        total = np.cumsum(values)
        return total - np.repeat(total[starts] - values[starts], lengths)

    counted = running(unpaired.astype(np.int64)) - unpaired <= 0  # up to the first unpaired crossing
    count = np.where(counted, running(sign), np.iinfo(np.int64).min)
    lead[ray[starts]] = np.maximum(np.maximum.reduceat(count, starts), 0)
    return lead


def flush_crossings(caster: RayCaster, origins: np.ndarray, unit: np.ndarray, ray: np.ndarray, face: np.ndarray,
                    points: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(ray, distance, face)``: the crossings :meth:`RayCaster.all_hits` stepped past (origins (n, 3) m, ``unit``
    (3,) their direction; its answer ``ray``, ``face`` (c,) and ``points`` (c, 3) m). The multiple-hit query steps
    past each crossing before it looks for the next, so of two faces in one plane where they overlap it reports
    one; the other is a partner of the one reported (:meth:`FlushPartners.of`) whose patch holds the crossing, and the
    ray crosses it (the Moller-Trumbore test: T. Moller and B. Trumbore, "Fast, minimum storage ray-triangle
    intersection", Journal of Graphics Tools 2(1), 1997; its edges included, so a crossing on the edge between a
    face's two triangles is found on both: :func:`back_face_lead` counts a body once a place).

    Nothing is cast again: O(c log c + q) for the q (crossing, partner) pairs of the crossings' faces, and
    :meth:`FlushPartners.of` of the faces crossed.
    """
    faces, face = np.unique(face, return_inverse=True)  # the partners of each face crossed, once
    starts, partners, patches = caster.scene.flush.of(faces)
    count = starts[face + 1] - starts[face]
    row = np.repeat(np.arange(len(face)), count)
    pair = np.arange(len(row)) + np.repeat(starts[face] - (np.cumsum(count) - count), count)
    local = caster.frame.to_local(points[row])
    inside = ((local >= patches[pair, 0]) & (local <= patches[pair, 1])).all(axis=1)
    row, partner = row[inside], partners[pair[inside]]
    start = caster.frame.to_local(origins[ray[row]])
    corners = caster.frame.to_local(caster.triangles[partner])
    side, other = corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]
    across = np.cross(unit, other)
    determinant = np.einsum("ij,ij->i", side, across)
    flat = np.abs(determinant) <= 1e-12 * np.linalg.norm(side, axis=1) * np.linalg.norm(other, axis=1)
    determinant = np.where(flat, 1.0, determinant)
    offset = start - corners[:, 0]
    u = np.einsum("ij,ij->i", offset, across) / determinant
    turned = np.cross(offset, side)
    v = (turned @ unit) / determinant
    distance = np.einsum("ij,ij->i", other, turned) / determinant
    tolerance = 1e-9
    crossed = ~flat & (u >= -tolerance) & (v >= -tolerance) & (u + v <= 1.0 + tolerance) & (distance >= 0.0)
    return ray[row[crossed]], distance[crossed], partner[crossed]


SOLID_DIRECTIONS = COMPASS[::2]
"""The horizontal directions (+x, +z, -x, -z) :func:`closed_solid_holds` looks along."""


def closed_solid_holds(caster: RayCaster, points: np.ndarray, height: float, needed: int = 5,
                       winding: np.ndarray | None = None) -> np.ndarray:
    """(n,) bool: each ground point (n, 3) lies inside a closed solid: along at least ``needed`` of five rays, the
    one straight up from ``EPSILON`` over it and those along +x, +z, -x and -z from ``height / 2`` over it (rays of
    unlimited length; ``height`` the agent's, metres), back faces come to outnumber front faces
    (:func:`back_face_lead`, with ``winding``).

    The sampling builder's rule needs all five
    (:func:`g2s_plugins.graph_builders.sampling.inside_closed_solids`); the disconnected-areas warning's four, with
    each body's winding (:func:`g2s_plugins.area_gaps.shut_in`).

    Cost: the upward query for every point, then each horizontal one for the points that can still reach
    ``needed`` (all five: those that led along every ray so far).
    """
    points = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    misses = np.zeros(len(points), dtype=np.int64)
    rows = np.arange(len(points))
    for lift, direction in [(EPSILON, UP)] + [(0.5 * height, way) for way in SOLID_DIRECTIONS]:
        misses[rows[back_face_lead(caster, points[rows] + lift * UP, direction, winding) <= 0]] += 1
        rows = rows[misses[rows] <= len(SOLID_DIRECTIONS) + 1 - needed]
    inside = np.zeros(len(points), dtype=bool)
    inside[rows] = True
    return inside


def has_room(distance: np.ndarray, needed: np.ndarray | float) -> np.ndarray:
    """(n,) bool: upward rays that hit at ``distance`` (metres, ``inf``: nothing) leave ``needed`` metres free."""
    return distance >= np.asarray(needed, dtype=np.float64) - HEIGHT_TOLERANCE


def head_room(caster: RayCaster, ground: np.ndarray, agent: AgentShape) -> np.ndarray:
    """(n,) bool: nothing lies within the agent's height above the ground points (one upward ray each)."""
    ground = np.asarray(ground, dtype=np.float64).reshape(-1, 3)
    return clear_above(caster, ground + EPSILON * UP, agent.height - EPSILON)


def ground_across_crack(
    caster: RayCaster,
    probes: np.ndarray,
    down: np.ndarray,
    sides: list[np.ndarray],
    reach: float | np.ndarray,
    walkable: Callable[[np.ndarray], np.ndarray],
    steps: tuple[float, ...] = (1.0,),
) -> tuple[np.ndarray, np.ndarray]:
    """Which probes that found no ground of their own stand on ground across a crack, and how far below.

    A probe over a crack (a grating's slots, unwelded tiles laid apart) stands on the floor beside
    it, as the agent's foot does: where walkable ground lies within ``reach`` along ``down`` on
    both sides of it, for the first of ``sides`` where it does. Each side is tried apart, at
    ``probe + f side`` and at ``probe - f side`` for each fraction ``f`` of ``steps`` in turn until
    one finds ground; with the default ``steps`` the two sides are tried as a pair, one side long
    (the ``entry_exit`` selector's search for the floor's end, docs/entry_exit.md, "A ninth round of
    piece kinds", causes 2 and 3). The sampling route's walk test (:func:`walks_in_batch`) and
    ledge probes (the sampling builder's ``agent_fits``) try :data:`CRACK_STEPS` of
    :func:`crack_sides`: across slots of a period just over a crack step (bars and slots 0.03 m,
    the step 0.05 m) a step either way lands in a slot on one side or the other wherever the probe
    stands in a slot, and half a step finds the bar the step overshoots (docs/entry_exit.md,
    "The grating's end on the sampling route"). Beyond a floor's edge ground lies on one side at
    most, and a hole wider than twice the longest step (r / 4 for :func:`crack_sides`) stays a
    hole: a probe in it lies more than a step from ground on one side at least.

    Args:
        caster: the level's ray caster.
        probes: (n, 3) ray origins, metres.
        down: (3,) or (n, 3) the rays' directions.
        sides: offsets tried in turn, each (3,) or (n, 3), metres: one crack step long.
        reach: longest ray that finds ground, metres: one for all, or (n,) one a probe.
        walkable: (m,) hit faces (-1: none) -> (m,) bool, the faces the caller's agent stands on.
        steps: fractions of each side at which its two sides are tried, nearest first.

    Returns:
        ``(on, distance)``: (n,) bool, the probe stands on ground across a crack; (n,) metres along
        ``down`` to the nearer side's ground (``inf`` where not on).

    Two rays a probe, side and step at most (a side that found ground tries no further step):
    O(n len(sides) len(steps)) rays. A batch of at most ``JOINT_CALL_MAX_RAYS`` rays for all of them
    (the walk test's: a few dozen probes) casts every side, step and direction in one call instead,
    the rays the rule would not have needed too: such a batch costs mostly per call (up to four calls
    of 0.8 ms a batch before, docs/performance.md, samp5_48), and a ray's answer is its own however
    it is cast (:meth:`RayCaster.first_hits_of`), so the rule's answer is the same; ``caster.rays_cast``
    counts the rays the rule needs either way, so a count does not depend on how the probes were batched.
    """
    probes = np.asarray(probes, dtype=np.float64).reshape(-1, 3)
    n = len(probes)
    down = np.broadcast_to(np.asarray(down, dtype=np.float64), (n, 3))
    offsets = [np.broadcast_to(np.asarray(side, dtype=np.float64), (n, 3)) for side in sides]
    reach = np.broadcast_to(np.asarray(reach, dtype=np.float64), (n,))
    # metres along down to walkable ground within reach, by side, step, direction (ahead of and behind the side)
    # and probe: inf where the ray found none, or was not cast because the rule did not need it
    along = np.full((len(sides), len(steps), 2, n), np.inf)
    if along.size <= JOINT_CALL_MAX_RAYS:
        hits = caster.first_hits_of([(probes + sign * fraction * offset, down) for offset in offsets for fraction in steps
                                     for sign in (1.0, -1.0)])
        face, distance = np.concatenate([hit.face for hit in hits]), np.concatenate([hit.distance for hit in hits])
        ground = (distance <= np.tile(reach, along.size // max(n, 1))) & walkable(face)
        along.reshape(-1)[ground] = distance[ground]
        caster.rays_cast -= along.size - _rays_needed(along)  # counted as the rule's rays, whatever the batches
    for s, offset in enumerate(offsets if along.size > JOINT_CALL_MAX_RAYS else ()):  # only the rays needed
        rows = np.flatnonzero(~_crack_ground(along[:s])[0])
        if len(rows) == 0:
            break
        for f, fraction in enumerate(steps):
            looking = [rows[np.isinf(along[s, :f, k][:, rows]).all(axis=0)] for k in range(2)]
            beside = caster.first_hits_of([(probes[looking[k]] + sign * fraction * offset[looking[k]], down[looking[k]])
                                           for k, sign in enumerate((1.0, -1.0))])
            for k, hit in enumerate(beside):
                ground = (hit.distance <= reach[looking[k]]) & walkable(hit.face)
                along[s, f, k, looking[k][ground]] = hit.distance[ground]
    return _crack_ground(along)


def _rays_needed(along: np.ndarray) -> int:
    """How many of the rays of ``along`` (see :func:`_crack_ground`) the crack rule casts ray by ray: a side's rays
    for the probes no earlier side put on ground, a step's for the directions no earlier step found ground in."""
    found = np.isfinite(along)
    earlier = np.cumsum(found, axis=1) - found > 0  # (sides, steps, 2, n): an earlier step of the side found ground
    off = np.stack([~_crack_ground(along[:s])[0] for s in range(len(along))])[:, None, None, :]  # not on before it
    return int((off & ~earlier).sum())


def _crack_ground(along: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """:func:`ground_across_crack`'s answer from ``along`` ((sides, steps, 2, n) metres to the ground each ray found,
    inf: none): each direction of a side takes the ground of its first step that found some, and a probe stands on
    the first side whose two directions both found ground, at the nearer of the two."""
    n = along.shape[-1]
    if len(along) == 0:  # no side tried yet
        return np.zeros(n, dtype=bool), np.full(n, np.inf)
    first = np.argmax(np.isfinite(along), axis=1)[:, None]  # (sides, 1, 2, n): 0 where no step found ground
    found = np.take_along_axis(along, first, axis=1)[:, 0]
    both = np.isfinite(found).all(axis=1)  # (sides, n)
    on = both.any(axis=0)
    side = np.argmax(both, axis=0)
    return on, np.where(on, found.min(axis=1)[side, np.arange(n)], np.inf)


_CRACK_AXES = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
"""The horizontal axes along which :func:`walks_in_batch` looks for ground on both sides of a probe that found none
(:func:`ground_across_crack`), one crack step (r / 8, docs/entry_exit.md: 0.05 m for the map-piece agent) away."""

CRACK_STEPS = (0.5, 1.0)
"""The fractions of a crack step at which the sampling route's ground probes try each side of a crack apart
(:func:`ground_across_crack`'s ``steps``): half a step, then a whole one. At most two rays more a side than a
pair at a step, for a probe that finds no ground of its own (docs/entry_exit.md, "The grating's end on the
sampling route")."""


def crack_sides(agent: AgentShape) -> list[np.ndarray]:
    """The sides (each (3,), metres) :func:`ground_across_crack` tries for a ground probe of ``agent``: one crack step
    (r / 8) along x, then along z, each tried apart at :data:`CRACK_STEPS`. The walk test's and the sampling
    builder's ledge probes' (one rule for both)."""
    return list(_CRACK_AXES * (agent.radius / 8.0))


STEP_GAP_AXES = np.array([[math.cos(turn), 0.0, math.sin(turn)] for turn in np.arange(8) * math.pi / 8])
"""The plan axes along which :func:`ground_across_step_gap` measures a gap: every 22.5 degrees, so that one of them
lies within 11.25 degrees of any gap's normal."""

STEP_GAP_SEARCH = 4
"""Rays a direction :func:`ground_across_step_gap` first casts, evenly up to ``step_gap``, before halving the last
stretch: a strip of floor narrower than ``step_gap / STEP_GAP_SEARCH`` beyond a gap may be missed."""

STEP_GAP_HALVINGS = 6
"""Halvings of the stretch where :func:`ground_across_step_gap` first found ground: each side's distance is read
at most ``step_gap / STEP_GAP_SEARCH / 2**STEP_GAP_HALVINGS`` (1.6 mm for a step gap of 0.4 m) too long."""


def ground_across_step_gap(
    caster: RayCaster,
    probes: np.ndarray,
    reach: float | np.ndarray,
    walkable: Callable[[np.ndarray], np.ndarray],
    step_gap: float,
) -> tuple[np.ndarray, np.ndarray]:
    """Which probes that found no ground of their own lie in a gap narrower than ``step_gap`` that the agent steps
    over, and how far below the nearer side's ground lies.

    Along each of :data:`STEP_GAP_AXES`, both ways, the first walkable ground within ``reach`` straight down is
    searched up to ``step_gap`` away (:data:`STEP_GAP_SEARCH` rays, then :data:`STEP_GAP_HALVINGS` halvings of the
    stretch that found it, while the two sides' readings still straddle ``step_gap``); the gap along an axis is the
    sum of the two sides' distances, and a probe is in a gap the agent steps over when the shortest of those is under
    ``step_gap``. Each distance is read a little long, and a straight gap's width along an axis is its width over
    the cosine of the angle between them, so a gap as wide as ``step_gap`` or wider is never stepped over; one
    narrower is whenever some axis reads it under ``step_gap``: always for a straight gap under ``step_gap`` cos
    11.25 degrees (0.981 ``step_gap``) less the reading's error, and in the band up to ``step_gap`` when the gap's
    normal lies close enough to an axis. The height the two sides differ by is the caller's to check (the walk
    test's and the ledge probes' step rule), as for a crack.

    Returns:
        ``(on, distance)``: (n,) bool, and (n,) metres down to the nearer side's ground (``inf`` where not on).

    At most ``16 (STEP_GAP_SEARCH + STEP_GAP_HALVINGS)`` downward rays a probe.
    """
    probes = np.asarray(probes, dtype=np.float64).reshape(-1, 3)
    n = len(probes)
    directions = np.concatenate([STEP_GAP_AXES, -STEP_GAP_AXES])  # axis a: directions a and a + len(STEP_GAP_AXES)
    if n == 0:
        return np.zeros(0, dtype=bool), np.zeros(0)
    reach = np.broadcast_to(np.asarray(reach, dtype=np.float64), (n,))
    lo = np.zeros((n, len(directions)))
    hi = np.full((n, len(directions)), np.inf)
    down = np.full((n, len(directions)), np.inf)
    stride = step_gap / STEP_GAP_SEARCH

    def cast(rows: np.ndarray, cols: np.ndarray, at: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        hits = caster.first_hits(probes[rows] + at[:, None] * directions[cols], -UP)
        return (hits.distance <= reach[rows]) & walkable(hits.face), hits.distance

    axes = len(STEP_GAP_AXES)

    def open_axes() -> np.ndarray:
        """(n, 2 axes) the directions still read: of the axes whose gap may read under ``step_gap``, of the probes no
        axis has yet read under it."""
        may = lo[:, :axes] + lo[:, axes:] < step_gap
        may &= ~(hi[:, :axes] + hi[:, axes:] < step_gap).any(axis=1, keepdims=True)
        return np.concatenate([may, may], axis=1)

    for k in range(1, STEP_GAP_SEARCH + 1):
        rows, cols = np.nonzero(np.isinf(hi) & open_axes())
        if len(rows) == 0:
            break
        found, distance = cast(rows, cols, np.full(len(rows), k * stride))
        hi[rows[found], cols[found]] = k * stride
        down[rows[found], cols[found]] = distance[found]
        lo[rows[~found], cols[~found]] = k * stride
    for _ in range(STEP_GAP_HALVINGS):  # only where the two sides' readings still straddle step_gap
        rows, cols = np.nonzero(np.isfinite(hi) & open_axes())
        if len(rows) == 0:
            break
        middle = 0.5 * (lo[rows, cols] + hi[rows, cols])
        found, distance = cast(rows, cols, middle)
        hi[rows[found], cols[found]] = middle[found]
        down[rows[found], cols[found]] = distance[found]
        lo[rows[~found], cols[~found]] = middle[~found]
    across = hi[:, :axes] + hi[:, axes:]  # (n, axes) the gap's width along each axis, read long
    best = np.argmin(across, axis=1)
    on = across[np.arange(n), best] < step_gap
    sides = np.stack([best, best + axes], axis=1)
    nearer = sides[np.arange(n), np.argmin(np.take_along_axis(hi, sides, axis=1), axis=1)]
    return on, np.where(on, down[np.arange(n), nearer], np.inf)


def ground_beside(
    caster: RayCaster,
    probes: np.ndarray,
    reach: float | np.ndarray,
    walkable: Callable[[np.ndarray], np.ndarray],
    agent: AgentShape,
) -> tuple[np.ndarray, np.ndarray]:
    """Which probes that found no ground of their own stand on ground beside them, and how far below: over a crack
    (:func:`ground_across_crack` with :func:`crack_sides` and :data:`CRACK_STEPS`), else, with the agent's
    ``step_gap``, in a gap narrower than it (:func:`ground_across_step_gap`). The walk test's and the sampling
    builder's ledge probes' rule (one rule for both); ``(on, distance)`` as :func:`ground_across_crack`'s.

    With a ``step_gap`` both callers also ask it of the probes whose ground lies more than the agent's climb under
    the floor they step from (the walk's straight line; a ledge probe's previous probe), with ``reach`` (one or
    (n,) a probe) ending at that floor plus the climb: a gap narrower than ``step_gap`` is stepped over however
    deep the floor under it, where a floor 0.42-0.5 m down (deeper than the climb, within the ground probes' reach)
    kept the probe on it and failed the step rule (review54 MED 2). Ground beyond the climb does not count as a
    side, so a real step down more than the climb stays a ledge."""
    on, distance = ground_across_crack(caster, probes, -UP, crack_sides(agent), reach, walkable, CRACK_STEPS)
    if agent.step_gap:
        rest = np.flatnonzero(~on)
        reach = np.broadcast_to(np.asarray(reach, dtype=np.float64), on.shape)
        gap, beside = ground_across_step_gap(caster, np.asarray(probes).reshape(-1, 3)[rest], reach[rest], walkable,
                                             agent.step_gap)
        on[rest[gap]] = True
        distance[rest[gap]] = beside[gap]
    return on, distance


def _slices_meet_bands(triangles: np.ndarray, origin: np.ndarray, along: np.ndarray, side: np.ndarray,
                       inset: float) -> np.ndarray:
    """(k,) bool: triangle ``triangles[i]`` ((k, 3, 3) corners, m) passes through the parallelogram ``origin[i] +
    s along[i] + t side[i]`` (s in (0, 1), t in (-1, 1); ``along`` and ``side`` (k, 3) at right angles), shrunk by
    ``inset`` (m) on every side.

    The triangle's corners in the frame (s, t, d) of the parallelogram (metres along ``along``, ``side`` and their
    normal) give the segment where it crosses d = 0: from the edge joining the corners of least and greatest d, to
    the edge of the middle corner on the other side. It passes through only with corners more than ``inset`` to
    both sides: the side of a box whose top lies in the plane does not, as the side lines skimming that walkable
    top are not stopped. Then the segment is clipped against the shrunk rectangle (Y.-D. Liang and B. A. Barsky,
    "A new concept and method for line clipping", ACM Transactions on Graphics 3(1), 1984). O(k).
    """
    normal = np.cross(along, side)
    length, width = np.linalg.norm(along, axis=1), np.linalg.norm(side, axis=1)
    axes = np.stack([along / length[:, None], side / width[:, None],
                     normal / np.linalg.norm(normal, axis=1, keepdims=True)], axis=1)  # (k, 3 axes, 3)
    frame = np.einsum("kcj,kaj->kca", triangles - origin[:, None, :], axes)  # (k, 3 corners, metres along each axis)
    frame = np.take_along_axis(frame, np.argsort(frame[:, :, 2], axis=1)[:, :, None], axis=1)
    low, middle, high = frame[:, 0], frame[:, 1], frame[:, 2]
    crossing = (low[:, 2] < -inset) & (high[:, 2] > inset)
    with np.errstate(divide="ignore", invalid="ignore"):
        start = (low + (high - low) * (-low[:, 2] / (high[:, 2] - low[:, 2]))[:, None])[:, :2]
        beyond = middle[:, 2] >= 0.0  # the middle corner on the high side: the other end lies on the low-middle edge
        first, second = np.where(beyond[:, None], low, middle), np.where(beyond[:, None], middle, high)
        end = (first + (second - first) * (-first[:, 2] / (second[:, 2] - first[:, 2]))[:, None])[:, :2]
    step = end - start
    enter, leave = np.zeros(len(triangles)), np.ones(len(triangles))
    for axis, (lowest, highest) in enumerate([(inset, length - inset), (inset - width, width - inset)]):
        with np.errstate(divide="ignore", invalid="ignore"):
            u_low, u_high = (lowest - start[:, axis]) / step[:, axis], (highest - start[:, axis]) / step[:, axis]
        flat = step[:, axis] == 0.0
        enter = np.where(flat, enter, np.maximum(enter, np.minimum(u_low, u_high)))
        leave = np.where(flat, leave, np.minimum(leave, np.maximum(u_low, u_high)))
        crossing &= ~flat | ((start[:, axis] > lowest) & (start[:, axis] < highest))
    return crossing & (enter < leave)


@dataclass(frozen=True)
class SteepFaces:
    """The triangles of a caster's mesh steeper than a max slope and a :class:`BoxGrid` of their 3-D boxes, for
    :func:`bands_meet_walls`.

    Attributes:
        triangles: (k, 3, 3) float64, their corners, metres.
        lo, hi: (k, 3) float64, their boxes.
        grid: the boxes binned in cubes of the boxes' median extent in plan (their larger side seen from above),
            at least a 4096th of the mesh's extent.
    """

    triangles: np.ndarray
    lo: np.ndarray
    hi: np.ndarray
    grid: BoxGrid

    @classmethod
    def of(cls, caster: RayCaster, max_slope_deg: float) -> SteepFaces:
        """Built in O(k log k) plus :class:`BoxGrid`'s build."""
        steep = np.nonzero(~caster.walkable_faces(np.arange(len(caster.triangles)), max_slope_deg))[0]
        triangles = caster.triangles[steep]
        lo, hi = triangles.min(axis=1), triangles.max(axis=1)
        plan = (hi - lo)[:, [0, 2]].max(axis=1)
        cell = max(float(np.median(plan)) if len(plan) else 1.0, caster.scene.extent[0] / 4096.0, 1e-3)
        return cls(triangles, lo, hi, BoxGrid(lo, hi, cell))

    @cached_property
    def slab_grid(self) -> _slabs.WallGrid:
        """The same triangles in the C++ extension's grid (:attr:`grid`'s origin and cell), for the body slab's
        whole test in one call (:func:`walks_in_batch`); built on first use, O(E) for its E entries.

        Its ``meets(low, along, side, heights, inset)`` ((n, 3) m each, ``heights`` (n, 2) m) answers (n,) bool:
        a triangle passes through the slab ``low[i] + s along[i] + t side[i] + h UP`` (s in (0, 1), t in (-1, 1),
        h from ``heights[i, 0]`` to ``heights[i, 1]``; ``side`` horizontal and at right angles to ``along``'s
        plan), shrunk by ``inset`` on every side: a box sheared along a sloping walk, the body of an agent above its
        step, so that a bollard or a crate lower than the walk's lifted line is found too. The exact test per pair
        and its geometry are ``src/slabs_module.cpp``'s."""
        return _slabs.WallGrid(np.ascontiguousarray(self.triangles, dtype=np.float64), np.ascontiguousarray(self.lo),
                               np.ascontiguousarray(self.hi), np.ascontiguousarray(self.grid.origin, dtype=np.float64),
                               float(self.grid.cell))


def bands_meet_walls(caster: RayCaster, low: np.ndarray, along: np.ndarray, side: np.ndarray,
                     max_slope_deg: float, inset: float = GRAZE_NUDGE) -> np.ndarray:
    """(n,) bool: a triangle of the caster's mesh steeper than ``max_slope_deg`` passes through the band ``low[i] +
    s along[i] + t side[i]`` (s in (0, 1), t in (-1, 1), shrunk by ``inset`` m on every side; ``side`` horizontal
    and at right angles to ``along``, all (n, 3) m): the strip a disk of radius ``|side|`` sweeps at the lifted
    segment's height, tested exactly, so that a post or a mullion standing wholly between two of
    :func:`walks_in_batch`' lines is found however thin it is (the body's slab between two heights is
    :attr:`SteepFaces.slab_grid`'s). Walkable triangles are left out, as the side lines leave them.

    Broad phase: the bands' boxes looked up in the steep triangles' 3-D :class:`BoxGrid`, built once per mesh and
    max slope (:meth:`RayCaster.steep_faces`), then the boxes of the pairs sharing a cell; narrow phase
    :func:`_slices_meet_bands`. Per call O(C log K + P) for the C cells the
    bands' boxes cover, the K cells the steep triangles occupy and the P pairs sharing a cell, whatever the number
    of steep triangles (the first call of a max slope also builds the grid, O(E log E) for its E entries).
    """
    n = len(low)
    meets = np.zeros(n, dtype=bool)
    steep = caster.steep_faces(max_slope_deg)
    if n == 0 or len(steep.triangles) == 0:
        return meets
    corners = np.stack([low - side, low + side, low + along + side, low + along - side], axis=1)
    band_lo, band_hi = corners.min(axis=1), corners.max(axis=1)
    walls, wall_lo, wall_hi = steep.triangles, steep.lo, steep.hi
    band, wall = steep.grid.pairs(band_lo, band_hi)
    # The boxes' overlap one axis at a time, each on the pairs the axes before it kept: about one pair in a hundred
    # sharing a cell overlaps (a wall's long triangles fill the cells along it), and the first axis drops most.
    for axis in (0, 2, 1):
        near = (band_lo[band, axis] <= wall_hi[wall, axis]) & (wall_lo[wall, axis] <= band_hi[band, axis])
        band, wall = band[near], wall[near]
    hit = _slices_meet_bands(walls[wall], low[band], along[band], side[band], inset)
    meets[band[hit]] = True
    return meets


def walks_in_batch(
    caster: RayCaster,
    starts: np.ndarray,
    ends: np.ndarray,
    agent: AgentShape,
    probe_step: float,
    margin: float = GROUND_MARGIN,
    max_gap: float | None = None,
    half_width: float = 0.0,
    body: bool = False,
) -> tuple[np.ndarray, np.ndarray]:
    """Whether the agent can walk straight from ``starts[i]`` to ``ends[i]`` (ground points).

    A segment is walkable when

    * the segment lifted by half the agent height crosses no triangle, nor,
      with ``half_width`` (metres, > 0), do its two copies moved by
      ``half_width`` to either side, horizontally at right angles to it: a
      disk that wide travels along it through no wall, jamb or pillar; and,
      as a solid narrower than ``half_width`` can stand wholly between two of
      the lines (a post, a mullion), no triangle steeper than the agent's
      max slope passes through the band between the side lines
      (:func:`bands_meet_walls`, exact; asked only where every other test
      passed). With ``body``, that band is the slab of the agent's body,
      from above its step to its head (:attr:`AgentShape.body`;
      :attr:`SteepFaces.slab_grid`), so that a
      bollard or a crate lower than the lifted segment, which the ground
      probes under the middle line miss, stops the walk too. The ends' own
      disks are the caller's to check;
    * under evenly spaced points along it (at most ``probe_step`` apart
      horizontally, both ends included) a short downward ray from the lifted
      segment finds ground no more than ``max_climb + margin`` below the
      straight line, on a triangle no steeper than the agent's max slope,
      and an upward ray from the same point finds the agent's height of
      head room above that ground (a point over a crack stands on the ground
      within one crack step on both sides of it, :func:`ground_across_crack`
      with :data:`CRACK_STEPS`);
    * between neighbouring points the ground rises or falls by no more than
      the agent's max climb (a step) or its max slope times their distance,
      and a horizontal ray from one point to the next at the climb over the
      lower one's ground (or at the higher one's, where the slope lets them
      differ by more) meets no triangle steeper than the max slope: a
      sill over the climb thinner than ``probe_step``, which no probe may
      land on, stops the walk as a step would, while a stair's nosings and
      a slope's crest between two probes stay under it (asked of the walks
      passing every test above; docs/sampling.md, "Thin sills between the
      climb and the knee");
    * with ``max_gap``, the ground under every point lies within ``max_gap``
      above or below the straight segment (it does not cut under a ramp or
      over a drop).

    The arithmetic runs in the C++ extension (``src/walks_module.cpp``,
    :class:`_walks.WalkBatch`): a few extension calls a batch round the ray
    casts (one intersector call, the rays grazing a triangle cast again aside
    as :meth:`RayCaster.first_hits` does), the probes over a crack handed to
    :func:`ground_across_crack` (the one crack rule, with the ledge probes'),
    and the band test; a numpy formulation ran a few hundred array operations
    a batch, each costing more per call than per walk on the batches of a few
    dozen walks that the builder and the mesh_los predicate ask (docs/performance.md,
    samp5_47 and walks47); the rays over the steps need the probes' ground,
    so theirs is a second cast. O(rays) a batch, plus the band test's.

    Args:
        caster: the level's ray caster.
        starts, ends: (n, 3) ground points, metres.
        agent: the walking agent.
        probe_step: longest horizontal distance between probe points, metres.
        margin: metres the ground may lie below the lifted probe's reach past the agent's climb.
        max_gap: metres the ground may lie off the straight segment (``None``: no limit).
        half_width: half the width of the band the side lines bound, metres (0: the middle line only).
        body: the band is the agent's body's slab rather than the lifted segment's strip.

    Returns:
        ``(ok, rise)``: (n,) bool, and (n,) float, the largest height change
        between neighbouring points of each segment (metres; ``inf`` where
        ground is missing).
    """
    starts = np.ascontiguousarray(starts, dtype=np.float64).reshape(-1, 3)
    ends = np.ascontiguousarray(ends, dtype=np.float64).reshape(-1, 3)
    n = len(starts)
    if n == 0:
        return np.zeros(0, dtype=bool), np.zeros(0)
    lift = 0.5 * agent.height
    batch = _walks.WalkBatch(starts, ends, lift, probe_step, half_width)
    shift = caster.frame.origin if caster.frame.shifted else None
    _cast_batch(caster, *batch.rays(shift), batch.hit, batch.set_hits)
    normal_y = caster.scene.normal_y
    least_y = math.cos(math.radians(agent.max_slope_deg)) - 1e-9  # RayCaster.walkable_faces' bound
    reach = lift + agent.max_climb + margin

    def walkable(faces: np.ndarray) -> np.ndarray:
        return caster.walkable_faces(faces, agent.max_slope_deg)

    # With a step gap, the probes whose ground lies more than the climb under the straight line (in the margin under
    # it) are asked too: one over a gap narrower than step_gap stands on the nearer side's ground, however deep the
    # floor under the gap (ground() is asked within the climb first, the last call's ground is the batch's).
    within_climb = lift + agent.max_climb
    deep = batch.ground(within_climb, normal_y, least_y) if agent.step_gap else np.zeros(0, dtype=np.int64)
    missing = batch.ground(reach, normal_y, least_y)
    if len(missing):  # a probe over a crack: the one crack rule, the ledge probes' too
        crack, beside = ground_beside(caster, batch.probe_points(missing), reach, walkable, agent)
        batch.set_ground(missing[crack], beside[crack])
    deep = np.setdiff1d(deep, missing, assume_unique=True)
    if len(deep):
        over, beside = ground_beside(caster, batch.probe_points(deep), within_climb, walkable, agent)
        batch.set_ground(deep[over], beside[over])
    knee, head = agent.body
    ok, rise, rows, low, along, side, heights = batch.verdict(
        normal_y, least_y, agent.height, agent.max_climb, agent.tan_slope, HEIGHT_TOLERANCE, max_gap, knee, head, body)
    walking = np.flatnonzero(ok)
    if len(walking):  # a sill over the climb between two probes, which neither lands on (benchmarks/thin_sills.py)
        steps = batch.steps(walking, agent.max_climb, RISE_TOLERANCE)
        _cast_batch(caster, *steps.rays(shift), steps.hit, steps.set_hits)
        ok[walking[steps.blocked(normal_y, least_y)]] = False
        still = ok[rows]
        rows, low, along, side = rows[still], low[still], along[still], side[still]
        heights = None if heights is None else heights[still]
    if len(rows) and heights is not None:  # the body's slab: broad and narrow phase in one extension call
        steep = caster.steep_faces(agent.max_slope_deg)
        if len(steep.triangles):
            ok[rows] = ~steep.slab_grid.meets(low, along, side, heights, GRAZE_NUDGE)
    elif len(rows):
        ok[rows] = ~bands_meet_walls(caster, low, along, side, agent.max_slope_deg)
    return ok, rise


def _cast_batch(caster: RayCaster, local: np.ndarray, unit: np.ndarray,
                hit: Callable[..., np.ndarray], set_hits: Callable[..., None]) -> None:
    """:meth:`RayCaster.first_hits` of rays a :class:`_walks.WalkBatch` made (``local`` (R, 3) origins in the
    caster's frame, ``unit`` (R, 3)), their answers handed back to it: ``hit`` the intersector's faces, then
    ``set_hits`` the grazing rays' cast aside."""
    if len(local) == 0 or len(caster.mesh.faces) == 0:
        return
    scene = caster.scene
    faces = caster._first_faces(local, unit).reshape(len(local))
    caster.rays_cast += len(local)
    grazing = hit(np.ascontiguousarray(faces, dtype=np.int64), local, scene.face_normals, scene.plane_points,
                  scene.centroids, scene.twin)
    if len(grazing):
        set_hits(grazing, *caster._cast_aside(local[grazing], unit[grazing]))
