"""``graph.json``: the initial surface graph in networkx node-link form.

Keys are sorted and floats written with ``repr`` precision, so the same mesh
and config give byte-identical files.
"""

from __future__ import annotations

import json
from pathlib import Path

import networkx as nx

from g2s_core.model import RunResult
from g2s_plugins.outputs.files import atomic_write


def write(result: RunResult, outdir: Path) -> list[Path]:
    """``graph.json`` in ``outdir``: the initial graph as networkx node-link JSON, with the mesh's name and
    SHA-256; nothing when the run built no graph."""
    if result.graph is None:
        return []
    data = nx.node_link_data(result.graph, edges="edges")
    data["mesh"] = {"name": result.mesh_name, "sha256": result.mesh_sha256}
    text = json.dumps(data, sort_keys=True, indent=1, default=_plain)
    return [atomic_write(outdir / "graph.json", text.encode("utf-8"))]


def _plain(value: object) -> object:
    """numpy scalars and arrays as plain JSON values."""
    if hasattr(value, "tolist"):
        return value.tolist()
    raise TypeError(f"cannot write {type(value).__name__} to JSON")
