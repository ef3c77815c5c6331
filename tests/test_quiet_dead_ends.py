"""Quiet dead ends (``coverage``'s ``quiet_step``): a leaf is no terminal where its dead end is less than that many
walking-flow percentile points quieter than the node it opens onto and the cover holds that node within its radius."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp

from g2s_core import pipeline
from g2s_core.config import find_config, load_raw_config, parse_config
from g2s_core.errors import ConfigError
from g2s_core.mesh import generate_level
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


def test_a_dead_end_is_left_to_the_cover_where_it_is_about_as_busy_as_its_way_in_and_the_cover_holds_that():
    arrays = star_with_dead_ends()
    rank = np.zeros(12)
    rank[[0, 1, 2, 3]] = [50, 80, 40, 60]  # the walkway
    rank[4] = 10  # 70 points under its way in (node 1)
    rank[5] = 25  # 15 points under node 2
    rank[[6, 7]] = [45, 15]  # the chain's mean, 30, is 30 points under node 3, 2 m away from its leaf
    rank[[10, 11]] = [50, 70]  # as busy as their ways in (nodes 0 and 3)
    rank[[8, 9]] = [1, 99]  # an area that is one chain: its leaves stay whatever their flow
    leaves = np.array([4, 5, 7, 8, 9, 10, 11])
    walkway = np.array([0, 1, 2, 3])
    assert coverage.quiet_dead_ends(arrays, leaves, rank, 30.0, walkway, 6.0).tolist() == [5, 10, 11]
    assert coverage.quiet_dead_ends(arrays, leaves, rank, 30.1, walkway, 6.0).tolist() == [5, 7, 10, 11]
    assert coverage.quiet_dead_ends(arrays, leaves, rank, 30.1, walkway, 1.5).tolist() == [5, 10, 11]
    # a way in the cover does not hold keeps its leaf: the cover would not reach the dead end within its radius
    assert coverage.quiet_dead_ends(arrays, leaves, rank, 30.0, np.array([0, 1, 3]), 6.0).tolist() == [10, 11]


def test_quiet_step_is_validated():
    raw = load_raw_config(find_config("map_analysis"))
    raw["terminals"]["params"]["quiet_step"] = -1
    with pytest.raises(ConfigError, match="terminals.params.quiet_step: expected a number"):
        pipeline.plan(parse_config(raw), Registry.from_entry_points())


@pytest.mark.parametrize("level", ["sample:pilaster_corridor", "sample:building"])
def test_the_cover_only_drops_leaves_and_adds_no_path(level):
    """In the cover (``coverage.cover``): the quiet leaves go, the waypoints and every other terminal stay."""
    registry = Registry.from_entry_points()

    def terminals(quiet_step: float) -> tuple[set, set]:
        raw = load_raw_config(find_config("map_analysis"))
        raw["stop_after"] = "terminals"
        raw["terminals"]["params"]["quiet_step"] = quiet_step
        result = pipeline.run(pipeline.plan(parse_config(raw), registry), registry, generate_level(level, registry=registry),
                              "level", "-")
        return set(result.terminals.without_waypoints), set(result.terminals.nodes) - set(result.terminals.without_waypoints)

    (leaves, waypoints), (quiet_leaves, quiet_waypoints) = terminals(0.0), terminals(30.0)
    assert quiet_leaves < leaves and quiet_waypoints == waypoints
