"""A twenty-eighth round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds28.py [--kinds a b] [--configs map_piece map_piece_sampling] [--yaws 0
22 45] [--detail] [--one-to-one]``

Eight kinds of docs/entry_exit.md, "A twenty-eighth round of piece kinds", each with its known openings (count, place,
width, height) written in its docstring before the detector first ran on them: the pieces of a level designer's
modular kit none of the earlier rounds built. Two round arches springing at 1.6 m, one wide enough for the 2 m agent
and one not; a sliding barn door on a doorway's inner face left open by just over the agent's width; a closed room
whose only way out is a stair down through a hole in its floor to a corridor below; a window seat whose 0.45 m sill
leads out to a railed balcony; a T-piece whose side arm is filled by a heap of rubble one can climb over; a room whose
floor slab was imported twice, 1 mm apart; a doorway cut with parallel jambs through the crown of a half-round apse;
two doorways 0.3 m apart of which one opens into a closed store room. Built with :mod:`piece_parts`, in the earlier
rounds' conventions.
"""

from __future__ import annotations

import math
import sys

import numpy as np
from piece_parts import (ROOM_DOORS, ROOM_OPENINGS, SLAB, arc_band, arm_junction, box, hull, kinds_by_name, prism,
                         room, round_level, run_kinds)

from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _N, _W

_level = round_level(28)


def low_spring_arches(spring: float = 1.6, strips: int = 16) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, a 1.6 m west doorway (z 2.2-3.8, lintel
    2.2 m); in the east wall two round (semicircular) arches whose jambs stop ``spring`` m (1.6) up, under the agent's
    2 m height: a wide one 1.6 m across (z 1.0-2.6, crown 2.4 m, 1.39 m clear at 2 m) and a narrow one 1.0 m across
    (z 3.8-4.8, crown 2.1 m, 0.6 m clear at 2 m), the wall over each in ``strips`` strips. A round arch springing at
    1.6 m lets the agent (0.8 m across, 2 m tall) through from a span of 2 sqrt(0.4^2 + 0.4^2) = 1.13 m, so a designer
    counts the wide one and not the narrow one. Known: two, at the floor (y 0): the west doorway, 1.6 m at (-0.3,
    3.0); the wide arch, 1.6 m (its width at the floor, as the earlier rounds' arches) at the wall's outer face (8.3,
    1.8), 2.4 m high at its crown. Not the narrow arch."""
    arches = ((1.8, 0.8), (4.3, 0.5))  # (centre z, radius)
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(c - r, c + r, 3.0) for c, r in arches]})
    for centre, radius in arches:
        edges = np.linspace(centre - radius, centre + radius, strips + 1)

        def soffit(z: float) -> float:  # the arch's underside at z, metres up
            return spring + math.sqrt(max(radius ** 2 - (z - centre) ** 2, 0.0))

        for z0, z1 in zip(edges[:-1], edges[1:]):
            parts.append(hull([[x, y, z] for x in (8.0, 8.3) for z, y in ((z0, soffit(z0)), (z1, soffit(z1)),
                                                                          (z0, 3.0), (z1, 3.0))]))
    return _level("low_spring_arches", parts, [ROOM_OPENINGS[0], _opening((8.3, 0.0, 1.8), _E, 1.6)])


def barn_door_slid_open(gap: float = 0.9) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, 1.6 m doorways west and east (z 2.2-3.8,
    lintels 2.2 m); before the east doorway, on the wall's inner face, a sliding (barn) door: a leaf 1.7 m long,
    0.04 m thick (x 7.94-7.98), from 0.01 m over the floor to 2.25 m, hanging from a rail (x 7.94-8.0, y 2.25-2.35,
    z 0.5-5.5), slid south so that ``gap`` m (0.9, just over the agent's 0.8 m) of the doorway stays free (the leaf
    over z 3.8 - ``gap`` - 1.7 to 3.8 - ``gap``). Known: two, at the floor (y 0): the west doorway, 1.6 m at (-0.3,
    3.0); the east one as wide as the way through it, ``gap`` m, at the wall's outer face (8.3, 3.8 - ``gap`` / 2),
    2.2 m high (the leaf stands 0.02 m inside the inner face: the way's waist, as round 27's double splay)."""
    edge = 3.8 - gap
    parts = room(8.0, 6.0, ROOM_DOORS)
    parts += [box(7.94, 7.98, 0.01, 2.25, edge - 1.7, edge), box(7.94, 8.0, 2.25, 2.35, 0.5, 5.5)]
    return _level("barn_door_slid_open", parts, [ROOM_OPENINGS[0], _opening((8.3, 0.0, 3.8 - gap / 2), _E, gap)])


def stair_hole_only_exit(riser: float = 0.2, tread: float = 0.3, steps: int = 14) -> SampleLevel:
    """A closed room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, no doorway; in its floor a hole
    (x 1.5-7.0, z 0-1.2) along the south wall, railed 1.0 m high along its north (z 1.2-1.3, x 2.1-7.0) and east
    (x 7.0-7.1) edges, over a straight stair 1.2 m wide going down east: ``steps`` (14) solid steps of ``riser`` m
    (0.2) on ``tread`` m (0.3) treads from x 1.5, then a corridor 1.2 m wide (z 0-1.2) at y -3.0 under the room's
    floor (2.8 m of head room under the slab), walled 0.3 m thick up to the slab, running east under the room's east
    wall to its open end at x 10.3, 2 m beyond the room. Known: one, 3 m down (y -3.0): the corridor's end, 1.2 m at
    (10.3, 0.6) facing east, 2.8 m high under the room and open above beyond it. Not the hole (a way down inside the
    piece)."""
    low = -(steps + 1) * riser
    end = 1.5 + steps * tread  # where the corridor's floor begins
    parts = room(8.0, 6.0, {})[1:]  # the walls, without the slab
    parts += [box(-0.3, 8.3, -SLAB, 0.0, 1.2, 6.3), box(-0.3, 1.5, -SLAB, 0.0, -0.3, 1.2),
              box(7.0, 8.3, -SLAB, 0.0, -0.3, 1.2)]  # the slab round the hole
    parts += [box(2.1, 7.0, 0.0, 1.0, 1.2, 1.3), box(7.0, 7.1, 0.0, 1.0, 0.0, 1.2)]  # the hole's railing
    parts += [box(1.5 + i * tread, 1.5 + (i + 1) * tread, low - SLAB, -(i + 1) * riser, 0.0, 1.2)
              for i in range(steps)]
    parts.append(box(end, 10.3, low - SLAB, low, 0.0, 1.2))  # the corridor's floor
    parts += [box(1.2, 10.3, low - SLAB, -SLAB, z0, z1) for z0, z1 in ((-0.3, 0.0), (1.2, 1.5))]
    parts.append(box(1.2, 1.5, low - SLAB, -SLAB, 0.0, 1.2))  # the stair well's west end
    return _level("stair_hole_only_exit", parts, [_opening((10.3, low, 0.6), _E, 1.2)])


def window_sill_balcony(sill: float = 0.45) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, 1.6 m doorways west and east (z 2.2-3.8,
    lintels 2.2 m); in the north wall a window 2.0 m wide (x 3.0-5.0) from a sill ``sill`` m (0.45, 0.05 over the
    climb) up to a 2.2 m head, a window seat of the sill's height in front of it (x 3.0-5.0, z 5.5-6.0), and beyond it
    a balcony at the room's floor height (slab x 2.5-5.5, z 6.3-7.8) railed 1.0 m high and 0.1 m thick on its west,
    north and east sides (2.8 x 1.4 m clear). Known: two, at the floor (y 0): the west doorway, 1.6 m at (-0.3, 3.0);
    the east one, 1.6 m at (8.3, 3.0). Not the window (a sill over the climb), nothing on the balcony (reached over
    the sill only, and closed)."""
    parts = room(8.0, 6.0, dict(ROOM_DOORS, N=[(3.0, 5.0, 2.2)]))
    parts += [box(3.0, 5.0, -SLAB, sill, 5.5, 6.3), box(2.5, 5.5, -SLAB, 0.0, 6.3, 7.8)]  # seat and sill; balcony
    parts += [box(2.5, 5.5, 0.0, 1.0, 7.7, 7.8), box(2.5, 2.6, 0.0, 1.0, 6.3, 7.7), box(5.4, 5.5, 0.0, 1.0, 6.3, 7.7)]
    return _level("window_sill_balcony", parts, ROOM_OPENINGS)


def t_rubble_arm(crest: float = 1.0) -> SampleLevel:
    """A T-piece of corridors 2.4 m wide (clear), walls 0.3 m thick and 3 m high: arms east, north and west of the
    origin, each 6 m to its open end; the north arm filled wall to wall by a collapsed-rubble heap from z 1.6 to 5.0:
    two overlapping irregular hulls whose crest runs about ``crest`` m (1.0; 0.9-1.15) up at z 3.2-3.7, their upward
    faces 31-47 degrees steep (under the agent's 60), no roof over it. Known: three, at the floor (y 0), 2.4 m each: the west end
    (-6, 0), the east end (6, 0) and the north arm's end (0, 6) beyond the heap (one climbs over it)."""
    parts, _ = arm_junction([0.0, 90.0, 180.0], [1.2, 1.2, 1.2], [6.0, 6.0, 6.0])
    parts.append(hull([[-1.2, -0.05, 1.6], [1.2, -0.05, 1.7], [-1.2, -0.05, 4.6], [1.2, -0.05, 4.4],
                       [-1.2, 0.9 * crest, 3.2], [0.2, 1.05 * crest, 3.3], [1.2, crest, 3.4]]))
    parts.append(hull([[-1.2, -0.05, 2.4], [1.2, -0.05, 2.2], [-1.2, -0.05, 5.0], [1.2, -0.05, 4.8],
                       [-1.2, 1.15 * crest, 3.7], [1.2, 0.95 * crest, 3.5]]))
    return _level("t_rubble_arm", parts, [_opening((-6.0, 0.0, 0.0), _W, 2.4), _opening((6.0, 0.0, 0.0), _E, 2.4),
                                          _opening((0.0, 0.0, 6.0), _N, 2.4)])


def doubled_floor_1mm(offset: float = 0.001) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, 1.6 m doorways west and east (z 2.2-3.8,
    lintels 2.2 m), its floor slab imported twice (two kit meshes overlapping): a second copy of the slab, the same
    box, ``offset`` m (1 mm) above the first, its top at 0.001 m and through the first one's top face. Known: two,
    at the floor (y 0, to the millimetre): the west doorway, 1.6 m at (-0.3, 3.0); the east one, 1.6 m at (8.3,
    3.0)."""
    parts = room(8.0, 6.0, ROOM_DOORS)
    parts.append(box(-0.3, 8.3, -SLAB + offset, offset, -0.3, 6.3))
    return _level("doubled_floor_1mm", parts, ROOM_OPENINGS)


def apse_crown_door(radius: float = 3.0, strips: int = 8) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, a 1.6 m west doorway (z 2.2-3.8, lintel
    2.2 m); east, in place of its east wall, a half-round apse: a cylindrical wall of inner radius ``radius`` m (3.0)
    and 0.3 m thick about (8, 3), in facets of at most 7.5 degrees, floored to its outer face; through its crown a
    doorway cut with parallel jambs (z 2.2-3.8, not radial: the reveals 0.31 m deep at the jambs, 0.3 m in the middle)
    under a lintel 2.2 m up in ``strips`` strips, its floor ending along the outer circle (x 11.20 at the jambs, 11.3
    in the middle). Known: two, at the floor (y 0): the west doorway, 1.6 m at (-0.3, 3.0); the apse's door, 1.6 m
    at the outer face's middle (8 + ``radius`` + 0.3, 3.0), facing east, 2.2 m high."""
    outer = radius + 0.3
    jamb = 0.8  # the door's half width

    def on(r: float, deg: float) -> tuple[float, float]:
        return 8.0 + r * math.cos(math.radians(deg)), 3.0 + r * math.sin(math.radians(deg))

    inner_deg, outer_deg = math.degrees(math.asin(jamb / radius)), math.degrees(math.asin(jamb / outer))
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(-0.3, 6.3, 3.0)]})
    parts.append(prism([on(outer, a) for a in np.linspace(-90.0, 90.0, 91)], -SLAB, 0.0))
    for sign in (-1.0, 1.0):
        a0, a1 = sorted((sign * inner_deg, sign * 90.0))
        parts += arc_band(8.0, 3.0, radius, outer, a0, a1, -SLAB, 3.0)
        arc = np.linspace(sign * inner_deg, sign * outer_deg, 4)
        parts.append(prism([on(radius, sign * inner_deg)] + [on(outer, a) for a in arc], -SLAB, 3.0))  # the jamb
    edges = np.linspace(3.0 - jamb, 3.0 + jamb, strips + 1)
    for z0, z1 in zip(edges[:-1], edges[1:]):
        plan = [(8.0 + math.sqrt(r ** 2 - (z - 3.0) ** 2), z) for r in (radius, outer) for z in (z0, z1)]
        parts.append(prism(plan, 2.2, 3.0))
    return _level("apse_crown_door", parts, [ROOM_OPENINGS[0], _opening((8.0 + outer, 0.0, 3.0), _E, 2 * jamb)])


def twin_doors_store_room() -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, a 1.6 m west doorway (z 2.2-3.8, lintel
    2.2 m); in the east wall two 1.2 m doorways 0.3 m apart (z 1.35-2.55 and 2.85-4.05, lintels 2.2 m): the south one
    opens out, the piece's floor ending at the wall's outer face; the north one opens into a closed store room 2.0 x
    2.0 m (clear x 8.3-10.3, z 2.85-4.85) walled 0.3 m thick and 3 m high, its south wall the pier between the doors
    carried on. Known: two, at the floor (y 0): the west doorway, 1.6 m at (-0.3, 3.0); the south east door, 1.2 m
    at its outer face (8.3, 1.95), 2.2 m high. Not the store room's door (it leads nowhere out of the piece)."""
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(1.35, 2.55, 2.2), (2.85, 4.05, 2.2)]})
    parts += [box(8.3, 10.6, -SLAB, 0.0, 2.55, 5.15), box(8.3, 10.6, -SLAB, 3.0, 2.55, 2.85),
              box(8.3, 10.6, -SLAB, 3.0, 4.85, 5.15), box(10.3, 10.6, -SLAB, 3.0, 2.85, 4.85)]
    return _level("twin_doors_store_room", parts, [ROOM_OPENINGS[0], _opening((8.3, 0.0, 1.95), _E, 1.2)])


KINDS = kinds_by_name(low_spring_arches, barn_door_slid_open, stair_hole_only_exit, window_sill_balcony, t_rubble_arm,
                      doubled_floor_1mm, apse_crown_door, twin_doors_store_room)
"""Kind name -> factory of the twenty-eighth round."""


if __name__ == "__main__":
    sys.exit(run_kinds(sys.argv[1:], kinds=KINDS, description=__doc__.splitlines()[0]))
