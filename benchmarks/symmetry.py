"""How far each stage's output on a symmetric level is from its own image (issue 9's heat map on competitive levels).

Run: ``.venv/bin/python benchmarks/symmetry.py [--levels paintball lanes moba rts_map kit_arena capture_flag]
[--seeds 0] [--presets map_analysis map_analysis_sampling]``

A competitive level is built symmetric on purpose, and a fair level's heat map is as symmetric as the level. Each
level kind named here is generated symmetric under a half turn about the centre of its bounds in plan (``paintball``,
``lanes``, ``moba``, ``rts_map``, ``kit_arena``, the last up to its kit's seams of 3 cm) or under a mirror in its middle
plane x = const (``capture_flag``), :data:`SYMMETRIES`; the table first checks that of the mesh (``mesh err``: the
largest distance from a vertex's image to the nearest vertex, m). For every level and preset it then measures, stage
by stage, how far the output is from its image, with the level's centre and cell grid chosen so that every cell's
image is a cell:

(a) ``cover``: the navmesh itself. Its detail triangles are rasterized in plan on cells of :data:`CELL` m
    (:func:`reference_stability.floor_raster`: a cell is covered when its centre lies in a triangle, at the
    triangle's height there), each cell in the polygon Detour finds under it
    (:func:`g2s_plugins.evaluation.polygons_under`); the share of covered cells whose image is covered too (within
    :data:`HEIGHT_TOLERANCE` in height, so decks over one another stay apart). Recast's voxel grid, regions and
    polygons are built in the level's frame, not its symmetry's: this is the cut's cost.
(b) ``flow/m2``: the walking flow per unit area on that raster: each cell takes its polygon's reference flow
    (:func:`g2s_plugins.evaluation.reference_flow` on the navmesh graph: exact up to 2,000 nodes) over the polygon's
    area; Spearman rho between a cell's value and its image's, over the covered cells whose image is covered.
    ``flow/poly`` is the same for the polygon's flow itself, not divided by its area (what a node's traffic
    reads before any structure): the two separate what polygons of unequal size do to the flow.
(c) ``heat``: the heat map, rasterized the same way: each polygon takes the first analyzer's value of its nearest
    structure node (:func:`g2s_plugins.evaluation.heat_map`); on the sampling route the samples' heat carried to the
    navmesh's polygons as ``rho_navmesh`` carries it (:func:`g2s_plugins.evaluation.carry`). ``ceiling`` is the same
    for ``rho_ceiling``'s heat map (each structure node the mean percentile of the run's reference flow over the
    nodes it stands for, :func:`g2s_plugins.evaluation.placement_heat`): what the structure's placement alone does
    to the reference's symmetry, before the analyzer's own flow (a sample of 256 sources) does more.
(d) ``paired``: the share of structure nodes with a structure node within :data:`PAIR_RADIUS` m of their image
    (a height difference counting ``PAIR_RADIUS / HEIGHT_TOLERANCE`` times: a node 1 m over the image's place is 3 m
    from it), and ``node rho``: Spearman rho of the values of each
    such node and its nearest one.

On the sampling route two more columns read the run's own graph: ``samples`` (the share of samples with a sample
within a tenth of the spacing of their image) and ``s flow`` (Spearman rho of the samples' reference flow and that
of the sample nearest their image); on the navmesh route "-". A stage that reads lower than the one before it broke
symmetry that its input had. This is a benchmark: nothing here asserts a target.

Cost per level: the preset's run, one more reference flow (on the sampling route a navmesh build and its flow, as
the ``traffic`` evaluator's), and the rasterization, O(cells) with one Detour look-up per cell, about 1.6e5-4e5
cells of 0.25 m.
"""

from __future__ import annotations

import argparse
import os
import platform
import subprocess
import time
from pathlib import Path

import networkx as nx
import numpy as np
from analysis_quality import KINDS
from reference_stability import floor_raster, node_positions
from scipy.spatial import cKDTree

from g2s_core import pipeline
from g2s_core.config import find_config, load_raw_config, parse_config
from g2s_core.errors import G2SError
from g2s_core.mesh import mesh_sha256
from g2s_core.model import RunResult
from g2s_core.registry import Registry
from g2s_plugins import evaluation, traffic
from g2s_plugins.graph_builders import navmesh as navmesh_builder
from g2s_plugins.recast import build_navmesh

CELL = 0.25
"""Raster cell, m."""

HEIGHT_TOLERANCE = 1.0
"""A cell's (or node's) image matches a cell (node) at most this far above or below it, m: half the agent's height."""

PAIR_RADIUS = 3.0
"""Structure nodes pair with their image's nearest node within this plan distance, m."""

HALF_TURN, MIRROR = "half turn", "mirror"
SYMMETRIES: dict[str, str] = {"paintball": HALF_TURN, "lanes": HALF_TURN, "moba": HALF_TURN, "rts_map": HALF_TURN,
                              "kit_arena": HALF_TURN, "capture_flag": MIRROR}
"""The symmetry each level kind is generated with (its docstring), about the centre of its bounds in plan."""


def image(points: np.ndarray, centre: np.ndarray, symmetry: str) -> np.ndarray:
    """(k, 3) the images of (k, 3) ``points`` (x, y, z; m) under ``symmetry`` about the plan point ``centre`` (x, z)."""
    turned = np.array(points, dtype=np.float64, copy=True)
    turned[:, 0] = 2.0 * centre[0] - turned[:, 0]
    if symmetry == HALF_TURN:
        turned[:, 2] = 2.0 * centre[1] - turned[:, 2]
    return turned


def image_rows(points: np.ndarray, centre: np.ndarray, symmetry: str, radius: float) -> np.ndarray:
    """(k,) for each of (k, 3) ``points``, the row of the point nearest its image within ``radius`` (m), heights
    scaled so that :data:`HEIGHT_TOLERANCE` counts as ``radius`` (-1: none; a k-d tree, O(k log k))."""
    scale = np.array([1.0, radius / HEIGHT_TOLERANCE, 1.0])
    distance, row = cKDTree(points * scale).query(image(points, centre, symmetry) * scale,
                                                  distance_upper_bound=radius)
    return np.where(np.isfinite(distance), row, -1)


def paired_rho(values: np.ndarray, partner: np.ndarray) -> float:
    """Spearman rho of (k,) ``values`` against their partners' (rows of ``partner``, -1 none; NaN where undefined)."""
    ok = (partner >= 0) & np.isfinite(values)
    ok[ok] &= np.isfinite(values[partner[ok]])
    return evaluation.spearman(values[ok], values[partner[ok]])


def polygon_values(graph: nx.Graph, values: np.ndarray, polygon_count: int) -> np.ndarray:
    """(P,) ``values`` ((n,) in :func:`~g2s_plugins.traffic.surface_arrays` order of a navmesh graph) by polygon
    index (NaN: a polygon not in the graph)."""
    by_polygon = np.full(polygon_count, np.nan)
    for row, node in enumerate(traffic.surface_arrays(graph).nodes):
        polygon = graph.nodes[node].get("polygon", -1)
        if polygon >= 0:
            by_polygon[polygon] = values[row]
    return by_polygon


def measure(result: RunResult, centre: np.ndarray, symmetry: str) -> dict[str, float]:
    """The measures (a)-(d) of a run (see the module docs), by column name."""
    reference = evaluation.reference_flow(result)
    surface = evaluation.navmesh_surface(result, reference)
    if result.context.navmesh is not None:
        navmesh = result.context.navmesh
    else:  # the reference navmesh navmesh_surface measures on, built again for its polygons
        navmesh = build_navmesh(result.context.mesh.vertices, result.context.mesh.faces, result.context.agent,
                                navmesh_builder.Params(ledge_filter=evaluation.REFERENCE_LEDGE_FILTER))
    cells = floor_raster(navmesh, CELL, tuple(centre))
    owner = evaluation.polygons_under(navmesh, cells)
    cells, owner = cells[owner >= 0], owner[owner >= 0]
    partner = image_rows(cells, centre, symmetry, CELL / 2)
    areas = polygon_values(surface.graph, traffic.surface_arrays(surface.graph).area, navmesh.polygon_count)
    flow = polygon_values(surface.graph, surface.flow, navmesh.polygon_count)
    first = next(iter(result.analysis.values()))
    heat = evaluation.heat_map(result.graph, result.structure, first)
    ceiling = evaluation.placement_heat(result.graph, result.structure, reference)
    if result.context.navmesh is None:
        arrays = traffic.surface_arrays(result.graph)
        heat, ceiling = (evaluation.carry(values, arrays.area, node_positions(result), surface)
                         for values in (heat, ceiling))
    heat, ceiling = (polygon_values(surface.graph, values, navmesh.polygon_count) for values in (heat, ceiling))
    with np.errstate(divide="ignore", invalid="ignore"):
        per_area = np.where(areas > 0, flow / areas, np.nan)
    measures = {"cover": float((partner >= 0).mean()),
                "flow/poly": paired_rho(flow[owner], partner),
                "flow/m2": paired_rho(per_area[owner], partner),
                "ceiling": paired_rho(ceiling[owner], partner),
                "heat": paired_rho(heat[owner], partner)}
    nodes = sorted(result.structure)
    positions = np.array([result.graph.nodes[node]["pos"] for node in nodes], dtype=np.float64)
    node_partner = image_rows(positions, centre, symmetry, PAIR_RADIUS)
    measures["paired"] = float((node_partner >= 0).mean())
    measures["node rho"] = paired_rho(np.array([first[node] for node in nodes]), node_partner)
    measures["samples"] = measures["s flow"] = float("nan")
    if result.context.navmesh is None:
        spacing = result.graph.graph.get("sampling_stats", {}).get("spacing", 2.0 * float(result.context.agent.radius))
        sample_partner = image_rows(node_positions(result), centre, symmetry, spacing / 10)
        measures["samples"] = float((sample_partner >= 0).mean())
        nearest = image_rows(node_positions(result), centre, symmetry, spacing)
        measures["s flow"] = paired_rho(reference, nearest)
    return measures


def mesh_error(vertices: np.ndarray, centre: np.ndarray, symmetry: str) -> float:
    """The largest distance from a vertex's image to the nearest vertex, m (0 for an exactly symmetric mesh)."""
    return float(cKDTree(vertices).query(image(vertices, centre, symmetry))[0].max())


def main(argv: list[str] | None = None, registry: Registry | None = None) -> None:
    """The table for ``argv`` (the command line when None), with ``registry`` (the installed plugins when None)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--levels", nargs="+", default=list(SYMMETRIES), choices=list(SYMMETRIES))
    parser.add_argument("--seeds", nargs="+", type=int, default=[0])
    parser.add_argument("--presets", nargs="+", default=["map_analysis", "map_analysis_sampling"])
    args = parser.parse_args(argv)
    registry = registry or Registry.from_entry_points()
    try:
        plans = {p: pipeline.plan(parse_config(load_raw_config(find_config(p)), p), registry, p) for p in args.presets}
    except G2SError as error:  # a preset name or config file that does not load: one line, exit 2
        parser.exit(2, f"{error}\n")
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True,
                            cwd=Path(__file__).parent).stdout.strip()
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f}; "
          f"commit {commit}; {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}")
    columns = ("cover", "flow/poly", "flow/m2", "ceiling", "heat", "paired", "node rho", "samples", "s flow")
    print(f"{'level':<16} {'symmetry':<9} {'mesh err':>8} {'preset':<22} {'nodes':>6} "
          + " ".join(f"{c:>9}" for c in columns) + f" {'cpu s':>7}")
    for name in args.levels:
        for seed in args.seeds:
            mesh = KINDS[name](seed)
            lo, hi = mesh.bounds
            centre = np.array([(lo[0] + hi[0]) / 2, (lo[2] + hi[2]) / 2])
            symmetry = SYMMETRIES[name]
            error = mesh_error(mesh.vertices, centre, symmetry)
            for preset, plan in plans.items():
                cpu = time.process_time()
                result = pipeline.run(plan, registry, mesh, f"{name}_s{seed}", mesh_sha256(mesh))
                measures = measure(result, centre, symmetry)
                cpu = time.process_time() - cpu
                print(f"{name + f'_s{seed}':<16} {symmetry:<9} {error:8.3f} {preset:<22} "
                      f"{result.structure.number_of_nodes():>6} "
                      + " ".join(f"{measures[c]:9.3f}" for c in columns) + f" {cpu:7.1f}", flush=True)


if __name__ == "__main__":
    main()
