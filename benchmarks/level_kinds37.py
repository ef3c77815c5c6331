"""Level kinds of the thirty-seventh held-out round (issue 9): generators no preset setting was made on.

Six kinds of shipped game levels that stress what no earlier round did, each a few hundred navmesh polygons with the
presets' agent (radius 0.5 m, height 2 m, climb 0.4 m, slope 45 degrees), seeds 0-2, built from the solids and helpers
of ``benchmarks/level_kinds.py`` and ``level_kinds30.py`` (imported, not copied): ``skirted_maze`` (a maze of
partitions that stand on legs *with a gap of 0.2-0.5 m under them*, drawn per panel, which no agent passes),
``awning_market`` (a market hall whose stalls' awnings slope out over the aisles *to a lower edge 1.9-2.3 m up*, drawn
per awning, head room about the agent's height on thin sloping sheets), ``arcade_cloister`` (two cloisters whose
garths are entered only between an arcade's piers, *0.5-1.2 m apart*, drawn per side, about the agent's 1 m),
``tilt_dock`` (a harbour's pontoons at the tide's height, *joined by ramps that tilt 10-25 degrees*, drawn per ramp,
their decks rolled 0-5 degrees), ``bump_park`` (a car park whose aisles are crossed by *speed bumps 0.08-0.15 m high
with flanks of 30-60 degrees*, drawn per bump, and whose islands and footway stand on *kerbs of 0.15-0.25 m*) and
``parapet_roofs`` (a rooftop of roofs *pitched 20-35 degrees* behind *parapets 0.3-0.9 m high*, drawn per side,
joined by flat walkways).

Run: ``.venv/bin/python benchmarks/level_kinds37.py OUT_DIR [--kinds skirted_maze parapet_roofs] [--seeds 0 1 2]``
writes ``OUT_DIR/<kind>_s<seed>.obj``; ``benchmarks/analysis_quality.py --levels`` takes the kinds' names too."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import trimesh
from level_kinds import _car, _ridged, _Solids, _trunk
from level_kinds import main as write_kinds
from level_kinds30 import _placed

PANEL = 0.05
"""Thickness of a partition panel, metres (a washroom's or an office's laminate partition)."""


def skirted_maze_plan(seed: int) -> dict:
    """The plan of :func:`skirted_maze` for ``seed``: the grid (columns, rows, cell size, its south-west corner) and
    each panel (its two plan end points, the gap under it and its top). The panels are the walls a random depth-first
    maze over the cells keeps, less a tenth of them (loops), less the two entrances in the grid's west and east
    sides. O(cells)."""
    rng = np.random.default_rng(seed)
    cols, rows = int(rng.integers(17, 21)), int(rng.integers(11, 14))
    cell = float(rng.uniform(3.0, 3.6))
    origin = (5.0, 5.0)
    open_walls: set[frozenset] = set()
    seen, stack = {(0, 0)}, [(0, 0)]
    while stack:  # a depth-first maze: every cell joined to every other by one path
        c, r = stack[-1]
        options = [(c + dc, r + dr) for dc, dr in ((1, 0), (-1, 0), (0, 1), (0, -1))
                   if 0 <= c + dc < cols and 0 <= r + dr < rows and (c + dc, r + dr) not in seen]
        if not options:
            stack.pop()
            continue
        nxt = options[int(rng.integers(len(options)))]
        open_walls.add(frozenset(((c, r), nxt)))
        seen.add(nxt)
        stack.append(nxt)
    walls = []  # (cell a, cell b or None for the grid's side, end points)
    for c in range(cols):
        for r in range(rows):
            x, z = origin[0] + c * cell, origin[1] + r * cell
            if c + 1 < cols:
                walls.append((frozenset(((c, r), (c + 1, r))), ((x + cell, z), (x + cell, z + cell))))
            if r + 1 < rows:
                walls.append((frozenset(((c, r), (c, r + 1))), ((x, z + cell), (x + cell, z + cell))))
            if r == 0:
                walls.append((None, ((x, z), (x + cell, z))))
            if r == rows - 1:
                walls.append((None, ((x, z + cell), (x + cell, z + cell))))
            if c == 0 and r != rows // 2:  # the west entrance: the middle row's side open
                walls.append((None, ((x, z), (x, z + cell))))
            if c == cols - 1 and r != (rows - 1) // 3:  # the east entrance
                walls.append((None, ((x + cell, z), (x + cell, z + cell))))
    panels = []
    for key, ends in walls:
        if key is not None and (key in open_walls or rng.random() < 0.1):
            continue
        panels.append({"ends": ends, "gap": float(rng.uniform(0.2, 0.5)), "top": float(rng.uniform(2.1, 2.4))})
    return {"grid": (cols, rows, cell, origin), "panels": panels}


def skirted_maze(seed: int) -> trimesh.Trimesh:
    """A maze of partitions (a horror game's washroom block, an escape room's office maze, a fair's panel maze) in a
    hall of 17-20 x 11-13 cells 3.0-3.6 m square (``skirted_maze_plan(seed)``), an aisle 5 m wide round it inside walls
    5 m high with a door 2.4 m wide in the south and the north wall, open to the sky. Every wall of the maze is a
    panel 0.05 m thick *standing on two legs with a gap of 0.2-0.5 m (drawn per panel) between the floor and its
    lower edge*, its top 2.1-2.4 m up: the floor runs on under every panel. The maze is a depth-first maze over the
    cells (one path between any two cells), a tenth of its other walls left out (loops), entered from the aisle at
    one cell of its west side and one of its east side. Benches (ridged) against a panel in a few cells and along the
    aisle.

    Expected (written before the first run): one area for a player (the aisle and every cell of the maze: a
    depth-first maze joins them all), *no way under any panel* (0.2-0.5 m of head room), so a path between two
    cells follows the maze's corridors (3.0-3.6 m, about 2-2.6 m of it for the agent's centre after the radius).
    The navmesh route reads the floor under a panel as floor without head room (none: a wall), so it should see the
    maze as drawn: one area, its corridors and dead ends. The sampling route's clearance rays (knee 0.5 m, waist,
    head) meet a panel whose lower edge is under 0.5 m; a panel hanging at 0.45-0.5 m is within a few centimetres of
    the knee ray, and an edge between two samples either side of a panel must not be made (the walk test's body
    slab from 0.5 m up meets it): if it were, the sampling route would join cells the maze keeps apart (shortcuts:
    traffic on no corridor, rho against the navmesh graph's flow lower than the round's others). Traffic highest
    on the maze's trunk between its two entrances, lowest in its dead ends."""
    plan = skirted_maze_plan(seed)
    rng = np.random.default_rng(seed + 1000)
    cols, rows, cell, (ox, oz) = plan["grid"]
    size_x, size_z = ox * 2 + cols * cell, oz * 2 + rows * cell
    s = _Solids()
    s.wall((0.0, 0.0), (size_x, 0.0), -0.1, 5.0, [(size_x / 2 - 1.2, 2.4)], thickness=0.3)
    s.wall((0.0, size_z), (size_x, size_z), -0.1, 5.0, [(size_x / 3, 2.4)], thickness=0.3)
    s.wall((0.0, 0.0), (0.0, size_z), -0.1, 5.0, thickness=0.3)
    s.wall((size_x, 0.0), (size_x, size_z), -0.1, 5.0, thickness=0.3)
    for panel in plan["panels"]:
        (x0, z0), (x1, z1) = panel["ends"]
        h = PANEL / 2
        s.box(min(x0, x1) - h, max(x0, x1) + h, panel["gap"], panel["top"], min(z0, z1) - h, max(z0, z1) + h)
        for x, z in ((x0, z0), (x1, z1)):  # the legs at its ends, 0.05 m square, to the floor
            s.box(x - 0.03, x + 0.03, -0.05, panel["gap"] + 0.01, z - 0.03, z + 0.03)
    holes: list[tuple[float, float, float, float]] = []
    south_closed = {panel["ends"][0] for panel in plan["panels"] if panel["ends"][0][1] == panel["ends"][1][1]}
    for _ in range(int(rng.integers(12, 18))):  # a bench in a cell against its south panel (never in an opening)
        c, r = int(rng.integers(cols)), int(rng.integers(rows))
        x, z = ox + c * cell + cell / 2, oz + r * cell + 0.35
        if (ox + c * cell, oz + r * cell) not in south_closed:
            continue
        holes.append(_ridged(s, x - 0.6, x + 0.6, z - 0.2, z + 0.2, -0.1, 0.45))
    for x in np.linspace(8.0, size_x - 8.0, 4):  # benches along the aisle's north wall
        holes.append(_ridged(s, float(x) - 1.0, float(x) + 1.0, size_z - 0.85, size_z - 0.45, -0.1, 0.45))
    s.ground(-4.0, size_x + 4.0, -4.0, size_z + 4.0, 0.0, holes)
    return s.mesh()


AWNING_PITCH = math.radians(15.0)
"""Slope of every awning, down and out over the aisle from the stall's front."""


def awning_market_plan(seed: int) -> dict:
    """The plan of :func:`awning_market` for ``seed``: the hall's size, the double rows of stalls (z0, z1 of the
    row's depth; each stall's x0, x1) and per stall and side facing an aisle its awning (reach out over the aisle,
    height of its lower edge). O(stalls)."""
    rng = np.random.default_rng(seed)
    size_x, size_z = float(rng.uniform(86.0, 96.0)), float(rng.uniform(56.0, 64.0))
    rows = []
    z = 4.0
    while z + 4.8 + 4.0 <= size_z:
        stalls = []
        x = 4.0
        while True:
            length = float(rng.uniform(3.0, 4.5))
            if x + length > size_x - 4.0:
                break
            awnings = {side: {"reach": float(rng.uniform(0.8, 1.3)), "edge": float(rng.uniform(1.9, 2.3))}
                       for side in ("south", "north")}
            stalls.append({"x": (x, x + length), "awnings": awnings})
            x += length + (4.0 if len(stalls) % 5 == 0 else 0.0)  # a cross aisle 4 m wide every five stalls
        rows.append({"z": (z, z + 4.8), "stalls": stalls})
        z += 4.8 + float(rng.uniform(2.8, 3.4))
    return {"size": (size_x, size_z), "rows": rows}


def _awning(s: _Solids, x0: float, x1: float, z_front: float, outward: float, reach: float, edge: float) -> None:
    """A canvas awning 0.04 m thick over [x0, x1] from a stall's front at ``z_front`` out ``reach`` m along
    ``outward`` (+1 or -1 in z), sloping down at :data:`AWNING_PITCH` to its lower edge's underside at ``edge``."""
    rise = reach * math.tan(AWNING_PITCH)
    z_out = z_front + outward * reach
    s.hull(np.array([[x, y + d, z] for x in (x0, x1) for z, y in ((z_front, edge + rise), (z_out, edge))
                     for d in (0.0, 0.04)]))


def awning_market(seed: int) -> trimesh.Trimesh:
    """A covered market's hall floor (an open-world city's market, a stealth game's bazaar) 86-96 x 56-64 m inside
    walls 5 m high with four doors, open to the sky: double rows of stalls along x (closed bodies 2.4 m deep each
    side, ridged 2.8 m up: no floor on them), 3-4.5 m long, a cross aisle 4 m wide every five stalls, aisles of
    2.8-3.4 m between the rows (``awning_market_plan(seed)``). Over each stall's front on each side a canvas awning
    *slopes out over the aisle 0.8-1.3 m at 15 degrees to a lower edge 1.9-2.3 m up* (drawn per awning), so in an
    aisle between two awnings the head room at its edges is about the agent's 2 m and the middle 0.2-1.8 m is open
    to the sky. Crates (ridged, 0.9 m) before some stalls, under the awnings.

    Expected (written before the first run): one area for a player (every aisle walked end to end, every stall's
    front reached). Under an awning whose lower edge is under 2.0 m the strip where its underside is under 2 m is
    (2.0 - edge) / tan 15 degrees = at most 0.37 m wide, at the awning's outer edge: no floor there for a 2 m agent,
    but the aisle keeps 2 m or more between the two sides' strips, so no aisle is cut. The navmesh route reads head
    room in cells of 0.125 m (an edge at 1.9-2.1 m may read either way, as the queue hall's shutters did) and should
    see one area with the aisles a little narrower; the sampling route's head ray (1.95 m) meets an awning only
    straight over a sample, its walk test the body slab to the head: one area too, samples thinner under the low
    edges. Traffic highest along the cross aisles and the aisles by the doors."""
    plan = awning_market_plan(seed)
    rng = np.random.default_rng(seed + 1000)
    size_x, size_z = plan["size"]
    s = _Solids()
    s.wall((0.0, 0.0), (size_x, 0.0), -0.1, 5.0, [(size_x * 0.3, 3.0), (size_x * 0.7, 3.0)], thickness=0.3)
    s.wall((0.0, size_z), (size_x, size_z), -0.1, 5.0, [(size_x * 0.5, 3.0)], thickness=0.3)
    s.wall((0.0, 0.0), (0.0, size_z), -0.1, 5.0, [(size_z * 0.5, 3.0)], thickness=0.3)
    s.wall((size_x, 0.0), (size_x, size_z), -0.1, 5.0, thickness=0.3)
    holes: list[tuple[float, float, float, float]] = []
    for row in plan["rows"]:
        z0, z1 = row["z"]
        for stall in row["stalls"]:
            x0, x1 = stall["x"]
            holes.append(_ridged(s, x0 + 0.05, x1 - 0.05, z0, z1, -0.1, 2.8))
            for side, (z_front, outward) in (("south", (z0, -1.0)), ("north", (z1, 1.0))):
                awning = stall["awnings"][side]
                _awning(s, x0 + 0.05, x1 - 0.05, z_front, outward, awning["reach"], awning["edge"])
                if rng.random() < 0.5:  # a crate under the awning, against the stall
                    xc = float(rng.uniform(x0 + 0.6, x1 - 0.6))
                    zc = z_front + outward * 0.35
                    holes.append(_ridged(s, xc - 0.4, xc + 0.4, zc - 0.3, zc + 0.3, -0.1, 0.9))
    s.ground(-4.0, size_x + 4.0, -4.0, size_z + 4.0, 0.0, holes)
    return s.mesh()


PIER = 0.6
"""Side of an arcade's square piers, metres."""


def arcade_cloister_plan(seed: int) -> dict:
    """The plan of :func:`arcade_cloister` for ``seed``: the precinct's size and per cloister its garth (x0, x1,
    z0, z1), its walk's width, per side of the garth (south, north, west, east) how many pitches its arcade has and
    the gap between its piers as built (the drawn gap, widened to whole pitches), and the doors in the walk's outer
    wall (side, offset along it). O(cloisters)."""
    rng = np.random.default_rng(seed)
    cloisters = []
    x = 8.0
    for _ in range(2):
        g = float(rng.uniform(20.0, 26.0))
        walk = float(rng.uniform(2.8, 3.4))
        z0 = 8.0 + walk
        widest = 1.2 if not cloisters else 0.8  # the second garth's arcade closed to the agent on every side
        drawn = {side: float(rng.uniform(0.5, widest)) for side in ("south", "north", "west", "east")}
        piers = {side: max(1, int((g - PIER) // (PIER + gap))) for side, gap in drawn.items()}  # whole pitches
        gaps = {side: (g - PIER) / n - PIER for side, n in piers.items()}  # as built: the drawn gap or a little over
        doors = [(side, float(rng.uniform(2.0, g + 2 * walk - 4.0))) for side in rng.choice(
            ["south", "north", "west", "east"], size=2, replace=False)]
        cloisters.append({"garth": (x + walk, x + walk + g, z0, z0 + g), "walk": walk, "gaps": gaps, "piers": piers,
                          "doors": doors})
        x += g + 2 * walk + float(rng.uniform(8.0, 12.0))
    size_z = max(c["garth"][3] + c["walk"] for c in cloisters) + 8.0
    return {"size": (x, size_z), "cloisters": cloisters}


def arcade_cloister(seed: int) -> trimesh.Trimesh:
    """A monastery's precinct (an adventure game's abbey, a stealth game's convent) with two cloisters: each a square
    garth 20-26 m across inside an open arcade of square piers 0.6 m thick and 3.5 m high under a lintel (3-3.5 m
    up), *the gap between neighbouring piers drawn per side of the garth, 0.5-1.2 m round the first garth and
    0.5-0.8 m round the second* (widened to whole pitches as built: 0.5-1.35 m), a walk 2.8-3.4 m wide round it
    (open to the sky) and an outer wall 5 m high with two doors 2 m wide onto the precinct's yard
    (``arcade_cloister_plan(seed)``). *A garth has no door*: it is entered only between the piers. The garth holds a
    well (ridged) and four trees; the yard round the cloisters, inside a precinct wall 3 m high with a gate, holds
    carts and woodpiles (ridged).

    Expected (written before the first run): for a player the yard and both walks are one area, and a garth is
    reached where one of its four sides has gaps of at least the agent's 1 m (a side of 0.5-1.0 m gaps is a wall to
    a 1 m agent): the second garth never (an area apart: its warning should name the arcade), the first where the
    plan's widest side is 1.0 m or more (seeds 0-2: all three, by 1.19, 1.27 and 1.15 m). On the navmesh route a gap
    of 1.0-1.2 m keeps no floor for the agent's centre (the radius leaves 0-0.2 m, under Recast's 0.25 m cells and
    its rounding, about 1.5 m being what a gap needs on its grid), so every garth should be an area apart there, its
    disconnected-areas warning naming the arcade; a player (and the brief) would call a garth behind gaps of 1.0-1.2
    m reachable and one behind gaps under 1.0 m not. The sampling route's 1 m grid finds the 0-0.2 m band in a gap
    only by chance and must not join samples across gaps under 1.0 m (a walk between piers is blocked for the
    agent's body): if it does it joins what a player cannot. Traffic on the walks and through the doors; none in a
    garth apart."""
    plan = arcade_cloister_plan(seed)
    rng = np.random.default_rng(seed + 1000)
    size_x, size_z = plan["size"]
    s = _Solids()
    s.wall((0.0, 0.0), (size_x, 0.0), -0.1, 3.0, [(6.0, 3.5)], thickness=0.4)
    s.wall((0.0, size_z), (size_x, size_z), -0.1, 3.0, thickness=0.4)
    s.wall((0.0, 0.0), (0.0, size_z), -0.1, 3.0, thickness=0.4)
    s.wall((size_x, 0.0), (size_x, size_z), -0.1, 3.0, thickness=0.4)
    holes: list[tuple[float, float, float, float]] = []
    keep: list[tuple[float, float, float, float]] = []
    pier = PIER
    for cl in plan["cloisters"]:
        gx0, gx1, gz0, gz1 = cl["garth"]
        walk = cl["walk"]
        ox0, ox1, oz0, oz1 = gx0 - walk, gx1 + walk, gz0 - walk, gz1 + walk
        keep.append((ox0 - 2.0, ox1 + 2.0, oz0 - 2.0, oz1 + 2.0))
        doors: dict[str, list[tuple[float, float]]] = {"south": [], "north": [], "west": [], "east": []}
        for side, offset in cl["doors"]:
            doors[side].append((offset, 2.0))
        s.wall((ox0, oz0), (ox1, oz0), -0.1, 5.0, doors["south"], thickness=0.4)
        s.wall((ox0, oz1), (ox1, oz1), -0.1, 5.0, doors["north"], thickness=0.4)
        s.wall((ox0, oz0), (ox0, oz1), -0.1, 5.0, doors["west"], thickness=0.4)
        s.wall((ox1, oz0), (ox1, oz1), -0.1, 5.0, doors["east"], thickness=0.4)
        # the arcade: piers along each side of the garth, the side's gap between them, corner piers shared
        for side, (a, b, fixed, along_x) in {"south": (gx0, gx1, gz0, True), "north": (gx0, gx1, gz1, True),
                                             "west": (gz0, gz1, gx0, False), "east": (gz0, gz1, gx1, False)}.items():
            n = cl["piers"][side]
            pitch = (b - a - PIER) / n
            for k in range(n + 1):
                t = a + k * pitch
                if along_x:
                    s.box(t, t + pier, -0.1, 3.5, fixed - pier / 2, fixed + pier / 2)
                else:
                    s.box(fixed - pier / 2, fixed + pier / 2, -0.1, 3.5, t, t + pier)
            lintel = (a, b, fixed - pier / 2, fixed + pier / 2)
            if along_x:
                s.box(lintel[0], lintel[1], 3.0, 3.5, lintel[2], lintel[3])
            else:
                s.box(lintel[2], lintel[3], 3.0, 3.5, lintel[0], lintel[1])
        c = np.array([(gx0 + gx1) / 2, (gz0 + gz1) / 2])
        holes.append(_ridged(s, c[0] - 0.9, c[0] + 0.9, c[1] - 0.9, c[1] + 0.9, -0.1, 1.0))  # the well
        for dx, dz in ((-1, -1), (1, -1), (-1, 1), (1, 1)):
            _trunk(s, c + np.array([dx, dz]) * (gx1 - gx0) * 0.27, 0.3, -0.1, 5.0)
    spots: list[tuple[np.ndarray, float]] = []
    for _ in range(int(rng.integers(10, 15))):  # carts and woodpiles in the yard
        p = _placed(rng, spots, 1.5, size_x - 1.5, 1.5, size_z - 1.5, 1.6, keep + [(4.0, 11.0, 0.0, 4.0)])
        if p is not None:
            holes.append(_ridged(s, p[0] - 1.2, p[0] + 1.2, p[1] - 0.6, p[1] + 0.6, -0.1, 1.4))
    s.ground(-4.0, size_x + 4.0, -4.0, size_z + 4.0, 0.0, holes)
    return s.mesh()


def tilt_dock_plan(seed: int) -> dict:
    """The plan of :func:`tilt_dock` for ``seed``: the quay's length and depth, the tide (how far the pontoons' decks
    float under the quay's top), and per pier: its main pontoon (x, z0, z1, width, deck, roll), the gangway down to
    it (slope), its head pontoon (deck, roll) with the ramp to it (slope, tilting up or down) and its fingers
    (z, side). O(piers)."""
    rng = np.random.default_rng(seed)
    n = int(rng.integers(8, 10))
    length = 16.0 + 22.0 * n
    tide = float(rng.uniform(1.4, 2.4))
    piers = []
    for k in range(n):
        x = 14.0 + 22.0 * k + float(rng.uniform(-2.0, 2.0))
        deck = -tide + float(rng.uniform(-0.3, 0.3))
        gangway = math.radians(float(rng.uniform(10.0, 25.0)))
        run = -deck / math.tan(gangway)
        z1 = -run
        z0 = z1 - float(rng.uniform(26.0, 36.0))
        head_rise = float(rng.choice([-1.0, 1.0]) * rng.uniform(0.4, 1.1))  # a barge higher or a float lower
        ramp = math.radians(float(rng.uniform(10.0, 25.0)))
        pitch = float(rng.uniform(6.0, 8.0))
        fingers = [(float(z), int(rng.choice([-1, 1]))) for z in np.arange(z1 - 5.0, z0 + 4.0, -pitch)]
        piers.append({"x": x, "z": (z0, z1), "width": float(rng.uniform(2.6, 3.2)), "deck": deck,
                      "roll": math.radians(float(rng.uniform(-5.0, 5.0))), "gangway": gangway,
                      "head": {"deck": deck + head_rise, "roll": math.radians(float(rng.uniform(-5.0, 5.0))),
                               "ramp": ramp, "run": abs(head_rise) / math.tan(ramp)},
                      "fingers": fingers})
    return {"length": length, "depth": 22.0, "tide": tide, "piers": piers}


def _rolled_deck(s: _Solids, x0: float, x1: float, z0: float, z1: float, deck: float, roll: float,
                 thickness: float = 0.4) -> None:
    """A float's deck over [x0, x1] x [z0, z1] whose top at its middle is ``deck``, rolled by ``roll`` radians about
    its axis along z (its +x edge higher for a positive roll), ``thickness`` m deep."""
    xm = (x0 + x1) / 2
    s.hull(np.array([[x, deck + (x - xm) * math.tan(roll) - d, z] for x in (x0, x1) for z in (z0, z1)
                     for d in (0.0, thickness)]))


def _railed_ramp(s: _Solids, a: np.ndarray, b: np.ndarray, width: float, ya: float, yb: float) -> None:
    """A ramp ``width`` m wide between its rails from plan point ``a`` at ``ya`` to ``b`` at ``yb``, railed 1 m high
    along both sides (solid rails 0.06 m thick, sloping with the deck)."""
    s.ramp(a, b, width + 0.12, ya, yb, thickness=0.15)
    along = (b - a) / np.linalg.norm(b - a)
    side = np.array([-along[1], along[0]])
    for sign in (-1.0, 1.0):
        off = side * sign * (width / 2 + 0.03)
        s.ramp(a + off, b + off, 0.06, ya + 1.0, yb + 1.0, thickness=1.0)


def tilt_dock(seed: int) -> trimesh.Trimesh:
    """A harbour's pontoon dock (an open-world coast's marina at low water, a heist's boat yard): a quay 22 m deep
    along x (its top y = 0, sheds and bollards on it, walled on its landward side, the water under everything else:
    no floor) with 8-9 piers south of it (``tilt_dock_plan(seed)``). Each pier: *a gangway 1.8 m wide, railed, from
    the quay's edge down to its main pontoon at a slope of 10-25 degrees (drawn per gangway)*, the pontoons floating
    1.1-2.7 m under the quay (the tide, drawn per level, and each float's freeboard); a main pontoon 2.6-3.2 m wide
    and 26-36 m long *rolled 0-5 degrees about its length* (drawn per pontoon); fingers 2.2 m wide and 7 m long every
    6-8 m off one side or the other, at the main pontoon's deck and roll; at its far end *a ramp of 10-25 degrees
    (drawn per ramp) up to a barge or down to a float 0.4-1.1 m away*, a head pontoon 12 x 6 m rolled on its own.
    Every ramp's lower end rests on its deck 0.05 m proud of it (a hinge plate); the upper end meets its deck flush.
    Bollards and cleats (ridged) on the decks, a boat (ridged) at some fingers.

    Expected (written before the first run): one area for a player (every pontoon, finger and head reached: ramps of
    10-25 degrees are under the agent's 45, the rolls of 0-5 degrees too, a hinge plate of 0.05 m is under the climb).
    On the navmesh route the kinks where a ramp meets a deck (10-25 degrees of change over a cell) and the rolled
    decks' edges should hold; gangways 1.8 m wide between rails keep about 0.8 m for the agent's centre, over the
    1.55 m round 36's bridges needed, so none should be lost. The fingers, 2.2 m over water on three sides, keep
    1.2 m less the ledge rule's cell from each edge. The sampling route casts down onto sloping decks: the same
    reachable places. Traffic highest on the gangways (each pier's only way) and the quay between them."""
    plan = tilt_dock_plan(seed)
    rng = np.random.default_rng(seed + 1000)
    length, depth = plan["length"], plan["depth"]
    s = _Solids()
    s.wall((0.0, depth), (length, depth), -0.1, 4.0, [(length / 2 - 2.0, 4.0)], thickness=0.4)
    s.wall((0.0, 0.0), (0.0, depth), -0.1, 4.0, thickness=0.4)
    s.wall((length, 0.0), (length, depth), -0.1, 4.0, thickness=0.4)
    keep = [(p["x"] - 3.0, p["x"] + 3.0, 0.0, 4.0) for p in plan["piers"]]
    spots: list[tuple[np.ndarray, float]] = []
    sheds: list[tuple[float, float, float, float]] = []
    for _ in range(int(rng.integers(4, 7))):  # sheds on the quay (closed: the quay stops under them)
        p = _placed(rng, spots, 2.0, length - 2.0, 6.0, depth - 1.0, 3.5, keep)
        if p is not None:
            sheds.append(_ridged(s, p[0] - 3.0, p[0] + 3.0, p[1] - 2.0, p[1] + 2.0, -0.1, 3.0))
    s.ground(0.0, length, 0.0, depth, 0.0, sheds, thickness=3.0)  # the quay
    for x in np.arange(5.0, length - 2.0, 7.0):  # bollards along the quay's edge, clear of the gangways
        if all(abs(x - p["x"]) > 2.5 for p in plan["piers"]):
            _trunk(s, np.array([float(x), 0.6]), 0.2, -0.1, 0.6)
    for pier in plan["piers"]:
        x, (z0, z1), w, deck, roll = pier["x"], pier["z"], pier["width"], pier["deck"], pier["roll"]
        _railed_ramp(s, np.array([x, 0.0]), np.array([x, z1 + 0.6]), 1.8, 0.0, deck + 0.05)  # on the deck's axis
        _rolled_deck(s, x - w / 2, x + w / 2, z0, z1 + 1.0, deck, roll)
        for zf, side in pier["fingers"]:
            xa = x + side * w / 2
            xb = xa + side * 7.0
            mid = (xa + xb) / 2  # the finger's deck in the pontoon's plane, flush with its edge, rolled alike
            _rolled_deck(s, min(xa, xb), max(xa, xb), zf - 1.1, zf + 1.1, deck + (mid - x) * math.tan(roll), roll)
            if rng.random() < 0.5:  # a boat moored alongside the finger
                zb = zf + 2.6 if rng.random() < 0.5 else zf - 2.6
                _ridged(s, min(xa, xb) + 0.3, max(xa, xb) - 0.3, zb - 1.2, zb + 1.2, deck - 1.0, deck + 0.9)
        head = pier["head"]
        hz1 = z0 - head["run"]
        ramp_w = 2.0
        a, b = np.array([x, z0 + 0.4]), np.array([x, hz1 - 0.4])
        if head["deck"] > deck:  # up to a barge: lower end on the pontoon, upper end flush with the barge
            _railed_ramp(s, a, b, ramp_w, deck + 0.05, head["deck"])
        else:  # down to a float: upper end flush with the pontoon, lower end on the float
            _railed_ramp(s, a, b, ramp_w, deck, head["deck"] + 0.05)
        _rolled_deck(s, x - 6.0, x + 6.0, hz1 - 6.0, hz1, head["deck"], head["roll"])
        for dx in (-5.2, 5.2):  # cleats on the head
            _ridged(s, x + dx - 0.3, x + dx + 0.3, hz1 - 3.2, hz1 - 2.8, head["deck"] - 0.1, head["deck"] + 0.3)
    return s.mesh()


def bump_park_plan(seed: int) -> dict:
    """The plan of :func:`bump_park` for ``seed``: the lot's size, the footway's kerb, the aisles (z0, z1) and per
    aisle its bumps (x, height, top width, flank angle), the double rows of bays (z0, z1 of the row, the island's
    kerb height) with the crossings through each island (x0, x1). O(bays)."""
    rng = np.random.default_rng(seed)
    size_x, size_z = float(rng.uniform(84.0, 96.0)), float(rng.uniform(58.0, 66.0))
    footway = (size_z - 4.0, float(rng.uniform(0.15, 0.25)))
    aisles, rows = [], []
    z = 2.0
    while True:
        aisle = (z, z + 6.5)
        bumps = []
        for x in np.arange(12.0 + float(rng.uniform(0.0, 4.0)), size_x - 8.0, float(rng.uniform(14.0, 22.0))):
            bumps.append({"x": float(x), "height": float(rng.uniform(0.08, 0.15)), "top": float(rng.uniform(0.2, 0.4)),
                          "flank": math.radians(float(rng.uniform(30.0, 60.0)))})
        aisles.append({"z": aisle, "bumps": bumps})
        z = aisle[1]
        if z + 11.2 + 6.5 > footway[0]:
            break
        crossings = [(float(x), float(x) + 2.0) for x in np.arange(20.0 + float(rng.uniform(0.0, 6.0)),
                                                                    size_x - 10.0, float(rng.uniform(22.0, 30.0)))]
        rows.append({"z": (z, z + 11.2), "kerb": float(rng.uniform(0.15, 0.25)), "crossings": crossings,
                     "occupancy": float(rng.uniform(0.7, 0.9))})
        z += 11.2
    return {"size": (size_x, size_z), "footway": footway, "aisles": aisles, "rows": rows}


def bump_park(seed: int) -> trimesh.Trimesh:
    """A retail park's surface car park (an open-world town's, a zombie game's supermarket lot) 84-96 x 58-66 m
    inside a fence 2 m high with two road gates: drive aisles 6.5 m wide along x, *each crossed every 14-22 m by a
    speed bump 0.08-0.15 m high, 0.2-0.4 m wide on top, whose flanks slope at 30-60 degrees (drawn per bump)*, between
    double rows of bays 5 m deep nose to nose over *a planted island 1.2 m wide on a kerb 0.15-0.25 m high (drawn
    per island)*, crossed at ground level every 22-30 m by a footpath 2 m wide; along the north a footway 4 m wide
    on *a kerb of 0.15-0.25 m* before a store's front (a wall 6 m high with three doors) (``bump_park_plan(seed)``).
    Cars (:func:`level_kinds._car`) in 70-90 % of the bays, trolley shelters and trees (trunks) on the islands.

    Expected (written before the first run): one area for a player: a bump of at most 0.15 m and a kerb of at most
    0.25 m are stepped over anywhere (under the 0.4 m climb), the islands' tops (1.2 m, under trees) and the
    footway are walked. A bump's flanks steeper than the agent's 45 degrees (about half of them) are faces Recast
    marks unwalkable: if the span over the ground takes that face's flag, each such bump is a strip of no floor
    across its aisle, and the radius widens it to about 1.3-1.5 m: the aisle cut, its pieces joined only through
    empty bays and the islands' crossings (a few areas apart where cars fill the bays) -- a miss for the navmesh
    route if it happens, since a player walks over a 0.1 m bump. The sampling route casts down and finds the bump's
    top or flank within the climb of the aisle: one area. Traffic highest along the aisles and the footway."""
    plan = bump_park_plan(seed)
    rng = np.random.default_rng(seed + 1000)
    size_x, size_z = plan["size"]
    s = _Solids()
    s.wall((0.0, 0.0), (size_x, 0.0), -0.1, 2.0, [(6.0, 7.0), (size_x - 13.0, 7.0)], thickness=0.2)
    s.wall((0.0, 0.0), (0.0, size_z), -0.1, 2.0, thickness=0.2)
    s.wall((size_x, 0.0), (size_x, size_z), -0.1, 2.0, thickness=0.2)
    s.wall((0.0, size_z), (size_x, size_z), -0.1, 6.0, [(size_x * f - 1.5, 3.0) for f in (0.25, 0.5, 0.75)],
           thickness=0.3)
    fz, kerb = plan["footway"]
    s.box(0.0, size_x, -0.3, kerb, fz, size_z)
    for x in np.linspace(6.0, size_x - 6.0, 6):  # trolley bays on the footway
        _ridged(s, float(x) - 1.2, float(x) + 1.2, fz + 0.8, fz + 1.4, kerb - 0.1, kerb + 1.1)
    for aisle in plan["aisles"]:
        z0, z1 = aisle["z"]
        for bump in aisle["bumps"]:
            h, top, flank = bump["height"], bump["top"], bump["flank"]
            half = top / 2 + h / math.tan(flank)
            x = bump["x"]
            s.hull(np.array([[xx, y, z] for z in (z0 + 0.3, z1 - 0.3) for xx, y in
                             ((x - half, 0.0), (x + half, 0.0), (x - top / 2, h), (x + top / 2, h))]
                            + [[x - half, -0.05, z] for z in (z0 + 0.3, z1 - 0.3)]))
    for row in plan["rows"]:
        z0, z1 = row["z"]
        zi0, zi1 = z0 + 5.0, z0 + 6.2  # the island between the two rows of bays
        xs = [1.0] + [v for c in row["crossings"] for v in c] + [size_x - 1.0]
        for xa, xb in zip(xs[0::2], xs[1::2]):
            s.box(xa, xb, -0.3, row["kerb"], zi0, zi1)
            for x in np.arange(xa + 3.0, xb - 1.0, 8.0):
                _trunk(s, np.array([float(x), (zi0 + zi1) / 2]), 0.2, row["kerb"] - 0.1, 4.0)
        for x in np.arange(2.0, size_x - 4.5, 2.6):  # the bays: 2.6 m wide, cars nosed in to the island
            if any(c0 - 2.6 < x < c1 for c0, c1 in row["crossings"]):
                continue
            for bz0, bz1 in ((z0 + 0.3, zi0 - 0.2), (zi1 + 0.2, z1 - 0.3)):
                if rng.random() < row["occupancy"]:
                    _car(s, float(x) + 0.4, float(x) + 2.2, bz0 + 0.2, bz1 - 0.2, 0.0)
    s.ground(-4.0, size_x + 4.0, -4.0, size_z, 0.0, [])
    return s.mesh()


def parapet_roofs_plan(seed: int) -> dict:
    """The plan of :func:`parapet_roofs` for ``seed``: the roof's height, the grid of bays (columns, rows, bay size,
    walkway width) and per bay its kind (pitched or a terrace), and for a pitched bay its pitch, its ridge's
    direction and the parapet's height on each side (south, north, west, east). O(bays)."""
    rng = np.random.default_rng(seed)
    cols, rows = int(rng.integers(6, 8)), 4
    bay = (float(rng.uniform(11.0, 14.0)), float(rng.uniform(9.0, 12.0)))
    walkway = float(rng.uniform(2.6, 3.4))
    bays = []
    for c in range(cols):
        for r in range(rows):
            if (c, r) == (0, 0):  # the stair tower's terrace
                bays.append({"cell": (c, r), "kind": "terrace"})
                continue
            if rng.random() < 0.3:
                bays.append({"cell": (c, r), "kind": "terrace"})
                continue
            bays.append({"cell": (c, r), "kind": "pitched", "pitch": math.radians(float(rng.uniform(20.0, 35.0))),
                         "along_x": bool(rng.random() < 0.5),
                         "parapets": {side: float(rng.uniform(0.3, 0.9))
                                      for side in ("south", "north", "west", "east")}})
    return {"height": 14.0, "grid": (cols, rows, bay, walkway), "bays": bays}


def parapet_roofs(seed: int) -> trimesh.Trimesh:
    """A city block's rooftop (a parkour game's or a stealth game's roofs, the fight's arena): one building 14 m high
    whose flat roof is a grid of 6-7 x 4 bays 11-14 x 9-12 m between *flat walkways 2.6-3.4 m wide* (the roof's top),
    a parapet 1.1 m high round the whole. About 70 % of the bays are *roofs pitched 20-35 degrees (drawn per roof)*,
    ridged along x or z, their eaves at the walkway's level *behind parapets 0.25 m thick and 0.3-0.9 m high, drawn
    per side* (none open); the rest are terraces at the walkway's level with AC units and skylights (ridged). The
    only way up is a stair tower (closed, ridged) whose door opens on the south-west terrace
    (``parapet_roofs_plan(seed)``); chimneys (ridged) on some roofs.

    Expected (written before the first run): the walkways and terraces are one area for a player. A pitched roof is
    reached over a parapet under the agent's 0.4 m climb (one side in six is; the parapet's top, 0.25 m wide, is
    stepped across) and is a place apart behind parapets of 0.4 m or more on all four sides (it should be an area
    apart, its warning naming a step too high: the parapet), about half of the roofs on each seed (by the plan 10 of
    20, 8 of 14 and 11 of 21 reached on seeds 0-2). Roofs of 20-35
    degrees are under the 45 degree slope: a reached roof is walked up to its ridge and over it. On the navmesh
    route the climb is read in cells of 0.125 m (3 cells, 0.375 m; round 36's benches of 0.45 m were climbed): a
    parapet of 0.375-0.45 m may read either way. The sampling route's step rule reads the climb from the mesh; its
    samples on the parapet's top need the agent's 1 m (none): it joins a roof only by a walk over the parapet.
    Traffic on the walkways, highest near the stair tower."""
    plan = parapet_roofs_plan(seed)
    rng = np.random.default_rng(seed + 1000)
    top = plan["height"]
    cols, rows, (bx, bz), w = plan["grid"]
    size_x, size_z = cols * bx + (cols + 1) * w, rows * bz + (rows + 1) * w
    s = _Solids()
    pitched = [(w + b["cell"][0] * (bx + w) + 0.25, w + b["cell"][0] * (bx + w) + bx - 0.25,
                w + b["cell"][1] * (bz + w) + 0.25, w + b["cell"][1] * (bz + w) + bz - 0.25)
               for b in plan["bays"] if b["kind"] == "pitched"]
    # the building, its top the walkways' and terraces', stopping under each pitched roof (a closed body: the top
    # running on inside it would be floor under the roof's slopes, where they rise over the agent's height)
    s.ground(0.0, size_x, 0.0, size_z, top, pitched, thickness=top)
    for a, b in (((0.0, 0.0), (size_x, 0.0)), ((0.0, size_z), (size_x, size_z)), ((0.0, 0.0), (0.0, size_z)),
                 ((size_x, 0.0), (size_x, size_z))):
        s.wall(a, b, top - 0.1, top + 1.1, thickness=0.3)
    _ridged(s, 0.15, 3.5, 0.15, 3.0, top - 0.1, top + 3.0)  # the stair tower in the south-west corner
    for b in plan["bays"]:
        c, r = b["cell"]
        x0, z0 = w + c * (bx + w), w + r * (bz + w)
        x1, z1 = x0 + bx, z0 + bz
        if b["kind"] == "terrace":
            for _ in range(int(rng.integers(3, 6))):  # AC units and skylights
                x = float(rng.uniform(x0 + 2.0, x1 - 2.0))
                z = float(rng.uniform(z0 + 1.5, z1 - 1.5))
                if c == 0 and r == 0 and x < 5.0 and z < 5.0:
                    continue
                _ridged(s, x - 0.8, x + 0.8, z - 0.6, z + 0.6, top - 0.1, top + 1.0)
            continue
        p = b["parapets"]
        t = 0.25
        s.box(x0, x1, top - 0.1, top + p["south"], z0, z0 + t)
        s.box(x0, x1, top - 0.1, top + p["north"], z1 - t, z1)
        s.box(x0, x0 + t, top - 0.1, top + p["west"], z0 + t, z1 - t)
        s.box(x1 - t, x1, top - 0.1, top + p["east"], z0 + t, z1 - t)
        ix0, ix1, iz0, iz1 = x0 + t, x1 - t, z0 + t, z1 - t  # the roof's eaves at the walkway's level inside
        if b["along_x"]:
            ridge = top + (iz1 - iz0) / 2 * math.tan(b["pitch"])
            s.hull(np.array([[x, top - 0.1, z] for x in (ix0, ix1) for z in (iz0, iz1)]
                            + [[x, top, z] for x in (ix0, ix1) for z in (iz0, iz1)]
                            + [[x, ridge, (iz0 + iz1) / 2] for x in (ix0, ix1)]))
        else:
            ridge = top + (ix1 - ix0) / 2 * math.tan(b["pitch"])
            s.hull(np.array([[x, top - 0.1, z] for x in (ix0, ix1) for z in (iz0, iz1)]
                            + [[x, top, z] for x in (ix0, ix1) for z in (iz0, iz1)]
                            + [[(ix0 + ix1) / 2, ridge, z] for z in (iz0, iz1)]))
        if rng.random() < 0.5:  # a chimney through the roof's lower slope
            x, z = float(rng.uniform(ix0 + 2.0, ix1 - 2.0)), float(rng.uniform(iz0 + 1.2, iz0 + 2.2))
            _ridged(s, x - 0.4, x + 0.4, z - 0.4, z + 0.4, top, ridge + 1.0)
    return s.mesh()


KINDS: dict[str, Callable[[int], trimesh.Trimesh]] = {
    "skirted_maze": skirted_maze, "awning_market": awning_market, "arcade_cloister": arcade_cloister,
    "tilt_dock": tilt_dock, "bump_park": bump_park, "parapet_roofs": parapet_roofs,
}
"""Kind name -> generator (seed -> Y-up mesh in metres) of the thirty-seventh round."""


if __name__ == "__main__":
    write_kinds(kinds=KINDS, description=__doc__.splitlines()[0])
