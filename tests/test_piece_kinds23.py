"""The twenty-third round's stair tower (``benchmarks/piece_kinds23.py``) end to end on the ``map_piece`` preset.

Its doorways stand on three landings 0, 3 and 6 m up, joined by four flights round an open well: each is one opening
at its own landing's floor, as wide as the doorway (docs/entry_exit.md, "A twenty-third round of piece kinds": 1.17-
1.20 m of 1.2 on both routes at 0, 22 and 45 degrees), and nothing else is. Turned 22 degrees, off the axes Recast's
voxels follow.
"""

from __future__ import annotations

import numpy as np

from g2s_core import pipeline
from g2s_core.config import PRESETS_DIR, load_config
from g2s_core.mesh import mesh_sha256
from g2s_core.registry import Registry
from g2s_plugins.samples import pieces
from tests.conftest import benchmark


def test_a_stair_towers_three_landing_doorways_are_its_openings() -> None:
    level = pieces.turned(benchmark("piece_kinds23").stair_tower_three_landings(), 22.0)
    registry = Registry.from_entry_points()
    plan = pipeline.plan(load_config(PRESETS_DIR / "map_piece.yaml"), registry)
    result = pipeline.run(plan, registry, level.mesh, "stair_tower", mesh_sha256(level.mesh))
    found = sorted(result.terminals.openings, key=lambda o: o.position[1])
    assert len(found) == 3
    for opening, known in zip(found, sorted(level.openings, key=lambda o: o.position[1])):
        assert np.linalg.norm(np.subtract(opening.position, known.position)) < 0.1  # its landing's floor, its door
        assert abs(opening.width - known.width) < 0.05
        assert np.dot(opening.heading, known.heading) > 0.99
