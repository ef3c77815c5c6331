"""Four of the twenty-ninth round's pieces (``benchmarks/piece_kinds29.py``) on the map-piece presets.

A portcullis raised until its bottom rail clears the 2 m agent, its spikes still hanging to 1.6 m: the corridor's end
behind it is no opening, on either route. A doorway whose threshold stands 0.3 m over the room's floor (a step down
just inside it): its opening lies on the threshold, 0.3 m up. An arcade of five arches between a loggia and the street
in front of it, one piece: the street's two ends and the loggia's back door are its openings, none at the arches. A
trapdoor over nothing in a room's floor, a ladder through it: no opening there.
(docs/entry_exit.md, "A twenty-ninth round of piece kinds".)
"""

from __future__ import annotations

import numpy as np
import pytest

from tests.conftest import round_openings


@pytest.mark.parametrize("preset", ["map_piece", "map_piece_sampling"])
def test_a_portcullis_whose_spikes_hang_under_the_agents_head_closes_the_end(preset: str) -> None:
    (only,) = round_openings("piece_kinds29", "spiked_portcullis_end", preset)
    assert abs(only.position[0]) < 0.05  # the west end; nothing at the portcullis 12 m east


def test_a_doorway_stepping_down_just_inside_opens_on_its_threshold() -> None:
    east = max(round_openings("piece_kinds29", "raised_threshold_step"), key=lambda o: o.position[0])
    assert abs(east.position[1] - 0.3) < 0.01 and abs(east.position[0] - 8.3) < 0.05


def test_an_arcade_onto_the_street_in_the_same_piece_holds_no_opening_at_its_arches() -> None:
    openings = round_openings("piece_kinds29", "arcade_onto_street")
    assert all(abs(o.position[2] + 0.5) > 1.0 for o in openings)  # none on the arcade's face (z -0.5)


def test_a_trapdoor_over_nothing_is_no_opening() -> None:
    openings = round_openings("piece_kinds29", "trapdoor_over_nothing")
    hatch = np.array([5.6, 0.0, 4.8])
    assert min(np.linalg.norm(np.asarray(o.position) - hatch) for o in openings) > 2.0
