"""Time and quality of the chokepoints and regions analyzers on generated dungeons.

Run: ``.venv/bin/python benchmarks/regions.py [--rooms 120 2400 12000] [--obstacles 0.3] [--seeds 1]
[--yaws 0 5 10 15 20 30 45 60 90] [--params '{"min_region_area": 4}'] [--set graph.params.cell_size=0.1]``,
or ``--levels FILE ...`` for mesh files (real levels: no known
answer, so the sizes, counts and times only; docs/plugins.md, real levels).

For each dungeon (``samples.dungeon(seed, rooms, obstacles)``) the
``level_regions`` preset runs once, then, on its navmesh and structure, the
split (:func:`g2s_plugins.decomposition.decompose`) and the scoring
(:func:`~g2s_plugins.decomposition.score`) are timed: wall and CPU seconds,
the best of up to 5 calls (CPU time is the figure to trust on a shared
machine; the load average is printed). It prints the sizes, the times, and how
well the result matches the generated level: the share of corridors with a
chokepoint in them and the share of rooms with a region of their own
(:func:`g2s_plugins.samples.rooms.dungeon_shares`). With ``--yaws`` each
dungeon is also turned about the vertical line through the centre of its
bounds (:func:`g2s_plugins.samples.pieces.turned`) and its layout with it, so
the shares show whether the split depends on how the level is turned. This is
a benchmark, not a test: nothing here asserts a time.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import time
from collections.abc import Callable
from typing import Any

import networkx as nx

import g2s_core
from g2s_core import pipeline
from g2s_core.config import PRESETS_DIR, RunConfig, parse_assignment, resolve_config
from g2s_core.errors import ConfigError
from g2s_core.model import RunResult
from g2s_core.registry import Registry
from g2s_plugins import decomposition
from g2s_plugins.analyzers.chokepoints import Params
from g2s_plugins.samples.levels import dungeon
from g2s_plugins.samples.pieces import turned, yaw_about_centre
from g2s_plugins.samples.rooms import dungeon_shares


def best_times(function: Callable[[], Any]) -> tuple[float, float, Any]:
    """(best wall seconds, best CPU seconds, value) of up to 5 calls, repeated while under 2 s in all."""
    walls, cpus, value = [], [], None
    while len(walls) < 5 and sum(walls) < 2.0:
        wall, cpu = time.perf_counter(), time.process_time()
        value = function()
        walls.append(time.perf_counter() - wall)
        cpus.append(time.process_time() - cpu)
    return min(walls), min(cpus), value


def timed_split(result: RunResult, params: Params | None = None) -> tuple[decomposition.Decomposition,
                                                                         list[dict[str, Any]], dict[str, float]]:
    """The split (with ``params``, the defaults when None) and the chokepoints of a run's navmesh and structure,
    with the times of both (:func:`best_times`): ``split_wall``, ``split_cpu``, ``score_wall``, ``score_cpu``, ms."""
    navmesh, structure = result.context.navmesh, result.structure.to_undirected(as_view=True)
    params = params or Params()
    split_wall, split_cpu, split = best_times(lambda: decomposition.decompose(navmesh, result.context.agent, params, result.context.mesh))
    score_wall, score_cpu, (chokepoints, _) = best_times(lambda: decomposition.score(split, structure))
    return split, chokepoints, {"split_wall": 1000 * split_wall, "split_cpu": 1000 * split_cpu,
                                "score_wall": 1000 * score_wall, "score_cpu": 1000 * score_cpu}


def measure(rooms: int, seed: int, obstacles: float, yaw: float, registry: Registry,
            params: Params | None = None, config: RunConfig | None = None) -> dict[str, float]:
    """One dungeon through ``config`` (the ``level_regions`` preset when None), then its split timed and matched."""
    level = dungeon(seed=seed, rooms=rooms, obstacles=obstacles)
    turn = yaw_about_centre(level.mesh, yaw)
    plan = pipeline.plan(config or resolve_config(PRESETS_DIR / "level_regions.yaml")[0], registry)
    result = pipeline.run(plan, registry, turned(level, yaw).mesh, level.name, "-")
    navmesh = result.context.navmesh
    split, chokepoints, times = timed_split(result, params)
    doors, own = dungeon_shares(level, chokepoints, split.regions, navmesh, turn)
    return {
        "yaw": yaw, "seed": seed, "rooms": rooms, "corridors": len(level.metadata["corridors"]), "polygons": navmesh.polygon_count,
        "portals": len(navmesh.portals().pairs), "structure": result.structure.number_of_nodes(),
        "regions": len(split.regions), "chokepoints": len(chokepoints), **times, "doors": doors, "own": own,
    }


def measure_file(path: str) -> dict[str, Any]:
    """The ``level_regions`` preset on a mesh file, then the split and the scoring timed as in :func:`measure`."""
    result = g2s_core.run(path, "level_regions")
    split, chokepoints, times = timed_split(result)
    return {
        "level": os.path.basename(path), "polygons": result.context.navmesh.polygon_count,
        "areas": nx.number_connected_components(result.graph), "regions": len(split.regions),
        "chokepoints": len(chokepoints), "articulations": sum(k["articulation"] for k in chokepoints), **times,
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rooms", type=int, nargs="+", default=[120, 2400, 12000])
    parser.add_argument("--obstacles", type=float, default=0.3)
    parser.add_argument("--seeds", type=int, default=1, help="dungeons per size (seeds 0 .. n-1)")
    parser.add_argument("--yaws", type=float, nargs="+", default=[0.0],
                        help="turn each dungeon by these angles about the vertical, degrees")
    parser.add_argument("--levels", nargs="+", default=[], metavar="FILE",
                        help="measure these mesh files instead of generated dungeons")
    parser.add_argument("--params", type=json.loads, default={}, metavar="JSON",
                        help="split settings other than the defaults, e.g. '{\"min_region_area\": 4}'")
    parser.add_argument("--set", nargs="+", default=[], metavar="KEY=VALUE", dest="overrides",
                        help="preset settings other than level_regions', e.g. graph.params.cell_size=0.1")
    args = parser.parse_args()
    params = Params(**args.params)
    try:
        overrides = dict(parse_assignment(text) for text in args.overrides)
        config = resolve_config(PRESETS_DIR / "level_regions.yaml", overrides)[0]
    except ConfigError as exc:
        parser.exit(2, f"{exc}\n")
    registry = Registry.from_entry_points()
    print(f"# {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}, "
          f"obstacles {args.obstacles}, params {args.params or 'defaults'}, preset settings {overrides or 'as given'}, "
          f"load average {os.getloadavg()[0]:.1f}")
    if args.levels:
        print("| level | polygons | walkable areas | regions | chokepoints | articulations | split CPU (wall) ms "
              "| score CPU (wall) ms |")
        print("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |")
        for path in args.levels:
            m = measure_file(path)
            print(f"| {m['level']} | {m['polygons']:,} | {m['areas']} | {m['regions']} | {m['chokepoints']} "
                  f"| {m['articulations']} | {m['split_cpu']:.0f} ({m['split_wall']:.0f}) "
                  f"| {m['score_cpu']:.0f} ({m['score_wall']:.0f}) |", flush=True)
        return
    print("| yaw | seed | rooms | corridors | polygons | portals | regions | chokepoints | split CPU (wall) ms "
          "| score CPU (wall) ms | corridors with a chokepoint | rooms with their own region |")
    print("| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |")
    for rooms in args.rooms:
        for seed in range(args.seeds):
            for yaw in args.yaws:
                m = measure(rooms, seed, args.obstacles, yaw, registry, params, config)
                print(f"| {m['yaw']:g} | {m['seed']} | {m['rooms']:,} | {m['corridors']:,} | {m['polygons']:,} "
                      f"| {m['portals']:,} | {m['regions']:,} | {m['chokepoints']:,} "
                      f"| {m['split_cpu']:.0f} ({m['split_wall']:.0f}) | {m['score_cpu']:.0f} ({m['score_wall']:.0f}) "
                      f"| {m['doors']:.1%} | {m['own']:.1%} |", flush=True)


if __name__ == "__main__":
    main()
