"""A gap in a straight wall turned to Recast's grid: shut when narrower than the agent, open when wider (issue 9).

A wall ``--thick`` m thick (0.3, a door's depth; 3 makes the gap a short passage) and 1.5 m high crosses square ground 24 m a side through its centre, turned ``angle`` degrees from
the x axis, and reaches past the ground's edges, so the only way from one side to the other is a gap ``gap`` m wide
(between the jambs' faces) at the centre. The navmesh of a preset's ``graph.params`` and agent is *open* when a
point 3 m in front of the wall at the gap and one 3 m behind it lie on polygons joined through Detour's links. An agent of
radius r never passes a gap narrower than 2 r: such a gap open is wrong. A wider one is open to the agent, but
Recast's erosion, counted in whole cells from the edge cells' centres, keeps it shut until it is some cells wider
(map_analysis on main, 7 December 2026: 1.6 m at 45 degrees); the table counts those apart (a gap of exactly 2 r, touching both jambs, in neither count). ``clearance``: how near a polygon corner within 2 m of
the gap comes to a jamb, m (the agent's radius, less at most half a cell's diagonal where the polygons follow cells).

Gaps are given as offsets from the agent's diameter (``--offsets``, default -0.2 -0.1 -0.05 0 +0.05 m; with the
presets' agent of radius 0.5 m: 0.8, 0.9, 0.95, 1.0, 1.05 m), each at ``--angles`` (default 0 10 20 30 45), plus
``--wide-offsets`` (default +0.05 to +1.0; 1.05-2.0 m with the presets' agent) at 45 degrees alone.

Run: ``.venv/bin/python benchmarks/narrow_gaps.py [--presets map_analysis map_piece] [--angles 0 10 20 30 45]
[--offsets -0.2 -0.1 -0.05 0 0.05] [--wide-offsets 0.05 0.1 0.2] [--thick 0.3] [--erosion joined|recast]
[--shifts 0 0.05 0.1 0.15 0.2]`` (``--shifts``: the wall moved by (s, 0.6 s) m on the grid, each s a case of its own)
(``--erosion`` only where the installed code has ``graph.params.erosion``).
"""

from __future__ import annotations

import argparse
import math
import sys
from typing import Any

import numpy as np
import trimesh
from level_kinds import _Solids
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

from g2s_core.config import PRESETS_DIR, RunConfig, load_config
from g2s_plugins.recast import NavMesh, RecastParams, build_navmesh

HIGH = 1.5
"""The wall's height, m: over the agent's climb, under its height, so that Recast, which rasterises a solid's
surfaces and not its inside, finds no floor with head room on the ground inside a thick wall."""

GROUND = 12.0
"""Half the ground's side, m."""

PROBE = 3.0
"""How far in front of and behind the gap the two points are, m."""


def _frame(angle: float) -> tuple[np.ndarray, np.ndarray]:
    """(along, across): unit plan vectors (x, z) along the wall turned ``angle`` degrees and across it."""
    turn = math.radians(angle)
    return np.array([math.cos(turn), math.sin(turn)]), np.array([-math.sin(turn), math.cos(turn)])


def wall_spans(gap: float) -> list[tuple[float, float]]:
    """The wall's two pieces as (u0, u1) along it, either side of a gap ``gap`` m wide at u = 0, each reaching past
    the ground's corners."""
    reach = GROUND * math.sqrt(2.0) + 1.0
    return [(-reach, -gap / 2), (gap / 2, reach)]


def level(angle: float, gap: float, thick: float, shift: tuple[float, float] = (0.0, 0.0)) -> trimesh.Trimesh:
    """The ground and the wall ``thick`` m thick with its gap, turned ``angle`` degrees, the gap's middle at
    ``shift`` (x, z; the ground stays put, so the shift moves the wall on Recast's grid)."""
    along, across = _frame(angle)
    s = _Solids()
    for u0, u1 in wall_spans(gap):
        plan = [np.array(shift) + u * along + v * across for u in (u0, u1) for v in (-thick / 2, thick / 2)]
        s.prism(np.array([plan[0], plan[2], plan[3], plan[1]]), 0.0, HIGH)
    s.box(-GROUND, GROUND, -0.5, 0.0, -GROUND, GROUND)
    return s.mesh()


def jamb_distance(points: np.ndarray, angle: float, gap: float, thick: float,
                  shift: tuple[float, float] = (0.0, 0.0)) -> np.ndarray:
    """(N,) the plan distance from ``points`` ((N,2) x, z) to the nearer wall piece (a rectangle ``thick`` m
    across, the gap's middle at ``shift``), m."""
    along, across = _frame(angle)
    u, v = (points - np.array(shift)) @ along, (points - np.array(shift)) @ across
    dv = np.maximum(np.abs(v) - thick / 2, 0.0)
    return np.min([np.hypot(np.maximum.reduce([u0 - u, np.zeros_like(u), u - u1]), dv)
                   for u0, u1 in wall_spans(gap)], axis=0)


def preset_config(preset: str) -> RunConfig | None:
    """The config of the preset named ``preset`` (a `--presets` value), or None after saying on stderr that none is."""
    path = PRESETS_DIR / f"{preset}.yaml"
    if not path.is_file():
        print(f"--presets: {preset}: no such preset ({path.name})", file=sys.stderr)
        return None
    return load_config(path)


def joined(navmesh: NavMesh, a: np.ndarray, b: np.ndarray) -> bool:
    """Whether points ``a`` and ``b`` (3,) lie on polygons joined through the navmesh's links."""
    n = navmesh.polygon_count
    pairs = navmesh.portals().pairs
    graph = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(n, n))
    _, label = connected_components(graph, directed=False)
    ends = [navmesh.nearest_poly(p, (0.5, 1.0, 0.5))[0] for p in (a, b)]
    return min(ends) >= 0 and label[ends[0]] == label[ends[1]]


def measure(angle: float, gap: float, thick: float, agent: Any, params: RecastParams,
            shift: tuple[float, float] = (0.0, 0.0)) -> dict:
    """One case: whether the gap is open, and the polygons' corners' nearest approach to a jamb near it."""
    mesh = level(angle, gap, thick, shift)
    navmesh = build_navmesh(mesh.vertices, mesh.faces, agent, params)
    _, across = _frame(angle)
    probe = PROBE + thick / 2
    front, back = (np.array([shift[0] + k * probe * across[0], 0.0, shift[1] + k * probe * across[1]]) for k in (-1.0, 1.0))
    on_ground = navmesh.vertices[navmesh.vertices[:, 1] < 1.0]  # not the wall's top, floor too when it is thick
    corners = on_ground[:, [0, 2]]
    near = corners[np.hypot(corners[:, 0] - shift[0], corners[:, 1] - shift[1]) < 2.0 + thick / 2]
    return {"open": joined(navmesh, front, back),
            "clearance": float(jamb_distance(near, angle, gap, thick, shift).min()) if len(near) else math.nan}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--presets", nargs="+", default=["map_analysis", "map_piece"])
    ap.add_argument("--angles", type=float, nargs="+", default=[0.0, 10.0, 20.0, 30.0, 45.0])
    ap.add_argument("--offsets", type=float, nargs="+", default=[-0.2, -0.1, -0.05, 0.0, 0.05])
    ap.add_argument("--wide-offsets", type=float, nargs="+", default=[0.05, 0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.75, 0.8, 0.9, 1.0])
    ap.add_argument("--thick", type=float, default=0.3, help="the wall's thickness, m: 0.3 a door, 3 a passage")
    ap.add_argument("--erosion", choices=["joined", "recast"], default=None)
    ap.add_argument("--shifts", type=float, nargs="+", default=[0.0],
                    help="move the wall by (s, 0.6 s) m for each s: other places of its jambs on the grid")
    a = ap.parse_args(argv)
    for preset in a.presets:
        config = preset_config(preset)
        if config is None:
            return 2
        extra = {} if a.erosion is None else {"erosion": a.erosion}
        if extra and "erosion" not in RecastParams.model_fields:
            print("--erosion: this code's graph.params has no erosion", file=sys.stderr)
            return 2
        params = RecastParams(**{**config.graph.params, **extra})
        diameter = 2 * config.agent.radius
        cases = [(angle, o) for o in a.offsets for angle in a.angles]
        cases += [(45.0, o) for o in a.wide_offsets if (45.0, o) not in cases]
        cases = [(angle, o, (s, 0.6 * s)) for angle, o in cases for s in a.shifts]
        print(f"{preset} (agent radius {config.agent.radius:g} m, cell {params.cell_size or config.agent.radius / 2:g} m, "
              f"wall {a.thick:g} m thick"
              f"{', erosion ' + a.erosion if a.erosion else ''}): gap m, angle deg, open/shut, clearance m")
        wrong, shut_wide = 0, 0
        for angle, offset, shift in cases:
            gap = round(diameter + offset, 3)
            row = measure(angle, gap, a.thick, config.agent, params, shift)
            state = "open" if row["open"] else "shut"
            wrong += offset < 0 and row["open"]
            shut_wide += offset > 0 and not row["open"]
            flag = "  WRONG: narrower than the agent" if offset < 0 and row["open"] else ""
            moved = f" shift {shift[0]:g},{shift[1]:g}" if len(a.shifts) > 1 else ""
            print(f"  {gap:5.3f} {angle:4g}{moved} {state} {row['clearance']:.3f}{flag}", flush=True)
        narrow = sum(o < 0 for _, o, _ in cases)
        print(f"  {preset}: {wrong} of {narrow} gaps narrower than the agent open; "
              f"{shut_wide} of {sum(o > 0 for _, o, _ in cases)} wider ones shut")
    return 0


if __name__ == "__main__":
    sys.exit(main())
