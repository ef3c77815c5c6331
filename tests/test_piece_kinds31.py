"""Four of the thirty-first round's pieces (``benchmarks/piece_kinds31.py``) on the map-piece presets.

A doorway in the outer wall of a tight quarter ring of corridor, its floor ending flush with the curved face: the
width between its radial jambs at the inner face (1.11 m), on both routes, where the extension along the edge left
the floor 0.1 m short of each jamb (1.00-1.08 m) before the ends moved out onto the passage's sides. Two raised
doorways side by side, a threshold 0.35 m up (under the climb: an opening at its top) and one 0.5 m up (over it:
none). A doorway with two pillars standing in it 0.3 m from its jambs: one opening, the 1.4 m between them. A balcony
over nothing whose only way on is the French window behind it. (docs/entry_exit.md, "A thirty-first round of piece
kinds".)
"""

from __future__ import annotations

import pytest

from tests.conftest import round_openings


@pytest.mark.parametrize("preset", ["map_piece", "map_piece_sampling"])
def test_a_doorway_in_a_curved_wall_is_as_wide_as_its_jambs_at_the_inner_face(preset: str) -> None:
    openings = round_openings("piece_kinds31", "tight_quarter_ring_side_door", preset)
    door = min(openings, key=lambda o: o.width)
    assert abs(door.width - 1.11) < 0.02  # 0.99-1.01 m before


def test_a_threshold_under_the_climb_opens_and_one_over_it_does_not() -> None:
    openings = round_openings("piece_kinds31", "twin_threshold_doors")
    raised = max(openings, key=lambda o: o.position[0])
    assert abs(raised.position[1] - 0.35) < 0.01 and abs(raised.position[2] - 1.6) < 0.05


def test_pillars_in_a_doorway_leave_one_opening_between_them() -> None:
    east = max(round_openings("piece_kinds31", "pillared_doorway_narrow_gaps"), key=lambda o: o.position[0])
    assert abs(east.width - 1.4) < 0.05


def test_a_balconys_french_window_is_its_only_opening() -> None:
    (window,) = round_openings("piece_kinds31", "french_window_balcony")
    assert abs(window.position[1] - 3.0) < 0.01 and window.heading[0] < -0.99
