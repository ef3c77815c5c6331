"""What most likely parts two walkable areas no walk joins, measured as a designer would measure it: between the
edges of the level's walkable ground, not between the nodes' centres.

The disconnected-areas warning (:mod:`g2s_core.disconnected`) names the cause
between the largest area and the nearest of the others a designer means to
join to it (:func:`joined_areas`: those of at least
:data:`JOINED_AREA_SHARE` of its walkable surface; with none, every area),
with that area's size; both graph builders set ``context.likely_cause`` to
:func:`likely_cause_of` their ground.

*The ground's edges* (:func:`ground_rim`): on the navmesh route, the edges of
the area's navmesh polygons that no polygon of the area lies across, a point
every cell (``cell_size``) along each; on the sampling route, the samples,
each standing for a square of its ``area``. Either surface is eroded: Recast
keeps the agent's centre ``ceil(radius / cell_size)`` cells from walls and
drops, the sampling builder ``clearance`` metres. The level's ground reaches
that far past a navmesh edge, and half the square's side plus the clearance
past a sample, so the gap between two areas' ground is the horizontal
distance of their closest edge points less both reaches. Measured on levels
of known gaps (docs/analysis_quality.md, "The disconnected-areas warning's
gap"): a jump gap of 0.8 m read 9.9-10.6 m between polygon centres, now 1.0 m
on the navmesh route (Recast's cells, 0.25 m, place each edge) and 1.0 m on
the sampling route (each sample stands for a 1 m square).

*The cause* (:func:`likely_cause`): from the vertical step between those
closest edges and the gap, compared with the agent's ``max_climb``,
``height`` and ``max_slope``: separate floors, a step too high to climb
(only when steeper than ``max_slope`` over the gap), or a gap, wall or
passage too narrow. When the closest pair is a floor above another but the
two areas also meet on one floor (a room shut by a narrow door above a
deck), the pair on one floor is named if it is closer with vertical offsets
counted ``height / max_climb`` times: a designer fixes the door, not the
storeys; but a pair on one floor across open air (no floor under it: a
gallery across a nave from another) gives way to the drop when a ramp at
``max_slope`` down it is shorter than a bridge across.

*The place* (:func:`where_between`): along a wall every edge point is about
as close to the other side as any, so the closest pair alone is any of them
(a wall's corner 4 m from the door the agent does not fit). On one floor,
the pairs within a spacing of the closest are tested with rays
(:func:`open_between`): the closest that faces an opening (nothing across at
half the agent's height, ground all along under it) is named, a door or a
plank narrower than the agent; with none, the run of such pairs, a wall or
a chasm, from end to end. Measured on generated rooms parted by a wall 10-30
m long with one door 0.6 or 0.8 m wide, planks over a chasm, and walls and
chasms with no way across (docs/analysis_quality.md, "The place the
disconnected-areas warning names"). *A floor shut inside a closed solid*
(:func:`shut_in`) is read with the sampling builder's rule for closed solids,
each body by its own winding, so that a mesh exported inside out reads as
the same mesh wound right.

*A ceiling lower than the agent* (:func:`low_ceiling`): Recast and the sampling
builder keep no floor under less head room than ``agent.height``, so a plank
over a channel's bed or a low beam across a room parts the floor under it
into two areas whose ground stops either side. On one floor, when nothing
lies across the pair at ``agent.max_climb`` over it (no wall), ground lies
under the stretch between them, and a ray up from that ground meets a face
under the agent's height, the cause is ``head room too low`` with the
ceiling's height over the floor and the floor's place under it; it is asked
before the closed-solid rule, whose rays half the agent's height up run
along a plank's underside 1.0-1.1 m over a bed. On the navmesh route a
ceiling at or a little over the agent's height, under what the navmesh's
height grid needs (:func:`navmesh_head_room`, from its cell height), read
also the agent's radius round the floor between them (Recast erodes round
the cells it drops), is named as head room the navmesh reads as too low when
the floor there is as wide as the agent (docs/analysis_quality.md, "The
warning's head room a little over the agent"). *A smaller area nearer*
(:func:`smaller_nearer`): the areas :func:`joined_areas` leaves out are not
measured for the cause, so a closet behind a thin wall beside the largest
went unnamed; the nearest of them is named after the cause when it comes
nearer than the area measured and within the agent's width. Measured on the
warnings of the levels that warn and the thirty-second round's sewer
(docs/analysis_quality.md, "The disconnected-areas warning's smaller
neighbours and head room").

*A partition hung over the floor* (:func:`hangs_to_the_floor`): a solid whose
underside lies under half the agent's height and which stands up past its
head is a wall to the agent, not a ceiling: the warning names the wall on
either route (the navmesh's edges lie Recast's heights over the floor, and
the climb-high segment from them met a partition 0.45 m up that the one from
the samples passed under). *The gap* a wall leaves (:func:`walled_gap`):
each side's ground stops at the first face across at half the agent's
height, so a sample's square reaches no farther than the wall (docs/
analysis_quality.md, "The disconnected-areas warning's walls, partitions and
fifth-nearest areas").

*A stair the graph builder lost* (:func:`way_up`): floors more than the
agent's height apart are named separate only when no walkable ground climbs
between them near the pair: faces within ``max_slope`` with ``height`` of head
room on vertical lines half the agent's radius apart, each rise between
neighbours at most ``max_climb`` (or two risers a tread between them walks),
from one area's closest edge to the other's, in a disc round the pair grown
until it finds a way or a step, up to ``MAX_WAY_UP_COLUMNS`` lines. Where it does, the cause names the stair or ramp with its width across at its
narrowest and the place (a wedge stair 1.1-1.4 m wide between a wall and a
drop that Recast's erosion and ledge rule take whole: :data:`LEDGE_CELLS`;
a companionway whose treads are shorter than a cell, by its two risers),
or the step over the climb that cuts it (docs/analysis_quality.md, "The
disconnected-areas warning's lost stairs" and "... far stairs and galleries").

Complexity: O(n) for the areas' n nodes (their sizes), O(e log e) for the e
edge points of the joined areas (one k-d tree of the largest's, to bound each
area's gap and rise from below), then a k-d tree per area measured (those
whose bound lies under the answer: :func:`nearest_area`), e = the areas'
polygon perimeter / ``cell_size`` on the navmesh route, their sample count on
the sampling route; with the mesh, O(m log m) for its m faces' closed bodies
and up to 9 rays (18 for the ceiling; on the navmesh route, 24 more a floor
point when it asks again for head room about the agent's) for each of at most
``MAX_PLACE_CANDIDATES`` pairs, 2 for the gap; the smaller areas as the joined
ones; floors apart, :func:`way_up`'s l log l for its l <= ``MAX_WAY_UP_COLUMNS``
lines.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from functools import partial
from typing import NamedTuple

import networkx as nx
import numpy as np
import trimesh
from scipy import sparse
from scipy.sparse.csgraph import breadth_first_order, connected_components, dijkstra
from scipy.spatial import cKDTree
from scipy.spatial.distance import pdist, squareform

from g2s_core.config import AgentConfig
from g2s_core.disconnected import area_summary, xyz
from g2s_core.model import NavMesh
from g2s_plugins._raycasting import (
    COMPASS, EPSILON, GROUND_MARGIN, UP, AgentShape, RayCaster, all_hits_down, closed_solid_holds, has_room, head_room,
)
from g2s_plugins.play_space import node_polygons
from g2s_plugins.recast.settings import voxel_config

Ground = tuple[np.ndarray, np.ndarray, np.ndarray]
"""``(points (k,3), reach (k,), spacing (k,))``, metres: :func:`ground_rim` of an area."""

Rim = Callable[[nx.Graph, Sequence[int]], Ground]
"""``(graph, nodes) -> ground``: :func:`ground_rim` of a graph builder's surface."""

JOINED_AREA_SHARE = 0.1
"""The share of the largest area's walkable surface from which another area is one a designer means to join to it
(:func:`joined_areas`): an island, a floe, a wing cut off. Smaller ones (a floor boxed in a pillar, a crate's top, a
pocket behind props) are left out of the cause's measure, however near, when such an area exists (the nearest is named
after it when within the agent's width: :func:`smaller_nearer`): on ``nav_test.obj`` a floor
of 6 m² boxed in 0.2 m from the largest area would hide the 4.7 m gap between its areas of 1,744 and 895 m²
(docs/analysis_quality.md, "The disconnected-areas warning's nearest area")."""


MAX_PLACE_CANDIDATES = 1024
"""Edge pairs at most that :func:`where_between` tests (more, which takes 256 m of edge points a cell apart all within
a cell of the closest pair, are thinned evenly along the edges)."""

READ_AS_EQUAL = 0.05
"""Metres under which two distances read the same in the warning (half the 0.1 m it prints): a smaller area is named
after the one measured (:func:`smaller_nearer`) when it comes nearer by more, and within the agent's width plus this
(on the sampling route, squares of 1 m, many areas read the same gap of 1.0 m, with float noise either side)."""

GROUND_RAYS = 8
"""Rays at most down onto the stretch between two areas' ground (:func:`open_between`): a half spacing of the edge
points apart (0.125 m on the navmesh route's cells of 0.25 m; 0.5 m between samples 1 m apart) up to this many."""


MAX_WAY_UP_COLUMNS = 65_536
"""Vertical lines at most that :func:`way_up` casts down over the ground round a warning's place (a disc 27 m in
radius, 54 m across, at the presets' 0.25 m spacing holds 36,600: a silo's spiral stair 11.5 m high); a larger disc
is shrunk to this, 36 m in radius at that spacing, as far as the search grows."""

WIDTH_CANDIDATES = 16
"""Points at most of a way's narrowest (by the columns' clearance) whose width :func:`width_across` measures."""

LEDGE_CELLS = 3
"""Cells past twice the erosion from which the navmesh keeps floor on a walkway between a wall and a drop: measured
in the thirty-fifth round (docs/analysis_quality.md, "A thirty-fifth round of level kinds") on a band 20 m long, a
wall on one side and a 3 m drop on the other, turned 0-45 degrees, with the presets' agent (erosion 0.5 m, cells 0.25
m) and ``ledge_filter: drops``: no floor at 1.1-1.2 m, some from 1.6 m, 7 m² or more of its 20 m from 1.8 m (1.75)."""

NEIGHBOURS = np.array([[1, 0], [0, 1], [1, 1], [1, -1]])
"""Grid offsets of :func:`way_up`'s columns linked to each column, one of each opposite pair (eight neighbours)."""


class Closest(NamedTuple):
    """Where two areas' ground comes closest (:func:`closest_step`).

    Attributes:
        gap: metres between the ground's edges, horizontal, at least 0.
        step: metres of rise between the closest edge points.
        pairs: (c, 2, 3) edge points of the first area and the second's nearest to each, metres: the closest pair
            first, then every pair within a spacing of the edge points (a cell; a sample's side) of it, nearer first.
        reach: (c, 2) metres the ground reaches past each point of :attr:`pairs` (:func:`ground_rim`).
        spacing: (c,) metres, the larger spacing of each pair's points along their edges.
    """

    gap: float
    step: float
    pairs: np.ndarray
    reach: np.ndarray
    spacing: np.ndarray

    @property
    def here(self) -> np.ndarray:
        """(3,) the first area's closest edge point."""
        return self.pairs[0, 0]

    @property
    def there(self) -> np.ndarray:
        """(3,) the second area's closest edge point."""
        return self.pairs[0, 1]


def ground_rim(graph: nx.Graph, nodes: Sequence[int], navmesh: NavMesh | None, erosion: float) -> Ground:
    """(k,3) points on the edges of the walkable surface of ``nodes`` (metres), (k,) how far the level's ground
    reaches past each, metres: ``erosion`` past a navmesh polygon's edge, half a square of the node's ``area``
    more past a node without a polygon (a sample; a portal point, area 0), and (k,) how far apart the points lie
    along the edge, metres: ``cell_size`` on a polygon's edge, the side of the node's square.

    A navmesh polygon's edges are those no polygon of ``nodes`` lies across, a point every ``cell_size`` along each
    (its ends included). O(edges + points).
    """
    polygons = node_polygons(graph, nodes) if navmesh is not None else np.full(len(nodes), -1)
    points = np.asarray([graph.nodes[n]["pos"] for n, p in zip(nodes, polygons) if p < 0], dtype=np.float64).reshape(-1, 3)
    spacing = [np.asarray([math.sqrt(float(graph.nodes[n].get("area", 0.0))) for n, p in zip(nodes, polygons) if p < 0])]
    reach = [spacing[0] / 2 + erosion]
    if navmesh is not None and (held := np.unique(polygons[polygons >= 0])).size:
        corners = np.asarray(navmesh.polygons)[held]
        valid = corners >= 0
        rows, column = np.nonzero(valid)
        beyond = np.asarray(navmesh.neighbours)[held][rows, column]
        rows, column = rows[~np.isin(beyond, held)], column[~np.isin(beyond, held)]
        vertices = np.asarray(navmesh.vertices, dtype=np.float64)
        start = vertices[corners[rows, column]]
        end = vertices[corners[rows, (column + 1) % valid.sum(axis=1)[rows]]]
        cell = float(navmesh.settings["cell_size"])
        count = np.ceil(np.linalg.norm(end - start, axis=1) / cell).astype(np.int64) + 1
        edge = np.repeat(np.arange(len(start)), count)
        along = (np.arange(len(edge)) - np.repeat(np.cumsum(count) - count, count)) / (count[edge] - 1)
        points = np.concatenate([points, start[edge] + along[:, None] * (end - start)[edge]])
        reach.append(np.full(len(edge), erosion))
        spacing.append(np.full(len(edge), cell))
    return points, np.concatenate(reach), np.concatenate(spacing)


def closest_step(a: Ground, b: Ground, climb_weight: float = 1.0, window: float | None = None) -> Closest:
    """Where the edges of two areas' ground, each its :func:`ground_rim`, come closest (vertical offsets counted
    ``climb_weight`` times): the gap is the closest points' horizontal distance less the ground's reach past each;
    the pairs within ``window`` metres of the closest (None: the points' spacing) with it.
    O((ka + kb) log kb) for their ka and kb points (a k-d tree of b's)."""
    (pa, ra, sa), (pb, rb, sb) = a, b
    scale = np.array([1.0, climb_weight, 1.0])
    distance, index = cKDTree(pb * scale).query(pa * scale)
    best = int(np.argmin(distance))
    there = int(index[best])
    offset = pb[there] - pa[best]
    gap = float(np.hypot(offset[0], offset[2])) - float(ra[best]) - float(rb[there])
    near = np.flatnonzero(distance <= distance[best] + (max(float(sa[best]), float(sb[there])) if window is None else window))
    if len(near) > MAX_PLACE_CANDIDATES:
        near = np.union1d(near[:: math.ceil(len(near) / MAX_PLACE_CANDIDATES)], [best])
    near = near[np.argsort(distance[near], kind="stable")]  # the closest first: argmin's, the first of equals
    return Closest(max(gap, 0.0), float(abs(offset[1])), np.stack([pa[near], pb[index[near]]], axis=1),
                   np.stack([ra[near], rb[index[near]]], axis=1), np.maximum(sa[near], sb[index[near]]))


def closest_step_for(a: Ground, b: Ground, agent: AgentConfig, window: float | None = None,
                     caster: RayCaster | None = None) -> Closest:
    """:func:`closest_step`, or the closest pair on one floor when the plain one is a floor above another and the
    one-floor pair is closer with vertical offsets counted ``agent.height / agent.max_climb`` times.

    With the mesh's ``caster``, a one-floor pair across open air (no ground under the stretch between them within the
    climb of their heights, :func:`floor_between`: no door's or plank's floor) gives way to the plain pair when a ramp
    at ``agent.max_slope`` down the drop (its plan run, plus the plain pair's gap) is shorter than a bridge across
    the gap: a gallery over its aisle is reached up from the aisle, not across the nave from the other gallery,
    while a roof 2 m across a street from another stays a gap to bridge (docs/analysis_quality.md, "The
    disconnected-areas warning's far stairs and galleries"). Two rays and up to ``GROUND_RAYS`` more."""
    plain = closest_step(a, b, window=window)
    climb = float(agent.max_climb)
    if plain.step <= climb or climb <= 0:
        return plain
    weighted = closest_step(a, b, float(agent.height) / climb, window)
    if weighted.step > climb:
        return plain
    if caster is not None:
        ramp = plain.gap + plain.step / math.tan(math.radians(float(agent.max_slope)))
        first = Closest(weighted.gap, weighted.step, weighted.pairs[:1], weighted.reach[:1], weighted.spacing[:1])
        if ramp < weighted.gap and not floor_between(caster, first, agent, climb).on_ground.any():
            return plain
    return weighted


def stretch_under(closest: Closest, start: np.ndarray, end: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(owner (r,), points (r,3))``: the middles of up to ``GROUND_RAYS`` equal parts of the stretch between two
    areas' ground along each segment from ``start`` (c,3) to ``end`` (c,3) (a pair of :attr:`Closest.pairs` raised),
    past each point's reach (plan distances: the reach is horizontal), each part at most half the pair's spacing long
    (the stretch's middle where the reaches overlap), and the pair each belongs to. O(c + r)."""
    plan = np.hypot(*(end - start)[:, [0, 2]].T)
    lo = np.minimum(closest.reach[:, 0] / np.maximum(plan, 1e-12), 0.5)
    hi = np.maximum(1 - closest.reach[:, 1] / np.maximum(plan, 1e-12), 0.5)
    parts = np.clip(np.ceil((hi - lo) * plan / np.maximum(closest.spacing / 2, EPSILON)), 1, GROUND_RAYS).astype(np.int64)
    owner = np.repeat(np.arange(len(start)), parts)
    part = np.arange(len(owner)) - np.repeat(np.cumsum(parts) - parts, parts)
    along = lo[owner] + (hi - lo)[owner] * (part + 0.5) / parts[owner]
    return owner, start[owner] + along[:, None] * (end - start)[owner]


def grounded(closest: Closest, owner: np.ndarray, ground: np.ndarray, agent: AgentConfig) -> np.ndarray:
    """(r,) bool: each ground height (r,) (``-inf``: none) lies within ``agent.max_climb`` of its pair's two points'
    heights (``owner`` (r,): the pair of :attr:`Closest.pairs`): a floor the agent would walk on between them."""
    heights, climb = closest.pairs[owner, :, 1], float(agent.max_climb)
    return (ground >= heights.min(axis=1) - climb) & (ground <= heights.max(axis=1) + climb)


class FloorBetween(NamedTuple):
    """What :func:`floor_between` finds between the two points of each of c pairs, lifted a height.

    Attributes:
        runs_on: (c,) bool: the straight segment between the lifted points meets no face and every ground point under
            the stretch between them is :func:`grounded`.
        owner: (r,) the pair of each ground point.
        floor: (r, 3) the first face down from the lifted segment at the middles of :func:`stretch_under`, metres
            (y ``-inf`` where nothing lies under it).
        on_ground: (r,) bool, :func:`grounded`.
    """

    runs_on: np.ndarray
    owner: np.ndarray
    floor: np.ndarray
    on_ground: np.ndarray


def floor_between(caster: RayCaster, closest: Closest, agent: AgentConfig, lift: float) -> FloorBetween:
    """:class:`FloorBetween` for :attr:`Closest.pairs` lifted ``lift`` metres: one ray along each segment (up, where
    a pair stands on one plan point: its ground test alone decides) and one down at each middle of
    :func:`stretch_under`, at most 1 + ``GROUND_RAYS`` rays a pair."""
    pairs = closest.pairs
    start, end = pairs[:, 0] + lift * UP, pairs[:, 1] + lift * UP
    length = np.linalg.norm(end - start, axis=1)
    owner, floor = stretch_under(closest, start, end)
    across, down = caster.first_hits_of([(start, np.where(length[:, None] > 0, end - start, UP)), (floor, -UP)])
    floor[:, 1] -= down.distance
    on_ground = grounded(closest, owner, floor[:, 1], agent)
    runs_on = ((length == 0) | (across.distance >= length)) & (np.bincount(owner, weights=~on_ground, minlength=len(pairs)) == 0)
    return FloorBetween(runs_on, owner, floor, on_ground)


def open_between(caster: RayCaster, closest: Closest, agent: AgentConfig) -> np.ndarray:
    """(c,) bool: each pair of :attr:`Closest.pairs` faces an opening: the straight segment between the two points
    raised half the agent's height meets no face (a wall, not a door), and ground lies under the stretch between
    the two areas' ground (:func:`stretch_under`) within ``agent.max_climb`` of the two points' heights (a plank
    or a doorway's floor; not a chasm, nor a sill): the first face down from the raised segment
    (:func:`floor_between`). At most 1 + ``GROUND_RAYS`` rays a pair.
    """
    return floor_between(caster, closest, agent, 0.5 * float(agent.height)).runs_on


class LowCeiling(NamedTuple):
    """A ceiling lower than the agent, or than the navmesh needs, over the floor between two areas
    (:func:`low_ceiling`).

    Attributes:
        head_room: metres from the floor up to the ceiling, under the head room asked.
        floor: (3,) the floor's point under it, metres.
        gap: metres between the two areas' ground there (the pair's plan distance less their reach).
    """

    head_room: float
    floor: np.ndarray
    gap: float


def low_ceiling(caster: RayCaster, closest: Closest, agent: AgentConfig, under: float | None = None,
                beside: float = 0.0) -> LowCeiling | None:
    """The ceiling lower than ``under`` (metres; None: the agent's height) that parts two areas on one floor, if one
    does: for the closest of :attr:`Closest.pairs` (nearer first) whose floor runs on between them, the lowest head
    room over it.

    A pair's floor runs on when the segment between its two points raised ``agent.max_climb`` (over what the agent
    steps on, under a beam or a plank) meets no face, a wall's, and the first face down from it at the middles of
    the stretch between their ground (:func:`stretch_under`) is ground within ``agent.max_climb`` of the two points
    (:func:`grounded`); the head room is how far a ray up from each such ground point (``EPSILON`` over it) goes,
    and the pair is parted by a ceiling when the least is under ``under`` (and, when that is over the agent's height,
    not under the agent's height: the head room read as too low is about the agent's height): Recast and the sampling builder
    keep no floor with less head room than ``agent.height``, so the two areas' ground stops either side of it (a
    plank over a channel's bed, a beam across a room), and the navmesh none with less than
    :func:`navmesh_head_room` on some floors. With ``beside`` (metres), the ground that far round each such point
    (:func:`floor_beside`) is read too. None when no pair is. 1 + 2 ``GROUND_RAYS`` rays a pair at most, 24 times
    more with ``beside``.
    """
    pairs = closest.pairs
    runs_on, owner, floor, on_ground = floor_between(caster, closest, agent, float(agent.max_climb))
    if beside > 0:
        owner, floor, on_ground = floor_beside(caster, closest, agent, owner, floor, on_ground, beside)
    room = np.full(len(floor), np.inf)
    room[on_ground] = caster.first_hits(floor[on_ground] + EPSILON * UP, UP).distance + EPSILON
    lowest = np.full(len(pairs), np.inf)
    np.minimum.at(lowest, owner, room)
    walled = np.bincount(owner, weights=hangs_to_the_floor(caster, floor, room, agent), minlength=len(pairs)) > 0
    height = float(agent.height)
    low = runs_on & ~walled & ~has_room(lowest, height if under is None else under)
    if under is not None and under > height:  # about the agent's height: not over a pair with a table beside it
        low &= has_room(lowest, height)
    if not low.any():
        return None
    chosen = int(np.argmax(low))  # the first, the closest, under a ceiling
    under = np.flatnonzero(owner == chosen)
    at = under[int(np.argmin(room[under]))]
    plan = float(np.hypot(*(pairs[chosen, 1] - pairs[chosen, 0])[[0, 2]]))
    return LowCeiling(float(room[at]), floor[at], max(plan - float(closest.reach[chosen].sum()), 0.0))


def floor_beside(caster: RayCaster, closest: Closest, agent: AgentConfig, owner: np.ndarray, floor: np.ndarray,
                 on_ground: np.ndarray, reach: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(owner, floor, on_ground)`` of :class:`FloorBetween` with, for each ground point, the ground ``reach`` metres
    from it along the eight :data:`~g2s_plugins._raycasting.COMPASS` headings where nothing lies across at
    ``agent.max_climb`` over it (the floor runs on to there; not a counter's or wall's side), found and tested as
    :func:`floor_between`'s: Recast erodes the agent's radius round every cell it keeps no floor on, so an aisle
    whose middle has open sky is cut by awnings' edges read too low on either side of it. Three rays a heading."""
    start = np.repeat(floor[on_ground] + float(agent.max_climb) * UP, len(COMPASS), axis=0)
    heading = np.tile(COMPASS, (int(on_ground.sum()), 1))
    clear = caster.first_hits(start, heading).distance >= reach
    near = owner[on_ground].repeat(len(COMPASS))[clear]
    points = start[clear] + reach * heading[clear]
    points[:, 1] -= caster.first_hits(points, -UP).distance
    return (np.concatenate([owner, near]), np.concatenate([floor, points]),
            np.concatenate([on_ground, grounded(closest, near, points[:, 1], agent)]))


def navmesh_head_room(settings: dict) -> float:
    """Metres of head room under which a navmesh built with ``settings`` (:func:`g2s_plugins.recast.resolve_settings`'s,
    as :attr:`NavMesh.settings <g2s_plugins.recast.NavMesh.settings>` keeps them) may keep no floor over a flat floor:
    Recast reads head room in cells of ``cell_height``, and over a floor a fraction ``a`` (0 <= a < 1) of a cell over a
    cell boundary the gap is floor(a + head room / cell_height) - 1 cells; the low-height filter keeps a gap of
    ``walkableHeight`` cells (a cell more with ``head_room: recast``), so a flat floor is walked from
    (``walkableHeight`` + 1 - a) cells (+ 1), and a head room under ``walkableHeight`` + 1 (+ 1) cells is cut where
    the floor lies on a boundary (docs/navmesh.md, "Head room a little over the agent's height": 2.125 m on
    ``map_analysis``'s 0.125 m cells, 2.05 m on ``map_piece``'s 0.05 m)."""
    voxels = voxel_config(settings)
    kept = voxels["walkableHeight"] + (1 if settings["recast_head_room"] else 0)
    return float((kept + 1) * voxels["ch"])


def hangs_to_the_floor(caster: RayCaster, floor: np.ndarray, room: np.ndarray, agent: AgentConfig) -> np.ndarray:
    """(r,) bool: over each floor point (r,3) a solid whose underside lies ``room`` (r,) metres up, under half the
    agent's height (where :func:`open_between` tests for walls), stands up past the agent's height (its top, one ray
    further up from inside it): a partition hung over the floor, a wall to the agent, not a ceiling to raise. A plank
    over a channel's bed or a beam is a slab whose top lies under the agent's head. One ray a point so low."""
    low = np.flatnonzero(room < 0.5 * float(agent.height))
    hangs = np.zeros(len(floor), dtype=bool)
    inside = floor[low] + (room[low] + EPSILON)[:, None] * UP
    hangs[low] = room[low] + EPSILON + caster.first_hits(inside, UP).distance >= float(agent.height)
    return hangs


def walled_gap(caster: RayCaster, closest: Closest, agent: AgentConfig) -> float:
    """:attr:`Closest.gap` with each side's reach cut where the segment between the closest pair's points raised half
    the agent's height (where :func:`open_between` tests for walls) first meets a face from that side: ground does
    not reach through a wall. A sample's square (half its side and the clearance past it) reaches across a wall
    0.3 m thick, so the gap read 0.0 m on the sampling route; Recast's eroded edges lie the erosion or more from a
    wall, so the navmesh route's gap stays. Two rays."""
    start, end = closest.pairs[0] + 0.5 * float(agent.height) * UP
    plan, length = float(np.hypot(*(end - start)[[0, 2]])), float(np.linalg.norm(end - start))
    if plan == 0:
        return closest.gap
    forth, back = caster.first_hits_of([(start[None], end - start), (end[None], start - end)])
    reach = np.minimum(closest.reach[0], np.array([forth.distance[0], back.distance[0]]) * plan / length)
    return max(plan - float(reach.sum()), 0.0)


def where_between(caster: RayCaster, closest: Closest, agent: AgentConfig) -> str:
    """Where two areas on one floor nearly meet, as the warning names it: ``e.g. between (x, y, z m) and (x, y, z m)``
    for the closest of the pairs (:attr:`Closest.pairs`) that faces an opening (:func:`open_between`: a door or
    plank too narrow for the agent); else ``along L m from (x, y, z m) to (x, y, z m)``, the run of a wall or
    chasm: the pairs' middles linked to the closest pair's through middles less than the agent's width apart past
    the pairs' spacing (a break in the run too narrow for the agent), and of those the two farthest apart in plan;
    the closest pair when those lie within the agent's width.
    Among pairs about as close (the points along a wall) the closest alone is any of them.
    O(c²) for the c <= ``MAX_PLACE_CANDIDATES`` pairs, and :func:`open_between`'s rays.
    """
    pairs, width = closest.pairs, 2 * float(agent.radius)
    opening = open_between(caster, closest, agent)
    chosen = int(np.argmax(opening))  # the first, the closest, that faces one
    if not opening[chosen]:
        middles = pairs.mean(axis=1)
        apart = squareform(pdist(middles[:, [0, 2]]))
        linked = apart < width + closest.spacing.max()
        run = breadth_first_order(sparse.csr_matrix(linked), 0, return_predecessors=False)
        within = apart[np.ix_(run, run)]
        first, last = run[np.array(np.unravel_index(int(np.argmax(within)), within.shape))]
        if apart[first, last] >= width:
            return f"along {apart[first, last]:.1f} m from ({xyz(middles[first])}) to ({xyz(middles[last])})"
    return between(pairs[chosen])


class WayUp(NamedTuple):
    """Walkable ground that climbs from one area's height to the other's (:func:`way_up`).

    Attributes:
        width: metres across it at its narrowest along the widest way (twice the farthest its middle keeps from an
            edge, a wall or a drop, plus a column's spacing).
        narrowest: (3,) a point of it that narrow, the nearest to the warning's pair, metres.
        risers: metres, 0 when the way is walked column to column; else the largest rise between neighbouring
            columns it needs that only its treads walk (:func:`walked_by_treads`: two risers between two columns).
    """

    width: float
    narrowest: np.ndarray
    risers: float = 0.0


class StepUp(NamedTuple):
    """The lowest step higher than ``agent.max_climb`` between the ground reached from each area (:func:`way_up`).

    Attributes:
        rise: metres, over ``agent.max_climb`` and at most ``agent.height``.
        foot: (3,) the ground at its foot, metres.
    """

    rise: float
    foot: np.ndarray


class GroundColumns(NamedTuple):
    """Walkable ground on a grid of vertical lines (:func:`ground_columns`).

    Attributes:
        points: (n, 3) ground points, metres: crossings with faces within ``agent.max_slope`` that leave
            ``agent.height`` of head room.
        cell: (n, 2) int64, each point's grid column.
        spacing: metres between neighbouring columns.
    """

    points: np.ndarray
    cell: np.ndarray
    spacing: float


def ground_columns(caster: RayCaster, centre: np.ndarray, radius: float, low: float, high: float,
                   agent: AgentConfig) -> GroundColumns:
    """The walkable ground between heights ``low`` and ``high`` (metres) on vertical lines half ``agent.radius``
    apart (the navmesh's cells for the presets' agent; under the 0.28 m tread of a stair) in a disc of ``radius``
    round ``centre`` (3,) (shrunk to :data:`MAX_WAY_UP_COLUMNS` lines). One multiple-hit query over the lines and
    one ray up from each crossing kept (:func:`~g2s_plugins._raycasting.head_room`)."""
    spacing = float(agent.radius) / 2
    radius = min(radius, spacing * math.sqrt(MAX_WAY_UP_COLUMNS / math.pi))
    reach = int(math.ceil(radius / spacing))
    grid = np.stack(np.meshgrid(np.arange(-reach, reach + 1), np.arange(-reach, reach + 1), indexing="ij"), -1).reshape(-1, 2)
    grid = grid[np.hypot(*grid.T) * spacing <= radius]
    column, points, face = all_hits_down(caster, centre[[0, 2]] + grid * spacing, high + float(agent.height) + 1.0)
    kept = caster.walkable_faces(face, float(agent.max_slope)) & (points[:, 1] >= low) & (points[:, 1] <= high)
    kept[kept] = head_room(caster, points[kept], AgentShape.from_config(agent))
    return GroundColumns(points[kept], grid[column[kept]], spacing)


def column_links(ground: GroundColumns, caster: RayCaster, agent: AgentConfig) -> tuple[np.ndarray, np.ndarray]:
    """``(a, b)`` (e,) indices of the ground points on neighbouring columns (eight neighbours) with nothing across
    the level segment between them at the agent's knee (:attr:`AgentShape.body`: over its step) over the higher of
    the two (a wall's face; not the riser between them), every such pair whatever the rise between them. One ray a
    pair."""
    cell = ground.cell
    span = int(np.abs(cell).max(initial=0)) + 2  # a neighbour's key stays inside the grid's encoding
    columns, column = np.unique((cell[:, 0] + span) * (2 * span + 1) + cell[:, 1] + span, return_inverse=True)
    column = column.ravel()
    order = np.argsort(column, kind="stable")
    count = np.bincount(column, minlength=len(columns))
    start = np.cumsum(count) - count
    pairs = []
    for offset in NEIGHBOURS:
        wanted = (cell[:, 0] + offset[0] + span) * (2 * span + 1) + cell[:, 1] + offset[1] + span
        found = np.minimum(np.searchsorted(columns, wanted), len(columns) - 1)
        there = np.where(columns[found] == wanted, found, -1)
        for layer in range(int(count.max(initial=0))):
            has = (there >= 0) & (count[np.maximum(there, 0)] > layer)
            a = np.flatnonzero(has)
            pairs.append(np.stack([a, order[start[there[a]] + layer]], 1))
    a, b = np.concatenate(pairs or [np.zeros((0, 2), np.int64)]).T
    start_points, end_points = ground.points[a].copy(), ground.points[b].copy()
    start_points[:, 1] = end_points[:, 1] = np.maximum(start_points[:, 1], end_points[:, 1]) + AgentShape.from_config(agent).body[0]
    length = np.linalg.norm(end_points - start_points, axis=1)
    clear = caster.first_hits(start_points, end_points - start_points).distance >= length
    return a[clear], b[clear]


def width_across(caster: RayCaster, points: np.ndarray, agent: AgentConfig, spacing: float) -> np.ndarray:
    """(n,) metres across the walkable ground at each point (n,3): along each of four horizontal axes (45 degrees
    apart, :data:`~g2s_plugins._raycasting.COMPASS`), the distance each way to its edge, summed, the least of the
    four: a band's width, up to 1 / cos(22.5°) = 8 % over at the worst heading. An edge is where a ray at the
    agent's knee meets a face (a wall) or a probe down, every quarter ``spacing`` out to eight agent radii, finds
    no ground within ``agent.max_climb`` of the point's height (a drop); the probes a quarter spacing apart place it
    to an eighth of a spacing (0.03 m at the presets'). 8 (1 + 32 / spacing × radius) rays a point."""
    knee = AgentShape.from_config(agent).body[0]
    step = spacing / 4
    along = np.arange(1, int(math.ceil(8 * float(agent.radius) / step)) + 1) * step
    count, directions = len(points), len(COMPASS)
    origins = np.repeat(points + knee * UP, directions, axis=0)
    heading = np.tile(COMPASS, (count, 1))
    wall = caster.first_hits(origins, heading).distance
    probes = (origins[:, None, :] + along[None, :, None] * heading[:, None, :]).reshape(-1, 3)
    ground = probes[:, 1] - caster.first_hits(probes, -UP).distance
    level = np.repeat(np.repeat(points[:, 1], directions), len(along))
    off = (np.abs(ground - level) > float(agent.max_climb)).reshape(-1, len(along))
    drop = np.where(off.any(axis=1), along[np.argmax(off, axis=1)] - step / 2, np.inf)
    reach = np.minimum(wall, drop).reshape(count, directions)
    return (reach[:, : directions // 2] + reach[:, directions // 2:]).min(axis=1)


def walked_by_treads(caster: RayCaster, start: np.ndarray, end: np.ndarray, agent: AgentConfig) -> np.ndarray:
    """(e,) bool: each pair of neighbouring columns' ground points ``start`` (e,3) and ``end`` (e,3) is walked along
    its treads: probes down at a quarter, half and three quarters of the way (from the agent's knee over the higher
    end, where :func:`column_links` found nothing across) each meet a face within ``agent.max_slope``, and each rise
    from point to point along the five is at most ``agent.max_climb``. A stair whose treads are shorter than the
    columns' spacing (a ship's companionway: treads 0.13-0.19 m deep, risers 0.20-0.24 m) puts two risers between
    two columns, over the climb, and a probe on the tread between them reads each; a single step over the climb, or
    a face steeper than the agent walks, leaves a rise over the climb or an unwalkable probe. Three rays a pair."""
    count = len(start)
    if count == 0:
        return np.zeros(0, dtype=bool)
    along = np.array([0.25, 0.5, 0.75])
    probes = (start[:, None, :] + along[None, :, None] * (end - start)[:, None, :]).reshape(-1, 3)
    probes[:, 1] = np.repeat(np.maximum(start[:, 1], end[:, 1]), len(along)) + AgentShape.from_config(agent).body[0]
    hits = caster.first_hits(probes, -UP)
    heights = (probes[:, 1] - hits.distance).reshape(count, len(along))
    walkable = caster.walkable_faces(hits.face, float(agent.max_slope)).reshape(count, len(along)).all(axis=1)
    profile = np.column_stack([start[:, 1], heights, end[:, 1]])
    return walkable & (np.abs(np.diff(profile, axis=1)) <= float(agent.max_climb)).all(axis=1)


def way_up(caster: RayCaster, closest: Closest, agent: AgentConfig) -> WayUp | StepUp | None:
    """:func:`way_up_within` a disc round the pair's middle whose radius is twice the run of a slope at
    ``agent.max_slope`` up the step plus twice the agent's height (a silo's spiral stair 11.5 m high: 27 m, 54 m
    across), grown twice over while it finds neither a way nor a step, up to :data:`MAX_WAY_UP_COLUMNS` lines (36 m
    at the presets' spacing): the closest pair of two decks lies anywhere along their edges, the stair between them
    where the designer put it (a tween deck's hull side 11 m from its companionway; docs/analysis_quality.md, "The
    disconnected-areas warning's far stairs and galleries")."""
    most = float(agent.radius) / 2 * math.sqrt(MAX_WAY_UP_COLUMNS / math.pi)
    radius = min(2 * closest.step / math.tan(math.radians(float(agent.max_slope))) + 2 * float(agent.height), most)
    while (found := way_up_within(caster, closest, agent, radius)) is None and radius < most:
        radius = min(2 * radius, most)
    return found


def way_up_within(caster: RayCaster, closest: Closest, agent: AgentConfig, radius: float) -> WayUp | StepUp | None:
    """Whether walkable ground climbs between two areas a floor or more apart (:attr:`Closest.step` over the
    agent's height) near where they come closest, as the agent would walk it: ground on faces within
    ``agent.max_slope`` with ``agent.height`` of head room (:func:`ground_columns`), each rise between neighbouring
    columns at most the agent's climb (or its slope over their distance) with nothing across at its knee
    (:func:`column_links`), from the lower area's closest edge point (within its ground's reach) to the upper's.

    A :class:`WayUp` when it does (a stair or ramp the graph builder lost: a wedge stair between a wall and a drop
    that the navmesh's erosion takes whole); else a :class:`StepUp` when the ground reached from each side meets at
    a rise over the climb and within the agent's height (a flight cut by a step too high); else None (no stair: a
    floor over another, a ramp steeper than the agent climbs, a ladder's rungs, with no head room between them).

    The ground searched is a disc of ``radius`` metres round the pair's middle. A rise over the climb between
    neighbouring columns is walked when its treads are (:func:`walked_by_treads`). O(l log l) for its l columns
    (:data:`MAX_WAY_UP_COLUMNS`), one ray a ground point up and one a neighbouring pair across, three more a pair
    whose rise is over what the agent walks and within its height.
    """
    lower, upper = sorted(closest.pairs[0], key=lambda point: point[1])
    reach_lower, reach_upper = closest.reach[0] if closest.pairs[0, 0, 1] <= closest.pairs[0, 1, 1] else closest.reach[0, ::-1]
    climb, height = float(agent.max_climb), float(agent.height)
    tolerance = climb + GROUND_MARGIN  # the navmesh's edges lie up to Recast's cells over the ground
    ground = ground_columns(caster, (lower + upper) / 2, radius, float(lower[1]) - tolerance, float(upper[1]) + tolerance, agent)
    if len(ground.points) == 0:
        return None
    a, b = column_links(ground, caster, agent)
    plan = np.hypot(*(ground.points[b] - ground.points[a])[:, [0, 2]].T)
    rise = np.abs(ground.points[b, 1] - ground.points[a, 1])
    walked = rise <= AgentShape.from_config(agent).max_rise(plan)
    treads = ~walked & (rise <= height)
    treads[treads] = walked_by_treads(caster, ground.points[a[treads]], ground.points[b[treads]], agent)
    n = len(ground.points)
    stepwise = walked.copy()  # the links walked column to column, before the treads' own
    walked |= treads
    links = sparse.coo_matrix((plan[walked], (a[walked], b[walked])), shape=(n, n)).tocsr()
    _, component = connected_components(links, directed=False)

    def near(point: np.ndarray, reach: float) -> np.ndarray:
        return ((np.hypot(*(ground.points - point)[:, [0, 2]].T) <= reach + 2 * ground.spacing)
                & (np.abs(ground.points[:, 1] - point[1]) <= tolerance))

    start, end = near(lower, float(reach_lower)), near(upper, float(reach_upper))
    joined = np.intersect1d(component[start], component[end])
    if joined.size == 0:
        step = np.isin(component[a], component[start]) & np.isin(component[b], component[end])
        step |= np.isin(component[b], component[start]) & np.isin(component[a], component[end])
        step &= (rise > climb) & (rise <= height)
        if not step.any():
            return None
        k = np.flatnonzero(step)[int(np.argmin(rise[step]))]
        foot = ground.points[a[k]] if ground.points[a[k], 1] < ground.points[b[k], 1] else ground.points[b[k]]
        return StepUp(float(rise[k]), foot)
    # the farthest each point keeps from an edge (a point with fewer than eight walked neighbours), along the links
    degree = np.bincount(a[walked], minlength=n) + np.bincount(b[walked], minlength=n)
    edge = np.flatnonzero(degree < 2 * len(NEIGHBOURS))
    inward = dijkstra(links, directed=False, indices=edge, min_only=True) if edge.size else np.full(n, np.inf)
    # the way's narrowest lies on its climb, between the two areas' heights, not on their own floors
    inward[(ground.points[:, 1] <= lower[1] + tolerance) | (ground.points[:, 1] >= upper[1] - tolerance)] = np.inf
    # the widest way: the largest clearance whose points still join the two sides
    levels = np.unique(inward[np.isfinite(inward)])[::-1]
    for level in levels:
        keep = inward >= level
        _, part = connected_components(links[keep][:, keep], directed=False)
        inside = np.full(n, -1)
        inside[keep] = part
        if np.intersect1d(inside[start], inside[end]).size:
            break
    else:
        level = np.inf
    # the risers only the treads walk, when the way needs them (the two sides part without)
    needed = treads & np.isin(component[a], joined)
    risers = 0.0
    if needed.any():
        steps = sparse.coo_matrix((plan[stepwise], (a[stepwise], b[stepwise])), shape=(n, n)).tocsr()
        _, by_step = connected_components(steps, directed=False)
        if not np.intersect1d(by_step[start], by_step[end]).size:
            risers = float(rise[needed].max())
    if not np.isfinite(level):  # the two areas' ground meets: no way between them to measure
        return WayUp(math.inf, ground.points[np.flatnonzero(start)[0]], risers)
    # of the way's narrowest columns, the nearest the warning's pair, measured across by rays: the columns'
    # clearance places it to a spacing or two either side
    way = np.flatnonzero(np.isin(inside, np.intersect1d(inside[start], inside[end])) & (inward == level))
    way = way[np.argsort(np.linalg.norm(ground.points[way] - (lower + upper) / 2, axis=1), kind="stable")[:WIDTH_CANDIDATES]]
    # rays along a stair's run meet its risers at the knee and read its treads' fall as a drop, so a flight's width
    # is at least what the columns' clearance along the walked links gives (they follow the treads)
    width = np.maximum(width_across(caster, ground.points[way], agent, ground.spacing), 2 * level + ground.spacing)
    chosen = int(np.argmin(width))
    return WayUp(float(width[chosen]), ground.points[way[chosen]], risers)


def way_up_cause(found: WayUp | StepUp, agent: AgentConfig, kept_width: float | None) -> str:
    """The warning's cause for what :func:`way_up` found: the step, or the stair or ramp with its width at its
    narrowest and where (a stair whose treads alone walk it, :attr:`WayUp.risers`: its two risers a cell), against
    the agent's width and, on the navmesh route, ``kept_width`` (metres: the least walkway between a wall and a drop
    that the navmesh keeps floor on; None on the sampling route)."""
    if isinstance(found, StepUp):
        return f"{likely_cause(found.rise, 0.0, agent)}, at ({xyz(found.foot)})"
    radius = float(agent.radius)
    width = "" if math.isinf(found.width) else f" about {found.width:.1f} m wide at its narrowest"
    if found.width < 2 * radius:
        return (f"a stair or ramp between them narrower than the agent ({width.strip()}; "
                f"agent.radius {radius:g} m), at ({xyz(found.narrowest)})")
    if found.risers > 0:  # the graph's cells or probes, as the columns, read two risers as one step
        return (f"a stair between them{width} whose treads are shorter than a cell (agent.radius / 2, "
                f"{radius / 2:g} m): neighbouring cells' ground differs by two risers, about {found.risers:.2f} m, over "
                f"agent.max_climb ({float(agent.max_climb):g} m), at ({xyz(found.narrowest)})")
    if kept_width is None:
        return (f"a stair or ramp between them{width} that the sampled graph does not walk for this agent "
                f"(agent.radius {radius:g} m, agent.max_climb {float(agent.max_climb):g} m), at ({xyz(found.narrowest)})")
    if found.width < kept_width:
        return (f"a stair or ramp between them{width}, narrower than the navmesh keeps for this agent (agent.radius "
                f"{radius:g} m; beside a drop the navmesh keeps floor from about {kept_width:.1f} m), "
                f"at ({xyz(found.narrowest)})")
    return (f"a stair or ramp between them{width} that the navmesh keeps no floor on for this agent "
            f"(agent.radius {radius:g} m), at ({xyz(found.narrowest)})")


def between(pair: np.ndarray) -> str:
    """``e.g. between (x, y, z m) and (x, y, z m)`` for a pair of points (2,3)."""
    return f"e.g. between ({xyz(pair[0])}) and ({xyz(pair[1])})"


def likely_cause(step: float, gap: float, agent: AgentConfig) -> str:
    """What most likely separates two areas whose ground's closest edges are ``gap`` m apart with a ``step`` m
    rise between them."""
    climb, height, radius = float(agent.max_climb), float(agent.height), float(agent.radius)
    if step > height:
        return (f"separate floors ({step:.1f} m apart) with no walkable stairs or ramp between them "
                f"for this agent (agent.max_climb {climb:g} m, agent.max_slope {float(agent.max_slope):g}°)")
    # a rise the agent would walk up as a slope over the gap (islands 18 m apart, 0.6 m in height) is no step
    if step > climb and step > gap * math.tan(math.radians(float(agent.max_slope))):
        return f"a step of about {step:.1f} m, higher than agent.max_climb ({climb:g} m)"
    return (f"a gap or passage too narrow for the agent (agent.radius {radius:g} m), or a wall, where their "
            f"ground lies about {gap:.1f} m apart")


def joined_areas(graph: nx.Graph, largest: Sequence[int], others: Sequence[Sequence[int]]) -> list[int]:
    """Indices of the areas of ``others`` (node lists of areas of ``graph``) that a designer means to join to
    ``largest``: those of at least :data:`JOINED_AREA_SHARE` of its walkable surface (m²); with none, every one, as
    all that is cut off from one large area is then small (a collision hull's floor beside a square: that floor,
    not the next in size). O(nodes)."""
    least = JOINED_AREA_SHARE * area_summary(graph, largest)[0]
    joined = [k for k, other in enumerate(others) if area_summary(graph, other)[0] >= least]
    return joined or list(range(len(others)))


def edge_distances(ground: Ground, others: Sequence[Ground]) -> np.ndarray:
    """(n,) metres: how near each of ``others`` (each its :func:`ground_rim`) comes ``ground`` by the straight-line
    distance of edge points. One k-d tree of ``ground``'s k points queried with the others' e points, O((k + e) log k)."""
    owner = np.repeat(np.arange(len(others)), [len(other[0]) for other in others])
    distance = np.full(len(others), np.inf)
    np.minimum.at(distance, owner, cKDTree(ground[0]).query(np.concatenate([other[0] for other in others]))[0])
    return distance


def nearest_area(ground: Ground, grounds: Sequence[Ground], areas: Sequence[Sequence[int]],
                 agent: AgentConfig, caster: RayCaster | None = None) -> tuple[Closest, Sequence[int]]:
    """Of ``areas`` (node lists, ``grounds`` their ground), the one whose ground comes nearest ``ground`` (gap and
    rise, :func:`closest_step_for`), with its :class:`Closest` (ties among those measured: the nearer by edge points,
    then the earlier).

    A gap is a pair's plan distance less both points' reach, so an area's hypot(gap, rise) is at least the
    straight-line distance of its edge points from ``ground``'s (:func:`edge_distances`) less the two grounds'
    farthest reach. The areas are measured in the order of that bound until it is no less than the nearest found (no
    area after it comes strictly nearer; ``caster`` as :func:`closest_step_for`'s): exact, whatever their count, at the cost of one :func:`closest_step_for` for each area whose bound lies under the
    answer (those within the answer plus two reaches of ``ground``'s edge points: half a square and the clearance
    each on the sampling route)."""
    distance = edge_distances(ground, grounds)
    bound = distance - ground[1].max() - np.array([other[1].max() for other in grounds])
    measured: list[tuple[float, float, int, Closest]] = []
    for k in np.argsort(bound, kind="stable").tolist():
        if measured and bound[k] >= min(measured)[0]:
            break
        closest = closest_step_for(ground, grounds[k], agent, caster=caster)
        measured.append((apart(closest), float(distance[k]), k, closest))
    _, _, k, closest = min(measured, key=lambda row: row[:3])
    return closest, areas[k]


def apart(closest: Closest) -> float:
    """hypot(gap, rise) of :class:`Closest`, metres: how far apart two areas' ground reads."""
    return math.hypot(closest.gap, closest.step)


def areas_cause(graph: nx.Graph, largest: Sequence[int], others: Sequence[Sequence[int]], agent: AgentConfig,
                rim: Rim, mesh: trimesh.Trimesh | None = None, kept_width: float | None = None,
                kept_head_room: float | None = None) -> str:
    """The likely cause between ``largest`` and the nearest of ``others`` (node lists of areas of ``graph``) of
    those :func:`joined_areas` keeps, with its size and where, e.g. ``from the largest area to the nearest
    area of 412 m², a step of about 0.6 m, ..., e.g. between (x, y, z m) and (x, y, z m)``. The nearest is the one whose
    ground's edges come closest (gap and rise, :func:`closest_step_for`), not the next in size: of a frozen lake's
    floes, the one across a crack, not a floe beyond it. A smaller area nearer still is named after it
    (:func:`smaller_nearer`).

    With ``mesh``, a nearest area whose closest place or middle (:func:`g2s_core.disconnected.area_summary`) is
    shut inside a closed solid of ``mesh`` (:func:`shut_in`) is named as such: Recast keeps the floor inside a
    closed box with head room, and either route a render floor inside a collision hull exported with the level.
    Before that, on one floor (a rise up to the agent's climb), a ceiling lower than the agent over the floor between
    them is named (:func:`low_ceiling`: a plank over a channel's bed, a beam); else, on one floor (a rise up to the
    agent's height), the place :func:`where_between` names: the door or plank too narrow for the agent, or the run
    of a wall or chasm. Floors farther apart are asked whether walkable ground climbs between them (:func:`way_up`;
    ``kept_width`` as :func:`way_up_cause`'s). ``kept_head_room``: on the navmesh route, :func:`navmesh_head_room`
    (:func:`nearest_cause`).
    """
    ground = rim(graph, largest)  # once, however many areas it is compared with
    joined = joined_areas(graph, largest, others)
    caster = None if mesh is None else RayCaster(mesh)
    closest, nearest = nearest_area(ground, [rim(graph, others[k]) for k in joined], [others[k] for k in joined], agent,
                                    caster)
    size, middle = area_summary(graph, nearest)
    named = set(joined)
    smaller = [other for k, other in enumerate(others) if k not in named]
    # a low ceiling is asked along the seam, not only where it comes closest (below)
    seam = None if mesh is None else closest_step_for(ground, rim(graph, nearest), agent, float(agent.height), caster)
    return (f"from the largest area to the nearest area of {size:,.0f} m², {nearest_cause(closest, middle, agent, mesh, seam, kept_width, kept_head_room)}"
            f"{smaller_nearer(graph, ground, smaller, apart(closest), agent, rim, mesh)}")


def smaller_nearer(graph: nx.Graph, ground: Ground, smaller: Sequence[Sequence[int]], named: float, agent: AgentConfig,
                   rim: Rim, mesh: trimesh.Trimesh | None = None) -> str:
    """``; and a smaller area of A m² lies nearer, its ground about G m from the largest's, R m higher, at (x, y, z
    m)``: of the areas :func:`joined_areas` leaves out (``smaller``, node lists of areas of ``graph``), the nearest
    to the largest's ``ground`` (:func:`nearest_area`) when it comes nearer than the area named (``named``: its
    hypot(gap, rise), metres; by ``READ_AS_EQUAL``) and within the agent's width (``2 agent.radius``): a closet behind a thin wall, a ledge just
    over the climb, a floor a door too narrow opens onto, that a designer fixing the named gap would not otherwise
    learn of; the place is its ground's closest edge point. Farther ones (a crate's top, a rock across the water) are
    left out: naming every crumb would lengthen every line. Empty when there is none. O(e log e) for the e edge
    points of the compared areas.
    """
    if not smaller:
        return ""
    closest, nodes = nearest_area(ground, [rim(graph, other) for other in smaller], smaller, agent,
                                  None if mesh is None else RayCaster(mesh))
    if apart(closest) > 2 * float(agent.radius) + READ_AS_EQUAL or apart(closest) > named - READ_AS_EQUAL:
        return ""
    rise = float(closest.there[1] - closest.here[1])
    level = "" if round(abs(rise), 1) == 0 else f", {abs(rise):.1f} m {'higher' if rise > 0 else 'lower'}"
    gap = closest.gap if mesh is None else walled_gap(RayCaster(mesh), closest, agent)
    return (f"; and a smaller area of {area_summary(graph, nodes)[0]:,.0f} m² lies nearer, its ground about "
            f"{gap:.1f} m from the largest's{level}, at ({xyz(closest.there)})")


def nearest_cause(closest: Closest, middle: np.ndarray, agent: AgentConfig, mesh: trimesh.Trimesh | None,
                  seam: Closest | None = None, kept_width: float | None = None,
                  kept_head_room: float | None = None) -> str:
    """:func:`areas_cause`'s cause and place for the area whose ground comes ``closest`` to the largest's, ``middle``
    (3,) a place inside it, metres; ``seam`` the same with the pairs up to ``agent.height`` farther than the closest
    (:func:`closest_step`'s window): a ceiling lower than the agent is asked of them when the pairs about as close as
    the closest have none (a beam wider than the wall beside it: its pairs lie its extra width farther). Floors more
    than the agent's height apart are named separate only when no walkable ground climbs between them near there
    (:func:`way_up`): else the stair or ramp the graph builder lost, or the step that cuts it (:func:`way_up_cause`).

    On the navmesh route (``kept_head_room``: :func:`navmesh_head_room`, metres) a ceiling at or over the agent's
    height but under that is named too, as head room the navmesh's height grid reads as too low, when none lower than
    the agent is found and the floor under it is as wide as the agent (:func:`width_across`): else a narrower cause
    holds (a door too narrow under a lintel a little over the agent), named as before. The sampling route tests head
    room at its points exactly, so its warnings keep the agent's height."""
    if mesh is None:
        return f"{likely_cause(closest.step, closest.gap, agent)}, {between(closest.pairs[0])}"
    caster = RayCaster(mesh)
    # a ceiling over floor that runs on between them first: nothing at the agent's step height parts them, so no
    # solid's wall does (the shut-in rule's rays, lifted half the agent's height, run along a plank's underside
    # 1.0-1.1 m over a channel's bed)
    if closest.step <= float(agent.max_climb):
        if (ceiling := ceiling_between(caster, closest, seam, agent)) is not None:
            return (f"head room too low: a ceiling about {ceiling.head_room:.1f} m over the floor, under agent.height "
                    f"({float(agent.height):g} m), where their ground lies about {ceiling.gap:.1f} m apart, "
                    f"at ({xyz(ceiling.floor)})")
        if kept_head_room is not None and kept_head_room > float(agent.height) and (
                ceiling := ceiling_between(caster, closest, seam, agent, kept_head_room, float(agent.radius))) is not None and (
                width_across(caster, ceiling.floor[None], agent, float(agent.radius) / 2)[0] >= 2 * float(agent.radius)):
            return (f"head room too low for the navmesh: a ceiling {ceiling.head_room:.2f} m over the floor, about the "
                    f"agent's height: the navmesh needs up to {round(kept_head_room, 4):g} m (agent.height "
                    f"{float(agent.height):g} m, read in cells of graph.params.cell_height), where their ground lies "
                    f"about {ceiling.gap:.1f} m apart, at ({xyz(ceiling.floor)})")
    gap = walled_gap(caster, closest, agent)
    # its closest place and its middle: a render post or column inside the solid may face the rays from one
    if shut_in(caster, np.stack([closest.there, middle]), agent).any():
        rise = float(closest.there[1] - closest.here[1])
        level = "at the same height" if round(abs(rise), 1) == 0 else f"{abs(rise):.1f} m {'higher' if rise > 0 else 'lower'}"
        return (f"a floor shut inside a closed solid (a box or collision hull exported with the level), {level}, "
                f"its ground about {gap:.1f} m from the other's, {between(closest.pairs[0])}")
    if closest.step > float(agent.height):
        found = way_up(caster, closest, agent)
        if found is not None:
            return way_up_cause(found, agent, kept_width)
        return f"{likely_cause(closest.step, gap, agent)}, {between(closest.pairs[0])}"
    cause = likely_cause(closest.step, gap, agent)
    return f"{cause}, {where_between(caster, closest, agent)}"


def ceiling_between(caster: RayCaster, closest: Closest, seam: Closest | None, agent: AgentConfig,
                    under: float | None = None, beside: float = 0.0) -> LowCeiling | None:
    """:func:`low_ceiling` under ``under`` (``beside`` as its) of the pairs about as close as the closest, else of the
    ``seam``'s (:func:`nearest_cause`)."""
    return (low_ceiling(caster, closest, agent, under, beside)
            or (None if seam is None else low_ceiling(caster, seam, agent, under, beside)))


def shut_in(caster: RayCaster, points: np.ndarray, agent: AgentConfig) -> np.ndarray:
    """(n,) bool: each ground point (n,3) lies inside a closed solid of the caster's mesh: along at least four of
    the five rays of the sampling builder's rule (:func:`g2s_plugins._raycasting.closed_solid_holds`, which
    :func:`g2s_plugins.graph_builders.sampling.inside_closed_solids` asks of all five), back faces of closed
    bodies come to outnumber front faces, each body read by its own winding (:attr:`_Scene.winding
    <g2s_plugins._raycasting._Scene.winding>`), so that a mesh wound inside out reads as it would wound right.

    A render object inside a collision hull meets one of them (the bandstand's roof over its deck, the fountain's
    column beside its basin, benchmarks/level_kinds.py ``collision_hulls``): its open faces stop that ray's count;
    a place meant to be walked sees its room's walls and ceiling from outside them. Five rays a point (a
    multiple-hit query each).
    """
    return closed_solid_holds(caster, points, float(agent.height), needed=4, winding=caster.scene.winding)


def likely_cause_of(agent: AgentConfig, navmesh: NavMesh | None = None, clearance: float = 0.0,
                    mesh: trimesh.Trimesh | None = None) -> Callable[[nx.Graph, Sequence[int], Sequence[Sequence[int]]], str]:
    """:func:`areas_cause` over a graph builder's ground: ``navmesh``'s polygons, eroded by Recast's
    ``ceil(radius / cell_size)`` cells, or samples kept ``clearance`` metres from walls and ledges; ``mesh`` to
    name floors shut inside closed solids, and the stairs either route lost (:func:`way_up`). On the navmesh route a
    walkway between a wall and a drop keeps floor from twice the erosion and :data:`LEDGE_CELLS` cells more."""
    cell = np.float32(navmesh.settings["cell_size"]) if navmesh is not None else None
    erosion = clearance if cell is None else float(np.ceil(np.float32(agent.radius) / cell) * cell)  # as Recast's float
    kept_width = None if cell is None else 2 * erosion + LEDGE_CELLS * float(cell)
    kept_head_room = None if navmesh is None else navmesh_head_room(navmesh.settings)
    return partial(areas_cause, agent=agent, rim=partial(ground_rim, navmesh=navmesh, erosion=erosion), mesh=mesh,
                   kept_width=kept_width, kept_head_room=kept_head_room)
