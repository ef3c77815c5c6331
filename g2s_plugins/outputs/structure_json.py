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
from itertools import chain, repeat
from operator import itemgetter
from pathlib import Path
from typing import Any

import numpy as np

from g2s_core import version
from g2s_core.lazy import lazy_module
from g2s_core.model import Opening, RunResult
from g2s_plugins.outputs.columns import by_groups
from g2s_plugins.outputs.common import (
    coordinates,
    edge_list,
    edges_with_data,
    final_graph,
    number,
    numbers,
    roots_of,
    terminal_ids,
    tree_parents,
    vector,
    vectors,
)
from g2s_plugins.outputs.files import atomic_write
from g2s_plugins.outputs.json_text import dumps_indented
from g2s_plugins.outputs.writers import collector_paused

nx = lazy_module("networkx")

SCHEMA_VERSION = 3
STRUCTURE_FILE = "structure.json"
RUN_FILE = "run.json"
RUN_SCHEMA_VERSION = 1
SCHEMA_PATH = Path(__file__).resolve().parent / "structure.schema.json"
"""The layout of ``structure.json``, version :data:`SCHEMA_VERSION` (JSON Schema draft 2020-12)."""

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
        nodes = _node_records(graph, terminals, result.analysis, keys)
        edges = _edge_records(graph)
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


def _node_records(graph: nx.Graph, terminals: set[int], analysis: dict, keys: list[str]) -> list[dict[str, Any]]:
    """The records of ``graph``'s nodes, by id; each attribute is rounded for all nodes at once (a column)."""
    ids = sorted(graph.nodes)
    attrs = list(map(graph.nodes.__getitem__, ids))
    parents = tree_parents(graph)
    positions = vectors([a["pos"] for a in attrs])
    normals = vectors([a.get("normal") for a in attrs])
    areas = numbers([a.get("area") for a in attrs])
    columns = {}  # key -> {node: rounded value} of the nodes that have one
    for key in keys:
        present = [n for n in ids if n in analysis[key]]
        columns[key] = dict(zip(present, numbers([analysis[key][n] for n in present])))
    extras = _extras(attrs, _NODE_KEYS)
    return [
        {
            "id": int(node),
            "position": position,
            "normal": normal,
            "area": area,
            "on_navmesh": None if a.get("on_navmesh") is None else bool(a["on_navmesh"]),
            "polygon": None if a.get("polygon") is None else int(a["polygon"]),
            "terminal": int(node) in terminals or bool(a.get("terminal", False)),
            "root": None if a.get("root") is None else int(a["root"]),
            "depth": None if a.get("depth") is None else int(a["depth"]),
            "parent": parents.get(node),
            "values": {key: columns[key][node] for key in keys if node in columns[key]},
            "extra": extra,
        }
        for node, a, position, normal, area, extra in zip(ids, attrs, positions, normals, areas, extras)
    ]


def _edge_records(graph: nx.Graph) -> list[dict[str, Any]]:
    """The records of ``graph``'s edges in :func:`edge_list`'s order, rounded a column at a time."""
    edges = edges_with_data(graph)
    attrs = [data for _, _, data in edges]
    weights = numbers([data.get("weight") for data in attrs])
    extras = _extras(attrs, _EDGE_KEYS)
    return [{"source": u, "target": v, "weight": weight, "extra": extra}
            for (u, v, _), weight, extra in zip(edges, weights, extras)]


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


class _Skip:
    """Marks a value that JSON cannot hold faithfully."""


_SKIP = _Skip()


def _plain(value: Any) -> Any:
    """``value`` as JSON data with rounded floats; :data:`_SKIP` for what cannot be written."""
    return _plain_column([value])[0]


def _plain_column(values: list) -> list:
    """:func:`_plain` of each of ``values``, a column: the values of a type (dicts: of a key set) go together."""
    return by_groups(values, type, _plain_of_kind)


def _plain_of_kind(kind: type, values: list) -> list:
    """:func:`_plain_column` of values that are all of type ``kind``."""
    if kind is float:
        return numbers(values)
    if kind is int or kind is str or kind is bool or kind is type(None):
        return values
    if kind is dict:
        return by_groups(values, tuple, _plain_dicts)
    if kind is list or kind is tuple:
        return _plain_lists(values)
    return [plain if plain is _SKIP or isinstance(plain, str) else _plain(plain) for plain in map(_builtin, values)]


def _plain_dicts(keys: tuple, values: list[dict]) -> list:
    """:func:`_plain_column` of dicts whose keys are ``keys`` (of these, or more): a column per key; keys become
    ``str``, values JSON cannot hold are left out."""
    if not keys:
        return [{} for _ in values]
    names = [str(key) for key in keys]
    columns = [_plain_column(list(map(itemgetter(key), values))) for key in keys]
    rows = list(map(dict, map(zip, repeat(names), zip(*columns))))
    if any(_SKIP in column for column in columns):
        rows = [{k: v for k, v in row.items() if v is not _SKIP} for row in rows]
    return rows


def _extras(attrs: list[dict[str, Any]], known: tuple[str, ...]) -> list[dict[str, Any]]:
    """Each of ``attrs``' attributes beyond the documented ones that JSON can hold (plugins' own, e.g. ``width``)."""
    extra_keys = {keys: tuple(k for k in keys if k not in known) for keys in set(map(tuple, attrs))}
    return by_groups(attrs, lambda a: extra_keys[tuple(a)], _plain_dicts)


def _plain_lists(values: list) -> list:
    """:func:`_plain_column` of lists (or tuples): three floats are a point or a direction (a portal's end)
    whose components are coordinates; a list with an item JSON cannot hold is itself left out."""
    sizes = list(map(len, values))
    flat = list(chain.from_iterable(values))
    size = sizes[0]
    if size and sizes.count(size) == len(sizes):  # lists of one length (points, portals): regrouped by zip
        points = size == 3 and set(map(type, flat)) == {float}
        if points or size != 3:
            items = coordinates(flat) if points else _plain_column(flat)
            rows = list(map(list, zip(*[iter(items)] * size)))
            return rows if points or _SKIP not in items else [_SKIP if _SKIP in row else row for row in rows]
    points_at = [len(value) == 3 and type(value[0]) is float and type(value[1]) is float and type(value[2]) is float
                 for value in values]
    items = iter(_plain_column([item for value, point in zip(values, points_at) if not point for item in value]))
    point_items = iter(coordinates([item for value, point in zip(values, points_at) if point for item in value]))
    result = []
    for value, point in zip(values, points_at):
        row = [next(point_items if point else items) for _ in value]
        result.append(_SKIP if not point and _SKIP in row else row)
    return result


def _builtin(value: Any) -> Any:
    """A value of a type beyond the plain ones as plain types (numpy scalars and arrays, sets, subclasses; a
    ``str`` subclass stays itself, as JSON writes it as a string), or :data:`_SKIP` when JSON cannot hold it."""
    if isinstance(value, str):
        return value
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, (int, np.integer)):
        return int(value)
    if isinstance(value, (float, np.floating)):
        return float(value)
    if isinstance(value, (set, frozenset)):
        try:
            return sorted(value)
        except TypeError:
            return _SKIP
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, dict):
        return dict(value)
    if isinstance(value, (list, tuple)):
        return list(value)
    return _SKIP
