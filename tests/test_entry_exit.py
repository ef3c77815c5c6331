"""The ``entry_exit`` TerminalSelector on generated levels with known openings.

Each level is built by :mod:`g2s_plugins.samples.levels`; its navmesh comes from the
``navmesh`` graph builder's hook (Recast), and the selector's hook is called
directly with a :class:`~g2s_core.model.RunContext`.
"""

from __future__ import annotations

import math
from functools import lru_cache

import networkx as nx
import numpy as np
import pytest
import trimesh
from pydantic import ValidationError

from g2s_plugins.samples import levels as samples
from g2s_core.config import AgentConfig
from g2s_core.errors import PluginError
from g2s_core.model import Opening, RunContext, Terminals
from g2s_plugins.graph_builders import navmesh as navmesh_builder
from g2s_plugins.terminals import entry_exit
from g2s_plugins.terminals._boundary import boundary_edges, boundary_loops, sample_loops

AGENT = AgentConfig(
    radius=samples.DESIGN_AGENT["radius"],
    height=samples.DESIGN_AGENT["height"],
    max_climb=samples.DESIGN_AGENT["max_climb"],
    max_slope=samples.DESIGN_AGENT["max_slope_deg"],
)
R = AGENT.radius


def _context(mesh) -> RunContext:
    return RunContext(mesh=mesh, agent=AGENT, centre=np.asarray(mesh.bounds, dtype=float).mean(axis=0))


def _build(level, navmesh_params: navmesh_builder.Params | None = None) -> tuple[nx.Graph, RunContext]:
    ctx = _context(level.mesh)
    params = navmesh_params or navmesh_builder.Params()
    graph = navmesh_builder.g2s_build_graph(mesh=level.mesh, params=params, context=ctx)
    return graph, ctx


@lru_cache(maxsize=None)
def _level(name: str, **kwargs):
    return samples.load_sample(name, **kwargs)


def _run(
    level, params: entry_exit.Params | None = None, navmesh_params: navmesh_builder.Params | None = None
) -> tuple[Terminals, nx.Graph, int, RunContext]:
    graph, ctx = _build(level, navmesh_params)
    before = graph.number_of_nodes()
    terminals = entry_exit.g2s_select_terminals(graph=graph, params=params or entry_exit.Params(), context=ctx)
    return terminals, graph, before, ctx


def _pairing(found: tuple[Opening, ...], known: tuple[Opening, ...]) -> list[tuple[Opening, Opening, float]]:
    """Each known opening with its nearest detected one (by midpoint) and their distance."""
    out = []
    for k in known:
        dists = [float(np.linalg.norm(np.subtract(f.position, k.position))) for f in found]
        j = int(np.argmin(dists))
        out.append((k, found[j], dists[j]))
    return out


# --------------------------------------------------------------------------
# The openings of the generated levels
# --------------------------------------------------------------------------

CASES = [
    ("straight_corridor", 2),
    ("corridor_with_ramp", 2),
    ("t_hub", 3),
    ("cross_hub", 4),
    ("closed_room", 0),
    ("room_with_window", 1),
]


@pytest.mark.parametrize(("name", "count"), CASES)
def test_openings_of_generated_levels(name: str, count: int) -> None:
    level = _level(name)
    assert len(level.openings) == count  # the ground truth itself
    terminals, graph, _, _ = _run(level)
    found = terminals.openings
    assert len(found) == count, f"{name}: expected {count} openings, found {[o.position for o in found]}"
    assert len(terminals.nodes) == count
    if count == 0:
        return
    pairs = _pairing(found, level.openings)
    # one detected opening per known one, none spurious (a one-to-one pairing)
    assert len({id(f) for _, f, _ in pairs}) == count
    for known, got, dist in pairs:
        assert dist <= R, f"{name}: opening at {got.position} is {dist:.3f} m from the known {known.position}"
        assert np.dot(got.heading, known.heading) > math.cos(math.radians(10))
        # end points on the same sides (p0 left, p1 right looking out), each within one radius
        assert np.linalg.norm(np.subtract(got.p0, known.p0)) <= R
        assert np.linalg.norm(np.subtract(got.p1, known.p1)) <= R
        assert got.width == pytest.approx(known.width, abs=2 * R)
        assert got.width == pytest.approx(float(np.linalg.norm(np.subtract(got.p1, got.p0))))
        # the opening's midpoint lies at floor height, on the level's edge
        assert got.position[1] == pytest.approx(known.position[1], abs=0.05)


def test_window_above_the_floor_is_not_an_exit() -> None:
    level = _level("room_with_window")
    terminals, _, _, _ = _run(level)
    window = np.asarray(level.metadata["window"]["centre"])
    (door,) = terminals.openings
    assert door.heading == pytest.approx((1.0, 0.0, 0.0), abs=0.05)
    assert np.linalg.norm(np.subtract(door.position, window)[[0, 2]]) > 3.0


def test_a_hole_lower_than_the_probe_height_is_an_exit() -> None:
    # A "window" whose sill is below the rays (half the agent's climb) is a doorway with a
    # threshold: the rays pass through it and the floor ends behind it.
    level = samples.room_with_window(sill_height=0.1)
    terminals, _, _, _ = _run(level)
    headings = sorted(tuple(np.round(o.heading, 1)) for o in terminals.openings)
    assert len(terminals.openings) == 2
    assert (0.0, 0.0, 1.0) in headings and (1.0, 0.0, 0.0) in headings
    # ... and with the probes below the sill again, it is a wall (unless the agent steps up onto the sill,
    # within its climb and between the window's jambs: a doorway over a threshold again)
    high = entry_exit.Params(sample_height=0.05, step_up=False)
    terminals, _, _, _ = _run(level, high)
    assert [tuple(np.round(o.heading, 1)) for o in terminals.openings] == [(1.0, 0.0, 0.0)]


def test_dungeon_exits() -> None:
    # A dungeon is a level, not a modular piece: its exits need not lie at its outer extent.
    level = samples.dungeon(seed=3, rooms=10, exits=3, obstacles=0.3)
    terminals, _, _, _ = _run(level, entry_exit.Params(extent_heights=None))
    assert len(terminals.openings) == 3
    for _, _, dist in _pairing(terminals.openings, level.openings):
        assert dist <= R


@pytest.mark.skipif(
    "tile_size" not in navmesh_builder.Params.model_fields, reason="this Recast build has no tiled navmeshes"
)
def test_tiled_navmesh_gives_the_same_openings() -> None:
    level = _level("cross_hub")
    solo, _, _, _ = _run(level)
    tiled, _, _, ctx = _run(level, navmesh_params=navmesh_builder.Params(tile_size=16))
    assert ctx.navmesh.tile_count > 1
    loops = boundary_loops(ctx.navmesh.vertices, ctx.navmesh.polygons, ctx.navmesh.neighbours)
    assert len(loops) == 1 and loops[0].closed  # the rim runs on across tile borders
    assert len(tiled.openings) == 4
    for _, got, dist in _pairing(tiled.openings, level.openings):
        assert dist <= R
    for a in solo.openings:
        assert min(np.linalg.norm(np.subtract(a.position, b.position)) for b in tiled.openings) < 0.1


class _Level:
    """A hand-made level: a floor slab 12 x 3 m with nothing around it, and a slab over its middle."""

    def __init__(self, roof_top: float):
        floor = trimesh.creation.box(extents=(12.0, 0.2, 3.0))
        floor.apply_translation((6.0, -0.1, 0.0))
        roof = trimesh.creation.box(extents=(8.0, 0.2, 3.0))
        roof.apply_translation((6.0, roof_top - 0.1, 0.0))
        self.mesh = trimesh.util.concatenate([floor, roof])


def test_a_roof_over_the_piece_has_no_exits() -> None:
    # The slab's top is walkable but lies 2.4 m over the floor, unreachable from it: no exits.
    level = _Level(roof_top=2.4)
    terminals, _, _, ctx = _run(level)
    assert {round(y, 1) for y in np.unique(ctx.navmesh.vertices[:, 1].round(1))} >= {2.4}  # Recast walks it
    assert len(terminals.openings) == 4  # the floor's four open sides
    assert all(abs(o.position[1]) < 0.05 for o in terminals.openings)
    # taken as a floor, its two long sides (nothing below beyond them) would be exits;
    # its short ends drop onto the floor below (a ledge inside the piece) and never are
    terminals, _, _, _ = _run(level, entry_exit.Params(main_floor_only=False))
    upper = [o for o in terminals.openings if o.position[1] > 2.0]
    assert len(terminals.openings) == 6 and len(upper) == 2
    assert all(abs(abs(o.heading[2]) - 1.0) < 0.05 for o in upper)


def test_an_unreachable_upper_floor_has_no_exits_unless_asked() -> None:
    # The same slab 4 m up (two agent heights): an upper level nothing leads to.
    terminals, _, _, _ = _run(_Level(roof_top=4.0))
    assert [o for o in terminals.openings if o.position[1] > 3.5] == []
    terminals, _, _, _ = _run(_Level(roof_top=4.0), entry_exit.Params(main_floor_only=False))
    assert len([o for o in terminals.openings if o.position[1] > 3.5]) == 2


def test_walled_two_floor_level_has_no_exit() -> None:
    terminals, graph, before, _ = _run(_level("two_floors"))
    assert terminals == Terminals(nodes=(), openings=())
    assert graph.number_of_nodes() == before


def test_closed_room_leaves_the_graph_alone() -> None:
    terminals, graph, before, _ = _run(_level("closed_room"))
    assert terminals.nodes == () and terminals.openings == ()
    assert graph.number_of_nodes() == before


# --------------------------------------------------------------------------
# Terminal nodes in the graph
# --------------------------------------------------------------------------


def test_terminal_nodes_are_added_and_joined() -> None:
    level = _level("cross_hub")
    terminals, graph, before, ctx = _run(level)
    assert terminals.nodes == tuple(range(before, before + 4))  # new ids after the largest, in order
    assert len(terminals.openings) == len(terminals.nodes)
    for node, opening in zip(terminals.nodes, terminals.openings):
        data = graph.nodes[node]
        assert data["pos"] == opening.position
        assert data["area"] == 0.0
        assert data["polygon"] == -1
        assert data["on_navmesh"] is False  # the opening lies on the floor's edge, r outside the navmesh
        assert np.linalg.norm(data["normal"]) == pytest.approx(1.0)
        (other,) = list(graph[node])  # one edge: the terminal is a leaf
        assert graph.nodes[other]["polygon"] >= 0  # joined to a polygon the opening runs along
        expected = np.linalg.norm(np.subtract(graph.nodes[other]["pos"], data["pos"]))
        assert graph.edges[node, other]["weight"] == pytest.approx(expected)
        assert graph.edges[node, other]["weight"] < level.metadata["params"]["arm_length"]
    assert nx.is_connected(graph)
    assert ctx.navmesh is not None


def test_terminal_on_the_navmesh_is_flagged() -> None:
    # An opening moved onto the navmesh (a stand-in detection) must be reported as on it.
    level = _level("straight_corridor")
    graph, ctx = _build(level)
    centre = ctx.navmesh.centres[0]
    opening = Opening(position=tuple(centre), heading=(1.0, 0.0, 0.0), width=1.0, p0=tuple(centre), p1=tuple(centre))
    det = entry_exit.Detection(openings=(opening,), polygons=((0,),), normals=((0.0, 1.0, 0.0),))
    terminals = entry_exit.add_terminals(graph, det, ctx.navmesh, AGENT)
    assert graph.nodes[terminals.nodes[0]]["on_navmesh"] is True
    assert graph.edges[terminals.nodes[0], 0]["weight"] == pytest.approx(0.0, abs=1e-9)


def test_needs_the_navmesh() -> None:
    level = _level("straight_corridor")
    ctx = _context(level.mesh)
    graph = nx.Graph()
    graph.add_node(0, pos=(0.0, 0.0, 0.0), normal=(0.0, 1.0, 0.0), area=1.0, on_navmesh=True, polygon=-1)
    with pytest.raises(PluginError, match="navmesh graph builder"):
        entry_exit.g2s_select_terminals(graph=graph, params=entry_exit.Params(), context=ctx)


# --------------------------------------------------------------------------
# Parameters, boundary loops, batching
# --------------------------------------------------------------------------


def test_params_are_documented_and_validated() -> None:
    assert entry_exit.NAME == "entry_exit"
    for name, field in entry_exit.Params.model_fields.items():
        assert field.description, f"{name} has no description"
    with pytest.raises(ValidationError):
        entry_exit.Params(fan_count=0)
    with pytest.raises(ValidationError):
        entry_exit.Params(sample_step=0)
    with pytest.raises(ValidationError):
        entry_exit.Params(not_a_param=1)


def test_boundary_loops_are_closed_and_keep_the_inside_on_the_left() -> None:
    _, ctx = _build(_level("t_hub"))
    nav = ctx.navmesh
    start, end, owner = boundary_edges(nav.vertices, nav.polygons, nav.neighbours)
    assert len(start) == int((nav.neighbours[nav.polygons >= 0] < 0).sum())
    d = nav.vertices[end] - nav.vertices[start]
    to_centre = nav.centres[owner] - nav.vertices[start]
    assert np.all(np.einsum("ij,ij->i", to_centre, np.cross([0.0, 1.0, 0.0], d)) > 0)
    loops = boundary_loops(nav.vertices, nav.polygons, nav.neighbours)
    assert len(loops) == 1 and loops[0].closed  # one rim, no holes in a T hub
    assert sum(lp.edge_count for lp in loops) == len(start)
    # the loop runs counter-clockwise seen from above (+Y): positive signed area in (z, x)
    p = loops[0].points
    area = 0.5 * np.sum(p[:, 2] * np.roll(p[:, 0], -1) - np.roll(p[:, 2], -1) * p[:, 0])
    assert area > 0
    smp = sample_loops(loops, 0.5)
    gaps = np.linalg.norm(np.diff(smp.position, axis=0), axis=1)
    assert gaps.max() <= 0.5 + 1e-9


def test_rays_are_cast_in_batches(monkeypatch: pytest.MonkeyPatch) -> None:
    from trimesh.ray import ray_pyembree

    calls: list[int] = []
    original = ray_pyembree._EmbreeWrap.run  # every Embree query goes through it

    def counting(self, origins, directions, **kwargs):
        calls.append(len(origins))
        return original(self, origins, directions, **kwargs)

    monkeypatch.setattr(ray_pyembree._EmbreeWrap, "run", counting)
    terminals, _, _, _ = _run(_level("cross_hub"))
    assert len(terminals.openings) == 4
    assert sum(calls) > 2000  # thousands of rays ...
    # ... in a fixed number of batched calls: one per step and bisection round (a batch with
    # rays grazing a triangle is cast again twice, nudged aside); the step gap's test adds two to the search (its rays
    # along the way and its sides): 60 calls without it on this level, 62 with it; the slot rule two (the floor's side
    # face looked back at and its probes beyond): 64
    assert len(calls) <= 3 * 20 + 4
