"""Wall and CPU time of writing ``structure.json`` and ``run.json`` after a run on a generated dungeon.

Run: ``.venv/bin/python benchmarks/structure_write.py [--rooms 12000] [--preset map_analysis] [--repeat 3]``

``samples.dungeon(seed=0, rooms=N)`` (12,000 rooms: the 100k-polygon level
of docs/performance.md) runs through the preset once in this process; then
the JSON writer (``g2s_plugins.outputs.structure_json.write``, what ``g2s run
--format json`` calls) writes its files ``--repeat`` times into a temporary
folder. Each line gives the wall and CPU time of one write, the load average
and the first 16 hex digits of ``structure.json``'s SHA-256, which must not
change between runs or versions, then where the write's time goes, timed
apart with the collector paused as the writer pauses it: the CPU time of
building ``structure.json``'s document (``structure_document``) and of its
text (``dumps``); the rest is ``run.json`` and the files. This is a
benchmark: nothing here asserts a time.
"""

from __future__ import annotations

import argparse
import hashlib
import os
import tempfile
import time
from pathlib import Path

from g2s_core import pipeline
from g2s_core.config import PRESETS_DIR, load_config
from g2s_core.mesh import mesh_sha256
from g2s_core.registry import Registry
from g2s_plugins.outputs import structure_json
from g2s_plugins.outputs.writers import collector_paused
from g2s_plugins.samples import levels as samples


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rooms", type=int, default=12000)
    parser.add_argument("--preset", default="map_analysis")
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    registry = Registry.from_entry_points()
    plan = pipeline.plan(load_config(PRESETS_DIR / f"{args.preset}.yaml"), registry, args.preset)
    mesh = samples.dungeon(seed=0, rooms=args.rooms).mesh
    result = pipeline.run(plan, registry, mesh, f"dungeon_{args.rooms}", mesh_sha256(mesh))
    print(f"preset {args.preset}, dungeon of {args.rooms} rooms: "
          f"{len(structure_json.structure_document(result)['nodes'])} structure nodes")
    for run in range(args.repeat):
        with tempfile.TemporaryDirectory() as folder:
            load = os.getloadavg()[0]
            wall, cpu = time.perf_counter(), time.process_time()
            structure_json.write(result, Path(folder))
            wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
            digest = hashlib.sha256(Path(folder, structure_json.STRUCTURE_FILE).read_bytes()).hexdigest()[:16]
            print(f"write {run + 1}: wall {wall:6.2f} s   CPU {cpu:6.2f} s   load average {load:.1f} -> "
                  f"{os.getloadavg()[0]:.1f}   structure.json sha256 {digest}...")
        with collector_paused():
            cpu = time.process_time()
            document = structure_json.structure_document(result)
            building = time.process_time() - cpu
            structure_json.dumps(document)
            print(f"  of which CPU: document {building:.2f} s, text {time.process_time() - cpu - building:.2f} s")


if __name__ == "__main__":
    main()
