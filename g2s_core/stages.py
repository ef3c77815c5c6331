"""The one table of plugin kinds: the eight pipeline stages, output writers and readers, level generators, batch executors
and commands of the ``g2s`` command line.

Everything that lists stages reads it: the config's sections
(:mod:`g2s_core.config`), the registry's look-ups and ``g2s plugins``
(:mod:`g2s_core.registry`), the pipeline loop (:mod:`g2s_core.pipeline`) and
the per-stage table of the outputs. Each kind's hook is specified in
:mod:`g2s_core.hookspecs`; every plugin's result is checked here, the same way
for all: a wrong result is that plugin's failure, not g2s's.

===========  =================  ==========================  ==========================================
key          title              hook                        the plugin returns
===========  =================  ==========================  ==========================================
graph        GraphBuilder       ``g2s_build_graph``         an undirected networkx.Graph
terminals    TerminalSelector   ``g2s_select_terminals``    Terminals whose nodes are in the graph
steiner      SteinerSolver      ``g2s_steiner_tree``        a tree of graph edges joining the terminals
loops        LoopAdder          ``g2s_add_loops``           the forest plus graph edges (optional)
roots        RootSelector       ``g2s_root_scores``         a finite score for every node of the tree
simplify     SimplifyPredicate  ``g2s_simplify_predicate``  a callable P(tree, a, b, c) -> bool
analyzers    Analyzer           ``g2s_analyze``             a number for every node of the structure [*]_
evaluators   Evaluator          ``g2s_evaluate``            a finite number for each named measure
outputs      OutputWriter       ``g2s_write_output``        the paths written, among its FILES
readers      ResultReader       ``g2s_read_result``         the result read back, a LoadedResult
levels       LevelGenerator     ``g2s_generate_level``      a trimesh.Trimesh with triangles
executors    Executor           ``g2s_execute``             an iterator of the summary rows of the pairs
commands     Command            ``g2s_command``             a function run(args) -> exit code
===========  =================  ==========================  ==========================================

.. [*] as a mapping, or as the ``values`` of an :class:`~g2s_core.model.AnalyzerResult`
   whose ``features`` (a mapping of JSON records) the pipeline keeps.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from g2s_core import hookspecs
from g2s_core.lazy import lazy_module
from g2s_core.model import AnalyzerResult, LoadedResult, Terminals

# a plugin's result is checked after the plugin has imported them; listing plugins needs none
nx, np, trimesh = lazy_module("networkx"), lazy_module("numpy"), lazy_module("trimesh")

Check = Callable[[Any, Mapping[str, Any], Any], "str | None"]
"""``check(result, hook arguments, plugin object)``: what is wrong with a result, or ``None``."""


@dataclass(frozen=True)
class Stage:
    """One kind of plugin.

    Attributes:
        key: config section, registry kind, entry-point name prefix and ``--stage`` value.
        title: the kind's name in messages and ``g2s plugins``.
        hook: the hook its plugins implement (see :mod:`g2s_core.hookspecs`).
        check: the test of a result (see :data:`Check`).
        check_each_call: for a hook that returns a function, the test of each
            of that function's results (``None``: the result is not a function).
        guard_each_call: that function's exceptions (but bad input) are the
            plugin's failure; ``False`` for a command, which runs as g2s's own
            commands do (an unexpected exception is exit 1, as today for ``g2s batch``).
        check_each_item: for a hook that returns an iterator, the test of each
            item it yields (``None``: the result is not an iterator).
        many: the config section lists any number of these plugins, each with
            a ``key`` naming its output (``analyzers``, ``evaluators``).
        step, label: its row in the per-stage table (pipeline stages only).
        result: the :class:`~g2s_core.model.RunResult` attribute holding its output.
        timing: the :class:`~g2s_core.model.StageStats` name of its step.
        declares: module attributes its plugins must declare besides ``NAME``.
        optional: a pipeline stage whose section a config may leave out (the run
            skips it); a section listing plugins (``analyzers``) may be empty anyway.
    """

    key: str
    title: str
    hook: str
    check: Check
    check_each_call: Callable[[Any], str | None] | None = None
    guard_each_call: bool = True
    check_each_item: Callable[[Any], str | None] | None = None
    many: bool = False
    step: str = ""
    label: str = ""
    result: str = ""
    timing: str = ""
    declares: tuple[str, ...] = ()
    optional: bool = False


def _graph(value: Any, kwargs: Mapping[str, Any], plugin: Any) -> str | None:
    if not isinstance(value, nx.Graph) or isinstance(value, nx.DiGraph):
        return f"{type(value).__name__}, not an undirected networkx.Graph"
    return None


def _terminals(value: Any, kwargs: Mapping[str, Any], plugin: Any) -> str | None:
    if not isinstance(value, Terminals):
        return f"{type(value).__name__}, not Terminals"
    unknown = [t for t in value.nodes if t not in kwargs["graph"]]
    return f"nodes not in the graph: {unknown[:5]}" if unknown else None


def _not_in(part: nx.Graph, whole: nx.Graph) -> list[Any]:
    """The nodes and edges of ``part`` that ``whole`` lacks.

    First one comparison of each node's neighbour set with networkx's own
    adjacency dicts (a lookup per edge took 0.13-0.2 s per call on a
    100k-polygon level); only a result with something missing is listed.
    """
    adjacency = dict(whole.adjacency())
    if all(u in adjacency and neighbours.keys() <= adjacency[u].keys() for u, neighbours in part.adjacency()):
        return []
    return [n for n in part if n not in whole] + [e for e in part.edges if not whole.has_edge(*e)]


def _tree(value: Any, kwargs: Mapping[str, Any], plugin: Any) -> str | None:
    graph, terminals = kwargs["graph"], kwargs["terminals"]
    if not isinstance(value, nx.Graph):
        return f"{type(value).__name__}, not a networkx.Graph"
    missing = [t for t in terminals if t not in value]
    if missing:
        return f"a tree that misses terminals {missing[:5]}"
    foreign = _not_in(value, graph)
    if foreign:
        return f"a tree with nodes or edges not in the graph: {foreign[:3]}"
    return None if nx.is_tree(value) else "a graph that is not a tree"


def _looped(value: Any, kwargs: Mapping[str, Any], plugin: Any) -> str | None:
    problem = _graph(value, kwargs, plugin)
    if problem is not None:
        return problem
    missing = _not_in(kwargs["forest"], value)
    if missing:
        return f"a graph that misses nodes or edges of the forest: {missing[:3]}"
    foreign = _not_in(value, kwargs["graph"])
    return f"nodes or edges not in the graph: {foreign[:3]}" if foreign else None


def _node_numbers(values: Any, nodes: Any, finite: bool, of: str = "node") -> str | None:
    if not isinstance(values, Mapping):
        return f"{type(values).__name__}, not a mapping of {of} -> number"
    missing = [n for n in nodes if n not in values]
    if missing:
        return f"no value for {of}s {missing[:5]}"
    for node in nodes:
        try:
            number = float(values[node])
        except (TypeError, ValueError):
            return f"{values[node]!r} for {of} {node}, not a number"
        if finite and not math.isfinite(number):
            return f"{number} for {of} {node}, not a finite number"
    return None


def _root_scores(value: Any, kwargs: Mapping[str, Any], plugin: Any) -> str | None:
    return _node_numbers(value, sorted(kwargs["tree"]), finite=True)


def _analysis(value: Any, kwargs: Mapping[str, Any], plugin: Any) -> str | None:
    if isinstance(value, AnalyzerResult):
        if not isinstance(value.features, Mapping):
            return f"AnalyzerResult features {type(value.features).__name__}, not a mapping of name -> records"
        value = value.values
    return _node_numbers(value, sorted(kwargs["structure"]), finite=False)


def _predicate(value: Any, kwargs: Mapping[str, Any], plugin: Any) -> str | None:
    kept = value is None and kwargs.get("simplified") is not None  # None keeps the structure it was given
    return None if callable(value) or kept else f"{type(value).__name__}, not a callable P(tree, a, b, c)"


def _bool(value: Any) -> str | None:
    # a plain bool first: this runs on every answer of a predicate, and np is looked up lazily (g2s_core.lazy)
    return None if isinstance(value, bool) or isinstance(value, np.bool_) else f"{type(value).__name__}, not a bool"


def _written(value: Any, kwargs: Mapping[str, Any], plugin: Any) -> str | None:
    if not isinstance(value, list) or not all(isinstance(p, Path) for p in value):
        return f"{type(value).__name__}, not a list of paths"
    folder, files = Path(kwargs["folder"]), tuple(plugin.FILES)
    stray = [str(p) for p in value if p.parent != folder or p.name not in files]
    return f"paths it does not declare in FILES {files}: {stray[:3]}" if stray else None


_MEASURE_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*")


def _measures(value: Any, kwargs: Mapping[str, Any], plugin: Any) -> str | None:
    names = list(value) if isinstance(value, Mapping) else []
    wrong = [n for n in names if not (isinstance(n, str) and _MEASURE_NAME.fullmatch(n))]
    if wrong:
        return f"the measure name {wrong[0]!r}, not letters, digits and _ starting with a letter"
    return _node_numbers(value, names, finite=True, of="measure")


def _iterator(value: Any, kwargs: Mapping[str, Any], plugin: Any) -> str | None:
    return None if isinstance(value, Iterator) else f"{type(value).__name__}, not an iterator"


def _row(value: Any) -> str | None:
    if isinstance(value, dict) and "config" in value and "level" in value:
        return None
    return f"{type(value).__name__}, not a summary row (a dict with config and level)"


def _command(value: Any, kwargs: Mapping[str, Any], plugin: Any) -> str | None:
    return None if callable(value) else f"{type(value).__name__}, not a function run(args) -> exit code"


def _exit_code(value: Any) -> str | None:
    return None if isinstance(value, int) and not isinstance(value, bool) else f"{type(value).__name__}, not an exit code"


def _loaded(value: Any, kwargs: Mapping[str, Any], plugin: Any) -> str | None:
    return None if isinstance(value, LoadedResult) else f"{type(value).__name__}, not a LoadedResult"


def _level(value: Any, kwargs: Mapping[str, Any], plugin: Any) -> str | None:
    if not isinstance(value, trimesh.Trimesh) or len(value.faces) == 0:
        return f"{type(value).__name__}, not a trimesh.Trimesh with triangles"
    return None


STAGES: tuple[Stage, ...] = (
    Stage("graph", "GraphBuilder", hookspecs.g2s_build_graph.__name__, _graph,
          step="Step 1", label="initial graph", result="graph", timing="graph"),
    Stage("terminals", "TerminalSelector", hookspecs.g2s_select_terminals.__name__, _terminals,
          step="Step 2", label="terminals", result="terminals", timing="terminals"),
    Stage("steiner", "SteinerSolver", hookspecs.g2s_steiner_tree.__name__, _tree,
          step="Step 3", label="Steiner tree", result="steiner", timing="steiner"),
    Stage("loops", "LoopAdder", hookspecs.g2s_add_loops.__name__, _looped,
          step="Step 3", label="loops kept", result="looped", timing="loops", optional=True),
    Stage("roots", "RootSelector", hookspecs.g2s_root_scores.__name__, _root_scores,
          step="Step 4", label="rooted trees", result="forest", timing="roots"),
    Stage("simplify", "SimplifyPredicate", hookspecs.g2s_simplify_predicate.__name__, _predicate, check_each_call=_bool,
          step="Step 5", label="simplification", result="structure", timing="simplify"),
    Stage("analyzers", "Analyzer", hookspecs.g2s_analyze.__name__, _analysis, many=True,
          step="Post-process", label="analysis", result="analysis", timing="analysis"),
    Stage("evaluators", "Evaluator", hookspecs.g2s_evaluate.__name__, _measures, many=True,
          step="Post-process", label="evaluation", result="metrics", timing="evaluation"),
    Stage("outputs", "OutputWriter", hookspecs.g2s_write_output.__name__, _written, declares=("FILES",)),
    Stage("readers", "ResultReader", hookspecs.g2s_read_result.__name__, _loaded),
    Stage("levels", "LevelGenerator", hookspecs.g2s_generate_level.__name__, _level),
    Stage("executors", "Executor", hookspecs.g2s_execute.__name__, _iterator, check_each_item=_row),
    Stage("commands", "Command", hookspecs.g2s_command.__name__, _command,
          check_each_call=_exit_code, guard_each_call=False),
)

BY_KEY: dict[str, Stage] = {stage.key: stage for stage in STAGES}
BY_HOOK: dict[str, Stage] = {stage.hook: stage for stage in STAGES}
PIPELINE: tuple[Stage, ...] = tuple(stage for stage in STAGES if stage.step)
"""The pipeline's stages, in order."""
