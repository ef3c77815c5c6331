"""The sampling builder's agent checks on stairs and ledge tops (docs/sampling.md, "Stairs and narrow ledge tops" and
"Steep flights and ledge tops fixed").

Main's ledge rule before stairs49 (one probe at the clearance, ground within max(climb, slope x clearance) + 0.1 m)
failed the first two; the ledge rule of branch ``ledge48`` (commit 88d8b51: two probes, the walk test's rise between
neighbours) passed them and failed the last, whose knee-high wall rays met the riser two steps up; with the wall
test's riser rule (:func:`g2s_plugins.graph_builders.sampling.walls_met`) all pass."""

from __future__ import annotations

import math

import numpy as np
import pytest
import trimesh

from g2s_plugins._raycasting import AgentShape, RayCaster
from g2s_plugins.graph_builders import sampling
from tests.conftest import benchmark, box

cases = benchmark("ledge_cases")
AGENT = AgentShape.from_config(cases.AGENT)


def top_samples(depth: float, height: float, back: str) -> tuple[int, bool]:
    """How many samples of the preset's graph (grid) stand on :func:`ledge_cases.ledge_level`'s top, and whether one
    of them is joined to the floor's middle."""
    mesh, middles, plan = cases.ledge_level(depth, height, back)
    graph = sampling.build_sampled_graph(mesh, sampling.Params(method="grid"), AGENT)
    pos = np.array([graph.nodes[n]["pos"] for n in sorted(graph.nodes)])
    over = cases.on_plan(pos, np.eye(4), plan, height - 0.05, height + 0.05)
    return int(over.sum()), bool(over.any() and cases.top_joined(graph, pos, over, middles[0]))


def test_a_45_degree_flight_has_ground_all_round_its_treads() -> None:
    # Risers 0.30 m, treads 0.30 m, 3 m wide: at the front of every tread (x 0.05 m into it, where no riser stands
    # within 0.5 m over the knee) the probes 0.25 m and 0.5 m up or down the flight find one riser each between
    # neighbours, 0.30 m, within the climb; main's rule before stairs49 read the two risers within 0.5 m, 0.6 m, as a
    # ledge.
    mesh, _, _ = cases.flight_level(0.30, 0.30, 3.0)
    points = np.array([[0.30 * k + 0.05, 0.30 * (k + 1), 0.0] for k in range(1, 8)])
    rejected = np.zeros(len(points), dtype=np.int8)
    fits = sampling.agent_fits(RayCaster(mesh), points, AGENT, AGENT.radius, rejected=rejected)
    assert fits.all(), rejected


@pytest.mark.parametrize("riser, tread", [(0.30, 0.30), (0.35, 0.25), (0.25, 0.25)])
def test_every_point_of_a_steep_flights_treads_fits(riser: float, tread: float) -> None:
    # Points every 0.05 m along the middle of each tread of flights 3 m wide: the knee-high wall rays (0.5 m up)
    # meet the riser two steps up within the clearance on the back of every tread, a step over the tread before it,
    # not a wall (the ledge rule of 88d8b51 alone turned them away: docs/sampling.md, "Stairs and narrow ledge tops").
    mesh, _, _ = cases.flight_level(riser, tread, 3.0)
    along = np.arange(0.025, tread, 0.05)
    points = np.array([[tread * k + x, riser * (k + 1), 0.0] for k in range(2, 7) for x in along])
    rejected = np.zeros(len(points), dtype=np.int8)
    fits = sampling.agent_fits(RayCaster(mesh), points, AGENT, AGENT.radius, rejected=rejected)
    assert fits.all(), rejected


def _knee_ray_meets_a_wall(*solids: trimesh.Trimesh) -> bool:
    """Whether :func:`sampling.walls_met` reads a wall where the knee-high ray from the origin along +x meets the
    first face (a floor 8 m square whose top is y = 0, with ``solids`` on it)."""
    mesh = trimesh.util.concatenate([box(-4.0, 4.0, -0.2, 0.0, -4.0, 4.0), *solids])
    caster = RayCaster(mesh)
    hits = caster.first_hits(np.array([[0.0, AGENT.body[0], 0.0]]), np.array([1.0, 0.0, 0.0]))
    assert hits.distance[0] < 0.5
    return bool(sampling.walls_met(caster, hits, AGENT, 0.5)[0])


def test_a_riser_onto_ground_within_a_step_is_no_wall_and_a_wall_on_it_is() -> None:
    # Two steps of 0.3 m (0.1 and 0.4 m from the point): the knee ray (0.5 m) meets the second riser, a step of 0.3 m
    # from the first tread to the second; 0.35 m, a step too; 0.45 m, over the climb, a wall.
    first = box(0.1, 2.0, 0.0, 0.3, -1.0, 1.0)
    for top, wall in ((0.6, False), (0.65, False), (0.75, True)):
        assert _knee_ray_meets_a_wall(first, box(0.4, 2.0, 0.3, top, -1.0, 1.0)) == wall
    # A wall on the floor, a wall on the first tread, and a fence 2 cm thick and 0.5 m high on it (its top 0.8 m up)
    # are walls.
    assert _knee_ray_meets_a_wall(box(0.4, 0.6, 0.0, 3.0, -1.0, 1.0))
    assert _knee_ray_meets_a_wall(first, box(0.4, 0.6, 0.3, 3.0, -1.0, 1.0))
    assert _knee_ray_meets_a_wall(first, box(0.4, 0.42, 0.3, 0.8, -1.0, 1.0))
    # A rock face of 60 degrees from the first tread up to 0.6 m: under the hit lies the face itself, a wall.
    rock = trimesh.convex.convex_hull([[x, y, z] for x, y in ((0.2, 0.3), (0.2 + 0.3 / math.tan(math.radians(60.0)), 0.6),
                                                               (2.0, 0.6), (2.0, 0.3)) for z in (-1.0, 1.0)])
    assert _knee_ray_meets_a_wall(first, rock)


def test_a_bench_narrower_than_the_agent_holds_no_sample() -> None:
    # A bench 0.5 m deep, 0.45 m high against a wall (the drained pools' spa): every point on it has the bench's
    # edge, 0.45 m down, within 0.25 m, over the climb; main's rule took the floor 0.45 m down as ground.
    assert top_samples(0.5, 0.45, "wall") == (0, False)
    assert top_samples(0.3, 0.45, "none") == (0, False)  # a low wall's top


def test_a_step_the_agent_cannot_climb_stays_apart_and_one_it_can_is_floor() -> None:
    # A platform 4 x 4 m: 0.45 m high (0.05 m over the climb) its top is an area of its own; 0.3 m high, floor.
    on, joined = top_samples(4.0, 0.45, "none")
    assert on > 0 and not joined
    on, joined = top_samples(4.0, 0.3, "none")
    assert on > 0 and joined


def test_a_45_degree_flight_turned_22_degrees_joins_its_floors() -> None:
    # Joined on main's rule by samples the passage stage adds; the rule of 88d8b51 let more grid candidates fit, left
    # two stranded, and the points it would add failed the knee-high wall rays, which meet the riser two steps up:
    # apart (docs/sampling.md, "Stairs and narrow ledge tops").
    mesh, middles, _ = cases.flight_level(0.30, 0.30, 2.0)
    turn = cases._turn(22.0)
    mesh.apply_transform(turn)
    graph = sampling.build_sampled_graph(mesh, sampling.Params(method="grid"), AGENT)
    assert cases.joined(graph, middles @ turn[:3, :3].T)
