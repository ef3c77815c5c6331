"""Level kinds of the twenty-seventh held-out round (issue 9): generators no preset setting was made on.

Six kinds of shipped game levels that stress what no earlier round did, each about 400-1,200 navmesh polygons with the
presets' agent (radius 0.5 m, height 2 m, climb 0.4 m, slope 45 degrees), seeds 0-2, built from the solids and
helpers of ``benchmarks/level_kinds.py`` (imported, not copied): ``container_maze`` (blocks of shipping containers one
walks *through*, their ends open or shut, a second tier of short containers on some roofs, the roofs joined by planks
and reached by two flights), ``listing_ferry`` (a ferry's car deck, cabin deck and open deck, the whole ship rolled
8-14 degrees and pitched 1-3: no floor level, no wall upright), ``pipe_network`` (round sewer pipes whose walkable
width is set by the slope of their curved floors and the head room under their curved tops, chambers at their
crossings, under a street), ``boardwalk`` (a marsh with no ground crossed by boardwalks at any angle, each thousands of
planks with gaps of 1-3 cm, platforms, bird hides), ``car_lot`` (a surface car park whose cars stand with gaps of
0.3-1.3 m, about the agent's 1 m width, so a row is a wall or not by chance) and ``festival_camp`` (a field of
marquees at random angles, each a room entered by one door, small tents, stages, stalls inside a fence with gates).

Run: ``.venv/bin/python benchmarks/level_kinds27.py OUT_DIR [--kinds boardwalk car_lot] [--seeds 0 1 2]`` writes
``OUT_DIR/<kind>_s<seed>.obj``; ``benchmarks/analysis_quality.py --levels`` takes the kinds' names too.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import trimesh
from level_kinds import _car, _crosses, _grid_edges, _random_tree, _ridged, _Solids, _stair_tower, _well_length
from level_kinds import main as write_kinds
from scipy.sparse.csgraph import minimum_spanning_tree
from scipy.spatial import Delaunay

CONTAINER = (12.2, 2.44, 2.59)
"""A 40-foot container's length, width and height (m); a 20-foot one is half as long."""


def _container(s: _Solids, x0: float, z0: float, y: float, length: float, ends: tuple[bool, bool]) -> None:
    """A container along x from plan point (x0, z0) (its south-west corner) on a floor at ``y``: a floor 0.15 m thick
    on top of ``y``, side walls and a roof 0.1 m thick (2.24 m clear inside, 2.34 m of head room), and at each end
    (west, east) a door wall when ``ends`` says shut, nothing when open (the doors swung back against the sides)."""
    _, width, height = CONTAINER
    x1, z1, top = x0 + length, z0 + width, y + height
    s.box(x0, x1, y, y + 0.15, z0, z1)
    s.box(x0, x1, top - 0.1, top, z0, z1)
    for z in (z0, z1 - 0.1):
        s.box(x0, x1, y, top, z, z + 0.1)
    for x, shut in ((x0, ends[0]), (x1 - 0.1, ends[1])):
        if shut:
            s.box(x, x + 0.1, y, top, z0, z1)


def container_maze(seed: int) -> trimesh.Trimesh:
    """A container yard (a shooter's "shipment" map) 4-5 x 4-5 blocks of 40-foot containers (12.2 x 2.44 x 2.59 m) laid
    side by side, 2-4 to a block, lanes 3-5 m wide between the blocks, on flat ground with a fence 3 m high round it.
    Each container's west end is open with a chance of 0.7, else shut by its doors, and its east end then open with a
    chance of 0.7 (never both shut: a shut box keeps a floor inside it one cannot reach), so most are tunnels one walks
    through (1.24 m wide for the agent); a 20-foot container stands on the west half of up to two of a block's roofs
    (never on its southmost), its west end (over the lane) shut, its east end open onto the roof, under a tarpaulin
    ridged at 50 degrees (no floor on top). The blocks' roofs (2.59 m up) are one walk: planks 2 m wide across the lanes
    join neighbouring blocks along a spanning tree of the blocks' grid and 30 % of the other neighbours, and two flights
    (riser 0.152 m) climb from the ground head-on to a block's end on the west and on the east edge (the container under
    the flight's head open at its other end).

    Expected (written before the first run): one area (ground, tunnels and roofs; a tunnel with both ends shut is a
    closed box; none is built). Traffic highest on the lanes through the middle of the yard and on the open tunnels that
    cut a block's length, lowest in tunnels open at one end only (dead ends) and on roofs far from the flights. A
    designer expects the structure to pass through open tunnels (an edge along each one walked, never through a shut end
    or a side wall), to show the roof walk as a layer over the lanes joined only at the flights, and no structure in a
    shut container."""
    rng = np.random.default_rng(seed)
    length, width, height = CONTAINER
    nbx, nbz = int(rng.integers(4, 6)), int(rng.integers(4, 6))
    wide = rng.integers(2, 5, size=(nbx, nbz))
    lanes_x = rng.uniform(3.0, 5.0, size=nbx + 1)
    lanes_x[[0, -1]] = 7.0  # room for a flight 5.2 m long at both ends
    lanes_z = rng.uniform(3.0, 5.0, size=nbz + 1)
    xs = lanes_x[0] + np.concatenate([[0.0], np.cumsum(length + lanes_x[1:-1])])  # each block column's west end
    row_depth = wide.max(axis=0) * width
    zs = lanes_z[0] + np.concatenate([[0.0], np.cumsum(row_depth[:-1] + lanes_z[1:-1])])  # each block row's south side
    size_x, size_z = xs[-1] + length + lanes_x[-1], zs[-1] + row_depth[-1] + lanes_z[-1]
    s = _Solids()
    s.box(-1.0, size_x + 1.0, -0.5, 0.0, -1.0, size_z + 1.0)
    for a, b in (((0.0, 0.0), (size_x, 0.0)), ((0.0, size_z), (size_x, size_z)), ((0.0, 0.0), (0.0, size_z)),
                 ((size_x, 0.0), (size_x, size_z))):
        s.wall(a, b, 0.0, 3.0, thickness=0.2)
    flights = []  # (block column, row, slot, heading): one up to a west end on the west edge, one to an east end
    for i, heading in ((0, 1.0), (nbx - 1, -1.0)):
        j = int(rng.integers(nbz))
        flights.append((i, j, int(rng.integers(int(wide[i, j]))), heading))
    upper: dict[tuple[int, int], set[int]] = {}  # block -> slots holding a 20-foot container on the roof
    for i in range(nbx):
        for j in range(nbz):
            for k in range(int(wide[i, j])):
                west_shut = bool(rng.random() > 0.7)  # never both ends shut: a shut box keeps floor inside
                east_shut = not west_shut and rng.random() > 0.7
                if (i, j, k, 1.0) in flights or (i, j, k, -1.0) in flights:  # a flight blocks one end: the other opens
                    west_shut = east_shut = False
                _container(s, xs[i], zs[j] + k * width, 0.0, length, (west_shut, east_shut))
            slots = 1 + rng.permutation(int(wide[i, j]) - 1)[:int(rng.integers(0, 3))]  # slot 0 stays free for planks
            upper[(i, j)] = {int(k) for k in slots}
            for k in upper[(i, j)]:
                _container(s, xs[i], zs[j] + k * width, height, length / 2, (True, False))
                _ridged(s, xs[i], xs[i] + length / 2, zs[j] + k * width, zs[j] + (k + 1) * width, 2 * height - 0.1,
                        2 * height + 0.6)  # a tarpaulin over the upper container: its roof is no floor
    _, pairs = _grid_edges(nbx, nbz)
    tree = _random_tree(rng, nbx * nbz, pairs)
    for a, b in pairs:
        if not (tree[a, b] or rng.random() < 0.3):
            continue
        (ia, ja), (ib, jb) = divmod(int(a), nbz), divmod(int(b), nbz)
        if ia != ib:  # across the lane east of block a, into block b's west end at a slot with no upper container
            reach = min(int(wide[ia, ja]), int(wide[ib, jb]))
            free = [k for k in range(reach) if k not in upper[(ib, jb)]]
            zc = zs[ja] + (int(rng.choice(free)) + 0.5) * width
            s.box(xs[ia] + length - 0.3, xs[ib] + 0.3, height - 0.1, height, zc - 1.0, zc + 1.0)
        else:  # across the lane north of block a, on the roofs' east halves
            xc = float(rng.uniform(xs[ia] + length / 2 + 1.5, xs[ia] + length - 1.5))
            s.box(xc - 1.0, xc + 1.0, height - 0.1, height, zs[ja] + wide[ia, ja] * width - 0.3, zs[jb] + 0.3)
    for i, j, k, heading in flights:
        end = xs[i] if heading > 0 else xs[i] + length
        s.stairs(np.array([end - heading * 17 * 0.3, zs[j] + (k + 0.5) * width]), np.array([heading, 0.0]), 1.6, 0.0,
                 height, height / 17)
    return s.mesh()


def listing_ferry(seed: int, roll: tuple[float, float] = (8.0, 14.0)) -> trimesh.Trimesh:
    """A ro-ro ferry 110-130 m long and 20-22 m wide (a sinking-ship level) built upright and then rolled ``roll``
    degrees (8-14, to port or starboard) about its long axis and pitched 1-3 degrees about its beam: a car deck at 0 m
    (cars in four lanes, the bow and stern doors shut), a cabin deck at 4 m (a lounge along the south side round the
    stair towers, a corridor 2 m wide along the ship entered from it by four doors 2.4 m wide, cabins 3 m wide and
    5.2-7.2 m deep north of the corridor through doors 1.5 m wide, a boxed two-tier bunk in each), an open deck at 8 m
    (lifeboats on chocks along both sides but in front of the towers' doors, benches, a rail 1.1 m high), and two
    switchback stair towers (:func:`level_kinds._stair_tower`, storeys 4 m) amidships fore and aft, a door onto each
    deck. Every floor is sloped 8-14 degrees across the ship, every wall leans; a step of the flights climbs 0.15 m plus
    or minus 0.04-0.07 m. ``roll=(0, 0)`` builds the same ship upright but for its pitch.

    Expected (written before the first run): one area (all slopes under 45 degrees, every step under the climb). A
    designer expects the same reading as the ship upright: traffic highest in the two stair towers and the lounge
    between them, then the corridors, lowest in the cabins (dead ends) and the car deck's far corners; the structure one
    path along the corridor with a short spur into each cabin or a cover of several, and nothing through a leaning wall.
    """
    rng = np.random.default_rng(seed)
    length, beam = float(rng.uniform(110.0, 130.0)), float(rng.uniform(20.0, 22.0))
    storey, well = 4.0, _well_length(4.0)
    s = _Solids()
    towers = [float(rng.uniform(length * 0.25, length * 0.3)), float(rng.uniform(length * 0.65, length * 0.7))]
    z_tower = 5.0  # each tower's doors face south, onto the lounge and the car deck's south lane
    # each tower's plan, a hole in the decks; from z_tower, not its wall's outer face, so the decks run under its doors
    tower_plans = [(x0 - 0.4, x0 + 4.4, z_tower, z_tower + well + 0.4) for x0 in towers]
    s.box(0.0, length, -0.3, 0.0, 0.0, beam)
    for y in (storey, 2 * storey):
        s.slab(0.0, length, 0.0, beam, y, tower_plans)
    for x0 in towers:
        _stair_tower(s, x0, z_tower, 0.0, 2, (0, 1, 2), storey)
    for z in (0.0, beam):  # the hull's sides up to the open deck's rail, its bow and stern
        s.wall((0.0, z), (length, z), -0.3, 2 * storey + 1.1, thickness=0.3)
    for x in (0.0, length):
        s.wall((x, 0.0), (x, beam), -0.3, 2 * storey + 1.1, thickness=0.3)
    for lane in range(4):  # the car deck: cars nose to tail in four lanes, leaving the towers' feet clear
        zc = 1.5 + (beam - 3.0) * (lane + 0.5) / 4
        x = 2.0
        while x < length - 6.5:
            car = (x, x + float(rng.uniform(4.2, 4.9)), zc - 0.9, zc + 0.9)
            clear = all(car[1] < p[0] - 1.5 or p[1] + 1.5 + 3.0 < car[0] or car[3] < p[2] - 1.0 or p[3] < car[2]
                        for p in tower_plans)
            if clear and rng.random() < 0.8:
                _car(s, *car, 0.0)
            x = car[1] + float(rng.uniform(0.6, 1.2))
    y = storey  # the cabin deck: a lounge round the towers (their doors face it), a corridor, cabins to the north
    lounge_wall, cabin_wall = z_tower + well + 0.6, z_tower + well + 2.6
    s.wall((0.0, lounge_wall), (length, lounge_wall), y, y + storey,
           [(float(d), 2.4) for d in rng.uniform(3.0, length - 5.4, size=4)], thickness=0.15)
    s.wall((3.0, cabin_wall), (length - 3.0, cabin_wall), y, y + storey,
           [(float(x) + 0.75, 1.5) for x in np.arange(0.0, length - 8.9, 3.0)], thickness=0.15)
    for x in np.arange(3.0, length - 2.9, 3.0):  # the cabins' walls; a two-tier bunk boxed to 2.1 m by each west one
        s.wall((float(x), cabin_wall), (float(x), beam), y, y + storey, thickness=0.15)
        if x < length - 5.9:
            s.box(float(x) + 0.1, float(x) + 1.0, y, y + 2.1, cabin_wall + 1.3, beam - 0.2)  # 1.6 m under the deck
    for _ in range(int(rng.integers(8, 13))):  # lounge tables, clear of the towers and their doors
        x, z = float(rng.uniform(2.0, length - 3.2)), float(rng.uniform(0.5, lounge_wall - 1.7))
        if all(x + 1.2 < p[0] - 1.0 or p[1] + 1.0 < x or z + 1.2 < p[2] - 2.0 or p[3] < z for p in tower_plans):
            s.box(x, x + 1.2, y, y + 0.75, z, z + 1.2)
    y = 2 * storey  # the open deck: lifeboats on chocks along both sides, benches amidships
    for z0, z1 in ((0.8, 3.0), (beam - 3.0, beam - 0.8)):
        for x in np.arange(6.0, length - 12.0, 12.0):
            if z0 > 1.0 or all(x + 8.0 < p[0] - 2.0 or p[1] + 2.0 < x for p in tower_plans):  # none by a door
                _ridged(s, float(x), float(x) + 8.0, z0, z1, y, y + 1.2)
    for _ in range(int(rng.integers(6, 10))):
        x, z = float(rng.uniform(4.0, length - 7.0)), float(rng.uniform(4.5, beam - 5.5))
        if all(x + 2.5 < p[0] - 1.0 or p[1] + 1.0 < x or z + 0.6 < p[2] - 1.0 or p[3] + 1.0 < z for p in tower_plans):
            s.box(x, x + 2.5, y, y + 0.45, z, z + 0.6)
    mesh = s.mesh()
    tilt = trimesh.transformations.rotation_matrix(math.radians(float(rng.uniform(*roll)) * rng.choice([-1.0, 1.0])),
                                                   [1.0, 0.0, 0.0], [length / 2, 0.0, beam / 2])
    pitch = trimesh.transformations.rotation_matrix(math.radians(float(rng.uniform(1.0, 3.0))), [0.0, 0.0, 1.0],
                                                    [length / 2, 0.0, beam / 2])
    return mesh.apply_transform(pitch @ tilt)


def _pipe(s: _Solids, a: np.ndarray, b: np.ndarray, radius: float, floor: float, staves: int = 18) -> None:
    """A round pipe along x or z from plan point ``a`` to ``b`` whose inside is ``radius`` m round, its lowest point
    at ``floor``: ``staves`` plates 0.15 m thick (one convex body each, 360 / staves degrees of the ring), the bottom
    one flat, so the plates tilt 0, 20, 40, 60 ... degrees for 18 staves (floor up to 40 degrees, walls beyond)."""
    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    along = (b - a) / np.linalg.norm(b - a)
    side = np.array([-along[1], along[0]])
    centre = floor + radius * math.cos(math.pi / staves)  # the bottom plate's inner face lies at ``floor``
    step = 2 * math.pi / staves
    for k in range(staves):
        ring = []
        for angle in ((k - 0.5) * step, (k + 0.5) * step):  # angles from straight down, round the pipe
            for r in (radius, radius + 0.15 / math.cos(step / 2)):
                offset, up = r * math.sin(angle), -r * math.cos(angle)
                ring += [[p[0] + side[0] * offset, centre + up, p[1] + side[1] * offset] for p in (a, b)]
        s.hull(np.array(ring))


def pipe_network(seed: int) -> trimesh.Trimesh:
    """A storm-drain network (a sewer level) under a street: a grid of 7-8 x 5-6 chambers 5 m square (floor at 0 m,
    walls 0.3 m thick) 15-19 m apart, joined by round pipes (:func:`_pipe`, 18 staves) along a spanning tree of the
    grid's edges and 40 % of the rest, each 1.6-1.9 m round inside: the pipe's floor is the plates at 0, 20 and 40
    degrees, about 2.1-2.5 m wide, and the head room under its curved top falls under the agent's 2 m beyond 1.0-1.4 m
    from its middle, so the walkable lane is set by the curve, not by a wall. The western chambers open through outfall
    pipes onto a yard at the chambers' floor (an open channel bank 12 m wide); a street 0.5 m thick lies 0.35 m over the
    pipes' tops and covers the chambers, reached from the yard by a ramp 24 m long (about 11 degrees) to a landing at
    its edge; a few kiosks stand on the street.

    Expected (written before the first run): one area (yard, pipes, chambers and street). Traffic highest on the street
    (most of the area, walked end to end) and on the ramp, then in the western chambers and the pipes that join the
    outfalls to the rest, lowest in the far chambers on spurs of the tree. A designer expects the structure to follow
    each pipe along its middle (one edge down a straight pipe, no node on its curved walls), a node in each chamber
    where pipes meet, and nothing under the street joined to the street but through the yard and the ramp."""
    rng = np.random.default_rng(seed)
    nx, nz = int(rng.integers(7, 9)), int(rng.integers(5, 7))
    pitch = float(rng.uniform(15.0, 19.0))
    yard = 12.0
    xs, zs = yard + 4.0 + pitch * np.arange(nx), 4.0 + pitch * np.arange(nz)  # the chambers' centres
    size_x, size_z = xs[-1] + 6.0, zs[-1] + 6.0
    radius_max = 1.9
    street = 2 * radius_max + 0.15 + 0.35 + 0.5  # its top; 0.35 m of void between the widest pipe and its underside
    s = _Solids()
    s.box(0.0, yard, -0.5, 0.0, 0.0, size_z)  # the yard; under the street only the chambers and pipes hold floor
    node, edges = _grid_edges(nx, nz)
    tree = _random_tree(rng, nx * nz, edges)
    openings: dict[tuple[int, str], float] = {}  # (chamber, side) -> the radius of the pipe through that wall
    pipes: list[tuple[np.ndarray, np.ndarray, float]] = []
    for a, b in edges:
        (ia, ja), (ib, jb) = divmod(int(a), nz), divmod(int(b), nz)
        if not (tree[a, b] or rng.random() < 0.4):
            continue
        radius = float(rng.uniform(1.6, 1.9))
        along_x = ia != ib
        pa = np.array([xs[ia] + 2.5, zs[ja]]) if along_x else np.array([xs[ia], zs[ja] + 2.5])
        pb = np.array([xs[ib] - 2.5, zs[jb]]) if along_x else np.array([xs[ib], zs[jb] - 2.5])
        pipes.append((pa, pb, radius))
        openings[(int(a), "east" if along_x else "north")] = radius
        openings[(int(b), "west" if along_x else "south")] = radius
    for j in range(nz):  # each western chamber's outfall to the yard
        radius = float(rng.uniform(1.6, 1.9))
        pipes.append((np.array([yard, zs[j]]), np.array([xs[0] - 2.5, zs[j]]), radius))
        openings[(int(node[0, j]), "west")] = radius
    for pa, pb, radius in pipes:
        _pipe(s, pa, pb, radius, 0.0)
    top = street - 0.5  # the street's underside: the chambers' walls rise to it
    for i in range(nx):
        for j in range(nz):
            x0, x1, z0, z1 = xs[i] - 2.5, xs[i] + 2.5, zs[j] - 2.5, zs[j] + 2.5
            s.box(x0, x1, -0.5, 0.0, z0, z1)
            for side, a, b in (("south", (x0, z0), (x1, z0)), ("north", (x0, z1), (x1, z1)),
                               ("west", (x0, z0), (x0, z1)), ("east", (x1, z0), (x1, z1))):
                radius = openings.get((int(node[i, j]), side))
                gap = [] if radius is None else [(2.5 - radius, 2 * radius)]
                s.wall(a, b, 0.0, top, gap, thickness=0.3)  # the pipe's own plates close the gap above its mouth
    s.box(yard, size_x, top, street, 0.0, size_z)
    s.wall((yard, 0.0), (yard, size_z), 0.0, top, [(zs[j] - 1.9, 3.8) for j in range(nz)], thickness=0.3)
    for j in range(nz):  # the retaining wall over each outfall's mouth, down to the pipe's top
        s.box(yard - 0.15, yard + 0.15, 2 * radius_max + 0.15, top, zs[j] - 1.9, zs[j] + 1.9)
    ramp_z0 = float(rng.uniform(2.0, size_z - 32.0))
    s.ramp(np.array([yard - 3.0, ramp_z0]), np.array([yard - 3.0, ramp_z0 + 24.0]), 3.0, 0.0, street)
    s.box(yard - 4.5, yard + 0.3, street - 0.3, street, ramp_z0 + 24.0, ramp_z0 + 27.0)  # the landing onto the street
    for _ in range(int(rng.integers(4, 8))):
        x, z = float(rng.uniform(yard + 3.0, size_x - 5.0)), float(rng.uniform(2.0, size_z - 4.0))
        _ridged(s, x, x + 3.0, z, z + 2.0, street - 0.1, street + 2.5)
    return s.mesh()


def _plank_walk(s: _Solids, rng: np.random.Generator, a: np.ndarray, b: np.ndarray, ya: float, yb: float,
                width: float) -> None:
    """A boardwalk ``width`` m wide from plan point ``a`` (its top at ``ya``) to ``b`` (at ``yb``): planks across it
    0.25-0.3 m wide and 0.05 m thick with gaps of 0.01-0.03 m between them, each one convex body, on joists (two
    beams 0.1 m square along its edges, 0.05 m under the planks)."""
    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    span = float(np.linalg.norm(b - a))
    along = (b - a) / span
    side = np.array([-along[1], along[0]]) * width / 2
    t = 0.0
    while t < span:
        t1 = min(t + float(rng.uniform(0.25, 0.3)), span)
        y0, y1 = ya + (yb - ya) * t / span, ya + (yb - ya) * t1 / span
        p0, p1 = a + along * t, a + along * t1
        s.hull(np.array([[p[0] + sg * side[0], y + dy, p[1] + sg * side[1]]
                         for p, y in ((p0, y0), (p1, y1)) for sg in (-1, 1) for dy in (-0.05, 0.0)]))
        t = t1 + float(rng.uniform(0.01, 0.03))
    for sg in (-0.9, 0.9):
        e0, e1 = a + sg * side, b + sg * side
        s.hull(np.array([[e[0] + dx, y + dy, e[1] + dz] for e, y in ((e0, ya), (e1, yb))
                         for dx, dz in ((0.05, 0.05), (-0.05, -0.05), (0.05, -0.05), (-0.05, 0.05))
                         for dy in (-0.15, -0.05)]))


def boardwalk(seed: int, scale: float = 1.0) -> trimesh.Trimesh:
    """A marsh nature reserve 200-220 x 160-180 m with no ground to walk (open water and reeds): 36-44 platforms (18 m
    apart at least, (octagons 5-8 m across, decks 0.5-1.2 m over the water) joined by boardwalks 2.2-2.6 m wide
    (:func:`_plank_walk`: planks with gaps of 1-3 cm, each one solid, at whatever angle the two platforms lie) along the
    Delaunay triangulation's minimum spanning tree and 35 % of its other edges whose walk is 8 m or longer, each walk
    sloping gently from one platform's height to the other's; a visitor centre's forecourt (20 x 11 m of ground) on the
    south shore joined to the nearest platform whose walk from it crosses no other walk; bird hides (a room 3 m square,
    walls 2.4 m, roofed, one door 1.6 m wide facing the walk) on three dead-end platforms. Every walking surface but the
    forecourt is planks.

    Expected (written before the first run): one area (thousands of separate planks read as one deck: their gaps are a
    tenth of Recast's cell). Traffic highest on the walks of the tree's trunk between the forecourt and the middle of
    the marsh, lowest on the far platforms and in the hides; the structure should run along each walk's middle, one edge
    or a few per straight walk, and through each hide's door, never across the water between two walks. ``scale``
    multiplies the marsh's sides (and the platforms' count by its square): 0.5 builds a smaller marsh by the same rules.
    """
    rng = np.random.default_rng(seed)
    size_x, size_z = scale * float(rng.uniform(200.0, 220.0)), scale * float(rng.uniform(160.0, 180.0))
    centres: list[np.ndarray] = []
    for _ in range(3000):
        if len(centres) == int(scale ** 2 * rng.integers(36, 45)):
            break
        c = np.array([rng.uniform(8.0, size_x - 8.0), rng.uniform(24.0, size_z - 8.0)])
        if all(np.linalg.norm(c - o) > 18.0 for o in centres):
            centres.append(c)
    points = np.array(centres)
    radii = rng.uniform(2.5, 4.0, len(points))
    heights = rng.uniform(0.5, 1.2, len(points))
    triangles = Delaunay(points).simplices
    pairs = {tuple(sorted((int(p), int(q)))) for tri in triangles
             for p, q in ((tri[0], tri[1]), (tri[1], tri[2]), (tri[0], tri[2]))}
    weights = np.zeros((len(points), len(points)))
    for p, q in pairs:
        weights[p, q] = np.linalg.norm(points[p] - points[q])
    tree = minimum_spanning_tree(weights).toarray() > 0
    s = _Solids()
    walks: dict[int, list[np.ndarray]] = {k: [] for k in range(len(points))}  # each platform's walks' headings
    laid: list[tuple[int, int]] = []  # the platforms each walk joins
    for c, r, y in zip(points, radii, heights):
        s.prism(c + r * np.array([[math.cos(a), math.sin(a)] for a in (np.arange(8) + 0.5) * math.pi / 4]), y - 0.3, y)
    for p, q in sorted(pairs):
        gap = weights[p, q] - radii[p] - radii[q]
        if not (tree[p, q] or tree[q, p] or (gap >= 8.0 and rng.random() < 0.35)):
            continue
        u = (points[q] - points[p]) / weights[p, q]
        laid.append((p, q))
        walks[p].append(u)
        walks[q].append(-u)
        _plank_walk(s, rng, points[p] + u * (radii[p] - 0.5), points[q] - u * (radii[q] - 0.5), heights[p], heights[q],
                    float(rng.uniform(2.2, 2.6)))
    forecourt = np.array([size_x / 2, 8.0])
    s.box(forecourt[0] - 10.0, forecourt[0] + 10.0, -0.5, 0.3, 4.0, 15.0)
    def crosses_a_walk(k: int, start: np.ndarray) -> bool:
        """Whether the way from ``start`` to platform ``k`` crosses a walk not ending there (its middle or an edge)."""
        for p, q in laid:
            along = (points[q] - points[p]) / weights[p, q]
            edge = np.array([-along[1], along[0]]) * 1.5
            if k not in (p, q) and any(_crosses(start, points[k], points[p] + o * edge, points[q] + o * edge)
                                       for o in (-1.0, 0.0, 1.0)):
                return True
        return False

    for nearest in np.argsort(np.linalg.norm(points - forecourt, axis=1)):  # the nearest platform reached crossing
        start = np.array([np.clip(points[nearest][0], forecourt[0] - 8.0, forecourt[0] + 8.0), 14.7])  # no walk
        if not crosses_a_walk(int(nearest), start):
            break
    u = points[nearest] - start
    u = u / np.linalg.norm(u)
    _plank_walk(s, rng, start, points[nearest] - u * (radii[nearest] - 0.5), 0.3, heights[nearest], 2.4)
    _ridged(s, forecourt[0] - 6.0, forecourt[0] + 6.0, 1.0, 4.0, -0.5, 4.0)  # the visitor centre, closed
    leaves = [k for k in range(len(points)) if len(walks[k]) == 1]
    for k in rng.permutation(leaves)[:3]:  # hides: a room 3 m square on a dead-end platform, away from its one walk
        c, y, u = points[k], heights[k], walks[k][0]
        x0, z0 = c - u * 1.2 - 1.5
        x1, z1 = x0 + 3.0, z0 + 3.0
        door = int(np.argmax(np.abs(u)))  # its door in the wall facing the walk
        for side, (a, b) in ((0, ((x0, z0), (x0, z1))), (0, ((x1, z0), (x1, z1))), (1, ((x0, z0), (x1, z0))),
                             (1, ((x0, z1), (x1, z1)))):
            facing = side == door and (a[side] - c[side]) * u[side] > 0
            s.wall(a, b, y, y + 2.4, [(0.7, 1.6)] if facing else [], thickness=0.15)
        _ridged(s, x0 - 0.2, x1 + 0.2, z0 - 0.2, z1 + 0.2, y + 2.4, y + 2.5)
    return s.mesh()


def car_lot(seed: int) -> trimesh.Trimesh:
    """A supermarket's surface car park 90-100 x 60-70 m: 5 double rows of bays 2.5 m wide and 5 m deep along x,
    nose to nose over a kerb 0.15 m high, aisles 6.5 m wide between the double rows, a footway 4 m wide along the
    shop's front (north) with its two doors, a fence round the rest with two road gates. A car stands in 75-95 % of
    the bays: 1.75-1.95 m wide and 4.2-4.9 m long, off the bay's middle by up to 0.3 m across and turned up to 4
    degrees (a hull ridged 1.4 m up, :func:`level_kinds._car`'s shape at an angle), so the gaps between neighbours
    are 0.3-1.3 m, about the agent's 1 m: whether a walker slips between two cars is chance.

    Expected (written before the first run): one area (the aisles join at both ends of every row). Traffic highest
    on the footway between the doors and along the aisles' ends (the walk from any bay to the shop goes down its
    aisle to the footway), lowest in the rows' middles far from the shop; walkers squeeze between cars where a gap
    opens, so a designer expects the structure along each aisle's middle and a few edges through the rows where
    gaps are, none through a car."""
    rng = np.random.default_rng(seed)
    length, rows = float(rng.uniform(90.0, 100.0)), 5
    s = _Solids()
    depth = 4.0 + rows * 10.0 + (rows + 1) * 6.5 + 4.0
    s.box(-1.0, length + 1.0, -0.5, 0.0, -1.0, depth + 1.0)
    s.wall((0.0, 0.0), (length, 0.0), 0.0, 2.0, [(float(rng.uniform(5.0, length / 2 - 12.0)), 7.0),
                                                   (float(rng.uniform(length / 2, length - 12.0)), 7.0)], thickness=0.1)
    for x in (0.0, length):
        s.wall((x, 0.0), (x, depth), 0.0, 2.0, thickness=0.1)
    shop = depth
    s.wall((0.0, shop), (length, shop), 0.0, 6.0, [(length * 0.3, 3.0), (length * 0.65, 3.0)], thickness=0.3)
    s.box(length * 0.3 - 1.0, length * 0.65 + 4.0, 0.0, 0.15, shop + 0.15, shop + 20.0)  # the shop floor, a step up
    s.wall((length * 0.3 - 1.0, shop + 20.0), (length * 0.65 + 4.0, shop + 20.0), 0.0, 6.0, thickness=0.3)
    for x in (length * 0.3 - 1.0, length * 0.65 + 4.0):
        s.wall((x, shop), (x, shop + 20.0), 0.0, 6.0, thickness=0.3)
    for r in range(rows):
        z_kerb = 6.5 + r * 16.5 + 5.0  # the double row's middle: bays 5 m deep on each side of the kerb
        s.box(6.0, length - 6.0, 0.0, 0.15, z_kerb - 0.3, z_kerb + 0.3)
        for side in (-1.0, 1.0):
            for x in np.arange(6.0, length - 8.4, 2.5):
                if rng.random() > rng.uniform(0.75, 0.95):
                    continue
                w, l = float(rng.uniform(1.75, 1.95)), float(rng.uniform(4.2, 4.9))
                centre = np.array([x + 1.25 + rng.uniform(-0.3, 0.3), z_kerb + side * (0.3 + 2.5)])
                angle = math.pi / 2 + math.radians(float(rng.uniform(-4.0, 4.0)))
                u, v = np.array([math.cos(angle), math.sin(angle)]), np.array([-math.sin(angle), math.cos(angle)])
                corners = [centre + su * l / 2 * u + sv * w / 2 * v for su in (-1, 1) for sv in (-1, 1)]
                ridge = [centre + su * l / 2 * u for su in (-1, 1)]
                s.hull(np.array([[p[0], -0.3, p[1]] for p in corners] + [[p[0], 1.4, p[1]] for p in ridge]))
    for _ in range(int(rng.integers(6, 10))):  # trolley bays and lamp posts in the aisles' ends
        x, z = float(rng.choice([2.0, length - 4.0])), float(rng.uniform(2.0, depth - 6.0))
        s.box(x, x + 0.4, 0.0, 5.0, z, z + 0.4)
    return s.mesh()


def festival_camp(seed: int) -> trimesh.Trimesh:
    """A music festival's camp field 130-150 x 100-110 m inside a fence 2 m high with three gates: 40-50 marquees
    (4-7 x 5-9 m, canvas walls 0.05 m thick and 2.3 m high under a roof ridged at 50 degrees, one door 2.2 m wide in
    a gable end) each turned to a random angle, 120-160 small tents (closed hulls 2.2-3 x 1.4-2.4 m, 1.2 m high, at
    any angle, 0.8 m clear of one another), two stages (ridged blocks 12 x 8 m one does not climb) with a standing
    area before each, and a row of food stalls (closed, ridged). Every marquee is a room at an angle to the axes,
    entered by its one door, a dead end.

    Expected (written before the first run): one area (every marquee's door 2.2 m wide, wider than the 2 m an angled
    door needs). Traffic highest between the gates and the stages' standing areas, lowest inside the marquees and
    among the small tents at the far corners; a designer expects the structure to enter each marquee through its door
    (or to cover it from outside through the door), never through canvas, and to weave between the small tents."""
    rng = np.random.default_rng(seed)
    size_x, size_z = float(rng.uniform(130.0, 150.0)), float(rng.uniform(100.0, 110.0))
    s = _Solids()
    s.wall((0.0, 0.0), (size_x, 0.0), 0.0, 2.0, [(float(rng.uniform(10.0, size_x - 20.0)), 6.0)], thickness=0.1)
    s.wall((0.0, size_z), (size_x, size_z), 0.0, 2.0, [(float(rng.uniform(10.0, size_x - 20.0)), 6.0)], thickness=0.1)
    s.wall((0.0, 0.0), (0.0, size_z), 0.0, 2.0, [(float(rng.uniform(10.0, size_z - 20.0)), 6.0)], thickness=0.1)
    s.wall((size_x, 0.0), (size_x, size_z), 0.0, 2.0, thickness=0.1)
    taken: list[tuple[np.ndarray, float]] = []  # (centre, clearance radius) of everything placed
    closed: list[tuple[float, float, float, float]] = []  # plans of the closed solids the ground stops under

    def free(c: np.ndarray, r: float) -> bool:
        """Whether a disc of radius ``r`` round plan point ``c`` clears all placed and lies 1.5 m inside the fence."""
        inside = r + 1.5 < min(c[0], c[1], size_x - c[0], size_z - c[1])
        return inside and all(np.linalg.norm(c - o) > r + ro for o, ro in taken)

    for x0 in (float(rng.uniform(10.0, size_x / 2 - 25.0)), float(rng.uniform(size_x / 2 + 5.0, size_x - 25.0))):
        z0 = size_z - 12.0
        closed.append(_ridged(s, x0, x0 + 12.0, z0, z0 + 8.0, -0.5, 1.5))  # a stage; its standing area kept clear
        taken += [(np.array([x0 + 6.0, z0 + 4.0]), 7.5), (np.array([x0 + 6.0, z0 - 9.0]), 9.0)]
    x = float(rng.uniform(20.0, size_x - 60.0))
    for k in range(8):  # the food stalls in a row along the south fence
        closed.append(_ridged(s, x + 5.0 * k, x + 5.0 * k + 3.5, 3.0, 6.0, -0.5, 2.4))
    taken += [(np.array([x + 20.0, 4.5]), 21.0)]
    s.ground(-1.0, size_x + 1.0, -1.0, size_z + 1.0, 0.0, closed)  # none inside a stage or a stall

    def turned(c: np.ndarray, angle: float, dx: float, dz: float) -> np.ndarray:
        """Plan point (2,): ``dx`` m along and ``dz`` m across a frame at ``c`` turned by ``angle`` radians."""
        u, v = np.array([math.cos(angle), math.sin(angle)]), np.array([-math.sin(angle), math.cos(angle)])
        return c + dx * u + dz * v

    marquees, wanted = 0, int(rng.integers(40, 51))
    for _ in range(3000):  # the marquees: length along their local x, the door in the gable end at +x
        if marquees == wanted:
            break
        w, l = float(rng.uniform(4.0, 7.0)), float(rng.uniform(5.0, 9.0))
        c = np.array([rng.uniform(8.0, size_x - 8.0), rng.uniform(8.0, size_z - 8.0)])
        r = math.hypot(w, l) / 2 + 1.5
        if not free(c, r):
            continue
        taken.append((c, r))
        marquees += 1
        angle = float(rng.uniform(0.0, 2 * math.pi))
        half_w, half_l = w / 2, l / 2
        walls = [((-half_l, -half_w), (half_l, -half_w)), ((-half_l, half_w), (half_l, half_w)),
                 ((-half_l, -half_w), (-half_l, half_w))]
        door_lo, door_hi = -1.1, 1.1  # the door's jambs along the +x gable, metres from its middle
        walls += [((half_l, -half_w), (half_l, door_lo)), ((half_l, door_hi), (half_l, half_w))]
        for (ax, az), (bx, bz) in walls:
            a, b = turned(c, angle, ax, az), turned(c, angle, bx, bz)
            n = np.array([-(b - a)[1], (b - a)[0]]) / np.linalg.norm(b - a) * 0.025  # half the canvas's thickness
            s.hull(np.array([[p[0] + sn * n[0], y, p[1] + sn * n[1]]
                             for p in (a, b) for sn in (-1, 1) for y in (0.0, 2.3)]))
        ridge = 2.3 + half_w * math.tan(math.radians(50.0))
        eaves = [turned(c, angle, sx * half_l, sz * half_w) for sx in (-1, 1) for sz in (-1, 1)]
        ridge_ends = [turned(c, angle, sx * half_l, 0.0) for sx in (-1, 1)]
        s.hull(np.array([[p[0], y, p[1]] for p in eaves for y in (2.3, 2.35)]
                        + [[p[0], ridge, p[1]] for p in ridge_ends]))
    tents = 0
    for _ in range(6000):  # the small tents
        if tents == int(rng.integers(120, 161)):
            break
        w, l = float(rng.uniform(1.4, 2.4)), float(rng.uniform(2.2, 3.0))
        c = np.array([rng.uniform(3.0, size_x - 3.0), rng.uniform(3.0, size_z - 3.0)])
        if not free(c, math.hypot(w, l) / 2 + 0.4):
            continue
        taken.append((c, math.hypot(w, l) / 2 + 0.4))
        tents += 1
        angle = float(rng.uniform(0.0, 2 * math.pi))
        floor = [turned(c, angle, sx * l / 2, sz * w / 2) for sx in (-1, 1) for sz in (-1, 1)]
        ridge = [turned(c, angle, sx * l / 2, 0.0) for sx in (-1, 1)]
        s.hull(np.array([[p[0], -0.3, p[1]] for p in floor] + [[p[0], 1.2, p[1]] for p in ridge]))
    return s.mesh()


KINDS: dict[str, Callable[[int], trimesh.Trimesh]] = {
    "container_maze": container_maze, "listing_ferry": listing_ferry,
    "pipe_network": pipe_network, "boardwalk": boardwalk,
    "car_lot": car_lot, "festival_camp": festival_camp,
}
"""Kind name -> generator (seed -> Y-up mesh in metres) of the twenty-seventh round."""


if __name__ == "__main__":
    write_kinds(kinds=KINDS, description=__doc__.splitlines()[0])
