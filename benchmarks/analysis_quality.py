"""How well map-analysis presets show where people walk (issue 9's measures).

Run: ``.venv/bin/python benchmarks/analysis_quality.py [--presets map_analysis_paper map_analysis]
[--levels nav_test samples dungeon_1k dungeon_20k dungeon_100k] [--seeds 0 1 2]``

For every level and preset it prints the measures of
:mod:`g2s_plugins.evaluation`: share of the walkable area within 3 / 6 / 10 m
of the structure (along the initial graph), share of the reference traffic
(area-weighted origin-destination flow on the initial graph) passing more
than 5 m from it, Spearman rho of the heat map (first analyzer, each polygon
given the value of its nearest structure node), of area-weighted
betweenness on the structure and of the best values the structure's nodes
could carry (the ceiling: the mean traffic of the polygons each stands
for) against that traffic, the structure's size as
a share of the polygons, the run's CPU time (``time.process_time``: the
machine is shared) and the wall time of every stage. The reference flow is
computed once per level and graph builder (exact up to 512 nodes, 512
area-sampled sources above). This is a benchmark: nothing here asserts a target.
"""

from __future__ import annotations

import argparse
import os
import platform
import time
from collections.abc import Iterator
from pathlib import Path

import trimesh

from g2s_core import pipeline
from g2s_core.config import PRESETS_DIR, load_config
from g2s_core.mesh import load_mesh, mesh_sha256
from g2s_core.registry import Registry
from g2s_plugins import evaluation
from g2s_plugins.samples import levels as samples

NAV_TEST = Path(__file__).resolve().parents[1] / ".." / "shared" / "data" / "nav_test.obj"
DUNGEONS = {"dungeon_1k": 115, "dungeon_20k": 2400, "dungeon_100k": 12000}
"""Generated dungeons: name -> rooms (about 8.5 navmesh polygons per room)."""

SAMPLE_LEVELS = ("cross_hub", "t_hub", "two_floors", "closed_room", "room_with_window", "corridor_with_ramp")


def levels(names: list[str], seeds: list[int]) -> Iterator[tuple[str, trimesh.Trimesh]]:
    for name in names:
        if name == "nav_test":
            yield name, load_mesh(NAV_TEST)[0]
        elif name == "samples":
            for sample in SAMPLE_LEVELS:
                yield sample, samples.load_sample(sample).mesh
        elif name in DUNGEONS:
            for seed in seeds:
                yield f"{name}_s{seed}", samples.dungeon(seed=seed, rooms=DUNGEONS[name]).mesh
        else:
            yield name, samples.load_sample(name).mesh


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--presets", nargs="+", default=["map_analysis_paper", "map_analysis"])
    parser.add_argument("--levels", nargs="+", default=["nav_test", "samples", "dungeon_1k", "dungeon_20k"],
                        help="nav_test, samples, a sample name, dungeon_1k, dungeon_20k, dungeon_100k")
    parser.add_argument("--seeds", nargs="+", type=int, default=[0], help="seeds of the generated dungeons")
    args = parser.parse_args()
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f}")
    registry = Registry.from_entry_points()
    plans = {p: pipeline.plan(load_config(PRESETS_DIR / f"{p}.yaml"), registry, p) for p in args.presets}
    header = (f"{'level':<18} {'preset':<28} {'polys':>7} {'<=3m':>6} {'<=6m':>6} {'<=10m':>6} {'off>5m':>7} "
              f"{'rho':>6} {'rho_abw':>7} {'ceiling':>7} {'struct':>7} {'cpu s':>7} {'total s':>8}  stages (s)")
    print(header)
    for name, mesh in levels(args.levels, args.seeds):
        references: dict[str, tuple] = {}  # per graph builder and its parameters: the flow depends only on the graph
        for preset, plan in plans.items():
            cpu = time.process_time()
            result = pipeline.run(plan, registry, mesh, name, mesh_sha256(mesh))
            cpu = time.process_time() - cpu
            graph_stage = plan.stages["graph"][0]
            builder = f"{graph_stage.plugin.name} {graph_stage.params.model_dump_json()}"
            if builder not in references:
                start = time.process_time()
                references[builder] = (evaluation.reference_flow(result), time.process_time() - start)
            q = evaluation.evaluate(result, references[builder][0])
            stages = " ".join(f"{k}={v:.2f}" for k, v in q.stage_seconds.items())
            within = " ".join(f"{100 * q.area_within[r]:5.1f}%" for r in evaluation.RADII)
            print(f"{name:<18} {preset:<28} {q.polygons:>7} {within} {100 * q.traffic_off:6.1f}% "
                  f"{q.rho:6.3f} {q.rho_area_betweenness:7.3f} {q.rho_ceiling:7.3f} {100 * q.structure_share:6.1f}% "
                  f"{cpu:7.2f} {sum(q.stage_seconds.values()):8.2f}  {stages}", flush=True)
        for builder, (flow, seconds) in references.items():
            print(f"{'':<18} (reference flow on the {builder.split()[0]} graph of {len(flow)} nodes: {seconds:.2f} s CPU)")


if __name__ == "__main__":
    main()
