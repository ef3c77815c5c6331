"""Inputs robust18 (6 December 2026) found breaking docs/errors.md's rules: an output folder whose path is not UTF-8
(bytes Python keeps as lone surrogates) in the line ``--json`` prints, in a batch's row files and its summary (an
internal error); a ``mesh_name`` given through the Python API that is not text or not UTF-8; a config of one long
comment read a character at a time; and the Python API's arguments of a wrong type (a ``TypeError`` or
``AttributeError`` from pathlib, not the documented ``G2SError`` naming the argument). Assertion messages show such
names through ``ascii`` so that a failure prints."""

from __future__ import annotations

import json
import os

import pytest
import yaml

from g2s_core.config import _Loader, _parse_yaml
from g2s_core.errors import ConfigError, G2SError, MeshError
from tests.reliability.checks import CORRIDOR, run_g2s

NOT_UTF8 = os.fsdecode(b"out\xff")
"""A folder name holding the byte 0xFF, which starts no UTF-8 character (Linux file names are bytes)."""


def strict_text(value: object) -> bool:
    """Whether every text in a JSON value (keys too) can be written as UTF-8 (no lone surrogate)."""
    if isinstance(value, dict):
        return all(strict_text(k) and strict_text(v) for k, v in value.items())
    if isinstance(value, list):
        return all(map(strict_text, value))
    return not isinstance(value, str) or not any("\ud800" <= c <= "\udfff" for c in value)


def test_the_json_line_names_an_output_folder_that_is_not_utf8_as_text(tmp_path, capsys):
    out = tmp_path / NOT_UTF8
    outcome = run_g2s(capsys, "run", "graph_only", CORRIDOR, "-o", out, "--json")
    assert outcome.code == 0, ascii(outcome.stderr)
    printed = json.loads(outcome.stdout)
    assert printed["outdir"] == f"{tmp_path}/out\\xff" and strict_text(printed), ascii(printed)
    assert printed["files"] == [f"{tmp_path}/out\\xff/graph.json"], ascii(printed["files"])


def test_a_batch_into_a_folder_that_is_not_utf8_writes_its_summary_and_text_rows(tmp_path, capsys):
    config = tmp_path / "quick.yaml"
    config.write_text("extends: graph_only\n")
    out = tmp_path / NOT_UTF8
    outcome = run_g2s(capsys, "batch", config, CORRIDOR, "-o", out, "--executor", "serial", "-q")
    assert outcome.code == 0, ascii(outcome.stderr)  # was 1: pyarrow encodes the summary's path as UTF-8
    row = json.loads(next((out / ".g2s-batch" / "quick").iterdir()).read_text(encoding="utf-8"))
    assert row["folder"] == f"{tmp_path}/out\\xff/quick/straight_corridor" and strict_text(row), ascii(row)
    assert (out / "summary.parquet").is_file() and "out\\xff" in (out / "summary.csv").read_text(encoding="utf-8")


@pytest.fixture(scope="module")
def slab():
    import trimesh

    return trimesh.creation.box(extents=(8.0, 0.2, 3.0))


def test_a_mesh_name_that_is_not_utf8_is_made_text_as_a_file_name_is(slab):
    from g2s_core import api

    result = api.run(slab, "graph_only", mesh_name=os.fsdecode(b"m\xff"))
    assert result.mesh_name == "m\\xff", ascii(result.mesh_name)


@pytest.mark.parametrize("name", [5, b"slab", object()])
def test_a_mesh_name_that_is_not_text_is_refused_naming_the_argument(slab, name):
    from g2s_core import api

    with pytest.raises(MeshError, match=f"^mesh_name: expected a text, got {type(name).__name__}$"):
        api.run(slab, "graph_only", mesh_name=name)


YAML_WITH_COMMENTS = [
    "# only a comment",
    "a: 1  # after a value\n# a line\n  # indented\nb: [1, # in a flow\n 2]\n",
    "\ufeff# after a byte-order mark\na: 1\n",
    "a: 1 # a comment with \ufeff inside, then the end\n# and \ufeff\ufeff again",
    "a:\n  - 1\n  # between items\n  - 2\n# the end, no line break",
    "a: |\n  # text of a literal block, not a comment\n  b\nc: 2 # comment\r\n# a CR LF line\r\nd: 3\n",
    "a: [1, 2\n# unclosed, an error after a comment",
]


@pytest.mark.parametrize("text", YAML_WITH_COMMENTS)
def test_comments_are_passed_over_as_pyyaml_passes_them(text):
    """The same tokens at the same marks (index, line, column) as PyYAML's own loader, or the same error."""
    def tokens(loader_class):
        loader = loader_class(text)
        try:
            return [(type(t).__name__, getattr(t, "value", None), t.start_mark.index, t.start_mark.line,
                     t.start_mark.column, t.end_mark.column) for t in iter(loader.get_token, None)]
        except yaml.YAMLError as exc:
            return str(exc)
    assert tokens(_Loader) == tokens(yaml.SafeLoader)


def test_a_long_comment_is_passed_over_in_one_step(monkeypatch):
    """PyYAML moved over a comment one character at a time (a config of one 50 MB comment line: 21 s of CPU)."""
    calls = []
    forward = yaml.reader.Reader.forward
    monkeypatch.setattr(yaml.reader.Reader, "forward", lambda self, length=1: calls.append(length) or forward(self, length))
    assert _parse_yaml("# " + "x" * 100_000 + "\na: 1  # " + "y" * 100_000 + "\n", "c.yaml") == {"a": 1}
    assert len(calls) < 20, len(calls)


@pytest.fixture(scope="module")
def result(slab):
    from g2s_core import api

    return api.run(slab, "graph_only", mesh_name="slab")


@pytest.mark.parametrize(("outdir", "got"), [(None, "NoneType"), (5, "int"), (b"out", "bytes"), ("", "an empty name"),
                                             (" ", "an empty name")])
def test_write_refuses_an_outdir_that_is_no_folder_path(result, outdir, got, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # an empty name was the working folder, and the files were written there
    with pytest.raises(G2SError, match=f"^outdir: expected a folder, got {got}$"):
        result.write(outdir)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(("formats", "got"), [(5, "int"), (b"json", "bytes"), ({"json": 1}, "dict")])
def test_write_refuses_formats_that_are_neither_a_text_nor_a_list(result, formats, got, tmp_path):
    with pytest.raises(G2SError, match=f"^formats: expected names, comma-separated or in a list, got {got}$"):
        result.write(tmp_path / "out", formats=formats)


@pytest.mark.parametrize(("path", "got"), [(None, "NoneType"), (5, "int"), ("", "an empty name")])
def test_load_result_refuses_a_path_that_is_no_path(path, got):
    from g2s_core import load_result

    with pytest.raises(G2SError, match=f"^path: expected a result folder or its structure.json, got {got}$"):
        load_result(path)


def test_run_refuses_an_empty_mesh_or_config_and_a_progress_that_cannot_be_called(slab):
    from g2s_core import api

    with pytest.raises(MeshError, match="^mesh: expected a mesh file, sample:NAME or a trimesh.Trimesh, got an empty name$"):
        api.run("")
    with pytest.raises(ConfigError, match="^config: expected a config file, a preset name, a mapping or a RunConfig, got an empty name$"):
        api.run(slab, "")
    with pytest.raises(G2SError, match="^progress: expected a function of one argument or None, got str$"):
        api.run(slab, "graph_only", progress="stage")


@pytest.mark.parametrize(("args", "kwargs", "message"), [
    (("graph_only", ["x.obj"], "out"), {}, "configs: expected a list of preset names or config files, got the text 'graph_only'"),
    ((["graph_only"], "x.obj", "out"), {}, "inputs: expected a list of mesh files, folders, patterns or sample:NAME, got the text 'x.obj'"),
    (([{"extends": "graph_only"}], ["x.obj"], "out"), {}, "configs[0]: expected a preset name or a config file, got dict"),
    ((["graph_only"], [5], "out"), {}, "inputs[0]: expected a mesh file, a folder, a pattern or sample:NAME, got int"),
    ((["graph_only"], ["x.obj"], None), {}, "outdir: expected a folder, got NoneType"),
    ((["graph_only"], ["x.obj"], "out"), {"evaluators": "traffic"}, "evaluators: expected a list of evaluator names, got the text 'traffic'"),
    ((["graph_only"], ["x.obj"], "out"), {"formats": 5}, "formats: expected names, comma-separated or in a list, got int"),
    ((["graph_only"], ["x.obj"], "out"), {"progress": 5}, "progress: expected a function of one argument or None, got int"),
])
def test_run_batch_refuses_arguments_of_the_wrong_type_before_any_pair(args, kwargs, message, tmp_path, monkeypatch):
    from g2s_core.batch import run_batch

    monkeypatch.chdir(tmp_path)
    with pytest.raises(G2SError) as caught:
        run_batch(*args, executor="serial", **kwargs)
    assert str(caught.value) == message
    assert list(tmp_path.iterdir()) == []
