"""The one rule for ties between computed values (scores, distances, centralities).

Values are compared after rounding to :data:`TIE_DIGITS` significant digits,
so that values equal but for floating-point noise (e.g. Brandes betweenness
of symmetric nodes, distances summed in another order) count as ties, which
the caller then breaks by a stated rule (usually the lower node id).
"""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np

TIE_DIGITS = 12
"""Significant digits kept when comparing values."""


def tie_value(value: float) -> float:
    """``value`` rounded to :data:`TIE_DIGITS` significant digits (decimal; zeros and non-finite values kept)."""
    return float(f"{float(value):.{TIE_DIGITS}g}")


def tie_values(values: Iterable[float]) -> np.ndarray:
    """:func:`tie_value` of each of ``values``: (n,) float64."""
    return np.array([tie_value(v) for v in np.asarray(values, dtype=np.float64).reshape(-1)], dtype=np.float64)


def rank_key(node: int, value: float) -> tuple[float, int]:
    """Sort key that ranks higher ``value`` first and breaks (rounded) ties by lower node id."""
    return (-tie_value(value), node)
