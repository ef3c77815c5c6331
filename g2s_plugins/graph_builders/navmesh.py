"""Surface graph from a Recast/Detour navmesh: one node per polygon, one edge per shared edge.

Builds a navmesh of the mesh for the run's agent (solo or tiled, see
:mod:`g2s_plugins.recast` and its ``tile_size`` parameter), stores it in
``context.navmesh`` and returns the polygon adjacency graph:

* node ``i`` = polygon ``i``: ``pos`` (centroid on the detail surface),
  ``normal``, ``area`` (m²), ``on_navmesh=True``, ``polygon=i``;
* edge ``(a, b)``, ``a < b``, for each pair of polygons sharing an edge
  (or, across a tile border, part of one): ``weight`` (distance between the
  two ``pos``), ``portal`` (the shared segment's two end points, mesh
  vertices) and ``width`` (its length).

Crests and troughs: where two polygons meet at a change of slope (the top or
the foot of a ramp) the straight segment between their centres cuts under the
crest or over the trough. When it strays more than ``max_edge_gap`` from the
walkable surface (:meth:`g2s_plugins.recast.NavMesh.segment_surface_gaps`,
probes ``agent radius / 2`` apart), the pair is joined through a *portal
node* instead: at the shared segment's midpoint on the detail surface,
``normal`` the mean of the two polygons', ``area`` 0, ``on_navmesh=True``,
``polygon=-1``; its two edges carry the pair's ``portal`` and ``width``.
Portal nodes are numbered after the polygons, in the order of their pairs.
``max_edge_gap: null`` gives the paper's graph (one edge per pair).

Corners: the two polygons are convex, so the segment between their centres
stays on them in plan exactly when it crosses their shared edge. One that
misses it (13-27 % of the pairs on generated dungeons and buildings) leaves
the pair round a corner, over other polygons or none, often for less than the
crest probes' spacing; that part, found exactly by clipping the segment
against both polygons in x-z (float64), is probed every
:data:`CORNER_PROBE_STEP` (5 mm), and the pair is routed as above when it
strays more than ``max_edge_gap`` there too (about 1 % of the pairs on
dungeons, 3 % on buildings, where a segment passing just outside its floor is
over the storey below; docs/navmesh.md).

Overlapping regions: Recast's watershed partition can make one region of
a switchback stairwell or spiral stair over several storeys, which overlaps
itself in plan; Recast traces its contour in plan and can lose its polygons or
their links there (the castle's spiral stairs come out as unlinked fragments).
The default ``partition: auto`` rebuilds the regions of
such a tile with ``monotone``, which never makes them, so nothing is left to
warn about. With ``partition: watershed`` the builder warns, with the count
and the first such region's position, when the navmesh has any
(:attr:`g2s_plugins.recast.NavMesh.region_overlaps`; docs/navmesh.md).

Nodes are inserted by polygon index, then the portal nodes; edges sorted by ``(a, b)``, then
each portal node's two.
"""

from __future__ import annotations

import math

import numpy as np
from pydantic import Field

from g2s_core.config import AgentConfig
from g2s_core.errors import G2SError
from g2s_core.lazy import lazy_module
from g2s_core.model import graph_of
from g2s_core.plugin import hookimpl
from g2s_plugins._surface import MAX_SURFACE_GAP
from g2s_plugins.play_space import PlaySpaceParams, cut_to_play_space
from g2s_plugins.recast import NavMesh, RecastParams, SettingsError, build_navmesh
from g2s_plugins.recast.settings import coarse_climb_warning, resolve_settings
from g2s_plugins.units_check import check_units
from g2s_plugins.walkable_check import check_walkable_surface, no_walkable_surface

area_gaps = lazy_module("g2s_plugins.area_gaps")  # it imports scipy and trimesh
nx = lazy_module("networkx")

NAME = "navmesh"


class Params(RecastParams, PlaySpaceParams):
    """Recast build parameters (see :class:`g2s_plugins.recast.RecastParams`), the crest rule and the play space
    (:class:`g2s_plugins.play_space.PlaySpaceParams`)."""

    max_edge_gap: float | None = Field(
        MAX_SURFACE_GAP, gt=0,
        description="an edge between two polygon centres straying further than this from the walkable surface "
        "(a crest or trough between them) goes through a node on their shared edge, m; null: never (the paper's graph)",
    )


def navmesh_graph(navmesh: NavMesh, agent: AgentConfig | None = None, max_edge_gap: float | None = None) -> nx.Graph:
    """The polygon adjacency graph of ``navmesh`` (the conventions of g2s_core.model).

    With ``max_edge_gap`` (m; needs ``agent`` for the probe spacing), pairs whose
    centre-to-centre segment strays further from the surface are joined through
    a portal node (see the module doc).
    """
    centres = navmesh.centres
    normals = navmesh.normals
    areas = navmesh.areas
    portals = navmesh.portals()
    pairs = portals.pairs
    weights = np.linalg.norm(centres[pairs[:, 1]] - centres[pairs[:, 0]], axis=1) if len(pairs) else np.zeros(0)

    # Plain Python values, converted in bulk (tolist) and zipped into tuples column by column: no list per row
    pos, nrm = _rows(centres), _rows(normals)
    nodes = {i: {"pos": p, "normal": n, "area": a, "on_navmesh": True, "polygon": i}
             for i, p, n, a in zip(range(navmesh.polygon_count), pos, nrm, areas.tolist())}
    crossing = np.zeros(len(pairs), dtype=bool)
    if max_edge_gap is not None and agent is None:
        raise ValueError("max_edge_gap needs the agent (its radius spaces the probes)")
    if max_edge_gap is not None and len(pairs):
        step, reach = _probe_spacing_and_reach(agent)
        starts, ends = centres[pairs[:, 0]], centres[pairs[:, 1]]
        _check_probe_count(float(np.hypot(*(ends - starts)[:, [0, 2]].T).sum()), step)
        gaps = navmesh.segment_surface_gaps(starts, ends, step, reach)
        crossing = (gaps > max_edge_gap) | (_corner_gaps(navmesh, reach) > max_edge_gap)
    direct = ~crossing
    shared = portals.endpoints[direct]
    graph = graph_of(nx.Graph(), nodes, (
        (a, b, {"weight": w, "portal": portal, "width": width})
        for a, b, w, portal, width in zip(
            *pairs[direct].T.tolist(), weights[direct].tolist(), zip(_rows(shared[:, 0]), _rows(shared[:, 1])),
            portals.widths[direct].tolist(),
        )
    ))
    if crossing.any():
        _add_portal_nodes(graph, navmesh, np.flatnonzero(crossing), agent, max_edge_gap)
    return graph


def _rows(points: np.ndarray) -> list[tuple[float, float, float]]:
    """(N,3) ``points`` as N tuples of 3 Python floats."""
    return list(zip(*points.T.tolist()))


def _probe_spacing_and_reach(agent: AgentConfig) -> tuple[float, float]:
    """The crest rule's probe spacing (agent radius / 2) and how far up or down a probe looks for the surface
    (twice the agent height), m."""
    return 0.5 * float(agent.radius), 2.0 * float(agent.height)


MAX_CREST_PROBES = 20_000_000
"""Crest probes at most in one pass (0.48 GB of positions): more means an agent radius far too small for the level."""


def _check_probe_count(length: float, step: float) -> None:
    """Refuse crest probes every ``step`` metres along ``length`` metres of links when they would be more than
    :data:`MAX_CREST_PROBES`."""
    if not (wanted := length / step) <= MAX_CREST_PROBES:
        raise G2SError(f"agent.radius: crest probes every {step:g} m (half the agent's radius) along {length:.4g} m "
                       f"of navmesh links make {wanted:.3g}, more than {MAX_CREST_PROBES:,}; use a larger agent.radius, "
                       "or check mesh.scale (the file's units to metres)")


CORNER_PROBE_STEP = 0.005
"""Probe spacing along the part of a centre segment outside its two polygons, m (see :func:`_corner_gaps`).

Those parts are short (0.5-1.1 m on average on the generated 1k levels) and
belong to 13-27 % of the pairs, so probing them 50 times more finely than the
crest rule costs about 0.1 s on the 23,101 pairs of ``dungeon(rooms=2400)``
(1 mm: 0.4 s; 1 cm: 0.05 s). What a finer spacing still finds are grazes:
against 1 mm probes, 5 mm ones flag 863 of its 867 pairs (1 cm: 859), and 0,
1 and 3 fewer on the three ``building_1k`` seeds; a stray between two probes
is less than 5 mm long and lies within 2.5 mm of a point on the surface."""

PLAN_TOLERANCE = 1e-6
"""Metres (plan, float64) a centre segment may pass outside its two polygons and still count as crossing their portal."""


def _corner_gaps(navmesh: NavMesh, reach: float) -> np.ndarray:
    """(E,) how far the part of each centre segment outside its two polygons strays from the surface, m.

    For each pair ``a``, ``b`` of ``navmesh.portals()``: the polygons are
    convex and share the portal, so the segment from ``a``'s centre to
    ``b``'s stays on them in plan exactly when it crosses the portal;
    otherwise it leaves ``a`` at ``t_a`` and enters ``b`` at ``t_b > t_a``
    (:func:`_clip`, float64) and passes a corner of the pair in between, over
    other polygons or none. That part alone is probed,
    :data:`CORNER_PROBE_STEP` apart, ends included
    (:meth:`NavMesh.segment_surface_gaps`, no surface within ``reach``:
    ``inf``); 0 for a segment crossing its portal (within
    :data:`PLAN_TOLERANCE`). O(E) sign tests, O(M · nvp) clipping of the M
    segments they leave in doubt, one C++ call over the parts outside.
    """
    portals = navmesh.portals()
    pairs, portal = portals.pairs, portals.endpoints
    gaps = np.zeros(len(pairs))
    starts, ends = navmesh.centres[pairs[:, 0]], navmesh.centres[pairs[:, 1]]
    # Only a segment not strictly between the portal's two ends needs clipping (most do not).
    sides = [_side(starts, ends, portal[:, end]) for end in (0, 1)]
    unsure = np.flatnonzero(~(sides[0] * sides[1] < 0))
    starts, ends, pairs = starts[unsure], ends[unsure], pairs[unsure]
    origin, direction = starts[:, [0, 2]], ends[:, [0, 2]] - starts[:, [0, 2]]
    leave_a = _clip(navmesh, pairs[:, 0], origin, direction, leaving=True)
    enter_b = _clip(navmesh, pairs[:, 1], origin, direction, leaving=False)
    with np.errstate(invalid="ignore"):  # a segment of no length in plan (inf * 0) is outside nothing
        outside = np.flatnonzero((enter_b - leave_a) * np.linalg.norm(direction, axis=1) > PLAN_TOLERANCE)
    if len(outside):
        span = ends[outside] - starts[outside]
        gaps[unsure[outside]] = navmesh.segment_surface_gaps(
            starts[outside] + leave_a[outside, None] * span, starts[outside] + enter_b[outside, None] * span,
            CORNER_PROBE_STEP, reach,
        )
    return gaps


def _side(starts: np.ndarray, ends: np.ndarray, points: np.ndarray) -> np.ndarray:
    """(E,) sign of the x-z cross product (end - start) x (point - start) of (E,3) arrays: which side of each line."""
    return np.sign(
        (ends[:, 0] - starts[:, 0]) * (points[:, 2] - starts[:, 2])
        - (ends[:, 2] - starts[:, 2]) * (points[:, 0] - starts[:, 0])
    )


def _clip(
    navmesh: NavMesh, polygons: np.ndarray, origin: np.ndarray, direction: np.ndarray, leaving: bool
) -> np.ndarray:
    """(E,) t where the x-z line ``origin + t direction`` ((E,2) each) leaves (or enters) each convex polygon.

    Cyrus-Beck: the smallest t over the edges the line runs out through
    (largest over those it runs in through); ``inf`` (``-inf``) when none.
    """
    corners = navmesh.polygons[polygons]
    padded = corners < 0  # the last vertex repeated: a zero-length edge, which bounds nothing
    last = np.take_along_axis(corners, (~padded).sum(axis=1, keepdims=True) - 1, axis=1)
    ring = navmesh.vertices[np.where(padded, last, corners)][..., [0, 2]]
    following = np.roll(ring, -1, axis=1)
    edge = following - ring
    turn = np.sign(np.sum(ring[..., 0] * following[..., 1] - following[..., 0] * ring[..., 1], axis=1))
    inward = np.stack([-edge[..., 1], edge[..., 0]], axis=2) * turn[:, None, None]  # either winding
    height = np.sum(inward * (origin[:, None, :] - ring), axis=2)
    rate = np.sum(inward * direction[:, None, :], axis=2)
    with np.errstate(divide="ignore", invalid="ignore"):
        crossing = -height / rate
    if leaving:
        return np.where(rate < 0, crossing, np.inf).min(axis=1)
    return np.where(rate > 0, crossing, -np.inf).max(axis=1)


REFINEMENTS = 3
"""How many times a piece of a routed edge is split again at its worst probe (at most 2**3 pieces a side)."""


def _add_portal_nodes(
    graph: nx.Graph, navmesh: NavMesh, which: np.ndarray, agent: AgentConfig, max_edge_gap: float
) -> None:
    """Join each pair ``which`` indexes (into ``navmesh.portals()``) along the surface (see the module doc)."""
    portals = navmesh.portals()
    reach = _probe_spacing_and_reach(agent)[1]
    extents = (float(navmesh.settings["cell_size"]), reach, float(navmesh.settings["cell_size"]))
    pairs, endpoints, widths = portals.pairs[which].tolist(), portals.endpoints[which], portals.widths[which].tolist()
    middles = endpoints.mean(axis=1)
    surface = [navmesh.nearest_poly(middle, extents=extents) for middle in middles]
    polygons = [int(polygon) if polygon >= 0 else a for (polygon, _), (a, _b) in zip(surface, pairs)]
    middles = np.array([nearest if polygon >= 0 else middle for (polygon, nearest), middle in zip(surface, middles)],
                       dtype=np.float64).reshape(-1, 3)
    centres = navmesh.centres
    # each pair's two halves, centre to middle and middle to centre, refined all together
    starts = np.stack([centres[[a for a, _ in pairs]], middles], axis=1).reshape(-1, 3)
    ends = np.stack([middles, centres[[b for _, b in pairs]]], axis=1).reshape(-1, 3)
    halves = _surface_points_between(navmesh, starts, ends, REFINEMENTS, agent, max_edge_gap, extents)
    chains = [[*halves[2 * k], (polygon, middle), *halves[2 * k + 1]] for k, (polygon, middle) in
              enumerate(zip(polygons, middles.tolist()))]
    # the normals of the polygons the new nodes stand on, as tuples in one pass (not the rows of all polygons)
    normals = iter(_rows(navmesh.normals[[on for chain in chains for on, _ in chain]]))
    nodes: dict[int, dict] = {}
    edges: list[tuple[int, int, dict]] = []
    node_data, node = graph._node, navmesh.polygon_count
    for (a, b), chain, portal, width in zip(pairs, chains, zip(_rows(endpoints[:, 0]), _rows(endpoints[:, 1])), widths):
        previous, previous_pos = a, node_data[a]["pos"]
        for _, point in chain:
            pos = tuple(point)
            nodes[node] = {"pos": pos, "normal": next(normals), "area": 0.0, "on_navmesh": True, "polygon": -1}
            edges.append((previous, node, {"weight": math.dist(previous_pos, pos), "portal": portal, "width": width}))
            previous, previous_pos, node = node, pos, node + 1
        edges.append((previous, b, {"weight": math.dist(previous_pos, node_data[b]["pos"]), "portal": portal, "width": width}))
    # all nodes, then all edges in the order they were made: the same graph as adding them pair by pair
    graph_of(graph, nodes, edges)


def _surface_points_between(
    navmesh: NavMesh, starts: np.ndarray, ends: np.ndarray, depth: int, agent: AgentConfig, max_edge_gap: float,
    extents: tuple[float, float, float],
) -> list[list[tuple[int, list[float]]]]:
    """For each segment ``starts[i] -> ends[i]`` ((S,3) each), the surface points (polygon, position) strictly
    between them that bring every piece within ``max_edge_gap``, in order from start to end.

    A piece is probed every probe step (``agent``'s); if its worst probe strays further than the gap, the surface
    point nearest that probe splits it in two, each refined again, ``depth`` levels in all. All pieces of a
    level in one C++ call.
    """
    found: list[list[tuple[int, list[float]]]] = [[] for _ in range(len(starts))]
    if depth == 0 or not len(starts):
        return found
    step, reach = _probe_spacing_and_reach(agent)
    span = ends - starts
    lengths = [math.hypot(dx, dz) for dx, _, dz in span.tolist()]
    _check_probe_count(sum(lengths), step)
    counts = [max(1, math.ceil(length / step)) for length in lengths]
    probed = [i for i, count in enumerate(counts) if count >= 2]
    if not probed:
        return found
    inner = np.array([counts[i] - 1 for i in probed])
    rows, first = np.repeat(probed, inner), np.cumsum(inner) - inner
    fraction = (np.arange(len(rows)) - np.repeat(first, inner) + 1) / np.repeat([counts[i] for i in probed], inner)
    probes = starts[rows] + fraction[:, None] * span[rows]
    gaps = navmesh.segment_surface_gaps(probes, probes, step, reach)
    split, points = [], []
    for i, worst in zip(probed, _first_largest(gaps, first).tolist()):
        if not gaps[worst] <= max_edge_gap:
            polygon, point = navmesh.nearest_poly(probes[worst], extents=extents)
            if polygon >= 0:  # else no surface there to follow
                split.append((i, int(polygon)))
                points.append(np.asarray(point, dtype=np.float64))
    if not split:
        return found
    indices = [i for i, _ in split]
    middles = np.array(points, dtype=np.float64).reshape(-1, 3)
    pieces = _surface_points_between(
        navmesh, np.concatenate([starts[indices], middles]), np.concatenate([middles, ends[indices]]), depth - 1,
        agent, max_edge_gap, extents,
    )
    for j, ((i, polygon), middle) in enumerate(zip(split, middles.tolist())):
        found[i] = [*pieces[j], (polygon, middle), *pieces[len(split) + j]]
    return found


def _first_largest(values: np.ndarray, starts: np.ndarray) -> np.ndarray:
    """(k,) for each run ``values[starts[j]:starts[j + 1]]`` (the last to the end; none empty) the index of its
    largest value, the first of equal ones, a NaN above all (``np.argmax`` of each run, without a call per run)."""
    top = np.repeat(np.maximum.reduceat(values, starts), np.diff(np.r_[starts, len(values)]))  # NaN where a run has one
    hit = (values == top) | (np.isnan(values) & np.isnan(top))
    return np.minimum.reduceat(np.where(hit, np.arange(len(values)), len(values)), starts)


def overlapping_regions_warning(overlaps: np.ndarray, partition: str) -> str:
    """The warning for (K,3) ``overlaps`` (:attr:`NavMesh.region_overlaps`, K > 0) of a ``partition`` build."""
    count = len(overlaps)
    x, y, z = (float(v) for v in overlaps[0])
    regions = "1 region that overlaps itself" if count == 1 else f"{count} regions that overlap themselves"
    return (
        f"graph: Recast's {partition} partition made {regions} in plan (a stairwell over several storeys?), "
        f"the first at ({x:.1f}, {y:.1f}, {z:.1f}) m: Recast may lose polygons there or their links (a stair "
        f"cut off); set graph.params.partition: auto, the default (docs/navmesh.md)"
    )


def no_polygons_reason(reason: str, agent: AgentConfig, params: Params) -> str:
    """Recast's ``reason`` for a navmesh without polygons, with the settings that decide it where Recast kept no
    region (``no contours``): the walkable areas left once the agent's radius is taken off (levels of small islands,
    a pad) are each under ``region_min_size``² cells, which Recast removes, or too small to outline in cells of
    ``cell_size``; both settings are named, in the level's metres."""
    if "no contours" not in reason:
        return reason
    settings = resolve_settings(agent, params)
    cell, size = settings["cell_size"], settings["region_min_size"]
    outline = f"too small to outline in cells of {cell:g} m"
    if math.trunc(size * size) == 0:  # Recast removed no region for its size
        return f"{reason}: each walkable area left once the agent's radius is taken off is {outline}; try a smaller " \
               f"graph.params.cell_size"
    return (f"{reason}: each walkable area left once the agent's radius is taken off is under "
            f"graph.params.region_min_size ({size:g}² cells of {cell:g} m, {math.trunc(size * size) * cell * cell:.3g} "
            f"m²), which Recast removes, or {outline}; try a smaller graph.params.region_min_size or cell_size")


@hookimpl
def g2s_build_graph(mesh, params, context):
    """Build the navmesh of ``mesh`` for ``context.agent`` and return its polygon graph, cut to the play space
    when ``params.play_points`` names one (:func:`g2s_plugins.play_space.cut_to_play_space`).

    Raises:
        G2SError: a setting or the level's size that Recast cannot handle
            (naming the key), a Recast step that fails on this input, or no
            surface this agent can walk: properties of the input and the
            settings, not failures of the program.
    """
    params = params if params is not None else Params()
    check_units(mesh, context)  # before the build, which a level in centimetres makes long
    try:
        navmesh = build_navmesh(mesh.vertices, mesh.faces, context.agent, params)
    except SettingsError as exc:
        raise G2SError(str(exc)) from exc
    except RuntimeError as exc:
        if "overlap themselves in plan" in str(exc):  # the partition's doing, not the mesh's
            raise G2SError(f"graph.params.partition: {params.partition}: {exc}") from exc
        if "no walkable" not in str(exc):
            raise G2SError(
                f"graph.params: {exc}; try another cell_size or tile_size (see docs/navmesh.md)"
            ) from exc
        raise no_walkable_surface(mesh, context.agent, no_polygons_reason(str(exc), context.agent, params)) from exc
    context.navmesh, context.likely_cause = navmesh, area_gaps.likely_cause_of(context.agent, navmesh, mesh=mesh)
    if len(navmesh.region_overlaps):
        context.warn(overlapping_regions_warning(navmesh.region_overlaps, params.partition))
    level_height = float(np.ptp(mesh.vertices[:, 1])) if len(mesh.vertices) else 0.0
    if coarse := coarse_climb_warning(navmesh.settings, params, level_height):
        context.warn(coarse)
    graph = navmesh_graph(navmesh, context.agent, params.max_edge_gap)
    check_walkable_surface(graph, mesh, context)
    return cut_to_play_space(graph, params.play_points, context)
