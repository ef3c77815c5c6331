"""Recesses (``coverage``'s ``recess_depth``): a row of shallow dead ends that one floor opens onto (the bays between
the pillars of a terrace) seeds one leaf terminal, not one per bay; a dead-end room off a corridor keeps its own."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp
import trimesh
from scipy.sparse import csgraph

from g2s_core import pipeline
from g2s_core.config import find_config, load_raw_config, parse_config
from g2s_core.errors import ConfigError
from g2s_core.registry import Registry
from g2s_plugins.terminals import coverage
from tests.conftest import box


@pytest.fixture(scope="module")
def registry() -> Registry:
    return Registry.from_entry_points()


def terrace_with_pillars() -> trimesh.Trimesh:
    """A terrace 60 x 5 m against a wall along z = 8, with a row of 22 pillars 0.6 m wide standing against the wall
    and 1.8 m deep, every 2.7 m: the agent (radius 0.5 m) walks into each bay between two pillars, 1.8 m deep."""
    parts = [box(0, 60, -0.2, 0, 3, 8), box(0, 60, 0, 3, 8, 9)]
    parts += [box(x - 0.3, x + 0.3, 0, 3, 6.2, 8) for x in np.arange(2.0, 59.0, 2.7)]
    return trimesh.util.concatenate(parts)


def room_off_a_corridor() -> trimesh.Trimesh:
    """A corridor 24 x 2.5 m and, through a door 2 m wide in its wall, a room 6 x 6.2 m: a dead end 6 m deep."""
    return trimesh.util.concatenate([
        box(0, 24, -0.2, 0, 0, 2.5), box(0, 24, 0, 3, -0.3, 0),  # corridor floor and its closed wall
        box(0, 10, 0, 3, 2.5, 2.8), box(12, 24, 0, 3, 2.5, 2.8),  # the wall with the door
        box(8, 14, -0.2, 0, 2.8, 9), box(7.7, 8, 0, 3, 2.8, 9), box(14, 14.3, 0, 3, 2.8, 9), box(7.7, 14.3, 0, 3, 9, 9.3),
    ])


def seeded(registry: Registry, mesh: trimesh.Trimesh, **params) -> list[tuple[float, float, float]]:
    """The positions of the leaf terminals (not the waypoints) ``map_analysis`` with ``params`` seeds on ``mesh``."""
    raw = load_raw_config(find_config("map_analysis"))
    raw["stop_after"] = "terminals"
    raw["terminals"]["params"].update(params)
    result = pipeline.run(pipeline.plan(parse_config(raw), registry), registry, mesh, "level", "-")
    return [result.graph.nodes[n]["pos"] for n in result.terminals.without_waypoints]


def test_a_terrace_with_a_pillar_row_seeds_one_bay(registry):
    def bays(**params) -> int:
        return sum(1 for x, _, z in seeded(registry, terrace_with_pillars(), **params) if z > 6.0)

    assert bays() >= 15  # a leaf in nearly every bay (dead_end_radii merges a few where the walkway is a chain)
    # quiet_step off: a bay about as busy as the terrace (map_analysis's quiet_step) would drop the row's one leaf too
    assert bays(recess_depth=2.0, quiet_step=0.0) == 1
    # bays 1.8 m deep are no recess when a recess lies within 1.5 m of its way in
    assert bays(recess_depth=1.5) == bays()


def test_a_dead_end_room_off_a_corridor_keeps_its_terminal(registry):
    def in_room(**params) -> int:
        return sum(1 for _, _, z in seeded(registry, room_off_a_corridor(), **params) if z > 3.0)

    assert in_room() >= 1
    assert in_room(recess_depth=2.0) == in_room()


def test_recess_params_are_validated(registry):
    for key, value, expected in (("recess_depth", -1, "a number"), ("recess_row", 1, "an integer")):
        raw = load_raw_config(find_config("map_analysis"))
        raw["terminals"]["params"][key] = value
        with pytest.raises(ConfigError, match=f"terminals.params.{key}: expected {expected}"):
            pipeline.plan(parse_config(raw), registry)


def path_lengths(lengths: list[float]) -> sp.csr_array:
    """(n, n) edge lengths of a path whose k-th edge joins nodes k and k + 1."""
    n = len(lengths) + 1
    rows, cols = np.arange(n - 1), np.arange(1, n)
    return sp.csr_array((np.concatenate([lengths, lengths]), (np.concatenate([rows, cols]), np.concatenate([cols, rows]))),
                        shape=(n, n))


def test_rows_chain_entrances_within_reach_along_the_graph():
    adjacency = path_lengths([2.0] * 9)  # nodes 0-9, 2 m apart
    # 0 and 2 are 4 m apart, 2 and 3 2 m, 3 and 8 10 m; 3 is listed twice (two recesses open onto it)
    labels = coverage.recess_row_labels(adjacency, np.array([0, 2, 3, 3, 8]), 4.0)
    assert labels[0] == labels[1] == labels[2] == labels[3] != labels[4]
    labels = coverage.recess_row_labels(adjacency, np.array([0, 2, 3, 3, 8]), 3.9)
    assert len({labels[0], labels[1], labels[4]}) == 3 and labels[1] == labels[2] == labels[3]


@pytest.mark.parametrize("seed", range(5))
def test_rows_are_single_linkage_of_the_graph_distances(seed):
    rng = np.random.default_rng(seed)
    points = rng.uniform(0, 30, size=(120, 2))
    pairs = np.array([(i, j) for i in range(120) for j in range(i + 1, 120) if np.hypot(*(points[i] - points[j])) < 4.5])
    lengths = np.hypot(*(points[pairs[:, 0]] - points[pairs[:, 1]]).T)
    adjacency = sp.csr_array((np.concatenate([lengths, lengths]), (np.concatenate([pairs[:, 0], pairs[:, 1]]),
                                                                    np.concatenate([pairs[:, 1], pairs[:, 0]]))), shape=(120, 120))
    entrances = np.sort(rng.choice(120, size=25, replace=False))
    labels = coverage.recess_row_labels(adjacency, entrances, 6.0)
    # by hand: every pair within 6 m along the graph joined, chained
    distance = csgraph.dijkstra(adjacency, directed=False, indices=entrances)[:, entrances]
    _, expected = csgraph.connected_components(sp.csr_array(distance <= 6.0), directed=False)
    assert np.array_equal(labels[:, None] == labels[None, :], expected[:, None] == expected[None, :])
