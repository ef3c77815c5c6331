"""run the full pipeline on the built-in dungeon sample

The ``g2s demo`` command (a Command plugin, as a third-party package would add one): the ``demo`` preset on
``sample:dungeon``, run as ``g2s run`` runs a config (:func:`g2s_core.cli.run_command`), then what to do with each
file it wrote.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
from pathlib import Path

from g2s_core.cli import EXIT_CODES, Output, add_output_options, output_folder, run_command
from g2s_core.errors import ConfigError
from g2s_core.mesh import SAMPLE_PREFIX
from g2s_core.plugin import hookimpl
from g2s_core.registry import installed

NAME = "demo"

HINTS = (
    ("report.html", "open {path} in a web browser (works offline) for the interactive 3D report"),
    ("heatmap.png", "{path}: top-down heat map of the analysis"),
    ("structure.glb", "{path}: level, navmesh and structure for any glTF viewer or Blender"),
    ("structure.json", "{path}: the structure as data (see docs/outputs.md)"),
    ("structure.graphml", "{path}, {graphml}: for networkx, Gephi, yEd"),
)
"""What to do with each file the demo may write, in the order the hint lists them."""


@hookimpl
def g2s_command(parser: argparse.ArgumentParser) -> Callable[[argparse.Namespace], int]:
    """``g2s demo``'s arguments; its run function."""
    parser.description, parser.epilog = "Run the full pipeline on the built-in dungeon sample.", EXIT_CODES
    parser.add_argument("-o", "--outdir", type=output_folder, default=Path("g2s-demo"), help="folder for the results (default: g2s-demo)")
    parser.add_argument("--rooms", type=int, default=12, help="rooms in the generated dungeon (default: 12)")
    parser.add_argument("--seed", type=int, default=0, help="seed of the generated dungeon (default: 0)")
    add_output_options(parser)
    return run


def run(args: argparse.Namespace) -> int:
    """The demo preset on the dungeon of ``--rooms`` and ``--seed``, then the hint; the exit code."""
    try:  # the dungeon generator's own bounds, named as the options the user gave ("rooms: ..." -> "--rooms: ...")
        installed().validate_params(installed().get("levels", "dungeon"), {"rooms": args.rooms, "seed": args.seed}, key="")
    except ConfigError as exc:
        raise ConfigError(f"--{exc}") from None
    args.config, args.mesh = "demo", f"{SAMPLE_PREFIX}dungeon?seed={args.seed}&rooms={args.rooms}"
    code = run_command(args, Output(stderr=True), mesh_name=f"dungeon (seed {args.seed}, {args.rooms} rooms)")
    if code == 0 and not (args.quiet or args.json):
        Output().print(hint(args.outdir), markup=False, highlight=False, soft_wrap=True)
    return code


def hint(outdir: Path) -> str:
    """Where the demo's results are and what to open each of them with: the files of :data:`HINTS` it wrote."""
    hints = ("  " + text.format(path=outdir / name, graphml=outdir / "graph.graphml") for name, text in HINTS
             if (outdir / name).exists())
    return "\n".join([f"the demo's results are in {outdir}/", *hints])
