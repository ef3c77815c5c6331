"""Does the walkable surface a graph builder found fit the level, or was the mesh misread?

A level read in the wrong frame (a Z-up file taken as Y-up) or wound inside
out (Recast and the sampler walk only on faces whose normal points up, so an
inside-out floor slab offers its underside, under its own top) still gives a
graph, but of the wrong surface or of a sliver of the level, and the run
looks like a success. Both graph builders (navmesh and sampling) call
:func:`check_walkable_surface` on their graph, and raise
:func:`no_walkable_surface` when they find nothing walkable.

The rule, from ``benchmarks/frame_check.py`` (table and justification in
docs/errors.md): a run is *suspicious* when its walkable area is less than
:data:`MIN_WALKABLE_SHARE` of the level's footprint, or less than
:data:`SMALL_MESH_SHARE` of it on a mesh of at most :data:`SMALL_MESH_FACES`
faces (:func:`looks_for_winding`), or when the level is more than
:data:`MAX_HEIGHT_RATIO` times as tall as its shorter horizontal side. A
suspicious run is warned about only when a cause is found
(:func:`likely_causes`): the level looks Z-up (:func:`looks_z_up`) and its
walkable surface does not show it upright (:func:`walks_upright`), or, for
a small share, closed bodies are wound inside out so that they hide their
floor (:func:`hidden_floor_bodies`; a room modelled as a box seen from
inside is wound inwards on purpose and does not count). No correct level
measured above :data:`SMALL_MESH_FACES` faces is suspicious, so on big
levels the check costs a sum over the nodes; the inside-out count (20 to
110 µs a face) runs only on the suspicious path and on the error.

A walkable surface more than :data:`MAX_SURFACE_OVER_FACES` times the plan
area of the faces that face up is refused: it stands on faces without area
(corners on a line), whose every touched cell Recast takes for floor.
Its cost: the first 65,536 faces' normals and areas on a correct level (a
hundredth of its upward area is enough to pass), all faces only on the way
to the refusal (0.6 s of CPU on 10^6).
"""

from __future__ import annotations

import math

import numpy as np

from g2s_core.config import AgentConfig
from g2s_core.errors import G2SError
from g2s_core.lazy import lazy_module
from g2s_core.mesh import flip_inside_out_bodies
from g2s_core.model import RunContext
from g2s_plugins._raycasting import UP, RayCaster

trimesh = lazy_module("trimesh")
nx = lazy_module("networkx")

MIN_WALKABLE_SHARE = 0.1
"""Walkable area over the footprint below which a run is suspicious: every correct level measured has
0.12 or more, the misread and inside-out ones it should catch 0.08 or less (docs/errors.md)."""

SMALL_MESH_FACES = 2000
"""Faces up to which a mesh is small: its inside-out count costs at most 0.04 to 0.4 s (20 to 190 µs a face),
so a share under :data:`SMALL_MESH_SHARE` is enough to look. The pieces, sample levels and ``nav_test.obj``
measured have 12 to 1,612 faces, the big levels 3,708 and more (docs/errors.md)."""

SMALL_MESH_SHARE = 0.5
"""Walkable share under which a small mesh is looked at for inside-out bodies: the damaged small runs measured
under it all warn (the inside-out Hallway piece: 0.152); correct ones under it (0.137 to 0.481) pay the count
and stay silent, as the cause test, not the share, keeps them so (docs/errors.md)."""

MAX_SURFACE_OVER_FACES = 100.0
"""Walkable area a graph builder found over the plan area of the mesh's faces that face up (within the agent's max
slope) above which the surface is refused (:func:`check_walkable_surface`): Recast marks every cell a face touches,
so faces with next to no area (corners on a line, to rounding) can cover a level's plan with floor. Measured
(docs/errors.md, robust8): 0.24 to 0.98 on the 47 sample levels, ``nav_test.obj`` and ``Ramp.obj`` (navmesh; 0.29 to
1.02 sampled); 4.3 to 42 on floors of bars 5 mm to 2 cm wide every 10 to 25 cm (Recast fills the gaps under a cell,
a walkable grating); 10^6 triangles with their corners on a line, alone: 416 m² of navmesh on 1.4e-10 m² of faces,
none facing up."""

MAX_AGAINST_NEIGHBOURS = 0.05
"""Share of the edges joining two faces that run the same way in both (faces wound against their neighbours: normals
a modeller left flipped) above which a misread run names it (:func:`wound_against_neighbours`): 0 on each of the 47
sample levels, ``nav_test.obj`` and the two shared pieces, 0.26 to 0.89 on the same with every other face flipped
(docs/errors.md, robust45)."""

RAY_START = 1e-3
"""Height over a face's centre the headroom ray of :func:`hidden_floor_bodies` starts at, metres: clear of the face."""

MAX_HEIGHT_RATIO = 2.0
"""Height over the shorter horizontal side above which a level is suspicious: the correct levels measured
reach 1.5, a level standing on its side 2.1 to 140 (docs/errors.md)."""

Z_UP_FLAT_AREA_RATIO = 3.0
"""Flat area along z over that along y above which a level looks Z-up whatever its shape: the correct
levels measured reach 2.2 (corridors: walls along z, no ceiling), the Z-up ones 1.0 to 24 (docs/errors.md).
A corridor along x whose walls are tall for its width reaches it too (the 15-degree sloped corridor: 3.3),
so the shape alone does not decide: :func:`walks_upright`."""

Z_UP_UNWALKED_RATIO = 4.0
"""Flat area along z over that along y above which a level no graph builder found a walkable surface on looks
Z-up. With no surface to show it upright (:func:`walks_upright`), the shape alone decides, so more of it than
:data:`Z_UP_FLAT_AREA_RATIO` asks: a tall piece read right has more wall than floor (a stairwell's landings too
narrow for the agent failed with the up-axis hint before 3 December 2026); the tall pieces measured reach 3.28,
the Z-up levels that fail so 5.09 and more (a platform on its side, ``Hallway.obj``'s file; docs/errors.md)."""

UPRIGHT_PIECE_SHARE = 0.7
"""Share of the walkable area in its largest connected piece from which that piece may show the level upright
(:func:`walks_upright`): the Z-up levels read as Y-up measured keep 0.65 or less in one piece (each wall's
side apart), the correct levels 1.00 but for a spiral stair whose top landing stands apart, 0.74
(docs/errors.md)."""

LEVEL_TILT = 5.0
"""Degrees from straight up within which a walkable node is level (:func:`climbs`): a wall's side read as a
floor leans 0, the ramps and stairs measured 8 and more; Recast's detail mesh leans a few nodes of level
floors up to 10 (``wall_tops``), so a piece climbs by leaning only over most of its area (docs/errors.md)."""


def footprint_area(mesh: trimesh.Trimesh) -> float:
    """Area of the mesh's axis-aligned bounding box seen from above (x by z), m²."""
    low, high = np.asarray(mesh.bounds)
    return float((high[0] - low[0]) * (high[2] - low[2]))


def walkable_area(graph: nx.Graph) -> float:
    """The area the graph's nodes stand for: their ``area`` summed, m²."""
    return math.fsum(area for _, area in graph.nodes(data="area", default=0.0))


def walkable_share(graph: nx.Graph, mesh: trimesh.Trimesh, walkable: float | None = None) -> float:
    """The :func:`walkable_area` of ``graph`` (``walkable`` when the caller has summed it) over the
    :func:`footprint_area`."""
    footprint = footprint_area(mesh)
    walkable = walkable_area(graph) if walkable is None else walkable
    return walkable / footprint if footprint > 0 else math.inf


UPWARD_BLOCK = 1 << 16
"""Faces :func:`upward_plan_area` adds up at a time before it looks whether it has ``enough``."""


def upward_plan_area(mesh: trimesh.Trimesh, max_slope: float, enough: float = math.inf) -> float:
    """Plan area (x by z, m²) of the mesh's faces within ``max_slope`` degrees of facing up (a face without area
    adds nothing), or a part of it of at least ``enough``: the faces are added :data:`UPWARD_BLOCK` at a time,
    and the sum stops once it reaches ``enough``.

    Why the blocks: the check that calls it needs only a hundredth of a correct level's upward area, which the
    first block gives; all faces at once cost 0.73 s of CPU on the 1.7 M faces of the 100k-polygon level
    (benchmarks/stage_times.py), 7 % of issue 9's 10 s.
    """
    vertices, faces = np.asarray(mesh.vertices, dtype=np.float64), np.asarray(mesh.faces)
    cos_slope, total = math.cos(math.radians(max_slope)), 0.0
    for start in range(0, len(faces), UPWARD_BLOCK):
        corners = vertices[faces[start:start + UPWARD_BLOCK]]
        cross = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])  # twice the area, along the normal
        up = cross[:, 1] >= cos_slope * np.sqrt(np.einsum("ij,ij->i", cross, cross))
        total += 0.5 * float(cross[up, 1].sum())
        if total >= enough:
            break
    return total


def height_ratio(mesh: trimesh.Trimesh) -> float:
    """The mesh's height (y extent) over its shorter horizontal (x, z) extent."""
    extent = np.ptp(np.asarray(mesh.bounds), axis=0)
    shorter = min(extent[0], extent[2])
    return float(extent[1] / shorter) if shorter > 0 else math.inf


def flat_area_ratio(mesh: trimesh.Trimesh, max_slope: float) -> float:
    """Area of the faces within ``max_slope`` degrees of ±z over that of the faces within it of ±y.

    Read in its own frame a level's flat faces are floors and ceilings (±y);
    a Z-up level read as Y-up has them facing along z.
    """
    normals = np.abs(np.asarray(mesh.face_normals))
    areas = np.asarray(mesh.area_faces)
    flat = math.cos(math.radians(max_slope))
    along_y = areas[normals[:, 1] >= flat].sum()
    along_z = areas[normals[:, 2] >= flat].sum()
    return float(along_z / along_y) if along_y > 0 else math.inf if along_z > 0 else 0.0  # no flat face: no frame


def looks_z_up(mesh: trimesh.Trimesh, max_slope: float) -> bool:
    """Whether ``mesh`` looks like a Z-up level read as Y-up.

    That is: more than :data:`Z_UP_FLAT_AREA_RATIO` times as much flat area
    along z as along y, or more at all on a level taller than
    :data:`MAX_HEIGHT_RATIO` times its shorter horizontal side.
    """
    ratio = flat_area_ratio(mesh, max_slope)
    return ratio > Z_UP_FLAT_AREA_RATIO or (ratio > 1 and height_ratio(mesh) > MAX_HEIGHT_RATIO)


def walks_upright(graph: nx.Graph, mesh: trimesh.Trimesh, agent: AgentConfig) -> bool:
    """Whether the walkable surface ``graph`` found on ``mesh`` shows the level read upright.

    A Z-up level read as Y-up walks on the sides of its walls: level patches,
    each apart at its own height, as the floors that joined them stand on
    edge. So the level is upright when its walkable surface covers at least
    :data:`MIN_WALKABLE_SHARE` of the footprint, at least
    :data:`UPRIGHT_PIECE_SHARE` of it lies in one connected piece
    (:func:`largest_piece`), and that piece :func:`climbs`. Landings joined
    only by a lift, or a single level floor, do not show it.
    """
    if walkable_share(graph, mesh) < MIN_WALKABLE_SHARE:
        return False
    share, nodes = largest_piece(graph)
    return share >= UPRIGHT_PIECE_SHARE and climbs(nodes, agent)


def largest_piece(graph: nx.Graph) -> tuple[float, list[dict]]:
    """The share of the graph's walkable area (the nodes' ``area``) in its largest connected piece (0 for a
    graph without area), and that piece's node attributes."""
    pieces = [[graph.nodes[node] for node in piece] for piece in nx.connected_components(graph)]
    areas = [math.fsum(node.get("area", 0.0) for node in piece) for piece in pieces]
    total = math.fsum(areas)
    if total <= 0:
        return 0.0, []
    largest = int(np.argmax(areas))
    return areas[largest] / total, pieces[largest]


def climbs(nodes: list[dict], agent: AgentConfig) -> bool:
    """Whether walkable nodes (their ``pos``, ``normal`` and ``area``) span more than ``agent.max_climb`` in
    height, or those leaning more than :data:`LEVEL_TILT` from straight up hold most of their area (a ramp
    can be one navmesh polygon)."""
    if not nodes:
        return False
    heights = [node["pos"][1] for node in nodes]
    areas = np.array([node.get("area", 0.0) for node in nodes])
    leaning = np.array([node.get("normal", UP)[1] < math.cos(math.radians(LEVEL_TILT)) for node in nodes])
    return max(heights) - min(heights) > agent.max_climb or 2 * areas[leaning].sum() > areas.sum()


def inside_out_bodies(mesh: trimesh.Trimesh) -> int:
    """How many closed bodies of ``mesh`` are wound inside out: against their nesting
    (:func:`g2s_core.mesh.flip_inside_out_bodies`: negative signed volume where no closed body holds them; a room in
    a closed building is wound inward as it should be).

    Coincident vertices are merged first (on a copy), so that a body written
    with split vertices (an OBJ's per-face normals) is still one closed body.
    """
    return len(_inside_out_faces(mesh)[1])


def hidden_floor_bodies(mesh: trimesh.Trimesh, agent: AgentConfig) -> int:
    """How many closed bodies of ``mesh`` are wound inside out *and* hide their floor that way.

    A closed body wound inside out (:func:`inside_out_bodies`; one that no
    closed body holds has a negative signed volume) is either a solid wound
    inside out, whose upturned underside lies under its own top, or a room
    modelled as a closed box seen from inside, whose floor faces up into the
    room on purpose. Cast up from each of the body's faces
    that face up (within ``agent.max_slope``), the first face of ``mesh`` above
    lies less than ``agent.height`` over the solid's underside (the agent cannot
    stand in a slab) and more over the room's floor (else it is no room). A body
    counts when more of its up-facing area has less than that headroom.
    Cost: :func:`inside_out_bodies` (20 to 110 µs a face) and one ray a face.
    """
    merged, bodies = _inside_out_faces(mesh)
    body_of = np.full(len(merged.faces), -1)
    for index, faces in enumerate(bodies):
        body_of[faces] = index
    up = np.flatnonzero((body_of >= 0) & (merged.face_normals[:, 1] >= math.cos(math.radians(agent.max_slope))))
    origins = merged.triangles_center[up] + RAY_START * UP
    headroom = RayCaster(merged).first_hits(origins, UP).distance + RAY_START  # inf where nothing is above
    area = merged.area_faces[up]
    cramped = np.bincount(body_of[up], weights=area * (headroom < agent.height), minlength=len(bodies))
    return int(np.count_nonzero(2 * cramped > np.bincount(body_of[up], weights=area, minlength=len(bodies))))


def _inside_out_faces(mesh: trimesh.Trimesh) -> tuple[trimesh.Trimesh, list[np.ndarray]]:
    """``mesh`` with coincident vertices merged, and the face indices of each of its closed bodies wound
    inside out (those :func:`g2s_core.mesh.flip_inside_out_bodies` flips)."""
    merged = trimesh.Trimesh(np.asarray(mesh.vertices), np.asarray(mesh.faces), process=True)
    return merged, flip_inside_out_bodies(merged)[1]


GENERAL_HINT = ("check mesh.scale (the file's units to metres), the agent settings, the mesh's up_axis, and that its "
                "floors' faces face up (their winding)")

ZERO_AREA_HINT = "every face has zero area (its corners on a line or at one point): the file holds no surface; export it again"

UP_AXIS_HINT = ("most flat faces face along z, not y: if the file is Z-up, set `mesh: {up_axis: z}` "
                "(or `y` if it is already z)")


def has_no_area(mesh: trimesh.Trimesh) -> bool:
    """Whether no face of ``mesh`` has area in the single precision the graph builders read it in: each face's
    height (twice its area over its longest edge, m) is at most the spacing of single-precision numbers at the
    mesh's largest coordinate, so its corners lie on a line or at one point, exactly or to the rounding of the
    file's digits (10^6 such triangles measured, docs/errors.md robust8)."""
    triangles = np.asarray(mesh.triangles)
    longest = np.sqrt(np.max(np.sum((triangles - np.roll(triangles, 1, axis=1)) ** 2, axis=2), axis=1))
    resolution = np.finfo(np.float32).eps * float(np.max(np.abs(triangles), initial=0.0))
    return bool(np.all(2 * np.asarray(mesh.area_faces) <= resolution * longest))


def likely_causes(mesh: trimesh.Trimesh, agent: AgentConfig, winding: bool = True,
                  graph: nx.Graph | None = None) -> list[str]:
    """What most likely made the walkable surface wrong for ``agent``, each naming the key to change.

    ``winding``: also look for closed bodies wound inside out that hide their floor
    (:func:`hidden_floor_bodies`, the costly check). ``graph``: the walkable surface found, if any:
    one that :func:`walks_upright` clears the up axis; without one, only a flat area along z over
    :data:`Z_UP_UNWALKED_RATIO` times that along y names it.
    """
    if has_no_area(mesh):  # a degenerate export, whatever its frame or winding
        return [ZERO_AREA_HINT]
    if graph is None:
        z_up = flat_area_ratio(mesh, agent.max_slope) > Z_UP_UNWALKED_RATIO
    else:
        z_up = looks_z_up(mesh, agent.max_slope) and not walks_upright(graph, mesh, agent)
    causes = [UP_AXIS_HINT] if z_up else []
    bodies = hidden_floor_bodies(mesh, agent) if winding else 0
    if bodies:
        causes.append(f"{bodies} closed bod{'y is' if bodies == 1 else 'ies are'} wound inside out "
                      "(walkable faces must face up): set `mesh: {clean: true}` to flip them")
    if winding and (against := wound_against_neighbours(mesh)) > MAX_AGAINST_NEIGHBOURS:
        causes.append(f"{100 * against:.0f} % of the edges between two faces join faces wound opposite ways (normals "
                      "flipped in the modeller; walkable faces must face up): set `mesh: {clean: true}` to wind each body one way")
    return causes


def wound_against_neighbours(mesh: trimesh.Trimesh) -> float:
    """Share of the edges joining exactly two faces of ``mesh`` (coincident vertices merged, on a copy) that run the
    same way in both, whose faces are wound opposite ways; 0 when no edge joins two faces. O(faces log faces)."""
    merged = trimesh.Trimesh(np.asarray(mesh.vertices), np.asarray(mesh.faces), process=True)
    pairs = trimesh.grouping.group_rows(merged.edges_sorted, require_count=2)
    edges = merged.edges[pairs]  # (pairs, 2 faces, 2 corners): wound one way, the second face runs the edge backwards
    return float(np.mean(np.all(edges[:, 0] == edges[:, 1], axis=1))) if len(pairs) else 0.0


def level_size(mesh: trimesh.Trimesh) -> str:
    """The mesh's extent in words: ``2.02 x 2.1 m (x, z), 0.176 m tall``."""
    extent = np.ptp(np.asarray(mesh.bounds), axis=0)
    return f"{extent[0]:.3g} x {extent[2]:.3g} m (x, z), {extent[1]:.3g} m tall"


def no_walkable_surface(mesh: trimesh.Trimesh, agent: AgentConfig, reason: str) -> G2SError:
    """The error of a graph builder that found nowhere ``agent`` can stand on ``mesh``: the agent,
    the builder's ``reason``, then the likely causes, else the level's size (a file in other units
    than metres shows in it: a 200 m level read at ``mesh.scale: 0.01`` is 2 m across) and what to check."""
    causes = likely_causes(mesh, agent)
    return G2SError(
        f"no walkable surface for the agent (radius {agent.radius} m, height {agent.height} m, "
        f"max climb {agent.max_climb} m, max slope {agent.max_slope} deg): {reason}; "
        + ("; ".join(causes) if causes else f"the level is {level_size(mesh)}: {GENERAL_HINT}")
    )


def looks_for_winding(share: float, faces: int) -> bool:
    """Whether a run whose walkable share is ``share`` on a mesh of ``faces`` faces is worth the inside-out count:
    under :data:`MIN_WALKABLE_SHARE` on any mesh, under :data:`SMALL_MESH_SHARE` on one of at most
    :data:`SMALL_MESH_FACES` faces."""
    return share < MIN_WALKABLE_SHARE or (faces <= SMALL_MESH_FACES and share < SMALL_MESH_SHARE)


def check_walkable_surface(graph: nx.Graph, mesh: trimesh.Trimesh, context: RunContext) -> None:
    """Warn through ``context`` (one line) when ``graph``'s walkable surface looks like a misread mesh (module doc).

    Raises:
        G2SError: the surface is more than :data:`MAX_SURFACE_OVER_FACES` times the plan area of the faces
            that face up: it stands on faces with next to no area, and the file holds no floor to walk on.
    """
    walkable = walkable_area(graph)
    faces = upward_plan_area(mesh, context.agent.max_slope, enough=walkable / MAX_SURFACE_OVER_FACES)
    if walkable > MAX_SURFACE_OVER_FACES * faces:
        raise G2SError(
            f"the walkable surface found ({walkable:.3g} m²) is more than {MAX_SURFACE_OVER_FACES:g} times the plan "
            f"area of the faces that face up ({faces:.3g} m²): the faces have next to no area (corners on a line or "
            "at one point) and the graph builder filled the cells they touch; export the mesh again"
        )
    share = walkable_share(graph, mesh, walkable)  # the area summed once
    winding, tall = looks_for_winding(share, len(mesh.faces)), height_ratio(mesh) > MAX_HEIGHT_RATIO
    if not (winding or tall):
        return
    causes = likely_causes(mesh, context.agent, winding=winding, graph=graph)
    if not causes:
        return
    walkable = f"{100 * share:.1f} % of the level's footprint is walkable"
    what = (f"only {walkable}" if share < MIN_WALKABLE_SHARE else
            walkable if not tall else f"the level is {height_ratio(mesh):.1f} times as tall as it is wide")
    context.warn(f"mesh: {what}; {'; '.join(causes)}")
