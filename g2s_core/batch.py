"""Batch runs from Python, where issue 13 documented them: ``g2s_core.batch.run_batch(configs, inputs, outdir, executor=...)``.

The implementation lives in :mod:`g2s_plugins.batch` (the runner and the
``g2s batch`` command plugin); this module re-exports the names scripts and
docs import, so that code written against this path keeps working. It is the
one module of the core that imports a plugin (tests/test_architecture.py
names it).
"""

from g2s_core.entry import entry_points_readable

with entry_points_readable():  # another package's broken entry_points.txt is named, not importlib's traceback
    from g2s_plugins.batch.runner import COLUMNS, METRIC_PREFIX, RECORDS, Pair, Progress, expand_inputs, run_batch, run_pair

__all__ = ["COLUMNS", "METRIC_PREFIX", "RECORDS", "Pair", "Progress", "expand_inputs", "run_batch", "run_pair"]
