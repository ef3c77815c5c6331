"""``benchmarks/shallow_dead_ends.py``'s plan width of a polygon (where the agent's centre can stand), by hand: the
least distance between two parallel lines holding it."""

from __future__ import annotations

import numpy as np
import pytest

from tests.conftest import benchmark

shallow_dead_ends = benchmark("shallow_dead_ends")


def test_plan_width_is_the_least_distance_between_parallel_lines_holding_the_polygon():
    # a strip 2 m long and 0.5 m wide, either way round and with a repeated corner: 0.5 m
    strip = np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 0.5], [0.0, 0.5]])
    assert shallow_dead_ends.plan_width(strip) == pytest.approx(0.5)
    assert shallow_dead_ends.plan_width(strip[::-1]) == pytest.approx(0.5)
    assert shallow_dead_ends.plan_width(np.insert(strip, 1, strip[0], axis=0)) == pytest.approx(0.5)
    # a right triangle with legs 3 and 4 m: its height onto the 5 m side, 12 / 5 = 2.4 m (less than either leg)
    assert shallow_dead_ends.plan_width(np.array([[0.0, 0.0], [3.0, 0.0], [0.0, 4.0]])) == pytest.approx(2.4)
    # the same strip turned by 30 degrees: 0.5 m still
    turn = np.radians(30.0)
    rotation = np.array([[np.cos(turn), -np.sin(turn)], [np.sin(turn), np.cos(turn)]])
    assert shallow_dead_ends.plan_width(strip @ rotation.T) == pytest.approx(0.5)
    # a degenerate polygon of one point has no edge: 0
    assert shallow_dead_ends.plan_width(np.zeros((1, 2))) == 0.0
