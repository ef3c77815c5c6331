"""The built-in output writers, as plugins (entry points ``outputs.<format>`` in pyproject.toml).

Each writer is a small object with the plugin's ``NAME`` (the format),
``FILES`` and summary; its module is imported when it first writes, because
plotly and matplotlib take a while to import and most commands never write
those formats. Each writes with CPython's cyclic collector paused (:func:`collector_paused`).
"""

from __future__ import annotations

import gc
import importlib
import os
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from g2s_core.errors import G2SError
from g2s_core.model import RunResult
from g2s_core.plugin import hookimpl


class LazyWriter:
    """An output-writer plugin whose ``write(result, folder)`` lives in ``g2s_plugins.outputs.<module>``."""

    def __init__(self, name: str, module: str, files: tuple[str, ...], summary: str) -> None:
        self.NAME = name
        self.FILES = files
        self.__doc__ = summary
        self.module = f"g2s_plugins.outputs.{module}"

    @hookimpl
    def g2s_write_output(self, result: RunResult, folder: Path) -> list[Path]:
        with collector_paused():
            try:
                return importlib.import_module(self.module).write(result, folder)
            except ValueError:
                if (backend := refused_backend()) is None:
                    raise
                raise G2SError(f"MPLBACKEND: expected a backend matplotlib knows (e.g. agg), got {backend!r}: the "
                               f"environment's, which matplotlib reads as it loads to draw the {self.NAME} output") from None

    def __repr__(self) -> str:
        return f"LazyWriter({self.NAME!r}, {self.module})"


def refused_backend() -> str | None:
    """The environment's ``MPLBACKEND`` when matplotlib refuses it as it loads, else ``None``: the ``ValueError`` of
    its import failed the writers that draw with matplotlib (``png``, and ``html`` and ``glb`` for their colour scale),
    exit 1, blaming them; the writers draw on Agg's canvas, without pyplot, whatever backend it names."""
    if (backend := os.environ.get("MPLBACKEND")) is None:
        return None
    try:
        importlib.import_module("matplotlib")
    except ValueError:
        return backend
    return None


@contextmanager
def collector_paused() -> Iterator[None]:
    """CPython's cyclic collector off in the block, then back as it was.

    A writer makes hundreds of thousands of short-lived objects (tubes, XML elements, records), none in a
    cycle, and each full collection that their allocations set off walks every object of the run as well
    (its graphs with their attribute dicts): on the 100k-polygon level, a third of the GraphML writer's time
    at load 4.5 (docs/performance.md). Nothing collectable is lost: the
    collector runs again as soon as it is back on.
    """
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()


json = LazyWriter("json", "structure_json", ("structure.json", "run.json"),
                  "The structure (deterministic) and the run's record: structure.json, run.json.")
html = LazyWriter("html", "html_report", ("report.html",), "A self-contained interactive report: report.html.")
glb = LazyWriter("glb", "gltf", ("structure.glb",), "Mesh, navmesh and structure as binary glTF: structure.glb.")
graphml = LazyWriter("graphml", "graphml", ("structure.graphml", "graph.graphml"),
                     "Final structure and initial graph for networkx, Gephi, yEd: structure.graphml, graph.graphml.")
png = LazyWriter("png", "heatmap", ("heatmap.png",), "A top-down heat map, one panel per floor: heatmap.png.")
graph = LazyWriter("graph", "graph_json", ("graph.json",), "The initial graph as networkx node-link JSON: graph.json.")
