"""Is the level in metres, or in centimetres (millimetres) read as metres?

A file in other units than metres runs without a word when it stays under the
navmesh's grid guard (``graph.params.max_level_cells``): a 20 m room with a
stair of five 0.2 m steps, exported in centimetres, is a room 2 km across with
steps 20 m tall, and gives thousands of nodes of wall tops and step tops the
agent cannot reach. Both built-in graph builders call :func:`check_units`
before they build, and warn when the level's *storeys* are out of proportion
to the agent.

The storeys: the mesh's faces within :data:`LEVEL_DEGREES` of facing straight
up (floors, step treads, landings, wall tops, roofs) lie at a few heights, and
each height above the lowest stands some distance over the next one below: a
step's riser, a slab's thickness, a storey, a wall's height. Their
:data:`GAP_QUANTILE` (weighted by the faces' area) is a length the level's
builders chose for people; read from centimetres every one of them is a
hundred times longer. The rule, measured on generated levels in metres and at
100 and 1000 times their size (``benchmarks/units_check.py``, docs/errors.md):
the levels in metres reach 4.75 agent heights (a hall's 9.5 m walls), the same
levels at 100 times their size (centimetres) reach more than
:data:`MAX_STOREY_HEIGHTS` agent heights unless nearly all their flat heights lie
closer than 0.16 m (a terrain, a helical ramp), and a level with a single flat
height (a flat plane, a slab) cannot be told.

Cost: one pass over at most :data:`SAMPLED_FACES` faces (a stride through the
mesh's faces), 0.04 s of CPU on the 1.7 M faces of the 100k-polygon level.
"""

from __future__ import annotations

import math

import numpy as np
import trimesh

from g2s_core.model import RunContext

LEVEL_DEGREES = 1.0
"""Degrees from straight up within which a face is level: a floor, a tread, a wall's top. Ramps and terrain lean
more and hold no storey."""

HEIGHT_TOLERANCE = 1e-4
"""Share of the level's largest extent within which two level faces' heights are one height (an export's rounding,
a floor written in pieces): 2 mm on a 20 m room, and the same share of it in any units."""

GAP_QUANTILE = 0.75
"""Quantile of the gaps between the level's flat heights (weighted by the area at the upper height) the rule reads:
the upper quartile, so that the risers of a few stairs and a ramp's landings do not hide the storeys."""

MAX_STOREY_HEIGHTS = 7.0
"""Agent heights over which the :data:`GAP_QUANTILE` gap says the file is not in metres: the generated levels in
metres measured reach 4.75 (docs/errors.md, a hall's walls 9.5 m over its floor), the rooms of the sample levels 1.5,
and read from centimetres they are 150."""

SAMPLED_FACES = 1 << 17
"""Faces the check reads at most: every k-th face of a larger mesh (k the smallest stride that fits), so that the
check costs little on a level of millions of faces; a stride leaves some heights out, which only widens gaps that
are already many to a metre on such a level (docs/errors.md)."""


def storey_gap(mesh: trimesh.Trimesh) -> float | None:
    """The :data:`GAP_QUANTILE` of the vertical gaps between the distinct heights of ``mesh``'s level faces, m
    (module doc); ``None`` when its level faces lie at one height (a flat plane) or it has none.

    Complexity: O(n log n) for the n faces read (at most :data:`SAMPLED_FACES`).
    """
    faces = np.asarray(mesh.faces)
    faces = faces[::max(1, math.ceil(len(faces) / SAMPLED_FACES))]
    vertices = np.asarray(mesh.vertices, dtype=np.float64)
    corners = vertices[faces]  # (n, 3, 3)
    cross = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])  # twice the area, along the normal
    doubled = np.sqrt(np.einsum("ij,ij->i", cross, cross))
    level = cross[:, 1] > math.cos(math.radians(LEVEL_DEGREES)) * doubled
    heights, areas = corners[level, :, 1].mean(axis=1), 0.5 * doubled[level]
    order = np.argsort(heights, kind="stable")
    heights, areas = heights[order], areas[order]
    starts = np.flatnonzero(np.diff(heights) > HEIGHT_TOLERANCE * float(np.max(np.ptp(vertices, axis=0)))) + 1
    if len(starts) == 0:
        return None
    gaps = np.diff(heights[np.r_[0, starts]])  # from each height's lowest face to the one below's
    held = np.add.reduceat(areas, np.r_[0, starts])  # the area at each height
    weights = np.minimum(held[:-1], held[1:])  # a gap counts as the smaller of the surfaces it parts
    if not weights.sum() > 0:
        return None
    order = np.argsort(gaps, kind="stable")
    cumulative = np.cumsum(weights[order])
    return float(gaps[order][np.searchsorted(cumulative, GAP_QUANTILE * cumulative[-1])])


def check_units(mesh: trimesh.Trimesh, context: RunContext) -> None:
    """Warn through ``context`` (one line, naming the level) when ``mesh``'s storeys are more than
    :data:`MAX_STOREY_HEIGHTS` times the agent's height: a file in centimetres or millimetres read as metres."""
    gap = storey_gap(mesh)
    if gap is None or gap <= MAX_STOREY_HEIGHTS * context.agent.height:
        return
    context.warn(
        f"mesh: {context.mesh_name}: its level surfaces (floors, treads, wall tops) lie {gap:.3g} m over one another "
        f"(upper quartile), {gap / context.agent.height:.0f} times the agent's height of {context.agent.height:g} m, "
        "as in a file in centimetres read as metres; if it is one, set mesh.scale: 0.01 (millimetres: 0.001)"
    )
