"""A twelfth round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds12.py [--kinds a b] [--configs map_piece map_piece_sampling]
[--yaws 0 22 45] [--detail]``

Twelve kinds no earlier round tried (docs/entry_exit.md, "A twelfth round of piece kinds"); their known
openings were written down before the detector first ran on them. Built, scored and printed as the tenth
round's (``benchmarks/piece_kinds10.py``: its helpers, conventions, agent and table).
"""

from __future__ import annotations

import sys
from functools import partial

import numpy as np
import trimesh
from piece_kinds10 import SLAB, _box, _hull, _room
from piece_kinds10 import _level as _level10
from piece_kinds10 import kinds_by_name, main as _run_kinds

from g2s_plugins.samples import pieces
from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _S, _W

_level = partial(_level10, round_=12)  # the tenth round's, tagged with this round


def _walls(width: float, depth: float, doors: dict[str, list[tuple[float, float, float]]],
           height: float = 3.0) -> list[trimesh.Trimesh]:
    """The walls of :func:`piece_kinds10._room` without its floor slab (the caller lays a floor with a hole or a gap)."""
    gaps = {side: [(a0, a1, 0.0, lintel) for a0, a1, lintel in runs] for side, runs in doors.items()}
    return [_box(*box) for box in pieces._wall_boxes(width, depth, 0.3, gaps, height, 0.0)]


def portcullis_half() -> SampleLevel:
    """Corridor 12 x 2.4 m open at both ends; at its east end, under a beam, a portcullis raised to 1.2 m only."""
    parts = [_box(0.0, 12.0, -SLAB, 0.0, -0.3, 2.7), _box(0.0, 12.0, -SLAB, 3.0, -0.3, 0.0),
             _box(0.0, 12.0, -SLAB, 3.0, 2.4, 2.7), _box(11.7, 12.0, 2.6, 3.0, 0.0, 2.4),
             _box(11.8, 11.88, 1.2, 1.28, 0.0, 2.4)]  # the portcullis' bottom rail
    parts += [_box(11.8, 11.88, 1.2, 2.6, z, z + 0.08) for z in np.arange(0.2, 2.4 - 0.08, 0.48)]
    return _level("portcullis_half", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4)])


def ladder_hole_cellar() -> SampleLevel:
    """Room 8 x 6 m, doorways west and east; a 1.2 m square hole against the east wall over a closed cellar 3 m down,
    a ladder down its east side."""
    hole_x, hole_z = (6.8, 8.0), (4.4, 5.6)
    parts = [_box(-0.3, 8.3, -SLAB, 0.0, -0.3, hole_z[0]), _box(-0.3, 8.3, -SLAB, 0.0, hole_z[1], 6.3),
             _box(-0.3, hole_x[0], -SLAB, 0.0, *hole_z)]
    parts += _walls(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(2.2, 3.8, 2.2)]})
    c = -3.0  # the cellar's floor, clear [5, 8] x [3, 6]; its ceiling the room's slab
    parts += [_box(4.7, 8.3, c - SLAB, c, 2.7, 6.3), _box(4.7, 5.0, c, -SLAB, 2.7, 6.3),
              _box(8.0, 8.3, c, -SLAB, 2.7, 6.3), _box(5.0, 8.0, c, -SLAB, 2.7, 3.0),
              _box(5.0, 8.0, c, -SLAB, 6.0, 6.3)]
    parts += [_box(7.85, 7.9, c, 1.0, z, z + 0.05) for z in (4.6, 5.35)]  # the ladder's stiles
    parts += [_box(7.85, 7.9, y, y + 0.04, 4.65, 5.35) for y in np.arange(c + 0.3, 0.9, 0.3)]  # its rungs
    return _level("ladder_hole_cellar", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((8.3, 0.0, 3.0), _E, 1.6)])


def basement_stair(riser: float = 0.2, steps: int = 10, landing: float = 0.0) -> SampleLevel:
    """Room 8 x 6 m at the ground, a west doorway; east a doorway onto ``steps`` steps down (``riser`` m, 0.3 m
    treads) in a trench, then a landing ``landing`` m deep; the bottom tread's (or the landing's) end is the piece's
    east edge."""
    parts = _room(8.0, 6.0, {"W": [(2.2, 3.8, 3.0)], "E": [(2.2, 3.8, 2.2)]})
    bottom, end = -riser * steps, 8.3 + 0.3 * steps + landing
    for i in range(steps):  # treads 0.3 m deep, tops -riser ... bottom
        parts.append(_box(8.3 + 0.3 * i, 8.6 + 0.3 * i, bottom - SLAB, -riser * (i + 1), 2.2, 3.8))
    if landing:
        parts.append(_box(end - landing, end, bottom - SLAB, bottom, 2.2, 3.8))
    parts += [_box(8.3, end, bottom - SLAB, 1.0, 2.0, 2.2), _box(8.3, end, bottom - SLAB, 1.0, 3.8, 4.0)]  # the trench
    return _level("basement_stair", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((end, bottom, 3.0), _E, 1.6)])


def edge_bend_corridor(width: float = 2.4, depth: float = 6.0) -> SampleLevel:
    """Room 8 x ``depth`` m, a west doorway; east a corridor ``width`` m wide (centred on the room) to a closed end at
    the piece's east edge, where it turns right (south): its south wall open over the last ``width`` m, nothing beyond.
    The room stands out ``(depth - width) / 2`` m beside the mouth."""
    z0, z1, x1 = depth / 2 - width / 2, depth / 2 + width / 2, 14.0
    parts = _room(8.0, depth, {"W": [(depth / 2 - 0.8, depth / 2 + 0.8, 3.0)], "E": [(z0, z1, 3.0)]})
    parts += [_box(8.3, x1 + 0.3, -SLAB, 0.0, z0 - 0.3, z1 + 0.3), _box(8.3, x1 + 0.3, -SLAB, 3.0, z1, z1 + 0.3),
              _box(8.3, x1 - width, -SLAB, 3.0, z0 - 0.3, z0), _box(x1, x1 + 0.3, -SLAB, 3.0, z0 - 0.3, z1)]
    return _level("edge_bend_corridor", parts, [_opening((-0.3, 0.0, depth / 2), _W, 1.6),
                                                _opening((x1 - width / 2, 0.0, z0 - 0.3), _S, width)])


def terrace_step(step: float = 0.3) -> SampleLevel:
    """Room 8 x 6 m, a west doorway; east a doorway whose floor, from the wall's inner face on, is a terrace ``step`` m
    up, 2 m deep beyond the wall and 3 m wide between 1 m walls, open east; an opening within the climb (0.4 m)."""
    parts = _room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(2.2, 3.8, 2.2 + step)]})
    parts += [_box(8.0, 10.3, -SLAB, step, 1.5, 4.5),
              _box(8.3, 10.3, -SLAB, step + 1.0, 1.2, 1.5), _box(8.3, 10.3, -SLAB, step + 1.0, 4.5, 4.8)]
    east = [_opening((10.3, step, 3.0), _E, 3.0)] if step <= 0.4 else []
    return _level(f"terrace_step_{round(step * 100):02d}", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6), *east])


def terrace_step_03() -> SampleLevel:
    """:func:`terrace_step` 0.3 m up: the terrace's end is an opening."""
    return terrace_step(0.3)


def terrace_step_06() -> SampleLevel:
    """:func:`terrace_step` 0.6 m up, over the climb: the room does not reach the terrace."""
    return terrace_step(0.6)


def glass_shopfront() -> SampleLevel:
    """Room 8 x 6 m, a west doorway; the east wall a shopfront: one pane of glass, a single one-sided quad, from the
    floor to 2.6 m over 5 m between the wall's ends, a transom above."""
    parts = _room(8.0, 6.0, {"W": [(2.2, 3.8, 3.0)], "E": [(0.5, 5.5, 2.6)]})
    x, (z0, z1), top = 8.15, (0.5, 5.5), 2.6
    parts.append(trimesh.Trimesh(vertices=[[x, 0.0, z0], [x, 0.0, z1], [x, top, z1], [x, top, z0]],
                                 faces=[[0, 2, 1], [0, 3, 2]], process=False))  # normal +x, facing out
    return _level("glass_shopfront", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6)])


def crevasse_room() -> SampleLevel:
    """Room 10 x 6 m, doorways west and east; a crevasse 1.5 m wide across the whole floor at its middle, nothing
    under it (the walls bridge it)."""
    parts = [_box(-0.3, 4.25, -SLAB, 0.0, -0.3, 6.3), _box(5.75, 10.3, -SLAB, 0.0, -0.3, 6.3)]
    parts += _walls(10.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(2.2, 3.8, 2.2)]})
    return _level("crevasse_room", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((10.3, 0.0, 3.0), _E, 1.6)])


def cave_mouth(seed: int = 0) -> SampleLevel:
    """A cave passage 12 m long in 0.5 m slices: floor +-0.06 m, walls' inner faces 1.1-1.4 m from the axis,
    ceiling 2.6-3.2 m, drawn at random (``seed``); both ends open."""
    rng = np.random.default_rng(seed)
    xs = np.arange(0.0, 12.01, 0.5)
    floor = rng.uniform(-0.06, 0.06, len(xs))
    south, north = -rng.uniform(1.1, 1.4, len(xs)), rng.uniform(1.1, 1.4, len(xs))
    ceiling = rng.uniform(2.6, 3.2, len(xs))
    parts = []
    for a, b in zip(range(len(xs) - 1), range(1, len(xs))):
        ends = ((xs[a], floor[a], south[a], north[a], ceiling[a]), (xs[b], floor[b], south[b], north[b], ceiling[b]))
        parts.append(_hull([[x, y, z] for x, f, s, n, _ in ends for y in (f - SLAB, f) for z in (s - 0.4, n + 0.4)]))
        parts.append(_hull([[x, y, z] for x, f, s, _, c in ends for y in (f - SLAB, c + 0.3) for z in (s - 0.4, s)]))
        parts.append(_hull([[x, y, z] for x, f, _, n, c in ends for y in (f - SLAB, c + 0.3) for z in (n, n + 0.4)]))
        parts.append(_hull([[x, y, z] for x, _, s, n, c in ends for y in (c, c + 0.3) for z in (s - 0.4, n + 0.4)]))
    return _level("cave_mouth", parts, [
        _opening((xs[i], floor[i], 0.5 * (south[i] + north[i])), heading, north[i] - south[i])
        for i, heading in ((0, _W), (-1, _E))])


def lean_to_eaves() -> SampleLevel:
    """Room 8 x 6 m, doorways west (2.2 m lintel) and east (2.1 m); a mono-pitch roof from 3.6 m over the west wall
    down to its underside 2.1 m at eaves 1.2 m past the east wall; nothing reaches it."""

    def roof(x: float) -> float:  # the roof's underside, metres
        return 3.6 - 1.5 * (x + 0.3) / 9.8

    parts = [_box(-0.3, 8.3, -SLAB, 0.0, -0.3, 6.3),
             _box(-0.3, 0.0, -SLAB, 3.6, -0.3, 2.2), _box(-0.3, 0.0, -SLAB, 3.6, 3.8, 6.3),
             _box(-0.3, 0.0, 2.2, 3.6, 2.2, 3.8),
             _box(8.0, 8.3, -SLAB, 2.4, -0.3, 2.2), _box(8.0, 8.3, -SLAB, 2.4, 3.8, 6.3),
             _box(8.0, 8.3, 2.1, 2.4, 2.2, 3.8),
             _hull([[x, y, z] for x in (-0.3, 9.5) for y in (roof(x), roof(x) + 0.2) for z in (-0.3, 6.3)])]
    for z0, z1 in ((-0.3, 0.0), (6.0, 6.3)):
        parts.append(_hull([[x, y, z] for x in (0.0, 8.0) for y in (-SLAB, roof(x) + 0.05) for z in (z0, z1)]))
    return _level("lean_to_eaves", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((8.3, 0.0, 3.0), _E, 1.6)])


def bridge_off_platform() -> SampleLevel:
    """Platform 8 x 8 m 4 m up on a solid block, parapets with a 1.6 m gap west and a 2 m gap east; from the east gap
    a railed deck (1.8 m clear) runs 8 m east over nothing to the piece's east edge."""
    f = 4.0
    parts = [_box(-0.2, 8.2, 0.0, f, -0.2, 8.2),
             _box(-0.2, 0.0, f, f + 1.0, 0.0, 3.2), _box(-0.2, 0.0, f, f + 1.0, 4.8, 8.0),
             _box(8.0, 8.2, f, f + 1.0, 0.0, 3.0), _box(8.0, 8.2, f, f + 1.0, 5.0, 8.0),
             _box(-0.2, 8.2, f, f + 1.0, -0.2, 0.0), _box(-0.2, 8.2, f, f + 1.0, 8.0, 8.2),
             _box(8.2, 16.2, f - 0.3, f, 3.0, 5.0),
             _box(8.2, 16.2, f, f + 1.0, 3.0, 3.1), _box(8.2, 16.2, f, f + 1.0, 4.9, 5.0)]
    return _level("bridge_off_platform", parts, [_opening((-0.2, f, 4.0), _W, 1.6), _opening((16.2, f, 4.0), _E, 1.8)])


def canal_walkways() -> SampleLevel:
    """Tunnel 12 m long, 3.4 m wide and 3 m high inside; a channel 1.0 m wide and deep along its middle (narrower than
    the agent needs), walkways 1.2 m either side; both ends open."""
    parts = [_box(0.0, 12.0, -1.0 - SLAB, 0.0, -0.3, 1.2), _box(0.0, 12.0, -1.0 - SLAB, 0.0, 2.2, 3.7),
             _box(0.0, 12.0, -1.0 - SLAB, -1.0, 1.2, 2.2),
             _box(0.0, 12.0, -1.0 - SLAB, 3.0, -0.3, 0.0), _box(0.0, 12.0, -1.0 - SLAB, 3.0, 3.4, 3.7),
             _box(0.0, 12.0, 3.0, 3.2, -0.3, 3.7)]
    return _level("canal_walkways", parts, [_opening((x, 0.0, z), heading, 1.2) for x, heading in ((0.0, _W), (12.0, _E))
                                            for z in (0.6, 2.8)])


KINDS = kinds_by_name(portcullis_half, ladder_hole_cellar, basement_stair, edge_bend_corridor, terrace_step_03,
                      terrace_step_06, glass_shopfront, crevasse_room, cave_mouth, lean_to_eaves,
                      bridge_off_platform, canal_walkways)
"""Kind name -> factory of the twelfth round."""


if __name__ == "__main__":
    sys.exit(_run_kinds(kinds=KINDS, description=__doc__.splitlines()[0]))
