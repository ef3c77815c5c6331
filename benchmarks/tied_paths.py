"""How much a walking flow depends on how it treats equally short paths: ``ties: first`` against ``split``.

Run: ``.venv/bin/python benchmarks/tied_paths.py [--presets map_analysis map_analysis_sampling my.yaml]
[--levels nav_test dungeon_1k building_1k ...] [--seeds 0 1 2] [--sources 256]``

For every level and preset it builds the run's initial graph (the preset's
graph stage only) and prints:

* ``nodes``, ``edges a node``;
* ``tie edges``: the share of the edges that lie on a shortest path from a
  source (``distance(v) + length = distance(w)`` within
  :data:`g2s_plugins.traffic.TIE_TOLERANCE`, relative) and reach a node that
  has another such edge (so the node's shortest paths split), over the
  sources of the sample; and the share of all edges whose relative excess
  ``(distance(v) + length - distance(w)) / distance(w)`` lies in ``(0,
  1e-13]``, ``(1e-13, 1e-6]`` and ``(1e-6, 1e-3]``: ties of rounding, what
  the tolerance adds beyond them, and what a larger one would (exactly 0,
  the edges of each search's own tree among them, in the first column);
* ``changed``: the share of nodes whose walking flow of ``--sources``
  sources (seed 0; exact when the graph has no more nodes with an area)
  differs between ``first`` and ``split`` by more than 1e-9 of the largest
  flow, and the Spearman rho of the two flows (unweighted, over every node);
* ``rho 2 samples``: for each of ``first`` and ``split``, the Spearman rho of
  the flows of two source samples (seeds 0 and 1): how noisy the heat map's
  flow is;
* CPU seconds of each flow (``time.process_time``: both threads).

The graph is the navmesh builder's or the sampling builder's, with the
preset's parameters. This is a benchmark: nothing here asserts anything.
"""

from __future__ import annotations

import argparse
import os
import platform
import time
from pathlib import Path

import numpy as np
from analysis_quality import levels
from scipy.sparse import csgraph

from g2s_core import pipeline
from g2s_core.config import find_config, load_raw_config, parse_config
from g2s_core.mesh import mesh_sha256
from g2s_core.registry import Registry
from g2s_plugins import evaluation, traffic

BINS = (0.0, 1e-13, 1e-6, 1e-3)
"""Edges of the relative-excess bins: exactly 0, then (BINS[i], BINS[i + 1]]."""


def excess_counts(arrays: traffic.SurfaceArrays, sources: np.ndarray) -> tuple[np.ndarray, float]:
    """Over ``sources``: the count of edges per bin of relative excess (:data:`BINS`, plus one for exactly 0, then
    one per bin) and the share of edges on shortest paths whose end has more than one such edge."""
    adjacency = arrays.adjacency
    rows = np.repeat(np.arange(arrays.n), np.diff(adjacency.indptr))
    counts, split, on_paths = np.zeros(len(BINS)), 0, 0
    for source in sources.tolist():
        distance = csgraph.dijkstra(adjacency, directed=True, indices=source)
        start, end = distance[rows], distance[adjacency.indices]
        with np.errstate(invalid="ignore", divide="ignore"):
            excess = (start + adjacency.data - end) / end
        reached = np.isfinite(start) & np.isfinite(end) & (end > 0)
        counts[0] += np.count_nonzero(reached & (excess == 0))
        for i in range(1, len(BINS)):
            counts[i] += np.count_nonzero(reached & (excess > BINS[i - 1]) & (excess <= BINS[i]))
        shortest = reached & (excess <= traffic.TIE_TOLERANCE)
        ways = np.bincount(adjacency.indices[shortest], minlength=arrays.n)
        on_paths += np.count_nonzero(shortest)
        split += np.count_nonzero(shortest & (ways[adjacency.indices] > 1))
    return counts / (len(sources) * adjacency.nnz), split / max(on_paths, 1)


def timed_flow(arrays: traffic.SurfaceArrays, sources: int, seed: int, ties: traffic.Ties) -> tuple[np.ndarray, float]:
    start = time.process_time()
    flow, _ = traffic.od_flow(arrays.adjacency, traffic.origin_weight(arrays), sources, seed, ties)
    return flow, time.process_time() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--presets", nargs="+", default=["map_analysis", "map_analysis_sampling"])
    parser.add_argument("--levels", nargs="+", default=["nav_test", "dungeon_1k"])
    parser.add_argument("--seeds", nargs="+", type=int, default=[0])
    parser.add_argument("--sources", type=int, default=traffic.WALKING_SOURCES)
    args = parser.parse_args()
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f}")
    registry = Registry.from_entry_points()
    plans = {}
    for preset in args.presets:
        raw = load_raw_config(find_config(preset))
        raw["stop_after"] = "graph"
        plans[Path(preset).stem] = pipeline.plan(parse_config(raw, preset), registry, preset)
    print(f"{'level':<16} {'preset':<30} {'nodes':>7} {'edges/n':>7} {'split edges':>11} {'=0':>7} {'<=1e-13':>8} "
          f"{'<=1e-6':>7} {'<=1e-3':>7} {'changed':>8} {'rho f/s':>8} {'2 samples f':>11} {'2 samples s':>11} "
          f"{'CPU f':>6} {'CPU s':>6}")
    for name, mesh in levels(args.levels, args.seeds):
        for preset, plan in plans.items():
            result = pipeline.run(plan, registry, mesh, name, mesh_sha256(mesh))
            arrays = traffic.surface_arrays(result.graph)
            rng = np.random.default_rng(0)
            bins, split = excess_counts(arrays, rng.choice(arrays.n, min(32, arrays.n), replace=False))
            first, cpu_first = timed_flow(arrays, args.sources, 0, "first")
            split_flow, cpu_split = timed_flow(arrays, args.sources, 0, "split")
            changed = np.abs(first - split_flow) > 1e-9 * max(first.max(), split_flow.max())
            again = {ties: timed_flow(arrays, args.sources, 1, ties)[0] for ties in ("first", "split")}
            print(f"{name:<16} {preset:<30} {arrays.n:>7} {arrays.adjacency.nnz / arrays.n:>7.2f} {split:>10.1%} "
                  + " ".join(f"{share:>7.2%}" for share in bins)
                  + f" {changed.mean():>8.1%} {evaluation.spearman(first, split_flow):>8.4f}"
                  f" {evaluation.spearman(first, again['first']):>11.4f} {evaluation.spearman(split_flow, again['split']):>11.4f}"
                  f" {cpu_first:>6.2f} {cpu_split:>6.2f}", flush=True)


if __name__ == "__main__":
    main()
