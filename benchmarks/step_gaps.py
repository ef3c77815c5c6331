"""Narrow gaps between floors: which do the two routes join, at any angle and place on the grid (issue 9)?

A row of two (or three) slabs 0.3 m thick, each 6 m wide, ``LENGTH`` m long along the row (the middle one of three
4 m), their tops at ``TOP`` m and, with ``--dh``, every second one ``dh`` m higher, parted by gaps ``width`` m wide
(between the slabs' faces) over a lower ground ``DROP`` m under the first slab's top (``--under ground``; with
``--under-depth``, that many m under it instead, each depth a case kind) or over nothing (``--under none``). The row
is turned ``yaw`` degrees about the vertical through the first gap's middle and moved by (s, 0.6 s) m in plan for
each shift s (sub-cell moves on Recast's grid). A gap is *joined* when the graph's nodes nearest the middles of the
two slabs beside it lie in one connected part (the navmesh route: the polygons under those points joined through
Detour's links; the sampling route: the sampled graph's samples nearest them).

The product rule (issue 9, session 54): a walker steps over a gap narrower than ``step_gap`` between two floors whose
heights differ by at most the agent's climb, at any angle and place on the grid; a gap at least ``step_gap`` wide is
never crossed. With a height difference over the climb no gap is crossed. How deep the floor under the gap lies
does not matter while it is deeper than the climb (review54 MED 2: a floor 0.42-0.5 m down, within the ground
probes' reach, parted what one 0.52 m or 3 m down joined); a floor within the climb under the slabs is a real step
down, walked however wide the gap (the agent steps into the channel and out).

Each preset runs its own graph builder (``graph.plugin``: navmesh or sampling) with its ``graph.params`` and agent.
Per (preset, case kind, width) the table gives how many of the (yaw, shift) cases are joined.

Run: ``.venv/bin/python benchmarks/step_gaps.py [--presets map_analysis map_analysis_sampling]
[--widths 0.02 0.05 ...] [--yaws 0 10 20 30 45] [--shifts 0 0.08 0.16] [--slabs 2] [--dh 0] [--under ground]
[--under-depth 0.3 0.42 0.45 0.5 0.52 3] [--set key=value ...]`` (``--set``: a ``graph.params`` key over the
preset's, e.g. ``step_gap=0``; numbers as YAML).
Several values of ``--slabs``, ``--dh``, ``--under`` and ``--under-depth`` give every combination as case kinds.
"""

from __future__ import annotations

import argparse
import itertools
import math
import sys
import time

import numpy as np
import trimesh
import yaml
from level_kinds import _Solids
from narrow_gaps import preset_config
from scipy.sparse import coo_matrix, csgraph
from scipy.spatial import cKDTree

from g2s_plugins._raycasting import AgentShape
from g2s_plugins.graph_builders import navmesh as navmesh_builder
from g2s_plugins.graph_builders import sampling
from g2s_plugins.recast import build_navmesh

TOP = 0.0
"""The first slab's top, m."""

DROP = 3.0
"""How far the lower ground lies under the first slab's top, m: far over the climb, under the ledge rules' reach."""

LENGTH = 6.0
"""Each outer slab's length along the row, m (the middle one of three: ``MIDDLE``)."""

MIDDLE = 4.0
"""The middle slab's length along the row when there are three, m: room for the agent between two gaps."""

WIDE = 3.0
"""Half the slabs' width across the row, m."""

THICK = 0.3
"""The slabs' thickness, m."""


def slab_spans(width: float, slabs: int) -> list[tuple[float, float]]:
    """(u0, u1) along the row of each slab, the first gap's middle at u = 0."""
    spans = [(-width / 2 - LENGTH, -width / 2)]
    start = width / 2
    for k in range(1, slabs):
        length = MIDDLE if k < slabs - 1 else LENGTH
        spans.append((start, start + length))
        start += length + width
    return spans


def level(width: float, slabs: int, dh: float, under: str, yaw: float, shift: float,
          depth: float = DROP) -> tuple[trimesh.Trimesh, np.ndarray]:
    """The mesh and the slabs' top middles ((slabs, 3), m), turned and moved; the lower ground ``depth`` m under
    the first slab's top (``under == "ground"``)."""
    s = _Solids()
    spans = slab_spans(width, slabs)
    middles = []
    for k, (u0, u1) in enumerate(spans):
        top = TOP + (dh if k % 2 else 0.0)
        s.box(u0, u1, top - THICK, top, -WIDE, WIDE)
        middles.append([(u0 + u1) / 2, top, 0.0])
    if under == "ground":
        s.box(spans[0][0] - 1.0, spans[-1][1] + 1.0, TOP - depth - 0.5, TOP - depth, -WIDE - 1.0, WIDE + 1.0)
    mesh = s.mesh()
    turn = trimesh.transformations.rotation_matrix(math.radians(yaw), (0.0, 1.0, 0.0))
    turn[:3, 3] = [shift, 0.0, 0.6 * shift]
    mesh.apply_transform(turn)
    return mesh, np.asarray(middles) @ turn[:3, :3].T + turn[:3, 3]


def parts_navmesh(mesh: trimesh.Trimesh, middles: np.ndarray, config, params: dict) -> np.ndarray:
    """The connected part of the polygon under each middle (-1: none), on the navmesh route."""
    nav = build_navmesh(mesh.vertices, mesh.faces, config.agent, navmesh_builder.Params(**params))
    n = nav.polygon_count
    pairs = nav.portals().pairs
    _, label = csgraph.connected_components(coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])),
                                                       shape=(n, n)), directed=False)
    polys = [nav.nearest_poly(p, (0.5, 1.0, 0.5))[0] for p in middles]
    return np.array([label[p] if p >= 0 else -1 for p in polys])


def parts_sampling(mesh: trimesh.Trimesh, middles: np.ndarray, config, params: dict) -> np.ndarray:
    """The connected part of the sample nearest each middle (within 1 m; -1: none), on the sampling route."""
    graph = sampling.build_sampled_graph(mesh, sampling.Params(**params), AgentShape.from_config(config.agent))
    nodes = sorted(graph.nodes)
    if not nodes:
        return np.full(len(middles), -1)
    index = {v: i for i, v in enumerate(nodes)}
    pos = np.array([graph.nodes[v]["pos"] for v in nodes])
    pairs = np.array([(index[a], index[b]) for a, b in graph.edges()]).reshape(-1, 2)
    _, label = csgraph.connected_components(coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])),
                                                       shape=(len(nodes), len(nodes))), directed=False)
    distance, nearest = cKDTree(pos).query(middles)
    return np.where(distance < 1.0, label[nearest], -1)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--presets", nargs="+", default=["map_analysis", "map_analysis_sampling"])
    ap.add_argument("--widths", type=float, nargs="+",
                    default=[0.02, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4, 0.45, 0.5, 0.6, 0.8])
    ap.add_argument("--yaws", type=float, nargs="+", default=[0.0, 10.0, 20.0, 30.0, 45.0])
    ap.add_argument("--shifts", type=float, nargs="+", default=[0.0, 0.08, 0.16])
    ap.add_argument("--slabs", type=int, nargs="+", default=[2], choices=[2, 3])
    ap.add_argument("--dh", type=float, nargs="+", default=[0.0], help="every second slab this much higher, m")
    ap.add_argument("--under", nargs="+", default=["ground"], choices=["ground", "none"])
    ap.add_argument("--under-depth", type=float, nargs="+", default=[DROP],
                    help="how far under the first slab's top the lower ground lies, m (--under ground)")
    ap.add_argument("--set", nargs="*", default=[], metavar="KEY=VALUE", help="graph.params over the preset's")
    ap.add_argument("--cases", action="store_true", help="print every case, not only the table")
    a = ap.parse_args(argv)
    extra = {}
    if min(a.under_depth) < THICK:
        print(f"--under-depth: {min(a.under_depth):g}: expected at least the slabs' thickness, {THICK:g} m", file=sys.stderr)
        return 2
    for item in a.set:
        key, sep, value = item.partition("=")
        if not sep:
            print(f"--set: {item}: expected KEY=VALUE", file=sys.stderr)
            return 2
        extra[key] = yaml.safe_load(value)
    for preset in a.presets:
        config = preset_config(preset)
        if config is None:
            return 2
        params = {**config.graph.params, **extra}
        route = config.graph.plugin
        parts = {"navmesh": parts_navmesh, "sampling": parts_sampling}.get(route)
        if parts is None:
            print(f"--presets: {preset}: graph.plugin {route} is neither navmesh nor sampling", file=sys.stderr)
            return 2
        print(f"{preset} ({route}; agent radius {config.agent.radius:g} m, climb {config.agent.max_climb:g} m; "
              f"graph.params {params}): joined gaps of (yaw, shift) cases, yaws {a.yaws}, shifts {a.shifts}")
        print(f"  {preset} | case kind | " + " | ".join(f"{w:g} m" for w in a.widths) + "   (% joined)")
        started = time.process_time()
        kinds = [(slabs, dh, under, depth) for slabs, dh, under in itertools.product(a.slabs, a.dh, a.under)
                 for depth in (a.under_depth if under == "ground" else [DROP])]
        for slabs, dh, under, depth in kinds:
            kind = f"{slabs} slabs, dh {dh:g} m, over " + (f"ground {depth:g} m down" if under == "ground" else under)
            cells = []
            for width in a.widths:
                joined = total = 0
                for yaw, shift in itertools.product(a.yaws, a.shifts):
                    mesh, middles = level(width, slabs, dh, under, yaw, shift, depth)
                    label = parts(mesh, middles, config, params)
                    for k in range(slabs - 1):
                        together = bool(label[k] >= 0 and label[k] == label[k + 1])
                        joined += together
                        total += 1
                        if a.cases:
                            print(f"    {kind} w {width:g} yaw {yaw:g} shift {shift:g} gap {k}: "
                                  f"{'joined' if together else 'apart'}", flush=True)
                cells.append(f"{100.0 * joined / total:.0f}")
            print(f"  {preset} | {kind} | " + " | ".join(cells), flush=True)
        print(f"  {preset}: {time.process_time() - started:.1f} s CPU", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
