"""Surface LoS: remove B when A sees C across the navigation mesh and the surface does not bend (Algorithm 5).

For a chain A -> B -> C of a rooted tree the predicate is the paper's
Algorithm 5 as :func:`g2s_plugins._surface.collapse_rule` states it (C a
leaf off the navmesh, with ``max_traffic_step`` set a step in walking
traffic at B, the chain's normals bending by more than
``normal_tolerance_deg``, or no line of sight: B stays), with this line of
sight from A to C:

* Detour's raycast from A to C over ``context.navmesh`` reaches C; and
* the straight segment A -> C stays within ``max_surface_gap`` of the
  navmesh's detail surface: at points at most ``probe_step`` apart along it,
  the detail surface lies within the gap above or below
  (:meth:`g2s_plugins.recast.NavMesh.segment_surface_gaps`). Detour's raycast is 2D:
  alone, it lets an edge run metres under a ramp whose foot it crosses.
  ``max_surface_gap: null`` leaves this check out, as the paper does.

Default tolerance, 10 degrees: Recast quantises heights to the cell height,
which tilts the polygons of a flat floor by a few degrees at most, and such
noise must not block a simplification (the Hub 5 artefact in the paper's
results); walkable ramps in levels are usually 15 to 45 degrees steep (the
default agent climbs up to 45), so 10 degrees still keeps a node where one
begins.

Cost per call: one navmesh raycast, O(polygons crossed), and one Detour
height query per probe point (at most |AC| / probe_step + 1 of them, stopping
at the first probe out of reach), both in one C++ call
(:meth:`g2s_plugins.recast.NavMesh.line_of_sight`). The pipeline's
simplification asks none of them from Python: the predicate carries the
whole-forest path of :mod:`g2s_core.simplify`, Algorithm 4 with these tests
in one C++ call (:meth:`g2s_plugins.recast.NavMesh.collapse_forest`).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

import numpy as np
from pydantic import Field

from g2s_core.errors import PluginError
from g2s_core.lazy import lazy_module
from g2s_core.model import RunContext
from g2s_core.plugin import hookimpl
from g2s_plugins import traffic
from g2s_plugins._surface import CollapseParams, RuleArrays, collapse_rule
from g2s_plugins.heat_guarantee import begin_ahead, guaranteed

if TYPE_CHECKING:  # g2s_core.simplify imports scipy (g2s_core.rooted): listing plugins and checking a config need neither
    from g2s_core.simplify import ForestArrays

structure_leaves = lazy_module("g2s_plugins.structure_leaves")  # it imports g2s_core.simplify, which imports scipy
nx = lazy_module("networkx")

NAME = "surface_los"


class Params(CollapseParams):
    """How much the surface may bend at a removed node, how far a new edge may stray from the navmesh surface, and
    which leaves that are no terminal go (:mod:`g2s_plugins.structure_leaves`)."""

    leaf_cover_radius: float | None = Field(
        None, gt=0, description="after Algorithm 4, drop the structure's leaves that are no terminal (a cover's "
        "waypoints at the ends of its paths) while every node within this many metres, along the graph, of the "
        "polygons the structure stands for stays so (set it to the cover's radius); null: every leaf stays"
    )
    leaf_near_distance: float = Field(
        5.0, gt=0, description="with leaf_cover_radius, a leaf also stays when dropping it would take a node within "
        "this many metres of those polygons farther (the distance at which traffic counts as passing the structure)"
    )


@hookimpl
def g2s_simplify_predicate(
    params: Params, context: RunContext, forest: nx.DiGraph, simplified: nx.DiGraph | None
) -> Callable[[nx.DiGraph, int, int, int], bool] | None:
    """The predicate of Algorithm 5 over ``context.navmesh``; with ``min_heat_rho``, the rounds of
    :func:`g2s_plugins.heat_guarantee.guaranteed`.

    Raises:
        PluginError: the run has no navigation mesh.
    """
    navmesh = context.navmesh
    if navmesh is None:
        raise PluginError("surface_los needs a navigation mesh; use the navmesh graph builder or the mesh_los predicate")
    params = params if params is not None else Params()
    agent = context.agent
    step = params.probe_step if params.probe_step is not None else 0.5 * float(agent.radius)
    gap = params.max_surface_gap

    def line_of_sight(start: tuple[float, ...], end: tuple[float, ...]) -> bool:
        return navmesh.line_of_sight(start, end, step, gap)

    # a navmesh without the C++ path (another implementation of g2s_core.model.NavMesh) is asked chain by chain;
    # one memo of lines of sight for every round of this predicate: the heat guarantee's later rounds ask most again
    memo = navmesh.sight_memo() if hasattr(navmesh, "collapse_forest") else None

    def native(arrays: ForestArrays, rule: RuleArrays) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        kept, added, loop = navmesh.collapse_forest(arrays, rule, step, gap, memo)
        if params.leaf_cover_radius is not None:  # the leaves that are no terminal, where the cover holds without them
            graph = traffic.surface_arrays(context.graph)
            kept = structure_leaves.pruned(arrays, kept, added, loop, graph, params.leaf_cover_radius,
                                           params.leaf_near_distance, rule.rank, rule.max_step)
        return kept, added, loop

    whole = native if memo is not None else None
    if whole is None and params.leaf_cover_radius is not None:  # the core's loop of predicate calls removes no leaf
        raise PluginError("leaf_cover_radius needs a navmesh with the native simplification (collapse_forest)")
    return guaranteed(lambda: collapse_rule(params, line_of_sight, context.graph, whole), params, context, forest,
                      simplified)


@hookimpl
def g2s_begin_ahead(params: Params, context: RunContext) -> None:
    """With ``min_heat_rho``, the heat guarantee's confirming walking flow begun beside steps 3-4
    (:func:`g2s_plugins.heat_guarantee.begin_ahead`)."""
    begin_ahead(params, context)
