"""Navmesh inputs Recast cannot handle: each is a clean user error (exit 2, one
line naming the key), never an internal error, a crash or a wrong result."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import trimesh

from g2s_core.cli import main
from g2s_plugins.recast import RecastParams, SettingsError, resolve_settings
from g2s_plugins.recast.build import check_grid
from tests.conftest import PROJECT


def quad_obj(path: Path, corners: list[tuple[float, float, float]]) -> Path:
    """A one-quad OBJ (two triangles) with the four corners in order."""
    lines = [f"v {x} {y} {z}" for x, y, z in corners] + ["f 1 2 3", "f 1 3 4"]
    path.write_text("\n".join(lines) + "\n")
    return path


def floor_obj(path: Path, size: float) -> Path:
    """A Y-up square floor ``size`` metres across, centred on the origin."""
    h = size / 2
    return quad_obj(path, [(-h, 0, -h), (-h, 0, h), (h, 0, h), (h, 0, -h)])


def run(tmp_path: Path, mesh: Path, extra: str, capsys) -> tuple[int, str]:
    config = tmp_path / "c.yaml"
    config.write_text("extends: graph_only\n" + extra)
    out = tmp_path / "out"
    code = main(["run", str(config), str(mesh), "-o", str(out), "--quiet"])
    err = capsys.readouterr().err
    assert code == 0 or not out.exists()
    return code, err


def assert_refused(code: int, err: str, *fragments: str) -> None:
    lines = [line for line in err.splitlines() if line.strip()]
    assert code == 2, err
    assert "Traceback" not in err and len(lines) == 1, err
    for fragment in fragments:
        assert fragment in lines[0], err


def test_z_up_floor_read_as_y_up_names_the_up_axis(tmp_path, capsys):
    mesh = quad_obj(tmp_path / "z_up.obj", [(-5, -5, 0), (5, -5, 0), (5, 5, 0), (-5, 5, 0)])
    assert_refused(*run(tmp_path, mesh, "", capsys), "error: z_up.obj: mesh: the level has no floor area",
                   "`mesh: {up_axis: z}`")
    code, err = run(tmp_path, mesh, "mesh: {up_axis: z}\n", capsys)
    assert code == 0, err


def test_bumpy_z_up_level_read_as_y_up_names_the_up_axis(tmp_path, capsys):
    # a Z-up floor with a step: not flat, so Recast runs and finds nothing walkable
    lines = ["v -5 -5 0", "v 0 -5 0", "v 0 5 0", "v -5 5 0", "v 0 -5 0.3", "v 5 -5 0.3", "v 5 5 0.3", "v 0 5 0.3",
             "f 1 2 3", "f 1 3 4", "f 5 6 7", "f 5 7 8"]
    mesh = tmp_path / "bumpy.obj"
    mesh.write_text("\n".join(lines) + "\n")
    assert_refused(*run(tmp_path, mesh, "", capsys), "error: bumpy.obj: no walkable surface", "`mesh: {up_axis: z}`")


def test_single_wall(tmp_path, capsys):
    mesh = quad_obj(tmp_path / "wall.obj", [(0, 0, -2), (0, 3, -2), (0, 3, 2), (0, 0, 2)])
    assert_refused(*run(tmp_path, mesh, "", capsys), "mesh: the level has no floor area", "flat along x")


@pytest.mark.parametrize(
    "size, fragment",
    [(1e-4, "error: f.obj: mesh: the level is less than one 0.25 m cell across"),
     (3e6, "error: f.obj: mesh: the level (3e+06 x 3e+06 m")],
)
def test_tiny_and_huge_levels(tmp_path, capsys, size, fragment):
    assert_refused(*run(tmp_path, floor_obj(tmp_path / "f.obj", size), "", capsys), fragment, "mesh.scale")


@pytest.mark.parametrize(
    "params, fragment",
    [
        ("{cell_size: 0.001}", "graph.params.cell_size: the agent's radius of 0.5 m is 500 cells"),
        ("{cell_size: 1.0e-9}", "graph.params.cell_size: the agent's radius"),
        ("{cell_size: 1.0e+12}", "graph.params.cell_size: 1e+12 m cells are larger than the level"),
        ("{cell_height: 1.0e-9}", "graph.params.cell_height: the agent's height of 2 m is 2e+09 cells"),
        ("{tile_size: 1.0e+9}", "graph.params.tile_size"),
        ("{region_min_size: 1.0e+6}", "graph.params.region_min_size"),
        ("{region_merge_size: 1.0e+6}", "graph.params.region_merge_size"),
        ("{agent_radius: .inf}", "graph.params.agent_radius"),
        ("{cell_size: .nan}", "graph.params.cell_size"),
        ("{edge_max_len: 1.0e+9}", "graph.params.edge_max_len"),
        ("{max_cells: 1.0e+30}", "graph.params.max_cells"),
    ],
)
def test_graph_params_recast_cannot_use(tmp_path, capsys, params, fragment):
    mesh = floor_obj(tmp_path / "f.obj", 10)
    assert_refused(*run(tmp_path, mesh, f"graph: {{plugin: navmesh, params: {params}}}\n", capsys), fragment)


@pytest.mark.parametrize(
    "section, fragment",
    [
        ("mesh: {scale: .inf}", "mesh.scale"),
        ("mesh: {scale: 1.0e+308}", "mesh.scale: 1e+308 makes"),
        ("mesh: {scale: 1.0e-320}", "mesh: the level is less than one 0.25 m cell across (0 x 0 m"),
        ("agent: {height: .inf}", "agent.height"),
        ("agent: {radius: .inf}", "agent.radius"),
        ("agent: {max_climb: .nan}", "agent.max_climb"),
        ("agent: {radius: 1.0e+12}", "agent.radius: the agent's radius of 1e+12 m is 1e+12 cells"),
        ("agent: {height: 1.0e+6}", "agent.height: the agent's height of 1e+06 m"),
    ],
)
def test_agent_and_mesh_values_recast_cannot_use(tmp_path, capsys, section, fragment):
    assert_refused(*run(tmp_path, floor_obj(tmp_path / "f.obj", 10), section + "\n", capsys), fragment)


def test_cli_process_exit_code_and_one_line(tmp_path):
    mesh = floor_obj(tmp_path / "f.obj", 10)
    config = tmp_path / "c.yaml"
    config.write_text("extends: graph_only\ngraph: {plugin: navmesh, params: {cell_height: 1.0e-9}}\n")
    proc = subprocess.run([sys.executable, "-m", "g2s_core.cli", "run", str(config), str(mesh), "-o",
                           str(tmp_path / "out")], capture_output=True, text=True, cwd=PROJECT,
                          env={**os.environ, "COLUMNS": "300"})
    assert proc.returncode == 2 and "Traceback" not in proc.stderr
    assert [line for line in proc.stderr.splitlines() if line.strip()] == [proc.stderr.strip()]
    assert "graph.params.cell_height" in proc.stderr and "agent settings" not in proc.stderr
    assert not (tmp_path / "out").exists()


class Agent:
    radius, height, max_climb, max_slope = 0.5, 2.0, 0.4, 45.0


def test_memory_guard_bounds_tiles_not_the_whole_grid():
    # a 3 km square level: 12000 x 12000 cells of 0.25 m (144 M, more than the default
    # max_cells) in 256-cell tiles of 266 x 266 cells each: the guard bounds one tile
    corners = np.array([[0.0, 0.0, 0.0], [3000.0, 3.0, 3000.0]])
    check_grid(corners, resolve_settings(Agent()))
    settings = resolve_settings(Agent())
    check_grid(corners, {**settings, "max_cells": 266 * 266})
    with pytest.raises(SettingsError, match="graph.params.max_cells: a tile of 256 cells plus its 5-cell border"):
        check_grid(corners, {**settings, "max_cells": 266 * 266 - 1})
    # forced solo, the same level is the whole grid
    with pytest.raises(SettingsError, match="graph.params.tile_size: a solo grid of 12000 x 12000 cells"):
        check_grid(corners, {**settings, "tile_size": 0})


def test_tile_count_is_bounded_without_overflow():
    corners = np.array([[-2.0e6, 0.0, -2.0e6], [2.0e6, 3.0, 2.0e6]])  # 1.6e7 cells a side, centred on the origin
    with pytest.raises(SettingsError, match="needs 3906250000 tiles"):
        check_grid(corners, resolve_settings(Agent(), RecastParams(cell_size=0.25)), cell_size_given=True,
                   max_level_cells=1 << 62)


# --- a level in the wrong units (docs/errors.md, "Units and scale") -------------------------------------------------


def test_flat_level_a_hundred_times_too_large_is_refused_at_once(tmp_path, capsys):
    # a flat 200 m level read at mesh.scale: 100 is 20 km across and has no height to show it: 6.4e9 cells
    # of 0.25 m, which Recast would build for about an hour; the time guard refuses it before any work
    mesh = floor_obj(tmp_path / "f.obj", 200)
    code, err = run(tmp_path, mesh, "mesh: {scale: 100}\n", capsys)
    assert_refused(code, err, "error: f.obj: mesh: the level (2e+04 x 2e+04 m", "graph.params.max_level_cells=1e+09", "mesh.scale")
    assert run(tmp_path, mesh, "", capsys)[0] == 0


def test_the_time_guard_counts_the_whole_grid():
    corners = np.array([[0.0, 0.0, 0.0], [250.0, 0.0, 250.0]])  # 1000 x 1000 cells of 0.25 m
    settings = resolve_settings(Agent())
    check_grid(corners, settings, max_level_cells=1000 * 1000)
    with pytest.raises(SettingsError, match=r"mesh: the level \(250 x 250 m .* 1000 x 1000 cells of 0.25 m"):
        check_grid(corners, settings, max_level_cells=1000 * 1000 - 1)
    with pytest.raises(SettingsError, match="graph.params.cell_size: the level"):
        check_grid(corners, resolve_settings(Agent(), RecastParams(cell_size=0.25)), cell_size_given=True,
                   max_level_cells=10)


def test_level_a_hundred_times_too_small_shows_its_size(tmp_path, capsys):
    # a 200 m level of rooms and corridors read at mesh.scale: 0.01 is 2 m across: nothing is walkable,
    # and the error gives the size, so that the wrong units show, and names mesh.scale first
    mesh = tmp_path / "rooms.obj"
    rooms = trimesh.util.concatenate([trimesh.creation.box(extents=(200, 0.2, 200)).apply_translation((0, -0.1, 0))]
                                     + [trimesh.creation.box(extents=(4, 3, 150)).apply_translation((x, 1.5, 0))
                                        for x in (-60, -20, 20, 60)])
    rooms.export(mesh)
    code, err = run(tmp_path, mesh, "mesh: {scale: 0.01}\n", capsys)
    assert_refused(code, err, "error: rooms.obj: no walkable surface", "the level is 2 x 2 m (x, z), 0.032 m tall: check mesh.scale")
    assert run(tmp_path, mesh, "", capsys)[0] == 0


@pytest.mark.parametrize("preset", ["graph_only", "map_piece"])
def test_y_up_level_read_as_z_up_names_the_up_axis(tmp_path, capsys, preset):
    # mesh.up_axis: z on a Y-up file stands the level on its side: its floors face along z. The tops of its
    # walls are walkable, so the run ends (exit 0) with a warning naming the key; a level whose walls have no
    # walkable top stops with exit 2 and the same cause (test_bumpy_z_up_level_read_as_y_up_names_the_up_axis)
    config = tmp_path / "c.yaml"
    config.write_text(f"extends: {preset}\nmesh: {{up_axis: z}}\n")
    outcome = main(["run", str(config), "sample:cross_hub", "-o", str(tmp_path / "out"), "--quiet"])
    err = capsys.readouterr().err
    assert outcome == 0, err
    assert "Traceback" not in err and "`mesh: {up_axis: z}` (or `y` if it is already z)" in err, err


def test_level_far_from_the_origin_builds_and_is_refused_only_where_double_precision_loses_the_cell(tmp_path, capsys):
    """At 5e6 m single precision keeps 0.5 m between values and Recast's rasteriser overran its stack (exit 134):
    the level is now built in its local frame; at 2e15 m double precision keeps only 0.25 m, half a cell."""
    def square(name: str, centre: float) -> Path:
        return quad_obj(tmp_path / name, [(centre - 20, 0, centre - 20), (centre - 20, 0, centre + 20),
                                          (centre + 20, 0, centre + 20), (centre + 20, 0, centre - 20)])

    (tmp_path / "near").mkdir(), (tmp_path / "far").mkdir()
    code, err = run(tmp_path / "near", square("utm.obj", 5e6), "", capsys)
    assert code == 0, err
    assert_refused(*run(tmp_path / "far", square("far.obj", 2e15), "", capsys),
                   "far.obj: mesh: vertices lie up to 2e+15 m from the origin, where double precision keeps only "
                   "0.25 m between values, more than half the cell of 0.25 m; move the level within 1.126e+15 m")
