"""The warning a designer reads when the terminals lie in areas no walk joins.

It says how many areas there are, how much walkable surface the largest ones
hold and where they are (metres), what most likely separates them, and stays
short whatever the number of areas (at most :data:`LISTED_AREAS` are named).

The likely cause is the graph builder's to tell (``context.likely_cause``,
:func:`g2s_plugins.area_gaps.likely_cause_of`): it is handed the largest area
and every other, largest first, and measures the gap between the walkable
ground of the largest and the nearest of those a designer means to join to
it, which takes the builder's surface (its polygons' edges, its erosion),
not only the graph's nodes.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from typing import Any

import networkx as nx
import numpy as np

LISTED_AREAS = 3
"""How many of the largest areas the warning places."""


def area_summary(graph: nx.Graph, nodes: Sequence[int]) -> tuple[float, np.ndarray]:
    """``(walkable area in m², a node position inside the area)`` of a connected set of nodes.

    The position is that of the node nearest the area-weighted centre, so it
    lies in the area even when the area is not convex.
    """
    points = np.asarray([graph.nodes[n]["pos"] for n in nodes], dtype=np.float64).reshape(-1, 3)
    weights = np.asarray([float(graph.nodes[n].get("area", 0.0)) for n in nodes])
    total = float(weights.sum())
    centre = (weights @ points) / total if total > 0 else points.mean(axis=0)
    return total, points[int(np.argmin(np.linalg.norm(points - centre, axis=1)))]


def disconnected_warning(graph: nx.Graph, areas: Mapping[Any, Sequence[int]], terminal_count: int,
                         likely_cause: Callable[[nx.Graph, Sequence[int], Sequence[Sequence[int]]], str] | None,
                         waypoint_count: int = 0) -> str:
    """The warning for terminals (and a selector's waypoints) spread over the connected ``areas`` (area id -> its
    nodes) of ``graph``; the counts are those the outputs give, a count of zero left out of the message.

    ``likely_cause(graph, largest area, the others largest first)`` names what most likely parts them and where; without it
    the cause is left out, and without node positions (an abstract graph) the places too.
    """
    apart = " and ".join(f"{count} {noun}{'s' * (count != 1)}" for count, noun in
                         ((terminal_count, "terminal"), (waypoint_count, "waypoint")) if count)
    if not all("pos" in graph.nodes[n] for nodes in areas.values() for n in nodes):
        sizes = sorted((len(nodes) for nodes in areas.values()), reverse=True)
        return (f"{apart} lie in {len(sizes)} disconnected areas, so they are joined by one tree "
                f"per area (the largest have {', '.join(map(str, sizes[:LISTED_AREAS]))} nodes).")
    summaries = sorted((area_summary(graph, nodes) + (nodes,) for nodes in areas.values()), key=lambda s: -s[0])
    listed = "; ".join(f"{size:.0f} m² near ({xyz(where)})" for size, where, _ in summaries[:LISTED_AREAS])
    rest = summaries[LISTED_AREAS:]
    more = f"; {len(rest)} more with {sum(s[0] for s in rest):.0f} m² in all" if rest else ""
    message = (f"{apart} lie in {len(summaries)} disconnected areas, so they are joined by "
               f"one tree per area. Largest areas: {listed}{more}.")
    if likely_cause is None or len(summaries) < 2:
        return message
    return f"{message} Likely cause: {likely_cause(graph, summaries[0][2], [other[2] for other in summaries[1:]])}."


def xyz(point: np.ndarray) -> str:
    """A place as the warning prints it, ``x, y, z m`` to 0.1 m."""
    return ", ".join(f"{round(float(v), 1) + 0.0:.1f}" for v in point) + " m"  # + 0.0: no "-0.0"
