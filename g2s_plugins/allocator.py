"""The C allocator's large blocks: handed back to the system when freed, not kept for later ones.

glibc's ``malloc`` serves a block of at least its mmap threshold (128 KiB at start) with a mapping of its own,
unmapped when the block is freed. But freeing such a block raises the threshold to the block's size (up to
32 MiB on 64-bit), so later blocks of up to that size come from the heaps (one per thread that allocates),
where freed memory goes back to the system only from a heap's top. numpy's arrays are such blocks: a run that
makes and drops arrays of a few MiB by the thousand (the sampling route's ray batches and walk tests on two
threads, the walking flows' trees) keeps most of what its busiest moments held, resident, to its end. On the
100k-polygon level that was more than half the sampling route's peak (docs/performance.md, mem48). A threshold
set by ``mallopt`` is no longer moved, so every block from 128 KiB up is unmapped when freed again.

Other C libraries (macOS, Windows, musl) decide for themselves: nothing is set there.
"""

from __future__ import annotations

import ctypes
import functools
import sys

M_MMAP_THRESHOLD = -3
"""glibc's ``mallopt`` parameter number for the mmap threshold (``malloc.h``)."""

LARGE_BLOCK = 128 * 1024
"""Bytes: blocks this large or larger get a mapping of their own (glibc's own starting threshold)."""


@functools.cache
def hand_back_large_blocks() -> bool:
    """Fix glibc's mmap threshold at :data:`LARGE_BLOCK` for this process (once; later calls do nothing).

    Returns whether it was set (``False`` on a system without glibc's ``mallopt``). Values computed do not
    depend on it, only the resident memory and the time the system takes to map and unmap the blocks.
    """
    if not sys.platform.startswith("linux"):
        return False
    try:
        libc = ctypes.CDLL(None)  # the process's own C library
    except OSError:
        return False
    mallopt = getattr(libc, "mallopt", None)
    return mallopt is not None and mallopt(M_MMAP_THRESHOLD, LARGE_BLOCK) == 1
