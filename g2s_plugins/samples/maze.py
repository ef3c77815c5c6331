"""A maze sample level: a square grid of corridor cells, many dead ends, a few loops.

Dungeons, buildings and castles are rooms joined by corridors; a maze is
corridors only, turning at nearly every cell, so a structure drawn along
lines of sight needs a node at almost every corner, and Recast's watershed
partition makes long winding regions of it (docs/analysis_quality.md,
"Level kinds the presets were not made on"). Built like the other samples
(:mod:`g2s_plugins.samples.levels`): one floor slab, walls as boxes from the
slab's bottom to ``WALL_HEIGHT``. Metres, Y up.
"""

from __future__ import annotations

from typing import Annotated, Any

import numpy as np
from pydantic import Field, NonNegativeInt, PositiveFloat, validate_call

from g2s_plugins.samples.levels import SLAB_THICKNESS, WALL_HEIGHT, WALL_THICKNESS, Probability, SampleLevel, _LevelBuilder


@validate_call
def maze(
    seed: NonNegativeInt = 0,
    cells: Annotated[int, Field(ge=2)] = 8,
    width: PositiveFloat = 2.5,
    loops: Probability = 0.06,
) -> SampleLevel:
    """A square maze: a perfect maze (one path between any two cells) with a few walls taken out.

    Deterministic for ``numpy.random.default_rng(seed)``: a depth-first
    backtracker carves the maze from the corner cell (0, 0), then ``loops``
    of the inner walls still standing are removed at random, each making a
    loop. Every wall, the outer ones included, is ``WALL_THICKNESS`` thick
    and centred on a cell boundary, so every corridor is ``width`` wide
    between its walls. ``cells=32`` gives about 1,000 navmesh polygons for
    the design agent.

    Args:
        seed: random seed.
        cells: cells along each side (the maze is cells x cells).
        width: clear width of a corridor between its walls, metres.
        loops: share (0 to 1) of the inner walls left by the perfect maze that are taken out.

    Metadata: ``pitch`` (cell size, m: ``width`` plus the wall), ``east_walls``
    ((cells - 1, cells) bool: a wall between cells (i, j) and (i + 1, j)),
    ``south_walls`` ((cells, cells - 1) bool: between (i, j) and (i, j + 1)),
    ``dead_ends`` (cells with one way out), ``loops`` (walls taken out),
    ``cycles`` (holes of the walkable area: groups of inner walls joined to
    neither the outer wall nor any other group; fewer than ``loops`` when
    four cells around a wall corner all open into each other).
    """
    rng = np.random.default_rng(seed)
    east, south = _carve(rng, cells)
    standing = np.concatenate([np.argwhere(east), np.argwhere(south)])
    kinds = np.r_[np.zeros(int(east.sum()), int), np.ones(int(south.sum()), int)]
    removed = rng.choice(len(standing), int(loops * len(standing)), replace=False)
    for k in removed:
        (east if kinds[k] == 0 else south)[tuple(standing[k])] = False
    pitch = width + WALL_THICKNESS
    side = cells * pitch
    b = _LevelBuilder()
    b.floors(0.0, side, 0.0, side, 0.0)
    half, bottom = WALL_THICKNESS / 2, -SLAB_THICKNESS
    # every wall as a box along its cell boundary, widened by half a wall at both ends to close the corners
    ei, ej = np.nonzero(east)
    si, sj = np.nonzero(south)
    outer = np.arange(cells)
    x0 = np.r_[(ei + 1) * pitch - half, si * pitch - half, np.full(cells, -half), np.full(cells, side - half),
               outer * pitch - half, outer * pitch - half]
    x1 = np.r_[(ei + 1) * pitch + half, (si + 1) * pitch + half, np.full(cells, half), np.full(cells, side + half),
               (outer + 1) * pitch + half, (outer + 1) * pitch + half]
    z0 = np.r_[ej * pitch - half, (sj + 1) * pitch - half, outer * pitch - half, outer * pitch - half,
               np.full(cells, -half), np.full(cells, side - half)]
    z1 = np.r_[(ej + 1) * pitch + half, (sj + 1) * pitch + half, (outer + 1) * pitch + half, (outer + 1) * pitch + half,
               np.full(cells, half), np.full(cells, side + half)]
    n = len(x0)
    b.boxes(np.column_stack([x0, np.full(n, bottom), z0]), np.column_stack([x1, np.full(n, WALL_HEIGHT), z1]))
    ways = np.zeros((cells, cells), int)  # open sides per cell
    ways[:-1] += ~east
    ways[1:] += ~east
    ways[:, :-1] += ~south
    ways[:, 1:] += ~south
    metadata: dict[str, Any] = {
        "params": {"seed": seed, "cells": cells, "width": width, "loops": loops},
        "floor_heights": (0.0,),
        "components": 1,
        "pitch": pitch,
        "east_walls": east,
        "south_walls": south,
        "dead_ends": int(np.sum(ways == 1)),
        "loops": len(removed),
        "cycles": _wall_islands(east, south),
    }
    return b.build("maze", [], metadata)


def _carve(rng: np.random.Generator, cells: int) -> tuple[np.ndarray, np.ndarray]:
    """The walls of a perfect maze by depth-first backtracking from cell (0, 0): (east, south) bool arrays."""
    east = np.ones((cells - 1, cells), bool)
    south = np.ones((cells, cells - 1), bool)
    seen = np.zeros((cells, cells), bool)
    seen[0, 0] = True
    stack = [(0, 0)]
    steps = ((1, 0), (-1, 0), (0, 1), (0, -1))
    while stack:
        i, j = stack[-1]
        fresh = [(i + di, j + dj) for di, dj in steps
                 if 0 <= i + di < cells and 0 <= j + dj < cells and not seen[i + di, j + dj]]
        if not fresh:
            stack.pop()
            continue
        a, c = fresh[rng.integers(len(fresh))]
        if a != i:
            east[min(a, i), j] = False
        else:
            south[i, min(c, j)] = False
        seen[a, c] = True
        stack.append((a, c))
    return east, south


def _wall_islands(east: np.ndarray, south: np.ndarray) -> int:
    """Groups of inner walls joined neither to the outer wall nor to another group: the holes of the floor.

    Walls join at the cells' corners, lattice points (x, z) in 0..cells; an
    east wall of cell (i, j) runs from corner (i + 1, j) to (i + 1, j + 1), a
    south wall from (i, j + 1) to (i + 1, j + 1). The outer wall joins every
    boundary corner, so those count as one group, which is no hole.
    """
    from scipy import sparse  # imported here, as in levels.py: `g2s plugins` lists the mazes without scipy
    from scipy.sparse import csgraph

    cells = east.shape[1]
    ei, ej = np.nonzero(east)
    si, sj = np.nonzero(south)
    ring = np.arange(cells)  # the outer wall, corner to next corner on all four sides
    x = np.r_[ei + 1, si, ring, ring, np.zeros(cells, int), np.full(cells, cells)]
    z = np.r_[ej, sj + 1, np.zeros(cells, int), np.full(cells, cells), ring, ring]
    x2 = np.r_[ei + 1, si + 1, ring + 1, ring + 1, np.zeros(cells, int), np.full(cells, cells)]
    z2 = np.r_[ej + 1, sj + 1, np.zeros(cells, int), np.full(cells, cells), ring + 1, ring + 1]
    n = (cells + 1) ** 2
    walls = sparse.coo_array((np.ones(len(x)), (x * (cells + 1) + z, x2 * (cells + 1) + z2)), shape=(n, n))
    _, group = csgraph.connected_components(walls, directed=False)
    inner = group[np.r_[(ei + 1) * (cells + 1) + ej, si * (cells + 1) + sj + 1]]
    return len(set(inner.tolist()) - {int(group[0])})


SAMPLES = {"maze": maze}
"""Sample name -> factory."""
