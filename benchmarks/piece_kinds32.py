"""A thirty-second round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds32.py [--kinds a b] [--configs map_piece map_piece_sampling] [--yaws 0
22 45] [--detail] [--one-to-one]``

Eight kinds of docs/entry_exit.md, "A thirty-second round of piece kinds", each with its known openings (count, place,
width, height) written in its docstring before the detector first ran on them: the pieces of a level designer's
modular kit none of the earlier rounds built. A dead-end corridor whose only other way on is a hatch in its ceiling up
a fixed ladder; two raised doorways side by side, one threshold 0.25 m up under a lintel 1.9 m over the floor and one
under 2.45 m; a corridor cut by an open drain 0.6 m across its whole width over a closed sump; an L-shaped room whose
door sits against its inner corner; two doors 0.3 m apart with a thin post between them under one lintel; a corridor
ending in a ramp at 20 degrees; a hexagonal room with doors on alternate sides; a terrace open along one whole side
to a cliff edge, railed but for one gap. Built with :mod:`piece_parts`, in the earlier rounds' conventions.
"""

from __future__ import annotations

import math
import sys

import numpy as np
from piece_parts import (ROOM_OPENINGS, SLAB, box, corridor, hull, kinds_by_name, polygon_room, room, round_level,
                         run_kinds)

from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _N, _S, _W

_level = round_level(32)


def ladder_hatch_dead_end(hatch: float = 1.0) -> SampleLevel:
    """Corridor 10 x 2.4 m (clear x 0-10, z 0-2.4), walls 0.3 m thick and 3 m high, open west, closed east by an end
    wall (x 10.0-10.3); over it a ceiling slab 3.0-3.2 m up (x 0-10.3, z -0.3-2.7) with a hatch ``hatch`` m (1.0)
    square near the east end (x 8.8-9.8, z 0.7-1.7) and a fixed ladder up the end wall's face to it (stiles 0.05 m
    square at z 0.70-0.75 and 1.65-1.70, x 9.90-9.95, from the floor to 3.2 m; rungs 0.04 m every 0.3 m from 0.3 m
    up); nothing of the piece above the hatch but the slab's top. Known: one, at the floor (y 0): the west end, 2.4 m
    at (0, 1.2), facing west, 3 m high. Not the hatch: the ladder is no walkable link for the navmesh (the agent
    walks, it does not climb 3 m), nor the slab's top (a roof no walk reaches)."""
    x0, x1, z0, z1 = 9.8 - hatch, 9.8, 1.2 - hatch / 2, 1.2 + hatch / 2
    parts = corridor(10.0) + [box(10.0, 10.3, -SLAB, 3.0, -0.3, 2.7),
                              box(0.0, x0, 3.0, 3.2, -0.3, 2.7), box(x1, 10.3, 3.0, 3.2, -0.3, 2.7),
                              box(x0, x1, 3.0, 3.2, -0.3, z0), box(x0, x1, 3.0, 3.2, z1, 2.7)]
    parts += [box(9.90, 9.95, 0.0, 3.2, 0.70, 0.75), box(9.90, 9.95, 0.0, 3.2, 1.65, 1.70)]
    parts += [box(9.90, 9.94, y, y + 0.04, 0.75, 1.65) for y in np.arange(0.3, 3.0, 0.3)]
    return _level("ladder_hatch_dead_end", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4)])


def sill_under_low_lintel(sill: float = 0.25, low: float = 1.9, high: float = 2.45) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, a 1.6 m west doorway (z 2.2-3.8, lintel
    2.2 m); in the east wall two doorways 1.2 m wide side by side (z 1.0-2.2 and 3.4-4.6, a pier 1.2 m between),
    each floored through the wall (x 8.0-8.3) by a threshold ``sill`` m (0.25, under the 0.4 m climb) up: the south
    one under a lintel ``low`` m (1.9) over the room's floor, 1.65 m over its threshold; the north one under a lintel
    ``high`` m (2.45) over the floor, 2.2 m over its threshold. The piece ends at the walls' outer faces. Known: two:
    the west doorway, 1.6 m at (-0.3, 3.0) at y 0; the north east doorway, 1.2 m at (8.3, 4.0), ``sill`` m up (the
    threshold's top), 2.2 m high. Not the south one: 1.65 m of head room over its threshold is no way for the 2 m
    agent, whatever the lintel's height over the room's floor."""
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(1.0, 2.2, low), (3.4, 4.6, high)]})
    parts += [box(8.0, 8.3, 0.0, sill, 1.0, 2.2), box(8.0, 8.3, 0.0, sill, 3.4, 4.6)]
    return _level("sill_under_low_lintel", parts, [ROOM_OPENINGS[0], _opening((8.3, sill, 4.0), _E, 1.2)])


def open_drain_corridor(drain: float = 0.6, depth: float = 2.0) -> SampleLevel:
    """Corridor 12 x 2.4 m (clear x 0-12, z 0-2.4), walls 0.3 m thick from ``depth`` m + the slab below the floor to
    3 m over it, both ends open; across its whole width at its middle an open drain ``drain`` m (0.6) wide (x
    5.7-6.3), its grate missing, over a closed sump ``depth`` m (2.0) deep: the floor either side a solid block
    down to the sump's floor, the walls closing its ends. The agent (radius 0.4 m, no jumps) does not cross: a hole
    is no floor, and the navmesh keeps the agent's radius back from each lip (1.4 m without floor), so the piece is
    two halves, each reached from its own end; the sump's floor, 0.6 m wide, holds no agent. Known: two, at the floor
    (y 0), 2.4 m each, 3 m high: the west end at (0, 1.2), facing west; the east end at (12, 1.2), facing east. Not the
    drain's lips (inside the piece)."""
    x0, x1, bottom = 6.0 - drain / 2, 6.0 + drain / 2, -depth - SLAB
    parts = [box(0.0, 12.0, bottom, 3.0, -0.3, 0.0), box(0.0, 12.0, bottom, 3.0, 2.4, 2.7),
             box(0.0, x0, bottom, 0.0, 0.0, 2.4), box(x1, 12.0, bottom, 0.0, 0.0, 2.4),
             box(x0, x1, bottom, -depth, 0.0, 2.4)]
    return _level("open_drain_corridor", parts,
                  [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, 1.2), _E, 2.4)])


def l_room_inner_corner_door(door: float = 1.2) -> SampleLevel:
    """An L-shaped room, walls 0.3 m thick and 3 m high: a south arm (clear x 0-10, z 0-4) and a west arm (clear x
    0-4, z 4-10), the notch north-east of the inner corner (4.3, 4.3) outside the piece; 1.6 m doorways (lintels 2.2
    m) at the arms' ends: the south arm's east end (x 10.0-10.3, z 1.2-2.8) and the west arm's north end (z
    10.0-10.3, x 1.2-2.8); in the south arm's north wall (z 4.0-4.3) a doorway ``door`` m (1.2) wide (x 4.3-5.5, lintel
    2.2 m) against the inner corner: its west jamb is the corner, the west arm's east wall's outer face (x 4.3) running
    on north past it; the slab ends at the walls' outer faces. Known: three, at the floor (y 0), 2.2 m high: the
    south arm's end, 1.6 m at (10.3, 2.0), facing east; the west arm's end, 1.6 m at (2.0, 10.3), facing north; the
    corner door, ``door`` m at (4.9, 4.3), facing north into the notch."""
    x1 = 4.3 + door
    parts = [box(-0.3, 10.3, -SLAB, 0.0, -0.3, 4.3), box(-0.3, 4.3, -SLAB, 0.0, 4.3, 10.3),
             box(-0.3, 10.3, -SLAB, 3.0, -0.3, 0.0), box(-0.3, 0.0, -SLAB, 3.0, 0.0, 10.3),
             box(10.0, 10.3, -SLAB, 3.0, 0.0, 1.2), box(10.0, 10.3, -SLAB, 3.0, 2.8, 4.3),
             box(10.0, 10.3, 2.2, 3.0, 1.2, 2.8),
             box(0.0, 1.2, -SLAB, 3.0, 10.0, 10.3), box(2.8, 4.3, -SLAB, 3.0, 10.0, 10.3),
             box(1.2, 2.8, 2.2, 3.0, 10.0, 10.3),
             box(4.0, 4.3, -SLAB, 3.0, 4.0, 10.0), box(x1, 10.0, -SLAB, 3.0, 4.0, 4.3),
             box(4.3, x1, 2.2, 3.0, 4.0, 4.3)]
    return _level("l_room_inner_corner_door", parts,
                  [_opening((10.3, 0.0, 2.0), _E, 1.6), _opening((2.0, 0.0, 10.3), _N, 1.6),
                   _opening((4.3 + door / 2, 0.0, 4.3), _N, door)])


def thin_post_twin_doors(apart: float = 0.3, post: float = 0.1) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, a 1.6 m west doorway (z 2.2-3.8, lintel
    2.2 m); in the east wall, under one lintel 2.2 m up over z 1.35-4.05, two doors 1.2 m wide (z 1.35-2.55 and
    2.85-4.05) ``apart`` m (0.3) apart, the wall between them only a thin post: ``apart`` m along the wall, ``post`` m
    (0.1) thick at the wall's middle (x 8.1-8.2), from the floor to the lintel, the wall's thickness either side of
    it open (0.1 m in front of it and behind it, narrower than the agent); the slab ends at the wall's outer face.
    Known: three, at the floor (y 0), 2.2 m high: the west doorway, 1.6 m at (-0.3, 3.0); each east door, 1.2 m at
    (8.3, 1.95) and at (8.3, 3.45), facing east. Decided before the run: two openings, as round 28's two doors 0.3
    m apart and the fifth round's twin doors beside a 0.2 m pier (a kit snaps a neighbour to each door): the post is
    as wide as those piers, the way between the doors round it 0.1 m, no way for the agent, and each door alone is
    0.4 m wider than the agent. (A mullion narrower than the agent through the wall, round 20, is a double door's
    frame: one.)"""
    z0, z1 = 2.7 - apart / 2, 2.7 + apart / 2
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(1.35, 4.05, 2.2)]})
    parts.append(box(8.15 - post / 2, 8.15 + post / 2, 0.0, 2.2, z0, z1))
    return _level("thin_post_twin_doors", parts,
                  [ROOM_OPENINGS[0], _opening((8.3, 0.0, 1.95), _E, 1.2), _opening((8.3, 0.0, 3.45), _E, 1.2)])


def ramp_end_twenty(slope_deg: float = 20.0, run: float = 4.0) -> SampleLevel:
    """Corridor 12 x 2.4 m (clear x 0-12, z 0-2.4), both ends open; its floor level (y 0) from x 0 to 12 - ``run``
    (8), then a ramp rising ``slope_deg`` (20, under the agent's 60) over the last ``run`` m (4) to the east end,
    ``run`` tan ``slope_deg`` = 1.46 m up; side walls 0.3 m thick up to 3 m over the ramp's top (4.46 m). Known:
    two, 2.4 m each, 3 m high: the west end at (0, 1.2) at y 0, facing west; the east end at the ramp's top edge,
    (12, 1.2) at y 1.46, facing east."""
    rise = run * math.tan(math.radians(slope_deg))
    start = 12.0 - run
    parts = [box(0.0, start, -SLAB, 0.0, 0.0, 2.4),
             hull([[x, y, z] for x, y in ((start, -SLAB), (start, 0.0), (12.0, rise), (12.0, -SLAB))
                   for z in (0.0, 2.4)]),
             box(0.0, 12.0, -SLAB, rise + 3.0, -0.3, 0.0), box(0.0, 12.0, -SLAB, rise + 3.0, 2.4, 2.7)]
    return _level("ramp_end_twenty", parts,
                  [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, rise, 1.2), _E, 2.4)])


def hexagon_alternate_doors(side: float = 4.0, door: float = 1.2) -> SampleLevel:
    """A regular hexagonal room about (5, 5), its clear floor's corners ``side`` m (4) from the centre at 0, 60, ...
    300 degrees (from +x towards +z: a corner on each axis, no side square to one), mitred walls 0.3 m thick and 3 m
    high; in the middle of three alternate sides, those facing 30, 150 and 270 degrees, a doorway ``door`` m (1.2)
    wide under a lintel 2.2 m up; the slab ends at the walls' outer faces. Known: three, at the floor (y 0), ``door``
    m each, 2.2 m high, at the outer faces' middles, the centre's inradius + 0.3 m = 3.76 m from (5, 5) along 30,
    150 and 270 degrees ((8.26, 6.88), (1.74, 6.88), (5.0, 1.24)), facing along them."""
    corners = [(5.0 + side * math.cos(math.radians(60.0 * k)), 5.0 + side * math.sin(math.radians(60.0 * k)))
               for k in range(6)]
    s0 = (side - door) / 2
    parts, frames = polygon_room(corners, {k: [(s0, s0 + door, 2.2)] for k in (0, 2, 4)})
    ends = []
    for k in (0, 2, 4):
        start, along, out = frames[k]
        mid = start + along * (side / 2) + out * 0.3
        ends.append(_opening((mid[0], 0.0, mid[1]), (out[0], 0.0, out[1]), door))
    return _level("hexagon_alternate_doors", parts, ends)


def cliff_terrace_railing_gap(gap: float = 1.2, drop: float = 6.0) -> SampleLevel:
    """A terrace on a cliff top: a solid block whose top (y 0) is the terrace, x -0.3-10.3, z 0-6.3, ``drop`` m (6)
    high, nothing below or beyond it; walls 0.3 m thick and 3 m high on its west (x -0.3-0), east (x 10-10.3) and
    north (z 6.0-6.3) sides, a 1.6 m doorway in the north wall (x 4.2-5.8, lintel 2.2 m); its whole south side (z 0)
    the cliff's edge, open but for a railing 1.0 m high and 0.1 m thick along it (z 0.0-0.1, x 0-10) with one gap
    ``gap`` m (1.2) wide off its middle (x 6.0-7.2). Known: two, at the terrace's height (y 0): the north doorway,
    1.6 m at (5.0, 6.3), facing north, 2.2 m high; the railing's gap, ``gap`` m at its outer face (6.6, 0.0), facing
    south, where a kit's ladder or stair module joins (as round 19's balcony railing's gap over nothing); not the
    railing's length (a drop of ``drop`` m behind a rail)."""
    g0, g1 = 6.0, 6.0 + gap
    parts = [box(-0.3, 10.3, -drop, 0.0, 0.0, 6.3),
             box(-0.3, 0.0, 0.0, 3.0, 0.0, 6.0), box(10.0, 10.3, 0.0, 3.0, 0.0, 6.0),
             box(-0.3, 4.2, 0.0, 3.0, 6.0, 6.3), box(5.8, 10.3, 0.0, 3.0, 6.0, 6.3), box(4.2, 5.8, 2.2, 3.0, 6.0, 6.3),
             box(0.0, g0, 0.0, 1.0, 0.0, 0.1), box(g1, 10.0, 0.0, 1.0, 0.0, 0.1)]
    return _level("cliff_terrace_railing_gap", parts,
                  [_opening((5.0, 0.0, 6.3), _N, 1.6), _opening(((g0 + g1) / 2, 0.0, 0.0), _S, gap)])


KINDS = kinds_by_name(ladder_hatch_dead_end, sill_under_low_lintel, open_drain_corridor, l_room_inner_corner_door,
                      thin_post_twin_doors, ramp_end_twenty, hexagon_alternate_doors, cliff_terrace_railing_gap)
"""Kind name -> factory of the thirty-second round."""


if __name__ == "__main__":
    sys.exit(run_kinds(sys.argv[1:], kinds=KINDS, description=__doc__.splitlines()[0]))
