"""Passages a little wider than the agent: does the sampled graph (and the navmesh graph) join the two floors they link?

Run: ``.venv/bin/python benchmarks/narrow_flights.py [--extras 0.05 0.1 0.2 0.4 0.6] [--yaws 0 22 45]
[--offsets 0 0.25 0.5 0.75] [--profiles flat stepped] [--shapes straight turning] [--sides walls drops]
[--method grid] [--navmesh]``

The level (built here, Y up, metres) joins floor A (x from -10 to 0, z from -5 to 5, its top at y = 0) to floor B
by one passage ``1 + extra`` m wide: twice the presets' agent radius (0.5 m) and ``extra`` more, so the band where
the agent's centre may stand is ``extra`` m wide.

* ``straight``: along x from x = 0 to 8, centred on z = ``offset``, to floor B (x from 8 to 18, z from -5 to 5);
  ``turning``: along x from 0 to 4 + ``offset``, a square landing, then along z to z = 10, centred on x =
  4 + ``offset`` + width / 2, to floor B (x from -6 to 14, z from 10 to 18), an L round a closed corner.
* ``flat``: the passage at y = 0, floor B too; ``stepped``: the passage climbs flights of risers 0.18 m and treads
  0.30 m (straight: 20 risers, 3.6 m; turning: 12 on the first leg and 16 on the second, 5.04 m), the rest of it
  level, floor B at the top.
* ``walls``: closed blocks 3 m thick, 3 m over the passage's top, on both sides of it (a corridor, a stairwell);
  ``drops``: nothing beside it and nothing under the floors (a bridge, a flight between drops: its sides are
  ledges, as the tavern's cellar flight's are under the kitchen's floor).

``offset`` (m) moves the passage (not the floors, which fix where the sampling grid lies) across the grid's lines.
The level is then turned by ``yaw`` degrees about the vertical axis. For every case the sampling builder runs with
its defaults (``--method``; the ``map_analysis_sampling`` preset's is ``grid``) and, with ``--navmesh``, the navmesh
builder with its defaults; a case prints whether the samples nearest the two floors' middles are in one connected
part of each graph, how many samples stand in the passage, and the sampling builder's CPU seconds. The totals
follow. This is a benchmark: nothing here asserts a target; the figures are in docs/sampling.md ("Passages a little
wider than the agent").
"""

from __future__ import annotations

import argparse
import itertools
import time

import numpy as np
import trimesh
from scipy.sparse import csgraph, csr_array
from scipy.spatial import cKDTree

import level_kinds  # the level kinds' solids (this script's folder)
from g2s_core.config import AgentConfig
from g2s_core.model import RunContext
from g2s_plugins._raycasting import AgentShape
from g2s_plugins.graph_builders import navmesh, sampling

RISER, TREAD = 0.18, 0.30
"""Metres: the flights' steps."""


def passage_level(extra: float, offset: float, profile: str, shape: str, sides: str) -> tuple[trimesh.Trimesh, np.ndarray, list]:
    """The level (unturned), the two floors' middles (2, 3) and the passage's plan rectangles (x0, x1, z0, z1)."""
    s = level_kinds._Solids()
    width = 1.0 + extra
    stepped = profile == "stepped"
    walls = sides == "walls"
    under = -0.3  # the slabs' underside (drops); walls stand on solid ground under everything

    def floor(x0: float, x1: float, z0: float, z1: float, top: float) -> None:
        s.box(x0, x1, top - 0.3 if not walls else -0.3, top, z0, z1)

    def flight(start: tuple[float, float], heading: tuple[float, float], y0: float, risers: int) -> None:
        s.stairs(np.array(start), np.array(heading), width, y0, risers * RISER, RISER, TREAD, None if walls else 0.3)

    floor(-10.0, 0.0, -5.0, 5.0, 0.0)
    lo, hi = offset - width / 2, offset + width / 2
    if shape == "straight":
        top = 20 * RISER if stepped else 0.0
        if stepped:
            flight((0.0, offset), (1.0, 0.0), 0.0, 20)
            floor(6.0, 8.0, lo, hi, top)
        else:
            floor(0.0, 8.0, lo, hi, 0.0)
        floor(8.0, 18.0, -5.0, 5.0, top)
        if walls:
            s.box(0.0, 8.0, under, top + 3.0, lo - 3.0, lo)
            s.box(0.0, 8.0, under, top + 3.0, hi, hi + 3.0)
        middles = np.array([[-5.0, 0.0, 0.0], [13.0, top, 0.0]])
        rects = [(0.0, 8.0, lo, hi)]
    else:
        corner = 4.0 + offset  # the landing's west side
        landing = 12 * RISER if stepped else 0.0
        top = landing + 16 * RISER if stepped else 0.0
        if stepped:
            flight((0.0, offset), (1.0, 0.0), 0.0, 12)
            floor(12 * TREAD, corner, lo, hi, landing)
        else:
            floor(0.0, corner, lo, hi, 0.0)
        floor(corner, corner + width, lo, hi, landing)  # the landing
        if stepped:
            flight((corner + width / 2, hi), (0.0, 1.0), landing, 16)
            floor(corner, corner + width, hi + 16 * TREAD, 10.0, top)
        else:
            floor(corner, corner + width, hi, 10.0, 0.0)
        floor(-6.0, 14.0, 10.0, 18.0, top)
        if walls:
            roof = top + 3.0
            s.box(0.0, corner + width + 3.0, under, roof, lo - 3.0, lo)  # outer, south
            s.box(corner + width, corner + width + 3.0, under, roof, lo, 10.0)  # outer, east
            s.box(0.0, corner, under, roof, hi, 10.0)  # the closed corner inside the L
        middles = np.array([[-5.0, 0.0, 0.0], [4.0, top, 14.0]])
        rects = [(0.0, corner + width, lo, hi), (corner, corner + width, lo, 10.0)]
    return s.mesh(), middles, rects


def _turn(degrees: float) -> np.ndarray:
    return trimesh.transformations.rotation_matrix(np.radians(degrees), (0.0, 1.0, 0.0))


def joined(graph, middles: np.ndarray) -> bool:
    """The graph's nodes nearest ``middles`` ((2, 3), m) are in one connected part."""
    nodes = sorted(graph.nodes)
    index = {n: i for i, n in enumerate(nodes)}
    pos = np.array([graph.nodes[n]["pos"] for n in nodes])
    ends = cKDTree(pos).query(middles)[1]
    pairs = np.array([(index[a], index[b]) for a, b in graph.edges()]).reshape(-1, 2)
    links = csr_array((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(len(nodes), len(nodes)))
    part = csgraph.connected_components(links, directed=False)[1]
    return bool(part[ends[0]] == part[ends[1]])


def in_passage(points: np.ndarray, turn: np.ndarray, rects: list) -> int:
    """How many of ``points`` ((n, 3), turned) stand in the passage's plan rectangles (unturned)."""
    local = points @ turn[:3, :3]  # the inverse turn
    inside = np.zeros(len(points), dtype=bool)
    for x0, x1, z0, z1 in rects:
        inside |= (local[:, 0] > x0) & (local[:, 0] < x1) & (local[:, 2] > z0) & (local[:, 2] < z1)
    return int(inside.sum())


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--extras", type=float, nargs="+", default=[0.05, 0.1, 0.2, 0.4, 0.6], help="width - 1 m")
    parser.add_argument("--yaws", type=float, nargs="+", default=[0.0, 22.0, 45.0], help="turns, degrees")
    parser.add_argument("--offsets", type=float, nargs="+", default=[0.0, 0.25, 0.5, 0.75], help="passage moves, m")
    parser.add_argument("--profiles", nargs="+", default=["flat", "stepped"], choices=["flat", "stepped"])
    parser.add_argument("--shapes", nargs="+", default=["straight", "turning"], choices=["straight", "turning"])
    parser.add_argument("--sides", nargs="+", default=["walls", "drops"], choices=["walls", "drops"])
    parser.add_argument("--method", default="grid", choices=["grid", "poisson"])
    parser.add_argument("--navmesh", action="store_true", help="also build the navmesh graph")
    args = parser.parse_args()

    config = AgentConfig(radius=0.5)
    agent = AgentShape.from_config(config)
    totals: dict[tuple[str, str, str, float], list[int]] = {}
    seconds = 0.0
    print("extra  profile  shape     sides  yaw   offset  sampled  in-passage  navmesh  cpu")
    for extra, profile, shape, sides, yaw, offset in itertools.product(
        args.extras, args.profiles, args.shapes, args.sides, args.yaws, args.offsets
    ):
        mesh, middles, rects = passage_level(extra, offset, profile, shape, sides)
        turn = _turn(yaw)
        mesh.apply_transform(turn)
        middles = middles @ turn[:3, :3].T
        started = time.process_time()
        graph = sampling.build_sampled_graph(mesh, sampling.Params(method=args.method), agent)
        took = time.process_time() - started
        seconds += took
        pos = np.array([graph.nodes[n]["pos"] for n in sorted(graph.nodes)])
        sampled = joined(graph, middles)
        nav = ""
        if args.navmesh:
            context = RunContext(mesh=mesh, agent=config, centre=mesh.bounds.mean(axis=0))
            nav = "yes" if joined(navmesh.g2s_build_graph(mesh=mesh, params=navmesh.Params(), context=context), middles) else "CUT"
        row = totals.setdefault((profile, shape, sides, extra), [0, 0, 0])
        row[0] += 1
        row[1] += sampled
        row[2] += nav == "yes"
        print(f"{extra:5.2f}  {profile:7s}  {shape:8s}  {sides:5s}  {yaw:4.0f}  {offset:6.2f}  {'yes' if sampled else 'CUT':>7}"
              f"  {in_passage(pos, turn, rects):10d}  {nav:>7}  {took:4.2f}", flush=True)
    print("\nprofile  shape     sides  extra  sampled joined  navmesh joined")
    for (profile, shape, sides, extra), (cases, sampled, nav) in totals.items():
        print(f"{profile:7s}  {shape:8s}  {sides:5s}  {extra:5.2f}  {sampled:3d} of {cases:3d}"
              f"  {f'{nav:3d} of {cases:3d}' if args.navmesh else ''}")
    print(f"sampling builder: {seconds:.1f} s CPU in all")


if __name__ == "__main__":
    main()
