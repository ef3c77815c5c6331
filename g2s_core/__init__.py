"""g2s core: stage interfaces (pluggy hooks), plugin registry, YAML config, pipeline and Python API.

The stage implementations live in plugins (``g2s_plugins`` for the built-in
ones), discovered through the ``g2s`` entry-point group. ``g2s_core.run`` and
``g2s_core.load_result`` are the Python API (:mod:`g2s_core.api`, docs/python.md).
"""

import importlib.metadata
from typing import Any

from g2s_core.model import NavMesh, Opening, RunContext, RunResult, StageStats, Terminals
from g2s_core.plugin import PluginParams, hookimpl, hookspec

DISTRIBUTION = "graph2structure"
"""The name g2s is published and installed under (``pip install graph2structure``)."""

__all__ = [
    "DISTRIBUTION", "NavMesh", "Opening", "PluginParams", "RunContext", "RunResult", "StageStats", "Terminals",
    "hookimpl", "hookspec", "load_result", "run", "version",
]


def version() -> str:
    """The installed g2s version, ``"unknown"`` when run from a checkout that is not installed."""
    try:
        return importlib.metadata.version(DISTRIBUTION)
    except importlib.metadata.PackageNotFoundError:
        return "unknown"


def __getattr__(name: str) -> Any:
    # the API imports the pipeline and the built-in writers, which import this
    # package: load it on first use rather than at import
    if name in ("run", "load_result"):
        from g2s_core import api

        return getattr(api, name)
    raise AttributeError(f"module 'g2s_core' has no attribute {name!r}")
