"""A sixteenth round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds16.py [--kinds a b] [--configs map_piece map_piece_sampling]
[--yaws 0 22 45] [--detail]``

Kinds of docs/entry_exit.md, "A sixteenth round of piece kinds", in the tenth round's conventions and table
(``benchmarks/piece_kinds10.py``).
"""

from __future__ import annotations

import math
import sys
from functools import partial

import numpy as np
from piece_kinds10 import SLAB, _arc_band, _box, _hull, _room
from piece_kinds10 import _level as _level10
from piece_kinds10 import kinds_by_name, main as _run_kinds
from piece_kinds14 import _corridor
from piece_kinds15 import _prism

from g2s_plugins.samples import pieces
from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _N, _S, _W

_level = partial(_level10, round_=16)  # the tenth round's, tagged with this round


def catwalk_over_hall() -> SampleLevel:
    """Hall 12 x 8 m, walls 6 m, 1.6 m doorways west and east; a catwalk 1.6 m wide 3 m up across it north-south
    through gaps in the north and south walls, solid parapets 1 m high along its sides, joined to nothing else."""
    gaps = {"W": [(3.2, 4.8, 0.0, 2.2)], "E": [(3.2, 4.8, 0.0, 2.2)], "S": [(5.2, 6.8, 2.8, 5.2)],
            "N": [(5.2, 6.8, 2.8, 5.2)]}
    parts = [_box(-0.3, 12.3, -SLAB, 0.0, -0.3, 8.3)] + [_box(*b) for b in pieces._wall_boxes(12.0, 8.0, 0.3, gaps, 6.0)]
    parts += [_box(5.2, 6.8, 2.8, 3.0, -0.3, 8.3), _box(5.1, 5.2, 2.8, 4.0, 0.0, 8.0), _box(6.8, 6.9, 2.8, 4.0, 0.0, 8.0)]
    return _level("catwalk_over_hall", parts, [_opening((-0.3, 0.0, 4.0), _W, 1.6), _opening((12.3, 0.0, 4.0), _E, 1.6),
                                               _opening((6.0, 3.0, -0.3), _S, 1.6), _opening((6.0, 3.0, 8.3), _N, 1.6)])


def baluster_terrace(pitch: float = 0.2) -> SampleLevel:
    """Terrace 8 x 6 m, 1.5 m up on a solid block over nothing, open west; on its other sides a balustrade of balusters
    0.08 m square every ``pitch`` m inside the slab's edge up to a top rail at 0.9-1.0 m."""
    f = 1.5
    parts = [_box(0.0, 8.0, 0.0, f, 0.0, 6.0), _box(0.02, 7.98, f + 0.9, f + 1.0, 0.02, 0.1),
             _box(0.02, 7.98, f + 0.9, f + 1.0, 5.9, 5.98), _box(7.9, 7.98, f + 0.9, f + 1.0, 0.02, 5.98)]
    for x in np.arange(0.02, 7.9, pitch):  # the south and north rows
        parts += [_box(x, x + 0.08, f, f + 0.9, 0.02, 0.1), _box(x, x + 0.08, f, f + 0.9, 5.9, 5.98)]
    for z in np.arange(0.02 + pitch, 5.9, pitch):  # the east row
        parts.append(_box(7.9, 7.98, f, f + 0.9, z, z + 0.08))
    return _level("baluster_terrace", parts, [_opening((0.0, f, 3.0), _W, 5.8)])


def chained_posts_end(chain: float = 0.5) -> SampleLevel:
    """Corridor 12 x 2.4 m, both ends open; across the east end a chain 0.03 m thick at ``chain`` m between posts
    0.15 m square and 1 m high at the walls."""
    parts = _corridor(12.0) + [_box(11.7, 11.85, 0.0, 1.0, 0.0, 0.15), _box(11.7, 11.85, 0.0, 1.0, 2.25, 2.4),
                               _box(11.76, 11.79, chain, chain + 0.03, 0.15, 2.25)]
    return _level("chained_posts_end", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4)])


def low_vault_tunnel(spring: float = 1.4, crown: float = 2.4) -> SampleLevel:
    """Tunnel 12 m long over a floor 3 m wide between walls ``spring`` m high; a vault in 0.25 m facets rising to
    ``crown`` m at the middle, spring + (crown - spring)(1 - ((z - 1.5) / 1.5)^2); both ends open where it is
    higher than the agent."""
    zs = np.arange(0.0, 3.001, 0.25)
    ys = spring + (crown - spring) * (1.0 - ((zs - 1.5) / 1.5) ** 2)
    parts = [_box(0.0, 12.0, -SLAB, 0.0, 0.0, 3.0), _box(0.0, 12.0, -SLAB, spring + 0.2, -0.3, 0.0),
             _box(0.0, 12.0, -SLAB, spring + 0.2, 3.0, 3.3)]
    parts += [_hull([[x, y + dy, z] for x in (0.0, 12.0) for z, y in ((za, ya), (zb, yb)) for dy in (0.0, 0.2)])
              for za, ya, zb, yb in zip(zs[:-1], ys[:-1], zs[1:], ys[1:])]
    free = 3.0 * math.sqrt(1.0 - (2.0 - spring) / (crown - spring))  # where the vault is the agent's 2 m high
    return _level("low_vault_tunnel", parts, [_opening((0.0, 0.0, 1.5), _W, free), _opening((12.0, 0.0, 1.5), _E, free)])


def _mitred(centre: list[tuple[float, float]], half: float) -> tuple[list[np.ndarray], list[np.ndarray]]:
    """The left and right offsets (plan, metres) at ``half`` m of the polyline ``centre``, mitred at its corners."""
    c = np.asarray(centre, dtype=np.float64)
    d = np.diff(c, axis=0)
    d /= np.linalg.norm(d, axis=1)[:, None]
    n = np.stack([-d[:, 1], d[:, 0]], axis=1)  # left of each leg
    left, right = [c[0] + half * n[0]], [c[0] - half * n[0]]
    for i in range(1, len(c) - 1):
        m = (n[i - 1] + n[i]) / (1.0 + n[i - 1] @ n[i])
        left.append(c[i] + half * m)
        right.append(c[i] - half * m)
    return left + [c[-1] + half * n[-1]], right + [c[-1] - half * n[-1]]


def kinked_bridge(width: float = 2.0, turn_deg: float = 45.0) -> SampleLevel:
    """Footbridge ``width`` m wide over nothing: 6 m east, then 6 m turned ``turn_deg`` to the north, mitred; solid
    parapets 1 m high and 0.1 m thick outside both sides; both ends open."""
    h = width / 2
    a = math.radians(turn_deg)
    end = (6.0 + 6.0 * math.cos(a), h + 6.0 * math.sin(a))
    centre = [(0.0, h), (6.0, h), end]
    left, right = _mitred(centre, h)
    left_out, right_out = _mitred(centre, h + 0.1)
    parts = []
    for i in range(2):
        parts.append(_prism([right[i], right[i + 1], left[i + 1], left[i]], -SLAB, 0.0))
        parts.append(_prism([left[i], left[i + 1], left_out[i + 1], left_out[i]], -SLAB, 1.0))
        parts.append(_prism([right[i], right[i + 1], right_out[i + 1], right_out[i]], -SLAB, 1.0))
    heading = (math.cos(a), 0.0, math.sin(a))
    return _level("kinked_bridge", parts, [_opening((0.0, 0.0, h), _W, width), _opening((end[0], 0.0, end[1]), heading, width)])


def cleated_gangway(slope_deg: float = 15.0) -> SampleLevel:
    """A pad 3 x 1.6 m open west, a gangway 8 m rising ``slope_deg`` with cleats 0.05 m wide and 0.04 m high every
    0.4 m across it, a pad 3 m long open east; walls 1 m above the surface along both sides."""
    top = 8.0 * math.tan(math.radians(slope_deg))
    profile = [(-3.0, 0.0), (0.0, 0.0), (8.0, top), (11.0, top)]
    parts = []
    for (xa, ya), (xb, yb) in zip(profile[:-1], profile[1:]):
        parts.append(_hull([[x, y + dy, z] for x, y in ((xa, ya), (xb, yb)) for dy in (-SLAB, 0.0) for z in (0.0, 1.6)]))
        parts += [_hull([[x, y + dy, z] for x, y in ((xa, ya), (xb, yb)) for dy in (-SLAB, 1.0) for z in (z0, z0 + 0.1)])
                  for z0 in (-0.1, 1.6)]
    g = top / 8.0
    for x in np.arange(0.4, 7.7, 0.4):  # cleats along the gangway, standing on its slope
        parts.append(_hull([[u, g * u + dy, z] for u in (x, x + 0.05) for dy in (-0.01, 0.04) for z in (0.0, 1.6)]))
    return _level("cleated_gangway", parts, [_opening((-3.0, 0.0, 0.8), _W, 1.6), _opening((11.0, top, 0.8), _E, 1.6)])


def rack_aisles() -> SampleLevel:
    """Room 12 x 8 m, a 1.6 m doorway west; racks 1 m deep and 2.5 m high from x 2 to 10 leave aisles 1.2 m wide;
    a 1.2 m doorway east at the middle aisle's end."""
    parts = _room(12.0, 8.0, {"W": [(3.2, 4.8, 2.2)], "E": [(4.4, 5.6, 2.2)]})
    parts += [_box(2.0, 10.0, 0.0, 2.5, z0, z0 + 1.0) for z0 in (1.2, 3.4, 5.6)]
    return _level("rack_aisles", parts, [_opening((-0.3, 0.0, 4.0), _W, 1.6), _opening((12.3, 0.0, 5.0), _E, 1.2)])


def bridge_gate_towers() -> SampleLevel:
    """Deck 12 x 2.4 m over nothing; at each end a gate: towers 1.5 m square beside the deck (2 m below it to 4 m up)
    and a lintel beam at 2.6-3.2 m over it; parapets 1 m high between the gates."""
    parts = [_box(0.0, 12.0, -SLAB, 0.0, 0.0, 2.4)]
    for x0, x1 in ((0.0, 1.5), (10.5, 12.0)):
        parts += [_box(x0, x1, -2.0, 4.0, -1.5, 0.0), _box(x0, x1, -2.0, 4.0, 2.4, 3.9), _box(x0, x1, 2.6, 3.2, 0.0, 2.4)]
    parts += [_box(1.5, 10.5, -SLAB, 1.0, -0.1, 0.0), _box(1.5, 10.5, -SLAB, 1.0, 2.4, 2.5)]
    return _level("bridge_gate_towers", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, 1.2), _E, 2.4)])


def stile_over_wall() -> SampleLevel:
    """Corridor 12 x 2.4 m, both ends open; across its middle a wall 1.2 m high and 0.3 m thick with three 0.3 m steps
    (treads 0.3 m) up to it and down from it, across the full width."""
    parts = _corridor(12.0) + [_box(5.85, 6.15, 0.0, 1.2, 0.0, 2.4)]
    for i in range(3):
        parts += [_box(4.95 + 0.3 * i, 5.25 + 0.3 * i, 0.0, 0.3 * (i + 1), 0.0, 2.4),
                  _box(6.75 - 0.3 * i, 7.05 - 0.3 * i, 0.0, 0.3 * (i + 1), 0.0, 2.4)]
    return _level("stile_over_wall", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, 1.2), _E, 2.4)])


def plank_bridge_gaps(gap: float = 0.06, planks: int = 33) -> SampleLevel:
    """A bridge 1.8 m wide of ``planks`` planks 0.25 m wide and 0.1 m thick, ``gap`` m apart, over nothing, on two
    stringers; solid parapets 1 m high outside its sides; both ends open."""
    pitch = 0.25 + gap
    length = (planks - 1) * pitch + 0.25
    parts = [_box(i * pitch, i * pitch + 0.25, -0.1, 0.0, 0.0, 1.8) for i in range(planks)]
    parts += [_box(0.0, length, -0.4, -0.1, z0, z0 + 0.1) for z0 in (0.0, 1.7)]
    parts += [_box(0.0, length, -0.4, 1.0, -0.1, 0.0), _box(0.0, length, -0.4, 1.0, 1.8, 1.9)]
    return _level("plank_bridge_gaps", parts, [_opening((0.0, 0.0, 0.9), _W, 1.8), _opening((length, 0.0, 0.9), _E, 1.8)])


def fountain_courtyard() -> SampleLevel:
    """Courtyard 12 x 12 m inside 3 m walls, a 2 m gate in the middle of each side; at its centre a basin's rim, a
    ring 1.6-2.0 m in radius and 0.5 m high."""
    gate = (5.0, 7.0, 3.0)
    parts = _room(12.0, 12.0, {side: [gate] for side in "WESN"}) + _arc_band(6.0, 6.0, 1.6, 2.0, 0.0, 360.0, 0.0, 0.5)
    return _level("fountain_courtyard", parts, [_opening((-0.3, 0.0, 6.0), _W, 2.0), _opening((12.3, 0.0, 6.0), _E, 2.0),
                                                _opening((6.0, 0.0, -0.3), _S, 2.0), _opening((6.0, 0.0, 12.3), _N, 2.0)])


def imperial_stair() -> SampleLevel:
    """Hall 10 x 8 m, walls 5 m, a 1.6 m doorway south; against the north wall a landing 3 x 1.5 m 2 m up, two flights
    of ten 0.2 m risers (0.3 m treads, 1.5 m wide) down from it west and east, and a 1.6 m doorway north off the
    landing (lintel 4.2 m) over nothing outside."""
    parts = _room(10.0, 8.0, {"S": [(4.2, 5.8, 2.2)], "N": [(4.2, 5.8, 4.2)]}, height=5.0)
    parts += [_box(3.5, 6.5, 0.0, 2.0, 6.5, 8.0), _box(4.2, 5.8, 0.0, 2.0, 8.0, 8.3)]
    for i in range(10):  # tread i's top 0.2 (i + 1) m up, the top one beside the landing
        parts += [_box(0.5 + 0.3 * i, 0.8 + 0.3 * i, 0.0, 0.2 * (i + 1), 6.5, 8.0),
                  _box(9.2 - 0.3 * i, 9.5 - 0.3 * i, 0.0, 0.2 * (i + 1), 6.5, 8.0)]
    return _level("imperial_stair", parts, [_opening((5.0, 0.0, -0.3), _S, 1.6), _opening((5.0, 2.0, 8.3), _N, 1.6)])


KINDS = kinds_by_name(catwalk_over_hall, baluster_terrace, chained_posts_end, low_vault_tunnel, kinked_bridge,
                      cleated_gangway, rack_aisles, bridge_gate_towers, stile_over_wall, plank_bridge_gaps,
                      fountain_courtyard, imperial_stair)
"""Kind name -> factory of the sixteenth round."""

if __name__ == "__main__":
    sys.exit(_run_kinds(kinds=KINDS, description=__doc__.splitlines()[0]))
