"""A twenty-third round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds23.py [--grates] [--kinds a b] [--configs map_piece
map_piece_sampling] [--yaws 0 22 45] [--detail]``

Eight kinds of docs/entry_exit.md, "A twenty-third round of piece kinds", each with its known openings written in
its docstring before the detector first ran on them: the pieces of a level designer's modular kit none of the
earlier rounds built. A T-junction whose branch a portcullis half down closes inside the piece, a doorway between
open sidelights over kick panels, a stair tower with a doorway on each of three landings, a room whose pit a bridge
crosses, a corridor whose open end is a floor grate, a yard in a picket fence whose gate leaf stands open outward,
two corridors crossing at 45 degrees, and a hall whose gallery a curved ramp reaches. Built with :mod:`piece_parts`,
in the earlier rounds' conventions. ``--grates`` runs, in their place, the end grate with bars 0.01-0.06 m wide and
0.02-0.08 m apart (:data:`GRATES`).
"""

from __future__ import annotations

import math
import sys
from functools import partial

import numpy as np
import trimesh
from piece_parts import (ROOM_OPENINGS, SLAB, arm_junction, box, corridor, flight, hull, kinds_by_name, picket_run,
                         room, round_level, run_kinds)

from g2s_plugins.samples import pieces
from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _N, _S, _W

_level = round_level(23)


def _walls(width: float, depth: float, gaps: dict[str, list[tuple[float, float, float, float]]],
           height: float) -> list[trimesh.Trimesh]:
    """Walls 0.3 m thick and ``height`` m high round the clear floor [0, width] x [0, depth] at 0, their gaps
    ``(a0, a1, bottom, top)`` as :func:`g2s_plugins.samples.pieces._wall_boxes` takes them (a doorway on an upper
    landing: its bottom that landing's height)."""
    return [box(*b) for b in pieces._wall_boxes(width, depth, 0.3, gaps, height)]


def t_junction_portcullis() -> SampleLevel:
    """T of 2.4 m corridors, walls 0.3 m and 3 m high: the main one along x (0-12, z 0-2.4), both ends open; a branch
    north from its middle (x 4.8-7.2) to its open end at z 8.0. Across the branch 1.0 m in from the junction (z
    3.40-3.48) a portcullis half down: bars 0.08 m square every 0.48 m and a bottom rail, from 1.0 m up to a beam at
    2.6 m (1.0 m of head room under it: no way through). Known: the main corridor's two ends and the branch's end
    (the branch beyond the portcullis reached from its own neighbour), 2.4 m each."""
    parts = corridor(12.0)[:2] + [box(0.0, 4.8, -SLAB, 3.0, 2.4, 2.7), box(7.2, 12.0, -SLAB, 3.0, 2.4, 2.7)]
    parts += [box(4.8, 7.2, -SLAB, 0.0, 2.4, 8.0),
              box(4.5, 4.8, -SLAB, 3.0, 2.7, 8.0), box(7.2, 7.5, -SLAB, 3.0, 2.7, 8.0)]
    parts += [box(4.5, 7.5, 2.6, 3.0, 3.34, 3.54), box(4.8, 7.2, 1.0, 1.08, 3.40, 3.48)]
    parts += [box(x, x + 0.08, 1.0, 2.6, 3.40, 3.48) for x in np.arange(5.0, 7.2 - 0.08, 0.48)]
    return _level("t_junction_portcullis", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4),
                                                   _opening((12.0, 0.0, 1.2), _E, 2.4),
                                                   _opening((6.0, 0.0, 8.0), _N, 2.4)])


def sidelight_door() -> SampleLevel:
    """Room 8 x 6 m, a 1.6 m doorway W; east a 1.2 m doorway (z 2.4-3.6) between two sidelights 0.4 m wide (z
    1.88-2.28 and 3.72-4.12), each beyond a mullion 0.12 m wide, over a kick panel 0.6 m high and open (no glass)
    from there to the 2.2 m lintel over all three. Known: both doorways, the east one 1.2 m (a sidelight is a window:
    narrower than the agent and over a panel higher than the climb)."""
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(1.88, 4.12, 2.2)]})
    parts += [box(8.0, 8.3, 0.0, 2.2, z0, z1) for z0, z1 in ((2.28, 2.4), (3.6, 3.72))]
    parts += [box(8.0, 8.3, 0.0, 0.6, z0, z1) for z0, z1 in ((1.88, 2.28), (3.72, 4.12))]
    return _level("sidelight_door", parts, [ROOM_OPENINGS[0], _opening((8.3, 0.0, 3.0), _E, 1.2)])


def stair_tower_three_landings() -> SampleLevel:
    """Stair tower 5.6 x 5.6 m inside, walls 0.3 m and 8.6 m high, no roof. Flights 1.4 m wide along the walls round
    an open well (x, z 1.4-4.2), each of 8 steps 0.35 m deep and 0.1875 m high (1.5 m), between corner landings 1.4 m
    square: up the south wall eastward to 1.5 m, the east wall northward to the NE landing at 3.0 m, the north wall
    westward to 4.5 m, the west wall southward to the SW landing at 6.0 m over the ground's corner; the first two
    flights and landings solid, the others on slabs 0.3 m thick with head room under them; a parapet 0.1 m thick, 1 m
    over the treads, along the well side and the top landing's east side. Doorways 1.2 m wide under lintels 2.2 m
    over their floor: W at the ground (z 2.2-3.4), E from the NE landing (z 4.3-5.5, 3.0 m up), S from the top landing
    (x 0.1-1.3, 6.0 m up). Known: the three doorways, each at its landing's floor on the wall's outer face."""
    gaps = {"W": [(2.2, 3.4, 0.0, 2.2)], "E": [(4.3, 5.5, 3.0, 5.2)], "S": [(0.1, 1.3, 6.0, 8.2)]}
    parts = [box(-0.3, 5.9, -SLAB, 0.0, -0.3, 5.9)] + _walls(5.6, 5.6, gaps, 8.6)
    run, rise = 0.35, 0.1875
    parts += flight((1.4, 0.0), (1, 0), (0.0, 1.4), 8, run, rise, 0.0)
    parts += [box(4.2, 5.6, -SLAB, 1.5, 0.0, 1.4)]
    parts += flight((0.0, 1.4), (0, 1), (4.2, 5.6), 8, run, rise, 1.5)
    parts += [box(4.2, 5.6, -SLAB, 3.0, 4.2, 5.6)]
    parts += flight((4.2, 0.0), (-1, 0), (4.2, 5.6), 8, run, rise, 3.0, solid=False)
    parts += [box(0.0, 1.4, 4.2, 4.5, 4.2, 5.6)]
    parts += flight((0.0, 4.2), (0, -1), (0.0, 1.4), 8, run, rise, 4.5, solid=False)
    parts += [box(0.0, 1.4, 5.7, 6.0, 0.0, 1.4)]
    for i in range(8):  # the parapets along the well, stepped with the treads
        a, b, top = 1.4 + i * run, 1.4 + (i + 1) * run, (i + 1) * rise
        parts += [box(a, b, 0.0, top + 1.0, 1.4, 1.5),  # first flight (solid under it)
                  box(4.1, 4.2, 0.0, 1.5 + top + 1.0, a, b),  # second flight
                  box(5.6 - b, 5.6 - a, 3.0 + top - 0.3, 3.0 + top + 1.0, 4.1, 4.2),  # third, on its slab
                  box(1.4, 1.5, 4.5 + top - 0.3, 4.5 + top + 1.0, 5.6 - b, 5.6 - a)]  # fourth
    parts += [box(1.4, 1.5, 5.7, 7.0, 0.0, 1.4)]
    return _level("stair_tower_three_landings", parts, [_opening((-0.3, 0.0, 2.8), _W, 1.2),
                                                        _opening((5.9, 3.0, 4.9), _E, 1.2),
                                                        _opening((0.7, 6.0, -0.3), _S, 1.2)])


def pit_bridge_room() -> SampleLevel:
    """Room 10 x 6 m, 1.6 m doorways W and E (z 2.2-3.8, lintels 2.2 m); a pit 2 m wide (x 4.0-6.0) and 3 m deep
    across the whole room, its bottom and sides part of the piece (the floor two solid blocks, the north and south
    walls carried down); an unrailed bridge 1.6 m wide (z 2.2-3.8, a 0.2 m slab) across it. Known: both doorways;
    none in the pit (walled all round, 3 m down) nor along the bridge's sides."""
    walls = room(10.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(2.2, 3.8, 2.2)]})[1:]
    parts = walls + [box(-0.3, 4.0, -3.2, 0.0, -0.3, 6.3), box(6.0, 10.3, -3.2, 0.0, -0.3, 6.3),
                     box(4.0, 6.0, -3.2, -3.0, -0.3, 6.3), box(4.0, 6.0, -3.0, -SLAB, -0.3, 0.0),
                     box(4.0, 6.0, -3.0, -SLAB, 6.0, 6.3), box(4.0, 6.0, -SLAB, 0.0, 2.2, 3.8)]
    return _level("pit_bridge_room", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((10.3, 0.0, 3.0), _E, 1.6)])


def end_grate_corridor(bar: float = 0.04, slot: float = 0.04) -> SampleLevel:
    """Corridor 12 x 2.4 m, walls 0.3 m and 3 m high, both ends open; its floor ends at x 10.8, and its last 1.2 m
    to the east end is a grate over nothing: bars ``bar`` m wide and 0.05 m deep across the corridor, ``slot`` m
    apart (15 bars 0.04 m apart by default), the last one ending at x 12.0. Known: both ends, 2.4 m, the east one on
    the grate's last bar."""
    pitch = bar + slot
    count = int(math.floor((1.2 - pitch) / pitch + 1e-9)) + 1  # bars from x 10.8 + slot on
    parts = corridor(12.0, floor=False) + [box(0.0, 10.8, -SLAB, 0.0, 0.0, 2.4)]
    parts += [box(12.0 - bar - pitch * k, 12.0 - pitch * k, -0.05, 0.0, 0.0, 2.4) for k in range(count)]
    return _level("end_grate_corridor", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4),
                                                _opening((12.0, 0.0, 1.2), _E, 2.4)])


def picket_fence_gate() -> SampleLevel:
    """Yard 10 x 8 m (ground x, z -0.1..10.1 and -0.1..8.1) in a picket fence 1 m high along its edge (band 0.1 m
    thick outside the clear yard): pickets 0.08 m wide with 0.08 m between them, rails at 0.2 and 0.75 m. West a
    2 m gap (z 3.0-5.0) between gateposts 0.12 m square and 1.3 m high; east a 1.2 m gate (z 3.4-4.6) between such
    posts, its leaf (pickets as the fence's, 0.05-1.0 m up) hinged at the south post and standing open 90 degrees
    outward, along x 10.12-11.32 (over no ground). Known: both gaps at the fence's outer line, 2.0 and 1.2 m (the
    pickets' 0.08 m gaps are no way through)."""
    parts = [box(-0.1, 10.1, -SLAB, 0.0, -0.1, 8.1)]
    parts += picket_run(-0.1, 10.1, (-0.1, 0.0), along_x=True) + picket_run(-0.1, 10.1, (8.0, 8.1), along_x=True)
    for (z0, z1), band in (((0.0, 2.88), (-0.1, 0.0)), ((5.12, 8.0), (-0.1, 0.0)),
                           ((0.0, 3.28), (10.0, 10.1)), ((4.72, 8.0), (10.0, 10.1))):
        parts += picket_run(z0, z1, band, along_x=False)
    parts += [box(-0.11, 0.01, 0.0, 1.3, z, z + 0.12) for z in (2.88, 5.0)]
    parts += [box(9.99, 10.11, 0.0, 1.3, z, z + 0.12) for z in (3.28, 4.6)]
    parts += picket_run(10.12, 11.32, (3.40, 3.45), along_x=True, height=0.95, ground=0.05)
    return _level("picket_fence_gate", parts, [_opening((-0.1, 0.0, 4.0), _W, 2.0),
                                               _opening((10.1, 0.0, 4.0), _E, 1.2)])


def oblique_crossing(length: float = 7.0) -> SampleLevel:
    """Two 2.4 m corridors crossing at 45 degrees about the origin, one along x, one along (1, 1) / sqrt(2) in (x, z),
    each arm ``length`` m from the crossing to its open end (cut square to the arm); walls 0.3 m thick and 3 m high
    meeting at the crossing's four inner corners (3.14 m from the centre in the 45-degree angles, 1.30 m in the
    135-degree ones). Known: the four ends, on the arms' axes ``length`` m out, 2.4 m, facing along the arms."""
    parts, arms = arm_junction([0.0, 45.0, 180.0, 225.0], [1.2] * 4, [length] * 4)
    ends = [_opening((d[0] * length, 0.0, d[1] * length), (d[0], 0.0, d[1]), 2 * half) for d, half in arms]
    return _level("oblique_crossing", parts, ends)


def _ramp_facet(centre: tuple[float, float], r0: float, r1: float, a0: float, a1: float, y0: float, y1: float,
                bottom: float) -> trimesh.Trimesh:
    """The solid under a curved ramp's facet between radii ``r0`` and ``r1`` about ``centre`` ((x, z)), from angle
    ``a0`` to ``a1`` (degrees, from +x towards +z), its top at ``y0`` along the radius at ``a0`` and ``y1`` at
    ``a1``, down to ``bottom``."""
    cx, cz = centre
    points = []
    for a, top in ((a0, y0), (a1, y1)):
        c, s = math.cos(math.radians(a)), math.sin(math.radians(a))
        points += [[cx + r * c, y, cz + r * s] for r in (r0, r1) for y in (bottom, top)]
    return hull(points)


def curved_ramp_gallery(facets: int = 12) -> SampleLevel:
    """Hall 12 x 8 m, walls 5.5 m high; its east 4 m (x 8-12) a gallery 2.5 m up on a solid podium, railed 1 m high
    along its west edge but where a curved ramp arrives. The ramp turns a quarter circle about (x 8.0, z 1.5), radii
    3.0-4.6 m (1.6 m wide) in ``facets`` facets: its foot at angle 180 degrees (x 3.4-5.0, z 1.5, heading north, 1.5 m
    from the south wall), rising evenly to 2.5 m at 90 degrees (x 8.0, z 4.5-6.1, heading east onto the gallery),
    22.7 degrees along its centre line; solid to the floor, railed 1 m high on both sides. A 1.6 m doorway W at the
    floor (z 3.2-4.8, lintel 2.2 m), one E from the gallery (z 3.2-4.8, 2.5 m up, lintel 2.2 m over it). Known: both
    doorways, the east one 2.5 m up."""
    gallery, centre = 2.5, (8.0, 1.5)
    gaps = {"W": [(3.2, 4.8, 0.0, 2.2)], "E": [(3.2, 4.8, gallery, gallery + 2.2)]}
    parts = [box(-0.3, 12.3, -SLAB, 0.0, -0.3, 8.3), box(8.0, 12.0, -SLAB, gallery, 0.0, 8.0)]
    parts += _walls(12.0, 8.0, gaps, 5.5)
    parts += [box(8.0, 8.1, gallery, gallery + 1.0, 0.0, 4.5), box(8.0, 8.1, gallery, gallery + 1.0, 6.1, 8.0)]
    angles = np.linspace(180.0, 90.0, facets + 1)
    heights = np.linspace(0.0, gallery, facets + 1)
    for a0, a1, y0, y1 in zip(angles[:-1], angles[1:], heights[:-1], heights[1:]):
        parts.append(_ramp_facet(centre, 3.0, 4.6, a0, a1, y0, y1, -SLAB))
        parts += [_ramp_facet(centre, r0, r1, a0, a1, y0 + 1.0, y1 + 1.0, -SLAB) for r0, r1 in ((2.9, 3.0), (4.6, 4.7))]
    return _level("curved_ramp_gallery", parts, [_opening((-0.3, 0.0, 4.0), _W, 1.6),
                                                 _opening((12.3, gallery, 4.0), _E, 1.6)])


KINDS = kinds_by_name(t_junction_portcullis, sidelight_door, stair_tower_three_landings, pit_bridge_room,
                      end_grate_corridor, picket_fence_gate, oblique_crossing, curved_ramp_gallery)
"""Kind name -> factory of the twenty-third round."""

GRATES = {f"end_grate_{round(bar * 100)}_{round(slot * 100)}cm": partial(end_grate_corridor, bar, slot)
          for bar, slot in ((0.04, 0.04), (0.02, 0.02), (0.03, 0.05), (0.02, 0.08), (0.06, 0.04), (0.01, 0.03))}
"""``end_grate_<bar>_<slot>cm`` -> :func:`end_grate_corridor` with bars that many centimetres wide and apart."""


if __name__ == "__main__":
    grates = "--grates" in sys.argv[1:]
    sys.exit(run_kinds([a for a in sys.argv[1:] if a != "--grates"], kinds=GRATES if grates else KINDS,
                       description=__doc__.splitlines()[0]))
