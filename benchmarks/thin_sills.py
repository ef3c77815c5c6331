"""Thin sills, steps and stairs a little under and over the agent's climb: which walks the sampling route's walk test
lets across them (docs/sampling.md, "Thin sills between the climb and the knee").

Each case is a floor (a slab 8 x 8 m, its top at 0) and, across the middle of it, turned by ``yaw`` about the vertical
through the origin: a ``sill`` (a box ``h`` m high and ``thickness`` m thick along the walks, 8 m long), a ``step``
(the floor beyond x = 0 raised by ``h``) or a ``stair`` (three risers of ``h``, treads 0.3 m, then a landing). The
walks run 1 m along x at z = 0 across it, from 26 starts 0.01 m apart (the probes' 0.25 m step covered at every
phase), and are asked of :func:`g2s_plugins._raycasting.walks_in_batch` as the sampling builder asks its edges: the
preset's agent and probe step, a band ``half_width`` 0.45 m (the builder's ``DISK_SHARE`` x clearance) and the
body's slab. The designer's answer: a sill, step or riser up to the agent's climb is crossed, one over the climb is
not; the navmesh route's ``climb: agent`` has a band of one cell height (0.025 m) over it, where either answer
passes. O(cases) ray casters, each a few dozen triangles.

Run: ``.venv/bin/python benchmarks/thin_sills.py [--preset map_analysis_sampling] [--heights ...] [--yaws ...]``;
prints, per kind and thickness, the walks crossed of 26 at each height and yaw, and the cases against the designer
(crossed over the climb + 0.025 m, or stopped up to the climb).
"""

from __future__ import annotations

import argparse
import itertools
import math

import numpy as np
import trimesh

from g2s_core.config import PRESETS_DIR, load_config
from g2s_plugins._raycasting import AgentShape, RayCaster, walks_in_batch
from g2s_plugins.graph_builders import sampling

KINDS = ("sill", "step", "stair")
HEIGHTS = (0.20, 0.30, 0.35, 0.38, 0.40, 0.41, 0.42, 0.425, 0.45, 0.50, 0.52)
THICKNESSES = (0.05, 0.12, 0.2, 0.3)
YAWS = (0.0, 22.0, 45.0)
OFFSETS = 0.01 * np.arange(26)
"""Where the walks start past -0.625 m: 26 starts 0.01 m apart, every phase of the 0.25 m probe step."""

LENGTH, HALF, BASE, TREAD, RISERS = 1.0, 4.0, -0.5, 0.3, 3
BAND = 0.45
"""The band's half width: the builder's DISK_SHARE (0.9) x the presets' clearance (0.5 m)."""
CLIMB_BAND = 0.025
"""Metres over the climb where either answer passes: the navmesh route's cell height under ``climb: agent``."""


def _slab(x0: float, x1: float, top: float, z0: float = -HALF, z1: float = HALF) -> trimesh.Trimesh:
    """A box over x [x0, x1], z [z0, z1] from the slabs' underside :data:`BASE` to ``top``."""
    box = trimesh.creation.box(extents=[x1 - x0, top - BASE, z1 - z0])
    box.apply_translation([(x0 + x1) / 2, (top + BASE) / 2, (z0 + z1) / 2])
    return box


def case(kind: str, h: float, thickness: float, yaw_deg: float) -> tuple[trimesh.Trimesh, np.ndarray, np.ndarray]:
    """The mesh of case ``kind`` (``h`` m high, a sill ``thickness`` m thick) turned by ``yaw_deg``, and the walks'
    starts and ends ((26, 3) ground points each, m)."""
    turn = trimesh.transformations.rotation_matrix(math.radians(yaw_deg), [0.0, 1.0, 0.0])
    floor = [_slab(-HALF, HALF, 0.0)]
    if kind == "sill":
        parts = [_slab(-thickness / 2, thickness / 2, h)]
    elif kind == "step":
        parts = [_slab(0.0, HALF, h)]
    elif kind == "stair":
        parts = [_slab(i * TREAD, HALF, (i + 1) * h) for i in range(RISERS)]
    else:
        raise ValueError(f"unknown kind {kind!r}; expected one of {KINDS}")
    for part in parts:
        part.apply_transform(turn)
    mesh = trimesh.util.concatenate(floor + parts)
    starts = np.zeros((len(OFFSETS), 3))
    starts[:, 0] = -(LENGTH / 2 + 0.125) + OFFSETS
    ends = starts + [LENGTH, 0.0, 0.0]
    for points in (starts, ends):  # the ground under each: the floor, or the step or tread it stands on
        along = points @ turn[:3, :3]  # into the case's own frame (the inverse of the turn)
        if kind == "step":
            points[:, 1] = np.where(along[:, 0] > 0.0, h, 0.0)
        elif kind == "stair":
            points[:, 1] = h * np.clip(np.floor(along[:, 0] / TREAD) + 1, 0, RISERS)
    return mesh, starts, ends


def crossed(preset: str, kind: str, h: float, thickness: float, yaw: float) -> int:
    """How many of the case's 26 walks the preset's walk test lets across."""
    config = load_config(PRESETS_DIR / f"{preset}.yaml")
    agent = AgentShape.from_config(config.agent)
    probe_step = sampling._resolve(sampling.Params(**config.graph.params), agent)[3]
    mesh, starts, ends = case(kind, h, thickness, yaw)
    ok, _ = walks_in_batch(RayCaster(mesh), starts, ends, agent, probe_step, half_width=BAND, body=True)
    return int(ok.sum())


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--preset", default="map_analysis_sampling")
    parser.add_argument("--kinds", nargs="+", default=list(KINDS), choices=KINDS)
    parser.add_argument("--heights", nargs="+", type=float, default=list(HEIGHTS))
    parser.add_argument("--thicknesses", nargs="+", type=float, default=list(THICKNESSES))
    parser.add_argument("--yaws", nargs="+", type=float, default=list(YAWS))
    args = parser.parse_args()
    climb = load_config(PRESETS_DIR / f"{args.preset}.yaml").agent.max_climb
    wrong = 0
    print(f"{args.preset} (climb {climb:g} m): walks crossed of {len(OFFSETS)}, at yaws {' / '.join(f'{y:g}' for y in args.yaws)}")
    print("| case | " + " | ".join(f"{h:.3f}" for h in args.heights) + " |")
    print("| --- |" + " ---: |" * len(args.heights))
    for kind in args.kinds:
        thicknesses = args.thicknesses if kind == "sill" else [0.0]
        for thickness in thicknesses:
            cells = []
            for h in args.heights:
                counts = [crossed(args.preset, kind, h, thickness, yaw) for yaw in args.yaws]
                if h <= climb + 1e-9:
                    wrong += sum(len(OFFSETS) - c for c in counts)
                elif h > climb + CLIMB_BAND + 1e-9:
                    wrong += sum(counts)
                cells.append(" / ".join(str(c) for c in counts))
            name = f"{kind} {thickness:g} m" if kind == "sill" else kind
            print(f"| {name} | " + " | ".join(cells) + " |", flush=True)
    cases = len(OFFSETS) * len(args.yaws) * len(args.heights) * (len(args.thicknesses) + len(args.kinds) - 1)
    print(f"walks against the designer: {wrong} of {cases}")


if __name__ == "__main__":
    main()
