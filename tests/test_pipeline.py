"""The whole pipeline on generated levels with known answers, and on the real test level."""

from __future__ import annotations

import networkx as nx
import pytest

from g2s_core import pipeline
from g2s_plugins.samples import levels as samples
from g2s_core.config import PRESETS_DIR, load_config, parse_config, load_raw_config
from g2s_core.errors import ConfigError
from g2s_core.mesh import load_mesh, mesh_sha256
from g2s_core.registry import Registry

FLOOR_POINTS = {"points": [[2, 0, 2], [32, 4, 8]], "max_distance": 4.0}
"""A point on each floor of samples.two_floors()."""


@pytest.fixture(scope="module")
def registry() -> Registry:
    return Registry.from_entry_points()


def run(registry: Registry, mesh, preset: str = "map_analysis_paper", **overrides):
    raw = load_raw_config(PRESETS_DIR / f"{preset}.yaml")
    raw.update(overrides)
    plan = pipeline.plan(parse_config(raw), registry)
    return pipeline.run(plan, registry, mesh, "level", mesh_sha256(mesh))


def trees(structure: nx.DiGraph) -> list[set[int]]:
    return [set(c) for c in nx.weakly_connected_components(structure)]


def test_two_floors_are_joined_through_the_ramp(registry):
    level = samples.two_floors(ramp=True)
    ramp = level.metadata["ramp"]
    result = run(registry, level.mesh, terminals={"plugin": "points", "params": FLOOR_POINTS})
    [tree] = trees(result.structure)
    heights = sorted(result.structure.nodes[n]["pos"][1] for n in tree)
    assert heights[0] == pytest.approx(0.0, abs=0.3) and heights[-1] == pytest.approx(4.0, abs=0.3)
    on_ramp = [n for n in tree if ramp["x0"] < result.structure.nodes[n]["pos"][0] < ramp["x1"]]
    assert on_ramp, "the structure must pass over the ramp"
    # ... on its surface, not under it (within half a metre of the ramp's height there)
    for n in on_ramp:
        x, y, _ = result.structure.nodes[n]["pos"]
        assert y == pytest.approx(ramp["y0"] + (x - ramp["x0"]) / ramp["run"] * (ramp["y1"] - ramp["y0"]), abs=0.5)
    assert not result.warnings


def test_without_the_ramp_the_floors_give_two_trees_and_a_warning(registry):
    result = run(registry, samples.two_floors(ramp=False).mesh, terminals={"plugin": "points", "params": FLOOR_POINTS})
    assert len(trees(result.structure)) == 2
    assert len(result.structure.graph["roots"]) == 2
    assert any("2 disconnected areas" in w for w in result.warnings)


def test_every_stage_is_timed_and_counted(registry):
    result = run(registry, samples.dungeon(seed=1, rooms=8).mesh)
    assert [s.stage for s in result.stages] == ["graph", "terminals", "steiner", "roots", "simplify", "analysis"]
    graph, steiner, structure = result.stage("graph"), result.stage("steiner"), result.stage("simplify")
    assert graph.nodes == result.graph.number_of_nodes() and graph.edges == result.graph.number_of_edges()
    assert result.stage("terminals").terminals == len(result.terminals.nodes) > 2
    assert steiner.nodes == result.steiner.number_of_nodes() and steiner.edges == steiner.nodes - len(trees(result.structure))
    assert structure.nodes <= steiner.nodes and nx.is_forest(result.structure.to_undirected())
    assert set(result.analysis["betweenness"]) == set(result.structure)
    assert all(s.seconds >= 0 for s in result.stages)


def test_leaf_terminals_all_survive_to_the_structure(registry):
    result = run(registry, samples.dungeon(seed=2, rooms=10).mesh)
    assert set(result.terminals.nodes) <= set(result.structure)
    # the simplified structure keeps every terminal and is a forest of the same trees
    assert len(trees(result.structure)) == len(trees(result.forest))


def test_stop_after_any_stage(registry):
    mesh = samples.cross_hub().mesh
    for stage, attribute in (("graph", "graph"), ("terminals", "terminals"), ("steiner", "steiner"), ("roots", "forest"), ("simplify", "structure")):
        result = run(registry, mesh, terminals={"plugin": "points", "params": {"points": [[0, 0, 0], [0, 0, 8]], "max_distance": 5}}, stop_after=stage)
        assert getattr(result, attribute) is not None
        assert result.stages[-1].stage == stage


def test_same_input_gives_the_same_structure(registry):
    mesh = samples.dungeon(seed=3, rooms=10).mesh
    first, second = run(registry, mesh), run(registry, mesh)
    assert list(first.structure.edges) == list(second.structure.edges)
    assert first.analysis == second.analysis


def test_a_stage_whose_plugin_is_missing_is_an_error_before_any_work(registry):
    raw = load_raw_config(PRESETS_DIR / "map_analysis.yaml")
    raw["roots"] = {"plugin": "elsewhere"}
    with pytest.raises(ConfigError, match="roots.plugin: RootSelector plugin 'elsewhere' is not installed"):
        pipeline.plan(parse_config(raw), registry)
    raw = load_raw_config(PRESETS_DIR / "map_analysis.yaml")
    del raw["steiner"]
    with pytest.raises(ConfigError, match="steiner: required key is missing"):
        pipeline.plan(parse_config(raw), registry)


def test_map_analysis_on_the_real_level(registry, shared_data):
    config = load_config(PRESETS_DIR / "map_analysis_paper.yaml")
    config = config.model_copy(update={"agent": config.agent.model_copy(update={"radius": 0.6, "max_climb": 0.9})})
    mesh, info = load_mesh(shared_data / "nav_test.obj")
    result = pipeline.run(pipeline.plan(config, registry), registry, mesh, info.name, info.sha256)
    structure = result.structure
    assert 100 <= result.graph.number_of_nodes() <= 220
    assert set(result.terminals.nodes) == {n for n, d in result.graph.degree if d == 1}
    assert structure.number_of_nodes() < result.steiner.number_of_nodes()
    values = result.analysis["betweenness"]
    assert max(values.values()) > 0 and set(values) == set(structure)
    # the level's areas are disconnected: the run says so and roots one tree per area
    assert any("disconnected areas" in w for w in result.warnings)
    assert len(structure.graph["roots"]) == len(trees(structure)) >= 3
