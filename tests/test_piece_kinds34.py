"""Pieces of the thirty-fourth round (``benchmarks/piece_kinds34.py``) on the map-piece presets.

A doorway through a thick wall with a crate standing in one half of its reveal, its face at the doorway's middle: on
the sampling route the middle of the floor's end lies a few millimetres inside the crate, and the passage's free part
was read through the crate's inside, on its side (1.985 m at 0 and 45 degrees, joined with the true part; 1.0 m but on
the crate's side at 22). It is now read again from just past the crate's face: the clear part beside it, 1.0 m, at
every yaw; and so is a crate covering more than half the doorway, whose inside the middle stands 0.2 m deep in (1.4 m
read for the 1.0 m clear part, 1.2 m off it, before). (docs/entry_exit.md, "A thirty-fourth round of piece kinds".)
"""

from __future__ import annotations

import numpy as np
import pytest

from g2s_plugins.samples import pieces
from tests.conftest import benchmark, piece_openings, round_openings


@pytest.mark.parametrize("yaw", [0.0, 22.0])
def test_a_crate_in_half_a_doorway_leaves_the_clear_half_on_the_sampling_route(yaw: float) -> None:
    level = pieces.turned(benchmark("piece_kinds34").crate_in_thick_doorway(), yaw)
    known = level.openings[1]
    (door,) = [o for o in piece_openings(level, "map_piece_sampling")
               if np.linalg.norm(np.subtract(o.position, known.position)) < 1.5]
    assert door.width == pytest.approx(1.0, abs=0.05)  # 1.985 m at 0 degrees before: the crate's half joined in
    assert np.linalg.norm(np.subtract(door.position, known.position)) < 0.1  # 1.0 m off at 22 degrees: the crate's half


def test_a_crate_over_more_than_half_a_doorway_leaves_its_clear_part_on_the_sampling_route() -> None:
    level = benchmark("piece_kinds34").crate_in_thick_doorway(crate=1.4, door=2.4)
    known = level.openings[1]
    (door,) = [o for o in piece_openings(level, "map_piece_sampling")
               if np.linalg.norm(np.subtract(o.position, known.position)) < 1.5]
    assert door.width == pytest.approx(1.0, abs=0.05)  # 1.4 m before: the crate's inside read as the free part
    assert np.linalg.norm(np.subtract(door.position, known.position)) < 0.1  # 1.2 m off before


def test_the_crate_in_half_a_doorway_at_zero_degrees_on_map_piece() -> None:
    round_openings("piece_kinds34", "crate_in_thick_doorway")  # the west doorway and the clear half, nothing else
