"""Openings and structures of map pieces against their known or designer-placed connectors.

Run: ``.venv/bin/python benchmarks/piece_quality.py [--config configs/map_piece.yaml] [--pieces DIR]
[--variations] [--held-out] [--yaws 0 5 10 15 20 30 45 60 90]``

Runs the map-piece preset on every generated piece of
:mod:`g2s_plugins.samples.pieces` (reference: the known openings) and on the
shared pieces ``../shared/data/pieces/*.obj`` (reference: the designers'
connectors in ``connectors.json``; the Hallway has none, so its tool
connectors stand in, and the table says so); with ``--held-out``, also on the
families the rules were not measured on (:data:`pieces.HELD_OUT` and
:data:`HELD_OUT_VARIATIONS`). Per piece it prints the
detected openings, precision (share of openings whose midpoint lies within
1.5 m of a reference connector), recall (share of reference connectors with
an opening that close), the number of trees of the structure, and the
largest height between a final edge and the navmesh surface under it
(edges made by simplification / all edges). With ``--yaws`` every piece and
its reference are turned about the vertical axis through the centre of the
piece's bounding box, one table per angle: the answer must not depend on how
the piece is turned.
docs/entry_exit.md records its output before and after changes.
"""

from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Callable
from pathlib import Path

import numpy as np
import trimesh

from g2s_core import pipeline
from g2s_core.config import AgentConfig, load_config
from g2s_core.errors import G2SError
from g2s_core.mesh import load_mesh, mesh_sha256
from g2s_core.model import RunResult
from g2s_core.registry import Registry
from g2s_plugins.samples import pieces

ROOT = Path(__file__).resolve().parents[1]
SHARED_PIECES = ROOT.parent / "shared" / "data" / "pieces"


def edge_surface_gap(result: RunResult) -> tuple[float, float]:
    """Largest height (m) between the structure's edges and the navmesh surface: (collapsed edges, all edges).

    Collapsed edges are those simplification made (not in the initial graph); the others join
    neighbouring navmesh polygons' centres.
    """
    from g2s_plugins._surface import edge_surface_gaps

    if result.context.navmesh is None or result.structure is None:
        return float("nan"), float("nan")
    gaps = edge_surface_gaps(result.structure, result.context.navmesh, result.context.agent)
    new = [g for (a, b), g in gaps.items() if not result.graph.has_edge(a, b)]
    return max(new, default=0.0), max(gaps.values(), default=0.0)


def trees(result: RunResult) -> int:
    """Number of trees in the final structure (0 when the run stopped before)."""
    return 0 if result.structure is None else len(result.structure.graph["roots"])


def measure(
    run: Callable[[trimesh.Trimesh, str], RunResult], name: str, mesh: trimesh.Trimesh, reference: np.ndarray
) -> dict:
    """One row: counts, precision, recall, trees and surface gap of ``run(mesh, name)``; ``error`` when it fails.

    ``reference``: (k, 3) the known openings' midpoints, metres.
    """
    try:
        result = run(mesh, name)
    except G2SError as error:  # what the user sees instead of openings
        return {"piece": name, "reference": len(reference), "error": str(error).split(":")[0]}
    openings = result.terminals.openings if result.terminals is not None else ()
    found = np.array([o.position for o in openings], dtype=np.float64).reshape(-1, 3)
    correct, recalled = pieces.match_openings(found, reference)
    return {
        "piece": name,
        "openings": len(openings),
        "reference": len(reference),
        "correct": correct,
        "recalled": recalled,
        "trees": trees(result),
        "gap": edge_surface_gap(result),
        "scores": [getattr(o, "score", None) for o in openings],
    }


def shared_references(folder: Path) -> dict[str, tuple[np.ndarray, str]]:
    """Piece name -> (reference midpoints, which connectors) for the shared pieces in ``folder``."""
    path = folder / "connectors.json"
    if not path.is_file():
        return {}
    data = json.loads(path.read_text(encoding="utf-8"))["pieces"]
    out = {}
    for name, entry in sorted(data.items()):
        designer = entry.get("designer_connectors", [])
        kind = "designer" if designer else "tool"
        chosen = designer or entry.get("tool_connectors", [])
        out[name] = (np.array([c["position"] for c in chosen], dtype=np.float64).reshape(-1, 3), kind)
    return out


def prior_measurements(
    mesh: trimesh.Trimesh, reference: np.ndarray, agent: AgentConfig, navmesh_params: dict
) -> list[tuple]:
    """Every candidate opening with the priors off: (known?, width m, gap to the outer extent m, on the main floor?).

    What docs/entry_exit.md quotes to justify each prior's default.
    """
    from g2s_plugins.recast import RecastParams, build_navmesh
    from g2s_plugins.terminals import entry_exit

    navmesh = build_navmesh(mesh.vertices, mesh.faces, agent, RecastParams(**navmesh_params))
    loose = entry_exit.Params(min_width_radii=0.0, extent_heights=None, main_floor_only=False)
    detection = entry_exit.detect_openings(mesh, navmesh, agent, loose)
    main = entry_exit.main_floor(navmesh, agent)
    corners = np.asarray(mesh.triangles, dtype=np.float64)
    frame = entry_exit.piece_frame(mesh)
    rows = []
    for opening, polygons in zip(detection.openings, detection.polygons):
        position = np.asarray(opening.position)
        known = bool(len(reference)) and bool(
            np.min(np.linalg.norm(reference - position, axis=1)) <= pieces.MATCH_DISTANCE
        )
        below = entry_exit.corners_below(corners, position[1] + float(agent.height))
        gap = entry_exit.extent_gap(below, position, np.asarray(opening.heading), frame)
        rows.append((known, opening.width, gap, bool(main[list(polygons)].any())))
    return rows


VARIATIONS = [
    ("doorway_room", {"wall": 0.4}), ("doorway_room", {"wall": 0.8}), ("doorway_room", {"doors": (1.2,) * 5}),
    ("doorway_room", {"doors": (2.0,) * 5, "wall": 0.3}),
    ("doorway_room", {"width": 8.0, "depth": 7.0, "doors": (1.4, 1.6, 1.3)}),
    ("curb_platform", {"curb": 0.25}), ("curb_platform", {"curb": 0.35, "gap": 1.2}),
    ("curb_platform", {"length": 20.0, "depth": 5.0}),
    ("wall_tops", {"high": 2.5}), ("wall_tops", {"thick": 3.0, "length": 16.0}),
    ("stair_deck", {"riser": 0.245}), ("stair_deck", {"riser": 0.2, "steps": 15, "tread": 0.28, "floor_length": 9.0}),
    ("stair_deck", {"stair_width": 1.5}),
    ("cross_platform", {"hub": 4.0, "arm_length": 3.0, "arm_width": 2.0}),
    ("cross_platform", {"hub": 10.0, "arm_length": 8.0, "arm_width": 6.0}),
    ("chamfered_platform", {"chamfer": 0.3}), ("chamfered_platform", {"length": 6.0, "width": 6.0, "chamfer": 0.4}),
]
"""Generated pieces with other parameters than the defaults: the rules must hold beyond the cases they were measured on."""

HELD_OUT_VARIATIONS = [
    ("bridge", {"width": 1.6}), ("bridge", {"width": 1.2}), ("windowed_room", {"sill": 0.5}), ("threshold_door", {"step": 0.3}),
    ("thick_wall_door", {"doors": (1.4, 2.0)}), ("narrow_door_room", {"narrow": 0.8}),
    ("narrow_door_room", {"door": 0.0}),
]
"""Held-out families with other parameters: 1.6 and 1.2 m bridges, a sill above the climb but low, a 0.3 m
threshold, wider tunnels, a door exactly the agent's diameter, a piece whose only door is too narrow."""

def print_table(rows: list[tuple[dict, str]]) -> None:
    """The per-piece table: counts, precision, recall, trees, surface gaps and scores."""
    print(f"{'piece':58s} {'ref':8s} {'found':>5s} {'refs':>4s} {'precision':>10s} {'recall':>8s} "
          f"{'trees':>5s} {'gap new/all m':>13s}  scores")
    for row, kind in rows:
        if "error" in row:
            print(f"{row['piece']:58s} {kind:8s} {'-':>5s} {row['reference']:4d}  error: {row['error']}")
            continue
        precision = row["correct"] / row["openings"] if row["openings"] else float("nan")
        recall = row["recalled"] / row["reference"] if row["reference"] else float("nan")
        scores = " ".join("-" if v is None else f"{v:.2f}" for v in row["scores"])
        print(f"{row['piece']:58s} {kind:8s} {row['openings']:5d} {row['reference']:4d} "
              f"{row['correct']:3d} {precision:6.0%} {row['recalled']:2d} {recall:5.0%} "
              f"{row['trees']:5d} {row['gap'][0]:6.2f}/{row['gap'][1]:5.2f}  {scores}")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--config", default=str(ROOT / "configs" / "map_piece.yaml"))
    parser.add_argument("--pieces", default=str(SHARED_PIECES), help="folder of the shared pieces and connectors.json")
    parser.add_argument("--priors", action="store_true", help="also list the generated pieces' candidates, priors off")
    parser.add_argument("--variations", action="store_true", help="also run the generated pieces with other parameters")
    parser.add_argument("--held-out", action="store_true",
                        help="also run the families the rules were not measured on (and, with --variations, theirs)")
    parser.add_argument(
        "--yaws", type=float, nargs="+", default=[0.0], metavar="DEG",
        help="turn every piece and its reference by these angles about the vertical axis through the centre of its "
        "bounding box, degrees; one table per angle (default: 0, as laid out)",
    )
    args = parser.parse_args(argv)
    registry = Registry.from_entry_points()
    plan = pipeline.plan(load_config(Path(args.config)), registry)

    def run(mesh: trimesh.Trimesh, name: str) -> RunResult:
        return pipeline.run(plan, registry, mesh, name, mesh_sha256(mesh))

    tuned = [name for name in pieces.PIECES if name not in pieces.HELD_OUT]
    generated = [(name, {}) for name in tuned] + (VARIATIONS if args.variations else [])
    if args.held_out:
        generated += [(name, {}) for name in pieces.HELD_OUT] + (HELD_OUT_VARIATIONS if args.variations else [])
    folder = Path(args.pieces)
    shared = [(name, load_mesh(folder / f"{name}.obj")[0], reference, kind)
              for name, (reference, kind) in shared_references(folder).items()]
    for index, yaw in enumerate(args.yaws):
        rows = []
        for name, kwargs in generated:
            level = pieces.PIECES[name](**kwargs)
            if yaw:
                level = pieces.turned(level, yaw)
            reference = np.array([o.position for o in level.openings], dtype=np.float64)
            label = name + "".join(f" {k}={v}" for k, v in kwargs.items())
            rows.append((measure(run, label, level.mesh, reference), "known"))
        for name, mesh, reference, kind in shared:
            if yaw:
                matrix = pieces.yaw_about_centre(mesh, yaw)
                mesh = mesh.copy()
                mesh.apply_transform(matrix)
                reference = trimesh.transform_points(reference, matrix) if len(reference) else reference
            rows.append((measure(run, name, mesh, reference), kind))
        if len(args.yaws) > 1 or yaw:
            print(("\n" if index else "") + f"yaw {yaw:g} degrees")
        print_table(rows)
    if args.priors:
        config = load_config(Path(args.config))
        print("\ncandidates with the priors off (generated pieces): piece, known, width m, extent gap m, main floor")
        for name, factory in pieces.PIECES.items():
            level = factory()
            reference = np.array([o.position for o in level.openings], dtype=np.float64)
            for known, width, gap, on_main in prior_measurements(
                level.mesh, reference, config.agent, dict(config.graph.params or {})
            ):
                print(f"  {name:20s} {'known' if known else 'other':5s} {width:6.2f} {gap:6.2f} {on_main}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
