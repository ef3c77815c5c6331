"""A thirty-fourth round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds34.py [--kinds a b] [--configs map_piece map_piece_sampling] [--yaws 0
22 45] [--detail] [--one-to-one]``

Eight kinds of docs/entry_exit.md, "A thirty-fourth round of piece kinds", each with its known openings (count, place,
width, height, facing) written in its docstring before the detector first ran on them: the pieces of a level designer's
modular kit none of the earlier rounds built. A warehouse whose two loading bays have roller shutters, one half up to
just over the agent's height, one down to 1.2 m; a doorway through a thick wall with a crate left standing in its
reveal; a street rising 1.5 m from end to end with a door in its side at mid length; an L-shaped balcony round a
raised room's corner with a gap in its railing on the far arm; a T whose three ends are 4.8, 2.4 and 1.2 m wide; a
plaza tile walled on two sides and open on the two others, nothing at their corner; a footbridge whose ends are flights
down to railed pads; a roofed tunnel with a door at the back of a niche in its thick side wall. Built with
:mod:`piece_parts`, in the earlier rounds' conventions.
"""

from __future__ import annotations

import sys

import numpy as np
from piece_kinds33 import folded_wall
from piece_parts import ROOM_OPENINGS, SLAB, box, flight, hull, kinds_by_name, room, round_level, run_kinds

from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _N, _S, _W

_level = round_level(34)


def roller_shutter_bays(open_to: float = 2.1, closed_to: float = 1.2) -> SampleLevel:
    """A warehouse (clear x 0-12, z 0-8), walls 0.3 m thick and 4.5 m high, no roof, floored to the walls' outer
    faces at y 0; in the west wall a 1.0 m door (z 3.5-4.5, lintel 2.2 m); in the east wall (x 12.0-12.3) two loading
    bays 3.0 m wide under a lintel 3.5 m up, the south one z 1.0-4.0, the north one z 4.6-7.6 (a 0.6 m pier between
    them). Each bay has a roller shutter: a curtain 0.04 m thick in the wall's middle (x 12.13-12.17) from the lintel
    down, and its drum's box on the wall's inner face over the bay (x 11.6-12.0, y 3.5-4.0); the north bay's curtain
    half up, its bottom edge ``open_to`` m (2.1) over the floor, just over the agent's 2.0 m height; the south bay's
    down to ``closed_to`` m (1.2), under it. Known: two, at the floor (y 0): the west door, 1.0 m at (-0.3, 4.0),
    facing west, 2.2 m high; the north bay, 3.0 m at (12.3, 6.1), facing east, ``open_to`` m (2.1) high (under the
    curtain). Not the south bay (1.2 m clear: the agent does not fit under it)."""
    parts = room(12.0, 8.0, {"W": [(3.5, 4.5, 2.2)], "E": [(1.0, 4.0, 3.5), (4.6, 7.6, 3.5)]}, height=4.5)
    for (z0, z1), bottom in (((1.0, 4.0), closed_to), ((4.6, 7.6), open_to)):
        parts += [box(12.13, 12.17, bottom, 3.5, z0, z1), box(11.6, 12.0, 3.5, 4.0, z0, z1)]
    return _level("roller_shutter_bays", parts,
                  [_opening((-0.3, 0.0, 4.0), _W, 1.0), _opening((12.3, 0.0, 6.1), _E, 3.0)])


def crate_in_thick_doorway(crate: float = 1.0, door: float = 2.0) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high but the east one 0.6 m thick (x 8.0-8.6),
    as a kit's outer wall; a 1.6 m west doorway (z 2.2-3.8, lintel 2.2 m); in the east wall a ``door`` m (2.0)
    doorway (z 2.0-4.0, lintel 2.2 m) through its whole thickness, and a crate left standing in its reveal against
    the south jamb: ``crate`` m (1.0) wide (z 2.0-3.0), 0.5 m deep (x 8.05-8.55, 0.05 m in from both faces) and 0.8 m
    high (over the 0.4 m climb); the slab to the walls' outer faces. Known: two, at the floor (y 0), 2.2 m high: the
    west doorway, 1.6 m at (-0.3, 3.0), facing west; the clear part of the east one beside the crate, ``door`` -
    ``crate`` m (1.0, z 3.0-4.0) at the wall's outer face, (8.6, 3.5), facing east (as round 20's rubble: the way
    through is the part the agent passes)."""
    z0 = 3.0 - door / 2
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(-0.3, 6.3, 3.0)]})  # the east wall built below, thicker
    parts += [box(8.0, 8.6, -SLAB, 0.0, -0.3, 6.3), box(8.0, 8.6, -SLAB, 3.0, -0.3, z0),
              box(8.0, 8.6, -SLAB, 3.0, z0 + door, 6.3), box(8.0, 8.6, 2.2, 3.0, z0, z0 + door),
              box(8.05, 8.55, 0.0, 0.8, z0, z0 + crate)]
    return _level("crate_in_thick_doorway", parts,
                  [ROOM_OPENINGS[0], _opening((8.6, 0.0, z0 + (crate + door) / 2), _E, door - crate)])


def sloped_street_side_door(rise: float = 1.5, length: float = 12.0) -> SampleLevel:
    """A street 4.0 m wide (clear z 0-4) and ``length`` m (12) long, its surface one plane rising ``rise`` m (1.5) from
    y 0 at its west end (x 0) to its east end (7.1 degrees), on a solid wedge; facades 0.3 m thick (z -0.3-0 and
    4.0-4.3) standing to 4 m over the street's top end (y 5.5); both ends open. In the north facade at mid length a
    1.2 m door (x 5.4-6.6) whose sill is level through the wall at the street's height at the door's middle (y 0.75;
    the street 0.075 m lower at its west jamb and higher at its east one, within the climb), under a lintel 2.2 m over
    it (y 2.95); the piece ends at the facade's outer face. Known: three: the west end, 4.0 m at (0, 2.0) at y 0,
    facing west; the east end, 4.0 m at (``length``, 2.0) at y ``rise``, facing east, both open to the sky; the door,
    1.2 m at (6.0, 4.3) at y 0.75, facing north, 2.2 m high."""
    top = rise + 4.0
    sill = rise * 6.0 / length
    parts = [hull([[x, y, z] for x, y in ((0.0, -SLAB), (0.0, 0.0), (length, rise), (length, -SLAB))
                   for z in (-0.3, 4.3)]),
             box(0.0, length, -SLAB, top, -0.3, 0.0), box(0.0, 5.4, -SLAB, top, 4.0, 4.3),
             box(6.6, length, -SLAB, top, 4.0, 4.3), box(5.4, 6.6, sill + 2.2, top, 4.0, 4.3),
             box(5.4, 6.6, -SLAB, sill, 4.0, 4.3)]
    return _level("sloped_street_side_door", parts,
                  [_opening((0.0, 0.0, 2.0), _W, 4.0), _opening((length, rise, 2.0), _E, 4.0),
                   _opening((6.0, sill, 4.3), _N, 1.2)])


def l_balcony_rail_gap(up: float = 3.0, gap: float = 1.2) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), its floor ``up`` m (3) up on a solid block under the room's footprint (x
    -0.3-8.3, z -0.3-6.3), walls 0.3 m thick and 3 m high, 1.6 m doorways west and east (z 2.2-3.8, lintels 2.2 m).
    The east doorway gives onto an L-shaped balcony 1.5 m deep round the room's north-east corner, at the floor's
    height on a 0.2 m slab over nothing: its east arm x 8.3-9.8, z 0-7.8; its north arm x 0-9.8, z 6.3-7.8. Railed
    1.0 m high and 0.1 m thick along its outer sides (x 9.7-9.8 and z 7.7-7.8) and across its two ends (z 0-0.1 at the
    east arm's south end, x 0-0.1 at the north arm's west end), but for a ``gap`` m (1.2) gap in the north railing
    (x 2.0-3.2), where a kit's ladder or stair module joins. Known: two, at y ``up``: the west doorway, 1.6 m at
    (-0.3, 3.0), facing west, 2.2 m high; the railing's gap, ``gap`` m at the railing's outer face (2.6, 7.8), facing
    north, open to the sky. Not the east doorway (inside the piece), not the railing's length (a drop behind a
    rail)."""
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(2.2, 3.8, 2.2)]}, floor=up)
    parts += [box(-0.3, 8.3, -SLAB, up - SLAB, -0.3, 6.3),
              box(8.3, 9.8, up - SLAB, up, 0.0, 7.8), box(0.0, 8.3, up - SLAB, up, 6.3, 7.8)]
    rail = up + 1.0
    g0, g1 = 2.6 - gap / 2, 2.6 + gap / 2
    parts += [box(9.7, 9.8, up, rail, 0.0, 7.8), box(0.0, g0, up, rail, 7.7, 7.8), box(g1, 9.8, up, rail, 7.7, 7.8),
              box(8.3, 9.7, up, rail, 0.0, 0.1), box(0.0, 0.1, up, rail, 6.3, 7.7)]
    return _level("l_balcony_rail_gap", parts,
                  [_opening((-0.3, up, 3.0), _W, 1.6), _opening((2.6, up, 7.8), _N, gap)])


def t_three_widths(wide: float = 4.8, middle: float = 2.4, narrow: float = 1.2) -> SampleLevel:
    """A T of three ends of different widths, walls 0.3 m thick and 3 m high, open to the sky, floor at y 0: a hall
    ``wide`` m (4.8) across (clear x 0-8, z 0-4.8) open at its west end (x 0); from its east wall (x 8.0-8.3) an arm
    ``middle`` m (2.4) wide on the hall's centre line (clear z 1.2-3.6) east to its open end at x 14; from its north
    wall (z 4.8-5.1) a stem ``narrow`` m (1.2) wide (clear x 5.0-6.2) north to its open end at z 10. Known: three, at
    the floor, each on its end's line, facing along its way: ``wide`` m at (0, 2.4) facing west; ``middle`` m at (14,
    2.4) facing east; ``narrow`` m at (5.6, 10.0) facing north."""
    c = wide / 2
    a0, a1 = c - middle / 2, c + middle / 2
    s0, s1 = 5.0, 5.0 + narrow
    parts = [box(0.0, 8.3, -SLAB, 0.0, -0.3, wide + 0.3), box(8.3, 14.0, -SLAB, 0.0, a0 - 0.3, a1 + 0.3),
             box(s0 - 0.3, s1 + 0.3, -SLAB, 0.0, wide + 0.3, 10.0),
             box(0.0, 8.3, -SLAB, 3.0, -0.3, 0.0),
             box(0.0, s0, -SLAB, 3.0, wide, wide + 0.3), box(s1, 8.3, -SLAB, 3.0, wide, wide + 0.3),
             box(8.0, 8.3, -SLAB, 3.0, 0.0, a0), box(8.0, 8.3, -SLAB, 3.0, a1, wide),
             box(8.3, 14.0, -SLAB, 3.0, a0 - 0.3, a0), box(8.3, 14.0, -SLAB, 3.0, a1, a1 + 0.3),
             box(s0 - 0.3, s0, -SLAB, 3.0, wide + 0.3, 10.0), box(s1, s1 + 0.3, -SLAB, 3.0, wide + 0.3, 10.0)]
    return _level("t_three_widths", parts,
                  [_opening((0.0, 0.0, c), _W, wide), _opening((14.0, 0.0, c), _E, middle),
                   _opening(((s0 + s1) / 2, 0.0, 10.0), _N, narrow)])


def open_corner_plaza(side: float = 8.0) -> SampleLevel:
    """A plaza tile ``side`` m (8) square (x 0-8, z 0-8) on a slab, floor at y 0, walled 3 m high and 0.3 m thick
    along its south (z -0.3-0) and west (x -0.3-0) sides, each wall ending flush with the open side it meets; its north
    and east sides open, nothing at their corner (8, 8): a kit's corner tile. Known: two, ``side`` m each, at the floor,
    open to the sky, one per neighbour snapped on: the north side at (4.0, 8.0), facing north; the east side at (8.0,
    4.0), facing east. Decided before the run: two, not one turning the corner, each reaching the open corner."""
    parts = [box(-0.3, side, -SLAB, 0.0, -0.3, side), box(-0.3, side, -SLAB, 3.0, -0.3, 0.0),
             box(-0.3, 0.0, -SLAB, 3.0, 0.0, side)]
    return _level("open_corner_plaza", parts,
                  [_opening((side / 2, 0.0, side), _N, side), _opening((side, 0.0, side / 2), _E, side)])


def footbridge_stair_ends(width: float = 2.0, steps: int = 20, riser: float = 0.15, tread: float = 0.3) -> SampleLevel:
    """A footbridge ``width`` m (2.0) wide (clear z 0-2) over nothing of the piece: a pad 1.2 m long at y 0 (x 0-1.2),
    a flight of ``steps`` (20) risers of ``riser`` m (0.15) on ``tread`` m (0.3) treads up east (x 1.2-7.2, carried
    on a sawtooth slab, open under it), a deck 6 m long (x 7.2-13.2) at 3.0 m on a 0.2 m slab, the same flight down
    east (x 13.2-19.2) and a pad (x 19.2-20.4) at y 0; balustrades 1.0 m high over the floor and 0.05 m thick along
    both sides (z -0.05-0 and 2.0-2.05) from end to end, over the flights 1.0 m over the line from each flight's
    foot to its top. Known: two, ``width`` m each at y 0,
    open to the sky: the west pad's end at (0, 1.0), facing west; the east pad's end at (20.4, 1.0), facing east. Not
    along the deck or the flights (railed), nothing under them."""
    top = steps * riser
    run = steps * tread
    x1 = 1.2 + run  # the west flight's top, the deck's west end
    x2, x3 = x1 + 6.0, x1 + 6.0 + run  # the deck's east end, the east flight's foot
    end = x3 + 1.2
    parts = [box(0.0, 1.2, -SLAB, 0.0, 0.0, width), box(x3, end, -SLAB, 0.0, 0.0, width),
             box(x1, x2, top - SLAB, top, 0.0, width)]
    parts += flight((1.2, 0.0), (1.0, 0.0), (0.0, width), steps, tread, riser, 0.0, solid=False)
    parts += flight((x3, 0.0), (-1.0, 0.0), (0.0, width), steps, tread, riser, 0.0, solid=False)
    for z0, z1 in ((-0.05, 0.0), (width, width + 0.05)):
        profile = [(0.0, 0.0), (1.2, 0.0), (x1, top), (x2, top), (x3, 0.0), (end, 0.0)]
        for (xa, ya), (xb, yb) in zip(profile[:-1], profile[1:]):
            parts.append(hull([[x, y + dy, z] for x, y in ((xa, ya), (xb, yb)) for dy in (0.0, 1.0)
                               for z in (z0, z1)]))
    return _level("footbridge_stair_ends", parts,
                  [_opening((0.0, 0.0, width / 2), _W, width), _opening((end, 0.0, width / 2), _E, width)])


def niche_door_tunnel(door: float = 1.0, niche: float = 1.6, depth: float = 1.0) -> SampleLevel:
    """A roofed tunnel 3.0 m wide (clear z 0-3) and 12 m long (x 0-12), both ends open, under a roof slab 0.3 m thick
    at 3.0 m over the whole (y 3.0-3.3); its south wall 0.3 m thick (z -0.3-0), its north wall ``depth`` + 0.3 m (1.3)
    thick (z 3.0-4.3), as a kit's retaining wall. At mid length in the north wall a niche ``niche`` m (1.6) wide (x
    5.2-6.8) and ``depth`` m (1.0) deep (z 3.0-4.0), floored level with the tunnel, up to the roof, and in its back
    (z 4.0-4.3) a ``door`` m (1.0) door on the niche's middle (x 5.5-6.5) under a lintel 2.2 m up; the slab to the
    walls' outer faces. Known: three, at the floor (y 0): the tunnel's ends, 3.0 m at (0, 1.5) facing west and at
    (12, 1.5) facing east, 3.0 m high; the door, ``door`` m at the north wall's outer face (6.0, 4.3), facing north,
    2.2 m high."""
    n0, n1 = 6.0 - niche / 2, 6.0 + niche / 2
    d0, d1 = 6.0 - door / 2, 6.0 + door / 2
    back = 3.0 + depth
    parts = [box(0.0, 12.0, -SLAB, 0.0, -0.3, back + 0.3), box(0.0, 12.0, 3.0, 3.3, -0.3, back + 0.3),
             box(0.0, 12.0, -SLAB, 3.0, -0.3, 0.0),
             box(0.0, n0, -SLAB, 3.0, 3.0, back + 0.3), box(n1, 12.0, -SLAB, 3.0, 3.0, back + 0.3),
             box(n0, d0, -SLAB, 3.0, back, back + 0.3), box(d1, n1, -SLAB, 3.0, back, back + 0.3),
             box(d0, d1, 2.2, 3.0, back, back + 0.3)]
    return _level("niche_door_tunnel", parts,
                  [_opening((0.0, 0.0, 1.5), _W, 3.0), _opening((12.0, 0.0, 1.5), _E, 3.0),
                   _opening((6.0, 0.0, back + 0.3), _N, door)])


def ramp_bridge_over_stream(deck: float = 3.0, ramp: float = 12.0) -> SampleLevel:
    """A probe of the review's LOW 8 (a floor at the foot of the main floor's ramp and the level test): a bridge 3 m
    wide (clear z 0-3) whose deck, 0.3 m thick with its top ``deck`` m (3) up, runs from its open west end (x 0) to x
    8, then ramps down ``ramp`` m (12) east to the ground (y 0) at its open east end; balustrades 1.0 m high and 0.1 m
    thick along both sides from end to end. Under the deck a stream bed 4.0 m wide (clear x 2-6) from z -4.5 to 7.5
    at y 0, between walls 0.3 m thick and 2.5 m high, open at both ends. Known: four: the deck's west end, 3.0 m at (0,
    1.5) at y ``deck``, facing west; the ramp's foot, 3.0 m at (8 + ``ramp``, 1.5) at y 0, facing east; the stream
    bed's ends, 4.0 m at (4.0, -4.5) facing south and at (4.0, 7.5) facing north, at y 0 (where the bed goes on into
    its neighbours)."""
    z0, z1 = -4.5, 7.5
    parts = [box(0.0, 8.0, deck - 0.3, deck, 0.0, 3.0),
             hull([[x, y, z] for x, y in ((8.0, deck - 0.3), (8.0, deck), (8.0 + ramp, 0.0), (8.0 + ramp, -SLAB))
                   for z in (0.0, 3.0)]),
             box(0.0, 8.0 + ramp, deck, deck + 1.0, -0.1, 0.0), box(0.0, 8.0 + ramp, deck, deck + 1.0, 3.0, 3.1),
             box(1.7, 6.3, -SLAB, 0.0, z0, z1), box(1.7, 2.0, -SLAB, 2.5, z0, z1), box(6.0, 6.3, -SLAB, 2.5, z0, z1)]
    return _level("ramp_bridge_over_stream", parts,
                  [_opening((0.0, deck, 1.5), _W, 3.0), _opening((8.0 + ramp, 0.0, 1.5), _E, 3.0),
                   _opening((4.0, 0.0, z0), _S, 4.0), _opening((4.0, 0.0, z1), _N, 4.0)])


def off_centre_fold_door(fold_deg: float = 15.0, near: float = 0.5, far: float = 2.0) -> SampleLevel:
    """A probe of the review's LOW 7 (a union of an opening's parts in two passes, a fold in the first): round 33's
    ``folded_wall_door`` with its doorway off the fold's middle: room (clear x 0-8, z 0-6 and east of it), walls 0.3
    m thick and 3 m high, a 1.6 m west doorway (z 2.2-3.8, lintel 2.2 m); its east wall two wings ``fold_deg`` (15)
    degrees off north-south meeting at an apex (8 + 3 tan ``fold_deg``, 3.0); the doorway's jambs square to the
    wings, ``near`` m (0.5) along the south wing's inner face and ``far`` m (2.0) along the north wing's from the
    apex, under a lintel 2.2 m up; the slab under the walls' whole footprint. Known: two, at the floor (y 0): the
    west doorway, 1.6 m at (-0.3, 3.0); the fold's doorway, the chord between its jambs' outer corners at that
    chord's middle, facing square to it (outward)."""
    parts, o1, o2 = folded_wall(fold_deg, near, far)
    chord = o2 - o1
    heading = np.array([chord[1], 0.0, -chord[0]]) / np.linalg.norm(chord)  # square to the chord, facing east
    mid = (o1 + o2) / 2
    return _level("off_centre_fold_door", parts,
                  [ROOM_OPENINGS[0], _opening((mid[0], 0.0, mid[1]), heading, float(np.linalg.norm(chord)))])


KINDS = kinds_by_name(roller_shutter_bays, crate_in_thick_doorway, sloped_street_side_door, l_balcony_rail_gap,
                      t_three_widths, open_corner_plaza, footbridge_stair_ends, niche_door_tunnel)
"""Kind name -> factory of the thirty-fourth round."""

PROBES = kinds_by_name(ramp_bridge_over_stream, off_centre_fold_door)
"""Kind name -> factory of the pieces built to check the review's two risks (``--probes``; not the round's kinds)."""


if __name__ == "__main__":
    probes = "--probes" in sys.argv[1:]
    sys.exit(run_kinds([a for a in sys.argv[1:] if a != "--probes"], kinds=PROBES if probes else KINDS,
                       description=__doc__.splitlines()[0]))
