"""GraphBuilder ``sampling``: the gap rule (``gap_radius``) joins the samples a thin band leaves apart, and only those."""

from __future__ import annotations

import networkx as nx
import numpy as np
import trimesh
from scipy import sparse
from scipy.sparse import csgraph
from scipy.spatial import cKDTree

from g2s_core.config import AgentConfig
from g2s_core.model import RunContext
from g2s_plugins.graph_builders import sampling

AGENT = AgentConfig(radius=0.5, height=2.0, max_climb=0.4, max_slope=45.0)
"""Spacing 1 m, connect_radius 2 m, gap_radius 3 m, clearance 0.5 m by default."""


def box(lo, hi) -> trimesh.Trimesh:
    lo, hi = np.asarray(lo, dtype=float), np.asarray(hi, dtype=float)
    return trimesh.creation.box(extents=hi - lo, transform=trimesh.transformations.translation_matrix((lo + hi) / 2))


def alley(width: float) -> trimesh.Trimesh:
    """Two open floors (x < 10 and x > 18) joined by an 8 m alley ``width`` m wide between closed 3 m blocks."""
    return trimesh.util.concatenate(
        [
            box((-10, -0.2, -10), (28, 0, 10)),
            box((10, 0, 0.5 * width), (18, 3, 10)),
            box((10, 0, -10), (18, 3, -0.5 * width)),
        ]
    )


def build(mesh: trimesh.Trimesh, **params) -> nx.Graph:
    context = RunContext(mesh=mesh, agent=AGENT, centre=np.asarray(mesh.bounds).mean(axis=0))
    return sampling.g2s_build_graph(mesh=mesh, params=sampling.Params(**params), context=context)


def nearest(graph: nx.Graph, point) -> int:
    return min(graph, key=lambda n: np.linalg.norm(np.subtract(graph.nodes[n]["pos"], point)))


def test_a_thin_alley_the_connect_radius_cuts_is_joined_straight_through():
    mesh = alley(1.6)  # a band of candidates 0.6 m wide; seed 0 leaves a gap over 2 m in it
    west, east = (0.0, 0.0, 0.0), (23.0, 0.0, 0.0)
    off = build(mesh, gap_radius=0)
    # the pick's own samples in the alley (area > 0; the passage rule's, area 0, now join the stretch too) leave
    # over 2 m of it bare
    along = sorted(pos[0] for _, pos, area in ((n, d["pos"], d["area"]) for n, d in off.nodes(data=True)) if 10 < pos[0] < 18 and pos[1] < 1 and area > 0)
    assert max(np.diff(along)) > 2.0
    graph = build(mesh)
    a, b = nearest(graph, west), nearest(graph, east)
    way = nx.shortest_path_length(graph, a, b, weight="weight")
    assert way < 1.1 * np.linalg.norm(np.subtract(graph.nodes[a]["pos"], graph.nodes[b]["pos"]))
    stats = graph.graph["sampling_stats"]
    # the passage rule's samples (moved_into_passages) now fill the bare stretch before the gap rule looks, which
    # then finds a short way between its ends: 1-3 gap edges joined it before they came
    assert stats["gap_radius"] == 3.0 and stats["samples_added"] >= 1 and stats["gap_edges"] == 0


def test_open_floor_gains_almost_no_edge():
    floor = box((-10, -0.2, -10), (10, 0, 10))
    off, graph = build(floor, gap_radius=0), build(floor)
    added = graph.number_of_edges() - off.number_of_edges()
    assert added == graph.graph["sampling_stats"]["gap_edges"]
    assert added <= 0.002 * off.number_of_edges()
    assert list(off.nodes(data="pos")) == list(graph.nodes(data="pos"))


def test_gap_pairs_are_those_without_a_short_way():
    # On a line, 1 m apart then 2.3 m: the last pair has no way at all.
    line = np.array([[0.0, 0, 0], [1.0, 0, 0], [3.3, 0, 0]])
    assert sampling._gap_pairs(line, np.array([[0, 1]]), 2.0, 3.0).tolist() == [[1, 2]]
    # 2.5 m apart with a common neighbour (a way of 3.2 m): not joined.
    apex = np.array([[0.0, 0, 0], [2.5, 0, 0], [1.25, 0, 1.0]])
    assert sampling._gap_pairs(apex, np.array([[0, 2], [1, 2]]), 2.0, 3.0).tolist() == []
    # The same two round three sides of a rectangle, a way of 5.7 m (over 2 x 2.5): joined; the
    # diagonals (2.97 m, a way of 4.1 m, under 2 x 2.97) are not.
    detour = np.array([[0.0, 0, 0], [2.5, 0, 0], [0.0, 0, 1.6], [2.5, 0, 1.6]])
    assert sampling._gap_pairs(detour, np.array([[0, 2], [2, 3], [1, 3]]), 2.0, 3.0).tolist() == [[0, 1]]
    # Off (gap_radius at most connect_radius): nothing.
    assert sampling._gap_pairs(line, np.array([[0, 1]]), 2.0, 2.0).shape == (0, 2)


def test_bounded_ways_by_tiles_are_the_ways_of_the_whole_graph():
    # 3,000 samples on a 150 m x 150 m square (6 x 6 tiles of 24 m for a limit of 6 m), joined within 2.2 m, and
    # every pair within 6 m: each way, found tile by tile on a renumbered part of the graph, has the bits of
    # scipy's Dijkstra on the whole graph (inf beyond the limit)
    rng = np.random.default_rng(5)
    samples = np.column_stack([rng.uniform(0, 150, 3000), rng.uniform(0, 0.5, 3000), rng.uniform(0, 150, 3000)])
    edges = cKDTree(samples).query_pairs(2.2, output_type="ndarray")
    lengths = np.linalg.norm(samples[edges[:, 1]] - samples[edges[:, 0]], axis=1)
    links = sparse.csr_array((lengths, (edges[:, 0], edges[:, 1])), shape=(3000, 3000))
    links = links + links.T
    pairs = cKDTree(samples).query_pairs(6.0, output_type="ndarray")
    way = sampling._bounded_ways(samples, links, pairs, 6.0)
    whole = csgraph.dijkstra(links, directed=False)[pairs[:, 0], pairs[:, 1]]
    expected = np.where(whole <= 6.0, whole, np.inf)
    assert 0 < np.count_nonzero(np.isinf(expected)) < len(pairs)
    np.testing.assert_array_equal(way.view(np.int64), expected.view(np.int64))


def test_runs_graph_keeps_the_runs_rows_and_columns():
    # rows and columns 1, 2 and 4 of a 6 x 6 matrix (runs [1, 3) and [4, 5), an empty one [3, 3) between)
    graph = sparse.csr_array(np.arange(36, dtype=float).reshape(6, 6) + 1.0)
    part, local = sampling._runs_graph(graph, np.array([[1, 3], [3, 3], [4, 5]]))
    kept = [1, 2, 4]
    np.testing.assert_array_equal(part.toarray(), graph.toarray()[np.ix_(kept, kept)])
    assert local(np.array([4, 1, 2])).tolist() == [2, 0, 1]


def test_the_new_edges_never_cross_a_wall():
    # A wall 0.2 m thick, 3 m high, across the whole floor: samples on both sides 1.2-3 m apart, no way between.
    mesh = trimesh.util.concatenate([box((-6, -0.2, -6), (6, 0, 6)), box((-0.1, 0, -6), (0.1, 3, 6))])
    graph = build(mesh)
    pos = np.array([graph.nodes[n]["pos"] for n in sorted(graph)])
    across = sampling._gap_pairs(pos, np.array(graph.edges), 2.0, 3.0)
    assert np.any(np.sign(pos[across[:, 0], 0]) != np.sign(pos[across[:, 1], 0]))  # the rule proposes such pairs
    assert all(np.sign(graph.nodes[a]["pos"][0]) == np.sign(graph.nodes[b]["pos"][0]) for a, b in graph.edges)
    assert nx.number_connected_components(graph) == 2


def test_same_graph_twice():
    mesh = alley(1.8)
    first, second = build(mesh, seed=1), build(mesh, seed=1)
    assert list(first.nodes(data=True)) == list(second.nodes(data=True))
    assert list(first.edges(data=True)) == list(second.edges(data=True))
