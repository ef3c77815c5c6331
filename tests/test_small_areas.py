"""A small walkable area gets structure by one rule on both routes (g2s_plugins/terminals/coverage.py, ``min_area``
and ``place_area``; docs/analysis_quality.md, "Small areas on both routes").

The level: a floor 40 x 24 m and on it a box 3 x 6 m, 1.5 m high (over the agent's climb, 0.4 m), whose top is
an area of its own: about 2 x 5 m once the builders keep the agent's radius, 0.5 m, from its edges (8.3 m² on the
navmesh route, one polygon and no leaf; 10 samples of 1 m² on the sampling route, no leaf either). The cover
radius is a tenth of the level's extent, 4.66 m, so ``min_area`` is pi (2.33)² = 17.1 m²: the top is a small area.
"""

from __future__ import annotations

import numpy as np
import pytest
import trimesh

import g2s_core

TOP = (-10.0, 0.0)
"""The middle of the box's top in plan (x, z), m."""


def floor_and_platform() -> trimesh.Trimesh:
    floor = trimesh.creation.box(extents=(40.0, 0.2, 24.0))
    floor.apply_translation((0.0, -0.1, 0.0))
    platform = trimesh.creation.box(extents=(3.0, 1.5, 6.0))
    platform.apply_translation((TOP[0], 0.75, TOP[1]))
    return trimesh.util.concatenate([floor, platform])


def on_top(result) -> list[np.ndarray]:
    positions = (np.asarray(result.graph.nodes[node]["pos"]) for node in result.structure.nodes)
    return [p for p in positions if p[1] > 1.0]


@pytest.mark.parametrize("preset", ["map_analysis", "map_analysis_sampling"])
def test_a_small_platform_gets_one_node_at_its_middle(preset):
    # before, a small area kept its leaves and had none here: the top was left out on both routes
    result = g2s_core.run(floor_and_platform(), preset)
    nodes = on_top(result)
    assert len(nodes) == 1
    # the graph centre: the polygon's centre, or the middle sample of two columns of five (ties: the lowest row)
    assert np.hypot(nodes[0][0] - TOP[0], nodes[0][2] - TOP[1]) < 1.0
    assert not [w for w in result.warnings if w.startswith("coverage:")]


@pytest.mark.parametrize("preset", ["map_analysis", "map_analysis_sampling"])
def test_a_platform_under_place_area_gets_no_node_and_is_named(preset):
    result = g2s_core.run(floor_and_platform(), preset, **{"terminals.params.place_area": 12.0})
    assert on_top(result) == []
    named = [w for w in result.warnings if w.startswith("coverage:")]
    assert len(named) == 1 and named[0].startswith("coverage: 1 walkable area(s) smaller than 12 m² (")
