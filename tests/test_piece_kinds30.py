"""Four of the thirtieth round's pieces (``benchmarks/piece_kinds30.py``) on the map-piece presets.

A spiral stair in a tower whose two doorways stand one over the other, 3.6 m apart: two openings at one place in
plan, on both routes. A footbridge whose deck runs on outside its railings as ledges narrower than the agent: its ends
between the railings, whole on the sampling route too, where a few samples near an end's middle left it 2.12 m of
2.4 before the extension along the edge reached as far as a sample looks for the floor's end. A doorway beside a
window at the floor 0.5 m high: the door alone, not widened by the window. A square room with a doorway in each
wall, each off its wall's middle. (docs/entry_exit.md, "A thirtieth round of piece kinds".)
"""

from __future__ import annotations

import numpy as np
import pytest

from tests.conftest import round_openings


@pytest.mark.parametrize("preset", ["map_piece", "map_piece_sampling"])
def test_a_spiral_stairs_doorways_one_over_the_other_are_two_openings(preset: str) -> None:
    openings = round_openings("piece_kinds30", "spiral_stair_stacked_doors", preset)
    heights = sorted(o.position[1] for o in openings)
    assert abs(heights[0]) < 0.01 and abs(heights[1] - 3.6) < 0.01
    plan = np.array([[o.position[0], o.position[2]] for o in openings])
    assert np.linalg.norm(plan[0] - plan[1]) < 0.05  # stacked: one place in plan


def test_a_bridges_end_between_railings_is_whole_on_the_sampling_route() -> None:
    openings = round_openings("piece_kinds30", "railed_bridge_outer_ledges", "map_piece_sampling")
    assert all(abs(o.width - 2.4) < 0.05 for o in openings)  # the west end read 2.12 m before


def test_a_window_at_the_floor_beside_a_door_neither_opens_nor_widens_it() -> None:
    east = max(round_openings("piece_kinds30", "door_beside_floor_window"), key=lambda o: o.position[0])
    assert abs(east.position[2] - 1.6) < 0.05 and abs(east.width - 1.2) < 0.05


def test_a_square_rooms_four_doorways_off_their_walls_middles() -> None:
    openings = round_openings("piece_kinds30", "four_wall_offset_doors")
    assert sorted(round(o.width, 1) for o in openings) == [1.0, 1.2, 1.6, 2.0]
