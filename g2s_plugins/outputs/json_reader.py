"""Reads back what the json writer wrote: structure.json, with the stage times of run.json (g2s_core.load_result).

The ``json`` writer (:mod:`g2s_plugins.outputs.structure_json`) owns the
format: its version, file names and JSON schemas (``structure.schema.json``,
``run.schema.json`` beside this module); this reader reads what it writes.
The reader trusts nothing in the file: it is read like every text input
(:mod:`g2s_core.input_files`) and checked against the schema before use, so a
damaged file is refused naming the file and the field.
"""

from __future__ import annotations

import functools
import json
import math
from pathlib import Path
from typing import Any

from g2s_core.errors import G2SError
from g2s_core.input_files import parse_nested, read_text
from g2s_core.lazy import lazy_module
from g2s_core.messages import show, show_key
from g2s_core.model import LoadedResult, Opening, StageStats, Terminals
from g2s_core.plugin import hookimpl
from g2s_plugins.outputs.structure_json import RUN_FILE, SCHEMA_PATH, SCHEMA_VERSION, STRUCTURE_FILE
from g2s_plugins.vectors import vec3

nx = lazy_module("networkx")

NAME = "json"

READABLE_VERSIONS = (1, 2, 3)
"""structure.json versions :func:`load_result` reads (1 has no ``features``, 1 and 2 no ``metrics``)."""
_ADDED_IN = {"features": 2, "metrics": 3}
"""Fields a version added, empty when a file of an older version is read."""

_SCHEMA_TYPES = {"array": "a list", "object": "a mapping", "string": "a string", "integer": "an integer",
                 "number": "a number", "boolean": "true or false", "null": "null"}
"""JSON schema types in the words of g2s's config messages."""

_BOUNDS = {"minimum": ">=", "maximum": "<=", "exclusiveMinimum": ">", "exclusiveMaximum": "<"}


class MalformedField(ValueError):
    """A field that follows the schema but contradicts another (an edge to a node the file lacks); the message
    starts with the field."""


@hookimpl
def g2s_read_result(path: Path) -> LoadedResult:
    """Read a result folder's ``structure.json`` (or that file), with the stage times of ``run.json`` beside it."""
    return load_result(path)


def load_result(path: str | Path) -> LoadedResult:
    """Read a ``structure.json`` (or the folder holding one) back.

    The document is checked against ``structure.schema.json`` before use; a
    file of an older version is checked as the current one with the fields
    its version lacks empty.

    Raises:
        G2SError: the file is missing, not a regular UTF-8 file, not JSON, not
            a g2s structure file, of a schema version this g2s does not read,
            or malformed (the message names the file and the field).
    """
    path = Path(path)
    if path.is_dir():
        path = path / STRUCTURE_FILE
    text = read_text(path, "structure file")
    try:
        document = parse_nested(text, json.loads, str(path))
    except json.JSONDecodeError as exc:
        raise G2SError(f"{path}: invalid JSON at line {exc.lineno}, column {exc.colno}: {exc.msg}") from None
    if not isinstance(document, dict) or document.get("format") != "g2s-structure":
        raise G2SError(f"{path}: not a g2s structure.json file")
    version = document.get("schema_version")
    if type(version) is not int or version not in READABLE_VERSIONS:  # True and 2.0 equal 1 and 2
        readable = ", ".join(map(str, READABLE_VERSIONS))
        newer = "; a newer g2s wrote it: upgrade g2s to read it" if type(version) is int and version > max(READABLE_VERSIONS) else ""
        if "schema_version" not in document:
            raise G2SError(f"{path}: schema_version: required key is missing (this g2s reads {readable})")
        raise G2SError(f"{path}: schema_version {show(version)} is not supported (this g2s reads {readable}){newer}")
    checked = {**document, "schema_version": SCHEMA_VERSION}
    for name, added in _ADDED_IN.items():
        if version < added:
            if name in document:
                raise G2SError(f"{path}: {name}: not a field of schema_version {version}")
            checked[name] = {}
    if found := _non_finite(document):
        raise G2SError(f"{path}: {found[0]}: expected a finite number, got {found[1]}")
    import jsonschema  # imported on first use: every command loads this plugin, few read results

    problem = jsonschema.exceptions.best_match(_schema_validator().iter_errors(checked))
    if problem is not None:
        where = "".join(f"[{p}]" if isinstance(p, int) else f".{show_key(p)}" for p in problem.absolute_path).lstrip(".")
        key, words = _in_words(problem)
        where = f"{where}.{show_key(key)}".lstrip(".") if key else where
        raise G2SError(f"{path}: {where or '(top level)'}: {words}")
    try:
        return _loaded(document, path)
    except MalformedField as exc:
        raise G2SError(f"{path}: {exc}") from None
    except (KeyError, TypeError, ValueError, OverflowError) as exc:  # what the schema cannot say
        raise G2SError(f"{path}: malformed structure file ({type(exc).__name__}: {exc})") from None


@functools.cache
def _schema_validator() -> Any:
    import jsonschema

    schema = json.loads(SCHEMA_PATH.read_text(encoding="utf-8"))
    return jsonschema.validators.validator_for(schema)(schema)


def _non_finite(value: Any, where: str = "") -> tuple[str, float] | None:
    """The first number in ``value`` that is not finite (``NaN``, ``Infinity``: Python's json reads them, JSON has
    none, the writer writes none; ``1e999`` reads as infinity) and where it is, e.g. ``nodes[3].position[0]``."""
    if isinstance(value, float) and not math.isfinite(value):
        return where, value
    items = value.items() if isinstance(value, dict) else enumerate(value) if isinstance(value, list) else ()
    for key, item in items:
        if found := _non_finite(item, f"{where}[{key}]" if isinstance(key, int) else f"{where}.{show_key(key)}".lstrip(".")):
            return found
    return None


def _in_words(problem: Any) -> tuple[str, str]:
    """A ``jsonschema`` error in the words of g2s's config messages: the key it is about, when below the error's
    path (a missing or unknown key), and ``expected ..., got ...`` (the validator's own message otherwise)."""
    rule, expected, value = problem.validator, problem.validator_value, problem.instance
    if rule == "required":
        return next(key for key in expected if key not in value), "required key is missing"
    if rule == "additionalProperties":
        known = ", ".join(problem.schema.get("properties", {}))
        return next(key for key in value if key not in problem.schema.get("properties", {})), f"unknown key (expected one of: {known})"
    kinds = [expected] if rule == "type" else [item.get("type") for item in expected] if rule in ("anyOf", "oneOf") else []
    if kinds and all(kinds):
        words = [_SCHEMA_TYPES[kind] for item in kinds for kind in ([item] if isinstance(item, str) else item)]
        return "", f"expected {' or '.join(dict.fromkeys(words))}, got {show(value)}"
    if rule in ("enum", "const"):
        return "", f"expected {'one of ' + ', '.join(map(show, expected)) if rule == 'enum' else show(expected)}, got {show(value)}"
    if rule in ("minItems", "maxItems"):
        return "", f"expected a list of {'at least' if rule == 'minItems' else 'at most'} {expected} items, got {show(value)}"
    if rule in _BOUNDS:
        return "", f"expected a number {_BOUNDS[rule]} {expected}, got {show(value)}"
    return "", _shorten(problem.message)


def _shorten(message: str, limit: int = 160) -> str:
    """A validator message cut to one short line (it quotes the offending value in full)."""
    line = " ".join(message.split())
    return line if len(line) <= limit else line[: limit - 3] + "..."


def _loaded(document: dict[str, Any], path: Path) -> LoadedResult:
    directed = bool(document["directed"])
    structure: nx.Graph = nx.DiGraph() if directed else nx.Graph()
    analysis: dict[str, dict[int, float | None]] = {key: {} for key in document["analysis_keys"]}
    first: dict[int, int] = {}  # node id -> the index of the record giving it
    for index, record in enumerate(document["nodes"]):
        node = int(record["id"])
        if (earlier := first.setdefault(node, index)) != index:  # add_node would merge the two records silently
            raise MalformedField(f"nodes[{index}].id: id {node} is given twice (first at nodes[{earlier}])")
        attrs: dict[str, Any] = dict(record["extra"])
        attrs["pos"] = vec3(record["position"])
        if record["normal"] is not None:
            attrs["normal"] = vec3(record["normal"])
        for key in ("area", "on_navmesh", "polygon", "root", "depth"):
            if record[key] is not None:
                attrs[key] = record[key]
        attrs["terminal"] = bool(record["terminal"])
        structure.add_node(node, **attrs)
        for key, value in record["values"].items():
            analysis.setdefault(key, {})[node] = value
    listed: dict[tuple[int, ...], int] = {}  # an edge's ends (sorted when undirected) -> the index of the record giving it
    for index, record in enumerate(document["edges"]):
        attrs = dict(record["extra"])
        if record["weight"] is not None:
            attrs["weight"] = record["weight"]
        ends = _known_nodes(structure, {end: record[end] for end in ("source", "target")}, f"edges[{index}]")
        if ends[0] == ends[1]:  # no graph g2s builds has one; networkx would keep it as a loop of the node
            raise MalformedField(f"edges[{index}]: an edge from node {ends[0]} to itself")
        if (earlier := listed.setdefault(tuple(ends if directed else sorted(ends)), index)) != index:  # add_edge would merge them
            raise MalformedField(f"edges[{index}]: the edge {ends[0]} {'->' if directed else '-'} {ends[1]} is given twice "
                                 f"(first at edges[{earlier}])")
        structure.add_edge(*ends, **attrs)  # add_edge alone would add a missing end as a node without position
    roots = _known_nodes(structure, dict(enumerate(document["roots"])), "roots")
    if directed:
        structure.graph["roots"] = roots
    terminals = None
    if document["terminals"] is not None:
        openings = tuple(
            Opening(
                vec3(o["position"]), vec3(o["heading"]), float(o["width"]), vec3(o["p0"]), vec3(o["p1"]),
                None if o.get("score") is None else float(o["score"]), o.get("reason"),
            )
            for o in document["terminals"]["openings"]
        )
        terminals = _terminals(document["terminals"], openings)
    graphs = document["graphs"]
    size = graphs.get("graph")
    return LoadedResult(
        schema_version=int(document["schema_version"]),
        mesh_name=document["mesh"]["name"],
        mesh_sha256=document["mesh"]["sha256"],
        config=document["config"],
        navmesh=document["navmesh"],
        final_stage=document["final_stage"],
        structure=structure,
        roots=roots,
        analysis=analysis,
        features=dict(document.get("features", {})),
        metrics={key: dict(measures) for key, measures in document.get("metrics", {}).items()},
        terminals=terminals,
        steiner=_edges_graph(graphs.get("steiner"), directed=False),
        forest=_edges_graph(graphs.get("forest"), directed=True),  # type: ignore[arg-type]
        graph_size=None if size is None else (int(size["nodes"]), int(size["edges"])),
        stages=_stages(document, path.parent / RUN_FILE),
        warnings=list(document["warnings"]),
        document=document,
    )


def _known_nodes(structure: nx.Graph, ids: dict[Any, Any], field: str) -> list[int]:
    """``ids`` (place in ``field`` -> node id) as ints, each a node of ``structure``."""
    for place, node in ids.items():
        if int(node) not in structure:
            where = f"{field}[{place}]" if isinstance(place, int) else f"{field}.{place}"
            raise MalformedField(f"{where}: node {int(node)} is not in nodes")
    return [int(node) for node in ids.values()]


def _terminals(data: dict[str, Any], openings: tuple[Opening, ...]) -> Terminals:
    """The selector's result: the terminals, then the waypoints (files without ``waypoint_ids`` have none)."""
    nodes = tuple(int(t) for t in data["node_ids"])
    waypoints = tuple(int(w) for w in data.get("waypoint_ids", ()))
    both = set(nodes).intersection(waypoints)
    if both:
        raise MalformedField(f"terminals.waypoint_ids: node {min(both)} is also in terminals.node_ids")
    return Terminals(nodes + waypoints, openings, waypoints)


def _edges_graph(data: dict[str, Any] | None, directed: bool) -> nx.Graph | None:
    if data is None:
        return None
    graph: nx.Graph = nx.DiGraph() if directed else nx.Graph()
    graph.add_nodes_from(int(n) for n in data["node_ids"])
    graph.add_edges_from((int(u), int(v)) for u, v in data["edge_list"])
    if directed:
        graph.graph["roots"] = [int(r) for r in data.get("roots", [])]
    return graph


def _stages(document: dict[str, Any], run_path: Path) -> list[StageStats]:
    seconds: dict[str, float] = {}
    try:
        run = parse_nested(read_text(run_path, "run file"), json.loads, str(run_path))
        if run.get("mesh", {}).get("sha256") == document["mesh"]["sha256"]:
            seconds = {s["stage"]: float(s["seconds"]) for s in run.get("stages", [])}
    except (G2SError, ValueError, TypeError, KeyError, AttributeError):  # timings are optional: a bad run.json is ignored
        seconds = {}
    return [
        StageStats(s["stage"], seconds.get(s["stage"], float("nan")), s["nodes"], s["edges"], s["terminals"])
        for s in document["stages"]
    ]
