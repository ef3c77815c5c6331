"""A thirty-sixth round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds36.py [--kinds a b] [--configs map_piece map_piece_sampling] [--yaws 0
22 45] [--detail] [--one-to-one]``

Eight kinds of docs/entry_exit.md, "A thirty-sixth round of piece kinds", each with its known openings (count, place,
width, height, facing) written in its docstring before the detector first ran on them: the pieces of a level designer's
modular kit none of the earlier rounds built. A washroom whose cubicles' thin partitions stand 0.15 m off the floor; a
door under a transom bar with an open fanlight over it; a cloister walk round a garth behind dwarf walls and piers; a
locker corridor with locker doors standing open into it; a corridor whose floor is a glass pane 0.02 m thick over a
void for 2 m; two stopped escalators side by side parted by a solid deck; a stepped ramp (a cordonata) of sloping
treads and low risers; a roofed lych gate in a low churchyard wall with a coffin stone in its passage. Built with
:mod:`piece_parts`, in the earlier rounds' conventions.
"""

from __future__ import annotations

import sys

from piece_parts import SLAB, box, flight, hull, kinds_by_name, room, round_level, run_kinds

from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _N, _S, _W

_level = round_level(36)


def cubicle_washroom(lift: float = 0.15, panel: float = 0.03) -> SampleLevel:
    """A washroom (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, no roof, floored to the walls' outer faces
    at y 0; a 1.6 m doorway in the west wall (z 2.2-3.8, lintel 2.2 m) and a 1.2 m door in the south wall (x 1.0-2.2,
    lintel 2.2 m); along the east wall four cubicles (x 6.5-8.0; z 0-1.5, 1.5-3.0, 3.0-4.5, 4.5-6.0) of kit panels
    ``panel`` m (0.03) thick standing ``lift`` m (0.15) off the floor up to 2.0 m, as a washroom's partitions stand on
    feet: three dividers (x 6.5-8.0, centred on z 1.5, 3.0 and 4.5) and a front along x 6.5 with a 0.9 m cubicle door
    standing open (no leaf) in each cubicle (z 0.3-1.2, 1.8-2.7, 3.3-4.2, 4.8-5.7). Known: two, at the floor (y 0),
    2.2 m high: the west doorway, 1.6 m at (-0.3, 3.0), facing west; the south door, 1.2 m at (1.6, -0.3), facing
    south. Not the cubicle doors (inside the piece), nothing under the raised panels (``lift`` m, far under the
    agent's 2.0 m)."""
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "S": [(1.0, 2.2, 2.2)]})
    half = panel / 2
    for z in (1.5, 3.0, 4.5):
        parts.append(box(6.5, 8.0, lift, 2.0, z - half, z + half))
    for z0, z1 in ((0.0, 0.3), (1.2, 1.8), (2.7, 3.3), (4.2, 4.8), (5.7, 6.0)):
        parts.append(box(6.5 - half, 6.5 + half, lift, 2.0, z0, z1))
    return _level("cubicle_washroom", parts,
                  [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((1.6, 0.0, -0.3), _S, 1.2)])


def fanlight_over_door(bar: float = 0.1, fanlight: float = 0.5) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, no roof, floored to the walls' outer faces
    at y 0; a 1.6 m doorway in the west wall (z 2.2-3.8, lintel 2.2 m); in the east wall a 1.0 m door (z 2.5-3.5)
    under a transom bar ``bar`` m (0.1) deep whose underside is 2.1 m up, and over the bar an open fanlight (no glass)
    ``fanlight`` m (0.5) high, the door's width (2.2-2.7 m up), the wall whole over it to 3 m. Known: two, at the floor
    (y 0): the west doorway, 1.6 m at (-0.3, 3.0), facing west, 2.2 m high; the east door, 1.0 m at the wall's outer
    face (8.3, 3.0), facing east, 2.1 m high (under the bar; the fanlight is a window 2.2 m up, no way through)."""
    top = 2.1 + bar
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(-0.3, 6.3, 3.0)]})  # the east wall built below
    parts += [box(8.0, 8.3, -SLAB, 3.0, -0.3, 2.5), box(8.0, 8.3, -SLAB, 3.0, 3.5, 6.3),
              box(8.0, 8.3, 2.1, top, 2.5, 3.5), box(8.0, 8.3, top + fanlight, 3.0, 2.5, 3.5)]
    return _level("fanlight_over_door", parts,
                  [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((8.3, 0.0, 3.0), _E, 1.0)])


_CLOISTER_PIERS = ((2.4, 2.8), (4.4, 4.8), (6.0, 6.4), (7.6, 8.0), (9.2, 9.6), (11.2, 11.6))
"""The cloister's piers along each arcade (metres along it from the outer wall's inner face), the first and last at
the garth's corners; the middle two flank the arcade's 1.2 m way into the garth (6.4-7.6)."""


def cloister_garth(dwarf: float = 0.6) -> SampleLevel:
    """A cloister (clear x 0-14, z 0-14), outer walls 0.3 m thick and 3.2 m high, no roof, floored at y 0 to the
    outer walls' outer faces (walk and garth one slab); a 1.6 m doorway in the west wall and one in the east wall
    (z 6.2-7.8, lintels 2.2 m). A walk 2.4 m wide runs round a square garth (x, z 2.7-11.3) behind four arcades 0.3
    m thick (the south one over z 2.4-2.7 and x 2.4-11.6, the north one over z 11.3-11.6, the west and east ones
    over x 2.4-2.7 and 11.3-11.6 between them): each a dwarf wall ``dwarf`` m (0.6, over the 0.4 m climb) high but
    for a 1.2 m way into the garth in its middle (6.4-7.6 along it), and piers 0.4 m long and 3.2 m high at 2.4,
    4.4, 6.0, 7.6, 9.2 and 11.2 m along it (their starts; the corners' piers shared), the arches between them open
    over the dwarf wall. Known: two, at the floor (y 0), 2.2 m high: the west doorway, 1.6 m at (-0.3, 7.0), facing
    west; the east doorway, 1.6 m at (14.3, 7.0), facing east. Not the ways into the garth or the arches (inside
    the piece)."""
    parts = room(14.0, 14.0, {"W": [(6.2, 7.8, 2.2)], "E": [(6.2, 7.8, 2.2)]}, height=3.2)

    def arcade(a0: float, a1: float, c0: float, c1: float, along_x: bool, y0: float, y1: float) -> None:
        parts.append(box(a0, a1, y0, y1, c0, c1) if along_x else box(c0, c1, y0, y1, a0, a1))

    for c0, c1, along_x, a0, a1 in ((2.4, 2.7, True, 2.4, 11.6), (11.3, 11.6, True, 2.4, 11.6),
                                    (2.4, 2.7, False, 2.7, 11.3), (11.3, 11.6, False, 2.7, 11.3)):
        for s0, s1 in ((a0, 6.4), (7.6, a1)):
            arcade(s0, s1, c0, c1, along_x, 0.0, dwarf)
        for p0, p1 in _CLOISTER_PIERS:
            p0, p1 = max(p0, a0), min(p1, a1)
            if p1 > p0:
                arcade(p0, p1, c0, c1, along_x, 0.0, 3.2)
    return _level("cloister_garth", parts,
                  [_opening((-0.3, 0.0, 7.0), _W, 1.6), _opening((14.3, 0.0, 7.0), _E, 1.6)])


def open_locker_corridor(leaf: float = 0.4) -> SampleLevel:
    """Corridor 12 x 2.4 m (clear x 0-12, z 0-2.4), walls 0.3 m thick and 3 m high, open to the sky, both ends open,
    floor at y 0; along its north wall a bank of lockers 0.5 m deep and 1.9 m high (x 1.0-11.0, z 1.9-2.4, solid to
    the slab), leaving 1.9 m beside it; four locker doors standing open square to the bank, leaves 0.02 m thick and
    ``leaf`` m (0.4) wide from 0.1 to 1.85 m up (z 1.9 - ``leaf`` to 1.9; x 2.0, 4.4, 6.8 and 9.2 to 0.02 m east of
    each), leaving 1.5 m beside each. Known: two, at the floor (y 0), 2.4 m each, open to the sky: the west end at
    (0, 1.2), facing west; the east end at (12, 1.2), facing east. Nothing along the lockers or at the leaves."""
    parts = [box(0.0, 12.0, -SLAB, 0.0, -0.3, 2.7), box(0.0, 12.0, -SLAB, 3.0, -0.3, 0.0),
             box(0.0, 12.0, -SLAB, 3.0, 2.4, 2.7), box(1.0, 11.0, -SLAB, 1.9, 1.9, 2.4)]
    parts += [box(x, x + 0.02, 0.1, 1.85, 1.9 - leaf, 1.9) for x in (2.0, 4.4, 6.8, 9.2)]
    return _level("open_locker_corridor", parts,
                  [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, 1.2), _E, 2.4)])


def glass_floor_span(pane: float = 0.02, span: tuple[float, float] = (5.0, 7.0)) -> SampleLevel:
    """Corridor 12 x 2.4 m (clear x 0-12, z 0-2.4), walls 0.3 m thick and 3 m high standing on the slab, open to the
    sky, both ends open, floor at y 0; over ``span`` (x 5.0-7.0) the slab is cut away and the floor is one glass pane
    ``pane`` m (0.02) thick, its top flush at y 0, butted to the slab's cut ends and between the walls (z 0-2.4),
    over nothing (a void through the piece, as a kit's glass walkway over a drop); the walls run whole past it.
    Known: two, at the floor (y 0), 2.4 m each, open to the sky: the west end at (0, 1.2), facing west; the east end
    at (12, 1.2), facing east. Not the pane's edges: the pane is floor."""
    g0, g1 = span
    parts = [box(0.0, g0, -SLAB, 0.0, -0.3, 2.7), box(g1, 12.0, -SLAB, 0.0, -0.3, 2.7),
             box(g0, g1, -pane, 0.0, 0.0, 2.4),
             box(0.0, 12.0, -SLAB, 3.0, -0.3, 0.0), box(0.0, 12.0, -SLAB, 3.0, 2.4, 2.7)]
    return _level("glass_floor_span", parts,
                  [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, 1.2), _E, 2.4)])


def escalator_pair(steps: int = 20, riser: float = 0.2, tread: float = 0.4) -> SampleLevel:
    """Two stopped escalators side by side in one well 2.4 m wide (clear z 0-2.4) between side walls 0.3 m thick
    standing 3 m over the floors (their tops level at 3.0 m beside the lower landing, ``steps * riser`` + 3.0 m
    beside the upper one, sloping between): a lower landing 2.0 m long (x 0-2, y 0), ``steps`` (20) risers of
    ``riser`` m (0.2) on ``tread`` m (0.4) treads rising east (x 2-10, solid), an upper landing 2.0 m long (x 10-12)
    at ``steps * riser`` m (4.0). Down the middle a solid deck (the two escalators' shared balustrade) 0.4 m wide
    (z 1.0-1.4) and 1.0 m over the floor beneath it, from x 1.0 to 11.0, ending 1.0 m short of each end: each
    escalator 1.0 m wide. Known: two, 2.4 m each, open to the sky: the lower end at (0, 1.2) at y 0, facing west;
    the upper end at (12, 1.2) at y ``steps * riser``, facing east. Decided before the run: ONE opening at each end
    (the deck ends 1.0 m inside the piece, so the end is one way 2.4 m wide; the escalators are two lanes of it, as
    round 33's central handrail), nothing along the deck."""
    top = steps * riser
    x0, x1 = 2.0, 2.0 + steps * tread
    parts = [box(0.0, x0, -SLAB, 0.0, -0.3, 2.7), box(x1, x1 + 2.0, top - SLAB, top, -0.3, 2.7)]
    parts += flight((x0, 0.0), (1.0, 0.0), (-0.3, 2.7), steps, tread, riser, 0.0)
    for z0, z1 in ((-0.3, 0.0), (2.4, 2.7)):
        parts += [box(0.0, x0, -SLAB, 3.0, z0, z1), box(x1, x1 + 2.0, top - SLAB, top + 3.0, z0, z1),
                  hull([[x, y, z] for x, lo, hi in ((x0, -SLAB, 3.0), (x1, top - SLAB, top + 3.0))
                        for y in (lo, hi) for z in (z0, z1)])]
    deck = [(1.0, 0.0, 1.0), (x0, 0.0, 1.0), (x1, top, 1.0), (x1 + 1.0, top, 1.0)]
    for (xa, ya, ha), (xb, yb, hb) in zip(deck[:-1], deck[1:]):  # over the lower landing, the flight, the upper one
        parts.append(hull([[x, y, z] for x, y0, h in ((xa, ya, ha), (xb, yb, hb))
                           for y in (y0 - SLAB, y0 + h) for z in (1.0, 1.4)]))
    return _level("escalator_pair", parts,
                  [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((x1 + 2.0, top, 1.2), _E, 2.4)])


def cordonata_ramp(flights: int = 5, slope: float = 0.1, riser: float = 0.12) -> SampleLevel:
    """A stepped ramp (a cordonata) 2.4 m wide (clear z 0-2.4) between walls 0.3 m thick standing 3 m over its top
    landing (y -SLAB to the top's 3 m), open to the sky: a bottom landing 2.0 m long (x 0-2, y 0), then ``flights``
    (5) treads 2.0 m long (x 2-12), each sloping up ``slope`` m (0.1) over its length (under 3 degrees) and ending in
    a riser ``riser`` m (0.12) high (a kit's cordone, within the climb) up to the next, the last riser up to a top
    landing 2.0 m long (x 12-14) at ``flights * (slope + riser)`` m (1.1); solid to the slab. Known: two, 2.4 m each,
    open to the sky: the bottom end at (0, 1.2) at y 0, facing west; the top end at (14, 1.2) at y ``flights *
    (slope + riser)``, facing east. Nothing along the treads or risers."""
    parts = [box(0.0, 2.0, -SLAB, 0.0, 0.0, 2.4)]
    y = 0.0
    for i in range(flights):
        xa, xb = 2.0 + 2.0 * i, 4.0 + 2.0 * i
        low, high = y, y + slope
        parts.append(hull([[x, yy, z] for x, top in ((xa, low), (xb, high)) for yy in (-SLAB, top)
                           for z in (0.0, 2.4)]))
        y = high + riser  # the riser is the next tread's (or the top landing's) west face
    top = y
    end = 2.0 + 2.0 * flights
    parts.append(box(end, end + 2.0, -SLAB, top, 0.0, 2.4))
    parts += [box(0.0, end + 2.0, -SLAB, top + 3.0, -0.3, 0.0), box(0.0, end + 2.0, -SLAB, top + 3.0, 2.4, 2.7)]
    return _level("cordonata_ramp", parts,
                  [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((end + 2.0, top, 1.2), _E, 2.4)])


def lych_gate_stone(stone: float = 0.6) -> SampleLevel:
    """A churchyard (clear x 0-10, z 0-8), open to the sky, floored at y 0 to its walls' outer faces; boundary walls
    0.3 m thick and 1.5 m high (over the 0.4 m climb) on all four sides, but for a 1.2 m gap in the north wall (x
    4.4-5.6, open to the sky) and a lych gate in the south wall: a 2.4 m gap (x 3.8-6.2) whose passage is roofed
    (a roof slab 0.2 m thick, its underside 2.6 m up, over x 3.6-6.4 and z -0.3-2.2) on two posts 0.2 m square
    inside the yard (x 3.6-3.8 and 6.2-6.4, z 2.0-2.2) and on the wall ends; under the roof a coffin stone
    ``stone`` m (0.6) high, 0.6 m wide and 1.8 m long (x 4.7-5.3, z 0.1-1.9), 0.1 m inside the wall's inner face,
    leaving 0.9 m either side of it. Known: two, at the floor (y 0): the lych gate, 2.4 m at the wall's outer face
    (5.0, -0.3), facing south, 2.6 m high; the north gap, 1.2 m at (5.0, 8.3), facing north, open to the sky.
    Decided before the run: ONE opening at the lych gate (the stone stands inside the piece and parts the way into
    two lanes 0.9 m wide, each wider than the agent), nothing at the stone's sides or ends."""
    parts = room(10.0, 8.0, {"S": [(3.8, 6.2, 1.5)], "N": [(4.4, 5.6, 1.5)]}, height=1.5)
    parts += [box(3.6, 6.4, 2.6, 2.8, -0.3, 2.2), box(3.6, 3.8, 0.0, 2.6, 2.0, 2.2), box(6.2, 6.4, 0.0, 2.6, 2.0, 2.2),
              box(3.6, 3.8, 1.5, 2.6, -0.3, 0.0), box(6.2, 6.4, 1.5, 2.6, -0.3, 0.0),
              box(4.7, 5.3, 0.0, stone, 0.1, 1.9)]
    return _level("lych_gate_stone", parts,
                  [_opening((5.0, 0.0, -0.3), _S, 2.4), _opening((5.0, 0.0, 8.3), _N, 1.2)])


KINDS = kinds_by_name(cubicle_washroom, fanlight_over_door, cloister_garth, open_locker_corridor, glass_floor_span,
                      escalator_pair, cordonata_ramp, lych_gate_stone)
"""Kind name -> factory of the thirty-sixth round."""


if __name__ == "__main__":
    sys.exit(run_kinds(sys.argv[1:], kinds=KINDS, description=__doc__.splitlines()[0]))
