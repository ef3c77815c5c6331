"""Column-wise conversion: the values of a column converted a group at a time (all of one type, one key set).

:mod:`g2s_plugins.outputs.json_text` writes, and
:mod:`g2s_plugins.outputs.structure_json` rounds, the values that sit at
the same place in many records together, so that Python works once per
group and C loops do the values; a column of mixed values (a float or
``None``, dicts of two key sets) is split by :func:`by_groups`.
"""

from __future__ import annotations

from collections.abc import Callable, Hashable, Sequence
from typing import Any

__all__ = ["by_groups"]


def by_groups(values: Sequence[Any], group: Callable[[Any], Hashable], convert: Callable[[Hashable, list], list]) -> list:
    """``convert(key, rows)`` of the rows of ``values`` that share ``group(row)``, put back in ``values``' order.

    ``convert`` returns one result per row it is given; a column of one
    group (the usual case) is converted whole, without being split.
    """
    keys = list(map(group, values))
    distinct = set(keys)
    if len(distinct) == 1:
        return convert(distinct.pop(), list(values))
    rows: dict[Hashable, list[int]] = {}
    for row, key in enumerate(keys):
        rows.setdefault(key, []).append(row)
    result: list[Any] = [None] * len(values)
    for key, indices in rows.items():
        for row, converted in zip(indices, convert(key, [values[i] for i in indices])):
            result[row] = converted
    return result
