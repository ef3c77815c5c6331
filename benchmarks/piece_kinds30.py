"""A thirtieth round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds30.py [--kinds a b] [--configs map_piece map_piece_sampling] [--yaws 0
22 45] [--detail] [--one-to-one]``

Eight kinds of docs/entry_exit.md, "A thirtieth round of piece kinds", each with its known openings (count, place,
width, height) written in its docstring before the detector first ran on them: the pieces of a level designer's
modular kit none of the earlier rounds built. A corridor ending in a hexagonal (iris) frame, narrower at its foot and
head than at its middle; a railed bridge whose deck runs on outside its railings as ledges narrower than the agent; a
roofed T whose stem ramps 1 m down; a spiral stair round a newel inside a tower, its two doorways stacked one over the
other; a room with a floored pit in its middle, a kerb round its rim and steps down into it; a doorway with a fallen
beam leaning across it, 0.9 m left to pass; a doorway beside a window at the floor 0.5 m high; a square room with a
doorway in each wall, each off the wall's middle. Built with :mod:`piece_parts`, in the earlier rounds' conventions.
"""

from __future__ import annotations

import math
import sys

import numpy as np
from piece_parts import ROOM_OPENINGS, SLAB, box, hull, kinds_by_name, prism, room, round_level, run_kinds

from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _N, _S, _W

_level = round_level(30)


def hex_iris_corridor_end(half_foot: float = 0.8, half_middle: float = 1.2, top: float = 2.4) -> SampleLevel:
    """Corridor 12 x 2.8 m (clear x 0-12, z 0-2.8), walls 0.3 m thick and 3 m high, open west; across its east end a
    bulkhead 0.3 m thick (x 11.7-12.0) from the floor to 3 m, a hexagonal (iris) hole through it centred on the axis
    (z 1.4): its corners (across, up) at (+-``half_foot``, 0) (1.6 m wide at the floor), (+-``half_middle``, 1.2)
    (2.4 m at 1.2 m up) and (+-``half_foot``, ``top``) (1.6 m at 2.4 m up), so 1.87 m wide at the agent's 2 m head:
    narrower at its foot and head than at its middle. Known: two, at the floor (y 0): the west end, 2.8 m at (0, 1.4),
    3 m high, facing west; the iris, 1.6 m at the bulkhead's outer face (12.0, 1.4) (its width at the floor, the
    narrowest under the agent's height), 2.4 m high at its middle, facing east."""
    parts = [box(0.0, 12.0, -SLAB, 0.0, 0.0, 2.8), box(0.0, 12.0, -SLAB, 3.0, -0.3, 0.0),
             box(0.0, 12.0, -SLAB, 3.0, 2.8, 3.1), box(11.7, 12.0, top, 3.0, 0.0, 2.8)]
    middle = 1.2
    for side in (-1.0, 1.0):  # the bulkhead beside the hole, below and above its widest line
        wall, foot, mid = 1.4 + side * 1.4, 1.4 + side * half_foot, 1.4 + side * half_middle
        for plan in ([(wall, 0.0), (foot, 0.0), (mid, middle), (wall, middle)],
                     [(wall, middle), (mid, middle), (foot, top), (wall, top)]):
            parts.append(hull([[x, y, z] for z, y in plan for x in (11.7, 12.0)]))
    return _level("hex_iris_corridor_end", parts,
                  [_opening((0.0, 0.0, 1.4), _W, 2.8), _opening((12.0, 0.0, 1.4), _E, 2 * half_foot)])


def railed_bridge_outer_ledges(ledge: float = 0.4, post_every: float = 1.5) -> SampleLevel:
    """A footbridge 12 m long (x 0-12) over nothing: a deck 0.3 m thick (y -0.3-0), 2.4 m clear between its railings
    (z 0-2.4), each railing 0.1 m thick (z -0.1-0 and 2.4-2.5): posts 0.1 m square every ``post_every`` m (1.5) from
    the deck to 1.1 m, a handrail 1.0-1.1 m and a mid rail 0.45-0.55 m up, open under the mid rail; the deck runs on
    ``ledge`` m (0.4, half the agent's 0.8 m) outside each railing (z -0.5 and 2.9), a cornice ledge with nothing
    beyond it. Known: two, at the deck (y 0): the ends between the railings, 2.4 m at (0, 1.2) facing west and (12,
    1.2) facing east, open above. Not the sides: behind a railing, a ledge narrower than the agent over nothing."""
    parts = [box(0.0, 12.0, -0.3, 0.0, -0.1 - ledge, 2.5 + ledge)]
    for z0, z1 in ((-0.1, 0.0), (2.4, 2.5)):
        parts += [box(x, x + 0.1, 0.0, 1.1, z0, z1) for x in np.arange(0.0, 12.0 - 0.1 + 1e-9, post_every)]
        parts += [box(11.9, 12.0, 0.0, 1.1, z0, z1), box(0.0, 12.0, 1.0, 1.1, z0, z1),
                  box(0.0, 12.0, 0.45, 0.55, z0, z1)]
    return _level("railed_bridge_outer_ledges", parts,
                  [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, 1.2), _E, 2.4)])


def roofed_t_ramp_down_stem(drop: float = 1.0, run: float = 5.0, level: float = 1.5) -> SampleLevel:
    """A roofed T of corridors 2.4 m wide (clear), walls 0.3 m thick, head room 3 m everywhere: the bar along x (clear
    x 0-12, z 0-2.4) at y 0, open at both ends, under a roof slab 0.2 m thick at 3 m; from its middle the stem (clear
    x 4.8-7.2) leaves south, its floor a ramp falling ``drop`` m (1.0) over ``run`` m (5.0: 11.3 degrees) from the
    bar's wall line (z 0), then ``level`` m (1.5) level to its open end at z -6.5, its roof following the floor 3 m
    over it. Known: three, 2.4 m each, 3 m high: the bar's ends at (0, 1.2) facing west and (12, 1.2) facing east at
    y 0; the stem's end at (6.0, -6.5) facing south, ``drop`` m down."""
    end = -run - level
    parts = [box(0.0, 12.0, -SLAB, 0.0, 0.0, 2.4), box(0.0, 12.0, -SLAB, 3.2, 2.4, 2.7),
             box(0.0, 4.8, -SLAB, 3.2, -0.3, 0.0), box(7.2, 12.0, -SLAB, 3.2, -0.3, 0.0),
             box(0.0, 12.0, 3.0, 3.2, -0.3, 2.7)]  # the bar's floor, walls and roof
    slope = ((0.0, 0.0), (-run, -drop))  # (z, rise) along the ramp's top
    parts.append(hull([[x, y + dy, z] for x in (4.8, 7.2) for z, y in slope for dy in (-SLAB, 0.0)]))  # the ramp
    parts.append(hull([[x, 3.0 + y + dy, z] for x in (4.5, 7.5) for z, y in slope for dy in (0.0, 0.2)]))  # its roof
    parts += [box(4.8, 7.2, -drop - SLAB, -drop, end, -run), box(4.5, 7.5, 3.0 - drop, 3.2 - drop, end, -run)]
    parts += [box(x0, x1, -drop - SLAB, 3.2, end, 0.0) for x0, x1 in ((4.5, 4.8), (7.2, 7.5))]  # the stem's walls
    return _level("roofed_t_ramp_down_stem", parts,
                  [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, 1.2), _E, 2.4),
                   _opening((6.0, -drop, end), _S, 2.4)])


def _sector(centre: tuple[float, float], side: float, a0: float, a1: float) -> list[tuple[float, float]]:
    """The plan polygon ((x, z) corners) of the cone from ``centre`` between the angles ``a0`` and ``a1`` (degrees from
    +x towards +z, less than 180 apart) clipped to the square [0, ``side``]^2: convex, as both are."""
    cx, cz = centre

    def hit(a: float) -> tuple[float, float]:
        dx, dz = math.cos(math.radians(a)), math.sin(math.radians(a))
        t = min((bound - c) / d for c, d in ((cx, dx), (cz, dz)) if abs(d) > 1e-12
                for bound in (0.0, side) if (bound - c) / d > 0)
        return cx + t * dx, cz + t * dz

    corners = [(x, z) for x in (0.0, side) for z in (0.0, side)]
    inside = sorted(((math.degrees(math.atan2(z - cz, x - cx)) - a0) % 360.0, (x, z)) for x, z in corners)
    return [centre, hit(a0)] + [c for d, c in inside if 0.0 < d < a1 - a0] + [hit(a1)]


def spiral_stair_stacked_doors(treads: int = 15, turn: float = 17.0, riser: float = 0.225) -> SampleLevel:
    """A stair tower 4.4 x 4.4 m inside (clear x 0-4.4, z 0-4.4), walls 0.3 m thick and 6.6 m high, no roof; round a
    newel 0.6 m across (8 facets, centred at (2.2, 2.2)) a spiral stair of ``treads`` (15) solid treads, each
    ``turn`` degrees (17) of the plan (wedges from the newel out to the walls) and ``riser`` m (0.225) over the last,
    turning from 250 degrees (from +x towards +z) on round through south, east and north, then a landing 0.25 m thick
    over the ground floor's remaining wedge (145-250 degrees) at 16 risers up (3.6 m), a parapet 1 m high on its edge
    at 250 degrees. Two doorways 1.2 m wide in the west wall (z 1.6-2.8), one over the other: at the ground under a
    lintel 2.2 m up, and from the landing 3.6 m up under one 2.2 m over it. Known: two, 1.2 m, facing west at the
    wall's outer face (-0.3, 2.2), 2.2 m high: the ground one at y 0 and the landing's at y 3.6, stacked."""
    side, centre, wall, top = 4.4, (2.2, 2.2), 0.3, 6.6
    landing = (treads + 1) * riser
    parts = [box(-wall, side + wall, -SLAB, 0.0, -wall, side + wall),
             box(-wall, 0.0, -SLAB, top, -wall, 1.6), box(-wall, 0.0, -SLAB, top, 2.8, side + wall),
             box(-wall, 0.0, 2.2, landing, 1.6, 2.8), box(-wall, 0.0, landing + 2.2, top, 1.6, 2.8),
             box(side, side + wall, -SLAB, top, -wall, side + wall),
             box(0.0, side, -SLAB, top, -wall, 0.0), box(0.0, side, -SLAB, top, side, side + wall)]
    ring = np.radians(np.arange(8) * 45.0 + 22.5)
    parts.append(prism([(centre[0] + 0.3 * math.cos(a), centre[1] + 0.3 * math.sin(a)) for a in ring], -SLAB, top))
    start = 250.0
    for k in range(treads):
        a0 = start + k * turn
        parts.append(prism(_sector(centre, side, a0 % 360.0, a0 % 360.0 + turn), -SLAB, (k + 1) * riser))
    parts.append(prism(_sector(centre, side, (start + treads * turn) % 360.0, start), landing - 0.25, landing))
    edge = np.array([math.cos(math.radians(start)), math.sin(math.radians(start))])
    across = np.array([-edge[1], edge[0]]) * 0.05
    far = np.array(_sector(centre, side, start - 1.0, start)[-1])
    near = np.array(centre)
    parts.append(prism([near - across, far - across, far + across, near + across], landing, landing + 1.0))
    return _level("spiral_stair_stacked_doors", parts,
                  [_opening((-wall, 0.0, 2.2), _W, 1.2), _opening((-wall, landing, 2.2), _W, 1.2)])


def kerbed_pit_room(depth: float = 1.5, kerb: float = 0.3, steps: int = 5) -> SampleLevel:
    """Room 10 x 8 m (clear x 0-10, z 0-8), walls 0.3 m thick and 3 m high, 1.6 m doorways west and east (z 3.2-4.8,
    lintels 2.2 m); in its middle a pit 4 x 4 m (x 3-7, z 2-6) ``depth`` m (1.5) deep with a floor of its own (part of
    the piece), a kerb ``kerb`` m (0.3, under the 0.4 m climb) high and 0.2 m thick round its rim, broken on the south
    side (x 4.4-5.6) where ``steps`` (5) steps 1.2 m wide, 0.3 m deep and 0.25 m high each go down north into it along
    its south side (z 2.0-3.5). Known: two, at the floor (y 0): the west doorway, 1.6 m at (-0.3, 4.0); the east one,
    1.6 m at (10.3, 4.0), 2.2 m high. Not the pit's rim nor its steps (inside the piece)."""
    doors = {"W": [(3.2, 4.8, 2.2)], "E": [(3.2, 4.8, 2.2)]}
    parts = room(10.0, 8.0, doors)[1:]  # the walls, without the slab
    bottom = -depth - SLAB
    parts += [box(-0.3, 10.3, bottom, 0.0, -0.3, 2.0), box(-0.3, 10.3, bottom, 0.0, 6.0, 8.3),
              box(-0.3, 3.0, bottom, 0.0, 2.0, 6.0), box(7.0, 10.3, bottom, 0.0, 2.0, 6.0),
              box(3.0, 7.0, bottom, -depth, 2.0, 6.0)]  # the floor round the pit, and the pit's floor
    parts += [box(2.8, 4.4, 0.0, kerb, 1.8, 2.0), box(5.6, 7.2, 0.0, kerb, 1.8, 2.0),
              box(2.8, 7.2, 0.0, kerb, 6.0, 6.2),
              box(2.8, 3.0, 0.0, kerb, 2.0, 6.0), box(7.0, 7.2, 0.0, kerb, 2.0, 6.0)]
    riser = depth / (steps + 1)
    parts += [box(4.4, 5.6, bottom, -(i + 1) * riser, 2.0 + 0.3 * i, 2.3 + 0.3 * i) for i in range(steps)]
    return _level("kerbed_pit_room", parts,
                  [_opening((-0.3, 0.0, 4.0), _W, 1.6), _opening((10.3, 0.0, 4.0), _E, 1.6)])


def fallen_beam_doorway(foot: float = 3.1) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, a 1.6 m west doorway (z 2.2-3.8, lintel
    2.2 m); in the east wall a doorway 2.0 m wide (z 2.0-4.0) under a lintel 2.4 m up, a fallen beam leaning across
    it in the wall's thickness (x 8.02-8.28): its head wedged in the doorway's south top corner (its plan-side corners
    (z, y) (2.0, 2.1) and (2.2, 2.4)), its foot on the floor (z 2.8 to ``foot``, 3.1), about 0.28 m thick; its north
    face runs from (``foot``, 0) to (2.2, 2.4), 2.35 m across at the agent's 2 m head. The way past it north of the
    beam is 0.9 m at the floor (z 3.1-4.0), wider above. Known: two, at the floor (y 0): the west doorway, 1.6 m at
    (-0.3, 3.0); the east one, 0.9 m (the usable width, its narrowest under the agent's height) at the wall's outer
    face (8.3, 3.55), 2.4 m high."""
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(2.0, 4.0, 2.4)]})
    parts.append(hull([[x, y, z] for z, y in ((foot - 0.3, 0.0), (foot, 0.0), (2.2, 2.4), (2.0, 2.1))
                       for x in (8.02, 8.28)]))
    return _level("fallen_beam_doorway", parts,
                  [ROOM_OPENINGS[0], _opening((8.3, 0.0, (foot + 4.0) / 2), _E, 4.0 - foot)])


def door_beside_floor_window(sill_high: float = 0.5) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, a 1.6 m west doorway (z 2.2-3.8, lintel
    2.2 m); in the east wall a 1.2 m doorway (z 1.0-2.2, lintel 2.2 m), a pier 0.2 m wide (z 2.2-2.4), then a window
    at the floor 2.4 m wide (z 2.4-4.8) and ``sill_high`` m (0.5) high (a basement light: the wall over it from 0.5
    m up), the slab ending at the wall's outer face. Known: two, at the floor (y 0): the west doorway, 1.6 m at
    (-0.3, 3.0); the east door, 1.2 m at (8.3, 1.6), 2.2 m high. Not the window: 0.5 m is no way for the 2 m agent,
    and it does not widen the door beside it."""
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(1.0, 2.2, 2.2), (2.4, 4.8, sill_high)]})
    return _level("door_beside_floor_window", parts, [ROOM_OPENINGS[0], _opening((8.3, 0.0, 1.6), _E, 1.2)])


def four_wall_offset_doors() -> SampleLevel:
    """Square room 8 x 8 m (clear x 0-8, z 0-8), walls 0.3 m thick and 3 m high, a doorway in each wall, none at its
    wall's middle, lintels 2.2 m: west 1.2 m at the south corner (z 0-1.2, its jamb the south wall's inner face);
    north 2.0 m (x 5.0-7.0); east 1.0 m (z 6.0-7.0); south 1.6 m (x 1.0-2.6). Known: four, at the floor (y 0), at the
    walls' outer faces, 2.2 m high: west 1.2 m at (-0.3, 0.6); north 2.0 m at (6.0, 8.3); east 1.0 m at (8.3, 6.5);
    south 1.6 m at (1.8, -0.3)."""
    parts = room(8.0, 8.0, {"W": [(0.0, 1.2, 2.2)], "N": [(5.0, 7.0, 2.2)], "E": [(6.0, 7.0, 2.2)],
                            "S": [(1.0, 2.6, 2.2)]})
    return _level("four_wall_offset_doors", parts,
                  [_opening((-0.3, 0.0, 0.6), _W, 1.2), _opening((6.0, 0.0, 8.3), _N, 2.0),
                   _opening((8.3, 0.0, 6.5), _E, 1.0), _opening((1.8, 0.0, -0.3), _S, 1.6)])


KINDS = kinds_by_name(hex_iris_corridor_end, railed_bridge_outer_ledges, roofed_t_ramp_down_stem,
                      spiral_stair_stacked_doors, kerbed_pit_room, fallen_beam_doorway, door_beside_floor_window,
                      four_wall_offset_doors)
"""Kind name -> factory of the thirtieth round."""


if __name__ == "__main__":
    sys.exit(run_kinds(sys.argv[1:], kinds=KINDS, description=__doc__.splitlines()[0]))
