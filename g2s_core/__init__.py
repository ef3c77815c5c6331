"""g2s core: stage interfaces (pluggy hooks), plugin registry, YAML config and pipeline.

The stage implementations live in plugins (``g2s_plugins`` for the built-in
ones), discovered through the ``g2s`` entry-point group.
"""

from g2s_core.model import NavMesh, Opening, RunContext, RunResult, StageStats, Terminals
from g2s_core.plugin import PluginParams, hookimpl, hookspec

__all__ = ["NavMesh", "Opening", "PluginParams", "RunContext", "RunResult", "StageStats", "Terminals", "hookimpl", "hookspec"]
