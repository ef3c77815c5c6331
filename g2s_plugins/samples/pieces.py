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

Units, frame and solids follow :mod:`g2s_plugins.samples.levels` (metres, Y
up, outward-facing hexahedra, floors' tops at the floor height). The pieces
are designed for :data:`PIECE_AGENT`, the agent of ``configs/map_piece.yaml``.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import trimesh
from pydantic import PositiveFloat, PositiveInt, validate_call

from g2s_core.model import Vec3, vec3

from g2s_plugins.samples.levels import SLAB_THICKNESS, SampleLevel, _LevelBuilder, _opening, _rect

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
        position = {"W": (x0, 0.0, centre), "E": (x1, 0.0, centre), "S": (centre, 0.0, z0), "N": (centre, 0.0, z1)}
        heading = {"W": _W, "E": _E, "S": _S, "N": _N}[side]
        openings.append(_opening(position[side], heading, door))
    for side, runs in gaps.items():
        along = (z0, z1) if side in "WE" else (x0, x1)
        cuts = [along[0], *[v for g in sorted(runs) for v in g], along[1]]
        for a0, a1 in zip(cuts[0::2], cuts[1::2]):
            if side == "W":
                _box(b, x0, 0.0, -SLAB_THICKNESS, TALL, a0, a1)
            elif side == "E":
                _box(b, width, x1, -SLAB_THICKNESS, TALL, a0, a1)
            elif side == "S":
                _box(b, a0, a1, -SLAB_THICKNESS, TALL, z0, 0.0)
            else:
                _box(b, a0, a1, -SLAB_THICKNESS, TALL, depth, z1)
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


PIECES = {
    "doorway_room": doorway_room,
    "curb_platform": curb_platform,
    "wall_tops": wall_tops,
    "stair_deck": stair_deck,
    "cross_platform": cross_platform,
    "chamfered_platform": chamfered_platform,
}
"""Piece name -> factory (keyword arguments only); registered in ``levels.SAMPLES``."""


def yaw_about_centre(mesh: trimesh.Trimesh, degrees: float) -> np.ndarray:
    """(4, 4) transform turning ``mesh`` by ``degrees`` about the vertical (+Y) axis through its bounding box's centre.

    Positive angles turn counter-clockwise seen from above (+X towards -Z): how a
    kit exported at another heading, or a piece placed turned in a level and
    exported in world space, reaches the detector.
    """
    centre = np.asarray(mesh.bounds, dtype=np.float64).mean(axis=0)
    return trimesh.transformations.rotation_matrix(np.radians(degrees), [0.0, 1.0, 0.0], point=centre)


def turned(level: SampleLevel, degrees: float) -> SampleLevel:
    """``level`` turned by ``degrees`` about its vertical centre line (:func:`yaw_about_centre`), openings with it."""
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
