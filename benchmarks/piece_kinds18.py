"""An eighteenth round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds18.py [--kinds a b] [--configs map_piece map_piece_sampling]
[--yaws 0 22 45] [--detail]``

Twelve kinds of docs/entry_exit.md, "An eighteenth round of piece kinds", each with its known openings written in
its docstring before the detector first ran on it: floors whose end is no level line (a crowned road, a step along
the way at one side, a dish falling to a drain, a room listing as a whole), meshes as exporters leave them (a
finely tessellated floor, a triangle soup with slivers, overlapping and coincident slabs), a drop deeper than the
climb inside a corridor, louvres across an end, a door in a cut corner, an unrailed well through the floor and
buttresses beside a door. Built with the tenth round's helpers and table (``benchmarks/piece_kinds10.py``).
"""

from __future__ import annotations

import math
import sys

import numpy as np
import trimesh
from piece_kinds10 import SLAB, _box, _hull, _room
from piece_kinds10 import kinds_by_name, main as _run_kinds
from piece_kinds14 import _corridor
from piece_kinds15 import _prism
from piece_parts import ROOM_DOORS as _DOORS
from piece_parts import ROOM_OPENINGS as _ROOM_DOORS
from piece_parts import round_level

from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _N, _S, _W

_level = round_level(18)  # the tenth round's, tagged with this round


def crowned_road(crown: float = 0.12) -> SampleLevel:
    """A road 12 x 4 m over nothing whose surface rises ``crown`` m from both sides to its middle line (two planes,
    3.4 degrees at 0.12 m), parapets 1 m high and 0.1 m thick outside both sides. Known: both ends, 4.0 m, at the
    road's sides' height."""
    half = [_hull([[x, y, z] for x in (0.0, 12.0) for z, top in ((z0, 0.0), (2.0, crown)) for y in (top - SLAB, top)])
            for z0 in (0.0, 4.0)]
    parts = half + [_box(0.0, 12.0, -SLAB, 1.0, -0.1, 0.0), _box(0.0, 12.0, -SLAB, 1.0, 4.0, 4.1)]
    return _level("crowned_road", parts, [_opening((0.0, 0.0, 2.0), _W, 4.0), _opening((12.0, 0.0, 2.0), _E, 4.0)])


def raised_half_corridor(rise: float = 0.3) -> SampleLevel:
    """Corridor 12 x 2.4 m, both ends open; its north half (z 1.2-2.4) raised ``rise`` m the whole length (a step
    within the climb running along the way out). Known: both ends, 2.4 m, over both levels."""
    parts = _corridor(12.0) + [_box(0.0, 12.0, 0.0, rise, 1.2, 2.4)]
    return _level("raised_half_corridor", parts,
                  [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, 1.2), _E, 2.4)])


def dense_floor_room(cell: float = 0.1) -> SampleLevel:
    """Room 8 x 6 m, 1.6 m doorways W and E; its floor slab's faces split until no edge is longer than ``cell`` m
    (88,960 triangles at 0.1 m, as an exporter leaves a sculpted floor). Known: both doorways."""
    parts = _room(8.0, 6.0, _DOORS)
    vertices, faces = trimesh.remesh.subdivide_to_size(parts[0].vertices, parts[0].faces, max_edge=cell)
    parts[0] = trimesh.Trimesh(vertices, faces, process=False)
    return _level("dense_floor_room", parts, _ROOM_DOORS)


def triangle_soup_room() -> SampleLevel:
    """Room 8 x 6 m, 1.6 m doorways W and E, as a triangle soup: no two faces share a vertex, and a fan of 40 sliver
    triangles (zero area, three corners on one line) lies along the floor under each doorway's outer edge. Known:
    both doorways."""
    mesh = trimesh.util.concatenate(_room(8.0, 6.0, _DOORS))
    corners = [np.asarray(mesh.triangles, dtype=np.float64)]
    for x in (-0.3, 8.3):  # the doorways' outer edges, z 2.2-3.8 at the floor's height
        t = np.linspace(2.2, 3.8, 41)
        corners.append(np.array([[[x, 0.0, a], [x, 0.0, 0.5 * (a + b)], [x, 0.0, b]] for a, b in zip(t[:-1], t[1:])]))
    soup = np.concatenate(corners).reshape(-1, 3)
    soup_mesh = trimesh.Trimesh(soup, np.arange(len(soup)).reshape(-1, 3), process=False)
    return SampleLevel(name="triangle_soup_room", mesh=soup_mesh, openings=tuple(_ROOM_DOORS), metadata={"round": 18})


def overlapping_slab_corridor() -> SampleLevel:
    """Corridor 12 x 2.4 m, both ends open, modelled in overlapping pieces: its floor two slabs (x 0-8 and 4-12)
    and a third coinciding face for face with the second's middle (x 4-8: the same corners), each wall two boxes
    overlapping over x 5-7. Known: both ends, 2.4 m."""
    parts = [_box(0.0, 8.0, -SLAB, 0.0, 0.0, 2.4), _box(4.0, 12.0, -SLAB, 0.0, 0.0, 2.4),
             _box(4.0, 12.0, -SLAB, 0.0, 0.0, 2.4)]
    parts += [_box(x0, x1, -SLAB, 3.0, z0, z1) for x0, x1 in ((0.0, 7.0), (5.0, 12.0)) for z0, z1 in ((-0.3, 0.0), (2.4, 2.7))]
    mesh = trimesh.util.concatenate(parts)  # not merged: the coinciding slab keeps its own vertices
    return SampleLevel(name="overlapping_slab_corridor", mesh=mesh, metadata={"round": 18},
                       openings=(_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, 1.2), _E, 2.4)))


def step_down_corridor(drop: float = 0.6) -> SampleLevel:
    """Corridor 12 x 2.4 m, both ends open; at x 6 its floor drops ``drop`` m (more than the climb: walked down, not
    up), walls 3 m over the upper floor. Known: both ends, 2.4 m (the west one at 0, the east one ``drop`` m down):
    a designer joins the piece at either end."""
    parts = [_box(0.0, 6.0, -drop - SLAB, 0.0, 0.0, 2.4), _box(6.0, 12.0, -drop - SLAB, -drop, 0.0, 2.4),
             _box(0.0, 12.0, -drop - SLAB, 3.0, -0.3, 0.0), _box(0.0, 12.0, -drop - SLAB, 3.0, 2.4, 2.7)]
    return _level("step_down_corridor", parts,
                  [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, -drop, 1.2), _E, 2.4)])


def louvred_end(pitch: float = 0.3) -> SampleLevel:
    """Corridor 12 x 2.4 m, walls 3 m; across its east end louvres: slats 0.05 m thick and 0.15 m deep (x 11.85-12)
    every ``pitch`` m from 0.25 m up to 2.95 m. Known: the west end only (2.4 m; the slats close the east one)."""
    parts = _corridor(12.0) + [_box(11.85, 12.0, y, y + 0.05, 0.0, 2.4) for y in np.arange(0.25, 2.951, pitch)]
    return _level("louvred_end", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4)])


def dished_plaza(dip: float = 0.3) -> SampleLevel:
    """Plaza 12 x 12 m inside walls 0.3 m thick and 2.5 m high, a 2 m gate in the middle of each side; its floor
    four planes falling from the walls' outer faces to a drain at the centre ``dip`` m down (2.7 degrees at 0.3 m).
    Known: the four gates, 2.0 m, at the outer faces."""
    outer = [(-0.3, -0.3), (12.3, -0.3), (12.3, 12.3), (-0.3, 12.3)]
    parts = [_hull([[x, y + top, z] for (x, z), top in (((6.0, 6.0), -dip), (a, 0.0), (b, 0.0)) for y in (-SLAB, 0.0)])
             for a, b in zip(outer, outer[1:] + outer[:1])]
    gate = [(5.0, 7.0, 2.5)]
    parts += _room(12.0, 12.0, {side: gate for side in "WESN"}, height=2.5)[1:]  # the walls, without the flat slab
    return _level("dished_plaza", parts, [_opening((-0.3, 0.0, 6.0), _W, 2.0), _opening((12.3, 0.0, 6.0), _E, 2.0),
                                          _opening((6.0, 0.0, -0.3), _S, 2.0), _opening((6.0, 0.0, 12.3), _N, 2.0)])


def corner_cut_door(cut: float = 2.5) -> SampleLevel:
    """Room 8 x 6 m, walls 0.3 m and 3 m high, a 1.6 m west doorway; its north-east corner cut off by a wall at 45
    degrees (``cut`` m along each side, mitred into the north and east walls) holding a 1.6 m doorway (lintel 2.2 m)
    in its middle, facing north-east. Known: both doorways (the corner one at the cut wall's outer face)."""
    n, u = np.array([1.0, 1.0]) / math.sqrt(2.0), np.array([1.0, -1.0]) / math.sqrt(2.0)  # out of the cut, along it
    a = np.array([8.0 - cut, 6.0])  # the cut's inner line runs from a, along u, for cut * sqrt(2)
    mitre = 0.3 * math.sqrt(2.0) - 0.3  # how far the outer faces' corners lie past the inner ones
    length = cut * math.sqrt(2.0)
    parts = [_prism([(-0.3, -0.3), (8.3, -0.3), (8.3, 6.0 - cut + mitre), (8.0 - cut + mitre, 6.3), (-0.3, 6.3)],
                    -SLAB, 0.0),
             _box(-0.3, 8.3, -SLAB, 3.0, -0.3, 0.0), _box(-0.3, 0.0, -SLAB, 3.0, 0.0, 2.2),
             _box(-0.3, 0.0, -SLAB, 3.0, 3.8, 6.0), _box(-0.3, 0.0, 2.2, 3.0, 2.2, 3.8),
             _prism([(-0.3, 6.0), (8.0 - cut, 6.0), (8.0 - cut + mitre, 6.3), (-0.3, 6.3)], -SLAB, 3.0),
             _prism([(8.0, -0.3), (8.3, -0.3), (8.3, 6.0 - cut + mitre), (8.0, 6.0 - cut)], -SLAB, 3.0)]

    def wall(t0: float, t1: float, y0: float, y1: float) -> trimesh.Trimesh:
        """The cut wall from ``t0`` to ``t1`` m along its inner line, mitred at its ends."""
        inner0, inner1 = a + t0 * u, a + t1 * u
        outer0 = np.array([8.0 - cut + mitre, 6.3]) if t0 == 0.0 else inner0 + 0.3 * n
        outer1 = np.array([8.3, 6.0 - cut + mitre]) if t1 == length else inner1 + 0.3 * n
        return _prism([tuple(inner0), tuple(inner1), tuple(outer1), tuple(outer0)], y0, y1)

    jambs = (0.5 * length - 0.8, 0.5 * length + 0.8)
    parts += [wall(0.0, jambs[0], -SLAB, 3.0), wall(jambs[1], length, -SLAB, 3.0), wall(*jambs, 2.2, 3.0)]
    door = a + 0.5 * length * u + 0.3 * n
    return _level("corner_cut_door", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6),
                                             _opening((door[0], 0.0, door[1]), (n[0], 0.0, n[1]), 1.6)])


def listing_deck_room(roll_deg: float = 3.0, pitch_deg: float = 2.0) -> SampleLevel:
    """Room 8 x 6 m, 1.6 m doorways W and E, tilted as a whole about its centre (4, 0, 3): ``roll_deg`` about the x
    axis (its floor falling towards the north, across the doorways) then ``pitch_deg`` about the z axis (the east
    doorway higher), walls leaning with it, as a ship's deck lists. Known: both doorways, 1.6 m, where the tilt takes them."""
    centre = [4.0, 0.0, 3.0]
    tilt = (trimesh.transformations.rotation_matrix(math.radians(pitch_deg), [0.0, 0.0, 1.0], centre)
            @ trimesh.transformations.rotation_matrix(math.radians(roll_deg), [1.0, 0.0, 0.0], centre))
    level = _level("listing_deck_room", _room(8.0, 6.0, _DOORS), _ROOM_DOORS)
    level.mesh.apply_transform(tilt)
    moved = [_opening(trimesh.transform_points([o.position], tilt)[0], tilt[:3, :3] @ np.asarray(o.heading), o.width)
             for o in level.openings]
    return SampleLevel(name=level.name, mesh=level.mesh, openings=tuple(moved), metadata=level.metadata)


def atrium_well(well: float = 4.0) -> SampleLevel:
    """Room 12 x 12 m, walls 3 m, 1.6 m doorways W and E (z 5.2-6.8); a square well ``well`` m across through its
    floor's middle down to nothing, unrailed. Known: both doorways; not the well's edges (inside the piece)."""
    a, b = 6.0 - well / 2, 6.0 + well / 2
    parts = _room(12.0, 12.0, {"W": [(5.2, 6.8, 2.2)], "E": [(5.2, 6.8, 2.2)]})[1:]
    parts += [_box(-0.3, a, -SLAB, 0.0, -0.3, 12.3), _box(b, 12.3, -SLAB, 0.0, -0.3, 12.3),
              _box(a, b, -SLAB, 0.0, -0.3, a), _box(a, b, -SLAB, 0.0, b, 12.3)]
    return _level("atrium_well", parts, [_opening((-0.3, 0.0, 6.0), _W, 1.6), _opening((12.3, 0.0, 6.0), _E, 1.6)])


def buttress_flanked_door(depth: float = 1.2) -> SampleLevel:
    """Room 8 x 6 m, 1.6 m doorways W and E; outside the west wall two buttresses ``depth`` m deep, 0.6 m wide and
    2.5 m high, 0.3 m beyond each jamb (z 1.3-1.9 and 4.1-4.7), with nothing under or between them beyond the wall.
    Known: both doorways (the west one at the wall's outer face, ``depth`` m inside the buttresses' faces)."""
    parts = _room(8.0, 6.0, _DOORS)
    parts += [_box(-0.3 - depth, -0.3, -SLAB, 2.5, z0, z0 + 0.6) for z0 in (1.3, 4.1)]
    return _level("buttress_flanked_door", parts, _ROOM_DOORS)


KINDS = kinds_by_name(crowned_road, raised_half_corridor, dense_floor_room, triangle_soup_room,
                      overlapping_slab_corridor, step_down_corridor, louvred_end, dished_plaza, corner_cut_door,
                      listing_deck_room, atrium_well, buttress_flanked_door)
"""Kind name -> factory of the eighteenth round."""


if __name__ == "__main__":
    sys.exit(_run_kinds(kinds=KINDS, description=__doc__.splitlines()[0]))
