"""Inputs robust15 (5 December 2026) found told in other words: the newest options with bad values (a spread heat map
with a scaling whose margin is not measured said pydantic's ``value error,``)."""

from __future__ import annotations

import pytest

from tests.reliability.checks import assert_clean_error, run_g2s, tree


@pytest.mark.parametrize("options", [["--set", "simplify.params.heat_sampling=spread"],
                                     ["--set", "simplify.params.heat_scaling=none"]])
def test_a_spread_heat_map_with_an_unmeasured_scaling_is_told_in_our_words(options, tmp_path, capsys):
    # map_analysis's heat map is independent and not scaled, map_analysis_sampling's spread and linear
    preset = "map_analysis" if "heat_sampling" in options[1] else "map_analysis_sampling"
    outcome = run_g2s(capsys, "run", preset, "sample:cross_hub", "-o", tmp_path / "out", *options)
    line = assert_clean_error(outcome, f"g2s: error: {preset}: simplify.params: min_heat_rho with heat_sampling: "
                                       "spread needs heat_scaling linear (the guarantee's margin for a spread heat map "
                                       "is measured for that alone), not none")
    assert "value error" not in line
    assert tree(tmp_path / "out") == []
