"""Mesh LoS: remove B when the agent can walk straight from A to C over the level mesh itself (no navmesh needed).

The counterpart of ``surface_los`` for graphs built without a navigation
mesh (the ``sampling`` builder), usable after any builder. For a chain
A -> B -> C of a rooted tree, ``P(tree, A, B, C)`` keeps B (returns False)
when

1. C is a leaf (no children) that is not on the walkable surface
   (``on_navmesh`` false): the walk test below means nothing for a point
   off the surface (e.g. an entry/exit point added outside it);
2. the angle between the surface normals at A and B exceeds
   ``normal_tolerance_deg`` (a zero-length normal counts as exceeding it):
   removing B would cut across a change of slope;
3. the agent cannot walk the straight segment A -> C: the segment lifted by
   half the agent height hits a triangle of ``context.mesh``, or under one
   of the points spaced at most ``probe_step`` apart along it a short
   downward ray finds no ground within ``max_climb + margin`` below the
   line, finds ground steeper than the agent's max slope or without head
   room, or the ground between two neighbouring points rises or falls more
   than a step (max climb) or the max slope allows.

Otherwise it returns True (B may go). Rules 1 and 2 are those of the paper's
Algorithm 5; rule 3 replaces its navmesh raycast (see ``surface_los`` for
the paper's reversed third test). The default tolerance, 10 degrees, is
``surface_los``'s, so the two predicates differ only in how they test the
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

import math
from collections.abc import Callable

import networkx as nx
import numpy as np
from pydantic import Field

from g2s_core.model import RunContext
from g2s_core.plugin import PluginParams, hookimpl
from g2s_plugins._raycasting import GROUND_MARGIN, AgentShape, RayCaster, walk_segments

NAME = "mesh_los"


class Params(PluginParams):
    """Normal tolerance and the resolution of the walk test."""

    normal_tolerance_deg: float = Field(
        10.0, ge=0, le=180, description="largest angle between the normals at A and B that still lets B go, degrees"
    )
    probe_step: float | None = Field(
        None, gt=0, le=100, description="ground probes along A -> C at most this far apart, m; default agent radius / 2"
    )
    margin: float = Field(
        GROUND_MARGIN, ge=0, le=10, description="ground may lie this much further below the line than the max climb, m"
    )


def normal_angle_deg(a: object, b: object) -> float:
    """Angle between two normals in degrees; ``inf`` when either has zero length."""
    va = np.asarray(a, dtype=np.float64)
    vb = np.asarray(b, dtype=np.float64)
    product = float(np.linalg.norm(va) * np.linalg.norm(vb))
    if not product > 0:
        return math.inf
    return math.degrees(math.acos(min(1.0, max(-1.0, float(np.dot(va, vb)) / product))))


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
            ok, _ = walk_segments(caster, np.array([start]), np.array([end]), agent, probe_step, params.margin)
            cache[key] = cache[(end, start)] = bool(ok[0])
        return cache[key]

    def predicate(tree: nx.DiGraph, a: int, b: int, c: int) -> bool:
        node_c = tree.nodes[c]
        if tree.out_degree(c) == 0 and not node_c.get("on_navmesh", False):
            return False
        if normal_angle_deg(tree.nodes[a]["normal"], tree.nodes[b]["normal"]) > tolerance:
            return False
        start = tuple(float(v) for v in tree.nodes[a]["pos"])
        end = tuple(float(v) for v in node_c["pos"])
        return walkable(start, end)

    return predicate


@hookimpl
def g2s_simplify_predicate(params: Params, context: RunContext) -> Callable[[nx.DiGraph, int, int, int], bool]:
    """Algorithm 5's rules with a walk test over ``context.mesh`` instead of the navmesh."""
    params = params if params is not None else Params()
    return mesh_los_predicate(context.mesh, AgentShape.from_config(context.agent), params)
