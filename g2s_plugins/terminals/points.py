"""Points: user-given positions (e.g. entry/exit points) added to the graph as terminal nodes.

Each point becomes a new node, joined to its ``connect`` nearest existing
nodes (scipy ``cKDTree``) that lie within ``max_distance``; the new edges'
``weight`` is the Euclidean distance. New ids follow the largest existing
id, in the order the points are given, and the terminals are the new nodes
in that order. A new node has ``pos`` = the point, ``normal`` = that of its
nearest node, ``area`` = 0, ``polygon`` = -1 and ``on_navmesh`` from
:func:`g2s_plugins._surface.on_navmesh` (a navmesh polygon within one cell
horizontally and the agent's max climb vertically; false without a navmesh).

Points come from ``points`` (a list of [x, y, z] in metres, mesh frame, Y
up) or from ``file``: JSON (a list of [x, y, z], or ``{"points": [...]}``)
or text/CSV (one point per line, numbers separated by commas, semicolons or
spaces; ``#`` starts a comment; a non-numeric first line is a header).
A relative ``file`` is read from the working directory.

Complexity: O(n log n) to build the k-d tree plus O(p (log n + k)) for p points.
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path
from typing import Annotated, Any

import numpy as np
from pydantic import Field, Strict, model_validator
from pydantic_core import PydanticCustomError

from g2s_core.errors import G2SError
from g2s_core.input_files import parse_nested, read_text
from g2s_core.lazy import lazy_module
from g2s_core.model import RunContext, Terminals
from g2s_core.plugin import PluginParams, hookimpl
from g2s_plugins._surface import on_navmesh
from g2s_plugins.vectors import vec3

spatial = lazy_module("scipy.spatial")
nx = lazy_module("networkx")

NAME = "points"

_DEFAULT_NORMAL = (0.0, 1.0, 0.0)


class Params(PluginParams):
    """Where the points come from (exactly one of points, file) and how they are joined."""

    points: list[Annotated[tuple[float, float, float], Strict(False)]] | None = Field(
        None, min_length=1, strict=False, description="points [x, y, z] in metres, mesh frame"
    )
    file: str | None = Field(None, description="JSON, CSV or text file with one point [x, y, z] per entry/line")
    connect: int = Field(1, ge=1, le=32, description="number of nearest graph nodes each point is joined to")
    max_distance: float = Field(2.0, gt=0, description="farthest a joined node may be from its point, metres")

    @model_validator(mode="after")
    def _one_source(self) -> Params:
        if (self.points is None) == (self.file is None):
            got = "both" if self.points is not None else "neither"
            raise PydanticCustomError("source", "give exactly one of points, file (got {got})", {"got": got})
        return self


_SEPARATORS = re.compile(r"[,;\s]+")


def _from_json(path: Path, text: str) -> list[Any]:
    try:
        data = parse_nested(text, json.loads, str(path))
    except json.JSONDecodeError as exc:
        raise G2SError(f"{path}: invalid JSON at line {exc.lineno}, column {exc.colno}: {exc.msg}") from None
    if isinstance(data, dict):
        if "points" not in data:
            raise G2SError(f"{path}: expected a list of [x, y, z] or a mapping with a 'points' list")
        data = data["points"]
    if not isinstance(data, list):
        raise G2SError(f"{path}: expected a list of [x, y, z] points")
    return data


def _from_text(path: Path, text: str) -> list[Any]:
    rows: list[Any] = []
    first = True
    for number, line in enumerate(text.splitlines(), start=1):
        content = line.split("#", 1)[0].strip()
        if not content:
            continue
        fields = [f for f in _SEPARATORS.split(content) if f]
        try:
            values = [float(f) for f in fields]
        except ValueError:
            if first:  # a header such as "x,y,z"
                first = False
                continue
            raise G2SError(f"{path}:{number}: expected 3 numbers x, y, z, got {content!r}") from None
        first = False
        if len(values) != 3:
            raise G2SError(f"{path}:{number}: expected 3 numbers x, y, z, got {len(values)}: {content!r}")
        rows.append(values)
    return rows


def read_points(file: str | Path) -> np.ndarray:
    """(p, 3) float64 points read from a JSON or text/CSV file (format in the module docs).

    Raises:
        G2SError: the file is missing, unreadable, malformed, or holds no point.
    """
    path = Path(file)
    text = read_text(path, "points file")
    stripped = text.lstrip()
    is_json = path.suffix.lower() == ".json" or stripped.startswith(("[", "{"))
    rows = _from_json(path, text) if is_json else _from_text(path, text)
    points = []
    for index, row in enumerate(rows):
        try:
            if is_json and not all(type(value) in (int, float) for value in row):  # true and "1" were read as 1
                raise TypeError(row)
            point = vec3(row)
        except (TypeError, ValueError):
            raise G2SError(f"{path}: point {index} is {json.dumps(row) if is_json else repr(row)}, expected [x, y, z] numbers") from None
        if not all(map(math.isfinite, point)):  # nan, inf, 1e999: was named without the file
            raise G2SError(f"{path}: point {index} {point} is not finite")
        points.append(point)
    if not points:
        raise G2SError(f"{path}: the file holds no points")
    return np.asarray(points, dtype=np.float64)


@hookimpl
def g2s_select_terminals(graph: nx.Graph, params: Params, context: RunContext) -> Terminals:
    """Add every point to ``graph`` as a new node joined to its nearest nodes; they are the terminals.

    Raises:
        G2SError: the graph has no nodes, or a point is farther than
            ``max_distance`` from every node (the message names the point).
    """
    # finite: the params refuse .nan and .inf, read_points the file's
    points = np.asarray(params.points, dtype=np.float64) if params.points is not None else read_points(params.file)
    existing = sorted(graph.nodes)
    if not existing:
        raise G2SError("the graph has no nodes to join the points to")
    positions = np.asarray([graph.nodes[node]["pos"] for node in existing], dtype=np.float64)
    k = min(params.connect, len(existing))
    distances, indices = spatial.cKDTree(positions).query(points, k=k)
    distances = np.asarray(distances).reshape(len(points), k)
    indices = np.asarray(indices).reshape(len(points), k)
    # Check every point before touching the graph.
    for i, point in enumerate(points):
        if distances[i, 0] > params.max_distance:
            x, y, z = point.tolist()
            raise G2SError(
                f"{params.file or 'terminals.params.points'}: point {i} ({x:g}, {y:g}, {z:g}) is {distances[i, 0]:.3g} m from the nearest graph node, "
                f"farther than max_distance = {params.max_distance:g} m"
            )
    first_id = int(max(existing)) + 1
    new_nodes: list[int] = []
    for i, point in enumerate(points):
        node = first_id + i
        nearest = existing[int(indices[i, 0])]
        graph.add_node(
            node,
            pos=vec3(point),
            normal=vec3(graph.nodes[nearest].get("normal", _DEFAULT_NORMAL)),
            area=0.0,
            on_navmesh=on_navmesh(context.navmesh, point, context.agent),
            polygon=-1,
        )
        for distance, index in zip(distances[i].tolist(), indices[i].tolist()):
            if distance <= params.max_distance:
                graph.add_edge(node, existing[int(index)], weight=float(distance))
        new_nodes.append(node)
    return Terminals(nodes=tuple(new_nodes))
