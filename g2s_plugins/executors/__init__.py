"""Executor plugins: where the pairs of a batch run (``g2s batch --executor NAME``)."""

INTERRUPT_POLL = 0.1
"""Seconds between two looks for a Ctrl-C while an executor waits on its pairs.

An executor that waits on a library's futures holds Ctrl-C back (:func:`g2s_core.result_folder.interrupts_held`),
looks for it between waits and acts on it once its workers are stopped: a KeyboardInterrupt raised inside the
library's wait could leave one of its locks held, and the shutdown then waited for ever (concurrent.futures: a pool of
quick items interrupted at random hung within 2 to 11 tries in each of 7 runs; 100 tries since, none).
"""
