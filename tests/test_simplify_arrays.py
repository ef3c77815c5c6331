"""The ``surface_los`` predicate's whole-forest path (Algorithm 4 and Algorithm 5's tests in C++,
src/forest_simplify.hpp) against :func:`g2s_core.simplify.simplify_forest`'s own loop asking the same predicate:
every node and edge, their attributes and their order, on random rooted forests over two generated levels
(terrain: slopes; castle: walls, stairs and storeys)."""

from __future__ import annotations

import dataclasses
import itertools
import math
import random

import networkx as nx
import numpy as np
import pytest

from g2s_core import pipeline
from g2s_core.config import PRESETS_DIR, load_config, load_raw_config, parse_config, set_key
from g2s_core.registry import Registry
from g2s_core.rooted import root_forest
from g2s_core.simplify import forest_arrays, simplify_forest
from g2s_plugins import _surface
from g2s_plugins.heat_guarantee import keeping
from g2s_plugins.predicates import surface_los
from g2s_plugins.recast import NavMesh

LEVELS = ("terrain", "castle")

PARAMS = (
    surface_los.Params(),
    surface_los.Params(normal_tolerance_deg=45.0, max_traffic_step=30.0),
    surface_los.Params(normal_tolerance_deg=20.0, whole_chain_normals=False, max_surface_gap=None),
)


@pytest.fixture(scope="module")
def runs():
    from g2s_plugins.samples.levels import SAMPLES

    registry = Registry.from_entry_points()
    plan = pipeline.plan(load_config(PRESETS_DIR / "map_analysis.yaml"), registry)
    return {name: pipeline.run(plan, registry, SAMPLES[name]().mesh, name, "-") for name in LEVELS}


def random_forest(graph: nx.Graph, seed: int) -> nx.DiGraph:
    """A random spanning forest of ``graph`` with about a tenth of its other edges as loops, rooted at random
    nodes; about one node in twenty a terminal and one in twenty off the navmesh."""
    rng = random.Random(seed)
    ranked = nx.Graph()
    ranked.add_nodes_from(graph.nodes(data=True))
    ranked.add_edges_from((u, v, {**data, "rank": rng.random()}) for u, v, data in graph.edges(data=True))
    structure = nx.minimum_spanning_tree(ranked, weight="rank")
    structure.add_edges_from((u, v, data) for u, v, data in ranked.edges(data=True)
                             if not structure.has_edge(u, v) and rng.random() < 0.1)
    forest = root_forest(structure, {node: rng.random() for node in structure}, centre=np.zeros(3))
    for data in forest._node.values():
        data["terminal"], data["on_navmesh"] = rng.random() < 0.05, data["on_navmesh"] and rng.random() > 0.05
    return forest


def through_python(predicate):
    """``predicate`` without its whole-forest path: simplify_forest asks it chain by chain."""
    return lambda tree, a, b, c: predicate(tree, a, b, c)


def layout(structure: nx.DiGraph) -> tuple:
    """Everything simplification decides: the graph's attributes, the nodes and their attributes, each node's
    successors and predecessors with the edges' attributes, all in order."""
    return (structure.graph, list(structure.nodes(data=True)),
            [(node, list(structure._succ[node].items()), list(structure._pred[node])) for node in structure])


def predicate_for(run, params):
    predicate = surface_los.g2s_simplify_predicate(params, run.context, run.forest, None)
    assert callable(getattr(predicate, "whole_forest", None))
    return predicate


@pytest.mark.parametrize("level", LEVELS)
@pytest.mark.parametrize("params", PARAMS, ids=("defaults", "map_analysis", "paper_like"))
def test_the_whole_forest_path_builds_the_structure_the_loop_builds(runs, level, params):
    run = runs[level]
    predicate = predicate_for(run, params)
    removed = shortened = 0
    for seed in range(6):
        forest = random_forest(run.graph, seed)
        structure = simplify_forest(forest, predicate)
        assert layout(structure) == layout(simplify_forest(forest, through_python(predicate)))
        removed += forest.number_of_nodes() - structure.number_of_nodes()
        # a loop edge the forest does not have: the loop pass removed a node
        shortened += sum(1 for u, v, loop in structure.edges(data="loop") if loop and not forest.has_edge(u, v))
    assert removed > shortened > 0


@pytest.mark.parametrize("level", LEVELS)
def test_the_comparison_sees_one_answer_flipped(runs, level):
    # a reference whose k-th deciding True answer (B has that one child C, or none: the loop pass) is False keeps
    # one node more: the layouts above must differ
    run = runs[level]
    predicate, forest = predicate_for(run, PARAMS[1]), random_forest(run.graph, 0)
    native = layout(simplify_forest(forest, predicate))
    for flipped in (0, 7, 40):
        count = itertools.count()

        def one_flipped(tree, a, b, c):
            answer = predicate(tree, a, b, c)
            return answer and (len(tree._succ[b]) > 1 or next(count) != flipped)

        assert layout(simplify_forest(forest, one_flipped)) != native


@pytest.mark.parametrize("level", LEVELS)
def test_nodes_a_later_heat_round_keeps_stay_on_both_paths(runs, level):
    run = runs[level]
    predicate = predicate_for(run, PARAMS[1])
    for seed in range(4):
        forest = random_forest(run.graph, seed)
        kept = set(random.Random(seed).sample(sorted(forest), len(forest) // 5))
        structure = simplify_forest(forest, keeping(predicate, kept))
        assert kept <= set(structure)
        assert layout(structure) == layout(simplify_forest(forest, keeping(through_python(predicate), kept)))


@pytest.mark.parametrize("level", LEVELS)
def test_the_rule_s_arrays_are_read_again_for_a_forest_whose_nodes_are_new(runs, level):
    # The rule's arrays are read once for a forest asked about again with the same ids and node dicts (the heat
    # guarantee's rounds); a forest of the same ids whose node dicts are new ones (a copy, every other node's normal
    # turned level) is read again: its structure is a fresh predicate's, not the first forest's.
    run = runs[level]
    predicate, forest = predicate_for(run, PARAMS[1]), random_forest(run.graph, 0)
    first = layout(simplify_forest(forest, predicate))
    assert layout(simplify_forest(forest, predicate)) == first
    turned = forest.copy()
    for node in list(turned)[::2]:
        turned.nodes[node]["normal"] = (1.0, 0.0, 0.0)
    again = layout(simplify_forest(turned, predicate))
    assert again == layout(simplify_forest(turned, predicate_for(run, PARAMS[1]))) and again != first


@pytest.mark.parametrize("level", LEVELS)
def test_a_sight_memo_answers_a_later_round_s_repeated_lines_of_sight_as_detour_does(runs, level):
    # a later heat round (more fixed nodes) asks many of the first round's lines of sight again: with the memo they
    # are answered from it, and every round's answer is the one the same call gives without a memo
    run, navmesh = runs[level], runs[level].context.navmesh
    arrays = forest_arrays(random_forest(run.graph, 0))
    rule = _surface.RuleArrays(
        on_navmesh=np.array([bool(d.get("on_navmesh", False)) for d in arrays.data]),
        rank=np.full(len(arrays.ids), np.nan), normals=np.array([d["normal"] for d in arrays.data], dtype=float),
        normal_lengths=np.array([math.hypot(*d["normal"]) for d in arrays.data]), max_step=None,
        tolerance_deg=45.0, whole_chain=True)
    memo = navmesh.sight_memo()
    first = navmesh.collapse_forest(arrays, rule, 0.1, 0.3, memo)
    asked, hits = len(memo), memo.hits
    assert asked > 100
    later = dataclasses.replace(arrays, fixed=arrays.fixed | (np.random.default_rng(0).random(len(arrays.ids)) < 0.2))
    second = navmesh.collapse_forest(later, rule, 0.1, 0.3, memo)
    assert memo.hits - hits > len(memo) - asked > 0  # mostly answered from the memo, a few tested anew
    for answer, reference in ((first, navmesh.collapse_forest(arrays, rule, 0.1, 0.3)),
                              (second, navmesh.collapse_forest(later, rule, 0.1, 0.3))):
        assert all(np.array_equal(x, y) for x, y in zip(answer, reference))
    with pytest.raises(ValueError, match="sight memo"):  # its answers hold for one probe step and gap
        navmesh.collapse_forest(arrays, rule, 0.2, 0.3, memo)


def test_the_pipeline_takes_the_whole_forest_path_in_every_heat_round(monkeypatch, runs):
    # min_heat_rho 0.99 on the castle restores nodes over several rounds; each asks the C++ path once, and the
    # structure is the one the loop gives with the same predicate
    from g2s_plugins.samples.levels import SAMPLES

    registry = Registry.from_entry_points()
    raw = set_key(load_raw_config(PRESETS_DIR / "map_analysis.yaml"), "simplify.params.min_heat_rho", 0.99, "test")
    plan = pipeline.plan(parse_config(raw), registry)
    calls = []
    native = NavMesh.collapse_forest
    monkeypatch.setattr(NavMesh, "collapse_forest", lambda *args: calls.append(1) or native(*args))
    structure = pipeline.run(plan, registry, SAMPLES["castle"]().mesh, "castle", "-").structure
    assert len(calls) >= 2
    rule = _surface.collapse_rule
    monkeypatch.setattr(surface_los, "collapse_rule", lambda params, sight, graph, native: rule(params, sight, graph))
    reference = pipeline.run(plan, registry, SAMPLES["castle"]().mesh, "castle", "-").structure
    assert len(calls) >= 2 and layout(structure) == layout(reference)


@pytest.fixture(scope="module")
def sampled():
    """``map_analysis_sampling`` on a small generated dungeon (no navmesh: the ``mesh_los`` predicate)."""
    from g2s_plugins.samples.levels import dungeon

    registry = Registry.from_entry_points()
    plan = pipeline.plan(load_config(PRESETS_DIR / "map_analysis_sampling.yaml"), registry)
    return pipeline.run(plan, registry, dungeon(seed=3, rooms=12).mesh, "dungeon", "-")


def test_mesh_los_whole_forest_path_builds_the_loop_structure_in_later_heat_rounds_too(monkeypatch, sampled):
    # mesh_los's whole-forest path (its walk test asked back from C++) against its chain-by-chain calls, on the
    # run's forest and random ones, in a first round and in a later heat round that keeps the first's structure and
    # some removed nodes. One predicate for both rounds, as the guarantee asks it: the later round's chains are
    # asked in C++ again, but its walk test casts rays only for walks no earlier round tested.
    from g2s_plugins import _raycasting
    from g2s_plugins.predicates import mesh_los

    walks, sights = [], []
    monkeypatch.setattr(mesh_los, "walks_in_batch", lambda caster, starts, *args, **kwargs: walks.append(len(starts))
                        or _raycasting.walks_in_batch(caster, starts, *args, **kwargs))
    seeing = mesh_los.collapse_forest_seeing
    monkeypatch.setattr(mesh_los, "collapse_forest_seeing", lambda forest, rule, sees, memo: seeing(
        forest, rule, lambda pairs: sights.append(len(pairs)) or sees(pairs), memo))
    params = mesh_los.Params(normal_tolerance_deg=45.0, max_traffic_step=30.0)
    for seed, forest in enumerate([sampled.forest] + [random_forest(sampled.graph, seed) for seed in range(3)]):
        predicate = mesh_los.g2s_simplify_predicate(params, sampled.context, forest, None)
        reference = mesh_los.g2s_simplify_predicate(params, sampled.context, forest, None)
        kept: set[int] = set()
        tested, asked = [], []
        for _ in range(2):  # a first round, then a later one
            walks.clear()
            sights.clear()
            structure = simplify_forest(forest, keeping(predicate, kept))
            tested.append(sum(walks))
            asked.append(sum(sights))
            assert kept <= set(structure)
            assert layout(structure) == layout(simplify_forest(forest, keeping(through_python(reference), kept)))
            removed = sorted(set(forest) - set(structure))
            kept = set(structure) | set(random.Random(seed).sample(removed, len(removed) // 10))
        assert forest.number_of_nodes() > structure.number_of_nodes()
        assert asked[1] > 0 and tested[1] < 0.25 * tested[0]


def test_a_batched_line_of_sight_that_fails_or_answers_short_stops_the_simplification(sampled):
    from g2s_core.simplify import forest_arrays
    from g2s_plugins.recast.navmesh import collapse_forest_seeing

    forest = forest_arrays(sampled.forest)
    n = len(forest.ids)
    rule = _surface.RuleArrays(on_navmesh=np.ones(n, bool), rank=np.full(n, np.nan), normals=np.tile([0.0, 1.0, 0.0], (n, 1)),
                               normal_lengths=np.ones(n), max_step=None, tolerance_deg=10.0, whole_chain=True)
    batches = []

    def sees(pairs):
        batches.append(pairs.copy())
        return np.ones(len(pairs), bool)

    kept, added, loop = collapse_forest_seeing(forest, rule, sees)
    # every walk passes: some nodes go
    assert len(batches) >= 1 and all(pairs.shape[1] == 2 for pairs in batches) and not kept.all()

    def failing(pairs):
        raise ValueError("no walk")

    with pytest.raises(ValueError, match="no walk"):
        collapse_forest_seeing(forest, rule, failing)
    with pytest.raises(ValueError, match="every pair"):
        collapse_forest_seeing(forest, rule, lambda pairs: np.ones(len(pairs) + 1, bool))


def test_a_memo_asks_a_batched_line_of_sight_about_each_segment_once_and_answers_as_it_did(runs, sampled):
    # a later heat round (more fixed nodes) asks many of the first round's chains again: with a memo they are
    # answered from it, by segment and either way round (a pair (c, a) after (a, c) is asked no more), and every
    # round's answer is the one the same call gives without a memo
    from g2s_core.simplify import forest_arrays
    from g2s_plugins.recast.navmesh import collapse_forest_seeing

    forest = forest_arrays(random_forest(sampled.graph, 1))
    n = len(forest.ids)
    rule = _surface.RuleArrays(on_navmesh=np.ones(n, bool), rank=np.full(n, np.nan), normals=np.tile([0.0, 1.0, 0.0], (n, 1)),
                               normal_lengths=np.ones(n), max_step=None, tolerance_deg=10.0, whole_chain=True)
    clear = np.random.default_rng(0).random((n, n)) < 0.7
    clear &= clear.T  # the same answer both ways round, as the memo needs
    asked: list[tuple[int, int]] = []

    def sees(pairs):
        asked.extend(map(tuple, pairs.tolist()))
        return clear[pairs[:, 0], pairs[:, 1]]

    memo = NavMesh.sight_memo()
    later = dataclasses.replace(forest, fixed=forest.fixed | (np.random.default_rng(1).random(n) < 0.2))
    answers = [collapse_forest_seeing(forest, rule, sees, memo)]
    first = len(asked)
    answers.append(collapse_forest_seeing(later, rule, sees, memo))
    segments = {frozenset(pair) for pair in asked[:first]}
    assert first > 100 and len(asked) > first  # the later round asks a few chains anew
    assert not any(frozenset(pair) in segments for pair in asked[first:])  # none asked before, either way round
    assert len(memo) == 2 * len({frozenset(pair) for pair in asked}) and memo.hits > len(asked) - first
    for answer, arrays in zip(answers, (forest, later)):
        assert all(np.array_equal(x, y) for x, y in zip(answer, collapse_forest_seeing(arrays, rule, sees)))
    # a navmesh's memo holds Detour's answers, this one those of sees: neither call takes the other's
    navmesh, navmesh_forest = runs["castle"].context.navmesh, forest_arrays(random_forest(runs["castle"].graph, 0))
    m = len(navmesh_forest.ids)
    navmesh_rule = dataclasses.replace(rule, on_navmesh=np.ones(m, bool), rank=np.full(m, np.nan),
                                       normals=np.tile([0.0, 1.0, 0.0], (m, 1)), normal_lengths=np.ones(m))
    with pytest.raises(ValueError, match="sight memo"):
        navmesh.collapse_forest(navmesh_forest, navmesh_rule, 0.1, 0.3, memo)
    detour = navmesh.sight_memo()
    navmesh.collapse_forest(navmesh_forest, navmesh_rule, 0.1, 0.3, detour)
    with pytest.raises(ValueError, match="sight memo"):
        collapse_forest_seeing(forest, rule, sees, detour)
