"""How the walkable surface looks when a level is read right, in the wrong frame, or inside out.

Run: ``.venv/bin/python benchmarks/frame_check.py [--sampling]``

For every sample level (:data:`g2s_plugins.samples.levels.SAMPLES`), four
generated dungeons, ``../shared/data/nav_test.obj``, the two shared pieces and
two generated pieces whose answers are known (:func:`thick_tiled_room`: its
floor tiles are closed slabs thicker than the agent's climb and thinner than
its height, so wound inside out they hide their floor; :func:`inward_box_room`:
a room modelled as one closed box seen from inside, whose negative volume is
meant and must not be warned about), four versions of the mesh:

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
(the nodes' area over the level's horizontal bounding-box area) and what g2s
tells the user (warning or error, and the causes it names). Pieces (the
generated ones and the shared ``.obj``) run with ``configs/map_piece.yaml``'s
agent, the rest with the presets' default agent. docs/errors.md records its
output and the thresholds chosen from it.
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np
import trimesh

import g2s_core
from g2s_core.config import resolve_config
from g2s_core.errors import G2SError
from g2s_core.mesh import Z_UP_TO_Y_UP
from g2s_plugins.samples.levels import SAMPLES, load_sample
from g2s_plugins.samples.pieces import PIECES
from g2s_plugins.walkable_check import (
    flat_area_ratio,
    footprint_area,
    height_ratio,
    hidden_floor_bodies,
    inside_out_bodies,
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


def levels() -> list[tuple[str, trimesh.Trimesh, bool]]:
    """(name, mesh, is a piece) for every level measured."""
    found = [(name, load_sample(name).mesh, name in PIECES) for name in SAMPLES if name != "dungeon"]
    found += [(f"dungeon rooms={d['rooms']} seed={d['seed']}", load_sample("dungeon", **d).mesh, False) for d in DUNGEONS]
    found.append(("nav_test.obj", trimesh.load(SHARED / "nav_test.obj", force="mesh", process=False), False))
    found += [(f"{p}.obj", trimesh.load(SHARED / "pieces" / f"{p}.obj", force="mesh", process=False), True)
              for p in ("Hallway", "Ramp")]
    found += [("thick_tiled_room", thick_tiled_room(), True), ("inward_box_room", inward_box_room(), True)]
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


def graph_run(mesh: trimesh.Trimesh, piece: bool, builder: str) -> tuple[float, str]:
    """Walkable area (m²) the builder finds (the nodes' ``area``; 0 when none) and what g2s tells the user:
    ``-`` nothing, ``warn`` or ``error`` with the causes it names (``z``: the up axis, ``inv``: inside-out bodies)."""
    config = "map_analysis_sampling" if builder == "sampling" else "map_piece" if piece else "map_analysis"
    agent = resolve_config("map_piece")[0].agent.model_dump() if piece else {}
    try:
        result = g2s_core.run(mesh, config, stop_after="graph", agent=agent)
    except G2SError as error:
        return 0.0, "error" + _causes(str(error))
    said = [w for w in result.warnings if w.startswith("mesh:")]
    return sum(a for _, a in result.graph.nodes(data="area")), ("warn" + _causes(said[0]) if said else "-")


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
          + " | ".join(f"{b} share | g2s says" for b in builders) + " |")
    print("|---" * (7 + 2 * len(builders)) + "|")
    for name, mesh, piece in levels():
        agent = resolve_config("map_piece" if piece else "map_analysis")[0].agent
        for version_name, make in versions.items():
            version = make(mesh)
            cells = []
            for builder in builders:
                area, said = graph_run(version, piece, builder)
                cells += [f"{area / footprint_area(version):.3f}", said]
            start = time.perf_counter()
            hiding = hidden_floor_bodies(version, agent)
            micros = 1e6 * (time.perf_counter() - start) / len(version.faces)
            print(f"| {name} | {version_name} | {len(mesh.faces)} | {height_ratio(version):.2f} | "
                  f"{flat_area_ratio(version, agent.max_slope):.2f} | {inside_out_bodies(version)} | "
                  f"{hiding} ({micros:.0f}) | " + " | ".join(cells) + " |", flush=True)


if __name__ == "__main__":
    main()
