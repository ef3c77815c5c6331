"""How deep the leaves of the navmesh graph are: places (dead-end rooms) against slivers along the walls.

Run: ``.venv/bin/python benchmarks/leaf_depths.py [--levels nav_test dungeon_1k building_1k terrain_1k castle_1k
my_level.obj] [--seeds 0 1 2] [--yaws 0 15 30 45]``

For every level (the names of ``benchmarks/analysis_quality.py``, or mesh
files) and yaw it builds the navmesh graph with the ``navmesh`` builder's
defaults for the default agent and prints, per kind of leaf, how many leaves
there are and their depths (:func:`g2s_plugins.terminals.coverage.leaf_depths`,
metres): quantiles and how many are shallower than 0.5 / 1 / 1.5 / 2 / 3 m.
The kinds come from the generators' ground truth, each leaf placed by its
centre turned back by the yaw: on ``dungeon`` levels ``dead-end room`` (a
room with one corridor), ``room`` (the other rooms) and ``corridor``
(outside every room); on ``building`` levels ``room`` (inside a room, on its
storey) and ``other`` (corridors, stairwells); elsewhere ``all``. Then
``rooms`` lines: per dead-end room (dungeon) or room (building) that holds
a leaf, the depth of its deepest leaf, that is the room's depth as
``leaf_min_depth`` sees it: a room whose deepest leaf is shallower than the
threshold gets no leaf terminal (the cover still reaches it). This is a
benchmark: nothing here asserts a target.
"""

from __future__ import annotations

import argparse
from collections import defaultdict

import networkx as nx
import numpy as np
import trimesh
from analysis_quality import levels_with_metadata

from g2s_core.config import AgentConfig
from g2s_core.errors import G2SError
from g2s_plugins.graph_builders import navmesh as navmesh_builder
from g2s_plugins.recast import build_navmesh
from g2s_plugins.samples.pieces import yaw_about_centre
from g2s_plugins.terminals.coverage import leaf_depths

THRESHOLDS = (0.5, 1.0, 1.5, 2.0, 3.0)
"""Depths the counts are given below, metres."""

QUANTILES = (0, 10, 25, 50, 75, 90, 100)


def rooms_of(metadata: dict) -> tuple[list[tuple[float, float, float, float, float]], list[str]]:
    """Known places of a generated level: ``(x0, x1, z0, z1, floor y)`` rectangles and each one's kind."""
    if "room_bounds" in metadata:  # dungeon
        corridors = np.zeros(len(metadata["room_bounds"]), dtype=np.int64)
        np.add.at(corridors, np.asarray(metadata["corridors"], dtype=np.int64).ravel(), 1)
        return ([(*bounds, 0.0) for bounds in metadata["room_bounds"]],
                ["dead-end room" if count == 1 else "room" for count in corridors])
    if "rooms" in metadata and "floor_heights" in metadata:  # building
        return [(r["x0"], r["x1"], r["z0"], r["z1"], r["y"]) for r in metadata["rooms"]], ["room"] * len(metadata["rooms"])
    return [], []


def place_of(point: np.ndarray, rooms: list, storey: float = 1.0) -> int:
    """The room holding ``point`` (x, y, z) in plan and within ``storey`` metres above its floor, -1 if none."""
    x, y, z = point
    for i, (x0, x1, z0, z1, floor) in enumerate(rooms):
        if x0 <= x <= x1 and z0 <= z <= z1 and abs(y - floor) < storey:
            return i
    return -1


def describe(depths: np.ndarray) -> str:
    quantiles = " ".join(f"{q:.2f}" for q in np.percentile(depths, QUANTILES)) if len(depths) else "-"
    below = " ".join(f"<{t:g}:{int((depths < t).sum())}" for t in THRESHOLDS)
    return f"{len(depths):4d}  quantiles {'/'.join(map(str, QUANTILES))}%: {quantiles}  {below}"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--levels", nargs="+", default=["nav_test", "dungeon_1k", "building_1k", "terrain_1k", "castle_1k"])
    parser.add_argument("--seeds", nargs="+", type=int, default=[0])
    parser.add_argument("--yaws", nargs="+", type=float, default=[0.0, 15.0, 30.0, 45.0])
    args = parser.parse_args()
    agent, params = AgentConfig(), navmesh_builder.Params()
    for name, mesh, metadata in levels_with_metadata(args.levels, args.seeds):
        rooms, kinds = rooms_of(metadata)
        for yaw in args.yaws:
            rotation = yaw_about_centre(mesh, yaw)
            turned = mesh if yaw == 0 else mesh.copy().apply_transform(rotation)
            try:
                navmesh = build_navmesh(turned.vertices, turned.faces, agent, params)
            except (RuntimeError, G2SError) as error:  # e.g. no walkable surface for the agent: say so, go on
                print(f"{name} yaw {yaw:g}: no navmesh: {error}", flush=True)
                continue
            graph = navmesh_builder.navmesh_graph(navmesh, agent, params.max_edge_gap)
            leaves = [node for node, degree in graph.degree() if degree == 1]
            depths = leaf_depths(graph, navmesh, leaves)
            centres = trimesh.transformations.transform_points(
                np.array([graph.nodes[leaf]["pos"] for leaf in leaves]).reshape(-1, 3), np.linalg.inv(rotation))
            places = [place_of(centre, rooms) for centre in centres]
            by_kind: dict[str, list[float]] = defaultdict(list)
            deepest: dict[int, float] = {}
            for place, depth in zip(places, depths.tolist()):
                kind = kinds[place] if place >= 0 else ("corridor" if "room_bounds" in metadata else "other" if rooms else "all")
                by_kind[kind].append(depth)
                if place >= 0 and kinds[place] in ("dead-end room", "room") and (
                        "room_bounds" not in metadata or kinds[place] == "dead-end room"):
                    deepest[place] = max(deepest.get(place, 0.0), depth)
            print(f"{name} yaw {yaw:g}: {navmesh.polygon_count} polygons, {len(leaves)} leaves "
                  f"({100 * len(leaves) / max(nx.number_of_nodes(graph), 1):.0f} % of the graph's nodes)")
            for kind in sorted(by_kind):
                print(f"  {kind:<14} {describe(np.array(by_kind[kind]))}")
            if deepest:
                print(f"  {'rooms':<14} {describe(np.array(sorted(deepest.values())))}", flush=True)


if __name__ == "__main__":
    main()
