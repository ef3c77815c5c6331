"""Inputs robust11 (4-5 December 2026) found ending in an internal error, a hang, a library's words or read silently
wrong, each test failing on the code before its fix (docs/errors.md, "The hostile-user pass of robust11")."""

from __future__ import annotations

import os
import signal

import pytest

from tests.reliability.checks import CORRIDOR, run_g2s, tree


def test_an_interrupt_that_trimesh_swallows_and_then_fails_on_is_an_interrupt(tmp_path, monkeypatch, capsys):
    # SIGTERM 2.2 s into `g2s run` (trimesh loading, load 10 on 2 cores): trimesh caught the KeyboardInterrupt while it
    # imported its optional parts, kept it as a placeholder, and failed on it a line later (`Path3D | None`:
    # TypeError); the run ended `g2s: internal error: TypeError: unsupported operand type(s) for |: 'ExceptionWrapper'
    # and 'NoneType'`, exit 1, blaming g2s for the user's own interrupt
    from g2s_core import cli

    class Importing:  # a module whose loading swallows the interrupt, then fails as trimesh's does
        def __getattr__(self, attribute: str) -> object:
            try:
                os.kill(os.getpid(), signal.SIGTERM)
            except BaseException:  # as trimesh's imports do
                pass
            raise TypeError("unsupported operand type(s) for |: 'ExceptionWrapper' and 'NoneType'")

    monkeypatch.setattr(cli, "api", Importing())
    outcome = run_g2s(capsys, "run", "graph_only", CORRIDOR, "-o", tmp_path / "out", "-q")
    assert (outcome.code, outcome.stderr) == (130, "g2s: interrupted\n")
    assert tree(tmp_path / "out") == []
