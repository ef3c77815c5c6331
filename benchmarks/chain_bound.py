"""How small line-of-sight simplification could make a structure: the nodes kept inside its chains (a bound).

Run: ``.venv/bin/python benchmarks/chain_bound.py [--preset map_analysis] [--levels nav_test dungeon_1k]
[--seeds 0 1 2]``

A *chain* of the rooted forest (before simplification) runs from a node
that Algorithm 4 keeps whatever the predicate says (a root, a leaf, a
terminal, a branch node or the end of a loop edge) through nodes with one
child and nothing else to the next such node. For each chain the script
counts the interior nodes kept by

``greedy``
    the preset's rule as Algorithm 4 applies it along a chain (remove the
    next node while the predicate holds from the last kept one);
``optimal``
    the fewest interior nodes such that the predicate holds from each kept
    node to the next for every node skipped (dynamic programming over the
    chain, O(k^2) predicate calls for k nodes);
``corners``
    the fewest hops when a kept node may also stand at a corner of its
    polygon (its navmesh vertices, moved 5 cm towards the polygon's centre)
    and consecutive points only need Detour's raycast to be clear: the
    positions a string-pulled path would use. An upper estimate of what
    moving nodes could save (no normal, traffic or surface-gap test).

and prints the structure's share of the polygons as the preset makes it,
then that share with each chain's greedy count replaced by the optimal one
and by the corner one. (The preset also removes branch nodes that see past
themselves and shortens loops; those removals are the same in all three.)
This is a
benchmark: nothing here asserts a target; the figures are in
docs/analysis_quality.md ("Where the losses are").
"""

from __future__ import annotations

import argparse
from collections.abc import Callable

import networkx as nx
import numpy as np

from analysis_quality import levels
from g2s_core import pipeline
from g2s_core.config import find_config, load_raw_config, parse_config
from g2s_core.mesh import mesh_sha256
from g2s_core.registry import Registry
from g2s_plugins.recast import NavMesh

CORNER_INSET = 0.05
"""m: a corner point's distance from its navmesh vertex towards the polygon's centre, inside the polygon."""


def chains(forest: nx.DiGraph) -> list[list[int]]:
    """The forest's chains, each ``[anchor, interior..., end]`` along tree edges (loop edges end chains)."""
    children: dict[int, list[int]] = {node: [] for node in forest}
    fixed = set(forest.graph["roots"])
    for a, b, loop in forest.edges(data="loop", default=False):
        if loop:
            fixed.update((a, b))
        else:
            children[a].append(b)
    fixed.update(node for node, terminal in forest.nodes(data="terminal", default=False) if terminal)
    fixed.update(node for node, kids in children.items() if len(kids) != 1)
    found = []
    for anchor in sorted(fixed):
        for child in sorted(children[anchor]):
            chain = [anchor, child]
            while chain[-1] not in fixed:
                chain.append(children[chain[-1]][0])
            if len(chain) > 2:
                found.append(chain)
    return found


def greedy_kept(chain: list[int], skip: Callable[[int, int], bool]) -> int:
    kept, anchor = 0, 0
    for j in range(1, len(chain) - 1):
        if not skip(anchor, j + 1):
            kept, anchor = kept + 1, j
    return kept


def optimal_kept(chain: list[int], skip: Callable[[int, int], bool]) -> int:
    hops = [0] + [len(chain)] * (len(chain) - 1)
    for j in range(1, len(chain)):
        hops[j] = min(hops[i] + 1 for i in range(j) if i == j - 1 or skip(i, j))
    return hops[-1] - 1


def corner_kept(chain: list[int], forest: nx.DiGraph, navmesh: NavMesh) -> int:
    points: list[tuple[int, np.ndarray]] = []  # (position along the chain, point); each position's centre first
    centres: set[int] = set()
    for index, node in enumerate(chain):
        centre = np.asarray(forest.nodes[node]["pos"], dtype=np.float64)
        centres.add(len(points))
        points.append((index, centre))
        polygon = forest.nodes[node].get("polygon", -1)
        if 0 < index < len(chain) - 1 and polygon >= 0:
            for vertex in navmesh.polygons[polygon]:
                if vertex < 0:
                    break
                corner = navmesh.vertices[vertex].astype(np.float64)
                towards = centre - corner
                points.append((index, corner + CORNER_INSET * towards / max(float(np.linalg.norm(towards)), 1e-9)))
    pairs = [(a, b) for a in range(len(points)) for b in range(len(points)) if points[b][0] > points[a][0]]
    clear = navmesh.raycast_many(np.array([points[a][1] for a, _ in pairs]), np.array([points[b][1] for _, b in pairs]))
    hops = [0] + [len(chain)] * (len(points) - 1)
    for (a, b), sees in sorted(zip(pairs, clear), key=lambda item: points[item[0][0]][0]):
        if sees or (a in centres and b in centres and points[b][0] == points[a][0] + 1):  # a graph edge
            hops[b] = min(hops[b], hops[a] + 1)
    return min(hops[b] for b in range(len(points)) if points[b][0] == len(chain) - 1) - 1


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--preset", default="map_analysis")
    parser.add_argument("--levels", nargs="+", default=["nav_test", "dungeon_1k"])
    parser.add_argument("--seeds", nargs="+", type=int, default=[0])
    args = parser.parse_args()
    registry = Registry.from_entry_points()
    plan = pipeline.plan(parse_config(load_raw_config(find_config(args.preset)), args.preset), registry, args.preset)
    print(f"{'level':<18} {'polys':>6} {'struct':>7} {'optimal':>8} {'corners':>8}")
    for name, mesh in levels(args.levels, args.seeds):
        result = pipeline.run(plan, registry, mesh, name, mesh_sha256(mesh))
        forest, navmesh, n = result.forest, result.context.navmesh, result.graph.number_of_nodes()
        predicate = pipeline.Step(registry, plan.stages["simplify"], result, {}).call()
        counts = np.zeros(3, dtype=int)
        for chain in chains(forest):
            def skip(i: int, j: int, chain: list[int] = chain) -> bool:
                return all(predicate(forest, chain[i], chain[x], chain[j]) for x in range(i + 1, j))
            counts += (greedy_kept(chain, skip), optimal_kept(chain, skip), corner_kept(chain, forest, navmesh))
        greedy, optimal, corners = (100 * count / n for count in counts)
        share = 100 * result.structure.number_of_nodes() / n
        print(f"{name:<18} {n:>6} {share:6.1f}% {share - greedy + optimal:7.1f}% {share - greedy + corners:7.1f}%",
              flush=True)


if __name__ == "__main__":
    main()
