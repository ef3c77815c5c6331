"""A thirty-first round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds31.py [--kinds a b] [--configs map_piece map_piece_sampling] [--yaws 0
22 45] [--detail] [--one-to-one]``

Eight kinds of docs/entry_exit.md, "A thirty-first round of piece kinds", each with its known openings (count, place,
width, height) written in its docstring before the detector first ran on them: the pieces of a level designer's
modular kit none of the earlier rounds built. A room whose east wall has two raised doorways side by side, one
threshold under the climb and one over it; a room whose middle is one step down, its doors at the upper level; a
corridor cut in two by a portcullis down to 1.4 m in its middle; a tight quarter ring of corridor with a door in its
outer wall; a Y at 60 degrees whose arms are narrower than its stem; a door beside an arrow slit at the floor, 0.2 m
wide; a doorway with two pillars standing in it 0.3 m from its jambs; a balcony over nothing whose only way on is the
French window behind it. Built with :mod:`piece_parts`, in the earlier rounds' conventions.
"""

from __future__ import annotations

import math
import sys

import numpy as np
from piece_parts import ROOM_OPENINGS, SLAB, arc_band, arm_junction, box, kinds_by_name, room, round_level, run_kinds

from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _S, _W

_level = round_level(31)


def twin_threshold_doors(low: float = 0.35, high: float = 0.5) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, a 1.6 m west doorway at the floor (z
    2.2-3.8, lintel 2.2 m); in the east wall two doorways 1.2 m wide side by side, a pier 1.2 m wide between them, each
    floored through the wall by a threshold (x 8.0-8.3) the step just inside its frame, under a lintel 2.2 m over the
    threshold: the south one (z 1.0-2.2) ``low`` m (0.35, under the 0.4 m climb) up, the north one (z 3.4-4.6)
    ``high`` m (0.5, over it) up; the piece ends at the walls' outer faces. Known: two: the west doorway, 1.6 m at
    (-0.3, 3.0) at y 0; the south east doorway, 1.2 m at (8.3, 1.6), ``low`` m up (the threshold's top), 2.2 m high.
    Not the north one: a step of ``high`` m is no way up or down for the agent."""
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(1.0, 2.2, low + 2.2), (3.4, 4.6, high + 2.2)]})
    parts += [box(8.0, 8.3, 0.0, low, 1.0, 2.2), box(8.0, 8.3, 0.0, high, 3.4, 4.6)]
    return _level("twin_threshold_doors", parts, [ROOM_OPENINGS[0], _opening((8.3, low, 1.6), _E, 1.2)])


def sunken_floor_room(step: float = 0.3, walk: float = 1.5) -> SampleLevel:
    """Room 10 x 8 m (clear x 0-10, z 0-8), walls 0.3 m thick and 3 m high over its upper floor, 1.6 m doorways west
    and east (z 3.2-4.8, lintels 2.2 m) at the upper floor (y 0); a walk ``walk`` m (1.5) wide round the walls at y 0,
    inside it the floor one step ``step`` m (0.3, under the 0.4 m climb) down (x 1.5-8.5, z 1.5-6.5, y -0.3), a
    conversation pit with no kerb. Known: two, at the upper floor (y 0): the west doorway, 1.6 m at (-0.3, 4.0); the
    east one, 1.6 m at (10.3, 4.0), 2.2 m high. Not the step round the sunken floor (inside the piece)."""
    doors = {"W": [(3.2, 4.8, 2.2)], "E": [(3.2, 4.8, 2.2)]}
    parts = room(10.0, 8.0, doors)[1:]  # the walls, without the slab
    lo, hi, bottom = walk, 10.0 - walk, -step - SLAB
    parts += [box(-0.3, 10.3, bottom, 0.0, -0.3, lo), box(-0.3, 10.3, bottom, 0.0, 8.0 - walk, 8.3),
              box(-0.3, lo, bottom, 0.0, lo, 8.0 - walk), box(hi, 10.3, bottom, 0.0, lo, 8.0 - walk),
              box(lo, hi, bottom, -step, lo, 8.0 - walk)]
    return _level("sunken_floor_room", parts,
                  [_opening((-0.3, 0.0, 4.0), _W, 1.6), _opening((10.3, 0.0, 4.0), _E, 1.6)])


def mid_portcullis_corridor(clear: float = 1.4) -> SampleLevel:
    """Corridor 12 x 2.4 m (clear x 0-12, z 0-2.4), walls 0.3 m thick and 3 m high, both ends open; across its middle,
    under a beam 2.6-3.0 m up (x 5.85-6.15), a portcullis let down until its bottom rail (x 5.96-6.04, 0.1 m high) is
    ``clear`` m (1.4) over the floor, its bars (0.08 m square every 0.48 m) on up to the beam: 1.4 m under it, no way
    for the 2 m agent, so the piece is two halves, each reached from its own neighbour. Known: two, at the floor (y
    0): the west end, 2.4 m at (0, 1.2), facing west; the east end, 2.4 m at (12, 1.2), facing east, 3 m high. Not the
    portcullis (inside the piece)."""
    parts = [box(0.0, 12.0, -SLAB, 0.0, -0.3, 2.7), box(0.0, 12.0, -SLAB, 3.0, -0.3, 0.0),
             box(0.0, 12.0, -SLAB, 3.0, 2.4, 2.7), box(5.85, 6.15, 2.6, 3.0, 0.0, 2.4),
             box(5.96, 6.04, clear, clear + 0.1, 0.0, 2.4)]
    parts += [box(5.96, 6.04, clear, 2.6, z, z + 0.08) for z in np.arange(0.2, 2.4 - 0.08, 0.48)]
    return _level("mid_portcullis_corridor", parts,
                  [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, 1.2), _E, 2.4)])


def tight_quarter_ring_side_door(inner: float = 0.8, door_half_deg: float = 10.0) -> SampleLevel:
    """A quarter ring of corridor about the origin from 0 to 90 degrees (from +x towards +z), 2.4 m wide (clear radii
    ``inner`` (0.8) to 3.2 m, centre line 2.0 m), walls 0.3 m thick (radii 0.5-0.8 and 3.2-3.5) and 3 m high in facets
    of 5 degrees, its ends radial and open; in the outer wall at 45 degrees a doorway between radial jambs at 45 -+
    ``door_half_deg`` (10) degrees under a lintel 2.2 m up: 1.11 m wide at the wall's inner face (the chord 2 x 3.2 x
    sin 10 degrees), 1.22 m at its outer face. Known: three, at the floor (y 0): the end at 0 degrees, 2.4 m at
    (2.0, 0), facing south (-z); the end at 90 degrees, 2.4 m at (0, 2.0), facing west; the door, 1.11 m (its
    narrowest) at its outer face's middle, 3.5 cos 10 = 3.45 m from the origin at 45 degrees ((2.44, 2.44)), facing out
    along 45 degrees, 2.2 m high."""
    outer, wall, step = inner + 2.4, 0.3, 5.0
    parts = arc_band(0.0, 0.0, inner - wall, outer + wall, 0.0, 90.0, -SLAB, 0.0, step)
    parts += arc_band(0.0, 0.0, inner - wall, inner, 0.0, 90.0, 0.0, 3.0, step)
    a0, a1 = 45.0 - door_half_deg, 45.0 + door_half_deg
    parts += arc_band(0.0, 0.0, outer, outer + wall, 0.0, a0, 0.0, 3.0, step)
    parts += arc_band(0.0, 0.0, outer, outer + wall, a1, 90.0, 0.0, 3.0, step)
    parts += arc_band(0.0, 0.0, outer, outer + wall, a0, a1, 2.2, 3.0, step)
    centre = (inner + outer) / 2
    mid = (outer + wall) * math.cos(math.radians(door_half_deg))
    out = np.array([1.0, 0.0, 1.0]) / math.sqrt(2.0)
    width = 2 * outer * math.sin(math.radians(door_half_deg))
    return _level("tight_quarter_ring_side_door", parts,
                  [_opening((centre, 0.0, 0.0), _S, 2.4), _opening((0.0, 0.0, centre), _W, 2.4),
                   _opening(tuple(out * mid), out, width)])


def narrow_arm_y_sixty(arm_half: float = 0.6, stem_half: float = 1.2) -> SampleLevel:
    """A Y of corridors meeting at the origin, walls 0.3 m thick and 3 m high, each end open and cut square to its
    arm: the stem 2 x ``stem_half`` m (2.4) wide west (180 degrees), 5 m long; two arms 2 x ``arm_half`` m (1.2, 0.4
    m over the agent's 0.8) wide at -30 and +30 degrees (from +x towards +z: 60 degrees between them), 6 m long, the
    wedge between them coming to a point 1.2 m from the origin. Known: three, at the floor (y 0), on the axes at those
    lengths, facing along them, 3 m high: the stem's, 2.4 m at (-5, 0); the arms', 1.2 m each at (5.20, -3.00) and
    (5.20, 3.00) in (x, z)."""
    parts, arms = arm_junction([-30.0, 30.0, 180.0], [arm_half, arm_half, stem_half], [6.0, 6.0, 5.0])
    ends = [_opening((axis[0] * length, 0.0, axis[1] * length), (axis[0], 0.0, axis[1]), 2 * half)
            for (axis, half), length in zip(arms, (6.0, 6.0, 5.0))]
    return _level("narrow_arm_y_sixty", parts, ends)


def door_beside_floor_slit(slit: float = 0.2, pier: float = 0.3) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, a 1.6 m west doorway (z 2.2-3.8, lintel
    2.2 m); in the east wall a 1.2 m doorway (z 1.0-2.2, lintel 2.2 m), a pier ``pier`` m (0.3) wide, then an arrow
    slit ``slit`` m (0.2) wide (z 2.5-2.7) from the floor to 2.2 m up, straight through the wall, the slab ending at
    the wall's outer face. Known: two, at the floor (y 0): the west doorway, 1.6 m at (-0.3, 3.0); the east door,
    1.2 m at (8.3, 1.6), 2.2 m high. Not the slit: 0.2 m is no way for the agent 0.8 m across, and it does not widen
    the door beside it."""
    s0 = 2.2 + pier
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(1.0, 2.2, 2.2), (s0, s0 + slit, 2.2)]})
    return _level("door_beside_floor_slit", parts, [ROOM_OPENINGS[0], _opening((8.3, 0.0, 1.6), _E, 1.2)])


def pillared_doorway_narrow_gaps(pillar: float = 0.3, gap: float = 0.3) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, a 1.6 m west doorway (z 2.2-3.8, lintel
    2.2 m); in the east wall a doorway 2.6 m wide (z 1.7-4.3) under a lintel 2.4 m up, two square pillars ``pillar``
    m (0.3) across standing in it through the wall's thickness (x 8.0-8.3), floor to lintel, each ``gap`` m (0.3) from
    its jamb (z 2.0-2.3 and 3.7-4.0): the gaps beside them 0.3 m (narrower than the agent's 0.8 m), 1.4 m between
    them. Known: two, at the floor (y 0): the west doorway, 1.6 m at (-0.3, 3.0); the pillared doorway as ONE
    opening, 1.4 m (the way between the pillars, the only one the agent fits) at (8.3, 3.0), 2.4 m high."""
    lo, hi = 1.7, 4.3
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(lo, hi, 2.4)]})
    parts += [box(8.0, 8.3, 0.0, 2.4, lo + gap, lo + gap + pillar), box(8.0, 8.3, 0.0, 2.4, hi - gap - pillar, hi - gap)]
    middle = hi - lo - 2 * (gap + pillar)
    return _level("pillared_doorway_narrow_gaps", parts, [ROOM_OPENINGS[0], _opening((8.3, 0.0, 3.0), _E, middle)])


def french_window_balcony(up: float = 3.0, window: float = 1.4) -> SampleLevel:
    """A balcony over nothing on a building's face: the face a wall 0.3 m thick (x -0.3-0) from ``up`` - 0.2 m to
    ``up`` + 3 m, z -1.0-4.6; the balcony's slab 0.2 m thick, its top ``up`` m (3.0) up, from the wall's back face
    (x -0.3) out to x 2.0, z 0-3.6 (clear 1.9 x 3.4 m inside a railing 1.0 m high and 0.1 m thick on its east, north
    and south edges); in the wall a French window ``window`` m (1.4) wide (z 1.1-2.5) at the balcony's floor under a
    lintel 2.2 m over it. Known: one, the French window, 1.4 m at the wall's back face (-0.3, 1.8), ``up`` m up,
    facing west (into the building, the neighbour), 2.2 m high. Not the railing's edges (a drop of 3 m)."""
    z0, z1 = 1.8 - window / 2, 1.8 + window / 2
    parts = [box(-0.3, 2.0, up - SLAB, up, 0.0, 3.6),
             box(-0.3, 0.0, up - SLAB, up + 3.0, -1.0, z0), box(-0.3, 0.0, up - SLAB, up + 3.0, z1, 4.6),
             box(-0.3, 0.0, up + 2.2, up + 3.0, z0, z1),
             box(1.9, 2.0, up, up + 1.0, 0.0, 3.6), box(0.0, 1.9, up, up + 1.0, 0.0, 0.1),
             box(0.0, 1.9, up, up + 1.0, 3.5, 3.6)]
    return _level("french_window_balcony", parts, [_opening((-0.3, up, 1.8), _W, window)])


KINDS = kinds_by_name(twin_threshold_doors, sunken_floor_room, mid_portcullis_corridor, tight_quarter_ring_side_door,
                      narrow_arm_y_sixty, door_beside_floor_slit, pillared_doorway_narrow_gaps, french_window_balcony)
"""Kind name -> factory of the thirty-first round."""


if __name__ == "__main__":
    sys.exit(run_kinds(sys.argv[1:], kinds=KINDS, description=__doc__.splitlines()[0]))
