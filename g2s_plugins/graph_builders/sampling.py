"""Sampling: surface graph from points sampled on the walkable surface, joined where the agent can walk.

The paper's "initial graph from sampling" (Sec. 3.1.1), for levels without a
navigation mesh or when a finer graph than one node per navmesh polygon is
wanted. No Recast is involved: ``context.navmesh`` stays ``None``.

1. *Walkable surface*: the triangles no steeper than the agent's max slope,
   cleaned with pymeshlab (close vertices merged, duplicate and zero-area
   faces dropped).
2. *Candidates*: ``method: poisson`` draws dense random points on that
   surface (``candidate_density`` per spacing², fixed seed); ``method: grid``
   drops a regular XZ grid onto it (every floor a vertical line crosses gives
   a point, so several floors give several samples per grid cell; a line
   through a crack, such as a grating's slot, gives a point on the floor
   beside it, :func:`_crack_candidates`).
3. *Agent checks*, batched upward/horizontal/downward rays per candidate:
   head room (nothing within the agent height above it); clearance (no wall
   within ``clearance`` metres, horizontal rays at knee, waist and head
   height, and up a compass direction whose curtain through the agent's
   body slab a steep face crosses, :func:`curtains_crossed`; a riser the
   agent steps up is no wall, :func:`walls_met`); no
   ledge within ``clearance`` (ground found at half that distance and at it
   in 8 directions, rising or falling between neighbouring probes by a step
   or the max slope at most, with head room; a probe over a crack, such as
   a grating's slot, stands on the ground beside it, the walk test's crack
   rule, and one in a gap narrower than ``step_gap`` on the nearer side's
   ground: :func:`~g2s_plugins._raycasting.ground_beside`). This erodes
   the walkable surface by ``clearance`` as Recast erodes it by the radius.
   Rays whose answer the geometry near a candidate already gives are not
   cast (:class:`_Surroundings`); the answers are the same. The wall and
   ledge rays, and the edges' walk tests and the passages' ledge rays
   (:func:`ledge_room`) below, are cast in batches by two threads
   (:func:`_each_batch`), the same answers again.
   *Closed solids* (:func:`inside_closed_solids`): a candidate that passed
   those checks is dropped when the first triangles above it and along
   ±x, ±z are all met from behind (the inside of an outward-wound block
   standing on the floor, which the checks above miss in the middle of a
   block taller than the agent and wider than twice the clearance).
4. *Samples*: for ``poisson``, a maximal Poisson-disk subset of the
   surviving candidates (no two closer than ``spacing``, every candidate
   within ``spacing`` of a sample), chosen by seeded dart throwing
   (:func:`poisson_disk_subset`; R. L. Cook, "Stochastic sampling in
   computer graphics", ACM Transactions on Graphics 5(1):51-72, 1986); for
   ``grid``, every surviving grid point.
   pymeshlab's own Poisson-disk filter is not used for this step: it draws
   from a process-wide random generator that cannot be seeded from Python,
   so the same input gives a different sample on every call.
5. *Edges*: pairs closer than ``connect_radius`` (scipy cKDTree) that pass
   :func:`g2s_plugins._raycasting.walks_in_batch` (the segment lifted by half
   the agent height hits nothing, nor do its copies moved ``DISK_SHARE`` ×
   ``clearance`` to either side, nor does a steep face pass through the slab
   those two sweep from above the agent's step to its head, so that a door, a
   slot between pillars or a slot beside a post narrower than the agent is not
   crossed, nor a row of bollards or crates lower than the lifted segment; the
   ground under evenly spaced points is walkable, has head room and changes
   height by at most a step or the max slope; a probe over a crack or a gap
   narrower than ``step_gap`` stands on the ground beside it); a pair on one open floor triangle, both samples that
   far inside its edges, passes without a ray
   (:class:`g2s_plugins._raycasting.OpenFloors`). Then *passages the samples
   miss* (:func:`moved_into_passages`): a passage a little wider than the
   agent leaves its centre a band narrower than the spacing, which no grid
   line may cross; the candidates turned away by a wall or a ledge with no
   candidate that fits near them, or only ones of several parts of the graph
   or of a part too small to keep, are moved straight off the nearest wall or
   ledge by what they lack of the clearance, the band is followed both ways
   out of the passage's mouths and into its turns, and the points where the
   agent fits with its whole width (:func:`nearest_wall`, ground in
   ``GROUND_DIRECTIONS`` directions) are added (area 0: they stand for no
   candidate's cell) and joined by the same walk test with the whole
   clearance as its half width (``DISK_SHARE`` of it is for grid samples,
   which the compass rays let stand that near a wall; an added point stands
   the whole clearance off, a square crossing of a passage the agent fits
   keeps that width, and the narrower band let crossings 1-4 degrees off
   square pass slots narrower than the agent), on the way or on it moved
   sideways by what ``DISK_SHARE`` leaves of the clearance (a corner on one
   side passed that near, as grid samples' edges pass it). Then the *gaps*
   (:func:`_gap_pairs`): in a passage only slightly wider than twice the
   clearance the samples form a thin band, where the pick can leave two
   consecutive ones farther apart than ``connect_radius``; pairs up to
   ``gap_radius`` apart that pass the same walk test are joined too, but
   only where the graph so far has no way between them shorter than
   ``GAP_STRETCH`` × their distance (on open ground a common neighbour
   is such a way, so almost nothing is added there). Weight = length +
   ``slope_penalty`` × |height change|.

Nodes (ids 0..n-1, ordered by x, then z, then y): ``pos`` (on the surface),
``normal`` (of the triangle under the sample), ``area`` (the walkable surface
the sample stands for: the candidates nearest to it for ``poisson``,
spacing² / cos(slope) for ``grid``, 0 for a sample added in a passage), ``on_navmesh=True`` ("on the walkable
surface"), ``polygon=-1``. Connected parts whose area is below
``min_region_area`` are dropped. ``graph.graph["sampling_stats"]`` holds
the resolved settings and counts (candidates, samples, rays, ...). The same mesh and parameters always give the same graph.

Cost, for c candidates, s samples and p sample pairs within
``connect_radius``: at most 41 rays a candidate (head room; 8 directions at
up to 3 heights; 8 ledge rays down and 8 up) and, along a direction whose curtain through the body slab a steep
face crosses, one at each end of each ``BODY_RAY_STEP`` band it crosses; and 2 or 4 for each ledge probe
that finds no ground of its own (up to the first that finds none beside it
either), fewer where
:class:`_Surroundings` gives the answer; one more upward ray a candidate
that fits, and 4 horizontal ones where that ray meets a face from behind; the Poisson-disk subset, k-d tree
queries over the candidates and their pairs within ``spacing``; the pairs,
one k-d tree query, then O(connect_radius / probe_step) rays (two of them the side lines) for each pair
not on one open floor triangle; the gaps, a k-d tree query within
``gap_radius``, one sparse matrix product for the common neighbours, a
bounded Dijkstra search from the pairs left, tile by tile, and the walk
test for the pairs that have no short way. Each ray is a search of Embree's bounding
volume hierarchy (trimesh's own intersector without Embree).
The passages: for s stranded candidates, up to ``MOVE_ROUNDS`` x (24 + 32
rays and the ledge halvings) each, then the agent checks at up to
2 x (``REACH_STEPS`` + ``END_HALVINGS``) points along each band, and the walk
test for the added samples' pairs.
"""

from __future__ import annotations

import copy
import math
import os
import threading
import time
import weakref
from collections.abc import Callable, Sequence
from concurrent.futures import ThreadPoolExecutor
from dataclasses import replace
from typing import Literal, TypeVar

import numpy as np
from pydantic import Field

from g2s_core.errors import G2SError
from g2s_core.lazy import lazy_module
from g2s_core.model import RunContext, graph_of
from g2s_core.plugin import hookimpl
from g2s_plugins._raycasting import (
    COMPASS,
    EPSILON,
    GRAZE_NUDGE,
    GROUND_MARGIN,
    CRACK_STEPS,
    UP,
    AgentShape,
    BoxOccupancy,
    FloorTriangles,
    Hits,
    OpenFloors,
    RayCaster,
    all_hits_down,
    clear_above,
    closed_solid_holds,
    crack_sides,
    ground_beside,
    head_room,
    RISE_TOLERANCE,
    ray_margin,
    walks_in_batch,
)
from g2s_plugins.allocator import hand_back_free_memory
from g2s_plugins.play_space import PlaySpaceParams, cut_to_play_space
from g2s_plugins.units_check import check_units
from g2s_plugins.walkable_check import check_walkable_surface, no_walkable_surface

trimesh, spatial = lazy_module("trimesh"), lazy_module("scipy.spatial")
sparse, csgraph = lazy_module("scipy.sparse"), lazy_module("scipy.sparse.csgraph")
area_gaps = lazy_module("g2s_plugins.area_gaps")  # it imports scipy and trimesh
nx = lazy_module("networkx")

NAME = "sampling"

MAX_CANDIDATES = 5_000_000
"""More candidate points than this means the spacing is far too small for the mesh."""

MAX_EDGE_BATCH = 200_000
"""Candidate edges tested per batch of rays (bounds memory on large levels)."""

MAX_LEDGE_BATCH = 50_000
"""Candidate points whose ledge rays (8 each) are cast per batch (bounds memory on large levels)."""

MAX_WALL_BATCH = 100_000
"""Candidate points whose wall rays (24 each at most) one thread casts at a time (:func:`agent_fits`)."""

MAX_ROOM_BATCH = 10_000
"""Points whose :func:`ledge_room` rays (``GROUND_DIRECTIONS`` each and their halvings) one thread casts at a time."""

RAY_THREADS = min(2, os.cpu_count() or 1)
"""Threads that cast a build's batches of rays (:func:`_each_batch`). Embree's calls and numpy's loops over
whole arrays let go of the GIL, so a second thread keeps a second core busy; the Python round them does not,
so more threads gain little (docs/performance.md, 6 December 2026, samp1_46)."""

Batch = TypeVar("Batch")


GAP_STRETCH = 2.0
"""A pair of samples beyond ``connect_radius`` but within ``gap_radius`` is joined only when the graph's way
between them is longer than this many times their distance (see :func:`_gap_pairs`)."""

DISK_SHARE = 0.9
"""An edge is kept only where a disk of this share of ``clearance`` travels along it through no wall
(:func:`~g2s_plugins._raycasting.walks_in_batch`' ``half_width``): just under cos 22.5 degrees (0.924), the least
distance from a straight wall at which the agent checks' 8 compass rays accept a sample, so an edge along a wall
between two accepted samples is not stopped by that wall. At 1.0, an edge 0.46 m from a wall of a 1.9 m corridor
of the 1k dungeon is stopped and two samples are cut off; at 0.9, in a 0.2 m wall turned 0, 22 and 45 degrees, every
door up to 1.0 m wide is closed and every one from 1.4 m open (docs/sampling.md, "Doors narrower than the agent").
An edge with a sample added in a passage is walked with the whole clearance instead, on the way or beside it
(:func:`_walkable_pairs_of`)."""


class Params(PlaySpaceParams):
    """Sampling method and density, edge rules, clean-up and the play space
    (:class:`g2s_plugins.play_space.PlaySpaceParams`)."""

    method: Literal["poisson", "grid"] = Field(
        "poisson", description="poisson: Poisson-disk samples; grid: regular XZ grid dropped on the surface"
    )
    spacing: float | None = Field(
        None, gt=0, le=100, description="distance between samples, m; default 2 x agent radius"
    )
    connect_radius: float | None = Field(
        None, gt=0, le=1000, description="join samples closer than this if walkable, m; default 2 x spacing"
    )
    clearance: float | None = Field(
        None, ge=0, le=100, description="keep samples this far from walls and ledges, m; default agent radius; 0: off"
    )
    probe_step: float | None = Field(
        None, gt=0, le=100, description="ground probes along an edge at most this far apart, m; default min(spacing, radius) / 2"
    )
    slope_penalty: float = Field(
        0.0, ge=0, description="edge weight added per metre of height change (0: weight = length)"
    )
    min_region_area: float | None = Field(
        None, ge=0, description="drop connected parts standing for less surface than this, m²; default 16 x radius² (Recast's)"
    )
    candidate_density: float = Field(
        8.0, ge=2, le=100, description="poisson: candidate points per spacing² the Poisson-disk subset is chosen from"
    )
    seed: int = Field(0, ge=0, description="poisson: seed of the candidate points and of the Poisson-disk pick")
    step_gap: float | None = Field(
        None,
        ge=0,
        le=100,
        description="the agent steps over a gap between floors narrower than this, m, where their heights differ by "
        "at most its max climb (the walk test's and the ledge probes' ground); default the agent's max climb (a "
        "stride clears a gap as wide as the step it climbs); 0: only cracks of a quarter of its radius (the paper "
        "presets; docs/sampling.md, Narrow gaps between floors)",
    )
    crack_lines: bool = Field(
        True,
        description="grid: a grid line through a crack (a grating's slot) takes a point on the floor beside it "
        "(docs/sampling.md, Grid lines through gratings' slots); false: only floors the line meets",
    )
    body_walls: bool = Field(
        True,
        description="the clearance check also finds walls in the agent's body slab, from over its climb to its head "
        "(a belt or rail between the knee, waist and head rays, 0.025 m tall or more), as the edges' walk test does; false: at "
        "those three rays only (the paper preset; docs/sampling.md, Belts and rails between the wall rays)",
    )
    gap_radius: float | None = Field(
        None,
        ge=0,
        le=1000,
        description="also join samples up to this far apart if walkable and the graph has no way between them "
        f"within {GAP_STRETCH:g} x their distance (gaps in thin passages), m; default 3 x spacing; 0: off",
    )


def _resolve(params: Params, agent: AgentShape) -> tuple[float, float, float, float, float]:
    """``(spacing, connect_radius, clearance, probe_step, gap_radius)`` with the defaults filled in."""
    spacing = params.spacing if params.spacing is not None else 2.0 * agent.radius
    connect = params.connect_radius if params.connect_radius is not None else 2.0 * spacing
    clearance = params.clearance if params.clearance is not None else agent.radius
    probe = params.probe_step if params.probe_step is not None else 0.5 * min(spacing, agent.radius)
    gap = params.gap_radius if params.gap_radius is not None else 3.0 * spacing
    return spacing, connect, clearance, probe, gap


# --- walkable surface -----------------------------------------------------------------


def walkable_surface(mesh: trimesh.Trimesh, agent: AgentShape) -> trimesh.Trimesh:
    """The triangles of ``mesh`` no steeper than the agent's max slope, cleaned with pymeshlab.

    Close vertices (1e-4 m) are merged, duplicate and zero-area faces and
    unreferenced vertices removed. Small pieces are *not* dropped here: a
    floor made of separate small tiles is one walkable area; islands too
    small for the agent go later (agent checks, ``min_region_area``).
    """
    import pymeshlab  # slow to import; only this builder needs it

    cos_slope = math.cos(math.radians(agent.max_slope_deg))
    keep = (np.asarray(mesh.face_normals)[:, 1] >= cos_slope - 1e-9) & (np.asarray(mesh.area_faces) > 1e-12)
    if not np.any(keep):
        return trimesh.Trimesh(vertices=np.zeros((0, 3)), faces=np.zeros((0, 3), dtype=np.int64), process=False)
    faces = np.asarray(mesh.faces)[keep]
    used, inverse = np.unique(faces.ravel(), return_inverse=True)
    meshset = pymeshlab.MeshSet()
    meshset.add_mesh(
        pymeshlab.Mesh(
            vertex_matrix=np.asarray(mesh.vertices, dtype=np.float64)[used],
            face_matrix=inverse.reshape(-1, 3).astype(np.int32),
        )
    )
    meshset.meshing_merge_close_vertices(threshold=pymeshlab.PureValue(1e-4))
    meshset.meshing_remove_duplicate_faces()
    meshset.meshing_remove_null_faces()
    meshset.meshing_remove_unreferenced_vertices()
    cleaned = meshset.current_mesh()
    surface = trimesh.Trimesh(
        vertices=cleaned.vertex_matrix().astype(np.float64),
        faces=cleaned.face_matrix().astype(np.int64),
        process=False,
    )
    # pymeshlab keeps the winding, so the normals still face up.
    return surface


# --- candidates and the agent checks ----------------------------------------------------


def _in_batches(rows: np.ndarray, size: int) -> list[np.ndarray]:
    """``rows`` (n,) cut into consecutive batches of at most ``size``, in order."""
    return [rows[begin : begin + size] for begin in range(0, len(rows), size)]


def _each_batch(caster: RayCaster, work: Callable[[RayCaster, Batch], None], batches: Sequence[Batch]) -> None:
    """``work(cast, batch)`` for every one of ``batches``, on :data:`RAY_THREADS` threads when there are several.

    Each thread casts through a copy of ``caster`` (the same scene and Embree intersector: Embree answers rays
    from several threads at once), whose rays are added to ``caster.rays_cast`` at the end. ``work`` writes its
    answers only where no other batch writes (the rows of its batch), and a ray's answer does not depend on the
    rays cast beside it, so the answers are the same whichever thread took a batch and when. The first batch runs
    alone when ``caster`` has cast nothing yet (Embree commits its scene on the first ray).
    """
    batches = list(batches)
    if caster.rays_cast == 0 and batches:
        work(caster, batches.pop(0))
    if RAY_THREADS < 2 or len(batches) < 2:
        for batch in batches:
            work(caster, batch)
        return
    casters: list[RayCaster] = []

    def run(batch: Batch) -> None:
        # one caster per thread, made on its first batch
        cast = getattr(own, "caster", None)
        if cast is None:
            cast = own.caster = copy.copy(caster)
            cast.rays_cast = 0
            casters.append(cast)
        work(cast, batch)

    own = threading.local()
    with ThreadPoolExecutor(RAY_THREADS) as pool:
        for done in [pool.submit(run, batch) for batch in batches]:
            done.result()
    caster.rays_cast += sum(cast.rays_cast for cast in casters)


def agent_fits(
    caster: RayCaster,
    points: np.ndarray,
    agent: AgentShape,
    clearance: float,
    triangles: np.ndarray | trimesh.Trimesh | None = None,
    faces: np.ndarray | None = None,
    rejected: np.ndarray | None = None,
    clear_of_walls: np.ndarray | None = None,
) -> np.ndarray:
    """(n,) bool: the agent can stand at each ground point.

    Head room above the point; if ``clearance > 0``, no wall within
    ``clearance`` horizontally at knee (max climb + margin), waist (half
    height) and head (height - margin) levels, and, with the agent's
    ``body_walls``, at the ends of each ``BODY_RAY_STEP`` band of its body
    slab whose curtain along a compass ray a steep face crosses
    (:func:`curtains_crossed`: a belt or rail between those levels) (a steep
    face but a riser the agent steps up, :func:`walls_met`), and in 8 directions at half the
    clearance and at it (``LEDGE_PROBES``) walkable ground rising or falling
    from the probe before (the point itself the first) by a step or the max
    slope over their distance at most, with head room over the outer one. A
    ledge probe that finds none stands on the ground within one crack step
    on both sides of it (each side tried apart at half a step and a step),
    along x, else along z, and with the agent's ``step_gap`` one in a gap
    narrower than that stands on the nearer side's ground
    (:func:`~g2s_plugins._raycasting.ground_beside`, the walk test's rule): a
    grating's slots and tiles laid apart are floor, a gap wider than two
    crack steps (r / 4) and at least ``step_gap`` is a ledge.

    ``triangles``, when given: the corners of a walkable triangle of the
    caster's mesh that each point lies on, (n, 3, 3); or, with ``faces``
    ((n,) int), the corners of a walkable surface (m, 3, 3) and each point
    lies on ``triangles[faces[i]]``, whose neighbours across its edges are
    then known too (given as the surface's Trimesh, found from its shared
    vertices, and only around the triangles that can hold the clearance disk,
    :meth:`~g2s_plugins._raycasting.FloorTriangles.near`: quicker on a finely
    tessellated floor). They only save rays: a point well inside its triangle
    (or the triangles across the edges near it), with nothing else near, has
    ground all around without casting (see :class:`_Surroundings`); the
    answer is the same.

    ``rejected``, when given ((n,) int array), receives the check that turned
    each point away: ``REJECTED_BY``'s index (0: it fits).

    ``clear_of_walls``, when given ((n,) bool array), receives for each point
    that fits whether :func:`nearest_wall` puts it the clearance or more from
    a wall, read from the wall rays cast here (the same 24 rays; a point none
    were cast for has no steep triangle within the clearance of its column,
    so none nearer).
    """
    points = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    why = rejected if rejected is not None else np.zeros(len(points), dtype=np.int8)
    ok = head_room(caster, points, agent)
    why[:] = np.where(ok, 0, REJECTED_BY.index("head room"))
    if clear_of_walls is not None:
        clear_of_walls[:] = True  # no wall is nearer than a clearance of 0
    if clearance <= 0 or not np.any(ok):
        return ok
    # Each test below only casts for the candidates every earlier test kept (a
    # point is out at its first wall), one direction per batch; lowest level first,
    # since most walls reach the knee.
    idx = np.nonzero(ok)[0]
    around = _Surroundings.of(caster, agent, clearance)

    # Walls and obstacles: horizontal rays; a walkable (ramp) face hit is ground, not a wall.
    levels = wall_levels(agent)
    far = around.steep.columns_free(points[idx], levels[0], levels[-1])
    near = idx[~far]
    wall_distance = np.full(len(points), np.inf) if clear_of_walls is not None else None
    clear = np.zeros(len(points), dtype=bool)

    ray_reach = clearance if wall_distance is None else wall_reach(clearance)

    def wall_ray(cast: RayCaster, near: np.ndarray, level: float, direction: np.ndarray) -> np.ndarray:
        """(len(near),) bool: the ray at ``level`` along ``direction`` meets a wall within the clearance."""
        hits = cast.first_hits(points[near] + level * UP, direction)
        met = walls_met(cast, hits, agent, ray_reach)
        wall = met & (hits.distance < clearance)
        why[near[wall]] = REJECTED_BY.index("wall")
        if wall_distance is not None:
            rows = np.flatnonzero(met & ~wall)
            length, _ = _wall_offsets(cast, hits, rows)
            kept = near[rows]
            wall_distance[kept] = np.minimum(wall_distance[kept], length)
        return wall

    def walls(cast: RayCaster, near: np.ndarray) -> None:
        for level in levels:
            for direction in COMPASS:
                near = near[~wall_ray(cast, near, level, direction)]
        # Between those levels (a belt, a rail): where a steep face crosses a compass ray's curtain through the
        # body's slab, rays at the ends of the BODY_RAY_STEP bands it crosses find it (a riser the agent steps up
        # crosses the curtain too and is no wall: the rays' walls_met says so).
        still = np.ones(len(near), dtype=bool)
        if agent.body_walls:
            crossed = curtains_crossed(cast, points[near], agent, ray_reach, np.array([agent.body]))[:, :, 0]
            levels_up = body_levels(agent)
            for k, direction in enumerate(COMPASS):
                rows = np.flatnonzero(crossed[:, k])
                bands = curtains_crossed(cast, points[near[rows]], agent, ray_reach,
                                         np.column_stack([levels_up[:-1], levels_up[1:]]), direction[None])[:, 0]
                at = np.zeros((len(rows), len(levels_up)), dtype=bool)  # (rows, levels): a band next to it is crossed
                at[:, :-1] |= bands
                at[:, 1:] |= bands
                for j, level in enumerate(levels_up):
                    ask = rows[at[:, j] & still[rows]]
                    still[ask[wall_ray(cast, near[ask], level, direction)]] = False
        clear[near[still]] = True

    _each_batch(caster, walls, _in_batches(near, MAX_WALL_BATCH))
    clear[idx[far]] = True
    idx = np.flatnonzero(clear)
    if clear_of_walls is not None:
        clear_of_walls[:] = wall_distance >= clearance

    # Ledges: ground in every direction at the clearance distance, a batch of
    # candidates at a time (8 rays each; one batch for all would hold several
    # (8 n, 3) arrays at once: 0.8 GB for 0.6 M candidates).
    reach = around.reach
    ok[:] = False
    if triangles is not None:
        on = np.asarray(faces)[idx] if faces is not None else np.arange(len(idx))
        if faces is None:
            floor = FloorTriangles(np.asarray(triangles, dtype=np.float64).reshape(-1, 3, 3)[idx], across=False)
        elif isinstance(triangles, trimesh.Trimesh):
            floor, on = FloorTriangles.near(triangles, on, clearance + around.margin)
        else:
            floor = FloorTriangles(np.asarray(triangles, dtype=np.float64).reshape(-1, 3, 3))
        plain = on >= 0
        plain[plain] = around.plain_ground(points[idx[plain]], floor, on[plain])
        ok[idx[plain]] = True
        idx = idx[~plain]

    def walkable(faces: np.ndarray) -> np.ndarray:
        return caster.walkable_faces(faces, agent.max_slope_deg)

    def ledges(cast: RayCaster, rows: np.ndarray) -> None:
        kept = np.ones(len(rows), dtype=bool)
        ground = np.ones((len(rows), len(COMPASS)), dtype=bool)
        distance = np.full((len(rows), len(COMPASS), LEDGE_PROBES + 1), reach)  # the point itself lies reach down
        for j in range(1, LEDGE_PROBES + 1):
            origins = points[rows][:, None, :] + j * around.step * COMPASS[None, :, :] + reach * UP
            down = cast.first_hits(origins.reshape(-1, 3), -UP)
            found = ((down.distance <= 2.0 * reach) & walkable(down.face)).reshape(ground.shape)
            distance[:, :, j] = np.where(found, down.distance.reshape(ground.shape), 0.0)
            # A probe over a crack (a grating's slot) stands on the ground beside it, as in the walk test; direction
            # by direction, only for the points no earlier probe has put out (one probe without ground is enough).
            for k in range(len(COMPASS)):
                missing = np.flatnonzero(kept & ~found[:, k])
                crack, beside = ground_beside(cast, origins[missing, k], 2.0 * reach, walkable, agent)
                distance[missing[crack], k, j] = beside[crack]
                kept[missing[~crack]] = False
                if agent.step_gap:  # one over a narrow gap above a floor deeper than the climb: ground_beside's
                    floor = distance[:, k, j - 1] + agent.max_climb
                    deep = np.flatnonzero(kept & found[:, k] & (distance[:, k, j] > floor))
                    over, beside = ground_beside(cast, origins[deep, k], floor[deep], walkable, agent)
                    distance[deep[over], k, j] = beside[over]
        ground[~kept] = False
        # Between neighbouring probes the ground rises or falls by the walk test's step or slope at most.
        ground &= np.abs(np.diff(distance, axis=2)).max(axis=2) <= around.rise + RISE_TOLERANCE
        # Head room over the outer landing point, from that probe's own origin (see walks_in_batch).
        ground[ground] = clear_above(cast, origins[ground], agent.height - distance[:, :, -1][ground])
        ok[rows] = ground.all(axis=1)  # a probe that put its point out kept no ground
        why[rows[~ok[rows]]] = REJECTED_BY.index("ledge")

    _each_batch(caster, ledges, _in_batches(idx, MAX_LEDGE_BATCH))
    return ok


def wall_levels(agent: AgentShape) -> list[float]:
    """Heights (m over a ground point, ascending) of :func:`agent_fits`' horizontal wall rays: knee and head (the
    agent's body, :attr:`AgentShape.body`) and waist (half the height)."""
    return sorted({round(level, 6) for level in (*agent.body, 0.5 * agent.height)})


BODY_RAY_STEP = 0.025
"""Metres: the bands of the agent's body slab whose curtains :func:`agent_fits` asks along a compass direction whose
curtain a steep face crosses (:func:`curtains_crossed`); rays at the ends of each band crossed find a bar, belt or
edge this tall or taller."""


def body_levels(agent: AgentShape) -> np.ndarray:
    """Heights (m over a ground point, ascending) of the wall rays up the agent's body slab
    (:attr:`~g2s_plugins._raycasting.AgentShape.body`), ``BODY_RAY_STEP`` apart, both ends included."""
    knee, head = agent.body
    count = max(1, math.ceil((head - knee) / BODY_RAY_STEP))
    return knee + (head - knee) * np.arange(count + 1) / count


def curtains_crossed(caster: RayCaster, points: np.ndarray, agent: AgentShape, reach: float, heights: np.ndarray,
                     directions: np.ndarray = COMPASS) -> np.ndarray:
    """(n, len(directions), len(heights)) bool: a triangle steeper than the agent's max slope crosses the vertical
    curtain from each ground point ``reach`` metres along each direction, between each pair of ``heights`` ((b, 2) m
    over the point): the walk test's slab test (:attr:`~g2s_plugins._raycasting.SteepFaces.slab_grid`,
    :func:`~g2s_plugins._raycasting.walks_in_batch` with ``body``) on a slab ``GRAZE_NUDGE`` wide. With the agent's
    body slab (:attr:`~g2s_plugins._raycasting.AgentShape.body`) a belt or rail hanging between :func:`wall_levels`'
    rays is crossed; whether it is a wall is the rays' to say (a riser the agent steps up is not, :func:`walls_met`).
    One extension call; O(n len(directions) len(heights)) slab tests after the broad phase."""
    points = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    heights = np.asarray(heights, dtype=np.float64).reshape(-1, 2)
    shape = (len(points), len(directions), len(heights))
    steep = caster.steep_faces(agent.max_slope_deg)
    if 0 in shape or len(steep.triangles) == 0:
        return np.zeros(shape, dtype=bool)
    low = np.broadcast_to(points[:, None, None, :], (*shape, 3)).reshape(-1, 3)
    along = np.broadcast_to((directions * reach)[None, :, None, :], (*shape, 3)).reshape(-1, 3)
    side = np.cross(UP, directions) * (2.0 * GRAZE_NUDGE)  # horizontal, at right angles
    side = np.broadcast_to(side[None, :, None, :], (*shape, 3)).reshape(-1, 3)
    band = np.broadcast_to(heights[None, None, :, :], (*shape, 2)).reshape(-1, 2)
    meets = steep.slab_grid.meets(np.ascontiguousarray(low), np.ascontiguousarray(along), np.ascontiguousarray(side),
                                  np.ascontiguousarray(band), GRAZE_NUDGE)
    return np.asarray(meets).reshape(shape)


def walls_met(caster: RayCaster, hits: Hits, agent: AgentShape, reach: float) -> np.ndarray:
    """(n,) bool: each level ray of ``hits`` (a wall ray, :func:`wall_levels`) met a wall within ``reach`` metres: a
    triangle steeper than the max slope that is not a riser the agent steps up.

    A riser: the ground in front of the face (a downward ray from ``EPSILON`` back along the ray from the hit) lies
    within the climb under the hit, and the face's top (a downward ray ``EPSILON`` past the hit, from just over the
    climb over that ground) is walkable ground no lower than the hit and no higher than the climb over that ground: between those two probes the ground rises by a step at
    most, the walk test's rule (:func:`~g2s_plugins._raycasting.walks_in_batch`), so the agent walking along the ray
    steps onto it (Recast erodes the walkable area only at a neighbour more than a step higher). A knee-high ray on a
    flight steeper than the knee over the clearance (0.30 m risers on 0.30 m treads) meets the riser two steps up,
    which stopped no agent (docs/sampling.md, "Steep flights and ledge tops"). A wall, a steep slope, a thin fence
    or a block over the climb, whatever it stands on, stays a wall; so does a riser onto a slot of a grating (no
    crack rule here). Up to two downward rays a steep hit within ``reach``.
    """
    wall = (hits.distance < reach) & ~caster.walkable_faces(hits.face, agent.max_slope_deg)
    rows = np.flatnonzero(wall)
    if len(rows) == 0:
        return wall
    at, unit = hits.points[rows], hits.unit[rows]
    front = caster.first_hits(at - EPSILON * unit, -UP)
    low = (front.distance <= agent.max_climb) & caster.walkable_faces(front.face, agent.max_slope_deg)
    # The top ray starts EPSILON over the climb, so that a riser of exactly the climb is met from above.
    rows, at, unit, lift = rows[low], at[low], unit[low], agent.max_climb - front.distance[low] + EPSILON
    top = caster.first_hits(at + EPSILON * unit + lift[:, None] * UP, -UP)
    step = (top.distance >= EPSILON - RISE_TOLERANCE) & (top.distance <= lift + EPSILON)
    wall[rows] = ~(step & caster.walkable_faces(top.face, agent.max_slope_deg))
    return wall


def wall_reach(clearance: float) -> float:
    """Metres: how far a compass ray reads walls for :func:`nearest_wall`, ``clearance`` / cos 22.5 degrees (a wall
    between two compass directions is that far along them when it is ``clearance`` away)."""
    return clearance / math.cos(math.pi / len(COMPASS))


REJECTED_BY = ("fits", "head room", "wall", "ledge")
"""What :func:`agent_fits` reports in ``rejected``: the index of the first check a point failed."""


def inside_closed_solids(caster: RayCaster, points: np.ndarray, agent: AgentShape) -> np.ndarray:
    """(n,) bool: each ground point lies inside a closed solid (a building block standing on the floor).

    A point is inside when, straight up from it and along +x, +z, -x and -z
    from half the agent's height over it (rays of unlimited length), the
    triangles met on their back side come to outnumber those met from the
    front (:func:`~g2s_plugins._raycasting.back_face_lead`): a closed body
    wound outwards, seen from within. Its own face met first is one back
    face; where that face lies buried in a wall, a floor, a ceiling or
    another body it overlaps, the first face met is that other body's, seen
    from the front, and its back face, past the buried one, makes the lead.
    A place meant to be walked is seen from the front: a room's walls face
    into it, a single quad (-1, never made up) or a wall slab (-1 then +1),
    and the underside of a bridge or a slab faces down at it (-1 then +1).
    A single-sided upper floor (a quad facing up) is met from behind above a
    room, but the room's walls are not, so its floor stays. A ray that meets
    nothing leaves the point outside. A level wound inside out is met from
    the front first everywhere, so it loses no point here and
    :mod:`g2s_plugins.walkable_check` still speaks about it. Faces in one
    plane (a crate against a wall or on another crate, a pillar's top in a
    ceiling) are all counted, back faces first at one place
    (:func:`~g2s_plugins._raycasting.back_face_lead`).

    The agent checks cannot tell: a solid taller than the agent and wider
    than twice the clearance leaves its floor's middle with head room and
    no wall or ledge within the clearance.

    Cost: one multiple-hit upward ray a point (one intersector pass per
    triangle crossed above it, and one more; the faces in one plane it
    stepped past found from the pairs of such faces, built once per mesh on
    its first crossing), and four multiple-hit horizontal rays for the
    points with a lead upwards
    (:func:`~g2s_plugins._raycasting.closed_solid_holds`, all five rays).
    """
    return closed_solid_holds(caster, points, agent.height)


STRANDED_REACH = math.sqrt(2.0)
"""Spacings: a candidate turned away by a wall or a ledge is *stranded* (:func:`moved_into_passages`) when the
candidates that fit this near it (``STRANDED_NEIGHBOURS`` at most) are none, or stand in more than one connected part
of the graph, or in a part too small to keep. Beside one straight wall or ledge of open floor some grid neighbour (8
of them, at most sqrt 2 spacings away) stands the clearance or more from it and fits, in the floor's part, so the
stranded are those of a passage whose band no line of the grid crosses (or crosses only here and there, at a slant,
leaving pieces of it apart), a nook, or a top too small for the agent."""

STRANDED_NEIGHBOURS = 8
"""The candidates that fit nearest a turned-away one (within ``STRANDED_REACH`` spacings) that decide whether it is
stranded: a grid candidate's 8 neighbours."""

MOVE_ROUNDS = 3
"""Moves at most per stranded candidate (:func:`moved_into_passages`): one off a straight wall, one per wall it
meets in a corner."""

LEDGE_PROBES = 2
"""Ground probes along each of :func:`agent_fits`' 8 ledge directions, evenly spaced out to the clearance, between
which (the point itself the first) the ground may rise or fall by the walk test's step or slope at most: half the
clearance apart (0.25 m for the presets' agent, the walk test's probe step), a flight's risers under the climb pass one
at a time and a block over it within the clearance (a bench, a bunk, a shelf's top narrower than the agent) does not.
One probe at the clearance alone read ground within max(climb, slope) of the point: a 45-degree flight of 0.30 m
treads put two risers, 0.6 m, within 0.5 m of every point, and a bench 0.45 m high passed (docs/sampling.md,
"Stairs and narrow ledge tops")."""

GROUND_DIRECTIONS = 32
"""Level directions in which :func:`ledge_room` looks for a ledge and an added point needs ground at the clearance
(:func:`_fits_clear`): a straight ledge is 360 / 64 degrees or less off one of them, so a band between ledges
narrower than the agent by more than 1 - cos 5.625 degrees (0.5 %) holds no such point, and a move along the one
with least room puts a point that far from the ledge (:func:`agent_fits`' 8 directions let a point stand 0.46 m from
a ledge 22 degrees off them)."""

AROUND = np.array(
    [[math.cos(a), 0.0, math.sin(a)] for a in np.arange(GROUND_DIRECTIONS) * (2.0 * math.pi / GROUND_DIRECTIONS)]
)
"""(GROUND_DIRECTIONS, 3) unit level vectors, counter-clockwise from +x in plan."""

LEDGE_HALVINGS = 6
"""Halvings that place a ledge along a direction (:func:`ledge_room`): to a 64th of the clearance (8 mm for 0.5 m)."""

REACH_STEPS = 4
"""Steps of half a spacing a moved sample's band is followed each way (:func:`moved_into_passages`): two spacings,
from a passage's first samples out past its mouth (a clearance deep) onto the floor it opens on."""

END_HALVINGS = 6
"""Halvings that place the last point of a band the agent fits at (:func:`moved_into_passages`): to a 128th of a
spacing (8 mm for 1 m), finer than the band of a passage 5 cm wider than the agent."""


def nearest_wall(caster: RayCaster, points: np.ndarray, agent: AgentShape, clearance: float) -> tuple[np.ndarray, np.ndarray]:
    """``(distance, away)``: (n,) metres from each ground point ((n, 3)) to the nearest steep triangle that a compass
    ray at a wall ray's height (:func:`wall_levels`) meets within ``clearance`` / cos 22.5 degrees (inf: none), and
    (n, 3) the level unit direction from that triangle's nearest point to the point.

    The distance is to the triangle, not along the ray: a wall 22 degrees off a compass direction that
    :func:`agent_fits`' rays read 0.5 m away stands 0.46 m off, and the agent, 0.5 m wide each side, does not fit
    there; at a passage's mouth the rays meet the wall's end face beside it, whose nearest point is its corner.
    24 rays a point, the nearest points by ``trimesh.triangles.closest_point``.
    """
    points = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    distance = np.full(len(points), np.inf)
    away = np.zeros((len(points), 3))
    for level in wall_levels(agent):
        for direction in COMPASS:
            hits = caster.first_hits(points + level * UP, direction)
            wall = np.flatnonzero(walls_met(caster, hits, agent, wall_reach(clearance)))
            if len(wall) == 0:
                continue
            length, level_offset = _wall_offsets(caster, hits, wall)
            nearer = length < distance[wall]
            rows = wall[nearer]
            distance[rows] = length[nearer]
            away[rows] = np.where((length[nearer] > 0)[:, None], level_offset[nearer] / np.maximum(length[nearer], 1e-12)[:, None], -direction)
    return distance, away


def _wall_offsets(caster: RayCaster, hits: Hits, rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(length, offset)`` of the level rays ``hits[rows]``, each of which met a wall (:func:`walls_met`): (k,) the
    level distance (m) from that triangle's nearest point (``trimesh.triangles.closest_point``) to the ray's origin and
    (k, 3) the level offset itself."""
    origins = hits.origins[rows]
    offset = (origins - trimesh.triangles.closest_point(caster.triangles[hits.face[rows]], origins)) * [1.0, 0.0, 1.0]
    return np.linalg.norm(offset, axis=1), offset


def ledge_room(caster: RayCaster, points: np.ndarray, agent: AgentShape, clearance: float) -> np.ndarray:
    """(n, ``GROUND_DIRECTIONS``) metres, at most ``clearance``: how far each ground point ((n, 3)) may go along each
    of the ``AROUND`` directions before a ledge: where a downward ray from a step or the max slope over the clearance (and the ground margin) above
    the point's height finds no walkable face within twice that. Where the probe at the clearance finds none, the
    last probe that does is found by halving (``LEDGE_HALVINGS``); a probe inside a wall finds none either, so a
    wall's foot reads as a ledge too. Plain rays (no crack, no head room over the landing): the answer places a point,
    :func:`agent_fits` decides on it. ``GROUND_DIRECTIONS`` downward rays a point and ``LEDGE_HALVINGS`` more for each
    direction with a ledge.
    """
    points = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    room = np.full((len(points), GROUND_DIRECTIONS), float(clearance))

    def measure(cast: RayCaster, batch: np.ndarray) -> None:
        rows, dirs = np.divmod(np.arange(len(batch) * GROUND_DIRECTIONS), GROUND_DIRECTIONS)
        rows = batch[rows]
        edge = ~_ground_at(cast, agent, clearance, points[rows] + clearance * AROUND[dirs])[0]
        rows, dirs = rows[edge], dirs[edge]
        low, high = np.zeros(len(rows)), np.full(len(rows), float(clearance))
        for _ in range(LEDGE_HALVINGS):
            middle = 0.5 * (low + high)
            found = _ground_at(cast, agent, clearance, points[rows] + middle[:, None] * AROUND[dirs])[0]
            low, high = np.where(found, middle, low), np.where(found, high, middle)
        room[rows, dirs] = low

    _each_batch(caster, measure, _in_batches(np.arange(len(points)), MAX_ROOM_BATCH))
    return room


def _ground_at(caster: RayCaster, agent: AgentShape, clearance: float, points: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(found, ground, face)``: (n,) bool, walkable ground within a step or the max slope over ``clearance`` of each
    point's ((n, 3)) height; (n, 3) the point moved onto it; (n,) its face (-1: none). One downward ray each."""
    reach = float(agent.max_rise(clearance)) + GROUND_MARGIN
    down = caster.first_hits(points + reach * UP, -UP)
    found = (down.distance <= 2.0 * reach) & caster.walkable_faces(down.face, agent.max_slope_deg)
    ground = points + np.where(found, reach - down.distance, 0.0)[:, None] * UP
    return found, ground, np.where(found, down.face, -1)


def _fits_clear(caster: RayCaster, agent: AgentShape, clearance: float, points: np.ndarray) -> np.ndarray:
    """(n,) bool: the agent fits at each ground point ((n, 3); :func:`agent_fits`), no steep triangle its rays meet
    lies nearer than ``clearance`` (:func:`nearest_wall`), there is ground at the clearance in ``GROUND_DIRECTIONS``
    directions (:func:`_ground_at`) and no closed solid holds it (:func:`inside_closed_solids`)."""
    clear_of_walls = np.zeros(len(points), dtype=bool)
    ok = agent_fits(caster, points, agent, clearance, clear_of_walls=clear_of_walls)
    ok &= clear_of_walls
    rows = np.flatnonzero(ok)
    probes = (points[rows][:, None, :] + clearance * AROUND[None, :, :]).reshape(-1, 3)
    ok[rows] = _ground_at(caster, agent, clearance, probes)[0].reshape(len(rows), GROUND_DIRECTIONS).all(axis=1)
    ok[ok] = ~inside_closed_solids(caster, points[ok], agent)
    return ok


def _fit_on_ground(caster: RayCaster, agent: AgentShape, clearance: float, points: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(ok, ground, face)`` as :func:`_ground_at`, ``ok`` also requiring :func:`_fits_clear` there."""
    ok, ground, face = _ground_at(caster, agent, clearance, points)
    ok[ok] = _fits_clear(caster, agent, clearance, ground[ok])
    return ok, ground, face


ADDED_LATTICE = 2.0**-20
"""Metres: the lattice :func:`moved_into_passages` puts its points on (a power of two, so whole metres plus a lattice
step are exact in float64 for any level within 10^9 m of the origin)."""


def moved_into_passages(
    caster: RayCaster,
    agent: AgentShape,
    clearance: float,
    spacing: float,
    candidates: np.ndarray,
    fits: np.ndarray,
    rejected: np.ndarray,
    part: np.ndarray,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(points, faces, stranded)``: points added where a passage's band holds no candidate that fits, (k, 3) m;
    (k,) the caster's faces under them; the indices of the stranded candidates (below) they were found from.

    A passage only a little wider than the agent leaves its centre a band narrower than the spacing, which the
    grid's lines (or the Poisson candidates) may all miss: the passage then holds no sample and the floors it joins
    are apart (the band of a flight 1.4 m wide, 0.4 m, missed by a 1 m grid's rows 0.07 m each side). Its candidates
    are stranded (``STRANDED_REACH``; ``candidates`` (n, 3), ``fits`` (n,) bool, ``rejected`` (n,) the
    :data:`REJECTED_BY` index from :func:`agent_fits`, ``part`` (f,) the connected part of the sample each candidate
    that fits stands in, -1 for a part too small to keep, :func:`_joined_parts`).

    1. *Moved*: each stranded candidate goes straight away from the nearer of the nearest wall (off its nearest
       point, :func:`nearest_wall`) and the nearest ledge (back along the direction with the least room,
       :func:`ledge_room`) until it stands the clearance (and ``EPSILON``) from it, onto the ground there, up to
       ``MOVE_ROUNDS`` times (a wall on the other side moves it back, so a passage the agent does not fit in stays
       empty).
    2. *Followed*: from each one that moved, the band is followed both ways across its last move (along the wall
       or ledge it moved off), ``REACH_STEPS`` steps of half a spacing, each on the ground
       and kept while the agent fits; where it stops fitting, the last place it fits is found by halving
       (``END_HALVINGS``). These reach out of a passage's mouth onto the floor beyond and, at a turn, into the
       corner where the two legs' bands cross, which straight edges from a sample a spacing away would cut.

    Every point is kept where the agent fits with its whole width (:func:`_fits_clear`: :func:`agent_fits`, no wall
    nearer than the clearance, ground at the clearance all round, no closed solid), none of the moved or followed
    ones within half a spacing of an earlier one (the ends of the bands: within ``EPSILON`` of an earlier end; a
    followed point near a grid sample is kept, since where a leg the grid samples meets a missed one only the point
    where their bands cross joins them). The edges' walk test then decides, as for every sample, where the agent
    walks.

    Cost: for s stranded candidates (none on open floor), ``MOVE_ROUNDS`` x (24 + 32 rays and the halvings) each,
    the checks at up to 2 x (``REACH_STEPS`` + ``END_HALVINGS``) points each; one k-d tree query over the
    turned-away candidates.
    """
    none = np.zeros((0, 3)), np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64)
    turned = np.flatnonzero(np.isin(rejected, (REJECTED_BY.index("wall"), REJECTED_BY.index("ledge"))))
    if clearance <= 0 or len(turned) == 0:
        return none
    fitting = spatial.cKDTree(candidates[fits]) if np.any(fits) else None
    if fitting is not None:
        near = fitting.query(candidates[turned], k=STRANDED_NEIGHBOURS, distance_upper_bound=STRANDED_REACH * spacing * (1.0 + 1e-9))[1]
        found = near < len(part)
        label = np.where(found, np.concatenate([part, [-1]])[near], -1)
        lowest = np.where(found, label, np.iinfo(np.int64).max).min(axis=1)
        highest = label.max(axis=1)
        small = np.any(found & (label < 0), axis=1)
        turned = turned[~found.any(axis=1) | small | (lowest != highest)]
    landed, points, face = _ground_at(caster, agent, clearance, candidates[turned])
    points, face = points[landed], face[landed]
    along = np.zeros((len(points), 3))  # the band's direction where a point moved (0: it did not)
    moving = np.arange(len(points))
    for _ in range(MOVE_ROUNDS):
        if len(moving) == 0:
            break
        # away from the nearer of the nearest wall (straight off it) and the nearest ledge (along the compass ray)
        wall, off_wall = nearest_wall(caster, points[moving], agent, clearance)
        room = ledge_room(caster, points[moving], agent, clearance)
        worst = np.argmin(room, axis=1)
        ledge = room[np.arange(len(moving)), worst]
        off_wall_first = wall <= ledge + clearance / 2**LEDGE_HALVINGS  # a wall's foot reads as a ledge too
        short = clearance - np.where(off_wall_first, wall, ledge)
        away = np.where(off_wall_first[:, None], off_wall, -AROUND[worst])
        move = short > 0
        moving, short, away = moving[move], short[move], away[move]
        along[moving] = np.cross(away, UP)
        landed, points[moving], face[moving] = _ground_at(caster, agent, clearance, points[moving] + (short + EPSILON)[:, None] * away)
        face[moving[~landed]] = -1
        moving = moving[landed]
    ok = face >= 0
    ok[ok] = _fits_clear(caster, agent, clearance, points[ok])
    moved, moved_face, along = points[ok], face[ok], along[ok]

    # Followed: both ways from each moved point along its band.
    starts = np.flatnonzero(np.any(along != 0.0, axis=1))
    last = np.concatenate([moved[starts], moved[starts]])
    heading = np.concatenate([along[starts], -along[starts]])
    steps: list[tuple[np.ndarray, np.ndarray]] = []
    going = np.arange(len(last))
    stopped = np.zeros(0, dtype=np.int64)
    step = 0.5 * spacing
    for _ in range(REACH_STEPS):
        fit, ground, under = _fit_on_ground(caster, agent, clearance, last[going] + step * heading[going])
        steps.append((ground[fit], under[fit]))
        stopped = np.concatenate([stopped, going[~fit]])
        last[going[fit]] = ground[fit]
        going = going[fit]
    low, high = np.zeros(len(stopped)), np.full(len(stopped), step)
    end, end_face = last[stopped].copy(), np.full(len(stopped), -1, dtype=np.int64)
    for _ in range(END_HALVINGS):
        middle = 0.5 * (low + high)
        fit, ground, under = _fit_on_ground(caster, agent, clearance, last[stopped] + middle[:, None] * heading[stopped])
        end[fit], end_face[fit] = ground[fit], under[fit]
        low, high = np.where(fit, middle, low), np.where(fit, high, middle)
    end, end_face = end[end_face >= 0], end_face[end_face >= 0]
    if len(end) > 1:
        first = np.sort(_throw_darts(end, EPSILON))
        end, end_face = end[first], end_face[first]

    points = np.concatenate([moved, *(p for p, _ in steps)])
    face = np.concatenate([moved_face, *(f for _, f in steps)])
    if len(points) > 1:
        first = np.sort(_throw_darts(points, 0.5 * spacing))
        points, face = points[first], face[first]
    # on a binary lattice of the caster's frame (whole metres from the world's origin), so that a level moved far
    # keeps every distance between its samples bit for bit, and with them the ties its later stages break
    local = np.round(caster.frame.to_local(np.concatenate([points, end])) / ADDED_LATTICE) * ADDED_LATTICE
    return caster.frame.to_world(local), np.concatenate([face, end_face]), turned


class _Surroundings:
    """What lies near a candidate, known without rays: answers that make some of ``agent_fits``'s rays needless.

    Every triangle's bounding box, grown by the clearance sideways and by
    ``margin`` on all sides, goes into one of two :class:`BoxOccupancy` grids:
    ``steep`` (steeper than the max slope: walls, ceilings, undersides) or
    ``walkable``. The margin covers how far Embree may see a ray from where
    it is: each origin goes to Embree rounded to float32 at its coordinates
    in the caster's local frame (:attr:`RayCaster.local_origin`; within a
    kilometre or so of the level, wherever the level lies), the level is
    scaled in float32, and a grazing ray is cast again nudged aside
    (:meth:`RayCaster.first_hits`).

    * No steep cell along a candidate's column from knee to head: no
      horizontal ray of ``clearance`` metres from it can meet a wall.
    * :meth:`plain_ground`: ground all around, certain.
    """

    def __init__(self, caster: RayCaster, agent: AgentShape, clearance: float) -> None:
        corners = caster.triangles
        self.agent, self.clearance = agent, clearance
        self.step = clearance / LEDGE_PROBES
        """Metres between neighbouring ledge probes (the point itself the first)."""
        self.rise = float(agent.max_rise(self.step))
        """Metres the ground may rise or fall between neighbouring ledge probes: the walk test's rule (a step or the
        max slope over their distance)."""
        self.reach = LEDGE_PROBES * self.rise + GROUND_MARGIN
        """Metres above the point's height the ledge rays start from: over the outermost probe's highest ground, plus
        the ground margin."""
        self.margin = ray_margin(caster, clearance + self.reach + agent.height)
        """Metres (:func:`~g2s_plugins._raycasting.ray_margin` over the highest ray start)."""
        if self.margin >= self.reach:  # a level hundreds of kilometres across: no ray could tell a step from a floor
            raise G2SError(
                f"sampling: the level is too large for the ray caster: rays on it are precise to {self.margin:.3g} m, "
                f"not within the {self.reach:.3g} m the ledge test looks down; check mesh.scale (the file's units to metres)"
            )
        widen = np.array([clearance + self.margin, self.margin, clearance + self.margin])
        walkable = caster.walkable_faces(np.arange(len(corners)), agent.max_slope_deg)
        cell = max(clearance, 0.25)
        self.steep = BoxOccupancy(corners[~walkable], widen, cell)
        # Cells half as high as a rise between probes (before any growing): a flat floor's own cell never reaches the
        # height plain_ground looks from.
        self.walkable = BoxOccupancy(corners[walkable], widen, np.array([cell, min(cell, 0.5 * (self.rise - self.margin)), cell]))

    @classmethod
    def of(cls, caster: RayCaster, agent: AgentShape, clearance: float) -> _Surroundings:
        """The surroundings of ``caster``'s mesh for this agent and clearance, built on the first call and kept
        while the caster lives: :func:`moved_into_passages` asks :func:`agent_fits` about a few points at a time,
        up to 12 times a build, and grids of the whole mesh built each time were a fifth of the 100k level's step 1
        (docs/performance.md)."""
        kept = _SURROUNDINGS.setdefault(caster, {})
        found = kept.get((agent, clearance))
        if found is None:
            found = kept[(agent, clearance)] = cls(caster, agent, clearance)
        return found

    def plain_ground(self, points: np.ndarray, floor: FloorTriangles, faces: np.ndarray) -> np.ndarray:
        """(n,) bool: the ledge test certainly passes at ``points`` (each on its triangle ``faces[i]`` of ``floor``).

        True where the clearance disk around a point (grown by ``margin``)
        lies inside its own walkable triangle seen from above, or inside it
        and the triangles across the edges the disk crosses
        (:meth:`~g2s_plugins._raycasting.FloorTriangles.disk_inside`), those
        triangles within ``drop`` of the point's height under the disk;
        where no steep triangle is near the point's column from that lowest
        point to the agent's height above the ledge rays' start; and where no
        walkable one is near it from ``rise - drop`` (less the margin) over
        the point up to there. Then each downward ledge ray lands on one of
        those triangles or on a walkable face under that height, so within
        ``drop`` below and ``rise - drop`` above the point: two neighbouring
        probes' grounds differ by less than ``rise`` (on those triangles, no
        steeper than the max slope, by at most the slope over ``step``), and
        each upward ray meets nothing within the agent's height: the rays'
        answer, without them.
        """
        top = self.reach + self.agent.height
        plain, drop = floor.disk_inside(points, faces, self.clearance + self.margin, self.clearance)
        low = self.rise - drop - self.margin
        plain &= low > drop
        plain[plain] = self.steep.columns_free(points[plain], -drop[plain] - self.margin, top)
        plain[plain] = self.walkable.columns_free(points[plain], low[plain], top)
        return plain


_SURROUNDINGS: weakref.WeakKeyDictionary[RayCaster, dict[tuple[AgentShape, float], _Surroundings]] = weakref.WeakKeyDictionary()
"""Each caster's :class:`_Surroundings` by agent and clearance (:meth:`_Surroundings.of`); an entry leaves with its
caster."""


def _poisson_candidates(surface: trimesh.Trimesh, spacing: float, params: Params) -> tuple[np.ndarray, np.ndarray, float]:
    """Dense random points on ``surface``: (points, face index, area each point stands for)."""
    area = float(surface.area)
    wanted = area * params.candidate_density / spacing / spacing  # spacing**2 is 0 for a spacing under 1e-162 m
    if not wanted <= MAX_CANDIDATES:
        raise G2SError(
            f"sampling: spacing {spacing:g} m is too small for {area:.4g} m² of walkable surface "
            f"({wanted:.4g} candidate points); use a larger spacing or a smaller candidate_density, or check "
            "mesh.scale (the file's units to metres)"
        )
    count = math.ceil(wanted)
    points, faces = trimesh.sample.sample_surface(surface, max(count, 1), seed=params.seed)
    return np.asarray(points, dtype=np.float64), np.asarray(faces, dtype=np.int64), area / max(count, 1)


GRID_OFFSET = (0.2548776662466927, 0.0698402909980533)
"""How far (fractions of the spacing, along x and z) the grid lies from the one centred on the footprint.

Centred, with whole-metre extents and a spacing of twice a 0.5 m agent radius, the grid's lines, and the agent
checks' probes a clearance (half the spacing) from them, fall exactly on a generated level's walls and triangle
edges, where a ray's hit or miss is decided by rounding: the same level moved 10 km got other samples
(sample:dungeon: 594, not 589). These fractions (1/g - 1/2 and 1/g^2 - 1/2, g the plastic number 1.3247...) are
neither simple fractions, nor are their sums and differences with each other and with a half, so neither the
lines nor their probes meet lines on simple fractions of a metre or at 45 degrees (measured in docs/sampling.md).
"""


GRID_TOLERANCE = 1e-9
"""Relative: a footprint's width within this of a whole number of spacings counts as that number."""

GRID_QUANTUM = 2.0**-26
"""Metres (15 nm): the grid's lines lie on its multiples, see :func:`_on_quantum`."""


def _on_quantum(start: float, spacing: float, count: int) -> np.ndarray:
    """(count,) line positions ``start + k spacing`` (m), each rounded to a multiple of ``GRID_QUANTUM``.

    The steps ``k spacing`` are rounded on their own, so the lines' distances to each other are the same bits
    wherever the level lies: sums of multiples of the quantum below 2^26 m are exact, and a level moved by whole
    metres gets the same lines moved by exactly as much (only ``start`` may round to its neighbour, a quantum
    away). Without it, positions 10 km out keep fewer bits than at the origin, and pairs of samples exactly
    ``connect_radius`` or ``gap_radius`` apart (whole multiples of the spacing) were taken or not by rounding.
    """
    steps = np.round(spacing * np.arange(count) / GRID_QUANTUM) * GRID_QUANTUM
    return float(np.round(start / GRID_QUANTUM)) * GRID_QUANTUM + steps


def _grid_candidates(surface: trimesh.Trimesh, spacing: float, agent: AgentShape | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Points where a regular XZ grid of vertical lines crosses ``surface``: (points, face index); with ``agent``,
    also the points of lines through a crack over that agent's floor (:func:`_crack_candidates`)."""
    lo, hi = np.asarray(surface.bounds)
    # inf for a tiny spacing. A footprint a whole number of spacings wide gets that many + 1 lines wherever it
    # lies: 10 km out its width may come out a rounding under (sample:t_junction: 13 x 3 lines at the origin,
    # 13 x 4 there).
    across = [float(np.floor((hi[i] - lo[i]) / spacing * (1.0 + GRID_TOLERANCE))) + 1 for i in (0, 2)]
    if not across[0] * across[1] <= MAX_CANDIDATES:
        raise G2SError(f"sampling: spacing {spacing:g} m gives a grid of {across[0]:.4g} x {across[1]:.4g} points; use a larger spacing")
    nx_, nz_ = map(int, across)
    # Centre the grid on the surface's footprint, then move it off the level's own lines (GRID_OFFSET).
    x0 = lo[0] + 0.5 * ((hi[0] - lo[0]) - (nx_ - 1) * spacing) + GRID_OFFSET[0] * spacing
    z0 = lo[2] + 0.5 * ((hi[2] - lo[2]) - (nz_ - 1) * spacing) + GRID_OFFSET[1] * spacing
    gx, gz = np.meshgrid(_on_quantum(x0, spacing, nx_), _on_quantum(z0, spacing, nz_), indexing="ij")
    xz = np.column_stack([gx.ravel(), gz.ravel()])
    caster = RayCaster(surface)
    column, points, faces = all_hits_down(caster, xz, hi[1] + 1.0)
    if len(points) == 0:
        return points, faces
    # Crossings of one line closer than a centimetre (shared triangle edges) are one point.
    duplicate = np.zeros(len(points), dtype=bool)
    duplicate[1:] = (column[1:] == column[:-1]) & (np.abs(np.diff(points[:, 1])) < EPSILON)
    column, points, faces = column[~duplicate], points[~duplicate], faces[~duplicate]
    if agent is not None:
        more, more_faces = _crack_candidates(caster, xz, (nx_, nz_), column, points, faces, agent, spacing, hi[1] + 1.0)
        points, faces = np.concatenate([points, more]), np.concatenate([faces, more_faces])
    return points, faces


def _crack_candidates(caster: RayCaster, xz: np.ndarray, shape: tuple[int, int], column: np.ndarray, points: np.ndarray,
                      faces: np.ndarray, agent: AgentShape, spacing: float, top: float) -> tuple[np.ndarray, np.ndarray]:
    """The grid lines through a crack: (points, face index) on the floor beside lines that met none there.

    A vertical line through a grating's slot meets no bar (the floor below, or nothing), and a whole grid column (bars
    along z) or row (bars along x) meets bars or slots alike, so a grating got samples in whole columns with columns
    missing between (docs/analysis_quality.md, the thirty-sixth round's gratings). A line that meets no floor within
    the climb of a floor met by the lines a crack step (:func:`~g2s_plugins._raycasting.crack_sides`) away on both
    sides, at half or a whole step (:data:`~g2s_plugins._raycasting.CRACK_STEPS`), along x or z, takes a point on
    that floor (the higher side's): the ledge probes' and the walk test's crack rule, which the agent checks apply to
    the point again. Only the lines that lack a floor a neighbouring line has are asked: within the climb of that
    floor, or of its own slope over the spacing (at most the max slope's), so that a floor under a flat grating 0.4-1
    m down does not pass for the grating's own while a ramp's next line is not asked. They are asked round after round
    from the points added, until no line gains one: a grating with no line on a bar is reached from the floor round
    it, and on other ground only the lines past a floor's edge are asked (docs/sampling.md, "Grid lines through
    gratings' slots").

    Eight multiple-hit lines a line asked (2 axes x 2 sides x 2 steps).
    """
    nx_, nz_ = shape
    normals = caster.face_normals

    def rise(face: np.ndarray) -> np.ndarray:  # (n,) m: the height a floor of these faces gains over the spacing
        up = np.clip(np.abs(normals[face, 1]), EPSILON, 1.0)
        return np.clip(np.sqrt(1.0 - up * up) / up * spacing, agent.max_climb, agent.max_rise(spacing))

    sides = [sign * fraction * axis for axis in crack_sides(agent) for fraction in CRACK_STEPS for sign in (1.0, -1.0)]
    asked = np.zeros(nx_ * nz_, dtype=bool)
    known_line, known_y = column, points[:, 1]
    new_line, new_y, new_reach = column, points[:, 1], rise(faces)
    found_points, found_faces = [], []
    while len(new_line):
        # Lines next to a line with a floor they lack (nothing of theirs within reach of its height).
        i, j = np.divmod(new_line, nz_)
        near, near_y, near_reach = [], [], []
        for di, dj in ((1, 0), (-1, 0), (0, 1), (0, -1)):
            inside = (i + di >= 0) & (i + di < nx_) & (j + dj >= 0) & (j + dj < nz_)
            near.append(((i + di) * nz_ + j + dj)[inside])
            near_y.append(new_y[inside])
            near_reach.append(new_reach[inside])
        line, y = np.concatenate(near), np.concatenate(near_y)
        keep = ~asked[line] & ~_has_floor_near(known_line, known_y, line, y, np.concatenate(near_reach))
        ask = np.unique(line[keep])
        if len(ask) == 0:
            break
        asked[ask] = True
        # Each side line's crossings, by the asked line and side.
        crossings = [all_hits_down(caster, xz[ask] + side[[0, 2]], top) for side in sides]
        got_line, got_y, got_face = [], [], []
        for axis in range(2):
            parts = crossings[4 * axis:4 * axis + 4]  # +half, -half, +whole, -whole steps along this axis
            ahead = [np.concatenate([parts[0][k], parts[2][k]]) for k in range(3)]
            behind = [np.concatenate([parts[1][k], parts[3][k]]) for k in range(3)]
            other = _highest_near(behind[0], behind[1][:, 1], ahead[0], ahead[1][:, 1], GROUND_MARGIN)
            rows = np.flatnonzero(~np.isnan(other))  # floor on both sides, within the ground margin of each other
            higher = np.maximum(ahead[1][:, 1], other)  # the higher side's: the one a foot over the crack stands on
            got_line.append(ahead[0][rows])
            got_y.append(higher[rows])
            got_face.append(ahead[2][rows])
        line, y, face = ask[np.concatenate(got_line)], np.concatenate(got_y), np.concatenate(got_face)
        order = np.lexsort((-y, line))
        line, y, face = line[order], y[order], face[order]
        # One point a floor and line: none within the climb of a floor the line met, nor of the next higher point.
        fresh = ~_has_floor_near(known_line, known_y, line, y, agent.max_climb)
        fresh[1:] &= (line[1:] != line[:-1]) | (y[:-1] - y[1:] > agent.max_climb)
        line, y, face = line[fresh], y[fresh], face[fresh]
        found_points.append(np.column_stack([xz[line, 0], y, xz[line, 1]]))
        found_faces.append(face)
        known_line, known_y = np.concatenate([known_line, line]), np.concatenate([known_y, y])
        new_line, new_y, new_reach = line, y, rise(face)
    if not found_points:
        return np.zeros((0, 3)), np.zeros(0, dtype=np.int64)
    return np.concatenate(found_points), np.concatenate(found_faces).astype(np.int64)


def _highest_near(known_line: np.ndarray, known_y: np.ndarray, line: np.ndarray, y: np.ndarray,
                  tolerance: float | np.ndarray) -> np.ndarray:
    """(n,) metres: the highest of the heights ``known_y`` of line ``line[i]`` within ``tolerance`` (one, or (n,) one
    a line) of ``y[i]`` (NaN: none). O((k + n) log k)."""
    if len(known_line) == 0 or len(line) == 0:
        return np.full(len(line), np.nan)
    widest = float(np.max(tolerance))
    low = min(float(known_y.min()), float(y.min())) - widest
    scale = max(float(known_y.max()), float(y.max())) + widest - low + 1.0  # lines' key ranges do not overlap
    keys = np.sort(known_line * scale + (known_y - low))
    at = np.searchsorted(keys, line * scale + (y + tolerance - low), side="right") - 1
    value = keys[np.maximum(at, 0)]
    near = (at >= 0) & (value >= line * scale + (y - tolerance - low))
    return np.where(near, value - line * scale + low, np.nan)


def _has_floor_near(known_line: np.ndarray, known_y: np.ndarray, line: np.ndarray, y: np.ndarray,
                    tolerance: float | np.ndarray) -> np.ndarray:
    """(n,) bool: line ``line[i]`` has a height of ``known_y`` within ``tolerance`` of ``y[i]``."""
    return ~np.isnan(_highest_near(known_line, known_y, line, y, tolerance))


POISSON_BLOCKS = 16
"""Parts of the pick order :func:`poisson_disk_subset` throws at a time (see there)."""


def poisson_disk_subset(points: np.ndarray, radius: float, seed: int = 0) -> np.ndarray:
    """Indices (ascending) of a maximal Poisson-disk subset of ``points`` ((n, 3), metres).

    Dart throwing over the given points: they are visited in a random order
    fixed by ``seed``; a point is taken unless a taken point lies within
    ``radius`` (its squared distance, summed over x, y, z, at most the
    radius squared, as scipy's cKDTree tests a pair). No two taken points are
    that close and every point lies within ``radius`` of a taken one.

    The order is thrown in ``POISSON_BLOCKS`` parts: the points of a part
    that no point taken in an earlier part lies near (one nearest-neighbour
    query among those taken) are thrown among themselves
    (:func:`_throw_darts`). Each point gets the answer of throwing them all one
    by one, while the pair search meets only the few points still free in a
    part, not every pair (1.8 M points and 22 M pairs on a 276 000 m² level).
    """
    points = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    n = len(points)
    if n <= 1:
        return np.arange(n)
    taken = np.zeros(0, dtype=np.int64)
    for part in np.array_split(np.random.default_rng(seed).permutation(n), POISSON_BLOCKS):
        if len(taken):
            # the nearest taken point, looked for a little beyond the radius, then tested exactly
            _, nearest = spatial.cKDTree(points[taken]).query(points[part], distance_upper_bound=radius * (1.0 + 1e-6))
            found = nearest < len(taken)
            near = np.zeros(len(part), dtype=bool)
            near[found] = ((points[part[found]] - points[taken[nearest[found]]]) ** 2).sum(axis=1) <= radius * radius
            part = part[~near]
        if len(part):
            taken = np.concatenate([taken, part[_throw_darts(points[part], radius)]])
    return np.sort(taken)


def _throw_darts(points: np.ndarray, radius: float) -> np.ndarray:
    """Indices (in visiting order) of ``points`` taken when they are visited in their order and each is taken
    unless a taken one lies within ``radius``; neighbour lists from one scipy cKDTree query."""
    n = len(points)
    pairs = spatial.cKDTree(points).query_pairs(radius, output_type="ndarray").reshape(-1, 2)
    # int32 halves the two lists.
    heads = np.concatenate([pairs[:, 0], pairs[:, 1]], dtype=np.int32)
    tails = np.concatenate([pairs[:, 1], pairs[:, 0]], dtype=np.int32)
    del pairs
    # Grouped by head in a sparse matrix's rows (a counting sort: 3 x faster than
    # argsort on 10 M pairs); a row's order is irrelevant, only its set is used.
    rows = sparse.csr_array((np.ones(len(heads), dtype=np.int8), (heads, tails)), shape=(n, n))
    del heads, tails
    neighbours, start = rows.indices, rows.indptr
    free = np.ones(n, dtype=bool)
    taken: list[int] = []
    for i in range(n):
        if free[i]:
            taken.append(i)
            free[neighbours[start[i] : start[i + 1]]] = False
    return np.asarray(taken, dtype=np.int64)


def _joined_parts(count: int, edges: np.ndarray, areas: np.ndarray, min_area: float) -> np.ndarray:
    """(count,) the connected part of each sample along ``edges`` ((m, 2) ids), -1 for a part standing for less than
    ``min_area`` m² (``areas``: (count,) m²) in all."""
    links = sparse.coo_array((np.ones(len(edges), dtype=np.int8), (edges[:, 0], edges[:, 1])), shape=(count, count))
    parts, part = csgraph.connected_components(links, directed=False)
    return np.where(np.bincount(part, weights=areas, minlength=parts)[part] < min_area, -1, part)


def _small_regions(count: int, edges: np.ndarray, areas: np.ndarray, min_area: float) -> tuple[np.ndarray, int]:
    """``(small, parts)``: (count,) bool, the samples of connected parts standing for less than ``min_area``
    m² in all; and how many such parts there are (none if ``min_area`` is 0).

    ``edges``: (m, 2) sample ids. A part's area is summed in the order
    networkx's ``connected_components`` gives its nodes (breadth first from
    its lowest id, neighbours in id order) wherever another order could
    round it to the other side of ``min_area``, so the parts dropped are
    those a sum over the networkx graph would drop.
    """
    if min_area <= 0 or count == 0:
        return np.zeros(count, dtype=bool), 0
    links = sparse.coo_array((np.ones(len(edges), dtype=np.int8), (edges[:, 0], edges[:, 1])), shape=(count, count))
    parts, part = csgraph.connected_components(links, directed=False)
    totals = np.bincount(part, weights=areas, minlength=parts)
    # Two orders of summing k positive terms differ by less than k float epsilons of the total.
    close = np.abs(totals - min_area) <= 1e-15 * np.bincount(part, minlength=parts) * totals
    if np.any(close):
        nodes = np.nonzero(close[part])[0]
        subgraph = nx.Graph()
        subgraph.add_nodes_from(nodes.tolist())
        subgraph.add_edges_from(edges[close[part[edges[:, 0]]]].tolist())
        area_list = areas.tolist()
        for component in nx.connected_components(subgraph):
            totals[part[next(iter(component))]] = sum(area_list[n] for n in component)
    small = totals < min_area
    return small[part], int(np.count_nonzero(small))


# --- edges ------------------------------------------------------------------------------


def _walkable_pairs(
    caster: RayCaster,
    agent: AgentShape,
    samples: np.ndarray,
    floor: np.ndarray,
    pairs: np.ndarray,
    probe_step: float,
    half_width: float,
    shift: float = 0.0,
) -> np.ndarray:
    """(m,) bool: the agent walks straight between the two samples of each of ``pairs`` ((m, 2) ids), a disk
    of ``half_width`` (m) travelling along the way through no wall, and no steep face in the slab it sweeps from
    above the agent's step to its head (:func:`~g2s_plugins._raycasting.walks_in_batch` with ``body``); with
    ``shift`` (m), along the way moved that far sideways, horizontally at right angles to it (to the left of the
    walk from the first sample to the second; negative: to the right), and lengthened by ``half_width`` past both
    samples, so that the band also covers the disks at its ends: :func:`walks_in_batch` leaves the ends' disks to
    the caller, and the moved ends are not the samples the caller checked, nor does every added sample clear a
    thin post between its compass rays (in ``benchmarks/post_slots.py``'s 0.95 m slots turned 22 degrees one
    stands 0.35 m off the post, and a moved band ending there crossed the slot).

    Unmoved, a pair on one open floor triangle (``floor``: each sample's, from
    :meth:`~g2s_plugins._raycasting.OpenFloors.faces_under` with ``room`` at least ``half_width``; -1 for none)
    passes without a ray; the others get :func:`walks_in_batch`, a batch at a time.
    """
    keep = np.zeros(len(pairs), dtype=bool) if shift else (floor[pairs[:, 0]] >= 0) & (floor[pairs[:, 0]] == floor[pairs[:, 1]])
    tested = np.nonzero(~keep)[0]

    def walks(cast: RayCaster, rows: np.ndarray) -> None:
        starts, ends = samples[pairs[rows, 0]], samples[pairs[rows, 1]]
        if shift:
            along = ends - starts
            left = np.stack([-along[:, 2], np.zeros(len(rows)), along[:, 0]], axis=1)
            length = np.linalg.norm(left, axis=1, keepdims=True)
            left = np.divide(left, length, out=np.zeros_like(left), where=length > 0)  # a vertical pair: none
            longer = np.divide(half_width * along, length, out=np.zeros_like(along), where=length > 0)
            starts, ends = starts + shift * left - longer, ends + shift * left + longer
        keep[rows] = walks_in_batch(cast, starts, ends, agent, probe_step, half_width=half_width, body=True)[0]

    _each_batch(caster, walks, _in_batches(tested, MAX_EDGE_BATCH))
    return keep


def _walkable_pairs_of(
    caster: RayCaster,
    agent: AgentShape,
    floors: OpenFloors,
    offset: float,
    samples: np.ndarray,
    floor: np.ndarray,
    added: np.ndarray,
    pairs: np.ndarray,
    probe_step: float,
    clearance: float,
) -> np.ndarray:
    """(m,) bool: :func:`_walkable_pairs` for ``pairs`` ((m, 2) ids), a band of ``DISK_SHARE`` x ``clearance``
    (m) between two grid samples (``floor``: theirs, with that room) and of the whole ``clearance`` for a pair
    with an added sample (``added``: (n,) bool per sample), along the way or, where that fails, along it moved
    sideways by (1 - ``DISK_SHARE``) x ``clearance`` to the left, then to the right.

    An added sample stands where the agent fits with its whole width (:func:`moved_into_passages`), so a passage
    the agent fits is crossed square at the full width; the narrower band is there for grid samples accepted by
    the compass rays, and it let added samples cross slots narrower than the agent 1-4 degrees off square. A band
    as wide as the agent crosses no such slot wherever it is moved, while moved it passes a corner on one side of
    the way that only the narrower band cleared, as the grid samples' edges pass it: the band on the way alone
    refused 11 of the lecture hall's edges from added samples, each passing an end panel's corner 0.41-0.4999 m
    off (docs/sampling.md, "Passages a little wider than the agent", "A miss it brings"). Their open floor
    triangles are found here with the whole clearance as room. Two more walk tests at most for each pair the band
    on the way refuses.
    """
    wide = added[pairs].any(axis=1)
    keep = np.zeros(len(pairs), dtype=bool)
    keep[~wide] = _walkable_pairs(caster, agent, samples, floor, pairs[~wide], probe_step, DISK_SHARE * clearance)
    if wide.any():
        slack = (1.0 - DISK_SHARE) * clearance
        ends = np.unique(pairs[wide])
        wide_floor = np.full(len(samples), -1, dtype=np.int64)
        wide_floor[ends] = floors.faces_under(samples[ends], offset, room=clearance)
        rows = np.flatnonzero(wide)
        for shift in (0.0, slack, -slack):
            rows = rows[~keep[rows]]
            keep[rows] = _walkable_pairs(caster, agent, samples, wide_floor, pairs[rows], probe_step, clearance, shift)
    return keep


def _gap_pairs(samples: np.ndarray, edges: np.ndarray, connect: float, gap: float) -> np.ndarray:
    """(k, 2) sample ids, each row and the rows ascending: pairs farther apart than ``connect`` but at most ``gap`` (m) whose way along
    ``edges`` ((m, 2) ids) is missing or longer than ``GAP_STRETCH`` times their distance.

    In a passage only slightly wider than twice the clearance the candidates
    form a thin band, and the Poisson-disk pick can leave consecutive samples
    along it farther apart than ``connect_radius``: the passage is cut. On
    open ground a pair that far apart almost always has a common neighbour,
    a way at most 2 x ``connect`` long, so it is found here with one sparse
    product and no search; the few pairs left get a shortest-path search from
    each first sample (:func:`_bounded_ways`), bounded by ``GAP_STRETCH`` x
    ``gap``. The pairs returned still need the walk test.
    """
    count = len(samples)
    if gap <= connect or count < 2:
        return np.zeros((0, 2), dtype=np.int64)
    pairs = np.asarray(spatial.cKDTree(samples).query_pairs(gap, output_type="ndarray"), dtype=np.int64).reshape(-1, 2)
    pairs = np.sort(pairs, axis=1)
    distance = np.linalg.norm(samples[pairs[:, 1]] - samples[pairs[:, 0]], axis=1)
    far = distance > connect
    pairs, distance = pairs[far], distance[far]
    if len(pairs) == 0:
        return pairs
    lengths = np.linalg.norm(samples[edges[:, 1]] - samples[edges[:, 0]], axis=1)
    links = sparse.csr_array((lengths, (edges[:, 0], edges[:, 1])), shape=(count, count))
    links = links + links.T
    # A common neighbour is a way of at most 2 x connect < 2 x distance <= GAP_STRETCH x distance.
    adjacent = (links > 0).astype(np.int32)
    shared = (adjacent @ adjacent)[pairs[:, 0], pairs[:, 1]] > 0
    pairs, distance = pairs[~shared], distance[~shared]
    if len(pairs) == 0:
        return pairs
    way = _bounded_ways(samples, links, pairs, GAP_STRETCH * gap)
    pairs = pairs[way > GAP_STRETCH * distance]
    return pairs[np.lexsort((pairs[:, 1], pairs[:, 0]))]


def _bounded_ways(samples: np.ndarray, links: sparse.csr_array, pairs: np.ndarray, limit: float) -> np.ndarray:
    """(k,) the shortest way along ``links`` (symmetric, weights in m) between the samples of each of ``pairs``
    ((k, 2) ids at most ``limit`` apart), or inf where it is longer than ``limit`` (m).

    A way no longer than ``limit`` stays within ``limit`` of its start, so the
    search from the sources in one XZ tile (side 4 x ``limit``) needs only the
    samples of that tile and the eight around it: scipy's Dijkstra on that
    part of the graph, its table (sources x part) small, its cost growing
    with the level's area, not its square. ``links`` is put in the order of
    the tiles' keys once, so that a part is three runs of consecutive rows
    (:func:`_runs_graph`). Numbered so, a part gives each way the same bits:
    with positive weights, Dijkstra's distance to a sample is the least of its
    neighbours' distances plus their edges, in whatever order it settles them.
    """
    side = 4.0 * limit
    tile = np.floor(samples[:, [0, 2]] / side).astype(np.int64)
    tile -= tile.min(axis=0)
    width = int(tile[:, 1].max()) + 3
    key = (tile[:, 0] + 1) * width + tile[:, 1] + 1  # a margin of one tile all round keeps the 3 x 3 keys apart
    order = np.argsort(key, kind="stable")
    starts = np.searchsorted(key[order], np.arange((int(tile[:, 0].max()) + 3) * width + 1))
    position = np.empty(len(samples), dtype=np.int64)
    position[order] = np.arange(len(samples))
    ordered = links[order][:, order]
    way = np.full(len(pairs), np.inf)
    by_home = np.argsort(key[pairs[:, 0]], kind="stable")
    homes, first = np.unique(key[pairs[by_home, 0]], return_index=True)
    for home, mine in zip(homes.tolist(), np.split(by_home, first[1:])):
        # the tiles home + dx width - 1 .. home + dx width + 1 for dx = -1, 0, 1: three runs of consecutive rows
        runs = starts[np.add.outer(home + width * np.arange(-1, 2), [-1, 2])]
        part, local = _runs_graph(ordered, runs)
        sources, row = np.unique(local(position[pairs[mine, 0]]), return_inverse=True)
        # directed (scipy's default): ``links`` holds each edge both ways already, and an undirected search would
        # make the transpose of every part for the same ways (a third of this function's time on the 100k level)
        table = csgraph.dijkstra(part, indices=sources, limit=limit)
        way[mine] = table[row, local(position[pairs[mine, 1]])]
    return way


def _runs_graph(graph: sparse.csr_array, runs: np.ndarray) -> tuple[sparse.csr_array, Callable[[np.ndarray], np.ndarray]]:
    """``(part, local)``: the rows and columns of ``graph`` (a square CSR array) in ``runs`` ((r, 2) ``[begin,
    end)`` ranges of rows, ascending and apart), numbered from 0 in that order; and the map from ``graph``'s row
    numbers in the runs ((k,) int) to ``part``'s. O(the runs' rows and entries), where scipy's indexing by columns
    makes a table of all of ``graph``'s columns each time."""
    begin, end = runs[:, 0], runs[:, 1]
    offset = np.cumsum(end - begin) - (end - begin)

    def local(rows: np.ndarray) -> np.ndarray:
        run = np.searchsorted(begin, rows, side="right") - 1
        return rows - begin[run] + offset[run]

    pointers = graph.indptr
    entries = np.concatenate([np.arange(pointers[a], pointers[b]) for a, b in runs.tolist()])  # the runs' rows' entries
    row_ends = np.cumsum(np.concatenate([np.diff(pointers[a : b + 1]) for a, b in runs.tolist()]))  # in ``entries``
    columns = graph.indices[entries]
    run = np.searchsorted(begin, columns, side="right") - 1
    inside = (run >= 0) & (columns < end[np.maximum(run, 0)])
    kept_before = np.concatenate([[0], np.cumsum(inside)])  # the entries kept before each of ``entries``
    count = int(offset[-1] + end[-1] - begin[-1])
    part = sparse.csr_array(
        (graph.data[entries[inside]], (columns - begin[run] + offset[run])[inside], kept_before[np.concatenate([[0], row_ends])]),
        shape=(count, count),
    )
    return part, local


# --- the hook ---------------------------------------------------------------------------


def build_sampled_graph(
    mesh: trimesh.Trimesh, params: Params, agent: AgentShape, timings: dict[str, float] | None = None
) -> nx.Graph:
    """The sampled surface graph of ``mesh`` (see the module docstring).

    ``timings``, when given, receives the seconds each step took (kept out of
    the graph so that its JSON output stays the same from run to run).
    """
    spacing, connect, clearance, probe_step, gap = _resolve(params, agent)
    agent = replace(agent, step_gap=agent.max_climb if params.step_gap is None else params.step_gap,
                    body_walls=params.body_walls)
    timings = timings if timings is not None else {}
    clock = time.perf_counter()

    def lap(name: str) -> None:
        nonlocal clock
        now = time.perf_counter()
        timings[name] = round(now - clock, 6)
        clock = now

    caster = RayCaster(mesh)
    # The open floors need the mesh alone: found on a second thread while the candidates are made and checked.
    aside = ThreadPoolExecutor(1)
    open_floors = aside.submit(OpenFloors, caster, agent, min_inradius=0.5 * spacing)
    aside.shutdown(wait=False)  # its one thread ends with that task
    surface = walkable_surface(mesh, agent)
    lap("surface")
    stats: dict[str, object] = {
        "method": params.method,
        "spacing": spacing,
        "connect_radius": connect,
        "gap_radius": gap,
        "clearance": clearance,
        "ray_backend": caster.backend,
        "surface_faces": int(len(surface.faces)),
        "surface_area": float(surface.area) if len(surface.faces) else 0.0,
    }
    graph = nx.Graph()
    graph.graph["sampling_stats"] = stats
    if len(surface.faces) == 0:
        stats.update(candidates=0, samples=0)
        return graph

    if params.method == "poisson":
        candidates, faces, candidate_area = _poisson_candidates(surface, spacing, params)
    else:
        candidates, faces = _grid_candidates(surface, spacing, agent if params.crack_lines else None)
        candidate_area = 0.0
    lap("candidates")
    rejected = np.zeros(len(candidates), dtype=np.int8)
    fits = agent_fits(caster, candidates, agent, clearance, surface, faces, rejected)
    lap("agent_checks")
    # Before the Poisson-disk pick, not after: a candidate inside a solid could
    # otherwise block one outside it or add to a sample's area.
    solid = inside_closed_solids(caster, candidates[fits], agent)
    fits[fits] = ~solid
    lap("solids")
    stats["candidates"] = int(len(candidates))
    stats["candidates_inside_solids"] = int(solid.sum())
    stats["candidates_fit"] = int(fits.sum())
    kept, kept_faces = candidates[fits], faces[fits]
    normals = np.asarray(surface.face_normals)[kept_faces]
    if params.method == "poisson":
        chosen = poisson_disk_subset(kept, spacing, params.seed)
        samples, sample_normals = kept[chosen], normals[chosen]
        owner = spatial.cKDTree(samples).query(kept)[1] if len(samples) else np.zeros(0, dtype=np.int64)
        areas = np.bincount(owner, minlength=len(samples)) * candidate_area
    else:
        samples, sample_normals = kept, normals
        owner = np.arange(len(kept))
        areas = spacing**2 / np.maximum(sample_normals[:, 1], 1e-6)
    lap("samples")

    # Deterministic node order: by x, then z, then y.
    order = np.lexsort((samples[:, 1], samples[:, 2], samples[:, 0]))
    samples, sample_normals, areas = samples[order], sample_normals[order], areas[order]
    owner = np.argsort(order)[owner]  # each candidate that fits: its sample's id

    pairs = spatial.cKDTree(samples).query_pairs(connect, output_type="ndarray") if len(samples) > 1 else np.zeros((0, 2), int)
    pairs = np.sort(np.asarray(pairs, dtype=np.int64).reshape(-1, 2), axis=1)
    pairs = pairs[np.lexsort((pairs[:, 1], pairs[:, 0]))]
    floors = open_floors.result()
    half_width = DISK_SHARE * clearance
    offset = floors.certain_offset(GROUND_MARGIN, None)
    floor = floors.faces_under(samples, offset, room=half_width)
    edges = pairs[_walkable_pairs(caster, agent, samples, floor, pairs, probe_step, half_width)]
    candidate_edges = len(pairs)
    lap("edges")

    min_area = params.min_region_area if params.min_region_area is not None else 16.0 * agent.radius**2
    part = _joined_parts(len(samples), edges, areas, min_area)[owner]
    added, added_faces, stranded = moved_into_passages(caster, agent, clearance, spacing, candidates, fits, rejected, part)
    stats["candidates_stranded"] = int(len(stranded))
    stats["samples_added"] = int(len(added))
    is_added = np.zeros(len(samples), dtype=bool)
    if len(added):
        # The added samples' edges (pairs with one of them at least), then the node order again.
        count = len(samples)
        samples = np.concatenate([samples, added])
        sample_normals = np.concatenate([sample_normals, caster.face_normals[added_faces]])
        areas = np.concatenate([areas, np.zeros(len(added))])  # the candidates they come from stand where the agent does not
        floor = np.concatenate([floor, np.full(len(added), -1, dtype=np.int64)])  # their pairs find theirs wider
        is_added = np.arange(len(samples)) >= count
        pairs = np.sort(np.asarray(spatial.cKDTree(samples).query_pairs(connect, output_type="ndarray"), dtype=np.int64).reshape(-1, 2), axis=1)
        pairs = pairs[pairs[:, 1] >= count]
        edges = np.concatenate([edges, pairs[_walkable_pairs_of(
            caster, agent, floors, offset, samples, floor, is_added, pairs, probe_step, clearance,
        )]])
        candidate_edges += len(pairs)
        order = np.lexsort((samples[:, 1], samples[:, 2], samples[:, 0]))
        samples, sample_normals, areas, floor = samples[order], sample_normals[order], areas[order], floor[order]
        is_added = is_added[order]
        edges = np.sort(np.argsort(order)[edges], axis=1)
        edges = edges[np.lexsort((edges[:, 1], edges[:, 0]))]
    sample_normals = sample_normals / np.linalg.norm(sample_normals, axis=1, keepdims=True)
    lap("passages")
    gaps = _gap_pairs(samples, edges, connect, gap)
    gaps = gaps[_walkable_pairs_of(caster, agent, floors, offset, samples, floor, is_added, gaps, probe_step, clearance)]
    if len(gaps):
        edges = np.concatenate([edges, gaps])
        edges = edges[np.lexsort((edges[:, 1], edges[:, 0]))]
    lap("gaps")
    # the rays are done: what their batches left free in the C heaps goes back before the graph's objects are made
    hand_back_free_memory()
    stats["candidate_edges"] = int(candidate_edges)
    stats["gap_edges"] = int(len(gaps))

    lengths = np.linalg.norm(samples[edges[:, 1]] - samples[edges[:, 0]], axis=1)
    weights = lengths + params.slope_penalty * np.abs(samples[edges[:, 1], 1] - samples[edges[:, 0], 1])
    small, dropped = _small_regions(len(samples), edges, areas, min_area)
    if dropped:
        # Ids stay in order (0..k-1 among the kept samples), edges in their sorted order.
        new_id = np.cumsum(~small) - 1
        kept_edge = ~small[edges[:, 0]]
        samples, sample_normals, areas = samples[~small], sample_normals[~small], areas[~small]
        edges, weights = new_id[edges[kept_edge]], weights[kept_edge]
    # each node's position and normal as a tuple, zipped from the columns: of the 680,329 nodes' graph, 1.9 s of
    # CPU against 2.9 s with a tuple made from each row (docs/performance.md, 6 December 2026, samp1_47)
    pos, nrm = list(zip(*samples.T.tolist())), list(zip(*sample_normals.T.tolist()))
    area_list = areas.astype(np.float64).tolist()
    # one int object per node, which its neighbours' dicts hold as their key for it too (an object per edge end
    # made by tolist was 2 x 2,790,938 x 32 bytes, 0.17 GiB, on the 100k level)
    ids = list(range(len(samples)))
    ends = (map(ids.__getitem__, column) for column in edges.T.tolist())
    # the graph add_nodes_from and add_edges_from make (the edges are unique), written straight into its dicts
    graph_of(
        graph,
        {i: {"pos": p, "normal": v, "area": a, "on_navmesh": True, "polygon": -1}
         for i, p, v, a in zip(ids, pos, nrm, area_list)},
        zip(*ends, [{"weight": w} for w in weights.tolist()]),
    )
    lap("graph")
    stats.update(
        samples=int(len(small)),
        nodes=graph.number_of_nodes(),
        edges=int(len(edges)),
        regions_dropped=dropped,
        rays=caster.rays_cast,
    )
    graph.graph["sampling_stats"] = stats
    return graph


@hookimpl
def g2s_build_graph(mesh: trimesh.Trimesh, params: Params, context: RunContext) -> nx.Graph:
    """Sample the walkable surface of ``mesh`` for ``context.agent`` and join the samples the agent can walk between;
    cut to the play space when ``params.play_points`` names one (:func:`g2s_plugins.play_space.cut_to_play_space`).

    Raises:
        G2SError: no place on the mesh where this agent fits (a property of the
            input and the settings, not a failure of the program).
    """
    check_units(mesh, context)  # before the build, which a level in centimetres makes long
    graph = build_sampled_graph(mesh, params, AgentShape.from_config(context.agent))
    if graph.number_of_nodes() == 0:
        raise no_walkable_surface(mesh, context.agent, "no sample where it fits")
    check_walkable_surface(graph, mesh, context)
    context.likely_cause = area_gaps.likely_cause_of(context.agent, clearance=graph.graph["sampling_stats"]["clearance"], mesh=mesh)
    return cut_to_play_space(graph, params.play_points, context)
