"""model.graph_of: the graph networkx's add_nodes_from and add_edges_from make, order included."""

from __future__ import annotations

import random

import networkx as nx
import pytest

from g2s_core.model import graph_of


def layout(graph: nx.Graph) -> list:
    """Everything whose order an output can see: nodes, each node's neighbours (and predecessors) with their data."""
    rows = [("graph", graph.graph), ("nodes", list(graph.nodes(data=True)))]
    rows += [("adj", u, list(below.items())) for u, below in graph.adjacency()]
    if graph.is_directed():
        rows += [("pred", v, list(graph.pred[v].items())) for v in graph]
    return rows


@pytest.mark.parametrize("kind", [nx.Graph, nx.DiGraph])
@pytest.mark.parametrize("seed", range(20))
def test_graph_of_is_add_nodes_then_add_edges(kind, seed):
    rng = random.Random(seed)
    nodes = rng.sample(range(50), rng.randint(1, 30))
    # distinct edges (an undirected one once, in whichever orientation came first), as the stages give them
    distinct: dict = {}
    for u, v in ((rng.choice(nodes), rng.choice(nodes)) for _ in range(rng.randint(0, 60))):
        distinct.setdefault((u, v) if kind is nx.DiGraph else frozenset((u, v)), (u, v))
    edges = list(distinct.values())
    data = {e: {"weight": rng.random(), "loop": rng.random() < 0.2} for e in edges}
    expected = kind(name="x")
    expected.add_nodes_from((n, {"pos": (float(n), 0.0, 0.0)}) for n in nodes)
    expected.add_edges_from((u, v, dict(data[u, v])) for u, v in edges)
    built = graph_of(kind(name="x"), {n: {"pos": (float(n), 0.0, 0.0)} for n in nodes},
                     ((u, v, dict(data[u, v])) for u, v in edges))
    assert layout(built) == layout(expected)
    if kind is nx.Graph:  # one dict per undirected edge, as networkx shares it between both ends
        assert all(built.adj[u][v] is built.adj[v][u] for u, v in built.edges)
    else:
        assert all(built.succ[u][v] is built.pred[v][u] for u, v in built.edges)


def test_an_edge_given_again_keeps_its_place_and_takes_the_last_dict():
    built = graph_of(nx.Graph(), {0: {}, 1: {}, 2: {}}, [(0, 1, {"a": 1}), (1, 2, {}), (1, 0, {"b": 2})])
    assert list(built.adj[1]) == [0, 2]
    assert built.edges[0, 1] == {"b": 2}
