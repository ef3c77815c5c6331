"""The heat guarantee's rounds on the sampling route, read three ways against the exact walking flow, per candidate.

Run: ``.venv/bin/python benchmarks/guarantee_levers.py [--levels nav_test forest cave islets craters:2 ...]
[--seeds 0] [--candidates independent spread] [--reference-dir DIR ...] [--jsonl OUT.jsonl] [--noise SEEDS]``

For every level (the names ``benchmarks/analysis_quality.py`` takes; ``name:seed`` for one seed of a generated
level) and candidate it runs ``--preset`` (``map_analysis_sampling``) in memory, one run at a time, and prints:
the structure's share of the samples, the run's CPU seconds (``time.process_time`` of ``pipeline.run``: the machine
is shared), its heat map's Spearman rho against the reference flow (``exact``: every source, the flow the heat map
ranks; ``(p)`` after it: a 2,048-source linearly scaled sample stands for it on graphs over ``--exact-up-to`` nodes),
whether the run warned about its heat map, the area within 6 m of the joined structure and the reference traffic
more than 5 m from it, the guarantee's rounds, and, over every round (each structure the guarantee measured), the
largest gap between each reading and the exact rho: ``own`` (the heat map against its own sample, the reading of an
independent sample with the margin ``MARGINS``), ``pooled`` (against the mean of its own sample and the second one,
:func:`g2s_plugins.heat_guarantee.second_sample`: the reading of a ``spread`` sample with ``POOLED_MARGINS``). Gaps are given only against an exact flow.

Candidates (each a set of the preset's parameters, the rest as the preset says):

* ``independent``: the heat map's and the ``flow`` analyzer's sample drawn independently (``heat_sampling`` and
  ``sampling`` ``independent``: ``map_analysis_sampling`` before 5 December 2026); the guarantee reads it against its
  own sample;
* ``spread``: the heat map's and the ``flow`` analyzer's sample drawn spread (``heat_sampling`` and ``sampling``
  ``spread``, :mod:`g2s_plugins.traffic`); the guarantee reads it pooled.

``--noise SEEDS`` prints instead, per level, how close the heat map's sample comes to the reference: the Spearman
rho over the nodes of its flow, and of the heat map that flow gives the ``independent`` candidate's final structure, drawn
independently, spread, and as the pool of two independent samples (512 sources), each the mean over SEEDS seeds.

``--pooled-margin`` sets the guarantee's margin for a pooled reading (``POOLED_MARGINS['linear']``) for this process
only, to measure what a margin would give. Reference flows are read from and written to the first
``--reference-dir`` as ``exact_<level>.npy`` or ``proxy_<level>.npy`` (found in any of them when their length is
the graph's). This is a benchmark: nothing here asserts a target (docs/analysis_quality.md, "A heat map with less
noise on the sampling route").
"""

from __future__ import annotations

import argparse
import copy
import json
import os
import time
from collections.abc import Hashable, Iterator
from pathlib import Path

import numpy as np
import trimesh
from analysis_quality import levels

from g2s_core import pipeline
from g2s_core.config import find_config, load_raw_config, parse_config
from g2s_core.mesh import mesh_sha256
from g2s_core.registry import Registry
from g2s_plugins import evaluation, heat_guarantee, traffic

CANDIDATES: dict[str, dict[str, object]] = {
    "independent": {"heat_sampling": "independent", "sampling": "independent"},
    "spread": {"heat_sampling": "spread", "sampling": "spread"},
}
"""Each candidate's parameters: ``heat_*`` of the ``simplify`` stage, the others of the first analyzer (``flow``)."""

PROXY_SOURCES = 2048
"""Sources of the reference on graphs too large for the exact flow (linearly scaled, split ties, seed 2: a sample
independent of the run's seeds 0 and 1)."""


def level_items(items: list[str], seeds: list[int]) -> Iterator[tuple[str, trimesh.Trimesh]]:
    """The levels of ``items`` (``name`` at every seed of ``seeds``, ``name:seed`` at that seed alone)."""
    for item in items:
        name, _, seed = item.partition(":")
        yield from levels([name], [int(seed)] if seed else seeds)


def candidate_plan(raw: dict, preset: str, parameters: dict[str, object], registry: Registry) -> pipeline.Plan:
    """The plan of ``raw`` (the preset's raw config) with ``parameters`` set (see :data:`CANDIDATES`)."""
    raw = copy.deepcopy(raw)
    for key, value in parameters.items():
        params = raw["simplify"]["params"] if key.startswith("heat_") else raw["analyzers"][0]["params"]
        params[key] = value
    return pipeline.plan(parse_config(raw, preset), registry, preset)


def reference_flow(name: str, graph, directories: list[Path], exact_up_to: int) -> tuple[np.ndarray, bool]:
    """(n,) the reference walking flow of ``graph`` (split ties) and whether it is exact, cached as .npy files."""
    arrays = traffic.surface_arrays(graph)
    for directory in directories:
        for kind in ("exact", "proxy"):
            path = directory / f"{kind}_{name}.npy"
            if path.exists():
                flow = np.load(path)
                if len(flow) == arrays.n:
                    return flow, kind == "exact"
    exact = arrays.n <= exact_up_to
    flow = traffic.arrays_walking_flow(arrays, None if exact else PROXY_SOURCES, seed=2, ties="split", scaling="linear")
    directories[0].mkdir(parents=True, exist_ok=True)
    np.save(directories[0] / f"{'exact' if exact else 'proxy'}_{name}.npy", flow)
    return flow, exact


class RoundLog:
    """The structures the guarantee measures in a run: :func:`g2s_plugins.heat_guarantee.restored` wrapped to keep
    each ``simplified`` structure's nodes (the function itself unchanged; restored by :meth:`close`)."""

    def __init__(self) -> None:
        self.structures: list[list[Hashable]] = []
        self._restored = heat_guarantee.restored

        def logged(graph, forest, simplified, *rest):
            self.structures.append(sorted(simplified))
            return self._restored(graph, forest, simplified, *rest)

        heat_guarantee.restored = logged

    def close(self) -> None:
        heat_guarantee.restored = self._restored


def measure(name: str, mesh: trimesh.Trimesh, candidate: str, plan: pipeline.Plan, registry: Registry,
            directories: list[Path], exact_up_to: int) -> dict:
    """One run of ``plan`` on ``mesh`` and its measures (the table's row, and every round's readings)."""
    log = RoundLog()
    try:
        cpu = time.process_time()
        result = pipeline.run(plan, registry, mesh, name, mesh_sha256(mesh))
        cpu = time.process_time() - cpu
    finally:
        log.close()
    graph = result.graph
    arrays = traffic.surface_arrays(graph)
    reference, exact = reference_flow(name, graph, directories, exact_up_to)
    simplify = plan.stages["simplify"][0].params
    order = traffic.sampling_order(graph, simplify.heat_sampling)
    shown = traffic.arrays_walking_flow(arrays, simplify.heat_sources, ties=simplify.heat_ties,
                                        scaling=simplify.heat_scaling, order=order)
    pooled = (shown + heat_guarantee.second_sample(arrays, simplify.heat_sources, simplify.heat_ties,
                                                   simplify.heat_scaling, order)) / 2.0
    rounds = []
    for nodes in log.structures:
        heat = evaluation.placement_heat(graph, nodes, shown)
        rounds.append([round(100 * len(nodes) / arrays.n, 2)] + [round(evaluation.spearman(heat, flow), 4)
                                                                  for flow in (reference, shown, pooled)])
    first = next(iter(result.analysis.values()))
    heat = evaluation.heat_map(graph, result.structure, first, evaluation.nearest_structure_rows(result))
    joined = result.looped if result.looped is not None else result.steiner
    distance, _ = traffic.distance_to(arrays, arrays.rows(sorted(joined)))
    area = traffic.origin_weight(arrays)
    gaps = {reading: max((r[column] - r[1] for r in rounds), default=float("nan")) if exact else float("nan")
            for reading, column in (("own", 2), ("pooled", 3))}
    return dict(
        level=name, candidate=candidate, samples=arrays.n, exact=exact,
        rho=round(evaluation.spearman(heat, reference), 4),
        warned=any("heat map" in warning for warning in result.warnings),
        share=round(100 * result.structure.number_of_nodes() / arrays.n, 2), cpu=round(cpu, 2),
        within_6m=round(100 * float(area[distance <= 6.0].sum() / area.sum()), 2),
        off_5m=round(100 * float(reference[distance > 5.0].sum() / reference.sum()), 2),
        rounds=len(rounds), max_gap_own=round(gaps["own"], 4), max_gap_pooled=round(gaps["pooled"], 4),
        per_round=rounds, load=round(os.getloadavg()[0], 1), time=time.strftime("%H:%M:%S", time.gmtime()),
    )


def sample_noise(name: str, mesh: trimesh.Trimesh, plan: pipeline.Plan, registry: Registry, directories: list[Path],
                 exact_up_to: int, seeds: int) -> dict:
    """How close the sample of ``plan`` (the ``independent`` candidate's) comes to the reference, drawn independently,
    spread, and two independent ones pooled: Spearman rho of each flow against the reference over the nodes, and of
    the heat map it gives the run's final structure, averaged over ``seeds`` seeds (0, 1, ...; the pool: seeds 2i and 2i + 1)."""
    result = pipeline.run(plan, registry, mesh, name, mesh_sha256(mesh))
    graph = result.graph
    arrays = traffic.surface_arrays(graph)
    reference, exact = reference_flow(name, graph, directories, exact_up_to)
    simplify = plan.stages["simplify"][0].params
    nearest = evaluation.nearest_structure_rows(result)

    def flow(seed: int, order: np.ndarray | None) -> np.ndarray:
        return traffic.arrays_walking_flow(arrays, simplify.heat_sources, seed=seed, ties=simplify.heat_ties,
                                           scaling=simplify.heat_scaling, order=order)

    samples = {
        "independent": [flow(seed, None) for seed in range(seeds)],
        "spread": [flow(seed, traffic.plan_order(graph)) for seed in range(seeds)],
        "pooled2": [(flow(2 * seed, None) + flow(2 * seed + 1, None)) / 2.0 for seed in range(seeds)],
    }
    row = dict(level=name, samples=arrays.n, exact=exact, share=round(100 * result.structure.number_of_nodes() / arrays.n, 2))
    for kind, flows in samples.items():
        row[f"{kind}_nodes"] = round(float(np.mean([evaluation.spearman(f, reference) for f in flows])), 4)
        row[f"{kind}_heat"] = round(float(np.mean([evaluation.spearman(evaluation.placement_heat(graph, result.structure, f, nearest), reference) for f in flows])), 4)
    return row


def main(argv: list[str] | None = None) -> None:
    """The table for ``argv`` (the command line when None)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--preset", default="map_analysis_sampling", help="the preset (or config file) the candidates change")
    parser.add_argument("--levels", nargs="+", default=["nav_test", "forest", "cave", "islets", "craters:2"],
                        help="level names as benchmarks/analysis_quality.py takes them; name:seed for one seed")
    parser.add_argument("--seeds", nargs="+", type=int, default=[0], help="seeds of generated levels named without one")
    parser.add_argument("--candidates", nargs="+", default=["independent", "spread"], choices=sorted(CANDIDATES),
                        help="run one after the other on each level")
    parser.add_argument("--pooled-margin", type=float, default=None,
                        help="the guarantee's margin for a pooled reading (POOLED_MARGINS['linear']) in this process")
    parser.add_argument("--reference-dir", nargs="+", type=Path, default=[Path("benchmarks/out/references")],
                        help="directories of cached reference flows; new ones are written to the first")
    parser.add_argument("--exact-up-to", type=int, default=8000,
                        help="graphs with at most this many nodes get the exact reference, larger ones a proxy")
    parser.add_argument("--jsonl", type=Path, default=None, help="also append every row, with its rounds, here")
    parser.add_argument("--noise", type=int, default=0, metavar="SEEDS",
                        help="instead of the candidates' runs: per level, the rho of the preset's own sample against the "
                             "reference, drawn independently, spread and two independent pooled, over this many seeds")
    args = parser.parse_args(argv)
    if args.pooled_margin is not None:
        heat_guarantee.POOLED_MARGINS["linear"] = args.pooled_margin
    registry = Registry.from_entry_points()
    raw = load_raw_config(find_config(args.preset))
    if args.noise:
        plan = candidate_plan(raw, args.preset, CANDIDATES["independent"], registry)
        kinds = ("independent", "spread", "pooled2")
        print(f"{'level':<16} {'samples':>7} {'share':>6}  rho of the nodes' flow (" + " / ".join(kinds)
              + ")  rho of the heat map at the structure (" + " / ".join(kinds) + ")")
        for name, mesh in level_items(args.levels, args.seeds):
            row = sample_noise(name, mesh, plan, registry, args.reference_dir, args.exact_up_to, args.noise)
            print(f"{name:<16} {row['samples']:>7} {row['share']:5.2f}%  "
                  + " / ".join(f"{row[k + '_nodes']:.4f}" for k in kinds) + ("" if row["exact"] else " (p)") + "  "
                  + " / ".join(f"{row[k + '_heat']:.4f}" for k in kinds), flush=True)
        return
    plans = {name: candidate_plan(raw, args.preset, CANDIDATES[name], registry) for name in args.candidates}
    print(f"load average {os.getloadavg()[0]:.1f}; pooled margin {heat_guarantee.POOLED_MARGINS['linear']:g}, "
          f"own margin {heat_guarantee.MARGINS['linear']:g}")
    print(f"{'level':<16} {'candidate':<10} {'samples':>7} {'share':>6} {'cpu s':>6} {'rho':>9} {'warns':>5} "
          f"{'<=6m':>6} {'off>5m':>6} {'rounds':>6} {'gap own':>8} {'gap pooled':>10}")
    out = args.jsonl.open("a") if args.jsonl else None
    for name, mesh in level_items(args.levels, args.seeds):
        for candidate, plan in plans.items():
            row = measure(name, mesh, candidate, plan, registry, args.reference_dir, args.exact_up_to)
            rho = f"{row['rho']:.4f}" + ("" if row["exact"] else "(p)")
            print(f"{name:<16} {candidate:<10} {row['samples']:>7} {row['share']:5.2f}% {row['cpu']:6.2f} {rho:>9} "
                  f"{'yes' if row['warned'] else '-':>5} {row['within_6m']:5.1f}% {row['off_5m']:5.2f}% "
                  f"{row['rounds']:>6} {row['max_gap_own']:8.4f} {row['max_gap_pooled']:10.4f}", flush=True)
            if out:
                out.write(json.dumps(row) + "\n")
                out.flush()


if __name__ == "__main__":
    main()
