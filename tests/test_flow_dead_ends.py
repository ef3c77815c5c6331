"""The ``flow`` analyzer's ``dead_ends``: a leaf no walk passes through shows its own value or its way's."""

from __future__ import annotations

import networkx as nx
import numpy as np
import pytest

from g2s_core.config import AgentConfig
from g2s_core.model import RunContext
from g2s_plugins.analyzers import flow as flow_analyzer


def corridor_with_a_recess() -> nx.Graph:
    """A corridor of five 1 m² samples along x (0-4) and a recess, sample 5, off its middle one."""
    graph = nx.Graph()
    for i in range(5):
        graph.add_node(i, pos=(float(i), 0.0, 0.0), area=1.0)
    graph.add_node(5, pos=(2.0, 0.0, 1.0), area=1.0)
    graph.add_edges_from([(0, 1), (1, 2), (2, 3), (3, 4), (2, 5)], weight=1.0)
    return graph


def heat(dead_ends: str) -> dict:
    graph = corridor_with_a_recess()
    context = RunContext(mesh=None, agent=AgentConfig(), centre=np.zeros(3), graph=graph)
    params = flow_analyzer.Params(aggregate="percentile", dead_ends=dead_ends)
    return flow_analyzer.g2s_analyze(graph, params, context)  # every sample a structure node


def test_a_recess_reads_as_the_way_it_opens_onto_only_when_asked():
    # ordered pairs through each sample: 1 and 3 part one end from the other four (2 x 4 = 8), 2 parts {0, 1},
    # {3, 4} and {5} (2 x (2 x 2 + 2 x 1 + 2 x 1) = 16); nothing passes through 0, 4 or 5. Percentiles of the six:
    # the three zeros share ranks 1-3 (100 (2 - 0.5) / 6 = 25), the two 8s ranks 4-5, the 16 rank 6
    bottom, middle, top = 25.0, 100.0 * 4.0 / 6.0, 100.0 * 5.5 / 6.0
    own = heat("own")
    assert [own[i] for i in range(6)] == pytest.approx([bottom, middle, top, middle, bottom, bottom])
    way = heat("way")
    assert [way[i] for i in range(6)] == pytest.approx([middle, middle, top, middle, middle, top])
    with pytest.raises(ValueError):
        flow_analyzer.Params(dead_ends="nearest")


def test_a_leaf_some_walk_passes_through_keeps_its_value():
    graph = corridor_with_a_recess()
    structure = nx.DiGraph([(2, 1), (2, 3)])  # a rooted tree: 1 and 3 are leaves, each standing for an end too
    context = RunContext(mesh=None, agent=AgentConfig(), centre=np.zeros(3), graph=graph)
    params = flow_analyzer.Params(aggregate="percentile", dead_ends="way")
    assert flow_analyzer.g2s_analyze(structure, params, context) == flow_analyzer.g2s_analyze(
        structure, params.model_copy(update={"dead_ends": "own"}), context)
