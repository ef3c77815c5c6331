"""SimplifyPredicate ``mesh_los``: line of sight over the level mesh, and Algorithm 5's rules."""

from __future__ import annotations

import math

import networkx as nx
import numpy as np
import pytest
import trimesh

from g2s_core.config import AgentConfig
from g2s_core.model import RunContext
from g2s_core.simplify import simplify_forest
from g2s_plugins.predicates import mesh_los

AGENT = AgentConfig(radius=0.5, height=2.0, max_climb=0.4, max_slope=45.0)
UP = (0.0, 1.0, 0.0)


def box(lo, hi) -> trimesh.Trimesh:
    lo, hi = np.asarray(lo, dtype=float), np.asarray(hi, dtype=float)
    return trimesh.creation.box(extents=hi - lo, transform=trimesh.transformations.translation_matrix((lo + hi) / 2))


def slab(x0, x1, z0, z1, top=0.0) -> trimesh.Trimesh:
    return box((x0, top - 0.2, z0), (x1, top, z1))


def level(*parts) -> trimesh.Trimesh:
    return trimesh.util.concatenate(list(parts))


def predicate(mesh, **params):
    context = RunContext(mesh=mesh, agent=AGENT, centre=np.zeros(3))
    return mesh_los.g2s_simplify_predicate(params=mesh_los.Params(**params), context=context, forest=None, simplified=None)


def chain(*specs) -> nx.DiGraph:
    """A rooted chain 0 -> 1 -> 2 ...; each spec is (pos, normal, on_navmesh)."""
    tree = nx.DiGraph()
    for i, (pos, normal, on_surface) in enumerate(specs):
        tree.add_node(i, pos=tuple(map(float, pos)), normal=tuple(normal), on_navmesh=on_surface, area=1.0, polygon=-1)
        if i:
            tree.add_edge(i - 1, i, weight=math.dist(specs[i - 1][0], pos))
    tree.graph["roots"] = [0]
    for depth, node in enumerate(sorted(tree)):
        tree.nodes[node].update(depth=depth, root=0)
    return tree


def tilted(degrees: float) -> tuple[float, float, float]:
    a = math.radians(degrees)
    return (math.sin(a), math.cos(a), 0.0)


FLOOR = slab(-10, 10, -10, 10)


def test_default_tolerance_is_surface_los_one():
    surface_los = pytest.importorskip("g2s_plugins.predicates.surface_los")
    ours = mesh_los.Params.model_fields["normal_tolerance_deg"].default
    assert ours == surface_los.Params.model_fields["normal_tolerance_deg"].default == 10.0


def test_clear_across_open_floor():
    p = predicate(FLOOR)
    tree = chain(((-8, 0, 0), UP, True), ((0, 0, 3), UP, True), ((8, 0, 0), UP, True))
    assert p(tree, 0, 1, 2) is True


def test_blocked_by_a_wall():
    wall = box((-0.1, -0.2, -3.0), (0.1, 3.0, 3.0))
    p = predicate(level(FLOOR, wall))
    blocked = chain(((-8, 0, 0), UP, True), ((0, 0, 5), UP, True), ((8, 0, 0), UP, True))
    assert p(blocked, 0, 1, 2) is False
    # Past the wall's end the line is clear again.
    around = chain(((-8, 0, 5), UP, True), ((0, 0, 6), UP, True), ((8, 0, 5), UP, True))
    assert p(around, 0, 1, 2) is True


def test_blocked_by_an_obstacle_lower_than_half_the_agent():
    # 0.8 m: the lifted segment (1 m up) passes over it, the ground probes do not.
    crate = box((-0.5, 0.0, -1.0), (0.5, 0.8, 1.0))
    p = predicate(level(FLOOR, crate))
    tree = chain(((-8, 0, 0), UP, True), ((0, 0, 4), UP, True), ((8, 0, 0), UP, True))
    assert p(tree, 0, 1, 2) is False
    # A 0.3 m step is climbed (max climb 0.4).
    step = box((-0.5, 0.0, -1.0), (0.5, 0.3, 1.0))
    assert predicate(level(FLOOR, step))(tree, 0, 1, 2) is True


def test_blocked_over_a_hole_in_the_floor():
    holed = level(slab(-10, -1, -10, 10), slab(1, 10, -10, 10))
    p = predicate(holed)
    across = chain(((-8, 0, 0), UP, True), ((0, 0, 12), UP, True), ((8, 0, 0), UP, True))
    assert p(across, 0, 1, 2) is False
    # A hole with a floor 3 m below is still a hole (deeper than a step).
    below = slab(-10, 10, -10, 10, top=-3.0)
    assert predicate(level(holed, below))(across, 0, 1, 2) is False
    # Beside the hole (same side) the line is clear.
    beside = chain(((-8, 0, 0), UP, True), ((-5, 0, 3), UP, True), ((-2, 0, 0), UP, True))
    assert p(beside, 0, 1, 2) is True


def test_blocked_under_a_low_ceiling():
    ceiling = box((-1.0, 1.5, -10.0), (1.0, 1.7, 10.0))
    tree = chain(((-8, 0, 0), UP, True), ((0, 0, 4), UP, True), ((8, 0, 0), UP, True))
    assert predicate(level(FLOOR, ceiling))(tree, 0, 1, 2) is False
    high = box((-1.0, 2.5, -10.0), (1.0, 2.7, 10.0))
    assert predicate(level(FLOOR, high))(tree, 0, 1, 2) is True


def test_normal_rule():
    p = predicate(FLOOR)
    bent = chain(((-8, 0, 0), UP, True), ((0, 0, 0), tilted(20.0), True), ((8, 0, 0), UP, True))
    assert p(bent, 0, 1, 2) is False
    slight = chain(((-8, 0, 0), UP, True), ((0, 0, 0), tilted(5.0), True), ((8, 0, 0), UP, True))
    assert p(slight, 0, 1, 2) is True
    # The tolerance is a parameter; a zero-length normal counts as exceeding it.
    assert predicate(FLOOR, normal_tolerance_deg=30.0)(bent, 0, 1, 2) is True
    flat = chain(((-8, 0, 0), UP, True), ((0, 0, 0), (0.0, 0.0, 0.0), True), ((8, 0, 0), UP, True))
    assert p(flat, 0, 1, 2) is False


def test_off_surface_leaf_rule():
    p = predicate(FLOOR)
    off_leaf = chain(((-8, 0, 0), UP, True), ((0, 0, 0), UP, True), ((8, 0, 0), UP, False))
    assert p(off_leaf, 0, 1, 2) is False
    # Not a leaf: the rule does not apply and the (clear) line decides.
    not_leaf = chain(((-8, 0, 0), UP, True), ((0, 0, 0), UP, True), ((8, 0, 0), UP, False), ((9, 0, 0), UP, True))
    assert p(not_leaf, 0, 1, 2) is True


def test_ramp_between_floors():
    # A 20 degree ramp from y = 0 (x = 0) to y = 2 (x = run), floors on both sides.
    run = 2.0 / math.tan(math.radians(20.0))
    ramp = trimesh.Trimesh(
        vertices=[[0, 0, -2], [run, 2, -2], [run, 2, 2], [0, 0, 2]], faces=[[0, 2, 1], [0, 3, 2]], process=False
    )
    mesh = level(slab(-6, 0, -2, 2), ramp, slab(run, run + 6, -2, 2, top=2.0))
    ramp_normal = tuple(ramp.face_normals[0])
    p = predicate(mesh)
    # Along the ramp: clear.
    up_ramp = chain(((0.5, 0.5 * math.tan(math.radians(20)), 0), ramp_normal, True), ((run / 2, 1.0, 0.5), ramp_normal, True), ((run - 0.5, 2 - 0.5 * math.tan(math.radians(20)), 0), ramp_normal, True))
    assert p(up_ramp, 0, 1, 2) is True
    # From the lower floor straight to the upper floor: the ground dips below the
    # line by more than a step at the foot of the ramp.
    across = chain(((-5, 0, 0), UP, True), ((0, 0, 0), UP, True), ((run + 5, 2, 0), UP, True))
    assert p(across, 0, 1, 2) is False


def test_simplifies_a_chain_only_where_the_line_is_clear():
    wall = box((-0.1, -0.2, -10.0), (0.1, 3.0, 2.0))
    p = predicate(level(FLOOR, wall))
    # A path from (-8, 0) around the wall's end at z = 2 to (8, 0), with extra nodes.
    points = [(-8, 0), (-6, 1), (-4, 2), (-2, 3), (0, 4), (2, 3), (4, 2), (6, 1), (8, 0)]
    tree = chain(*[((x, 0.0, z), UP, True) for x, z in points])
    simplified = simplify_forest(tree, p)
    path = nx.shortest_path(simplified, 0, len(points) - 1)
    assert len(path) < len(points)
    for a, b in zip(path, path[1:]):  # no remaining edge crosses the wall
        pa, pb = simplified.nodes[a]["pos"], simplified.nodes[b]["pos"]
        if (pa[0] + 0.1) * (pb[0] - 0.1) < 0 or (pa[0] - 0.1) * (pb[0] + 0.1) < 0:
            t = -pa[0] / (pb[0] - pa[0])
            assert pa[2] + t * (pb[2] - pa[2]) > 2.0
    # Without the wall the whole chain collapses to one edge.
    open_floor = simplify_forest(tree, predicate(FLOOR))
    assert sorted(open_floor.edges) == [(0, len(points) - 1)]


def test_mesh_los_keeps_b_when_a_to_c_runs_under_the_ground() -> None:
    # A 0.9 m hump with 20-degree flanks across the floor: the straight line A -> C along the
    # floor runs through it. The walk test alone accepts it (ground above the line, within half
    # the agent height, slopes walkable); the surface gap rejects it.
    from g2s_plugins.samples.levels import _hexahedra_mesh, _sloped_blocks

    run = 0.9 / math.tan(math.radians(20.0))
    hump = _hexahedra_mesh(np.concatenate([
        _sloped_blocks(2.0, 2.0 + run, -3.0, 3.0, -0.2, 0.0, 0.9),
        _sloped_blocks(2.0 + run, 3.0 + run, -3.0, 3.0, -0.2, 0.9, 0.9),
        _sloped_blocks(3.0 + run, 3.0 + 2 * run, -3.0, 3.0, -0.2, 0.9, 0.0),
    ]))
    tree = chain(((0, 0, 0), UP, True), ((1, 0, 0), UP, True), ((9, 0, 0), UP, True))
    mesh = level(FLOOR, hump)
    assert predicate(mesh, max_surface_gap=1.0)(tree, 0, 1, 2) is True
    assert predicate(mesh)(tree, 0, 1, 2) is False


def test_mesh_los_keeps_b_where_a_to_c_passes_a_corner_closer_than_the_agent_could() -> None:
    # A 3 m block fills x, z in [0, 3]; A -> C runs along x + z = -0.3, 0.21 m from its corner at the origin, and
    # meets nothing: one line sees C. The agent's disk, 0.9 x its 0.5 m radius = 0.45 m either side, would hit
    # the corner, so B, out at (-1.5, -1.5), stays. With the sampling builder's clearance at 0.2 m (the graph's
    # sampling_stats) the band is 0.18 m, which clears the corner.
    from g2s_plugins._raycasting import AgentShape

    mesh = level(FLOOR, box((0.0, 0.0, 0.0), (3.0, 3.0, 3.0)))
    tree = chain(((-2.0, 0, 1.7), UP, True), ((-1.5, 0, -1.5), UP, True), ((1.7, 0, -2.0), UP, True))
    assert predicate(mesh, clearance=0.0)(tree, 0, 1, 2) is True  # one line: B went, before
    assert predicate(mesh)(tree, 0, 1, 2) is False
    sampled = nx.Graph(sampling_stats={"clearance": 0.2})
    agent = AgentShape.from_config(AGENT)
    assert mesh_los.walk_half_width(mesh_los.Params(), agent, sampled) == pytest.approx(0.18)
    assert mesh_los.mesh_los_predicate(mesh, agent, mesh_los.Params(), sampled)(tree, 0, 1, 2) is True
    assert mesh_los.walk_half_width(mesh_los.Params(), agent, None) == pytest.approx(0.45)
    assert mesh_los.walk_half_width(mesh_los.Params(clearance=1.0), agent, sampled) == pytest.approx(0.9)


def test_lookahead_batches_walks_without_changing_answers(monkeypatch: pytest.MonkeyPatch) -> None:
    # The tree a sampled dungeon gives, simplified with and without testing the walks below C ahead.
    from g2s_core import pipeline
    from g2s_core.config import PRESETS_DIR, load_raw_config, parse_config
    from g2s_core.mesh import mesh_sha256
    from g2s_core.registry import Registry
    from g2s_plugins._raycasting import walks_in_batch
    from g2s_plugins.samples.levels import dungeon

    registry = Registry.from_entry_points()
    config = parse_config(load_raw_config(PRESETS_DIR / "map_analysis_sampling.yaml"), "test")
    mesh = dungeon(seed=3, rooms=12).mesh
    run = pipeline.run(pipeline.plan(config, registry, "test"), registry, mesh, "dungeon", mesh_sha256(mesh))
    batches: list[int] = []

    def counting(caster, starts, *args, **kwargs):
        batches.append(len(starts))
        return walks_in_batch(caster, starts, *args, **kwargs)

    monkeypatch.setattr(mesh_los, "walks_in_batch", counting)
    simplified = {}
    for lookahead in (0, mesh_los.LOOKAHEAD):
        monkeypatch.setattr(mesh_los, "LOOKAHEAD", lookahead)
        batches.clear()
        tree = simplify_forest(run.forest, predicate(mesh))
        simplified[lookahead] = (sorted(tree.edges(data="weight")), len(batches), max(batches))
    alone, ahead = simplified[0], simplified[mesh_los.LOOKAHEAD]
    assert alone[0] == ahead[0]
    assert ahead[1] < alone[1]


def test_open_floor_is_a_walkable_triangle_with_nothing_near_it_up_to_the_agent_height() -> None:
    from g2s_plugins._raycasting import AgentShape, OpenFloors, RayCaster

    agent = AgentShape.from_config(AGENT)
    floor = slab(-10, 10, -10, 10)  # its top: two triangles, each the other's neighbour across the diagonal
    top = np.nonzero(floor.face_normals[:, 1] > 0.9)[0]

    def open_top(*parts) -> np.ndarray:
        return OpenFloors(RayCaster(level(floor, *parts)), agent).open[top]

    assert open_top().all()
    assert open_top(box((-11, 2.1, -11), (11, 2.3, 11))).all()  # a ceiling over the agent's head
    assert not open_top(box((-11, 1.5, -11), (11, 1.7, 11))).any()  # a ceiling within its height
    assert open_top(slab(-10, 10, -10, 10, top=-3.0)).all()  # a floor below
    pillar = open_top(box((6, 0, -3), (7, 3, -2)))  # stands on one of the two triangles
    assert pillar.sum() == 1

    floors = OpenFloors(RayCaster(floor), agent)
    points = np.array([[5.0, 0.0, -5.0], [5.0, 0.005, -5.0], [5.0, 0.02, -5.0], [9.99, 0.0, -5.0], [0.0, 0.0, 0.0]])
    faces = floors.faces_under(points)
    assert faces[0] in top and faces[1] == faces[0]
    assert (faces[2:] == -1).all()  # off the plane, at the floor's edge, on the diagonal
    assert (floors.faces_under(points, max_offset=0.001)[:2] == [faces[0], -1]).all()


@pytest.mark.parametrize("name, scale, offset", [
    ("building?seed=1", 4.0, 0.0), ("cluttered_room", 1.0, 0.0), ("two_storey", 1.0, 0.0), ("stair_deck", 2.0, 0.0),
    ("building?seed=2", 2.0, 1e7),
])
def test_walks_on_one_open_floor_pass_with_every_ray_cast(name: str, scale: float, offset: float) -> None:
    # The claim OpenFloors makes, against walks_in_batch casting every ray, on random points (some off the
    # plane, some near the edges) and agents; /tmp-style sweeps of it over all generators found no exception.
    from g2s_core.config import MeshConfig
    from g2s_core.mesh import generate_level
    from g2s_plugins._raycasting import AgentShape, OpenFloors, RayCaster, walks_in_batch

    mesh = generate_level(f"sample:{name}", MeshConfig(scale=scale))
    mesh.vertices = mesh.vertices + np.array([offset, 0.01 * offset, -offset])
    caster = RayCaster(mesh)
    rng = np.random.default_rng(7)
    walks = {0.0: 0, 0.45: 0, 0.18: 0}
    for radius, height, climb, slope, margin, gap in [(0.5, 2.0, 0.4, 45.0, 0.1, 0.4), (0.2, 1.0, 0.2, 20.0, 0.0, 0.005)]:
        agent = AgentShape.from_config(AgentConfig(radius=radius, height=height, max_climb=climb, max_slope=slope))
        floors = OpenFloors(caster, agent)
        face = rng.choice(np.nonzero(floors.open)[0], 3000)
        weights = np.concatenate([rng.dirichlet([1, 1, 1], 2000), rng.dirichlet([0.2, 0.2, 0.2], 1000)])
        points = np.einsum("ni,nij->nj", weights, caster.triangles[face]) + rng.uniform(-0.012, 0.012, (3000, 1)) * UP
        # and, for the sampling builder's edges, with side lines (half_width) over points that far inside too
        for half_width in (0.0, round(0.9 * radius, 2)):
            under = floors.faces_under(points, floors.certain_offset(margin, gap), room=half_width)
            assert ((under == -1) | (under == face)).all()
            on = rng.permutation(np.nonzero(under >= 0)[0])
            on = on[np.argsort(under[on], kind="stable")]  # by triangle, in random order on each
            starts, ends = np.concatenate([on[:-1], on[:-2]]), np.concatenate([on[1:], on[2:]])
            same = under[starts] == under[ends]
            ok, _ = walks_in_batch(caster, points[starts[same]], points[ends[same]], agent, 0.25, margin, gap,
                                   half_width=half_width)
            assert ok.all()
            walks[half_width] += int(same.sum())
    # cluttered_room has no open triangle wide enough for the side lines' room: its wide walks are none
    assert walks[0.0] > 200 and (walks[0.45] + walks[0.18] > 100 or name == "cluttered_room")


def test_open_floor_answers_save_walk_tests_not_answers(monkeypatch: pytest.MonkeyPatch) -> None:
    # A sampled building's tree simplified with the open-floor answers and with every walk tested by rays.
    from g2s_core import pipeline
    from g2s_core.config import PRESETS_DIR, MeshConfig, load_raw_config, parse_config
    from g2s_core.mesh import generate_level, mesh_sha256
    from g2s_core.registry import Registry
    from g2s_plugins._raycasting import OpenFloors, walks_in_batch

    registry = Registry.from_entry_points()
    config = parse_config(load_raw_config(PRESETS_DIR / "map_analysis_sampling.yaml"), "test")
    mesh = generate_level("sample:building?seed=1", MeshConfig(scale=2.0))
    run = pipeline.run(pipeline.plan(config, registry, "test"), registry, mesh, "building", mesh_sha256(mesh))
    walks: list[int] = []

    def counting(caster, starts, *args, **kwargs):
        walks.append(len(starts))
        return walks_in_batch(caster, starts, *args, **kwargs)

    class NoOpenFloors(OpenFloors):
        def faces_under(self, points, max_offset=0.0, room=0.0):
            return np.full(len(points), -1)

    monkeypatch.setattr(mesh_los, "walks_in_batch", counting)
    simplified = {}
    for floors in (NoOpenFloors, OpenFloors):
        monkeypatch.setattr(mesh_los, "OpenFloors", floors)
        walks.clear()
        tree = simplify_forest(run.forest, predicate(mesh, normal_tolerance_deg=45.0))
        simplified[floors] = (sorted(tree.edges(data="weight")), sum(walks))
    assert simplified[OpenFloors][0] == simplified[NoOpenFloors][0]
    assert simplified[OpenFloors][1] < 0.5 * simplified[NoOpenFloors][1]


def test_mesh_los_stops_a_walk_over_low_bollards_with_the_bodys_slab() -> None:
    # The row of tests/test_sampling_body.py: 0.7 m bollards 0.2 m square, centres 0.8 m apart along z at x = 0. A
    # walk A -> C along x at z = 0.4 passes between two of them; its side lines (z -0.05 and 0.85, 0.45 m off) pass
    # over them at 1 m, but they stand in the body's slab (0.5-1.95 m), which the default surface gap (0.4 m, under
    # the 0.5 m knee) lets the walk test. Without a surface gap (the paper's rule) no slab is tested; a 0.45 m row
    # lies under the slab.
    from tests.test_sampling_body import bollard_row

    tree = chain(((-3, 0, 0.4), UP, True), ((0, 0, 3), UP, True), ((3, 0, 0.4), UP, True))
    assert predicate(bollard_row(0.7))(tree, 0, 1, 2) is False
    assert predicate(bollard_row(0.7), max_surface_gap=None)(tree, 0, 1, 2) is True
    assert predicate(bollard_row(0.45))(tree, 0, 1, 2) is True
