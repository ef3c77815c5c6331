"""A twenty-ninth round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds29.py [--kinds a b] [--configs map_piece map_piece_sampling] [--yaws 0
22 45] [--detail] [--one-to-one]``

Eight kinds of docs/entry_exit.md, "A twenty-ninth round of piece kinds", each with its known openings (count, place,
width, height) written in its docstring before the detector first ran on them: the pieces of a level designer's
modular kit none of the earlier rounds built. A portcullis whose bottom rail clears the agent but whose spikes hang to
1.6 m; a doorway whose threshold is 0.3 m over the room's floor (a step down just inside it); a trapdoor in a room's
floor over nothing, a ladder hanging through it; an L corner of corridors whose north arm ramps up 0.9 m; a hole
knocked through a wall at the floor, ragged edged, rubble on the floor; a wide doorway screened by two thin columns
into three gaps; a floor of loose tiles with 5 mm gaps through it; an arcade of five arches between a loggia and the
street in front of it. Built with :mod:`piece_parts`, in the earlier rounds' conventions.
"""

from __future__ import annotations

import math
import sys

import numpy as np
from piece_parts import (ROOM_DOORS, ROOM_OPENINGS, SLAB, box, corridor, hull, kinds_by_name, prism, room,
                         round_level, run_kinds)

from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _N, _S, _W

_level = round_level(29)


def spiked_portcullis_end(points: float = 1.6, rail: float = 2.1) -> SampleLevel:
    """Corridor 12 x 2.4 m (clear x 0-12, z 0-2.4), walls 0.3 m thick and 3 m high, both ends open; at its east end,
    under a beam 2.6-3.0 m up (x 11.7-12.0), a portcullis raised until its bottom rail (x 11.8-11.88) is ``rail`` m
    (2.1) up, over the agent's 2 m, but its spikes hang under the rail to ``points`` m (1.6): 0.06 m square every
    0.24 m (0.18 m between them), and its bars (0.08 m square every 0.48 m) carry on from the rail to the beam. Known:
    one, the west end, 2.4 m at (0, 1.2) at the floor (y 0), 3 m high; not the east end (1.6 m under the spikes'
    points, and 0.18 m between them: no way for the agent, 0.8 m across and 2 m tall)."""
    parts = corridor(12.0) + [box(11.7, 12.0, 2.6, 3.0, 0.0, 2.4), box(11.8, 11.88, rail, rail + 0.08, 0.0, 2.4)]
    parts += [box(11.8, 11.88, rail, 2.6, z, z + 0.08) for z in np.arange(0.2, 2.4 - 0.08, 0.48)]
    parts += [box(11.81, 11.87, points, rail, z, z + 0.06) for z in np.arange(0.09, 2.4 - 0.06, 0.24)]
    return _level("spiked_portcullis_end", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4)])


def raised_threshold_step(step: float = 0.3) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, 1.6 m doorways west and east (z 2.2-3.8);
    the east doorway's floor through the wall a threshold ``step`` m (0.3, within the 0.4 m climb) over the room's
    floor (x 8.0-8.3), the step down just inside its frame, under a lintel 2.5 m up (2.2 m over the threshold); the
    west one at the floor under a 2.2 m lintel; the piece ends at the walls' outer faces. Known: two: the west
    doorway, 1.6 m at (-0.3, 3.0) at y 0; the east one, 1.6 m at (8.3, 3.0), ``step`` m up (the threshold's top, where
    the neighbour's floor meets it), 2.2 m high."""
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(2.2, 3.8, 2.2 + step)]})
    parts.append(box(8.0, 8.3, 0.0, step, 2.2, 3.8))
    return _level("raised_threshold_step", parts, [ROOM_OPENINGS[0], _opening((8.3, step, 3.0), _E, 1.6)])


def trapdoor_over_nothing(depth: float = 3.0) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, 1.6 m doorways west and east (z 2.2-3.8,
    lintels 2.2 m); in its floor a trapdoor 1.2 m square (x 5.0-6.2, z 4.2-5.4) over nothing (the piece under it is
    another module), its lid (0.05 m thick) lying open on the floor north of it (x 5.0-6.2, z 5.45-5.95),
    and a ladder (stiles 0.05 m square, rungs every 0.3 m) hanging from its south edge ``depth`` m (3.0) down into
    the void. Known: two, at the floor (y 0): the west doorway, 1.6 m at (-0.3, 3.0); the east one, 1.6 m at (8.3,
    3.0). Not the trapdoor: a way down a ladder is no walk for the agent, and a designer joins it to the module below
    by a link of their own (an off-mesh connection placed by hand), not by a walking opening at the piece's face."""
    hole_x, hole_z = (5.0, 6.2), (4.2, 5.4)
    parts = room(8.0, 6.0, ROOM_DOORS)[1:]  # the walls, without the slab
    parts += [box(-0.3, 8.3, -SLAB, 0.0, -0.3, hole_z[0]), box(-0.3, 8.3, -SLAB, 0.0, hole_z[1], 6.3),
              box(-0.3, hole_x[0], -SLAB, 0.0, *hole_z), box(hole_x[1], 8.3, -SLAB, 0.0, *hole_z)]
    parts.append(box(5.0, 6.2, 0.0, 0.05, 5.45, 5.95))  # the lid, laid back on the floor
    parts += [box(x, x + 0.05, -depth, 0.0, 4.25, 4.3) for x in (5.2, 5.95)]  # the ladder's stiles
    parts += [box(5.25, 5.95, y, y + 0.04, 4.25, 4.29) for y in np.arange(-depth + 0.3, -0.1, 0.3)]  # its rungs
    return _level("trapdoor_over_nothing", parts, ROOM_OPENINGS)


def l_corner_ramp_up(rise: float = 0.9, run: float = 4.0) -> SampleLevel:
    """An L corner of corridors 2.4 m wide (clear), walls 0.3 m thick: a south arm along x (clear x 0-8.4, z 0-2.4),
    open at its west end (x 0); a north arm (clear x 6.0-8.4) from the corner north to its open end at z 8.0, its
    floor a ramp rising ``rise`` m (0.9) over ``run`` m (4.0: 12.7 degrees) from z 2.4, then level at ``rise`` m to
    the end; walls 3 m high over the lower floor, 3 + ``rise`` m along the north arm. Known: two, 2.4 m each: the west
    end at (0, 1.2) at y 0 facing west, 3 m high; the north end at (7.2, 8.0), ``rise`` m up, facing north."""
    top = 3.0 + rise
    parts = [box(0.0, 8.4, -SLAB, 0.0, 0.0, 2.4), box(6.0, 8.4, -SLAB, rise, 2.4 + run, 8.0),
             hull([[x, y, z] for x in (6.0, 8.4) for z, y in ((2.4, 0.0), (2.4 + run, rise), (2.4, -SLAB),
                                                                (2.4 + run, -SLAB))])]
    parts += [box(0.0, 8.7, -SLAB, 3.0, -0.3, 0.0), box(8.4, 8.7, -SLAB, top, -0.3, 8.0),
              box(0.0, 6.0, -SLAB, 3.0, 2.4, 2.7), box(5.7, 6.0, -SLAB, top, 2.4, 8.0)]
    return _level("l_corner_ramp_up", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((7.2, rise, 8.0), _N, 2.4)])


_RAGGED_LAYERS = ((0.0, 0.3, 2.25, 3.75), (0.3, 0.6, 2.1, 3.9), (0.6, 0.9, 2.3, 3.7), (0.9, 1.2, 2.15, 3.85),
                  (1.2, 1.5, 2.35, 3.65), (1.5, 1.8, 2.2, 3.8), (1.8, 2.1, 2.4, 3.6), (2.1, 2.4, 2.3, 3.75),
                  (2.4, 2.7, 2.7, 3.3))
"""The knocked-through hole's layers: (y0, y1, south edge z, north edge z) metres, floor to top."""


def knocked_through_hole() -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, a 1.6 m west doorway (z 2.2-3.8, lintel
    2.2 m); in the east wall a hole knocked through at the floor, its edges ragged: in layers 0.3 m high its south
    edge at z 2.25, 2.1, 2.3, 2.15, 2.35, 2.2, 2.4, 2.3 and its north edge at 3.75, 3.9, 3.7, 3.85, 3.65, 3.8, 3.6,
    3.75 from the floor to 2.4 m, its top ragged (z 2.7-3.3 open to 2.7 m), each layer's edges leaning 0.05 m across
    the wall's thickness (wider at the outer face); rubble on the room's floor before it: five chunks 0.1-0.25 m high
    (under the 0.4 m climb). The narrowest the hole is under the agent's 2 m is 1.2 m (z 2.4-3.6, 1.8-2.1 m up).
    Known: two, at the floor (y 0): the west doorway, 1.6 m at (-0.3, 3.0); the hole, 1.2 m (the narrowest way
    through it for the 2 m agent) at its outer face (8.3, 3.0), 2.4 m high."""
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(1.9, 4.1, 3.0)]})  # the east wall's gap, filled below
    for y0, y1, south, north in _RAGGED_LAYERS:  # the jambs' layers, each edge 0.05 m back at the outer face
        parts.append(prism([(8.0, 1.9), (8.0, south), (8.3, south - 0.05), (8.3, 1.9)], y0, y1))
        parts.append(prism([(8.0, north), (8.0, 4.1), (8.3, 4.1), (8.3, north + 0.05)], y0, y1))
    parts.append(box(8.0, 8.3, 2.7, 3.0, 1.9, 4.1))  # the wall over the hole
    rubble = ((7.0, 2.0, 0.25), (7.4, 4.2, 0.15), (6.2, 3.4, 0.1), (7.6, 2.6, 0.12), (6.8, 4.6, 0.2))
    for x, z, h in rubble:
        parts.append(hull([[x - 0.2, 0.0, z - 0.15], [x + 0.25, 0.0, z - 0.1], [x + 0.1, 0.0, z + 0.2],
                           [x - 0.15, 0.0, z + 0.15], [x, h, z]]))
    return _level("knocked_through_hole", parts, [ROOM_OPENINGS[0], _opening((8.3, 0.0, 3.0), _E, 1.2)])


def column_screen_three_gaps(gap: float = 1.0, column: float = 0.3, sides: int = 8) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, a 1.6 m west doorway (z 2.2-3.8, lintel
    2.2 m); in the east wall a doorway 3 * ``gap`` + 2 * ``column`` m wide (3.6 m, z 1.2-4.8) under a lintel 2.4 m
    up, screened by two round columns ``column`` m (0.3) across in ``sides`` facets, centred in the wall's thickness
    (x 8.15) at z 2.35 and 3.65, floor to lintel: three gaps of ``gap`` m (1.0) each. Known: two, at the floor (y 0):
    the west doorway, 1.6 m at (-0.3, 3.0); the screened doorway as ONE opening, 3.6 m at its outer face (8.3, 3.0),
    2.4 m high: a column narrower than the agent (0.3 of 0.8 m) is the doorway's frame, not a wall between doors
    (the twentieth round's mullion), and a kit snaps one neighbour to the doorway."""
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(1.2, 1.2 + 3 * gap + 2 * column, 2.4)]})
    angles = np.radians(np.arange(sides) * 360.0 / sides + 180.0 / sides)
    for centre in (1.2 + gap + column / 2, 1.2 + 2 * gap + 1.5 * column):
        ring = [(8.15 + column / 2 * math.cos(a), centre + column / 2 * math.sin(a)) for a in angles]
        parts.append(prism(ring, -SLAB, 2.4))
    return _level("column_screen_three_gaps", parts,
                  [ROOM_OPENINGS[0], _opening((8.3, 0.0, 1.2 + 1.5 * gap + column), _E, 3 * gap + 2 * column)])


def loose_tile_floor(tile: float = 0.6, joint: float = 0.005) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, 1.6 m doorways west and east (z 2.2-3.8,
    lintels 2.2 m); its floor, under the walls and through the doorways too, no slab but loose tiles ``tile`` m (0.6)
    square and 0.2 m thick laid from the walls' outer south-west corner (-0.3, -0.3), the last row and column cut
    short at the outer faces, with ``joint`` m (5 mm) open joints between them through to nothing below. Known: two,
    at the floor (y 0): the west doorway, 1.6 m at (-0.3, 3.0); the east one, 1.6 m at (8.3, 3.0) (the joints are
    seams, no way down: 5 mm is a thirtieth of the agent's radius)."""
    parts = room(8.0, 6.0, ROOM_DOORS)[1:]  # the walls, without the slab
    for x0 in np.arange(-0.3, 8.3 - 1e-9, tile):
        for z0 in np.arange(-0.3, 6.3 - 1e-9, tile):
            x1, z1 = min(x0 + tile - joint, 8.3), min(z0 + tile - joint, 6.3)
            parts.append(box(x0, x1, -SLAB, 0.0, z0, z1))
    return _level("loose_tile_floor", parts, ROOM_OPENINGS)


def arcade_onto_street(span: float = 1.8, pier: float = 0.9, arches: int = 5, spring: float = 2.2,
                       strips: int = 12) -> SampleLevel:
    """A loggia 14.4 m long and 3 m deep (clear x 0-14.4, z 0-3.0) behind an arcade on its south side, and the
    street in front of it, one piece. The loggia's floor at y 0; its west, north and east walls 0.3 m thick and 3.6 m
    high, a 1.6 m doorway (x 6.4-8.0, lintel 2.2 m) in the north one; its south side an arcade 0.5 m deep (z -0.5-0):
    ``arches`` (5) round arches ``span`` m (1.8) across springing at ``spring`` m (2.2; crown 3.1 m), between piers
    ``pier`` m (0.9, wider than the agent) wide, the arches from x 0.9 every 2.7 m, the wall 3.6 m high, each arch's
    head in ``strips`` strips. In front, the street: 4 m wide (z -4.5 to -0.5) and 0.15 m down (a kerb at the
    arcade's face), its floor the piece's full length (x -0.3 to 14.7), open at both ends, the far side a facade 0.3 m
    thick and 4 m high (z -4.8 to -4.5). Known: three: the loggia's north doorway, 1.6 m at (7.2, 3.3) at y 0, facing
    north, 2.2 m high; the street's ends, 4.0 m each at (-0.3, -2.5) facing west and (14.7, -2.5) facing east, 0.15 m
    down, open above. Not the arches: they join the piece's own loggia and street (a way inside the piece)."""
    length, street = 14.4, -0.15
    parts = [box(-0.3, length + 0.3, -SLAB, 0.0, -0.5, 3.3), box(-0.3, length + 0.3, street - SLAB, street, -4.5, -0.5),
             box(-0.3, length + 0.3, street - SLAB, 4.0, -4.8, -4.5),  # the street's floor and far facade
             box(-0.3, 0.0, -SLAB, 3.6, 0.0, 3.3), box(length, length + 0.3, -SLAB, 3.6, 0.0, 3.3),
             box(-0.3, 6.4, -SLAB, 3.6, 3.0, 3.3), box(8.0, length + 0.3, -SLAB, 3.6, 3.0, 3.3),
             box(6.4, 8.0, 2.2, 3.6, 3.0, 3.3), box(-0.3, 0.0, -SLAB, 3.6, -0.5, 0.0),
             box(length, length + 0.3, -SLAB, 3.6, -0.5, 0.0)]  # the walls' ends at the arcade's line
    radius = span / 2
    for k in range(arches):
        a0 = pier + k * (span + pier)
        parts.append(box(a0 + span, a0 + span + pier, -SLAB, 3.6, -0.5, 0.0))  # the pier east of the arch
        edges = np.linspace(a0, a0 + span, strips + 1)
        for x0, x1 in zip(edges[:-1], edges[1:]):
            y0, y1 = (spring + math.sqrt(max(radius ** 2 - (x - a0 - radius) ** 2, 0.0)) for x in (x0, x1))
            parts.append(hull([[x, y, z] for z in (-0.5, 0.0) for x, y in ((x0, y0), (x1, y1), (x0, 3.6),
                                                                          (x1, 3.6))]))
    parts.append(box(0.0, pier, -SLAB, 3.6, -0.5, 0.0))  # the west end pier
    return _level("arcade_onto_street", parts,
                  [_opening((7.2, 0.0, 3.3), _N, 1.6), _opening((-0.3, street, -2.5), _W, 4.0),
                   _opening((length + 0.3, street, -2.5), _E, 4.0)])


KINDS = kinds_by_name(spiked_portcullis_end, raised_threshold_step, trapdoor_over_nothing, l_corner_ramp_up,
                      knocked_through_hole, column_screen_three_gaps, loose_tile_floor, arcade_onto_street)
"""Kind name -> factory of the twenty-ninth round."""


if __name__ == "__main__":
    sys.exit(run_kinds(sys.argv[1:], kinds=KINDS, description=__doc__.splitlines()[0]))
