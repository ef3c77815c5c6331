"""Entry/exit detection does not depend on how a map piece is turned about the vertical (its yaw).

The generated pieces of :mod:`g2s_plugins.samples.pieces` turned by
:func:`~g2s_plugins.samples.pieces.turned`: every known opening and nothing
else, one tree; the piece's own frame; the floor Recast cuts in two at a
pinch stays one floor.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

from g2s_core.config import PRESETS_DIR, load_config
from g2s_plugins.samples import pieces
from g2s_plugins.terminals import entry_exit

CONFIG = load_config(PRESETS_DIR / "map_piece.yaml")


@pytest.mark.parametrize(
    ("name", "kwargs", "yaw"),
    [
        ("doorway_room", {}, 15.0),
        ("doorway_room", {}, 30.0),
        ("cross_platform", {}, 15.0),
        ("cross_platform", {}, 30.0),
        ("curb_platform", {}, 15.0),
        ("curb_platform", {}, 30.0),  # each curb gap was cut into 2 or 3 overlapping openings
        # 1.2 m doors Recast closes at some yaws: the floor's end lies the wall's thickness beyond the erosion.
        ("doorway_room", {"doors": (1.2,) * 5}, 45.0),
        ("doorway_room", {"wall": 0.8}, 45.0),
    ],
)
def test_a_turned_piece_gives_every_known_opening_and_nothing_else(run_piece, name: str, kwargs: dict, yaw: float) -> None:
    level, result = run_piece(name, yaw, **kwargs)
    found = result.terminals.openings
    assert len(found) == len(level.openings), [o.position for o in found]
    for known in level.openings:
        distances = [float(np.linalg.norm(np.subtract(o.position, known.position))) for o in found]
        best = found[int(np.argmin(distances))]
        assert min(distances) <= CONFIG.agent.radius, f"{name} at {yaw} degrees: no opening near {known.position}"
        assert np.dot(best.heading, known.heading) > 0.98
        assert best.width == pytest.approx(known.width, abs=2 * CONFIG.agent.radius)
    assert len(result.structure.graph["roots"]) == 1


def test_turned_moves_the_openings_with_the_piece() -> None:
    level = pieces.doorway_room()
    quarter = pieces.turned(level, 90.0)
    # +90 degrees about +Y takes the west door's heading -X to +Z, and keeps the bounding box's centre.
    assert quarter.openings[0].heading == pytest.approx((0.0, 0.0, 1.0), abs=1e-12)
    assert np.asarray(quarter.mesh.bounds).mean(axis=0) == pytest.approx(np.asarray(level.mesh.bounds).mean(axis=0))
    assert quarter.metadata["yaw_deg"] == 90.0


@pytest.mark.parametrize("yaw", [0.0, 5.0, 15.0, 30.0, 45.0, 80.0])
def test_the_piece_frame_is_its_walls_directions(yaw: float) -> None:
    frame = entry_exit.piece_frame(pieces.turned(pieces.doorway_room(), yaw).mesh)
    angle = math.degrees(math.atan2(-frame[0, 2], frame[0, 0])) % 90.0
    assert min(abs(angle - yaw % 90.0), 90.0 - abs(angle - yaw % 90.0)) < 1e-6
    assert frame[2] == pytest.approx(np.cross(frame[0], [0.0, 1.0, 0.0]))
    assert frame[1] == pytest.approx(-frame[0]) and frame[3] == pytest.approx(-frame[2])


def test_a_piece_on_x_and_z_keeps_exactly_x_and_z() -> None:
    for name in pieces.PIECES:
        frame = entry_exit.piece_frame(pieces.PIECES[name]().mesh)
        assert np.array_equal(np.abs(frame), [[1, 0, 0], [1, 0, 0], [0, 0, 1], [0, 0, 1]]), name


def test_a_turned_heading_is_measured_along_the_pieces_own_axis() -> None:
    # A 10 x 4 m box turned by 15 degrees: the midpoint of its long side, heading 3 degrees off the side's normal
    # (a short opening's fit noise), lies at the extent along the piece's axis, not 10 * sin(15) / 2 m inside it.
    turn = math.radians(15.0)
    u, w = np.array([math.cos(turn), 0.0, -math.sin(turn)]), np.array([math.sin(turn), 0.0, math.cos(turn)])
    corners = np.array([a * 5.0 * u + b * 2.0 * w for a in (-1, 1) for b in (-1, 1)])
    frame = np.array([u, -u, w, -w])
    noisy = math.radians(3.0)
    heading = math.cos(noisy) * w + math.sin(noisy) * u
    assert entry_exit.extent_gap(corners, 2.0 * w, heading, frame) == pytest.approx(0.0, abs=1e-12)
    axes = np.array([[1.0, 0.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 0.0, -1.0]])
    along_z = float(np.max(corners @ axes[2]) - 2.0 * w @ axes[2])
    assert along_z > 1.0  # on X and Z it would be dropped ...
    own = float(np.max(corners @ heading) - 2.0 * w @ heading)
    assert entry_exit.extent_gap(corners, 2.0 * w, heading, axes) == pytest.approx(own)  # ... a wrong frame never counts more


def _quads(*quads: tuple[float, float, float, float, float]) -> SimpleNamespace:
    """A navmesh of separate square-cornered quads (x0, x1, z0, z1, y), none joined by an edge."""
    vertices, polygons, areas = [], [], []
    for x0, x1, z0, z1, y in quads:
        start = len(vertices)
        vertices += [(x0, y, z0), (x0, y, z1), (x1, y, z1), (x1, y, z0)]
        polygons.append([start, start + 1, start + 2, start + 3])
        areas.append((x1 - x0) * (z1 - z0))
    return SimpleNamespace(
        vertices=np.array(vertices, dtype=np.float64),
        polygons=np.array(polygons, dtype=np.int32),
        neighbours=np.full((len(polygons), 4), -1, dtype=np.int32),
        areas=np.array(areas, dtype=np.float64),
    )


@pytest.mark.parametrize(
    ("second", "joined"),
    [
        ((2.1, 4.0, 0.0, 2.0, 0.0), True),  # 0.1 m away at the same height: one floor cut at a pinch
        ((2.0, 4.0, 0.0, 2.0, 0.3), True),  # touching, a step lower than the climb
        ((3.2, 5.1, 0.0, 2.0, 0.0), False),  # 1.2 m away: a wall stood between them
        ((2.1, 4.0, 0.0, 2.0, 0.6), False),  # a step higher than the climb
    ],
)
def test_the_main_floor_joins_floors_recast_cut_apart(second: tuple, joined: bool) -> None:
    # A 2 x 2 m half (4 m2), a second one (3.8-4 m2) and a 3 x 2 m roof (6 m2) 3 m up: the halves together are the
    # main floor; apart, the larger half is (the roof, over them, is never the main floor).
    navmesh = _quads((0.0, 2.0, 0.0, 2.0, 0.0), second, (0.0, 3.0, 0.0, 2.0, 3.0))
    main = entry_exit.main_floor(navmesh, CONFIG.agent)
    assert main.tolist() == ([True, True, False] if joined else [True, False, False])
