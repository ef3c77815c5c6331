"""How much of the floor a designer means to be walked the sampling builder keeps, and what turns the rest away.

Run: ``.venv/bin/python benchmarks/sampling_coverage.py [--cases a b] [--methods grid poisson] [--yaws 0 22 45]
[--agent r h climb slope]``

Each case is a generated piece with a known answer: its floor and the solids standing on it, drawn in plan.
The designer's area is where the agent's centre may stand: on the floor, at least the clearance (the agent's
radius) from the floor's edge and from every solid, computed on a 1 cm raster (a Euclidean distance
transform), not by rays. A grating's slots are cracks: its floor is the grating's outline. Per case, method and
yaw it prints

* ``designer``: that area, m²;
* ``kept``: the area the sampler's candidates that fit stand for on that floor (a grid candidate spacing² /
  cos(slope), a Poisson one the surface area over the candidates), and ``graph``: the area of the final graph's
  samples there (after the Poisson-disk pick and the small-region clean-up);
* ``lost``: candidates on the floor more than ``BAND`` inside the designer's area that do not fit, as area,
  split by the check that turned them away (:data:`~g2s_plugins.graph_builders.sampling.REJECTED_BY`, and
  ``solid`` for :func:`~g2s_plugins.graph_builders.sampling.inside_closed_solids`);
* ``wrong``: candidates that fit more than ``BAND`` outside it (nearer a solid or the floor's edge than the
  clearance less the band), as area, and the nearest any fitting candidate stands to a solid or an edge;
* ``elsewhere``: area kept off the designer's floor (roofs, a canopy's top).

Figures are recorded in docs/sampling.md, "Floor the sampler keeps".
"""

from __future__ import annotations

import argparse
import math
import sys
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
import trimesh
from scipy import ndimage
from scipy.spatial import ConvexHull

import piece_kinds10  # the tenth round's piece kinds and their helpers (this script's folder)
from g2s_plugins._raycasting import AgentShape, RayCaster
from g2s_plugins.graph_builders import sampling
from g2s_plugins.samples import pieces

_box, _hull = piece_kinds10._box, piece_kinds10._hull

RASTER = 0.01
"""Metres: the cell of the designer's plan."""

BAND = 0.03
"""Metres: candidates this close to the designer's boundary count neither as lost nor as wrong (the raster, the
8 clearance directions' corners and float rounding decide there)."""

PIECE_AGENT = (0.4, 2.0, 0.4, 60.0)
"""radius, height, max climb (m), max slope (degrees): the map-piece agent the pieces are designed for."""


@dataclass
class Case:
    """A level and its designer's answer, in the level's own (unturned) frame."""

    parts: list[trimesh.Trimesh]
    floors: list[np.ndarray] = field(default_factory=list)
    """Plan polygons (k, 2) of x, z, convex: where the floor is."""
    solids: list[np.ndarray] = field(default_factory=list)
    """Plan polygons (k, 2), convex: what stands on the floor within the agent's height."""
    floor_height: Callable[[np.ndarray], np.ndarray] = lambda xz: np.zeros(len(xz))
    """(n, 2) x, z -> (n,) the floor's top, m."""

    @property
    def mesh(self) -> trimesh.Trimesh:
        mesh = trimesh.util.concatenate(self.parts)
        mesh.merge_vertices()
        return mesh


def _hull2d(xz: np.ndarray) -> np.ndarray:
    """The convex hull (k, 2) of plan points (n, 2), counter-clockwise in (x, z) (scipy's Qhull)."""
    return xz[ConvexHull(xz).vertices]


def _by_height(parts: list[trimesh.Trimesh], height: float, floor_y: float = 0.0) -> Case:
    """A case from convex parts: a part whose top is the floor's is floor, one that reaches into the agent's
    height above it a solid, one wholly above that (a canopy, a lintel over the agent) neither."""
    case = Case(parts=list(parts), floor_height=lambda xz: np.full(len(xz), floor_y))
    for part in parts:
        low, high = part.bounds[0][1], part.bounds[1][1]
        if abs(high - floor_y) < 1e-6:
            case.floors.append(_hull2d(np.asarray(part.vertices)[:, [0, 2]]))
        elif low < floor_y + height and high > floor_y:
            case.solids.append(_hull2d(np.asarray(part.vertices)[:, [0, 2]]))
    return case


def _captured(factory: Callable[[], object], height: float) -> Case:
    """The parts ``factory`` (a piece kind of ``piece_kinds10``) builds, as a case; the same mesh as the kind's."""
    captured: list[list[trimesh.Trimesh]] = []
    original = piece_kinds10._level
    piece_kinds10._level = lambda name, parts, openings: captured.append(parts) or original(name, parts, openings)
    try:
        level = factory()
    finally:
        piece_kinds10._level = original
    case = _by_height(captured[0], height)
    assert np.array_equal(case.mesh.vertices, level.mesh.vertices), "the case is the kind's mesh"
    return case


def plain_room(height: float) -> Case:
    """Room 8 x 6 m, walls 0.3 m thick and 3 m high, a 1.6 m doorway west."""
    return _by_height(piece_kinds10._room(8.0, 6.0, {"W": [(2.2, 3.8, 3.0)]}), height)


def pillar_room(height: float) -> Case:
    """Room 12 x 10 m, a 1.6 m doorway west, six pillars 0.6 m square and 3 m tall, one turned 30 degrees."""
    parts = piece_kinds10._room(12.0, 10.0, {"W": [(4.2, 5.8, 3.0)]})
    for x, z in ((3.0, 3.0), (6.0, 3.0), (9.0, 3.0), (3.0, 7.0), (6.0, 7.0)):
        parts.append(_box(x - 0.3, x + 0.3, 0.0, 3.0, z - 0.3, z + 0.3))
    a = math.radians(30.0)
    corners = [(9.0 + 0.3 * (u * math.cos(a) - v * math.sin(a)), 7.0 + 0.3 * (u * math.sin(a) + v * math.cos(a)))
               for u in (-1, 1) for v in (-1, 1)]
    parts.append(_hull([[x, y, z] for x, z in corners for y in (0.0, 3.0)]))
    return _by_height(parts, height)


def ramp(height: float, degrees: float = 15.0) -> Case:
    """A corridor 2.4 m wide between walls 3 m high over its floor: 3 m flat, a ramp 8 m long at ``degrees``,
    3 m flat at its top; closed at both ends."""
    g = math.tan(math.radians(degrees))
    top = 8.0 * g

    def y(x):
        return np.clip(np.asarray(x, dtype=np.float64) - 3.0, 0.0, 8.0) * g

    def strip(x0, x1, z0, z1, bottom, above):
        return _hull([[x, float(y(x)) + d, z] for x in (x0, x1) for d in (bottom, above) for z in (z0, z1)])

    parts, solids = [], []
    for x0, x1 in ((0.0, 3.0), (3.0, 11.0), (11.0, 14.0)):
        parts.append(strip(x0, x1, 0.0, 2.4, -0.2, 0.0))
        for z0, z1 in ((-0.3, 0.0), (2.4, 2.7)):
            parts.append(strip(x0, x1, z0, z1, -0.2, 3.0))
            solids.append(np.array([[x0, z0], [x1, z0], [x1, z1], [x0, z1]]))
    parts += [_box(-0.3, 0.0, -0.2, 3.0, -0.3, 2.7), _box(14.0, 14.3, top - 0.2, top + 3.0, -0.3, 2.7)]
    solids += [np.array([[-0.3, -0.3], [0.0, -0.3], [0.0, 2.7], [-0.3, 2.7]]),
               np.array([[14.0, -0.3], [14.3, -0.3], [14.3, 2.7], [14.0, 2.7]])]
    return Case(parts=parts, floors=[np.array([[0.0, 0.0], [14.0, 0.0], [14.0, 2.4], [0.0, 2.4]])], solids=solids,
                floor_height=lambda xz: y(xz[:, 0]))


def grated_room(height: float, slot: float = 0.02, slat: float = 0.08) -> Case:
    """Room 8 x 6 m, 1.6 m doorways west and east, its floor a grating over nothing: slats ``slat`` m wide running
    west-east, ``slot`` m apart, 0.05 m thick, out to the walls' outer faces."""
    room = piece_kinds10._room(8.0, 6.0, {"W": [(2.2, 3.8, 3.0)], "E": [(2.2, 3.8, 3.0)]})
    parts = room[1:]  # the walls; the grating replaces the slab
    z = -0.3
    while z < 6.3 - 1e-9:
        parts.append(_box(-0.3, 8.3, -0.05, 0.0, z, min(z + slat, 6.3)))
        z += slat + slot
    case = _by_height(parts, height)
    case.floors = [np.array([[-0.3, -0.3], [8.3, -0.3], [8.3, 6.3], [-0.3, 6.3]])]
    return case


def split_floor(height: float, gap: float = 0.15) -> Case:
    """Room 8 x 6 m whose floor is two slabs ``gap`` m apart across its middle (x 4), over nothing: wider than a
    crack (twice the crack step, r / 4), so the floor's edges along it are ledges."""
    room = piece_kinds10._room(8.0, 6.0, {"W": [(2.2, 3.8, 3.0)]})
    x = 4.0 - 0.5 * gap
    parts = room[1:] + [_box(-0.3, x, -0.2, 0.0, -0.3, 6.3), _box(x + gap, 8.3, -0.2, 0.0, -0.3, 6.3)]
    return _by_height(parts, height)


CASES: dict[str, Callable[[float], Case]] = {
    "plain_room": plain_room,
    "pillar_room": pillar_room,
    "ramp_15": ramp,
    "split_floor_15cm": split_floor,
    "grating_2cm": grated_room,
    "grating_3cm": lambda height: grated_room(height, slot=0.03),
    "drum_1.5": lambda height: _captured(lambda: piece_kinds10.revolving_drum(1.5), height),
    "drum_1.8": lambda height: _captured(lambda: piece_kinds10.revolving_drum(1.8), height),
}
"""Case name -> builder (of the agent's height)."""


def _fill(raster: np.ndarray, origin: np.ndarray, polygon: np.ndarray) -> None:
    """Set the cells of ``raster`` (x by z, cell ``RASTER`` from ``origin``) whose centres lie in a convex polygon."""
    lo = np.floor((polygon.min(axis=0) - origin) / RASTER).astype(int)
    hi = np.ceil((polygon.max(axis=0) - origin) / RASTER).astype(int) + 1
    lo, hi = np.maximum(lo, 0), np.minimum(hi, raster.shape)
    if np.any(hi <= lo):
        return
    gx, gz = np.meshgrid(origin[0] + (np.arange(lo[0], hi[0]) + 0.5) * RASTER,
                         origin[1] + (np.arange(lo[1], hi[1]) + 0.5) * RASTER, indexing="ij")
    inside = np.ones(gx.shape, dtype=bool)
    for a, b in zip(polygon, np.roll(polygon, -1, axis=0)):  # counter-clockwise in (x, z): inside on the left
        inside &= (b[0] - a[0]) * (gz - a[1]) - (b[1] - a[1]) * (gx - a[0]) >= 0
    raster[lo[0]:hi[0], lo[1]:hi[1]] |= inside


class Designer:
    """The distance from each plan point on the floor to the nearest solid or floor edge (m; 0 off the floor)."""

    def __init__(self, case: Case) -> None:
        everything = np.concatenate(case.floors + case.solids)
        self.origin = everything.min(axis=0) - 0.5
        shape = tuple(np.ceil((everything.max(axis=0) + 0.5 - self.origin) / RASTER).astype(int))
        free = np.zeros(shape, dtype=bool)
        for polygon in case.floors:
            _fill(free, self.origin, polygon)
        blocked = np.zeros(shape, dtype=bool)
        for polygon in case.solids:
            _fill(blocked, self.origin, polygon)
        self.distance = ndimage.distance_transform_edt(free & ~blocked) * RASTER

    def area(self, clearance: float) -> float:
        return float(np.count_nonzero(self.distance >= clearance)) * RASTER * RASTER

    def at(self, xz: np.ndarray) -> np.ndarray:
        cell = np.floor((xz - self.origin) / RASTER).astype(int)
        cell = np.clip(cell, 0, np.array(self.distance.shape) - 1)
        return self.distance[cell[:, 0], cell[:, 1]]


def measure(case: Case, method: str, yaw: float, agent: AgentShape) -> dict[str, float]:
    """The figures of one run (see the module docstring)."""
    mesh = case.mesh
    back = np.eye(4)
    if yaw:
        turn = pieces.yaw_about_centre(mesh, yaw)
        mesh = mesh.copy()
        mesh.apply_transform(turn)
        back = np.linalg.inv(turn)
    params = sampling.Params(method=method)
    spacing, _, clearance, _, _ = sampling._resolve(params, agent)
    surface = sampling.walkable_surface(mesh, agent)
    if method == "poisson":
        candidates, faces, each = sampling._poisson_candidates(surface, spacing, params)
        weight = np.full(len(candidates), each)
    else:
        candidates, faces = sampling._grid_candidates(surface, spacing)
        weight = spacing**2 / np.maximum(np.asarray(surface.face_normals)[faces][:, 1], 1e-6)
    caster = RayCaster(mesh)
    why = np.zeros(len(candidates), dtype=np.int8)
    fits = sampling.agent_fits(caster, candidates, agent, clearance, surface, faces, rejected=why)
    solid = np.zeros(len(candidates), dtype=bool)
    solid[fits] = sampling.inside_closed_solids(caster, candidates[fits], agent)
    fits &= ~solid
    designer = Designer(case)

    def on_floor(points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        own = trimesh.transform_points(points, back)
        level = np.abs(own[:, 1] - case.floor_height(own[:, [0, 2]])) < 0.02
        return level, designer.at(own[:, [0, 2]])

    floor, room = on_floor(candidates)
    inside, outside = floor & (room >= clearance + BAND), floor & (room < clearance - BAND)
    graph = sampling.build_sampled_graph(mesh, params, agent)
    nodes = np.array([d["pos"] for _, d in graph.nodes(data=True)]).reshape(-1, 3)
    areas = np.array([d["area"] for _, d in graph.nodes(data=True)])
    node_floor, _ = on_floor(nodes)
    row = {
        "designer": designer.area(clearance),
        "kept": float(weight[fits & floor].sum()),
        "graph": float(areas[node_floor].sum()),
        "lost": float(weight[inside & ~fits].sum()),
        "wrong": float(weight[outside & fits].sum()),
        "nearest": float(room[fits & floor].min()) if np.any(fits & floor) else math.nan,
        "elsewhere": float(weight[fits & ~floor].sum()),
    }
    for code, name in enumerate(sampling.REJECTED_BY[1:], start=1):
        row[f"lost: {name}"] = float(weight[inside & ~fits & (why == code)].sum())
    row["lost: solid"] = float(weight[inside & solid].sum())
    return row


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cases", nargs="+", choices=sorted(CASES), default=list(CASES))
    parser.add_argument("--methods", nargs="+", choices=["grid", "poisson"], default=["grid", "poisson"])
    parser.add_argument("--yaws", type=float, nargs="+", default=[0.0, 22.0, 45.0])
    parser.add_argument("--agent", type=float, nargs=4, default=PIECE_AGENT, metavar=("R", "H", "CLIMB", "SLOPE"))
    args = parser.parse_args(argv)
    radius, height, climb, slope = args.agent
    agent = AgentShape(radius=radius, height=height, max_climb=climb, max_slope_deg=slope)
    print("case, method, yaw: designer / kept / graph m²; lost (head room, wall, ledge, solid); wrong; nearest m; elsewhere")
    for name in args.cases:
        case = CASES[name](height)
        for method in args.methods:
            for yaw in args.yaws:
                r = measure(case, method, yaw, agent)
                print(f"  {name:12s} {method:7s} {yaw:4g}: {r['designer']:6.2f} / {r['kept']:6.2f} / {r['graph']:6.2f};"
                      f" lost {r['lost']:5.2f} ({r['lost: head room']:.2f}, {r['lost: wall']:.2f},"
                      f" {r['lost: ledge']:.2f}, {r['lost: solid']:.2f}); wrong {r['wrong']:.2f};"
                      f" nearest {r['nearest']:.3f}; elsewhere {r['elsewhere']:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
