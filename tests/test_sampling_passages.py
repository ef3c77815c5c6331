"""Sampling: passages a little wider than the agent that the grid's lines miss are joined, narrower ones are not.

Levels from ``benchmarks/narrow_flights.py`` (two floors joined by one passage ``1 + extra`` m wide, the presets'
agent of radius 0.5 m, so the band its centre may stand in is ``extra`` m wide); the distances and directions in
the hand-built tests are checked by hand.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import trimesh

from g2s_core import api
from g2s_core.config import AgentConfig
from g2s_plugins._raycasting import AgentShape, RayCaster
from g2s_plugins.graph_builders import sampling
from tests.conftest import benchmark, box

AGENT = AgentShape.from_config(AgentConfig(radius=0.5))


def _joined(extra: float, offset: float, profile: str, sides: str, yaw: float, shape: str = "straight") -> tuple[bool, dict]:
    flights = benchmark("narrow_flights")
    mesh, middles, _ = flights.passage_level(extra, offset, profile, shape, sides)
    turn = flights._turn(yaw)
    mesh.apply_transform(turn)
    graph = sampling.build_sampled_graph(mesh, sampling.Params(method="grid"), AGENT)
    return flights.joined(graph, middles @ turn[:3, :3].T), graph.graph["sampling_stats"]


@pytest.mark.parametrize(
    ("extra", "offset", "profile", "sides", "yaw", "shape"),
    [
        (0.4, 0.5, "flat", "walls", 0.0, "straight"),  # a corridor 1.4 m wide whose band (z from 0.3 to 0.7) no grid row crosses
        (0.4, 0.5, "stepped", "drops", 0.0, "straight"),  # the tavern's cellar flight: 1.4 m wide between drops
        (0.05, 0.0, "flat", "walls", 22.0, "straight"),  # 5 cm to spare, turned off the grid's axes
        (0.2, 0.0, "flat", "walls", 0.0, "turning"),  # an L: the corner where the two legs' bands cross
    ],
)
def test_a_passage_the_grid_misses_is_joined(extra, offset, profile, sides, yaw, shape):
    joined, stats = _joined(extra, offset, profile, sides, yaw, shape)
    assert stats["samples_added"] > 0
    assert joined


@pytest.mark.parametrize(("sides", "yaw"), [("walls", 22.0), ("drops", 22.0), ("walls", 0.0)])
def test_a_passage_narrower_than_the_agent_stays_apart(sides, yaw):
    # 0.95 m: the 8 compass rays of the agent checks let a point stand 0.46 m from a wall 22 degrees off them, so a
    # moved point could have fitted there; the added points need the whole clearance
    assert not _joined(-0.05, 0.25, "flat", sides, yaw)[0]


def test_nearest_wall_is_the_distance_to_the_triangle_not_along_the_ray():
    # a wall face on x = 0.3 (a block from x = 0.3 to 1.3) turned 22 degrees; the point 0.4 m from it
    wall = box(0.3, 1.3, 0.0, 3.0, -5.0, 5.0)
    floor = box(-5.0, 5.0, -0.2, 0.0, -5.0, 5.0)
    mesh = trimesh.util.concatenate([floor, wall])
    angle = math.radians(22.0)
    mesh.apply_transform(trimesh.transformations.rotation_matrix(angle, (0.0, 1.0, 0.0)))
    point = np.array([[-0.1, 0.0, 0.0]]) @ trimesh.transformations.rotation_matrix(angle, (0.0, 1.0, 0.0))[:3, :3].T
    distance, away = sampling.nearest_wall(RayCaster(mesh), point, AGENT, 0.5)
    assert distance[0] == pytest.approx(0.4, abs=1e-6)  # along the +x-most compass ray it reads 0.4 / cos 22 = 0.431
    assert away[0] == pytest.approx([-math.cos(angle), 0.0, math.sin(angle)], abs=1e-6)


def test_ledge_room_finds_the_edge_along_each_direction():
    # a slab whose edge is x = 0.2; from the origin the ledge lies 0.2 m along +x, 0.2 / cos 45 = 0.283 m along the
    # diagonals next to it, found to the halvings' step (0.5 / 64 m), and beyond the clearance elsewhere
    mesh = box(-5.0, 0.2, -0.2, 0.0, -5.0, 5.0)
    room = sampling.ledge_room(RayCaster(mesh), np.zeros((1, 3)), AGENT, 0.5)[0]
    step = 0.5 / 2**sampling.LEDGE_HALVINGS
    assert room[0] == pytest.approx(0.2, abs=step)
    quarter = sampling.GROUND_DIRECTIONS // 8
    assert room[quarter] == pytest.approx(0.2 * math.sqrt(2.0), abs=step)
    assert room[sampling.GROUND_DIRECTIONS // 2] == 0.5  # -x: floor all the way


def test_ledge_room_in_batches_on_two_threads_is_that_of_one_call(monkeypatch: pytest.MonkeyPatch):
    # points on a 0.13 m lattice round the mouth of a flight 1.2 m wide between drops, turned 22 degrees: many of
    # them near a ledge, so the halvings run; batches of 7 points taken by two threads in any order
    mesh, _, _ = benchmark("narrow_flights").passage_level(0.2, 0.0, "flat", "straight", "drops")
    mesh.apply_transform(trimesh.transformations.rotation_matrix(math.radians(22.0), (0.0, 1.0, 0.0)))
    x, z = np.meshgrid(np.arange(-3.0, 3.0, 0.13), np.arange(-2.0, 2.0, 0.13))
    points = np.column_stack([x.ravel(), np.zeros(x.size), z.ravel()])

    def room(threads: int, batch: int) -> tuple[np.ndarray, int]:
        monkeypatch.setattr(sampling, "RAY_THREADS", threads)
        monkeypatch.setattr(sampling, "MAX_ROOM_BATCH", batch)
        caster = RayCaster(mesh)
        return sampling.ledge_room(caster, points, AGENT, 0.5), caster.rays_cast

    whole, rays = room(1, len(points))
    assert 0 < np.count_nonzero(whole < 0.5) < whole.size  # ledges found by halving, and open directions
    for threads in (2, 1):
        batched, batched_rays = room(threads, 7)
        np.testing.assert_array_equal(batched, whole)
        assert batched_rays == rays


@pytest.mark.parametrize("offset", [0.0, 0.3])
def test_added_samples_do_not_cross_a_slot_narrower_than_the_agent(offset):
    # benchmarks/post_slots.py's 0.95 m slots beside a 0.2 m post, turned 22 degrees: the samples added at the slots'
    # mouths (area 0) are walked with the whole clearance, so a crossing 1-4 degrees off square that a band of
    # DISK_SHARE x clearance (0.45 m each side) fits through the slot is refused
    slots = benchmark("post_slots")
    mesh, matrix = slots._placed(slots.post_level(0.95, 0.2), 22.0, offset)
    graph = sampling.build_sampled_graph(mesh, sampling.Params(method="grid"), AGENT)
    ends = (np.array([[0.0, 0.0, -3.0, 1.0], [0.0, 0.0, 3.0, 1.0]]) @ matrix.T)[:, :3]
    assert graph.graph["sampling_stats"]["samples_added"] > 0
    assert not slots.joined(*slots._arrays(graph), ends)


def _added_pair_walkable(mesh: trimesh.Trimesh, added: tuple[float, float], other: tuple[float, float]) -> bool:
    """Whether the sampling builder's edge rule joins a sample added in a passage at (x, z) ``added`` to a grid
    sample at ``other`` (both on the ground, y = 0)."""
    caster = RayCaster(mesh)
    floors = sampling.OpenFloors(caster, AGENT, min_inradius=0.5)
    samples = np.array([[added[0], 0.0, added[1]], [other[0], 0.0, other[1]]])
    return bool(sampling._walkable_pairs_of(
        caster, AGENT, floors, floors.certain_offset(sampling.GROUND_MARGIN, None), samples, np.full(2, -1),
        np.array([True, False]), np.array([[0, 1]]), 0.25, 0.5,
    )[0])


def test_an_added_sample_joins_past_a_corner_on_one_side_as_grid_samples_do():
    # a block x -3..0, z 0..3 (corner at the origin); the added sample stands 0.51 m off its side, the other in
    # front of it; the way between passes the corner 0.633 / 1.3014 = 0.486 m off, which DISK_SHARE's 0.45 m band
    # clears and the whole clearance's band on the way does not: moved 0.05 m away from the corner it clears
    # 0.536 m (the lecture hall's aisle ends, docs/sampling.md "A miss it brings")
    mesh = trimesh.util.concatenate([box(-5.0, 5.0, -0.2, 0.0, -5.0, 5.0), box(-3.0, 0.0, 0.0, 3.0, 0.0, 3.0)])
    assert _added_pair_walkable(mesh, (0.51, 0.5), (0.45, -0.8))


@pytest.mark.parametrize("slot", [0.95, 0.99])
def test_an_added_sample_crosses_no_slot_narrower_than_the_agent_moved_either_way(slot):
    # a 0.2 m wall along z = 0 with a slot `slot` m wide about x = 0, crossed 1.7 degrees off square and 0.03 m off
    # its middle: a band as wide as the agent (1 m) fits through it neither on the way nor 0.05 m to either side
    half = slot / 2
    mesh = trimesh.util.concatenate([
        box(-5.0, 5.0, -0.2, 0.0, -5.0, 5.0), box(-5.0, -half, 0.0, 3.0, -0.1, 0.1), box(half, 5.0, 0.0, 3.0, -0.1, 0.1),
    ])
    assert not _added_pair_walkable(mesh, (0.06, -1.0), (0.0, 1.0))
    assert _added_pair_walkable(mesh, (0.06, -1.0), (0.06, -2.0))  # the same sample walks on its own side


def test_the_lecture_halls_sampled_heat_map_meets_its_target():
    # sample:lecture_hall's third aisle has ends 1.7 m wide that no grid line crosses inside the band, so samples
    # are added there; with only the band on the way their edges past the end panels' corners were refused, and
    # the heat map stopped at rho 0.886 with a warning (112 structure nodes); moved past the corner, 0.9001 (83)
    result = api.run("sample:lecture_hall", "map_analysis_sampling")
    assert result.graph.graph["sampling_stats"]["samples_added"] > 0
    assert not [w for w in result.warnings if "Spearman rho" in w]
