"""The built-in output writers (plugins, see :mod:`g2s_plugins.outputs.writers`), chosen by format
name in the config or on the CLI; :mod:`g2s_core.outputs` manages the output folder. The ``json``
format is also read back (:mod:`g2s_plugins.outputs.json_reader`, a ResultReader plugin).

Every writer takes the :class:`~g2s_core.model.RunResult` and the output folder
and returns the paths it wrote. The writers of a run write into one staging
folder whose files then move into the output folder together
(:mod:`g2s_core.result_folder`), so a failed run never leaves half a result.

=========  ==========================================  =====================================
format     files                                       what
=========  ==========================================  =====================================
json       structure.json, run.json                    the structure (deterministic), timings
html       report.html                                 self-contained interactive report
glb        structure.glb                               mesh, navmesh and structure, binary glTF
graphml    structure.graphml, graph.graphml            final structure and initial graph
png        heatmap.png                                 top-down heat map, one panel per floor
graph      graph.json                                  initial graph, networkx node-link JSON
=========  ==========================================  =====================================

See ``docs/outputs.md`` for the details of each format.
"""

from typing import Any

from g2s_core.model import LoadedResult

__all__ = ["LoadedResult", "load_result"]


def __getattr__(name: str) -> Any:
    # the reader imports networkx and scipy; the writers' plugin objects in this package, which every
    # command lists, import neither
    if name == "load_result":
        from g2s_plugins.outputs.json_reader import load_result

        return load_result
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
