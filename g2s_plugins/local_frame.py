"""The local frame of a level: levels far from the origin keep their single-precision detail.

Recast and Detour (the navmesh) and Embree (the ray caster of the built-in
plugins) compute in single precision, which keeps at most 2^-23 of a
coordinate's size between values: 0.06 mm below 1 km, but 1 mm at 10 km and
6 cm at 1,000 km, enough to move a wall across a cell edge or a ray past a
wall's end. A level exported in world coordinates (a tile of an open world,
GIS terrain) is therefore translated in double precision before it reaches
either, and every coordinate they give back is translated back:
:class:`~g2s_plugins.recast.navmesh.NavMesh` and
:class:`~g2s_plugins._raycasting.RayCaster` take and return world
coordinates only. Both choose the frame by the rule below, written once here.

Rule (per axis, from the bounding box's centre ``c``): the local origin is
the roundest whole number of metres within :data:`NEAR_ORIGIN` of ``c``:
``0`` when ``|c| <= NEAR_ORIGIN`` (every level near the origin is built
and cast against untranslated, exactly as before), else the multiple of the largest power of
ten in that window, the nearest to ``c`` (the lower one on a tie). The window is
2,048 m wide, so the local origin is a whole number of kilometres at least,
and a level moved by a round distance (10 km, 1,000 km) gets that distance
back as its local origin: Recast and Embree then see the very coordinates
of the level at the origin. Otherwise the local coordinates lie within ``NEAR_ORIGIN`` plus
half the level's extent of the local origin, as they would near the origin.

Subtracting a whole number from a coordinate under 2^53 m is exact in double
precision when both lie within a factor two of each other (the level far out)
and otherwise rounds at 2^-52 of the local coordinate, far finer than the
single-precision rounding that follows; adding the local origin back rounds at
double precision's spacing at the world coordinate (2 nm at 10^7 m).
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["NEAR_ORIGIN", "LocalFrame", "local_origin"]

NEAR_ORIGIN = 1024.0
"""Half the width of the window the local origin is chosen in, m (2^10). A level less than 2 km across then lies
within 2^11 m of its local origin, where single precision keeps at most 2^-13 m (0.12 mm) between values: 1/400 of
the finest automatic cell size (0.05 m) and 1/80 of the finest automatic cell height (0.01 m). Measured on nav_test.obj (map_analysis): moved by up to 2,000 m its navmesh
keeps its 173 polygons (centres within 0.16 mm), moved by 3,000 m and more it gains one (docs/navmesh.md,
"Levels far from the origin")."""


def local_origin(lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """The local frame's origin of a level with bounding box ``lo``..``hi`` ((3,) each, m), as in the module docs.

    Returns:
        (3,) float64, whole metres; all zero when the box's centre is within
        :data:`NEAR_ORIGIN` of the origin along every axis.
    """
    centre = (np.asarray(lo, dtype=np.float64) + np.asarray(hi, dtype=np.float64)) / 2.0
    return np.array([_roundest_near(float(c)) for c in centre])


def _roundest_near(centre: float) -> float:
    if abs(centre) <= NEAR_ORIGIN:
        return 0.0
    low, high = centre - NEAR_ORIGIN, centre + NEAR_ORIGIN
    exponent = math.floor(math.log10(max(abs(low), abs(high))))
    while exponent > 3 and not _multiples(low, high, 10.0**exponent):
        exponent -= 1
    power = 10.0**exponent  # 1,000 m at least: the 2,048 m window holds two or three multiples of it
    return float(min(_multiples(low, high, power), key=lambda k: (abs(k * power - centre), k)) * power)


def _multiples(low: float, high: float, power: float) -> range:
    """The k with ``low <= k * power <= high``."""
    return range(math.ceil(low / power), math.floor(high / power) + 1)


class LocalFrame:
    """The local frame of a set of points: translations in and out of it, the identity near the origin.

    Near the origin nothing is added or subtracted (not even zeros: ``-0.0 + 0.0`` is ``0.0``), so such a level's
    arrays are passed on bit for bit and its outputs are those of a build without a frame.

    Args:
        points: (n, 3) world coordinates, m; the frame's origin is :func:`local_origin` of their bounds (none:
            the world's own frame).
    """

    def __init__(self, points: np.ndarray | tuple = ()) -> None:
        points = np.asarray(points, dtype=np.float64).reshape(-1, 3)
        origin = local_origin(points.min(axis=0), points.max(axis=0)) if len(points) else np.zeros(3)
        origin.flags.writeable = False
        self.origin: np.ndarray = origin
        """(3,) float64, whole metres."""
        self.shifted = bool(origin.any())
        """Whether the origin is not the world's."""

    def to_local(self, points: np.ndarray) -> np.ndarray:
        """(..., 3) world coordinates in this frame (float64; ``points`` themselves when not shifted)."""
        return points - self.origin if self.shifted else points

    def to_world(self, points: np.ndarray) -> np.ndarray:
        """(..., 3) coordinates of this frame in the world's (float64; ``points`` themselves when not shifted)."""
        return points + self.origin if self.shifted else points
