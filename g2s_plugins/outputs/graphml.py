"""``structure.graphml`` (the final structure) and ``graph.graphml`` (the initial graph).

GraphML holds only scalars, so attributes are flattened: a 3-vector ``pos``
becomes ``pos_x``, ``pos_y``, ``pos_z``; an (n, 3) array ``portal`` becomes
``portal_0_x`` ... ``portal_{n-1}_z``; other arrays ``name_0``, ``name_1`` ...;
``None`` values are left out (GraphML's "no data"). Floats are rounded as
in ``structure.json`` (:func:`g2s_plugins.outputs.common.number`, the
components of 3-vectors :func:`~g2s_plugins.outputs.common.coordinate`). Structure nodes also get ``terminal``, ``parent`` (absent
for roots) and one ``value_<key>`` per analysis value; the graph carries
``mesh_name``, ``mesh_sha256``, ``final_stage``, ``roots`` (comma-separated)
and ``analysis_keys``. Nodes and edges are written in ascending id order.
"""

from __future__ import annotations

import functools
import io
from pathlib import Path
from typing import Any

import networkx as nx
import numpy as np

from g2s_core.model import RunResult
from g2s_plugins.outputs.common import coordinate, edge_list, final_graph, number, roots_of, terminal_ids, tree_parents
from g2s_plugins.outputs.files import atomic_write

STRUCTURE_FILE = "structure.graphml"
GRAPH_FILE = "graph.graphml"
_AXES = ("x", "y", "z")


def write(result: RunResult, outdir: Path) -> list[Path]:
    """``structure.graphml`` (the final graph, :func:`~g2s_plugins.outputs.common.final_graph`) and ``graph.graphml``
    (the initial graph) in ``outdir``, each when the run has it."""
    written = []
    stage, graph = final_graph(result)
    terminals = set(terminal_ids(result))
    if graph is not None:
        flat = _flat_graph(graph, terminals, result.analysis)
        flat.graph.update(
            mesh_name=result.mesh_name,
            mesh_sha256=result.mesh_sha256,
            final_stage=stage or "",
            roots=",".join(str(r) for r in roots_of(graph)),
            analysis_keys=",".join(result.analysis),
        )
        written.append(atomic_write(outdir / STRUCTURE_FILE, _graphml_bytes(flat)))
    if result.graph is not None:
        flat = _flat_graph(result.graph, terminals, {})
        flat.graph.update(mesh_name=result.mesh_name, mesh_sha256=result.mesh_sha256)
        written.append(atomic_write(outdir / GRAPH_FILE, _graphml_bytes(flat)))
    return written


def _graphml_bytes(graph: nx.Graph) -> bytes:
    buffer = io.BytesIO()
    nx.write_graphml(graph, buffer, encoding="utf-8", prettyprint=True)
    return buffer.getvalue()


def _flat_graph(graph: nx.Graph, terminals: set[int], analysis: dict[str, dict[int, float]]) -> nx.Graph:
    flat: nx.Graph = nx.DiGraph() if graph.is_directed() else nx.Graph()
    parents = tree_parents(graph)
    for node in sorted(graph.nodes):
        attrs = flatten({k: v for k, v in graph.nodes[node].items() if k != "values"})  # written as value_<key>
        attrs["terminal"] = int(node) in terminals or bool(graph.nodes[node].get("terminal", False))
        if node in parents:
            attrs["parent"] = int(parents[node])
        for key, values in analysis.items():
            value = number(values[node]) if node in values else None
            if value is not None:
                attrs[f"value_{key}"] = value
        flat.add_node(int(node), **attrs)
    for u, v in edge_list(graph):
        flat.add_edge(u, v, **flatten(graph.edges[u, v]))
    return flat


def flatten(attrs: dict[str, Any]) -> dict[str, Any]:
    """GraphML-compatible scalars for a node's or edge's attributes (see the module doc)."""
    flat: dict[str, Any] = {}
    for name, value in attrs.items():
        _flatten_into(flat, str(name), value)
    return flat


def _flatten_into(flat: dict[str, Any], name: str, value: Any) -> None:
    # floats, positions, normals and portals first, without arrays: they are nearly all the values
    if isinstance(value, (float, np.floating)):
        x = number(value)
        if x is not None:
            flat[name] = x
    elif _is_float_triple(value):  # a position, a direction or a portal's end: coordinates
        for key, x in zip(_axis_names(name), value):
            x = coordinate(x)
            if x is not None:
                flat[key] = x
    elif type(value) is tuple and all(_is_float_triple(row) for row in value):
        for i, row in enumerate(value):
            _flatten_into(flat, f"{name}_{i}", row)
    elif value is None:
        return
    elif isinstance(value, (bool, np.bool_)):
        flat[name] = bool(value)
    elif isinstance(value, (int, np.integer)):
        flat[name] = int(value)
    elif isinstance(value, str):
        flat[name] = value
    elif isinstance(value, (list, tuple, np.ndarray)):
        try:
            array = np.asarray(value, dtype=np.float64)
        except (TypeError, ValueError):
            flat[name] = str(value)
            return
        if array.ndim == 1 and len(array) == 3:
            for axis, x in zip(_AXES, array):
                _flatten_into(flat, f"{name}_{axis}", float(x))
        elif array.ndim == 2 and array.shape[1] == 3:
            for i, row in enumerate(array):
                for axis, x in zip(_AXES, row):
                    _flatten_into(flat, f"{name}_{i}_{axis}", float(x))
        else:
            integral = np.asarray(value).dtype.kind in "iub"
            for i, x in enumerate(array.reshape(-1)):
                _flatten_into(flat, f"{name}_{i}", int(x) if integral else float(x))
    else:
        flat[name] = str(value)


def _is_float_triple(value: Any) -> bool:
    return type(value) is tuple and len(value) == 3 and type(value[0]) is type(value[1]) is type(value[2]) is float


@functools.cache
def _axis_names(name: str) -> tuple[str, str, str]:
    return tuple(f"{name}_{axis}" for axis in _AXES)
