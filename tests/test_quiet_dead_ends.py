"""Quiet dead ends (``coverage``'s ``quiet_step``): a leaf is seeded only where its dead end is at least that many
walking-flow percentile points quieter than the node it opens onto; the cover reaches the others."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp

from g2s_core import pipeline
from g2s_core.config import find_config, load_raw_config, parse_config
from g2s_core.errors import ConfigError
from g2s_core.registry import Registry
from g2s_plugins.surface_arrays import SurfaceArrays
from g2s_plugins.terminals import coverage


def star_with_dead_ends() -> SurfaceArrays:
    """A walkway round the loop 0-1-2-3 (1 m edges) with dead ends: leaf 4 off node 1, leaf 5 off node 2, the chain
    6-7 off node 3 (7 the leaf), leaves 10 and 11 off nodes 0 and 3, and an area that is one chain, 8-9."""
    edges = [(0, 1), (1, 2), (2, 3), (3, 0), (1, 4), (2, 5), (3, 6), (6, 7), (0, 10), (3, 11), (8, 9)]
    rows = np.array([a for a, b in edges] + [b for a, b in edges])
    cols = np.array([b for a, b in edges] + [a for a, b in edges])
    n = 12
    adjacency = sp.csr_array((np.ones(len(rows)), (rows, cols)), shape=(n, n))
    return SurfaceArrays(list(range(n)), {i: i for i in range(n)}, adjacency, np.ones(n))


def test_a_dead_end_is_seeded_only_where_it_is_quieter_than_its_way_in_by_the_step():
    arrays = star_with_dead_ends()
    rank = np.zeros(12)
    rank[[0, 1, 2, 3]] = [50, 80, 40, 60]  # the walkway
    rank[4] = 10  # 70 points under its way in (node 1)
    rank[5] = 25  # 15 points under node 2
    rank[[6, 7]] = [45, 15]  # the chain's mean, 30, is 30 points under node 3
    rank[[8, 9]] = [1, 99]  # an area that is one chain: its leaves stay whatever their flow
    leaves = np.array([4, 5, 7, 8, 9, 10, 11])
    rank[10], rank[11] = 50, 70  # as busy as their ways in (0 and 3)
    assert coverage.loud_dead_ends(arrays, leaves, rank, 30.0).tolist() == [4, 7, 8, 9]
    assert coverage.loud_dead_ends(arrays, leaves, rank, 30.1).tolist() == [4, 8, 9]
    assert coverage.loud_dead_ends(arrays, leaves, rank, 15.0).tolist() == [4, 5, 7, 8, 9]


def test_quiet_step_is_validated():
    raw = load_raw_config(find_config("map_analysis"))
    raw["terminals"]["params"]["quiet_step"] = -1
    with pytest.raises(ConfigError, match="terminals.params.quiet_step: expected a number"):
        pipeline.plan(parse_config(raw), Registry.from_entry_points())
