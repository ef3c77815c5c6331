"""An opening's width and height as a designer reads them, against what both map-piece routes report.

Run: ``.venv/bin/python benchmarks/opening_measures.py [--cases a b] [--configs map_piece map_piece_sampling]
[--yaws 0 22 45]``

A designer sizes a doorway by its narrowest clear width through the wall (a reveal splaying out to the face, a
stop in the wall's middle, a round tower's radial jambs) and sets it on its own floor (a doorway steps down or up
from the room). Each case below is a room 8 x 6 m with a 1.6 m doorway west and the case's doorway east (the round
tower excepted), with the true width and floor height of each doorway; per case, preset and yaw (the piece turned
about its vertical centre line, :func:`g2s_plugins.samples.pieces.turned`) it prints, for each known opening, the
reported width and midpoint height of the detected opening within
:data:`~g2s_plugins.samples.pieces.MATCH_DISTANCE` of it ("missed" when none). Figures are recorded in
docs/entry_exit.md, "An opening's width and height as a designer reads them".
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable
from dataclasses import replace

import numpy as np
from piece_kinds21 import round_tower_doors, stepped_wall_passage
from piece_kinds22 import _east_wall_removed, battered_wall_door, splayed_reveal_door, sunken_doorway_steps
from piece_parts import ROOM_DOORS, ROOM_OPENINGS, SLAB, box, prism, room, round_level

from g2s_core import pipeline
from g2s_core.config import PRESETS_DIR, load_config
from g2s_core.mesh import mesh_sha256
from g2s_core.registry import Registry
from g2s_plugins.samples import pieces
from g2s_plugins.samples.levels import SampleLevel, _opening
from g2s_plugins.samples.pieces import _E

_level = round_level(23)


def _thick_east_wall(way: list[tuple[float, float]], north: list[tuple[float, float]],
                     south: list[tuple[float, float]]) -> list:
    """A room 8 x 6 m (1.6 m doorway W) whose east wall is 1 m thick (x 8.0-9.0): prisms over the plan polygons
    ``north`` and ``south`` ((x, z) corners) from the slab's bottom to 3 m, the way ``way`` between them floored and
    under a 2.2 m lintel."""
    parts = _east_wall_removed(room(8.0, 6.0, ROOM_DOORS))
    return parts + [prism(north, -SLAB, 3.0), prism(south, -SLAB, 3.0), prism(way, 2.2, 3.0), prism(way, -SLAB, 0.0)]


def thick_wall_door() -> SampleLevel:
    """The east wall 1 m thick (x 8.0-9.0), a 1.2 m doorway straight through it (z 2.4-3.6). Known: both, the east
    one at the outer face, 1.2 m."""
    parts = _thick_east_wall([(8.0, 2.4), (9.0, 2.4), (9.0, 3.6), (8.0, 3.6)],
                             [(8.0, 3.6), (9.0, 3.6), (9.0, 6.3), (8.0, 6.3)],
                             [(8.0, -0.3), (9.0, -0.3), (9.0, 2.4), (8.0, 2.4)])
    return _level("thick_wall_door", parts, [ROOM_OPENINGS[0], _opening((9.0, 0.0, 3.0), _E, 1.2)])


def inward_splayed_door() -> SampleLevel:
    """:func:`splayed_reveal_door` turned inside out: the east wall 1 m thick, its doorway 1.2 m wide at the outer
    face (z 2.4-3.6) splaying to 2.2 m at the inner (z 1.9-4.1). Known: both, the east one at the outer face,
    1.2 m."""
    parts = _thick_east_wall([(8.0, 1.9), (9.0, 2.4), (9.0, 3.6), (8.0, 4.1)],
                             [(8.0, 4.1), (9.0, 3.6), (9.0, 6.3), (8.0, 6.3)],
                             [(8.0, -0.3), (9.0, -0.3), (9.0, 2.4), (8.0, 1.9)])
    return _level("inward_splayed_door", parts, [ROOM_OPENINGS[0], _opening((9.0, 0.0, 3.0), _E, 1.2)])


def rebated_door() -> SampleLevel:
    """The east wall 1 m thick, its doorway 1.6 m wide at both faces (z 2.2-3.8) with a stop in the wall's middle
    (x 8.4-8.6) narrowing it to 1.2 m (z 2.4-3.6), full height. Known: both, the east one at the outer face,
    1.2 m (the clear width past the stop)."""
    parts = _thick_east_wall([(8.0, 2.2), (9.0, 2.2), (9.0, 3.8), (8.0, 3.8)],
                             [(8.0, 3.8), (9.0, 3.8), (9.0, 6.3), (8.0, 6.3)],
                             [(8.0, -0.3), (9.0, -0.3), (9.0, 2.2), (8.0, 2.2)])
    parts += [box(8.4, 8.6, 0.0, 2.2, 2.2, 2.4), box(8.4, 8.6, 0.0, 2.2, 3.6, 3.8)]
    return _level("rebated_door", parts, [ROOM_OPENINGS[0], _opening((9.0, 0.0, 3.0), _E, 1.2)])


def raised_doorway_steps() -> SampleLevel:
    """:func:`sunken_doorway_steps` the other way up: the east doorway (z 2.2-3.8) three 0.15 m steps up, treads
    0.5 m deep at 0.15, 0.30 and 0.45 m (x 6.5-7.0, 7.0-7.5, 7.5-8.3, the last through the wall) between cheeks
    up to 0.45 m, under a lintel 2.65 m over the room's floor (2.2 m over the top tread). Known: both, the east one at
    the top tread (y 0.45)."""
    parts = room(8.0, 6.0, {"W": [(2.2, 3.8, 2.2)], "E": [(2.2, 3.8, 2.65)]})
    parts += [box(x0, x1, 0.0, top, 2.2, 3.8) for x0, x1, top in ((6.5, 7.0, 0.15), (7.0, 7.5, 0.30), (7.5, 8.3, 0.45))]
    return _level("raised_doorway_steps", parts, [ROOM_OPENINGS[0], _opening((8.3, 0.45, 3.0), _E, 1.6)])


def _round_tower_narrowest() -> SampleLevel:
    """:func:`round_tower_doors` with its known widths the narrowest chord between the radial jambs (at the inner
    face, radius 2.5 m: 2 x 2.5 x 0.8 / 3.0 = 1.33 m) in place of the outer face's 1.6 m."""
    level = round_tower_doors()
    inner_chord = 2.0 * 2.5 * 0.8 / 3.0
    return replace(level, openings=tuple(replace(o, width=inner_chord) for o in level.openings))


CASES: dict[str, Callable[[], SampleLevel]] = {
    "splayed_reveal_door": splayed_reveal_door,
    "inward_splayed_door": inward_splayed_door,
    "thick_wall_door": thick_wall_door,
    "rebated_door": rebated_door,
    "round_tower_doors": _round_tower_narrowest,
    "battered_wall_door": battered_wall_door,
    "sunken_doorway_steps": sunken_doorway_steps,
    "raised_doorway_steps": raised_doorway_steps,
    "stepped_wall_passage": stepped_wall_passage,
}
"""Case name -> factory; each level's known openings carry the true width and floor height."""


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cases", nargs="+", choices=sorted(CASES), default=list(CASES))
    parser.add_argument("--configs", nargs="+", default=["map_piece", "map_piece_sampling"])
    parser.add_argument("--yaws", type=float, nargs="+", default=[0.0, 22.0, 45.0])
    args = parser.parse_args(argv)
    registry = Registry.from_entry_points()
    for config in args.configs:
        plan = pipeline.plan(load_config(PRESETS_DIR / f"{config}.yaml"), registry)
        print(f"{config}: case, known opening (true width m, floor y m) -> per yaw reported width, midpoint y")
        for name in args.cases:
            rows: dict[int, list[str]] = {}
            for yaw in args.yaws:
                level = CASES[name]()
                level = pieces.turned(level, yaw) if yaw else level
                result = pipeline.run(plan, registry, level.mesh, name, mesh_sha256(level.mesh))
                openings = list(result.terminals.openings) if result.terminals is not None else []
                found = np.array([o.position for o in openings], dtype=np.float64).reshape(-1, 3)
                for i, known in enumerate(level.openings):
                    gaps = np.linalg.norm(found - np.asarray(known.position), axis=1)
                    if not len(gaps) or gaps.min() > pieces.MATCH_DISTANCE:
                        rows.setdefault(i, []).append("missed")
                        continue
                    o = openings[int(np.argmin(gaps))]
                    rows.setdefault(i, []).append(f"{o.width:.2f} {o.position[1]:+.2f}")
            for i, known in enumerate(CASES[name]().openings):
                print(f"  {name:22s} {i} ({known.width:.2f}, {known.position[1]:+.2f}) -> {'; '.join(rows[i])}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
