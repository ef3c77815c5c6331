"""Level kinds of the fifth held-out round (issue 9): generators no preset setting was made on.

Six kinds, each about 1,000 navmesh polygons with the presets' agent (radius 0.5 m, height 2 m, climb 0.4 m):
``subway`` (platforms, track pits 1.2 m lower, stairs up to two concourses), ``archipelago`` (islands joined by
narrow railed bridges), ``car_park`` (three storeys joined by ramps and two switchback stairwells, the top one
an office), ``forest`` (hilly ground, 300 trunks, fallen logs), ``stadium`` (a bowl of stepped tiers, aisle
stairs, a cross aisle and vomitories out to an outer deck) and ``harbour`` (a quay, piers, moored boats with
walkable decks). Y up, metres, ``numpy.random.default_rng(seed)``; every solid is a closed convex body with
outward faces (trimesh's convex hull), so Recast reads each top as floor. Recast also reads as floor the ground
inside a closed solid with head room over it, so the ground stops under the stadium's stands and the harbour's
warehouses (a first draft had walkable strips inside the stands and a floor in every warehouse).

Run: ``.venv/bin/python benchmarks/level_kinds.py OUT_DIR [--kinds subway forest] [--seeds 0 1 2]`` writes
``OUT_DIR/<kind>_s<seed>.obj``, the files ``benchmarks/analysis_quality.py --levels`` takes (which also takes the
kinds' names and builds them with ``--seeds``).
"""

from __future__ import annotations

import argparse
import math
from collections.abc import Callable
from pathlib import Path

import numpy as np
import trimesh


class _Solids:
    """Convex solids gathered into one mesh."""

    def __init__(self) -> None:
        self.parts: list[trimesh.Trimesh] = []

    def hull(self, points: np.ndarray) -> None:
        """The convex hull of ``points`` (k, 3), metres."""
        self.parts.append(trimesh.convex.convex_hull(np.asarray(points, dtype=np.float64)))

    def box(self, x0: float, x1: float, y0: float, y1: float, z0: float, z1: float) -> None:
        """An axis-aligned box over [x0, x1] x [y0, y1] x [z0, z1]."""
        self.hull(np.array([[x, y, z] for x in (x0, x1) for y in (y0, y1) for z in (z0, z1)]))

    def prism(self, plan: np.ndarray, y0: float, y1: float) -> None:
        """A vertical prism over the convex plan polygon ``plan`` (k, 2) of x, z, between heights y0 < y1."""
        plan = np.asarray(plan, dtype=np.float64)
        self.hull(np.concatenate([np.insert(plan, 1, y, axis=1) for y in (y0, y1)]))

    def slab(self, x0: float, x1: float, z0: float, z1: float, top: float, holes: list[tuple[float, float, float, float]],
             thickness: float = 0.3) -> None:
        """A floor slab over [x0, x1] x [z0, z1] with its top at ``top``, open over each hole (x0, x1, z0, z1).

        Cut along every hole's edges into a grid of rectangles; the cells outside all holes are kept.
        """
        xs = np.unique(np.clip([x0, x1, *[h[i] for h in holes for i in (0, 1)]], x0, x1))
        zs = np.unique(np.clip([z0, z1, *[h[i] for h in holes for i in (2, 3)]], z0, z1))
        for a, b in zip(xs[:-1], xs[1:]):
            for c, d in zip(zs[:-1], zs[1:]):
                mx, mz = (a + b) / 2, (c + d) / 2
                if not any(h[0] < mx < h[1] and h[2] < mz < h[3] for h in holes):
                    self.box(a, b, top - thickness, top, c, d)

    def stairs(self, start: np.ndarray, heading: np.ndarray, width: float, y0: float, rise: float,
               riser: float = 0.15, tread: float = 0.30) -> None:
        """A straight flight from ``start`` (x, z) along the unit ``heading`` (x, z), climbing ``rise`` from ``y0``.

        Each step is a solid block from ``y0`` up to its tread; the flight's plan is ``rise / riser * tread`` long.
        """
        start, heading = np.asarray(start, dtype=np.float64), np.asarray(heading, dtype=np.float64)
        side = np.array([-heading[1], heading[0]]) * width / 2
        for i in range(int(round(rise / riser))):
            a, b = start + heading * tread * i, start + heading * tread * (i + 1)
            self.prism(np.array([a - side, b - side, b + side, a + side]), y0 - 0.3, y0 + riser * (i + 1))

    def ramp(self, a: np.ndarray, b: np.ndarray, width: float, ya: float, yb: float, thickness: float = 0.3) -> None:
        """A straight deck from plan point ``a`` (x, z) with its top at ``ya`` to ``b`` at ``yb``, ``width`` m wide."""
        a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
        along = (b - a) / np.linalg.norm(b - a)
        side = np.array([-along[1], along[0]]) * width / 2
        corners = [(a - side, ya), (a + side, ya), (b - side, yb), (b + side, yb)]
        self.hull(np.array([[p[0], y - d, p[1]] for p, y in corners for d in (0.0, thickness)]))

    def mesh(self) -> trimesh.Trimesh:
        """Every solid in one mesh, coincident vertices merged."""
        mesh = trimesh.util.concatenate(self.parts)
        mesh.merge_vertices()
        return mesh


def subway(seed: int) -> trimesh.Trimesh:
    """A subway station: side and island platforms at y = 0, two track pits 1.2 m lower, a concourse at each end.

    Across z: side platform, pit, island platform, pit, island platform, pit, side platform, walled in. Each end has a concourse
    4.5 m up (a slab over the whole width with a gate line across it), reached from every platform by a
    flight of 0.15 / 0.30 m steps 2.5 m wide. Two rows of pillars every 4.5-5.5 m on each island, benches on the platforms.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    length = rng.uniform(230.0, 250.0)
    side_w, island_w, pit_w = rng.uniform(4.5, 6.0), rng.uniform(8.0, 11.0), 4.6
    edges = np.cumsum([0.0, side_w, pit_w, island_w, pit_w, island_w, pit_w, side_w])  # z of each band's edges
    platforms = list(zip(edges[0::2], edges[1::2]))
    pits = list(zip(edges[1::2], edges[2::2]))
    width = edges[-1]
    concourse = rng.uniform(18.0, 26.0, size=2)  # x extent of the concourse at each end
    s.box(0, length, -1.7, -1.2, 0, width)  # pit floor everywhere under the bands
    for z0, z1 in platforms:
        s.box(0, length, -1.7, 0.0, z0, z1)
    for z0, z1 in pits:  # rails in the pits
        for offset in (1.5, 3.1):
            s.box(0, length, -1.2, -1.05, z0 + offset - 0.04, z0 + offset + 0.04)
    s.box(-0.5, 0, -1.7, 8.0, -0.5, width + 0.5)
    s.box(length, length + 0.5, -1.7, 8.0, -0.5, width + 0.5)
    s.box(-0.5, length + 0.5, -1.7, 8.0, -0.5, 0)
    s.box(-0.5, length + 0.5, -1.7, 8.0, width, width + 0.5)
    run = 4.5 / 0.15 * 0.30
    for end, extent in enumerate(concourse):
        x0, x1 = (0.0, extent) if end == 0 else (length - extent, length)
        s.slab(x0, x1, 0, width, 4.5, [])
        gate = (x0 + x1) / 2 + (-3.0 if end == 0 else 3.0)  # a gate line: 0.6 m cabinets, 1.3 m passages
        for z in np.arange(0.4, width - 1.0, 1.9):
            s.box(gate - 0.4, gate + 0.4, 4.5, 5.5, z, z + 0.6)
        toward = np.array([-1.0, 0.0]) if end == 0 else np.array([1.0, 0.0])
        foot_x = x1 + run if end == 0 else x0 - run
        for z0, z1 in platforms:
            zc = (z0 + z1) / 2 + rng.uniform(-0.2, 0.2) * (z1 - z0 - 2.5)
            s.stairs(np.array([foot_x, zc]), toward, 2.5, 0.0, 4.5)
    for x in np.arange(concourse[0] + run + 4.0, length - concourse[1] - run - 2.0, rng.uniform(4.5, 5.5)):
        for z0, z1 in platforms[1:-1]:  # two rows of pillars on each island, benches between them
            for zc in (z0 + 2.2, z1 - 2.2):
                s.box(x - 0.4, x + 0.4, 0.0, 4.2, zc - 0.4, zc + 0.4)
            if rng.random() < 0.5:
                s.box(x + 2.0, x + 4.0, 0.0, 0.45, (z0 + z1) / 2 - 0.3, (z0 + z1) / 2 + 0.3)
        for z0, z1 in (platforms[0], platforms[-1]):
            if rng.random() < 0.8:
                zb = z0 + 0.6 if z0 == 0 else z1 - 1.1
                s.box(x - 1.0, x + 1.0, 0.0, 0.45, zb, zb + 0.5)
    return s.mesh()


def _islands(rng: np.random.Generator, n: int, extent: float) -> tuple[np.ndarray, np.ndarray]:
    """Centres (n, 2) and radii (n,) of islands in a square ``extent`` m wide, at least 12 m of water apart."""
    centres, radii = [], []
    while len(centres) < n:
        c, r = rng.uniform(20, extent - 20, size=2), rng.uniform(9.0, 18.0)
        if all(np.linalg.norm(c - d) > r + q + 12.0 for d, q in zip(centres, radii)):
            centres.append(c)
            radii.append(r)
    return np.array(centres), np.array(radii)


def archipelago(seed: int) -> trimesh.Trimesh:
    """Islands (flat convex tops 0.5-2 m up, rocks and palm trunks on them) joined by narrow railed bridges.

    The bridges follow the islands' minimum spanning tree plus 3 of the next shortest pairs (a few loops);
    each deck is 1.8-2.4 m between 1 m railings and slopes from one island's top to the other's.
    No water surface: the sea is nothing to walk on.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    centres, radii = _islands(rng, 26, 330.0)
    tops = rng.uniform(0.5, 2.0, size=len(centres))
    for c, r, top in zip(centres, radii, tops):
        angles = np.sort(rng.uniform(0, 2 * math.pi, size=14))
        plan = c + (r * rng.uniform(0.75, 1.0, size=14))[:, None] * np.stack([np.cos(angles), np.sin(angles)], 1)
        s.prism(plan, top - 3.0, top)
        for _ in range(rng.integers(6, 12)):  # rocks and palms well inside the shore
            p = c + rng.uniform(-0.5, 0.5, size=2) * r
            if rng.random() < 0.5:
                rock = rng.uniform(0.8, 2.2)
                s.hull(np.concatenate([p + rng.normal(0, rock / 2, size=(8, 2)), rng.uniform(top - 0.2, top + rock, (8, 1))],
                                      axis=1)[:, [0, 2, 1]])
            else:
                angles = np.linspace(0, 2 * math.pi, 8, endpoint=False)
                s.prism(p + 0.25 * np.stack([np.cos(angles), np.sin(angles)], 1), top - 0.5, top + 6.0)
    gaps = np.linalg.norm(centres[:, None] - centres[None], axis=2) - radii[:, None] - radii[None]
    pairs = sorted((gaps[i, j], i, j) for i in range(len(centres)) for j in range(i + 1, len(centres)))
    group = list(range(len(centres)))

    def root(i: int) -> int:
        while group[i] != i:
            i = group[i]
        return i

    chosen, extra = [], []
    for _, i, j in pairs:  # Kruskal's minimum spanning tree, then the shortest pairs left
        if root(i) != root(j):
            group[root(i)] = root(j)
            chosen.append((i, j))
        elif len(extra) < 3:
            extra.append((i, j))
    for i, j in chosen + extra:
        along = (centres[j] - centres[i]) / np.linalg.norm(centres[j] - centres[i])
        a, b = centres[i] + along * (radii[i] * 0.6), centres[j] - along * (radii[j] * 0.6)
        width = rng.uniform(1.8, 2.4)
        s.ramp(a, b, width, tops[i], tops[j])
        side = np.array([-along[1], along[0]]) * (width / 2 - 0.05)
        shore_a, shore_b = centres[i] + along * radii[i], centres[j] - along * radii[j]
        span = np.linalg.norm(b - a)
        t = np.array([np.dot(shore_a - a, along), np.dot(shore_b - a, along)]) / span
        ya, yb = tops[i] + t * (tops[j] - tops[i])
        for sign in (-1, 1):  # railings over the water only, so the bridge's ends stay open
            s.ramp(shore_a + sign * side, shore_b + sign * side, 0.1, ya + 1.0, yb + 1.0, thickness=1.3)
    return s.mesh()


def car_park(seed: int) -> trimesh.Trimesh:
    """Three storeys 3.5 m apart on a 90 x 58 m plan: two car-park decks and an office on top.

    Storey k joins k + 1 by a 6 m ramp at 10 degrees through a slot in k + 1, at alternate ends; two
    switchback stairwells (3 x 6.4 m shafts, walls with one 1.6 m door a storey) at opposite corners. Decks
    have 0.6 m pillars on an 8 m grid and parked cars (4.2 x 1.8 x 1.5 m blocks); the office has a row of 6 x 12 m
    rooms along its back (a 1.2 m door each) and desks in the open floor; 1.1 m parapets.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    size_x, size_z, storey = 90.0, 58.0, 3.5
    run = storey / math.tan(math.radians(10.0))
    ramps = [(10.0, 10.0 + run, 2.0, 8.0) if k % 2 == 0 else (size_x - 10.0 - run, size_x - 10.0, 2.0, 8.0)
             for k in range(2)]
    wells = [(size_x - 3.0, size_x, size_z - 6.4, size_z), (0.0, 3.0, size_z - 6.4, size_z)]
    for k in range(3):
        y = k * storey
        holes = list(wells) if k > 0 else []
        if k > 0:
            holes.append(ramps[k - 1])
        s.slab(0, size_x, -0.2, size_z, y, holes)
        for x0, x1, z0, z1 in ((-0.3, 0, -0.2, size_z), (size_x, size_x + 0.3, -0.2, size_z),
                               (-0.3, size_x + 0.3, -0.5, -0.2), (-0.3, size_x + 0.3, size_z, size_z + 0.3)):
            s.box(x0, x1, y, y + 1.1, z0, z1)
        for x0, x1, z0, z1 in wells:  # shaft walls, a door toward the deck on the inner long side
            inner = x0 - 0.2 if x0 > 0 else x1
            s.box(inner, inner + 0.2, y, y + storey - 0.3, z0, z0 + 2.0)
            s.box(inner, inner + 0.2, y, y + storey - 0.3, z0 + 3.6, z1)
            s.box(x0, x1, y, y + storey - 0.3, z0 - 0.2, z0)
        if k < 2:
            x0, x1, z0, z1 = ramps[k]
            up = k % 2 == 0
            s.ramp(np.array([x0 if up else x1, 5.0]), np.array([x1 if up else x0, 5.0]), 6.0, y, y + storey)
            for z in (z0 - 0.2, z1):  # kerbs along the ramp's slot
                s.box(x0, x1, y, y + 1.0, z, z + 0.2)
        if k < 2:
            for x in np.arange(8.0, size_x - 4.0, 8.0):
                for z in np.arange(12.0, size_z - 4.0, 8.0):
                    s.box(x - 0.3, x + 0.3, y, y + storey - 0.3, z - 0.3, z + 0.3)
            for _ in range(45):
                x, z = rng.uniform(5, size_x - 9), rng.uniform(11.0, size_z - 8.0)
                s.box(x, x + 4.2, y, y + 1.5, z, z + 1.8) if rng.random() < 0.7 else s.box(x, x + 1.8, y, y + 1.5, z, z + 4.2)
        else:
            wall = size_z - 12.0  # one row of rooms along the back, 12 m deep, a 1.2 m door each
            rooms = np.arange(6.0, size_x - 6.0 + 1e-9, 6.0)
            doors = rooms[:-1] + rng.uniform(1.0, 3.8, size=len(rooms) - 1)
            xs = [rooms[0], *sum(([d, d + 1.2] for d in doors), []), rooms[-1]]
            for a, b in zip(xs[0::2], xs[1::2]):
                s.box(a, b, y, y + 3.0, wall, wall + 0.15)
            for x in rooms:
                s.box(x, x + 0.15, y, y + 3.0, wall, size_z)
            for _ in range(90):
                x, z = rng.uniform(6, size_x - 8), rng.uniform(11.0, size_z - 15.0)
                s.box(x, x + 1.6, y, y + 0.75, z, z + 0.8)
    for x0, x1, z0, z1 in wells:  # switchbacks: up along +z on one half, landing, back along -z on the other
        for k in range(2):
            y = k * storey
            s.stairs(np.array([x0 + 0.75, z0 + 0.4]), np.array([0.0, 1.0]), 1.5, y, storey / 2, riser=0.175, tread=0.28)
            landing = z0 + 0.4 + 10 * 0.28
            s.box(x0, x1, y, y + storey / 2, landing, z1)
            s.stairs(np.array([x0 + 2.25, landing]), np.array([0.0, -1.0]), 1.5, y + storey / 2, storey / 2,
                     riser=0.175, tread=0.28)
    return s.mesh()


def forest(seed: int) -> trimesh.Trimesh:
    """Open hilly ground 120 m square (hills up to about 6 m, slopes under 25 degrees) with 300 tree trunks
    (octagons 0.2-0.6 m in radius) and 30 fallen logs (0.3-0.5 m radius, 4-10 m long) lying on it."""
    rng = np.random.default_rng(seed)
    s = _Solids()
    size, step = 120.0, 2.5
    grid = np.arange(0.0, size + step / 2, step)
    waves = rng.normal(size=(6, 4))

    def height(x: np.ndarray, z: np.ndarray) -> np.ndarray:
        return sum(1.2 * np.sin(x * (0.02 + 0.03 * abs(w[0])) + w[1] * 3) * np.cos(z * (0.02 + 0.03 * abs(w[2])) + w[3] * 3)
                   for w in waves)

    gx, gz = np.meshgrid(grid, grid, indexing="ij")
    n = len(grid)
    vertices = np.stack([gx.ravel(), height(gx, gz).ravel(), gz.ravel()], axis=1)
    index = np.arange(n * n).reshape(n, n)
    a, b, c, d = index[:-1, :-1].ravel(), index[1:, :-1].ravel(), index[1:, 1:].ravel(), index[:-1, 1:].ravel()
    faces = np.concatenate([np.stack([a, c, b], 1), np.stack([a, d, c], 1)])  # counter-clockwise seen from +y
    ground = trimesh.Trimesh(vertices, faces, process=False)
    skirt = ground.copy()
    skirt.vertices[:, 1] -= 0.5
    skirt.invert()
    s.parts += [ground, skirt]
    angles = np.linspace(0, 2 * math.pi, 8, endpoint=False)
    ring = np.stack([np.cos(angles), np.sin(angles)], 1)
    trunks = rng.uniform(3.0, size - 3.0, size=(300, 2))
    for (x, z), r in zip(trunks, rng.uniform(0.2, 0.6, size=300)):
        y = float(height(np.array(x), np.array(z)))
        s.prism(np.array([x, z]) + r * ring, y - 1.5, y + 9.0)
    for _ in range(30):
        centre, heading = rng.uniform(8.0, size - 8.0, size=2), rng.uniform(0, math.pi)
        half, r = rng.uniform(2.0, 5.0), rng.uniform(0.3, 0.5)
        along = np.array([math.cos(heading), math.sin(heading)])
        ends = [centre - half * along, centre + half * along]
        ys = [float(height(np.array(p[0]), np.array(p[1]))) + r * 0.8 for p in ends]
        side = np.array([-along[1], along[0]])
        s.hull(np.array([[p[0] + r * ca * side[0], y + r * sa, p[1] + r * ca * side[1]]
                         for p, y in zip(ends, ys) for ca, sa in ring]))
    return s.mesh()


def stadium(seed: int) -> trimesh.Trimesh:
    """A bowl: a pitch at y = 0, four stands of stepped tiers (open corners), each with aisle stairs, a cross aisle
    half way up, a top walkway, and vomitories (tunnels 3 m wide) from the cross aisle out to an outer deck at
    the cross aisle's height, which stairs at both ends of the stand bring down to the ground.

    Tier rows are 0.8 m deep and 0.45 m high (more than the agent's climb: seats are not walked on); aisles
    (2 m wide) climb them in half steps of 0.225 / 0.4 m.
    """
    rng = np.random.default_rng(seed)
    s = _Solids()
    half_x, half_z = rng.uniform(52.0, 58.0), rng.uniform(34.0, 38.0)
    lower, upper, row, rise = int(rng.integers(9, 12)), int(rng.integers(9, 12)), 0.8, 0.45
    margin = 5.0  # flat walk between the pitch and the first row
    cross_depth, top_depth = 3.0, 3.0
    # one stand's depth profile, distance from its front (toward the pitch): (start, end, top) per step
    steps: list[tuple[float, float, float]] = []
    d, y = 0.0, 0.0
    for i in range(lower):
        y += rise
        steps.append((d, d + row, y))
        d += row
    steps.append((d, d + cross_depth, y))
    cross = (d, d + cross_depth, y)
    d += cross_depth
    for i in range(upper):
        y += rise
        steps.append((d, d + row, y))
        d += row
    steps.append((d, d + top_depth, y))
    depth, cross_y = d + top_depth, cross[2]
    near_x, near_z = half_x + margin, half_z + margin
    # the ground stops under the stands, whose solid tiers reach down to its bottom: no floor inside a solid
    s.slab(-half_x - 40, half_x + 40, -half_z - 40, half_z + 40, 0.0, [
        (-half_x, half_x, near_z, near_z + depth), (-half_x, half_x, -near_z - depth, -near_z),
        (near_x, near_x + depth, -half_z, half_z), (-near_x - depth, -near_x, -half_z, half_z)], thickness=0.5)
    deck_depth = 5.0
    for side in range(4):
        along_x = side < 2
        span = half_x if along_x else half_z
        front = (half_z if along_x else half_x) + margin
        sign = 1.0 if side % 2 == 0 else -1.0

        def put(a0: float, a1: float, d0: float, d1: float, y0: float, y1: float) -> None:
            """A box in the stand's frame: ``a`` along it, ``d`` outward from its front."""
            n0, n1 = sorted((sign * (front + d0), sign * (front + d1)))
            if along_x:
                s.box(a0, a1, y0, y1, n0, n1)
            else:
                s.box(n0, n1, y0, y1, a0, a1)

        aisles = np.linspace(-span + 6.0, span - 6.0, int(rng.integers(12, 15)))
        vomitories = (aisles[:-1] + aisles[1:]) / 2
        vomitories = vomitories[::3]
        cuts = sorted([(a - 1.0, a + 1.0, "aisle") for a in aisles] + [(v - 1.5, v + 1.5, "vom") for v in vomitories])
        bounds = [-span, *sum(([c[0], c[1]] for c in cuts), []), span]
        for a0, a1 in zip(bounds[0::2], bounds[1::2]):  # plain tiers between the cuts
            for d0, d1, top in steps:
                put(a0, a1, d0, d1, -0.5, top)
        for a0, a1, kind in cuts:
            for d0, d1, top in steps:
                if kind == "aisle":
                    if d1 - d0 > row + 1e-9:  # cross aisle and top walkway stay whole across the aisle
                        put(a0, a1, d0, d1, -0.5, top)
                    else:
                        put(a0, a1, d0, d0 + row / 2, -0.5, top - rise / 2)
                        put(a0, a1, d0 + row / 2, d1, -0.5, top)
                elif d0 < cross[1] - 1e-9:  # a vomitory cuts only the upper tiers
                    put(a0, a1, d0, d1, -0.5, top)
                else:  # the tunnel: floor at the cross aisle, roof 2.6 m over it under the upper tiers
                    put(a0, a1, d0, d1, -0.5, cross_y)
                    if top > cross_y + 2.9:
                        put(a0, a1, d0, d1, cross_y + 2.6, top)
        put(-span, span, depth, depth + deck_depth, cross_y - 0.3, cross_y)  # the outer deck
        put(-span, span, depth + deck_depth, depth + deck_depth + 0.2, cross_y, cross_y + 1.1)
        run = cross_y / 0.15 * 0.30
        for end in (-1.0, 1.0):  # stairs from the deck's ends down to the ground, going outward along the stand
            a = end * span
            centre_d = sign * (front + depth + deck_depth / 2)
            start = np.array([a + end * run, centre_d]) if along_x else np.array([centre_d, a + end * run])
            heading = np.array([-end, 0.0]) if along_x else np.array([0.0, -end])
            s.stairs(start, heading, deck_depth - 0.4, 0.0, cross_y)
    return s.mesh()


def harbour(seed: int) -> trimesh.Trimesh:
    """A quay 2 m above the water with warehouses, bollards and crates, 9-10 piers out over the water, and boats moored
    along the piers: small ones whose decks lie 0.2-0.35 m under the pier (stepped onto over a gap in their
    bulwark), larger ones whose decks lie 1 m above it, reached by a gangway. No water surface."""
    rng = np.random.default_rng(seed)
    s = _Solids()
    length, quay = 300.0, 24.0
    warehouses = [(x, x + rng.uniform(12.0, 18.0), -quay, -quay + rng.uniform(7.0, 10.0))
                  for x in np.arange(6.0, length - 20.0, rng.uniform(24.0, 30.0))]  # along the back
    s.slab(0, length, -quay, 0.0, 2.0, warehouses, thickness=4.0)  # no quay inside a warehouse's solid
    for x0, x1, z0, z1 in warehouses:
        s.box(x0, x1, -2.0, 9.0, z0, z1)
    for x in np.arange(3.0, length - 2.0, 6.0):
        s.box(x - 0.25, x + 0.25, 2.0, 2.6, -1.0, -0.5)
    for _ in range(70):  # crates and containers on the open quay
        x, z = rng.uniform(2.0, length - 8.0), rng.uniform(-quay + 11.0, -3.5)
        w, d = (rng.uniform(1.0, 2.0), rng.uniform(1.0, 2.0)) if rng.random() < 0.6 else (6.0, 2.4)
        s.box(x, x + w, 2.0, 2.0 + rng.uniform(0.8, 2.6), z, z + d)
    piers = np.linspace(14.0, length - 14.0, int(rng.integers(9, 11)))
    for px in piers + rng.uniform(-3.0, 3.0, size=len(piers)):
        width, reach = rng.uniform(3.0, 5.0), rng.uniform(30.0, 55.0)
        s.box(px - width / 2, px + width / 2, 1.5, 2.0, -0.1, reach)
        for z in np.arange(3.0, reach - 1.0, 7.0):
            for sx in (-1, 1):
                bx = px + sx * (width / 2 - 0.35)
                s.box(bx - 0.2, bx + 0.2, 2.0, 2.5, z - 0.2, z + 0.2)
        for sx in (-1, 1):
            z = 2.0
            while z < reach - 8.0:
                big = rng.random() < 0.3
                beam, hull_len = (rng.uniform(5.0, 7.0), rng.uniform(14.0, 20.0)) if big else (rng.uniform(2.6, 3.8), rng.uniform(7.0, 11.0))
                if z + hull_len > reach:
                    break
                deck = 3.0 if big else 2.0 - rng.uniform(0.2, 0.35)
                near = px + sx * width / 2 + (sx * 1.5 if big else 0.0)
                far = near + sx * beam
                x0, x1 = sorted((near, far))
                bow = hull_len * 0.2
                plan = np.array([[x0, z], [x1, z], [x1, z + hull_len - bow], [(x0 + x1) / 2, z + hull_len],
                                 [x0, z + hull_len - bow]])
                s.prism(plan, deck - 1.5, deck)
                gap = (z + hull_len * 0.4, z + hull_len * 0.4 + 1.8)
                for a, b in ((z, gap[0]), (gap[1], z + hull_len - bow)):  # bulwark along the pier side, open at the gap
                    s.box(near - 0.1 if sx > 0 else near, near if sx > 0 else near + 0.1, deck, deck + 0.8, a, b)
                s.box(x0, x1, deck, deck + 0.8, z, z + 0.15)
                outer = far - sx * 0.15
                s.box(min(outer, far), max(outer, far), deck, deck + 0.8, z, z + hull_len - bow)
                cx0, cx1 = sorted((near + sx * beam * 0.35, far - sx * 0.5))
                s.box(cx0, cx1, deck, deck + 2.2, z + hull_len * 0.55, z + hull_len * 0.8)  # the cabin
                if big:  # a gangway from the pier's edge up to the bulwark's gap
                    s.ramp(np.array([px + sx * (width / 2 - 1.0), sum(gap) / 2]), np.array([near + sx * 0.6, sum(gap) / 2]),
                          1.4, 2.0, deck)
                z += hull_len + rng.uniform(1.0, 4.0)
    return s.mesh()


KINDS: dict[str, Callable[[int], trimesh.Trimesh]] = {
    "subway": subway, "archipelago": archipelago, "car_park": car_park,
    "forest": forest, "stadium": stadium, "harbour": harbour,
}
"""Kind name -> generator (seed -> Y-up mesh in metres)."""


def main(argv: list[str] | None = None) -> None:
    """Write the OBJ files ``argv`` asks for (the command line when None)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", type=Path, help="directory for the OBJ files")
    parser.add_argument("--kinds", nargs="+", default=list(KINDS), choices=list(KINDS))
    parser.add_argument("--seeds", nargs="+", type=int, default=[0, 1, 2])
    args = parser.parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    for kind in args.kinds:
        for seed in args.seeds:
            path = args.out / f"{kind}_s{seed}.obj"
            KINDS[kind](seed).export(path)
            print(path)


if __name__ == "__main__":
    main()
