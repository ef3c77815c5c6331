"""benchmarks/reference_stability.py: the string-pulled path and the floor raster, on hand-built corridors."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

from tests.conftest import benchmark

stability = benchmark("reference_stability")


def point(x: float, z: float, y: float = 0.0) -> np.ndarray:
    return np.array([x, y, z])


def corridor_portals(centres: list[np.ndarray],
                     portals: list[tuple[np.ndarray, np.ndarray]]) -> tuple[np.ndarray, np.ndarray]:
    """The portals' (left, right) ends as :func:`pulled_flow` orders them, seen from each polygon's centre."""
    lefts, rights = [], []
    for centre, (e0, e1) in zip(centres, portals):
        right_first = stability._cross(centre, e1, e0) > 0.0
        lefts.append(e1 if right_first else e0)
        rights.append(e0 if right_first else e1)
    return np.array(lefts), np.array(rights)


def test_the_path_turns_at_the_inner_corner_either_way() -> None:
    # a corridor 2 m wide along +x (polygons x 0-2, 2-4, 4-6), then one along +z or -z from x 4-6
    for side in (1.0, -1.0):
        centres = [point(1, 0), point(3, 0), point(5, 0)]
        portals = [(point(2, -1), point(2, 1)), (point(4, -1), point(4, 1)), (point(4, side), point(6, side))]
        lefts, rights = corridor_portals(centres, portals)
        path = stability.funnel(point(0, 0), point(5, 7 * side), lefts, rights)
        # straight to the inner corner (4, side), crossing x = 2 half way, then straight to the end
        np.testing.assert_allclose(path[1], point(2, 0.5 * side))
        assert any(np.allclose(p, point(4, side)) for p in path)
        np.testing.assert_allclose(path[-1], point(5, 7 * side))
        assert len(path) <= 5


def test_a_straight_walk_crosses_each_portal_at_its_height() -> None:
    # a ramp: the portals rise 1 m each; the walk from z = 0 straight along x crosses them at z = 0 and their height
    centres = [point(1, 0, 0.5), point(3, 0, 1.5)]
    portals = [(point(2, -1, 1.0), point(2, 1, 1.0)), (point(4, -1, 2.0), point(4, 1, 2.0))]
    lefts, rights = corridor_portals(centres, portals)
    path = stability.funnel(point(0, 0, 0.0), point(5, 0, 2.5), lefts, rights)
    np.testing.assert_allclose(path[1:3], [point(2, 0, 1.0), point(4, 0, 2.0)])
    dense = stability.densified(path)
    assert np.all(np.hypot(*np.diff(dense[:, [0, 2]], axis=0).T) <= stability.PATH_STEP + 1e-12)


def test_the_raster_counts_each_cell_of_a_square_once() -> None:
    # a 1 m square of two triangles sharing a diagonal, 0.5 m up: 4 x 4 cells of 0.25 m, none twice
    corners = [point(0, 0, 0.5), point(1, 0, 0.5), point(1, 1, 0.5), point(0, 1, 0.5)]
    square = SimpleNamespace(detail_vertices=np.array(corners),
                             detail_triangles=np.array([[0, 1, 2], [0, 2, 3]]))
    cells = stability.floor_raster(square, 0.25)
    assert len(cells) == 16
    np.testing.assert_allclose(sorted(set(cells[:, 0])), [0.125, 0.375, 0.625, 0.875])
    assert np.all(cells[:, 1] == 0.5)
