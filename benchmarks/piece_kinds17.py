"""A seventeenth round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds17.py [--kinds a b] [--configs map_piece map_piece_sampling]
[--yaws 0 22 45] [--detail]``

Twelve kinds of docs/entry_exit.md, "A seventeenth round of piece kinds": sloped sills and passages, things along
or across an end that the agent cannot pass (benches, a table, a flight's underside), a fork, a gap in a parapet,
small relief in the floor (a recess, a median strip, rails). Built with the tenth round's helpers and table
(``benchmarks/piece_kinds10.py``).
"""

from __future__ import annotations

import math
import sys
from functools import partial

import numpy as np
import trimesh
from piece_kinds10 import SLAB, _box, _hull, _room
from piece_kinds10 import _level as _level10
from piece_kinds10 import kinds_by_name, main as _run_kinds
from piece_kinds14 import _corridor
from piece_kinds15 import _prism

from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _S, _W

_level = partial(_level10, round_=17)  # the tenth round's, tagged with this round


def _sloped(x0: float, x1: float, z0: float, z1: float, y0: float, y1: float, rise: float) -> trimesh.Trimesh:
    """A box over [x0, x1] x [z0, z1] whose bottom and top (``y0``, ``y1`` at x = 0) rise ``rise`` m per m of x."""
    return _hull([[x, y + rise * x, z] for x in (x0, x1) for z in (z0, z1) for y in (y0, y1)])


def ramp_side_door(slope_deg: float = 10.0) -> SampleLevel:
    """Corridor 12 x 2.4 m rising ``slope_deg`` along x, walls 3 m over the ramp, both ends open; a 1.6 m doorway
    (lintel 2.2 m over the ramp) in the south wall at x 5.2-6.8 with nothing beyond it."""
    g = math.tan(math.radians(slope_deg))
    parts = [_sloped(0.0, 12.0, -0.3, 2.4, -SLAB, 0.0, g), _sloped(0.0, 12.0, 2.4, 2.7, -SLAB, 3.0, g),
             _sloped(0.0, 5.2, -0.3, 0.0, -SLAB, 3.0, g), _sloped(6.8, 12.0, -0.3, 0.0, -SLAB, 3.0, g),
             _sloped(5.2, 6.8, -0.3, 0.0, 2.2, 3.0, g)]
    return _level("ramp_side_door", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 12.0 * g, 1.2), _E, 2.4),
                                            _opening((6.0, 6.0 * g, -0.3), _S, 1.6)])


def bench_corridor(bench: float = 0.45) -> SampleLevel:
    """Corridor 12 x 3.0 m, walls 3 m, both ends open; benches ``bench`` m high and 0.4 m deep along both walls the
    whole length."""
    parts = [_box(0.0, 12.0, -SLAB, 0.0, 0.0, 3.0), _box(0.0, 12.0, -SLAB, 3.0, -0.3, 0.0),
             _box(0.0, 12.0, -SLAB, 3.0, 3.0, 3.3), _box(0.0, 12.0, 0.0, bench, 0.0, 0.4),
             _box(0.0, 12.0, 0.0, bench, 2.6, 3.0)]
    return _level("bench_corridor", parts, [_opening((0.0, 0.0, 1.5), _W, 2.2), _opening((12.0, 0.0, 1.5), _E, 2.2)])


def ramped_wall_passage(rise: float = 0.3) -> SampleLevel:
    """Room 8 x 6 m, a 1.6 m west doorway; the east wall 1.2 m thick with a 1.6 m passage whose floor rises ``rise``
    m through it (head room 2.5 m over it); nothing beyond."""
    g = rise / 1.2
    parts = _room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(-0.3, 6.3, 3.0)]})
    parts += [_box(8.0, 9.2, -SLAB, 3.0, -0.3, 2.2), _box(8.0, 9.2, -SLAB, 3.0, 3.8, 6.3),
              _hull([[x, y, z] for x in (8.0, 9.2) for z in (2.2, 3.8) for y in (-SLAB, g * (x - 8.0))]),
              _hull([[x, y, z] for x in (8.0, 9.2) for z in (2.2, 3.8) for y in (g * (x - 8.0) + 2.5, 3.0 + rise)])]
    return _level("ramped_wall_passage", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((9.2, rise, 3.0), _E, 1.6)])


def table_in_end() -> SampleLevel:
    """Corridor 12 x 2.4 m, both ends open; a table 1.2 x 1.2 m (top 0.72-0.76 m on legs 0.06 m square at its
    corners) at x 10.6-11.8 over the south half of the east end."""
    x0, x1, z0, z1 = 10.6, 11.8, 0.0, 1.2
    parts = _corridor(12.0) + [_box(x0, x1, 0.72, 0.76, z0, z1)]
    parts += [_box(x, x + 0.06, 0.0, 0.72, z, z + 0.06) for x in (x0, x1 - 0.06) for z in (z0, z1 - 0.06)]
    return _level("table_in_end", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, 1.8), _E, 1.2)])


def pentagon_room(radius: float = 6.0, doors: tuple[int, ...] = (2, 4)) -> SampleLevel:
    """Regular pentagon of circumradius ``radius`` m about (6, 6), walls 0.3 m and 3 m high; a 1.6 m doorway (2.2 m
    lintel) in the middle of each side of ``doors``, side k facing 54 + 72 k degrees (from +x towards +z)."""
    centre = np.array([6.0, 6.0])
    apothem = radius * math.cos(math.radians(36.0))
    corner = lambda a, k: centre + a / math.cos(math.radians(36.0)) * np.array(
        [math.cos(math.radians(18.0 + 72.0 * k)), math.sin(math.radians(18.0 + 72.0 * k))])
    parts = [_prism([corner(apothem + 0.3, k) for k in range(5)], -SLAB, 0.0)]
    openings = []
    for k in range(5):
        phi = math.radians(54.0 + 72.0 * k)
        normal, along = np.array([math.cos(phi), math.sin(phi)]), np.array([-math.sin(phi), math.cos(phi)])
        inner = (corner(apothem, k), corner(apothem, k + 1))
        outer = (corner(apothem + 0.3, k), corner(apothem + 0.3, k + 1))
        if k not in doors:
            parts.append(_prism([inner[0], inner[1], outer[1], outer[0]], -SLAB, 3.0))
            continue
        mid_in, mid_out = centre + apothem * normal, centre + (apothem + 0.3) * normal
        jamb = lambda sign: [mid_in + sign * 0.8 * along, mid_out + sign * 0.8 * along]
        # the side runs from corner k to corner k + 1 along ``along``
        parts.append(_prism([inner[0], jamb(-1.0)[0], jamb(-1.0)[1], outer[0]], -SLAB, 3.0))
        parts.append(_prism([jamb(1.0)[0], inner[1], outer[1], jamb(1.0)[1]], -SLAB, 3.0))
        parts.append(_prism([*jamb(-1.0), *jamb(1.0)[::-1]], 2.2, 3.0))
        openings.append(_opening((mid_out[0], 0.0, mid_out[1]), (normal[0], 0.0, normal[1]), 1.6))
    return _level("pentagon_room", parts, openings)


def ramped_raised_door(sill: float = 0.6) -> SampleLevel:
    """Room 8 x 6 m, a 1.6 m west doorway; a 1.6 m east doorway (z 2.2-3.8) with its sill ``sill`` m up, reached by a
    landing 1.6 x 1.6 m before it and a ramp 1.6 m wide along the east wall down to the floor at the north wall;
    nothing beyond."""
    parts = _room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(2.2, 3.8, sill + 2.2)]})
    parts += [_box(6.4, 8.3, 0.0, sill, 2.2, 3.8),  # the landing, on through the wall's gap to its outer face
              _hull([[x, y, z] for x in (6.4, 8.0) for z, top in ((3.8, sill), (6.0, 0.0)) for y in (0.0, top)])]
    return _level("ramped_raised_door", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((8.3, sill, 3.0), _E, 1.6)])


def forked_ramp(slope_deg: float = 10.0) -> SampleLevel:
    """A ramp 2.4 m wide rising ``slope_deg`` east over 4 m, a landing 2.4 x 4.8 m, two arms 1.6 m wide (z -1.2..0.4
    and 2.0..3.6) rising as much over 4 m more; parapets 1 m high, 0.1 m thick along every side but the three ends;
    over nothing."""
    g = math.tan(math.radians(slope_deg))
    top, high = 4.0 * g, 8.0 * g
    parts = [_sloped(0.0, 4.0, 0.0, 2.4, -SLAB, 0.0, g), _box(4.0, 6.4, top - SLAB, top, -1.2, 3.6)]
    parts += [_sloped(6.4, 10.4, z0, z1, -SLAB - 6.4 * g + top, top - 6.4 * g, g) for z0, z1 in ((-1.2, 0.4), (2.0, 3.6))]
    parts += [_sloped(0.0, 4.0, z0, z1, -SLAB, 1.0, g) for z0, z1 in ((-0.1, 0.0), (2.4, 2.5))]
    parts += [_box(4.0, 6.4, top - SLAB, top + 1.0, z0, z1) for z0, z1 in ((-1.3, -1.2), (3.6, 3.7))]
    parts += [_box(3.9, 4.0, top - SLAB, top + 1.0, z0, z1) for z0, z1 in ((-1.3, 0.0), (2.4, 3.7))]
    parts.append(_box(6.4, 6.5, top - SLAB, top + 1.0, 0.4, 2.0))
    parts += [_sloped(6.4, 10.4, z0, z1, -SLAB - 6.4 * g + top, 1.0 + top - 6.4 * g, g)
              for z0, z1 in ((-1.3, -1.2), (0.4, 0.5), (1.9, 2.0), (3.6, 3.7))]
    return _level("forked_ramp", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((10.4, high, -0.4), _E, 1.6),
                                         _opening((10.4, high, 2.8), _E, 1.6)])


def parapet_gap_bridge(gap: float = 1.2) -> SampleLevel:
    """Deck 12 x 2.4 m over nothing, solid parapets 1 m high outside both sides, the south one with a ``gap`` m gap
    at its middle."""
    a, b = 6.0 - gap / 2, 6.0 + gap / 2
    parts = [_box(0.0, 12.0, -SLAB, 0.0, 0.0, 2.4), _box(0.0, 12.0, -SLAB, 1.0, 2.4, 2.5),
             _box(0.0, a, -SLAB, 1.0, -0.1, 0.0), _box(b, 12.0, -SLAB, 1.0, -0.1, 0.0)]
    return _level("parapet_gap_bridge", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, 1.2), _E, 2.4),
                                                _opening((6.0, 0.0, 0.0), _S, gap)])


def mat_recess_door(depth: float = 0.05) -> SampleLevel:
    """Room 8 x 6 m, 1.6 m doorways west and east; inside the east one a mat recess 0.8 x 1.6 m, ``depth`` m deep."""
    walls = _room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(2.2, 3.8, 2.2)]})[1:]  # the walls, without the slab
    floor = [_box(-0.3, 7.2, -SLAB, 0.0, -0.3, 6.3), _box(7.2, 8.3, -SLAB, 0.0, -0.3, 2.2),
             _box(7.2, 8.3, -SLAB, 0.0, 3.8, 6.3), _box(8.0, 8.3, -SLAB, 0.0, 2.2, 3.8),
             _box(7.2, 8.0, -SLAB, -depth, 2.2, 3.8)]
    return _level("mat_recess_door", floor + walls, [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((8.3, 0.0, 3.0), _E, 1.6)])


def median_strip_corridor(strip: float = 0.3) -> SampleLevel:
    """Corridor 12 x 2.4 m, both ends open; a strip 0.6 m wide and ``strip`` m high along its middle the whole
    length."""
    parts = _corridor(12.0) + [_box(0.0, 12.0, 0.0, strip, 0.9, 1.5)]
    return _level("median_strip_corridor", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, 1.2), _E, 2.4)])


def stair_underside_end(low: float = 1.2, high: float = 3.2) -> SampleLevel:
    """Corridor 12 x 2.4 m, walls 4 m, both ends open; over x 10-12 a flight's underside sloping across the corridor
    from ``low`` m at its south wall to ``high`` m at its north wall (a slab 0.2 m thick)."""
    parts = _corridor(12.0, height=4.0)
    parts.append(_hull([[x, y + dy, z] for x in (10.0, 12.0) for z, y in ((0.0, low), (2.4, high)) for dy in (0.0, 0.2)]))
    free = 2.4 * (high - 2.0) / (high - low)  # where the underside is the agent's 2 m high or more
    return _level("stair_underside_end", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4),
                                                 _opening((12.0, 0.0, 2.4 - free / 2), _E, free)])


def rail_track_tunnel() -> SampleLevel:
    """Tunnel 12 x 3.0 m, walls and roof 3 m, both ends open; two rails 0.07 m wide and 0.1 m high at z 0.90-0.97
    and 2.03-2.10 the whole length."""
    parts = [_box(0.0, 12.0, -SLAB, 0.0, 0.0, 3.0), _box(0.0, 12.0, -SLAB, 3.0, -0.3, 0.0),
             _box(0.0, 12.0, -SLAB, 3.0, 3.0, 3.3), _box(0.0, 12.0, 3.0, 3.3, -0.3, 3.3),
             _box(0.0, 12.0, 0.0, 0.1, 0.9, 0.97), _box(0.0, 12.0, 0.0, 0.1, 2.03, 2.1)]
    return _level("rail_track_tunnel", parts, [_opening((0.0, 0.0, 1.5), _W, 3.0), _opening((12.0, 0.0, 1.5), _E, 3.0)])


KINDS = kinds_by_name(ramp_side_door, bench_corridor, ramped_wall_passage, table_in_end, pentagon_room,
                      ramped_raised_door, forked_ramp, parapet_gap_bridge, mat_recess_door, median_strip_corridor,
                      stair_underside_end, rail_track_tunnel)
"""Kind name -> factory of the seventeenth round."""


if __name__ == "__main__":
    sys.exit(_run_kinds(kinds=KINDS, description=__doc__.splitlines()[0]))
