"""Inputs robust8 (4 December 2026) found read silently wrong or told in other words: a mesh of triangles whose
corners lie on a line (no area, to rounding) gave a structure, Recast having filled every cell they touch with floor;
a ``.glb`` that is not one was a Python exception's words; an interrupt while the interpreter wound down after a run
killed g2s by SIGINT without a word; the Python API's ``write`` named ``--format``."""

from __future__ import annotations

import math
import subprocess
import sys

import numpy as np
import pytest
import trimesh

import g2s_core
from g2s_core.errors import G2SError
from g2s_plugins.walkable_check import MAX_SURFACE_OVER_FACES, has_no_area, upward_plan_area
from tests.reliability.checks import assert_clean_error, run_g2s, tree


def slivers(count: int, size: float, seed: int = 0) -> trimesh.Trimesh:
    """``count`` triangles in the plane y = 0 over ``size`` x ``size`` m, each with its third corner on the line
    through the other two (computed in double precision: areas of rounding only)."""
    rng = np.random.default_rng(seed)
    start = rng.uniform(0, size, (count, 2))
    angle = rng.uniform(0, 2 * math.pi, count)
    along = np.stack([np.cos(angle), np.sin(angle)], 1) * rng.uniform(0.2, 1.0, (count, 1))
    corners = np.stack([start, start + along, start + rng.uniform(0.1, 0.9, (count, 1)) * along], 1).reshape(-1, 2)
    vertices = np.zeros((3 * count, 3))
    vertices[:, [0, 2]] = corners
    return trimesh.Trimesh(vertices, np.arange(3 * count).reshape(count, 3), process=False)


def grating(width: float, pitch: float, size: float) -> trimesh.Trimesh:
    """A floor of bars ``width`` m wide along z, one every ``pitch`` m over ``size`` x ``size`` m, facing up."""
    bars = [trimesh.Trimesh([[x, 0, 0], [x + width, 0, 0], [x + width, 0, size], [x, 0, size]], [[0, 2, 1], [0, 3, 2]])
            for x in np.arange(0.0, size, pitch)]
    return trimesh.util.concatenate(bars)


@pytest.fixture(scope="module")
def sliver_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("slivers") / "slivers.obj"
    slivers(20_000, 8.0).export(path)
    return path


def test_the_sliver_mesh_has_no_area_and_no_face_facing_up(sliver_file):
    mesh = trimesh.load(sliver_file, force="mesh", process=False)
    assert has_no_area(mesh) and upward_plan_area(mesh, 45.0) < 1e-3  # the file's 8 decimals: areas of rounding
    assert not has_no_area(grating(0.005, 0.25, 4.0))


def test_a_mesh_of_slivers_alone_is_refused_naming_the_file(sliver_file, tmp_path, capsys):
    # was exit 0 and a structure of a few nodes on a navmesh covering the slivers' plan
    outcome = run_g2s(capsys, "run", "map_analysis", sliver_file, "-o", tmp_path / "out")
    assert_clean_error(outcome, f"{sliver_file.name}: the walkable surface found (",
                       f"is more than {MAX_SURFACE_OVER_FACES:g} times the plan area of the faces that face up (",
                       "the faces have next to no area (corners on a line or at one point)")
    assert tree(tmp_path / "out") == []


def test_the_sampling_route_names_the_zero_area_of_slivers(sliver_file, tmp_path, capsys):
    # was "the level is 9 x 9 m ...: check mesh.scale ..., the agent settings, the mesh's up_axis, and ... winding"
    outcome = run_g2s(capsys, "run", "map_analysis_sampling", sliver_file, "-o", tmp_path / "out")
    assert_clean_error(outcome, f"{sliver_file.name}: no walkable surface for the agent",
                       "every face has zero area (its corners on a line or at one point)")


def test_a_grating_of_thin_bars_is_still_a_floor():
    result = g2s_core.run(grating(0.005, 0.25, 8.0), "map_analysis", stop_after="graph")
    walkable = sum(area for _, area in result.graph.nodes(data="area"))
    assert 10 < walkable / upward_plan_area(result.context.mesh, 45.0) < MAX_SURFACE_OVER_FACES


def test_slivers_beside_a_floor_are_not_refused():
    floor = trimesh.Trimesh([[0, 0, 0], [8, 0, 0], [8, 0, 8], [0, 0, 8]], [[0, 2, 1], [0, 3, 2]])
    result = g2s_core.run(trimesh.util.concatenate([floor, slivers(20_000, 8.0).apply_translation([8, 0, 0])]),
                          "map_analysis", stop_after="graph")
    assert result.graph.number_of_nodes() > 0


def test_the_check_raises_through_the_api_too():
    with pytest.raises(G2SError, match="the faces have next to no area"):
        g2s_core.run(slivers(20_000, 8.0), "map_analysis", stop_after="graph")


def test_an_interrupt_after_the_command_leaves_its_exit_code(tmp_path):
    # a Ctrl-C (or SIGTERM) while the interpreter wound down after a run (1.3 s after one of 584 polygons) killed g2s
    # by SIGINT without a word, its results written: a status of 130 over a finished run
    script = (
        "import os, signal, sys\n"
        "from g2s_core import entry\n"
        f"sys.argv = ['g2s', 'run', 'graph_only', 'sample:straight_corridor', '-q', '-o', {str(tmp_path / 'out')!r}]\n"
        "code = entry.main()\n"
        "os.kill(os.getpid(), signal.SIGINT)\n"
        "os.kill(os.getpid(), signal.SIGTERM)\n"
        "sys.exit(code)\n"
    )
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120)
    assert (done.returncode, done.stderr) == (0, "")
    assert tree(tmp_path / "out") == ["graph.json"]


@pytest.mark.parametrize("data, says", [
    (b"hello world\n", "not a GLB file: it starts with b'hell', not b'glTF'"),
    (bytes(range(200, 256)) * 20, "not a GLB file: it starts with b'\\xc8\\xc9\\xca\\xcb', not b'glTF'"),
    # robust44: the glTF JSON is named by the check of every file whose content is another format's
    (b'{"asset": {"version": "2.0"}}', "the file's content is not GLB (binary glTF) but glTF JSON, by its first bytes "
                                       "b'{\"ass'; rename it level.gltf"),
])
def test_a_glb_file_that_is_none_says_so(data, says, tmp_path, capsys):
    # was "cannot read mesh (ValueError: incorrect header on GLB file)", a Python exception's words
    path = tmp_path / "level.glb"
    path.write_bytes(data)
    outcome = run_g2s(capsys, "run", "graph_only", path, "-o", tmp_path / "out")
    assert assert_clean_error(outcome) == f"g2s: error: {path}: {says}"


def test_the_python_api_names_its_own_formats_parameter(tmp_path):
    result = g2s_core.run("sample:straight_corridor", "graph_only")
    with pytest.raises(G2SError, match=r"^formats: unknown output format 'jsno' \(expected some of: "):  # was "--format: ..."
        result.write(tmp_path / "out", formats=["jsno"])
    assert not (tmp_path / "out").exists()
