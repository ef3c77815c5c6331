"""Properties that hold on every input (hypothesis): the Steiner step, simplification, and the
config validator."""

from __future__ import annotations

import itertools
import math

import networkx as nx
import numpy as np
import pytest
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from g2s_core.config import parse_config
from g2s_core.errors import ConfigError
from g2s_core.model import RunContext
from g2s_core.pipeline import plan, steiner_forest
from g2s_core.registry import installed
from g2s_core.rooted import root_forest
from g2s_core.simplify import simplify_forest
from g2s_plugins.steiner.kou import kou_steiner_tree
from g2s_plugins.steiner.mehlhorn import mehlhorn_steiner_tree

SOLVERS = {"kou": kou_steiner_tree, "mehlhorn": mehlhorn_steiner_tree}
FEW = settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@st.composite
def weighted_graphs(draw, max_nodes: int = 9) -> nx.Graph:
    """A graph of 2..max_nodes nodes with random integer-ish weights; maybe disconnected."""
    n = draw(st.integers(2, max_nodes))
    pairs = list(itertools.combinations(range(n), 2))
    chosen = draw(st.lists(st.sampled_from(pairs), min_size=1, max_size=len(pairs), unique=True))
    graph = nx.Graph()
    graph.add_nodes_from(range(n))
    for u, v in chosen:
        graph.add_edge(u, v, weight=float(draw(st.integers(1, 20))))
    return graph


def tree_weight(tree: nx.Graph, graph: nx.Graph) -> float:
    return sum(graph.edges[u, v]["weight"] for u, v in tree.edges)


def exact_steiner_weight(graph: nx.Graph, terminals: list[int]) -> float:
    """Optimum by brute force: the lightest spanning tree over terminals plus any subset of the other nodes."""
    others = [n for n in graph if n not in terminals]
    best = math.inf
    for size in range(len(others) + 1):
        for extra in itertools.combinations(others, size):
            sub = graph.subgraph([*terminals, *extra])
            if nx.is_connected(sub):
                best = min(best, nx.minimum_spanning_tree(sub).size(weight="weight"))
    return best


@pytest.mark.parametrize("method", sorted(SOLVERS))
@FEW
@given(data=st.data())
def test_steiner_tree_spans_every_reachable_terminal_within_the_bound(method, data):
    graph = data.draw(weighted_graphs())
    terminals = data.draw(st.lists(st.sampled_from(sorted(graph)), min_size=1, max_size=len(graph), unique=True))
    context = RunContext(mesh=None, agent=None, centre=np.zeros(3))
    forest = steiner_forest(graph, terminals, SOLVERS[method], context)
    assert nx.is_forest(forest)
    assert set(terminals) <= set(forest)
    for u, v in forest.edges:
        assert graph.has_edge(u, v)
    component_of = {n: i for i, c in enumerate(nx.connected_components(graph)) for n in c}
    for tree_nodes in nx.connected_components(forest):
        # one tree per area of the graph, and it joins every terminal of that area
        areas = {component_of[n] for n in tree_nodes}
        assert len(areas) == 1
        area_terminals = sorted(t for t in terminals if component_of[t] in areas)
        assert set(area_terminals) <= tree_nodes
        tree = forest.subgraph(tree_nodes)
        if len(area_terminals) >= 2:
            optimum = exact_steiner_weight(graph.subgraph({n for n in graph if component_of[n] in areas}),
                                           area_terminals)
            # an optimal tree has l <= |terminals| leaves, so 2(1 - 1/l) <= 2(1 - 1/|terminals|)
            assert tree_weight(tree, graph) <= 2 * (1 - 1 / len(area_terminals)) * optimum + 1e-9
    assert len(context.warnings) == (1 if len({component_of[t] for t in terminals}) > 1 else 0)


@st.composite
def rooted_forests(draw) -> nx.DiGraph:
    """A random tree with random positions and terminals, rooted by random scores."""
    n = draw(st.integers(1, 12))
    tree = nx.Graph()
    tree.add_node(0)
    for node in range(1, n):
        tree.add_edge(node, draw(st.integers(0, node - 1)))
    coords = st.floats(-50, 50, allow_nan=False, allow_infinity=False)
    for node in tree:
        tree.nodes[node]["pos"] = np.array([draw(coords), draw(coords), draw(coords)])
        tree.nodes[node]["terminal"] = draw(st.booleans())
    scores = {node: draw(st.integers(0, 5)) for node in tree}
    return root_forest(tree, scores, np.zeros(3))


@FEW
@given(forest=rooted_forests(), answers=st.lists(st.booleans(), min_size=1, max_size=30))
def test_simplification_never_disconnects_terminals_nor_adds_nodes(forest, answers):
    calls = itertools.count()

    def predicate(tree, a, b, c):  # any answers at all, in any order
        return answers[next(calls) % len(answers)]

    terminals = {n for n in forest if forest.nodes[n].get("terminal")}
    simplified = simplify_forest(forest, predicate)
    assert set(simplified) <= set(forest)
    assert terminals <= set(simplified)
    assert set(simplified.graph["roots"]) == set(forest.graph["roots"]) <= set(simplified)
    assert nx.is_forest(simplified.to_undirected())
    assert nx.number_weakly_connected_components(simplified) == nx.number_weakly_connected_components(forest)
    for node in simplified:
        assert simplified.in_degree(node) <= 1
        for root in simplified.graph["roots"]:
            if node in nx.descendants(forest, root) or node == root:
                assert node == root or node in nx.descendants(simplified, root)


# --- random YAML-like documents against the validator ----------------------------------------------

_KEYS = ["mesh", "agent", "graph", "terminals", "steiner", "roots", "simplify", "analyzers", "stop_after",
         "outputs", "plugin", "params", "key", "radius", "height", "max_climb", "max_slope", "up_axis", "scale",
         "clean", "formats", "metric", "threshold", "top_k", "point", "file", "extends", "navmesh", "kou",
         "betweenness", "points", "connect", "max_distance", "x"]
_SCALARS = st.one_of(
    st.none(), st.booleans(), st.integers(-10**30, 10**30), st.floats(), st.text(max_size=8),
    st.sampled_from(["navmesh", "kou", "betweenness", "metric", "points", "y", "z", "json", "graph", "1e999"]),
)
_REGISTRY = installed()
_DOCUMENTS = st.recursive(
    _SCALARS,
    lambda children: st.one_of(
        st.lists(children, max_size=4),
        st.dictionaries(st.one_of(st.sampled_from(_KEYS), st.integers(-3, 3)), children, max_size=5),
    ),
    max_leaves=25,
)


@settings(max_examples=100, deadline=None)
@given(document=st.dictionaries(st.sampled_from(_KEYS), _DOCUMENTS, max_size=6))
def test_any_document_is_a_config_or_a_clean_config_error(document):
    try:
        plan(parse_config(document, source="fuzz.yaml"), _REGISTRY, source="fuzz.yaml")
    except ConfigError as exc:
        message = str(exc)
        assert message.startswith("fuzz.yaml: ") and "\n" not in message


@settings(max_examples=75, deadline=None)
@given(document=_DOCUMENTS)
def test_any_yaml_text_is_a_config_or_a_clean_config_error(document, tmp_path_factory):
    from g2s_core.config import load_config

    path = tmp_path_factory.mktemp("yaml") / "fuzz.yaml"
    path.write_text(yaml.safe_dump(document, allow_unicode=True))
    try:
        load_config(path)
    except ConfigError as exc:
        assert str(exc).startswith(str(path)) and "\n" not in str(exc)
