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
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
import trimesh
from pydantic import PositiveFloat, validate_call

from g2s_plugins.samples.levels import (
    NX,
    NZ,
    PX,
    PZ,
    WALL_HEIGHT,
    WALL_THICKNESS,
    RampSlope,
    SampleLevel,
    _LevelBuilder,
    _no_apertures,
    _ramp_meta,
    _ramp_run,
)

_OPPOSITE = {PX: NX, PZ: NZ}


def _build(name: str, rooms: list[tuple[float, float, float, float, float]],
           doors: list[tuple[int, int, int, float, float]], params: dict[str, Any],
           expected: dict[str, Any], extra: dict[str, Any] | None = None,
           ramp: tuple[float, float] | None = None) -> SampleLevel:
    """Rooms ``(x0, x1, z0, z1, floor y)`` and doors ``(room a, room b, side of a, centre, width)``.

    A door sits on side ``PX`` or ``PZ`` of room ``a``; room ``b`` starts one
    wall thickness beyond it. ``centre`` is the door's centre along the wall
    (world z for ``PX``, world x for ``PZ``). ``ramp = (centre z, width)`` joins
    room 0's +X wall to room 1's -X wall by a walled ramp along +X.
    """
    b = _LevelBuilder()
    bounds = np.array([r[:4] for r in rooms], dtype=np.float64)
    heights = np.array([r[4] for r in rooms], dtype=np.float64)
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
}
"""The room samples, registered in :data:`g2s_plugins.samples.levels.SAMPLES`."""
