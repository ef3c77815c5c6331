"""Procedural sample levels with known ground truth, for tests and demos.

Every factory here builds a level in code and returns a :class:`SampleLevel`:
one triangle mesh plus the ground truth a test needs (the openings, floor
heights, the number of loops, ...). Frames and units follow the rest of g2s:
metres, Y up, right-handed; floors are at ``y = 0`` unless a factory says
otherwise.

How the levels are made
-----------------------
Every level is a set of solid hexahedra (mostly axis-aligned boxes), each with
outward-facing triangles, merged into one mesh with duplicate vertices merged:

* floors are slabs ``SLAB_THICKNESS`` (0.2 m) thick whose top is the floor
  height; their top triangles face +Y;
* walls are boxes ``WALL_THICKNESS`` (0.2 m) thick standing *outside* the
  floor they bound (their inner face is the floor's edge), from the slab's
  bottom to ``WALL_HEIGHT`` (3 m) above the floor, so a 2 m tall agent can
  neither walk over nor under them and Recast rasterises them solidly;
* ramps are solid wedges with sloped side walls that stay ``WALL_HEIGHT``
  above the ramp surface;
* an *opening* is a floor edge with no wall: the slab stops and there is
  nothing beyond it.

The levels are designed for :data:`DESIGN_AGENT` (radius 0.5 m, height 2 m,
max climb 0.4 m, max slope 45 degrees): corridors and doors are at least 2 m
wide, obstacles keep gaps wider than the agent.

:class:`~g2s_core.model.Opening` end points follow one rule here: facing
along ``heading`` (out of the level), ``p0`` is on the left and ``p1`` on the
right, i.e. ``p0 = position + width / 2 * (up x heading)``.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Annotated, Any

import numpy as np
from pydantic import Field, NonNegativeFloat, NonNegativeInt, PositiveFloat, PositiveInt, validate_call

from g2s_core.model import Opening, Vec3
from g2s_plugins.vectors import vec3

# trimesh and scipy are imported in the functions that build with them, here and in the other sample modules:
# `g2s plugins` lists every sample level (its factory's signature) without them (docs/performance.md, "Start-up")
if TYPE_CHECKING:
    import trimesh

WALL_HEIGHT = 3.0
"""Height of every wall above the floor it bounds, metres."""

WALL_THICKNESS = 0.2
"""Thickness of every wall box, metres."""

SLAB_THICKNESS = 0.2
"""Thickness of every floor slab (its top is the floor height), metres."""

Probability = Annotated[float, Field(ge=0, le=1)]
"""A factory parameter that is a probability."""

RampSlope = Annotated[float, Field(gt=0, lt=90)]
"""A factory parameter that is a ramp's slope, degrees (a ramp rises, so its run is finite and > 0)."""

DESIGN_AGENT: dict[str, float] = {
    "radius": 0.5,
    "height": 2.0,
    "max_climb": 0.4,
    "max_slope_deg": 45.0,
}
"""The agent the samples are designed for (metres, degrees)."""

# Sides of an axis-aligned rectangle, in the order used by aperture arrays.
NX, PX, NZ, PZ = 0, 1, 2, 3
_SIDE_HEADING = np.array([[-1.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 0.0, 1.0]])
_SIDE_NAME = ("-X", "+X", "-Z", "+Z")

# A hexahedron's corner i sits at (x, y, z) = (i & 1, i >> 1 & 1, i >> 2 & 1) of
# its box; the quads below run counter-clockwise seen from outside.
_HEX_BITS = np.array([[i & 1, (i >> 1) & 1, (i >> 2) & 1] for i in range(8)], dtype=np.float64)
_HEX_QUADS = np.array(
    [[2, 6, 7, 3], [0, 1, 5, 4], [1, 3, 7, 5], [0, 4, 6, 2], [4, 5, 7, 6], [0, 2, 3, 1]],
    dtype=np.int64,
)
_HEX_FACES = np.concatenate([_HEX_QUADS[:, [0, 1, 2]], _HEX_QUADS[:, [0, 2, 3]]])  # (12, 3)

_EPS = 1e-9


@dataclass(frozen=True)
class SampleLevel:
    """A generated level and its ground truth.

    Attributes:
        name: the factory's name (a key of :data:`SAMPLES`).
        mesh: one merged triangle mesh, metres, Y up; duplicate vertices are
            merged and every solid's triangles face outwards, so floor tops
            face +Y. Not watertight in general (solids touch and overlap).
        openings: the ground-truth entries/exits, in a documented order.
        metadata: factory-specific ground truth. Every level has
            ``params`` (the arguments used), ``floor_heights`` (tuple of
            floats, m), ``floor_area`` (m², top surface of floors and ramps
            before any agent erosion), ``closed`` (no openings),
            ``components`` (number of walkable regions not joined to each
            other), ``cycles`` (independent loops of the walkable area: holes
            around obstacles plus loops of rooms), ``design_agent``,
            ``wall_height``, ``wall_thickness``, ``slab_thickness``.
    """

    name: str
    mesh: trimesh.Trimesh
    openings: tuple[Opening, ...]
    metadata: dict[str, Any] = field(default_factory=dict)


# --------------------------------------------------------------------------
# Geometry helpers
# --------------------------------------------------------------------------


def _col(values: Any, n: int) -> np.ndarray:
    """``values`` (scalar or sequence) broadcast to a (n,) float64 array."""
    return np.broadcast_to(np.asarray(values, dtype=np.float64), (n,)).astype(np.float64)


def _columns(*values: Any) -> list[np.ndarray]:
    """Scalars and (n,) sequences broadcast together to (n,) float64 arrays."""
    arrays = np.broadcast_arrays(*(np.asarray(v, dtype=np.float64) for v in values))
    return [np.atleast_1d(a).astype(np.float64) for a in arrays]


def _box_corners(lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """Corners of axis-aligned boxes: lo, hi (n, 3) -> (n, 8, 3), metres."""
    return lo[:, None, :] + _HEX_BITS[None, :, :] * (hi - lo)[:, None, :]


def _axis_boxes(
    along_x: Any, a0: Any, a1: Any, c0: Any, c1: Any, y0: Any, y1: Any
) -> tuple[np.ndarray, np.ndarray]:
    """Boxes given along/across ranges: (lo, hi), each (n, 3), metres.

    ``along_x`` (n,) bool says whether the "along" range [a0, a1] is on X
    (then [c0, c1] is on Z) or on Z (then [c0, c1] is on X); [y0, y1] is on Y.
    The other arguments are scalars or (n,) arrays.
    """
    a0, a1, c0, c1, y0, y1 = _columns(a0, a1, c0, c1, y0, y1)
    ax = np.broadcast_to(np.asarray(along_x, dtype=bool), a0.shape)[:, None]
    lo = np.where(ax, np.stack([a0, y0, c0], axis=1), np.stack([c0, y0, a0], axis=1))
    hi = np.where(ax, np.stack([a1, y1, c1], axis=1), np.stack([c1, y1, a1], axis=1))
    return lo, hi


def _sloped_blocks(x0: Any, x1: Any, z0: Any, z1: Any, bottom: Any, top0: Any, top1: Any) -> np.ndarray:
    """Blocks over [x0, x1] x [z0, z1] with a flat bottom and a top rising along +X.

    The top is at ``top0`` over x0 and ``top1`` over x1. All arguments are
    scalars or (n,) arrays in metres; returns hexahedron corners (n, 8, 3).
    """
    x0, x1, z0, z1, bottom, top0, top1 = _columns(x0, x1, z0, z1, bottom, top0, top1)
    bx, by, bz = _HEX_BITS[:, 0], _HEX_BITS[:, 1], _HEX_BITS[:, 2]
    x = x0[:, None] + bx[None] * (x1 - x0)[:, None]
    z = z0[:, None] + bz[None] * (z1 - z0)[:, None]
    top = top0[:, None] + bx[None] * (top1 - top0)[:, None]
    y = np.where(by[None] > 0, top, bottom[:, None])
    return np.stack([x, y, z], axis=2)


def _plan_hexahedra(base: np.ndarray, top: np.ndarray, y0: Any, y1: Any) -> np.ndarray:
    """Hexahedra with vertical sides between a base quad at ``y0`` and a top quad at ``y1``.

    ``base`` and ``top`` are (n, 4, 2) x, z corners in the order (u0, v0),
    (u1, v0), (u1, v1), (u0, v1) of the solid's own (u, v) frame, with v to
    the left of u seen from above (counter-clockwise, as an axis-aligned box's
    x0z0, x1z0, x1z1, x0z1); ``y0``, ``y1`` scalars or (n,), metres. Returns
    corners (n, 8, 3) in the ``_HEX_BITS`` order.
    """
    base = np.asarray(base, dtype=np.float64).reshape(-1, 4, 2)
    top = np.asarray(top, dtype=np.float64).reshape(-1, 4, 2)
    y0, y1 = _col(y0, len(base)), _col(y1, len(base))
    quad_corner = np.array([0, 1, 3, 2])[(_HEX_BITS[:, 0] + 2 * _HEX_BITS[:, 2]).astype(int)]  # (8,)
    upper = _HEX_BITS[:, 1] > 0
    xz = np.where(upper[None, :, None], top[:, quad_corner], base[:, quad_corner])
    y = np.where(upper[None, :], y1[:, None], y0[:, None])
    return np.stack([xz[:, :, 0], y, xz[:, :, 1]], axis=2)


def _turned_rectangle(cx: float, cz: float, half_x: float, half_z: float, angle: float) -> np.ndarray:
    """Corners (4, 2) of a rectangle turned by ``angle`` about its centre, counter-clockwise from above."""
    local = np.array([[-half_x, -half_z], [half_x, -half_z], [half_x, half_z], [-half_x, half_z]])
    c, s = math.cos(angle), math.sin(angle)
    return local @ np.array([[c, s], [-s, c]]) + (cx, cz)


def _hexahedra_mesh(corners: np.ndarray) -> trimesh.Trimesh:
    """One mesh from hexahedra (n, 8, 3), 12 outward triangles each, vertices merged."""
    import trimesh

    n = len(corners)
    vertices = corners.reshape(-1, 3)
    faces = (_HEX_FACES[None, :, :] + 8 * np.arange(n, dtype=np.int64)[:, None, None]).reshape(-1, 3)
    mesh = trimesh.Trimesh(vertices=vertices, faces=faces, process=False)
    mesh.merge_vertices()
    return mesh


def _opening(position: Any, heading: Any, width: float) -> Opening:
    """An :class:`Opening` from its midpoint, outward heading and width (metres).

    ``p0`` is left of ``heading`` seen from above (+Y), ``p1`` right of it.
    """
    p = np.asarray(position, dtype=np.float64)
    h = np.asarray(heading, dtype=np.float64)
    h = h / np.linalg.norm(h)
    half = 0.5 * float(width) * np.cross([0.0, 1.0, 0.0], h)
    return Opening(
        position=vec3(p + 0.0),
        heading=vec3(h + 0.0),
        width=float(width),
        p0=vec3(p + half + 0.0),
        p1=vec3(p - half + 0.0),
    )


def _no_apertures(n: int) -> np.ndarray:
    """An aperture array for ``n`` rooms with solid walls: (n, 4, 4) of NaN."""
    return np.full((n, 4, 4), np.nan)


class _LevelBuilder:
    """Collects the solids of a level and makes the :class:`SampleLevel`."""

    def __init__(self) -> None:
        self._corners: list[np.ndarray] = []
        self.floor_area = 0.0

    # -- raw solids ---------------------------------------------------------

    def boxes(self, lo: np.ndarray, hi: np.ndarray) -> None:
        """Add axis-aligned boxes, lo/hi (n, 3) metres; empty boxes are skipped."""
        lo = np.asarray(lo, dtype=np.float64).reshape(-1, 3)
        hi = np.asarray(hi, dtype=np.float64).reshape(-1, 3)
        keep = np.all(hi - lo > _EPS, axis=1)
        if np.any(keep):
            self._corners.append(_box_corners(lo[keep], hi[keep]))

    def hexahedra(self, corners: np.ndarray) -> None:
        """Add general hexahedra, corners (n, 8, 3) in the ``_HEX_BITS`` order."""
        self._corners.append(np.asarray(corners, dtype=np.float64).reshape(-1, 8, 3))

    # -- level parts --------------------------------------------------------

    def floors(self, x0: Any, x1: Any, z0: Any, z1: Any, top: Any) -> None:
        """Floor slabs over [x0, x1] x [z0, z1] with their top at ``top`` (scalars or (n,))."""
        lo, hi = _axis_boxes(True, x0, x1, z0, z1, np.asarray(top) - SLAB_THICKNESS, top)
        self.boxes(lo, hi)
        self.floor_area += float(np.sum((hi[:, 0] - lo[:, 0]) * (hi[:, 2] - lo[:, 2])))

    def corridors(self, along_x: Any, start: Any, end: Any, centre: Any, width: Any, floor: Any) -> None:
        """Straight corridors: a floor slab and a wall on each long side, ends open.

        Each corridor runs over [start, end] along X (``along_x``) or Z, is
        ``width`` wide (clear width between the walls) around ``centre`` on
        the other axis, with its floor at ``floor``. Scalars or (n,) arrays.
        """
        a0, a1, c, w, y = _columns(start, end, centre, width, floor)
        half, t = 0.5 * w, WALL_THICKNESS
        lo, hi = _axis_boxes(along_x, a0, a1, c - half, c + half, y - SLAB_THICKNESS, y)
        self.boxes(lo, hi)
        self.floor_area += float(np.sum((a1 - a0) * w))
        for c0, c1 in ((c + half, c + half + t), (c - half - t, c - half)):
            self.boxes(*_axis_boxes(along_x, a0, a1, c0, c1, y - SLAB_THICKNESS, y + WALL_HEIGHT))

    def room_walls(self, bounds: np.ndarray, floor: Any, apertures: np.ndarray | None = None) -> None:
        """Walls around rectangular floors, with at most one aperture per side.

        Args:
            bounds: (n, 4) floor rectangles ``x0, x1, z0, z1``, metres.
            floor: scalar or (n,) floor heights, metres.
            apertures: (n, 4, 4) per room and side (order ``NX, PX, NZ, PZ``):
                ``along0, along1`` (the aperture's range along the side, in
                world Z for the X sides and world X for the Z sides) and
                ``bottom, top`` (its height range above the floor). A NaN row
                is a solid wall. ``bottom <= 0`` leaves the wall open down to
                the floor (a doorway or a corridor mouth), ``top >=
                WALL_HEIGHT`` leaves it open to the top.
        """
        bounds = np.asarray(bounds, dtype=np.float64).reshape(-1, 4)
        n = len(bounds)
        floor = _col(floor, n)
        apertures = _no_apertures(n) if apertures is None else np.asarray(apertures, dtype=np.float64)
        t = WALL_THICKNESS
        x0, x1, z0, z1 = bounds.T
        y_bottom, y_top = floor - SLAB_THICKNESS, floor + WALL_HEIGHT
        for side in range(4):
            along_x = side in (NZ, PZ)
            a0, a1 = (x0 - t, x1 + t) if along_x else (z0 - t, z1 + t)
            edge = (x0, x1, z0, z1)[side]
            c0, c1 = (edge - t, edge) if side in (NX, NZ) else (edge, edge + t)
            ap = apertures[:, side]
            solid = np.isnan(ap[:, 0])
            g0 = np.where(solid, a1, ap[:, 0])
            g1 = np.where(solid, a1, ap[:, 1])
            below_top = np.where(solid | ~(ap[:, 2] > 0), y_bottom, floor + ap[:, 2])
            above_bottom = np.where(solid, y_top, floor + np.minimum(ap[:, 3], WALL_HEIGHT))
            for p0, p1, q0, q1 in (
                (a0, g0, y_bottom, y_top),
                (g1, a1, y_bottom, y_top),
                (g0, g1, y_bottom, below_top),
                (g0, g1, above_bottom, y_top),
            ):
                self.boxes(*_axis_boxes(along_x, p0, p1, c0, c1, q0, q1))

    def ramp(self, x0: float, x1: float, zc: float, width: float, y0: float, y1: float) -> None:
        """A walled ramp along +X from (x0, y0) to (x1, y1), ``width`` wide around z = ``zc``.

        The ramp is a solid wedge down to ``y0 - SLAB_THICKNESS``; its side
        walls stay ``WALL_HEIGHT`` above the ramp surface. Both ends are open.
        """
        half, t, bottom = 0.5 * width, WALL_THICKNESS, y0 - SLAB_THICKNESS
        self.hexahedra(_sloped_blocks(x0, x1, zc - half, zc + half, bottom, y0, y1))
        z0, z1 = [zc + half, zc - half - t], [zc + half + t, zc - half]
        self.hexahedra(_sloped_blocks(x0, x1, z0, z1, bottom, y0 + WALL_HEIGHT, y1 + WALL_HEIGHT))
        self.floor_area += width * math.hypot(x1 - x0, y1 - y0)

    # -- result -------------------------------------------------------------

    def build(self, name: str, openings: list[Opening], metadata: dict[str, Any]) -> SampleLevel:
        """The :class:`SampleLevel` made of everything added so far."""
        mesh = _hexahedra_mesh(np.concatenate(self._corners))
        meta = {
            "floor_area": round(self.floor_area, 9),
            "closed": len(openings) == 0,
            "design_agent": dict(DESIGN_AGENT),
            "wall_height": WALL_HEIGHT,
            "wall_thickness": WALL_THICKNESS,
            "slab_thickness": SLAB_THICKNESS,
        }
        meta.update(metadata)
        return SampleLevel(name=name, mesh=mesh, openings=tuple(openings), metadata=meta)


def _rect(x0: float, x1: float, z0: float, z1: float) -> dict[str, float]:
    """A floor rectangle for metadata: ``{"x0", "x1", "z0", "z1"}``, metres."""
    return {"x0": float(x0), "x1": float(x1), "z0": float(z0), "z1": float(z1)}


def _end_openings(x_start: float, y_start: float, x_end: float, y_end: float, width: float) -> list[Opening]:
    """The open -X and +X ends of a corridor along X centred on z = 0."""
    return [
        _opening((x_start, y_start, 0.0), (-1.0, 0.0, 0.0), width),
        _opening((x_end, y_end, 0.0), (1.0, 0.0, 0.0), width),
    ]


def _ramp_run(rise: float, slope_deg: float) -> float:
    """Horizontal length (m) of a ramp climbing ``rise`` metres at ``slope_deg`` (in (0, 90))."""
    return rise / math.tan(math.radians(slope_deg))


def _ramp_meta(
    x0: float, x1: float, zc: float, width: float, y0: float, y1: float, slope_deg: float
) -> dict[str, float]:
    """Metadata of a ramp along +X: extent ``x0, x1, z0, z1`` and end heights ``y0, y1``
    (m), ``slope_deg``, ``run`` (horizontal length, m)."""
    return {
        **_rect(x0, x1, zc - width / 2, zc + width / 2),
        "y0": float(y0),
        "y1": float(y1),
        "slope_deg": float(slope_deg),
        "run": float(x1 - x0),
    }


# --------------------------------------------------------------------------
# Simple samples
# --------------------------------------------------------------------------


@validate_call
def straight_corridor(length: PositiveFloat = 12.0, width: PositiveFloat = 3.0) -> SampleLevel:
    """A straight corridor along +X, walled on both long sides, both ends open.

    The floor covers x in [0, length], z in [-width/2, width/2] at y = 0.
    Openings (2): the -X end at x = 0, then the +X end at x = ``length``.
    Metadata: ``floor_heights`` (0.0,).

    Args:
        length: corridor length, metres.
        width: corridor width between its walls, metres.
    """
    b = _LevelBuilder()
    b.corridors(True, 0.0, length, 0.0, width, 0.0)
    meta = {
        "params": {"length": length, "width": width},
        "floor_heights": (0.0,),
        "floor": _rect(0.0, length, -width / 2, width / 2),
        "components": 1,
        "cycles": 0,
    }
    return b.build("straight_corridor", _end_openings(0.0, 0.0, length, 0.0, width), meta)


@validate_call
def corridor_with_ramp(
    lower_length: PositiveFloat = 6.0,
    upper_length: PositiveFloat = 6.0,
    width: PositiveFloat = 3.0,
    rise: PositiveFloat = 2.0,
    slope_deg: RampSlope = 20.0,
) -> SampleLevel:
    """A corridor along +X that climbs a walled ramp to a higher floor; both ends open.

    Lower floor: x in [0, lower_length] at y = 0. Ramp: from x = lower_length
    up to y = ``rise`` (run = rise / tan(slope_deg)). Upper floor: the next
    ``upper_length`` at y = ``rise`` (a thin slab, nothing below it). The
    corridor is centred on z = 0.
    Openings (2): the lower end (heading -X, y = 0), then the upper end
    (heading +X, y = ``rise``).
    Metadata: ``floor_heights`` (0, rise); ``ramp`` dict with ``x0, x1, z0,
    z1`` (its extent, m), ``y0, y1`` (heights at its ends), ``slope_deg``,
    ``run``.

    Args:
        lower_length: length of the lower floor, metres.
        upper_length: length of the upper floor, metres.
        width: width of the corridor and the ramp, metres.
        rise: height of the upper floor above the lower one, metres.
        slope_deg: the ramp's slope, degrees (the design agent walks up to 45).
    """
    run = _ramp_run(rise, slope_deg)
    xr0, xr1 = lower_length, lower_length + run
    x_end = xr1 + upper_length
    b = _LevelBuilder()
    b.corridors(True, [0.0, xr1], [xr0, x_end], 0.0, width, [0.0, rise])
    b.ramp(xr0, xr1, 0.0, width, 0.0, rise)
    meta = {
        "params": {
            "lower_length": lower_length,
            "upper_length": upper_length,
            "width": width,
            "rise": rise,
            "slope_deg": slope_deg,
        },
        "floor_heights": (0.0, float(rise)),
        "ramp": _ramp_meta(xr0, xr1, 0.0, width, 0.0, rise, slope_deg),
        "components": 1,
        "cycles": 0,
    }
    return b.build("corridor_with_ramp", _end_openings(0.0, 0.0, x_end, rise, width), meta)


def _hub(
    name: str, arms: tuple[int, ...], hub_size: float, arm_length: float, arm_width: float
) -> SampleLevel:
    """A square hub room centred on the origin with corridor arms on the given sides."""
    if arm_width >= hub_size:
        raise ValueError(f"arm_width ({arm_width}) must be < hub_size ({hub_size})")
    h, w = 0.5 * hub_size, float(arm_width)
    b = _LevelBuilder()
    b.floors(-h, h, -h, h, 0.0)
    apertures = _no_apertures(1)
    openings = []
    for side in arms:
        apertures[0, side] = (-w / 2, w / 2, 0.0, WALL_HEIGHT)
        sign = 1.0 if side in (PX, PZ) else -1.0
        start, end = (h, h + arm_length) if sign > 0 else (-h - arm_length, -h)
        b.corridors(side in (NX, PX), start, end, 0.0, w, 0.0)
        openings.append(_opening(_SIDE_HEADING[side] * (h + arm_length), _SIDE_HEADING[side], w))
    b.room_walls([[-h, h, -h, h]], 0.0, apertures)
    meta = {
        "params": {"hub_size": hub_size, "arm_length": arm_length, "arm_width": arm_width},
        "floor_heights": (0.0,),
        "hub": _rect(-h, h, -h, h),
        "arms": tuple(_SIDE_NAME[s] for s in arms),
        "components": 1,
        "cycles": 0,
    }
    return b.build(name, openings, meta)


@validate_call
def cross_hub(
    hub_size: PositiveFloat = 8.0, arm_length: PositiveFloat = 6.0, arm_width: PositiveFloat = 3.0
) -> SampleLevel:
    """A square hub room (centred on the origin, y = 0) with 4 corridor arms, ends open.

    The hub covers [-hub_size/2, hub_size/2]² in x, z; each arm is centred on
    an axis. Openings (4), one per arm end, in the order +X, +Z, -X, -Z
    (``metadata['arms']``).

    Args:
        hub_size: side of the square hub, metres.
        arm_length: length of each arm from the hub's wall to its open end, metres.
        arm_width: width of each arm, metres.
    """
    return _hub("cross_hub", (PX, PZ, NX, NZ), hub_size, arm_length, arm_width)


@validate_call
def t_hub(
    hub_size: PositiveFloat = 8.0, arm_length: PositiveFloat = 6.0, arm_width: PositiveFloat = 3.0
) -> SampleLevel:
    """Like :func:`cross_hub` with 3 arms (+X, -X, -Z; the +Z side is walled): 3 openings.

    Args:
        hub_size: side of the square hub, metres.
        arm_length: length of each arm from the hub's wall to its open end, metres.
        arm_width: width of each arm, metres.
    """
    return _hub("t_hub", (PX, NX, NZ), hub_size, arm_length, arm_width)


@validate_call
def closed_room(width: PositiveFloat = 8.0, depth: PositiveFloat = 6.0) -> SampleLevel:
    """A room closed by walls on all sides: 0 openings.

    The floor covers x in [-width/2, width/2], z in [-depth/2, depth/2] at y = 0.

    Args:
        width: the floor's extent along X, metres.
        depth: the floor's extent along Z, metres.
    """
    bounds = [-width / 2, width / 2, -depth / 2, depth / 2]
    b = _LevelBuilder()
    b.floors(*bounds, 0.0)
    b.room_walls([bounds], 0.0)
    meta = {
        "params": {"width": width, "depth": depth},
        "floor_heights": (0.0,),
        "room": _rect(*bounds),
        "components": 1,
        "cycles": 0,
    }
    return b.build("closed_room", [], meta)


@validate_call
def room_with_window(
    width: PositiveFloat = 8.0,
    depth: PositiveFloat = 6.0,
    door_width: PositiveFloat = 2.0,
    door_height: PositiveFloat = 2.5,
    window_width: PositiveFloat = 2.0,
    sill_height: PositiveFloat = 1.0,
    window_top: float = 2.0,
) -> SampleLevel:
    """A room with a doorway (the one opening) and a window (not an opening).

    The floor covers x in [-width/2, width/2], z in [-depth/2, depth/2] at
    y = 0. The doorway is a gap centred on z = 0 in the +X wall, under a
    lintel; the floor ends at the doorway (nothing beyond), so it leads
    outside. The window is a hole centred on x = 0 in the +Z wall.
    Openings (1): the doorway, heading +X.
    Metadata: ``door`` and ``window`` dicts with ``p0, p1`` (ends of the
    bottom edge on the wall's inner face, m), ``heading`` (outward),
    ``width`` and heights (``height``; ``sill_height``, ``top``).

    Args:
        width: the floor's extent along X, metres.
        depth: the floor's extent along Z, metres.
        door_width: the doorway's width, metres.
        door_height: height of the lintel's underside above the floor, metres.
        window_width: the window's width, metres.
        sill_height: height of the window's bottom above the floor, metres.
        window_top: height of the window's top above the floor, metres.
    """
    if door_width >= depth or window_width >= width:
        raise ValueError("door_width must be < depth and window_width < width")
    if not sill_height < window_top <= WALL_HEIGHT:
        raise ValueError(f"need sill_height < window_top <= {WALL_HEIGHT}")
    hw, hd = width / 2, depth / 2
    b = _LevelBuilder()
    b.floors(-hw, hw, -hd, hd, 0.0)
    apertures = _no_apertures(1)
    apertures[0, PX] = (-door_width / 2, door_width / 2, 0.0, door_height)
    apertures[0, PZ] = (-window_width / 2, window_width / 2, sill_height, window_top)
    b.room_walls([[-hw, hw, -hd, hd]], 0.0, apertures)
    door = _opening((hw, 0.0, 0.0), (1.0, 0.0, 0.0), door_width)
    window = _opening((0.0, sill_height, hd), (0.0, 0.0, 1.0), window_width)
    meta = {
        "params": {
            "width": width,
            "depth": depth,
            "door_width": door_width,
            "door_height": door_height,
            "window_width": window_width,
            "sill_height": sill_height,
            "window_top": window_top,
        },
        "floor_heights": (0.0,),
        "room": _rect(-hw, hw, -hd, hd),
        "door": {
            "p0": door.p0,
            "p1": door.p1,
            "heading": door.heading,
            "width": float(door_width),
            "height": float(door_height),
        },
        "window": {
            "p0": window.p0,
            "p1": window.p1,
            "heading": window.heading,
            "width": float(window_width),
            "sill_height": float(sill_height),
            "top": float(window_top),
            "centre": vec3((0.0, (sill_height + window_top) / 2, hd)),
        },
        "components": 1,
        "cycles": 0,
    }
    return b.build("room_with_window", [door], meta)


@validate_call
def two_floors(
    ramp: bool = True,
    size: PositiveFloat = 16.0,
    block: PositiveFloat = 6.0,
    upper_height: PositiveFloat = 4.0,
    upper_size: PositiveFloat = 10.0,
    ramp_width: PositiveFloat = 3.0,
    slope_deg: RampSlope = 20.0,
) -> SampleLevel:
    """A ground floor that loops around a central block, and an upper floor beside it.

    Ground floor (y = 0): the square [0, size]² minus the central block
    [b0, b1]² (b0 = (size - block) / 2), so the walkable area is a ring and
    paths around it form a cycle. The block is four walls around a void with
    no floor and no roof, so no walkable surface exists on or in it.
    Upper floor (y = ``upper_height``): a square room beside the ground floor
    on +X (it covers nothing below it), centred on z = size / 2, starting at
    x = size + run where run = upper_height / tan(slope_deg). The ramp climbs
    from the ground floor's +X wall (centred on z = size / 2) to the upper
    floor's -X wall; without it both walls are solid and the two floors are
    not connected. Everything else is walled: 0 openings.
    Metadata: ``floor_heights``, ``ground`` / ``upper`` / ``block`` extents
    (``x0, x1, z0, z1``), ``ramp`` (as in :func:`corridor_with_ramp`, or
    ``None``), ``components`` (1 or 2), ``cycles`` (1).

    Args:
        ramp: whether a walled ramp joins the two floors.
        size: side of the square ground floor, metres.
        block: side of the central block, metres.
        upper_height: height of the upper floor above the ground floor, metres.
        upper_size: side of the square upper floor, metres.
        ramp_width: the ramp's width, metres.
        slope_deg: the ramp's slope, degrees (the design agent walks up to 45).
    """
    if block >= size:
        raise ValueError(f"block ({block}) must be < size ({size})")
    if ramp_width >= min(size, upper_size):
        raise ValueError("ramp_width must be < size and < upper_size")
    run = _ramp_run(upper_height, slope_deg)
    b0, b1 = (size - block) / 2, (size + block) / 2
    zc, t = size / 2, WALL_THICKNESS
    ground = np.array([0.0, size, 0.0, size])
    upper = np.array([size + run, size + run + upper_size, zc - upper_size / 2, zc + upper_size / 2])
    b = _LevelBuilder()
    # The ring: two full-width strips and two strips between them beside the block.
    b.floors([0.0, 0.0, 0.0, b1], [size, size, b0, size], [0.0, b1, b0, b0], [b0, size, b1, b1], 0.0)
    # The block: walls inside the hole, against the ring's inner edges.
    x0, x1, z0, z1 = [b0, b1 - t, b0, b0], [b0 + t, b1, b1, b1], [b0, b0, b0, b1 - t], [b1, b1, b0 + t, b1]
    b.boxes(*_axis_boxes(True, x0, x1, z0, z1, -SLAB_THICKNESS, WALL_HEIGHT))
    b.floors(*upper, upper_height)
    apertures = _no_apertures(2)
    ramp_meta = None
    if ramp:
        apertures[0, PX] = (zc - ramp_width / 2, zc + ramp_width / 2, 0.0, WALL_HEIGHT)
        apertures[1, NX] = apertures[0, PX]
        b.ramp(size, size + run, zc, ramp_width, 0.0, upper_height)
        ramp_meta = _ramp_meta(size, size + run, zc, ramp_width, 0.0, upper_height, slope_deg)
    b.room_walls(np.stack([ground, upper]), [0.0, upper_height], apertures)
    meta = {
        "params": {
            "ramp": ramp,
            "size": size,
            "block": block,
            "upper_height": upper_height,
            "upper_size": upper_size,
            "ramp_width": ramp_width,
            "slope_deg": slope_deg,
        },
        "floor_heights": (0.0, float(upper_height)),
        "ground": _rect(*ground),
        "upper": _rect(*upper),
        "block": _rect(b0, b1, b0, b1),
        "ramp": ramp_meta,
        "components": 1 if ramp else 2,
        "cycles": 1,
    }
    return b.build("two_floors", [], meta)


# --------------------------------------------------------------------------
# Dungeon
# --------------------------------------------------------------------------

_STEP = 0.25  # metres; room sizes and offsets are multiples of it
_MOUTH_MARGIN = 0.5  # metres of wall kept between a corridor mouth and a room corner


def _grow_slots(rng: np.random.Generator, n: int) -> np.ndarray:
    """``n`` 4-connected grid slots grown at random from (0, 0): (n, 2) int, shifted to >= 0."""
    draws = rng.random(n)
    slots = [(0, 0)]
    seen = {(0, 0)}
    frontier: list[tuple[int, int]] = []

    def push(cell: tuple[int, int]) -> None:
        i, j = cell
        for nb in ((i + 1, j), (i - 1, j), (i, j + 1), (i, j - 1)):
            if nb not in seen:
                seen.add(nb)
                frontier.append(nb)

    push(slots[0])
    for k in range(1, n):
        idx = int(draws[k] * len(frontier))
        cell = frontier[idx]
        frontier[idx] = frontier[-1]
        frontier.pop()
        slots.append(cell)
        push(cell)
    out = np.array(slots, dtype=np.int64).reshape(-1, 2)
    return out - out.min(axis=0)


def _steps(rng: np.random.Generator, low: Any, high: Any) -> np.ndarray:
    """Random multiples of ``_STEP`` in [low, high] (scalars or arrays of one shape), metres."""
    lo = np.ceil(np.asarray(low) / _STEP - 1e-9).astype(np.int64)
    hi = np.floor(np.asarray(high) / _STEP + 1e-9).astype(np.int64)
    return rng.integers(lo, hi + 1) * _STEP


def _slot_neighbours(slots: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Neighbouring slot pairs: ((m, 2) room indices (a, b) with b the +X or +Z neighbour of a,
    (m,) bool, True when b is the +X neighbour). +X pairs come first."""
    stride = int(slots[:, 1].max()) + 2  # j + 1 never wraps into the next i
    keys = slots[:, 0] * stride + slots[:, 1]
    order = np.argsort(keys)
    sorted_keys = keys[order]
    pairs, along_x = [], []
    for step, is_x in ((stride, True), (1, False)):
        pos = np.minimum(np.searchsorted(sorted_keys, keys + step), len(keys) - 1)
        hit = sorted_keys[pos] == keys + step
        pairs.append(np.column_stack([np.nonzero(hit)[0], order[pos[hit]]]))
        along_x.append(np.full(int(hit.sum()), is_x))
    return np.concatenate(pairs).astype(np.int64).reshape(-1, 2), np.concatenate(along_x)


def _spanning_tree_plus_loops(
    rng: np.random.Generator, n: int, pairs: np.ndarray, loops: float
) -> tuple[np.ndarray, int]:
    """Indices of the chosen ``pairs``: a random spanning tree of the n rooms, then
    ``round(loops * n)`` (at least 1 when ``loops > 0``, as far as there are spare pairs)
    other pairs. Returns (indices, number of extra pairs)."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import minimum_spanning_tree

    weights = 1.0 + rng.random(len(pairs))
    in_tree = np.zeros(len(pairs), dtype=bool)
    if n > 1:
        a, b = pairs.min(axis=1), pairs.max(axis=1)
        tree = minimum_spanning_tree(coo_matrix((weights, (a, b)), shape=(n, n))).tocoo()
        tree_keys = np.minimum(tree.row, tree.col) * n + np.maximum(tree.row, tree.col)
        in_tree = np.isin(a * n + b, tree_keys)
    spare = np.nonzero(~in_tree)[0]
    wanted = max(1, round(loops * n)) if loops > 0 else 0
    n_extra = min(len(spare), wanted)
    extra = np.sort(rng.choice(spare, size=n_extra, replace=False)) if n_extra else spare[:0]
    return np.concatenate([np.nonzero(in_tree)[0], extra]), n_extra


def _outer_sides(slots: np.ndarray) -> list[tuple[int, int]]:
    """(room, side) pairs, sorted, whose side faces no room further along its row or column."""
    found = set()
    for axis, side_lo, side_hi in ((0, NX, PX), (1, NZ, PZ)):
        line = slots[:, 1 - axis]
        for value in np.unique(line):
            members = np.nonzero(line == value)[0]
            coords = slots[members, axis]
            found.add((int(members[np.argmin(coords)]), side_lo))
            found.add((int(members[np.argmax(coords)]), side_hi))
    return sorted(found)


def _pillar_lattice(
    rng: np.random.Generator, centres: np.ndarray, half: np.ndarray, size: float, gap: float, density: float
) -> np.ndarray:
    """Pillar centres (k, 2) in x, z: a lattice of pitch ``size + gap`` centred in each room
    (centres, half sizes (n, 2)), ``gap`` clear of the walls; each site taken with
    probability ``density``."""
    pitch = size + gap
    span = 2.0 * (half - gap) - size  # (n, 2) room for the spread of pillar centres, m
    count = np.where(span >= 0, np.floor(span / pitch + 1e-9).astype(np.int64) + 1, 0)
    m = int(count.max()) if len(count) else 0
    if m == 0:
        return np.zeros((0, 2))
    k = np.arange(m)
    site = (k[None, :, None] < count[:, 0, None, None]) & (k[None, None, :] < count[:, 1, None, None])
    room, i, j = np.nonzero(site & (rng.random((len(centres), m, m)) < density))
    x = centres[room, 0] + (i - (count[room, 0] - 1) / 2) * pitch
    z = centres[room, 1] + (j - (count[room, 1] - 1) / 2) * pitch
    return np.column_stack([x, z])


MAX_DUNGEON_ROOMS = 100_000
"""The largest dungeon (eight times the 12,000-room, 100,781-polygon benchmark level): a count from a typo
(``rooms=100000000``) generated for minutes before anything said why; larger levels: benchmarks/large_level.py."""


@validate_call
def dungeon(
    seed: NonNegativeInt = 0,
    rooms: Annotated[int, Field(ge=1, le=MAX_DUNGEON_ROOMS)] = 12,
    room_min: PositiveFloat = 5.0,
    room_max: float = 10.0,
    spacing: PositiveFloat = 14.0,
    corridor_width: PositiveFloat = 3.0,
    loops: NonNegativeFloat = 0.15,
    obstacles: Probability = 0.3,
    pillar_size: PositiveFloat = 1.0,
    pillar_gap: PositiveFloat = 1.6,
    exits: NonNegativeInt = 0,
    exit_length: PositiveFloat = 3.0,
) -> SampleLevel:
    """Rooms of random sizes on a grid, joined by corridors, with optional pillars.

    Layout: the rooms' grid slots are grown at random as one 4-connected
    blob; each slot holds a room whose sides are random multiples of 0.5 m in
    [room_min, room_max], shifted at random inside its slot (every room
    covers its slot centre ± room_min / 2). Corridors join neighbouring rooms
    along a random spanning tree of the slot adjacency, plus
    ``round(loops * rooms)`` (at least 1 when ``loops > 0`` and the layout
    allows) extra neighbour pairs, which make loops. Obstacles: square
    pillars a wall high on a lattice centred in each room, with gaps wider
    than the design agent by default. The navmesh size grows with ``rooms`` and ``obstacles`` (see docs/samples.md).
    Exits: corridor stubs leave rooms on the outside of the layout (sides
    with no room further along their row or column) and end open;
    ``exits=0`` (default) gives a closed dungeon.

    All floors are at y = 0. Geometry is built with numpy: 5000 rooms take
    about a second. Same arguments, same level (``numpy.random.default_rng(seed)``).

    Openings: one per exit, in the order of ``metadata['exit_rooms']``.
    Metadata: ``room_centres`` (tuple of (x, 0, z), room i's floor centre,
    m), ``room_bounds`` (tuple of (x0, x1, z0, z1)), ``slots`` (tuple of grid
    (i, j)), ``corridors`` (tuple of room-index pairs (a, b), a < b, the
    spanning tree's first), ``tree_corridors`` (rooms - 1), ``loops`` (extra
    corridors), ``pillars`` (count), ``pillar_centres`` (tuple of (x, 0, z)),
    ``exit_rooms`` (tuple of (room, side name)), ``cycles`` (loops +
    pillars: each pillar is a hole in the walkable area), ``components`` (1).

    Args:
        seed: seed of the random layout.
        rooms: number of rooms, at most :data:`MAX_DUNGEON_ROOMS`.
        room_min: smallest side of a room, metres.
        room_max: largest side of a room, metres.
        spacing: pitch of the rooms' grid, metres.
        corridor_width: width of the corridors and exits, metres.
        loops: extra corridors beyond the spanning tree, per room.
        obstacles: probability that a lattice site in a room holds a pillar.
        pillar_size: side of a square pillar, metres.
        pillar_gap: clear gap between pillars, and between a pillar and a wall, metres.
        exits: number of open corridor stubs.
        exit_length: length of each exit corridor, metres.
    """
    params = dict(locals())
    if room_max < room_min:
        raise ValueError(f"room_max ({room_max}) must be >= room_min ({room_min})")
    if room_min < corridor_width + 2 * _MOUTH_MARGIN:
        raise ValueError(f"room_min must be >= corridor_width + {2 * _MOUTH_MARGIN}")
    if spacing < room_max + 2 * WALL_THICKNESS + 1.0:
        raise ValueError(f"spacing must be >= room_max + {2 * WALL_THICKNESS + 1.0}")
    rng = np.random.default_rng(seed)

    # Rooms: random sizes (0.5 m steps), shifted inside their slots.
    slots = _grow_slots(rng, rooms)
    size_steps = int((room_max - room_min) / 0.5 + 1e-9)
    half = 0.5 * (room_min + 0.5 * rng.integers(0, size_steps + 1, size=(rooms, 2)))
    slack = half - 0.5 * room_min
    centres = slots * spacing + _steps(rng, -slack, slack)
    bounds = np.column_stack([centres - half, centres + half])[:, [0, 2, 1, 3]]  # x0, x1, z0, z1

    # Corridors between neighbours, offset at random inside the band both rooms cover.
    pairs, along_x = _slot_neighbours(slots)
    chosen, n_loops = _spanning_tree_plus_loops(rng, rooms, pairs, loops)
    pairs, along_x = pairs[chosen], along_x[chosen]
    a, c = pairs[:, 0], pairs[:, 1]
    band = 0.5 * (room_min - corridor_width) - _MOUTH_MARGIN
    centre = np.where(along_x, slots[a, 1], slots[a, 0]) * spacing
    centre = centre + _steps(rng, -band, np.full(len(pairs), band))
    start = np.where(along_x, bounds[a, PX], bounds[a, PZ])
    end = np.where(along_x, bounds[c, NX], bounds[c, NZ])
    apertures = _no_apertures(rooms)
    mouths = np.column_stack([centre - corridor_width / 2, centre + corridor_width / 2])
    mouths = np.column_stack([mouths, np.zeros(len(pairs)), np.full(len(pairs), WALL_HEIGHT)])
    apertures[a, np.where(along_x, PX, PZ)] = mouths
    apertures[c, np.where(along_x, NX, NZ)] = mouths
    b = _LevelBuilder()
    b.floors(bounds[:, 0], bounds[:, 1], bounds[:, 2], bounds[:, 3], 0.0)
    b.corridors(along_x, start, end, centre, corridor_width, 0.0)

    # Exits: open-ended stubs from sides that face the outside of the layout.
    openings: list[Opening] = []
    exit_rooms: list[tuple[int, str]] = []
    if exits:
        outer = _outer_sides(slots)
        if exits > len(outer):
            raise ValueError(f"exits ({exits}) exceeds the {len(outer)} outer room sides")
        picked = [outer[i] for i in sorted(rng.choice(len(outer), size=exits, replace=False))]
        room, side = (np.array(v) for v in zip(*picked))
        on_x = np.isin(side, (NX, PX))
        mid = np.where(on_x, slots[room, 1], slots[room, 0]) * spacing
        mid = mid + _steps(rng, -band, np.full(exits, band))
        edge = bounds[room, side]
        far = edge + np.where(np.isin(side, (PX, PZ)), exit_length, -exit_length)
        b.corridors(on_x, np.minimum(edge, far), np.maximum(edge, far), mid, corridor_width, 0.0)
        apertures[room, side] = np.column_stack(
            [mid - corridor_width / 2, mid + corridor_width / 2, np.zeros(exits), np.full(exits, WALL_HEIGHT)]
        )
        for r, s, m, f in zip(room.tolist(), side.tolist(), mid.tolist(), far.tolist()):
            position = (f, 0.0, m) if s in (NX, PX) else (m, 0.0, f)
            openings.append(_opening(position, _SIDE_HEADING[s], corridor_width))
            exit_rooms.append((r, _SIDE_NAME[s]))
    b.room_walls(bounds, 0.0, apertures)

    # Pillars, standing in the floor slab like the walls.
    pillars = _pillar_lattice(rng, centres, half, pillar_size, pillar_gap, obstacles)
    hp, k = pillar_size / 2, len(pillars)
    b.boxes(
        np.column_stack([pillars[:, 0] - hp, np.full(k, -SLAB_THICKNESS), pillars[:, 1] - hp]),
        np.column_stack([pillars[:, 0] + hp, np.full(k, WALL_HEIGHT), pillars[:, 1] + hp]),
    )

    def points(xz: np.ndarray) -> tuple[Vec3, ...]:
        return tuple((x, 0.0, z) for x, z in xz.tolist())

    meta = {
        "params": params,
        "floor_heights": (0.0,),
        "room_centres": points(centres),
        "room_bounds": tuple(tuple(row) for row in bounds.tolist()),
        "slots": tuple(tuple(row) for row in slots.tolist()),
        "corridors": tuple((min(p), max(p)) for p in pairs.tolist()),
        "tree_corridors": rooms - 1,
        "loops": int(n_loops),
        "pillars": k,
        "pillar_centres": points(pillars),
        "exit_rooms": tuple(exit_rooms),
        "components": 1,
        "cycles": int(n_loops) + k,
    }
    return b.build("dungeon", openings, meta)


# --------------------------------------------------------------------------
# Registry
# --------------------------------------------------------------------------

SAMPLES: dict[str, Callable[..., SampleLevel]] = {
    "straight_corridor": straight_corridor,
    "corridor_with_ramp": corridor_with_ramp,
    "cross_hub": cross_hub,
    "t_hub": t_hub,
    "two_floors": two_floors,
    "closed_room": closed_room,
    "room_with_window": room_with_window,
    "dungeon": dungeon,
}
"""Sample name -> factory. Every factory takes keyword arguments only."""

# Rooms joined by doors (chokepoint and region ground truth), map pieces with
# known openings, outdoor terrain, multi-storey buildings, castles and mazes build on the helpers above.
from g2s_plugins.samples.buildings import SAMPLES as _BUILDING_SAMPLES  # noqa: E402
from g2s_plugins.samples.castle import SAMPLES as _CASTLE_SAMPLES  # noqa: E402
from g2s_plugins.samples.maze import SAMPLES as _MAZE_SAMPLES  # noqa: E402
from g2s_plugins.samples.outdoor import SAMPLES as _OUTDOOR_SAMPLES  # noqa: E402
from g2s_plugins.samples.pieces import PIECES as _PIECE_SAMPLES  # noqa: E402
from g2s_plugins.samples.rooms import SAMPLES as _ROOM_SAMPLES  # noqa: E402

SAMPLES.update(_ROOM_SAMPLES)
SAMPLES.update(_PIECE_SAMPLES)
SAMPLES.update(_OUTDOOR_SAMPLES)
SAMPLES.update(_BUILDING_SAMPLES)
SAMPLES.update(_CASTLE_SAMPLES)
SAMPLES.update(_MAZE_SAMPLES)


def load_sample(name: str, **kwargs: Any) -> SampleLevel:
    """Build the sample ``name`` with ``kwargs``; ``KeyError`` lists the names when unknown."""
    try:
        factory = SAMPLES[name]
    except KeyError:
        raise KeyError(f"unknown sample {name!r}; known samples: {', '.join(SAMPLES)}") from None
    return factory(**kwargs)


__all__ = [
    "DESIGN_AGENT",
    "SAMPLES",
    "SLAB_THICKNESS",
    "WALL_HEIGHT",
    "WALL_THICKNESS",
    "SampleLevel",
    "closed_room",
    "corridor_with_ramp",
    "cross_hub",
    "dungeon",
    "load_sample",
    "room_with_window",
    "straight_corridor",
    "t_hub",
    "two_floors",
]
