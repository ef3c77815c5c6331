"""Resident memory of every stage of a preset on a generated dungeon: where a run's peak is, and what each stage keeps.

Run: ``.venv/bin/python benchmarks/stage_memory.py [--rooms 12000] [--preset map_analysis_sampling]
[--mark module:function ...] [--tracemalloc 25]``

``samples.dungeon(seed=0, rooms=N)`` runs through the preset in this process, as ``benchmarks/stage_times.py``
runs it. A thread reads the process's resident set (``VmRSS`` of ``/proc/self/status``, Linux only) every
``--every`` seconds (0.05) and files each reading under the phase running then: the stage the pipeline's progress
callback last announced, or, inside a function named with ``--mark`` (e.g.
``g2s_plugins.graph_builders.sampling:moved_into_passages``), that function within its stage. Printed per phase,
in order: the resident set when it began, its highest reading and when it ended (what the phase left alive for
the next), GiB; then the process's ``VmHWM`` (the kernel's own peak, which a 50 ms sampler can miss by a
short-lived array).

With ``--tracemalloc N`` the run is traced (several times slower: use a small level) and printed per stage:
the Python-side peak (``tracemalloc``, numpy's arrays included) and, of the snapshot the sampler took at the
run's highest traced memory, the ``N`` source lines whose allocations were alive then, largest first.
This is a benchmark: nothing here asserts a size.
"""

from __future__ import annotations

import argparse
import functools
import importlib
import os
import platform
import sys
import threading
import time
import tracemalloc
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from g2s_core import pipeline
from g2s_core.config import find_config, load_config
from g2s_core.mesh import mesh_sha256
from g2s_core.registry import Registry
from g2s_core.stages import PIPELINE
from g2s_plugins.samples import levels as samples

STAGE_STARTS = {f"{stage.step}: {stage.label}" for stage in PIPELINE}
GIB = 2**30


def status_bytes(field_name: str) -> int:
    """One ``kB`` field of ``/proc/self/status`` (``VmRSS``, ``VmHWM``), in bytes."""
    with open("/proc/self/status", encoding="ascii") as status:
        for line in status:
            if line.startswith(field_name + ":"):
                return int(line.split()[1]) * 1024
    raise KeyError(field_name)


@dataclass
class Phase:
    """One phase's readings, bytes: the first, the highest and the last."""

    name: str
    start: int
    peak: int = 0
    end: int = 0
    traced_peak: int = 0


@dataclass
class Sampler:
    """Reads the resident set every ``every`` seconds on its own thread and files it under the current phase.

    With ``trace``, also snapshots ``tracemalloc`` whenever the traced memory passes its highest reading by
    ``trace_step`` bytes, keeping the last: the allocations alive near the run's traced peak.
    """

    every: float
    trace: bool = False
    trace_step: int = 64 * 2**20
    phases: list[Phase] = field(default_factory=list)
    stage: str = "start"
    peak_snapshot: tracemalloc.Snapshot | None = None
    _snapshot_at: int = 0
    _stop: threading.Event = field(default_factory=threading.Event)
    _lock: threading.Lock = field(default_factory=threading.Lock)

    def enter(self, name: str) -> None:
        """Begin phase ``name``; the current one ends (its last reading taken now)."""
        with self._lock:
            rss = status_bytes("VmRSS")
            if self.phases:
                self._close(self.phases[-1], rss)
            self.phases.append(Phase(name, rss, rss))
            if self.trace:
                tracemalloc.reset_peak()

    def _close(self, phase: Phase, rss: int) -> None:
        phase.end, phase.peak = rss, max(phase.peak, rss)
        if self.trace:
            phase.traced_peak = tracemalloc.get_traced_memory()[1]

    def read(self) -> None:
        with self._lock:
            if self.phases:
                self.phases[-1].peak = max(self.phases[-1].peak, status_bytes("VmRSS"))
        if self.trace and (traced := tracemalloc.get_traced_memory()[0]) > self._snapshot_at + self.trace_step:
            self.peak_snapshot, self._snapshot_at = tracemalloc.take_snapshot(), traced

    def run(self) -> None:
        while not self._stop.wait(self.every):
            self.read()

    def stop(self) -> None:
        self._stop.set()
        with self._lock:
            self._close(self.phases[-1], status_bytes("VmRSS"))


def marked(sampler: Sampler, function: Callable[..., Any], name: str) -> Callable[..., Any]:
    """``function`` wrapped so that the sampler files its readings under ``name`` (then back to its caller's)."""

    @functools.wraps(function)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        sampler.enter(f"  {name}")
        try:
            return function(*args, **kwargs)
        finally:
            sampler.enter(f"  (rest of {sampler.stage})")

    return wrapper


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rooms", type=int, default=12000)
    parser.add_argument("--preset", default="map_analysis_sampling", help="a preset name or a config file")
    parser.add_argument("--every", type=float, default=0.05, help="seconds between readings")
    parser.add_argument("--mark", action="append", default=[], help="module:function to time as a phase of its own")
    parser.add_argument("--tracemalloc", type=int, default=0, metavar="N", help="trace; print the N largest lines")
    args = parser.parse_args()
    registry = Registry.from_entry_points()
    plan = pipeline.plan(load_config(find_config(args.preset)), registry, args.preset)
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}; "
          f"preset {args.preset}, dungeon of {args.rooms} rooms")
    sampler = Sampler(args.every, trace=args.tracemalloc > 0)
    for target in args.mark:
        module_name, attribute = target.split(":")
        original = getattr(importlib.import_module(module_name), attribute)
        wrapped = marked(sampler, original, attribute)
        for module in list(sys.modules.values()):  # the modules that imported it by name too
            if getattr(module, attribute, None) is original:
                setattr(module, attribute, wrapped)
    if sampler.trace:
        tracemalloc.start()
    sampler.enter("mesh")
    mesh = samples.dungeon(seed=0, rooms=args.rooms).mesh
    thread = threading.Thread(target=sampler.run, daemon=True)
    thread.start()
    load, start = os.getloadavg()[0], time.perf_counter()

    def progress(message: str) -> None:
        if message in STAGE_STARTS:
            sampler.stage = str(message)
            sampler.enter(sampler.stage)

    result = pipeline.run(plan, registry, mesh, f"dungeon_{args.rooms}", mesh_sha256(mesh), progress=progress)
    sampler.stop()
    thread.join()
    wall = time.perf_counter() - start
    print(f"{len(result.graph)} nodes, {result.graph.number_of_edges()} edges; {wall:.1f} s wall, "
          f"load average {load:.1f} -> {os.getloadavg()[0]:.1f}")
    traced = "   traced peak" if sampler.trace else ""
    print(f"{'phase':<44} {'start':>7} {'peak':>7} {'end':>7}{traced}   (GiB, resident)")
    for phase in sampler.phases:
        row = f"{phase.name:<44} {phase.start / GIB:7.2f} {phase.peak / GIB:7.2f} {phase.end / GIB:7.2f}"
        print(row + (f"   {phase.traced_peak / GIB:11.2f}" if sampler.trace else ""))
    print(f"VmHWM (the kernel's peak resident set): {status_bytes('VmHWM') / GIB:.2f} GiB")
    if sampler.peak_snapshot is not None:
        stats = sampler.peak_snapshot.statistics("lineno")
        total = sum(stat.size for stat in stats)
        print(f"alive at the traced peak: {total / GIB:.2f} GiB in {sum(stat.count for stat in stats)} blocks; largest:")
        for stat in stats[: args.tracemalloc]:
            frame = stat.traceback[0]
            print(f"  {stat.size / 2**20:9.1f} MiB {stat.count:10d} blocks  {frame.filename}:{frame.lineno}")


if __name__ == "__main__":
    main()
