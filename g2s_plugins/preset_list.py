"""list the preset configs and what each is for

The ``g2s presets`` command (a Command plugin, as ``g2s plugins`` is): each preset's name and its description, in two
columns wrapped to the terminal (:func:`g2s_core.config.presets`, which ``g2s run --help`` lists too).
"""

from __future__ import annotations

import argparse
from collections.abc import Callable

from g2s_core.cli import EXIT_CODES, Output, columns
from g2s_core.config import presets
from g2s_core.plugin import hookimpl

NAME = "presets"


@hookimpl
def g2s_command(parser: argparse.ArgumentParser) -> Callable[[argparse.Namespace], int]:
    """``g2s presets``' description; its run function."""
    parser.description, parser.epilog = "List the preset configs and what each is for.", EXIT_CODES
    return run


def run(args: argparse.Namespace) -> int:
    """The presets, one a row; exit code 0."""
    console = Output()
    console.print("\n".join(columns(list(presets().items()), console.width, 0)), markup=False, highlight=False, soft_wrap=True)
    return 0
