"""Start-up time of the ``g2s`` command: how long a user waits for the answers that need no computation.

Run from the repository root: ``.venv/bin/python benchmarks/startup.py [--runs 5] [--piece ../shared/data/pieces/Hallway.obj]
[--only TEXT] [--g2s COMMAND] [--against COMMAND]`` (``--g2s``: time another g2s, e.g. an older checkout's, against the
same load; ``--against``: a second g2s whose warm runs alternate with the first's, run by run, no cold runs).

Each command runs ``--runs`` times warm (files in the page cache, the first
run discarded) and ``--runs`` times cold: before each cold run the pages of
the venv, the Python installation and this checkout are dropped from the page
cache with ``posix_fadvise(DONTNEED)`` (only those files, so that other work on
the machine keeps its cache). Wall time of the whole process, median and range; the CPU seconds (user + system)
of the warm runs, which a loaded machine inflates far less than the wall time; peak memory (max RSS) of the last
run. The load average is printed first and last: wall times taken under load are not comparable.

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
TYPO_PARAMS_CONFIG = "extends: map_piece\ngraph:\n  params: {cell_szie: 0.2}\n"
"""A config with a misspelt key among a plugin's parameters: checked once that plugin is loaded, exit 2."""


def commands(g2s: list[str], piece: str, folder: Path) -> list[tuple[str, list[str], int]]:
    """``(label, argv, expected exit code)`` of each measured command, ``g2s`` being the command's argv."""
    typo, typo_params = folder / "typo.yaml", folder / "typo_params.yaml"
    typo.write_text(TYPO_CONFIG)
    typo_params.write_text(TYPO_PARAMS_CONFIG)
    return [
        ("g2s --version", [*g2s, "--version"], 0),
        ("g2s --help", [*g2s, "--help"], 0),
        ("g2s plugins", [*g2s, "plugins"], 0),
        ("g2s run typo.yaml (exit 2)", [*g2s, "run", str(typo), piece, "-o", str(folder / "never")], 2),
        ("g2s run typo_params.yaml (exit 2)", [*g2s, "run", str(typo_params), piece, "-o", str(folder / "never")], 2),
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


def timed(argv: list[str], expected: int) -> tuple[float, float, float]:
    """(wall seconds, CPU seconds, peak RSS in MB) of one run of ``argv``, which must exit with ``expected``."""
    start = time.perf_counter()
    child = subprocess.Popen(argv, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    stderr = child.stderr.read()
    _, status, usage = os.wait4(child.pid, 0)
    seconds = time.perf_counter() - start
    child.returncode = os.waitstatus_to_exitcode(status)
    if child.returncode != expected:
        sys.exit(f"{' '.join(argv)}: exit {child.returncode}, expected {expected}: {stderr.strip()}")
    return seconds, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024


def spread(values: list[float]) -> str:
    """``median (min-max)``."""
    return f"{statistics.median(values):.2f} ({min(values):.2f}-{max(values):.2f})"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--piece", default=str((ROOT.parent / "shared" / "data" / "pieces" / "Hallway.obj")))
    parser.add_argument("--only", help="only the commands whose label contains this text")
    parser.add_argument("--g2s", default=str(VENV_BIN / "g2s"),
                        help="the g2s command to time, split like a shell would (default: this venv's g2s)")
    parser.add_argument("--against", help="a second g2s command: warm runs alternate between the two, no cold runs")
    args = parser.parse_args()
    cached = [Path(sys.prefix), Path(sysconfig.get_paths()["stdlib"]), ROOT / "g2s_core", ROOT / "g2s_plugins",
              ROOT / "build"]
    print("load average:", " ".join(f"{x:.2f}" for x in os.getloadavg()))
    print(f"{'command':44} {'warm median (range) s':>24} {'warm CPU s':>24} {'cold median (range) s':>24} {'max RSS MB':>10}")
    g2s_commands = [shlex.split(args.g2s), *([shlex.split(args.against)] if args.against else [])]
    with tempfile.TemporaryDirectory() as tmp:
        for measured in zip(*(commands(g2s, args.piece, Path(tmp)) for g2s in g2s_commands)):
            label = measured[0][0]
            if args.only and args.only not in label:
                continue
            for _, argv, expected in measured:
                timed(argv, expected)  # warms the cache
            warm: list[list[tuple[float, float, float]]] = [[] for _ in measured]
            for _ in range(args.runs):
                for runs, (_, argv, expected) in zip(warm, measured):  # alternated: both see the same load
                    runs.append(timed(argv, expected))
            for which, runs in enumerate(warm):
                cold = []
                for _ in range(0 if args.against else args.runs):
                    drop_from_page_cache(*cached)
                    cold.append(timed(measured[which][1], measured[which][2])[0])
                name = label if not args.against else f"{label} [{'g2s' if which == 0 else 'against'}]"
                cells = [spread([run[0] for run in runs]), spread([run[1] for run in runs]), spread(cold) if cold else "-"]
                print(f"{name:44} {cells[0]:>24} {cells[1]:>24} {cells[2]:>24} {runs[-1][2]:10.0f}", flush=True)
    print("load average:", " ".join(f"{x:.2f}" for x in os.getloadavg()))


if __name__ == "__main__":
    main()
