"""Raised shapes near tile borders: the parts of their tops a solo build keeps and a tiled one drops, and the other way
round (docs/navmesh.md, "Islands at tile borders").

Run: ``.venv/bin/python benchmarks/border_island_shapes.py [--shapes 150] [--seed 0] [--tile-sizes 16 32]
[--erosion joined|recast]``. Each
shape (a ring, a U, a dumbbell or a cross, drawn with random bars 1.2-2.4 m wide and 2-5.5 m long, turned a random
angle) stands 1.5 m high on a floor 24 m a side, its centre within 1.5 m of a point where tile borders of 16 and 32
cells cross; ``tests/test_recast.py``'s agent (radius 0.3 m) and cells of 0.25 m. The connected parts of its top
(polygons joined by portals) are compared in plan, sampled every 0.125 m: a solo part is *lost* when the tiled build
covers under half of it, a tiled part is *extra* when the solo build covers under half of it. Prints one line per
shape and tile size where anything differs, then the totals. A benchmark: nothing here asserts a target.
"""

from __future__ import annotations

import argparse
import math
import sys
import types

import numpy as np
import trimesh
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

from g2s_plugins.recast import NavMesh, RecastParams, build_navmesh

AGENT = types.SimpleNamespace(radius=0.3, height=2.0, max_climb=0.4, max_slope=45.0)
HIGH, STEP = 1.5, 0.125
"""The shapes' height and the plan sampling step, m."""


def box(x0: float, x1: float, z0: float, z1: float) -> trimesh.Trimesh:
    """A box from the floor to HIGH over the plan rectangle [x0, x1] x [z0, z1]."""
    b = trimesh.creation.box(extents=(x1 - x0, HIGH, z1 - z0))
    b.apply_translation(((x0 + x1) / 2, HIGH / 2, (z0 + z1) / 2))
    return b


def shape(kind: str, rng: np.random.Generator) -> trimesh.Trimesh:
    """A raised shape of ``kind`` about the origin, unturned, from bars of random width and length."""
    w, a, b = rng.uniform(1.2, 2.4), rng.uniform(2.0, 5.5), rng.uniform(2.0, 5.5)
    if kind == "ring":
        parts = [box(-a / 2, a / 2, -b / 2, -b / 2 + w), box(-a / 2, a / 2, b / 2 - w, b / 2),
                 box(-a / 2, -a / 2 + w, -b / 2, b / 2), box(a / 2 - w, a / 2, -b / 2, b / 2)]
    elif kind == "u":
        parts = [box(-a / 2, a / 2, -b / 2, -b / 2 + w), box(-a / 2, -a / 2 + w, -b / 2, b / 2),
                 box(a / 2 - w, a / 2, -b / 2, b / 2)]
    elif kind == "dumbbell":
        head = rng.uniform(1.8, 2.8)
        parts = [box(-a / 2 - head, -a / 2, -head / 2, head / 2), box(a / 2, a / 2 + head, -head / 2, head / 2),
                 box(-a / 2, a / 2, -w / 2, w / 2)]
    else:  # cross
        parts = [box(-a / 2, a / 2, -w / 2, w / 2), box(-w / 2, w / 2, -b / 2, b / 2)]
    return trimesh.util.concatenate(parts)


def top_parts(nm: NavMesh) -> tuple[np.ndarray, np.ndarray]:
    """(the top polygons, each one's connected part among them): polygons over half the shapes' height."""
    top = np.flatnonzero(nm.centres[:, 1] > HIGH / 2)
    pairs = nm.portals().pairs
    on_top = np.isin(pairs, top).all(axis=1)
    n = nm.polygon_count
    graph = coo_matrix((np.ones(int(on_top.sum())), (pairs[on_top, 0], pairs[on_top, 1])), shape=(n, n))
    _, label = connected_components(graph, directed=False)
    return top, label[top]


def covered(nm: NavMesh, polys: np.ndarray, points: np.ndarray) -> np.ndarray:
    """(N,) whether each plan point (x, z) lies in one of ``polys`` (Recast's polygons are convex)."""
    inside = np.zeros(len(points), bool)
    for p in polys:
        corners = nm.vertices[nm.polygons[p][nm.polygons[p] >= 0]][:, [0, 2]]
        edges = np.roll(corners, -1, axis=0) - corners
        rel = points[:, None, :] - corners[None]
        cross = edges[None, :, 0] * rel[:, :, 1] - edges[None, :, 1] * rel[:, :, 0]
        inside |= (cross >= 0).all(axis=1) | (cross <= 0).all(axis=1)
    return inside


def compare(solo: NavMesh, tiled: NavMesh, points: np.ndarray) -> tuple[list[float], list[float]]:
    """(the solo parts' floors the tiled build loses, the tiled parts' floors the solo build lacks), m² of samples."""
    found = []
    for nm in (solo, tiled):
        top, part = top_parts(nm)
        found.append([covered(nm, top[part == q], points) for q in np.unique(part)])
    solo_all = np.any(found[0], axis=0) if found[0] else np.zeros(len(points), bool)
    tiled_all = np.any(found[1], axis=0) if found[1] else np.zeros(len(points), bool)
    cell = STEP * STEP
    lost = [m.sum() * cell for m in found[0] if m.any() and (tiled_all & m).sum() < m.sum() / 2]
    extra = [m.sum() * cell for m in found[1] if m.any() and (solo_all & m).sum() < m.sum() / 2]
    return lost, extra


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--shapes", type=int, default=150)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--tile-sizes", nargs="+", type=int, default=[16, 32])
    ap.add_argument("--erosion", default="joined", choices=["joined", "recast"])
    a = ap.parse_args(argv)
    rng = np.random.default_rng(a.seed)
    ground = trimesh.creation.box(extents=(24.0, 0.2, 24.0))
    ground.apply_translation((0.0, -0.1, 0.0))
    kinds = ["ring", "u", "dumbbell", "cross"]
    builds = lost_builds = extra_builds = dropped = 0
    lost_shapes: set[int] = set()
    for i in range(a.shapes):
        kind = kinds[i % len(kinds)]
        raised = shape(kind, rng)
        yaw = rng.uniform(0.0, 90.0)
        centre = (rng.choice([-4.0, 4.0]) + rng.uniform(-1.5, 1.5), rng.choice([-4.0, 4.0]) + rng.uniform(-1.5, 1.5))
        turn = trimesh.transformations.rotation_matrix(math.radians(yaw), (0.0, 1.0, 0.0))
        turn[[0, 2], 3] = centre
        raised.apply_transform(turn)
        level = trimesh.util.concatenate([ground, raised])
        (x0, _, z0), (x1, _, z1) = raised.bounds
        gx, gz = np.meshgrid(np.arange(x0, x1, STEP) + STEP / 2, np.arange(z0, z1, STEP) + STEP / 2)
        points = np.column_stack([gx.ravel(), gz.ravel()])
        solo = build_navmesh(level.vertices, level.faces, AGENT, RecastParams(cell_size=0.25, tile_size=0, erosion=a.erosion))
        for ts in a.tile_sizes:
            tiled = build_navmesh(level.vertices, level.faces, AGENT, RecastParams(cell_size=0.25, tile_size=ts, erosion=a.erosion))
            lost, extra = compare(solo, tiled, points)
            builds += 1
            dropped += tiled.config()["borderIslandPolygons"]
            lost_builds += bool(lost)
            extra_builds += bool(extra)
            if lost:
                lost_shapes.add(i)
            if lost or extra:
                print(f"shape {i:>3} {kind:<8} yaw={yaw:5.1f} centre=({centre[0]:6.2f}, {centre[1]:6.2f}) tile={ts:>2} "
                      f"lost={[round(float(f), 2) for f in lost]} extra={[round(float(f), 2) for f in extra]} "
                      f"dropped={tiled.config()['borderIslandPolygons']}", flush=True)
    print(f"shapes={a.shapes} tiled_builds={builds} lost_builds={lost_builds} lost_shapes={len(lost_shapes)} "
          f"extra_builds={extra_builds} polygons_dropped={dropped}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
