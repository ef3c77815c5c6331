"""Turned doors in solo and tiled builds: how many open (docs/navmesh.md, "Doors at an angle to the grid").

Run: ``.venv/bin/python benchmarks/seam_doors.py [--doors 1.3 1.45 1.55 1.7] [--yaws 0 15 30 45]
[--tile-sizes 0 16 32]``. ``tests/test_turned_doors.py``'s room (a door in a 0.2 m wall, ``map_analysis``'s navmesh
and agent) at five places of its jambs on the grid (the test's three and two more), every door width and yaw, built
with each tile size (0: solo). With tiles of 16 and 32 cells a tile seam runs through the room's middle, so through
the door at 0 degrees. Prints each case whose tiled builds differ from the solo one, then the count of open doors per
tile size. A benchmark: nothing here asserts a target.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from tests.test_turned_doors import PLACES, door_open  # noqa: E402

MORE_PLACES = [(0.11, 0.19), (0.2, 0.22)]
"""Two places of the room's centre (x, z, m) besides the test's three."""


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--doors", nargs="+", type=float, default=[1.3, 1.45, 1.55, 1.7])
    ap.add_argument("--yaws", nargs="+", type=float, default=[0.0, 15.0, 30.0, 45.0])
    ap.add_argument("--tile-sizes", nargs="+", type=int, default=[0, 16, 32])
    a = ap.parse_args(argv)
    opened = dict.fromkeys(a.tile_sizes, 0)
    cases = 0
    for door in a.doors:
        for yaw in a.yaws:
            for place in PLACES + MORE_PLACES:
                row = {ts: door_open(door, yaw, place, tile_size=ts) for ts in a.tile_sizes}
                cases += 1
                for ts, is_open in row.items():
                    opened[ts] += is_open
                if len(set(row.values())) > 1:
                    print(f"door={door} yaw={yaw:g} place={place} " + " ".join(f"tile{ts}={int(v)}" for ts, v in row.items()),
                          flush=True)
    print(" ".join(f"tile{ts}: {n}/{cases} open" for ts, n in opened.items()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
