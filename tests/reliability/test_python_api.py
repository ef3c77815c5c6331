"""The Python API (g2s_core.run, RunResult.write, load_result) keeps the command line's promises:
a bad config, key or mesh raises one G2SError line naming it; a folder that cannot take the results
is refused before anything is written; a run's files appear all together or not at all; inputs
(mesh, config files, points files) are never overwritten."""

from __future__ import annotations

from pathlib import Path

import pytest

import g2s_core
from g2s_core.errors import ConfigError, G2SError, MeshError
from g2s_plugins.outputs import heatmap
from tests.reliability.checks import CORRIDOR, snapshot, tree


@pytest.fixture(scope="module")
def result():
    """A quick complete run (step 1 only) of a generated corridor."""
    return g2s_core.run(CORRIDOR, "graph_only")


def _one_line(error: pytest.ExceptionInfo, *fragments: str) -> None:
    message = str(error.value)
    assert "\n" not in message and message, message
    for fragment in fragments:
        assert fragment in message, message


@pytest.mark.parametrize(
    "config, overrides, fragments",
    [
        ({"extends": "graph_only", "agent": {"radius": "wide"}}, {}, ("config mapping", "agent.radius", "'wide'")),
        ({"extends": "graph_only", "agent": {"radius": float("nan")}}, {}, ("agent.radius", "finite")),
        ({"extends": "graph_only", "agnet": {}}, {}, ("config mapping", "agnet")),
        ({"extends": "no_such_preset"}, {}, ("config mapping", "extends", "no_such_preset")),
        ({"extends": "graph_only", "graph": {"plugin": "navmesh", "params": {"cell_size": -1}}}, {},
         ("cell_size",)),
        ("graph_only", {"agent.radiuss": 1}, ("override agent.radiuss", "unknown key 'radiuss'")),
        ("graph_only", {"agent.radius": float("inf")}, ("agent.radius", "finite")),
        ("graph_only", {"graph.params.cell_size": "small"}, ("cell_size", "'small'")),
        (42, {}, ("config", "int")),
    ],
    ids=["wrong-type", "nan", "unknown-section", "missing-extends", "plugin-param", "unknown-key",
         "infinite-override", "plugin-override", "not-a-config"],
)
def test_bad_config_dict_or_key(config, overrides, fragments):
    with pytest.raises(ConfigError) as error:
        g2s_core.run(CORRIDOR, config, **overrides)
    _one_line(error, *fragments)


def test_deeply_nested_config_dict():
    config: dict = {"extends": "graph_only", "graph": {"plugin": "navmesh", "params": {}}}
    inner = config["graph"]["params"]
    for _ in range(2000):
        inner["x"] = {}
        inner = inner["x"]
    with pytest.raises(ConfigError) as error:
        g2s_core.run(CORRIDOR, config)
    _one_line(error, "config mapping", "nested deeper than 100 levels")


@pytest.mark.parametrize(
    "make, fragments",
    [
        (lambda tmp: tmp / "missing.obj", ("missing.obj", "no such mesh file")),
        (lambda tmp: tmp, ("expected a mesh file, got a folder",)),
        (lambda tmp: _text(tmp / "junk.obj", "v 1 2\nf 1 2 3\n"), ("junk.obj",)),
        (lambda tmp: _text(tmp / "empty.stl", ""), ("empty.stl",)),
        (lambda tmp: _text(tmp / "level.txt", "v 0 0 0\n"), ("level.txt", "unsupported mesh type")),
    ],
    ids=["missing", "folder", "malformed-obj", "empty-stl", "unsupported-type"],
)
def test_bad_mesh(make, fragments, tmp_path):
    mesh = make(tmp_path)
    with pytest.raises(MeshError) as error:
        g2s_core.run(str(mesh), "graph_only")
    _one_line(error, *fragments)


@pytest.mark.parametrize("make", [lambda t: t.Scene(), lambda t: t.PointCloud([[0, 0, 0]]), lambda t: None],
                         ids=["scene", "point-cloud", "none"])
def test_a_mesh_of_another_type_is_a_mesh_error(make):
    # was "TypeError: expected str, bytes or os.PathLike object, not Scene": trimesh.load gives a Scene for a glTF
    import trimesh

    with pytest.raises(MeshError) as error:
        g2s_core.run(make(trimesh), "graph_only")
    _one_line(error, "mesh: expected a mesh file, sample:NAME or a trimesh.Trimesh, got")


def test_numpy_values_in_a_config_are_recorded_as_numbers():
    # were "PydanticSerializationError: Unable to serialize unknown type: <class 'numpy.int64'>" as the run ended
    import numpy as np

    result = g2s_core.run(CORRIDOR, {"extends": "map_analysis", "roots": {"plugin": "point", "params": {"point": np.array([1.0, 0, 2])}}},
                          **{"terminals.params.radius": np.int64(6)})
    assert result.config["roots"]["params"]["point"] == [1.0, 0.0, 2.0]
    assert result.config["terminals"]["params"]["radius"] == 6


def test_a_nul_byte_in_a_structure_path_is_a_clean_error():
    # the reader's os.open raised ValueError, reported as the json reader's own failure
    with pytest.raises(G2SError) as error:
        g2s_core.load_result("a\0b.json")
    _one_line(error, "cannot read structure file (embedded null byte)")


def _text(path: Path, text: str) -> Path:
    path.write_text(text)
    return path


@pytest.mark.parametrize(
    "where, fragment",
    [
        (lambda tmp: Path("/proc/g2s-results"), "cannot write results there"),
        (lambda tmp: tmp / "afile" / "sub", "afile is not a folder"),
        (lambda tmp: tmp / "afile", "exists and is not a folder"),
    ],
    ids=["proc", "below-a-file", "a-file"],
)
def test_unwritable_outdir(where, fragment, result, tmp_path):
    (tmp_path / "afile").write_text("mine\n")
    outdir = where(tmp_path)
    with pytest.raises(G2SError) as error:
        result.write(outdir, formats="json")
    _one_line(error, str(outdir), fragment)
    assert (tmp_path / "afile").read_text() == "mine\n"
    assert tree(tmp_path) == ["afile"]


def test_existing_results_need_force_and_are_replaced_all_together(result, tmp_path):
    outdir = tmp_path / "out"
    result.write(outdir, formats="json")
    (outdir / "notes.txt").write_text("mine")
    before = snapshot(outdir.iterdir())
    with pytest.raises(G2SError) as error:
        result.write(outdir, formats="json")
    _one_line(error, str(outdir), "already holds results (run.json, structure.json)", "use --force")
    with pytest.raises(G2SError) as error:
        result.write(outdir, formats="png")  # a result of another format counts too
    _one_line(error, "already holds results")
    assert snapshot(outdir.iterdir()) == before
    assert [p.name for p in result.write(outdir, formats="png", force=True)] == ["heatmap.png"]
    assert tree(outdir) == ["heatmap.png", "notes.txt"]  # the json results went in the same step


def test_a_failing_writer_leaves_nothing(result, tmp_path, monkeypatch):
    outdir = tmp_path / "out"
    result.write(outdir, formats="json")
    before = snapshot(outdir.iterdir())

    def fails(result, outdir):
        (outdir / "heatmap.png").write_bytes(b"half")
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(heatmap, "write", fails)
    with pytest.raises(G2SError):
        result.write(outdir, formats="json,png", force=True)
    assert snapshot(outdir.iterdir()) == before and tree(outdir) == ["run.json", "structure.json"]


def test_inputs_are_never_overwritten(tmp_path):
    """The mesh, the config file and a points file lying in the output folder under result
    names are refused even with force, whatever format would write over them."""
    from g2s_plugins.samples import levels as samples

    mesh = tmp_path / "structure.glb"
    samples.straight_corridor().mesh.export(mesh)
    points = tmp_path / "graph.json"
    points.write_text("[[0, 0, 0], [0, 0, 5]]")
    config = tmp_path / "report.html"
    config.write_text("extends: map_analysis\nstop_after: steiner\n"
                      f"terminals: {{plugin: points, params: {{file: '{points}', max_distance: 50}}}}\n")
    inputs = snapshot([mesh, config, points])
    result = g2s_core.run(str(mesh), str(config))
    assert set(result.inputs) >= {mesh, config, points}
    for formats in ("glb", "html", "graph"):
        with pytest.raises(G2SError) as error:
            result.write(tmp_path, formats=formats, force=True)
        _one_line(error, "has the name of a result file", "choose another output folder")
    assert snapshot([mesh, config, points]) == inputs
    assert tree(tmp_path) == ["graph.json", "report.html", "structure.glb"]
