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
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from typing import Any

from pydantic import Field

from g2s_core.errors import G2SError
from g2s_core.plugin import PluginParams, hookimpl
from g2s_core.result_folder import interrupts_held
from g2s_plugins.executors import INTERRUPT_POLL

NAME = "dask"


class Params(PluginParams):
    """Which cluster."""

    scheduler: str | None = Field(None, description="address of a running scheduler, e.g. tcp://host:8786 "
                                  "(default: start a LocalCluster and close it at the end)")
    workers: int | None = Field(None, ge=1, description="processes of the LocalCluster (default: the CPU count)")


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
    run (Dask tries it on another worker first: ``distributed.scheduler.allowed-failures``, 3 by default).

    The cluster holds at most as many items as its workers have threads, the others wait here: Dask sends a worker
    more items than it runs at once (a batch of fewer than twice the threads all at once), and an item waiting on a
    worker that another item kills is as suspect to Dask as the killer, and was lost with it.
    """
    from dask.distributed import Client, LocalCluster, as_completed
    from distributed.scheduler import KilledWorker

    if params.scheduler:
        cluster = None
        try:
            client = Client(params.scheduler)
        except (OSError, ValueError) as exc:  # the user's address, not this plugin, is at fault
            raise G2SError(f"--scheduler: expected the address of a running Dask scheduler (tcp://host:8786), got "
                           f"{params.scheduler!r}: {' '.join(str(exc).split())}") from exc
    else:
        with _children_ignore_interrupt():
            # a pair's failure reaches g2s through its future; Dask's own ERROR lines (a worker's heartbeat to a
            # scheduler that Ctrl-C is closing, seen under load) would break the one-line "g2s: interrupted"
            cluster = LocalCluster(
                n_workers=params.workers or os.cpu_count(), threads_per_worker=1, processes=True,
                dashboard_address=":0", silence_logs=logging.CRITICAL,
            )
        client = Client(cluster)
    waiting, running, completed = list(items), {}, as_completed()

    def submit_more() -> None:
        """Items onto the cluster while it has a thread free (one at least, while its workers start or restart)."""
        while waiting and len(running) < max(1, sum(client.nthreads().values())):
            item = waiting.pop(0)
            future = client.submit(function, item, pure=False)  # run again when asked again (resume decides, not a cache)
            running[future] = item
            completed.add(future)

    with interrupts_held() as interrupts:  # acted on once the cluster is closed (INTERRUPT_POLL)
        try:
            submit_more()
            while not (interrupts or completed.is_empty()):
                finished = completed.next_batch(block=False)
                if not finished:
                    time.sleep(INTERRUPT_POLL)
                for future in finished:
                    item = running.pop(future)
                    try:
                        row = future.result()
                    except KilledWorker:  # which ended the batch, exit 1 blaming this plugin in Dask's 600 characters
                        row = lost(item, "every Dask worker that held it died")
                    submit_more()
                    yield row
        finally:
            client.cancel(list(running))
            client.close()
            if cluster is not None:
                cluster.close()
