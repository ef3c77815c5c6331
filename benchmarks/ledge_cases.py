"""Stairs and narrow ledge tops: does the sampled graph (and the navmesh graph) read them as the agent's rules say?

Run: ``.venv/bin/python benchmarks/ledge_cases.py [--kinds flights ledges] [--yaws 0 22 45] [--navmesh]``

Generated cases with known answers for the presets' agent (radius 0.5 m, height 2 m, climb 0.4 m, max slope 45
degrees), Y up, metres, each turned by ``yaw`` degrees about the vertical axis:

* ``flights``: floor A (x from -6 to 0, z from -3 to 3, its top at y = 0), a straight flight along +x from x = 0,
  ``width`` m wide (1.2, 2 or 3) between walls 3 m over its treads, whose steps are solid blocks of ``riser`` and
  ``tread`` m, up to floor B (6 x 6 m) about 3 m up (``round(3 / riser)`` risers). Known answer: a flight whose risers
  are within the agent's climb joins A and B (the treads are level; each riser is a step), one whose risers are over
  it does not.
* ``ledges``: a floor 8 x 8 m and on it, along x from -2 to 2, a block ``depth`` m deep (z from 0 to ``depth``) and
  ``height`` m high: against a wall 3 m high along its back (``back: wall``, a bench, a bunk) or standing free
  (``back: none``, a shelf, a low wall's top). Known answer: a top within the climb is floor joined to the floor
  round it; a top over the climb is never joined to the floor, and holds no sample when it is narrower than the
  agent (``depth`` under 2 x radius: no place on it where the agent's whole width stands).

For every case the sampling builder runs with the ``map_analysis_sampling`` preset's method (``grid``) and its
defaults; with ``--navmesh``, the navmesh builder as the ``map_analysis``
preset runs it (``ledge_filter: drops``, ``climb: agent``). Each row prints the samples on the flight or
the top, whether the graph joins what the known answer says (``ok``) or not (``WRONG``), and the navmesh graph's
answer beside it as a reference. This is a benchmark: nothing here asserts a target; the figures are in
docs/sampling.md ("Stairs and narrow ledge tops").
"""

from __future__ import annotations

import argparse
import itertools
import time

import numpy as np
import trimesh

import level_kinds  # the level kinds' solids (this script's folder)
from narrow_flights import _turn, joined
from scipy.sparse import csgraph, csr_array
from scipy.spatial import cKDTree
from g2s_core.config import AgentConfig
from g2s_core.model import RunContext
from g2s_plugins._raycasting import AgentShape
from g2s_plugins.graph_builders import navmesh, sampling

AGENT = AgentConfig(radius=0.5, height=2.0, max_climb=0.4, max_slope=45.0)
"""The presets' agent."""

STEPS = [(0.15, 0.35), (0.18, 0.28), (0.20, 0.30), (0.25, 0.30), (0.25, 0.25), (0.29, 0.30), (0.30, 0.30),
         (0.30, 0.25), (0.33, 0.30), (0.35, 0.35), (0.35, 0.25), (0.45, 0.30), (0.50, 0.35)]
"""(riser, tread) metres: from a gentle flight to steeper than 45 degrees, and two with risers over the climb."""

WIDTHS = (1.2, 2.0, 3.0)
"""Metres: the flights' widths, one a case in turn."""

DEPTHS = (0.3, 0.5, 0.75, 0.9, 1.2, 1.5)
HEIGHTS = (0.3, 0.45, 0.6, 0.9, 1.2)
"""Metres: the ledge blocks' depths and heights."""


def flight_level(riser: float, tread: float, width: float) -> tuple[trimesh.Trimesh, np.ndarray, tuple]:
    """The level (unturned), floor A's and floor B's middles (2, 3) and the flight's plan (x0, x1, z0, z1)."""
    s = level_kinds._Solids()
    count = int(round(3.0 / riser))
    top, length = count * riser, count * tread
    s.box(-6.0, 0.0, -0.3, 0.0, -3.0, 3.0)
    s.stairs(np.array([0.0, 0.0]), np.array([1.0, 0.0]), width, 0.0, top, riser=riser, tread=tread)
    s.box(length, length + 6.0, -0.3, top, -3.0, 3.0)
    for side in (-1.0, 1.0):
        s.box(0.0, length, -0.3, top + 3.0, side * width / 2, side * (width / 2 + 0.2))
    return s.mesh(), np.array([[-3.0, 0.0, 0.0], [length + 3.0, top, 0.0]]), (0.0, length, -width / 2, width / 2)


def ledge_level(depth: float, height: float, back: str) -> tuple[trimesh.Trimesh, np.ndarray, tuple]:
    """The level (unturned), the floor's middle and the top's middle (2, 3) and the top's plan (x0, x1, z0, z1)."""
    s = level_kinds._Solids()
    s.box(-4.0, 4.0, -0.3, 0.0, -4.0, 4.0)
    s.box(-2.0, 2.0, 0.0, height, 0.0, depth)
    if back == "wall":
        s.box(-4.0, 4.0, 0.0, 3.0, depth, depth + 0.2)
    return s.mesh(), np.array([[0.0, 0.0, -2.5], [0.0, height, depth / 2]]), (-2.0, 2.0, 0.0, depth)


def on_plan(points: np.ndarray, turn: np.ndarray, plan: tuple, low: float, high: float) -> np.ndarray:
    """(n,) bool: which of ``points`` ((n, 3), turned) stand over the plan rectangle (unturned) at heights in
    [low, high]."""
    local = points @ turn[:3, :3]  # the inverse turn
    x0, x1, z0, z1 = plan
    inside = (local[:, 0] > x0) & (local[:, 0] < x1) & (local[:, 2] > z0) & (local[:, 2] < z1)
    return inside & (local[:, 1] >= low) & (local[:, 1] <= high)


def top_joined(graph, pos: np.ndarray, on: np.ndarray, floor: np.ndarray) -> bool:
    """Some sample of ``on`` ((n,) bool over the graph's sorted nodes, positions ``pos``) is in the connected part of
    the sample nearest ``floor`` ((3,), m)."""
    nodes = sorted(graph.nodes)
    index = {n: i for i, n in enumerate(nodes)}
    pairs = np.array([(index[a], index[b]) for a, b in graph.edges()]).reshape(-1, 2)
    links = csr_array((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(len(nodes), len(nodes)))
    part = csgraph.connected_components(links, directed=False)[1]
    return bool(np.any(part[on] == part[cKDTree(pos).query(floor)[1]]))


def cases(kinds: list[str], yaws: list[float]) -> list[tuple]:
    """``(kind, label, mesh, middles, plan, heights, expected_joined, expect_no_samples)`` for every case, unturned."""
    rows = []
    if "flights" in kinds:
        for i, ((riser, tread), yaw) in enumerate(itertools.product(STEPS, yaws)):
            width = WIDTHS[i % len(WIDTHS)]
            mesh, middles, plan = flight_level(riser, tread, width)
            rows.append(("flight", f"{riser:.2f}/{tread:.2f} w{width:.1f}", yaw, mesh, middles, plan,
                         (0.05, 3.0 - 0.05), riser <= AGENT.max_climb, False))
    if "ledges" in kinds:
        for depth, height, back, yaw in itertools.product(DEPTHS, HEIGHTS, ("wall", "none"), yaws):
            mesh, middles, plan = ledge_level(depth, height, back)
            reachable = height <= AGENT.max_climb
            rows.append(("ledge", f"d{depth:.2f} h{height:.2f} {back}", yaw, mesh, middles, plan,
                         (height - 0.05, height + 0.05), reachable, not reachable and depth < 2 * AGENT.radius))
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--kinds", nargs="+", default=["flights", "ledges"], choices=["flights", "ledges"])
    parser.add_argument("--yaws", type=float, nargs="+", default=[0.0, 22.0, 45.0], help="turns, degrees")
    parser.add_argument("--navmesh", action="store_true", help="also build the navmesh graph")
    args = parser.parse_args()

    agent = AgentShape.from_config(AGENT)
    seconds, wrong, count = 0.0, 0, 0
    print("kind    case                 yaw  samples  joined  expected  sampling  navmesh  cpu")
    for kind, label, yaw, mesh, middles, plan, heights, expected, bare in cases(args.kinds, args.yaws):
        turn = _turn(yaw)
        mesh.apply_transform(turn)
        middles = middles @ turn[:3, :3].T
        started = time.process_time()
        graph = sampling.build_sampled_graph(mesh, sampling.Params(method="grid"), agent)
        took = time.process_time() - started
        seconds += took
        pos = np.array([graph.nodes[n]["pos"] for n in sorted(graph.nodes)]).reshape(-1, 3)
        over = on_plan(pos, turn, plan, *heights)
        on = int(over.sum())
        if kind == "flight":
            together = len(pos) > 0 and joined(graph, middles)
            right = together == expected
        else:  # a top within the climb: whatever samples it holds are joined; over it: none is, and none stand
            together = on > 0 and top_joined(graph, pos, over, middles[0])
            right = (together or on == 0) if expected else not together and not (bare and on > 0)
        wrong += not right
        count += 1
        nav = ""
        if args.navmesh:
            context = RunContext(mesh=mesh, agent=AGENT, centre=mesh.bounds.mean(axis=0))
            params = navmesh.Params(ledge_filter="drops", climb="agent")
            nav_graph = navmesh.g2s_build_graph(mesh=mesh, params=params, context=context)
            nav = "joined" if joined(nav_graph, middles) else "apart"
        print(f"{kind:6s}  {label:19s}  {yaw:4.0f}  {on:7d}  {'yes' if together else 'no':>6s}"
              f"  {'yes' if expected else 'no':>8s}{' (bare)' if bare else '       '}  {'ok' if right else 'WRONG':>5s}"
              f"  {nav:>7s}  {took:4.2f}", flush=True)
    print(f"{count - wrong} of {count} cases as the agent's rules say; sampling builder {seconds:.1f} s CPU in all")


if __name__ == "__main__":
    main()
