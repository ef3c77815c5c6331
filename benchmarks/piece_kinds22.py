"""A twenty-second round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds22.py [--kinds a b] [--configs map_piece map_piece_sampling]
[--yaws 0 22 45] [--detail]``

Eight kinds of docs/entry_exit.md, "A twenty-second round of piece kinds", each with its known openings written in
its docstring before the detector first ran on it. Two hold a way a designer would not use as an opening beside
their doorways: a Dutch door whose lower leaf is shut, and an embrasure through a battered wall. Six hold openings as
a kit's pieces come: a doorway cut through a battered (bunker) wall, a tall opening under a railed mezzanine, a
doorway three steps down, columns 0.3 m from two doorways' jambs, a doorway whose jambs splay through a wall 1 m
thick, and a path between planters under a pergola. Built with :mod:`piece_parts`, in the earlier rounds'
conventions.
"""

from __future__ import annotations

import math
import sys

import trimesh
from piece_parts import (ROOM_DOORS, ROOM_OPENINGS, SLAB, box, hull, kinds_by_name, prism, room, round_level,
                         run_kinds)

from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _W

_level = round_level(22)

_BATTER_DEG = 65.0
"""Degrees from the horizontal of a battered wall's outer face: steeper than the map-piece agent walks (60)."""


def _east_wall_removed(parts: list[trimesh.Trimesh]) -> list[trimesh.Trimesh]:
    """``parts`` of :func:`room` 8 m wide without the east wall's boxes (those starting at x 8.0)."""
    return [p for p in parts if p.bounds[0][0] < 7.99]


def _battered_east(gap: tuple[float, float] | None, sill: float = 0.0, head: float = 2.2,
                   height: float = 3.0) -> tuple[list[trimesh.Trimesh], float]:
    """The east wall of a room 8 x 6 m battered: its inner face at x 8.0, its outer face leaning back from x
    ``8.3 + height / tan(_BATTER_DEG)`` at the floor to 8.3 at ``height``, over z -0.3..6.3, from the slab's bottom;
    ``gap`` (z0, z1) a way through it with vertical jambs from ``sill`` to ``head`` m, floored to the outer face's
    foot where ``sill`` is 0. Returns the parts and the outer face's x at the floor."""
    foot = 8.3 + height / math.tan(math.radians(_BATTER_DEG))

    def wedge(z0: float, z1: float, y0: float, y1: float) -> trimesh.Trimesh:
        x0, x1 = (foot - (foot - 8.3) * max(y, 0.0) / height for y in (y0, y1))  # the outer face at y0 and y1
        return hull([[x, y, z] for z in (z0, z1) for x, y in ((8.0, y0), (x0, y0), (x1, y1), (8.0, y1))])

    if gap is None:
        return [wedge(-0.3, 6.3, -SLAB, height)], foot
    z0, z1 = gap
    parts = [wedge(-0.3, z0, -SLAB, height), wedge(z1, 6.3, -SLAB, height), wedge(z0, z1, head, height),
             wedge(z0, z1, -SLAB, sill) if sill > 0 else box(8.0, foot, -SLAB, 0.0, z0, z1)]
    return parts, foot


def battered_wall_door() -> SampleLevel:
    """Room 8 x 6 m, a 1.6 m doorway W; the east wall battered like a bunker's (outer face 65 degrees from the
    horizontal, from x 9.70 at the floor to 8.3 at 3 m), a 1.6 m way through it (z 2.2-3.8) with vertical jambs and
    its floor to the outer face, under the wall's mass from 2.2 m (at the inner face; open to the sky from x 8.67,
    where the outer face comes down to 2.2 m, its sides the wall's sloping faces). Known: both, the east one at the
    outer face's foot (x 9.70)."""
    parts = _east_wall_removed(room(8.0, 6.0, ROOM_DOORS))
    east, foot = _battered_east((2.2, 3.8))
    return _level("battered_wall_door", parts + east, [ROOM_OPENINGS[0], _opening((foot, 0.0, 3.0), _E, 1.6)])


def battered_wall_embrasure() -> SampleLevel:
    """:func:`battered_wall_door` with, in place of the east way, an embrasure 1.2 m wide (z 2.4-3.6) from 0.6 m to
    1.5 m up through the battered wall. Known: the west doorway alone (a window: the rays at half the climb meet the
    wall under it)."""
    parts = _east_wall_removed(room(8.0, 6.0, ROOM_DOORS))
    east, _ = _battered_east((2.4, 3.6), sill=0.6, head=1.5)
    return _level("battered_wall_embrasure", parts + east, [ROOM_OPENINGS[0]])


def mezzanine_over_opening() -> SampleLevel:
    """Hall 10 x 8 m, walls 6 m high; a 1.6 m doorway W (z 3.2-4.8, lintel 2.2 m); in the east wall an opening
    3.2 m wide (z 2.4-5.6) and 5 m high, under a mezzanine inside along the east wall (x 7.5-10, its top 3 m up, a
    slab 0.2 m thick resting on the north, south and east walls, no way up) railed 1 m high along its west edge and
    across the opening. Known: both at the hall's floor; none on the mezzanine (railed)."""
    parts = room(10.0, 8.0, {"W": [(3.2, 4.8, 2.2)], "E": [(2.4, 5.6, 5.0)]}, height=6.0)
    parts += [box(7.5, 10.0, 2.8, 3.0, 0.0, 8.0), box(7.5, 7.6, 3.0, 4.0, 0.0, 8.0),
              box(9.9, 10.0, 3.0, 4.0, 2.4, 5.6)]
    return _level("mezzanine_over_opening", parts, [_opening((-0.3, 0.0, 4.0), _W, 1.6),
                                                    _opening((10.3, 0.0, 4.0), _E, 3.2)])


def sunken_doorway_steps() -> SampleLevel:
    """Room 8 x 6 m, a 1.6 m doorway W; the east doorway (z 2.2-3.8) three steps down: a well 1.6 m wide cut in the
    floor before it, treads 0.5 m deep at -0.15, -0.30 and -0.45 m (x 6.5-7.0, 7.0-7.5, 7.5-8.3, the last through
    the wall), under a lintel 2.2 m over the lowest tread. Known: both, the east one at the lowest tread (y -0.45)."""
    walls = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(2.2, 3.8, 1.75)]})[1:]
    floor = [box(-0.3, 6.5, -SLAB, 0.0, -0.3, 6.3), box(6.5, 8.3, -SLAB, 0.0, -0.3, 2.2),
             box(6.5, 8.3, -SLAB, 0.0, 3.8, 6.3)]
    floor += [box(x0, x1, -0.45 - SLAB, top, 2.2, 3.8)
              for x0, x1, top in ((6.5, 7.0, -0.15), (7.0, 7.5, -0.30), (7.5, 8.3, -0.45))]
    return _level("sunken_doorway_steps", walls + floor, [ROOM_OPENINGS[0], _opening((8.3, -0.45, 3.0), _E, 1.6)])


def column_beside_doors() -> SampleLevel:
    """Room 8 x 6 m, 1.6 m doorways W and E (z 2.2-3.8, lintels 2.2 m); a column 0.4 m square and 3 m high 0.3 m
    from a jamb of each: inside, before the west doorway's south jamb (x 0.4-0.8, z 1.5-1.9), and outside, beside the
    east doorway's north jamb (x 8.3-8.7, z 4.1-4.5). Known: both doorways."""
    parts = room(8.0, 6.0, ROOM_DOORS) + [box(0.4, 0.8, 0.0, 3.0, 1.5, 1.9), box(8.3, 8.7, -SLAB, 3.0, 4.1, 4.5)]
    return _level("column_beside_doors", parts, ROOM_OPENINGS)


def splayed_reveal_door() -> SampleLevel:
    """Room 8 x 6 m, a 1.6 m doorway W; the east wall 1 m thick (x 8.0-9.0), its doorway 1.2 m wide at the inner face
    (z 2.4-3.6) splaying to 2.2 m at the outer face (z 1.9-4.1), under a 2.2 m lintel, floored through. Known: both;
    the east one at the outer face, as wide as the way through (1.2 m)."""
    parts = _east_wall_removed(room(8.0, 6.0, ROOM_DOORS))
    north = [(8.0, 3.6), (9.0, 4.1), (9.0, 6.3), (8.0, 6.3)]
    south = [(8.0, -0.3), (9.0, -0.3), (9.0, 1.9), (8.0, 2.4)]
    way = [(8.0, 2.4), (9.0, 1.9), (9.0, 4.1), (8.0, 3.6)]
    parts += [prism(north, -SLAB, 3.0), prism(south, -SLAB, 3.0), prism(way, 2.2, 3.0), prism(way, -SLAB, 0.0)]
    return _level("splayed_reveal_door", parts, [ROOM_OPENINGS[0], _opening((9.0, 0.0, 3.0), _E, 1.2)])


def dutch_door_lower_closed() -> SampleLevel:
    """Room 8 x 6 m, 1.6 m doorways W and E (lintels 2.2 m); the east one a Dutch door, its lower leaf shut (0.05 m
    thick at the wall's outer face, 1.1 m high), its upper leaf open. Known: the west doorway alone."""
    parts = room(8.0, 6.0, ROOM_DOORS) + [box(8.25, 8.3, 0.0, 1.1, 2.2, 3.8)]
    return _level("dutch_door_lower_closed", parts, [ROOM_OPENINGS[0]])


def pergola_walk() -> SampleLevel:
    """Room 8 x 6 m, 1.6 m doorways W and E; from the east one a path 2 m wide (z 2.0-4.0) runs 5 m out (x 8.3-13.3)
    between planters 0.3 m wide and 0.6 m high, under a pergola: posts 0.15 m square on the planters every 1 m, two
    beams along them and slats across 0.1 m wide every 0.5 m, 2.4-2.5 m up. Known: the west doorway and the path's
    end (x 13.3, 2.0 m); the east doorway leads onto the path (no opening)."""
    parts = room(8.0, 6.0, ROOM_DOORS)
    parts += [box(8.3, 13.3, -SLAB, 0.0, 2.0, 4.0), box(8.3, 13.3, -SLAB, 0.6, 1.7, 2.0),
              box(8.3, 13.3, -SLAB, 0.6, 4.0, 4.3)]
    for x in (9.3, 10.3, 11.3, 12.3, 13.15):
        parts += [box(x, x + 0.15, 0.6, 2.4, 1.775, 1.925), box(x, x + 0.15, 0.6, 2.4, 4.075, 4.225)]
    parts += [box(8.3, 13.3, 2.3, 2.4, 1.775, 1.925), box(8.3, 13.3, 2.3, 2.4, 4.075, 4.225)]
    parts += [box(x, x + 0.1, 2.4, 2.5, 1.7, 4.3) for x in (8.4 + 0.5 * i for i in range(10))]
    return _level("pergola_walk", parts, [ROOM_OPENINGS[0], _opening((13.3, 0.0, 3.0), _E, 2.0)])


KINDS = kinds_by_name(battered_wall_door, battered_wall_embrasure, mezzanine_over_opening, sunken_doorway_steps,
                      column_beside_doors, splayed_reveal_door, dutch_door_lower_closed, pergola_walk)
"""Kind name -> factory of the twenty-second round."""


if __name__ == "__main__":
    sys.exit(run_kinds(kinds=KINDS, description=__doc__.splitlines()[0]))
