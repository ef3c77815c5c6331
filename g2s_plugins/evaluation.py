"""How well a map-analysis run shows where people walk: coverage, traffic off the
structure, agreement of the heat map with the reference flow.

The measures (all along the initial walkable graph, distances in metres):

``area_within``
    share of the walkable area (sum of node ``area``) whose node lies within
    r metres of the structure, for each r of ``radii``. "The structure" is
    every node of the Steiner stage's forest with its loop paths
    (``RunResult.looped``, else ``steiner``): the final
    structure's edges stand for those chains of polygons; less the
    branches of the leaves simplification dropped
    (:func:`g2s_plugins.structure_leaves.standing_for`).
``traffic_off``
    share of the reference flow (:func:`reference_flow`) through nodes more
    than ``off_distance`` metres from the structure.
``rho``
    Spearman correlation, over the nodes of the initial graph that reach the
    final structure, between the heat map (each node takes the first
    analyzer's value of its nearest final-structure node) and the reference
    flow.
``rho_area``
    ``rho`` with each node weighted by its walkable area (``area``, m²; 1
    per node when no node has an area, as the reference flow draws them): a
    weighted Spearman correlation, the weighted Pearson correlation of the
    weighted mid-ranks (:func:`weighted_spearman`). ``rho`` ranks every
    polygon equally, so a 0.4 m² sliver along a wall moves it as much as a
    200 m² hall (the paper's own limit: every polygon counts the same,
    whatever its size); here each square metre counts the same. Nodes of no
    area (portal nodes) count nothing. Same nodes as ``rho``.
``rho_area_betweenness``
    the same as ``rho`` for area-weighted betweenness on the final structure, whatever
    the run's analyzers are (an honest check when the run's heat map is the
    ``flow`` analyzer, which agrees with the reference partly by
    construction).
``rho_ceiling``
    the same when each final-structure node carries the mean percentile
    rank of the reference flow over the initial-graph nodes it stands for
    (the same nearest-node mapping): what the structure's node placement
    allows, whatever the analyzer. The mean rank fits each node's polygons
    best in squares of ranks, which is close to but not exactly the best
    order for a rank correlation, so an analyzer can beat it slightly on
    tiny graphs. The ``flow`` analyzer with ``aggregate: percentile``
    computes these values (from its own source sample on big graphs): its
    rho is this figure by construction.
``rho_within``
    ``rho`` within each connected area of the initial graph: the Pearson
    correlation, pooled over the areas, of the heat map's and the reference
    flow's percentile ranks within their own area (each node's mid-rank
    among the nodes of its area that reach the structure, over their
    count; :func:`within_area_rho`). Same nodes as ``rho``. ``rho`` also
    ranks the areas against one another: an area apart holds few pairs,
    so all its nodes sit low in the flow and, when the heat map is right
    about that, low in the heat map too, which counts as agreement however
    the area's own nodes are ordered (a level of a street and 17 roofs
    apart read ``rho`` 0.957-0.974 where the street alone read 0.828-0.878:
    docs/analysis_quality.md, "A twenty-first round of level kinds"). Ranks
    within an area remove that order and keep each area's own. On a level
    of one area it is ``rho`` (percentile ranks are the mid-ranks over a
    constant; equal up to rounding). With no ties it is the mean of the
    areas' own Spearman rho weighted by n - 1/n for an area of n nodes
    (each area's rank variance times its count: about one a node, as in
    ``rho``); an area of one node weighs nothing, and an area where one of
    the two is constant adds to the other's spread only, which lowers the
    figure (a heat map that varies where the flow does not). Why this
    form: a mean of the areas' own rho needs a rule for each area where it
    is undefined (one or two nodes, a constant), and weighted by walkable
    area it would let one wide hall outweigh many small rooms, unlike
    ``rho``; the largest area's rho ignores every other area (a level of
    storeys joined only by ladders has three of like size). A Spearman rho
    of the pooled percentiles would rank them again across areas and lose
    the exact decomposition above.
``rho_within_ceiling``
    ``rho_within`` of ``rho_ceiling``'s heat map: what the structure's node
    placement allows within each area.
``structure_share``
    final structure nodes / initial graph nodes.
``rho_navmesh``, ``rho_navmesh_ceiling``
    ``rho`` and ``rho_ceiling`` measured on the *navmesh graph* of the level
    instead of the run's own initial graph: where people walk is a property
    of the level, which issue 9 defines as the walking flow
    (:func:`reference_flow`, the same sources rule) on the graph of navmesh
    polygons, whatever graph the run analyses. For a run of the ``navmesh``
    builder (``context.navmesh`` set) that graph is the run's own and the
    mapping below is the identity, so these are ``rho`` and
    ``rho_ceiling`` exactly. Otherwise (the sampling route) the navmesh of
    the same mesh is built for the run's agent with the ``navmesh``
    builder's default parameters but :data:`REFERENCE_LEDGE_FILTER` (:func:`~g2s_plugins.recast.build_navmesh`,
    :func:`~g2s_plugins.graph_builders.navmesh.navmesh_graph`) and the heat
    map is carried from the samples to its nodes (:func:`navmesh_surface`,
    :func:`carry`):

    * each sample belongs to the polygon it stands on: Detour's nearest
      polygon (:meth:`~g2s_plugins.recast.NavMesh.nearest_poly`, one call
      per sample: the extension has no batched form), unless the nearest
      point on it is off the sample in plan (more than
      :data:`PLAN_TOLERANCE`) or more than the navmesh's climb tolerance
      away in height: then it belongs to none (samples in the margin Recast
      erodes a little wider than the sampler's clearance, crate tops Recast
      leaves out);
    * a polygon's value is the area-weighted mean of the heat of the
      samples on it that reach the structure (each sample's heat as in
      ``rho``), exactly the common value when they all have one (so ties
      stay ties for the rank correlation);
    * a polygon with no such sample, and a portal node (``area`` 0, on a
      crest between two polygons: ``rho`` ranks it like any node with the
      value of its nearest structure node, so here it takes a value the same
      way as an empty polygon), takes the heat of the nearest sample that
      reaches the structure (3D, from its ``pos``; scipy ``cKDTree``) within
      :data:`REACH_SPACINGS` sample spacings (the builder's ``spacing``,
      else twice the agent radius, its default), else it is left out; so is
      every node of a connected area of the navmesh on which no such sample
      stands (an island inside a crate: the nearest sample is outside it);
    * for the ceiling each structure node carries the mean percentile of
      the navmesh reference over the samples it stands for (the same
      nearest-node rule as ``rho_ceiling``), each sample counting its
      polygon's (samples on no polygon count nothing), carried the same way.
``navmesh_area_left_out``
    share of the navmesh graph's area that the heat map could not be carried
    to (no sample that reaches the structure on or near it; on the navmesh
    route: the nodes that reach no structure, which ``rho`` leaves out too).

Play space. A run whose graph builder names ``play_points`` (the play space
of a level whose file also holds background ground) has an initial graph cut
to that space where it was built (:mod:`g2s_plugins.play_space`), so every
measure above is the play space's with no rule of its own here: the shares'
totals (area, reference flow, nodes) are its, and the reference flow is
walked, and its sources drawn, there alone. Off the navmesh route the
reference navmesh graph is cut by the same rule
(:func:`g2s_plugins.play_space.play_space_graph`).

Cost: two multi-source Dijkstra searches plus the reference flow (see
:func:`g2s_plugins.traffic.od_flow`). Off the navmesh route the navmesh
measures add a navmesh build of the mesh (Recast: the ``navmesh`` builder's
graph stage), its reference flow, one Detour look-up per sample, one
k-d tree query and two more multi-source searches; a navmesh that cannot be
built leaves them out.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Hashable, Iterable, Mapping
from dataclasses import dataclass

import numpy as np

from g2s_core.lazy import lazy_module
from g2s_core.model import RunResult
from g2s_plugins import centrality, play_space, traffic
from g2s_plugins.graph_builders import navmesh as navmesh_builder
from g2s_plugins.recast import NavMesh, SettingsError, build_navmesh

csgraph, spatial = lazy_module("scipy.sparse.csgraph"), lazy_module("scipy.spatial")
structure_leaves = lazy_module("g2s_plugins.structure_leaves")  # it imports g2s_core.simplify, which imports scipy
nx = lazy_module("networkx")

RADII = (3.0, 6.0, 10.0)
"""Coverage radii reported by default, metres."""

REFERENCE_SOURCES = 512
"""Graphs with more nodes of positive weight than this and than :data:`g2s_plugins.traffic.EXACT_NODES` get a
sampled reference flow with this many sources; smaller ones the exact flow."""

REFERENCE_TIES: traffic.Ties = "split"
"""The reference flow splits each pair's weight evenly over all its shortest paths (:mod:`g2s_plugins.traffic`):
issue 9's walker takes "the shortest path", and where several tie none is more the one than another. Before 4
December 2026 (evening) it took the first (``first``). On navmesh graphs, whose lengths rarely tie, the two are
the same: nav_test's and the 1k dungeons' and buildings' exact flows are the same floats either way (nav_test's
within 1.1e-16 of the largest), so no rho of the navmesh route moved; on a grid of samples the first is a pattern
of the search's tie rule (docs/analysis_quality.md, "Walking flow that splits tied paths")."""

REFERENCE_SCALING: traffic.Scaling = "linear"
"""How a sampled reference flow (graphs over :data:`g2s_plugins.traffic.EXACT_NODES` nodes) counts its sources'
pairs: linearly scaled (:func:`g2s_plugins.traffic.linear_through`; Geisberger, Sanders and Schultes, ALENEX 2008),
an unbiased estimate without the plain sample's excess round its sources. Against the exact flow, on the sampling
route's grids (nav_test, the 1k building and dungeon, seed 0, sources of seeds 0 and 1), the linear 512-source
reference ranks the samples at Spearman 0.992-1.000 where the plain one gave 0.960-0.985, and the heat map's rho
against it is within 0.007 of its rho against the exact flow, where the plain one read 0.010-0.035 low; on the 20k
dungeon's navmesh within 0.002 (plain: -0.008 to +0.002)
(docs/analysis_quality.md, "A reference flow without its sources' excess"). Before 5 December 2026 it was plain
(``none``)."""

PLAN_TOLERANCE = 1e-3
"""A sample stands on a polygon when Detour's nearest point on it is this close in plan, m (float32 rounding)."""

REACH_SPACINGS = 2.0
"""A navmesh node without a sample takes the nearest sample's heat within this many sample spacings."""

REFERENCE_LEDGE_FILTER = "drops"
"""The ledge filter of the reference navmesh built for the sampling route, as ``map_analysis`` builds its own:
Recast's filter (the builder's default) also drops ground of 37-45 degrees the agent and the sampler walk, so the
reference walked less of the level than the samples (docs/analysis_quality.md, "The sampling route on slopes"). Before
4 December 2026 (evening) it was the builder's default, ``recast``."""


@dataclass(frozen=True)
class Quality:
    """The measures of one run (see the module docs); shares are in [0, 1]."""

    area_within: dict[float, float]
    traffic_off: float
    rho: float
    rho_area_betweenness: float
    rho_ceiling: float
    structure_share: float
    rho_navmesh: float = float("nan")
    rho_navmesh_ceiling: float = float("nan")
    navmesh_area_left_out: float = float("nan")
    rho_area: float = float("nan")
    rho_within: float = float("nan")
    rho_within_ceiling: float = float("nan")

    def measures(self) -> dict[str, float]:
        """The measures by name, as the ``traffic`` evaluator reports them (``area_within_6m``,
        ``traffic_off``, ``rho``, ``rho_area``, ``rho_area_betweenness``, ``rho_ceiling``, ``rho_within``,
        ``rho_within_ceiling``, ``structure_share``, ``rho_navmesh``, ``rho_navmesh_ceiling``,
        ``navmesh_area_left_out``); NaN ones left out."""
        named = {**{f"area_within_{r:g}m": v for r, v in self.area_within.items()}, "traffic_off": self.traffic_off,
                 "rho": self.rho, "rho_area": self.rho_area, "rho_area_betweenness": self.rho_area_betweenness, "rho_ceiling": self.rho_ceiling,
                 "rho_within": self.rho_within, "rho_within_ceiling": self.rho_within_ceiling,
                 "structure_share": self.structure_share, "rho_navmesh": self.rho_navmesh,
                 "rho_navmesh_ceiling": self.rho_navmesh_ceiling, "navmesh_area_left_out": self.navmesh_area_left_out}
        return {name.replace(".", "_"): value for name, value in named.items() if math.isfinite(value)}


def reference_flow(result: RunResult, max_sources: int = REFERENCE_SOURCES, seed: int = 0) -> np.ndarray:
    """(n,) area-weighted OD flow through each initial-graph node, in graph node order: exact up to
    :data:`g2s_plugins.traffic.EXACT_NODES` (or ``max_sources``) nodes of positive weight, the heat-map
    guarantee's rule, else from ``max_sources`` sampled sources, linearly scaled (:data:`REFERENCE_SCALING`); ties
    split (:data:`REFERENCE_TIES`)."""
    return traffic.walking_flow(result.graph, max_sources, seed, exact_up_to=traffic.EXACT_NODES, ties=REFERENCE_TIES,
                                scaling=REFERENCE_SCALING)


def nearest_structure_rows(result: RunResult) -> np.ndarray:
    """(n,) the row of each initial-graph node's nearest final-structure node along the graph (-1: none)."""
    return _nearest_rows(result.graph, result.structure)


def _nearest_rows(graph: nx.Graph, structure_nodes: Iterable[Hashable]) -> np.ndarray:
    arrays = traffic.surface_arrays(graph)
    return traffic.distance_to(arrays, arrays.rows(sorted(structure_nodes)))[1]


def heat_map(graph: nx.Graph, structure_nodes: Iterable[Hashable], values: Mapping[Hashable, float],
             nearest: np.ndarray | None = None) -> np.ndarray:
    """(n,) each node of ``graph`` (a run's initial graph) given the value of its nearest structure node (NaN where none).

    ``nearest``: :func:`nearest_structure_rows` of the run, when already known.
    """
    arrays = traffic.surface_arrays(graph)
    structure = sorted(structure_nodes)
    if nearest is None:
        nearest = _nearest_rows(graph, structure)
    by_row = np.full(arrays.n, np.nan)
    by_row[arrays.rows(structure)] = [values[node] for node in structure]
    return np.where(nearest >= 0, by_row[np.maximum(nearest, 0)], np.nan)


def placement_heat(graph: nx.Graph, structure_nodes: Iterable[Hashable], flow: np.ndarray,
                   nearest: np.ndarray | None = None, areas: np.ndarray | None = None) -> np.ndarray:
    """(n,) the heat map whose structure nodes carry the mean percentile of ``flow`` over the nodes they stand for.

    Each node of ``graph`` gets its nearest structure node's mean of
    :func:`~g2s_plugins.traffic.percentile` of the (n,) ``flow``: the
    ``flow`` analyzer's heat map with ``aggregate: percentile`` when ``flow``
    is its walking flow, and ``rho_ceiling``'s when ``flow`` is the reference.
    With (n,) ``areas`` (:func:`area_labels`) the percentiles are those within each connected area
    (:func:`within_area_percentiles`; a structure node stands only for nodes of its own area).
    """
    if nearest is None:  # one search for both: the nodes each structure node stands for are those it is nearest to
        nearest = _nearest_rows(graph, structure_nodes)
    return nearest_mean(nearest, traffic.percentile(flow) if areas is None else within_area_percentiles(flow, areas))


def nearest_mean(nearest: np.ndarray, values: np.ndarray) -> np.ndarray:
    """(n,) each node given the mean of (n,) ``values`` over the nodes whose nearest structure node is its own (NaN
    where none): :func:`~g2s_plugins.traffic.gather` with ``mean`` then :func:`heat_map`, to the bit, on arrays
    alone. ``nearest``: (n,) each node's nearest structure node's row (-1: none), the second result of
    :func:`~g2s_plugins.traffic.distance_to`. O(n)."""
    return np.where(nearest >= 0, traffic.gathered(nearest, values, mean=True)[np.maximum(nearest, 0)], np.nan)


def placement_rho(graph: nx.Graph, structure_nodes: Iterable[Hashable], flow: np.ndarray,
                  nearest: np.ndarray | None = None) -> float:
    """Spearman rho between :func:`placement_heat` and ``flow`` over the nodes that reach the structure
    (``rho_ceiling`` when ``flow`` is the reference flow; NaN when undefined)."""
    return spearman(placement_heat(graph, structure_nodes, flow, nearest), flow)


@dataclass(frozen=True)
class NavmeshSurface:
    """The navmesh graph a run's heat map is measured on, and how the run's initial graph stands on it.

    Attributes:
        graph: the navmesh polygon graph (:mod:`g2s_plugins.graph_builders.navmesh`).
        flow: (N,) its reference flow, in :func:`~g2s_plugins.traffic.surface_arrays` order.
        owner: (n,) for each row of the run's initial graph, the row of the navmesh node it stands on (-1: none).
        reach: how far a navmesh node looks for the nearest sample when none stands on it, m.
    """

    graph: nx.Graph
    flow: np.ndarray
    owner: np.ndarray
    reach: float


def polygons_under(navmesh: NavMesh, points: np.ndarray, reach: float = PLAN_TOLERANCE) -> np.ndarray:
    """(n,) the polygon each of the (n,3) ``points`` stands on, or comes within ``reach`` metres of in plan, -1 where
    none (see the module docs)."""
    polygons = np.full(len(points), -1, dtype=np.int64)
    for i, point in enumerate(np.asarray(points, dtype=np.float64)):
        polygon, nearest = navmesh.nearest_poly(point)
        if (polygon >= 0 and abs(nearest[1] - point[1]) <= navmesh.climb_tolerance
                and math.hypot(nearest[0] - point[0], nearest[2] - point[2]) <= reach):
            polygons[i] = polygon
    return polygons


def navmesh_surface(result: RunResult, reference: np.ndarray, max_sources: int = REFERENCE_SOURCES,
                    seed: int = 0) -> NavmeshSurface | None:
    """The navmesh graph of the run's level, its reference flow and the mapping to it (see the module docs).

    Args:
        reference: :func:`reference_flow` of the run's own graph (the navmesh's, on the navmesh route).

    Returns ``None`` when Recast cannot build a navmesh of the mesh for the run's agent.
    """
    arrays = traffic.surface_arrays(result.graph)
    if result.context.navmesh is not None:  # the run's graph is the navmesh graph: the identity
        return NavmeshSurface(result.graph, reference, np.arange(arrays.n), 0.0)
    context = result.context
    params = navmesh_builder.Params(ledge_filter=REFERENCE_LEDGE_FILTER)
    try:
        navmesh = build_navmesh(context.mesh.vertices, context.mesh.faces, context.agent, params)
    except (SettingsError, RuntimeError):
        return None
    graph = navmesh_builder.navmesh_graph(navmesh, context.agent, params.max_edge_gap)
    points = play_space.play_points(result.config)
    if points is not None:  # the level's walking flow in the run's play space, by the rule that cut the run's graph
        graph = play_space.play_space_graph(graph, navmesh, points, context.agent.height)
    navmesh_arrays = traffic.surface_arrays(graph)
    polygon_rows = np.full(navmesh.polygon_count, -1, dtype=np.int64)
    kept_polygons = [polygon for polygon in range(navmesh.polygon_count) if polygon in graph]
    polygon_rows[kept_polygons] = navmesh_arrays.rows(kept_polygons)
    polygons = polygons_under(navmesh, _positions(result.graph))
    owner = np.where(polygons >= 0, polygon_rows[np.maximum(polygons, 0)], -1)
    spacing = result.graph.graph.get("sampling_stats", {}).get("spacing", 2.0 * float(context.agent.radius))
    flow = traffic.walking_flow(graph, max_sources, seed, exact_up_to=traffic.EXACT_NODES, ties=REFERENCE_TIES,
                                scaling=REFERENCE_SCALING)
    return NavmeshSurface(graph, flow, owner, REACH_SPACINGS * spacing)


def carry(values: np.ndarray, area: np.ndarray, positions: np.ndarray, surface: NavmeshSurface) -> np.ndarray:
    """(N,) ``values`` of the run's initial-graph nodes carried to the navmesh graph's nodes (NaN: left out).

    Args:
        values: (n,) one value per initial-graph row (NaN: none, e.g. a node that reaches no structure).
        area: (n,) their areas, m² (the weights of a polygon's mean).
        positions: (n,3) their positions, m.

    A navmesh node takes the area-weighted mean of the values standing on
    it (their common value exactly when they are all equal; the plain mean
    when their areas are all 0), else the value of the nearest valued node
    within ``surface.reach`` (3D), else NaN; every node of a connected area of
    the navmesh graph on which no valued node stands is NaN. O(n + N log n).
    """
    n_nodes = traffic.surface_arrays(surface.graph).n
    valued = np.isfinite(values)
    on = valued & (surface.owner >= 0)
    owner, value, weight = surface.owner[on], values[on], area[on]
    count = np.bincount(owner, minlength=n_nodes)
    weights = np.bincount(owner, weights=weight, minlength=n_nodes)
    weighted = np.bincount(owner, weights=weight * value, minlength=n_nodes)
    plain = np.bincount(owner, weights=value, minlength=n_nodes)
    lowest, highest = np.full(n_nodes, np.inf), np.full(n_nodes, -np.inf)
    np.minimum.at(lowest, owner, value)
    np.maximum.at(highest, owner, value)
    with np.errstate(invalid="ignore", divide="ignore"):
        carried = np.where(weights > 0, weighted / weights, plain / count)
    carried = np.where(lowest == highest, lowest, carried)
    empty = np.flatnonzero(count == 0)
    carried[empty] = np.nan
    if empty.size and valued.any():
        distance, nearest = spatial.cKDTree(positions[valued]).query(_positions(surface.graph)[empty])
        near = distance <= surface.reach
        carried[empty[near]] = values[valued][nearest[near]]
    # an area of the navmesh that no valued sample stands on (an island inside a crate, which the sampler leaves
    # out) is left out: its nearest sample lies across a wall, where the reference walks
    component = area_labels(surface.graph)
    held = np.bincount(component[owner], minlength=len(component)) > 0
    carried[~held[component]] = np.nan
    return carried


def area_labels(graph: nx.Graph) -> np.ndarray:
    """(n,) the connected area of each node of ``graph``, in :func:`~g2s_plugins.traffic.surface_arrays` order:
    labels 0 .. areas - 1 (scipy's connected components, O(n + m))."""
    return csgraph.connected_components(traffic.surface_arrays(graph).adjacency, directed=False)[1]


def _positions(graph: nx.Graph) -> np.ndarray:
    """(n,3) the ``pos`` of every node, in :func:`~g2s_plugins.traffic.surface_arrays` order."""
    nodes = traffic.surface_arrays(graph).nodes
    return np.array([graph.nodes[node]["pos"] for node in nodes], dtype=np.float64).reshape(-1, 3)


def _navmesh_ceiling(result: RunResult, surface: NavmeshSurface) -> dict:
    """Per final-structure node, the mean percentile of the navmesh reference over the samples it stands for."""
    standing = surface.owner >= 0
    percentile = np.where(standing, traffic.percentile(surface.flow)[np.maximum(surface.owner, 0)], 0.0)
    sums = traffic.gather(result.graph, result.structure, percentile)
    counts = traffic.gather(result.graph, result.structure, standing.astype(np.float64))
    return {node: sums[node] / counts[node] if counts[node] > 0 else float("nan") for node in sums}


def spearman(heat: np.ndarray, reference: np.ndarray) -> float:
    """Spearman rho of (n,) ``heat`` and ``reference`` over the entries where ``heat`` is finite (NaN: fewer
    than three, or either constant there): :func:`weighted_spearman` with equal weights, which is
    ``scipy.stats.spearmanr`` up to rounding, without importing ``scipy.stats`` (0.3-0.6 s of CPU, more than a
    1k-polygon level's whole run, which ``min_heat_rho`` measures)."""
    ok = np.isfinite(heat)
    if ok.sum() < 3 or np.ptp(heat[ok]) == 0 or np.ptp(reference[ok]) == 0:
        return float("nan")
    return weighted_spearman(heat[ok], reference[ok], np.ones(int(ok.sum())))


def weighted_spearman(x: np.ndarray, y: np.ndarray, weight: np.ndarray) -> float:
    """Spearman's rho of (n,) ``x`` and ``y`` with (n,) ``weight`` >= 0 per observation (NaN when undefined).

    Each value's rank is its weighted mid-rank: the weight of the smaller
    values plus half that of its ties, so tied values share one rank and an
    observation of weight w counts as w observations; rho is the weighted
    Pearson correlation of the two rank vectors (``numpy.cov`` with
    ``aweights``). With equal weights this is ``scipy.stats.spearmanr``
    (ranks shifted and scaled alike, which a correlation ignores). The same
    construction, weighted ranks then a weighted Pearson correlation, as
    the weighted Spearman of the R package wCorr (Bailey, Emad, Zhang and
    Xie, "wCorr Formulas"). O(n log n).
    """
    if not weight.sum() > 0:
        return float("nan")
    return _pearson(_weighted_midranks(x, weight), _weighted_midranks(y, weight), weight)


def within_area_rho(heat: np.ndarray, reference: np.ndarray, area: np.ndarray) -> float:
    """``rho_within`` (see the module docs): the Pearson correlation of (n,) ``heat`` and ``reference`` turned into
    percentile ranks within each connected area of (n,) labels ``area`` (:func:`within_area_percentiles` with exact
    ties, as :func:`spearman` ranks), over the entries where ``heat`` is finite (NaN: fewer than three, or either rank
    constant within every area).

    A rank's mean is 50 in every area, so the pooled correlation is that of deviations from each area's own mean
    (the pooled within-group correlation of the areas' ranks). O(n log n), one sort per area.
    """
    ok = np.isfinite(heat)
    if ok.sum() < 3:
        return float("nan")
    heat_ranks, reference_ranks = (within_area_percentiles(values[ok], area[ok], _exact_percentiles)
                                   for values in (heat, reference))
    return _pearson(heat_ranks, reference_ranks, np.ones(int(ok.sum())))


def within_area_percentiles(values: np.ndarray, area: np.ndarray,
                            percentile: Callable[[np.ndarray], np.ndarray] = traffic.percentile) -> np.ndarray:
    """(n,) each of (n,) ``values``' percentile rank (0-100, ``100 (rank - 0.5) / count``, ties averaged) among the
    entries of its area (equal labels of (n,) ``area``), by ``percentile``: by default
    :func:`~g2s_plugins.traffic.percentile` (ties within rounding, the heat map's scale), so that on a graph of one
    area it is ``traffic.percentile(values)`` bit for bit. O(n log n), one sort per area."""
    order = np.argsort(area, kind="stable")
    percentiles = np.empty(len(values))
    for group in np.split(order, np.flatnonzero(np.diff(area[order])) + 1):
        percentiles[group] = percentile(values[group])
    return percentiles


def _exact_percentiles(values: np.ndarray) -> np.ndarray:
    """(n,) ``100 (rank - 0.5) / n`` of (n,) ``values``, only exactly equal values tied (:func:`spearman`'s ranks)."""
    return 100.0 * _weighted_midranks(values, np.ones(len(values))) / len(values)


def _pearson(x: np.ndarray, y: np.ndarray, weight: np.ndarray) -> float:
    """The weighted Pearson correlation of (n,) ``x`` and ``y`` (``numpy.cov`` with ``aweights``; NaN when either
    is constant)."""
    covariance = np.cov(x, y, aweights=weight)
    if not (covariance[0, 0] > 0 and covariance[1, 1] > 0):
        return float("nan")
    return float(covariance[0, 1] / math.sqrt(covariance[0, 0] * covariance[1, 1]))


def _weighted_midranks(values: np.ndarray, weight: np.ndarray) -> np.ndarray:
    distinct, inverse = np.unique(values, return_inverse=True)
    tied = np.bincount(inverse, weights=weight, minlength=len(distinct))
    return (np.cumsum(tied) - tied / 2)[inverse]


def evaluate(
    result: RunResult,
    reference: np.ndarray | None = None,
    radii: tuple[float, ...] = RADII,
    off_distance: float = 5.0,
    max_sources: int = REFERENCE_SOURCES,
    seed: int = 0,
) -> Quality:
    """The measures of a run that got to the analysis (see the module docs).

    Args:
        reference: :func:`reference_flow` of the same graph, when already known
            (it depends only on the graph, not on the preset).
        max_sources, seed: the reference flows' source sample (:func:`reference_flow`).
    """
    arrays = traffic.surface_arrays(result.graph)
    if reference is None:
        reference = reference_flow(result, max_sources, seed)
    area = traffic.origin_weight(arrays)
    if result.structure is None:  # no terminals: nothing was joined
        return Quality({r: 0.0 for r in radii}, 1.0, float("nan"), float("nan"), float("nan"), 0.0)
    joined = (structure_leaves.standing_for(result.forest, result.structure) if result.forest is not None
              else result.looped if result.looped is not None else result.steiner)
    distance, _ = traffic.distance_to(arrays, arrays.rows(sorted(joined)))
    within = {r: float(area[distance <= r].sum() / area.sum()) for r in radii}
    total_flow = reference.sum()
    off = float(reference[distance > off_distance].sum() / total_flow) if total_flow > 0 else 0.0
    nearest = nearest_structure_rows(result)
    first = next(iter(result.analysis.values()), None)
    heat = heat_map(result.graph, result.structure, first, nearest) if first is not None else None
    rho = spearman(heat, reference) if heat is not None else float("nan")
    areas = area_labels(result.graph)
    rho_within = within_area_rho(heat, reference, areas) if heat is not None else float("nan")
    ceiling_heat = placement_heat(result.graph, result.structure, reference, nearest)
    rho_area = float("nan")
    if heat is not None and np.isfinite(rho):
        ok = np.isfinite(heat)
        rho_area = weighted_spearman(heat[ok], reference[ok], area[ok])
    undirected = result.structure.to_undirected(as_view=True)
    weights = traffic.represented_area(result.graph, undirected)
    betweenness = centrality.betweenness(undirected, weighted=True, node_weight=weights)
    rho_navmesh = rho_navmesh_ceiling = left_out = float("nan")
    surface = navmesh_surface(result, reference, max_sources, seed)
    if surface is not None:
        positions = _positions(result.graph)

        def on_navmesh(values: np.ndarray) -> np.ndarray:
            return carry(values, arrays.area, positions, surface)

        if first is not None:
            rho_navmesh = spearman(on_navmesh(heat), surface.flow)
        ceiling = heat_map(result.graph, result.structure, _navmesh_ceiling(result, surface), nearest)
        rho_navmesh_ceiling = spearman(on_navmesh(ceiling), surface.flow)
        reached = on_navmesh(np.where(nearest >= 0, 1.0, np.nan))
        navmesh_area = traffic.surface_arrays(surface.graph).area
        left_out = float(navmesh_area[np.isnan(reached)].sum() / navmesh_area.sum())
    return Quality(
        area_within=within,
        traffic_off=off,
        rho=rho,
        rho_area=rho_area,
        rho_area_betweenness=spearman(heat_map(result.graph, result.structure, betweenness, nearest), reference),
        rho_ceiling=spearman(ceiling_heat, reference),
        rho_within=rho_within,
        rho_within_ceiling=within_area_rho(ceiling_heat, reference, areas),
        structure_share=result.structure.number_of_nodes() / arrays.n,
        rho_navmesh=rho_navmesh,
        rho_navmesh_ceiling=rho_navmesh_ceiling,
        navmesh_area_left_out=left_out,
    )
