"""``structure.json`` (deterministic) and ``run.json`` (timings); :mod:`g2s_plugins.outputs.json_reader` reads them back.

``structure.json`` holds what a run found: the input mesh's name and SHA-256,
the resolved config, the navmesh statistics, every node and edge of the final
structure with its tree data and analysis values, the rooted trees, the
terminals and openings, the sizes (and edges) of the Steiner tree and the
rooted trees before simplification, the node/edge counts of every stage and
the warnings. Its layout is described by ``structure.schema.json`` beside this module
(``schema_version`` 3: version 1 plus ``features``, the records
analyzers such as ``chokepoints`` and ``regions`` return (version 2), plus
``metrics``, the evaluators' measures (version 3); older files are still read).
``terminals.waypoint_ids``, the selector's waypoints, came later without a new
version: it is written only when there are waypoints, so the file of a run
without them did not change (docs/outputs.md).

Determinism rule: the same mesh and config give a byte-identical
``structure.json``. Keys are sorted, lists are in a fixed order (nodes and
edges by id), floats are rounded to 9 significant digits (``format(x,
'.9g')``; the components of 3-vectors also to 5 decimals, finer from 10^4 m
out; ``-0.0`` written as
``0.0``, non-finite values as ``null``), and
nothing that varies between runs is written to it: wall times (stage seconds,
the navmesh build time) and the g2s version go to ``run.json`` instead.
"""

from __future__ import annotations

import platform
from pathlib import Path
from typing import Any

import networkx as nx
import numpy as np

from g2s_core import version
from g2s_core.model import Opening, RunResult
from g2s_plugins.outputs.common import edge_list, final_graph, number, roots_of, terminal_ids, tree_parents, vector
from g2s_plugins.outputs.files import atomic_write
from g2s_plugins.outputs.json_text import dumps_indented
from g2s_plugins.outputs.writers import collector_paused

SCHEMA_VERSION = 3
STRUCTURE_FILE = "structure.json"
RUN_FILE = "run.json"
RUN_SCHEMA_VERSION = 1
SCHEMA_PATH = Path(__file__).resolve().parent / "structure.schema.json"
"""The layout of ``structure.json``, version :data:`SCHEMA_VERSION` (JSON Schema draft 2020-12)."""
RUN_SCHEMA_PATH = Path(__file__).resolve().parent / "run.schema.json"
"""The layout of ``run.json``, version :data:`RUN_SCHEMA_VERSION`."""

_NODE_KEYS = ("pos", "normal", "area", "on_navmesh", "polygon", "terminal", "depth", "root", "values")
_EDGE_KEYS = ("weight",)
_TIMING_WORDS = ("seconds", "time")


# --- writing -----------------------------------------------------------------


def write(result: RunResult, outdir: Path) -> list[Path]:
    """Write ``structure.json`` and ``run.json`` into ``outdir``."""
    with collector_paused():  # also when called directly, not as the plugin (benchmarks/structure_write.py)
        structure = atomic_write(outdir / STRUCTURE_FILE, dumps(structure_document(result)))
    run = atomic_write(outdir / RUN_FILE, dumps(run_document(result)))
    return [structure, run]


def dumps(document: dict[str, Any]) -> bytes:
    """The fixed JSON form: sorted keys, one-space indent, UTF-8, final newline.

    The text of ``json.dumps(document, sort_keys=True, indent=1,
    ensure_ascii=False, allow_nan=False)``, character for character, from
    :func:`g2s_plugins.outputs.json_text.dumps_indented` (the standard
    library's indented encoder is pure Python).
    """
    return (dumps_indented(document) + "\n").encode("utf-8")


def structure_document(result: RunResult) -> dict[str, Any]:
    """The content of ``structure.json`` as plain Python data."""
    stage, graph = final_graph(result)
    keys = list(result.analysis)
    terminals = set(terminal_ids(result))
    nodes: list[dict[str, Any]] = []
    edges: list[dict[str, Any]] = []
    roots: list[int] = []
    trees: list[dict[str, Any]] = []
    if graph is not None:
        roots = roots_of(graph)
        parents = tree_parents(graph)
        for node in sorted(graph.nodes):
            nodes.append(_node_record(graph, node, terminals, result.analysis, keys, parents.get(node)))
        for u, v in edge_list(graph):
            attrs = graph.edges[u, v]
            edges.append({
                "source": u,
                "target": v,
                "weight": _optional_number(attrs.get("weight")),
                "extra": _extra(attrs, _EDGE_KEYS),
            })
        for root in roots:
            members = sorted({root, *nx.descendants(graph, root)})
            trees.append({
                "root": root,
                "node_ids": members,
                "edges": len(members) - 1,
                "max_depth": max(int(graph.nodes[n].get("depth", 0)) for n in members),
            })
    mesh = result.context.mesh
    document: dict[str, Any] = {
        "schema_version": SCHEMA_VERSION,
        "format": "g2s-structure",
        "units": "m",
        "up_axis": "y",
        "mesh": {
            "name": result.mesh_name,
            "sha256": result.mesh_sha256,
            "vertices": int(len(mesh.vertices)) if mesh is not None else None,
            "faces": int(len(mesh.faces)) if mesh is not None else None,
            "bounds": [vector(b) for b in np.asarray(mesh.bounds)] if mesh is not None else None,
        },
        "config": _plain(result.config),
        "navmesh": _navmesh_stats(result, timing=False),
        "final_stage": stage,
        "directed": bool(graph is not None and graph.is_directed()),
        "roots": roots,
        "analysis_keys": keys,
        "features": _plain(result.features),
        "metrics": _plain(result.metrics),
        "nodes": nodes,
        "edges": edges,
        "trees": trees,
        "terminals": None if result.terminals is None else _terminals(result),
        "graphs": {
            "graph": _size(result.graph),
            "steiner": _with_edges(result.steiner),
            "forest": _with_edges(result.forest),
            "structure": _size(result.structure),
        },
        "stages": [
            {"stage": s.stage, "nodes": s.nodes, "edges": s.edges, "terminals": s.terminals} for s in result.stages
        ],
        "warnings": list(result.warnings),
    }
    return document


def run_document(result: RunResult) -> dict[str, Any]:
    """The content of ``run.json``: what varies between runs (times, versions)."""
    return {
        "schema_version": RUN_SCHEMA_VERSION,
        "format": "g2s-run",
        "mesh": {"name": result.mesh_name, "sha256": result.mesh_sha256},
        "stages": [
            {"stage": s.stage, "seconds": float(s.seconds), "nodes": s.nodes, "edges": s.edges, "terminals": s.terminals}
            for s in result.stages
        ],
        "total_seconds": float(result.total_seconds),
        "navmesh": _navmesh_stats(result, timing=True),
        "g2s_version": version(),
        "python": platform.python_version(),
    }


def _node_record(
    graph: nx.Graph, node: int, terminals: set[int], analysis: dict, keys: list[str], parent: int | None
) -> dict[str, Any]:
    attrs = graph.nodes[node]
    return {
        "id": int(node),
        "position": vector(attrs["pos"]),
        "normal": vector(attrs.get("normal")),
        "area": _optional_number(attrs.get("area")),
        "on_navmesh": None if attrs.get("on_navmesh") is None else bool(attrs["on_navmesh"]),
        "polygon": None if attrs.get("polygon") is None else int(attrs["polygon"]),
        "terminal": int(node) in terminals or bool(attrs.get("terminal", False)),
        "root": None if attrs.get("root") is None else int(attrs["root"]),
        "depth": None if attrs.get("depth") is None else int(attrs["depth"]),
        "parent": parent,
        "values": {key: number(analysis[key][node]) for key in keys if node in analysis[key]},
        "extra": _extra(attrs, _NODE_KEYS),
    }


def _terminals(result: RunResult) -> dict[str, Any]:
    """Step 2's result: the terminals, the openings and, only when there are any, the waypoints (so that the
    file of a run without waypoints is the same as before they were recorded)."""
    terminals: dict[str, Any] = {
        "node_ids": terminal_ids(result),
        "openings": [_opening(o) for o in result.terminals.openings],
    }
    if result.terminals.waypoints:
        terminals["waypoint_ids"] = [int(w) for w in result.terminals.waypoints]
    return terminals


def _opening(opening: Opening) -> dict[str, Any]:
    return {
        "position": vector(opening.position),
        "heading": vector(opening.heading),
        "width": number(opening.width),
        "p0": vector(opening.p0),
        "p1": vector(opening.p1),
        "score": None if opening.score is None else number(opening.score),
        "reason": opening.reason,
    }


def _size(graph: nx.Graph | None) -> dict[str, int] | None:
    if graph is None:
        return None
    return {"nodes": graph.number_of_nodes(), "edges": graph.number_of_edges()}


def _with_edges(graph: nx.Graph | None) -> dict[str, Any] | None:
    if graph is None:
        return None
    data: dict[str, Any] = dict(_size(graph) or {})
    data["node_ids"] = sorted(int(n) for n in graph.nodes)
    data["edge_list"] = [list(e) for e in edge_list(graph)]
    if graph.is_directed():
        data["roots"] = roots_of(graph)
    return data


def _navmesh_stats(result: RunResult, timing: bool) -> dict[str, Any] | None:
    """``navmesh.stats()`` split in its timing entries (``timing=True``) and the rest."""
    navmesh = result.context.navmesh
    if navmesh is None:
        return None
    values = navmesh.stats()
    chosen = {str(k): v for k, v in values.items() if any(w in str(k) for w in _TIMING_WORDS) == timing}
    return _plain(chosen)


def _optional_number(value: Any) -> float | None:
    return None if value is None else number(value)


class _Skip:
    """Marks a value that JSON cannot hold faithfully."""


_SKIP = _Skip()


def _plain(value: Any) -> Any:
    """``value`` as JSON data with rounded floats; :data:`_SKIP` for what cannot be written."""
    kind = type(value)  # the plain types first, by identity: most attribute values are (a quarter of the writing)
    if kind is float:
        return number(value)
    if kind is int or kind is str or kind is bool or value is None:
        return value
    if kind is not dict and kind is not tuple and kind is not list:  # so are the containers (the edges' portals)
        if isinstance(value, str):
            return value
        if isinstance(value, (bool, np.bool_)):
            return bool(value)
        if isinstance(value, (int, np.integer)):
            return int(value)
        if isinstance(value, (float, np.floating)):
            return number(value)
        if isinstance(value, (set, frozenset)):
            try:
                value = sorted(value)
            except TypeError:
                return _SKIP
        elif isinstance(value, np.ndarray):
            value = value.tolist()
        elif not isinstance(value, (dict, list, tuple)):
            return _SKIP
    if isinstance(value, dict):
        items = {str(k): _plain(v) for k, v in value.items()}
        return {k: v for k, v in items.items() if v is not _SKIP}
    if len(value) == 3 and all(type(v) is float for v in value):  # a point or a direction (a portal's end)
        return vector(value)
    items = [_plain(v) for v in value]
    return _SKIP if any(i is _SKIP for i in items) else items


def _extra(attrs: dict[str, Any], known: tuple[str, ...]) -> dict[str, Any]:
    """Attributes beyond the documented ones that JSON can hold (plugins' own, e.g. ``width``)."""
    return _plain({k: v for k, v in attrs.items() if k not in known})
