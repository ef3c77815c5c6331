"""Openings behind a gap the agent steps over, on both map-piece routes (``_over_step_gap`` in
``g2s_plugins/terminals/entry_exit.py``; docs/entry_exit.md, "Openings behind a gap the agent steps over").

A gutter or cut 0.15-0.39 m wide and deeper than the climb just inside a doorway ended the floor's end search at its
near lip, so the doorway beyond was lost, where the agent steps over a gap narrower than its step gap (the climb).
Two rules that saw ground past the gap everywhere lost known doorways elsewhere: these also hold two of them.
"""

from __future__ import annotations

import numpy as np
import pytest

from g2s_core.config import PRESETS_DIR, load_config
from g2s_core.mesh import generate_level
from g2s_core.model import RunContext
from g2s_plugins._raycasting import RayCaster
from g2s_plugins.graph_builders import sampling
from g2s_plugins.samples import pieces
from g2s_plugins.terminals import entry_exit
from tests.conftest import benchmark, piece_openings

PRESETS = ["map_piece", "map_piece_sampling"]


def _score(level, openings: list) -> tuple[int, int, int, int]:
    recalled, missed, correct, other, _ = benchmark("piece_kinds10").score(level, openings, one_to_one=True)
    return recalled, missed, correct, other


@pytest.mark.parametrize("preset", PRESETS)
@pytest.mark.parametrize("width", [0.2, 0.35])
def test_a_doorway_behind_a_deep_gutter_the_agent_steps_over_is_an_opening(preset: str, width: float) -> None:
    # the gutter 1.0 m deep, its bottom beyond the 0.4 m climb, against the east wall's inner face
    level = benchmark("piece_kinds35").gutter_inside_doorway(width=width, depth=1.0)
    openings = piece_openings(level, preset)
    assert _score(level, openings) == (2, 0, 2, 0)
    assert sorted(round(o.width, 1) for o in openings) == [1.6, 1.6]


@pytest.mark.parametrize("preset", PRESETS)
@pytest.mark.parametrize("sill", [-0.02, -0.2, -0.35, 0.2])
def test_a_doorway_behind_a_gutter_is_found_with_its_floor_a_little_lower_or_higher(preset: str, sill: float) -> None:
    # the doorway's floor beyond the gutter lower than the room's within the climb: the rays a sixteenth of a step
    # under the room's floor pass over its lip, so the step gap asks again just under the floor the way's probes
    # found beyond it (lost on both routes before: review56 MED 3)
    level = benchmark("piece_kinds35").gutter_inside_doorway(width=0.3, depth=1.0, sill=sill)
    openings = piece_openings(level, preset)
    east = [o for o in openings if abs(o.position[0] - 8.3) < 0.2 and abs(o.position[2] - 3.0) < 0.2]
    assert len(openings) == 2 and len(east) == 1 and abs(east[0].width - 1.6) < 0.1, openings


def _slab_gutter(width: float, sill: float):
    """The gutter room with every floor a slab 0.2 m thick over nothing: the gutter a slot through it, the doorway's
    floor beyond it a slab whose top lies ``sill`` m over the room's."""
    kinds = benchmark("piece_kinds35")
    g0 = 8.0 - width
    parts = kinds.room(8.0, 6.0, kinds.ROOM_DOORS)[1:] + [
        kinds.box(-0.3, g0, -kinds.SLAB, 0.0, -0.3, 6.3), kinds.box(g0, 8.3, -kinds.SLAB, 0.0, -0.3, 2.0),
        kinds.box(g0, 8.3, -kinds.SLAB, 0.0, 4.0, 6.3), kinds.box(8.0, 8.3, sill - kinds.SLAB, sill, 2.0, 4.0)]
    return kinds._level("slab_gutter", parts, kinds.ROOM_OPENINGS)


@pytest.mark.parametrize("preset", PRESETS)
@pytest.mark.parametrize("sill", [-0.1, 0.2])
def test_a_doorway_behind_a_slot_between_slabs_is_found(preset: str, sill: float) -> None:
    # a slab's lip lies within its 0.2 m thickness of its top: rays just under the room's floor pass under one 0.2 m
    # higher and over one 0.1 m lower (the doorway lost on both routes at 0 degrees before); a fixed lower pass at
    # the climb's depth would pass under both slabs
    level = _slab_gutter(0.2, sill)
    assert _score(level, piece_openings(level, preset)) == (2, 0, 2, 0)


@pytest.mark.parametrize(("script", "kind", "yaw"), [
    ("piece_kinds11", "side_stair_door", 22.0), ("piece_kinds34", "footbridge_stair_ends", 45.0)])
def test_a_stairs_treads_beside_a_floors_end_are_no_far_floor(script: str, kind: str, yaw: float) -> None:
    # rays cast again at the climb's depth wherever the first found no gap (7cbb0a0, taken back) started inside the
    # stairs' bodies under their treads and found one more opening here (2 here at 45 degrees)
    level = pieces.turned(getattr(benchmark(script), kind)(), yaw)
    assert _score(level, piece_openings(level, "map_piece_sampling")) == (2, 0, 2, 0)


def test_rays_inside_a_stairs_body_meet_no_gap() -> None:
    # side_stair_door's third tread from the landing (z 2.2-2.5, its top 0.2 m, its body down to 0): a probe 1.0 m
    # up over it, the way down the flight (-z); rays 0.997 m down run inside the tread and leave it through its two
    # ends, 0.3 m apart, faces turned away from each other: no gap's sides (7cbb0a0 read them as one)
    agent = load_config(PRESETS_DIR / "map_piece_sampling.yaml").agent
    s = entry_exit._settings(entry_exit.Params(), agent)
    caster = RayCaster(benchmark("piece_kinds11").side_stair_door().mesh)
    probe, way, down = np.array([[9.12, 1.0, 2.49]]), np.array([[0.0, 0.0, -1.0]]), np.array([[0.0, -1.0, 0.0]])
    inside = np.array([1.0 - s.delta / 8.0])  # the rays' depth, less the sixteenth of a step they run under it
    gap = dict(width=s.step_gap, facing=True, strip=2.0 * s.delta)
    assert not entry_exit._narrow_gap_along(caster, probe, way, down, inside, s, **gap)[0].any()
    # a control: the gutter's air, 0.1 m inside its near lip, the rays just under the room's floor
    room = RayCaster(benchmark("piece_kinds35").gutter_inside_doorway(width=0.3, depth=1.0).mesh)
    over = entry_exit._narrow_gap_along(room, np.array([[7.8, s.lift, 3.0]]), np.array([[1.0, 0.0, 0.0]]), down,
                                        np.array([s.lift]), s, **gap)[0]
    assert over.all()


@pytest.mark.parametrize("preset", PRESETS)
def test_a_doorway_behind_a_cut_is_reached_past_the_search_reach(preset: str) -> None:
    # a cut 0.35 m wide, 0.1 m inside the east wall: the doorway's outer face lies 1.27 m past the navmesh's
    # boundary, beyond the 1.2 m reach, which the probes over the cut add to
    level = benchmark("cut_doorways").cut_doorway(0.35)
    openings = piece_openings(level, preset)
    assert _score(level, openings) == (2, 0, 2, 0)
    assert sorted(round(o.width, 1) for o in openings) == [1.6, 1.6]


def test_without_a_step_gap_the_gutter_ends_the_floor() -> None:
    # terminals.params.step_gap 0: gaps narrower than two search steps alone, as before the rule
    level = benchmark("piece_kinds35").gutter_inside_doorway(width=0.35, depth=1.0)
    agent = load_config("configs/map_piece_sampling.yaml").agent
    ctx = RunContext(mesh=level.mesh, agent=agent, centre=np.asarray(level.mesh.bounds).mean(axis=0))
    graph = sampling.g2s_build_graph(mesh=level.mesh, params=sampling.Params(), context=ctx)
    for step_gap, known in ((0.0, 1), (None, 2)):
        terminals = entry_exit.g2s_select_terminals(graph=graph.copy(), params=entry_exit.Params(step_gap=step_gap),
                                                    context=ctx)
        assert _score(level, list(terminals.openings)) == (known, 2 - known, known, 0)


@pytest.mark.parametrize(("script", "kind", "yaw"), [
    ("piece_kinds12", "cave_mouth", 22.0),  # its floor's end on sloped slivers at the mouth's corners
    ("piece_kinds17", "ramped_wall_passage", 0.0),  # a ramp up to the end: probes along its tilted normal
    ("piece_kinds28", "twin_doors_store_room", 22.0),  # the store room's wall square to the door's floor end
    ("piece_kinds32", "l_room_inner_corner_door", 0.0),
])
def test_a_floors_real_end_is_no_gap(script: str, kind: str, yaw: float) -> None:
    # the builder's own test in the search (eight axes straight down) put these ends up to a search step past the
    # floor and lost the opening on the sampling route; the rule's sides must face each other along the way
    level = getattr(benchmark(script), kind)()
    level = pieces.turned(level, yaw) if yaw else level
    known = len(level.openings)
    assert _score(level, piece_openings(level, "map_piece_sampling")) == (known, 0, known, 0)


@pytest.mark.parametrize("preset", PRESETS)
@pytest.mark.parametrize("yaw", [0.0, 45.0])
def test_a_slot_wider_than_the_step_gap_is_no_opening(preset: str, yaw: float) -> None:
    # a cut 0.45 m wide, over the 0.4 m step gap, 0.1 m inside the east wall: the room's floor goes on beyond it,
    # so its near lip (5.3-6.0 m along it before the rule) is no way out; the east doorway lies beyond a slot the
    # agent does not cross, and the west doorway is left
    level = benchmark("cut_doorways").cut_doorway(0.45)
    level = pieces.turned(level, yaw) if yaw else level
    assert [round(o.width, 1) for o in piece_openings(level, preset)] == [1.6]


@pytest.mark.parametrize("gap", [0.2, 0.35])
def test_a_cuts_lip_beside_the_found_doorway_is_no_opening(gap: float) -> None:
    # on the sampling route at 22 degrees the cut's lip beside the east doorway read as a third opening (1.58 m at
    # g 0.2, 2.60 m at 0.35) where a way along the lip slanted past the doorway's jamb
    level = pieces.turned(benchmark("cut_doorways").cut_doorway(gap), 22.0)
    openings = piece_openings(level, "map_piece_sampling")
    assert _score(level, openings) == (2, 0, 2, 0)
    assert sorted(round(o.width, 1) for o in openings) == [1.6, 1.6]


# Where the floor's end search found the sample terrain's west border end on the sampling route (x, y, z, m: 0.03-0.06
# m inside it) and the ways taken there, 5-45 degrees off straight out (read from a run of map_piece_sampling on
# sample:terrain). Looking back from past the border just under the ground meets the terrain's own sloping top, no
# side: square to it runs out over the ground the way started from, or along the border over it, and the probes find
# the terrain itself with no gap before it. Read as floor beyond, these ways were dropped mid-border and the border,
# one 24.34 m opening, read as two (21.63 and 5.12 m).
TERRAIN_BORDER_ENDS = [
    ((0.0593, -9.7854, 6.3452), (-0.95295, 0.29193, 0.08163)),  # out over the terrain's top, then nothing
    ((0.0551, -9.1583, 2.3689), (-0.93976, 0.19327, 0.28197)),
    ((0.0599, -9.7023, 4.9758), (-0.78886, 0.19410, 0.58312)),
    ((0.0295, -7.2298, 16.1356), (-0.90332, -0.03727, -0.42735)),  # along the border, over the terrain
    ((0.0294, -7.2321, 16.1305), (-0.71232, -0.18479, -0.67709)),
]


def test_the_terrain_met_at_its_border_is_no_floor_beyond() -> None:
    config = load_config(PRESETS_DIR / "map_piece_sampling.yaml")
    s = entry_exit._settings(entry_exit.Params(), config.agent)
    ends, ways = (np.array(v, dtype=np.float64) for v in zip(*TERRAIN_BORDER_ENDS))
    caster = RayCaster(generate_level("sample:terrain", config.mesh))
    assert not entry_exit._floor_beyond(ends, ways, caster, s).any()
    # the cut room's slot 0.45 m wide (x 7.45-7.9, its floor's top at 0): ways from its near lip straight out and 60
    # degrees along it have the room's floor beyond, a gap first
    room = RayCaster(benchmark("cut_doorways").cut_doorway(0.45).mesh)
    lip = np.array([[7.44, s.lift, 3.0]] * 2)
    across = np.array([[1.0, 0.0, 0.0], [0.5, 0.0, 0.866]])
    assert entry_exit._floor_beyond(lip, across, room, s).all()
