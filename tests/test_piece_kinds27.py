"""Two of the twenty-seventh round's pieces (``benchmarks/piece_kinds27.py``) on the ``map_piece`` preset.

A gate closed by a portcullis raised to 1.2 m (no way for the 2 m agent) beside an open postern 1.0 m wide: the postern
is an opening, the gate none. Two storeys joined by a floor hatch and a ladder, each with a door of its own: both doors
are openings, the upper one 3 m up, the hatch none; on the sampling route too, where the hatch's lid 0.95 m in front of
the upper door's wall breaks the sampled surface into pieces whose seams the storey rule's share no longer counts
(docs/entry_exit.md, "A twenty-seventh round of piece kinds").
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

from g2s_core import pipeline
from g2s_core.config import PRESETS_DIR, load_config
from g2s_core.mesh import mesh_sha256
from g2s_core.registry import Registry
from g2s_plugins.terminals.entry_exit import _seams
from tests.conftest import benchmark


def _found_one_to_one(kind: str, preset: str = "map_piece") -> list:
    """The openings ``preset`` finds on the round's ``kind`` at 0 degrees, checked to be its two known ones, one each,
    nothing else, within 0.05 m of their widths."""
    level = getattr(benchmark("piece_kinds27"), kind)()
    registry = Registry.from_entry_points()
    plan = pipeline.plan(load_config(PRESETS_DIR / f"{preset}.yaml"), registry)
    openings = list(pipeline.run(plan, registry, level.mesh, level.name, mesh_sha256(level.mesh)).terminals.openings)
    recalled, missed, correct, other, width_error = benchmark("piece_kinds10").score(level, openings, one_to_one=True)
    assert (recalled, missed, correct, other) == (2, 0, 2, 0)
    assert width_error < 0.05
    return openings


def test_a_half_raised_portcullis_is_no_way_and_the_postern_beside_it_is_one() -> None:
    openings = _found_one_to_one("portcullis_beside_postern")
    gate = np.array([8.3, 0.0, 2.0])  # the gate's middle at the wall's outer face
    assert min(np.linalg.norm(np.asarray(o.position) - gate) for o in openings) > 1.0


def test_an_upper_storey_reached_by_a_ladder_keeps_its_door_and_the_hatch_is_none() -> None:
    upper = max(_found_one_to_one("two_storey_hatch_ladder"), key=lambda o: o.position[1])
    assert abs(upper.position[1] - 3.0) < 0.01 and abs(upper.position[0] - 8.3) < 0.05  # at the upper door's outer face


def test_the_upper_storey_s_door_is_kept_on_the_sampling_route_across_the_seams_before_it() -> None:
    openings = _found_one_to_one("two_storey_hatch_ladder", "map_piece_sampling")  # the upper door was missed
    assert max(o.position[1] for o in openings) == 3.0


def test_seams_are_boundaries_facing_each_other_across_less_than_the_radius() -> None:
    """Samples along x (walkable side on the tangent's left, outward ``tangent x normal``): a stretch at z 0 facing +z
    and one at z 0.2 facing -z (a seam 0.2 m wide), one at z 2 facing +z and one at z 2.6 facing -z (0.6 m apart, over
    the 0.4 m radius), and the two sides of a single file at z 5, the second's samples 0.05 m along and a rounding
    (1e-9 m) over (opposite outward directions: each lies ahead of the other by the rounding alone, no seam)."""
    x = np.arange(0.0, 1.0, 0.1)
    rows = [(0.0, 0.0, 1.0), (0.0, 0.2, -1.0), (0.0, 2.0, 1.0), (0.0, 2.6, -1.0), (0.0, 5.0, 1.0),
            (0.05, 5.0 + 1e-9, -1.0)]  # (along x, z, the tangent's x)
    position = np.array([[xi + along, 0.0, z] for along, z, _ in rows for xi in x])
    tangent = np.array([[t, 0.0, 0.0] for _, _, t in rows for _ in x])
    normal = np.tile([0.0, 1.0, 0.0], (len(position), 1))
    seam = _seams(SimpleNamespace(position=position), SimpleNamespace(tangent=tangent, normal=normal),
                  SimpleNamespace(radius=0.4, climb=0.4))
    assert seam.reshape(len(rows), -1).any(axis=1).tolist() == [True, True, False, False, False, False]
    assert seam.reshape(len(rows), -1)[:2].all()
