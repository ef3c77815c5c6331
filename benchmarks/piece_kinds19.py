"""A nineteenth round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds19.py [--kinds a b] [--configs map_piece map_piece_sampling]
[--yaws 0 22 45] [--detail]``

Twelve kinds of docs/entry_exit.md, "A nineteenth round of piece kinds", each with its known openings written in
its docstring before the detector first ran on it, as a modular kit's pieces come: a sill plate standing proud of a
doorway, a floor of skirting and of bevelled tiles, two modules laid a seam apart, a grate of square holes, a
covered drain across a door; a T-junction whose arm is a ramp, a curved corridor whose ends face off the grid, a
corridor flaring at its mouths; a pivot door standing open in its doorway, a railing gap at a balcony's front, and
a cellar tunnel reached down a ladder shaft. Built with :mod:`piece_parts` (the earlier rounds' helpers and table).
"""

from __future__ import annotations

import math
import sys

import numpy as np
import trimesh
from piece_parts import (ROOM_DOORS, ROOM_OPENINGS, SLAB, arc_band, box, corridor, hull, kinds_by_name, prism, room,
                         round_level, run_kinds)

from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _N, _W

_level = round_level(19)


def sill_plate_door(rise: float = 0.1) -> SampleLevel:
    """Room 8 x 6 m, 1.6 m doorways W and E; across the east one a sill plate ``rise`` m high (a raised threshold
    of 5-15 cm), 0.5 m deep, standing 0.1 m proud of both wall faces and running 0.1 m into both jambs. Known: both
    doorways, 1.6 m (the east one at the plate's outer edge, ``rise`` m up)."""
    parts = room(8.0, 6.0, ROOM_DOORS) + [box(7.9, 8.4, 0.0, rise, 2.1, 3.9)]
    return _level("sill_plate_door", parts, [ROOM_OPENINGS[0], _opening((8.4, rise, 3.0), _E, 1.6)])


def grid_grate_corridor(pitch: float = 0.08, bar: float = 0.03) -> SampleLevel:
    """Corridor 12 x 2.4 m, both ends open; its floor solid over x 0-3 and 9-12, between them a grate over nothing of
    square bars ``bar`` m wide both ways every ``pitch`` m (holes 0.05 m square). Known: both ends, 2.4 m."""
    parts = corridor(12.0, floor=False) + [box(0.0, 3.0, -SLAB, 0.0, 0.0, 2.4), box(9.0, 12.0, -SLAB, 0.0, 0.0, 2.4)]
    parts += [box(3.0, 9.0, -bar, 0.0, z, z + bar) for z in np.arange(0.0, 2.4 - bar + 1e-9, pitch)]
    parts += [box(x, x + bar, -bar, 0.0, 0.0, 2.4) for x in np.arange(3.0, 9.0 - bar + 1e-9, pitch)]
    return _level("grid_grate_corridor", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, 1.2), _E, 2.4)])


def t_ramp_arm(slope_deg: float = 12.0) -> SampleLevel:
    """T-junction: a corridor 12 x 2.4 m open W and E; from its middle an arm 2.4 m wide leaves north, its floor a
    ramp rising ``slope_deg`` over 5 m from the corridor's wall line, then 1 m level, open at its end; walls 3 m over
    the floor. Known: the three ends, 2.4 m (the arm's at the ramp's top, 1.06 m up at 12 degrees)."""
    rise = 5.0 * math.tan(math.radians(slope_deg))
    top = rise + 3.0
    parts = [box(0.0, 12.0, -SLAB, 0.0, 0.0, 2.4), box(0.0, 12.0, -SLAB, 3.0, -0.3, 0.0),
             box(0.0, 4.5, -SLAB, 3.0, 2.4, 2.7), box(7.5, 12.0, -SLAB, 3.0, 2.4, 2.7),
             hull([[x, y, z] for x in (4.8, 7.2) for z, ys in ((2.4, (-SLAB, 0.0)), (7.4, (-SLAB, rise))) for y in ys]),
             box(4.8, 7.2, -SLAB, rise, 7.4, 8.4), box(4.5, 4.8, -SLAB, top, 2.4, 8.4), box(7.2, 7.5, -SLAB, top, 2.4, 8.4)]
    return _level("t_ramp_arm", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, 1.2), _E, 2.4),
                                        _opening((6.0, rise, 8.4), _N, 2.4)])


def skew_arc_corridor(a0: float = 17.0, a1: float = 87.0) -> SampleLevel:
    """A curved corridor off the grid: centre line radius 6 m about the origin, 2.4 m wide, walls 0.3 m and 3 m high,
    from ``a0`` to ``a1`` degrees (from +x towards +z) in facets of 5 degrees, its ends radial, both open. Known: both
    ends, 2.4 m, at the centre line, facing along the arc out of it."""
    parts = (arc_band(0.0, 0.0, 4.8, 7.2, a0, a1, -SLAB, 0.0, step_deg=5.0)
             + arc_band(0.0, 0.0, 4.5, 4.8, a0, a1, -SLAB, 3.0, step_deg=5.0)
             + arc_band(0.0, 0.0, 7.2, 7.5, a0, a1, -SLAB, 3.0, step_deg=5.0))
    b0, b1 = math.radians(a0), math.radians(a1)
    ends = [_opening((6.0 * math.cos(b0), 0.0, 6.0 * math.sin(b0)), (math.sin(b0), 0.0, -math.cos(b0)), 2.4),
            _opening((6.0 * math.cos(b1), 0.0, 6.0 * math.sin(b1)), (-math.sin(b1), 0.0, math.cos(b1)), 2.4)]
    return _level("skew_arc_corridor", parts, ends)


def skirted_room(height: float = 0.12, depth: float = 0.02) -> SampleLevel:
    """Room 8 x 6 m, 1.6 m doorways W and E; skirting boards ``height`` m high standing ``depth`` m proud of every
    inner wall face, returning through both doorways along their jambs' faces to the outer faces. Known: both
    doorways, 1.6 m (the door's width above the skirting)."""
    parts = room(8.0, 6.0, ROOM_DOORS)
    parts += [box(0.0, 8.0, 0.0, height, 0.0, depth), box(0.0, 8.0, 0.0, height, 6.0 - depth, 6.0)]
    for x0, x1 in ((0.0, depth), (8.0 - depth, 8.0)):  # along the west and east walls' inner faces, beside the doors
        parts += [box(x0, x1, 0.0, height, 0.0, 2.2), box(x0, x1, 0.0, height, 3.8, 6.0)]
    for x0, x1 in ((-0.3, 0.0), (8.0, 8.3)):  # along the jambs' faces through the wall
        parts += [box(x0, x1, 0.0, height, 2.2, 2.2 + depth), box(x0, x1, 0.0, height, 3.8 - depth, 3.8)]
    return _level("skirted_room", parts, ROOM_OPENINGS)


def bevelled_tile_floor(tile: float = 2.0, bevel: float = 0.03) -> SampleLevel:
    """Room 8 x 6 m, 1.6 m doorways W and E; its floor tiles ``tile`` m square from the walls' outer south-west corner
    (the last row and column cut short), each with its top edges bevelled ``bevel`` m at 45 degrees: V grooves 0.06 m
    wide and 0.03 m deep between them, one running out through both doorways along z 3.7. Known: both doorways."""
    xs = list(np.arange(-0.3, 8.3, tile)) + [8.3]
    zs = list(np.arange(-0.3, 6.3, tile)) + [6.3]
    parts = room(8.0, 6.0, ROOM_DOORS)[1:]  # the walls, without the flat slab
    for x0, x1 in zip(xs[:-1], xs[1:]):
        for z0, z1 in zip(zs[:-1], zs[1:]):
            parts.append(hull([[x, y, z] for x in (x0, x1) for z in (z0, z1) for y in (-SLAB, -bevel)]
                              + [[x, 0.0, z] for x in (x0 + bevel, x1 - bevel) for z in (z0 + bevel, z1 - bevel)]))
    return _level("bevelled_tile_floor", parts, ROOM_OPENINGS)


def kit_seam_corridor(gap: float = 0.01, offset: float = 0.02) -> SampleLevel:
    """Two corridor modules 6 x 2.4 m (floor and walls), both ends open, laid end to end ``gap`` m apart (a slit
    through floor and walls) and the east one ``offset`` m lower, as a kit's modules snap with a seam. Known: both
    ends, 2.4 m (the east one at x 12 + ``gap``, ``offset`` m down)."""
    west = corridor(6.0)
    east = [part.copy().apply_translation([6.0 + gap, -offset, 0.0]) for part in corridor(6.0)]
    return _level("kit_seam_corridor", west + east,
                  [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0 + gap, -offset, 1.2), _E, 2.4)])


def flared_mouth_corridor(mouth: float = 4.0, flare: float = 1.0) -> SampleLevel:
    """Corridor 2.4 m wide between walls 0.3 m thick and 3 m high, 12 m long; over its last ``flare`` m at each end
    the walls splay out to a mouth ``mouth`` m wide at the piece's face (38.7 degrees at 4.0 m over 1 m). Known: both
    mouths, ``mouth`` m wide, at x 0 and 12."""
    spread = (mouth - 2.4) / 2.0
    parts = [box(flare, 12.0 - flare, -SLAB, 0.0, -0.3, 2.7), box(flare, 12.0 - flare, -SLAB, 3.0, -0.3, 0.0),
             box(flare, 12.0 - flare, -SLAB, 3.0, 2.4, 2.7)]
    for face, inner in ((0.0, flare), (12.0, 12.0 - flare)):
        parts.append(prism([(face, -spread - 0.3), (inner, -0.3), (inner, 2.7), (face, 2.4 + spread + 0.3)], -SLAB, 0.0))
        for z_in, z_out, side in ((0.0, -spread, -1.0), (2.4, 2.4 + spread, 1.0)):  # the splayed walls, 0.3 m thick
            run = np.array([face - inner, z_out - z_in])
            out = np.array([-run[1], run[0]]) / np.linalg.norm(run)  # square to the wall, away from the corridor
            out = out if out[1] * side > 0 else -out
            corners = [(inner, z_in), (face, z_out), (face + 0.3 * out[0], z_out + 0.3 * out[1]),
                       (inner + 0.3 * out[0], z_in + 0.3 * out[1])]
            parts.append(prism(corners, -SLAB, 3.0))
    return _level("flared_mouth_corridor", parts,
                  [_opening((0.0, 0.0, 1.2), _W, mouth), _opening((12.0, 0.0, 1.2), _E, mouth)])


def covered_drain_door(width: float = 0.2, depth: float = 0.1, slot: float = 0.03) -> SampleLevel:
    """Room 8 x 6 m, 1.6 m doorways W and E; across the east doorway, in the wall's thickness (x 8.05-8.25), a drain
    channel ``width`` m wide and ``depth`` m deep, covered flush by a grate of bars 0.02 m wide running out of the
    door (along x), ``slot`` m apart. Known: both doorways."""
    a, b = 8.15 - width / 2, 8.15 + width / 2
    parts = room(8.0, 6.0, ROOM_DOORS)[1:]
    parts += [box(-0.3, a, -SLAB, 0.0, -0.3, 6.3), box(b, 8.3, -SLAB, 0.0, -0.3, 6.3),
              box(a, b, -SLAB, 0.0, -0.3, 2.2), box(a, b, -SLAB, 0.0, 3.8, 6.3), box(a, b, -SLAB, -depth, 2.2, 3.8)]
    parts += [box(a - 0.01, b + 0.01, -0.02, 0.0, z, z + 0.02) for z in np.arange(2.2 + slot, 3.8 - 0.02, 0.02 + slot)]
    return _level("covered_drain_door", parts, ROOM_OPENINGS)


def ladder_shaft_cellar(depth: float = 3.2) -> SampleLevel:
    """Room 8 x 6 m, walls 3 m, a 1.6 m doorway west, the east wall closed; a shaft 1.2 x 2.0 m (x 6.0-7.2, z 2.0-4.0)
    through its floor, unrailed, with a ladder (rungs 0.3 m apart) on its west wall down to a tunnel ``depth`` m below,
    2.0 m wide, that runs east from under the shaft out through the piece's east face (x 8.3). Known: the west
    doorway and the tunnel's east end (2.0 m, ``depth`` m down); not the shaft (a vertical way inside the piece)."""
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)]})[1:]
    parts += [box(-0.3, 6.0, -SLAB, 0.0, -0.3, 6.3), box(7.2, 8.3, -SLAB, 0.0, -0.3, 6.3),
              box(6.0, 7.2, -SLAB, 0.0, -0.3, 2.0), box(6.0, 7.2, -SLAB, 0.0, 4.0, 6.3)]
    low = -depth
    parts += [box(6.0, 8.3, low - SLAB, low, 2.0, 4.0),  # the tunnel's floor, its walls up to the room's slab
              box(5.7, 6.0, low - SLAB, 0.0, 1.7, 4.3), box(5.7, 8.3, low - SLAB, -SLAB, 1.7, 2.0),
              box(5.7, 8.3, low - SLAB, -SLAB, 4.0, 4.3)]
    parts += [box(6.0, 6.1, y, y + 0.03, 2.6, 3.4) for y in np.arange(low + 0.3, 0.95, 0.3)]  # the ladder's rungs
    parts += [box(6.0, 6.1, low, 1.0, z, z + 0.05) for z in (2.55, 3.4)]  # and its stiles
    return _level("ladder_shaft_cellar", parts, [ROOM_OPENINGS[0], _opening((8.3, low, 3.0), _E, 2.0)])


def pivot_door_open(leaf: float = 2.4) -> SampleLevel:
    """Room 8 x 6 m, a 1.6 m doorway west; east a ``leaf`` m wide doorway (z 1.8-4.2) under a 2.2 m lintel holding a
    pivot door: a leaf ``leaf`` x 2.1 m, 0.05 m thick, 0.01 m over the floor, turned 90 degrees about its middle on
    the wall's middle line, so it stands along x across the door's middle, 1.05 m out of both wall faces. Known: the
    west doorway and the two gaps beside the leaf, 1.175 m each, at the wall's outer face."""
    half = leaf / 2
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(3.0 - half, 3.0 + half, 2.2)]})
    parts.append(box(8.15 - half, 8.15 + half, 0.01, 2.11, 2.975, 3.025))
    gap = half - 0.025
    return _level("pivot_door_open", parts, [ROOM_OPENINGS[0], _opening((8.3, 0.0, 3.0 - half + gap / 2), _E, gap),
                                             _opening((8.3, 0.0, 3.025 + gap / 2), _E, gap)])


def railing_gap_balcony(gap: float = 1.2) -> SampleLevel:
    """Room 8 x 6 m whose floor lies 3 m up on a solid block, 1.6 m doorways W and E; east a balcony slab 4 m wide (z
    1-5) and 2 m deep over nothing, railed 1 m high (0.1 m thick) along its three sides but for a ``gap`` m gap in the
    middle of its front (east) railing, where a kit's ladder or stair module would join. Known: the west doorway (3 m
    up) and the railing gap (at the railing's outer face, 3 m up, ``gap`` m)."""
    parts = room(8.0, 6.0, ROOM_DOORS, floor=3.0) + [box(-0.3, 8.3, 0.0, 3.0 - SLAB, -0.3, 6.3)]
    parts += [box(8.3, 10.3, 3.0 - SLAB, 3.0, 1.0, 5.0),
              box(8.3, 10.3, 3.0 - SLAB, 4.0, 1.0, 1.1), box(8.3, 10.3, 3.0 - SLAB, 4.0, 4.9, 5.0),
              box(10.2, 10.3, 3.0 - SLAB, 4.0, 1.1, 3.0 - gap / 2), box(10.2, 10.3, 3.0 - SLAB, 4.0, 3.0 + gap / 2, 4.9)]
    return _level("railing_gap_balcony", parts, [_opening((-0.3, 3.0, 3.0), _W, 1.6), _opening((10.3, 3.0, 3.0), _E, gap)])


KINDS = kinds_by_name(sill_plate_door, grid_grate_corridor, t_ramp_arm, skew_arc_corridor, skirted_room,
                      bevelled_tile_floor, kit_seam_corridor, flared_mouth_corridor, covered_drain_door,
                      ladder_shaft_cellar, pivot_door_open, railing_gap_balcony)
"""Kind name -> factory of the nineteenth round."""


if __name__ == "__main__":
    sys.exit(run_kinds(kinds=KINDS, description=__doc__.splitlines()[0]))
