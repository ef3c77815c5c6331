"""Flow: area-weighted origin-destination walking flow on the navmesh, carried onto the structure.

Walkers go between every pair of polygons (or graph nodes), drawn in
proportion to their areas, along the shortest path of the *initial* graph
(space syntax's "choice" weighted by area). Each polygon belongs to the
structure node that stands for it (its nearest structure node along the
graph); a structure node's value is the mean through-flow of its polygons
(``aggregate: mean``, the default), their sum (``sum``), or the mean of
their flow's percentile ranks among all polygons, 0-100 (``percentile``).
The mean is a density: a node standing for many polygons does not outrank a
busier node standing for few. The percentile is a density of ranks: one
busy polygon among quiet ones does not lift its node above a node whose
polygons are all fairly busy, which is what a heat map's order should say.
Measured on nav_test and generated dungeons (docs/analysis_quality.md),
against the polygons' own flow, same structures: Spearman 0.89 (sum), 0.94
(mean), 0.96 (percentile) on nav_test; 0.78, 0.83, 0.88 on a 1k-polygon
dungeon.

A pair's equally short paths (``ties``): all its weight along the one the
search settles first (``first``, the default), or split evenly over all of
them (``split``, Brandes's path counts; :mod:`g2s_plugins.traffic`), which
makes the flow of a regular grid of samples, whose path lengths nearly all
tie, independent of node numbering and far less noisy from a sample of
sources (docs/analysis_quality.md, "Walking flow that splits tied paths").
A sampled flow counts each sampled source's pairs whole (``scaling: none``)
or linearly scaled (``linear``: a pair's weight on a node in proportion to
how far along its path the node lies, so the nodes round each sampled
source do not read busy; :mod:`g2s_plugins.traffic`, docs/analysis_quality.md,
"The sampling preset's held-out misses").
A sample draws its sources independently (``sampling: independent``) or
spread along a Hilbert curve over the nodes in plan (``spread``: a
systematic sample, about as close to the exact flow as twice as many
independent sources; :mod:`g2s_plugins.traffic`, docs/analysis_quality.md,
"A heat map with less noise on the sampling route").
A polygon's flow is its own through-flow (``across: node``, the default),
or the trips across a section of the way through it, each counted once
whichever lane it takes (``across: section``: every polygon; ``across:
lanes``: the polygons of a lane, the navmesh route only;
:mod:`g2s_plugins.cross_sections`). Measured against the evaluation's
reference (docs/analysis_quality.md, "Parallel lanes in the heat map"),
neither is the presets' heat map: the reference ranks polygons.
A leaf of the structure whose polygons no walk passes through (their flow
0: a recess, a dent between a rail's posts, where the cover put a terminal)
shows its own value, the bottom of the scale (``dead_ends: own``, the
default), or that of the node it hangs from (``way``). Measured
(docs/analysis_quality.md, "A spine walk's heat"): such leaves are what
reads the beach's promenade cold node by node, and ``way`` lifts it over the
sand, but leaves of zero flow stand in every room's corners too, and the
reference ranks them at the bottom: not the presets' heat map.
The ``min_heat_rho`` and ``max_traffic_step`` of the simplification, and a
traffic-aware ``coverage``, read a walking flow of their own settings
(``heat_sources``/``heat_ties``/``heat_scaling``/``heat_sampling``,
``traffic_sources``/``traffic_ties``/``traffic_scaling``): set them as this
analyzer's, so they measure the heat map the run shows and the flow is
computed once. The cover always draws its sources independently: beside
``sampling: spread`` (``map_analysis_sampling``) its flow is a second one,
which the guarantee's pooled reading takes (:mod:`g2s_plugins.heat_guarantee`).

Exact up to ``max_sources`` nodes, from that many area-sampled sources
above, with the Hoeffding bound of :mod:`g2s_plugins.traffic` (0.10 of all
pair weight per polygon for 256 sources, delta = 0.01; a node's mean is
estimated the same way, each source's term again in [0, A²], so the same
bound holds for it; with ``scaling: linear`` a source's term reaches twice
that range, and the bound doubles). Values are shares of all pair weight (``mean``,
``sum``) or percentiles.
Cost: O(k (m + n log n)) for k sources on the initial graph; ``dead_ends: way`` O(n) more.
"""

from __future__ import annotations

from collections.abc import Hashable, Mapping
from typing import Literal

from pydantic import Field

from g2s_core.errors import PluginError
from g2s_core.lazy import lazy_module
from g2s_core.model import RunContext
from g2s_core.plugin import PluginParams, hookimpl
from g2s_plugins import traffic
from g2s_plugins.decomposition import DecompositionParams

cross_sections = lazy_module("g2s_plugins.cross_sections")  # it imports scipy
nx = lazy_module("networkx")

NAME = "flow"


class Params(PluginParams):
    """Exactness against speed, and how the polygons' flow becomes a node's value."""

    max_sources: int = Field(traffic.WALKING_SOURCES, ge=1, description="graphs with more nodes than this sample this many area-weighted sources")
    seed: int = Field(0, description="seed of the source sample")
    ties: traffic.Ties = Field(
        traffic.WALKING_TIES, description="a pair's equally short paths: first (all its weight along one) or split (evenly over all "
        "of them; for grids of samples, whose path lengths tie)"
    )
    scaling: traffic.Scaling = Field(
        traffic.WALKING_SCALING, description="a sampled source's pairs: none (each pair's whole weight on its path) or "
        "linear (weighted by how far along the path a node lies: no busy ring round each sampled source)"
    )
    sampling: traffic.Sampling = Field(
        traffic.WALKING_SAMPLING, description="how a sample draws its sources: independent (each in proportion to area) "
        "or spread (a systematic sample along a Hilbert curve over the nodes in plan: less noise for as many sources)"
    )
    across: Literal["node", "section", "lanes"] = Field(
        "node", description="each polygon's flow: its own (node); the trips across the way's cross-section through it, "
        "each counted once whichever polygon of the section it crosses (section: so the lanes of a gate line or an "
        "escalator bank and the polygons across a wide slope read as one way); or, for a polygon standing in a lane, "
        "the trips across its lane and the lanes side by side with it, the others keeping their own (lanes; the "
        "navmesh route only); g2s_plugins.cross_sections"
    )
    section_gap: float = Field(
        2.5, gt=0, description="across: section or lanes: stretches of floor along a section at most this far apart "
        "are one way (the barriers between a gate's gaps with the agent's clearance round them), m"
    )
    section_reach: float = Field(
        30.0, gt=0, description="across: section or lanes: a section reaches at most this far either side of a "
        "polygon, m"
    )
    lane_width: float = Field(
        DecompositionParams.model_fields["passage_width"].default, gt=0, description="across: lanes: floor narrower "
        "than this along a section is a lane, in agent diameters (walkable; the regions' passage_width)"
    )
    aggregate: Literal["mean", "sum", "percentile"] = Field(
        "mean", description="a structure node's value: mean (a density) or sum of the through-flow of the polygons it "
        "stands for, or the mean percentile rank (0-100) of their flow"
    )
    dead_ends: Literal["own", "way"] = Field(
        "own", description="a leaf of the structure whose polygons no walk passes through (their flow, `across`'s, is 0: a recess, "
        "a dent between a rail's posts, where the cover put a terminal): its own value (own), the bottom of the "
        "scale, or that of the structure node it hangs from (way: the recess reads as the way it opens onto)"
    )


@hookimpl
def g2s_analyze(structure: nx.Graph, params: Params, context: RunContext) -> Mapping[int, float]:
    """Through-flow of the initial graph, averaged, summed or ranked per structure node."""
    lanes = params.across == "lanes"
    if lanes and context.navmesh is None:  # told before any flow is computed
        raise PluginError("flow: across: lanes needs a navmesh (the navmesh graph builder); this run has none")
    # with sections every polygon's value is its section's: the plain flow (ties, scaling) is only the lanes' rest
    flow = None if params.across == "section" else traffic.walking_flow(
        context.graph, max_sources=params.max_sources, seed=params.seed, ties=params.ties, scaling=params.scaling,
        sampling=params.sampling)
    if params.across != "node":
        flow = cross_sections.walking_across(
            context.graph, flow, params.max_sources, params.seed, params.section_gap, params.section_reach,
            context.agent.height, context.navmesh if lanes else None,
            params.lane_width * 2.0 * context.agent.radius if lanes else None)
    arrays = traffic.surface_arrays(context.graph)
    _, nearest = traffic.distance_to(arrays, arrays.rows(sorted(structure)))  # searched once: dead_ends reads it too
    if params.aggregate == "percentile":
        values = traffic.gather(context.graph, structure, traffic.percentile(flow), mean=True, nearest=nearest)
    else:
        total = traffic.origin_weight(arrays).sum()
        values = traffic.gather(context.graph, structure, flow / max(total**2, 1e-300), mean=params.aggregate == "mean",
                                nearest=nearest)
    if params.dead_ends == "way":
        return dead_ends_as_their_way(structure, values, traffic.gather(context.graph, structure, flow, nearest=nearest))
    return values


def dead_ends_as_their_way(structure: nx.Graph, values: dict[Hashable, float],
                           passing: Mapping[Hashable, float]) -> dict[Hashable, float]:
    """``values`` with each leaf of ``structure`` (one neighbour, edges taken both ways) whose ``passing`` flow is 0
    given its neighbour's value (that neighbour's own, also when it is such a leaf too). O(n)."""
    ways = structure.to_undirected(as_view=True)
    result = dict(values)
    for node in structure:
        if ways.degree(node) == 1 and passing[node] == 0.0:
            result[node] = values[next(iter(ways.neighbors(node)))]
    return result
