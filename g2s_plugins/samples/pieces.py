"""Procedural map pieces with known openings: the cases entry/exit detection must get right.

Each factory builds one modular map piece in code and returns a
:class:`~g2s_plugins.samples.levels.SampleLevel` whose ``openings`` are the
connectors a designer would place: where the piece meets its neighbours, at
its outer extent, facing out. Every case reproduces one way a detector goes
wrong on real pieces (see docs/entry_exit.md):

* :func:`doorway_room`: doorways 1.2 to 2 m wide in 0.6 m thick walls (Recast
  leaves a V-shaped notch of navmesh in each);
* :func:`curb_platform`: a floor rimmed by a 0.3 m curb (lower than the
  agent's climb) with two gaps; only the gaps are openings;
* :func:`wall_tops`: a corridor between a 3.7 m high thick wall (its top is
  walkable but unreachable) and a 0.3 m high bench (reachable, walled
  behind); only the corridor's ends are openings;
* :func:`stair_deck`: a ground floor and an upper deck 3 m up, joined by
  stairs with 0.25 m risers; one opening on each level;
* :func:`cross_platform`: a wall-less cross-shaped slab; the openings are the
  four arm ends, not the arms' sides;
* :func:`chamfered_platform`: a wall-less slab with chamfered corners; the
  openings are its four sides, the chamfers are narrower than the agent.
* :func:`sloped_corridor`: a corridor rising 10 degrees, a doorway in each end
  wall; at the lower one the floor slopes down out of the piece (found after
  the held-out families).
* :func:`roofed_corridor`: a corridor under a flat roof whose walkable top
  outweighs the floor it covers (found in the fourth round of piece kinds).
* :func:`twin_doors`: two doorways side by side, a pier of wall between them
  narrower than the agent; each is an opening (found in the fifth round).
* :func:`stair_exit`: stairs with 0.2 m risers leaving a room at their top,
  the piece's edge (found in the fifth round).

The held-out families (:data:`HELD_OUT`) are shapes designers build that the
rules were not measured on when they were set (docs/entry_exit.md, "Piece
shapes it was not tuned on"): :func:`corner_corridor`, :func:`t_junction`,
:func:`bridge`, :func:`windowed_room`, :func:`threshold_door`,
:func:`open_side_room`, :func:`thick_wall_door`, :func:`two_storey`,
:func:`cluttered_room` and :func:`narrow_door_room`; their known openings were
chosen as a designer would before the detector ran on them.

Units, frame and solids follow :mod:`g2s_plugins.samples.levels` (metres, Y
up, outward-facing hexahedra, floors' tops at the floor height). The pieces
are designed for :data:`PIECE_AGENT`, the agent of ``configs/map_piece.yaml``.
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import TYPE_CHECKING, Annotated

import numpy as np
from pydantic import Field, NonNegativeFloat, PositiveFloat, PositiveInt, validate_call

from g2s_core.model import Vec3

from g2s_plugins.samples.levels import SLAB_THICKNESS, SampleLevel, _LevelBuilder, _opening, _rect, _sloped_blocks
from g2s_plugins.vectors import vec3

if TYPE_CHECKING:
    import trimesh

PIECE_AGENT: dict[str, float] = {"radius": 0.4, "height": 2.0, "max_climb": 0.4, "max_slope_deg": 60.0}
"""The agent the pieces are designed for (metres, degrees): that of ``configs/map_piece.yaml``."""

TALL = 3.0
"""Height of the pieces' walls above their floor, metres (more than the agent's 2 m)."""

_W, _E, _S, _N = (-1.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 0.0, -1.0), (0.0, 0.0, 1.0)


def _box(b: _LevelBuilder, x0: float, x1: float, y0: float, y1: float, z0: float, z1: float) -> None:
    b.boxes(np.array([[x0, y0, z0]]), np.array([[x1, y1, z1]]))


def _prism(b: _LevelBuilder, x0z0: tuple, x1z0: tuple, x0z1: tuple, x1z1: tuple, y0: float, y1: float) -> None:
    """A vertical prism over a convex quad given as its (x, z) corners in box order."""
    quad = [x0z0, x1z0, x0z1, x1z1]
    corners = np.array(
        [[quad[(i & 1) + 2 * ((i >> 2) & 1)][0], (y0, y1)[(i >> 1) & 1], quad[(i & 1) + 2 * ((i >> 2) & 1)][1]]
         for i in range(8)],
        dtype=np.float64,
    )
    b.hexahedra(corners[None])


def _meta(params: dict, floors: tuple[float, ...], components: int = 1) -> dict:
    return {"params": params, "floor_heights": floors, "components": components, "piece_agent": dict(PIECE_AGENT)}


_HEADING = {"W": _W, "E": _E, "S": _S, "N": _N}


def _door(side: str, centre: float, door: float, width: float, depth: float, wall: float, floor: float = 0.0):
    """The known opening of a doorway in a wall of :func:`_walls`: on the wall's outer face, facing out.

    ``side`` is one of ``"WESN"``; ``centre`` the doorway's centre along the side (world Z on the
    west and east walls, world X on the south and north ones), ``door`` its width and ``floor`` the
    height of its floor, metres.
    """
    position = {"W": (-wall, floor, centre), "E": (width + wall, floor, centre),
                "S": (centre, floor, -wall), "N": (centre, floor, depth + wall)}[side]
    return _opening(position, _HEADING[side], door)


def _wall_boxes(
    width: float, depth: float, wall: float, gaps: dict[str, list[tuple[float, float, float, float]]],
    height: float = TALL, floor: float = 0.0,
) -> list[tuple[float, float, float, float, float, float]]:
    """The boxes ``(x0, x1, y0, y1, z0, z1)``, metres, of walls ``wall`` thick and ``height`` high round the clear
    floor [0, width] x [0, depth] whose top is at ``floor``, with gaps; from the slab's underside
    (``SLAB_THICKNESS`` below the floor) up.

    ``gaps`` maps a side (``"W"``, ``"E"``, ``"S"``, ``"N"``) to its gaps ``(a0, a1, bottom, top)``,
    metres: the range along the side (world Z on the west and east walls, world X on the others,
    the walls' outer corners included) and the heights above the floor between which the wall is
    open: 0 and ``height`` for a doorway open to the sky, a lintel below ``height``, a sill or a
    threshold step above 0. The gaps of one side must not overlap along it; a side with no gap
    is a whole wall, one gap spanning it leaves it open (no box of no length).
    """
    x0, x1, z0, z1 = -wall, width + wall, -wall, depth + wall
    across = {"W": (x0, 0.0), "E": (width, x1), "S": (z0, 0.0), "N": (depth, z1)}
    boxes = []

    def part(side: str, a0: float, a1: float, y0: float, y1: float) -> None:
        c0, c1 = across[side]
        boxes.append((c0, c1, y0, y1, a0, a1) if side in "WE" else (a0, a1, y0, y1, c0, c1))

    bottom_of_slab, top_of_wall = floor - SLAB_THICKNESS, floor + height
    for side in "WESN":
        along = (z0, z1) if side in "WE" else (x0, x1)
        runs = sorted(gaps.get(side, ()))
        cuts = [along[0], *[v for g in runs for v in g[:2]], along[1]]
        for a0, a1 in zip(cuts[0::2], cuts[1::2]):
            if a1 > a0:
                part(side, a0, a1, bottom_of_slab, top_of_wall)
        for a0, a1, bottom, top in runs:
            if bottom > 0:
                part(side, a0, a1, bottom_of_slab, floor + bottom)
            if top < height:
                part(side, a0, a1, floor + top, top_of_wall)
    return boxes


def _walls(
    b: _LevelBuilder, width: float, depth: float, wall: float,
    gaps: dict[str, list[tuple[float, float, float, float]]], height: float = TALL,
) -> None:
    """Adds to ``b`` the walls of :func:`_wall_boxes` round a floor at height 0."""
    for box in _wall_boxes(width, depth, wall, gaps, height):
        _box(b, *box)


@validate_call
def doorway_room(
    width: PositiveFloat = 12.0, depth: PositiveFloat = 9.0, wall: PositiveFloat = 0.6,
    doors: tuple[float, ...] = (1.2, 1.5, 2.0, 1.5, 1.8),
) -> SampleLevel:
    """A walled room with up to five doorways.

    The floor slab runs under the walls to their outer faces, where the
    piece ends; a doorway is a full-height gap in the wall. Each opening is
    the doorway's outer face, as wide as the door.

    Args:
        width: clear floor inside the walls along X, metres.
        depth: clear floor inside the walls along Z, metres.
        wall: thickness of the walls, metres.
        doors: widths of the doorways, metres, in this order: west (centred),
            east (centred), south (a quarter of the width along), south (three
            quarters along), north (centred); fewer widths leave the last
            walls whole.
    """
    if not 1 <= len(doors) <= 5 or min(doors) <= 0:
        raise ValueError(f"doors must be 1 to 5 widths > 0, got {doors!r}")
    b = _LevelBuilder()
    x0, x1, z0, z1 = -wall, width + wall, -wall, depth + wall
    b.floors(x0, x1, z0, z1, 0.0)
    slots = [  # (side, centre along the side)
        ("W", depth / 2), ("E", depth / 2), ("S", width / 4), ("S", 3 * width / 4), ("N", width / 2),
    ][: len(doors)]
    gaps: dict[str, list[tuple[float, float]]] = {"W": [], "E": [], "S": [], "N": []}
    openings = []
    for (side, centre), door in zip(slots, doors):
        if door >= (depth if side in "WE" else width) / 2:
            raise ValueError(f"door {door} m does not fit the {side} wall")
        gaps[side].append((centre - door / 2, centre + door / 2))
        openings.append(_door(side, centre, door, width, depth, wall))
    _walls(b, width, depth, wall, {side: [(a0, a1, 0.0, TALL) for a0, a1 in runs] for side, runs in gaps.items()})
    params = {"width": width, "depth": depth, "wall": wall, "doors": tuple(doors)}
    meta = _meta(params, (0.0,))
    meta["floor"] = _rect(x0, x1, z0, z1)
    return b.build("doorway_room", openings, meta)


@validate_call
def curb_platform(
    length: PositiveFloat = 12.7, depth: PositiveFloat = 8.0, curb: PositiveFloat = 0.3,
    curb_width: PositiveFloat = 0.2, gap: PositiveFloat = 2.0,
) -> SampleLevel:
    """A wall-less platform rimmed by a curb, with a gap in the middle of each short side.

    The curb is lower than the agent's climb, so Recast (and probes cast
    higher than it) step over it; the platform's edge beyond it drops into
    the void. Openings: the two gaps (west and east).

    Args:
        length: the platform's extent along X, metres.
        depth: the platform's extent along Z (its short sides), metres.
        curb: the curb's height, metres.
        curb_width: the curb's width, metres.
        gap: width of each gap in the curb, metres.
    """
    if gap >= depth - 2 * curb_width:
        raise ValueError(f"gap {gap} m does not fit the {depth} m side")
    b = _LevelBuilder()
    b.floors(0.0, length, 0.0, depth, 0.0)
    c = curb_width
    _box(b, 0.0, length, 0.0, curb, 0.0, c)
    _box(b, 0.0, length, 0.0, curb, depth - c, depth)
    for xa, xb in ((0.0, c), (length - c, length)):
        _box(b, xa, xb, 0.0, curb, c, (depth - gap) / 2)
        _box(b, xa, xb, 0.0, curb, (depth + gap) / 2, depth - c)
    openings = [_opening((0.0, 0.0, depth / 2), _W, gap), _opening((length, 0.0, depth / 2), _E, gap)]
    params = {"length": length, "depth": depth, "curb": curb, "curb_width": curb_width, "gap": gap}
    return b.build("curb_platform", openings, _meta(params, (0.0,)))


@validate_call
def wall_tops(
    length: PositiveFloat = 12.0, width: PositiveFloat = 4.0, high: PositiveFloat = 3.7, low: PositiveFloat = 0.3,
    thick: PositiveFloat = 2.0,
) -> SampleLevel:
    """A corridor open at both ends between two thick walls: one high, one low (a bench).

    The high wall's top is walkable for Recast but unreachable from the
    floor (no opening on it). The bench is reachable (lower than the climb);
    a full-height wall stands behind it, and it stops ``thick`` short of the
    corridor's ends, so it holds no opening either; the floor's edge beside
    it, between the bench and each end, is open but lies ``thick + 0.2`` m
    inside the piece's extent. Openings: the corridor's west and east ends.

    Args:
        length: the corridor's length along X, metres.
        width: the corridor's width between the two walls, metres.
        high: height of the high wall, metres.
        low: height of the bench, metres.
        thick: thickness of both walls, metres.
    """
    if length <= 2 * thick + 2:
        raise ValueError(f"length must exceed 2 * thick + 2, got {length}")
    b = _LevelBuilder()
    b.floors(0.0, length, 0.0, width, 0.0)
    _box(b, 0.0, length, -SLAB_THICKNESS, high, width, width + thick)
    _box(b, thick, length - thick, -SLAB_THICKNESS, low, -thick, 0.0)
    _box(b, thick, length - thick, -SLAB_THICKNESS, TALL, -thick - 0.2, -thick)
    _box(b, thick - 0.2, thick, -SLAB_THICKNESS, TALL, -thick - 0.2, 0.0)
    _box(b, length - thick, length - thick + 0.2, -SLAB_THICKNESS, TALL, -thick - 0.2, 0.0)
    openings = [_opening((0.0, 0.0, width / 2), _W, width), _opening((length, 0.0, width / 2), _E, width)]
    params = {"length": length, "width": width, "high": high, "low": low, "thick": thick}
    meta = _meta(params, (0.0, low), components=2)  # the high wall's top is an area of its own
    return b.build("wall_tops", openings, meta)


@validate_call
def stair_deck(
    floor_length: PositiveFloat = 8.0, deck_length: PositiveFloat = 4.0, width: PositiveFloat = 6.0,
    riser: PositiveFloat = 0.25, tread: PositiveFloat = 0.3, steps: PositiveInt = 12, stair_width: PositiveFloat = 2.0,
) -> SampleLevel:
    """A walled ground floor and a deck ``steps * riser`` higher, joined by straight stairs.

    The ground floor runs over x in [0, floor_length]; the deck is a solid
    podium over [floor_length, floor_length + deck_length] with parapets on
    its long sides. The stairs rise along +X against the north wall and end
    at the podium. Openings: the ground floor's west end and the deck's east
    end.

    Args:
        floor_length: length of the ground floor along X, metres.
        deck_length: length of the deck along X, metres.
        width: width of the ground floor and the deck, metres.
        riser: height of each step, metres.
        tread: depth of each step along X, metres.
        steps: number of steps.
        stair_width: width of the stairs, metres.
    """
    if steps * tread >= floor_length or stair_width >= width:
        raise ValueError("the stairs must fit the ground floor")
    top = steps * riser
    b = _LevelBuilder()
    x_deck = floor_length
    b.floors(0.0, x_deck, 0.0, width, 0.0)
    _box(b, x_deck, x_deck + deck_length, -SLAB_THICKNESS, top, 0.0, width)
    b.floor_area += deck_length * width
    x_stairs = x_deck - steps * tread
    for i in range(steps):
        _box(b, x_stairs + i * tread, x_deck, -SLAB_THICKNESS, (i + 1) * riser, width - stair_width, width)
    for z0, z1 in ((-0.2, 0.0), (width, width + 0.2)):
        _box(b, 0.0, x_deck, -SLAB_THICKNESS, top + TALL, z0, z1)
        _box(b, x_deck, x_deck + deck_length, top, top + 1.2, z0, z1)
    openings = [
        _opening((0.0, 0.0, width / 2), _W, width),
        _opening((x_deck + deck_length, top, width / 2), _E, width),
    ]
    params = {"floor_length": floor_length, "deck_length": deck_length, "width": width, "riser": riser,
              "tread": tread, "steps": steps, "stair_width": stair_width}
    return b.build("stair_deck", openings, _meta(params, (0.0, top)))


@validate_call
def cross_platform(
    hub: PositiveFloat = 6.0, arm_length: PositiveFloat = 5.0, arm_width: PositiveFloat = 3.0
) -> SampleLevel:
    """A wall-less cross: a square hub and four arms; the openings are the arm ends.

    Args:
        hub: side of the square hub, metres.
        arm_length: length of each arm beyond the hub, metres.
        arm_width: width of each arm, metres.
    """
    if arm_width > hub:
        raise ValueError(f"arm_width must be at most hub, got {arm_width}")
    b = _LevelBuilder()
    h, a, w = hub / 2, hub / 2 + arm_length, arm_width / 2
    b.floors(-h, h, -h, h, 0.0)
    b.floors(np.array([-a, h, -w, -w]), np.array([-h, a, w, w]),
             np.array([-w, -w, -a, h]), np.array([w, w, -h, a]), 0.0)
    openings = [_opening(p, d, arm_width) for p, d in
                (((-a, 0.0, 0.0), _W), ((a, 0.0, 0.0), _E), ((0.0, 0.0, -a), _S), ((0.0, 0.0, a), _N))]
    params = {"hub": hub, "arm_length": arm_length, "arm_width": arm_width}
    return b.build("cross_platform", openings, _meta(params, (0.0,)))


@validate_call
def chamfered_platform(
    length: PositiveFloat = 10.0, width: PositiveFloat = 5.0, chamfer: PositiveFloat = 0.45
) -> SampleLevel:
    """A wall-less slab with its corners cut at 45 degrees.

    The chamfers (``chamfer * sqrt(2)`` long) are narrower than the agent's
    diameter. Openings: the four straight sides between the chamfers.

    Args:
        length: the slab's extent along X, metres.
        width: the slab's extent along Z, metres.
        chamfer: how far each cut reaches along each side from the corner, metres.
    """
    if 2 * chamfer >= min(length, width):
        raise ValueError(f"chamfer {chamfer} m does not fit the slab")
    b = _LevelBuilder()
    c, y0 = chamfer, -SLAB_THICKNESS
    b.floors(c, length - c, 0.0, width, 0.0)
    _prism(b, (0.0, c), (c, 0.0), (0.0, width - c), (c, width), y0, 0.0)
    _prism(b, (length - c, 0.0), (length, c), (length - c, width), (length, width - c), y0, 0.0)
    b.floor_area += 2 * c * (width - c)
    openings = [
        _opening((0.0, 0.0, width / 2), _W, width - 2 * c),
        _opening((length, 0.0, width / 2), _E, width - 2 * c),
        _opening((length / 2, 0.0, 0.0), _S, length - 2 * c),
        _opening((length / 2, 0.0, width), _N, length - 2 * c),
    ]
    params = {"length": length, "width": width, "chamfer": chamfer}
    return b.build("chamfered_platform", openings, _meta(params, (0.0,)))


@validate_call
def sloped_corridor(
    length: PositiveFloat = 12.0, width: PositiveFloat = 2.4, wall: PositiveFloat = 0.3, door: PositiveFloat = 1.6,
    slope: Annotated[float, Field(gt=0, lt=45)] = 10.0,
) -> SampleLevel:
    """A corridor rising ``slope`` degrees along +X, each end closed by a wall with a doorway.

    The floor (a wedge) and the walls (``TALL`` above the floor everywhere)
    rise with the corridor; the lower doorway opens onto nothing, the floor
    sloping down out of the piece. Found after the held-out families: the
    floor's tilted normal put the lower door's edge and extension outside its
    jambs (docs/entry_exit.md, "Piece kinds measured after the held-out
    set"). Openings: both doorways' outer faces, at the floor's height there.

    Args:
        length: clear length between the end walls along X, metres.
        width: clear width between the side walls along Z, metres.
        wall: thickness of all walls, metres.
        door: width of both doorways, metres.
        slope: the floor's rise, degrees.
    """
    if door >= width:
        raise ValueError(f"door ({door:g} m) must be narrower than the corridor ({width:g} m)")
    rise = math.tan(math.radians(slope))
    x0, x1 = -wall, length + wall
    y0, y1 = x0 * rise, x1 * rise
    bottom = y0 - SLAB_THICKNESS
    b = _LevelBuilder()
    b.hexahedra(_sloped_blocks(x0, x1, -wall, width + wall, bottom, y0, y1))
    b.floor_area += width * length / math.cos(math.radians(slope))
    sides = [(x0, x1, -wall, 0.0), (x0, x1, width, width + wall)]
    lo, hi = width / 2 - door / 2, width / 2 + door / 2
    for a, e in ((x0, 0.0), (length, x1)):
        sides += [(a, e, 0.0, lo), (a, e, hi, width)]
    for a, e, z0, z1 in sides:
        b.hexahedra(_sloped_blocks(a, e, z0, z1, bottom, a * rise + TALL, e * rise + TALL))
    openings = [_opening((x0, y0, width / 2), _W, door), _opening((x1, y1, width / 2), _E, door)]
    params = {"length": length, "width": width, "wall": wall, "door": door, "slope": slope}
    return b.build("sloped_corridor", openings, _meta(params, (y0, y1)))


@validate_call
def roofed_corridor(
    length: PositiveFloat = 12.0, width: PositiveFloat = 2.4, wall: PositiveFloat = 0.3, roof: PositiveFloat = 0.2
) -> SampleLevel:
    """A walled corridor open at both ends under a flat roof ``roof`` thick on its walls, as real exports close them.

    The roof's top (``TALL + roof`` up, over the floor and the walls) is walkable for Recast but
    unreachable, and outweighs the floor it covers. Found in the fourth round of piece kinds: the
    roof was taken for the main floor and its edges for the openings (docs/entry_exit.md).
    Openings: the corridor's two ends, as wide as it.

    Args:
        length: the corridor's length along X, metres.
        width: clear width between the walls along Z, metres.
        wall: thickness of the walls, metres.
        roof: thickness of the roof slab, metres.
    """
    b = _LevelBuilder()
    b.floors(0.0, length, -wall, width + wall, 0.0)
    _box(b, 0.0, length, -SLAB_THICKNESS, TALL, -wall, 0.0)
    _box(b, 0.0, length, -SLAB_THICKNESS, TALL, width, width + wall)
    _box(b, 0.0, length, TALL, TALL + roof, -wall, width + wall)
    openings = [_opening((0.0, 0.0, width / 2), _W, width), _opening((length, 0.0, width / 2), _E, width)]
    params = {"length": length, "width": width, "wall": wall, "roof": roof}
    return b.build("roofed_corridor", openings, _meta(params, (0.0, TALL + roof), components=2))


@validate_call
def twin_doors(
    width: PositiveFloat = 8.0, depth: PositiveFloat = 6.0, wall: PositiveFloat = 0.3,
    door: PositiveFloat = 1.2, pier: PositiveFloat = 0.2,
) -> SampleLevel:
    """A walled room with two doorways side by side in its east wall, a ``pier`` of wall between them, and one west.

    Samples along the wall inside see out through both doorways alike (the navmesh need not enter a
    doorway barely wider than the agent, and runs in front of a pier narrower than it), so the two
    were one edge spanning the pier, measured from its middle and dropped. Found in the fifth round
    of piece kinds (docs/entry_exit.md). Openings: the west doorway (1.6 m) and each east one.

    Args:
        width: clear floor inside the walls along X, metres.
        depth: clear floor inside the walls along Z, metres.
        wall: thickness of the walls, metres.
        door: width of each east doorway, metres.
        pier: the wall between the east doorways, metres.
    """
    b = _LevelBuilder()
    b.floors(-wall, width + wall, -wall, depth + wall, 0.0)
    centres = (depth / 2 - (door + pier) / 2, depth / 2 + (door + pier) / 2)
    gaps = {"W": [(depth / 2 - 0.8, depth / 2 + 0.8, 0.0, TALL)],
            "E": [(c - door / 2, c + door / 2, 0.0, TALL) for c in centres]}
    _walls(b, width, depth, wall, gaps)
    openings = [_door("W", depth / 2, 1.6, width, depth, wall), *(_door("E", c, door, width, depth, wall) for c in centres)]
    params = {"width": width, "depth": depth, "wall": wall, "door": door, "pier": pier}
    return b.build("twin_doors", openings, _meta(params, (0.0,)))


@validate_call
def stair_exit(
    width: PositiveFloat = 8.0, depth: PositiveFloat = 6.0, wall: PositiveFloat = 0.3,
    riser: PositiveFloat = 0.2, tread: PositiveFloat = 0.3, steps: PositiveInt = 10, door: PositiveFloat = 1.6,
) -> SampleLevel:
    """A walled room whose east doorway opens onto stairs leaving the piece at their top.

    ``steps`` steps (``riser`` high, ``tread`` deep, ``door`` wide between 0.2 m walls) rise along
    +X from the doorway; the top tread ends at the piece's east edge, with no landing. A riser as
    high as the edge search's rays (0.2 m for :data:`PIECE_AGENT`) lies in their plane: they passed
    over the top step unseen, the edge was found a riser low and the opening was dropped. Found in
    the fifth round of piece kinds (docs/entry_exit.md). Openings: the west doorway and the stairs'
    top edge, ``steps * riser`` up.

    Args:
        width: clear floor inside the walls along X, metres.
        depth: clear floor inside the walls along Z, metres.
        wall: thickness of the walls, metres.
        riser: height of each step, metres.
        tread: depth of each step along X, metres.
        steps: number of steps.
        door: width of both doorways and of the stairs, metres.
    """
    b = _LevelBuilder()
    b.floors(-wall, width + wall, -wall, depth + wall, 0.0)
    gaps = {side: [(depth / 2 - door / 2, depth / 2 + door / 2, 0.0, TALL)] for side in "WE"}
    _walls(b, width, depth, wall, gaps)
    z0, z1 = depth / 2 - door / 2, depth / 2 + door / 2
    for i in range(1, steps + 1):
        x0, x1 = width + wall + tread * (i - 1), width + wall + tread * i
        _box(b, x0, x1, -SLAB_THICKNESS, riser * i, z0, z1)
        _box(b, x0, x1, -SLAB_THICKNESS, riser * i + TALL, z0 - 0.2, z0)
        _box(b, x0, x1, -SLAB_THICKNESS, riser * i + TALL, z1, z1 + 0.2)
    b.floor_area += steps * tread * door
    top = steps * riser
    openings = [_door("W", depth / 2, door, width, depth, wall),
                _opening((width + wall + steps * tread, top, depth / 2), _E, door)]
    params = {"width": width, "depth": depth, "wall": wall, "riser": riser, "tread": tread, "steps": steps, "door": door}
    return b.build("stair_exit", openings, _meta(params, (0.0, top)))


# --------------------------------------------------------------------------
# Held-out families: shapes designers build that the rules above were not measured on
# --------------------------------------------------------------------------


@validate_call
def corner_corridor(
    length: PositiveFloat = 8.0, width: PositiveFloat = 2.4, wall: PositiveFloat = 0.3, door: PositiveFloat = 1.6
) -> SampleLevel:
    """An L-shaped corridor turning left by 90 degrees, closed at both ends by walls with a doorway.

    The first leg runs along +X over x in [0, length] (clear width ``width``
    over z in [0, width]); the second turns to +Z at its east end and runs
    to z = ``length``. Openings: the west end's doorway and the north end's,
    each centred on its leg, on the end wall's outer face.

    Args:
        length: each leg's clear length along its own axis, metres (the outer corner included).
        width: the corridor's clear width, metres.
        wall: thickness of the walls, metres.
        door: width of each end's doorway, metres.
    """
    if not door < width < length / 2:
        raise ValueError(f"need door < width < length / 2, got {door}, {width}, {length}")
    b = _LevelBuilder()
    t, inner = wall, length - width
    b.floors(np.array([-t, inner - t]), np.array([length + t, length + t]),
             np.array([-t, width + t]), np.array([width + t, length + t]), 0.0)
    _box(b, -t, length + t, -SLAB_THICKNESS, TALL, -t, 0.0)  # outer walls
    _box(b, length, length + t, -SLAB_THICKNESS, TALL, 0.0, length + t)
    _box(b, -t, inner, -SLAB_THICKNESS, TALL, width, width + t)  # inner walls
    _box(b, inner - t, inner, -SLAB_THICKNESS, TALL, width + t, length + t)
    for a0, a1 in ((0.0, (width - door) / 2), ((width + door) / 2, width)):
        _box(b, -t, 0.0, -SLAB_THICKNESS, TALL, a0, a1)  # west end wall
        _box(b, inner + a0, inner + a1, -SLAB_THICKNESS, TALL, length, length + t)  # north end wall
    openings = [_opening((-t, 0.0, width / 2), _W, door), _opening((inner + width / 2, 0.0, length + t), _N, door)]
    params = {"length": length, "width": width, "wall": wall, "door": door}
    return b.build("corner_corridor", openings, _meta(params, (0.0,)))


@validate_call
def t_junction(
    length: PositiveFloat = 12.0, branch: PositiveFloat = 5.0, width: PositiveFloat = 2.4, wall: PositiveFloat = 0.3
) -> SampleLevel:
    """A walled corridor open at both ends with a branch, open at its end, leaving its middle to +Z.

    The main corridor runs over x in [0, length], z in [0, width]; the branch
    (as wide) leaves its north wall at the middle and ends ``branch`` beyond
    the wall's outer face. Openings: the three open ends, as wide as the corridor.

    Args:
        length: the main corridor's length along X, metres.
        branch: the branch's length beyond the main corridor's north wall, metres.
        width: clear width of both corridors, metres.
        wall: thickness of the walls, metres.
    """
    if width >= length / 2:
        raise ValueError(f"width must be below length / 2, got {width}")
    b = _LevelBuilder()
    t, c, h = wall, length / 2, width / 2
    top = width + t + branch
    b.floors(np.array([0.0, c - h - t]), np.array([length, c + h + t]),
             np.array([-t, width + t]), np.array([width + t, top]), 0.0)
    _box(b, 0.0, length, -SLAB_THICKNESS, TALL, -t, 0.0)
    for x0, x1 in ((0.0, c - h), (c + h, length)):
        _box(b, x0, x1, -SLAB_THICKNESS, TALL, width, width + t)
    for x0, x1 in ((c - h - t, c - h), (c + h, c + h + t)):
        _box(b, x0, x1, -SLAB_THICKNESS, TALL, width, top)
    openings = [_opening((0.0, 0.0, h), _W, width), _opening((length, 0.0, h), _E, width),
                _opening((c, 0.0, top), _N, width)]
    params = {"length": length, "branch": branch, "width": width, "wall": wall}
    return b.build("t_junction", openings, _meta(params, (0.0,)))


@validate_call
def bridge(
    length: PositiveFloat = 12.0, width: PositiveFloat = 2.0, railing: PositiveFloat = 1.0,
    rail_width: PositiveFloat = 0.1,
) -> SampleLevel:
    """A narrow walkway over a void between two railings, open at both ends.

    Nothing of the piece lies under the deck (x in [0, length], z in [0,
    width]); the railings (higher than the agent's climb, too narrow to
    stand on) run along both long sides. Openings: the two ends, as wide as
    the walkway between the railings. The default width leaves every
    preset's agent (radius up to 0.5 m) a navmesh; Recast gives the 0.4 m
    agent none on some narrower ones (docs/entry_exit.md).

    Args:
        length: the walkway's length along X, metres.
        width: clear width between the railings, metres.
        railing: the railings' height above the deck, metres.
        rail_width: the railings' thickness, metres.
    """
    b = _LevelBuilder()
    b.floors(0.0, length, -rail_width, width + rail_width, 0.0)
    _box(b, 0.0, length, 0.0, railing, -rail_width, 0.0)
    _box(b, 0.0, length, 0.0, railing, width, width + rail_width)
    openings = [_opening((0.0, 0.0, width / 2), _W, width), _opening((length, 0.0, width / 2), _E, width)]
    params = {"length": length, "width": width, "railing": railing, "rail_width": rail_width}
    return b.build("bridge", openings, _meta(params, (0.0,)))


@validate_call
def windowed_room(
    width: PositiveFloat = 10.0, depth: PositiveFloat = 8.0, wall: PositiveFloat = 0.3, door: PositiveFloat = 1.6,
    window: PositiveFloat = 1.5, sill: PositiveFloat = 0.9, window_top: PositiveFloat = 2.1,
) -> SampleLevel:
    """A walled room with one doorway (south) and four windows (two north, one west, one east).

    A window is a hole in the wall from ``sill`` to ``window_top`` above the
    floor: the agent cannot step through it, so it is no opening; the room's
    floor ends under it at the wall. Openings: the doorway only.

    Args:
        width: clear floor inside the walls along X, metres.
        depth: clear floor inside the walls along Z, metres.
        wall: thickness of the walls, metres.
        door: width of the doorway, metres (open to the walls' top).
        window: width of each window, metres.
        sill: height of the windows' sills above the floor, metres.
        window_top: height of the windows' tops above the floor, metres.
    """
    if not sill < window_top < TALL or window >= depth / 2:
        raise ValueError("need sill < window_top < 3 m and window < depth / 2")
    b = _LevelBuilder()
    b.floors(-wall, width + wall, -wall, depth + wall, 0.0)
    pane = (sill, window_top)
    gaps = {
        "W": [(depth / 2 - window / 2, depth / 2 + window / 2, *pane)],
        "E": [(depth / 2 - window / 2, depth / 2 + window / 2, *pane)],
        "S": [(width / 2 - door / 2, width / 2 + door / 2, 0.0, TALL)],
        "N": [(c - window / 2, c + window / 2, *pane) for c in (width / 4, 3 * width / 4)],
    }
    _walls(b, width, depth, wall, gaps)
    params = {"width": width, "depth": depth, "wall": wall, "door": door, "window": window, "sill": sill,
              "window_top": window_top}
    return b.build("windowed_room", [_door("S", width / 2, door, width, depth, wall)], _meta(params, (0.0,)))


@validate_call
def threshold_door(
    width: PositiveFloat = 8.0, depth: PositiveFloat = 6.0, wall: PositiveFloat = 0.3, door: PositiveFloat = 1.6,
    step: PositiveFloat = 0.2,
) -> SampleLevel:
    """A walled room with two doorways: the west one over a threshold ``step`` high, the east one level.

    The threshold fills the west doorway across the wall's thickness: the
    agent steps up onto it (``step`` is below its climb) and leaves the piece
    at its outer edge. Openings: both doorways, the west one at the
    threshold's height.

    Args:
        width: clear floor inside the walls along X, metres.
        depth: clear floor inside the walls along Z, metres.
        wall: thickness of the walls (the threshold's depth), metres.
        door: width of both doorways, metres.
        step: the threshold's height above the floor, metres.
    """
    b = _LevelBuilder()
    b.floors(-wall, width + wall, -wall, depth + wall, 0.0)
    across = (depth / 2 - door / 2, depth / 2 + door / 2)
    _walls(b, width, depth, wall, {"W": [(*across, step, TALL)], "E": [(*across, 0.0, TALL)]})
    openings = [_door("W", depth / 2, door, width, depth, wall, floor=step), _door("E", depth / 2, door, width, depth, wall)]
    params = {"width": width, "depth": depth, "wall": wall, "door": door, "step": step}
    return b.build("threshold_door", openings, _meta(params, (0.0, step)))


@validate_call
def open_side_room(
    width: PositiveFloat = 10.0, depth: PositiveFloat = 6.0, wall: PositiveFloat = 0.3, door: PositiveFloat = 1.6
) -> SampleLevel:
    """A room walled on three sides whose whole south side is open, with a doorway in the north wall.

    The open side is one opening as wide as the room (the walls' ends bound
    it), however wide: not several. Openings: the open side and the doorway.

    Args:
        width: clear floor along X (the open side's width), metres.
        depth: clear floor along Z, metres.
        wall: thickness of the walls, metres.
        door: width of the north doorway, metres.
    """
    b = _LevelBuilder()
    b.floors(-wall, width + wall, 0.0, depth + wall, 0.0)
    _walls(b, width, depth, wall, {"W": [(-wall, 0.0, 0.0, TALL)], "E": [(-wall, 0.0, 0.0, TALL)],
                                    "S": [(-wall, width + wall, 0.0, TALL)],
                                    "N": [(width / 2 - door / 2, width / 2 + door / 2, 0.0, TALL)]})
    openings = [_opening((width / 2, 0.0, 0.0), _S, width), _door("N", width / 2, door, width, depth, wall)]
    params = {"width": width, "depth": depth, "wall": wall, "door": door}
    return b.build("open_side_room", openings, _meta(params, (0.0,)))


@validate_call
def thick_wall_door(
    width: PositiveFloat = 8.0, depth: PositiveFloat = 6.0, wall: PositiveFloat = 1.0,
    doors: tuple[float, ...] = (1.2, 1.6), door_height: PositiveFloat = 2.4,
) -> SampleLevel:
    """A room in walls ``wall`` thick whose two doorways, under lintels, are short tunnels.

    Openings: the west and east doorways' outer faces.

    Args:
        width: clear floor inside the walls along X, metres.
        depth: clear floor inside the walls along Z, metres.
        wall: thickness of the walls (the tunnels' length), metres.
        doors: widths of the west and east doorways, metres.
        door_height: height of the lintels' undersides above the floor, metres.
    """
    if len(doors) != 2 or min(doors) <= 0:
        raise ValueError(f"doors must be 2 widths > 0, got {doors!r}")
    b = _LevelBuilder()
    b.floors(-wall, width + wall, -wall, depth + wall, 0.0)
    gaps = {side: [(depth / 2 - d / 2, depth / 2 + d / 2, 0.0, door_height)] for side, d in zip("WE", doors)}
    _walls(b, width, depth, wall, gaps)
    openings = [_door(side, depth / 2, d, width, depth, wall) for side, d in zip("WE", doors)]
    params = {"width": width, "depth": depth, "wall": wall, "doors": tuple(doors), "door_height": door_height}
    return b.build("thick_wall_door", openings, _meta(params, (0.0,)))


@validate_call
def two_storey(
    width: PositiveFloat = 10.0, depth: PositiveFloat = 8.0, wall: PositiveFloat = 0.3, storey: PositiveFloat = 3.2,
    riser: PositiveFloat = 0.2, tread: PositiveFloat = 0.3, stair_width: PositiveFloat = 1.6,
    door: PositiveFloat = 1.6, door_height: PositiveFloat = 2.4,
) -> SampleLevel:
    """A two-storey house without a roof: a doorway on each floor, straight stairs inside.

    The upper floor (its top ``storey`` up) covers the ground floor but for
    the stairwell over the stairs, which rise along +X against the north
    wall from x = 2 m. Openings: the ground floor's doorway in the west wall
    and the upper floor's in the east wall (both centred, under lintels).

    Args:
        width: clear floor inside the walls along X, metres.
        depth: clear floor inside the walls along Z, metres.
        wall: thickness of the walls, metres.
        storey: height of the upper floor above the ground floor, metres.
        riser: height of each step, metres (``storey`` is rounded to whole steps).
        tread: depth of each step along X, metres.
        stair_width: width of the stairs and the stairwell, metres.
        door: width of both doorways, metres.
        door_height: height of the lintels above each floor, metres.
    """
    steps = max(1, round(storey / riser))
    top = steps * riser
    x_start, x_end = 2.0, 2.0 + steps * tread
    if x_end >= width or stair_width >= depth / 2 or door_height + 0.2 >= top:
        raise ValueError("the stairs must fit the ground floor and the doors a storey")
    b = _LevelBuilder()
    b.floors(-wall, width + wall, -wall, depth + wall, 0.0)
    z_well = depth - stair_width
    b.floors(np.array([0.0, 0.0, x_end]), np.array([width, x_start, width]),
             np.array([0.0, z_well, z_well]), np.array([z_well, depth, depth]), top)
    for i in range(steps):
        _box(b, x_start + i * tread, x_end, -SLAB_THICKNESS, (i + 1) * riser, z_well, depth)
    across = (depth / 2 - door / 2, depth / 2 + door / 2)
    _walls(b, width, depth, wall, {"W": [(*across, 0.0, door_height)], "E": [(*across, top, top + door_height)]},
           height=top + TALL)
    openings = [_door("W", depth / 2, door, width, depth, wall), _door("E", depth / 2, door, width, depth, wall, top)]
    params = {"width": width, "depth": depth, "wall": wall, "storey": storey, "riser": riser, "tread": tread,
              "stair_width": stair_width, "door": door, "door_height": door_height}
    return b.build("two_storey", openings, _meta(params, (0.0, top)))


@validate_call
def cluttered_room(
    width: PositiveFloat = 10.0, depth: PositiveFloat = 8.0, wall: PositiveFloat = 0.3, door: PositiveFloat = 1.6,
    crate: PositiveFloat = 1.0, pillar: PositiveFloat = 0.5,
) -> SampleLevel:
    """A walled room with a doorway west and east; crates flank the west one, a pillar stands before the east one.

    Two crates (``crate`` wide, deep and high) stand against the west wall on
    either side of its doorway, touching the jambs' line; a full-height pillar
    (``pillar`` square) stands 1 m inside the east doorway, on its centre
    line. The crates' tops are higher than the climb: no way onto them.
    Openings: the two doorways.

    Args:
        width: clear floor inside the walls along X, metres.
        depth: clear floor inside the walls along Z, metres.
        wall: thickness of the walls, metres.
        door: width of both doorways, metres.
        crate: the crates' side, metres.
        pillar: the pillar's side, metres.
    """
    b = _LevelBuilder()
    b.floors(-wall, width + wall, -wall, depth + wall, 0.0)
    lo, hi = depth / 2 - door / 2, depth / 2 + door / 2
    _walls(b, width, depth, wall, {"W": [(lo, hi, 0.0, TALL)], "E": [(lo, hi, 0.0, TALL)]})
    _box(b, 0.0, crate, 0.0, crate, lo - crate, lo)
    _box(b, 0.0, crate, 0.0, crate, hi, hi + crate)
    p = pillar / 2
    _box(b, width - 1.0 - pillar, width - 1.0, 0.0, TALL, depth / 2 - p, depth / 2 + p)
    openings = [_door(side, depth / 2, door, width, depth, wall) for side in "WE"]
    params = {"width": width, "depth": depth, "wall": wall, "door": door, "crate": crate, "pillar": pillar}
    return b.build("cluttered_room", openings, _meta(params, (0.0,)))


@validate_call
def narrow_door_room(
    width: PositiveFloat = 8.0, depth: PositiveFloat = 6.0, wall: PositiveFloat = 0.3,
    narrow: PositiveFloat = 0.6, door: NonNegativeFloat = 1.6,
) -> SampleLevel:
    """A walled room with a doorway narrower than the agent (west) and, unless ``door`` is 0, a wide one (east).

    The agent (:data:`PIECE_AGENT`, 0.8 m across) cannot pass the narrow
    doorway, so it is no opening. Openings: the east doorway; none without it.

    Args:
        width: clear floor inside the walls along X, metres.
        depth: clear floor inside the walls along Z, metres.
        wall: thickness of the walls, metres.
        narrow: width of the west doorway, metres.
        door: width of the east doorway, metres; 0: no east doorway.
    """
    b = _LevelBuilder()
    b.floors(-wall, width + wall, -wall, depth + wall, 0.0)
    gaps = {"W": [(depth / 2 - narrow / 2, depth / 2 + narrow / 2, 0.0, TALL)]}
    if door > 0:
        gaps["E"] = [(depth / 2 - door / 2, depth / 2 + door / 2, 0.0, TALL)]
    _walls(b, width, depth, wall, gaps)
    openings = [_door("E", depth / 2, door, width, depth, wall)] if door > 0 else []
    params = {"width": width, "depth": depth, "wall": wall, "narrow": narrow, "door": door}
    return b.build("narrow_door_room", openings, _meta(params, (0.0,)))


HELD_OUT = {
    "corner_corridor": corner_corridor,
    "t_junction": t_junction,
    "bridge": bridge,
    "windowed_room": windowed_room,
    "threshold_door": threshold_door,
    "open_side_room": open_side_room,
    "thick_wall_door": thick_wall_door,
    "two_storey": two_storey,
    "cluttered_room": cluttered_room,
    "narrow_door_room": narrow_door_room,
}
"""The held-out families: piece shapes the entry/exit rules were not measured on when they were set
(docs/entry_exit.md, "Piece shapes it was not tuned on"); name -> factory."""


PIECES = {
    "doorway_room": doorway_room,
    "curb_platform": curb_platform,
    "wall_tops": wall_tops,
    "stair_deck": stair_deck,
    "cross_platform": cross_platform,
    "chamfered_platform": chamfered_platform,
    "sloped_corridor": sloped_corridor,
    "roofed_corridor": roofed_corridor,
    "twin_doors": twin_doors,
    "stair_exit": stair_exit,
    **HELD_OUT,
}
"""Piece name -> factory (keyword arguments only), the held-out families included; registered in ``levels.SAMPLES``."""


def yaw_about_centre(mesh: trimesh.Trimesh, degrees: float) -> np.ndarray:
    """(4, 4) transform turning ``mesh`` by ``degrees`` about the vertical (+Y) axis through its bounding box's centre.

    Positive angles turn counter-clockwise seen from above (+X towards -Z): how a
    kit exported at another heading, or a piece placed turned in a level and
    exported in world space, reaches the detector.
    """
    import trimesh  # imported where used, as in levels.py: `g2s plugins` lists the pieces without it

    centre = np.asarray(mesh.bounds, dtype=np.float64).mean(axis=0)
    return trimesh.transformations.rotation_matrix(np.radians(degrees), [0.0, 1.0, 0.0], point=centre)


def turned(level: SampleLevel, degrees: float) -> SampleLevel:
    """``level`` turned by ``degrees`` about its vertical centre line (:func:`yaw_about_centre`), openings with it."""
    import trimesh

    matrix = yaw_about_centre(level.mesh, degrees)
    mesh = level.mesh.copy()
    mesh.apply_transform(matrix)

    def point(p: Vec3) -> Vec3:
        return vec3(trimesh.transform_points(np.asarray([p], dtype=np.float64), matrix)[0])

    def vector(v: Vec3) -> Vec3:
        return vec3(matrix[:3, :3] @ np.asarray(v, dtype=np.float64))

    openings = tuple(
        replace(o, position=point(o.position), heading=vector(o.heading), p0=point(o.p0), p1=point(o.p1))
        for o in level.openings
    )
    metadata = {**level.metadata, "yaw_deg": float(degrees)}
    return SampleLevel(name=level.name, mesh=mesh, openings=openings, metadata=metadata)


MATCH_DISTANCE = 1.5
"""Metres: a detected opening matches a reference connector when their midpoints are this close."""


def match_openings(found: np.ndarray, reference: np.ndarray, distance: float = MATCH_DISTANCE) -> tuple[int, int]:
    """How a detected set of opening midpoints compares with reference ones.

    Args:
        found: (n, 3) detected midpoints, metres.
        reference: (m, 3) reference midpoints (known openings, designers' connectors).
        distance: largest midpoint distance of a match, metres.

    Returns:
        ``(correct, recalled)``: how many detected midpoints lie within
        ``distance`` of some reference one (precision = correct / n), and how
        many reference midpoints have a detected one that close (recall =
        recalled / m).
    """
    found = np.asarray(found, dtype=np.float64).reshape(-1, 3)
    reference = np.asarray(reference, dtype=np.float64).reshape(-1, 3)
    if len(found) == 0 or len(reference) == 0:
        return 0, 0
    near = np.linalg.norm(found[:, None, :] - reference[None, :, :], axis=2) <= distance
    return int(near.any(axis=1).sum()), int(near.any(axis=0).sum())
