"""Pieces of the thirty-sixth round (``benchmarks/piece_kinds36.py``) on the map-piece presets.

A lych gate's coffin stone 0.4 m inside its wall split the gate's 2.4 m opening at 45 degrees on the navmesh route:
its two lanes' parts ended 7 mm apart on the stone's side, along one line, and only parts that overlap were joined
(docs/entry_exit.md, "A thirty-sixth round of piece kinds"). These hold the rule that joins parts abutting along one
line with nothing standing between them, and a door under a transom bar with an open fanlight over it.
"""

from __future__ import annotations

import numpy as np
import pytest

from g2s_core.config import PRESETS_DIR, load_config
from g2s_core.model import Opening
from g2s_plugins._raycasting import RayCaster
from g2s_plugins.samples import pieces
from g2s_plugins.terminals import entry_exit
from tests.conftest import benchmark, box, piece_openings, round_openings


def _along_x(x0: float, x1: float) -> Opening:
    """An opening from x0 to x1 m along X at the origin's height, facing -Z."""
    return Opening(((x0 + x1) / 2, 0.0, 0.0), (0.0, 0.0, -1.0), x1 - x0, (x0, 0.0, 0.0), (x1, 0.0, 0.0))


def test_parts_abutting_along_one_line_with_nothing_between_them_are_one_opening() -> None:
    wide, part = _along_x(0.9, 2.4), _along_x(0.0, 0.893)  # 7 mm apart, the lych gate's parts at 45 degrees
    asked = []

    def free(a: np.ndarray, b: np.ndarray) -> bool:
        asked.append((a.tolist(), b.tolist()))
        return True

    assert list(entry_exit._repeated([wide, part], 0.4, 30.0, 0.4, free, 0.05)) == [-1, 0]
    assert asked == [([0.9, 0.0, 0.0], [0.893, 0.0, 0.0])]  # the two ends that face each other
    # something standing between them on the line (a leaf turned across a doorway, a post): two openings
    assert list(entry_exit._repeated([wide, part], 0.4, 30.0, 0.4, lambda a, b: False, 0.05)) == [-1, -1]
    # farther apart than the reach, or asked without the rule: two openings, as before
    assert list(entry_exit._repeated([wide, _along_x(0.0, 0.8)], 0.4, 30.0, 0.4, free, 0.05)) == [-1, -1]
    assert list(entry_exit._repeated([wide, part], 0.4, 30.0, 0.4)) == [-1, -1]
    # its end more than the climb above the wider one's (a cliff between two stretches of a border), its middle
    # within the climb of the wider one's line: two openings
    cliff = Opening((0.45, 0.25, 0.0), (0.0, 0.0, -1.0), 0.96, (0.0, 0.0, 0.0), (0.893, 0.5, 0.0))
    assert list(entry_exit._repeated([wide, cliff], 0.4, 30.0, 0.4, free, 0.05)) == [-1, -1]


def test_the_floors_end_between_two_parts_is_free_unless_something_stands_across_it() -> None:
    s = entry_exit._settings(entry_exit.Params(), load_config(PRESETS_DIR / "map_piece.yaml").agent)
    a, b = np.array([0.0, 0.0, 0.0]), np.array([0.05, 0.0, 0.0])
    floor = box(-1.0, 1.0, -0.2, 0.0, -1.0, 1.0)
    leaf = box(0.015, 0.035, 0.0, 2.0, -1.0, 1.0)  # a leaf 0.02 m thick standing across the line between them
    assert entry_exit._free_along(a, b, RayCaster(floor), s)
    assert not entry_exit._free_along(a, b, RayCaster(floor + leaf), s)


def test_a_lych_gates_coffin_stone_leaves_the_gate_one_opening_at_45_degrees() -> None:
    level = pieces.turned(benchmark("piece_kinds36").lych_gate_stone(), 45.0)
    recalled, missed, correct, other, width_error = benchmark("piece_kinds10").score(
        level, piece_openings(level, "map_piece"), one_to_one=True)
    assert (recalled, missed, correct, other) == (2, 0, 2, 0)
    assert width_error < 0.05


@pytest.mark.parametrize("preset", ["map_piece", "map_piece_sampling"])
def test_a_door_under_an_open_fanlight_is_one_opening_at_the_floor(preset: str) -> None:
    openings = round_openings("piece_kinds36", "fanlight_over_door", preset)
    assert all(abs(o.position[1]) < 0.05 for o in openings)  # at the floor, not at the fanlight's sill 2.2 m up
