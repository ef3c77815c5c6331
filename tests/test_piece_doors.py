"""Doors in thick walls, narrow walkways, chamfers and curbs on the map-piece preset (docs/entry_exit.md, "Causes fixed").

Each test holds one cause found and fixed, on a small generated piece of
:mod:`g2s_plugins.samples.pieces` or on hand-made detector input.
"""

from __future__ import annotations

import numpy as np
import pytest
import trimesh

from g2s_core.config import PRESETS_DIR, load_config
from g2s_plugins._raycasting import RayCaster
from g2s_plugins.recast import RecastParams, build_navmesh
from g2s_plugins.recast.settings import resolve_settings, voxel_config
from g2s_plugins.samples import pieces
from g2s_plugins.terminals import entry_exit

CONFIG = load_config(PRESETS_DIR / "map_piece.yaml")


def test_the_preset_erodes_exactly_the_agent_radius() -> None:
    # Recast erodes ceil(radius / cell_size) cells in single precision: 0.4 / 0.133 is 3.0075, so 4 cells
    # (0.532 m); the preset's cell size is 0.4 / 3 in single precision, 3 cells of it are the radius.
    params = RecastParams(**CONFIG.graph.params)
    voxels = voxel_config(resolve_settings(CONFIG.agent, params))
    assert voxels["walkableRadius"] == 3
    assert float(voxels["walkableRadius"] * voxels["cs"]) == pytest.approx(CONFIG.agent.radius, abs=1e-6)
    level = pieces.thick_wall_door()
    navmesh = build_navmesh(level.mesh.vertices, level.mesh.faces, CONFIG.agent, params)
    assert navmesh.config()["walkableRadius"] == 3
    # The 1.2 m doorway (west, z 2.4-3.6 m) in the 1 m wall (x -1 to 0) stays open: navmesh inside the wall.
    inside = navmesh.vertices[navmesh.vertices[:, 0] < -0.3]
    assert len(inside) and np.all((inside[:, 2] > 2.4) & (inside[:, 2] < 3.6))


@pytest.mark.parametrize(
    ("name", "kwargs", "yaw"),
    [
        # Before, Recast closed these doors (1.2 m doors in walls 1-1.2 m thick: found at 2 and 0 of 9 yaws).
        ("thick_wall_door", {"wall": 1.2, "doors": (1.2, 1.2)}, 0.0),
        ("thick_wall_door", {"wall": 1.0, "doors": (1.2, 1.2)}, 45.0),
        # Before, no navmesh at all (a 1.2 m walkway between railings: 0 of 9 yaws).
        ("bridge", {"width": 1.2}, 15.0),
        # Before the snap's slack, a navmesh corner Recast raised onto the 0.35 m curb looked over it.
        ("curb_platform", {"curb": 0.35, "gap": 1.2}, 45.0),
        # The chamfers (0.64 m) measured 0.88 m when the extension's probes stood 0.1 m inside the edge.
        ("chamfered_platform", {}, 30.0),
        # Thresholds higher than the rays (0.2 m): found from the step's top, between the door's jambs.
        ("threshold_door", {"step": 0.3}, 0.0),
        ("threshold_door", {"step": 0.35}, 10.0),
    ],
)
def test_every_known_opening_and_nothing_else(run_piece, name: str, kwargs: dict, yaw: float) -> None:
    level, result = run_piece(name, yaw, **kwargs)
    found = result.terminals.openings
    assert len(found) == len(level.openings), [(o.position, o.width) for o in found]
    for known in level.openings:
        distances = [float(np.linalg.norm(np.subtract(o.position, known.position))) for o in found]
        best = found[int(np.argmin(distances))]
        assert min(distances) <= CONFIG.agent.radius, f"{name} at {yaw} degrees: no opening near {known.position}"
        assert best.width == pytest.approx(known.width, abs=0.1)
    assert len(result.structure.graph["roots"]) == 1


def _ways(directions: np.ndarray, edges: np.ndarray) -> entry_exit._Ways:
    n = len(edges)
    up = np.tile([0.0, 1.0, 0.0], (n, 1))
    tangent = np.tile([0.0, 0.0, -1.0], (n, 1))
    return entry_exit._Ways(edges.copy(), up, tangent, np.ones(n, bool), directions, edges, np.zeros(n, bool),
                            np.zeros(n), np.zeros(n, bool), np.full((n, 3), np.nan))


def test_a_segment_that_walks_round_a_corner_is_fitted_without_the_corner() -> None:
    # The shared Hallway's recessed connector at yaw 0: the way out turns 20-25 degrees a sample round
    # the notch's corner (never 30 at once), then runs straight along the edge x = 1 for 9 samples.
    turn = np.radians([-70.0, -65.0, -45.0, -25.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0])
    directions = np.stack([np.cos(turn), np.zeros_like(turn), np.sin(turn)], axis=1)
    corner = [[1.45, 0.0, -0.87], [1.25, 0.0, -0.87], [1.09, 0.0, -0.87], [1.01, 0.0, -0.87]]
    straight = [[1.0, 0.0, -0.94 - 0.2 * i] for i in range(9)]
    ways = _ways(directions, np.array(corner + straight))
    settings = entry_exit._settings(entry_exit.Params(), CONFIG.agent)
    floor = RayCaster(trimesh.creation.box(bounds=[[-1.0, -0.2, -3.0], [3.0, 0.0, 1.0]]))  # the edge points' ground
    (edge,) = entry_exit._match_edges([np.arange(13)], ways, floor, settings, entry_exit.Params())
    assert edge.samples.tolist() == list(range(3, 13))  # the corner's samples looking out 45+ degrees away dropped
    assert edge.outward == pytest.approx([1.0, 0.0, 0.0], abs=0.01)
    assert edge.first[0] == pytest.approx(1.0, abs=0.01) and edge.last[0] == pytest.approx(1.0, abs=0.01)
    # Whole, the segment fits no line: the corner's four edge points are off it.
    _, _, residual = entry_exit._fit_line(ways.edge)
    assert np.count_nonzero(residual <= 0.1) < 0.8 * 13


def _detect(level, **params):
    navmesh = build_navmesh(level.mesh.vertices, level.mesh.faces, CONFIG.agent, RecastParams(**CONFIG.graph.params))
    return entry_exit.detect_openings(level.mesh, navmesh, CONFIG.agent, entry_exit.Params(**params))


def test_a_step_up_is_a_doorway_only_between_jambs() -> None:
    threshold = pieces.threshold_door(step=0.3)
    assert len(_detect(threshold).openings) == 2
    (level,) = _detect(threshold, step_up=False).openings  # the rays at 0.2 m meet the 0.3 m step
    assert level.position[0] > 1.0  # the east doorway only
    # The curb is the same step at the piece's edge, with no jambs: only its gaps are openings.
    curb = pieces.curb_platform(curb=0.3)
    found = _detect(curb).openings
    assert len(found) == 2 and all(o.width == pytest.approx(2.0, abs=0.1) for o in found)
