"""How many of a structure's edges pass a steep face closer than the agent could: a corner cut, a door too narrow.

Run: ``.venv/bin/python benchmarks/structure_clearance.py [--presets map_analysis_sampling map_analysis my.yaml]
[--levels nav_test dungeon_1k building_1k castle_1k terrain_1k office spaceship] [--seeds 0]
[--shares 0.5 0.9]``

For every level (the names of ``benchmarks/analysis_quality.py``'s ``--levels``: nav_test, the 1k families, the
kinds of ``benchmarks/level_kinds.py``) and preset (a name or a config file, e.g. one extending a preset with
``simplify: {params: {clearance: 0}}``) it runs the preset with the ``traffic`` evaluator and prints, for the
structure's edges (each node pair once; the loops' edges too):

* ``edges``: how many, and ``made``: how many are not edges of the initial graph (simplification drew them);
* ``near S``, for each share S of ``--shares``: the edges whose band ``S`` x clearance (the agent radius, the
  sampling builder's default) to either side, at half the agent's height over the segment between the two nodes,
  meets a face steeper than the agent's max slope (:func:`g2s_plugins._raycasting.bands_meet_walls`, the
  builder's own band test, exact): the edges the agent, as wide as the band, could not walk straight. 0.9 is the
  builder's band (``DISK_SHARE``), which its own edges pass;
* the traffic evaluator's structure share, rho, area within 6 m and share of the traffic passing more than 5 m
  from the structure (``off>5m``; docs/analysis_quality.md);
* the CPU seconds of the simplification step (``time.process_time`` between the pipeline's progress messages
  at its start and at the next stage's) and the load average when the row was printed: the machine is shared.

This is a benchmark: nothing here asserts a target. The figures are in docs/sampling.md ("Simplified edges as wide
as the agent").
"""

from __future__ import annotations

import argparse
import os
import platform
import time
from pathlib import Path

import networkx as nx
import numpy as np
from analysis_quality import levels

from g2s_core import pipeline
from g2s_core.config import find_config, load_raw_config, parse_config
from g2s_core.mesh import mesh_sha256
from g2s_core.registry import Registry
from g2s_core.stages import PIPELINE
from g2s_plugins._raycasting import UP, AgentShape, RayCaster, bands_meet_walls
from g2s_plugins.batch.runner import with_evaluators

SIMPLIFY_START = next(f"{stage.step}: {stage.label}" for stage in PIPELINE if stage.timing == "simplify")
STAGE_STARTS = {f"{stage.step}: {stage.label}" for stage in PIPELINE}


def edges_near_walls(caster: RayCaster, structure: nx.Graph, agent: AgentShape, half_width: float) -> np.ndarray:
    """(m,) bool per edge of ``structure`` (in ``structure.edges`` order): the band ``half_width`` (m) to either side
    of the segment between its nodes' ``pos``, lifted by half the agent height, meets a steep face."""
    ends = np.array([(structure.nodes[u]["pos"], structure.nodes[v]["pos"]) for u, v in structure.edges],
                    dtype=np.float64).reshape(-1, 2, 3)
    along = ends[:, 1] - ends[:, 0]
    horizontal = np.hypot(along[:, 0], along[:, 2])
    flat = horizontal > 1e-9  # a vertical edge has no side to widen towards
    side = np.zeros_like(along)
    side[flat, 0], side[flat, 2] = -along[flat, 2], along[flat, 0]
    side[flat] *= (half_width / horizontal[flat])[:, None]
    near = np.zeros(len(ends), dtype=bool)
    near[flat] = bands_meet_walls(caster, ends[flat, 0] + 0.5 * agent.height * UP, along[flat], side[flat],
                                  agent.max_slope_deg)
    return near


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--presets", nargs="+", default=["map_analysis_sampling", "map_analysis"])
    parser.add_argument("--levels", nargs="+", default=["nav_test", "dungeon_1k", "building_1k", "castle_1k",
                                                        "terrain_1k"])
    parser.add_argument("--seeds", nargs="+", type=int, default=[0])
    parser.add_argument("--shares", nargs="+", type=float, default=[0.5, 0.9],
                        help="band half-widths, as shares of the clearance (the agent radius)")
    args = parser.parse_args()
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f}")
    registry = Registry.from_entry_points()
    plans = {Path(p).stem: pipeline.plan(parse_config(with_evaluators(load_raw_config(find_config(p)), ["traffic"]), p),
                                         registry, p) for p in args.presets}
    near_columns = " ".join(f"{f'near {s:g}':>8}" for s in args.shares)
    print(f"{'level':<18} {'preset':<28} {'edges':>6} {'made':>6} {near_columns} {'struct':>7} {'rho':>6} "
          f"{'<=6m':>6} {'off>5m':>6} {'simplify cpu s':>14} {'load':>5}")
    for name, mesh in levels(args.levels, args.seeds):
        caster = RayCaster(mesh)
        for preset, plan in plans.items():
            marks: list[tuple[str, float]] = []

            def mark(message: object) -> None:
                if message in STAGE_STARTS:
                    marks.append((str(message), time.process_time()))

            result = pipeline.run(plan, registry, mesh, name, mesh_sha256(mesh), progress=mark)
            starts = [label for label, _ in marks]
            at = starts.index(SIMPLIFY_START)
            simplify_cpu = marks[at + 1][1] - marks[at][1]
            agent = AgentShape.from_config(result.context.agent)
            structure = nx.Graph(result.structure)
            made = sum(not result.graph.has_edge(u, v) for u, v in structure.edges)
            near = " ".join(f"{int(edges_near_walls(caster, structure, agent, s * agent.radius).sum()):>8}"
                            for s in args.shares)
            q = result.metrics["traffic"]
            print(f"{name:<18} {preset:<28} {structure.number_of_edges():>6} {made:>6} {near} "
                  f"{100 * q['structure_share']:6.1f}% {q['rho']:6.3f} {100 * q['area_within_6m']:5.1f}% "
                  f"{100 * q['traffic_off']:5.1f}% {simplify_cpu:14.2f} {os.getloadavg()[0]:5.1f}", flush=True)


if __name__ == "__main__":
    main()
