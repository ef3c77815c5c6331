"""A twentieth round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds20.py [--kinds a b] [--configs map_piece map_piece_sampling]
[--yaws 0 22 45] [--detail]``

Twelve kinds of docs/entry_exit.md, "A twentieth round of piece kinds", each with its known openings written in
its docstring before the detector first ran on it. Five hold a gap in their walls a designer would not use as an
opening beside their doorways: a corner window at waist height, a hole the agent must stoop through, a five-bar
gate across a doorway, a bricked-up doorway (a blind recess in the outer face) and a niche reaching out to the
piece's face. Seven hold openings as a kit's pieces come: a double door split by a thin mullion, a doorway under a
semi-elliptic arch, an open switchback stair leaving at two heights on opposite sides, a doorway half filled by
rubble, a doorway near the acute corner of a wall at 30 degrees, a roofed ramp of 10 degrees with a landing, and a
ledge whose unrailed end stops over a drop. Built with :mod:`piece_parts`, in the earlier rounds' conventions.
"""

from __future__ import annotations

import math
import sys

import numpy as np
from piece_parts import (ROOM_DOORS, ROOM_OPENINGS, SLAB, box, hull, kinds_by_name, polygon_room, room, round_level,
                         run_kinds)

from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _N, _S, _W

_level = round_level(20)


def corner_window_room(sill: float = 1.0) -> SampleLevel:
    """Room 8 x 6 m, 1.6 m doorways W and E; at its south-east corner a corner window with no post: 2 m along each
    wall (x 6.3-8.3 in the south wall, z -0.3-1.7 in the east one), from a sill ``sill`` m up to 2.2 m. Known: both
    doorways; not the window (its sill is over the climb: a designer's window, no way out)."""
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(-0.3, 1.7, 2.2), (2.2, 3.8, 2.2)], "S": [(6.3, 8.3, 2.2)]})
    parts += [box(8.0, 8.3, -SLAB, sill, -0.3, 1.7), box(6.3, 8.3, -SLAB, sill, -0.3, 0.0)]
    return _level("corner_window_room", parts, ROOM_OPENINGS)


def stooping_hole_wall(height: float = 1.5) -> SampleLevel:
    """Room 8 x 6 m, 1.6 m doorways W and E; in the south wall a hole 1.6 m wide (x 3.2-4.8) from the floor to
    ``height`` m, under the agent's 2 m. Known: both doorways; not the hole (the agent does not fit under it)."""
    parts = room(8.0, 6.0, {**ROOM_DOORS, "S": [(3.2, 4.8, height)]})
    return _level("stooping_hole_wall", parts, ROOM_OPENINGS)


def five_bar_gate_door(rails: int = 5) -> SampleLevel:
    """Room 8 x 6 m, 1.6 m doorways W and E (lintels 2.2 m); the east one closed by a gate in the wall's middle: ``rails``
    horizontal rails 0.1 m high and 0.05 m thick across it, the lowest 0.15 m up, 0.25 m apart (the top one's top at
    1.25 m), the doorway open above them up to the lintel. Known: the west doorway only (the gate closes the east
    one: the agent does not pass 0.95 m under a lintel)."""
    parts = room(8.0, 6.0, ROOM_DOORS)
    parts += [box(8.125, 8.175, y, y + 0.1, 2.2, 3.8) for y in 0.15 + 0.25 * np.arange(rails)]
    return _level("five_bar_gate_door", parts, ROOM_OPENINGS[:1])


def bricked_up_door(depth: float = 0.15) -> SampleLevel:
    """Room 8 x 6 m, a 1.6 m doorway W; in the east wall a bricked-up doorway: the 1.6 m gap (z 2.2-3.8, lintel 2.2 m)
    filled from the inner face, leaving a blind recess ``depth`` m deep in the outer face over the slab. Known: the
    west doorway only (no way through)."""
    parts = room(8.0, 6.0, ROOM_DOORS) + [box(8.0, 8.3 - depth, -SLAB, 2.2, 2.2, 3.8)]
    return _level("bricked_up_door", parts, ROOM_OPENINGS[:1])


def wall_niche_room(depth: float = 1.0) -> SampleLevel:
    """Room 8 x 6 m, 1.6 m doorways W and E; in the north wall a niche 1.6 m wide (x 3.2-4.8) and ``depth`` m deep
    beyond the wall's inner face, floored level with the room, 2.2 m high, closed at its back by a wall 0.3 m thick
    that is the piece's north face. Known: both doorways; not the niche (closed behind)."""
    back = 6.0 + depth
    parts = room(8.0, 6.0, {**ROOM_DOORS, "N": [(3.2, 4.8, 2.2)]})
    parts += [box(3.2, 4.8, -SLAB, 0.0, 6.3, back), box(2.9, 5.1, -SLAB, 3.0, back, back + 0.3),
              box(2.9, 3.2, -SLAB, 3.0, 6.3, back), box(4.8, 5.1, -SLAB, 3.0, 6.3, back),
              box(3.2, 4.8, 2.2, 3.0, 6.3, back)]
    return _level("wall_niche_room", parts, ROOM_OPENINGS)


def mullion_double_door(leaf: float = 0.9, mullion: float = 0.1) -> SampleLevel:
    """Room 8 x 6 m, a 1.6 m doorway W; east a double doorway (lintel 2.2 m) of two ``leaf`` m gaps either side of a
    central mullion ``mullion`` m wide through the wall's thickness, centred on z 3. Known: the west doorway and the
    double door as ONE opening, 2 * ``leaf`` + ``mullion`` m (1.9 m), at the mullion, as the third round's
    ``double_door``: a kit snaps one neighbour to a double door; a mullion narrower than the agent is part of the
    door's frame, not a wall between two doors (each 0.9 m leaf alone is barely wider than the agent's 0.8 m)."""
    half = mullion / 2
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(3.0 - half - leaf, 3.0 + half + leaf, 2.2)]})
    parts.append(box(8.0, 8.3, -SLAB, 2.2, 3.0 - half, 3.0 + half))
    return _level("mullion_double_door", parts,
                  [ROOM_OPENINGS[0], _opening((8.3, 0.0, 3.0), _E, 2 * leaf + mullion)])


def elliptic_arch_door(span: float = 2.4, spring: float = 0.8, crown: float = 2.6, strips: int = 24) -> SampleLevel:
    """Room 8 x 6 m, a 1.6 m doorway W; east a doorway ``span`` m wide (z 1.8-4.2) under a semi-elliptic arch: jambs
    ``spring`` m high, crown ``crown`` m, the wall over it in ``strips`` strips; clear 1.79 m at the agent's 2 m.
    Known: both doorways, the east one ``span`` m (its width at the floor, as the gothic arch's 1.6 m)."""
    half, rise = span / 2, crown - spring
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(3.0 - half, 3.0 + half, 3.0)]})

    def soffit(z: float) -> float:  # the arch's underside at z, metres up
        return spring + rise * math.sqrt(max(1.0 - ((z - 3.0) / half) ** 2, 0.0))

    edges = np.linspace(3.0 - half, 3.0 + half, strips + 1)
    for z0, z1 in zip(edges[:-1], edges[1:]):
        parts.append(hull([[x, y, z] for x in (8.0, 8.3) for z, y in ((z0, soffit(z0)), (z1, soffit(z1)),
                                                                      (z0, 3.0), (z1, 3.0))]))
    return _level("elliptic_arch_door", parts, [ROOM_OPENINGS[0], _opening((8.3, 0.0, 3.0), _E, span)])


def open_switchback_stair(riser: float = 0.2, tread: float = 0.3) -> SampleLevel:
    """An open switchback stair without walls or roof, 1.2 m lanes each side of a central wall (z 1.2-1.4, 4.4 m up):
    a bottom pad 1.5 x 1.2 m at the ground (x 0-1.5, z 0-1.2), seven ``riser`` m steps east (``tread`` m treads), a
    landing 1.6 m up across both lanes (x 3.6-5.1), seven steps west to a top pad 3.2 m up (x 0-1.5, z 1.4-2.6);
    every block solid to the ground; railings 1 m high and 0.1 m thick along the outer sides, the landing's east
    end and both pads' west ends. Known: the bottom pad's south edge (1.5 m, facing -z, at the ground) and the top
    pad's north edge (1.5 m, facing +z, 3.2 m up): the two ways out at two heights on opposite sides."""
    top = 8 * riser
    parts = [box(0.0, 1.5, -SLAB, 0.0, 0.0, 1.2), box(0.0, 1.5, -SLAB, 2 * top, 1.4, 2.6),
             box(3.6, 5.1, -SLAB, top, 0.0, 2.6), box(0.0, 3.6, -SLAB, 2 * top + 1.2, 1.2, 1.4)]
    for i in range(1, 8):
        up, x0 = i * riser, 1.5 + (i - 1) * tread  # flight 1, east along z 0-1.2
        parts += [box(x0, x0 + tread, -SLAB, up, 0.0, 1.2), box(x0, x0 + tread, -SLAB, up + 1.0, -0.1, 0.0)]
        x1 = 3.6 - (i - 1) * tread  # flight 2, west along z 1.4-2.6
        parts += [box(x1 - tread, x1, -SLAB, top + up, 1.4, 2.6), box(x1 - tread, x1, -SLAB, top + up + 1.0, 2.6, 2.7)]
    parts += [box(3.6, 5.2, -SLAB, top + 1.0, -0.1, 0.0), box(3.6, 5.2, -SLAB, top + 1.0, 2.6, 2.7),
              box(5.1, 5.2, -SLAB, top + 1.0, 0.0, 2.6), box(-0.1, 0.0, -SLAB, 1.0, 0.0, 1.2),
              box(-0.1, 0.0, -SLAB, 2 * top + 1.0, 1.4, 2.6)]
    return _level("open_switchback_stair", parts,
                  [_opening((0.75, 0.0, 0.0), _S, 1.5), _opening((0.75, 2 * top, 2.6), _N, 1.5)])


def rubble_half_door() -> SampleLevel:
    """Room 8 x 6 m, a 1.6 m doorway W; east a 2.0 m doorway (z 2.0-4.0, lintel 2.2 m) whose south part is filled by a
    rubble heap through the wall: an irregular hull 1.1-1.3 m high, spilling 0.5 m out of both wall faces, its foot
    reaching z 2.9 at the floor, its flank steeper than the agent's slope. Known: the west doorway and the clear part
    of the east one, 1.1 m (z 2.9-4.0), at the wall's outer face."""
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(2.0, 4.0, 2.2)]})
    parts.append(hull([[7.5, 0.0, 2.0], [8.8, 0.0, 2.0], [7.5, 0.0, 2.75], [8.8, 0.0, 2.8], [8.15, 0.0, 2.9],
                       [7.9, 1.3, 2.0], [8.45, 1.1, 2.0], [8.0, 1.2, 2.55], [8.35, 1.15, 2.6]]))
    return _level("rubble_half_door", parts, [ROOM_OPENINGS[0], _opening((8.3, 0.0, 3.45), _E, 1.1)])


def acute_wall_door(lean_deg: float = 30.0) -> SampleLevel:
    """Room whose plan is a trapezium: south wall 8 m (z 0), west wall 6 m, north wall from x 0 to 8 + 6 tan
    ``lean_deg`` (11.46 m), the east wall diagonal, ``lean_deg`` off north, meeting the north one at 60 degrees;
    walls 0.3 m, mitred, 3 m high. A 1.6 m doorway (lintel 2.2 m) in the west wall's middle, and one in the diagonal
    wall whose north jamb stands 1.0 m from the acute corner (along the inner face). Known: both doorways, the
    diagonal one at the wall's outer face facing its normal (30 degrees south of east)."""
    far = 8.0 + 6.0 * math.tan(math.radians(lean_deg))
    side = 6.0 / math.cos(math.radians(lean_deg))
    parts, frames = polygon_room([(0.0, 0.0), (8.0, 0.0), (far, 6.0), (0.0, 6.0)],
                                 {1: [(side - 2.6, side - 1.0, 2.2)], 3: [(2.2, 3.8, 2.2)]})
    openings = []
    for i, s in ((3, 3.0), (1, side - 1.8)):
        p, d, n = frames[i]
        mid = p + d * s + n * 0.3
        openings.append(_opening((mid[0], 0.0, mid[1]), (n[0], 0.0, n[1]), 1.6))
    return _level("acute_wall_door", parts, openings)


def landing_ramp_tunnel(slope_deg: float = 10.0) -> SampleLevel:
    """A roofed tunnel 12 m long, 2.4 m wide and 2.6 m high inside, walls 0.3 m, roof 0.2 m, both ends open: a ramp
    rising ``slope_deg`` over x 0-5, a level landing over x 5-7, a second ramp over x 7-12 (1.76 m up at its top at
    10 degrees). Known: both ends, 2.4 m (the east one at the top's height)."""
    g = math.tan(math.radians(slope_deg))
    runs = [(0.0, 5.0, 0.0, 5.0 * g), (5.0, 7.0, 5.0 * g, 5.0 * g), (7.0, 12.0, 5.0 * g, 10.0 * g)]
    parts = []
    for ends in runs:
        for z0, z1, under, over in ((-0.3, 2.7, -SLAB, 0.0), (-0.3, 0.0, -SLAB, 3.0), (2.4, 2.7, -SLAB, 3.0),
                                    (-0.3, 2.7, 2.6, 2.8)):  # floor, walls and roof following the floor's slope
            parts.append(hull([[x, y + dy, z] for x, y in (ends[0::2], ends[1::2]) for dy in (under, over)
                               for z in (z0, z1)]))
    return _level("landing_ramp_tunnel", parts,
                  [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 10.0 * g, 1.2), _E, 2.4)])


def dead_end_ledge(length: float = 8.0) -> SampleLevel:
    """Room 8 x 6 m whose floor lies 3 m up on a solid block, 1.6 m doorways W and E; from the east doorway a ledge
    1.2 m wide runs north along the east wall's outer face (x 8.3-9.5) from z 2.0 to ``length`` m, over nothing,
    railed 1 m high (0.1 m) along its east side and its south end; its north end is unrailed and stops over the drop,
    past the room's north face. Decided before the run, as the fourth round's decision (e): a floor of the piece
    ending over nothing of the piece at its outer extent is where the next piece of a kit joins (a designer who
    meant a drop would rail it, as the ledge's side is); so an opening. Known: the west doorway (3 m up) and the
    ledge's north end (1.2 m, facing +z, 3 m up)."""
    parts = room(8.0, 6.0, ROOM_DOORS, floor=3.0) + [box(-0.3, 8.3, 0.0, 3.0 - SLAB, -0.3, 6.3)]
    parts += [box(8.3, 9.5, 3.0 - SLAB, 3.0, 2.0, length), box(9.5, 9.6, 3.0 - SLAB, 4.0, 1.9, length),
              box(8.3, 9.5, 3.0 - SLAB, 4.0, 1.9, 2.0)]
    return _level("dead_end_ledge", parts, [_opening((-0.3, 3.0, 3.0), _W, 1.6), _opening((8.9, 3.0, length), _N, 1.2)])


KINDS = kinds_by_name(corner_window_room, stooping_hole_wall, five_bar_gate_door, bricked_up_door, wall_niche_room,
                      mullion_double_door, elliptic_arch_door, open_switchback_stair, rubble_half_door,
                      acute_wall_door, landing_ramp_tunnel, dead_end_ledge)
"""Kind name -> factory of the twentieth round."""


if __name__ == "__main__":
    sys.exit(run_kinds(kinds=KINDS, description=__doc__.splitlines()[0]))
