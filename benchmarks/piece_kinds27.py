"""A twenty-seventh round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds27.py [--kinds a b] [--configs map_piece map_piece_sampling] [--yaws 0
22 45] [--detail] [--one-to-one]``

Eight kinds of docs/entry_exit.md, "A twenty-seventh round of piece kinds", each with its known openings (count,
place, width, height) written in its docstring before the detector first ran on them: the pieces of a level
designer's modular kit none of the earlier rounds built. A gatehouse whose portcullis hangs half raised beside an open
postern, a doorway with a step down to a porch right behind its frame, a doorway through a wall 1.5 m thick splayed
from both faces to a waist, a corridor laid at 30 degrees to the kit grid with both ends cut along the grid, a
doorway whose threshold is a stone of its own 1 cm clear of the floor and the jambs, a cliff-top path whose railing
has a gap over the piece's own floor 6 m below, two storeys joined by a floor hatch and a ladder, and a doorway whose
two leaves stand swung out square to the wall. Built with :mod:`piece_parts`, in the earlier rounds' conventions.
"""

from __future__ import annotations

import math
import sys

import numpy as np
from piece_parts import SLAB, box, kinds_by_name, prism, room, round_level, run_kinds

from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _W

_level = round_level(27)


def portcullis_beside_postern() -> SampleLevel:
    """Gatehouse room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 4 m high; a 1.6 m west doorway (z 2.2-3.8,
    lintel 2.2 m); in the east wall a gate 2.4 m wide (z 0.8-3.2) under a lintel 3.2 m up, closed by a portcullis in
    the wall's middle (x 8.11-8.19) raised only to 1.2 m: bars 0.08 m square every 0.4 m from a bottom rail 1.2-1.28 m
    up to the lintel (1.2 m of head room under it: no way through for the 2 m agent); 0.8 m north of it (z 4.0-5.0) an
    open postern 1.0 m wide under a 2.1 m lintel. Known: two, at the floor (y 0): the west doorway, 1.6 m at (-0.3,
    3.0); the postern, 1.0 m at its outer face (8.3, 4.5). Not the gate."""
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(0.8, 3.2, 3.2), (4.0, 5.0, 2.1)]}, height=4.0)
    parts.append(box(8.11, 8.19, 1.2, 1.28, 0.8, 3.2))  # the portcullis' bottom rail
    parts += [box(8.11, 8.19, 1.2, 3.2, z, z + 0.08) for z in np.arange(0.9, 3.2 - 0.08, 0.4)]
    return _level("portcullis_beside_postern", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6),
                                                      _opening((8.3, 0.0, 4.5), _E, 1.0)])


def porch_step_down(step: float = 0.3) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high; 1.6 m doorways west and east (z 2.2-3.8,
    lintels 2.2 m), the east one's threshold at the floor through the wall; right behind its frame (the wall's outer
    face, x 8.3) the floor steps ``step`` m (0.3, within the 0.4 m climb) down to a porch 2.0 m deep (x 8.3-10.3) and
    2.4 m wide (z 1.8-4.2) between cheek walls 0.3 m thick and 1.0 m high over it, open east. Known: two: the west
    doorway, 1.6 m at (-0.3, 3.0) at y 0; the porch's end, 2.4 m at (10.3, 3.0), ``step`` m down, facing east (the way
    leaves the piece there; the step behind the frame is inside the piece, one way on)."""
    low = -step
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(2.2, 3.8, 2.2)]})
    parts.append(box(8.3, 10.3, low - SLAB, low, 1.5, 4.5))
    parts += [box(8.3, 10.3, low - SLAB, low + 1.0, z0, z1) for z0, z1 in ((1.5, 1.8), (4.2, 4.5))]
    return _level("porch_step_down", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6),
                                            _opening((10.3, low, 3.0), _E, 2.4)])


def double_splayed_thick_wall() -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, a 1.6 m west doorway (z 2.2-3.8, lintel
    2.2 m); its east wall 1.5 m thick (x 8.0-9.5) holding a doorway splayed from both faces: 2.2 m wide at the inner
    and the outer face (z 1.9-4.1), narrowing in straight reveals to 1.2 m at the wall's middle (x 8.75, z 2.4-3.6),
    under a lintel 2.2 m up, floored through. Known: two, at the floor (y 0): the west doorway, 1.6 m at (-0.3, 3.0);
    the east one at the outer face (9.5, 3.0), as wide as the way through, its waist: 1.2 m."""
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(-0.3, 6.3, 3.0)]})
    parts.append(box(8.3, 9.5, -SLAB, 0.0, 1.9, 4.1))  # the doorway's floor beyond the room's slab
    parts.append(prism([(8.0, -0.3), (9.5, -0.3), (9.5, 1.9), (8.75, 2.4), (8.0, 1.9)], -SLAB, 3.0))
    parts.append(prism([(8.0, 4.1), (8.75, 3.6), (9.5, 4.1), (9.5, 6.3), (8.0, 6.3)], -SLAB, 3.0))
    parts.append(prism([(8.0, 1.9), (8.75, 2.4), (8.75, 3.6), (8.0, 4.1)], 2.2, 3.0))  # the lintel, in two halves
    parts.append(prism([(8.75, 2.4), (9.5, 1.9), (9.5, 4.1), (8.75, 3.6)], 2.2, 3.0))
    return _level("double_splayed_thick_wall", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6),
                                                      _opening((9.5, 0.0, 3.0), _E, 1.2)])


def skew_grid_corridor(angle_deg: float = 30.0, length: float = 10.0) -> SampleLevel:
    """A corridor 2.4 m wide (clear), walls 0.3 m thick and 3 m high, laid ``angle_deg`` (30) degrees off the kit
    grid: its axis from the origin along (cos 30, sin 30) in (x, z), ``length`` m (10) to its far end; both ends,
    floor and walls, cut along the grid (x 0 and x 10 cos 30 = 8.66), so each open end's clear floor is 2.4 / cos 30 =
    2.77 m long. Known: two, at the floor (y 0), each as wide as its cut (the rounds' oblique ends): (0, 0) facing west
    and (8.66, 5.0) facing east, 2.77 m."""
    a = math.radians(angle_deg)
    d, n = np.array([math.cos(a), math.sin(a)]), np.array([-math.sin(a), math.cos(a)])
    x_end = length * math.cos(a)

    def at(offset: float, x: float) -> tuple[float, float]:
        """Where the line ``offset`` m left of the axis meets the grid line at ``x``."""
        point = n * offset + d * (x - offset * n[0]) / d[0]
        return float(point[0]), float(point[1])

    def strip(o0: float, o1: float, y1: float):
        return prism([at(o0, 0.0), at(o0, x_end), at(o1, x_end), at(o1, 0.0)], -SLAB, y1)

    parts = [strip(-1.2, 1.2, 0.0), strip(1.2, 1.5, 3.0), strip(-1.5, -1.2, 3.0)]
    cut = 2.4 / math.cos(a)
    return _level("skew_grid_corridor", parts, [_opening((0.0, 0.0, 0.0), _W, cut),
                                               _opening((x_end, 0.0, x_end * math.tan(a)), _E, cut)])


def threshold_stone_gaps(gap: float = 0.01) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, 1.6 m doorways west and east (z 2.2-3.8,
    lintels 2.2 m); the room's floor a slab ending ``gap`` m (0.01) short of the east wall's inner face (x 7.99), and
    the east doorway's floor through the wall a threshold stone of its own (another kit object, another material):
    x 8.0-8.3, ``gap`` m clear of the floor and of both jambs (z 2.21-3.79), its top flush at y 0; the piece ends at
    the wall's outer face. Known: two, at the floor (y 0): the west doorway, 1.6 m at (-0.3, 3.0); the east one, 1.6 m
    at its outer face (8.3, 3.0) (the stone is the doorway's floor; the slits are seams, no way down)."""
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(2.2, 3.8, 2.2)]})[1:]  # the walls, without the slab
    parts += [box(-0.3, 8.0 - gap, -SLAB, 0.0, -0.3, 6.3), box(8.0, 8.3, -SLAB, 0.0, 2.2 + gap, 3.8 - gap)]
    return _level("threshold_stone_gaps", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6),
                                                 _opening((8.3, 0.0, 3.0), _E, 1.6)])


def cliff_path_railing_gap(gap: float = 1.2, drop: float = 6.0) -> SampleLevel:
    """A path along a cliff top: a solid block whose top (y 0) is the path, x 0-10, z 2-6, open at its west and east
    ends; a rock face 4 m high along its north side (z 6-6.3); along its south edge, the cliff's, a railing 1.0 m high
    and 0.1 m thick (z 2.0-2.1) with a ``gap`` m (1.2) gap in its middle (x 4.4-5.6). Below the cliff, ``drop`` m (6)
    down, a closed yard of the piece's own: x 0-10, z -3-2, walled 2 m high on its west, south and east sides. Known:
    two, at the path's height (y 0), 3.9 m each (between the railing and the rock): its west end at (0, 4.05) and its
    east end at (10, 4.05). Not the railing's gap (a drop of ``drop`` m into the piece's own yard, no way out), nothing
    in the yard (closed)."""
    low = -drop
    parts = [box(0.0, 10.0, low - SLAB, 0.0, 2.0, 6.0), box(0.0, 10.0, low - SLAB, 4.0, 6.0, 6.3)]
    x0, x1 = 5.0 - gap / 2, 5.0 + gap / 2
    parts += [box(0.0, x0, 0.0, 1.0, 2.0, 2.1), box(x1, 10.0, 0.0, 1.0, 2.0, 2.1)]
    parts += [box(0.0, 10.0, low - SLAB, low, -3.0, 2.0), box(-0.3, 10.3, low - SLAB, low + 2.0, -3.3, -3.0)]
    parts += [box(-0.3, 0.0, low - SLAB, low + 2.0, -3.0, 2.0), box(10.0, 10.3, low - SLAB, low + 2.0, -3.0, 2.0)]
    return _level("cliff_path_railing_gap", parts, [_opening((0.0, 0.0, 4.05), _W, 3.9),
                                                   _opening((10.0, 0.0, 4.05), _E, 3.9)])


def two_storey_hatch_ladder() -> SampleLevel:
    """Two storeys of a room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick: the ground storey's walls 3 m high with
    a 1.6 m west doorway (z 2.2-3.8, lintel 2.2 m); over it a floor slab 0.2 m thick, its top 3 m up, with a hatch
    1.0 m square (x 6.0-7.0, z 2.5-3.5), its lid standing open on the hatch's east edge (x 7.0-7.05, 1.0 m high), and
    a ladder under the hatch (stiles and rungs every 0.3 m on its east side, x 6.9-7.0); the upper storey's walls 3 m
    high over its floor with a 1.6 m east doorway (z 2.2-3.8, lintel 2.2 m over the upper floor). Known: two: the west
    doorway, 1.6 m at (-0.3, 3.0) at y 0; the upper east doorway, 1.6 m at (8.3, 3.0), 3 m up. Not the hatch (a
    vertical way inside the piece, by the ladder: no walk for the agent)."""
    upper = 3.0
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)]})
    parts += [box(*b) for b in ((-0.3, 6.0, upper - SLAB, upper, -0.3, 6.3), (7.0, 8.3, upper - SLAB, upper, -0.3, 6.3),
                                (6.0, 7.0, upper - SLAB, upper, -0.3, 2.5), (6.0, 7.0, upper - SLAB, upper, 3.5, 6.3))]
    parts += room(8.0, 6.0, {"E": [(2.2, 3.8, 2.2)]}, floor=upper)[1:]  # the upper walls, on the slab above
    parts.append(box(7.0, 7.05, upper, upper + 1.0, 2.5, 3.5))  # the hatch's lid, open
    parts += [box(6.9, 7.0, 0.0, upper, z, z + 0.05) for z in (2.6, 3.35)]  # the ladder's stiles
    parts += [box(6.9, 7.0, y, y + 0.03, 2.65, 3.35) for y in np.arange(0.3, upper - 0.1, 0.3)]  # and its rungs
    return _level("two_storey_hatch_ladder", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6),
                                                    _opening((8.3, upper, 3.0), _E, 1.6)])


def leaves_swung_out_door(leaf: float = 0.9) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, a 1.6 m west doorway (z 2.2-3.8, lintel
    2.2 m); east a double doorway 2 * ``leaf`` m (1.8) wide (z 2.1-3.9) under a 2.2 m lintel whose two leaves, each
    ``leaf`` m long, 0.05 m thick and 2.1 m high, 0.01 m over the floor's height, stand swung 90 degrees out, square
    to the wall from its outer face (x 8.3 to 8.3 + ``leaf``) just outside the jambs (z 2.05-2.1 and 3.9-3.95), over
    no floor; the piece's floor ends at the wall's outer face. Known: two, at the floor (y 0): the west doorway, 1.6 m
    at (-0.3, 3.0); the east one, 1.8 m at the wall's outer face (8.3, 3.0), not at the leaves' ends."""
    half = leaf
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(3.0 - half, 3.0 + half, 2.2)]})
    parts += [box(8.3, 8.3 + leaf, 0.01, 2.11, z, z + 0.05) for z in (3.0 - half - 0.05, 3.0 + half)]
    return _level("leaves_swung_out_door", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6),
                                                  _opening((8.3, 0.0, 3.0), _E, 2 * leaf)])


KINDS = kinds_by_name(portcullis_beside_postern, porch_step_down, double_splayed_thick_wall, skew_grid_corridor,
                      threshold_stone_gaps, cliff_path_railing_gap, two_storey_hatch_ladder, leaves_swung_out_door)
"""Kind name -> factory of the twenty-seventh round."""


if __name__ == "__main__":
    sys.exit(run_kinds(sys.argv[1:], kinds=KINDS, description=__doc__.splitlines()[0]))
