"""The warning a designer reads when the terminals lie in areas no walk joins.

It says how many areas there are, how much walkable surface the largest ones
hold and where they are (metres), what most likely separates them, and stays
short whatever the number of areas (at most :data:`LISTED_AREAS` are named).

The likely cause comes from the closest pair of nodes between the largest
area and each of the next :data:`COMPARED_AREAS` largest ones (a k-d tree per
pair, O(n log n) in the nodes of those areas): the vertical step between them,
compared with the agent's ``max_climb`` and ``height``, tells a step too high
to climb, separate floors, or a gap or passage too narrow for the agent.
When the closest pair is a floor above another but the two areas also meet
on one floor (a room shut by a narrow door above a deck), the pair on one
floor is named if it is closer with vertical offsets counted ``height /
max_climb`` times: a designer fixes the door, not the storeys.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import networkx as nx
import numpy as np
from scipy.spatial import cKDTree

LISTED_AREAS = 3
"""How many of the largest areas the warning places."""
COMPARED_AREAS = 4
"""How many areas after the largest one are searched for the closest neighbour."""


def area_summary(graph: nx.Graph, nodes: Sequence[int]) -> tuple[float, np.ndarray]:
    """``(walkable area in m², a node position inside the area)`` of a connected set of nodes.

    The position is that of the node nearest the area-weighted centre, so it
    lies in the area even when the area is not convex.
    """
    points = _positions(graph, nodes)
    weights = np.asarray([float(graph.nodes[n].get("area", 0.0)) for n in nodes])
    total = float(weights.sum())
    centre = (weights @ points) / total if total > 0 else points.mean(axis=0)
    return total, points[int(np.argmin(np.linalg.norm(points - centre, axis=1)))]


def closest_step(graph: nx.Graph, a: Sequence[int], b: Sequence[int],
                 climb_weight: float = 1.0) -> tuple[float, float, np.ndarray, np.ndarray, float]:
    """``(horizontal distance, vertical step, point of a, point of b, run)`` of the closest nodes of ``a`` and ``b``
    (metres), vertical offsets counted ``climb_weight`` times. ``run`` is the horizontal distance less half the
    width of each node's surface (the square root of its ``area``): how far apart the two surfaces' edges lie."""
    pa, pb = _positions(graph, a), _positions(graph, b)
    scale = np.array([1.0, climb_weight, 1.0])
    distance, index = cKDTree(pb * scale).query(pa * scale)
    best = int(np.argmin(distance))
    offset, nodes = pb[index[best]] - pa[best], (a[best], b[int(index[best])])
    horizontal = float(np.hypot(offset[0], offset[2]))
    run = horizontal - sum(np.sqrt(float(graph.nodes[n].get("area", 0.0))) for n in nodes) / 2
    return horizontal, float(abs(offset[1])), pa[best], pb[index[best]], max(run, 0.0)


def closest_step_for(graph: nx.Graph, a: Sequence[int], b: Sequence[int], agent: Any) -> tuple[float, float, np.ndarray, np.ndarray, float]:
    """:func:`closest_step`, or the closest pair on one floor when the plain one is a floor above another and the
    one-floor pair is closer with vertical offsets counted ``agent.height / agent.max_climb`` times."""
    plain = closest_step(graph, a, b)
    if plain[1] <= float(agent.max_climb) or float(agent.max_climb) <= 0:
        return plain
    weighted = closest_step(graph, a, b, float(agent.height) / float(agent.max_climb))
    return weighted if weighted[1] <= float(agent.max_climb) else plain


def likely_cause(step: float, gap: float, agent: Any, run: float = 0.0) -> str:
    """What most likely separates two areas whose closest nodes are ``gap`` m apart with a ``step`` m rise, their
    surfaces' edges ``run`` m apart."""
    climb, height, radius = float(agent.max_climb), float(agent.height), float(agent.radius)
    if step > height:
        return (f"separate floors ({step:.1f} m apart) with no walkable stairs or ramp between them "
                f"for this agent (agent.max_climb {climb:g} m, agent.max_slope {float(agent.max_slope):g}°)")
    # a rise the agent would walk up as a slope over the run (islands 18 m apart, 0.6 m in height) is no step
    if step > climb and step > run * np.tan(np.radians(float(agent.max_slope))):
        return f"a step of about {step:.1f} m, higher than agent.max_climb ({climb:g} m)"
    # the nodes are polygon centres or samples, so their distance bounds the gap, it does not measure it
    return (f"a gap or passage too narrow for the agent (agent.radius {radius:g} m), or a wall, between "
            f"places about {gap:.1f} m apart")


def disconnected_warning(graph: nx.Graph, areas: Mapping[Any, Sequence[int]], terminal_count: int, agent: Any) -> str:
    """The warning for terminals spread over the connected ``areas`` (area id -> its nodes) of ``graph``.

    ``agent`` has ``radius``, ``height``, ``max_climb`` and ``max_slope`` (metres, degrees); without
    it the cause is left out, and without node positions (an abstract graph) the places too.
    """
    if not all("pos" in graph.nodes[n] for nodes in areas.values() for n in nodes):
        sizes = sorted((len(nodes) for nodes in areas.values()), reverse=True)
        return (f"{terminal_count} terminals lie in {len(sizes)} disconnected areas, so they are joined by one tree "
                f"per area (the largest have {', '.join(map(str, sizes[:LISTED_AREAS]))} nodes).")
    summaries = sorted((area_summary(graph, nodes) + (nodes,) for nodes in areas.values()), key=lambda s: -s[0])
    listed = "; ".join(f"{size:.0f} m² near ({_xyz(where)})" for size, where, _ in summaries[:LISTED_AREAS])
    rest = summaries[LISTED_AREAS:]
    more = f"; {len(rest)} more with {sum(s[0] for s in rest):.0f} m² in all" if rest else ""
    message = (f"{terminal_count} terminals lie in {len(summaries)} disconnected areas, so they are joined by "
               f"one tree per area. Largest areas: {listed}{more}.")
    if agent is None or len(summaries) < 2:
        return message
    largest = summaries[0][2]
    gap, step, here, there, run = min((closest_step_for(graph, largest, other[2], agent) for other in summaries[1:1 + COMPARED_AREAS]),
                                      key=lambda pair: np.hypot(pair[0], pair[1]))
    return (f"{message} Likely cause: {likely_cause(step, gap, agent, run)}, "
            f"e.g. between ({_xyz(here)}) and ({_xyz(there)}).")


def _positions(graph: nx.Graph, nodes: Sequence[int]) -> np.ndarray:
    return np.asarray([graph.nodes[n]["pos"] for n in nodes], dtype=np.float64).reshape(-1, 3)


def _xyz(point: np.ndarray) -> str:
    return ", ".join(f"{round(float(v), 1) + 0.0:.1f}" for v in point) + " m"  # + 0.0: no "-0.0"
