"""The ``navmesh`` GraphBuilder plugin (g2s_plugins.graph_builders.navmesh)."""

from __future__ import annotations

import math
import time
import types

import networkx as nx
import numpy as np
import pluggy
import pytest
import trimesh

from g2s_core import hookspecs
from g2s_core.errors import G2SError
from g2s_core.model import RunContext
from g2s_core.plugin import PROJECT, PluginParams
from g2s_plugins._surface import edge_surface_gaps
from g2s_plugins.graph_builders import navmesh as plugin
from g2s_plugins.recast import NavMesh, RecastParams
from g2s_plugins.samples import levels
from tests.test_recast import slab, spiral_tower

AGENT = types.SimpleNamespace(radius=0.3, height=2.0, max_climb=0.4, max_slope=45.0)
DEMO_AGENT = types.SimpleNamespace(radius=0.6, height=2.0, max_climb=0.9, max_slope=45.0)


def level() -> trimesh.Trimesh:
    """A 30 x 20 m floor with two wall boxes and a raised platform reached by a step."""
    return trimesh.util.concatenate(
        [
            slab((30, 0.2, 20), (0, -0.1, 0)),
            slab((0.5, 3, 12), (-5, 1.5, -4)),
            slab((0.5, 3, 12), (5, 1.5, 4)),
            slab((6, 0.3, 6), (11, 0.15, -6)),
        ]
    )


def context(mesh, agent=AGENT) -> RunContext:
    return RunContext(mesh=mesh, agent=agent, centre=np.asarray(mesh.bounds.mean(axis=0)))


def run(mesh, params=None, agent=AGENT):
    ctx = context(mesh, agent)
    graph = plugin.g2s_build_graph(mesh=mesh, params=params or plugin.Params(), context=ctx)
    return graph, ctx


def test_plugin_contract():
    assert plugin.NAME == "navmesh"
    assert issubclass(plugin.Params, RecastParams) and issubclass(plugin.Params, PluginParams)
    assert plugin.__doc__.strip().splitlines()[0]
    pm = pluggy.PluginManager(PROJECT)
    pm.add_hookspecs(hookspecs)
    pm.register(plugin)
    mesh = level()
    ctx = context(mesh)
    graph = pm.hook.g2s_build_graph(mesh=mesh, params=plugin.Params(), context=ctx)
    assert isinstance(graph, nx.Graph) and graph.number_of_nodes() > 0
    assert isinstance(ctx.navmesh, NavMesh)


def test_graph_attributes_follow_the_model():
    graph, ctx = run(level(), plugin.Params(max_edge_gap=None))
    nm = ctx.navmesh
    assert graph.number_of_nodes() == nm.polygon_count
    assert list(graph.nodes) == list(range(nm.polygon_count))
    assert graph.number_of_edges() == len(nm.portals().pairs) > 0
    for i, data in graph.nodes(data=True):
        assert set(data) == {"pos", "normal", "area", "on_navmesh", "polygon"}
        assert isinstance(data["pos"], tuple) and len(data["pos"]) == 3
        assert all(type(v) is float for v in data["pos"] + data["normal"])
        assert type(data["area"]) is float and data["area"] > 0
        assert data["on_navmesh"] is True and data["polygon"] == i
        assert math.isclose(math.hypot(*data["normal"]), 1.0, rel_tol=1e-9) and data["normal"][1] > 0
        assert np.allclose(data["pos"], nm.centres[i])
    verts = {tuple(v) for v in nm.vertices.tolist()}
    for a, b, data in graph.edges(data=True):
        pa, pb = np.array(graph.nodes[a]["pos"]), np.array(graph.nodes[b]["pos"])
        assert data["weight"] == pytest.approx(float(np.linalg.norm(pa - pb)), rel=1e-12)
        p0, p1 = data["portal"]
        assert isinstance(p0, tuple) and len(p0) == 3 and p0 in verts and p1 in verts
        assert data["width"] == pytest.approx(math.dist(p0, p1), rel=1e-12) and data["width"] > 0
        # both polygons really share the portal's two vertices
        for poly in (a, b):
            ring = {tuple(nm.vertices[k]) for k in nm.polygons[poly] if k >= 0}
            assert {p0, p1} <= ring
    # one connected floor (walls do not cut it; the 0.3 m step is climbable)
    assert nx.is_connected(graph)
    assert sum(d["area"] for _, d in graph.nodes(data=True)) == pytest.approx(nm.areas.sum())


def test_deterministic_order():
    g1, _ = run(level())
    g2, _ = run(level())
    assert list(g1.nodes(data=True)) == list(g2.nodes(data=True))
    assert list(g1.edges(data=True)) == list(g2.edges(data=True))
    edges = list(g1.edges())
    assert all(a < b for a, b in edges) and edges == sorted(edges)


def test_params_reach_recast():
    coarse, ctx_c = run(level(), plugin.Params(cell_size=0.3, cell_height=0.2))
    fine, ctx_f = run(level())
    assert ctx_c.navmesh.stats()["cell_size"] == pytest.approx(0.3)
    assert ctx_f.navmesh.stats()["cell_size"] == pytest.approx(0.15)
    small_polys, ctx_s = run(level(), plugin.Params(verts_per_poly=3))
    assert ctx_s.navmesh.nvp == 3 and small_polys.number_of_nodes() > fine.number_of_nodes()


def test_disconnected_floors_give_components():
    mesh = trimesh.util.concatenate([slab((10, 0.2, 10), (0, -0.1, 0)), slab((10, 0.2, 10), (20, -0.1, 0))])
    graph, _ = run(mesh)
    assert nx.number_connected_components(graph) == 2


def test_nav_test_level(shared_data):
    mesh = trimesh.load(shared_data / "nav_test.obj", force="mesh")
    t0 = time.perf_counter()
    graph, ctx = run(mesh, plugin.Params(cell_size=0.3, cell_height=0.2), agent=DEMO_AGENT)
    seconds = time.perf_counter() - t0
    nm = ctx.navmesh
    components = sorted((len(c) for c in nx.connected_components(graph)), reverse=True)
    degree1 = sum(1 for _, d in graph.degree if d == 1)
    # measured with librecast 1.5.1 (Debian): 153 polygons, 151 edges, 23 degree-1,
    # 17 components: 6 areas of 6..77 polygons plus 11 single polygons (mostly the
    # insides / tops of closed boxes, which Recast keeps as walkable islands)
    assert 100 <= graph.number_of_nodes() <= 220
    assert 120 <= graph.number_of_edges() <= 180
    assert 15 <= degree1 <= 30
    assert 3 <= len(components) <= 25
    assert components[0] >= 50 and sum(components[:3]) >= 0.6 * graph.number_of_nodes()
    # several floors: the surface spans more than 10 m of height
    ys = nm.centres[:, 1]
    assert ys.max() - ys.min() > 10.0
    assert seconds < 5.0


def test_tiled_graph_follows_the_model():
    """A forced tiled build: same graph conventions, connected like the solo one, deterministic."""
    params = plugin.Params(tile_size=32)
    graph, ctx = run(level(), params)
    nm = ctx.navmesh
    solo, _ = run(level(), plugin.Params(tile_size=0))
    assert nm.tile_size == 32 and nm.tile_count > 20
    assert graph.number_of_nodes() == nm.polygon_count > solo.number_of_nodes()
    assert graph.number_of_edges() == len(nm.portals().pairs)
    assert nx.is_connected(graph) and nx.is_connected(solo)
    area = sum(d["area"] for _, d in graph.nodes(data=True))
    assert area == pytest.approx(sum(d["area"] for _, d in solo.nodes(data=True)), rel=0.03)
    verts = {tuple(v) for v in nm.vertices.tolist()}
    for a, b, data in graph.edges(data=True):
        p0, p1 = data["portal"]
        assert p0 in verts and p1 in verts  # the ends of the shared segment are mesh vertices
        assert data["width"] == pytest.approx(math.dist(p0, p1), rel=1e-12) and data["width"] > 0
        for poly in (a, b):  # ... on an edge of both polygons (seen from above)
            ring = nm.vertices[[k for k in nm.polygons[poly] if k >= 0]][:, [0, 2]]
            for p in (p0, p1):
                q = np.array(p)[[0, 2]]
                d = np.roll(ring, -1, axis=0) - ring
                t = np.clip(np.einsum("ij,ij->i", q - ring, d) / np.einsum("ij,ij->i", d, d), 0, 1)
                assert np.min(np.linalg.norm(ring + t[:, None] * d - q, axis=1)) < 1e-4
    again, _ = run(level(), params)  # tiles are built in threads: the result does not depend on it
    assert list(graph.nodes(data=True)) == list(again.nodes(data=True))
    assert list(graph.edges(data=True)) == list(again.edges(data=True))


BASE_AGENT = types.SimpleNamespace(radius=0.5, height=2.0, max_climb=0.4, max_slope=45.0)


def test_crests_are_crossed_on_the_surface():
    """Floors joined by a ramp: the segment from a ramp polygon's centre to the upper floor's cuts
    under the crest; the default graph goes over it through portal nodes, ``max_edge_gap: null`` does not."""
    mesh = levels.SAMPLES["floors_joined_by_ramp"]().mesh
    paper, ctx = run(mesh, plugin.Params(max_edge_gap=None), agent=BASE_AGENT)
    nm = ctx.navmesh
    assert list(paper) == list(range(nm.polygon_count)) and paper.number_of_edges() == len(nm.portals().pairs)
    routed, _ = run(mesh, agent=BASE_AGENT)
    added = [n for n in routed if n >= nm.polygon_count]
    assert added and list(routed)[: nm.polygon_count] == list(range(nm.polygon_count))
    for node in added:
        data = routed.nodes[node]
        assert (data["polygon"], data["area"], data["on_navmesh"]) == (-1, 0.0, True)
        assert routed.degree(node) == 2
    # Contracting the portal nodes gives back the paper's adjacency.
    contracted = routed.copy()
    for node in added:
        u, v = contracted.neighbors(node)
        contracted.remove_node(node)
        contracted.add_edge(u, v)
    assert {tuple(sorted(e)) for e in contracted.edges} == {tuple(sorted(e)) for e in paper.edges}
    paper_gaps = edge_surface_gaps(paper, nm, BASE_AGENT)
    routed_gaps = edge_surface_gaps(routed, nm, BASE_AGENT)
    assert max(paper_gaps.values()) > 0.6
    assert max(routed_gaps.values()) <= plugin.Params().max_edge_gap + 0.05  # the probes' spacing adds a little


def _crosses_in_plan(a, b, p, q) -> bool:
    """Whether the x-z segment a-b meets the x-z segment p-q (orientations; independent of the builder's clipping)."""
    def side(o, r, s):
        return (r[0] - o[0]) * (s[2] - o[2]) - (r[2] - o[2]) * (s[0] - o[0])
    return side(a, b, p) * side(a, b, q) <= 0 and side(p, q, a) * side(p, q, b) <= 0


def test_centre_segments_are_clipped_to_their_polygons():
    """Unit square A = [0, 1]², then B = [1, 2] x [0, 4] (clockwise) sharing x = 1, 0 <= z <= 1 with it:
    from A's centre (0.5, 0.5) to (1.5, 2) the segment leaves A through z = 1 at t = 1/3 and enters B at
    x = 1, t = 1/2, passing the portal's end (1, 1) outside both; to (1.5, 0.5) it crosses the portal at t = 1/2."""
    corners = [(0, 0), (1, 0), (1, 1), (0, 1), (1, 0), (1, 4), (2, 4), (2, 0)]
    navmesh = types.SimpleNamespace(
        vertices=np.array([(x, 0.0, z) for x, z in corners]),
        polygons=np.array([[0, 1, 2, 3, -1, -1], [4, 5, 6, 7, -1, -1]]),
    )
    origin = np.array([[0.5, 0.5], [0.5, 0.5]])
    direction = np.array([[1.0, 1.5], [1.0, 0.0]])
    leave = plugin._clip(navmesh, np.array([0, 0]), origin, direction, leaving=True)
    enter = plugin._clip(navmesh, np.array([1, 1]), origin, direction, leaving=False)
    assert leave.tolist() == pytest.approx([1 / 3, 0.5]) and enter.tolist() == pytest.approx([0.5, 0.5])


def test_first_largest_is_each_runs_argmax():
    """Runs [1, 3, 3], [2, nan, 5, nan], [0, 0] and [inf]: the first 3 (index 1), the first NaN (4), the first 0 (7),
    the inf (9), as np.argmax of each run gives them."""
    values = np.array([1, 3, 3, 2, np.nan, 5, np.nan, 0, 0, np.inf])
    starts = np.array([0, 3, 7, 9])
    assert plugin._first_largest(values, starts).tolist() == [1, 4, 7, 9]
    runs = np.split(values, starts[1:])
    assert [int(start + np.argmax(run)) for start, run in zip(starts, runs)] == [1, 4, 7, 9]


def two_rooms_and_a_passage() -> trimesh.Trimesh:
    """Two 4 x 4 m floors 2 m apart along x, joined along their z = 0 sides by a passage 1.5 m wide (no walls)."""
    return trimesh.util.concatenate([
        slab((4, 0.2, 4), (2, -0.1, 2)), slab((2, 0.2, 1.5), (5, -0.1, 0.75)), slab((4, 0.2, 4), (8, -0.1, 2)),
    ])


def test_corner_cuts_between_probes_are_routed():
    """With the presets' agent (r = 0.5 m) Recast makes 4 polygons: a strip along the passage and into both
    rooms, and three polygons of the rooms. The segment from the strip's centre to the first room's leaves
    the navmesh round the passage's corner for less than the crest rule's 0.25 m probe spacing; it misses its
    portal in plan, so the builder routes it through a portal node; the other pairs cross their portals and
    keep one edge (a flat floor: no crest either)."""
    mesh = two_rooms_and_a_passage()
    paper, ctx = run(mesh, plugin.Params(max_edge_gap=None), agent=BASE_AGENT)
    nm, portals = ctx.navmesh, ctx.navmesh.portals()
    starts, ends = nm.centres[portals.pairs[:, 0]], nm.centres[portals.pairs[:, 1]]
    crosses = [_crosses_in_plan(a, b, p, q) for a, b, (p, q) in zip(starts, ends, portals.endpoints)]
    assert crosses.count(False) == 1
    cut = crosses.index(False)
    step = 0.5 * BASE_AGENT.radius
    assert nm.segment_surface_gaps(starts, ends, step, 4.0).max() <= 0.4  # the crest rule's probes see nothing
    assert nm.segment_surface_gaps(starts[[cut]], ends[[cut]], 0.01, 4.0)[0] == math.inf  # finer ones do
    assert max(edge_surface_gaps(paper, nm, BASE_AGENT, step=0.01).values()) == math.inf
    routed, _ = run(mesh, agent=BASE_AGENT)
    assert [routed.has_edge(a, b) for a, b in portals.pairs.tolist()] == crosses
    assert routed.number_of_nodes() == nm.polygon_count + 1
    assert max(edge_surface_gaps(routed, nm, BASE_AGENT, step=0.01).values()) <= 0.4


def test_segment_surface_gaps_on_a_slab():
    mesh = slab((10, 0.2, 10), (0, -0.1, 0))
    _, ctx = run(mesh, plugin.Params(max_edge_gap=None))
    nm = ctx.navmesh
    A = np.array([[-2.0, 0.3, 0.0], [-2.0, 0.0, 0.0], [-2.0, 3.0, 0.0], [-2.0, 0.0, 0.0]])
    B = np.array([[2.0, 0.3, 1.0], [2.0, 0.5, 0.0], [2.0, 3.0, 0.0], [20.0, 0.0, 0.0]])
    gaps = nm.segment_surface_gaps(A, B, step=0.1, reach=1.0)
    assert gaps[0] == pytest.approx(0.3, abs=nm.settings["cell_height"])  # level, 0.3 m above
    assert gaps[1] == pytest.approx(0.5, abs=nm.settings["cell_height"])  # rising: the far end counts
    assert gaps[2] == math.inf  # 3 m above: beyond reach
    assert gaps[3] == math.inf  # runs off the slab
    # one segment at a time (the surface_los predicate's call): the same values
    assert [nm.segment_surface_gap(a, b, step=0.1, reach=1.0) for a, b in zip(A.tolist(), B.tolist())] == gaps.tolist()
    # 1,000 rows, shared between the cores in chunks: each row's value as on its own
    rng = np.random.default_rng(2)
    A, B = rng.uniform(-6, 6, (1000, 3)), rng.uniform(-6, 6, (1000, 3))
    A[:, 1], B[:, 1] = rng.uniform(-0.5, 1.5, 1000), rng.uniform(-0.5, 1.5, 1000)
    gaps = nm.segment_surface_gaps(A, B, step=0.1, reach=1.0)
    assert np.isfinite(gaps).any() and np.isinf(gaps).any()
    assert [nm.segment_surface_gap(a, b, step=0.1, reach=1.0) for a, b in zip(A.tolist(), B.tolist())] == gaps.tolist()


def test_line_of_sight_is_the_raycast_and_the_surface_gap_together():
    # surface_los's one C++ call gives what its two tests give one after the other, on a level with a ramp
    # between two floors (a segment can run clear in plan yet under the ramp) and walls
    _, ctx = run(levels.SAMPLES["floors_joined_by_ramp"]().mesh)
    nm = ctx.navmesh
    rng = np.random.default_rng(5)
    pairs = nm.portals().pairs[rng.integers(len(nm.portals().pairs), size=400)]
    A, B = nm.centres[pairs[:, 0]], nm.centres[pairs[:, 1]] + rng.uniform(-2.0, 2.0, (400, 3)) * [1, 0, 1]
    A[:100] += rng.uniform(-0.5, 0.5, (100, 3))  # and points off the surface
    for max_gap in (0.4, 0.1, None):
        expected = [nm.raycast(a, b)[0] and (max_gap is None or nm.segment_surface_gap(a, b, 0.3, max_gap) <= max_gap)
                    for a, b in zip(A.tolist(), B.tolist())]
        assert [nm.line_of_sight(a, b, 0.3, max_gap) for a, b in zip(A.tolist(), B.tolist())] == expected
        assert 0 < sum(expected) < len(expected)  # clear and blocked pairs both


def test_overlapping_regions_are_warned_about():
    stairwell = levels.SAMPLES["building"]()  # 3 storeys: watershed makes one region of the stairwell
    design = stairwell.metadata["design_agent"]
    agent = types.SimpleNamespace(radius=design["radius"], height=design["height"],
                                  max_climb=design["max_climb"], max_slope=design["max_slope_deg"])
    _, watershed = run(stairwell.mesh, plugin.Params(partition="watershed"), agent=agent)
    (warning,) = watershed.warnings
    x, y, z = watershed.navmesh.region_overlaps[0]
    assert warning.startswith("graph: Recast's watershed partition made 1 region that overlaps itself in plan")
    assert f"({x:.1f}, {y:.1f}, {z:.1f}) m" in warning and warning.endswith(
        "set graph.params.partition: auto, the default (docs/navmesh.md)")
    # the default (auto) rebuilt the overlapping tile: nothing left to warn about
    _, default = run(stairwell.mesh, agent=agent)
    assert default.warnings == [] and len(default.navmesh.region_overlaps) == 0
    assert default.navmesh.repartitioned_tiles.tolist() == [[0, 0]]
    _, flat = run(level())
    assert flat.warnings == []


def test_a_watershed_navmesh_lost_to_overlaps_names_the_partition():
    # not "no walkable surface" with hints about the mesh: the partition lost it
    with pytest.raises(G2SError) as error:
        run(spiral_tower(), plugin.Params(partition="watershed"), agent=BASE_AGENT)
    assert str(error.value).startswith("graph.params.partition: watershed: Recast: no walkable polygons (1 region(s) "
                                       "overlap themselves in plan and Recast made no polygon of them; partition "
                                       "'auto' rebuilds such regions)")


def test_islands_recast_removes_whole_name_the_settings_that_keep_them():
    """Nine squares of 2.5 m, 3 m apart: once the agent's radius (and the ledges) are taken off, each is under the
    default region_min_size (8² cells of 0.25 m); Recast keeps no region, and the line names both settings that
    decide it, not only Recast's question. region_min_size 3 keeps them (each square about 1 m²)."""
    islands = trimesh.util.concatenate([slab((2.5, 0.2, 2.5), (5.5 * i, -0.1, 5.5 * j))
                                        for i in range(3) for j in range(3)])
    with pytest.raises(G2SError) as error:
        run(islands, agent=BASE_AGENT)
    assert ("Recast: no walkable polygons (no contours; regions too small?): each walkable area left once the agent's "
            "radius is taken off is under graph.params.region_min_size (8² cells of 0.25 m, 4 m²), which Recast "
            "removes, or too small to outline in cells of 0.25 m; try a smaller graph.params.region_min_size or "
            "cell_size; the level is") in str(error.value)
    graph, _ = run(islands, plugin.Params(region_min_size=3), agent=BASE_AGENT)
    assert nx.number_connected_components(graph) == 9
