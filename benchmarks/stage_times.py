"""CPU and wall time of every stage of a preset on a generated dungeon (issue 9's speed target).

Run: ``.venv/bin/python benchmarks/stage_times.py [--rooms 12000] [--preset map_analysis|my.yaml] [--repeat 1]
[--stage-peaks]``

``samples.dungeon(seed=0, rooms=N)`` (12,000 rooms: 100,781 navmesh
polygons) runs through the preset in this process. For each stage it prints
the wall time and the CPU time of the whole process (all threads: the
navmesh build runs its tiles on every core), read at the pipeline's progress
callback, which fires as each stage starts, and the graph's size (the initial
graph's nodes and edges, with the sampling builder's rays, and the structure's),
so that a change in time is told from a change in the work. With ``--stage-peaks`` (Linux) it
also prints each stage's peak RSS: the kernel's high-water mark read and
reset (``/proc/self/clear_refs``) as each stage starts, so that a change in
the run's peak is traced to the stage that makes it. On a machine shared with other
jobs the wall times grow with the load average (printed before and after);
the CPU times much less, so compare those. This is a benchmark: nothing here
asserts a time.
"""

from __future__ import annotations

import argparse
import math
import os
import platform
import resource
import time

from g2s_core import pipeline
from g2s_core.config import find_config, load_config
from g2s_core.mesh import mesh_sha256
from g2s_core.model import RunResult
from g2s_core.registry import Registry
from g2s_core.stages import PIPELINE
from g2s_plugins.samples import levels as samples

STAGE_STARTS = {f"{stage.step}: {stage.label}" for stage in PIPELINE}
"""What the progress callback hears as each stage starts; a warning the run tells it too (the coverage selector's
about small areas, on this level) is no stage and splits none."""


def peak_rss_since_reset() -> float:
    """GiB: this process's peak RSS since the last :func:`reset_peak_rss` (the kernel's ``VmHWM``), then reset."""
    with open("/proc/self/status") as status:
        peak = next(int(line.split()[1]) for line in status if line.startswith("VmHWM:")) / 2**20
    reset_peak_rss()
    return peak


def reset_peak_rss() -> None:
    """Start this process's peak RSS afresh from its current RSS (Linux: ``/proc/self/clear_refs``, "5")."""
    with open("/proc/self/clear_refs", "w") as clear:
        clear.write("5")


def graph_counts(result: RunResult) -> str:
    """The run's work in counts: the initial graph's nodes and edges (and the sampling builder's rays) and the
    structure's nodes and edges."""
    graph, structure = result.graph, result.structure
    rays = graph.graph.get("sampling_stats", {}).get("rays") if graph is not None else None
    return (f"initial graph {graph.number_of_nodes() if graph is not None else 0} nodes, "
            f"{graph.number_of_edges() if graph is not None else 0} edges"
            + (f" ({rays} rays)" if rays is not None else "")
            + f"; structure {structure.number_of_nodes() if structure is not None else 0} nodes, "
            f"{structure.number_of_edges() if structure is not None else 0} edges")


def stage_times(plan: pipeline.Plan, registry: Registry, rooms: int,
                peaks: bool = False) -> tuple[list[tuple[str, float, float, float]], int, str]:
    """One run: (label, wall s, CPU s, peak RSS GiB or nan without ``peaks``) per stage, the number of navmesh
    polygons, and :func:`graph_counts`."""
    mesh = samples.dungeon(seed=0, rooms=rooms).mesh
    marks: list[tuple[str, float, float]] = []
    stage_peaks: list[float] = []

    def mark(message: str) -> None:
        if message in STAGE_STARTS or message == "end":
            marks.append((message, time.perf_counter(), time.process_time()))
            if peaks:  # the stage before this mark's peak (the first mark's: the dungeon's build, dropped)
                stage_peaks.append(peak_rss_since_reset())

    result = pipeline.run(plan, registry, mesh, f"dungeon_{rooms}", mesh_sha256(mesh), progress=mark)
    mark("end")
    stage_peaks = stage_peaks[1:] if peaks else [math.nan] * (len(marks) - 1)
    stages = [(label, w1 - w0, c1 - c0, peak)
              for (label, w0, c0), (_, w1, c1), peak in zip(marks, marks[1:], stage_peaks)]
    polygons = result.context.navmesh.polygon_count if result.context.navmesh is not None else 0
    return stages, polygons, graph_counts(result)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rooms", type=int, default=12000)
    parser.add_argument("--preset", default="map_analysis", help="a preset name or a config file (e.g. one extending a preset)")
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--stage-peaks", action="store_true", help="print each stage's peak RSS too (Linux)")
    args = parser.parse_args()
    registry = Registry.from_entry_points()
    plan = pipeline.plan(load_config(find_config(args.preset)), registry, args.preset)
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}; "
          f"preset {args.preset}, dungeon of {args.rooms} rooms")
    peaks: list[float] = []
    for run in range(args.repeat):
        load = os.getloadavg()[0]
        stages, polygons, counts = stage_times(plan, registry, args.rooms, args.stage_peaks)
        print(f"run {run + 1}: {polygons} polygons, load average {load:.1f} -> {os.getloadavg()[0]:.1f}")
        print(f"  {counts}")
        for label, wall, cpu, stage_peak in stages:
            memory = f"   peak RSS {stage_peak:5.2f} GiB" if args.stage_peaks else ""
            print(f"  {label:<40} wall {wall:7.2f} s   CPU {cpu:7.2f} s{memory}")
        print(f"  {'total':<40} wall {sum(s[1] for s in stages):7.2f} s   CPU {sum(s[2] for s in stages):7.2f} s")
        peaks.extend(stage[3] for stage in stages)
    # the kernel's reset high-water mark lowers getrusage's figure too: with --stage-peaks the stages' largest
    peak = max(peaks) if args.stage_peaks else resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 2**20
    print(f"peak memory (max RSS, this process): {peak:.2f} GiB")


if __name__ == "__main__":
    main()
