"""How well map-analysis presets show where people walk (issue 9's measures).

Run: ``.venv/bin/python benchmarks/analysis_quality.py [--presets map_analysis_paper map_analysis my.yaml]
[--levels nav_test samples dungeon_1k dungeon_20k dungeon_100k terrain_1k terrain_20k building_1k building_20k
castle_1k castle_20k subway archipelago car_park forest stadium harbour school cathedral mine ship village market
office airport sewer lanes prison museum my_level.obj]
[--seeds 0 1 2] [--yaws 0 30 45]``

For every level and preset it runs the preset with the ``traffic`` evaluator
added (the evaluator plugin any config or ``g2s batch --evaluate traffic``
uses, on :mod:`g2s_plugins.evaluation`) and prints its measures: share of the walkable area within 3 / 6 / 10 m
of the structure (along the initial graph), share of the reference traffic
(area-weighted origin-destination flow on the initial graph) passing more
than 5 m from it, Spearman rho of the heat map (first analyzer, each polygon
given the value of its nearest structure node), the same with every polygon
weighted by its area ("rho_a", :func:`g2s_plugins.evaluation.weighted_spearman`), of area-weighted
betweenness on the structure and of the best values the structure's nodes
could carry (the ceiling: the mean traffic of the polygons each stands
for) against that traffic, the same heat map and ceiling against the
reference traffic on the level's navmesh graph ("rho nav", "ceil nav": the
run's own graph on the navmesh route, the heat map carried from the samples
to the polygons on the sampling route) and the share of the navmesh's area
left out of them ("nav out"), the structure's size as
a share of the polygons, the run's CPU time (``time.process_time``: the
machine is shared; the evaluation included), the wall time of every stage
but the evaluation ("total s") and that of the evaluation, which computes
the reference flow (exact up to 2,000 nodes, :data:`g2s_plugins.traffic.EXACT_NODES`; 512 area-sampled sources
above, linearly scaled since 5 December 2026; exact up to 512 before 4 December 2026)
for each run, the number of navmesh regions left overlapping themselves in plan
("overlap", :attr:`g2s_plugins.recast.NavMesh.region_overlaps`) and of tiles the
``auto`` partition rebuilt because watershed overlapped there ("redone",
:attr:`g2s_plugins.recast.NavMesh.repartitioned_tiles`) and of polygons whose
detail heights Recast read from another storey, rebuilt ("detail",
:attr:`g2s_plugins.recast.NavMesh.detail_redone_polygons`; all three "-" without a
navmesh) and, last (after the columns of earlier versions of the table, which keep their places), rho and the
ceiling within each connected area ("rho in", "ceil in": ranks taken within each area, so the order between areas,
which an area apart gets right trivially, does not count; ``rho_within``, ``rho_within_ceiling``) and the number of
connected areas of the run's graph ("areas", :func:`g2s_plugins.evaluation.area_labels`: more than one where the
walkable floor falls apart, e.g. a corridor the navmesh's erosion cuts). ``--presets``
takes preset names or config files (a file extending a preset with other parameters; one whose graph builder names
``play_points`` is measured over its play space alone, "polys" counting its polygons); ``--levels`` also takes mesh files (any format
``g2s run`` reads, Y-up metres), so the same table can be made for levels of
one's own, and the level kinds of ``benchmarks/level_kinds.py``, ``level_kinds26.py``, ``level_kinds27.py``, ``level_kinds28.py``, ``level_kinds29.py``, ``level_kinds30.py``, ``level_kinds31.py``, ``level_kinds32.py``, ``level_kinds33.py``, ``level_kinds34.py``, ``level_kinds35.py``, ``level_kinds36.py``, ``level_kinds37.py``, ``level_kinds38.py`` and ``level_kinds39.py`` (each built with ``seed=s``); ``--yaws`` runs every level also turned by those angles (degrees,
about the vertical axis through the centre of its bounds), to check that the
figures do not depend on how a level lies in its frame. This is a benchmark: nothing here asserts a target.
"""

from __future__ import annotations

import argparse
import os
import platform
import time
from collections.abc import Iterator
from pathlib import Path

import trimesh
from level_kinds import KINDS as EARLIER_KINDS
from level_kinds26 import KINDS as ROUND_26_KINDS
from level_kinds27 import KINDS as ROUND_27_KINDS
from level_kinds28 import KINDS as ROUND_28_KINDS
from level_kinds29 import KINDS as ROUND_29_KINDS
from level_kinds30 import KINDS as ROUND_30_KINDS
from level_kinds31 import KINDS as ROUND_31_KINDS
from level_kinds32 import KINDS as ROUND_32_KINDS
from level_kinds33 import KINDS as ROUND_33_KINDS
from level_kinds34 import KINDS as ROUND_34_KINDS
from level_kinds35 import KINDS as ROUND_35_KINDS
from level_kinds36 import KINDS as ROUND_36_KINDS
from level_kinds37 import KINDS as ROUND_37_KINDS
from level_kinds38 import KINDS as ROUND_38_KINDS
from level_kinds39 import KINDS as ROUND_39_KINDS

from g2s_core import pipeline
from g2s_core.config import find_config, load_raw_config, parse_config
from g2s_core.errors import G2SError
from g2s_core.mesh import load_mesh, mesh_sha256
from g2s_core.registry import Registry
from g2s_plugins import evaluation, traffic
from g2s_plugins.batch.runner import with_evaluators
from g2s_plugins.samples import levels as samples
from g2s_plugins.samples.pieces import yaw_about_centre

NAV_TEST = Path(__file__).resolve().parents[1] / ".." / "shared" / "data" / "nav_test.obj"
DUNGEONS = {"dungeon_1k": 115, "dungeon_20k": 2400, "dungeon_100k": 12000}
"""Generated dungeons: name -> rooms (about 8.5 navmesh polygons per room)."""

FAMILIES = {
    "terrain_1k": ("terrain", {"size": 165.0}),
    "terrain_20k": ("terrain", {"size": 720.0}),
    "building_1k": ("building", {"floors": 4, "rooms": 40, "stairwells": 2}),
    "building_20k": ("building", {"floors": 12, "rooms": 280, "stairwells": 6}),
    "castle_1k": ("castle", {"bridges": 2}),
    "castle_20k": ("castle", {"towers": 24, "size": 520.0, "statues": 20.0, "keep_storeys": 6, "bridges": 4}),
}
"""Other level families: name -> (sample, arguments), each level built with ``seed=s``. About 1k / 20k navmesh
polygons with the default agent (seed 0: terrain 931 / 19,864, building 959 / 19,719, castle 1,079 / 20,038 with
the default watershed partition; other seeds within a few per cent, castle 1k 996-1,079); the other arguments
are the generators' defaults."""

KINDS = {**EARLIER_KINDS, **ROUND_26_KINDS, **ROUND_27_KINDS, **ROUND_28_KINDS, **ROUND_29_KINDS, **ROUND_30_KINDS,
         **ROUND_31_KINDS, **ROUND_32_KINDS, **ROUND_33_KINDS, **ROUND_34_KINDS,
         **ROUND_35_KINDS, **ROUND_36_KINDS, **ROUND_37_KINDS, **ROUND_38_KINDS, **ROUND_39_KINDS}
"""Every held-out level kind: name -> generator (seed -> Y-up mesh in metres), rounds 5-25 (``level_kinds.py``), 26
(``level_kinds26.py``), 27 (``level_kinds27.py``), 28 (``level_kinds28.py``), 29 (``level_kinds29.py``), 30
(``level_kinds30.py``), 31 (``level_kinds31.py``), 32 (``level_kinds32.py``), 33 (``level_kinds33.py``), 34
(``level_kinds34.py``), 35 (``level_kinds35.py``), 36 (``level_kinds36.py``), 37 (``level_kinds37.py``), 38 (``level_kinds38.py``) and 39
(``level_kinds39.py``)."""

SAMPLE_LEVELS = ("cross_hub", "t_hub", "two_floors", "closed_room", "room_with_window", "corridor_with_ramp")


def levels(names: list[str], seeds: list[int]) -> Iterator[tuple[str, trimesh.Trimesh]]:
    for name, mesh, _ in levels_with_metadata(names, seeds):
        yield name, mesh


def levels_with_metadata(names: list[str], seeds: list[int]) -> Iterator[tuple[str, trimesh.Trimesh, dict]]:
    """Each level of ``names`` (see ``--levels``) with its generator's metadata (``{}`` for mesh files)."""
    for name in names:
        if name == "nav_test":
            yield name, load_mesh(NAV_TEST)[0], {}
        elif name == "samples":
            for sample in SAMPLE_LEVELS:
                level = samples.load_sample(sample)
                yield sample, level.mesh, level.metadata
        elif name in DUNGEONS:
            for seed in seeds:
                level = samples.dungeon(seed=seed, rooms=DUNGEONS[name])
                yield f"{name}_s{seed}", level.mesh, level.metadata
        elif Path(name).is_file():
            yield Path(name).stem, load_mesh(Path(name))[0], {}
        elif name in KINDS:
            for seed in seeds:
                yield f"{name}_s{seed}", KINDS[name](seed), {}
        elif name in FAMILIES:
            sample, arguments = FAMILIES[name]
            for seed in seeds:
                level = samples.load_sample(sample, seed=seed, **arguments)
                yield f"{name}_s{seed}", level.mesh, level.metadata
        else:
            level = samples.load_sample(name)
            yield name, level.mesh, level.metadata


def turned(named_meshes: Iterator[tuple[str, trimesh.Trimesh]], yaws: list[float]) -> Iterator[tuple[str, trimesh.Trimesh]]:
    """Each level turned by each of ``yaws`` (degrees, :func:`g2s_plugins.samples.pieces.yaw_about_centre`)."""
    for name, mesh in named_meshes:
        for yaw in yaws:
            yield (name, mesh) if yaw == 0 else (f"{name}_yaw{yaw:g}", mesh.copy().apply_transform(yaw_about_centre(mesh, yaw)))


def main(argv: list[str] | None = None, registry: Registry | None = None) -> None:
    """The table for ``argv`` (the command line when None), with ``registry`` (the installed plugins when None)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--presets", nargs="+", default=["map_analysis_paper", "map_analysis"])
    parser.add_argument("--levels", nargs="+", default=["nav_test", "samples", "dungeon_1k", "dungeon_20k"],
                        help="nav_test, samples, a sample name, dungeon_1k, dungeon_20k, dungeon_100k, "
                             "terrain_1k, terrain_20k, building_1k, building_20k, castle_1k, castle_20k, a kind of benchmarks/level_kinds.py, level_kinds26.py, level_kinds27.py, level_kinds28.py, level_kinds29.py, level_kinds30.py, level_kinds31.py, level_kinds32.py, level_kinds33.py, level_kinds34.py, level_kinds35.py, level_kinds36.py, level_kinds37.py, level_kinds38.py or level_kinds39.py "
                             f"({', '.join(KINDS)}), or a mesh file (Y-up, metres)")
    parser.add_argument("--seeds", nargs="+", type=int, default=[0], help="seeds of the generated levels")
    parser.add_argument("--yaws", nargs="+", type=float, default=[0.0],
                        help="degrees: run every level also turned by these angles about the vertical axis")
    args = parser.parse_args(argv)
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f}")
    registry = registry or Registry.from_entry_points()
    plans = {Path(p).stem: pipeline.plan(parse_config(with_evaluators(load_raw_config(find_config(p)), ["traffic"]), p),
                                         registry, p) for p in args.presets}
    header = (f"{'level':<18} {'preset':<28} {'polys':>7} {'<=3m':>6} {'<=6m':>6} {'<=10m':>6} {'off>5m':>7} "
              f"{'rho':>6} {'rho_a':>6} {'rho_abw':>7} {'ceiling':>7} {'rho nav':>7} {'ceil nav':>8} {'nav out':>7} {'struct':>7} {'overlap':>7} {'redone':>6} {'detail':>6} {'cpu s':>7} {'total s':>8} {'eval s':>7} {'rho in':>6} {'ceil in':>7} {'areas':>5}  stages (s)")
    print(header)
    for name, mesh in turned(levels(args.levels, args.seeds), args.yaws):
        for preset, plan in plans.items():
            cpu = time.process_time()
            try:
                result = pipeline.run(plan, registry, mesh, name, mesh_sha256(mesh))
            except G2SError as error:  # a level the preset cannot run (e.g. no walkable surface): say so, go on
                print(f"{name:<18} {preset:<28} error: {error}", flush=True)
                continue
            cpu = time.process_time() - cpu
            if "traffic" not in result.metrics:  # the run stopped before the evaluation (e.g. no terminals)
                print(f"{name:<18} {preset:<28} stopped after {result.stages[-1].stage}: {'; '.join(result.warnings)}")
                continue
            q = result.metrics["traffic"]
            seconds = {s.stage: s.seconds for s in result.stages}
            evaluating = seconds.pop("evaluation")
            stages = " ".join(f"{k}={v:.2f}" for k, v in seconds.items())
            within = " ".join(f"{100 * q[f'area_within_{r:g}m']:5.1f}%" for r in evaluation.RADII)
            rho, rho_area, abw, ceiling, rho_in, ceiling_in, rho_nav, ceiling_nav, nav_out = (
                q.get(k, float("nan")) for k in ("rho", "rho_area", "rho_area_betweenness", "rho_ceiling", "rho_within",
                                                 "rho_within_ceiling", "rho_navmesh", "rho_navmesh_ceiling",
                                                 "navmesh_area_left_out"))
            polygons = traffic.surface_arrays(result.graph).n  # the nodes the measures count (the play space's, when named)
            areas = int(evaluation.area_labels(result.graph).max(initial=-1)) + 1
            navmesh = result.context.navmesh
            overlaps, redone, detail = ("-", "-", "-") if navmesh is None else (
                len(navmesh.region_overlaps), len(navmesh.repartitioned_tiles), len(navmesh.detail_redone_polygons))
            print(f"{name:<18} {preset:<28} {polygons:>7} {within} {100 * q['traffic_off']:6.1f}% "
                  f"{rho:6.3f} {rho_area:6.3f} {abw:7.3f} {ceiling:7.3f} {rho_nav:7.3f} {ceiling_nav:8.3f} {100 * nav_out:6.1f}% "
                  f"{100 * q['structure_share']:6.1f}% "
                  f"{overlaps:>7} {redone:>6} {detail:>6} {cpu:7.2f} {sum(seconds.values()):8.2f} {evaluating:7.2f} {rho_in:6.3f} {ceiling_in:7.3f} {areas:5d}  {stages}", flush=True)


if __name__ == "__main__":
    main()
