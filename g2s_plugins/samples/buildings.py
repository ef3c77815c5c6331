"""A multi-storey sample level: storeys of rooms along a corridor, joined by stairwells.

Dungeons (:func:`g2s_plugins.samples.levels.dungeon`) have one floor;
:func:`building` stacks ``floors`` storeys, so that a structure must climb
stairs and a level's traffic runs through a few stairwells. Built like the
other samples (:mod:`g2s_plugins.samples.levels`): floor slabs, walls
outside the floors they bound, doors as gaps with a floor, stairs as solid
steps. Metres, Y up.
"""

from __future__ import annotations

import math
from typing import Annotated, Any

import numpy as np
from pydantic import Field, NonNegativeInt, PositiveFloat, PositiveInt, validate_call

from g2s_plugins.samples.levels import (
    NX,
    NZ,
    PX,
    PZ,
    SLAB_THICKNESS,
    WALL_HEIGHT,
    WALL_THICKNESS,
    Probability,
    SampleLevel,
    _LevelBuilder,
    _no_apertures,
)

MAX_RISER = 0.15
"""Highest stair riser, metres. Recast (0.25 m cells and a 0.375 m climb in 0.125 m cells for the design agent)
drops a cell as a ledge when its neighbours, 0.5 m apart, differ by more than the climb, and 0.3 m treads put two
risers between them: 0.25 and 0.2 m risers left every flight unwalkable, 0.17 and 0.15 m joined the storeys
(measured)."""

TREAD = 0.3
"""Depth of a stair tread, metres (with ``MAX_RISER``, a flight rises about 27 degrees)."""

STAIR_WIDTH = 2.0
"""Clear width of a stair flight, metres."""

LANDING = 2.0
"""Length of the landings at both ends of a flight, metres."""

STAIR_DOOR = 2.0
"""Width of a stairwell's door to the corridor, metres."""

MIN_STOREY = 3.3
"""Least height from one storey's floor to the next, metres: a wall (3 m) and the slab above (0.2 m) fit, 0.1 m apart."""

MIN_LOBBY = 2.5
"""Least depth of a stairwell's lobby, metres (Recast's navmesh collapsed a 2 m lobby to a line, measured)."""

_DOOR_MARGIN = 0.3  # metres of wall kept between a door and a room's corner


@validate_call
def building(
    seed: NonNegativeInt = 0,
    floors: PositiveInt = 3,
    rooms: Annotated[int, Field(ge=2)] = 10,
    stairwells: NonNegativeInt = 1,
    storey: Annotated[float, Field(ge=MIN_STOREY)] = 3.5,
    corridor_width: PositiveFloat = 2.4,
    room_depth: Annotated[float, Field(ge=2 * (STAIR_WIDTH + WALL_THICKNESS) + MIN_LOBBY)] = 8.0,
    room_min: PositiveFloat = 4.0,
    room_max: PositiveFloat = 7.0,
    door_min: PositiveFloat = 1.5,
    door_max: PositiveFloat = 1.8,
    connections: Probability = 0.3,
) -> SampleLevel:
    """Storeys of rooms on both sides of a corridor, joined by switchback stairwells.

    Layout: every storey has a straight corridor along +X (x in [0, length],
    z in [0, corridor_width]) with a row of rooms ``room_depth`` deep on each
    side, one wall thickness (0.2 m) away. The north row (+Z) holds the
    stairwells, spread evenly along it, and ``rooms // 2`` rooms; the south
    row the other rooms. Room widths along X are random in [room_min,
    room_max] (north row, the same on every storey) or a random split of
    the building's length (south row, drawn again for every storey). Every
    room has a door to the corridor ``door_min``-``door_max`` wide (uniform)
    at a random place along its wall; two neighbouring rooms of a row share
    a door of that width with probability ``connections``. Storey k's floor
    is at y = k ``storey``.

    A stairwell is ``2 x 2 + run`` m along X, where run = steps x 0.3 m,
    steps = ceil(storey / 0.15) (risers of at most 0.15 m, so a flight rises
    about 27 degrees, walkable for the design agent; see ``MAX_RISER``).
    It holds two 2 m wide strips along its north wall, walled from each other and from the rest of
    the stairwell (the lobby, reached by a 2 m door from the corridor) over
    the run, open to 2 m landings at both ends. Flight k joins storey k
    to k + 1: in the north strip rising along +X for even k, in the inner
    strip rising along -X for odd k (a switchback), and storey k + 1's slab
    has a hole over it. No roof; the corridor's ends are walled.

    Numpy-built and fast: 12 storeys of 280 rooms (about 20k navmesh
    polygons) take about a second. Same arguments, same mesh bytes
    (``numpy.random.default_rng(seed)``).

    Args:
        seed: seed of the random generator.
        floors: number of storeys (a count).
        rooms: rooms per storey, stairwells not counted (a count).
        stairwells: stairwells joining every storey to the next (a count, >= 1 when floors > 1).
        storey: height from one storey's floor to the next, metres.
        corridor_width: clear width of each storey's corridor, metres.
        room_depth: depth of every room across the corridor, metres (fits a stairwell; at 7 m Recast split some, docs/samples.md).
        room_min: smallest room width along the corridor, metres.
        room_max: largest room width along the corridor, metres.
        door_min: narrowest door, metres (the design agent needs 1.5 m: 1.4 m doors closed, measured).
        door_max: widest door, metres.
        connections: probability that two neighbouring rooms share a door.

    Openings: none (closed). Metadata: ``floor_heights`` (storey floors, m),
    ``length`` (the corridor's, m), ``rooms`` (tuple of ``{"x0", "x1",
    "z0", "z1", "y"}`` room rectangles, storey by storey, stairwells not
    included), ``rooms_per_floor``, ``stairwells`` (tuple of ``{"x0", "x1",
    "z0", "z1"}``, the same on every storey), ``flights`` (floors - 1 per
    stairwell), ``steps`` and ``riser`` (m) per flight, ``corridor_doors``
    and ``room_doors`` (counts, all storeys, stairwell doors included in
    the first), ``floor_area`` (m²: the floors' and stair treads' top
    surfaces in plan, a flight counted as the floor under it, before the
    agent's radius is taken off), ``components``
    (1), ``cycles`` (None: not counted).
    """
    params = dict(locals())
    if floors > 1 and stairwells < 1:
        raise ValueError(f"a building of {floors} floors needs stairwells >= 1")
    t = WALL_THICKNESS
    if not door_min <= door_max <= room_min - 2 * _DOOR_MARGIN:
        raise ValueError(f"need door_min <= door_max <= room_min - {2 * _DOOR_MARGIN:g}")
    if room_max < room_min:
        raise ValueError(f"room_max ({room_max}) must be >= room_min ({room_min})")
    rng = np.random.default_rng(seed)
    steps = math.ceil(storey / MAX_RISER - 1e-9)
    riser, run = storey / steps, steps * TREAD
    well = 2 * LANDING + run

    # North row: rooms and stairwells, fixed for every storey; the building's length follows from it.
    n_south, n_north = (rooms + 1) // 2, rooms // 2
    slots = n_north + stairwells
    is_well = np.zeros(slots, dtype=bool)
    is_well[[round((j + 0.5) * slots / stairwells - 0.5) for j in range(stairwells)]] = True
    north_widths = np.where(is_well, well, rng.uniform(room_min, room_max, slots))
    length = max(float(north_widths.sum()) + (slots - 1) * t, n_south * (room_min + room_max) / 2 + (n_south - 1) * t)
    north_widths[~is_well] += (length - north_widths.sum() - (slots - 1) * t) / n_north
    north_x0 = np.concatenate([[0.0], np.cumsum(north_widths + t)[:-1]])
    z_south, z_north = (-t - room_depth, -t), (corridor_width + t, corridor_width + t + room_depth)

    b = _LevelBuilder()
    room_rects: list[dict[str, float]] = []
    wells = [{"x0": float(x0), "x1": float(x0 + w), "z0": z_north[0], "z1": z_north[1]}
             for x0, w in zip(north_x0[is_well], north_widths[is_well])]
    corridor_doors = room_doors = 0
    for k in range(floors):
        y = k * storey
        south_widths = room_min + (length - (n_south - 1) * t - n_south * room_min) * rng.dirichlet(np.ones(n_south))
        south_x0 = np.concatenate([[0.0], np.cumsum(south_widths + t)[:-1]])
        b.floors(0.0, length, 0.0, corridor_width, y)
        b.boxes(np.array([[-t, y - SLAB_THICKNESS, -t], [length, y - SLAB_THICKNESS, -t]]),
                np.array([[0.0, y + WALL_HEIGHT, corridor_width + t], [length + t, y + WALL_HEIGHT, corridor_width + t]]))
        for x0s, widths, (z0, z1), door_side, wells_here in (
            (south_x0, south_widths, z_south, PZ, np.zeros(n_south, dtype=bool)),
            (north_x0, north_widths, z_north, NZ, is_well),
        ):
            bounds = np.column_stack([x0s, x0s + widths, np.full(len(x0s), z0), np.full(len(x0s), z1)])
            apertures = _no_apertures(len(bounds))
            door_width = np.where(wells_here, STAIR_DOOR, rng.uniform(door_min, door_max, len(bounds)))
            slack = np.maximum(widths - door_width - 2 * _DOOR_MARGIN, 0.0)
            centre = x0s + _DOOR_MARGIN + door_width / 2 + np.where(wells_here, slack / 2, rng.random(len(bounds)) * slack)
            apertures[:, door_side] = np.column_stack([centre - door_width / 2, centre + door_width / 2,
                                                       np.zeros(len(bounds)), np.full(len(bounds), WALL_HEIGHT)])
            wall_z = (z1, z1 + t) if door_side == PZ else (z0 - t, z0)
            b.floors(centre - door_width / 2, centre + door_width / 2, wall_z[0], wall_z[1], y)
            corridor_doors += len(bounds)
            inner = ~wells_here[:-1] & ~wells_here[1:] & (rng.random(len(bounds) - 1) < connections)
            inner_width = rng.uniform(door_min, door_max, len(bounds) - 1)
            inner_centre = z0 + _DOOR_MARGIN + inner_width / 2 + rng.random(len(bounds) - 1) * np.maximum(
                room_depth - inner_width - 2 * _DOOR_MARGIN, 0.0)
            for i in np.nonzero(inner)[0]:
                gap = (inner_centre[i] - inner_width[i] / 2, inner_centre[i] + inner_width[i] / 2, 0.0, WALL_HEIGHT)
                apertures[i, PX] = apertures[i + 1, NX] = gap
                b.floors(bounds[i, 1], bounds[i, 1] + t, gap[0], gap[1], y)
            room_doors += int(inner.sum())
            rooms_here = ~wells_here
            b.floors(bounds[rooms_here, 0], bounds[rooms_here, 1], bounds[rooms_here, 2], bounds[rooms_here, 3], y)
            b.room_walls(bounds, y, apertures)
            room_rects += [{"x0": float(r[0]), "x1": float(r[1]), "z0": float(r[2]), "z1": float(r[3]), "y": y}
                           for r in bounds[rooms_here]]
        for well_rect in wells:
            _stairwell_storey(b, well_rect, k, floors, storey, steps, riser)
    for well_rect in wells:  # the walls along the flights, through every storey
        xs, z1 = well_rect["x0"] + LANDING, well_rect["z1"]
        for z_wall in (z1 - STAIR_WIDTH - t, z1 - 2 * STAIR_WIDTH - 2 * t):
            b.boxes(np.array([[xs, -SLAB_THICKNESS, z_wall]]),
                    np.array([[xs + run, (floors - 1) * storey + WALL_HEIGHT, z_wall + t]]))

    meta: dict[str, Any] = {
        "params": params,
        "floor_heights": tuple(float(k * storey) for k in range(floors)),
        "length": float(length),
        "rooms": tuple(room_rects),
        "rooms_per_floor": rooms,
        "stairwells": tuple(wells),
        "flights": (floors - 1) * stairwells,
        "steps": steps,
        "riser": float(riser),
        "corridor_doors": corridor_doors,
        "room_doors": room_doors,
        "components": 1,
        "cycles": None,
    }
    return b.build("building", [], meta)


def _stairwell_storey(b: _LevelBuilder, well: dict[str, float], k: int, floors: int, storey: float,
                      steps: int, riser: float) -> None:
    """Storey ``k`` of a stairwell: its floor (less the hole over the flight arriving from below) and the
    flight up to storey ``k + 1``. Strips: north (flights of even k, up along +X), inner (odd k, up along -X)."""
    t, y = WALL_THICKNESS, k * storey
    x0, x1, z0, z1 = well["x0"], well["x1"], well["z0"], well["z1"]
    xs, xe = x0 + LANDING, x0 + LANDING + steps * TREAD
    strips = ((z1 - STAIR_WIDTH, z1), (z1 - 2 * STAIR_WIDTH - t, z1 - STAIR_WIDTH - t))
    floor = [(x0, xs, z0, z1), (xe, x1, z0, z1)]
    hole = strips[(k - 1) % 2] if k else None
    cuts = [z0, z1] if hole is None else [z0, hole[0], hole[1], z1]
    floor += [(xs, xe, a, c) for a, c in zip(cuts[::2], cuts[1::2])]
    for rect in floor:
        b.floors(*rect, y)
    b.floor_area -= 2 * t * (xe - xs)  # under the two walls along the flights
    if k == floors - 1:
        return
    sz0, sz1 = strips[k % 2]
    i = np.arange(steps)
    if k % 2 == 0:  # up along +X
        sx0, sx1 = xs + i * TREAD, np.full(steps, xe)
    else:  # up along -X
        sx0, sx1 = np.full(steps, xs), xe - i * TREAD
    b.boxes(np.column_stack([sx0, np.full(steps, y - SLAB_THICKNESS), np.full(steps, sz0)]),
            np.column_stack([sx1, y + (i + 1) * riser, np.full(steps, sz1)]))


SAMPLES = {"building": building}
"""The multi-storey samples, registered in :data:`g2s_plugins.samples.levels.SAMPLES`."""
