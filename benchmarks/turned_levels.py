"""What a level loses on the navmesh route when it is turned about the vertical (issue 9).

Run: ``.venv/bin/python benchmarks/turned_levels.py [--levels castle building dungeon] [--yaws 0 15 30 45]
[--erosion joined recast] [--cell-size 0.16666667] [--ledge-filter drops recast off]``

For every sample level and seed (``--seeds``, 0), yaw (degrees, :func:`g2s_plugins.samples.pieces.yaw_about_centre`) and Recast
setting it builds the navmesh the ``map_analysis`` preset builds (its agent, ``ledge_filter: drops`` unless told)
and prints the total floor (m², the detail triangles' area), the connected areas (components of the polygons
joined by portals; "under 8² cells" those smaller than ``region_min_size``² cells, which Recast removes
from a solo build but keeps in a tile where they touch its border) and, for every area but the largest, its floor and its centre turned back into the level's
own frame, so areas of different yaws can be laid over each other; "outline" is the navmesh's edge with no polygon
across (m: along walls and drops) and "strip" the floor lost against the first yaw per metre of the first yaw's
outline (cm: the width of the strip the turn takes along the outline, were all of it taken there). ``--tile-size 0``
builds solo, ``--agent-radius 0`` without erosion (Recast keeps regions under ``region_min_size`` that touch a tile border). ``--where`` adds the floor the turned
level lacks against the unturned one, binned by the distance of the lost points to the nearest floor kept (a
strip along walls vs. a room gone). On the ``building`` sample it also lists the rooms (metadata) whose floor is
mostly outside the largest area, with the widths of their doors to the corridor (the door floors' extents in the
mesh), and which doors to the corridor are open (floor within 5 cm of the door's middle) and closed. This is a benchmark: nothing here asserts a target.
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from types import SimpleNamespace

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree

from g2s_plugins.recast import NavMesh, RecastParams, build_navmesh
from g2s_plugins.samples import levels as samples
from g2s_plugins.samples.pieces import yaw_about_centre

AGENT = SimpleNamespace(radius=0.5, height=2.0, max_climb=0.4, max_slope=45.0)
"""The presets' agent (configs/base.yaml)."""


def areas(navmesh: NavMesh) -> tuple[np.ndarray, np.ndarray]:
    """(label per polygon, floor per label in m²) of the polygons joined by portals."""
    n = navmesh.polygon_count
    pairs = navmesh.portals().pairs
    graph = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(n, n))
    _, label = connected_components(graph, directed=False)
    return label, np.bincount(label, weights=navmesh.areas)


def boundary_length(navmesh: NavMesh) -> float:
    """Metres of polygon edge with no polygon across: the navmesh's outline, along walls and drops."""
    polygons, neighbours = navmesh.polygons, navmesh.neighbours
    nxt = np.where(np.roll(polygons, -1, axis=1) >= 0, np.roll(polygons, -1, axis=1), polygons[:, :1])
    edge = (polygons >= 0) & (neighbours < 0)
    a, b = navmesh.vertices[polygons[edge]], navmesh.vertices[nxt[edge]]
    return float(np.linalg.norm((a - b)[:, [0, 2]], axis=1).sum())


def floor_points(navmesh: NavMesh, step: float = 0.1) -> np.ndarray:
    """(K,3) points on the detail triangles about ``step`` m apart (barycentric grid per triangle)."""
    tri = navmesh.detail_vertices[navmesh.detail_triangles]
    out = []
    for a, b, c in tri:
        n = max(1, math.ceil(max(np.linalg.norm(b - a), np.linalg.norm(c - a), np.linalg.norm(c - b)) / step))
        i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
        keep = i + j < n
        u, v = (i[keep] + 1 / 3) / n, (j[keep] + 1 / 3) / n
        out.append(a + u[:, None] * (b - a) + v[:, None] * (c - a))
    return np.concatenate(out)


def building_rooms_apart(level: samples.SampleLevel, nav: NavMesh, label: np.ndarray, main: int,
                         back: np.ndarray) -> list[str]:
    """The building sample's rooms whose floor lies mostly outside area ``main``: storey, centre x, side, door widths."""
    meta, mesh = level.metadata, level.mesh
    t, corridor = meta["wall_thickness"], meta["params"]["corridor_width"]
    tri = mesh.vertices[mesh.faces]
    up = mesh.face_normals[:, 1] > 0.99
    centres = (np.c_[nav.centres, np.ones(len(nav.centres))] @ back.T)[:, :3]
    out = []
    for r in meta["rooms"]:
        inside = ((centres[:, 0] > r["x0"]) & (centres[:, 0] < r["x1"]) & (centres[:, 2] > r["z0"])
                  & (centres[:, 2] < r["z1"]) & (np.abs(centres[:, 1] - r["y"]) < 0.8))
        if nav.areas[inside & (label == main)].sum() >= nav.areas[inside].sum() / 2:
            continue
        band = (corridor, corridor + t) if r["z0"] > 0 else (-t, 0.0)  # the wall between the room and the corridor
        door = (up & (np.abs(tri[:, :, 1] - r["y"]).max(1) < 1e-6) & (tri[:, :, 2].min(1) >= band[0] - 1e-6)
                & (tri[:, :, 2].max(1) <= band[1] + 1e-6) & (tri[:, :, 0].min(1) > r["x0"]) & (tri[:, :, 0].max(1) < r["x1"]))
        width = tri[door, :, 0].max() - tri[door, :, 0].min() if door.any() else math.nan
        out.append(f"storey y={r['y']:g} x={(r['x0'] + r['x1']) / 2:.1f} {'north' if r['z0'] > 0 else 'south'} "
                   f"door {width:.3f} m")
    return out


def building_corridor_doors(level: samples.SampleLevel, nav: NavMesh, turn: np.ndarray) -> tuple[list[float], list[float]]:
    """(widths of the open, of the closed) doors between the building sample's rooms and corridors: a door is open
    when the navmesh has floor within 5 cm of its middle, in the wall (``turn`` the level's (4, 4) transform)."""
    meta, mesh = level.metadata, level.mesh
    t, corridor = meta["wall_thickness"], meta["params"]["corridor_width"]
    tri = mesh.vertices[mesh.faces]
    up = mesh.face_normals[:, 1] > 0.99
    open_, closed = [], []
    for y in meta["floor_heights"]:
        for band in ((corridor, corridor + t), (-t, 0.0)):  # the corridor's north and south walls
            strip = (up & (np.abs(tri[:, :, 1] - y).max(1) < 1e-6) & (tri[:, :, 2].min(1) >= band[0] - 1e-6)
                     & (tri[:, :, 2].max(1) <= band[1] + 1e-6))
            for x0, x1 in sorted({(round(a, 4), round(b, 4)) for a, b in zip(tri[strip, :, 0].min(1), tri[strip, :, 0].max(1))}):
                middle = turn @ np.array([(x0 + x1) / 2, y, (band[0] + band[1]) / 2, 1.0])
                poly, near = nav.nearest_poly(middle[:3], (0.05, 0.5, 0.05))
                kept = poly >= 0 and math.dist((near[0], near[2]), (middle[0], middle[2])) < 0.05
                (open_ if kept else closed).append(x1 - x0)
    return open_, closed


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--levels", nargs="+", default=["castle", "building", "dungeon"])
    ap.add_argument("--seeds", nargs="+", type=int, default=[0])
    ap.add_argument("--yaws", nargs="+", type=float, default=[0.0, 15.0, 30.0, 45.0])
    ap.add_argument("--erosion", nargs="+", default=["joined"], choices=["joined", "recast"])
    ap.add_argument("--ledge-filter", nargs="+", default=["drops"], choices=["recast", "drops", "off"])
    ap.add_argument("--cell-size", nargs="+", type=float, default=[None])
    ap.add_argument("--agent-radius", type=float, default=None,
                    help="override the agent's radius (0: no erosion, the grid's rasterisation alone)")
    ap.add_argument("--tile-size", nargs="+", type=int, default=[None])
    ap.add_argument("--where", action="store_true", help="bin the floor lost against yaw 0 by its distance to floor kept")
    a = ap.parse_args(argv)
    unknown = [name for name in a.levels if name not in samples.SAMPLES]
    if unknown:
        print(f"--levels: unknown sample {unknown[0]!r}; expected one of {', '.join(samples.SAMPLES)}", file=sys.stderr)
        return 2
    for name, seed in [(n, s) for n in a.levels for s in a.seeds]:
        level = samples.load_sample(name, seed=seed)
        mesh = level.mesh
        for erosion in a.erosion:
            for ledge in a.ledge_filter:
                for cell, tile in [(c, t) for c in a.cell_size for t in a.tile_size]:
                    params = RecastParams(erosion=erosion, ledge_filter=ledge, cell_size=cell, tile_size=tile,
                                          agent_radius=a.agent_radius)
                    reference = None
                    for yaw in a.yaws:
                        turn = yaw_about_centre(mesh, yaw)
                        m = mesh.copy().apply_transform(turn) if yaw else mesh
                        start = time.perf_counter()
                        nav = build_navmesh(m.vertices, m.faces, AGENT, params)
                        seconds = time.perf_counter() - start
                        label, floor = areas(nav)
                        cell_side = cell if cell is not None else AGENT.radius / 2  # the rule of RecastParams
                        # what Recast removes from a solo build: areas under region_min_size² cells
                        small = int((floor < (params.region_min_size * cell_side) ** 2).sum())
                        back = np.linalg.inv(turn)
                        order = np.argsort(-floor)
                        parts = []
                        for k in order[1:]:
                            c = np.average(nav.centres[label == k], axis=0, weights=nav.areas[label == k])
                            c = (back @ np.append(c, 1.0))[:3]
                            parts.append(f"{floor[k]:.1f}m2@({c[0]:.1f},{c[1]:.1f},{c[2]:.1f})")
                        if yaw == a.yaws[0]:
                            first_floor, outline = nav.areas.sum(), boundary_length(nav)
                        strip = 100 * (first_floor - nav.areas.sum()) / outline  # cm of floor lost per metre of outline
                        print(f"{name:<9} s{seed} {erosion:<6} {ledge:<6} cell={cell or 'auto'!s:<10} tile={'auto' if tile is None else tile!s:<4} yaw={yaw:>4g} "
                              f"floor={nav.areas.sum():9.1f} outline={boundary_length(nav):7.0f} strip={strip:5.1f}cm "
                              f"areas={len(floor):3d} (under {params.region_min_size:g}² cells {small:2d}) largest={floor.max():9.1f} "
                              f"{seconds:5.2f}s  others: {' '.join(parts)}", flush=True)
                        if name == "building":
                            opened, shut = building_corridor_doors(level, nav, turn)
                            print(f"    doors to the corridor: {len(opened)} open (narrowest {min(opened):.3f} m), "
                                  f"{len(shut)} closed ({', '.join(f'{w:.3f}' for w in sorted(shut))} m)")
                            for room in building_rooms_apart(level, nav, label, int(order[0]), back):
                                print(f"    room apart: {room}")
                        if a.where:
                            pts = floor_points(nav)
                            pts = (np.c_[pts, np.ones(len(pts))] @ back.T)[:, :3]
                            if reference is None:  # the first yaw's floor is what the others are held against
                                reference, per = pts, nav.areas.sum() / len(pts)
                                continue
                            d, _ = cKDTree(pts).query(reference, distance_upper_bound=5.0)
                            bins = [0.15, 0.3, 0.6, 1.0, 2.0, 5.0, np.inf]
                            counts = np.histogram(np.minimum(d, 1e9), bins=bins)[0] * per
                            print(f"    lost vs yaw {a.yaws[0]:g}, by distance to the floor kept (m): "
                                  + " ".join(f"{lo:g}-{hi:g}:{c:.1f}m2" for lo, hi, c in zip(bins, bins[1:], counts)))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
