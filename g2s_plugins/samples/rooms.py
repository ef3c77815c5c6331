"""Sample levels of rooms joined by doors, with the chokepoints and regions they should give.

Each factory returns a :class:`~g2s_plugins.samples.levels.SampleLevel` built
like the other samples (slabs, walls outside the floors, see
:mod:`g2s_plugins.samples.levels`). Rooms are axis-aligned rectangles; a door
is a gap in the wall two rooms share (the wall is ``WALL_THICKNESS`` thick and
the gap has a floor), so the only ways between rooms are the doors, and a
ramp joins floors at different heights. Everything is walled: 0 openings.

Metadata (besides the common keys of ``SampleLevel``):

``rooms``
    tuple of room rectangles ``{"x0", "x1", "z0", "z1", "y"}`` (floor, m).
``doors``
    tuple of ``{"rooms": (a, b), "position": (x, y, z), "p0", "p1", "width"}``:
    the door's centre on the middle of the wall at floor height, the ends of
    its gap there, and its clear width (m, before the agent's radius).
``expected``
    what a region/chokepoint analysis should find: ``regions`` (rooms),
    ``chokepoints`` (doors and ramps), ``articulation`` (per door, whether
    closing it disconnects the level) and, where it applies, ``ranking``
    (door indices, highest chokepoint score first).
``obstacles``
    (where a level has them) tuple of ``{"x0", "x1", "z0", "z1"}``: solids a
    wall high standing in the floor (desk rows, a closed room, pilasters),
    their roofs too steep to stand on, so that they are walls and never
    walkable islands.

Five samples are the shapes a designer calls passages, not rooms (aisles
between desk rows, a ring corridor, a catwalk, a dead-end corridor), beside
small offices that must stay rooms; their ``expected`` is what the width rule
of :mod:`g2s_plugins.decomposition` is checked against. The last four are
corridors for its pinch rule: a straight and a bent corridor narrowed by
pilasters (one region each), a door across a corridor and a long gallery
beside a corridor (two regions: doors stay chokepoints). The last two come from the held-out round of
3 December 2026 (docs/plugins.md): a room with two doors to one corridor (a room, not a strip beside the corridor),
and a warehouse whose shelving aisles are part of its hall (the side-strip rule).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np
from pydantic import PositiveFloat, PositiveInt, validate_call

from g2s_plugins.samples.levels import (
    NX,
    NZ,
    PX,
    PZ,
    SLAB_THICKNESS,
    WALL_HEIGHT,
    WALL_THICKNESS,
    RampSlope,
    SampleLevel,
    _LevelBuilder,
    _no_apertures,
    _ramp_meta,
    _ramp_run,
    _rect,
    _sloped_blocks,
)

_OPPOSITE = {PX: NX, PZ: NZ}

_ROOF_SLOPE = math.tan(math.radians(60.0))
"""Rise per metre of an obstacle's roof: steeper than any agent walks, so a roof is never a walkable island."""


def _obstacles(b: _LevelBuilder, boxes: list[tuple[float, float, float, float]]) -> tuple[dict[str, float], ...]:
    """Solids over ``(x0, x1, z0, z1)`` from the floor slab's bottom to a wall's height, roofs rising
    along +X at :data:`_ROOF_SLOPE`; their metadata records."""
    x0, x1, z0, z1 = (np.array(column, dtype=np.float64) for column in zip(*boxes))
    b.hexahedra(_sloped_blocks(x0, x1, z0, z1, -SLAB_THICKNESS, WALL_HEIGHT, WALL_HEIGHT + (x1 - x0) * _ROOF_SLOPE))
    return tuple(_rect(*box) for box in boxes)


def _floor_cells(room: np.ndarray, boxes: list[tuple[float, float, float, float]]) -> list[tuple[float, ...]]:
    """The floor rectangle ``room`` (x0, x1, z0, z1) less the ``boxes``, as the cells (x0, x1, z0, z1) of the grid
    their sides make. Recast sees surfaces, not solids: a floor left under an obstacle would be a walkable
    room inside it."""
    x0, x1, z0, z1 = room
    xs = np.unique(np.clip([x0, x1, *(v for box in boxes for v in box[:2])], x0, x1))
    zs = np.unique(np.clip([z0, z1, *(v for box in boxes for v in box[2:])], z0, z1))
    cells = [(a, b, c, d) for a, b in zip(xs, xs[1:]) for c, d in zip(zs, zs[1:])]
    return [cell for cell in cells if not any(a < (cell[0] + cell[1]) / 2 < b and c < (cell[2] + cell[3]) / 2 < d
                                              for a, b, c, d in boxes)]


def _build(name: str, rooms: list[tuple[float, float, float, float, float]],
           doors: list[tuple[int, int, int, float, float]], params: dict[str, Any],
           expected: dict[str, Any], extra: dict[str, Any] | None = None,
           ramp: tuple[float, float] | None = None,
           obstacles: list[tuple[float, float, float, float]] = (), b: _LevelBuilder | None = None) -> SampleLevel:
    """Rooms ``(x0, x1, z0, z1, floor y)`` and doors ``(room a, room b, side of a, centre, width)``.

    A door sits on side ``PX`` or ``PZ`` of room ``a``; room ``b`` starts one
    wall thickness beyond it. ``centre`` is the door's centre along the wall
    (world z for ``PX``, world x for ``PZ``). ``ramp = (centre z, width)`` joins
    room 0's +X wall to room 1's -X wall by a walled ramp along +X.
    ``obstacles``: ``(x0, x1, z0, z1)`` solids standing in the floor (:func:`_obstacles`);
    ``b``: a builder already holding other parts of the level.
    """
    b = b or _LevelBuilder()
    bounds = np.array([r[:4] for r in rooms], dtype=np.float64)
    heights = np.array([r[4] for r in rooms], dtype=np.float64)
    if obstacles:
        extra = {**(extra or {}), "obstacles": _obstacles(b, list(obstacles))}
        cells = [(*cell, y) for room, y in zip(bounds, heights) for cell in _floor_cells(room, obstacles)]
        b.floors(*np.array(cells).T)
    else:
        b.floors(bounds[:, 0], bounds[:, 1], bounds[:, 2], bounds[:, 3], heights)
    apertures = _no_apertures(len(rooms))
    door_meta = []
    t = WALL_THICKNESS
    if ramp is not None:
        zc, width = ramp
        b.ramp(bounds[0, PX], bounds[1, NX], zc, width, heights[0], heights[1])
        apertures[0, PX] = apertures[1, NX] = (zc - width / 2, zc + width / 2, 0.0, WALL_HEIGHT)
    for a, other, side, centre, width in doors:
        edge = bounds[a, side]
        if abs(bounds[other, _OPPOSITE[side]] - (edge + t)) > 1e-9:
            raise ValueError(f"room {other} must start one wall thickness beyond side {side} of room {a}")
        gap = (centre - width / 2, centre + width / 2, 0.0, WALL_HEIGHT)
        apertures[a, side] = gap
        apertures[other, _OPPOSITE[side]] = gap
        y = float(heights[a])
        along_x = side == PX
        b.floors(*((edge, edge + t, gap[0], gap[1]) if along_x else (gap[0], gap[1], edge, edge + t)), y)
        middle = float(edge + t / 2)
        position = (middle, y, centre) if along_x else (centre, y, middle)
        ends = [(middle, y, gap[0]), (middle, y, gap[1])] if along_x else [(gap[0], y, middle), (gap[1], y, middle)]
        door_meta.append({"rooms": (a, other), "position": position, "p0": ends[0], "p1": ends[1],
                          "width": float(width)})
    b.room_walls(bounds, heights, apertures)
    meta = {
        "params": params,
        "floor_heights": tuple(sorted({float(h) for h in heights})),
        "rooms": tuple({"x0": r[0], "x1": r[1], "z0": r[2], "z1": r[3], "y": r[4]} for r in rooms),
        "doors": tuple(door_meta),
        "expected": expected,
        "components": 1,
    }
    meta.update(extra or {})
    return b.build(name, [], meta)


@validate_call
def two_rooms_one_door(size: PositiveFloat = 8.0, door_width: PositiveFloat = 2.0) -> SampleLevel:
    """Two square rooms side by side along X, joined by one door in the middle of their shared wall.

    Room 0 covers [0, size]², room 1 [size + 0.2, 2 size + 0.2] x [0, size], both at y = 0.
    Expected: the door is the top chokepoint and an articulation point; two regions.

    Args:
        size: side of each square room, metres.
        door_width: the door's clear width, metres.
    """
    if door_width >= size:
        raise ValueError("door_width must be < size")
    s, t = float(size), WALL_THICKNESS
    rooms = [(0.0, s, 0.0, s, 0.0), (s + t, 2 * s + t, 0.0, s, 0.0)]
    expected = {"regions": 2, "chokepoints": 1, "articulation": (True,), "ranking": (0,)}
    return _build("two_rooms_one_door", rooms, [(0, 1, PX, s / 2, door_width)],
                  {"size": size, "door_width": door_width}, expected, {"cycles": 0})


@validate_call
def room_with_two_doors(
    size: PositiveFloat = 8.0, narrow: PositiveFloat = 1.8, wide: PositiveFloat = 3.0
) -> SampleLevel:
    """A middle room with a narrow door to a room on -X and a wide door to a room on +X.

    Rooms (y = 0): 0 the middle one, 1 on -X, 2 on +X. Door 0 joins rooms 1-0,
    door 1 rooms 0-2; the level is symmetric otherwise, so the same traffic
    crosses both doors and the narrow one must score higher. Expected: three
    regions, both doors articulation points.

    Args:
        size: side of each square room, metres.
        narrow: clear width of door 0, metres.
        wide: clear width of door 1, metres.
    """
    if not narrow < wide < size:
        raise ValueError("need narrow < wide < size")
    s, t = float(size), WALL_THICKNESS
    rooms = [(0.0, s, 0.0, s, 0.0), (-s - t, -t, 0.0, s, 0.0), (s + t, 2 * s + t, 0.0, s, 0.0)]
    doors = [(1, 0, PX, s / 2, narrow), (0, 2, PX, s / 2, wide)]
    expected = {"regions": 3, "chokepoints": 2, "articulation": (True, True), "ranking": (0, 1)}
    return _build("room_with_two_doors", rooms, doors, {"size": size, "narrow": narrow, "wide": wide},
                  expected, {"cycles": 0})


@validate_call
def loop_of_four_rooms(size: PositiveFloat = 8.0, door_width: PositiveFloat = 2.0) -> SampleLevel:
    """Four square rooms on a 2 x 2 grid, each joined to its two neighbours: one loop.

    Rooms (y = 0): 0 at [0, size]², 1 beside it on +X, 2 beside 0 on +Z, 3 diagonal.
    Doors: 0-1, 2-3 (on +X sides), 0-2, 1-3 (on +Z sides), centred on the walls.
    Expected: four regions, four chokepoints, no articulation points.

    Args:
        size: side of each square room, metres.
        door_width: clear width of every door, metres.
    """
    if door_width >= size:
        raise ValueError("door_width must be < size")
    s, t = float(size), WALL_THICKNESS
    lo, hi = (0.0, s), (s + t, 2 * s + t)
    rooms = [(*lo, *lo, 0.0), (*hi, *lo, 0.0), (*lo, *hi, 0.0), (*hi, *hi, 0.0)]
    doors = [(0, 1, PX, s / 2, door_width), (2, 3, PX, s + t + s / 2, door_width),
             (0, 2, PZ, s / 2, door_width), (1, 3, PZ, s + t + s / 2, door_width)]
    expected = {"regions": 4, "chokepoints": 4, "articulation": (False,) * 4}
    return _build("loop_of_four_rooms", rooms, doors, {"size": size, "door_width": door_width},
                  expected, {"cycles": 1})


@validate_call
def floors_joined_by_ramp(
    size: PositiveFloat = 10.0, upper_height: PositiveFloat = 3.0, ramp_width: PositiveFloat = 2.5,
    slope_deg: RampSlope = 20.0,
) -> SampleLevel:
    """A ground room, a walled ramp up along +X, and an upper room at ``upper_height``.

    Room 0 covers [0, size]² at y = 0, room 1 [size + run, 2 size + run] x [0, size]
    at y = ``upper_height`` (run = upper_height / tan(slope_deg)); the ramp,
    centred on z = size / 2, joins gaps in the rooms' facing walls. Expected: two
    regions on two floors, the ramp a chokepoint between them and an articulation
    point. Metadata ``ramp`` as in ``corridor_with_ramp``.

    Args:
        size: side of each square room, metres.
        upper_height: height of the upper room's floor above the ground room's, metres.
        ramp_width: the ramp's width, metres.
        slope_deg: the ramp's slope, degrees (the design agent walks up to 45).
    """
    if ramp_width >= size:
        raise ValueError("ramp_width must be < size")
    run = _ramp_run(upper_height, slope_deg)
    s, zc = float(size), size / 2
    rooms = [(0.0, s, 0.0, s, 0.0), (s + run, 2 * s + run, 0.0, s, float(upper_height))]
    params = {"size": size, "upper_height": upper_height, "ramp_width": ramp_width, "slope_deg": slope_deg}
    expected = {"regions": 2, "chokepoints": 1, "articulation": (True,), "floors": 2}
    ramp = _ramp_meta(s, s + run, zc, ramp_width, 0.0, upper_height, slope_deg)
    return _build("floors_joined_by_ramp", rooms, [], params, expected, {"ramp": ramp, "cycles": 0},
                  ramp=(zc, ramp_width))


@validate_call
def lecture_hall(
    aisles: PositiveInt = 3, aisle_width: PositiveFloat = 2.2, aisle_end: PositiveFloat = 1.7,
    row_length: PositiveFloat = 12.0, block_width: PositiveFloat = 3.0,
) -> SampleLevel:
    """A hall with blocks of desk rows, and aisles between the blocks that narrow at both ends.

    ``aisles + 1`` blocks ``block_width`` wide (x) and ``row_length`` long (z)
    stand ``aisle_width`` apart, 3 m from the hall's side walls, 4 m from its
    front (z = 0) and 3 m from its back. A 0.6 m long end panel at each end of
    a block juts into the aisles so that an aisle's ends are ``aisle_end``
    wide (wall to wall). The blocks are obstacles larger than
    ``obstacle_area``: walls to the split. Expected: one region, the hall, no
    chokepoint (the aisles are passages within it; before the width rule each
    was a region between two chokepoints, as the 1 m aisles with 0.7-0.8 m
    ends of the lecture hall of docs/plugins.md's real levels). Metadata ``aisles``: ``{"x0", "x1", "z0",
    "z1"}`` of each aisle between blocks.

    Args:
        aisles: number of aisles between blocks.
        aisle_width: clear width of an aisle between two blocks, metres.
        aisle_end: clear width of an aisle between the end panels, metres.
        row_length: length of a block of desk rows along z, metres.
        block_width: width of a block of desk rows along x, metres.
    """
    if not aisle_end < aisle_width:
        raise ValueError("aisle_end must be < aisle_width")
    side, front, back, panel = 3.0, 4.0, 3.0, 0.6
    jut = (aisle_width - aisle_end) / 2
    step = block_width + aisle_width
    width = 2 * side + (aisles + 1) * block_width + aisles * aisle_width
    z0, z1 = front, front + row_length
    blocks = [(side + i * step, side + i * step + block_width) for i in range(aisles + 1)]
    obstacles = [(x0, x1, z0 + panel, z1 - panel) for x0, x1 in blocks]
    obstacles += [(x0 - jut, x1 + jut, za, zb) for x0, x1 in blocks for za, zb in ((z0, z0 + panel), (z1 - panel, z1))]
    params = {"aisles": aisles, "aisle_width": aisle_width, "aisle_end": aisle_end, "row_length": row_length,
              "block_width": block_width}
    extra = {"aisles": tuple(_rect(a[1], b[0], z0, z1) for a, b in zip(blocks, blocks[1:])), "cycles": aisles + 1}
    return _build("lecture_hall", [(0.0, width, 0.0, z1 + back, 0.0)], [], params,
                  {"regions": 1, "chokepoints": 0}, extra, obstacles=obstacles)


@validate_call
def ring_corridor(
    size: PositiveFloat = 16.0, width: PositiveFloat = 3.5, narrow: PositiveFloat = 2.5,
    door_width: PositiveFloat = 1.8,
) -> SampleLevel:
    """A corridor all round a closed room, narrowed by pilasters at three spots, and a room off it.

    Room 0 is the square [0, size]² holding the closed room (an obstacle) in its
    middle, so that its walkable floor is a ring ``width`` wide; pilasters on the
    outer walls (1 m long, in the middle of the -Z, +X and +Z sides) narrow the
    ring to ``narrow``. Room 1 (8 x 8 m) lies on -X, joined by a door in the
    middle of the -X side. Expected: two regions (the ring and the room) and the
    door the one chokepoint; the pilasters are no chokepoints (as on
    docs/plugins.md's real levels, where a ring 2.5 m walkable narrowed to
    1.5-1.8 m was cut into 3 regions). Met by the pinch rule of
    :mod:`g2s_plugins.decomposition` (before it: 4 regions at the pilasters).

    Args:
        size: side of the square around the closed room, metres.
        width: clear width of the ring corridor, metres.
        narrow: clear width of the ring at a pilaster, metres.
        door_width: clear width of the door to the room on -X, metres.
    """
    if not narrow < width < size / 2 - 1.0 or door_width >= size - 2 * width:
        raise ValueError("need narrow < width < size / 2 - 1 and door_width < size - 2 width")
    s, t, mid, jut = float(size), WALL_THICKNESS, size / 2, width - narrow
    rooms = [(0.0, s, 0.0, s, 0.0), (-8.0 - t, -t, mid - 4.0, mid + 4.0, 0.0)]
    obstacles = [(width, s - width, width, s - width),
                 (mid - 0.5, mid + 0.5, 0.0, jut), (s - jut, s, mid - 0.5, mid + 0.5), (mid - 0.5, mid + 0.5, s - jut, s)]
    params = {"size": size, "width": width, "narrow": narrow, "door_width": door_width}
    expected = {"regions": 2, "chokepoints": 1, "articulation": (True,)}
    return _build("ring_corridor", rooms, [(1, 0, PX, mid, door_width)], params, expected, {"cycles": 1},
                  obstacles=obstacles)


@validate_call
def catwalk(
    length: PositiveFloat = 22.0, width: PositiveFloat = 2.5, narrow: PositiveFloat = 1.9,
    height: PositiveFloat = 1.5, slope_deg: RampSlope = 15.0,
) -> SampleLevel:
    """A hall with a raised catwalk along its -Z wall, reached by a walled ramp, narrowed by a pilaster.

    The hall is [0, run + 2 + length] x [0, 12] at y = 0; the catwalk is the top
    of a solid ledge ``height`` tall and ``width`` deep against the -Z wall,
    over x from run + 2 to the +X wall; a walled ramp ``width`` wide climbs to
    it along +X from x = 2 (run = height / tan(slope_deg)). A pilaster on the
    wall halfway along the catwalk narrows it to ``narrow`` (its open edge is a
    drop: the navmesh keeps the agent's radius from it too). Expected: one
    region and no chokepoint: the catwalk is a passage of the hall, not a room
    (it was two regions joined at the pilaster, as the catwalks on
    docs/plugins.md's real levels). Metadata ``catwalk`` and ``ramp`` extents.

    Args:
        length: length of the catwalk, metres.
        width: depth of the ledge (wall to drop), metres.
        narrow: depth of the ledge beside the pilaster, metres.
        height: height of the catwalk above the hall's floor, metres.
        slope_deg: the ramp's slope, degrees (the design agent walks up to 45).
    """
    if not narrow < width < 6.0:
        raise ValueError("need narrow < width < 6")
    run = _ramp_run(height, slope_deg)
    x0, x1, zc = 2.0 + run, 2.0 + run + length, width / 2
    b = _LevelBuilder()
    b.boxes(np.array([[x0, -SLAB_THICKNESS, 0.0]]), np.array([[x1, height, width]]))
    b.ramp(2.0, x0, zc, width, 0.0, height)
    middle = (x0 + x1) / 2
    params = {"length": length, "width": width, "narrow": narrow, "height": height, "slope_deg": slope_deg}
    extra = {"catwalk": _rect(x0, x1, 0.0, width) | {"y": float(height)},
             "ramp": _ramp_meta(2.0, x0, zc, width, 0.0, height, slope_deg), "floor_heights": (0.0, float(height))}
    return _build("catwalk", [(0.0, x1, 0.0, 12.0, 0.0)], [], params, {"regions": 1, "chokepoints": 0}, extra,
                  obstacles=[(middle - 0.5, middle + 0.5, 0.0, width - narrow)], b=b)


@validate_call
def offices(
    count: PositiveInt = 4, width: PositiveFloat = 4.0, depth: PositiveFloat = 5.0,
    corridor_width: PositiveFloat = 3.0, door_width: PositiveFloat = 1.8,
) -> SampleLevel:
    """Small offices side by side off a corridor, one door each.

    The corridor runs along +X at z in [0, corridor_width], as ``count``
    segments ``width`` long joined by openings its full width (room i, i < count);
    office i (room count + i, ``width`` x ``depth``, 3 x 4 m walkable for the
    design agent by default) lies beyond the +Z wall of segment i, joined by a
    door in its middle. Expected: ``count + 1`` regions (the corridor and every
    office), one chokepoint at each office door, all articulations.

    Args:
        count: number of offices.
        width: width of an office along the corridor, metres.
        depth: depth of an office, metres.
        corridor_width: clear width of the corridor, metres.
        door_width: clear width of an office door, metres.
    """
    if not door_width < min(width, corridor_width):
        raise ValueError("door_width must be < width and < corridor_width")
    t = WALL_THICKNESS
    step = width + t
    segments = [(i * step, i * step + width, 0.0, corridor_width, 0.0) for i in range(count)]
    rooms = segments + [(x0, x1, corridor_width + t, corridor_width + t + depth, 0.0) for x0, x1, *_ in segments]
    doors = [(i, i + 1, PX, corridor_width / 2, corridor_width) for i in range(count - 1)]
    doors += [(i, count + i, PZ, i * step + width / 2, door_width) for i in range(count)]
    params = {"count": count, "width": width, "depth": depth, "corridor_width": corridor_width,
              "door_width": door_width}
    expected = {"regions": count + 1, "chokepoints": count, "articulation": (True,) * count}
    return _build("offices", rooms, doors, params, expected, {"cycles": 0})


@validate_call
def dead_end_corridor(
    size: PositiveFloat = 8.0, length: PositiveFloat = 14.0, width: PositiveFloat = 2.0,
    door_width: PositiveFloat = 1.6,
) -> SampleLevel:
    """A square room with a narrow dead-end corridor off it, behind a door narrower still.

    Room 0 is [0, size]²; the corridor (room 1) runs along +X from its +X wall,
    ``length`` long and ``width`` wide around z = size / 2, through a door
    ``door_width`` wide. Expected: one region: the corridor is too narrow for
    two agents to pass (1 m walkable for the design agent) and leads nowhere,
    so it is a passage of the room (it was a region of its own behind a
    chokepoint).

    Args:
        size: side of the square room, metres.
        length: length of the corridor, metres.
        width: clear width of the corridor, metres.
        door_width: clear width of the door between the room and the corridor, metres.
    """
    if not door_width < width < size:
        raise ValueError("need door_width < width < size")
    s, t, mid = float(size), WALL_THICKNESS, size / 2
    rooms = [(0.0, s, 0.0, s, 0.0), (s + t, s + t + length, mid - width / 2, mid + width / 2, 0.0)]
    params = {"size": size, "length": length, "width": width, "door_width": door_width}
    return _build("dead_end_corridor", rooms, [(0, 1, PX, mid, door_width)], params,
                  {"regions": 1, "chokepoints": 0}, {"cycles": 0})



@validate_call
def pilaster_corridor(
    length: PositiveFloat = 24.0, width: PositiveFloat = 3.5, narrow: PositiveFloat = 2.5,
    door_width: PositiveFloat = 1.8,
) -> SampleLevel:
    """A straight corridor narrowed by pilasters at three spots, between two rooms behind doors.

    Room 0 is the corridor, [0, length] x [0, width]; pilasters (1 m long) at a quarter, half and three
    quarters of its length, on its -Z, +Z and -Z walls in turn, narrow it to ``narrow``. Rooms 1 and 2
    (8 x 8 m) lie beyond its -X and +X ends, each through a door in the middle of the end wall.
    Expected (fixed before the shape rule was run): three regions (the corridor and the two rooms)
    and the two doors the chokepoints; a pilaster leaves the corridor one space, as a designer sees it.

    Args:
        length: length of the corridor, metres.
        width: clear width of the corridor, metres.
        narrow: clear width of the corridor beside a pilaster, metres.
        door_width: clear width of the two doors, metres.
    """
    if not door_width < width or not narrow < width or length < 12.0:
        raise ValueError("need door_width < width, narrow < width and length >= 12")
    s, t, mid, jut = float(length), WALL_THICKNESS, width / 2, width - narrow
    rooms = [(0.0, s, 0.0, width, 0.0), (-8.0 - t, -t, mid - 4.0, mid + 4.0, 0.0),
             (s + t, s + t + 8.0, mid - 4.0, mid + 4.0, 0.0)]
    spots = [s / 4, s / 2, 3 * s / 4]
    obstacles = [(x - 0.5, x + 0.5, *((0.0, jut) if i % 2 == 0 else (width - jut, width))) for i, x in enumerate(spots)]
    params = {"length": length, "width": width, "narrow": narrow, "door_width": door_width}
    expected = {"regions": 3, "chokepoints": 2, "articulation": (True, True)}
    return _build("pilaster_corridor", rooms, [(1, 0, PX, mid, door_width), (0, 2, PX, mid, door_width)], params,
                  expected, {"cycles": 0}, obstacles=obstacles)


@validate_call
def bent_corridor(
    arm: PositiveFloat = 16.0, width: PositiveFloat = 3.5, narrow: PositiveFloat = 2.5,
    door_width: PositiveFloat = 1.8,
) -> SampleLevel:
    """An L-shaped corridor narrowed by a pilaster in each arm, with a room at one end.

    Room 0 is the arm along +X, [0, arm] x [0, width]; room 1 the arm along +Z, ``width`` wide and
    ``arm`` long, beyond room 0's +X end and joined to it by an opening the corridor's full width (the
    corner). A 1 m pilaster on the outer wall halfway along each arm narrows it to ``narrow``. Room 2
    (8 x 8 m) lies beyond the end of the +Z arm, through a door. Expected (fixed before the shape rule
    was run): two regions (the corridor and the room) and the door the one chokepoint.

    Args:
        arm: length of each arm, metres.
        width: clear width of the corridor, metres.
        narrow: clear width of an arm beside its pilaster, metres.
        door_width: clear width of the door to the room, metres.
    """
    if not door_width < width or not narrow < width or arm < 2 * width:
        raise ValueError("need door_width < width, narrow < width and arm >= 2 width")
    s, t, jut = float(arm), WALL_THICKNESS, width - narrow
    x0 = s + t
    rooms = [(0.0, s, 0.0, width, 0.0), (x0, x0 + width, 0.0, s, 0.0),
             (x0 + width / 2 - 4.0, x0 + width / 2 + 4.0, s + t, s + t + 8.0, 0.0)]
    obstacles = [(s / 2 - 0.5, s / 2 + 0.5, 0.0, jut), (x0 + width - jut, x0 + width, s / 2 - 0.5, s / 2 + 0.5)]
    params = {"arm": arm, "width": width, "narrow": narrow, "door_width": door_width}
    doors = [(0, 1, PX, width / 2, width), (1, 2, PZ, x0 + width / 2, door_width)]
    expected = {"regions": 2, "chokepoints": 1, "articulation": (True,)}
    return _build("bent_corridor", rooms, doors, params, expected, {"cycles": 0}, obstacles=obstacles)


@validate_call
def door_in_corridor(
    length: PositiveFloat = 12.0, width: PositiveFloat = 3.5, door_width: PositiveFloat = 1.8,
) -> SampleLevel:
    """A straight corridor in two halves, parted by a wall across it with a door in its middle.

    Room 0 is the first half, [0, length] x [0, width]; room 1 the second, beyond its +X end. Expected (fixed before
    the shape rule was run): two regions and the door the one chokepoint. A designer puts a door across
    a corridor to part it: it can be shut, held or locked and it breaks the sight line, so it bounds
    two spaces as a door between rooms does; a pilaster does none of this.

    Args:
        length: length of each half, metres.
        width: clear width of the corridor, metres.
        door_width: clear width of the door, metres.
    """
    if not door_width < width:
        raise ValueError("need door_width < width")
    s, t = float(length), WALL_THICKNESS
    rooms = [(0.0, s, 0.0, width, 0.0), (s + t, 2 * s + t, 0.0, width, 0.0)]
    params = {"length": length, "width": width, "door_width": door_width}
    expected = {"regions": 2, "chokepoints": 1, "articulation": (True,)}
    return _build("door_in_corridor", rooms, [(0, 1, PX, width / 2, door_width)], params, expected, {"cycles": 0})


@validate_call
def gallery(
    length: PositiveFloat = 20.0, depth: PositiveFloat = 5.0, corridor_width: PositiveFloat = 3.5,
    door_width: PositiveFloat = 1.8,
) -> SampleLevel:
    """A long gallery beside a corridor as long, joined through a door in the middle of their shared wall.

    Room 0 is the corridor, [0, length] x [0, corridor_width]; room 1 the gallery, ``length`` x ``depth``,
    beyond its +Z wall. Both are long for their width, as the ring's pieces are. Expected (fixed before
    the shape rule was run): two regions and the door the one chokepoint.

    Args:
        length: length of the corridor and of the gallery, metres.
        depth: clear depth of the gallery, metres.
        corridor_width: clear width of the corridor, metres.
        door_width: clear width of the door, metres.
    """
    if door_width >= length:
        raise ValueError("need door_width < length")
    s, t, w = float(length), WALL_THICKNESS, float(corridor_width)
    rooms = [(0.0, s, 0.0, w, 0.0), (0.0, s, w + t, w + t + depth, 0.0)]
    params = {"length": length, "depth": depth, "corridor_width": corridor_width, "door_width": door_width}
    expected = {"regions": 2, "chokepoints": 1, "articulation": (True,)}
    return _build("gallery", rooms, [(0, 1, PZ, s / 2, door_width)], params, expected, {"cycles": 0})


@validate_call
def two_doors_to_a_corridor(
    length: PositiveFloat = 24.0, corridor_width: PositiveFloat = 3.0, door_width: PositiveFloat = 2.0,
    spacing: PositiveFloat = 4.0,
) -> SampleLevel:
    """A room with two doors to the same corridor, and a room behind a door at each end of the corridor.

    The corridor runs along +X, [0, length] x [0, corridor_width], as two segments (rooms 0 and 1) joined by an
    opening its full width at x = 10; the 8 x 6 m room beyond its +Z wall is two halves (rooms 2 and 3) joined
    along their whole shared side, one door ``door_width`` wide from each half to the segment beside it, the
    doors' centres ``spacing`` apart around x = 10 (2 m by default, where the held-out level had 1.6 m: turned by
    45 degrees the navmesh closes 1.6 m doors); rooms 4 and 5 (8 x 8 m) lie beyond the corridor's -X and +X
    ends through 1.8 m doors. Expected (fixed before the level was first analysed, held-out round of 3 December
    2026): 4 regions (corridor, room, two end rooms), 4 chokepoints; the room's two doors are no articulations
    (closing one leaves the other), the end doors are.

    Args:
        length: length of the corridor, metres (at least 16).
        corridor_width: clear width of the corridor, metres.
        door_width: clear width of each of the room's two doors, metres.
        spacing: distance between the centres of the room's two doors, metres.
    """
    if length < 16.0 or not door_width < spacing < 8.0 - door_width or corridor_width <= 1.8:
        raise ValueError("need length >= 16, door_width < spacing < 8 - door_width and corridor_width > 1.8")
    s, t, w = float(length), WALL_THICKNESS, float(corridor_width)
    mid = w / 2
    rooms = [(0.0, 10.0, 0.0, w, 0.0), (10.0 + t, s, 0.0, w, 0.0),
             (6.0, 10.0, w + t, w + t + 6.0, 0.0), (10.0 + t, 14.0, w + t, w + t + 6.0, 0.0),
             (-8.0 - t, -t, mid - 4.0, mid + 4.0, 0.0), (s + t, s + t + 8.0, mid - 4.0, mid + 4.0, 0.0)]
    doors = [(0, 2, PZ, 10.0 - spacing / 2 + t / 2, door_width), (1, 3, PZ, 10.0 + spacing / 2 + t / 2, door_width),
             (4, 0, PX, mid, 1.8), (1, 5, PX, mid, 1.8), (0, 1, PX, mid, w), (2, 3, PX, w + t + 3.0, 6.0)]
    params = {"length": length, "corridor_width": corridor_width, "door_width": door_width, "spacing": spacing}
    expected = {"regions": 4, "chokepoints": 4, "articulation": (False, False, True, True)}
    return _build("two_doors_to_a_corridor", rooms, doors, params, expected, {"cycles": 1})


@validate_call
def shelving_warehouse(
    aisles: tuple[PositiveFloat, ...] = (2.4, 3.0, 3.6, 3.0, 2.4), rack_depth: PositiveFloat = 1.2,
    rack_length: PositiveFloat = 14.0, door_width: PositiveFloat = 2.0,
) -> SampleLevel:
    """A 32 x 24 m warehouse hall with a row of full-height shelving racks, and an office off it through a door.

    ``len(aisles) + 1`` racks ``rack_depth`` deep (x) and ``rack_length`` long (z, from z = 5) stand from x = 4,
    ``aisles[i]`` apart (clear width between racks i and i + 1); the racks are obstacles larger than
    ``obstacle_area``, walls to the split. The office (room 1, 6 x 6 m) lies beyond the hall's +X wall through a door
    ``door_width`` wide at z = 3. Expected (fixed before the level was first analysed, held-out round of 3 December
    2026): 2 regions and the door the one chokepoint: the aisles are part of the hall, as a lecture hall's are.
    Metadata ``racks``: ``{"x0", "x1", "z0", "z1"}`` of each rack.

    Args:
        aisles: clear width of each aisle between two racks, metres.
        rack_depth: depth of a rack along x, metres.
        rack_length: length of a rack along z, metres (at most 17).
        door_width: clear width of the office door, metres.
    """
    if rack_length > 17.0 or 4.0 + (len(aisles) + 1) * rack_depth + sum(aisles) > 30.0 or door_width >= 6.0:
        raise ValueError("the racks must leave 2 m of the hall free on every side and door_width must be < 6")
    x0 = 4.0 + np.concatenate([[0.0], np.cumsum(np.asarray(aisles) + rack_depth)])
    racks = [(float(x), float(x) + rack_depth, 5.0, 5.0 + rack_length) for x in x0]
    t = WALL_THICKNESS
    rooms = [(0.0, 32.0, 0.0, 24.0, 0.0), (32.0 + t, 38.0 + t, 0.0, 6.0, 0.0)]
    params = {"aisles": list(aisles), "rack_depth": rack_depth, "rack_length": rack_length, "door_width": door_width}
    expected = {"regions": 2, "chokepoints": 1, "articulation": (True,)}
    return _build("shelving_warehouse", rooms, [(0, 1, PX, 3.0, door_width)], params, expected,
                  {"racks": tuple(_rect(*rack) for rack in racks), "cycles": len(racks)}, obstacles=racks)


def dungeon_shares(level: SampleLevel, chokepoints: list[dict[str, Any]], regions: list[dict[str, Any]],
                   navmesh: Any, turn: np.ndarray | None = None) -> tuple[float, float]:
    """How well chokepoints and regions found on a ``dungeon`` match its generated corridors and rooms.

    Returns (share of corridors with a chokepoint in them, share of rooms whose
    centre lies in a region no other room's centre lies in). A corridor's box
    runs between the two rooms' facing walls, 1 m into each room (a mouth), across
    the band both rooms cover. Chokepoints and regions are the records of the
    ``chokepoints`` and ``regions`` analyzers; ``navmesh`` the run's navmesh.
    ``turn``: the (4, 4) transform the analysed mesh had from ``level``'s (e.g.
    :func:`g2s_plugins.samples.pieces.yaw_about_centre`), so the layout is
    turned with it; None when the level was analysed as generated.
    """
    import trimesh  # imported where used, as in levels.py: `g2s plugins` lists the rooms without it

    turn = np.eye(4) if turn is None else np.asarray(turn, dtype=np.float64)
    labels = np.full(navmesh.polygon_count, -1)
    for region in regions:
        labels[region["polygons"]] = region["id"]
    centres = trimesh.transform_points(np.asarray(level.metadata["room_centres"], dtype=np.float64), turn)
    room_region = np.array([labels[navmesh.nearest_poly(c, extents=(3.0, 1.0, 3.0))[0]] for c in centres])
    values, counts = np.unique(room_region, return_counts=True)
    own = np.isin(room_region, values[(counts == 1) & (values >= 0)])
    bounds = np.asarray(level.metadata["room_bounds"])  # x0, x1, z0, z1
    slots = np.asarray(level.metadata["slots"])
    found = np.asarray([c["position"] for c in chokepoints], dtype=np.float64).reshape(-1, 3)
    found = trimesh.transform_points(found, np.linalg.inv(turn))[:, [0, 2]]  # back into the layout's frame
    located = 0
    for a, b in level.metadata["corridors"]:
        axis = 0 if slots[a, 0] != slots[b, 0] else 1  # the corridor runs along x (0) or z (1)
        other = 1 - axis
        first, second = sorted((a, b), key=lambda i: slots[i, axis])
        along = (bounds[first, 2 * axis + 1] - 1.0, bounds[second, 2 * axis] + 1.0)
        across = (max(bounds[a, 2 * other], bounds[b, 2 * other]), min(bounds[a, 2 * other + 1], bounds[b, 2 * other + 1]))
        inside = ((found[:, axis] >= along[0]) & (found[:, axis] <= along[1])
                  & (found[:, other] >= across[0]) & (found[:, other] <= across[1]))
        located += bool(inside.any())
    return located / max(len(level.metadata["corridors"]), 1), float(own.mean())


SAMPLES: dict[str, Callable[..., SampleLevel]] = {
    "two_rooms_one_door": two_rooms_one_door,
    "room_with_two_doors": room_with_two_doors,
    "loop_of_four_rooms": loop_of_four_rooms,
    "floors_joined_by_ramp": floors_joined_by_ramp,
    "lecture_hall": lecture_hall,
    "ring_corridor": ring_corridor,
    "catwalk": catwalk,
    "offices": offices,
    "dead_end_corridor": dead_end_corridor,
    "pilaster_corridor": pilaster_corridor,
    "bent_corridor": bent_corridor,
    "door_in_corridor": door_in_corridor,
    "gallery": gallery,
    "two_doors_to_a_corridor": two_doors_to_a_corridor,
    "shelving_warehouse": shelving_warehouse,
}
"""The room samples, registered in :data:`g2s_plugins.samples.levels.SAMPLES`."""
