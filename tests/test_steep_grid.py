"""The steep faces' grids, built once per mesh and max slope (:meth:`RayCaster.steep_faces`), answer
:func:`bands_meet_walls` and the body slab's test (:attr:`SteepFaces.slab_grid`) as a test of every band or slab
against every steep face does."""

from __future__ import annotations

import math

import numpy as np
import trimesh

from g2s_plugins._raycasting import RayCaster, _slices_meet_bands, bands_meet_walls


def two_slopes() -> trimesh.Trimesh:
    """A 10 x 10 m floor at y = 0; a 60 degree slope facing -x from x = 4 (2 m high, up to x = 4 + 2 / tan 60),
    z 0..5; an upright wall along x at z = 8, 3 m high."""
    run = 2.0 / math.tan(math.radians(60.0))
    vertices = np.array([
        [0, 0, 0], [10, 0, 0], [10, 0, 10], [0, 0, 10],                    # floor
        [4, 0, 0], [4, 0, 5], [4 + run, 2, 5], [4 + run, 2, 0],            # slope
        [0, 0, 8], [10, 0, 8], [10, 3, 8], [0, 3, 8],                      # wall
    ], dtype=np.float64)
    faces = np.array([[0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], [8, 9, 10], [8, 10, 11]])
    return trimesh.Trimesh(vertices, faces, process=False)


def slabs_meet(triangle: np.ndarray, low: np.ndarray, along: np.ndarray, side: np.ndarray, heights,
               inset: float = 1e-4) -> np.ndarray:
    """(n,) bool: the one upright ``triangle`` ((3, 3) corners, m) passes through the body slabs ``low`` + s ``along``
    + t ``side`` + h UP (h in ``heights``, (n, 2) or (2,) m), as the slab grid of a mesh of that triangle alone says."""
    caster = RayCaster(trimesh.Trimesh(np.asarray(triangle, dtype=np.float64).reshape(3, 3), [[0, 1, 2]], process=False))
    heights = np.ascontiguousarray(np.broadcast_to(np.asarray(heights, dtype=np.float64), (len(low), 2)))
    return caster.steep_faces(45.0).slab_grid.meets(low, along, side, heights, inset)


def every_pair(caster: RayCaster, low: np.ndarray, along: np.ndarray, side: np.ndarray, max_slope_deg: float,
               heights: np.ndarray | None) -> np.ndarray:
    """(n,) bool: :func:`bands_meet_walls` (or with ``heights`` the slab grid) without a broad phase, each band against
    each steep triangle (a slab against a grid of that triangle alone, whose cells hold nothing else)."""
    steep = caster.triangles[~caster.walkable_faces(np.arange(len(caster.triangles)), max_slope_deg)]
    if heights is not None:
        return np.logical_or.reduce([slabs_meet(triangle, low, along, side, heights) for triangle in steep])
    band, wall = (index.reshape(-1) for index in np.meshgrid(np.arange(len(low)), np.arange(len(steep)), indexing="ij"))
    hit = _slices_meet_bands(steep[wall], low[band], along[band], side[band], 1e-4)
    return np.logical_or.reduceat(hit, np.arange(0, len(hit), len(steep)))


def test_the_cached_grid_answers_as_every_pair_for_two_slopes() -> None:
    mesh = two_slopes()
    caster = RayCaster(mesh)
    # the slope: 60 degrees from horizontal (its normal 0.5 up); the wall upright
    assert np.allclose(caster.face_normals[2:4, 1], 0.5) and np.allclose(caster.face_normals[4:6, 1], 0.0)
    # hand-checked: at 0.5 m the slope stands at x = 4 + 0.5 / tan 60 = 4.29; a band along x from x = 3 crosses it,
    # one along z from z = 6 crosses the wall, one from (1, 1) along x meets neither
    low = np.array([[3.0, 0.5, 2.0], [1.0, 0.5, 6.0], [1.0, 0.5, 1.0]])
    along = np.array([[3.0, 0.0, 0.0], [0.0, 0.0, 3.0], [2.0, 0.0, 0.0]])
    side = np.array([[0.0, 0.0, 0.4], [-0.4, 0.0, 0.0], [0.0, 0.0, 0.4]])
    assert bands_meet_walls(caster, low, along, side, 45.0, inset=1e-4).tolist() == [True, True, False]
    assert bands_meet_walls(caster, low, along, side, 70.0, inset=1e-4).tolist() == [False, True, False]
    # the same as body slabs 0.5 m either side of the lines (y 0 to 1): the slope and the wall; lifted 2.6-3.0 m
    # over them (y 3.1 to 3.5) the slabs pass over the slope's 2 m top and the wall's 3 m one
    for heights, meets in [((-0.5, 0.5), [True, True, False]), ((2.6, 3.0), [False, False, False])]:
        slabs = np.tile(heights, (3, 1))
        assert caster.steep_faces(45.0).slab_grid.meets(low, along, side, slabs, 1e-4).tolist() == meets
    # one grid per max slope, shared by every caster of the mesh
    assert RayCaster(mesh).steep_faces(45.0) is caster.steep_faces(45.0)
    assert len(caster.steep_faces(45.0).triangles) == 4 and len(caster.steep_faces(70.0).triangles) == 2
    # random bands and slabs, some reaching out of the grid: the same answers as every pair, for both slopes
    rng = np.random.default_rng(7)
    n = 300
    low = rng.uniform([-2, 0, -2], [12, 2.5, 12], size=(n, 3))
    along = rng.uniform(-4, 4, size=(n, 3)) * [1, 0.2, 1]
    side = np.stack([-along[:, 2], np.zeros(n), along[:, 0]], axis=1)
    side *= (rng.uniform(0.05, 0.6, n) / np.hypot(along[:, 0], along[:, 2]))[:, None]
    heights = np.sort(rng.uniform(-1, 1, size=(n, 2)), axis=1)
    for max_slope in (45.0, 70.0, 45.0):
        steep = caster.steep_faces(max_slope)
        for slab in (None, heights):
            cached = bands_meet_walls(caster, low, along, side, max_slope, inset=1e-4) if slab is None else \
                steep.slab_grid.meets(low, along, side, slab, 1e-4)
            assert cached.tolist() == every_pair(caster, low, along, side, max_slope, slab).tolist()
            assert 0 < cached.sum() < n
