"""Fixtures of the reliability suite."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.reliability.checks import QUICK_CONFIG


@pytest.fixture
def quick_config(tmp_path: Path) -> Path:
    path = tmp_path / "quick.yaml"
    path.write_text(QUICK_CONFIG)
    return path
