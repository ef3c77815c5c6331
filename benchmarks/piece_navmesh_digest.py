"""The navmesh of every map-piece kind of ``piece_kinds10.py`` ... ``piece_kinds37.py``, of every generated piece
(:data:`g2s_plugins.samples.pieces.PIECES`, "gen") and of the shared pieces (``piece_quality.py``'s, "shared"),
turned 0, 22 and 45 degrees: polygons, walkable area and a digest of its polygons, to tell a navmesh change that
moves no opening from none.

Run: ``.venv/bin/python benchmarks/piece_navmesh_digest.py [--rounds 28 29 30 31 32] [--yaws 0 22 45]
[--config map_piece] [--no-pieces]``. One row per kind and yaw: round (gen, shared), kind, yaw, polygons, area m², sha256[:12] of the
polygons' vertices (rounded to 1 mm) and vertex indices. Run it on two versions of the code and compare the rows:
the same digest, the same navmesh (so the same openings); another, read the openings of ``piece_kindsNN.py
--detail`` on both. A benchmark: nothing here asserts a target.
"""

from __future__ import annotations

import argparse
import hashlib
import importlib
import sys
from typing import Any

import numpy as np
import trimesh

from piece_quality import SHARED_PIECES

from g2s_core.config import PRESETS_DIR, load_config
from g2s_core.mesh import load_mesh
from g2s_plugins.recast import NavMesh, RecastParams, build_navmesh
from g2s_plugins.samples import pieces

FIRST_ROUND, LAST_ROUND = 10, 37


def digest(navmesh: NavMesh) -> str:
    """sha256[:12] of the navmesh's vertices (1 mm) and polygons' vertex indices."""
    h = hashlib.sha256()
    h.update(np.round(np.asarray(navmesh.vertices, dtype=np.float64) * 1000).astype(np.int64).tobytes())
    h.update(np.asarray(navmesh.polygons, dtype=np.int64).tobytes())
    return h.hexdigest()[:12]


def row(group: str, name: str, yaw: float, mesh: trimesh.Trimesh, agent: Any, params: RecastParams) -> None:
    """Build ``mesh``'s navmesh and print its row (Recast's error, such as no walkable surface, in its place)."""
    try:
        navmesh = build_navmesh(mesh.vertices, mesh.faces, agent, params)
    except RuntimeError as error:
        print(f"{group:>6} {name:32s} {yaw:4g} error: {str(error)[:60]}", flush=True)
        return
    print(f"{group:>6} {name:32s} {yaw:4g} {navmesh.polygon_count:6d} {float(navmesh.areas.sum()):10.3f} "
          f"{digest(navmesh)}", flush=True)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rounds", type=int, nargs="+", default=list(range(FIRST_ROUND, LAST_ROUND + 1)))
    ap.add_argument("--yaws", type=float, nargs="+", default=[0.0, 22.0, 45.0])
    ap.add_argument("--config", default="map_piece")
    ap.add_argument("--no-pieces", action="store_true", help="the rounds' kinds alone, not the generated and shared")
    a = ap.parse_args(argv)
    bad = [r for r in a.rounds if not FIRST_ROUND <= r <= LAST_ROUND]
    if bad:
        print(f"--rounds: expected rounds {FIRST_ROUND}-{LAST_ROUND}, got {bad}", file=sys.stderr)
        return 2
    config = load_config(PRESETS_DIR / f"{a.config}.yaml")
    params = RecastParams(**config.graph.params)
    groups = [(str(r), importlib.import_module(f"piece_kinds{r}").KINDS) for r in a.rounds]
    if not a.no_pieces:
        groups.append(("gen", pieces.PIECES))
    for group, kinds in groups:
        for name, factory in kinds.items():
            for yaw in a.yaws:
                mesh = (pieces.turned(factory(), yaw) if yaw else factory()).mesh
                row(group, name, yaw, mesh, config.agent, params)
    if not a.no_pieces:
        for path in sorted(SHARED_PIECES.glob("*.obj")):
            mesh = load_mesh(path)[0]
            for yaw in a.yaws:
                turned = mesh.copy().apply_transform(pieces.yaw_about_centre(mesh, yaw)) if yaw else mesh
                row("shared", path.stem, yaw, turned, config.agent, params)
    return 0


if __name__ == "__main__":
    sys.exit(main())
