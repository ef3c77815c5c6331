"""Memory the C allocator holds free: handed back to the system where a stage's arrays are done with.

glibc's ``malloc`` serves a block of at least its mmap threshold (128 KiB at start) with a mapping of its own,
unmapped when the block is freed; but freeing such a block raises the threshold to the block's size (up to
32 MiB on 64-bit), so later blocks of up to that size come from the heaps (one per thread that allocates),
where freed memory goes back to the system only from a heap's top. numpy's arrays are such blocks: the sampling
builder's ray batches on two threads left 0.64 GiB free in the heaps on the 100k-polygon level, resident
to the run's end, which CPython's objects (in arenas of their own) do not reuse. ``malloc_trim`` hands back
every free page of every heap, once, where it is called; fixing the threshold instead (``mallopt``) unmapped
every block as it was freed, at 15 % more CPU on the 20k level (the system's time to map and clear the pages
again; docs/performance.md, mem48).

Other C libraries (macOS, Windows, musl) decide for themselves: nothing is done there.
"""

from __future__ import annotations

import ctypes
import functools
import sys
from collections.abc import Callable


@functools.cache
def _malloc_trim() -> Callable[[int], int] | None:
    """glibc's ``malloc_trim``, or ``None`` where the C library has none."""
    if not sys.platform.startswith("linux"):
        return None
    try:
        libc = ctypes.CDLL(None)  # the process's own C library
    except OSError:
        return None
    return getattr(libc, "malloc_trim", None)


def hand_back_free_memory() -> bool:
    """Hand the free pages of the C allocator's heaps back to the system (glibc's ``malloc_trim(0)``): resident
    memory falls, values computed do not change. Whether any was handed back (``False`` without glibc).

    Cost: a walk over the heaps' free blocks (milliseconds), and a page fault for each page handed back that a
    later block uses again.
    """
    trim = _malloc_trim()
    return trim is not None and trim(0) == 1
