"""How the walkable surface looks when a level is read right, in the wrong frame, or inside out.

Run: ``.venv/bin/python benchmarks/frame_check.py [--sampling]``

For every sample level (:data:`g2s_plugins.samples.levels.SAMPLES`), four
generated dungeons, ``../shared/data/nav_test.obj``, the two shared pieces and
two generated pieces whose answers are known (:func:`thick_tiled_room`: its
floor tiles are closed slabs thicker than the agent's climb and thinner than
its height, so wound inside out they hide their floor; :func:`inward_box_room`:
a room modelled as one closed box seen from inside, whose negative volume is
meant and must not be warned about), and tall, narrow pieces read right that
must not be warned about either (:data:`TALL_PIECES`: the sloped corridor at
15 degrees along x and along z, two stairwell towers, a spiral stair, a lift
shaft with landings and an atrium with galleries), four versions of the mesh:

* ``correct``: as made (Y up, outward-facing solids);
* ``z-up``: the same level written as a Z-up file and read with the default
  ``mesh.up_axis: y`` (the level stands on its side);
* ``inverted``: every face wound the other way (``trimesh`` ``invert``);
* ``half inv.``: every other closed body (watertight connected part) inverted.

Per version it prints (a Markdown table) the statistics
:mod:`g2s_plugins.walkable_check` decides on: the height over the shorter
horizontal side, the flat area facing along z over that along y, the closed
bodies wound inside out, those of them that hide their floor (under less
than the agent's height of headroom) and the microseconds a face finding
them took (on the machine's load of the moment), and per graph
builder (navmesh; with ``--sampling`` also sampling) the *walkable share*
(the nodes' area over the level's horizontal bounding-box area), the share
of the walkable area in its largest connected piece and whether that piece
climbs (:func:`g2s_plugins.walkable_check.walks_upright`), and what g2s
tells the user (warning or error, and the causes it names). Pieces (the
generated ones and the shared ``.obj``) run with ``configs/map_piece.yaml``'s
agent, the rest with the presets' default agent. docs/errors.md records its
output and the thresholds chosen from it.
"""

from __future__ import annotations

import argparse
import math
import time
from pathlib import Path

import networkx as nx
import numpy as np
import trimesh

import g2s_core
from g2s_core.config import resolve_config
from g2s_core.errors import G2SError
from g2s_core.mesh import Z_UP_TO_Y_UP
from g2s_plugins.samples.levels import SAMPLES, load_sample
from g2s_plugins.samples.pieces import PIECES
from g2s_plugins.walkable_check import (
    climbs,
    flat_area_ratio,
    footprint_area,
    height_ratio,
    hidden_floor_bodies,
    inside_out_bodies,
    largest_piece,
)

ROOT = Path(__file__).resolve().parents[1]
SHARED = ROOT.parent / "shared" / "data"
DUNGEONS = [{"rooms": 12, "seed": 0}, {"rooms": 40, "seed": 1}, {"rooms": 115, "seed": 2}, {"rooms": 600, "seed": 3}]


def box(low: tuple[float, float, float], high: tuple[float, float, float]) -> trimesh.Trimesh:
    """The closed, outward-facing box between corners ``low`` and ``high`` (metres)."""
    low_corner, high_corner = np.asarray(low, dtype=float), np.asarray(high, dtype=float)
    return trimesh.creation.box(extents=high_corner - low_corner).apply_translation((low_corner + high_corner) / 2)


def thick_tiled_room(thickness: float = 0.6) -> trimesh.Trimesh:
    """An 8 x 6 m room floored with four closed tiles ``thickness`` thick (top at y = 0), walled 3 m high
    and 0.3 m thick, with a 1.6 m doorway in its east wall. The default 0.6 m lies between
    ``map_piece``'s agent climb (0.4 m: Recast cannot merge an upturned underside with the top)
    and height (2 m). The tiles are 2 cm apart (less than a navmesh cell), so that no two share an
    edge and each is a closed body of its own."""
    gap = 0.02
    tiles = [box((x + gap / 2, -thickness, z + gap / 2), (x + 4.0 - gap / 2, 0.0, z + 3.0 - gap / 2))
             for x in (0.0, 4.0) for z in (0.0, 3.0)]
    walls = [box((-0.3, -thickness, -0.3), (0.0, 3.0, 6.3)), box((8.0, -thickness, -0.3), (8.3, 3.0, 2.2)),
             box((8.0, -thickness, 3.8), (8.3, 3.0, 6.3)), box((0.0, -thickness, -0.3), (8.0, 3.0, 0.0)),
             box((0.0, -thickness, 6.0), (8.0, 3.0, 6.3))]
    return trimesh.util.concatenate(tiles + walls)


def inward_box_room() -> trimesh.Trimesh:
    """An 8 x 3 x 6 m room modelled as one closed box wound inwards: seen from inside, its floor
    faces up into it (negative signed volume, on purpose)."""
    return inverted(box((0.0, 0.0, 0.0), (8.0, 3.0, 6.0)))


def tower_walls(x1: float, z1: float, top: float, thickness: float = 0.2, door: float = 1.0) -> list[trimesh.Trimesh]:
    """Walls ``thickness`` thick around the room [0, x1] x [0, z1] from y = -0.2 to ``top`` (metres),
    with a doorway ``door`` wide and 2.2 m tall in the middle of the south wall (z = 0)."""
    a, b = x1 / 2 - door / 2, x1 / 2 + door / 2
    return [box((-thickness, -0.2, -thickness), (0.0, top, z1 + thickness)),
            box((x1, -0.2, -thickness), (x1 + thickness, top, z1 + thickness)),
            box((0.0, -0.2, z1), (x1, top, z1 + thickness)),
            box((0.0, -0.2, -thickness), (a, top, 0.0)), box((b, -0.2, -thickness), (x1, top, 0.0)),
            box((a, 2.2, -thickness), (b, top, 0.0))]


def flight(x0: float, x1: float, z0: float, z1: float, y0: float, y1: float, steps: int) -> list[trimesh.Trimesh]:
    """Solid steps over [z0, z1] rising from ``y0`` at ``x0`` to ``y1`` at ``x1`` (``x1 < x0`` runs back)."""
    edges = np.linspace(x0, x1, steps + 1)
    return [box((min(a, b), y0 - 0.2, z0), (max(a, b), y0 + (y1 - y0) * (i + 1) / steps, z1))
            for i, (a, b) in enumerate(zip(edges[:-1], edges[1:]))]


def stairwell(storeys: int, storey: float = 3.0) -> trimesh.Trimesh:
    """A 4 x 4 m tower (3.6 m inside) of ``storeys`` storeys: per storey a flight of 9 steps along the
    south wall, a half landing on the east, a flight back along the north wall, and a landing on the west."""
    parts = tower_walls(3.6, 3.6, storeys * storey + 1.0) + [box((0.0, -0.2, 0.0), (3.6, 0.0, 3.6))]
    for s in range(storeys):
        y = s * storey
        parts += flight(0.8, 2.8, 0.0, 1.5, y, y + storey / 2, 9)
        parts.append(box((2.8, y + storey / 2 - 0.2, 0.0), (3.6, y + storey / 2, 3.6)))
        parts += flight(2.8, 0.8, 2.1, 3.6, y + storey / 2, y + storey, 9)
        parts.append(box((0.0, y + storey - 0.2, 1.5 if s + 1 < storeys else 0.0), (0.8, y + storey, 3.6)))
    return trimesh.util.concatenate(parts)


def spiral_stair(turns: int = 3, rise: float = 3.0, radius: float = 1.8, steps: int = 16) -> trimesh.Trimesh:
    """A spiral stair of ``turns`` turns (``rise`` m and ``steps`` treads 0.7 m wide a turn) round a 0.3 m
    core, in a square tower 2 * ``radius`` m inside, with a half landing at the top."""
    height = turns * rise
    parts = [p.apply_translation((-radius, 0.0, -radius)) for p in tower_walls(2 * radius, 2 * radius, height + 2.5)]
    parts.append(box((-radius, -0.2, -radius), (radius, 0.0, radius)))
    core = trimesh.creation.cylinder(radius=0.3, height=height + 2.7, sections=12)
    core.apply_transform(trimesh.transformations.rotation_matrix(math.pi / 2, (1, 0, 0)))
    parts.append(core.apply_translation((0.0, (height + 2.3) / 2, 0.0)))
    for i in range(turns * steps):
        top = (i + 1) * rise / steps
        tread = box((0.25, top - 0.25, -0.35), (radius, top, 0.35))
        parts.append(tread.apply_transform(trimesh.transformations.rotation_matrix(2 * math.pi * i / steps, (0, 1, 0))))
    parts.append(box((-radius, height - 0.2, -radius), (0.0, height, radius)))
    return trimesh.util.concatenate(parts)


def lift_shaft(storeys: int = 4, storey: float = 3.0) -> trimesh.Trimesh:
    """A 3 x 3 m landing per storey beside a 1.8 x 3 m lift shaft, each storey walled with a doorway."""
    parts = [box((3.2, -0.2, 0.0), (5.0, 0.0, 3.0))]
    for s in range(storeys):
        y = s * storey
        parts += [p.apply_translation((0.0, y, 0.0)) for p in tower_walls(5.0, 3.0, storey - 0.2)]
        parts += [box((0.0, y - 0.2, 0.0), (3.0, y, 3.0)), box((3.0, y - 0.2, 0.0), (3.2, y + storey - 0.2, 3.0))]
    return trimesh.util.concatenate(parts)


def atrium(galleries: int = 2, storey: float = 4.0) -> trimesh.Trimesh:
    """A 6 x 4 m atrium (galleries + 1) * ``storey`` m tall, with a 1.2 m gallery railed 1 m high along
    each long side at every storey above the ground."""
    parts = tower_walls(6.0, 4.0, (galleries + 1) * storey) + [box((0.0, -0.2, 0.0), (6.0, 0.0, 4.0))]
    for g in range(1, galleries + 1):
        y = g * storey
        for z0, z1, rail in ((0.0, 1.2, 1.1), (2.8, 4.0, 2.8)):
            parts += [box((0.0, y - 0.25, z0), (6.0, y, z1)), box((0.0, y, rail), (6.0, y + 1.0, rail + 0.1))]
    return trimesh.util.concatenate(parts)


def turned_to_z(mesh: trimesh.Trimesh) -> trimesh.Trimesh:
    """``mesh`` turned a quarter turn about y (what ran along x runs along z)."""
    return mesh.copy().apply_transform(trimesh.transformations.rotation_matrix(math.pi / 2, (0, 1, 0)))


TALL_PIECES = {
    "sloped_corridor slope=15": lambda: load_sample("sloped_corridor", slope=15.0).mesh,
    "sloped_corridor slope=15 along z": lambda: turned_to_z(load_sample("sloped_corridor", slope=15.0).mesh),
    "stairwell 3 storeys": lambda: stairwell(3),
    "stairwell 4 storeys": lambda: stairwell(4),
    "spiral_stair": spiral_stair,
    "lift_shaft": lift_shaft,
    "atrium": atrium,
}
"""Tall, narrow pieces read right (Y up, metres; ``map_piece``'s agent), by name."""


def levels() -> list[tuple[str, trimesh.Trimesh, bool]]:
    """(name, mesh, is a piece) for every level measured."""
    found = [(name, load_sample(name).mesh, name in PIECES) for name in SAMPLES if name != "dungeon"]
    found += [(f"dungeon rooms={d['rooms']} seed={d['seed']}", load_sample("dungeon", **d).mesh, False) for d in DUNGEONS]
    found.append(("nav_test.obj", trimesh.load(SHARED / "nav_test.obj", force="mesh", process=False), False))
    found += [(f"{p}.obj", trimesh.load(SHARED / "pieces" / f"{p}.obj", force="mesh", process=False), True)
              for p in ("Hallway", "Ramp")]
    found += [("thick_tiled_room", thick_tiled_room(), True), ("inward_box_room", inward_box_room(), True)]
    found += [(name, make(), True) for name, make in TALL_PIECES.items()]
    return found


def z_up_misread(mesh: trimesh.Trimesh) -> trimesh.Trimesh:
    """The level as a Z-up file holds it (the inverse of ``mesh.up_axis: z``), taken as Y-up."""
    return trimesh.Trimesh(np.asarray(mesh.vertices) @ Z_UP_TO_Y_UP, mesh.faces, process=False)


def inverted(mesh: trimesh.Trimesh) -> trimesh.Trimesh:
    return trimesh.Trimesh(mesh.vertices, np.asarray(mesh.faces)[:, ::-1], process=False)


def closed_bodies(mesh: trimesh.Trimesh) -> tuple[np.ndarray, np.ndarray]:
    """(M,) body label of each face (coincident vertices merged) and (bodies,) bool: the body is closed."""
    merged = trimesh.Trimesh(np.asarray(mesh.vertices), np.asarray(mesh.faces), process=True)
    labels = trimesh.graph.connected_component_labels(merged.face_adjacency, node_count=len(merged.faces))
    edges = merged.edges_sorted.reshape(-1, 3, 2)
    closed = np.array([trimesh.graph.is_watertight(edges[labels == body].reshape(-1, 2))[0]
                       for body in range(labels.max() + 1)])
    return labels, closed


def half_inverted(mesh: trimesh.Trimesh) -> trimesh.Trimesh:
    """Every other closed body wound the other way."""
    faces = np.array(mesh.faces)
    labels, closed = closed_bodies(mesh)
    flip = np.isin(labels, np.flatnonzero(closed)[::2])
    faces[flip] = faces[flip][:, ::-1]
    return trimesh.Trimesh(mesh.vertices, faces, process=False)


def graph_run(mesh: trimesh.Trimesh, piece: bool, builder: str) -> tuple[float, str, str]:
    """Walkable area (m²) the builder finds (the nodes' ``area``; 0 when none), its largest connected piece
    (:func:`piece_cell`) and what g2s tells the user: ``-`` nothing, ``warn`` or ``error`` with the causes
    it names (``z``: the up axis, ``inv``: inside-out bodies)."""
    config = "map_analysis_sampling" if builder == "sampling" else "map_piece" if piece else "map_analysis"
    agent = resolve_config("map_piece")[0].agent.model_dump() if piece else {}
    try:
        result = g2s_core.run(mesh, config, stop_after="graph", agent=agent)
    except G2SError as error:
        return 0.0, "-", "error" + _causes(str(error))
    said = [w for w in result.warnings if w.startswith("mesh:")]
    return (sum(a for _, a in result.graph.nodes(data="area")), piece_cell(result.graph, agent_of(piece)),
            "warn" + _causes(said[0]) if said else "-")


def agent_of(piece: bool):
    return resolve_config("map_piece" if piece else "map_analysis")[0].agent


def piece_cell(graph: nx.Graph, agent) -> str:
    """The share of the walkable area in the graph's largest connected piece, then whether that piece
    ``climbs`` or is ``level`` (:func:`g2s_plugins.walkable_check.climbs`)."""
    share, nodes = largest_piece(graph)
    return f"{share:.2f} {'climbs' if climbs(nodes, agent) else 'level'}"


def _causes(message: str) -> str:
    causes = [tag for tag, key in (("z", "up_axis: z"), ("inv", "clean: true")) if key in message]
    return f" {'+'.join(causes)}" if causes else ""


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--sampling", action="store_true", help="also measure the sampling builder")
    args = parser.parse_args()
    versions = {"correct": lambda m: m, "z-up": z_up_misread, "inverted": inverted, "half inv.": half_inverted}
    builders = ["navmesh", "sampling"] if args.sampling else ["navmesh"]
    print("| level | version | faces | height ratio | z/y flat area | inside-out bodies | hiding their floor (µs a face) | "
          + " | ".join(f"{b} share | largest piece | g2s says" for b in builders) + " |")
    print("|---" * (7 + 3 * len(builders)) + "|")
    for name, mesh, piece in levels():
        agent = agent_of(piece)
        for version_name, make in versions.items():
            version = make(mesh)
            cells = []
            for builder in builders:
                area, largest, said = graph_run(version, piece, builder)
                cells += [f"{area / footprint_area(version):.3f}", largest, said]
            start = time.perf_counter()
            hiding = hidden_floor_bodies(version, agent)
            micros = 1e6 * (time.perf_counter() - start) / len(version.faces)
            print(f"| {name} | {version_name} | {len(mesh.faces)} | {height_ratio(version):.2f} | "
                  f"{flat_area_ratio(version, agent.max_slope):.2f} | {inside_out_bodies(version)} | "
                  f"{hiding} ({micros:.0f}) | " + " | ".join(cells) + " |", flush=True)


if __name__ == "__main__":
    main()
