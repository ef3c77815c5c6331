"""Level kinds of the thirty-first held-out round (issue 9): generators no preset setting was made on.

Six kinds of shipped game levels that stress what no earlier round did, each about 400-1,200 navmesh polygons with the
presets' agent (radius 0.5 m, height 2 m, climb 0.4 m, slope 45 degrees), seeds 0-2, built from the solids and helpers
of ``benchmarks/level_kinds.py`` (imported, not copied): ``crypt`` (groin-vaulted bays whose curved ceilings, crowns
2.15-2.35 m over the floor, leave head room only in a lattice of lanes under the crowns), ``solar_farm`` (rows of panel
tables tilted at 50 degrees whose low edges hang 0.6-1.2 m over the ground: floor under the high side only),
``mirror_maze`` (a maze of mirrors on a triangular lattice, every corridor at 0, 60 or 120 degrees and about the agent's
need), ``temple_steps`` (a sanctuary of temples on platforms of three steps whose risers, 0.42-0.50 m, stand just over
the agent's climb, each reached by one flight), ``ice_floes`` (a frozen lake broken into floes by cracks 0.05-0.6 m
wide, about Recast's cell of 0.25 m) and ``bell_towers`` (towers climbed only by turret stairs whose clear width,
1.55-2.25 m drawn per stair, straddles what the agent needs on a helix).

Run: ``.venv/bin/python benchmarks/level_kinds31.py OUT_DIR [--kinds crypt ice_floes] [--seeds 0 1 2]`` writes
``OUT_DIR/<kind>_s<seed>.obj``; ``benchmarks/analysis_quality.py --levels`` takes the kinds' names too."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import trimesh
from level_kinds import _lid, _ridged, _sector, _Solids, _trunk, _wall_line
from level_kinds import main as write_kinds
from level_kinds30 import _placed


def _vault_quadrant(s: _Solids, centre: np.ndarray, half: float, crown: float, spring: float, top: float,
                    signs: tuple[float, float], pieces: int = 8) -> None:
    """One quarter of a groin vault over the square bay of half side ``half`` m about plan point ``centre`` (x, z):
    the solid between the vault's underside and ``top``. A groin vault is two barrel vaults crossing, so under it
    the ceiling at offsets (u, v) from the bay's middle is f(min(u, v)), f(t) = spring + (crown - spring)
    sqrt(1 - (t / half)^2) (an elliptical arch from ``spring`` at the bay's edge to ``crown`` on its middle lines).
    Each of the quarter's two triangles (u <= v and v <= u) is cut into ``pieces`` strips, each one convex hull under
    the arch's chord. O(pieces) solids."""
    ts = np.linspace(0.0, half, pieces + 1)
    fs = spring + (crown - spring) * np.sqrt(np.clip(1.0 - (ts / half) ** 2, 0.0, 1.0))
    su, sv = signs
    for k in range(pieces):
        t0, t1, f0, f1 = ts[k], ts[k + 1], fs[k], fs[k + 1]
        for swap in (False, True):  # the triangle where v (swap: u) is the smaller offset
            corners = [(t0, t0, f0), (half, t0, f0), (half, t1, f1), (t1, t1, f1)]  # (u, v, y) with v = min
            points = []
            for u, v, y in corners:
                if swap:
                    u, v = v, u
                p = centre + np.array([su * u, sv * v])
                points += [[p[0], y, p[1]], [p[0], top, p[1]]]
            s.hull(np.array(points))


def crypt(seed: int, bays: tuple[int, int, int, int] = (12, 15, 5, 7)) -> trimesh.Trimesh:
    """A church's crypt (a gothic adventure's or a horror game's) under its nave: 12-14 x 5-6 square bays (``bays``: the
    ranges [a, b) x [c, d) they are drawn from) 4.2-4.8 m a side, each groin-vaulted (:func:`_vault_quadrant`) from a
    springing 1.3 m over the floor at its corners to a crown 2.15-2.35 m over it on its middle lines (drawn per bay):
    head room of the agent's 2 m only within 0.57-0.75 of a half bay of each middle line, so of a floor with no wall
    inside it the agent walks a lattice of lanes with 2.4-3.6 m of head room across (1.4-2.6 m for its centre), one
    along each row and column of bays. Piers 0.7 m square at every inner bay corner, walls 0.6 m thick round it; stone
    tombs (1 x 2.2 m, 0.9 m high) in the middle of about one inner bay in eight, no two side by side. The nave above
    (its floor 3.3 m over the crypt's, 8.4 m beyond it at each end) holds pews either side of a middle aisle and an
    altar on two steps; the crypt is entered only down two flights (17 risers, 1.8 m wide), one from each end of the
    nave, in wells outside its walls, each through a door (lintel 2.4 m) into the middle row of bays.

    Expected (written before the first run): one area. In the crypt, floor only on the lanes under the vaults'
    middle lines, none near a pier or along the walls; the structure along those lanes, never through a pier, a tomb
    or a wall, nor across a vault's low corner. Traffic highest on the crypt's middle lane between its two doors and
    on the nave's middle aisle, lowest in the crypt's corner bays and in the lanes a tomb ends."""
    rng = np.random.default_rng(seed)
    nx, nz, bay = int(rng.integers(bays[0], bays[1])), int(rng.integers(bays[2], bays[3])), float(rng.uniform(4.2, 4.8))
    length, width, storey = nx * bay, nz * bay, 3.3
    spring, top = 1.3, storey - 0.3  # the vaults' solids stop under the nave's floor slab
    s = _Solids()
    s.box(-0.6, length + 0.6, -0.3, 0.0, -0.6, width + 0.6)  # the crypt's floor
    tombs: set[tuple[int, int]] = set()
    for i in range(1, nx - 1):
        for j in range(1, nz - 1):
            if rng.random() < 0.125 and not {(i - 1, j), (i, j - 1), (i - 1, j - 1), (i + 1, j - 1)} & tombs:
                tombs.add((i, j))
    for i in range(nx):
        for j in range(nz):
            centre = np.array([(i + 0.5) * bay, (j + 0.5) * bay])
            crown = float(rng.uniform(2.15, 2.35))
            for signs in ((1.0, 1.0), (1.0, -1.0), (-1.0, 1.0), (-1.0, -1.0)):
                _vault_quadrant(s, centre, bay / 2, crown, spring, top, signs)
            if (i, j) in tombs:
                s.box(centre[0] - 1.1, centre[0] + 1.1, -0.1, 0.9, centre[1] - 0.5, centre[1] + 0.5)
    for i in range(1, nx):
        for j in range(1, nz):
            s.box(i * bay - 0.35, i * bay + 0.35, 0.0, top, j * bay - 0.35, j * bay + 0.35)
    door_z = (nz // 2 + 0.5) * bay
    for x in (-0.3, length + 0.3):
        s.wall((x, -0.6), (x, width + 0.6), 0.0, storey, [(door_z - 0.9 + 0.6, 1.8)], thickness=0.6)
        s.box(x - 0.3, x + 0.3, 2.4, storey, door_z - 0.9, door_z + 0.9)  # the door's lintel
    for z in (-0.3, width + 0.3):
        s.wall((-0.6, z), (length + 0.6, z), 0.0, storey, thickness=0.6)
    # the wells: a flight down from the nave to a landing 1.2 m before each door, between walls that rise on as the
    # rails round the nave floor's hole over it
    run, holes = 17 * 0.3, []
    for foot, heading in ((-1.8, -1.0), (length + 1.8, 1.0)):
        head = foot + heading * run
        s.stairs(np.array([foot, door_z]), np.array([heading, 0.0]), 1.8, 0.0, storey, storey / 17, 0.3)
        x0, x1 = sorted((head, foot - heading * 1.2))
        holes.append((x0, x1, door_z - 0.9, door_z + 0.9))
        s.box(*sorted((foot, foot - heading * 1.2)), -0.3, 0.0, door_z - 0.9, door_z + 0.9)  # the landing at its foot
        for z in (door_z - 1.05, door_z + 1.05):
            s.box(x0, x1, 0.0, storey + 1.0, z - 0.15, z + 0.15)
    nave_x0, nave_x1, nave_z0, nave_z1 = -9.0, length + 9.0, -1.0, width + 1.0
    s.slab(nave_x0, nave_x1, nave_z0, nave_z1, storey, holes, thickness=0.3)
    for x in (nave_x0, nave_x1):
        s.wall((x, nave_z0), (x, nave_z1), storey, storey + 6.0, thickness=0.5)
    for z in (nave_z0, nave_z1):
        s.wall((nave_x0, z), (nave_x1, z), storey, storey + 6.0, thickness=0.5)
    _lid(s, nave_x0 - 0.3, nave_x1 + 0.3, nave_z0 - 0.3, nave_z1 + 0.3, storey + 6.0)
    aisle_z = (nave_z0 + nave_z1) / 2
    x = 2.0
    while x < length - 4.0:  # pews either side of a middle aisle 3 m wide, 1.1 m apart
        for z0, z1 in ((nave_z0 + 1.5, aisle_z - 1.5), (aisle_z + 1.5, nave_z1 - 1.5)):
            s.box(x, x + 0.6, storey - 0.1, storey + 0.9, z0, z1)
        x += 1.7
    for k, rise in enumerate((0.15, 0.30)):  # the altar's two steps at the east end, the altar on them
        s.box(length + 2.0 + 0.4 * k, length + 6.0, storey, storey + rise,
              aisle_z - 3.0 + 0.4 * k, aisle_z + 3.0 - 0.4 * k)
    s.box(length + 4.0, length + 5.5, storey + 0.2, storey + 1.3, aisle_z - 1.2, aisle_z + 1.2)
    return s.mesh()


def solar_farm(seed: int) -> trimesh.Trimesh:
    """A solar farm (an open-world shooter's or a survival game's) 130-145 x 95-105 m inside a fence 2.2 m high with
    one gate 6 m wide: a perimeter track, a central track 6 m wide along z cutting two blocks of rows, each row a line
    of panel tables along x, 18-24 m long between crossings 3 m wide. Each table faces south, tilted at 50 degrees (a
    northern site's angle, over the agent's slope limit: nothing on a panel is floor), its plan 2.4-3.0 m deep, its low
    (south) edge 0.6-1.2 m over the ground (drawn per row) and its high edge 3.5-4.8 m: the agent stands under the high
    side only, where the underside is over 2 m, from 0.7-1.2 m (in plan) behind the low edge on. Posts 0.15 m square
    every 3.5 m under both edges; aisles 1.6-2.8 m between the rows (drawn per block). Inverter huts (ridged) between
    the perimeter track and the first rows, a substation in a fenced yard (a gate 4 m wide, transformers), an operations
    building (ridged) by the gate.

    Expected (written before the first run): one area. Floor in every aisle, widened under each table's high side and
    along the rear posts' line, none under a low edge; the structure along the aisles and under the high sides, never
    under a panel where it hangs under 2 m, through a post or the fence. Traffic highest on the central track and the
    perimeter track between the gate and the blocks, lowest in the aisles' middles between crossings."""
    rng = np.random.default_rng(seed)
    size_x, size_z = float(rng.uniform(130.0, 145.0)), float(rng.uniform(95.0, 105.0))
    tilt = math.tan(math.radians(50.0))
    s = _Solids()
    yard = (size_x - 40.0, size_x - 8.0, size_z - 30.0, size_z - 8.0)  # the substation (north-east)
    office = (10.0, 24.0, 10.0, 18.0)
    transformers = [(yard[0] + 9.0 + 8.0 * k, yard[0] + 13.0 + 8.0 * k, yard[2] + 8.0, yard[2] + 12.0)
                    for k in range(3)]
    huts = []
    for k in range(int(rng.integers(3, 6))):  # inverter huts between the perimeter track and the first rows
        x = 14.0 + k * (size_x - 30.0) / 5.0 + float(rng.uniform(0.0, 6.0))
        huts.append((x, x + 3.0, 20.0, 22.5))
    for plan in [office] + transformers + huts:  # closed bodies the ground stops under
        _ridged(s, *plan, 0.0, 3.0)
    s.ground(0.0, size_x, 0.0, size_z, 0.0, [office] + transformers + huts)
    gate = float(rng.uniform(30.0, 50.0))
    for z in (0.0, size_z):
        s.wall((0.0, z), (size_x, z), 0.0, 2.2, [(gate, 6.0)] if z == 0.0 else [], thickness=0.1)
    for x in (0.0, size_x):
        s.wall((x, 0.0), (x, size_z), 0.0, 2.2, thickness=0.1)
    s.wall((yard[0], yard[2]), (yard[1], yard[2]), 0.0, 2.2, [(4.0, 4.0)], thickness=0.1)
    s.wall((yard[0], yard[3]), (yard[1], yard[3]), 0.0, 2.2, thickness=0.1)
    for x in (yard[0], yard[1]):
        s.wall((x, yard[2]), (x, yard[3]), 0.0, 2.2, thickness=0.1)
    middle = size_x / 2
    for x0, x1 in ((12.0, middle - 3.0), (middle + 3.0, size_x - 12.0)):
        aisle = float(rng.uniform(1.6, 2.8))
        z = 26.0
        while True:
            depth, low = float(rng.uniform(2.4, 3.0)), float(rng.uniform(0.6, 1.2))
            high = low + depth * tilt
            if z + depth > size_z - 12.0 or (x1 > yard[0] and z + depth > yard[2] - 4.0):
                break
            cuts = [x0]
            while cuts[-1] + 18.0 < x1:
                cuts.append(min(x1, cuts[-1] + float(rng.uniform(18.0, 24.0))))
            for a, b in zip(cuts[:-1], cuts[1:]):
                a, b = a + 1.5, b - 1.5  # crossings 3 m wide between tables
                if b - a < 6.0:
                    continue
                s.hull(np.array([[x, y + d, zz] for x in (a, b) for zz, y in ((z, low), (z + depth, high))
                                 for d in (0.0, 0.08)]))
                post = a + 0.2
                while post < b:
                    for pz, py in ((z + 0.15, low), (z + depth - 0.15, high - 0.3)):
                        s.box(post - 0.075, post + 0.075, 0.0, py, pz - 0.075, pz + 0.075)
                    post += 3.5
            z += depth + aisle
    return s.mesh()


def mirror_maze(seed: int) -> trimesh.Trimesh:
    """A fairground's mirror maze (a horror or a carnival level) in a tent hall 60-66 x 40-44 m (walls 3 m, under a
    ridged lid 3.5 m up): mirrors 0.1 m thick and 2.4 m high stand on the edges of a lattice of equilateral triangles
    of side 3.0-3.3 m (drawn per seed; a triangle's inscribed circle 0.87-0.95 m in radius, the agent 0.5 m), posts
    0.2 m across at the lattice's corners, so every corridor runs at 0, 60 or 120 degrees and is about the agent's
    need. The maze is a random spanning tree of the triangles (depth first), each mirror between two triangles of the
    tree left out, and one in ten of the others too (loops, as real mirror mazes have); an entrance and an exit on the
    maze's south side, onto a lobby 6 m deep along the hall's south wall (a ticket booth in it, a door at each end).
    The half triangles between the lattice's ragged ends and the hall's walls are solid.

    Expected (written before the first run): one area. Floor in every triangle (the tree reaches all), the corridors
    through the left-out mirrors; the structure along the corridors, never through a mirror or a post. Traffic highest
    on the path from the entrance to the exit and in the lobby, lowest in the tree's dead-end triangles."""
    rng = np.random.default_rng(seed)
    side = float(rng.uniform(3.0, 3.3))
    size_x, size_z, lobby = float(rng.uniform(60.0, 66.0)), float(rng.uniform(40.0, 44.0)), 6.0
    row_h = side * math.sqrt(3.0) / 2
    rows, cols = int((size_z - lobby - 1.0) // row_h), int((size_x - 2.0) // side)
    x_left, x_right, top = (size_x - cols * side) / 2, (size_x + cols * side) / 2, lobby + rows * row_h

    def corner(c: tuple[int, int]) -> np.ndarray:
        """Lattice corner c = (i, j): the i-th of row j, odd rows shifted east by half a side."""
        return np.array([x_left + (c[0] + 0.5 * (c[1] % 2)) * side, lobby + c[1] * row_h])

    def valid(c: tuple[int, int]) -> bool:
        return 0 <= c[0] <= cols - c[1] % 2 and 0 <= c[1] <= rows

    triangles = []
    for j in range(rows):
        shift = j % 2
        for i in range(cols + 1):
            for cs in (((i, j), (i + 1, j), (i + shift, j + 1)), ((i + 1 - shift, j), (i + 1, j + 1), (i, j + 1))):
                if all(valid(c) for c in cs):
                    triangles.append(cs)
    edges: dict[frozenset, list[int]] = {}
    for t, cs in enumerate(triangles):
        for a, b in ((cs[0], cs[1]), (cs[1], cs[2]), (cs[2], cs[0])):
            edges.setdefault(frozenset((a, b)), []).append(t)
    neighbours: dict[int, list[tuple[frozenset, int]]] = {t: [] for t in range(len(triangles))}
    for e, ts in edges.items():
        if len(ts) == 2:
            neighbours[ts[0]].append((e, ts[1]))
            neighbours[ts[1]].append((e, ts[0]))
    open_edges: set[frozenset] = set()
    seen, stack = {0}, [0]
    while stack:  # a random depth-first spanning tree: O(triangles)
        steps = [(e, o) for e, o in neighbours[stack[-1]] if o not in seen]
        if not steps:
            stack.pop()
            continue
        e, o = steps[int(rng.integers(len(steps)))]
        open_edges.add(e)
        seen.add(o)
        stack.append(o)
    doors = {frozenset(((i, 0), (i + 1, 0))) for i in (1, cols - 2)}  # the entrance and the exit
    s = _Solids()
    booth = (size_x / 2 - 2.0, size_x / 2 + 2.0, 0.2, 2.2)
    fillers = [(0.0, x_left, lobby, size_z), (x_right, size_x, lobby, size_z), (x_left, x_right, top, size_z)]
    s.ground(0.0, size_x, 0.0, size_z, 0.0, [booth] + fillers)  # Recast reads surfaces: no floor inside a solid
    s.box(-6.0, 0.0, -0.3, 0.0, 0.0, lobby)  # the fairground outside the lobby's doors
    s.box(size_x, size_x + 6.0, -0.3, 0.0, 0.0, lobby)
    for e, ts in edges.items():
        if e in open_edges or e in doors or (len(ts) == 2 and rng.random() < 0.1):
            continue
        a, b = (corner(c) for c in e)
        _wall_line(s, a, b, 0.0, 2.4, 0.1, [])
    for c in {c for cs in triangles for c in cs}:
        p = corner(c)
        s.box(p[0] - 0.1, p[0] + 0.1, 0.0, 2.4, p[1] - 0.1, p[1] + 0.1)
    half = side / 2
    for j in range(rows):  # the half triangles at the ragged ends, and everything beyond them, solid
        z0, z1 = lobby + j * row_h, lobby + (j + 1) * row_h
        if j % 2 == 0:
            west = [(x_left, z0), (x_left + half, z1), (x_left, z1)]
            east = [(x_right, z0), (x_right, z1), (x_right - half, z1)]
        else:
            west = [(x_left, z0), (x_left + half, z0), (x_left, z1)]
            east = [(x_right - half, z0), (x_right, z0), (x_right, z1)]
        for plan in (west, east):
            s.prism(np.array(plan), 0.0, 2.4)
    for x0, x1, z0, z1 in fillers:
        s.box(x0, x1, 0.0, 2.4, z0, z1)
    for x in (0.0, size_x):  # the hall, a door 2 m wide at each end of the lobby
        s.wall((x, 0.0), (x, size_z), 0.0, 3.0, [(2.0, 2.0)], thickness=0.3)
    for z in (0.0, size_z):
        s.wall((0.0, z), (size_x, z), 0.0, 3.0, thickness=0.3)
    s.box(booth[0], booth[1], 0.0, 2.6, booth[2], booth[3])  # the ticket booth
    _lid(s, -0.3, size_x + 0.3, -0.3, size_z + 0.3, 3.5)
    return s.mesh()


def temple_steps(seed: int) -> trimesh.Trimesh:
    """An ancient sanctuary (a historical action game's) 150-170 x 105-120 m inside a wall 3 m high entered through a
    gatehouse 5 m wide in the south wall: up to 3 temples (as many as fit 5 m apart), each on a platform of three steps
    whose risers, 0.42-0.50 m (drawn per temple), stand just over the agent's 0.4 m climb, treads 0.9-1.2 m; each
    platform is climbed only by one flight of small steps (risers under 0.18 m, 3-4 m wide) in the middle of its east
    front, cut through the three steps. On each platform a ring of columns (1.1 m across, gaps 1.3-1.7 m) round a walled
    cella entered by a door 3 m wide from the east (the front's middle gap as wide as the flight), all under a ridged
    roof; an altar (1.2 m high) east of each temple; along the north wall a stoa (a colonnade 8 m deep on one step of
    0.16 m, roofed) and statues on plinths 1.5 m high about the ground.

    Expected (written before the first run): one area. Each platform's top and the treads of its three steps reached
    up its flight alone, never up the tall steps (which a player in a game climbs but the agent does not); the
    structure up each flight, never straight up a platform's side. Traffic highest from the gatehouse to the temples'
    flights and through the columns into each cella, lowest behind the temples and in the stoa's ends."""
    rng = np.random.default_rng(seed)
    size_x, size_z = float(rng.uniform(150.0, 170.0)), float(rng.uniform(105.0, 120.0))
    s = _Solids()
    gate = size_x / 2 - 2.5
    piers = [(x, x + 3.0, -3.0, 3.0) for x in (gate - 3.0, gate + 5.0)]
    s.ground(0.0, size_x, 0.0, size_z, 0.0, piers)
    s.wall((0.0, 0.0), (size_x, 0.0), 0.0, 3.0, [(gate, 5.0)], thickness=0.6)
    s.wall((0.0, size_z), (size_x, size_z), 0.0, 3.0, thickness=0.6)
    for x in (0.0, size_x):
        s.wall((x, 0.0), (x, size_z), 0.0, 3.0, thickness=0.6)
    for plan in piers:  # the gatehouse's
        _ridged(s, *plan, 0.0, 6.0)
    spots: list[tuple[np.ndarray, float]] = []
    stoa = (10.0, size_x - 10.0, size_z - 9.0, size_z - 1.0)
    keep = [stoa, (gate - 8.0, gate + 13.0, 0.0, 20.0)]
    for _ in range(3):
        long_side, short_side = float(rng.uniform(28.0, 36.0)), float(rng.uniform(15.0, 19.0))
        p = _placed(rng, spots, 6.0, size_x - 6.0, 6.0, size_z - 12.0, long_side / 2 + 5.0, keep)
        if p is None:
            continue
        riser, tread = float(rng.uniform(0.42, 0.50)), float(rng.uniform(0.9, 1.2))
        hx, hz = short_side / 2, long_side / 2  # the temple's long side along z, its front facing east (+x)
        flight_w = float(rng.uniform(3.0, 4.0))
        for k in range(3):  # the steps, each cut by the flight's slot
            grow = (2 - k) * tread
            x0, x1, z0, z1 = p[0] - hx - grow, p[0] + hx + grow, p[1] - hz - grow, p[1] + hz + grow
            slot = [(p[0] + hx, x1 + 0.01, p[1] - flight_w / 2, p[1] + flight_w / 2)] if grow else []
            s.slab(x0, x1, z0, z1, riser * (k + 1), slot, thickness=riser * (k + 1) + 0.3)
        height = 3 * riser
        steps = math.ceil(height / 0.18)
        s.stairs(np.array([p[0] + hx + 2 * tread + 0.3 * steps, p[1]]), np.array([-1.0, 0.0]), flight_w, 0.0, height,
                 height / steps, 0.3)
        # the flight's top landing fills the slot through the two lower steps
        s.box(p[0] + hx - 0.01, p[0] + hx + 2 * tread, -0.3, height, p[1] - flight_w / 2, p[1] + flight_w / 2)
        cx0, cx1, cz0, cz1 = p[0] - hx + 3.5, p[0] + hx - 3.5, p[1] - hz + 4.0, p[1] + hz - 4.0  # the cella
        s.wall((cx1, cz0), (cx1, cz1), height, height + 8.0, [((cz1 - cz0) / 2 - 1.5, 3.0)], thickness=0.6)
        s.wall((cx0, cz0), (cx0, cz1), height, height + 8.0, thickness=0.6)
        for z in (cz0, cz1):
            s.wall((cx0 - 0.3, z), (cx1 + 0.3, z), height, height + 8.0, thickness=0.6)
        gap = float(rng.uniform(1.3, 1.7))
        for a, b, fixed, along_x in ((p[1] - hz + 1.0, p[1] + hz - 1.0, p[0] - hx + 1.0, False),
                                     (p[1] - hz + 1.0, p[1] + hz - 1.0, p[0] + hx - 1.0, False),
                                     (p[0] - hx + 1.0, p[0] + hx - 1.0, p[1] - hz + 1.0, True),
                                     (p[0] - hx + 1.0, p[0] + hx - 1.0, p[1] + hz - 1.0, True)):
            n = max(2, round((b - a) / (1.1 + gap)) + 1)
            front = fixed > p[0] and not along_x
            for q in np.linspace(a, b, n):
                if front and abs(q - p[1]) < flight_w / 2 + 0.55:  # the front's middle gap, as wide as the flight
                    continue
                _trunk(s, np.array([q, fixed] if along_x else [fixed, q]), 0.55, height, height + 8.0)
        _lid(s, p[0] - hx, p[0] + hx, p[1] - hz, p[1] + hz, height + 8.0)
        altar_x = p[0] + hx + 2 * tread + 0.3 * steps + 6.0
        s.box(altar_x, altar_x + 2.0, -0.1, 1.2, p[1] + flight_w, p[1] + flight_w + 3.0)
    s.box(stoa[0], stoa[1], -0.3, 0.16, stoa[2], stoa[3])  # the stoa: a step, a back wall, columns, a roof
    for q in np.arange(stoa[0] + 1.0, stoa[1] - 0.5, 3.0):
        _trunk(s, np.array([q, stoa[2] + 0.8]), 0.45, 0.16, 5.0)
    _lid(s, stoa[0], stoa[1], stoa[2], stoa[3] + 1.0, 5.0)
    for _ in range(8):  # statues on plinths
        q = _placed(rng, spots, 8.0, size_x - 8.0, 8.0, size_z - 12.0, 1.5, keep)
        if q is not None:
            s.box(q[0] - 0.8, q[0] + 0.8, -0.1, 1.5, q[1] - 0.8, q[1] + 0.8)
            _ridged(s, q[0] - 0.4, q[0] + 0.4, q[1] - 0.4, q[1] + 0.4, 1.5, 3.5)
    return s.mesh()


def _cut_convex(plan: np.ndarray, normal: np.ndarray, offset: float) -> np.ndarray:
    """The part (k, 2) of the convex plan polygon ``plan`` (n, 2) where normal . p >= offset (Sutherland and
    Hodgman's clipping against one half-plane, 1974); empty (0, 2) when none. O(n)."""
    out = []
    for a, b in zip(plan, np.roll(plan, -1, axis=0)):
        da, db = float(normal @ a) - offset, float(normal @ b) - offset
        if da >= 0.0:
            out.append(a)
        if (da >= 0.0) != (db >= 0.0):
            out.append(a + (b - a) * da / (da - db))
    return np.array(out).reshape(-1, 2)


def ice_floes(seed: int) -> trimesh.Trimesh:
    """A frozen lake broken into floes (a survival game's or an arctic shooter's): 130-150 x 90-100 m of ice 0.4 m
    thick at y = 0 between two shores (ground 0.2 m higher, 30 m deep, along its west and east sides), open water (no
    floor) under it. 16-20 straight cracks at random angles run from shore to shore or side to side, each 0.05-0.6 m
    wide (drawn per crack), about Recast's cell of 0.25 m and the step a person takes over a crack: every floe is the
    convex piece of the lake between cracks (:func:`_cut_convex`), shrunk by half of each crack's width; the lake meets
    each shore across a crack too. On the ice: fishing huts (ridged, 2 x 3 m, eaves 0.5 m), sleds (1 m high), a pressure
    ridge of blocks; on the shores: cabins (ridged), trees, a jetty.

    Expected (written before the first run): cracks under a cell's width no break, floes across them one floor; a crack
    of 0.3-0.6 m a break the agent does not cross (it does not jump), so the lake falls into several areas, some
    joined to a shore and some adrift; the structure never across an open crack. Traffic highest on each shore and on
    the floes that join them, none on a floe adrift."""
    rng = np.random.default_rng(seed)
    lake_x, lake_z, shore = float(rng.uniform(130.0, 150.0)), float(rng.uniform(90.0, 100.0)), 30.0
    s = _Solids()
    cracks = []
    for _ in range(int(rng.integers(16, 21))):
        angle = float(rng.uniform(0.0, math.pi))
        normal = np.array([math.cos(angle), math.sin(angle)])
        through = np.array([rng.uniform(0.1, 0.9) * lake_x, rng.uniform(0.1, 0.9) * lake_z])
        cracks.append((normal, float(normal @ through), float(rng.uniform(0.05, 0.6))))
    edge = [float(rng.uniform(0.05, 0.6)) for _ in range(2)]  # the cracks along the west and east shores
    floes = [np.array([[edge[0], 0.0], [lake_x - edge[1], 0.0], [lake_x - edge[1], lake_z], [edge[0], lake_z]])]
    for normal, offset, width in cracks:
        pieces = []
        for plan in floes:
            for sign in (1.0, -1.0):
                part = _cut_convex(plan, sign * normal, sign * offset + width / 2)
                if len(part) >= 3:
                    pieces.append(part)
        floes = pieces
    for plan in floes:
        x, z = plan[:, 0], plan[:, 1]
        area = 0.5 * abs(float(x @ np.roll(z, -1) - z @ np.roll(x, -1)))  # the shoelace formula
        if area > 0.05:
            s.prism(plan, -0.4, 0.0)
    spots: list[tuple[np.ndarray, float]] = []
    for _ in range(10):  # fishing huts and sleds on the ice
        p = _placed(rng, spots, 5.0, lake_x - 5.0, 5.0, lake_z - 5.0, 2.2, [])
        if p is not None and rng.random() < 0.6:
            _ridged(s, p[0] - 1.0, p[0] + 1.0, p[1] - 1.5, p[1] + 1.5, -0.2, 0.5)  # its ridge 2.29 m up
        elif p is not None:
            s.box(p[0] - 0.6, p[0] + 0.6, -0.2, 1.0, p[1] - 1.2, p[1] + 1.2)
    ridge_z = float(rng.uniform(0.3, 0.7)) * lake_z
    for x in np.arange(20.0, lake_x - 20.0, 2.5):  # a pressure ridge: blocks with gaps
        if rng.random() < 0.6:
            s.box(x, x + 1.6, -0.2, float(rng.uniform(0.6, 1.4)), ridge_z - 0.8, ridge_z + 0.8)
    for x0 in (-shore, lake_x):  # each shore's ground stops under its cabins (Recast reads surfaces, not solids)
        cabins = []
        for _ in range(4):
            z = float(rng.uniform(5.0, lake_z - 12.0))
            x = x0 + float(rng.uniform(6.0, shore - 14.0))
            cabins.append(_ridged(s, x, x + 8.0, z, z + 6.0, 0.2, 3.0))
        s.ground(x0, x0 + shore, 0.0, lake_z, 0.2, cabins, thickness=1.0)
        for _ in range(10):
            _trunk(s, np.array([x0 + rng.uniform(2.0, shore - 2.0), rng.uniform(2.0, lake_z - 2.0)]), 0.3, 0.2, 6.0)
    jetty_z = float(rng.uniform(20.0, lake_z - 20.0))
    s.box(-4.0, 0.0, -0.1, 0.35, jetty_z - 1.5, jetty_z + 1.5)
    return s.mesh()


def _turret_stair(s: _Solids, centre: np.ndarray, y0: float, turns: int, turn_rise: float, outer: float,
                  per_turn: int, door: float) -> float:
    """A newel stair in a round turret about plan point ``centre`` (x, z) from ``y0`` up ``turns`` turns of
    ``turn_rise`` m: a newel 0.25 m in radius (:func:`level_kinds._trunk`) and ``per_turn`` wedges a turn, each 0.12 m
    thick, from the newel to radius ``outer`` (the clear width outer - 0.25 m), counter-clockwise: ``per_turn`` - 2
    steps, then a landing of three wedges at the turn's top (its last step and two more), whose middle faces the angle
    ``door`` (radians). The turret's wall (0.3 m, 20 pieces) is open over each landing's middle and over the foot,
    below the first landing, with a sill through the wall at each landing. Returns the top's height. O(turns x
    per_turn) solids."""
    sector, riser = 2 * math.pi / per_turn, turn_rise / (per_turn - 2)
    start = door - (per_turn - 1.5) * sector  # the first step's start, so that each landing's middle wedge faces door
    for k in range(turns):
        for m in range(per_turn):
            a, y = start + (k * per_turn + m) * sector, y0 + k * turn_rise + riser * min(m + 1, per_turn - 2)
            s.prism(centre + _sector(0.2, outer + 0.05, a, a + sector * 1.02), y - 0.12, y)
        sill = y0 + (k + 1) * turn_rise
        s.prism(centre + _sector(outer - 0.1, outer + 0.35, door - sector, door + sector), sill - 0.12, sill)
    _trunk(s, centre, 0.25, y0 - 0.3, y0 + turns * turn_rise + 2.5)
    pieces, width = 20, 2 * math.pi / 20
    for k in range(turns + 1):
        for m in range(pieces):
            if abs(math.remainder((m + 0.5) * width - door, 2 * math.pi)) < sector + width / 2:
                continue
            y = y0 + k * turn_rise
            s.prism(centre + _sector(outer, outer + 0.3, m * width, (m + 1) * width), y - (0.0 if k else 0.3),
                    y + (turn_rise if k < turns else 1.1))
    return y0 + turns * turn_rise


def bell_towers(seed: int) -> trimesh.Trimesh:
    """A town square (an assassination game's or a medieval sandbox's) 90-100 x 70-80 m, paved, houses (ridged)
    round it leaving four streets out, and up to four towers 7-8 m square (as many as fit 5 m apart, off the streets'
    lines), each of 3-4 storeys of 3.2 m (a room on each, the ground's with a door 1.6 m wide onto the square, a bell
    chamber on top open under a roof, its parapet 1.1 m high, a bell hanging to 1.6 m over its floor), each climbed only
    by a turret stair (:func:`_turret_stair`, 14 steps and a landing a turn of 3.2 m, risers 0.23 m) against its east
    wall, a door 1.6 m wide from every storey onto the turret's landing: the stair's clear width, 1.55-2.25 m (drawn per
    tower), straddles what a helix of wedges needs for the agent on Recast's cells of 0.25 m (its 1 m plus the cells
    rounded off on both curved sides: about 1.9 m on a draft of one turret alone, where 1.0-1.45 m, a real turret's
    width, never held floor). A fountain (its basin a step of 0.35 m), 40 market stalls (0.9 m high, 1 x 2 m) and
    benches on the square.

    Expected (written before the first run): the square and its streets one area; a tower's rooms joined to it up
    its turret where the stair's clear width is 1.95 m or more, otherwise apart (each storey an area of its own, or
    left out under the cover's smallest area). The structure up each walkable turret round its newel, never through
    its wall or a tower's; traffic highest across the square between the streets, lowest in the towers' top rooms."""
    rng = np.random.default_rng(seed)
    size_x, size_z = float(rng.uniform(90.0, 100.0)), float(rng.uniform(70.0, 80.0))
    s = _Solids()
    mx, mz = size_x / 2, size_z / 2
    blocks = [(-20.0, mx - 4.0, -20.0, 0.0), (mx + 4.0, size_x + 20.0, -20.0, 0.0),
              (-20.0, mx - 4.0, size_z, size_z + 20.0), (mx + 4.0, size_x + 20.0, size_z, size_z + 20.0),
              (-20.0, 0.0, 0.0, mz - 4.0), (-20.0, 0.0, mz + 4.0, size_z),
              (size_x, size_x + 20.0, 0.0, mz - 4.0), (size_x, size_x + 20.0, mz + 4.0, size_z)]
    s.ground(-20.0, size_x + 20.0, -20.0, size_z + 20.0, 0.0, blocks)
    for x0, x1, z0, z1 in blocks:  # each block a row of houses 6-9 m along its longer side, ridged
        along_x = x1 - x0 > z1 - z0
        lo, hi = (x0, x1) if along_x else (z0, z1)
        while lo < hi - 0.01:
            w = hi - lo if hi - lo < 12.0 else float(rng.uniform(6.0, 9.0))
            _ridged(s, *((lo, lo + w, z0, z1) if along_x else (x0, x1, lo, lo + w)), 0.0, 7.0)
            lo += w
    spots: list[tuple[np.ndarray, float]] = [(np.array([mx, mz]), 6.0)]
    _trunk(s, np.array([mx, mz]), 3.0, -0.1, 0.35)  # the fountain's basin (a step up) and its column
    _trunk(s, np.array([mx, mz]), 0.6, 0.35, 3.0)
    storey = 3.2
    streets = [(mx - 5.0, mx + 5.0, -1.0, size_z + 1.0), (-1.0, size_x + 1.0, mz - 5.0, mz + 5.0)]
    for _ in range(4):
        side, outer = float(rng.uniform(7.0, 8.0)), float(rng.uniform(1.8, 2.5))
        p = _placed(rng, spots, 6.0, size_x - 6.0 - 2 * outer, 6.0, size_z - 6.0, side / 2 + outer + 1.5, streets)
        if p is None:
            continue
        storeys = int(rng.integers(3, 5))
        x0, x1, z0, z1 = p[0] - side / 2, p[0] + side / 2, p[1] - side / 2, p[1] + side / 2
        turret = np.array([x1 + outer + 0.55, p[1]])  # against the east wall, its doors facing west into the tower
        top = _turret_stair(s, turret, 0.0, storeys, storey, outer, 16, math.pi)
        door = (side / 2 - 0.8, 1.6)
        for m in range(storeys + 1):  # each storey's floor and walls: a door to the turret, the ground's to the square
            y = m * storey
            height = storey if m < storeys else 1.1
            if m:
                s.box(x0, x1, y - 0.3, y, z0, z1)
                s.box(x1 - 0.3, turret[0] - outer + 0.2, y - 0.3, y, p[1] - 0.8, p[1] + 0.8)  # the threshold
            s.wall((x1, z0), (x1, z1), y, y + height, [door], thickness=0.5)
            s.wall((x0, z0), (x0, z1), y, y + height, [] if m else [door], thickness=0.5)
            for z in (z0, z1):
                s.wall((x0 - 0.25, z), (x1 + 0.25, z), y, y + height, thickness=0.5)
        for cx in (x0, x1):  # the bell chamber's corner posts, its roof and a bell hanging to 1.6 m over its floor
            for cz in (z0, z1):
                s.box(cx - 0.25, cx + 0.25, top, top + 3.5, cz - 0.25, cz + 0.25)
        _lid(s, x0 - 0.5, x1 + 0.5, z0 - 0.5, z1 + 0.5, top + 3.5)
        s.box(p[0] - 0.8, p[0] + 0.8, top + 1.6, top + 3.5, p[1] - 0.8, p[1] + 0.8)
    for _ in range(40):  # market stalls and benches
        q = _placed(rng, spots, 4.0, size_x - 4.0, 4.0, size_z - 4.0, 1.6, [])
        if q is not None:
            s.box(q[0] - 1.0, q[0] + 1.0, -0.1, 0.9, q[1] - 0.5, q[1] + 0.5)
    return s.mesh()


KINDS: dict[str, Callable[[int], trimesh.Trimesh]] = {
    "crypt": crypt, "solar_farm": solar_farm, "mirror_maze": mirror_maze,
    "temple_steps": temple_steps, "ice_floes": ice_floes, "bell_towers": bell_towers,
}
"""Kind name -> generator (seed -> Y-up mesh in metres) of the thirty-first round."""


if __name__ == "__main__":
    write_kinds(kinds=KINDS, description=__doc__.splitlines()[0])
