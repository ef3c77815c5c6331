"""Inputs robust7 (4 December 2026) found told in PyYAML's, Recast's or no words: a YAML key of more than 1,024
characters (named in PyYAML's words), numbers that YAML 1.1 and 1.2 read differently (``017``, ``1:30``) or that PyYAML alone reads as text
(``+.5``), a ``g2s batch`` argument that is a link to itself, an ASCII PLY of more rows than its header declares
(read silently as the rows declared), and a mesh whose faces use two vertices in all (blamed on the graph builder)."""

from __future__ import annotations

import re

import pytest
import trimesh

from g2s_core.config import load_raw_config, parse_assignment
from g2s_core.errors import ConfigError, MeshError
from g2s_core.mesh import load_mesh
from tests.reliability.checks import assert_clean_error, run_g2s, tree


@pytest.mark.parametrize("text, line", [
    ("k" * 1100 + ": 1\n", 2),                      # was "could not find expected ':'"
    ("agent:\n  " + "r" * 1030 + ": 1\n", 3),       # was "mapping values are not allowed here"
    ("agent: {" + "r" * 1030 + ": 1}\n", 2),         # was "expected ',' or '}', but got ':'"
])
def test_a_key_longer_than_1024_characters_is_named_as_such(text, line, tmp_path, capsys):
    config = tmp_path / "long.yaml"
    config.write_text("extends: map_piece\n" + text)
    outcome = run_g2s(capsys, "run", config, "sample:straight_corridor", "-o", tmp_path / "out")
    assert_clean_error(outcome, f"{config}: invalid YAML at line {line}, ", "a key of more than 1,024 characters, YAML's limit on a key")
    assert tree(tmp_path / "out") == []


@pytest.mark.parametrize("value, number", [("+.5", 0.5), ("-.5", -0.5), ("+.5e1", 5.0), (".5", 0.5), ("007", 7), ("1_000", 1000)])
def test_numbers_every_yaml_version_reads_alike_are_numbers(value, number):
    assert parse_assignment(f"agent.radius={value}") == ("agent.radius", number)  # +.5 and -.5 were the texts '+.5', '-.5'


@pytest.mark.parametrize("value, says", [
    ("017", "017 is 15 in YAML 1.1 (octal) and 17 in YAML 1.2; write 17 (or 15) without the leading 0"),  # was 15, silently
    ("1:30", "1:30 is 90 in YAML 1.1 (base 60) and text in YAML 1.2; write 90, or quote it as text"),  # was 90, silently
    ("-1:30.5", "-1:30.5 is -90.5 in YAML 1.1 (base 60) and text in YAML 1.2; write -90.5, or quote it as text"),
])
def test_numbers_yaml_versions_read_differently_are_refused_naming_both_readings(value, says, tmp_path):
    config = tmp_path / "c.yaml"
    config.write_text(f"agent:\n  radius: {value}\n")
    with pytest.raises(ConfigError, match=f"^{re.escape(f'{config}: invalid YAML at line 2, column 11: {says}')}$"):
        load_raw_config(config)
    with pytest.raises(ConfigError, match=re.escape(f"--set agent.radius: the value {value!r} is not valid YAML ({says})")):
        parse_assignment(f"agent.radius={value}")
    assert parse_assignment("agent.radius='017'") == ("agent.radius", "017")  # quoted, a text


def test_a_batch_argument_that_is_a_link_to_itself_says_so(tmp_path, capsys):
    (tmp_path / "self.obj").symlink_to(tmp_path / "self.obj")
    outcome = run_g2s(capsys, "batch", "map_piece", tmp_path / "self.obj", "-o", tmp_path / "out")
    # was "self.obj: no such mesh file, folder or pattern (or sample:NAME)"
    assert_clean_error(outcome, f"{tmp_path / 'self.obj'}: cannot read mesh file (Too many levels of symbolic links)")
    assert tree(tmp_path / "out") == []


def _ascii_ply(declared_faces: int) -> bytes:
    box = trimesh.creation.box([4, 2, 4])
    text = box.export(file_type="ply", encoding="ascii")
    return text.replace(b"element face 12", f"element face {declared_faces}".encode())


def test_an_ascii_ply_of_more_rows_than_its_header_declares_is_refused(tmp_path):
    path = tmp_path / "level.ply"
    path.write_bytes(_ascii_ply(9))  # was read as the 9 faces declared, the 3 after them dropped without a word
    first_extra = path.read_bytes().split(b"end_header")[0].count(b"\n") + 2 + 8 + 9
    with pytest.raises(MeshError, match=f"^{re.escape(f'{path}: ASCII PLY has 3 rows more than its header declares (from line {first_extra})')}$"):
        load_mesh(path)
    path.write_bytes(_ascii_ply(12) + b"\n\n")  # blank lines after the rows are no rows
    assert len(load_mesh(path)[0].faces) == 12


def test_a_mesh_whose_faces_use_two_vertices_is_said_not_blamed_on_the_graph_builder(tmp_path, capsys):
    level = tmp_path / "level.obj"
    level.write_text("v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nf 1 -2 3\n")  # -2 counts back to vertex 3: the face (1, 3, 3)
    outcome = run_g2s(capsys, "run", "map_piece", level, "-o", tmp_path / "out")
    # was "GraphBuilder plugin 'navmesh' (package 'graph2structure') failed: raised ValueError: Recast: the mesh
    # needs at least 3 vertices and 1 face", which sent the user to the plugin's authors
    assert_clean_error(outcome, f"{level}: the faces use 2 vertices in all: every face has zero area; export it again")


def test_a_plugin_of_a_kind_whose_name_starts_with_a_vowel_is_an_one():
    import types

    from g2s_core.errors import PluginError
    from g2s_core.plugin import hookimpl
    from g2s_core.registry import Registry

    @hookimpl
    def g2s_analyze(structure, params, context):
        return {}

    plugin = types.ModuleType("flat")
    plugin.NAME, plugin.g2s_analyze = "flat", g2s_analyze
    with pytest.raises(PluginError, match=r": the plugin is an Analyzer, whose entry points are named 'analyzers.<name>'$"):
        Registry().register(plugin, package="p", entry_point="terminals.flat")  # was "the plugin is a Analyzer"
