"""Inputs robust44 (6 December 2026) found breaking docs/errors.md's rules: ``g2s batch`` with a networkx setting of
the environment that networkx refuses, an internal error (exit 1)."""

from __future__ import annotations

import pytest

from tests.reliability.checks import CORRIDOR, assert_clean_error, run_g2s_process, tree


@pytest.mark.parametrize("name, value, says", [
    ("NETWORKX_BACKEND_PRIORITY", "nosuch", "Unknown backend when setting 'algos': 'nosuch'"),
    ("NETWORKX_WARNINGS_TO_IGNORE", "nosuch", "Unknown warning when setting 'warnings_to_ignore': 'nosuch'"),
])
def test_a_batch_with_networkx_settings_that_it_refuses_names_them(name, value, says, monkeypatch, tmp_path):
    # was exit 1, "internal error: ValueError: ...": the batch runner imported networkx through g2s_core.pipeline,
    # unguarded, before the API's import that names them (a child process, where networkx is not loaded yet)
    monkeypatch.setenv(name, value)
    outcome = run_g2s_process("batch", "graph_only", CORRIDOR, "-o", tmp_path / "out", "--executor", "serial")
    assert_clean_error(outcome, f"{name}={value!r}: networkx refused the environment's setting as it loaded ({says}")
    assert tree(tmp_path / "out") == []
