"""Lines of sight asked ahead (NavMesh.sights_ahead, the surface_los predicate's on a rooted forest)."""

from __future__ import annotations

import time

import g2s_core
import numpy as np

from g2s_core.simplify import simplify_forest
from g2s_plugins.predicates import surface_los
from g2s_plugins.samples import levels
from tests.test_navmesh_builder import run


def test_sights_ahead_answers_as_line_of_sight_whoever_computes_them():
    # a random tree over the polygon centres of a level with a ramp between two floors and walls: every pair two
    # and three edges apart (which the worker computes ahead) and pairs further apart (computed when asked), asked
    # right away and again once the worker is done, equal line_of_sight of the same points
    _, ctx = run(levels.SAMPLES["floors_joined_by_ramp"]().mesh)
    nm = ctx.navmesh
    rng = np.random.default_rng(3)
    count = 300
    polygons = rng.integers(nm.polygon_count, size=count)
    pos = nm.centres[polygons] + rng.uniform(-1.0, 1.0, (count, 3)) * [1, 0, 1]
    parent = np.r_[-1, [rng.integers(max(0, i - 5), i) for i in range(1, count)]]  # node i's parent comes before it
    ids = np.arange(count, dtype=np.int64) + 1000  # ids need not be rows
    heads, tails = ids[parent[1:]], ids[1:]
    wanted = np.ones(count, dtype=bool)
    for max_gap in (0.4, None):
        ahead = nm.sights_ahead(ids, heads, tails, pos, wanted, 0.3, max_gap)
        up = np.r_[parent, -1]  # up[-1]: above a root, none
        near = [(a, c) for c in range(count) for a in (up[up[c]], up[up[up[c]]]) if a >= 0]
        far = [tuple(pair) for pair in rng.integers(count, size=(200, 2))]
        expected = [nm.line_of_sight(pos[a], pos[c], 0.3, max_gap) for a, c in near + far]
        asked = [ahead.sees(ids[a], ids[c]) for a, c in near + far]
        time.sleep(0.2)
        assert asked == expected == [ahead.sees(ids[a], ids[c]) for a, c in near + far]
        assert 0 < sum(expected) < len(expected)  # clear and blocked pairs both


def test_surface_los_on_its_forest_simplifies_as_without_it():
    # the pipeline's predicate (given the forest: its lines of sight asked ahead) and the one asked outside the
    # pipeline (no forest: each line of sight when asked) give the same structure, node and edge order included
    result = g2s_core.run("sample:dungeon?rooms=40&seed=1", "map_analysis", stop_after="simplify")
    params, forest = surface_los.Params(), result.forest
    ahead = surface_los.g2s_simplify_predicate(params=params, context=result.context, forest=forest, simplified=None)
    alone = surface_los.g2s_simplify_predicate(params=params, context=result.context, forest=None, simplified=None)
    first, second = simplify_forest(forest, ahead), simplify_forest(forest, alone)
    assert list(first.nodes(data=True)) == list(second.nodes(data=True))
    assert list(first.edges(data=True)) == list(second.edges(data=True))
    assert first.number_of_nodes() < forest.number_of_nodes()
