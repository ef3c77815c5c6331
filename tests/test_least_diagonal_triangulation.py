"""The detail-chord rule's triangulation (``_recast.least_diagonal_triangulation``) on hand-checked outlines.

Recast's ``triangulateHull`` fans out over a polygon with no inside samples; the rule replaces it with the
triangulation of least total diagonal length (docs/navmesh.md, Detail chords). Every case below has a
known minimum that a fan from the first point misses: a diagonal along a side (a flat triangle between
collinear samples) or a longer total.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

from g2s_plugins.recast import _recast


def triangulate(points, **kwargs) -> np.ndarray:
    return _recast.least_diagonal_triangulation(np.asarray(points, dtype=np.float64), **kwargs)


def signed_areas(points, triangles) -> np.ndarray:
    """(T,) signed plan areas, positive for counter-clockwise triangles."""
    a, b, c = (np.asarray(points, dtype=np.float64)[triangles[:, k]] for k in range(3))
    return 0.5 * ((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (c[:, 0] - a[:, 0]) * (b[:, 1] - a[:, 1]))


def diagonals(n: int, triangles) -> set[tuple[int, int]]:
    """The triangles' edges that are not sides of the n-point outline."""
    edges = {tuple(sorted((int(t[e]), int(t[(e + 1) % 3])))) for t in triangles for e in range(3)}
    return {(i, j) for i, j in edges if j - i not in (1, n - 1)}


def diagonal_lengths(points, triangles) -> np.ndarray:
    p = np.asarray(points, dtype=np.float64)
    return np.array(sorted(math.dist(p[i], p[j]) for i, j in diagonals(len(p), triangles)))


def assert_triangulates(points, triangles) -> None:
    """n - 2 counter-clockwise triangles of positive area that tile the (counter-clockwise, convex) outline:
    every side in one triangle, every diagonal in two, the areas summing to the outline's (shoelace)."""
    n = len(points)
    assert triangles.shape == (n - 2, 3) and triangles.dtype == np.int32
    assert np.all(signed_areas(points, triangles) > 0)
    uses: dict[tuple[int, int], int] = {}
    for t in triangles:
        for e in range(3):
            edge = tuple(sorted((int(t[e]), int(t[(e + 1) % 3]))))
            uses[edge] = uses.get(edge, 0) + 1
    assert all(uses.get((i, i + 1)) == 1 for i in range(n - 1)) and uses.get((0, n - 1)) == 1
    assert all(count == 2 for edge, count in uses.items() if edge[1] - edge[0] not in (1, n - 1))
    x, y = np.asarray(points, dtype=np.float64).T
    outline_area = 0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)
    assert signed_areas(points, triangles).sum() == pytest.approx(outline_area)


# A 2 x 2 square with the midpoint of each side, as Recast samples a polygon's edges.
SAMPLED_SQUARE = [(0, 0), (1, 0), (2, 0), (2, 1), (2, 2), (1, 2), (0, 2), (0, 1)]
# A 10 x 1 sliver sampled every metre along its long sides: 0..10 along the bottom, 11..21 back along the top.
SLIVER = [(x, 0) for x in range(11)] + [(x, 1) for x in range(10, -1, -1)]
# A regular hexagon of radius 2 about (3, -1).
HEXAGON = [(3 + 2 * math.cos(k * math.pi / 3), -1 + 2 * math.sin(k * math.pi / 3)) for k in range(6)]


def test_square_takes_one_diagonal_and_a_sampled_square_cuts_its_corners():
    triangles = triangulate([(0, 0), (2, 0), (2, 2), (0, 2)])
    assert_triangulates([(0, 0), (2, 0), (2, 2), (0, 2)], triangles)
    assert diagonal_lengths([(0, 0), (2, 0), (2, 2), (0, 2)], triangles) == pytest.approx([2 * math.sqrt(2)])
    # Any diagonal of a square is the minimum, a fan's too. With its sides' midpoints, each midpoint needs
    # a diagonal of its own (its neighbours are collinear with it): at best the four corners are cut off
    # (four diagonals of sqrt(2), the only ones that short) and the inner square split by one of length 2.
    triangles = triangulate(SAMPLED_SQUARE)
    assert_triangulates(SAMPLED_SQUARE, triangles)
    lengths = diagonal_lengths(SAMPLED_SQUARE, triangles)
    assert lengths == pytest.approx([math.sqrt(2)] * 4 + [2])
    assert lengths.sum() == pytest.approx(4 * math.sqrt(2) + 2)


def test_sliver_is_cut_across_never_along():
    # No diagonal joins two samples of one side (they are collinear), so each joins (x1, 0) to (x2, 1) and
    # is at least 1 long, exactly 1 only straight across: at most 9 such rungs (x = 1..9), and the other 10
    # of the n - 3 = 19 diagonals are at least sqrt(2). The minimum, 9 + 10 sqrt(2), is the ladder: the
    # 9 rungs and one diagonal of each unit square.
    triangles = triangulate(SLIVER)
    assert_triangulates(SLIVER, triangles)
    lengths = diagonal_lengths(SLIVER, triangles)
    assert len(lengths) == 19
    assert lengths.sum() == pytest.approx(9 + 10 * math.sqrt(2))
    assert lengths.max() == pytest.approx(math.sqrt(2))  # across the sliver, none along it
    assert np.count_nonzero(np.isclose(lengths, 1.0)) == 9


def test_regular_hexagon_takes_the_inner_triangle_not_a_fan():
    # Three diagonals: the inner triangle's three short ones (2 sqrt(3) each at radius 2, 6 sqrt(3) in all)
    # beat a fan's or a zigzag's two short ones and a long one through the centre (4 sqrt(3) + 4).
    triangles = triangulate(HEXAGON)
    assert_triangulates(HEXAGON, triangles)
    lengths = diagonal_lengths(HEXAGON, triangles)
    assert lengths == pytest.approx([2 * math.sqrt(3)] * 3)
    assert lengths.sum() == pytest.approx(3 * math.sqrt(3) * 2)
    assert lengths.sum() < 4 * math.sqrt(3) + 4


def all_triangulations(indices: tuple[int, ...]):
    """Every triangulation of the convex polygon `indices` (in order), as lists of triangles."""
    if len(indices) < 3:
        yield []
        return
    a, b = indices[0], indices[-1]
    for k in range(1, len(indices) - 1):
        for left in all_triangulations(indices[: k + 1]):
            for right in all_triangulations(indices[k:]):
                yield left + right + [(a, indices[k], b)]


def test_irregular_octagon_matches_every_triangulation_enumerated():
    # Eight points at uneven angles on an ellipse: the result's total is the least over all 132 (Catalan(6))
    # triangulations, which a fan from the first point is not.
    angles = np.radians([0, 20, 75, 130, 170, 200, 260, 320])
    octagon = np.column_stack([5 * np.cos(angles), 2 * np.sin(angles)])
    totals = [diagonal_lengths(octagon, np.array(t)).sum() for t in all_triangulations(tuple(range(8)))]
    assert len(totals) == 132
    triangles = triangulate(octagon)
    assert_triangulates(octagon, triangles)
    assert diagonal_lengths(octagon, triangles).sum() == pytest.approx(min(totals))
    fan = np.array([(0, k, k + 1) for k in range(1, 7)])
    assert diagonal_lengths(octagon, fan).sum() > min(totals) + 0.1


def test_triangles_are_wound_as_the_outline_is():
    # Each row is (a, k, b) with a < k < b: a clockwise outline gives clockwise triangles, the same rows.
    for outline in (SAMPLED_SQUARE, SLIVER, HEXAGON):
        clockwise = outline[::-1]
        triangles = triangulate(clockwise)
        assert np.all(np.diff(triangles, axis=1) > 0)
        assert np.all(signed_areas(clockwise, triangles) < 0)
        assert diagonal_lengths(clockwise, triangles).sum() == pytest.approx(
            diagonal_lengths(outline, triangulate(outline)).sum()
        )


def test_degenerate_input_gives_no_triangles():
    for points in ([], [(0, 0)], [(0, 0), (1, 0)], [(0, 0), (1, 0), (2, 0)], [(0, 0), (1, 0), (2, 0), (3, 0)]):
        result = triangulate(np.reshape(np.asarray(points, dtype=np.float64), (-1, 2)))
        assert result.shape == (0, 3) and result.dtype == np.int32
    # flat_area: the least doubled area a triangle may have
    almost_flat = [(0, 0), (1, 1e-7), (2, 0)]
    assert triangulate(almost_flat).tolist() == [[0, 1, 2]]
    assert triangulate(almost_flat, flat_area=1e-6).shape == (0, 3)
    with pytest.raises(TypeError):
        triangulate(np.zeros((4, 3)))
