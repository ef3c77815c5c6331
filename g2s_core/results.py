"""Reading a run's ``structure.json`` back (the ``json`` output writer's format, ``docs/outputs.md``).

The format belongs to g2s, not to the writer plugin: its version, file names and
reader live here, and the writer (``g2s_plugins.outputs.structure_json``) writes
what this reads.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import networkx as nx

from g2s_core.errors import G2SError
from g2s_core.model import Opening, StageStats, Terminals, vec3

SCHEMA_VERSION = 2
READABLE_VERSIONS = (1, 2)
"""structure.json versions :func:`load_result` reads (1 has no ``features``)."""
STRUCTURE_FILE = "structure.json"
RUN_FILE = "run.json"


@dataclass
class LoadedResult:
    """A ``structure.json`` read back, with networkx graphs.

    ``structure`` is the final structure: a :class:`networkx.DiGraph` (edges
    parent -> child, ``graph["roots"]``) when the run got to rooted trees, an
    undirected graph otherwise. Its nodes carry the attributes of
    :mod:`g2s_core.model` (``pos``, ``normal``, ``area``, ``on_navmesh``,
    ``polygon``, ``depth``, ``root``), ``terminal`` (bool) and the plugins'
    extra attributes; its edges ``weight`` and extras. ``analysis`` maps each
    analyzer's key to its value per node, ``features`` to its records (empty
    for version 1 files). ``stages`` come with their seconds
    when ``run.json`` of the same mesh lies beside the file, NaN otherwise.
    """

    schema_version: int
    mesh_name: str
    mesh_sha256: str
    config: dict[str, Any]
    navmesh: dict[str, Any] | None
    final_stage: str | None
    structure: nx.Graph
    roots: list[int]
    analysis: dict[str, dict[int, float | None]]
    features: dict[str, dict[str, Any]]
    terminals: Terminals | None
    steiner: nx.Graph | None
    forest: nx.DiGraph | None
    graph_size: tuple[int, int] | None
    stages: list[StageStats] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    document: dict[str, Any] = field(default_factory=dict, repr=False)


def load_result(path: str | Path) -> LoadedResult:
    """Read a ``structure.json`` (or the folder holding one) back.

    Raises:
        G2SError: the file is missing, not JSON, not a g2s structure file, or
            of a schema version this g2s does not read.
    """
    path = Path(path)
    if path.is_dir():
        path = path / STRUCTURE_FILE
    try:
        document = json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise G2SError(f"{path}: no such file") from None
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise G2SError(f"{path}: not a readable JSON file ({exc})") from None
    if not isinstance(document, dict) or document.get("format") != "g2s-structure":
        raise G2SError(f"{path}: not a g2s structure.json file")
    version = document.get("schema_version")
    if version not in READABLE_VERSIONS:
        readable = ", ".join(map(str, READABLE_VERSIONS))
        raise G2SError(f"{path}: schema_version {version!r} is not supported (this g2s reads {readable})")
    try:
        return _loaded(document, path)
    except (KeyError, TypeError, ValueError) as exc:
        raise G2SError(f"{path}: malformed structure file ({type(exc).__name__}: {exc})") from None


def _loaded(document: dict[str, Any], path: Path) -> LoadedResult:
    directed = bool(document["directed"])
    structure: nx.Graph = nx.DiGraph() if directed else nx.Graph()
    analysis: dict[str, dict[int, float | None]] = {key: {} for key in document["analysis_keys"]}
    for record in document["nodes"]:
        node = int(record["id"])
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
    for record in document["edges"]:
        attrs = dict(record["extra"])
        if record["weight"] is not None:
            attrs["weight"] = record["weight"]
        structure.add_edge(int(record["source"]), int(record["target"]), **attrs)
    roots = [int(r) for r in document["roots"]]
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
        terminals = Terminals(tuple(int(t) for t in document["terminals"]["node_ids"]), openings)
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
        terminals=terminals,
        steiner=_edges_graph(graphs.get("steiner"), directed=False),
        forest=_edges_graph(graphs.get("forest"), directed=True),  # type: ignore[arg-type]
        graph_size=None if size is None else (int(size["nodes"]), int(size["edges"])),
        stages=_stages(document, path.parent / RUN_FILE),
        warnings=list(document["warnings"]),
        document=document,
    )


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
        run = json.loads(run_path.read_text(encoding="utf-8"))
        if run.get("mesh", {}).get("sha256") == document["mesh"]["sha256"]:
            seconds = {s["stage"]: float(s["seconds"]) for s in run.get("stages", [])}
    except (OSError, ValueError, TypeError, KeyError, AttributeError):
        seconds = {}
    return [
        StageStats(s["stage"], seconds.get(s["stage"], float("nan")), s["nodes"], s["edges"], s["terminals"])
        for s in document["stages"]
    ]
