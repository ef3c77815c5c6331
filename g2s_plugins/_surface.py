"""The walkable surface as the built-in plugins share it: on-navmesh points and Algorithm 5's collapse rule.

* :func:`on_navmesh`: the one rule deciding whether a point stands on the
  navigation mesh (terminal selectors use it to set a node's ``on_navmesh``).
* :func:`collapse_rule`: the paper's Algorithm 5 (Sec. 3.1.5) as both line-of-
  sight predicates (``surface_los`` over the navmesh, ``mesh_los`` over the
  level mesh) apply it; they differ only in the line-of-sight test they pass.
  With a native rule (:class:`RuleArrays`: both predicates' in C++,
  src/forest_simplify.hpp) the predicate also carries the core's
  whole-forest path.
* :func:`normals_angle_deg`: the normal test.
* :func:`traffic_ranks`: the walking-flow percentile of each node, for the
  rule's optional traffic test (``max_traffic_step``).
* :func:`edge_surface_gaps`: how far every edge of a structure strays above
  or below the navmesh's detail surface
  (:meth:`g2s_plugins.recast.NavMesh.segment_surface_gaps`, the check
  ``surface_los`` adds to Algorithm 5; ``mesh_los`` makes it against the
  level mesh).

Conventions: metres, degrees, Y up.
"""

from __future__ import annotations

import itertools
import math
import operator
from collections.abc import Callable, Hashable, Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Literal, TypeVar

import numpy as np
from pydantic import Field, model_validator
from pydantic_core import PydanticCustomError

from g2s_core.config import AgentConfig
from g2s_core.errors import PluginError
from g2s_core.lazy import lazy_module
from g2s_core.model import NavMesh
from g2s_core.plugin import PluginParams
from g2s_plugins import traffic

nx = lazy_module("networkx")

if TYPE_CHECKING:  # g2s_core.simplify imports scipy (g2s_core.rooted): listing plugins and checking a config need neither
    from g2s_core.simplify import ForestArrays

Vec = Sequence[float]
LineOfSight = Callable[[tuple[float, ...], tuple[float, ...]], bool]

MAX_SURFACE_GAP = 0.4
"""Metres a collapsed edge may pass above or below the walkable surface (default of both LoS predicates).

Measured with ``benchmarks/piece_quality.py`` (docs/entry_exit.md): the edges
simplification makes on the generated pieces, stairs with 0.25 m risers
included, stay within 0.01 m of the surface; the shortcut under the shared
Ramp's ramp strayed 2.42 m. 0.4 m lies between and under the 0.5 m the
structures must never exceed.
"""


class HeatFlowParams(PluginParams):
    """A heat-map target, ``min_heat_rho`` (each plugin says what it does to meet it), and the walking flow it reads:
    the heat map's, as the ``flow`` analyzer computes it (:mod:`g2s_plugins.heat_guarantee`)."""

    min_heat_rho: float | None = Field(
        None, ge=-1, le=1, description="the Spearman rho the heat map must reach against walking flow; null: none"
    )
    heat_sources: int = Field(
        traffic.WALKING_SOURCES, ge=1, description="sources of the walking flow max_traffic_step and min_heat_rho read "
        "(the heat map's): set as the flow analyzer's max_sources"
    )
    heat_ties: traffic.Ties = Field(
        traffic.WALKING_TIES, description="equally short paths in that walking flow (first or split): set as the flow analyzer's ties"
    )
    heat_scaling: traffic.Scaling = Field(
        traffic.WALKING_SCALING, description="that walking flow's sampled pairs (none or linear): set as the flow analyzer's scaling"
    )
    heat_sampling: traffic.Sampling = Field(
        traffic.WALKING_SAMPLING, description="how that walking flow draws its sources (independent or spread): set as "
        "the flow analyzer's sampling"
    )

    @model_validator(mode="after")
    def _pooled_margin_measured(self) -> HeatFlowParams:
        """A spread heat map is read pooled (:data:`g2s_plugins.heat_guarantee.POOLED_MARGINS`), whose margin is
        measured for some scalings only."""
        from g2s_plugins.heat_guarantee import POOLED_MARGINS  # it imports this module

        if self.min_heat_rho is not None and self.heat_sampling == "spread" and self.heat_scaling not in POOLED_MARGINS:
            # pydantic's custom error: a ValueError's words reached the user as "value error, min_heat_rho ..."
            raise PydanticCustomError(
                "pooled_margin", "min_heat_rho with heat_sampling: spread needs heat_scaling {needed} (the guarantee's "
                "margin for a spread heat map is measured for that alone), not {got}",
                {"needed": " or ".join(POOLED_MARGINS), "got": self.heat_scaling})
        return self


class CollapseParams(HeatFlowParams):
    """Algorithm 5's tolerances, the same for both line-of-sight predicates.

    ``max_surface_gap: null`` with ``whole_chain_normals: false`` is the
    paper's Algorithm 5 exactly (configs/map_analysis_paper.yaml).
    """

    normal_tolerance_deg: float = Field(
        10.0, ge=0, le=180, description="largest angle between the normals of A, B and C that still lets B go, degrees"
    )
    whole_chain_normals: bool = Field(
        True, description="compare the normals of A, B and C pairwise; false: A and B only, as the paper does"
    )
    max_surface_gap: float | None = Field(
        MAX_SURFACE_GAP,
        gt=0,
        description="largest height between the segment A -> C and the walkable surface, m; null: no such check (the paper)",
    )
    probe_step: float | None = Field(
        None, gt=0, le=100, description="surface probes along A -> C at most this far apart, m; default agent radius / 2"
    )
    max_traffic_step: float | None = Field(
        None,
        ge=0,
        le=100,
        description="keep B when the walking-flow percentile (0-100) of B differs from A's or C's by more than this, "
        "percentile points; null: no such check",
    )
    min_heat_rho: float | None = Field(
        None,
        ge=-1,
        le=1,
        description="simplify less where the heat map would rank the polygons with a Spearman rho under this against "
        "walking flow: restore removed nodes until it holds (g2s_plugins/heat_guarantee.py); null: no such check",
    )
    heat_rounds_keep: Literal["structure", "restored"] = Field(
        "structure", description="what each later round of min_heat_rho keeps when it simplifies the forest again: "
        "every node of the last structure and the nodes it restores (structure), or only the nodes restored so far "
        "(restored), the predicate deciding the others again, so a node kept because its chain's ends did not see "
        "each other goes where a restored node ends that chain and sees past it"
    )
    heat_rho_within_areas: bool = Field(
        False, description="min_heat_rho reads rho with ranks taken within each connected area (the traffic "
        "evaluator's rho_within), so that an area apart, low in the flow and the heat map as a whole, gets no credit "
        "for that, and chooses the removed nodes it restores on the flow's percentiles within their area and the heat "
        "drawn from those percentiles; false: rho and percentiles over the whole graph"
    )


def on_navmesh(navmesh: NavMesh | None, point: Vec, agent: AgentConfig) -> bool:
    """Whether ``point`` stands on ``navmesh``: a polygon within one cell horizontally and the climb vertically.

    One cell (the navmesh's ``cell_size``) is the resolution of the navmesh: a point on its boundary is on it, a point on the
    floor's real edge (about one agent radius outside, where Recast eroded it)
    is not. ``False`` when ``navmesh`` is ``None``.
    """
    if navmesh is None:
        return False
    horizontal = float(navmesh.settings["cell_size"])
    vertical = max(float(agent.max_climb), 1e-3)
    p = np.asarray(point, dtype=np.float64)
    index, nearest = navmesh.nearest_poly(p, extents=(horizontal, vertical, horizontal))
    if int(index) < 0:
        return False
    offset = np.asarray(nearest, dtype=np.float64) - p
    return bool(math.hypot(offset[0], offset[2]) <= horizontal + 1e-9 and abs(offset[1]) <= vertical + 1e-9)


def normals_angle_deg(a: Vec, b: Vec) -> float:
    """Angle between two normals in degrees; ``inf`` when either has zero length.

    Plain floats rather than numpy: it runs once per predicate call, on 3-vectors.
    """
    lengths = math.hypot(*a) * math.hypot(*b)
    if not lengths > 0:
        return math.inf
    cosine = (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / lengths
    return math.degrees(math.acos(min(1.0, max(-1.0, cosine))))


def edge_surface_gaps(structure: nx.Graph, navmesh: NavMesh, agent: AgentConfig, step: float = 0.1) -> dict[tuple[int, int], float]:
    """How far each edge between two on-navmesh nodes strays from the navmesh surface, m (``inf``: leaves it).

    Edges to a node off the navmesh (an opening on the floor's real edge) are left out: their far
    end lies where Recast eroded the surface away.
    """
    edges = [
        (a, b) for a, b in structure.edges
        if structure.nodes[a].get("on_navmesh") and structure.nodes[b].get("on_navmesh")
    ]
    starts = np.array([structure.nodes[a]["pos"] for a, _ in edges], dtype=np.float64).reshape(-1, 3)
    ends = np.array([structure.nodes[b]["pos"] for _, b in edges], dtype=np.float64).reshape(-1, 3)
    gaps = navmesh.segment_surface_gaps(starts, ends, step, 2.0 * float(agent.height))
    return dict(zip(edges, gaps.tolist()))


def traffic_ranks(
    graph: nx.Graph, sources: int = traffic.WALKING_SOURCES, ties: traffic.Ties = traffic.WALKING_TIES,
    scaling: traffic.Scaling = traffic.WALKING_SCALING, sampling: traffic.Sampling = traffic.WALKING_SAMPLING,
) -> dict[Hashable, float]:
    """Walking-flow percentile rank (0-100) of each node of ``graph`` that some walk starts at or passes through.

    The rank is :func:`g2s_plugins.traffic.percentile` of
    :func:`g2s_plugins.traffic.walking_flow` of ``sources`` area-sampled
    sources (seed 0), ``ties``, ``scaling`` and ``sampling`` (``heat_sources``, ``heat_ties``, ``heat_scaling`` and
    ``heat_sampling``, by
    default the ``flow`` analyzer's defaults): the array that analyzer and a
    traffic-aware ``coverage`` of the same settings use, computed once per graph. A node no walk
    touches, with no area and no through-flow (an opening the ``entry_exit``
    selector adds: area 0, at the end of the graph), gets no rank: its 0
    says nothing about the traffic around it. A portal node of the
    ``navmesh`` builder (area 0, between two polygons) is ranked by the
    walks passing through it.
    """
    arrays = traffic.surface_arrays(graph)
    flow = traffic.arrays_walking_flow(arrays, max_sources=sources, ties=ties, scaling=scaling,
                                       order=traffic.sampling_order(graph, sampling))
    rank = traffic.percentile(flow)
    walked = (traffic.origin_weight(arrays) > 0) | (flow > 0)
    return {node: value for node, value, keep in zip(arrays.nodes, rank.tolist(), walked.tolist()) if keep}


@dataclass(frozen=True)
class RuleArrays:
    """:func:`collapse_rule`'s tests on the rows of a :class:`~g2s_core.simplify.ForestArrays` (n nodes).

    ``on_navmesh`` (n,) bool; ``rank`` (n,) float64 the walking-flow percentile of :func:`traffic_ranks`, NaN for
    a node without one; ``normals`` (n,3) float64; ``normal_lengths`` (n,) float64 their ``math.hypot`` (the
    lengths :func:`normals_angle_deg` multiplies, so a native angle is the Python one to the bit); then the
    tolerances of :class:`CollapseParams`.
    """

    on_navmesh: np.ndarray
    rank: np.ndarray
    normals: np.ndarray
    normal_lengths: np.ndarray
    max_step: float | None
    tolerance_deg: float
    whole_chain: bool


NativeRule = Callable[["ForestArrays", RuleArrays], tuple[np.ndarray, np.ndarray, np.ndarray]]
"""Algorithm 4 with the rule in native code: the whole-forest answer of :mod:`g2s_core.simplify`."""

Derived = TypeVar("Derived")


class ForestDerived:
    """What a predicate derives from a forest's arrays (the collapse rule's :class:`RuleArrays`, ``mesh_los``'s
    structure of its edges), kept while it is asked about the same forest: one whose arrays are the very arrays of
    the last one, bar ``fixed``. The pipeline reads a forest once for all the rounds of the heat guarantee
    (:func:`g2s_core.simplify.simplify_forest`), whose later rounds replace only ``fixed``
    (:func:`g2s_plugins.heat_guarantee.keeping`), so they take what the first round derived, keyed by identity in
    O(1); a forest read again (another caller) derives it again. What is derived must not depend on ``fixed``."""

    def __init__(self) -> None:
        self._key: tuple[object, ...] = ()
        self._values: dict[str, object] = {}

    def get(self, forest: ForestArrays, name: str, derive: Callable[[ForestArrays], Derived]) -> Derived:
        """``derive(forest)``, derived once per forest under ``name``."""
        key = (forest.ids, forest.parent, forest.depth, forest.loops, forest.roots, forest.points, forest.data)
        if len(key) != len(self._key) or any(map(operator.is_not, key, self._key)):
            self._key, self._values = key, {}  # the last forest's arrays alone are kept
        if name not in self._values:
            self._values[name] = derive(forest)
        return self._values[name]  # type: ignore[return-value]


def collapse_rule(
    params: CollapseParams, line_of_sight: LineOfSight, graph: nx.Graph | None = None, native: NativeRule | None = None,
    derived: ForestDerived | None = None,
) -> Callable[[nx.DiGraph, int, int, int], bool]:
    """``P(tree, A, B, C)`` of the paper's Algorithm 5 with ``params``' tolerances: True when B may be removed.

    B is kept (False) when

    1. C is a leaf not on the walkable surface (``on_navmesh`` false): a line
       of sight to a point off the surface means nothing;
    2. with ``max_traffic_step`` set, the walking-flow percentile of B
       (:func:`traffic_ranks` of ``graph``, the run's initial graph) differs
       from that of A or of C by more than it: the heat map gives each
       polygon its nearest structure node's value, so removing B would give
       B's surroundings the value of a node whose traffic differs; a node
       without a rank (not in ``graph``, or an opening no walk touches) is
       not compared;
    3. the normals of the chain bend by more than ``normal_tolerance_deg``:
       the largest angle between the normals of the pairs AB, BC and AC
       (:func:`normals_angle_deg`; with ``whole_chain_normals`` false the
       normals of A and B only, as the paper does, which lets a collapse cut
       across a change of slope at C);
    4. ``line_of_sight(A.pos, C.pos)`` is false: the straight segment is not
       walkable on the surface (each predicate's test, which also rejects a
       segment straying from the surface by more than its gap tolerance).

    Tests 2 and 3 cost a few lookups; test 4 runs only when they let B go.
    Test 2 compares the nodes' own polygons, not the polygons each will
    stand for: those depend on which nodes the rest of the simplification
    keeps. As A stays while the nodes after it are removed one by one, every
    node removed between two kept ones is within the step of the first.

    The paper's pseudocode writes test 4 backwards (it sets ``canCollapse =
    false`` when there *is* line of sight, and its last line sets it true
    unconditionally); its text states the intent implemented here: collapse
    only when A and C see each other on the surface.

    With ``native``, the predicate carries ``whole_forest`` (see
    :mod:`g2s_core.simplify`): ``native`` given the forest and these tests as
    :class:`RuleArrays`, which must answer as this predicate does; those arrays
    are read once per forest and kept in ``derived`` (the caller's, when
    ``native`` keeps what it derives from the forest there too).

    Raises:
        PluginError: ``max_traffic_step`` is set and there is no ``graph``.
    """
    tolerance_deg, whole_chain, max_step = params.normal_tolerance_deg, params.whole_chain_normals, params.max_traffic_step
    ranks: Mapping[Hashable, float] = {}
    if max_step is not None:
        if graph is None:
            raise PluginError("max_traffic_step needs the run's initial surface graph")
        ranks = traffic_ranks(graph, params.heat_sources, params.heat_ties, params.heat_scaling, params.heat_sampling)
    bends: dict[tuple[Vec, Vec], bool] = {}

    def bent(u: Vec, v: Vec) -> bool:
        """Whether normals ``u`` and ``v`` are further apart than the tolerance, remembered per pair: a level's
        nodes share few distinct normals, and the angle's arithmetic cost more than a look-up (0.9 us a call)."""
        try:
            return bends[u, v]
        except KeyError:
            bends[u, v] = answer = normals_angle_deg(u, v) > tolerance_deg
            return answer
        except TypeError:  # a normal that is a list or an array
            return normals_angle_deg(u, v) > tolerance_deg

    def predicate(tree: nx.DiGraph, a: int, b: int, c: int) -> bool:
        # networkx's own dicts rather than its views (a method call per look-up): this runs on every call
        nodes = tree._node
        node_a, node_c = nodes[a], nodes[c]
        if not node_c.get("on_navmesh", False) and not tree._succ[c]:  # C a leaf
            return False
        rank_b = ranks.get(b)
        # a node without a rank is not compared (it counts as B's); no generator: this runs on every call
        if rank_b is not None and (abs(ranks.get(a, rank_b) - rank_b) > max_step or abs(ranks.get(c, rank_b) - rank_b) > max_step):
            return False
        # pair by pair: a chain whose first pair bends needs no other angle
        normal_a, normal_b = node_a["normal"], nodes[b]["normal"]
        if bent(normal_a, normal_b):
            return False
        if whole_chain:
            normal_c = node_c["normal"]
            if bent(normal_b, normal_c) or bent(normal_a, normal_c):
                return False
        return line_of_sight(tuple(map(float, node_a["pos"])), tuple(map(float, node_c["pos"])))

    if native is not None:
        kept = derived if derived is not None else ForestDerived()

        def rule_arrays(forest: ForestArrays) -> RuleArrays:
            """The tests' arrays of ``forest``, read from its node dicts (a 20k-polygon level's forest of 75k nodes:
            about 0.1 s of CPU; once per forest, :class:`ForestDerived`)."""
            data, n = forest.data, len(forest.data)
            normals = list(map(operator.itemgetter("normal"), data))
            return RuleArrays(
                on_navmesh=np.fromiter((bool(node.get("on_navmesh", False)) for node in data), bool, n),
                rank=np.fromiter((ranks.get(node, math.nan) for node in forest.ids.tolist()), np.float64, n),
                normals=np.fromiter(itertools.chain.from_iterable(normals), np.float64, 3 * n).reshape(n, 3),
                normal_lengths=np.fromiter(itertools.starmap(math.hypot, normals), np.float64, n),
                max_step=max_step, tolerance_deg=tolerance_deg, whole_chain=whole_chain)

        def whole_forest(forest: ForestArrays) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
            return native(forest, kept.get(forest, "rule arrays", rule_arrays))

        predicate.whole_forest = whole_forest  # type: ignore[attr-defined]
    return predicate
