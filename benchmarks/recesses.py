"""Leaf terminals in shallow recesses: how deep each seeded leaf's dead end is, its area, its walking flow and its row.

Run: ``.venv/bin/python benchmarks/recesses.py [--levels stepwell dry_dock nav_test dungeon_1k my_level.obj]
[--seeds 0 1 2] [--depth 2] [--row 3] [--preset map_analysis]``

For every level (the names of ``benchmarks/analysis_quality.py``, or mesh
files) it runs ``--preset`` up to the terminals and reads the leaves it
seeds (its terminals less the waypoints) that are leaves of the graph. Per
leaf (:func:`g2s_plugins.terminals.coverage.dead_end_depths`): the depth of
its dead end (the leaf and the chain of degree-2 nodes behind it) beyond
its way in, metres; the dead end's area (m²); the walking-flow percentile
(the 256-source flow the ``coverage`` cover reads) of the leaf and of its
entrance, the node its dead end opens onto. It prints how many leaves lie
within 1 / 2 / 3 m of their way in, the median depth and area of those
within ``--depth`` (the recesses) and of the others, the median flow
percentiles, and how many recesses lie in rows of at least 2 and of at
least ``--row`` (entrances within the cover radius of one another along the
graph, chained: :func:`g2s_plugins.terminals.coverage.recess_row_labels`),
that is how many leaves ``recess_depth: --depth`` with ``recess_row:
--row`` would stop seeding. This is a benchmark: nothing here asserts a target.
"""

from __future__ import annotations

import argparse

import numpy as np
from analysis_quality import levels

from g2s_core import pipeline
from g2s_core.config import find_config, load_raw_config, parse_config
from g2s_core.registry import Registry
from g2s_plugins import traffic
from g2s_plugins.terminals import coverage


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--levels", nargs="+", default=["stepwell", "dry_dock", "nav_test", "dungeon_1k"])
    parser.add_argument("--seeds", nargs="+", type=int, default=[0])
    parser.add_argument("--depth", type=float, default=2.0, help="metres: a dead end within this of its way in is a recess")
    parser.add_argument("--row", type=int, default=3, help="the fewest recesses that are a row")
    parser.add_argument("--preset", default="map_analysis")
    args = parser.parse_args(argv)
    registry = Registry.from_entry_points()
    raw = load_raw_config(find_config(args.preset))
    raw["stop_after"] = "terminals"
    plan = pipeline.plan(parse_config(raw, args.preset), registry, args.preset)
    print(f"{'level':<18} {'seeded':>6} {'<=1m':>5} {'<=2m':>5} {'<=3m':>5}  {'recesses: depth, area':<22} "
          f"{'others: depth, area':<22} {'pct leaf':>8} {'pct entr':>8} {'rows>=2':>7} {'rows>=' + str(args.row):>7} {'dropped':>7}")
    for name, mesh in levels(args.levels, args.seeds):
        result = pipeline.run(plan, registry, mesh, name, "-")
        graph, navmesh = result.graph, result.context.navmesh
        arrays = traffic.surface_arrays(graph)
        degree = np.diff(arrays.adjacency.indptr)
        leaves = arrays.rows(sorted(result.terminals.without_waypoints))
        leaves = np.sort(leaves[degree[leaves] == 1])
        if navmesh is None or len(leaves) == 0:
            print(f"{name:<18} no navmesh or no leaves", flush=True)
            continue
        depths, entrances = coverage.dead_end_depths(graph, navmesh, arrays, leaves)
        area = np.array([arrays.area[coverage.dead_end_chain(arrays.adjacency, leaf)[0]].sum() for leaf in leaves.tolist()])
        rank = traffic.percentile(traffic.arrays_walking_flow(arrays, max_sources=traffic.WALKING_SOURCES,
                                                             ties=traffic.WALKING_TIES, scaling=traffic.WALKING_SCALING))
        shallow = depths <= args.depth
        radius = coverage.default_radius(result.context)
        labels = sizes = np.zeros(0, dtype=np.int64)  # no recess: no row
        if shallow.any():
            labels = coverage.recess_row_labels(arrays.adjacency, entrances[shallow], radius)
            sizes = np.bincount(labels)[labels]
        in_row = sizes >= args.row
        dropped = int(in_row.sum()) - len(np.unique(labels[in_row])) if in_row.any() else 0
        known = entrances >= 0
        print(f"{name:<18} {len(leaves):>6} {int((depths <= 1).sum()):>5} {int((depths <= 2).sum()):>5} "
              f"{int((depths <= 3).sum()):>5}  {_medians(depths[shallow], area[shallow]):<22} "
              f"{_medians(depths[~shallow], area[~shallow]):<22} {np.median(rank[leaves]):8.1f} "
              f"{np.median(rank[entrances[known]]) if known.any() else float('nan'):8.1f} "
              f"{int((sizes >= 2).sum()):>7} {int(in_row.sum()):>7} {dropped:>7}", flush=True)


def _medians(depths: np.ndarray, area: np.ndarray) -> str:
    """How many dead ends, and the median of their ``depths`` (k,), m, and ``area`` (k,), m²."""
    return f"{len(depths)}: {np.median(depths):.2f} m, {np.median(area):.1f} m²" if len(depths) else "0"


if __name__ == "__main__":
    main()
