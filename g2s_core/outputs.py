"""A run's output folder: choosing formats among the installed output writers, and writing them.

Output writers are plugins (see :mod:`g2s_core.hookspecs`, ``g2s_write_output``):
each has a format ``NAME`` and declares the ``FILES`` it writes. Any installed
writer may be named in ``--format`` or the config's ``outputs.formats``.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence
from pathlib import Path

from g2s_core.errors import G2SError
from g2s_core.model import RunResult
from g2s_core.registry import PluginInfo, Registry, installed

DEFAULT_FORMATS: tuple[str, ...] = ("json", "html")
"""What a run writes when neither the config nor ``--format`` says."""


def writers(registry: Registry | None = None) -> dict[str, PluginInfo]:
    """Format name -> its installed writer, by name."""
    return {info.name: info for info in (registry or installed()).plugins("outputs")}


def result_files(registry: Registry | None = None) -> dict[str, tuple[str, ...]]:
    """Format name -> the file names its writer declares (what ``--force`` may replace)."""
    return {name: tuple(info.plugin.FILES) for name, info in writers(registry).items()}


def parse_formats(formats: str | Sequence[str], source: str = "--format", registry: Registry | None = None) -> list[str]:
    """Format names from ``"json,html"`` or a list: stripped, lower-cased, duplicates dropped, order kept.

    Raises:
        G2SError: a name is not an installed writer, or none is given; the message starts with ``source``.
    """
    known = writers(registry)
    items = formats.split(",") if isinstance(formats, str) else list(formats)
    names: list[str] = []
    for item in items:
        name = str(item).strip().lower()
        if not name:
            continue
        if name not in known:
            raise G2SError(f"{source}: unknown output format {name!r} (expected some of: {', '.join(known)})")
        if name not in names:
            names.append(name)
    if not names:
        raise G2SError(f"{source}: no output format given (expected some of: {', '.join(known)})")
    return names


def result_paths(outdir: Path, formats: Sequence[str] | None = None, registry: Registry | None = None) -> list[Path]:
    """The result files of ``formats`` (all installed formats when ``None``) inside ``outdir``."""
    files = result_files(registry)
    chosen = files if formats is None else formats
    return [outdir / name for fmt in chosen for name in files.get(fmt, ())]


def check_outdir(
    outdir: Path, formats: Sequence[str], force: bool, protect: Sequence[Path] = (), registry: Registry | None = None
) -> None:
    """Refuse an output folder that cannot take the results, without creating anything.

    Any result file of any installed format already in ``outdir`` counts as an
    earlier result and is refused unless ``force``. The files in ``protect``
    (the input mesh) are never written or removed, even with ``force``.

    Raises:
        G2SError: unknown format, ``outdir`` is a file, results exist without
            ``force``, or a result file would be an input file.
    """
    parse_formats(formats, registry=registry)
    if outdir.exists() and not outdir.is_dir():
        raise G2SError(f"{outdir}: exists and is not a folder")
    every = result_paths(outdir, registry=registry)
    for path in every:
        for guarded in protect:
            if _same_file(path, Path(guarded)):
                raise G2SError(
                    f"{outdir}: the input {guarded} has the name of a result file ({path.name}); "
                    "choose another output folder"
                )
    existing = sorted(p.name for p in every if p.exists())
    if existing and not force:
        raise G2SError(f"{outdir}: already holds results ({', '.join(existing)}); use --force to replace them")


def prepare_outdir(
    outdir: Path, formats: Sequence[str], force: bool, protect: Sequence[Path] = (), registry: Registry | None = None
) -> None:
    """:func:`check_outdir`, then create ``outdir`` (and its parents)."""
    check_outdir(outdir, formats, force, protect, registry)
    outdir.mkdir(parents=True, exist_ok=True)


def write_outputs(
    result: RunResult,
    outdir: Path,
    formats: Sequence[str],
    replace: bool = False,
    progress: Callable[[str], None] | None = None,
    registry: Registry | None = None,
) -> list[Path]:
    """Write every requested format into ``outdir`` (prepared by :func:`prepare_outdir`).

    With ``replace`` (``--force``), result files of the formats not requested
    that an earlier run left are removed once the new ones are written, so the
    folder never mixes two runs.
    """
    registry = registry or installed()
    known = writers(registry)
    written: list[Path] = []
    result.formats = tuple(parse_formats(formats, registry=registry))
    for fmt in result.formats:
        if progress is not None:
            progress(f"writing {fmt}")
        written.extend(registry.call(known[fmt], result=result, folder=outdir))
    if replace:
        keep = {p.resolve() for p in written}
        for path in result_paths(outdir, registry=registry):
            if path.exists() and path.resolve() not in keep:
                path.unlink()
    return written


def _same_file(a: Path, b: Path) -> bool:
    try:
        return a.exists() and b.exists() and os.path.samefile(a, b)
    except OSError:
        return False
