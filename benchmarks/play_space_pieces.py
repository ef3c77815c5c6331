"""Map pieces with play points: the openings ``entry_exit`` finds over the piece the play space stands on against those
it finds over the whole mesh, on every kind of the tenth to twenty-first rounds.

Run: ``.venv/bin/python benchmarks/play_space_pieces.py [--rounds 10 21] [--configs map_piece map_piece_sampling]
[--yaws 0] [--detail]``

With ``graph.params.play_points`` the rays, the outer extent and ``leave_footprint`` read the faces of the parts the
play space stands on and of those touching them (:func:`g2s_plugins.play_space.play_space_faces`), not the whole mesh;
a piece's own parts must all stay: its walls, lintels and roofs are what close and hide its ways out. Per kind,
preset and yaw the piece is run once without play points, to take a play point: the position of the node of largest
area (a navmesh polygon's, or a sample's: the first of equal ones) among those within ``MATCH_DISTANCE`` of a known
opening, or among all when it has none or none lies that near (the main floor's, where a known opening leaves).
It is run again with that point twice: as the selector runs, and with the whole mesh in place of the piece
(``entry_exit.play_space_piece`` replaced by the mesh itself). It prints the mesh's parts
(:func:`g2s_plugins.play_space.mesh_parts`), the share of faces the piece keeps and, when the two runs' openings differ
(positions or widths by more than 1 mm), both lists.
"""

from __future__ import annotations

import argparse
import importlib
import sys

import numpy as np

from g2s_core import pipeline
from g2s_core.config import PRESETS_DIR, RunConfig, load_config, resolve_config
from g2s_core.errors import G2SError
from g2s_core.mesh import mesh_sha256
from g2s_core.registry import Registry
from g2s_plugins import play_space
from g2s_plugins.samples import pieces
from g2s_plugins.terminals import entry_exit

_SAME = 1e-3
"""Metres: openings whose midpoints, ends and widths agree this closely are the same."""


def _play_point(result, level) -> list[float]:
    """The position of the node of largest area near a known opening of ``level`` (see the module doc)."""
    nodes = [(node, data) for node, data in result.graph.nodes(data=True) if data.get("area", 0.0) > 0.0]
    positions = np.array([data["pos"] for _, data in nodes], dtype=np.float64)
    areas = np.array([data["area"] for _, data in nodes], dtype=np.float64)
    known = np.array([o.position for o in level.openings], dtype=np.float64).reshape(-1, 3)
    near = np.ones(len(nodes), dtype=bool)
    if len(known):
        close = (np.linalg.norm(positions[:, None, :] - known[None, :, :], axis=2) <= pieces.MATCH_DISTANCE).any(axis=1)
        near = close if close.any() else near
    best = int(np.flatnonzero(near)[np.argmax(areas[near])])
    return positions[best].tolist()


def _with_points(path, points) -> RunConfig:
    """The preset at ``path`` with ``graph.params.play_points`` = ``points``."""
    return resolve_config(path, {"graph.params.play_points": points})[0]


def _same(a, b) -> bool:
    if len(a) != len(b):
        return False
    return all(np.allclose(np.r_[x.position, x.p0, x.p1, x.width], np.r_[y.position, y.p0, y.p1, y.width], atol=_SAME)
               for x, y in zip(a, b))


def _listed(openings) -> str:
    return ", ".join(f"({o.position[0]:.2f}, {o.position[1]:.2f}, {o.position[2]:.2f}) {o.width:.2f}"
                     for o in openings) or "none"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, nargs=2, default=[10, 21], metavar=("FIRST", "LAST"))
    parser.add_argument("--configs", nargs="+", default=["map_piece", "map_piece_sampling"])
    parser.add_argument("--yaws", type=float, nargs="+", default=[0.0])
    parser.add_argument("--detail", action="store_true", help="list both runs' openings for every kind")
    args = parser.parse_args(argv)
    registry = Registry.from_entry_points()
    kinds = {}
    for round_ in range(args.rounds[0], args.rounds[1] + 1):
        kinds.update(importlib.import_module(f"piece_kinds{round_}").KINDS)
    as_built = entry_exit.play_space_piece
    for config in args.configs:
        path = PRESETS_DIR / f"{config}.yaml"
        plan = pipeline.plan(load_config(path), registry)
        same = runs = 0
        print(f"{config}: kind, yaw, parts, faces kept, openings with play points (piece; whole mesh)")
        for name, factory in kinds.items():
            for yaw in args.yaws:
                level = factory()
                level = pieces.turned(level, yaw) if yaw else level
                try:
                    point = _play_point(pipeline.run(plan, registry, level.mesh, name, mesh_sha256(level.mesh)), level)
                    played = pipeline.plan(_with_points(path, [point]), registry)
                    result = pipeline.run(played, registry, level.mesh, name, mesh_sha256(level.mesh))
                    entry_exit.play_space_piece = lambda mesh, *_: mesh
                    try:
                        whole = pipeline.run(played, registry, level.mesh, name, mesh_sha256(level.mesh))
                    finally:
                        entry_exit.play_space_piece = as_built
                except G2SError as error:
                    print(f"  {name:24s} {yaw:4g}  error: {str(error)[:60]}")
                    continue
                piece = as_built(level.mesh, result.graph, result.context.agent,
                                 entry_exit.Params(**(result.config["terminals"].get("params") or {})))
                mine = list(result.terminals.openings) if result.terminals is not None else []
                theirs = list(whole.terminals.openings) if whole.terminals is not None else []
                runs += 1
                same += _same(mine, theirs)
                parts = len(np.unique(play_space.mesh_parts(level.mesh)))
                line = (f"  {name:24s} {yaw:4g}  {parts:3d} parts  {len(piece.faces)}/{len(level.mesh.faces)} faces  "
                        f"{len(mine)}; {len(theirs)}")
                print(line + ("" if _same(mine, theirs) and not args.detail
                              else f"\n      piece: {_listed(mine)}\n      whole: {_listed(theirs)}"), flush=True)
        print(f"  total: the same openings in {same} of {runs} runs")
    return 0


if __name__ == "__main__":
    sys.exit(main())
