"""A fifteenth round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds15.py [--kinds a b] [--configs map_piece map_piece_sampling]
[--yaws 0 22 45] [--detail]``

Kinds of docs/entry_exit.md, "A fifteenth round of piece kinds", in the tenth round's conventions and table
(``benchmarks/piece_kinds10.py``).
"""

from __future__ import annotations

import math
import sys
from functools import partial

import numpy as np
import trimesh
from piece_kinds10 import SLAB, _arc_band, _box, _disc, _hull, _room
from piece_kinds10 import _level as _level10
from piece_kinds10 import kinds_by_name, main as _run_kinds
from piece_kinds14 import _corridor

from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _N, _W

_level = partial(_level10, round_=15)  # the tenth round's, tagged with this round


def _prism(plan, y0: float, y1: float) -> trimesh.Trimesh:
    """The vertical prism over the convex plan polygon ``plan`` ((x, z) corners, metres) from ``y0`` to ``y1``."""
    return _hull([[x, y, z] for x, z in plan for y in (y0, y1)])


def triangle_room(side: float = 10.0) -> SampleLevel:
    """Equilateral room of ``side`` m sides, walls 0.3 m; a 1.6 m doorway (2.2 m lintel) in the middle of each side."""
    corners = np.array([[0.0, 0.0], [side, 0.0], [side / 2, side * math.sqrt(3) / 2]])
    centre = corners.mean(axis=0)
    inradius = side / (2 * math.sqrt(3))
    outer = centre + (corners - centre) * (inradius + 0.3) / inradius
    parts, openings = [_prism(outer, -SLAB, 0.0)], []
    for p, q in zip(corners, np.roll(corners, -1, axis=0)):
        d = (q - p) / side
        n = np.array([d[1], -d[0]]) if np.dot(np.array([d[1], -d[0]]), p - centre) > 0 else np.array([-d[1], d[0]])

        def band(s0: float, s1: float, y0: float, y1: float) -> trimesh.Trimesh:  # the wall over [s0, s1] along p -> q
            return _prism([p + d * s0, p + d * s1, p + d * s1 + n * 0.3, p + d * s0 + n * 0.3], y0, y1)

        parts += [band(-0.6, side / 2 - 0.8, -SLAB, 3.0), band(side / 2 + 0.8, side + 0.6, -SLAB, 3.0),
                  band(side / 2 - 0.8, side / 2 + 0.8, 2.2, 3.0)]
        mid = p + d * side / 2 + n * 0.3
        openings.append(_opening((mid[0], 0.0, mid[1]), (n[0], 0.0, n[1]), 1.6))
    return _level("triangle_room", parts, openings)


def roundabout_three_exits(radius: float = 6.0, road: float = 4.0, reach: float = 10.0) -> SampleLevel:
    """A round plaza of ``radius`` m inside a 3 m wall round a raised island 2 m in radius (1 m high); three roads
    ``road`` m wide leave it at 0, 120 and 240 degrees between walls to ``reach`` m from the centre."""
    half = road / 2
    gap = math.degrees(math.asin(half / radius))
    parts = [_disc(0.0, 0.0, radius + 0.3, -SLAB, 0.0), _disc(0.0, 0.0, 2.0, -SLAB, 1.0)]
    openings = []
    for a in (0.0, 120.0, 240.0):
        u = np.array([math.cos(math.radians(a)), math.sin(math.radians(a))])
        v = np.array([-u[1], u[0]])

        def rect(x0: float, x1: float, z0: float, z1: float):  # a rectangle in the road's frame, plan corners
            return [u * x + v * z for x, z in ((x0, z0), (x1, z0), (x1, z1), (x0, z1))]

        start = math.sqrt(radius**2 - half**2)
        parts += [_prism(rect(0.0, reach, -half - 0.3, half + 0.3), -SLAB, 0.0),
                  _prism(rect(start - 0.3, reach, -half - 0.3, -half), -SLAB, 3.0),
                  _prism(rect(start - 0.3, reach, half, half + 0.3), -SLAB, 3.0)]
        parts += _arc_band(0.0, 0.0, radius, radius + 0.3, a + gap, a + 120.0 - gap, -SLAB, 3.0)
        openings.append(_opening((u[0] * reach, 0.0, u[1] * reach), (u[0], 0.0, u[1]), road))
    return _level("roundabout_three_exits", parts, openings)


def dogleg_wall_passage(chamber: float = 0.8) -> SampleLevel:
    """Room 8 x 6 m, a west doorway; its east wall 2 m thick with a passage 1.2 m wide and 2.4 m high through it that
    jogs 1 m north half way (a chamber ``chamber`` m long, at most 2, spanning both halves)."""
    parts = _room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(-0.3, 6.3, 3.0)]})
    parts.append(_box(8.3, 10.0, -SLAB, 0.0, -0.3, 6.3))
    a, b = 9.0 - chamber / 2, 9.0 + chamber / 2
    for x0, x1, z_lo, z_hi in ((8.0, a, 2.4, 3.6), (a, b, 2.4, 4.6), (b, 10.0, 3.4, 4.6)):
        parts += [_box(x0, x1, 0.0, 3.0, -0.3, z_lo), _box(x0, x1, 0.0, 3.0, z_hi, 6.3)]  # the wall beside the void
    parts.append(_box(8.0, 10.0, 2.4, 3.0, 2.4, 4.6))  # the passage's ceiling
    return _level("dogleg_wall_passage", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((10.0, 0.0, 4.0), _E, 1.2)])


def hanging_sign_corridor(bottom: float = 1.7, cover: float = 1.2) -> SampleLevel:
    """Corridor 12 x 2.4 m, both ends open; at its east end a sign hangs from a beam 2.6 m up down to ``bottom`` m over
    the south ``cover`` m (the end's free part: the rest where the sign hangs lower than the agent's 2 m)."""
    parts = _corridor(12.0) + [_box(11.8, 11.95, 2.6, 2.7, -0.3, 2.7), _box(11.85, 11.9, bottom, 2.6, 0.0, cover)]
    free = cover if bottom < 2.0 else 0.0
    return _level("hanging_sign_corridor", parts,
                  [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, (free + 2.4) / 2), _E, 2.4 - free)])


def wedge_sill_door(sill: float = 0.15) -> SampleLevel:
    """Room 8 x 6 m, a west doorway; the east doorway's threshold a wedge ``sill`` m high at the wall's middle,
    sloping to the floor 0.3 m inside the wall and at its outer face; nothing beyond the wall."""
    parts = _room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(2.2, 3.8, 2.2)]})
    parts.append(_hull([[x, y, z] for x, y in ((7.7, 0.0), (8.15, sill), (8.3, 0.0)) for z in (2.2, 3.8)]
                       + [[7.7, -0.01, z] for z in (2.2, 3.8)]))
    return _level("wedge_sill_door", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((8.3, 0.0, 3.0), _E, 1.6)])


def sagging_rope_bridge(sag: float = 0.4) -> SampleLevel:
    """Deck 12 x 1.6 m over nothing, sagging ``sag`` m at its middle (a parabola in 0.5 m facets); rope rails 0.04 m
    square 1 m above it along both sides, outside the deck, on posts at its ends."""
    xs = np.arange(0.0, 12.001, 0.5)
    ys = -sag * (1.0 - ((xs - 6.0) / 6.0) ** 2)
    parts = [_hull([[x, y + dy, z] for x, y in ((xa, ya), (xb, yb)) for dy in (-0.15, 0.0) for z in (0.0, 1.6)])
             for xa, ya, xb, yb in zip(xs[:-1], ys[:-1], xs[1:], ys[1:])]
    for z0 in (-0.04, 1.6):
        parts += [_hull([[x, y + dy, z] for x, y in ((xa, ya), (xb, yb)) for dy in (0.96, 1.0) for z in (z0, z0 + 0.04)])
                  for xa, ya, xb, yb in zip(xs[:-1], ys[:-1], xs[1:], ys[1:])]
        parts += [_box(x, x + 0.08, -0.15, 1.0, z0 - 0.04, z0 + 0.04) for x in (0.0, 11.92)]
    return _level("sagging_rope_bridge", parts, [_opening((0.0, 0.0, 0.8), _W, 1.6), _opening((12.0, 0.0, 0.8), _E, 1.6)])


def winder_stair() -> SampleLevel:
    """A stairwell 1.6 m wide between walls 4 m above the treads: a pad 2 m long open west, four 0.2 m risers east,
    three winder treads turning north about the inner corner (30 degrees each), four risers north to a top pad
    2.2 m up, 2 m long, open north."""
    parts = [_box(-2.0, 0.0, -SLAB, 0.0, 0.0, 1.6)]
    parts += [_box(0.3 * i, 0.3 * (i + 1), -SLAB, 0.2 * (i + 1), 0.0, 1.6) for i in range(4)]
    inner = np.array([1.2, 1.6])
    p30 = np.array([1.2 + 1.6 * math.tan(math.radians(30.0)), 0.0])  # where the 30 and 60 degree lines from the
    p60 = np.array([2.8, 1.6 - 1.6 / math.tan(math.radians(60.0))])  # inner corner meet the outer walls' faces
    for top, plan in ((1.0, [inner, [1.2, 0.0], p30]), (1.2, [inner, p30, [2.8, 0.0], p60]), (1.4, [inner, p60, [2.8, 1.6]])):
        parts.append(_prism(plan, -SLAB, top))
    parts += [_box(1.2, 2.8, -SLAB, 1.6 + 0.2 * i, 1.6 + 0.3 * i, 1.9 + 0.3 * i) for i in range(3)]
    parts.append(_box(1.2, 2.8, -SLAB, 2.2, 2.5, 4.5))
    parts += [_box(-2.0, 2.8, -SLAB, 4.0, -0.3, 0.0), _box(2.8, 3.1, -SLAB, 6.2, -0.3, 4.5),  # south, then east
              _box(-2.0, 1.2, -SLAB, 4.0, 1.6, 1.9), _box(0.9, 1.2, -SLAB, 6.2, 1.6, 4.5)]  # north, then west
    return _level("winder_stair", parts, [_opening((-2.0, 0.0, 0.8), _W, 1.6), _opening((2.0, 2.2, 4.5), _N, 1.6)])


def sawtooth_wall_corridor() -> SampleLevel:
    """Corridor 12 m long, both ends open; its walls' inner faces a zigzag in plan, teeth 0.3 m deep every 1 m, their
    tips 2.4 m apart at whole metres (the ends among them)."""
    parts = [_box(0.0, 12.0, -SLAB, 0.0, -0.6, 3.0), _box(0.0, 12.0, -SLAB, 3.0, -0.6, -0.3),
             _box(0.0, 12.0, -SLAB, 3.0, 2.7, 3.0)]
    for k in range(13):
        x0, x1 = max(0.0, k - 0.5), min(12.0, k + 0.5)
        for base, tip in ((-0.3, 0.0), (2.7, 2.4)):
            parts.append(_prism([[x0, base], [k, tip], [x1, base]] + ([[k, base]] if x0 == k or x1 == k else []),
                                0.0, 3.0))
    return _level("sawtooth_wall_corridor", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, 1.2), _E, 2.4)])


def drawbridge_chains(slope_deg: float = 3.0) -> SampleLevel:
    """Corridor 6 x 3 m open west, through a gate 3 m wide (3.5 m lintel) in a wall 1.5 m thick standing 2 m out either
    side; beyond it a drawbridge deck 6 x 3 m falling ``slope_deg`` over nothing, chains 0.05 m square from the wall's
    face 4 m up to lugs outside the deck's far corners."""
    drop = 6.0 * math.tan(math.radians(slope_deg))
    parts = [_box(-6.0, 1.5, -SLAB, 0.0, -0.3, 3.3), _box(-6.0, 0.0, -SLAB, 3.0, -0.3, 0.0),
             _box(-6.0, 0.0, -SLAB, 3.0, 3.0, 3.3), _box(0.0, 1.5, -SLAB, 5.0, -2.0, 0.0),
             _box(0.0, 1.5, -SLAB, 5.0, 3.0, 5.0), _box(0.0, 1.5, 3.5, 5.0, 0.0, 3.0),
             _hull([[x, y + dy, z] for x, y in ((1.5, 0.0), (7.5, -drop)) for dy in (-0.3, 0.0) for z in (0.0, 3.0)])]
    for z0 in (-0.1, 3.05):
        parts.append(_hull([[x, y + dy, z] for x, y in ((1.5, 4.0), (7.3, 0.1 - drop)) for dy in (0.0, 0.05)
                            for z in (z0, z0 + 0.05)]))
        parts.append(_box(7.2, 7.4, -0.3 - drop, 0.15 - drop, z0, z0 + 0.05))
    return _level("drawbridge_chains", parts,
                  [_opening((-6.0, 0.0, 1.5), _W, 3.0), _opening((7.5, -drop, 1.5), _E, 3.0)])


def half_parapet_end() -> SampleLevel:
    """Corridor 12 x 2.4 m, both ends open; across its east end's south half a wall 1 m high and 0.3 m thick."""
    parts = _corridor(12.0) + [_box(11.7, 12.0, 0.0, 1.0, 0.0, 1.2)]
    return _level("half_parapet_end", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, 1.8), _E, 1.2)])


def crenellated_wall_walk() -> SampleLevel:
    """A wall walk 12 x 2 m on a solid wall 4 m high, both ends open; north a plain parapet 1.2 m high, south a
    crenellated one: 0.9 m high, merlons 1 m long up to 1.8 m every 1.6 m (crenels 0.6 m)."""
    parts = [_box(0.0, 12.0, -4.0, 0.0, -0.4, 2.4), _box(0.0, 12.0, 0.0, 1.2, 2.0, 2.4),
             _box(0.0, 12.0, 0.0, 0.9, -0.4, 0.0)]
    parts += [_box(x, min(x + 1.0, 12.0), 0.9, 1.8, -0.4, 0.0) for x in np.arange(0.0, 12.0, 1.6)]
    return _level("crenellated_wall_walk", parts, [_opening((0.0, 0.0, 1.0), _W, 2.0), _opening((12.0, 0.0, 1.0), _E, 2.0)])


def sloped_ceiling_tunnel(low: float = 1.5) -> SampleLevel:
    """Tunnel 12 x 2.4 m, both ends' floors open; its ceiling 3 m up at the west end falls to ``low`` m at the east
    end (the agent's 2 m fit only the west part)."""
    g = (3.0 - low) / 12.0
    parts = _corridor(12.0, height=3.2) + [_hull([[x, 3.0 - g * x + dy, z] for x in (0.0, 12.0) for dy in (0.0, 0.2)
                                                  for z in (-0.3, 2.7)])]
    return _level("sloped_ceiling_tunnel", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4)])


KINDS = kinds_by_name(triangle_room, roundabout_three_exits, dogleg_wall_passage, hanging_sign_corridor,
                      wedge_sill_door, sagging_rope_bridge, winder_stair, sawtooth_wall_corridor, drawbridge_chains,
                      half_parapet_end, crenellated_wall_walk, sloped_ceiling_tunnel)
"""Kind name -> factory of the fifteenth round."""

if __name__ == "__main__":
    sys.exit(_run_kinds(kinds=KINDS, description=__doc__.splitlines()[0]))
