"""Known answers the navmesh meets with each ledge filter (Recast's, its first rule alone, none), and the filter
the presets use (benchmarks/ledge_filter.py; docs/navmesh.md, "Ledge filter in the presets" and "A ledge filter of
our own")."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh
from pydantic import ValidationError

from g2s_core.config import PRESETS_DIR, load_config
from g2s_plugins.recast import RecastParams
from tests.conftest import benchmark
from tests.reliability.checks import assert_clean_error, run_g2s

lf = benchmark("ledge_filter")


@pytest.mark.parametrize("preset", ["map_analysis", "map_piece"])
def test_the_benchmark_grids_are_the_presets(preset):
    config = load_config(PRESETS_DIR / f"{preset}.yaml")
    agent, params = lf.GRIDS[preset]
    assert (config.agent.radius, config.agent.height, config.agent.max_climb, config.agent.max_slope) == (
        agent.radius, agent.height, agent.max_climb, agent.max_slope)
    given = config.graph.params or {}
    assert {k: given[k] for k in given if k in params} == params and set(params) <= set(given)
    # both take drops (docs/navmesh.md, "The drops-only ledge filter" and "Where the slopes' CPU goes; map_analysis takes
    # drops"); the builder's default stays Recast's
    assert given.get("ledge_filter", "recast") == "drops"


@pytest.mark.parametrize("grid, degrees, joins", [
    ("map_analysis", 30.0, True), ("map_analysis", 36.0, True), ("map_analysis", 46.0, False),
    ("map_piece", 55.0, True), ("map_piece", 62.0, False),
])
def test_ramps_with_the_ledge_filter(grid, degrees, joins):
    mesh, ends = lf.ramp(degrees)
    assert lf.joined(lf.navmesh(mesh, grid, ledge="recast"), ends) is joins


@pytest.mark.parametrize("grid", ["map_analysis", "map_piece"])
def test_a_step_or_wall_over_the_climb_stays_cut_either_way(grid):
    agent, _ = lf.GRIDS[grid]
    wall, halves = lf.low_wall(agent.max_climb + lf.WALL_OVER_CLIMB)
    stairs, ends = lf.stairs(0.45, 0.30)
    for ledge in lf.FILTERS:
        assert not lf.joined(lf.navmesh(wall, grid, ledge), halves)
        assert not lf.joined(lf.navmesh(stairs, grid, ledge), ends)


@pytest.mark.parametrize("rise", [0.125, 0.30])
def test_a_single_step_under_the_climb_is_walked(rise):
    mesh = trimesh.util.concatenate([lf.floor(6.0, 3.0, -3.0, 0.0), lf.floor(6.0, 3.0, 3.0, rise)])
    for ledge in lf.FILTERS:
        assert lf.joined(lf.navmesh(mesh, "map_analysis", ledge), np.array([[-3.0, 0, 0], [3.0, rise, 0]]))


def test_the_ledge_filter_cuts_climbable_stairs_on_the_map_analysis_grid():
    # two risers of 0.25 m differ by more than the grid's 0.375 m climb: the filter's second rule drops the treads
    mesh, ends = lf.stairs(0.25, 0.25)
    assert not lf.joined(lf.navmesh(mesh, "map_analysis", ledge="recast"), ends)
    assert lf.joined(lf.navmesh(mesh, "map_analysis", ledge="drops"), ends)
    assert lf.joined(lf.navmesh(mesh, "map_analysis", ledge="off"), ends)


@pytest.mark.parametrize("degrees", [40.0, 44.0])
def test_the_first_rule_alone_walks_slopes_up_to_max_slope_on_the_map_analysis_grid(degrees):
    # the second rule's limit on this grid is atan(0.375 / 0.5) = 36.9 degrees; the agent's max_slope is 45
    mesh, ends = lf.ramp(degrees)
    assert not lf.joined(lf.navmesh(mesh, "map_analysis", ledge="recast"), ends)
    assert lf.joined(lf.navmesh(mesh, "map_analysis", ledge="drops"), ends)


@pytest.mark.parametrize("grid", ["map_analysis", "map_piece"])
def test_without_the_ledge_filter_the_navmesh_overhangs_drops(grid):
    # Recast's voxels take a cell the platform's edge crosses as platform, and erosion counts the radius from that
    # cell's far side; the filter's first rule drops the cell. Least clearance over 8 positions of the edge in its
    # cell.
    agent, _ = lf.GRIDS[grid]
    cell = lf.cell_size(grid)
    assert lf.least_edge_clearance(grid, ledge="recast") >= agent.radius - 1e-3
    assert lf.least_edge_clearance(grid, ledge="drops") >= agent.radius - 1e-3
    assert lf.least_edge_clearance(grid, ledge="off") < agent.radius - cell / 2


@pytest.mark.parametrize("grid", ["map_analysis", "map_piece"])
def test_the_first_rule_alone_is_recasts_filter_where_no_neighbours_differ_by_more_than_the_climb(grid):
    # a platform 1 m high on flat ground: every span's neighbours within the climb lie at its own height, so the
    # second rule drops nothing and both filters give the same navmesh
    mesh = lf.platform(0.05)
    recast, drops = (lf.navmesh(mesh, grid, ledge) for ledge in ("recast", "drops"))
    assert recast.polygon_count == drops.polygon_count > 0
    assert np.array_equal(recast.vertices, drops.vertices) and np.array_equal(recast.polygons, drops.polygons)


def test_the_replaced_key_is_refused_with_what_to_write():
    with pytest.raises(ValidationError, match="filter_ledge_spans was replaced by ledge_filter: write ledge_filter: "
                                              "recast for true, off for false"):
        RecastParams(filter_ledge_spans=False)
    with pytest.raises(ValidationError):
        RecastParams(ledge_filter="on")


def test_a_config_with_the_replaced_key_exits_2_naming_it(tmp_path, capsys):
    outcome = run_g2s(capsys, "run", "map_analysis", "sample:straight_corridor", "-o", tmp_path / "out",
                      "--set", "graph.params.filter_ledge_spans=false")
    assert_clean_error(outcome, "map_analysis: graph.params: filter_ledge_spans was replaced by ledge_filter")
