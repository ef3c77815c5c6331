"""Writers of a run's results, chosen by format name in the config or on the CLI.

Every writer takes the :class:`~g2s_core.model.RunResult` and the output folder
and returns the paths it wrote. Files are written atomically (temporary file in
the same folder, then rename), so a failed run never leaves half a file.

=========  ==========================================  =====================================
format     files                                       what
=========  ==========================================  =====================================
json       structure.json, run.json                    the structure (deterministic), timings
html       report.html                                 self-contained interactive report
glb        structure.glb                               mesh, navmesh and structure, binary glTF
graphml    structure.graphml, graph.graphml            final structure and initial graph
png        heatmap.png                                 top-down heat map, one panel per floor
graph      graph.json                                  initial graph, networkx node-link JSON
=========  ==========================================  =====================================

See ``docs/outputs.md`` for the details of each format.
"""

from __future__ import annotations

import importlib
import os
from collections.abc import Callable, Sequence
from pathlib import Path

from g2s_core.errors import G2SError
from g2s_core.model import RunResult
from g2s_plugins.outputs.structure_json import LoadedResult, load_result

Writer = Callable[[RunResult, Path], list[Path]]

__all__ = [
    "DEFAULT_FORMATS", "RESULT_FILES", "WRITERS", "LoadedResult", "Writer",
    "check_outdir", "load_result", "parse_formats", "prepare_outdir", "result_paths", "write_outputs",
]

def _lazy(module: str) -> Writer:
    """The ``write`` of ``g2s_plugins.outputs.<module>``, imported on first use (plotly and
    matplotlib take a while to import, and most commands never write those formats)."""

    def write(result: RunResult, outdir: Path) -> list[Path]:
        return importlib.import_module(f"g2s_plugins.outputs.{module}").write(result, outdir)

    write.__qualname__ = write.__name__ = f"write_{module}"
    write.__doc__ = f"Writer of g2s_plugins.outputs.{module}."
    return write


WRITERS: dict[str, Writer] = {
    "json": _lazy("structure_json"),
    "html": _lazy("html_report"),
    "glb": _lazy("gltf"),
    "graphml": _lazy("graphml"),
    "png": _lazy("heatmap"),
    "graph": _lazy("graph_json"),
}
"""Format name -> writer."""

RESULT_FILES: dict[str, tuple[str, ...]] = {
    "json": ("structure.json", "run.json"),
    "html": ("report.html",),
    "glb": ("structure.glb",),
    "graphml": ("structure.graphml", "graph.graphml"),
    "png": ("heatmap.png",),
    "graph": ("graph.json",),
}
"""Format name -> the file names it writes (what ``--force`` may replace)."""

DEFAULT_FORMATS: tuple[str, ...] = ("json", "html")
"""What a run writes when neither the config nor ``--format`` says."""


def parse_formats(formats: str | Sequence[str], source: str = "--format") -> list[str]:
    """Format names from ``"json,html"`` or a list: stripped, duplicates dropped, order kept.

    Raises:
        G2SError: a name is unknown or none is given; the message starts with ``source``.
    """
    items = formats.split(",") if isinstance(formats, str) else list(formats)
    names: list[str] = []
    for item in items:
        name = str(item).strip().lower()
        if not name:
            continue
        if name not in WRITERS:
            raise G2SError(f"{source}: unknown output format {name!r} (expected some of: {', '.join(WRITERS)})")
        if name not in names:
            names.append(name)
    if not names:
        raise G2SError(f"{source}: no output format given (expected some of: {', '.join(WRITERS)})")
    return names


def result_paths(outdir: Path, formats: Sequence[str] | None = None) -> list[Path]:
    """The result files of ``formats`` (all formats when ``None``) inside ``outdir``."""
    chosen = WRITERS if formats is None else formats
    return [outdir / name for fmt in chosen for name in RESULT_FILES.get(fmt, ())]


def check_outdir(outdir: Path, formats: Sequence[str], force: bool, protect: Sequence[Path] = ()) -> None:
    """Refuse an output folder that cannot take the results, without creating anything.

    Any result file of any format already in ``outdir`` counts as an earlier
    result and is refused unless ``force``. The files in ``protect`` (the
    input mesh) are never written or removed, even with ``force``.

    Raises:
        G2SError: unknown format, ``outdir`` is a file, results exist without
            ``force``, or a result file would be an input file.
    """
    parse_formats(formats)
    if outdir.exists() and not outdir.is_dir():
        raise G2SError(f"{outdir}: exists and is not a folder")
    for path in result_paths(outdir):
        for guarded in protect:
            if _same_file(path, Path(guarded)):
                raise G2SError(
                    f"{outdir}: the input {guarded} has the name of a result file ({path.name}); "
                    "choose another output folder"
                )
    existing = sorted(p.name for p in result_paths(outdir) if p.exists())
    if existing and not force:
        raise G2SError(f"{outdir}: already holds results ({', '.join(existing)}); use --force to replace them")


def prepare_outdir(outdir: Path, formats: Sequence[str], force: bool, protect: Sequence[Path] = ()) -> None:
    """:func:`check_outdir`, then create ``outdir`` (and its parents)."""
    check_outdir(outdir, formats, force, protect)
    outdir.mkdir(parents=True, exist_ok=True)


def write_outputs(
    result: RunResult,
    outdir: Path,
    formats: Sequence[str],
    replace: bool = False,
    progress: Callable[[str], None] | None = None,
) -> list[Path]:
    """Write every requested format into ``outdir`` (prepared by :func:`prepare_outdir`).

    With ``replace`` (``--force``), result files of the formats not requested
    that an earlier run left are removed once the new ones are written, so the
    folder never mixes two runs.
    """
    written: list[Path] = []
    result.formats = tuple(parse_formats(formats))
    for fmt in result.formats:
        if progress is not None:
            progress(f"writing {fmt}")
        written.extend(WRITERS[fmt](result, outdir))
    if replace:
        keep = {p.resolve() for p in written}
        for path in result_paths(outdir):
            if path.exists() and path.resolve() not in keep:
                path.unlink()
    return written


def _same_file(a: Path, b: Path) -> bool:
    try:
        return a.exists() and b.exists() and os.path.samefile(a, b)
    except OSError:
        return False
