"""Running the configured stages in order on a mesh (the paper's Algorithm 1)."""

from __future__ import annotations

import functools
import gc
import math
import time
from collections.abc import Callable, Collection, Sequence
from dataclasses import dataclass
from typing import Any

import networkx as nx
import numpy as np
import trimesh

from g2s_core.config import RunConfig
from g2s_core.disconnected import disconnected_warning
from g2s_core.errors import ConfigError, G2SError
from g2s_core.model import AnalyzerResult, RunContext, RunResult, StageStats, graph_of
from g2s_core.plugin import PluginParams
from g2s_core.registry import PluginInfo, Registry
from g2s_core.rooted import components, root_forest
from g2s_core.simplify import forest_arrays, simplify_forest
from g2s_core.stages import BY_KEY, PIPELINE

ProgressCallback = Callable[[str], None]


@dataclass(frozen=True)
class ResolvedStage:
    """A config section's plugin with validated parameters; ``key`` names its values (analyzers)."""

    plugin: PluginInfo
    params: PluginParams
    key: str


@dataclass(frozen=True)
class Plan:
    """The stages a config asks for, validated against the installed plugins.

    ``stages`` maps each stage that runs to its plugins (one, or the analyzers or evaluators in config order).
    """

    config: RunConfig
    stages: dict[str, tuple[ResolvedStage, ...]]


def plan(config: RunConfig, registry: Registry, source: str = "<config>") -> Plan:
    """Match every stage the config runs to an installed plugin and validate its parameters.

    Raises:
        ConfigError: a stage is missing, its plugin is not installed, or its
            parameters do not validate; the message starts with ``source``.
        PluginFailure: a chosen plugin is installed but failed to load.
    """
    stages: dict[str, tuple[ResolvedStage, ...]] = {}
    try:
        for section in config.stages_to_run():
            entry = getattr(config, section)
            if entry is None and not BY_KEY[section].optional:
                raise ConfigError(
                    f"{section}: required key is missing (a plugin for this stage, or stop_after before it)"
                )
            listed = {f"{section}.{i}": e for i, e in enumerate(entry)} if isinstance(entry, list) else {section: entry}
            resolved = tuple(_resolve(registry, section, key, e) for key, e in listed.items() if e is not None)
            if resolved:
                stages[section] = resolved
    except ConfigError as exc:
        raise ConfigError(f"{source}: {exc}") from None
    for section, planned in stages.items():
        keys = [p.key for p in planned]
        duplicates = sorted({k for k in keys if keys.count(k) > 1})
        if duplicates:
            raise ConfigError(f"{source}: {section}: two plugins write values named {duplicates[0]!r}; give one a 'key'")
    return Plan(config, stages)


def _resolve(registry: Registry, section: str, key: str, entry: Any) -> ResolvedStage:
    info = registry.get(section, entry.plugin, key=f"{key}.plugin")
    params = registry.validate_params(info, entry.params, f"{key}.params")
    return ResolvedStage(info, params, getattr(entry, "key", None) or entry.plugin)


def run(
    plan_: Plan,
    registry: Registry,
    mesh: trimesh.Trimesh,
    mesh_name: str,
    mesh_sha256: str,
    progress: ProgressCallback | None = None,
) -> RunResult:
    """Run the planned stages on ``mesh`` in the order of the stage table and return what they produced.

    Each step stores its output in the result; a step that returns ``False``
    (nothing left to do, e.g. no terminals) ends the run early.
    """
    config = plan_.config
    say = progress or (lambda _message: None)
    context = RunContext(mesh, config.agent, mesh.bounds.mean(axis=0), mesh_name=mesh_name, progress=say)
    result = RunResult(config=config.record(), mesh_name=mesh_name, mesh_sha256=mesh_sha256, context=context)
    # CPython's cyclic collector stays off while the stages run: they build hundreds of thousands of
    # networkx dicts, and every collection their allocations trigger rescans all the live ones (about an
    # eighth of the CPU time of a 100k-polygon level, docs/performance.md); reference counting still frees
    # what they drop, and a cycle among it waits for the first collection after the run
    collecting = gc.isenabled()
    gc.disable()
    try:
        for stage in PIPELINE:
            if stage.key not in plan_.stages:  # an optional stage or an empty list left out, or past stop_after
                continue
            say(f"{stage.step}: {stage.label}")
            record: dict[str, Any] = {}
            start = time.perf_counter()
            step = Step(registry, plan_.stages[stage.key], result, record)
            go_on = _STEPS[stage.key](step) is not False
            result.stages.append(StageStats(stage.timing, time.perf_counter() - start, **record))
            if not go_on:
                break
            if stage.key == "terminals":  # the planned plugins may begin work ahead of steps 3-4 (hookspecs)
                for planned in (chosen for stage_plugins in plan_.stages.values() for chosen in stage_plugins):
                    registry.begin_ahead(planned.plugin, params=planned.params, context=context)
    finally:
        if collecting:
            gc.enable()
    return result


@dataclass(frozen=True)
class Step:
    """What one step of :func:`run` works with: the registry, its planned plugin(s), the result so far,
    and ``record``, the counts of its :class:`~g2s_core.model.StageStats`."""

    registry: Registry
    planned: tuple[ResolvedStage, ...]
    result: RunResult
    record: dict[str, Any]

    def call(self, **kwargs: Any) -> Any:
        """The stage's single plugin, called with its parameters and the run's context."""
        (chosen,) = self.planned
        return self.registry.call(chosen.plugin, params=chosen.params, context=self.result.context, **kwargs)


def _graph_step(step: Step) -> bool | None:
    result = step.result
    graph = step.call(mesh=result.context.mesh)
    if graph.number_of_nodes() == 0:
        raise G2SError("no walkable surface found for the agent (the initial graph is empty)")  # named by api.execute
    _keep(step, "graph", graph)
    result.context.graph = graph


def _terminals_step(step: Step) -> bool | None:
    result, graph = step.result, step.result.graph
    terminals = step.call(graph=graph)
    step.record.update(terminals=len(terminals.nodes))
    result.terminals = terminals
    for node in terminals.without_waypoints:
        graph.nodes[node]["terminal"] = True
    if not terminals.nodes:
        result.context.warn(
            f"the {step.planned[0].plugin.name!r} terminal selector found no terminals in {result.mesh_name}: "
            "there is nothing to join, so the run stops after step 2"
        )
    return bool(terminals.nodes)


def _keep(step: Step, name: str, graph: nx.Graph) -> None:
    """Store a step's graph as the result's attribute ``name`` and record its size."""
    # len(graph.edges) counts as number_of_edges() does, without a degree view per node (10-15 ms less on 100k nodes)
    step.record.update(nodes=graph.number_of_nodes(), edges=len(graph.edges))
    setattr(step.result, name, graph)


def _steiner_step(step: Step) -> bool | None:
    result = step.result
    _keep(step, "steiner", steiner_forest(result.graph, result.terminals.nodes, lambda sub, terms: step.call(
        graph=sub, terminals=terms), result.context, result.terminals.waypoints))


def _loops_step(step: Step) -> bool | None:
    result = step.result
    _keep(step, "looped", _with_graph_attributes(step.call(graph=result.graph, forest=result.steiner), result.graph))


def _roots_step(step: Step) -> bool | None:
    result = step.result
    # the root selector scores the Steiner tree itself (its measures are O(n) on a
    # tree, not on a tree with loops); nodes the loops added are never roots
    structure = result.looped if result.looped is not None else result.steiner
    scores = {**dict.fromkeys(structure, -math.inf), **step.call(tree=result.steiner)}
    result.forest = root_forest(structure, scores, result.context.centre)


def _simplify_step(step: Step) -> bool | None:
    forest, structure, again = step.result.forest, None, step.registry.takes(step.planned[0].plugin, "simplified")
    arrays = functools.cache(functools.partial(forest_arrays, forest))  # read once, if at all, for every round
    # a plugin that takes `simplified` is asked again with each structure until it keeps one (hookspecs.py)
    while (structure is None or again) and (predicate := step.call(forest=forest, simplified=structure)) is not None:
        structure = simplify_forest(forest, predicate, arrays)
    _keep(step, "structure", structure)


def _analyzers_step(step: Step) -> bool | None:
    result = step.result
    undirected = result.structure.to_undirected(as_view=True)
    for analyzer in step.planned:
        values = step.registry.call(analyzer.plugin, params=analyzer.params, structure=undirected, context=result.context)
        if isinstance(values, AnalyzerResult):
            result.features[analyzer.key] = dict(values.features)
            values = values.values
        result.analysis[analyzer.key] = {n: float(values[n]) for n in result.structure}


def _evaluators_step(step: Step) -> None:
    result = step.result
    for evaluator in step.planned:
        measures = step.registry.call(evaluator.plugin, params=evaluator.params, result=result, context=result.context)
        result.metrics[evaluator.key] = {name: float(value) for name, value in measures.items()}


_STEPS: dict[str, Callable[[Step], bool | None]] = {
    "graph": _graph_step,
    "terminals": _terminals_step,
    "steiner": _steiner_step,
    "loops": _loops_step,
    "roots": _roots_step,
    "simplify": _simplify_step,
    "analyzers": _analyzers_step,
    "evaluators": _evaluators_step,
}
"""The step of each pipeline stage of :data:`g2s_core.stages.PIPELINE`."""


def steiner_forest(
    graph: nx.Graph,
    terminals: Sequence[int],
    solve: Callable[[nx.Graph, list[int]], nx.Graph],
    context: RunContext,
    waypoints: Collection[int] = (),
) -> nx.Graph:
    """One Steiner tree per connected component of ``graph`` that holds terminals (``waypoints`` among them).

    ``solve(subgraph, terminals)`` is called for components with two or more
    terminals (with the whole graph when all terminals share one component); a component with one terminal gives a single-node tree. When
    terminals lie in several components a warning places the largest and names
    the likely cause (:mod:`g2s_core.disconnected`); it counts the terminals
    and the ``waypoints`` apart, as the outputs do. The forest's nodes and edges share the graph's attribute dicts.
    """
    ids = np.sort(np.fromiter(graph._node, np.int64, len(graph)))
    label = components(graph, ids)[3]
    groups: dict[int, list[int]] = {}
    for index, terminal in zip(label[np.searchsorted(ids, wanted := sorted(set(terminals)))].tolist(), wanted):
        groups.setdefault(index, []).append(terminal)
    areas = {index: ids[label == index].tolist() for index in groups} if len(groups) > 1 else {}
    if areas:
        joined_waypoints = len(set(waypoints).intersection(wanted))
        context.warn(disconnected_warning(graph, areas, len(wanted) - joined_waypoints, context.likely_cause, joined_waypoints))
    nodes, edges = [], []
    for index, group in sorted(groups.items()):
        # a subgraph view is slow to iterate: with a single group of terminals
        # the solver gets the whole graph (its other components are unreachable)
        part = graph if len(groups) == 1 else graph.subgraph(areas[index])
        tree = solve(part, group) if len(group) > 1 else nx.empty_graph(group)  # a lone terminal: its own tree
        nodes += sorted(tree.nodes)
        edges += sorted((u, v) if u <= v else (v, u) for u, v in tree.edges)
    # the groups' nodes and edges are disjoint: all nodes first then all edges make the same graph as group by group
    # the graph's own attribute dicts, shared as a subgraph view shares them: no step changes them after step 2
    return graph_of(nx.Graph(), {node: graph._node[node] for node in nodes}, ((u, v, graph._adj[u][v]) for u, v in edges))


def _with_graph_attributes(part: nx.Graph, graph: nx.Graph) -> nx.Graph:
    """``part`` (nodes and edges of ``graph``) with ``graph``'s attributes copied onto them.

    ``graph``'s attributes are read from networkx's own dicts, not through a view object per node and edge.
    """
    node_data, adjacency = graph._node, graph._adj
    for node, data in part._node.items():
        data.update(node_data[node])
    for u, v, data in part.edges(data=True):
        data.update(adjacency[u][v])
    return part
