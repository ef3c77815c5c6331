"""Level kinds of the twenty-sixth held-out round (issue 9): generators no preset setting was made on.

Six kinds of shipped game levels that stress what no earlier round did, each about 400-1,200 navmesh polygons with the
presets' agent (radius 0.5 m, height 2 m, climb 0.4 m, slope 45 degrees), seeds 0-2, built from the solids and
helpers of ``benchmarks/level_kinds.py`` (imported, not copied): ``paintball`` (an open field of hundreds of pieces of
low cover under the climb height among tall bunkers, the same under a half turn), ``holed_mill`` (a derelict mill of
three storeys whose upper floors are holed by dozens of collapses, two stair towers), ``vineyard`` (a valley whose
flanks rise in terraces and risers at 33-42 degrees, walkable all the way up, over a stream crossed by footbridges),
``catwalk_hall`` (a hall with no floor whose walkable surfaces are railed catwalks 1.8 m wide at three heights, two
stair towers), ``double_doors`` (a block of small rooms opening into one another through double doors whose leaves
stand open, half shut or shut) and ``split_decks`` (a car park of two halves offset by half a storey, joined only by
ramps spiralling between them).

Run: ``.venv/bin/python benchmarks/level_kinds26.py OUT_DIR [--kinds paintball vineyard] [--seeds 0 1 2]`` writes
``OUT_DIR/<kind>_s<seed>.obj``; ``benchmarks/analysis_quality.py --levels`` takes the kinds' names too.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import trimesh
from level_kinds import (_car, _doored_wall, _grid_edges, _rail_ring, _random_tree, _ridged, _Solids, _stair_tower,
                         _terrain, _well_length)
from level_kinds import main as write_kinds


def _half_turn(points: np.ndarray, length: float, width: float) -> np.ndarray:
    """Plan points (k, 2) of x, z turned by 180 degrees about the middle of the rectangle [0, length] x [0, width]."""
    return np.array([length, width]) - np.asarray(points, dtype=np.float64)


def _spaced(rect: tuple[float, float, float, float], taken: list[tuple[float, float, float, float]], gap: float) -> bool:
    """Whether the plan rectangle (x0, x1, z0, z1) stays ``gap`` m clear of every rectangle of ``taken``."""
    x0, x1, z0, z1 = rect
    return all(x1 + gap <= o[0] or o[1] + gap <= x0 or z1 + gap <= o[2] or o[3] + gap <= z0 for o in taken)


def paintball(seed: int) -> trimesh.Trimesh:
    """A paintball (speedball) field 140-160 x 100-110 m of flat ground inside a net 3 m high, the same under a half turn
    about its middle: a start pen 10 x 8 m at each end, opened to the field by a gap 3 m wide; 40-50 pairs of tall
    bunkers (pyramids 1.8 m square and 1.7 m high, cans 1.2 m across with a cone from 1.3 to 2.0 m, snakes 4-8 m long
    and 1.2 m wide ridged from 0.9 m), each 3 m clear of every other; and 160-200 pairs of low cover under the
    presets' 0.4 m climb height, which one steps onto and over: logs (0.3-0.4 m thick, 2-4 m long, at any angle, their
    tops 0.25-0.35 m up), tyre stacks (octagons 0.8-1.0 m across, 0.2-0.38 m), pallets (1.2 x 1.0 m, 0.15 m) and
    sandbag lines (3-5 x 0.6 m, 0.35 m), which may touch one another and the bunkers. No top of a bunker is floor (all
    over 45 degrees), and no bunker holds floor under it (less than the agent's height inside).

    Expected (written before the first run): one area. Traffic highest down the middle of the field between the two
    pens' gaps and in the gaps themselves (every way out of a pen), lowest in the pens' back corners and along the net
    at the field's far sides. The low cover changes nothing a designer draws: walkers go straight over it, so the
    structure should run through the low cover as if it were not there, and bend only round the tall bunkers; the
    heat map should be (nearly) the same under the half turn, as the field is."""
    rng = np.random.default_rng(seed)
    length, width = float(rng.uniform(140.0, 160.0)), float(rng.uniform(100.0, 110.0))
    s = _Solids()
    s.box(-1.0, length + 1.0, -0.5, 0.0, -1.0, width + 1.0)
    s.wall((0.0, 0.0), (length, 0.0), 0.0, 3.0, thickness=0.1)
    s.wall((0.0, width), (length, width), 0.0, 3.0, thickness=0.1)
    s.wall((0.0, 0.0), (0.0, width), 0.0, 3.0, thickness=0.1)
    s.wall((length, 0.0), (length, width), 0.0, 3.0, thickness=0.1)
    mid = width / 2
    for x, gate_side in ((10.0, 1), (length - 10.0, -1)):  # each pen's inner wall at x, its gap 3 m wide in the middle
        s.wall((x, mid - 4.0), (x, mid + 4.0), 0.0, 3.0, [(2.5, 3.0)], thickness=0.1)
        for z in (mid - 4.0, mid + 4.0):
            s.wall((min(x, x - 10.0 * gate_side), z), (max(x, x - 10.0 * gate_side), z), 0.0, 3.0, thickness=0.1)
    pens = [(0.0, 12.0, mid - 6.0, mid + 6.0), (length - 12.0, length, mid - 6.0, mid + 6.0)]

    def both(plan: np.ndarray, y0: float, y1: float, apex: np.ndarray | None = None) -> None:
        """A prism over the convex ``plan`` (k, 2) from y0 to y1, with the optional ``apex`` points (j, 3) on top, and
        its copy under the half turn."""
        for points, top in ((plan, apex), (_half_turn(plan, length, width), None if apex is None else np.column_stack(
                [length - apex[:, 0], apex[:, 1], width - apex[:, 2]]))):
            solid = [np.insert(points, 1, y, axis=1) for y in (y0, y1)]
            s.hull(np.concatenate(solid + ([] if top is None else [top])))

    taken: list[tuple[float, float, float, float]] = list(pens)
    pairs, tries = int(rng.integers(40, 51)), 0
    while pairs and tries < 2000:
        tries += 1
        kind = rng.choice(["pyramid", "can", "snake"])
        c = np.array([rng.uniform(14.0, length / 2 + 4.0), rng.uniform(3.0, width - 3.0)])
        long = float(rng.uniform(4.0, 8.0))
        half = {"pyramid": (0.9, 0.9), "can": (0.6, 0.6), "snake": (long / 2, 0.6)}[kind]
        if rng.random() < 0.5 and kind == "snake":
            half = half[::-1]
        rect = (c[0] - half[0], c[0] + half[0], c[1] - half[1], c[1] + half[1])
        mirror = (length - rect[1], length - rect[0], width - rect[3], width - rect[2])
        if not (_spaced(rect, taken, 3.0) and _spaced(mirror, taken + [rect], 3.0)):
            continue
        taken += [rect, mirror]
        pairs -= 1
        if kind == "pyramid":
            both(np.array([[rect[0], rect[2]], [rect[1], rect[2]], [rect[1], rect[3]], [rect[0], rect[3]]]), -0.3, 0.0,
                 np.array([[c[0], 1.7, c[1]]]))
        elif kind == "can":
            ring = c + 0.6 * np.array([[math.cos(a), math.sin(a)] for a in np.arange(8) * math.pi / 4])
            both(ring, -0.3, 1.3, np.array([[c[0], 2.0, c[1]]]))
        else:
            along = 0 if half[0] > half[1] else 1
            ends = np.array([[rect[0], c[1]], [rect[1], c[1]]] if along == 0 else [[c[0], rect[2]], [c[0], rect[3]]])
            ridge = np.insert(ends, 1, 0.9 + 0.6 * math.tan(math.radians(50.0)), axis=1)
            both(np.array([[rect[0], rect[2]], [rect[1], rect[2]], [rect[1], rect[3]], [rect[0], rect[3]]]), -0.3, 0.9,
                 ridge)
    for _ in range(int(rng.integers(160, 201))):
        kind = rng.choice(["log", "tyres", "pallet", "sandbags"], p=[0.35, 0.3, 0.15, 0.2])
        c = np.array([rng.uniform(13.0, length - 13.0), rng.uniform(1.5, width - 1.5)])
        angle = float(rng.uniform(0.0, math.pi))
        u, v = np.array([math.cos(angle), math.sin(angle)]), np.array([-math.sin(angle), math.cos(angle)])
        if kind == "tyres":
            radius = float(rng.uniform(0.4, 0.5))
            plan = c + radius * np.array([[math.cos(a), math.sin(a)] for a in np.arange(8) * math.pi / 4])
            top = float(rng.uniform(0.2, 0.38))
        else:
            along, across, top = {"log": (rng.uniform(1.0, 2.0), rng.uniform(0.15, 0.2), rng.uniform(0.25, 0.35)),
                                  "pallet": (0.6, 0.5, 0.15), "sandbags": (rng.uniform(1.5, 2.5), 0.3, 0.35)}[kind]
            plan = np.array([c + su * along * u + sv * across * v for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1))])
            top = float(top)
        if _half_turn(plan, length, width)[:, 0].min() < 12.5 or plan[:, 0].min() < 12.5:
            continue  # no cover in a pen
        both(plan, -0.3, top)
    return s.mesh()


def holed_mill(seed: int) -> trimesh.Trimesh:
    """A derelict mill 60-70 x 34-40 m of three storeys 4 m apart (floors at 0, 4 and 8 m) in a yard 8 m wide: brick
    walls 0.3 m thick with 3 doors 2.4 m wide on the ground floor's south side and one on each end, a grid of columns
    0.5 m square every 7.5-8.5 m through all storeys, ridged machines (2-5 x 1.5-3 m, the ground stopping under them) on
    the ground floor, and two switchback stair towers (:func:`level_kinds._stair_tower`) against the north wall, a door
    onto every storey. Each upper floor is holed by 24-34 collapses 1.5-5.5 m a side, each 2.5 m clear of every other
    collapse and of the walls and 5 m clear of the towers' doors, so the floor between them stays a lattice of lanes
    at least 2.5 m wide; nothing rails the holes.

    Expected (written before the first run): one area. The upper storeys are reached only through the two stair
    towers, so their traffic funnels from the towers' doors along the lanes between the collapses; the ground floor
    and the yard carry the most (every door and both towers' feet), the top storey's far corners the least. A designer
    expects the structure on each upper floor to run between the holes (never over one: an edge across a collapse is
    a walk through the air), with a node at each tower door, and the heat map's order: ground floor and yard, then
    the first floor near the towers, then the second floor."""
    rng = np.random.default_rng(seed)
    length, depth, storey = float(rng.uniform(60.0, 70.0)), float(rng.uniform(34.0, 40.0)), 4.0
    s = _Solids()
    well = _well_length(storey)
    towers = [float(rng.uniform(6.0, 12.0)), float(rng.uniform(length - 16.0, length - 10.0))]  # each tower's x0
    machines: list[tuple[float, float, float, float]] = []
    for _ in range(200):
        if len(machines) == 10:
            break
        w, d = float(rng.uniform(2.0, 5.0)), float(rng.uniform(1.5, 3.0))
        x, z = float(rng.uniform(3.0, length - 3.0 - w)), float(rng.uniform(3.0, depth - 6.0 - d))
        if _spaced((x, x + w, z, z + d), machines, 3.0):
            machines.append((x, x + w, z, z + d))
    s.ground(-8.0, length + 8.0, -8.0, depth + well + 8.0, 0.0, machines)
    for machine in machines:
        _ridged(s, *machine, -0.5, 1.2)
    pitch = float(rng.uniform(7.5, 8.5))
    columns = [(x, z) for x in np.arange(pitch, length - 1.0, pitch) for z in np.arange(pitch, depth - 1.0, pitch)]
    columns = [(x, z) for x, z in columns
               if _spaced((x - 0.25, x + 0.25, z - 0.25, z + 0.25), machines, 0.0)]
    for x, z in columns:
        s.box(x - 0.25, x + 0.25, 0.0, 3 * storey, z - 0.25, z + 0.25)
    doors_south = sorted(rng.uniform(4.0, length - 6.4, size=3))
    for k in range(3):
        y = k * storey
        south = [(float(d), 2.4) for d in doors_south] if k == 0 else []
        s.wall((0.0, 0.0), (length, 0.0), y, y + storey, south, thickness=0.3)
        end = [(float(rng.uniform(4.0, depth - 8.0)), 2.4)] if k == 0 else []
        s.wall((0.0, 0.0), (0.0, depth), y, y + storey, end, thickness=0.3)
        end = [(float(rng.uniform(4.0, depth - 8.0)), 2.4)] if k == 0 else []
        s.wall((length, 0.0), (length, depth), y, y + storey, end, thickness=0.3)
        s.wall((0.0, depth), (length, depth), y, y + storey, [(x0 - 0.4, 4.8) for x0 in towers], thickness=0.3)
    for x0 in towers:
        _stair_tower(s, x0, depth + 0.2, 0.0, 2, (0, 1, 2), storey)
    for k in (1, 2):
        holes: list[tuple[float, float, float, float]] = []
        keep_clear = [(x0 - 3.0, x0 + 7.0, depth - 5.0, depth) for x0 in towers]
        for _ in range(4000):
            if len(holes) == int(rng.integers(24, 35)):
                break
            w, d = float(rng.uniform(1.5, 5.5)), float(rng.uniform(1.5, 5.5))
            x, z = float(rng.uniform(2.5, length - 2.5 - w)), float(rng.uniform(2.5, depth - 2.5 - d))
            if _spaced((x, x + w, z, z + d), holes, 2.5) and _spaced((x, x + w, z, z + d), keep_clear, 0.0):
                holes.append((x, x + w, z, z + d))
        s.ground(0.0, length, 0.0, depth + 0.2, k * storey, holes, thickness=0.3)
    return s.mesh()


def vineyard(seed: int) -> trimesh.Trimesh:
    """A vineyard valley on a 1 m grid (:func:`level_kinds._terrain`), 120-140 m across (x) and 140-160 m long (z): a
    floor 12-16 m wide falling 2 % along z, a stream 3 m wide down its middle (no ground: water) crossed by 3
    footbridges 2.5 m wide, and on each side flanks of 5-6 terraces 4-7 m deep, each riser 2.5-5 m high at 33-42
    degrees (under the presets' 45-degree limit, so every riser is walked), the terraces wandering 3 m along the valley
    on a wave 60-90 m long. A row of vines (a wall 0.3 m thick, 1.2 m high, gaps 2 m wide every 12-18 m) stands along
    the middle of every terrace; a few rocks lie on the floor.

    Expected (written before the first run): one area (the two flanks meet only over the footbridges). Walkers take
    the straight way up and down the risers (all under 45 degrees), not along the terraces, so a designer expects the
    traffic highest on the valley floor near the footbridges and on the bridges themselves, then across the lower
    terraces opposite each bridge, lowest on the top terraces' far ends; the structure should climb the risers
    directly (no switchback), and show the bridges as the only joins across the stream."""
    rng = np.random.default_rng(seed)
    across, along = float(rng.uniform(120.0, 140.0)), float(rng.uniform(140.0, 160.0))
    floor_half = float(rng.uniform(6.0, 8.0))
    xs, zs = np.arange(0.0, across + 0.5, 1.0), np.arange(0.0, along + 0.5, 1.0)
    shelves = []  # per flank: breakpoints (distance from the floor's edge, height) of the terraces and risers
    for _ in range(2):
        d, h, points = 0.0, 0.0, [(0.0, 0.0)]
        for _ in range(int(rng.integers(5, 7))):
            rise, slope = float(rng.uniform(2.5, 5.0)), math.radians(float(rng.uniform(33.0, 42.0)))
            d += rise / math.tan(slope)
            h += rise
            points.append((d, h))
            d += float(rng.uniform(4.0, 7.0))
            points.append((d, h))
        points.append((1e4, h))
        shelves.append(np.array(points))
    wave, phase = float(rng.uniform(60.0, 90.0)), float(rng.uniform(0.0, 2 * math.pi))
    gx, gz = np.meshgrid(xs, zs, indexing="ij")
    middle = across / 2
    wander = 3.0 * np.sin(2 * math.pi * gz / wave + phase)
    west = np.maximum(middle - floor_half - gx + wander, 0.0)
    east = np.maximum(gx - middle - floor_half + wander, 0.0)
    heights = np.interp(west, shelves[0][:, 0], shelves[0][:, 1]) + np.interp(east, shelves[1][:, 0], shelves[1][:, 1])
    heights -= 0.02 * gz
    cells_x, cells_z = (xs[:-1] + xs[1:]) / 2, (zs[:-1] + zs[1:]) / 2
    stream = np.abs(cells_x - middle) < 1.5
    bridges = sorted(rng.choice(np.arange(12, int(along) - 12, 6), size=3, replace=False))
    keep = np.ones((len(xs) - 1, len(zs) - 1), dtype=bool)
    keep[stream, :] = False
    s = _Solids()
    _terrain(s, xs, zs, heights, keep)
    for z in bridges:
        y = -0.02 * (z + 1.25) + 0.1
        s.box(middle - 2.5, middle + 2.5, y - 0.3, y, float(z), float(z) + 2.5)
    for side, profile in ((-1, shelves[0]), (1, shelves[1])):
        for (d0, h0), (d1, h1) in zip(profile[1:-1:2], profile[2:-1:2]):  # each terrace from d0 to d1 at height h0
            d = (d0 + d1) / 2
            z, gap = 0.0, float(rng.uniform(12.0, 18.0))
            while z < along:
                z1 = min(z + gap, along)
                zz = np.arange(z, z1 + 0.01, 1.0)
                line = middle + side * (floor_half + d - 3.0 * np.sin(2 * math.pi * zz / wave + phase))
                for a, b, za, zb in zip(line[:-1], line[1:], zz[:-1], zz[1:]):
                    ya, yb = h0 - 0.02 * za, h0 - 0.02 * zb
                    s.hull(np.array([[a + dx, y, za] for dx in (-0.15, 0.15) for y in (ya - 0.3, ya + 1.2)]
                                    + [[b + dx, y, zb] for dx in (-0.15, 0.15) for y in (yb - 0.3, yb + 1.2)]))
                z, gap = z1 + 2.0, float(rng.uniform(12.0, 18.0))
    for _ in range(int(rng.integers(5, 9))):
        p = np.array([middle + rng.choice([-1, 1]) * rng.uniform(2.5, floor_half - 1.0), rng.uniform(5.0, along - 5.0)])
        s.rock(rng, p, 0.5, -0.02 * p[1] - 0.3, -0.02 * p[1] + 1.2)
    return s.mesh()


def catwalk_hall(seed: int) -> trimesh.Trimesh:
    """A turbine hall with no floor (a cooling pond under it) 70-84 x 40-48 m whose walkable surfaces are catwalks:
    at each of three heights (6, 10 and 14 m) a grid of 7-8 x 5 junctions (landings 3 m square) joined by railed
    catwalks 1.8 m wide along a random spanning tree of the grid's edges and 25 % of the rest (a different tree each
    height), rails 1.1 m high and 0.1 m thick on both sides of each catwalk and round each landing but where a
    catwalk meets it. Two switchback stair towers (:func:`level_kinds._stair_tower`) stand north of the hall, a door
    onto each height, each door reached by a catwalk from the nearest junction of the grid's north row. Nothing else
    is floor: the walkable area is the catwalks and landings (under 1.8 m wide but for the landings) and the towers.

    Expected (written before the first run): one area. Traffic highest in the two towers and on the catwalks from
    their doors into each grid, then on the tree's trunk edges (the few catwalks every way between two halves of a
    height crosses), lowest on dead-end catwalks of the tree's leaves. A designer expects the structure to follow the
    catwalks (never to cut between two of them across the void), one node per landing at most, and the heat map to
    pick out the tree's bridges (edges whose loss would part a height) over its loops."""
    rng = np.random.default_rng(seed)
    nx, nz = int(rng.integers(7, 9)), 5
    length, depth = float(nx * rng.uniform(10.0, 10.5)), float(nz * rng.uniform(8.0, 9.6))
    xs, zs = np.linspace(4.0, length - 4.0, nx), np.linspace(4.0, depth - 4.0, nz)
    s = _Solids()
    storey, heights = 4.0, (6.0, 10.0, 14.0)
    tower_columns = sorted(rng.choice(np.arange(nx), size=2, replace=False))
    node, edges = _grid_edges(nx, nz)
    for y in heights:
        tree = _random_tree(rng, nx * nz, edges)
        kept = [(a, b) for a, b in edges if tree[a, b] or rng.random() < 0.25]
        openings: dict[int, dict[str, list[tuple[float, float]]]] = {k: {} for k in range(nx * nz)}
        for a, b in kept:
            (ia, ja), (ib, jb) = divmod(int(a), nz), divmod(int(b), nz)
            if ia != ib:  # along x: from a's east side to b's west side
                x0, x1, zc = xs[ia] + 1.5, xs[ib] - 1.5, zs[ja]
                s.box(x0, x1, y - 0.2, y, zc - 0.9, zc + 0.9)
                for z in (zc - 0.85, zc + 0.85):
                    s.wall((x0, z), (x1, z), y, y + 1.1, thickness=0.1)
                openings[int(a)].setdefault("east", []).append((0.6, 1.8))
                openings[int(b)].setdefault("west", []).append((0.6, 1.8))
            else:  # along z
                z0, z1, xc = zs[ja] + 1.5, zs[jb] - 1.5, xs[ia]
                s.box(xc - 0.9, xc + 0.9, y - 0.2, y, z0, z1)
                for x in (xc - 0.85, xc + 0.85):
                    s.wall((x, z0), (x, z1), y, y + 1.1, thickness=0.1)
                openings[int(a)].setdefault("north", []).append((0.6, 1.8))
                openings[int(b)].setdefault("south", []).append((0.6, 1.8))
        for i in tower_columns:  # the catwalk from the north row's junction to the tower's door
            xc, z0 = xs[i], zs[-1] + 1.5
            s.box(xc - 0.9, xc + 0.9, y - 0.2, y, z0, depth + 0.2)
            for x in (xc - 0.85, xc + 0.85):
                s.wall((x, z0), (x, depth), y, y + 1.1, thickness=0.1)
            openings[int(node[i, -1])].setdefault("north", []).append((0.6, 1.8))
        for k in range(nx * nz):
            i, j = divmod(k, nz)
            if not openings[k]:
                continue  # a junction no catwalk of this height reaches holds no landing
            s.box(xs[i] - 1.5, xs[i] + 1.5, y - 0.2, y, zs[j] - 1.5, zs[j] + 1.5)
            _rail_ring(s, xs[i] - 1.45, xs[i] + 1.45, zs[j] - 1.45, zs[j] + 1.45, y, openings[k])
    for i in tower_columns:
        x0 = float(xs[i]) - 2.0
        s.box(x0, x0 + 4.0, heights[0] - 0.3, heights[0], depth + 0.2, depth + 2.2)  # the lowest landing
        _stair_tower(s, x0, depth + 0.2, heights[0], 2, (0, 1, 2), storey)
    for x, z0, z1 in ((-0.3, -0.3, depth), (length, -0.3, depth)):
        s.box(x, x + 0.3, 0.0, heights[-1] + 4.0, z0, z1)  # the hall's end walls
    s.box(-0.3, length + 0.3, 0.0, heights[-1] + 4.0, -0.3, 0.0)
    return s.mesh()


def _double_door(s: _Solids, a: tuple[float, float], b: tuple[float, float], y1: float, start: float,
                 leaves: tuple[str, str], into: float, width: float = 2.4) -> None:
    """A wall along x or z from plan point ``a`` to ``b`` on a floor at 0, up to ``y1``, with one double doorway
    ``width`` m wide from ``start`` m along it (lintel 2.3 m, :func:`level_kinds._doored_wall`) whose two leaves, each
    half the width and 5 cm thick, are hinged at the jambs: "open" swings 90 degrees into the side ``into`` (+1 or -1
    across the wall), "closed" fills its half of the doorway on the wall's line."""
    _doored_wall(s, a, b, 0.0, y1, [(start, width, "open", into)])
    along = 0 if a[1] == b[1] else 1
    lo, fixed = min(a[along], b[along]), a[1 - along]
    half = width / 2
    for hinge, sign, leaf in ((lo + start, 1.0, leaves[0]), (lo + start + width, -1.0, leaves[1])):
        if leaf == "closed":
            u0, u1, v0, v1 = min(hinge, hinge + sign * half), max(hinge, hinge + sign * half), fixed - 0.025, fixed + 0.025
        else:
            u = hinge + sign * 0.045
            v0, v1 = sorted((fixed + into * 0.1, fixed + into * (0.1 + half - 0.05)))
            u0, u1 = min(u, u + sign * 0.05), max(u, u + sign * 0.05)
        if along == 0:
            s.box(u0, u1, -0.05, 2.15, v0, v1)
        else:
            s.box(v0, v1, -0.05, 2.15, u0, u1)


def double_doors(seed: int) -> trimesh.Trimesh:
    """A block of small rooms that open into one another with no corridor (an asylum's wards, a stealth game's
    mansion wing): a grid of 11-13 x 8-10 rooms 4.5-6 m a side (walls 0.2 m thick, 3 m high, no roof) in a yard 4 m wide,
    each wall between two rooms of a random spanning tree of the grid holding a double doorway 2.4 m wide (leaves 1.2 m,
    lintel 2.3 m) with both leaves open at 90 degrees, and 30 % of the other walls one whose leaves are open, one
    open and one shut (a gap of 1.2 m: at most some offsets to Recast's grid let the agent through) or both shut, in
    equal shares; two entrances from the yard (both leaves open); a bed (2 x 0.9-1.0 m, 0.6-0.8 m high) along a wall
    with no doorway in two rooms of three that have one.

    Expected (written before the first run): one area (the tree's doors join every room; a door with one leaf shut may
    or may not join its two rooms, a shut one never does). Traffic highest along the chains of rooms between the two
    entrances and in the rooms where the tree branches, lowest in the tree's leaf rooms; the structure should pass
    through each open double door (one edge through each doorway, not through a wall), and a designer reads each room
    of the tree's trunk as a node."""
    rng = np.random.default_rng(seed)
    nx, nz = int(rng.integers(11, 14)), int(rng.integers(8, 11))
    xs = np.concatenate([[0.0], np.cumsum(rng.uniform(4.5, 6.0, nx))])
    zs = np.concatenate([[0.0], np.cumsum(rng.uniform(4.5, 6.0, nz))])
    s = _Solids()
    s.box(-4.0, xs[-1] + 4.0, -0.5, 0.0, -4.0, zs[-1] + 4.0)
    node, walls = _grid_edges(nx, nz)
    tree = _random_tree(rng, nx * nz, walls)
    doored: set[tuple[int, str]] = set()  # (room, side) of every wall holding a doorway
    for a, b in walls:
        (ia, ja), (ib, jb) = divmod(int(a), nz), divmod(int(b), nz)
        if ia != ib:  # the wall at x = xs[ib] from zs[ja] to zs[ja + 1]
            line, span, sides = ((xs[ib], zs[ja]), (xs[ib], zs[ja + 1])), zs[ja + 1] - zs[ja], ("east", "west")
        else:
            line, span, sides = ((xs[ia], zs[jb]), (xs[ia + 1], zs[jb])), xs[ia + 1] - xs[ia], ("north", "south")
        if tree[a, b]:
            leaves = ("open", "open")
        elif rng.random() < 0.3:
            leaves = [("open", "open"), ("open", "closed"), ("closed", "closed")][int(rng.integers(3))]
        else:
            s.wall(*line, -0.5, 3.0)
            continue
        doored.update({(int(a), sides[0]), (int(b), sides[1])})
        _double_door(s, *line, 3.0, float(rng.uniform(0.5, span - 2.9)), leaves, float(rng.choice([-1.0, 1.0])))
    entrances = {("south", int(rng.integers(nx))), ("north", int(rng.integers(nx)))}
    for side, z in (("south", 0.0), ("north", zs[-1])):
        for i in range(nx):
            line = ((xs[i], z), (xs[i + 1], z))
            if (side, i) in entrances:
                doored.add((int(node[i, 0 if side == "south" else -1]), side))
                into = 1.0 if side == "south" else -1.0
                _double_door(s, *line, 3.0, float(rng.uniform(0.5, xs[i + 1] - xs[i] - 2.9)), ("open", "open"), into)
            else:
                s.wall(*line, -0.5, 3.0)
    for x in (0.0, xs[-1]):
        s.wall((x, 0.0), (x, zs[-1]), -0.5, 3.0)
    for i in range(nx):
        for j in range(nz):
            free = [side for side in ("south", "north", "west", "east") if (int(node[i, j]), side) not in doored]
            if not free or rng.random() > 2 / 3:
                continue
            x0, x1, z0, z1 = xs[i] + 0.1, xs[i + 1] - 0.1, zs[j] + 0.1, zs[j + 1] - 0.1
            side, d, h = free[int(rng.integers(len(free)))], float(rng.uniform(0.9, 1.0)), float(rng.uniform(0.6, 0.8))
            if side in ("south", "north"):
                u = float(rng.uniform(x0 + 0.3, x1 - 2.3))
                z = z0 if side == "south" else z1 - d
                s.box(u, u + 2.0, -0.1, h, z, z + d)
            else:
                u = float(rng.uniform(z0 + 0.3, z1 - 2.3))
                x = x0 if side == "west" else x1 - d
                s.box(x, x + d, -0.1, h, u, u + 2.0)
    return s.mesh()


def split_decks(seed: int) -> trimesh.Trimesh:
    """A split-level car park 60-72 m long of two halves 16 m deep, 6 m apart across a light well, offset by half a
    storey (1.5 m): the south half's decks at 0, 3, 6, 9 (and 12) m, the north half's at 1.5, 4.5, 7.5 (and 10.5) m,
    4-5 decks a half. Ramps 6 m long and 6 m wide (14 degrees) across the well join each south deck up to the north
    deck half a storey above at the east end and each north deck up to the next south deck at the west end, so the
    ramps spiral round the well: the only way between decks. Each deck holds two rows of bays 2.5 x 5 m along its long
    sides (a car, :func:`level_kinds._car`, in 55-80 % of them) either side of an aisle 6 m wide, pillars 0.6 m square
    every 7.5 m along both edges, parapets 1.1 m high round the outside and along the well but at the ramps; the south
    half's ground deck opens onto a pavement 4 m wide along the street.

    Expected (written before the first run): one area. Every way between decks winds round the spiral, so the traffic
    is highest on the lowest ramps and the aisles between them (every walker above the ground passes), falling deck by
    deck to the top; on each deck highest along the aisle between its two ramps (one at each end) and lowest in the
    bays' corners. A designer expects the structure to show one path per deck along its aisle from ramp to ramp and
    each ramp as an edge, with the decks' heat in the order of their heights."""
    rng = np.random.default_rng(seed)
    length = float(rng.choice([60.0, 67.5, 75.0]))
    levels = int(rng.integers(4, 6))
    south, north = (0.0, 16.0), (22.0, 38.0)
    s = _Solids()
    s.box(-4.0, length + 4.0, -0.5, 0.0, -4.0, 22.0)  # the pavement, the ground deck and the well's floor
    top = 3.0 * (levels - 1) + 1.5
    for x in np.arange(0.0, length + 0.1, 7.5):
        for z in (*south, *north):
            s.box(x - 0.3, x + 0.3, 0.0 if z < 20 else 1.2, top + 1.1, z - 0.3, z + 0.3)
    for k in range(levels):
        for (z0, z1), y in ((south, 3.0 * k), (north, 3.0 * k + 1.5)):
            if y > top:
                continue
            if y > 0:
                s.box(0.0, length, y - 0.3, y, z0, z1)
            for zb0, zb1 in ((z0 + 0.3, z0 + 5.3), (z1 - 5.3, z1 - 0.3)):
                for x in np.arange(1.0, length - 2.5, 2.5):
                    if rng.random() < rng.uniform(0.55, 0.8):
                        _car(s, x + 0.35, x + 2.15, zb0 + 0.3, zb1 - 0.3, y)
            outer, inner = (z0, z1) if z0 == 0.0 else (z1, z0)
            ramps = []  # (start along the inner edge, width) of the ramps meeting this deck
            east, west = (length - 10.0, 6.0), (4.0, 6.0)
            if z0 == 0.0:
                ramps += [east] if y < top else []
                ramps += [west] if k > 0 else []
            else:
                ramps += [east, west] if y + 1.5 <= top else [east]
            if y > 0 or outer != 0.0:
                s.wall((0.0, outer), (length, outer), y, y + 1.1, thickness=0.2)
            s.wall((0.0, inner), (length, inner), y, y + 1.1, ramps, thickness=0.2)
            for x in (0.0, length):
                s.wall((x, z0), (x, z1), y, y + 1.1, thickness=0.2)
        y = 3.0 * k
        if y + 1.5 <= top:  # the east ramp from the south deck at y up to the north deck at y + 1.5
            s.ramp(np.array([length - 7.0, south[1]]), np.array([length - 7.0, north[0]]), 6.0, y, y + 1.5)
        if y + 3.0 <= top:  # the west ramp from the north deck at y + 1.5 up to the south deck at y + 3
            s.ramp(np.array([7.0, north[0]]), np.array([7.0, south[1]]), 6.0, y + 1.5, y + 3.0)
    return s.mesh()


KINDS: dict[str, Callable[[int], trimesh.Trimesh]] = {
    "paintball": paintball, "holed_mill": holed_mill, "vineyard": vineyard, "catwalk_hall": catwalk_hall,
    "double_doors": double_doors, "split_decks": split_decks,
}
"""Kind name -> generator (seed -> Y-up mesh in metres) of the twenty-sixth round."""


if __name__ == "__main__":
    write_kinds(kinds=KINDS, description=__doc__.splitlines()[0])
