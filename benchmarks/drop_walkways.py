"""Walkways and stairs beside a drop: the narrowest width each route keeps joined (issue 9).

Round 35's silo stairs (``benchmarks/level_kinds35.py`` silo_stair: treads 1.1-1.4 m wide between a wall and an open
well) were lost on the navmesh route and kept on the sampling route. This measures the floor beside a drop on small
hand-checkable cases: two landings 4 m deep and 8 m wide, their tops 3 m over ground, joined by a walkway ``width``
m wide and :data:`LENGTH` m long of one of four kinds, the whole turned ``yaw`` degrees about the vertical and moved
by (s, 0.6 s) m on Recast's grid (``--shifts``):

- ``wall_drop``: a slab with a wall 0.4 m thick and 3 m over it along one side and a 3 m drop along the other (a
  balcony, a walkway round an open well);
- ``catwalk``: a slab with a 3 m drop along both sides;
- ``stair_well``: a flight of treads 0.3 m deep and 0.18 m high (0.25 m thick, open risers) rising from the first
  landing to the second, a wall along one side and the well (the ground, 3 m and more below) along the other, as the
  silo stair but straight;
- ``corridor``: a slab between two such walls, the reference: a corridor between two walls.

A case *joins* when a point 2 m into each landing lies on one connected area: on the navmesh route Detour's links
between polygons (``narrow_gaps.joined``), on the sampling route the graph's edges between the samples nearest the two
points. Per case on the navmesh route also ``kept``: the narrowest width of floor the polygons hold across the walkway
at a quarter, half and three quarters of its length, m; ``edge``: how near a polygon corner on the walkway or the
landings' ends comes to the drop beside the walkway, m (negative: floor over the drop; the landings' corners at the
walkway's ends count); ``along``: the same for the polygons' parts more than 1 m from the walkway's ends. The presets' agent is 0.5 m in radius on ``map_analysis`` and
0.4 m on ``map_piece`` (cells of 0.25 and 0.133 m); an agent passes a walkway from twice its radius.

Run: ``.venv/bin/python benchmarks/drop_walkways.py [--presets map_analysis map_piece map_analysis_sampling
map_piece_sampling] [--kinds wall_drop catwalk stair_well corridor] [--widths 0.8 0.9 ... 2.0] [--yaws 0 10 20 30 45]
[--shifts 0 0.07 0.13] [--erosion joined|recast] [--cases]``: per preset a table of (kind, width) -> the share of
(yaw, shift) cases that join, the narrowest kept width and nearest approach to a drop's edge; then per (kind, yaw) the
narrowest width from which every wider one joins at every shift. ``--cases`` prints each case as well. This is a
benchmark: nothing here asserts a target; the figures are in docs/navmesh.md ("Walkways beside a drop")."""

from __future__ import annotations

import argparse
import math
import sys
import time
from typing import Any

import numpy as np
import trimesh
from level_kinds import _Solids
from narrow_gaps import joined, preset_config
from scipy.sparse import csgraph, csr_array
from scipy.spatial import cKDTree

from g2s_core.model import RunContext
from g2s_plugins.graph_builders import sampling
from g2s_plugins.recast import NavMesh, RecastParams, build_navmesh

KINDS = ("wall_drop", "catwalk", "stair_well", "corridor")
LENGTH = 10.0
"""The walkway's length between the landings, m."""
TOP = 3.0
"""The first landing's and the walkway's top over the ground, m: the drop."""
LANDING = (4.0, 4.0)
"""The landings' depth along the walkway and half width across it, m."""
WALL = (0.4, 3.0)
"""A wall's thickness and its height over the walkway's top (or the flight's top), m."""
TREAD, RISER = 0.3, 0.18
"""The flight's treads: depth and rise, m (33 treads over :data:`LENGTH`, 5.94 m up)."""


def _frame(yaw: float, shift: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(origin, along, across): plan vectors (x, z) of the walkway's frame turned ``yaw`` degrees, moved (s, 0.6 s)."""
    turn = math.radians(yaw)
    return np.array([shift, 0.6 * shift]), np.array([math.cos(turn), math.sin(turn)]), np.array([-math.sin(turn), math.cos(turn)])


def rise(kind: str) -> float:
    """How far the second landing's top lies over the first's, m."""
    return round(LENGTH / TREAD) * RISER if kind == "stair_well" else 0.0


def level(kind: str, width: float, yaw: float, shift: float) -> trimesh.Trimesh:
    """The case's level: ground, two landings and the walkway of ``kind`` between them (u along, v across)."""
    origin, along, across = _frame(yaw, shift)

    def plan(u0: float, u1: float, v0: float, v1: float) -> np.ndarray:
        return np.array([origin + u * along + v * across for u, v in ((u0, v0), (u1, v0), (u1, v1), (u0, v1))])

    s = _Solids()
    half = LENGTH / 2
    deep, side = LANDING
    up = rise(kind)
    s.prism(plan(-half - deep, -half, -side, side), TOP - 0.3, TOP)
    s.prism(plan(half, half + deep, -side, side), TOP + up - 0.3, TOP + up)
    if kind == "stair_well":
        steps = round(LENGTH / TREAD)
        for i in range(steps):
            y = TOP + RISER * (i + 1)
            s.prism(plan(-half + i * LENGTH / steps, -half + (i + 1) * LENGTH / steps, -width / 2, width / 2), y - 0.25, y)
    else:
        s.prism(plan(-half, half, -width / 2, width / 2), TOP - 0.3, TOP)
    walls = {"wall_drop": [-1.0], "stair_well": [-1.0], "corridor": [-1.0, 1.0], "catwalk": []}[kind]
    for k in walls:
        v0 = k * width / 2
        s.prism(plan(-half, half, min(v0, v0 + k * WALL[0]), max(v0, v0 + k * WALL[0])), 0.0, TOP + up + WALL[1])
    reach = half + deep + 2.0 + abs(shift)
    s.box(-reach, reach, -0.5, 0.0, -reach, reach)
    return s.mesh()


def ends(kind: str, yaw: float, shift: float) -> tuple[np.ndarray, np.ndarray]:
    """The two points 2 m into the landings, (3,) each."""
    origin, along, _ = _frame(yaw, shift)
    u = LENGTH / 2 + 2.0
    a, b = origin - u * along, origin + u * along
    return np.array([a[0], TOP, a[1]]), np.array([b[0], TOP + rise(kind), b[1]])


def drop_sides(kind: str, width: float) -> list[float]:
    """The v of each drop's edge along the walkway."""
    return {"wall_drop": [width / 2], "stair_well": [width / 2], "catwalk": [-width / 2, width / 2], "corridor": []}[kind]


def kept_floor(navmesh: NavMesh, kind: str, width: float, yaw: float, shift: float) -> tuple[float, float, float]:
    """(kept, edge, along): the narrowest width the polygons over the walkway cover across it at a quarter, half and
    three quarters of its length; the nearest approach of a polygon corner on the floor's level within 1 m of the
    walkway's ends or between them to the drop beside the walkway (the landings' corners at its ends count); and that
    of the corners more than 1 m from the walkway's ends to the drop's edge (nan: no drop, or no such corner), m."""
    origin, along, across = _frame(yaw, shift)
    xz = navmesh.vertices[:, [0, 2]] - origin
    u, v, y = xz @ along, xz @ across, navmesh.vertices[:, 1]
    on = (y > TOP - 0.5) & (y < TOP + rise(kind) + 0.5)  # the walkway's and landings' floor, not the ground nor a wall top
    kept = math.inf
    for at in (-LENGTH / 4, 0.0, LENGTH / 4):
        pieces = []
        for poly in navmesh.polygons:
            idx = poly[poly >= 0]
            if not on[idx].all():
                continue
            pu, pv = u[idx], v[idx]
            if pu.min() > at or pu.max() < at:
                continue
            hits = []  # where the (convex) polygon's outline crosses u = at
            for a, b in zip(range(len(idx)), list(range(1, len(idx))) + [0]):
                if (pu[a] - at) * (pu[b] - at) <= 0 and pu[a] != pu[b]:
                    hits.append(pv[a] + (at - pu[a]) / (pu[b] - pu[a]) * (pv[b] - pv[a]))
            if hits:
                pieces.append((min(hits), max(hits)))
        pieces.sort()
        best, lo, hi = 0.0, None, None  # the widest run of overlapping pieces
        for p0, p1 in pieces:
            if lo is None or p0 > hi + 1e-4:
                lo, hi = p0, p1
            hi = max(hi, p1)
            best = max(best, hi - lo)
        kept = min(kept, best)
    near = on & (np.abs(u) < LENGTH / 2 + 1.0)  # the walkway's corners and the landings' next to it
    edge = along = math.nan
    if near.any():
        for e in drop_sides(kind, width):  # the drop beside the walkway: |u| <= LENGTH / 2, v past the edge
            du = np.maximum(np.abs(u[near]) - LENGTH / 2, 0.0)
            dv = abs(e) - np.sign(e) * v[near]  # negative: past the edge
            gap = np.where(dv > 0, np.hypot(du, dv), np.where(du > 0, du, dv))
            edge = float(np.nanmin([edge, gap.min()]))
        for poly in navmesh.polygons:  # each polygon's part more than 1 m from the walkway's ends
            idx = poly[poly >= 0]
            if not on[idx].all():
                continue
            middle = _clip_band(np.stack([u[idx], v[idx]], 1), LENGTH / 2 - 1.0)
            for e in drop_sides(kind, width):
                if len(middle):
                    along = float(np.nanmin([along, (abs(e) - np.sign(e) * middle[:, 1]).min()]))
    return kept, edge, along


def _clip_band(outline: np.ndarray, half: float) -> np.ndarray:
    """The corners of the convex ``outline`` ((k, 2) u, v) clipped to -half <= u <= half (none: no part there)."""
    for sign in (1.0, -1.0):
        out = []
        for p, q in zip(outline, np.roll(outline, -1, axis=0)):
            dp, dq = half - sign * p[0], half - sign * q[0]
            if dp >= 0:
                out.append(p)
            if dp * dq < 0:
                out.append(p + dp / (dp - dq) * (q - p))
        outline = np.array(out).reshape(-1, 2)
        if not len(outline):
            break
    return outline


def sampled_joined(graph: Any, a: np.ndarray, b: np.ndarray) -> bool:
    """Whether the samples nearest ``a`` and ``b`` (each within 1 m) are one connected part of the sampled graph."""
    nodes = sorted(graph.nodes)
    pos = np.array([graph.nodes[n]["pos"] for n in nodes])
    index = {n: i for i, n in enumerate(nodes)}
    dist, near = cKDTree(pos).query(np.stack([a, b]))
    if max(dist) > 1.0:
        return False
    edges = np.array([(index[p], index[q]) for p, q in graph.edges()]).reshape(-1, 2)
    matrix = csr_array((np.ones(len(edges)), (edges[:, 0], edges[:, 1])), shape=(len(nodes), len(nodes)))
    _, label = csgraph.connected_components(matrix, directed=False)
    return bool(label[near[0]] == label[near[1]])


def measure(preset: str, config: Any, kind: str, width: float, yaw: float, shift: float,
            erosion: str | None) -> dict:
    """One case on ``preset``'s route: joined, and on the navmesh route the kept width and the edge's clearance."""
    mesh = level(kind, width, yaw, shift)
    a, b = ends(kind, yaw, shift)
    if config.graph.plugin == "sampling":
        context = RunContext(mesh=mesh, agent=config.agent, centre=mesh.bounds.mean(axis=0))
        graph = sampling.g2s_build_graph(mesh=mesh, params=sampling.Params(**config.graph.params), context=context)
        return {"joined": sampled_joined(graph, a, b), "kept": math.nan, "edge": math.nan, "along": math.nan}
    params = RecastParams(**{**config.graph.params, **({"erosion": erosion} if erosion else {})})
    navmesh = build_navmesh(mesh.vertices, mesh.faces, config.agent, params)
    kept, edge, along = kept_floor(navmesh, kind, width, yaw, shift)
    return {"joined": bool(joined(navmesh, a, b)), "kept": float(kept), "edge": edge, "along": along}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--presets", nargs="+", default=["map_analysis", "map_piece"])
    ap.add_argument("--kinds", nargs="+", default=list(KINDS))
    ap.add_argument("--widths", type=float, nargs="+", default=[round(0.8 + 0.1 * k, 2) for k in range(13)])
    ap.add_argument("--yaws", type=float, nargs="+", default=[0.0, 10.0, 20.0, 30.0, 45.0])
    ap.add_argument("--shifts", type=float, nargs="+", default=[0.0, 0.07, 0.13])
    ap.add_argument("--erosion", choices=["joined", "recast"], default=None,
                    help="the navmesh presets' graph.params.erosion (default: the preset's)")
    ap.add_argument("--cases", action="store_true", help="print every case")
    a = ap.parse_args(argv)
    for kind in a.kinds:
        if kind not in KINDS:
            print(f"--kinds: {kind}: expected one of {', '.join(KINDS)}", file=sys.stderr)
            return 2
    if any(w <= 0 for w in a.widths):
        print("--widths: expected positive widths, m", file=sys.stderr)
        return 2
    for preset in a.presets:
        config = preset_config(preset)
        if config is None:
            return 2
        started = time.process_time()
        print(f"## {preset} (route {config.graph.plugin}, agent radius {config.agent.radius:g} m"
              f"{', erosion ' + a.erosion if a.erosion and config.graph.plugin != 'sampling' else ''})")
        print("| kind | width m | joined (of yaws x shifts) | kept width m, min-max | nearest to the drop m: all / "
              "along |")
        print("| --- | ---: | ---: | ---: | ---: |")
        table: dict[tuple[str, float, float], list[bool]] = {}
        for kind in a.kinds:
            for width in a.widths:
                rows = []
                for yaw in a.yaws:
                    for shift in a.shifts:
                        row = measure(preset, config, kind, width, yaw, shift, a.erosion)
                        rows.append(row)
                        table.setdefault((kind, yaw, width), []).append(row["joined"])
                        if a.cases:
                            print(f"  {kind} {width:g} yaw {yaw:g} shift {shift:g}: {row}", flush=True)
                share = sum(r["joined"] for r in rows)
                kept = [r["kept"] for r in rows if not math.isnan(r["kept"])]
                edge = [r["edge"] for r in rows if not math.isnan(r["edge"])]
                along = [r["along"] for r in rows if not math.isnan(r["along"])]
                kept_text = f"{min(kept):.2f}-{max(kept):.2f}" if kept else "-"
                edge_text = (f"{min(edge):.3f}" if edge else "-") + " / " + (f"{min(along):.3f}" if along else "-")
                print(f"| {kind} | {width:g} | {share}/{len(rows)} | {kept_text} | {edge_text} |", flush=True)
        print(f"\nnarrowest width from which every wider one joins at every shift ({preset}):")
        print("| kind | " + " | ".join(f"yaw {y:g}" for y in a.yaws) + " |")
        print("| --- |" + " ---: |" * len(a.yaws))
        for kind in a.kinds:
            cells = []
            for yaw in a.yaws:
                narrowest = None
                for width in sorted(a.widths, reverse=True):
                    if not all(table[(kind, yaw, width)]):
                        break
                    narrowest = width
                cells.append(f"{narrowest:g}" if narrowest is not None else "-")
            print(f"| {kind} | " + " | ".join(cells) + " |")
        print(f"({time.process_time() - started:.1f} s CPU)\n", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
