"""Entry/exit points: the openings where a map piece meets its neighbours.

Follows the entry/exit method the paper uses for map pieces (section
"Entry/exit points"): the navmesh boundary is sampled, each sample is tested
for a way out, the samples are grown into segments, and each segment is
matched to the edge of the source geometry it stands for. Every opening
becomes a terminal node, with a confidence score and the reason it was kept.

Steps (``r`` = agent radius, ``h`` = ``sample_height``):

1. Boundary loops: navmesh polygon edges with no neighbour, chained into
   loops with the walkable side on the left (see :mod:`._boundary`).
2. Sampling: a sample every ``sample_step`` along each loop, snapped onto the
   source mesh by a short ray along the polygon normal (down first, then up);
   the hit triangle's normal is kept.
3. Ways out: from each sample, lifted ``h`` above the surface, a fan of
   ``fan_count`` directions in the surface plane, up to ``fan_half_angle_deg``
   either side of straight out. Along each, rays cast down find where the
   surface ends (the floor's edge, looked for up to ``edge_search_radii * r``
   away: Recast erodes the walkable area by ``r``, so the navmesh boundary
   lies about ``r`` inside the real edge; it ends where three rays in a row meet
   no walkable face, so a gap between floor tiles or planks narrower than two
   search steps is no edge, nor a gap across the way narrower than ``step_gap``
   (the climb) whose far side faces the near one with ground within the climb
   going on beyond it, which the agent steps over (its probes add to the reach); a ray meets
   the surface within the climb of the ground the one before it stood on, so
   the search walks down a stair; on a sampled surface, whose boundary stands
   farther inside the floor, a sample finding no way out looks again up to
   the sampling builder's clearance plus 1.5 spacings, :func:`sampled_edge_search`,
   from probes cast once as far as that for both looks). A direction
   is a way out when the edge is found, the ray along it stays clear for
   ``outward_radii * r`` (no wall, jamb or curb higher than ``h`` in the
   way), the same way a search step below the agent's height is clear up to
   the edge (head room: no lintel lower than the agent), the same way at every half search
   step of height from the climb up to that is clear one agent radius past
   the edge (no rail of a railing between its posts) and, with
   ``leave_footprint``, one agent radius beyond the edge nothing of the piece
   lies straight below, nor above lower than the head-room ray (a ledge over
   a lower floor of the piece, a canopy too low to stand under or a hole
   under its ramp is no exit; eaves are no obstacle), nor, square to the
   edge within the search's reach past the floor's side face, the piece's
   floor within the climb of the ground at the end (a slot wider than the
   step gap is no exit: ``_floor_beyond``). A sample with a
   way out takes the one reaching the edge soonest. The fan, rather than one
   ray straight out, finds the way out of Recast's V-shaped notch in a
   doorway through a thick wall, whose slanted sides face the jambs. With
   ``step_up``, a sample with no way out whose ray straight out meets a step
   within the climb (a threshold, a curb) looks again from the step's top;
   such an opening is kept only between jambs (step 6).
4. Segments: runs of consecutive samples with a way out, split where the way
   out turns by more than ``max_turn_deg``.
5. Matching to the geometry (the paper's "corresponding segment in the
   original geometry"): the edge points of a segment must fit one straight
   line within ``edge_tolerance_radii * r`` (80 % of them) or follow the
   boundary's direction within ``match_angle_deg`` (a curved edge); a
   segment that fits neither is fitted again without the samples at its ends
   whose way out lies more than ``max_turn_deg`` from its median one (a
   segment that walked round a corner onto the edge); a line over one surface
   fitted steeper than the agent walks runs through edge points on several
   treads, and is taken level in plan. An edge runs the way its boundary
   walks. An edge is cut where
   something stands on it between two free stretches (a pier between two
   doorways the samples saw out through alike; not where a way out from the
   floor ends within it, as over a strip within the climb running out
   through the edge), and its ends are raised onto
   a step top just inside them (a riser as high as the rays, which they pass
   over), or, where its samples walked down steps to it, lowered onto the
   floor that ends there (as far down as the lowest floor its ways walked
   down to). The
   opening lies on that line; its ends are extended along the edge while the
   surface goes on inside the edge, ends just outside it, and nothing stands
   in the way or straight out: this undoes the retreat from walls. The line
   is then laid on the floor ending along it (the least-squares line through
   the ground's heights probed along it): samples on treads within the climb
   of that floor leave their edge points at their own heights. An
   opening overlapping a wider one along the same line, facing the same way,
   is the same opening found twice (its middle within ``r`` of the wider one's line in plan, an end or its
   middle within the climb of the line's height there, read in plan and height on a sloped line too): the wider
   one is stretched along its line
   to span both and the other dropped, again until none overlaps a wider one.
   Two parts turned apart by more than ``max_turn_deg`` but less than square,
   meeting end to end with nothing between them, are one opening between their
   far ends when the way's sides run in square to the chord there (a corridor's
   floor cut in a V past its walls' ends) and the outer-extent prior keeps it.
6. Priors, each measured on the generated pieces of
   :mod:`g2s_plugins.samples.pieces` (docs/entry_exit.md):

   * width: openings no wider than ``min_width_radii * r`` (default the
     agent's diameter) are dropped (chamfers, slivers, a door exactly as
     wide as the agent, which Recast erodes away), and so are openings whose
     clear width across, between their edge and the navmesh, is no wider
     (bars across a doorway; measured from the step top within the climb
     there, not from inside a strip running out through the opening); an opening is the narrowest free part of that
     passage above the climb and at the head-room rays' height (a sliding
     leaf or a rubble chunk in the wall, or a sign hanging or a vault coming
     down lower than the agent, leaves part of the door), the passage read
     through the wall, past the samples up to the edge search's reach, to
     where its sides open out (a reveal splaying out to the face is as wide
     as its inner face);
   * jambs (``step_up``): an opening found from step tops needs something
     at half the agent's height within two search steps of both its ends
     (a threshold's jambs); a curb along the piece's edge has none;
   * reachability (``main_floor_only``): the opening must run along the
     navmesh floor of largest area, the main floor and what the agent
     reaches from it (an unreachable wall top, a roof, holds no exit); a
     floor is a navmesh component with those whose boundary comes within
     ``r`` at the same height (Recast's grid cuts narrow passages at some yaws),
     and a floor over others (a closed ceiling's top) is a roof, never the main one;
     other floors leaving the piece at the main floor's level (within the climb)
     that are no roof, or rise a storey from there, hold openings with it (a
     corridor cut in two by a barrier, a flight carried over the hall and cut
     from it at its foot), and so do
     the storeys (an agent's height or more from it) leaving the piece that
     walls or railings close along most of their boundary (a deck over a
     corridor), and the floors the agent walks down to off their ledges, less
     than a storey down (a corridor's far half beyond a 0.6 m drop); of floors
     of comparable area, the main one is that from which the agent reaches the
     most, walking down;
   * outer extent (``extent_heights``): modular pieces meet their neighbours
     at their outer extent, facing out. The opening's gap to the piece's
     extent along its heading (the largest ``vertex . heading`` over the faces
     reaching down to the agent's height over the opening, minus the
     midpoint's: eaves and upper storeys overhanging it do not count; a heading near one of the piece's own horizontal
     axes, taken from its walls, is measured along that axis) must not exceed
     ``extent_heights`` agent heights; an opening between jambs (as for
     ``step_up``) measures it over the triangles straight ahead of it alone
     (whose span along the opening overlaps its own), so a room standing out
     beside a corridor's side mouth does not drop it.

   The score is the product of three factors in [0, 1]: the share of edge
   points on the fitted line, ``1 - gap / (extent_heights * height)``, and
   ``min(1, width / (2 * minimum width))``. ``min_score`` and ``best`` keep
   only the openings above a score or the best N.
7. Terminals: each opening gives an :class:`~g2s_core.model.Opening`
   (midpoint at floor height, horizontal outward heading, width, end points
   ``p0`` on the left and ``p1`` on the right looking out, ``score``,
   ``reason``) and a new graph node at its midpoint (ids after the largest
   id, in opening order; ``pos``, ``normal``, ``area`` 0, ``on_navmesh`` by
   :func:`g2s_plugins._surface.on_navmesh`, ``polygon`` -1), joined by one
   edge (so it stays a leaf of any tree) to the nearest node among the
   navmesh polygons the segment runs along (to the nearest node when the
   graph has no polygon nodes), with ``weight`` = Euclidean distance.

A window or any hole above the floor is not an exit: the rays at ``h`` (half
the step the agent climbs) hit the wall under it; nor is a floor's edge
behind a curb higher than ``h``. A closed piece has no openings: the
selector returns no terminals and the pipeline stops with a warning. Every
batch of rays (one per step and bisection round) is one call of the shared
:class:`g2s_plugins._raycasting.RayCaster`, never one call per ray.

Runs on the surface the graph covers: the polygons of the navigation mesh
the ``navmesh`` graph builder leaves in ``context.navmesh`` that the graph
holds (:func:`held_navmesh`: every one, or those of the play space when the
builder was given ``play_points``); without a navmesh, the ``sampling``
builder's graph's own faces (:mod:`._sampled_surface`), which stand for the
navmesh polygons (normals, the main floor, the nodes an opening is joined
to). Every step and rule is the same on both. The rays, the outer extent
and ``leave_footprint`` read the whole mesh (``context.mesh``), or, when the
builder was given ``play_points``, the piece the play space stands on
(:func:`play_space_piece`: its parts and those touching them), so a backdrop
or a skybox apart from it hides none of its openings.

Cost, for a navmesh of V vertices and B boundary edges, S samples (the
boundary's length / ``sample_step``), k = ``fan_count`` and o openings:
O(V log V + B log B) to chain the loops; rays, in batches: up to three to snap
each sample, and per sample and fan direction one outward ray, at most
``(edge_search_radii * r + step_gap) / d`` downward probes (d = min(``sample_step``,
r) / 4), up to 5 rays more for a probe over a gap, and 4 bisection rays to find the surface's end, (agent height -
climb) / d across the way for the directions clear so far, two more beyond it
with ``leave_footprint``: O(S k (edge_search_radii r + agent height) / d) rays (up to twice
that with ``step_up``, for the samples searched again from a step's top; on a sampled surface the probes reach
the second look's distance instead, and the tests after them are cast again for the samples it answers).
The main floor adds a k-d tree over boundary samples r / 4 apart, each opening's passage up to
max(its samples' depth, ``edge_search_radii * r``) / d steps of a few rays each (and a floor laid along it, its
length / d rays), the repeated openings an O(o^2) comparison, the openings between jambs O(F) each
over the mesh's F triangles, the terminals a k-d tree query each.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np
from pydantic import Field

from g2s_core.config import AgentConfig
from g2s_core.errors import PluginError
from g2s_core.lazy import lazy_module
from g2s_core.model import NavMesh, Opening, RunContext, Terminals
from g2s_core.plugin import PluginParams, hookimpl
from g2s_plugins._raycasting import UP, RayCaster, ground_across_crack
from g2s_plugins._surface import on_navmesh
from g2s_plugins.play_space import PLAY_POINTS, held_polygons, play_space_faces
from g2s_plugins.terminals._boundary import BoundaryLoop, LoopSamples, boundary_loops, polygon_components, sample_loops
from g2s_plugins.terminals._sampled_surface import SampledSurface, sampled_surface
from g2s_plugins.vectors import vec3

trimesh, spatial = lazy_module("trimesh"), lazy_module("scipy.spatial")
nx = lazy_module("networkx")

NAME = "entry_exit"

_REFINE_ROUNDS = 4
"""Bisection rounds that place a found edge to 1/16 of the search step."""

_SAME_WIDTH = 1e-4
"""Metres: widths this close are equal (an opening between jambs measures their distance to the ray
caster's single precision: a 0.8 m door 0.8000011 m)."""

_SAME_HEIGHT = 1e-4
"""Metres: heights this close are equal. Recast's polygon corners lie on whole cells in single precision (0.45000005 m
for 0.45): a flight's floor whose lowest corner lies exactly the climb above the main floor's (two 0.2 m risers)
measured 0.40000005 m, and its landing's door was missed (docs/entry_exit.md, "A fourteenth round of piece kinds")."""

_INSET_STEPS = 0.5
"""Search steps: how far inside the edge line the extension's candidates stand. Past an open corner the
floor goes on under them for about this far again (a chamfer's 135-degree corner), so the measured width
grows by twice it: 0.5 steps (0.025 m for the map-piece agent) is 8 times the found edge's precision
(:data:`_REFINE_ROUNDS`); at 2 steps the 0.64 m chamfers of ``chamfered_platform`` measured 0.88 m,
wider than the agent (docs/entry_exit.md)."""

_END_REACH_STEPS = 2.0
"""Search steps: how far past a found edge point :func:`_onto_floor_end` looks for the floor going on (0.1 m for
the map-piece agent, over twice the largest shortfall measured, 0.04 m)."""

_SNAP_SLACK = 0.01
"""Metres added to the snap's downward reach (2 x ``snap_distance``): Recast lifts a navmesh corner to the
highest span around it, up to the climb above the floor, and single precision and a polygon tilted
towards that corner then put the floor a fraction of a millimetre beyond the reach (0.80017 m for 0.8 m:
``curb_platform curb=0.35`` turned by 30 to 60 degrees); the smallest cell height allowed."""

_TOUCH_RADII = 2.0
"""Agent radii: with play points, parts of the mesh closer than this touch, one piece (:func:`play_space_piece`): a
gap the agent cannot pass through (its diameter, 0.8 m for the map-piece agent) parts nothing it walks, so parts the
method reads as one floor (unwelded tiles or planks a crack apart) stay one piece, and so does a canopy on posts
ending in the air 0.4 m off a wall, which the whole mesh reads as closing its doorway. At two search steps (0.1 m,
until 6 December 2026) that canopy was dropped and its doorway found; the backdrops measured stand 1.7 m or more off
the piece (docs/entry_exit.md, "An opening's width and height as a designer reads them")."""

_SIDES_OPEN_STEPS = 1.0
"""Search steps: a passage read past its samples ends where its free width grows by more than this (its sides open
out into the room behind the wall, metres at once; a reveal splaying inwards by 45 degrees a side grows two steps
a step, one splaying less reads no narrower for going on). Rays along a straight jamb agree to the ray caster's
precision."""

_SET_BACK_COS = math.cos(math.radians(45.0))
"""A face met just inside an edge stands across the way out when it turns back out across the edge within 45
degrees: a post's face, parallel to the edge, at 0; a side wall meeting a corridor's end cut 30 degrees off square
(round 27's skewed corridor) at 60, left to the extension's ray along the edge as before (the split at piers counts
any face: one at an edge's end only ends it, as a jamb)."""

_STEP_DIGITS = 9
"""Decimal places to which a reach in search steps is rounded before it is counted up to whole steps: far finer
than a step, coarser than floating point's error on a product of two parameters."""

_MAX_PROBE_RAYS = 1_000_000
"""Probe rays cast per batch when looking for the surface's end (a level's whole boundary at once, samples x fan
directions x search steps, held 1.9 GB on a 274 x 226 m level)."""


class Params(PluginParams):
    """Boundary sampling, ways out, segment rules and priors; lengths in metres unless noted.

    Defaults follow the agent: samples every half agent radius, rays at half
    the highest step it climbs, openings at least as wide as the agent.
    """

    sample_step: float | None = Field(
        None, gt=0, description="spacing of the boundary samples, m; None: half the agent radius"
    )
    sample_height: float | None = Field(
        None,
        gt=0,
        description="height of the rays above the surface, m: a curb or sill higher than this closes the way "
        "(but a step within the climb between jambs, see step_up); "
        "None: half the agent's max climb, at least 0.1",
    )
    snap_distance: float | None = Field(
        None,
        gt=0,
        le=1e6,  # a longer ray meets nothing a level holds, and 1e308 overflowed the rays' ends to inf
        description="longest ray that snaps a sample onto the mesh, m (at most 1,000 km); None: the agent's max "
        "climb, at least 0.1",
    )
    fan_count: int = Field(9, ge=1, le=64, description="directions tried from each sample for a way out")
    fan_half_angle_deg: float = Field(
        80.0, ge=0, lt=90, description="the fan spans this much either side of straight out, degrees"
    )
    max_turn_deg: float = Field(
        30.0, ge=0, le=180, description="a segment ends where the way out turns by more than this, degrees"
    )
    outward_radii: float = Field(
        4.0, ge=0, description="the way out must be clear this far from the sample, agent radii"
    )
    min_width_radii: float = Field(
        2.0,
        ge=0,
        description="openings no wider are dropped, agent radii (default: the agent's diameter; one exactly as wide "
        "as the agent is no way through)",
    )
    max_slope_deg: float | None = Field(
        None, ge=0, le=90, description="drop openings steeper than this from the horizontal, degrees; None: keep all"
    )
    edge_search_radii: float = Field(
        3.0,
        gt=0,
        description="how far beyond the navmesh boundary the surface's edge is looked for, agent radii "
        "(Recast's erosion, plus the wall's thickness where it closes a doorway barely wider than the agent: "
        "up to 1.2 m for walls 0.8 m thick); on a sampled surface a sample finding nothing within it looks again "
        "up to the sampling builder's clearance plus 1.5 spacings",
    )
    edge_tolerance_radii: float = Field(
        0.25,
        gt=0,
        description="the edge points of a segment must lie this close to one straight line, agent radii",
    )
    match_angle_deg: float = Field(
        30.0,
        ge=0,
        le=90,
        description="a curved edge matches a segment when its local direction stays this close to the "
        "boundary's, degrees",
    )
    step_gap: float | None = Field(
        None,
        ge=0,
        le=100,
        description="the floor's end search steps over a gap across the way narrower than this, m, whose far side "
        "faces its near one and holds walkable ground within the climb going on beyond it (a gutter or a slot just "
        "inside a doorway); None: the agent's max climb, the sampling builder's default step gap; 0: gaps narrower "
        "than two search steps alone",
    )
    leave_footprint: bool = Field(
        True,
        description="an exit must lead out of the piece: one agent radius beyond its edge nothing of the "
        "piece lies straight below, nor above lower than a search step under the agent's height, nor, square to "
        "the edge within edge_search_radii * r past the floor's side face, the piece's floor at the ground's "
        "height (false: keep ledges, holes and slots inside the piece and exits under low canopies)",
    )
    step_up: bool = Field(
        True,
        description="where a step higher than the rays but within the climb closes the way out, look again from "
        "its top; such an opening is kept only between jambs (something at half the agent's height at both "
        "ends): a doorway over a threshold, not a curb",
    )
    main_floor_only: bool = Field(
        True,
        description="keep only openings on the navmesh floor of largest area (a component with those whose "
        "boundary comes within one agent radius at the same height: the main floor and what is reachable from it) "
        "and the floors at its level that leave the piece too, and the storeys leaving it that walls or railings "
        "close along most of their boundary; false: every component's",
    )
    extent_heights: float | None = Field(
        0.5,
        gt=0,
        description="an opening lies at most this many agent heights inside the piece's outer extent along "
        "its heading; None: anywhere",
    )
    min_score: float = Field(0.0, ge=0, le=1, description="drop openings scoring below this")
    best: int | None = Field(None, ge=1, description="keep only the best N openings by score; None: all")


SAMPLED_SEARCH_SPACINGS = 1.5
"""Sample spacings: on a sampled surface a sample finding no way out within ``edge_search_radii * r`` looks again up
to the builder's clearance plus this many spacings (:func:`sampled_edge_search`). The surface's boundary runs between samples, which a Poisson-disk pick over
candidates leaves up to about a spacing inside the eroded floor, and farther where no candidate fell near its
edge: over the 564 known openings of the generated families and the tenth to fifteenth rounds' kinds at 0, 22
and 45 degrees, the boundary stood at most the clearance plus 1.46 spacings (1.56 m) from the floor's end
(docs/entry_exit.md, "A sixteenth round of piece kinds")."""


def sampled_edge_search(spacing: float, clearance: float) -> float:
    """How far beyond a sampled surface's boundary a sample finding no way out looks again for the floor's end, m: the
    builder's ``clearance`` plus :data:`SAMPLED_SEARCH_SPACINGS` sample ``spacing`` (m)."""
    return clearance + SAMPLED_SEARCH_SPACINGS * spacing


@dataclass(frozen=True)
class _Settings:
    radius: float
    height: float
    climb: float
    step: float
    lift: float
    snap: float
    delta: float
    walkable_cos: float  # cosine of the agent's steepest walkable slope
    walkable_tan: float  # its tangent
    head: float  # height of the head-room rays over the surface: a search step under the agent's height
    search: float  # how far beyond the boundary the edge search looks for the surface's end
    farther: float  # how far it looks again from a sample that found no way out (a sampled surface's), else 0
    step_gap: float  # the floor's end search steps over a gap across the way narrower than this, m (0: none)


def _settings(params: Params, agent: AgentConfig, farther: float | None = None) -> _Settings:
    r = float(agent.radius)
    climb = float(agent.max_climb)
    step = float(params.sample_step) if params.sample_step is not None else r / 2.0
    lift = float(params.sample_height) if params.sample_height is not None else max(0.5 * climb, 0.1)
    snap = float(params.snap_distance) if params.snap_distance is not None else max(climb, 0.1)
    delta = min(step, r) / 4.0
    return _Settings(
        radius=r, height=float(agent.height), climb=climb, step=step, lift=lift, snap=snap, delta=delta,
        walkable_cos=math.cos(math.radians(float(agent.max_slope))),
        walkable_tan=math.tan(math.radians(float(agent.max_slope))),
        # A lintel lower than the agent closes the way, one as high does not (a search step is the detector's
        # resolution in height, as in length; the map-piece preset's cell height is the same 0.05 m). At the
        # agent's height less ``lift`` (1.8 m) lintels from 1.8 to 2 m passed (docs/entry_exit.md, "An eleventh
        # round of piece kinds").
        head=float(agent.height) - delta,
        search=float(params.edge_search_radii) * r,
        farther=0.0 if farther is None else float(farther),
        step_gap=climb if params.step_gap is None else float(params.step_gap),
    )


def _unit(v: np.ndarray) -> np.ndarray:
    n = np.linalg.norm(v, axis=-1, keepdims=True)
    return v / np.where(n > 1e-12, n, 1.0)


# --------------------------------------------------------------------------
# Steps 2-3: snapping and ways out
# --------------------------------------------------------------------------


@dataclass(frozen=True)
class _Ways:
    """Per sample: where it stands and its way out, if any."""

    base: np.ndarray  # (M,3) sample on the surface
    normal: np.ndarray  # (M,3) surface normal
    tangent: np.ndarray  # (M,3) walking direction in the surface plane
    found: np.ndarray  # (M,) bool: the sample has a way out
    direction: np.ndarray  # (M,3) the way out (unit, surface plane)
    edge: np.ndarray  # (M,3) where the surface ends along it
    stepped: np.ndarray  # (M,) bool: the way out starts on a step up (``base`` is on its top)
    drop: np.ndarray  # (M,) how far below ``base`` the way out ends, down steps (else 0), m
    into_piece: np.ndarray  # (M,) bool: a way reaches the surface's end clear, but the piece lies below beyond it
    landing: np.ndarray  # (M,3) where the agent walking off that end lands, one radius past it (NaN: no such way)


def _walkable(caster: RayCaster, face: np.ndarray, s: _Settings) -> np.ndarray:
    """(n,) bool: the hit faces (-1: none) lie within the agent's slope, either side up."""
    return np.abs(caster.face_normals[np.maximum(face, 0)] @ UP) >= s.walkable_cos


def _snap(
    samples: LoopSamples, polygon_normals: np.ndarray, caster: RayCaster, s: _Settings
) -> tuple[np.ndarray, np.ndarray]:
    """Samples moved onto the mesh (down along the polygon normal, straight down, then up) and the hit normals.

    Only faces the agent can walk count: a polygon Recast laid over a step tilts, and its normal
    can lead onto the riser."""
    snap = s.snap
    n_nav = _unit(polygon_normals[samples.polygon])
    base = samples.position.copy()
    normal = n_nav.copy()

    # Down: from ``snap`` above the sample, so a sample a little under the surface is found too;
    # then straight down, then up along the normal.
    down = caster.first_hits(samples.position + n_nav * snap, -n_nav)
    dist, pts, tri = down.distance, down.points, down.face
    ok = (dist <= 2.0 * snap + _SNAP_SLACK) & _walkable(caster, tri, s)
    vertical = np.broadcast_to(UP, n_nav.shape)
    for start, direction, reach in ((snap, -1.0, 2.0 * snap + _SNAP_SLACK), (0.0, 1.0, snap)):
        miss = np.nonzero(~ok)[0]
        if not len(miss):
            break
        axis = n_nav[miss] if direction > 0 else vertical[miss]
        hits = caster.first_hits(samples.position[miss] + axis * start, axis * direction)
        good = (hits.distance <= reach) & _walkable(caster, hits.face, s)
        pts[miss[good]], tri[miss[good]] = hits.points[good], hits.face[good]
        ok[miss[good]] = True
    base[ok] = pts[ok]
    face_n = caster.face_normals[tri[ok]]
    flip = np.einsum("ij,ij->i", face_n, n_nav[ok]) < 0
    face_n[flip] *= -1.0
    normal[ok] = face_n
    return base, normal


def _surface_ends(
    caster: RayCaster, origins: np.ndarray, directions: np.ndarray, down: np.ndarray, s: _Settings,
    reaches: tuple[float, ...],
) -> list[tuple[np.ndarray, np.ndarray]]:
    """Per reach of ``reaches`` (m): (n,) distance along each direction where the surface under the lifted origins
    ends (NaN: not within that reach, m), and (n,) how far below the origin's ground the surface ends there, m, where
    the way went down steps (:func:`_down_steps`), else 0.

    The probes are cast once, as far as the farthest reach; each reach reads the first of them (a probe's answer
    and the walk down steps up to it depend on the probes before it alone), as a search that far and no farther
    would: its last probe finding no surface is an end (no farther probe shows it a crack).

    Only faces the agent can walk count as surface: on a floor sloping down out of the piece the probes,
    cast along its tilted normal, would otherwise meet the slab's own end face below the floor's edge
    and put the edge beyond it (by ``lift * tan(slope)``: 0.05 m at 15 degrees)."""
    reach = max(reaches)
    if not (steps := reach / s.delta) <= _MAX_PROBE_RAYS:  # a batch could not hold one sample's probes
        raise PluginError(f"terminals.params.edge_search_radii: looking {reach:.4g} m beyond the boundary in steps of "
                          f"{s.delta:.4g} m makes {steps:.3g} probes a sample, more than {_MAX_PROBE_RAYS:,}; use a smaller one")
    # whole search steps, counted in decimal as the parameters are written: 3.0 * 0.4 m is 1.2000000000000002 m,
    # which a ceiling in floating point made 25 steps (1.25 m) for 24
    n_base = max(1, math.ceil(round(steps, _STEP_DIGITS)))
    counts = [max(1, math.ceil(round(r / s.delta, _STEP_DIGITS))) for r in reaches]  # each reach's probes
    # A reach is counted on the floor: the probes over a gap the agent steps over (:func:`_over_step_gap`) add to it,
    # so probes are cast as much farther as the step gap is wide (a doorway 0.4 m past a 0.35 m cut, its floor's end
    # 1.27 m past the navmesh's boundary, lay beyond the 1.2 m reach)
    n_gap = math.ceil(round(s.step_gap / s.delta, _STEP_DIGITS))
    n_off = n_base + n_gap
    offsets = s.delta * np.arange(1, n_off + 1)
    lo = np.full((len(reaches), len(origins)), np.nan)
    # how far the ground stood on last lies below the origin's, down a stair only
    drop = np.zeros((len(reaches), len(origins)))
    ground_at_end = np.full((len(reaches), len(origins)), np.nan)  # the ground stood on nearest the end, m down
    batch = max(1, _MAX_PROBE_RAYS // n_off)
    for begin in range(0, len(origins), batch):
        part = slice(begin, begin + batch)
        probes = (origins[part, None, :] + directions[part, None, :] * offsets[None, :, None]).reshape(-1, 3)
        probe_down = np.repeat(down[part], n_off, axis=0)
        hits = caster.first_hits(probes, probe_down)
        walkable = _walkable(caster, hits.face, s)
        missing = (hits.distance > s.lift + s.climb) | ~walkable
        # A probe in a crack running along the way (a grating's slot, the way out within a few degrees of
        # it) stays in it from one probe to the next: it stands on the surface when surface lies a search
        # step to both sides of it, across the way (beyond an edge oblique to the way, one side at most).
        # (over the reach's own probes, as without the step gap's: a row with no ground in them measures from the
        # origin's, not from ground the probes cast farther for a stepped gap find)
        on, far = ~missing.reshape(-1, n_off), hits.distance.reshape(-1, n_off)
        ground = np.concatenate([_nearest_ground(on[:, :n_base], far[:, :n_base]), _nearest_ground(on, far)[:, n_base:]],
                                axis=1).ravel()
        ground_after = _ground_after(on, far).ravel()
        rows = np.flatnonzero(missing)
        side = s.delta * _unit(np.cross(directions[part][rows // n_off], UP))
        across, beside = ground_across_crack(
            caster, probes[rows], probe_down[rows], [side], s.lift + s.climb, lambda faces: _walkable(caster, faces, s)
        )
        # ... and a probe over a gap across the way stands on the surface where the gap is narrower than two
        # search steps, measured (:func:`_over_narrow_gap`)
        still = rows[~across]
        over, beyond = _over_narrow_gap(caster, probes[still], directions[part][still // n_off], probe_down[still],
                                        ground[still], s)
        gapped = np.flatnonzero(~across)
        across[gapped], beside[gapped] = over, beyond
        # ... and one over a wider gap across the way that the agent steps over, onto a floor going on beyond it
        # (:func:`_over_step_gap`; the search's probes alone: the bisection places an end the search decided)
        left = rows[~across]
        stepped, ground_beyond = _over_step_gap(caster, probes[left], directions[part][left // n_off], probe_down[left],
                                                ground[left], ground_after[left], s)
        gapped = np.flatnonzero(~across)
        across[gapped], beside[gapped] = stepped, ground_beyond
        over_gap = np.zeros(len(probes), dtype=bool)
        over_gap[left[stepped]] = True
        over_gap = over_gap.reshape(-1, n_off)
        missing[rows] = ~across
        # such a probe stands on the ground beside the crack: the walk down steps goes on from there, not from
        # whatever lies under the crack (a floor below a catwalk's slot)
        distance = hits.distance.copy()
        distance[rows[across]], walkable[rows[across]] = beside[across], True
        missing, walkable = missing.reshape(-1, n_off), walkable.reshape(-1, n_off)
        depth = distance.reshape(-1, n_off) - s.lift
        for r, count in enumerate(counts):
            reached = count + over_gap[:, :count + n_gap].sum(axis=1)  # the reach's probes, and as many over gaps
            beyond = np.arange(n_off)[None, :] >= reached[:, None]
            # the probes beyond a row's reach find nothing, so its last probes are its ends as at the end of a row
            ends, before = _down_steps(missing | beyond, np.where(beyond, np.inf, depth), walkable & ~beyond, s.climb)
            stood = _nearest_ground(~ends, depth + s.lift)
            # The surface ends where three probes in a row find none: a gap narrower than two search steps
            # (unwelded floor tiles, planks laid 6 cm apart) is no edge, and neither the agent nor Recast's voxels
            # see it; at two in a row two probes fell in one 6 cm gap (docs/entry_exit.md, "An eighteenth round of
            # piece kinds"). A search's last probe finding none is an end, and so are its last two.
            ends[:, :-2] &= ends[:, 1:-1] & ends[:, 2:]
            ends[:, -2:-1] &= ends[:, -1:]
            ends &= ~beyond
            end = np.argmax(ends, axis=1)
            lo[r, part] = np.where(ends.any(axis=1), end * s.delta, np.nan)
            drop[r, part] = before[np.arange(len(end)), end]
            ground_at_end[r, part] = stood[np.arange(len(end)), np.maximum(end - 1, 0)]
    results: list[tuple[np.ndarray, np.ndarray]] = []
    for r in range(len(reaches)):
        edge = np.full(len(origins), np.nan)
        rows = np.nonzero(np.isfinite(lo[r]))[0]
        # a nearer reach's end, from the same probe and the same ground, is bisected alike: read it again
        same = np.zeros(len(rows), dtype=bool)
        for q in range(r):
            again = (lo[q, rows] == lo[r, rows]) & (drop[q, rows] == drop[r, rows]) & ~same
            edge[rows[again]] = results[q][0][rows[again]]
            same |= again
        rows = rows[~same]
        low, high = lo[r, rows], lo[r, rows] + s.delta
        for _ in range(_REFINE_ROUNDS):  # bisection between the last offset with surface and the first without
            mid = 0.5 * (low + high)
            probe = origins[rows] + directions[rows] * mid[:, None]
            hit = caster.first_hits(probe, down[rows])
            on = (hit.distance <= s.lift + s.climb + drop[r, rows]) & _walkable(caster, hit.face, s)
            off = np.flatnonzero(~on)
            on[off] = _over_narrow_gap(caster, probe[off], directions[rows[off]], down[rows[off]],
                                       ground_at_end[r, rows[off]], s)[0]
            low = np.where(on, mid, low)
            high = np.where(on, high, mid)
        edge[rows] = 0.5 * (low + high)
        results.append((edge, np.where(np.isfinite(lo[r]), drop[r], 0.0)))
    return results


def _nearest_ground(on: np.ndarray, distance: np.ndarray) -> np.ndarray:
    """(n, k): along each row of probes, the ``distance`` ((n, k) m) of the last one ``on`` ((n, k) bool) the
    ground at or before each, else of the first after it (:func:`_ground_after`), NaN where the row has none. A
    sample over a slot finds no ground of its own and stays at the navmesh's height, up to a cell over the floor's
    top: the ground a probe beyond it stands on is the one to measure from. O(n k)."""
    k = on.shape[1]
    last = np.maximum.accumulate(np.where(on, np.arange(k)[None, :], -1), axis=1)
    before = np.take_along_axis(distance, np.maximum(last, 0), axis=1)
    return np.where(last >= 0, before, _ground_after(on, distance))


def _ground_after(on: np.ndarray, distance: np.ndarray) -> np.ndarray:
    """(n, k): along each row of probes, the ``distance`` ((n, k) m) of the first one ``on`` ((n, k) bool) the ground
    at or after each, NaN where none is. Over a gap, the floor the row's probes find beyond it. O(n k)."""
    k = on.shape[1]
    first = np.minimum.accumulate(np.where(on, np.arange(k)[None, :], k)[:, ::-1], axis=1)[:, ::-1]
    return np.where(first < k, np.take_along_axis(distance, np.minimum(first, k - 1), axis=1), np.nan)


_FACING_COS = math.cos(math.radians(45.0))
"""A gap's far side faces its near one when their faces' normals lie within 45 degrees of opposite in plan: the two
lips of a gutter or slot are parallel, and what the rays meet at a floor's end beside another thing's side (a store
room's wall beside a doorway's floor) stands square to it (:func:`_over_step_gap`)."""


def _over_step_gap(
    caster: RayCaster, probes: np.ndarray, directions: np.ndarray, down: np.ndarray, ground: np.ndarray,
    ground_after: np.ndarray, s: _Settings,
) -> tuple[np.ndarray, np.ndarray]:
    """Which of the (n,3) ``probes`` that found no ground, and no gap narrower than two search steps
    (:func:`_over_narrow_gap`), stand over a gap across the way narrower than the step gap (``s.step_gap``) that the
    agent steps over, and how far along ``down`` ((n,3)) from them the nearer side's ground lies ((n,) m, inf where
    not).

    The product's rule (docs/sampling.md, "Narrow gaps between floors"): the agent steps over a gap narrower than
    the step gap (by default its climb) between floors within its climb of each other, so a gutter or slot 0.15-0.39
    m wide just inside a doorway, deeper than the climb, is no floor's end, and the doorway beyond it is an opening.
    Measured along the way (``directions`` (n,3)) and back, a sixteenth of a step under the ground's top (``ground``
    (n,) m along ``down``, NaN: the origin's); where that finds no gap and the way's own probes found ground beyond
    it at another height within the climb (``ground_after`` (n,) m along ``down``, NaN: none, :func:`_ground_after`),
    again with the ray ahead a sixteenth of a step under that far ground's top: a far floor 0.02 m lower has its lip
    under the first rays, a slab 0.2 m higher and 0.2 m thick its underside over them (docs/entry_exit.md, "A far
    floor lower than the near one, asked by its ground"). Both sides met from the gap, their faces' normals within
    45 degrees of opposite in plan (:data:`_FACING_COS`), each side's distance taken square to its face, the two under
    the step gap; walkable
    ground within the climb just past both lips, and still two search steps past the far one (a strip the next
    probes stand on, not a beam's top): :func:`_narrow_gap_along` with those bounds. Not the builder's own test (:func:`~g2s_plugins._raycasting.
    ground_across_step_gap`, straight down along eight axes): at a floor's real end the search's probes, cast along a
    tilted floor's normal, meet no ground where straight down they do, and ground beside a probe along the end's own
    line counts for it, so that test put floors' ends up to a search step past their real ones and lost five
    known openings (docs/entry_exit.md, "Openings behind a gap the agent steps over"). Two rays a probe, two more
    where a far floor at another height is asked, three more where the gap is narrow enough: O(n).
    """
    if not s.step_gap:
        return np.zeros(len(probes), dtype=bool), np.full(len(probes), np.inf)
    ground = np.where(np.isfinite(ground), ground, s.lift)
    on, distance = _narrow_gap_along(caster, probes, directions, down, ground, s, width=s.step_gap, facing=True,
                                     strip=2.0 * s.delta)
    # asked again only where the way's probes found the far side's ground (a floor, not a riser's face): rays cast
    # again at a fixed depth wherever the first found no gap met stairs' bodies beside floors' ends (7cbb0a0)
    other = np.flatnonzero(~on & (np.abs(ground_after - ground) > s.delta / 16.0) & (ground_after <= ground + s.climb))
    if len(other):
        on[other], distance[other] = _narrow_gap_along(
            caster, probes[other], directions[other], down[other], ground[other], s, width=s.step_gap, facing=True,
            strip=2.0 * s.delta, ahead_at=ground_after[other])
    return on, distance


def _over_narrow_gap(
    caster: RayCaster, probes: np.ndarray, directions: np.ndarray, down: np.ndarray, ground: np.ndarray, s: _Settings
) -> tuple[np.ndarray, np.ndarray]:
    """Which of the (n,3) ``probes`` that found no ground stand over a gap across the way, or a slot along it,
    narrower than two search steps, and how far along ``down`` ((n,3)) from them the ground beside it lies ((n,) m,
    inf where not).

    The gap is measured, not sampled: rays along the way (``directions``, (n,3)) and back, a sixteenth of a step
    under the ground's top (``ground`` (n,) m along ``down`` from each probe; NaN where no probe of the way stood
    on any: then at the origin's ground and a search step, the navmesh's cell height, lower), and where they find
    no narrow gap, rays square to the way (:func:`_narrow_gap_at`), reach its sides, each
    side's distance is taken square to the face met, and walkable ground within the climb must lie just past both.
    Probes a search step apart sample a grate's bars narrower than a step as they fall: three in a row missed the
    last bars of one (bars 0.04 m wide, 0.04 m apart) and put its end 0.08 m short, and a search's last probe in a
    slot was an end (docs/entry_exit.md, "A twenty-third round of piece kinds" and "A twenty-fourth round"). A
    floor's end has no side ahead within two steps; faces of no thickness give no side (three probes in a row stay
    the rule there). Two rays a probe, two more square to the way where those find no narrow gap, two more where
    the gap is narrow (all twice, where the ground is unknown): O(n).
    """
    known = np.isfinite(ground)
    on, distance = _narrow_gap_at(caster, probes, directions, down, np.where(known, ground, s.lift), s)
    lower = np.flatnonzero(~known & ~on)
    if len(lower):
        on[lower], distance[lower] = _narrow_gap_at(caster, probes[lower], directions[lower], down[lower],
                                                    np.full(len(lower), s.lift + s.delta), s)
    return on, distance


def _narrow_gap_at(
    caster: RayCaster, probes: np.ndarray, directions: np.ndarray, down: np.ndarray, ground: np.ndarray, s: _Settings
) -> tuple[np.ndarray, np.ndarray]:
    """:func:`_over_narrow_gap` with the ground's top known, ``ground`` ((n,) m) along ``down`` from each probe: the
    gap measured along the way, then, where that finds none, square to it. A slot running along the way (a grating
    of bars along it) has no sides ahead, and the crack rule's ground a search step to both sides of the probe
    falls in the next slots where they are as wide as the bars and their pitch is more than a step and less than
    two (bars 0.03 m wide, 0.03 m apart: a probe in a slot never has bars a step to both sides), so probes along
    the slots ended the floor where the grating began (docs/entry_exit.md, "A twenty-sixth round of piece
    kinds"). O(n) rays, twice as many where the way meets no narrow gap."""
    on, distance = _narrow_gap_along(caster, probes, directions, down, ground, s)
    slot = np.flatnonzero(~on)
    if len(slot):
        square = _unit(np.cross(directions[slot], UP))
        on[slot], distance[slot] = _narrow_gap_along(caster, probes[slot], square, down[slot], ground[slot], s)
    return on, distance


def _narrow_gap_along(
    caster: RayCaster, probes: np.ndarray, directions: np.ndarray, down: np.ndarray, ground: np.ndarray, s: _Settings,
    width: float | None = None, facing: bool = False, strip: float = 0.0, ahead_at: np.ndarray | None = None,
) -> tuple[np.ndarray, np.ndarray]:
    """Which probes stand over a gap narrower than ``width`` m (None: two search steps) measured along ``directions``
    ((n,3)) and back, and how far along ``down`` the ground beside it lies (:func:`_over_narrow_gap`). ``facing``: its
    sides' faces also lie within 45 degrees of opposite in plan (:data:`_FACING_COS`), each met from the gap's side
    (rays starting inside a stair's body under its treads leave it through two faces turned away from each other,
    docs/entry_exit.md, "A far floor lower than the near one, asked by its ground"); ``strip`` (m): the far side's
    ground also goes on that far past its lip (:func:`_over_step_gap`); ``ahead_at`` ((n,) m along ``down``, None:
    ``ground``): the ground the ray ahead runs just under, the far side's own."""
    on, distance = np.zeros(len(probes), dtype=bool), np.full(len(probes), np.inf)
    if not len(probes):
        return on, distance
    under = probes + down * (ground + s.delta / 16.0)[:, None]
    under_ahead = under if ahead_at is None else probes + down * (ahead_at + s.delta / 16.0)[:, None]
    ahead, behind = caster.first_hits_of([(under_ahead, directions), (under, -directions)])
    # each side's distance across it (square to the face met): a way along a slot meets its sides far off
    across = []
    for hit, sign in ((ahead, 1.0), (behind, -1.0)):
        met = np.isfinite(hit.distance)
        along = np.einsum("ij,ij->i", caster.face_normals[np.maximum(hit.face, 0)], directions)
        if facing:  # met from the gap's side: a ray starting inside a solid leaves it through faces turned away
            met &= along * sign < 0.0
        across.append(np.where(met, np.where(met, hit.distance, 0.0) * np.abs(along), np.inf))
    narrow = across[0] + across[1] < (2.0 * s.delta if width is None else width)
    if facing:
        plan = [_unit(caster.face_normals[np.maximum(hit.face, 0)] * np.array([1.0, 0.0, 1.0])) for hit in (ahead, behind)]
        narrow &= np.einsum("ij,ij->i", plan[0], plan[1]) <= -_FACING_COS
    rows = np.flatnonzero(narrow)
    if not len(rows):
        return on, distance
    past = s.delta / 16.0  # onto each side's top, past its edge
    far = probes[rows] + directions[rows] * (ahead.distance[rows] + past)[:, None]
    sides = caster.first_hits_of([
        (far, down[rows]),
        (probes[rows] - directions[rows] * (behind.distance[rows] + past)[:, None], down[rows]),
    ] + ([(far + directions[rows] * strip, down[rows])] if strip > 0.0 else []))
    reach = ground[rows] + s.climb
    both = np.logical_and.reduce([(hit.distance <= reach) & _walkable(caster, hit.face, s) for hit in sides])
    on[rows[both]] = True
    distance[rows[both]] = np.minimum(sides[0].distance, sides[1].distance)[both]
    return on, distance


def _down_steps(
    missing: np.ndarray, depth: np.ndarray, walkable: np.ndarray, climb: float
) -> tuple[np.ndarray, np.ndarray]:
    """The probes of a way out that walk down steps, each within the climb of the ground stood on before it.

    ``missing`` (n, k): the probes finding no ground within the climb of the origin's (along the way, k
    probes a search step apart); ``depth`` (n, k): how far each probe's ground lies below the origin's, m
    (inf: none); ``walkable`` (n, k): its face within the agent's slope. A stair going down off the piece's
    edge drops more than the climb within the search's reach: measured from the origin alone, a sample on
    its side saw the floor end at the first riser that took it past the climb, one or two treads short of the
    stair's end, and a segment's edge points lay on several risers (docs/entry_exit.md, "A twelfth round of
    piece kinds"). Walking the probes in order, one whose ground lies within the climb of the last ground
    stood on stands on the surface. Returns ``missing`` with those probes found and (n, k) the depth of the
    last ground stood on before each probe where a probe of its row was found so, else 0 (the reach of the
    bisection that follows: the same as before for every other row). O(n k).
    """
    missing = missing.copy()
    last = np.zeros(len(depth))  # depth of the last ground stood on
    before = np.zeros(depth.shape)
    followed = np.zeros(len(depth), dtype=bool)
    for j in range(depth.shape[1]):
        before[:, j] = last
        grounded = walkable[:, j] & np.isfinite(depth[:, j])
        down = missing[:, j] & grounded & (depth[:, j] - last <= climb)
        missing[:, j] &= ~down
        followed |= down
        last = np.where(~missing[:, j] & grounded, depth[:, j], last)
    return missing, np.where(followed[:, None], before, 0.0)


def _floor_beyond(edge_at: np.ndarray, way: np.ndarray, caster: RayCaster, s: _Settings) -> np.ndarray:
    """(n,) bool: the piece's own floor found again beyond a gap the agent does not step over, square to the edge.

    ``edge_at``: points ``lift`` m over the ground where the floor's end search along ``way`` found it end. Looking
    back along ``way`` from half a search step past it, just under the ground, meets the floor's side face (none:
    a face of no thickness, read as no gap, as by the step-gap rule); square to the edge is that face's plan
    normal, since a way along a slot slants over it far past one radius and a sampled boundary's own normal may
    run along it. Beyond the face, from one search step to ``search`` m past it, a point with no floor straight
    below comes before one with walkable floor facing up within the climb of the ground at the end: a gap, then
    the floor again. The floor going on from the face is no floor beyond: where the face met is not the edge's
    side (a terrain's own sloping top, met looking back at its border) the square runs out over the ground the
    way started from, or along the border over it, and a border's ways were dropped mid-border, splitting it
    (docs/entry_exit.md, "A slot in the floor is not a way out"). O(n search / d) rays."""
    plan = np.array([1.0, 0.0, 1.0])
    under = edge_at + way * (s.delta / 2.0) - UP * (s.lift + s.delta / 4.0)
    side = caster.first_hits(under, -way)
    met = np.isfinite(side.distance) & (side.distance <= s.delta)
    square = _unit(caster.face_normals[np.maximum(side.face, 0)] * plan)
    square *= np.where(np.einsum("ij,ij->i", square, way) < 0.0, -1.0, 1.0)[:, None]  # the face's outer side
    lip = np.where(met[:, None], np.nan_to_num(side.points) * plan + edge_at * UP, edge_at)  # at the rays' height
    steps = np.arange(s.delta, s.search + s.delta / 2.0, s.delta)
    probes = (lip[None, :, :] + steps[:, None, None] * square[None, :, :]).reshape(-1, 3)
    hit = caster.first_hits(probes, -UP)
    up = caster.face_normals[np.maximum(hit.face, 0)] @ UP >= s.walkable_cos
    level = np.abs(hit.distance - s.lift) <= s.climb
    floor = (np.isfinite(hit.distance) & up & level).reshape(len(steps), -1)
    at_face = np.logical_and.accumulate(floor, axis=0)  # the floor going on from the face, no gap yet
    return met & (floor & ~at_face).any(axis=0)


def _fan(
    base: np.ndarray, normal: np.ndarray, tangent: np.ndarray, caster: RayCaster, s: _Settings, params: Params,
    reaches: tuple[float, ...],
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The way out of each point of ``base`` (step 3), the surface's end looked for up to the first of ``reaches``
    (m) along each direction, and for a point with none, up to the next: (M,) found, (M,3) direction, (M,) distance
    to the edge, (M,) how far below the point's ground the surface ends there (down steps, else 0), (M,) bool:
    some direction of a look the point took reaches the surface's end clear but for the piece lying below beyond
    it (a drop into the piece), and (M,3) where the piece lies straight below one radius past that end, along the
    direction nearest straight out of the first look that met one (NaN: none)."""
    outward = np.cross(tangent, normal)  # the walkable side is on the left of the tangent
    m, k = len(base), int(params.fan_count)
    half = math.radians(float(params.fan_half_angle_deg))
    theta = np.linspace(-half, half, k) if k > 1 else np.zeros(1)
    dirs = (np.cos(theta)[None, :, None] * outward[:, None, :] + np.sin(theta)[None, :, None] * tangent[:, None, :])
    dirs = dirs.reshape(-1, 3)
    lifted = np.repeat(base + normal * s.lift, k, axis=0)
    down = np.repeat(-normal, k, axis=0)
    clear = caster.first_hits(lifted, dirs).distance > float(params.outward_radii) * s.radius
    todo = np.nonzero(clear)[0]
    looks = _surface_ends(caster, lifted[todo], dirs[todo], down[todo], s, reaches)
    found, chosen = np.zeros(m, dtype=bool), np.arange(m) * k
    edge_of, drop_of = np.zeros(m), np.zeros(m)
    into_piece = np.zeros(m, dtype=bool)
    landing = np.full((m, 3), np.nan)
    heights = np.arange(s.climb + s.delta / 4.0, s.head, s.delta / 2.0)  # none when the agent climbs its height
    for look_edge, look_drop in looks:
        looking = np.repeat(~found, k)  # the directions of the points with no way out yet
        edge, drop = np.full(m * k, np.nan), np.zeros(m * k)
        edge[todo], drop[todo] = look_edge, look_drop
        ok = np.isfinite(edge) & looking
        if ok.any():
            # Head room: the rays at ``lift`` pass under a lintel lower than the agent (a window at floor
            # level, a vent); the same way at ``head`` must be clear up to the edge.
            rows = np.nonzero(ok)[0]
            head = np.repeat(base + normal * s.head, k, axis=0)[rows]
            ok[rows[caster.first_hits(head, dirs[rows]).distance <= edge[rows]]] = False
        if ok.any() and len(heights):
            # Bars across the way (a railing's rails between its posts) pass between the rays at ``lift`` and
            # the head-room ray: the way must be clear at every half search step of height from the climb up to
            # the head-room ray until the agent's body is past the edge, one radius beyond it (a rope 0.04 m thick
            # passed between rays a whole step apart: docs/entry_exit.md, "A sixteenth round of piece kinds").
            rows = np.nonzero(ok)[0]
            start = np.repeat(base, k, axis=0)[rows]
            up = np.repeat(normal, k, axis=0)[rows]
            origins = (start[None, :, :] + heights[:, None, None] * up[None, :, :]).reshape(-1, 3)
            hits = caster.first_hits(origins, np.tile(dirs[rows], (len(heights), 1))).distance
            barred = (hits.reshape(len(heights), -1) <= (edge[rows] + s.radius)[None, :]).any(axis=0)
            ok[rows[barred]] = False
        if params.leave_footprint and ok.any():
            rows = np.nonzero(ok)[0]
            beyond = lifted[rows] + dirs[rows] * (edge[rows] + s.radius)[:, None]
            below = caster.first_hits(beyond, -UP).distance
            above = caster.first_hits(beyond, UP).distance
            into = np.zeros(m * k, dtype=bool)
            into[rows[np.isfinite(below)]] = True
            into = into.reshape(m, k)
            # where the agent walking off the end lands: the direction nearest straight out that drops
            lands = np.full((m * k, 3), np.nan)
            drops = np.isfinite(below)
            lands[rows[drops]] = beyond[drops] - UP * below[drops, None]
            nearest = np.argmin(np.where(into, np.abs(theta)[None, :], np.inf), axis=1)
            first = into.any(axis=1) & ~into_piece
            landing[first] = lands[np.flatnonzero(first) * k + nearest[first]]
            into_piece |= into.any(axis=1)
            # Above, only what the agent could not stand under blocks the way (the head-room rule): eaves do not.
            ok[rows[np.isfinite(below) | (above < s.head)]] = False
            # A slot in the floor wider than the step gap: the piece's floor goes on beyond it, square to the edge
            # (a way along the slot slants over it far past one radius), so the way leads into the piece, not out.
            rows = np.nonzero(ok)[0]
            if len(rows):
                edge_at = lifted[rows] + dirs[rows] * edge[rows, None]
                ok[rows[_floor_beyond(edge_at, dirs[rows], caster, s)]] = False
        # The soonest way out; among equals, the one closest to straight out. A point with none keeps its first
        # direction and how far that look found the surface going along it (0: not within its reach).
        cost = np.where(ok, edge, np.inf).reshape(m, k) + 1e-6 * np.abs(theta)[None, :]
        pick = np.argmin(cost, axis=1)
        now = np.isfinite(cost[np.arange(m), pick])
        edge_of[~found] = np.nan_to_num(edge[np.flatnonzero(~found) * k])
        picked = np.arange(m)[now] * k + pick[now]
        chosen[now], edge_of[now], drop_of[now] = picked, edge[picked], drop[picked]
        found |= now
    return found, dirs[chosen], edge_of, drop_of, into_piece, landing


def _step_tops(
    base: np.ndarray, normal: np.ndarray, outward: np.ndarray, caster: RayCaster, s: _Settings, params: Params
) -> tuple[np.ndarray, np.ndarray]:
    """Where the agent steps up onto what blocks the rays straight out: (M,) bool and (M,3) the step's top.

    A point's step is what its straight-out ray meets within ``outward_radii * r`` when the surface one
    search step behind that face lies within the climb, higher than half the rays' height (not the floor
    under a wall) and facing up: a threshold, a curb.
    """
    lifted = base + normal * s.lift
    hit = caster.first_hits(lifted, outward)
    near = np.isfinite(hit.distance) & (hit.distance <= float(params.outward_radii) * s.radius)
    top = np.full_like(base, np.nan)
    rows = np.nonzero(near)[0]
    if not len(rows):
        return near, top
    above = (lifted[rows] + outward[rows] * (hit.distance[rows] + s.delta)[:, None]
             + normal[rows] * (s.climb - s.lift))
    down = caster.first_hits(above, -normal[rows])
    height = s.climb - down.distance
    facing = np.einsum("ij,ij->i", caster.face_normals[np.maximum(down.face, 0)], normal[rows])
    step = np.isfinite(down.distance) & (height > 0.5 * s.lift) & (facing > 0.5)
    near[rows[~step]] = False
    top[rows[step]] = down.points[step]
    return near, top


def _ways_out(
    samples: LoopSamples, polygon_normals: np.ndarray, caster: RayCaster, s: _Settings, params: Params
) -> _Ways:
    base, normal = _snap(samples, polygon_normals, caster, s)
    tangent = _unit(samples.tangent - np.einsum("ij,ij->i", samples.tangent, normal)[:, None] * normal)
    # A sampled surface's boundary stands farther inside the floor than a navmesh's: a sample that finds no way out
    # within the navmesh route's reach looks again as far as the sampling allows.
    reaches = (s.search, s.farther) if s.farther > s.search else (s.search,)
    found, direction, reach, drop, into_piece, landing = _fan(base, normal, tangent, caster, s, params, reaches)
    stepped = np.zeros(len(base), dtype=bool)
    if params.step_up:
        rows = np.nonzero(~found)[0]
        near, top = _step_tops(base[rows], normal[rows], np.cross(tangent[rows], normal[rows]), caster, s, params)
        rows, top = rows[near], top[near]
        if len(rows):
            up_found, up_direction, up_reach, up_drop, _, _ = _fan(top, normal[rows], tangent[rows], caster, s, params,
                                                                (s.search,))
            rows, top = rows[up_found], top[up_found]
            base[rows], found[rows], stepped[rows] = top, True, True
            direction[rows], reach[rows], drop[rows] = up_direction[up_found], up_reach[up_found], up_drop[up_found]
    edge = base + direction * reach[:, None]
    return _Ways(base, normal, tangent, found, direction, edge, stepped, drop, into_piece, landing)


# --------------------------------------------------------------------------
# Step 4: segments
# --------------------------------------------------------------------------


def _segments(samples: LoopSamples, ways: _Ways, max_turn_deg: float) -> list[np.ndarray]:
    """Sample index runs with a way out, split where the way out turns by more than ``max_turn_deg``."""
    cos_turn = math.cos(math.radians(max_turn_deg))
    segments: list[np.ndarray] = []
    bounds = np.flatnonzero(np.r_[True, samples.loop[1:] != samples.loop[:-1], True])
    for lo, hi in zip(bounds[:-1], bounds[1:]):
        idx = np.arange(lo, hi)
        d = ways.direction[idx]
        turn = np.einsum("ij,ij->i", d, np.roll(d, 1, axis=0)) < cos_turn
        cut = ~ways.found[idx] | turn
        if samples.closed[samples.loop[lo]]:
            if cut.any():  # begin the walk at a cut so no segment wraps round
                first = int(np.argmax(~ways.found[idx])) if (~ways.found[idx]).any() else int(np.argmax(turn))
                idx = np.roll(idx, -first)
        else:
            turn[0] = True
        current: list[int] = []
        for i in idx.tolist():
            j = i - lo
            if current and ways.found[i] and not turn[j]:
                current.append(i)
                continue
            if len(current) > 1:
                segments.append(np.asarray(current, dtype=np.int64))
            current = [i] if ways.found[i] else []
        if len(current) > 1:
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
    straight: float  # share of the edge points within the tolerance of the line


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


def _ground_at_edge(points: np.ndarray, outward: np.ndarray, caster: RayCaster, s: _Settings) -> np.ndarray:
    """(n,) the height of the walkable ground just inside (n,3) edge ``points``, m, else the points' own heights.

    An edge point lies along its sample's way out, in the plane of the surface under the sample: on a floor uneven
    within the climb (rough rock) that plane, carried a metre out, misses the ground at the edge by up to the
    unevenness, and two points of one edge a few centimetres apart in plan differ by decimetres. Probed straight
    down from the climb above, half a search step inside, back along ``outward`` (n,3), the ways out; ground within
    the climb either side.
    """
    hit = caster.first_hits(points - outward * (_INSET_STEPS * s.delta) + UP * s.climb,
                            np.broadcast_to(-UP, points.shape).copy())
    ground = np.isfinite(hit.distance) & (hit.distance <= 2.0 * s.climb) & _walkable(caster, hit.face, s)
    return np.where(ground, points[:, 1] + s.climb - hit.distance, points[:, 1])


def _edge_tolerance(params: Params, s: _Settings) -> float:
    """How far off a straight line an edge's points may lie, m: ``edge_tolerance_radii`` agent radii, at least two
    search steps."""
    return max(2.0 * s.delta, float(params.edge_tolerance_radii) * s.radius)


def _match_edges(segments: list[np.ndarray], ways: _Ways, caster: RayCaster, s: _Settings,
                 params: Params) -> list[_Edge]:
    """Match each segment to the straight (or smoothly curved) edge its samples found; others are dropped."""
    tolerance = _edge_tolerance(params, s)
    cos_match = math.cos(math.radians(float(params.match_angle_deg)))
    cos_turn = math.cos(math.radians(float(params.max_turn_deg)))

    def fit(samples: np.ndarray) -> tuple[np.ndarray, np.ndarray, float] | None:
        points = ways.edge[samples]
        centre, direction, residual = _fit_line(points)
        # A floor curved across the way (a round pipe) ends along an arc in the vertical plane: such an edge,
        # whose points climb along it no steeper than the agent walks (one surface), is straight in plan. A
        # steeper jump is a riser between two surfaces (a wall's top beside a ceiling's), fitted in 3D; unless
        # the samples climb it too, within the climb: then it is the floor's own step, walked on both sides (a
        # kerb across a tunnel's end); an edge dropping under samples that stay level is still a riser. A jump
        # between points carried out in their samples' planes is a riser only where the ground at the edge jumps
        # too: on a floor uneven within the climb those planes miss the ground at the edge by decimetres.
        rise = np.diff(points[:, 1])
        run = np.hypot(*np.diff(points[:, [0, 2]], axis=0).T)
        steep = np.abs(rise) > s.walkable_tan * run + 1e-9
        walked = (np.abs(rise) <= s.climb) & (np.abs(rise - np.diff(ways.base[samples, 1])) <= s.delta)
        riser = steep & ~walked
        if riser.any():
            ground = np.diff(_ground_at_edge(points, ways.direction[samples], caster, s))
            riser &= np.abs(ground) > s.walkable_tan * run + 1e-9
        if not riser.any():
            _, plan, residual = _fit_line(points[:, [0, 2]])
            # A line in one walkable surface is no steeper than the agent walks; a steeper fit is the height of
            # samples on several treads seeing one floor's end (a flight's foot seen from a line of samples going
            # down it: a vertical line, no edge at all, at 45 degrees), not the edge's: it is level in plan.
            if abs(direction[1]) > s.walkable_tan * math.hypot(direction[0], direction[2]) + 1e-9:
                direction = np.array([plan[0], 0.0, plan[1]])
        straight = float(np.count_nonzero(residual <= tolerance)) / len(points)
        if straight < 0.8 and not _follows(points, ways.tangent[samples], cos_match):
            return None  # the edge points fit no straight edge and no curve along the segment: a corner
        return centre, direction, straight

    kept = []
    for samples in segments:
        matched = fit(samples)
        if matched is None:
            # A segment that walked round a corner onto an edge (its way out turning a little at each
            # sample, never by max_turn_deg at once): the samples at its ends looking out more than
            # max_turn_deg away from its median way out belong to the corner; fit the rest again.
            median = _unit(np.median(ways.direction[samples], axis=0))
            inside = np.flatnonzero(ways.direction[samples] @ median >= cos_turn)
            if len(inside) < 2:
                continue
            samples = samples[inside[0]: inside[-1] + 1]
            matched = fit(samples)
            if matched is None:
                continue
        centre, direction, straight = matched
        points = ways.edge[samples]
        nrm = _unit(ways.normal[samples].mean(axis=0))
        out = _unit(np.cross(direction, nrm))
        if np.dot(out, ways.direction[samples].sum(axis=0)) < 0:
            out = -out
        # The edge runs from ``first`` to ``last`` the way the boundary walks (the floor on its left), as
        # :func:`_extend` grows its ends: not in its edge points' order, which runs back where samples at a
        # single-file line's end look out the other way (``pier_end`` on the sampling route: an end grown
        # inwards past the other, 1.93 m of 2.2; docs/entry_exit.md, "A seventeenth round of piece kinds").
        if np.dot(direction, np.cross(nrm, out)) < 0:
            direction = -direction
        t = (points - centre) @ direction
        kept.append(
            _Edge(samples, centre + direction * t.min(), centre + direction * t.max(), out, nrm, min(1.0, straight))
        )
    return kept


def _split_at_piers(kept: list[_Edge], ways: _Ways, caster: RayCaster, s: _Settings) -> list[_Edge]:
    """Each edge cut where something stands on it between two free stretches (a pier between two doorways).

    The navmesh need not enter doorways barely wider than the agent (a 1.2 m door eroded to 0.4 m, which
    Recast's grid keeps or closes with its phase), and then the samples along the wall inside see out
    through two neighbouring doorways alike: one segment, one edge spanning both and the pier between,
    whose middle stands in the pier. Candidates every search step along the edge, where
    :func:`_extend`'s stand (half a step inside the edge line, ``lift`` up), are blocked when the way
    straight out meets something within ``r``, or when a ray along the edge from it, above the climb,
    meets something not walkable before the next candidate and neither is blocked so (a leaf thinner
    than a search step standing across the edge, between the rays straight out; not ground rising
    along a terrain's border); a blocked run with free candidates
    on both sides cuts the edge, and each part keeps the samples whose edge points lie along it (at
    least two). Blocked runs at the ends (jambs) only end the edge, as before. O(edge length / search
    step) rays per edge.
    """
    inset = _INSET_STEPS * s.delta
    out: list[_Edge] = []
    for e in kept:
        length = float(np.linalg.norm(e.last - e.first))
        n = int(length / s.delta) + 1
        if n < 3:
            out.append(e)
            continue
        along = (e.last - e.first) / length
        t = s.delta * np.arange(n)
        points = e.first + along * t[:, None] - e.outward * inset + UP * s.lift
        blocked = caster.first_hits(points, np.tile(e.outward, (n, 1))).distance <= s.radius + inset
        # and where something thinner than a search step stands across the edge between two free candidates, above the
        # climb (not a strip the agent steps onto) and not walkable (not ground rising along a terrain's border), which
        # neither ray straight out meets: a pivot leaf turned open across a doorway's middle (docs/entry_exit.md, "A
        # twenty-first round of piece kinds")
        over = points[:-1] + UP * (s.climb + s.delta - s.lift)
        hits = caster.first_hits(over, np.tile(along, (n - 1, 1)))
        across = (hits.distance <= s.delta) & ~_walkable(caster, np.maximum(hits.face, 0), s)
        blocked[:-1] |= across & ~blocked[:-1] & ~blocked[1:]
        # and where something stands just inside the edge, whichever way its face turns: a post in a wall's thickness
        # between two doors; a side wall met so only ends the edge, as a jamb (docs/entry_exit.md, "A thirty-second
        # round of piece kinds")
        blocked |= _set_back(points, np.tile(e.outward, (n, 1)), caster, s, facing_out=False)
        t_edge = (ways.edge[e.samples] - e.first) @ along
        blocked &= ~_walked_through(blocked, t, t_edge[~ways.stepped[e.samples]])
        free = np.flatnonzero(~blocked)
        if len(free) < 2 or not blocked[free[0]: free[-1] + 1].any():
            out.append(e)
            continue
        starts = np.r_[0, np.flatnonzero(np.diff(free) > 1) + 1]
        for run in np.split(free, starts[1:]):
            lo, hi = t[run[0]] - s.delta, t[run[-1]] + s.delta
            part = e.samples[(t_edge >= lo) & (t_edge <= hi)]
            if len(part) < 2:
                continue
            tp = (ways.edge[part] - e.first) @ along
            out.append(replace(e, samples=part, first=e.first + along * tp.min(), last=e.first + along * tp.max()))
    return out


def _walked_through(blocked: np.ndarray, t: np.ndarray, t_ways: np.ndarray) -> np.ndarray:
    """(n,) bool: the candidates of ``blocked`` (n,) runs along an edge that a sample's way out ends within.

    ``t`` (n,): the candidates' places along the edge, m; ``t_ways``: where the ways out of its samples that start
    on the floor (not on a step up) reach the edge, m along it. A way out is clear at the rays' height up to the
    edge, so none ends in front of a pier between two doorways; but the candidates stand ``lift`` above the edge's
    line, and where a strip within the climb runs out through the edge (a median strip down a corridor's middle,
    its samples walking out along its top) they stand inside it and meet its end face (docs/entry_exit.md, "An
    eighteenth round of piece kinds"). A way walked over the strip shows the agent goes out there. Ways ending
    within a sample step of every candidate of a run instead: the 0.2 m pier between ``twin_doors``' doorways lay
    within that of the doorways' ways, and the doors were one. O(n + runs x ways).
    """
    walked = np.zeros(len(blocked), dtype=bool)
    runs = np.flatnonzero(np.diff(np.r_[0, blocked.astype(np.int8), 0]))
    for lo, hi in zip(runs[::2], runs[1::2]):  # blocked candidates lo .. hi - 1
        walked[lo:hi] = bool(((t_ways >= t[lo]) & (t_ways <= t[hi - 1])).any())
    return walked


def _set_back(points: np.ndarray, out: np.ndarray, caster: RayCaster, s: _Settings, facing_out: bool = True) -> np.ndarray:
    """(n,) bool: something stands across the way out just inside an edge at ``points`` (n,3), candidates half a
    search step inside its line and ``lift`` up, ``out`` (n,3) its outward unit vectors: met looking straight in
    above the climb (nothing the agent steps onto), nearer the edge's line than the agent's radius, not walkable and,
    with ``facing_out``, its face turned back out across the edge (:data:`_SET_BACK_COS`). A thin post in a wall's
    thickness between two doors, set back 0.1 m from the face the floor ends at, which no ray straight out meets: the
    doors' edges were one, extended over the post and read 0.3 m wide at it (docs/entry_exit.md, "A thirty-second
    round of piece kinds"). One ray each, O(n)."""
    inset = _INSET_STEPS * s.delta
    hits = caster.first_hits(points + UP * (s.climb + s.delta - s.lift), -out)
    faces = np.maximum(hits.face, 0)
    stands = (hits.distance <= s.radius - inset) & ~_walkable(caster, faces, s)
    if facing_out:
        stands &= np.abs(np.einsum("ij,ij->i", caster.face_normals[faces], out)) >= _SET_BACK_COS
    return stands


def _onto_grazed_step(points: np.ndarray, out: np.ndarray, caster: RayCaster, s: _Settings) -> np.ndarray:
    """(n,3) ``points`` (on edges) raised onto a step top just inside them that lies higher by more than half the rays' height.

    The edge search's rays stand ``lift`` above the sample; a step exactly that high (a stair's
    0.2 m riser for the map-piece agent) lies in their plane, so they pass over its top unseen and
    the floor's end beyond it is found at the sample's height, a riser below the real edge, where
    the extension's candidates then stand in the step's top face. Probed straight down from the
    climb above, half a search step inside the edge.
    """
    inset = _INSET_STEPS * s.delta
    hit = caster.first_hits(points - out * inset + UP * s.climb, np.broadcast_to(-UP, points.shape).copy())
    rise = s.climb - hit.distance
    step = np.isfinite(hit.distance) & (rise > 0.5 * s.lift) & _walkable(caster, hit.face, s)
    raised = points.copy()
    raised[step, 1] += rise[step]
    return raised


def _onto_ground_below(points: np.ndarray, out: np.ndarray, depth: np.ndarray, caster: RayCaster,
                       s: _Settings) -> np.ndarray:
    """(n,3) ``points`` (on edges) lowered onto the walkable ground just inside them, at most ``depth`` (n,) m below.

    An edge found down steps (:func:`_down_steps`) lies at its samples' heights, a tread or more above the floor
    that ends there (a stair going down off the piece: 0.4 m above its foot), where the extension's candidates
    find no floor within the climb. Probed straight down from the rays' height, half a search step inside the edge
    (a point a little under the ground, where a line fitted through edge points on several treads runs on past
    them, is raised onto it); ``depth`` NaN leaves a point as it is.
    """
    inset = _INSET_STEPS * s.delta
    rows = np.flatnonzero(np.isfinite(depth))
    lowered = points.copy()
    if not len(rows):
        return lowered
    hit = caster.first_hits(points[rows] - out[rows] * inset + UP * s.lift, np.broadcast_to(-UP, (len(rows), 3)).copy())
    ground = np.isfinite(hit.distance) & (hit.distance <= s.lift + depth[rows] + _SAME_HEIGHT) & _walkable(caster, hit.face, s)
    lowered[rows[ground], 1] -= hit.distance[ground] - s.lift
    return lowered


def _onto_floor_end(first: np.ndarray, last: np.ndarray, out: np.ndarray, caster: RayCaster,
                    s: _Settings) -> tuple[np.ndarray, np.ndarray]:
    """(n,3) (n,3): the ends ``first`` and ``last`` of edges moved out in plan onto the floor's end where the floor
    goes on past them and past the edge's middle, by the least of the three shortfalls and at most
    :data:`_END_REACH_STEPS` search steps.

    An edge point lies where the probes along its sample's normal stop finding floor, in the plane of the surface
    under the sample. On a floor curving up into the piece (an undulating corridor's end in a trough) that plane,
    carried out to the edge, passes under the floor there, and the last probes cross the slab's end face below the
    floor's top: the edge is found a few centimetres short (0.025-0.04 m, against the bisection's 0.003 on a plane),
    and the extension's test that the floor ends half a search step past the edge line finds floor and stops at
    once (docs/entry_exit.md, "A fourteenth round of piece kinds"). Such a shortfall lies along the whole edge;
    where the floor's end is ragged the line fitted through it lies inside it at one end only, and where the floor
    turns out past the edge's ends (a recess) the floor goes on past the ends alone: both are left as they are.
    Probed straight down from the climb above, every quarter search step out along the horizontal part of
    ``out`` (n,3); ground counts from a search step below the end up to the climb above it (not a lower floor
    beyond a step down). On a plane no probe finds floor: the ends stay.
    """
    horizontal = _unit(out * np.array([1.0, 0.0, 1.0]))
    offsets = 0.25 * s.delta * np.arange(1, int(round(4 * _END_REACH_STEPS)) + 1)
    ends = np.concatenate([first, 0.5 * (first + last), last])
    away = np.concatenate([horizontal, horizontal, horizontal])
    probes = (ends[:, None, :] + away[:, None, :] * offsets[None, :, None] + UP * s.climb).reshape(-1, 3)
    hit = caster.first_hits(probes, np.broadcast_to(-UP, probes.shape).copy())
    ground = np.isfinite(hit.distance) & (hit.distance <= s.climb + s.delta) & _walkable(caster, hit.face, s)
    run = np.cumprod(ground.reshape(len(ends), -1), axis=1).sum(axis=1)  # leading probes on floor, each point
    shortfall = np.where(run > 0, offsets[np.maximum(run - 1, 0)], 0.0).reshape(3, -1)
    moved = shortfall.min(axis=0)[:, None] * horizontal
    return first + moved, last + moved


def _seams(samples: LoopSamples, ways: _Ways, s: _Settings) -> np.ndarray:
    """(M,) bool: the boundary samples facing another stretch of boundary less than the agent's radius away in plan,
    within the climb: seams between parts of one floor, which :func:`main_floor` joins (boundaries within a radius),
    not the floor's sides. Two samples face each other when each lies ahead of the other, within 60 degrees of its
    outward direction in plan (:data:`_SEAM_AHEAD`), and those directions are opposed. A wall between two floors
    leaves them at least the agent's diameter and the wall apart, so only a cut in the surface makes a seam: a
    sampled surface broken into pieces in a passage barely wider than the agent (the twenty-seventh round's hatch
    lid 0.95 m in front of a door wall), a floor Recast cuts at a pinch. O(M log M + P) for the P pairs within the
    radius (a k-d tree)."""
    outward = np.cross(ways.tangent, ways.normal) * np.array([1.0, 0.0, 1.0])
    outward /= np.maximum(np.linalg.norm(outward, axis=1, keepdims=True), 1e-12)
    position = samples.position
    pairs = spatial.cKDTree(position[:, [0, 2]]).query_pairs(s.radius, output_type="ndarray").reshape(-1, 2)
    i, j = pairs[:, 0], pairs[:, 1]
    gap = (position[j] - position[i]) * np.array([1.0, 0.0, 1.0])
    ahead = _SEAM_AHEAD * np.linalg.norm(gap, axis=1)
    facing = ((np.abs(position[i, 1] - position[j, 1]) <= s.climb) & (np.einsum("ij,ij->i", gap, outward[i]) > ahead)
              & (np.einsum("ij,ij->i", gap, outward[j]) < -ahead) & (np.einsum("ij,ij->i", outward[i], outward[j]) < 0.0))
    seam = np.zeros(len(position), dtype=bool)
    seam[i[facing]] = True
    seam[j[facing]] = True
    return seam


_SEAM_AHEAD = 0.5
"""Cosine of the widest angle off a boundary sample's outward direction (in plan) at which another sample lies ahead of
it, facing it across a seam (:func:`_seams`): 60 degrees. The two sides of a single file of samples (a polygon of two
corners, whose boundary runs along both its sides) lie along the line from each other, 90 degrees off, and are no
seam; with no angle the rounding of their positions made about half of them seams (``catwalk_over_hall`` at 45
degrees on the sampling route: 87 -> 53 samples counted; docs/entry_exit.md, "A twenty-seventh round of piece
kinds")."""


def _drop_links(samples: LoopSamples, ways: _Ways, s: _Settings) -> np.ndarray:
    """(D, 2) polygon pairs (from, to): a boundary sample's polygon and the polygon of the floor the agent lands on
    walking off the ledge before it, more than the climb and less than a storey (the agent's height) down.

    The agent lands one radius past the ledge (:func:`_fan`'s ``landing``); the floor there is the surface's whose
    boundary sample lies nearest in plan within the edge search's reach and within the climb of the landing in
    height (Recast erodes the lower floor a radius from the riser; a sampled surface stands farther in). O(M log M)
    for M samples.
    """
    base = ways.base[:, 1]
    depth = base - ways.landing[:, 1]
    dropping = np.flatnonzero(np.isfinite(depth) & (depth > s.climb) & (depth < s.height - _SAME_HEIGHT))
    if not len(dropping):
        return np.zeros((0, 2), dtype=np.int64)
    reach = max(s.search, s.farther)
    tree = spatial.cKDTree(ways.base[:, [0, 2]])
    pairs = []
    for i, near in zip(dropping, tree.query_ball_point(ways.landing[dropping][:, [0, 2]], reach)):
        near = np.asarray(near, dtype=np.int64)
        near = near[np.abs(base[near] - ways.landing[i, 1]) <= s.climb]
        if len(near):
            plan = np.linalg.norm(ways.base[near][:, [0, 2]] - ways.landing[i, [0, 2]], axis=1)
            pairs.append((samples.polygon[i], samples.polygon[near[np.argmin(plan)]]))
    return np.asarray(pairs, dtype=np.int64).reshape(-1, 2)


def _walked_down_to(samples: np.ndarray, ways: _Ways) -> float:
    """The height of the lowest floor the ways out of ``samples`` walked down steps to, m; NaN when none did."""
    down = samples[ways.drop[samples] > 0.0]
    return float(np.min(ways.edge[down, 1] - ways.drop[down])) if len(down) else math.nan


def _above(points: np.ndarray, floor: np.ndarray) -> np.ndarray:
    """(n,) how far (n,3) ``points`` lie above ``floor`` (n,) heights, m (0 where they lie below it); NaN where the
    floor is NaN."""
    return np.maximum(points[:, 1] - floor, 0.0)


def _extend(kept: list[_Edge], caster: RayCaster, s: _Settings, floor: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The ends of each opening, extended along its edge (one batched pass per test): (n,3) and (n,3).

    Candidates just inside the edge, beyond both ends: the surface must go on under them, the
    way along the edge must be clear, and so must the way out of them. They stand ``lift`` straight
    above the edge and probe straight down: lifted along a floor's normal that tilts out of the piece
    (a floor sloping down out of it) they would stand ``lift * sin(slope)`` farther out, outside the
    jambs' faces from 7 degrees on, and the extension would run along the walls' outer faces.
    ``floor`` (n,): the height of the lowest floor each edge's ways walked down steps to, m (its ends are first
    lowered onto the ground below them as far down as that floor, :func:`_onto_ground_below`); NaN: at its samples'
    level. The candidates reach two agent radii and a sample step past each end (a navmesh's boundary stands a
    radius in from the jambs), and on a sampled surface as far as a sample looks again for the floor's end
    (``s.farther``): its boundary stands up to that far inside the floor's end along the edge too, and a wide end
    covered by a few samples near its middle (a bridge's end between railings, 1.12 m of its 2.4 m reached from
    them at 0 degrees) was left short by the difference (docs/entry_exit.md, "A thirtieth round of piece kinds").
    """
    n = len(kept)
    out = np.array([e.outward for e in kept])
    nrm = np.array([e.normal for e in kept])
    inset = _INSET_STEPS * s.delta  # candidates stand this far inside the edge line
    first = _onto_grazed_step(np.array([e.first for e in kept]), out, caster, s)
    last = _onto_grazed_step(np.array([e.last for e in kept]), out, caster, s)
    # Each end may lie as far above that floor as the fitted line leaves it: its samples stand on several treads, and
    # a line through their edge points climbs along the edge (``basement_stair`` at 22 degrees on the sampling route:
    # an end 0.84 m above the foot, whose ways walked down 0.8 m at most, was left there, 1.28 m of 1.6).
    first, last = _onto_floor_end(_onto_ground_below(first, out, _above(first, floor), caster, s),
                                  _onto_ground_below(last, out, _above(last, floor), caster, s), out, caster, s)
    along = _unit(np.cross(nrm, out))  # walking direction along the edge (interior on the left)
    n_ext = max(1, int(math.ceil(max(2.0 * s.radius + s.step, s.farther) / s.delta)))
    steps = s.delta * np.arange(1, n_ext + 1)
    ends = np.stack([first, last])  # (2, n, 3)
    sign = np.array([-1.0, 1.0])[:, None, None]
    starts = ends - (out * inset)[None] + UP * s.lift
    direction = sign * along[None]  # (2, n, 3)
    d_along = caster.first_hits(starts.reshape(-1, 3), direction.reshape(-1, 3)).distance.reshape(2, n)
    cand = (starts[:, :, None, :] + direction[:, :, None, :] * steps[None, None, :, None]).reshape(-1, 3)
    down = np.broadcast_to(-UP, (2 * n * n_ext, 3))
    outwards = np.broadcast_to(out[None, :, None, :], (2, n, n_ext, 3)).reshape(-1, 3)
    reach = s.lift + s.climb
    floor = caster.first_hits(cand, down).distance <= reach
    # A candidate over a gap narrower than two search steps, measured, stands on the floor, as a probe of the way
    # out does (:func:`_over_narrow_gap`): along the edge, a step apart, two or three candidates in a row fall into
    # the slots of a grating of bars along the way 0.06 m apart (docs/entry_exit.md, "A twenty-sixth round of piece
    # kinds"), more than the one the crack rule below steps over.
    gaps = np.flatnonzero(~floor)
    floor[gaps] = _over_narrow_gap(caster, cand[gaps], np.broadcast_to(direction[:, :, None, :], (2, n, n_ext, 3))
                                   .reshape(-1, 3)[gaps], down[gaps], np.full(len(gaps), np.nan), s)[0]
    floor = floor.reshape(2, n, n_ext)
    # One candidate over a crack, with floor on both sides of it, stands on the floor: the crack rule of
    # ground_across_crack, its two sides the neighbouring candidates a search step away (no ray more).
    floor[:, :, :-1] |= np.concatenate([np.ones((2, n, 1), dtype=bool), floor[:, :, :-2]], axis=2) & floor[:, :, 1:]
    beyond = caster.first_hits(cand + outwards * (2.0 * inset), down).distance  # just past the edge line
    edge_goes_on = (beyond > reach).reshape(2, n, n_ext)
    open_out = (caster.first_hits(cand, outwards).distance > s.radius + inset).reshape(2, n, n_ext)
    if s.farther > 0.0:
        # On a sampled surface the candidates run farther than a sample stood, and the samples stand only where the
        # agent has its head room: so must the candidates (a keystone hanging to 1.7 m in a doorway's middle, under
        # which the rays at ``lift`` run on, put the middle of one half's extended end under it, read 0 m wide there).
        above = caster.first_hits(cand, np.broadcast_to(UP, cand.shape).copy()).distance
        open_out &= (above > s.head - s.lift).reshape(2, n, n_ext)
    valid = floor & edge_goes_on & open_out
    # A candidate with something standing across the way out just inside it stops the extension where a free one (valid,
    # nothing so inside it) lies beyond it along the edge before its ray meets anything: a post between two doors
    # (:func:`_set_back`), not a rib on a side just before the side itself, which stops it a candidate later and half a
    # step nearer (a corrugated container's face, 0.03 m ribs 0.15 m in: 1.115-1.132 m of the 1.14 between them at 0
    # and 45 degrees), nor a wall's face behind a sill plate standing proud of it (1.576-1.589 m of 1.6).
    set_back = _set_back(cand, outwards, caster, s).reshape(2, n, n_ext)
    reached = valid & ~set_back & (steps[None, None, :] <= d_along[:, :, None])
    free_beyond = np.zeros_like(valid)
    free_beyond[:, :, :-1] = np.logical_or.accumulate(reached[:, :, ::-1], axis=2)[:, :, ::-1][:, :, 1:]
    run = np.cumprod(valid & ~(set_back & free_beyond), axis=2).sum(axis=2)  # leading valid candidates
    ext = np.minimum(np.where(run < n_ext, run + 0.5, run) * s.delta, d_along)
    # Where that stopped it, the post's face is placed to 1/16 of a step between the last candidate and the first: a
    # table's leg 0.2 m in at a corridor's end left the free half beside it 1.181 m of 1.2 half a step short.
    side, row = np.nonzero(run < n_ext)
    at = run[side, row]
    stopped = (set_back & free_beyond)[side, row, np.minimum(at, n_ext - 1)]
    side, row, at = side[stopped], row[stopped], at[stopped]
    lo, hi = at * s.delta, (at + 1) * s.delta
    for _ in range(_REFINE_ROUNDS):
        mid = 0.5 * (lo + hi)
        points = starts[side, row] + direction[side, row] * mid[:, None]
        behind = _set_back(points, out[row], caster, s)
        lo, hi = np.where(behind, lo, mid), np.where(behind, mid, hi)
    ext[side, row] = np.minimum(0.5 * (lo + hi), d_along[side, row])
    return first - along * ext[0][:, None], last + along * ext[1][:, None]


def _onto_floor_along(kept: list[_Edge], first: np.ndarray, last: np.ndarray, caster: RayCaster,
                      s: _Settings) -> tuple[np.ndarray, np.ndarray]:
    """(n,3) (n,3): each opening's ends ``first`` and ``last`` moved up or down onto the floor that ends along it.

    An edge point lies along its sample's way out in the plane of the surface under the sample, and the line through
    a segment's points at their mean height: where the samples stand on several treads within the climb of the floor
    that ends (a doorway three 0.15 m steps down, its samples on the two lower treads), the opening lay between
    them, 0.08 m over its floor on the navmesh and 0.15 m on the sampling route (docs/entry_exit.md, "An opening's
    width and height as a designer reads them"). The floor is probed straight down from the climb above the line,
    every search step along it from a step inside each end and half a search step inside the edge (ground within the
    climb either side, walkable), and the line is laid on it: the least-squares line through the ground's heights
    along the opening (its slope kept where the floor slopes along the edge, a ramp's side). Ends moving less than
    :data:`_SAME_HEIGHT`, or with no ground found, stay. O(opening length / search step) rays each, in one batch.
    """
    inset = _INSET_STEPS * s.delta
    lengths = np.linalg.norm(last - first, axis=1)
    spots = [s.delta * np.arange(1, max(2, int(length / s.delta))) if length > 2.0 * s.delta else np.array([0.5 * length])
             for length in lengths]
    rows = np.repeat(np.arange(len(kept)), [len(t) for t in spots])
    t = np.concatenate(spots)
    along = (last - first) / np.maximum(lengths, 1e-12)[:, None]
    out = np.array([e.outward for e in kept])
    line = first[rows] + along[rows] * t[:, None]
    hit = caster.first_hits(line - out[rows] * inset + UP * s.climb, np.broadcast_to(-UP, line.shape).copy())
    ground = np.isfinite(hit.distance) & (hit.distance <= 2.0 * s.climb) & _walkable(caster, hit.face, s)
    rise = s.climb - hit.distance  # the ground's height over the line, m
    first, last = first.copy(), last.copy()
    for i in range(len(kept)):
        on = (rows == i) & ground
        if not on.any():
            continue
        u, v = t[on], rise[on]
        slope = 0.0 if np.ptp(u) <= 0.0 else float(np.polyfit(u, v, 1)[0])
        at_first = float(np.mean(v) - slope * np.mean(u))
        at_last = at_first + slope * lengths[i]
        if max(abs(at_first), abs(at_last)) > _SAME_HEIGHT:
            first[i, 1] += at_first
            last[i, 1] += at_last
    return first, last


def _passages(
    kept: list[_Edge], first: np.ndarray, last: np.ndarray, ways: _Ways, caster: RayCaster, s: _Settings
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The narrowest clear width across each opening between its edge and the navmesh, and its free part.

    At every search step in from the edge, as deep as its samples stand from it (the wall's thickness
    and the erosion) and on while the passage's sides close in or run on, up to the edge search's reach
    (:func:`_through_the_wall`), rays each way along the edge from the opening's middle. At the rays' height:
    bars or a grille in the wall leave gaps narrower than the agent however wide the hole. One search
    step above the climb (over what the agent steps onto, such as a low slab of rubble, and not
    stopped by ground it walks onto) and at the head-room rays' height: a leaf or a chunk standing in
    the passage, or a sign hanging into it lower than the agent, leaves its free part. Returns (n,)
    the narrowest width at the rays' height, m, (n,) (n,) how far the narrowest free part above
    the climb reaches from the middle towards ``first`` and towards ``last`` (along the edge, m;
    infinite where nothing stands), and (n,) how deep in from the edge that free part was read (m).
    """
    out = np.array([e.outward for e in kept])
    nrm = np.array([e.normal for e in kept])
    along = _unit(np.cross(nrm, out))
    towards_last = np.einsum("ij,ij->i", along, last - first) >= 0.0
    mid = 0.5 * (first + last)
    # A way down steps has no wall of one level to measure across (the rays from its end would run into the
    # treads behind it): its passage is not narrowed.
    reach = np.where(ways.drop > 0.0, 0.0, np.linalg.norm(ways.edge - ways.base, axis=1))
    deep = np.array([np.median(reach[e.samples]) for e in kept])
    limit = np.where(deep > 0.0, np.maximum(deep, s.search), 0.0)
    widths, back, ahead = np.full(len(kept), np.inf), np.full(len(kept), np.inf), np.full(len(kept), np.inf)
    levels = [(k, np.nonzero(k * s.delta <= limit)[0])
              for k in range(1, int(math.ceil(float(limit.max(initial=0.0)) / s.delta)) + 1)]
    if not levels:  # every opening's ways walked down steps: nothing narrows them
        return widths, back, ahead
    # The rays at ``lift`` stand on what the agent steps onto there: from the floor's height they would start inside a
    # strip within the climb running out through the opening's middle and measure its width. Probed for every step
    # in at once (one batch).
    starts = np.cumsum([0] + [len(rows) for _, rows in levels])
    row_of = np.concatenate([rows for _, rows in levels])  # each (step, opening) entry's opening
    depth_of = np.concatenate([np.full(len(rows), k * s.delta) for k, rows in levels])
    insides = mid[row_of] - out[row_of] * depth_of[:, None]
    on_steps = _onto_grazed_step(insides, out[row_of], caster, s)
    # Past its samples the passage is read while the floor goes on within the climb of the opening's, the rays
    # standing on it (steps up through a thick wall: rays at the opening's height would graze the treads, and run in
    # the solid under a room floor higher than the climb); not over a drop. Probed from twice the climb above.
    below = caster.first_hits(insides + UP * (2.0 * s.climb), np.broadcast_to(-UP, insides.shape).copy())
    floored = np.isfinite(below.distance) & (np.abs(below.distance - 2.0 * s.climb) <= s.climb) & _walkable(
        caster, below.face, s)
    beyond = depth_of > deep[row_of]
    insides[beyond & floored, 1] = (insides[:, 1] + 2.0 * s.climb - below.distance)[beyond & floored]
    # Every step's rays in one batch (the rays at ``lift`` from the step top, the free part's, and the way on inward
    # from each step and from the edge: something standing across it within a step and a half, a wall closing a
    # pad's back, ends the passage before a step read in its face's plane, whose rays along the face meet it anywhere).
    low = on_steps + UP * s.lift
    n = len(row_of)
    free_origins, free_directions = _free_rays(insides, along[row_of], s)
    hits = caster.first_hits(
        np.concatenate([low, low, *free_origins, insides + UP * (s.climb + s.delta),
                        insides + UP * s.head, mid + UP * (s.climb + s.delta), mid + UP * s.head]),
        np.concatenate([along[row_of], -along[row_of], *free_directions, -out[row_of],
                        -out[row_of], -out, -out]))
    across = hits.distance[:n] + hits.distance[n: 2 * n]
    to_first_of, to_last_of = _free_reads(hits, 2 * n, along[row_of], towards_last[row_of], caster, s)
    near = hits.distance[(2 + len(free_origins)) * n:] <= 1.5 * s.delta  # past the low rays and the free ones
    closed_of = near[:n] | near[n: 2 * n]  # the way on from each entry's step
    closed = near[2 * n: 2 * n + len(kept)] | near[2 * n + len(kept):]  # from each opening's last step read: the edge
    ended = np.zeros(len(kept), dtype=bool)  # the passage's sides opened out (the room behind the wall), or it ended
    came_out = np.zeros(len(kept), dtype=bool)  # its sides opened out: it came out of the wall
    samples_read = np.full((4, len(kept)), np.inf)  # widths, back, ahead and where read, as deep as the samples stand
    opened_at = np.zeros(len(kept), dtype=np.int64)  # the entry at which its sides opened out
    narrowest_at = np.zeros(len(kept))  # how deep in from the edge the narrowest free part was read, m
    for k in range(len(levels)):
        entries = np.arange(starts[k], starts[k + 1])
        entries = entries[~ended[row_of[entries]]]
        rows = row_of[entries]
        off = beyond[entries] & (~floored[entries] | closed[rows])
        ended[rows[off]] = True
        entries, rows = entries[~off], rows[~off]
        closed[rows] = closed_of[entries]
        to_first, to_last = to_first_of[entries], to_last_of[entries]
        opened = _through_the_wall(to_first + to_last, back[rows] + ahead[rows], s)
        ended[rows[opened]] = came_out[rows[opened]] = True
        opened_at[rows[opened]] = entries[opened]
        widths[rows[~opened]] = np.minimum(widths[rows[~opened]], across[entries[~opened]])
        narrower = ~opened & (to_first + to_last < back[rows] + ahead[rows])
        back[rows[narrower]], ahead[rows[narrower]] = to_first[narrower], to_last[narrower]
        narrowest_at[rows[narrower]] = depth_of[entries[narrower]]
        within = rows[~beyond[entries]]
        samples_read[:, within] = widths[within], back[within], ahead[within], narrowest_at[within]
    # Where the sides opened between a step and the one before, the narrowest part lies between them (at a splay's
    # inner face): bisected as the floor's end is, all such openings at once.
    rows = np.flatnonzero(came_out & (depth_of[opened_at] > 1.5 * s.delta))
    lo, hi = depth_of[opened_at[rows]] - s.delta, depth_of[opened_at[rows]]
    for _ in range(_REFINE_ROUNDS):
        depth = 0.5 * (lo + hi)
        between = mid[rows] - out[rows] * depth[:, None]
        between[:, 1] = insides[opened_at[rows], 1]
        origins, directions = _free_rays(between, along[rows], s)
        to_first, to_last = _free_reads(caster.first_hits(np.concatenate(origins), np.concatenate(directions)), 0,
                                        along[rows], towards_last[rows], caster, s)
        opened = _through_the_wall(to_first + to_last, back[rows] + ahead[rows], s)
        narrower = ~opened & (to_first + to_last < back[rows] + ahead[rows])
        back[rows[narrower]], ahead[rows[narrower]] = to_first[narrower], to_last[narrower]
        narrowest_at[rows[narrower]] = depth[narrower]
        lo, hi = np.where(opened, lo, depth), np.where(opened, depth, hi)
    sides_opened = depth_of[opened_at]
    sides_opened[rows] = hi
    _flush_with_the_face(np.flatnonzero(came_out), sides_opened, mid, out, along, towards_last,
                         insides[opened_at, 1], (back, ahead, narrowest_at), caster, s)
    # What was read past the samples counts where the passage came out of the wall: a corridor running on (tapering,
    # or flaring to its mouth) is read as deep as its samples stand, as before.
    read_past = (widths, back, ahead, narrowest_at)
    return tuple(np.where(came_out, past, read) for past, read in zip(read_past, samples_read))


_FLUSH_STEPS = (0.5, 1.0)
"""Search steps past the face where a passage's sides open out at which :func:`_flush_with_the_face` reads what stands
flush with it (a sliding leaf hung 0.02 m off the face spans 0.4-1.2 steps), against a read half a step before it."""


def _flush_with_the_face(rows: np.ndarray, sides_opened: np.ndarray, mid: np.ndarray, out: np.ndarray,
                         along: np.ndarray, towards_last: np.ndarray, floor: np.ndarray,
                         read: tuple[np.ndarray, np.ndarray, np.ndarray], caster: RayCaster, s: _Settings) -> None:
    """Narrows the free part of the openings ``rows`` (indices into the (n,) arrays) by what stands flush with the face
    where their passage's sides opened out, ``sides_opened`` (n,) m in from the edge, across the way: a side read
    :data:`_FLUSH_STEPS` search steps past the face nearer, by more than the depth between the reads, than half a step
    before it (steeper than 45 degrees to the way, as the splay rule's sides; the nearest such read counts). A sliding
    leaf hung 0.02 m off a wall's inner face and slid half across the doorway leaves the agent only the way between
    its end, square to the way, and the far jamb (``benchmarks/piece_kinds28.py``'s barn door: 0.9 m, read 1.53-1.58
    m). A wall running on past the face (a curved corridor's outer wall, a cave's) and a leaf swung into the room
    (the twenty-fifth round's ajar leaf, 30 degrees to the way) run along the way: the room's, not the doorway's.
    ``mid``, ``out``, ``along`` (n,3), ``towards_last`` (n,) bool and the floor's height ``floor`` (n,) as in
    :func:`_passages`; ``read`` its (back, ahead, narrowest_at) (n,) each, updated in place where the way narrows.
    One batch of :func:`_free_rays`, O(len(rows)) rays."""
    if not len(rows):
        return
    back, ahead, narrowest_at = read
    offsets = np.array([-0.5, *_FLUSH_STEPS]) * s.delta  # before the face, then past it
    every = np.tile(rows, len(offsets))
    depth = sides_opened[every] + np.repeat(offsets, len(rows))
    at = mid[every] - out[every] * depth[:, None]
    at[:, 1] = floor[every]
    origins, directions = _free_rays(at, along[every], s)
    reads = _free_reads(caster.first_hits(np.concatenate(origins), np.concatenate(directions)), 0, along[every],
                        towards_last[every], caster, s)
    for free, side in zip((r.reshape(len(offsets), len(rows)) for r in reads), (back, ahead)):
        across = free[1:] < free[0] - (offsets[1:] - offsets[0])[:, None]
        nearest = np.where(across, free[1:], np.inf)
        k = np.argmin(nearest, axis=0)
        nearer = nearest[k, np.arange(len(rows))] < side[rows]
        side[rows[nearer]] = nearest[k, np.arange(len(rows))][nearer]
        narrowest_at[rows[nearer]] = sides_opened[rows[nearer]] + offsets[1:][k[nearer]]


def _free_rays(inside: np.ndarray, along: np.ndarray, s: _Settings) -> tuple[list[np.ndarray], list[np.ndarray]]:
    """The rays reading how far a passage is free from (n,3) ``inside`` (on the floor, in from an opening's middle)
    along (n,3) ``along`` and back: origins and directions, four blocks of n each (a search step above the climb, over
    what the agent steps onto, ahead and back; at the head-room rays' height, what hangs into the passage lower than
    the agent, a sign over part of it or a vault coming down at its sides, ahead and back), read by
    :func:`_free_reads`; and a fifth straight up from the first height, whether the point stands inside a solid."""
    high, head = inside + UP * (s.climb + s.delta), inside + UP * s.head
    return [high, high, head, head, high], [along, -along, along, -along, np.broadcast_to(UP, high.shape)]


def _in_solid(caster: RayCaster, hits, rays: np.ndarray, s: _Settings) -> np.ndarray:
    """(n,) bool: the rays ``rays`` of ``hits``, cast straight up from a search step over the climb above the floor
    (:func:`_free_rays`' fifth block), start inside a solid: they meet a face from behind under the agent's head."""
    behind = caster.face_normals[np.maximum(hits.face[rays], 0)] @ UP > 0.0
    return (hits.distance[rays] < s.head - s.climb - s.delta) & behind


def _free_reads(hits, at: int, along: np.ndarray, towards_last: np.ndarray, caster: RayCaster,
                s: _Settings, again: bool = True) -> tuple[np.ndarray, np.ndarray]:
    """(n,) (n,): how far the passage is free towards each opening's first and last end (m, infinite where nothing
    stands), from the :func:`_free_rays` of (n,3) ``along`` cast as ``hits`` from index ``at`` on; the nearer of the
    two heights each way, towards the last end along ``along`` where ``towards_last`` (n,) bool. Above the climb,
    ground the agent walks onto (a terrain rising beside its border) is in no one's way, at either height. ``again``:
    read again from just past the nearer face of what the middle stands inside (once: not when reading again)."""
    n = len(along)
    free = []
    for block, direction in ((0, along), (n, -along)):
        reach = [np.where(_ground_ahead(caster, hits, rays, direction, s), np.inf, hits.distance[rays])
                 for rays in (np.arange(at + block, at + block + n), np.arange(at + 2 * n + block, at + 3 * n + block))]
        free.append(np.minimum(*reach))
    forward, backward = free
    if again:
        # The middle inside something standing in the passage (a crate in part of a doorway, its face near the middle
        # or short of it: the sampling route's floor end spans the whole doorway): the rays run through its inside and
        # read it as the free part, on its side. Met from behind straight up under the agent's head: read again from
        # just past its nearer face along the edge, where that stands in the open (docs/entry_exit.md, "A
        # thirty-fourth round of piece kinds").
        exit_ahead, exit_back = hits.distance[at: at + n], hits.distance[at + n: at + 2 * n]
        inside = np.flatnonzero(_in_solid(caster, hits, np.arange(at + 4 * n, at + 5 * n), s)
                                & np.isfinite(np.minimum(exit_ahead, exit_back)))
        if len(inside):
            shift = np.where(exit_ahead[inside] <= exit_back[inside], 1.0, -1.0) * (
                np.minimum(exit_ahead[inside], exit_back[inside]) + 0.5 * s.delta)
            floor = hits.origins[at: at + n][inside] - UP * (s.climb + s.delta) + along[inside] * shift[:, None]
            origins, directions = _free_rays(floor, along[inside], s)
            again_hits = caster.first_hits(np.concatenate(origins), np.concatenate(directions))
            ahead_again, back_again = _free_reads(again_hits, 0, along[inside], np.zeros(len(inside), dtype=bool),
                                                  caster, s, again=False)
            # not out into the next solid (a riser running into a jamb): the first read stands
            out = ~_in_solid(caster, again_hits, np.arange(4 * len(inside), 5 * len(inside)), s)
            forward[inside[out]], backward[inside[out]] = (ahead_again + shift)[out], (back_again - shift)[out]
    return np.where(towards_last, backward, forward), np.where(towards_last, forward, backward)


def _through_the_wall(free: np.ndarray, narrowest: np.ndarray, s: _Settings) -> np.ndarray:
    """(n,) bool: the passage has come out of the wall: its free width ``free`` (n,) is more than
    :data:`_SIDES_OPEN_STEPS` search steps wider than the narrowest read so far, ``narrowest`` (n,) (m; infinite:
    none yet).

    A designer sizes a doorway by its narrowest clear width through the wall. The samples stand where Recast's
    erosion leaves them, ``r`` inside the floor's end on the navmesh: a reveal splaying from 1.2 m at the inner face of
    a wall 1 m thick to 2.2 m at the outer was read 0.4-0.8 m in, 1.40-1.80 m wide with the yaw (docs/entry_exit.md,
    "An opening's width and height as a designer reads them"). The passage is read in from the edge while its sides
    close in or run on (a splay, radial jambs, a stop in the wall), as deep as its samples stand or the edge search
    reaches out (``edge_search_radii * r``), whichever is deeper, and no farther than where they open out: the room
    behind the wall, whose furniture is no part of the doorway. What is read past the samples counts only where they
    do open out within that reach: a corridor running on past it (tapering, or flaring to its mouth) is no reveal.
    """
    return free > narrowest + _SIDES_OPEN_STEPS * s.delta


def _ground_ahead(caster: RayCaster, hits, at: slice, directions: np.ndarray, s: _Settings) -> np.ndarray:
    """(n,) bool: the rays ``at`` of ``hits``, cast along ``directions`` (n,3), met ground the agent walks onto: a face
    within its slope either side up (meshes are not always wound one way), but not one met on its front that faces
    down, a ceiling or a vault coming down ahead. A ray starting inside a hill rising beside a terrain's border meets
    the ground from behind, facing up: ground (its border's openings stay whole)."""
    faces = np.maximum(hits.face[at], 0)
    normals = caster.face_normals[faces]
    ceiling = (np.einsum("ij,ij->i", normals, directions) < 0.0) & (normals @ UP <= -s.walkable_cos)
    return hits.hit[at] & _walkable(caster, hits.face[at], s) & ~ceiling


def _free_part(
    first: np.ndarray, last: np.ndarray, back: np.ndarray, ahead: np.ndarray, out_to: np.ndarray | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """(n,3) (n,3): the openings' ends ``first`` and ``last`` moved along their edge onto the free part's ends.

    ``back`` and ``ahead`` (n,): how far the passage is free from the middle towards each end (see
    :func:`_passages`). The floor's end runs the door's whole width while a sliding leaf in the wall's
    middle, or a rubble chunk just inside the face, leaves only part of it to walk through: the
    opening is that part, as it is where something stands at the face (the floor ends there). ``out_to``
    (2, n) bool (towards ``first``, towards ``last``): ends moved out onto the free part's end where it lies
    beyond them (:func:`_curved_floor_ends`); None: none.
    """
    half = 0.5 * np.linalg.norm(last - first, axis=1)
    along = (last - first) / np.maximum(2.0 * half, 1e-12)[:, None]
    mid = 0.5 * (first + last)
    reach = np.stack([back, ahead])
    reach = np.minimum(half, reach) if out_to is None else np.where(out_to, reach, np.minimum(half, reach))
    return mid - along * reach[0][:, None], mid + along * reach[1][:, None]


def _curved_floor_ends(
    kept: list[_Edge], first: np.ndarray, last: np.ndarray, back: np.ndarray, ahead: np.ndarray, deep: np.ndarray,
    caster: RayCaster, s: _Settings
) -> np.ndarray:
    """(2, n) bool (towards ``first``, towards ``last``): the openings' ends short of their passage's sides where the
    floor's end curves in from the edge's line before them, to be moved out onto the sides (:func:`_free_part`).

    A doorway in a curved wall (a quarter ring of corridor, outer radius 3.5 m, radial jambs 1.11 m apart at the
    inner face) has its floor end flush with the wall's outer face: an arc whose ends lie 0.05 m inside the line
    through its middle, so the extension's candidates (:func:`_extend`), half a search step inside that line, leave
    the floor 0.1 m short of each jamb and the opening read 1.00-1.08 m (docs/entry_exit.md, "A thirty-first round of
    piece kinds"). An end is short when the passage is free beyond it (``back``, ``ahead`` (n,), m from the middle of
    ``first`` and ``last`` (n,3), read ``deep`` (n,) m in from the edge, :func:`_passages`), within the extension's
    reach, at the rays' height as well as above the climb (a jamb standing straight up: an iris frame's sloping foot
    is free farther above than at the floor); the extension stopped for want of floor (none under its next
    candidate); and the floor is there under the free part's end as deep in as that was read: a floor's end that
    curves in, not one that ends (a plank narrower than its doorway has no floor under the jamb's foot as deep in
    either), nor one that runs on past the line or is stopped by something along it (floor under the next
    candidate). Two batches of rays, O(n)."""
    out = np.array([e.outward for e in kept])
    length = np.linalg.norm(last - first, axis=1)
    along = (last - first) / np.maximum(length, 1e-12)[:, None]
    mid, half = 0.5 * (first + last), 0.5 * length
    reach = np.stack([back, ahead])  # (2, n): from the middle towards first, towards last
    sign = np.array([-1.0, 1.0])[:, None, None]
    wider = np.isfinite(reach) & (reach > half + _SAME_WIDTH) & (reach <= half + 2.0 * s.radius + s.step)
    wider &= np.isfinite(deep)[None]  # a free part read nowhere (no step in from the edge) is no side
    if not wider.any():
        return wider
    deep = np.where(np.isfinite(deep), deep, 0.0)
    directions = (sign * along[None]).reshape(-1, 3)
    low = np.tile(mid - out * deep[:, None] + UP * s.lift, (2, 1))
    free_low = caster.first_hits(low, directions).distance.reshape(2, -1) >= reach - _SAME_WIDTH
    beyond = mid[None] + sign * along[None] * np.where(wider, reach, half)[:, :, None]
    inset = _INSET_STEPS * s.delta
    ends = np.stack([first, last])
    probes = np.concatenate([(ends + sign * along[None] * (0.5 * s.delta) - out[None] * inset).reshape(-1, 3),
                             (beyond - out[None] * deep[None, :, None]).reshape(-1, 3)]) + UP * s.lift
    floor = (caster.first_hits(probes, np.broadcast_to(-UP, probes.shape).copy()).distance
             <= s.lift + s.climb).reshape(2, 2, -1)
    return wider & free_low & ~floor[0] & floor[1]


def _between_jambs(
    kept: list[_Edge], first: np.ndarray, last: np.ndarray, caster: RayCaster, s: _Settings,
    height: float | None = None,
) -> np.ndarray:
    """(n,) bool: something stands at both ends of each opening at half the agent's height (a doorway's jambs), or at
    ``height`` m over the edge.

    Probes start one search step inside the opening's ends and inside its edge line, half the agent's
    height (``height``) above it, and look along the edge for 2 search steps.
    """
    out = np.array([e.outward for e in kept])
    nrm = np.array([e.normal for e in kept])
    along = _unit(np.cross(nrm, out))
    lift = nrm * (0.5 * s.height if height is None else height) - out * s.delta
    starts = np.concatenate([first + along * s.delta + lift, last - along * s.delta + lift])
    directions = np.concatenate([-along, along])
    reach = caster.first_hits(starts, directions).distance <= 2.0 * s.delta
    return reach[: len(kept)] & reach[len(kept):]


# --------------------------------------------------------------------------
# Step 6: priors and scores
# --------------------------------------------------------------------------


@dataclass(frozen=True)
class HeldNavMesh:
    """A navmesh cut to the polygons a graph holds (:func:`held_navmesh`): the fields :func:`detect_openings` reads,
    its polygons renumbered 0..H-1 in the navmesh's order.

    Attributes:
        vertices: (V,3) the navmesh's vertices, metres (all of them: the polygons index them).
        polygons: (H,nvp) the held polygons' rows of the navmesh's.
        neighbours: (H,nvp) the held polygon across each edge, -1 at the boundary and where the navmesh's
            neighbour is not held.
        normals: (H,3) and areas (H,), m²: the navmesh's.
        detail_vertices: (DV,3) the navmesh's; detail_triangles (DT',3) those of the held polygons, in the navmesh's
            order, and detail_polygon (DT',) their polygons.
        ids: (H,) the navmesh polygon of each row, ascending.
    """

    vertices: np.ndarray
    polygons: np.ndarray
    neighbours: np.ndarray
    normals: np.ndarray
    areas: np.ndarray
    detail_vertices: np.ndarray
    detail_triangles: np.ndarray
    detail_polygon: np.ndarray
    ids: np.ndarray


def held_navmesh(navmesh: NavMesh, graph: nx.Graph) -> HeldNavMesh:
    """``navmesh`` cut to the polygons ``graph`` holds (:func:`g2s_plugins.play_space.held_polygons`): the play
    space, when the graph builder was given play points, else every polygon. Its boundary runs round the held
    polygons alone, so an area the play space left out (a backdrop, a skybox's floor) holds no opening and weighs
    on no floor of the reachability prior. O(P + DT)."""
    held = held_polygons(graph, navmesh.polygon_count)
    ids = np.flatnonzero(held)
    row = np.full(navmesh.polygon_count, -1, dtype=np.int64)
    row[ids] = np.arange(len(ids))
    neighbours = np.asarray(navmesh.neighbours)[ids]
    detail_polygon = np.asarray(navmesh.detail_polygon)
    kept = held[detail_polygon]
    return HeldNavMesh(
        np.asarray(navmesh.vertices), np.asarray(navmesh.polygons)[ids],
        np.where(neighbours >= 0, row[neighbours], -1).astype(neighbours.dtype), np.asarray(navmesh.normals)[ids],
        np.asarray(navmesh.areas)[ids],
        np.asarray(navmesh.detail_vertices), np.asarray(navmesh.detail_triangles)[kept],
        row[detail_polygon[kept]].astype(detail_polygon.dtype), ids)


@dataclass(frozen=True)
class Detection:
    """What :func:`detect_openings` found: the openings and the navmesh polygons each runs along."""

    openings: tuple[Opening, ...]
    polygons: tuple[tuple[int, ...], ...]
    normals: tuple[tuple[float, float, float], ...]


def main_floor(
    navmesh: NavMesh | HeldNavMesh | SampledSurface, agent: AgentConfig, loops: list[BoundaryLoop] | None = None,
    looks_out: np.ndarray | None = None, closed: np.ndarray | None = None, drops: np.ndarray | None = None,
) -> np.ndarray:
    """(P,) bool: the polygons of the navmesh's main floor: its floor of largest area that is no roof, and those at its level.

    A floor is a connected component of the navmesh, together with every other one whose boundary
    comes within one agent radius horizontally and the agent's climb vertically. Recast's voxel
    grid can cut a floor in two where a passage barely wider than the agent pinches (the shared
    Hallway turned by 5 and 60 degrees: halves 0.15 and 0.02 m apart), while a wall between two
    floors, however thin, leaves them at least 1.12 m apart (generated, at every yaw; see
    docs/entry_exit.md). A roof is a floor over others (:func:`area_below`, at least ``_ROOF_SHARE``
    of its area): a closed ceiling's top outweighs the floor under it, which it covers and overhangs.
    ``loops``: the navmesh's :func:`boundary_loops`, when the caller has them. ``looks_out``: (P,) bool,
    the polygons whose boundary looks out of the piece (step 2's segments); given, a floor the agent
    can leave comes first, roof or not: a floor walled all round holds no opening whatever its size
    (a bridge's deck lies over the closed trough under it, which the roof test alone would keep); and
    with a floor that leaves, every other one that leaves too, whose lowest polygon (a polygon's height is its first
    corner's) or lowest corner lies within the climb of the main one's, either taken, and that is no roof or rises the
    agent's height or more from there: the parts of a corridor cut by a barrier or by a pass narrower than
    Recast keeps, a flight carried over the hall it rises from and cut from it at its foot; not a wall's top,
    a ravine's floor below a bridge or a flat roof at the main floor's level (a tunnel's). ``closed``: (P, 2)
    each polygon's boundary samples on the floor's sides (not its seams, :func:`_seams`) closed by what stands on its
    floor (no way out, and none reaching the floor's end but for the piece lying below beyond it), and all of them;
    given,
    a floor a storey (the agent's height) or more above or below the main one that leaves the piece, with at
    least :data:`_WALKWAY_CLOSED` of its boundary samples closed (walls or railings along its sides), holds
    openings too: a railed deck crossing over a corridor, and the corridor under it; not a wall's top whose
    sides drop into the piece. ``drops``: (D, 2) polygon pairs (from, to) of :func:`_drop_links`, a ledge the agent
    walks off and the floor it lands on, more than the climb and less than a storey down; given, the floors the
    kept ones reach so, down one ledge after another, that leave the piece, are no roof and are somewhere
    :data:`_FOOTPRINT_RADII` agent radii across (:func:`polygon_widths`; not a sampled surface's single file, nor a
    channel the agent barely fits) hold openings too, and a floor of at least :data:`_RIVAL_SHARE` of the largest's
    area from which the agent reaches more area so is the main floor: a corridor whose floor drops 0.6 m half-way
    holds both its ends, whichever half is measured larger; a terrace over the climb beyond a room's door, dropping
    into the room, none (docs/entry_exit.md, "A nineteenth round of piece kinds").
    """
    neighbours = np.asarray(navmesh.neighbours)
    if len(neighbours) == 0:
        return np.zeros(0, dtype=bool)
    radius = float(agent.radius)
    if loops is None:
        loops = boundary_loops(navmesh.vertices, navmesh.polygons, neighbours)
    samples = sample_loops(loops, radius / 4.0, "agent.radius")
    near = spatial.cKDTree(samples.position[:, [0, 2]]).query_pairs(radius, output_type="ndarray").reshape(-1, 2)
    level = np.abs(samples.position[near[:, 0], 1] - samples.position[near[:, 1], 1]) <= float(agent.max_climb)
    pairs = samples.polygon[near[level]]
    if isinstance(navmesh, SampledSurface):  # faces apart along single-file samples the agent walks
        pairs = np.concatenate([pairs, navmesh.joined])
    label = polygon_components(neighbours, pairs)
    area = np.bincount(label, weights=np.asarray(navmesh.areas, dtype=np.float64))
    roof = area_below(navmesh, label, float(agent.height)) >= _ROOF_SHARE
    leaves = np.zeros(len(area), dtype=bool)
    if looks_out is not None:
        leaves[np.unique(label[np.asarray(looks_out, dtype=bool)])] = True
    # Leaving first, then no roof (the lowest floor has none below it), then area; ties to the lowest label.
    best = np.lexsort((-np.arange(len(area)), area, ~roof, leaves))[-1]
    if looks_out is None or not leaves[best]:
        return label == int(best)
    floors = ~roof & leaves
    links = np.zeros((0, 2), dtype=np.int64) if drops is None else label[np.asarray(drops, dtype=np.int64)]
    # A floor walked down to holds the agent's footprint: somewhere wider than a passage the agent barely fits (the
    # canal's channel 1.0 m wide, where Recast keeps no floor: a single file of samples, or since the sampling
    # builder's passage rule a band 0.2 m wide; docs/entry_exit.md, "Since the passage rule").
    widest = np.zeros(len(area))
    np.maximum.at(widest, label, polygon_widths(navmesh))
    links = links[widest[links[:, 1]] >= _FOOTPRINT_RADII * radius]
    reach = _walked_down(links, floors)
    if len(links):
        # Floors of comparable area rank by the area the agent reaches from them, down their ledges: the upper half
        # of a corridor whose floor drops half-way is its main floor, whichever half the surface measures larger.
        reached = (reach.astype(np.float64) @ area) * (floors & (area >= _RIVAL_SHARE * area[best]))
        if reached.max() > reached[best]:
            best = int(np.argmax(reached))
    # Floors at its level that leave the piece too hold openings with it: a barrier higher than the climb, or a pass
    # Recast cuts, splits one floor in two, each part with its own ends (a corridor's far end was missed).
    height = np.asarray(navmesh.vertices, dtype=np.float64)[np.asarray(navmesh.polygons)[:, 0], 1]
    lowest = np.full(len(area), np.inf)
    np.minimum.at(lowest, label, height)
    # A "roof" rising a storey from the main floor's level is a flight carried over the hall it rises from, cut from it
    # at its foot; a ceiling's top there lies flat (a tunnel's roof at the ground, a container's top) and stays out
    # (docs/entry_exit.md, "A twenty-fifth round of piece kinds").
    corners = np.asarray(navmesh.polygons)
    top = np.full(len(area), -np.inf)
    np.maximum.at(top, np.broadcast_to(label[:, None], corners.shape)[corners >= 0],
                  np.asarray(navmesh.vertices, dtype=np.float64)[corners[corners >= 0], 1])
    rises = top - lowest >= float(agent.height)
    # At its level too where its lowest corner or the main floor's is (either floor's height taken either way; the
    # comparison by first corners alone kept): Recast keeps a lane of a flight parted from its neighbour by a handrail
    # as one polygon from its foot to its top, whose first corner may be the top's (a stair module's handrail down its
    # middle at 22 and 45 degrees: one lane's ends lost, either lane the main floor; docs/entry_exit.md, "A
    # thirty-third round of piece kinds"). Lowest corners in place of first corners moved an uneven level's floors
    # (nav_test.obj; "A twenty-first round of piece kinds").
    bottom = np.full(len(area), np.inf)
    np.minimum.at(bottom, np.broadcast_to(label[:, None], corners.shape)[corners >= 0],
                  np.asarray(navmesh.vertices, dtype=np.float64)[corners[corners >= 0], 1])
    within = float(agent.max_climb) + _SAME_HEIGHT
    at_level = np.zeros(len(area), dtype=bool)
    for mine in (lowest, bottom):
        for main in (lowest[best], bottom[best]):
            at_level |= np.abs(mine - main) <= within
    kept = leaves & (~roof | rises) & at_level
    if closed is not None:  # a storey of its own, walled or railed along its sides
        counts = np.zeros((len(area), 2))  # each floor's closed boundary samples, and all of them
        np.add.at(counts, label, np.asarray(closed, dtype=np.float64))
        storey = np.abs(lowest - lowest[best]) >= float(agent.height) - _SAME_HEIGHT
        kept |= leaves & storey & (counts[:, 0] >= _WALKWAY_CLOSED * counts[:, 1])
    kept[best] = True
    kept |= reach[kept].any(axis=0)  # and the floors the agent walks down to from those, off their ledges
    return kept[label]


def polygon_widths(navmesh: NavMesh | HeldNavMesh | SampledSurface) -> np.ndarray:
    """(P,) each polygon's width in plan, m: the widest of its fan triangles (corners 0, j, j + 1) across, twice its
    area over its longest side (the narrowest strip holding it); 0 for a polygon of two corners (samples in single
    file). On a navmesh, or a sampled surface, eroded by the agent's radius from walls and ledges, a floor W wide is
    about W - 2 r across. O(P k) for P polygons of at most k corners."""
    polygons = np.asarray(navmesh.polygons)
    plan = np.asarray(navmesh.vertices, dtype=np.float64)[:, [0, 2]]
    widths = np.zeros(len(polygons))
    for j in range(1, polygons.shape[1] - 1):
        rows = np.flatnonzero(polygons[:, j + 1] >= 0)
        first = plan[polygons[rows, 0]]
        b, c = plan[polygons[rows, j]] - first, plan[polygons[rows, j + 1]] - first
        twice_area = np.abs(b[:, 0] * c[:, 1] - b[:, 1] * c[:, 0])
        longest = np.max(np.linalg.norm(np.stack([b, c, c - b]), axis=2), axis=0)
        widths[rows] = np.maximum(widths[rows], twice_area / np.maximum(longest, 1e-12))
    return widths


def _walked_down(links: np.ndarray, floors: np.ndarray) -> np.ndarray:
    """(C, C) bool: row c, the ``floors`` (C,) bool the agent reaches from floor c walking down ledges (``links`` (D, 2)
    floor pairs (from, to), :func:`_drop_links`), c itself included, through floors only. O(C^2 D) at most."""
    reach = np.eye(len(floors), dtype=bool)
    links = np.unique(links[floors[links[:, 0]] & floors[links[:, 1]]], axis=0)
    while True:
        step = reach.copy()
        np.logical_or.at(step.T, links[:, 1], reach.T[links[:, 0]])  # unbuffered: several links reach one floor
        if (step == reach).all():
            return reach
        reach = step


_RIVAL_SHARE = 0.5
"""Share of the largest floor's area from which a floor ranks with it by the area the agent reaches from it, walking
down ledges (:func:`main_floor`). Measured on the two halves of a corridor whose floor drops 0.45-1.9 m half-way, at
0, 22 and 45 degrees on both routes (the halves of one designed area: the smaller over the larger 0.97-1.00 on the
navmesh, 0.56-0.94 on the sampling route), and on the twelfth round's terrace 0.6 m up beyond a room's doorway, whose
floor drops into the room and which must not hold an opening (the terrace over the room: 0.03-0.08):
docs/entry_exit.md, "A nineteenth round of piece kinds"."""

_FOOTPRINT_RADII = 0.6
"""Agent radii a floor walked down to is across somewhere, eroded by the agent's radius (:func:`polygon_widths`),
from which it holds openings (:func:`main_floor`). Measured on a canal whose channel 1.0 m deep is 0.9-2.0 m wide
beside its walkways, and a corridor dropping 1.0 m onto a narrower one, at 0, 22 and 45 degrees on both routes
(docs/entry_exit.md, "Since the passage rule"): the navmesh keeps the lower floor from 1.2 m (1.1 m
at 45 degrees), 0.27-0.38 m across (0.67-0.94 r; two of the preset's cells of r / 3 at least); the sampling route's
band in a 1.0 m channel, W - 2 r = 0.2 m (0.5 r), measures 0.18 m, in a 1.1 m one 0.28 m."""

_WALKWAY_CLOSED = 0.6
"""Share of a floor's boundary samples closed by what stands on it (no way out, none dropping into the piece) from
which a floor a storey or more from the main one, leaving the piece, holds openings too (:func:`main_floor`): walls or
railings along its sides. Measured at 0, 22 and 45 degrees on both routes over the generated families and the
tenth to fifteenth rounds' kinds (docs/entry_exit.md, "A sixteenth round of piece kinds"): the railed deck crossing
``overpass_crossing``'s corridor, and the corridor under it, 0.74-0.81; every other floor a storey from the main
one that leaves the piece (roofs, wall and hedge tops, a cliff's top) 0.00-0.44."""

_ROOF_SHARE = 0.1
"""A floor over other floors of at least this share of its own area, an agent's height or more below, is a roof.
Measured (docs/entry_exit.md, "A fourth round of piece kinds"): roofs over corridors 1.2-2.4 m wide 0.22-0.79
(a roof overhangs its walls, and the floor under it is eroded by the agent's radius from them), the shared
Hallway's roof 0.07-0.34; every other floor of the generated and shared pieces (wall tops, a round island) 0.00-0.04."""
# Barycentric points sampling each triangle (its centroid and one towards each corner, equal weights):
# a roof's few large polygons are sampled inside, not only at their centroids.
_COVER_POINTS = np.array([[1 / 3, 1 / 3, 1 / 3], [2 / 3, 1 / 6, 1 / 6], [1 / 6, 2 / 3, 1 / 6], [1 / 6, 1 / 6, 2 / 3]])


def area_below(navmesh: NavMesh | HeldNavMesh | SampledSurface, label: np.ndarray, height: float) -> np.ndarray:
    """(C,) the area of other components lying under each component, at least ``height`` lower, over its own area.

    A roof or a ceiling's top (walkable for Recast, as real exports close their rooms) lies over
    the floor it covers; a floor does not. ``label``: (P,) component of every polygon, C = its
    largest + 1; ``height``: the agent's height, metres. Each polygon is cut into triangles: a
    navmesh's detail triangles (its polygons' corners can lie far off the surface: a pitched roof's
    one polygon spans both slopes at 1.6 m, its ridge 3.85 m up, over a floor at 0.1 m), else a fan
    (a sampled surface's polygon of two corners: the line between them, weighing its polygon's area);
    each sampled at four points weighted by area; from each, a ray cast up from ``height`` above it
    finds the first navmesh surface there, which it lies under. O(T log T) for T triangles with the
    ray caster's BVH.
    """
    if hasattr(navmesh, "detail_polygon"):
        vertices = np.asarray(navmesh.detail_vertices, dtype=np.float64)
        triangles = np.asarray(navmesh.detail_triangles)
        owner = np.asarray(navmesh.detail_polygon)
    else:
        polygons = np.asarray(navmesh.polygons)
        vertices = np.asarray(navmesh.vertices, dtype=np.float64)
        fan = range(1, polygons.shape[1] - 1)  # triangle (0, j, j + 1) of each polygon with a corner j + 1
        owners = [np.flatnonzero(polygons[:, j + 1] >= 0) for j in fan]
        lines = np.flatnonzero(polygons[:, 2] < 0)  # polygons of two corners: single-file samples
        triangles = np.concatenate([polygons[o][:, [0, j, j + 1]] for j, o in zip(fan, owners)]
                                   + [polygons[lines][:, [0, 1, 1]]])
        owner = np.concatenate(owners + [lines])
    corners = vertices[triangles]
    area = 0.5 * np.linalg.norm(np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]), axis=1)
    if not hasattr(navmesh, "detail_polygon"):  # a line of samples stands for the band its polygon's area gives
        area[len(area) - len(lines):] = np.asarray(navmesh.areas, dtype=np.float64)[lines]
    points = np.einsum("kj,tjd->tkd", _COVER_POINTS, corners).reshape(-1, 3)
    caster = RayCaster(trimesh.Trimesh(vertices, triangles, process=False))
    hits = caster.first_hits(points + UP * height, UP)
    own = np.repeat(label[owner], len(_COVER_POINTS))
    over = label[owner[np.maximum(hits.face, 0)]]
    under = hits.hit & (over != own)
    weight = np.repeat(area / len(_COVER_POINTS), len(_COVER_POINTS))
    count = int(label.max()) + 1
    total = np.bincount(label[owner], weights=area, minlength=count)
    return np.bincount(over[under], weights=weight[under], minlength=count) / np.maximum(total, 1e-12)


_AXIS_SNAP_COS = math.cos(math.radians(20.0))
_WALL_SIN = math.sin(math.radians(10.0))
_FRAME_BIN_DEG = 1.0
_FRAME_SPREAD_DEG = 3.0


def _quarter_turns(h: np.ndarray) -> np.ndarray:
    """(4, n, 2): the horizontal (x, z) vectors ``h`` (n, 2) turned by 0, 90, 180 and 270 degrees.

    Turned by swapping and negating components, so an axis-aligned vector stays exactly on its axis.
    """
    x, z = h[:, 0], h[:, 1]
    return np.stack([np.stack([x, z], 1), np.stack([-z, x], 1), np.stack([-x, -z], 1), np.stack([z, -x], 1)])


def piece_frame(mesh: trimesh.Trimesh) -> np.ndarray:
    """(4, 3) the piece's own horizontal axes, taken from its walls: ``[u, -u, w, -w]`` with ``w`` = ``u`` turned 90 degrees.

    Modular pieces are laid out on two perpendicular horizontal directions, whatever yaw they were
    exported at. The walls' and slab sides' faces (normals within 10 degrees of horizontal) vote
    for their normal's direction modulo 90 degrees, weighted by area, in 1 degree bins; ``u`` is the
    area-weighted median of the normals within 3 degrees of the fullest bin, each first turned by a
    multiple of 90 degrees onto it: one face's own direction, so a piece most of whose walls lie
    exactly on X and Z gives exactly the X and Z axes, whatever a few slanted faces say. A piece
    with no wall face gives them too.
    """
    normals = np.asarray(mesh.face_normals, dtype=np.float64)
    areas = np.asarray(mesh.area_faces, dtype=np.float64)
    # A face whose corners lie on one line has no normal: trimesh gives it (0, 0, 0), and turned an area of 1e-17 m²
    # rather than 0 (a triangle soup's slivers, docs/entry_exit.md, "An eighteenth round of piece kinds"); no vote.
    wall = (np.abs(normals[:, 1]) <= _WALL_SIN) & (np.hypot(normals[:, 0], normals[:, 2]) > 0.5) & (areas > 0)
    u = np.array([1.0, 0.0])
    if wall.any():
        h = normals[wall][:, [0, 2]]
        h = h / np.linalg.norm(h, axis=1, keepdims=True)
        weight = areas[wall]
        angle = np.degrees(np.arctan2(h[:, 1], h[:, 0])) % 90.0
        bins = int(round(90.0 / _FRAME_BIN_DEG))
        votes = np.bincount(np.floor(angle / _FRAME_BIN_DEG).astype(np.int64) % bins, weights=weight, minlength=bins)
        votes = votes + np.roll(votes, 1) + np.roll(votes, -1)  # a peak on a bin border is not split
        peak = np.radians((int(np.argmax(votes)) + 0.5) * _FRAME_BIN_DEG)
        turns = _quarter_turns(h)  # (4, n, 2)
        toward = turns @ np.array([math.cos(peak), math.sin(peak)])
        folded = turns[np.argmax(toward, axis=0), np.arange(len(h))]
        near = np.flatnonzero(np.max(toward, axis=0) >= math.cos(math.radians(_FRAME_SPREAD_DEG + _FRAME_BIN_DEG)))
        order = near[np.argsort(np.arctan2(folded[near, 1], folded[near, 0]), kind="stable")]
        half = np.searchsorted(np.cumsum(weight[order]), 0.5 * weight[order].sum())
        u = folded[order[min(half, len(order) - 1)]]
    return np.array([[u[0], 0.0, u[1]], [-u[0], 0.0, -u[1]], [-u[1], 0.0, u[0]], [u[1], 0.0, -u[0]]])


def corners_below(corners: np.ndarray, top: float) -> np.ndarray:
    """(3 k, 3) the corners of the triangles ``corners`` (F, 3, 3) cut to their parts at ``top`` (m) or lower, three
    a triangle (a triangle with one corner above ``top`` leaves two).

    The piece's extent at an opening is that of what the agent meets there: ``top`` is its head over
    the opening, and eaves, a roof or an upper storey overhanging the opening do not count; nor does the part of a
    face above the head: a wall leaning out 20 degrees over a door, 3 m high, counted whole, put the door 1.09 m
    inside the extent, and it was dropped (docs/entry_exit.md, "A fourteenth round of piece kinds"). O(F).
    """
    tri = corners[corners[:, :, 1].min(axis=1) <= top]
    above = tri[:, :, 1] > top
    count = above.sum(axis=1)

    def rolled(rows: np.ndarray, first: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        order = (first[:, None] + np.arange(3)[None, :]) % 3  # each triangle's corners from ``first`` on
        t = np.take_along_axis(tri[rows], order[:, :, None], axis=1)
        return t[:, 0], t[:, 1], t[:, 2]

    def crossing(p: np.ndarray, q: np.ndarray) -> np.ndarray:  # where p (below) -> q (above) crosses ``top``
        return p + ((top - p[:, 1]) / (q[:, 1] - p[:, 1]))[:, None] * (q - p)

    one, two = np.flatnonzero(count == 1), np.flatnonzero(count == 2)
    a, b, c = rolled(one, (np.argmax(above[one], axis=1) + 1) % 3)  # c above: the quad a, b, (b c), (a c)
    bc, ac = crossing(b, c), crossing(a, c)
    d, e, f = rolled(two, np.argmin(above[two], axis=1))  # d below: the triangle d, (d e), (d f)
    parts = [tri[count == 0], np.stack([a, b, bc], axis=1), np.stack([a, bc, ac], axis=1),
             np.stack([d, crossing(d, e), crossing(d, f)], axis=1)]
    return np.concatenate(parts).reshape(-1, 3)


def straight_ahead(vertices: np.ndarray, a: np.ndarray, b: np.ndarray, heading: np.ndarray, margin: float) -> np.ndarray:
    """(k, 3) the corners of the triangles among ``vertices`` ((3 m, 3), three corners a triangle, as
    :func:`corners_below` gives them) that lie straight ahead of the opening from ``a`` to ``b``: whose span along
    the opening overlaps its own by more than ``margin`` m (a jamb's face, flush with the opening's end, does not).

    A doorway between jambs leads out of the piece whatever stands beside it: a corridor turning at the piece's edge
    opens sideways with the room it leaves standing out 1.8 m beside its mouth (docs/entry_exit.md, "A twelfth
    round of piece kinds"). A triangle reaching across the opening's span counts whole, so a large one reaching
    both ahead and aside counts its farthest corner (the gap is never under-measured for lack of corners).
    """
    tri = vertices.reshape(-1, 3, 3)
    along = np.cross(UP, heading)
    along = along / max(float(np.linalg.norm(along)), 1e-12)
    lo, hi = sorted((float(a @ along), float(b @ along)))
    span = tri @ along
    keep = (span.max(axis=1) > lo + margin) & (span.min(axis=1) < hi - margin)
    return tri[keep].reshape(-1, 3)


def extent_gap(vertices: np.ndarray, point: np.ndarray, heading: np.ndarray, frame: np.ndarray) -> float:
    """How far ``point`` lies inside the extent of ``vertices`` along the horizontal unit ``heading``, m.

    Modular pieces are laid out on two perpendicular horizontal axes, ``frame`` (4, 3) (see
    :func:`piece_frame`): a heading within 20 degrees of one is measured along that axis, so the
    few degrees of noise in a short opening's fitted edge do not add the piece's extent along the
    other axis. The snap only ever helps: the gap is the smaller of the two, since a piece whose
    walls run in many directions (a curved corridor) has no axes to speak of, and its frame is
    whichever direction wins the vote by a hair (a U-shaped corridor of 24 facets turned by 22
    degrees: 11.7 or 49.2 degrees as its vertices move by 5e-9 m, and at 49.2 an end at the extent
    along its own heading measured 3.69 m inside along the axis).
    """
    cos = frame @ heading
    along_heading = float(np.max(vertices @ heading) - point @ heading)
    if cos.max() < _AXIS_SNAP_COS:
        return along_heading
    axis = frame[int(np.argmax(cos))]
    return min(along_heading, float(np.max(vertices @ axis) - point @ axis))


def _repeated(openings: list[Opening], radius: float, max_turn_deg: float, climb: float,
              free_along: Callable[[np.ndarray, np.ndarray], bool] | None = None, reach: float = 0.0,
              one_way: Callable[[int, int, np.ndarray, np.ndarray, np.ndarray], bool] | None = None,
              meet: float = 0.0) -> np.ndarray:
    """(n,) int: for each opening that overlaps a wider one along the same edge, facing the same way, that one's index; else -1.

    Recast's voxel staircase along an edge turned off the grid's axes can cut one opening's
    samples into several segments; each is extended along the edge (step 5) over much of the same
    opening (the generated ``curb_platform`` turned by 5 to 60 degrees: 2 or 3 per curb gap), and
    an obstacle standing before a doorway splits its samples in two, each seeing part of the door
    (the held-out ``cluttered_room``'s pillar). A narrower opening whose midpoint lies within
    ``radius`` of a wider one's line in plan, one of its ends or its midpoint within ``climb`` of the
    line's height there (:func:`_along_line`), whose extent along it overlaps the wider one's and whose heading is within
    ``max_turn_deg`` of it is the same opening found again: an edge lies at its samples' heights, and
    samples on a flight's treads see the floor end at its foot within the climb below them, or down
    the steps (on the sampling route ``grand_steps``' foot: a part 0.4 m above the rest; a flight of 12
    risers: a part rising from the foot to 0.82 m above it; docs/entry_exit.md, "A sixteenth round of
    piece kinds").

    One that does not overlap it but abuts it, its nearer end within ``reach`` m of the wider one's end along the
    line in plan and within ``climb`` of it in height, is the same opening too when ``free_along(a, b)`` finds nothing
    standing on the line between those two ends (a, b (3,), m): two parts of one floor's end whose passages' sides met on it (a lych gate's coffin stone 0.4 m
    inside the wall, its two lanes' parts ending 7 mm apart on the stone's side at 45 degrees; docs/entry_exit.md, "A
    thirty-sixth round of piece kinds"), not two ways either side of a leaf or a post standing across it, nor two
    stretches of a terrain's border either side of a cliff (ends 0.04 m apart in plan, 4.8 m in height).

    One facing more than ``max_turn_deg`` but less than square away from a wider one ``i``, meeting it end to end
    (their nearest ends within ``meet`` m in plan and ``climb`` in height, ``free_along`` between them), is the same
    opening when ``one_way(i, j, a, b, out)`` takes the floor's end between their far ends (a, b (3,), m; ``out``
    (3,): the two headings' sum) for one way out: a corridor's floor cut in a V past its walls' ends (a prow, its
    halves 60 degrees apart; docs/entry_exit.md, "A thirty-seventh round of piece kinds"), not a plaza's two open
    sides meeting at a corner between walls at right angles (:func:`_sides_square`).
    """
    n = len(openings)
    into = np.full(n, -1, dtype=np.int64)
    first = np.array([o.p0 for o in openings], dtype=np.float64).reshape(n, 3)
    last = np.array([o.p1 for o in openings], dtype=np.float64).reshape(n, 3)
    heading = np.array([o.heading for o in openings], dtype=np.float64).reshape(n, 3)
    width = np.linalg.norm(last - first, axis=1)
    cos_turn = math.cos(math.radians(max_turn_deg))
    order = np.argsort(-width, kind="stable")
    for rank, i in enumerate(order):
        if into[i] >= 0 or width[i] <= 0:
            continue
        span = last[i] - first[i]
        for j in order[rank + 1 :]:
            if into[j] >= 0:
                continue
            if np.dot(heading[i], heading[j]) < cos_turn:
                if one_way is not None and free_along is not None and np.dot(heading[i], heading[j]) > 0.0 and (
                        fold := _end_to_end(first[i], last[i], first[j], last[j], meet, climb)) and free_along(
                        fold[0], fold[1]) and one_way(i, j, fold[2], fold[3], heading[i] + heading[j]):
                    into[j] = i
                continue
            u, plan, rise = _along_line(first[i], span, np.stack([first[j], 0.5 * (first[j] + last[j]), last[j]]))
            near = plan[1] <= radius and np.abs(rise).min() <= climb + _SAME_HEIGHT
            lo, hi = min(u[0], u[2]), max(u[0], u[2])
            if near and lo < 1.0 and hi > 0.0:
                into[j] = i
            elif near and free_along is not None and (abut := _abutting(first[i], last[i], first[j], last[j], u, reach)):
                if abs(abut[0][1] - abut[1][1]) <= climb + _SAME_HEIGHT and free_along(*abut):
                    into[j] = i
    return into


def _abutting(first: np.ndarray, last: np.ndarray, first_j: np.ndarray, last_j: np.ndarray, u: np.ndarray,
              reach: float) -> tuple[np.ndarray, np.ndarray] | None:
    """The wider opening's end (``first``/``last``, (3,) m) and the narrower one's end (``first_j``/``last_j``) that
    face each other when the narrower lies beyond it along its line (``u``: where the narrower one's first end, middle
    and last end lie along it, :func:`_along_line`) with a gap of at most ``reach`` m in plan between them; else
    None."""
    span = float(np.linalg.norm((last - first) * np.array([1.0, 0.0, 1.0])))
    if span <= 0.0:
        return None
    if min(u[0], u[2]) >= 1.0 and (min(u[0], u[2]) - 1.0) * span <= reach:
        return last, (first_j if u[0] <= u[2] else last_j)
    if max(u[0], u[2]) <= 0.0 and -max(u[0], u[2]) * span <= reach:
        return first, (first_j if u[0] >= u[2] else last_j)
    return None


def _end_to_end(first: np.ndarray, last: np.ndarray, first_j: np.ndarray, last_j: np.ndarray, reach: float,
                climb: float) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray] | None:
    """Where two openings (ends ``first``/``last`` and ``first_j``/``last_j``, (3,) m) meet end to end: their nearest
    ends, within ``reach`` m in plan and ``climb`` in height, and their far ends; else None."""
    ends, ends_j = (first, last), (first_j, last_j)
    k, m = min(((k, m) for k in range(2) for m in range(2)),
               key=lambda km: float(np.hypot(*(ends[km[0]] - ends_j[km[1]])[[0, 2]])))
    gap = ends[k] - ends_j[m]
    if float(np.hypot(gap[0], gap[2])) > reach or abs(float(gap[1])) > climb + _SAME_HEIGHT:
        return None
    return ends[k], ends_j[m], ends[1 - k], ends_j[1 - m]


def _sides_square(a: np.ndarray, b: np.ndarray, out: np.ndarray, caster: RayCaster, s: _Settings,
                  tolerance: float) -> bool:
    """Whether the floor's end from ``a`` to ``b`` ((3,) m) is a way between two sides running in square to its chord:
    one search step and one agent radius in from the chord's middle (away from ``out``, (3,), in plan), rays at
    ``lift`` over it along the chord each way meet something half the chord away, within ``tolerance`` m. Not an open
    side (the rays run on) nor walls closing in (a plaza's corner between walls at right angles: 0.4 m nearer one
    radius in)."""
    chord = (b - a) * np.array([1.0, 0.0, 1.0])
    width = float(np.linalg.norm(chord))
    if width <= _SAME_WIDTH:
        return False
    along = chord / width
    inward = np.cross(along, UP)
    inward = inward if np.dot(inward, out) < 0.0 else -inward
    starts = 0.5 * (a + b) + UP * s.lift + inward * np.array([[s.delta], [s.radius]])
    hits = caster.first_hits(np.concatenate([starts, starts]), np.repeat(np.stack([along, -along]), 2, axis=0))
    return bool((np.abs(hits.distance - 0.5 * width) <= tolerance).all())


def _free_along(a: np.ndarray, b: np.ndarray, caster: RayCaster, s: _Settings) -> bool:
    """Whether nothing stands on the floor's end between its points ``a`` and ``b`` ((3,) m): rays from each towards
    the other at the search's height over them (``lift``) meet nothing before they pass each other. Two rays: one
    starting on a face that ends there (a passage's side) would not see it."""
    d = (b - a) * np.array([1.0, 0.0, 1.0])
    gap = float(np.linalg.norm(d))
    if gap <= _SAME_WIDTH:
        return True
    d /= gap
    hits = caster.first_hits(np.stack([a, b]) + UP * s.lift, np.stack([d, -d]))
    return bool((hits.distance > gap).all())


def _along_line(start: np.ndarray, span: np.ndarray, points: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Where (k,3) ``points`` lie against the line from ``start`` over ``span`` (3,), m, read in plan and in height.

    Returns (k,) the share of the span each lies along in plan (0 at ``start``, 1 at its end), (k,) its distance
    from the line in plan, m, and (k,) its height above the line's point there, m. On a sloped line (a ramp's or a
    stair's edge) a perpendicular in 3D leans along it: its height part is not the height over the line, nor its
    plan part the distance in plan (docs/entry_exit.md, "A seventeenth round of piece kinds"). A line with no length
    in plan (a riser's) is read along its span in 3D.
    """
    rel = points - start
    plan_span = span * np.array([1.0, 0.0, 1.0])
    length = float(np.dot(plan_span, plan_span))
    reference = plan_span if length > 1e-12 else span
    u = rel @ reference / float(np.dot(reference, reference))
    off = rel - np.outer(u, span)
    return u, np.hypot(off[:, 0], off[:, 2]), off[:, 1]


def _union_ends(wide: Opening, ends: np.ndarray, turned: np.ndarray,
                tolerance: float) -> tuple[np.ndarray, np.ndarray] | None:
    """The ends of ``wide`` stretched along its own line over ``ends`` (k,3), m (the floor's ends of openings repeating
    it), each read along it in plan (:func:`_along_line`); None when they lie within it (or there are none). An
    outermost end of a part along another line (``turned``, (k,) bool) lying farther than ``tolerance`` m off the line
    in plan is the union's end itself: the floor's end turns there (a doorway's floor running out to the apex of a wall
    folded either side of it: two parts along the wings' faces 30 degrees apart, joined along one of them, faced 15
    degrees off; docs/entry_exit.md, "A thirty-third round of piece kinds")."""
    p0, p1 = np.asarray(wide.p0, dtype=np.float64), np.asarray(wide.p1, dtype=np.float64)
    ends = np.asarray(ends, dtype=np.float64).reshape(-1, 3)
    if not len(ends):
        return None
    u, off, _ = _along_line(p0, p1 - p0, ends)
    lo, hi = min(0.0, float(u.min())), max(1.0, float(u.max()))
    if lo > -1e-9 / wide.width and hi < 1.0 + 1e-9 / wide.width:
        return None
    a, b = p0 + (p1 - p0) * lo, p0 + (p1 - p0) * hi
    first, last = int(np.argmin(u)), int(np.argmax(u))
    if lo < 0.0 and turned[first] and off[first] > tolerance:
        a = ends[first]
    if hi > 1.0 and turned[last] and off[last] > tolerance:
        b = ends[last]
    return a, b


def detect_openings(
    mesh: trimesh.Trimesh,
    surface: NavMesh | HeldNavMesh | SampledSurface,
    agent: AgentConfig,
    params: Params | None = None,
    edge_search_farther: float | None = None,
) -> Detection:
    """Steps 1-6 of the method: the openings of ``mesh`` for ``agent`` on ``surface``, in detection order.

    Args:
        mesh: the source ``trimesh.Trimesh`` (metres, Y up).
        surface: the walkable surface as polygons: a :class:`g2s_plugins.recast.NavMesh` built from
            ``mesh``, or the :func:`~g2s_plugins.terminals._sampled_surface.sampled_surface` of a
            sampled graph of it.
        agent: object with ``radius``, ``height``, ``max_climb``, ``max_slope``.
        params: :class:`Params`; ``None`` for the defaults.
        edge_search_farther: how far beyond the boundary a sample that finds no floor's end within
            ``edge_search_radii * r`` looks again, m (on a sampled surface, :func:`sampled_edge_search`); ``None``:
            not again.
    """
    params = params if params is not None else Params()
    s = _settings(params, agent, edge_search_farther)
    loops = boundary_loops(surface.vertices, surface.polygons, surface.neighbours)
    samples = sample_loops(loops, s.step, "agent.radius" if params.sample_step is None else "terminals.params.sample_step",
                           tips=True)
    if len(samples.loop) == 0:
        return Detection((), (), ())
    caster = RayCaster(mesh)
    ways = _ways_out(samples, np.asarray(surface.normals), caster, s, params)
    segments = _segments(samples, ways, float(params.max_turn_deg))
    if params.main_floor_only:
        looks_out = np.zeros(len(surface.areas), dtype=bool)
        for g in segments:
            looks_out[samples.polygon[g]] = True
        # each polygon's boundary samples on the floor's sides (not its seams) closed by what stands on the floor, and
        # all of them
        side = ~_seams(samples, ways, s)
        closed = np.zeros((len(surface.areas), 2))
        counted = np.stack([~ways.found & ~ways.into_piece, np.ones(len(ways.found), bool)], 1)
        np.add.at(closed, samples.polygon[side], counted[side])
        main = main_floor(surface, agent, loops, looks_out, closed, _drop_links(samples, ways, s))
        segments = [g for g in segments if main[samples.polygon[g]].any()]
    kept = _split_at_piers(_match_edges(segments, ways, caster, s, params), ways, caster, s)
    if not kept:
        return Detection((), (), ())
    # How far down steps the edges' samples found the floor ending (the deepest; 0 for a floor's own level).
    p_first, p_last = _onto_floor_along(
        kept, *_extend(kept, caster, s, np.array([_walked_down_to(e.samples, ways) for e in kept])), caster, s)

    corners = np.asarray(mesh.triangles, dtype=np.float64)
    frame = piece_frame(mesh)
    min_width = float(params.min_width_radii) * s.radius
    tolerance = _edge_tolerance(params, s)
    # Parts joined into one opening face within max_turn_deg of it; those more than half that apart run along other
    # lines (a fold's two wings, 30 degrees apart), nearer ones are the same edge found again (bevelled tiles' ends, 6)
    cos_fold = math.cos(math.radians(0.5 * float(params.max_turn_deg)))
    max_gap = None if params.extent_heights is None else float(params.extent_heights) * s.height
    max_slope = None if params.max_slope_deg is None else math.radians(float(params.max_slope_deg))

    def scored(e: _Edge, a: np.ndarray, b: np.ndarray, framed: bool) -> Opening | None:
        """The opening between ``a`` and ``b`` on ``e``'s edge with its score; None when the outer-extent prior drops it.

        ``framed``: between jambs, whose extent is measured over what lies straight ahead of it alone."""
        width = float(np.linalg.norm(b - a))
        heading = e.outward.copy()
        heading[1] = 0.0
        heading = _unit(heading) if np.linalg.norm(heading) > 1e-6 else e.outward
        # Square to the opening in plan: the horizontal part of ``outward`` (the edge's direction crossed with the
        # floor's normal) leans along the edge where the floor slopes both along and across it, and the outer
        # extent is measured along the heading, so a lean of a fraction of a degree over a piece tens of metres
        # long moves the gap by decimetres (the sample terrain's west border: 0.44 degrees, 0.28 m).
        plan = (b - a) * np.array([1.0, 0.0, 1.0])
        if np.linalg.norm(plan) > 1e-6 and heading[1] == 0.0:
            square = _unit(np.cross(plan, UP))
            heading = square if np.dot(square, heading) >= 0.0 else -square
        mid = (a + b) / 2.0
        below = corners_below(corners, mid[1] + s.height)
        if framed:
            below = straight_ahead(below, a, b, heading, s.delta)
        gap = max(0.0, extent_gap(below, mid, heading, frame))
        if max_gap is not None and gap > max_gap:
            return None
        extent_factor = 1.0 if max_gap is None else 1.0 - gap / max_gap
        width_factor = min(1.0, width / (2.0 * min_width)) if min_width > 0 else 1.0
        score = round(e.straight * extent_factor * width_factor, 6)
        reason = (
            f"floor ends along a {width:.2f} m edge ({e.straight:.0%} of its points on one line), "
            f"{gap:.2f} m inside the piece's outer extent facing out, nothing of the piece beyond"
            + (", on the main floor" if params.main_floor_only else "")
        )
        left = np.cross(UP, heading)
        p0, p1 = (b, a) if np.dot(b - a, left) > 0 else (a, b)
        return Opening(vec3(mid), vec3(heading), width, vec3(p0), vec3(p1), score, reason)

    jambs = _between_jambs(kept, p_first, p_last, caster, s)
    # A step along the piece's edge is a threshold, not a curb, between things at both ends the agent cannot step onto
    # from its top, however low: a sitting wall 1.0 m high lowered to 0.3 m along a stretch, its ends 0.7 m over the
    # stretch's top, under the jambs' probes at half the agent's height (docs/entry_exit.md, "A thirty-third round of
    # piece kinds"); a curb round a platform ends in nothing higher than itself.
    stepped_jambs = jambs | _between_jambs(kept, p_first, p_last, caster, s, s.climb + s.delta)
    passages, back, ahead, sides_at = _passages(kept, p_first, p_last, ways, caster, s)
    half = 0.5 * np.linalg.norm(p_last - p_first, axis=1)
    # Each end moved in onto the passage's side (a jamb) read deeper than the agent's radius, the floor's end's own
    # depth on the navmesh; one the free part reaches to the ray caster's precision is the floor's (a yard's open side
    # turned 22 degrees: its parts' ends 4e-6 m short of their free part's), as is a side read no deeper (a post at
    # an open side's corner, 0.05-0.23 m in: a pavilion's side at 22 degrees on the sampling route read 5.22 m for
    # 5.5 without it; a splayed reveal's jambs are read 0.98-1.01 m in, 60 of 62 parts at 0, 22 and 45 degrees).
    in_side = (sides_at > s.radius)[:, None]
    at_side = np.stack([back < half - _SAME_WIDTH, ahead < half - _SAME_WIDTH], axis=1) & in_side
    curved = _curved_floor_ends(kept, p_first, p_last, back, ahead, sides_at, caster, s)
    # An end moved out onto its passage's side is the side's on the same terms as one moved in: read deeper than the
    # agent's radius. One read nearer the edge is the floor's, and stretches a union of repeated openings: a railed
    # cliff path's end at 45 degrees on the sampling route, a part's end moved out by 0.1 mm onto a side read 0.2 m
    # in, left its union 3.86 m for 3.9 (docs/entry_exit.md, "A thirty-second round of piece kinds").
    at_side |= curved.T & in_side
    p_first, p_last = _free_part(p_first, p_last, back, ahead, curved)
    found: list[tuple[Opening, tuple[int, ...], tuple[float, float, float]]] = []
    edges: list[_Edge] = []
    framed_of: list[bool] = []
    floor_ends_of: list[np.ndarray] = []  # each opening's ends that are the floor's, not a side of its passage
    for e, a, b, framed, step_framed, passage, sides in zip(kept, p_first, p_last, jambs, stepped_jambs, passages,
                                                            at_side):
        if min(float(np.linalg.norm(b - a)), passage) < min_width + _SAME_WIDTH:
            continue
        if ways.stepped[e.samples].mean() > 0.5 and not step_framed:
            continue  # a step along the piece's edge with no jambs: a curb, not a threshold
        d = b - a
        if max_slope is not None and math.atan2(abs(d[1]), math.hypot(d[0], d[2])) > max_slope + 1e-12:
            continue
        opening = scored(e, a, b, bool(framed))
        if opening is None:
            continue
        polys = tuple(sorted(set(samples.polygon[e.samples].tolist())))
        found.append((opening, polys, vec3(e.normal)))
        edges.append(e)
        framed_of.append(bool(framed))
        floor_ends_of.append(np.array([a, b])[~sides])
    # An opening found again is one with the wider one, which spans both; again until none is left,
    # since a union can reach one that overlapped none of its parts (a plaza's side on the sampling
    # route: parts 3.28-9.98 and 0.54-3.37 m along it, then one at 0.17-2.80 m). Each pass drops
    # one at least: at most n passes of O(n^2) for n openings. A part stretches it by its floor's ends alone: an end
    # moved in onto its passage's side deep in the wall lies where that part's line, a degree or two off the wall's,
    # meets the side as deep as the narrowest width stands (a splayed reveal's inner face, 1 m in: 1.234 m for 1.2 on
    # the sampling route, the extremes of 15 parts' ends; docs/entry_exit.md, "Since the passage rule").
    def one_way(i: int, j: int, a: np.ndarray, b: np.ndarray, out: np.ndarray) -> bool:
        """Whether openings ``i`` and ``j``, turned apart and meeting end to end, are one way out between their far
        ends ``a`` and ``b``: the way's sides run in square to its chord there, and the outer-extent prior keeps the
        opening between them (a prow cut 40 degrees or more off square reaches 1 m past its chord: its halves stay)."""
        return _sides_square(a, b, out, caster, s, tolerance) and scored(edges[i], a, b, framed_of[i]) is not None

    while True:
        into = _repeated([f[0] for f in found], s.radius, float(params.max_turn_deg), s.climb,
                         lambda a, b: _free_along(a, b, caster, s), s.delta, one_way, tolerance)
        if not (into >= 0).any():
            break
        for i in sorted(set(into[into >= 0].tolist())):
            parts = np.flatnonzero(into == i)
            # each part's floor ends, and whether the part runs along another line than the wider one
            turned = [np.full(len(floor_ends_of[j]), float(np.dot(found[i][0].heading, found[j][0].heading)) < cos_fold)
                      for j in parts]
            ends = _union_ends(found[i][0], np.concatenate([floor_ends_of[j] for j in parts]), np.concatenate(turned),
                               tolerance)
            union = None if ends is None else scored(edges[i], *ends, framed_of[i])
            if union is not None:
                polys = tuple(sorted(set(found[i][1]).union(*(found[j][1] for j in parts))))
                found[i] = (union, polys, found[i][2])
                floor_ends_of[i] = np.concatenate([floor_ends_of[i], *(floor_ends_of[j] for j in parts)])
        found, edges, framed_of, floor_ends_of = ([item for item, again in zip(items, into) if again < 0]
                                                  for items in (found, edges, framed_of, floor_ends_of))
    found = [f for f in found if f[0].score >= float(params.min_score) - 1e-12]
    if params.best is not None and len(found) > params.best:
        order = sorted(range(len(found)), key=lambda i: (-found[i][0].score, i))[: params.best]
        found = [found[i] for i in sorted(order)]
    return Detection(tuple(f[0] for f in found), tuple(f[1] for f in found), tuple(f[2] for f in found))


# --------------------------------------------------------------------------
# Step 7: terminals
# --------------------------------------------------------------------------


def add_terminals(
    graph: nx.Graph,
    detection: Detection,
    surface: NavMesh | SampledSurface,
    agent: AgentConfig,
) -> Terminals:
    """Add one node per opening to ``graph`` (see the module doc) and return the terminals.

    ``surface``: the one the openings were found on; on a sampled graph's, an opening is joined to
    the nearest sample at the corners of its faces.
    """
    if not detection.openings:
        return Terminals(nodes=(), openings=())
    sampled = surface if isinstance(surface, SampledSurface) else None
    navmesh = None if sampled is not None else surface
    node_of_polygon: dict[int, int] = {}
    ids, positions = [], []
    for node, data in graph.nodes(data=True):
        polygon = data.get("polygon", -1)
        if polygon is not None and polygon >= 0:
            node_of_polygon.setdefault(int(polygon), node)
        if "pos" in data:
            ids.append(node)
            positions.append(data["pos"])
    tree = spatial.cKDTree(np.asarray(positions, dtype=np.float64)) if positions else None
    next_id = max((int(n) for n in graph.nodes), default=-1) + 1
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
            on_navmesh=on_navmesh(navmesh, pos, agent),
            polygon=-1,
        )
        # One edge, so the terminal stays a leaf: never a shortcut between polygons, never
        # an inner node the simplification could remove.
        if sampled is None:
            candidates = [node_of_polygon[p] for p in polys if p in node_of_polygon]
        else:
            corners = sampled.polygons[list(polys)]
            candidates = [sampled.nodes[i] for i in np.unique(corners[corners >= 0]).tolist()]
        if not candidates and tree is not None:
            candidates = [ids[int(tree.query(pos)[1])]]
        if candidates:
            lengths = [float(np.linalg.norm(np.asarray(graph.nodes[c]["pos"], dtype=float) - pos)) for c in candidates]
            best = int(np.argmin(lengths))
            graph.add_edge(node, candidates[best], weight=lengths[best])
        nodes.append(node)
    return Terminals(nodes=tuple(nodes), openings=detection.openings)


def play_space_piece(mesh: trimesh.Trimesh, graph: nx.Graph, agent: AgentConfig, params: Params) -> trimesh.Trimesh:
    """The faces of ``mesh`` that make the piece ``graph``'s play space is (:func:`g2s_plugins.play_space.play_space_faces`):
    the parts with a face within the snap distance of one of its nodes and those touching them, parts up to
    :data:`_TOUCH_RADII` agent radii apart included; the rays, the outer extent and ``leave_footprint`` read them
    alone, so a backdrop or a skybox apart from the piece hides none of its openings. ``mesh`` itself when no face
    lies that near a node (none was measured: a node stands on the walkable surface). O((F + n) log F + pairs)."""
    footing = np.array([pos for _, pos in graph.nodes(data="pos") if pos is not None], dtype=np.float64)
    s = _settings(params, agent)
    keep = play_space_faces(mesh, footing, s.snap, _TOUCH_RADII * s.radius)
    if not keep.any():
        return mesh
    return trimesh.Trimesh(np.asarray(mesh.vertices), np.asarray(mesh.faces)[keep], process=False)


@hookimpl
def g2s_select_terminals(graph: nx.Graph, params: Params, context: RunContext) -> Terminals:
    """Find the piece's entries/exits, add one terminal node per opening and return them.

    On a navmesh when the run has one; else on the surface the ``sampling`` builder's graph covers
    (:mod:`._sampled_surface`).
    """
    mesh = context.mesh if graph.graph.get(PLAY_POINTS) is None else play_space_piece(context.mesh, graph, context.agent,
                                                                                      params)
    if context.navmesh is not None:
        held = held_navmesh(context.navmesh, graph)
        detection = detect_openings(mesh, held, context.agent, params)
        polygons = tuple(tuple(held.ids[list(polys)].tolist()) for polys in detection.polygons)
        return add_terminals(graph, replace(detection, polygons=polygons), context.navmesh, context.agent)
    stats = graph.graph.get("sampling_stats")
    if not stats or "spacing" not in stats:
        raise PluginError(
            "entry_exit needs the navmesh graph builder or the sampling one (graph: plugin: navmesh or sampling): "
            "the run has no navigation mesh and no sampled surface to take the boundary from"
        )
    surface = sampled_surface(graph, float(stats["spacing"]))
    search = sampled_edge_search(float(stats["spacing"]), float(stats["clearance"]))
    detection = detect_openings(mesh, surface, context.agent, params, search)
    return add_terminals(graph, detection, surface, context.agent)
