"""``walks_in_batch`` over floors with cracks: a grating's slots are stepped over, a hole is not; over thin sills: one over
the climb is not."""
from __future__ import annotations

import numpy as np
import pytest
import trimesh

from g2s_core.config import PRESETS_DIR, load_config
from g2s_plugins._raycasting import (
    CRACK_STEPS, JOINT_CALL_MAX_RAYS, UP, AgentShape, RayCaster, crack_sides, ground_across_crack, walks_in_batch,
)
from tests.conftest import benchmark

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
    ok, _ = walks_in_batch(RayCaster(_grating(gap)), starts, ends, AGENT, 0.2)
    assert ok.tolist() == [True, True, True]


def test_a_gap_wider_than_twice_the_crack_step_is_no_floor() -> None:
    # Two decks 0.2 m apart: the walk across the gap finds no ground over it, as before.
    mesh = trimesh.util.concatenate([trimesh.creation.box(bounds=[[0.0, -0.05, 0.0], [6.0, 0.0, 1.0]]),
                                     trimesh.creation.box(bounds=[[0.0, -0.05, 1.2], [6.0, 0.0, 2.2]])])
    starts, ends = np.array([[3.0, 0.0, 0.3], [3.0, 0.0, 1.1]]), np.array([[3.0, 0.0, 1.9], [5.0, 0.0, 1.1]])
    ok, _ = walks_in_batch(RayCaster(mesh), starts, ends, AGENT, 0.1)
    assert ok.tolist() == [False, False]


def test_the_crack_rule_needs_ground_on_both_sides_along_one_of_its_sides() -> None:
    # ground_across_crack is the one crack rule of walks_in_batch and of entry_exit's search for the floor's end.
    # Probes 0.1 m over: the middle of a 2 cm slot along x (slats across it along z only); 0.03 m past the deck's
    # end, over a slat (ground on one side along x, none along z); the 0.2 m gap between two decks (none a step away).
    caster = RayCaster(_grating(0.02))
    two = trimesh.util.concatenate([trimesh.creation.box(bounds=[[0.0, -0.05, 0.0], [6.0, 0.0, 1.0]]),
                                    trimesh.creation.box(bounds=[[0.0, -0.05, 1.2], [6.0, 0.0, 2.2]])])
    step = AGENT.radius / 8.0
    slot = [2.0, 0.1, 0.09]

    def walkable(faces: np.ndarray) -> np.ndarray:
        return caster.walkable_faces(faces, AGENT.max_slope_deg)

    along_x, along_z = np.array([step, 0.0, 0.0]), np.array([0.0, 0.0, step])
    on, distance = ground_across_crack(caster, np.array([slot, slot]), -UP, [along_x], 0.5, walkable)
    assert on.tolist() == [False, False] and np.isinf(distance).all()  # both sides in the slot: no ground found
    on, distance = ground_across_crack(caster, np.array([slot, [6.03, 0.1, 0.54]]), -UP, [along_x, along_z], 0.5,
                                       walkable)
    assert on.tolist() == [True, False] and distance[0] == pytest.approx(0.1) and distance[1] == np.inf
    on, _ = ground_across_crack(RayCaster(two), np.array([[3.0, 0.1, 1.1]]), -UP, [along_z], 0.5,
                                lambda faces: faces >= 0)
    assert on.tolist() == [False]


def _hole_across(gap: float) -> trimesh.Trimesh:
    """A walkway 6 m (x) by 2.2 m + ``gap`` (z), 0.05 m thick, cut across by a hole ``gap`` wide from z 1.0."""
    return trimesh.util.concatenate([trimesh.creation.box(bounds=[[0.0, -0.05, 0.0], [6.0, 0.0, 1.0]]),
                                     trimesh.creation.box(bounds=[[0.0, -0.05, 1.0 + gap], [6.0, 0.0, 2.2 + gap]])])


def test_the_sampling_route_tries_each_side_of_a_crack_apart() -> None:
    # Slots as wide as the bars (0.03 m, a period of 0.06 m, just over the crack step r / 8 = 0.05 m): a step either
    # way from a slot's middle lands in the next slots on both sides, so the pair at a step found no floor and a walk
    # along the slot, or across the bars through it, was no walk (docs/entry_exit.md, "The grating's end on the
    # sampling route"). Each side tried apart, half a step then a step (CRACK_STEPS), finds a bar on both sides.
    slot = 0.03 + 0.03 + 0.015  # the middle of the second slot, z 0.06-0.09
    starts, ends = np.array([[0.5, 0.0, slot], [0.5, 0.0, 0.3]]), np.array([[5.5, 0.0, slot], [0.5, 0.0, 2.0]])
    ok, _ = walks_in_batch(RayCaster(_grating(0.03, slat=0.03)), starts, ends, AGENT, 0.2)
    assert ok.tolist() == [True, True]


def test_the_crack_rule_answers_alike_in_one_call_and_ray_by_ray() -> None:
    # A batch of at most JOINT_CALL_MAX_RAYS rays for every side, step and direction casts them all in one call (the
    # walk test's small batches), a larger one only the rays the rule needs: the same answers. Bars and slots 0.03 m:
    # a probe 0.1 m over a slot's middle stands on the bars 0.1 m below (half a step along z, a bar either side);
    # one 0.1 m over nothing, 0.2 m past either end of the deck, finds ground within a step on one side at most.
    caster = RayCaster(_grating(0.03, slat=0.03))
    slots = [[2.0, 0.1, 0.03 + 0.06 * k + 0.015] for k in range(10)]
    probes = np.array(slots + [[6.2, 0.1, 1.0], [-0.2, 0.1, 0.5]])
    known = [True] * 10 + [False, False]

    def rule(points: np.ndarray) -> tuple[np.ndarray, np.ndarray, int]:
        before = caster.rays_cast
        on, distance = ground_across_crack(caster, points, -UP, crack_sides(AGENT), 0.5,
                                           lambda faces: caster.walkable_faces(faces, AGENT.max_slope_deg), CRACK_STEPS)
        return on, distance, caster.rays_cast - before

    rays_each = 2 * len(crack_sides(AGENT)) * len(CRACK_STEPS)
    on, distance, cast = rule(probes)
    assert on.tolist() == known and cast < rays_each * len(probes)  # counted: the rays the rule needs
    assert distance[:10] == pytest.approx(np.full(10, 0.1)) and np.isinf(distance[10:]).all()
    copies = JOINT_CALL_MAX_RAYS // (rays_each * len(probes)) + 1
    many_on, many_distance, many_cast = rule(np.tile(probes, (copies, 1)))
    assert many_on.tolist() == known * copies and many_cast == cast * copies  # the rays needed, ray by ray
    assert many_distance.tolist() == np.tile(distance, copies).tolist()


@pytest.mark.parametrize("gap, floor", [(0.04, True), (0.11, False), (0.15, False)])
def test_a_hole_across_a_walkway_wider_than_two_crack_steps_stays_a_hole(gap: float, floor: bool) -> None:
    # The rule's width limit: a probe in a gap stands on floor only where floor lies within a step (r / 8 = 0.05 m)
    # of it on both sides. Every probe in a gap narrower than a step does; in one wider than two steps (r / 4 =
    # 0.1 m), 0.15 m where a foot goes through, none does, wherever in it (every 7 mm or so across, and a walk over it
    # probed every 2 cm): it stays a hole.
    caster = RayCaster(_hole_across(gap))
    probes = np.stack([np.full(15, 3.0), np.full(15, 0.1), 1.0 + np.linspace(0.002, gap - 0.002, 15)], axis=1)
    on, _ = ground_across_crack(caster, probes, -UP, [np.array([0.0, 0.0, AGENT.radius / 8.0])], 0.5,
                                lambda faces: faces >= 0, CRACK_STEPS)
    assert on.all() if floor else not on.any()
    ok, _ = walks_in_batch(caster, np.array([[3.0, 0.0, 0.3]]), np.array([[3.0, 0.0, 1.9 + gap]]), AGENT, 0.02)
    assert ok.tolist() == [floor]


@pytest.mark.parametrize("yaw", [0.0, 22.0, 45.0])
@pytest.mark.parametrize(("height", "crossed"), [(0.45, 0), (0.35, 26)])
def test_a_thin_sill_over_the_climb_is_never_crossed_and_one_under_it_always(yaw: float, height: float,
                                                                             crossed: int) -> None:
    # A sill 0.12 m thick, under the 0.25 m probe step, stopped a walk only where a probe landed on it or, from
    # 0.5 m up, through the body's slab: a 0.45 m sill was crossed by 14 of the 26 walks at 0 degrees (round 38's
    # coaming deck joined cabins behind coamings of 0.41-0.49 m). A ray from each probe to the next at the climb
    # over the lower one's ground meets it now; a 0.35 m one stays under that ray at every offset.
    assert benchmark("thin_sills").crossed("map_analysis_sampling", "sill", height, 0.12, yaw) == crossed


def test_a_wide_agent_walks_up_a_stair_whose_probe_step_spans_two_risers() -> None:
    # An agent of radius 1.0 m probes every 0.5 m, so on a 45-degree stair of 0.25 m risers two probes differ by
    # two risers, which its 45-degree slope allows; a ray at the climb over the lower probe met the upper riser and
    # stopped 24 of these 26 walks (review57 MED 3). The ray starts at the higher probe's ground where that is higher.
    agent = AgentShape.from_config(load_config(PRESETS_DIR / "map_analysis_sampling.yaml").agent.model_copy(
        update={"radius": 1.0}))
    steps = [trimesh.creation.box(bounds=[[0.25 * i, -0.5, -4.0], [4.0, 0.25 * (i + 1), 4.0]]) for i in range(6)]
    caster = RayCaster(trimesh.util.concatenate([trimesh.creation.box(bounds=[[-4.0, -0.5, -4.0], [4.0, 0.0, 4.0]]),
                                                 *steps]))
    starts = np.zeros((26, 3))
    starts[:, 0] = -1.0 + 0.01 * np.arange(26)
    ends = starts + [3.0, 1.5, 0.0]
    ok, _ = walks_in_batch(caster, starts, ends, agent, 0.5, half_width=0.9, body=True)
    assert ok.all()
