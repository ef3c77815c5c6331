"""Two of the twenty-seventh round's pieces (``benchmarks/piece_kinds27.py``) on the ``map_piece`` preset.

A gate closed by a portcullis raised to 1.2 m (no way for the 2 m agent) beside an open postern 1.0 m wide: the postern
is an opening, the gate none. Two storeys joined by a floor hatch and a ladder, each with a door of its own: both doors
are openings, the upper one 3 m up, the hatch none (docs/entry_exit.md, "A twenty-seventh round of piece kinds").
"""

from __future__ import annotations

import numpy as np

from g2s_core import pipeline
from g2s_core.config import PRESETS_DIR, load_config
from g2s_core.mesh import mesh_sha256
from g2s_core.registry import Registry
from tests.conftest import benchmark


def _openings(level) -> list:
    registry = Registry.from_entry_points()
    plan = pipeline.plan(load_config(PRESETS_DIR / "map_piece.yaml"), registry)
    return list(pipeline.run(plan, registry, level.mesh, level.name, mesh_sha256(level.mesh)).terminals.openings)


def test_a_half_raised_portcullis_is_no_way_and_the_postern_beside_it_is_one() -> None:
    level = benchmark("piece_kinds27").portcullis_beside_postern()
    openings = _openings(level)
    recalled, missed, correct, other, width_error = benchmark("piece_kinds10").score(level, openings, one_to_one=True)
    assert (recalled, missed, correct, other) == (2, 0, 2, 0)
    assert width_error < 0.05
    gate = np.array([8.3, 0.0, 2.0])  # the gate's middle at the wall's outer face
    assert min(np.linalg.norm(np.asarray(o.position) - gate) for o in openings) > 1.0


def test_an_upper_storey_reached_by_a_ladder_keeps_its_door_and_the_hatch_is_none() -> None:
    level = benchmark("piece_kinds27").two_storey_hatch_ladder()
    openings = _openings(level)
    recalled, missed, correct, other, width_error = benchmark("piece_kinds10").score(level, openings, one_to_one=True)
    assert (recalled, missed, correct, other) == (2, 0, 2, 0)
    assert width_error < 0.05
    upper = max(openings, key=lambda o: o.position[1])
    assert abs(upper.position[1] - 3.0) < 0.01 and abs(upper.position[0] - 8.3) < 0.05  # at the upper door's outer face
