"""Does the sampled graph join two floors through a narrow alley, and how straight is its way through?

Run: ``.venv/bin/python benchmarks/narrow_passages.py [--widths 1.6 1.8 2.0 2.4] [--turns 0 17 30 45]
[--seeds 0 1 2] [--set gap_radius=0] [--set connect_radius=2.5 ...]``

The level (built here, Y up, metres): a floor slab 38 x 20 m, its top at
y = 0 (x from -10 to 28, z from -10 to 10), and on it two closed blocks 3 m
high, from x = 10 to 18, that leave between them an alley ``width`` metres
wide along x, centred on z = 0. So two open floors, x in [-10, 10] and
[18, 28], are joined only by the 8 m alley; the blocks' roofs are walkable
but out of reach (3 m up). The whole level is turned about the vertical
axis by ``turn`` degrees, so that the alley does not follow the axes the
samples' cKDTree and the agent checks' rays are aligned with. The agent is
the presets' (radius 0.5 m, so spacing 1 m and clearance 0.5 m by default:
the band of candidates left in the alley is ``width - 1`` m wide).

For each width, turn and ``sampling`` seed the builder runs with its
defaults (and the ``--set`` parameters); a case prints whether the two
floors' centres, (0, 0, 0) and (23, 0, 0) before the turn, are in one
connected part of the graph, the detour ratio (the graph distance between
the samples nearest the two centres over their straight distance, which is
walkable: the alley's axis passes through both centres; ``inf`` when cut),
and the graph's edge count. The totals follow. This is a benchmark:
nothing here asserts a target; the figures are in docs/sampling.md
("Narrow passages and spacing").
"""

from __future__ import annotations

import argparse
import time

import numpy as np
import trimesh
import yaml
from scipy.sparse import csgraph, csr_array
from scipy.spatial import cKDTree

from g2s_core.config import AgentConfig
from g2s_core.model import RunContext
from g2s_plugins.graph_builders import sampling

FLOOR_CENTRES = np.array([[0.0, 0.0, 0.0], [23.0, 0.0, 0.0]])
"""The two open floors' centres before the turn, m."""


def _box(lo: tuple[float, float, float], hi: tuple[float, float, float]) -> trimesh.Trimesh:
    box = trimesh.creation.box(extents=np.subtract(hi, lo))
    box.apply_translation(np.add(lo, hi) / 2.0)
    return box


def _turn(degrees: float) -> np.ndarray:
    return trimesh.transformations.rotation_matrix(np.radians(degrees), (0.0, 1.0, 0.0))


def alley_level(width: float, turn: float) -> trimesh.Trimesh:
    """Two floors joined by an 8 m alley ``width`` m wide between closed 3 m blocks, turned by ``turn`` degrees."""
    parts = [
        _box((-10.0, -0.2, -10.0), (28.0, 0.0, 10.0)),
        _box((10.0, 0.0, 0.5 * width), (18.0, 3.0, 10.0)),
        _box((10.0, 0.0, -10.0), (18.0, 3.0, -0.5 * width)),
    ]
    mesh = trimesh.util.concatenate(parts)
    mesh.apply_transform(_turn(turn))
    return mesh


def detour_ratio(graph, centres: np.ndarray) -> float:
    """Graph distance between the samples nearest ``centres`` ((2, 3), m) over their straight distance; inf if cut."""
    nodes = sorted(graph.nodes)
    pos = np.array([graph.nodes[n]["pos"] for n in nodes])
    index = {n: i for i, n in enumerate(nodes)}
    ends = cKDTree(pos).query(centres)[1]
    edges = np.array([(index[a], index[b], w) for a, b, w in graph.edges(data="weight")])
    matrix = csr_array((edges[:, 2], (edges[:, 0].astype(int), edges[:, 1].astype(int))), shape=(len(nodes), len(nodes)))
    along = csgraph.dijkstra(matrix, directed=False, indices=int(ends[0]))[int(ends[1])]
    return float(along / np.linalg.norm(pos[ends[1]] - pos[ends[0]]))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--widths", type=float, nargs="+", default=[1.6, 1.8, 2.0, 2.4], help="alley widths, m")
    parser.add_argument("--turns", type=float, nargs="+", default=[0.0, 17.0, 30.0, 45.0], help="turns, degrees")
    parser.add_argument("--seeds", type=int, nargs="+", default=[0, 1, 2], help="sampling seeds")
    parser.add_argument("--set", action="append", default=[], metavar="KEY=VALUE", help="a sampling parameter (YAML value)")
    args = parser.parse_args()
    extra = {}
    for item in args.set:
        key, _, value = item.partition("=")
        extra[key] = yaml.safe_load(value)

    agent = AgentConfig(radius=0.5)
    cut = cases = 0
    ratios: list[float] = []
    edge_total = 0
    seconds = 0.0
    print("width  turn  seed  joined  detour  edges")
    for width in args.widths:
        for turn in args.turns:
            mesh = alley_level(width, turn)
            centres = FLOOR_CENTRES @ _turn(turn)[:3, :3].T
            for seed in args.seeds:
                context = RunContext(mesh=mesh, agent=agent, centre=mesh.bounds.mean(axis=0))
                started = time.process_time()
                graph = sampling.g2s_build_graph(mesh=mesh, params=sampling.Params(seed=seed, **extra), context=context)
                seconds += time.process_time() - started
                ratio = detour_ratio(graph, centres)
                joined = bool(np.isfinite(ratio))
                cases += 1
                cut += not joined
                edge_total += graph.number_of_edges()
                if joined:
                    ratios.append(ratio)
                print(f"{width:5.2f} {turn:5.0f} {seed:5d}  {'yes' if joined else 'CUT':>6}  {ratio:6.3f}  {graph.number_of_edges():5d}", flush=True)
    spread = f"{min(ratios):.3f}-{max(ratios):.3f}, mean {np.mean(ratios):.3f}" if ratios else "none joined"
    print(f"cut in {cut} of {cases} cases; detour ratio of the joined {spread}; "
          f"{edge_total} edges in all; {seconds:.1f} s CPU building; parameters {extra or 'defaults'}")


if __name__ == "__main__":
    main()
