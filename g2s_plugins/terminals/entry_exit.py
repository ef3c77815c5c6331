"""Entry/exit points: the walkable boundary segments that lead out of a map piece.

Follows the entry/exit method the paper uses for map pieces (section
"Entry/exit points"): the navmesh boundary is sampled, each sample is
classified with a circle of ray casts as a possible segment start and/or end,
the samples are grown into segments, and each segment is matched to the edge
of the source geometry it stands for. Every opening becomes a terminal node.

Steps (``r`` = agent radius, ``h`` = ``sample_height``, ``R`` = probe radius
= ``max(sample_step, r * probe_radius_scale)``):

1. Boundary loops: navmesh polygon edges with no neighbour, chained into
   loops with the walkable side on the left (see :mod:`._boundary`).
2. Sampling: a sample every ``sample_step`` along each loop, snapped onto the
   source mesh by a short ray along the polygon normal (down first, then up);
   the hit triangle's normal is kept and the sample lifted ``h`` above it.
3. Classification: ``probe_count`` rays of length ``R`` in a circle in the
   plane of the surface. Rays pointing back along the loop are ignored for
   "can start", rays pointing forward for "can end"; a sample can start
   (end) a segment when none of the rays it considers hits the mesh.
4. Segments: from a sample that can start, grown through the following
   samples that can end; a segment closes at a sample that cannot end, where
   the loop turns by more than ``max_turn_deg``, or where the ray straight
   out (perpendicular to the loop, in the surface plane) hits the mesh within
   ``outward_radii * r`` (the opening must lead outside the piece).
   Segments shorter than ``min_width_radii * r``, steeper than
   ``max_slope_deg`` (when set) or on a roof (``roof_gap_heights``) are
   dropped.
5. Matching to the geometry (the paper's "corresponding segment in the
   original geometry"): the navmesh lies about ``r`` inside the real edge
   (Recast erodes it by the agent radius), so the edge is looked for straight
   out of every sample, up to ``edge_search_radii * r`` away, with rays cast
   down onto the surface. A segment is kept when

   * the surface ends there for at least half of its samples (where it goes
     on, the navmesh stops for a limit of the agent, e.g. head room, and the
     piece does not end);
   * with ``leave_footprint``, one agent radius beyond the edge nothing of the
     piece lies straight below or above for most samples (a ledge over a
     lower floor of the piece, or a hole under its ramp, is no exit);
   * the edge points fit one straight line within ``edge_tolerance_radii *
     r`` (80 % of them) or follow the boundary's direction within
     ``match_angle_deg`` (a curved edge); a navmesh boundary that cuts across
     a corner of the geometry matches neither.

   The opening lies on that line; its ends are extended along the edge, up to
   ``R + sample_step``, while the surface goes on inside the edge, ends just
   outside it, and nothing stands in the way or straight out: this undoes the
   retreat the probe circle causes next to walls.
6. Terminals: each segment gives an :class:`~g2s_core.model.Opening`
   (midpoint at floor height, horizontal outward heading, width, end points
   ``p0`` on the left and ``p1`` on the right looking out) and a new graph
   node at its midpoint (ids after the largest id, in opening order; ``pos``,
   ``normal``, ``area`` 0, ``on_navmesh`` from Detour's nearest polygon
   within one cell, ``polygon`` -1), joined by one edge (so it stays a leaf
   of any tree) to the nearest node among the navmesh polygons the segment
   runs along (to the nearest node when the graph has no polygon nodes), with
   ``weight`` = Euclidean distance.

A window or any hole above the floor is not an exit: the rays at ``h`` (just
above a step the agent may climb) hit the wall under it. A closed piece has
no openings: the selector returns no terminals and the pipeline stops with a
warning. Every batch of rays (one per step) is one call of trimesh's Embree
intersector, never one call per ray.

Needs the navigation mesh the ``navmesh`` graph builder leaves in
``context.navmesh``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import networkx as nx
import numpy as np
import trimesh
from pydantic import Field
from scipy.spatial import cKDTree

from g2s_core.config import AgentConfig
from g2s_core.errors import PluginError
from g2s_core.model import NavMesh, Opening, RunContext, Terminals, vec3
from g2s_core.plugin import PluginParams, hookimpl
from g2s_plugins.terminals._boundary import (
    UP,
    LoopSamples,
    RayCaster,
    boundary_loops,
    polygon_components,
    sample_loops,
)

NAME = "entry_exit"

_REFINE_ROUNDS = 4
"""Bisection rounds that place a found edge to 1/16 of the search step."""

_SIDEWAYS = 1e-9
"""|cos| below which a probe counts as perpendicular to the loop (considered for start and end)."""


class Params(PluginParams):
    """Boundary sampling, ray probes and segment rules; lengths in metres unless noted.

    Defaults follow the agent: samples every agent radius, probes just above
    the highest step it climbs, a probe circle a quarter wider than the agent.
    """

    sample_step: float | None = Field(
        None, gt=0, description="spacing of the boundary samples, m; None: the agent radius"
    )
    sample_height: float | None = Field(
        None,
        gt=0,
        description="height of the probe rays above the surface, m; None: 1.25 x the agent's max climb, at least 0.1",
    )
    snap_distance: float | None = Field(
        None,
        gt=0,
        description="longest ray that snaps a sample onto the mesh, m; None: the agent's max climb, at least 0.1",
    )
    probe_count: int = Field(32, ge=4, le=1024, description="rays in each sample's probe circle")
    probe_radius_scale: float = Field(
        1.25, gt=0, description="probe circle radius in agent radii (at least one sample step)"
    )
    max_turn_deg: float = Field(
        10.0, ge=0, le=180, description="a segment ends where the boundary turns by more than this, degrees"
    )
    outward_radii: float = Field(
        4.0, ge=0, description="the way straight out of an opening must be clear this far, agent radii"
    )
    min_width_radii: float = Field(1.0, ge=0, description="shorter segments are dropped, agent radii")
    max_slope_deg: float | None = Field(
        None, ge=0, le=90, description="drop segments steeper than this from the horizontal, degrees; None: keep all"
    )
    edge_search_radii: float = Field(
        2.5,
        gt=0,
        description="how far beyond the navmesh boundary the surface's edge is looked for, agent radii "
        "(Recast's erosion plus contour error stays below ~2.2)",
    )
    edge_tolerance_radii: float = Field(
        0.25,
        gt=0,
        description="the edge points found beyond a segment must lie this close to one straight line, "
        "agent radii (else the segment cuts across a corner and matches no edge)",
    )
    match_angle_deg: float = Field(
        30.0,
        ge=0,
        le=90,
        description="a curved edge matches a segment when its local direction stays this close to the "
        "boundary's, degrees (a boundary cutting a right-angled corner is 45 degrees off)",
    )
    roof_gap_heights: float = Field(
        1.5,
        ge=0,
        description="a walkable area with no walkable link to the rest that lies, over 90 % of its area, "
        "less than this many agent heights above other walkable surface of the piece is the top of the "
        "piece's ceiling (a roof), not a floor: it holds no exits; 0 keeps roofs",
    )
    leave_footprint: bool = Field(
        True,
        description="an exit must lead out of the piece: one agent radius beyond its edge nothing of the "
        "piece lies straight below or above (false: keep ledges and holes inside the piece)",
    )


@dataclass(frozen=True)
class _Settings:
    radius: float
    climb: float
    step: float
    height: float
    snap: float
    probe_radius: float
    delta: float


def _settings(params: Params, agent) -> _Settings:
    r = float(agent.radius)
    climb = float(agent.max_climb)
    step = float(params.sample_step) if params.sample_step is not None else r
    height = float(params.sample_height) if params.sample_height is not None else max(1.25 * climb, 0.1)
    snap = float(params.snap_distance) if params.snap_distance is not None else max(climb, 0.1)
    return _Settings(
        radius=r,
        climb=climb,
        step=step,
        height=height,
        snap=snap,
        probe_radius=max(step, r * float(params.probe_radius_scale)),
        delta=min(step, r) / 8.0,
    )


def _unit(v: np.ndarray) -> np.ndarray:
    n = np.linalg.norm(v, axis=-1, keepdims=True)
    return v / np.where(n > 1e-12, n, 1.0)


# --------------------------------------------------------------------------
# Steps 2-3: snapping and classification
# --------------------------------------------------------------------------


@dataclass(frozen=True)
class _Probed:
    base: np.ndarray  # (M,3) sample on the surface
    normal: np.ndarray  # (M,3) surface normal
    tangent: np.ndarray  # (M,3) walking direction in the surface plane
    outward: np.ndarray  # (M,3) out of the walkable area, in the surface plane
    can_start: np.ndarray
    can_end: np.ndarray
    clear_out: np.ndarray


def _snap(
    samples: LoopSamples, polygon_normals: np.ndarray, caster: RayCaster, snap: float
) -> tuple[np.ndarray, np.ndarray]:
    """Samples moved onto the mesh along the polygon normal (down first, then up) and the hit normals."""
    n_nav = _unit(polygon_normals[samples.polygon])
    base = samples.position.copy()
    normal = n_nav.copy()
    # Down: from ``snap`` above the sample, so a sample a little under the surface is found too.
    dist, pts, tri = caster.first_hits(samples.position + n_nav * snap, -n_nav)
    ok = dist <= 2.0 * snap
    miss = np.nonzero(~ok)[0]
    if len(miss):
        d_up, p_up, t_up = caster.first_hits(samples.position[miss], n_nav[miss])
        up_ok = d_up <= snap
        dist[miss[up_ok]], pts[miss[up_ok]], tri[miss[up_ok]] = d_up[up_ok], p_up[up_ok], t_up[up_ok]
        ok[miss[up_ok]] = True
    base[ok] = pts[ok]
    face_n = caster.face_normals[tri[ok]]
    flip = np.einsum("ij,ij->i", face_n, n_nav[ok]) < 0
    face_n[flip] *= -1.0
    normal[ok] = face_n
    return base, normal


def _probe(
    samples: LoopSamples, polygon_normals: np.ndarray, caster: RayCaster, s: _Settings, params: Params
) -> _Probed:
    base, normal = _snap(samples, polygon_normals, caster, s.snap)
    tangent = samples.tangent - np.einsum("ij,ij->i", samples.tangent, normal)[:, None] * normal
    tangent = _unit(tangent)
    left = np.cross(normal, tangent)  # inwards
    outward = -left
    lifted = base + normal * s.height
    m, k = len(base), int(params.probe_count)
    # The ray straight out: for the segment rule (outward_radii) and, when it is one of the
    # probes (probe_count a multiple of 4), to skip probing samples it already blocks.
    d_out, _, _ = caster.first_hits(lifted, outward)
    clear_out = d_out > float(params.outward_radii) * s.radius
    todo = np.nonzero(d_out > s.probe_radius)[0] if k % 4 == 0 else np.arange(m)
    theta = 2.0 * math.pi * np.arange(k) / k
    cos, sin = np.cos(theta), np.sin(theta)
    dirs = cos[None, :, None] * tangent[todo, None, :] + sin[None, :, None] * left[todo, None, :]
    dist, _, _ = caster.first_hits(np.repeat(lifted[todo], k, axis=0), dirs.reshape(-1, 3))
    blocked = (dist <= s.probe_radius).reshape(len(todo), k)
    can_start = np.zeros(m, dtype=bool)
    can_end = np.zeros(m, dtype=bool)
    can_start[todo] = ~np.any(blocked & (cos >= -_SIDEWAYS)[None, :], axis=1)
    can_end[todo] = ~np.any(blocked & (cos <= _SIDEWAYS)[None, :], axis=1)
    return _Probed(base, normal, tangent, outward, can_start, can_end, clear_out)


# --------------------------------------------------------------------------
# Step 4: segments
# --------------------------------------------------------------------------


def _turns(samples: LoopSamples, max_turn_deg: float) -> np.ndarray:
    """(M,) bool: the loop turns by more than ``max_turn_deg`` between the previous sample and this one."""
    m = len(samples.loop)
    prev = np.arange(m) - 1
    first = np.r_[True, samples.loop[1:] != samples.loop[:-1]]
    last_of_loop = np.r_[samples.loop[1:] != samples.loop[:-1], True]
    last_index = np.nonzero(last_of_loop)[0]
    prev[first] = last_index[samples.loop[first]]  # closed loops wrap round
    cosang = np.clip(np.einsum("ij,ij->i", samples.tangent, samples.tangent[prev]), -1.0, 1.0)
    turn = cosang < math.cos(math.radians(max_turn_deg))
    turn[first & ~samples.closed[samples.loop]] = True  # an open chain starts afresh
    return turn


def _segments(samples: LoopSamples, probed: _Probed, turn: np.ndarray) -> list[np.ndarray]:
    """Sample index runs, each a segment grown from a start sample through samples that can end."""
    start_ok = probed.can_start & probed.clear_out
    cont_ok = probed.can_end & probed.clear_out & ~turn
    segments: list[np.ndarray] = []
    bounds = np.flatnonzero(np.r_[True, samples.loop[1:] != samples.loop[:-1], True])
    for lo, hi in zip(bounds[:-1], bounds[1:]):
        idx = np.arange(lo, hi)
        breaks = np.nonzero(~cont_ok[idx])[0]
        if samples.closed[samples.loop[lo]] and len(breaks):
            idx = np.roll(idx, -int(breaks[0]))  # begin the walk at a break so no segment wraps
        current: list[int] = []
        for i in idx.tolist():
            if current and cont_ok[i]:
                current.append(i)
                continue
            if current:
                segments.append(np.asarray(current, dtype=np.int64))
                current = []
            if start_ok[i]:
                current = [i]
        if current:
            if len(current) == len(idx) and samples.closed[samples.loop[lo]]:
                half = len(current) // 2  # an open rim all round: two openings, not one with no ends
                segments.extend([np.asarray(current[:half], np.int64), np.asarray(current[half:], np.int64)])
            else:
                segments.append(np.asarray(current, dtype=np.int64))
    return segments


# --------------------------------------------------------------------------
# Step 5: matching each segment to the geometry's edge
# --------------------------------------------------------------------------


@dataclass(frozen=True)
class _Edge:
    """A segment matched to a straight edge of the geometry."""

    samples: np.ndarray  # sample indices of the segment, in walking order
    first: np.ndarray  # (3,) the segment's start, on the edge
    last: np.ndarray  # (3,) the segment's end, on the edge
    outward: np.ndarray  # (3,) unit, out of the piece, in the surface plane
    normal: np.ndarray  # (3,) unit surface normal


def roof_polygons(navmesh, caster: RayCaster, agent, gap_heights: float) -> np.ndarray:
    """(P,) bool: polygons of navmesh components that are roofs over the piece's own walkable surface.

    A component is a roof when, over at least 90 % of its area, a walkable face (front side up,
    within the agent's max slope) of the mesh lies straight below the polygon centre, lower by more
    than the agent's max climb (not the surface itself) and by less than ``gap_heights`` agent
    heights: too little room for a storey, so the area is the top of the ceiling over that floor.
    Areas that hold a walkable link to other floors (stairs, ramps) form one component with them
    and are never roofs.
    """
    polygons = np.asarray(navmesh.polygons)
    p = len(polygons)
    if p == 0 or gap_heights <= 0:
        return np.zeros(p, dtype=bool)
    centres = np.asarray(navmesh.centres, dtype=np.float64)
    areas = np.asarray(navmesh.areas, dtype=np.float64)
    climb = max(float(agent.max_climb), 0.05)
    gap = gap_heights * float(agent.height)
    ray, dist, tri = caster.all_hits(centres + UP * climb, np.repeat(-UP[None, :], p, axis=0))
    drop = dist - climb  # how far below the polygon's surface
    walkable = caster.face_normals[tri, 1] >= math.cos(math.radians(float(agent.max_slope)))
    good = walkable & (drop > climb) & (drop < gap)
    over = np.zeros(p, dtype=bool)
    over[ray[good]] = True
    label = polygon_components(navmesh.neighbours)
    total = np.bincount(label, weights=areas)
    covered = np.bincount(label, weights=areas * over, minlength=len(total))
    roof = covered >= 0.9 * np.maximum(total, 1e-12)
    return roof[label]


def _fit_line(points: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Centroid, unit direction and each point's distance to the least-squares line through ``points``."""
    centre = points.mean(axis=0)
    if len(points) < 2:
        return centre, np.zeros(3), np.zeros(len(points))
    _, _, vt = np.linalg.svd(points - centre, full_matrices=False)
    direction = vt[0]
    rel = points - centre
    off = rel - np.outer(rel @ direction, direction)
    return centre, direction, np.linalg.norm(off, axis=1)


def _follows(points: np.ndarray, tangents: np.ndarray, cos_match: float) -> bool:
    """Whether a polyline of edge points runs along ``tangents`` (within the angle) at 80 % of its points.

    The local direction at a point is the chord between its neighbours (one-sided at the ends),
    which keeps the found edge's quantisation noise small.
    """
    if len(points) < 3:
        return False
    i = np.arange(len(points))
    nxt = points[np.minimum(i + 1, len(points) - 1)]
    prv = points[np.maximum(i - 1, 0)]
    chord = _unit(nxt - prv)
    agree = np.abs(np.einsum("ij,ij->i", chord, tangents)) >= cos_match
    return bool(np.count_nonzero(agree) >= 0.8 * len(points))


def _match_edges(
    segments: list[np.ndarray], probed: _Probed, caster: RayCaster, s: _Settings, params: Params
) -> list[_Edge]:
    """Match each segment to the straight edge of the surface beyond it; unmatched segments are dropped."""
    if not segments:
        return []
    idx = np.concatenate(segments)
    owner = np.repeat(np.arange(len(segments)), [len(g) for g in segments])
    base, normal, outward = probed.base[idx], probed.normal[idx], probed.outward[idx]
    n_off = max(1, int(math.ceil(float(params.edge_search_radii) * s.radius / s.delta)))
    offsets = s.delta * np.arange(1, n_off + 1)
    lifted = base + normal * s.height
    origins = (lifted[:, None, :] + outward[:, None, :] * offsets[None, :, None]).reshape(-1, 3)
    dist, _, _ = caster.first_hits(origins, np.repeat(-normal, n_off, axis=0))
    present = (dist <= s.height + s.climb).reshape(len(idx), n_off)
    missing = ~present
    found = missing.any(axis=1)
    first_missing = np.argmax(missing, axis=1)
    # Bisection between the last offset with surface and the first without (batched per round).
    lo = np.where(found, first_missing * s.delta, np.nan)
    hi = lo + s.delta
    rows = np.nonzero(found)[0]
    for _ in range(_REFINE_ROUNDS):
        mid = 0.5 * (lo[rows] + hi[rows])
        probe = base[rows] + outward[rows] * mid[:, None] + normal[rows] * s.height
        d_mid, _, _ = caster.first_hits(probe, -normal[rows])
        on = d_mid <= s.height + s.climb
        lo[rows] = np.where(on, mid, lo[rows])
        hi[rows] = np.where(on, hi[rows], mid)
    edge = 0.5 * (lo + hi)
    edge_points = base + outward * np.nan_to_num(edge)[:, None]

    # One agent radius beyond the edge: is anything of the piece straight below or above?
    beyond = edge_points + outward * s.radius + normal * s.height
    vertical = np.repeat(UP[None, :], len(idx), axis=0)
    d_down, _, _ = caster.first_hits(beyond, -vertical)
    d_up, _, _ = caster.first_hits(beyond, vertical)
    inside = found & (np.isfinite(d_down) | np.isfinite(d_up))

    tolerance = max(2.0 * s.delta, float(params.edge_tolerance_radii) * s.radius)
    cos_match = math.cos(math.radians(float(params.match_angle_deg)))
    kept = []
    for g, samples in enumerate(segments):
        mine = np.nonzero(owner == g)[0]
        hit = mine[found[mine]]
        if len(hit) * 2 < len(mine) or len(hit) < 2:
            continue  # the surface goes on: the agent stops here, the piece does not end
        if params.leave_footprint and int(inside[hit].sum()) * 2 > len(hit):
            continue  # beyond the edge is still the piece: a ledge, a roof over its floor, a hole under a ramp
        centre, direction, residual = _fit_line(edge_points[hit])
        straight = np.count_nonzero(residual <= tolerance) >= 0.8 * len(hit)
        if not straight and not _follows(edge_points[hit], probed.tangent[idx[hit]], cos_match):
            continue  # the edge points fit no straight edge and no curve along the segment: a corner
        walk = base[mine[-1]] - base[mine[0]]
        if np.dot(direction, walk) < 0:
            direction = -direction
        nrm = _unit(normal[mine].mean(axis=0))
        out = _unit(np.cross(direction, nrm))
        if np.dot(out, outward[mine].sum(axis=0)) < 0:
            out = -out
        t = (base[mine] - centre) @ direction
        kept.append(
            _Edge(
                samples=samples,
                first=centre + direction * t.min(),
                last=centre + direction * t.max(),
                outward=out,
                normal=nrm,
            )
        )
    return kept


def _openings(kept: list[_Edge], caster: RayCaster, s: _Settings) -> list[Opening]:
    """Openings on the geometry's edge, their ends extended along it (one batched pass per test)."""
    if not kept:
        return []
    n = len(kept)
    out = np.array([e.outward for e in kept])
    nrm = np.array([e.normal for e in kept])
    first = np.array([e.first for e in kept])
    last = np.array([e.last for e in kept])
    along = _unit(np.cross(nrm, out))  # walking direction along the edge (interior on the left)
    inset = 2.0 * s.delta  # candidates stand this far inside the edge line

    # Candidate extensions beyond both ends, just inside the edge: the surface must go on
    # under them, the way along the edge must be clear, and so must the way out of them.
    n_ext = max(1, int(math.ceil((s.probe_radius + s.step) / s.delta)))
    steps = s.delta * np.arange(1, n_ext + 1)
    ends = np.stack([first, last])  # (2, n, 3)
    sign = np.array([-1.0, 1.0])[:, None, None]
    starts = ends - (out * inset)[None] + (nrm * s.height)[None]
    direction = sign * along[None]  # (2, n, 3)
    d_along, _, _ = caster.first_hits(starts.reshape(-1, 3), direction.reshape(-1, 3))
    d_along = d_along.reshape(2, n)
    cand = (starts[:, :, None, :] + direction[:, :, None, :] * steps[None, None, :, None]).reshape(-1, 3)
    down = np.broadcast_to(-nrm[None, :, None, :], (2, n, n_ext, 3)).reshape(-1, 3)
    outwards = np.broadcast_to(out[None, :, None, :], (2, n, n_ext, 3)).reshape(-1, 3)
    d_floor, _, _ = caster.first_hits(cand, down)
    d_beyond, _, _ = caster.first_hits(cand + outwards * (2.0 * inset), down)  # just past the edge line
    d_out, _, _ = caster.first_hits(cand, outwards)
    floor = (d_floor <= s.height + s.climb).reshape(2, n, n_ext)
    edge_goes_on = (d_beyond > s.height + s.climb).reshape(2, n, n_ext)
    open_out = (d_out > s.radius + inset).reshape(2, n, n_ext)
    run = np.cumprod(floor & edge_goes_on & open_out, axis=2).sum(axis=2)  # leading valid candidates
    reach = np.where(run < n_ext, run + 0.5, run) * s.delta  # the edge lies between valid and invalid
    ext = np.minimum(reach, d_along)
    p_first = first - along * ext[0][:, None]
    p_last = last + along * ext[1][:, None]

    openings = []
    for i in range(n):
        heading = out[i].copy()
        heading[1] = 0.0
        heading = _unit(heading) if np.linalg.norm(heading) > 1e-6 else out[i]
        left = np.cross(UP, heading)
        a, b = p_first[i], p_last[i]
        p0, p1 = (b, a) if np.dot(b - a, left) > 0 else (a, b)
        openings.append(
            Opening(
                position=vec3((p0 + p1) / 2.0),
                heading=vec3(heading),
                width=float(np.linalg.norm(p1 - p0)),
                p0=vec3(p0),
                p1=vec3(p1),
            )
        )
    return openings


# --------------------------------------------------------------------------
# The whole method
# --------------------------------------------------------------------------


@dataclass(frozen=True)
class Detection:
    """What :func:`detect_openings` found: the openings and the navmesh polygons each runs along."""

    openings: tuple[Opening, ...]
    polygons: tuple[tuple[int, ...], ...]
    normals: tuple[tuple[float, float, float], ...]


def detect_openings(
    mesh: trimesh.Trimesh, navmesh: NavMesh, agent: AgentConfig, params: Params | None = None
) -> Detection:
    """Steps 1-5 of the method: the openings of ``mesh`` for ``agent`` on ``navmesh``.

    Args:
        mesh: the source ``trimesh.Trimesh`` (metres, Y up).
        navmesh: a :class:`g2s_plugins.recast.NavMesh` built from it.
        agent: object with ``radius``, ``height``, ``max_climb``, ``max_slope``.
        params: :class:`Params`; ``None`` for the defaults.
    """
    params = params if params is not None else Params()
    s = _settings(params, agent)
    loops = boundary_loops(navmesh.vertices, navmesh.polygons, navmesh.neighbours)
    samples = sample_loops(loops, s.step)
    if len(samples.loop) == 0:
        return Detection((), (), ())
    caster = RayCaster(mesh)
    probed = _probe(samples, np.asarray(navmesh.normals), caster, s, params)
    segments = _segments(samples, probed, _turns(samples, float(params.max_turn_deg)))
    roof = roof_polygons(navmesh, caster, agent, float(params.roof_gap_heights))
    segments = [g for g in segments if not roof[samples.polygon[g]].all()]

    min_len = float(params.min_width_radii) * s.radius
    max_slope = None if params.max_slope_deg is None else math.radians(float(params.max_slope_deg))
    keep = []
    for g in segments:
        pts = probed.base[g]
        length = len(g) * float(samples.spacing[samples.loop[g[0]]])  # each sample stands for one spacing
        if length < min_len - 1e-9:
            continue
        if max_slope is not None:
            d = pts[-1] - pts[0]
            if math.atan2(abs(d[1]), math.hypot(d[0], d[2])) > max_slope + 1e-12:
                continue
        keep.append(g)
    kept = _match_edges(keep, probed, caster, s, params)
    openings = _openings(kept, caster, s)
    polys = tuple(tuple(sorted(set(samples.polygon[e.samples].tolist()))) for e in kept)
    normals = tuple(vec3(e.normal) for e in kept)
    return Detection(tuple(openings), polys, normals)


def _on_navmesh(navmesh, point: np.ndarray, tolerance: float, climb: float) -> bool:
    index, nearest = navmesh.nearest_poly(point)
    if index < 0:
        return False
    nearest = np.asarray(nearest, dtype=np.float64)
    return bool(math.hypot(*(nearest[[0, 2]] - point[[0, 2]])) <= tolerance and abs(nearest[1] - point[1]) <= climb)


def add_terminals(graph: nx.Graph, detection: Detection, navmesh: NavMesh, agent: AgentConfig) -> Terminals:
    """Add one node per opening to ``graph`` (see the module doc) and return the terminals."""
    if not detection.openings:
        return Terminals(nodes=(), openings=())
    node_of_polygon: dict[int, int] = {}
    ids, positions = [], []
    for node, data in graph.nodes(data=True):
        polygon = data.get("polygon", -1)
        if polygon is not None and polygon >= 0:
            node_of_polygon.setdefault(int(polygon), node)
        if "pos" in data:
            ids.append(node)
            positions.append(data["pos"])
    tree = cKDTree(np.asarray(positions, dtype=np.float64)) if positions else None
    next_id = max((int(n) for n in graph.nodes), default=-1) + 1
    tolerance = float(navmesh.settings["cell_size"])
    climb = max(float(agent.max_climb), 0.01)
    nodes = []
    for opening, polys, normal in zip(detection.openings, detection.polygons, detection.normals):
        node = next_id
        next_id += 1
        pos = np.asarray(opening.position, dtype=np.float64)
        graph.add_node(
            node,
            pos=opening.position,
            normal=normal,
            area=0.0,
            on_navmesh=_on_navmesh(navmesh, pos, tolerance, climb),
            polygon=-1,
        )
        # One edge, so the terminal stays a leaf: never a shortcut between polygons, never
        # an inner node the simplification could remove.
        candidates = [node_of_polygon[p] for p in polys if p in node_of_polygon]
        if not candidates and tree is not None:
            candidates = [ids[int(tree.query(pos)[1])]]
        if candidates:
            lengths = [float(np.linalg.norm(np.asarray(graph.nodes[c]["pos"], dtype=float) - pos)) for c in candidates]
            best = int(np.argmin(lengths))
            graph.add_edge(node, candidates[best], weight=lengths[best])
        nodes.append(node)
    return Terminals(nodes=tuple(nodes), openings=detection.openings)


@hookimpl
def g2s_select_terminals(graph: nx.Graph, params: Params, context: RunContext) -> Terminals:
    """Find the piece's entries/exits, add one terminal node per opening and return them."""
    if context.navmesh is None:
        raise PluginError(
            "entry_exit needs the navmesh graph builder (graph: plugin: navmesh): "
            "the run has no navigation mesh to take the boundary from"
        )
    params = params if params is not None else Params()
    detection = detect_openings(context.mesh, context.navmesh, context.agent, params)
    return add_terminals(graph, detection, context.navmesh, context.agent)
