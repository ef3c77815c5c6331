"""The map-piece preset end to end: every piece gives one rooted, simplified tree joining all its openings."""

from __future__ import annotations

import networkx as nx
import pytest

from g2s_core import pipeline
from g2s_plugins.samples import levels as samples
from g2s_core.config import PRESETS_DIR, load_config
from g2s_core.mesh import load_mesh, mesh_sha256
from g2s_core.registry import Registry

PIECES_WITH_OPENINGS = ("straight_corridor", "corridor_with_ramp", "cross_hub", "t_hub", "room_with_window")


@pytest.fixture(scope="module")
def map_piece():
    registry = Registry.from_entry_points()
    plan = pipeline.plan(load_config(PRESETS_DIR / "map_piece.yaml"), registry)
    return lambda mesh, name: pipeline.run(plan, registry, mesh, name, mesh_sha256(mesh))


def assert_one_tree_joining_every_opening(result) -> None:
    structure = result.structure
    assert result.terminals.openings and len(result.terminals.nodes) == len(result.terminals.openings)
    assert set(result.terminals.nodes) <= set(structure)
    assert nx.is_tree(structure.to_undirected())
    [root] = structure.graph["roots"]
    assert structure.nodes[root]["depth"] == 0
    assert set(result.analysis["depth"]) == set(structure)


@pytest.mark.parametrize("name", PIECES_WITH_OPENINGS)
def test_generated_pieces(map_piece, name):
    level = samples.load_sample(name)
    result = map_piece(level.mesh, name)
    assert len(result.terminals.openings) == len(level.openings)
    assert_one_tree_joining_every_opening(result)


def test_straight_corridor_reduces_to_at_most_three_nodes(map_piece):
    result = map_piece(samples.straight_corridor().mesh, "straight_corridor")
    assert result.structure.number_of_nodes() <= 3


def test_closed_room_stops_with_a_clear_warning(map_piece):
    result = map_piece(samples.closed_room().mesh, "closed_room")
    assert result.terminals.nodes == () and result.structure is None
    assert any("found no terminals" in w for w in result.warnings)


@pytest.mark.parametrize("piece", ["Hallway", "Ramp"])
def test_pieces_from_the_data_set(map_piece, shared_data, piece):
    mesh, info = load_mesh(shared_data / "pieces" / f"{piece}.obj")
    result = map_piece(mesh, info.name)
    assert len(result.terminals.openings) >= 5
    assert_one_tree_joining_every_opening(result)
