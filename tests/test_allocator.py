"""g2s_plugins.allocator: the free pages of the C heaps go back to the system."""

from __future__ import annotations

import platform
import sys

import numpy as np
import pytest

from g2s_plugins.allocator import hand_back_free_memory


def resident_mib() -> float:
    with open("/proc/self/status", encoding="ascii") as status:
        return next(int(line.split()[1]) for line in status if line.startswith("VmRSS:")) / 1024


@pytest.mark.skipif(not sys.platform.startswith("linux") or platform.libc_ver()[0] != "glibc", reason="glibc only")
def test_arrays_freed_under_a_kept_one_go_back_to_the_system():
    # Freeing 8 MiB arrays raises glibc's mmap threshold above 2 MiB; then 150 arrays of 2 MiB come from the heap,
    # and a copy made after them keeps the heap's top in use: freed, they stay resident until the heap is trimmed.
    for _ in range(3):
        np.ones(1 << 20)
    arrays = [np.full(1 << 18, float(i)) for i in range(150)]
    kept = arrays[-1].copy()
    del arrays
    before = resident_mib()
    assert hand_back_free_memory()
    assert resident_mib() < before - 200  # of the 300 MiB freed
    assert kept[0] == 149.0
