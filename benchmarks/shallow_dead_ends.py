"""Shallow dead ends of the navmesh graph: how many there are, how many nodes they hold, how many end the structure.

Run: ``.venv/bin/python benchmarks/shallow_dead_ends.py [--presets map_analysis my.yaml] [--levels hill_fort
dungeon_1k my_level.obj] [--seeds 0 1 2]``

A leaf's dead end is it and the chain of degree-2 nodes behind it, up to
its entrance, the first node of degree 3 or more
(:func:`g2s_plugins.terminals.coverage.dead_end_chain`); it is *shallow*
when every vertex of its polygons lies within the agent's diameter, in
plan, of the segment it shares with the entrance
(:func:`g2s_plugins.terminals.coverage.dead_end_depths`): a notch the
agent's body fills, such as the small polygons a grid of 1 m leaves along
the jagged edge of a face steeper than the slope limit. For every level
(the names of ``benchmarks/analysis_quality.py``, or mesh files) and preset
it runs the preset and prints: the graph's nodes and leaves; the shallow
dead ends, the nodes they hold and how many of those are portal nodes
(``polygon`` -1, area 0, which the heat map's rho ranks like any node);
their polygons' median area and plan width (the least distance between two
parallel lines holding the polygon, where the agent's centre can stand);
how many of them the cover seeded (``terminals`` less its waypoints) and how
many of the final structure's tips (degree 1) lie in one, of all its nodes
and tips. This is a benchmark: nothing here asserts a target.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
from analysis_quality import levels

from g2s_core import pipeline
from g2s_core.config import find_config, load_raw_config, parse_config
from g2s_core.registry import Registry
from g2s_plugins import traffic
from g2s_plugins.terminals.coverage import dead_end_chain, dead_end_depths


def plan_width(points: np.ndarray) -> float:
    """The least distance between two parallel lines holding the convex polygon of (k, 2) ``points`` (in order), m:
    for a convex polygon one of the lines lies along an edge."""
    widths = []
    for start, end in zip(points, np.roll(points, -1, axis=0), strict=True):
        span = end - start
        length = float(np.hypot(*span))
        if length > 0:
            across = np.array([-span[1], span[0]]) / length
            widths.append(float(np.abs((points - start) @ across).max()))
    return min(widths, default=0.0)


def main(argv: list[str] | None = None) -> None:
    """The table for ``argv`` (the command line when None)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--presets", nargs="+", default=["map_analysis"])
    parser.add_argument("--levels", nargs="+", default=["hill_fort"])
    parser.add_argument("--seeds", nargs="+", type=int, default=[0])
    args = parser.parse_args(argv)
    registry = Registry.from_entry_points()
    plans = {Path(p).stem: pipeline.plan(parse_config(load_raw_config(find_config(p)), p), registry, p)
             for p in args.presets}
    print(f"{'level':<18} {'preset':<16} {'nodes':>6} {'leaves':>6} {'shallow':>7} {'in them':>7} {'portal':>6} "
          f"{'area m2':>7} {'width m':>7} {'seeded':>6} {'struct':>6} {'tips':>5} {'in them':>7}")
    for name, mesh in levels(args.levels, args.seeds):
        for preset, plan in plans.items():
            result = pipeline.run(plan, registry, mesh, name, "-")
            graph, navmesh = result.graph, result.context.navmesh
            arrays = traffic.surface_arrays(graph)
            leaves = np.flatnonzero(np.diff(arrays.adjacency.indptr) == 1)
            depths, entrances = dead_end_depths(graph, navmesh, arrays, leaves)
            shallow = leaves[(depths < 2 * result.context.agent.radius) & (entrances >= 0)]
            held: set = set()
            polygons = []
            for leaf in shallow.tolist():
                chain, _ = dead_end_chain(arrays.adjacency, leaf)
                held.update(arrays.nodes[i] for i in chain)
                polygons += [p for p in (graph.nodes[arrays.nodes[i]].get("polygon", -1) for i in chain) if p >= 0]
            portal = sum(graph.nodes[n].get("polygon", -1) < 0 for n in held)
            area = float(np.median(navmesh.areas[polygons])) if polygons else float("nan")
            width = float(np.median([plan_width(navmesh.vertices[navmesh.polygons[p][navmesh.polygons[p] >= 0]][:, [0, 2]])
                                     for p in polygons])) if polygons else float("nan")
            seeded = sum(n in held for n in result.terminals.without_waypoints)
            structure = result.structure.to_undirected()
            tips = [n for n in structure if structure.degree(n) == 1]
            print(f"{name:<18} {preset:<16} {arrays.n:>6} {len(leaves):>6} {len(shallow):>7} {len(held):>7} {portal:>6} "
                  f"{area:>7.2f} {width:>7.2f} {seeded:>6} {structure.number_of_nodes():>6} {len(tips):>5} "
                  f"{sum(n in held for n in tips):>7}", flush=True)


if __name__ == "__main__":
    main()
