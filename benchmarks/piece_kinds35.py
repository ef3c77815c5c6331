"""A thirty-fifth round of map-piece kinds with their known openings, run through both map-piece routes.

Run: ``.venv/bin/python benchmarks/piece_kinds35.py [--kinds a b] [--configs map_piece map_piece_sampling] [--yaws 0
22 45] [--detail] [--one-to-one]``

Eight kinds of docs/entry_exit.md, "A thirty-fifth round of piece kinds", each with its known openings (count, place,
width, height, facing) written in its docstring before the detector first ran on them: the pieces of a level designer's
modular kit none of the earlier rounds built. A doorway with an open gutter across its floor just inside it; a flight
inside a room whose top step meets a door high in the end wall, no landing; a garage whose tilt-up door lies open as a
panel under the ceiling; a corridor whose way out weaves through two staggered barriers; a cell block's corridor with
barred cell fronts and open cell doors; an office tile of thin stud partitions with 0.9 m doors; a doorway whose two
jambs are of different depths; a hall with a stage across one end and a door at the back of the stage. Built with
:mod:`piece_parts`, in the earlier rounds' conventions.
"""

from __future__ import annotations

import sys

import numpy as np
from piece_parts import ROOM_DOORS, ROOM_OPENINGS, SLAB, box, flight, kinds_by_name, room, round_level, run_kinds

from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _N, _W

_level = round_level(35)


def gutter_inside_doorway(width: float = 0.3, depth: float = 0.3, sill: float = 0.0) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, 1.6 m doorways west and east (z 2.2-3.8,
    lintels 2.2 m); across the east doorway, just inside it against the wall's inner face, an open gutter ``width`` m
    (0.3) wide (x 7.7-8.0) and ``depth`` m (0.3) deep from z 2.0 to 4.0 (0.2 m past each jamb), its grate missing,
    its bottom closed; the floor a solid slab to the walls' outer faces, the doorway's floor through the wall at y 0.
    The agent (radius 0.4 m) steps over a gap this narrow at the floor's height (the product's step-gap rule: no floor
    is lost to a slot narrower than the agent, docs/entry_exit.md). Known: two, at the floor (y 0), 2.2 m high: the
    west doorway, 1.6 m at (-0.3, 3.0), facing west; the east one, 1.6 m at its outer face (8.3, 3.0), facing east.
    Not the gutter's lips (inside the piece). ``sill`` (m, within the climb): the doorway's floor beyond the gutter
    that much over the room's (its known opening's height stays the room floor's)."""
    g0 = 8.0 - width
    bottom = -depth - SLAB
    parts = room(8.0, 6.0, ROOM_DOORS)[1:]  # the walls, the floor built below round the gutter
    parts += [box(-0.3, g0, bottom, 0.0, -0.3, 6.3), box(g0, 8.3, bottom, 0.0, -0.3, 2.0),
              box(g0, 8.3, bottom, 0.0, 4.0, 6.3), box(8.0, 8.3, bottom, sill, 2.0, 4.0),
              box(g0, 8.0, bottom, -depth, 2.0, 4.0)]
    return _level("gutter_inside_doorway", parts, ROOM_OPENINGS)


def stair_to_high_door(steps: int = 6, riser: float = 0.2, tread: float = 0.3) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 4 m high, no roof, a 1.6 m west doorway at the floor
    (z 2.2-3.8, lintel 2.2 m); along the north wall a solid flight 1.2 m wide (z 4.8-6.0) of ``steps`` (6) risers of
    ``riser`` m (0.2) on ``tread`` m (0.3) treads rising east to the east wall's inner face (x 6.2-8.0), its top
    tread 1.2 m up and no landing: in the east wall over it a 1.2 m door (z 4.8-6.0) whose sill is flush with the top
    tread (1.2 m), under a lintel 2.2 m over the sill (3.4 m); nothing outside the wall. The flight's south side open
    over the room (a drop into the piece's own floor). Known: two: the west doorway, 1.6 m at (-0.3, 3.0) at y 0,
    facing west; the high door, 1.2 m at the wall's outer face (8.3, 5.4) at y 1.2, facing east, 2.2 m high. None
    along the flight's open side."""
    top = steps * riser
    x0 = 8.0 - steps * tread
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(-0.3, 6.3, 4.0)]}, height=4.0)  # east wall below
    parts += [box(8.0, 8.3, -SLAB, 4.0, -0.3, 4.8), box(8.0, 8.3, -SLAB, top, 4.8, 6.0),
              box(8.0, 8.3, top + 2.2, 4.0, 4.8, 6.0), box(8.0, 8.3, -SLAB, 4.0, 6.0, 6.3)]
    parts += flight((x0, 0.0), (1.0, 0.0), (4.8, 6.0), steps, tread, riser, 0.0)
    return _level("stair_to_high_door", parts, [ROOM_OPENINGS[0], _opening((8.3, top, 5.4), _E, 1.2)])


def tilt_up_garage_door(panel_at: float = 2.1, deep: float = 2.4) -> SampleLevel:
    """A garage (clear x 0-6, z 0-6), walls 0.3 m thick and 3 m high, no roof, floored to the walls' outer faces at
    y 0; in the west wall a 1.0 m door (z 2.5-3.5, lintel 2.2 m); in the east wall a 2.6 m garage doorway (z 1.7-4.3,
    lintel 2.4 m) whose tilt-up door stands open: its panel, 2.6 m wide and 0.05 m thick, lies level inside under
    the lintel, its underside ``panel_at`` m (2.1) up, from the wall's inner face ``deep`` m (2.4) into the garage
    (x 3.6-6.0), over the doorway's width; 0.1 m over the agent's 2.0 m. Known: two, at the floor (y 0): the west
    door, 1.0 m at (-0.3, 3.0), facing west, 2.2 m high; the garage doorway, 2.6 m at its outer face (6.3, 3.0),
    facing east, 2.4 m high at the face (``panel_at`` m under the panel just inside). With the panel's underside at
    or under the agent's 2.0 m height the agent cannot pass under it, and the garage doorway is no opening."""
    parts = room(6.0, 6.0, {"W": [(2.5, 3.5, 2.2)], "E": [(1.7, 4.3, 2.4)]})
    parts.append(box(6.0 - deep, 6.0, panel_at, panel_at + 0.05, 1.7, 4.3))
    garage = [_opening((6.3, 0.0, 3.0), _E, 2.6)] if panel_at > 2.0 else []
    return _level("tilt_up_garage_door", parts, [_opening((-0.3, 0.0, 3.0), _W, 1.0)] + garage)


def chicane_barrier_end(barrier: float = 1.1) -> SampleLevel:
    """Corridor 12 x 2.4 m (clear x 0-12, z 0-2.4), walls 0.3 m thick and 3 m high, open to the sky, both ends open,
    floor at y 0; two barriers across it 0.1 m thick and ``barrier`` m (1.1) high (over the 0.4 m climb), staggered
    as a kit's chicane: one from the south wall at x 7.95-8.05 over z 0-1.4, one from the north wall at x 9.45-9.55
    over z 1.0-2.4, leaving 1.0 m beside each and 1.4 m between them; the east end 2.45 m past the second. Known: two,
    at the floor, open to the sky, 2.4 m each: the west end at (0, 1.2), facing west; the east end at (12, 1.2),
    facing east. Not the gaps beside the barriers (inside the piece)."""
    parts = [box(0.0, 12.0, -SLAB, 0.0, -0.3, 2.7), box(0.0, 12.0, -SLAB, 3.0, -0.3, 0.0),
             box(0.0, 12.0, -SLAB, 3.0, 2.4, 2.7),
             box(7.95, 8.05, 0.0, barrier, 0.0, 1.4), box(9.45, 9.55, 0.0, barrier, 1.0, 2.4)]
    return _level("chicane_barrier_end", parts,
                  [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, 1.2), _E, 2.4)])


def cell_block_corridor(pitch: float = 0.15, bar: float = 0.04) -> SampleLevel:
    """A cell block's corridor 12 x 2.4 m (clear x 0-12, z 0-2.4), open to the sky, both ends open, floor at y 0; its
    south wall 0.3 m thick and 3 m high (z -0.3-0); along its north side three cells (clear z 2.5-4.8; x 0.3-3.9,
    4.1-7.9, 8.1-11.7), walled 0.3 m thick and 3 m high at their ends (x 0-0.3, 11.7-12.0) and back (z 4.8-5.1),
    parted by walls 0.2 m thick (x 3.9-4.1, 7.9-8.1); each cell's front a row of bars ``bar`` m (0.04) square at
    ``pitch`` m (0.15) centres (0.11 m clear, z 2.43-2.47) from the floor to a header 0.1 m deep (z 2.4-2.5) from
    2.2 to 3.0 m up, but for a 0.9 m cell door standing open (no leaf) in each front (x 1.6-2.5, 5.6-6.5, 9.6-10.5);
    the slab under the whole. Known: two, at the floor (y 0), 2.4 m each, open to the sky: the corridor's west end at
    (0, 1.2), facing west; its east end at (12, 1.2), facing east. Not the cell doors (they lead into closed cells of
    the piece), nothing along the bars."""
    parts = [box(0.0, 12.0, -SLAB, 0.0, -0.3, 5.1), box(0.0, 12.0, -SLAB, 3.0, -0.3, 0.0),
             box(0.0, 12.0, -SLAB, 3.0, 4.8, 5.1), box(0.0, 0.3, -SLAB, 3.0, 2.4, 4.8),
             box(11.7, 12.0, -SLAB, 3.0, 2.4, 4.8), box(3.9, 4.1, -SLAB, 3.0, 2.4, 4.8),
             box(7.9, 8.1, -SLAB, 3.0, 2.4, 4.8), box(0.3, 11.7, 2.2, 3.0, 2.4, 2.5)]
    for c0, c1, d0 in ((0.3, 3.9, 1.6), (4.1, 7.9, 5.6), (8.1, 11.7, 9.6)):
        for x in np.arange(c0 + pitch / 2, c1 - bar, pitch):
            if x + bar > d0 and x < d0 + 0.9:
                continue  # the open door
            parts.append(box(x, x + bar, 0.0, 2.2, 2.43, 2.47))
    return _level("cell_block_corridor", parts,
                  [_opening((0.0, 0.0, 1.2), _W, 2.4), _opening((12.0, 0.0, 1.2), _E, 2.4)])


def stud_partition_office(thin: float = 0.05, door: float = 0.9) -> SampleLevel:
    """An office tile (clear x 0-10, z 0-6) of stud partitions ``thin`` m (0.05) thick and 2.4 m high, no roof, on a
    slab to the outer partitions' outer faces, floor at y 0; a partition across it (x 4.975-5.025) making two rooms,
    with a ``door`` m (0.9) door (z 4.5-5.4); a ``door`` m door in the west partition (z 1.0-1.9) and one in the east
    partition (z 1.0-1.9); each door under a head 2.1 m up. Known: two, at the floor (y 0), 2.1 m high: the west door,
    ``door`` m at its outer face (-``thin``, 1.45), facing west; the east door, ``door`` m at (10 + ``thin``, 1.45),
    facing east. Not the door between the rooms (inside the piece)."""
    t, h = thin, 2.4
    d0, d1 = 1.0, 1.0 + door
    m0, m1 = 4.5, 4.5 + door
    parts = [box(-t, 10.0 + t, -SLAB, 0.0, -t, 6.0 + t), box(-t, 10.0 + t, -SLAB, h, -t, 0.0),
             box(-t, 10.0 + t, -SLAB, h, 6.0, 6.0 + t)]
    for x0, x1, (a0, a1) in ((-t, 0.0, (d0, d1)), (10.0, 10.0 + t, (d0, d1)), (5.0 - t / 2, 5.0 + t / 2, (m0, m1))):
        parts += [box(x0, x1, -SLAB, h, 0.0, a0), box(x0, x1, -SLAB, h, a1, 6.0), box(x0, x1, 2.1, h, a0, a1)]
    return _level("stud_partition_office", parts,
                  [_opening((-t, 0.0, (d0 + d1) / 2), _W, door), _opening((10.0 + t, 0.0, (d0 + d1) / 2), _E, door)])


def uneven_jamb_door(deep: float = 0.9) -> SampleLevel:
    """Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, a 1.6 m west doorway (z 2.2-3.8, lintel
    2.2 m); its east wall 0.3 m thick (x 8.0-8.3) south of a 1.6 m doorway (z 2.2-3.8, lintel 2.2 m over x 8.0-8.3)
    and ``deep`` m (0.9) thick north of it (x 8.0-8.9, z 3.8-6.3: a kit's service duct cased against the wall), so the
    doorway's north jamb runs 0.6 m past its south one; the slab under the walls' footprint, the doorway's floor
    ending at the thin wall's outer face (x 8.3). Known: two, at the floor (y 0), 2.2 m high: the west doorway, 1.6 m
    at (-0.3, 3.0), facing west; the east one, 1.6 m where its floor ends (8.3, 3.0), facing east."""
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(-0.3, 6.3, 3.0)]})  # the east wall built below
    parts += [box(8.0, 8.3, -SLAB, 3.0, -0.3, 2.2), box(8.0, 8.3, 2.2, 3.0, 2.2, 3.8),
              box(8.0, 8.0 + deep, -SLAB, 3.0, 3.8, 6.3)]
    return _level("uneven_jamb_door", parts, ROOM_OPENINGS)


def stage_back_door(stage: float = 0.9, steps: int = 5) -> SampleLevel:
    """A hall (clear x 0-10, z 0-6), walls 0.3 m thick and 4 m high, no roof, floor at y 0; across its east end a
    stage ``stage`` m (0.9) high (x 7-10, z 0-6, solid to the slab), reached by a flight 1.2 m wide (z 2.4-3.6) of
    ``steps`` (5) risers of ``stage`` / ``steps`` m (0.18) on 0.3 m treads rising east to the stage's front (x
    5.5-7.0), the stage's front open over the hall elsewhere (a 0.9 m drop into the piece). Doorways: 1.6 m in the
    west wall (z 2.2-3.8, lintel 2.2 m), 1.2 m in the north wall at the hall's floor (x 2.0-3.2, lintel 2.2 m), and a
    1.2 m door at the back of the stage in the east wall (z 2.4-3.6), its sill the stage's top, its lintel 2.2 m over
    it; the slab to the walls' outer faces. Known: three, 2.2 m high: the west doorway, 1.6 m at (-0.3, 3.0) at y 0,
    facing west; the north doorway, 1.2 m at (2.6, 6.3) at y 0, facing north; the stage door, 1.2 m at (10.3, 3.0)
    at y ``stage``, facing east. None along the stage's front."""
    tread = 0.3
    parts = room(10.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "N": [(2.0, 3.2, 2.2)], "E": [(-0.3, 6.3, 4.0)]}, height=4.0)
    parts += [box(10.0, 10.3, -SLAB, 4.0, -0.3, 2.4), box(10.0, 10.3, -SLAB, stage, 2.4, 3.6),
              box(10.0, 10.3, stage + 2.2, 4.0, 2.4, 3.6), box(10.0, 10.3, -SLAB, 4.0, 3.6, 6.3),
              box(7.0, 10.0, -SLAB, stage, 0.0, 6.0)]
    parts += flight((7.0 - steps * tread, 0.0), (1.0, 0.0), (2.4, 3.6), steps, tread, stage / steps, 0.0)
    return _level("stage_back_door", parts,
                  [ROOM_OPENINGS[0], _opening((2.6, 0.0, 6.3), _N, 1.2), _opening((10.3, stage, 3.0), _E, 1.2)])


KINDS = kinds_by_name(gutter_inside_doorway, stair_to_high_door, tilt_up_garage_door, chicane_barrier_end,
                      cell_block_corridor, stud_partition_office, uneven_jamb_door, stage_back_door)
"""Kind name -> factory of the thirty-fifth round."""


def deep_gutter_doorway() -> SampleLevel:
    """Probe: ``gutter_inside_doorway`` with the gutter 0.35 m wide (x 7.65-8.0) and 1.0 m deep, its bottom beyond the
    0.4 m climb: the agent steps over a slot narrower than itself (0.8 m across) at the floor's height, so the
    known openings are the kind's two, 1.6 m each at (-0.3, 3.0) and (8.3, 3.0), at y 0."""
    return gutter_inside_doorway(width=0.35, depth=1.0)


def low_panel_garage() -> SampleLevel:
    """Probe: ``tilt_up_garage_door`` with the open panel's underside 1.9 m up, under the agent's 2.0 m: known, one,
    the west door, 1.0 m at (-0.3, 3.0) at y 0, facing west; not the garage doorway (the agent cannot stand under
    the panel that fills its inside 2.4 m deep)."""
    return tilt_up_garage_door(panel_at=1.9)


def shallow_tread_high_door() -> SampleLevel:
    """Probe: ``stair_to_high_door`` of 8 risers of 0.2 m on 0.25 m treads (x 6.0-8.0), the door's sill 1.6 m up,
    its top tread 0.25 m deep, less than the agent's 0.4 m radius: known, two, the west doorway, 1.6 m at (-0.3,
    3.0) at y 0, and the high door, 1.2 m at (8.3, 5.4) at y 1.6, facing east (the sill through the wall, 0.3 m,
    and the top tread make 0.55 m of level floor before the door's outer face)."""
    return stair_to_high_door(steps=8, tread=0.25)


def thinner_partition_office() -> SampleLevel:
    """Probe: ``stud_partition_office`` with partitions 0.02 m thick and 0.85 m doors, 0.05 m wider than the agent:
    known, two, 0.85 m each at (-0.02, 1.425) facing west and (10.02, 1.425) facing east, at y 0."""
    return stud_partition_office(thin=0.02, door=0.85)


PROBES = kinds_by_name(deep_gutter_doorway, low_panel_garage, shallow_tread_high_door, thinner_partition_office)
"""Kind name -> factory of the variants built to look for the kinds' limits (``--probes``; not the round's kinds)."""


if __name__ == "__main__":
    probes = "--probes" in sys.argv[1:]
    sys.exit(run_kinds([a for a in sys.argv[1:] if a != "--probes"], kinds=PROBES if probes else KINDS,
                       description=__doc__.splitlines()[0]))
