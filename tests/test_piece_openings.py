"""Entry/exit detection and the map-piece preset on the generated pieces of :mod:`g2s_plugins.samples.pieces`.

Each of the first six pieces reproduces a case that fooled the detector on
real pieces (curbs, unreachable wall tops, doorways in thick walls, stairs,
wall-less slabs, chamfers); the held-out families (``pieces.HELD_OUT``) are
shapes the rules were not measured on. Their known openings are the ground truth.
"""

from __future__ import annotations

import numpy as np
import pytest

from g2s_core.config import PRESETS_DIR, load_config
from g2s_plugins._surface import MAX_SURFACE_GAP, edge_surface_gaps
from g2s_plugins.recast import RecastParams, build_navmesh
from g2s_plugins.samples import levels, pieces
from g2s_plugins.terminals import entry_exit

CONFIG = load_config(PRESETS_DIR / "map_piece.yaml")


def test_the_pieces_are_registered_samples_for_the_preset_agent() -> None:
    assert set(pieces.PIECES) <= set(levels.SAMPLES)
    agent = CONFIG.agent
    assert (agent.radius, agent.height, agent.max_climb, agent.max_slope) == tuple(pieces.PIECE_AGENT.values())


@pytest.mark.parametrize("name", sorted(pieces.PIECES))
def test_every_known_opening_and_nothing_else(run_piece, name: str) -> None:
    level, result = run_piece(name)
    found = result.terminals.openings
    assert len(found) == len(level.openings), [o.position for o in found]
    radius = CONFIG.agent.radius
    for known in level.openings:
        distances = [float(np.linalg.norm(np.subtract(o.position, known.position))) for o in found]
        best = found[int(np.argmin(distances))]
        assert min(distances) <= radius, f"{name}: no opening near {known.position}"
        assert np.dot(best.heading, known.heading) > 0.98
        assert best.width == pytest.approx(known.width, abs=2 * radius)
        assert 0.0 < best.score <= 1.0 and "outer extent" in best.reason


@pytest.mark.parametrize("name", sorted(pieces.PIECES))
def test_one_tree_per_piece_on_the_surface(run_piece, name: str) -> None:
    _, result = run_piece(name)
    assert len(result.structure.graph["roots"]) == 1
    assert set(result.terminals.nodes) <= set(result.structure)
    gaps = edge_surface_gaps(result.structure, result.context.navmesh, result.context.agent)
    assert max(gaps.values(), default=0.0) <= MAX_SURFACE_GAP + 0.05


def _detect(level, **params):
    navmesh = build_navmesh(level.mesh.vertices, level.mesh.faces, CONFIG.agent, RecastParams(**CONFIG.graph.params))
    return entry_exit.detect_openings(level.mesh, navmesh, CONFIG.agent, entry_exit.Params(**params))


def test_priors_are_what_removes_the_spurious_edges() -> None:
    # Off, the cross's arm sides (6.5 m inside its extent) come back ...
    loose = _detect(pieces.cross_platform(), extent_heights=None)
    assert len(loose.openings) == 12
    # ... and so do the unreachable wall top's edges.
    loose = _detect(pieces.wall_tops(), main_floor_only=False)
    assert any(o.position[1] > 3.0 for o in loose.openings)


def test_a_curb_lower_than_the_rays_is_stepped_over() -> None:
    low = pieces.curb_platform(curb=0.15)
    assert len(_detect(low, sample_height=0.1).openings) == 2  # the gaps
    over = _detect(low, sample_height=0.3).openings  # whole sides, the gaps' sides included
    assert len(over) == 4 and max(o.width for o in over) > 12.0


def test_best_and_min_score_keep_the_strongest_openings() -> None:
    level = pieces.doorway_room()
    every = _detect(level).openings
    scores = sorted((o.score for o in every), reverse=True)
    assert len(every) == 5 and scores[-1] < scores[0]
    best = _detect(level, best=2).openings
    assert sorted((o.score for o in best), reverse=True) == scores[:2]
    above = _detect(level, min_score=scores[-1] + 1e-6).openings
    assert len(above) == 4
