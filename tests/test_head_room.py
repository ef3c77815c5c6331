"""Head room a little over and under the agent's height on the navmesh route (docs/navmesh.md, "Head room under an
edge"): generated corridors of ``benchmarks/head_room.py``, the presets' agent (height 2 m) and grids."""

from __future__ import annotations

import pytest

from g2s_core.config import PRESETS_DIR, load_config
from g2s_plugins.recast import RecastParams
from tests.conftest import benchmark

head_room = benchmark("head_room")


def walks(preset: str, head: float, lift: float, **params) -> bool:
    """Whether the navmesh of ``preset`` (its graph's ``params`` overridden) joins the two ends of a flat corridor
    under ``head`` m of head room, its floor ``lift`` m over a multiple of the cell height."""
    config = load_config(PRESETS_DIR / f"{preset}.yaml")
    mesh, ends = head_room.case_mesh("corridor", head, 0.0, lift)
    return head_room.navmesh_walks(mesh, ends, config.agent, RecastParams(**{**config.graph.params, **params}))


@pytest.mark.parametrize("preset, lift", [("map_piece", 0.0), ("map_analysis", 0.1)])
def test_a_corridor_a_little_over_the_agent_holds_floor(preset, lift):
    # 2.05 m over the floor: 41 cells of 0.05 m (map_piece); 16.4 of 0.125 m (map_analysis), its floor 0.8 of a
    # cell over a multiple, so the gap Recast sees after rounding is 16 cells, the agent's height. Recast's own
    # filter needed 17 (a gap of more than the agent's height in cells) and dropped both corridors.
    assert walks(preset, 2.05, lift)


@pytest.mark.parametrize("preset", ["map_piece", "map_analysis"])
@pytest.mark.parametrize("lift", [0.0, 0.02, 0.0625, 0.1])
def test_a_corridor_under_the_agent_holds_none(preset, lift):
    assert not walks(preset, 1.9, lift)
    assert not walks(preset, 1.95, lift)


@pytest.mark.parametrize("preset, lift, grid", [("map_piece", 0.0, {}), ("map_analysis", 0.1, {"climb": "recast"})])
def test_recasts_own_filter_stays_for_the_paper_preset(preset, lift, grid):
    # `head_room: recast` (map_analysis_paper) keeps the filter as Recast ships it: a cell more than the agent, here
    # on the grid map_analysis had before its cells of 0.025 m (docs/navmesh.md, "The climb at every alignment")
    assert not walks(preset, 2.05, lift, head_room="recast", **grid)
    assert walks(preset, 2.3, lift, head_room="recast", **grid)
