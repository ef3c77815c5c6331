"""Pieces of the thirty-fifth round (``benchmarks/piece_kinds35.py``) on the map-piece presets.

The round's eight kinds gave their known openings and nothing else on both routes at 0, 22 and 45 degrees; these
hold two of them whose openings a rule could lose: a door whose sill is flush with a flight's top tread (no landing),
and a garage whose tilt-up door lies open inside as a panel, a doorway when the panel is over the agent's height and
none under it (docs/entry_exit.md, "A thirty-fifth round of piece kinds").
"""

from __future__ import annotations

import pytest

from tests.conftest import benchmark, piece_openings, round_openings


@pytest.mark.parametrize("preset", ["map_piece", "map_piece_sampling"])
def test_a_door_flush_with_a_flights_top_tread_is_an_opening_at_its_sill(preset: str) -> None:
    openings = round_openings("piece_kinds35", "stair_to_high_door", preset)
    (high,) = [o for o in openings if o.position[1] > 1.0]
    assert high.position[1] == pytest.approx(1.2, abs=0.05)  # the sill, flush with the top tread


@pytest.mark.parametrize(("panel_at", "known"), [(2.1, 2), (1.9, 1)])
def test_a_garage_doorway_under_an_open_tilt_panel_is_an_opening_only_if_the_agent_fits_under(
        panel_at: float, known: int) -> None:
    level = benchmark("piece_kinds35").tilt_up_garage_door(panel_at=panel_at)
    assert len(level.openings) == known
    recalled, missed, correct, other, _ = benchmark("piece_kinds10").score(
        level, piece_openings(level, "map_piece_sampling"), one_to_one=True)
    assert (recalled, missed, correct, other) == (known, 0, known, 0)
