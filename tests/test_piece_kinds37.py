"""Pieces of the thirty-seventh round (``benchmarks/piece_kinds37.py``) on the map-piece presets.

A corridor whose floor runs past its walls' ends in a V (a prow, each half cut 30 degrees off square) was found as two
openings, one per half: parts facing 60 degrees apart were never joined. Two parts turned apart by less than a square,
meeting end to end, are now one opening when the way's sides run in square to the chord between their far ends. A
squeeze stile (a slot narrower than the agent at every height) is no opening; a doorway whose sill is a room floor
raised over the climb, reached by a step stone, is one at the raised floor's height; a tapered doorway's width is the
clear width the agent's whole height passes through, read under its lintel at the head-room rays' height, not its
width at the floor (docs/entry_exit.md, "A thirty-seventh round of piece kinds").
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from g2s_core.config import PRESETS_DIR, load_config
from g2s_core.model import Opening
from g2s_plugins._raycasting import RayCaster
from g2s_plugins.samples import pieces
from g2s_plugins.terminals import entry_exit
from tests.conftest import benchmark, box, piece_openings, round_openings

PRESETS = ["map_piece", "map_piece_sampling"]


@pytest.mark.parametrize("preset", PRESETS)
def test_a_squeeze_stile_narrower_than_the_agent_is_no_opening(preset: str) -> None:
    round_openings("piece_kinds37", "squeeze_stile_yard", preset)  # the two gateways, one each, nothing else


@pytest.mark.parametrize("preset", PRESETS)
def test_a_doorway_off_a_floor_raised_over_the_climb_is_at_that_floor(preset: str) -> None:
    openings = round_openings("piece_kinds37", "genkan_step_stone", preset)
    assert sorted(round(o.position[1], 2) for o in openings) == [0.0, 0.45]


@pytest.mark.parametrize("preset", PRESETS)
def test_a_tapered_doorways_width_is_read_at_the_agents_head(preset: str) -> None:
    kinds = benchmark("piece_kinds37")
    level = kinds.tapered_doorway()
    s = entry_exit._settings(entry_exit.Params(), load_config(PRESETS_DIR / f"{preset}.yaml").agent)
    foot, head, lintel = 1.4, 1.0, 2.4  # the kind's defaults
    at_head = foot - (foot - head) * s.head / lintel  # the jambs' clear width at the head-room rays' height
    east = [o for o in piece_openings(level, preset) if o.position[0] > 4.0]
    assert len(east) == 1
    assert abs(east[0].width - at_head) < 0.05  # 1.07 m, not the 1.4 m at the floor


def _half(a: tuple[float, float], b: tuple[float, float], heading: tuple[float, float]) -> Opening:
    """An opening at the floor from (x, z) ``a`` to ``b``, facing the plan direction ``heading``."""
    p0, p1 = np.array([a[0], 0.0, a[1]]), np.array([b[0], 0.0, b[1]])
    h = np.array([heading[0], 0.0, heading[1]]) / math.hypot(*heading)
    return Opening(tuple((p0 + p1) / 2), tuple(h), float(np.linalg.norm(p1 - p0)), tuple(p0), tuple(p1))


def test_parts_turned_apart_meeting_end_to_end_are_one_opening_when_the_way_is_one() -> None:
    tip = 1.2 * math.tan(math.radians(30.0))  # the prow's halves, 60 degrees apart, meeting 0.03 m apart at its tip
    north = _half((tip, 1.19), (0.0, 2.4), (math.cos(math.radians(30.0)), math.sin(math.radians(30.0))))
    south = _half((0.0, 0.0), (tip, 1.22), (math.cos(math.radians(30.0)), -math.sin(math.radians(30.0))))
    asked = []

    def one_way(i: int, j: int, a: np.ndarray, b: np.ndarray, out: np.ndarray) -> bool:
        asked.append((i, j, sorted(round(v, 2) for v in (a[2], b[2]))))
        return True

    def repeated(openings: list[Opening], way=one_way, meet: float = 0.1) -> list[int]:
        return list(entry_exit._repeated(openings, 0.4, 30.0, 0.4, lambda a, b: True, 0.05, way, meet))

    assert repeated([south, north]) == [-1, 0]
    assert asked == [(0, 1, [0.0, 2.4])]  # the far ends, at the walls' ends
    assert repeated([south, north], lambda *_: False) == [-1, -1]  # not one way (a plaza's corner): two
    assert repeated([south, north], meet=0.01) == [-1, -1]  # not meeting: two
    assert list(entry_exit._repeated([south, north], 0.4, 30.0, 0.4)) == [-1, -1]  # asked without the rule: two
    east, north_side = _half((8.0, 0.0), (8.0, 8.0), (1.0, 0.0)), _half((8.0, 8.0), (0.0, 8.0), (0.0, 1.0))
    assert repeated([east, north_side]) == [-1, -1]  # a square corner: never asked
    assert len(asked) == 1


def test_a_ways_sides_run_square_to_its_chord_in_a_corridor_not_at_a_plazas_corner() -> None:
    s = entry_exit._settings(entry_exit.Params(), load_config(PRESETS_DIR / "map_piece.yaml").agent)
    floor = box(-10.0, 10.0, -0.2, 0.0, -10.0, 10.0)
    corridor = floor + box(-10.0, 0.0, 0.0, 3.0, -0.3, 0.0) + box(-10.0, 0.0, 0.0, 3.0, 2.4, 2.7)
    a, b, east = np.array([0.0, 0.0, 0.0]), np.array([0.0, 0.0, 2.4]), np.array([1.0, 0.0, 0.0])
    assert entry_exit._sides_square(a, b, east, RayCaster(corridor), s, 0.1)
    assert not entry_exit._sides_square(a, b, east, RayCaster(floor), s, 0.1)  # no sides: an open platform's end
    plaza = floor + box(-8.3, 0.0, 0.0, 3.0, -8.3, -8.0) + box(-8.3, -8.0, 0.0, 3.0, -8.3, 0.0)  # walls south, west
    corner = np.array([-8.0, 0.0, 0.0]), np.array([0.0, 0.0, -8.0])
    assert not entry_exit._sides_square(*corner, np.array([1.0, 0.0, 1.0]), RayCaster(plaza), s, 0.1)


@pytest.mark.parametrize(("preset", "yaw"), [("map_piece", 0.0), ("map_piece", 45.0), ("map_piece_sampling", 0.0)])
def test_a_prow_end_is_one_opening_between_the_walls_ends(preset: str, yaw: float) -> None:
    level = benchmark("piece_kinds37").prow_end_corridor()
    level = pieces.turned(level, yaw) if yaw else level
    recalled, missed, correct, other, width_error = benchmark("piece_kinds10").score(
        level, piece_openings(level, preset), one_to_one=True)
    assert (recalled, missed, correct, other) == (2, 0, 2, 0)
    assert width_error < 0.05


def test_a_plazas_two_open_sides_meeting_at_its_corner_stay_two() -> None:
    round_openings("piece_kinds34", "open_corner_plaza", "map_piece")
