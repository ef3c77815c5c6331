"""``entry_exit`` on the sampling route: openings on the surface a sampled graph covers (no navmesh).

docs/entry_exit.md, "Openings on the sampling route (3 December 2026)".
"""

from __future__ import annotations

import math
from dataclasses import replace

import networkx as nx
import numpy as np
import pytest
import trimesh

from g2s_core.config import load_config
from g2s_core.errors import PluginError
from g2s_core.model import RunContext
from g2s_plugins.graph_builders import sampling
from g2s_plugins.samples import levels as samples
from g2s_plugins.samples import pieces
from g2s_plugins.terminals import entry_exit
from g2s_plugins.terminals._boundary import BoundaryLoop, boundary_loops, sample_loops
from g2s_plugins.terminals._sampled_surface import sampled_surface
from tests.conftest import benchmark

CONFIG = load_config("configs/map_piece_sampling.yaml")


def _openings(level) -> tuple[np.ndarray, np.ndarray, nx.Graph, tuple]:
    """(found midpoints, known midpoints, the graph, the terminals) of ``level`` on the preset's sampling route."""
    ctx = RunContext(mesh=level.mesh, agent=CONFIG.agent, centre=np.asarray(level.mesh.bounds).mean(axis=0))
    graph = sampling.g2s_build_graph(mesh=level.mesh, params=sampling.Params(), context=ctx)
    before = graph.number_of_nodes()
    terminals = entry_exit.g2s_select_terminals(graph=graph, params=entry_exit.Params(), context=ctx)
    assert graph.number_of_nodes() == before + len(terminals.nodes)
    found = np.array([o.position for o in terminals.openings], dtype=np.float64).reshape(-1, 3)
    known = np.array([o.position for o in level.openings], dtype=np.float64).reshape(-1, 3)
    return found, known, graph, terminals


def _grid(side: int, holes: set[tuple[int, int]] = frozenset()) -> nx.Graph:
    """A ``side`` x ``side`` grid of samples 1 m apart on y = 0, joined to their 8 neighbours, ``holes`` left out."""
    graph = nx.Graph()
    cells = [(i, j) for i in range(side) for j in range(side) if (i, j) not in holes]
    for i, j in cells:
        graph.add_node((i, j), pos=(float(i), 0.0, float(j)), normal=(0.0, 1.0, 0.0))
    for i, j in cells:
        for di, dj in ((1, 0), (0, 1), (1, 1), (1, -1)):
            if (i + di, j + dj) in graph:
                graph.add_edge((i, j), (i + di, j + dj))
    return graph


def test_corridor_with_two_open_ends_has_exactly_two_openings() -> None:
    found, known, _, _ = _openings(samples.straight_corridor())
    assert len(found) == 2
    assert pieces.match_openings(found, known) == (2, 2)


def test_closed_room_with_one_door_has_one_opening() -> None:
    level = samples.room_with_window()  # one doorway; the window above the sill is no way out
    found, known, graph, terminals = _openings(level)
    assert len(found) == 1 and pieces.match_openings(found, known) == (1, 1)
    (opening,) = terminals.openings
    assert opening.width == pytest.approx(level.openings[0].width, abs=0.1)
    # The terminal is a leaf joined to a sample; off the surface the samples stand on.
    (node,) = terminals.nodes
    assert graph.degree[node] == 1 and graph.nodes[node]["on_navmesh"] is False


def test_grid_faces_and_their_boundary() -> None:
    # 3 x 3 samples 1 m apart: the diagonals are not Delaunay (each square's four corners on one
    # circle), so four unit squares, and one boundary loop round the 8 outer samples.
    surface = sampled_surface(_grid(3), spacing=1.0)
    assert len(surface.polygons) == 4 and np.allclose(surface.areas, 1.0)
    (loop,) = boundary_loops(surface.vertices, surface.polygons, surface.neighbours)
    assert loop.closed and loop.edge_count == 8
    # Interior on the left seen from above (+Y up): (up x t) . (centre - p) > 0 on every edge.
    t = np.roll(loop.points, -1, axis=0) - loop.points
    left = np.cross([0.0, 1.0, 0.0], t)
    assert (np.einsum("ij,ij->i", left, np.array([1.0, 0.0, 1.0]) - loop.points) > 0).all()


def test_a_hole_larger_than_two_spacings_squared_is_open() -> None:
    # 6 x 6 samples with the middle 2 x 2 gone (a pillar's hole): 16 unit squares, and a triangle
    # at each of the hole's corners (the diagonal there has a common neighbour on one side only),
    # round an octagon of 9 - 4 x 0.5 = 7 m².
    pillar = {(2, 2), (2, 3), (3, 2), (3, 3)}
    surface = sampled_surface(_grid(6, pillar), spacing=1.0)
    assert len(surface.polygons) == 20 and sorted(np.round(surface.areas, 9)) == [0.5] * 4 + [1.0] * 16
    loops = boundary_loops(surface.vertices, surface.polygons, surface.neighbours)
    assert sorted(lp.edge_count for lp in loops) == [8, 20]
    # With samples 2 m apart the same hole is less than 2 spacings squared: walkable surface.
    surface = sampled_surface(_grid(6, pillar), spacing=2.0)
    assert len(surface.polygons) == 21
    assert [lp.edge_count for lp in boundary_loops(surface.vertices, surface.polygons, surface.neighbours)] == [20]


def test_samples_in_single_file_keep_both_sides_as_boundary() -> None:
    graph = nx.Graph()
    for i in range(4):
        graph.add_node(i, pos=(float(i), 0.0, 0.0), normal=(0.0, 1.0, 0.0), area=0.2 * (i + 1))
    graph.add_edges_from([(0, 1), (1, 2), (2, 3)])
    surface = sampled_surface(graph, spacing=1.0)
    # each polygon of two corners weighs half the surface each of its samples stands for
    assert len(surface.polygons) == 3 and np.allclose(surface.areas, [0.3, 0.5, 0.7])
    (loop,) = boundary_loops(surface.vertices, surface.polygons, surface.neighbours)
    assert loop.edge_count == 6  # out along one side, back along the other
    assert len(surface.joined) == 2  # one floor


def test_a_line_of_samples_is_walked_round_both_its_ends() -> None:
    # Coordinates where the sign of a two-corner polygon's inside, rounding noise, turned both its edges one way
    # (docs/entry_exit.md, "A fifteenth round of piece kinds"): the loop broke into open chains.
    graph = nx.Graph()
    for i, (x, z) in enumerate(((1.37, -4.59), (-4.83, 4.13), (1.07, 0.44))):
        graph.add_node(i, pos=(x, 0.0, z), normal=(0.0, 1.0, 0.0))
    graph.add_edges_from([(0, 1), (1, 2)])
    surface = sampled_surface(graph, spacing=1.0)
    (loop,) = boundary_loops(surface.vertices, surface.polygons, surface.neighbours)
    assert loop.closed and loop.edge_count == 4
    turns = {tuple(np.round(p, 2)) for p in loop.points}
    assert len(turns) == 3  # out to one end along one side, round it, back along the other side


def test_stairs_down_in_single_file_keep_their_foot_on_the_sampling_route() -> None:
    level = benchmark("piece_kinds12").basement_stair(0.2, 12, 0.0)  # 1.6 m between the trench's walls
    found, known, _, _ = _openings(level)
    assert pieces.match_openings(found, known) == (2, 2)


def test_walkways_in_single_file_under_a_roof_hold_the_openings() -> None:
    found, known, _, _ = _openings(benchmark("piece_kinds12").canal_walkways())
    assert len(found) >= 2 and np.all(found[:, 1] < 0.5)  # none on the tunnel's roof, 3.2 m up
    assert pieces.match_openings(found, known)[0] == len(found)


def test_needs_a_navmesh_or_a_sampled_graph() -> None:
    level = samples.straight_corridor()
    ctx = RunContext(mesh=level.mesh, agent=CONFIG.agent, centre=np.zeros(3))
    graph = nx.Graph()
    graph.add_node(0, pos=(0.0, 0.0, 0.0), normal=(0.0, 1.0, 0.0), area=1.0, on_navmesh=True, polygon=-1)
    with pytest.raises(PluginError, match="navmesh graph builder or the sampling one"):
        entry_exit.g2s_select_terminals(graph=graph, params=entry_exit.Params(), context=ctx)


def test_the_sampling_preset_finds_openings() -> None:
    assert CONFIG.graph.plugin == "sampling" and CONFIG.terminals.plugin == "entry_exit"


@pytest.mark.parametrize("pier, yaw", [(0.1, 0.0), (0.3, 45.0)])
def test_two_doors_side_by_side_on_the_sampling_route(pier: float, yaw: float) -> None:
    # As on the navmesh route (tests/test_entry_exit_kinds.py): one edge spanned both doors and the pier.
    level = pieces.twin_doors(pier=pier)
    level = pieces.turned(level, yaw) if yaw else level
    found, known, _, _ = _openings(level)
    assert len(found) == 3 and pieces.match_openings(found, known) == (3, 3)


def test_a_bridge_over_a_closed_trough_keeps_its_ends_on_the_sampling_route() -> None:
    # As on the navmesh route (tests/test_entry_exit_kinds.py): the deck, over the trough's floor, was a roof and
    # the trough, walled all round, the main floor, so no terminal at all. A floor the agent can leave comes first.
    from tests.test_entry_exit_kinds import _bridge_over_a_closed_trough

    level = samples.SampleLevel(name="bridge", mesh=_bridge_over_a_closed_trough(), metadata={}, openings=(
        samples._opening((0.0, 0.0, 1.2), (-1.0, 0.0, 0.0), 2.4), samples._opening((10.0, 0.0, 1.2), (1.0, 0.0, 0.0), 2.4)))
    found, known, _, _ = _openings(pieces.turned(level, 22.0))
    assert pieces.match_openings(found, known) == (2, 2) and len(found) == 2


def _plaza_with_an_arch() -> samples.SampleLevel:
    """A plaza 10 x 10 m open on all four sides, a freestanding arch (piers 0.6 m, 2 m apart, a lintel at 3 m) in its middle."""
    from tests.test_entry_exit_kinds import _box

    mesh = trimesh.util.concatenate([
        _box(0, 10, -0.2, 0.0, 0, 10), _box(3.4, 4.0, 0.0, 3.0, 4.7, 5.3), _box(6.0, 6.6, 0.0, 3.0, 4.7, 5.3),
        _box(3.4, 6.6, 3.0, 3.6, 4.7, 5.3)])
    sides = [((0, 0, 5), (-1, 0, 0)), ((10, 0, 5), (1, 0, 0)), ((5, 0, 0), (0, 0, -1)), ((5, 0, 10), (0, 0, 1))]
    return samples.SampleLevel(name="plaza_arch", mesh=mesh, metadata={},
                               openings=tuple(samples._opening(p, h, 10.0) for p, h in sides))


@pytest.mark.parametrize("yaw", [0.0, 45.0])
def test_an_opening_found_again_through_a_union_is_one(yaw: float) -> None:
    # Eighth round's `plaza_arch`: one side's samples gave parts 3.28-9.98, 0.54-3.37 and 0.17-2.80 m along it; the
    # first two were one, and their union then overlapped the third, which overlapped neither: a fifth terminal
    # on that side (at 0 and 45 degrees). The repeats are now merged until none is left.
    level = _plaza_with_an_arch()
    found, known, _, terminals = _openings(pieces.turned(level, yaw) if yaw else level)
    assert len(found) == 4 and pieces.match_openings(found, known) == (4, 4)
    assert all(o.width > 9.5 for o in terminals.openings)


def test_a_barrier_the_agent_cannot_climb_leaves_both_ends_on_the_sampling_route() -> None:
    # As on the navmesh route (tests/test_entry_exit_kinds.py): only the larger part's end was found.
    from tests.test_entry_exit_kinds import _corridor_with_a_barrier

    level = samples.SampleLevel(name="barrier", mesh=_corridor_with_a_barrier(1.0), metadata={}, openings=(
        samples._opening((0.0, 0.0, 1.2), (-1.0, 0.0, 0.0), 2.4), samples._opening((12.0, 0.0, 1.2), (1.0, 0.0, 0.0), 2.4)))
    found, known, _, _ = _openings(pieces.turned(level, 22.0))
    assert pieces.match_openings(found, known) == (2, 2) and len(found) == 2


def test_the_sampled_edge_search_reaches_the_clearance_and_a_spacing_and_a_half() -> None:
    assert entry_exit.sampled_edge_search(spacing=0.8, clearance=0.4) == pytest.approx(1.6)
    assert entry_exit.sampled_edge_search(spacing=2.0, clearance=0.5) == pytest.approx(3.5)


@pytest.mark.parametrize("level, yaw", [
    (lambda: pieces.bridge(width=1.2), 22.0),  # its line's ends 1.36 and 1.1 m from the floor's ends
    (lambda: benchmark("piece_kinds15").sagging_rope_bridge(), 0.0),
    (lambda: benchmark("piece_kinds15").winder_stair(), 45.0),  # the top pad's last sample 1.31 m from its end
])
def test_a_line_ending_beyond_the_navmesh_routes_search_keeps_its_end(level, yaw: float) -> None:
    # A sample finding no way out within edge_search_radii * r (1.2 m) looks again as far as the sampling leaves
    # the boundary from the floor's end (1.6 m): without it one end of each was missed.
    built = level()
    found, known, _, _ = _openings(pieces.turned(built, yaw) if yaw else built)
    assert pieces.match_openings(found, known) == (len(known), len(found))


def test_a_rope_rail_thinner_than_a_search_step_closes_the_decks_side() -> None:
    # The rope (0.04 m) passed between bar rays a search step (0.05 m) apart: a third opening along the side.
    found, known, _, _ = _openings(benchmark("piece_kinds15").sagging_rope_bridge())
    assert len(found) == 2 and pieces.match_openings(found, known) == (2, 2)


def test_a_flights_foot_seen_from_several_treads_is_one_opening() -> None:
    # Samples on the treads see the foot within the climb below them, or down the steps along a line rising
    # through the treads: each part found again lies within the climb of the foot's line at one end at least.
    found, known, _, terminals = _openings(benchmark("piece_kinds13").grand_steps())
    east = [o for o in terminals.openings if abs(o.position[0] - 12.4) < 0.05]
    assert len(east) == 1 and east[0].width == pytest.approx(8.0, abs=0.15)
    found, known, _, _ = _openings(benchmark("piece_kinds12").basement_stair(0.2, 12, 0.0))
    assert len(found) == 2


def test_a_roof_walled_less_than_a_storey_up_holds_no_opening() -> None:
    # The sloping tunnel's roof, between its walls where they stand above it: closed along 68 % of its boundary
    # samples at 22 degrees, but 1.8 m over the floor, less than the agent's height: no storey of its own.
    level = pieces.turned(benchmark("piece_kinds15").sloped_ceiling_tunnel(), 22.0)
    found, _, _, _ = _openings(level)
    assert len(found) == 1 and found[0, 1] < 0.1


def test_an_edge_seen_back_against_the_walk_grows_its_ends_outwards() -> None:
    # The pier's end holds a line of samples; with the second look its last two samples on one side look out the
    # other way, their edge points after the rest's, back against the walk: the edge's ends, ordered by those
    # points, grew inwards past each other (1.93 m of the 2.2 m between the rails).
    found, known, _, terminals = _openings(benchmark("piece_kinds14").pier_end())
    end = [o for o in terminals.openings if o.position[0] > 13.5]
    assert len(end) == 1 and end[0].width == pytest.approx(2.2, abs=0.05)


@pytest.mark.parametrize("riser, steps, yaw", [(0.2, 10, 22.0), (0.25, 8, 45.0), (0.2, 8, 0.0)])
def test_a_flights_foot_seen_from_a_line_down_it_measures_the_flight(riser: float, steps: int, yaw: float) -> None:
    # A line of samples down the flight sees its foot from several treads; the edge through their points climbs
    # along it (an end 0.84 m above the foot, lowered by the deepest way's 0.8 m only: 0.2 x 10 at 22 degrees,
    # 1.28 m) or stands vertical (0.25 x 8 at 45: 1.0 m of height over 0.35 m in plan, 1.30 m). With a landing
    # (0.2 x 8 at 0), a part seen from a tread the climb above it is taken in by the landing's level opening.
    level = benchmark("piece_kinds12").basement_stair(riser, steps, 0.6 if yaw == 0.0 else 0.0)
    found, known, _, terminals = _openings(pieces.turned(level, yaw) if yaw else level)
    assert len(found) == 2 and pieces.match_openings(found, known) == (2, 2)
    assert all(o.width == pytest.approx(1.6, abs=0.05) for o in terminals.openings)


@pytest.mark.parametrize("yaw", [0.0, 45.0])
def test_a_floor_walked_down_to_holds_its_end_and_a_channel_the_agent_barely_fits_none(yaw: float) -> None:
    # A corridor's floor dropping 1.0 m half-way: on the sampled surface the upper half measured 0.56 of the lower's
    # area, and the lower was the main floor (the west end missed). The canal's channel, 1.0 m down beside its
    # walkways, was sampled in single file; since the sampling builder's passage rule it is a band of faces 0.18 m
    # across (the agent's 0.8 m in 1.0 m), which held its two ends at y = -1 until a floor walked down to had to be
    # 0.6 agent radii across (the navmesh keeps no floor there).
    corridor = benchmark("piece_kinds18").step_down_corridor(1.0)
    found, known, _, _ = _openings(pieces.turned(corridor, yaw) if yaw else corridor)
    assert pieces.match_openings(found, known) == (2, 2) and len(found) == 2
    canal = benchmark("piece_kinds12").canal_walkways()
    found, _, _, _ = _openings(pieces.turned(canal, yaw) if yaw else canal)
    assert len(found) and (found[:, 1] > -0.5).all()


def test_a_polygons_width_is_its_widest_fan_triangle_across() -> None:
    # A strip 2 x 0.2 m: each fan triangle is 0.2 m across its 2.01 m diagonal (twice 0.2 m^2 over it); a polygon of
    # two corners (samples in single file) has none; a unit square 1 / sqrt 2 (its fan triangles' diagonal).
    surface = sampled_surface(nx.Graph(), 1.0)
    vertices = np.array([[0, 0, 0], [2, 0, 0], [2, 0, 0.2], [0, 0, 0.2], [5, 0, 0], [6, 0, 0], [6, 0, 1], [5, 0, 1]],
                        dtype=np.float64)
    polygons = np.array([[0, 1, 2, 3], [0, 1, -1, -1], [4, 5, 6, 7]])
    widths = entry_exit.polygon_widths(replace(surface, vertices=vertices, polygons=polygons))
    assert widths == pytest.approx([0.4 / math.hypot(2.0, 0.2), 0.0, math.sqrt(0.5)])


def test_a_single_file_lines_tip_holds_samples_looking_ahead() -> None:
    # A line of two samples 2 m apart: its loop runs out along the line and back. Each tip holds three more
    # samples, their outward sides turned 45, 90 and 135 degrees from the incoming side's towards the outgoing
    # one's, in walking order; a loop with area (a square) holds none.
    line = BoundaryLoop(points=np.array([[0.0, 0.0, 0.0], [2.0, 0.0, 0.0]]), polygons=np.array([0, 0]), closed=True)
    plain, tipped = sample_loops([line], 0.5), sample_loops([line], 0.5, tips=True)
    assert len(plain.position) == 8 and len(tipped.position) == 14
    at_far = np.flatnonzero(np.all(tipped.position == [2.0, 0.0, 0.0], axis=1))
    assert at_far.tolist() == [7, 8, 9]  # the near tip's 3 (the loop starts there), 4 out along the line, then these
    outward = np.cross(tipped.tangent[at_far], [0.0, 1.0, 0.0])
    half = np.sqrt(0.5)
    assert np.allclose(outward, [[half, 0.0, half], [1.0, 0.0, 0.0], [half, 0.0, -half]])
    square = boundary_loops(np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 0.0, 1.0], [0.0, 0.0, 1.0]]),
                            np.array([[0, 3, 2, 1]]), np.full((1, 4), -1))
    assert len(sample_loops(square, 0.25, tips=True).position) == len(sample_loops(square, 0.25).position)


def test_a_pad_at_a_single_file_lines_end_holds_its_opening() -> None:
    # The open switchback stair's top pad holds one sample, the end of its flight's line; at 22 degrees one loop
    # sample on its open side found the way out, and a segment needs two: the pad's edge was missed.
    level = pieces.turned(benchmark("piece_kinds20").open_switchback_stair(), 22.0)
    found, known, _, _ = _openings(level)
    assert len(found) == 2 and pieces.match_openings(found, known) == (2, 2)


def test_a_pivot_leaf_across_a_doorway_cuts_its_edge_in_two() -> None:
    # The nineteenth round's pivot door, its 0.05 m leaf turned open across the 2.4 m doorway's middle: at 22 degrees
    # one segment saw out through both gaps, and no candidate of the pier test, 0.05 m apart along the edge, met the
    # leaf straight out (one stood inside it and saw its far end); the edge, measured from its middle at the leaf, was
    # 0.05 m wide and dropped. A ray along the edge between two candidates meets the leaf: two openings of 1.175 m.
    level = pieces.turned(benchmark("piece_kinds19").pivot_door_open(), 22.0)
    found, known, _, _ = _openings(level)
    assert len(found) == 3 and pieces.match_openings(found, known) == (3, 3)
