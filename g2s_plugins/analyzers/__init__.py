"""Analyzer plugins: a value for every node of the final structure (the paper's post-process)."""
