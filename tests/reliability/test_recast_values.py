"""Agent, mesh and navmesh values the Recast build cannot honour (issue 11, items 2, 3 and 5; the
checks live in g2s_core.config and g2s_plugins.recast): exit 2 blaming the right key."""

from __future__ import annotations

import pytest

from tests.reliability.checks import CORRIDOR, assert_clean_error, run_g2s, tree


@pytest.mark.parametrize(
    "setting, blamed",
    [
        ("mesh: {scale: .inf}", "mesh.scale: expected a finite number"),
        ("mesh: {scale: 1.0e+308}", "mesh.scale: 1e+308"),
        ("agent: {height: .inf}", "agent.height: expected a finite number"),
        ("agent: {radius: 1.0e+12}", "agent.radius: "),
        ("graph: {plugin: navmesh, params: {cell_height: 1.0e-9}}", "graph.params.cell_height: "),
        ("graph: {plugin: navmesh, params: {region_min_size: 1.0e+6}}", "graph.params.region_min_size: "),
    ],
    ids=["scale-inf", "scale-huge", "height-inf", "radius-huge", "cell-height-tiny", "region-min-size-huge"],
)
def test_value_recast_cannot_honour_blames_its_key(setting, blamed, tmp_path, capsys):
    config = tmp_path / "c.yaml"
    config.write_text(f"extends: graph_only\n{setting}\n")
    out = tmp_path / "out"
    assert_clean_error(run_g2s(capsys, "run", config, CORRIDOR, "-o", out), blamed)
    assert tree(out) == []
