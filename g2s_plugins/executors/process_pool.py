"""A pool of worker processes on this machine (concurrent.futures); Ctrl-C lets the running pairs finish."""

from __future__ import annotations

import os
import signal
from collections.abc import Callable, Iterator, Sequence
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from multiprocessing import get_context
from typing import Any

from pydantic import Field

from g2s_core.plugin import PluginParams, hookimpl

NAME = "local"


class Params(PluginParams):
    """The pool's size."""

    workers: int | None = Field(None, ge=1, description="worker processes (default: the CPU count)")


def _ignore_interrupt() -> None:
    """Pool workers leave Ctrl-C to the batch, which lets their running pair finish."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)


@hookimpl
def g2s_execute(
    function: Callable[[Any], dict[str, Any]], items: Sequence[Any], params: Params
) -> Iterator[dict[str, Any]]:
    """Each item in a worker process, yielded as it finishes."""
    # forkserver: workers start from a clean process, not a copy of one with a progress thread running
    pool = ProcessPoolExecutor(params.workers or os.cpu_count(), get_context("forkserver"), _ignore_interrupt)
    try:
        pending = {pool.submit(function, item) for item in items}
        while pending:
            finished, pending = wait(pending, return_when=FIRST_COMPLETED)
            for future in finished:
                yield future.result()
    finally:  # also on Ctrl-C or when the batch closes the iterator: the running pairs finish, the others are dropped
        pool.shutdown(wait=True, cancel_futures=True)
