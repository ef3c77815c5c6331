"""The sampling builder's edges sweep the agent's body, from above its step to its head: an obstacle above the step
and lower than half the agent's height (a bollard, a crate, a low wall), under the lifted segment, stops them."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
import trimesh

from g2s_plugins._raycasting import GRAZE_NUDGE, AgentShape, RayCaster, bands_meet_walls, walks_in_batch
from g2s_plugins.graph_builders import sampling
from tests.test_sampling_doors import AGENT, box, rooms_joined
from tests.test_steep_grid import slabs_meet


def bollard_row(height: float) -> trimesh.Trimesh:
    """A 16 x 12 m floor split at x = 0 by a row of bollards 0.2 m square and ``height`` m high, 0.6 m apart (centres
    every 0.8 m along z from 0), running past the floor (no way round)."""
    bollards = [box((-0.1, 0, z - 0.1), (0.1, height, z + 0.1)) for z in np.arange(-8.8, 8.81, 0.8)]
    return trimesh.util.concatenate([box((-8, -0.2, -6), (8, 0, 6)), *bollards])


def test_a_row_of_bollards_above_the_step_splits_the_rooms() -> None:
    # Before the body's slab a 0.7 m row (under the edges' lifted segment at 1 m) joined the two halves; a 0.3 m row
    # is a step the agent climbs (docs/sampling.md, "The agent's body between the edge's lines").
    assert [rooms_joined(bollard_row(height)) for height in (0.7, 0.3)] == [False, True]


def test_the_body_slab_stops_a_walk_between_low_bollards() -> None:
    # Hand-checkable: a walk along x through the middle of the gap at z = 0.4 between the bollards at z = 0 and 0.8;
    # its side lines (z -0.05 and 0.85) pass over the 0.7 m bollards at 1 m, which stand in the slab from 0.5 m (a
    # 0.4 m step and the 0.1 m ground margin) to 1.95 m. A 0.45 m row lies under the slab.
    agent = AgentShape.from_config(AGENT)
    starts, ends = np.array([[-1.0, 0.0, 0.4]]), np.array([[1.0, 0.0, 0.4]])
    assert agent.body == pytest.approx((0.5, 1.95))
    for height, passes in [(0.7, False), (0.45, True)]:
        caster = RayCaster(bollard_row(height))
        assert walks_in_batch(caster, starts, ends, agent, 0.25, half_width=0.45)[0].tolist() == [True]
        assert walks_in_batch(caster, starts, ends, agent, 0.25, half_width=0.45, body=True)[0].tolist() == [passes]
    lifted, along, side = starts + [0.0, 1.0, 0.0], ends - starts, np.array([[0.0, 0.0, 0.45]])
    caster = RayCaster(bollard_row(0.7))
    assert bands_meet_walls(caster, lifted, along, side, 45.0).tolist() == [False]
    assert caster.steep_faces(45.0).slab_grid.meets(lifted, along, side, np.array([[-0.5, 0.95]]), GRAZE_NUDGE).tolist() == [True]


def test_a_face_meets_the_slab_only_inside_it() -> None:
    # The slab: 2 m along x from the origin, 0.45 m either side, 0.5-1.95 m up from the line; a thin upright triangle
    # at (x, z) from y = bottom to top, 0.1 m wide at its foot, narrowing to nothing at its top.
    origin, along, side = np.zeros((1, 3)), np.array([[2.0, 0.0, 0.0]]), np.array([[0.0, 0.0, 0.45]])

    def upright(x: float, z: float, bottom: float = -1.0, top: float = 1.0) -> np.ndarray:
        return np.array([[[x, bottom, z], [x, top, z], [x, bottom, z + 0.1]]])

    # at 0.5 m up the triangle spans z to z + 0.025: z -0.5 stays 0.025 m outside the side
    for corners, meets in [((1.0, 0.0), True), ((1.0, 0.4), True), ((1.0, 0.46), False), ((1.0, -0.5), False),
                           ((2.1, 0.0), False), ((1.0, 0.0, -1.0, 0.49), False), ((1.0, 0.0, -1.0, 0.6), True),
                           ((1.0, 0.0, 1.9, 3.0), True), ((1.0, 0.0, 1.96, 3.0), False)]:
        assert slabs_meet(upright(*corners), origin, along, side, (0.5, 1.95)).tolist() == [meets]
    # A wall across the walk, its corners all outside the slab: met through the slab's edges.
    across = np.array([[[1.0, -5.0, -5.0], [1.0, -5.0, 5.0], [1.0, 10.0, 0.0]]])
    assert slabs_meet(across, origin, along, side, (0.5, 1.95)).tolist() == [True]
    # A walk rising 1 m over its 2 m: at x = 1 its line is 0.5 m up, so a post 0.9 m high stands 0.4 m above it
    # (under the slab) and one 1.1 m high 0.6 m (in it); a beam hanging down to 2.5 m clears the slab's top there
    # (2.45 m), one down to 2.4 m does not. The slab's box (y 0.5 to 2.95) holds each, so the exact test decides.
    rising = np.array([[2.0, 1.0, 0.0]])
    for bottom, top, meets in [(0.0, 0.9, False), (0.0, 1.1, True), (2.5, 4.0, False), (2.4, 4.0, True)]:
        post = upright(1.0, 0.0, bottom, top)
        assert slabs_meet(post, origin, rising, side, (0.5, 1.95)).tolist() == [meets]


@pytest.mark.parametrize("top", [0.6, 0.75, 0.9, 1.3, 1.7])
def test_a_belt_hanging_between_the_wall_rays_keeps_the_agent_its_clearance_away(top: float) -> None:
    # A belt 0.05 m deep and 0.02 m thick whose top hangs ``top`` m over an open floor (round 36's queue hall): the
    # knee (0.5 m), waist (1.0 m) and head (1.95 m) rays pass over or under most of these, so points 0.2 and 0.4 m
    # from it fitted; the body's slab (0.5-1.95 m) is crossed and the rays up it meet the belt. 0.6 m off it fits.
    agent = AgentShape.from_config(AGENT)
    mesh = trimesh.util.concatenate([box((-5, -0.2, -5), (5, 0, 5)), box((-5, top - 0.05, -0.01), (5, top, 0.01))])
    points = np.array([[0.0, 0.0, offset] for offset in (0.2, 0.4, 0.6)])
    rejected = np.zeros(len(points), dtype=np.int8)
    ok = sampling.agent_fits(RayCaster(mesh), points, agent, agent.radius, rejected=rejected)
    assert ok.tolist() == [False, False, True]
    assert [sampling.REJECTED_BY[code] for code in rejected] == ["wall", "wall", "fits"]


def test_a_riser_the_agent_steps_up_crosses_the_body_slab_but_is_no_wall() -> None:
    # A flight of 0.3 m risers on 0.3 m treads: the body's slab from a tread crosses the risers above, and each ray up
    # it that meets one meets a riser the agent steps up (walls_met), so a point on a tread 1 m wide still fits.
    agent = AgentShape.from_config(AGENT)
    treads = [box((0.3 * k, -0.2, -0.5 - 1.0), (10, 0.3 * k, 1.5)) for k in range(8)]
    mesh = trimesh.util.concatenate([box((-5, -0.2, -1.5), (10, 0, 1.5)), *treads])
    caster = RayCaster(mesh)
    points = np.array([[0.3 * k + 0.15, 0.3 * k, 0.0] for k in range(1, 6)])
    assert sampling.curtains_crossed(caster, points, agent, agent.radius, np.array([agent.body])).any()
    assert sampling.agent_fits(caster, points, agent, agent.radius).all()


def test_the_paper_preset_keeps_its_three_wall_rays() -> None:
    # body_walls: false (configs/map_analysis_sampling_paper.yaml): a belt at 0.75 m is not seen, as before.
    agent = replace(AgentShape.from_config(AGENT), body_walls=False)
    mesh = trimesh.util.concatenate([box((-5, -0.2, -5), (5, 0, 5)), box((-5, 0.7, -0.01), (5, 0.75, 0.01))])
    assert sampling.agent_fits(RayCaster(mesh), np.array([[0.0, 0.0, 0.2]]), agent, agent.radius).tolist() == [True]


@pytest.mark.parametrize(("preset", "seen"), [("map_analysis_sampling", True), ("map_analysis_sampling_paper", False)])
def test_each_presets_body_walls_reaches_the_clearance_check(preset: str, seen: bool) -> None:
    # The preset's own params (read from configs/, not written here) through build_sampled_graph: a belt 0.7-0.75 m up
    # across a 6 x 6 m floor, between the knee and waist rays, keeps the main preset's samples 0.45 m or more off it;
    # the paper preset (body_walls: false) stands samples under it as before (review55).
    from g2s_core.config import PRESETS_DIR, load_config

    params = sampling.Params(**{**load_config(PRESETS_DIR / f"{preset}.yaml").graph.params, "method": "grid"})
    mesh = trimesh.util.concatenate([box((-3, -0.2, -3), (3, 0, 3)), box((-3, 0.7, -0.01), (3, 0.75, 0.01))])
    graph = sampling.build_sampled_graph(mesh, params, AgentShape.from_config(AGENT))
    off_belt = np.abs(np.array([graph.nodes[n]["pos"] for n in graph])[:, 2])
    assert len(off_belt) > 10
    assert bool((off_belt < 0.45).any()) is not seen
