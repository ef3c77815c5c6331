"""The built navmesh: its arrays, shared edges (portals) and Detour queries.

:class:`NavMesh` wraps the extension's ``NavMeshCore`` (one Detour tile, or
several joined): it copies the mesh arrays once, computes per-polygon centres,
normals and areas with numpy, and forwards raycasts and nearest-polygon
look-ups to Detour. Coordinates are metres with Y up, as in the mesh: a level
far from the origin is built in a local frame (:mod:`g2s_plugins.local_frame`), and every
attribute and method here takes and returns world coordinates all the same.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from ..local_frame import LocalFrame
from . import _recast

__all__ = ["NavMesh", "Portals", "FLT_MAX", "DT_VERTS_PER_POLYGON"]

FLT_MAX = float(np.finfo(np.float32).max)
"""Detour's ``FLT_MAX``: the raycast ``t`` when the ray reached its end point."""

DT_VERTS_PER_POLYGON: int = int(_recast.DT_VERTS_PER_POLYGON)
"""Detour's largest polygon (vertices)."""


@dataclass(frozen=True)
class Portals:
    """The shared edges of a navmesh, each adjacent polygon pair once, sorted by (a, b).

    Within a tile two polygons share a whole edge: ``endpoints`` are its two
    vertices, in the order of ``a``'s edge (the first such edge of ``a`` when
    they share several). Across a tile border an edge of ``a`` may touch
    several polygons of the next tile: each pair is listed with the part of
    the border they share, whose end points are vertices of ``a`` or ``b``
    (the overlap of their two collinear edges), in the direction of ``a``'s edge.

    Attributes:
        pairs: (E,2) int64, polygon indices ``a < b``.
        endpoints: (E,2,3) float64, the shared segment's end points, metres.
        widths: (E,) float64, the shared segment's length, metres.
    """

    pairs: np.ndarray
    endpoints: np.ndarray
    widths: np.ndarray


class NavMesh:
    """A built navmesh (one Detour tile, or several joined) and its queries.

    Arrays (copies taken once from the extension, metres, Y up):

    ``vertices``        (V,3) float64, polygon vertices.
    ``polygons``        (P,nvp) int32, vertex indices, padded with -1.
    ``neighbours``      (P,nvp) int32, polygon across edge j (vertex j -> j+1,
                        wrapping), -1 at the boundary. From Detour's links:
                        a tile-border edge touching several polygons lists
                        the one sharing the longest part (ties: lowest
                        index), so there ``i`` may list ``k`` while ``k``
                        lists another polygon; :meth:`portals` has every pair.
    ``area_ids``        (P,) int32, Recast area ids (63 = walkable).
    ``region_ids``      (P,) int32, Recast region ids (per tile, offset to
                        stay unique; regions stop at tile borders).
    ``detail_vertices`` (DV,3) float64, the height-detail mesh vertices.
    ``detail_triangles`` (DT,3) int32, indices into ``detail_vertices``.
    ``detail_polygon``  (DT,) int32, polygon owning each detail triangle.
    ``centres``         (P,3) float64, polygon centroid (xz) lifted onto the
                        polygon's detail surface.
    ``normals``         (P,3) float64, area-weighted unit normal of the
                        polygon's detail triangles, +Y side.
    ``areas``           (P,) float64, m², sum of the detail triangle areas.
    ``region_overlaps`` (K,3) float64, one span (x, floor y, z) of each Recast
                        region of the built navmesh holding two spans of one
                        xz column: a region overlapping itself in plan, whose
                        contours (traced in plan) can lose polygons or their
                        links. Only the ``watershed`` partition leaves them
                        (``auto`` redoes those tiles); tile by tile, a tile
                        without polygons too, but not the regions of the
                        small parts a tiled build drops at tile borders.
    ``repartitioned_tiles`` (R,2) int32, tile (x, z) of each tile whose
                        watershed regions overlapped, or had one region
                        whose contours total more than 128 vertices, and
                        that the ``auto`` partition rebuilt with
                        ``monotone`` and that holds polygons (row-major order;
                        ``(0, 0)`` for a solo navmesh); empty for the other
                        partitions.
    ``detail_redone_polygons`` (N,) int32, ascending: polygons whose
                        detail heights Recast read from their region on
                        another storey (a region winding back over itself
                        one storey up or down, as round a spiral stair) and
                        that were rebuilt from their own storey; the other
                        polygons keep Recast's detail exactly (docs/navmesh.md,
                        "Detail heights").
    ``detail_resampled_polygons`` (N,) int32, ascending: polygons whose
                        detail triangles left the floor under them by more
                        than the agent's climb (too narrow for Recast's
                        inside samples and bent, as along the foot or the
                        crest of a ramp) and that were rebuilt with finer
                        samples (docs/navmesh.md, "Detail chords").

    Polygon index ``i`` is Detour polygon ``poly_ref(i)``. Polygons are
    numbered tile by tile (row-major tiles); tiles share equal border vertices.

    Every coordinate above and every query below is in world coordinates;
    ``local_origin`` (3,) float64 is where the frame Recast built in lies
    (:mod:`g2s_plugins.local_frame`; all zero for a level near the origin, whose arrays are
    Recast's values as they are).
    """

    def __init__(self, core: Any, settings: dict[str, Any], frame: LocalFrame | None = None):
        self._core = core
        self.settings = dict(settings)
        self._frame = LocalFrame() if frame is None else frame
        # a query point's conversion, once per raycast: near the origin _vec itself, no call more than before
        self._local: Callable[[Any], tuple[float, float, float]] = self._shifted_point if self._frame.shifted else _vec
        local_vertices, local_detail = core.vertices, core.detail_vertices
        self.vertices: np.ndarray = self._world(local_vertices)
        self.polygons: np.ndarray = core.polygons
        self.neighbours: np.ndarray = core.neighbours
        self.area_ids: np.ndarray = core.area_ids
        self.region_ids: np.ndarray = core.region_ids
        self.detail_vertices: np.ndarray = self._world(local_detail)
        self.detail_triangles: np.ndarray = core.detail_triangles
        self.detail_polygon: np.ndarray = core.detail_polygon
        self.region_overlaps: np.ndarray = self._world(core.region_overlaps)
        self.repartitioned_tiles: np.ndarray = core.repartitioned_tiles
        self.detail_redone_polygons: np.ndarray = core.detail_redone_polygons
        self.detail_resampled_polygons: np.ndarray = core.detail_resampled_polygons
        # in the local frame, where the barycentric lift is as precise as for a level at the origin
        local_centres, self.normals, self.areas = _surface(
            self.polygon_count, local_vertices, self.polygons,
            local_detail, self.detail_triangles, self.detail_polygon,
        )
        self.centres: np.ndarray = self._world(local_centres)
        self._portals: Portals | None = None

    # ------------------------------------------------------------ sizes
    @property
    def polygon_count(self) -> int:
        """Number of polygons P."""
        return int(self._core.polygon_count)

    @property
    def nvp(self) -> int:
        """Max vertices per polygon (the width of ``polygons``)."""
        return int(self._core.nvp)

    @property
    def tile_size(self) -> int:
        """Tile side in cells; 0 for a solo navmesh."""
        return int(self._core.tile_size)

    @property
    def tile_count(self) -> int:
        """Number of Detour tiles holding polygons (1 for a solo navmesh)."""
        return int(self._core.tile_count)

    @property
    def tile_first_polygon(self) -> np.ndarray:
        """(T,) int32, the index of each tile's first polygon (tiles holding polygons, in row-major order)."""
        return self._core.tile_first_polygon

    @property
    def build_seconds(self) -> float:
        """Wall time of the C++ build (Recast + Detour), seconds."""
        return float(self._core.build_seconds)

    def config(self) -> dict[str, Any]:
        """Recast's resolved ``rcConfig`` (voxel units, whole grid size, bounds ``bmin``, ``bmax`` in world
        coordinates) and the tiling: ``tileSize`` (0: solo), ``borderSize``, ``tileGrid``, ``tiles``, ``autoTiled``."""
        config = dict(self._core.config())
        if self._frame.shifted:
            for key in ("bmin", "bmax"):
                config[key] = tuple(float(v) for v in self._world(np.asarray(config[key], dtype=np.float64)))
        return config

    def stats(self) -> dict[str, Any]:
        """Sizes and timing: polygons, vertices, detail triangles, tiles, cell size/height, seconds; and
        ``local_origin`` ([x, y, z], m) for a level built in a translated frame (none near the origin)."""
        stats = {
            "polygons": self.polygon_count,
            "vertices": int(len(self.vertices)),
            "detail_vertices": int(len(self.detail_vertices)),
            "detail_triangles": int(len(self.detail_triangles)),
            "portals": int(len(self.portals().pairs)),
            "cell_size": self.settings["cell_size"],
            "cell_height": self.settings["cell_height"],
            "tile_size": self.tile_size,
            "tiles": self.tile_count,
            "area_m2": float(self.areas.sum()),
            "build_seconds": self.build_seconds,
        }
        if self._frame.shifted:
            stats["local_origin"] = [float(v) for v in self.local_origin]
        return stats

    # ------------------------------------------------------------ topology
    def portals(self) -> Portals:
        """The shared polygon edges, every adjacent pair once (from Detour's links, computed at build)."""
        if self._portals is None:
            pairs = np.asarray(self._core.portal_pairs, dtype=np.int64).reshape(-1, 2)
            local = np.asarray(self._core.portal_endpoints, dtype=np.float64).reshape(-1, 2, 3)
            widths = np.linalg.norm(local[:, 1] - local[:, 0], axis=1)
            self._portals = Portals(pairs=pairs, endpoints=self._world(local), widths=widths)
        return self._portals

    # ------------------------------------------------------------ queries
    @property
    def default_extents(self) -> tuple[float, float, float]:
        """Half extents of the nearest-polygon search when none are given:
        ``(max(2r, 2cs), max(h, 2ch), max(2r, 2cs))`` for agent radius r, height h."""
        return tuple(float(v) for v in self._core.default_extents)  # type: ignore[return-value]

    @property
    def climb_tolerance(self) -> float:
        """Vertical tolerance of the raycast end check: ``max(agent max climb, 2 cell heights)``, m."""
        return float(self._core.climb_tolerance)

    def raycast(self, a: ArrayLike, b: ArrayLike, extents: ArrayLike | None = None) -> tuple[bool, float]:
        """Whether the straight walk from ``a`` to ``b`` along the navmesh is clear.

        Starts on the polygon nearest ``a`` (within ``extents`` half extents,
        default :attr:`default_extents`) and runs Detour's ``raycast`` towards
        ``b``. ``clear`` is True when the ray reaches ``b`` (``t == FLT_MAX``)
        and the polygon it ends in has its surface at ``b``'s x,z within
        :attr:`climb_tolerance` of ``b.y``. ``t`` is Detour's hit parameter
        (fraction of a->b where a wall was hit, ``FLT_MAX`` when not hit; 0
        when ``a`` is on no polygon).
        """
        clear, t = self._core.raycast(self._local(a), self._local(b), None if extents is None else _vec(extents))
        return bool(clear), float(t)

    def raycast_many(self, A: ArrayLike, B: ArrayLike, extents: ArrayLike | None = None) -> np.ndarray:
        """(N,) bool: ``raycast(A[i], B[i])[0]`` for (N,3) ``A`` and ``B``, looped in C++."""
        extents = None if extents is None else _vec(extents)
        return self._core.raycast_many(self._local_rows(A), self._local_rows(B), extents)

    def nearest_poly(self, p: ArrayLike, extents: ArrayLike | None = None) -> tuple[int, np.ndarray]:
        """(polygon index, (3,) nearest point on it) within the half ``extents``; (-1, p) if none."""
        idx, point = self._core.nearest_poly(self._local(p), None if extents is None else _vec(extents))
        return int(idx), self._world(point)

    def segment_surface_gaps(self, A: ArrayLike, B: ArrayLike, step: float, reach: float, horizontal: float | None = None) -> np.ndarray:
        """(S,) how far each straight segment ``A[i] -> B[i]`` ((S,3) each) strays from the walkable surface, m.

        Probes at most ``step`` apart horizontally along each segment, both ends
        included; a probe's gap is its vertical distance to the surface: over a
        polygon, to its detail surface straight above or below (Detour's
        height-accurate triangles; the nearest in height where floors
        overlap); over none, e.g. where Recast eroded the boundary, to the
        nearest boundary point of a polygon within ``horizontal`` (default one
        ``cell_size``). A segment's gap is its probes' largest, ``inf`` when a
        probe has no surface within ``reach``. Looped in C++, the rows shared
        between the cores (each row's value does not depend on it):
        O(length / step) probes, each O(polygons within ``horizontal``).
        """
        horizontal = float(self.settings["cell_size"]) if horizontal is None else float(horizontal)
        return self._core.segment_surface_gaps(self._local_rows(A), self._local_rows(B), float(step), horizontal,
                                               float(reach))

    def segment_surface_gap(self, a: ArrayLike, b: ArrayLike, step: float, reach: float, horizontal: float | None = None) -> float:
        """:meth:`segment_surface_gaps` of the one segment ``a -> b`` (two 3-sequences), m.

        The same C++ computation without arrays in or out: for callers that test
        one segment at a time (the ``surface_los`` predicate).
        """
        horizontal = float(self.settings["cell_size"]) if horizontal is None else float(horizontal)
        return float(self._core.segment_surface_gap(self._local(a), self._local(b), float(step), horizontal,
                                                    float(reach)))

    def line_of_sight(self, a, b, step: float, max_gap: float | None) -> bool:
        """Whether :meth:`raycast` from ``a`` to ``b`` is clear and, unless ``max_gap`` (m) is ``None``, the
        segment strays no further than that from the walkable surface (:meth:`segment_surface_gap` with
        ``reach=max_gap``, probes ``step`` apart): the same two answers in one C++ call instead of two (the
        ``surface_los`` predicate's test, tens of thousands of calls on a 100k-polygon level)."""
        return self._core.line_of_sight(self._local(a), self._local(b), float(step), float(self.settings["cell_size"]),
                                        None if max_gap is None else float(max_gap))

    def collapse_forest(self, forest: Any, rule: Any, step: float, max_gap: float | None,
                        memo: Any = None) -> tuple[np.ndarray, ...]:
        """The whole-forest answer (kept (n,) bool, added (k,2) int64, loop (k,) bool; :mod:`g2s_core.simplify`)
        of the ``surface_los`` predicate for ``forest`` (a :class:`~g2s_core.simplify.ForestArrays`): the paper's
        Algorithm 4 with Algorithm 5's tests of ``rule`` (a :class:`~g2s_plugins._surface.RuleArrays`) and
        :meth:`line_of_sight` (``step``, ``max_gap``) in one C++ call (src/forest_simplify.hpp), its walks below
        different kept nodes on all cores (the same answer on any number). ``memo`` (from :meth:`sight_memo`, or
        ``None``): the lines of sight of earlier calls with the same ``step`` and ``max_gap``, each segment's answer
        looked up there before it is tested and kept there after (a segment's answer depends on its ends alone);
        ``ValueError`` for a memo of another navmesh or other settings."""
        return self._core.collapse_forest(
            forest.ids, forest.parent, forest.depth, forest.fixed, forest.loops, forest.roots,
            self._local_rows(forest.points), rule.on_navmesh, rule.rank, rule.max_step, rule.normals,
            rule.normal_lengths, float(rule.tolerance_deg), bool(rule.whole_chain), float(step),
            float(self.settings["cell_size"]), None if max_gap is None else float(max_gap), memo)

    @staticmethod
    def sight_memo() -> Any:
        """An empty memo of lines of sight for :meth:`collapse_forest` (``len()``: the segments answered; ``hits``:
        the tests it answered)."""
        return _recast.SightMemo()

    def poly_ref(self, index: int) -> int:
        """Detour ``dtPolyRef`` of polygon ``index``."""
        return int(self._core.poly_ref(int(index)))

    def poly_index(self, ref: int) -> int:
        """Polygon index of a Detour ``dtPolyRef`` (-1 for 0)."""
        return int(self._core.poly_index(int(ref)))

    def __repr__(self) -> str:
        return f"NavMesh(polygons={self.polygon_count}, vertices={len(self.vertices)})"

    # ------------------------------------------------------------ frames
    @property
    def local_origin(self) -> np.ndarray:
        """(3,) float64: where the frame Recast built in lies (all zero for a level near the origin)."""
        return self._frame.origin

    def _world(self, local: np.ndarray) -> np.ndarray:
        """(..., 3) local coordinates -> world (float64)."""
        return self._frame.to_world(local)

    def _shifted_point(self, p) -> tuple[float, float, float]:
        """One world point (a 3-sequence) -> local, as the extension takes it."""
        x, y, z = _vec(p)
        ox, oy, oz = self._frame.origin
        return (x - float(ox), y - float(oy), z - float(oz))

    def _local_rows(self, points) -> np.ndarray:
        """(N,3) world points (any array-like) -> local, float64 and C-contiguous as the extension takes them."""
        return self._frame.to_local(np.ascontiguousarray(points, dtype=np.float64).reshape(-1, 3))


# ---------------------------------------------------------------- numpy helpers

def collapse_forest_seeing(
    forest: Any, rule: Any, sees: Callable[[np.ndarray], np.ndarray], memo: Any = None
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """:meth:`NavMesh.collapse_forest`'s answer for ``forest`` (a :class:`~g2s_core.simplify.ForestArrays`) and
    ``rule`` (a :class:`~g2s_plugins._surface.RuleArrays`) with the line of sight ``sees`` instead of the
    navmesh's (the ``mesh_los`` predicate's walk test; no navmesh needed): Algorithm 4 and Algorithm 5's other tests
    in C++ on one thread (src/forest_simplify.hpp), asking ``sees((k,2) int64 rows (a, c) of forest)`` -> (k,) bool
    only for the chains those let go, in batches: the walks below every kept node go on until each is done or needs
    an answer not given yet, and then the pairs they all wait for are given in one call. The answers must depend
    on the pairs alone, not on the batches or their order. ``memo`` (a :meth:`NavMesh.sight_memo` of no navmesh, or
    None): what ``sees`` answered in earlier calls, by the segment between the two nodes' ``forest.points`` (either
    way round), asked of it no more (the heat guarantee's later rounds ask about most of their chains again); the
    answers must then depend on the segment alone, and be the same both ways round."""
    return _recast.collapse_forest(
        forest.ids, forest.parent, forest.depth, forest.fixed, forest.loops, forest.roots, rule.on_navmesh, rule.rank,
        rule.max_step, rule.normals, rule.normal_lengths, float(rule.tolerance_deg), bool(rule.whole_chain), sees,
        np.ascontiguousarray(forest.points, dtype=np.float64), memo)


def _vec(p) -> tuple[float, float, float]:
    # unpacking rather than numpy: called once per raycast, on a tuple or (3,) array
    x, y, z = p
    return (float(x), float(y), float(z))


def _surface(P, verts, polys, dverts, dtris, owner):
    """Per-polygon centres, normals and areas from the detail triangles (vectorised)."""
    p0, p1, p2 = dverts[dtris[:, 0]], dverts[dtris[:, 1]], dverts[dtris[:, 2]]
    cross = np.cross(p1 - p0, p2 - p0)                 # 2 * area * normal
    cross[cross[:, 1] < 0] *= -1.0                     # +Y side
    tri_area = 0.5 * np.linalg.norm(cross, axis=1)
    areas = np.bincount(owner, weights=tri_area, minlength=P)
    nsum = np.stack([np.bincount(owner, weights=cross[:, k], minlength=P) for k in range(3)], axis=1)
    nlen = np.linalg.norm(nsum, axis=1)
    normals = np.tile(np.array([0.0, 1.0, 0.0]), (P, 1))
    ok = nlen > 0
    normals[ok] = nsum[ok] / nlen[ok, None]

    # Polygon centroid in xz: projected-area-weighted triangle centroids.
    proj = 0.5 * np.abs(cross[:, 1])
    cen = (p0 + p1 + p2) / 3.0
    wsum = np.bincount(owner, weights=proj, minlength=P)
    cx = np.bincount(owner, weights=proj * cen[:, 0], minlength=P)
    cz = np.bincount(owner, weights=proj * cen[:, 2], minlength=P)
    good = wsum > 0
    # the vertex mean is the centre only of a polygon with no area in plan (none of its triangles' or no triangle;
    # every other one has x, z from its triangles and a height lifted from one): few, so only theirs (a gather of
    # every polygon's vertices took a third of this function's time)
    vertical = np.flatnonzero(~good)
    valid = polys[vertical] >= 0
    cnt = np.maximum(valid.sum(axis=1), 1)
    pv = verts[np.where(valid, polys[vertical], 0)] * valid[..., None]
    centres = np.empty((P, 3))
    centres[vertical] = pv.sum(axis=1) / cnt[:, None]
    centres[good, 0] = cx[good] / wsum[good]
    centres[good, 2] = cz[good] / wsum[good]

    # Lift onto the detail triangle under/over the centroid: barycentric
    # coordinates of the owner's centroid in every triangle, best one per polygon.
    qx, qz = centres[owner, 0], centres[owner, 2]
    d = (p1[:, 2] - p2[:, 2]) * (p0[:, 0] - p2[:, 0]) + (p2[:, 0] - p1[:, 0]) * (p0[:, 2] - p2[:, 2])
    safe = np.where(np.abs(d) > 1e-12, d, 1.0)
    l0 = ((p1[:, 2] - p2[:, 2]) * (qx - p2[:, 0]) + (p2[:, 0] - p1[:, 0]) * (qz - p2[:, 2])) / safe
    l1 = ((p2[:, 2] - p0[:, 2]) * (qx - p2[:, 0]) + (p0[:, 0] - p2[:, 0]) * (qz - p2[:, 2])) / safe
    lam = np.stack([l0, l1, 1.0 - l0 - l1], axis=1)
    score = np.where(np.abs(d) > 1e-12, np.minimum(np.minimum(l0, l1), lam[:, 2]), -np.inf)
    best = _best_per_owner(score, owner, P)
    has = best >= 0
    b = best[has]
    lb = np.clip(lam[b], 0.0, None)
    lb /= np.maximum(lb.sum(axis=1, keepdims=True), 1e-300)
    centres[has, 1] = lb[:, 0] * p0[b, 1] + lb[:, 1] * p1[b, 1] + lb[:, 2] * p2[b, 1]
    return centres, normals, areas


def _best_per_owner(score: np.ndarray, owner: np.ndarray, P: int) -> np.ndarray:
    """(P,) int64: for each owner 0..P-1 the index of its highest ``score`` ((T,) each), the last of equal ones;
    -1 for an owner of none.

    The detail triangles come owner by owner (the extension writes them polygon by polygon), so the groups are
    runs and one maximum per run finds them: O(T), 7 ms for the 221,798 triangles of the 100k-polygon level
    where a sort by (owner, score) took 36-49 ms (docs/performance.md); out of order or with a NaN score, that
    sort, whose order (NaN highest, a stable sort's last of equals) is the rule.
    """
    best = np.full(P, -1, dtype=np.int64)
    if len(owner) == 0:
        return best
    if np.any(owner[1:] < owner[:-1]) or np.isnan(score).any():
        order = np.lexsort((score, owner))
        grouped = owner[order]
        last = np.r_[grouped[1:] != grouped[:-1], True]
        best[grouped[last]] = order[last]
        return best
    starts = np.flatnonzero(np.r_[True, owner[1:] != owner[:-1]])
    top = np.repeat(np.maximum.reduceat(score, starts), np.diff(np.r_[starts, len(owner)]))
    best[owner[starts]] = np.maximum.reduceat(np.where(score == top, np.arange(len(owner)), -1), starts)
    return best
