"""The twenty-sixth round's grating of bars along the way (``benchmarks/piece_kinds26.py``) on the ``map_piece`` preset,
and the rounds' one-to-one count.

The corridor's last 3 m are bars 0.03 m wide, 0.03 m apart, running along the way over nothing: its east end is the
bars' ends, 2.4 m wide (docs/entry_exit.md, "A twenty-sixth round of piece kinds": missed at 0 degrees before the
narrow-gap measure looked square to the way, 2.38 m since). A second opening found near a known one is correct
under the rounds' count and other under ``--one-to-one``.
"""

from __future__ import annotations

from g2s_core import pipeline
from g2s_core.config import PRESETS_DIR, load_config
from g2s_core.mesh import mesh_sha256
from g2s_core.registry import Registry
from g2s_plugins.samples.levels import _opening
from g2s_plugins.samples.pieces import _E, _W
from tests.conftest import benchmark


def test_a_corridor_ending_in_a_grating_of_bars_along_the_way_keeps_its_end() -> None:
    level = benchmark("piece_kinds26").bar_grating_end()
    registry = Registry.from_entry_points()
    plan = pipeline.plan(load_config(PRESETS_DIR / "map_piece.yaml"), registry)
    openings = list(pipeline.run(plan, registry, level.mesh, level.name, mesh_sha256(level.mesh)).terminals.openings)
    recalled, missed, correct, other, width_error = benchmark("piece_kinds10").score(level, openings, one_to_one=True)
    assert (recalled, missed, correct, other) == (2, 0, 2, 0)
    assert width_error < 0.05
    east = max(openings, key=lambda o: o.position[0])
    assert abs(east.position[0] - 12.0) < 0.05 and abs(east.position[1]) < 0.01  # the bars' ends, at the floor


def test_the_one_to_one_count_makes_a_second_opening_near_a_known_one_other() -> None:
    rounds = benchmark("piece_kinds10")
    level = rounds._level("two_doors", [rounds._box(0.0, 1.0, 0.0, 1.0, 0.0, 1.0)],
                          [_opening((0.0, 0.0, 0.0), _W, 1.6), _opening((10.0, 0.0, 0.0), _E, 1.6)])
    found = [_opening((0.0, 0.0, -0.6), _W, 1.0), _opening((0.0, 0.0, 0.6), _W, 1.0)]  # both 0.6 m off the west one
    assert rounds.score(level, found) == (1, 1, 2, 0, 0.6000000000000001)
    assert rounds.score(level, found, one_to_one=True)[:4] == (1, 1, 1, 1)
