"""A dask.distributed cluster: a scheduler's workers, or a LocalCluster of single-threaded processes started here.

Workers import the batch's function by name and look plugins up in their own
environment: every worker needs g2s and the same plugins installed, and sees
the meshes and the output folder at the same paths (see docs/batch.md).
"""

from __future__ import annotations

import logging
import os
import signal
import time
from collections.abc import Callable, Generator, Iterator, Sequence
from contextlib import contextmanager
from typing import Any

from pydantic import Field

from g2s_core.errors import G2SError
from g2s_core.plugin import PluginParams, hookimpl
from g2s_core.result_folder import interrupts_held
from g2s_plugins.executors import INTERRUPT_POLL, require_open_files, workers_named

NAME = "dask"

NO_WORKERS_LIMIT = 60.0
"""Seconds the LocalCluster may go without a worker before its unfinished pairs are lost: Dask does not start a
worker again that died as it started (a pair that kills its worker, under load), and the batch waited for ever."""

CLUSTER_FILES = 12
"""Files (sockets, pipes) a LocalCluster opens in this process besides its workers' (:data:`WORKER_FILES`): with 6
open before, ``graph_only`` on 3 levels ran under ``ulimit -n`` 30 on one worker, 42 on two and 56 on three, and
under 28, 40 and 48 a nanny failed to start, or the cluster of two waited for ever (robust15)."""

WORKER_FILES = 12
"""Files a LocalCluster holds in this process for each worker (its nanny's and worker's connections; measured as
:data:`CLUSTER_FILES`)."""

NO_WORKERS = "the Dask cluster's workers died as they started, and none was left to run it"


class Params(PluginParams):
    """Which cluster."""

    scheduler: str | None = Field(None, description="address of a running scheduler, e.g. tcp://host:8786 "
                                  "(default: start a LocalCluster and close it at the end)")
    workers: int | None = Field(None, ge=1, description="processes of the LocalCluster (default: the CPU count; "
                                "never more than the batch's pairs)")


@contextmanager
def _children_ignore_interrupt() -> Iterator[None]:
    """Processes started inside ignore Ctrl-C (the disposition is inherited), this one keeps its handler."""
    handler = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, handler)


@hookimpl
def g2s_execute(
    function: Callable[[Any], dict[str, Any]], items: Sequence[Any], params: Params, lost: Callable[[Any, str], dict[str, Any]]
) -> Iterator[dict[str, Any]]:
    """Each item as a Dask task, yielded as it finishes; an item whose workers died running it is ``lost``, the others
    run, unless the local cluster has gone :data:`NO_WORKERS_LIMIT` seconds without a worker: then every item left is
    ``lost``.

    Dask tries an item on another worker when its worker dies (``distributed.scheduler.allowed-failures``, 3 by
    default), and counts a death against every item the worker held, those waiting there too: a sound item queued on
    the worker of one that kills it failed with it. The items Dask gave up on run again one at a time, alone on the
    cluster, where the one whose workers die is ``lost``.
    """
    from dask.distributed import Client, LocalCluster

    if params.scheduler:
        cluster = None
        try:
            client = Client(params.scheduler)
        except (OSError, ValueError) as exc:  # the user's address, not this plugin, is at fault
            raise G2SError(f"--scheduler: expected the address of a running Dask scheduler (tcp://host:8786), got "
                           f"{params.scheduler!r}: {' '.join(str(exc).split())}") from exc
    else:
        # no more workers than pairs: each starts a process up front (2 pairs on `--workers 8`: 7.9-9.9 s, capped 5.6-5.7)
        workers = max(1, min(params.workers or os.cpu_count() or 1, len(items)))
        require_open_files(CLUSTER_FILES + WORKER_FILES * workers, f"a Dask LocalCluster of {workers_named(workers)}")
        with _children_ignore_interrupt():
            # a pair's failure reaches g2s through its future; Dask's own ERROR lines (a worker's heartbeat to a
            # scheduler that Ctrl-C is closing, seen under load) would break the one-line "g2s: interrupted"
            cluster = LocalCluster(
                n_workers=workers, threads_per_worker=1,
                processes=True, dashboard_address=":0", silence_logs=logging.CRITICAL,
            )
        client = Client(cluster)
    # pure=False: a pair is run again when asked again (resume decides what is finished, not Dask's cache)
    futures = {client.submit(function, item, pure=False): item for item in items}
    with interrupts_held() as interrupts:  # acted on once the cluster is closed (INTERRUPT_POLL)
        try:
            suspects = yield from _finished(futures, cluster, interrupts, lost)
            while suspects and not interrupts:
                item, *suspects = suspects
                alone = {client.submit(function, item, pure=False): item}
                futures.update(alone)  # to be cancelled with the others
                killed = yield from _finished(alone, cluster, interrupts, lost, later=suspects)
                if killed is None:  # no worker left: the suspects were lost with it
                    break
                if killed:
                    yield lost(item, "every Dask worker that held it died")
        finally:
            client.cancel([f for f in futures if not f.done()])
            client.close()
            if cluster is not None:
                cluster.close()


def _finished(
    futures: dict[Any, Any], cluster: Any, interrupts: list[int], lost: Callable[[Any, str], dict[str, Any]],
    later: Sequence[Any] = (),
) -> Generator[dict[str, Any], None, list[Any] | None]:
    """Yield the row of each of ``futures`` (future: item) as it finishes; return the items whose workers all died
    (Dask's ``KilledWorker``), in the order they did, to run again. Stops early on an interrupt.

    When the local ``cluster`` (``None``: a scheduler's) has gone :data:`NO_WORKERS_LIMIT` seconds without a worker,
    the items not finished, those to run again and the items ``later`` are ``lost``, and ``None`` is returned."""
    from dask.distributed import as_completed
    from distributed.scheduler import KilledWorker

    suspects: list[Any] = []
    unread = set(futures)

    def rows(finished: Sequence[Any]) -> Iterator[dict[str, Any]]:
        for future in finished:
            unread.discard(future)
            try:
                row = future.result()
            except KilledWorker:  # it killed its workers, or waited on a worker another item killed
                suspects.append(futures[future])
                continue
            yield row

    completed = as_completed(futures)
    staffed = time.monotonic()
    while not (interrupts or completed.is_empty()):
        finished = completed.next_batch(block=False)
        if cluster is None or cluster.scheduler_info.get("workers"):
            staffed = time.monotonic()
        elif not finished and time.monotonic() - staffed > NO_WORKERS_LIMIT:
            # one look at each: a pair that finished since the batch above is yielded, one finishing after it is
            # lost, none is left without its row
            done = {future: future.done() for future in futures if future in unread}
            yield from rows([future for future in done if done[future]])
            left = [futures[future] for future in done if not done[future]]
            yield from (lost(item, NO_WORKERS) for item in [*left, *suspects, *later])
            return None
        if not finished:
            time.sleep(INTERRUPT_POLL)
        yield from rows(finished)
    return suspects
