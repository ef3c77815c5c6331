"""``benchmarks/structure_sources.py`` on the T hub (a square hub with three arms, 9 navmesh polygons on
``map_analysis``): where each structure node comes from and which simplification keeps it, checked by hand."""

from __future__ import annotations

import pytest
from tests.conftest import benchmark

from g2s_core import pipeline
from g2s_core.config import find_config, load_raw_config
from g2s_core.mesh import mesh_sha256
from g2s_core.registry import Registry
from g2s_plugins.samples import levels

sources = benchmark("structure_sources")


@pytest.fixture(scope="module")
def t_hub():
    """The T hub, ``map_analysis``'s raw config, the installed plugins and the preset's run."""
    registry, raw = Registry.from_entry_points(), load_raw_config(find_config("map_analysis"))
    mesh = levels.t_hub().mesh
    run = pipeline.run(sources.plan_with(raw, "map_analysis", {}, registry), registry, mesh, "t_hub", mesh_sha256(mesh))
    return registry, raw, mesh, run


def test_removing_every_removable_node_keeps_the_forests_leaves_and_root(t_hub):
    # Algorithm 4 never removes a leaf or a root, and with no predicate it removes every other node of a tree without
    # terminals among its inner nodes
    run = t_hub[3]
    kept, rounds = sources.simplified(run, None)
    leaves = {node for node in run.forest if run.forest.out_degree(node) == 0}
    assert set(kept) == leaves | set(run.forest.graph["roots"])
    assert rounds == 1


def test_the_preset_simplified_again_is_the_runs_structure(t_hub):
    registry, raw, _, run = t_hub
    params = sources.plan_with(raw, "map_analysis", {}, registry).stages["simplify"][0].params
    assert set(sources.simplified(run, params)[0]) == set(run.structure)


def test_every_structure_node_has_one_origin_and_one_test(t_hub):
    registry, raw, mesh, run = t_hub
    report = sources.level_report("t_hub", mesh, raw, "map_analysis", registry)
    # the forest is every polygon: 4 seeded leaves, 4 cover waypoints and the hub's Steiner node that joins them
    assert report["polygons"] == report["forest"] == run.forest.number_of_nodes() == 9
    assert report["forest_origins"] == {"leaf": 4, "traffic cover": 4, "plain cover": 0, "steiner": 1, "loop": 0}
    seeded = set(run.terminals.nodes) - set(run.terminals.waypoints)
    assert report["table"]["leaf"]["always"] == len(seeded) == 4
    assert sum(sum(row.values()) for row in report["table"].values()) == run.structure.number_of_nodes()
    # 6 nodes with no predicate (the forest's 5 leaves and its root); line of sight keeps one more, a waypoint
    assert report["sizes"]["always"] == 6 and report["sizes"]["+guarantee"] == 7
    assert report["table"]["traffic cover"]["raycast"] == 1
    assert set(report["front"]) == set(sources.TERMINAL_LEVERS)
