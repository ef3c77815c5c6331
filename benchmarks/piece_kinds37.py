"""A thirty-seventh round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds37.py [--kinds a b] [--configs map_piece map_piece_sampling] [--yaws 0
22 45] [--detail] [--one-to-one]``

Eight kinds of docs/entry_exit.md, "A thirty-seventh round of piece kinds", each with its known openings (count,
place, width, height, facing) written in its docstring before the detector first ran on them: the pieces of a level
designer's modular kit none of the earlier rounds built. A walled yard with a squeeze stile (a V-shaped slot in its
wall, narrower than the agent at every height); a tapered (Egyptian) doorway, wider at its foot than under its
lintel; a corridor whose end is a prow (the floor cut in a V, each half 30 degrees off square); an entrance hall (a
genkan) whose room floor stands 0.45 m up, over the climb, reached by a step stone; a hall with a serpentine of
rope barriers on posts; a doorway onto a kerb ramp rising 0.3 m over 1 m between cheek walls; a roofed corridor with
a light well rising through its roof; a road through a toll plaza, islands with booths under a canopy. Built with
:mod:`piece_parts`, in the earlier rounds' conventions.
"""

from __future__ import annotations

import math
import sys

from piece_parts import (ROOM_DOORS, ROOM_OPENINGS, SLAB, box, corridor, hull, kinds_by_name, prism, room,
                         round_level, run_kinds)

from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _N, _W

_level = round_level(37)


def squeeze_stile_yard(foot: float = 0.2, top: float = 0.6, wall: float = 1.2) -> SampleLevel:
    """A walled yard (clear x 0-8, z 0-6), open to the sky, floored at y 0 to its walls' outer faces; walls 0.3 m
    thick and ``wall`` m (1.2, over the 0.4 m climb) high; a 1.2 m gateway in the west wall (z 2.4-3.6) and a 1.6 m
    one in the north wall (x 3.2-4.8), both open to the sky; in the east wall a squeeze stile: a V-shaped slot
    centred on z 3.0, ``foot`` m (0.2) wide at the floor widening evenly to ``top`` m (0.6) at the wall's top, the
    floor running through it. Known: two, at the floor (y 0), open to the sky: the west gateway, 1.2 m at (-0.3,
    3.0), facing west; the north gateway, 1.6 m at (4.0, 6.3), facing north. Not the stile: it is narrower than the
    agent's 0.8 m at every height."""
    parts = room(8.0, 6.0, {"W": [(2.4, 3.6, wall)], "N": [(3.2, 4.8, wall)], "E": [(-0.3, 6.3, wall)]},
                 height=wall)
    for sign in (-1.0, 1.0):  # the stile's south (-) and north (+) cheeks, each from the slot to the wall's corner
        far, at_foot, at_top = 3.0 + sign * 3.3, 3.0 + sign * foot / 2, 3.0 + sign * top / 2
        parts.append(hull([[x, y, z] for x in (8.0, 8.3)
                           for y, z in ((-SLAB, far), (-SLAB, at_foot), (0.0, at_foot), (wall, at_top), (wall, far))]))
    return _level("squeeze_stile_yard", parts,
                  [_opening((-0.3, 0.0, 3.0), _W, 1.2), _opening((4.0, 0.0, 6.3), _N, 1.6)])


def tapered_doorway(foot: float = 1.4, head: float = 1.0, lintel: float = 2.4) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, no roof, floored to the walls' outer faces
    at y 0; a 1.6 m doorway in the west wall (z 2.2-3.8, lintel 2.2 m); in the east wall a tapered (Egyptian)
    doorway centred on z 3.0, ``foot`` m (1.4) wide at the floor narrowing evenly to ``head`` m (1.0) under its
    lintel ``lintel`` m (2.4) up (1.07 m at the agent's 2.0 m head), the wall whole over it to 3 m. Known: two, at
    the floor (y 0): the west doorway, 1.6 m at (-0.3, 3.0), facing west, 2.2 m high; the tapered doorway at the
    wall's outer face (8.3, 3.0), facing east, 2.4 m high, its width decided before the run as the designer's
    measure, at the floor: 1.4 m (it is wider than the agent at every height up to the agent's)."""
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(-0.3, 6.3, 3.0)]})  # the east wall built below
    for sign in (-1.0, 1.0):  # the south (-) and north (+) jambs
        far, at_foot, at_head = 3.0 + sign * 3.3, 3.0 + sign * foot / 2, 3.0 + sign * head / 2
        parts.append(hull([[x, y, z] for x in (8.0, 8.3)
                           for y, z in ((-SLAB, far), (-SLAB, at_foot), (0.0, at_foot), (lintel, at_head),
                                        (lintel, far))]))
    parts.append(box(8.0, 8.3, lintel, 3.0, -0.3, 6.3))
    return _level("tapered_doorway", parts,
                  [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((8.3, 0.0, 3.0), _E, foot)])


def prow_end_corridor(cut_deg: float = 30.0) -> SampleLevel:
    """Corridor 12 x 2.4 m (clear x 0-12, z 0-2.4), walls 0.3 m thick and 3 m high ending square at x 12, open to
    the sky, floor at y 0; its west end open and square at x 0; its east end a prow: the floor runs past the walls'
    ends in a V, each half of the end cut ``cut_deg`` (30) degrees off square, from the walls' ends (12, 0) and (12,
    2.4) to a point on the axis at (12 + 1.2 tan ``cut_deg``, 1.2) = (12.69, 1.2); the cut's two halves 1.39 m long
    each. Known: two, at the floor (y 0), 2.4 m each, open to the sky: the west end at (0, 1.2), facing west; the
    prow, decided before the run as ONE opening (one way out between the walls' ends), 2.4 m (the way's width
    between the walls' ends; the cut's length is 2.77 m) at (12, 1.2), facing east. Nothing along either half of
    the cut alone."""
    tip = 12.0 + 1.2 * math.tan(math.radians(cut_deg))
    parts = corridor(12.0, floor=False) + [prism([(0.0, 0.0), (12.0, 0.0), (tip, 1.2), (12.0, 2.4), (0.0, 2.4)],
                                                 -SLAB, 0.0)]
    return _level("prow_end_corridor", parts,
                  [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, 1.2), _E, 2.4)])


def genkan_step_stone(raised: float = 0.45, stone: float = 0.25) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick standing 3 m over the raised floor, no roof; an entrance
    hall (a genkan) 1.5 m deep (x 0-1.5) floored at y 0 to the west wall's outer face; the rest of the room's floor
    raised ``raised`` m (0.45, over the 0.4 m climb; x 1.5-8, solid) and run out under the east doorway to the
    wall's outer face; in the genkan against the raised floor's edge a step stone ``stone`` m (0.25) high, 1.2 m
    wide and 0.6 m deep (x 0.9-1.5, z 2.4-3.6), the only way up (0.25 then 0.2 m). A 1.6 m doorway in the west wall
    (z 2.2-3.8, lintel 2.2 m over y 0) and one in the east wall (z 2.2-3.8, its sill the raised floor, lintel 2.2 m
    over it). Known: two, 1.6 m each, 2.2 m high: the west doorway at (-0.3, 3.0) at y 0, facing west; the east
    doorway at (8.3, 3.0) at y ``raised``, facing east. Nothing at the raised floor's edge or the stone (inside the
    piece)."""
    top = raised + 3.0
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(2.2, 3.8, raised + 2.2)]}, height=top)
    parts += [box(1.5, 8.0, 0.0, raised, 0.0, 6.0), box(8.0, 8.3, 0.0, raised, 2.2, 3.8),
              box(0.9, 1.5, 0.0, stone, 2.4, 3.6)]
    return _level("genkan_step_stone", parts,
                  [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((8.3, raised, 3.0), _E, 1.6)])


def queue_rope_hall(rope: float = 0.03, post: float = 0.06) -> SampleLevel:
    """Hall 10 x 8 m (clear x 0-10, z 0-8), walls 0.3 m thick and 3 m high, no roof, floored to the walls' outer
    faces at y 0; a 1.6 m doorway in the west wall and one in the east wall (z 5.2-6.8, lintels 2.2 m). Over the
    hall's south half a queue: three lines of rope barriers, posts ``post`` m (0.06) square and 1.0 m high every 2.2
    m or less along each line, ropes ``rope`` m (0.03) thick between them 0.85 m up: at z 1.2 from the west wall to
    x 8.8, at z 2.4 from x 1.2 to the east wall, at z 3.6 from the west wall to x 8.8, leaving lanes 1.2 m wide
    turning through 1.2 m ends (a serpentine entered from the hall's north half at x 8.8-10). Known: two, at the
    floor (y 0), 1.6 m each, 2.2 m high: the west doorway at (-0.3, 6.0), facing west; the east doorway at (10.3,
    6.0), facing east. Nothing at the ropes or posts (inside the piece)."""
    parts = room(10.0, 8.0, {"W": [(5.2, 6.8, 2.2)], "E": [(5.2, 6.8, 2.2)]})
    h, r = post / 2, rope / 2
    for z, x0, x1 in ((1.2, 0.0, 8.8), (2.4, 1.2, 10.0), (3.6, 0.0, 8.8)):
        parts.append(box(x0, x1, 0.85 - r, 0.85 + r, z - r, z + r))
        n = math.ceil((x1 - x0) / 2.2)
        for i in range(n + 1):
            x = min(max(x0 + i * (x1 - x0) / n, x0 + h), x1 - h)  # the end posts against the wall or at the line's end
            parts.append(box(x - h, x + h, 0.0, 1.0, z - h, z + h))
    return _level("queue_rope_hall", parts,
                  [_opening((-0.3, 0.0, 6.0), _W, 1.6), _opening((10.3, 0.0, 6.0), _E, 1.6)])


def kerb_ramp_apron(rise: float = 0.3, run: float = 1.0) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, no roof, floored to the walls' outer faces
    at y 0; a 1.6 m doorway in the west wall and one in the east wall (z 2.2-3.8, lintels 2.2 m); outside the east
    doorway a kerb ramp: an apron 1.6 m wide (z 2.2-3.8) and ``run`` m (1.0) long (x 8.3-9.3) rising evenly from
    the floor at the wall's face to ``rise`` m (0.3, 16.7 degrees) at its outer end, solid to the slab's underside,
    between cheek walls 0.3 m thick and 1.0 m over the ramp's top (z 1.9-2.2 and 3.8-4.1), open to the sky. Known:
    two, 1.6 m each: the west doorway at (-0.3, 3.0) at y 0, facing west, 2.2 m high; the kerb ramp's outer end,
    where the next piece snaps, at (9.3, 3.0) at y ``rise``, facing east, open to the sky. Nothing at the east
    doorway itself (the way runs on down the ramp)."""
    end = 8.3 + run
    parts = room(8.0, 6.0, ROOM_DOORS)
    parts.append(hull([[x, y, z] for x, top in ((8.3, 0.0), (end, rise)) for y in (-SLAB, top) for z in (2.2, 3.8)]))
    for z0, z1 in ((1.9, 2.2), (3.8, 4.1)):
        parts.append(hull([[x, y, z] for x, top in ((8.3, 1.0), (end, rise + 1.0)) for y in (-SLAB, top)
                           for z in (z0, z1)]))
    return _level("kerb_ramp_apron", parts,
                  [ROOM_OPENINGS[0], _opening((end, rise, 3.0), _E, 1.6)])


def light_well_tunnel(well: tuple[float, float] = (5.0, 7.0), rise: float = 3.0) -> SampleLevel:
    """Corridor 12 x 2.4 m (clear x 0-12, z 0-2.4), walls 0.3 m thick and 3 m high, floor at y 0, both ends open,
    roofed by a slab 0.2 m thick over its walls (y 3.0-3.2, x 0-12, z -0.3-2.7) but for a light well over ``well``
    (x 5-7, the corridor's width): the roof cut away there and the well's walls, 0.3 m thick, rising ``rise`` m
    (3.0) over the roof round it (x 4.7-7.3, z -0.3-2.7), open to the sky at the top. Known: two, at the floor
    (y 0), 2.4 m each, 3.0 m high: the west end at (0, 1.2), facing west; the east end at (12, 1.2), facing east.
    Nothing at the well (no floor up there; its top is 6.2 m over the floor)."""
    w0, w1 = well
    top = 3.2 + rise
    parts = corridor(12.0) + [box(0.0, w0, 3.0, 3.2, -0.3, 2.7), box(w1, 12.0, 3.0, 3.2, -0.3, 2.7),
                              box(w0 - 0.3, w0, 3.2, top, -0.3, 2.7), box(w1, w1 + 0.3, 3.2, top, -0.3, 2.7),
                              box(w0, w1, 3.0, top, -0.3, 0.0), box(w0, w1, 3.0, top, 2.4, 2.7)]
    return _level("light_well_tunnel", parts,
                  [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, 1.2), _E, 2.4)])


def toll_plaza_islands(kerb: float = 0.15) -> SampleLevel:
    """A road through a toll plaza (clear x 0-16, z 0-10), open at both ends, floor at y 0, between barrier walls
    0.3 m thick and 1.0 m high (over the climb) along its sides (z -0.3-0 and 10-10.3); two islands ``kerb`` m
    (0.15) high, 1.2 m wide and 6 m long (x 5-11; z 3.0-4.2 and 5.8-7.0), solid to the slab, each carrying a booth
    2 m long (x 7-9, 0.1 m inside the island's sides) up to a canopy slab 0.3 m thick whose underside is 5.0 m up,
    over x 6-10 across the road and its barriers; lanes 3.0, 1.6 and 3.0 m wide between them. Known: two, at the
    floor (y 0), 10 m each, open to the sky: the west end at (0, 5.0), facing west; the east end at (16, 5.0),
    facing east. Decided before the run: ONE opening at each end (the islands stand inside the piece, 5 m from
    each end, and part the road into lanes each wider than the agent), nothing at the islands or booths."""
    parts = [box(0.0, 16.0, -SLAB, 0.0, -0.3, 10.3), box(0.0, 16.0, -SLAB, 1.0, -0.3, 0.0),
             box(0.0, 16.0, -SLAB, 1.0, 10.0, 10.3), box(6.0, 10.0, 5.0, 5.3, -0.3, 10.3)]
    for z0, z1 in ((3.0, 4.2), (5.8, 7.0)):
        parts += [box(5.0, 11.0, 0.0, kerb, z0, z1), box(7.0, 9.0, kerb, 5.0, z0 + 0.1, z1 - 0.1)]
    return _level("toll_plaza_islands", parts,
                  [_opening((0.0, 0.0, 5.0), _W, 10.0), _opening((16.0, 0.0, 5.0), _E, 10.0)])


KINDS = kinds_by_name(squeeze_stile_yard, tapered_doorway, prow_end_corridor, genkan_step_stone, queue_rope_hall,
                      kerb_ramp_apron, light_well_tunnel, toll_plaza_islands)
"""Kind name -> factory of the thirty-seventh round."""


if __name__ == "__main__":
    sys.exit(run_kinds(sys.argv[1:], kinds=KINDS, description=__doc__.splitlines()[0]))
