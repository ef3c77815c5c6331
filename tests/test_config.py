"""Config reading: extends, presets, and one-line errors for every bad case."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from g2s_core.config import PRESETS_DIR, RunConfig, load_config, load_raw_config
from g2s_core.errors import ConfigError


def write(tmp_path: Path, name: str, text: str) -> Path:
    path = tmp_path / name
    path.write_text(textwrap.dedent(text))
    return path


def error_of(path: Path) -> str:
    with pytest.raises(ConfigError) as caught:
        load_config(path)
    message = str(caught.value)
    assert "\n" not in message
    return message


def test_defaults_and_stage_order(tmp_path):
    config = load_config(write(tmp_path, "c.yaml", "graph: {plugin: navmesh}\nstop_after: graph\n"))
    assert config.agent.radius == 0.5 and config.mesh.up_axis == "y"
    assert config.stages_to_run() == ("graph",)
    assert RunConfig().stages_to_run()[-2:] == ("analyzers", "evaluators")


def test_extends_merges_mappings_and_replaces_lists(tmp_path):
    write(tmp_path, "parent.yaml", """
        agent: {radius: 0.3, height: 1.8}
        graph: {plugin: navmesh, params: {cell_size: 0.2}}
        analyzers: [{plugin: degree}, {plugin: depth}]
    """)
    child = write(tmp_path, "child.yaml", """
        extends: parent.yaml
        agent: {radius: 0.4}
        graph: {params: {cell_height: 0.1}}
        analyzers: [{plugin: betweenness}]
    """)
    config = load_config(child)
    assert config.agent.radius == 0.4 and config.agent.height == 1.8
    assert config.graph.plugin == "navmesh"
    assert config.graph.params == {"cell_size": 0.2, "cell_height": 0.1}
    assert [a.plugin for a in config.analyzers] == ["betweenness"]


def test_a_section_naming_another_plugin_does_not_inherit_its_parameters(tmp_path):
    write(tmp_path, "parent.yaml", """
        terminals: {plugin: coverage, params: {traffic_weight: 0.1, radius: 5.0}}
        simplify: {plugin: surface_los, params: {max_surface_gap: null}}
    """)
    child = write(tmp_path, "child.yaml", """
        extends: parent.yaml
        terminals: {plugin: metric, params: {top_k: 3}}
        simplify: {params: {whole_chain_normals: false}}
    """)
    config = load_config(child)
    assert (config.terminals.plugin, config.terminals.params) == ("metric", {"top_k": 3})
    # the same plugin, named or not, merges key by key
    assert config.simplify.params == {"max_surface_gap": None, "whole_chain_normals": False}
    same = write(tmp_path, "same.yaml", "extends: parent.yaml\nterminals: {plugin: coverage, params: {radius: 4.0}}\n")
    assert load_config(same).terminals.params == {"traffic_weight": 0.1, "radius": 4.0}


def test_extends_finds_presets_by_name(tmp_path):
    config = load_config(write(tmp_path, "c.yaml", "extends: map_analysis\nagent: {radius: 0.6}\n"))
    assert config.terminals.plugin == "coverage" and config.agent.radius == 0.6
    assert (PRESETS_DIR / "map_analysis.yaml").is_file()


def test_every_preset_validates():
    presets = sorted(PRESETS_DIR.glob("*.yaml"))
    assert len(presets) >= 5
    for preset in presets:
        load_config(preset)


def test_extends_cycle_is_an_error(tmp_path):
    write(tmp_path, "a.yaml", "extends: b.yaml\n")
    b = write(tmp_path, "b.yaml", "extends: a.yaml\n")
    assert "extends: cycle" in error_of(b)
    assert "extends: cycle myself.yaml -> myself.yaml" in error_of(write(tmp_path, "myself.yaml", "extends: myself\n"))


def test_errors_in_extended_configs_name_them_by_the_users_relative_paths(tmp_path, monkeypatch):
    # the files a config extends were named by their absolute paths (the cycle, the bad value, the missing preset)
    monkeypatch.chdir(tmp_path)
    (tmp_path / "sub").mkdir()
    write(tmp_path, "sub/a.yaml", "extends: b.yaml\n")
    write(tmp_path, "sub/b.yaml", "extends: a.yaml\n")
    assert error_of(Path("sub/a.yaml")) == "sub/a.yaml: extends: cycle a.yaml -> b.yaml -> a.yaml"
    write(tmp_path, "sub/c.yaml", "extends: d\n")
    write(tmp_path, "sub/d.yaml", "extends: nope\n")
    assert error_of(Path("sub/c.yaml")).startswith("sub/d.yaml: extends: no config file or preset named 'nope'")
    write(tmp_path, "sub/d.yaml", "agent: [\n")
    assert error_of(Path("sub/c.yaml")).startswith("sub/d.yaml: invalid YAML at line 2")


@pytest.mark.parametrize("extends", ["map_analysis", "map_analysis.yaml"])
def test_a_file_named_after_the_preset_it_extends_extends_the_preset(tmp_path, extends):
    mine = write(tmp_path, "map_analysis.yaml", f"extends: {extends}\nagent: {{radius: 0.3}}\n")
    config = load_config(mine)
    assert config.agent.radius == 0.3
    assert config.model_dump()["terminals"] == load_config(PRESETS_DIR / "map_analysis.yaml").model_dump()["terminals"]


@pytest.mark.parametrize(
    "text, expected",
    [
        ("agent: {radius: ten}\n", "c.yaml: agent.radius: expected a number > 0, got 'ten'"),
        ("agent: {max_slope: 95}\n", "c.yaml: agent.max_slope: expected a number > 0 and < 90, got 95"),
        ("agnet: {radius: 1}\n", "c.yaml: agnet: unknown key (expected one of: mesh, agent,"),
        ("graph: {plugin: navmesh, parms: {}}\n", "c.yaml: graph.parms: unknown key (expected one of: plugin, params)"),
        ("graph: {params: {}}\n", "c.yaml: graph.plugin: required key is missing"),
        ("mesh: {up_axis: w}\n", "c.yaml: mesh.up_axis: expected one of 'y', 'z', got 'w'"),
        ("mesh: {scale: 0}\n", "c.yaml: mesh.scale: expected a number > 0, got 0"),
        ("mesh: {clean: maybe}\n", "c.yaml: mesh.clean: expected true or false, got 'maybe'"),
        ("agent: 3\n", "c.yaml: agent: expected a mapping, got 3"),
        ("analyzers: {plugin: degree}\n", "c.yaml: analyzers: expected a list of mappings, got a mapping"),
        ("stop_after: never\n", "c.yaml: stop_after: expected one of 'graph',"),
        ("- a\n- b\n", "c.yaml: expected a mapping of settings at the top level, got a list of 2 items"),
        ("agent: {radius: [1\n", "c.yaml: invalid YAML at line"),
        ("extends: no_such_preset\n", "c.yaml: extends: no config file or preset named 'no_such_preset'"),
        ("agent: {radius: 0.3}\nagent: {height: 1.5}\n",
         "c.yaml: invalid YAML at line 2, column 1: duplicate key 'agent' (first at line 1)"),
        ("agent: {radius: 0.3, radius: 9}\n", "c.yaml: invalid YAML at line 1, column 22: duplicate key 'radius' (first at"),
        ("agent: {radius: true}\n", "c.yaml: agent.radius: expected a number > 0, got true"),
        ("agent: {height: '1.5'}\n", "c.yaml: agent.height: expected a number > 0, got '1.5'"),
        ("mesh: {clean: 1}\n", "c.yaml: mesh.clean: expected true or false, got 1"),
    ],
)
def test_bad_configs_give_one_line_naming_the_key(tmp_path, text, expected):
    assert error_of(write(tmp_path, "c.yaml", text)).startswith(f"{tmp_path}/{expected}")


def test_merged_keys_may_be_overridden_but_not_written_twice(tmp_path):
    base = "corner: &corner {radius: 0.3, height: 1.5}\n"
    assert load_raw_config(write(tmp_path, "m.yaml", base + "agent: {<<: *corner, radius: 0.4}\n"))["agent"] == \
        {"radius": 0.4, "height": 1.5}
    assert "duplicate key 'radius'" in error_of(write(tmp_path, "d.yaml", base + "agent: {<<: *corner, radius: 0.4, radius: 1}\n"))


def test_missing_config_file(tmp_path):
    assert error_of(tmp_path / "absent.yaml").endswith("absent.yaml: no such config file")


def test_empty_config_is_all_defaults(tmp_path):
    assert load_raw_config(write(tmp_path, "empty.yaml", "")) == {}


def test_every_preset_states_its_purpose_in_one_line():
    from g2s_core.config import presets

    purposes = presets()
    assert set(purposes) == {p.stem for p in PRESETS_DIR.glob("*.yaml")}
    for name, purpose in purposes.items():
        assert purpose.endswith(".") and len(purpose) <= 90, (name, purpose)


def test_set_key_merges_mappings_indexes_lists_and_leaves_the_input_alone():
    from g2s_core.config import parse_assignment, set_key

    raw = {"agent": {"radius": 0.5, "height": 2.0}, "analyzers": [{"plugin": "degree"}]}
    changed = set_key(raw, *parse_assignment("agent.radius=0.25"), source="--set")
    changed = set_key(changed, "analyzers.0.params", {"normalized": False}, source="--set")
    changed = set_key(changed, *parse_assignment("outputs.formats=[json, glb]"), source="--set")
    assert changed == {"agent": {"radius": 0.25, "height": 2.0}, "outputs": {"formats": ["json", "glb"]},
                       "analyzers": [{"plugin": "degree", "params": {"normalized": False}}]}
    assert raw == {"agent": {"radius": 0.5, "height": 2.0}, "analyzers": [{"plugin": "degree"}]}
    assert parse_assignment("graph.plugin=navmesh") == ("graph.plugin", "navmesh")
    assert parse_assignment("stop_after=") == ("stop_after", None)


@pytest.mark.parametrize(("text", "value"), [
    ("1e-3", 0.001), ("2E3", 2000.0), ("-1.5e+2", -150.0), (".5e1", 5.0), ("1_0e1", 100.0),  # YAML 1.2 floats
    ("1e", "1e"), ("e3", "e3"), ("1e3x", "1e3x"), ("12", 12), ("0.25", 0.25),  # not exponent floats: as before
])
def test_numbers_with_an_exponent_are_numbers_in_configs_and_set(text, value, tmp_path):
    from g2s_core.config import parse_assignment, resolve_config

    assert parse_assignment(f"terminals.params.radius={text}") == ("terminals.params.radius", value)
    config_file = tmp_path / "c.yaml"
    config_file.write_text(f"extends: map_analysis\nmesh: {{scale: 1e-2}}\nterminals: {{params: {{radius: {text}}}}}\n")
    if isinstance(value, float) and value > 0:
        config, _ = resolve_config(str(config_file), {})
        assert config.mesh.scale == 0.01 and config.terminals.params["radius"] == value


def test_set_replaces_a_stage_section_naming_another_plugin_as_extends_does():
    from g2s_core.config import resolve_config

    config, _ = resolve_config("map_analysis", {"terminals": {"plugin": "leaves"}})
    assert config.terminals.plugin == "leaves" and config.terminals.params == {}
    same, _ = resolve_config("map_analysis", {"terminals": {"params": {"radius": 4.0}}})
    assert same.terminals.plugin == "coverage" and same.terminals.params["radius"] == 4.0
    assert same.terminals.params["traffic_weight"] == 0.1


@pytest.mark.parametrize("text, expected", [
    # robust6's configs that fight back (4 December 2026); what each said before
    ("agent: {1: 1}\n", "agent: expected names as keys, got 1"),  # "agent.1: expected a mapping, got 1"
    ("agent: {null: 1}\n", "agent: expected names as keys, got null"),  # "agent.None: keys should be strings, got null"
    ("graph: {plugin: navmesh, params: {null: 2}}\n",  # "graph.params.None: input should be a valid string, got null"
     "graph.params: expected names as keys, got null"),
    ("agent: {radius: " + "x" * 1_000_000 + "}\n",  # the megabyte, on one line
     "agent.radius: expected a number > 0, got '" + "x" * 60 + "...' (1,000,000 characters)"),
    ("agent: {radius: 1" + "0" * 400 + "}\n", "agent.radius: expected a number > 0, got an integer of 401 digits"),  # all 401
    ("agent: {radius: 1" + "0" * 5000 + "}\n",  # "(Exceeds the limit (4300 digits) for integer string conversion: ...
     "unreadable value (an integer of more than 4300 digits)"),  # ... use sys.set_int_max_str_digits() to increase the limit)"
    ("agent: {radius: !!binary eQ==}\n", "agent.radius: expected a number > 0, got binary data of 1 byte"),  # "got b'y'"
    ("outputs: {formats: !!set {json: null}}\n", "outputs.formats: expected a list of strings, got a set of 1 item"),  # {'json'}
    ('"a\\nb": 1\n', "'a\\nb': unknown key (expected one of: mesh, agent, graph, terminals, steiner, loops, roots, simplify, "
                    "analyzers, evaluators, stop_after, outputs)"),  # the newline itself: two lines
    ("agent: {radius: 0.3}\n\x07\n", "line 2: character U+0007 is not allowed in YAML"),  # "invalid YAML: not valid YAML"
    ("agent: {radius: 0.3}\n---\nagent: {radius: 0.4}\n",  # "... column 1: but found another document"
     "invalid YAML at line 2, column 1: expected a single document in the stream but found another document"),
])
def test_configs_that_fight_back_are_said_in_g2s_words_on_a_short_line(tmp_path, text, expected):
    message = error_of(write(tmp_path, "c.yaml", text))
    assert message == f"{tmp_path}/c.yaml: {expected}"


def test_a_chain_of_a_thousand_extends_is_read(tmp_path):
    # was "c487.yaml: nested deeper than 100 levels of mappings and lists": Python's stack ran out inside the YAML reader
    for index in range(1000):
        (tmp_path / f"c{index}.yaml").write_text(f"extends: c{index + 1}\n")
    (tmp_path / "c1000.yaml").write_text("extends: map_piece\nagent: {radius: 0.3}\n")
    config = load_config(tmp_path / "c0.yaml")
    assert config.agent.radius == 0.3 and config.terminals.plugin == "entry_exit"
    (tmp_path / "c1000.yaml").write_text("extends: c500\n")
    assert error_of(tmp_path / "c0.yaml").endswith("c1000.yaml -> c500.yaml")  # a cycle is still one
