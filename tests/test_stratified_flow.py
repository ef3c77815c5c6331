"""The walking flow's sample stratified by connected area: the small areas walked exactly, the draws over the rest
(:func:`g2s_plugins.traffic.exact_areas`, :func:`g2s_plugins.traffic.walking_sources`)."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp

from g2s_plugins import traffic


def path_areas(sizes: list[int]) -> sp.csr_array:
    """(n, n) edge lengths of one path graph of each of ``sizes`` nodes, side by side, unit lengths."""
    rows = [start + i for start, size in zip(np.cumsum([0, *sizes[:-1]]), sizes) for i in range(size - 1)]
    n = sum(sizes)
    one = sp.coo_array((np.ones(len(rows)), (rows, np.add(rows, 1))), shape=(n, n))
    return sp.csr_array(one + one.T)


def grid_areas(sides: list[tuple[int, int]], seed: int = 5) -> tuple[sp.csr_array, np.ndarray]:
    """(n, n) edge lengths of one w x h grid of each of ``sides`` (lengths 0.5-1.5 m), and (n,) areas 0.5-2 m²."""
    rng = np.random.default_rng(seed)
    rows, cols, start = [], [], 0
    for w, h in sides:
        cell = np.arange(w * h).reshape(w, h) + start
        rows += [*cell[:-1, :].ravel(), *cell[:, :-1].ravel()]
        cols += [*cell[1:, :].ravel(), *cell[:, 1:].ravel()]
        start += w * h
    length = rng.uniform(0.5, 1.5, len(rows))
    one = sp.coo_array((length, (rows, cols)), shape=(start, start))
    return sp.csr_array(one + one.T), rng.uniform(0.5, 2.0, start)


BIG_AND_ISLANDS = [(20, 20), (2, 3), (3, 3), (1, 4), (1, 1), (4, 5)]
"""A big area of 400 nodes and five islands of 1-20 nodes (40 in all)."""


def test_the_smallest_areas_are_taken_while_their_squared_sizes_stay_within_one_sample():
    adjacency = path_areas([10, 2, 1, 3])  # 16 nodes; with 1 source one sample's work is 16 node visits
    area = traffic.exact_areas(adjacency, 1)
    # 1 + 4 + 9 = 14 <= 16, and the area of 10 nodes would make it 114
    assert (area >= 0).tolist() == [False] * 10 + [True] * 6
    assert traffic.exact_areas(adjacency, 2).tolist() == area.tolist()  # 114 > 32
    assert np.all(traffic.exact_areas(adjacency, 8) >= 0)  # 114 <= 128: every area, at no more than a sample's work
    assert np.all(traffic.exact_areas(path_areas([16]), 1) < 0)  # one area is never taken above max_sources nodes


@pytest.mark.parametrize("ties", ["first", "split"])
@pytest.mark.parametrize("scaling", ["none", "linear"])
def test_the_islands_read_their_exact_flow_and_the_big_area_its_sample(ties, scaling):
    adjacency, weight = grid_areas(BIG_AND_ISLANDS)
    island = traffic.exact_areas(adjacency, 32) >= 0
    assert island.sum() == 40 and not island[:400].any()
    exact, _ = traffic.od_flow(adjacency, weight, ties=ties)
    for order in (None, np.random.default_rng(1).permutation(weight.size)):
        flow, sampled = traffic.od_flow(adjacency, weight, 32, 3, ties, scaling, order)
        assert sampled == 32
        assert flow[island] == pytest.approx(exact[island], rel=1e-12, abs=0.0)
        assert np.any(flow[island] > 0) and not np.array_equal(flow[~island], exact[~island])
        # same graph and seed: the same bits
        assert np.array_equal(flow, traffic.od_flow(adjacency, weight, 32, 3, ties, scaling, order)[0])


def test_the_draws_fall_on_the_rest_and_carry_its_weight():
    adjacency, weight = grid_areas(BIG_AND_ISLANDS)
    island = traffic.exact_areas(adjacency, 32) >= 0
    sources, factor, sampled = traffic.walking_sources(weight, 32, 7, exact=island)
    walked = island[sources]
    assert sampled == 32 and np.all(np.diff(sources) > 0)
    assert sources[walked].tolist() == np.flatnonzero(island).tolist() and np.array_equal(factor[walked], weight[island])
    assert factor[~walked].sum() == pytest.approx(weight[~island].sum())  # 32 draws of weight A_R / 32


def test_the_big_areas_estimate_is_unbiased_within_hoeffdings_bound():
    adjacency, weight = grid_areas(BIG_AND_ISLANDS)
    weight[400:] *= 10.0  # islands of as much weight as the big area: a draw's factor of A, not A_R, reads 2x
    exact, _ = traffic.od_flow(adjacency, weight, ties="split")
    seeds, sources = 150, 16
    # the mean of 150 samples of 16 independent draws is one sample of 2,400 draws over the big area (weight A_R)
    mean = sum(traffic.od_flow(adjacency, weight, sources, seed, "split")[0] for seed in range(seeds)) / seeds
    big = weight[:400].sum()
    assert np.abs(mean - exact)[:400].max() / big ** 2 <= traffic.flow_error_bound(seeds * sources)
    assert np.abs(mean - exact)[:400].max() / big ** 2 > 0  # a sample, not the exact flow


def test_a_graph_of_one_area_is_sampled_as_before():
    adjacency, weight = grid_areas([(12, 10)])
    assert np.all(traffic.exact_areas(adjacency, 16) < 0)
    # the draws as they were made before areas were told apart: over every node of positive weight
    draws = np.random.default_rng(4).choice(np.arange(120), size=16, replace=True, p=weight / weight.sum())
    sources, counts = np.unique(draws, return_counts=True)
    got_sources, got_factor, _ = traffic.walking_sources(weight, 16, 4, exact=np.zeros(120, dtype=bool))
    assert np.array_equal(got_sources, sources) and np.array_equal(got_factor, counts * (weight.sum() / 16))
    flow, _ = traffic.od_flow(adjacency, weight, 16, 4, "split")
    assert np.array_equal(flow, counts * (weight.sum() / 16) @ traffic.split_path_flow(adjacency, sources, weight))


def test_a_rest_of_no_more_weighted_nodes_than_sources_is_walked_whole():
    adjacency, weight = grid_areas([(10, 10), (2, 2), (1, 3)])  # 107 nodes; the 7 of the islands walked exactly
    weight[20:100] = 0.0  # the big area holds 20 nodes of positive weight: 27 in all, over 24 sources
    assert (traffic.exact_areas(adjacency, 24) >= 0).sum() == 7
    flow, sampled = traffic.od_flow(adjacency, weight, 24, 0, "split")
    assert sampled is None and flow == pytest.approx(traffic.od_flow(adjacency, weight, ties="split")[0], rel=1e-12)
