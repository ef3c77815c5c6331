"""No edge of a final structure strays more than 0.5 m above or below the walkable surface.

Every generated sample and piece (:data:`g2s_plugins.samples.levels.SAMPLES`)
under both presets, and the shared nav_test level under the map-analysis one
(the shared pieces: ``tests/test_shared_pieces.py``). The initial graph's
edges over crests and troughs go through portal nodes (the navmesh builder's
``max_edge_gap``) and collapses stay within ``max_surface_gap`` of the
surface (``surface_los``); this checks what the two give together, probing
every 0.1 m along each edge between on-navmesh nodes. The default building's
watershed regions overlap themselves (a known Recast defect), so the default
``partition: auto`` builds it with monotone regions, and its structure passes (the
builder routes centre segments that cut a corner of the navmesh between its
probes, module doc). Recast's detail mesh read some polygons' heights from
another storey of their region (storey 2's floor from the flight below it with
``partition: watershed``, a stair from the turn above on the castle); the
navmesh rebuilds those (``NavMesh.detail_redone_polygons``), and both pass.
"""

from __future__ import annotations

import pytest

from g2s_core import pipeline
from g2s_core.config import PRESETS_DIR, load_config, load_raw_config, parse_config, set_key
from g2s_core.mesh import load_mesh
from g2s_core.registry import Registry
from g2s_plugins._surface import edge_surface_gaps
from g2s_plugins.samples.levels import SAMPLES
from tests.test_recast import spiral_tower

LIMIT = 0.5
"""Metres a final edge may pass above or below the walkable surface."""

PRESETS = ("map_piece", "map_analysis")

@pytest.fixture(scope="module")
def plans():
    registry = Registry.from_entry_points()
    return registry, {name: pipeline.plan(load_config(PRESETS_DIR / f"{name}.yaml"), registry) for name in PRESETS}


def _largest_gap(registry, plan, mesh, name: str) -> float:
    result = pipeline.run(plan, registry, mesh, name, "-")
    if result.structure is None:  # no terminals: no structure to check
        return 0.0
    gaps = edge_surface_gaps(result.structure, result.context.navmesh, result.context.agent)
    return max(gaps.values(), default=0.0)


@pytest.mark.parametrize("preset", PRESETS)
@pytest.mark.parametrize("sample", sorted(SAMPLES))
def test_generated_structures_stay_on_the_surface(plans, sample: str, preset: str) -> None:
    registry, plan = plans[0], plans[1][preset]
    assert _largest_gap(registry, plan, SAMPLES[sample]().mesh, sample) <= LIMIT


def test_spiral_stair_structure_stays_on_the_surface(plans) -> None:
    # watershed gets no navmesh at all here; auto's monotone regions keep the turns apart (tests/test_recast.py)
    registry, plan = plans[0], plans[1]["map_analysis"]
    result = pipeline.run(plan, registry, spiral_tower(), "spiral_tower", "-")
    assert len(result.context.navmesh.repartitioned_tiles) == 1 and result.structure.number_of_edges() > 5
    gaps = edge_surface_gaps(result.structure, result.context.navmesh, result.context.agent)
    assert max(gaps.values()) <= LIMIT


def test_nav_test_structure_stays_on_the_surface(plans, shared_data) -> None:
    registry, plan = plans[0], plans[1]["map_analysis"]
    mesh, _ = load_mesh(shared_data / "nav_test.obj")
    assert _largest_gap(registry, plan, mesh, "nav_test") <= LIMIT

def test_watershed_building_stays_on_the_surface(plans) -> None:
    # watershed's stairwell region overlaps itself and Recast's detail mesh read storey 2's floor over
    # flight 0 from the flight, 5 m below: structure edges left the surface by metres there until the
    # navmesh rebuilt such polygons' detail (NavMesh.detail_redone_polygons)
    registry = plans[0]
    raw = set_key(load_raw_config(PRESETS_DIR / "map_analysis.yaml"), "graph.params.partition", "watershed", "test")
    plan = pipeline.plan(parse_config(raw), registry)
    assert _largest_gap(registry, plan, SAMPLES["building"]().mesh, "building") <= LIMIT
