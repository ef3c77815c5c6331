"""A twenty-sixth round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds26.py [--kinds a b] [--configs map_piece map_piece_sampling] [--yaws 0
22 45] [--detail] [--one-to-one]``

Eight kinds of docs/entry_exit.md, "A twenty-sixth round of piece kinds", each with its known openings (count, place,
width, height) written in its docstring before the detector first ran on them: the pieces of a level designer's
modular kit none of the earlier rounds built. A split-level hall whose stair climbs to a half landing with a door of
its own, a doorway half closed by a leaf drawn out of a pocket in the wall, a corridor T whose arm ends over a kerb
within the climb, a wide doorway under a lintel whose keystone hangs lower than the agent's head, a sunken court left
by a ramp whose top lies flush in the ground plane, a corridor whose last metres are a grating of bars along the way,
a door beside a window whose sill is just over the climb, and a corridor bend whose outer corner is cut by a wall
holding a door. Built with :mod:`piece_parts`, in the earlier rounds' conventions.
"""

from __future__ import annotations

import math
import sys

import numpy as np
from piece_parts import SLAB, box, corridor, flight, hull, kinds_by_name, prism, room, round_level, run_kinds

from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _N, _W

_level = round_level(26)


def split_level_half_landing() -> SampleLevel:
    """Hall 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 4.5 m high, no roof; a 1.2 m west doorway at the floor
    (z 2.4-3.6, lintel 2.2 m); along the north wall a solid flight 1.2 m wide (z 4.8-6.0) of 8 risers 0.2 m on
    treads 0.3 m, rising east from x 3.0 to x 5.4, onto a half landing 1.6 m up (solid to the floor) over x 5.4-8.0,
    z 3.6-6.0, open over the hall on its south and west sides; in the east wall a 1.2 m doorway off the landing (z
    4.2-5.4), its sill the landing's 1.6 m, its lintel 2.2 m over it (3.8 m up). Known: two, at two heights: the west
    doorway, 1.2 m at its outer face (-0.3, 3.0) at y 0; the landing's, 1.2 m at (8.3, 4.8), 1.6 m up. None along
    the landing's or the flight's open sides (they drop into the piece's own hall)."""
    parts = room(8.0, 6.0, {"W": [(2.4, 3.6, 2.2)], "E": [(4.2, 5.4, 3.8)]}, height=4.5)
    parts += [box(8.0, 8.3, -SLAB, 1.6, 4.2, 5.4), box(5.4, 8.0, -SLAB, 1.6, 3.6, 6.0)]
    parts += flight((3.0, 0.0), (1, 0), (4.8, 6.0), 8, 0.3, 0.2, 0.0)
    return _level("split_level_half_landing", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.2),
                                                     _opening((8.3, 1.6, 4.8), _E, 1.2)])


def pocket_door_half_drawn() -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high; a 1.6 m west doorway (z 2.2-3.8, lintel
    2.2 m); east a 1.6 m doorway (z 2.2-3.8, lintel 2.2 m) with a sliding leaf's pocket north of it: over z 3.8-5.4
    the wall is two skins 0.12 m thick (x 8.0-8.12 and 8.18-8.3) round a cavity 0.06 m wide, open at the jamb, up to
    the lintel; the leaf (0.05 m thick, x 8.125-8.175, 1.6 m long, y 0.01-2.15) drawn 0.6 m out of the pocket,
    over z 3.2-4.8, leaves 1.0 m of the doorway (z 2.2-3.2) free through the wall's middle (1.6 m in front of it,
    in the outer skin's thickness). Known: two, at the floor (y 0): the west doorway, 1.6 m at (-0.3, 3.0); the east
    one's free part, 1.0 m at the wall's outer face (8.3, 2.7)."""
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(2.2, 5.4, 2.2)]})
    parts += [box(8.0, 8.12, -SLAB, 2.2, 3.8, 5.4), box(8.18, 8.3, -SLAB, 2.2, 3.8, 5.4)]
    parts += [box(8.125, 8.175, 0.01, 2.15, 3.2, 4.8)]
    return _level("pocket_door_half_drawn", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6),
                                                   _opening((8.3, 0.0, 2.7), _E, 1.0)])


def t_arm_kerb_sill(kerb: float = 0.3) -> SampleLevel:
    """Corridor T: a corridor 12 x 2.4 m (clear x 0-12, z 0-2.4), walls 0.3 m thick and 3 m high, open west and east;
    from its middle an arm 2.4 m wide (x 4.8-7.2) leaves north to z 7.4, open at its end, where a kerb ``kerb`` m
    (0.3) high and 0.2 m deep (z 7.2-7.4) runs across its whole width, within the 0.4 m climb. Known: three, 2.4 m
    each: the corridor's ends at the floor (y 0), (0, 1.2) facing west and (12, 1.2) facing east; the arm's end at
    the kerb's outer face (6.0, 7.4) facing north, at the floor's height (the kerb's top ``kerb`` m over it)."""
    parts = [box(0.0, 12.0, -SLAB, 0.0, -0.3, 2.4), box(4.8, 7.2, -SLAB, 0.0, 2.4, 7.4)]
    parts += [box(0.0, 12.0, -SLAB, 3.0, -0.3, 0.0), box(0.0, 4.8, -SLAB, 3.0, 2.4, 2.7)]
    parts += [box(7.2, 12.0, -SLAB, 3.0, 2.4, 2.7), box(4.5, 4.8, -SLAB, 3.0, 2.7, 7.4)]
    parts += [box(7.2, 7.5, -SLAB, 3.0, 2.7, 7.4), box(4.8, 7.2, 0.0, kerb, 7.2, 7.4)]
    return _level("t_arm_kerb_sill", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, 1.2), _E, 2.4),
                                            _opening((6.0, 0.0, 7.4), _N, 2.4)])


def keystone_lintel_door() -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3.2 m high; a 1.6 m west doorway (z 2.2-3.8, lintel
    2.2 m); east a doorway 2.4 m wide (z 1.8-4.2) under a lintel 2.6 m up with a keystone hanging from its middle
    through the wall's thickness: a wedge 0.5 m wide at the lintel (z 2.75-3.25) narrowing to 0.3 m (z 2.85-3.15) at
    its foot, 1.7 m up, lower than the agent (2.0 m) in the doorway's centre; the sides stand 2.6 m clear. At the
    head-room ray's height (1.95 m) the keystone is 0.36 m wide, leaving 1.02 m either side of it. Known: two, at the
    floor (y 0): the west doorway, 1.6 m at (-0.3, 3.0); the east one, 2.4 m as drawn at (8.3, 3.0) (the way at the
    agent's head is two parts of 1.02 m: one doorway to a designer)."""
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(1.8, 4.2, 2.6)]}, height=3.2)
    corners = [(2.75, 2.6), (3.25, 2.6), (2.85, 1.7), (3.15, 1.7)]
    parts.append(hull([[x, y, z] for x in (8.0, 8.3) for z, y in corners]))
    return _level("keystone_lintel_door", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6),
                                                 _opening((8.3, 0.0, 3.0), _E, 2.4)])


def sunken_court_ramp(slope_deg: float = 20.0) -> SampleLevel:
    """A sunken court 8 x 6 m (clear x 0-8, z 0-6), its floor 3 m below the ground plane (y -3), its walls 0.3 m
    thick standing to the ground plane (tops at y 0, no parapet), no roof; a 1.6 m west doorway at its floor (z
    2.2-3.8, lintel 2.2 m over it); east a ramp 2.0 m wide (z 2-4) rising ``slope_deg`` (20) degrees from the court's
    floor at x 8 to the ground plane at x 8 + 3 / tan 20 = 16.24, between retaining walls 0.3 m thick (z 1.7-2.0,
    4.0-4.3) whose tops lie flush with it at y 0: the ramp's top is its end, flush in the ground plane the next piece
    continues. Known: two: the west doorway, 1.6 m at its outer face (-0.3, 3.0), 3 m down (y -3); the ramp's top,
    2.0 m at (16.24, 3.0) at y 0, facing east."""
    floor = -3.0
    top = 8.0 - floor / math.tan(math.radians(slope_deg))
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(2.0, 4.0, 3.0)]}, floor=floor)
    parts.append(hull([[x, y, z] for x, y0 in ((8.0, floor), (top, 0.0)) for y in (y0, y0 - SLAB)
                       for z in (1.7, 4.3)]))
    parts += [hull([[x, y, z] for x in (8.0, top) for y in (floor - SLAB, 0.0) for z in band])
              for band in ((1.7, 2.0), (4.0, 4.3))]
    return _level("sunken_court_ramp", parts, [_opening((-0.3, floor, 3.0), _W, 1.6),
                                              _opening((top, 0.0, 3.0), _E, 2.0)])


def bar_grating_end(bar: float = 0.03, gap: float = 0.03) -> SampleLevel:
    """Corridor 12 x 2.4 m (clear x 0-12, z 0-2.4), walls 0.3 m thick and 3 m high, both ends open; its floor solid
    over x 0-9, then to its east end a grating over nothing of bars ``bar`` m (0.03) wide and deep running along the
    way (x 9-12), ``gap`` m (0.03) apart across it from the south wall (the last bar at z 2.34-2.37): the floor's
    east end is the bars' ends. Known: both ends, 2.4 m, at the floor (y 0): (0, 1.2) facing west, (12, 1.2) facing
    east."""
    parts = corridor(12.0, floor=False) + [box(0.0, 9.0, -SLAB, 0.0, 0.0, 2.4)]
    parts += [box(9.0, 12.0, -bar, 0.0, z, z + bar) for z in np.arange(0.0, 2.4 - bar + 1e-9, bar + gap)]
    return _level("bar_grating_end", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, 1.2), _E, 2.4)])


def door_beside_low_window(sill: float = 0.5) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high; a 1.6 m west doorway (z 2.2-3.8, lintel
    2.2 m); in the east wall a 1.0 m doorway at the floor (z 1.0-2.0) and, 1.4 m north of it, a window 1.2 m wide (z
    3.4-4.6) from a sill ``sill`` m (0.5) up, 0.1 m over the climb, to the same 2.2 m head; nothing beyond the wall.
    Known: two, at the floor (y 0): the west doorway, 1.6 m at (-0.3, 3.0); the east door, 1.0 m at its outer face
    (8.3, 1.5). Not the window (a sill over the climb: no way out)."""
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(1.0, 2.0, 2.2), (3.4, 4.6, 2.2)]})
    parts.append(box(8.0, 8.3, -SLAB, sill, 3.4, 4.6))
    return _level("door_beside_low_window", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6),
                                                   _opening((8.3, 0.0, 1.5), _E, 1.0)])


def chamfered_bend_door(door: float = 1.2) -> SampleLevel:
    """A corridor bend: an arm 2.4 m wide from its open west end (x 0, clear z 0-2.4) to the bend, and one 2.4 m wide
    (clear x 3.6-6.0) from the bend north to its open end at z 6.0; walls 0.3 m thick and 3 m high. The bend's outer
    (south-east) corner is cut off by a wall at 45 degrees from (4.0, 0) to (6.0, 2.0) on its inner face (2.83 m
    long, mitred into the south and east walls), holding a ``door`` m (1.2) doorway in its middle under a 2.2 m
    lintel, facing south-east. Known: three, at the floor (y 0): the west end, 2.4 m at (0, 1.2); the north end, 2.4 m
    at (4.8, 6.0); the cut wall's doorway, ``door`` m at its outer face, (5.0, 1.0) + 0.3 m along (1, -1) / sqrt 2
    = (5.21, 0.79), facing (1, -1) / sqrt 2."""
    wall, length = 0.3, 2.0 * math.sqrt(2.0)
    start = np.array([4.0, 0.0])
    along, out = np.array([1.0, 1.0]) / math.sqrt(2.0), np.array([1.0, -1.0]) / math.sqrt(2.0)
    mitre = wall * (math.sqrt(2.0) - 1.0)  # how far the cut wall's outer face runs past its inner face at each end
    south_end, east_end = start - along * mitre + out * wall, start + along * (length + mitre) + out * wall
    parts = [prism([(0.0, -wall), (3.3, -wall), (3.3, 2.4 + wall), (0.0, 2.4 + wall)], -SLAB, 0.0)]
    parts.append(prism([(3.3, -wall), tuple(south_end), tuple(east_end), (6.0 + wall, 6.0), (3.3, 6.0)], -SLAB, 0.0))
    parts.append(prism([(0.0, -wall), tuple(south_end), (4.0, 0.0), (0.0, 0.0)], -SLAB, 3.0))
    parts.append(prism([(6.0, 2.0), tuple(east_end), (6.0 + wall, 6.0), (6.0, 6.0)], -SLAB, 3.0))
    parts += [box(0.0, 3.6, -SLAB, 3.0, 2.4, 2.4 + wall), box(3.6 - wall, 3.6, -SLAB, 3.0, 2.4 + wall, 6.0)]
    s0, s1 = (length - door) / 2, (length + door) / 2

    def band(a0: float, a1: float, o0: float, o1: float, y0: float, y1: float):
        """The cut wall between a0 and a1 m along its inner face, o0 and o1 along its outer face."""
        corners = [start + along * a0, start + along * a1, start + along * o1 + out * wall,
                   start + along * o0 + out * wall]
        return prism([tuple(c) for c in corners], y0, y1)

    parts += [band(0.0, s0, -mitre, s0, -SLAB, 3.0), band(s1, length, s1, length + mitre, -SLAB, 3.0)]
    parts.append(band(s0, s1, s0, s1, 2.2, 3.0))
    middle = start + along * length / 2 + out * wall
    return _level("chamfered_bend_door", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((4.8, 0.0, 6.0), _N, 2.4),
                                                _opening((middle[0], 0.0, middle[1]), (out[0], 0.0, out[1]), door)])


KINDS = kinds_by_name(split_level_half_landing, pocket_door_half_drawn, t_arm_kerb_sill, keystone_lintel_door,
                      sunken_court_ramp, bar_grating_end, door_beside_low_window, chamfered_bend_door)
"""Kind name -> factory of the twenty-sixth round."""


if __name__ == "__main__":
    sys.exit(run_kinds(sys.argv[1:], kinds=KINDS, description=__doc__.splitlines()[0]))
