"""Mesh LoS: remove B when the agent can walk straight from A to C over the level mesh itself (no navmesh needed).

The counterpart of ``surface_los`` for graphs built without a navigation
mesh (the ``sampling`` builder), usable after any builder. For a chain
A -> B -> C of a rooted tree the predicate is the paper's Algorithm 5 as
:func:`g2s_plugins._surface.collapse_rule` states it (C a leaf off the
surface, the chain's normals bending by more than ``normal_tolerance_deg``,
or no line of sight: B stays), with this line of sight: the agent can walk
the straight segment A -> C over ``context.mesh``. The segment lifted by half
the agent height hits no triangle, and under each of the points spaced at
most ``probe_step`` apart along it a short downward ray finds walkable ground
with head room, within ``max_surface_gap`` above or below the segment and
within ``max_climb + margin`` below it, and the ground between two
neighbouring points rises or falls no more than a step (max climb) or the max
slope allows (:func:`g2s_plugins._raycasting.walk_segments`). The defaults
are ``surface_los``'s, so the two predicates differ only in how they test the
line of sight.

Which predicate to use:

* ``surface_los`` when the run has a navmesh (``navmesh`` builder): one
  Detour raycast per call, and "visible" means "on the same navmesh", which
  also respects Recast's erosion by the agent radius.
* ``mesh_los`` when it has none (``sampling`` builder, a third-party
  builder), or to test against the true geometry rather than Recast's
  voxelised approximation. It tests a line of zero width: it does not keep
  the agent radius away from walls the segment passes beside.

Cost per call: one batch of about 2 L / probe_step + 3 rays (L = |AC|),
through Embree when available; answers are cached per (A, C) pair.
"""

from __future__ import annotations

from collections.abc import Callable

import networkx as nx
import numpy as np
from pydantic import Field

from g2s_core.model import RunContext
from g2s_core.plugin import hookimpl
from g2s_plugins._raycasting import GROUND_MARGIN, AgentShape, RayCaster, walk_segments
from g2s_plugins._surface import CollapseParams, collapse_rule

NAME = "mesh_los"


class Params(CollapseParams):
    """Algorithm 5's tolerances and the resolution of the walk test (``max_surface_gap``: to the ground under A -> C)."""

    margin: float = Field(
        GROUND_MARGIN, ge=0, le=10, description="ground may lie this much further below the line than the max climb, m"
    )


def mesh_los_predicate(
    mesh: object, agent: AgentShape, params: Params
) -> Callable[[nx.DiGraph, int, int, int], bool]:
    """``P(tree, a, b, c)`` over ``mesh`` for ``agent`` (see the module docstring)."""
    probe_step = params.probe_step if params.probe_step is not None else 0.5 * agent.radius
    tolerance = params.normal_tolerance_deg
    caster: RayCaster | None = None
    cache: dict[tuple[tuple[float, ...], tuple[float, ...]], bool] = {}

    def walkable(start: tuple[float, ...], end: tuple[float, ...]) -> bool:
        nonlocal caster
        key = (start, end)
        if key not in cache:
            if caster is None:  # built on first use: runs that never reach here pay nothing
                caster = RayCaster(mesh)
            ok, _ = walk_segments(
                caster, np.array([start]), np.array([end]), agent, probe_step, params.margin, params.max_surface_gap
            )
            cache[key] = cache[(end, start)] = bool(ok[0])
        return cache[key]

    return collapse_rule(tolerance, walkable, params.whole_chain_normals)


@hookimpl
def g2s_simplify_predicate(params: Params, context: RunContext) -> Callable[[nx.DiGraph, int, int, int], bool]:
    """Algorithm 5's rules with a walk test over ``context.mesh`` instead of the navmesh."""
    params = params if params is not None else Params()
    return mesh_los_predicate(context.mesh, AgentShape.from_config(context.agent), params)
