"""Inputs robust5's command-line fuzzing (4 December 2026) found told wrongly or read silently: a plugin
parameter refused by its own rule was described by its type and bounds, which allowed the value
(``tile_size: expected an integer or null >= 0 and <= 16777215, got 2``), and a JSON points file's ``true`` and
``"1"`` were read as the coordinate 1."""

from __future__ import annotations

import re

import pytest

from g2s_core.errors import G2SError
from g2s_plugins.terminals.points import read_points
from tests.reliability.checks import assert_clean_error, run_g2s, tree


def test_a_parameter_refused_by_its_own_rule_says_the_rule(tmp_path, capsys):
    outcome = run_g2s(capsys, "run", "map_analysis", "sample:straight_corridor", "-o", tmp_path / "out",
                      "--set", "graph.params.tile_size=2")
    assert_clean_error(outcome, "map_analysis: graph.params.tile_size: tile_size must be 0 (solo) or >= 16 cells, got 2")
    assert tree(tmp_path / "out") == []


@pytest.mark.parametrize("text, says", [
    ("[[true, false, true]]", "point 0 is [true, false, true], expected [x, y, z] numbers"),
    ('[["1", "0", "0"]]', 'point 0 is ["1", "0", "0"], expected [x, y, z] numbers'),
    ("[[6, 0, 0], [null, 0, 0]]", "point 1 is [null, 0, 0], expected [x, y, z] numbers"),  # was [None, 0, 0]
])
def test_a_json_points_file_of_other_values_than_numbers_is_refused(text, says, tmp_path):
    points = tmp_path / "points.json"
    points.write_text(text)
    with pytest.raises(G2SError, match=f"^{re.escape(f'{points}: {says}')}$"):
        read_points(points)
    points.write_text("[[6, 0, 0], [6.5, 0.1, -1e-3]]")
    assert read_points(points).tolist() == [[6, 0, 0], [6.5, 0.1, -1e-3]]
