"""g2s core: stage interfaces (pluggy hooks), plugin registry, YAML config, pipeline and Python API.

The stage implementations live in plugins (``g2s_plugins`` for the built-in
ones), discovered through the ``g2s`` entry-point group. ``g2s_core.run`` and
``g2s_core.load_result`` are the Python API (:mod:`g2s_core.api`, docs/python.md).

The names below are imported on first use: the ``g2s`` console script imports
this package before it can catch a Ctrl-C (:mod:`g2s_core.entry`), so it
imports only the standard library.
"""

import importlib
from typing import Any

DISTRIBUTION = "graph2structure"
"""The name g2s is published and installed under (``pip install graph2structure``)."""

__all__ = [
    "DISTRIBUTION", "NavMesh", "Opening", "PluginParams", "RunContext", "RunResult", "StageStats", "Terminals",
    "hookimpl", "hookspec", "load_result", "run", "version",
]

_HOMES = {**dict.fromkeys(["NavMesh", "Opening", "RunContext", "RunResult", "StageStats", "Terminals"], "model"),
          **dict.fromkeys(["PluginParams", "hookimpl", "hookspec"], "plugin"), "run": "api", "load_result": "api"}
"""The module of :data:`__all__`'s names (``api`` imports the pipeline and the writers, which import this package)."""


def version() -> str:
    """The installed g2s version, ``"unknown"`` when run from a checkout that is not installed."""
    import importlib.metadata  # a tenth of a second: only --version and the run records need it

    try:
        return importlib.metadata.version(DISTRIBUTION)
    except importlib.metadata.PackageNotFoundError:
        return "unknown"


def __getattr__(name: str) -> Any:
    if name in _HOMES:
        return getattr(importlib.import_module(f"g2s_core.{_HOMES[name]}"), name)
    raise AttributeError(f"module 'g2s_core' has no attribute {name!r}")
