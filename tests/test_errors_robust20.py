"""Inputs robust20 (6 December 2026) found breaking docs/errors.md's rules: ``g2s --help`` and ``--version`` with
both standard streams closed (exit 0, the help sent to the closed standard error's stream)."""

from __future__ import annotations

import sys

import pytest

from g2s_core.cli import main


def exit_code(args: list[str]) -> int:
    try:
        return main(args)
    except SystemExit as stopped:
        return stopped.code


@pytest.mark.parametrize("args", [["--help"], ["run", "--help"], ["--version"]])
def test_help_and_version_with_both_streams_closed_are_not_a_success(args, monkeypatch):
    # `g2s --help >&- 2>&-`: sys.stdout and sys.stderr are both None, and argparse's help, meant for standard output,
    # was taken for standard error's (`file is sys.stderr`), whose failed write is dropped: exit 0, nothing written
    monkeypatch.setattr(sys, "stdout", None)
    monkeypatch.setattr(sys, "stderr", None)
    assert exit_code(args) == 2
    assert exit_code(["run"]) == 2  # a usage error's line, meant for standard error, is dropped and its code stands


def test_help_with_standard_error_closed_is_written_and_a_usage_error_is_not(monkeypatch, capsys):
    monkeypatch.setattr(sys, "stderr", None)
    assert exit_code(["--help"]) == 0
    assert capsys.readouterr().out.startswith("usage: g2s ")
    assert exit_code(["run"]) == 2
    assert capsys.readouterr().out == ""  # the error line does not go to standard output
