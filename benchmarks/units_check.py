"""Does the units check tell a level in centimetres from a large level in metres? Its confusion table.

Run: ``.venv/bin/python benchmarks/units_check.py [--groups ...] [--kinds subway ...] [--seeds 0 1 2]``

For every sample level (:data:`g2s_plugins.samples.levels.SAMPLES`), every level kind of
``benchmarks/level_kinds.py`` (seeds 0-2), ``../shared/data/nav_test.obj`` and the two shared pieces, big
terrains (the ``terrain`` sample 450 and 1,000 m across, and 3 km across in cells of 10 m) and open levels 2-5 km
across in metres (:func:`open_city`: box buildings on a street grid, with flights of steps or without, low ones, and
towers 50-300 m tall), it reads :func:`g2s_plugins.units_check.storey_gap` on the level as made (metres) and
scaled by 39.37 (inches), 100 (centimetres) and 1000 (millimetres), and counts per group how often the check
warns (the gap over :data:`~g2s_plugins.units_check.MAX_STOREY_HEIGHTS` times the presets' agent height of 2 m)
and how often it cannot tell (one flat height or none). It prints the table, the levels in metres with the
largest gaps (the closest to a false warning) and those whose centimetre reading stays silent, then the CPU
seconds of the check on the 100k-polygon dungeon (``dungeon(seed=0, rooms=12000)``, 1.7 M faces). docs/errors.md
records its output.
"""

from __future__ import annotations

import argparse
import sys
import time
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import trimesh

from g2s_plugins.samples.levels import SAMPLES, dungeon, load_sample
from g2s_plugins.samples.outdoor import terrain
from g2s_plugins.units_check import MAX_STOREY_HEIGHTS, storey_gap

sys.path.insert(0, str(Path(__file__).parent))
import level_kinds  # noqa: E402

SHARED = Path(__file__).resolve().parents[1].parent / "shared" / "data"
AGENT_HEIGHT = 2.0
"""The presets' agent height, metres."""

SCALES = {"m": 1.0, "in": 39.37, "cm": 100.0, "mm": 1000.0}
"""The units a level is read from, as the factor from metres to them."""


def box(low: tuple[float, float, float], high: tuple[float, float, float]) -> trimesh.Trimesh:
    """A closed box between two corners, metres."""
    low_, high_ = np.asarray(low, dtype=float), np.asarray(high, dtype=float)
    return trimesh.creation.box(extents=high_ - low_, transform=trimesh.transformations.translation_matrix((low_ + high_) / 2))


def open_city(size: float, blocks: int, low: float, high: float, stairs: bool, seed: int) -> trimesh.Trimesh:
    """An open level ``size`` m square in metres: a ground slab 1 m thick, a ``blocks`` x ``blocks`` street grid
    whose blocks hold (three in four) a box building ``low`` to ``high`` m tall and 0.3 to 0.8 of the block wide,
    and with ``stairs`` beside three buildings in ten a flight of ten 0.18 m steps."""
    rng = np.random.default_rng(seed)
    parts = [box((0, -1, 0), (size, 0, size))]
    pitch = size / blocks
    for i in range(blocks):
        for j in range(blocks):
            if rng.random() < 0.25:
                continue
            width, depth = rng.uniform(0.3, 0.8, 2) * pitch
            height = rng.uniform(low, high)
            x, z = (i + 0.5) * pitch, (j + 0.5) * pitch
            parts.append(box((x - width / 2, 0, z - depth / 2), (x + width / 2, height, z + depth / 2)))
            if stairs and rng.random() < 0.3:
                parts += [box((x + width / 2 + 0.5, 0, z - 3 + 0.3 * k), (x + width / 2 + 3.5, 0.18 * (k + 1), z - 2.7 + 0.3 * k))
                          for k in range(10)]
    return trimesh.util.concatenate(parts)


GROUPS = ("sample levels", "level kinds", "nav_test, pieces", "big terrains", "open levels 2-5 km")
"""The table's rows."""


def levels(groups: list[str], kinds: list[str], seeds: list[int]) -> Iterator[tuple[str, str, trimesh.Trimesh]]:
    """(group, name, mesh in metres) of every level of ``groups`` the table counts."""
    if GROUPS[0] in groups:
        for name in SAMPLES:
            yield GROUPS[0], name, load_sample(name).mesh
    if GROUPS[1] in groups:
        for kind in kinds:
            for seed in seeds:
                yield GROUPS[1], f"{kind} s{seed}", level_kinds.KINDS[kind](seed)
    if GROUPS[2] in groups:
        for name in ("nav_test.obj", "pieces/Hallway.obj", "pieces/Ramp.obj"):
            yield GROUPS[2], name, trimesh.load(SHARED / name, force="mesh", process=False)
    if GROUPS[3] in groups:
        yield GROUPS[3], "terrain 450 m", terrain(size=450.0).mesh
        yield GROUPS[3], "terrain 1000 m", terrain(size=1000.0).mesh
        yield GROUPS[3], "terrain 3 km, cells of 10 m", terrain(size=3000.0, cell=10.0, relief=30.0, obstacles=0.02).mesh
    if GROUPS[4] in groups:
        yield GROUPS[4], "city 3 km", open_city(3000.0, 30, 4.0, 60.0, True, 0)
        yield GROUPS[4], "city 3 km, no steps", open_city(3000.0, 30, 4.0, 60.0, False, 0)
        yield GROUPS[4], "city 2 km, low", open_city(2000.0, 40, 3.0, 12.0, True, 2)
        yield GROUPS[4], "city 5 km, towers 50-300 m", open_city(5000.0, 25, 50.0, 300.0, False, 1)


def scaled(mesh: trimesh.Trimesh, factor: float) -> trimesh.Trimesh:
    """``mesh`` read from a file in units ``factor`` times smaller than metres."""
    return trimesh.Trimesh(np.asarray(mesh.vertices) * factor, np.asarray(mesh.faces), process=False)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--groups", nargs="+", default=list(GROUPS), choices=GROUPS)
    parser.add_argument("--kinds", nargs="+", default=list(level_kinds.KINDS), choices=list(level_kinds.KINDS))
    parser.add_argument("--seeds", nargs="+", type=int, default=[0, 1, 2])
    args = parser.parse_args()
    limit = MAX_STOREY_HEIGHTS * AGENT_HEIGHT
    counts: dict[str, dict[str, list[int]]] = {}  # group -> units -> [warned, silent, cannot tell]
    metres: list[tuple[float, str]] = []
    silent_cm: list[tuple[float, str]] = []
    for group, name, mesh in levels(args.groups, args.kinds, args.seeds):
        gaps = {units: storey_gap(scaled(mesh, factor)) for units, factor in SCALES.items()}
        print(f"{group}: {name}: " + ", ".join(f"{units} {gap if gap is None else f'{gap:.3g}'}" for units, gap in gaps.items()),
              flush=True)
        for units, gap in gaps.items():
            cell = counts.setdefault(group, {}).setdefault(units, [0, 0, 0])
            cell[2 if gap is None else 0 if gap > limit else 1] += 1
            if units == "m" and gap is not None:
                metres.append((gap, f"{group}: {name}"))
            if units == "cm" and gap is not None and gap <= limit:
                silent_cm.append((gap, f"{group}: {name}"))
    print(f"warns when the gap is over {limit:g} m ({MAX_STOREY_HEIGHTS:g} agent heights of {AGENT_HEIGHT:g} m)\n")
    print("| levels | " + " | ".join(f"{units} (x{factor:g}): warned / silent / cannot tell" for units, factor in SCALES.items()) + " |")
    print("|---|" + "---|" * len(SCALES))
    for group, by_units in counts.items():
        print(f"| {group} | " + " | ".join("{} / {} / {}".format(*by_units[units]) for units in SCALES) + " |")
    print("\nlargest gaps in metres:", ", ".join(f"{name} {gap:.3g} m" for gap, name in sorted(metres)[-8:]))
    print(f"silent in centimetres ({len(silent_cm)}):", ", ".join(f"{name} {gap:.3g} m" for gap, name in sorted(silent_cm)))
    mesh = dungeon(seed=0, rooms=12000).mesh
    start = time.process_time()
    gap = storey_gap(mesh)
    print(f"\n100k-polygon dungeon ({len(mesh.faces):,} faces): gap {gap} m, {time.process_time() - start:.3f} s of CPU")


if __name__ == "__main__":
    main()
