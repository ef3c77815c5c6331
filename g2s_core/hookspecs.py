"""The six stage interfaces of the pipeline, as pluggy hook specifications.

A plugin implements exactly one of these hooks. The pipeline calls only the
plugin the config chose for that stage, so every hook is ``firstresult``.
A hook implementation may take any subset of the named arguments.

=================  ==========================  ====================================
stage              hook                        returns
=================  ==========================  ====================================
GraphBuilder       ``g2s_build_graph``         the initial surface graph
TerminalSelector   ``g2s_select_terminals``    :class:`~g2s_core.model.Terminals`
SteinerSolver      ``g2s_steiner_tree``        a tree spanning the terminals
RootSelector       ``g2s_root_scores``         a score per node (higher = root)
SimplifyPredicate  ``g2s_simplify_predicate``  a predicate ``P(tree, a, b, c)``
Analyzer           ``g2s_analyze``             a value per node (or ``AnalyzerResult``)
=================  ==========================  ====================================
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence

import networkx as nx

from g2s_core.model import AnalyzerResult, RunContext, Terminals
from g2s_core.plugin import PluginParams, hookspec


@hookspec(firstresult=True)
def g2s_build_graph(mesh, params: PluginParams, context: RunContext) -> nx.Graph:
    """GraphBuilder: build the initial surface graph from a triangle mesh.

    ``mesh`` is a ``trimesh.Trimesh`` in metres with Y up. Return a graph that
    follows the conventions of :mod:`g2s_core.model`. A builder that makes a
    navigation mesh stores it in ``context.navmesh``.
    """


@hookspec(firstresult=True)
def g2s_select_terminals(graph: nx.Graph, params: PluginParams, context: RunContext) -> Terminals:
    """TerminalSelector: choose the nodes the structure must join.

    The selector may add nodes to ``graph`` (e.g. entry/exit points), joined
    to existing nodes by edges carrying ``weight``.
    """


@hookspec(firstresult=True)
def g2s_steiner_tree(
    graph: nx.Graph, terminals: Sequence[int], params: PluginParams, context: RunContext
) -> nx.Graph:
    """SteinerSolver: a tree of ``graph`` that joins all ``terminals``.

    All ``terminals`` (at least two) lie in one connected component of
    ``graph``; the graph may hold other components, which no path reaches
    (the pipeline splits the terminals by component and handles single ones). Return a tree whose
    edges are edges of ``graph`` (attributes need not be copied). The same
    input must always give the same tree.
    """


@hookspec(firstresult=True)
def g2s_root_scores(tree: nx.Graph, params: PluginParams, context: RunContext) -> Mapping[int, float]:
    """RootSelector: a score for every node of ``tree`` (a forest).

    The pipeline roots each component at its highest-scoring node; equal
    scores are broken by distance to ``context.centre``, then by node id.
    """


@hookspec(firstresult=True)
def g2s_simplify_predicate(
    params: PluginParams, context: RunContext
) -> Callable[[nx.DiGraph, int, int, int], bool]:
    """SimplifyPredicate: return ``P(tree, a, b, c)``.

    For a chain a -> b -> c of the rooted ``tree`` (a DiGraph whose nodes carry
    the surface attributes), ``P`` says whether b may be removed and c joined
    to a directly. It is asked for every child c of b.
    """


@hookspec(firstresult=True)
def g2s_analyze(
    structure: nx.Graph, params: PluginParams, context: RunContext
) -> Mapping[int, float] | AnalyzerResult:
    """Analyzer: a value for every node of the final structure (undirected).

    An analyzer that also finds records (chokepoints, regions ...) returns an
    :class:`~g2s_core.model.AnalyzerResult`; the pipeline keeps its
    ``features`` in ``RunResult.features`` under the analyzer's key.
    """


STAGE_HOOKS: dict[str, str] = {
    "graph": "g2s_build_graph",
    "terminals": "g2s_select_terminals",
    "steiner": "g2s_steiner_tree",
    "roots": "g2s_root_scores",
    "simplify": "g2s_simplify_predicate",
    "analyzers": "g2s_analyze",
}
"""Config section -> hook name, in pipeline order."""

STAGE_TITLES: dict[str, str] = {
    "graph": "GraphBuilder",
    "terminals": "TerminalSelector",
    "steiner": "SteinerSolver",
    "roots": "RootSelector",
    "simplify": "SimplifyPredicate",
    "analyzers": "Analyzer",
}
