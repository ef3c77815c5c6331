"""What the later rounds of map-piece kinds build with, in one module (``benchmarks/piece_kinds18.py`` onwards).

The tenth round's solids, room, table and runner (``benchmarks/piece_kinds10.py``), the fourteenth's corridor and
the fifteenth's prism, under the names the later rounds import, and the room with two doorways several rounds start
from. Conventions of those rounds: metres, Y up, X east, Z north; solids are convex hulls of their corners; floors'
tops at their height over slabs ``SLAB`` (0.2 m) thick; walls 0.3 m thick and 3 m high unless said.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import partial

from piece_kinds10 import SLAB as SLAB
from piece_kinds10 import _arc_band as arc_band
from piece_kinds10 import _box as box
from piece_kinds10 import _hull as hull
from piece_kinds10 import _level as _level10
from piece_kinds10 import _room as room
from piece_kinds10 import kinds_by_name as kinds_by_name
from piece_kinds10 import main as run_kinds
from piece_kinds14 import _corridor as corridor
from piece_kinds15 import _prism as prism

from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E, _W

__all__ = ["SLAB", "ROOM_DOORS", "ROOM_OPENINGS", "arc_band", "box", "corridor", "hull", "kinds_by_name", "prism",
           "room", "round_level", "run_kinds"]

ROOM_DOORS = {"W": [(2.2, 3.8, 2.2)], "E": [(2.2, 3.8, 2.2)]}
"""1.6 m doorways under 2.2 m lintels in the middle of the west and east walls of a room 6 m deep (:func:`room`)."""

ROOM_OPENINGS = [_opening((-0.3, 0.0, 3.0), _W, 1.6), _opening((8.3, 0.0, 3.0), _E, 1.6)]
""":data:`ROOM_DOORS`' openings in a room 8 x 6 m: at the walls' outer faces, at the floor's height."""


def round_level(round_: int) -> Callable[..., SampleLevel]:
    """The tenth round's piece builder (name, parts, known openings), tagging its pieces with ``round_``."""
    return partial(_level10, round_=round_)
