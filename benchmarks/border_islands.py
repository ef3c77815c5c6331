"""Which levels are built in tiles, and the small connected areas their navmesh keeps (docs/navmesh.md, "Islands at
tile borders").

Run: ``.venv/bin/python benchmarks/border_islands.py [--levels castle dungeon_20k dungeon_100k kinds] [--seeds 0]
[--yaws 0 45] [--preset map_analysis] [--tile-size 64]``. ``--levels`` takes what ``analysis_quality.py --levels``
takes, and ``kinds`` for every held-out kind (``analysis_quality.KINDS``). For every level, seed and yaw
(degrees, :func:`g2s_plugins.samples.pieces.yaw_about_centre`) it builds the preset's navmesh (``--tile-size``
overrides its ``tile_size``) and prints the tiling (tile side in cells, 0 solo; tiles; whether the automatic mode fell
back to tiles), the polygons, the connected areas (polygons joined by portals), how many of them are smaller than
``region_min_size``² cells (the size Recast removes from a solo build) and their floor (m²), and the wall time of the
build. A last line counts the tiled levels and the small areas. A benchmark: nothing here asserts a target.
"""

from __future__ import annotations

import argparse
import sys
import time

import numpy as np
from analysis_quality import KINDS, levels
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

from g2s_core.config import PRESETS_DIR, load_config
from g2s_plugins.recast import NavMesh, RecastParams, build_navmesh
from g2s_plugins.samples.pieces import yaw_about_centre


def area_floors(navmesh: NavMesh) -> np.ndarray:
    """(A,) the floor of each connected area (polygons joined by portals), m²."""
    n = navmesh.polygon_count
    pairs = navmesh.portals().pairs
    graph = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(n, n))
    _, label = connected_components(graph, directed=False)
    return np.bincount(label, weights=navmesh.areas)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--levels", nargs="+", default=["kinds", "dungeon_20k", "dungeon_100k"])
    ap.add_argument("--seeds", nargs="+", type=int, default=[0])
    ap.add_argument("--yaws", nargs="+", type=float, default=[0.0])
    ap.add_argument("--preset", default="map_analysis")
    ap.add_argument("--tile-size", type=int, default=None, help="override the preset's tile_size (cells; 0 solo)")
    a = ap.parse_args(argv)
    config = load_config(PRESETS_DIR / f"{a.preset}.yaml")
    params = RecastParams(**config.graph.params)
    if a.tile_size is not None:
        params = params.model_copy(update={"tile_size": a.tile_size})
    names = [n for name in a.levels for n in (KINDS if name == "kinds" else [name])]
    runs = tiled = small_total = 0
    for name, mesh in levels(names, a.seeds):
        for yaw in a.yaws:
            turned = mesh.copy().apply_transform(yaw_about_centre(mesh, yaw)) if yaw else mesh
            start = time.perf_counter()
            navmesh = build_navmesh(turned.vertices, turned.faces, config.agent, params)
            seconds = time.perf_counter() - start
            cfg = navmesh.config()
            floors = area_floors(navmesh)
            small = floors[floors < (params.region_min_size * cfg["cs"]) ** 2]
            runs += 1
            tiled += cfg["tileSize"] > 0
            small_total += len(small)
            print(f"{name:<28} yaw={yaw:>4g} tile={cfg['tileSize']:>3} tiles={cfg['tiles']:>4} "
                  f"auto_tiled={int(cfg['autoTiled'])} polygons={navmesh.polygon_count:>7} areas={len(floors):>3} "
                  f"small={len(small):>2} ({small.sum():.2f} m2) {seconds:6.2f}s", flush=True)
    print(f"runs={runs} tiled={tiled} small_areas={small_total}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
