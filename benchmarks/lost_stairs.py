"""Known answers for the disconnected-areas warning between floors a storey apart: is a stair there or not?

Each case is a yard (y = 0) beside a terrace 2.8-3.6 m high (drawn per seed), a wall 6 m high along the terrace's
back edge, and between yard and terrace, against the wall, one of:

- ``no_stair``: nothing: the floors are separate, the warning says so ("separate floors ... no walkable stairs");
- ``narrow_stair``: a straight stair 1.1-1.4 m wide (drawn per seed) between the wall and a drop to the yard, risers
  0.17-0.19 m on 0.28 m treads: walkable for the presets' agent (1 m wide), but the navmesh keeps no floor on a
  walkway that narrow between a wall and a drop (docs/analysis_quality.md, "A thirty-fifth round of level kinds"):
  the warning should name the stair, its width and where;
- ``cut_stair``: the same stair 2.5 m wide with one riser of 0.8 m halfway up: not a lost narrow stair, the
  warning should name the step;
- ``steep_ramp``: a ramp 2.5 m wide at 50-55 degrees (over the agent's 45): not walkable, the text unchanged;
- ``ladder``: rungs 0.6 m wide every 0.3 m up the terrace's face between two rails: not walkable (no head room
  over a rung), the text unchanged.

The whole level is turned by ``yaw`` degrees about the vertical and moved by a seed's offset. ``write OUT`` writes
``CASE_yYAW_sSEED.obj`` for each case, yaw (0, 30) and seed (0, 1); ``run OUT [--label L]`` runs
``g2s run PRESET FILE -q --format json`` on each with ``map_analysis`` and ``map_analysis_sampling`` and prints one
JSON line per run: the file, the preset, the exit code and the warnings' likely causes. O(cases x a pipeline run).
"""

from __future__ import annotations

import argparse
import json
import math
import subprocess
import sys
import tempfile
from collections.abc import Callable
from pathlib import Path

import numpy as np
import trimesh

TERRACE_X = 4.0
"""The terrace's face (x, metres, before the turn): the yard lies at x < 4, the terrace over x 4-14."""

WALL_Z = 8.0
"""The wall's face (z, metres): the terrace, yard and ways up lie at z < 8."""

TREAD = 0.28
"""Metres of each tread's run."""


def _box(x0: float, x1: float, y0: float, y1: float, z0: float, z1: float) -> trimesh.Trimesh:
    box = trimesh.creation.box(extents=[x1 - x0, y1 - y0, z1 - z0])
    box.apply_translation([(x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2])
    return box


def _flight(risers: list[float], width: float) -> list[trimesh.Trimesh]:
    """Treads 0.25 m thick cantilevered from the wall, ending at the terrace's face, each rising ``risers[i]`` over
    the last (no solid under them: a solid standing on the yard holds the yard's face inside it)."""
    heights = np.cumsum(risers)[:-1]  # the last riser climbs onto the terrace
    x = TERRACE_X - TREAD * len(heights)
    return [_box(x + TREAD * i, x + TREAD * (i + 1), float(h) - 0.25, float(h), WALL_Z - width, WALL_Z)
            for i, h in enumerate(heights)]


def level(case: str, yaw: float, seed: int) -> trimesh.Trimesh:
    """The level of ``case`` (module docs) turned ``yaw`` degrees, drawn by ``seed``."""
    rng = np.random.default_rng(seed)
    height = float(rng.uniform(2.8, 3.6))
    parts = [_box(-10.0, TERRACE_X, -0.3, 0.0, -8.0, WALL_Z), _box(TERRACE_X, 14.0, -0.3, height, -8.0, WALL_Z),
             _box(-10.0, 14.0, -0.3, 6.0, WALL_Z, WALL_Z + 0.3)]
    count = round(height / 0.18)
    if case == "narrow_stair":
        parts += _flight([height / count] * count, float(rng.uniform(1.1, 1.4)))
    elif case == "cut_stair":
        rest = (height - 0.8) / (count - 4)
        risers = [rest] * (count - 4)
        risers.insert(len(risers) // 2, 0.8)
        parts += _flight(risers, 2.5)
    elif case == "steep_ramp":
        run = height / math.tan(math.radians(float(rng.uniform(50.0, 55.0))))
        slab = 0.3 / math.cos(math.atan2(height, run))  # a slab 0.3 m thick: nothing stands on the yard
        corners = [[x, y + dy, z] for x, y in ((TERRACE_X - run, 0.0), (TERRACE_X, height)) for dy in (0.0, -slab)
                   for z in (WALL_Z - 2.5, WALL_Z)]
        parts.append(trimesh.convex.convex_hull(np.array(corners)))
    elif case == "ladder":
        z0 = WALL_Z - 1.5
        parts += [_box(TERRACE_X - 0.25, TERRACE_X - 0.2, y - 0.02, y + 0.02, z0, z0 + 0.6)
                  for y in np.arange(0.3, height, 0.3)]
        parts += [_box(TERRACE_X - 0.3, TERRACE_X - 0.2, 0.0, height + 1.0, z, z + 0.05) for z in (z0 - 0.05, z0 + 0.6)]
    elif case != "no_stair":
        raise ValueError(f"unknown case {case!r}")
    mesh = trimesh.util.concatenate(parts)
    turn = trimesh.transformations.rotation_matrix(math.radians(yaw), [0.0, 1.0, 0.0])
    turn[[0, 2], 3] = rng.uniform(-50.0, 50.0, 2)
    mesh.apply_transform(turn)
    return mesh


CASES: dict[str, Callable[[float, int], trimesh.Trimesh]] = {
    case: (lambda yaw, seed, case=case: level(case, yaw, seed))
    for case in ("no_stair", "narrow_stair", "cut_stair", "steep_ramp", "ladder")
}
"""Case name -> level (yaw degrees, seed)."""

PRESETS = ("map_analysis", "map_analysis_sampling")


def write(out: Path, yaws: list[float], seeds: list[int]) -> list[Path]:
    """Each case's level for each yaw and seed as ``out/CASE_yYAW_sSEED.obj``."""
    out.mkdir(parents=True, exist_ok=True)
    paths = []
    for case, make in CASES.items():
        for yaw in yaws:
            for seed in seeds:
                paths.append(out / f"{case}_y{yaw:g}_s{seed}.obj")
                make(yaw, seed).export(paths[-1])
    return paths


def run(out: Path, label: str) -> None:
    """One JSON line per OBJ file of ``out`` and preset: the likely causes of its warnings."""
    g2s = Path(sys.executable).with_name("g2s")
    for path in sorted(out.glob("*.obj")):
        for preset in PRESETS:
            with tempfile.TemporaryDirectory() as results:
                done = subprocess.run([str(g2s), "run", preset, str(path), "-o", results, "-q", "--format", "json"],
                                      capture_output=True, text=True, check=False)
                warnings = json.loads(Path(results, "structure.json").read_text())["warnings"] if done.returncode == 0 else []
            causes = [w.split("Likely cause: ", 1)[1] for w in warnings if "Likely cause: " in w]
            print(json.dumps({"label": label, "file": path.name, "preset": preset, "rc": done.returncode,
                              "cause": causes}), flush=True)


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("step", choices=["write", "run"])
    parser.add_argument("out", type=Path, help="folder of the OBJ files")
    parser.add_argument("--label", default="", help="run: a label for each line (a commit)")
    parser.add_argument("--yaws", nargs="+", type=float, default=[0.0, 30.0])
    parser.add_argument("--seeds", nargs="+", type=int, default=[0, 1])
    args = parser.parse_args(argv)
    if args.step == "write":
        for path in write(args.out, args.yaws, args.seeds):
            print(path)
    else:
        run(args.out, args.label)


if __name__ == "__main__":
    main()
