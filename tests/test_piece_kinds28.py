"""Three of the twenty-eighth round's pieces (``benchmarks/piece_kinds28.py``) on the map-piece presets.

A sliding (barn) door hung on a doorway's inner face and slid half across it leaves the agent 0.9 m between its end
and the far jamb: the opening is that part, on both routes (it read the doorway's 1.6 m, the leaf standing just past
where the passage's sides open out; docs/entry_exit.md, "A twenty-eighth round of piece kinds"). Two round arches
springing at 1.6 m: the 1.6 m one is an opening, the 1.0 m one (0.6 m clear at the agent's 2 m) none. A closed room
whose only way out is a stair down through its floor: one opening, at the corridor's end 3 m down.
"""

from __future__ import annotations

import numpy as np
import pytest

from tests.conftest import round_openings


@pytest.mark.parametrize("preset", ["map_piece", "map_piece_sampling"])
def test_a_barn_door_slid_half_across_leaves_the_part_beside_it(preset: str) -> None:
    east = max(round_openings("piece_kinds28", "barn_door_slid_open", preset), key=lambda o: o.position[0])
    assert abs(east.width - 0.9) < 0.05 and abs(east.position[2] - 3.35) < 0.05  # between the leaf's end and the jamb


def test_of_two_arches_springing_at_1_6_m_only_the_one_the_agent_stands_up_in_is_an_opening() -> None:
    # the arch's 1.44 m at the head-room rays
    openings = round_openings("piece_kinds28", "low_spring_arches", width_tolerance=0.2)
    narrow = np.array([8.3, 0.0, 4.3])
    assert min(np.linalg.norm(np.asarray(o.position) - narrow) for o in openings) > 1.0


def test_a_stair_down_through_the_floor_leads_to_the_only_opening() -> None:
    (only,) = round_openings("piece_kinds28", "stair_hole_only_exit")
    assert abs(only.position[1] + 3.0) < 0.01 and abs(only.position[0] - 10.3) < 0.05
