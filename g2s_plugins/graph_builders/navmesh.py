"""Surface graph from a Recast/Detour navmesh: one node per polygon, one edge per shared edge.

Builds a navmesh of the mesh for the run's agent (solo or tiled, see
:mod:`g2s_plugins.recast` and its ``tile_size`` parameter), stores it in
``context.navmesh`` and returns the polygon adjacency graph:

* node ``i`` = polygon ``i``: ``pos`` (centroid on the detail surface),
  ``normal``, ``area`` (m²), ``on_navmesh=True``, ``polygon=i``;
* edge ``(a, b)``, ``a < b``, for each pair of polygons sharing an edge
  (or, across a tile border, part of one): ``weight`` (distance between the
  two ``pos``), ``portal`` (the shared segment's two end points, mesh
  vertices) and ``width`` (its length).

Nodes are inserted by polygon index and edges sorted by ``(a, b)``.
"""

from __future__ import annotations

import networkx as nx
import numpy as np

from g2s_core.errors import G2SError
from g2s_core.plugin import hookimpl
from g2s_plugins.recast import NavMesh, RecastParams, SettingsError, build_navmesh

NAME = "navmesh"


class Params(RecastParams):
    """Recast build parameters (see :class:`g2s_plugins.recast.RecastParams`)."""


def navmesh_graph(navmesh: NavMesh) -> nx.Graph:
    """The polygon adjacency graph of ``navmesh`` (the conventions of g2s_core.model)."""
    centres = navmesh.centres
    normals = navmesh.normals
    areas = navmesh.areas
    portals = navmesh.portals()
    pairs = portals.pairs
    weights = np.linalg.norm(centres[pairs[:, 1]] - centres[pairs[:, 0]], axis=1) if len(pairs) else np.zeros(0)

    # Plain Python values, converted in bulk (tolist) rather than per element.
    pos = [tuple(p) for p in centres.tolist()]
    nrm = [tuple(n) for n in normals.tolist()]
    area = areas.tolist()
    graph = nx.Graph()
    graph.add_nodes_from(
        (i, {"pos": pos[i], "normal": nrm[i], "area": area[i], "on_navmesh": True, "polygon": i})
        for i in range(navmesh.polygon_count)
    )
    ends = portals.endpoints.tolist()
    graph.add_edges_from(
        (a, b, {"weight": w, "portal": (tuple(e[0]), tuple(e[1])), "width": wd})
        for (a, b), w, e, wd in zip(pairs.tolist(), weights.tolist(), ends, portals.widths.tolist())
    )
    return graph


@hookimpl
def g2s_build_graph(mesh, params, context):
    """Build the navmesh of ``mesh`` for ``context.agent`` and return its polygon graph.

    Raises:
        G2SError: a setting or the level's size that Recast cannot handle
            (naming the key), a Recast step that fails on this input, or no
            surface this agent can walk: properties of the input and the
            settings, not failures of the program.
    """
    params = params if params is not None else Params()
    try:
        navmesh = build_navmesh(mesh.vertices, mesh.faces, context.agent, params)
    except SettingsError as exc:
        raise G2SError(str(exc)) from exc
    except RuntimeError as exc:
        if "no walkable" not in str(exc):
            raise G2SError(
                f"graph.params: {exc}; try another cell_size or tile_size (see docs/navmesh.md)"
            ) from exc
        agent = context.agent
        raise G2SError(
            f"no walkable surface for the agent (radius {agent.radius} m, height {agent.height} m, "
            f"max climb {agent.max_climb} m, max slope {agent.max_slope} deg): {exc}; "
            f"{_up_axis_hint(mesh, agent.max_slope)}"
        ) from exc
    context.navmesh = navmesh
    return navmesh_graph(navmesh)


def _up_axis_hint(mesh, max_slope: float) -> str:
    """What to check when nothing is walkable: the up axis when the faces that
    could be floors face along z rather than y, else the agent and the scale."""
    normals = np.asarray(mesh.face_normals)
    areas = np.asarray(mesh.area_faces)
    level = np.cos(np.radians(max_slope))
    along_y = areas[np.abs(normals[:, 1]) >= level].sum()
    along_z = areas[np.abs(normals[:, 2]) >= level].sum()
    if along_z > along_y:
        return ("most flat faces face along z, not y: if the file is Z-up, set `mesh: {up_axis: z}` "
                "(or `y` if it is already z)")
    return "check the agent settings and the mesh's up_axis and scale"
