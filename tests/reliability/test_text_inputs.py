"""Config, points and structure files that are not what they claim: FIFOs, devices, folders,
huge, not UTF-8, nested too deeply. Each is refused at once with one line naming the file."""

from __future__ import annotations

import json
import os
from collections.abc import Callable
from pathlib import Path

import pytest

from g2s_core.config import load_config
from g2s_core.errors import ConfigError, G2SError
from g2s_core.input_files import MAX_NESTING, MAX_TEXT_BYTES, nesting_depth, read_text
from g2s_plugins.outputs.json_reader import load_result
from g2s_plugins.terminals.points import read_points
from tests.reliability.checks import CORRIDOR, assert_clean_error, run_g2s, run_g2s_process, tree

# --- the files -------------------------------------------------------------------


def fifo(folder: Path, name: str) -> Path:
    path = folder / name
    os.mkfifo(path)
    return path


def deep_yaml(folder: Path, name: str) -> Path:
    path = folder / name
    path.write_text("a: " + "[" * 1000 + "]" * 1000 + "\n")  # past Python's recursion limit
    return path


def deep_json(folder: Path, name: str) -> Path:
    path = folder / name
    path.write_text("[" * 100_000 + "]" * 100_000)
    return path


def latin1(folder: Path, name: str) -> Path:
    path = folder / name
    path.write_bytes("# café\nagent: {radius: 0.5}\n".encode("latin-1"))
    return path


def folder_input(folder: Path, name: str) -> Path:
    path = folder / name
    path.mkdir()
    return path


BAD_FILES: dict[str, tuple[Callable[[Path, str], Path], str]] = {
    "fifo": (fifo, "got a FIFO"),
    "device": (lambda _folder, _name: Path("/dev/zero"), "got a character device"),
    "folder": (folder_input, "got a folder"),
    "missing": (lambda folder, name: folder / name, "no such"),
    "not-utf8": (latin1, "line 1: byte 0xe9 is not UTF-8"),
    "deep": (deep_yaml, f"nested deeper than {MAX_NESTING} levels"),
}
"""Kind of bad text file -> (maker, what the message says)."""


# --- config files ------------------------------------------------------------------


@pytest.mark.parametrize("kind", sorted(BAD_FILES))
def test_bad_config_file_cli(kind, tmp_path, capsys):
    make, says = BAD_FILES[kind]
    config = make(tmp_path, "config.yaml")
    out = tmp_path / "out"
    outcome = run_g2s(capsys, "run", config, CORRIDOR, "-o", out)
    assert_clean_error(outcome, str(config), says)
    assert tree(out) == []


@pytest.mark.parametrize("kind", sorted(BAD_FILES))
def test_bad_config_file_api(kind, tmp_path):
    make, says = BAD_FILES[kind]
    config = make(tmp_path, "config.yaml")
    with pytest.raises(ConfigError, match=str(config)) as caught:
        load_config(config)
    assert says in str(caught.value)


def test_fifo_config_does_not_hang_a_real_process(tmp_path):
    config = fifo(tmp_path, "config.yaml")
    outcome = run_g2s_process("run", config, CORRIDOR, "-o", tmp_path / "out", timeout=60)
    assert_clean_error(outcome, str(config), "FIFO")


def test_extended_config_is_read_the_same_way(tmp_path, capsys):
    parent = latin1(tmp_path, "parent.yaml")
    child = tmp_path / "child.yaml"
    child.write_text("extends: parent.yaml\n")
    assert_clean_error(run_g2s(capsys, "run", child, CORRIDOR, "-o", tmp_path / "out"), str(parent), "UTF-8")


def test_utf8_byte_order_mark_is_accepted(tmp_path):
    config = tmp_path / "bom.yaml"
    config.write_bytes(b"\xef\xbb\xbfagent: {radius: 0.25}\n")
    assert load_config(config).agent.radius == 0.25


@pytest.mark.parametrize(
    "text, says",
    [
        ("a: &x [*x]\n", "nested deeper"),  # a list that holds itself
        ("a: " + "{b: " * 150 + "1" + "}" * 150 + "\n", "nested deeper"),
        ("a: " + "9" * 5000 + "\n", "unreadable value"),  # more digits than Python converts
        ("a: 2024-13-45\n", "unreadable value"),  # a date that does not exist
        ("a: [1, 2\n", "invalid YAML at line"),
        ("- 1\n- 2\n", "expected a mapping of settings at the top level"),
    ],
    ids=["self-alias", "deep-mapping", "huge-integer", "bad-date", "syntax", "top-list"],
)
def test_odd_yaml_documents(text, says, tmp_path):
    config = tmp_path / "odd.yaml"
    config.write_text(text)
    with pytest.raises(ConfigError, match=str(config)) as caught:
        load_config(config)
    assert says in str(caught.value)


def test_a_config_name_too_long_for_the_file_system_is_not_found(tmp_path, capsys):
    # Path.is_file raised "OSError: [Errno 36] File name too long": an internal error
    config = tmp_path / "long.yaml"
    config.write_text("extends: " + "x" * 5000 + "\n")
    outcome = run_g2s(capsys, "run", config, CORRIDOR, "-o", tmp_path / "out")
    assert_clean_error(outcome, f"{config}: extends: no config file or preset named 'xxx")
    outcome = run_g2s(capsys, "run", "y" * 300, CORRIDOR, "-o", tmp_path / "out")
    assert_clean_error(outcome, "y" * 300 + ": no such config file or preset")


def test_yaml_bomb_is_refused_quickly(tmp_path):
    lines = ["a0: &a0 [x, x, x, x, x, x, x, x, x]"]
    lines += [f"a{i}: &a{i} [{', '.join([f'*a{i - 1}'] * 9)}]" for i in range(1, 10)]
    config = tmp_path / "bomb.yaml"
    config.write_text("\n".join(lines) + "\n")
    with pytest.raises(ConfigError, match="bomb.yaml"):  # 9**10 strings once expanded: it must never be
        load_config(config)


# --- points files ----------------------------------------------------------------------


def points_config(tmp_path: Path, points_file: Path) -> Path:
    config = tmp_path / "points.yaml"
    config.write_text(
        "extends: graph_only\nterminals: {plugin: points, params: {file: '%s'}}\nstop_after: terminals\n" % points_file
    )
    return config


@pytest.mark.parametrize("kind", sorted(set(BAD_FILES) - {"deep"}))
def test_bad_points_file_cli(kind, tmp_path, capsys):
    make, says = BAD_FILES[kind]
    points = make(tmp_path, "points.csv")
    out = tmp_path / "out"
    outcome = run_g2s(capsys, "run", points_config(tmp_path, points), CORRIDOR, "-o", out)
    assert_clean_error(outcome, str(points), says)
    assert tree(out) == []


@pytest.mark.parametrize("kind", sorted(BAD_FILES))
def test_bad_points_file_api(kind, tmp_path):
    make, says = BAD_FILES[kind]
    points = make(tmp_path, "points.json") if kind != "deep" else deep_json(tmp_path, "points.json")
    with pytest.raises(G2SError, match=str(points)) as caught:
        read_points(points)
    assert says in str(caught.value) or kind == "deep" and "nested deeper" in str(caught.value)


@pytest.mark.parametrize(
    "text, says",
    [
        ("[" * 300 + "]" * 300, "nested deeper"),
        ("[[1, 2, " + "9" * 5000 + "]]", "unreadable value"),
        ("[[1, 2]]", "point 0"),
        ('{"points": {"a": 1}}', "expected a list"),
        ("[[1, 2, 3e999]]", "not finite"),
    ],
    ids=["deep", "huge-integer", "two-numbers", "mapping", "infinite"],
)
def test_odd_points_json(text, says, tmp_path):
    points = tmp_path / "points.json"
    points.write_text(text)
    with pytest.raises(G2SError) as caught:
        read_points(points)
    assert str(points) in str(caught.value) and says in str(caught.value)


@pytest.mark.parametrize("text, says", [
    # were "point 0 (0.0, 0.0, inf) is not finite", without the file (robust2 sweep, 3 December 2026)
    ("0, 0, 1e999\n", "point 0 (0.0, 0.0, inf) is not finite"),
    ("x,y,z\n1,nan,2\n", "point 0 (1.0, nan, 2.0) is not finite"),
    # were "point 0 (1000, 0, 2000) is ... m from the nearest graph node ...", without the file: millimetres
    ("1000,0,2000\n", "point 0 (1000, 0, 2000) is"),
])
def test_a_point_refused_by_the_run_names_its_file(text, says, tmp_path, capsys):
    points = tmp_path / "points.csv"
    points.write_text(text)
    outcome = run_g2s(capsys, "run", points_config(tmp_path, points), CORRIDOR, "-o", tmp_path / "out")
    assert_clean_error(outcome, f"{points}: {says}")


# --- structure.json read back --------------------------------------------------------------


@pytest.mark.parametrize("kind", sorted(BAD_FILES))
def test_bad_structure_file(kind, tmp_path):
    make, says = BAD_FILES[kind]
    path = make(tmp_path, "structure.json") if kind != "deep" else deep_json(tmp_path, "structure.json")
    if kind == "folder":  # a folder is where load_result looks for structure.json
        path, says = path / "structure.json", "no such"
    with pytest.raises(G2SError, match=str(path)) as caught:
        load_result(path)
    assert says in str(caught.value) or kind == "deep" and "nested deeper" in str(caught.value)


# --- the helper itself ------------------------------------------------------------------------


def test_size_cap_is_checked_before_reading(tmp_path):
    big = tmp_path / "big.yaml"
    with big.open("wb") as handle:  # a sparse file: large, but costs no disk
        handle.truncate(MAX_TEXT_BYTES + 1)
    with pytest.raises(G2SError, match="too large"):
        read_text(big, "config file")


def test_nesting_depth_counts_shared_objects_once_per_level():
    shared: list = []
    for _ in range(50):
        shared = [shared] * 10  # 10**50 paths, 50 objects
    assert nesting_depth(shared, limit=100) == 51
    looped: list = []
    looped.append(looped)
    assert nesting_depth(looped, limit=100) == 101
    assert nesting_depth(json.loads('{"a": [1, {"b": 2}]}'), limit=100) == 3


def test_deeply_nested_set_value_is_refused_in_one_short_line(tmp_path, capsys):
    value = "[" * 3000
    outcome = run_g2s(capsys, "run", "graph_only", CORRIDOR, "-o", tmp_path / "out", "--set", f"agent={value}")
    line = assert_clean_error(outcome, "--set agent:", "nested deeper than 100 levels")
    assert len(line) < 200
    assert tree(tmp_path) == []
