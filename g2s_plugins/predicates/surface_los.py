"""Surface LoS: remove B when A sees C across the navigation mesh and the surface does not bend at B (Algorithm 5).

For a chain A -> B -> C of a rooted tree, ``P(tree, A, B, C)`` keeps B
(returns False) when

1. C is a leaf (no children) that is not on the navigation mesh: a
   line-of-sight test on the navmesh surface means nothing for a point off
   it (e.g. an entry/exit point added outside the mesh);
2. the angle between the surface normals at A and B exceeds
   ``normal_tolerance_deg``: removing B would cut across a change of slope
   (the start of a ramp or stairs) and the structure would leave the surface;
   a zero-length normal counts as exceeding it;
3. the Detour raycast from A to C over ``context.navmesh`` is blocked.

Otherwise it returns True (B may go). The paper's pseudocode (Algorithm 5)
writes the third test backwards: it sets ``canCollapse = false`` when there
*is* line of sight, and its last line sets ``canCollapse = true``
unconditionally. Its text (Sec. 3.1.5) states the intent implemented here:
collapse only when A and C see each other on the navmesh surface.

Default tolerance, 10 degrees: Recast quantises heights to the cell height,
which tilts the polygons of a flat floor by a few degrees at most, and such
noise must not block a simplification (the Hub 5 artefact in the paper's results);
walkable ramps in levels are usually 15 to 45 degrees steep (the default
agent climbs up to 45), so 10 degrees still keeps a node where one begins.

Cost per call: one navmesh raycast, O(polygons crossed).
"""

from __future__ import annotations

import math
from collections.abc import Callable

import networkx as nx
from pydantic import Field

from g2s_core.errors import PluginError
from g2s_core.model import RunContext
from g2s_core.plugin import PluginParams, hookimpl

NAME = "surface_los"


class Params(PluginParams):
    """How much the surface may bend at a removed node."""

    normal_tolerance_deg: float = Field(
        10.0, ge=0, le=180, description="largest angle between the normals at A and B that still lets B go, degrees"
    )


def normals_angle_deg(a: tuple[float, float, float], b: tuple[float, float, float]) -> float:
    """Angle between two normals in degrees; ``inf`` when either has zero length.

    Plain floats rather than numpy: it runs once per predicate call, on 3-vectors.
    """
    lengths = math.hypot(*a) * math.hypot(*b)
    if not lengths > 0:
        return math.inf
    cosine = (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / lengths
    return math.degrees(math.acos(min(1.0, max(-1.0, cosine))))


@hookimpl
def g2s_simplify_predicate(params: Params, context: RunContext) -> Callable[[nx.DiGraph, int, int, int], bool]:
    """The predicate of Algorithm 5 over ``context.navmesh``.

    Raises:
        PluginError: the run has no navigation mesh.
    """
    navmesh = context.navmesh
    if navmesh is None:
        raise PluginError("surface_los needs a navigation mesh; use the navmesh graph builder or the mesh_los predicate")
    tolerance = params.normal_tolerance_deg

    def predicate(tree: nx.DiGraph, a: int, b: int, c: int) -> bool:
        node_c = tree.nodes[c]
        if tree.out_degree(c) == 0 and not node_c.get("on_navmesh", False):
            return False
        if normals_angle_deg(tree.nodes[a]["normal"], tree.nodes[b]["normal"]) > tolerance:
            return False
        clear, _t = navmesh.raycast(tree.nodes[a]["pos"], node_c["pos"])
        return clear

    return predicate
