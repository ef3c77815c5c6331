"""An outdoor sample level: a hilly heightfield with cliffs, rocks, trees and ruined walls.

Dungeons (:func:`g2s_plugins.samples.levels.dungeon`) are rooms and
corridors on one flat floor; :func:`terrain` is what they lack: big open
areas on uneven ground, whose only boundaries are slopes too steep to walk,
scattered obstacles and the edge of the map.

The ground is one open surface (a triangulated height grid seen from above,
no underside); obstacles are solid hexahedra built like the other samples'
(:mod:`g2s_plugins.samples.levels`) and sunk into the ground. Metres, Y up.
"""

from __future__ import annotations

import dataclasses
import math
from typing import TYPE_CHECKING

import numpy as np
from pydantic import NonNegativeFloat, NonNegativeInt, PositiveFloat, validate_call

from g2s_plugins.samples.levels import DESIGN_AGENT, SampleLevel, _LevelBuilder, _plan_hexahedra, _turned_rectangle

# trimesh and scipy are imported where used, as in levels.py: `g2s plugins` lists these levels without them
if TYPE_CHECKING:
    import trimesh

_HILL_AREA = 400.0  # m² of map per hill or hollow
_HILL_SIGMA = (6.0, 18.0)  # m, range of a hill's Gaussian width
_CLIFF_HEIGHT = (3.0, 6.0)  # m, range of a cliff's height at its middle
_CLIFF_LENGTH = (12.0, 30.0)  # m, range of a cliff's length (4 sigma of its taper)
_CLIFF_SHARPNESS = 0.3  # m, width of the tanh step across a cliff's face (steeper than a grid cell)
_TREE = {"side": (0.5, 0.9), "height": (5.0, 8.0)}  # m; trunks, square
_ROCK = {"half": (0.8, 1.8), "height": (2.2, 3.0), "top": 0.25}  # m; truncated pyramids, top = 0.25 x base
_TREE_SHARE = 0.6  # of obstacles; the rest are rocks
_RUIN = {"segments": (2, 4), "length": (2.0, 5.0), "gap": (1.5, 3.0), "thickness": 0.5, "height": (2.2, 3.0)}
_SINK = 0.3  # m an obstacle reaches below the lowest ground under it


@validate_call
def terrain(
    seed: NonNegativeInt = 0,
    size: PositiveFloat = 100.0,
    relief: PositiveFloat = 8.0,
    obstacles: NonNegativeFloat = 0.5,
    cliffs: NonNegativeFloat = 4.0,
    ruins: NonNegativeFloat = 2.0,
    cell: PositiveFloat = 1.5,
) -> SampleLevel:
    """An open square of hilly ground with cliffs, scattered trees and rocks and a few ruined walls.

    Layout: the ground covers x, z in [0, size] as a grid of ``cell``-metre
    squares, each cut into two triangles along its (x0, z0)-(x1, z1)
    diagonal. Its height is a sum of ``size² / 400`` random Gaussian hills
    and hollows (widths 6-18 m, heights up to ``relief``) and of cliffs:
    each a face 3-6 m high and 12-30 m long, sharper than a grid cell (so
    steeper than 45 degrees: not walkable), with the ground sloping gently
    down behind it and the face tapering off at both ends, so that one can
    walk around it. Hills can also be too steep in places. Obstacles stand
    on the ground at uniformly random places: trees (square trunks 0.5-0.9 m
    wide, 5-8 m tall) and rocks (truncated pyramids 1.6-3.6 m wide at the
    base, 2.2-3 m tall, turned at random, sides steeper than 45 degrees and
    tops too small for the agent). Ruins are broken walls: 2-4 segments 2-5 m
    long and 0.5 m thick in a line, 1.5-3 m gaps between them, 2.2-3 m tall.
    Every obstacle is taller than the design agent and reaches 0.3 m below
    the ground. The map's edge is open (nothing beyond it).

    Numpy-built: ``size=450`` (about 20k navmesh polygons with the default
    agent) takes about a second. Same arguments, same mesh bytes
    (``numpy.random.default_rng(seed)``).

    Args:
        seed: seed of the random generator.
        size: side of the square map, metres.
        relief: largest height of a hill or depth of a hollow, metres.
        obstacles: trees and rocks per 100 m² of map (a density).
        cliffs: cliffs per hectare (10,000 m²) of map (a density).
        ruins: ruined walls per hectare of map (a density).
        cell: side of a ground grid square, metres (1-2 m is realistic).

    Openings: none (the edge of the map is not an entry). Metadata:
    ``floor_heights`` (lowest and highest ground height, m), ``ground``
    (``{"cells": grid squares a side, "cell": m}``), ``hills``, ``cliffs``,
    ``trees``, ``rocks``, ``ruins``, ``ruin_segments`` (counts),
    ``obstacle_centres`` (tuple of (x, y, z): trees, then rocks, then ruin
    segments; y the ground height under the centre), ``walkable_area``
    (m²: the ground triangles no steeper than the design agent's 45 degrees,
    less the footprints of the obstacles standing on them; before the
    agent's radius is taken off), ``boundary_length`` (m: the edge between
    walkable and other ground triangles, the map's edge bordering walkable
    ground, and the obstacles' perimeters), ``erosion_estimate`` (m²:
    ``radius x boundary_length``, roughly what a navmesh loses along those
    boundaries), ``steep_share`` (share of the ground's area steeper than 45
    degrees), ``components`` (connected regions of walkable ground
    triangles, obstacles ignored), ``largest_component_share`` (of the
    walkable ground area), ``cycles`` (None: not counted).
    """
    import trimesh

    params = {"seed": seed, "size": size, "relief": relief, "obstacles": obstacles, "cliffs": cliffs,
              "ruins": ruins, "cell": cell}
    n = max(1, round(size / cell))
    if n > 2000:
        raise ValueError(f"size / cell must be <= 2000 grid squares a side, got {size / cell:g}")
    rng = np.random.default_rng(seed)
    step = size / n
    axis = np.arange(n + 1) * step
    gx, gz = np.meshgrid(axis, axis, indexing="ij")  # (n + 1, n + 1), vertex (i, j) at x = axis[i], z = axis[j]

    height = np.zeros_like(gx)
    hills = max(1, round(size * size / _HILL_AREA))
    centres = rng.uniform(0.0, size, (hills, 2))
    sigma = rng.uniform(*_HILL_SIGMA, hills)
    amplitude = relief * rng.uniform(0.3, 1.0, hills) * rng.choice([-1.0, 1.0], hills)
    for (cx, cz), s, a in zip(centres, sigma, amplitude):  # each hill on the squares within 4 sigma of it
        i0, j0 = (max(int((c - 4 * s) / step), 0) for c in (cx, cz))
        i1, j1 = (min(int((c + 4 * s) / step) + 2, n + 1) for c in (cx, cz))
        window = (slice(i0, i1), slice(j0, j1))
        height[window] += a * np.exp(-((gx[window] - cx) ** 2 + (gz[window] - cz) ** 2) / (2 * s * s))

    n_cliffs = int(rng.poisson(cliffs * size * size / 1e4))
    for cx, cz, angle, length, rise in zip(
        *rng.uniform(0.0, size, (2, n_cliffs)), rng.uniform(0.0, 2 * math.pi, n_cliffs),
        rng.uniform(*_CLIFF_LENGTH, n_cliffs), rng.uniform(*_CLIFF_HEIGHT, n_cliffs),
    ):
        reach = 2 * length  # 4 sigma of the taper behind the face
        i0, j0 = (max(int((c - reach) / step), 0) for c in (cx, cz))
        i1, j1 = (min(int((c + reach) / step) + 2, n + 1) for c in (cx, cz))
        x, z = gx[i0:i1, j0:j1] - cx, gz[i0:i1, j0:j1] - cz
        across = x * math.cos(angle) + z * math.sin(angle)  # > 0 behind the face
        along = -x * math.sin(angle) + z * math.cos(angle)
        taper = np.exp(-(along**2) / (2 * (length / 4) ** 2) - np.maximum(across, 0.0) ** 2 / (2 * (length / 2) ** 2))
        height[i0:i1, j0:j1] += rise * 0.5 * (1.0 + np.tanh(across / _CLIFF_SHARPNESS)) * taper

    ground, walkable, triangle_area = _ground(axis, height, n)
    b = _LevelBuilder()
    footprints, perimeters, centres_xz = [], [], []

    def ground_range(xz: np.ndarray) -> tuple[float, float]:
        """Lowest and highest ground vertex height under the bounding box of points (k, 2) in x, z."""
        lo = np.clip(np.floor(xz.min(axis=0) / step).astype(int), 0, n)
        hi = np.clip(np.ceil(xz.max(axis=0) / step).astype(int), 0, n)
        patch = height[lo[0]:hi[0] + 1, lo[1]:hi[1] + 1]
        return float(patch.min()), float(patch.max())

    def prism(base: np.ndarray, top: np.ndarray, tall: float) -> None:
        """A hexahedron with base and top quads (4, 2) in x, z, counter-clockwise seen from above
        (corner order x0z0, x1z0, x1z1, x0z1 of its local frame), ``tall`` metres above the ground."""
        low, high = ground_range(base)
        b.hexahedra(_plan_hexahedra(base, top, low - _SINK, high + tall))
        footprints.append(_polygon_area(base))
        perimeters.append(float(np.linalg.norm(base - np.roll(base, 1, axis=0), axis=1).sum()))
        centres_xz.append(base.mean(axis=0))

    count = int(rng.poisson(obstacles * size * size / 100.0))
    place = rng.uniform(0.0, size, (count, 2))
    is_tree = rng.random(count) < _TREE_SHARE
    turn = rng.uniform(0.0, math.pi / 2, count)
    tree_side = rng.uniform(*_TREE["side"], count)
    tree_height = rng.uniform(*_TREE["height"], count)
    rock_half = rng.uniform(*_ROCK["half"], count)
    rock_height = rng.uniform(*_ROCK["height"], count)
    for k in np.nonzero(is_tree)[0]:
        trunk = _turned_rectangle(*place[k], tree_side[k] / 2, tree_side[k] / 2, turn[k])
        prism(trunk, trunk, tree_height[k])
    for k in np.nonzero(~is_tree)[0]:
        base = _turned_rectangle(*place[k], rock_half[k], rock_half[k], turn[k])
        top = _turned_rectangle(*place[k], _ROCK["top"] * rock_half[k], _ROCK["top"] * rock_half[k], turn[k])
        prism(base, top, rock_height[k])

    n_ruins = int(rng.poisson(ruins * size * size / 1e4))
    segments = 0
    for start, angle, pieces in zip(rng.uniform(0.0, size, (n_ruins, 2)), rng.uniform(0.0, math.pi, n_ruins),
                                    rng.integers(_RUIN["segments"][0], _RUIN["segments"][1] + 1, n_ruins)):
        direction = np.array([math.cos(angle), math.sin(angle)])
        offset = 0.0
        for length, gap, tall in zip(rng.uniform(*_RUIN["length"], pieces), rng.uniform(*_RUIN["gap"], pieces),
                                     rng.uniform(*_RUIN["height"], pieces)):
            middle = start + (offset + length / 2) * direction
            wall = _turned_rectangle(*middle, length / 2, _RUIN["thickness"] / 2, angle)
            prism(wall, wall, tall)
            offset += length + gap
            segments += 1

    on_walkable = _walkable_at(np.array(centres_xz).reshape(-1, 2), walkable, step, n)
    walkable_area = float(triangle_area[walkable].sum()) - float(np.sum(np.array(footprints)[on_walkable]))
    boundary = _walkable_boundary(walkable, step, n) + float(np.sum(np.array(perimeters)[on_walkable]))
    components, largest = _components(walkable, triangle_area, n)
    y_under = [float(_height_at(height, step, n, x, z)) for x, z in centres_xz]
    b.hexahedra(np.zeros((0, 8, 3)))  # so that a map with no obstacle builds too
    b.floor_area = float(triangle_area.sum())
    level = b.build("terrain", [], {
        "params": params,
        "floor_heights": (float(height.min()), float(height.max())),
        "ground": {"cells": n, "cell": step},
        "hills": hills,
        "cliffs": n_cliffs,
        "trees": int(is_tree.sum()),
        "rocks": int((~is_tree).sum()),
        "ruins": n_ruins,
        "ruin_segments": segments,
        "obstacle_centres": tuple((float(x), y, float(z)) for (x, z), y in zip(centres_xz, y_under)),
        "walkable_area": round(walkable_area, 6),
        "boundary_length": round(boundary, 6),
        "erosion_estimate": round(DESIGN_AGENT["radius"] * boundary, 6),
        "steep_share": float(triangle_area[~walkable].sum() / triangle_area.sum()),
        "components": components,
        "largest_component_share": largest,
        "cycles": None,
    })
    mesh = trimesh.util.concatenate([ground, level.mesh])
    mesh.merge_vertices()
    return dataclasses.replace(level, mesh=mesh)


def _ground(axis: np.ndarray, height: np.ndarray, n: int) -> tuple[trimesh.Trimesh, np.ndarray, np.ndarray]:
    """The ground surface of a height grid (n + 1, n + 1): (mesh, walkable (2 n², ) bool, 3D areas (2 n², ) m²).

    Triangle 2 (i n + j) and 2 (i n + j) + 1 are the two halves of grid square (i, j), both facing up.
    """
    import trimesh

    gx, gz = np.meshgrid(axis, axis, indexing="ij")
    vertices = np.column_stack([gx.ravel(), height.ravel(), gz.ravel()])
    index = np.arange((n + 1) ** 2).reshape(n + 1, n + 1)
    a, b, c, d = index[:-1, :-1].ravel(), index[1:, :-1].ravel(), index[1:, 1:].ravel(), index[:-1, 1:].ravel()
    # a (x0, z0), b (x1, z0), c (x1, z1), d (x0, z1): (a, d, c) and (a, c, b) face +Y
    faces = np.stack([np.column_stack([a, d, c]), np.column_stack([a, c, b])], axis=1).reshape(-1, 3)
    mesh = trimesh.Trimesh(vertices=vertices, faces=faces, process=False)
    normals = mesh.face_normals
    walkable = normals[:, 1] >= math.cos(math.radians(DESIGN_AGENT["max_slope_deg"]))
    return mesh, walkable, mesh.area_faces


def _polygon_area(corners: np.ndarray) -> float:
    """Area (m²) of a simple polygon given by its corners (k, 2) in order (shoelace formula)."""
    x, z = corners[:, 0], corners[:, 1]
    return 0.5 * abs(float(np.dot(x, np.roll(z, -1)) - np.dot(z, np.roll(x, -1))))


def _walkable_at(xz: np.ndarray, walkable: np.ndarray, step: float, n: int) -> np.ndarray:
    """Whether the ground square under each point (k, 2) has a walkable half: (k,) bool."""
    ij = np.clip(np.floor(xz / step).astype(int), 0, n - 1)
    square = ij[:, 0] * n + ij[:, 1]
    return walkable[2 * square] | walkable[2 * square + 1]


def _height_at(height: np.ndarray, step: float, n: int, x: float, z: float) -> float:
    """Ground height (m) at the grid vertex nearest (x, z)."""
    i, j = (min(max(round(v / step), 0), n) for v in (x, z))
    return height[i, j]


def _triangle_edges(n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Edges shared by two ground triangles: (t0, t1, horizontal length in grid steps), each (e,)."""
    square = np.arange(n * n).reshape(n, n)
    first, second = 2 * square, 2 * square + 1  # (a, d, c) touches -X and +Z; (a, c, b) touches -Z and +X
    t0 = [first.ravel(), second[:-1, :].ravel(), first[:, :-1].ravel()]
    t1 = [second.ravel(), first[1:, :].ravel(), second[:, 1:].ravel()]
    lengths = [np.full(n * n, math.sqrt(2.0)), np.ones(n * (n - 1)), np.ones(n * (n - 1))]
    return np.concatenate(t0), np.concatenate(t1), np.concatenate(lengths)


def _walkable_boundary(walkable: np.ndarray, step: float, n: int) -> float:
    """Horizontal length (m) of the walkable ground's border: edges to steeper triangles and the map's edge."""
    t0, t1, length = _triangle_edges(n)
    inner = float(np.sum(length[walkable[t0] != walkable[t1]]))
    square = np.arange(n * n).reshape(n, n)
    first, second = 2 * square, 2 * square + 1
    rim = walkable[first[0, :]].sum() + walkable[first[:, -1]].sum() + walkable[second[-1, :]].sum() \
        + walkable[second[:, 0]].sum()
    return (inner + float(rim)) * step


def _components(walkable: np.ndarray, area: np.ndarray, n: int) -> tuple[int, float]:
    """(number of connected regions of walkable triangles, the largest one's share of their area)."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    t0, t1, _ = _triangle_edges(n)
    keep = walkable[t0] & walkable[t1]
    graph = coo_matrix((np.ones(int(keep.sum())), (t0[keep], t1[keep])), shape=(len(walkable),) * 2)
    _, labels = connected_components(graph, directed=False)
    sums = np.bincount(labels[walkable], weights=area[walkable])
    sums = sums[sums > 0]
    return len(sums), float(sums.max() / sums.sum()) if len(sums) else 0.0


SAMPLES = {"terrain": terrain}
"""The outdoor samples, registered in :data:`g2s_plugins.samples.levels.SAMPLES`."""
