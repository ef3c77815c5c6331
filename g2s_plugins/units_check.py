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
step's riser, a slab's thickness, a storey, a wall's height. Each gap weighs
the smaller of the two surfaces it parts, and their :data:`GAP_QUANTILE` is a
length the level's builders chose for people; read from centimetres it is a
hundred times longer. Measured on generated levels in metres and at 39.37, 100
and 1000 times their size (``benchmarks/units_check.py``, table in
docs/errors.md, "Centimetres told from metres"): the 425 levels in metres that
can be told reach 4.8 agent heights, and 394 of them read from centimetres
reach more than :data:`MAX_STOREY_HEIGHTS`, all of them from millimetres. A
level with a single flat height (a flat plane, a slab) cannot be told.

Cost: one pass over at most :data:`SAMPLED_FACES` faces (a seeded random choice
of a larger mesh's faces), 0.07 s of CPU on the 1.7 M faces of the 100k-polygon level.
"""

from __future__ import annotations

import math

import numpy as np

from g2s_core.lazy import lazy_module
from g2s_core.model import RunContext

trimesh = lazy_module("trimesh")

LEVEL_DEGREES = 1.0
"""Degrees from straight up within which a face is level: a floor, a tread, a wall's top. Ramps and terrain lean
more and hold no storey."""

HEIGHT_TOLERANCE = 1e-4
"""Share of the level's largest extent within which two level faces' heights are one height (an export's rounding,
a floor written in pieces): 2 mm on a 20 m room, and the same share of it in any units."""

GAP_QUANTILE = 0.75
"""Quantile of the gaps between the level's flat heights (each weighing the smaller of the surfaces it parts) the rule
reads: the upper quartile, so that the risers of a few stairs and a ramp's landings do not hide the storeys."""

MAX_STOREY_HEIGHTS = 7.0
"""Agent heights over which the :data:`GAP_QUANTILE` gap says the file is not in metres: the generated levels in
metres measured reach 4.8 (a backdrop's 9.6 m, docs/errors.md), the rooms of the sample levels 1.5; read from
centimetres the levels whose gap at their true size is over 0.14 m warn, 394 of 425 measured."""

MIN_PARTED_AREA = 1.0
"""Square metres (in the file's units read as metres) of level surface the gaps must part, summed over the gaps as
they are weighed, for the level to be told: a storey holds at least where an agent stands (the presets' agent's
footprint is 0.79 m²). Under it the level faces are slivers, such as the few cells of a cave's sloping terrain that
come out level (round 34's scree cave of seed 1: two faces of 0.1 m² under a rock top 16 m over them read as a
16 m storey), and the level cannot be told, as a level of one flat height cannot (docs/analysis_quality.md, "A
thirty-fourth round of level kinds")."""

SAMPLED_FACES = 1 << 17
"""Faces the check reads at most: a seeded random choice of a larger mesh's faces, so that the check costs about
0.07 s of CPU, not 0.37 s, on the 1.7 M faces of the 100k-polygon level. Random, not every k-th face: a level built
of one repeated module has a period in its face order, which a stride can meet so that it reads no roof at all (a
city of 12,000 box houses, 144,012 faces, read every 2nd face: no level face)."""


def storey_gap(mesh: trimesh.Trimesh, min_parted_area: float = MIN_PARTED_AREA) -> float | None:
    """The :data:`GAP_QUANTILE` of the vertical gaps between the distinct heights of ``mesh``'s level faces, m
    (module doc); ``None`` when its level faces lie at one height (a flat plane), it has none, or the gaps part
    less than ``min_parted_area`` m² of them, weighed as the quantile weighs them (:data:`MIN_PARTED_AREA`).

    Complexity: O(n log n) for the n faces read (at most :data:`SAMPLED_FACES`).
    """
    faces = np.asarray(mesh.faces)
    if len(faces) > SAMPLED_FACES:
        faces = faces[np.sort(np.random.default_rng(0).choice(len(faces), SAMPLED_FACES, replace=False))]
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
    if not weights.sum() > max(min_parted_area, 0.0):
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
        "as in a file in centimetres read as metres; if it is one, set mesh.scale: 0.01 (millimetres: 0.001; inches: 0.0254)"
    )
