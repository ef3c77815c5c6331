"""Ground inside closed solids, and open ground beside them, on generated levels with known answers.

Kinds (each on a 24 x 24 m floor slab 0.3 m thick; sizes and places drawn from the seed; the whole level turned by
each yaw about the vertical through the origin):

* ``overlap 0 %`` ... ``overlap 50 %``: a box (a crate, a lift shaft) reaching that share of its depth into a wall
  slab; at 0 % its face lies in the wall's face (touching: two faces in one plane, facing each other);
* ``flush with a wall``: a box set into a wall slab, its back face in the plane of the wall's back face;
* ``on the floor, sunk flush``: a box through the floor slab, its bottom in the plane of the slab's bottom;
* ``crate on a crate``: a crate standing on another, shifted by up to half its width (the lower one's top and the
  upper one's bottom share a plane); ``, flush``: not shifted (they share the whole face, corner for corner);
* ``pillar in a wall``: a pillar from the floor slab to a ceiling slab built into a wall slab, its back face flush
  with the wall's back face, its top face in the ceiling's bottom face;
* ``room in a room``: a closed room (outer shell and inner shell: a hollow box with no way in) standing inside a
  larger closed room; both rooms' floors are open ground;
* ``building with a door``: walls one closed body (a ring cut by a door 1.2 m wide, walls 0.3 m thick) under a
  roof slab resting on them: the floor inside is open ground;
* ``thin walls``: a room of four wall slabs 0.1-0.3 m thick overlapping at the corners, a crate against one of
  them inside;
* ``building, crate and pillar``: the building with a door, a crate in a corner inside flush with two walls' inner
  faces, and a pillar 0.8 m square from the floor to the roof's bottom (the reviewer's case of shut48).

A *ground point* is every crossing of an up-facing triangle (normal y > 0.5) on vertical lines a quarter metre
apart. It is *inside* when the agent standing on it has its feet (10 cm up) and its middle (half its height up)
inside solids' material (a box's inside, less a hollow room's cavity) by more than 5 cm, *open* when its feet lie
outside every solid's material by more than 5 cm; points in between are left out (feet in a crate's top buried in
a wall, middle above the wall). Each row counts, for the sampling builder's rule
(:func:`g2s_plugins.graph_builders.sampling.inside_closed_solids`) and the disconnected-areas warning's
(:func:`g2s_plugins.area_gaps.shut_in`), the inside points called open (*kept*) and the open points called inside
(*dropped*); with ``--routes``, the sampled graph's samples and both presets' graph and structure nodes that lie
inside (`map_analysis_sampling`, `map_analysis`).

Usage: ``python benchmarks/closed_solid_kinds.py [--yaws 0 22 45] [--seeds 0 1 2] [--routes] [--kinds ...]``.
Cost: one multiple-hit ray per vertical line and the rules' rays per ground point; ``--routes`` adds two runs a case.
"""

from __future__ import annotations

import argparse
import math
import sys
from collections.abc import Callable
from pathlib import Path

import numpy as np
import trimesh

sys.path[:0] = [str(Path(__file__).resolve().parent), str(Path(__file__).resolve().parent.parent)]

from g2s_core.config import AgentConfig  # noqa: E402
from g2s_plugins._raycasting import AgentShape, RayCaster, all_hits_down  # noqa: E402

Box = tuple[float, float, float, float, float, float]
"""``(x0, x1, y0, y1, z0, z1)`` metres, before the yaw."""

Solid = tuple[Box, tuple[Box, ...]]
"""A solid's outer box and its cavities: its material is the box less the cavities."""

MARGIN = 0.05
"""Metres: how far inside or outside solids' material a point must lie to be judged (:func:`truth`)."""

GRID = 0.25
"""Metres between the vertical lines the ground points are found on."""

AGENT = AgentConfig()


def box(bounds: Box, inward: bool = False) -> trimesh.Trimesh:
    """A closed box, wound outward (``inward``: wound inside out, a room's cavity seen from within)."""
    x0, x1, y0, y1, z0, z1 = bounds
    mesh = trimesh.creation.box(bounds=[[x0, y0, z0], [x1, y1, z1]])
    if inward:
        mesh.invert()
    return mesh


def hollow(bounds: Box, wall: float) -> tuple[list[trimesh.Trimesh], Solid]:
    """A closed room with no way in: the outer box and the cavity ``wall`` metres inside it, wound inward."""
    x0, x1, y0, y1, z0, z1 = bounds
    cavity = (x0 + wall, x1 - wall, y0 + wall, y1 - wall, z0 + wall, z1 - wall)
    return [box(bounds), box(cavity, inward=True)], (bounds, (cavity,))


def prism(quads: list[list[tuple[float, float]]], y0: float, y1: float) -> trimesh.Trimesh:
    """One closed body: the footprint made of convex quads ((x, z) corners in order round each, sharing whole
    edges, each quad turning the same way) extruded from ``y0`` to ``y1``, wound outward."""
    corners = [(x, z) for quad in quads for x, z in quad]
    keys = {c: i for i, c in enumerate(dict.fromkeys(corners))}
    points = list(keys)
    n = len(points)
    vertices = [(x, y0, z) for x, z in points] + [(x, y1, z) for x, z in points]
    faces, edges = [], {}
    for quad in quads:
        a, b, c, d = (keys[p] for p in quad)
        faces += [(a + n, c + n, b + n), (a + n, d + n, c + n), (a, b, c), (a, c, d)]
        for s, e in ((a, b), (b, c), (c, d), (d, a)):
            edges[(s, e)] = edges.get((s, e), 0) + 1
    for s, e in edges:
        if (e, s) not in edges:  # a footprint boundary edge: a side wall
            faces += [(s, e, e + n), (s, e + n, s + n)]
    mesh = trimesh.Trimesh(vertices, faces, process=True)
    trimesh.repair.fix_normals(mesh)
    return mesh


def ring(x0: float, x1: float, z0: float, z1: float, wall: float, y0: float, y1: float,
         door: tuple[float, float] | None = None) -> trimesh.Trimesh:
    """Four walls ``wall`` metres thick as one closed body (a ring), a gap from x = door[0] to door[1] in the
    south wall (z0) if given."""
    a, b, c, d = (x0, z0), (x1, z0), (x1, z1), (x0, z1)
    ia, ib, ic, id_ = (x0 + wall, z0 + wall), (x1 - wall, z0 + wall), (x1 - wall, z1 - wall), (x0 + wall, z1 - wall)
    quads = [[b, c, ic, ib], [c, d, id_, ic], [d, a, ia, id_]]
    if door is None:
        quads.append([a, b, ib, ia])
    else:
        quads += [[a, (door[0], z0), (door[0], z0 + wall), ia], [(door[1], z0), b, ib, (door[1], z0 + wall)]]
    return prism(quads, y0, y1)


FLOOR: Box = (-12.0, 12.0, -0.3, 0.0, -12.0, 12.0)


def _crate(rng: np.random.Generator) -> tuple[float, float, float]:
    """A crate's width (x), depth (z) and height, metres: wider than twice the clearance, taller than the agent."""
    return float(rng.uniform(2.5, 4.0)), float(rng.uniform(2.5, 4.0)), float(rng.uniform(2.2, 3.0))


def _crate_in_a_wall(rng: np.random.Generator, depths: Callable[[float, float], tuple[float, float]]) -> tuple[list[Box], list[Solid]]:
    """A crate standing against a wall, ``depths(wall thickness, crate depth)`` (m) its back and front from the wall's
    face."""
    w, d, h = _crate(rng)
    x, wall_t = float(rng.uniform(-4, 0)), float(rng.uniform(0.2, 0.4))
    wall = (-12.0, 12.0, 0.0, 3.2, -wall_t, 0.0)
    back, front = depths(wall_t, d)
    crate = (x, x + w, 0.0, h, -back, front)
    return [FLOOR, wall, crate], [(FLOOR, ()), (wall, ()), (crate, ())]


def overlapping(share: float) -> Callable[[np.random.Generator], tuple[list[Box], list[Solid]]]:
    return lambda rng: _crate_in_a_wall(rng, lambda wall_t, d: (share * d, (1 - share) * d))


def flush_with_a_wall(rng: np.random.Generator) -> tuple[list[Box], list[Solid]]:
    return _crate_in_a_wall(rng, lambda wall_t, d: (wall_t, d - wall_t))


def sunk_flush(rng: np.random.Generator) -> tuple[list[Box], list[Solid]]:
    w, d, h = _crate(rng)
    x, z = float(rng.uniform(-4, 0)), float(rng.uniform(-4, 0))
    crate = (x, x + w, -0.3, h, z, z + d)
    return [FLOOR, crate], [(FLOOR, ()), (crate, ())]


def crate_on_a_crate(shift: float) -> Callable[[np.random.Generator], tuple[list[Box], list[Solid]]]:
    def kind(rng: np.random.Generator) -> tuple[list[Box], list[Solid]]:
        w, d, h = _crate(rng)
        x, z = float(rng.uniform(-4, 0)), float(rng.uniform(-4, 0))
        dx, dz = float(rng.uniform(0, shift * w)), float(rng.uniform(0, shift * d))
        lower = (x, x + w, 0.0, h, z, z + d)
        upper = (x + dx, x + dx + w, h, 2 * h, z + dz, z + dz + d)
        return [FLOOR, lower, upper], [(FLOOR, ()), (lower, ()), (upper, ())]
    return kind


def pillar_in_a_wall(rng: np.random.Generator) -> tuple[list[Box], list[Solid]]:
    w, d, _ = _crate(rng)
    x, wall_t = float(rng.uniform(-4, 0)), float(rng.uniform(0.2, 0.4))
    wall = (-12.0, 12.0, 0.0, 3.2, -wall_t, 0.0)
    ceiling = (-12.0, 12.0, 3.2, 3.5, -12.0, 12.0)
    pillar = (x, x + w, 0.0, 3.2, -wall_t, d - wall_t)
    return [FLOOR, wall, ceiling, pillar], [(FLOOR, ()), (wall, ()), (ceiling, ()), (pillar, ())]


def room_in_a_room(rng: np.random.Generator) -> tuple[list[Box | tuple[list[trimesh.Trimesh]]], list[Solid]]:
    wall = float(rng.uniform(0.1, 0.3))
    outer = (-9.0, float(rng.uniform(7, 9)), -0.3, float(rng.uniform(5, 6)), -9.0, float(rng.uniform(7, 9)))
    x, z = float(rng.uniform(-4, -2)), float(rng.uniform(-4, -2))
    inner = (x, x + float(rng.uniform(5, 7)), -0.3 + wall, 3.5, z, z + float(rng.uniform(5, 7)))
    parts_o, solid_o = hollow(outer, wall)
    parts_i, solid_i = hollow(inner, wall)
    return [(parts_o + parts_i,)], [solid_o, solid_i]


def building_with_a_door(rng: np.random.Generator) -> tuple[list, list[Solid]]:
    x0, z0 = float(rng.uniform(-8, -6)), float(rng.uniform(-8, -6))
    x1, z1 = x0 + float(rng.uniform(9, 12)), z0 + float(rng.uniform(9, 12))
    door = float(rng.uniform(x0 + 1, x1 - 3))
    walls = ring(x0, x1, z0, z1, 0.3, 0.0, 3.0, door=(door, door + 1.2))
    roof = (x0, x1, 3.0, 3.3, z0, z1)
    solids: list[Solid] = [(FLOOR, ()), (roof, ()),
                           ((x0, x1, 0.0, 3.0, z0, z1), ((x0 + 0.3, x1 - 0.3, 0.0, 3.0, z0 + 0.3, z1 - 0.3),
                                                         (door, door + 1.2, 0.0, 3.0, z0, z0 + 0.3)))]
    return [FLOOR, roof, ([walls],)], solids


def building_crate_and_pillar(rng: np.random.Generator) -> tuple[list, list[Solid]]:
    parts, solids = building_with_a_door(rng)
    x0, x1, _, _, z0, z1 = solids[1][0]  # the roof's plan is the building's
    w, d, h = _crate(rng)
    crate = (x0 + 0.3, x0 + 0.3 + w, 0.0, h, z1 - 0.3 - d, z1 - 0.3)  # in the corner, flush with two walls' inner faces
    px, pz = float(rng.uniform(x1 - 4.0, x1 - 2.0)), float(rng.uniform(z0 + 2.0, z0 + 4.0))
    pillar = (px, px + 0.8, 0.0, 3.0, pz, pz + 0.8)  # from the floor to the roof's bottom
    return [*parts, crate, pillar], [*solids, (crate, ()), (pillar, ())]


def thin_walls(rng: np.random.Generator) -> tuple[list[Box], list[Solid]]:
    t = float(rng.uniform(0.1, 0.3))
    x0, z0 = float(rng.uniform(-8, -6)), float(rng.uniform(-8, -6))
    x1, z1 = x0 + float(rng.uniform(9, 12)), z0 + float(rng.uniform(9, 12))
    walls = [(x0 - t, x0, 0.0, 3.0, z0 - t, z1 + t), (x1, x1 + t, 0.0, 3.0, z0 - t, z1 + t),
             (x0 - t, x1 + t, 0.0, 3.0, z0 - t, z0), (x0 - t, x1 + t, 0.0, 3.0, z1, z1 + t)]
    w, d, h = _crate(rng)
    cx = float(rng.uniform(x0 + 1, x1 - w - 1))
    crate = (cx, cx + w, 0.0, h, z0, z0 + d)  # against the south wall's inner face
    return [FLOOR, *walls, crate], [(FLOOR, ()), *((wall, ()) for wall in walls), (crate, ())]


KINDS: dict[str, Callable[[np.random.Generator], tuple[list, list[Solid]]]] = {
    "overlap 0 %": overlapping(0.0),
    "overlap 10 %": overlapping(0.1),
    "overlap 25 %": overlapping(0.25),
    "overlap 50 %": overlapping(0.5),
    "flush with a wall": flush_with_a_wall,
    "on the floor, sunk flush": sunk_flush,
    "crate on a crate": crate_on_a_crate(0.5),
    "crate on a crate, flush": crate_on_a_crate(0.0),
    "pillar in a wall": pillar_in_a_wall,
    "room in a room": room_in_a_room,
    "building with a door": building_with_a_door,
    "thin walls": thin_walls,
    "building, crate and pillar": building_crate_and_pillar,
}
"""Kind -> (seeded generator) -> (parts: boxes or ``([meshes],)``, the solids' material)."""


def _turned(yaw_deg: float) -> np.ndarray:
    """(4, 4) the rotation by ``yaw_deg`` about +Y."""
    return trimesh.transformations.rotation_matrix(math.radians(yaw_deg), [0.0, 1.0, 0.0])


def case(kind: str, seed: int, yaw_deg: float) -> tuple[list[trimesh.Trimesh], list[Solid]]:
    """The parts of the level of ``kind`` drawn with ``seed``, turned by ``yaw_deg``, and its solids (before the
    yaw); the level is their concatenation."""
    parts, solids = KINDS[kind](np.random.default_rng(seed))
    meshes = [m.copy() for p in parts for m in (p[0] if isinstance(p[0], list) else [box(p)])]
    for mesh in meshes:
        mesh.apply_transform(_turned(yaw_deg))
    return meshes, solids


def _within(points: np.ndarray, bounds: Box, grow: float) -> np.ndarray:
    lo = np.array(bounds[0::2]) - grow
    hi = np.array(bounds[1::2]) + grow
    return ((points > lo) & (points < hi)).all(axis=1)


def _material(points: np.ndarray, solids: list[Solid]) -> tuple[np.ndarray, np.ndarray]:
    """(n,) bool inside some solid's material by more than ``MARGIN``, (n,) bool outside all by more than it."""
    inside = np.zeros(len(points), dtype=bool)
    open_ = np.ones(len(points), dtype=bool)
    for outer, cavities in solids:
        in_cavity = np.zeros(len(points), dtype=bool)
        near_cavity = np.zeros(len(points), dtype=bool)
        for cavity in cavities:
            in_cavity |= _within(points, cavity, -MARGIN)
            near_cavity |= _within(points, cavity, MARGIN)
        inside |= _within(points, outer, -MARGIN) & ~near_cavity
        open_ &= ~_within(points, outer, MARGIN) | in_cavity
    return inside, open_


def truth(points: np.ndarray, solids: list[Solid], yaw_deg: float) -> tuple[np.ndarray, np.ndarray]:
    """(n,) bool inside, (n,) bool open, for ground points (n, 3) of the turned level: inside when the agent's
    feet (``2 * MARGIN`` up) and middle (half its height up) both lie inside solids' material, open when its feet lie
    outside all of it (neither: a face near the feet, or feet in a solid and the middle out of it)."""
    back = trimesh.transform_points(points, _turned(-yaw_deg))
    feet_in, feet_out = _material(back + [0.0, 2 * MARGIN, 0.0], solids)
    middle_in, _ = _material(back + [0.0, 0.5 * float(AGENT.height), 0.0], solids)
    return feet_in & middle_in, feet_out


def ground_points(parts: list[trimesh.Trimesh]) -> np.ndarray:
    """(n, 3) metres: where vertical lines ``GRID`` apart cross an up-facing triangle of a part, each part on its
    own (in one mesh the intersector would skip one of two faces in one plane: a crate's bottom and the floor)."""
    lo, hi = np.min([p.bounds[0] for p in parts], axis=0), np.max([p.bounds[1] for p in parts], axis=0)
    xs, zs = np.arange(lo[0] + GRID / 2, hi[0], GRID), np.arange(lo[2] + GRID / 2, hi[2], GRID)
    xz = np.stack(np.meshgrid(xs, zs, indexing="ij"), axis=-1).reshape(-1, 2)
    found = []
    for part in parts:
        caster = RayCaster(part)
        _, point, face = all_hits_down(caster, xz, float(hi[1]) + 1.0)
        found.append(point[caster.face_normals[face, 1] > 0.5])
    return np.concatenate(found)


def rules(mesh: trimesh.Trimesh, points: np.ndarray) -> dict[str, np.ndarray]:
    """Each rule's answer (n,) bool (inside a closed solid) for ground ``points``."""
    from g2s_plugins import area_gaps
    from g2s_plugins.graph_builders import sampling

    caster = RayCaster(mesh)
    answers = {"sampler": sampling.inside_closed_solids(caster, points, AgentShape.from_config(AGENT))}
    answers["warning"] = area_gaps.shut_in(caster, points, AGENT)
    return answers


def measure(kind: str, seed: int, yaw_deg: float, routes: bool = False) -> dict[str, int]:
    """Counts of one case: ground points inside / open, and per rule those it keeps (inside called open) and drops
    (open called inside); with ``routes`` the nodes inside of both presets' graphs and structures."""
    parts, solids = case(kind, seed, yaw_deg)
    mesh = trimesh.util.concatenate(parts)
    points = ground_points(parts)
    inside, open_ = truth(points, solids, yaw_deg)
    row = {"inside": int(inside.sum()), "open": int(open_.sum())}
    for name, answer in rules(mesh, points).items():
        row[f"{name} kept"] = int((inside & ~answer).sum())
        row[f"{name} dropped"] = int((open_ & answer).sum())
    if routes:
        from g2s_core import api

        for preset, short in (("map_analysis_sampling", "sampling"), ("map_analysis", "navmesh")):
            result = api.run(mesh, preset, mesh_name=f"{kind} {seed} {yaw_deg:g}")
            for part, graph in (("graph", result.graph), ("structure", result.structure)):
                pos = np.array([graph.nodes[n]["pos"] for n in graph.nodes], dtype=np.float64).reshape(-1, 3)
                row[f"{short} {part} inside"] = int(truth(pos, solids, yaw_deg)[0].sum())
    return row


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--yaws", type=float, nargs="+", default=[0.0, 22.0, 45.0])
    parser.add_argument("--seeds", type=int, nargs="+", default=[0, 1, 2])
    parser.add_argument("--kinds", nargs="+", default=list(KINDS))
    parser.add_argument("--routes", action="store_true")
    args = parser.parse_args(argv)
    header = None
    for kind in args.kinds:
        for seed in args.seeds:
            for yaw in args.yaws:
                row = measure(kind, seed, yaw, args.routes)
                if header is None:
                    header = list(row)
                    print("| kind | seed | yaw | " + " | ".join(header) + " |")
                    print("|---|---:|---:|" + "---:|" * len(header))
                print(f"| {kind} | {seed} | {yaw:g} | " + " | ".join(str(row[k]) for k in header) + " |", flush=True)


if __name__ == "__main__":
    main()
