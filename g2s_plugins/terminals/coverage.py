"""Coverage: leaves, then the farthest uncovered nodes, until every walkable node lies within ``radius`` of a terminal.

The paper's leaves reach every dead end, but a room with no degree-1 polygon
(a dead-end room split into polygons around a pillar, a ring corridor) gets
no terminal and no structure. This selector keeps the leaves and then covers
the rest greedily, farthest first (a farthest-point cover, as in Gonzalez's
k-center heuristic: T. F. Gonzalez, "Clustering to minimize the maximum
intercluster distance", Theoretical Computer Science 38:293-306, 1985):

1. distances from the leaves along the graph (one multi-source Dijkstra);
   an area without leaves is seeded with its node farthest from its
   lowest-id node;
2. while some node is farther than ``radius`` from the set, the farthest
   one and its shortest path back to the set join it (an incremental
   Steiner tree grown farthest first), and the distances are lowered by a
   Dijkstra from the new path that follows only the nodes it brings closer.

The nodes added in step 2 are terminals, so the Steiner structure contains
them all and every node of an area with terminals ends up within
``radius`` of the structure along the graph. They are *waypoints*:
simplification may drop them like any node on a path (the structure's
straight edges still pass there), so they do not bloat the final structure.
Areas (connected components) smaller than ``min_area`` are seeded at their
graph centre (:func:`area_centres`), not at their leaves, and covered like
any: a navmesh cuts a small area into few polygons, one of them often a
leaf, where a grid of samples almost never has one, so seeding leaves
covered a small area on one route and left it out on the other. Areas
smaller than ``place_area`` get no terminal and are named in a warning.

Default ``radius``: 12 agent radii (6 m for the default 0.5 m agent), but
no more than a tenth of the level's horizontal extent so that small levels
get more than one terminal. Measured on a 115-room generated dungeon
(docs/analysis_quality.md, ``map_analysis``): 4 m gives a structure of
58 % of the polygons, 6 m 48 % and 8 m 46 %, with 100 %, 100 % and 99.7 %
of the area within 6 m; the best agreement of a heat map on the structure
with walking flow (the ceiling) falls with the radius: 0.90, 0.84, 0.81.
Default ``min_area``: the area of a disc of half the ``radius`` (28 m² for
the default 6 m); on ``nav_test`` the areas between it and a whole disc of
``radius`` (113 m²) are an 88 m² walkway and a 53 m² platform, places
people stand on, which keep their leaves as dead ends (until 7 December
2026 the areas under it were left out unless they had a leaf:
docs/analysis_quality.md, "Islands"). Default ``place_area``: the smallest
part either graph builder keeps, 16 agent radii squared (4 m² for the
default agent). Measured in docs/analysis_quality.md ("Small areas on both
routes"): the areas under ``min_area`` on the generated levels are 4-28 m²
(crate, stall and container tops, boat decks, islets, channel beds cut off
under walkways) with no size that parts a crate top from a channel bed or
an islet, and the navmesh route alone has smaller ones, slivers of
0.1-3.9 m² (a theatre's seats no agent reaches).

Traffic-aware cover (``traffic_weight`` > 0). A cover by walking distance
alone places its nodes without regard to where traffic changes, and the
heat map gives every polygon the value of its nearest structure node: a
quiet side room within ``radius`` of a busy path takes the path's value
(on a 1k-polygon dungeon the polygons off the Steiner paths carried 58 %
of the heat map's rank error, docs/analysis_quality.md "Where the losses
are"). So the cover first runs on lengths that also count the change of
traffic along each edge::

    length(u, v) + traffic_weight * |p(u) - p(v)|

with p the percentile rank, 0-100, of each node's walking flow
(:func:`g2s_plugins.traffic.walking_flow` of ``traffic_sources``
area-sampled sources, seed 0, and ``traffic_ties``, by default the ``flow``
analyzer's defaults: the same array that analyzer computes with the same
settings, so a run with both computes it once) and ``traffic_weight`` in
metres per percentile point; its radius is ``traffic_radius``. Where
traffic steps from busy to quiet, distances grow and the cover puts a node
on the quiet side. Then the plain cover above runs from that set, so every
node still lies within ``radius`` metres of it along the graph.
``traffic_weight: 0`` (the default) is the plain cover alone, unchanged.
Default ``traffic_radius``: 5/3 of ``radius`` (10 m for 6 m): the weighted
lengths are longer than the walking ones, and a radius as small as the
plain cover's adds nodes everywhere traffic changes at all. Measured in
docs/analysis_quality.md ("Traffic-aware cover") on the 1k-polygon
dungeons (seeds 0 / 1 / 2): weight 0.1 m per point, traffic radius 10 m
and radius 6 m raise the heat map's rho from 0.881 / 0.877 / 0.871 to
0.931 / 0.918 / 0.908 with a structure of 53.9 / 47.3 / 47.3 % of the
polygons instead of 48.4 / 44.8 / 41.1 %; the plain cover needs a 4.5 m
radius for 0.920 / 0.900 / 0.907 with 55.8 / 49.9 / 49.4 %. nav_test:
0.956 -> 0.953, 55.3 -> 54.7 %.

Shallow leaves (``leaf_min_depth`` > 0). Recast's convex decomposition
(at most 6 vertices a polygon) leaves thin polygons along curved or angled
walls beside a big room polygon: leaves of the graph that are no dead-end
place. Only the leaves at least ``leaf_min_depth`` deep are seeded
(:func:`leaf_depths`: how far the polygon reaches beyond the edge it
shares); the others are covered within ``radius`` like any node. Measured
in docs/analysis_quality.md ("Slivers and places: leaf depth"): 1 m, the
default agent's diameter, keeps the leaf of 29 of 30 generated dead-end
rooms and drops about half of the leaves of a dungeon turned by 30 degrees,
but lowers rho on a 1k dungeon from 0.929 to 0.898, so no preset sets it;
``0`` (the default) seeds every leaf, unchanged.

Dead-end places (``dead_end_radii`` > 0). A dead end reached through one
way may hold several leaves: the rim of a round tank roof at the top of its
stair is cut into 4-6 degree-1 polygons, a dead-end landing into two, where a
designer marks one dead end. A *dead-end piece* is what hangs beyond a bridge
of the graph (an edge whose removal parts it; the side away from the block,
2-edge-connected component, of most area); when every node of the piece lies
within ``dead_end_radii`` cover radii of its entrance (the bridge's end on
its side), along the graph, the leaves of the largest such piece are one
place and only the farthest from its entrance is seeded (ties: lowest row);
the cover still reaches the others within ``radius``. Measured in
docs/analysis_quality.md ("Terminals and chokepoints a designer marks").
``0`` (the default) seeds every leaf, unchanged.

Recesses (``recess_depth`` > 0). A leaf whose dead end (it and the chain
of degree-2 nodes behind it) lies within ``recess_depth`` metres of its way
in is a recess: the bay between two pillars of a terrace's pillar row, the
strip between two bollards and a quay's edge. Recesses whose entrances lie
within ``radius`` of one another along the graph, chained, are a row, and
a row of at least ``recess_row`` seeds one leaf (:func:`recess_rows`),
before ``dead_end_radii``; the cover reaches the rest. Measured in
docs/analysis_quality.md ("Terminals in shallow recesses"): 2 m takes 3.3-
7.6 points off the stepwells' structure, but their bays are a quarter of
their polygons and rho falls to 0.898-0.907 (0.889 on a market), so no
preset sets it; ``0`` (the default) seeds every leaf, unchanged.

Quiet dead ends (``quiet_step`` > 0). A seeded leaf gives its dead end
(it and the chain of degree-2 nodes behind it) a heat of its own: the
mean walking-flow percentile of its nodes. Where the node it opens onto
(its entrance, of degree 3 or more) is about as quiet, that heat is
nearly what the entrance's node gives it anyway, and the leaf's spur buys
no rank: the bay between two deck chairs off a quiet stretch of
promenade, a dent off a back alley. After the cover, a leaf whose dead
end is less than ``quiet_step`` points quieter than its entrance, whose
entrance the cover holds and whose dead end lies within ``radius`` of
that entrance along the graph, is no terminal (:func:`quiet_dead_ends`):
every way from the dead end passes the entrance, so the radius guarantee
holds without it and no new path is needed. Leaves of areas too small to
cover stay. Measured in docs/analysis_quality.md ("Dents along lined
edges"). ``0`` (the default) keeps every leaf, unchanged.

Dents within a rank budget (``dent_depth`` > 0 and ``dent_rho_budget`` > 0).
A dent is a seeded leaf whose dead end (it and the chain of degree-2 nodes
behind it) lies within ``dent_depth`` metres of its way in
(:func:`dead_end_depths`): the bay between two bollards along a towpath, a
corner of a parterre's bed, a bay behind a pillar. Its leaf costs a node of
structure, and what it buys is rank: without it the dead end takes the heat
of a node on the walkway it opens onto, up to 60-70 percentile points too
high for a dent nobody walks through. Spearman's rho over n polygons is
1 - 6 sum(d²) / (n (n² - 1)) for rank differences d (C. Spearman, "The
proof and measurement of association between two things", American Journal
of Psychology 15:72-101, 1904), so a dead end whose nodes' percentiles p_i
(0-100) take the percentile p_s of the terminal nearest its entrance
instead (and so do the nodes of the path between them, which the leaf's
spur brings in) adds about 6 sum((p_s - p_i) / 100)² / n to the loss of
rho. After the cover (and ``quiet_step``), the dents the cover holds within
``radius`` without them (:func:`dent_costs`) are dropped cheapest first
(ties: lowest row) while their summed estimated loss stays within
``dent_rho_budget``
(:func:`dents_within_budget`); as with ``quiet_step`` no path is needed.
Measured in docs/analysis_quality.md ("Dents between posts and corners").
``0`` (the default) keeps every dent, unchanged.

Complexity: O(m + n log n) for step 1 plus, per added path, a Dijkstra over
the nodes that path brings closer (in practice the area around it); with
``traffic_weight`` > 0, that twice, plus the walking flow, O(k (m + n log n))
for k = 256 sources, unless the run's ``flow`` analyzer already needs it;
with ``recess_depth`` > 0, one more multi-source Dijkstra, limited to
``radius``; with ``quiet_step`` > 0, the walking flow (once, as above)
and a walk up each leaf's chain; with ``dent_rho_budget`` > 0, those, two
multi-source Dijkstras and a sort of the k dents, O(k c nvp + m + n log n +
k log k).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from pydantic import Field, model_validator
from pydantic_core import PydanticCustomError

from g2s_core.lazy import lazy_module
from g2s_core.model import NavMesh, RunContext, Terminals
from g2s_core.plugin import PluginParams, hookimpl
from g2s_plugins import _trees, traffic

rx = lazy_module("rustworkx")
sp, csgraph = lazy_module("scipy.sparse"), lazy_module("scipy.sparse.csgraph")
nx = lazy_module("networkx")

NAME = "coverage"

AGENT_RADII = 12.0
"""Default cover radius in agent radii."""

EXTENT_SHARE = 0.1
"""Default cover radius at most this share of the level's horizontal extent."""

TRAFFIC_RADIUS_SHARE = 10.0 / 6.0
"""Default ``traffic_radius`` as a multiple of ``radius``."""

PART_AGENT_RADII_SQUARED = 16.0
"""Default ``place_area`` in agent radii squared (4 m² for the default 0.5 m agent): the smallest walkable part
either graph builder keeps, Recast's ``region_min_size`` of 8 cells of half an agent radius squared and the sampling
builder's ``min_region_area``. Smaller areas were found on the navmesh route alone (docs/analysis_quality.md,
"Small areas on both routes")."""

CENTRE_ROWS = 1024
"""Sources of one Dijkstra call when a small area's centre is sought (:func:`area_centres`): at most this many rows
of distances, 8 MB for an area of 1,000 nodes, whatever ``min_area`` a user sets."""

CENTRE_EXACT_NODES = 4096
"""Largest area whose centre :func:`area_centres` finds exactly, a Dijkstra from each of its nodes; past it (an area
that large is under ``min_area`` only when a user sets it far over its default) the cost would grow with the square
of the area, so the centre is taken against :data:`CENTRE_LANDMARKS` far-apart nodes instead."""

CENTRE_LANDMARKS = 8
"""Far-apart nodes (farthest-point order) whose distances stand for each node's farthest in a large area."""


class Params(PluginParams):
    """Cover radius, the smallest area that is forced in, and the traffic-aware cover before the plain one."""

    radius: float | None = Field(None, gt=0, description="every walkable node within this many metres (along the graph) of a terminal; default 12 agent radii, at most 1/10 of the level's extent")
    min_area: float | None = Field(None, ge=0, description="walkable areas smaller than this (m²) are seeded at their graph centre, not at their leaves, then covered as any; default pi (radius / 2)²")
    place_area: float | None = Field(None, ge=0, description="walkable areas smaller than this (m²) get no terminal and are named in a warning; default 16 agent.radius², the smallest part the graph builders keep")
    traffic_weight: float = Field(0.0, ge=0, description="metres added to each edge per percentile point of walking-flow difference between its ends, for a first cover that puts nodes where traffic changes; 0: the plain cover only")
    traffic_radius: float | None = Field(None, gt=0, description="radius of that traffic-aware cover, in metres of those lengths; default 5/3 radius (10 m for 6 m)")
    traffic_sources: int = Field(traffic.WALKING_SOURCES, ge=1, description="sources of the walking flow that cover reads: set as the flow analyzer's max_sources")
    traffic_ties: traffic.Ties = Field(traffic.WALKING_TIES, description="equally short paths in that walking flow (first or split): set as the flow analyzer's ties")
    dead_end_radii: float = Field(0.0, ge=0, description="leaves of one dead end (all that hangs beyond one bridge of the graph) reaching no farther than this many cover radii from its entrance are one place: only the farthest is seeded, the cover reaches the rest; 0: every leaf")
    traffic_scaling: traffic.Scaling = Field(traffic.WALKING_SCALING, description="that walking flow's sampled pairs (none or linear): set as the flow analyzer's scaling")
    leaf_min_depth: float = Field(0.0, ge=0, description="leaves of the navmesh graph less deep than this (m: how far their polygon reaches beyond the edge it shares) are not seeded as terminals, the cover still reaches them; 0: every leaf; leaves without a polygon (the sampling route) always count")
    recess_depth: float = Field(0.0, ge=0, description="a leaf whose dead end (it and the chain of degree-2 nodes behind it) lies within this many metres of its way in is a recess; recesses whose ways in lie within the cover radius of one another along the graph are a row, and a row of at least recess_row seeds one of them, the cover reaches the rest; 0: every leaf; leaves without a polygon (the sampling route) are no recess")
    recess_row: int = Field(3, ge=2, description="the fewest recesses that are a row (recess_depth)")
    quiet_step: float = Field(0.0, ge=0, description="a leaf whose dead end (it and the chain of degree-2 nodes behind it) is less than this many walking-flow percentile points quieter than the node it opens onto, which the cover holds within the cover radius, is no terminal; 0: every leaf")
    dent_depth: float = Field(0.0, ge=0, description="a leaf whose dead end (it and the chain of degree-2 nodes behind it) lies within this many metres of its way in is a dent, which dent_rho_budget may drop; 0: no dents; leaves without a polygon (the sampling route) are no dent")
    dent_rho_budget: float = Field(0.0, ge=0, le=1, description="dents the cover holds within the cover radius without them are no terminal, least first by the Spearman rho their heat map would lose taking the walking-flow percentile of the terminal nearest their way in, while that estimated loss summed stays within this; 0: every dent")

    @model_validator(mode="before")
    @classmethod
    def _play_points_moved(cls, data: object) -> object:
        # A parameter of this selector until 5 December 2026: the play space is now cut where the graph is built
        if isinstance(data, dict) and "play_points" in data:
            raise PydanticCustomError("moved", "play_points is a parameter of the graph builder now: set graph.params.play_points")
        return data


def default_radius(context: RunContext) -> float:
    """The default cover radius for the agent and level of ``context``, metres."""
    extent = np.ptp(np.asarray(context.mesh.bounds, dtype=np.float64)[:, [0, 2]], axis=0)
    return float(min(AGENT_RADII * context.agent.radius, EXTENT_SHARE * float(np.hypot(*extent)) or math.inf))


@dataclass(frozen=True)
class Cover:
    """The rows (of ``arrays``, :func:`g2s_plugins.traffic.surface_arrays`) each step of the cover chose.

    ``leaves``: the seeded leaves, sorted; ``traffic``: the rows the
    traffic-aware cover holds (the seeds included; equal to the seeds
    without ``traffic_weight``); ``rows``: all the terminals, sorted. The
    waypoints are ``rows`` less ``leaves``.
    """

    arrays: traffic.SurfaceArrays
    leaves: np.ndarray
    traffic: np.ndarray
    rows: np.ndarray


@hookimpl
def g2s_select_terminals(graph: nx.Graph, params: Params, context: RunContext) -> Terminals:
    """Leaves plus the farthest-first cover paths, by ascending id."""
    chosen = cover(graph, params, context)
    nodes = chosen.arrays.nodes
    waypoints = np.setdiff1d(chosen.rows, chosen.leaves)
    return Terminals(
        nodes=tuple(sorted(nodes[i] for i in chosen.rows.tolist())),
        waypoints=tuple(sorted(nodes[i] for i in waypoints.tolist())),
    )


def cover(graph: nx.Graph, params: Params, context: RunContext) -> Cover:
    """The seeded leaves, the traffic-aware cover and the plain cover of ``graph`` (see the module docs)."""
    radius = params.radius if params.radius is not None else default_radius(context)
    min_area = params.min_area if params.min_area is not None else math.pi * (radius / 2) * (radius / 2)  # ** overflows
    place_area = params.place_area if params.place_area is not None else smallest_part(context)
    arrays = traffic.surface_arrays(graph)
    drops_dents = params.dent_depth > 0 and params.dent_rho_budget > 0
    reads_traffic = params.traffic_weight > 0 or params.quiet_step > 0 or drops_dents
    if reads_traffic:  # its trees on a thread of their own while the leaves and dead ends are found here
        traffic.start_walking_flow(arrays, max_sources=params.traffic_sources, ties=params.traffic_ties,
                                   scaling=params.traffic_scaling)
    adjacency = arrays.adjacency
    degree = np.diff(adjacency.indptr)
    count, labels = csgraph.connected_components(adjacency, directed=False)
    component_area = np.bincount(labels, weights=arrays.area, minlength=count)
    left_out = component_area < place_area
    small = left_out | (component_area < min_area)
    # a small area is seeded at its centre whatever its tessellation: its leaves (which a navmesh of few polygons
    # has and a grid of samples almost never) do not count
    leaves = np.flatnonzero((degree == 1) & ~small[labels])
    if params.leaf_min_depth > 0:
        depths = leaf_depths(graph, context.navmesh, [arrays.nodes[i] for i in leaves.tolist()])
        leaves = leaves[depths >= params.leaf_min_depth]
    if params.recess_depth > 0:
        leaves = recess_rows(graph, context.navmesh, arrays, leaves, params.recess_depth, radius, params.recess_row)
    if params.dead_end_radii > 0:
        leaves = dead_end_places(adjacency, arrays.area, leaves, params.dead_end_radii * radius)
    has_leaf = np.zeros(count, dtype=bool)
    has_leaf[labels[leaves]] = True
    if left_out.any():
        context.warn(
            f"coverage: {int(left_out.sum())} walkable area(s) smaller than {place_area:.3g} m² "
            f"({component_area[left_out].sum():.3g} m² in all) are not covered: smaller than a part the graph builders "
            f"keep (place_area), too small to be a place"
        )
    places = small & ~left_out
    seeds = np.concatenate([leaves, _seeds(adjacency, labels, has_leaf, small), area_centres(adjacency, labels, places)])
    eligible = ~left_out[labels]
    if reads_traffic:
        rank = walking_percentile(arrays, params.traffic_sources, params.traffic_ties, params.traffic_scaling)
    if params.traffic_weight > 0:
        traffic_radius = params.traffic_radius if params.traffic_radius is not None else TRAFFIC_RADIUS_SHARE * radius
        # the plain cover below grows from this one, so its radius guarantee holds whatever this one chose
        lengths = traffic_lengths(arrays, rank, params.traffic_weight)
        seeds = cover_paths(lengths, seeds, eligible, traffic_radius)
    rows = np.union1d(leaves, cover_paths(adjacency, seeds, eligible, radius))
    if params.quiet_step > 0:
        quiet = quiet_dead_ends(arrays, leaves, rank, params.quiet_step, rows, radius)
        leaves, seeds, rows = (np.setdiff1d(rows_, quiet) for rows_ in (leaves, seeds, rows))
    if drops_dents:
        dents = dents_within_budget(graph, context.navmesh, arrays, leaves, rank,
                                    params.dent_depth, rows, radius, params.dent_rho_budget)
        leaves, seeds, rows = (np.setdiff1d(rows_, dents) for rows_ in (leaves, seeds, rows))
    return Cover(arrays, np.sort(leaves), np.unique(seeds), rows)


def dead_end_places(adjacency: sp.csr_array, area: np.ndarray, leaves: np.ndarray, reach: float) -> np.ndarray:
    """The ``leaves`` (rows) left when those of one dead-end place are one: the sorted rows kept.

    ``adjacency``: (n, n) edge lengths, m; ``area``: (n,) m². The graph's
    bridges (``rustworkx.bridges``) cut it into blocks (2-edge-connected
    components) joined in a tree; each connected area's tree is rooted at its
    block of most area (ties: lowest label). A block and all below it are a
    dead-end piece entered at its bridge's end on its side; distances from
    the root blocks (one multi-source Dijkstra) less the entrance's are the
    distances within the piece, since every way in passes the entrance. Each
    leaf belongs to the largest piece round it whose farthest node lies
    within ``reach`` metres of its entrance; of the leaves of one such piece
    the farthest from the roots stays. O(m + n log n).
    """
    if len(leaves) < 2:  # nothing to merge
        return np.sort(leaves)
    n = adjacency.shape[0]
    upper = sp.triu(adjacency, k=1).tocoo()
    graph = rx.PyGraph(multigraph=False)
    graph.add_nodes_from(range(n))
    graph.add_edges_from_no_data(list(zip(upper.row.tolist(), upper.col.tolist(), strict=True)))
    bridges = np.sort(np.array(list(rx.bridges(graph)), dtype=np.int64).reshape(-1, 2), axis=1)
    bridges = bridges[np.lexsort(bridges.T[::-1])]  # by lower end, then higher
    is_bridge = np.zeros(upper.nnz, dtype=bool)
    if len(bridges):
        keys = upper.row.astype(np.int64) * n + upper.col
        is_bridge = np.isin(keys, bridges[:, 0] * n + bridges[:, 1])
    inside = sp.csr_array((np.ones(int((~is_bridge).sum())), (upper.row[~is_bridge], upper.col[~is_bridge])), shape=(n, n))
    blocks, block = csgraph.connected_components(inside, directed=False)
    block_area = np.bincount(block, weights=area, minlength=blocks)
    ends = block[bridges]  # (b, 2) the blocks each bridge joins
    # the tree of blocks plus one extra node joined to the root block of every connected area
    _, tree = csgraph.connected_components(
        sp.csr_array((np.ones(len(ends)), (ends[:, 0], ends[:, 1])), shape=(blocks, blocks)), directed=False)
    order = np.lexsort((np.arange(blocks), -block_area, tree))
    roots = order[np.unique(tree[order], return_index=True)[1]]
    hub = np.full(len(roots), blocks)
    links = np.concatenate([ends, np.column_stack([hub, roots])])
    forest = sp.csr_array((np.ones(len(links)), (links[:, 0], links[:, 1])), shape=(blocks + 1, blocks + 1))
    visit, parent = csgraph.breadth_first_order(forest, blocks, directed=False, return_predecessors=True)
    visit = visit[1:]  # the hub first
    entrance = np.full(blocks, -1, dtype=np.int64)
    below = parent[ends[:, 0]] == ends[:, 1]  # the bridge's first block hangs under its second
    entrance[np.where(below, ends[:, 0], ends[:, 1])] = np.where(below, bridges[:, 0], bridges[:, 1])
    distance = csgraph.dijkstra(adjacency, directed=False, indices=np.flatnonzero(np.isin(block, roots)), min_only=True)
    farthest = np.full(blocks, -np.inf)
    np.maximum.at(farthest, block, distance)
    # the two walks over the blocks on Python lists: a numpy scalar read per step cost 4 times as long
    order, parents, farthest = visit.tolist(), parent.tolist(), farthest.tolist()
    for b in reversed(order):  # children before parents
        if (up := parents[b]) < blocks and farthest[b] > farthest[up]:
            farthest[up] = farthest[b]
    within_reach = ((entrance >= 0) & (np.array(farthest) - distance[np.maximum(entrance, 0)] <= reach)).tolist()
    place = [-1] * blocks
    for b in order:  # parents before children: a piece inside a piece within reach takes its place
        up = parents[b]
        place[b] = place[up] if up < blocks and place[up] >= 0 else (b if within_reach[b] else -1)
    owner = np.array(place, dtype=np.int64)[block[leaves]]
    alone = leaves[owner < 0]
    grouped = leaves[owner >= 0]
    by_place = np.lexsort((grouped, -distance[grouped], owner[owner >= 0]))
    firsts = np.unique(owner[owner >= 0][by_place], return_index=True)[1]
    return np.sort(np.concatenate([alone, grouped[by_place][firsts]]))


def quiet_dead_ends(arrays: traffic.SurfaceArrays, leaves: np.ndarray, rank: np.ndarray, step: float,
                    cover: np.ndarray, reach: float) -> np.ndarray:
    """The ``leaves`` (rows of ``arrays``) the ``cover`` (rows) holds without them: the sorted rows of those whose dead
    end is less than ``step`` percentile points quieter than the node it opens onto, which ``cover`` holds, and
    lies within ``reach`` metres of it.

    ``rank``: (n,) walking-flow percentiles, 0-100 (:func:`walking_percentile`).
    A leaf's dead end is it and the chain of degree-2 nodes behind it
    (:func:`dead_end_chain`), opening onto a node of degree 3 or more, its
    entrance. Seeded, the leaf gives the dead end a heat of its own, the
    mean percentile of its nodes (the ``flow`` analyzer's ``aggregate:
    percentile``); left out, the dead end takes the value of the structure
    node at its entrance: the same within ``step`` points. Every way from
    the leaf to the rest of the graph passes the entrance, so with the
    entrance in the cover and the dead end within ``reach`` (the cover
    radius) of it, every node lies as close to the cover without the leaf
    as the radius asks: no new path is needed. A leaf whose area is one
    chain (its chain ends at another leaf) stays. O(k c) for k leaves with
    chains of c nodes.
    """
    degree = np.diff(arrays.adjacency.indptr)
    held = np.zeros(arrays.n, dtype=bool)
    held[cover] = True
    quiet = []
    for leaf in np.sort(leaves).tolist():
        chain, entrance = dead_end_chain(arrays.adjacency, leaf)
        if (entrance >= 0 and degree[entrance] >= 3 and held[entrance] and rank[entrance] - rank[chain].mean() < step
                and arrays.adjacency[chain, chain[1:] + [entrance]].sum() <= reach):
            quiet.append(leaf)
    return np.asarray(quiet, dtype=np.int64)


def dents_within_budget(graph: nx.Graph, navmesh: NavMesh | None, arrays: traffic.SurfaceArrays, leaves: np.ndarray,
                        rank: np.ndarray, depth: float, cover: np.ndarray, reach: float, budget: float) -> np.ndarray:
    """The dents among ``leaves`` (rows of ``arrays``) the ``cover`` (rows) holds without them, within a rank
    ``budget``: the sorted rows of those dropped.

    The dents and their costs are :func:`dent_costs`'; they go in ascending
    order of cost (ties: lowest row) while the costs summed stay within
    ``budget`` (an estimated loss of Spearman rho). O(k c nvp + m + n log n +
    k log k) for k leaves with chains of c nodes.
    """
    dents, costs = dent_costs(graph, navmesh, arrays, leaves, rank, depth, cover, reach)
    order = np.lexsort((dents, costs))
    return np.sort(dents[order][np.cumsum(costs[order]) <= budget])


def dent_costs(graph: nx.Graph, navmesh: NavMesh | None, arrays: traffic.SurfaceArrays, leaves: np.ndarray,
               rank: np.ndarray, depth: float, cover: np.ndarray, reach: float) -> tuple[np.ndarray, np.ndarray]:
    """(k,) the sorted rows of the dents among ``leaves`` (rows of ``arrays``) that the ``cover`` (rows) holds
    without them, and (k,) the Spearman rho each would cost the heat map.

    ``rank``: (n,) walking-flow percentiles, 0-100 (:func:`walking_percentile`).
    A leaf is a dent when its dead end lies within ``depth`` metres of its
    way in (:func:`dead_end_depths`) and opens onto a node of degree 3 or
    more, its entrance. The cover holds a dent without it when every node
    whose nearest row of ``cover`` is the dent's leaf (its cell) lies within
    ``reach`` metres of the cover less every dent: then whichever dents go,
    a node of a dropped one's cell is still within ``reach``, and every other
    node keeps its nearest row. Left out, the dead end's nodes (the leaf and
    its chain), and the nodes of the shortest path from its entrance to the
    nearest row of the cover less every dent (the spur the leaf brings into
    the structure; none where the cover holds the entrance), take the
    percentile p_s of that row instead of their own p_i: with Spearman's
    rho = 1 - 6 sum(d²) / (n (n² - 1)) and rank differences
    d = n (p_s - p_i) / 100, the cost is about 6 sum(((p_s - p_i) / 100)²) / n.
    Without ``navmesh`` there are no dents. O(k (c nvp + l) + m + n log n)
    for k leaves with chains of c nodes and paths of l: two multi-source
    Dijkstras.
    """
    leaves = np.sort(leaves)
    none = np.zeros(0, dtype=np.int64), np.zeros(0)
    if navmesh is None or len(leaves) == 0:
        return none
    depths, entrances = dead_end_depths(graph, navmesh, arrays, leaves)
    degree = np.diff(arrays.adjacency.indptr)
    shallow = (depths <= depth) & (entrances >= 0)
    shallow[shallow] = degree[entrances[shallow]] >= 3
    candidates, entrances = leaves[shallow], entrances[shallow]
    rest = np.setdiff1d(cover, candidates)
    if len(candidates) == 0 or len(rest) == 0:
        return none
    _, _, nearest = csgraph.dijkstra(arrays.adjacency, directed=False, indices=cover, min_only=True,
                                     return_predecessors=True)
    to_rest, toward_rest, _ = csgraph.dijkstra(arrays.adjacency, directed=False, indices=rest, min_only=True,
                                               return_predecessors=True)
    farthest = np.full(arrays.n, -np.inf)  # per cover row: its cell's farthest node from the cover less the dents
    reached = nearest >= 0
    np.maximum.at(farthest, nearest[reached], to_rest[reached])
    dents, costs = [], []
    for leaf, entrance in zip(candidates.tolist(), entrances.tolist(), strict=True):
        if farthest[leaf] <= reach:
            chain, _ = dead_end_chain(arrays.adjacency, leaf)
            row = entrance
            while toward_rest[row] >= 0:  # up to the nearest row of the cover less the dents
                chain.append(row)
                row = int(toward_rest[row])
            dents.append(leaf)
            costs.append(6.0 * float(np.sum(((rank[row] - rank[chain]) / 100.0) ** 2)) / arrays.n)
    return np.asarray(dents, dtype=np.int64), np.asarray(costs, dtype=np.float64)


def recess_rows(graph: nx.Graph, navmesh: NavMesh | None, arrays: traffic.SurfaceArrays, leaves: np.ndarray,
                depth: float, reach: float, row: int) -> np.ndarray:
    """The ``leaves`` (rows of ``arrays``) left when each row of recesses seeds one: the sorted rows kept.

    A leaf is a recess when its dead end lies within ``depth`` metres of its
    way in (:func:`dead_end_depths`): a bay between pillars or bollards, not a
    room entered through it. Recesses whose entrances lie within ``reach``
    metres of one another along the graph, chained, are a row
    (:func:`recess_row_labels`); a row of at least ``row`` recesses keeps
    only its leaf of lowest row. Without ``navmesh`` there are no recesses.
    O(k c + m + n log n) for k leaves with chains of c nodes.
    """
    leaves = np.sort(leaves)
    if navmesh is None or len(leaves) < row:
        return leaves
    depths, entrances = dead_end_depths(graph, navmesh, arrays, leaves)
    shallow = depths <= depth
    recesses = leaves[shallow]
    if len(recesses) < row:
        return leaves
    labels = recess_row_labels(arrays.adjacency, entrances[shallow], reach)
    in_row = np.bincount(labels)[labels] >= row
    firsts = np.unique(labels[in_row], return_index=True)[1]  # each row's recess of lowest row
    return np.setdiff1d(leaves, np.setdiff1d(recesses[in_row], recesses[in_row][firsts]))


def dead_end_depths(graph: nx.Graph, navmesh: NavMesh, arrays: traffic.SurfaceArrays,
                    leaves: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(k,) how far each of the ``leaves`` (rows of ``arrays``)' dead end reaches beyond its way in, m, and (k,) the
    row of its entrance.

    A leaf's dead end is the leaf and the chain of degree-2 nodes behind it;
    its way in is the edge from that chain to the first node of degree 3 or
    more, the entrance. The depth is the largest plan (x-z) distance from a
    vertex of the dead end's navmesh polygons to that edge's ``portal``
    segment: the polygons are convex, so no point of the dead end lies
    farther. ``inf`` (entrance -1) where it is unknown: an area that is one
    chain, a way in without a portal, a dead end without polygons (the
    sampling route). O(k c nvp) for chains of c nodes.
    """
    depths, entrances = np.full(len(leaves), np.inf), np.full(len(leaves), -1, dtype=np.int64)
    known, corners, portals = [], [], []
    for k, leaf in enumerate(leaves.tolist()):
        chain, entrance = dead_end_chain(arrays.adjacency, leaf)
        if entrance < 0:
            continue
        portal = graph.edges[arrays.nodes[chain[-1]], arrays.nodes[entrance]].get("portal")
        polygons = [graph.nodes[arrays.nodes[i]].get("polygon", -1) for i in chain]
        vertices = [navmesh.polygons[p][navmesh.polygons[p] >= 0] for p in polygons if p >= 0]
        if portal is None or not vertices:
            continue
        known.append(k)
        corners.append(np.concatenate(vertices))
        portals.append(np.asarray(portal, dtype=np.float64)[:, [0, 2]])
        entrances[k] = entrance
    if known:
        # every dead end's corners against its own portal at once: a call per leaf was most of the cover's time
        counts = np.array([len(c) for c in corners])
        segment = np.repeat(np.stack(portals), counts, axis=0)
        offset = navmesh.vertices[np.concatenate(corners)][:, [0, 2]] - segment[:, 0]
        span = segment[:, 1] - segment[:, 0]
        with np.errstate(invalid="ignore", divide="ignore"):
            t = np.clip(np.nan_to_num(np.einsum("pj,pj->p", offset, span) / np.einsum("pj,pj->p", span, span)), 0.0, 1.0)
        distances = np.linalg.norm(offset - t[:, None] * span, axis=1)
        depths[known] = np.maximum.reduceat(distances, np.concatenate([[0], np.cumsum(counts)[:-1]]))
    return depths, entrances


def dead_end_chain(adjacency: sp.csr_array, leaf: int) -> tuple[list[int], int]:
    """The dead end of ``leaf`` (a row of the (n, n) edge lengths ``adjacency`` with one neighbour): the leaf and the
    chain of degree-2 rows behind it, in order, and the row it opens onto (its first node of degree 3 or more; -1
    when the whole area is one chain). O(c) for a chain of c nodes."""
    indptr = adjacency.indptr
    chain, previous, current = [leaf], -1, leaf
    while True:
        ahead = [j for j in adjacency.indices[indptr[current]:indptr[current + 1]].tolist() if j != previous]
        if len(ahead) != 1:
            return chain, -1
        if indptr[ahead[0] + 1] - indptr[ahead[0]] != 2:
            return chain, ahead[0]
        previous, current = current, ahead[0]
        chain.append(current)


def recess_row_labels(adjacency: sp.csr_array, entrances: np.ndarray, reach: float) -> np.ndarray:
    """(k,) a label per entrance (rows of the (n, n) edge lengths ``adjacency``), one per row: entrances within
    ``reach`` metres of one another along the graph, chained (single linkage), share it.

    One multi-source Dijkstra from the entrances, limited to ``reach``: two
    entrances within ``reach`` are joined through the regions of nearest
    entrance that their shortest path crosses, each crossing edge (u, v)
    giving d(u) + length + d(v) <= ``reach`` (the lemma behind Mehlhorn's
    Steiner tree: K. Mehlhorn, "A faster approximation algorithm for the
    Steiner problem in graphs", Information Processing Letters 27:125-128,
    1988), so the rows are exact. O(m + n log n).
    """
    sources = np.unique(entrances)
    distance, _, nearest = csgraph.dijkstra(adjacency, directed=False, indices=sources, min_only=True,
                                            return_predecessors=True, limit=reach)
    upper = sp.triu(adjacency, k=1).tocoo()
    ends = np.column_stack([nearest[upper.row], nearest[upper.col]])
    linked = (ends[:, 0] != ends[:, 1]) & (ends >= 0).all(axis=1) & (
        distance[upper.row] + upper.data + distance[upper.col] <= reach)
    pairs = np.searchsorted(sources, ends[linked])
    _, label = csgraph.connected_components(
        sp.csr_array((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(len(sources), len(sources))),
        directed=False)
    return label[np.searchsorted(sources, entrances)]


def leaf_depths(graph: nx.Graph, navmesh: NavMesh | None, leaves: list) -> np.ndarray:
    """(k,) how far a walker can go into each of the ``leaves`` (degree-1 nodes) beyond the edge it shares, m.

    A leaf's depth is the largest horizontal (x-z) distance from a vertex of
    its navmesh polygon to the nearest segment it shares with its one
    neighbouring polygon: the polygon is convex, so that is the farthest any
    point of it lies from the way in. The shared segments are the ``portal``
    of the leaf's graph edge (Detour's shared part, exact across a tile
    border, where the edge may touch the next tile's polygon over only part
    of its length; on a crest the edge to the portal node carries the pair's
    segment) and every other edge of the polygon that the neighbour holds
    whole (both vertices its own: two polygons of one tile can share more
    than one edge, and ``portal`` lists the first). A leaf with no polygon
    (``polygon`` -1 or absent: a sample of the sampling route, whose graph
    has no polygons, or a graph built without ``navmesh``) gets ``inf``: its
    depth is unknown, so it counts as deep. O(k nvp²).
    """
    depths = np.full(len(leaves), np.inf)
    if navmesh is None:
        return depths
    for k, leaf in enumerate(leaves):
        polygon = graph.nodes[leaf].get("polygon", -1)
        if polygon < 0:
            continue
        corners = navmesh.polygons[polygon]
        corners = corners[corners >= 0]
        following = np.roll(corners, -1)
        across = navmesh.neighbours[polygon][: len(corners)]
        whole = [j for j in np.flatnonzero(across >= 0).tolist()
                 if np.isin([corners[j], following[j]], navmesh.polygons[across[j]]).all()]
        plan = navmesh.vertices[:, [0, 2]]
        starts, ends = [plan[corners[whole]]], [plan[following[whole]]]
        (neighbour,) = graph[leaf]
        portal = graph.edges[leaf, neighbour].get("portal")
        if portal is not None:
            starts.append(np.asarray(portal[0], dtype=np.float64)[None, [0, 2]])
            ends.append(np.asarray(portal[1], dtype=np.float64)[None, [0, 2]])
        start, end = np.concatenate(starts), np.concatenate(ends)
        if len(start):
            depths[k] = _plan_distances(plan[corners], start, end).min(axis=1).max()
    return depths


def _plan_distances(points: np.ndarray, start: np.ndarray, end: np.ndarray) -> np.ndarray:
    """(p, s) distance from each of the (p,2) ``points`` to each segment ``start[j] -> end[j]`` ((s,2) each)."""
    span = end - start
    length2 = np.einsum("ij,ij->i", span, span)
    offset = points[:, None, :] - start[None, :, :]
    with np.errstate(invalid="ignore", divide="ignore"):
        t = np.clip(np.nan_to_num(np.einsum("psj,sj->ps", offset, span) / length2), 0.0, 1.0)
    return np.linalg.norm(offset - t[..., None] * span[None, :, :], axis=2)


def walking_percentile(arrays: traffic.SurfaceArrays, sources: int = traffic.WALKING_SOURCES,
                       ties: traffic.Ties = traffic.WALKING_TIES,
                       scaling: traffic.Scaling = traffic.WALKING_SCALING) -> np.ndarray:
    """(n,) the percentile, 0-100, of each row's walking flow (``sources`` sampled sources, ``ties``,
    ``scaling``): what the traffic-aware cover reads."""
    return traffic.percentile(traffic.arrays_walking_flow(arrays, max_sources=sources, ties=ties, scaling=scaling))


def traffic_lengths(arrays: traffic.SurfaceArrays, rank: np.ndarray, weight: float) -> sp.csr_array:
    """(n, n) edge lengths of a graph's ``arrays`` plus ``weight`` x the difference of the walking-flow
    percentiles ``rank`` ((n,), 0-100: :func:`walking_percentile`) of each edge's ends.

    Rows as in ``arrays`` (:func:`g2s_plugins.traffic.surface_arrays`);
    ``weight`` in metres per percentile point (0-100). O(m).
    """
    adjacency = arrays.adjacency
    rows = np.repeat(np.arange(arrays.n), np.diff(adjacency.indptr))
    lengths = adjacency.data + weight * np.abs(rank[rows] - rank[adjacency.indices])
    return sp.csr_array((lengths, adjacency.indices, adjacency.indptr), shape=adjacency.shape)


def _seeds(adjacency, labels: np.ndarray, has_leaf: np.ndarray, small: np.ndarray) -> np.ndarray:
    """One node per big enough area without leaves (``has_leaf``, ``small``: (areas,) bool): the farthest from its
    lowest-id node."""
    firsts = np.unique(labels, return_index=True)[1]
    lonely = firsts[~has_leaf & ~small]
    if lonely.size == 0:
        return np.zeros(0, dtype=np.int64)
    distance = csgraph.dijkstra(adjacency, directed=False, indices=lonely, min_only=True)
    seeds = []
    for first in lonely.tolist():
        members = np.flatnonzero(labels == labels[first])
        seeds.append(int(members[np.argmax(distance[members])]))
    return np.asarray(seeds, dtype=np.int64)


def area_centres(adjacency: sp.csr_array, labels: np.ndarray, chosen: np.ndarray) -> np.ndarray:
    """The graph centre of each ``chosen`` area: (k,) rows, one per area by ascending area label, each the node whose
    farthest node of its area lies nearest (ties: the lowest row).

    ``adjacency``: (n, n) edge lengths, m; ``labels``: (n,) each node's area;
    ``chosen``: (areas,) bool. The centre is where a designer puts the one
    mark of a small place (a channel bed, an islet), found
    alike on a navmesh of two polygons and on a grid of samples: the middle
    of a strip, of a rectangle. Exact up to :data:`CENTRE_EXACT_NODES` nodes:
    Dijkstra from every node of the area, :data:`CENTRE_ROWS` sources at a
    time (memory), O(n_c (m_c + n_c log n_c)) for an area of n_c nodes and
    m_c edges; the areas asked are those under ``min_area``, a few dozen nodes
    each with the defaults. A larger area reads each node's farthest as its
    farthest of :data:`CENTRE_LANDMARKS` landmarks, each the node farthest from
    those before (the first the farthest from the area's lowest row), in
    O(k (m_c + n_c log n_c)): on a strip the two ends, so its middle.
    """
    order = np.argsort(labels, kind="stable")  # each area's rows together, ascending
    bounds = np.searchsorted(labels[order], np.arange(len(chosen) + 1))
    centres = []
    for area in np.flatnonzero(chosen).tolist():
        members = order[bounds[area]:bounds[area + 1]]
        within = adjacency[members][:, members]
        if len(members) <= CENTRE_EXACT_NODES:
            farthest = np.concatenate([csgraph.dijkstra(within, directed=False, indices=rows).max(axis=1)
                                       for rows in np.array_split(np.arange(len(members)), -(-len(members) // CENTRE_ROWS))])
        else:
            farthest = _landmark_reach(within)
        centres.append(int(members[np.argmin(farthest)]))
    return np.asarray(centres, dtype=np.int64)


def _landmark_reach(within: sp.csr_array) -> np.ndarray:
    """(n_c,) each node's distance to the farthest of :data:`CENTRE_LANDMARKS` farthest-point landmarks, m: a lower
    bound of its farthest node along the connected graph ``within``."""
    first = int(np.argmax(csgraph.dijkstra(within, directed=False, indices=0)))
    nearest = reach = csgraph.dijkstra(within, directed=False, indices=first)  # to the nearest / farthest landmark
    for _ in range(CENTRE_LANDMARKS - 1):
        from_landmark = csgraph.dijkstra(within, directed=False, indices=int(np.argmax(nearest)))
        nearest, reach = np.minimum(nearest, from_landmark), np.maximum(reach, from_landmark)
    return reach


def smallest_part(context: RunContext) -> float:
    """The default ``place_area``: :data:`PART_AGENT_RADII_SQUARED` agent radii squared, m² (0 without an agent)."""
    return 0.0 if context.agent is None else PART_AGENT_RADII_SQUARED * context.agent.radius * context.agent.radius


def cover_paths(adjacency: sp.csr_array, seeds: np.ndarray, eligible: np.ndarray, radius: float) -> np.ndarray:
    """The seeds plus, farthest node first, shortest paths to the growing set until all is within ``radius``.

    After each path the distances are lowered by a Dijkstra from the path
    that only follows nodes it brings closer, so the work per path is the
    area around it, not the whole level. The nodes farther than ``radius``
    are taken farthest first (ties: lowest row), and one that came closer
    since its distance was read goes back into a heap at its new distance;
    the loop runs in C++ (:func:`g2s_plugins._trees.cover_paths`, whose heaps
    are Python's ``heapq`` step for step, so equally short ways are chosen as
    that gives them).
    """
    start, predecessor, _ = csgraph.dijkstra(
        adjacency, directed=False, indices=seeds, min_only=True, return_predecessors=True
    )
    far = np.flatnonzero((start > radius) & eligible)
    far = far[np.lexsort((-far, start[far]))]  # taken from the end: farthest first, ties lowest row first
    added = _trees.cover_paths(
        *traffic.extension_csr(adjacency), np.ascontiguousarray(start, dtype=np.float64),
        np.ascontiguousarray(predecessor, dtype=np.int32), np.ascontiguousarray(far, dtype=np.int64), float(radius),
    )
    return np.unique(np.concatenate([seeds, added]))
