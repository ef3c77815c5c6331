"""Values no setting accepts: NaN and infinities in any plugin parameter or config number,
and out-of-range command-line options."""

from __future__ import annotations

from typing import get_args

import pytest
from pydantic import BaseModel

from g2s_core.config import AgentConfig, MeshConfig, parse_config
from g2s_core.errors import ConfigError
from g2s_core.registry import installed
from tests.reliability.checks import CORRIDOR, assert_clean_error, run_g2s, tree

NON_FINITE = {"nan": ".nan", "inf": ".inf", "-inf": "-.inf"}
"""Name -> how YAML writes it."""


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


@pytest.mark.parametrize("spelling", [".nan", ".NaN", "nan", ".inf", "-.inf", "'inf'"])
def test_metric_threshold_nan_cli(spelling, tmp_path, capsys):
    config = tmp_path / "nan.yaml"
    config.write_text(
        "extends: map_analysis\nterminals: {plugin: metric, params: {metric: degree, threshold: %s}}\n" % spelling
    )
    out = tmp_path / "out"
    outcome = run_g2s(capsys, "run", config, CORRIDOR, "-o", out)
    assert_clean_error(outcome, "nan.yaml: terminals.params.threshold: expected a finite number")
    assert tree(out) == []


@pytest.mark.parametrize("point", ["[.nan, 0, 0]", "[0, .inf, 0]", "[0, 0, -.inf]"])
def test_root_point_non_finite_cli(point, tmp_path, capsys):
    config = tmp_path / "root.yaml"
    config.write_text("extends: map_analysis\nroots: {plugin: point, params: {point: %s}}\n" % point)
    outcome = run_g2s(capsys, "run", config, CORRIDOR, "-o", tmp_path / "out")
    assert_clean_error(outcome, "root.yaml: roots.params.point.", "expected a finite number")


# --- command-line options -------------------------------------------------------------------


@pytest.mark.parametrize(
    "option, value, says",
    [("--rooms", "0", "--rooms: expected an integer >= 1, got 0"),
     ("--rooms", "-3", "--rooms: expected an integer >= 1, got -3"),
     ("--rooms", "100000000", "sample:dungeon.rooms: expected an integer >= 1 and <= 100000, got '100000000'"),
     ("--seed", "-1", "--seed: expected an integer >= 0, got -1")],
)
def test_demo_options_out_of_range(option, value, says, tmp_path, capsys):
    out = tmp_path / "demo"
    outcome = run_g2s(capsys, "demo", "-o", out, option, value)
    assert_clean_error(outcome, says)
    assert tree(out) == []
