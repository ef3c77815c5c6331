"""Steiner solver timings: g2s ``kou`` and ``mehlhorn`` against networkx and rustworkx.

Run: ``.venv/bin/python benchmarks/steiner.py [--skip-slow] [--repeat 5]``

Each case is a square grid graph (a stand-in for a navmesh graph) with random
edge weights uniform in [0.5, 1.5) and a random sample of terminals, both from
a fixed seed. For every solver it prints the best wall time over ``--repeat``
runs (a single run when the first one takes over 5 s) and the tree weight.

* g2s times include converting the networkx graph to CSR and building the
  networkx result, i.e. exactly what the SteinerSolver hook does.
* networkx ``steiner_tree`` works on the networkx graph directly.
* rustworkx ``steiner_tree`` is timed on a prepared ``PyGraph``; the
  conversion from networkx is printed separately as "rx convert".

This is a benchmark, not a test: nothing here asserts a time.
"""

from __future__ import annotations

import argparse
import datetime
import os
import platform
import random
import time
from collections.abc import Callable
from dataclasses import dataclass

import networkx as nx
import rustworkx as rx
from networkx.algorithms.approximation import steiner_tree as nx_steiner_tree

from g2s_plugins.steiner.kou import kou_steiner_tree
from g2s_plugins.steiner.mehlhorn import mehlhorn_steiner_tree


@dataclass(frozen=True)
class Case:
    side: int
    terminals: int
    slow: bool = True  # run the solvers that take minutes here (networkx kou)
    kou: bool = True  # run g2s kou (|S| Dijkstras)


CASES = (
    Case(side=32, terminals=256),  # 1,024 nodes, 25 %
    Case(side=71, terminals=1260),  # 5,041 nodes, 25 %
    Case(side=71, terminals=1800),  # 5,041 nodes, 36 %: the rustworkx 18 ms reference point
    Case(side=316, terminals=25000, slow=False, kou=False),  # 99,856 nodes, 25 %
)


def grid_case(side: int, terminals: int, seed: int = 2026) -> tuple[nx.Graph, list[int]]:
    rng = random.Random(seed)
    graph = nx.convert_node_labels_to_integers(nx.grid_2d_graph(side, side), ordering="sorted")
    for u, v in graph.edges:
        graph.edges[u, v]["weight"] = rng.uniform(0.5, 1.5)
    return graph, sorted(rng.sample(range(graph.number_of_nodes()), terminals))


def to_rustworkx(graph: nx.Graph) -> tuple[rx.PyGraph, dict[int, int]]:
    pygraph = rx.PyGraph()
    index = dict(zip(graph.nodes, pygraph.add_nodes_from(list(graph.nodes))))
    pygraph.add_edges_from([(index[u], index[v], w) for u, v, w in graph.edges(data="weight")])
    return pygraph, index


def best_time(run: Callable[[], float], repeat: int) -> tuple[float, float]:
    """Best wall time (s) of ``run`` over ``repeat`` runs, and the weight it returned."""
    best, weight = float("inf"), float("nan")
    for attempt in range(repeat):
        start = time.perf_counter()
        weight = run()
        best = min(best, time.perf_counter() - start)
        if attempt == 0 and best > 5.0:
            break
    return best, weight


def nx_weight(tree: nx.Graph) -> float:
    return sum(w for _, _, w in tree.edges(data="weight"))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--skip-slow", action="store_true", help="skip networkx kou (minutes at 5k nodes)")
    parser.add_argument("--repeat", type=int, default=5, help="runs per solver; the best time is shown")
    args = parser.parse_args()

    print(f"date {datetime.date.today()}  python {platform.python_version()}  cpus {os.cpu_count()}  "
          f"networkx {nx.__version__}  rustworkx {rx.__version__}")
    print(f"{'nodes':>7} {'edges':>7} {'terms':>6}  {'solver':<18} {'time ms':>10} {'weight':>12}")
    for case in CASES:
        graph, terminals = grid_case(case.side, case.terminals)
        start = time.perf_counter()
        pygraph, index = to_rustworkx(graph)
        convert = time.perf_counter() - start
        rx_terminals = [index[t] for t in terminals]

        solvers: list[tuple[str, Callable[[], float]]] = [
            ("g2s mehlhorn", lambda: nx_weight(mehlhorn_steiner_tree(graph, terminals))),
        ]
        if case.kou:
            solvers.append(("g2s kou", lambda: nx_weight(kou_steiner_tree(graph, terminals))))
        solvers.append(("rustworkx", lambda: sum(rx.steiner_tree(pygraph, rx_terminals, float).edges())))
        solvers.append(("networkx mehlhorn", lambda: nx_weight(nx_steiner_tree(graph, terminals, method="mehlhorn"))))
        if case.slow and not args.skip_slow:
            solvers.append(("networkx kou", lambda: nx_weight(nx_steiner_tree(graph, terminals, method="kou"))))

        size = f"{graph.number_of_nodes():>7} {graph.number_of_edges():>7} {len(terminals):>6}"
        print(f"{size}  {'rx convert':<18} {convert * 1e3:>10.1f}", flush=True)
        for name, run in solvers:
            seconds, weight = best_time(run, args.repeat)
            print(f"{size}  {name:<18} {seconds * 1e3:>10.1f} {weight:>12.4f}", flush=True)


if __name__ == "__main__":
    main()
