"""Values no setting accepts: NaN and infinities in any plugin parameter or config number, values of another
type than a plugin parameter's (a bool or a quoted number for a number), and out-of-range command-line options."""

from __future__ import annotations

from typing import Literal, get_args, get_origin

import pytest
from pydantic import BaseModel, Strict

from g2s_core.config import AgentConfig, MeshConfig, parse_config
from g2s_core.errors import ConfigError
from g2s_core.messages import show
from g2s_core.registry import installed
from tests.reliability.checks import CORRIDOR, assert_clean_error, run_g2s, run_g2s_process, tree


def _takes_floats(annotation) -> bool:
    return annotation is float or any(_takes_floats(a) for a in get_args(annotation))


def _float_fields(model: type[BaseModel]) -> list[str]:
    return [name for name, info in model.model_fields.items() if _takes_floats(info.annotation)]


def _plugin_float_params() -> list[tuple[str, str, str]]:
    registry = installed()
    return [(info.stage, info.name, field) for info in registry.plugins() for field in _float_fields(info.params_model)]


def _value_for(model: type[BaseModel], field: str, number: float):
    """``number`` shaped as ``field`` takes it: a scalar, or inside a point, a list of points or a list of numbers."""
    text = repr(model.model_fields[field].annotation)
    if "tuple" in text and "list" in text:
        return [[number, 0.0, 0.0]]
    if "tuple" in text:
        return [number, 0.0, 0.0]
    if "list" in text:
        return [number]
    return number


PLUGIN_FLOATS = _plugin_float_params()


def test_the_built_in_plugins_have_float_parameters_to_check():
    assert len(PLUGIN_FLOATS) >= 10
    assert ("terminals", "metric", "threshold") in PLUGIN_FLOATS
    assert ("roots", "point", "point") in PLUGIN_FLOATS


@pytest.mark.parametrize("stage, plugin, field", PLUGIN_FLOATS, ids=["/".join(p) for p in PLUGIN_FLOATS])
@pytest.mark.parametrize("number", [float("nan"), float("inf"), float("-inf")], ids=["nan", "inf", "-inf"])
def test_no_plugin_parameter_accepts_non_finite_numbers(stage, plugin, field, number):
    registry = installed()
    info = registry.get(stage, plugin)
    params = {field: _value_for(info.params_model, field, number)}
    with pytest.raises(ConfigError) as caught:
        registry.validate_params(info, params, key=f"{stage}.params")
    message = str(caught.value)
    # the selection rules of some plugins are checked after each field: a finite field is refused first
    assert f"{stage}.params.{field}" in message and "expected a finite number" in message, message


@pytest.mark.parametrize("section, model", [("agent", AgentConfig), ("mesh", MeshConfig)])
def test_no_config_number_accepts_non_finite_numbers(section, model):
    for field in _float_fields(model):
        for number in (float("nan"), float("inf"), float("-inf")):
            with pytest.raises(ConfigError, match=rf"my\.yaml: {section}\.{field}: expected a finite number"):
                parse_config({section: {field: number}}, source="my.yaml")


@pytest.mark.parametrize("spelling, expected", [
    (".nan", "expected a finite number, got nan"), (".NaN", "expected a finite number, got nan"),
    (".inf", "expected a finite number, got inf"), ("-.inf", "expected a finite number, got -inf"),
    # YAML reads these as strings, which are no numbers (they were converted before parameters were strict)
    ("nan", "expected a number or null, got 'nan'"), ("'inf'", "expected a number or null, got 'inf'"),
])
def test_metric_threshold_nan_cli(spelling, expected, tmp_path, capsys):
    config = tmp_path / "nan.yaml"
    config.write_text(
        "extends: map_analysis\nterminals: {plugin: metric, params: {metric: degree, threshold: %s}}\n" % spelling
    )
    out = tmp_path / "out"
    outcome = run_g2s(capsys, "run", config, CORRIDOR, "-o", out)
    assert_clean_error(outcome, f"nan.yaml: terminals.params.threshold: {expected}")
    assert tree(out) == []


@pytest.mark.parametrize("point", ["[.nan, 0, 0]", "[0, .inf, 0]", "[0, 0, -.inf]"])
def test_root_point_non_finite_cli(point, tmp_path, capsys):
    config = tmp_path / "root.yaml"
    config.write_text("extends: map_analysis\nroots: {plugin: point, params: {point: %s}}\n" % point)
    outcome = run_g2s(capsys, "run", config, CORRIDOR, "-o", tmp_path / "out")
    assert_clean_error(outcome, "root.yaml: roots.params.point.", "expected a finite number")


# --- values of the wrong type: plugin parameters are strict, as the config's sections -------------

WRONG_TYPES = {float: [True, "7"], int: [True, "7", 7.5], str: [7, True], bool: [1, "true"]}
"""A field's scalar type -> values that are not of it, as YAML reads them (``true``, ``'7'``, ``7``)."""


def _scalar_type(annotation):
    """The one scalar type of WRONG_TYPES that ``annotation`` holds (inside ``| None``, lists, tuples), else None."""
    found = {a for a in _leaves(annotation) if a in WRONG_TYPES}
    return found.pop() if len(found) == 1 and not any(get_origin(a) is Literal for a in _leaves(annotation)) else None


def _leaves(annotation):
    arguments = [a for a in get_args(annotation) if a is not Ellipsis and not isinstance(a, Strict)]
    return [leaf for a in arguments for leaf in _leaves(a)] if arguments and get_origin(annotation) is not Literal \
        else [annotation]


PLUGIN_TYPED = [(info.stage, info.name, field, kind) for info in installed().plugins()
                for field, model_field in info.params_model.model_fields.items()
                if (kind := _scalar_type(model_field.annotation)) is not None]


def test_every_kind_of_plugin_parameter_is_checked():
    kinds = {kind for *_, kind in PLUGIN_TYPED}
    assert kinds == set(WRONG_TYPES)
    assert ("graph", "navmesh", "cell_size", float) in PLUGIN_TYPED
    assert ("terminals", "points", "points", float) in PLUGIN_TYPED and ("levels", "doorway_room", "doors", float) in PLUGIN_TYPED


@pytest.mark.parametrize("stage, plugin, field, kind", PLUGIN_TYPED, ids=["/".join(p[:3]) for p in PLUGIN_TYPED])
def test_no_plugin_parameter_takes_a_value_of_another_type(stage, plugin, field, kind):
    """A bool is no number, a string no number, a number no string: each refused naming the key and the value."""
    registry = installed()
    info = registry.get(stage, plugin)
    for wrong in WRONG_TYPES[kind]:
        with pytest.raises(ConfigError) as caught:
            registry.validate_params(info, {field: _value_for(info.params_model, field, wrong)}, key=f"{stage}.params")
        message = str(caught.value)
        assert message.startswith(f"{stage}.params.{field}") and ": expected " in message, message
        assert message.endswith(f", got {show(wrong)}"), message


@pytest.mark.parametrize("section, says", [
    ("graph: {plugin: navmesh, params: {cell_size: true}}", "graph.params.cell_size: expected a number or null > 0, got true"),
    ("terminals: {plugin: coverage, params: {radius: '7'}}", "terminals.params.radius: expected a number or null > 0, got '7'"),
    ("terminals: {plugin: points, params: {file: 7}}", "terminals.params.file: expected a string or null, got 7"),
    ("terminals: {plugin: points, params: {points: [[0, true, 0]]}}", "terminals.params.points.0.1: expected a list of lists of 3 numbers or null"),
    ("roots: {plugin: point, params: {point: [0, 0, '1']}}", "roots.params.point.2: expected a list of 3 numbers, got '1'"),
    ("roots: {plugin: point, params: {point: [1, 2]}}", "roots.params.point: expected a list of 3 numbers, got a list of 2 items"),
    ("analyzers: [{plugin: degree, params: {weighted: 1}}]", "analyzers.0.params.weighted: expected true or false, got 1"),
    ("evaluators: [{plugin: traffic, params: {radii: [6, true]}}]", "evaluators.0.params.radii.1: expected a list of numbers"),
    ("evaluators: [{plugin: traffic, params: {seed: 1.5}}]", "evaluators.0.params.seed: expected an integer, got 1.5"),
])
def test_a_parameter_of_the_wrong_type_is_refused_before_any_work(section, says, tmp_path, capsys):
    """These ran before (``true`` read as 1 m, ``'7'`` as 7 m), now exit 2 with one line."""
    config = tmp_path / "typed.yaml"
    config.write_text(f"extends: map_analysis\n{section}\n")
    outcome = run_g2s(capsys, "run", config, CORRIDOR, "-o", tmp_path / "out")
    assert_clean_error(outcome, f"typed.yaml: {says}")
    assert tree(tmp_path / "out") == []


@pytest.mark.parametrize("config, setting, says", [
    # each of these valid but extreme values ended in a plugin's failure, or (detail_sample_dist) a segmentation fault
    ("graph_only", "graph.params.cell_height=1e300", "graph.params.cell_height: 1e+300 m is more than Recast's single"),
    ("map_piece", "terminals.params.edge_search_radii=1e300", "terminals.params.edge_search_radii: looking 4e+299 m"),
    ("map_analysis_sampling_paper", "graph.params.spacing=1e-300", "sampling: spacing 1e-300 m is too small for 1"),
    ("map_analysis_sampling", "graph.params.method=grid", "sampling: spacing 4.94066e-324 m gives a grid of inf x inf points"),
    ("map_piece", "terminals.params.sample_step=1e-300", "terminals.params.sample_step: a sample every 1e-300 m along the"),
    ("graph_only", "agent.radius=1e-300", "agent.radius: crest probes every 5e-301 m (half the agent's radius) along"),
    ("graph_only", "graph.params.detail_sample_dist=0", "graph.params.detail_sample_dist: expected a number >= 0.9, got 0"),
])
def test_a_value_out_of_proportion_to_the_level_is_refused_naming_its_key(config, setting, says, tmp_path):
    extra = ["--set", "graph.params.spacing=5e-324"] if "method=grid" in setting else []  # the grid's size overflows
    outcome = run_g2s_process("run", config, "sample:two_rooms_one_door", "-o", tmp_path / "out", "--set", setting, *extra)
    assert_clean_error(outcome, says)
    assert tree(tmp_path / "out") == []


@pytest.mark.parametrize("setting", ["roots={plugin: point, params: {point: [1e300, 0, 0]}}", "terminals.params.radius=1e300"])
def test_a_huge_distance_still_runs(setting, tmp_path):
    # the root point's distances overflowed to inf (the root selector "returned -inf"); the cover radius's square
    # raised OverflowError
    outcome = run_g2s_process("run", "map_analysis", CORRIDOR, "-o", tmp_path / "out", "-q", "--set", setting)
    assert outcome.code == 0, outcome.stderr


def test_lists_tuples_and_integers_for_numbers_are_still_taken():
    registry = installed()

    def params(stage, plugin, **values):
        return registry.validate_params(registry.get(stage, plugin), values, key=f"{stage}.params")

    assert params("roots", "point", point=[1, 0, 2.5]).point == (1.0, 0.0, 2.5)  # YAML gives a list for a tuple
    assert params("terminals", "points", points=[[0, 0, 1], (2, 0, 3.5)]).points == [(0.0, 0.0, 1.0), (2.0, 0.0, 3.5)]
    assert params("terminals", "points", file="points.csv").file == "points.csv"
    assert params("evaluators", "traffic", radii=(3, 6)).radii == [3.0, 6.0]  # Python code may give a tuple
    assert params("levels", "doorway_room", doors=[1, 1.5]).doors == (1.0, 1.5)
    radius = params("terminals", "coverage", radius=7).radius
    assert radius == 7 and isinstance(radius, float)


@pytest.mark.parametrize("how", [["--set", "terminals.params.radius=7"], ["--set", "terminals.params={radius: 7.5}"]])
def test_a_number_given_with_set_is_read_as_yaml_and_taken(how, tmp_path, capsys):
    outcome = run_g2s(capsys, "run", "map_analysis", CORRIDOR, "-o", tmp_path / "out", "--format", "json", "-q", *how)
    assert outcome.code == 0, outcome.stderr
    assert (tmp_path / "out" / "structure.json").is_file()


def test_a_quoted_number_given_with_set_is_refused(tmp_path, capsys):
    outcome = run_g2s(capsys, "run", "map_analysis", CORRIDOR, "-o", tmp_path / "out", "--set", "terminals.params.radius='7'")
    assert_clean_error(outcome, "terminals.params.radius: expected a number or null > 0, got '7'")


@pytest.mark.parametrize("spec", ["sample:dungeon?rooms=5&seed=2", "sample:two_floors?ramp=false", "sample:straight_corridor?length=9.5"])
def test_a_sample_query_is_text_converted_to_its_types(spec, tmp_path, capsys):
    """A URL query holds only text: ``rooms=5`` is the integer 5, ``ramp=false`` false (pydantic's reading of text)."""
    outcome = run_g2s(capsys, "run", "graph_only", spec, "-o", tmp_path / "out", "-q")
    assert outcome.code == 0, outcome.stderr


@pytest.mark.parametrize("query, says", [
    ("rooms=abc", "rooms: expected an integer >= 1 and <= 100000, got 'abc'"),
    ("rooms=true", "rooms: expected an integer >= 1 and <= 100000, got 'true'"),
    ("rooms=2.5", "rooms: expected an integer >= 1 and <= 100000, got '2.5'"),
    ("seed=", "seed: expected an integer >= 0, got ''"),
])
def test_a_sample_query_value_that_is_not_of_its_type_is_refused(query, says, tmp_path, capsys):
    outcome = run_g2s(capsys, "run", "graph_only", f"sample:dungeon?{query}", "-o", tmp_path / "out")
    assert_clean_error(outcome, f"sample:dungeon.{says}")
    assert tree(tmp_path / "out") == []


def test_executor_parameters_are_strict_too(tmp_path):
    from g2s_plugins.batch.runner import run_batch

    with pytest.raises(ConfigError, match=r"^executor 'local' params\.workers: expected an integer or null >= 1, got '2'$"):
        run_batch(["graph_only"], [CORRIDOR], tmp_path / "out", "local", executor_params={"workers": "2"})
    assert not (tmp_path / "out").exists()


# --- command-line options -------------------------------------------------------------------


@pytest.mark.parametrize(
    "option, value, says",
    [("--rooms", "0", "--rooms: expected an integer >= 1 and <= 100000, got 0"),
     ("--rooms", "-3", "--rooms: expected an integer >= 1 and <= 100000, got -3"),
     # was named sample:dungeon.rooms, a spec the user never wrote (the generator's bound, checked after the CLI's)
     ("--rooms", "100001", "--rooms: expected an integer >= 1 and <= 100000, got 100001"),
     ("--seed", "-1", "--seed: expected an integer >= 0, got -1")],
)
def test_demo_options_out_of_range(option, value, says, tmp_path, capsys):
    out = tmp_path / "demo"
    outcome = run_g2s(capsys, "demo", "-o", out, option, value)
    assert_clean_error(outcome, says)
    assert tree(out) == []
