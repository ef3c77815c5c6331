"""A castle sample level: curtain walls with wall-walks, round towers with spiral stairs, a keep, bridges.

Dungeons (:mod:`g2s_plugins.samples.levels`), terrain
(:mod:`g2s_plugins.samples.outdoor`) and buildings
(:mod:`g2s_plugins.samples.buildings`) have no walkway that passes over
other walkable ground, no spiral stair and no walk on top of a wall; real
action and role-playing levels have all three. :func:`castle` builds them:
a wall-walk over a gate passage, bridges from the wall-walks to a keep over
the courtyard, towers whose spiral stairs wind over themselves for more than
two turns. Solids as in the other samples (hexahedra with outward faces,
merged); metres, Y up, the courtyard at y = 0.
"""

from __future__ import annotations

import math
from typing import Annotated, Any

import numpy as np
from pydantic import Field, NonNegativeFloat, NonNegativeInt, validate_call

from g2s_plugins.samples.buildings import MAX_RISER, TREAD
from g2s_plugins.samples.levels import (
    SLAB_THICKNESS,
    SampleLevel,
    _LevelBuilder,
    _plan_hexahedra,
    _turned_rectangle,
)

STOREY = 3.5
"""Height of a keep storey, metres."""

WALK = 2 * STOREY
"""Height of the wall-walks (the curtain walls' tops) and of the bridges, metres: the keep's floor 2."""

TOWER_TOP = WALK + 5.0
"""Height of the towers' top platforms, metres."""

NEWEL = 2.5
"""Radius of a spiral stair's solid central column, metres."""

TOWER_INNER = 5.0
"""Inner radius of a tower's wall, metres: the spiral stairs are ``TOWER_INNER - NEWEL`` = 2.5 m wide."""

TOWER_WALL = 1.0
"""Thickness of a tower's wall, metres."""

MIN_NEWEL_TREAD = 0.25
"""Shallowest tread of a spiral step at the newel, metres. Recast's ledge filter drops a cell whose neighbours,
0.5 m apart for the default agent, differ by more than its climb (0.375 m in cells): treads of 0.25 m keep two
risers of 0.15 m within that span (see :data:`g2s_plugins.samples.buildings.MAX_RISER`)."""

MAX_SPIRAL_RATE = MAX_RISER * NEWEL / MIN_NEWEL_TREAD
"""Fastest rise of a spiral stair, metres per radian (1.5)."""

STEP_THICKNESS = 0.3
"""Thickness of a spiral step, landing or platform (their undersides are open), metres."""

CLEARANCE = 2.4
"""Least head room over every walkable surface that something passes over, metres (the agent needs 2)."""

SEPARATION = CLEARANCE + STEP_THICKNESS
"""Least height between two walkable surfaces of a tower at the same x, z, metres."""

CURTAIN = 3.5
"""Thickness of a curtain wall, metres (its top is the wall-walk)."""

PARAPET = 0.4
"""Thickness of a parapet, metres (wall-walks are ``CURTAIN - 2 PARAPET`` = 2.7 m wide between theirs)."""

PARAPET_HEIGHT = 1.2
"""Height of the parapets above the surface they guard, metres (the agent climbs 0.4)."""

DOOR_WIDTH = 2.2
"""Width of the towers' and keep's doors, metres."""

DOOR_HEIGHT = 2.4
"""Height of the towers' and keep's doors, metres."""

GATE_WIDTH = 3.2
"""Width of the gate passage through a curtain wall, metres."""

GATE_HEIGHT = 4.0
"""Height of the gate passage, metres (the wall-walk passes 3 m above its ceiling)."""

KEEP_INNER = 20.0
"""Inner side of the square keep, metres."""

KEEP_WALL = 1.0
"""Thickness of the keep's walls, metres."""

BRIDGE_WIDTH = 3.0
"""Width of a bridge deck, metres (2.4 m between its parapets)."""

BRIDGE_DECK = 0.8
"""Thickness of a bridge deck, metres (the courtyard under it has ``WALK - 0.8`` = 6.2 m of head room)."""

STAIR_WIDTH = 2.0
"""Width of the straight stair from the courtyard to a wall-walk, metres."""

_ARC_STEP = 0.2  # radians: the longest arc one hexahedron stands for (chord error 2.5 cm at 6 m)
_MARGIN = 0.15  # m of solid kept between a door and a stair, a wall's end or another opening
_DOOR_SLACK = 0.3  # radians of head-room stretch wanted on each side of a tower's courtyard door
_STATUE = {"side": (1.2, 2.0), "height": (2.5, 4.0)}  # m; square plinths, turned at random
_WELL = (0.35, 1.3, 0.9)  # m: inner and outer radius (the shaft narrower than the agent), height
_CLEAR_OF_WALLS = 6.0  # m from a curtain wall's centre line to the nearest statue centre
_CLEAR_OF_KEEP = 3.5  # m from the keep's walls to the nearest statue centre
_STATUE_SPACING = 4.5  # m between statue centres


@validate_call
def castle(
    seed: NonNegativeInt = 0,
    towers: Annotated[int, Field(ge=3)] = 6,
    size: Annotated[float, Field(ge=44.0)] = 110.0,
    keep_storeys: Annotated[int, Field(ge=2)] = 4,
    bridges: NonNegativeInt = 1,
    statues: NonNegativeFloat = 14.0,
    margin: Annotated[float, Field(ge=3.0)] = 10.0,
) -> SampleLevel:
    """A walled castle: round towers with spiral stairs, wall-walks, a gate, a keep and bridges to it.

    Layout (plan, x and z, the castle's centre at the origin): ``towers``
    round towers stand at the corners of a regular polygon whose sides, the
    curtain walls, are ``size / 2`` from the centre (wall 0's middle on +x,
    wall i's at angle 2 pi i / towers, tower i between walls i - 1 and i).
    The ground is one square slab at y = 0 that reaches ``margin`` beyond
    the towers: the courtyard inside, a field outside. Curtain walls are
    3.5 m thick and 7 m tall; their tops are the wall-walks (2.7 m between
    1.2 m parapets), which run into the towers through doors.

    * Gate: a 3.2 m wide, 4 m tall passage through the middle of wall
      ``towers // 2``, the only way between the courtyard and the field;
      the wall-walk passes over it.
    * Towers: 12 m outer diameter, 1 m walls, hollow around a 5 m newel
      column. A spiral stair (2.5 m wide, risers <= 0.15 m, treads >= 0.25
      m at the newel, a step 0.3 m thick) rises from a door to the
      courtyard to a landing at 7 m that reaches both wall-walks' doors, then
      on to the top platform at 12 m (a 1.2 m parapet, a hole over the
      stair's end). Its rate (m per radian) is chosen per tower so that the
      courtyard door is clear of the stair and every part of the stair, the
      landing and the platform has >= 2.4 m of head room under anything
      above it; 2.1-3.4 turns in all.
    * Keep: a square tower 20 m inside (1 m walls) at the centre,
      ``keep_storeys`` storeys of 3.5 m and a roof with a 1.2 m parapet;
      straight flights (0.15 m risers, 0.3 m treads, 2 m wide) along the
      walls join each storey to the next through a hole in the floor above.
      A door to the courtyard faces the gate.
    * Bridges: ``bridges`` decks 3 m wide (0.8 m thick, parapets) at 7 m
      from a wall-walk's middle to the keep's floor 2 (its roof when it has
      two storeys), over the courtyard; only walls facing a side of the keep
      (angle a multiple of 90 degrees) take one, wall 0 first.
    * A straight stair (0.15 m risers, 2 m wide, against the inner face of
      the first long enough wall from ``towers // 2 + 1`` on) climbs from the
      courtyard to a wall-walk; none when no wall fits it (metadata).
    * Courtyard: a well (a ring 0.9 m tall) and about ``statues`` statues
      per 1000 m² of courtyard (plinths 1.2-2 m wide, 2.5-4 m tall, turned
      at random), >= 6 m from the walls, 3.5 m from the keep, 4.5 m apart.

    Numpy-built: the default (about 1,050 navmesh polygons with the default
    agent) takes 0.1 s, ``towers=24, size=520, statues=20`` (about 20,000)
    1.8 s. Same arguments, same mesh bytes (``numpy.random.default_rng(seed)``:
    statue places, sizes and turns).

    Args:
        seed: seed of the random generator (the statues).
        towers: number of towers and of curtain walls (a count, >= 3).
        size: span of the curtain walls, metres: twice the distance from the castle's centre to each wall's centre line.
        keep_storeys: storeys of the keep (a count, >= 2; floor 2 is at the wall-walks' height, 7 m).
        bridges: bridges from a wall-walk to the keep (a count; at most the walls facing a side of the keep).
        statues: statues per 1000 m² of courtyard (a density).
        margin: width of the field around the towers, metres.

    Openings: none (closed). Metadata: ``floor_heights`` (m), ``walk_height``,
    ``tower_top`` (m), ``towers`` (tuple of ``{"centre": (x, z), "top":
    (x, y, z) a point on the top platform, "door": (x, y, z) the courtyard
    door's middle, "turns": the spiral's turns, "rates": its two flights'
    rise, m per radian}``), ``walks`` (tuple of (x, y, z), a point on each
    wall-walk, a quarter along it), ``keep`` (``{"half": inner half side,
    "floors": tuple of (x, y, z) points on every floor and the roof}``),
    ``bridges`` (tuple of ``{"wall", "deck": (x, y, z) its middle, "under":
    (x, y, z) the courtyard below}``), ``gate`` (``{"wall", "passage": (x,
    y, z) its middle, "walk": (x, y, z) the wall-walk above}``),
    ``wall_stair`` (``{"wall", "foot", "top"}`` points, or None), ``courtyard``
    ((x, y, z), a free point), ``field`` ((x, y, z), a free point outside),
    ``statues`` (count), ``well`` ((x, z)), ``floor_area`` (m², the top
    surfaces in plan: ground slab, wall-walks, decks, keep floors, tower
    landings and platforms, stair treads; footprints of what stands on the
    ground not taken off), ``components`` (1), ``cycles`` (None).
    """
    params = dict(locals())
    n = towers
    apothem = size / 2
    circumradius = apothem / math.cos(math.pi / n)
    wall_length = 2 * apothem * math.tan(math.pi / n)
    tower_outer = TOWER_INNER + TOWER_WALL
    if wall_length < 2 * tower_outer + GATE_WIDTH + 4 * _MARGIN:
        raise ValueError(f"the curtain walls of {n} towers at size {size:g} are {wall_length:.1f} m long; "
                         f"towers need >= {2 * tower_outer + GATE_WIDTH + 4 * _MARGIN:.1f} m (raise size)")
    keep_outer = KEEP_INNER / 2 + KEEP_WALL
    if circumradius - tower_outer < math.sqrt(2) * keep_outer + _CLEAR_OF_KEEP:
        raise ValueError(f"the keep does not fit between {n} towers at size {size:g} (raise size)")
    bridge_walls = [i for i in range(n) if (4 * i) % n == 0][:bridges]
    if len(bridge_walls) < bridges:
        raise ValueError(f"a castle of {n} towers has {len(bridge_walls)} walls facing a side of the keep; "
                         f"bridges must be <= {len(bridge_walls)}")
    rng = np.random.default_rng(seed)
    gate_wall = n // 2
    tower_angles = (2 * np.arange(n) - 1) * math.pi / n
    centres = circumradius * np.column_stack([np.cos(tower_angles), np.sin(tower_angles)])

    b = _LevelBuilder()
    _ground(b, n, apothem, apothem + tower_outer + margin)
    stair_wall = _stair_wall(n, gate_wall, bridge_walls, wall_length)
    walks = [_curtain_wall(b, centres[i], centres[(i + 1) % n], i == gate_wall, i in bridge_walls, i == stair_wall)
             for i in range(n)]
    towers_meta = [_tower(b, centres[i], centres[i - 1], centres[(i + 1) % n]) for i in range(n)]
    keep_meta = _keep(b, keep_storeys, gate_wall, n, bridge_walls)
    bridges_meta = [_bridge(b, i, n, apothem, keep_outer) for i in bridge_walls]
    wall_stair = None if stair_wall is None else _wall_stair(b, centres, stair_wall)

    courtyard_point = (float(keep_outer + 3.0), 0.0, float(keep_outer + 3.0))
    gate_angle = 2 * math.pi * gate_wall / n
    gate_dir = np.array([math.cos(gate_angle), math.sin(gate_angle)])
    field_xz = (apothem + CURTAIN / 2 + margin / 2) * gate_dir
    free = [np.array(p)[[0, 2]] for p in [courtyard_point, *[m["under"] for m in bridges_meta]]]
    well, n_statues = _courtyard(b, rng, n, apothem, circumradius, keep_outer, statues, free)

    heights = sorted({0.0, WALK, TOWER_TOP, *(p[1] for p in keep_meta["floors"])})
    meta: dict[str, Any] = {
        "params": params,
        "floor_heights": tuple(float(h) for h in heights),
        "walk_height": WALK,
        "tower_top": TOWER_TOP,
        "towers": tuple(towers_meta),
        "walks": tuple(walks),
        "keep": keep_meta,
        "bridges": tuple(bridges_meta),
        "gate": {"wall": gate_wall, "passage": _xyz(apothem * gate_dir, 0.0), "walk": _xyz(apothem * gate_dir, WALK)},
        "wall_stair": wall_stair,
        "courtyard": courtyard_point,
        "field": _xyz(field_xz, 0.0),
        "statues": n_statues,
        "well": well,
        "components": 1,
        "cycles": None,
    }
    return b.build("castle", [], meta)


# --------------------------------------------------------------------------
# Plan geometry
# --------------------------------------------------------------------------


def _xyz(xz: Any, y: float) -> tuple[float, float, float]:
    return (float(xz[0]), float(y), float(xz[1]))


def _strip(a: np.ndarray, direction: np.ndarray, s0: Any, s1: Any, l0: Any, l1: Any) -> np.ndarray:
    """Quads (n, 4, 2) over [s0, s1] along ``direction`` (a unit (2,) x, z vector) from ``a`` and [l0, l1]
    to its left (seen from above: the +90 degree turn of ``direction``, x towards z); scalars or (n,)."""
    s0, s1, l0, l1 = np.broadcast_arrays(*(np.atleast_1d(np.asarray(v, dtype=np.float64)) for v in (s0, s1, l0, l1)))
    left = np.array([-direction[1], direction[0]])
    corners = [(s0, l0), (s1, l0), (s1, l1), (s0, l1)]
    return np.stack([a + s[:, None] * direction + lat[:, None] * left for s, lat in corners], axis=1)


def _sectors(centre: np.ndarray, r0: float, r1: float, a0: Any, a1: Any) -> np.ndarray:
    """Quads (n, 4, 2) of annulus sectors around ``centre``: radii [r0, r1], angles [a0, a1] (radians, a0 < a1,
    counter-clockwise from +x towards +z), each arc as its chord."""
    a0, a1 = np.atleast_1d(np.asarray(a0, dtype=np.float64)), np.atleast_1d(np.asarray(a1, dtype=np.float64))
    corners = [(r0, a0), (r1, a0), (r1, a1), (r0, a1)]  # u along the radius, v along the angle: counter-clockwise
    return np.stack([centre + r * np.column_stack([np.cos(a), np.sin(a)]) for r, a in corners], axis=1)


def _arcs(a0: float, a1: float) -> tuple[np.ndarray, np.ndarray]:
    """[a0, a1] cut into equal arcs of at most ``_ARC_STEP`` radians: (starts, ends)."""
    edges = np.linspace(a0, a1, max(1, math.ceil((a1 - a0) / _ARC_STEP - 1e-9)) + 1)
    return edges[:-1], edges[1:]


def _solid(b: _LevelBuilder, quads: np.ndarray, y0: Any, y1: Any) -> None:
    """Vertical prisms over plan quads (n, 4, 2) from ``y0`` to ``y1`` (scalars or (n,))."""
    if len(quads):
        b.hexahedra(_plan_hexahedra(quads, quads, y0, y1))


def _walled_strip(b: _LevelBuilder, a: np.ndarray, direction: np.ndarray, length: float, l0: float, l1: float,
                  y0: float, y1: float, openings: list[tuple[float, float, float, float]]) -> None:
    """A straight wall over [0, length] along ``direction`` from ``a``, [l0, l1] to its left, from ``y0`` to
    ``y1``, with ``openings`` (s0, s1, bottom, top): the wall stays below ``bottom`` and above ``top`` there."""
    cuts = sorted({0.0, length, *(s for o in openings for s in o[:2])})
    for s0, s1 in zip(cuts[:-1], cuts[1:]):
        here = [o for o in openings if o[0] <= (s0 + s1) / 2 <= o[1]]
        spans = [(y0, here[0][2]), (here[0][3], y1)] if here else [(y0, y1)]
        for lo, hi in spans:
            if hi - lo > 1e-9:
                _solid(b, _strip(a, direction, s0, s1, l0, l1), lo, hi)


# --------------------------------------------------------------------------
# Parts
# --------------------------------------------------------------------------


def _ground(b: _LevelBuilder, n: int, apothem: float, field_apothem: float) -> None:
    """The ground slabs at y = 0: the courtyard inside the curtain walls and the field outside them, out to a
    polygon whose sides are ``field_apothem`` from the centre. Nothing lies under the walls: Recast sees a solid
    only by its faces, so a slab under a thick wall would be a floor inside it (an island)."""
    def corners(distance: float) -> np.ndarray:  # (n, 2) vertices of the polygon whose sides are that far
        angles = (2 * np.arange(n) - 1) * math.pi / n
        return distance / math.cos(math.pi / n) * np.column_stack([np.cos(angles), np.sin(angles)])

    inner, outer, rim = corners(apothem - CURTAIN / 2), corners(apothem + CURTAIN / 2), corners(field_apothem)
    following = np.roll(np.arange(n), -1)
    middles = (inner + inner[following]) / 2
    kites = np.stack([np.zeros((n, 2)), middles[np.roll(np.arange(n), 1)], inner, middles], axis=1)
    field = np.stack([outer, rim, rim[following], outer[following]], axis=1)
    _solid(b, np.concatenate([kites, field]), -SLAB_THICKNESS, 0.0)
    b.floor_area += n * math.tan(math.pi / n) * ((apothem - CURTAIN / 2) ** 2 + field_apothem**2
                                                 - (apothem + CURTAIN / 2) ** 2)


def _curtain_wall(b: _LevelBuilder, start: np.ndarray, end: np.ndarray, gate: bool, bridge: bool,
                  stair: bool) -> tuple[float, float, float]:
    """The curtain wall from tower centre ``start`` to ``end``: a solid block whose top is the wall-walk, its
    parapets (the inner one open where a bridge or the wall stair's landing joins), the gate passage.
    Returns a point on the walk."""
    direction = (end - start) / np.linalg.norm(end - start)
    reach = TOWER_INNER + TOWER_WALL / 2  # the block ends inside the towers' walls
    a, length = start + reach * direction, float(np.linalg.norm(end - start)) - 2 * reach
    half, middle = CURTAIN / 2, length / 2
    gap = [(middle - GATE_WIDTH / 2, middle + GATE_WIDTH / 2, -SLAB_THICKNESS, GATE_HEIGHT)] if gate else []
    _walled_strip(b, a, direction, length, -half, half, -SLAB_THICKNESS, WALK, gap)
    if gate:  # the passage's floor (the ground stops at the wall's faces)
        _solid(b, _strip(a, direction, gap[0][0], gap[0][1], -half, half), -SLAB_THICKNESS, 0.0)
        b.floor_area += GATE_WIDTH * CURTAIN
    b.floor_area += length * (CURTAIN - 2 * PARAPET)
    # The castle's centre is to the left of every wall (towers run counter-clockwise): the inner parapet is there.
    _solid(b, _strip(a, direction, 0.0, length, -half, -half + PARAPET), WALK, WALK + PARAPET_HEIGHT)
    joints = [(middle - BRIDGE_WIDTH / 2, middle + BRIDGE_WIDTH / 2)] if bridge else []
    joints += [tuple(s - reach for s in _stair_landing())] if stair else []
    _walled_strip(b, a, direction, length, half - PARAPET, half, WALK, WALK + PARAPET_HEIGHT,
                  [(s0, s1, WALK, WALK + PARAPET_HEIGHT) for s0, s1 in joints])
    return _xyz(a + length / 4 * direction, WALK)


def _first_flight(n1: int, riser1: float, landing: float, door_range: tuple[float, float]) -> tuple[float, float]:
    """(rate, door) of a tower's first flight: ``n1`` risers of ``riser1`` ending at the landing (``landing``
    radians long), its rate in m per radian and the courtyard door's angle counter-clockwise after the landing's
    start, in ``door_range``; chosen so that the door lies in the widest stretch of ground floor with
    ``SEPARATION`` head room under the stair, or ``_DOOR_SLACK`` radians inside it at the gentlest rate.

    The rate is at least ``SEPARATION / (2 pi - landing)`` (the stair one turn below the landing's end is that
    far under it) and at most ``MAX_SPIRAL_RATE``; candidates 0.005 m/rad and 1/20 of the door range apart,
    doors nearer the range's middle first, the first best kept.
    """
    door_half = (DOOR_WIDTH / 2 + _MARGIN) / TOWER_INNER
    middle = sum(door_range) / 2
    doors = sorted(np.linspace(*door_range, 21), key=lambda d: abs(d - middle))
    best, best_margin = None, -math.inf
    for rate in np.arange(SEPARATION / (2 * math.pi - landing), MAX_SPIRAL_RATE, 0.005):
        sweep = (n1 - 1) * riser1 / rate  # the flight's angle
        low = (SEPARATION + STEP_THICKNESS) / rate  # the stair's first stretch with too little head room under it
        for door in doors:
            # the door's angle after the flight's start in [0, 2 pi): clear in [low + door_half, 2 pi - door_half]
            after_start = (door + sweep) % (2 * math.pi)
            margin = min(after_start - low - door_half, 2 * math.pi - door_half - after_start, _DOOR_SLACK)
            if margin > best_margin + 1e-9:
                best, best_margin = (float(rate), float(door)), margin
    if best is None or best_margin < 0:
        raise ValueError("no spiral stair fits the tower's doors")  # not reached for 3-64 towers (tests)
    return best


def _tower(b: _LevelBuilder, centre: np.ndarray, previous: np.ndarray, following: np.ndarray) -> dict[str, Any]:
    """A round tower at ``centre`` between the towers ``previous`` and ``following``: wall with a courtyard
    door and two wall-walk doors, newel, spiral stair in two flights with a landing at the walk, top platform."""
    def angle(v: np.ndarray) -> float:
        return math.atan2(float(v[1]), float(v[0]))

    door_half = (DOOR_WIDTH / 2 + _MARGIN) / TOWER_INNER
    to_prev, to_next, inward = angle(previous - centre), angle(following - centre), angle(-centre)
    # The landing: the arc from one walk door to the other through the courtyard side (counter-clockwise).
    start = min(to_prev, to_next, key=lambda a: (inward - a) % (2 * math.pi))
    other = max(to_prev, to_next, key=lambda a: (inward - a) % (2 * math.pi))
    landing_start = start - door_half
    landing = (other - start) % (2 * math.pi) + 2 * door_half

    (n1, riser1, _), (n2, riser2, _) = _straight_flight(WALK), _straight_flight(TOWER_TOP - WALK)  # risers only
    # The courtyard door: between the curtain walls' faces (their half thickness, seen from the tower's outside).
    wall_half = math.asin(CURTAIN / 2 / (TOWER_INNER + TOWER_WALL)) + DOOR_WIDTH / 2 / (TOWER_INNER + TOWER_WALL)
    door_range = (door_half + wall_half, landing - door_half - wall_half)
    rate1, door_after = _first_flight(n1, riser1, landing, door_range)
    door_angle = landing_start + door_after
    rate2 = SEPARATION / (2 * math.pi - landing)  # the stair one turn above the landing's start is that far over it
    step1, step2 = riser1 / rate1, riser2 / rate2
    first = landing_start - (n1 - 1) * step1
    second = landing_start + landing
    arrival = second + (n2 - 1) * step2

    inner, outer = NEWEL - 0.05, TOWER_INNER + 0.05  # steps reach into the newel and the wall
    for flight_start, step, riser, n_risers, base in ((first, step1, riser1, n1, 0.0), (second, step2, riser2, n2, WALK)):
        k = np.arange(1, n_risers)
        tops = base + k * riser
        _solid(b, _sectors(centre, inner, outer, flight_start + (k - 1) * step, flight_start + k * step),
               np.maximum(tops - STEP_THICKNESS, -SLAB_THICKNESS), tops)
    _solid(b, _sectors(centre, inner, outer, *_arcs(landing_start, second)), WALK - STEP_THICKNESS, WALK)
    # The top platform, less a hole over the flight's last SEPARATION metres (and one step).
    hole = SEPARATION / rate2 + step2
    _solid(b, _sectors(centre, inner, outer, *_arcs(arrival, arrival + 2 * math.pi - hole)),
           TOWER_TOP - STEP_THICKNESS, TOWER_TOP)
    # The newel: a ring of sectors from 0.6 of its radius out, and a square (corners within it) filling the middle.
    core = np.array([[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]]) * NEWEL * 0.64 + centre
    _solid(b, np.concatenate([core[None], _sectors(centre, NEWEL * 0.6, NEWEL, *_arcs(0.0, 2 * math.pi))]),
           -SLAB_THICKNESS, TOWER_TOP)
    # The ground floor around the newel (the ground slabs leave out the walls, _ground).
    _solid(b, _sectors(centre, NEWEL, TOWER_INNER + 0.05, *_arcs(0.0, 2 * math.pi)), -SLAB_THICKNESS, 0.0)
    annulus = math.pi * (TOWER_INNER**2 - NEWEL**2)
    b.floor_area += annulus * (1 + ((n1 - 1) * step1 + landing + (n2 - 1) * step2 + 2 * math.pi - hole) / (2 * math.pi))

    doors = [(door_angle, 0.0), (to_prev, WALK), (to_next, WALK)]
    edges = sorted({*np.linspace(0.0, 2 * math.pi, round(2 * math.pi / _ARC_STEP) + 1)[:-1],
                    *((a + s * DOOR_WIDTH / 2 / TOWER_INNER) % (2 * math.pi) for a, _ in doors for s in (-1, 1))})
    edges.append(edges[0] + 2 * math.pi)
    for a0, a1 in zip(edges[:-1], edges[1:]):
        mid = (a0 + a1) / 2
        sill = next((y for a, y in doors if abs((mid - a + math.pi) % (2 * math.pi) - math.pi)
                     < DOOR_WIDTH / 2 / TOWER_INNER), None)
        spans = [(-SLAB_THICKNESS, sill), (sill + DOOR_HEIGHT, TOWER_TOP + PARAPET_HEIGHT)] if sill is not None \
            else [(-SLAB_THICKNESS, TOWER_TOP + PARAPET_HEIGHT)]
        for lo, hi in spans:
            if hi - lo > 1e-9:
                _solid(b, _sectors(centre, TOWER_INNER, TOWER_INNER + TOWER_WALL, a0, a1), lo, hi)
    door = centre + (TOWER_INNER + TOWER_WALL / 2) * np.array([math.cos(door_angle), math.sin(door_angle)])
    turns = ((n1 - 1) * step1 + landing + (n2 - 1) * step2) / (2 * math.pi)
    return {"centre": (float(centre[0]), float(centre[1])), "top": _xyz(centre, TOWER_TOP), "door": _xyz(door, 0.0),
            "turns": round(turns, 6), "rates": (round(rate1, 6), round(rate2, 6))}


def _keep(b: _LevelBuilder, storeys: int, gate_wall: int, n: int, bridge_walls: list[int]) -> dict[str, Any]:
    """The keep at the centre: walls with doors (courtyard, bridges), floors, flights, roof."""
    h, t = KEEP_INNER / 2, KEEP_WALL
    roof = storeys * STOREY
    steps, riser, run = _straight_flight(STOREY)
    flight_start = DOOR_WIDTH / 2 + 0.4  # along a side from its middle: doors stay clear
    # Sides 0-3 face +x, +z, -x, -z; side s's wall runs counter-clockwise (seen from above) from corner to corner.
    normals = np.array([[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]])
    gate_angle = 2 * math.pi * gate_wall / n
    door_side = int(np.argmax(normals @ [math.cos(gate_angle), math.sin(gate_angle)]))
    bridge_sides = {round(4 * i / n) % 4 for i in bridge_walls}
    for s, normal in enumerate(normals):
        along = np.array([-normal[1], normal[0]])
        a = normal * h - along * (h + t)
        openings = [(h + t - DOOR_WIDTH / 2, h + t + DOOR_WIDTH / 2, y, y + DOOR_HEIGHT)
                    for y, here in ((0.0, s == door_side), (WALK, s in bridge_sides)) if here]
        # the wall's inside is to the right of ``along`` (towards the centre): lateral offsets [-t, 0]
        _walled_strip(b, a, along, KEEP_INNER + 2 * t, -t, 0.0, -SLAB_THICKNESS, roof + PARAPET_HEIGHT,
                      [(s0, s1, -SLAB_THICKNESS if y == 0.0 else y, top) for s0, s1, y, top in openings])
    floors = [(0.0, 0.0, 0.0)]
    for k in range(1, storeys + 1):
        y, side = k * STOREY, (k - 1) % 4  # flight k - 1 runs along side (k - 1) % 4, up counter-clockwise
        normal, along = normals[side], np.array([-normals[side][1], normals[side][0]])
        hole = _strip(normal * h, along, flight_start, flight_start + run, 0.0, STAIR_WIDTH)[0]
        lo, hi = hole.min(axis=0), hole.max(axis=0)
        rects = [(-h, lo[0], -h, h), (hi[0], h, -h, h), (lo[0], hi[0], -h, lo[1]), (lo[0], hi[0], hi[1], h)]
        for x0, x1, z0, z1 in rects:
            if x1 - x0 > 1e-9 and z1 - z0 > 1e-9:
                b.floors(x0, x1, z0, z1, y)
        i = np.arange(steps - 1)
        _solid(b, _strip(normal * h, along, flight_start + i * TREAD, flight_start + run, 0.0, STAIR_WIDTH),
               y - STOREY - SLAB_THICKNESS, y - STOREY + (i + 1) * riser)
        b.floor_area += STAIR_WIDTH * run
        floors.append((0.0, float(y), 0.0))
    return {"half": h, "floors": tuple(floors), "door_side": door_side}


def _bridge(b: _LevelBuilder, wall: int, n: int, apothem: float, keep_outer: float) -> dict[str, Any]:
    """A deck at the walk's height from the keep's side to the middle of wall ``wall``'s walk, with parapets."""
    angle = 2 * math.pi * wall / n
    direction = np.array([math.cos(angle), math.sin(angle)])
    origin = np.zeros(2)
    half = BRIDGE_WIDTH / 2
    _solid(b, _strip(origin, direction, keep_outer, apothem, -half, half), WALK - BRIDGE_DECK, WALK)
    inner_face = apothem - CURTAIN / 2
    _solid(b, _strip(origin, direction, [keep_outer] * 2, [inner_face] * 2, [-half, half - PARAPET / 2],
                     [-half + PARAPET / 2, half]), WALK, WALK + PARAPET_HEIGHT)
    b.floor_area += (inner_face - keep_outer) * BRIDGE_WIDTH
    middle = (keep_outer + inner_face) / 2 * direction
    return {"wall": wall, "deck": _xyz(middle, WALK), "under": _xyz(middle, 0.0)}


def _straight_flight(rise: float) -> tuple[int, float, float]:
    """(risers, riser height, run) of a straight flight up ``rise`` metres: risers <= ``MAX_RISER``, ``TREAD`` treads."""
    steps = math.ceil(rise / MAX_RISER - 1e-9)
    return steps, rise / steps, steps * TREAD


def _stair_landing() -> tuple[float, float]:
    """Where the wall stair's landing lies along its wall, metres from the wall's first tower's centre."""
    top = TOWER_INNER + TOWER_WALL + 2.0 + _straight_flight(WALK)[2]
    return top - TREAD, top + STAIR_WIDTH


def _stair_wall(n: int, gate_wall: int, bridge_walls: list[int], wall_length: float) -> int | None:
    """The wall that takes the straight stair: the first from ``gate_wall + 1`` on with room for it beside its
    towers' doors and whatever is in its middle (the gate, a bridge's joint); None when none has."""
    end = _stair_landing()[1]
    for i in [(gate_wall + 1 + j) % n for j in range(n)]:
        busy = i == gate_wall or i in bridge_walls
        room = wall_length / 2 - max(GATE_WIDTH, BRIDGE_WIDTH) / 2 - 1.0 if busy else wall_length - 8.0
        if end <= room:
            return i
    return None


def _wall_stair(b: _LevelBuilder, centres: np.ndarray, wall: int) -> dict[str, Any]:
    """A straight stair against the courtyard side of curtain wall ``wall`` from the ground to its walk, then a
    landing beside the walk (the walk's inner parapet is open there, :func:`_curtain_wall`)."""
    n = len(centres)
    steps, riser, _ = _straight_flight(WALK)
    start = centres[wall]
    direction = (centres[(wall + 1) % n] - start) / np.linalg.norm(centres[(wall + 1) % n] - start)
    left = np.array([-direction[1], direction[0]])
    a = start + (CURTAIN / 2) * left  # the wall's inner face
    foot = TOWER_INNER + TOWER_WALL + 2.0
    landing0, landing1 = _stair_landing()
    k = np.arange(steps - 1)
    # nested blocks, each to the landing's end: a column under the flight meets a top face every riser, so
    # Recast (which sees solids only by their faces) finds no floor with head room inside the stair
    _solid(b, _strip(a, direction, foot + k * TREAD, landing1, 0.0, STAIR_WIDTH), -SLAB_THICKNESS, (k + 1) * riser)
    _solid(b, _strip(a, direction, landing0, landing1, 0.0, STAIR_WIDTH), -SLAB_THICKNESS, WALK)
    b.floor_area += STAIR_WIDTH * (landing1 - foot)
    return {"wall": wall, "foot": _xyz(a + (foot - 1.0) * direction + left, 0.0),
            "top": _xyz(a + (landing0 + landing1) / 2 * direction + left, WALK)}


def _courtyard(b: _LevelBuilder, rng: np.random.Generator, n: int, apothem: float, circumradius: float,
               keep_outer: float, density: float, free: list[np.ndarray]) -> tuple[tuple[float, float], int]:
    """A well and statues at random free places of the courtyard; returns (the well's centre, statues)."""
    wall_angles = 2 * math.pi * np.arange(n) / n
    wall_normals = np.column_stack([np.cos(wall_angles), np.sin(wall_angles)])
    area = n * apothem * apothem * math.tan(math.pi / n) - (2 * keep_outer) ** 2
    wanted = int(rng.poisson(density * area / 1000.0)) + 1  # the well first
    tower_centres = circumradius * np.column_stack([np.cos((2 * np.arange(n) - 1) * math.pi / n),
                                                    np.sin((2 * np.arange(n) - 1) * math.pi / n)])
    candidates = rng.uniform(-apothem, apothem, (40 * wanted, 2))
    clear = (np.max(candidates @ wall_normals.T, axis=1) <= apothem - _CLEAR_OF_WALLS) \
        & (np.max(np.abs(candidates), axis=1) >= keep_outer + _CLEAR_OF_KEEP) \
        & (np.min(np.linalg.norm(candidates[:, None] - tower_centres[None], axis=2), axis=1)
           >= TOWER_INNER + TOWER_WALL + _CLEAR_OF_WALLS)
    taken: dict[tuple[int, int], list[np.ndarray]] = {}  # grid cells _STATUE_SPACING wide -> the places in each

    def cell(p: np.ndarray) -> tuple[int, int]:
        return int(p[0] // _STATUE_SPACING), int(p[1] // _STATUE_SPACING)

    for p in free:  # kept clear: statues stay _STATUE_SPACING away
        taken.setdefault(cell(p), []).append(p)
    placed: list[np.ndarray] = []
    for p in candidates[clear]:
        if len(placed) == wanted:
            break
        c = cell(p)
        near = (q for i in (-1, 0, 1) for j in (-1, 0, 1) for q in taken.get((c[0] + i, c[1] + j), []))
        if any(np.linalg.norm(q - p) < _STATUE_SPACING for q in near):
            continue
        taken.setdefault(c, []).append(p)
        placed.append(p)
    well, statues = placed[0], placed[1:]
    inner, outer, tall = _WELL
    _solid(b, _sectors(well, inner, outer, *_arcs(0.0, 2 * math.pi)), -SLAB_THICKNESS, tall)
    sides = rng.uniform(*_STATUE["side"], len(statues))
    heights = rng.uniform(*_STATUE["height"], len(statues))
    turns = rng.uniform(0.0, math.pi / 2, len(statues))
    for p, side, tall, turn in zip(statues, sides, heights, turns):
        _solid(b, _turned_rectangle(p[0], p[1], side / 2, side / 2, turn)[None], -SLAB_THICKNESS, tall)
    return (float(well[0]), float(well[1])), len(statues)


SAMPLES = {"castle": castle}
"""The castle samples, registered in :data:`g2s_plugins.samples.levels.SAMPLES`."""
