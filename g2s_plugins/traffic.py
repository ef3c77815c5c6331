"""Walking on the initial surface graph: distance to a structure, the area each
structure node stands for, and area-weighted origin-destination flow.

Shared by the ``coverage`` terminal selector, the ``flow`` and ``area``
analyzers, area-weighted betweenness and :mod:`g2s_plugins.evaluation`.
The walking flow of an initial graph is computed once per graph and
sample (:func:`walking_flow`): a traffic-aware ``coverage`` and the
``flow`` analyzer of the same run share it.
Every computation is a sparse-graph search over the whole graph at once:
:func:`scipy.sparse.csgraph.dijkstra`, except the hundreds of shortest-path
trees of the flow and the sums up them (:func:`shortest_path_flow`), which
run in the C++ extension on two threads and give scipy's trees exactly.

Origin-destination flow (space syntax's "choice", weighted by area)
--------------------------------------------------------------------
Space syntax (B. Hillier and J. Hanson, The Social Logic of Space, Cambridge
University Press, 1984) calls "choice" what network science calls
betweenness (L. C. Freeman, Sociometry 40(1):35-41, 1977); here each pair
counts the product of its ends' areas.

A walker goes from origin s to destination t, both drawn in proportion to
the area of their nodes (polygons), along the shortest path of the graph.
The flow through node v is the total pair weight of the paths that pass
*through* v (v not an end point)::

    flow(v) = sum over ordered pairs (s, t), s != v != t, of a_s a_t [v on path(s, t)]

Where a pair has several shortest paths, ``ties`` says which one it takes.

``first``
    For one source s the shortest paths form a tree (scipy's predecessor
    tree: of equal-length alternatives, the one through the node settled
    first), and the weight passing through v is ``a_s * (A_v - a_v)`` with
    A_v the area of v's subtree. Every pair's whole weight goes one way,
    however many ways are as short.
``split``
    Each pair's weight is split evenly over all its shortest paths, path
    lengths equal within :data:`TIE_TOLERANCE` (relative) counting as equal:
    the through-weight of v from s is ``a_s * sum_t a_t sigma_st(v) /
    sigma_st``, sigma_st the number of shortest s-t paths and sigma_st(v)
    those through v, accumulated by Brandes's dependency recursion
    (:func:`split_path_flow`). This is the flow's definition that does not
    depend on node numbering. It matters where path lengths tie: on a
    regular grid of samples nearly every pair has many equally short paths
    (1 + 1 + sqrt 2 and sqrt 2 + 1 + 1), and ``first`` sends all of one
    source's ties along the lines its tie rule favours, a pattern that
    changes from source to source, so a sample of sources gives a rough
    flow. On a navmesh graph, whose lengths run between irregular polygon
    centres and portals, exact ties are rare and both give nearly the same
    flow (docs/analysis_quality.md, "Walking flow that splits tied paths").

Summed over all sources either is exact in O(n (m + n log n)).

For big graphs k sources are drawn with replacement with probability
a_s / A (A = total area) and ``flow ~ (A / k) sum_i through_{s_i}``, an
unbiased estimate. Each term lies in [0, A^2], so by Hoeffding's
inequality (W. Hoeffding, "Probability inequalities for sums of bounded
random variables", J. American Statistical Association 58(301):13-30,
1963), for any node, with probability >= 1 - delta::

    |estimate(v) - flow(v)| <= A^2 sqrt(ln(2 / delta) / (2 k))

i.e. the *share* of all pair weight passing through v (flow / A^2) is off by
at most ``sqrt(ln(2 / delta) / (2 k))`` (0.10 for k = 256, delta = 0.01);
:func:`flow_error_bound` returns it. The sources come from
``numpy.random.default_rng(seed)``: same graph, same seed, same values.
Cost: O(k (m + n log n)) plus O(k n) memory in blocks.

Small areas walked exactly
--------------------------

No path leaves a connected area of the graph (a roof out of reach, an islet,
a room behind a closed door), so each area's flow comes from its own
sources alone. Drawn over the whole graph in proportion to area, the k
sources miss many small areas (a roof of 50 m² in a town of 16,000 m² gets
one of 256 independent draws with probability 0.55), and every node of an area
without a source reads 0. So the sample is stratified by area (W. G.
Cochran, Sampling Techniques, 3rd ed., Wiley 1977, ch. 5): the smallest
areas are walked exactly, every node of positive weight a source with its
own weight as factor (:func:`exact_areas` chooses them: smallest first by
node count n_c while the sum of n_c² stays within one sample's work, k n),
and the k draws are made over the other areas only, each draw's factor
``A_R / k`` with A_R the weight of those areas. Each stratum's estimate is
unbiased (the exact one trivially, the drawn one as above with A_R for A),
so the whole is unbiased, and the Hoeffding bound above holds with A_R² <=
A² (the nodes of the exact areas have no error at all). The exact areas'
trees span their own areas only (:func:`_exact_area_flow`): O(k n) more for
their sums at most, O(sum_c n_c (m_c + n_c log n_c)) for their searches, and
O(n + m) to find the areas. A graph of one area (or one whose areas are all
too big) is sampled exactly as before, bit for bit; where the draws' areas
hold at most k nodes of positive weight they too are walked whole. Measured
(docs/analysis_quality.md, "Small areas walked exactly"): a roof town's heat
map's rho against the exact flow on the navmesh route 0.847-0.907 ->
0.967-0.982, each now its ceiling (a roof no source fell on read 0).

Linear scaling (``scaling: linear``)
------------------------------------

That estimate is unbiased but lumpy where it matters for a heat map: every
walk from a sampled source leaves it through its few neighbours, so the
nodes next to each sampled source get all of its weight and read busier
than they are (on grid samplings with split ties, the samples 0.5-1.6 m
from a sampled source read 2.5-6.5 percentile points high and carry 25-52 %
of the sample's squared rank error on five levels; docs/analysis_quality.md, "The sampling
preset's held-out misses"). R. Geisberger, P. Sanders and D. Schultes
("Better approximation of betweenness centrality", ALENEX 2008, 90-100)
weight each pair's contribution to v by how far along its path v lies::

    through_s(v) = 2 sum_t a_t share_st(v) d(s, v) / d(s, t)

so a node next to the source gets little of a far pair. With the same
shortest paths in both directions (``ties: split``: share_st = share_ts on
an undirected graph) d(s, v) / d(s, t) + d(t, v) / d(t, s) = 1 for every v
on them, so over the two ordered pairs the expectation is the plain flow's:
still unbiased. (With ``first`` the two directions of a tied pair may take
different paths, and the sum is unbiased only up to that choice.) It is the
plain sums of :func:`split_path_flow` or :func:`shortest_path_flow` with
each source's target values divided by their distance, then multiplied by
d(s, v): in the extension, each source's one search gives the distances that
scale its values, on the same threads as the plain flow. The exact flow
(every source) is the same either way and is computed plainly. A sampled
flow of this kind with ``ties: split`` runs on the graph renumbered along
its Hilbert curve in plan (:func:`flow_layout`, below): the same bits, with
a node's neighbours close to it in memory.

Spread sources (``sampling: spread``)
-------------------------------------

Independent draws leave some parts of a level with more sources than their
area's share and others with fewer, and a node's flow depends on where the
sources lie. Drawn spread, the k sources are a systematic sample with
probability proportional to area along a space-filling order of the nodes
(W. G. Madow, "On the theory of systematic sampling, II", Annals of
Mathematical Statistics 20(3):333-354, 1949; W. G. Cochran, Sampling
Techniques, 3rd ed., Wiley 1977, ch. 8): the nodes are ordered along a
Hilbert curve over their positions in plan (D. Hilbert, Math. Ann.
38:459-460, 1891), their areas laid end to end, and the sources are the
nodes at u, u + A/k, ..., u + (k - 1) A/k with one uniform u in [0, A/k).
Each node is still drawn k a_s / A times in expectation, so the estimate is
as unbiased as the independent one, but every stretch of the curve holding
A/k of the area gets one source: a stratified sample whose strata are
compact in plan, and nearby sources' trees carry similar flow, so the
error is lower. Measured on grid samplings (docs/analysis_quality.md, "A heat
map with less noise on the sampling route"): a spread sample of 256 ranks the
nodes against the exact flow about as well as 512 independent ones, at the
cost of 256. The order is O(n log n) once per graph (:func:`plan_order`).
"""

from __future__ import annotations

import math
import os
import threading
from collections.abc import Callable, Hashable, Iterable, Iterator
from concurrent.futures import Future
from itertools import repeat
from typing import Literal

import numpy as np

from g2s_core.lazy import lazy_module
from g2s_plugins import _trees
from g2s_plugins.flow_layout import FlowLayout, renumbered
from g2s_plugins.surface_arrays import MIN_LENGTH, SurfaceArrays, surface_arrays

sp, csgraph = lazy_module("scipy.sparse"), lazy_module("scipy.sparse.csgraph")
nx = lazy_module("networkx")

__all__ = [
    "EXACT_NODES", "TIE_TOLERANCE", "WALKING_SAMPLING", "WALKING_SCALING", "WALKING_SOURCES", "WALKING_TIES", "Sampling",
    "Scaling", "SurfaceArrays", "Ties", "arrays_walking_flow", "at_least_min_length", "distance_to", "flow_error_bound",
    "flow_layout", "gather", "is_exact", "linear_through", "od_flow", "origin_weight", "percentile", "plan_order",
    "represented_area", "sampling_order", "shortest_path_flow", "source_blocks", "split_path_flow",
    "start_walking_flow", "surface_arrays", "tie_tolerance", "tree_threads", "waiting_flag", "walking_flow",
    "walking_sources",
]

Ties = Literal["first", "split"]
"""How a walking flow treats a pair's equally short paths: all its weight along one (``first``) or split evenly
over all of them (``split``); see the module docs."""

Scaling = Literal["none", "linear"]
"""How a sampled walking flow counts a sampled source's pairs: each pair's whole weight on every node of its path
(``none``) or weighted by how far along the path the node lies (``linear``, Geisberger, Sanders and Schultes); see
the module docs. An exact flow is the same either way."""

Sampling = Literal["independent", "spread"]
"""How a sampled walking flow draws its sources: independently in proportion to area (``independent``), or as a
systematic sample along a Hilbert curve over the nodes' positions in plan (``spread``); see the module docs."""

TIE_TOLERANCE = 1e-6
"""Relative difference within which two path lengths tie for ``ties: split`` (:func:`split_path_flow`).

Why this size: it must hold the rounding of two float sums of the same
exact length, and the noise a level's coordinates put into lengths that are
meant to be equal, and stay below the differences its real geometry makes.
A distance is a float sum of at most n - 1 non-negative edge lengths, each
addition rounding by at most eps/2 of a partial sum no larger than the
whole (eps = 2^-52), so two sums of one exact length (1 + 1 + sqrt 2 and
sqrt 2 + 1 + 1 on a grid) differ by at most about n eps of it: 2.2e-10 for
a million nodes. Measured on grid samplings (the relative excess ``(d(v) +
length - d(w)) / d(w)`` of every edge from 16 sources, by decade;
``benchmarks/tied_paths.py`` prints it in four bins; docs/analysis_quality.md,
"Walking flow that splits tied paths"):
on a generated dungeon's exact geometry the excesses that are not 0 lie at
1e-15 (rounding) and then from 1e-3 up, nothing between; on nav_test's
floor (an OBJ file's coordinates) a cluster runs from 1e-12 to 1e-8 (3.6 %
of the edges: steps whose lengths differ by micrometres of height), thins
to 0.11 % in (1e-8, 1e-7] and 0.04 % in (1e-7, 1e-6], and rises again from
1e-5 (0.45 % in (1e-5, 1e-4]), where slopes begin.
1e-6 lies in that gap: 1 mm over 1 km of walking, which no walker tells
apart. On rolling terrain the excesses run on through every size, and the
tolerance ties only 0.1 % of the edges there, those differing by under
1e-6.
"""

BLOCK_ENTRIES = 1 << 22
"""Tree entries computed at once by :func:`od_flow` and :mod:`g2s_plugins.cross_sections` (32 MB of float64;
:func:`source_blocks`)."""

KEPT_ENTRIES = 1 << 25
"""Tree entries :func:`od_flow` keeps before it sums them into the flow (256 MiB of float64: every block of the
100k-polygon level's 255 sources). Each sum is a matrix product, after which OpenBLAS's worker thread spins for
a while on the core the second tree thread needs: the trees of all these blocks first, then the products in the
same order (the same bits), took 0.05-0.27 s less wall time and 0.14-0.38 s less CPU on that level (four
alternating runs, load 2.2; docs/performance.md)."""

WALKING_SOURCES = 256
"""Sources of the walking flow that the ``flow`` analyzer and a traffic-aware ``coverage`` compute by default
(one computation per run when both use it: :func:`walking_flow`)."""

WALKING_TIES: Ties = "first"
"""Ties of that walking flow by default: the ``flow`` analyzer's ``ties``, which the simplification's ``heat_ties``
and ``coverage``'s ``traffic_ties`` default to as well."""

WALKING_SCALING: Scaling = "none"
"""Scaling of that walking flow's sample by default: the ``flow`` analyzer's ``scaling``, which ``heat_scaling`` and
``traffic_scaling`` default to as well."""

WALKING_SAMPLING: Sampling = "independent"
"""How that walking flow draws its sources by default: the ``flow`` analyzer's ``sampling``, which ``heat_sampling``
defaults to as well (a traffic-aware ``coverage`` always draws them independently)."""

HILBERT_BITS = 16
"""Bits per axis of the grid :func:`plan_order` orders the nodes on: 65,536 cells along the level's longer side in
plan (1.5 mm a cell on a 100 m level, 15 mm on 1 km, 1.5 m on 100 km). Nodes in one cell (above one another, or
closer than a cell) keep their row order."""

EXACT_NODES = 2000
"""The heat-map guarantee (:mod:`g2s_plugins.heat_guarantee`) and the evaluation's reference
(:mod:`g2s_plugins.evaluation`) compute the exact walking flow of graphs with at most this many nodes of positive
weight (``exact_up_to`` of :func:`walking_flow`): a 256-source sample ranks a structure's heat map up to 0.024 of
rho above the exact flow on levels of 700-1,400 polygons, whose exact flow costs 0.02-0.13 s of CPU (0.18 s at
1,974, O(n (m + n log n)); a `g2s run` of such a level, 2.2-3.7 s; docs/analysis_quality.md, "A guaranteed heat
map")."""

THREADS = min(2, os.cpu_count() or 1)
"""Threads of :func:`shortest_path_flow` (each runs whole sources; the values do not depend on it), but one on a
flow begun ahead that no caller waits for yet (:func:`start_walking_flow`)."""


def distance_to(arrays: SurfaceArrays, sources: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Distance from every node to its nearest source along the graph, and that source.

    Args:
        sources: (k,) rows of the source nodes.

    Returns:
        distance: (n,) metres (``inf`` where no source is reachable).
        nearest: (n,) row of the nearest source, -1 where none is reachable.
    """
    if len(sources) == 0:
        return np.full(arrays.n, np.inf), np.full(arrays.n, -1, dtype=np.int64)
    distance, _, nearest = csgraph.dijkstra(
        arrays.adjacency, directed=False, indices=np.asarray(sources), min_only=True,
        return_predecessors=True,
    )
    nearest = np.where(np.isfinite(distance), nearest, -1).astype(np.int64)
    return distance, nearest


def gather(
    graph: nx.Graph, structure_nodes: Iterable[Hashable], values: np.ndarray, mean: bool = False,
    nearest: np.ndarray | None = None,
) -> dict[Hashable, float]:
    """Per structure node, the sum (or mean) of ``values`` over the graph nodes it stands for.

    Every node of ``graph`` belongs to its nearest structure node along the
    graph (equal distances: scipy's choice, deterministic), so the nodes a
    simplification removed count for the node that absorbed their part of
    the surface. Nodes that reach no structure node give nothing.

    Args:
        values: (n,) one value per graph node, in the order of
            :func:`surface_arrays`.
        mean: divide each sum by the number of graph nodes it gathers.
        nearest: (n,) each graph node's nearest structure node's row, when
            the caller has it (the second result of :func:`distance_to` from
            the structure nodes' rows); else searched here.
    """
    arrays = surface_arrays(graph)
    structure = sorted(structure_nodes)
    if nearest is None:
        _, nearest = distance_to(arrays, arrays.rows(structure))
    totals = gathered(nearest, values, mean)
    return {node: float(totals[arrays.index[node]]) for node in structure}


def gathered(nearest: np.ndarray, values: np.ndarray, mean: bool = False) -> np.ndarray:
    """(n,) :func:`gather`'s sums (or means) by row: each row's sum of (n,) ``values`` over the nodes whose nearest
    structure node's row it is, in (n,) ``nearest`` (-1: none; 0 for a row no node is nearest to). O(n)."""
    reached = nearest >= 0
    totals = np.bincount(nearest[reached], weights=np.asarray(values, dtype=np.float64)[reached], minlength=len(nearest))
    if mean:
        totals /= np.maximum(np.bincount(nearest[reached], minlength=len(nearest)), 1)
    return totals


def percentile(values: np.ndarray) -> np.ndarray:
    """(n,) each value's percentile rank among ``values``, 0-100: ``100 (rank - 0.5) / n``, ties averaged.

    The heat map's scale when only the order of the polygons' traffic
    matters: a node's mean percentile is not pulled up by one busy polygon
    the way its mean flow is. A rank is ``scipy.stats.rankdata``'s
    (``method="average"``; all ``nan`` when a value is ``nan``) but for what
    counts as a tie, computed here with one stable sort: the mean rank of a
    run of ties, ``first + (count - 1) / 2``, is a whole or half number, so
    it is the same float however it is computed, and a run needs no import
    of ``scipy.stats`` (0.3 s or more, docs/performance.md). O(n log n).

    **Ties within rounding.** In the sorted values a run of ties goes on
    while each value exceeds the one before it by at most
    :func:`tie_tolerance` (``2 n eps`` of the largest magnitude): flows equal
    in exact arithmetic (two samples placed symmetrically) whose float sums
    came out a few units in the last place apart, in a way that depends on
    where the level lies, rank as equal. The rule chains: values 1,
    1 + t, 1 + 2t (t the tolerance) are one run of three, though its ends
    differ by 2t; it is the rule that splits the sorted values into runs
    whatever their spacing, and a chain joins distinct values only where
    they lie within a tolerance of each other, which the flows measured do
    not (see :func:`tie_tolerance`).
    """
    values = np.asarray(values, dtype=np.float64).reshape(-1)
    n = values.size
    order = np.argsort(values, kind="stable")
    ordered = values[order]
    with np.errstate(invalid="ignore"):  # inf - inf is nan, no step beyond the tolerance: equal infinities tie
        steps = np.diff(ordered)
    starts = np.flatnonzero(np.concatenate([[True], steps > tie_tolerance(values)]))
    counts = np.diff(np.append(starts, n))
    ranks = np.empty(n)
    ranks[order] = np.repeat(starts + 1 + (counts - 1) / 2, counts)
    if np.isnan(values).any():
        ranks[:] = np.nan
    return 100.0 * (ranks - 0.5) / max(n, 1)


def tie_tolerance(values: np.ndarray) -> float:
    """The largest difference :func:`percentile` counts as a tie among the (n,) ``values``: ``2 n eps max |v|``
    (eps = 2^-52, the largest magnitude over the finite values; 0 when there are none).

    Why: a walking flow (:func:`od_flow`) is a sum of non-negative terms,
    per source a subtree's values (at most n of them, added up the tree by
    :func:`shortest_path_flow`, less the node's own value), then the sources'
    products with their factors (at most n sources). However a sum of
    non-negative terms is ordered, each of its roundings is at most eps/2 of
    a partial sum no larger than the whole, so a flow is off by at most
    about ``(n + n) eps / 2`` of the scale of its sums, and two flows equal
    in exact arithmetic lie within ``2 n eps`` of it. The values alone do
    not give that scale (the total pair weight A²), so the largest value
    stands for it. Measured (3 December 2026, ``map_analysis_sampling`` on
    nav_test.obj, n = 2,862, at the origin and moved 10 km to 10,000 km):
    the tolerance is 1.3e-12 of the largest flow (which is 2% of A²); flows
    tied but for rounding differ by at most 6 units in their last place
    (1.1e-16 of the largest), distinct ones by at least 5.3e-6 of it, so
    neither comes near the tolerance, and the last bits of the areas and
    lengths a level far out gets from its world coordinates move the ties
    only within it.
    """
    values = np.asarray(values, dtype=np.float64).reshape(-1)
    finite = np.abs(values[np.isfinite(values)])
    return 2.0 * values.size * float(np.finfo(np.float64).eps) * float(finite.max()) if finite.size else 0.0


def represented_area(graph: nx.Graph, structure_nodes: Iterable[Hashable]) -> dict[Hashable, float]:
    """The walkable area each structure node stands for, m² (:func:`gather` of the nodes' ``area``)."""
    return gather(graph, structure_nodes, surface_arrays(graph).area)


def shortest_path_flow(adjacency: sp.csr_array, sources: np.ndarray, values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Shortest-path trees from ``sources``, and the value passing through each node of each tree.

    Args:
        adjacency: (n, n) edge lengths, CSR; row i holds the edges leaving i.
        sources: (b,) rows of the sources.
        values: (n,) the value of each node.

    Returns:
        predecessors: (b, n) int32, the trees exactly as
            ``scipy.sparse.csgraph.dijkstra(adjacency, directed=True,
            indices=sources, return_predecessors=True)`` gives them (scipy
            1.15 and later), equal lengths included (-9999: the source, or
            unreached).
        through: (b, n) float64, ``values`` summed over each node's
            descendants in that tree (its subtree without itself); 0 for the
            source and for unreached nodes.

    In the C++ extension (``src/trees_module.cpp``) on :func:`tree_threads`
    threads: per source O(m log m) for the search (which queues only the
    nodes that are not passages of a corridor, two neighbours each, and walks
    through those) and O(m) for the sums,
    each node's children added in index order with numpy's pairwise sum, so
    the values are the bits the scipy-and-numpy formulation gives. Why C++:
    scipy's search holds the GIL, so it cannot use the second core (two
    Python threads gave 1.02-1.07x, docs/performance.md); here each thread
    runs whole sources.

    Raises:
        ValueError: an index or source out of range, or a negative length.
    """
    return _trees.shortest_path_flow(
        *extension_csr(adjacency), np.asarray(sources, dtype=np.int32), np.ascontiguousarray(values, dtype=np.float64),
        tree_threads(), waiting_flag(),
    )


def split_path_flow(adjacency: sp.csr_array, sources: np.ndarray, values: np.ndarray) -> np.ndarray:
    """(b, n) float64: per source of the (b,) ``sources`` and node v, the sum over targets t != v of ``values[t]``
    times the share of the source's shortest paths to t that pass through v (``ties: split``, module docs).

    Args:
        adjacency: (n, n) edge lengths >= 0, CSR; row i holds the edges leaving i.
        sources: (b,) rows of the sources.
        values: (n,) the value of each node (its area, m²).

    0 for the source and for unreached nodes. Path lengths within
    :data:`TIE_TOLERANCE` of each other (relative) count as equal. Brandes's
    accumulation (U. Brandes, "A faster algorithm for betweenness
    centrality", J. Mathematical Sociology 25(2):163-177, 2001; target
    values as in U. Brandes, "On variants of shortest-path betweenness
    centrality and their generic computation", Social Networks
    30(2):136-145, 2008): per source one Dijkstra search, O(m log m), then
    one pass forward over the settled nodes counting shortest paths and one
    back summing values, O(m) each; memory O(n + m) per thread beside the
    (b, n) result. In the C++ extension (``src/trees_module.cpp``) on
    :func:`tree_threads` threads, each source's sums in a fixed order: the same
    bits for any thread count.

    Raises:
        ValueError: an index or source out of range, or a negative length.
    """
    return _trees.split_path_flow(
        *extension_csr(adjacency), np.asarray(sources, dtype=np.int32), np.ascontiguousarray(values, dtype=np.float64),
        TIE_TOLERANCE, tree_threads(), waiting_flag(),
    )


def extension_csr(adjacency: sp.csr_array) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``adjacency``'s CSR arrays as the C++ extension takes them: (n+1,) int32 indptr, (m,) int32 indices, (m,)
    float64 lengths, each contiguous."""
    csr = sp.csr_array(adjacency)
    return (np.ascontiguousarray(csr.indptr, dtype=np.int32), np.ascontiguousarray(csr.indices, dtype=np.int32),
            np.ascontiguousarray(csr.data, dtype=np.float64))


def flow_error_bound(sources: int, delta: float = 0.01) -> float:
    """Hoeffding bound on the error of sampled flow, as a share of all pair weight A².

    With probability >= 1 - ``delta`` for any one node, ``|estimate - exact|
    <= bound * A^2`` when ``sources`` sources are drawn (see the module docs).
    """
    return math.sqrt(math.log(2.0 / delta) / (2.0 * sources))


def od_flow(
    adjacency: sp.csr_array,
    weight: np.ndarray,
    max_sources: int | None = None,
    seed: int = 0,
    ties: Ties = "first",
    scaling: Scaling = "none",
    order: np.ndarray | None = None,
    areas: np.ndarray | None = None,
    layout: FlowLayout | None = None,
) -> tuple[np.ndarray, int | None]:
    """Weighted origin-destination flow through every node (see the module docs).

    Args:
        adjacency: (n, n) symmetric edge lengths.
        weight: (n,) origin/destination weight of each node (area, m²).
        max_sources: graphs with at most this many nodes of positive weight
            are computed exactly; above it, the smallest connected areas
            (:func:`exact_areas`) are walked exactly and this many sources
            are sampled over the rest. ``None``: always exact.
        seed: seed of the source sample.
        ties: a pair's equally short paths: all its weight along the first
            (:func:`shortest_path_flow`) or split evenly over all of them
            (:func:`split_path_flow`).
        scaling: a sampled source's pairs counted whole (``none``) or
            linearly scaled (``linear``, :func:`linear_through`); an exact
            flow ignores it.
        order: (n,) every row once, the order along which a sample's
            sources are spread (``sampling: spread``, :func:`plan_order`);
            ``None``: drawn independently. An exact flow ignores it.
        areas: (n,) :func:`exact_areas` of ``adjacency`` for ``max_sources``, when the caller holds them
            (:func:`arrays_exact_areas`); ``None``: found here when a sample needs them.
        layout: ``adjacency`` renumbered (:func:`flow_layout`), on which a sample's linearly scaled split flow runs
            (the same values, in less time); ``None``: it runs on ``adjacency``.

    Returns:
        flow: (n,) pair weight passing through each node (ordered pairs,
            end points excluded), in units of ``weight``².
        sampled: the number of sampled sources, or ``None`` when exact.
    """
    weight = np.asarray(weight, dtype=np.float64)
    n = len(weight)
    flow = np.zeros(n)
    if n == 0 or not np.any(weight > 0):
        return flow, None
    sources, factor, sampled, area = stratified_sources(adjacency, weight, max_sources, seed, order, areas)
    if area is not None and np.any(area >= 0):
        alone = area[sources] >= 0
        _exact_area_flow(flow, adjacency, weight, area, sources[alone], factor[alone], ties, max_sources)
        sources, factor = sources[~alone], factor[~alone]
    linear = sampled is not None and scaling == "linear"
    kept = []
    for lo, block_sources in source_blocks(sources, n):
        # adjacency is symmetric: a directed search scans each edge once instead of from both of
        # its stored directions, with the same distances and predecessors
        through = (linear_through(adjacency, block_sources, weight, ties, layout) if linear
                   else _through(adjacency, block_sources, weight, ties))
        kept.append((lo, through))
        if lo + len(block_sources) >= len(sources) or sum(through.size for _, through in kept) >= KEPT_ENTRIES:
            for start, through in kept:  # block by block, in order: the sum of the products as before
                flow += factor[start:start + len(through)] @ through
            kept.clear()
    return flow, sampled


def stratified_sources(
    adjacency: sp.csr_array, weight: np.ndarray, max_sources: int | None, seed: int = 0,
    order: np.ndarray | None = None, areas: np.ndarray | None = None,
) -> tuple[np.ndarray, np.ndarray, int | None, np.ndarray | None]:
    """The sources of :func:`od_flow`'s sample on ``adjacency`` (n, n) for ``weight`` (n,) with some weight > 0: the
    smallest areas walked exactly beside ``max_sources`` draws over the rest (module docs, "Small areas walked
    exactly"), ``order`` as :func:`walking_sources` takes it, ``areas`` as :func:`od_flow` does.

    Returns :func:`walking_sources`' ``sources``, ``factor`` and ``sampled``, and (n,) the :func:`exact_areas`
    (``None`` when every node of positive weight is a source, which no area then needs). O(n + m) beside the draws.
    """
    if max_sources is None or np.count_nonzero(weight > 0) <= max_sources:
        area = None
    else:
        area = exact_areas(adjacency, max_sources) if areas is None else areas
    return *walking_sources(weight, max_sources, seed, order, None if area is None else area >= 0), area


def exact_areas(adjacency: sp.csr_array, max_sources: int) -> np.ndarray:
    """(n,) int64: each node's connected area of ``adjacency`` (n, n) when :func:`od_flow` walks that area exactly
    beside a sample of ``max_sources`` sources, else -1 (module docs, "Small areas walked exactly").

    The areas are taken smallest first (by node count n_c, ties by their first row) while the sum of their n_c²
    stays within one sample's work, ``max_sources`` n: walking every node of an area costs O(n_c (m_c + n_c log
    n_c)) for the searches and O(n_c²) for the sums. A graph of one area of n > ``max_sources`` nodes is never
    taken (n² > ``max_sources`` n): it is sampled as before. O(n + m) for the areas, O(c log c) for their order.
    """
    count, label = csgraph.connected_components(adjacency, directed=False)
    size = np.bincount(label, minlength=count)
    smallest = np.argsort(size, kind="stable")
    taken = np.zeros(count, dtype=bool)
    taken[smallest[np.cumsum(size[smallest].astype(np.float64) ** 2) <= float(max_sources) * label.size]] = True
    return np.where(taken[label], label, -1).astype(np.int64)


def arrays_exact_areas(arrays: SurfaceArrays, max_sources: int) -> np.ndarray:
    """:func:`exact_areas` of ``arrays``' adjacency for ``max_sources``, read-only, cached with the arrays (so dropped
    when the graph changes size): the cover's, the heat guarantee's, the ``flow`` analyzer's and the evaluation's
    samples of one graph, which differ in seed, ties or scaling but not in ``max_sources``, find the areas once
    (a connected-components pass, about 17 ms at 100k polygons)."""
    key = ("exact_areas", max_sources)
    if key not in arrays.derived:  # two threads may both compute it: the same array, either kept
        area = exact_areas(arrays.adjacency, max_sources)
        area.flags.writeable = False
        arrays.derived[key] = area
    return arrays.derived[key]


def _exact_area_flow(
    flow: np.ndarray, adjacency: sp.csr_array, weight: np.ndarray, area: np.ndarray, sources: np.ndarray,
    factor: np.ndarray, ties: Ties, group_nodes: int,
) -> None:
    """Add to ``flow`` (n,) the exact flow of the areas :func:`exact_areas` marks in ``area`` (n,), from their
    ``sources`` (every node of positive weight, rows in ascending order) with ``factor`` (their weights), each group
    of :func:`exact_area_groups` on its own graph (one call of the extension per block of :func:`source_blocks`, not
    per area: a level may hold thousands of islands). Cost O(sum_c n_c max(group_nodes, n_c)) for the sums, <=
    O(group_nodes n + sum_c n_c²) (with :func:`od_flow`'s ``group_nodes = max_sources`` and :func:`exact_areas`'
    bound, two samples' worth), and O(sum_c n_c (m_c + n_c log n_c)) for the searches.
    """
    for rows, graph, which, local in exact_area_groups(adjacency, area, sources, group_nodes):
        for lo, block in source_blocks(local, len(rows)):
            flow[rows] += factor[which[lo:lo + len(block)]] @ _through(graph, block, weight[rows], ties)


def exact_area_groups(
    adjacency: sp.csr_array, area: np.ndarray, sources: np.ndarray, group_nodes: int,
) -> Iterator[tuple[np.ndarray, sp.csr_array, np.ndarray, np.ndarray]]:
    """The areas :func:`exact_areas` marks in ``area`` (n,) in groups (smallest first) of at most ``max(group_nodes,
    n_c)`` nodes, n_c the group's largest area, with their ``sources`` (rows of those areas, ascending).

    No path leaves an area, so each area's trees need not span the rest of the graph. Yields per group (g,) its rows,
    each area's in row order (the trees' tie order as on the whole graph), (g, g) its ``adjacency``, (j,) the indices
    into ``sources`` of its sources and (j,) their rows in the group. O(n + m) for the subgraph.
    """
    rows = np.flatnonzero(area >= 0)
    size = np.bincount(area[rows])
    rows = rows[np.lexsort((rows, area[rows], size[area[rows]]))]
    sub = sp.csr_array(adjacency[rows][:, rows])
    local = np.full(len(area), -1, dtype=np.int64)
    local[rows] = np.arange(rows.size)
    sources = local[sources]
    area_ends = np.flatnonzero(np.r_[area[rows][1:] != area[rows][:-1], True]) + 1
    start = 0
    for end_index, end in enumerate(area_ends):
        last = end_index + 1 == len(area_ends)
        if not last and area_ends[end_index + 1] - start <= max(group_nodes, area_ends[end_index + 1] - end):
            continue  # the next area fits in this group
        group = np.flatnonzero((sources >= start) & (sources < end))
        yield rows[start:end], sub[start:end][:, start:end], group, sources[group] - start
        start = end


def source_blocks(sources: np.ndarray, n: int) -> Iterator[tuple[int, np.ndarray]]:
    """The (k,) ``sources`` in order, in blocks whose (b, n) trees on a graph of ``n`` nodes hold at most
    :data:`BLOCK_ENTRIES` entries (one source at least): each block's first index in ``sources`` and its rows."""
    block = max(1, BLOCK_ENTRIES // max(n, 1))
    for lo in range(0, len(sources), block):
        yield lo, sources[lo:lo + block]


def walking_sources(
    weight: np.ndarray, max_sources: int | None, seed: int = 0, order: np.ndarray | None = None,
    exact: np.ndarray | None = None,
) -> tuple[np.ndarray, np.ndarray, int | None]:
    """The sources :func:`od_flow` walks from, for ``weight`` (n,) with some weight > 0.

    Args:
        order: (n,) every row once (:func:`plan_order`): the ``max_sources`` draws are spread along it, the nodes
            whose weights, laid end to end in this order, hold the points ``u + i W / max_sources`` (W: the weight
            drawn from, i = 0 .. max_sources - 1, one uniform ``u`` below the step, drawn from the first stream
            ``numpy.random.SeedSequence(seed).spawn`` gives, so that its errors are independent of those of the
            independent sample of the same seed); ``None``: drawn independently.
        exact: (n,) bool, the nodes of the areas walked exactly beside the sample (:func:`exact_areas`): each of
            their nodes of positive weight a source, the draws made over the other nodes only; ``None``: none.

    Returns:
        sources: (k,) rows, ascending: every node of positive weight when there are at most ``max_sources`` of them
            (or ``max_sources`` is ``None``), else those of the ``exact`` areas and the distinct nodes of
            ``max_sources`` draws over the rest in proportion to weight, with replacement
            (``numpy.random.default_rng(seed)``) or spread; when the rest has at most ``max_sources`` nodes of
            positive weight, all of them.
        factor: (k,) each source's factor: its weight, or its draws times the rest's weight / ``max_sources``.
        sampled: the number of draws, or ``None`` when every weighted node is a source.
    """
    candidates = np.flatnonzero(weight > 0)
    if max_sources is None or candidates.size <= max_sources:
        return candidates, weight[candidates], None
    rest = np.ones(weight.size, dtype=bool) if exact is None else ~exact
    drawn_from = candidates[rest[candidates]]
    if drawn_from.size <= max_sources:  # the rest too is walked whole, at no more than a sample's cost
        return candidates, weight[candidates], None
    if order is None:
        rng = np.random.default_rng(seed)
        draws = rng.choice(drawn_from, size=max_sources, replace=True, p=weight[drawn_from] / weight[drawn_from].sum())
    else:  # its start from a stream spawned off the seed's: independent of the independent sample of the same seed
        start = np.random.default_rng(np.random.SeedSequence(seed).spawn(1)[0]).uniform()
        along = np.asarray(order)[(weight[order] > 0) & rest[order]]
        ends = np.cumsum(weight[along])
        step = ends[-1] / max_sources
        points = (start + np.arange(max_sources)) * step
        draws = along[np.minimum(np.searchsorted(ends, points, side="right"), along.size - 1)]
    sources, counts = np.unique(draws, return_counts=True)
    # the rest's weight as a sum over all n nodes (0 in the exact areas): with no area exact, weight.sum()'s bits
    factor = counts * (np.where(rest, weight, 0.0).sum() / max_sources)
    walked = candidates[~rest[candidates]]
    if walked.size == 0:
        return sources, factor, max_sources
    merged = np.argsort(np.r_[walked, sources], kind="stable")
    return np.r_[walked, sources][merged], np.r_[weight[walked], factor][merged], max_sources


def plan_order(graph: nx.Graph) -> np.ndarray:
    """(n,) the rows of ``graph``'s :func:`surface_arrays` along a Hilbert curve over the nodes' ``pos`` in plan
    (x, z; Y up), ties by row: the order a ``spread`` sample's sources are drawn along (module docs).

    The positions are scaled onto a square grid of 2^:data:`HILBERT_BITS` cells a side over the level's bounds in plan,
    so the order depends only on where the nodes lie relative to each other (not on where the level lies in the
    world). Cached with the arrays. O(n HILBERT_BITS) for the curve's index, O(n log n) for the sort.
    """
    arrays = surface_arrays(graph)
    if "plan_order" not in arrays.derived:
        data = graph.nodes
        plan = np.array([data[node]["pos"] for node in arrays.nodes], dtype=np.float64).reshape(-1, 3)[:, [0, 2]]
        order = np.argsort(hilbert_index(plan, HILBERT_BITS), kind="stable")
        order.flags.writeable = False
        arrays.derived["plan_order"] = order
    return arrays.derived["plan_order"]


def flow_layout(arrays: SurfaceArrays) -> FlowLayout | None:
    """``arrays``' graph renumbered along its :func:`plan_order` for the walking flow's kernel
    (:mod:`g2s_plugins.flow_layout`: the same values in less time), its lengths at least :data:`MIN_LENGTH`; ``None``
    when the graph is gone or has nodes without a ``pos``. Cached with the arrays, once per graph for every sampled
    split flow of a run (the cover's, the loops', the simplification's and the ``flow`` analyzer's). O(n log n) for
    the order (shared with a ``spread`` sample), O(n + m) for the arrays."""
    if "flow_layout" not in arrays.derived:  # two threads may both make it: the same arrays, either kept
        graph = arrays.graph()
        placed = graph is not None and all(map(dict.__contains__, map(graph._node.__getitem__, arrays.nodes),
                                               repeat("pos")))
        arrays.derived["flow_layout"] = renumbered(at_least_min_length(arrays.adjacency), plan_order(graph)) if placed else None
    return arrays.derived["flow_layout"]


def hilbert_index(points: np.ndarray, bits: int) -> np.ndarray:
    """(n,) int64 position along a Hilbert curve of each of the (n, 2) ``points`` (m), scaled by their bounds' longer
    side onto a square grid of 2^``bits`` cells a side (``bits`` <= 31). The curve's recursion, quadrant by quadrant
    from the coarsest (the standard bit-by-bit conversion of a cell to its distance along the curve), vectorised over
    the points: O(n bits)."""
    points = np.asarray(points, dtype=np.float64).reshape(-1, 2)
    cells = (1 << bits) - 1
    if points.size == 0:
        return np.zeros(0, dtype=np.int64)
    low = points.min(axis=0)
    side = float((points.max(axis=0) - low).max())
    grid = np.zeros(points.shape, dtype=np.int64) if side == 0 else np.minimum(
        ((points - low) / side * cells).astype(np.int64), cells)
    x, y = grid[:, 0], grid[:, 1]
    index = np.zeros(len(points), dtype=np.int64)
    half = 1 << (bits - 1)
    while half > 0:
        right, up = (x & half) > 0, (y & half) > 0
        index += half * half * ((3 * right) ^ up)
        turn = ~up  # the lower quadrants are turned so that the curve runs on through them
        mirror = turn & right
        x, y = np.where(mirror, x ^ cells, x), np.where(mirror, y ^ cells, y)  # below ``half``: half - 1 - x
        x, y = np.where(turn, y, x), np.where(turn, x, y)
        half >>= 1
    return index


def sampling_order(graph: nx.Graph, sampling: Sampling) -> np.ndarray | None:
    """The ``order`` argument of :func:`arrays_walking_flow` for ``sampling``: :func:`plan_order` for ``spread``,
    ``None`` for ``independent``."""
    return plan_order(graph) if sampling == "spread" else None


def linear_through(
    adjacency: sp.csr_array, sources: np.ndarray, values: np.ndarray, ties: Ties, layout: FlowLayout | None = None,
) -> np.ndarray:
    """(b, n) float64: per source s of the (b,) ``sources`` and node v, 2 d(s, v) times the sum over targets t != v
    of ``values[t]`` / d(s, t) times the share of the source's shortest paths to t through v (``ties``): the
    linearly scaled through-weight of the module docs.

    Args:
        adjacency: (n, n) edge lengths >= 0, CSR, symmetric; a length under :data:`MIN_LENGTH` is read as that
            (:func:`at_least_min_length`: a pair at distance 0 still counts, its ratio d(s, v) / d(s, t) then that
            of the steps between them).
        sources: (b,) rows of the sources.
        values: (n,) the value of each node (its area, m²).
        layout: ``adjacency`` renumbered (:func:`flow_layout`; its lengths at least :data:`MIN_LENGTH`), for ``ties``
            ``split``: the kernel runs on it, with the same bits; ``None``: on ``adjacency``.

    0 for the source and for unreached nodes. In the C++ extension (``src/trees_module.cpp``) on :func:`tree_threads`
    threads, each source one search, O(m log m), whose distances scale the values before the sums of
    :func:`split_path_flow` (or :func:`shortest_path_flow`) over that search, O(m), and weigh them after: the same bits
    as scipy's distances with numpy's divisions and products around those functions called per source.
    """
    sources, values = np.asarray(sources, dtype=np.int32), np.ascontiguousarray(values, dtype=np.float64)
    if layout is not None and ties == "split":
        return _trees.linear_path_flow(layout.indptr, layout.indices, layout.lengths, sources, values, ties,
                                       TIE_TOLERANCE, tree_threads(), waiting_flag(), layout.original)
    return _trees.linear_path_flow(*extension_csr(at_least_min_length(adjacency)), sources, values, ties, TIE_TOLERANCE,
                                   tree_threads(), waiting_flag())


def at_least_min_length(adjacency: sp.csr_array) -> sp.csr_array:
    """``adjacency`` with every stored length under :data:`MIN_LENGTH` (a stored zero: coincident nodes) read as that,
    as :func:`surface_arrays` stores it, so that a linearly scaled flow's pair at distance 0 still counts (else it is
    dropped: its ratio 0 / 0). O(m)."""
    if np.any(adjacency.data < MIN_LENGTH):
        return sp.csr_array((np.maximum(adjacency.data, MIN_LENGTH), adjacency.indices, adjacency.indptr), adjacency.shape)
    return adjacency


def _through(adjacency: sp.csr_array, sources: np.ndarray, values: np.ndarray, ties: Ties) -> np.ndarray:
    """(b, n) the plain through-weight per source: :func:`split_path_flow` or :func:`shortest_path_flow`, as
    ``ties`` says."""
    if ties == "split":
        return split_path_flow(adjacency, sources, values)
    return shortest_path_flow(adjacency, sources, values)[1]


def origin_weight(arrays: SurfaceArrays) -> np.ndarray:
    """(n,) the weight walkers are drawn by: each node's area, m², or 1 per node when no node has an area."""
    return arrays.area if arrays.area.sum() > 0 else np.ones(arrays.n)


def walking_flow(
    graph: nx.Graph, max_sources: int | None = None, seed: int = 0, exact_up_to: int = 0, ties: Ties = "first",
    scaling: Scaling = "none", sampling: Sampling = "independent",
) -> np.ndarray:
    """(n,) :func:`od_flow` of ``graph`` by :func:`origin_weight`, in :func:`surface_arrays` order; read-only.

    Exact on graphs with at most ``max(max_sources, exact_up_to)`` nodes of
    positive weight (:func:`is_exact`), else from ``max_sources`` sampled
    sources, counted as ``scaling`` says and drawn as ``sampling`` says.

    Cached per graph object, ``ties`` and ``(max_sources, seed, scaling, sampling)`` (none of them when exact: the exact flow draws no sample) for as long as its
    :func:`surface_arrays` are (the graph's size unchanged): the selector and
    the analyzer of one run that ask for the same flow get the same array,
    computed once. It is read-only so that no caller can change another's
    values; divide into a new array (``flow / total``).
    """
    return arrays_walking_flow(surface_arrays(graph), max_sources, seed, exact_up_to, ties, scaling,
                               sampling_order(graph, sampling))


def arrays_walking_flow(
    arrays: SurfaceArrays, max_sources: int | None = None, seed: int = 0, exact_up_to: int = 0, ties: Ties = "first",
    scaling: Scaling = "none", order: np.ndarray | None = None,
) -> np.ndarray:
    """:func:`walking_flow` of the graph ``arrays`` were made from, for a caller that holds them already (each
    :func:`surface_arrays` look-up counts the graph's edges: 20-30 ms on a 100k-polygon level); ``order``: that
    graph's :func:`sampling_order` (a ``spread`` sample's :func:`plan_order`, the only order the cache knows)."""
    key, compute = _walking_flow_work(arrays, max_sources, seed, exact_up_to, ties, scaling, order)
    if key not in arrays.derived:
        begun = arrays.begun.pop(key, None)
        if begun is not None:  # its trees on THREADS threads from its next source on: this thread now waits for them
            begun.take()
        arrays.derived[key] = begun.result() if begun is not None else compute()
    return arrays.derived[key]


def start_walking_flow(
    arrays: SurfaceArrays, max_sources: int | None = None, seed: int = 0, exact_up_to: int = 0, ties: Ties = "first",
    scaling: Scaling = "none", order: np.ndarray | None = None,
) -> None:
    """Begin :func:`arrays_walking_flow` of these arguments on a thread of its own, for a caller that will ask for it
    later and has work for this thread meanwhile: that call waits for it and gets the array it would have computed
    (the flow does not depend on the thread or the timing), and an error it raised. Nothing when the flow is
    computed or begun already.

    Why: the flow's trees run on both cores (:func:`shortest_path_flow`, the GIL released), and the Python a stage
    runs before it needs the flow keeps one core busy and the other idle; begun ahead, the trees take that idle
    core. They take that core alone (one thread, :func:`tree_threads`) until a caller waits for the flow, then both
    again from its next source on (:func:`waiting_flag`): two tree threads beside the caller's Python would share
    two cores three ways and slow that Python, the run's longest chain, by up to a third. A flow begun and never taken (a heat guarantee none of whose rounds meets its target, a run stopped by an
    error or Ctrl-C) runs to its end all the same, sharing the cores with whatever the process does next (up to one
    flow's time: about 3 s of CPU at 100k polygons). The thread is not a daemon: the interpreter waits for it before
    it exits, as it would have waited for the flow in the caller's thread; a daemon thread still in the extension
    when the interpreter finalises is unwound there, which aborts the process (exit -6 in place of 2 or 130).
    """
    key, compute = _walking_flow_work(arrays, max_sources, seed, exact_up_to, ties, scaling, order)
    if key in arrays.derived or key in arrays.begun:
        return
    future = BegunFlow()

    def run() -> None:
        _AHEAD.flow = future  # its trees on one thread until a caller takes it (tree_threads)
        try:
            future.set_result(compute())
        except BaseException as exc:  # handed to the caller that takes the flow
            future.set_exception(exc)

    arrays.begun[key] = future
    threading.Thread(target=run, name="walking flow").start()


class BegunFlow(Future):
    """A walking flow being computed on a thread of its own (:func:`start_walking_flow`); ``taken`` is set once a
    caller waits for it (:meth:`take`), and ``waiting`` with it: the extension's copy of that event, which its call
    under way reads between sources without the GIL."""

    def __init__(self) -> None:
        super().__init__()
        self.taken = threading.Event()
        self.waiting = _trees.Waiting()

    def take(self) -> None:
        """Mark the flow as waited for (:func:`arrays_walking_flow`): its trees on :data:`THREADS` threads from its
        next source on, in the extension's call under way too (:func:`waiting_flag`)."""
        self.waiting.set()
        self.taken.set()


_AHEAD = threading.local()
"""``flow``: on a thread that computes a flow begun ahead, its :class:`BegunFlow`."""


def tree_threads() -> int:
    """Threads of the extension's next call of trees: 1 on the thread of a flow begun ahead that no caller waits for
    yet (the caller's own thread holds the other core: :func:`start_walking_flow`), else :data:`THREADS`. The values
    do not depend on it."""
    begun = getattr(_AHEAD, "flow", None)
    return 1 if begun is not None and not begun.taken.is_set() else THREADS


def waiting_flag() -> _trees.Waiting | None:
    """What the extension's next call of trees takes as ``waiting``: on the thread of a flow begun ahead, its
    :class:`BegunFlow`'s ``waiting``, so that a call on one thread (:func:`tree_threads`) takes a second from its
    next source on once a caller waits for the flow, instead of finishing its block of sources (39 at 100k polygons,
    about 0.4 s of CPU) on one core while the other idles; else (or on a one-core machine) ``None``. Given whether or
    not the flow is taken yet (a call on two threads ignores it), so that a caller that comes between the two
    look-ups still gets both threads. The values do not depend on it."""
    begun = getattr(_AHEAD, "flow", None)
    return begun.waiting if begun is not None and THREADS > 1 else None


def _walking_flow_work(
    arrays: SurfaceArrays, max_sources: int | None, seed: int, exact_up_to: int, ties: Ties, scaling: Scaling,
    order: np.ndarray | None,
) -> tuple[tuple[Hashable, ...], Callable[[], np.ndarray]]:
    """The cache key of :func:`arrays_walking_flow` of these arguments, and the computation of its read-only array."""
    exact = is_exact(arrays, max_sources, exact_up_to)
    # one exact flow for every caller that gets it
    sampling = "independent" if order is None else "spread"
    key = ("walking_flow", ties) if exact else ("walking_flow", ties, max_sources, seed, scaling, sampling)

    def compute() -> np.ndarray:
        layout = flow_layout(arrays) if not exact and ties == "split" and scaling == "linear" else None
        flow, _ = od_flow(arrays.adjacency, origin_weight(arrays), None if exact else max_sources, seed, ties, scaling,
                          order, None if exact else arrays_exact_areas(arrays, max_sources), layout)
        flow.flags.writeable = False
        return flow

    return key, compute


def is_exact(arrays: SurfaceArrays, max_sources: int | None, exact_up_to: int = 0) -> bool:
    """Whether :func:`arrays_walking_flow` with these arguments is the exact flow (the graph has at most
    ``max(max_sources, exact_up_to)`` nodes of positive :func:`origin_weight`, or ``max_sources`` is ``None``)."""
    return max_sources is None or np.count_nonzero(origin_weight(arrays) > 0) <= max(max_sources, exact_up_to)
