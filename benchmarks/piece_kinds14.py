"""A fourteenth round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds14.py [--kinds a b] [--configs map_piece map_piece_sampling]
[--yaws 0 22 45] [--detail]``

Kinds of docs/entry_exit.md, "A fourteenth round of piece kinds", in the tenth round's conventions and table
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
from piece_kinds13 import height_field

from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _N, _S, _W

_level = partial(_level10, round_=14)  # the tenth round's, tagged with this round


def _corridor(length: float, height: float = 3.0, floor: bool = True) -> list[trimesh.Trimesh]:
    """Corridor along x over [0, ``length``], clear z [0, 2.4], walls 0.3 m thick from the slab's underside to
    ``height``; both ends open; its floor slab unless ``floor`` is false."""
    walls = [_box(0.0, length, -SLAB, height, -0.3, 0.0), _box(0.0, length, -SLAB, height, 2.4, 2.7)]
    return ([_box(0.0, length, -SLAB, 0.0, 0.0, 2.4)] if floor else []) + walls


def leaning_wall_door(lean_deg: float = 15.0) -> SampleLevel:
    """Room 8 x 6 m, a west doorway; its east wall leans out by ``lean_deg``, a 1.6 m doorway in it under a lintel
    from 2.2 m."""
    g = math.tan(math.radians(lean_deg))
    parts = _room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(-0.3, 6.3, 3.0)]})

    def leaning(z0: float, z1: float, y0: float, y1: float) -> trimesh.Trimesh:  # a piece of the wall over [y0, y1]
        return _hull([[x + g * y, y, z] for x in (8.0, 8.3) for y in (y0, y1) for z in (z0, z1)])

    parts += [leaning(-0.3, 2.2, 0.0, 3.0), leaning(3.8, 6.3, 0.0, 3.0), leaning(2.2, 3.8, 2.2, 3.0)]
    return _level("leaning_wall_door", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((8.3, 0.0, 3.0), _E, 1.6)])


def _railing(x0: float, x1: float, z0: float, z1: float) -> list[trimesh.Trimesh]:
    """A 1 m railing along x over [x0, x1] on a deck at 0 between z0 and z1: posts 0.1 m square at its ends and at
    most 1.5 m apart, rails 0.45-0.55 and 0.9-1.0 m up."""
    posts = np.linspace(x0, x1 - 0.1, max(2, math.ceil((x1 - x0 - 0.1) / 1.5) + 1))
    return ([_box(x, x + 0.1, 0.0, 1.0, z0, z1) for x in posts]
            + [_box(x0, x1, y0, y0 + 0.1, z0, z1) for y0 in (0.45, 0.9)])


def gapped_rail_bridge() -> SampleLevel:
    """Footbridge 14 x 2.4 m over nothing; its railings broken by two 0.6 m gaps north and a 1.4 m gap south."""
    parts = [_box(0.0, 14.0, -0.3, 0.0, 0.0, 2.4)]
    for x0, x1 in ((0.0, 4.0), (4.6, 9.0), (9.6, 14.0)):
        parts += _railing(x0, x1, 2.3, 2.4)
    for x0, x1 in ((0.0, 6.3), (7.7, 14.0)):
        parts += _railing(x0, x1, 0.0, 0.1)
    return _level("gapped_rail_bridge", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((14.0, 0.0, 1.2), _E, 2.4),
                                                _opening((7.0, 0.0, 0.0), _S, 1.4)])


def _strip(a: tuple[float, float], b: tuple[float, float], ya: float, yb: float, half: float, bottom: float,
           top: float) -> trimesh.Trimesh:
    """A slab or parapet along the plan segment a -> b ((x, z), metres), ``half`` either side of it, from ``bottom``
    to ``top`` over a surface rising from ``ya`` at a to ``yb`` at b."""
    d = np.subtract(b, a) / np.linalg.norm(np.subtract(b, a))
    side = np.array([-d[1], d[0]]) * half
    return _hull([[p[0] + s * side[0], y + dy, p[1] + s * side[1]] for p, y in ((a, ya), (b, yb))
                  for s in (-1.0, 1.0) for dy in (bottom, top)])


def ramp_landing_turn() -> SampleLevel:
    """Ramp 8 m east at 8 degrees, a 2 x 2 m landing, a ramp 8 m north at 8 degrees; pads at the foot (west) and the
    top (north), parapets 1 m round everything but the pads' ends; nothing under it."""
    rise = 8.0 * math.tan(math.radians(8.0))
    parts = [_box(-2.0, 0.0, -SLAB, 0.0, 0.0, 2.0), _strip((0.0, 1.0), (8.0, 1.0), 0.0, rise, 1.0, -SLAB, 0.0),
             _box(8.0, 10.0, rise - SLAB, rise, 0.0, 2.0),
             _strip((9.0, 2.0), (9.0, 10.0), rise, 2 * rise, 1.0, -SLAB, 0.0),
             _box(8.0, 10.0, 2 * rise - SLAB, 2 * rise, 10.0, 12.0)]
    parapets = [((-2.0, -0.05), (0.0, -0.05), 0.0, 0.0), ((0.0, -0.05), (8.0, -0.05), 0.0, rise),
                ((8.0, -0.05), (10.1, -0.05), rise, rise),  # south of the pad, run 1 and the landing
                ((-2.0, 2.05), (0.0, 2.05), 0.0, 0.0), ((0.0, 2.05), (7.95, 2.05), 0.0, rise),  # north of them
                ((10.05, -0.1), (10.05, 2.0), rise, rise), ((10.05, 2.0), (10.05, 10.0), rise, 2 * rise),
                ((10.05, 10.0), (10.05, 12.0), 2 * rise, 2 * rise),  # east of the landing, run 2 and the top pad
                ((7.95, 2.0), (7.95, 10.0), rise, 2 * rise), ((7.95, 10.0), (7.95, 12.0), 2 * rise, 2 * rise)]
    parts += [_strip(a, b, ya, yb, 0.05, -SLAB, 1.0) for a, b, ya, yb in parapets]
    return _level("ramp_landing_turn", parts, [_opening((-2.0, 0.0, 1.0), _W, 2.0), _opening((9.0, 2 * rise, 12.0), _N, 2.0)])


def floor_gap_corridor(gap: float = 0.3) -> SampleLevel:
    """Corridor 12 x 2.4 m, both ends open; a ``gap`` m gap across its floor at its middle over nothing."""
    parts = _corridor(12.0, floor=False) + [_box(0.0, 6.0 - gap / 2, -SLAB, 0.0, 0.0, 2.4),
                                            _box(6.0 + gap / 2, 12.0, -SLAB, 0.0, 0.0, 2.4)]
    return _level("floor_gap_corridor", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, 1.2), _E, 2.4)])


def scree_cave_mouth(seed: int = 0) -> SampleLevel:
    """A scree apron rising 8.5 degrees east to a cliff face, rough (0.12 m, ``seed``) with four boulders, between
    rock walls; a dead-end cave in the cliff; the apron's foot (west) open."""
    rng = np.random.default_rng(seed)
    xs, zs = np.arange(0.0, 10.01, 0.5), np.arange(0.0, 8.01, 0.5)
    heights = 0.15 * xs[:, None] + rng.uniform(0.0, 0.12, (len(xs), len(zs)))
    parts = [height_field(xs, zs, heights), _box(0.0, 10.0, -SLAB, -0.01, 0.0, 8.0),
             _box(0.0, 10.0, -SLAB, 4.0, -0.6, 0.0), _box(0.0, 10.0, -SLAB, 4.0, 8.0, 8.6)]
    for x, z, size, tall in ((3.5, 2.0, 1.0, 0.8), (5.0, 6.0, 1.2, 1.0), (6.5, 3.5, 0.8, 0.6), (7.5, 1.0, 1.0, 0.9)):
        base = 0.15 * x
        parts.append(_box(x - size / 2, x + size / 2, base - 0.1, base + tall, z - size / 2, z + size / 2))
    parts += [_box(10.0, 16.0, -SLAB, 6.0, -0.6, 2.5), _box(10.0, 16.0, -SLAB, 6.0, 5.5, 8.6),
              _box(10.0, 16.0, 3.8, 6.0, 2.5, 5.5), _box(15.0, 16.0, -SLAB, 3.8, 2.5, 5.5),
              _box(10.0, 15.0, -SLAB, 1.5, 2.5, 5.5)]
    return _level("scree_cave_mouth", parts, [_opening((0.0, float(heights[0].mean()), 4.0), _W, 8.0)])


def column_base_door() -> SampleLevel:
    """Room 8 x 6 m, a west doorway; the east doorway flanked outside by engaged columns on bases 0.3 m proud of the
    wall; no floor beyond the wall."""
    parts = _room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(2.2, 3.8, 2.4)]})
    for z0, z1, s0, s1 in ((1.7, 2.2, 1.9, 2.2), (3.8, 4.3, 3.8, 4.1)):
        parts += [_box(8.3, 8.6, -SLAB, 0.4, z0, z1), _box(8.3, 8.5, 0.4, 2.8, s0, s1)]
    return _level("column_base_door", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((8.3, 0.0, 3.0), _E, 1.6)])


def invisible_wall_cut() -> SampleLevel:
    """Yard 12 x 8 m, doorways west and east; a collision wall, one quad without thickness, cuts it in two along
    x = 4.5 + 3 z / 8."""
    parts = _room(12.0, 8.0, {"W": [(3.2, 4.8, 2.2)], "E": [(3.2, 4.8, 2.2)]})
    (za, zb), (y0, y1) = (-0.3, 8.3), (-SLAB, 4.0)
    corners = [[4.5 + 3.0 * z / 8.0, y, z] for z, y in ((za, y0), (zb, y0), (zb, y1), (za, y1))]
    parts.append(trimesh.Trimesh(vertices=corners, faces=[[0, 1, 2], [0, 2, 3]], process=False))
    return _level("invisible_wall_cut", parts, [_opening((-0.3, 0.0, 4.0), _W, 1.6), _opening((12.3, 0.0, 4.0), _E, 1.6)])


def pier_end() -> SampleLevel:
    """A quay 4 x 6 m on a solid block, railed but for its west end; a railed pier 14 x 2.4 m on piles over nothing
    (water is no collision geometry), its end open."""
    parts = [_box(-4.0, 0.0, -3.0, 0.0, -1.0, 5.0), _box(0.0, 14.0, -0.3, 0.0, 0.0, 2.4),
             _box(-4.0, 0.0, 0.0, 1.0, -1.0, -0.9), _box(-4.0, 0.0, 0.0, 1.0, 4.9, 5.0),
             _box(-0.1, 0.0, 0.0, 1.0, -1.0, 0.0), _box(-0.1, 0.0, 0.0, 1.0, 2.4, 5.0),
             _box(0.0, 14.0, 0.0, 1.0, 0.0, 0.1), _box(0.0, 14.0, 0.0, 1.0, 2.3, 2.4)]
    parts += [_box(x - 0.15, x + 0.15, -3.0, -0.3, z - 0.15, z + 0.15) for x in (3.0, 6.0, 9.0, 12.0) for z in (0.15, 2.25)]
    return _level("pier_end", parts, [_opening((-4.0, 0.0, 2.0), _W, 6.0), _opening((14.0, 0.0, 1.2), _E, 2.4)])


def pipe_sill_corridor(radius: float = 0.15) -> SampleLevel:
    """Corridor 12 x 2.4 m, both ends open; a pipe of ``radius`` m lying on the floor across its east end."""
    angles = np.arange(16) * 2 * math.pi / 16
    pipe = _hull([[12.0 - radius + radius * math.cos(a), radius + radius * math.sin(a), z]
                  for a in angles for z in (0.0, 2.4)])
    return _level("pipe_sill_corridor", _corridor(12.0) + [pipe],
                  [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, 1.2), _E, 2.4)])


def airlock_vestibule() -> SampleLevel:
    """Room 8 x 6 m, a west doorway; east a 1.2 m doorway into a roofed vestibule 2 x 3 m whose 1.2 m outer doorway
    is offset from the inner one."""
    parts = _room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(1.8, 3.0, 2.2)]})
    parts += [_box(8.3, 10.6, -SLAB, 0.0, 1.2, 4.8), _box(8.3, 10.3, -SLAB, 2.8, 1.2, 1.5),
              _box(8.3, 10.3, -SLAB, 2.8, 4.5, 4.8), _box(8.3, 10.6, 2.6, 2.8, 1.2, 4.8),
              _box(10.3, 10.6, -SLAB, 2.6, 1.2, 3.0), _box(10.3, 10.6, -SLAB, 2.6, 4.2, 4.8),
              _box(10.3, 10.6, 2.2, 2.6, 3.0, 4.2)]
    return _level("airlock_vestibule", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((10.6, 0.0, 3.6), _E, 1.2)])


def landing_side_door(foot: float = 0.3) -> SampleLevel:
    """Room 8 x 6 m, walls 5 m, a west doorway; a stair along the east wall rising north from ``foot`` m off the south
    wall (at most 1.3) to a landing 1 m up, 2.3 m long, and on to a top landing 2 m up; a doorway in the east wall
    off the landing, over nothing outside."""
    door = foot + 1.7  # the east doorway's south side
    parts = _room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(door, door + 1.6, 3.2)]}, height=5.0)
    parts.append(_box(8.0, 8.3, -SLAB, 1.0, door, door + 1.6))  # the wall under the doorway, up to the landing
    for base, top, end in ((foot, 0.0, foot + 3.5), (foot + 3.5, 1.0, 6.0)):  # a flight of four 0.2 m risers on 0.3 m
        # treads, then a landing at the fifth riser's top
        parts += [_box(6.8, 8.0, 0.0, top + 0.2 * (i + 1), base + 0.3 * i, base + 0.3 * (i + 1)) for i in range(4)]
        parts.append(_box(6.8, 8.0, 0.0, top + 1.0, base + 1.2, end))
    return _level("landing_side_door", parts,
                  [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((8.3, 1.0, door + 0.8), _E, 1.6)])


def undulating_corridor(amplitude: float = 0.3, period: float = 5.0) -> SampleLevel:
    """Corridor 12 x 2.4 m, walls 4 m, both ends open; its floor undulates, ``amplitude`` (1 - cos(2 pi x /
    ``period``)) m high."""
    xs = np.arange(0.0, 12.001, 0.25)
    ys = amplitude * (1.0 - np.cos(2.0 * math.pi * xs / period))
    parts = _corridor(12.0, height=4.0, floor=False)
    parts += [_hull([[x, y, z] for x, top in ((xa, ya), (xb, yb)) for y in (-SLAB, top) for z in (0.0, 2.4)])
              for xa, ya, xb, yb in zip(xs[:-1], ys[:-1], xs[1:], ys[1:])]
    return _level("undulating_corridor", parts,
                  [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, float(ys[-1]), 1.2), _E, 2.4)])


KINDS = kinds_by_name(leaning_wall_door, gapped_rail_bridge, ramp_landing_turn, floor_gap_corridor, scree_cave_mouth,
                      column_base_door, invisible_wall_cut, pier_end, pipe_sill_corridor, airlock_vestibule,
                      landing_side_door, undulating_corridor)
"""Kind name -> factory of the fourteenth round."""


if __name__ == "__main__":
    sys.exit(_run_kinds(kinds=KINDS, description=__doc__.splitlines()[0]))
