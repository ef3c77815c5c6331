"""Result writers: structure.json (schema, round trip, byte identity), run.json, GraphML, PNG, folders, CLI.

The hand-made run below uses the core's own rooting and simplification on a
small two-floor level, so the writers can be tested without the stage plugins;
the tests at the end run the real pipeline when its plugins are installed.
"""

from __future__ import annotations

import io
import json
import math
import struct
import time
from pathlib import Path

import networkx as nx
import numpy as np
import pytest
import trimesh

from g2s_core.config import AgentConfig, load_config
from g2s_core.errors import G2SError
from g2s_core.model import Opening, RunContext, RunResult, StageStats, Terminals
from g2s_core.outputs import (
    DEFAULT_FORMATS,
    check_outdir,
    parse_formats,
    result_files,
    write_outputs,
    writers,
)
from g2s_plugins.outputs import load_result
from g2s_plugins.outputs import colours, common, graphml, heatmap, structure_json
from g2s_core.pipeline import steiner_forest
from g2s_core.rooted import root_forest
from g2s_core.simplify import simplify_forest
from tests.conftest import PROJECT

PIPELINE_PLUGINS = {("graph", "navmesh"), ("terminals", "leaves"), ("steiner", "kou"), ("roots", "betweenness"),
                    ("simplify", "surface_los"), ("analyzers", "betweenness")}


# --- a hand-made run ---------------------------------------------------------------


def two_floor_mesh() -> trimesh.Trimesh:
    """Two 10 m x 6 m slabs, floor tops at Y = 0 and Y = 4."""
    low = trimesh.creation.box(extents=(10.0, 0.2, 6.0))
    low.apply_translation((5.0, -0.1, 3.0))
    high = trimesh.creation.box(extents=(6.0, 0.2, 4.0))
    high.apply_translation((3.0, 3.9, 2.0))
    return trimesh.util.concatenate([low, high])


def _timed(stages: list[StageStats], stage: str, make, counts):
    start = time.perf_counter()
    value = make()
    stages.append(StageStats(stage, time.perf_counter() - start, **counts(value)))
    return value


def make_result(navmesh=None, analysis: bool = True, waypoints: tuple[int, ...] = ()) -> RunResult:
    """A complete run on :func:`two_floor_mesh`: grid graph, corner terminals (and ``waypoints``, which the
    Steiner tree joins but which are not terminals), Steiner tree, rooted, simplified."""
    mesh = two_floor_mesh()
    stages: list[StageStats] = []
    config = load_config(PROJECT / "configs" / "map_analysis.yaml").model_dump(mode="json")
    context = RunContext(mesh=mesh, agent=AgentConfig(), centre=np.asarray(mesh.bounds).mean(axis=0), navmesh=navmesh)

    def build_graph() -> nx.Graph:
        graph = nx.Graph()
        points = [(x, 0.0, z) for x in (1.0, 3.0, 5.0, 7.0, 9.0) for z in (1.0, 3.0, 5.0)]
        points += [(x, 4.0, z) for x in (1.0, 3.0, 5.0) for z in (1.0, 3.0)]
        for node, p in enumerate(points):
            graph.add_node(node, pos=p, normal=(0.0, 1.0, -0.0), area=4.0, on_navmesh=True, polygon=node,
                           region=int(p[1] > 1.0))
        for a in graph.nodes:
            for b in graph.nodes:
                pa, pb = np.asarray(points[a]), np.asarray(points[b])
                if a < b and pa[1] == pb[1] and np.isclose(np.linalg.norm(pa - pb), 2.0):
                    graph.add_edge(a, b, weight=2.0, width=2.0)
        # a stair from the lower floor (9, 0, 5) to the upper one (5, 4, 3)
        graph.add_edge(14, 19, weight=float(np.linalg.norm(np.subtract(points[14], points[19]))), width=1.0)
        return graph

    graph = _timed(stages, "graph", build_graph, counts=lambda g: dict(nodes=len(g), edges=g.number_of_edges()))
    context.graph = graph
    opening = Opening((0.0, 0.0, 3.0), (-1.0, 0.0, 0.0), 2.0, (0.0, 0.0, 2.0), (0.0, 0.0, 4.0))
    terminals = _timed(stages, "terminals", lambda: Terminals((0, 2, 12, 20, 15, *waypoints), (opening,), waypoints),
                       counts=lambda t: dict(terminals=len(t.nodes)))
    for t in terminals.without_waypoints:
        graph.nodes[t]["terminal"] = True

    def solve(sub: nx.Graph, terms: list[int]) -> nx.Graph:
        return nx.algorithms.approximation.steiner_tree(sub, terms, weight="weight", method="kou")

    steiner = _timed(stages, "steiner", lambda: steiner_forest(graph, terminals.nodes, solve, context),
                     counts=lambda s: dict(nodes=len(s), edges=s.number_of_edges()))
    forest = _timed(stages, "roots", lambda: root_forest(steiner, nx.betweenness_centrality(steiner), context.centre),
                    counts=lambda f: {})

    def straight(tree: nx.DiGraph, a: int, b: int, c: int) -> bool:
        pa, pb, pc = (np.asarray(tree.nodes[n]["pos"]) for n in (a, b, c))
        return bool(np.allclose(np.cross(pb - pa, pc - pb), 0.0)) and pa[1] == pc[1]

    structure = _timed(stages, "simplify", lambda: simplify_forest(forest, straight),
                       counts=lambda s: dict(nodes=len(s), edges=s.number_of_edges()))
    values: dict[str, dict[int, float]] = {}
    if analysis:
        def analyse() -> dict[str, dict[int, float]]:
            undirected = structure.to_undirected(as_view=True)
            return {"betweenness": dict(nx.betweenness_centrality(undirected)),
                    "degree": {n: float(d) for n, d in undirected.degree}}
        values = _timed(stages, "analysis", analyse, counts=lambda v: {})
    context.warn("terminals <b>near</b> the edge & one more")
    return RunResult(config=config, mesh_name="two floors.obj", mesh_sha256="ab" * 32, context=context, graph=graph,
                     terminals=terminals, steiner=steiner, forest=forest, structure=structure, analysis=values,
                     stages=stages)


def real_navmesh(mesh: trimesh.Trimesh):
    """The navmesh Recast builds for ``mesh``, or a skip when the extension is not built."""
    recast = pytest.importorskip("g2s_plugins.recast", reason="the Recast extension is not built")
    return recast.build_navmesh(mesh.vertices, mesh.faces, AgentConfig())


@pytest.fixture(scope="module")
def result() -> RunResult:
    return make_result()


def _schema(name: str) -> dict:
    jsonschema = pytest.importorskip("jsonschema")
    schema = json.loads((Path(structure_json.__file__).parent / name).read_text())
    jsonschema.Draft202012Validator.check_schema(schema)
    return schema


def _validate(document: dict, name: str) -> None:
    import jsonschema

    jsonschema.Draft202012Validator(_schema(name)).validate(document)


def _same(a, b) -> bool:
    """Equal after the writers' rounding (floats to 9 significant digits, tuples as lists)."""
    if isinstance(a, (tuple, list, np.ndarray)):
        return isinstance(b, (tuple, list)) and len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b))
    if isinstance(a, (float, np.floating)) and not isinstance(a, bool):
        return b == common.number(a)
    return a == b


# --- structure.json -----------------------------------------------------------------


def test_structure_json_follows_the_shipped_schema(result, tmp_path):
    written = structure_json.write(result, tmp_path)
    assert [p.name for p in written] == ["structure.json", "run.json"]
    document = json.loads((tmp_path / "structure.json").read_text())
    _validate(document, "structure.schema.json")
    _validate(json.loads((tmp_path / "run.json").read_text()), "run.schema.json")
    assert document["schema_version"] == 3 and document["features"] == {} and document["metrics"] == {}
    assert document["mesh"] == {"name": "two floors.obj", "sha256": "ab" * 32, "vertices": 16, "faces": 24,
                                "bounds": [[0.0, -0.2, 0.0], [10.0, 4.0, 6.0]]}
    assert document["config"] == result.config
    assert document["final_stage"] == "simplify" and document["directed"] is True
    assert document["analysis_keys"] == ["betweenness", "degree"]
    assert document["roots"] == result.structure.graph["roots"]
    assert [n["id"] for n in document["nodes"]] == sorted(result.structure.nodes)
    assert document["terminals"]["node_ids"] == [0, 2, 12, 20, 15]
    assert document["terminals"]["openings"][0]["p1"] == [0.0, 0.0, 4.0]
    assert document["graphs"]["graph"] == {"nodes": 21, "edges": result.graph.number_of_edges()}
    assert document["graphs"]["steiner"]["edges"] == result.steiner.number_of_edges()
    assert [s["stage"] for s in document["stages"]] == ["graph", "terminals", "steiner", "roots", "simplify", "analysis"]
    assert document["warnings"] == ["terminals <b>near</b> the edge & one more"]
    # the trees partition the structure, and every parent link matches an edge
    assert sorted(n for t in document["trees"] for n in t["node_ids"]) == sorted(result.structure.nodes)
    parents = {n["id"]: n["parent"] for n in document["nodes"]}
    assert {(p, c) for c, p in parents.items() if p is not None} == set(result.structure.edges)


def test_structure_json_text_is_the_standard_librarys(result, waypoint_result):
    # the writer's own encoder (outputs.json_text) must give json.dumps's text of the same document
    for run in (result, waypoint_result):
        document = structure_json.structure_document(run)
        text = json.dumps(document, sort_keys=True, indent=1, ensure_ascii=False, allow_nan=False) + "\n"
        assert structure_json.dumps(document) == text.encode("utf-8")


def test_node_parents_are_the_tree_parents_with_loop_partners_skipped(result):
    from g2s_core.rooted import tree_parent

    forest = nx.DiGraph()
    forest.add_edge(2, 3, loop=True)  # 3's first predecessor is a loop partner, its tree parent is 1
    forest.add_edges_from([(0, 1), (0, 2), (1, 3), (3, 4)])
    for graph in (forest, result.structure):
        expected = {node: tree_parent(graph, node) for node in graph}
        assert {node: common.tree_parents(graph).get(node) for node in graph} == expected
    assert common.tree_parents(forest)[3] == 1
    assert common.tree_parents(nx.Graph([(0, 1)])) == {}


def test_schema_rejects_what_the_writer_must_not_write(result):
    jsonschema = pytest.importorskip("jsonschema")
    document = structure_json.structure_document(result)
    broken = json.loads(json.dumps(document))
    broken["nodes"][0]["position"] = [1.0, 2.0]
    with pytest.raises(jsonschema.ValidationError):
        _validate(broken, "structure.schema.json")
    broken = json.loads(json.dumps(document))
    broken["stages"][0]["seconds"] = 0.1
    with pytest.raises(jsonschema.ValidationError):
        _validate(broken, "structure.schema.json")


def test_round_trip_gives_back_the_same_structure(result, tmp_path):
    structure_json.write(result, tmp_path)
    loaded = load_result(tmp_path)
    original = result.structure
    assert isinstance(loaded.structure, nx.DiGraph)
    assert sorted(loaded.structure.nodes) == sorted(original.nodes)
    assert sorted(loaded.structure.edges) == sorted(original.edges)
    assert loaded.roots == original.graph["roots"] == loaded.structure.graph["roots"]
    terminals = set(result.terminals.nodes)
    for node, attrs in original.nodes(data=True):
        back = loaded.structure.nodes[node]
        for key, value in attrs.items():
            if key == "terminal":
                continue
            assert _same(value, back[key]), (node, key, value, back[key])
        assert back["terminal"] == (node in terminals)
        assert set(back) - set(attrs) <= {"terminal"}
    for u, v, attrs in original.edges(data=True):
        back = loaded.structure.edges[u, v]
        assert set(back) == set(attrs)
        assert all(_same(attrs[k], back[k]) for k in attrs)
    assert set(loaded.analysis) == set(result.analysis)
    for key, values in result.analysis.items():
        assert set(loaded.analysis[key]) == set(values)
        assert all(loaded.analysis[key][n] == common.number(v) for n, v in values.items())
    assert loaded.terminals.nodes == result.terminals.nodes
    assert loaded.terminals.openings == result.terminals.openings
    assert sorted(loaded.steiner.edges) == sorted(tuple(sorted(e)) for e in result.steiner.edges)
    assert sorted(loaded.forest.edges) == sorted(result.forest.edges)
    assert loaded.graph_size == (result.graph.number_of_nodes(), result.graph.number_of_edges())
    assert [(s.stage, s.nodes, s.edges, s.terminals) for s in loaded.stages] == \
        [(s.stage, s.nodes, s.edges, s.terminals) for s in result.stages]
    assert [s.seconds for s in loaded.stages] == [s.seconds for s in result.stages]  # from run.json
    assert loaded.warnings == result.warnings and loaded.config == result.config
    # without run.json the counts stay and the times are unknown
    (tmp_path / "run.json").unlink()
    assert all(math.isnan(s.seconds) for s in load_result(tmp_path / "structure.json").stages)


def test_structure_json_is_byte_identical_for_the_same_input(tmp_path):
    first, second = make_result(), make_result()
    assert [s.seconds for s in first.stages] != [s.seconds for s in second.stages]  # the runs really differ in time
    for run, name in ((first, "a"), (second, "b")):
        (tmp_path / name).mkdir()
        structure_json.write(run, tmp_path / name)
    a, b = (tmp_path / "a" / "structure.json").read_bytes(), (tmp_path / "b" / "structure.json").read_bytes()
    assert a == b
    assert b"seconds" not in a and a.endswith(b"\n")
    assert (tmp_path / "a" / "run.json").read_bytes() != (tmp_path / "b" / "run.json").read_bytes()


def test_numbers_are_rounded_to_nine_significant_digits():
    assert common.number(1 / 3) == 0.333333333
    assert common.number(123456.7891234) == 123456.789
    assert math.copysign(1.0, common.number(-0.0)) == 1.0
    assert common.number(float("nan")) is None and common.number(float("inf")) is None
    assert common.number(np.float32(0.1)) == 0.100000001


def test_coordinates_keep_ten_micrometres_far_from_the_origin():
    assert common.coordinate(9999.123456789) == 9999.12346  # under 10^4 m: 9 significant digits, as number
    assert common.coordinate(123456.7891234) == 123456.78912
    assert common.vector((-1.0e7 - 0.123456, 0.5, float("nan"))) == [-10000000.12346, 0.5, None]


def test_load_result_refuses_other_files(tmp_path):
    path = tmp_path / "structure.json"
    with pytest.raises(G2SError, match="no such structure file"):
        load_result(path)
    path.write_text("{not json")
    with pytest.raises(G2SError, match="invalid JSON at line 1"):
        load_result(path)
    path.write_text(json.dumps({"format": "g2s-structure", "schema_version": 4}))
    with pytest.raises(G2SError, match="schema_version 4 is not supported"):
        load_result(path)
    path.write_text(json.dumps({"nodes": []}))
    with pytest.raises(G2SError, match="not a g2s structure.json"):
        load_result(path)


def test_navmesh_statistics_without_timings(tmp_path):
    mesh = two_floor_mesh()
    run = make_result(navmesh=real_navmesh(mesh))
    document = structure_json.structure_document(run)
    stats = run.context.navmesh.stats()
    assert document["navmesh"]["polygons"] == stats["polygons"] >= 2
    assert "build_seconds" not in document["navmesh"]
    assert structure_json.run_document(run)["navmesh"] == {"build_seconds": stats["build_seconds"]}
    _validate(document, "structure.schema.json")


def test_runs_stopped_early_still_describe_their_last_graph(result):
    early = RunResult(config=result.config, mesh_name="m", mesh_sha256="0" * 64, context=result.context,
                      graph=result.graph, stages=result.stages[:1])
    document = structure_json.structure_document(early)
    assert document["final_stage"] == "graph" and document["directed"] is False
    assert len(document["nodes"]) == 21 and document["trees"] == [] and document["terminals"] is None
    assert all(e["source"] < e["target"] for e in document["edges"])
    _validate(document, "structure.schema.json")


# --- GraphML --------------------------------------------------------------------------


def test_graphml_flattens_attributes(result, tmp_path):
    written = graphml.write(result, tmp_path)
    assert [p.name for p in written] == ["structure.graphml", "graph.graphml"]
    structure = nx.read_graphml(tmp_path / "structure.graphml", node_type=int)
    assert structure.is_directed()
    assert sorted(structure.nodes) == sorted(result.structure.nodes)
    assert sorted(structure.edges) == sorted(result.structure.edges)
    for node, attrs in result.structure.nodes(data=True):
        back = structure.nodes[node]
        assert (back["pos_x"], back["pos_y"], back["pos_z"]) == tuple(common.number(v) for v in attrs["pos"])
        assert back["normal_z"] == 0.0 and back["depth"] == attrs["depth"] and back["root"] == attrs["root"]
        assert back["value_betweenness"] == common.number(result.analysis["betweenness"][node])
        assert back["terminal"] == (node in result.terminals.nodes)
        parents = list(result.structure.predecessors(node))
        assert back.get("parent") == (parents[0] if parents else None)
    assert structure.graph["roots"] == ",".join(map(str, result.structure.graph["roots"]))
    assert structure.graph["mesh_sha256"] == "ab" * 32
    graph = nx.read_graphml(tmp_path / "graph.graphml", node_type=int)
    assert not graph.is_directed()
    assert graph.number_of_nodes() == 21 and graph.number_of_edges() == result.graph.number_of_edges()
    assert graph.edges[14, 19]["width"] == 1.0


def test_flatten_handles_arrays_and_none():
    flat = graphml.flatten({"pos": np.array([1.0, 2.0, 3.0]), "portal": ((0, 0, 0), (1.5, 0, 2)), "ids": [4, 5],
                            "gone": None, "flag": np.bool_(True), "n": np.int64(7), "name": "x"})
    assert flat == {"pos_x": 1.0, "pos_y": 2.0, "pos_z": 3.0, "portal_0_x": 0.0, "portal_0_y": 0.0, "portal_0_z": 0.0,
                    "portal_1_x": 1.5, "portal_1_y": 0.0, "portal_1_z": 2.0, "ids_0": 4, "ids_1": 5, "flag": True,
                    "n": 7, "name": "x"}
    assert all(type(v) in (bool, int, float, str) for v in flat.values())


# --- PNG ------------------------------------------------------------------------------


def _png_chunks(data: bytes) -> list[tuple[bytes, bytes]]:
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    chunks, offset = [], 8
    while offset < len(data):
        (length,) = struct.unpack(">I", data[offset:offset + 4])
        chunks.append((data[offset + 4:offset + 8], data[offset + 8:offset + 8 + length]))
        offset += 12 + length
    return chunks


def test_heatmap_png_has_a_panel_per_floor_and_no_metadata(result, tmp_path):
    assert [len(g) for g in heatmap.floor_groups(result.structure, 2.0)] == [
        sum(1 for n in result.structure if result.structure.nodes[n]["pos"][1] < 1.0),
        sum(1 for n in result.structure if result.structure.nodes[n]["pos"][1] > 1.0)]
    path, = heatmap.write(result, tmp_path)
    data = path.read_bytes()
    chunks = _png_chunks(data)
    kinds = [kind for kind, _ in chunks]
    assert kinds[0] == b"IHDR" and kinds[-1] == b"IEND"
    assert not {b"tEXt", b"iTXt", b"zTXt", b"tIME"} & set(kinds), kinds
    width, height = struct.unpack(">II", chunks[0][1][:8])
    assert width == round((2 * heatmap.PANEL_INCHES + 1.2) * heatmap.DPI)  # two floors side by side + colour bar
    assert height == round(heatmap.PANEL_INCHES * heatmap.DPI)
    assert heatmap.render(result) == data  # deterministic
    one_floor = heatmap.floor_groups(result.structure, 10.0)
    assert len(one_floor) == 1
    # the ground under each floor: the upward faces of its slab (two triangles each), seen as X/Z
    ground = heatmap._ground(result, result.structure, heatmap.floor_groups(result.structure, 2.0),
                             heatmap._walkable(result))
    assert [g.shape for g in ground] == [(2, 3, 2), (2, 3, 2)]
    assert np.allclose(ground[0].reshape(-1, 2).max(axis=0), [10.0, 6.0])
    assert np.allclose(ground[1].reshape(-1, 2).max(axis=0), [6.0, 4.0])


# --- floors: storeys told apart by the walkable area at each height --------------------------------------


def _rectangle(x0: float, x1: float, z0: float, z1: float, y0: float, y1: float | None = None) -> np.ndarray:
    """(2, 3, 3) the two triangles of a rectangle in plan, at height ``y0`` (rising along x to ``y1``)."""
    y1 = y0 if y1 is None else y1
    a, b, c, d = (x0, y0, z0), (x1, y1, z0), (x1, y1, z1), (x0, y0, z1)
    return np.array([[a, b, c], [a, c, d]], dtype=np.float64)


def test_floors_split_two_storeys_joined_by_a_ramp_of_evenly_spaced_nodes():
    # 10 x 10 m floors at y = 0 and y = 4 joined by a 2 m wide ramp rising 4 m over 10 m: 200 m² flat, 21.5 m²
    # of ramp spread over 4 m, so 0.27 m² (0.12 %) in each 0.1 m bin; the nodes climb the ramp every 0.5 m
    ground = np.concatenate([_rectangle(0, 10, 0, 10, 0.0), _rectangle(10, 20, 4, 6, 0.0, 4.0),
                             _rectangle(20, 30, 0, 10, 4.0)])
    heights = [0.0, 0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0, 4.0]
    assert [g.tolist() for g in common.floors(heights, 2.0)] == [list(range(11))]  # the gap rule: one floor
    # the nodes up to 2.0 m are nearer the lower storey (1.9 m from its 0-0.1 m band) than the upper (4-4.1 m)
    assert [g.tolist() for g in common.floors(heights, 2.0, ground)] == [[0, 1, 2, 3, 4, 5], [6, 7, 8, 9, 10]]


@pytest.mark.parametrize("lower", [-4.7, -4.2, -3.6, -2.3, -1.3, -0.7])
def test_floors_exactly_an_agent_height_apart_stay_two_in_single_precision(lower):
    # storeys 2.0 m apart (the agent's height) at round heights, as the navmesh gives them in float32: the upper
    # reads 1e-7 m under its round height, and its 0.1 m bin was one short of the lower's + 20: one panel
    # (robust5, 4 December 2026: 20 of 10,000 placements from -5 to 5 m in steps of 1 mm merged)
    low, high = float(np.float32(lower)), float(np.float32(lower + 2.0))
    assert high - low < 2.0
    ground = np.concatenate([_rectangle(0, 10, 0, 10, low), _rectangle(12, 22, 0, 10, high)])
    floors = common.floors([low] * 3 + [high] * 3, 2.0, ground)
    assert [g.tolist() for g in floors] == [[0, 1, 2], [3, 4, 5]]


def test_floors_keep_a_hill_in_one_floor():
    # a 60 x 60 m heightfield, y = 6 sin(x / 9) cos(z / 9) on a 2 m grid: 12 m of relief, every slope under
    # 45 degrees; its area spreads over the heights, no 0.1 m bin holds 1 % of it
    x, z = np.meshgrid(np.arange(0.0, 62.0, 2.0), np.arange(0.0, 62.0, 2.0), indexing="ij")
    y = 6.0 * np.sin(x / 9.0) * np.cos(z / 9.0)
    corners = np.stack([x, y, z], axis=-1)
    a, b, c, d = corners[:-1, :-1], corners[1:, :-1], corners[1:, 1:], corners[:-1, 1:]
    ground = np.concatenate([np.stack([a, b, c], axis=2), np.stack([a, c, d], axis=2)]).reshape(-1, 3, 3)
    heights = y.reshape(-1)
    assert len(common.floors(heights, 2.0, ground)) == 1


def test_floors_keep_splitting_at_a_gap_in_the_node_heights():
    # today's case: floors 3 m apart with nothing between, and a 2 x 2 m platform 6 m up holding 0.4 % of the
    # area (no storey by its area) but 3 m above the nearest node: three floors, with or without the ground
    ground = np.concatenate([_rectangle(0, 30, 0, 15, 0.0), _rectangle(0, 30, 0, 15, 3.0), _rectangle(0, 2, 0, 2, 6.0)])
    heights = [3.0, 0.0, 6.0, 0.1, 3.1]
    expected = [[1, 3], [0, 4], [2]]
    assert [g.tolist() for g in common.floors(heights, 2.0)] == expected
    assert [g.tolist() for g in common.floors(heights, 2.0, ground)] == expected


def test_floors_keep_a_landing_far_from_every_storey_whole():
    # storeys 10 m apart (the mine kind's levels), a 2 x 2 m landing half way whose nodes (5.0 and 5.1 m) are
    # nearer the lower and the upper storey: more than an agent height from both, it stays one floor
    ground = np.concatenate([_rectangle(0, 20, 0, 20, 0.0), _rectangle(0, 20, 0, 20, 10.0), _rectangle(0, 2, 0, 2, 5.0)])
    heights = [0.0, 10.0, 5.0, 5.1, 0.0]
    assert [g.tolist() for g in common.floors(heights, 2.0, ground)] == [[0, 4], [2, 3], [1]]


def test_heatmap_colours_follow_the_values(tmp_path):
    """Values on viridis: dark purple lowest, yellow highest; depth colours as in the paper."""
    assert colours.heat_colour(0.0) == (68, 1, 84) and colours.heat_colour(1.0) == (253, 231, 37)
    assert colours.plotly_heat_scale()[0] == [0.0, "rgb(68,1,84)"] and colours.plotly_heat_scale()[-1][0] == 1.0
    assert list(colours.normalise([2.0, 4.0, 3.0])) == [0.0, 1.0, 0.5]
    assert list(colours.normalise([5.0, 5.0])) == [0.0, 0.0]
    assert colours.depth_colour(1) == (220, 30, 30) and colours.depth_colour(2) == (240, 200, 0)
    assert colours.depth_colour(1 + len(colours.DEPTH_COLOURS)) == colours.depth_colour(1)
    assert colours.ROOT_COLOUR not in colours.DEPTH_COLOURS  # roots never share a colour with a depth


def test_heatmap_marks_terminals_and_openings_and_explains_dashed_edges(result):
    from matplotlib.image import imread

    groups = heatmap.floor_groups(result.structure, 2.0)
    labels = [h.get_label() for h in heatmap._legend_handles(result, result.structure, groups)]
    assert labels == ["root", "terminal", "opening", "edge to another floor (stairs, ramp or drop)"]
    points, segments = heatmap._terminals_by_floor(result, result.structure, groups)
    assert [len(p) for p in points] == [3, 2] and [len(s) for s in segments] == [1, 0]  # the opening is downstairs
    pixels = (imread(io.BytesIO(heatmap.render(result)))[:, :, :3] * 255).round()
    vermilion = np.all(np.abs(pixels - colours.TERMINAL_COLOUR) <= 2, axis=-1)
    assert vermilion.sum() > 200  # the squares and the opening's bar are drawn


# --- waypoints: nodes the Steiner tree joins that are not terminals -------------------------

WAYPOINTS = (4, 7, 10)
"""The waypoints of the hand-made run with waypoints: simplification drops 4 and 7 and keeps 10."""
TERMINALS = [0, 2, 12, 20, 15]
"""Its terminals, in the selector's order (those of :func:`make_result`)."""


@pytest.fixture(scope="module")
def waypoint_result() -> RunResult:
    return make_result(waypoints=WAYPOINTS)


def test_structure_json_and_graphml_record_waypoints_apart_from_the_terminals(waypoint_result, result, tmp_path):
    run = waypoint_result
    assert [w for w in WAYPOINTS if w in run.structure] == [10]  # simplification may drop waypoints
    assert common.terminal_ids(run) == TERMINALS
    document = structure_json.structure_document(run)
    _validate(document, "structure.schema.json")
    assert document["terminals"]["node_ids"] == TERMINALS and document["terminals"]["waypoint_ids"] == [4, 7, 10]
    assert {r["id"] for r in document["nodes"] if r["terminal"]} == set(TERMINALS) & set(run.structure)
    assert "waypoint_ids" not in structure_json.structure_document(result)["terminals"]  # only when there are any
    graphml.write(run, tmp_path)
    for name in ("structure.graphml", "graph.graphml"):
        flags = nx.get_node_attributes(nx.read_graphml(tmp_path / name, node_type=int), "terminal")
        assert {n for n, flag in flags.items() if flag} == set(TERMINALS) & set(flags), name


def test_load_result_gives_back_the_terminals_and_the_waypoints(waypoint_result, tmp_path):
    run = waypoint_result
    structure_json.write(run, tmp_path)
    loaded = load_result(tmp_path)
    assert loaded.terminals.nodes == (*TERMINALS, *WAYPOINTS)  # the terminals, then the waypoints
    assert loaded.terminals.waypoints == run.terminals.waypoints == WAYPOINTS
    assert loaded.terminals.without_waypoints == run.terminals.without_waypoints == tuple(TERMINALS)
    assert dict(loaded.structure.nodes(data="terminal")) == dict(run.structure.nodes(data="terminal", default=False))
    document = json.loads((tmp_path / "structure.json").read_text())
    document["terminals"]["waypoint_ids"] = [4, 12]
    (tmp_path / "structure.json").write_text(json.dumps(document))
    with pytest.raises(G2SError, match=r"terminals\.waypoint_ids: node 12 is also in terminals\.node_ids"):
        load_result(tmp_path)


def test_heatmap_marks_the_terminals_not_the_waypoints(waypoint_result):
    groups = heatmap.floor_groups(waypoint_result.structure, 2.0)
    points, _ = heatmap._terminals_by_floor(waypoint_result, waypoint_result.structure, groups)
    expected = [tuple(waypoint_result.graph.nodes[t]["pos"]) for t in TERMINALS]
    assert sorted(map(tuple, np.concatenate(points).tolist())) == sorted(expected)
    labels = [h.get_label() for h in heatmap._legend_handles(waypoint_result, waypoint_result.structure, groups)]
    assert labels == ["root", "terminal", "opening", "edge to another floor (stairs, ramp or drop)"]


def test_html_report_marks_the_terminals_not_the_waypoints(waypoint_result):
    from g2s_plugins.outputs import html_report

    figure = html_report.build_figure(waypoint_result)
    squares, = [t for t in figure.data if t.name == html_report.LAYER_TERMINALS and t.mode == "markers"]
    assert [text.split("<br>")[0] for text in squares.text] == [f"node {t} (terminal)" for t in TERMINALS]
    markers = [trace for trace in figure.data if getattr(trace, "mode", "") == "markers"]
    heads = {text.split("<br>")[0] for trace in markers for text in trace.text or ()}
    waypoint_heads = {head for head in heads if head.split(" (")[0] in {f"node {w}" for w in WAYPOINTS}}
    assert waypoint_heads and not any("terminal" in head for head in waypoint_heads)  # hovered, not a terminal
    # the count is of terminals; the waypoints step 2's #N also counts are named beside it
    assert (f"<dt>terminals</dt><dd>5 (and {len(set(WAYPOINTS))} waypoints the structure also joins)</dd>"
            in html_report.render(waypoint_result))


# --- folders and formats ------------------------------------------------------------------


def test_parse_formats():
    assert parse_formats("json, html,,PNG") == ["json", "html", "png"]
    with pytest.raises(G2SError, match="--format: 'json' is given twice"):  # as --evaluate refuses a name twice
        parse_formats("json,html,JSON")
    assert parse_formats(["glb"]) == ["glb"]
    with pytest.raises(G2SError, match="--format: unknown output format 'pdf'"):
        parse_formats("json,pdf")
    with pytest.raises(G2SError, match="no output format"):
        parse_formats(" , ")
    assert DEFAULT_FORMATS == ("json", "html")
    assert set(writers()) == set(result_files()) >= {"json", "html", "glb", "graphml", "png"}


def test_existing_results_are_refused_without_force_and_stale_ones_removed_with_it(result, tmp_path):
    out = tmp_path / "out"
    check_outdir(out, ["json"], force=False)
    assert not out.exists()  # checking creates nothing
    write_outputs(result, out, ["png"])
    (out / "notes.txt").write_text("mine")
    with pytest.raises(G2SError, match=r"already holds results \(heatmap.png\); use --force"):
        write_outputs(result, out, ["json"])  # a result of *another* format counts too
    written = write_outputs(result, out, ["json"], replace=True)
    assert sorted(p.name for p in out.iterdir()) == ["notes.txt", "run.json", "structure.json"]
    assert [p.name for p in written] == ["structure.json", "run.json"]
    assert not list(out.glob(".*.tmp"))


def test_the_input_mesh_is_never_a_result(tmp_path):
    mesh = tmp_path / "structure.glb"
    two_floor_mesh().export(mesh)
    before = mesh.read_bytes()
    for force in (False, True):
        with pytest.raises(G2SError, match="has the name of a result file"):
            check_outdir(tmp_path, ["json"], force=force, protect=[mesh])
    assert mesh.read_bytes() == before
    with pytest.raises(G2SError, match="is not a folder"):
        check_outdir(mesh, ["json"], force=True)


# --- the command line ---------------------------------------------------------------------


def g2s(capsys, *args: str) -> tuple[int, str, str]:
    """Run the CLI in this process: (exit code, stdout, stderr)."""
    from g2s_core import cli

    capsys.readouterr()
    code = cli.main(list(args))
    out, err = capsys.readouterr()
    return code, out, err


def test_cli_refuses_bad_formats_and_existing_results_before_running(tmp_path, capsys):
    code, out, err = g2s(capsys, "run", "configs/map_analysis.yaml", "sample:straight_corridor", "-o",
                         str(tmp_path / "o"), "--format", "json,pdf")
    assert code == 2 and out == "" and err.strip().splitlines() == [
        "g2s: error: --format: unknown output format 'pdf' (expected some of: glb, graph, graphml, html, json, png)"]
    assert not (tmp_path / "o").exists()
    config = tmp_path / "c.yaml"
    config.write_text("extends: map_analysis\noutputs: {formats: [json, gif]}\n")
    code, _, err = g2s(capsys, "run", str(config), "sample:straight_corridor", "-o", str(tmp_path / "o"))
    assert code == 2 and "c.yaml: outputs.formats: unknown output format 'gif'" in err
    out_dir = tmp_path / "old"
    out_dir.mkdir()
    (out_dir / "report.html").write_text("earlier")
    code, _, err = g2s(capsys, "run", "configs/map_analysis.yaml", "sample:straight_corridor", "-o", str(out_dir),
                       "--format", "json")
    assert code == 2 and "already holds results (report.html); use --force" in err
    assert (out_dir / "report.html").read_text() == "earlier"


def test_each_format_writes_exactly_its_result_files(result, tmp_path):
    for fmt in writers():
        folder = tmp_path / fmt
        folder.mkdir()
        written = write_outputs(result, folder, [fmt])
        assert tuple(p.name for p in written) == result_files()[fmt]
        assert sorted(p.name for p in folder.iterdir()) == sorted(result_files()[fmt])
        assert all(p.stat().st_mode & 0o044 == 0o044 for p in written)  # readable by others (umask 022)


def _plugins_missing() -> str | None:
    from g2s_core.registry import Registry

    installed = {(p.stage, p.name) for p in Registry.from_entry_points().plugins()}
    missing = sorted(f"{s}.{n}" for s, n in PIPELINE_PLUGINS - installed)
    return f"stage plugins not installed yet: {', '.join(missing)}" if missing else None


needs_plugins = pytest.mark.skipif(_plugins_missing() is not None, reason=str(_plugins_missing()))


@needs_plugins
def test_real_run_json_is_deterministic_and_valid(tmp_path):
    from g2s_core import pipeline
    from g2s_plugins.samples import levels as samples
    from g2s_core.mesh import mesh_sha256
    from g2s_core.registry import Registry

    registry = Registry.from_entry_points()
    plan = pipeline.plan(load_config(PROJECT / "configs" / "map_analysis.yaml"), registry)
    level = samples.cross_hub()
    outputs = []
    for name in ("a", "b"):
        run = pipeline.run(plan, registry, level.mesh, level.name, mesh_sha256(level.mesh))
        (tmp_path / name).mkdir()
        outputs.append(write_outputs(run, tmp_path / name, ["json", "graphml", "png"]))
    assert (tmp_path / "a" / "structure.json").read_bytes() == (tmp_path / "b" / "structure.json").read_bytes()
    assert (tmp_path / "a" / "heatmap.png").read_bytes() == (tmp_path / "b" / "heatmap.png").read_bytes()
    document = json.loads((tmp_path / "a" / "structure.json").read_text())
    _validate(document, "structure.schema.json")
    assert document["navmesh"]["polygons"] > 0 and document["final_stage"] == "simplify"
    assert document["analysis_keys"] == ["flow"]
    loaded = load_result(tmp_path / "a")
    assert sorted(loaded.structure.edges) == sorted(run.structure.edges)
    assert loaded.analysis["flow"] == {n: common.number(v) for n, v in run.analysis["flow"].items()}


@needs_plugins
def test_cli_run_writes_the_chosen_formats_and_a_json_summary(tmp_path, capsys):
    out_dir = tmp_path / "out"
    code, out, err = g2s(capsys, "run", "configs/map_analysis.yaml", "sample:cross_hub", "-o", str(out_dir), "--json")
    assert code == 0, err
    summary = json.loads(out)
    assert summary["formats"] == ["json", "html"]  # base.yaml's default
    assert sorted(Path(f).name for f in summary["files"]) == ["report.html", "run.json", "structure.json"]
    assert summary["final"]["stage"] == "simplify" and summary["final"]["analysis"] == ["flow"]
    assert err == ""
    code, out, err = g2s(capsys, "run", "configs/map_analysis.yaml", "sample:cross_hub", "-o", str(out_dir),
                         "--format", "glb,png", "--quiet", "--force")
    assert code == 0 and out == "" and err == ""
    assert sorted(p.name for p in out_dir.iterdir()) == ["heatmap.png", "structure.glb"]  # the old json/html went
    code, out, err = g2s(capsys, "run", "configs/map_analysis.yaml", "sample:cross_hub", "-o", str(out_dir), "--force",
                         "--format", "graphml")
    assert code == 0 and "Step 5" in out and f"wrote {out_dir / 'structure.graphml'}" in out


@needs_plugins
def test_demo_writes_all_five_formats_and_they_agree(tmp_path, capsys):
    import trimesh as _trimesh

    out_dir = tmp_path / "demo"
    code, out, err = g2s(capsys, "demo", "-o", str(out_dir), "--rooms", "6")
    assert code == 0, err
    expected = sorted(name for fmt in ("json", "html", "glb", "graphml", "png") for name in result_files()[fmt])
    assert sorted(p.name for p in out_dir.iterdir()) == expected
    assert f"open {out_dir / 'report.html'} in a web browser" in out
    loaded = load_result(out_dir)
    scene = _trimesh.load(out_dir / "structure.glb")
    names = set(scene.graph.nodes_geometry)
    assert {"level_mesh", "navmesh_surface"} <= names and any(n.startswith("edges_value_") for n in names)
    assert {n for n in names if n.startswith("root_")} == {f"root_{r}" for r in loaded.roots}
    assert {n for n in names if n.startswith("node_")} == {f"node_{n}" for n in loaded.structure}
    terminals = loaded.terminals.without_waypoints
    assert {n for n in names if n.startswith("terminal_")} == {f"terminal_{t}" for t in terminals}
    graph = nx.read_graphml(out_dir / "structure.graphml", node_type=int)
    assert sorted(graph.edges) == sorted(loaded.structure.edges)
    assert {n: d["value_flow"] for n, d in graph.nodes(data=True)} == loaded.analysis["flow"]


def test_heatmap_colour_bar_ticks_whole_numbers_for_whole_number_values():
    """A depth scale 0-3 shows ticks 0, 1, 2, 3, not 0.5 ... 2.5 (map_piece on the shared Hallway did, 6 December 2026)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.colors import Normalize
    from matplotlib.figure import Figure

    def ticks(values: list[float]) -> list[float]:
        figure = Figure()
        FigureCanvasAgg(figure)
        ax = figure.subplots()
        points = ax.scatter(values, values, c=values, norm=Normalize(min(values), max(values)))
        bar = heatmap.colour_bar(figure, points, [ax], "depth", values)
        figure.canvas.draw()
        low, high = min(values), max(values)
        return [t for t in bar.get_ticks() if low <= t <= high]

    assert ticks([0.0, 1.0, 2.0, 3.0]) == [0.0, 1.0, 2.0, 3.0]
    assert any(not t.is_integer() for t in ticks([0.0, 0.25, 1.5, 3.0]))  # a real-valued scale keeps its ticks


def test_colour_bars_say_the_flow_heat_map_is_percentile_ranks():
    """The map-analysis presets' flow is a percentile rank (0-100), not a count; other values keep their name."""
    from types import SimpleNamespace

    from g2s_core.config import resolve_config

    config = resolve_config("map_analysis")[0].model_dump(mode="json")
    ranked = SimpleNamespace(config=config)
    assert common.value_title(ranked, "flow") == "flow, percentile rank 0-100"
    assert common.value_title(ranked, "betweenness") == "betweenness"
    config["analyzers"][0]["params"]["aggregate"] = "mean"
    assert common.value_title(ranked, "flow") == "flow"  # a mean of shares has no such unit


@pytest.mark.parametrize("mesh, preset, floors", [
    ("sample:straight_corridor", "map_piece", 1), ("sample:two_floors", "map_piece", 2),
    ("sample:two_storey", "map_piece", 2), ("sample:building", "map_piece", 3),
    ("sample:building?floors=4", "map_piece", 4), ("sample:building?floors=5", "map_analysis", 5),
    ("Ramp.obj", "map_piece", 3), ("Ramp.obj", "demo", 2), ("sample:dungeon?seed=0&rooms=8", "demo", 1),
    ("sample:dungeon?seed=1", "level_regions", 1)])
def test_heatmap_draws_no_text_past_the_canvas(mesh, preset, floors, shared_data):
    """Every panel's, the colour bar's and the legend's tight box lies on the canvas after a draw, for 1 to 5
    floors (panels in one row and in two, with and without a colour bar). Before: the shared Ramp.obj's y label
    started 5.4 px left of the canvas (10.4 px with the demo preset), a ``−10.0`` tick label having come into view
    after the layout had set the margins; keeping the aspect by the box under the layout instead cut the demo
    preset's 8-room dungeon by 4.8 px; the legend's five entries in one row overran a one-panel canvas by
    39.4 px on each side (level_regions, dungeon seed 1)."""
    from g2s_core import api

    source = str(shared_data / "pieces" / mesh) if mesh.endswith(".obj") else mesh
    figure = heatmap.figure_of(api.run(source, preset))
    figure.canvas.draw()
    renderer = figure.canvas.get_renderer()
    shown = [ax for ax in figure.axes if ax.get_visible()]
    assert len([ax for ax in shown if ax.get_label() != "<colorbar>"]) == floors
    assert len(figure.legends) == 1
    for part in shown + list(figure.legends):
        box = part.get_tightbbox(renderer)
        assert min(box.x0, box.y0) >= 0.0 and box.x1 <= figure.bbox.width and box.y1 <= figure.bbox.height, (
            mesh, part, box)
