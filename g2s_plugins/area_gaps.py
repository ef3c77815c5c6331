"""What most likely parts two walkable areas no walk joins, measured as a designer would measure it: between the
edges of the level's walkable ground, not between the nodes' centres.

The disconnected-areas warning (:mod:`g2s_core.disconnected`) names the cause
between the largest area and each of the next ones; both graph builders set
``context.likely_cause`` to :func:`likely_cause_of` their ground.

*The ground's edges* (:func:`ground_rim`): on the navmesh route, the edges of
the area's navmesh polygons that no polygon of the area lies across, a point
every cell (``cell_size``) along each; on the sampling route, the samples,
each standing for a square of its ``area``. Either surface is eroded: Recast
keeps the agent's centre ``ceil(radius / cell_size)`` cells from walls and
drops, the sampling builder ``clearance`` metres. The level's ground reaches
that far past a navmesh edge, and half the square's side plus the clearance
past a sample, so the gap between two areas' ground is the horizontal
distance of their closest edge points less both reaches. Measured on levels
of known gaps (docs/analysis_quality.md, "The disconnected-areas warning's
gap"): a jump gap of 0.8 m read 9.9-10.6 m between polygon centres, now 1.0 m
on the navmesh route (Recast's cells, 0.25 m, place each edge) and 1.0 m on
the sampling route (each sample stands for a 1 m square).

*The cause* (:func:`likely_cause`): from the vertical step between those
closest edges and the gap, compared with the agent's ``max_climb``,
``height`` and ``max_slope``: separate floors, a step too high to climb
(only when steeper than ``max_slope`` over the gap), or a gap, wall or
passage too narrow. When the closest pair is a floor above another but the
two areas also meet on one floor (a room shut by a narrow door above a
deck), the pair on one floor is named if it is closer with vertical offsets
counted ``height / max_climb`` times: a designer fixes the door, not the
storeys.

Complexity: O(e log e) for the e edge points of the compared areas (a k-d
tree per pair of areas), e = the areas' polygon perimeter / ``cell_size`` on
the navmesh route, their sample count on the sampling route.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from functools import partial

import networkx as nx
import numpy as np
import trimesh
from scipy.spatial import cKDTree

from g2s_core.config import AgentConfig
from g2s_core.disconnected import area_summary, xyz
from g2s_core.model import NavMesh
from g2s_plugins._raycasting import COMPASS, EPSILON, UP, RayCaster, hit_from_behind
from g2s_plugins.play_space import node_polygons

Rim = Callable[[nx.Graph, Sequence[int]], tuple[np.ndarray, np.ndarray]]
"""``(graph, nodes) -> (points (k,3), reach (k,))``: :func:`ground_rim` of a graph builder's surface."""


def ground_rim(graph: nx.Graph, nodes: Sequence[int], navmesh: NavMesh | None, erosion: float) -> tuple[np.ndarray, np.ndarray]:
    """(k,3) points on the edges of the walkable surface of ``nodes`` (metres) and (k,) how far the level's ground
    reaches past each, metres: ``erosion`` past a navmesh polygon's edge, half a square of the node's ``area``
    more past a node without a polygon (a sample; a portal point, area 0).

    A navmesh polygon's edges are those no polygon of ``nodes`` lies across, a point every ``cell_size`` along each
    (its ends included). O(edges + points).
    """
    polygons = node_polygons(graph, nodes) if navmesh is not None else np.full(len(nodes), -1)
    points = np.asarray([graph.nodes[n]["pos"] for n, p in zip(nodes, polygons) if p < 0], dtype=np.float64).reshape(-1, 3)
    reach = [np.asarray([math.sqrt(float(graph.nodes[n].get("area", 0.0))) / 2 + erosion
                         for n, p in zip(nodes, polygons) if p < 0])]
    if navmesh is not None and (held := np.unique(polygons[polygons >= 0])).size:
        corners = np.asarray(navmesh.polygons)[held]
        valid = corners >= 0
        rows, column = np.nonzero(valid)
        beyond = np.asarray(navmesh.neighbours)[held][rows, column]
        rows, column = rows[~np.isin(beyond, held)], column[~np.isin(beyond, held)]
        vertices = np.asarray(navmesh.vertices, dtype=np.float64)
        start = vertices[corners[rows, column]]
        end = vertices[corners[rows, (column + 1) % valid.sum(axis=1)[rows]]]
        count = np.ceil(np.linalg.norm(end - start, axis=1) / float(navmesh.settings["cell_size"])).astype(np.int64) + 1
        edge = np.repeat(np.arange(len(start)), count)
        along = (np.arange(len(edge)) - np.repeat(np.cumsum(count) - count, count)) / (count[edge] - 1)
        points = np.concatenate([points, start[edge] + along[:, None] * (end - start)[edge]])
        reach.append(np.full(len(edge), erosion))
    return points, np.concatenate(reach)


def closest_step(a: tuple[np.ndarray, np.ndarray], b: tuple[np.ndarray, np.ndarray],
                 climb_weight: float = 1.0) -> tuple[float, float, np.ndarray, np.ndarray]:
    """``(gap, vertical step, point of a, point of b)`` of the closest edge points of two areas' ground, each given
    as its :func:`ground_rim` ``(points, reach)`` (metres, vertical offsets counted ``climb_weight`` times): the gap
    is their horizontal distance less the ground's reach past each, at least 0."""
    (pa, ra), (pb, rb) = a, b
    scale = np.array([1.0, climb_weight, 1.0])
    distance, index = cKDTree(pb * scale).query(pa * scale)
    best = int(np.argmin(distance))
    there = int(index[best])
    offset = pb[there] - pa[best]
    gap = float(np.hypot(offset[0], offset[2])) - float(ra[best]) - float(rb[there])
    return max(gap, 0.0), float(abs(offset[1])), pa[best], pb[there]


def closest_step_for(a: tuple[np.ndarray, np.ndarray], b: tuple[np.ndarray, np.ndarray],
                     agent: AgentConfig) -> tuple[float, float, np.ndarray, np.ndarray]:
    """:func:`closest_step`, or the closest pair on one floor when the plain one is a floor above another and the
    one-floor pair is closer with vertical offsets counted ``agent.height / agent.max_climb`` times."""
    plain = closest_step(a, b)
    if plain[1] <= float(agent.max_climb) or float(agent.max_climb) <= 0:
        return plain
    weighted = closest_step(a, b, float(agent.height) / float(agent.max_climb))
    return weighted if weighted[1] <= float(agent.max_climb) else plain


def likely_cause(step: float, gap: float, agent: AgentConfig) -> str:
    """What most likely separates two areas whose ground's closest edges are ``gap`` m apart with a ``step`` m
    rise between them."""
    climb, height, radius = float(agent.max_climb), float(agent.height), float(agent.radius)
    if step > height:
        return (f"separate floors ({step:.1f} m apart) with no walkable stairs or ramp between them "
                f"for this agent (agent.max_climb {climb:g} m, agent.max_slope {float(agent.max_slope):g}°)")
    # a rise the agent would walk up as a slope over the gap (islands 18 m apart, 0.6 m in height) is no step
    if step > climb and step > gap * math.tan(math.radians(float(agent.max_slope))):
        return f"a step of about {step:.1f} m, higher than agent.max_climb ({climb:g} m)"
    return (f"a gap or passage too narrow for the agent (agent.radius {radius:g} m), or a wall, where their "
            f"ground lies about {gap:.1f} m apart")


def areas_cause(graph: nx.Graph, largest: Sequence[int], others: Sequence[Sequence[int]], agent: AgentConfig,
                rim: Rim, mesh: trimesh.Trimesh | None = None) -> str:
    """The likely cause between ``largest`` and the nearest of ``others`` (node lists of areas of ``graph``) and
    where, e.g. ``a step of about 0.6 m, ..., e.g. between (x, y, z m) and (x, y, z m)``.

    With ``mesh``, a nearest area whose closest place or middle (:func:`g2s_core.disconnected.area_summary`) is
    shut inside a closed solid of ``mesh`` (:func:`shut_in`) is named as such: Recast keeps the floor inside a
    closed box with head room, and either route a render floor inside a collision hull exported with the level.
    """
    ground = rim(graph, largest)  # once, however many areas it is compared with
    (gap, step, here, there), nearest = min(((closest_step_for(ground, rim(graph, other), agent), other) for other in others),
                                            key=lambda pair: math.hypot(pair[0][0], pair[0][1]))
    cause = likely_cause(step, gap, agent)
    if mesh is not None:
        # its closest place and its middle: a render post or column inside the solid may face the rays from one
        if shut_in(RayCaster(mesh), np.stack([there, area_summary(graph, nearest)[1]]), agent).any():
            rise = float(there[1] - here[1])
            level = "at the same height" if round(abs(rise), 1) == 0 else f"{abs(rise):.1f} m {'higher' if rise > 0 else 'lower'}"
            cause = (f"a floor shut inside a closed solid (a box or collision hull exported with the level), {level}, "
                     f"its ground about {gap:.1f} m from the other's")
    return f"{cause}, e.g. between ({xyz(here)}) and ({xyz(there)})"


def shut_in(caster: RayCaster, points: np.ndarray, agent: AgentConfig) -> np.ndarray:
    """(n,) bool: each ground point (n,3) lies inside a closed solid of the caster's mesh: of the first faces
    straight up from it and along +x, +z, -x and -z from half the agent's height over it, at most one is met from
    the front (the rays of :func:`g2s_plugins.graph_builders.sampling.inside_closed_solids`, which needs all five).

    A render object inside a collision hull faces one of them (the bandstand's roof over its deck, the fountain's
    column beside its basin, benchmarks/level_kinds.py ``collision_hulls``); a place meant to be walked sees its
    room's walls and ceiling from the front. Five rays a point.
    """
    points = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    hits = [caster.first_hits(points + EPSILON * UP, UP)]
    hits += [caster.first_hits(points + 0.5 * float(agent.height) * UP, direction) for direction in COMPASS[::2]]
    return sum(hit_from_behind(caster, hit).astype(int) for hit in hits) >= len(hits) - 1


def likely_cause_of(agent: AgentConfig, navmesh: NavMesh | None = None, clearance: float = 0.0,
                    mesh: trimesh.Trimesh | None = None) -> Callable[[nx.Graph, Sequence[int], Sequence[Sequence[int]]], str]:
    """:func:`areas_cause` over a graph builder's ground: ``navmesh``'s polygons, eroded by Recast's
    ``ceil(radius / cell_size)`` cells, or samples kept ``clearance`` metres from walls and ledges; ``mesh`` to
    name floors shut inside closed solids."""
    cell = np.float32(navmesh.settings["cell_size"]) if navmesh is not None else None
    erosion = clearance if cell is None else float(np.ceil(np.float32(agent.radius) / cell) * cell)  # as Recast's float
    return partial(areas_cause, agent=agent, rim=partial(ground_rim, navmesh=navmesh, erosion=erosion), mesh=mesh)
