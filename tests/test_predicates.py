"""SimplifyPredicate plugins: surface_los (Algorithm 5), max_length, always, never."""

from __future__ import annotations

import math

import networkx as nx
import numpy as np
import pytest

from g2s_core.config import AgentConfig
from g2s_core.errors import PluginError
from g2s_core.model import RunContext
from g2s_core.simplify import simplify_forest
from g2s_plugins._surface import normals_angle_deg, traffic_ranks
from g2s_plugins.predicates import always, max_length, never, surface_los

UP = (0.0, 1.0, 0.0)


class SquareWithWall:
    """A geometry test double of a navmesh: the floor square [0, 10] x [0, 10] (y = 0)
    with a wall on x = 5 for z in [0, 7]. ``raycast`` is clear when both ends are
    on the square and the segment does not cross the wall; ``t`` is the fraction
    where it is stopped (``inf`` when clear)."""

    settings = {"cell_size": 0.25}

    def __init__(self):
        self.calls = []

    def segment_surface_gaps(self, A, B, step, reach):
        """Largest height above or below the floor along each segment (``inf``: off the square or beyond reach)."""
        gaps = []
        for a, b in zip(np.reshape(A, (-1, 3)), np.reshape(B, (-1, 3))):
            points = a + np.linspace(0.0, 1.0, 101)[:, None] * (b - a)
            on = ((points[:, [0, 2]] >= 0.0) & (points[:, [0, 2]] <= 10.0)).all(axis=1)
            gap = np.abs(points[:, 1]).max()
            gaps.append(gap if on.all() and gap <= reach else math.inf)
        return np.array(gaps)

    def segment_surface_gap(self, a, b, step, reach):
        return float(self.segment_surface_gaps(a, b, step, reach)[0])

    def line_of_sight(self, a, b, step, max_gap):
        """The real navmesh's one call: the raycast, then (unless ``max_gap`` is None) the gap test."""
        clear, _t = self.raycast(a, b)
        if not clear or max_gap is None:
            return clear
        return self.segment_surface_gap(a, b, step, max_gap) <= max_gap

    @staticmethod
    def _inside(p):
        return 0.0 <= p[0] <= 10.0 and 0.0 <= p[2] <= 10.0 and abs(p[1]) < 0.5

    def raycast(self, a, b):
        self.calls.append((tuple(a), tuple(b)))
        a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
        if not self._inside(a):
            return False, 0.0
        if (a[0] - 5.0) * (b[0] - 5.0) < 0:  # crosses the plane of the wall
            t = (5.0 - a[0]) / (b[0] - a[0])
            z = a[2] + t * (b[2] - a[2])
            if 0.0 <= z <= 7.0:
                return False, float(t)
        if not self._inside(b):
            return False, 1.0
        return True, math.inf


def context(navmesh=None) -> RunContext:
    return RunContext(mesh=None, agent=AgentConfig(), centre=np.zeros(3), navmesh=navmesh)


def chain(*specs) -> nx.DiGraph:
    """A rooted chain 0 -> 1 -> 2 ...; each spec is (pos, normal, on_navmesh)."""
    tree = nx.DiGraph()
    for i, (pos, normal, on_mesh) in enumerate(specs):
        tree.add_node(i, pos=tuple(map(float, pos)), normal=normal, on_navmesh=on_mesh, area=1.0, polygon=i)
        if i:
            tree.add_edge(i - 1, i, weight=math.dist(specs[i - 1][0], pos))
    tree.graph["roots"] = [0]
    for i in tree:
        tree.nodes[i]["depth"] = i
        tree.nodes[i]["root"] = 0
    return tree


def make(module, navmesh=None, **params):
    rounds = {"forest": None, "simplified": None} if module is surface_los else {}  # the first call of the pipeline's
    return module.g2s_simplify_predicate(params=module.Params(**params), context=context(navmesh), **rounds)


# --- surface_los ---------------------------------------------------------------------------


def test_surface_los_collapses_when_a_sees_c():
    navmesh = SquareWithWall()
    p = make(surface_los, navmesh)
    tree = chain(((1, 0, 9), UP, True), ((5, 0, 8), UP, True), ((9, 0, 9), UP, True))
    assert p(tree, 0, 1, 2) is True
    assert navmesh.calls == [((1.0, 0.0, 9.0), (9.0, 0.0, 9.0))]


def test_surface_los_keeps_b_when_the_wall_blocks_a_to_c():
    p = make(surface_los, SquareWithWall())
    tree = chain(((1, 0, 5), UP, True), ((5, 0, 8), UP, True), ((9, 0, 5), UP, True))
    assert p(tree, 0, 1, 2) is False


def test_surface_los_keeps_b_before_a_leaf_off_the_navmesh_without_raycasting():
    navmesh = SquareWithWall()
    p = make(surface_los, navmesh)
    tree = chain(((1, 0, 9), UP, True), ((2, 0, 9), UP, True), ((3, 0, 9), UP, False))
    assert p(tree, 0, 1, 2) is False
    assert navmesh.calls == []
    # the same node off the navmesh but not a leaf: only the raycast decides
    tree.add_node(3, pos=(4.0, 0.0, 9.0), normal=UP, on_navmesh=True)
    tree.add_edge(2, 3)
    assert p(tree, 0, 1, 2) is True


def test_surface_los_keeps_b_where_the_surface_bends():
    tilted = (0.0, math.cos(math.radians(12)), math.sin(math.radians(12)))  # 12 degrees from up
    tree = chain(((1, 0, 9), UP, True), ((2, 0, 9), tilted, True), ((3, 0, 9), UP, True))
    assert make(surface_los, SquareWithWall())(tree, 0, 1, 2) is False  # default 10 degrees
    assert make(surface_los, SquareWithWall(), normal_tolerance_deg=15.0)(tree, 0, 1, 2) is True
    # the whole chain is compared: a bend between B and C keeps B too
    tree = chain(((1, 0, 9), UP, True), ((2, 0, 9), UP, True), ((3, 0, 9), tilted, True))
    assert make(surface_los, SquareWithWall())(tree, 0, 1, 2) is False


def test_surface_los_keeps_b_when_a_to_c_leaves_the_surface():
    # C stands 0.45 m over the floor (the raycast accepts it): the segment A -> C ends
    # 0.45 m from the surface, more than the 0.4 m allowed by default.
    tree = chain(((1, 0, 9), UP, True), ((2, 0, 9), UP, True), ((3, 0.45, 9), UP, True))
    assert make(surface_los, SquareWithWall())(tree, 0, 1, 2) is False
    assert make(surface_los, SquareWithWall(), max_surface_gap=0.5)(tree, 0, 1, 2) is True


def test_surface_los_remembers_bends_per_pair_of_normals_and_takes_array_normals():
    # the normal test's answers are remembered per pair of normals: asked again, in either order and after
    # other pairs, a pair gets the answer its angle gives; a normal given as an array (unhashable) is compared
    tilted = (0.0, math.cos(math.radians(12)), math.sin(math.radians(12)))
    p = make(surface_los, SquareWithWall())
    bent = chain(((1, 0, 9), UP, True), ((2, 0, 9), tilted, True), ((3, 0, 9), UP, True))
    flat = chain(((1, 0, 9), UP, True), ((2, 0, 9), UP, True), ((3, 0, 9), UP, True))
    assert [p(tree, 0, 1, 2) for tree in (bent, flat, bent, flat)] == [False, True, False, True]
    for normal, expected in ((np.array(tilted), False), (np.array(UP), True), ([0.0, 1.0, 0.0], True)):
        tree = chain(((1, 0, 9), UP, True), ((2, 0, 9), normal, True), ((3, 0, 9), UP, True))
        assert p(tree, 0, 1, 2) is expected


def test_surface_los_zero_normal_keeps_b():
    tree = chain(((1, 0, 9), (0.0, 0.0, 0.0), True), ((2, 0, 9), UP, True), ((3, 0, 9), UP, True))
    assert make(surface_los, SquareWithWall(), normal_tolerance_deg=180.0)(tree, 0, 1, 2) is False


def walked_path(count: int = 5) -> nx.Graph:
    """The initial graph of a corridor: polygons 0 - 1 - ... in a row, 1 m apart, each 1 m²."""
    graph = nx.path_graph(count)
    nx.set_edge_attributes(graph, 1.0, "weight")
    nx.set_node_attributes(graph, 1.0, "area")
    return graph


def test_traffic_ranks_of_a_corridor_leave_openings_out():
    # through-flow of a row of five: 2 k (4 - k) ordered pairs pass node k: 0, 6, 8, 6, 0;
    # an opening (area 0) after node 4 starts no walk and adds no flow, but counts among the six ranked values:
    # ranks 2 (three 0s), 4.5 (two 6s), 6 -> percentiles 100 (rank - 0.5) / 6
    graph = walked_path()
    graph.add_edge(4, 5, weight=1.0)
    graph.nodes[5]["area"] = 0.0
    assert traffic_ranks(graph) == pytest.approx({0: 25.0, 1: 400 / 6, 2: 550 / 6, 3: 400 / 6, 4: 25.0})
    # a portal node (area 0) between polygons 1 and 2 is ranked by the walks through it: 2 x 2 x 3 = 12, the most
    graph = walked_path()
    graph.remove_edge(1, 2)
    graph.add_edges_from([(1, 5), (5, 2)], weight=0.5)
    graph.nodes[5]["area"] = 0.0
    assert traffic_ranks(graph)[5] == pytest.approx(100 * 5.5 / 6)


def test_surface_los_traffic_step_keeps_b_where_the_flow_changes():
    # the corridor's percentiles (five values 0, 6, 8, 6, 0): 20, 60, 90, 60, 20; the tree follows it in the open
    graph = walked_path()
    tree = chain(*[((1 + 2 * i, 0, 9), UP, True) for i in range(5)])

    def simplified(**params) -> list[tuple[int, int]]:
        ctx = RunContext(mesh=None, agent=AgentConfig(), centre=np.zeros(3), navmesh=SquareWithWall(), graph=graph)
        predicate = surface_los.g2s_simplify_predicate(params=surface_los.Params(**params), context=ctx, forest=None, simplified=None)
        return sorted(simplify_forest(tree, predicate).edges)

    assert simplified() == [(0, 4)]
    # 35 points: 0 (20) -> 1 (60) steps 40, so 1 stays; 1 -> 2 (90) -> 3 steps 30, so 2 goes; 3 (60) -> 4 (20) keeps 3
    assert simplified(max_traffic_step=35) == [(0, 1), (1, 3), (3, 4)]
    assert simplified(max_traffic_step=25) == [(0, 1), (1, 2), (2, 3), (3, 4)]
    # 40 points: 1 goes (40 and 30), then 2 (90) is compared with the kept 0 (20): 70, so 2 stays; 3 goes
    assert simplified(max_traffic_step=40) == [(0, 2), (2, 4)]
    assert simplified(max_traffic_step=70) == [(0, 4)]


def test_traffic_step_needs_the_initial_graph():
    with pytest.raises(PluginError, match="max_traffic_step"):
        make(surface_los, SquareWithWall(), max_traffic_step=10.0)


def test_normals_angle():
    assert normals_angle_deg(UP, UP) == 0.0
    assert normals_angle_deg(UP, (0.0, 0.0, 2.0)) == pytest.approx(90.0)
    assert normals_angle_deg(UP, (0.0, -1.0, 0.0)) == pytest.approx(180.0)
    assert normals_angle_deg(UP, (0.0, 0.0, 0.0)) == math.inf


def test_surface_los_without_a_navmesh_is_a_plugin_error():
    with pytest.raises(PluginError, match="surface_los needs a navigation mesh; use the navmesh graph builder or the mesh_los predicate"):
        make(surface_los, None)


def test_surface_los_simplifies_a_corridor_around_a_wall():
    # a corridor along the north side (z = 9), then south along the east side, then west:
    # 0 (1,9) 1 (3,9) 2 (5,9) 3 (7,9) 4 (9,9) 5 (9,4) 6 (9,1) 7 (6,1)
    points = [(1, 9), (3, 9), (5, 9), (7, 9), (9, 9), (9, 4), (9, 1), (6, 1)]
    tree = chain(*(((x, 0, z), UP, True) for x, z in points))
    structure = simplify_forest(tree, make(surface_los, SquareWithWall()))
    # 0 sees 2, 3 and 4 past the wall's north end (z = 7) but not 5 (the line 0-5
    # crosses x = 5 at z = 6.5); from 4 everything east of the wall is in sight
    assert sorted(structure.edges) == [(0, 4), (4, 7)]
    assert structure.edges[0, 4]["weight"] == pytest.approx(8.0)


def _floor_with_wall():
    trimesh = pytest.importorskip("trimesh")
    recast = pytest.importorskip("g2s_plugins.recast")
    floor_vertices = np.array([[0, 0, 0], [10, 0, 0], [10, 0, 10], [0, 0, 10]], dtype=np.float64)
    floor_faces = np.array([[0, 2, 1], [0, 3, 2]])
    wall = trimesh.creation.box(extents=[0.4, 3.0, 7.0])
    wall.apply_translation([5.0, 1.5, 3.5])  # x in [4.8, 5.2], z in [0, 7], 3 m high
    vertices = np.vstack([floor_vertices, wall.vertices])
    faces = np.vstack([floor_faces, wall.faces + len(floor_vertices)])
    return recast.build_navmesh(vertices, faces, AgentConfig())


def test_surface_los_with_a_real_navmesh():
    navmesh = _floor_with_wall()
    p = make(surface_los, navmesh)
    over_wall = chain(((2, 0, 5), UP, True), ((5, 0, 8.5), UP, True), ((8, 0, 5), UP, True))
    assert p(over_wall, 0, 1, 2) is False
    open_floor = chain(((2, 0, 9), UP, True), ((5, 0, 8.5), UP, True), ((8, 0, 9), UP, True))
    assert p(open_floor, 0, 1, 2) is True
    same_side = chain(((2, 0, 2), UP, True), ((3, 0, 4), UP, True), ((2, 0, 6), UP, True))
    assert p(same_side, 0, 1, 2) is True


# --- max_length, always, never ---------------------------------------------------------


def test_max_length_compares_a_to_c():
    tree = chain(((0, 0, 0), UP, True), ((3, 0, 4), UP, True), ((6, 0, 8), UP, True))  # |AC| = 10
    assert make(max_length)(tree, 0, 1, 2) is True  # default 10 m
    assert make(max_length, max_length=9.99)(tree, 0, 1, 2) is False
    assert make(max_length, max_length=10.0)(tree, 0, 1, 2) is True


def test_always_and_never():
    tree = chain(*(((i, 0, 0), UP, True) for i in range(5)))
    assert make(always)(tree, 0, 1, 2) is True
    assert make(never)(tree, 0, 1, 2) is False
    assert sorted(simplify_forest(tree, make(always)).edges) == [(0, 4)]
    assert sorted(simplify_forest(tree, make(never)).edges) == sorted(tree.edges)


def test_register_as_predicates_and_run_through_pluggy():
    from g2s_core.registry import Registry

    registry = Registry()
    for module in (surface_los, max_length, always, never):
        info = registry.register(module, package="graph2structure", entry_point=f"simplify.{module.NAME}")
        assert (info.stage, info.name) == ("simplify", module.NAME)
    predicate = registry.call(registry.get("simplify", "never"), params=never.Params(), context=context(), forest=None,
                              simplified=None)
    assert predicate(chain(((0, 0, 0), UP, True), ((1, 0, 0), UP, True), ((2, 0, 0), UP, True)), 0, 1, 2) is False
