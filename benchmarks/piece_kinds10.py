"""A tenth round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds10.py [--kinds a b] [--configs map_piece map_piece_sampling]
[--yaws 0 22 45] [--detail] [--one-to-one]``

Twelve piece kinds none of the nine earlier rounds tried (docs/entry_exit.md, "A tenth round of piece
kinds"), each with its known openings written down before the detector first ran on them: where a
designer puts the connectors, on the piece's outer face at the height of the floor the way leaves from,
facing out, as wide as the way. Conventions of the earlier rounds: metres, Y up, X east, Z north; solids
are convex hulls of their corners; floors' tops at their height over slabs 0.2 m thick; walls 0.3 m thick
and 3 m high unless said; designed for the map-piece agent (r 0.4, h 2.0, climb 0.4, slope 60 degrees).

Per kind, preset and yaw (the piece and its openings turned about the vertical axis through the centre
of its bounding box, :func:`g2s_plugins.samples.pieces.turned`) it prints found / missed / other: known
openings with a detected opening (a terminal on the sampling route) within
:data:`~g2s_plugins.samples.pieces.MATCH_DISTANCE` (1.5 m), known ones without, and detected ones farther
than that from every known one; and the largest |found width - known width| over the matched ones.
``--one-to-one`` pairs each known opening with one detected opening at most, so a second one found near it
counts as other. ``--detail`` lists every detected opening (position, width, score). Figures are recorded in
docs/entry_exit.md.
"""

from __future__ import annotations

import argparse
import math
import sys
from collections.abc import Callable

import numpy as np
import trimesh
from scipy.optimize import linear_sum_assignment

from g2s_core import pipeline
from g2s_core.config import PRESETS_DIR, load_config
from g2s_core.errors import G2SError
from g2s_core.mesh import mesh_sha256
from g2s_core.registry import Registry
from g2s_plugins.samples import pieces
from g2s_plugins.samples.levels import SLAB_THICKNESS as SLAB  # the floor slabs' thickness, metres
from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _N, _S, _W


def kinds_by_name(*factories: Callable[[], SampleLevel]) -> dict[str, Callable[[], SampleLevel]]:
    """Each piece-kind factory under its function's name, as a round lists its kinds."""
    return {factory.__name__: factory for factory in factories}


def _hull(points) -> trimesh.Trimesh:
    """The convex hull of (k, 3) corners, metres."""
    return trimesh.convex.convex_hull(np.asarray(points, dtype=np.float64))


def _box(x0: float, x1: float, y0: float, y1: float, z0: float, z1: float) -> trimesh.Trimesh:
    return _hull([[x, y, z] for x in (x0, x1) for y in (y0, y1) for z in (z0, z1)])


def _level(name: str, parts: list[trimesh.Trimesh], openings: list, round_: int = 10) -> SampleLevel:
    """The piece ``name`` made of ``parts`` with its known ``openings``, tagged with the round that added it."""
    mesh = trimesh.util.concatenate(parts)
    mesh.merge_vertices()
    return SampleLevel(name=name, mesh=mesh, openings=tuple(openings), metadata={"round": round_})


def _room(width: float, depth: float, doors: dict[str, list[tuple[float, float, float]]], wall: float = 0.3,
          height: float = 3.0, floor: float = 0.0) -> list[trimesh.Trimesh]:
    """Floor slab and walls round the clear floor [0, width] x [0, depth] at ``floor`` m up.

    ``doors`` maps a side (``"WESN"``) to its gaps ``(a0, a1, lintel)``: the range along the side (z on
    W and E, x on S and N; outer corners included) and the lintel's height above the floor (``height``
    for none).
    """
    gaps = {side: [(a0, a1, 0.0, lintel) for a0, a1, lintel in runs] for side, runs in doors.items()}
    return [_box(-wall, width + wall, floor - SLAB, floor, -wall, depth + wall)] + [
        _box(*box) for box in pieces._wall_boxes(width, depth, wall, gaps, height, floor)]


def portcullis_raised() -> SampleLevel:
    """Corridor 12 x 2.4 m open at both ends; at its east end a portcullis raised to 2.2 m under a beam."""
    parts = [_box(0.0, 12.0, -SLAB, 0.0, -0.3, 2.7), _box(0.0, 12.0, -SLAB, 3.0, -0.3, 0.0),
             _box(0.0, 12.0, -SLAB, 3.0, 2.4, 2.7), _box(11.7, 12.0, 2.6, 3.0, 0.0, 2.4)]
    parts += [_box(11.8, 11.88, 2.2, 2.6, z, z + 0.08) for z in np.arange(0.2, 2.4 - 0.08, 0.48)]
    return _level("portcullis_raised", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, 1.2), _E, 2.4)])


def _arc_band(cx: float, cz: float, r0: float, r1: float, a0: float, a1: float, y0: float, y1: float,
              step_deg: float = 7.5) -> list[trimesh.Trimesh]:
    """A curved wall between radii r0 and r1 about (cx, cz) from angle a0 to a1 (degrees, from +x towards +z)."""
    n = max(1, math.ceil((a1 - a0) / step_deg))
    angles = np.radians(np.linspace(a0, a1, n + 1))
    out = []
    for b0, b1 in zip(angles[:-1], angles[1:]):
        ring = [(cx + r * math.cos(b), cz + r * math.sin(b)) for r in (r0, r1) for b in (b0, b1)]
        out.append(_hull([[x, y, z] for x, z in ring for y in (y0, y1)]))
    return out


def _disc(cx: float, cz: float, r: float, y0: float, y1: float, facets: int = 48) -> trimesh.Trimesh:
    angles = np.arange(facets) * 2 * math.pi / facets
    return _hull([[cx + r * math.cos(a), y, cz + r * math.sin(a)] for a in angles for y in (y0, y1)])


def revolving_drum(r: float = 1.5) -> SampleLevel:
    """Room 8 x 6 m, a west doorway; in the east wall a revolving door's drum (inner radius ``r`` m, at most 2.8),
    wings book-folded."""
    cx, cz = 8.15, 3.0
    parts = _room(8.0, 6.0, {"W": [(2.2, 3.8, 3.0)], "E": [(cz - r, cz + r, 3.0)]})
    parts.append(_disc(cx, cz, r + 0.05, -SLAB, 0.0))
    parts.append(_disc(cx, cz, r + 0.05, 2.4, 2.6))
    for a0, a1 in ((60.0, 120.0), (240.0, 300.0)):
        parts += _arc_band(cx, cz, r, r + 0.05, a0, a1, 0.0, 2.4)
    parts.append(_box(cx - r, cx + r, 0.0, 2.4, cz - 0.075, cz + 0.075))
    chord = 2.0 * r * math.sin(math.radians(60.0))  # of the mouth's 120 degrees
    return _level("revolving_drum", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((cx + r, 0.0, cz), _E, chord)])


def embrasure_wall() -> SampleLevel:
    """Courtyard 12 x 8 m, doorways west and north; south a curtain wall 1.5 m thick with four splayed arrow slits."""
    parts = _room(12.0, 8.0, {"W": [(3.2, 4.8, 3.0)], "N": [(5.2, 6.8, 3.0)], "S": [(-0.3, 12.3, 3.0)]})
    inner, outer = 0.6, 0.05  # half widths of an embrasure at the wall's inner (z 0) and outer (z -1.5) face
    lefts = [(c - inner, c - outer) for c in (2.5, 4.83, 7.17, 9.5)] + [(12.3, 12.3)]
    rights = [(-0.3, -0.3)] + [(c + inner, c + outer) for c in (2.5, 4.83, 7.17, 9.5)]
    parts.append(_box(-0.3, 12.3, -SLAB, 0.0, -1.5, 0.0))
    for (a_in, a_out), (b_in, b_out) in zip(rights, lefts):  # the wall between two embrasures
        parts.append(_hull([[x, y, z] for x, z in ((a_in, 0.0), (a_out, -1.5), (b_in, 0.0), (b_out, -1.5))
                            for y in (-SLAB, 4.0)]))
    parts.append(_box(-0.3, 12.3, 2.5, 4.0, -1.5, 0.0))
    return _level("embrasure_wall", parts, [_opening((-0.3, 0.0, 4.0), _W, 1.6), _opening((6.0, 0.0, 8.3), _N, 1.6)])


def sloped_culvert() -> SampleLevel:
    """Box culvert 12 m long, 2.4 x 2.2 m inside, falling 6 degrees east, a channel along its floor's middle."""
    g = math.tan(math.radians(6.0))

    def strip(z0: float, z1: float, bottom: float, top: float) -> trimesh.Trimesh:
        return _hull([[x, -g * x + y, z] for x in (0.0, 12.0) for y in (bottom, top) for z in (z0, z1)])

    parts = [strip(0.0, 1.0, -SLAB, 0.0), strip(1.4, 2.4, -SLAB, 0.0), strip(1.0, 1.4, -SLAB - 0.15, -0.15),
             strip(-0.3, 0.0, -SLAB, 2.2), strip(2.4, 2.7, -SLAB, 2.2), strip(-0.3, 2.7, 2.2, 2.4)]
    return _level("sloped_culvert", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, -12.0 * g, 1.2), _E, 2.4)])


def ceiling_hatch_room() -> SampleLevel:
    """Room 8 x 6 m, doorways west and east, under a ceiling slab with a 1.2 m hatch and nothing to reach it."""
    parts = _room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(2.2, 3.8, 2.2)]})
    parts += [_box(-0.3, 8.3, 3.0, 3.2, -0.3, 2.4), _box(-0.3, 8.3, 3.0, 3.2, 3.6, 6.3),
              _box(-0.3, 3.4, 3.0, 3.2, 2.4, 3.6), _box(4.6, 8.3, 3.0, 3.2, 2.4, 3.6)]
    return _level("ceiling_hatch_room", parts,
                  [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((8.3, 0.0, 3.0), _E, 1.6)])


def loading_dock() -> SampleLevel:
    """Warehouse 1.2 m up, a dock door onto an apron with a 1.2 m drop to a yard, steps down at its north end."""
    f = 1.2
    parts = _room(10.0, 8.0, {"W": [(3.2, 4.8, 4.0)], "E": [(2.5, 5.5, 3.5)]}, height=4.0, floor=f)
    parts += [_box(-0.3, 10.3, 0.0, f - SLAB, -0.3, 8.3),  # the block under the warehouse
              _box(10.3, 12.3, 0.0, f, 0.0, 8.0),  # the apron
              _box(12.3, 18.3, -SLAB, 0.0, 0.0, 8.0),  # the yard
              _box(10.3, 18.3, -SLAB, f + 2.0, -0.3, 0.0), _box(10.3, 18.3, -SLAB, f + 2.0, 8.0, 8.3)]
    for i in range(5):  # treads 0.3 m deep at 1.0, 0.8, ... 0.2 m, then the yard: six 0.2 m risers
        parts.append(_box(12.3 + 0.3 * i, 12.6 + 0.3 * i, 0.0, f - 0.2 * (i + 1), 6.8, 8.0))
    return _level("loading_dock", parts, [_opening((-0.3, f, 4.0), _W, 1.6), _opening((18.3, 0.0, 4.0), _E, 8.0)])


def window_seat_alcove() -> SampleLevel:
    """Room 8 x 6 m, doorways west and north; east an alcove 0.9 m deep with a 0.35 m seat under a window."""
    parts = _room(8.0, 6.0, {"W": [(2.2, 3.8, 3.0)], "N": [(3.2, 4.8, 3.0)], "E": [(2.1, 3.9, 2.4)]})
    parts += [_box(8.3, 9.2, -SLAB, 0.0, 2.1, 3.9), _box(8.3, 9.5, -SLAB, 2.4, 1.8, 2.1),
              _box(8.3, 9.5, -SLAB, 2.4, 3.9, 4.2), _box(8.3, 9.5, 2.4, 2.6, 1.8, 4.2),
              _box(8.6, 9.2, 0.0, 0.35, 2.1, 3.9),
              _box(9.2, 9.5, -SLAB, 0.8, 2.1, 3.9), _box(9.2, 9.5, 2.2, 2.4, 2.1, 3.9),
              _box(9.2, 9.5, -SLAB, 2.4, 2.1, 2.3), _box(9.2, 9.5, -SLAB, 2.4, 3.7, 3.9)]
    return _level("window_seat_alcove", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((4.0, 0.0, 6.3), _N, 1.6)])


def zigzag_ramp() -> SampleLevel:
    """Three 8 m ramp runs of 8 degrees side by side joined by landings, parapets between; open bottom and top pads."""
    g = math.tan(math.radians(8.0))
    rise = 8.0 * g
    parts = []

    def run(z0: float, z1: float, xa: float, ya: float, xb: float, yb: float, extra: float = 0.0) -> None:
        parts.append(_hull([[x, y + d, z] for x, y in ((xa, ya), (xb, yb)) for d in (-SLAB, extra) for z in (z0, z1)]))

    run(0.0, 1.6, 0.0, 0.0, 8.0, rise)
    run(2.0, 3.6, 8.0, rise, 0.0, 2 * rise)
    run(4.0, 5.6, 0.0, 2 * rise, 8.0, 3 * rise)
    parts += [_box(-1.6, 0.0, -SLAB, 0.0, 0.0, 1.6), _box(8.0, 9.6, rise - SLAB, rise, 0.0, 3.6),
              _box(-1.6, 0.0, 2 * rise - SLAB, 2 * rise, 2.0, 5.6), _box(8.0, 9.6, 3 * rise - SLAB, 3 * rise, 4.0, 5.6)]
    # parapets 1 m over the surface they stand beside: the runs' outer sides, between the runs (over the higher
    # one), round the landings and the pads
    run(-0.2, 0.0, 0.0, 0.0, 8.0, rise, 1.0)
    run(5.6, 5.8, 0.0, 2 * rise, 8.0, 3 * rise, 1.0)
    parts.append(_hull([[x, y, z] for x, ys in ((0.0, (-SLAB, 2 * rise + 1.0)), (8.0, (rise - SLAB, rise + 1.0)))
                        for y in ys for z in (1.6, 2.0)]))
    parts.append(_hull([[x, y, z] for x, ys in ((0.0, (2 * rise - SLAB, 2 * rise + 1.0)),
                                                (8.0, (rise - SLAB, 3 * rise + 1.0))) for y in ys for z in (3.6, 4.0)]))
    parts += [_box(-1.6, 0.0, -SLAB, 1.0, -0.2, 0.0), _box(-1.6, 0.0, -SLAB, 2 * rise + 1.0, 1.6, 2.0),
              _box(8.0, 9.8, rise - SLAB, rise + 1.0, -0.2, 0.0), _box(9.6, 9.8, rise - SLAB, rise + 1.0, 0.0, 3.6),
              _box(8.0, 9.8, rise - SLAB, 3 * rise + 1.0, 3.6, 4.0),
              _box(-1.8, -1.6, 2 * rise - SLAB, 2 * rise + 1.0, 2.0, 5.8),
              _box(-1.8, 0.0, 2 * rise - SLAB, 2 * rise + 1.0, 5.6, 5.8),
              _box(8.0, 9.6, 3 * rise - SLAB, 3 * rise + 1.0, 5.6, 5.8)]
    return _level("zigzag_ramp", parts, [_opening((-1.6, 0.0, 0.8), _W, 1.6), _opening((9.6, 3 * rise, 4.8), _E, 1.6)])


def curved_wall_door() -> SampleLevel:
    """Room whose east wall is an arc (r 8 m about (0, 4)), a doorway flush in the arc at +10 degrees; a west doorway."""
    cz, r, half, step = 4.0, 8.0, math.degrees(0.8 / 8.0), 64.0 / 48
    rim = [(8.3 * math.cos(a), cz + 8.3 * math.sin(a)) for a in np.radians(np.linspace(-32.0, 32.0, 49))]
    ends = [(-0.3, -0.3), (-0.3, 8.3), (7.1, -0.3), (7.1, 8.3)]
    parts = [_hull([[x, y, z] for x, z in ends + rim for y in (-SLAB, 0.0)]),
             _box(-0.3, 0.0, -SLAB, 3.0, -0.3, 3.2), _box(-0.3, 0.0, -SLAB, 3.0, 4.8, 8.3),
             _box(-0.3, 7.1, -SLAB, 3.0, -0.3, 0.0), _box(-0.3, 7.1, -SLAB, 3.0, 8.0, 8.3)]
    parts += _arc_band(0.0, cz, r, r + 0.3, -32.0, 10.0 - half, -SLAB, 3.0, step)
    parts += _arc_band(0.0, cz, r, r + 0.3, 10.0 + half, 32.0, -SLAB, 3.0, step)
    parts += _arc_band(0.0, cz, r, r + 0.3, 10.0 - half, 10.0 + half, 2.2, 3.0, step)
    a = math.radians(10.0)
    return _level("curved_wall_door", parts, [_opening((-0.3, 0.0, 4.0), _W, 1.6),
                                              _opening((8.3 * math.cos(a), 0.0, cz + 8.3 * math.sin(a)),
                                                       (math.cos(a), 0.0, math.sin(a)), 1.6)])


def hedge_maze_border(seed: int = 0) -> SampleLevel:
    """Maze corner 12 x 12 m in hedges 0.9 m thick, faces jittered 0.1 m, gaps 1.2 m in the south and east borders."""
    rng = np.random.default_rng(seed)
    parts = [_box(-0.8, 12.8, -SLAB, 0.0, -0.8, 12.8)]  # the ground, under the hedges' jittered outer faces

    def hedge(x0: float, x1: float, z0: float, z1: float) -> None:
        along_x = (x1 - x0) >= (z1 - z0)
        a0, a1 = (x0, x1) if along_x else (z0, z1)
        cuts = np.linspace(a0, a1, max(1, round((a1 - a0) / 1.5)) + 1)
        for b0, b1 in zip(cuts[:-1], cuts[1:]):
            lo, hi = (z0, z1) if along_x else (x0, x1)
            d = rng.uniform(-0.1, 0.1, 4)
            corners = [(b0, lo + d[0]), (b1, lo + d[1]), (b0, hi + d[2]), (b1, hi + d[3])]
            parts.append(_hull([[u, y, v] if along_x else [v, y, u] for u, v in corners for y in (-SLAB, 2.4)]))

    for x0, x1, z0, z1 in ((-0.9, 2.0, -0.9, 0.0), (3.2, 12.9, -0.9, 0.0), (12.0, 12.9, 0.0, 8.0),
                           (12.0, 12.9, 9.2, 12.9), (-0.9, 12.0, 12.0, 12.9), (-0.9, 0.0, 0.0, 12.0),
                           (0.0, 9.4, 4.0, 4.9), (4.5, 5.4, 6.5, 12.0)):
        hedge(x0, x1, z0, z1)
    return _level("hedge_maze_border", parts, [_opening((2.6, 0.0, -0.9), _S, 1.2), _opening((12.9, 0.0, 8.6), _E, 1.2)])


def high_sill_door() -> SampleLevel:
    """Room 8 x 6 m, doorways west and east under 2.4 m lintels; a 0.25 m sill through the west one's wall."""
    parts = _room(8.0, 6.0, {"W": [(2.2, 3.8, 2.4)], "E": [(2.2, 3.8, 2.4)]})
    parts.append(_box(-0.3, 0.0, -SLAB, 0.25, 2.2, 3.8))
    return _level("high_sill_door", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((8.3, 0.0, 3.0), _E, 1.6)])


def shallow_balcony() -> SampleLevel:
    """Room 8 x 6 m 3 m up on a solid block, a west doorway; east a doorway onto a railed balcony 0.9 m deep."""
    f = 3.0
    parts = _room(8.0, 6.0, {"W": [(2.2, 3.8, 3.0)], "E": [(2.2, 3.8, 2.2)]}, floor=f)
    parts += [_box(-0.3, 8.3, 0.0, f - SLAB, -0.3, 6.3), _box(8.3, 9.3, f - SLAB, f, 1.5, 4.5),
              _box(9.2, 9.3, f, f + 1.0, 1.5, 4.5), _box(8.3, 9.2, f, f + 1.0, 1.5, 1.6),
              _box(8.3, 9.2, f, f + 1.0, 4.4, 4.5)]
    return _level("shallow_balcony", parts, [_opening((-0.3, f, 3.0), _W, 1.6)])


KINDS = kinds_by_name(portcullis_raised, revolving_drum, embrasure_wall, sloped_culvert, ceiling_hatch_room,
                      loading_dock, window_seat_alcove, zigzag_ramp, curved_wall_door, hedge_maze_border,
                      high_sill_door, shallow_balcony)
"""Kind name -> factory of the tenth round."""


def score(level: SampleLevel, openings, one_to_one: bool = False) -> tuple[int, int, int, int, float]:
    """(recalled, missed, correct, other, largest width error m) of detected ``openings`` against ``level``'s known ones.

    A known opening is recalled, and a detected one correct, when their midpoints lie within
    :data:`~g2s_plugins.samples.pieces.MATCH_DISTANCE`; the width error is over those pairs. ``one_to_one``: each
    known opening is paired with one detected opening at most, and each detected one with one known one (the most
    pairs within the distance, then the least total distance: scipy's ``linear_sum_assignment``, O((n + m)^3)), so a
    second opening found near a known one counts as other, not correct.
    """
    known = np.array([o.position for o in level.openings], dtype=np.float64).reshape(-1, 3)
    found = np.array([o.position for o in openings], dtype=np.float64).reshape(-1, 3)
    if len(found) == 0:
        return 0, len(known), 0, 0, float("nan")
    distance = np.linalg.norm(found[:, None, :] - known[None, :, :], axis=2)
    near = distance <= pieces.MATCH_DISTANCE
    if one_to_one:
        rows, cols = linear_sum_assignment(np.where(near, distance, 1e6))
        paired = near[rows, cols]
        near = np.zeros_like(near)
        near[rows[paired], cols[paired]] = True
    errors = [abs(openings[i].width - level.openings[j].width) for i, j in zip(*np.nonzero(near))]
    recalled, correct = int(near.any(axis=0).sum()), int(near.any(axis=1).sum())
    return recalled, len(known) - recalled, correct, len(found) - correct, max(errors, default=float("nan"))


def main(argv: list[str] | None = None, kinds: dict[str, Callable[[], SampleLevel]] | None = None,
         description: str | None = None) -> int:
    """Run ``kinds`` (default: the tenth round's) through the presets and print the table; the other rounds' scripts
    call it with theirs."""
    kinds = KINDS if kinds is None else kinds
    parser = argparse.ArgumentParser(description=description or __doc__.splitlines()[0])
    parser.add_argument("--kinds", nargs="+", choices=sorted(kinds), default=list(kinds))
    parser.add_argument("--configs", nargs="+", default=["map_piece", "map_piece_sampling"])
    parser.add_argument("--yaws", type=float, nargs="+", default=[0.0, 22.0, 45.0])
    parser.add_argument("--detail", action="store_true", help="list every detected opening")
    parser.add_argument("--one-to-one", action="store_true",
                        help="pair each known opening with one detected opening at most (see score)")
    args = parser.parse_args(argv)
    registry = Registry.from_entry_points()
    for config in args.configs:
        plan = pipeline.plan(load_config(PRESETS_DIR / f"{config}.yaml"), registry)
        totals = np.zeros(5, dtype=int)  # recalled, missed, correct, other, known
        print(f"{config}: kind, known, per yaw found/missed/other, largest width error m")
        for name in args.kinds:
            cells, worst = [], []
            for yaw in args.yaws:
                level = kinds[name]()
                level = pieces.turned(level, yaw) if yaw else level
                try:
                    result = pipeline.run(plan, registry, level.mesh, name, mesh_sha256(level.mesh))
                except G2SError as error:  # what the user sees instead of openings
                    cells.append("error: " + str(error).split(":")[0][:40])
                    totals += (0, len(level.openings), 0, 0, len(level.openings))
                    continue
                openings = list(result.terminals.openings) if result.terminals is not None else []
                recalled, missed, correct, other, error = score(level, openings, args.one_to_one)
                totals += (recalled, missed, correct, other, len(level.openings))
                worst += [] if math.isnan(error) else [error]
                cells.append(f"{recalled}/{missed}/{other}")
                if args.detail:
                    for o in openings:
                        print(f"    {name} yaw {yaw:g}: at ({o.position[0]:.2f}, {o.position[1]:.2f}, "
                              f"{o.position[2]:.2f}) width {o.width:.2f} score {getattr(o, 'score', float('nan')):.2f}")
            print(f"  {name:20s} {len(kinds[name]().openings)}  {'; '.join(cells)}  {max(worst, default=float('nan')):.2f}")
        recalled, missed, correct, other, known = (int(v) for v in totals)
        print(f"  total: precision {correct}/{correct + other}, recall {recalled}/{known}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
