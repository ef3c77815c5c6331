"""Plugin registry: stage detection, duplicates, missing plugins, parameter errors."""

from __future__ import annotations

import types

import pytest
from pydantic import Field

from g2s_core import DISTRIBUTION
from g2s_core.errors import ConfigError, PluginError
from g2s_core.model import Terminals
from g2s_core.plugin import PluginParams, hookimpl
from g2s_core.registry import Registry, plugin_parameters


def make_plugin(name: str, **members) -> types.ModuleType:
    module = types.ModuleType(f"plugin_{name}")
    module.NAME = name
    for key, value in members.items():
        setattr(module, key, value)
    return module


class TopK(PluginParams):
    k: int = Field(5, ge=1, description="how many nodes to keep")


@hookimpl
def select_first(graph, params):
    return Terminals(tuple(sorted(graph)[: params.k]))


def terminal_plugin(name: str = "first_k") -> types.ModuleType:
    return make_plugin(name, Params=TopK, g2s_select_terminals=select_first)


def test_stage_comes_from_the_hook_and_call_reaches_only_that_plugin():
    registry = Registry()
    first = registry.register(terminal_plugin("first_k"), package="pkg-a", entry_point="terminals.first_k")

    @hookimpl
    def select_none(graph):
        return Terminals(())

    registry.register(make_plugin("none", g2s_select_terminals=select_none), package="pkg-b", entry_point="x")
    assert first.stage == "terminals" and first.package == "pkg-a"
    assert [p.name for p in registry.plugins("terminals")] == ["first_k", "none"]
    params = registry.validate_params(first, {"k": 2}, "terminals.params")
    assert registry.call(first, graph={3: 0, 1: 0, 2: 0}, params=params, context=None) == Terminals((1, 2))
    none = registry.get("terminals", "none")
    assert registry.call(none, graph={1: 0}, params=none.params_model(), context=None) == Terminals(())


def test_same_stage_and_name_twice_names_both_packages():
    registry = Registry()
    registry.register(terminal_plugin(), package="pkg-a", entry_point="one")
    with pytest.raises(PluginError) as caught:
        registry.register(terminal_plugin(), package="pkg-b", entry_point="two")
    assert "'pkg-a'" in str(caught.value) and "'pkg-b'" in str(caught.value)
    assert "TerminalSelector 'first_k'" in str(caught.value)


def test_same_name_in_different_stages_is_fine():
    @hookimpl
    def analyze(structure):
        return {}

    registry = Registry()
    registry.register(terminal_plugin("betweenness"), package="p", entry_point="a")
    registry.register(make_plugin("betweenness", g2s_analyze=analyze), package="p", entry_point="b")
    assert {p.stage for p in registry.plugins()} == {"terminals", "analyzers"}


def test_a_plugin_implements_exactly_one_stage():
    @hookimpl
    def analyze(structure):
        return {}

    registry = Registry()
    with pytest.raises(PluginError, match="exactly one stage hook, found g2s_analyze, g2s_select_terminals"):
        registry.register(make_plugin("both", g2s_select_terminals=select_first, g2s_analyze=analyze), package="p", entry_point="e")
    with pytest.raises(PluginError, match="found none"):
        registry.register(make_plugin("neither"), package="p", entry_point="e")


def test_unknown_hook_and_missing_name_are_errors():
    @hookimpl
    def g2s_no_such_stage():
        return None

    registry = Registry()
    with pytest.raises(PluginError, match="g2s_no_such_stage"):
        registry.register(make_plugin("odd", g2s_no_such_stage=g2s_no_such_stage), package="p", entry_point="e")
    nameless = types.ModuleType("nameless")
    nameless.g2s_select_terminals = select_first
    with pytest.raises(PluginError, match="no NAME"):
        Registry().register(nameless, package="p", entry_point="e")


def test_missing_plugin_names_the_key_and_lists_installed():
    registry = Registry()
    registry.register(terminal_plugin("leaves"), package="p", entry_point="e")
    with pytest.raises(ConfigError) as caught:
        registry.get("terminals", "entry_exit", key="terminals.plugin")
    assert str(caught.value) == "terminals.plugin: TerminalSelector plugin 'entry_exit' is not installed (installed: leaves)"


@pytest.mark.parametrize(
    "params, message",
    [
        ({"k": "ten"}, "terminals.params.k: expected an integer >= 1, got 'ten'"),
        ({"k": 0}, "terminals.params.k: expected an integer >= 1, got 0"),
        ({"kk": 3}, "terminals.params.kk: unknown key (expected one of: k)"),
    ],
)
def test_parameter_errors_are_one_line(params, message):
    registry = Registry()
    info = registry.register(terminal_plugin(), package="p", entry_point="e")
    with pytest.raises(ConfigError) as caught:
        registry.validate_params(info, params, "terminals.params")
    assert str(caught.value) == message


def test_parameter_help_comes_from_the_declaration():
    info = Registry().register(terminal_plugin(), package="p", entry_point="e")
    assert list(plugin_parameters(info)) == [("k", "an integer >= 1", "5", "how many nodes to keep")]


def test_builtin_plugins_register_through_entry_points():
    registry = Registry.from_entry_points()
    builtin = {(p.stage, p.name) for p in registry.plugins() if p.package == DISTRIBUTION}
    assert ("graph", "navmesh") in builtin
    assert all(p.entry_point == f"{p.stage}.{p.name}" for p in registry.plugins() if p.package == DISTRIBUTION)


def test_every_builtin_parameter_is_documented():
    registry = Registry.from_entry_points()
    builtin = [p for p in registry.plugins() if p.package == DISTRIBUTION]
    assert {("graph", "sampling"), ("simplify", "mesh_los")} <= {(p.stage, p.name) for p in builtin}
    for info in builtin:
        for name, field in info.params_model.model_fields.items():
            assert field.description, f"{info.stage}.{info.name}: {name}"
