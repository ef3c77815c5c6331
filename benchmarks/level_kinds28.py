"""Level kinds of the twenty-eighth held-out round (issue 9): generators no preset setting was made on.

Six kinds of shipped game levels that stress what no earlier round did, each about 400-1,200 navmesh polygons with the
presets' agent (radius 0.5 m, height 2 m, climb 0.4 m, slope 45 degrees), seeds 0-2, built from the solids and
helpers of ``benchmarks/level_kinds.py`` (imported, not copied): ``double_helix`` (a car park whose decks are joined by
two helical ramps interleaved in one round well, each a storey a half turn, a storey apart over one another),
``low_station`` (a space station of modules and corridors whose ceilings stand 2.3-2.4 m over the floor, tight ones
2.05-2.2 m, just over the agent's 2 m, pipe runs lowering one side, hatches with sills, ducts 1.8 m high no one
walks), ``fallen_giants`` (a jungle floor split by a gorge crossed only by giant fallen trunks, and a plateau reached
only up leaning trunks),
``canal_city`` (a city of blocks between canals, quays along both banks, few humped step bridges: long parallel lanes
a canal apart), ``grand_stair`` (a mansion's hall whose imperial staircase splits at a half landing into two mirrored
flights meeting at a gallery: tied ways up) and ``data_hall`` (a data centre's raised floor of rack rows whose aisles
are 0.9-1.6 m wide, about the agent's 1 m, long and parallel, reached by a ramp and steps).

Run: ``.venv/bin/python benchmarks/level_kinds28.py OUT_DIR [--kinds double_helix canal_city] [--seeds 0 1 2]``
writes ``OUT_DIR/<kind>_s<seed>.obj``; ``benchmarks/analysis_quality.py --levels`` takes the kinds' names too.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import trimesh
from level_kinds import _car, _grid_edges, _random_tree, _ridged, _Solids, _stair_tower, _terrain, _well_length
from level_kinds import main as write_kinds


def _helix_ramp(s: _Solids, centre: np.ndarray, r0: float, r1: float, a0: float, a1: float, y0: float, y1: float,
                pieces: int) -> None:
    """A ramp over the ring r0 < r < r1 (m) about plan point ``centre`` from the angle ``a0`` to ``a1`` (radians,
    counter-clockwise seen from above along +x towards +z) climbing from ``y0`` to ``y1`` (its top, m): ``pieces``
    convex blocks 0.3 m thick, each a chord of its arc, top heights linear in the angle."""
    for k in range(pieces):
        corners = []
        for t in (k / pieces, (k + 1) / pieces):
            angle, top = a0 + t * (a1 - a0), y0 + t * (y1 - y0)
            for r in (r0, r1):
                p = centre + r * np.array([math.cos(angle), math.sin(angle)])
                corners += [[p[0], top, p[1]], [p[0], top - 0.3, p[1]]]
        s.hull(np.array(corners))


def double_helix(seed: int) -> trimesh.Trimesh:
    """A multi-storey car park of 4-5 decks over the ground (storeys 3 m), 62-70 x 40-46 m, whose decks are joined by a
    round ramp well in the middle (outer radius 10-11 m round a solid core 3 m in radius) holding *two helical ramps
    interleaved*: ramp A climbs from the ground at the well's east side, B from its west side, each a storey a half
    turn (about 8 degrees mid-ramp, 24 pieces a turn), so at any angle A and B lie a storey (2.7 m clear) over one
    another, and each deck meets one ramp at the east and the other at the west, through openings 40 degrees wide in
    the well's wall (full storey height) with a landing to the deck's edge. A pedestrian stair tower
    (:func:`level_kinds._stair_tower`, a door on every storey) stands in the south-west corner. Pillars 0.6 m square on
    a grid of about 8 m, cars (:func:`level_kinds._car`) in 55-75 % of the bays along the north and south edges, a
    parapet 1.1 m high round every deck above the ground, the ramps' well walled to 1.1 m on the top deck.

    Expected (written before the first run): one area (every deck reached by both ramps and by the stair tower).
    Traffic highest on the ramps' half turns and at the well's openings (a walk between two decks takes one of the two
    ramps or the tower), then on the decks' middles between the openings and the tower, lowest in the bays along the
    decks' far edges; a designer expects the structure along each half turn of each ramp (both helices, a storey
    apart), through the well's openings, never through its wall or from a ramp to the ramp a storey over it."""
    rng = np.random.default_rng(seed)
    storey, decks = 3.0, int(rng.integers(4, 6))
    length, depth = float(rng.uniform(62.0, 70.0)), float(rng.uniform(40.0, 46.0))
    outer, core = float(rng.uniform(10.0, 11.0)), 3.0
    centre = np.array([length / 2 + float(rng.uniform(-4.0, 4.0)), depth / 2])
    well = (centre[0] - outer, centre[0] + outer, centre[1] - outer, centre[1] + outer)
    opening = math.radians(20.0)  # half the openings' arc
    landings = [(centre[0] + outer * math.cos(opening) - 0.3, centre[0] + outer, centre[1] - outer * math.sin(opening),
                 centre[1] + outer * math.sin(opening)),
                (centre[0] - outer, centre[0] - outer * math.cos(opening) + 0.3, centre[1] - outer * math.sin(opening),
                 centre[1] + outer * math.sin(opening))]
    tower_x, tower_z, tower_well = 3.0, 4.0, _well_length(storey)
    tower = (tower_x - 0.4, tower_x + 4.4, tower_z, tower_z + tower_well + 0.4)
    s = _Solids()
    # the ground and the well's floor, stopping under the core (a square inside it: the ground it leaves inside the
    # core, under 1 m wide, holds no floor for the agent)
    s.ground(-1.0, length + 1.0, -1.0, depth + 1.0, 0.0,
             [(centre[0] - 2.0, centre[0] + 2.0, centre[1] - 2.0, centre[1] + 2.0)])
    _stair_tower(s, tower_x, tower_z, 0.0, decks, tuple(range(decks + 1)), storey)
    for k in range(1, decks + 1):
        y = k * storey
        s.slab(0.0, length, 0.0, depth, y, [well, tower])
        for landing in landings:
            s.box(landing[0], landing[1], y - 0.3, y, landing[2], landing[3])
        for a, b in (((0.0, 0.0), (length, 0.0)), ((0.0, depth), (length, depth)), ((0.0, 0.0), (0.0, depth)),
                     ((length, 0.0), (length, depth))):
            s.wall(a, b, y, y + 1.1, thickness=0.2)
    pieces = 36
    for k in range(decks + 1):  # the well's wall, storey by storey, open over the landings' arcs east and west
        y0 = k * storey
        y1 = y0 + (1.1 if k == decks else storey - 0.3)
        for j in range(pieces):
            a0, a1 = 2 * math.pi * j / pieces, 2 * math.pi * (j + 1) / pieces
            mid = (a0 + a1) / 2
            if min(abs(math.remainder(mid, math.pi)), abs(math.remainder(mid - math.pi, math.pi))) < opening:
                continue
            ring = [centre + r * np.array([math.cos(a), math.sin(a)]) for a in (a0, a1) for r in (outer - 0.3, outer)]
            s.hull(np.array([[p[0], y, p[1]] for p in ring for y in (y0, y1)]))
    ring = centre + core * np.array([[math.cos(a), math.sin(a)] for a in np.arange(16) * math.pi / 8])
    top = decks * storey + 1.0  # the core's top a cone at 50 degrees: no floor on it
    s.hull(np.array([[p[0], y, p[1]] for p in ring for y in (0.0, top)]
                    + [[centre[0], top + core * math.tan(math.radians(50.0)), centre[1]]]))
    for start in (0.0, math.pi):  # ramp A from the east, B from the west, each a storey a half turn
        _helix_ramp(s, centre, core, outer - 0.3, start, start + decks * math.pi, 0.0, decks * storey, 12 * decks)
    for k in range(decks + 1):
        y = k * storey
        for x in np.arange(8.0, length - 4.0, 8.0):  # pillars clear of the well, the tower and the bays' fronts
            for z in np.arange(8.0, depth - 4.0, 8.0):
                by_tower = x < tower[1] + 2.0 and z < tower[3] + 2.0
                if math.hypot(x - centre[0], z - centre[1]) > outer + 2.0 and not by_tower:
                    s.box(x - 0.3, x + 0.3, y, y + storey - 0.3, z - 0.3, z + 0.3)
        for z0, z1 in ((0.5, 5.0), (depth - 5.0, depth - 0.5)):
            filled = float(rng.uniform(0.55, 0.75))  # the share of this row's bays holding a car
            for x in np.arange(tower[1] + 3.0 if z0 < 1.0 else 1.0, length - 3.0, 2.5):
                if rng.random() < filled:
                    _car(s, x + 0.35, x + 2.15, z0, z1, y)
    return s.mesh()


def _hatch_wall(s: _Solids, a: tuple[float, float], b: tuple[float, float], ceiling: float,
                hatches: list[tuple[float, float]]) -> None:
    """A bulkhead 0.2 m thick from plan point ``a`` to ``b`` (along x or z) from the floor (0) to ``ceiling``, pierced
    by each hatch (start, width along the wall, as :meth:`_Solids.wall`'s doors): open from a sill 0.15 m high to a
    lintel 2.45 m over the floor (2.3 m clear)."""
    s.wall(a, b, 0.0, ceiling, hatches, thickness=0.2)
    along = 0 if a[1] == b[1] else 1
    lo = min(a[along], b[along])
    for start, width in hatches:
        c0, c1 = lo + start, lo + start + width
        for y0, y1 in ((0.0, 0.15), (2.45, ceiling)):
            if along == 0:
                s.box(c0, c1, y0, y1, a[1] - 0.1, a[1] + 0.1)
            else:
                s.box(a[0] - 0.1, a[0] + 0.1, y0, y1, c0, c1)


def low_station(seed: int) -> trimesh.Trimesh:
    """A space station's deck of 6-7 x 5-6 modules (rooms 9-12 x 7-9 m, ceilings 2.5-2.8 m) 16 x 14 m apart on a grid,
    joined by corridors 2.4-2.8 m wide *under low ceilings*, with a pipe run (0.3-0.4 m deep, its underside 1.7 m up)
    along one wall lowering the head room on that side. The corridors of a spanning tree of the grid have ceilings
    2.3-2.4 m over the floor; 30 % of the grid's other edges hold a corridor too, half of them *tight* (ceilings
    2.05-2.2 m, 0.05-0.2 m over the agent's 2 m), half ducts (1.8 m, under the agent's height: no one walks them).
    Every corridor enters a module through a hatch in its bulkhead: an opening 1.6 m wide from a sill 0.15 m high to a
    lintel 2.45 m up, under a collar 0.4 m long at the lintel's height (a ceiling lower than the lintel straight over
    the sill's edge shares Recast's cells with it: a first draft's hatches held no floor so). Consoles and lockers in
    the modules. No floor outside: every ceiling is a closed body ridged at 50
    degrees, so no roof is floor. A scratch measurement before the first run (a corridor 2.4 m wide alone, its floor
    slab's bottom 0.3-0.6 m under its top): a ceiling 2.15 m over the floor holds no floor for the presets' agent on
    three of four alignments to Recast's cells of 0.125 m, 2.25 m does on all four; so the tight corridors are about
    that threshold, and the hatches and tree corridors over it.

    Expected (written before the first run): one area (modules and tree corridors; a duct holds no floor; a tight
    corridor may or may not, as measured). Traffic highest in the corridors of the tree's trunk and the modules in the
    grid's middle, lowest in leaf modules; a designer expects the structure to run along each walkable corridor
    (beside its pipe run, on the side with head room) through both hatches, never through a duct, a bulkhead or the
    void, and would count a tight corridor (a 2 m agent fits) as a way: where Recast's rounding drops one, a loop of
    the station is missing from the analysis."""
    rng = np.random.default_rng(seed)
    nx, nz = int(rng.integers(6, 8)), int(rng.integers(5, 7))
    pitch_x, pitch_z = 16.0, 14.0
    sizes = np.stack([rng.uniform(9.0, 12.0, (nx, nz)), rng.uniform(7.0, 9.0, (nx, nz))], axis=-1)
    ceilings = rng.uniform(2.5, 2.8, (nx, nz))
    _, pairs = _grid_edges(nx, nz)
    tree = _random_tree(rng, nx * nz, pairs)
    s = _Solids()
    hatches: dict[tuple[int, int, str], list[tuple[float, float]]] = {}  # (i, j, side) -> hatches in that bulkhead

    def plan(i: int, j: int) -> tuple[float, float, float, float]:
        """Module (i, j)'s walls' middle lines: x0, x1, z0, z1 (m)."""
        cx, cz = i * pitch_x, j * pitch_z
        return cx - sizes[i, j, 0] / 2, cx + sizes[i, j, 0] / 2, cz - sizes[i, j, 1] / 2, cz + sizes[i, j, 1] / 2

    for a, b in pairs:
        walkable = bool(tree[a, b] or tree[b, a])
        if not walkable and rng.random() > 0.3:
            continue
        duct = not walkable and rng.random() < 0.5
        tight = not walkable and not duct
        (ia, ja), (ib, jb) = divmod(int(a), nz), divmod(int(b), nz)
        width = float(rng.uniform(2.4, 2.8))
        ceiling = 1.8 if duct else float(rng.uniform(2.05, 2.2)) if tight else float(rng.uniform(2.3, 2.4))
        pipe = float(rng.uniform(0.3, 0.4))
        side = rng.choice([-1.0, 1.0])
        pa, pb = plan(ia, ja), plan(ib, jb)
        if ia != ib:  # along x, from a's east bulkhead to b's west one
            zc = ja * pitch_z + float(rng.uniform(-1.5, 1.5))
            x0, x1 = pa[1], pb[0]
            s.box(x0, x1, -0.3, 0.0, zc - width / 2, zc + width / 2)
            for z in (zc - width / 2 - 0.1, zc + width / 2 + 0.1):
                s.wall((x0, z), (x1, z), 0.0, 2.45, thickness=0.2)
            for c0, c1, y in ((x0 + 0.1, x0 + 0.5, 2.45), (x0 + 0.5, x1 - 0.5, ceiling), (x1 - 0.5, x1 - 0.1, 2.45)):
                _ridged(s, c0, c1, zc - width / 2 - 0.2, zc + width / 2 + 0.2, y, y + 0.2)  # a collar at each hatch
            zp = zc + side * (width / 2 - pipe / 2)
            s.box(x0, x1, 1.7, ceiling, zp - pipe / 2, zp + pipe / 2)
            hatches.setdefault((ia, ja, "e"), []).append((zc - 0.8 - pa[2], 1.6))
            hatches.setdefault((ib, jb, "w"), []).append((zc - 0.8 - pb[2], 1.6))
        else:  # along z, from a's north bulkhead to b's south one
            xc = ia * pitch_x + float(rng.uniform(-2.0, 2.0))
            z0, z1 = pa[3], pb[2]
            s.box(xc - width / 2, xc + width / 2, -0.3, 0.0, z0, z1)
            for x in (xc - width / 2 - 0.1, xc + width / 2 + 0.1):
                s.wall((x, z0), (x, z1), 0.0, 2.45, thickness=0.2)
            for c0, c1, y in ((z0 + 0.1, z0 + 0.5, 2.45), (z0 + 0.5, z1 - 0.5, ceiling), (z1 - 0.5, z1 - 0.1, 2.45)):
                _ridged(s, xc - width / 2 - 0.2, xc + width / 2 + 0.2, c0, c1, y, y + 0.2)
            xp = xc + side * (width / 2 - pipe / 2)
            s.box(xp - pipe / 2, xp + pipe / 2, 1.7, ceiling, z0, z1)
            hatches.setdefault((ia, ja, "n"), []).append((xc - 0.8 - pa[0], 1.6))
            hatches.setdefault((ib, jb, "s"), []).append((xc - 0.8 - pb[0], 1.6))
    for i in range(nx):
        for j in range(nz):
            x0, x1, z0, z1 = plan(i, j)
            ceiling = float(ceilings[i, j])
            s.box(x0, x1, -0.3, 0.0, z0, z1)
            for side, a, b in (("s", (x0, z0), (x1, z0)), ("n", (x0, z1), (x1, z1)), ("w", (x0, z0), (x0, z1)),
                               ("e", (x1, z0), (x1, z1))):
                _hatch_wall(s, a, b, ceiling, hatches.get((i, j, side), []))
            _ridged(s, x0 - 0.1, x1 + 0.1, z0 - 0.1, z1 + 0.1, ceiling, ceiling + 0.2)
            for _ in range(int(rng.integers(2, 5))):  # consoles and lockers against the side walls, clear of hatches
                x = float(rng.uniform(x0 + 2.5, x1 - 3.5))
                side = "s" if rng.random() < 0.5 else "n"
                z = z0 + 0.1 if side == "s" else z1 - 0.8
                if all(x + 2.0 < x0 + start or x0 + start + width + 1.0 < x
                       for start, width in hatches.get((i, j, side), [])):
                    s.box(x, x + 1.0, 0.0, float(rng.choice([0.9, 2.0])), z, z + 0.7)
    return s.mesh()


def _log(s: _Solids, a: np.ndarray, b: np.ndarray, radius: float, top_a: float, top_b: float) -> None:
    """A fallen trunk from plan point ``a`` to ``b`` (x, z) whose top line runs from height ``top_a`` to ``top_b``:
    a prism of 12 sides round its axis ``radius`` m under the top line, one face uppermost (the top three faces within
    30 degrees of level, about 1.55 ``radius`` m of walkable width)."""
    axis = np.array([b[0] - a[0], top_b - top_a, b[1] - a[1]])
    axis /= np.linalg.norm(axis)
    side = np.cross(axis, [0.0, 1.0, 0.0])
    side /= np.linalg.norm(side)
    up = np.cross(side, axis)
    points = []
    for p, top in ((a, top_a), (b, top_b)):
        centre = np.array([p[0], top, p[1]]) - up * radius / math.cos(math.pi / 12)
        for k in range(12):
            angle = (k + 0.5) * math.pi / 6  # a face's middle at 0: straight up
            points.append(centre + radius / math.cos(math.pi / 12) * (math.cos(angle) * up + math.sin(angle) * side))
    s.hull(np.array(points))


def fallen_giants(seed: int) -> trimesh.Trimesh:
    """A jungle floor 160-175 x 120-130 m of uneven ground (sums of waves, 1-2 m of relief, slopes under 30 degrees)
    split along z by a gorge 12-16 m wide that meanders (no floor: a drop into nothing), crossed only by 3-4 *giant
    fallen trunks* (12-sided, 1.2-1.6 m in radius, their ends sunk in the banks so their tops meet the ground within 0.2
    m), each a ramp from bank to bank over the gorge; on the east bank a plateau 4-5 m high (its edges a cliff one does
    not climb) reached only up 2 trunks leaning from the ground onto its edge (14-18 m long, 12-20 degrees). 24 standing
    giants (octagonal trunks 1.2-1.8 m in radius, 25 m high to a cone) on both banks and the plateau, each with 4-6
    buttress roots (fins 0.3 m thick running 3-5 m out, 3 m high at the trunk falling to the ground) making alcoves
    between them.

    Expected (written before the first run): one area (the banks joined by the trunks over the gorge, the plateau by its
    leaning trunks). Traffic highest on the gorge's crossing trunks and the ground leading to them, then on the leaning
    trunks, lowest in the alcoves between buttress roots and the banks' far corners; a designer expects the structure
    along each trunk's top, never across the gorge elsewhere, never up the cliff, never through a root fin."""
    rng = np.random.default_rng(seed)
    size_x, size_z, step = float(rng.uniform(160.0, 175.0)), float(rng.uniform(120.0, 130.0)), 2.0
    xs, zs = np.arange(0.0, size_x + step / 2, step), np.arange(0.0, size_z + step / 2, step)
    waves = rng.normal(size=(5, 4))
    gorge_x, gorge_w = size_x * float(rng.uniform(0.4, 0.5)), float(rng.uniform(12.0, 16.0))
    bend = rng.uniform(-6.0, 6.0, 2)
    plateau = (gorge_x + gorge_w / 2 + float(rng.uniform(22.0, 28.0)), size_x - 6.0, size_z * 0.45, size_z - 6.0)
    lift = float(rng.uniform(4.0, 5.0))

    def middle(z: np.ndarray) -> np.ndarray:
        """The gorge's middle line's x at ``z`` (m)."""
        return gorge_x + bend[0] * np.sin(z / size_z * math.pi) + bend[1] * np.sin(z / size_z * 2 * math.pi)

    def height(x: np.ndarray, z: np.ndarray) -> np.ndarray:
        """The ground's height (m) at plan points ``x``, ``z`` (same shapes), the plateau's lift inside its plan."""
        y = sum(0.45 * np.sin(x * (0.03 + 0.03 * abs(w[0])) + w[1] * 3)
                * np.cos(z * (0.03 + 0.03 * abs(w[2])) + w[3] * 3) for w in waves)
        inside = (plateau[0] <= x) & (x <= plateau[1]) & (plateau[2] <= z) & (z <= plateau[3])
        return y + lift * inside

    gx, gz = np.meshgrid(xs, zs, indexing="ij")
    heights = height(gx, gz)
    cx, cz = (gx[:-1, :-1] + gx[1:, 1:]) / 2, (gz[:-1, :-1] + gz[1:, 1:]) / 2
    keep = np.abs(cx - middle(cz)) > gorge_w / 2
    s = _Solids()
    _terrain(s, xs, zs, heights, keep)
    crossings = int(rng.integers(3, 5))
    for z in (np.arange(crossings) + 0.5) / crossings * size_z + rng.uniform(-4.0, 4.0, crossings):
        z = float(np.clip(z, 8.0, size_z - 8.0))
        x_mid = float(middle(np.array(z)))
        turn = float(rng.uniform(-0.25, 0.25))  # the trunk lies up to 14 degrees off square to the gorge
        half = gorge_w / 2 + 4.0
        a = np.array([x_mid - half, z - half * math.tan(turn)])
        b = np.array([x_mid + half, z + half * math.tan(turn)])
        _log(s, a, b, float(rng.uniform(1.2, 1.6)), float(height(a[0], a[1])) + 0.2, float(height(b[0], b[1])) + 0.2)
    for k in range(2):  # the leaning trunks, onto the plateau's west and south edges
        if k == 0:
            z = float(rng.uniform(plateau[2] + 6.0, plateau[3] - 6.0))
            top = np.array([plateau[0] + 1.5, z])
            foot = top - np.array([float(rng.uniform(14.0, 18.0)), 0.0])
        else:
            x = float(rng.uniform(plateau[0] + 6.0, plateau[1] - 6.0))
            top = np.array([x, plateau[2] + 1.5])
            foot = top - np.array([0.0, float(rng.uniform(14.0, 18.0))])
        _log(s, foot, top, float(rng.uniform(1.2, 1.6)), float(height(foot[0], foot[1])) + 0.2,
             float(height(top[0], top[1])) + 0.2)
    giants: list[np.ndarray] = []
    for _ in range(400):
        if len(giants) == 24:
            break
        p = np.array([rng.uniform(6.0, size_x - 6.0), rng.uniform(6.0, size_z - 6.0)])
        clear_of_gorge = abs(p[0] - float(middle(np.array(p[1])))) > gorge_w / 2 + 7.0
        clear_of_cliff = not (plateau[0] - 7.0 < p[0] < plateau[1] + 7.0 and plateau[2] - 7.0 < p[1] < plateau[3] + 7.0
                              and not (plateau[0] + 7.0 < p[0] < plateau[1] - 7.0 and plateau[2] + 7.0 < p[1]))
        if clear_of_gorge and clear_of_cliff and all(np.linalg.norm(p - g) > 14.0 for g in giants):
            giants.append(p)
    for p in giants:
        r, y = float(rng.uniform(1.2, 1.8)), float(height(p[0], p[1]))
        ring = p + r * np.array([[math.cos(a), math.sin(a)] for a in np.arange(8) * math.pi / 4])
        s.hull(np.array([[q[0], yq, q[1]] for q in ring for yq in (y - 1.0, y + 25.0)]
                        + [[p[0], y + 25.0 + 2 * r, p[1]]]))
        for angle in rng.uniform(0.0, 2 * math.pi) + np.arange(int(rng.integers(4, 7))) * 2 * math.pi / 6:
            u = np.array([math.cos(angle), math.sin(angle)])
            v = np.array([-u[1], u[0]]) * 0.15
            tip = p + u * (r + float(rng.uniform(3.0, 5.0)))
            y_tip = float(height(tip[0], tip[1]))
            s.hull(np.array([[q[0], yq, q[1]] for q, y_top in ((p, y + 3.0), (tip, y_tip))
                             for q in (q - v, q + v) for yq in (min(y, y_tip) - 1.0, y_top)]))
    return s.mesh()


def canal_city(seed: int) -> trimesh.Trimesh:
    """A canal city (a Venice level) of 4-5 x 3-4 blocks 30-42 m square between canals 7-10 m wide with no floor in
    them. Along each canal both banks hold a quay (fondamenta) 2.2-3 m wide at 0.8 m over the water's line, running the
    canal's whole length, so each canal is *two long parallel lanes a canal apart*; a block's buildings (ridged, 9-14 m
    high) stand behind its quays, cut by 1-2 alleys (calli) 1.8-3 m wide each way between quays, one block in two
    holding a square (campo) where the building nearest its middle would stand. The banks are joined only by humped step
    bridges 3 m wide (8 steps of 0.15 m up from each quay's edge to a deck 1.2 m over it, railed 1 m high) across
    the canals between neighbouring blocks along a spanning tree of the blocks' grid and 20 % of the other
    neighbours, one bridge at most a canal stretch, none at a block's corner; canals round the city's edge are
    lined by a quay on the city's side only.

    Expected (written before the first run): one area (every block reached over the bridges). Traffic highest on the
    bridges of the tree's trunk and the quays and alleys leading to them, lowest on quays far from any bridge and in
    the blocks at the tree's leaves; a designer expects the structure along each quay (both banks of a canal, two
    lanes), crossing a canal only on a bridge, never over the water or through a building."""
    rng = np.random.default_rng(seed)
    nx, nz = int(rng.integers(4, 6)), int(rng.integers(3, 5))
    canal = rng.uniform(7.0, 10.0, (nx + 1, nz + 1))  # widths drawn as one grid, of which only its first column and row
    canal_x, canal_z = canal[:, 0], canal[0, :]  # are read: [i] the canal west of block column i, [j] south of row j
    block_x, block_z = rng.uniform(30.0, 42.0, nx), rng.uniform(30.0, 42.0, nz)
    x_edges = np.concatenate([[0.0], np.cumsum(np.ravel(np.column_stack([canal_x[:-1], block_x])))])  # canal, block...
    z_edges = np.concatenate([[0.0], np.cumsum(np.ravel(np.column_stack([canal_z[:-1], block_z])))])
    bx = [(float(x_edges[2 * i + 1]), float(x_edges[2 * i + 2])) for i in range(nx)]  # each block's x0, x1
    bz = [(float(z_edges[2 * j + 1]), float(z_edges[2 * j + 2])) for j in range(nz)]
    quay = rng.uniform(2.2, 3.0, (nx, nz, 4))  # each block's quay width on its west, east, south and north sides
    s = _Solids()
    ground = 0.8
    _, pairs = _grid_edges(nx, nz)
    tree = _random_tree(rng, nx * nz, pairs)
    for i in range(nx):
        for j in range(nz):
            x0, x1 = bx[i]
            z0, z1 = bz[j]
            inner = (x0 + quay[i, j, 0], x1 - quay[i, j, 1], z0 + quay[i, j, 2], z1 - quay[i, j, 3])
            alleys_x = sorted(rng.uniform(inner[0] + 8.0, inner[1] - 8.0, int(rng.integers(1, 3))))
            alleys_z = sorted(rng.uniform(inner[2] + 8.0, inner[3] - 8.0, int(rng.integers(1, 3))))
            widths_x, widths_z = rng.uniform(1.8, 3.0, len(alleys_x)), rng.uniform(1.8, 3.0, len(alleys_z))
            cuts_x = [inner[0]] + [c for a, w in zip(alleys_x, widths_x) for c in (a - w / 2, a + w / 2)] + [inner[1]]
            cuts_z = [inner[2]] + [c for a, w in zip(alleys_z, widths_z) for c in (a - w / 2, a + w / 2)] + [inner[3]]
            cells = [(a, b, c, d) for a, b in zip(cuts_x[0::2], cuts_x[1::2])
                     for c, d in zip(cuts_z[0::2], cuts_z[1::2]) if b - a > 2.0 and d - c > 2.0]
            middle = (x0 + x1) / 2, (z0 + z1) / 2
            nearest = min(range(len(cells)), key=lambda k: math.hypot((cells[k][0] + cells[k][1]) / 2 - middle[0],
                                                                       (cells[k][2] + cells[k][3]) / 2 - middle[1]))
            campo = rng.random() < 0.5
            buildings = [cell for k, cell in enumerate(cells) if not (campo and k == nearest)]  # the square left open
            for cell in buildings:
                _ridged(s, *cell, ground, ground + float(rng.uniform(9.0, 14.0)))
            s.ground(x0, x1, z0, z1, ground, buildings, thickness=1.8)  # none inside a building
    for a, b in pairs:
        if not (tree[a, b] or tree[b, a] or rng.random() < 0.2):
            continue
        (ia, ja), (ib, jb) = divmod(int(a), nz), divmod(int(b), nz)
        if ia != ib:  # across the canal between columns ia and ib, along x
            z_lo, z_hi = max(bz[ja][0], bz[jb][0]), min(bz[ja][1], bz[jb][1])
            zc = float(rng.uniform(z_lo + 6.0, z_hi - 6.0))
            _step_bridge(s, np.array([bx[ia][1], zc]), np.array([bx[ib][0], zc]), ground)
        else:
            x_lo, x_hi = max(bx[ia][0], bx[ib][0]), min(bx[ia][1], bx[ib][1])
            xc = float(rng.uniform(x_lo + 6.0, x_hi - 6.0))
            _step_bridge(s, np.array([xc, bz[ja][1]]), np.array([xc, bz[jb][0]]), ground)
    return s.mesh()


def grand_stair(seed: int) -> trimesh.Trimesh:
    """A mansion of two storeys 4.5 m apart (a boss fight's or a mystery's house): a hall 16-18 x 20-22 m in the middle,
    open from the ground to the sky, between two wings 14-16 m wide of 2 x 2 rooms a storey (doors 1.6 m wide in the
    partitions between them, one of the four left shut one time in two). The hall's *imperial staircase*: a central
    flight 3 m wide (risers 0.15 m) climbs north to a half landing 2.25 m up across the hall's north end, from which two
    mirrored flights 2 m wide climb back south along the hall's side walls to arms 2 m wide at 4.5 m that run on along
    the side walls to a gallery 3.5 m deep across the hall's south end: two ways up exactly alike, meeting at the
    gallery. Rails 1 m high along every open edge over the hall. On the ground a front door 2.4 m wide in the hall's
    south wall onto a forecourt 45 m deep laid out as a parterre (hedge beds 1 m high at their edges and ridged, 3-6 x
    2.5-4.5 m, on a grid with paths 1.8-3 m wide between them, a walk 6 m wide kept clear to the door), and a door 1.6 m
    wide from the hall into each wing's inner south room; upstairs a door from the gallery and one from each arm into
    the wing's inner rooms; a servants' flight 1.6 m wide (risers 0.18 m) along the east wall of the east wing's outer
    north room, railed upstairs. 3-5 tables in every room.

    Expected (written before the first run): one area. Traffic highest on the central flight, the half landing and the
    forecourt's way to the front door, the two side flights and arms alike (the level is mirrored about the hall's
    middle but for the wings' doors and the servants' stair), lowest in the wings' outer north rooms; a designer
    expects the structure up the central flight, along both side flights (not one of them only) to the gallery, never
    through a rail, a floor or from the landing to the gallery through the air."""
    rng = np.random.default_rng(seed)
    storey, hall_w, hall_d = 4.5, float(rng.uniform(16.0, 18.0)), float(rng.uniform(20.0, 22.0))
    wing = float(rng.uniform(14.0, 16.0))
    size_x = 2 * wing + hall_w
    xh0, xh1, xc = wing, wing + hall_w, size_x / 2
    landing, run = hall_d - 3.0, 15 * 0.3  # the half landing's south edge; a flight's plan length (15 risers)
    head = landing - run  # where the side flights reach the arms, and where the central flight starts
    back = (size_x - 1.75, hall_d / 2 + 1.5)  # the servants' flight's foot: 25 risers of 0.18 m north by the east wall
    back_hole = (back[0] - 0.05, size_x - 0.15, back[1], back[1] + 25 * 0.28)
    s = _Solids()
    beds: list[tuple[float, float, float, float]] = []
    z = -3.0
    while z - 2.5 > -44.0:  # the parterre's rows of hedge beds, from the house outwards, clear of the walk to the door
        depth = float(rng.uniform(2.5, 4.5))
        x = -1.0
        while x < size_x:
            length = float(rng.uniform(3.0, 6.0))
            if x + length < xc - 3.0 or x > xc + 3.0:
                beds.append(_ridged(s, x, min(x + length, size_x + 1.0), max(z - depth, -44.0), z, 0.0, 1.0))
            x += length + float(rng.uniform(1.8, 3.0))
        z -= depth + float(rng.uniform(1.8, 3.0))
    s.ground(-2.0, size_x + 2.0, -45.0, hall_d, 0.0, beds)  # the forecourt and the house's ground floor, none in a bed
    s.slab(0.0, xh0, 0.0, hall_d, storey, [])
    s.slab(xh1, size_x, 0.0, hall_d, storey, [back_hole])
    s.slab(xh0, xh1, 0.0, 3.5, storey, [])  # the gallery
    for x0 in (xh0, xh1 - 2.0):  # the arms
        s.slab(x0, x0 + 2.0, 3.5, head, storey, [])
    s.box(xh0, xh1, storey / 2 - 0.45, storey / 2, landing, hall_d)  # 1.8 m under it: no floor there
    s.stairs(np.array([xc, head]), np.array([0.0, 1.0]), 3.0, 0.0, storey / 2, depth=0.45)
    for x in (xh0 + 1.0, xh1 - 1.0):
        s.stairs(np.array([x, landing]), np.array([0.0, -1.0]), 2.0, storey / 2, storey / 2, depth=0.45)
    rails = [((xh0 + 2.0, 3.5, storey), (xh0 + 2.0, head, storey)),
             ((xh1 - 2.0, 3.5, storey), (xh1 - 2.0, head, storey)),
             ((xh0 + 2.0, 3.5, storey), (xh1 - 2.0, 3.5, storey)),
             ((xh0 + 2.0, head, storey), (xh0 + 2.0, landing, storey / 2)),
             ((xh1 - 2.0, head, storey), (xh1 - 2.0, landing, storey / 2)),
             ((xh0 + 2.0, landing, storey / 2), (xc - 1.5, landing, storey / 2)),
             ((xc + 1.5, landing, storey / 2), (xh1 - 2.0, landing, storey / 2)),
             ((xc - 1.5, head, 0.0), (xc - 1.5, landing, storey / 2)),
             ((xc + 1.5, head, 0.0), (xc + 1.5, landing, storey / 2))]
    for (ax, az, ay), (bx, bz, by) in rails:  # 0.1 m thick, 1 m over the floor or the steps' nosing line
        d = np.array([bx - ax, bz - az]) / math.hypot(bx - ax, bz - az)
        n = np.array([-d[1], d[0]]) * 0.05
        s.hull(np.array([[px + sn * n[0], py + dy, pz + sn * n[1]] for px, pz, py in ((ax, az, ay), (bx, bz, by))
                         for sn in (-1.0, 1.0) for dy in (0.0, 1.0)]))
    for k in (0, 1):
        y0, y1 = k * storey, (k + 1) * storey
        s.wall((0.0, 0.0), (size_x, 0.0), y0, y1, [(xc - 1.2 - 0.0, 2.4)] if k == 0 else [], thickness=0.3)
        s.wall((0.0, hall_d), (size_x, hall_d), y0, y1, thickness=0.3)
        for x in (0.0, size_x):
            s.wall((x, 0.0), (x, hall_d), y0, y1, thickness=0.3)
        for x in (xh0, xh1):  # the hall's side walls
            s.wall((x, 0.0), (x, hall_d), y0, y1, [(4.0, 1.6)] if k == 0 else [(1.0, 1.6), (head - 2.4, 1.6)],
                   thickness=0.3)
        for w0, w1, inner in ((0.0, xh0, xh0), (xh1, size_x, xh1)):  # each wing's 2 x 2 rooms
            mid_x, mid_z = (w0 + w1) / 2, hall_d / 2
            shut = int(rng.integers(4)) if rng.random() < 0.5 else -1
            doors = [[(float(rng.uniform(1.0, mid_z - 2.6)), 1.6)], [(float(rng.uniform(1.0, mid_z - 2.6)), 1.6)],
                     [(float(rng.uniform(0.8, mid_x - w0 - 2.4)), 1.6)],
                     [(float(rng.uniform(0.8, w1 - mid_x - 2.4)), 1.6)]]
            if shut >= 0:
                doors[shut] = []
            s.wall((mid_x, 0.0), (mid_x, mid_z), y0, y1, doors[0], thickness=0.2)
            s.wall((mid_x, mid_z), (mid_x, hall_d), y0, y1, [(d[0] + 0.0, 1.6) for d in doors[1]], thickness=0.2)
            s.wall((w0, mid_z), (mid_x, mid_z), y0, y1, doors[2], thickness=0.2)
            s.wall((mid_x, mid_z), (w1, mid_z), y0, y1, doors[3], thickness=0.2)
            for room in ((w0, mid_x, 0.0, mid_z), (mid_x, w1, 0.0, mid_z), (w0, mid_x, mid_z, hall_d),
                         (mid_x, w1, mid_z, hall_d)):
                for _ in range(int(rng.integers(3, 6))):  # tables and chairs, clear of the servants' flight
                    x = float(rng.uniform(room[0] + 2.0, room[1] - 3.5))
                    z = float(rng.uniform(room[2] + 2.0, room[3] - 3.0))
                    if x + 1.5 < back_hole[0] - 1.2 or z + 1.0 < back[1] - 1.5 or z > back_hole[3] + 1.5:
                        s.box(x, x + 1.5, y0, y0 + 0.75, z, z + 1.0)
    s.stairs(np.array([size_x - 0.95, back[1]]), np.array([0.0, 1.0]), 1.6, 0.0, storey, 0.18, 0.28, depth=0.45)
    s.box(back_hole[0] - 0.1, back_hole[0], storey, storey + 1.0, back_hole[2], back_hole[3])  # its rail upstairs
    return s.mesh()


def data_hall(seed: int) -> trimesh.Trimesh:
    """A data centre's two halls, each 70-80 x 40-48 m on a raised floor 0.6 m up, walls and ceiling 4 m high (the
    ceiling a closed body ridged at 50 degrees), north and south of a corridor 4 m wide (floor at 0) and each entered
    from it through two openings: one up a ramp 1.5 m wide at 1 in 12 onto a landing, one up 4 steps of 0.15 m (each in
    a quarter of the corridor's length of its own). In each hall rows of racks (closed boxes 1.2 m deep, 2.2 m high)
    along x in 3-4 runs split by cross aisles 2.4 m wide along z, alternately facing across *cold aisles 1.8-2.4 m wide*
    and backing onto *hot aisles 1.2-1.8 m wide*, about what the agent's 1 m needs on Recast's cells of 0.25 m (1.5 m),
    so whether a hot aisle holds floor is chance; a perimeter aisle 2.5-3 m wide round the rows, cooling units (1 x 2.5
    m, 2 m high) every 5-6 m along the east and west walls.

    Expected (written before the first run): one area (every cold aisle open at both ends onto a cross or perimeter
    aisle; a hot aisle too narrow holds no floor, not an area apart). Traffic highest in the corridor and on each
    hall's perimeter aisle along the corridor between its two entrances, then along the cross aisles, lowest in the
    aisles' middles far from the entrances; a designer expects the structure along each cold aisle's middle (long
    parallel lanes 3-4 m apart, one edge or a few each, not merged across a row of racks), along the cross aisles,
    never through a row."""
    rng = np.random.default_rng(seed)
    size_x, floor = float(rng.uniform(70.0, 80.0)), 0.6
    s = _Solids()
    s.box(-3.0, size_x + 3.0, -0.5, 0.0, -4.0, 0.0)  # the corridor, z from -4 to 0
    for x in (-3.0, size_x + 3.0):
        s.wall((x, -4.0), (x, 0.0), 0.0, 4.0, thickness=0.2)
    for sign in (1.0, -1.0):  # the north hall from z = 0 up, the south one from z = -4 down
        def at(z: float) -> float:
            """Plan z of a point ``z`` m from the corridor into this hall."""
            return z if sign > 0 else -4.0 - z

        def box(x0: float, x1: float, y0: float, y1: float, z0: float, z1: float) -> None:
            """:meth:`_Solids.box` with z measured from the corridor into this hall."""
            s.box(x0, x1, y0, y1, *sorted((at(z0), at(z1))))

        size_z, margin = float(rng.uniform(40.0, 48.0)), float(rng.uniform(2.5, 3.0))
        box(0.0, size_x, -0.5, floor, 0.0, size_z)
        z0, z1 = sorted((at(0.0), at(size_z)))
        _ridged(s, -0.1, size_x + 0.1, z0 - 0.1, z1 + 0.1, 4.0, 4.2)  # the ceiling: 1.2 m over the racks: none is floor
        quarter = size_x / 4  # the entrances in the corridor's quarters: the north hall's ramp in the first and steps
        ramp_q, steps_q = (0, 2) if sign > 0 else (3, 1)  # in the third, the south hall's in the fourth and second
        ramp_x = float(rng.uniform(ramp_q * quarter + 2.0, (ramp_q + 1) * quarter - 11.6))
        steps_x = float(rng.uniform(steps_q * quarter + 2.0, (steps_q + 1) * quarter - 4.4))
        s.wall((0.0, at(0.0)), (size_x, at(0.0)), 0.0, 4.0, [(ramp_x, 2.4), (steps_x, 2.4)], thickness=0.2)
        s.wall((0.0, at(size_z)), (size_x, at(size_z)), 0.0, 4.0, thickness=0.2)
        for x in (0.0, size_x):
            s.wall((x, min(at(0.0), at(size_z))), (x, max(at(0.0), at(size_z))), 0.0, 4.0, thickness=0.2)
        box(ramp_x, ramp_x + 2.4, -0.5, floor, -2.0, 0.0)  # the ramp's landing in the corridor, then the ramp along +x
        s.ramp(np.array([ramp_x + 2.4, at(-1.25)]), np.array([ramp_x + 2.4 + 12.0 * floor, at(-1.25)]), 1.5, floor, 0.0)
        s.stairs(np.array([steps_x + 1.2, at(-1.2 - 4 * 0.3)]), np.array([0.0, sign]), 2.4, 0.0, floor, 0.15, 0.3)
        for x in (0.2, size_x - 1.2):  # cooling units
            for z in np.arange(margin + 1.0, size_z - 3.5, float(rng.uniform(5.0, 6.0))):
                box(x, x + 1.0, floor, floor + 2.0, z, z + 2.5)
        runs = int(rng.integers(3, 5))
        inner_x0, inner_x1 = 1.2 + margin, size_x - 1.2 - margin
        run_length = (inner_x1 - inner_x0 - 2.4 * (runs - 1)) / runs
        z, facing = margin, True  # the next row's edge nearer the corridor; whether the aisle beyond it is cold
        while True:
            for r in range(runs):
                x0 = inner_x0 + r * (run_length + 2.4)
                box(x0, x0 + run_length, floor, floor + 2.2, z, z + 1.2)
            aisle = float(rng.uniform(1.8, 2.4)) if facing else float(rng.uniform(1.2, 1.8))
            if z + 1.2 + aisle + 1.2 > size_z - margin:
                break
            z += 1.2 + aisle
            facing = not facing
    return s.mesh()

def _step_bridge(s: _Solids, a: np.ndarray, b: np.ndarray, ground: float) -> None:
    """A humped bridge 3 m wide from bank point ``a`` to ``b`` (x, z; the banks' edges, along x or z) at ``ground``:
    8 steps of 0.15 / 0.35 m up from each bank over the water, a deck 1.2 m up between them, rails 1 m high on both
    sides from end to end (0.1 m thick)."""
    span = float(np.linalg.norm(b - a))
    u = (b - a) / span
    rise, run = 1.2, 8 * 0.35
    for start, heading in ((a, u), (b, -u)):
        s.stairs(start, heading, 3.0, ground, rise, 0.15, 0.35, depth=0.4)
    deck_a, deck_b = a + u * run, b - u * run
    s.ramp(deck_a, deck_b, 3.0, ground + rise, ground + rise, thickness=0.4)
    side = np.array([-u[1], u[0]]) * 1.55
    for sign in (-1.0, 1.0):
        for p, q, y0, y1 in ((a, deck_a, ground, ground + rise), (deck_a, deck_b, ground + rise, ground + rise),
                             (deck_b, b, ground + rise, ground)):
            ends = [(p + sign * side, y0), (q + sign * side, y1)]
            s.hull(np.array([[e[0] + dx, y + dy, e[1] + dz] for e, y in ends for dy in (0.0, 1.0)
                             for dx, dz in ((0.05 * u[1], -0.05 * u[0]), (-0.05 * u[1], 0.05 * u[0]))]))


KINDS: dict[str, Callable[[int], trimesh.Trimesh]] = {
    "double_helix": double_helix, "low_station": low_station, "fallen_giants": fallen_giants,
    "canal_city": canal_city, "grand_stair": grand_stair, "data_hall": data_hall,
}
"""Kind name -> generator (seed -> Y-up mesh in metres) of the twenty-eighth round."""


if __name__ == "__main__":
    write_kinds(kinds=KINDS, description=__doc__.splitlines()[0])
