"""Head room a little over and under the agent's height: which routes walk it (docs/navmesh.md, "Head room under an
edge").

Four generated cases join two open pads 5 x 5 m by a way 2.4 m wide under a ceiling ``head`` metres over its floor
(measured vertically): ``corridor`` (8 m long, flat), ``doorway`` (a wall 0.3 m thick across one floor, a doorway
2 m wide under a lintel at ``head``), ``ramp`` (a corridor rising 1.5 m over 8 m, 10.6 degrees, its ceiling
parallel) and ``stair`` (a flight of 8 steps, risers 0.16 m and treads 0.3 m, 28.1 degrees, its ceiling parallel to
the line through the nosings, ``head`` over it). A fifth, ``deck_edge``, is a car park's ramp passing under the edge
of the deck above: a ramp 3 m wide rising 3 m over 9 m (18.4 degrees) from a ground floor to an upper deck, open at
its sides, and over its first 3 m a deck whose edge stands ``head`` over the ramp. Each is turned by ``yaw`` about the vertical and raised by ``lift`` over the slabs' common
underside, so that its floor lies on or off a multiple of the cell height over the level's lowest point (Recast's
grid starts there). A way is walked by the navmesh when a Detour ray from one pad's middle reaches the other's; by the
sampling route when its graph joins the samples nearest the two pads' middles. Built from ``benchmarks/piece_parts.py``'s
solids. O(cases) builds, each a few hundred triangles.

Run: ``.venv/bin/python benchmarks/head_room.py [--presets map_analysis map_piece] [--no-sampling]``; prints one row a
case: kind, head, yaw, lift, the navmesh's answer, the sampling route's, and the designer's (head >= agent height).
"""

from __future__ import annotations

import argparse
import itertools
import math
from collections.abc import Callable, Iterator
from typing import Any

import networkx as nx
import numpy as np
import trimesh
from piece_parts import box, flight, hull

from g2s_core.config import PRESETS_DIR, load_config
from g2s_plugins._raycasting import AgentShape
from g2s_plugins.graph_builders import sampling
from g2s_plugins.recast import RecastParams, build_navmesh

KINDS = ("corridor", "doorway", "ramp", "stair", "deck_edge")
HEADS = (1.95, 2.0, 2.05, 2.1, 2.15, 2.2, 2.3)
YAWS = (0.0, 22.0, 45.0)
LIFTS = (0.0, 0.02, 0.0625, 0.1)
"""Floor heights over the slabs' underside beyond its 0.5 m: on the cell heights 0.125 and 0.05 m, 0.0 lies on a
multiple of both, 0.1 on one of 0.05 only, 0.02 and 0.0625 on neither."""

BASE = -0.5
"""Every slab's underside: the level's lowest point, where Recast's grid starts."""

WIDTH, PAD, WALL, RISE = 2.4, 5.0, 0.3, 1.5


def _pads_and_walls(length: float, wall_top: float, rise: float) -> list[trimesh.Trimesh]:
    """The two pads (open to the sky, at heights 0 and ``rise``) at either end of a way of ``length`` m along x over
    z [0, WIDTH], and the way's side walls up to ``wall_top``."""
    z0, z1 = -(PAD - WIDTH) / 2, (PAD + WIDTH) / 2
    return [box(-PAD, 0.0, BASE, 0.0, z0, z1), box(length, length + PAD, BASE, rise, z0, z1),
            box(0.0, length, BASE, wall_top, -WALL, 0.0), box(0.0, length, BASE, wall_top, WIDTH, WIDTH + WALL)]


def _sloped_ceiling(length: float, at: Callable[[float], float]) -> trimesh.Trimesh:
    """A ceiling slab 0.2 m thick over z [-WALL, WIDTH + WALL] whose underside runs straight from ``at(0)`` to
    ``at(length)``."""
    return hull([[x, at(x) + dy, z] for x in (0.0, length) for dy in (0.0, 0.2) for z in (-WALL, WIDTH + WALL)])


def case_mesh(kind: str, head: float, yaw_deg: float = 0.0, lift: float = 0.0) -> tuple[trimesh.Trimesh, np.ndarray]:
    """The case ``kind`` with head room ``head`` (m), turned by ``yaw_deg`` and its floors raised by ``lift`` (m) over
    the slabs' underside (kept at :data:`BASE`). Returns the mesh and the two pads' middles ((2, 3), metres)."""
    wide = WIDTH
    if kind == "corridor":
        length, rise = 8.0, 0.0
        parts = [box(0.0, length, BASE, 0.0, 0.0, WIDTH), _sloped_ceiling(length, lambda x: head)]
        parts += _pads_and_walls(length, head + 0.2, rise)
    elif kind == "doorway":  # one floor either side of a wall 0.3 m thick pierced by a doorway 2 m wide
        length, rise = 8.3, 0.0
        z0, z1 = -(PAD - WIDTH) / 2, (PAD + WIDTH) / 2
        mid0, mid1 = WIDTH / 2 - 1.0, WIDTH / 2 + 1.0
        parts = [box(-PAD, length + PAD, BASE, 0.0, z0, z1), box(4.0, 4.3, 0.0, 3.0, z0, mid0),
                 box(4.0, 4.3, 0.0, 3.0, mid1, z1), box(4.0, 4.3, head, 3.0, mid0, mid1)]
    elif kind == "ramp":
        length, rise = 8.0, RISE
        parts = [hull([[x, y, z] for x in (0.0, length) for y in (BASE, rise * x / length) for z in (0.0, WIDTH)]),
                 _sloped_ceiling(length, lambda x: rise * x / length + head)]
        parts += _pads_and_walls(length, rise + head + 0.2, rise)
    elif kind == "stair":  # 8 steps up from a landing 1 m long to one 1.2 m long, all under one ceiling
        steps, riser, tread = 9, 0.16, 0.3
        rise, run = steps * riser, (steps - 1) * tread
        length = 2.2 + run
        # the line through the nosings, at 0 a tread before the first riser and at ``rise`` over the top landing
        nosing = lambda x: min(max((x - 1.0 + tread) * riser / tread, 0.0), rise)  # noqa: E731
        parts = [box(0.0, 1.0, BASE, 0.0, 0.0, WIDTH), box(1.0 + run, length, BASE, rise, 0.0, WIDTH)]
        parts += flight((1.0, 0.0), (1.0, 0.0), (0.0, WIDTH), steps - 1, tread, riser, 0.0)
        for a, b in ((0.0, 1.0 - tread), (1.0 - tread, 1.0 + run), (1.0 + run, length)):
            parts.append(hull([[x, nosing(x) + head + dy, z] for x in (a, b) for dy in (0.0, 0.2)
                               for z in (-WALL, WIDTH + WALL)]))
        parts += _pads_and_walls(length, rise + head + 0.2, rise)
    elif kind == "deck_edge":  # no walls: the ramp's sides and the decks' rims are open
        length, rise, wide = 9.0, 3.0, 3.0
        parts = [hull([[x, y, z] for x in (0.0, length) for y in (BASE, rise * x / length) for z in (0.0, wide)]),
                 box(-PAD, 0.0, BASE, 0.0, 0.0, wide), box(length, length + PAD, BASE, rise, 0.0, wide),
                 box(-PAD, 3.0, 1.0 + head, 1.2 + head, 0.0, wide)]
    else:
        raise ValueError(f"unknown kind {kind!r}; expected one of {KINDS}")
    mesh = trimesh.util.concatenate(parts)
    mesh.merge_vertices()
    mids = np.array([[-PAD / 2, 0.0, wide / 2], [length + PAD / 2, rise, wide / 2]])
    lifted = mesh.vertices.copy()
    lifted[:, 1] = np.where(lifted[:, 1] > BASE + 1e-9, lifted[:, 1] + lift, lifted[:, 1])
    mids[:, 1] += lift
    turn = trimesh.transformations.rotation_matrix(math.radians(yaw_deg), [0.0, 1.0, 0.0])[:3, :3]
    out = trimesh.Trimesh(lifted @ turn.T, mesh.faces, process=False)
    return out, mids @ turn.T


def navmesh_walks(mesh: trimesh.Trimesh, mids: np.ndarray, agent, params: RecastParams) -> bool:
    """Whether a Detour ray from the first pad's middle reaches the second's over the navmesh of ``mesh``."""
    try:
        nav = build_navmesh(mesh.vertices, mesh.faces, agent, params)
    except RuntimeError:  # nothing walkable at all
        return False
    clear, _ = nav.raycast(mids[0], mids[1])
    return clear


def sampling_walks(mesh: trimesh.Trimesh, mids: np.ndarray, agent) -> bool:
    """Whether the sampling route's graph of ``mesh`` joins the samples nearest the two pads' middles."""
    graph = sampling.build_sampled_graph(mesh, sampling.Params(), AgentShape.from_config(agent))
    if graph.number_of_nodes() == 0:
        return False
    pos = np.array([graph.nodes[n]["pos"] for n in graph.nodes])
    nodes = list(graph.nodes)
    a, b = (nodes[int(np.argmin(np.linalg.norm(pos - m, axis=1)))] for m in mids)
    return nx.has_path(graph, a, b)


def case_parser(description: str, kinds: tuple[str, ...], measure: str, values: tuple[float, ...]) -> argparse.ArgumentParser:
    """The command line of a sweep of cases: presets, kinds, the measured values (``--<measure>``, m), yaws and
    lifts (shared with ``benchmarks/climb_steps.py``)."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--presets", nargs="+", default=["map_analysis", "map_piece"])
    parser.add_argument("--kinds", nargs="+", default=list(kinds), choices=kinds)
    parser.add_argument(f"--{measure}", nargs="+", type=float, default=list(values))
    parser.add_argument("--yaws", nargs="+", type=float, default=list(YAWS))
    parser.add_argument("--lifts", nargs="+", type=float, default=list(LIFTS))
    parser.add_argument("--no-sampling", action="store_true", help="the navmesh's answers alone")
    return parser


def sweep(args: argparse.Namespace, values: list[float], case_mesh: Callable[..., tuple[trimesh.Trimesh, np.ndarray]]
          ) -> Iterator[tuple[str, Any, str, float, float, float, bool, bool | None]]:
    """Every case of a sweep (``args`` of :func:`case_parser`, ``values`` its measured ones, m), preset by preset:
    ``(preset, its config, kind, value, yaw, lift, walked on the navmesh, walked on the sampling route or None with
    --no-sampling)``; ``case_mesh(kind, value, yaw, lift)`` gives the mesh and its two ends (shared with
    ``benchmarks/climb_steps.py``)."""
    for preset in args.presets:
        config = load_config(PRESETS_DIR / f"{preset}.yaml")
        params = RecastParams(**config.graph.params)
        for kind, value, yaw, lift in itertools.product(args.kinds, values, args.yaws, args.lifts):
            mesh, ends = case_mesh(kind, value, yaw, lift)
            nav = navmesh_walks(mesh, ends, config.agent, params)
            samp = None if args.no_sampling else sampling_walks(mesh, ends, config.agent)
            yield preset, config, kind, value, yaw, lift, nav, samp


def main() -> None:
    args = case_parser(__doc__.splitlines()[0], KINDS, "heads", HEADS).parse_args()
    print("preset kind head yaw lift navmesh sampling designer")
    for preset, config, kind, head, yaw, lift, nav, samp in sweep(args, args.heads, case_mesh):
        designer = "yes" if head >= config.agent.height else "no"
        print(f"{preset} {kind} {head:.2f} {yaw:g} {lift:g} {'yes' if nav else 'no'} "
              f"{'-' if samp is None else 'yes' if samp else 'no'} {designer}", flush=True)

if __name__ == "__main__":
    main()
