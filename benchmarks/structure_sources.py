"""Where the navmesh route's structure nodes come from, and what each lever that removes them costs.

Run: ``.venv/bin/python benchmarks/structure_sources.py [--preset map_analysis] [--levels nav_test dungeon_1k hotel
...] [--seeds 0 1 2] [--terminal-levers preset "radius 8 m" ...] [--jsonl OUT.jsonl]``

For every level (the names ``benchmarks/analysis_quality.py`` takes) it runs ``--preset`` (a ``coverage`` terminal
selector and a ``surface_los`` simplification, as ``map_analysis``) in memory and prints two tables.

**Sources** (counts, and shares of the polygon count). Each node of the final structure is put in one row by where
it entered the forest: a seeded leaf (a terminal simplification never removes; ``dents kept`` counts those whose
dead end lies within ``dent_depth`` of its way in, :func:`g2s_plugins.terminals.coverage.dead_end_depths`), a
waypoint of the traffic-aware cover (the seeds of areas without a leaf among them), a waypoint of the plain cover,
a Steiner node (on the Steiner forest, no terminal) or a loop node (on a loop path the ``loops`` stage added); and in
one column by the last of these simplifications, each adding one test to the one before, whose structure before it
does not hold it (``always`` when every one holds it):
``always`` (Algorithm 4 removing every node it may: the leaves, terminals and loop ends, which no predicate removes),
``raycast`` (Algorithm 5 with Detour's raycast alone: no surface gap, normal test, traffic step or guarantee),
``+surface`` (the preset's ``max_surface_gap``: the line of sight ``surface_los`` asks), ``+normals``
(the preset's ``normal_tolerance_deg``), ``+traffic`` (its ``max_traffic_step``) and ``+guarantee`` (its
``min_heat_rho``: the preset itself; its rounds are counted). Algorithm 4 is greedy, so a later structure need not
hold an earlier one's nodes (a node the guarantee restores may be one ``raycast`` keeps); ``sizes`` gives every
structure's size. The seeded leaves the preset's
``quiet_step`` and ``dent_rho_budget`` dropped are counted apart.

**Front**: the share of the polygons each lever keeps against rho, the area within 6 m and the traffic more than 5 m
away (:func:`g2s_plugins.evaluation.evaluate`, the ``traffic`` evaluator's measures, against one reference flow per
level), for the terminals of the preset, of the preset with every dent the cover holds dropped
(``dent_rho_budget: 1``), with every leaf the cover holds dropped as well (``quiet_step: 100``), with the plain cover
alone (``traffic_weight: 0``), with a cover radius of 8 m and with the leaves alone (every leaf seeded, no cover:
an unbounded radius, no traffic weight, no dead-end places, quiet dead ends or dents; a seed per area without a
leaf), the terminals that any choice of the cover's waypoints adds to, each simplified as above and with the traffic step or
the guarantee alone left out; then the lowest share of a point that meets rho >= 0.9, 95 % within 6 m and at most
5 % of the traffic more than 5 m away, and the highest rho of a point at 35 % or under (``always`` and ``raycast``
left out of both: their edges need not stay on the walkable surface). The simplification levers also drop the
structure's leaves that are no terminal (``surface_los``'s ``leaf_cover_radius``, :mod:`g2s_plugins.structure_leaves`),
holding every node within the cover's radius and 5 m of the structure, the radius alone, or nothing (a bound);
``--terminal-levers`` runs only the terminal levers named (the preset's always runs).

This is a benchmark: nothing here asserts a target (docs/analysis_quality.md, "Where the structure's nodes come
from").
"""

from __future__ import annotations

import argparse
import copy
import json
import os
import time
from collections.abc import Callable, Collection
from typing import Any

import networkx as nx
import numpy as np
import trimesh
from analysis_quality import levels

from g2s_core import pipeline
from g2s_core.config import find_config, load_raw_config, parse_config
from g2s_core.mesh import mesh_sha256
from g2s_core.model import AnalyzerResult, RunResult
from g2s_core.registry import Registry
from g2s_core.simplify import simplify_forest
from g2s_plugins import evaluation, traffic
from g2s_plugins.predicates import surface_los
from g2s_plugins.terminals import coverage

SIMPLIFICATIONS: dict[str, dict[str, Any] | None] = {
    "always": None,
    "raycast": {"max_surface_gap": None, "normal_tolerance_deg": 180.0, "max_traffic_step": None, "min_heat_rho": None},
    "+surface": {"normal_tolerance_deg": 180.0, "max_traffic_step": None, "min_heat_rho": None},
    "+normals": {"max_traffic_step": None, "min_heat_rho": None},
    "+traffic": {"min_heat_rho": None},
    "+guarantee": {},
}
"""Each simplification, as the parameters of the preset's ``surface_los`` it changes (``None``: every removable node
goes, no predicate), each adding one test to the one before."""

LEVERS: dict[str, dict[str, Any] | None] = {
    "no traffic step": {"max_traffic_step": None},
    "no guarantee": {"min_heat_rho": None},
    "leaves dropped": {"leaf_cover_radius": "cover"},
    "leaves dropped, radius only": {"leaf_cover_radius": "cover", "leaf_near_distance": "cover"},
    "leaves dropped, unbounded": {"leaf_cover_radius": 1e9, "leaf_near_distance": 1e9},
}
"""Further simplifications of the front: the preset with one test left out, or with the structure's leaves that are
no terminal dropped (``leaf_cover_radius``, :mod:`g2s_plugins.structure_leaves`) where every node within the cover's
radius (``"cover"``: the run's ``coverage`` radius) and 5 m of the structure stays so, within the radius alone, or
everywhere (a bound: no distance held)."""

TERMINAL_LEVERS: dict[str, dict[str, Any]] = {
    "preset": {},
    "dents all dropped": {"dent_rho_budget": 1.0},
    "held leaves dropped": {"dent_rho_budget": 1.0, "quiet_step": 100.0},
    "plain cover": {"traffic_weight": 0.0},
    "radius 8 m": {"radius": 8.0},
    "leaves alone": {"radius": 1e9, "traffic_weight": 0.0, "dead_end_radii": 0.0, "quiet_step": 0.0, "dent_rho_budget": 0.0},
}
"""The terminal selections of the front, as the parameters of the preset's ``coverage`` they change."""

ORIGINS = ("leaf", "traffic cover", "plain cover", "steiner", "loop")


def plan_with(raw: dict, preset: str, terminals: dict[str, Any], registry: Registry) -> pipeline.Plan:
    """The plan of ``raw`` (the preset's raw config) with ``terminals`` set among ``coverage``'s parameters."""
    raw = copy.deepcopy(raw)
    raw["terminals"].setdefault("params", {}).update(terminals)
    return pipeline.plan(parse_config(raw, preset), registry, preset)


def simplified(result: RunResult, params: surface_los.Params | None) -> tuple[nx.DiGraph, int]:
    """``result``'s forest simplified with ``surface_los`` of ``params`` (the pipeline's rounds: the guarantee asks
    again until it keeps a structure), or with every removable node removed when ``params`` is None; and the rounds."""
    forest = result.forest
    if params is None:
        return simplify_forest(forest, lambda tree, a, b, c: True), 1
    structure, rounds = None, 0
    while (predicate := surface_los.g2s_simplify_predicate(params=params, context=result.context, forest=forest,
                                                          simplified=structure)) is not None:
        structure, rounds = simplify_forest(forest, predicate), rounds + 1
    return structure, rounds


def origins(result: RunResult, params: coverage.Params) -> tuple[dict[int, str], set[int], dict[str, int]]:
    """Each forest node's origin (:data:`ORIGINS`), the seeded leaves whose dead end is a dent, and the leaves the
    preset's ``quiet_step`` and dents dropped (``{"quiet": k, "dents": k}``)."""
    graph, context = result.graph, result.context
    chosen = coverage.cover(graph, params, context)
    nodes = chosen.arrays.nodes
    leaves = {nodes[i] for i in chosen.leaves.tolist()}
    traffic_cover = {nodes[i] for i in chosen.traffic.tolist()} - leaves
    plain = {nodes[i] for i in chosen.rows.tolist()} - leaves - traffic_cover
    assert leaves | traffic_cover | plain == set(result.terminals.nodes), "the cover differs from the run's"
    origin: dict[int, str] = {}
    for node in result.forest:
        origin[node] = ("leaf" if node in leaves else "traffic cover" if node in traffic_cover else
                        "plain cover" if node in plain else "steiner" if node in result.steiner else "loop")
    dents: set[int] = set()
    if params.dent_depth > 0 and context.navmesh is not None:
        depths, _ = coverage.dead_end_depths(graph, context.navmesh, chosen.arrays, chosen.leaves)
        dents = {nodes[i] for i, depth in zip(chosen.leaves.tolist(), depths.tolist()) if depth <= params.dent_depth}
    every = coverage.cover(graph, params.model_copy(update={"quiet_step": 0.0, "dent_rho_budget": 0.0}), context)
    loud = coverage.cover(graph, params.model_copy(update={"dent_rho_budget": 0.0}), context)
    dropped = {"quiet": len(every.leaves) - len(loud.leaves), "dents": len(loud.leaves) - len(chosen.leaves)}
    return origin, dents, dropped


def measures(result: RunResult, structure: nx.DiGraph, plan: pipeline.Plan, registry: Registry,
             reference: np.ndarray) -> dict[str, float]:
    """The traffic evaluator's measures of ``result`` with ``structure`` in place of its own, its analyzers run
    again on it."""
    trial = copy.copy(result)
    trial.structure, trial.analysis = structure, {}
    undirected = structure.to_undirected(as_view=True)
    for analyzer in plan.stages["analyzers"]:
        values = registry.call(analyzer.plugin, params=analyzer.params, structure=undirected, context=result.context)
        if isinstance(values, AnalyzerResult):
            values = values.values
        trial.analysis[analyzer.key] = {n: float(values[n]) for n in structure}
    quality = evaluation.evaluate(trial, reference)
    return {"share": quality.structure_share, "rho": quality.rho, "within_6m": quality.area_within[6.0],
            "traffic_off": quality.traffic_off}


def level_report(name: str, mesh: trimesh.Trimesh, raw: dict, preset: str, registry: Registry,
                 terminal_levers: Collection[str] = tuple(TERMINAL_LEVERS)) -> dict[str, Any]:
    """Sources and front of one level (see the module docs)."""
    report: dict[str, Any] = {"level": name}
    reference: np.ndarray | None = None
    base = plan_with(raw, preset, {}, registry).stages["simplify"][0].params
    for lever, terminals in ((k, v) for k, v in TERMINAL_LEVERS.items() if k in terminal_levers):
        plan = plan_with(raw, preset, terminals, registry)
        cpu = time.process_time()
        result = pipeline.run(plan, registry, mesh, name, mesh_sha256(mesh))
        report.setdefault("cpu_s", {})[lever] = round(time.process_time() - cpu, 2)
        if reference is None:
            reference = evaluation.reference_flow(result)
        polygons = traffic.surface_arrays(result.graph).n
        structures: dict[str, nx.DiGraph] = {}
        radius = plan.stages["terminals"][0].params.radius or coverage.default_radius(result.context)
        for step, change in {**SIMPLIFICATIONS, **LEVERS}.items():
            change = None if change is None else {k: radius if v == "cover" else v for k, v in change.items()}
            params = None if change is None else base.model_copy(update=change)
            structures[step], rounds = simplified(result, params)
            report.setdefault("front", {}).setdefault(lever, {})[step] = measures(result, structures[step], plan,
                                                                                   registry, reference)
            if step == "+guarantee":
                report.setdefault("rounds", {})[lever] = rounds
        final = structures["+guarantee"]
        assert set(final) == set(result.structure), "the preset's simplification differs from the run's"
        if lever != "preset":
            continue
        origin, dents, dropped = origins(result, plan.stages["terminals"][0].params)
        table = {o: dict.fromkeys(SIMPLIFICATIONS, 0) for o in ORIGINS}
        steps = list(SIMPLIFICATIONS)
        for node in final:  # the last test without which the structure before it would not hold the node
            pairs = zip(steps[-2::-1], steps[::-1])  # (earlier, later), the last pair first
            test = next((later for earlier, later in pairs if node not in structures[earlier]), steps[0])
            table[origin[node]][test] += 1
        report.update(polygons=polygons, forest=result.forest.number_of_nodes(), table=table,
                      forest_origins={o: sum(1 for v in origin.values() if v == o) for o in ORIGINS},
                      sizes={step: structures[step].number_of_nodes() for step in structures},
                      dents_kept=len(dents & set(final)), leaves_dropped=dropped)
    return report


def print_report(report: dict[str, Any], say: Callable[[str], None] = print) -> None:
    """The two tables of one level's ``report``."""
    n = report["polygons"]
    say(f"\n{report['level']}: {n} polygons, forest {report['forest']} nodes ({100 * report['forest'] / n:.1f} %), "
        f"structure {report['sizes']['+guarantee']} ({100 * report['sizes']['+guarantee'] / n:.1f} %), guarantee "
        f"rounds {report['rounds']['preset']}, dents kept {report['dents_kept']}, leaves dropped by quiet_step "
        f"{report['leaves_dropped']['quiet']} and by dents {report['leaves_dropped']['dents']}, cpu {report['cpu_s']}")
    say(f"  {'origin':<14} {'forest':>7} " + " ".join(f"{s:>11}" for s in SIMPLIFICATIONS) + f" {'kept':>13}")
    for origin, row in report["table"].items():
        kept = sum(row.values())
        say(f"  {origin:<14} {report['forest_origins'][origin]:>7} "
            + " ".join(f"{v:>4} {100 * v / n:5.1f}%" for v in row.values()) + f" {kept:>5} {100 * kept / n:5.1f} %")
    column = {s: sum(row[s] for row in report["table"].values()) for s in SIMPLIFICATIONS}
    say(f"  {'all':<14} {report['forest']:>7} " + " ".join(f"{v:>4} {100 * v / n:5.1f}%" for v in column.values())
        + f" {sum(column.values()):>5}")
    say("  sizes: " + ", ".join(f"{s} {100 * v / n:.1f} %" for s, v in report["sizes"].items()))
    for lever, steps in report["front"].items():
        say(f"  front, {lever}: " + "; ".join(
            f"{s} {100 * m['share']:.1f} % rho {m['rho']:.3f} 6m {100 * m['within_6m']:.1f} "
            f"off {100 * m['traffic_off']:.1f}" for s, m in steps.items()))
    points = [(m, f"{lever} / {s}") for lever, steps in report["front"].items() for s, m in steps.items()
              if s not in ("always", "raycast")]
    meeting = [(m["share"], label) for m, label in points if m["rho"] >= 0.9 and m["within_6m"] >= 0.95
               and m["traffic_off"] <= 0.05]
    small = [(m["rho"], label) for m, label in points if m["share"] <= 0.35]
    say("  smallest meeting the targets: " + (f"{100 * min(meeting)[0]:.1f} % ({min(meeting)[1]})" if meeting else
                                               "none")
        + "; best rho at <= 35 %: " + (f"{max(small)[0]:.3f} ({max(small)[1]})" if small else "none"))


def main(argv: list[str] | None = None) -> None:
    """Both tables for every level of ``argv`` (the command line when None)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--preset", default="map_analysis")
    parser.add_argument("--levels", nargs="+", default=["nav_test", "dungeon_1k"])
    parser.add_argument("--seeds", nargs="+", type=int, default=[0])
    parser.add_argument("--terminal-levers", nargs="+", choices=list(TERMINAL_LEVERS), default=list(TERMINAL_LEVERS),
                        help="the terminal levers of the front (the preset's always runs)")
    parser.add_argument("--jsonl", help="also append each level's report to this file, a JSON object a line")
    args = parser.parse_args(argv)
    print(f"load average {os.getloadavg()[0]:.1f}", flush=True)
    registry = Registry.from_entry_points()
    raw = load_raw_config(find_config(args.preset))
    for name, mesh in levels(args.levels, args.seeds):
        report = level_report(name, mesh, raw, args.preset, registry, {"preset", *args.terminal_levers})
        print_report(report, lambda line: print(line, flush=True))
        if args.jsonl:
            with open(args.jsonl, "a", encoding="utf-8") as out:
                out.write(json.dumps(report) + "\n")


if __name__ == "__main__":
    main()
