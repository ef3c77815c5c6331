"""TerminalSelector plugins: leaves, metric, points."""

from __future__ import annotations

import json

import networkx as nx
import numpy as np
import pytest
from pydantic import ValidationError

from g2s_core.config import AgentConfig
from g2s_core.errors import G2SError
from g2s_core.model import RunContext, Terminals
from g2s_plugins.terminals import leaves, metric, points


def context(navmesh=None) -> RunContext:
    return RunContext(mesh=None, agent=AgentConfig(), centre=np.zeros(3), navmesh=navmesh)


def surface_graph(graph: nx.Graph, spacing: float = 1.0) -> nx.Graph:
    """Give every node a pos on the floor (x = id * spacing) and the surface attributes."""
    for node in graph.nodes:
        graph.nodes[node].update(
            pos=(float(node) * spacing, 0.0, 0.0), normal=(0.0, 1.0, 0.0), area=1.0, on_navmesh=True, polygon=node
        )
    for u, v in graph.edges:
        graph.edges[u, v]["weight"] = abs(u - v) * spacing
    return graph


def select(module, graph, **params) -> Terminals:
    return module.g2s_select_terminals(graph=graph, params=module.Params(**params), context=context())


# --- leaves ------------------------------------------------------------------------------


def test_leaves_are_degree_one_nodes_sorted():
    graph = nx.union(nx.star_graph(4), nx.path_graph(range(10, 14)))  # star 0..4, path 10..13
    graph.add_node(20)  # isolated: degree 0, not a leaf
    graph.add_edge(30, 30)  # self-loop only: degree 2, not a leaf
    assert select(leaves, graph) == Terminals(nodes=(1, 2, 3, 4, 10, 13))


def test_leaves_of_a_cycle_are_none():
    assert select(leaves, nx.cycle_graph(5)).nodes == ()


def test_one_leaf_warns_that_the_structure_is_one_node():
    graph = nx.cycle_graph(6)  # a ring of streets with one dead-end alley
    graph.add_edge(0, 6)
    run = context()
    assert leaves.g2s_select_terminals(graph=graph, params=leaves.Params(), context=run).nodes == (6,)
    assert run.warnings == ["leaves: the graph's 7 nodes have one dead end, so the structure is that node; a level "
                            "of loops has almost none, and the coverage terminal selector (the map_analysis preset) "
                            "reaches every area"]
    two = context()
    leaves.g2s_select_terminals(graph=nx.path_graph(3), params=leaves.Params(), context=two)
    assert two.warnings == []


# --- metric ------------------------------------------------------------------------------


def test_metric_top_k_betweenness_picks_the_middle_of_a_path():
    assert select(metric, nx.path_graph(5), metric="betweenness", top_k=1).nodes == (2,)
    assert select(metric, nx.path_graph(5), metric="betweenness", top_k=3).nodes == (1, 2, 3)


def test_metric_selects_per_component():
    graph = nx.union(nx.path_graph(5), nx.path_graph(range(10, 13)))
    assert select(metric, graph, metric="betweenness", top_k=1).nodes == (2, 11)
    assert select(metric, graph, metric="closeness", top_k=1).nodes == (2, 11)
    # 0.4 of 5 nodes -> 2 (ties 1 and 3 after node 2: lower id first); 0.4 of 3 -> ceil(1.2) = 2
    assert select(metric, graph, metric="betweenness", top_fraction=0.4).nodes == (1, 2, 10, 11)


def test_metric_top_fraction_rounds_up_without_float_noise():
    graph = nx.path_graph(10)
    assert len(select(metric, graph, metric="degree", top_fraction=0.3).nodes) == 3  # 0.3 * 10 is 3.0000000000000004
    assert len(select(metric, graph, metric="degree", top_fraction=0.31).nodes) == 4


def test_metric_threshold_uses_the_metric_values():
    star = nx.star_graph(4)  # centre betweenness 1.0, leaves 0.0
    assert select(metric, star, metric="betweenness", threshold=0.5).nodes == (0,)
    assert select(metric, star, metric="betweenness", threshold=0.0).nodes == (0, 1, 2, 3, 4)
    # degree centrality: centre 4/4 = 1, leaves 1/4
    assert select(metric, star, metric="degree", threshold=0.25).nodes == (0, 1, 2, 3, 4)
    assert select(metric, star, metric="degree", threshold=0.26).nodes == (0,)


def test_metric_ties_are_broken_by_node_id():
    cycle = nx.relabel_nodes(nx.cycle_graph(6), {i: 10 - i for i in range(6)})  # ids 5..10, all equivalent
    for name in ("betweenness", "closeness", "degree", "eigenvector", "katz"):
        assert select(metric, cycle, metric=name, top_k=2).nodes == (5, 6), name


def test_metric_degree_filter_is_the_hybrid_strategy():
    # a "broom": path 0-1-2-3 then a star at 3 with leaves 4, 5, 6
    broom = nx.Graph([(0, 1), (1, 2), (2, 3), (3, 4), (3, 5), (3, 6)])
    assert select(metric, broom, metric="betweenness", top_k=1).nodes == (3,)
    # among degree-2 nodes, the most between is 2
    assert select(metric, broom, metric="betweenness", top_k=1, min_degree=2, max_degree=2).nodes == (2,)
    # among leaves, closeness ranks 4, 5, 6 (equal, nearer the rest) above 0
    assert select(metric, broom, metric="closeness", top_k=3, max_degree=1).nodes == (4, 5, 6)
    assert select(metric, broom, metric="closeness", top_fraction=1.0, max_degree=1).nodes == (0, 4, 5, 6)
    assert select(metric, broom, metric="degree", top_k=5, min_degree=4).nodes == (3,)
    assert select(metric, broom, metric="degree", top_k=5, min_degree=5).nodes == ()


def test_metric_weighted_betweenness_follows_lengths():
    # square 0-1-2-3-0 with a long side 0-3: paths from 0 to 3 go round by 1 and 2
    square = nx.Graph()
    square.add_weighted_edges_from([(0, 1, 1.0), (1, 2, 1.0), (2, 3, 1.0), (3, 0, 10.0)])
    # unweighted, all four are equivalent; weighted, 1 and 2 carry the 0-3 pair
    assert select(metric, square, metric="betweenness", top_k=2).nodes == (0, 1)
    assert select(metric, square, metric="betweenness", top_k=2, weighted=True).nodes == (1, 2)


def test_metric_katz_that_diverges_is_a_g2s_error():
    with pytest.raises(G2SError, match="does not converge"):
        select(metric, nx.complete_graph(6), metric="katz", attenuation=0.5, top_k=1)


@pytest.mark.parametrize(
    "params,message",
    [
        ({}, "give exactly one of top_k, top_fraction, threshold (got none of them)"),
        ({"top_k": 2, "threshold": 0.1}, "(got top_k and threshold)"),
        ({"top_k": 2, "min_degree": 3, "max_degree": 2}, "min_degree (3) is larger than max_degree (2)"),
    ],
)
def test_metric_params_need_exactly_one_selection(params, message):
    with pytest.raises(ValidationError) as info:
        metric.Params(**params)
    assert message in str(info.value)


def test_metric_params_ranges():
    with pytest.raises(ValidationError):
        metric.Params(top_k=0)
    with pytest.raises(ValidationError):
        metric.Params(top_fraction=1.5)
    with pytest.raises(ValidationError):
        metric.Params(top_k=1, metric="pagerank")
    with pytest.raises(ValidationError):
        metric.Params(top_k=1, attenuation=0.0)


# --- points ------------------------------------------------------------------------------


def test_points_are_added_as_joined_nodes():
    graph = surface_graph(nx.path_graph(4))  # nodes at x = 0, 1, 2, 3
    graph.nodes[3]["normal"] = (0.0, 0.0, 1.0)
    result = select(points, graph, points=[[3.5, 0.0, 0.0], [-0.5, 0.0, 0.3]])
    assert result == Terminals(nodes=(4, 5))
    assert graph.nodes[4] == {
        "pos": (3.5, 0.0, 0.0), "normal": (0.0, 0.0, 1.0), "area": 0.0, "on_navmesh": False, "polygon": -1
    }
    assert sorted(graph.adj[4]) == [3]
    assert graph.edges[4, 3]["weight"] == pytest.approx(0.5)
    assert sorted(graph.adj[5]) == [0]
    assert graph.edges[5, 0]["weight"] == pytest.approx(np.hypot(0.5, 0.3))


def test_points_connect_to_several_nearest_within_max_distance():
    graph = surface_graph(nx.path_graph(4))
    select(points, graph, points=[[1.4, 0.0, 0.0]], connect=3, max_distance=1.0)
    # nearest nodes 1 (0.4), 2 (0.6), 0 (1.4 > max_distance: not joined)
    assert sorted(graph.adj[4]) == [1, 2]
    assert graph.edges[4, 2]["weight"] == pytest.approx(0.6)


def test_points_ids_follow_the_largest_existing_id():
    graph = surface_graph(nx.Graph([(3, 17)]))
    assert select(points, graph, points=[[17.0, 0.0, 0.5]]).nodes == (18,)


def test_point_too_far_is_an_error_naming_it_and_leaves_the_graph_alone():
    graph = surface_graph(nx.path_graph(3))
    with pytest.raises(G2SError, match=r"point 1 \(10, 0, 0\) is 8 m from the nearest graph node, farther than max_distance = 2 m"):
        select(points, graph, points=[[0.0, 0.0, 0.5], [10.0, 0.0, 0.0]])
    assert graph.number_of_nodes() == 3


def test_points_from_json_csv_and_text_files(tmp_path):
    expected = [(0.5, 0.0, 0.0), (1.5, 0.0, 0.25)]
    files = {
        "p.json": json.dumps([[0.5, 0, 0], [1.5, 0, 0.25]]),
        "q.json": json.dumps({"points": [[0.5, 0, 0], [1.5, 0, 0.25]]}),
        "p.csv": "x,y,z\n0.5,0,0\n1.5,0,0.25\n",
        "p.txt": "# entry points\n0.5 0 0\n\n1.5\t0  0.25   # the second\n",
    }
    for name, text in files.items():
        path = tmp_path / name
        path.write_text(text)
        assert [tuple(p) for p in points.read_points(path).tolist()] == expected, name
        graph = surface_graph(nx.path_graph(3))
        assert select(points, graph, file=str(path)).nodes == (3, 4)
        assert graph.nodes[4]["pos"] == expected[1]


@pytest.mark.parametrize(
    "name,text,message",
    [
        ("bad.csv", "x,y,z\n1,2,3\n1,2\n", r"bad.csv:3: expected 3 numbers x, y, z, got 2"),
        ("bad.txt", "1 2 3\nnorth 2 3\n", r"bad.txt:2: expected 3 numbers x, y, z, got 'north 2 3'"),
        ("bad.json", "[[1, 2, 3], [1, 2]]", r"bad.json: point 1 is \[1, 2\], expected \[x, y, z\] numbers"),
        ("broken.json", "[[1, 2, 3]", r"broken.json: invalid JSON"),
        ("empty.csv", "# nothing\n", r"empty.csv: the file holds no points"),
    ],
)
def test_points_file_errors_name_the_file_and_line(tmp_path, name, text, message):
    path = tmp_path / name
    path.write_text(text)
    with pytest.raises(G2SError, match=message):
        points.read_points(path)


def test_points_missing_file(tmp_path):
    with pytest.raises(G2SError, match="no such points file"):
        select(points, surface_graph(nx.path_graph(2)), file=str(tmp_path / "nope.csv"))


def test_points_params_need_exactly_one_source():
    with pytest.raises(ValidationError, match=r"give exactly one of points, file \(got neither\)"):
        points.Params()
    with pytest.raises(ValidationError, match=r"\(got both\)"):
        points.Params(points=[[0, 0, 0]], file="p.csv")
    with pytest.raises(ValidationError):
        points.Params(points=[[0, 0]])
    with pytest.raises(ValidationError):
        points.Params(points=[[0, 0, 0]], connect=0)


def _floor_navmesh():
    recast = pytest.importorskip("g2s_plugins.recast")
    vertices = np.array([[0, 0, 0], [10, 0, 0], [10, 0, 10], [0, 0, 10]], dtype=np.float64)
    faces = np.array([[0, 2, 1], [0, 3, 2]])
    return recast.build_navmesh(vertices, faces, AgentConfig())


def test_points_on_navmesh_with_a_real_navmesh():
    navmesh = _floor_navmesh()  # the walkable area is the floor shrunk by the agent radius (0.5 m)
    graph = surface_graph(nx.path_graph(6), spacing=1.0)
    for node in graph:
        graph.nodes[node]["pos"] = (1.0 + node, 0.0, 5.0)
    ctx = context(navmesh)
    result = points.g2s_select_terminals(
        graph=graph, params=points.Params(points=[[3.2, 0.0, 5.0], [0.05, 0.0, 5.0], [-1.5, 0.0, 5.0]], max_distance=3.0),
        context=ctx,
    )
    assert [graph.nodes[n]["on_navmesh"] for n in result.nodes] == [True, False, False]


def test_register_as_terminal_selectors_and_run_through_pluggy():
    from g2s_core.registry import Registry

    registry = Registry()
    for module in (leaves, metric, points):
        info = registry.register(module, package="graph2structure", entry_point=f"terminals.{module.NAME}")
        assert (info.stage, info.name) == ("terminals", module.NAME)
    info = registry.get("terminals", "metric")
    params = registry.validate_params(info, {"metric": "degree", "top_k": 1}, key="terminals.params")
    assert registry.call(info, graph=nx.star_graph(3), params=params, context=context()).nodes == (0,)
