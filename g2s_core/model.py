"""The data that flows between stages, and the record of a run.

Surface graph conventions (what every plugin may rely on)
---------------------------------------------------------
The initial graph is a :class:`networkx.Graph` with integer node ids.

Node attributes:
    ``pos``        tuple of 3 floats, metres, in the mesh frame (Y up).
    ``normal``     tuple of 3 floats, unit surface normal.
    ``area``       float, m², the surface the node stands for (0 for added points).
    ``on_navmesh`` bool, whether the node lies on the walkable surface.
    ``polygon``    int, navmesh polygon index, or -1 when the node is not a polygon.
Edge attributes:
    ``weight``     float, Euclidean distance between the two ``pos``, metres.
    plus builder-specific ones (``portal``, ``width`` for the navmesh builder).

Rooted forests (stage 4 and 5) are :class:`networkx.DiGraph` with edges
parent -> child, the node attributes above plus ``depth`` (root = 0) and
``root`` (id of the node's root); ``forest.graph["roots"]`` lists the roots.
With ``loops:`` configured the structure may have cycles: the rooted trees
are spanning trees and the other edges carry ``loop=True`` (see
:mod:`g2s_core.rooted`).
"""

from __future__ import annotations

from collections.abc import Callable, Hashable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, Protocol, runtime_checkable

if TYPE_CHECKING:  # annotations only: importing them here would slow every command (g2s_core.lazy)
    import networkx as nx
    import numpy as np
    import trimesh

    from g2s_core.config import AgentConfig

Vec3 = tuple[float, float, float]


def graph_of(graph: nx.Graph, nodes: Mapping[Hashable, dict], edges: Iterable[tuple[Hashable, Hashable, dict]]) -> nx.Graph:
    """The empty ``graph`` given ``nodes`` (id -> its own attribute dict), then ``edges`` (u, v, their own dict).

    The graph add_nodes_from and add_edges_from make, nodes and edges in the same order, for edges joining
    given nodes (an edge given again keeps its place and takes the last dict, where add_edges_from merges
    them); written straight into networkx's dicts (as its graph classes document), without its checks
    per node and edge: about half the time on a 100k-polygon level.
    """
    graph._node.update(nodes)
    successors, predecessors = graph._adj, graph._pred if graph.is_directed() else graph._adj
    for node in nodes:
        successors[node], predecessors[node] = {}, {}
    for u, v, data in edges:
        successors[u][v] = predecessors[v][u] = data
    return graph


class Portals(Protocol):
    """Where navmesh polygons touch: for E touching pairs (a < b, sorted), ``pairs`` (E,2) int64,
    the touching segment's ``endpoints`` (E,2,3) float64 and ``widths`` (E,) float64, metres."""

    pairs: np.ndarray
    endpoints: np.ndarray
    widths: np.ndarray


@runtime_checkable
class NavMesh(Protocol):
    """What a graph builder that makes a navigation mesh puts in ``context.navmesh``.

    Writers and plugins use only these arrays and queries (``g2s_plugins.recast``
    provides them from Recast/Detour). Metres, Y up.

    Attributes:
        vertices: (V,3) float64, polygon vertices.
        polygons: (P,nvp) int32, vertex indices per polygon, padded with -1.
        neighbours: (P,nvp) int32, polygon across edge j (vertex j -> j+1), -1 at the boundary.
        centres: (P,3) float64, a point of each polygon's surface near its centroid.
        normals: (P,3) float64, unit surface normal of each polygon, +Y side.
        areas: (P,) float64, m², surface area of each polygon.
        detail_vertices: (DV,3) float64, vertices of the height-detail triangles.
        detail_triangles: (DT,3) int32, the walkable surface as triangles of ``detail_vertices``.
        settings: the build's world-unit settings; at least ``cell_size`` and ``cell_height``, metres.
        polygon_count: P.
    """

    vertices: np.ndarray
    polygons: np.ndarray
    neighbours: np.ndarray
    centres: np.ndarray
    normals: np.ndarray
    areas: np.ndarray
    detail_vertices: np.ndarray
    detail_triangles: np.ndarray
    settings: Mapping[str, float]

    @property
    def polygon_count(self) -> int: ...

    def portals(self) -> Portals:
        """The shared polygon edges."""

    def stats(self) -> dict[str, Any]:
        """Sizes and timing for the run record (JSON values)."""

    def raycast(self, a: Any, b: Any, extents: Any = None) -> tuple[bool, float]:
        """Whether the straight walk from point ``a`` to point ``b`` along the surface is clear,
        and the fraction of a->b where it was blocked."""

    def nearest_poly(self, p: Any, extents: Any = None) -> tuple[int, np.ndarray]:
        """(polygon index or -1, (3,) nearest surface point) within the half ``extents`` of ``p``."""

    def segment_surface_gaps(self, A: Any, B: Any, step: float, reach: float) -> np.ndarray:
        """(S,) the largest vertical distance from the surface along each segment ``A[i] -> B[i]``,
        probed at most ``step`` apart, m; ``inf`` where a probe has no surface within ``reach``."""


@dataclass(frozen=True)
class Opening:
    """An entry/exit of a map piece: a segment of walkable boundary that leads outside.

    Attributes:
        position: midpoint of the opening at floor height, metres.
        heading: unit vector pointing out of the piece.
        width: length of the opening segment, metres.
        p0, p1: the segment's end points, metres.
        score: the detector's confidence in [0, 1]; ``None`` when not detected
            (ground truth, user input).
        reason: why the detector kept it (the measurements behind the score).
    """

    position: Vec3
    heading: Vec3
    width: float
    p0: Vec3
    p1: Vec3
    score: float | None = None
    reason: str | None = None


@dataclass(frozen=True)
class Terminals:
    """What a TerminalSelector returns.

    Attributes:
        nodes: terminal node ids, in a deterministic order. Nodes the selector
            added to the graph are included.
        openings: the entry/exit openings the terminals stand for, if any.
        waypoints: those of ``nodes`` that only pull the structure into an
            area (e.g. coverage): the Steiner tree joins them, but unlike the
            other terminals simplification may remove them, and they are not
            terminals of the result (no ``terminal`` flag, no marker).
    """

    nodes: tuple[int, ...]
    openings: tuple[Opening, ...] = ()
    waypoints: tuple[int, ...] = ()

    @property
    def without_waypoints(self) -> tuple[int, ...]:
        """The terminals of the result: ``nodes`` minus ``waypoints``, in the selector's order."""
        waypoints = set(self.waypoints)
        return tuple(node for node in self.nodes if node not in waypoints)


@dataclass(frozen=True)
class StageStats:
    """Wall time and size of one stage, as in the paper's Tables 2 and 3."""

    stage: str
    seconds: float
    nodes: int | None = None
    edges: int | None = None
    terminals: int | None = None


@dataclass(frozen=True)
class AnalyzerResult:
    """What an Analyzer may return instead of a plain mapping: values plus records.

    Attributes:
        values: a float for every node of the structure (as a plain mapping would be).
        features: structured findings (e.g. ``{"chokepoints": [...]}``), JSON data
            only (dicts, lists, str, int, float, bool, None); kept on
            ``RunResult.features[key]`` and written to the outputs.
    """

    values: Mapping[int, float]
    features: Mapping[str, Any] = field(default_factory=dict)


@dataclass
class LoadedResult:
    """A run's result read back from its files by a ResultReader plugin (:func:`g2s_core.load_result`).

    ``structure`` is the final structure: a :class:`networkx.DiGraph` (edges
    parent -> child, ``graph["roots"]``) when the run got to rooted trees, an
    undirected graph otherwise. Its nodes carry the attributes of this module
    (``pos``, ``normal``, ``area``, ``on_navmesh``, ``polygon``, ``depth``,
    ``root``), ``terminal`` (bool) and the plugins' extra attributes; its edges
    ``weight`` and extras. ``analysis`` maps each analyzer's key to its value
    per node, ``features`` to its records; ``metrics`` maps each evaluator's
    key to its measures. ``stages`` carry their seconds when the reader found
    them (NaN otherwise). ``schema_version`` is the version of the format read;
    ``document`` the file's raw content. What a format does not hold stays
    empty (``None``, ``[]``, ``{}``).
    """

    schema_version: int
    mesh_name: str
    mesh_sha256: str
    config: dict[str, Any]
    structure: nx.Graph
    navmesh: dict[str, Any] | None = None
    final_stage: str | None = None
    roots: list[int] = field(default_factory=list)
    analysis: dict[str, dict[int, float | None]] = field(default_factory=dict)
    features: dict[str, dict[str, Any]] = field(default_factory=dict)
    metrics: dict[str, dict[str, float]] = field(default_factory=dict)
    terminals: Terminals | None = None
    steiner: nx.Graph | None = None
    forest: nx.DiGraph | None = None
    graph_size: tuple[int, int] | None = None
    stages: list[StageStats] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    document: dict[str, Any] = field(default_factory=dict, repr=False)


class RaisedWarning(str):
    """A warning as the run's ``progress`` callback receives it, the moment it is raised: its message, a ``str``
    (any callback can show it), of its own class (so a callback can tell it from a stage's name)."""


@dataclass
class RunContext:
    """Shared, read-mostly state that every hook receives as ``context``.

    Attributes:
        mesh: the input triangle mesh (``trimesh.Trimesh``), in metres, Y up.
        agent: the agent settings (:class:`g2s_core.config.AgentConfig`).
        centre: (3,) float64, centre of the mesh's axis-aligned bounding box.
        navmesh: the :class:`NavMesh` the graph builder made, or ``None`` when
            the graph was built without one.
        mesh_name: the file or sample name of the mesh, as the outputs record it, for plugins' warnings.
        graph: the initial surface graph, once stage 1 has run.
        likely_cause: set by the graph builder: ``likely_cause(graph, largest area, the others largest first)`` (node lists)
            names what most likely parts the largest area from the nearest of those a designer means to join to it, and
            where, for the disconnected-areas warning (:mod:`g2s_core.disconnected`); ``None``: the warning
            names no cause.
        warnings: messages for the user collected during the run.
        progress: the run's progress callback, which :meth:`warn` also tells each warning as a
            :class:`RaisedWarning`, before a costly step rather than after the run.
    """

    mesh: trimesh.Trimesh
    agent: AgentConfig
    centre: np.ndarray
    navmesh: NavMesh | None = None
    mesh_name: str = "mesh"
    graph: nx.Graph | None = None
    likely_cause: Callable[[nx.Graph, Sequence[int], Sequence[Sequence[int]]], str] | None = None
    warnings: list[str] = field(default_factory=list)
    progress: Callable[[str], None] = lambda _message: None

    def warn(self, message: str) -> None:
        """Record a warning for the run result and the CLI, and tell the progress callback at once."""
        self.warnings.append(message)
        self.progress(RaisedWarning(message))


@dataclass
class RunResult:
    """Everything a run produced, stage by stage; stages not run are ``None``.

    ``looped`` is the Steiner forest plus the loop paths of the ``loops:``
    step (``None`` when it is not configured); it is what steps 4 and 5 work on.
    """

    config: dict[str, Any]
    mesh_name: str
    mesh_sha256: str
    context: RunContext
    graph: nx.Graph | None = None
    terminals: Terminals | None = None
    steiner: nx.Graph | None = None
    looped: nx.Graph | None = None
    forest: nx.DiGraph | None = None
    structure: nx.DiGraph | None = None
    analysis: dict[str, dict[int, float]] = field(default_factory=dict)
    features: dict[str, dict[str, Any]] = field(default_factory=dict)
    metrics: dict[str, dict[str, float]] = field(default_factory=dict)
    """Each evaluator's measures by name, under the evaluator's key (``evaluators:`` in the config)."""
    stages: list[StageStats] = field(default_factory=list)
    mesh_path: Path | None = None
    """The mesh file the run read, if any."""
    inputs: tuple[Path, ...] = ()
    """Every file the run read (mesh, config files, points files), which :meth:`write` never overwrites."""
    formats: tuple[str, ...] = ()
    """The output formats this run's results are written in (set by the writer before writing)."""

    @property
    def warnings(self) -> list[str]:
        return self.context.warnings

    def write(self, outdir: str | Path, formats: str | Sequence[str] | None = None, force: bool = False) -> list[Path]:
        """Write the result files (``g2s run``'s) into ``outdir``; see :func:`g2s_core.api.write_result`."""
        from g2s_core.api import write_result  # the writers are plugins, which import this module

        return write_result(self, outdir, formats, force=force)

    @property
    def total_seconds(self) -> float:
        return sum(s.seconds for s in self.stages)

    def stage(self, name: str) -> StageStats | None:
        """The stats of stage ``name``, or ``None`` when it did not run."""
        return next((s for s in self.stages if s.stage == name), None)
