"""A level read in the wrong frame or wound inside out is reported, never a silent meaningless result.

The rule and its thresholds come from ``benchmarks/frame_check.py`` (docs/errors.md).
"""

from __future__ import annotations

import networkx as nx
import numpy as np
import pytest
import trimesh

import g2s_core
from g2s_core.errors import G2SError
from g2s_core.mesh import Z_UP_TO_Y_UP, clean_mesh
from g2s_plugins.samples.levels import SAMPLES, load_sample
from g2s_plugins.samples.pieces import PIECES
from g2s_core.config import resolve_config
from g2s_plugins.walkable_check import (
    MAX_HEIGHT_RATIO,
    SMALL_MESH_FACES,
    SMALL_MESH_SHARE,
    height_ratio,
    hidden_floor_bodies,
    inside_out_bodies,
    looks_for_winding,
    looks_z_up,
    walkable_share,
    walks_upright,
)

BUILDERS = ["navmesh", "sampling"]


def as_z_up_file(mesh: trimesh.Trimesh) -> trimesh.Trimesh:
    """The level as a Z-up file holds it: read with the default ``mesh.up_axis: y``, it stands on its side."""
    return trimesh.Trimesh(np.asarray(mesh.vertices) @ Z_UP_TO_Y_UP, mesh.faces, process=False)


def inverted(mesh: trimesh.Trimesh) -> trimesh.Trimesh:
    return trimesh.Trimesh(mesh.vertices, np.asarray(mesh.faces)[:, ::-1], process=False)


def graph_run(level: trimesh.Trimesh, builder: str, /, **overrides) -> g2s_core.RunResult:
    """Step 1 of the map analysis preset of ``builder`` on ``level``; ``overrides`` as ``g2s_core.run`` takes them."""
    config = "map_analysis_sampling" if builder == "sampling" else "map_analysis"
    return g2s_core.run(level, config, stop_after="graph", **overrides)


def mesh_warnings(result) -> list[str]:
    return [w for w in result.warnings if w.startswith("mesh:")]


def slab(x0: float, x1: float, z0: float, z1: float, thickness: float) -> trimesh.Trimesh:
    """A closed, outward-facing floor slab over [x0, x1] x [z0, z1] m whose top is at y = 0."""
    return trimesh.creation.box(extents=(x1 - x0, thickness, z1 - z0)).apply_translation(
        ((x0 + x1) / 2, -thickness / 2, (z0 + z1) / 2))


PIECE_AGENT = {"radius": 0.4, "height": 2.0, "max_climb": 0.4, "max_slope": 60}


def hallway(shared_data) -> trimesh.Trimesh:
    return trimesh.load(shared_data / "pieces" / "Hallway.obj", force="mesh", process=False)


# --- the statistics on hand-checkable meshes -------------------------------------------


def test_height_ratio_and_share_of_a_slab():
    slab = trimesh.creation.box(extents=(10.0, 0.5, 4.0))
    assert height_ratio(slab) == pytest.approx(0.5 / 4.0)
    tower = trimesh.creation.box(extents=(2.0, 9.0, 3.0))
    assert height_ratio(tower) == pytest.approx(4.5)
    graph = nx.Graph()
    graph.add_nodes_from([(0, {"area": 3.0}), (1, {"area": 1.0})])
    assert walkable_share(graph, slab) == pytest.approx(4.0 / 40.0)


def test_a_z_up_dungeon_looks_z_up_and_the_dungeon_does_not():
    level = load_sample("dungeon", rooms=12).mesh
    assert not looks_z_up(level, 45.0)
    assert looks_z_up(as_z_up_file(level), 45.0)


def test_hidden_floor_bodies_tell_an_inside_out_slab_from_a_room_seen_from_inside():
    agent = resolve_config("map_piece")[0].agent  # 2 m tall
    thin, thick = inverted(slab(0, 4, 0, 4, 0.6)), inverted(slab(0, 4, 0, 4, 2.5))
    room = inverted(trimesh.creation.box(extents=(8.0, 3.0, 6.0)))  # its floor faces up into it, 3 m under its ceiling
    assert [inside_out_bodies(m) for m in (thin, thick, room)] == [1, 1, 1]
    # under 2 m of headroom the upturned underside hides a floor; a slab thicker than the agent is tall
    # looks like a room from inside, and is not counted
    assert [hidden_floor_bodies(m, agent) for m in (thin, thick, room)] == [1, 0, 0]
    assert hidden_floor_bodies(trimesh.util.concatenate([thin, room.apply_translation((10, 0, 0))]), agent) == 1


def test_only_small_meshes_are_looked_at_above_the_share_threshold():
    assert looks_for_winding(0.05, 10 * SMALL_MESH_FACES)
    assert looks_for_winding(SMALL_MESH_SHARE - 0.01, SMALL_MESH_FACES)
    assert not looks_for_winding(SMALL_MESH_SHARE - 0.01, SMALL_MESH_FACES + 1)
    assert not looks_for_winding(SMALL_MESH_SHARE, 12)


def test_inside_out_bodies_counts_closed_bodies_of_negative_volume():
    boxes = [trimesh.creation.box(extents=(1, 1, 1)).apply_translation((3.0 * i, 0, 0)) for i in range(3)]
    inside_out = trimesh.util.concatenate([boxes[0], inverted(boxes[1]), inverted(boxes[2])])
    assert inside_out_bodies(inside_out) == 2
    open_box = trimesh.Trimesh(boxes[0].vertices, boxes[0].faces[2:][:, ::-1])  # two triangles missing
    assert inside_out_bodies(open_box) == 0


# --- the warning, from both graph builders ----------------------------------------------


@pytest.mark.parametrize("builder", BUILDERS)
def test_a_z_up_level_read_as_y_up_warns_naming_the_up_axis(builder):
    result = graph_run(as_z_up_file(load_sample("cross_hub").mesh), builder)
    (warning,) = mesh_warnings(result)
    assert "times as tall as it is wide" in warning and "`mesh: {up_axis: z}`" in warning, warning
    again = graph_run(as_z_up_file(load_sample("cross_hub").mesh), builder, mesh={"up_axis": "z"})
    assert mesh_warnings(again) == []


def sloped_corridor(along_z: bool) -> trimesh.Trimesh:
    """The 15-degree sloped corridor (12 x 2.4 m, walls 3 m over its floor): 2.2 times as tall as it is wide,
    its side walls along z when it runs along x (more flat area along z than along y: it looks Z-up)."""
    mesh = load_sample("sloped_corridor", slope=15.0).mesh
    return mesh.apply_transform(trimesh.transformations.rotation_matrix(np.pi / 2, (0, 1, 0))) if along_z else mesh


def test_walks_upright_needs_one_piece_that_climbs():
    agent = resolve_config("map_piece")[0].agent
    mesh = trimesh.creation.box(extents=(4.0, 4.0, 4.0))  # footprint 16 m²

    def graph(*nodes):
        built = nx.Graph()
        built.add_nodes_from((i, {"pos": (0.0, y, 0.0), "normal": normal, "area": 2.0}) for i, (y, normal) in enumerate(nodes))
        return built

    flat, ramp = (0.0, 1.0, 0.0), (0.0, np.cos(np.radians(15)), np.sin(np.radians(15)))
    level = graph((0.0, flat), (0.1, flat))
    level.add_edge(0, 1)
    assert not walks_upright(level, mesh, agent)  # a wall's side, read as a floor, is level
    assert walks_upright(graph((0.0, ramp)), mesh, agent)  # a ramp can be one node
    stairs = graph((0.0, flat), (1.5, flat))
    assert not walks_upright(stairs, mesh, agent)  # two patches apart, at their own heights
    stairs.add_edge(0, 1)
    assert walks_upright(stairs, mesh, agent)
    assert not walks_upright(graph((0.0, ramp)), trimesh.creation.box(extents=(8.0, 4.0, 8.0)), agent)  # a sliver


@pytest.mark.parametrize("builder", BUILDERS)
def test_a_tall_piece_read_right_does_not_warn_and_its_z_up_file_does(builder):
    along_x, along_z = sloped_corridor(along_z=False), sloped_corridor(along_z=True)
    assert height_ratio(along_x) > MAX_HEIGHT_RATIO and looks_z_up(along_x, PIECE_AGENT["max_slope"])
    for piece in (along_x, along_z):
        assert mesh_warnings(graph_run(piece, builder, agent=PIECE_AGENT)) == []
    # the Z-up file of the corridor along z stands 4.2 times as tall as wide on the sides of its end walls
    (warning,) = mesh_warnings(graph_run(as_z_up_file(along_z), builder, agent=PIECE_AGENT))
    assert "times as tall as it is wide" in warning and "`mesh: {up_axis: z}`" in warning, warning
    assert mesh_warnings(graph_run(as_z_up_file(along_z), builder, agent=PIECE_AGENT, mesh={"up_axis": "z"})) == []


@pytest.mark.parametrize("builder", BUILDERS)
@pytest.mark.parametrize("name", [n for n in SAMPLES if n not in PIECES])
def test_no_sample_level_read_right_warns(name, builder):
    assert mesh_warnings(graph_run(load_sample(name).mesh, builder)) == []


@pytest.mark.parametrize("builder", BUILDERS)
@pytest.mark.parametrize("name", list(PIECES))
def test_no_sample_piece_read_right_warns(name, builder):
    assert mesh_warnings(graph_run(load_sample(name).mesh, builder, agent=PIECE_AGENT)) == []


@pytest.mark.parametrize("builder", BUILDERS)
def test_nav_test_read_right_does_not_warn(shared_data, builder):
    level = trimesh.load(shared_data / "nav_test.obj", force="mesh", process=False)
    assert mesh_warnings(graph_run(level, builder)) == []


def test_nav_test_read_as_z_up_warns(shared_data):
    level = trimesh.load(shared_data / "nav_test.obj", force="mesh", process=False)
    (warning,) = mesh_warnings(graph_run(as_z_up_file(level), "navmesh"))
    assert "`mesh: {up_axis: z}`" in warning and "inside out" not in warning, warning


def test_an_inside_out_piece_warns(shared_data):
    wrong = g2s_core.run(inverted(hallway(shared_data)), "map_piece", stop_after="terminals")
    (warning,) = mesh_warnings(wrong)
    assert "1 closed body is wound inside out" in warning and "`mesh: {clean: true}`" in warning, warning
    assert "up_axis" not in warning


@pytest.mark.parametrize("builder", BUILDERS)
def test_a_piece_with_one_of_two_thick_tiles_inside_out_warns(builder):
    # 0.6 m tiles: thicker than the climb (Recast cannot merge the upturned underside with the top), 2 cm apart;
    # the other tile walks, about 0.3 of the footprint: above MIN_WALKABLE_SHARE, under SMALL_MESH_SHARE
    piece = trimesh.util.concatenate([slab(0, 3.99, 0, 4, 0.6), inverted(slab(4.01, 8, 0, 4, 0.6))])
    result = graph_run(piece, builder, agent=PIECE_AGENT)
    (warning,) = mesh_warnings(result)
    assert "1 closed body is wound inside out" in warning and "`mesh: {clean: true}`" in warning, warning
    assert mesh_warnings(graph_run(piece, builder, agent=PIECE_AGENT, mesh={"clean": True})) == []


@pytest.mark.parametrize("builder", BUILDERS)
def test_a_narrow_room_modelled_as_a_box_seen_from_inside_does_not_warn(builder):
    room = inverted(trimesh.creation.box(extents=(1.6, 3.0, 10.0)))  # negative volume on purpose
    result = graph_run(room, builder, agent=PIECE_AGENT)
    assert walkable_share(result.graph, room) < SMALL_MESH_SHARE  # so the inside-out count runs
    assert inside_out_bodies(room) == 1 and mesh_warnings(result) == []


def test_cleaning_an_inside_out_piece_restores_its_openings(shared_data):
    piece = hallway(shared_data)
    right = g2s_core.run(piece, "map_piece", stop_after="terminals")
    cleaned = g2s_core.run(inverted(piece), "map_piece", stop_after="terminals", mesh={"clean": True})
    assert mesh_warnings(cleaned) == [] and mesh_warnings(right) == []
    found = [np.array([o.position for o in r.terminals.openings]) for r in (right, cleaned)]
    # its 6 connectors (the edge of its notch, a seventh before the navmesh kept floor under head room of the
    # agent's height in cells: docs/navmesh.md, "Head room a little over the agent's height")
    assert len(found[0]) == 6 and found[1].shape == found[0].shape
    assert np.allclose(found[1], found[0], atol=1e-6)
    assert np.allclose(found[0], found[1], atol=1e-6)


# --- the "no walkable surface" errors ---------------------------------------------------


@pytest.mark.parametrize("builder", BUILDERS)
def test_no_walkable_surface_on_an_inside_out_slab_names_the_cause(builder):
    # 1 m thick: the upturned underside lies 1 m under the top, too low for the agent to stand on
    slab = inverted(trimesh.creation.box(extents=(12.0, 1.0, 12.0)))
    with pytest.raises(G2SError, match="no walkable surface") as caught:
        graph_run(slab, builder)
    assert "1 closed body is wound inside out" in str(caught.value)
    assert "`mesh: {clean: true}`" in str(caught.value) and "up_axis: z" not in str(caught.value)
    assert graph_run(slab, builder, mesh={"clean": True}).graph.number_of_nodes() > 0


def test_cleaning_flips_inside_out_bodies_and_counts_them():
    right = trimesh.creation.box(extents=(2, 1, 2))
    wrong = inverted(trimesh.creation.box(extents=(2, 1, 2)).apply_translation((5, 0, 0)))
    cleaned, counts = clean_mesh(trimesh.util.concatenate([right, wrong]))
    assert counts["flipped_bodies"] == 1
    assert [body.volume > 0 for body in cleaned.split(only_watertight=False)] == [True, True]
    _, counts = clean_mesh(right)
    assert counts["flipped_bodies"] == 0


def narrow_stairwell(storeys: int = 4, storey: float = 3.0) -> trimesh.Trimesh:
    """A 4 x 4 m tower (3.6 m inside, walls 0.2 m) of ``storeys`` storeys read right (Y up): per storey a flight
    of 9 solid steps 1.5 m wide along the south wall, a 0.8 m half landing on the east, a flight back along the
    north wall and a 0.8 m landing on the west. Its flat area along z is 1.96 times that along y."""
    def box(low, high):
        low, high = np.asarray(low, dtype=float), np.asarray(high, dtype=float)
        return trimesh.creation.box(extents=high - low).apply_translation((low + high) / 2)

    top = storeys * storey + 1.0
    parts = [box((-0.2, -0.2, -0.2), (0.0, top, 3.8)), box((3.6, -0.2, -0.2), (3.8, top, 3.8)),
             box((0.0, -0.2, -0.2), (3.6, top, 0.0)), box((0.0, -0.2, 3.6), (3.6, top, 3.8)),
             box((0.0, -0.2, 0.0), (3.6, 0.0, 3.6))]
    for s in range(storeys):
        y = s * storey
        for i in range(9):
            parts.append(box((0.8 + 2.0 * i / 9, y - 0.2, 0.0), (0.8 + 2.0 * (i + 1) / 9, y + storey / 2 * (i + 1) / 9, 1.5)))
            parts.append(box((2.8 - 2.0 * (i + 1) / 9, y + storey / 2 - 0.2, 2.1),
                             (2.8 - 2.0 * i / 9, y + storey / 2 + storey / 2 * (i + 1) / 9, 3.6)))
        parts.append(box((2.8, y + storey / 2 - 0.2, 0.0), (3.6, y + storey / 2, 3.6)))
        parts.append(box((0.0, y + storey - 0.2, 1.5 if s + 1 < storeys else 0.0), (0.8, y + storey, 3.6)))
    return trimesh.util.concatenate(parts)


@pytest.mark.parametrize("builder", BUILDERS)
def test_no_walkable_surface_on_a_tall_piece_read_right_does_not_name_the_up_axis(builder):
    # an agent too wide for the 0.8 m landings: the error added "if the file is Z-up, set `mesh: {up_axis: z}`"
    # (the tower is 3.3 times as tall as wide and has more wall along z than floor), though it stands upright
    tower = narrow_stairwell()
    assert looks_z_up(tower, PIECE_AGENT["max_slope"])
    with pytest.raises(G2SError, match="no walkable surface") as caught:
        graph_run(tower, builder, agent={**PIECE_AGENT, "radius": 0.9})
    assert "up_axis: z" not in str(caught.value) and "the level is 4 x 4 m (x, z), 13.2 m tall" in str(caught.value)


@pytest.mark.parametrize("builder", BUILDERS)
def test_no_walkable_surface_on_a_platform_on_its_side_names_the_up_axis(builder):
    # a 20 x 20 m platform with a 0.3 m curb, written Z-up and read Y-up: its flat area faces along z
    platform = load_sample("curb_platform").mesh
    with pytest.raises(G2SError, match="no walkable surface") as caught:
        graph_run(as_z_up_file(platform), builder)
    assert "`mesh: {up_axis: z}`" in str(caught.value)
