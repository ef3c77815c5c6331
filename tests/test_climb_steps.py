"""Steps a little over and under the agent's climb on the navmesh route (docs/navmesh.md, "The climb at every
alignment"): generated steps of ``benchmarks/climb_steps.py``, the presets' agent (climb 0.4 m) and grids."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh

from g2s_core.config import PRESETS_DIR, load_config
from g2s_plugins.recast import RecastParams, SettingsError, build_navmesh, resolve_settings, voxel_config
from g2s_plugins.recast.settings import MAX_SPAN_HEIGHT, climb_cell_height, coarse_climb_warning
from tests.conftest import benchmark

climb_steps = benchmark("climb_steps")
head_room = benchmark("head_room")

LIFTS = (0.0, 0.02, 0.0625, 0.1)


def climbs(preset: str, kind: str, h: float, lift: float, **params) -> bool:
    """Whether the navmesh of ``preset`` (its graph's ``params`` overridden) joins the lower and upper floors of
    ``kind`` with steps of ``h`` m, its lower floor ``lift`` m over the slabs' underside."""
    config = load_config(PRESETS_DIR / f"{preset}.yaml")
    mesh, ends = climb_steps.case_mesh(kind, h, 0.0, lift)
    return head_room.navmesh_walks(mesh, ends, config.agent, RecastParams(**{**config.graph.params, **params}))


@pytest.mark.parametrize("lift", LIFTS)
def test_a_bench_seat_over_the_climb_is_not_climbed_at_any_alignment(lift):
    # 0.45 m on 0.125 m cells is 3.6-4.6 cells by where the floor lies; Recast's climb of floor(0.4 / 0.125) = 3
    # cells refused it only where the two floors rounded 4 cells apart: the canteen's tables over their benches
    assert not climbs("map_analysis", "step", 0.45, lift)
    assert not climbs("map_analysis", "table", 0.45, lift)


@pytest.mark.parametrize("lift", LIFTS)
def test_a_step_up_to_the_climb_is_climbed_at_every_alignment(lift):
    # Recast's 3 cells refused 0.40 m where the floor lies 0.8 of a cell over a boundary (lift 0.1), and a flight of
    # 0.39 m risers there too (one of its three risers meets that alignment)
    assert climbs("map_analysis", "step", 0.38, lift)
    assert climbs("map_analysis", "step", 0.40, lift)
    assert climbs("map_analysis", "flight", 0.39, lift)
    assert climbs("map_piece", "step", 0.40, lift)  # 8 cells of 0.05 m: Recast's climb is exact there already


def test_the_paper_reading_stays_recasts():
    # `climb: recast` (map_analysis_paper, graph_only): 0.45 m climbed where the floors round 3 cells apart
    assert climbs("map_analysis", "step", 0.45, 0.0, climb="recast")
    assert not climbs("map_analysis", "step", 0.45, 0.1, climb="recast")


def test_the_climb_cell_divides_the_climb_in_single_precision():
    for climb in (0.1, 0.25, 0.3, 0.35, 0.4, 0.45, 0.5, 0.6, 0.75, 1.0):
        ch = climb_cell_height(climb, 2.0)
        config = voxel_config(resolve_settings(load_config(PRESETS_DIR / "map_analysis.yaml").agent,
                                               RecastParams(climb="agent", agent_max_climb=climb)))
        assert ch <= 0.025 + 1e-9 and float(config["ch"]) == pytest.approx(ch)
        assert int(config["walkableClimb"]) * ch == pytest.approx(climb, abs=1e-6)


def test_a_tall_level_or_agent_gets_coarser_climb_cells():
    # 1000 m of level in at most 8189 cells: 0.4 / 3 m; an agent of 10 m and its climb in at most 254 cells: 0.4 / 9 m
    assert climb_cell_height(0.4, 2.0, 1000.0) == pytest.approx(0.4 / 3)
    assert climb_cell_height(0.4, 10.0) == pytest.approx(0.4 / 9)
    tall_climb = climb_cell_height(7.0, 2.0)  # a climb over 255 cells of 0.025 m: coarser cells, the climb whole
    assert (7.0 + 2.0) / tall_climb <= 254 + 1e-3 and 7.0 / tall_climb == pytest.approx(round(7.0 / tall_climb))


@pytest.mark.parametrize("height", [2.0, 6.1, 6.2, 10.0])
def test_a_tall_agent_climbs_steps_under_open_sky(height):
    # Recast keeps a span's clearance in 8 bits (an open sky reads 255 cells) and links two spans only where the
    # agent's height fits over the higher: on cells chosen for the height alone a 6.1-10 m agent lost steps of
    # 0.19-0.39 m under the climb (review56 HIGH 1)
    agent = load_config(PRESETS_DIR / "map_analysis.yaml").agent.model_copy(update={"height": height})
    params = RecastParams(ledge_filter="drops", climb="agent")
    ground = climb_steps.box(-10.0, 10.0, -0.5, 0.0, -10.0, 10.0)
    for step, joined in ((0.30, True), (0.39, True), (0.50, False)):
        pad = climb_steps.box(0.0, 5.0, 0.0, step, 0.0, 5.0)
        mesh = trimesh.util.concatenate([ground, pad])
        ends = np.array([[-5.0, 0.0, -5.0], [2.5, step, 2.5]])
        assert head_room.navmesh_walks(mesh, ends, agent, params) == joined, (height, step)
    assert climb_cell_height(0.4, 2.0, 4000.0) is None  # Recast's reading, as a tall level always had
    assert climb_cell_height(0.0, 2.0) is None


@pytest.mark.parametrize("tall", [300.0, 5000.0])
def test_a_tall_level_builds_or_is_refused_in_one_line(tall):
    # a floor and a post `tall` m high: 0.025 m cells would need 12,000 and 200,000 of Recast's 8191; the first is
    # built on coarser climb cells, the second on none (Recast's own 0.125 m would need 40,000) and is refused
    mesh, _ = climb_steps.case_mesh("table", 0.3, 0.0, 0.0)
    post = climb_steps.box(5.0, 5.2, 0.0, tall, 5.0, 5.2)
    vertices = list(mesh.vertices) + list(post.vertices)
    faces = list(mesh.faces) + list(post.faces + len(mesh.vertices))
    config = load_config(PRESETS_DIR / "map_analysis.yaml")
    params = RecastParams(**config.graph.params)
    if tall < 1000:
        nav = build_navmesh(vertices, faces, config.agent, params)
        assert nav.settings["cell_height"] * MAX_SPAN_HEIGHT >= tall
        assert nav.settings["cell_height"] < 0.125
    else:
        with pytest.raises(SettingsError, match="^mesh: .* cells of 0.125 m tall"):
            build_navmesh(vertices, faces, config.agent, params)


@pytest.mark.parametrize("tall, agent_height, warned", [(0.0, 2.0, None), (300.0, 2.0, "level's 300.5 m"),
                                                        (0.0, 10.0, "agent's height and climb (10 + 0.4 m)")])
def test_coarser_climb_cells_are_named_in_a_warning(tall, agent_height, warned):
    # review56 LOW 5: a tall level or agent gets cells coarser than the climb band, so a step a little over the climb
    # may be climbed again; the run says so, with the cell height and its cause
    from g2s_core.model import RunContext
    from g2s_plugins.graph_builders import navmesh as builder

    mesh, _ = climb_steps.case_mesh("table", 0.3, 0.0, 0.0)
    if tall:
        mesh = trimesh.util.concatenate([mesh, climb_steps.box(5.0, 5.2, 0.0, tall, 5.0, 5.2)])
    config = load_config(PRESETS_DIR / "map_analysis.yaml")
    agent = config.agent.model_copy(update={"height": agent_height})
    context = RunContext(mesh=mesh, agent=agent, centre=np.asarray(mesh.bounds.mean(axis=0)))
    builder.g2s_build_graph(mesh=mesh, params=builder.Params(**config.graph.params), context=context)
    coarse = [w for w in context.warnings if w.startswith("graph.params.climb: agent")]
    if warned is None:
        assert not coarse
    else:
        assert len(coarse) == 1 and warned in coarse[0] and "m over the agent's climb of 0.4 m" in coarse[0]


def test_the_warning_on_recasts_cells_names_the_band_round_the_climb():
    # review57 LOW 7: from about 820 m the cells are Recast's 0.125 m, of which the 0.4 m climb is no whole number
    # (3 cells, 0.375 m): a step under the climb may be refused too, so the warning names the band both sides of it
    config = load_config(PRESETS_DIR / "map_analysis.yaml")
    params = RecastParams(**config.graph.params)
    warned = coarse_climb_warning(resolve_settings(config.agent, params, 900.0), params, 900.0)
    assert warned is not None and "a step from 0.375 to 0.5 m (the agent's climb is 0.4 m) may be climbed or not" in (
        warned)
    exact = coarse_climb_warning(resolve_settings(config.agent, params, 300.0), params, 300.0)
    assert exact is not None and "a step up to 0.04 m over the agent's climb of 0.4 m may be climbed" in exact
