"""A run's output folder: choosing formats among the installed output writers, and writing them.

Output writers are plugins (see :mod:`g2s_core.hookspecs`, ``g2s_write_output``):
each has a format ``NAME`` and declares the ``FILES`` it writes. Any installed
writer may be named in ``--format`` or the config's ``outputs.formats``.
The writers of a run write into one staging folder whose files then move
into the output folder together (:mod:`g2s_core.result_folder`).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from g2s_core.errors import G2SError
from g2s_core.messages import show
from g2s_core.model import RunResult
from g2s_core.registry import PluginInfo, Registry, installed
from g2s_core.result_folder import check_writable, killed_move, refuse_inputs, staged

if TYPE_CHECKING:
    from g2s_core.config import RunConfig

DEFAULT_FORMATS: tuple[str, ...] = ("json", "html")
"""What a run writes when neither the config nor ``--format`` says."""


def writers(registry: Registry | None = None) -> dict[str, PluginInfo]:
    """Format name -> its installed writer, by name."""
    return {info.name: info for info in (registry or installed()).plugins("outputs")}


def result_files(registry: Registry | None = None) -> dict[str, tuple[str, ...]]:
    """Format name -> the file names its writer declares (what ``--force`` may replace)."""
    return {name: tuple(info.plugin.FILES) for name, info in writers(registry).items()}


def parse_formats(formats: str | Sequence[str], source: str = "--format", registry: Registry | None = None) -> list[str]:
    """Format names from ``"json,html"`` or a list: stripped, lower-cased, empty items dropped, order kept.

    Raises:
        G2SError: ``formats`` is neither a text nor a list (or tuple), a name is not an installed writer, is given
            twice (as ``--evaluate`` refuses a name twice), or none is given; the message starts with ``source``.
    """
    if not isinstance(formats, (str, list, tuple)):  # the Python API's: an int failed in Python's words, b"json" as '106'
        raise G2SError(f"{source}: expected names, comma-separated or in a list, got {type(formats).__name__}")
    known = writers(registry)
    items = formats.split(",") if isinstance(formats, str) else list(formats)
    names = [name for name in (str(item).strip().lower() for item in items) if name]
    for index, name in enumerate(names):
        if name not in known:
            raise G2SError(f"{source}: unknown output format {show(name)} (expected some of: {', '.join(known)})")
        if name in names[:index]:
            raise G2SError(f"{source}: {show(name)} is given twice (expected some of: {', '.join(known)})")
    if not names:
        raise G2SError(f"{source}: no output format given (expected some of: {', '.join(known)})")
    return names


def chosen_formats(given: str | Sequence[str] | None, config: RunConfig, source: str, option: str = "formats") -> list[str]:
    """``given`` (``--format``, named ``option`` in errors), else the ``outputs.formats`` the config sets,
    else :data:`DEFAULT_FORMATS`; checked by :func:`parse_formats`."""
    if given is not None:
        return parse_formats(given, option)
    if "formats" in config.outputs.model_fields_set:
        return parse_formats(config.outputs.formats, f"{source}: outputs.formats")
    return list(DEFAULT_FORMATS)


def result_paths(outdir: Path, formats: Sequence[str] | None = None, registry: Registry | None = None) -> list[Path]:
    """The result files of ``formats`` (all installed formats when ``None``) inside ``outdir``."""
    files = result_files(registry)
    return [outdir / name for fmt in (files if formats is None else formats) for name in files.get(fmt, ())]


def check_outdir(
    outdir: Path, formats: str | Sequence[str], force: bool, protect: Sequence[Path] = (), registry: Registry | None = None
) -> list[str]:
    """Refuse an output folder that cannot take the results, without creating anything; the formats' names.

    Any result file of any installed format already in ``outdir`` counts as an
    earlier result and is refused unless ``force``. The files in ``protect``
    (the input mesh, config and points files) are never written or removed,
    even with ``force``.

    Raises:
        G2SError: unknown format, ``outdir`` cannot be created or written,
            results exist without ``force``, a result file would be an
            input file, or a folder has a result file's name.
    """
    names = parse_formats(formats, "formats", registry=registry)  # the API's parameter: the command line checked its own
    check_writable(outdir)
    every = result_paths(outdir, registry=registry)
    refuse_inputs(outdir, every, protect)
    if folders := [p.name for p in every if p.is_dir()]:  # the move into place would stop there, half done
        raise G2SError(f"{outdir}: {', '.join(folders)}: a folder has the name of a result file; move it or choose another output folder")
    if (existing := sorted(p.name for p in every if p.exists())) and not force:
        mixed = f"; {killed}" if (killed := killed_move(outdir)) else ""
        raise G2SError(f"{outdir}: already holds results ({', '.join(existing)}){mixed}; use --force to replace them")
    return names


def write_outputs(
    result: RunResult,
    outdir: Path,
    formats: str | Sequence[str],
    replace: bool = False,
    progress: Callable[[str], None] | None = None,
    registry: Registry | None = None,
    protect: Sequence[Path] = (),
) -> list[Path]:
    """Write every requested format into ``outdir``, all files at once or none (see :mod:`g2s_core.result_folder`).

    :func:`check_outdir` is applied first. With ``replace`` (``--force``),
    result files of the formats not requested that an earlier run left are
    removed in the same step, so the folder never mixes two runs.
    """
    registry = registry or installed()
    known = writers(registry)
    result.formats = tuple(check_outdir(outdir, formats, replace, protect, registry))
    obsolete = [p for p in result_paths(outdir, registry=registry) if p.exists()] if replace else []
    names: list[str] = []
    killed = killed_move(outdir)  # said once this run's files have replaced what it left
    with staged(outdir, obsolete, protect) as staging:
        for fmt in result.formats:
            if progress is not None:
                progress(f"writing {fmt}")
            names.extend(Path(p).name for p in registry.call(known[fmt], result=result, folder=staging))
        if appeared := sorted(p.name for p in result_paths(outdir, registry=registry) if p.exists() and p not in obsolete):
            raise G2SError(f"{outdir}: another run wrote {', '.join(appeared)} there meanwhile; nothing of this run was written")
    if killed:
        result.context.warn(f"{outdir}: {killed}; this run's results replaced them")
    return [outdir / name for name in names]
