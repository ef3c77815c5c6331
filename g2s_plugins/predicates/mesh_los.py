"""Mesh LoS: remove B when the agent can walk straight from A to C over the level mesh itself (no navmesh needed).

The counterpart of ``surface_los`` for graphs built without a navigation
mesh (the ``sampling`` builder), usable after any builder. For a chain
A -> B -> C of a rooted tree the predicate is the paper's Algorithm 5 as
:func:`g2s_plugins._surface.collapse_rule` states it (C a leaf off the
surface, with ``max_traffic_step`` set a step in walking traffic at B, the
chain's normals bending by more than ``normal_tolerance_deg``, or no line
of sight: B stays), with this line of sight: the agent can walk
the straight segment A -> C over ``context.mesh``. The segment lifted by half
the agent height hits no triangle, nor do its copies moved ``DISK_SHARE`` x
``clearance`` to either side, nor does a face steeper than the max slope pass
through the band between them (the sampling builder's test of its own edges,
so that a simplified edge cuts no corner and crosses no door the agent could
not: :func:`walk_half_width`); and under each of the points spaced at
most ``probe_step`` apart along it a short downward ray finds walkable ground
with head room, within ``max_surface_gap`` above or below the segment and
within ``max_climb + margin`` below it, and the ground between two
neighbouring points rises or falls no more than a step (max climb) or the max
slope allows (:func:`g2s_plugins._raycasting.walks_in_batch`). The tolerances'
defaults are ``surface_los``'s, so the two predicates differ only in how they
test the line of sight.

Which predicate to use:

* ``surface_los`` when the run has a navmesh (``navmesh`` builder): one
  Detour raycast per call, and "visible" means "on the same navmesh", which
  also respects Recast's erosion by the agent radius.
* ``mesh_los`` when it has none (``sampling`` builder, a third-party
  builder), or to test against the true geometry rather than Recast's
  voxelised approximation. It keeps 0.9 x the clearance away from walls the
  segment passes beside (``clearance: 0``: a line of zero width, as before
  6 December 2026), where Recast erodes by the whole agent radius, and
  tests the agent's body between its side lines from knee to head
  (``walks_in_batch(..., body=True)``, as the builder's edges), so a walk
  does not pass over a crate the builder's edges stop at; only with a
  ``max_surface_gap`` no larger than the knee's height, which keeps the
  ground under the line below the slab.

Cost: a walk between two nodes on one open floor triangle, both that band's
half-width farther inside its edges, passes without a ray
(:class:`g2s_plugins._raycasting.OpenFloors`, looked up once for every node
of the tree); any other costs about 2 L / probe_step + 5 rays (L = |AC|),
through Embree when available, and, where those pass, its share of one band
test per batch (:func:`g2s_plugins._raycasting.bands_meet_walls`, which
looks the band up in the steep triangles' grid, built once per mesh:
docs/sampling.md, "Simplified edges as wide as the agent"). A batch is
:func:`g2s_plugins._raycasting.walks_in_batch`, the builder's walk test, its
arithmetic in the C++ extension round the ray casts (in numpy a batch of a
few dozen walks cost its per-call overhead, about 0.75 ms).
Answers are cached per (A, C) pair for the predicate's life: the heat guarantee's rounds
(:mod:`g2s_plugins.heat_guarantee`) ask the same predicate, so a later
round casts rays only for walks no earlier round tested, and on the
whole-forest path below the C++ forest walk keeps the answers too (a
``SightMemo``), so a later round asks Python only about chains no earlier
round asked. Simplification
takes the predicate's whole-forest path (:mod:`g2s_core.simplify`):
Algorithm 4 and Algorithm 5's other tests in C++ (src/forest_simplify.hpp,
``surface_los``'s), which asks this walk test back in Python only for the
chains those tests let go, and in batches: the walks below every kept node
go on until each needs a walk not known yet, and those walks are tested in
one ray batch, each with the walks from its A to the nodes just below its C,
which that walk asks about next if B goes (``LOOKAHEAD``). A ray batch costs
mostly per call (docs/performance.md, "The sampling route's simplification
in C++").
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING, NamedTuple

import numpy as np
from pydantic import Field

from g2s_core.lazy import lazy_module
from g2s_core.model import RunContext
from g2s_core.plugin import hookimpl
from g2s_plugins._raycasting import GROUND_MARGIN, AgentShape, OpenFloors, RayCaster, walks_in_batch
from g2s_plugins._surface import CollapseParams, ForestDerived, RuleArrays, collapse_rule
from g2s_plugins.graph_builders.sampling import DISK_SHARE
from g2s_plugins.heat_guarantee import begin_ahead, guaranteed
from g2s_plugins.recast.navmesh import NavMesh, collapse_forest_seeing

nx = lazy_module("networkx")

if TYPE_CHECKING:  # g2s_core.simplify imports scipy (g2s_core.rooted): listing plugins and checking a config need neither
    from g2s_core.simplify import ForestArrays

NAME = "mesh_los"


class Params(CollapseParams):
    """Algorithm 5's tolerances and the resolution of the walk test (``max_surface_gap``: to the ground under A -> C)."""

    margin: float = Field(
        GROUND_MARGIN, ge=0, le=10, description="ground may lie this much further below the line than the max climb, m"
    )
    clearance: float | None = Field(
        None, ge=0, le=100, description="the walk A -> C sweeps a disk of 0.9 x this through no wall, as the sampling "
        "builder's edges do, m; default the sampling builder's clearance, else the agent radius; 0: one line"
    )


def walk_half_width(params: Params, agent: AgentShape, graph: nx.Graph | None) -> float:
    """Metres to either side of A -> C the walk test's side lines and band reach: ``DISK_SHARE`` x the clearance
    (``params.clearance``, else the sampling builder's from ``graph``'s ``sampling_stats``, else the agent radius),
    the builder's rule for its own edges, so a walk between two samples along a wall passes where the builder's
    edges do."""
    clearance = params.clearance
    if clearance is None:
        clearance = (graph.graph.get("sampling_stats") or {}).get("clearance") if graph is not None else None
    return DISK_SHARE * float(clearance if clearance is not None else agent.radius)


LOOKAHEAD = 8
"""Nodes below C whose walks from A are tested in the same batch as A -> C (see :func:`mesh_los_predicate`).

Measured on dungeon_1k and building_1k (map_analysis_sampling, simplify CPU, chain by chain): 2.9-3.0 s without
lookahead, 1.15-1.5 s for any of 2, 4, 8, 12 or 32, within the shared machine's noise of each other. With the walks
asked in batches (a 500-room dungeon's first round, before the loop pass asked its chains together): 2,881 ray
batches of 26,558 walks at 8, 2,691 of 64,865 at 32, 2,683 of 164,019 at 128: the nodes under C are not what the
batches wait for."""


Point = tuple[float, ...]


class _Structure(NamedTuple):
    """The structure walk tests are asked from: its nodes, each node's successors (tree and loop edges) and
    position."""

    nodes: Iterable[int]
    successors: Callable[[int], Iterable[int]]
    position: Callable[[int], Point]

    def below(self, c: int, count: int) -> list[Point]:
        """The positions of up to ``count`` nodes under ``c``, nearest first (breadth first, by id)."""
        found: list[int] = []
        frontier = [c]
        while frontier and len(found) < count:
            frontier = sorted(n for node in frontier for n in self.successors(node))
            found.extend(frontier[: count - len(found)])
        return list(map(self.position, found))


def mesh_los_predicate(
    mesh: object, agent: AgentShape, params: Params, graph: nx.Graph | None = None
) -> Callable[[nx.DiGraph, int, int, int], bool]:
    """``P(tree, a, b, c)`` over ``mesh`` for ``agent`` (see the module docstring); ``graph``: the run's
    initial graph, which ``max_traffic_step`` needs (:func:`g2s_plugins._surface.collapse_rule`).

    Walks are tested in batches, each walk on its own rays, so the answers
    are those of one test per pair; only the number of ray batches changes.
    A walk A -> C not cached yet is tested with the walks from A to the
    ``LOOKAHEAD`` nodes nearest under C, which simplification asks about
    next if it removes B: one batch then answers a run of removals along a
    chain. The predicate carries the whole-forest path
    (:mod:`g2s_core.simplify`): :func:`g2s_plugins.recast.navmesh.collapse_forest_seeing`
    with this walk test, which asks the walks of every chain waiting for one
    in a single batch; there the lookahead reads the forest's own edges
    (below C they are the structure's while Algorithm 4 runs: C's subtree
    is not walked yet).
    """
    probe_step = params.probe_step if params.probe_step is not None else 0.5 * agent.radius
    half_width = walk_half_width(params, agent, graph)
    caster: RayCaster | None = None
    floor_of: dict[Point, int] = {}  # the open floor triangle each node of the tree stands on, or -1
    walked: dict[tuple[Point, Point], bool] = {}  # walks tested, start -> end
    cache: dict[tuple[Point, Point], bool] = {}  # answers given, for (A, C) and (C, A)
    asking: tuple[_Structure, int, int] | None = None  # the structure, A and C of the chain being answered
    memo = NavMesh.sight_memo()  # ``cache`` as the C++ forest walk reads it, so a later round asks no answered pair

    # The body's slab stands on the straight line A -> C: it is the agent's body only where the ground under the
    # line stays below its knee, which a surface gap no larger than the knee keeps at every probe (without one,
    # the paper's rule, the line may run through a hill and the slab meet the hill's own faces).
    body = params.max_surface_gap is not None and params.max_surface_gap <= agent.body[0]

    def start_casting(structure: _Structure) -> RayCaster:
        """The caster, and the open floor under every node of ``structure`` (built on first use: runs that never
        get here pay nothing; nodes keep their positions while simplification removes some)."""
        caster = RayCaster(mesh)
        floors = OpenFloors(caster, agent, min_inradius=agent.radius)
        if floors.open.any():
            positions = list(dict.fromkeys(map(structure.position, structure.nodes)))
            faces = floors.faces_under(np.array(positions).reshape(-1, 3),
                                       floors.certain_offset(params.margin, params.max_surface_gap), room=half_width)
            floor_of.update(zip(positions, faces.tolist()))
        return caster

    def certain(start: Point, end: Point) -> bool:
        """Both ends on the same open floor triangle: the walk passes (:class:`OpenFloors`)."""
        face = floor_of.get(start, -1)
        return face >= 0 and floor_of.get(end, -1) == face

    def walks(structure: _Structure, pairs: list[tuple[int, int]]) -> list[bool]:
        """Whether the agent walks from A to C, for each pair (A, C) of nodes of ``structure``; the walks not
        known yet, and those from A to the nodes under C not known either, tested in one batch."""
        nonlocal caster
        if caster is None:
            caster = start_casting(structure)
        asked = [(structure.position(a), structure.position(c)) for a, c in pairs]
        answers = list(map(cache.get, asked))
        if None not in answers:  # all given before: most calls of the heat guarantee's later rounds
            return answers
        tested: dict[tuple[Point, Point], None] = {}
        for (_, c), (start, end) in zip(pairs, asked):
            if (start, end) in cache or (start, end) in walked:
                continue
            if certain(start, end):
                walked[(start, end)] = True
                continue
            tested[(start, end)] = None
            tested.update(((start, e), None) for e in structure.below(c, LOOKAHEAD)
                          if (start, e) not in walked and e != end and not certain(start, e))
        if tested:
            starts, ends = zip(*tested)
            ok, _ = walks_in_batch(caster, np.array(starts), np.array(ends), agent, probe_step, params.margin,
                                  params.max_surface_gap, half_width, body=body)
            walked.update(zip(tested, ok.tolist()))
        for start, end in asked:
            if (start, end) not in cache:
                cache[(start, end)] = cache[(end, start)] = walked[(start, end)]
        return [cache[pair] for pair in asked]

    def line_of_sight(start: Point, end: Point) -> bool:
        """The walk test of the chain being answered (``start`` and ``end``: its A's and C's positions)."""
        structure, a, c = asking
        return walks(structure, [(a, c)])[0]

    derived = ForestDerived()  # what the rule and ``native`` derive from the last forest asked about

    def forest_structure(forest: ForestArrays) -> tuple[list[int], _Structure]:
        """``forest``'s ids and the :class:`_Structure` of its edges (once per forest, :class:`ForestDerived`)."""
        ids = forest.ids.tolist()
        successors: dict[int, list[int]] = {node: [] for node in ids}
        for node, row in zip(ids, forest.parent.tolist()):
            if row >= 0:
                successors[ids[row]].append(node)
        for u, v in forest.loops.tolist():
            successors[ids[u]].append(ids[v])
        return ids, _Structure(ids, successors.__getitem__, dict(zip(ids, map(tuple, forest.points.tolist()))).__getitem__)

    def native(forest: ForestArrays, rule_arrays: RuleArrays) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        ids, structure = derived.get(forest, "structure", forest_structure)

        def sees(pairs: np.ndarray) -> np.ndarray:  # (k,2) rows of the forest -> (k,) bool
            return np.array(walks(structure, [(ids[a], ids[c]) for a, c in pairs.tolist()]), dtype=bool)

        return collapse_forest_seeing(forest, rule_arrays, sees, memo)

    rule = collapse_rule(params, line_of_sight, graph, native, derived)

    def predicate(tree: nx.DiGraph, a: int, b: int, c: int) -> bool:
        nonlocal asking
        nodes = tree._node
        asking = (_Structure(tree, tree.successors, lambda node: tuple(map(float, nodes[node]["pos"]))), a, c)
        try:
            return rule(tree, a, b, c)
        finally:
            asking = None

    predicate.whole_forest = rule.whole_forest  # type: ignore[attr-defined]
    return predicate


@hookimpl
def g2s_simplify_predicate(
    params: Params, context: RunContext, forest: nx.DiGraph, simplified: nx.DiGraph | None
) -> Callable[[nx.DiGraph, int, int, int], bool] | None:
    """Algorithm 5's rules with a walk test over ``context.mesh`` instead of the navmesh; with ``min_heat_rho``,
    the rounds of :func:`g2s_plugins.heat_guarantee.guaranteed`."""
    params = params if params is not None else Params()
    agent = AgentShape.from_config(context.agent)
    return guaranteed(lambda: mesh_los_predicate(context.mesh, agent, params, context.graph), params, context, forest,
                      simplified)


@hookimpl
def g2s_begin_ahead(params: Params, context: RunContext) -> None:
    """With ``min_heat_rho``, the heat guarantee's confirming walking flow begun beside steps 3-4
    (:func:`g2s_plugins.heat_guarantee.begin_ahead`)."""
    begin_ahead(params, context)
