"""The ledge filters (Recast's, its first rule alone, none) against generated cases with known answers
(docs/navmesh.md, "Ledge filter in the presets" and "The drops-only ledge filter").

Run: ``.venv/bin/python benchmarks/ledge_filter.py``

Every case is built on the two grids of the product presets, each with its
preset's agent (:data:`GRIDS`), with each ``ledge_filter`` of :data:`FILTERS`:
``recast`` (Recast's demo setting), ``drops`` (its first rule alone) and
``off``. The known answers:

- two floors 2 m apart joined by a ramp (4 m wide, open sides) are joined
  iff the ramp is no steeper than the agent's ``max_slope``;
- two floors joined by a flight of solid steps (open sides) are joined iff
  the riser is no higher than the agent's ``max_climb``; a single step
  likewise;
- a wall across a corridor floor, just higher than the climb, is not
  crossed;
- on a platform 1 m above the ground the navmesh keeps at least the agent's
  radius from the platform's edge, less half a cell (erosion works in whole
  cells): the least over the platform moved by 0, 1/8, ..., 7/8 of a cell
  against the grid (the ground fixes the grid's origin), since where an edge
  falls in its cell decides how far Recast's conservative voxels overhang it.

"joined" is a path over Detour's polygon links (:meth:`NavMesh.portals`)
between the polygons nearest the two floors' middles. Without a ledge
filter Recast's links and erosion still keep the agent off steps and walls
over the climb (``rcBuildCompactHeightfield`` links two spans only when their
floors differ by at most ``walkableClimb``; ``rcErodeWalkableArea`` treats a
span with a missing link as a border), but erosion counts the radius from the
voxels, which overhang a drop by up to a cell: the clearance table shows it
(the first rule, kept by ``drops``, removes the overhanging cell).
This is a benchmark: nothing here asserts.
"""

from __future__ import annotations

import math
import types
from typing import Any

import networkx as nx
import numpy as np
import trimesh

from g2s_plugins.recast import NavMesh, RecastParams, build_navmesh

GRIDS: dict[str, tuple[types.SimpleNamespace, dict[str, Any]]] = {
    "map_analysis": (types.SimpleNamespace(radius=0.5, height=2.0, max_climb=0.4, max_slope=45.0),
                     {"climb": "agent"}),
    "map_piece": (types.SimpleNamespace(radius=0.4, height=2.0, max_climb=0.4, max_slope=60.0),
                  {"cell_size": 0.13333334, "cell_height": 0.05, "region_min_size": 6}),
}
"""Grid name -> (agent, Recast parameters) of configs/base.yaml + map_analysis.yaml and configs/map_piece.yaml."""
FILTERS = ("recast", "drops", "off")
"""The ``ledge_filter`` values compared."""

RAMP_DEGREES = (20.0, 30.0, 36.0, 40.0, 44.0, 46.0, 50.0, 55.0, 58.0, 62.0)
STAIRS = ((0.15, 0.30), (0.20, 0.25), (0.20, 0.30), (0.25, 0.25), (0.25, 0.35), (0.30, 0.30), (0.35, 0.40),
          (0.45, 0.30), (0.50, 0.40))
"""(riser, tread) of the flights, m: under the presets' 0.4 m climb, then over it."""
STEPS = (0.125, 0.30, 0.45)
"""Single steps between two floors, m: one map-analysis cell height, under and over the climb."""
WALL_OVER_CLIMB = 0.05
"""The low wall is this much higher than the climb, m."""


def slab(extents: tuple[float, float, float], centre: tuple[float, float, float]) -> trimesh.Trimesh:
    """A closed box of ``extents`` (x, y, z, m) centred at ``centre``."""
    return trimesh.creation.box(extents=extents, transform=trimesh.transformations.translation_matrix(centre))


def floor(size_x: float, size_z: float, x: float, top: float) -> trimesh.Trimesh:
    """A 0.2 m thick slab centred at (``x``, 0) in plan whose top is at height ``top``."""
    return slab((size_x, 0.2, size_z), (x, top - 0.1, 0.0))


def ramp(degrees: float, width: float = 4.0, rise: float = 2.0) -> tuple[trimesh.Trimesh, np.ndarray]:
    """Two 6 x ``width`` m floors ``rise`` apart joined along +x by an open-sided ramp of ``degrees``;
    (mesh, (2,3) the floors' middles)."""
    run = rise / math.tan(math.radians(degrees))
    ends = np.array([[-3.0, 0.0, 0.0], [run + 3.0, rise, 0.0]])
    surface = trimesh.Trimesh(vertices=[[0, 0, -width / 2], [run, rise, -width / 2], [run, rise, width / 2],
                                        [0, 0, width / 2]], faces=[[0, 2, 1], [0, 3, 2]])
    return trimesh.util.concatenate([floor(6.0, width, -3.0, 0.0), floor(6.0, width, run + 3.0, rise), surface]), ends


def stairs(riser: float, tread: float, steps: int = 8, width: float = 2.0) -> tuple[trimesh.Trimesh, np.ndarray]:
    """A lower floor, ``steps`` solid open-sided steps up along +x, an upper floor; (mesh, (2,3) the floors' middles)."""
    parts = [floor(6.0, width, -3.0, 0.0)]
    for i in range(steps):
        top = (i + 1) * riser
        parts.append(slab((tread, top + 0.2, width), ((i + 0.5) * tread, top / 2 - 0.1, 0.0)))
    top, start = steps * riser, steps * tread
    parts.append(floor(6.0, width, start + 3.0, top))
    return trimesh.util.concatenate(parts), np.array([[-3.0, 0.0, 0.0], [start + 3.0, top, 0.0]])


def low_wall(height: float, width: float = 3.0) -> tuple[trimesh.Trimesh, np.ndarray]:
    """A 12 x ``width`` m floor with a 0.2 m thick wall of ``height`` across it at x = 0; (mesh, the two halves' middles)."""
    mesh = trimesh.util.concatenate([floor(12.0, width, 0.0, 0.0), slab((0.2, height, width), (0.0, height / 2, 0.0))])
    return mesh, np.array([[-3.0, 0.0, 0.0], [3.0, 0.0, 0.0]])


def platform(shift: float, size: float = 8.0, height: float = 1.0) -> trimesh.Trimesh:
    """A solid ``size`` x ``size`` m platform, its top at ``height``, centred at (``shift``, ``shift``) in plan on a
    20 x 20 m ground centred at the origin."""
    return trimesh.util.concatenate([floor(20.0, 20.0, 0.0, 0.0), slab((size, height, size), (shift, height / 2, shift))])


def navmesh(mesh: trimesh.Trimesh, grid: str, ledge: str) -> NavMesh | None:
    """The navmesh of ``mesh`` with ``grid``'s agent and parameters and ``ledge_filter`` ``ledge``; None when nothing
    is walkable."""
    agent, params = GRIDS[grid]
    try:
        return build_navmesh(mesh.vertices, mesh.faces, agent, RecastParams(**params, ledge_filter=ledge))
    except RuntimeError:  # nothing walkable left
        return None


def joined(nm: NavMesh | None, ends: np.ndarray) -> bool:
    """Whether polygons under both ``ends`` ((2,3), m) exist and Detour's links join them."""
    if nm is None:
        return False
    a, b = (nm.nearest_poly(end, (0.5, 0.3, 0.5))[0] for end in ends)
    if a < 0 or b < 0:
        return False
    g = nx.Graph()
    g.add_nodes_from(range(nm.polygon_count))
    g.add_edges_from(nm.portals().pairs.tolist())
    return nx.has_path(g, a, b)


def edge_clearance(nm: NavMesh | None, shift: float, size: float = 8.0, height: float = 1.0) -> float:
    """Least plan distance (m) from a navmesh vertex on the :func:`platform` top (within 0.3 m of ``height``) to the
    platform's edge; nan when the top has no navmesh."""
    if nm is None:
        return float("nan")
    top = nm.vertices[np.abs(nm.vertices[:, 1] - height) < 0.3]
    if len(top) == 0:
        return float("nan")
    return float((size / 2 - np.abs(top[:, [0, 2]] - shift).max(axis=1)).min())


def least_edge_clearance(grid: str, ledge: str, shifts: int = 8) -> float:
    """Least :func:`edge_clearance` (m) over the platform moved by 0, 1/``shifts``, ... of a cell against the grid."""
    cell = cell_size(grid)
    return min(edge_clearance(navmesh(platform(k * cell / shifts), grid, ledge), k * cell / shifts)
               for k in range(shifts))


def cell_size(grid: str) -> float:
    """The xz cell size (m) ``grid`` builds with (the builder's rule when the preset leaves it out)."""
    agent, params = GRIDS[grid]
    return params.get("cell_size") or min(max(agent.radius / 2, 0.05), 1.0)


def cases(grid: str) -> list[tuple[str, str, Any]]:
    """(case, known answer, what to measure) for ``grid``: (joined or not, (mesh, the floors' middles)) or
    ``(minimum clearance m, None)`` for :func:`least_edge_clearance`."""
    agent, params = GRIDS[grid]
    rows: list[tuple[str, str, Any]] = []
    for degrees in RAMP_DEGREES:
        rows.append((f"ramp {degrees:g} deg", degrees <= agent.max_slope, ramp(degrees)))
    for riser, tread in STAIRS:
        rows.append((f"stairs {riser:.2f}/{tread:.2f} m", riser <= agent.max_climb, stairs(riser, tread)))
    for rise in STEPS:
        mesh = trimesh.util.concatenate([floor(6.0, 3.0, -3.0, 0.0), floor(6.0, 3.0, 3.0, rise)])
        rows.append((f"step {rise:.3f} m", rise <= agent.max_climb, (mesh, np.array([[-3.0, 0, 0], [3.0, rise, 0]]))))
    height = agent.max_climb + WALL_OVER_CLIMB
    rows.append((f"wall {height:.2f} m", False, low_wall(height)))
    rows.append(("clearance from a 1 m drop", agent.radius - cell_size(grid) / 2, None))
    return rows


def main() -> None:
    for grid, (agent, params) in GRIDS.items():
        print(f"\n{grid}: agent radius {agent.radius} m, climb {agent.max_climb} m, max slope {agent.max_slope} deg, "
              f"params {params or 'defaults'}")
        print(f"{'case':<28} {'known':>8}" + "".join(f" {ledge:>9}" for ledge in FILTERS))
        met = dict.fromkeys(FILTERS, 0)
        rows = cases(grid)
        for name, known, built in rows:
            shown = []
            for ledge in FILTERS:
                if isinstance(known, bool):
                    value = joined(navmesh(built[0], grid, ledge), built[1])
                    ok = value is known
                    shown.append(f"{'joined' if value else 'cut':>8}{'' if ok else '!'}")
                else:
                    value = least_edge_clearance(grid, ledge)
                    ok = value >= known - 1e-6
                    shown.append(f"{value:7.3f} m{'' if ok else '!'}")
                met[ledge] += ok
            answer = ("joined" if known else "cut") if isinstance(known, bool) else f">={known:.3f} m"
            print(f"{name:<28} {answer:>8}" + "".join(f" {one:>9}" for one in shown))
        total = len(rows)
        print("known answers met: " + ", ".join(f"{ledge} {met[ledge]} / {total}" for ledge in FILTERS)
              + " ('!': not met)")


if __name__ == "__main__":
    main()
