"""A pool of worker processes on this machine (concurrent.futures).

Ctrl-C lets the running pairs finish, and a pair whose worker dies (killed for want of memory, a crash in native code)
fails alone."""

from __future__ import annotations

import multiprocessing
import os
import signal
import threading
from collections.abc import Callable, Generator, Iterator, Sequence
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool
from contextlib import contextmanager
from typing import Any

from pydantic import Field

from g2s_core.plugin import PluginParams, hookimpl
from g2s_core.result_folder import interrupts_held
from g2s_plugins.executors import INTERRUPT_POLL, require_open_files, workers_named

NAME = "local"

POOL_FILES = 10
"""Files (pipes, sockets) the pool opens in this process besides two a worker (:data:`WORKER_FILES`), counting those
it opens as it starts a worker: with 6 open before, 2 pairs of ``graph_only`` ran under ``ulimit -n`` 18 on one worker
and 20 on two, and failed under 16 and 18 (the pool then holds 16 and 18 open; 22 on four workers; robust15)."""

WORKER_FILES = 2
"""Files the pool holds in this process for each worker it starts (measured as :data:`POOL_FILES`)."""

DIED = "its worker process died as it ran"
"""Why a pair whose worker died failed: the pool cannot tell a signal's kind."""


class PoolThreadDied(RuntimeError):
    """A thread of the pool itself could not start or died: the pairs it would have handed out never finish."""


class Params(PluginParams):
    """The pool's size."""

    workers: int | None = Field(None, ge=1, description="worker processes (default: the CPU count)")


def _ignore_interrupt() -> None:
    """Pool workers leave Ctrl-C to the batch, which lets their running pair finish."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)


@hookimpl
def g2s_execute(
    function: Callable[[Any], dict[str, Any]], items: Sequence[Any], params: Params, lost: Callable[[Any, str], dict[str, Any]]
) -> Iterator[dict[str, Any]]:
    """Each item in a worker process, yielded as it finishes; an item whose worker died is ``lost``, the others run.

    A worker's death breaks the whole pool (concurrent.futures stops its other workers and fails every item not
    finished). The item that killed it was one of the first ``workers`` items left unfinished (the pool hands its
    items out in order, one to each worker): those run again one at a time, in a pool of one worker, where the item
    whose worker dies is the first one left; then the rest runs in a whole pool again.
    """
    size = params.workers or os.cpu_count() or 1
    waiting = list(items)
    started = min(size, len(waiting))  # the pool starts a worker as an item waits for one, up to ``size``
    if started:
        require_open_files(POOL_FILES + WORKER_FILES * started, f"the local executor's pool of {workers_named(started)}")
    while waiting:
        left = yield from _pooled(function, waiting, size)
        suspects, waiting = left[:size], left[size:]
        while suspects:
            left = yield from _pooled(function, suspects, 1)
            if left:
                yield lost(left[0], DIED)
            suspects = left[1:]


def _pooled(function: Callable[[Any], dict[str, Any]], items: Sequence[Any], workers: int) -> Generator[dict[str, Any], None, list[Any]]:
    """Yield ``function(item)`` for ``items`` from a pool of ``workers`` as each finishes; return the items left
    unfinished, in their order, when a worker died (none when every item ran).

    A Ctrl-C is taken between waits and acted on once the pool has shut down (:data:`INTERRUPT_POLL`).

    Raises:
        PoolThreadDied: a thread of the pool could not start or died (under a tight memory limit: ``ulimit -v``).
    """
    earlier = set(multiprocessing.active_children())
    with interrupts_held() as interrupts, _thread_deaths() as deaths:
        # forkserver: workers start from a clean process, not a copy of one with a progress thread running
        pool = ProcessPoolExecutor(workers, multiprocessing.get_context("forkserver"), _ignore_interrupt)
        futures: dict[Any, Any] = {}
        try:
            try:
                futures = {pool.submit(function, item): item for item in items}
            except RuntimeError as exc:  # `can't start new thread`: the pool starts its own with the first item
                if "can't start new thread" not in str(exc):
                    raise
                deaths.append(exc)
            pending = set(futures)
            # dead, the pool's thread (which could not start the one feeding its workers) left them waiting for ever
            while pending and not (interrupts or deaths):
                finished, pending = wait(pending, timeout=INTERRUPT_POLL, return_when=FIRST_COMPLETED)
                for future in finished:
                    if not isinstance(future.exception(), BrokenProcessPool):
                        yield future.result()
        finally:  # also on Ctrl-C or when the batch closes the iterator: the running pairs finish, the others are dropped
            if deaths:  # its workers wait on a queue no thread feeds, and the interpreter's exit would wait on them
                for process in set(multiprocessing.active_children()) - earlier:
                    process.terminate()
            pool.shutdown(wait=not deaths, cancel_futures=True)  # a thread that never started cannot be joined
    if deaths:
        raise PoolThreadDied(f"the pool cannot run its threads ({type(deaths[0]).__name__}: {deaths[0]}; under a "
                             "memory limit? --executor serial needs none)") from deaths[0]
    return [item for future, item in futures.items() if isinstance(future.exception(), BrokenProcessPool)]


@contextmanager
def _thread_deaths() -> Iterator[list[BaseException]]:
    """The exceptions that end a thread started in the block (the pool's), kept (not printed as a traceback) for the
    block to see; a thread started before it dies as it would have."""
    deaths: list[BaseException] = []
    earlier = set(threading.enumerate())
    previous = threading.excepthook

    def take(died: Any) -> None:
        if died.thread in earlier:
            previous(died)
        else:
            deaths.append(died.exc_value or RuntimeError("a thread died"))

    threading.excepthook = take
    try:
        yield deaths
    finally:
        threading.excepthook = previous
