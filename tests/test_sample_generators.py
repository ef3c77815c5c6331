"""The sample levels as level-generator plugins: each parameter documented once, by its factory."""

from __future__ import annotations

import inspect
import os
import subprocess
import sys

import pytest

from g2s_core.errors import ConfigError
from g2s_core.mesh import generate_level
from g2s_plugins.samples.generators import GENERATORS, documented_args
from g2s_plugins.samples.levels import SAMPLES, dungeon
from tests.conftest import PROJECT


def _example(width: float = 1.0, height: float = 2.0, label: str = "") -> None:
    """A summary line.

    Args:
        width: the first entry, metres.
        height (float): an entry with a type, whose text
            goes on over two lines.
        label: the last one.

    Returns:
        Nothing; ``Returns:`` ends the section.
    """


def test_args_section_entries_with_types_and_continuation_lines():
    assert documented_args(_example) == {
        "width": "the first entry, metres.",
        "height": "an entry with a type, whose text goes on over two lines.",
        "label": "the last one.",
    }
    assert documented_args(len) == {}  # a docstring without an Args: section


def test_a_parameter_description_is_its_args_line():
    params = {g.NAME: g.Params for g in GENERATORS}["dungeon"].model_fields
    assert params["spacing"].description == "pitch of the rooms' grid, metres."
    assert params["obstacles"].description == "probability that a lattice site in a room holds a pillar."
    assert "        spacing: pitch of the rooms' grid, metres.\n" in dungeon.__doc__


@pytest.mark.parametrize("name", list(SAMPLES))
def test_every_generator_parameter_is_documented(name):
    factory = SAMPLES[name]
    parameters = [p for p in inspect.signature(factory).parameters.values() if p.default is not p.empty]
    described = documented_args(factory)
    missing = [p.name for p in parameters if not described.get(p.name)]
    assert not missing, f"{factory.__module__}.{factory.__name__}(): no Args: entry for {', '.join(missing)}"
    stale = set(described) - {p.name for p in parameters}
    assert not stale, f"{factory.__module__}.{factory.__name__}(): Args: names no parameter {', '.join(sorted(stale))}"
    fields = {g.NAME: g.Params for g in GENERATORS}[name].model_fields
    for parameter in parameters:
        assert fields[parameter.name].description == described[parameter.name]
        assert not fields[parameter.name].description.startswith("argument "), "the old boilerplate"


def test_plugins_listing_shows_the_unit_and_bounds_of_dungeon_spacing():
    proc = subprocess.run([sys.executable, "-m", "g2s_core.cli", "plugins", "--stage", "levels"], capture_output=True,
                          text=True, cwd=PROJECT, env={**os.environ, "COLUMNS": "200"})
    assert proc.returncode == 0, proc.stderr
    block = proc.stdout.split("\n  dungeon ", 1)[1].split("\n  ", 1)[1]
    spacing = next(line.strip() for line in block.splitlines() if line.strip().startswith("spacing:"))
    assert spacing.split(maxsplit=1)[1] == "a number > 0, default 14.0. pitch of the rooms' grid, metres."


@pytest.mark.parametrize(
    "spec, message",
    [
        ("sample:dungeon?obstacles=1.5", "sample:dungeon.obstacles: expected a number >= 0 and <= 1, got '1.5'"),
        ("sample:dungeon?rooms=0", "sample:dungeon.rooms: expected an integer >= 1 and <= 100000, got '0'"),
        # a typo's count generated for minutes before anything said why
        ("sample:dungeon?rooms=100000000", "sample:dungeon.rooms: expected an integer >= 1 and <= 100000, got '100000000'"),
        ("sample:corridor_with_ramp?slope_deg=90", "sample:corridor_with_ramp.slope_deg: expected a number > 0 and < 90, got '90'"),
    ],
)
def test_bounds_in_the_signature_are_checked_before_the_factory_runs(spec, message):
    with pytest.raises(ConfigError) as caught:
        generate_level(spec)
    assert str(caught.value) == message
