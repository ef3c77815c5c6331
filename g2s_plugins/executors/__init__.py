"""Executor plugins: where the pairs of a batch run (``g2s batch --executor NAME``)."""
