"""Steps a little over and under the agent's climb: which routes climb them (docs/navmesh.md, "The climb at every
alignment").

Three generated cases, each turned by ``yaw`` about the vertical and its floors raised by ``lift`` over the slabs'
common underside (the level's lowest point, where Recast's grid starts), so that the lower floor lies on or off a
multiple of the cell height: ``step`` (two open pads 5 x 5 m, the second ``h`` higher, side by side), ``flight`` (the
pads joined by three risers of ``h``, treads 1 m deep, 5 m wide) and ``table`` (a platform 4 x 4 m, ``h`` high, in
the middle of a floor 12 x 12 m: the canteen's table over its bench). A case is climbed by the navmesh when a Detour
ray from the lower floor's middle reaches the upper's; by the sampling route when its graph joins the samples nearest
them (``benchmarks/head_room.py``'s tests, imported). Built from ``benchmarks/piece_parts.py``'s solids. O(cases)
builds, each a few dozen triangles.

Run: ``.venv/bin/python benchmarks/climb_steps.py [--presets map_analysis map_piece] [--no-sampling] [--rows]``;
prints, per preset and kind, the cases climbed of 12 (3 turns x 4 alignments) at each step height for the navmesh
and the sampling route, and the designer's answer (h <= the agent's climb); ``--rows`` prints every case too.
"""

from __future__ import annotations

import itertools
import math
from collections import defaultdict

import numpy as np
import trimesh
from head_room import case_parser, sweep
from piece_parts import box, flight


KINDS = ("step", "flight", "table")
HEIGHTS = (0.30, 0.325, 0.35, 0.36, 0.37, 0.38, 0.39, 0.40, 0.41, 0.42, 0.43, 0.44, 0.45, 0.475, 0.50)

BASE = -0.5
"""Every slab's underside: the level's lowest point, where Recast's grid starts."""

PAD, TREAD, RISERS, FLOOR, TABLE = 5.0, 1.0, 3, 12.0, 4.0


def case_mesh(kind: str, h: float, yaw_deg: float = 0.0, lift: float = 0.0) -> tuple[trimesh.Trimesh, np.ndarray]:
    """The case ``kind`` with steps of ``h`` m, turned by ``yaw_deg`` and its floors raised by ``lift`` (m) over the
    slabs' underside (kept at :data:`BASE`). Returns the mesh and the lower and upper floors' middles ((2, 3), m)."""
    if kind == "step":
        parts = [box(-PAD, 0.0, BASE, 0.0, 0.0, PAD), box(0.0, PAD, BASE, h, 0.0, PAD)]
        mids = [[-PAD / 2, 0.0, PAD / 2], [PAD / 2, h, PAD / 2]]
    elif kind == "flight":  # the lower pad, two treads (risers 1 and 2) and the upper pad on the third riser
        run = (RISERS - 1) * TREAD
        parts = [box(-PAD, 0.0, BASE, 0.0, 0.0, PAD), box(run, run + PAD, BASE, RISERS * h, 0.0, PAD)]
        parts += flight((0.0, 0.0), (1.0, 0.0), (0.0, PAD), RISERS - 1, TREAD, h, 0.0)
        mids = [[-PAD / 2, 0.0, PAD / 2], [run + PAD / 2, RISERS * h, PAD / 2]]
    elif kind == "table":
        half, top = FLOOR / 2, TABLE / 2
        parts = [box(-half, half, BASE, 0.0, -half, half), box(-top, top, 0.0, h, -top, top)]
        mids = [[-(half + top) / 2, 0.0, 0.0], [0.0, h, 0.0]]
    else:
        raise ValueError(f"unknown kind {kind!r}; expected one of {KINDS}")
    mesh = trimesh.util.concatenate(parts)
    mesh.merge_vertices()
    lifted = mesh.vertices.copy()
    lifted[:, 1] = np.where(lifted[:, 1] > BASE + 1e-9, lifted[:, 1] + lift, lifted[:, 1])
    ends = np.array(mids)
    ends[:, 1] += lift
    turn = trimesh.transformations.rotation_matrix(math.radians(yaw_deg), [0.0, 1.0, 0.0])[:3, :3]
    return trimesh.Trimesh(lifted @ turn.T, mesh.faces, process=False), ends @ turn.T


def main() -> None:
    parser = case_parser(__doc__.splitlines()[0], KINDS, "heights", HEIGHTS)
    parser.add_argument("--rows", action="store_true", help="print every case, not only the counts")
    args = parser.parse_args()
    turns = len(args.yaws) * len(args.lifts)
    for preset, cases in itertools.groupby(sweep(args, args.heights, case_mesh), key=lambda case: case[0]):
        counts: dict[tuple[str, float], list[int]] = defaultdict(lambda: [0, 0])
        for _, config, kind, h, yaw, lift, nav, samp in cases:
            counts[kind, h][0] += nav
            counts[kind, h][1] += bool(samp)
            if args.rows:
                print(f"{preset} {kind} {h:.3f} {yaw:g} {lift:g} navmesh {'yes' if nav else 'no'} "
                      f"sampling {'-' if samp is None else 'yes' if samp else 'no'}", flush=True)
        climb = config.agent.max_climb
        print(f"{preset} (climb {climb:g} m): climbed of {turns}, navmesh / sampling")
        print("| kind | " + " | ".join(f"{h:.3f}" for h in args.heights) + " |")
        print("| --- |" + " ---: |" * len(args.heights))
        for kind in args.kinds:
            cells = (f"{counts[kind, h][0]}" + ("" if args.no_sampling else f" / {counts[kind, h][1]}")
                     for h in args.heights)
            print(f"| {kind} | " + " | ".join(cells) + " |")
        print("| designer | " + " | ".join(f"{turns if h <= climb + 1e-9 else 0}" for h in args.heights) + " |",
              flush=True)


if __name__ == "__main__":
    main()
