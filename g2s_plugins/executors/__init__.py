"""Executor plugins: where the pairs of a batch run (``g2s batch --executor NAME``)."""

import os

from g2s_core.errors import G2SError

INTERRUPT_POLL = 0.1
"""Seconds between two looks for a Ctrl-C while an executor waits on its pairs.

An executor that waits on a library's futures holds Ctrl-C back (:func:`g2s_core.result_folder.interrupts_held`),
looks for it between waits and acts on it once its workers are stopped: a KeyboardInterrupt raised inside the
library's wait could leave one of its locks held, and the shutdown then waited for ever (concurrent.futures: a pool of
quick items interrupted at random hung within 2 to 11 tries in each of 7 runs; 100 tries since, none).
"""


def workers_named(count: int) -> str:
    """``"1 worker"``, ``"2 workers"``."""
    return f"{count} worker{'s' if count != 1 else ''}"


def require_open_files(needed: int, what: str) -> None:
    """Refuse to start ``what`` (e.g. "the local executor's pool of 2 workers"), which opens about ``needed`` more
    files (pipes and sockets count) than this process holds now, when the process's limit (``ulimit -n``) is lower.

    Started under such a limit, the libraries failed in their own words, after their processes had started: the
    process pool's ``Too many open files``, ``No usable temporary directory found`` or its forkserver's traceback, Dask's
    ``Nanny failed to start.``, and a LocalCluster of 2 workers under ``ulimit -n 40`` waited for ever (robust15).

    Raises:
        G2SError: the limit is lower than the files held now plus ``needed`` (like a full disk, the user's to change).
    """
    import resource  # POSIX only; this project's executors run on Linux

    limit = resource.getrlimit(resource.RLIMIT_NOFILE)[0]
    try:
        held = len(os.listdir("/proc/self/fd"))  # Linux; elsewhere the check is left to the libraries
    except OSError:
        return
    if limit != resource.RLIM_INFINITY and held + needed > limit:
        raise G2SError(f"ulimit -n: {what} needs about {held + needed} open files ({held} open now), more than the "
                       f"process's limit of {limit}: raise it (ulimit -n 1024), or run fewer workers or the "
                       "serial executor (the pairs one by one in this process)")
