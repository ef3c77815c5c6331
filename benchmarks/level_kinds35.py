"""Level kinds of the thirty-fifth held-out round (issue 9): generators no preset setting was made on.

Six kinds of shipped game levels that stress what no earlier round did, each a few hundred navmesh polygons with the
presets' agent (radius 0.5 m, height 2 m, climb 0.4 m, slope 45 degrees), seeds 0-2, built from the solids and helpers
of ``benchmarks/level_kinds.py``, ``level_kinds30.py`` and ``level_kinds34.py`` (imported, not copied):
``rack_aisles`` (a warehouse of pallet racks whose aisles are 1.05-1.75 m wide, drawn per aisle, about the agent's
need; one block square to the grid, one turned 20-35 degrees), ``terrace_village`` (terraces on a slope behind
retaining walls at 5-25 degrees to the grid, joined by flights and ramped alleys at arbitrary headings),
``ring_seating`` (an amphitheatre of concentric standing rings whose risers, drawn per ring from 0.30-0.50 m,
straddle the 0.4 m climb, with radial aisles of half steps), ``silo_stair`` (three silos each climbed by a stair of
wedge treads 1.1-1.4 m wide cantilevered from the wall round an open well), ``seam_plaza`` (a pier deck of thin
paving plates with seams of 1-3 cm, laid at 10-40 degrees to the grid over water) and ``kit_flights`` (a block whose
stairs are one kit flight each, placed in storeys 3.3-3.9 m high, so each flight's last step up to its landing is
whatever the kit leaves: 0-0.55 m).

Run: ``.venv/bin/python benchmarks/level_kinds35.py OUT_DIR [--kinds rack_aisles kit_flights] [--seeds 0 1 2]``
writes ``OUT_DIR/<kind>_s<seed>.obj``; ``benchmarks/analysis_quality.py --levels`` takes the kinds' names too."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import trimesh
from level_kinds import _ridged, _Solids, _trunk, _wall_line
from level_kinds import main as write_kinds
from level_kinds30 import _placed, _ridged_strip
from level_kinds34 import _yaw_point, _yawed

CLIMB = 0.4
"""The presets' agent's climb, metres: a step up to it is walked, one over it is a wall."""

LIFT = 0.5
"""Height over its floor of the underside of a body stood on a floor that is not cut under it (a rack on its bottom
beam, a house on a turned terrace, a kiosk on paving plates): Recast reads surfaces, so a floor face inside a closed
body with head room over it would be floor, and an underside within a few of its 0.1 m height cells of the floor
is merged with it (0.15 m was: a floor inside each body, an area apart); 0.5 m of room under the body is no head
room for the agent's 2 m."""


def _rack_block(s: _Solids, rng: np.random.Generator, length: float, rows: int, yaw: float,
                at: np.ndarray) -> list[float]:
    """One block of :func:`rack_aisles` in its own frame (rows along x from -length / 2 to length / 2, stacked along
    z from z = 0), turned by ``yaw`` degrees and moved to plan point ``at`` as :func:`level_kinds34._yawed` does:
    ``rows`` racks 1.2 m deep and 5.5 m high (ridged) with an aisle drawn 1.05-1.75 m wide between each two, each
    rack cut by a cross aisle 2.6 m wide at the middle. Returns the aisles' widths, first to last along z."""
    block = _Solids()
    widths = [float(rng.uniform(1.05, 1.75)) for _ in range(rows - 1)]
    z = 0.0
    for k in range(rows):
        for x0, x1 in ((-length / 2, -1.3), (1.3, length / 2)):
            _ridged_strip(block, np.array([x0, z + 0.6]), np.array([x1, z + 0.6]), 1.2, LIFT, 5.5)
        z += 1.2 + (widths[k] if k < rows - 1 else 0.0)
    for part in block.parts:  # about the block's centre
        part.apply_translation([0.0, 0.0, -z / 2])
    s.parts += _yawed(block.parts, yaw, at)
    return widths


def rack_aisles(seed: int) -> trimesh.Trimesh:
    """A distribution warehouse (a stealth game's, a shooter's warehouse map) 64-72 x 46-52 m, walls 8 m high with two
    doors 4 m wide in its south wall and one in its north wall, under no roof: two blocks of *pallet racks whose aisles
    are 1.05-1.75 m wide, drawn per aisle* (the agent's 1 m and 0.05-0.75 m more: the narrow-aisle racking real
    warehouses have, every aisle open at both ends and at a cross aisle 2.6 m wide across the block's middle), each
    block 8-10 racks (1.2 m deep, 5.5 m high, ridged) 22-26 m long. The west block is square to the grid, the east
    block *turned 20-35 degrees* (either way). South of the blocks a staging strip 6 m deep with pallet stacks
    (ridged, 1.2 x 1.0 x 1.5 m); a forklift (ridged) in the turned block's cross aisle; a loading office (ridged) in
    the north-west corner.

    Expected (written before the first run): for a player one area, every aisle walked end to end (the narrowest,
    1.05 m, leaves 2.5 cm either side of the agent). Rounds 33-34 measured that the navmesh route keeps a passage
    along the grid from about 1.5 m and one at an angle from 1.6-1.7 m (Recast's 0.25 m cells, the radius eroded in
    whole cells), so on the navmesh route the aisles under 1.5 m of the square block and under 1.7 m of the turned
    one may be lost (floor missing, not areas apart: each aisle's ends are on open floor); the sampling route keeps an
    aisle only where a sample lies within the aisle's spare width of its centre line, so it may lose the narrowest
    too. The structure along the staging strip, the blocks' ends and cross aisles, a chain up each aisle kept; never
    through a rack. Traffic highest on the staging strip between the doors and along the cross aisles, lowest in
    the aisles' far halves."""
    rng = np.random.default_rng(seed)
    size_x, size_z = float(rng.uniform(64.0, 72.0)), float(rng.uniform(46.0, 52.0))
    s = _Solids()
    holes: list[tuple[float, float, float, float]] = []
    south = sorted(float(x) for x in rng.uniform(4.0, size_x - 8.0, 2))
    if south[1] - south[0] < 6.0:
        south[1] = min(size_x - 8.0, south[0] + 6.0) if south[0] + 6.0 <= size_x - 8.0 else south[0] - 6.0
    s.wall((0.0, 0.0), (size_x, 0.0), -0.1, 8.0, [(x, 4.0) for x in sorted(south)], thickness=0.3)
    s.wall((0.0, size_z), (size_x, size_z), -0.1, 8.0, [(float(rng.uniform(size_x / 2, size_x - 8.0)), 4.0)],
           thickness=0.3)
    s.wall((0.0, 0.0), (0.0, size_z), -0.1, 8.0, thickness=0.3)
    s.wall((size_x, 0.0), (size_x, size_z), -0.1, 8.0, thickness=0.3)
    staging = 6.0
    west_rows, east_rows = int(rng.integers(8, 11)), int(rng.integers(8, 11))
    west_len, east_len = float(rng.uniform(22.0, 26.0)), float(rng.uniform(22.0, 26.0))
    _rack_block(s, rng, west_len, west_rows, 0.0, np.array([3.0 + west_len / 2, staging + 2.0 + 12.0]))
    yaw = float(rng.choice([-1.0, 1.0]) * rng.uniform(20.0, 35.0))
    east_at = np.array([size_x - 4.0 - 15.0, staging + 2.0 + 15.0])
    _rack_block(s, rng, east_len, east_rows, yaw, east_at)
    truck = _yaw_point(np.array([0.0, 0.0]), yaw, east_at)  # a forklift parked in the turned block's cross aisle
    along = _yaw_point(np.array([0.0, 1.0]), yaw, east_at) - truck
    _ridged_strip(s, truck - along * 1.2, truck + along * 0.6, 1.1, LIFT, 2.1)
    spots: list[tuple[np.ndarray, float]] = []
    for _ in range(int(rng.integers(6, 11))):  # pallet stacks on the staging strip, clear of the doors' fronts
        p = _placed(rng, spots, 2.0, size_x - 2.0, 1.5, staging - 0.5, 1.0,
                    [(x - 1.0, x + 5.0, 0.0, 3.0) for x in south])
        if p is not None:
            holes.append(_ridged(s, p[0] - 0.6, p[0] + 0.6, p[1] - 0.5, p[1] + 0.5, -0.1, 1.5))
    holes.append(_ridged(s, 0.15, 6.0, size_z - 5.0, size_z - 0.15, -0.1, 3.0))  # the loading office
    s.ground(-10.0, size_x + 10.0, -10.0, size_z + 6.0, 0.0, holes)
    return s.mesh()


def _line_z(line: tuple[float, float, float], x: float) -> float:
    """The plan z of retaining wall ``line`` (z at x = 0, slope dz / dx, height of the terrace above it) at ``x``."""
    return line[0] + line[1] * x


def terrace_village(seed: int) -> trimesh.Trimesh:
    """A hill village (an adventure game's Mediterranean town, a shooter's hillside map) on a slope 90-100 m wide
    along x: 5-6 terraces one above another up the slope (z), each 12-18 m deep behind *a retaining wall whose line
    runs 5-25 degrees off the x axis* (either way, drawn per wall, so no two walls are parallel), its face 1.6-2.6 m
    high (over the climb: a wall to a walker), the lowest terrace a street at y = 0. Each retaining wall is crossed by
    *2-3 flights 1.8-2.4 m wide whose headings lie up to 35 degrees off the wall's normal* (risers 0.16-0.18 m, the
    top step running on into the terrace above), and by one *ramped alley* 2.5 m wide climbing along the wall's foot
    at 8-12 degrees, its high end beside the upper terrace's edge. On each terrace 3-5 houses (ridged, 5-9 m by 5-7 m,
    turned with their terrace's wall), a tree or two; a parapet 1 m high along the top terrace's back.

    Expected (written before the first run): one area; each terrace reached from the one below by its flights and
    its alley (a walker never up a retaining wall's face), whatever their angle to Recast's grid. The structure a
    net along each terrace, joined to the next up each flight and alley; traffic highest on the flights and the
    alleys (the only ways up), lowest at the terraces' ends and on the top terrace."""
    rng = np.random.default_rng(seed)
    width = float(rng.uniform(90.0, 100.0))
    n = int(rng.integers(5, 7))
    lines: list[tuple[float, float, float]] = []  # (z at x = 0, dz / dx, height of the terrace above)
    z0, height = 0.0, 0.0
    for _ in range(n - 1):
        slope = math.tan(math.radians(float(rng.choice([-1.0, 1.0]) * rng.uniform(5.0, 25.0))))
        depth = float(rng.uniform(12.0, 18.0))
        # the wall's line, its mean z a terrace's depth past the last one's, its end points kept 9 m or more apart
        mid = (z0 if not lines else _line_z(lines[-1], width / 2)) + depth
        start = mid - slope * width / 2
        if lines:
            start = max(start, max(lines[-1][0] + 9.0, lines[-1][0] + lines[-1][1] * width + 9.0 - slope * width))
        height += float(rng.uniform(1.6, 2.6))
        lines.append((start, slope, height))
    top = max(lines[-1][0], lines[-1][0] + lines[-1][1] * width) + float(rng.uniform(12.0, 18.0))
    s = _Solids()
    floors = [(-12.0, 0.0, 0.0)] + lines + [(top, 0.0, 0.0)]  # the street's front edge, the walls, the back edge
    for k in range(n):  # terrace k: between line k (its front) and line k + 1 (its back), its top at line k's height
        front, back = floors[k], floors[k + 1]
        y = front[2]
        plan = np.array([[0.0, _line_z(front, 0.0)], [width, _line_z(front, width)],
                         [width, _line_z(back, width)], [0.0, _line_z(back, 0.0)]])
        s.prism(plan, -1.0, y)
    parapet = np.array([[0.0, top], [width, top], [width, top + 0.4], [0.0, top + 0.4]])
    s.prism(parapet, lines[-1][2], lines[-1][2] + 1.0)
    for k, line in enumerate(lines):  # the ways up each retaining wall from terrace k (below) to terrace k + 1
        below = floors[k][2]
        rise = line[2] - below
        normal = np.array([-line[1], 1.0]) / math.hypot(line[1], 1.0)  # plan normal of the wall, pointing up the slope
        wall_dir = np.array([normal[1], -normal[0]])  # along the wall, toward +x
        xs = sorted(float(x) for x in rng.uniform(8.0, width - 8.0, int(rng.integers(2, 4))))
        for j in range(1, len(xs)):  # flights 10 m or more apart
            xs[j] = max(xs[j], xs[j - 1] + 10.0)
        xs = [x for x in xs if x < width - 8.0]
        for x in xs:
            w = float(rng.uniform(1.8, 2.4))
            off = math.radians(float(rng.uniform(-35.0, 35.0)))
            heading = math.cos(off) * normal + math.sin(off) * wall_dir
            riser = rise / math.ceil(rise / 0.18)
            run = rise / riser * 0.3
            foot = np.array([x, _line_z(line, x)])
            overrun = w / 2 * abs(math.tan(off)) + 0.3  # the top step runs on into the terrace above
            end = foot + heading * overrun
            s.stairs(end - heading * run, heading, w, below, rise, riser, 0.3)
        # the ramped alley along the wall's foot, from its low end to its high end beside the upper edge
        length = rise / math.tan(math.radians(float(rng.uniform(8.0, 12.0))))
        span = length * math.cos(math.atan(line[1])) + 1.5  # the alley's and its landing's extent along x
        free = [x for x in np.arange(4.0 + span, width - 4.0, 1.0) if all(not x - span - 4.0 < f < x + 4.0 for f in xs)]
        hi_x = float(free[0]) if free else 4.0 + span
        hi = np.array([hi_x - 1.5, _line_z(line, hi_x - 1.5)]) - normal * 1.25
        lo = hi - wall_dir * length
        s.ramp(lo, hi, 2.5, below, line[2], thickness=0.4)
        s.ramp(hi, hi + wall_dir * 1.5, 2.5, line[2], line[2], thickness=0.4)  # a landing at its head
    for k in range(n):  # houses on each terrace, 2 m behind the wall in front of it and turned with it
        front, back = floors[k], floors[k + 1]
        y = front[2]
        along = np.array([1.0, front[1]]) / math.hypot(1.0, front[1])
        inward = np.array([-along[1], along[0]])
        spots: list[tuple[np.ndarray, float]] = []
        for _ in range(int(rng.integers(3, 6))):
            w, d = float(rng.uniform(5.0, 9.0)), float(rng.uniform(4.0, 6.0))
            x = float(rng.uniform(6.0 + w / 2, width - 6.0 - w / 2))
            base = np.array([x, _line_z(front, x)]) + inward * (2.0 + d / 2)
            if _line_z(back, x) - _line_z(front, x) < d + 7.5 or any(np.linalg.norm(base - c) < r + w / 2 + 3.0
                                                                   for c, r in spots):
                continue  # 5.5 m or more left before the wall behind, for its flights and alley
            spots.append((base, w / 2))
            _ridged_strip(s, base - along * w / 2, base + along * w / 2, d, y + LIFT, y + 3.0)
        for _ in range(int(rng.integers(1, 3))):
            x = float(rng.uniform(6.0, width - 6.0))
            p = np.array([x, (_line_z(front, x) + _line_z(back, x)) / 2])
            if all(np.linalg.norm(p - c) > r + 2.0 for c, r in spots):
                _trunk(s, p, 0.3, y - 0.1, y + 4.0)
    return s.mesh()


def ring_seating_plan(seed: int) -> dict:
    """The plan of :func:`ring_seating` for ``seed``: the arena's radius, each ring's (inner radius, tread, riser,
    top) from the arena out, the aisles' angles (radians, 0 at +x, the bowl over 0-pi), and ``joined``: for each riser
    whether the agent steps it (up to :data:`CLIMB`), the arena's first. O(rings)."""
    rng = np.random.default_rng(seed)
    arena = float(rng.uniform(12.0, 15.0))
    rings, r, top = [], arena, 0.0
    for _ in range(int(rng.integers(12, 16))):
        tread, riser = float(rng.uniform(1.6, 2.0)), float(rng.uniform(0.30, 0.50))
        top += riser
        rings.append((r, tread, riser, top))
        r += tread
    aisles = list(np.linspace(0.0, math.pi, int(rng.integers(5, 8)) + 2)[1:-1])
    return {"arena": arena, "rings": rings, "aisles": aisles, "joined": [riser <= CLIMB for *_, riser, _ in rings]}


def _sector(r0: float, r1: float, a0: float, a1: float) -> np.ndarray:
    """The plan (4, 2) of the ring sector between radii r0 < r1 and angles a0 < a1 (radians), its arcs as chords."""
    return np.array([[r0 * math.cos(a0), r0 * math.sin(a0)], [r1 * math.cos(a0), r1 * math.sin(a0)],
                     [r1 * math.cos(a1), r1 * math.sin(a1)], [r0 * math.cos(a1), r0 * math.sin(a1)]])


def ring_seating(seed: int) -> trimesh.Trimesh:
    """An amphitheatre of standing rings (a festival bowl, an arena shooter's colosseum): a round arena 12-15 m in
    radius (y = 0) and, over its north half (angles 0-180 degrees), 12-15 concentric rings of standing room, each 1-1.3
    m deep (room for the agent's 1 m) and *a riser drawn per ring from 0.30-0.50 m above the one inside it*, so some
    risers are under the 0.4 m climb and some over (``ring_seating_plan(seed)["joined"]``); the rings are built of
    chords of 5 degrees or less. 5-7 *radial aisles* 1.8 m wide at even angles climb the rings in half steps (two a
    ring, each half its riser, under the climb), with no rail: from an aisle's steps one steps sideways onto each ring.
    Behind the top ring a promenade 4 m deep at its height with a wall 1.2 m high; the arena holds a stage (ridged,
    8 x 5 m) and south of it a forecourt (y = 0) 30 m deep with two kiosks (ridged).

    Expected (written before the first run, from the plan): one area. Each ring reached from the one inside it
    across their riser where it is under the climb (0.30-0.40 m), else only at the aisles; so a run of rings joined
    by low risers is one walk, and the rings with a high riser on both sides are reached only along an aisle (Recast
    reads heights in cells of a fraction of the climb, so a riser just under 0.4 m may read over it, as the
    football terrace's did). The structure up each aisle as a chain, the rings' runs as arcs between the aisles;
    never straight up a riser over the climb. Traffic highest in the arena and up the aisles nearest the
    forecourt, lowest on the rings' ends at angles 0 and 180 degrees."""
    plan = ring_seating_plan(seed)
    rng = np.random.default_rng(seed + 1000)
    s = _Solids()
    arena, rings, aisles = plan["arena"], plan["rings"], plan["aisles"]
    s.prism(np.array([[math.cos(a), math.sin(a)] for a in np.linspace(0.0, math.pi, 37)]) * arena
            + np.array([0.0, 0.0]), -0.5, 0.0)  # the arena's half disc north of z = 0 (chords)
    outer = rings[-1][0] + rings[-1][1]
    s.box(-outer - 4.0, outer + 4.0, -0.5, 0.0, -30.0, 0.0)  # the forecourt and the arena's south half
    below = 0.0
    for r0, tread, riser, top in rings:
        r1 = r0 + tread
        half = [0.9 / r0 for _ in aisles]  # each aisle's half width as an angle at the ring's inner edge
        cuts = [0.0] + [x for a, h in zip(aisles, half) for x in (a - h, a + h)] + [math.pi]
        for a0, a1 in zip(cuts[0::2], cuts[1::2]):  # the ring's runs between the aisles, chords of 5 degrees or less
            k = max(1, math.ceil((a1 - a0) / math.radians(5.0)))
            for b0, b1 in zip(np.linspace(a0, a1, k + 1)[:-1], np.linspace(a0, a1, k + 1)[1:]):
                s.prism(_sector(r0, r1, float(b0), float(b1)), -0.5, top)
        for a, h in zip(aisles, half):  # the aisle's two half steps in this ring
            s.prism(_sector(r0, r0 + tread / 2, a - h, a + h), -0.5, below + riser / 2)
            s.prism(_sector(r0 + tread / 2, r1, a - h, a + h), -0.5, top)
        below = top
    top = rings[-1][3]
    k = 36
    for b0, b1 in zip(np.linspace(0.0, math.pi, k + 1)[:-1], np.linspace(0.0, math.pi, k + 1)[1:]):
        s.prism(_sector(outer, outer + 4.0, float(b0), float(b1)), -0.5, top)  # the promenade
        s.prism(_sector(outer + 4.0, outer + 4.3, float(b0), float(b1)), -0.5, top + 1.2)  # its wall
    _ridged(s, -4.0, 4.0, arena - 8.0, arena - 3.0, LIFT, 1.2)
    for side in (-1.0, 1.0):
        x = side * float(rng.uniform(8.0, outer - 4.0))
        _ridged(s, x - 2.0, x + 2.0, -22.0, -19.0, LIFT, 2.6)
    return s.mesh()


def silo_stair(seed: int) -> trimesh.Trimesh:
    """A grain terminal (a shooter's industrial map, a survival game's farm): 4 round silos 6-7.5 m in inner radius
    (walls 0.4 m, as 24-sided prisms' pieces) in a row along x in a yard (y = 0), each *climbed by a stair of wedge
    treads 1.1-1.4 m wide (drawn per silo) cantilevered from its inner wall round an open well*: 18-22 treads a
    turn, risers 0.17-0.19 m (drawn per silo), no rail, the well's floor (the silo's floor, y = 0) under it, for 3-4
    turns. Each silo is entered by a door 1.6-1.9 m wide and 2.6 m high just before the stair's foot (under the first
    turn's end, 3 m up); at the stair's top a landing
    (the treads' band, 4 treads long) opens by a door 1.8 m wide onto a gallery 2.4 m wide (railed 1.1 m) that runs
    along x over the silos' tops to the next silo's top landing. Bins and a truck (ridged) in the yard.

    Expected (written before the first run): one area: the yard, each silo's floor, each stair (a chain from floor
    to top, its inner edge a drop over the well and its outer the wall, so the agent's need is its 1 m between a
    ledge and a wall: the 1.1 m treads leave 0.1 m), the gallery joining the tops. Whether the navmesh route keeps a
    tread band of 1.1-1.2 m between a wall and a drop (Recast erodes the radius from both) is open; a band it loses
    parts the silo's top from its floor, and the disconnected-areas warning should name the stair. Traffic highest
    across the yard between the doors and along the gallery, lowest on each silo's floor under the stair. (The
    draft's foot door, under the first treads, and its 3 silos were changed after the first run:
    docs/analysis_quality.md, "A thirty-fifth round of level kinds".)"""
    rng = np.random.default_rng(seed)
    s = _Solids()
    radii = [float(rng.uniform(6.0, 7.5)) for _ in range(4)]
    xs, x = [], 0.0
    for r in radii:  # the silos' centres along x, 4 m between their walls
        xs.append(x + r + 0.4)
        x += 2 * r + 0.8 + 4.0
    reach = max(radii) + 0.4
    tops: list[float] = []
    for cx, r in zip(xs, radii):
        c = np.array([cx, 0.0])
        width = float(rng.uniform(1.1, 1.4))
        per_turn = int(rng.integers(18, 23))
        riser = float(rng.uniform(0.17, 0.19))
        steps = per_turn * int(rng.integers(3, 5))
        step = 2 * math.pi / per_turn
        top_door = math.pi / 2  # the top landing's door faces the gallery (north, +z)
        start = top_door - step * (steps + 2)  # tread i spans start + step * i to start + step * (i + 1)
        for i in range(steps):  # wedge treads 0.25 m thick, cantilevered from the wall (0.05 m into it)
            y = riser * (i + 1)
            s.prism(_sector(r - width, r + 0.05, start + step * i, start + step * (i + 1)) + c, y - 0.25, y)
        top = riser * steps
        tops.append(top)
        for j in range(4):  # the top landing: the band carried on 4 treads' worth at the top's height
            s.prism(_sector(r - width, r + 0.05, start + step * (steps + j), start + step * (steps + j + 1)) + c,
                    top - 0.25, top)
        foot_door = start - 2.5 * step  # under the first turn's last treads, 3 m or more up: head room

        def near(angle: float, door: float) -> bool:
            return abs(math.atan2(math.sin(angle - door), math.cos(angle - door))) < math.radians(8.0)

        k = 24
        for b0, b1 in zip(np.linspace(-math.pi, math.pi, k + 1)[:-1], np.linspace(-math.pi, math.pi, k + 1)[1:]):
            plan = _sector(r, r + 0.4, float(b0), float(b1)) + c
            if near((b0 + b1) / 2, foot_door):  # a door 2.6 m high by the stair's foot, the ground through it
                s.prism(plan, 2.6, top + 3.0)
            elif near((b0 + b1) / 2, top_door):  # a door onto the gallery: the wall under it is its sill
                s.prism(plan, -0.5, top)
                s.prism(plan, top + 2.3, top + 3.0)
            else:
                s.prism(plan, -0.5, top + 3.0)
        ring = np.linspace(0.0, 2 * math.pi, 24, endpoint=False)  # the roof, a cone at 50 degrees: no floor on it
        base = c + (r + 0.4) * np.stack([np.cos(ring), np.sin(ring)], 1)
        s.hull(np.concatenate([np.insert(base, 1, top + 3.0, axis=1),
                               [[c[0], top + 3.0 + (r + 0.4) * math.tan(math.radians(50.0)), c[1]]]]))
    # the gallery: a deck 2.4 m wide along x north of the silos, each silo's landing door joined to it by a bridge
    for cx, r, top in zip(xs, radii, tops):
        s.box(cx - 1.2, cx + 1.2, top - 0.3, top, r + 0.1, reach + 2.4)
    for i in range(len(xs) - 1):
        ya, yb = tops[i], tops[i + 1]
        s.ramp(np.array([xs[i], reach + 1.2]), np.array([xs[i + 1], reach + 1.2]), 2.4, ya, yb, thickness=0.3)
        lo, hi = min(ya, yb), max(ya, yb)
        _wall_line(s, np.array([xs[i] - 1.2, reach + 2.45]), np.array([xs[i + 1] + 1.2, reach + 2.45]), lo - 0.3,
                   hi + 1.1, 0.1, [])
        _wall_line(s, np.array([xs[i] + 1.2, reach - 0.05]), np.array([xs[i + 1] - 1.2, reach - 0.05]), lo - 0.3,
                   hi + 1.1, 0.1, [])
    holes: list[tuple[float, float, float, float]] = []
    spots: list[tuple[np.ndarray, float]] = []
    for _ in range(int(rng.integers(6, 11))):  # bins and a truck in the yard south of the silos
        p = _placed(rng, spots, 0.0, xs[-1] + radii[-1], -reach - 14.0, -reach - 3.0, 1.0, [])
        if p is not None:
            holes.append(_ridged(s, p[0] - 0.8, p[0] + 0.8, p[1] - 0.6, p[1] + 0.6, -0.1, 1.4))
    x = float(rng.uniform(6.0, xs[-1]))
    holes.append(_ridged(s, x - 4.0, x + 4.0, -reach - 22.0, -reach - 19.5, -0.1, 3.2))
    s.ground(-12.0, xs[-1] + radii[-1] + 12.0, -reach - 28.0, reach + 8.0, 0.0, holes)
    return s.mesh()


def seam_plaza(seed: int) -> trimesh.Trimesh:
    """A pier plaza over water (a harbour town's square in an open-world game): a deck 60-70 x 40-46 m, 4 m over the
    water (no floor under it: the seams open onto the drop), *made of thin paving plates 0.08 m thick, 1.0-1.5 m
    square (one size a seed), laid in a grid turned 10-40 degrees to the level's axes, 1-3 cm apart (drawn per seam)
    and each plate's top 0-1 cm off the deck's height* (a modular kit's plates snapped by hand), the plates clipped to
    the deck's rectangle where they cross its edge (a plate is kept whole if its centre is on the deck, so the edge
    is ragged by up to half a plate). The deck is reached from a quay (y = 4, solid, 12 m deep along its south side);
    on it 8-12 planters (ridged, 2 x 1 m), 3-5 kiosks (ridged, 3 x 3 m), lamp posts and a bandstand (a round
    platform 0.35 m high, 6 m across, a step up anywhere). A rail 1.1 m high runs round the deck's other three sides.

    Expected (written before the first run): one area, the whole deck walked: every seam (1-3 cm) is far under
    Recast's 0.25 m cells, so the navmesh route sees one floor; the sampling route probes the ground every 0.25 m
    along its edges, and a probe that falls in a seam meets no floor for 4 m, so it may cut edges across seams (the
    boardwalk of round 27 had seams only along narrow walks; here they cross a wide open floor at an angle every
    1-1.5 m). The structure as on a plain deck: a few nodes across the open floor and round the kiosks; traffic
    highest from the quay across the middle to the bandstand."""
    rng = np.random.default_rng(seed)
    size_x, size_z = float(rng.uniform(60.0, 70.0)), float(rng.uniform(40.0, 46.0))
    plate = float(rng.uniform(1.0, 1.5))
    yaw = math.radians(float(rng.choice([-1.0, 1.0]) * rng.uniform(10.0, 40.0)))
    deck = 4.0
    s = _Solids()
    u, v = np.array([math.cos(yaw), math.sin(yaw)]), np.array([-math.sin(yaw), math.cos(yaw)])
    reach = int(math.hypot(size_x, size_z) / plate) + 2
    centre = np.array([size_x / 2, size_z / 2])
    seams_u = np.cumsum(np.concatenate([[0.0], plate + rng.uniform(0.01, 0.03, 2 * reach)]))
    seams_v = np.cumsum(np.concatenate([[0.0], plate + rng.uniform(0.01, 0.03, 2 * reach)]))
    seams_u -= seams_u[reach]
    seams_v -= seams_v[reach]
    for i in range(2 * reach):
        for j in range(2 * reach):
            a0, b0 = seams_u[i], seams_v[j]
            a1, b1 = a0 + plate, b0 + plate  # the plate; the next starts 1-3 cm on
            mid = centre + u * (a0 + a1) / 2 + v * (b0 + b1) / 2
            if not (0.0 <= mid[0] <= size_x and 0.0 <= mid[1] <= size_z):
                continue
            plan = np.array([centre + u * a + v * b for a, b in ((a0, b0), (a1, b0), (a1, b1), (a0, b1))])
            top = deck + float(rng.uniform(-0.01, 0.01))
            s.prism(plan, top - 0.08, top)
    s.box(-4.0, size_x + 4.0, deck - 2.0, deck, -12.0, -0.0)  # the quay, solid, along the deck's south side
    edge = plate * 0.75  # the rail stands outside the ragged edge (plates reach half a diagonal past the deck's)
    for a, b in (((-edge, 0.0), (-edge, size_z + edge)), ((size_x + edge, 0.0), (size_x + edge, size_z + edge)),
                 ((-edge, size_z + edge), (size_x + edge, size_z + edge))):
        _wall_line(s, np.array(a), np.array(b), deck - 0.5, deck + 1.1, 0.1, [])
    spots: list[tuple[np.ndarray, float]] = []
    band = _placed(rng, spots, 10.0, size_x - 10.0, 12.0, size_z - 6.0, 3.5, [])
    if band is not None:
        ang = np.linspace(0.0, 2 * math.pi, 16, endpoint=False)
        s.prism(band + 3.0 * np.stack([np.cos(ang), np.sin(ang)], 1), deck - 0.3, deck + 0.35)
    for _ in range(int(rng.integers(3, 6))):
        p = _placed(rng, spots, 3.0, size_x - 3.0, 4.0, size_z - 3.0, 2.5, [])
        if p is not None:
            _ridged(s, p[0] - 1.5, p[0] + 1.5, p[1] - 1.5, p[1] + 1.5, deck + LIFT, deck + 2.6)
    for _ in range(int(rng.integers(8, 13))):
        p = _placed(rng, spots, 2.0, size_x - 2.0, 2.0, size_z - 2.0, 1.3, [])
        if p is not None:
            _ridged(s, p[0] - 1.0, p[0] + 1.0, p[1] - 0.5, p[1] + 0.5, deck + LIFT, deck + 0.8)
    for _ in range(int(rng.integers(6, 11))):
        p = _placed(rng, spots, 1.5, size_x - 1.5, 1.5, size_z - 1.5, 0.5, [])
        if p is not None:
            _trunk(s, p, 0.1, deck - 0.1, deck + 4.0)
    return s.mesh()


def kit_flights_plan(seed: int) -> dict:
    """The plan of :func:`kit_flights` for ``seed``: the storeys' floor heights (the ground's first), each stair
    core's kit (risers, riser height, rise from its foot to its last tread), for each core and storey k the step from
    its flight's last tread up to floor k + 1 (``steps[core][k]``; negative where the flight overshoots, its last
    tread over the floor, a step down), ``walked`` (that step within :data:`CLIMB` either way) and ``areas``: the
    groups of storeys joined by walked flights (lists of storey indices, the ground's first). O(cores x storeys)."""
    rng = np.random.default_rng(seed)
    storeys = [float(rng.uniform(3.45, 3.95)) for _ in range(3)]
    floors = [0.0] + [float(y) for y in np.cumsum(storeys)]
    cores = []
    for _ in range(4):
        riser = float(rng.uniform(0.170, 0.180))
        cores.append((20, riser, 20 * riser))
    steps = [[floors[k + 1] - floors[k] - rise for k in range(len(storeys))] for _, _, rise in cores]
    walked = [[-CLIMB <= st <= CLIMB for st in row] for row in steps]
    areas: list[list[int]] = []
    for k in range(len(floors)):
        if k and any(row[k - 1] for row in walked):
            areas[-1].append(k)
        else:
            areas.append([k])
    return {"floors": floors, "cores": cores, "steps": steps, "walked": walked, "areas": areas}


def kit_flights(seed: int) -> trimesh.Trimesh:
    """An office block (a shooter's tower assault, a stealth game's offices) 48-56 x 26-30 m of a ground storey and 3
    upper floors, *each storey 3.45-3.95 m high (drawn per storey)*, climbed by 4 stair cores whose flights are *one
    kit piece each: a straight flight of 20 risers of 0.170-0.180 m (drawn per core), the same piece on every
    storey*, so its last tread lands up to 0.55 m under the floor above (``kit_flights_plan(seed)["steps"]``) or up to
    0.15 m over it. A core is a well 6.4 m wide walled along both sides (open at its ends) holding two lanes 3 m wide:
    the flights run up along x, storey by storey in alternate lanes, each floor open over the flight below it. Each
    storey is an open floor with 6-10 desks (ridged) and a lift core (walled, no floor); the ground storey opens by two
    doors 3 m wide onto a street (y = 0) along its south side; the roof, behind a parapet, is the top floor.

    Expected (written before the first run, from the plan): a flight whose last step is at most the 0.4 m climb joins
    its two storeys; one whose step is over it (18 % of flights on average) is a dead end up to a wall of 0.4-0.55 m
    (a modelling slip a designer fixes by scaling the piece). A storey is cut off only when all four flights up to
    it fail (the plan's ``areas``). Recast reads heights in cells of a fraction of the climb, so a last step of
    0.35-0.4 m may read over it (as the football terrace's risers did). Where a flight fails, the structure should
    not climb it (a dead end, not a way); a disconnected-areas warning, where a storey is cut off, should name a
    flight's top (a step of about 0.4-0.55 m)."""
    plan = kit_flights_plan(seed)
    rng = np.random.default_rng(seed + 1000)
    size_x, size_z = float(rng.uniform(48.0, 56.0)), float(rng.uniform(26.0, 30.0))
    floors = plan["floors"]
    s = _Solids()
    tread = 0.28
    run = 20 * tread
    cores = [(6.0, 3.0), (size_x - 6.0 - run, 3.0), (6.0, size_z - 9.4), (size_x - 6.0 - run, size_z - 9.4)]
    mid = size_x / 2
    shaft = (mid - 2.9, mid + 2.9, size_z / 2 - 1.9, size_z / 2 + 1.9)  # the lift core's inside: no floor on any storey
    s.slab(-10.0, size_x + 10.0, -12.0, size_z + 6.0, 0.0, [shaft], thickness=0.5)  # the ground and the street
    for k, y in enumerate(floors):
        lane = 3.2 * (k % 2)  # this storey's flights' lane in each well; the floor over the last lane is open
        if k > 0:
            below = 3.2 * ((k - 1) % 2)
            s.slab(0.0, size_x, 0.0, size_z, y, [(x0, x0 + run, z0 + below, z0 + below + 3.0) for x0, z0 in cores]
                   + [shaft], thickness=0.3)
        if k == len(floors) - 1:  # the roof's parapet
            for a, b in (((0.0, 0.0), (size_x, 0.0)), ((0.0, size_z), (size_x, size_z)), ((0.0, 0.0), (0.0, size_z)),
                         ((size_x, 0.0), (size_x, size_z))):
                s.wall(a, b, y, y + 1.1, thickness=0.2)
            break
        h = floors[k + 1] - y - 0.3  # the walls stop under the slab above
        doors = [(float(rng.uniform(14.0, mid - 6.0)), 3.0), (float(rng.uniform(mid + 3.0, size_x - 17.0)), 3.0)] \
            if k == 0 else []
        s.wall((0.0, 0.0), (size_x, 0.0), y, y + h, doors, thickness=0.3)
        s.wall((0.0, size_z), (size_x, size_z), y, y + h, thickness=0.3)
        s.wall((0.0, 0.0), (0.0, size_z), y, y + h, thickness=0.3)
        s.wall((size_x, 0.0), (size_x, size_z), y, y + h, thickness=0.3)
        for (x0, z0), (_, riser, rise) in zip(cores, plan["cores"]):
            s.stairs(np.array([x0, z0 + lane + 1.5]), np.array([1.0, 0.0]), 3.0, y, rise, riser, tread)
            for zw in (z0 - 0.2, z0 + 6.2):  # the well's side walls, 1 m past the flight's ends
                s.box(x0 - 1.0, x0 + run + 1.0, y, y + h, zw, zw + 0.2)
        for a, b in (((mid - 3.0, size_z / 2 - 2.0), (mid + 3.0, size_z / 2 - 2.0)),
                     ((mid - 3.0, size_z / 2 + 2.0), (mid + 3.0, size_z / 2 + 2.0)),
                     ((mid - 3.0, size_z / 2 - 2.0), (mid - 3.0, size_z / 2 + 2.0)),
                     ((mid + 3.0, size_z / 2 - 2.0), (mid + 3.0, size_z / 2 + 2.0))):  # the lift core
            s.wall(a, b, y, y + h, thickness=0.2)
        spots: list[tuple[np.ndarray, float]] = []
        keep = [(x0 - 3.0, x0 + run + 3.0, z0 - 1.0, z0 + 7.4) for x0, z0 in cores] \
            + [(mid - 4.5, mid + 4.5, size_z / 2 - 3.5, size_z / 2 + 3.5)]
        for _ in range(int(rng.integers(6, 11))):
            p = _placed(rng, spots, 1.0, size_x - 1.0, 1.5, size_z - 1.5, 1.2, keep)
            if p is not None:
                _ridged(s, p[0] - 0.8, p[0] + 0.8, p[1] - 0.4, p[1] + 0.4, y + LIFT, y + 0.75)
    return s.mesh()


KINDS: dict[str, Callable[[int], trimesh.Trimesh]] = {
    "rack_aisles": rack_aisles, "terrace_village": terrace_village, "ring_seating": ring_seating,
    "silo_stair": silo_stair, "seam_plaza": seam_plaza, "kit_flights": kit_flights,
}
"""Kind name -> generator (seed -> Y-up mesh in metres) of the thirty-fifth round."""


if __name__ == "__main__":
    write_kinds(kinds=KINDS, description=__doc__.splitlines()[0])
