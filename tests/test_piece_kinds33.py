"""Pieces of the thirty-third round (``benchmarks/piece_kinds33.py``) on the map-piece presets.

A yard's sitting wall 1.0 m high lowered to 0.3 m (within the climb) along a stretch: the stretch is an opening on
both routes, a step between things the agent cannot step onto from its top, where it was dropped as a curb (the jambs'
probes at half the agent's height pass over a 1.0 m wall). A stair module with a handrail down its middle: each
lane's two ends on `map_piece` at 22 and 45 degrees, where one lane was lost as off the main floor's level (Recast
keeps the lane as one polygon whose first corner is the top's), as both routes find them at 0 degrees; and, by the same
rule, the landing's door of the twenty-first round's stair out of a corner doorway on `map_piece` at 0 degrees.
(docs/entry_exit.md, "A thirty-third round of piece kinds".)
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from g2s_plugins.samples import pieces
from tests.conftest import benchmark, piece_openings, round_openings


@pytest.mark.parametrize("preset", ["map_piece", "map_piece_sampling"])
def test_a_sitting_walls_stretch_within_the_climb_is_an_opening(preset: str) -> None:
    south = [o for o in round_openings("piece_kinds33", "sitting_wall_step_over", preset) if o.position[2] < 0.0]
    assert len(south) == 1  # 2.4 m at the wall's outer face (round_openings); none before: a curb


@pytest.mark.parametrize("yaw", [22.0, 45.0])
def test_both_lanes_of_a_stair_parted_by_a_handrail_keep_their_ends(yaw: float) -> None:
    level = pieces.turned(benchmark("piece_kinds33").stair_central_handrail(), yaw)
    found = piece_openings(level, "map_piece")
    assert len(found) == 4  # two lanes, two ends each (two before: one lane off the main floor's level)
    assert all(1.5 < o.width < 1.6 for o in found)
    assert sorted(round(o.position[1], 1) for o in found) == [0.0, 0.0, 1.6, 1.6]


def test_a_flight_recast_keeps_as_one_polygon_from_its_second_riser_keeps_its_landings_door() -> None:
    round_openings("piece_kinds21", "corner_stair_exit")  # both doorways, 1.6 m each; the landing's missed before


@pytest.mark.parametrize("yaw", [0.0, 45.0])
def test_a_doorway_at_a_walls_fold_spans_its_jambs_and_faces_square_to_them(yaw: float) -> None:
    level = pieces.turned(benchmark("piece_kinds33").folded_wall_door(), yaw)
    known = level.openings[1]
    (door,) = [o for o in piece_openings(level, "map_piece") if np.linalg.norm(np.subtract(o.position, known.position)) < 1.5]
    assert door.width == pytest.approx(1.70, abs=0.03)  # 1.64 / 1.62 m before, along one wing's line
    assert np.dot(door.heading, known.heading) > math.cos(math.radians(2.0))  # 15 degrees off before
