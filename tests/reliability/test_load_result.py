"""``load_result`` on structure.json files that are not what g2s wrote: one G2SError naming the
file and the field, never another exception."""

from __future__ import annotations

import copy
import json
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from g2s_core.cli import main
from g2s_core.errors import G2SError
from g2s_plugins.outputs.json_reader import load_result


@pytest.fixture(scope="module")
def written(tmp_path_factory) -> dict:
    """A real structure.json of a whole run."""
    out = tmp_path_factory.mktemp("result")
    assert main(["run", "configs/map_analysis.yaml", "sample:cross_hub", "-o", str(out), "--format", "json", "-q"]) == 0
    return json.loads((out / "structure.json").read_text())


def _write(folder: Path, document) -> Path:
    path = folder / "structure.json"
    path.write_text(json.dumps(document) if not isinstance(document, str) else document)
    return path


def _set(document: dict, where: tuple, value) -> dict:
    changed = copy.deepcopy(document)
    target = changed
    for key in where[:-1]:
        target = target[key]
    target[where[-1]] = value
    return changed


CASES = [
    (("nodes", 0, "id"), 1e400, "nodes[0].id"),  # JSON reads 1e400 as inf: an OverflowError in int()
    (("nodes", 0, "id"), "seven", "nodes[0].id"),
    (("nodes", 0, "position"), [1, 2], "nodes[0].position"),
    (("nodes", 0, "position"), None, "nodes[0].position"),
    (("nodes", 0, "values"), [], "nodes[0].values"),
    (("nodes", 0, "extra"), "x", "nodes[0].extra"),
    (("nodes",), {"a": 1}, "nodes"),
    (("edges", 0, "source"), [0], "edges[0].source"),
    (("mesh",), [], "mesh"),
    (("mesh", "name"), 3, "mesh.name"),
    (("terminals",), {"node_ids": "abc", "openings": []}, "terminals"),
    (("graphs", "steiner", "edge_list"), [[1, 2, 3]], "graphs.steiner"),
    (("directed",), "yes", "directed"),
    (("roots",), [1.5], "roots[0]"),
    (("warnings",), "one", "warnings"),
    (("stages", 0), 5, "stages[0]"),
    (("stages", 2), {"\n": None}, "stages[2]"),  # a key holding a newline is quoted, not written raw: one line
    (("nodes", 0, "a\nb"), 1, "nodes[0].'a\\nb'"),
]


@pytest.mark.parametrize("where, value, field", CASES, ids=[c[2] + "=" + repr(c[1])[:12] for c in CASES])
def test_malformed_field_is_named(where, value, field, written, tmp_path):
    path = _write(tmp_path, _set(written, where, value))
    with pytest.raises(G2SError) as caught:
        load_result(path)
    message = str(caught.value)
    assert message.startswith(f"{path}: ") and field in message and "\n" not in message, message


@pytest.mark.parametrize(
    "where, field",
    [(("edges", 0, "target"), "edges[0].target"), (("edges", 1, "source"), "edges[1].source"), (("roots", 0), "roots[0]")],
)
def test_a_reference_to_a_node_not_in_nodes_is_refused(where, field, written, tmp_path):
    missing = max(node["id"] for node in written["nodes"]) + 1
    path = _write(tmp_path, _set(written, where, missing))
    with pytest.raises(G2SError) as caught:
        load_result(path)
    # was "malformed structure file (ValueError: FIELD: ...)" before 4 December 2026 (robust5)
    assert str(caught.value) == f"{path}: {field}: node {missing} is not in nodes"


@pytest.mark.parametrize(
    "text, says",
    [
        ("", "invalid JSON"),
        ("[]", "not a g2s structure.json file"),
        ('{"format": "g2s-structure", "schema_version": 99}', "schema_version 99"),
        ('{"format": "g2s-structure", "schema_version": 1}', ": required key is missing"),
        ('{"format": "g2s-structure", "schema_version": 1, "x": ' + "[" * 5000 + "]" * 5000 + "}", "nested deeper"),
        ('{"format": "g2s-structure", "schema_version": 1e999}', "schema_version inf"),
    ],
    ids=["empty", "list", "version", "bare", "deep", "infinite-version"],
)
def test_malformed_documents(text, says, tmp_path):
    path = _write(tmp_path, text)
    with pytest.raises(G2SError) as caught:
        load_result(path)
    assert str(caught.value).startswith(str(path)) and says in str(caught.value), str(caught.value)


def test_the_written_file_loads(written, tmp_path):
    loaded = load_result(_write(tmp_path, written))
    assert loaded.structure.number_of_nodes() == len(written["nodes"])


def _paths(document, prefix=()):
    """Every (path, value) inside ``document``."""
    yield prefix, document
    if isinstance(document, dict):
        for key, value in document.items():
            yield from _paths(value, (*prefix, key))
    elif isinstance(document, list):
        for index, value in enumerate(document[:3]):
            yield from _paths(value, (*prefix, index))


_JSON_VALUES = st.recursive(
    st.one_of(st.none(), st.booleans(), st.integers(-(10**20), 10**20), st.floats(allow_nan=False),
              st.text(max_size=5)),
    lambda children: st.one_of(st.lists(children, max_size=3), st.dictionaries(st.text(max_size=4), children, max_size=3)),
    max_leaves=8,
)


@settings(max_examples=60, deadline=None)
@given(data=st.data())
def test_any_single_change_loads_or_is_a_clean_error(data, written, tmp_path_factory):
    places = [p for p, _ in _paths(written) if p]
    where = data.draw(st.sampled_from(places))
    document = _set(written, where, data.draw(_JSON_VALUES)) if data.draw(st.booleans()) else _drop(written, where)
    path = _write(tmp_path_factory.mktemp("mutant"), document)
    try:
        load_result(path)
    except G2SError as exc:
        assert str(exc).startswith(f"{path}: ") and "\n" not in str(exc)


def _drop(document: dict, where: tuple) -> dict:
    changed = copy.deepcopy(document)
    target = changed
    for key in where[:-1]:
        target = target[key]
    del target[where[-1]]
    return changed


def _older(document: dict, version: int) -> dict:
    """``document`` as an older version wrote it: version 1 had no ``features``, 1 and 2 no ``metrics``."""
    dropped = {"metrics", "features"} if version == 1 else {"metrics"}
    old = {k: v for k, v in copy.deepcopy(document).items() if k not in dropped}
    old["schema_version"] = version
    return old


@pytest.mark.parametrize("version", [1, 2])
def test_older_files_are_read_and_checked_as_the_current_version_without_its_new_fields(version, written, tmp_path):
    loaded = load_result(_write(tmp_path, _older(written, version)))
    assert loaded.schema_version == version and loaded.metrics == {}
    assert version > 1 or loaded.features == {}
    assert loaded.structure.number_of_nodes() == len(written["nodes"])
    path = _write(tmp_path, _set(_older(written, version), ("nodes", 0, "position"), [1, 2]))
    with pytest.raises(G2SError, match=r"nodes\[0\]\.position"):
        load_result(path)
    for field in ("features", "metrics")[version - 1:]:
        path = _write(tmp_path, {**_older(written, version), field: {}})
        with pytest.raises(G2SError, match=f"{field}: not a field of schema_version {version}"):
            load_result(path)


@pytest.mark.parametrize("run_text", ["[]", "{", '{"stages": 5}', "[" * 5000, "\xff"])
def test_a_damaged_run_json_only_loses_the_timings(run_text, written, tmp_path):
    _write(tmp_path, written)
    (tmp_path / "run.json").write_text(run_text, encoding="latin-1")
    loaded = load_result(tmp_path)
    assert [s.stage for s in loaded.stages] == [s["stage"] for s in written["stages"]]
    assert all(s.seconds != s.seconds for s in loaded.stages)  # NaN: no timings
