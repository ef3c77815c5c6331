"""Dents within a rank budget (``coverage``'s ``dent_depth`` and ``dent_rho_budget``): the bays between the posts
lining a corridor lose their terminals, cheapest first, while the cover still holds every node within its radius; a
side room, deeper than a dent, keeps its own."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh
from scipy.sparse import csgraph

from g2s_core import pipeline
from g2s_core.config import find_config, load_raw_config, parse_config
from g2s_core.errors import ConfigError
from g2s_core.model import RunResult
from g2s_core.registry import Registry
from g2s_plugins.terminals import coverage
from tests.conftest import box

BAYS_FROM = 6.0
"""z (m) beyond which a node stands in a bay between the posts."""

ROOM_BEFORE = -0.5
"""z (m) short of which a node stands in the side room."""


@pytest.fixture(scope="module")
def registry() -> Registry:
    return Registry.from_entry_points()


def corridor_lined_with_posts() -> trimesh.Trimesh:
    """A corridor 40 x 8 m: along its wall at z = 8 a row of 14 posts 0.6 m wide and 1.8 m deep every 2.7 m (the
    agent, radius 0.5 m, walks into each bay between two posts, 1.7 m deep), and through a door 2 m wide in its
    other wall a side room 6 x 6 m (a dead end 6 m deep)."""
    parts = [box(0, 40, -0.2, 0, 0, 8), box(0, 40, 0, 3, 8, 9)]
    parts += [box(x - 0.3, x + 0.3, 0, 3, 6.2, 8) for x in np.arange(2.0, 39.0, 2.7)]
    parts += [box(0, 17, 0, 3, -0.3, 0), box(19, 40, 0, 3, -0.3, 0)]  # the wall with the door
    parts += [box(15, 21, -0.2, 0, -6.3, -0.3), box(14.7, 15, 0, 3, -6.3, -0.3), box(21, 21.3, 0, 3, -6.3, -0.3),
              box(14.7, 21.3, 0, 3, -6.6, -6.3)]  # the room
    return trimesh.util.concatenate(parts)


def run_cover(registry: Registry, **params) -> tuple[RunResult, coverage.Cover]:
    """``map_analysis`` with ``params`` up to its terminals on the corridor, and its cover."""
    raw = load_raw_config(find_config("map_analysis"))
    raw["stop_after"] = "terminals"
    raw["terminals"]["params"].update(params)
    config = parse_config(raw)
    result = pipeline.run(pipeline.plan(config, registry), registry, corridor_lined_with_posts(), "level", "-")
    return result, coverage.cover(result.graph, coverage.Params(**config.terminals.params), result.context)


def z_of(result: RunResult, nodes) -> list[float]:
    return [result.graph.nodes[n]["pos"][2] for n in nodes]


def test_the_bays_between_posts_lose_their_terminals_and_the_side_room_keeps_its_own(registry):
    before, _ = run_cover(registry)
    after, cover = run_cover(registry, dent_depth=2.0, dent_rho_budget=1.0)
    bays_before = sum(z > BAYS_FROM for z in z_of(before, before.terminals.without_waypoints))
    bays_after = sum(z > BAYS_FROM for z in z_of(after, after.terminals.without_waypoints))
    assert bays_before >= 5
    # one bay keeps its leaf: without every bay's, part of the corridor would lie farther than the radius
    assert bays_after <= 1
    in_room = sorted(n for n, z in zip(before.terminals.nodes, z_of(before, before.terminals.nodes), strict=True)
                     if z < ROOM_BEFORE)
    assert in_room
    assert in_room == sorted(n for n, z in zip(after.terminals.nodes, z_of(after, after.terminals.nodes), strict=True)
                             if z < ROOM_BEFORE)
    distance = csgraph.dijkstra(cover.arrays.adjacency, directed=False, indices=cover.rows, min_only=True)
    assert distance.max() <= coverage.default_radius(after.context)


def test_the_cheapest_dent_goes_first_and_the_budget_bounds_the_rest(registry):
    result, cover = run_cover(registry)
    arrays = cover.arrays
    rank = coverage.walking_percentile(arrays)
    radius = coverage.default_radius(result.context)
    dents, costs = coverage.dent_costs(result.graph, result.context.navmesh, arrays, cover.leaves, rank, 2.0,
                                       cover.rows, radius)
    assert len(dents) >= 5 and (costs > 0).all()
    # a bay as busy as the corridor costs nothing: it alone fits a budget too small for any other
    cheap = dents[len(dents) // 2]
    chain, entrance = coverage.dead_end_chain(arrays.adjacency, int(cheap))
    rank[chain] = rank[entrance]
    assert coverage.dents_within_budget(result.graph, result.context.navmesh, arrays, cover.leaves, rank, 2.0,
                                        cover.rows, radius, 1e-9).tolist() == [cheap]
    budget = float(np.sort(costs)[:3].sum())
    dropped = coverage.dents_within_budget(result.graph, result.context.navmesh, arrays, cover.leaves,
                                           coverage.walking_percentile(arrays), 2.0, cover.rows, radius, budget)
    assert 1 <= len(dropped) <= 3 and costs[np.isin(dents, dropped)].sum() <= budget
    # no leaf is a dent at 1 m here: the bays are all 1.6-1.8 m deep
    assert coverage.dent_costs(result.graph, result.context.navmesh, arrays, cover.leaves, rank, 1.0, cover.rows,
                               radius)[0].size == 0


def test_dent_params_are_validated(registry):
    for key, value in (("dent_depth", -1), ("dent_rho_budget", -0.1), ("dent_rho_budget", 1.5)):
        raw = load_raw_config(find_config("map_analysis"))
        raw["terminals"]["params"][key] = value
        with pytest.raises(ConfigError, match=f"terminals.params.{key}: expected a number"):
            pipeline.plan(parse_config(raw), registry)
