"""How much issue 9's navmesh reference depends on how the navmesh cuts the floor, and how close each route's heat
map comes to a walking flow that depends on no tessellation.

Run: ``.venv/bin/python benchmarks/reference_stability.py [--levels nav_test dungeon_1k terrain_1k castle_1k
market my_level.obj] [--seeds 0 1] [--cell 0.25] [--pairs 1024 16] [--stability-pairs 256 16] [--jobs 1]``

Issue 9's reference flow counts the area-weighted origin-destination walkers through each navmesh *polygon*
(:func:`g2s_plugins.evaluation.reference_flow` on the ``navmesh`` builder's graph). How a polygon is cut is
Recast's choice, so the same floor under another tessellation gets another reference. Every flow below is put on
one common raster of the floor (square cells of ``--cell`` metres in plan, at the height of the default navmesh's
detail surface: the centre of every cell inside one of its detail triangles, on every storey) and compared there by
Spearman's rho over the cells both have (each cell counts alike, so each square metre does):

* ``poly``: the reference flow of a navmesh (``navmesh`` builder parameters with the reference's
  :data:`g2s_plugins.evaluation.REFERENCE_LEDGE_FILTER`, exact up to 2,000 polygons, 512 linearly scaled sources
  above), each cell taking the flow of the polygon holding it (Detour's nearest polygon,
  :func:`g2s_plugins.evaluation.polygons_under`). Tessellations: ``default``; ``tri`` (``verts_per_poly: 3``);
  ``monotone`` (``partition: monotone``, long thin polygons); ``cs0.2`` (``cell_size: 0.2`` instead of the
  agent's radius / 2); ``yaw22`` and ``yaw45`` (the level turned by 22.5 and 45 degrees about the vertical
  through its centre, which re-cuts it; the raster is turned with it, so each cell is the same piece of floor).
* ``pulled``: a walking flow without polygons: ``--pairs S T`` origin-destination pairs, S origin cells and T
  destination cells for each drawn uniformly from the raster (so by area, as the reference draws its pairs), each
  walked along the string-pulled path through the corridor of polygons a shortest path of the navmesh's polygon
  graph crosses (the simple stupid funnel algorithm, Mononen 2010, the way Detour's ``findStraightPath`` pulls
  a ``findPath`` corridor; O(corridor) per pair), each cell counting the walkers whose path passes within
  :data:`WALKER_REACH` of it (in plan; a height difference counts :data:`HEIGHT_SCALE` as much, so a storey
  above is out of reach). It counts walkers per square metre, not per polygon; its own dependence on the
  tessellation (the corridor) is measured the same way (``pulled`` under each tessellation against the
  default's, the same ``--stability-pairs``, a subset of those pairs), and its sampling noise by another draw of
  as many pairs on the default navmesh against the first (printed on the ``raster`` line).
* ``sampled``: the sampling route's own walking flow (its initial graph of ``map_analysis_sampling``, its
  evaluation's reference: :func:`g2s_plugins.evaluation.reference_flow`), each cell taking the flow of the
  nearest sample (3D, heights scaled by :data:`HEIGHT_SCALE`) within two sample spacings.

Then the heat maps, on the same raster: ``map_analysis`` (each cell its polygon's value, each polygon the value of
its nearest structure node, as issue 9 measures) and ``map_analysis_sampling`` (each cell its nearest sample's), each
against ``poly`` (default), ``pulled`` (default) and ``sampled``; beside them the issue's own measures of the
sampling run (``rho``, against its own graph, and ``rho nav``, against the default navmesh, per polygon:
:mod:`g2s_plugins.evaluation`). Cost per level: six navmesh builds and their flows, ``2 S`` Dijkstra
searches of the polygon graph and ``2 S T`` funnels (the pairs and the other draw), ``6 S' T'`` of each for the
``--stability-pairs``, each funnel's path read against a k-d tree of the raster, one Detour look-up per cell and
tessellation, and one run of each preset: on the 1k dungeon of seed 0 (96,133 cells) 258 s of CPU, of which
3.9 s the presets and 4.7 s the navmeshes and their flows on the raster (the rest: the 57,344 funnels and their
paths, and the sampling run's own measures). This is a benchmark: nothing here asserts a target.
"""

from __future__ import annotations

import argparse
import itertools
import math
import multiprocessing
import os
import platform
import time
from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np
import trimesh
from analysis_quality import levels
from scipy.sparse import coo_array, csgraph
from scipy.spatial import cKDTree

from g2s_core import pipeline
from g2s_core.config import AgentConfig, find_config, load_raw_config, parse_config
from g2s_core.mesh import mesh_sha256
from g2s_core.model import RunResult
from g2s_core.registry import Registry
from g2s_plugins import evaluation, traffic
from g2s_plugins.graph_builders import navmesh as navmesh_builder
from g2s_plugins.recast import NavMesh, build_navmesh
from g2s_plugins.samples.pieces import yaw_about_centre

WALKER_REACH = 0.5
"""A walker counts on every raster cell within this of its string-pulled path, m (in plan)."""

HEIGHT_SCALE = 0.5
"""Height differences count this much of a plan distance when cells are matched to paths and samples (a cell 1 m
above a path is as far as one 0.5 m beside it): a storey above or below is out of reach."""

PATH_STEP = 0.25
"""The string-pulled path is read at points this far apart in plan, m (half :data:`WALKER_REACH`)."""

TESSELLATIONS: dict[str, tuple[dict, float]] = {
    "default": ({}, 0.0),
    "tri": ({"verts_per_poly": 3}, 0.0),
    "monotone": ({"partition": "monotone"}, 0.0),
    "cs0.2": ({"cell_size": 0.2}, 0.0),
    "yaw22": ({}, 22.5),
    "yaw45": ({}, 45.0),
}
"""Name -> (``navmesh`` builder parameters over the reference's, yaw of the level in degrees)."""

PRESETS = ("map_analysis", "map_analysis_sampling")


def floor_raster(navmesh: NavMesh, cell: float, corner: tuple[float, float] = (0.0, 0.0)) -> np.ndarray:
    """(M,3) the centres of the ``cell``-metre plan grid (a cell's corner at the plan point ``corner``, x and z; the
    world origin by default) inside the detail triangles of ``navmesh``, lifted onto them; a centre on an edge of two
    triangles counted once. O(M + DT)."""
    corners = navmesh.detail_vertices[navmesh.detail_triangles] - [corner[0], 0.0, corner[1]]  # (DT,3,3)
    points = []
    for a, b, c in corners:
        low, high = np.minimum(np.minimum(a, b), c), np.maximum(np.maximum(a, b), c)
        xs = (np.arange(math.floor(low[0] / cell - 0.5), math.ceil(high[0] / cell - 0.5) + 1) + 0.5) * cell
        zs = (np.arange(math.floor(low[2] / cell - 0.5), math.ceil(high[2] / cell - 0.5) + 1) + 0.5) * cell
        gx, gz = (g.ravel() for g in np.meshgrid(xs, zs))
        denominator = (b[2] - c[2]) * (a[0] - c[0]) + (c[0] - b[0]) * (a[2] - c[2])
        if abs(denominator) < 1e-12:
            continue
        wa = ((b[2] - c[2]) * (gx - c[0]) + (c[0] - b[0]) * (gz - c[2])) / denominator
        wb = ((c[2] - a[2]) * (gx - c[0]) + (a[0] - c[0]) * (gz - c[2])) / denominator
        wc = 1.0 - wa - wb
        inside = (wa >= -1e-9) & (wb >= -1e-9) & (wc >= -1e-9)
        heights = wa * a[1] + wb * b[1] + wc * c[1]
        points.append(np.column_stack([gx[inside], heights[inside], gz[inside]]))
    raster = np.concatenate(points)
    _, first = np.unique(np.column_stack([np.floor(raster[:, [0, 2]] / cell), np.round(raster[:, 1] / 0.05)]),
                         axis=0, return_index=True)
    return raster[np.sort(first)] + [corner[0], 0.0, corner[1]]


def scaled(points: np.ndarray) -> np.ndarray:
    """(n,3) ``points`` with heights scaled by :data:`HEIGHT_SCALE` (the metric cells are matched in)."""
    return points * np.array([1.0, HEIGHT_SCALE, 1.0])


@dataclass
class Tessellated:
    """One navmesh of the level and the raster on it.

    Attributes:
        navmesh: the navmesh (in the turned level's frame for a turned tessellation).
        cells: (M,3) the raster in that frame.
        polygon: (M,) the polygon holding each cell (-1: none).
        poly_flow: (M,) the reference flow of the cell's polygon (NaN: none).
    """

    navmesh: NavMesh
    cells: np.ndarray
    polygon: np.ndarray
    poly_flow: np.ndarray


def tessellate(mesh: trimesh.Trimesh, agent: AgentConfig, raster: np.ndarray, parameters: dict,
               yaw: float) -> Tessellated:
    """The navmesh of ``mesh`` turned by ``yaw`` degrees built with ``parameters`` and its reference flow on
    ``raster`` (turned with it)."""
    cells = raster
    if yaw:
        turn = yaw_about_centre(mesh, yaw)
        mesh = mesh.copy().apply_transform(turn)
        cells = trimesh.transformations.transform_points(raster, turn)
    params = navmesh_builder.Params(ledge_filter=evaluation.REFERENCE_LEDGE_FILTER, **parameters)
    navmesh = build_navmesh(mesh.vertices, mesh.faces, agent, params)
    graph = navmesh_builder.navmesh_graph(navmesh, agent, params.max_edge_gap)
    arrays = traffic.surface_arrays(graph)
    flow = traffic.walking_flow(graph, evaluation.REFERENCE_SOURCES, 0, exact_up_to=traffic.EXACT_NODES,
                                ties=evaluation.REFERENCE_TIES, scaling=evaluation.REFERENCE_SCALING)
    by_polygon = np.full(navmesh.polygon_count, np.nan)
    kept = [p for p in range(navmesh.polygon_count) if p in graph]
    by_polygon[kept] = flow[arrays.rows(kept)]
    polygon = evaluation.polygons_under(navmesh, cells)
    return Tessellated(navmesh, cells, polygon, np.where(polygon >= 0, by_polygon[np.maximum(polygon, 0)], np.nan))


def _cross(origin: np.ndarray, a: np.ndarray, b: np.ndarray) -> float:
    """Twice the signed plan area of (origin, a, b) (Detour's ``dtTriArea2D``: positive clockwise seen from +Y)."""
    return (b[0] - origin[0]) * (a[2] - origin[2]) - (a[0] - origin[0]) * (b[2] - origin[2])


def funnel(start: np.ndarray, end: np.ndarray, lefts: np.ndarray, rights: np.ndarray) -> np.ndarray:
    """(k,3) the string-pulled path from ``start`` to ``end`` through the (n,3) portals ``lefts`` -> ``rights``
    (left and right as seen walking along the corridor), each crossing of a portal a point of the path (its height
    read along the portal), so that consecutive points lie in one polygon: the simple stupid funnel algorithm
    (Mononen 2010), O(n) amortised per restart, O(n^2) at worst."""
    lefts = np.vstack([lefts, end])
    rights = np.vstack([rights, end])
    corners, corner_portals = [start], [-1]
    apex, apex_index = start, -1
    sides = [(start, -1), (start, -1)]  # the funnel's left and right edges: (point, portal)
    i = 0
    while i < len(lefts):
        restarted = False
        # the right side, then the left: the same rule mirrored (the sign of every area flips)
        for side, sign, news in ((1, 1.0, rights), (0, -1.0, lefts)):
            (point, _), (other, other_index) = sides[side], sides[1 - side]
            if sign * _cross(apex, point, news[i]) > 0.0:
                continue  # this side widens: no change
            if np.array_equal(apex, point) or sign * _cross(apex, other, news[i]) > 0.0:
                sides[side] = (news[i], i)  # it tightens
                continue
            # it crosses the other side: that side's point is a corner, and the funnel starts again there
            corners.append(other)
            corner_portals.append(other_index)
            apex, apex_index = other, other_index
            sides = [(apex, apex_index), (apex, apex_index)]
            i = apex_index + 1
            restarted = True
            break
        if not restarted:
            i += 1
    corners.append(end)
    corner_portals.append(len(lefts) - 1)
    path = [start]
    for (a, first), (b, last) in zip(zip(corners, corner_portals), zip(corners[1:], corner_portals[1:])):
        for portal in range(first + 1, last):  # the portals this straight leg crosses
            path.append(_crossing(a, b, lefts[portal], rights[portal]))
        path.append(b)
    return np.array(path)


def _crossing(a: np.ndarray, b: np.ndarray, left: np.ndarray, right: np.ndarray) -> np.ndarray:
    """The point where the plan segment a-b crosses the portal left-right, its height read along the portal."""
    direction, edge = (b - a)[[0, 2]], (right - left)[[0, 2]]
    denominator = direction[0] * edge[1] - direction[1] * edge[0]
    if abs(denominator) < 1e-12:
        return 0.5 * (left + right)
    offset = (left - a)[[0, 2]]
    t = float(np.clip((direction[1] * offset[0] - direction[0] * offset[1]) / denominator, 0.0, 1.0))
    return left + t * (right - left)


def densified(path: np.ndarray) -> np.ndarray:
    """(k,3) points along the (p,3) polyline ``path`` (p >= 2) at most :data:`PATH_STEP` apart in plan, heights
    linear."""
    starts, ends = path[:-1], path[1:]
    steps = np.maximum(1, np.ceil(np.hypot(*(ends - starts)[:, [0, 2]].T) / PATH_STEP)).astype(np.int64)
    segment = np.repeat(np.arange(len(starts)), steps)
    along = (np.arange(steps.sum()) - np.repeat(np.cumsum(steps) - steps, steps) + 1) / np.repeat(steps, steps)
    return np.vstack([path[:1], starts[segment] + along[:, None] * (ends - starts)[segment]])


def pulled_flow(tessellated: Tessellated, origins: np.ndarray, destinations: np.ndarray) -> np.ndarray:
    """(M,) per raster cell, the walkers of the pairs of (S,) ``origins`` and each one's (S,T) ``destinations``
    (cell indices) whose string-pulled path passes within :data:`WALKER_REACH` of it (see the module docs); pairs
    in different connected areas, or with a cell on no polygon, walk nowhere."""
    navmesh, cells, polygon = tessellated.navmesh, tessellated.cells, tessellated.polygon
    portals = navmesh.portals()
    centres = navmesh.centres
    a, b = portals.pairs[:, 0], portals.pairs[:, 1]
    lengths = np.maximum(np.linalg.norm(centres[b] - centres[a], axis=1), 1e-9)
    count = navmesh.polygon_count
    adjacency = coo_array((np.concatenate([lengths, lengths]), (np.concatenate([a, b]), np.concatenate([b, a]))),
                          shape=(count, count)).tocsr()
    shared = {(int(p), int(q)): ends for p, q, ends in zip(a, b, portals.endpoints)}
    tree = cKDTree(scaled(cells))
    walkers = np.zeros(len(cells))
    on = polygon[origins] >= 0
    origins, destinations = origins[on], destinations[on]
    _, predecessors = csgraph.dijkstra(adjacency, indices=polygon[origins], return_predecessors=True)
    for row, origin in enumerate(origins):
        paths = []
        for destination in destinations[row]:
            corridor = [int(polygon[destination])]
            if corridor[0] < 0:
                continue
            while corridor[-1] != polygon[origin] and corridor[-1] >= 0:
                corridor.append(int(predecessors[row, corridor[-1]]))
            if corridor[-1] < 0:
                continue  # another connected area
            corridor.reverse()
            lefts, rights = [], []
            for p, q in zip(corridor[:-1], corridor[1:]):
                ends = shared[(min(p, q), max(p, q))]
                e0, e1 = ends if p < q else ends[::-1]
                # left and right as seen from p's centre towards q's: the end with the positive area is the right one
                right_first = _cross(centres[p], e1, e0) > 0.0
                lefts.append(e1 if right_first else e0)
                rights.append(e0 if right_first else e1)
            paths.append(densified(funnel(cells[origin], cells[destination], np.array(lefts).reshape(-1, 3),
                                          np.array(rights).reshape(-1, 3))))
        if paths:  # one k-d tree query for the origin's paths; each walker counts once on a cell
            reached = tree.query_ball_point(scaled(np.concatenate(paths)), WALKER_REACH, return_sorted=False)
            counts = np.fromiter(map(len, reached), dtype=np.int64, count=len(reached))
            hits = np.fromiter(itertools.chain.from_iterable(reached), dtype=np.int64, count=int(counts.sum()))
            walker = np.repeat(np.repeat(np.arange(len(paths)), [len(p) for p in paths]), counts)
            walkers += np.bincount(np.unique(walker * len(cells) + hits) % len(cells), minlength=len(cells))
    return walkers


def rho(x: np.ndarray, y: np.ndarray) -> float:
    """Spearman rho of (M,) ``x`` and ``y`` over the cells where both are finite (NaN when undefined)."""
    ok = np.isfinite(x) & np.isfinite(y)
    return evaluation.spearman(np.where(ok, x, np.nan), np.where(ok, y, 0.0))


def node_positions(result: RunResult) -> np.ndarray:
    """(n,3) the ``pos`` of each node of the run's initial graph, in surface-array order."""
    graph = result.graph
    return np.array([graph.nodes[node]["pos"] for node in traffic.surface_arrays(graph).nodes]).reshape(-1, 3)


def on_raster_by_sample(values: np.ndarray, positions: np.ndarray, cells: np.ndarray, reach: float) -> np.ndarray:
    """(M,) each cell the value of the nearest of the (n,3) ``positions`` with a finite value (heights scaled by
    :data:`HEIGHT_SCALE`) within ``reach`` metres (NaN: none)."""
    valued = np.isfinite(values)
    distance, nearest = cKDTree(scaled(positions[valued])).query(scaled(cells))
    return np.where(distance <= reach, values[valued][np.minimum(nearest, valued.sum() - 1)], np.nan)


def heat(result: RunResult) -> np.ndarray:
    """(n,) the run's heat map on its initial graph (first analyzer, nearest structure node)."""
    first = next(iter(result.analysis.values()))
    return evaluation.heat_map(result.graph, result.structure, first)


def measure(job: tuple[str, trimesh.Trimesh, float, tuple[int, int], tuple[int, int]]) -> list[str]:
    """The table's lines for one level (see the module docs)."""
    name, mesh, cell, (sources, targets), (few_sources, few_targets) = job
    started = time.process_time()
    registry = Registry.from_entry_points()
    runs = {}
    for preset in PRESETS:
        config = parse_config(load_raw_config(find_config(preset)), preset)
        runs[preset] = pipeline.run(pipeline.plan(config, registry, preset), registry, mesh, name, mesh_sha256(mesh))
    presets_done = time.process_time()
    agent = runs["map_analysis_sampling"].context.agent
    default_navmesh = build_navmesh(mesh.vertices, mesh.faces, agent,
                                    navmesh_builder.Params(ledge_filter=evaluation.REFERENCE_LEDGE_FILTER))
    raster = floor_raster(default_navmesh, cell)
    rng = np.random.default_rng(0)
    origins, destinations = rng.choice(len(raster), sources), rng.choice(len(raster), (sources, targets))
    tessellations = {t: tessellate(mesh, agent, raster, parameters, yaw)
                     for t, (parameters, yaw) in TESSELLATIONS.items()}
    tessellated_done = time.process_time()
    base, base_pulled = tessellations["default"].poly_flow, pulled_flow(tessellations["default"], origins, destinations)
    few = (origins[:few_sources], destinations[:few_sources, :few_targets])
    pulled = {t: pulled_flow(tessellated, *few) for t, tessellated in tessellations.items()}
    sampling = runs["map_analysis_sampling"]
    spacing = sampling.graph.graph.get("sampling_stats", {}).get("spacing", 2.0 * float(agent.radius))
    reach = evaluation.REACH_SPACINGS * spacing
    positions = node_positions(sampling)
    own_flow = evaluation.reference_flow(sampling)
    sampled = on_raster_by_sample(np.asarray(own_flow, dtype=np.float64), positions, raster, reach)
    other_origins, other_destinations = (np.random.default_rng(1).choice(len(raster), n)
                                         for n in (sources, (sources, targets)))
    reliability = rho(pulled_flow(tessellations["default"], other_origins, other_destinations), base_pulled)
    navmesh_run = runs["map_analysis"]
    navmesh_heat = heat(navmesh_run)
    rows = traffic.surface_arrays(navmesh_run.graph).rows
    under = evaluation.polygons_under(navmesh_run.context.navmesh, raster)
    by_polygon = np.full(navmesh_run.context.navmesh.polygon_count, np.nan)
    kept = [p for p in range(len(by_polygon)) if p in navmesh_run.graph]
    by_polygon[kept] = navmesh_heat[rows(kept)]
    quality = evaluation.evaluate(sampling, reference=own_flow)

    def row(label: str, nodes: str, values: np.ndarray, pulled_values: str = "", note: str = "", own: str = "") -> str:
        others = [rho(values, tessellations[t].poly_flow) for t in tessellations if t not in ("default", own)]
        against_pulled = rho(values, base_pulled)
        return (f"{name:<16} {label:<22} {nodes:>6} {rho(values, base):7.3f} {min(others):6.3f}-{max(others):5.3f} "
                f"{against_pulled:7.3f} {against_pulled / math.sqrt(reliability):7.3f} {pulled_values:>7} "
                f"{rho(values, sampled):7.3f}  {note}")

    lines = [f"{name:<16} {'raster':<22} cells {len(raster)} ({cell:g} m), pairs {sources} x {targets}, "
             f"pulled against another draw of as many pairs {reliability:.3f}"]
    for t, tessellated in tessellations.items():
        lines.append(row(f"poly {t}", str(tessellated.navmesh.polygon_count), tessellated.poly_flow,
                         f"{rho(pulled[t], pulled['default']):.3f}", own=t))
    lines.append(row("sampled flow", str(len(positions)), sampled))
    lines.append(row("heat map_analysis", "", np.where(under >= 0, by_polygon[np.maximum(under, 0)], np.nan)))
    lines.append(row("heat map_analysis_sampling", "", on_raster_by_sample(heat(sampling), positions, raster, reach),
                     note=f"issue's rho: own graph {quality.rho:.3f}, navmesh {quality.rho_navmesh:.3f}"))
    lines.append(f"{name:<16} cpu {time.process_time() - started:.1f} s: presets {presets_done - started:.1f} s, "
                 f"navmeshes and their flows on the raster {tessellated_done - presets_done:.1f} s")
    return lines


def jobs(names: list[str], seeds: list[int], cell: float, pairs: tuple[int, int],
         stability_pairs: tuple[int, int]) -> Iterator[tuple]:
    for name, mesh in levels(names, seeds):
        yield name, mesh, cell, pairs, stability_pairs


def main(argv: list[str] | None = None) -> None:
    """The table for ``argv`` (the command line when None)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                     epilog="columns (Spearman rho on the raster): v poly, against the default "
                                            "navmesh's reference; v other poly, the lowest and highest against the "
                                            "other tessellations'; v pull, against the default's string-pulled "
                                            "flow; v pull*, that over the square root of the pulled flow's "
                                            "agreement with another draw of pairs (corrected for its noise, "
                                            "Spearman 1904); pull v, that tessellation's pulled flow against the "
                                            "default's (the same --stability-pairs); v samp, against the sampled "
                                            "graph's flow")
    parser.add_argument("--levels", nargs="+", default=["nav_test", "dungeon_1k", "terrain_1k", "castle_1k", "market"],
                        help="as benchmarks/analysis_quality.py's --levels")
    parser.add_argument("--seeds", nargs="+", type=int, default=[0, 1], help="seeds of the generated levels")
    parser.add_argument("--cell", type=float, default=0.25, help="raster cell side, m")
    parser.add_argument("--pairs", nargs=2, type=int, default=[1024, 16], metavar=("S", "T"),
                        help="origin cells of the string-pulled flow and destination cells of each")
    parser.add_argument("--stability-pairs", nargs=2, type=int, default=[256, 16], metavar=("S", "T"),
                        help="the first S of those origins and T of each one's destinations: the pairs walked under "
                             "every tessellation")
    parser.add_argument("--jobs", type=int, default=1, help="levels measured at once (processes)")
    args = parser.parse_args(argv)
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f}")
    print(f"{'level':<16} {'flow':<22} {'nodes':>6} {'v poly':>7} {'v other poly':>12} {'v pull':>7} {'v pull*':>7} "
          f"{'pull v':>7} {'v samp':>7}")
    work = jobs(args.levels, args.seeds, args.cell, tuple(args.pairs), tuple(args.stability_pairs))
    if args.jobs == 1:
        results = map(measure, work)
    else:
        results = multiprocessing.get_context("spawn").Pool(args.jobs).imap(measure, work)
    for lines in results:
        print("\n".join(lines), flush=True)


if __name__ == "__main__":
    main()
