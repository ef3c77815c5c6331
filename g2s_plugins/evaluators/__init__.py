"""Evaluator plugins: measures of how good a run's result is (``evaluators:`` in the config)."""
