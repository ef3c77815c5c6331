"""Where a heat map's rank errors sit: the samples whose walking-flow percentile differs from the heat they are given.

Run: ``.venv/bin/python benchmarks/rank_errors.py [--preset map_analysis_sampling] [--levels platform_tower:0
diagonal_dungeon:0 dungeon_1k:0 ...] [--exact-up-to 8000]``

For every level (the names ``benchmarks/analysis_quality.py`` takes; ``name:seed`` for one seed) it runs the preset
in memory and reads two node sets against the exact walking flow (every source, split ties: the flow the heat map
ranks; above ``--exact-up-to`` nodes a 2,048-source linearly scaled sample stands for it, marked ``(p)``): the
looped forest (the Steiner tree with its loops, every node kept: the most the guarantee can restore) and the final
structure. Each node of the graph gets the mean percentile of the nodes its nearest node of the set stands for
(:func:`g2s_plugins.evaluation.placement_heat`, the ``rho_ceiling`` heat map). Printed per set: its share of the
nodes, Spearman rho, and the rank error's squares (percentile minus heat, summed) as a share of the percentiles'
own variance: a Pearson correlation of the percentiles with their cell means is sqrt(1 - that share), so it is what
caps rho. Then the same squares split by each node's *contrast*, the largest step in percentile to a neighbour along
the graph: a node beside a line of through traffic (a straight walk across a small platform between two joins on
one line, which no tied path spreads) steps by 50 points or more, and a structure node on the line stands for it.
Last, ``--greedy``: how many nodes the final structure would need added, 1 % of the graph at a time, those of
largest rank error first (no paths to them: a bound, not a rule), to reach rho 0.9.
This is a benchmark: nothing here asserts a target (docs/analysis_quality.md, "Spurs where the heat map ranks
worst").
"""

from __future__ import annotations

import argparse
import math
import os
import time
from collections.abc import Hashable, Iterable

import numpy as np
import scipy.sparse as sp
from guarantee_levers import level_items

from g2s_core import pipeline
from g2s_core.config import find_config, load_raw_config, parse_config
from g2s_core.mesh import mesh_sha256
from g2s_core.registry import Registry
from g2s_plugins import evaluation, traffic

CONTRAST_BINS = (0.0, 10.0, 20.0, 30.0, 50.0, 101.0)
"""Edges of the contrast bins, percentile points."""

PROXY_SOURCES = 2048
"""Sources of the reference on graphs over ``--exact-up-to`` nodes (linearly scaled, split ties, seed 2)."""


def contrast(arrays: traffic.SurfaceArrays, percentile: np.ndarray) -> np.ndarray:
    """(n,) each node's largest absolute percentile step to a neighbour along the graph (0 for a node alone)."""
    edges = sp.coo_array(arrays.adjacency)
    steps = np.abs(percentile[edges.row] - percentile[edges.col])
    largest = np.zeros(arrays.n)
    np.maximum.at(largest, edges.row, steps)
    np.maximum.at(largest, edges.col, steps)
    return largest


def read(graph, nodes: Iterable[Hashable], reference: np.ndarray, percentile: np.ndarray,
         steps: np.ndarray) -> tuple[float, float, list[tuple[float, float, float]]]:
    """Rho of ``nodes``' heat map, its squared rank errors over the percentiles' variance, and per contrast bin
    (share of the nodes, mean absolute error, share of the squares)."""
    heat = evaluation.placement_heat(graph, nodes, reference)
    ok = np.isfinite(heat)
    error = np.where(ok, percentile - heat, 0.0)
    squares = float(np.sum(error ** 2))
    variance = float(np.sum((percentile[ok] - percentile[ok].mean()) ** 2))
    bins = []
    for low, high in zip(CONTRAST_BINS, CONTRAST_BINS[1:]):
        inside = ok & (steps >= low) & (steps < high)
        bins.append((inside.sum() / ok.sum(), float(np.abs(error[inside]).mean()) if inside.any() else 0.0,
                     float(np.sum(error[inside] ** 2)) / squares if squares else 0.0))
    return evaluation.spearman(heat, reference), squares / variance, bins


def greedy(graph, nodes: Iterable[Hashable], reference: np.ndarray, percentile: np.ndarray, arrays) -> tuple[int, float]:
    """Nodes added to ``nodes`` (1 % of the graph a round, largest rank error first) until rho >= 0.9, and rho then."""
    kept, added = set(nodes), 0
    while True:
        heat = evaluation.placement_heat(graph, kept, reference)
        rho = evaluation.spearman(heat, reference)
        if rho >= 0.9:
            return added, rho
        error = np.where(np.isfinite(heat), np.abs(percentile - heat), -1.0)
        error[arrays.rows(sorted(kept))] = -1.0
        chosen = np.lexsort((np.arange(arrays.n), -error))[:math.ceil(0.01 * arrays.n)]
        chosen = chosen[error[chosen] > 0]
        if chosen.size == 0:
            return added, rho
        kept.update(arrays.nodes[row] for row in chosen.tolist())
        added += chosen.size


def main(argv: list[str] | None = None) -> None:
    """The table for ``argv`` (the command line when None)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--preset", default="map_analysis_sampling", help="a preset name or config file")
    parser.add_argument("--levels", nargs="+", default=["platform_tower:0", "diagonal_dungeon:0", "dungeon_1k:0"],
                        help="level names as benchmarks/analysis_quality.py takes them; name:seed for one seed")
    parser.add_argument("--seeds", nargs="+", type=int, default=[0], help="seeds of generated levels named without one")
    parser.add_argument("--exact-up-to", type=int, default=8000,
                        help="graphs with at most this many nodes get the exact reference, larger ones a proxy")
    parser.add_argument("--greedy", action="store_true", help="also the nodes the structure would need added")
    args = parser.parse_args(argv)
    registry = Registry.from_entry_points()
    plan = pipeline.plan(parse_config(load_raw_config(find_config(args.preset)), args.preset), registry, args.preset)
    print(f"load average {os.getloadavg()[0]:.1f}; preset {args.preset}; contrast bins (points) "
          + ", ".join(f"{low:g}-{high:g}" for low, high in zip(CONTRAST_BINS, CONTRAST_BINS[1:]))
          + "; per bin: share of the nodes / mean |error| / share of the squared errors")
    for name, mesh in level_items(args.levels, args.seeds):
        cpu = time.process_time()
        result = pipeline.run(plan, registry, mesh, name, mesh_sha256(mesh))
        cpu = time.process_time() - cpu
        graph = result.graph
        arrays = traffic.surface_arrays(graph)
        exact = arrays.n <= args.exact_up_to
        reference = traffic.arrays_walking_flow(arrays, None if exact else PROXY_SOURCES, seed=2, ties="split",
                                                scaling="linear")
        percentile = traffic.percentile(reference)
        steps = contrast(arrays, percentile)
        looped = result.looped if result.looped is not None else result.steiner
        for label, nodes in (("looped forest", looped), ("structure", result.structure)):
            rho, unexplained, bins = read(graph, nodes, reference, percentile, steps)
            print(f"{name:<20} {arrays.n:>6} {label:<14} {100 * len(nodes) / arrays.n:5.1f}%  rho {rho:.4f}"
                  f"{'' if exact else '(p)'}  squares/variance {unexplained:.3f}  cpu {cpu:.1f} s  "
                  + "  ".join(f"{100 * s:4.1f}/{e:4.1f}/{100 * q:4.1f}%" for s, e, q in bins), flush=True)
        if args.greedy:
            added, rho = greedy(graph, result.structure, reference, percentile, arrays)
            print(f"{name:<20} {arrays.n:>6} greedy: +{added} nodes ({100 * added / arrays.n:.1f} points) -> "
                  f"{100 * (len(result.structure) + added) / arrays.n:.1f}%, rho {rho:.4f}", flush=True)


if __name__ == "__main__":
    main()
