"""A run's result files appear in the output folder all together or not at all.

:func:`check_writable` refuses, before any work, an output folder that cannot
be created or written. :func:`staged` gives the writers an empty staging
folder on the same file system as the output folder and, once every writer
has finished, moves the files into place:

* the output folder does not exist yet: the staging folder is made beside it,
  and a folder inside it, made with the umask's mode, is renamed to it (one
  atomic rename);
* it exists (it may hold the user's other files, even the input mesh): the
  staging folder is made inside it and each file is renamed into place, with
  Ctrl-C held back until the last rename is done. SIGKILL or a power loss
  between those renames leaves the folder holding part of the run's files;
  the staging folder, renamed with :data:`MOVING_MARK` first, holds the rest
  and tells the next run (:func:`killed_move`).

When a writer fails (disk full, ``ulimit -f``, Ctrl-C) the staging folder is
removed, together with any parent folder created for it, and the output
folder is as it was. A staging folder that a killed process left behind is
removed by the next run into the same output folder; it is never taken for a
result.
"""

from __future__ import annotations

import contextlib
import errno
import os
import re
import shutil
import signal
import sys
import tempfile
import threading
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from g2s_core.errors import G2SError

STAGING_MARK = ".g2s-staging-"
"""Part of every staging folder's name, followed by the writing process's id."""

MOVING_MARK = ".moving"
"""Ends the name of a staging folder whose files are being renamed into an existing output folder."""

_STAGING_NAME = re.compile(re.escape(STAGING_MARK) + r"(\d+)-")


def check_writable(outdir: Path) -> None:
    """Refuse an output folder that cannot be created or written, creating nothing.

    Raises:
        G2SError: ``outdir`` or one of its parents is a file, or the nearest
            existing folder does not let a folder be created in it (read-only,
            no permission, ``/proc``).
    """
    try:
        base, missing = _missing_folders(outdir)
        if not base.is_dir():
            if base == outdir:  # a dangling link exists as a name only: say where it points
                raise G2SError(f"{outdir}: exists and is not a folder" if base.exists()
                               else f"{outdir}: a link to {os.readlink(base)}, which does not exist")
            raise G2SError(f"{outdir}: cannot create the folder, {base} is not a folder")
        longest = max((len(os.fsencode(folder.name)) for folder in missing), default=0)
        if longest > os.pathconf(base, "PC_NAME_MAX"):
            raise G2SError(f"{outdir}: cannot create the folder (a name of {longest} bytes is too long)")
        # a path beneath it (the staging folder, its files) adds a name of up to NAME_MAX; the system takes PC_PATH_MAX
        if (length := len(os.fsencode(outdir.absolute()))) + os.pathconf(base, "PC_NAME_MAX") > os.pathconf(base, "PC_PATH_MAX"):
            raise G2SError(f"{outdir}: cannot create the folder (a path of {length:,} bytes is too long for the files in it)")
        os.rmdir(tempfile.mkdtemp(dir=base, prefix=f"{STAGING_MARK}{os.getpid()}-"))
    except (OSError, ValueError) as exc:  # a name too long, a NUL byte, a read-only place, a file system of no blocks
        pseudo = isinstance(exc, FileNotFoundError) and os.statvfs(base).f_blocks == 0  # /proc: "No such file or directory"
        reason = f"{base} takes no new folders; give a folder on a disk" if pseudo else getattr(exc, "strerror", None) or exc
        raise G2SError(f"{outdir}: cannot write results there ({reason})") from None


@contextmanager
def staged(outdir: Path, obsolete: Sequence[Path] = (), protect: Sequence[Path] = ()) -> Iterator[Path]:
    """An empty folder to write a run's files into; they move to ``outdir`` when the block ends.

    Args:
        outdir: the output folder (created, with its parents, if missing).
        obsolete: files in ``outdir`` to remove in the same step (an earlier
            run's results of formats not written this time).
        protect: input files; the move refuses to replace or remove them.

    Raises:
        G2SError: a file could not be written or moved (disk full, file size
            limit, permissions), or it would replace a file of ``protect``;
            nothing of the run is left behind.
    """
    outdir = Path(outdir)
    check_writable(outdir)
    created: list[Path] = []
    staging = None
    try:
        for folder in reversed(_missing_folders(outdir.parent)[1]):  # outermost first
            with contextlib.suppress(FileExistsError):  # made meanwhile by another run (a batch's pairs share a folder)
                folder.mkdir()
                created.append(folder)
        inside = outdir.is_dir()
        home = outdir if inside else outdir.parent
        _remove_stale(home)
        beside = "" if inside else f".{outdir.name[:64]}"  # short enough for any name limit
        staging = Path(tempfile.mkdtemp(dir=home, prefix=f"{beside}{STAGING_MARK}{os.getpid()}-"))
        # the folder that becomes the output folder is made by mkdir, which gives it the umask's mode: mkdtemp's
        # 0700 kept other users (a web server showing report.html) out of a new output folder
        results = staging if inside else staging / outdir.name
        results.mkdir(exist_ok=True)
        yield results
        stop_if_interrupted()
        with interrupts_held():
            if inside:  # only a kill can stop the renames below half done; the mark lets the next run say so
                staging = results = staging.rename(f"{staging}{MOVING_MARK}")
            _move_into_place(results, outdir, obsolete, protect)
            if results != staging:
                staging.rmdir()  # emptied by the rename
    except BaseException as exc:
        # another process removed the folder (rm -r of the output folder): a writer's FileNotFoundError is no fault of its own
        vanished = staging is not None and not staging.is_dir() and isinstance(exc, Exception)
        if staging is not None:
            shutil.rmtree(staging, ignore_errors=True)
        for folder in reversed(created):
            with contextlib.suppress(OSError):  # not empty: something else was put there meanwhile
                folder.rmdir()
        storage = _storage_error(exc)
        if storage is not None or vanished:
            why = "its folder was removed meanwhile" if vanished else storage.strerror or storage
            left = f" (the staging folder {staging} could not be removed; the next run removes it)" if staging and staging.exists() else ""
            raise G2SError(f"{outdir}: cannot write results ({why}); nothing was written{left}") from None
        raise


STORAGE_ERRNOS = frozenset({errno.ENOSPC, errno.EFBIG, errno.EDQUOT, errno.EROFS, errno.EIO})
"""Failures of the storage itself (full, file size limit, read-only, I/O), whoever was writing."""


def _storage_error(exc: BaseException) -> OSError | None:
    """The OSError behind ``exc`` that is the environment's fault, if any.

    Our own moves fail with a plain OSError; a writer plugin's failure comes
    wrapped (as that plugin's failure) and counts only when the storage
    itself failed, which is no fault of the plugin.
    """
    if isinstance(exc, OSError):
        return exc
    cause = exc.__cause__
    return cause if isinstance(cause, OSError) and cause.errno in STORAGE_ERRNOS else None


def _move_into_place(staging: Path, outdir: Path, obsolete: Sequence[Path], protect: Sequence[Path]) -> None:
    if not outdir.exists():
        os.rename(staging, outdir)
        return
    names = sorted(p.name for p in staging.iterdir())
    refuse_inputs(outdir, [outdir / name for name in names] + list(obsolete), protect)
    for name in names:
        os.replace(staging / name, outdir / name)
    for path in obsolete:
        if path.name not in names:
            path.unlink(missing_ok=True)
    staging.rmdir()


def _missing_folders(folder: Path) -> tuple[Path, list[Path]]:
    """The nearest path at or above ``folder`` that exists, and the missing ones below it, innermost first."""
    missing = []
    while not os.path.lexists(folder) and folder != folder.parent:
        missing.append(folder)
        folder = folder.parent
    return folder, missing


def _remove_stale(home: Path) -> None:
    """Remove staging folders in ``home`` whose process no longer runs."""
    for path in home.iterdir():
        match = _STAGING_NAME.search(path.name)
        if match and path.is_dir() and not _process_alive(int(match.group(1))):
            shutil.rmtree(path, ignore_errors=True)


def killed_move(outdir: Path) -> str | None:
    """What a run killed while renaming its files into ``outdir`` left there, in words; ``None`` if no run was."""
    pids = [int(match.group(1)) for path in (outdir.iterdir() if outdir.is_dir() else ())
            if path.name.endswith(MOVING_MARK) and (match := _STAGING_NAME.search(path.name))]
    if dead := sorted(pid for pid in pids if not _process_alive(pid)):
        return f"a run killed while moving its results in (process {', '.join(map(str, dead))}) left only part of them there"
    return None


def _process_alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (PermissionError, OverflowError, ValueError):
        return pid != 0
    return True


def refuse_inputs(outdir: Path, paths: Sequence[Path], protect: Sequence[Path]) -> None:
    """Raise :class:`G2SError` when a result path of ``paths`` is one of the input files ``protect``."""
    for path in paths:
        for guarded in protect:
            if same_file(path, Path(guarded)):
                raise G2SError(f"{outdir}: the input {guarded} has the name of a result file ({path.name}); "
                               "choose another output folder")


def same_file(a: Path, b: Path) -> bool:
    """Whether ``a`` and ``b`` both exist and are the same file."""
    try:
        return a.exists() and b.exists() and os.path.samefile(a, b)
    except OSError:
        return False


_TAKEN: list[int] = []
"""The interrupts a command took (:func:`interrupts_held` with ``hold=False``), its KeyboardInterrupt swallowed or not."""


def interrupted() -> bool:
    """Whether the command took an interrupt (SIGINT, SIGTERM), its KeyboardInterrupt swallowed by a library or not."""
    return bool(_TAKEN)


def stop_if_interrupted() -> None:
    """Raise KeyboardInterrupt if the command took an interrupt that a library swallowed."""
    if interrupted():
        raise KeyboardInterrupt


@contextmanager
def interrupts_held(hold: bool = True) -> Iterator[list[int]]:
    """Hold Ctrl-C (SIGINT) and SIGTERM back until the block ends, then act on them, also when the block fails (the
    interrupt then ends it, the failure its context); the block gets the list of signals taken so far, to stop early
    at a point of its choosing.

    With ``hold`` false (a whole command) they raise KeyboardInterrupt at once and are remembered for
    :func:`stop_if_interrupted`: trimesh, scipy and PIL catch BaseException while they load, and a run whose
    interrupt they swallowed went on and wrote its results. Python itself swallows one raised in a ``__del__``
    method or a weakref callback (the import system's, while a module loads), printing ``Exception ignored in ...``
    and its traceback; that print is left out, the interrupt being remembered. A signal the parent process
    ignores (a background job's Ctrl-C) stays ignored.
    """
    if threading.current_thread() is not threading.main_thread():
        yield []
        return
    received: list[int] = []

    def take(number: int, _frame: object) -> None:
        received.append(number)
        if not hold:
            _TAKEN.append(number)
            raise KeyboardInterrupt

    def unraisable(problem: Any) -> None:
        if not (problem.exc_type is KeyboardInterrupt and _TAKEN):
            previous_hook(problem)

    previous = {sig: signal.signal(sig, take) for sig in (signal.SIGINT, signal.SIGTERM) if signal.getsignal(sig) is not signal.SIG_IGN}
    previous_hook, sys.unraisablehook = sys.unraisablehook, sys.unraisablehook if hold else unraisable
    try:
        yield received
    finally:
        sys.unraisablehook = previous_hook
        for sig, handler in previous.items():
            signal.signal(sig, handler)
        if not hold:  # the command is over: a script's next run in this process starts afresh
            _TAKEN.clear()
        elif received:  # in the finally, so that one taken as the block failed is not dropped for that failure
            signal.raise_signal(received[0])
