"""How small the structure gets when simplification may join nodes that do not see each other (a bound).

Run: ``.venv/bin/python benchmarks/join_bound.py [--offsets los 1 2 none] [--steps 60 40]
[--levels nav_test dungeon_1k building_1k castle_1k terrain_1k] [--seeds 0 1 2]``

``map_analysis`` joins the covering terminals by Steiner and loop paths and
simplification then keeps every path node past which line of sight fails.
This script runs ``benchmarks/analysis_quality.py`` on ``map_analysis``
with its simplification relaxed, to measure what line of sight costs in
structure size and what dropping it would cost in rho. It registers a
simplify predicate for this run only, ``route_offset`` (not a plugin of
the package): B of a chain A -> B -> C may go when every test of the
preset's ``surface_los`` but line of sight holds (traffic step, normals,
leaves off the surface) and either ``surface_los`` itself holds or the
route the removed nodes trace from A to C (the positions of every node
removed between them, B included) lies within ``offset`` metres of the
straight segment A -> C. The columns:

``los``
    the preset as it is (line of sight required);
``1``, ``2``, ...
    line of sight, or a route within that many metres of the new edge;
``none``
    no line of sight at all: the tests that protect rho (traffic step,
    normals) alone decide.

An edge of a ``none`` or offset structure may cross a wall or a pillar:
these are measuring sticks, not structures a preset should draw. Each
``--steps`` value is the predicate's ``max_traffic_step`` (``off``: none).
This is a benchmark: nothing here asserts a target; the figures are in
docs/analysis_quality.md ("Joining without line of sight").
"""

from __future__ import annotations

import argparse
import tempfile
from collections.abc import Callable
from pathlib import Path

import networkx as nx
import numpy as np
import yaml

import analysis_quality
from g2s_core.config import find_config, load_raw_config
from g2s_core.model import RunContext
from g2s_core.plugin import hookimpl
from g2s_core.registry import Registry
from g2s_plugins._surface import CollapseParams, collapse_rule
from g2s_plugins.predicates import surface_los

Predicate = Callable[[nx.DiGraph, int, int, int], bool]


class RouteOffsetParams(CollapseParams):
    """``surface_los``'s parameters, and how far the removed nodes' route may lie from a new edge."""

    offset: float | None = None
    """m; None: line of sight is not asked at all."""


class RouteOffset:
    """Surface LoS, or a removed route within ``offset`` metres of the new edge (a measuring stick)."""

    NAME = "route_offset"
    Params = RouteOffsetParams

    @hookimpl
    def g2s_simplify_predicate(self, params: RouteOffsetParams, context: RunContext) -> Predicate:
        """The relaxed predicate over the run's navmesh (see the module docs)."""
        sees = surface_los.g2s_simplify_predicate(surface_los.Params(**params.model_dump(exclude={"offset"})), context, None, None)
        allowed = collapse_rule(params, lambda start, end: True, context.graph)
        routes: dict[tuple[int, int], np.ndarray] = {}  # the removed nodes' positions along each new edge, (k, 3) m

        def route(u: int, v: int) -> np.ndarray:
            return routes.get((min(u, v), max(u, v)), np.empty((0, 3)))

        def predicate(tree: nx.DiGraph, a: int, b: int, c: int) -> bool:
            if not allowed(tree, a, b, c):
                return False
            points = np.vstack([route(a, b), np.asarray(tree.nodes[b]["pos"], float)[None, :], route(b, c)])
            if params.offset is not None and not sees(tree, a, b, c):
                if _farthest_from_segment(points, tree.nodes[a]["pos"], tree.nodes[c]["pos"]) > params.offset:
                    return False
            routes[min(a, c), max(a, c)] = points
            return True

        return predicate


def _farthest_from_segment(points: np.ndarray, start, end) -> float:
    """The largest distance (m) of ``points`` (k, 3) from the segment ``start`` -> ``end``."""
    start, end = np.asarray(start, float), np.asarray(end, float)
    along = end - start
    length2 = float(along @ along)
    t = np.clip((points - start) @ along / length2, 0.0, 1.0) if length2 > 0 else np.zeros(len(points))
    return float(np.linalg.norm(points - (start + t[:, None] * along), axis=1).max())


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--offsets", nargs="+", default=["los", "1", "2", "none"])
    parser.add_argument("--steps", nargs="+", default=["60", "40"])
    parser.add_argument("--levels", nargs="+", default=["nav_test", "dungeon_1k", "building_1k", "castle_1k", "terrain_1k"])
    parser.add_argument("--seeds", nargs="+", default=["0", "1", "2"])
    args = parser.parse_args()
    registry = Registry.from_entry_points()
    registry.register(RouteOffset(), package="benchmarks", entry_point="simplify.route_offset")
    preset_params = load_raw_config(find_config("map_analysis"))["simplify"]["params"]
    with tempfile.TemporaryDirectory() as folder:
        configs = []
        for offset in args.offsets:
            for step in args.steps:
                params = {**preset_params, "max_traffic_step": None if step == "off" else float(step)}
                if offset != "los":
                    params["offset"] = None if offset == "none" else float(offset)
                plugin = "surface_los" if offset == "los" else "route_offset"
                path = Path(folder) / f"{offset}_step{step}.yaml"
                path.write_text(yaml.safe_dump({"extends": "map_analysis", "simplify": {"plugin": plugin, "params": params}}))
                configs.append(str(path))
        analysis_quality.main(["--presets", *configs, "--levels", *args.levels, "--seeds", *args.seeds], registry)


if __name__ == "__main__":
    main()
