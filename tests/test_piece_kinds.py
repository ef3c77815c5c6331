"""The tenth and eleventh rounds' piece kinds (``benchmarks/piece_kinds10.py``, ``benchmarks/piece_kinds11.py``)
put each known opening where a floor ends.

Cheap checks of the generators only (no detector run; docs/entry_exit.md, "A tenth round of piece kinds" and "An
eleventh round of piece kinds", has the figures): 0.3 m inside every known opening something lies under it within
0.5 m of its height (its floor), and 0.1 m outside nothing does within 1 m (the floor ends there), at 0 and 22
degrees of yaw.
"""

from __future__ import annotations

import numpy as np
import pytest

from g2s_plugins._raycasting import UP, RayCaster
from g2s_plugins.samples import pieces
from tests.conftest import benchmark

KINDS = {name: factory for module in ("piece_kinds10", "piece_kinds11") for name, factory in benchmark(module).KINDS.items()}


@pytest.mark.parametrize("yaw", [0.0, 22.0])
@pytest.mark.parametrize("name", sorted(KINDS))
def test_each_known_opening_lies_where_its_floor_ends(name: str, yaw: float) -> None:
    level = KINDS[name]()
    level = pieces.turned(level, yaw) if yaw else level
    assert len(level.openings) in (1, 2, 3)
    position = np.array([o.position for o in level.openings], dtype=np.float64)
    heading = np.array([o.heading for o in level.openings], dtype=np.float64)
    caster = RayCaster(level.mesh)
    inside = caster.first_hits(position - 0.3 * heading + 0.3 * UP, -UP).distance
    outside = caster.first_hits(position + 0.1 * heading + 0.3 * UP, -UP).distance
    assert np.all(inside <= 0.5) and np.all(outside > 1.3)
