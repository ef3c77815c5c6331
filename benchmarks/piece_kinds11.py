"""An eleventh round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds11.py [--kinds a b] [--configs map_piece map_piece_sampling]
[--yaws 0 22 45] [--detail]``

Twelve piece kinds none of the ten earlier rounds tried (docs/entry_exit.md, "An eleventh round of piece
kinds"), each with its known openings written down before the detector first ran on them. The conventions,
the helpers (walls, boxes, hulls) and the table are the tenth round's (``benchmarks/piece_kinds10.py``):
metres, Y up, X east, Z north; floors' tops at their height over slabs 0.2 m thick; walls 0.3 m thick and 3 m
high unless said; an opening on the piece's outer face at the height of the floor the way leaves from, facing
out, as wide as the way; designed for the map-piece agent (r 0.4, h 2.0, climb 0.4, slope 60 degrees).
Figures are recorded in docs/entry_exit.md.
"""

from __future__ import annotations

import math
import sys

import numpy as np
import trimesh
from piece_kinds10 import SLAB, _box, _hull, _room
from piece_kinds10 import _level as _level10
from piece_kinds10 import kinds_by_name, main as _run_kinds

from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _N, _S, _W


def _level(name: str, parts: list[trimesh.Trimesh], openings: list) -> SampleLevel:
    """The tenth round's :func:`piece_kinds10._level`, tagged with this round."""
    return _level10(name, parts, openings, round_=11)


def screen_wall_door() -> SampleLevel:
    """Room 8 x 6 m, a west doorway; east a 1.2 m doorway behind a dog-leg screen (toilets style): in, south along
    a 1.2 m lobby, round the screen's end."""
    parts = _room(8.0, 6.0, {"W": [(2.2, 3.8, 3.0)], "E": [(2.4, 3.6, 2.2)]})
    parts += [_box(6.65, 6.8, 0.0, 2.2, 1.6, 4.4), _box(6.8, 8.0, 0.0, 2.2, 4.25, 4.4)]
    return _level("screen_wall_door", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((8.3, 0.0, 3.0), _E, 1.2)])


def counter_doorway() -> SampleLevel:
    """Room 8 x 6 m, a west doorway; the east doorway filled by a counter 1.0 m high through the wall."""
    parts = _room(8.0, 6.0, {"W": [(2.2, 3.8, 3.0)], "E": [(2.2, 3.8, 2.2)]})
    parts.append(_box(7.7, 8.3, 0.0, 1.0, 2.2, 3.8))
    return _level("counter_doorway", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6)])


def container_gap(gap: float = 1.2) -> SampleLevel:
    """Two shipping containers (6.06 x 2.44 x 2.59 m) ``gap`` m apart on a slab under them and the gap; ribbed faces."""
    length, width, height = 6.06, 2.44, 2.59
    parts = [_box(0.0, length, -SLAB, 0.0, 0.0, 2 * width + gap),
             _box(0.0, length, 0.0, height, 0.0, width), _box(0.0, length, 0.0, height, width + gap, 2 * width + gap)]
    for x in np.arange(0.15, length - 0.1, 0.3):  # corrugation: ribs 0.1 m wide standing 0.03 m out into the gap
        parts += [_box(x, x + 0.1, 0.0, height, width, width + 0.03),
                  _box(x, x + 0.1, 0.0, height, width + gap - 0.03, width + gap)]
    middle = width + gap / 2
    return _level("container_gap", parts, [_opening((0.0, 0.0, middle), _W, gap), _opening((length, 0.0, middle), _E, gap)])


def kerbed_tunnel(kerb: float = 0.3, sidewalk: float = 1.2) -> SampleLevel:
    """Tunnel 12 m long, 4 m wide inside: a roadway and a ``sidewalk`` m wide on a ``kerb`` m kerb (1.2 and 0.3: within
    the climb); both ends open."""
    parts = [_box(0.0, 12.0, -SLAB, 0.0, -0.3, 4.3), _box(0.0, 12.0, 0.0, kerb, 4.0 - sidewalk, 4.0),
             _box(0.0, 12.0, -SLAB, 3.2, -0.3, 0.0), _box(0.0, 12.0, -SLAB, 3.2, 4.0, 4.3),
             _box(0.0, 12.0, 3.2, 3.4, -0.3, 4.3)]
    return _level("kerbed_tunnel", parts, [_opening((0.0, 0.0, 2.0), _W, 4.0), _opening((12.0, 0.0, 2.0), _E, 4.0)])


def low_lintel_door(lintel: float = 1.85) -> SampleLevel:
    """Room 8 x 6 m: a west doorway under a 2.1 m lintel, an east one under ``lintel`` m (an opening from the agent's
    2 m)."""
    parts = _room(8.0, 6.0, {"W": [(2.2, 3.8, 2.1)], "E": [(2.2, 3.8, lintel)]})
    east = [_opening((8.3, 0.0, 3.0), _E, 1.6)] if lintel >= 2.0 else []
    return _level("low_lintel_door", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6), *east])


def side_stair_door() -> SampleLevel:
    """Room 8 x 6 m 1 m up on a block, a west doorway; east a doorway onto a landing, steps down south along the
    wall to a pad at the ground whose south end is the piece's edge; railed on their outer sides."""
    f = 1.0
    parts = _room(8.0, 6.0, {"W": [(2.2, 3.8, 3.0)], "E": [(3.4, 5.0, 2.2)]}, floor=f)
    parts += [_box(-0.3, 8.3, 0.0, f - SLAB, -0.3, 6.3),  # the block under the room
              _box(8.3, 9.9, 0.0, f, 3.4, 5.0),  # the landing
              _box(8.3, 9.9, -SLAB, 0.0, -0.3, 2.2)]  # the pad
    for i in range(4):  # treads 0.3 m deep, tops 0.8 ... 0.2 m: five 0.2 m risers from the landing to the pad
        parts.append(_box(8.3, 9.9, 0.0, f - 0.2 * (i + 1), 3.4 - 0.3 * (i + 1), 3.4 - 0.3 * i))
    parts += [_box(8.3, 10.0, f, f + 1.0, 5.0, 5.1), _box(9.9, 10.0, f, f + 1.0, 3.4, 5.0),  # the landing's rails
              _hull([[x, y, z] for x in (9.9, 10.0) for z, ys in ((3.4, (f - 0.2, f + 1.0)), (2.2, (-SLAB, 1.0)))
                     for y in ys]),  # the stair's rail
              _box(9.9, 10.0, -SLAB, 1.0, -0.3, 2.2)]  # the pad's
    return _level("side_stair_door", parts, [_opening((-0.3, f, 3.0), _W, 1.6), _opening((9.1, 0.0, -0.3), _S, 1.6)])


def exterior_gallery() -> SampleLevel:
    """Room 8 x 6 m 3 m up on a block, a west doorway; east a doorway onto a gallery along the facade, open at both
    ends at the piece's south and north faces, a parapet on its outer side, nothing under it."""
    f = 3.0
    parts = _room(8.0, 6.0, {"W": [(2.2, 3.8, 3.0)], "E": [(2.2, 3.8, 2.2)]}, floor=f)
    parts += [_box(-0.3, 8.3, 0.0, f - SLAB, -0.3, 6.3), _box(8.3, 10.0, f - SLAB, f, -0.3, 6.3),
              _box(9.9, 10.0, f, f + 1.0, -0.3, 6.3)]
    return _level("exterior_gallery", parts, [_opening((-0.3, f, 3.0), _W, 1.6), _opening((9.1, f, -0.3), _S, 1.6),
                                              _opening((9.1, f, 6.3), _N, 1.6)])


def turnstile_line() -> SampleLevel:
    """Yard 10 x 8 m, a north doorway; in the south wall a line of turnstiles (four 0.55 m lanes between 1 m
    cabinets, arms across them) and a 1.2 m gate."""
    parts = _room(10.0, 8.0, {"N": [(4.2, 5.8, 3.0)], "S": [(1.0, 5.9, 3.0)]})
    cabinets = [1.0 + 0.85 * i for i in range(5)]  # west sides: 0.3 m cabinets with 0.55 m lanes between
    parts += [_box(x, x + 0.3, 0.0, 1.0, -0.3, 0.9) for x in cabinets]
    parts += [_box(x + 0.3, x + 0.85, 0.88, 0.92, 0.28, 0.32) for x in cabinets[:-1]]  # the arms
    return _level("turnstile_line", parts, [_opening((5.3, 0.0, -0.3), _S, 1.2), _opening((5.0, 0.0, 8.3), _N, 1.6)])


def humped_bridge() -> SampleLevel:
    """A footbridge 12 m long and 2 m wide humped 1.2 m (a circular arc, 20 degrees at its ends), parapets 1 m,
    nothing under it; both ends open at the ground."""
    span, rise, width = 12.0, 1.2, 2.0
    radius = ((span / 2) ** 2 + rise**2) / (2 * rise)
    xs = np.linspace(0.0, span, 25)
    ys = np.sqrt(radius**2 - (xs - span / 2) ** 2) - (radius - rise)
    parts = []
    for (xa, ya), (xb, yb) in zip(zip(xs[:-1], ys[:-1]), zip(xs[1:], ys[1:])):
        for z0, z1, top in ((0.0, width, 0.0), (-0.15, 0.0, 1.0), (width, width + 0.15, 1.0)):
            parts.append(_hull([[x, y + d, z] for x, y in ((xa, ya), (xb, yb)) for d in (-SLAB, top) for z in (z0, z1)]))
    return _level("humped_bridge", parts, [_opening((0.0, 0.0, 1.0), _W, width), _opening((span, 0.0, 1.0), _E, width)])


def tapered_corridor() -> SampleLevel:
    """Corridor 10 m long narrowing from 3.0 m (west end) to 1.2 m (east end) between walls 0.3 m thick; ends open."""
    length, west, east = 10.0, 1.5, 0.6  # half widths
    t = 0.3 * math.hypot(length, west - east) / length  # the walls' thickness across z, 0.3 m square to them
    parts = [_hull([[x, y, z] for x, h in ((0.0, west + t), (length, east + t)) for z in (-h, h) for y in (-SLAB, 0.0)])]
    for sign in (-1.0, 1.0):
        parts.append(_hull([[x, y, sign * z] for x, h in ((0.0, west), (length, east)) for z in (h, h + t)
                            for y in (-SLAB, 3.0)]))
    return _level("tapered_corridor", parts, [_opening((0.0, 0.0, 0.0), _W, 2 * west),
                                              _opening((length, 0.0, 0.0), _E, 2 * east)])


def jettied_storey_door() -> SampleLevel:
    """Room 8 x 6 m, doorways west and east; over it an upper storey projecting 1 m past the east wall (a jetty),
    no way up; no floor beyond the east doorway."""
    parts = _room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(2.2, 3.8, 2.2)]})
    parts += [_box(-0.3, 9.3, 3.0, 3.2, -0.3, 6.3),
              _box(-0.3, 9.3, 3.2, 6.0, -0.3, 0.0), _box(-0.3, 9.3, 3.2, 6.0, 6.0, 6.3),
              _box(-0.3, 0.0, 3.2, 6.0, 0.0, 6.0), _box(9.0, 9.3, 3.2, 6.0, 0.0, 6.0)]
    return _level("jettied_storey_door", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((8.3, 0.0, 3.0), _E, 1.6)])


def open_riser_stair() -> SampleLevel:
    """Room 8 x 6 m, walls 5.4 m, a west doorway at the floor; 14 open treads (0.05 m thick) along the north wall
    up to a landing 3 m up across the east end, from which an east doorway leaves."""
    f = 3.0
    parts = _room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(2.2, 3.8, 5.4)]}, height=5.4)
    parts += [_box(8.0, 8.3, -SLAB, f, 2.2, 3.8), _box(8.0, 8.3, f + 2.2, 5.4, 2.2, 3.8),  # under and over the door
              _box(6.0, 8.0, f - SLAB, f, 0.0, 6.0), _box(6.0, 6.1, f, f + 1.0, 0.0, 4.8)]  # landing, parapet
    for i in range(14):  # tread i's top at 0.2 (i + 1) m, its nose 0.3 (14 - i) m west of the landing
        x1 = 6.0 - 0.3 * (13 - i)
        parts.append(_box(x1 - 0.3, x1, 0.2 * (i + 1) - 0.05, 0.2 * (i + 1), 4.8, 6.0))
    return _level("open_riser_stair", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((8.3, f, 3.0), _E, 1.6)])


KINDS = kinds_by_name(screen_wall_door, counter_doorway, container_gap, kerbed_tunnel, low_lintel_door,
                      side_stair_door, exterior_gallery, turnstile_line, humped_bridge, tapered_corridor,
                      jettied_storey_door, open_riser_stair)
"""Kind name -> factory of the eleventh round."""


if __name__ == "__main__":
    sys.exit(_run_kinds(kinds=KINDS, description=__doc__.splitlines()[0]))
