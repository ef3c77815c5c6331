"""A guaranteed heat map: simplification stops short where the heat map would rank the polygons less like the
walking flow than ``min_heat_rho`` (a parameter of both line-of-sight predicates, :mod:`g2s_plugins._surface`).

The quantity: Spearman rho, over the nodes of the run's initial graph
that reach the structure, between each node's walking flow and the value
the heat map gives it. The heat map is the one the run shows: the mean
percentile, over the nodes its nearest structure node stands for, of the
walking flow of the ``flow`` analyzer's sources
(:func:`g2s_plugins.evaluation.placement_heat` of
:func:`g2s_plugins.traffic.walking_flow` with the predicate's
``heat_sources``, ``heat_ties`` and ``heat_scaling``, which a config sets as that analyzer's
``max_sources``, ``ties`` and ``scaling``: the array that analyzer with ``aggregate:
percentile`` and ``max_traffic_step`` use). The walking flow it is ranked
against is the exact one on graphs of up to
:data:`~g2s_plugins.traffic.EXACT_NODES` nodes with an area, its ties split
whatever ``heat_ties`` says (the evaluation's reference,
:data:`~g2s_plugins.evaluation.REFERENCE_TIES`: on a navmesh graph of
axis-aligned aisles, whose path lengths tie, the first-tie flow ranks the
polygons only 0.96 like it, and a heat map measured against the first-tie
flow read 0.905 where the evaluation read 0.877, docs/analysis_quality.md
"A twenty-eighth round of level kinds"); above
that it is the same sample, whose rho reads higher than the
exact one (its heat map and its reference share the sample's errors), so
there the target is ``min_heat_rho`` plus the margin :data:`MARGINS` gives
that sample's ``scaling`` (how far its measure reads high depends on the
estimator: 0.04 for a plain sample, 0.02 for a linearly scaled one). A heat map
whose sample is spread (``heat_sampling: spread``, a systematic sample:
:mod:`g2s_plugins.traffic`) is ranked there instead against the mean of its
sample and an independent one (:func:`second_sample`), with the margin
:data:`POOLED_MARGINS`. A structure that
meets it there is confirmed (:func:`confirm`) with a second sample of as
many sources (:func:`second_sample`): errors independent of the heat
map's lower a rank correlation instead of raising it, and Spearman's
correction for attenuation (C. Spearman, Am. J. Psychol. 15(1):72-101,
1904) estimates the rho against the exact flow from the two samples; when
that estimate is under ``min_heat_rho`` the run warns with the figures.
The confirmation changes no structure. Why not Hoeffding:
:func:`~g2s_plugins.traffic.flow_error_bound` bounds each node's error by
0.10 of all pair weight at 256 sources, more than the flow of the busiest
polygon of a level (about 0.02 of it on nav_test), so it orders no two
polygons and bounds no rank correlation; the margin is measured instead
(docs/analysis_quality.md, "A guaranteed heat map").

The mechanism, a Douglas-Peucker tolerance for the heat map (D. H.
Douglas and T. K. Peucker, Cartographica 10(2):112-122, 1973, keep the
point farthest from the simplified line until every point is within the
tolerance): Algorithm 4 simplifies as it always does and the result is
measured. While rho is under the target, of the removed nodes whose own
polygon's percentile differs from the heat the map gives it by more than
:data:`FLOOR` points, those whose return would lower the heat map's squared
error most (:func:`restore_gains`: the nodes each would take over, their
new heat and that of the cells they leave) are restored (both on the heat
map's sampled scale, so the exact flow decides when to stop, not which
nodes come back, and a structure changes only where that decision does;
with ``heat_rho_within_areas`` the percentiles within the node's connected
area and the heat drawn from them, the same on a graph of one area),
:data:`RESTORED_SHARE` of the forest's nodes at a time, or, where that many read the target (read with the
last structure's nodes, before simplifying), the fewest of them that do, found by bisection (:func:`_fewest_meeting`):
the forest is simplified again by the same
predicate, which now keeps them and every node the last structure kept
(:func:`keeping`), so each round's structure holds the last one's; with
``heat_rounds_keep: restored``, them and the nodes restored in earlier rounds
only, the predicate deciding the others again: a node kept because its
chain's ends did not see each other goes where a restored node now ends that
chain and sees past it (docs/analysis_quality.md, "Restored nodes that end
a chain (7 December 2026)"). A
structure that meets the target is the one Algorithm 4 gave, unchanged;
when no removed node differs by more than the floor and rho is still
under the target, the last structure is kept with a warning that says so.

Restoring gives back at most the whole forest, so where the forest's own
heat map reads under the target no round meets it, and just over it only
nearly the whole forest does. The loop adder
(``loops.params.min_heat_rho`` of ``spanner``) reads that before rooting
and, where it reads under the target plus a headroom, joins the nodes the
forest's heat map ranks worst to it (:func:`spurs`), the same measure and
floor; Algorithm 4 never removes a leaf, so each spur's end stays in the
structure.

Complexity: a round is one simplification (its predicate calls) and one
measure (a multi-source Dijkstra over the initial graph, O(m + n log n),
and two sorts), and under the target one more multi-source Dijkstra and a
sort to rank the candidates (:func:`restore_gains`) and one more measure of the round's nodes before simplifying,
1 + ceil(log2 k) in the round whose k nodes read the target (:func:`_fewest_meeting`); each round but the last
restores ceil(share x forest nodes) nodes, so there are at most 1 / :data:`RESTORED_SHARE` + 1 of them.
A structure that meets the target costs one measure, and above the exact
size one more sampled walking flow (the confirmation's, once per run; a
spread heat map's second sample from the first round on, which in
``map_analysis_sampling`` is the cover's flow, computed already), begun on a
thread of its own once step 2 has run (:func:`begin_ahead`, the predicate
plugins' ``g2s_begin_ahead``; at the latest as the first simplification starts,
:func:`begin_second_sample`), so that it takes the core that the Python of
steps 3-4 leaves idle. The exact flow is
computed once per run, on the first measure: O(n (m + n log n)), 0.02-0.13 s
of CPU on levels of 700-1,400 polygons, 0.18 s at 1,974.
"""

from __future__ import annotations

import dataclasses
import math
import weakref
from collections.abc import Callable, Hashable, Iterable

import numpy as np

from g2s_core.lazy import lazy_module
from g2s_core.model import RunContext
from g2s_plugins import evaluation, traffic
from g2s_plugins._surface import CollapseParams

csgraph = lazy_module("scipy.sparse.csgraph")
nx = lazy_module("networkx")

Predicate = Callable[["nx.DiGraph", int, int, int], bool]

RESTORED_SHARE = 0.02
"""Forest nodes restored per round, as a share of the forest's nodes."""

MARGINS: dict[traffic.Scaling, float] = {"none": 0.04, "linear": 0.02}
"""Rho above ``min_heat_rho`` a structure must reach when the graph has more than
:data:`g2s_plugins.traffic.EXACT_NODES` nodes with an area, measured against the run's own 256-source walking flow
rather than the exact one, by that flow's ``scaling``. Measured, not bounds: a level where the gap is larger gets
less than it asked for, and a structure that meets its target is confirmed against another sample
(:func:`confirm`), which warns where the estimate is under ``min_heat_rho`` ("An honest guarantee on grids").

``none``: the most by which that measure exceeded the rho against the exact flow (split ties, the evaluation's
reference), rounded up: 0.0346 on the castle of seed 1 of ``benchmarks/analysis_quality.py``'s ``castle_20k``
(21,292 polygons), whose structure met the margin 0.03 of before with 0.899 against the exact flow; 0.0325 on seed 0,
0.0321 on seed 2, 0.0063-0.0073 on the 20k dungeons, 0.0134-0.0150 on the 20k terrains (seeds 0-2) and 0.0124 on
the 20k building of seed 0 (docs/analysis_quality.md, "The guarantee's margin on 20k levels (6 December 2026)").
The 0.03 of before was 0.027 on 50 levels of 273-12,854 polygons rounded up ("A guaranteed heat map"), none of them
a 20k castle. On the sampling route's grid with split ties a plain sample's gap reached 0.049 on the held-out kinds
and the bunker kept 0.873 against the exact flow ("The guarantee's sample on grids").

``linear`` (the sample linearly scaled, as ``map_analysis_sampling`` draws it: each sampled source's pairs count on
a node in proportion to how far along their path it lies, which removes the plain sample's overcount round its
sources): the most by which that measure exceeded the rho against the exact flow at any structure the guarantee
measured (every round of every run), 0.0175 over 498 measures on 50 grid levels of 2,304-25,487 samples
(the islets, whose islands out of reach split the graph; 0.0097 the next, the cave; docs/analysis_quality.md, "The
sampling preset with linear scaling on every held-out kind"), rounded up. There mine and museum still end at the
floor (0.9078 and 0.9097 by their own measure, 0.905 and 0.909 exact)."""

POOLED_MARGINS: dict[traffic.Scaling, float] = {"linear": 0.009}
"""Rho above ``min_heat_rho`` a structure must reach when its heat map's sample is drawn spread (``heat_sampling:
spread``) and the graph has more than :data:`g2s_plugins.traffic.EXACT_NODES` nodes with an area, read against the
pooled sample: the heat map, drawn from its own sample, ranked against the mean of that sample and the independent
sample of the same sources, seed, ties and scaling (:func:`second_sample`: the one a traffic-aware ``coverage`` of
those settings computed already), so that it shares half its errors with its reference instead of all of them.
Measured, not a bound: the most by which that reading exceeded the rho against the exact flow at any structure the
guarantee measured (every round of ``map_analysis_sampling``'s runs with the margin 0.01, which go on past this
margin's), 0.0081 over 349 measures on 54 grid levels of 2,304-25,487 samples with an exact flow (the helix; 0.0076
the cave, 0.0027 the islets, at most 0.0016 elsewhere), rounded up (docs/analysis_quality.md, "A heat map with less
noise on the sampling route"). Only ``linear`` is measured."""

CONFIRMING_SEED = 1
"""Seed of the sample that confirms an independently drawn sampled heat map that met its target (:func:`confirm`):
not 0, the seed of the heat map's own sample (the ``flow`` analyzer's default ``seed``), so that the two samples'
errors are independent. A spread heat map is confirmed by the independent sample of its own seed instead
(:func:`second_sample`)."""

SPUR_SHARE = 0.01
"""Nodes :func:`spurs` joins to the forest per round, as a share of the graph's nodes."""

HALVINGS = 4
"""Bisection steps :func:`_fewest_meeting` takes at most: the last round restores at most 1/16 of its share more than
the fewest that read the target (to the node on the small levels, whose rounds restore 20-35 nodes), for at most five
readings (about 0.5 s of CPU on the 20k dungeon, whose step 5 takes 9-12 s: docs/analysis_quality.md, "The sampling
route's first structure (7 December 2026)")."""

FLOOR = 10.0
"""Percentile points: a removed node whose polygon's walking-flow percentile differs from the heat the map gives it
by no more than this is never restored (the smallest ``max_traffic_step`` measured, docs/analysis_quality.md)."""


def restored(
    graph: nx.Graph, forest: nx.DiGraph, simplified: nx.DiGraph, min_rho: float, context: RunContext,
    sources: int = traffic.WALKING_SOURCES, ties: traffic.Ties = traffic.WALKING_TIES,
    scaling: traffic.Scaling = traffic.WALKING_SCALING, sampling: traffic.Sampling = traffic.WALKING_SAMPLING,
    within_areas: bool = False,
) -> set[Hashable] | None:
    """The nodes the next simplification of ``forest`` must keep, or ``None`` when ``simplified`` is kept.

    ``None`` when the heat map of ``simplified`` ranks the nodes of
    ``graph`` (the run's initial graph) with rho >= ``min_rho`` against
    their exact walking flow (up to :data:`~g2s_plugins.traffic.EXACT_NODES`
    nodes with an area; above, rho >= ``min_rho`` + ``MARGINS[scaling]``
    against the heat map's own flow of ``sources`` sampled sources counted as
    ``scaling`` says, then :func:`confirm`-ed by another sample; both of
    ``ties``), or rho is undefined (every node's flow alike), or
    no removed node differs by more than :data:`FLOOR` (a warning gives rho);
    else every node of ``simplified`` and, of the removed nodes of ``forest``
    whose percentile differs from their heat by more than :data:`FLOOR`, those
    whose return lowers the heat map's squared error most
    (:func:`restore_gains`), by decreasing gain then node id: ceil(:data:`RESTORED_SHARE` x the forest's nodes) of
    them, or the fewest of those whose heat map reads the target (:func:`_fewest_meeting`).

    ``within_areas``: rho is :func:`~g2s_plugins.evaluation.within_area_rho` over the connected areas of ``graph``
    instead (docs/analysis_quality.md, "The heat map within each connected area"), and a removed node's
    difference and gain are between its flow's percentile within its area
    (:func:`~g2s_plugins.evaluation.within_area_percentiles`, the scale that rho ranks the flow on) and the heat the
    map gives it when drawn from those percentiles: a heat right across areas and wrong within one is what that rho
    counts. On a graph of one area both are the level-wide ones, so the same nodes come back. Above the exact size the
    margin and the confirmation are those measured for the level-wide rho.
    """
    areas = evaluation.area_labels(graph) if within_areas else None
    reading = heat_reading(graph, simplified, sources, ties, scaling, sampling, areas)
    arrays, shown, heat, rho, margin = reading.arrays, reading.shown, reading.heat, reading.rho, reading.margin
    exact, pooled, order = reading.exact, reading.pooled, reading.order
    if not rho < min_rho + margin:
        if not exact and not math.isnan(rho):  # NaN: every node's flow alike, nothing to confirm
            confirm(heat, shown, rho, min_rho, context, arrays, sources, ties, scaling, order)
        return None
    removed, removed_rows = _removed(arrays, forest, reading.rows)
    if areas is None:
        own, given = reading.own, heat
    else:  # the flow's percentiles within each area, as rho within areas ranks it, and the heat drawn from them
        own, given = (evaluation.within_area_percentiles(shown, areas),
                      evaluation.placement_heat(graph, simplified, shown, reading.nearest, areas))
    difference = np.abs(own - given)[removed_rows]
    above = difference > FLOOR  # NaN (a node reaching no structure node) is not
    if not above.any():
        measure = ("walking flow" if exact else f"the mean walking flow of a spread and an independent sample of {sources} sources"
                   if pooled else f"walking flow from {sources} sampled sources")
        wanted = f"min_heat_rho {min_rho:g}" + ("" if exact else f" plus the margin {margin:g} a sampled flow needs")
        within = " within each connected area" if areas is not None else ""
        context.warn(f"the heat map ranks the polygons with Spearman rho{within} {rho:.3f} against {measure}, "
                     f"under {wanted}: no node simplification removed differs from the heat it is given by more than "
                     f"{FLOOR:g} percentile points{' within its area' if within else ''}")
        return None
    candidates = removed_rows[above]
    gain = restore_gains(arrays, reading.distance, reading.nearest, own, candidates)
    ranked = removed[above][np.lexsort((removed[above], -gain))]
    count = math.ceil(RESTORED_SHARE * forest.number_of_nodes())
    previous, _LAST_RHO[forest] = _LAST_RHO.get(forest), rho
    if previous is None or rho + (rho - previous) >= min_rho + margin:  # this round may be the last
        count = _fewest_meeting(graph, set(simplified), ranked[:count].tolist(), min_rho + margin, sources, ties,
                                scaling, sampling, areas)
    return set(simplified) | set(ranked[:count].tolist())


def _fewest_meeting(graph: nx.Graph, structure: set[Hashable], ranked: list[Hashable], target: float,
                    sources: int, ties: traffic.Ties, scaling: traffic.Scaling, sampling: traffic.Sampling,
                    areas: np.ndarray | None) -> int:
    """How many of a round's ``ranked`` nodes (k, best first) to restore: the fewest whose heat map, with the nodes of
    ``structure`` (the round's structure, under ``target`` by the guarantee's reading, :func:`heat_reading`), reads
    ``target`` or more, found by bisection to within k / 2^:data:`HALVINGS` of them; all k when even all of them
    read under it.

    The reading is of the nodes alone, before the forest is simplified again: that simplification keeps them and the
    structure's nodes and, measured, nothing more, so the round's structure is what was read and the guarantee's
    measure of it confirms it (or, where the simplification keeps more and reads under, asks for another round);
    with ``heat_rounds_keep: restored`` it may keep fewer of the structure's nodes, and the same measure decides.
    Why: a round restores a fixed share of the forest, and the last one overshoots the target by up to that share of
    the nodes (docs/analysis_quality.md, "The sampling route's first structure (7 December 2026)"); Douglas and
    Peucker's rule adds one point at a time, the rounds a share at a time only for speed.

    :func:`restored` asks only in a round that may be the last: the first, and any whose rho, raised again by as
    much as the last round raised it, would read the target (later rounds raise rho less, docs/analysis_quality.md,
    "The heat guarantee's restore choice"); elsewhere a round restores all k, as before.

    Complexity: one reading (a multi-source Dijkstra and two sorts, O(m + n log n)) where even all k read under the
    target, at most 1 + :data:`HALVINGS` where they read it; a simplification would cost each of them (on the 20k
    dungeon a reading is about 0.1 s of CPU, a round 0.7-1.1 s).
    """

    def meets(count: int) -> bool:
        reading = heat_reading(graph, structure | set(ranked[:count]), sources, ties, scaling, sampling, areas)
        return not reading.rho < target

    if len(ranked) <= 1 or not meets(len(ranked)):
        return len(ranked)
    fail, meet = 0, len(ranked)  # the structure alone reads under the target; all k read it
    for _ in range(HALVINGS):
        if meet - fail <= 1:
            break
        middle = (fail + meet) // 2
        fail, meet = (fail, middle) if meets(middle) else (middle, meet)
    return meet


def restore_gains(arrays: traffic.SurfaceArrays, distance: np.ndarray, nearest: np.ndarray, own: np.ndarray,
                  candidates: np.ndarray) -> np.ndarray:
    """(k,) how much restoring each of the (k,) ``candidates`` (rows of ``arrays``, removed nodes) would lower the
    heat map's squared error: the sum over the nodes of the graph of (own percentile - heat)², in percentile points².

    A restored node takes over the nodes nearer to it along the graph than to their nearest structure node
    (``nearest``, (n,) rows, -1: none, at (n,) ``distance`` metres: :func:`~g2s_plugins.traffic.distance_to` of the
    structure); the heat map gives them the mean of (n,) ``own`` over them, and each structure node whose cell they
    leave the mean of the rest. With a cell's error ``Q - S² / N`` (``Q`` the sum of squares of ``own``, ``S`` its
    sum, ``N`` its nodes), the gain of a candidate that takes the nodes of sum ``S_rs``, count ``N_rs`` from each
    structure node ``s`` is ``S_r² / N_r + Σ_s [(S_s - S_rs)² / (N_s - N_rs) - S_s² / N_s]`` (a structure node stays
    in its own cell, so ``N_s - N_rs >= 1``): the within-group sum of squares of Ward's clustering (J. H. Ward,
    J. Am. Stat. Assoc. 58(301):236-244, 1963), which a split lowers. Which nodes a candidate would take is read from
    one multi-source Dijkstra search from all candidates (each node counted for its nearest candidate alone): several
    restored in one round share the nodes between them. Why: a node whose own percentile is far from its heat may
    stand for one sample; the largest difference alone restores it before a node that would mend twenty
    (docs/analysis_quality.md, "The heat guarantee's restore choice").

    Complexity: one multi-source Dijkstra search, O(m + n log n), and a sort of the (candidate, structure node)
    pairs, O(n log n).
    """
    gain = np.zeros(len(candidates))
    if len(candidates) == 0:
        return gain
    to_candidate, closest = traffic.distance_to(arrays, candidates)
    taken = np.flatnonzero((closest >= 0) & (nearest >= 0) & (to_candidate < distance))
    if taken.size == 0:
        return gain
    own = np.asarray(own, dtype=np.float64)
    cell_sum, cell_count = traffic.gathered(nearest, own), np.bincount(nearest[nearest >= 0], minlength=arrays.n)
    index = np.full(arrays.n, -1, dtype=np.int64)
    index[candidates] = np.arange(len(candidates))
    taker, giver = index[closest[taken]], nearest[taken]
    pairs, pair_of = np.unique(taker * arrays.n + giver, return_inverse=True)
    pair_sum = np.bincount(pair_of, weights=own[taken])
    pair_count = np.bincount(pair_of).astype(np.float64)
    pair_taker, pair_giver = pairs // arrays.n, pairs % arrays.n
    left_sum, left_count = cell_sum[pair_giver] - pair_sum, cell_count[pair_giver] - pair_count
    change = left_sum ** 2 / left_count - cell_sum[pair_giver] ** 2 / cell_count[pair_giver]
    taken_sum = np.bincount(pair_taker, weights=pair_sum, minlength=len(candidates))
    taken_count = np.bincount(pair_taker, weights=pair_count, minlength=len(candidates))
    gain += np.bincount(pair_taker, weights=change, minlength=len(candidates))
    has = taken_count > 0
    gain[has] += taken_sum[has] ** 2 / taken_count[has]
    return gain


def _removed(arrays: traffic.SurfaceArrays, forest: nx.DiGraph, structure_rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(k,) int64 the ids of the nodes of ``forest`` whose rows of ``arrays`` (the run's initial graph, which holds
    every forest node) are not among the (s,) ``structure_rows``, ascending, and (k,) their rows. O(n log n) in
    numpy's loops (a Python test of each forest node against the structure graph: 17 ms a round on a 20k-polygon
    level's forest of 75k nodes)."""
    ids = np.fromiter(forest, np.int64, forest.number_of_nodes())
    rows = arrays.rows(ids.tolist())
    kept = np.zeros(arrays.n, dtype=bool)
    kept[structure_rows] = True
    gone = np.flatnonzero(~kept[rows])
    ascending = gone[np.argsort(ids[gone], kind="stable")]
    return ids[ascending], rows[ascending]


@dataclasses.dataclass(frozen=True)
class HeatReading:
    """How a structure's heat map ranks the nodes of a run's initial graph, as the guarantee reads it.

    ``arrays``: the graph's :func:`~g2s_plugins.traffic.surface_arrays`; ``shown`` (n,) the heat map's walking flow;
    ``heat`` (n,) the heat map (:func:`~g2s_plugins.evaluation.placement_heat` of ``shown``); ``rho`` its Spearman
    rho against the reference (the exact flow when ``exact``, the mean of ``shown`` and :func:`second_sample` when
    ``pooled``, else ``shown`` itself); ``margin`` the rho over a target that reading must reach (:data:`MARGINS`,
    :data:`POOLED_MARGINS`, 0 when exact); ``order`` the sample's :func:`~g2s_plugins.traffic.sampling_order`;
    ``own`` (n,) :func:`~g2s_plugins.traffic.percentile` of ``shown``; ``rows`` (s,) the structure nodes' rows,
    by ascending id; ``nearest`` (n,) each node's nearest structure node's row (-1: none) and ``distance`` (n,) metres
    to it along the graph (``inf``: none)."""

    arrays: traffic.SurfaceArrays
    shown: np.ndarray
    heat: np.ndarray
    rho: float
    margin: float
    exact: bool
    pooled: bool
    order: np.ndarray | None
    own: np.ndarray
    rows: np.ndarray
    nearest: np.ndarray
    distance: np.ndarray


@dataclasses.dataclass(frozen=True)
class _Flows:
    """What :func:`heat_reading` reads of a graph's walking flows for one setting, the same for every structure:
    :class:`HeatReading`'s fields of those names, and ``reference`` the flow rho is read against."""

    order: np.ndarray | None
    shown: np.ndarray
    own: np.ndarray
    reference: np.ndarray
    exact: bool
    pooled: bool
    margin: float


def _flows(graph: nx.Graph, arrays: traffic.SurfaceArrays, sources: int, ties: traffic.Ties, scaling: traffic.Scaling,
           sampling: traffic.Sampling) -> _Flows:
    """:class:`_Flows` of ``graph`` (its ``arrays``), computed once per graph and setting and kept with its arrays:
    the guarantee reads them in every round, where the percentiles' sort and the look-ups of the arrays cost about as
    much as that round's Dijkstra search on the sampling route (a 20k-polygon level, docs/performance.md)."""
    key = ("heat reading", sources, ties, scaling, sampling, traffic.EXACT_NODES)  # the size read exactly decides too
    if key not in arrays.derived:
        order = traffic.sampling_order(graph, sampling)
        shown = traffic.arrays_walking_flow(arrays, sources, ties=ties, scaling=scaling, order=order)  # the heat map's
        exact = traffic.is_exact(arrays, sources, traffic.EXACT_NODES)
        pooled = not exact and sampling == "spread"
        if pooled:  # half the heat map's errors shared with its reference instead of all of them
            reference = (shown + second_sample(arrays, sources, ties, scaling, order)) / 2.0
        else:  # exact: the evaluation's reference, whose ties split whatever the heat map's do; else the heat map's
            reference = traffic.arrays_walking_flow(arrays, sources, exact_up_to=traffic.EXACT_NODES,
                                                    ties=evaluation.REFERENCE_TIES if exact else ties, scaling=scaling)
        margin = 0.0 if exact else POOLED_MARGINS[scaling] if pooled else MARGINS[scaling]
        arrays.derived[key] = _Flows(order, shown, traffic.percentile(shown), reference, exact, pooled, margin)
    return arrays.derived[key]


def heat_reading(
    graph: nx.Graph, structure_nodes: Iterable[Hashable], sources: int, ties: traffic.Ties, scaling: traffic.Scaling,
    sampling: traffic.Sampling, areas: np.ndarray | None = None,
) -> HeatReading:
    """The guarantee's reading of the heat map of ``structure_nodes`` over ``graph`` (the run's initial graph), whose
    walking flow is of ``sources``, ``ties``, ``scaling`` and ``sampling``; with (n,) ``areas``
    (:func:`~g2s_plugins.evaluation.area_labels`) rho within each area. One multi-source Dijkstra and two sorts, once
    the flows are computed (each once per graph, :func:`_flows`)."""
    arrays = traffic.surface_arrays(graph)
    flows = _flows(graph, arrays, sources, ties, scaling, sampling)
    rows = arrays.rows(sorted(structure_nodes))
    distance, nearest = traffic.distance_to(arrays, rows)
    heat = evaluation.nearest_mean(nearest, flows.own)  # evaluation.placement_heat of the flow shown
    reference = flows.reference
    rho = evaluation.spearman(heat, reference) if areas is None else evaluation.within_area_rho(heat, reference, areas)
    return HeatReading(arrays, flows.shown, heat, rho, flows.margin, flows.exact, flows.pooled, flows.order, flows.own,
                       rows, nearest, distance)


def spurs(
    graph: nx.Graph, forest_nodes: Iterable[Hashable], min_rho: float, headroom: float,
    sources: int = traffic.WALKING_SOURCES, ties: traffic.Ties = traffic.WALKING_TIES,
    scaling: traffic.Scaling = traffic.WALKING_SCALING, sampling: traffic.Sampling = traffic.WALKING_SAMPLING,
) -> list[list[Hashable]]:
    """Paths of ``graph`` (the run's initial graph) from the nodes the heat map of ``forest_nodes`` ranks worst to
    the forest, when that heat map, every node of the forest kept, reads under the guarantee's target
    (``min_rho`` plus the reading's margin, :func:`heat_reading`) plus ``headroom``. Then, round by round, the
    nodes outside the forest whose own percentile of the heat map's flow differs most from the heat they are given
    (by more than :data:`FLOOR` points; by decreasing difference, then row), ceil(:data:`SPUR_SHARE` x the graph's
    nodes) of them, are joined to it by their shortest paths to its nearest node, until the reading reaches the
    target plus ``headroom`` or no node differs by more than the floor. Empty when the forest reads the target plus
    ``headroom``. Each path runs from a forest node out; the paths of one round are branches of one shortest-path
    tree, so they add no loop.

    Why: under the target no simplification of the forest can meet it, since restoring removed nodes gives back at
    most the whole forest: on a level whose walking flow steps by 50 percentile points or more between
    neighbouring nodes (a line of through traffic across a small platform, its dead-end sides beside it), a
    structure node on the line stands for the quiet nodes beside it, and no node of the forest sits there
    (docs/analysis_quality.md, "Spurs where the heat map ranks worst"). Just over the target the guarantee can meet
    it only by giving back nearly the whole forest: behind a wall with gaps (vine rows, double doors, galleries)
    the flow runs as a busy line from gap to gap beside quiet floor, and the forest's paths cross both, so its
    removed nodes each mend little; the spurs reach the samples ranked worst, and as leaves they stay
    (docs/analysis_quality.md, "Walls with gaps on the sampling route").

    Complexity: per round one multi-source Dijkstra for the paths and one reading, O(m + n log n); each round adds
    at least one node.
    """
    nodes = set(forest_nodes)
    reading = heat_reading(graph, nodes, sources, ties, scaling, sampling)
    target = min_rho + reading.margin
    if not reading.rho < target + headroom:
        return []
    arrays, paths, own = reading.arrays, [], reading.own
    while reading.rho < target + headroom:
        rows = arrays.rows(sorted(nodes))
        _, predecessor, _ = csgraph.dijkstra(arrays.adjacency, directed=False, indices=rows, min_only=True,
                                             return_predecessors=True)
        difference = np.abs(own - reading.heat)
        difference[rows] = np.nan
        outside = np.flatnonzero(difference > FLOOR)  # NaN (the forest's own nodes, nodes reaching none) is not
        if outside.size == 0:
            break
        for row in outside[np.lexsort((outside, -difference[outside]))][:math.ceil(SPUR_SHARE * arrays.n)].tolist():
            if arrays.nodes[row] in nodes:  # on a path this round added
                continue
            path = [row]
            while predecessor[path[-1]] >= 0 and arrays.nodes[path[-1]] not in nodes:
                path.append(int(predecessor[path[-1]]))
            path_nodes = [arrays.nodes[r] for r in reversed(path)]
            paths.append(path_nodes)
            nodes.update(path_nodes)
        reading = heat_reading(graph, nodes, sources, ties, scaling, sampling)
    return paths


def confirm(
    heat: np.ndarray, shown: np.ndarray, rho: float, min_rho: float, context: RunContext,
    arrays: traffic.SurfaceArrays, sources: int, ties: traffic.Ties, scaling: traffic.Scaling = traffic.WALKING_SCALING,
    order: np.ndarray | None = None,
) -> None:
    """Warn unless (n,) ``heat``, a heat map drawn from ``shown`` (the walking flow of ``sources`` sampled sources,
    which ranks it with ``rho``), is estimated to rank the nodes with rho >= ``min_rho`` against the exact walking
    flow (``ties`` and ``scaling`` throughout; ``order``: the sample's :func:`~g2s_plugins.traffic.sampling_order`).

    The estimate: rho against ``other``, the flow of as many sources of :func:`second_sample`, divided by
    the square root of the two samples' own rho (their reliability): Spearman's correction for attenuation. Against
    its own sample the heat map reads high (they share the sample's errors), against ``other`` low (errors the heat
    map does not share lower a correlation); the correction removes the second bias (within 0.007 of the exact rho
    on 10 grid levels, docs/analysis_quality.md, "An honest guarantee on grids"). It takes the two samples to be
    equally reliable; a spread sample is the more reliable (its errors are smaller), so against an independent
    ``other`` the square root divides by more than ``other``'s own attenuation and the estimate reads low: a
    warning errs on the side of saying so. One more sampled walking flow, unless ``other`` was computed already.
    """
    other = second_sample(arrays, sources, ties, scaling, order)
    against_other, reliability = evaluation.spearman(heat, other), evaluation.spearman(shown, other)
    if math.isnan(against_other):  # every node's flow alike
        return
    estimate = against_other / math.sqrt(reliability) if reliability > 0 else math.nan
    if not estimate >= min_rho:
        said = (f"about {estimate:.3f} against the exact walking flow (corrected for the second sample's errors), "
                f"under min_heat_rho {min_rho:g}" if reliability > 0 else "the samples disagree, so nothing confirms "
                f"min_heat_rho {min_rho:g} (more heat_sources make them agree)")
        context.warn(f"the heat map ranks the polygons with Spearman rho {rho:.3f} against the walking flow of the "
                     f"sample of {sources} sources it is drawn from, but {against_other:.3f} against another sample "
                     f"of {sources}, whose own rho with the first is {reliability:.3f}: {said}")


def second_sample(
    arrays: traffic.SurfaceArrays, sources: int, ties: traffic.Ties, scaling: traffic.Scaling, order: np.ndarray | None,
) -> np.ndarray:
    """(n,) the walking flow whose errors are independent of the heat map's sample (``order``: that sample's
    :func:`~g2s_plugins.traffic.sampling_order`): for an independent sample, as many sources drawn with
    :data:`CONFIRMING_SEED`; for a spread one, the independent sample of seed 0, which the spread sample's start is
    drawn independently of (:func:`~g2s_plugins.traffic.walking_sources`) and which a traffic-aware ``coverage`` of
    the same ``sources``, ``ties`` and ``scaling`` computed already (so a run of ``map_analysis_sampling`` walks no
    more sampled flows than with independent samples)."""
    return traffic.arrays_walking_flow(arrays, sources, seed=_second_seed(order), ties=ties, scaling=scaling)


def _second_seed(order: np.ndarray | None) -> int:
    """The seed of :func:`second_sample` for a heat map whose sample's order is ``order``."""
    return CONFIRMING_SEED if order is None else 0


def begin_second_sample(graph: nx.Graph, sources: int, ties: traffic.Ties, scaling: traffic.Scaling,
                        sampling: traffic.Sampling) -> None:
    """Begin :func:`second_sample`'s walking flow on a thread of its own
    (:func:`~g2s_plugins.traffic.start_walking_flow`) when the heat map of ``graph`` is a sample (more nodes with
    an area than :data:`~g2s_plugins.traffic.EXACT_NODES`), once step 2 has run (:func:`begin_ahead`) or as the first
    simplification is about to start: it runs on the core that steps 3-4 (their Python) or that simplification (its
    Python, the structure built back, the first measure) leave idle.
    Its CPU is spent for nothing only when no round meets the target (:func:`restored`'s warning at the floor)."""
    arrays = traffic.surface_arrays(graph)
    if not traffic.is_exact(arrays, sources, traffic.EXACT_NODES):
        traffic.start_walking_flow(arrays, sources, seed=_second_seed(traffic.sampling_order(graph, sampling)),
                                   ties=ties, scaling=scaling)


def begin_ahead(params: CollapseParams, context: RunContext) -> None:
    """What a predicate plugin with ``params.min_heat_rho`` begins ahead (its ``g2s_begin_ahead``,
    :mod:`g2s_core.hookspecs`, which the pipeline asks for once step 2 has run): :func:`begin_second_sample` of its
    heat map's settings, so that the confirming flow runs beside steps 3-4, whose Python leaves a core idle, instead
    of beside step 5's. Nothing without a guarantee or a graph."""
    if params.min_heat_rho is not None and context.graph is not None:
        begin_second_sample(context.graph, params.heat_sources, params.heat_ties, params.heat_scaling,
                            params.heat_sampling)


def keeping(predicate: Predicate, kept: set[Hashable]) -> Predicate:
    """``predicate``, except that a node of ``kept`` is never removed; its whole-forest path
    (:mod:`g2s_core.simplify`) too, where it has one, given those nodes as fixed ones."""

    def keep(tree: nx.DiGraph, a: int, b: int, c: int) -> bool:
        return b not in kept and predicate(tree, a, b, c)

    whole_forest = getattr(predicate, "whole_forest", None)
    if whole_forest is not None:
        fixed = np.fromiter(kept, np.int64, len(kept))
        keep.whole_forest = lambda forest: whole_forest(  # type: ignore[attr-defined]
            dataclasses.replace(forest, fixed=forest.fixed | np.isin(forest.ids, fixed)))
    return keep


def guaranteed(
    make_predicate: Callable[[], Predicate], params: CollapseParams, context: RunContext, forest: nx.DiGraph | None,
    simplified: nx.DiGraph | None,
) -> Predicate | None:
    """What a predicate hook returns with ``params.min_heat_rho`` (the hookspec's ``simplified`` protocol): the
    predicate of ``make_predicate`` first, then, after each structure, ``None`` to keep it or that same predicate
    keeping the nodes of :func:`restored` (its walking flow: ``params.heat_sources``, ``params.heat_ties`` and
    ``params.heat_scaling``; its rho within areas with ``params.heat_rho_within_areas``), or with
    ``params.heat_rounds_keep`` ``restored`` only the nodes it gave back in this round and every earlier one."""
    if simplified is None:
        predicate = make_predicate()
        if forest is not None:  # None: asked outside the pipeline, for one predicate
            _FIRST[forest] = predicate
            _LAST_RHO.pop(forest, None)
            _RESTORED.pop(forest, None)
            begin_ahead(params, context)  # begun already when the pipeline asked for it after step 2
        return predicate
    if params.min_heat_rho is None:
        return None
    kept = restored(context.graph, forest, simplified, params.min_heat_rho, context, params.heat_sources,
                    params.heat_ties, params.heat_scaling, params.heat_sampling, params.heat_rho_within_areas)
    if kept is None or params.heat_rounds_keep == "structure":
        return None if kept is None else keeping(_FIRST[forest], kept)
    # every round adds at least one removed node to what it restored, so the rounds end as the other way's do
    _RESTORED[forest] = _RESTORED.get(forest, set()) | (kept - set(simplified))
    return keeping(_FIRST[forest], _RESTORED[forest])


_LAST_RHO: weakref.WeakKeyDictionary[nx.DiGraph, float] = weakref.WeakKeyDictionary()
"""The guarantee's reading of each forest's last structure under its target (:func:`restored`), forgotten as its
first simplification begins (:func:`guaranteed`)."""

_RESTORED: weakref.WeakKeyDictionary[nx.DiGraph, set[Hashable]] = weakref.WeakKeyDictionary()
"""The nodes the guarantee has restored into each forest's structure so far (:func:`guaranteed`), forgotten as its
first simplification begins."""

_FIRST: weakref.WeakKeyDictionary[nx.DiGraph, Predicate] = weakref.WeakKeyDictionary()
"""The predicate each forest was first simplified with, asked again in the later rounds: its answers depend on the
chain's nodes alone, and its caches (ray casters, walks, normal tests) hold for every round."""
