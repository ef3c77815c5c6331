"""What the later rounds of map-piece kinds build with, in one module (``benchmarks/piece_kinds18.py`` onwards).

The tenth round's solids, room, table and runner (``benchmarks/piece_kinds10.py``), the fourteenth's corridor and
the fifteenth's prism, under the names the later rounds import, the room with two doorways several rounds start
from, and the later rounds' own shared parts (flights, picket fences, corridors meeting at any angles).
Conventions of those rounds: metres, Y up, X east, Z north; solids are convex hulls of their corners; floors' tops
at their height over slabs ``SLAB`` (0.2 m) thick; walls 0.3 m thick and 3 m high unless said.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from functools import partial

import numpy as np
import trimesh

from piece_kinds10 import SLAB as SLAB
from piece_kinds10 import _arc_band as arc_band
from piece_kinds10 import _box as box
from piece_kinds10 import _hull as hull
from piece_kinds10 import _level as _level10
from piece_kinds10 import _room as room
from piece_kinds10 import kinds_by_name as kinds_by_name
from piece_kinds10 import main as run_kinds
from piece_kinds14 import _corridor as corridor
from piece_kinds15 import _prism as prism

from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _W

__all__ = ["SLAB", "ROOM_DOORS", "ROOM_OPENINGS", "arc_band", "arm_junction", "box", "corridor", "flight", "hull",
           "kinds_by_name", "picket_run", "polygon_room", "prism", "room", "round_level", "run_kinds"]

ROOM_DOORS = {"W": [(2.2, 3.8, 2.2)], "E": [(2.2, 3.8, 2.2)]}
"""1.6 m doorways under 2.2 m lintels in the middle of the west and east walls of a room 6 m deep (:func:`room`)."""

ROOM_OPENINGS = [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((8.3, 0.0, 3.0), _E, 1.6)]
""":data:`ROOM_DOORS`' openings in a room 8 x 6 m: at the walls' outer faces, at the floor's height."""


def round_level(round_: int) -> Callable[..., SampleLevel]:
    """The tenth round's piece builder (name, parts, known openings), tagging its pieces with ``round_``."""
    return partial(_level10, round_=round_)


def polygon_room(corners, doors: dict[int, list[tuple[float, float, float]]], wall: float = 0.3,
                 height: float = 3.0) -> tuple[list[trimesh.Trimesh], list[tuple[np.ndarray, np.ndarray, np.ndarray]]]:
    """Floor slab and mitred walls ``wall`` m thick and ``height`` m high round the clear floor whose plan is the convex
    polygon ``corners`` ((k, 2) (x, z) metres, turning from +x towards +z as the rounds' arcs do), floor at 0.

    ``doors`` maps a side's index (side i runs from corner i to corner i + 1) to its gaps ``(s0, s1, lintel)``: metres
    along the side's inner face from corner i, and the lintel's height (``height`` for none). Returns the parts and,
    per side, its inner start point, unit direction and outward unit normal ((2,) each, plan), from which a door's
    outer midpoint is ``start + direction * s + normal * wall``. O(k + doors) solids.
    """
    inner = np.asarray(corners, dtype=np.float64)
    k = len(inner)
    frames = []
    for i in range(k):
        d = inner[(i + 1) % k] - inner[i]
        d = d / np.linalg.norm(d)
        frames.append((inner[i], d, np.array([d[1], -d[0]])))  # outward for corners turning from +x towards +z

    def outer_corner(i: int) -> np.ndarray:  # where the outer faces of sides i - 1 and i meet
        (p, d, n), (q, e, m) = frames[i - 1], frames[i]
        a, b = p + n * wall, q + m * wall
        t = np.linalg.solve(np.column_stack([d, -e]), b - a)[0]
        return a + d * t

    outer = np.array([outer_corner(i) for i in range(k)])
    parts = [prism(outer, -SLAB, 0.0)]
    for i, (p, d, n) in enumerate(frames):
        length = float(np.dot(inner[(i + 1) % k] - p, d))
        a0 = float(np.dot(outer[i] - p, d))  # the outer corners along the side, in the inner face's measure
        a1 = float(np.dot(outer[(i + 1) % k] - p, d))

        def band(s0: float, s1: float, o0: float, o1: float, y0: float, y1: float) -> trimesh.Trimesh:
            return prism([p + d * s0, p + d * s1, p + d * o1 + n * wall, p + d * o0 + n * wall], y0, y1)

        cuts = [(0.0, a0)] + [((s0, s0), (s1, s1)) for s0, s1, _ in sorted(doors.get(i, ()))] + [(length, a1)]
        flat = [cuts[0]] + [c for pair in cuts[1:-1] for c in pair] + [cuts[-1]]
        for (s0, o0), (s1, o1) in zip(flat[0::2], flat[1::2]):
            parts.append(band(s0, s1, o0, o1, -SLAB, height))
        for s0, s1, lintel in doors.get(i, ()):
            if lintel < height:
                parts.append(band(s0, s1, s0, s1, lintel, height))
    return parts, frames


def flight(start: tuple[float, float], direction: tuple[float, float], across: tuple[float, float], steps: int,
           tread: float, riser: float, base: float, solid: bool = True,
           underside: float = 0.3) -> list[trimesh.Trimesh]:
    """A straight flight of ``steps`` boxes rising ``riser`` m each from ``base`` m (the first step's top at
    ``base + riser``), ``tread`` m deep along the unit axis ``direction`` ((1, 0), (-1, 0), (0, 1) or (0, -1) in
    (x, z)) from ``start`` ((x, z) of the first step's back edge on that axis), spanning ``across`` ((lo, hi) on the
    other axis). Each step reaches down to ``base - SLAB`` when ``solid``, else ``underside`` m under its top (a
    flight carried on a sawtooth slab with head room under it). O(steps) solids."""
    (sx, sz), (dx, dz) = start, direction
    out = []
    for i in range(steps):
        top = base + (i + 1) * riser
        bottom = base - SLAB if solid else top - underside
        a0, a1 = sorted((i * tread, (i + 1) * tread))
        if dx:
            x0, x1 = sorted((sx + dx * a0, sx + dx * a1))
            out.append(box(x0, x1, bottom, top, *across))
        else:
            z0, z1 = sorted((sz + dz * a0, sz + dz * a1))
            out.append(box(*across, bottom, top, z0, z1))
    return out


def picket_run(a0: float, a1: float, line: tuple[float, float], along_x: bool, height: float = 1.0,
               picket: float = 0.08, gap: float = 0.08, ground: float = 0.0) -> list[trimesh.Trimesh]:
    """A picket fence along x (``along_x``) or z from ``a0`` to ``a1`` m, its pickets ``picket`` m wide with ``gap``
    m between them over the band ``line`` ((lo, hi) across the fence), from ``ground`` to ``height`` m above it,
    and two rails 0.08 m high (0.2 and 0.75 m up) along the same band. O((a1 - a0) / (picket + gap)) solids."""
    starts = np.arange(a0, a1 - picket + 1e-9, picket + gap)
    spans = [(a, a + picket, ground, ground + height) for a in starts]
    spans += [(a0, a1, ground + y, ground + y + 0.08) for y in (0.2, 0.75)]
    if along_x:
        return [box(s0, s1, y0, y1, *line) for s0, s1, y0, y1 in spans]
    return [box(*line, y0, y1, s0, s1) for s0, s1, y0, y1 in spans]


def arm_junction(angles_deg: list[float], halves: list[float], lengths: list[float], wall: float = 0.3,
                 height: float = 3.0) -> tuple[list[trimesh.Trimesh], list[tuple[np.ndarray, float]]]:
    """Straight corridors ("arms") meeting at the origin, floor at 0: arm k along the plan angle ``angles_deg[k]``
    (degrees from +x towards +z, increasing; less than 180 degrees between neighbours), ``2 * halves[k]`` m wide
    and ``lengths[k]`` m from the origin to its open end, cut square to it; walls ``wall`` m thick and ``height`` m
    high meeting at the inner corners, where the wall lines of neighbouring arms cross. Returns the parts and, per
    arm, its unit axis ((2,) (x, z)) and half width, from which its end's midpoint is ``axis * length``. O(arms)
    solids."""
    axes = [np.array([math.cos(a), math.sin(a)]) for a in np.radians(angles_deg)]

    def left(d: np.ndarray) -> np.ndarray:  # the unit normal on the side of increasing angle
        return np.array([-d[1], d[0]])

    def corner(d: np.ndarray, e: np.ndarray, offset_d: float, offset_e: float) -> np.ndarray:
        """Where the line ``offset_d`` m left of axis ``d`` meets the one ``offset_e`` m right of the next axis ``e``."""
        t = np.linalg.solve(np.column_stack([d, -e]), -left(e) * offset_e - left(d) * offset_d)
        return left(d) * offset_d + d * t[0]

    nxt = list(range(1, len(axes))) + [0]
    inner = [corner(axes[k], axes[j], halves[k], halves[j]) for k, j in enumerate(nxt)]  # between arms k and k + 1
    outer = [corner(axes[k], axes[j], halves[k] + wall, halves[j] + wall) for k, j in enumerate(nxt)]
    parts = [prism(inner, -SLAB, 0.0)]
    for k, (d, half, length) in enumerate(zip(axes, halves, lengths)):
        n = left(d)
        parts.append(prism([inner[k - 1], d * length - n * half, d * length + n * half, inner[k]], -SLAB, 0.0))
        parts.append(prism([inner[k], d * length + n * half, d * length + n * (half + wall), outer[k]], -SLAB, height))
        parts.append(prism([inner[k - 1], d * length - n * half, d * length - n * (half + wall), outer[k - 1]],
                           -SLAB, height))
    return parts, list(zip(axes, halves))
