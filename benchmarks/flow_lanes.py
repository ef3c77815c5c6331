"""How much of the sampling route's miss against the navmesh graph's flow ("rho nav") is its own walking flow's, and
how much of that is lanes: per level, the heat map and the flow it follows, each carried to the navmesh polygons.

Run: ``.venv/bin/python benchmarks/flow_lanes.py [--levels labyrinth nav_test my_level.obj] [--seeds 0 1 2]``
(levels as ``benchmarks/analysis_quality.py`` names them).

For each level it runs ``map_analysis_sampling`` and prints:

* ``samples``, ``added``: the initial graph's nodes, and those of them of area 0 (the points the sampler adds in
  passages its grid misses, :func:`g2s_plugins.graph_builders.sampling.moved_into_passages`);
* ``rho``: the heat map against the run's own walking flow (the evaluation's ``rho``);
* ``heat nav``: the heat map against the navmesh graph's flow (the evaluation's ``rho_navmesh``);
* ``flow nav``: the run's own walking flow (the evaluation's reference on its graph) carried to the polygons the same
  way (:func:`g2s_plugins.evaluation.carry`: each polygon the area-weighted mean of the samples standing on it) and
  ranked against the navmesh graph's flow: what a heat map that followed its own flow sample by sample would read;
* ``busiest nav``: each polygon given the largest own walking flow of the samples within the sampler's clearance of
  it in plan (Detour's nearest polygon, no farther in height than the navmesh's climb; Recast erodes the floor a
  little wider than the sampler, and the added points stand exactly the clearance off a wall), against the navmesh
  graph's flow: the walkers that pass the polygon in any lane, at least;
* ``quiet``: the share of those samples whose flow is under a tenth of their polygon's busiest (beside the lane the
  walkers take through it).

Cost per level: one run of the preset with the ``traffic`` evaluator's navmesh measures (a navmesh build and its
flow), one more navmesh build (Recast builds the same polygons) and one Detour look-up per sample. This is a
benchmark: nothing here asserts a target.
"""

from __future__ import annotations

import argparse
import os
import platform

import numpy as np
from analysis_quality import levels

from g2s_core import pipeline
from g2s_core.config import find_config, load_raw_config, parse_config
from g2s_core.mesh import mesh_sha256
from g2s_core.registry import Registry
from g2s_plugins import evaluation, traffic
from g2s_plugins.graph_builders import navmesh as navmesh_builder
from g2s_plugins.recast import build_navmesh

PRESET = "map_analysis_sampling"
QUIET = 0.1
"""A sample is quiet when its flow is under this share of its polygon's busiest."""


def polygons_within(result, surface: evaluation.NavmeshSurface, reach: float) -> np.ndarray:
    """(n,) the navmesh graph row of the polygon each sample of the run stands on or within ``reach`` of in plan
    (-1: none)."""
    context = result.context
    navmesh = build_navmesh(context.mesh.vertices, context.mesh.faces, context.agent,
                            navmesh_builder.Params(ledge_filter=evaluation.REFERENCE_LEDGE_FILTER))
    arrays = traffic.surface_arrays(surface.graph)
    rows = np.full(navmesh.polygon_count, -1, dtype=np.int64)
    kept = [polygon for polygon in range(navmesh.polygon_count) if polygon in surface.graph]
    rows[kept] = arrays.rows(kept)
    graph = result.graph
    positions = np.array([graph.nodes[node]["pos"] for node in traffic.surface_arrays(graph).nodes], dtype=np.float64)
    polygons = evaluation.polygons_under(navmesh, positions, reach)
    return np.where(polygons >= 0, rows[polygons], -1)


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--levels", nargs="+", default=["labyrinth"])
    parser.add_argument("--seeds", nargs="+", type=int, default=[0])
    args = parser.parse_args(argv)
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f}")
    registry = Registry.from_entry_points()
    plan = pipeline.plan(parse_config(load_raw_config(find_config(PRESET)), PRESET), registry, PRESET)
    print(f"{'level':<18} {'samples':>7} {'added':>6} {'rho':>6} {'heat nav':>8} {'flow nav':>8} {'busiest nav':>11} "
          f"{'quiet':>6}")
    for name, mesh in levels(args.levels, args.seeds):
        result = pipeline.run(plan, registry, mesh, name, mesh_sha256(mesh))
        reference = np.asarray(evaluation.reference_flow(result), dtype=np.float64)
        surface = evaluation.navmesh_surface(result, reference)
        if surface is None or result.structure is None:
            print(f"{name:<18} no navmesh or no structure")
            continue
        arrays = traffic.surface_arrays(result.graph)
        positions = np.array([result.graph.nodes[node]["pos"] for node in arrays.nodes], dtype=np.float64)
        heat = evaluation.heat_map(result.graph, result.structure, next(iter(result.analysis.values())))

        def on_navmesh(values: np.ndarray) -> np.ndarray:
            return evaluation.carry(values, arrays.area, positions, surface)

        owner = polygons_within(result, surface, float(result.graph.graph["sampling_stats"]["clearance"]))
        on = owner >= 0
        busiest = np.full(traffic.surface_arrays(surface.graph).n, -np.inf)
        np.maximum.at(busiest, owner[on], reference[on])
        quiet = reference[on] < QUIET * busiest[owner[on]]
        print(f"{name:<18} {arrays.n:>7} {int(np.count_nonzero(arrays.area == 0)):>6} "
              f"{evaluation.spearman(heat, reference):6.3f} {evaluation.spearman(on_navmesh(heat), surface.flow):8.3f} "
              f"{evaluation.spearman(on_navmesh(reference), surface.flow):8.3f} "
              f"{evaluation.spearman(np.where(np.isfinite(busiest), busiest, np.nan), surface.flow):11.3f} "
              f"{100 * quiet.mean():5.1f}%", flush=True)


if __name__ == "__main__":
    main()
