"""Recast/Detour navigation meshes: parameters, build, and Detour queries.

The compiled extension :mod:`g2s_plugins.recast._recast` (nanobind, linked
against the system's Recast/Detour, Debian ``librecast-dev``) builds a navmesh
with Recast's standard pipeline, *solo* (one tile) or *tiled* (square tiles
built in parallel and joined in one Detour navmesh), and keeps the Detour
navmesh and query object for raycasts and nearest-polygon look-ups.

* :mod:`.settings`: :class:`RecastParams` (every build parameter, with
  defaults), the cell size rule and the voxel values derived from it;
* :mod:`.build`: :func:`build_navmesh` (triangles + agent + params ->
  :class:`NavMesh`), the tiling rule and the memory guard;
* :mod:`.navmesh`: :class:`NavMesh` (the mesh arrays, per-polygon centres /
  normals / areas, shared edges (portals) and the Detour queries).

Coordinates are metres with Y up, as in the mesh.
"""

from __future__ import annotations

from .build import build_navmesh
from .navmesh import DT_VERTS_PER_POLYGON, FLT_MAX, NavMesh, Portals
from .settings import MIN_TILE_SIZE, RecastParams, SettingsError, resolve_settings, voxel_config

__all__ = [
    "RecastParams",
    "NavMesh",
    "Portals",
    "SettingsError",
    "build_navmesh",
    "resolve_settings",
    "voxel_config",
    "FLT_MAX",
    "DT_VERTS_PER_POLYGON",
    "MIN_TILE_SIZE",
]
