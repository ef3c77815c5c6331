"""Writers of a run's results, chosen by format name in the config or on the CLI.

Every writer takes the :class:`~g2s_core.model.RunResult` and the output folder
and returns the paths it wrote. The writers of a run write into one staging
folder whose files then move into the output folder together
(:mod:`g2s_core.result_folder`), so a failed run never leaves half a result.

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
from collections.abc import Callable, Sequence
from pathlib import Path

from g2s_core.errors import G2SError
from g2s_core.model import RunResult
from g2s_core.result_folder import check_writable, same_file, staged
from g2s_plugins.outputs.structure_json import LoadedResult, load_result

Writer = Callable[[RunResult, Path], list[Path]]

__all__ = [
    "DEFAULT_FORMATS", "RESULT_FILES", "WRITERS", "LoadedResult", "Writer",
    "check_outdir", "load_result", "parse_formats", "result_paths", "write_outputs",
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
    input mesh, config and points files) are never written or removed, even
    with ``force``.

    Raises:
        G2SError: unknown format, ``outdir`` cannot be created or written,
            results exist without ``force``, or a result file would be an
            input file.
    """
    parse_formats(formats)
    check_writable(outdir)
    for path in result_paths(outdir):
        for guarded in protect:
            if same_file(path, Path(guarded)):
                raise G2SError(
                    f"{outdir}: the input {guarded} has the name of a result file ({path.name}); "
                    "choose another output folder"
                )
    existing = sorted(p.name for p in result_paths(outdir) if p.exists())
    if existing and not force:
        raise G2SError(f"{outdir}: already holds results ({', '.join(existing)}); use --force to replace them")


def write_outputs(
    result: RunResult,
    outdir: Path,
    formats: Sequence[str],
    replace: bool = False,
    progress: Callable[[str], None] | None = None,
    protect: Sequence[Path] = (),
) -> list[Path]:
    """Write every requested format into ``outdir``, all files at once or none (see :mod:`g2s_core.result_folder`).

    :func:`check_outdir` is applied first. With ``replace`` (``--force``),
    result files of the formats not requested that an earlier run left are
    removed in the same step, so the folder never mixes two runs.
    """
    check_outdir(outdir, formats, replace, protect)
    obsolete = [p for p in result_paths(outdir) if p.exists()] if replace else []
    names: list[str] = []
    with staged(outdir, obsolete, protect) as staging:
        for fmt in parse_formats(formats):
            if progress is not None:
                progress(f"writing {fmt}")
            names.extend(path.name for path in WRITERS[fmt](result, staging))
    return [outdir / name for name in names]
