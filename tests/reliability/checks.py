"""What every reliability test checks: the exit code, one clean line naming the culprit,
no traceback, nothing left in the output folder, inputs unchanged."""

from __future__ import annotations

import hashlib
import os
import subprocess
import sys
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

import pytest

from g2s_core.cli import main

CORRIDOR = "sample:straight_corridor"
"""A level small enough that a whole run takes well under a second."""

QUICK_CONFIG = "extends: graph_only\n"
"""Step 1 only, graph.json: the quickest complete run."""


@dataclass
class Outcome:
    code: int
    stdout: str
    stderr: str


def run_g2s(capsys: pytest.CaptureFixture[str], *args: str | Path) -> Outcome:
    """``g2s ARGS`` in this process."""
    code = main([str(a) for a in args])
    captured = capsys.readouterr()
    return Outcome(code, captured.out, captured.err)


def run_g2s_process(*args: str | Path, timeout: float = 60, **kwargs) -> Outcome:
    """``g2s ARGS`` in a child process (for FIFOs, signals and resource limits)."""
    proc = subprocess.run(
        [sys.executable, "-m", "g2s_core.cli", *map(str, args)],
        capture_output=True, text=True, timeout=timeout, env={**os.environ, "COLUMNS": "300"}, **kwargs,
    )
    return Outcome(proc.returncode, proc.stdout, proc.stderr)


def assert_clean_error(outcome: Outcome, *fragments: str, code: int = 2) -> str:
    """The run failed with ``code`` and one line ``g2s: error: ...`` holding every fragment; that line."""
    assert outcome.code == code, outcome.stderr
    assert "Traceback" not in outcome.stderr
    lines = [line for line in outcome.stderr.splitlines() if line.strip()]
    assert len(lines) == 1, outcome.stderr
    assert lines[0].startswith("g2s: error: "), lines[0]
    for fragment in fragments:
        assert fragment in lines[0], lines[0]
    return lines[0]


def snapshot(paths: Iterable[Path]) -> dict[Path, str]:
    """SHA-256 of each file's bytes, to show inputs were not changed."""
    return {p: hashlib.sha256(p.read_bytes()).hexdigest() for p in paths}


def tree(folder: Path) -> list[str]:
    """Every path under ``folder`` (hidden ones too), relative, sorted; [] if it does not exist."""
    if not folder.exists():
        return []
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*"))
