"""Writers of a run's results, chosen by format name in the config or on the CLI.

Every writer takes the :class:`~g2s_core.model.RunResult` and the output folder
and returns the paths it wrote. Files are written atomically (temporary file in
the same folder, then rename), so a failed run never leaves half a file.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path

from g2s_core.errors import G2SError
from g2s_core.model import RunResult
from g2s_core.outputs import graph_json

Writer = Callable[[RunResult, Path], list[Path]]


WRITERS: dict[str, Writer] = {"graph": graph_json.write}
"""Format name -> writer."""

RESULT_FILES = {"graph": ("graph.json",)}
"""Format name -> the file names it writes (what ``--force`` may replace)."""


def prepare_outdir(outdir: Path, formats: Sequence[str], force: bool) -> None:
    """Create ``outdir``; refuse to replace earlier results unless ``force``."""
    unknown = [f for f in formats if f not in WRITERS]
    if unknown:
        raise G2SError(f"unknown output format {unknown[0]!r} (expected some of: {', '.join(WRITERS)})")
    if outdir.exists() and not outdir.is_dir():
        raise G2SError(f"{outdir}: exists and is not a folder")
    existing = sorted(
        name for fmt in WRITERS for name in RESULT_FILES.get(fmt, ()) if (outdir / name).exists()
    )
    if existing and not force:
        raise G2SError(f"{outdir}: already holds results ({', '.join(existing)}); use --force to replace them")
    outdir.mkdir(parents=True, exist_ok=True)


def write_outputs(result: RunResult, outdir: Path, formats: Sequence[str]) -> list[Path]:
    """Write every requested format into ``outdir`` (prepared by :func:`prepare_outdir`)."""
    written: list[Path] = []
    for fmt in formats:
        written.extend(WRITERS[fmt](result, outdir))
    return written
