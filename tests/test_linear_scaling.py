"""A sampled walking flow with linear scaling (``scaling: linear``): by hand on a corridor, unbiased over the sources,
and the settings that choose it."""

from __future__ import annotations

import networkx as nx
import numpy as np
import pytest
import scipy.sparse as sp
from scipy.sparse import csgraph

from g2s_core.config import find_config, load_raw_config
from g2s_plugins import _trees, traffic
from g2s_plugins._surface import CollapseParams
from g2s_plugins.analyzers import flow as flow_analyzer
from g2s_plugins.terminals import coverage


def corridor(n: int) -> sp.csr_array:
    """Symmetric unit edge lengths of a corridor 0 - 1 - ... - n-1."""
    return traffic.surface_arrays(nx.path_graph(n), weighted=False).adjacency


def test_the_corridor_by_hand():
    # from source 0 of a corridor of four 1 m² nodes the plain sum puts both farther nodes' weight on node 1 (2)
    # and node 3's on node 2 (1); linearly scaled, each pair counts twice the share of its path already walked:
    # node 1: 2 x 1 x (1/2 + 1/3) = 5/3, node 2: 2 x 2 x 1/3 = 4/3
    values = np.ones(4)
    assert traffic.split_path_flow(corridor(4), np.array([0]), values).tolist() == [[0.0, 2.0, 1.0, 0.0]]
    through = traffic.linear_through(corridor(4), np.array([0]), values, "split")
    assert through[0].tolist() == pytest.approx([0.0, 5 / 3, 4 / 3, 0.0])
    # the first-path trees give the same here (one path per pair)
    assert traffic.linear_through(corridor(4), np.array([0]), values, "first")[0] == pytest.approx(through[0])


def test_next_to_a_source_it_reads_less_busy():
    # the plain sum gives the node beside a corridor's end every walk that starts there (8 of 9 m²); scaled, the far
    # pairs count little there: 2 x (1/2 + ... + 1/8) = 3.44
    through = traffic.linear_through(corridor(9), np.array([0]), np.ones(9), "split")[0]
    assert traffic.split_path_flow(corridor(9), np.array([0]), np.ones(9))[0][1] == 7.0
    assert through[1] == pytest.approx(2 * sum(1 / t for t in range(2, 9)))


def unit_grid() -> tuple[sp.csr_array, np.ndarray]:
    """A 4 x 5 grid with diagonals (lengths 1 and sqrt 2: many tied paths) and unequal areas."""
    graph = nx.grid_2d_graph(4, 5)
    graph.add_edges_from(((x, y), (x + 1, y + d)) for x, y in list(graph) for d in (-1, 1) if (x + 1, y + d) in graph)
    graph = nx.convert_node_labels_to_integers(graph, ordering="sorted", label_attribute="at")
    for u, v in graph.edges:
        (a, b), (c, d) = graph.nodes[u]["at"], graph.nodes[v]["at"]
        graph.edges[u, v]["weight"] = float(np.hypot(a - c, b - d))
    area = 1.0 + np.arange(graph.number_of_nodes()) % 3
    return traffic.surface_arrays(graph).adjacency, area


def test_every_source_weighted_by_its_area_gives_the_exact_flow():
    # the sample draws each source with probability a_s / A and weighs it A / k, so the estimate's expectation is
    # the sum over every source of a_s x its term: with split ties each pair's two directions add up to 1 along
    # its paths, so that sum is the exact flow (unbiased)
    adjacency, area = unit_grid()
    exact, sampled = traffic.od_flow(adjacency, area, ties="split")
    assert sampled is None
    scaled = area @ traffic.linear_through(adjacency, np.arange(len(area)), area, "split")
    assert scaled == pytest.approx(exact, rel=1e-9)
    # and the plain sum too, each source's term differently spread
    plain = area @ traffic.split_path_flow(adjacency, np.arange(len(area)), area)
    assert plain == pytest.approx(exact, rel=1e-9)


@pytest.mark.parametrize("stored", ["graph", "zeros"])
def test_coincident_nodes_keep_their_pairs(stored):
    # a corridor 0 - 1 - 2 - 3 - 4 of 1 m, 0, 0 and 1 m edges (nodes 1, 2, 3 at one position), areas 1-5 m²; the exact
    # flow through node 2 is 2 x (1 + 2) x (4 + 5) = 54. From source 1 the pair (1, 3) passes node 2 half way (its
    # zero-length steps counted as the graph's arrays store them, MIN_LENGTH each): 2 x 4 x 1/2 = 4. With the zeros
    # stored as such that pair lay at distance 0 and was dropped: node 2 summed to 38 over every source
    graph = nx.Graph()
    graph.add_weighted_edges_from([(0, 1, 1.0), (1, 2, 0.0), (2, 3, 0.0), (3, 4, 1.0)])
    rows, cols = [0, 1, 2, 3, 1, 2, 3, 4], [1, 2, 3, 4, 0, 1, 2, 3]
    adjacency = traffic.surface_arrays(graph).adjacency if stored == "graph" else \
        sp.csr_array(([1.0, 0.0, 0.0, 1.0] * 2, (rows, cols)), shape=(5, 5))
    area = np.arange(1.0, 6.0)
    exact, _ = traffic.od_flow(adjacency, area, ties="split")
    assert exact.tolist() == [0.0, 24.0, 54.0, 60.0, 0.0]
    assert traffic.linear_through(adjacency, np.array([1]), area, "split")[0][2] == pytest.approx(4.0)
    for ties in ("split", "first"):
        assert area @ traffic.linear_through(adjacency, np.arange(5), area, ties) == pytest.approx(exact, rel=1e-9)


def test_only_a_sampled_flow_is_scaled():
    adjacency, area = unit_grid()
    exact, _ = traffic.od_flow(adjacency, area, ties="split")
    assert np.array_equal(traffic.od_flow(adjacency, area, ties="split", scaling="linear")[0], exact)
    plain, sampled = traffic.od_flow(adjacency, area, 4, ties="split")
    scaled, _ = traffic.od_flow(adjacency, area, 4, ties="split", scaling="linear")
    assert sampled == 4 and not np.allclose(plain, scaled)
    # the same four sources (seed 0), each term scaled: the sum of linear_through weighted as the sample weighs
    sources, counts = np.unique(np.random.default_rng(0).choice(20, size=4, p=area / area.sum()), return_counts=True)
    expected = (counts * area.sum() / 4) @ traffic.linear_through(adjacency, sources, area, "split")
    assert scaled == pytest.approx(expected, rel=1e-12)


def brute_force_linear(graph: nx.Graph, source: int, area: np.ndarray, ties: str) -> np.ndarray:
    """(n,) the linearly scaled through-weight from ``source``, pair by pair: 2 d(s, v) sum_t a_t share_st(v) / d(s, t),
    the share over networkx's shortest paths (``split``: every one, evenly) or along scipy's predecessor tree
    (``first``)."""
    distance = nx.single_source_dijkstra_path_length(graph, source, weight="weight")
    through = np.zeros(len(graph))
    if ties == "split":
        for t in distance:
            if t == source:
                continue
            paths = list(nx.all_shortest_paths(graph, source, t, weight="weight"))
            for path in paths:
                for v in path[1:-1]:
                    through[v] += area[t] / distance[t] / len(paths)
    else:
        adjacency = nx.to_scipy_sparse_array(graph, nodelist=range(len(graph)), weight="weight", format="csr")
        _, predecessor = csgraph.dijkstra(adjacency, indices=source, return_predecessors=True)
        for t in distance:
            v = predecessor[t]
            while t != source and v != source:
                through[v] += area[t] / distance[t]
                v = predecessor[v]
    return np.array([2.0 * distance.get(v, 0.0) * through[v] for v in range(len(graph))])


@pytest.mark.parametrize("ties", ["split", "first"])
@pytest.mark.parametrize("seed", range(4))
def test_the_extension_is_the_pair_by_pair_sum(seed, ties):
    # a random graph of integer lengths 1-3 (many tied paths, some nodes out of reach) and random areas: every
    # source's row against the sum over its pairs, one at a time
    rng = np.random.default_rng(seed)
    graph = nx.gnm_random_graph(16, 26, seed=seed)
    for a, b in graph.edges:
        graph.edges[a, b]["weight"] = float(rng.integers(1, 4))
    area = rng.uniform(0.5, 5.0, len(graph))
    adjacency = nx.to_scipy_sparse_array(graph, nodelist=range(len(graph)), weight="weight", format="csr")
    through = traffic.linear_through(adjacency, np.arange(len(graph)), area, ties)
    for source in range(len(graph)):
        assert through[source] == pytest.approx(brute_force_linear(graph, source, area, ties), rel=1e-12, abs=1e-12)


@pytest.mark.parametrize("ties", ["split", "first"])
def test_the_same_bits_on_one_thread_or_two_in_any_source_order(monkeypatch, ties):
    # a grid with diagonals (ties everywhere) and a corridor off it (the first-path search walks its passages)
    adjacency, area = unit_grid()
    graph = nx.from_scipy_sparse_array(adjacency)
    nx.add_path(graph, [19, 20, 21, 22, 23], weight=0.7)
    adjacency = nx.to_scipy_sparse_array(graph, nodelist=range(24), weight="weight", format="csr")
    area = np.concatenate([area, [0.5, 2.0, 1.5, 3.0]])
    sources = np.array([3, 23, 0, 11, 19, 7])
    through = traffic.linear_through(adjacency, sources, area, ties)
    monkeypatch.setattr(traffic, "THREADS", 1)
    assert np.array_equal(traffic.linear_through(adjacency, sources, area, ties), through)
    assert np.array_equal(traffic.linear_through(adjacency, sources[::-1], area, ties), through[::-1])
    # the corridor's far end by hand: from 23, node 22 carries every other reached node's area over its distance
    distance = csgraph.dijkstra(adjacency, indices=23)
    beyond = np.arange(22)
    assert through[1][22] == pytest.approx(2 * 0.7 * np.sum(area[beyond] / distance[beyond]), rel=1e-12)


def test_bad_input_is_refused():
    with pytest.raises(ValueError, match="ties"):
        traffic.linear_through(corridor(3), np.array([0]), np.ones(3), "all")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="source"):
        traffic.linear_through(corridor(3), np.array([3]), np.ones(3), "split")
    # (linear_through floors every length at MIN_LENGTH, so only the extension itself sees a negative one)
    negative = traffic.extension_csr(sp.csr_array(([-1.0, -1.0], ([0, 1], [1, 0])), shape=(2, 2)))
    with pytest.raises(ValueError, match="negative"):
        _trees.linear_path_flow(*negative, np.array([0], dtype=np.int32), np.ones(2), "first", 0.0, 1)


def test_the_settings_that_choose_it():
    # none by default everywhere; the sampling preset sets linear for the analyzer, the guarantee's heat flow and the
    # traffic-aware cover alike, so the three read one flow
    assert traffic.WALKING_SCALING == "none"
    assert flow_analyzer.Params().scaling == CollapseParams().heat_scaling == coverage.Params().traffic_scaling == "none"
    raw = load_raw_config(find_config("map_analysis_sampling"))
    (analyzer,) = (a for a in raw["analyzers"] if a["plugin"] == "flow")
    assert analyzer["params"]["scaling"] == raw["simplify"]["params"]["heat_scaling"] == "linear"
    assert raw["terminals"]["params"]["traffic_scaling"] == "linear"
    with pytest.raises(ValueError):
        flow_analyzer.Params(scaling="quadratic")
