"""``walks_in_batch`` (the walk test of the sampling builder's edges and of the mesh_los predicate, its arithmetic in
the C++ extension) on hand-checkable walks: through a row of bollards (the body's slab), across a grating's slots
(the crack rule, :func:`ground_across_crack` itself), over a hole, into a wall, up a step, and far from the origin
(the shifted frame)."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh

from g2s_plugins._raycasting import AgentShape, RayCaster, walks_in_batch
from tests.test_raycasting_walk import AGENT as PIECE_AGENT
from tests.test_raycasting_walk import _grating
from tests.test_sampling_body import bollard_row
from tests.test_sampling_doors import AGENT, box


def walks(caster: RayCaster, starts: list, ends: list, agent: AgentShape, probe_step: float,
          **options) -> tuple[list[bool], list[float]]:
    """The walks' answers and rises (metres, ``inf``: no ground under a probe)."""
    ok, rise = walks_in_batch(caster, np.array(starts, dtype=np.float64), np.array(ends, dtype=np.float64), agent,
                              probe_step, **options)
    assert ok.dtype == bool and rise.shape == ok.shape
    return ok.tolist(), rise.tolist()


def both(caster: RayCaster, starts: list, ends: list, agent: AgentShape, probe_step: float, **options) -> list[bool]:
    """The walks' answers, where every probe found ground on a level floor (rise 0)."""
    ok, rise = walks(caster, starts, ends, agent, probe_step, **options)
    assert rise == [0.0] * len(ok)
    return ok


def test_the_body_slab_stops_a_walk_between_bollards_above_the_step() -> None:
    # tests/test_sampling_body.py's walk between two bollards: the 0.7 m row stands in the slab (0.5-1.95 m above
    # the ground), the 0.45 m row under it; without the body only the lines at 1 m are tested, which pass over both.
    agent = AgentShape.from_config(AGENT)
    walk = ([[-1.0, 0.0, 0.4]], [[1.0, 0.0, 0.4]])
    for height, passes in [(0.7, False), (0.45, True)]:
        caster = RayCaster(bollard_row(height))
        assert both(caster, *walk, agent, 0.25, half_width=0.45, body=True) == [passes]
        # 2 m in 0.25 m steps: 9 probes, each a ray down and one up, the lifted line and its two side copies; then,
        # the walk passing those, a ray from each probe to the next at the climb (8; the bollards stand beside it)
        assert caster.rays_cast == 29
        assert both(caster, *walk, agent, 0.25, half_width=0.45) == [True]


def test_walks_into_a_wall_up_a_step_and_nowhere() -> None:
    # A 16 x 12 m floor with a 2 m wall across x = 3 (z from -6 to 0) and a 0.3 m step up beyond x = -3: a walk
    # through the wall, one beside it (its side lines 0.45 m clear of the wall's end at z = 0), one up the step
    # (0.3 m: under the 0.4 m climb), one off the floor (no ground past x = 8), and one standing still.
    agent = AgentShape.from_config(AGENT)
    mesh = trimesh.util.concatenate([box((-8, -0.2, -6), (8, 0, 6)), box((2.9, 0, -6), (3.1, 2.0, 0)),
                                     box((-8, 0, -6), (-3, 0.3, 6))])
    starts = [[1.0, 0.0, -2.0], [1.0, 0.0, 1.0], [-2.0, 0.0, 2.0], [6.0, 0.0, 3.0], [1.0, 0.0, 4.0]]
    ends = [[5.0, 0.0, -2.0], [5.0, 0.0, 1.0], [-4.0, 0.3, 2.0], [9.0, 0.0, 3.0], [1.0, 0.0, 4.0]]
    ok, rise = walks(RayCaster(mesh), starts, ends, agent, 0.25, half_width=0.45, body=True)
    assert ok == [False, True, True, False, True]
    # the wall stands on the floor (its lifted probes find ground through it), the step rises 0.3 m between two
    # probes, and past x = 8 the probes find none
    assert rise[:2] == [0.0, 0.0] and rise[2] == pytest.approx(0.3) and rise[3:] == [np.inf, 0.0]


@pytest.mark.parametrize("gap", [0.01, 0.02])
def test_a_walk_steps_over_a_grating_slot_not_over_a_hole(gap: float) -> None:
    # tests/test_raycasting_walk.py's walks: along a slot and across the slats (the crack rule finds ground a crack
    # step to both sides), and across the 0.2 m gap between two decks (no ground a step away).
    slot = 0.08 + gap / 2.0
    starts = [[0.5, 0.0, slot], [0.5, 0.0, 0.3], [0.5, 0.0, 0.2]]
    ends = [[5.5, 0.0, slot], [5.5, 0.0, 2.0], [3.0, 0.0, 2.2]]
    assert both(RayCaster(_grating(gap)), starts, ends, PIECE_AGENT, 0.2) == [True, True, True]
    decks = trimesh.util.concatenate([trimesh.creation.box(bounds=[[0.0, -0.05, 0.0], [6.0, 0.0, 1.0]]),
                                      trimesh.creation.box(bounds=[[0.0, -0.05, 1.2], [6.0, 0.0, 2.2]])])
    assert walks(RayCaster(decks), [[3.0, 0.0, 0.3], [3.0, 0.0, 1.1]], [[3.0, 0.0, 1.9], [5.0, 0.0, 1.1]],
                 PIECE_AGENT, 0.1, max_gap=0.5) == ([False, False], [np.inf, np.inf])


def test_each_side_of_a_crack_is_tried_apart_across_bars_as_wide_as_their_slots() -> None:
    # tests/test_raycasting_walk.py's grating of 0.03 m bars and 0.03 m slots (grate47): from a slot's middle a whole
    # crack step (0.05 m) either way lands in the next slots, so the two sides tried as a pair at a step found no
    # floor; each side apart, half a step then a step (CRACK_STEPS), finds a bar on both. A walk along the second
    # slot (z 0.06-0.09) and one across the bars through it both pass, on level ground.
    slot = 0.03 + 0.03 + 0.015
    caster = RayCaster(_grating(0.03, slat=0.03))
    assert both(caster, [[0.5, 0.0, slot], [0.5, 0.0, 0.3]], [[5.5, 0.0, slot], [0.5, 0.0, 2.0]], PIECE_AGENT,
                0.2) == [True, True]


def test_far_from_the_origin_the_rays_start_in_the_shifted_frame() -> None:
    # The bollard row 3,000 km out: the caster's frame is shifted, and the answers are those near the origin.
    agent = AgentShape.from_config(AGENT)
    offset = np.array([3.0e6, 0.0, -2.0e6])
    caster = RayCaster(bollard_row(0.7).apply_translation(offset))
    assert caster.frame.shifted
    starts, ends = [list(offset + [-1.0, 0.0, 0.4]), list(offset + [-1.0, 0.0, 3.0])], [
        list(offset + [1.0, 0.0, 0.4]), list(offset + [-3.0, 0.0, 3.0])]
    assert both(caster, starts, ends, agent, 0.25, half_width=0.45, body=True) == [False, True]
