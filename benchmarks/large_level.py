"""A ~10M-triangle generated level through ``g2s run`` with default navmesh settings.

Run: ``.venv/bin/python benchmarks/large_level.py [--copies 31] [--rooms 74] [--config configs/graph_only.yaml]``

The level is ``copies x copies`` copies of ``samples.dungeon(seed=0, rooms=N)``
side by side (2 m apart), written as a binary PLY into a temporary folder; then
``g2s run CONFIG LEVEL -o OUT --json`` runs in a child process. Printed: the
level's size, the time to write it, the run's wall time, CPU time (user +
system, all threads; less sensitive to other jobs than wall time) and peak
memory (the child's maximum resident set size), and the run's own stage times. Mesh loading
is timed separately in this process. This is a benchmark, not a test: nothing
here asserts a time. Run it once or twice, not in a loop, on a shared machine.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import trimesh

from g2s_core.mesh import load_mesh
from g2s_plugins.samples import levels as samples

PROJECT = Path(__file__).resolve().parent.parent


def tiled_dungeon(copies: int, rooms: int, gap: float = 2.0) -> trimesh.Trimesh:
    """``copies x copies`` copies of one dungeon on a grid, ``gap`` metres apart."""
    base = samples.dungeon(seed=0, rooms=rooms).mesh
    pitch = base.extents[[0, 2]] + gap
    i, k = np.meshgrid(np.arange(copies), np.arange(copies), indexing="ij")
    offsets = np.zeros((copies * copies, 3))
    offsets[:, 0] = i.ravel() * pitch[0]
    offsets[:, 2] = k.ravel() * pitch[1]
    vertices = (base.vertices[None] + offsets[:, None]).reshape(-1, 3)
    faces = (base.faces[None] + (np.arange(len(offsets)) * len(base.vertices))[:, None, None]).reshape(-1, 3)
    return trimesh.Trimesh(vertices=vertices, faces=faces, process=False)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--copies", type=int, default=31, help="copies per side (default 31: 9.9M triangles)")
    parser.add_argument("--rooms", type=int, default=74, help="rooms of the copied dungeon")
    parser.add_argument("--config", default=str(PROJECT / "configs" / "graph_only.yaml"), help="run config")
    args = parser.parse_args()

    print(f"python {platform.python_version()}, {os.cpu_count()} cores, load average {os.getloadavg()[0]:.2f}")
    with tempfile.TemporaryDirectory() as tmp:
        t = time.perf_counter()
        mesh = tiled_dungeon(args.copies, args.rooms)
        path = Path(tmp) / "level.ply"
        mesh.export(path)
        print(f"level: {len(mesh.faces):,} triangles, {len(mesh.vertices):,} vertices, "
              f"{mesh.extents[0]:.0f} x {mesh.extents[2]:.0f} m, {path.stat().st_size / 2**20:.0f} MiB PLY, "
              f"made in {time.perf_counter() - t:.1f} s")
        del mesh

        t = time.perf_counter()
        load_mesh(path)
        print(f"load_mesh: {time.perf_counter() - t:.2f} s (in this process)")

        command = [sys.executable, "-m", "g2s_core.cli", "run", args.config, str(path), "-o", str(Path(tmp) / "out"),
                   "--json", "--format", "json"]
        t = time.perf_counter()
        proc = subprocess.run(command, capture_output=True, text=True, cwd=PROJECT)
        wall = time.perf_counter() - t
        usage = resource.getrusage(resource.RUSAGE_CHILDREN)
        peak = usage.ru_maxrss / 2**20  # KiB -> GiB
        cpu = usage.ru_utime + usage.ru_stime
        if proc.returncode != 0:
            sys.exit(f"g2s run failed ({proc.returncode}): {proc.stderr.strip()}")
        summary = json.loads(proc.stdout)
        print(f"g2s run {Path(args.config).name}: {wall:.1f} s wall, {cpu:.1f} s CPU, {peak:.2f} GiB peak RSS, "
              f"load average {os.getloadavg()[0]:.2f}")
        for stage in summary["stages"]:
            print(f"  {stage['stage']:<10} {stage['seconds']:8.2f} s  nodes={stage['nodes']} edges={stage['edges']}")


if __name__ == "__main__":
    main()
