"""The disconnected-areas warning's likely cause on the levels that warn, measured against what a designer would fix.

Two steps, so that a change to the cause (``g2s_plugins/area_gaps.py``) is measured without running the levels again:

``collect OUT_DIR [--round 50|32]`` runs each level of :data:`WARNINGS` (round 50: the 72 warnings of
docs/analysis_quality.md "The disconnected-areas warning's nearest area") or of :data:`ROUND_32` (its 18 levels on
both routes; round 36-37: :data:`ROUND_36_37`; round 38: :data:`ROUND_38`) through the Steiner step (``map_analysis``: navmesh route; ``map_analysis_sampling``: sampling route),
stops it at the warning and keeps what the cause is measured on (the graph, its areas, the agent, the builder's
ground and the mesh) in ``OUT_DIR/<level>_<route>.pkl``, with the warning the code of the run gave.

``report OUT_DIR --before FILE`` prints, per kept warning, its likely cause by ``FILE`` (another commit's
``area_gaps.py``: ``git show 66a3764:g2s_plugins/area_gaps.py > FILE``) and by the current code, each marked "the
run's" when the whole warning equals the one the run gave, the CPU seconds of its second call (the first builds the
mesh's ray scene), and whether it meets rule K (docs/analysis_quality.md "The disconnected-areas warning's smaller
neighbours and head room"), from each area's separation from the largest
(:func:`g2s_plugins.area_gaps.closest_step_for`: gap, rise; hypot of the two):

- J' (round 50): it names the nearest area of at least a tenth of the largest's surface (of all, when none is), within
  0.5 m of hypot(gap, rise);
- K1: when an area under that tenth comes within the agent's width (hypot <= 2 agent.radius) and nearer than the
  named one (both read at the warning's 0.1 m: :data:`g2s_plugins.area_gaps.READ_AS_EQUAL`), the message names such an
  area (one within 0.1 m of the nearest's distance), and names none when there is none;
- K2: on round 32's sewer, a named pair whose both ends lie on a channel's bed (under the walkways by 0.9 m or more)
  is parted by a plank's head room and is named so ("head room too low"); round 36's queue hall names head room on the
  navmesh route (a shop behind a shutter under 2 m; its sampling route's warnings are not judged); round 37's awning market names head room or an awning's top ("separate floors"); no other
  message names head room.

Run: ``.venv/bin/python benchmarks/disconnected_warnings.py collect OUT_DIR`` (about 4 min on 2 loaded cores; ``--round
32``: 4 min more), then ``report OUT_DIR --before FILE`` (about 2 min). O(levels x a pipeline run to the Steiner
step); the report O(areas x :func:`~g2s_plugins.area_gaps.closest_step_for`) a warning.
"""

from __future__ import annotations

import argparse
import importlib.util
import math
import os
import pickle
import re
import sys
import time
from functools import partial
from pathlib import Path
from types import ModuleType, SimpleNamespace

import numpy as np
from analysis_quality import KINDS, NAV_TEST
from level_kinds32 import KINDS as ROUND_32_KINDS
from level_kinds36 import KINDS as ROUND_36_KINDS
from level_kinds37 import KINDS as ROUND_37_KINDS
from level_kinds38 import KINDS as ROUND_38_KINDS

from g2s_core import api, pipeline
from g2s_core.disconnected import area_summary, disconnected_warning
from g2s_core.mesh import load_mesh
from g2s_plugins import area_gaps

DATA = NAV_TEST.parent
ROUTES = {"navmesh": "map_analysis", "sampling": "map_analysis_sampling"}

WARNINGS = [
    ("Hallway.obj", "sampling"), ("archipelago s0", "navmesh"), ("archipelago s1", "navmesh"),
    ("archipelago s2", "navmesh"), ("battle_royale s0", "navmesh"), ("battle_royale s1", "navmesh"),
    ("beams s0", "navmesh"), ("beams s0", "sampling"), ("beams s1", "navmesh"), ("beams s1", "sampling"),
    ("beams s2", "navmesh"), ("beams s2", "sampling"), ("bell_towers s0", "sampling"), ("bell_towers s1", "navmesh"),
    ("bell_towers s2", "navmesh"), ("bell_towers s2", "sampling"), ("car_park s0", "navmesh"),
    ("car_park s0", "sampling"), ("cave s0", "navmesh"), ("collision_hulls s0", "navmesh"),
    ("collision_hulls s0", "sampling"), ("collision_hulls s1", "navmesh"), ("collision_hulls s1", "sampling"),
    ("collision_hulls s2", "navmesh"), ("collision_hulls s2", "sampling"), ("flooded s0", "navmesh"),
    ("flooded s0", "sampling"), ("flooded s1", "navmesh"), ("flooded s1", "sampling"), ("flooded s2", "navmesh"),
    ("flooded s2", "sampling"), ("harbour s0", "navmesh"), ("ice_floes s0", "navmesh"), ("ice_floes s0", "sampling"),
    ("ice_floes s1", "navmesh"), ("ice_floes s1", "sampling"), ("ice_floes s2", "navmesh"),
    ("ice_floes s2", "sampling"), ("islets s0", "navmesh"), ("islets s0", "sampling"), ("islets s1", "navmesh"),
    ("islets s1", "sampling"), ("islets s2", "navmesh"), ("islets s2", "sampling"), ("jump_gaps s0", "navmesh"),
    ("jump_gaps s0", "sampling"), ("jump_gaps s1", "navmesh"), ("jump_gaps s1", "sampling"),
    ("jump_gaps s2", "navmesh"), ("jump_gaps s2", "sampling"), ("market s0", "navmesh"), ("nav_test.obj", "navmesh"),
    ("nav_test.obj", "sampling"), ("rooftops s0", "navmesh"), ("rooftops s0", "sampling"),
    ("rooftops s1", "sampling"), ("rooftops s2", "navmesh"), ("rooftops s2", "sampling"),
    ("sample:roofed_corridor", "navmesh"), ("sample:roofed_corridor", "sampling"),
    ("sample:terrain?size=160", "navmesh"), ("sample:wall_tops", "navmesh"), ("sample:wall_tops", "sampling"),
    ("sewer s1", "navmesh"), ("sewer s2", "navmesh"), ("ship s0", "navmesh"), ("slopes s0", "navmesh"),
    ("slopes s1", "navmesh"), ("slopes s1", "sampling"), ("slopes s2", "navmesh"), ("subway s0", "navmesh"),
    ("subway s0", "sampling"),
]
"""(level, route) of the 72 warnings round 50 measured: a kind and seed, a sample or a file of the shared data."""

ROUND_32 = [(f"{kind} s{seed}", route) for kind in ROUND_32_KINDS for seed in range(3) for route in ROUTES]
"""(level, route) of the thirty-second round's 18 levels on both routes (those that warn are kept)."""

ROUND_36_37 = [(f"{kind} s{seed}", route) for kinds in (ROUND_36_KINDS, ROUND_37_KINDS) for kind in kinds
               for seed in range(3) for route in ROUTES]
"""(level, route) of the thirty-sixth and thirty-seventh rounds' levels on both routes (those that warn are kept): the
queue hall's shutter and the awning market's awnings, head room a little over the agent's height."""

ROUND_38 = [(f"{kind} s{seed}", route) for kind in ROUND_38_KINDS for seed in range(3) for route in ROUTES]
"""(level, route) of the thirty-eighth round's levels on both routes (those that warn are kept): the coaming deck's
tween deck, reached by companionways 11 m from the hull side the nearest pair lies on, and the rubble nave's gallery
over its aisle, whose nearest pair on one floor lies across the nave."""

NEAR_TIE = 0.1
"""Metres: an area named within this of the nearest's hypot(gap, rise) is as good as the nearest (K1)."""


class _Stop(Exception):
    """Raised at the warning: the run is not needed past it."""


def mesh_of(level: str) -> object:
    """The mesh (or ``sample:`` name) of a level as :data:`WARNINGS` names it."""
    if level.endswith(".obj"):
        return load_mesh(DATA / level if level == "nav_test.obj" else DATA / "pieces" / level)[0]
    if level.startswith("sample:"):
        return level
    kind, seed = level.rsplit(" s", 1)
    return KINDS[kind](int(seed))


def collect(out: Path, runs: list[tuple[str, str]]) -> None:
    """Each run's warning and what its cause is measured on, pickled in ``out``."""
    out.mkdir(parents=True, exist_ok=True)
    original = pipeline.disconnected_warning
    for level, route in runs:
        kept: dict = {}

        def keep(graph, areas, terminal_count, likely_cause, waypoint_count=0):  # noqa: ANN001, ANN202
            rim = likely_cause.keywords["rim"].keywords
            navmesh = rim["navmesh"]
            kept.update(graph=graph, areas=dict(areas), terminals=terminal_count, waypoints=waypoint_count,
                        agent=likely_cause.keywords["agent"], erosion=rim["erosion"], mesh=likely_cause.keywords["mesh"],
                        navmesh=None if navmesh is None else SimpleNamespace(
                            vertices=np.asarray(navmesh.vertices), polygons=np.asarray(navmesh.polygons),
                            neighbours=np.asarray(navmesh.neighbours), settings=dict(navmesh.settings)),
                        message=original(graph, areas, terminal_count, likely_cause, waypoint_count))
            raise _Stop

        pipeline.disconnected_warning = keep
        try:
            api.run(mesh_of(level), ROUTES[route], mesh_name=level.replace(" ", "_"))
        except Exception:  # noqa: BLE001  the stop, wrapped or not; a run that fails keeps nothing
            pass
        finally:
            pipeline.disconnected_warning = original
        name = re.sub(r"[^A-Za-z0-9_.=-]+", "_", level)
        if kept:
            (out / f"{name}_{route}.pkl").write_bytes(pickle.dumps(kept))
        print(f"{level} {route}: {'warned' if kept else 'no warning'}; load {os.getloadavg()[0]:.1f}", flush=True)


def cause_of(kept: dict, gaps: ModuleType = area_gaps):  # noqa: ANN201
    """The cause of ``gaps`` (:mod:`g2s_plugins.area_gaps` or another commit's copy of it) over a kept run's ground,
    as the graph builder makes it (:func:`~g2s_plugins.area_gaps.likely_cause_of`: on the sampling route the erosion
    is the builder's clearance; on the navmesh route it is Recast's, from the navmesh's cells)."""
    return gaps.likely_cause_of(kept["agent"], kept["navmesh"], kept["erosion"], kept["mesh"])


def module_of(path: Path) -> ModuleType:
    """The cause's module of another commit, from a copy of its ``g2s_plugins/area_gaps.py``."""
    spec = importlib.util.spec_from_file_location("area_gaps_before", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def separations(kept: dict) -> list[tuple[float, float, float, float, bool]]:
    """Per area but the largest, largest first: (m², gap m, signed rise m, hypot(gap, rise), joined) against the
    largest (:func:`g2s_plugins.area_gaps.closest_step_for`, :func:`~g2s_plugins.area_gaps.joined_areas`)."""
    graph, agent = kept["graph"], kept["agent"]
    areas = sorted(kept["areas"].values(), key=lambda nodes: -area_summary(graph, nodes)[0])
    rim = partial(area_gaps.ground_rim, graph, navmesh=kept["navmesh"], erosion=kept["erosion"])
    largest = rim(areas[0])
    joined = set(area_gaps.joined_areas(graph, areas[0], areas[1:]))
    rows = []
    for k, nodes in enumerate(areas[1:]):
        closest = area_gaps.closest_step_for(largest, rim(nodes), agent)
        rise = float(closest.there[1] - closest.here[1])
        rows.append((area_summary(graph, nodes)[0], closest.gap, rise, math.hypot(closest.gap, closest.step), k in joined))
    return rows


def judged(name: str, rows: list[tuple[float, float, float, float, bool]], width: float,
           cause: str) -> tuple[bool, bool, bool, str]:
    """(J', K1, K2, what K wants) of a warning's likely ``cause`` (the text after "Likely cause: ") on a kept run,
    ``rows`` its :func:`separations`, ``width`` the agent's (m)."""
    pool = [r for r in rows if r[4]] or rows
    wanted = min(pool, key=lambda r: r[3])
    size = float(re.match(r"from the largest area to the nearest area of ([\d,]+) m²", cause).group(1).replace(",", ""))
    candidates = [r for r in pool if round(r[0]) == size]
    j = any(abs(r[3] - wanted[3]) <= 0.5 for r in candidates)
    measured = min(candidates, key=lambda r: abs(r[3] - wanted[3]))[3] if candidates else math.inf
    nearer = [r for r in rows if not r[4] and r[3] <= width + area_gaps.READ_AS_EQUAL
              and r[3] <= measured - area_gaps.READ_AS_EQUAL]
    smaller = re.search(r"a smaller area of ([\d,]+) m²", cause)
    if nearer:
        best = min(r[3] for r in nearer)
        k1 = bool(smaller) and any(round(r[0]) == float(smaller.group(1).replace(",", "")) and r[3] <= best + NEAR_TIE
                                   for r in nearer)
    else:
        k1 = not smaller
    low = "head room too low" in cause
    if name.startswith("sewer_planks"):  # by construction: a named pair both on a bed is parted by a plank
        named = cause.split("; and a smaller area")[0]
        places = [np.array(p.split(", "), dtype=float) for p in re.findall(r"\(([-\d.]+, [-\d.]+, [-\d.]+) m\)", named)]
        k2 = low == (bool(places) and all(p[1] <= -0.9 for p in places))
    elif name.startswith("queue_hall"):  # round 36: a shop behind a shutter under 2 m on the navmesh route; the
        k2 = low or name.endswith("_sampling")  # sampling route's (a belt 0.9 m up, a shutter, a wall) not judged
    elif name.startswith("awning_market"):  # round 37: aisles cut under awnings about 2 m up, or an awning's top
        k2 = low or "separate floors" in cause
    else:
        k2 = not low
    want = f"{wanted[0]:,.0f} m² hypot {wanted[3]:.1f}"
    if nearer:
        near = min(nearer, key=lambda r: r[3])
        want += f"; smaller {near[0]:,.0f} m² hypot {near[3]:.1f}"
    return j, k1, k2, want


def report(out: Path, before: Path) -> None:
    """Each kept warning's cause by ``before`` (a copy of another commit's ``area_gaps.py``) and by the current code,
    rule K's verdict on each, and the counts."""
    old = module_of(before)
    counts, seconds = {"before": 0, "now": 0}, {"before": 0.0, "now": 0.0}
    total = 0
    for path in sorted(out.glob("*.pkl")):
        kept = pickle.loads(path.read_bytes())
        rows, width = separations(kept), 2 * float(kept["agent"].radius)
        total += 1
        for label, gaps in (("before", old), ("now", area_gaps)):
            warning = partial(disconnected_warning, kept["graph"], kept["areas"], kept["terminals"], cause_of(kept, gaps),
                              kept["waypoints"])
            warning()  # the mesh's ray scene and its closed bodies, built once and shared, left out of the timing
            began = time.process_time()
            message = warning()
            spent = time.process_time() - began
            seconds[label] += spent
            cause = message.split("Likely cause: ", 1)[1]
            j, k1, k2, want = judged(path.stem, rows, width, cause)
            counts[label] += j and k1 and k2
            same = ", the run's" if message == kept["message"] else ""
            print(f"{path.stem} [{label}{same}] J'={'y' if j else 'n'} K1={'y' if k1 else 'n'} K2={'y' if k2 else 'n'} "
                  f"{spent:.2f} s (wanted {want}): {cause}", flush=True)
    for label, good in counts.items():
        print(f"{label}: {good} of {total} name what a designer would fix (J', K1 and K2); "
              f"{seconds[label]:.1f} s of CPU for the warnings")


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("step", choices=["collect", "report"])
    parser.add_argument("out", type=Path)
    parser.add_argument("--round", choices=["50", "32", "36-37", "38"], default="50", help="collect: which levels")
    parser.add_argument("--before", type=Path, help="report: a copy of another commit's g2s_plugins/area_gaps.py "
                                                    "(git show REV:g2s_plugins/area_gaps.py > FILE) to compare with")
    args = parser.parse_args(argv)
    print(f"load average {os.getloadavg()[0]:.1f}", file=sys.stderr)
    if args.step == "collect":
        collect(args.out, {"50": WARNINGS, "32": ROUND_32, "36-37": ROUND_36_37, "38": ROUND_38}[args.round])
    else:
        report(args.out, args.before)


if __name__ == "__main__":
    main()
