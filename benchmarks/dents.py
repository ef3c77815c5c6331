"""Where the cover's terminals stand, what each costs in structure nodes, and how its heat compares with its polygons.

Run: ``.venv/bin/python benchmarks/dents.py [--levels cruise_ship beach hotel hospital nav_test stepwell my_level.obj]
[--seeds 0 1 2] [--preset map_analysis|my.yaml]``

For every level (the names of ``benchmarks/analysis_quality.py``, or mesh
files) it runs ``--preset`` and reads its terminals by the step of
``coverage`` that chose them (:func:`g2s_plugins.terminals.coverage.cover`):
the seeded leaves, the waypoints of the traffic-aware cover and those of
the plain cover (the farthest uncovered), as they stand before
``dent_rho_budget``, whose drops it counts with the Spearman rho each dent
the cover holds without it would cost by estimate
(:func:`~g2s_plugins.terminals.coverage.dent_costs`). Each seeded leaf's dead end (the
leaf and the chain of degree-2 nodes behind it,
:func:`~g2s_plugins.terminals.coverage.dead_end_depths`) is a *dent* when
it reaches at most ``--depth`` metres beyond its way in, else a *room*.

Cost: the final structure's *spurs*, each a structure leaf and the chain
of degree-2 structure nodes behind it up to its first node of degree 3 or
more (that node not counted), by where the spur's leaf stands: in a dent
(a node of a dent's dead end), in a room, or elsewhere (a waypoint's leaf
on open floor). Heat: for the spurs' leaves, the median of their heat (the
first analyzer's value, a walking-flow percentile), of the mean reference
percentile of the polygons each stands for (the value a perfect node there
would carry) and of the heat of the node their spur joins. Then the
ceiling (``rho_ceiling``, :func:`g2s_plugins.evaluation.placement_rho`)
and structure share with the spurs of each kind (dent, room, open floor)
pruned, and with each of them cut to the node next to its joint (a node
at its door): what giving those places no node of their own, or one at
their door, would cost at best. This is a benchmark: nothing here asserts
a target.
"""

from __future__ import annotations

import argparse

import networkx as nx
import numpy as np
from analysis_quality import levels

from g2s_core import pipeline
from g2s_core.config import find_config, load_raw_config, parse_config
from g2s_core.registry import Registry
from g2s_plugins import evaluation, traffic
from g2s_plugins.terminals import coverage


def spurs(structure: nx.Graph) -> list[list]:
    """Each leaf spur of the undirected ``structure``: its leaf first, then the degree-2 nodes behind it (the node of
    degree 3 or more it joins left out; a structure that is one path gives none)."""
    found = []
    for leaf in sorted(node for node, degree in structure.degree if degree == 1):
        chain, previous, current = [leaf], None, leaf
        while True:
            ahead = [n for n in structure[current] if n != previous]
            if len(ahead) != 1:
                chain = []
                break
            if structure.degree[ahead[0]] != 2:
                chain.append(ahead[0])  # the joint, dropped below
                break
            previous, current = current, ahead[0]
            chain.append(current)
        if chain and structure.degree[chain[-1]] >= 3:
            found.append(chain)
    return found


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--levels", nargs="+", default=["cruise_ship", "beach", "hotel", "hospital", "nav_test", "stepwell"])
    parser.add_argument("--seeds", nargs="+", type=int, default=[0])
    parser.add_argument("--depth", type=float, default=None,
                        help="metres: a dead end within this of its way in is a dent (default: the preset's "
                        "dent_depth, which its drops use too, or 2 m where it sets none)")
    parser.add_argument("--preset", default="map_analysis")
    args = parser.parse_args(argv)
    registry = Registry.from_entry_points()
    config = parse_config(load_raw_config(find_config(args.preset)), args.preset)
    plan = pipeline.plan(config, registry, args.preset)
    params = coverage.Params(**config.terminals.params)
    if args.depth is None:
        args.depth = params.dent_depth or 2.0
    for name, mesh in levels(args.levels, args.seeds):
        result = pipeline.run(plan, registry, mesh, name, "-")
        graph, navmesh = result.graph, result.context.navmesh
        # the terminals as they stand before the dent budget, so a dent it dropped still reads as a dent
        chosen = coverage.cover(graph, params.model_copy(update={"dent_rho_budget": 0.0}), result.context)
        arrays = chosen.arrays
        n = arrays.n
        degree = np.diff(arrays.adjacency.indptr)
        leaves = chosen.leaves[degree[chosen.leaves] == 1]
        rank = coverage.walking_percentile(arrays, params.traffic_sources, params.traffic_ties, params.traffic_scaling)
        dents, costs = coverage.dent_costs(graph, navmesh, arrays, leaves, rank, args.depth, chosen.rows,
                                           params.radius or coverage.default_radius(result.context))
        dropped = np.setdiff1d(chosen.rows, coverage.cover(graph, params, result.context).rows)
        depths, _ = coverage.dead_end_depths(graph, navmesh, arrays, leaves)
        kind = np.zeros(n, dtype=np.int8)  # 0 open floor, 1 in a dent's dead end, 2 in a room's
        for leaf, depth in zip(leaves.tolist(), depths.tolist(), strict=True):
            kind[coverage.dead_end_chain(arrays.adjacency, leaf)[0]] = 1 if depth <= args.depth else 2
        traffic_waypoints = np.setdiff1d(chosen.traffic, chosen.leaves)
        plain_waypoints = np.setdiff1d(chosen.rows, chosen.traffic)
        structure = result.structure.to_undirected()
        kept = arrays.rows(sorted(structure))
        heat_values = next(iter(result.analysis.values()))
        reference = evaluation.reference_flow(result)
        percentile = traffic.percentile(reference)
        nearest = evaluation.nearest_structure_rows(result)
        stands_for = np.bincount(nearest[nearest >= 0], weights=percentile[nearest >= 0], minlength=n) / np.maximum(
            np.bincount(nearest[nearest >= 0], minlength=n), 1)
        found = spurs(structure)
        by_kind = {0: [], 1: [], 2: []}
        for chain in found:
            by_kind[int(kind[arrays.index[chain[0]]])].append(chain)
        ceiling = evaluation.placement_rho(graph, structure, reference, nearest)
        print(f"{name}: {n} nodes, structure {len(kept)} ({100 * len(kept) / n:.1f} %), ceiling {ceiling:.3f}; "
              f"terminals: {len(leaves)} seeded leaves ({int((depths <= args.depth).sum())} dents <= {args.depth:g} m, "
              f"{int((depths > args.depth).sum())} rooms; depth <= 1 / 2 / 3 m: {int((depths <= 1).sum())} / "
              f"{int((depths <= 2).sum())} / {int((depths <= 3).sum())}), {len(traffic_waypoints)} traffic waypoints "
              f"({int((kind[traffic_waypoints] == 1).sum())} in dents, {int(np.isin(traffic_waypoints, kept).sum())} kept), "
              f"{len(plain_waypoints)} farthest-uncovered waypoints ({int(np.isin(plain_waypoints, kept).sum())} kept)")
        print(f"  dents the cover holds without them: {len(dents)}, estimated rho each would cost "
              f"(coverage.dent_costs) median {np.median(costs) if len(costs) else 0:.4f}, all {costs.sum():.4f}; "
              f"dropped by dent_rho_budget ({params.dent_rho_budget:g}): {len(dropped)}, "
              f"estimated {costs[np.isin(dents, dropped)].sum():.4f}")
        for k, label in ((1, "dent"), (2, "room"), (0, "open floor")):
            chains = by_kind[k]
            if not chains:
                print(f"  {label:<10} spurs: none")
                continue
            tips = arrays.rows([c[0] for c in chains])
            joints = [c[-1] for c in chains]
            cost = np.array([len(c) - 1 for c in chains])
            rest = set(structure) - {node for c in chains for node in c[:-1]}
            pruned = evaluation.placement_rho(graph, rest, reference)
            door = rest | {c[-2] for c in chains}
            at_door = evaluation.placement_rho(graph, door, reference)
            print(f"  {label:<10} spurs: {len(chains)}, {int(cost.sum())} nodes ({100 * cost.sum() / n:.1f} points), "
                  f"per spur median {np.median(cost):.0f} (max {cost.max()}); heat of its leaf {np.median([heat_values[c[0]] for c in chains]):.1f}, "
                  f"its polygons {np.median(stands_for[tips]):.1f}, its joint {np.median([heat_values[j] for j in joints]):.1f}; "
                  f"pruned: structure {100 * len(rest) / n:.1f} %, ceiling {pruned:.3f}; cut to the node next to its joint: "
                  f"{100 * len(door) / n:.1f} %, ceiling {at_door:.3f}", flush=True)


if __name__ == "__main__":
    main()
