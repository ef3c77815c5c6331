"""Analyzer plugins, called on the undirected view of a rooted structure as the pipeline does."""

from __future__ import annotations

import networkx as nx
import numpy as np
import pytest

from g2s_core.config import AgentConfig
from g2s_core.errors import PluginError
from g2s_core.model import RunContext
from g2s_core.rooted import root_forest
from g2s_plugins.analyzers import betweenness, closeness, degree, depth


def context() -> RunContext:
    return RunContext(mesh=None, agent=AgentConfig(), centre=np.zeros(3))


def structure_of(graph: nx.Graph) -> nx.DiGraph:
    """Root every tree of ``graph`` at its lowest id, as a pipeline structure."""
    for node in graph:
        graph.nodes[node].setdefault("pos", (float(node), 0.0, 0.0))
    return root_forest(graph, {n: -float(n) for n in graph}, np.zeros(3))


def analyze(module, structure, **params):
    view = structure.to_undirected(as_view=True) if structure.is_directed() else structure
    return module.g2s_analyze(structure=view, params=module.Params(**params), context=context())


def test_betweenness_of_a_path_structure():
    structure = structure_of(nx.path_graph(5))
    assert analyze(betweenness, structure) == pytest.approx({0: 0.0, 1: 0.5, 2: 4 / 6, 3: 0.5, 4: 0.0})
    assert analyze(betweenness, structure, normalized=False) == pytest.approx({0: 0, 1: 3, 2: 4, 3: 3, 4: 0})


def test_betweenness_of_two_trees():
    forest = nx.union(nx.star_graph(3), nx.path_graph(range(10, 13)))
    values = analyze(betweenness, structure_of(forest), normalized=False)
    assert values == pytest.approx({0: 3, 1: 0, 2: 0, 3: 0, 10: 0, 11: 1, 12: 0})


def test_betweenness_on_a_graph_with_a_cycle_matches_networkx():
    graph = nx.Graph()
    graph.add_weighted_edges_from([(0, 1, 1.0), (1, 2, 1.0), (2, 3, 1.0), (3, 0, 10.0), (3, 4, 2.0)])
    expected = nx.betweenness_centrality(graph, weight="weight")
    ours = analyze(betweenness, graph, weighted=True)
    assert ours == pytest.approx(expected)
    assert ours[1] > 0 and ours[0] < ours[2]
    assert analyze(betweenness, graph) == pytest.approx(nx.betweenness_centrality(graph))


def test_closeness_weighted_and_in_hops():
    graph = nx.Graph()
    graph.add_weighted_edges_from([(0, 1, 1.0), (1, 2, 3.0)])
    structure = structure_of(graph)
    assert analyze(closeness, structure) == pytest.approx({0: 2 / 5, 1: 2 / 4, 2: 2 / 7})
    assert analyze(closeness, structure, weighted=False) == pytest.approx({0: 2 / 3, 1: 1.0, 2: 2 / 3})


def test_degree_counts_and_lengths():
    graph = nx.Graph()
    graph.add_weighted_edges_from([(0, 1, 2.0), (0, 2, 3.0), (0, 3, 4.0)])
    structure = structure_of(graph)
    assert analyze(degree, structure) == {0: 3.0, 1: 1.0, 2: 1.0, 3: 1.0}
    assert analyze(degree, structure, weighted=True) == {0: 9.0, 1: 2.0, 2: 3.0, 3: 4.0}
    assert analyze(degree, structure, normalized=True) == pytest.approx({0: 1.0, 1: 1 / 3, 2: 1 / 3, 3: 1 / 3})


def test_depth_reads_the_pipeline_attribute():
    forest = nx.union(nx.path_graph(4), nx.star_graph(range(10, 13)))  # star centre 10
    structure = structure_of(forest)
    assert structure.graph["roots"] == [0, 10]
    assert analyze(depth, structure) == {0: 0.0, 1: 1.0, 2: 2.0, 3: 3.0, 10: 0.0, 11: 1.0, 12: 1.0}
    structure.nodes[3]["depth"] = 7  # the attribute is what is reported
    assert analyze(depth, structure)[3] == 7.0


def test_depth_from_roots_when_the_attribute_is_missing():
    graph = nx.path_graph(5)
    graph.graph["roots"] = [2]
    assert analyze(depth, graph) == {0: 2.0, 1: 1.0, 2: 0.0, 3: 1.0, 4: 2.0}
    graph.add_edge(8, 9)
    with pytest.raises(PluginError, match=r"not reachable from any root: \[8, 9\]"):
        analyze(depth, graph)


def test_depth_needs_depth_or_roots():
    with pytest.raises(PluginError, match="needs node attributes \"depth\" or graph\\[\"roots\"\\]"):
        analyze(depth, nx.path_graph(3))


def test_register_as_analyzers_and_run_through_pluggy():
    from g2s_core.registry import Registry

    registry = Registry()
    for module in (betweenness, closeness, degree, depth):
        info = registry.register(module, package="graph2structure", entry_point=f"analyzers.{module.NAME}")
        assert (info.stage, info.name) == ("analyzers", module.NAME)
    structure = structure_of(nx.path_graph(3)).to_undirected(as_view=True)
    info = registry.get("analyzers", "depth")
    assert registry.call(info, structure=structure, params=depth.Params(), context=context()) == {0: 0.0, 1: 1.0, 2: 2.0}
