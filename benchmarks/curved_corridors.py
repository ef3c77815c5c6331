"""Ring and straight corridors between hedges drawn as chords: the narrowest width the navmesh keeps joined (issue 9).

The round-33 labyrinth (``benchmarks/level_kinds33.py``) lost its 1.75 m ring corridors on the navmesh route (34
areas) while a straight corridor of that width joined. This measures it on small hand-checkable cases: a *ring*
corridor between two hedges 0.4 m thick and 2.4 m high (as the labyrinth's), each drawn as chords of about ``c`` m
whose ends lie on circles ``width + 0.4`` m apart (``width`` between the hedges' faces at the chords' ends), the
centre line of the corridor ``radius`` m from the ring's centre; and a *straight* corridor of the same width and hedges,
20 m long, at ``angle`` degrees to the x axis. Ground under everything; the presets' agent (radius 0.5 m, height 2 m,
climb 0.4 m, slope 45 degrees).

Per case it builds the navmesh (``graph.params`` as in ``configs/map_analysis.yaml`` plus ``--cell-size`` and
``--erosion``) and counts
the corridor's *areas* (connected components of the polygons whose centres lie between the hedges, joined through
Detour's links) and its *gaps* (points every 0.25 m along the centre line with no corridor polygon within half the
width); a corridor *joins* with one area and no gap. ``clearance``: how near a corner of those polygons comes to a
hedge, m. ``--scan`` prints, per chord, radius (or angle), the narrowest
width of ``--widths`` from which on every wider one joins too.

Run: ``.venv/bin/python benchmarks/curved_corridors.py --scan [--cell-size 0.1667] [--chords 0.4 0.8 1.6]
[--radii 5 10 20 30] [--angles 0 20 45] [--erosion recast]``; ``--case ring 10 1.75 0.8`` prints one case's areas, gaps and polygons."""

from __future__ import annotations

import argparse
import math
import sys
import time
from types import SimpleNamespace

import numpy as np
import trimesh
from level_kinds import _Solids
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

from g2s_plugins.recast import NavMesh, RecastParams, build_navmesh

AGENT = SimpleNamespace(radius=0.5, height=2.0, max_climb=0.4, max_slope=45.0)
"""The presets' agent (configs/base.yaml)."""

THICK, HIGH = 0.4, 2.4
"""The labyrinth's hedges: 0.4 m thick, 2.4 m high."""

STRAIGHT_LENGTH = 20.0


def _strip(p: np.ndarray, q: np.ndarray) -> np.ndarray:
    """The plan (4, 2) of a hedge from plan point ``p`` (x, z) to ``q``, :data:`THICK` m thick about the line (as
    :func:`level_kinds._wall_line` draws its prisms)."""
    along = (q - p) / np.linalg.norm(q - p)
    side = np.array([-along[1], along[0]]) * THICK / 2
    return np.array([p - side, q - side, q + side, p + side])


def ring_plans(radius: float, width: float, chord: float) -> list[np.ndarray]:
    """The hedges of a ring corridor ``width`` m wide (between the hedges' faces at the chords' ends) round the
    circle of ``radius`` m: two closed hedges of chords of about ``chord`` m, each chord's plan (4, 2)."""
    plans = []
    for r in (radius - width / 2 - THICK / 2, radius + width / 2 + THICK / 2):
        pieces = max(8, round(2 * math.pi * r / chord))
        angles = np.linspace(0.0, 2 * math.pi, pieces + 1)
        plans += [_strip(r * np.array([math.cos(a), math.sin(a)]), r * np.array([math.cos(b), math.sin(b)]))
                  for a, b in zip(angles[:-1], angles[1:])]
    return plans


def straight_plans(angle: float, width: float) -> list[np.ndarray]:
    """The hedges of a straight corridor ``width`` m wide and :data:`STRAIGHT_LENGTH` m long along the x axis turned
    ``angle`` degrees, closed at both ends."""
    turn = math.radians(angle)
    along, across = np.array([math.cos(turn), math.sin(turn)]), np.array([-math.sin(turn), math.cos(turn)])
    half, side = STRAIGHT_LENGTH / 2, width / 2 + THICK / 2
    return [plan for k in (-1.0, 1.0) for plan in (
        _strip(-half * along + k * side * across, half * along + k * side * across),
        _strip(k * half * along - side * across, k * half * along + side * across))]


def level(plans: list[np.ndarray]) -> trimesh.Trimesh:
    """The hedges of ``plans``, :data:`HIGH` m high, on ground reaching 1 m past them."""
    s = _Solids()
    for plan in plans:
        s.prism(plan, 0.0, HIGH)
    edge = float(np.abs(np.concatenate(plans)).max()) + 1.0
    s.box(-edge, edge, -0.5, 0.0, -edge, edge)
    return s.mesh()


def ring(radius: float, width: float, chord: float) -> trimesh.Trimesh:
    """The level of :func:`ring_plans`."""
    return level(ring_plans(radius, width, chord))


def straight(angle: float, width: float) -> trimesh.Trimesh:
    """The level of :func:`straight_plans`."""
    return level(straight_plans(angle, width))


def clearance(points: np.ndarray, plans: list[np.ndarray]) -> np.ndarray:
    """(N,) the distance in plan from each of ``points`` ((N,2) x, z) to the nearest hedge of ``plans`` (0 inside
    one), m."""
    best = np.full(len(points), np.inf)
    for plan in plans:
        sides = []
        for a, b in zip(plan, np.roll(plan, -1, axis=0)):
            ab = b - a
            t = np.clip((points - a) @ ab / (ab @ ab), 0.0, 1.0)
            best = np.minimum(best, np.linalg.norm(points - (a + t[:, None] * ab), axis=1))
            sides.append(ab[0] * (points[:, 1] - a[1]) - ab[1] * (points[:, 0] - a[0]))
        sides = np.array(sides)
        best[(sides >= 0).all(axis=0) | (sides <= 0).all(axis=0)] = 0.0  # inside the (convex) hedge either way round
    return best


def corridor_areas(navmesh: NavMesh, inside: np.ndarray, line: np.ndarray, width: float) -> tuple[int, int]:
    """(areas, gaps): the connected components of the polygons ``inside`` ((P,) bool) and the points of the centre
    ``line`` ((K,3)) with none of those polygons within ``width / 2`` m."""
    n = navmesh.polygon_count
    pairs = navmesh.portals().pairs
    keep = inside[pairs[:, 0]] & inside[pairs[:, 1]]
    graph = coo_matrix((np.ones(int(keep.sum())), (pairs[keep, 0], pairs[keep, 1])), shape=(n, n))
    _, label = connected_components(graph, directed=False)
    areas = len(set(label[inside].tolist()))
    extents = (width / 2, 0.5, width / 2)
    gaps = 0
    for p in line:
        poly, near = navmesh.nearest_poly(p, extents)
        if poly < 0 or not inside[poly] or math.dist((near[0], near[2]), (p[0], p[2])) > width / 2:
            gaps += 1
    return areas, gaps


def measure(kind: str, size: float, width: float, chord: float, params: RecastParams) -> dict:
    """One case: ``kind`` ring (``size`` the radius, m) or straight (``size`` the angle, degrees)."""
    plans = ring_plans(size, width, chord) if kind == "ring" else straight_plans(size, width)
    mesh = level(plans)
    start = time.perf_counter()
    navmesh = build_navmesh(mesh.vertices, mesh.faces, AGENT, params)
    seconds = time.perf_counter() - start
    c = navmesh.centres
    if kind == "ring":
        r = np.hypot(c[:, 0], c[:, 2])
        inside = np.abs(r - size) < width / 2
        steps = max(8, round(2 * math.pi * size / 0.25))
        a = np.linspace(0.0, 2 * math.pi, steps, endpoint=False)
        line = np.stack([size * np.cos(a), np.zeros(steps), size * np.sin(a)], axis=1)
    else:
        turn = math.radians(size)
        along = np.array([math.cos(turn), math.sin(turn)])
        across = np.array([-math.sin(turn), math.cos(turn)])
        u, v = c[:, [0, 2]] @ along, c[:, [0, 2]] @ across
        inside = (np.abs(v) < width / 2) & (np.abs(u) < STRAIGHT_LENGTH / 2)
        # the centre line but the agent's radius and a cell at each closed end, where no floor is meant to reach
        t = np.arange(-STRAIGHT_LENGTH / 2 + 1.0, STRAIGHT_LENGTH / 2 - 1.0 + 1e-9, 0.25)
        line = np.stack([t * along[0], np.zeros(len(t)), t * along[1]], axis=1)
    areas, gaps = corridor_areas(navmesh, inside, line, width)
    corners = np.unique(navmesh.polygons[inside][navmesh.polygons[inside] >= 0])
    near = float(clearance(navmesh.vertices[corners][:, [0, 2]], plans).min()) if len(corners) else math.nan
    return {"areas": areas, "gaps": gaps, "polygons": int(inside.sum()), "clearance": near, "seconds": seconds,
            "joined": areas == 1 and gaps == 0}


def narrowest(kind: str, size: float, chord: float, widths: list[float], params: RecastParams) -> tuple[float | None, list[str]]:
    """The narrowest of ``widths`` from which on every wider one joins (None: the widest does not), and each
    width's ``areas/gaps``."""
    rows = [measure(kind, size, w, chord, params) for w in widths]
    joined = None
    for w, row in zip(reversed(widths), reversed(rows)):
        if not row["joined"]:
            break
        joined = w
    return joined, [f"{r['areas']}/{r['gaps']}" for r in rows]


def _number(text: str) -> float | None:
    try:
        number = float(text)
    except ValueError:
        return None
    return number if math.isfinite(number) else None


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--scan", action="store_true")
    ap.add_argument("--case", nargs=4, metavar=("KIND", "SIZE", "WIDTH", "CHORD"))
    ap.add_argument("--cell-size", type=float, default=None)
    ap.add_argument("--ledge-filter", default="drops", choices=["recast", "drops", "off"])
    ap.add_argument("--erosion", default="joined", choices=["joined", "recast"])
    ap.add_argument("--chords", type=float, nargs="+", default=[0.4, 0.8, 1.6])
    ap.add_argument("--radii", type=float, nargs="+", default=[5.0, 10.0, 20.0, 30.0])
    ap.add_argument("--angles", type=float, nargs="+", default=[0.0, 10.0, 20.0, 30.0, 45.0])
    ap.add_argument("--widths", type=float, nargs="+", default=[round(1.5 + 0.05 * k, 2) for k in range(21)])
    a = ap.parse_args(argv)
    params = RecastParams(ledge_filter=a.ledge_filter, cell_size=a.cell_size, erosion=a.erosion)
    if a.case:
        kind, size, width, chord = a.case[0], _number(a.case[1]), _number(a.case[2]), _number(a.case[3])
        if kind not in ("ring", "straight") or None in (size, width, chord) or width <= 0 or (
                kind == "ring" and (size <= 0 or chord <= 0)):
            print(f"--case: KIND must be ring or straight, WIDTH a positive number, a ring's SIZE (radius) and CHORD "
                  f"positive numbers, a straight corridor's SIZE its angle in degrees; got {' '.join(a.case)}",
                  file=sys.stderr)
            return 2
        print(measure(kind, size, width, chord, params))
        return 0
    if not a.scan:
        ap.print_usage(sys.stderr)
        return 2
    print("widths (areas/gaps each): " + " ".join(f"{w:g}" for w in a.widths))
    print("| case | chord m | narrowest joining width m | areas/gaps per width |")
    print("| --- | ---: | ---: | --- |")
    for chord in a.chords:
        for radius in a.radii:
            w, rows = narrowest("ring", radius, chord, a.widths, params)
            print(f"| ring r {radius:g} m | {chord:g} | {w if w is not None else '-'} | {' '.join(rows)} |", flush=True)
    for angle in a.angles:
        w, rows = narrowest("straight", angle, 0.0, a.widths, params)
        print(f"| straight {angle:g} deg | - | {w if w is not None else '-'} | {' '.join(rows)} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
