"""Levels per minute of `g2s batch`: serial vs the local process pool vs a Dask LocalCluster.

    .venv/bin/python benchmarks/batch.py [--levels 200] [--rooms 120] [--workers 2] [--format json]
        [--executors serial,local,dask] [--evaluate traffic]

Each level is ``sample:dungeon?seed=S&rooms=R`` (generated inside its pair, as
a batch of sample specs does; 120 rooms give about 1,000 navmesh polygons),
run with configs/map_analysis.yaml. Every executor writes into a fresh
temporary folder. Speed-up and efficiency (speed-up / workers) are against the
serial run; the load average before and after each run says whether other
jobs shared the machine. Figures go to docs/performance.md.
"""

from __future__ import annotations

import argparse
import os
import sys
import tempfile
import time
from pathlib import Path

from g2s_plugins.batch.runner import run_batch

PROJECT = Path(__file__).resolve().parents[1]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--levels", type=int, default=200)
    parser.add_argument("--rooms", type=int, default=120)
    parser.add_argument("--workers", type=int, default=os.cpu_count())
    parser.add_argument("--format", default="json")
    parser.add_argument("--executors", default="serial,local,dask")
    parser.add_argument("--evaluate", default="", help="evaluators added to the config (g2s batch --evaluate)")
    args = parser.parse_args()
    config = PROJECT / "configs" / "map_analysis.yaml"
    levels = [f"sample:dungeon?seed={seed}&rooms={args.rooms}" for seed in range(args.levels)]
    print(f"{args.levels} dungeons of {args.rooms} rooms, {args.workers} workers, {os.cpu_count()} CPUs, "
          f"formats {args.format}, evaluators: {args.evaluate or 'none'}")
    print("| executor | seconds | levels/min | speed-up | efficiency | failed | polygons (mean) | load before -> after |")
    print("| --- | ---: | ---: | ---: | ---: | ---: | ---: | --- |")
    serial_seconds = None
    for executor in args.executors.split(","):
        with tempfile.TemporaryDirectory() as folder:
            load_before = os.getloadavg()[0]
            start = time.perf_counter()
            summary = run_batch([config], levels, Path(folder) / "out", executor,
                                workers=None if executor == "serial" else args.workers, formats=args.format,
                                evaluators=[name for name in args.evaluate.split(",") if name])
            seconds = time.perf_counter() - start
            load_after = os.getloadavg()[0]
        if executor == "serial":
            serial_seconds = seconds
        speedup = serial_seconds / seconds if serial_seconds else float("nan")
        workers = 1 if executor == "serial" else args.workers
        print(f"| {executor} | {seconds:.1f} | {60 * len(summary) / seconds:.0f} | {speedup:.2f}x | "
              f"{100 * speedup / workers:.0f} % | {int((summary['status'] != 'ok').sum())} | "
              f"{summary['nodes_graph'].mean():.0f} | {load_before:.2f} -> {load_after:.2f} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
