"""Known answers the presets' navmesh meets with Recast's ledge filter on, and why the presets keep it
(benchmarks/ledge_filter.py; docs/navmesh.md, "Ledge filter in the presets")."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import numpy as np
import pytest
import trimesh

from g2s_core.config import PRESETS_DIR, load_config

ROOT = Path(__file__).resolve().parents[1]


def _load(name: str):
    spec = importlib.util.spec_from_file_location(name, ROOT / "benchmarks" / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


lf = _load("ledge_filter")


@pytest.mark.parametrize("preset", ["map_analysis", "map_piece"])
def test_the_benchmark_grids_are_the_presets(preset):
    config = load_config(PRESETS_DIR / f"{preset}.yaml")
    agent, params = lf.GRIDS[preset]
    assert (config.agent.radius, config.agent.height, config.agent.max_climb, config.agent.max_slope) == (
        agent.radius, agent.height, agent.max_climb, agent.max_slope)
    given = config.graph.params or {}
    assert {k: given[k] for k in given if k in params} == params and set(params) <= set(given)
    assert given.get("filter_ledge_spans", True) is True  # the presets keep Recast's ledge filter


@pytest.mark.parametrize("grid, degrees, joins", [
    ("map_analysis", 30.0, True), ("map_analysis", 36.0, True), ("map_analysis", 46.0, False),
    ("map_piece", 55.0, True), ("map_piece", 62.0, False),
])
def test_ramps_with_the_ledge_filter(grid, degrees, joins):
    mesh, ends = lf.ramp(degrees)
    assert lf.joined(lf.navmesh(mesh, grid, ledge=True), ends) is joins


@pytest.mark.parametrize("grid", ["map_analysis", "map_piece"])
def test_a_step_or_wall_over_the_climb_stays_cut_either_way(grid):
    agent, _ = lf.GRIDS[grid]
    wall, halves = lf.low_wall(agent.max_climb + lf.WALL_OVER_CLIMB)
    stairs, ends = lf.stairs(0.45, 0.30)
    for ledge in (True, False):
        assert not lf.joined(lf.navmesh(wall, grid, ledge), halves)
        assert not lf.joined(lf.navmesh(stairs, grid, ledge), ends)


@pytest.mark.parametrize("rise", [0.125, 0.30])
def test_a_single_step_under_the_climb_is_walked(rise):
    mesh = trimesh.util.concatenate([lf.floor(6.0, 3.0, -3.0, 0.0), lf.floor(6.0, 3.0, 3.0, rise)])
    assert lf.joined(lf.navmesh(mesh, "map_analysis", ledge=True), np.array([[-3.0, 0, 0], [3.0, rise, 0]]))


def test_the_ledge_filter_cuts_climbable_stairs_on_the_map_analysis_grid():
    # two risers of 0.25 m differ by more than the grid's 0.375 m climb: the filter's second rule drops the treads
    mesh, ends = lf.stairs(0.25, 0.25)
    assert not lf.joined(lf.navmesh(mesh, "map_analysis", ledge=True), ends)
    assert lf.joined(lf.navmesh(mesh, "map_analysis", ledge=False), ends)


@pytest.mark.parametrize("grid", ["map_analysis", "map_piece"])
def test_without_the_ledge_filter_the_navmesh_overhangs_drops(grid):
    # Recast's voxels take a cell the platform's edge crosses as platform, and erosion counts the radius from that
    # cell's far side; the ledge filter drops the cell. Least clearance over 8 positions of the edge in its cell.
    agent, _ = lf.GRIDS[grid]
    cell = lf.cell_size(grid)
    assert lf.least_edge_clearance(grid, ledge=True) >= agent.radius - 1e-3
    assert lf.least_edge_clearance(grid, ledge=False) < agent.radius - cell / 2
