"""A room whose floor is cut by a gap just inside its east doorway, run through both map-piece routes (review54 LOW 3).

Run: ``.venv/bin/python benchmarks/cut_doorways.py [--kinds cut_0.3 ...] [--configs map_piece map_piece_sampling]
[--yaws 0 22 45] [--detail] [--one-to-one]``

Room 8 x 6 m (clear x 0-8, z 0-6), walls 0.3 m thick and 3 m high, 1.6 m doorways in the middle of its west and east
walls (z 2.2-3.8, lintels 2.2 m): :data:`piece_parts.ROOM_DOORS`. Its floor slab (0.2 m thick, to the walls' outer
faces) is cut by a gap ``g`` m wide across the whole room, ending 0.1 m inside the east wall's inner face: the slabs
run x -0.3 to 7.9 - g and x 7.9 to 8.3, nothing under the gap. On the sampling route the graph steps over a gap
narrower than the builder's ``step_gap`` (its default, the agent's climb: 0.4 m), so the floor goes on across it:
known, the two doorways (1.6 m at (-0.3, 3.0) facing west and at (8.3, 3.0) facing east), at g 0 to 0.35. At 0.45
the gap is wider than the step gap and the east doorway lies beyond a slot the agent does not cross (the strip past
the gap, 0.1 m clear of the wall, holds no floor the agent stands on); the known openings stay the two the designer
built, so the table's score is read with the openings listed (``--detail``): a designer should see the west doorway
alone there, and both routes show the gap's edge as a 5-6 m opening instead. At 0.2-0.35 both routes find the east
doorway since the floor's end search steps over such a gap (``terminals.params.step_gap``; docs/entry_exit.md,
"Openings behind a gap the agent steps over"); before, the table counted the gap's edge as the east doorway. Built
with :mod:`piece_parts`, in the earlier rounds' conventions.
"""

from __future__ import annotations

import sys
from functools import partial

from piece_parts import ROOM_DOORS, ROOM_OPENINGS, SLAB, box, room, round_level, run_kinds

from g2s_plugins.samples.levels import SampleLevel

_level = round_level(55)

GAPS = (0.0, 0.2, 0.3, 0.35, 0.45)
"""The gaps' widths, m: none, three under the sampling presets' step gap (0.4 m) and one over it."""


def cut_doorway(gap: float = 0.3) -> SampleLevel:
    """:func:`piece_parts.room` 8 x 6 m with :data:`piece_parts.ROOM_DOORS`, its floor cut by a gap ``gap`` m wide
    ending 0.1 m inside the east wall (see the module doc); ``gap`` 0: the floor whole."""
    walls = room(8.0, 6.0, ROOM_DOORS)[1:]  # the room's own slab is replaced by the two below
    floor = [box(-0.3, 8.3, -SLAB, 0.0, -0.3, 6.3)] if gap <= 0 else [
        box(-0.3, 7.9 - gap, -SLAB, 0.0, -0.3, 6.3), box(7.9, 8.3, -SLAB, 0.0, -0.3, 6.3)]
    return _level(f"cut_doorway_{gap:g}", walls + floor, ROOM_OPENINGS)


KINDS = {f"cut_{gap:g}": partial(cut_doorway, gap) for gap in GAPS}

if __name__ == "__main__":
    sys.exit(run_kinds(kinds=KINDS, description=__doc__.splitlines()[0]))
