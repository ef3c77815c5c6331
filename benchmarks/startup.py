"""Start-up time of the ``g2s`` command: how long a user waits for the answers that need no computation.

Run from the repository root: ``.venv/bin/python benchmarks/startup.py [--runs 5] [--piece ../shared/data/pieces/Hallway.obj]
[--only TEXT] [--g2s COMMAND]`` (``--g2s``: time another g2s, e.g. an older checkout's, against the same load).

Each command runs ``--runs`` times warm (files in the page cache, the first
run discarded) and ``--runs`` times cold: before each cold run the pages of
the venv, the Python installation and this checkout are dropped from the page
cache with ``posix_fadvise(DONTNEED)`` (only those files, so that other work on
the machine keeps its cache). Wall time of the whole process, median and range;
peak memory (max RSS) of the last run. The load average is printed first:
figures taken under load are not comparable.

This is a benchmark, not a test: nothing here asserts a time (docs/performance.md, "Start-up", records figures).
"""

from __future__ import annotations

import argparse
import os
import shlex
import statistics
import subprocess
import sys
import sysconfig
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
VENV_BIN = Path(sys.executable).parent
TYPO_CONFIG = "extends: map_piece\nagnet: {radius: 0.4}\n"
"""A config with a misspelt key: the exit-2 path (``g2s: error: ...agnet...``)."""


def commands(g2s: list[str], piece: str, folder: Path) -> list[tuple[str, list[str], int]]:
    """``(label, argv, expected exit code)`` of each measured command, ``g2s`` being the command's argv."""
    typo = folder / "typo.yaml"
    typo.write_text(TYPO_CONFIG)
    return [
        ("g2s --version", [*g2s, "--version"], 0),
        ("g2s --help", [*g2s, "--help"], 0),
        ("g2s plugins", [*g2s, "plugins"], 0),
        ("g2s run typo.yaml (exit 2)", [*g2s, "run", str(typo), piece, "-o", str(folder / "never")], 2),
        (f"g2s run map_piece {Path(piece).name}",
         [*g2s, "run", str(ROOT / "configs" / "map_piece.yaml"), piece, "-o", str(folder / "out"), "--force", "-q"], 0),
        ('python -c "import g2s_core"', [sys.executable, "-c", "import g2s_core"], 0),
    ]


def drop_from_page_cache(*folders: Path) -> None:
    """Drop the cached pages of every file under ``folders`` (clean pages only; nothing is written)."""
    for folder in folders:
        for path in folder.rglob("*"):
            try:
                if path.is_file() and not path.is_symlink():
                    with open(path, "rb") as file:
                        os.posix_fadvise(file.fileno(), 0, 0, os.POSIX_FADV_DONTNEED)
            except OSError:
                continue


def timed(argv: list[str], expected: int) -> tuple[float, float]:
    """(wall seconds, peak RSS in MB) of one run of ``argv``, which must exit with ``expected``."""
    start = time.perf_counter()
    child = subprocess.Popen(argv, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    stderr = child.stderr.read()
    _, status, usage = os.wait4(child.pid, 0)
    seconds = time.perf_counter() - start
    child.returncode = os.waitstatus_to_exitcode(status)
    if child.returncode != expected:
        sys.exit(f"{' '.join(argv)}: exit {child.returncode}, expected {expected}: {stderr.strip()}")
    return seconds, usage.ru_maxrss / 1024


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--piece", default=str((ROOT.parent / "shared" / "data" / "pieces" / "Hallway.obj")))
    parser.add_argument("--only", help="only the commands whose label contains this text")
    parser.add_argument("--g2s", default=str(VENV_BIN / "g2s"),
                        help="the g2s command to time, split like a shell would (default: this venv's g2s)")
    args = parser.parse_args()
    cached = [Path(sys.prefix), Path(sysconfig.get_paths()["stdlib"]), ROOT / "g2s_core", ROOT / "g2s_plugins",
              ROOT / "build"]
    print("load average:", " ".join(f"{x:.2f}" for x in os.getloadavg()))
    print(f"{'command':40} {'warm median (range) s':>24} {'cold median (range) s':>24} {'max RSS MB':>10}")
    with tempfile.TemporaryDirectory() as tmp:
        for label, argv, expected in commands(shlex.split(args.g2s), args.piece, Path(tmp)):
            if args.only and args.only not in label:
                continue
            timed(argv, expected)  # warms the cache
            warm = [timed(argv, expected)[0] for _ in range(args.runs)]
            cold = []
            for _ in range(args.runs):
                drop_from_page_cache(*cached)
                seconds, peak = timed(argv, expected)
                cold.append(seconds)
            cells = [f"{statistics.median(t):.2f} ({min(t):.2f}-{max(t):.2f})" for t in (warm, cold)]
            print(f"{label:40} {cells[0]:>24} {cells[1]:>24} {peak:10.0f}", flush=True)
    print("load average:", " ".join(f"{x:.2f}" for x in os.getloadavg()))


if __name__ == "__main__":
    main()
