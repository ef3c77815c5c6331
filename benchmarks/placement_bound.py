"""How far node placement alone could take issue 9's rho at a given structure size (a bound, not a preset).

Run: ``.venv/bin/python benchmarks/placement_bound.py [--levels nav_test dungeon_1k] [--seeds 0 1 2]
[--shares 0.35 0.25] [--join 0.25]``

The issue's rho gives each polygon the heat-map value of its nearest
structure node (along the initial graph) and ranks it against the
reference flow (:func:`g2s_plugins.evaluation.reference_flow`). The best a
node can carry is the mean reference of the polygons it stands for (the
*ceiling*). This script asks which rho a set of that many nodes could reach
if they could sit anywhere, i.e. without being joined into paths under line
of sight:

``bound``
    greedy removal, started from every polygon being a node: each step
    removes the node whose polygons, handed to their next nearest node,
    add the least squared rank error (each node's value the mean rank of its
    polygons); rho of the remaining set at each ``--shares``. Lazy
    evaluation (a removal only makes later removals dearer in practice, so
    the cheapest stale cost is re-evaluated before it is taken); one
    multi-source Dijkstra per evaluation: tens of seconds for 1,000 polygons.
``join``
    the bound's node set at share ``--join`` handed to the real preset as
    its terminals (``map_analysis`` with a terminal selector that returns
    them): Steiner tree, loops, rooting and line-of-sight simplification
    then join them, and the run is measured like any other (structure share,
    rho of its ``flow`` heat map, area within 6 m); "covered" adds the
    ``coverage`` selector's cover paths grown from that set (its default
    radius) as waypoints, which simplification may drop.

This is a benchmark: nothing here asserts a target; the figures are in
docs/analysis_quality.md ("How far node placement could go").
"""

from __future__ import annotations

import argparse
import heapq
import os

import networkx as nx
import numpy as np
from pydantic import Field
from scipy.sparse import csgraph
from scipy.stats import rankdata, spearmanr

from analysis_quality import levels
from g2s_core import pipeline
from g2s_core.config import PRESETS_DIR, load_raw_config, parse_config
from g2s_core.mesh import mesh_sha256
from g2s_core.model import RunContext, RunResult, Terminals
from g2s_core.plugin import PluginParams, hookimpl
from g2s_core.registry import Registry
from g2s_plugins import evaluation, traffic
from g2s_plugins.terminals import coverage


def greedy_bound(result: RunResult, reference: np.ndarray, shares: list[float]) -> dict[float, tuple[float, np.ndarray]]:
    """For each share: (rho, rows of the node set) of the greedy removal described in the module docs."""
    arrays = traffic.surface_arrays(result.graph)
    n, ranks = arrays.n, rankdata(reference)
    kept = np.ones(n, dtype=bool)

    def owners(mask: np.ndarray) -> np.ndarray:
        source = csgraph.dijkstra(arrays.adjacency, directed=False, indices=np.flatnonzero(mask), min_only=True,
                                  return_predecessors=True)[2]
        return np.where(source < 0, np.arange(n), source)  # a polygon no node reaches stands for itself

    def cell_means(owner: np.ndarray) -> np.ndarray:
        return (np.bincount(owner, weights=ranks, minlength=n) / np.maximum(np.bincount(owner, minlength=n), 1))[owner]

    def error_without(row: int) -> float:
        mask = kept.copy()
        mask[row] = False
        return float(((ranks - cell_means(owners(mask))) ** 2).sum())

    heap = [(error_without(row), row) for row in range(n)]
    heapq.heapify(heap)
    found: dict[float, tuple[float, np.ndarray]] = {}
    for share in sorted(shares, reverse=True):
        while kept.sum() > share * n and heap:
            _, row = heapq.heappop(heap)
            error = error_without(row)
            if heap and error > heap[0][0]:
                heapq.heappush(heap, (error, row))
                continue
            kept[row] = False
        heat = cell_means(owners(kept))
        found[share] = (float(spearmanr(heat, reference).statistic), np.flatnonzero(kept))
    return found


class GivenTerminals:
    """A terminal selector returning the node set it is given (the ``join`` experiment)."""

    NAME = "given_rows"

    class Params(PluginParams):
        rows: list[int] = Field(default_factory=list, description="rows of the initial graph's nodes")
        cover: bool = Field(False, description="add the coverage selector's cover paths from these rows, as waypoints")

    @hookimpl
    def g2s_select_terminals(self, graph: nx.Graph, params: Params, context: RunContext) -> Terminals:
        arrays = traffic.surface_arrays(graph)
        rows = np.asarray(params.rows, dtype=np.int64)
        waypoints = np.zeros(0, dtype=np.int64)
        if params.cover:
            cover = coverage.cover_paths(arrays.adjacency, rows, np.ones(arrays.n, dtype=bool), coverage.default_radius(context))
            waypoints = np.setdiff1d(cover, rows)
        return Terminals(nodes=tuple(sorted(arrays.nodes[row] for row in np.union1d(rows, waypoints).tolist())),
                         waypoints=tuple(sorted(arrays.nodes[row] for row in waypoints.tolist())))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--levels", nargs="+", default=["nav_test", "dungeon_1k"])
    parser.add_argument("--seeds", nargs="+", type=int, default=[0, 1, 2])
    parser.add_argument("--preset", default="map_analysis")
    parser.add_argument("--shares", nargs="+", type=float, default=[0.35, 0.25])
    parser.add_argument("--join", type=float, default=0.25, help="share whose node set is joined by the preset")
    args = parser.parse_args()
    shares = sorted({*args.shares, args.join})
    registry = Registry.from_entry_points()
    registry.register(GivenTerminals(), package="benchmarks", entry_point="placement_bound")
    raw = load_raw_config(PRESETS_DIR / f"{args.preset}.yaml")
    plan = pipeline.plan(parse_config(raw, args.preset), registry, args.preset)
    print(f"load average {os.getloadavg()[0]:.1f}; preset {args.preset}")
    print(f"{'level':<16} {'what':<26} {'structure':>9} {'rho':>6} {'<=6m':>6}")
    for name, mesh in levels(args.levels, args.seeds):
        result = pipeline.run(plan, registry, mesh, name, mesh_sha256(mesh))
        reference = evaluation.reference_flow(result)
        quality = evaluation.evaluate(result, reference)
        print(f"{name:<16} {'the preset (its ceiling)':<26} {quality.structure_share:9.3f} "
              f"{quality.rho_ceiling:6.3f} {quality.area_within[6.0]:6.3f}")
        found = greedy_bound(result, reference, shares)
        for share in sorted(found, reverse=True):
            print(f"{name:<16} {f'bound at {share:g}':<26} {share:9.3f} {found[share][0]:6.3f}")
        for cover in (False, True):
            params = {"rows": found[args.join][1].tolist(), "cover": cover}
            joined_plan = pipeline.plan(parse_config({**raw, "terminals": {"plugin": "given_rows", "params": params}},
                                                     "join"), registry, "join")
            joined = evaluation.evaluate(pipeline.run(joined_plan, registry, mesh, name, mesh_sha256(mesh)), reference)
            what = f"bound {args.join:g} joined" + (", covered" if cover else "")
            print(f"{name:<16} {what:<26} {joined.structure_share:9.3f} {joined.rho:6.3f} "
                  f"{joined.area_within[6.0]:6.3f}", flush=True)


if __name__ == "__main__":
    main()
