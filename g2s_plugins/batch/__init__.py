"""Batch runs over many levels: the ``g2s batch`` command (``command``) and the runner it and Python scripts use (``runner``).

``from g2s_plugins.batch.runner import run_batch`` (docs/batch.md);
``g2s_core.batch`` re-exports the same names.
"""
