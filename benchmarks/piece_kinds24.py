"""A twenty-fourth round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds24.py [--kinds a b] [--configs map_piece map_piece_sampling]
[--yaws 0 22 45] [--detail]``

Eight kinds of docs/entry_exit.md, "A twenty-fourth round of piece kinds", each with its known openings (count,
place, width, height) written in its docstring before the detector first ran on them: the pieces of a level
designer's modular kit none of the earlier rounds built. A corridor with a low beam across it to duck under, a hall
whose unrailed balcony a stair reaches, a Y-fork whose arms are of three widths, a corridor sloping up to a doorway
in its end wall, a hangar with a 10 m gate, a corridor narrowing at a shoulder (a reducer), a shipping container
with both door leaves open outward, and a square U-turn whose two ends lie side by side. Built with
:mod:`piece_parts`, in the earlier rounds' conventions.
"""

from __future__ import annotations

import math
import sys

from piece_parts import SLAB, arm_junction, box, corridor, flight, hull, kinds_by_name, room, round_level, run_kinds

from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _N, _S, _W

_level = round_level(24)


def low_beam_corridor() -> SampleLevel:
    """Corridor 12 x 2.4 m (x 0-12, z 0-2.4), walls 0.3 m and 3 m high, both ends open; a beam 0.3 m wide across it
    at x 4.85-5.15, its underside 1.5 m over the floor (0.5 m under the agent's head: no way under it) and its top at
    1.8 m. Known: both ends, 2.4 m, at the floor (y 0), on x 0 and x 12; none at the beam (the corridor's two parts,
    4.85 and 6.85 m long, each hold their own end)."""
    parts = corridor(12.0) + [box(4.85, 5.15, 1.5, 1.8, 0.0, 2.4)]
    return _level("low_beam_corridor", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, 1.2), _E, 2.4)])


def balcony_over_hall() -> SampleLevel:
    """Hall 12 x 8 m (clear x 0-12, z 0-8), walls 0.3 m and 6.5 m high, no roof; along its east side a balcony
    2.5 m deep (x 9.5-12) whose top is 3.0 m up, on a slab 0.3 m thick with head room under it, its west edge open
    over the hall (no rail); a straight flight 1.4 m wide along the north wall (z 6.6-8.0) of 16 steps 0.3 m deep and
    0.1875 m high rising eastward from x 4.7 to the balcony at x 9.5, solid under it, unrailed. A 1.6 m doorway W at
    the floor (z 3.2-4.8, lintel 2.2 m), one E from the balcony (z 3.2-4.8, its sill 3.0 m up, lintel 2.2 m over
    it). Known: both doorways at the walls' outer faces, 1.6 m each: the west one at the floor (y 0), the east one
    3.0 m up; none along the balcony's open edge nor the flight's side (drops into the piece's own hall)."""
    balcony = 3.0
    parts = room(12.0, 8.0, {"W": [(3.2, 4.8, 2.2)], "E": [(-0.3, 8.3, 6.5)]}, height=6.5)
    parts += [box(12.0, 12.3, -SLAB, 6.5, z0, z1) for z0, z1 in ((-0.3, 3.2), (4.8, 8.3))]
    parts += [box(12.0, 12.3, balcony + 2.2, 6.5, 3.2, 4.8), box(12.0, 12.3, -SLAB, balcony, 3.2, 4.8)]
    parts += [box(9.5, 12.0, balcony - 0.3, balcony, 0.0, 8.0)]
    parts += flight((4.7, 0.0), (1, 0), (6.6, 8.0), 16, 0.3, balcony / 16, 0.0)
    return _level("balcony_over_hall", parts, [_opening((-0.3, 0.0, 4.0), _W, 1.6),
                                              _opening((12.3, balcony, 4.0), _E, 1.6)])


def y_fork_unequal_arms() -> SampleLevel:
    """A Y of corridors meeting at the origin, walls 0.3 m thick and 3 m high, each arm's end open and cut square to
    it: the stem 2.4 m wide west (180 degrees) 5 m long; an arm 1.6 m wide at 30 degrees (from +x towards +z) 6 m
    long; an arm 3.2 m wide at -35 degrees 8 m long. Known: the three ends at the floor (y 0), on the arms' axes at
    those lengths, facing along them: 2.4 m at (-5, 0), 1.6 m at (5.20, 3.00), 3.2 m at (6.55, -4.59) in (x, z)."""
    angles, halves, lengths = [30.0, 180.0, 325.0], [0.8, 1.2, 1.6], [6.0, 5.0, 8.0]
    parts, arms = arm_junction(angles, halves, lengths)
    ends = [_opening((d[0] * length, 0.0, d[1] * length), (d[0], 0.0, d[1]), 2 * half)
            for (d, half), length in zip(arms, lengths)]
    return _level("y_fork_unequal_arms", parts, ends)


def sloped_corridor_end_door(slope_deg: float = 10.0) -> SampleLevel:
    """Corridor 2.4 m wide (z 0-2.4), its floor rising ``slope_deg`` from y 0 at its open west end (x 0) to 1.76 m
    at its east end wall (x 10.0-10.3, 10 degrees); side walls 0.3 m thick up to 4.5 m. In the end wall a 1.2 m
    doorway (z 0.6-1.8) under a lintel 2.2 m over the slope's top, its sill level with it through the wall. Known:
    the west end, 2.4 m, at y 0 on x 0; the east doorway, 1.2 m, at the wall's outer face (x 10.3) 1.76 m up."""
    top = 10.0 * math.tan(math.radians(slope_deg))
    parts = [hull([[x, y, z] for x in (0.0, 10.0) for y in (x * top / 10.0 - SLAB, x * top / 10.0) for z in (0.0, 2.4)])]
    parts += [box(0.0, 10.3, -SLAB, 4.5, -0.3, 0.0), box(0.0, 10.3, -SLAB, 4.5, 2.4, 2.7)]
    parts += [box(10.0, 10.3, -SLAB, 4.5, 0.0, 0.6), box(10.0, 10.3, -SLAB, 4.5, 1.8, 2.4),
              box(10.0, 10.3, -SLAB, top, 0.6, 1.8), box(10.0, 10.3, top + 2.2, 4.5, 0.6, 1.8)]
    return _level("sloped_corridor_end_door", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4),
                                                     _opening((10.3, top, 1.2), _E, 1.2)])


def hangar_gate() -> SampleLevel:
    """Hangar 24 x 16 m (clear x 0-24, z 0-16), walls 0.3 m and 8 m high, no roof; in the south wall a gate 10 m wide
    (x 7-17) under a lintel 6 m up; in the north wall a 1.2 m door (x 11.4-12.6) under a 2.2 m lintel. Known: both,
    at the floor (y 0) on the walls' outer faces: the gate 10 m at (12, -0.3), the door 1.2 m at (12, 16.3)."""
    parts = room(24.0, 16.0, {"S": [(7.0, 17.0, 6.0)], "N": [(11.4, 12.6, 2.2)]}, height=8.0)
    return _level("hangar_gate", parts, [_opening((12.0, 0.0, -0.3), _S, 10.0), _opening((12.0, 0.0, 16.3), _N, 1.2)])


def reducer_corridor() -> SampleLevel:
    """Corridor 3.2 m wide (z 0-3.2) from its open west end (x 0) to a shoulder wall 0.3 m thick at x 6.0-6.3, then
    1.6 m wide (z 0.8-2.4, on the same centre line) to its open east end (x 12); walls 0.3 m thick and 3 m high.
    Known: both ends at the floor (y 0): the west one 3.2 m at (0, 1.6), the east one 1.6 m at (12, 1.6)."""
    parts = [box(0.0, 6.0, -SLAB, 0.0, 0.0, 3.2), box(6.0, 12.0, -SLAB, 0.0, 0.8, 2.4)]
    parts += [box(0.0, 6.3, -SLAB, 3.0, -0.3, 0.0), box(0.0, 6.3, -SLAB, 3.0, 3.2, 3.5)]
    parts += [box(6.0, 6.3, -SLAB, 3.0, 0.0, 0.8), box(6.0, 6.3, -SLAB, 3.0, 2.4, 3.2)]
    parts += [box(6.3, 12.0, -SLAB, 3.0, 0.5, 0.8), box(6.3, 12.0, -SLAB, 3.0, 2.4, 2.7)]
    return _level("reducer_corridor", parts, [_opening((0.0, 0.0, 1.6), _W, 3.2), _opening((12.0, 0.0, 1.6), _E, 1.6)])


def open_container_doors() -> SampleLevel:
    """A shipping container standing alone: clear inside x 0-5.9, z 0-2.35, floor at y 0 on a 0.15 m base, steel
    walls and roof 0.05 m thick (the roof's underside 2.39 m up); its west end closed, its east end open, both door
    leaves (1.175 m wide, 0.05 m thick, y -0.1-2.3) hinged at the side walls' outer corners and standing open 90
    degrees outward, along x 5.9-7.075 just outside the side walls (z -0.10..-0.05 and 2.40..2.45), over no floor.
    Known: the open end, 2.35 m, at the floor (y 0) on x 5.9; none along the leaves."""
    parts = [box(-0.05, 5.9, -0.15, 0.0, -0.05, 2.40), box(-0.05, 5.9, 2.39, 2.44, -0.05, 2.40)]
    parts += [box(-0.05, 5.9, -0.15, 2.39, -0.05, 0.0), box(-0.05, 5.9, -0.15, 2.39, 2.35, 2.40),
              box(-0.05, 0.0, -0.15, 2.39, 0.0, 2.35)]
    parts += [box(5.9, 7.075, -0.1, 2.3, z0, z1) for z0, z1 in ((-0.10, -0.05), (2.40, 2.45))]
    return _level("open_container_doors", parts, [_opening((5.9, 0.0, 1.175), _E, 2.35)])


def hairpin_corridor() -> SampleLevel:
    """A square U-turn of 2.4 m corridors: two legs along x (z 0-2.4 and z 2.7-5.1) from x 0 to the turn (x 8-10.4,
    z 0-5.1), between them a wall 0.3 m thick (z 2.4-2.7) from x 0 to 8; outer walls 0.3 m thick, all 3 m high.
    Known: both ends, side by side on x 0 facing west, at the floor (y 0): 2.4 m each, at z 1.2 and 3.9 (0.3 m of
    wall between them)."""
    parts = [box(0.0, 10.4, -SLAB, 0.0, 0.0, 5.1), box(0.0, 8.0, -SLAB, 3.0, 2.4, 2.7)]
    parts += [box(0.0, 10.7, -SLAB, 3.0, -0.3, 0.0), box(0.0, 10.7, -SLAB, 3.0, 5.1, 5.4),
              box(10.4, 10.7, -SLAB, 3.0, 0.0, 5.1)]
    return _level("hairpin_corridor", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((0.0, 0.0, 3.9), _W, 2.4)])


KINDS = kinds_by_name(low_beam_corridor, balcony_over_hall, y_fork_unequal_arms, sloped_corridor_end_door, hangar_gate,
                      reducer_corridor, open_container_doors, hairpin_corridor)
"""Kind name -> factory of the twenty-fourth round."""


if __name__ == "__main__":
    sys.exit(run_kinds(sys.argv[1:], kinds=KINDS, description=__doc__.splitlines()[0]))
