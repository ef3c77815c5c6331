"""Running the configured stages in order on a mesh (the paper's Algorithm 1)."""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass
from typing import Any

import networkx as nx
import numpy as np
import trimesh

from g2s_core.config import RunConfig
from g2s_core.errors import ConfigError, G2SError, PluginError
from g2s_core.model import RunContext, RunResult, StageStats, Terminals
from g2s_core.plugin import PluginParams
from g2s_core.loops import add_loops
from g2s_core.registry import PluginInfo, Registry
from g2s_core.rooted import root_forest
from g2s_core.simplify import simplify_forest

ProgressCallback = Callable[[str], None]


@dataclass(frozen=True)
class ResolvedStage:
    """A config section matched to its plugin, with validated parameters."""

    section: str
    plugin: PluginInfo
    params: PluginParams
    key: str | None = None


@dataclass(frozen=True)
class Plan:
    """The stages a config asks for, validated against the installed plugins."""

    config: RunConfig
    stages: dict[str, ResolvedStage]
    analyzers: tuple[ResolvedStage, ...]


def plan(config: RunConfig, registry: Registry, source: str = "<config>") -> Plan:
    """Match every stage the config runs to an installed plugin and validate its parameters.

    Raises:
        ConfigError: a stage is missing, its plugin is not installed, or its
            parameters do not validate; the message starts with ``source``.
    """
    stages: dict[str, ResolvedStage] = {}
    analyzers: list[ResolvedStage] = []
    try:
        for section in config.stages_to_run():
            if section == "analyzers":
                for index, entry in enumerate(config.analyzers):
                    key = f"analyzers.{index}"
                    info = registry.get("analyzers", entry.plugin, key=f"{key}.plugin")
                    params = registry.validate_params(info, entry.params, key=f"{key}.params")
                    analyzers.append(ResolvedStage(section, info, params, entry.key or entry.plugin))
                continue
            entry = getattr(config, section)
            if entry is None:
                raise ConfigError(
                    f"{section}: required key is missing (a plugin for this stage, or stop_after before it)"
                )
            info = registry.get(section, entry.plugin, key=f"{section}.plugin")
            stages[section] = ResolvedStage(section, info, registry.validate_params(info, entry.params, f"{section}.params"))
    except ConfigError as exc:
        raise ConfigError(f"{source}: {exc}") from None
    keys = [a.key for a in analyzers]
    duplicates = sorted({k for k in keys if keys.count(k) > 1})
    if duplicates:
        raise ConfigError(f"{source}: analyzers: two analyzers write values named {duplicates[0]!r}; give one a 'key'")
    return Plan(config, stages, tuple(analyzers))


@contextmanager
def _timed(stats: list[StageStats], stage: str, **counts: Any) -> Iterator[dict[str, Any]]:
    record: dict[str, Any] = dict(counts)
    start = time.perf_counter()
    yield record
    stats.append(StageStats(stage, time.perf_counter() - start, **record))


def run(
    plan_: Plan,
    registry: Registry,
    mesh: trimesh.Trimesh,
    mesh_name: str,
    mesh_sha256: str,
    progress: ProgressCallback | None = None,
) -> RunResult:
    """Run the planned stages on ``mesh`` and return everything they produced."""
    config = plan_.config
    say = progress or (lambda _message: None)
    bounds = np.asarray(mesh.bounds, dtype=np.float64)
    context = RunContext(mesh=mesh, agent=config.agent, centre=bounds.mean(axis=0))
    result = RunResult(config=config.record(), mesh_name=mesh_name, mesh_sha256=mesh_sha256, context=context)
    stages = plan_.stages

    say("Step 1: initial graph")
    with _timed(result.stages, "graph") as record:
        graph = _call(registry, stages["graph"], mesh=mesh, context=context)
        if not isinstance(graph, nx.Graph) or isinstance(graph, nx.DiGraph):
            raise PluginError(f"GraphBuilder {stages['graph'].plugin.name!r} returned {type(graph).__name__}, not an undirected networkx.Graph")
        if graph.number_of_nodes() == 0:
            raise G2SError(f"{mesh_name}: no walkable surface found for the agent (the initial graph is empty)")
        record.update(nodes=graph.number_of_nodes(), edges=graph.number_of_edges())
    context.graph = result.graph = graph
    if "terminals" not in stages:
        return result

    say("Step 2: terminals")
    with _timed(result.stages, "terminals") as record:
        terminals = _call(registry, stages["terminals"], graph=graph, context=context)
        if not isinstance(terminals, Terminals):
            raise PluginError(f"TerminalSelector {stages['terminals'].plugin.name!r} returned {type(terminals).__name__}, not Terminals")
        unknown = [t for t in terminals.nodes if t not in graph]
        if unknown:
            raise PluginError(f"TerminalSelector {stages['terminals'].plugin.name!r} returned nodes not in the graph: {unknown[:5]}")
        record.update(terminals=len(terminals.nodes))
    result.terminals = terminals
    for node in set(terminals.nodes).difference(terminals.waypoints):
        graph.nodes[node]["terminal"] = True
    if not terminals.nodes:
        context.warn(
            f"the {stages['terminals'].plugin.name!r} terminal selector found no terminals in {mesh_name}: "
            "there is nothing to join, so the run stops after step 2"
        )
        return result
    if "steiner" not in stages:
        return result

    say("Step 3: Steiner tree")
    with _timed(result.stages, "steiner") as record:
        steiner = steiner_forest(graph, terminals.nodes, lambda sub, terms: _call(
            registry, stages["steiner"], graph=sub, terminals=terms, context=context), context)
        record.update(nodes=steiner.number_of_nodes(), edges=steiner.number_of_edges())
    tree = steiner
    if config.loops is not None:
        with _timed(result.stages, "loops") as record:
            steiner = add_loops(graph, tree, config.loops.stretch, config.loops.min_gain)
            record.update(nodes=steiner.number_of_nodes(), edges=steiner.number_of_edges())
    result.steiner = steiner
    if "roots" not in stages:
        return result

    say("Step 4: rooted trees")
    with _timed(result.stages, "roots"):
        # the root selector scores the Steiner tree itself (its measures are O(n) on
        # a tree, not on a tree with loops); nodes the loops added are never roots
        scores = {**dict.fromkeys(steiner, -math.inf), **_call(registry, stages["roots"], tree=tree, context=context)}
        forest = root_forest(steiner, scores, context.centre)
    result.forest = forest
    if "simplify" not in stages:
        return result

    say("Step 5: simplification")
    with _timed(result.stages, "simplify") as record:
        predicate = _call(registry, stages["simplify"], context=context)
        structure = simplify_forest(forest, predicate)
        record.update(nodes=structure.number_of_nodes(), edges=structure.number_of_edges())
    result.structure = structure
    if not plan_.analyzers:
        return result

    say("Post-process: analysis")
    with _timed(result.stages, "analysis"):
        undirected = structure.to_undirected(as_view=True)
        for analyzer in plan_.analyzers:
            values = _call(registry, analyzer, structure=undirected, context=context)
            missing = [n for n in structure if n not in values]
            if missing:
                raise PluginError(f"Analyzer {analyzer.plugin.name!r} gave no value for nodes {missing[:5]}")
            result.analysis[analyzer.key] = {n: float(values[n]) for n in structure}
    return result


def _call(registry: Registry, stage: ResolvedStage, **kwargs: Any) -> Any:
    return registry.call(stage.plugin, params=stage.params, **kwargs)


def steiner_forest(
    graph: nx.Graph,
    terminals: Sequence[int],
    solve: Callable[[nx.Graph, list[int]], nx.Graph],
    context: RunContext,
) -> nx.Graph:
    """One Steiner tree per connected component of ``graph`` that holds terminals.

    ``solve(subgraph, terminals)`` is called for components with two or more
    terminals (with the whole graph when all terminals share one component); a component with one terminal gives a single-node tree. When
    terminals lie in several components a warning lists the groups that could
    not be joined. The forest's nodes and edges carry the graph's attributes.
    """
    component_of: dict[int, int] = {}
    components = sorted((sorted(c) for c in nx.connected_components(graph)), key=lambda c: c[0])
    for index, component in enumerate(components):
        for node in component:
            component_of[node] = index
    groups: dict[int, list[int]] = {}
    for terminal in sorted(set(terminals)):
        groups.setdefault(component_of[terminal], []).append(terminal)
    if len(groups) > 1:
        listing = "; ".join(f"{{{', '.join(map(str, g[:8]))}{', ...' if len(g) > 8 else ''}}}" for g in groups.values())
        context.warn(f"terminals lie in {len(groups)} disconnected areas and cannot all be joined; one tree per area: {listing}")
    forest = nx.Graph()
    for index, group in sorted(groups.items()):
        if len(group) == 1:
            forest.add_node(group[0])
            continue
        # a subgraph view is slow to iterate: with a single group of terminals
        # the solver gets the whole graph (its other components are unreachable)
        tree = solve(graph if len(groups) == 1 else graph.subgraph(components[index]), group)
        _check_tree(tree, graph, group)
        forest.add_nodes_from(sorted(tree.nodes))
        forest.add_edges_from(sorted(tuple(sorted(e)) for e in tree.edges))
    for node in forest.nodes:
        forest.nodes[node].update(graph.nodes[node])
    for u, v in forest.edges:
        forest.edges[u, v].update(graph.edges[u, v])
    return forest


def _check_tree(tree: Any, graph: nx.Graph, terminals: list[int]) -> None:
    if not isinstance(tree, nx.Graph):
        raise PluginError(f"the Steiner solver returned {type(tree).__name__}, not a networkx.Graph")
    missing = [t for t in terminals if t not in tree]
    if missing:
        raise PluginError(f"the Steiner solver's tree misses terminals {missing[:5]}")
    foreign = [e for e in tree.edges if not graph.has_edge(*e)]
    if foreign:
        raise PluginError(f"the Steiner solver's tree has edges not in the graph: {foreign[:3]}")
    if not nx.is_tree(tree):
        raise PluginError("the Steiner solver returned a graph that is not a tree")
