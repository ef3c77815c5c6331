"""Building a navmesh: input checks, the grid and tiling guards, and the extension call.

Tiling rule (``tile_size``): ``None`` (automatic) builds solo when both sides
of the xz grid are at most 512 cells and the solo mesh fits one Detour tile
(65535 poly-mesh vertices, 16-bit regions); otherwise, or when the solo build
fails for size, tiles of 256 cells (also when the solo grid
exceeds ``max_cells``). ``0`` forces solo, ``n >= 16`` forces
tiles of ``n`` cells. A tile is rasterised with a border of ``walkableRadius +
3`` cells. Polygons are numbered tile by tile (tiles in row-major order, x
fastest), in each tile in Recast's order; a solo build is one tile. A tiled
build drops the connected parts at tile borders smaller than
``region_min_size``² cells in all, which Recast keeps in a tile (it cannot
weigh a part a border cuts) and drops from a solo build (docs/navmesh.md,
"Islands at tile borders").

Memory guard: ``max_cells`` bounds the xz cells rasterised at once, that is
the solo grid, or one tile with its border (tiles are built one per worker
thread); a tiled grid has at most :data:`~.settings.MAX_TILES` tiles.
Time guard: ``max_level_cells`` bounds the cells of the whole xz grid, so that a
flat level read in the wrong units (100 times too large: no height to betray
it) stops at once instead of building for an hour.

Frame: Recast builds in the level's local frame (:mod:`g2s_plugins.local_frame`), the vertices
translated in double precision; a level is refused only where double
precision itself keeps less than half a cell between coordinates.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from ..local_frame import LocalFrame
from . import _recast
from .navmesh import NavMesh
from .settings import (
    MAX_GRID_SIDE,
    MAX_LEVEL_CELLS,
    MAX_SPAN_HEIGHT,
    MAX_TILES,
    RecastParams,
    SettingsError,
    resolve_settings,
    voxel_config,
)

__all__ = ["build_navmesh", "AUTO_SOLO_MAX_CELLS", "AUTO_TILE_SIZE"]

AUTO_SOLO_MAX_CELLS = 512
"""Automatic tiling: solo when both grid sides are at most this many cells."""

AUTO_TILE_SIZE = 256
"""Automatic tiling: the tile side (cells) of levels larger than that."""

_SCALE_HINT = "check mesh.scale (the file's units to metres) and mesh.up_axis"


def build_navmesh(vertices: ArrayLike, faces: ArrayLike, agent: Any, params: RecastParams | None = None) -> NavMesh:
    """Build a navmesh, solo or tiled (see the tiling rule in the module docs).

    Args:
        vertices: (N,3) float32/float64, metres, Y up, world coordinates (the navmesh returns them too).
        faces: (M,3) integer vertex indices of triangles.
        agent: object with ``radius``, ``height``, ``max_climb`` (m), ``max_slope`` (deg).
        params: :class:`RecastParams`; ``None`` for the defaults.

    Raises:
        SettingsError: a setting, or the level's size with these settings, that
            Recast cannot handle; the message starts with the key at fault.
        ValueError: bad input arrays.
        RuntimeError: a Recast/Detour step failed ("Recast: <step> failed
            [in tile (x, y) of X x Z] (<Recast's log>)"), or nothing is walkable
            ("Recast: no walkable polygons ...").
    """
    params = params or RecastParams()
    v = np.asarray(vertices)
    if v.dtype not in (np.float32, np.float64):
        v = v.astype(np.float64)
    v = np.ascontiguousarray(v)
    f = np.asarray(faces)
    if f.dtype not in (np.int32, np.int64):
        if not np.issubdtype(f.dtype, np.integer):
            raise ValueError("Recast: faces must be integer vertex indices")
        f = f.astype(np.int64)
    f = np.ascontiguousarray(f)
    if v.ndim != 2 or v.shape[1] != 3 or f.ndim != 2 or f.shape[1] != 3:
        raise ValueError(f"Recast: expected (N,3) vertices and (M,3) faces, got {v.shape} and {f.shape}")
    if not np.isfinite(v).all():
        raise ValueError("Recast: vertices must be finite")
    level_height = float(v[:, 1].max() - v[:, 1].min()) if len(v) else None
    settings = resolve_settings(agent, params, level_height)
    if len(v):
        check_precision(v, float(voxel_config(settings)["cs"]))
    frame = LocalFrame(np.stack(bounds(v)) if len(v) else v)  # the frame reads only the points' bounds
    v = frame.to_local(v)  # float64 when shifted, whatever v was
    if len(v):
        check_grid(v, settings, cell_size_given=params.cell_size is not None,
                   cell_height_given=params.cell_height is not None, max_level_cells=params.max_level_cells)
    core = _recast.build(v, f, **settings)
    return NavMesh(core, settings, frame)


def bounds(points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """((3,), (3,)) the smallest and largest coordinate of the (N,3) ``points`` along each axis (N > 0).

    Column by column: numpy reduces an (N,3) array along its first axis three values at a time, 30 ms each way
    for the 864k vertices of the 100k-polygon level, a column in 0.4 ms (docs/performance.md).
    """
    return (np.array([points[:, k].min() for k in range(3)], dtype=points.dtype),
            np.array([points[:, k].max() for k in range(3)], dtype=points.dtype))


def check_precision(vertices: np.ndarray, cell_size: float) -> None:
    """Refuse a level so far from the origin that double precision keeps less than half a cell between values.

    Raises:
        SettingsError: naming ``mesh``, with the distance a level can lie at with this cell size.
    """
    far = float(np.abs(vertices).max())
    if np.spacing(far) > cell_size / 2:
        reach = 2.0 ** (math.floor(math.log2(cell_size / 2)) + 53)
        raise SettingsError(
            f"mesh: vertices lie up to {far:.4g} m from the origin, where double precision keeps only "
            f"{np.spacing(far):g} m between values, more than half the cell of {cell_size:g} m; move the level "
            f"within {reach:.4g} m of the origin"
        )


def check_grid(vertices: np.ndarray, settings: dict[str, Any], cell_size_given: bool = False,
               cell_height_given: bool = False, max_level_cells: int = MAX_LEVEL_CELLS) -> None:
    """Refuse a level whose voxel grid Recast cannot hold, before anything is allocated.

    Computes the grid as Recast does (float32 bounds, ``(int)(extent / cs + 0.5)``
    cells a side) in Python integers, so no size can overflow, and checks it
    against the memory guard and Recast's and Detour's limits. ``vertices`` are
    those Recast gets: in the local frame.

    Raises:
        SettingsError: naming ``graph.params.<key>`` when that setting was
            given, else ``mesh``, with the level's size.
    """
    with np.errstate(over="ignore", invalid="ignore"):
        lo, hi = (side.astype(np.float32) for side in bounds(vertices))
        extent = (hi - lo).astype(np.float64)
    if not (np.isfinite(lo).all() and np.isfinite(hi).all() and np.isfinite(extent).all()):
        raise SettingsError(
            "mesh: vertex coordinates beyond Recast's single-precision range (|x| < 3.4e38 m); " + _SCALE_HINT
        )
    voxels = voxel_config(settings)
    cs, ch = float(voxels["cs"]), float(voxels["ch"])
    size = f"{extent[0]:.4g} x {extent[2]:.4g} m (x, z), {extent[1]:.4g} m tall"
    cs_key = "graph.params.cell_size" if cell_size_given else "mesh"
    far = float(np.abs(np.concatenate([lo, hi])).max())
    if np.spacing(np.float32(far)) > cs / 2:  # Recast's rasteriser overruns its stack from about 2^22 m out
        raise SettingsError(
            f"{cs_key}: the level ({size}) reaches {far:.4g} m from its local origin (docs/navmesh.md), where "
            f"Recast's single precision keeps only {np.spacing(np.float32(far)):g} m between values, more than "
            f"half the cell of {cs:g} m; {_SCALE_HINT}, or use a larger graph.params.cell_size"
        )
    width, depth = (int(np.floor(e / cs + 0.5)) for e in (extent[0], extent[2]))
    if width < 1 or depth < 1:
        if cell_size_given and extent[0] > 0 and extent[2] > 0:
            raise SettingsError(f"{cs_key}: {cs:g} m cells are larger than the level ({size})")
        if (extent[0] < cs / 2) != (extent[2] < cs / 2) and extent[1] >= cs:
            flat = "x" if extent[0] < cs / 2 else "z"
            raise SettingsError(
                f"mesh: the level has no floor area ({size}: flat along {flat}, standing up along y); if the "
                "file is Z-up, set `mesh: {up_axis: z}` (or `y` if it is already z)"
            )
        raise SettingsError(f"mesh: the level is less than one {cs:g} m cell across ({size}); {_SCALE_HINT}")
    if max(width, depth) > MAX_GRID_SIDE:
        raise SettingsError(
            f"{cs_key}: the level ({size}) is {width} x {depth} cells of {cs:g} m, more than "
            f"{MAX_GRID_SIDE} a side; {_SCALE_HINT}, or use a larger graph.params.cell_size"
        )
    if width * depth > max_level_cells:
        raise SettingsError(
            f"{cs_key}: the level ({size}) is {width} x {depth} cells of {cs:g} m ({width * depth:.3g}), more than "
            f"graph.params.max_level_cells={max_level_cells:.3g} (about a minute of Recast per 1e8 cells); {_SCALE_HINT}, "
            "or use a larger graph.params.cell_size or max_level_cells"
        )
    layers = extent[1] / ch
    if layers > MAX_SPAN_HEIGHT:
        key = "graph.params.cell_height" if cell_height_given else "mesh"
        raise SettingsError(
            f"{key}: the level ({size}) is {layers:.4g} cells of {ch:g} m tall, more than Recast's "
            f"{MAX_SPAN_HEIGHT}; {_SCALE_HINT}, or use a larger graph.params.cell_height"
        )
    tile_size, max_cells = settings["tile_size"], settings["max_cells"]
    auto_solo = max(width, depth) <= AUTO_SOLO_MAX_CELLS and width * depth <= max_cells
    if tile_size == 0 or (tile_size is None and auto_solo):
        if width * depth > max_cells:
            raise SettingsError(
                f"graph.params.tile_size: a solo grid of {width} x {depth} cells ({size}) exceeds "
                f"graph.params.max_cells={max_cells}; build in tiles or use a larger cell_size"
            )
        return
    side = tile_size or AUTO_TILE_SIZE
    border = int(voxels["walkableRadius"]) + 3
    if (side + 2 * border) ** 2 > max_cells:
        key = "graph.params.tile_size" if tile_size else "graph.params.max_cells"
        raise SettingsError(
            f"{key}: a tile of {side} cells plus its {border}-cell border has {(side + 2 * border) ** 2} cells, "
            f"more than graph.params.max_cells={max_cells}"
        )
    tiles = -(-width // side) * -(-depth // side)
    if tiles > MAX_TILES:
        raise SettingsError(
            f"{cs_key}: the level ({size}) needs {tiles} tiles of {side} x {side} cells of {cs:g} m, more than "
            f"Detour's {MAX_TILES}; {_SCALE_HINT}, or use a larger graph.params.cell_size or tile_size"
        )
