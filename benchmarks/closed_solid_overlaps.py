"""Samples inside closed boxes that overlap walls, floors, ceilings or each other (the sampling builder).

A closed box 3 x 2.9 x 2.2 m (a lift shaft, a crate, a pillar) on a 20 x 20 m floor slab, in seven settings: free,
touching a wall slab, overlapping one wall slab by 0.1 m, in a corner overlapping two, sunk 0.2 m into the floor, a
pillar through the floor and a ceiling slab, and a stack of two boxes overlapping each other; the whole level turned
by each yaw about the vertical through the origin. A sample is *inside* when, turned back, it lies within a box's
footprint below its top less half a metre. Every box here is taller than the agent and wider than twice the
clearance, so only the closed-solid rule (docs/sampling.md, "Samples inside closed solids") keeps samples out.

Usage: ``python benchmarks/closed_solid_overlaps.py [--preset map_analysis_sampling] [--yaws 0 22 45]``
(prints one row per case and yaw: samples, samples inside, candidates the rule dropped).
"""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

import numpy as np
import trimesh

sys.path[:0] = [str(Path(__file__).resolve().parent), str(Path(__file__).resolve().parent.parent)]

from piece_parts import box  # noqa: E402

from g2s_core.config import PRESETS_DIR, load_config  # noqa: E402
from g2s_plugins._raycasting import AgentShape  # noqa: E402
from g2s_plugins.graph_builders import sampling  # noqa: E402

WIDTH, DEPTH, HEIGHT = 3.0, 2.9, 2.2
"""Metres: the box's extent along x, along z, and its height over the floor."""

OVERLAP = 0.1
"""Metres a box reaches into a wall slab."""

WALL = 0.25
"""Metres: a wall slab's thickness (3.2 m high)."""

FLOOR = box(-10, 10, -0.3, 0.0, -10, 10)
CEILING = box(-10, 10, 3.2, 3.4, -10, 10)


def _wall_south(overlap: float) -> trimesh.Trimesh:
    """A wall slab along x whose north face lies ``overlap`` metres north of the box's south face (z = 0)."""
    return box(-10, 10, 0.0, 3.2, overlap - WALL, overlap)


def _wall_west(overlap: float) -> trimesh.Trimesh:
    return box(overlap - WALL, overlap, 0.0, 3.2, -10, 10)


def _one_box(bottom: float = 0.0, top: float = HEIGHT) -> trimesh.Trimesh:
    return box(0, WIDTH, bottom, top, 0, DEPTH)


CASES: dict[str, tuple[list[trimesh.Trimesh], list[tuple[float, float, float, float, float]]]] = {
    "free": ([FLOOR, _one_box()], [(0, WIDTH, 0, DEPTH, HEIGHT)]),
    "touching a wall": ([FLOOR, _one_box(), _wall_south(0.0)], [(0, WIDTH, 0, DEPTH, HEIGHT)]),
    "overlapping a wall": ([FLOOR, _one_box(), _wall_south(OVERLAP)], [(0, WIDTH, 0, DEPTH, HEIGHT)]),
    "overlapping a wall, ceiling": ([FLOOR, _one_box(), _wall_south(OVERLAP), CEILING], [(0, WIDTH, 0, DEPTH, HEIGHT)]),
    "corner, two walls": ([FLOOR, _one_box(), _wall_south(OVERLAP), _wall_west(OVERLAP)], [(0, WIDTH, 0, DEPTH, HEIGHT)]),
    "sunk in the floor": ([FLOOR, _one_box(bottom=-0.2)], [(0, WIDTH, 0, DEPTH, HEIGHT)]),
    "pillar, floor to ceiling": ([FLOOR, _one_box(bottom=-0.2, top=3.3), CEILING], [(0, WIDTH, 0, DEPTH, 3.2)]),
    "crate stack": (
        [FLOOR, _one_box(), box(2.0, 2.0 + WIDTH, 0.0, HEIGHT, 1.0, 1.0 + DEPTH)],
        [(0, WIDTH, 0, DEPTH, HEIGHT), (2.0, 2.0 + WIDTH, 1.0, 1.0 + DEPTH, HEIGHT)],
    ),
}
"""Case name -> (the level's parts, the boxes' footprints as (x0, x1, z0, z1, top) in metres before the yaw)."""


def _turned(yaw_deg: float) -> np.ndarray:
    """(4, 4) the rotation by ``yaw_deg`` about +Y."""
    return trimesh.transformations.rotation_matrix(math.radians(yaw_deg), [0.0, 1.0, 0.0])


def case_level(name: str, yaw_deg: float) -> trimesh.Trimesh:
    """The level of case ``name`` turned by ``yaw_deg`` degrees."""
    mesh = trimesh.util.concatenate([part.copy() for part in CASES[name][0]])
    mesh.apply_transform(_turned(yaw_deg))
    return mesh


def inside_count(name: str, yaw_deg: float, positions: np.ndarray) -> int:
    """Samples at ``positions`` ((n, 3) metres, the turned level's frame) inside a box of case ``name``."""
    back = trimesh.transform_points(np.asarray(positions, dtype=np.float64).reshape(-1, 3), _turned(-yaw_deg))
    inside = np.zeros(len(back), dtype=bool)
    for x0, x1, z0, z1, top in CASES[name][1]:
        inside |= (back[:, 0] > x0) & (back[:, 0] < x1) & (back[:, 2] > z0) & (back[:, 2] < z1) & (back[:, 1] < top - 0.5)
    return int(inside.sum())


def measure(name: str, yaw_deg: float, preset: str = "map_analysis_sampling") -> dict[str, int]:
    """``samples``, ``inside`` (:func:`inside_count`) and ``dropped`` (candidates_inside_solids) of one case."""
    config = load_config(PRESETS_DIR / f"{preset}.yaml")
    graph = sampling.build_sampled_graph(
        case_level(name, yaw_deg), sampling.Params(**(config.graph.params or {})), AgentShape.from_config(config.agent)
    )
    positions = np.array([graph.nodes[n]["pos"] for n in graph.nodes]).reshape(-1, 3)
    return {"samples": len(positions), "inside": inside_count(name, yaw_deg, positions),
            "dropped": int(graph.graph["sampling_stats"]["candidates_inside_solids"])}


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--preset", default="map_analysis_sampling")
    parser.add_argument("--yaws", type=float, nargs="+", default=[0.0, 22.0, 45.0])
    args = parser.parse_args(argv)
    print("| case | yaw | samples | inside | candidates dropped |")
    print("|---|---:|---:|---:|---:|")
    for name in CASES:
        for yaw in args.yaws:
            row = measure(name, yaw, args.preset)
            print(f"| {name} | {yaw:g} | {row['samples']} | {row['inside']} | {row['dropped']} |", flush=True)


if __name__ == "__main__":
    main()
