"""Pieces of the thirty-third round (``benchmarks/piece_kinds33.py``) on the map-piece presets.

A yard's sitting wall 1.0 m high lowered to 0.3 m (within the climb) along a stretch: the stretch is an opening on
both routes, a step between things the agent cannot step onto from its top, where it was dropped as a curb (the jambs'
probes at half the agent's height pass over a 1.0 m wall). (docs/entry_exit.md, "A thirty-third round of piece kinds".)
"""

from __future__ import annotations

import pytest

from tests.conftest import round_openings


@pytest.mark.parametrize("preset", ["map_piece", "map_piece_sampling"])
def test_a_sitting_walls_stretch_within_the_climb_is_an_opening(preset: str) -> None:
    south = [o for o in round_openings("piece_kinds33", "sitting_wall_step_over", preset) if o.position[2] < 0.0]
    assert len(south) == 1  # 2.4 m at the wall's outer face (round_openings); none before: a curb

