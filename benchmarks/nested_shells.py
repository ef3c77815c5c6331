"""Closed shells inside closed shells under ``mesh.clean``: which floors each route walks (docs/navmesh.md, "Closed
rooms inside closed rooms under mesh.clean").

Each case is a level of closed boxes, each box one closed shell (12 triangles), as a modeller exports them: a solid
(a building, a crate) faces out, and a room inside a solid, the hollow it holds, faces into the room, so that its
floor faces up and its walls and ceiling face the room (a wall has two sides: the building's outside faces out, the
room's inside faces in; a room modelled with walls of its own inside another room is a solid with a hollow again).
The cases:

* ``room_in_building``: a building 12 x 3.4 x 10 m, walls, floor and roof 0.3 m thick, holding one room (11.4 x 2.8
  x 9.4 m, its floor 0.3 m up): walkable are its roof and the room's floor;
* ``crate_in_room``: the same with a crate 2 x 0.6 x 2 m on the room's floor (a solid: faces out);
* ``rooms_in_rooms``: a room inside a room inside a room: a building 24 x 9.3 x 20 m holding a room (floor 0.3 m up,
  ceiling 9.0 m), on whose floor stands a second building 18 x 6.2 x 14 m holding a second room (floor 0.6 m,
  ceiling 6.2 m), on whose floor stands a third building 12 x 3.2 x 8 m holding the third room (floor 0.9 m, ceiling
  3.5 m): six shells, each inside all the ones before it; walkable are the three rooms' floors (the first two
  around the building standing on them) and the three roofs;
* ``crate_flipped``: ``crate_in_room`` whose crate alone is wound inside out (a modeller's flipped crate);
* each of the first three ``inverted``: every face of the file wound the other way (the whole export inside out).

A right winding of each shell is known: the building and crate face out (signed volume > 0), the rooms in (< 0).
Each case is turned by ``yaw`` (degrees) about the vertical. For each it prints the shells wound as the right model
after ``mesh.clean``'s :func:`g2s_core.mesh.flip_inside_out_bodies`, and the walkable area (the graph's nodes'
``area``, m^2) at each floor height of each route's step 1 with ``mesh: {clean: true}`` (``map_analysis``: the
navmesh; ``map_analysis_sampling``: the samples). O(cases) runs, each of a few hundred triangles.

With ``--levels`` it runs the rule on the sample levels (each of the 47 with its defaults, the five seeded kinds at
seeds 1 and 2, ``terrain?size=160``, ``dungeon?rooms=30`` and ``?rooms=200``) and the three shared meshes
(``../shared/data``: ``nav_test.obj`` and the two pieces), each as made and with every face wound the other way,
vertices merged as the walkable check merges them: the faces the rule turns against those trimesh's
``repair.fix_inversion`` per body (the rule before 7 December 2026) turns, and the CPU seconds of each. The same
faces on a level mean that no closed body of it lies inside another (at an odd depth) where it matters.

Run: ``.venv/bin/python benchmarks/nested_shells.py [--yaws 0 22 45] [--levels]``.
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np
import trimesh

import g2s_core
from g2s_core.mesh import clean_mesh, flip_inside_out_bodies, generate_level, load_mesh
from g2s_plugins.samples.levels import SAMPLES

WALL = 0.3
"""Thickness (m) of every building's walls, floor and roof."""

ROUTES = {"navmesh": "map_analysis", "sampling": "map_analysis_sampling"}


def shell(lo: tuple[float, float, float], hi: tuple[float, float, float], outward: bool) -> trimesh.Trimesh:
    """One closed box from ``lo`` to ``hi`` (m), its faces facing out (a solid) or in (a room seen from inside)."""
    box = trimesh.creation.box(bounds=np.array([lo, hi], dtype=np.float64))
    return box if outward else trimesh.Trimesh(box.vertices, box.faces[:, ::-1], process=False)


def building(lo: tuple[float, float, float], hi: tuple[float, float, float]) -> list[trimesh.Trimesh]:
    """A closed building from ``lo`` to ``hi`` facing out and the room it holds (walls, floor and roof
    :data:`WALL` thick) facing in."""
    inner_lo, inner_hi = np.add(lo, WALL), np.subtract(hi, WALL)
    return [shell(lo, hi, True), shell(tuple(inner_lo), tuple(inner_hi), False)]


def room_in_building() -> list[trimesh.Trimesh]:
    return building((0.0, 0.0, 0.0), (12.0, 3.4, 10.0))


def crate_in_room() -> list[trimesh.Trimesh]:
    return room_in_building() + [shell((4.0, WALL, 4.0), (6.0, WALL + 0.6, 6.0), True)]


def rooms_in_rooms() -> list[trimesh.Trimesh]:
    return (building((0.0, 0.0, 0.0), (24.0, 9.3, 20.0)) + building((3.0, 0.3, 3.0), (21.0, 6.5, 17.0))
            + building((6.0, 0.6, 6.0), (18.0, 3.8, 14.0)))


def crate_flipped() -> list[trimesh.Trimesh]:
    *rooms, crate = crate_in_room()
    return rooms + [trimesh.Trimesh(crate.vertices, crate.faces[:, ::-1], process=False)]


def _inverted(make: Callable[[], list[trimesh.Trimesh]]) -> Callable[[], list[trimesh.Trimesh]]:
    return lambda: [trimesh.Trimesh(part.vertices, part.faces[:, ::-1], process=False) for part in make()]


CASES: dict[str, Callable[[], list[trimesh.Trimesh]]] = {
    "room_in_building": room_in_building,
    "crate_in_room": crate_in_room,
    "rooms_in_rooms": rooms_in_rooms,
    "crate_flipped": crate_flipped,
    "room_in_building inverted": _inverted(room_in_building),
    "crate_in_room inverted": _inverted(crate_in_room),
    "rooms_in_rooms inverted": _inverted(rooms_in_rooms),
}

RIGHT: dict[str, Callable[[], list[trimesh.Trimesh]]] = {
    name: {"crate_flipped": crate_in_room}.get(name, CASES[name.split()[0]]) for name in CASES}
"""Each case's right model: its shells as a modeller means them."""

FLOORS = {"room_in_building": (0.3, 3.4), "crate_in_room": (0.3, 0.9, 3.4), "rooms_in_rooms": (0.3, 0.6, 0.9, 3.8, 6.5, 9.3)}
"""The heights (m) of the walkable tops of each case's right model: rooms' floors, the crate's top, roofs."""


def floors(name: str) -> tuple[float, ...]:
    """:data:`FLOORS` of the case ``name`` (its right model's)."""
    return FLOORS[RIGHT[name].__name__]


def level(parts: list[trimesh.Trimesh], yaw: float) -> trimesh.Trimesh:
    """The parts as one mesh, turned by ``yaw`` degrees about the vertical (y)."""
    turn = trimesh.transformations.rotation_matrix(np.radians(yaw), (0.0, 1.0, 0.0))
    return trimesh.util.concatenate(parts).apply_transform(turn)


def shell_volumes(mesh: trimesh.Trimesh) -> list[float]:
    """The signed volume (m^3) of each closed shell of ``mesh`` (faces joined by shared edges), in order of their
    lowest face index."""
    bodies = sorted(trimesh.graph.connected_components(mesh.face_adjacency, min_len=4), key=min)
    return [float(trimesh.Trimesh(mesh.vertices, mesh.faces[body], process=False).volume) for body in bodies]


def wound_right(name: str, yaw: float) -> bool:
    """Whether ``mesh.clean`` leaves every shell of the case wound as its right model (the same signs of volume)."""
    cleaned, _ = clean_mesh(level(CASES[name](), yaw))
    return np.array_equal(np.sign(shell_volumes(cleaned)), np.sign([part.volume for part in RIGHT[name]()]))


def walkable_by_floor(mesh: trimesh.Trimesh, route: str, heights: tuple[float, ...]) -> list[float]:
    """Walkable area (m^2) of step 1 of ``route`` (a key of :data:`ROUTES`) with ``mesh: {clean: true}`` on each
    floor of ``heights`` (m, rising): a node counts on the highest floor at most 0.05 m above it (the navmesh's
    polygons lie up to a few cells over their floor, the samples on it)."""
    graph = g2s_core.run(mesh, ROUTES[route], stop_after="graph", mesh={"clean": True}).graph
    areas = [0.0] * len(heights)
    for _, data in graph.nodes(data=True):
        floor = np.searchsorted(heights, float(data["pos"][1]) + 0.05) - 1
        if floor >= 0:
            areas[floor] += float(data.get("area", 0.0))
    return areas


SHARED = Path(__file__).resolve().parents[2] / "shared" / "data"

SEEDED = ("building", "castle", "dungeon", "maze", "terrain")


def levels() -> list[str]:
    """The levels of ``--levels``: ``sample:`` specs and the shared meshes that exist."""
    specs = [f"sample:{name}" for name in SAMPLES] + [f"sample:{name}?seed={seed}" for name in SEEDED for seed in (1, 2)]
    specs += ["sample:terrain?size=160", "sample:dungeon?rooms=30", "sample:dungeon?rooms=200"]
    return specs + [str(path) for path in (SHARED / "nav_test.obj", SHARED / "pieces" / "Hallway.obj",
                                           SHARED / "pieces" / "Ramp.obj") if path.exists()]


def turned_before(mesh: trimesh.Trimesh) -> np.ndarray:
    """The faces trimesh's ``repair.fix_inversion`` per body turns: every closed body of negative signed volume."""
    fixed = mesh.copy()
    trimesh.repair.fix_inversion(fixed, multibody=True)
    return np.flatnonzero(np.any(fixed.faces != mesh.faces, axis=1))


def compare_on_levels() -> None:
    """One row a level and winding: faces, faces turned before and now, whether the same, CPU seconds of each."""
    print("| level | wound | faces | turned before | turned now | same | CPU s before, now |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    for spec in levels():
        mesh = generate_level(spec) if spec.startswith("sample:") else load_mesh(spec)[0]
        for wound, faces in (("as made", np.asarray(mesh.faces)), ("inverted", np.asarray(mesh.faces)[:, ::-1])):
            merged = trimesh.Trimesh(np.asarray(mesh.vertices), faces, process=True)
            start = time.process_time()
            before = turned_before(merged)
            middle = time.process_time()
            fixed, _ = flip_inside_out_bodies(merged)
            end = time.process_time()
            now = np.flatnonzero(np.any(fixed.faces != merged.faces, axis=1))
            print(f"| {Path(spec).name if not spec.startswith('sample:') else spec} | {wound} | {len(faces)} | {len(before)} | "
                  f"{len(now)} | {'yes' if np.array_equal(before, now) else 'no'} | {middle - start:.2f}, {end - middle:.2f} |",
                  flush=True)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--yaws", type=float, nargs="+", default=[0.0, 22.0, 45.0])
    parser.add_argument("--levels", action="store_true", help="the rule against the one before on the sample levels")
    args = parser.parse_args()
    if args.levels:
        compare_on_levels()
        return
    print("| case | yaw | shells wound right | " + " | ".join(f"{route}: m^2 on each floor (height m: area)" for route in ROUTES)
          + " |")
    print("| --- | --- | --- | " + " | ".join("---" for _ in ROUTES) + " |")
    for name in CASES:
        for yaw in args.yaws:
            mesh = level(CASES[name](), yaw)
            cells = [", ".join(f"{height:g}: {area:.1f}" for height, area in zip(floors(name), walkable_by_floor(
                mesh, route, floors(name)))) for route in ROUTES]
            print(f"| {name} | {yaw:g} | {'yes' if wound_right(name, yaw) else 'no'} | " + " | ".join(cells) + " |",
                  flush=True)


if __name__ == "__main__":
    main()
