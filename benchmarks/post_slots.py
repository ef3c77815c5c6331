"""Do the sampled graph's edges pass a post between two slots, a column in a corridor, a row of bollards?

Run: ``.venv/bin/python benchmarks/post_slots.py [--yaws 0 22 45] [--offsets 0 0.3] [--navmesh] [--kinds SUBSTR ...]``

Generated levels (built here, Y up, metres; the presets' agent, radius 0.5 m,
so 1.0 m wide, clearance 0.5 m, spacing 1 m; ``sampling``'s defaults with
``method: grid``, as ``map_analysis_sampling``):

* ``post``: two 10 x 10 m rooms side by side on one floor slab, parted by a
  0.2 m wall 3 m high along z = 0 with one opening of two slots ``slot`` m
  wide each side of a post ``post`` m square (the post and the jambs stand
  the wall's full height);
* ``column``: two 10 x 10 m rooms joined by a corridor 6 m long and ``width``
  m wide between closed 3 m blocks, a column ``post`` m square in its middle
  (so two passages of (``width`` - ``post``) / 2 m);
* ``bollards``: one 20 x 20 m floor crossed along z = 0 by a row of bollards
  ``post`` m square, 1.2 m high (and, in the ``low`` rows, 0.5, 0.7 or 0.9 m:
  above the agent's 0.4 m step, under half its 2 m height),
  ``slot`` m apart, from wall to wall (closed 3 m walls all round);
  ``crates``: the same row of 0.8 m square crates, 1.2 m high or, in the ``low`` rows, lower;
* ``low wall``: the same walled floor crossed along z = 0, wall to wall, by a
  wall 0.2 m thick and as high as the row says (0.3 m: a step the agent climbs).

The ``gap`` rows take the slots, passages and gaps at 0.90, 0.95, 0.99, 1.01,
1.05 and 1.1 x the agent's width.

Each level is turned about the vertical axis by every yaw and moved by every
offset (the same distance along x and z, so that the grid's lines fall
elsewhere against the opening). A case is *joined* when the samples nearest
the two sides' middles (3 m either side of the opening's middle, along its
normal) lie in one connected part of the graph; with ``--navmesh`` the
``navmesh`` builder's defaults are asked the same about its polygons. The
agent fits when a slot (a passage) is at least its width, 1.0 m, or the
obstacle is no higher than its step (``max_climb``, 0.4 m). This is a
benchmark: nothing here asserts a target; the figures are in docs/sampling.md
("A post between the edge's lines", "The agent's body between the edge's lines").
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Callable
from functools import partial

import numpy as np
import trimesh
from scipy.sparse import csgraph, csr_array
from scipy.spatial import cKDTree

from g2s_core.config import AgentConfig
from g2s_core.model import RunContext
from g2s_plugins.graph_builders import navmesh, sampling

AGENT_WIDTH = 1.0
"""The presets' agent's width (twice its 0.5 m radius), m."""


def _box(lo: tuple[float, float, float], hi: tuple[float, float, float]) -> trimesh.Trimesh:
    box = trimesh.creation.box(extents=np.subtract(hi, lo))
    box.apply_translation(np.add(lo, hi) / 2.0)
    return box


def post_level(slot: float, post: float) -> trimesh.Trimesh:
    """Two rooms parted along z = 0 by a 0.2 m wall whose opening is two ``slot`` m slots beside a ``post`` m post."""
    half = slot + 0.5 * post
    return trimesh.util.concatenate([
        _box((-10.0, -0.2, -10.0), (10.0, 0.0, 10.0)),
        _box((-10.0, 0.0, -0.1), (-half, 3.0, 0.1)),
        _box((half, 0.0, -0.1), (10.0, 3.0, 0.1)),
        _box((-0.5 * post, 0.0, -0.5 * post), (0.5 * post, 3.0, 0.5 * post)),
    ])


def column_level(width: float, post: float) -> trimesh.Trimesh:
    """Two 10 x 10 m rooms (z < -3 and z > 3) joined by a 6 m corridor ``width`` m wide along z with a column in it."""
    half = 0.5 * width
    return trimesh.util.concatenate([
        _box((-5.0, -0.2, -13.0), (5.0, 0.0, 13.0)),
        _box((-5.0, 0.0, -3.0), (-half, 3.0, 3.0)),
        _box((half, 0.0, -3.0), (5.0, 3.0, 3.0)),
        _box((-0.5 * post, 0.0, -0.5 * post), (0.5 * post, 3.0, 0.5 * post)),
    ])


def _walled_floor() -> list[trimesh.Trimesh]:
    """A 20 x 20 m floor slab with closed walls 3 m high all round."""
    return [
        _box((-10.0, -0.2, -10.0), (10.0, 0.0, 10.0)),
        _box((-10.2, 0.0, -10.0), (-10.0, 3.0, 10.0)), _box((10.0, 0.0, -10.0), (10.2, 3.0, 10.0)),
        _box((-10.0, 0.0, -10.2), (10.0, 3.0, -10.0)), _box((-10.0, 0.0, 10.0), (10.0, 3.0, 10.2)),
    ]


def bollard_level(gap: float, post: float, height: float = 1.2) -> trimesh.Trimesh:
    """A 20 x 20 m walled floor crossed along z = 0 by bollards ``post`` m square and ``height`` m high, ``gap`` m
    apart, wall to wall."""
    parts = _walled_floor()
    # Bollards centred on x = 0 and every (gap + post) m, the gaps at the walls no wider than ``gap``.
    pitch = gap + post
    count = int(np.ceil((10.0 - gap - 0.5 * post) / pitch))
    for x in pitch * np.arange(-count, count + 1):
        lo, hi = max(x - 0.5 * post, -10.0), min(x + 0.5 * post, 10.0)
        parts.append(_box((lo, 0.0, -0.5 * post), (hi, height, 0.5 * post)))
    return trimesh.util.concatenate(parts)


def low_wall_level(height: float) -> trimesh.Trimesh:
    """The walled 20 x 20 m floor of :func:`bollard_level` crossed along z = 0, wall to wall, by a wall 0.2 m thick and
    ``height`` m high."""
    return trimesh.util.concatenate([*_walled_floor(), _box((-10.0, 0.0, -0.1), (10.0, height, 0.1))])


def _placed(mesh: trimesh.Trimesh, yaw: float, offset: float) -> tuple[trimesh.Trimesh, np.ndarray]:
    """The level turned by ``yaw`` degrees and moved (``offset``, 0, ``offset``) m, and the matrix that did it."""
    matrix = trimesh.transformations.rotation_matrix(np.radians(yaw), (0.0, 1.0, 0.0))
    matrix[[0, 2], 3] = offset
    mesh = mesh.copy()
    mesh.apply_transform(matrix)
    return mesh, matrix


def joined(positions: np.ndarray, edges: np.ndarray, ends: np.ndarray) -> bool:
    """Whether the nodes nearest ``ends`` ((2, 3) m) of a graph (``positions`` (n, 3), ``edges`` (m, 2)) are in one part."""
    count = len(positions)
    matrix = csr_array((np.ones(len(edges)), (edges[:, 0], edges[:, 1])), shape=(count, count))
    labels = csgraph.connected_components(matrix, directed=False)[1]
    first, second = cKDTree(positions).query(ends)[1]
    return bool(labels[first] == labels[second])


def _arrays(graph) -> tuple[np.ndarray, np.ndarray]:
    nodes = sorted(graph.nodes)
    index = {n: i for i, n in enumerate(nodes)}
    positions = np.array([graph.nodes[n]["pos"] for n in nodes])
    edges = np.array([(index[a], index[b]) for a, b in graph.edges()], dtype=np.int64).reshape(-1, 2)
    return positions, edges


GAP_SHARES = (0.90, 0.95, 0.99, 1.01, 1.05, 1.1)
"""The ``gap`` rows' slot, passage and gap widths, in agent widths."""

LOW_HEIGHTS = (0.5, 0.7, 0.9)
"""The ``low`` rows' obstacle heights, m: above the agent's 0.4 m step, under half its 2 m height."""

Case = tuple[str, Callable[[float, float], trimesh.Trimesh], list[tuple[float, float]], float, float]
"""kind, level, (slot or passage width, post) pairs, the distance of the two probe points from the opening (m), the
obstacle's height (m; the agent fits whatever the gap where it is no higher than the step)."""

CASES: list[Case] = [
    ("post", post_level, [(s, p) for s in (0.6, 0.8, 1.4, 1.8) for p in (0.1, 0.2, 0.3, 0.4)], 3.0, 3.0),
    ("column", column_level, [(w, p) for p in (0.1, 0.2, 0.3, 0.4) for w in (2 * 0.8 + p, 2 * 2.0 + p)], 6.0, 3.0),
    ("bollards", bollard_level, [(0.6, p) for p in (0.1, 0.2, 0.3, 0.4)] + [(1.8, 0.2)], 3.0, 1.2),
    ("bollards 0.9 m high", partial(bollard_level, height=0.9), [(0.6, 0.2)], 3.0, 0.9),
    ("gap post", post_level, [(g * AGENT_WIDTH, 0.2) for g in GAP_SHARES], 3.0, 3.0),
    ("gap column", column_level, [(2 * g * AGENT_WIDTH + 0.2, 0.2) for g in GAP_SHARES], 6.0, 3.0),
    ("gap bollards", bollard_level, [(g * AGENT_WIDTH, 0.2) for g in GAP_SHARES], 3.0, 1.2),
    ("crates", bollard_level, [(0.6, 0.8), (1.2, 0.8)], 3.0, 1.2),
    *[(f"low bollards {h:.1f} m", partial(bollard_level, height=h), [(0.6, 0.2)], 3.0, h) for h in LOW_HEIGHTS],
    *[(f"low crates {h:.1f} m", partial(bollard_level, height=h), [(0.6, 0.8), (1.2, 0.8)], 3.0, h) for h in LOW_HEIGHTS],
    *[(f"low wall {h:.1f} m", lambda slot, post, h=h: low_wall_level(h), [(0.0, 0.2)], 3.0, h) for h in (0.3, *LOW_HEIGHTS)],
]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--yaws", type=float, nargs="+", default=[0.0, 22.0, 45.0], help="turns, degrees")
    parser.add_argument("--offsets", type=float, nargs="+", default=[0.0, 0.3], help="moves along x and z, m")
    parser.add_argument("--navmesh", action="store_true", help="also ask the navmesh builder")
    parser.add_argument("--kinds", nargs="+", default=None, help="only the kinds whose name holds one of these")
    args = parser.parse_args()
    agent = AgentConfig(radius=0.5)
    seconds = 0.0
    print("kind                 slot  post  fits  sampling joined  navmesh joined   (of yaws x offsets)")
    for kind, make, sizes, reach, height in CASES:
        if args.kinds and not any(part in kind for part in args.kinds):
            continue
        for slot, post in sizes:
            passage = 0.5 * (slot - post) if kind.endswith("column") else slot
            joins = [0, 0]
            cases = 0
            for yaw in args.yaws:
                for offset in args.offsets:
                    mesh, matrix = _placed(make(slot, post), yaw, offset)
                    ends = (np.array([[0.0, 0.0, -reach, 1.0], [0.0, 0.0, reach, 1.0]]) @ matrix.T)[:, :3]
                    context = RunContext(mesh=mesh, agent=agent, centre=mesh.bounds.mean(axis=0))
                    started = time.process_time()
                    graph = sampling.g2s_build_graph(mesh=mesh, params=sampling.Params(method="grid"), context=context)
                    seconds += time.process_time() - started
                    joins[0] += joined(*_arrays(graph), ends)
                    if args.navmesh:
                        polygons = navmesh.g2s_build_graph(mesh=mesh, params=navmesh.Params(), context=context)
                        joins[1] += joined(*_arrays(polygons), ends)
                    cases += 1
            fits = "yes" if passage >= AGENT_WIDTH or height <= agent.max_climb else "no"
            nav = f"{joins[1]:2d} of {cases}" if args.navmesh else "-"
            print(f"{kind:19s} {passage:5.2f} {post:5.2f}  {fits:>4}  {joins[0]:6d} of {cases:<2d}  {nav:>12}", flush=True)
    print(f"{seconds:.1f} s CPU in the sampling builder")


if __name__ == "__main__":
    main()
