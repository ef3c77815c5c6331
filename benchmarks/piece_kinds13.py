"""A thirteenth round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds13.py [--kinds a b] [--configs map_piece map_piece_sampling]
[--yaws 0 22 45] [--detail]``

Kinds of docs/entry_exit.md, "A thirteenth round of piece kinds", in the tenth round's conventions and table
(``benchmarks/piece_kinds10.py``).
"""

from __future__ import annotations

import math
import sys
from functools import partial

import numpy as np
import trimesh
from piece_kinds10 import SLAB, _box, _hull, _room
from piece_kinds10 import _level as _level10
from piece_kinds10 import kinds_by_name, main as _run_kinds

from g2s_plugins.samples import pieces
from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _N, _S, _W

_level = partial(_level10, round_=13)  # the tenth round's, tagged with this round


def l_shaped_room() -> SampleLevel:
    """L-shaped room: a south arm [0, 10] x [0, 4] and a west arm [0, 4] x [0, 10]; doorways at both arms' ends and
    one in the south arm's inner wall facing the notch (6 m inside the piece's north extent)."""
    t, h, lintel = 0.3, 3.0, 2.2
    parts = [_box(-t, 10 + t, -SLAB, 0.0, -t, 4 + t), _box(-t, 4 + t, -SLAB, 0.0, 4 + t, 10 + t)]

    def wall(x0, x1, z0, z1, gap=None):  # a wall box along x or z, with one doorway gap (a0, a1) along it
        along_x = (x1 - x0) > (z1 - z0)
        if gap is None:
            return [_box(x0, x1, -SLAB, h, z0, z1)]
        a0, a1 = gap
        if along_x:
            return [_box(x0, a0, -SLAB, h, z0, z1), _box(a1, x1, -SLAB, h, z0, z1), _box(a0, a1, lintel, h, z0, z1)]
        return [_box(x0, x1, -SLAB, h, z0, a0), _box(x0, x1, -SLAB, h, a1, z1), _box(x0, x1, lintel, h, a0, a1)]

    parts += wall(-t, 10 + t, -t, 0.0)  # south
    parts += wall(-t, 0.0, 0.0, 10 + t)  # west
    parts += wall(10.0, 10 + t, 0.0, 4.0, gap=(1.2, 2.8))  # the south arm's east end
    parts += wall(4.0, 10 + t, 4.0, 4 + t, gap=(6.2, 7.8))  # the south arm's inner wall, facing the notch
    parts += wall(4.0, 4 + t, 4 + t, 10.0)  # the west arm's inner wall
    parts += wall(-t, 4 + t, 10.0, 10 + t, gap=(1.2, 2.8))  # the west arm's north end
    return _level("l_shaped_room", parts, [_opening((10.3, 0.0, 2.0), _E, 1.6), _opening((2.0, 0.0, 10.3), _N, 1.6),
                                           _opening((7.0, 0.0, 4.3), _N, 1.6)])


def bead_curtain_door() -> SampleLevel:
    """Room 8 x 6 m, doorways west and east under 2.2 m lintels; the east one hung with strands 0.01 m square every
    0.1 m from the lintel to 0.05 m above the floor (collision geometry: not a way through)."""
    parts = _room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(2.2, 3.8, 2.2)]})
    parts += [_box(8.145, 8.155, 0.05, 2.2, z - 0.005, z + 0.005) for z in np.arange(2.25, 3.8, 0.1)]
    return _level("bead_curtain_door", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6)])


def height_field(xs: np.ndarray, zs: np.ndarray, heights: np.ndarray) -> trimesh.Trimesh:
    """The surface over the grid ``xs`` x ``zs`` (metres) at ``heights`` (len(xs), len(zs)), two triangles a cell,
    normals up (+Y)."""
    vertices = [[x, heights[i, j], z] for i, x in enumerate(xs) for j, z in enumerate(zs)]
    n = len(zs)
    faces = []
    for i in range(len(xs) - 1):
        for j in range(n - 1):
            a, b, c, d = i * n + j, i * n + j + 1, (i + 1) * n + j, (i + 1) * n + j + 1
            faces += [[a, b, d], [a, d, c]]
    return trimesh.Trimesh(vertices=vertices, faces=faces, process=False)


def rough_floor_tunnel(seed: int = 0, rough: float = 0.2) -> SampleLevel:
    """Tunnel 12 m long and 3.0 m wide, roof 3.2 m up; its floor a height field on a 0.5 m grid, heights uniform in
    [0, ``rough``] m drawn at random (``seed``), on a solid base; both ends open."""
    rng = np.random.default_rng(seed)
    xs, zs = np.arange(0.0, 12.01, 0.5), np.arange(0.0, 3.01, 0.5)
    heights = rng.uniform(0.0, rough, (len(xs), len(zs)))
    parts = [height_field(xs, zs, heights), _box(0.0, 12.0, -SLAB, -0.01, 0.0, 3.0),
             _box(0.0, 12.0, -SLAB, 3.2, -0.3, 0.0), _box(0.0, 12.0, -SLAB, 3.2, 3.0, 3.3),
             _box(0.0, 12.0, 3.2, 3.4, -0.3, 3.3)]
    return _level("rough_floor_tunnel", parts, [_opening((x, float(heights[i].mean()), 1.5), heading, 3.0)
                                                for i, x, heading in ((0, 0.0, _W), (-1, 12.0, _E))])


def overpass_crossing() -> SampleLevel:
    """A corridor along x at the ground (2.4 m clear, walls 3.2 m) and over it a railed deck along z, 3.5 m up,
    resting on the corridor's walls, nothing else under it; all four ends open."""
    parts = [_box(0.0, 12.0, -SLAB, 0.0, 4.5, 7.5),
             _box(0.0, 12.0, -SLAB, 3.2, 4.5, 4.8), _box(0.0, 12.0, -SLAB, 3.2, 7.2, 7.5),
             _box(4.7, 7.3, 3.2, 3.5, 0.0, 12.0),
             _box(4.7, 4.8, 3.5, 4.5, 0.0, 12.0), _box(7.2, 7.3, 3.5, 4.5, 0.0, 12.0)]
    return _level("overpass_crossing", parts, [_opening((0.0, 0.0, 6.0), _W, 2.4), _opening((12.0, 0.0, 6.0), _E, 2.4),
                                               _opening((6.0, 3.5, 0.0), _S, 2.4), _opening((6.0, 3.5, 12.0), _N, 2.4)])


def grand_steps() -> SampleLevel:
    """Terrace 10 x 8 m 1.2 m up on a solid block, a west doorway, parapets north and south; east six 0.2 m steps
    (0.4 m treads) down across its full width, no side walls, the ground-level bottom tread's end the piece's edge."""
    f = 1.2
    parts = [_box(-0.3, 10.0, 0.0, f, -0.2, 8.2),
             _box(-0.3, 0.0, f, f + 3.0, -0.2, 3.2), _box(-0.3, 0.0, f, f + 3.0, 4.8, 8.2),
             _box(-0.3, 0.0, f + 2.2, f + 3.0, 3.2, 4.8),
             _box(0.0, 10.0, f, f + 1.0, -0.2, 0.0), _box(0.0, 10.0, f, f + 1.0, 8.0, 8.2)]
    parts += [_box(10.0 + 0.4 * i, 10.4 + 0.4 * i, -SLAB, f - 0.2 * (i + 1), 0.0, 8.0) for i in range(6)]
    return _level("grand_steps", parts, [_opening((-0.3, f, 4.0), _W, 1.6), _opening((12.4, 0.0, 4.0), _E, 8.0)])


def cliff_ledge() -> SampleLevel:
    """A ledge 1.0 m wide and 12 m long at the foot of a rock face (from 6 m below to 4 m above it), nothing under it
    or beyond its open side; both ends open."""
    parts = [_box(0.0, 12.0, -0.3, 0.0, 0.0, 1.0), _box(0.0, 12.0, -6.0, 4.0, 1.0, 1.6)]
    return _level("cliff_ledge", parts, [_opening((0.0, 0.0, 0.5), _W, 1.0), _opening((12.0, 0.0, 0.5), _E, 1.0)])


def stepped_street() -> SampleLevel:
    """Street 16 m long and 4 m wide between walls 4 m high; its floor four flats 4 m long at 0, 0.3, 0.6 and 0.9 m
    (steps across its whole width, within the climb); both ends open."""
    parts = [_box(4.0 * i, 4.0 * (i + 1), -SLAB, 0.3 * i, 0.0, 4.0) for i in range(4)]
    parts += [_box(0.0, 16.0, -SLAB, 4.0, -0.3, 0.0), _box(0.0, 16.0, -SLAB, 4.0, 4.0, 4.3)]
    return _level("stepped_street", parts, [_opening((0.0, 0.0, 2.0), _W, 4.0), _opening((16.0, 0.9, 2.0), _E, 4.0)])


def oblique_end_corridor() -> SampleLevel:
    """Corridor 2.4 m wide, walls 0.3 m; its west end square and open at x 0, its east end (floor and walls) cut at 45
    degrees along x = 10 + (z + 0.3): the clear floor's cut 3.39 m long."""

    def cut(z: float) -> float:  # the end's x at z
        return 10.0 + (z + 0.3)

    def prism(z0: float, z1: float, y0: float, y1: float) -> trimesh.Trimesh:  # x from 0 to the cut
        return _hull([[x, y, z] for z in (z0, z1) for x in (0.0, cut(z)) for y in (y0, y1)])

    parts = [prism(-0.3, 2.7, -SLAB, 0.0), prism(-0.3, 0.0, -SLAB, 3.0), prism(2.4, 2.7, -SLAB, 3.0)]
    return _level("oblique_end_corridor", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4),
                                                  _opening((11.5, 0.0, 1.2), (1.0, 0.0, -1.0), 2.4 * math.sqrt(2.0))])


def amphitheatre_aisle() -> SampleLevel:
    """Hall 10 x 10 m, walls 5.5 m; a stage at the floor, five seating rows 0.8 m deep rising 0.45 m each (over the
    climb), an aisle through them in 0.225 m steps, a walkway at the top; a doorway south at the stage and one east
    from the walkway, 2.25 m up."""
    top = 2.25
    parts = [_box(-0.3, 10.3, -SLAB, 0.0, -0.3, 10.3)]
    for k in range(1, 6):  # row k over x [4 + 0.8 (k - 1), 4 + 0.8 k]
        x0 = 4.0 + 0.8 * (k - 1)
        for z0, z1 in ((0.0, 4.3), (5.7, 10.0)):
            parts.append(_box(x0, x0 + 0.8, 0.0, 0.45 * k, z0, z1))
        parts.append(_box(x0, x0 + 0.4, 0.0, 0.45 * k - 0.225, 4.3, 5.7))
        parts.append(_box(x0 + 0.4, x0 + 0.8, 0.0, 0.45 * k, 4.3, 5.7))
    parts.append(_box(8.0, 10.0, 0.0, top, 0.0, 10.0))
    parts += [_box(*box) for box in pieces._wall_boxes(10.0, 10.0, 0.3, {
        "S": [(1.2, 2.8, 0.0, 2.2)], "E": [(4.2, 5.8, top, top + 2.2)]}, 5.5, 0.0)]
    return _level("amphitheatre_aisle", parts, [_opening((2.0, 0.0, -0.3), _S, 1.6), _opening((10.3, top, 5.0), _E, 1.6)])


def glass_end_corridor() -> SampleLevel:
    """Corridor 12 x 2.4 m, west end open; its east end closed by a glass pane 0.02 m thick (a closed box) across the
    clear width from the floor to 3 m, flush with the walls' and the floor's ends."""
    parts = [_box(0.0, 12.0, -SLAB, 0.0, -0.3, 2.7), _box(0.0, 12.0, -SLAB, 3.0, -0.3, 0.0),
             _box(0.0, 12.0, -SLAB, 3.0, 2.4, 2.7), _box(11.98, 12.0, 0.0, 3.0, 0.0, 2.4)]
    return _level("glass_end_corridor", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4)])


def kick_plate_gate() -> SampleLevel:
    """Yard 10 x 8 m inside a fence 1.2 m high; south a 1.6 m gate between gateposts 1.5 m high with a kick plate
    0.15 m high and 0.03 m thick across it; north a plain 1.6 m gap."""
    fence, t = 1.2, 0.1
    parts = [_box(-t, 10 + t, -SLAB, 0.0, -t, 8 + t),
             _box(-t, 0.0, 0.0, fence, 0.0, 8.0), _box(10.0, 10 + t, 0.0, fence, 0.0, 8.0),
             _box(-t, 4.0, 0.0, fence, -t, 0.0), _box(6.0, 10 + t, 0.0, fence, -t, 0.0),
             _box(4.0, 4.2, 0.0, 1.5, -0.15, 0.05), _box(5.8, 6.0, 0.0, 1.5, -0.15, 0.05),
             _box(4.2, 5.8, 0.0, 0.15, -0.065, -0.035),
             _box(-t, 4.2, 0.0, fence, 8.0, 8 + t), _box(5.8, 10 + t, 0.0, fence, 8.0, 8 + t)]
    return _level("kick_plate_gate", parts, [_opening((5.0, 0.0, -t), _S, 1.6), _opening((5.0, 0.0, 8 + t), _N, 1.6)])


def round_door(strips: int = 32) -> SampleLevel:
    """Room 8 x 6 m, a plain west doorway; east a round doorway: a circle of radius 1.2 m centred 1.0 m above the floor
    at z 3, cut by the floor (1.33 m clear at the floor and at 2.0 m), the wall round it in ``strips`` strips."""
    radius, centre_y, cz = 1.2, 1.0, 3.0
    parts = _room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(cz - radius, cz + radius, 3.0)]})

    def hole(z: float) -> tuple[float, float]:  # the hole's bottom and top at z, metres
        half = math.sqrt(max(radius ** 2 - (z - cz) ** 2, 0.0))
        return max(centre_y - half, 0.0), centre_y + half

    edges = np.linspace(cz - radius, cz + radius, strips + 1)
    for z0, z1 in zip(edges[:-1], edges[1:]):
        (b0, t0), (b1, t1) = hole(z0), hole(z1)
        parts.append(_hull([[x, y, z] for x in (8.0, 8.3) for z, y in ((z0, t0), (z1, t1), (z0, 3.0), (z1, 3.0))]))
        if b0 > 0 or b1 > 0:
            parts.append(_hull([[x, y, z] for x in (8.0, 8.3) for z, y in ((z0, b0), (z1, b1), (z0, -SLAB), (z1, -SLAB))]))
    clear = 2.0 * math.sqrt(radius ** 2 - centre_y ** 2)
    return _level("round_door", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((8.3, 0.0, cz), _E, clear)])


KINDS = kinds_by_name(l_shaped_room, bead_curtain_door, rough_floor_tunnel, overpass_crossing, grand_steps,
                      cliff_ledge, stepped_street, oblique_end_corridor, amphitheatre_aisle, glass_end_corridor,
                      kick_plate_gate, round_door)
"""Kind name -> factory of the thirteenth round."""


if __name__ == "__main__":
    sys.exit(_run_kinds(kinds=KINDS, description=__doc__.splitlines()[0]))
