"""Level kinds of the twenty-ninth held-out round (issue 9): generators no preset setting was made on.

Six kinds of shipped game levels that stress what no earlier round did, each about 400-1,200 navmesh polygons with the
presets' agent (radius 0.5 m, height 2 m, climb 0.4 m, slope 45 degrees), seeds 0-2, built from the solids and
helpers of ``benchmarks/level_kinds.py`` (imported, not copied): ``lava_tubes`` (a cave system of tubes 6 m wide
whose floors climb and fall from one chamber to the next, the floors spanning 6-10 m of height, every floor
uneven), ``cubicle_farm`` (an open-plan office floor of cubicle pods, each cubicle a dead end entered through an opening
1.6-2.0 m wide between partitions 1.5 m high), ``football_terrace`` (a football ground's standing terraces whose steps
rise 0.30-0.38 m, just under the agent's 0.4 m climb, crossed by staggered crush barriers), ``hypostyle_hall`` (a
temple hall of a dense grid of columns whose gaps, 1.2-2.3 m, straddle what the agent's 1 m needs), ``opera_house``
(a horseshoe of small boxes on 3-4 tiers stacked over one another round a void, each box a dead end off a corridor)
and ``dune_sea`` (a desert of crescent dunes whose slip faces stand at 38-52 degrees, about the agent's 45-degree
limit, walked round by their backs and horns).

Run: ``.venv/bin/python benchmarks/level_kinds29.py OUT_DIR [--kinds lava_tubes dune_sea] [--seeds 0 1 2]`` writes
``OUT_DIR/<kind>_s<seed>.obj``; ``benchmarks/analysis_quality.py --levels`` takes the kinds' names too.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import trimesh
from level_kinds import _lid, _paint, _ridged, _Solids, _stair_tower, _terrain, _tiles, _trunk, _well_length
from level_kinds import main as write_kinds
from scipy.sparse.csgraph import minimum_spanning_tree


def lava_tubes(seed: int) -> trimesh.Trimesh:
    """A lava-tube cave system (a survival game's caves, open to the sky through collapsed roofs) on 2 m tiles
    (:func:`level_kinds._tiles`), 96 x 72 tiles (192 x 144 m): 9-12 chambers (ellipses 3-5 tiles in radius, their
    outlines wobbling by a tile) *at several heights*, joined by tubes 3 tiles (6 m) wide along the minimum spanning tree
    of the chambers' centres (no loop: a draft's extra tubes crossed others at other heights), each tube's floor
    climbing or falling 0.12-0.2 m a tile (3.5-6 degrees, mostly up from the first chamber; every tile a flat step, so a
    tile's edge is a step of at most about 0.25 m, under the agent's 0.4 m climb) from one chamber's floor to the
    other's, so the floors span 6-10 m of height. Every floor is uneven: waves of 0.3 m over the whole map (steps of a
    few centimetres tile to tile), 2-4 boulders (0.8-2 m high) in each chamber. The rock round the open tiles rises 6 m
    over the highest floor (ridged: no floor on it), so no tube is walked but along its floor.

    Expected (written before its first run): one area. Traffic highest in the tubes of the tree's trunk and the
    chambers between them, lowest in leaf chambers; a designer expects the structure along each tube's floor, rising
    and falling with it, never through the rock between two tubes or chambers at different heights."""
    rng = np.random.default_rng(seed)
    n, m = 96, 72
    count = int(rng.integers(9, 13))
    centres: list[np.ndarray] = []
    while len(centres) < count:
        c = np.array([rng.integers(9, n - 9), rng.integers(9, m - 9)])
        if all(np.linalg.norm(c - d) > 20.0 for d in centres) or rng.random() < 0.02:
            centres.append(c)
    radii = rng.uniform(3.0, 5.0, (count, 2))
    apart = np.array([[np.linalg.norm(a - b) for b in centres] for a in centres])
    tree = minimum_spanning_tree(apart).tocoo()
    edges = [(int(a), int(b)) for a, b in zip(tree.row, tree.col)]
    heights = np.full(count, np.nan)
    heights[0] = 0.0

    def run(a: int, b: int) -> float:
        """The length (tiles) of the tube from chamber ``a`` to ``b`` outside both chambers' smaller radii."""
        return max(float(apart[a, b] - radii[a].min() - radii[b].min()), 1.0)

    while np.isnan(heights).any():  # each chamber from its tree neighbour, 0.12-0.2 m a tile of tube apart, mostly up
        for a, b in edges:
            for p, q in ((a, b), (b, a)):
                if not np.isnan(heights[p]) and np.isnan(heights[q]):
                    heights[q] = heights[p] + float(rng.choice([-1.0, 1.0], p=[0.3, 0.7]) * rng.uniform(0.12, 0.2)) * run(p, q)
    gi, gj = np.meshgrid(np.arange(n) + 0.5, np.arange(m) + 0.5, indexing="ij")
    waves = rng.normal(size=(3, 4))
    uneven = sum(0.1 * np.sin(gi * (0.1 + 0.1 * abs(w[0])) + w[1] * 3) * np.cos(gj * (0.1 + 0.1 * abs(w[2])) + w[3] * 3)
                 for w in waves)
    floor = np.full((n, m), np.nan)
    for a, b in edges:  # the tubes, each tile at its place along the tube between the chambers' edges
        mask = np.zeros((n, m), dtype=bool)
        _paint(mask, centres[a], centres[b], 1)
        d = (centres[b] - centres[a]).astype(float)
        along = ((gi - centres[a][0] - 0.5) * d[0] + (gj - centres[a][1] - 0.5) * d[1]) / float(np.linalg.norm(d))
        t = np.clip((along - radii[a].min()) / run(a, b), 0.0, 1.0)
        fresh = mask & np.isnan(floor)
        floor[fresh] = (heights[a] + t * (heights[b] - heights[a]))[fresh]
    wobble = rng.uniform(0.0, 2 * math.pi, (count, 3))
    s = _Solids()
    for k, c in enumerate(centres):  # the chambers over the tubes' ends
        angle = np.arctan2(gj - c[1] - 0.5, gi - c[0] - 0.5)
        r = np.hypot((gi - c[0] - 0.5) / radii[k, 0], (gj - c[1] - 0.5) / radii[k, 1])
        inside = r < 1.0 + 0.15 * np.sin(3 * angle + wobble[k, 0]) + 0.1 * np.sin(5 * angle + wobble[k, 1])
        floor[inside] = heights[k]
        for _ in range(int(rng.integers(2, 5))):  # boulders, clear of the chamber's middle
            p = (c + 0.5 + radii[k] * 0.6 * np.array([math.cos(a := float(rng.uniform(0, 2 * math.pi))), math.sin(a)])) * 2.0
            s.rock(rng, p, 0.5, heights[k] + uneven[c[0], c[1]], heights[k] + float(rng.uniform(0.8, 2.0)))
    floor = np.round((floor + uneven) / 0.05) * 0.05  # whole 5 cm steps, so runs of one height merge into boxes
    _tiles(s, floor, 2.0, float(np.nanmax(floor)) + 6.0)
    return s.mesh()


def cubicle_farm(seed: int) -> trimesh.Trimesh:
    """An open-plan office floor (an office shooter's or a stealth level's) 72-80 x 40-46 m under a ceiling 3.2 m up
    (:func:`level_kinds._lid`), walls 0.25 m thick: in its middle pods of cubicles, each pod 2 rows of 3-5 cubicles
    2.8-3.2 m square back to back, behind partitions 1.5 m high and 0.1 m thick (a *low wall* one sees over but does
    not cross), each cubicle entered from the aisle through an opening 1.6-2.0 m wide (a little over the 1.5 m the
    agent's 1 m needs on Recast's cells of 0.25 m) and holding an L of desks 0.75 m high and 0.7 m deep along its back
    and one side. Aisles 1.8-2.4 m wide between pods, a main aisle 3 m wide along x through the middle; along the north
    wall 4-6 meeting rooms 5-7 m wide and 6 m deep (doors 1.6 m, a table 0.75 m high in each), a kitchen bay with a
    counter; the way in a lobby 6 m wide through the south wall from a lift lobby (two lift shafts, walled, no floor).

    Expected (written before the first run): one area (every cubicle's opening over the agent's need; a cubicle cut
    off would be an area apart and named in a warning). Traffic highest on the main aisle and the lobby, then the
    aisles between pods, lowest inside the cubicles (small dead ends of about 5 m2 each) and the meeting rooms; a
    designer expects the structure along the aisles with at most a short leaf or dent into a cubicle, never over a
    partition (1.5 m: a low wall), a desk or through a wall."""
    rng = np.random.default_rng(seed)
    size_x, size_z = float(rng.uniform(72.0, 80.0)), float(rng.uniform(40.0, 46.0))
    lobby = float(rng.uniform(size_x / 2 - 8.0, size_x / 2 + 2.0))
    shafts = [(x, x + 3.0, -7.9, -5.0) for x in (lobby - 6.0, lobby + 9.0)]
    s = _Solids()
    # the floor and the lift lobby's (z from -8 to 0), none inside the shafts (closed boxes 2.2 m high: the sampling
    # route reads the floor inside one, under 2.2 m of head room, as an area apart; a first draft's did)
    s.ground(-0.2, size_x + 0.2, -8.0, size_z + 0.2, 0.0, shafts, thickness=0.3)
    _lid(s, -0.2, size_x + 0.2, -8.0, size_z + 0.2, 3.2)
    s.wall((0.0, 0.0), (size_x, 0.0), 0.0, 3.2, [(lobby, 6.0)], thickness=0.25)
    s.wall((0.0, size_z), (size_x, size_z), 0.0, 3.2, thickness=0.25)
    for x in (0.0, size_x):
        s.wall((x, -8.0), (x, size_z), 0.0, 3.2, thickness=0.25)
    s.wall((0.0, -8.0), (size_x, -8.0), 0.0, 3.2, thickness=0.25)
    for x0, x1, z0, z1 in shafts:  # lift shafts, closed (no floor in them)
        s.box(x0, x1, -0.3, 2.2, z0, z1)
    rooms = int(rng.integers(4, 7))  # meeting rooms along the north wall, then a kitchen bay
    x = 0.0
    for _ in range(rooms):
        width = float(rng.uniform(5.0, 7.0))
        if x + width > size_x - 8.0:
            break
        s.wall((x, size_z - 6.0), (x + width, size_z - 6.0), 0.0, 3.2, [(float(rng.uniform(0.8, width - 2.4)), 1.6)],
               thickness=0.15)
        s.wall((x + width, size_z - 6.0), (x + width, size_z), 0.0, 3.2, thickness=0.15)
        s.box(x + 1.8, x + width - 1.8, 0.0, 0.75, size_z - 3.6, size_z - 2.4)
        x += width
    s.box(x + 1.0, size_x - 1.0, 0.0, 0.9, size_z - 0.8, size_z)  # the kitchen's counter
    main_z = size_z / 2 - 1.5 + float(rng.uniform(-3.0, 3.0))  # the main aisle's south edge (3 m wide)
    for lo, hi in ((2.4, main_z), (main_z + 3.0, size_z - 6.0 - 2.4)):  # the bands of pods south and north of it
        cell = float(rng.uniform(2.8, 3.2))
        x = 2.4
        while True:
            columns = int(rng.integers(3, 6))
            if x + columns * cell > size_x - 2.4:
                columns = int((size_x - 2.4 - x) // cell)
            if columns < 2:
                break
            z = lo
            while z + 2 * cell <= hi:
                _pod(s, rng, x, z, cell, columns)
                z += 2 * cell + float(rng.uniform(1.8, 2.4))
            x += columns * cell + float(rng.uniform(1.8, 2.4))
    return s.mesh()


def _pod(s: _Solids, rng: np.random.Generator, x0: float, z0: float, cell: float, columns: int) -> None:
    """A pod of 2 x ``columns`` cubicles ``cell`` m square from plan corner (x0, z0): partitions 1.5 m high round and
    between them, the south row open to the south aisle and the north row to the north one through openings 1.6-2.0
    m wide (each at a random place along its cubicle's front), an L of desks (0.75 m high, 0.7 m deep) along each
    cubicle's back and one side."""
    x1, zm, z1 = x0 + columns * cell, z0 + cell, z0 + 2 * cell
    s.wall((x0, zm), (x1, zm), 0.0, 1.5, thickness=0.1)  # the spine between the rows
    for x in np.arange(columns + 1) * cell + x0:
        s.wall((float(x), z0), (float(x), z1), 0.0, 1.5, thickness=0.1)
    for front, back, sign in ((z0, zm, 1.0), (z1, zm, -1.0)):
        openings = []
        for c in range(columns):
            width = float(rng.uniform(1.6, 2.0))
            openings.append((c * cell + 0.05 + float(rng.uniform(0.0, cell - 0.1 - width)), width))
            cx0, cx1 = x0 + c * cell + 0.05, x0 + (c + 1) * cell - 0.05
            s.box(cx0, cx1, 0.0, 0.75, *sorted((back - sign * 0.75, back - sign * 0.05)))  # the desk along the back
            side_x = cx0 if rng.random() < 0.5 else cx1 - 0.7
            s.box(side_x, side_x + 0.7, 0.0, 0.75, *sorted((back - sign * 0.75, back - sign * (cell - 1.3))))
        s.wall((x0, front), (x1, front), 0.0, 1.5, openings, thickness=0.1)


def football_terrace(seed: int) -> trimesh.Trimesh:
    """A football ground of standing terraces (a lower-league ground, a hooligan level): a pitch 100-105 x 64-68 m
    (ground at 0) with a strip 4 m wide round it, and on each of its four sides a stand of 14-18 steps *whose risers,
    one height a stand drawn from 0.30-0.38 m, stand just under the agent's 0.4 m climb* (treads 0.7-0.8 m, too
    narrow for the agent alone: a terrace is walked only because its steps are climbed), behind a pitch wall 1.1 m
    high with 2-3 gates 2 m wide onto the strip. Crush barriers (1.05 m high, 0.1 m thick, 3-5 m long, gaps 1.8-2.6 m
    between them, staggered row to row) on every 4th-5th step. Behind each stand's top step a concourse 5 m deep at its
    height, walled 1.1 m at the back; at both ends of each side stand's concourse a flight (0.15 / 0.3 m steps, 2.4 m
    wide) down to the ground outside the stands, which joins the corners (open) between the stands to the pitch's
    strip (the end stands' concourses are reached over their terraces only).

    Expected (written before the first run): one area, every terrace walked all over (each riser under the 0.4 m climb;
    Recast rounds heights to cells of 0.125 m, so a riser over 0.375 m may read as four cells, over its three cells of
    climb, and cut a terrace across: a designer would call that wrong). Traffic highest on the pitch's strip and
    through the gates, the corners and the concourses' flights, lowest in the terraces' top corners and the pitch's
    middle; a designer expects the structure up and down each terrace through the barriers' gaps, never through a
    barrier or over the pitch wall."""
    rng = np.random.default_rng(seed)
    length, width = float(rng.uniform(100.0, 105.0)), float(rng.uniform(64.0, 68.0))
    x0, x1, z0, z1 = -4.0, length + 4.0, -4.0, width + 4.0  # the pitch and its strip
    # each stand: its front line's ends (plan), the unit vector up the terrace, steps, riser, tread
    stands = [(np.array(a), np.array(b), np.array(up), int(rng.integers(14, 19)), float(rng.uniform(0.30, 0.38)),
               float(rng.uniform(0.7, 0.8)))
              for a, b, up in (((x0, z0), (x1, z0), (0.0, -1.0)), ((x1, z1), (x0, z1), (0.0, 1.0)),
                               ((x0, z1), (x0, z0), (-1.0, 0.0)), ((x1, z0), (x1, z1), (1.0, 0.0)))]
    s = _Solids()
    footprints = []  # the stands' and flights' plans: the ground stops under them (Recast would find floor inside)
    for a, b, up, steps, riser, tread in stands:
        along, depth = (b - a) / np.linalg.norm(b - a), steps * tread + 0.2
        corners = [a, b, a + up * (depth + 5.3), b + up * (depth + 5.3)]
        if up[0] == 0.0:  # the side stands' flights (below)
            corners += [end + up * (depth + 2.5 + sign * 1.2) - heading * 2 * steps * riser
                        for end, heading in ((a, along), (b, -along)) for sign in (-1.0, 1.0)]
        footprints.append((*(f(c[0] for c in corners) for f in (min, max)), *(f(c[1] for c in corners) for f in (min, max))))
    s.ground(x0 - 45.0, x1 + 45.0, z0 - 45.0, z1 + 45.0, 0.0, [(p[0], p[1], p[2], p[3]) for p in footprints])
    for a, b, up, steps, riser, tread in stands:
        along, span = (b - a) / np.linalg.norm(b - a), float(np.linalg.norm(b - a))
        s.stairs((a + b) / 2 + up * 0.2, up, span, 0.0, steps * riser, riser, tread)
        top, depth = steps * riser, steps * tread + 0.2
        back = (a + b) / 2 + up * depth
        s.ramp(back, back + up * 5.0, span, top, top, thickness=top + 0.3)  # the concourse, solid to the ground
        wall_line = back + up * 5.1
        s.ramp(wall_line, wall_line + up * 0.2, span, top + 1.1, top + 1.1, thickness=1.1)
        gates = sorted(float(g) for g in rng.uniform(4.0, span - 6.0, int(rng.integers(2, 4))))
        pieces, t = [], 0.0
        for g in gates:  # the pitch wall's solid pieces between the gates
            if g > t + 0.5:
                pieces.append((t, g))
            t = max(t, g + 2.0)
        pieces.append((t, span))
        for p0, p1 in pieces:
            c = a + along * (p0 + p1) / 2 + up * 0.1
            s.ramp(c - along * (p1 - p0) / 2, c + along * (p1 - p0) / 2, 0.2, 1.1, 1.1, thickness=1.1 + 0.3)
        k, shift = int(rng.integers(3, 5)), 0.0
        while k < steps - 1:  # crush barriers on the tread of step k, staggered
            t = shift
            while t < span - 2.0:
                run = float(rng.uniform(3.0, 5.0))
                c = a + along * (t + run / 2) + up * (0.2 + (k + 0.5) * tread)
                y = (k + 1) * riser
                s.ramp(c - along * min(run, span - t) / 2, c + along * min(run, span - t) / 2, 0.1, y + 1.05,
                       y + 1.05, thickness=1.05 + 0.1)
                t += run + float(rng.uniform(1.8, 2.6))
            shift = 2.0 - shift  # the next row's barriers start 2 m along: their gaps fall before this row's runs
            k += int(rng.integers(4, 6))
        if up[0] != 0.0:  # the end stands' concourses are reached from their terraces only
            continue
        for end, heading in ((a, along), (b, -along)):  # flights (0.15 / 0.3 m steps) down from the concourse's ends
            s.stairs(end + up * (depth + 2.5) - heading * 2 * top, heading, 2.4, 0.0, top, 0.15, 0.3)
    return s.mesh()


def hypostyle_hall(seed: int) -> trimesh.Trimesh:
    """An Egyptian temple's hypostyle hall (an adventure game's tomb or temple): a hall 48-56 x 36-42 m under a roof
    9 m up (:func:`level_kinds._lid`) inside walls 0.8 m thick, filled with *a dense grid of columns* (16-sided,
    0.7-0.85 m in radius, 8 m high) on centres 2.9-3.4 m apart along x and 3.2-3.8 m along z, so the gaps between
    neighbours are 1.2-2.0 m across x and 1.5-2.4 m across z, about the 1.5 m the agent's 1 m needs on Recast's cells of
    0.25 m: whether a gap is a way is chance, lane by lane. A processional way 6 m wide along z up the middle between
    two rows of great columns (1.4 m in radius) from a gate 5 m wide in the south wall (off a forecourt 20 m deep with a
    pylon, an obelisk on each side) to a sanctuary: a dais 1.2 m high across the hall's north end reached by a flight 4
    m wide (8 risers of 0.15 m), a shrine (ridged) on it, and side doors 3 m wide in the east and west walls onto a
    walk 4 m wide outside. A few fallen drums (0.8 m high) lie between the columns.

    Expected (written before the first run): one area. Traffic highest along the processional way from the gate to the
    dais and in the forecourt, then along the lanes between columns to the side doors, lowest in the hall's corners; a
    designer expects the structure down the processional way and along the column lanes (walked by a person between
    columns 1.2 m apart, so a lane Recast closes is a way missing), never through a column."""
    rng = np.random.default_rng(seed)
    size_x, size_z = float(rng.uniform(48.0, 56.0)), float(rng.uniform(36.0, 42.0))
    pitch_x, pitch_z = float(rng.uniform(2.9, 3.4)), float(rng.uniform(3.2, 3.8))
    radius, mid = float(rng.uniform(0.7, 0.85)), size_x / 2
    dais = size_z - 6.0  # the dais's south edge
    s = _Solids()
    pylons = [(mid - 12.0, mid - 6.0, -3.0, 0.0), (mid + 6.0, mid + 12.0, -3.0, 0.0)]  # either side of the gate
    s.ground(-6.0, size_x + 6.0, -22.0, size_z + 1.0, 0.0, pylons)
    _lid(s, -0.4, size_x + 0.4, -0.4, size_z + 0.4, 9.0)  # the walls stop 1 m under it (as every solid there)
    s.wall((0.0, 0.0), (size_x, 0.0), 0.0, 8.0, [(mid - 2.5, 5.0)], thickness=0.8)
    s.wall((0.0, size_z), (size_x, size_z), 0.0, 8.0, thickness=0.8)
    door_z = float(rng.uniform(8.0, dais - 6.0))
    for x in (0.0, size_x):
        s.wall((x, 0.0), (x, size_z), 0.0, 8.0, [(door_z, 3.0)], thickness=0.8)
    for x in (mid - 12.0, mid + 6.0):  # the pylon's towers and obelisks
        _ridged(s, x, x + 6.0, -3.0, 0.0, 0.0, 12.0)
        _trunk(s, np.array([x + 3.0, -10.0]), 0.6, 0.0, 10.0)
    s.box(0.5, size_x - 0.5, 0.0, 1.2, dais, size_z - 0.5)
    s.stairs(np.array([mid, dais - 1.6]), np.array([0.0, 1.0]), 4.0, 0.0, 1.2, 0.15, 0.2)
    _ridged(s, mid - 2.0, mid + 2.0, size_z - 4.0, size_z - 1.5, 1.2, 4.0)
    angles = np.linspace(0, 2 * math.pi, 16, endpoint=False)
    ring = np.stack([np.cos(angles), np.sin(angles)], 1)
    for z in np.arange(3.0, dais - 4.0, 4.5):  # the great columns along the way
        for x in (mid - 4.5, mid + 4.5):
            s.prism(np.array([x, z]) + 1.4 * ring, 0.0, 8.0)
    xs = [x for x in np.arange(1.5 + radius, size_x - 1.0 - radius, pitch_x) if abs(x - mid) > 4.5 + 1.4 + radius + 1.5]
    zs = np.arange(1.5 + radius, dais - 1.0 - radius, pitch_z)
    for x in xs:
        for z in zs:
            if abs(z - door_z - 1.5) > 2.5 + radius or 6.0 < x < size_x - 6.0:  # a clear way in from each side door
                s.prism(np.array([x, z]) + radius * ring, 0.0, 8.0)
    for _ in range(int(rng.integers(3, 6))):  # fallen drums between the columns
        x, z = xs[int(rng.integers(len(xs) - 1))] + pitch_x / 2, zs[int(rng.integers(len(zs) - 1))] + pitch_z / 2
        s.prism(np.array([x, z]) + 0.5 * ring, 0.0, 0.8)
    return s.mesh()


def opera_house(seed: int) -> trimesh.Trimesh:
    """An opera house's auditorium (an assassination level, a heist's finale): stalls 22-24 m wide and 26-30 m deep
    (floor at 0; rows of seats 0.85 m high and 0.5 m deep every 0.95 m in two blocks between side aisles 1.6 m and a
    middle aisle 1.8 m wide), a stage 12 m deep 1.1 m up at the south (two flights up from the stalls' front corners),
    and round the other three sides a horseshoe of *small boxes stacked on 3-4 tiers* 3.5 m apart: each tier's boxes
    (2.4-2.8 m wide, 2.6 m deep, partitions to the tier above, a parapet 1 m high over the void) each a dead end
    entered by a door 1.6 m wide off a corridor 2.2 m wide behind them, the corridors of each tier one U. On the
    ground the same U is a foyer round the stalls, entered through two doors 2 m wide in each side and the back. Two
    stair towers (:func:`level_kinds._stair_tower`) behind the U's back corners, a door onto the U on every tier.

    Expected (written before the first run): one area. Traffic highest in the stair towers and the U's back corridor
    between them, then the foyer's doors into the stalls and the stalls' aisles; lowest in the boxes (dead ends of about
    6 m2, one a door) and the stage's back; a designer expects the structure round each tier's U with at most a short
    leaf or dent into a box, never through a partition, from a box down into the stalls or from one tier's box to the
    box over it."""
    rng = np.random.default_rng(seed)
    a, depth, tiers, storey = float(rng.uniform(11.0, 12.0)), float(rng.uniform(26.0, 30.0)), int(rng.integers(3, 5)), 3.5
    band, corridor, front = 2.6, 2.2, 3.0  # the boxes' depth, the corridor's width, the boxes' start from the stage
    outer = a + band + corridor  # the U's outer wall's half-width
    back_out = depth + band + corridor  # the U's back outer wall's z
    s = _Solids()
    s.ground(-outer - 0.5, outer + 0.5, front - 0.2, back_out + 0.4, 0.0, [])
    s.ground(-a, a, 0.0, front - 0.2, 0.0, [])  # the stalls' front, under no wing
    s.box(-a, a, -0.5, 1.1, -12.0, 0.0)  # the stage
    for x in (-a + 1.0, a - 1.0):
        s.stairs(np.array([x, 2.4]), np.array([0.0, -1.0]), 1.6, 0.0, 1.1, 1.1 / 8, 0.3)
    s.wall((-a, -12.0), (a, -12.0), 0.0, 9.0, thickness=0.3)
    for x in (-a, a):
        s.wall((x, -12.0), (x, 0.0), 0.0, 9.0, thickness=0.3)
    for z in np.arange(4.0, depth - 3.0, 0.95):  # the stalls' rows
        for x0, x1 in ((-a + 1.6, -0.9), (0.9, a - 1.6)):
            s.box(x0, x1, 0.0, 0.85, z, z + 0.5)
    tower_x = (-outer + 0.4, outer - 4.4)
    for k in range(tiers + 1):
        y = k * storey
        top = y + storey - 0.3  # the tier above's slab's underside
        if k:
            s.slab(-outer, -a, front, back_out + 0.4, y, [])  # to the towers' landings, under their doors
            s.slab(a, outer, front, back_out + 0.4, y, [])
            s.slab(-a, a, depth, back_out + 0.4, y, [])
        if k == tiers:  # the top: a closed gallery's floor over the last tier, walled
            for x in (-outer, outer):
                s.wall((x, front), (x, back_out + 0.2), y, y + 1.1, thickness=0.2)
            continue
        if k == 0:  # the foyer: the walls round the stalls with their doors
            for x in (-a, a):
                s.wall((x, front), (x, depth), 0.0, top, [(2.0, 2.0), (depth - front - 6.0, 2.0)], thickness=0.2)
            s.wall((-a, depth), (a, depth), 0.0, top, [(a - 5.0, 2.0), (a + 3.0, 2.0)], thickness=0.2)
        else:
            widths = float(rng.uniform(2.4, 2.8))
            for x in (-a, a):  # parapets and the boxes along the sides
                s.wall((x, front), (x, depth), y, y + 1.0, thickness=0.2)
                line = x - band if x < 0 else x + band
                cuts = np.linspace(front, depth + band, max(2, round((depth + band - front) / widths)) + 1)
                for z in cuts[1:-1]:
                    s.wall((min(x, line), float(z)), (max(x, line), float(z)), y, top, thickness=0.15)
                s.wall((line, front), (line, depth + band), y, top,
                       [(float(c0 - front + (c1 - c0 - 1.6) / 2), 1.6) for c0, c1 in zip(cuts[:-1], cuts[1:])],
                       thickness=0.2)
            s.wall((-a, depth), (a, depth), y, y + 1.0, thickness=0.2)  # the back's parapet and boxes
            cuts = np.linspace(-a, a, max(2, round(2 * a / widths)) + 1)
            for x in cuts:
                s.wall((float(x), depth), (float(x), depth + band), y, top, thickness=0.15)
            s.wall((-a - band, depth + band), (a + band, depth + band), y, top,
                   [(float(c0 + a + band + (c1 - c0 - 1.6) / 2), 1.6) for c0, c1 in zip(cuts[:-1], cuts[1:])],
                   thickness=0.2)
        for x in (-outer, outer):  # the U's outer walls
            s.wall((x, front), (x, back_out), y, y + storey, thickness=0.2)
        s.wall((-outer, front), (-a, front), y, y + storey, thickness=0.2)
        s.wall((a, front), (outer, front), y, y + storey, thickness=0.2)
        s.wall((-outer, back_out + 0.2), (outer, back_out + 0.2), y, y + storey,
               [(tx + outer + 1.2, 1.6) for tx in tower_x], thickness=0.4)
    for tx in tower_x:
        s.ground(tx, tx + 4.0, back_out + 0.4, back_out + 0.4 + _well_length(storey), 0.0, [])  # the foot's landing
        _stair_tower(s, tx, back_out + 0.4, 0.0, tiers, tuple(range(tiers + 1)), storey)
    return s.mesh()


def dune_sea(seed: int) -> trimesh.Trimesh:
    """A desert of crescent (barchan) dunes (an open-world desert, a racing game's dune run) on a 1 m grid
    (:func:`level_kinds._terrain`), 210-230 x 150-170 m: 18-24 dunes, each a back rising into the wind (along -x) at
    10-16 degrees for 18-34 m to a crest, then a *slip face at 38-52 degrees* (drawn per dune, so some under and some
    over the agent's 45-degree limit) down to the desert floor, the dune's height falling off across the wind
    (narrowing to horns), on a floor rolling by under 0.5 m. A ruined caravanserai's walls (2.5 m high, 0.6 m thick,
    an L and a straight piece), 30-40 rocks (0.8-2 m high) and 6-10 palms at an oasis pool (no floor, a round hole
    6-8 m across) in the floor.

    Expected (written before the first run): one area (every dune walked round its horns and over its back). Slip faces
    over 45 degrees hold no floor, those under it do (a designer sets the limit and expects it kept); traffic highest
    in the corridors between dunes and round the oasis, lowest on the dunes' crests and the level's corners; a designer
    expects the structure round and over the dunes' backs, never straight up a slip face steeper than 45 degrees."""
    rng = np.random.default_rng(seed)
    size_x, size_z = float(rng.uniform(210.0, 230.0)), float(rng.uniform(150.0, 170.0))
    xs, zs = np.arange(0.0, size_x + 0.5, 1.0), np.arange(0.0, size_z + 0.5, 1.0)
    gx, gz = np.meshgrid(xs, zs, indexing="ij")
    waves = rng.normal(size=(3, 4))
    heights = sum(0.15 * np.sin(gx * (0.02 + 0.02 * abs(w[0])) + w[1] * 3) * np.cos(gz * (0.02 + 0.02 * abs(w[2]))
                                                                                      + w[3] * 3) for w in waves)
    oasis = np.array([float(rng.uniform(20.0, size_x - 20.0)), float(rng.uniform(20.0, size_z - 20.0))])
    pool = float(rng.uniform(3.0, 4.0))
    dunes: list[tuple[float, float, float]] = []
    wanted = int(rng.integers(18, 25))
    for _ in range(400):
        if len(dunes) == wanted:
            break
        back = float(rng.uniform(18.0, 34.0))
        cx, cz = float(rng.uniform(back, size_x - 10.0)), float(rng.uniform(12.0, size_z - 12.0))
        if math.hypot(cx - oasis[0], cz - oasis[1]) < back + 12.0 or any(
                abs(cx - d[0]) < back + 12.0 and abs(cz - d[1]) < 26.0 for d in dunes):
            continue
        dunes.append((cx, cz, back))
        rise, face = math.tan(math.radians(float(rng.uniform(10.0, 16.0)))), math.tan(math.radians(float(rng.uniform(38.0, 52.0))))
        crest = back * rise
        spread = float(rng.uniform(10.0, 14.0))  # the dune's half-width across the wind at its crest
        # the crest line bows downwind toward the horns: x of the crest at offset dz is cx + 0.02 dz^2
        bow = cx + 0.04 * (gz - cz) ** 2
        across = np.clip(1.0 - ((gz - cz) / spread) ** 2, 0.0, None)
        up = crest - rise * np.maximum(bow - gx, 0.0)
        down = crest - face * np.maximum(gx - bow, 0.0)
        dune = np.clip(np.where(gx <= bow, up, down), 0.0, None) * across
        heights = np.maximum(heights, dune)
    cx_cells, cz_cells = (gx[:-1, :-1] + gx[1:, 1:]) / 2, (gz[:-1, :-1] + gz[1:, 1:]) / 2
    keep = np.hypot(cx_cells - oasis[0], cz_cells - oasis[1]) > pool
    s = _Solids()
    _terrain(s, xs, zs, heights, keep)

    def ground_at(x: float, z: float) -> float:
        """The ground's height (m) at the grid point nearest plan point (x, z)."""
        return float(heights[int(round(min(max(x, 0.0), size_x))), int(round(min(max(z, 0.0), size_z)))])

    for k in range(int(rng.integers(6, 11))):  # palms round the pool
        angle = 2 * math.pi * k / 10 + float(rng.uniform(-0.2, 0.2))
        p = oasis + (pool + float(rng.uniform(2.0, 5.0))) * np.array([math.cos(angle), math.sin(angle)])
        _trunk(s, p, 0.25, ground_at(*p) - 0.5, ground_at(*p) + 7.0)
    for _ in range(int(rng.integers(30, 41))):  # rocks on the floor, clear of the pool
        p = np.array([float(rng.uniform(5.0, size_x - 5.0)), float(rng.uniform(5.0, size_z - 5.0))])
        if np.linalg.norm(p - oasis) > pool + 3.0:
            s.rock(rng, p, 0.8, ground_at(*p) - 0.5, ground_at(*p) + float(rng.uniform(0.8, 2.0)))
    wx = float(rng.uniform(10.0, size_x - 40.0))
    wz = 4.0 if oasis[1] > size_z / 2 else size_z - 24.0
    for x0, x1, z0, z1 in ((wx, wx + 20.0, wz, wz + 0.6), (wx, wx + 0.6, wz, wz + 16.0), (wx + 8.0, wx + 26.0, wz + 12.0, wz + 12.6)):
        base = min(ground_at(x0, z0), ground_at(x1, z1)) - 1.0
        s.box(x0, x1, base, max(ground_at(x0, z0), ground_at(x1, z1)) + 2.5, z0, z1)
    return s.mesh()


KINDS: dict[str, Callable[[int], trimesh.Trimesh]] = {
    "lava_tubes": lava_tubes, "cubicle_farm": cubicle_farm, "football_terrace": football_terrace,
    "hypostyle_hall": hypostyle_hall, "opera_house": opera_house, "dune_sea": dune_sea,
}
"""Kind name -> generator (seed -> Y-up mesh in metres) of the twenty-ninth round."""


if __name__ == "__main__":
    write_kinds(kinds=KINDS, description=__doc__.splitlines()[0])
