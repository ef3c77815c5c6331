"""Where two versions of the navmesh code differ on a level: the floor one has and the other has not, and how near
it comes to the level's walls.

Run: ``.venv/bin/python benchmarks/navmesh_diff.py dump OUT.npz --levels car_park canyon [--seeds 0] [--preset
map_analysis]`` with each version's code (its own ``.venv``), then ``... compare BEFORE.npz AFTER.npz [--rise 1]``. ``--levels``
takes what ``analysis_quality.py --levels`` takes. ``compare`` prints per level: polygons and walkable area before
and after, the polygons of each whose centre no polygon of the other covers (in plan, within ``--rise`` m, default 1, of its corners' heights),
their area and the box round them (x, z), and *clearance*: the least distance from their corners, lifted 0.5 m, to
a wall (a face of the level steeper than the agent's slope), against the same for every polygon of the version
(the agent's radius less at most half a cell's diagonal where the polygons follow the cells). A benchmark: nothing
here asserts a target.
"""

from __future__ import annotations

import argparse
import math
import sys

import numpy as np
import trimesh
from analysis_quality import levels

from g2s_core.config import PRESETS_DIR, load_config
from g2s_plugins.recast import RecastParams, build_navmesh

LIFT = 0.5
"""How far over a polygon's corner the wall distance is read, m (walls are faces steeper than the agent's slope,
so under the agent's height; the corner itself lies on the floor a wall stands on)."""


def dump(out: str, names: list[str], seeds: list[int], preset: str) -> None:
    """Write each level's navmesh (vertices, polygons, centres, areas) and its walls' triangles to ``out``."""
    config = load_config(PRESETS_DIR / f"{preset}.yaml")
    params = RecastParams(**config.graph.params)
    arrays: dict[str, np.ndarray] = {}
    for name, mesh in levels(names, seeds):
        navmesh = build_navmesh(mesh.vertices, mesh.faces, config.agent, params)
        steep = mesh.face_normals[:, 1] < math.cos(math.radians(config.agent.max_slope))
        arrays |= {f"{name}/vertices": np.asarray(navmesh.vertices), f"{name}/polygons": np.asarray(navmesh.polygons),
                   f"{name}/centres": np.asarray(navmesh.centres), f"{name}/areas": np.asarray(navmesh.areas),
                   f"{name}/walls": np.asarray(mesh.vertices)[mesh.faces[steep]]}
    np.savez_compressed(out, **arrays)


def covered(points: np.ndarray, vertices: np.ndarray, polygons: np.ndarray, rise: float) -> np.ndarray:
    """(N,) whether each of ``points`` lies in plan in one of the convex ``polygons``, within ``rise`` m of its
    corners' heights."""
    inside = np.zeros(len(points), dtype=bool)
    for polygon in polygons:
        ring = vertices[polygon[polygon >= 0]]
        lo, hi = ring.min(axis=0), ring.max(axis=0)
        near = ~inside & np.all((points[:, [0, 2]] >= lo[[0, 2]] - 1e-6) & (points[:, [0, 2]] <= hi[[0, 2]] + 1e-6), axis=1)
        near &= (points[:, 1] > lo[1] - rise) & (points[:, 1] < hi[1] + rise)  # a sloped polygon's span metres
        if not near.any():
            continue
        p = points[near][:, [0, 2]]
        a, b = ring[:, [0, 2]], np.roll(ring[:, [0, 2]], -1, axis=0)
        cross = (b[:, 0] - a[:, 0])[None] * (p[:, 1:2] - a[:, 1][None]) - (b[:, 1] - a[:, 1])[None] * (p[:, 0:1] - a[:, 0][None])
        inside[np.nonzero(near)[0][(cross >= -1e-9).all(axis=1) | (cross <= 1e-9).all(axis=1)]] = True
    return inside


def clearance(corners: np.ndarray, walls: np.ndarray) -> float:
    """The least distance from ``corners`` lifted :data:`LIFT` m to the wall triangles ``walls`` (T,3,3), m."""
    if not len(corners) or not len(walls):
        return math.nan
    mesh = trimesh.Trimesh(walls.reshape(-1, 3), np.arange(len(walls) * 3).reshape(-1, 3), process=False)
    _, distance, _ = trimesh.proximity.closest_point(mesh, corners + [0.0, LIFT, 0.0])
    return float(distance.min())


def compare(before: str, after: str, rise: float) -> None:
    """Print the table of ``compare`` (module docs) for the levels in both files."""
    b, a = np.load(before), np.load(after)
    names = sorted({k.split("/")[0] for k in b.files} & {k.split("/")[0] for k in a.files})
    print("level: polygons before -> after, area m² before -> after; only before: polygons, m², box; only after: "
          "polygons, m², box, clearance of those / of all after m")
    for name in names:
        one, two = ({k: f[f"{name}/{k}"] for k in ("vertices", "polygons", "centres", "areas", "walls")} for f in (b, a))
        lost = ~covered(one["centres"], two["vertices"], two["polygons"], rise)
        new = ~covered(two["centres"], one["vertices"], one["polygons"], rise)

        def box(n: dict, keep: np.ndarray) -> str:
            if not keep.any():
                return "-"
            c = n["centres"][keep]
            return f"x {c[:, 0].min():.1f}..{c[:, 0].max():.1f} z {c[:, 2].min():.1f}..{c[:, 2].max():.1f}"

        corners = two["vertices"][np.unique(two["polygons"][new][two["polygons"][new] >= 0])]
        every = two["vertices"][np.unique(two["polygons"][two["polygons"] >= 0])]
        print(f"{name}: {len(one['areas'])} -> {len(two['areas'])}, {one['areas'].sum():.2f} -> {two['areas'].sum():.2f}; "
              f"only before {int(lost.sum())}, {one['areas'][lost].sum():.2f}, {box(one, lost)}; "
              f"only after {int(new.sum())}, {two['areas'][new].sum():.2f}, {box(two, new)}, "
              f"{clearance(corners, two['walls']):.3f} / {clearance(every, two['walls']):.3f}", flush=True)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = ap.add_subparsers(dest="command", required=True)
    d = sub.add_parser("dump")
    d.add_argument("out")
    d.add_argument("--levels", nargs="+", required=True)
    d.add_argument("--seeds", nargs="+", type=int, default=[0])
    d.add_argument("--preset", default="map_analysis")
    c = sub.add_parser("compare")
    c.add_argument("before")
    c.add_argument("after")
    c.add_argument("--rise", type=float, default=1.0,
                   help="m: how far a centre may lie over or under a polygon's corners (a hill's top inside a polygon "
                        "of a terrain rises more: give its height there)")
    args = ap.parse_args(argv)
    if args.command == "dump":
        if not (PRESETS_DIR / f"{args.preset}.yaml").is_file():
            print(f"--preset: {args.preset}: no such preset", file=sys.stderr)
            return 2
        dump(args.out, args.levels, args.seeds, args.preset)
    else:
        compare(args.before, args.after, args.rise)
    return 0


if __name__ == "__main__":
    sys.exit(main())
