"""Where the wait of ``g2s run`` on a 100k-polygon OBJ goes: start-up, reading the mesh, the stages, the writers.

Run: ``.venv/bin/python benchmarks/end_to_end.py [--rooms 12000] [--preset map_analysis]
[--formats json,glb,graphml,html,png] [--skip-cli]``

``samples.dungeon(seed=0, rooms=N)`` (12,000 rooms: the 100k-polygon level of
docs/performance.md, 1.69 M triangles) is exported as an OBJ into a temporary
folder. Then, in a fresh child process (so that the imports count), the
phases of ``g2s run PRESET level.obj -o OUT --format json`` are timed one by
one with the functions the command calls: importing g2s and finding its
plugins, planning, :func:`g2s_core.api.open_mesh`, :func:`g2s_core.api.execute`
(split into its stages and the time outside them) and
:func:`g2s_core.api.write_result` for each of ``--formats``, each written
alone into its own folder. Last, unless ``--skip-cli``, the command itself
runs in a child process and its wall time is printed. Each phase gives its
wall and CPU time (the process's, both cores' worth for the stages); the
load average is printed before and after: figures taken under load are not
comparable, CPU times less so than wall times.

This is a benchmark, not a test: nothing here asserts a time.
"""

from __future__ import annotations

import argparse
import hashlib
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

PROJECT = Path(__file__).resolve().parent.parent


def phases(level: Path, preset: str, formats: list[str], outdir: Path) -> None:
    """Time each phase of a run of ``preset`` on ``level`` in this (fresh) process and print it."""
    start = time.perf_counter()
    from g2s_core import api, pipeline
    from g2s_core.config import resolve_config
    from g2s_core.registry import installed

    registry = installed()
    registry.plugins("outputs")
    report("import g2s_core + registry", start)

    start = time.perf_counter()
    config, source = resolve_config(preset, {})
    plan = pipeline.plan(config, registry, source=source)
    report("plan", start)

    start = time.perf_counter()
    mesh = api.open_mesh(level, config, registry=registry)
    report("api.open_mesh", start, f"{len(mesh.mesh.faces):,} triangles")

    start = time.perf_counter()
    result = api.execute(plan, registry, mesh)
    seconds = time.perf_counter() - start
    stages = sum(s.seconds for s in result.stages)
    report("api.execute", start, f"stages {stages:.2f} s, outside them {seconds - stages:.2f} s")

    for fmt in formats:
        start = time.perf_counter()
        written = api.write_result(result, outdir / fmt, fmt, registry=registry)
        sizes = ", ".join(f"{p.name} {p.stat().st_size / 2**20:.1f} MiB" for p in written)
        extra = ""
        if fmt == "json":
            extra = f", structure.json sha256 {hashlib.sha256((outdir / fmt / 'structure.json').read_bytes()).hexdigest()[:16]}"
        report(f"api.write_result {fmt}", start, sizes + extra)


def report(label: str, start: float, note: str = "") -> None:
    """Print ``label``'s wall time since ``start`` (``time.perf_counter``) and the CPU time since the last report."""
    global _cpu_start
    cpu, _cpu_start = time.process_time() - _cpu_start, time.process_time()
    print(f"  {label:<28} {time.perf_counter() - start:7.2f} s  CPU {cpu:6.2f} s   {note}", flush=True)


_cpu_start = time.process_time()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rooms", type=int, default=12000)
    parser.add_argument("--preset", default="map_analysis")
    parser.add_argument("--formats", default="json", help="writers to time one by one (default json)")
    parser.add_argument("--skip-cli", action="store_true", help="do not time the g2s command itself")
    parser.add_argument("--phases", type=Path, help=argparse.SUPPRESS)  # the child: the OBJ to time phases on
    args = parser.parse_args()
    formats = [f.strip() for f in args.formats.split(",") if f.strip()]
    if args.phases is not None:
        with tempfile.TemporaryDirectory() as out:
            phases(args.phases, args.preset, formats, Path(out))
        return

    from g2s_plugins.samples import levels as samples

    print(f"{os.cpu_count()} cores, load average {os.getloadavg()[0]:.2f}")
    with tempfile.TemporaryDirectory() as tmp:
        level = Path(tmp) / "level.obj"
        start = time.perf_counter()
        mesh = samples.dungeon(seed=0, rooms=args.rooms).mesh
        mesh.export(level)
        print(f"level: dungeon(seed=0, rooms={args.rooms}), {len(mesh.faces):,} triangles, "
              f"{level.stat().st_size / 2**20:.0f} MiB OBJ, made in {time.perf_counter() - start:.1f} s")
        del mesh
        print(f"phases of g2s run {args.preset} level.obj (one child process):")
        child = [sys.executable, __file__, "--phases", str(level), "--preset", args.preset, "--formats", args.formats]
        subprocess.run(child, check=True, cwd=PROJECT)
        if not args.skip_cli:
            command = [sys.executable, "-m", "g2s_core.cli", "run", args.preset, str(level), "-o", str(Path(tmp) / "out"),
                       "--format", "json", "-q"]
            start = time.perf_counter()
            subprocess.run(command, check=True, cwd=PROJECT)
            print(f"g2s run {args.preset} level.obj -o out --format json: {time.perf_counter() - start:.1f} s wall")
    print(f"load average {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
