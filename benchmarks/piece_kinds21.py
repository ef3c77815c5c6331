"""A twenty-first round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds21.py [--kinds a b] [--configs map_piece map_piece_sampling]
[--yaws 0 22 45] [--detail]``

Eleven kinds of docs/entry_exit.md, "A twenty-first round of piece kinds", each with its known openings written in
its docstring before the detector first ran on it. Four hold a way a designer would not use as an opening beside
their doorways: a hearth under a chimney open to the sky, a lift shaft's doorway onto a drop, a chute steeper than
the agent walks and a stair up to a landing in front of a bricked-up doorway. Seven hold openings as a kit's pieces
come: a loading bay 8 m wide, two doorways in a round tower, a ramp down into the ground to a tunnel's mouth, a
stair leaving a room's corner at 45 degrees to its walls, steps down through a thick wall, a doorway in a wall of
glass and two doorways meeting at a corner post 0.3 m square. Built with :mod:`piece_parts`, in the earlier
rounds' conventions.
"""

from __future__ import annotations

import math
import sys

import numpy as np
from piece_parts import (ROOM_DOORS, ROOM_OPENINGS, SLAB, arc_band, box, hull, kinds_by_name, polygon_room, prism,
                         room, round_level, run_kinds)

from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _S, _W

_level = round_level(21)


def hearth_chimney_room(lintel: float = 2.1) -> SampleLevel:
    """Room 8 x 6 m, 1.6 m doorways W and E; in the north wall a hearth 1.6 m wide (x 3.2-4.8) under a ``lintel`` m
    lintel, 1.0 m deep (through the wall and 0.7 m into a chimney breast outside it, x 2.6-5.4, 5 m high), floored
    level with the room, its flue 1.6 x 0.7 m open to the sky above it, closed at its back. Known: both doorways;
    not the hearth (closed behind; its only way on is up the flue)."""
    parts = room(8.0, 6.0, {**ROOM_DOORS, "N": [(3.2, 4.8, lintel)]})
    parts += [box(3.2, 4.8, -SLAB, 0.0, 6.3, 7.0), box(2.6, 5.4, -SLAB, 5.0, 7.0, 7.3),
              box(2.6, 3.2, -SLAB, 5.0, 6.3, 7.0), box(4.8, 5.4, -SLAB, 5.0, 6.3, 7.0),
              box(2.6, 5.4, 3.0, 5.0, 6.0, 6.3)]  # the breast's back, sides, and front over the room's wall
    return _level("hearth_chimney_room", parts, ROOM_OPENINGS)


def lift_shaft_door(depth: float = 3.0) -> SampleLevel:
    """Room 8 x 6 m, 1.6 m doorways W and E; in the north wall a 1.2 m doorway (x 3.4-4.6, lintel 2.2 m) onto a lift
    shaft 2 x 2 m inside (x 3.0-5.0, z 6.3-8.3, walls 0.3 m from ``depth`` m down to 3 m up), its floor ``depth`` m
    below the room's, no cage. Known: both doorways; not the shaft's door (a drop into the piece's own shaft)."""
    parts = room(8.0, 6.0, {**ROOM_DOORS, "N": [(3.4, 4.6, 2.2)]})
    parts += [box(3.0, 5.0, -depth - SLAB, -depth, 6.3, 8.3), box(2.7, 5.3, -depth - SLAB, 3.0, 8.3, 8.6),
              box(2.7, 3.0, -depth - SLAB, 3.0, 6.3, 8.3), box(5.0, 5.3, -depth - SLAB, 3.0, 6.3, 8.3),
              box(3.0, 5.0, -depth - SLAB, -SLAB, 6.0, 6.3)]  # the shaft's floor, walls, and its side under the room
    return _level("lift_shaft_door", parts, ROOM_OPENINGS)


def steep_chute_door(slope_deg: float = 65.0) -> SampleLevel:
    """Room 8 x 6 m whose floor lies 3 m up on a solid block, 1.6 m doorways W and E (edges over nothing, 3 m up);
    in the south wall a 1.6 m doorway (x 3.2-4.8, lintel 2.2 m) onto a chute of ``slope_deg`` (steeper than the
    agent's 60 degrees) from the wall's outer face down to the ground, solid under it, between side walls 0.2 m thick
    standing 1 m over it. Known: the W and E doorways (3 m up); not the chute (no walking down it)."""
    run = 3.0 / math.tan(math.radians(slope_deg))
    foot = -0.3 - run
    parts = room(8.0, 6.0, {**ROOM_DOORS, "S": [(3.2, 4.8, 2.2)]}, floor=3.0) + [
        box(-0.3, 8.3, 0.0, 3.0 - SLAB, -0.3, 6.3)]
    parts.append(hull([[x, y, z] for x in (3.2, 4.8) for y, z in ((3.0, -0.3), (0.0, foot), (0.0, -0.3))]))
    for x0, x1 in ((3.0, 3.2), (4.8, 5.0)):
        parts.append(hull([[x, y, z] for x in (x0, x1) for y, z in ((4.0, -0.3), (1.0, foot), (0.0, foot), (0.0, -0.3))]))
    return _level("steep_chute_door", parts,
                  [_opening((-0.3, 3.0, 3.0), _W, 1.6), _opening((8.3, 3.0, 3.0), _E, 1.6)])


def blind_stair_landing(steps: int = 10) -> SampleLevel:
    """Room 10 x 6 m, walls 5 m high, 1.6 m doorways W and E (lintels 2.2 m); against the north wall a stair 1.2 m
    wide (z 4.8-6.0) of ``steps`` 0.2 m risers on 0.3 m treads rising east from x 2.0 to a landing 2 m up (x 5-7),
    solid to the floor, open on its south side and east end (unrailed, over the room); above the landing a doorway
    in the north wall bricked up from its outer face (x 5.4-6.6, 2.2 m high over the landing), leaving a recess
    0.15 m deep. Known: both doorways; not the landing (its only way on is the bricked-up door)."""
    top = 0.2 * steps
    parts = room(10.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(2.2, 3.8, 2.2)], "N": [(5.4, 6.6, top + 2.2)]}, height=5.0)
    parts += [box(2.0 + 0.3 * i, 2.3 + 0.3 * i, -SLAB, 0.2 * (i + 1), 4.8, 6.0) for i in range(steps)]
    parts += [box(2.0 + 0.3 * steps, 2.0 + 0.3 * steps + 2.0, -SLAB, top, 4.8, 6.0),
              box(5.4, 6.6, -SLAB, top + 2.2, 6.15, 6.3)]
    return _level("blind_stair_landing", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((10.3, 0.0, 3.0), _E, 1.6)])


def wide_shutter_bay(bay: float = 8.0) -> SampleLevel:
    """Warehouse 12 x 10 m, walls 4.5 m high; a 1.6 m doorway W (z 4.2-5.8, lintel 2.2 m); east a loading bay
    ``bay`` m wide centred on z 5 under a lintel 3.5 m up, the floor level through it. Known: the west doorway and
    the bay, ``bay`` m (one opening: one shutter, one neighbour)."""
    parts = room(12.0, 10.0, {"W": [(4.2, 5.8, 2.2)], "E": [(5.0 - bay / 2, 5.0 + bay / 2, 3.5)]}, height=4.5)
    return _level("wide_shutter_bay", parts, [_opening((-0.3, 0.0, 5.0), _W, 1.6), _opening((12.3, 0.0, 5.0), _E, bay)])


def round_tower_doors(inner: float = 2.5, wall: float = 0.5, bearings: tuple[float, ...] = (30.0, 200.0)) -> SampleLevel:
    """A round tower without a roof: inner radius ``inner`` m, walls ``wall`` m thick and 4 m high in facets of at most
    7.5 degrees, a floor slab over the outer circle; doorways at ``bearings`` (degrees from +x towards +z) with
    radial jambs, 1.6 m across at the outer face (1.33 m at the inner one), lintels 2.2 m. No wall direction
    dominates. Known: both doorways, at the outer face, facing out along their bearings, 1.6 m."""
    outer = inner + wall
    half = math.degrees(math.asin(0.8 / outer))
    rim = [(outer * math.cos(a), outer * math.sin(a)) for a in np.radians(np.arange(0.0, 360.0, 7.5))]
    parts = [prism(rim, -SLAB, 0.0)]
    edges = sorted((b - half, b + half) for b in bearings)
    for (_, a0), (a1, _) in zip(edges, edges[1:] + [(edges[0][0] + 360.0, 0.0)]):
        parts += arc_band(0.0, 0.0, inner, outer, a0, a1, -SLAB, 4.0)
    for a0, a1 in edges:
        parts += arc_band(0.0, 0.0, inner, outer, a0, a1, 2.2, 4.0)
    openings = []
    for b in bearings:
        c, s = math.cos(math.radians(b)), math.sin(math.radians(b))
        mid = outer * math.cos(math.radians(half))
        openings.append(_opening((mid * c, 0.0, mid * s), (c, 0.0, s), 1.6))
    return _level("round_tower_doors", parts, openings)


def cellar_ramp(slope_deg: float = 20.0) -> SampleLevel:
    """Room 8 x 6 m at the ground, a 1.6 m doorway W; east a 2.0 m doorway (z 2-4, lintel 2.2 m) onto a ramp 2.0 m
    wide going down ``slope_deg`` into the ground between retaining walls 0.3 m thick standing 1 m over the ground,
    to 3 m down, then level to x 18.5; from x 15.5 on a roof (its underside 0.3 m below the ground) makes it a
    tunnel whose mouth, 3 m down, is the piece's east face (2.3-2.7 m head room under it). Known: the west doorway
    and the tunnel's mouth (2.0 m, facing +x, 3 m down)."""
    foot = 8.3 + 3.0 / math.tan(math.radians(slope_deg))
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(2.0, 4.0, 2.2)]})
    parts += [hull([[x, y, z] for x, y in ((8.3, 0.0), (foot, -3.0), (8.3, -3.0 - SLAB), (foot, -3.0 - SLAB))
                    for z in (2.0, 4.0)]),
              box(foot, 18.5, -3.0 - SLAB, -3.0, 2.0, 4.0), box(8.3, 18.5, -3.0 - SLAB, 1.0, 1.7, 2.0),
              box(8.3, 18.5, -3.0 - SLAB, 1.0, 4.0, 4.3), box(15.5, 18.5, -0.3, 0.0, 2.0, 4.0)]
    return _level("cellar_ramp", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((18.5, -3.0, 3.0), _E, 2.0)])


def corner_stair_exit(steps: int = 6) -> SampleLevel:
    """Room 8 x 6 m (floor at the ground) whose north-east corner is cut by a wall at 45 degrees (from (8, 4) to
    (6, 6) inside), walls 0.3 m, mitred; a 1.6 m doorway W (lintel 2.2 m) and a 1.6 m doorway in the middle of the
    cut wall, onto a stair going up north-east, 45 degrees off the room's walls: ``steps`` 0.2 m risers on 0.3 m
    treads, 1.6 m wide, then a pad 1.5 m deep at 1.2 m up, solid to the ground, between side walls 0.2 m thick
    standing 1 m over the treads; the pad's north-east end is the piece's face, open over nothing. Known: the west
    doorway and the pad's end (1.6 m, facing north-east, 1.2 m up)."""
    parts, frames = polygon_room([(0.0, 0.0), (8.0, 0.0), (8.0, 4.0), (6.0, 6.0), (0.0, 6.0)],
                                 {2: [(0.614, 2.214, 2.2)], 4: [(2.2, 3.8, 2.2)]})
    p, d, n = frames[2]
    mid = p + d * 1.414  # the cut wall's door, at its inner face

    def block(u0: float, u1: float, v0: float, v1: float, top: float):  # a solid in the stair's frame (u out, v along)
        return prism([mid + n * u + d * v for u, v in ((u0, v0), (u1, v0), (u1, v1), (u0, v1))], -SLAB, top)

    end = 0.3 + 0.3 * steps + 1.5
    for i in range(steps):
        u0, u1 = 0.3 + 0.3 * i, 0.6 + 0.3 * i
        parts += [block(u0, u1, -0.8, 0.8, 0.2 * (i + 1)), block(u0, u1, -1.0, -0.8, 0.2 * (i + 1) + 1.0),
                  block(u0, u1, 0.8, 1.0, 0.2 * (i + 1) + 1.0)]
    top, u_pad = 0.2 * steps, 0.3 + 0.3 * steps
    parts += [block(u_pad, end, -0.8, 0.8, top), block(u_pad, end, -1.0, -0.8, top + 1.0),
              block(u_pad, end, 0.8, 1.0, top + 1.0)]
    pad_end = mid + n * end
    return _level("corner_stair_exit", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6),
                                               _opening((pad_end[0], top, pad_end[1]), (n[0], 0.0, n[1]), 1.6)])


def stepped_wall_passage(thickness: float = 1.5) -> SampleLevel:
    """Room 8 x 6 m whose floor lies 0.6 m up on a solid block, walls 0.3 m but the east one ``thickness`` m, walls
    3 m over the floor; a 1.6 m doorway W (its edge 0.6 m over nothing) and, east, a 1.6 m passage (z 2.2-3.8) through
    the thick wall under a lintel 2.2 m over the room's floor, going down three 0.2 m steps on 0.4 m treads to the
    ground at the wall's outer face. Known: the west doorway (0.6 m up) and the passage's outer end (1.6 m, at the
    ground, at x 8 + ``thickness``)."""
    outer = 8.0 + thickness
    parts = room(8.0, 6.0, ROOM_DOORS, floor=0.6) + [box(-0.3, 8.3, -SLAB, 0.6 - SLAB, -0.3, 6.3)]
    parts += [box(8.3, outer, -SLAB, 3.6, -0.3, 2.2), box(8.3, outer, -SLAB, 3.6, 3.8, 6.3),
              box(8.3, outer, 2.8, 3.6, 2.2, 3.8)]
    tread = (outer - 8.3) / 3
    parts += [box(8.3 + tread * i, 8.3 + tread * (i + 1), -SLAB, 0.4 - 0.2 * i, 2.2, 3.8) for i in range(3)]
    return _level("stepped_wall_passage", parts,
                  [_opening((-0.3, 0.6, 3.0), _W, 1.6), _opening((outer, 0.0, 3.0), _E, 1.6)])


def glass_wall_door(pane: float = 0.02) -> SampleLevel:
    """Room 8 x 6 m, a 1.6 m doorway W; the east wall a wall of glass: closed panes ``pane`` m thick in the wall's
    line (x 8.15) from the floor to 3 m, over z 0-2.2 and 3.8-6.0 between the north and south walls, with a
    1.6 m doorway between them (z 2.2-3.8) under a glass transom from 2.2 m up; the floor slab to the wall's outer
    face (x 8.3). Known: the west doorway and the glass wall's doorway (1.6 m); not the glass."""
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(-0.3, 6.3, 3.0)]})
    x0, x1 = 8.15 - pane / 2, 8.15 + pane / 2
    parts += [box(x0, x1, 0.0, 3.0, 0.0, 2.2), box(x0, x1, 0.0, 3.0, 3.8, 6.0), box(x0, x1, 2.2, 3.0, 2.2, 3.8)]
    return _level("glass_wall_door", parts, ROOM_OPENINGS)


def corner_post_doors() -> SampleLevel:
    """Room 8 x 6 m, a 1.6 m doorway W; at the south-east corner two 1.6 m doorways (lintels 2.2 m), one in the
    south wall (x 6.4-8.0) and one in the east wall (z 0.0-1.6), nothing between them but the corner post 0.3 m
    square (x 8.0-8.3, z -0.3-0.0). Known: three openings, the west doorway and each corner doorway (two neighbours:
    they face two ways)."""
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "S": [(6.4, 8.0, 2.2)], "E": [(0.0, 1.6, 2.2)]})
    return _level("corner_post_doors", parts, [ROOM_OPENINGS[0], _opening((7.2, 0.0, -0.3), _S, 1.6),
                                               _opening((8.3, 0.0, 0.8), _E, 1.6)])


KINDS = kinds_by_name(hearth_chimney_room, lift_shaft_door, steep_chute_door, blind_stair_landing, wide_shutter_bay,
                      round_tower_doors, cellar_ramp, corner_stair_exit, stepped_wall_passage, glass_wall_door,
                      corner_post_doors)
"""Kind name -> factory of the twenty-first round."""


if __name__ == "__main__":
    sys.exit(run_kinds(kinds=KINDS, description=__doc__.splitlines()[0]))
