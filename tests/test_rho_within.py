"""``rho_within``: the heat map's agreement within each connected area, on hand-checkable graphs and through the
``traffic`` evaluator."""

from __future__ import annotations

import networkx as nx
import numpy as np
import pytest
import trimesh

from g2s_core import pipeline
from g2s_core.config import PRESETS_DIR, load_raw_config, parse_config
from g2s_core.mesh import mesh_sha256
from g2s_core.registry import Registry
from g2s_plugins import evaluation


def test_right_between_the_areas_and_reversed_within_them_reads_minus_one():
    # two areas of three nodes, flows 1-3 and 10-30: the heat map puts the busy area above the quiet one but
    # reverses each area's own order; level-wide, flow ranks 1..6 against heat ranks 3 2 1 6 5 4:
    # rho = 1 - 6 (4 + 0 + 4 + 4 + 0 + 4) / (6 (36 - 1)) = 0.543
    reference = np.array([1.0, 2.0, 3.0, 10.0, 20.0, 30.0])
    heat = np.array([3.0, 2.0, 1.0, 30.0, 20.0, 10.0])
    area = np.array([0, 0, 0, 1, 1, 1])
    assert evaluation.spearman(heat, reference) == pytest.approx(1 - 6 * 16 / 210)
    assert evaluation.within_area_rho(heat, reference, area) == pytest.approx(-1.0)


def test_wrong_between_the_areas_and_right_within_them_reads_one():
    # the quiet area's heat above the busy one's, each area's own order right: flow ranks 1..6 against heat ranks
    # 4 5 6 1 2 3, rho = 1 - 6 (6 x 9) / 210 = -0.543
    reference = np.array([1.0, 2.0, 3.0, 10.0, 20.0, 30.0])
    heat = np.array([11.0, 12.0, 13.0, 1.0, 2.0, 3.0])
    area = np.array([0, 0, 0, 1, 1, 1])
    assert evaluation.spearman(heat, reference) == pytest.approx(1 - 6 * 54 / 210)
    assert evaluation.within_area_rho(heat, reference, area) == pytest.approx(1.0)


def test_areas_weigh_by_their_rank_variance_about_one_a_node():
    # an area of 3 nodes ranked right (rho 1) and one of 5 reversed (rho -1), no ties: weights n - 1/n,
    # 8/3 and 24/5, so rho_within = (8/3 - 24/5) / (8/3 + 24/5) = -2/7
    reference = np.array([1.0, 2.0, 3.0, 1.0, 2.0, 3.0, 4.0, 5.0])
    heat = np.array([1.0, 2.0, 3.0, 5.0, 4.0, 3.0, 2.0, 1.0])
    area = np.array([7, 7, 7, 2, 2, 2, 2, 2])
    assert evaluation.within_area_rho(heat, reference, area) == pytest.approx(-2 / 7)
    # a node alone in its area has no rank to agree on: it weighs nothing
    alone = evaluation.within_area_rho(np.append(heat, 100.0), np.append(reference, 0.0), np.append(area, 9))
    assert alone == pytest.approx(-2 / 7)


def test_one_area_gives_rho_and_nodes_out_of_reach_are_left_out():
    rng = np.random.default_rng(3)
    reference = rng.integers(0, 6, 40).astype(float)  # ties in both
    heat = reference + rng.integers(0, 4, 40)
    heat[[5, 17]] = np.nan  # nodes that reach no structure node
    one_area = np.zeros(40, dtype=np.int64)
    assert evaluation.within_area_rho(heat, reference, one_area) == pytest.approx(evaluation.spearman(heat, reference),
                                                                                  abs=1e-12)
    # an area whose nodes all reach no structure node counts nothing
    areas = np.append(one_area, [1, 1, 1])
    outside = evaluation.within_area_rho(np.append(heat, [np.nan] * 3), np.append(reference, [9.0, 0.0, 5.0]), areas)
    assert outside == pytest.approx(evaluation.spearman(heat, reference), abs=1e-12)


def test_one_area_ranks_values_one_ulp_apart_as_rho_does():
    # a heat map of means holds values one ulp apart (a level's 78.57142857142858 twice and 78.57142857142857):
    # spearman ties only exact equals, so rho within one area must too, or the two read apart
    low = 78.57142857142857
    high = np.nextafter(low, np.inf)
    heat = np.array([high, high, low, 10.0, 90.0, 50.0])
    reference = np.array([3.0, 1.0, 2.0, 0.0, 5.0, 4.0])
    rho = evaluation.spearman(heat, reference)
    assert evaluation.within_area_rho(heat, reference, np.zeros(6, dtype=np.int64)) == pytest.approx(rho, abs=1e-12)


def test_undefined_when_no_area_has_an_order():
    area = np.array([0, 0, 1, 1])
    assert np.isnan(evaluation.within_area_rho(np.array([1.0, 1.0, 5.0, 5.0]), np.arange(4.0), area))
    assert np.isnan(evaluation.within_area_rho(np.array([1.0, np.nan]), np.arange(2.0), area[:2]))


def test_area_labels_follow_the_graphs_connected_areas():
    graph = nx.Graph()
    graph.add_nodes_from((n, {"pos": (float(n), 0.0, 0.0), "area": 1.0}) for n in range(6))
    graph.add_edges_from([(0, 1), (1, 2), (4, 5)], weight=1.0)
    labels = evaluation.area_labels(graph)
    assert labels[0] == labels[1] == labels[2] and labels[4] == labels[5] and len(set(labels.tolist())) == 3


def test_the_evaluator_reports_it_on_a_level_of_two_floors_apart():
    """Two slabs 20 m apart, too far for any link: two connected areas. On each the ``flow`` heat map of
    ``map_analysis`` is the ceiling's own (both exact), so within the areas it reads its ceiling."""
    slabs = [trimesh.creation.box((width, 0.2, 6.0)) for width in (30.0, 12.0)]
    slabs[1].apply_translation((0.0, 0.0, 20.0))
    mesh = trimesh.util.concatenate(slabs)
    raw = load_raw_config(PRESETS_DIR / "map_analysis.yaml")
    raw["evaluators"] = [{"plugin": "traffic"}]
    registry = Registry.from_entry_points()
    result = pipeline.run(pipeline.plan(parse_config(raw), registry), registry, mesh, "slabs", mesh_sha256(mesh))
    measures = result.metrics["traffic"]
    assert len(set(evaluation.area_labels(result.graph).tolist())) == 2
    assert -1.0 <= measures["rho_within"] <= 1.0
    assert measures["rho_within"] == pytest.approx(measures["rho_within_ceiling"], abs=1e-12)
