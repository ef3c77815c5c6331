"""Every hook a plugin may implement, as pluggy hook specifications.

A plugin implements exactly one of the stage hooks (every hook here but
``g2s_begin_ahead``, which a pipeline stage's plugin may implement beside its
own); the kind of plugin (its stage) is the stage hook it implements.
:mod:`g2s_core.stages` lists them in one table with what each must return and
how the result is checked. g2s calls only the plugin
the config (or the command line) chose, so every hook is ``firstresult``. A
hook implementation may take any subset of the named arguments.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable, Iterator, Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from g2s_core.model import AnalyzerResult, LoadedResult, RunContext, RunResult, Terminals
from g2s_core.plugin import PluginParams, hookspec

if TYPE_CHECKING:  # annotations only (g2s_core.lazy)
    import networkx as nx
    import trimesh


@hookspec(firstresult=True)
def g2s_build_graph(mesh: trimesh.Trimesh, params: PluginParams, context: RunContext) -> nx.Graph:
    """GraphBuilder: build the initial surface graph from a triangle mesh.

    ``mesh`` is in metres with Y up. Return a graph that follows the
    conventions of :mod:`g2s_core.model`. A builder that makes a navigation
    mesh stores it in ``context.navmesh`` (a :class:`~g2s_core.model.NavMesh`);
    one that can tell what parts the areas of its surface sets
    ``context.likely_cause`` for the disconnected-areas warning.
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
def g2s_add_loops(graph: nx.Graph, forest: nx.Graph, params: PluginParams, context: RunContext) -> nx.Graph:
    """LoopAdder: ``forest`` (the Steiner forest, edges of ``graph``) with paths of ``graph`` added back.

    A tree loses every loop of the level; a loop adder keeps some. Return a
    graph holding every node and edge of ``forest`` plus the edges of
    ``graph`` it adds (``forest`` itself when it adds none); the pipeline
    copies the graph's attributes onto new nodes and edges. ``forest``'s node
    and edge attribute dicts are ``graph``'s own (shared, as a subgraph view
    shares them): add nodes and edges, never change their attributes.
    Optional: without a ``loops:`` section the structure stays the paper's tree.
    """


@hookspec(firstresult=True)
def g2s_root_scores(tree: nx.Graph, params: PluginParams, context: RunContext) -> Mapping[int, float]:
    """RootSelector: a score for every node of ``tree`` (a forest).

    The pipeline roots each component at its highest-scoring node; equal
    scores are broken by distance to ``context.centre``, then by node id.
    """


@hookspec(firstresult=True)
def g2s_simplify_predicate(
    params: PluginParams, context: RunContext, forest: nx.DiGraph, simplified: nx.DiGraph | None
) -> Callable[[nx.DiGraph, int, int, int], bool] | None:
    """SimplifyPredicate: return ``P(tree, a, b, c)``.

    For a chain a -> b -> c of the rooted ``tree`` (a DiGraph whose nodes carry
    the surface attributes), ``P`` says whether b may be removed and c joined
    to a directly. It is asked for every child c of b and must return a bool.
    ``forest`` is the rooted forest that simplification starts from.

    A predicate whose result must meet a condition takes ``simplified``: the
    pipeline then asks the hook again with the structure the last predicate
    gave (``None`` on the first call) and simplifies ``forest`` anew with each
    predicate it returns, until it returns ``None``, which keeps that
    structure. A hook that does not take ``simplified`` is asked once.

    ``P`` may carry ``P.whole_forest``, the whole forest's simplification
    in one call (:mod:`g2s_core.simplify`), which must answer as Algorithm 4
    asking ``P`` chain by chain does; the pipeline then takes it.
    """


@hookspec(firstresult=True)
def g2s_begin_ahead(params: PluginParams, context: RunContext) -> None:
    """Optional beside a pipeline stage's hook: begin, on threads of the plugin's own, work its stage will need,
    once step 2 has chosen the terminals (``context.graph`` exists); asked of every plugin the run planned.

    Steps 3-4 run Python on one core, so work begun here takes the other (the heat guarantee's confirming walking
    flow, :mod:`g2s_plugins.heat_guarantee`). What is begun changes no result: the stage later takes the values it
    would have computed itself, and an error raised there reaches the stage that takes them.
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


@hookspec(firstresult=True)
def g2s_evaluate(result: RunResult, params: PluginParams, context: RunContext) -> Mapping[str, float]:
    """Evaluator: measures of how good the run's result is, by name (after the analyzers).

    ``result`` holds every stage's output (the initial graph, the Steiner
    forest, the structure, the analyzers' values). Return a finite number for
    each measure, named with letters, digits and ``_``; leave out a measure
    that cannot be computed on this run (e.g. a correlation of constant values).
    """


@hookspec(firstresult=True)
def g2s_write_output(result: RunResult, folder: Path) -> list[Path]:
    """OutputWriter: write the result files of one format into ``folder``; return their paths.

    The plugin declares ``FILES``, the names of every file it may write (what
    ``--force`` may replace); it writes only those, and may skip ones that
    make no sense for the run (e.g. before step 5).
    """


@hookspec(firstresult=True)
def g2s_read_result(path: Path) -> LoadedResult:
    """ResultReader: read back the files that the OutputWriter of the same ``NAME`` wrote.

    ``path`` is a result folder or one of the format's files. A file that is
    missing, damaged or not of the format is the user's bad input: raise
    :class:`~g2s_core.errors.G2SError` naming the file and the field.
    """


@hookspec(firstresult=True)
def g2s_generate_level(params: PluginParams) -> trimesh.Trimesh:
    """LevelGenerator: build a level (metres, Y up) from its declared parameters.

    Used as ``sample:NAME?param=value&...`` wherever a mesh file is accepted.
    """


@hookspec(firstresult=True)
def g2s_execute(function: Callable[[Any], dict[str, Any]], items: Sequence[Any], params: PluginParams,
                lost: Callable[[Any, str], dict[str, Any]]) -> Iterator[dict[str, Any]]:
    """Executor: ``function(item)`` for every item of a batch, yielded as each finishes (any order).

    ``function`` (the batch runner's ``run_pair``) and the items are
    picklable and importable by name, so they may run in other processes or
    on other machines; the function never raises for a failed pair (its row
    says so). Closing the iterator (the batch was interrupted) stops the work
    not yet started. An item whose process died as it ran (killed for want of
    memory, a crash in native code) has the row ``lost(item, reason)``, ``reason`` saying what died
    (recorded as failed): an executor that can tell yields it and runs the other
    items on; one that raises ends the batch. An item that finished must not
    run again; one stopped by another's death may.
    """


@hookspec(firstresult=True)
def g2s_command(parser: argparse.ArgumentParser) -> Callable[[argparse.Namespace], int]:
    """Command: ``g2s NAME``; add its arguments to ``parser``, return the function that runs it.

    ``parser`` is the command's own subparser (its help line in ``g2s --help``
    is the plugin's summary; the plugin may set its ``usage``, ``description``
    and ``epilog``). The function gets the parsed arguments and returns the
    exit code; it runs as g2s's own commands do: bad input is a
    :class:`~g2s_core.errors.G2SError` with a one-line message (exit 2), any
    other exception an internal error (exit 1).
    """
