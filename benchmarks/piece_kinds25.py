"""A twenty-fifth round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds25.py [--feet] [--kinds a b] [--configs map_piece
map_piece_sampling] [--yaws 0 22 45] [--detail]``

Eight kinds of docs/entry_exit.md, "A twenty-fifth round of piece kinds", each with its known openings (count,
place, width, height) written in its docstring before the detector first ran on them: the pieces of a level
designer's modular kit none of the earlier rounds built. A corridor with a door in its side wall and one in its end
wall, a gate closed by its leaf with a wicket door cut in it, twin tunnels joined by a cross passage, a timber-framed
doorway with knee braces in its upper corners, an open pavilion on four corner posts, a door whose leaf stands ajar
into the room, a door under a flight of stairs beside the flight's own upper door, and a road closed by a boom
barrier beside a gap for walkers. Built with :mod:`piece_parts`, in the earlier rounds' conventions. ``--feet``
runs, in their place, the door under the stair with the flight's foot 0.3-1.2 m off the wall in front of it
(:data:`FEET`).
"""

from __future__ import annotations

import math
import sys
from functools import partial

from piece_parts import ROOM_DOORS, SLAB, box, flight, hull, kinds_by_name, room, round_level, run_kinds

from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _N, _S, _W

_level = round_level(25)


def side_and_end_door_corridor() -> SampleLevel:
    """Corridor 10 x 2.4 m (clear x 0-10, z 0-2.4), walls 0.3 m thick and 3 m high, its west end open; in its east
    end wall (x 10-10.3) a 1.0 m doorway against the south wall (z 0-1.0, its south jamb the south wall's inner face)
    under a 2.2 m lintel; in its north wall (z 2.4-2.7) a 1.2 m doorway at x 6.8-8.0 under a 2.2 m lintel; the floor
    runs under both doorways to the walls' outer faces. Known: three, at the floor (y 0): the west end, 2.4 m at
    (0, 1.2); the end wall's doorway, 1.0 m at its outer face (10.3, 0.5); the side doorway, 1.2 m at its outer face
    (7.4, 2.7)."""
    parts = [box(0.0, 10.3, -SLAB, 0.0, -0.3, 2.7), box(0.0, 10.3, -SLAB, 3.0, -0.3, 0.0)]
    parts += [box(0.0, 6.8, -SLAB, 3.0, 2.4, 2.7), box(8.0, 10.3, -SLAB, 3.0, 2.4, 2.7)]
    parts += [box(6.8, 8.0, 2.2, 3.0, 2.4, 2.7)]
    parts += [box(10.0, 10.3, -SLAB, 3.0, 1.0, 2.4), box(10.0, 10.3, 2.2, 3.0, 0.0, 1.0)]
    return _level("side_and_end_door_corridor", parts, [_opening((0.0, 0.0, 1.2), _W, 2.4),
                                                       _opening((10.3, 0.0, 0.5), _E, 1.0),
                                                       _opening((7.4, 0.0, 2.7), _N, 1.2)])


def wicket_gate_door() -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 4 m high; a 1.6 m doorway west (z 2.2-3.8, lintel
    2.2 m); in the east wall a gateway 3.2 m wide (z 1.4-4.6) under a 3.0 m lintel, closed by a gate leaf 0.08 m thick
    in the wall's middle (x 8.11-8.19) from the floor to the lintel, with a wicket door cut in it: 1.0 m wide (z
    2.5-3.5), its sill the leaf's bottom rail 0.1 m high, its head 2.3 m up. Known: two, at the floor (y 0; the
    wicket's sill 0.1 m over it, under ``sample_height``): the west doorway, 1.6 m at (-0.3, 3.0); the wicket, 1.0 m,
    at the wall's outer face (8.3, 3.0) (the gateway's outer half, x 8.19-8.3, is 3.2 m wide in front of it)."""
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(1.4, 4.6, 3.0)]}, height=4.0)
    leaf = (8.11, 8.19)
    parts += [box(*leaf, 0.0, 3.0, 1.4, 2.5), box(*leaf, 0.0, 3.0, 3.5, 4.6)]
    parts += [box(*leaf, 0.0, 0.1, 2.5, 3.5), box(*leaf, 2.3, 3.0, 2.5, 3.5)]
    return _level("wicket_gate_door", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((8.3, 0.0, 3.0), _E, 1.0)])


def twin_bore_cross_passage() -> SampleLevel:
    """Twin tunnels 14 m long (x 0-14), each 3.0 m wide: the south bore z 0-3, the north bore z 4-7, a wall 1.0 m
    thick between them (z 3-4) and outer walls 0.5 m thick, all 3.5 m high under a roof slab 0.3 m thick over the
    whole (y 3.5-3.8); mid-length a cross passage 1.2 m wide (x 6.4-7.6) through the middle wall under a 2.2 m lintel
    joins them. Known: the four bore ends, 3.0 m each, at the floor (y 0): on x 0 facing west and on x 14 facing east,
    at z 1.5 and 5.5 (1.0 m of wall between the two on each face); none at the cross passage (inside the piece)."""
    parts = [box(0.0, 14.0, -SLAB, 0.0, -0.5, 7.5), box(0.0, 14.0, 3.5, 3.8, -0.5, 7.5)]
    parts += [box(0.0, 14.0, -SLAB, 3.5, -0.5, 0.0), box(0.0, 14.0, -SLAB, 3.5, 7.0, 7.5)]
    parts += [box(0.0, 6.4, -SLAB, 3.5, 3.0, 4.0), box(7.6, 14.0, -SLAB, 3.5, 3.0, 4.0)]
    parts += [box(6.4, 7.6, 2.2, 3.5, 3.0, 4.0)]
    ends = [_opening((x, 0.0, z), heading, 3.0) for x, heading in ((0.0, _W), (14.0, _E)) for z in (1.5, 5.5)]
    return _level("twin_bore_cross_passage", parts, ends)


def braced_frame_door(leg: float = 0.5) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high; a timber-framed west doorway 1.6 m wide
    (z 2.2-3.8) under a 2.4 m lintel, with a knee brace in each upper corner through the wall's thickness: a
    triangle whose legs run ``leg`` m (0.5) down the jamb from the lintel (to 1.9 m) and along the lintel from the
    jamb, so at height y the way is 1.6 - 2 (y - 1.9) m wide: 1.5 m at 1.95 m (the head-room ray's height), 1.4 m at
    the agent's 2.0 m; a plain 1.6 m doorway east (lintel 2.2 m). Known: two, at the floor (y 0), 1.6 m each as the
    designer draws them: the west one at (-0.3, 3.0) (the detector reads a doorway's free part at the head-room
    ray's height: 1.5 m), the east one at (8.3, 3.0)."""
    lintel = 2.4
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, lintel)], "E": ROOM_DOORS["E"]})
    for jamb, inward in ((2.2, 1.0), (3.8, -1.0)):
        corners = [(jamb, lintel - leg), (jamb, lintel), (jamb + inward * leg, lintel)]
        parts.append(hull([[x, y, z] for x in (-0.3, 0.0) for z, y in corners]))
    return _level("braced_frame_door", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((8.3, 0.0, 3.0), _E, 1.6)])


def pavilion_four_posts() -> SampleLevel:
    """An open pavilion: a floor 6 x 6 m (x 0-6, z 0-6) at y 0 on a slab, four corner posts 0.25 m square (inside
    the floor's corners) up to a roof slab 0.2 m thick at 2.8 m (y 2.8-3.0) overhanging the floor by 0.3 m on every
    side; no walls. Known: the floor's four sides, each 5.5 m between its posts, at the floor (y 0) on the floor's
    edges: (3, 0) facing south, (3, 6) north, (0, 3) west, (6, 3) east."""
    parts = [box(0.0, 6.0, -SLAB, 0.0, 0.0, 6.0), box(-0.3, 6.3, 2.8, 3.0, -0.3, 6.3)]
    parts += [box(x, x + 0.25, 0.0, 2.8, z, z + 0.25) for x in (0.0, 5.75) for z in (0.0, 5.75)]
    sides = [((3.0, 0.0, 0.0), _S), ((3.0, 0.0, 6.0), _N), ((0.0, 0.0, 3.0), _W), ((6.0, 0.0, 3.0), _E)]
    return _level("pavilion_four_posts", parts, [_opening(p, h, 5.5) for p, h in sides])


def ajar_leaf_door(open_deg: float = 60.0) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high; a 1.2 m west doorway (z 2.4-3.6) under a
    2.2 m lintel whose leaf (1.2 m wide, 0.05 m thick, y 0.01-2.1) is hinged at the north jamb's inner corner (0,
    3.6) and stands ajar ``open_deg`` (60) degrees into the room: its free edge at (1.04, 3.0), the leaf's face 1.01
    m from the south jamb's inner corner (1.2 sin 60 less half its thickness); a plain 1.6 m doorway east (z
    2.2-3.8). Known: two, at the floor (y 0): the west doorway, 1.2 m at the wall's outer face (-0.3, 3.0) (the way
    past the leaf is 1.01 m wide, behind the wall's inner face); the east one, 1.6 m at (8.3, 3.0)."""
    parts = room(8.0, 6.0, {"W": [(2.4, 3.6, 2.2)], "E": ROOM_DOORS["E"]})
    a = math.radians(open_deg)
    along, across = (math.sin(a), -math.cos(a)), (math.cos(a), math.sin(a))  # (x, z): hinge to free edge, its normal
    hinge = (0.0, 3.6)
    plan = [(hinge[0] + along[0] * s + across[0] * t, hinge[1] + along[1] * s + across[1] * t)
            for s in (0.0, 1.2) for t in (-0.025, 0.025)]
    parts.append(hull([[x, y, z] for x, z in plan for y in (0.01, 2.1)]))
    return _level("ajar_leaf_door", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.2), _opening((8.3, 0.0, 3.0), _E, 1.6)])


def door_under_stair(foot: float = 0.3) -> SampleLevel:
    """Hall 8 x 8 m (clear x 0-8, z 0-8), walls 0.3 m thick and 7 m high, no roof; along the east wall (x 6.6-8.0)
    a flight of 20 steps 0.28 m deep and 0.2 m high rising north from z 0.3 (the last one's top 4.0 m up at z 5.9),
    carried on a sawtooth slab 0.3 m under its treads (head room under it), open on its west side; a landing 4.0 m up
    (slab y 3.7-4.0) over x 6.6-8.0, z 5.9-8.0, its west edge open over the hall. Doorways: west, 1.6 m at the floor
    (z 3.2-4.8, lintel 2.2 m); east at the floor under the flight, 1.2 m (z 3.8-5.0, lintel 2.2 m; the flight's
    underside over it 2.3-3.1 m up); east from the landing, 1.2 m (z 6.4-7.6), its sill 4.0 m up, lintel 2.2 m over
    it. Known: three, at the walls' outer faces: the west one, 1.6 m at (-0.3, 4.0) at y 0; the one under the flight,
    1.2 m at (8.3, 4.4) at y 0; the landing's, 1.2 m at (8.3, 7.0) 4.0 m up. None along the flight's or the landing's
    open sides (they drop into the piece's own hall).

    ``foot``: where the flight starts (z, metres off the south wall's inner face), its 20 treads sharing the run to
    z 5.9; 0.3 builds the piece above, the others measure what the foot's room in front of the wall does
    (:data:`FEET`)."""
    landing, top = 4.0, 5.9
    parts = room(8.0, 8.0, {"W": [(3.2, 4.8, 2.2)], "E": [(-0.3, 8.3, 7.0)]}, height=7.0)  # east wall: below
    parts += [box(8.0, 8.3, -SLAB, 7.0, z0, z1) for z0, z1 in ((-0.3, 3.8), (5.0, 6.4), (7.6, 8.3))]
    parts += [box(8.0, 8.3, 2.2, 7.0, 3.8, 5.0)]
    parts += [box(8.0, 8.3, landing + 2.2, 7.0, 6.4, 7.6), box(8.0, 8.3, -SLAB, landing, 6.4, 7.6)]
    parts += flight((6.6, foot), (0, 1), (6.6, 8.0), 20, (top - foot) / 20, 0.2, 0.0, solid=False)
    parts += [box(6.6, 8.0, landing - 0.3, landing, top, 8.0)]
    return _level("door_under_stair", parts, [_opening((-0.3, 0.0, 4.0), _W, 1.6),
                                             _opening((8.3, 0.0, 4.4), _E, 1.2),
                                             _opening((8.3, landing, 7.0), _E, 1.2)])


def boom_barrier_road() -> SampleLevel:
    """A gated road between site walls: clear x 0-12, z 0-6, walls 0.3 m thick and 3 m high along z 0 and z 6, its
    west end open; at its east end a post 0.3 m square and 1.1 m high (x 11.7-12.0, z 1.5-1.8) carrying a boom 0.1 m
    square across the road at y 0.95-1.05 (x 11.8-11.9, from the post to the north wall at z 6): above the 0.4 m
    climb and under the agent's 2 m, no way under or over it; between the south wall and the post a gap 1.5 m wide
    (z 0-1.5) for walkers. Known: two, at the floor (y 0): the west end, 6.0 m at (0, 3.0); the walkers' gap, 1.5 m
    at the road's end (12, 0.75). None along the boom."""
    parts = [box(0.0, 12.0, -SLAB, 0.0, 0.0, 6.0), box(0.0, 12.0, -SLAB, 3.0, -0.3, 0.0)]
    parts += [box(0.0, 12.0, -SLAB, 3.0, 6.0, 6.3), box(11.7, 12.0, 0.0, 1.1, 1.5, 1.8)]
    parts += [box(11.8, 11.9, 0.95, 1.05, 1.8, 6.0)]
    return _level("boom_barrier_road", parts, [_opening((0.0, 0.0, 3.0), _W, 6.0),
                                              _opening((12.0, 0.0, 0.75), _E, 1.5)])


KINDS = kinds_by_name(side_and_end_door_corridor, wicket_gate_door, twin_bore_cross_passage, braced_frame_door,
                      pavilion_four_posts, ajar_leaf_door, door_under_stair, boom_barrier_road)
"""Kind name -> factory of the twenty-fifth round."""

FEET = {f"door_under_stair_foot_{round(foot * 100)}cm": partial(door_under_stair, foot)
        for foot in (0.3, 0.5, 0.7, 0.9, 1.2)}
"""``door_under_stair_foot_<n>cm`` -> :func:`door_under_stair` with the flight's foot that many centimetres off the
south wall."""


if __name__ == "__main__":
    feet = "--feet" in sys.argv[1:]
    sys.exit(run_kinds([a for a in sys.argv[1:] if a != "--feet"], kinds=FEET if feet else KINDS,
                       description=__doc__.splitlines()[0]))
