"""``walk_segments`` over floors with cracks: a grating's slots are stepped over, a hole is not."""
from __future__ import annotations

import numpy as np
import pytest
import trimesh

from g2s_core.config import PRESETS_DIR, load_config
from g2s_plugins._raycasting import AgentShape, RayCaster, walk_segments

AGENT = AgentShape.from_config(load_config(PRESETS_DIR / "map_piece_sampling.yaml").agent)


def _grating(gap: float, slat: float = 0.08, length: float = 6.0, width: float = 2.4) -> trimesh.Trimesh:
    """A deck ``length`` (x) by ``width`` (z) m of slats ``slat`` wide running along x, ``gap`` apart, 0.05 m thick."""
    starts = np.arange(0.0, width - slat + 1e-9, slat + gap)
    return trimesh.util.concatenate([trimesh.creation.box(bounds=[[0.0, -0.05, z], [length, 0.0, z + slat]])
                                     for z in starts])


@pytest.mark.parametrize("gap", [0.005, 0.01, 0.02])
def test_a_walk_along_a_grating_slot_steps_over_it(gap: float) -> None:
    # Every probe of a walk along a slot, and some of a walk across the slats, fell through it: no ground, no edge
    # (eighth round's `catwalk_grating`, ninth round's `grated_room` on the sampling route: 2 cm slots, no sample
    # kept). Ground is looked for again a crack step (r / 8) beside a probe that finds none.
    slot = 0.08 + gap / 2.0  # the middle of the first slot
    starts = np.array([[0.5, 0.0, slot], [0.5, 0.0, 0.3], [0.5, 0.0, 0.2]])
    ends = np.array([[5.5, 0.0, slot], [5.5, 0.0, 2.0], [3.0, 0.0, 2.2]])
    ok, _ = walk_segments(RayCaster(_grating(gap)), starts, ends, AGENT, 0.2)
    assert ok.tolist() == [True, True, True]


def test_a_gap_wider_than_twice_the_crack_step_is_no_floor() -> None:
    # Two decks 0.2 m apart: the walk across the gap finds no ground over it, as before.
    mesh = trimesh.util.concatenate([trimesh.creation.box(bounds=[[0.0, -0.05, 0.0], [6.0, 0.0, 1.0]]),
                                     trimesh.creation.box(bounds=[[0.0, -0.05, 1.2], [6.0, 0.0, 2.2]])])
    starts, ends = np.array([[3.0, 0.0, 0.3], [3.0, 0.0, 1.1]]), np.array([[3.0, 0.0, 1.9], [5.0, 0.0, 1.1]])
    ok, _ = walk_segments(RayCaster(mesh), starts, ends, AGENT, 0.1)
    assert ok.tolist() == [False, False]
