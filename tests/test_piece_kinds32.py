"""Pieces of the thirty-second round (``benchmarks/piece_kinds32.py``) and two earlier ones on the map-piece presets.

Two doors 0.3 m apart whose wall between them is only a thin post set back 0.1 m from the face the floor ends at:
two openings, 1.2 m each, on both routes, where the doors' edge ran over the post and was read 0.3 m wide at it
(neither door found at 0 and 45 degrees before the post was looked for inside the edge). A railed cliff path's end
at 45 degrees on the sampling route: 3.9 m between the railing and the rock, 3.86 m while an end moved out onto a
side read 0.2 m in was the side's. The revolving drum's mouth (round 10): the two ways either side of the wing pack,
one opening each, as two doors beside a pier. A dead-end corridor whose hatch up a ladder is no opening. (docs/
entry_exit.md, "A thirty-second round of piece kinds".)
"""

from __future__ import annotations

import numpy as np
import pytest

from g2s_plugins.samples import pieces
from tests.conftest import benchmark, piece_openings, round_openings


@pytest.mark.parametrize("preset", ["map_piece", "map_piece_sampling"])
def test_two_doors_either_side_of_a_thin_set_back_post_are_two_openings(preset: str) -> None:
    east = [o for o in round_openings("piece_kinds32", "thin_post_twin_doors", preset) if o.position[0] > 8.0]
    assert len(east) == 2  # each its known door, 1.2 m (round_openings); none at 0 degrees before: 0.3 m at the post


def test_a_railed_cliff_paths_end_at_45_degrees_is_as_wide_as_the_path_on_the_sampling_route() -> None:
    level = pieces.turned(benchmark("piece_kinds27").cliff_path_railing_gap(), 45.0)
    found = piece_openings(level, "map_piece_sampling")
    assert len(found) == 2
    assert all(abs(o.width - 3.9) < 0.02 for o in found)  # one 3.86 m before


def test_a_revolving_drums_mouth_is_its_two_ways_either_side_of_the_wing_pack() -> None:
    level = benchmark("piece_kinds10").revolving_drum()
    mouth = [o for o in piece_openings(level, "map_piece") if o.position[0] > 8.0]
    assert len(mouth) == 2
    assert sorted(o.position[2] > 3.0 for o in mouth) == [False, True]  # one each side of the pack (z 3.0)
    assert all(1.2 < o.width < 1.4 for o in mouth)


def test_a_hatch_up_a_ladder_is_no_opening() -> None:
    (end,) = round_openings("piece_kinds32", "ladder_hatch_dead_end")
    assert np.dot(end.heading, (-1.0, 0.0, 0.0)) > 0.99
