"""Plugin registry: stage detection, duplicates, missing plugins, parameter errors."""

from __future__ import annotations

import types

import pytest
from pydantic import Field

from g2s_core import DISTRIBUTION
from g2s_core.errors import ConfigError, PluginError, PluginFailure
from g2s_core.model import Terminals
from g2s_core.plugin import PluginParams, hookimpl
from g2s_core.registry import Registry
from g2s_plugins.plugin_list import plugin_parameters


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


def test_begin_ahead_reaches_only_that_plugin_and_its_failures_name_it():
    begun = []

    @hookimpl
    def begin(params, context):
        begun.append(context)

    @hookimpl
    def begin_broken(context):
        raise KeyError("settings")

    registry = Registry()
    eager = registry.register(make_plugin("eager", g2s_select_terminals=select_first, g2s_begin_ahead=begin),
                              package="p", entry_point="a")
    plain = registry.register(terminal_plugin("plain"), package="p", entry_point="b")
    broken = registry.register(make_plugin("broken", g2s_select_terminals=select_first, g2s_begin_ahead=begin_broken),
                               package="pkg-b", entry_point="c")
    assert eager.stage == "terminals"  # g2s_begin_ahead is no stage hook
    registry.begin_ahead(plain, params=None, context="run")  # no g2s_begin_ahead: nothing asked
    registry.begin_ahead(eager, params=None, context="run")
    assert begun == ["run"]
    with pytest.raises(PluginFailure, match=r"^TerminalSelector plugin 'broken' \(package 'pkg-b'\) failed: "
                                            r"raised KeyError: 'settings'$"):
        registry.begin_ahead(broken, params=None, context="run")
    with pytest.raises(PluginError, match="found none"):  # alone it makes no plugin
        registry.register(make_plugin("ahead", g2s_begin_ahead=begin), package="p", entry_point="d")


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


def test_a_check_of_the_whole_mapping_is_reported_without_the_mapping():
    from g2s_plugins.terminals import metric

    registry = Registry()
    info = registry.register(metric, package="p", entry_point="e")
    with pytest.raises(ConfigError) as caught:
        registry.validate_params(info, {"top_k": 2, "min_degree": 3, "max_degree": 2}, "terminals.params")
    assert str(caught.value) == "terminals.params: min_degree (3) is larger than max_degree (2); no node can pass"


def test_parameter_help_comes_from_the_declaration():
    info = Registry().register(terminal_plugin(), package="p", entry_point="e")
    assert list(plugin_parameters(info)) == [("k", "an integer >= 1", "5", "how many nodes to keep")]


def test_builtin_plugins_register_through_entry_points():
    registry = Registry.from_entry_points()
    builtin = {(p.stage, p.name) for p in registry.plugins() if p.package == DISTRIBUTION}
    assert ("graph", "navmesh") in builtin
    for info in registry.plugins():
        if info.package == DISTRIBUTION:  # the sample levels come as one list, from entry point levels.samples
            assert info.entry_point == (f"{info.stage}.{info.name}" if info.stage != "levels" else "levels.samples")


def test_every_builtin_parameter_is_documented():
    registry = Registry.from_entry_points()
    builtin = [p for p in registry.plugins() if p.package == DISTRIBUTION]
    assert {("graph", "sampling"), ("simplify", "mesh_los")} <= {(p.stage, p.name) for p in builtin}
    for info in builtin:
        for name, field in info.params_model.model_fields.items():
            assert field.description, f"{info.stage}.{info.name}: {name}"


# --- a plugin's own failures: exceptions and wrong results name the plugin and its package ---


def _chain_tree():
    import networkx as nx

    tree = nx.path_graph(3)
    for node in tree:
        tree.nodes[node]["pos"] = (float(node), 0.0, 0.0)
    return tree


def test_a_root_selector_that_misses_nodes_fails_as_itself():
    @hookimpl
    def scores(tree):
        return {0: 1.0}

    registry = Registry()
    info = registry.register(make_plugin("partial", g2s_root_scores=scores), package="pkg-r", entry_point="roots.partial")
    with pytest.raises(PluginFailure) as caught:
        registry.call(info, tree=_chain_tree(), params=info.params_model(), context=None)
    assert str(caught.value) == "RootSelector plugin 'partial' (package 'pkg-r') failed: returned no value for nodes [1, 2]"


def test_a_loop_adder_must_keep_the_forest_and_add_only_graph_edges():
    import networkx as nx

    graph = nx.cycle_graph(4)
    forest = nx.path_graph(4)

    @hookimpl
    def drop(graph, forest):
        return nx.Graph([(0, 1)])

    @hookimpl
    def invent(graph, forest):
        return nx.Graph([*forest.edges, (0, 2)])

    @hookimpl
    def close(graph, forest):
        return nx.Graph([*forest.edges, (3, 0)])

    registry = Registry()
    infos = [registry.register(make_plugin(name, g2s_add_loops=hook), package="pkg-l", entry_point=name)
             for name, hook in (("drop", drop), ("invent", invent), ("close", close))]
    problems = []
    for info in infos[:2]:
        with pytest.raises(PluginFailure) as caught:
            registry.call(info, graph=graph, forest=forest, params=info.params_model(), context=None)
        problems.append(str(caught.value))
    assert problems == [
        "LoopAdder plugin 'drop' (package 'pkg-l') failed: returned a graph that misses nodes or edges of the forest: [2, 3, (1, 2)]",
        "LoopAdder plugin 'invent' (package 'pkg-l') failed: returned nodes or edges not in the graph: [(0, 2)]",
    ]
    closed = registry.call(infos[2], graph=graph, forest=forest, params=infos[2].params_model(), context=None)
    assert nx.cycle_basis(closed)


def test_a_steiner_solver_must_return_a_tree():
    import networkx as nx

    graph = nx.Graph([(0, 1), (1, 2), (2, 3), (3, 0), (2, 4)])

    @hookimpl
    def cycle(graph, terminals):  # four nodes, four edges
        return nx.Graph([(0, 1), (1, 2), (2, 3), (3, 0)])

    @hookimpl
    def apart(graph, terminals):  # five nodes, four edges, yet two components: a cycle and 4 alone
        return nx.union(nx.cycle_graph(4), nx.empty_graph([4]))

    @hookimpl
    def path(graph, terminals):
        return nx.Graph([(0, 1), (1, 2), (2, 4)])

    registry = Registry()
    infos = [registry.register(make_plugin(name, g2s_steiner_tree=hook), package="pkg-s", entry_point=name)
             for name, hook in (("cycle", cycle), ("apart", apart), ("path", path))]
    for info in infos[:2]:
        with pytest.raises(PluginFailure, match="returned a graph that is not a tree"):
            registry.call(info, graph=graph, terminals=[0, 3], params=info.params_model(), context=None)
    assert sorted(registry.call(infos[2], graph=graph, terminals=[0, 4], params=infos[2].params_model(),
                                context=None).edges) == [(0, 1), (1, 2), (2, 4)]


def test_a_predicate_that_returns_none_or_raises_fails_as_itself():
    @hookimpl
    def predicate():
        return lambda tree, a, b, c: None if c == 2 else tree.nodes[b]["missing"]

    registry = Registry()
    info = registry.register(make_plugin("sloppy", g2s_simplify_predicate=predicate), package="pkg-p", entry_point="e")
    checked = registry.call(info, params=info.params_model(), context=None, forest=None, simplified=None)
    with pytest.raises(PluginFailure, match=r"^SimplifyPredicate plugin 'sloppy' \(package 'pkg-p'\) failed: "
                                            r"its function returned NoneType, not a bool$"):
        checked(_chain_tree(), 0, 1, 2)
    with pytest.raises(PluginFailure, match=r"failed: its function raised KeyError: 'missing'$"):
        checked(_chain_tree(), 0, 1, 1)


@pytest.mark.parametrize("measures, problem", [
    ({"rho": float("nan")}, "returned nan for measure rho, not a finite number"),
    ({"area within 3m": 0.5}, "returned the measure name 'area within 3m', not letters, digits and _ starting with a letter"),
    ({"share": "high"}, "returned 'high' for measure share, not a number"),
    ([0.5], "returned list, not a mapping of measure -> number"),
])
def test_an_evaluator_gives_finite_numbers_by_name(measures, problem):
    @hookimpl
    def evaluate(result):
        return measures

    registry = Registry()
    info = registry.register(make_plugin("loose", g2s_evaluate=evaluate), package="pkg-e", entry_point="e")
    with pytest.raises(PluginFailure) as caught:
        registry.call(info, result=None, params=info.params_model(), context=None)
    assert str(caught.value) == f"Evaluator plugin 'loose' (package 'pkg-e') failed: {problem}"
    measures = {"share": 1, "rho": -0.5}
    assert registry.call(info, result=None, params=info.params_model(), context=None) == measures


def test_an_executor_yields_rows_and_its_failures_name_it():
    rows = [{"config": "c", "level": "a"}, {"config": "c", "level": "b"}]
    closed = []

    @hookimpl
    def execute(function, items):
        try:
            for item in items:
                yield function(item)
            raise OSError("the cluster went away")
        finally:
            closed.append(True)

    registry = Registry()
    info = registry.register(make_plugin("flaky", g2s_execute=execute), package="pkg-x", entry_point="e")
    results = registry.call(info, function=dict, items=rows, params=info.params_model(), lost=lost_row)
    assert [next(results), next(results)] == rows
    with pytest.raises(PluginFailure, match=r"^Executor plugin 'flaky' \(package 'pkg-x'\) failed: "
                                            r"its iterator raised OSError: the cluster went away$"):
        next(results)
    results = registry.call(info, function=dict, items=rows, params=info.params_model(), lost=lost_row)
    next(results)
    results.close()  # as a batch does on Ctrl-C: the executor's own iterator is closed too
    assert closed == [True, True]
    lists = registry.call(info, function=lambda item: [item], items=rows, params=info.params_model(), lost=lost_row)
    with pytest.raises(PluginFailure, match="failed: its iterator gave list, not a summary row"):
        next(lists)

    @hookimpl
    def collect(function, items):
        return [function(item) for item in items]

    eager = registry.register(make_plugin("eager", g2s_execute=collect), package="pkg-x", entry_point="eager")
    with pytest.raises(PluginFailure, match="failed: returned list, not an iterator"):
        registry.call(eager, function=dict, items=rows, params=eager.params_model(), lost=lost_row)


def lost_row(row: dict, reason: str) -> dict:
    """A batch's row of an item whose process died (the executor hook's ``lost``)."""
    return {**row, "status": "failed", "error": reason}


def test_bad_input_found_by_a_plugin_stays_the_users_error():
    @hookimpl
    def select(graph):
        raise ConfigError("points.txt: line 3: expected 3 numbers")

    registry = Registry()
    info = registry.register(make_plugin("strict", g2s_select_terminals=select), package="p", entry_point="e")
    with pytest.raises(ConfigError, match="points.txt"):
        registry.call(info, graph={}, params=info.params_model(), context=None)


def test_a_writer_declares_its_files_and_writes_only_those(tmp_path):
    @hookimpl
    def write(result, folder):
        return [folder / "other.txt"]

    registry = Registry()
    with pytest.raises(PluginError, match="OutputWriter plugins declare FILES, this one does not"):
        registry.register(make_plugin("nofiles", g2s_write_output=write), package="p", entry_point="e")
    info = registry.register(make_plugin("txt", FILES=("notes.txt",), g2s_write_output=write), package="pkg-w", entry_point="e")
    with pytest.raises(PluginFailure, match=r"OutputWriter plugin 'txt' \(package 'pkg-w'\) failed: returned paths it "
                                            r"does not declare in FILES \('notes.txt',\)"):
        registry.call(info, result=None, folder=tmp_path)


def test_a_plugin_that_fails_to_load_is_kept_aside(monkeypatch):
    import importlib.metadata

    good = importlib.metadata.EntryPoint("terminals.first_k", "tests.test_registry:FIRST_K", "g2s")
    bad = importlib.metadata.EntryPoint("terminals.gone", "no_such_package_g2s.plugin", "g2s")
    monkeypatch.setattr(importlib.metadata, "entry_points", lambda group: [good, bad])
    registry = Registry.from_entry_points()
    assert [p.name for p in registry.plugins()] == ["first_k"]
    assert [(b.entry_point, b.target) for b in registry.broken()] == [("terminals.gone", "no_such_package_g2s.plugin")]
    assert "No module named 'no_such_package_g2s'" in registry.broken()[0].reason
    with pytest.raises(PluginFailure, match=r"^TerminalSelector plugin 'gone' \(package '\?'\) failed to load: "):
        registry.get("terminals", "gone")
    with pytest.raises(ConfigError, match=r"failed to load: terminals.gone of package '\?', see `g2s plugins`"):
        registry.get("terminals", "other")


FIRST_K = terminal_plugin("first_k")


def test_two_installed_plugins_of_one_name_stop_the_runs_that_ask_for_it(monkeypatch):
    import importlib.metadata

    def entry_point(package, plugin):
        return types.SimpleNamespace(name="terminals.first_k", value=f"{package.replace('-', '_')}.first_k",
                                     dist=types.SimpleNamespace(name=package), load=lambda: plugin)

    found = [entry_point("pkg-b", OTHER_FIRST_K), entry_point("pkg-a", FIRST_K)]
    monkeypatch.setattr(importlib.metadata, "entry_points", lambda group: found)
    registry = Registry.from_entry_points()
    assert [(b.package, b.entry_point) for b in registry.broken()] == [("pkg-b", "terminals.first_k")]
    with pytest.raises(PluginFailure, match=r"two plugins provide TerminalSelector 'first_k': package 'pkg-a'"):
        registry.get("terminals", "first_k")


OTHER_FIRST_K = terminal_plugin("first_k")


def test_a_distribution_without_a_name_does_not_stop_the_listing(monkeypatch):
    # importlib.metadata gives a distribution whose METADATA is missing or half written (a pip install under way)
    # the name None: sorting None beside a package's name was a TypeError, an internal error of every command
    import importlib.metadata

    def entry_point(package, name, plugin):
        return types.SimpleNamespace(name=f"terminals.{name}", value=f"x.{name}", dist=types.SimpleNamespace(name=package),
                                     load=lambda: plugin)

    found = [entry_point("pkg-a", "first_k", FIRST_K), entry_point(None, "other", OTHER_K)]
    monkeypatch.setattr(importlib.metadata, "entry_points", lambda group: found)
    registry = Registry.from_entry_points()
    assert [(p.name, p.package) for p in registry.plugins()] == [("first_k", "pkg-a"), ("other", "?")]


OTHER_K = terminal_plugin("other")


def test_entry_points_load_when_their_stage_is_first_asked_for(monkeypatch):
    """``<stage>.<name>`` entry points load with their stage, the others with the first stage asked for;
    a broken one is listed (with every other) once all are asked for, in the order of the entry points."""
    import importlib.metadata

    loaded = []

    def entry_point(name, plugin):
        def load():
            loaded.append(name)
            if plugin is None:
                raise ImportError(f"{name} is broken")
            return plugin

        return types.SimpleNamespace(name=name, value=f"pkg.{name}", dist=types.SimpleNamespace(name="pkg"), load=load)

    @hookimpl
    def depth(structure):
        return {node: 0.0 for node in structure}

    found = [entry_point("terminals.first_k", FIRST_K), entry_point("analyzers.depth", make_plugin("depth", g2s_analyze=depth)),
             entry_point("anything", make_plugin("any_k", Params=TopK, g2s_select_terminals=select_first)),
             entry_point("analyzers.gone", None), entry_point("terminals.gone", None)]
    monkeypatch.setattr(importlib.metadata, "entry_points", lambda group: found)
    registry = Registry.from_entry_points()
    assert loaded == []
    assert [p.name for p in registry.plugins("terminals")] == ["any_k", "first_k"]
    assert sorted(loaded) == ["anything", "terminals.first_k", "terminals.gone"]
    assert registry.get("analyzers", "depth").stage == "analyzers"
    assert [b.entry_point for b in registry.broken()] == ["analyzers.gone", "terminals.gone"]
    assert sorted(loaded) == ["analyzers.depth", "analyzers.gone", "anything", "terminals.first_k", "terminals.gone"]


def test_an_entry_point_named_for_another_stage_is_broken():
    """Loaded only with the stage its name gives, it would be missing from a registry that loaded the other one."""
    registry = Registry()
    with pytest.raises(PluginError, match=r"entry point 'analyzers.first_k' of package 'p': the plugin is a "
                                          r"TerminalSelector, whose entry points are named 'terminals.<name>'"):
        registry.register(terminal_plugin(), package="p", entry_point="analyzers.first_k")
    assert registry.plugins() == []
