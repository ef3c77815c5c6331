"""A level in centimetres read as metres is warned about; the same level in metres is not.

The rule and its threshold come from ``benchmarks/units_check.py`` (docs/errors.md, "Units and scale").
"""

from __future__ import annotations

import numpy as np
import pytest
import trimesh

import g2s_core
from g2s_plugins.units_check import MAX_STOREY_HEIGHTS, storey_gap


def box(low: tuple[float, float, float], high: tuple[float, float, float]) -> trimesh.Trimesh:
    """A closed box between two corners, metres."""
    low_, high_ = np.asarray(low, dtype=float), np.asarray(high, dtype=float)
    return trimesh.creation.box(extents=high_ - low_, transform=trimesh.transformations.translation_matrix((low_ + high_) / 2))


def stair_room(side: float, steps: int, scale: float = 1.0) -> trimesh.Trimesh:
    """A room ``side`` m square: a floor slab 0.2 m thick, walls 0.2 m thick and 2.5 m tall, and a flight of
    ``steps`` steps 0.2 m tall and 0.3 m deep, 1 m wide, rising along x to the wall; read from units ``scale``
    times smaller than metres (100: centimetres)."""
    parts = [box((0, -0.2, 0), (side, 0, side)), box((0, 0, 0), (side, 2.5, 0.2)), box((0, 0, side - 0.2), (side, 2.5, side)),
             box((0, 0, 0), (0.2, 2.5, side)), box((side - 0.2, 0, 0), (side, 2.5, side))]
    parts += [box((side - 0.2 - 0.3 * (steps - k), 0, 1), (side - 0.2, 0.2 * (k + 1), 2)) for k in range(steps)]
    mesh = trimesh.util.concatenate(parts)
    mesh.apply_scale(scale)
    return mesh


def test_the_gap_of_a_room_with_a_flight_is_its_walls_height():
    """Hand-checked: the level faces of ``stair_room(20, 5)`` are the boxes' tops, at 0 (the floor slab, 400 m²),
    0.2, 0.4, 0.6, 0.8 and 1.0 (the steps, 1.5, 1.2, 0.9, 0.6 and 0.3 m²) and 2.5 (the walls, 16 m²). Each gap
    weighs the smaller surface it parts: the five gaps of 0.2 m weigh 1.5 + 1.2 + 0.9 + 0.6 + 0.3 = 4.5, the
    walls' 1.5 m over the top step 0.3, so the upper quartile of 4.8 is 0.2 m. Without the flight the only gap is
    the walls' 2.5 m. Read from centimetres both are 100 times larger; a slab alone (one flat height) cannot be
    told at any size."""
    assert storey_gap(stair_room(20.0, 5)) == pytest.approx(0.2)
    assert storey_gap(stair_room(20.0, 5, scale=100.0)) == pytest.approx(20.0)
    assert storey_gap(stair_room(20.0, 0)) == pytest.approx(2.5)
    assert storey_gap(stair_room(20.0, 0, scale=100.0)) == pytest.approx(250.0)
    assert storey_gap(box((0, -0.2, 0), (2000, 0, 2000))) is None


COARSE = {"navmesh": "cell_size", "sampling": "spacing"}
"""The parameter that sets how finely each graph builder reads the level, metres."""


@pytest.mark.parametrize("builder", ["navmesh", "sampling"])
@pytest.mark.parametrize("scale, warned", [(1.0, False), (100.0, True)])
def test_a_small_level_in_centimetres_warns_naming_the_file_and_the_scale(tmp_path, builder, scale, warned):
    """A 4 m room with three steps, written in metres and in centimetres, through each graph builder (navmesh cells
    of 2.5 m, samples every 20 m, in the 400 m room the centimetres make, so that it builds in a second): the
    centimetre file's steps stand 20 m apart, 10 agent heights (over :data:`MAX_STOREY_HEIGHTS`), and the run
    warns once, naming the file and ``mesh.scale: 0.01``; a result all the same (exit 0)."""
    path = tmp_path / f"room_{scale:g}.obj"
    stair_room(4.0, 3, scale=scale).export(path)
    params = {} if scale == 1 else {COARSE[builder]: 2.5 if builder == "navmesh" else 20.0}
    result = g2s_core.run(path, "graph_only", graph={"plugin": builder, "params": params})
    told = [warning for warning in result.warnings if "mesh.scale: 0.01" in warning]
    assert result.graph.number_of_nodes() > 0
    assert len(told) == warned
    if warned:
        assert told[0].startswith(f"mesh: {path.name}: ") and "20 m" in told[0]
        assert f"{20 / 2:.0f} times the agent's height" in told[0] and 20 / 2 > MAX_STOREY_HEIGHTS


def test_a_level_of_one_repeated_module_is_read_past_its_period(monkeypatch):
    """A town of 100 box houses 3 m tall on a slab: each house's 12 faces repeat, its roof at places 7 and 9 of
    each twelve (trimesh's box, as the slab's top), so reading every 2nd face would read no level face at all; the
    seeded random choice of faces reads roofs and finds the houses' 3 m (300 m from centimetres)."""
    monkeypatch.setattr("g2s_plugins.units_check.SAMPLED_FACES", 606)
    houses = [box((8 * (k % 10), 0, 8 * (k // 10)), (8 * (k % 10) + 4, 3, 8 * (k // 10) + 4)) for k in range(100)]
    town = trimesh.util.concatenate([box((0, -0.2, 0), (80, 0, 80)), *houses])
    assert len(town.faces) == 1212
    assert storey_gap(town) == pytest.approx(3.0)
    town.apply_scale(100)
    assert storey_gap(town) == pytest.approx(300.0)


def test_a_level_whose_only_low_level_faces_are_slivers_cannot_be_told():
    """A cave's rock top (100 m² at 16 m) over sloping ground whose only level faces are two slivers of 0.09 m² (at 0
    and -4 m), as round 34's scree cave of seed 1 has: the gaps part 0.18 m² of level surface, under
    :data:`~g2s_plugins.units_check.MIN_PARTED_AREA`, so the level cannot be told (read as before, the gaps of 4 and
    16 m weigh the same and the quartile reads 16 m, 8 agent heights: a false warning of centimetres). Read from
    centimetres the slivers hold 900 m² each and the 1,600 m gap is told."""
    cave = trimesh.util.concatenate([box((0, 15, 0), (10, 16, 10)), box((20, -1, 0), (20.3, 0, 0.3)),
                                     box((30, -5, 0), (30.3, -4, 0.3))])
    assert storey_gap(cave) is None
    assert storey_gap(cave, min_parted_area=0.0) == pytest.approx(16.0)
    cave.apply_scale(100)
    assert storey_gap(cave) == pytest.approx(1600.0)
