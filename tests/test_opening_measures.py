"""An opening's width and height as a designer reads them (docs/entry_exit.md, "An opening's width and height as a
designer reads them"): the narrowest clear width through the wall, the opening on its own floor.

The pieces are those of ``benchmarks/opening_measures.py`` (rooms 8 x 6 m, metres, Y up), on both map-piece routes.
"""

from __future__ import annotations

import numpy as np
import pytest

from g2s_core.config import PRESETS_DIR, load_config
from g2s_core.model import Opening, RunContext
from g2s_plugins.graph_builders import sampling
from g2s_plugins.recast import RecastParams, build_navmesh
from g2s_plugins.samples import pieces
from g2s_plugins.samples.levels import SampleLevel
from g2s_plugins.terminals import entry_exit
from tests.conftest import benchmark

MEASURES = benchmark("opening_measures")
NAVMESH = load_config(PRESETS_DIR / "map_piece.yaml")
SAMPLING = load_config(PRESETS_DIR / "map_piece_sampling.yaml")


def _openings(level: SampleLevel, route: str) -> tuple[Opening, ...]:
    """The openings of ``level`` on the ``route`` ("navmesh" or "sampling") of the map-piece presets."""
    if route == "navmesh":
        mesh = level.mesh
        navmesh = build_navmesh(mesh.vertices, mesh.faces, NAVMESH.agent, RecastParams(**NAVMESH.graph.params))
        return entry_exit.detect_openings(mesh, navmesh, NAVMESH.agent).openings
    ctx = RunContext(mesh=level.mesh, agent=SAMPLING.agent, centre=np.asarray(level.mesh.bounds).mean(axis=0))
    graph = sampling.g2s_build_graph(mesh=level.mesh, params=sampling.Params(**SAMPLING.graph.params), context=ctx)
    return entry_exit.g2s_select_terminals(graph=graph, params=entry_exit.Params(), context=ctx).openings


def _the_east_one(level: SampleLevel, route: str) -> tuple[Opening, Opening]:
    """(found, known): the opening found within the match distance of ``level``'s second known one, and that one."""
    known = level.openings[1]
    found = [o for o in _openings(level, route)
             if np.linalg.norm(np.subtract(o.position, known.position)) <= pieces.MATCH_DISTANCE]
    assert len(found) == 1
    return found[0], known


@pytest.mark.parametrize(("route", "yaw"), [("navmesh", 0.0), ("navmesh", 45.0), ("sampling", 0.0)])
def test_a_reveal_splaying_out_to_the_face_is_as_wide_as_its_inner_face(route: str, yaw: float) -> None:
    # 1.2 m at the inner face of a wall 1 m thick, 2.2 m at the outer: read where the samples stand, 0.4-0.9 m in,
    # it measured 1.40 and 1.80 m on the navmesh at 0 and 45 degrees and 1.25 m on the sampling route. Since the
    # sampling builder's passage rule the sampled reveal is found 16 times, each read to the inner face, and the
    # union of their ends, each moved onto a jamb 1 m in along its line up to 1.4 degrees off the wall's, read
    # 1.234 m: a part stretches it by its floor's ends alone.
    found, known = _the_east_one(pieces.turned(MEASURES.splayed_reveal_door(), yaw), route)
    assert found.width == pytest.approx(known.width, abs=0.02)


def test_a_doorway_through_a_thick_wall_keeps_its_width_where_the_floor_steps_up_through_it() -> None:
    # Read on past the samples, rays at the opening's height would graze the treads rising through the wall and run in
    # the solid under the room's floor 0.6 m up (a passage 1.6 m wide read 0.88-1.28 m): they stand on the floor, and
    # stop where it rises past the climb.
    for route in ("navmesh", "sampling"):
        found, known = _the_east_one(pieces.turned(MEASURES.stepped_wall_passage(), 22.0), route)
        assert found.width == pytest.approx(known.width, abs=0.05)


@pytest.mark.parametrize("case", ["sunken_doorway_steps", "raised_doorway_steps"])
@pytest.mark.parametrize("route", ["navmesh", "sampling"])
def test_a_doorway_steps_down_or_up_lies_on_its_own_floor(case: str, route: str) -> None:
    # Samples on the two treads before the doorway carried the line between them: -0.37 and -0.30 m for a floor at
    # -0.45 m, +0.37 and +0.41 m for one at +0.45 m.
    found, known = _the_east_one(MEASURES.CASES[case](), route)
    assert found.position[1] == pytest.approx(known.position[1], abs=0.005)
    assert found.p0[1] == pytest.approx(known.position[1], abs=0.005)
    assert found.p1[1] == pytest.approx(known.position[1], abs=0.005)


def test_the_passage_comes_out_of_the_wall_where_its_sides_open_out() -> None:
    s = entry_exit._settings(entry_exit.Params(), NAVMESH.agent)  # a search step of 0.05 m
    free = np.array([1.25, 1.30, 1.31, 5.0, np.inf, 1.2])
    narrowest = np.array([1.25, 1.25, 1.25, 1.2, 1.2, np.inf])
    assert entry_exit._through_the_wall(free, narrowest, s).tolist() == [False, False, True, True, True, False]


def test_an_open_side_between_posts_reads_its_posts_as_its_ends() -> None:
    # Twenty-fifth round's pavilion on four corner posts 0.25 m square, turned 22 degrees, on the sampling route: its
    # north side is found as a few parts, one of them with its end on a post, read 0.05-0.23 m in from the floor's
    # edge. Its line runs as near the wall's as its floor's end does, and the union of the parts reads 5.48 m for the
    # 5.5 between the posts; taken for a splayed reveal's jamb, read 1 m in (whose transport to the face along its
    # part's line, a degree or two off the wall's, reads up to 0.026 m past it), the post was no end: 5.22 m.
    level = pieces.turned(benchmark("piece_kinds25").pavilion_four_posts(), 22.0)
    found = _openings(level, "sampling")
    for known in level.openings:
        near = [o for o in found if np.linalg.norm(np.subtract(o.position, known.position)) <= pieces.MATCH_DISTANCE]
        assert len(near) == 1 and near[0].width == pytest.approx(known.width, abs=0.05)
