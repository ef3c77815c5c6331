"""list installed plugins and their parameters, and broken ones

The ``g2s plugins`` command (a Command plugin, as ``g2s demo`` is): the installed plugins under their stage's config
key, each with its parameters (accepted values, default, description) in two columns wrapped to the terminal, then
the entry points that failed to load and why. ``--stage KEY`` loads and lists that stage's alone.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable, Iterable

from rich.markup import escape

from g2s_core.cli import EXIT_CODES, Output, columns
from g2s_core.messages import describe_field
from g2s_core.plugin import hookimpl
from g2s_core.registry import PluginInfo, installed
from g2s_core.stages import STAGES

NAME = "plugins"


@hookimpl
def g2s_command(parser: argparse.ArgumentParser) -> Callable[[argparse.Namespace], int]:
    """``g2s plugins``' arguments; its run function."""
    parser.description, parser.epilog = "List installed plugins and their parameters, and broken ones.", EXIT_CODES
    parser.add_argument("--stage", choices=[stage.key for stage in STAGES], help="only this stage")
    return run


def run(args: argparse.Namespace) -> int:
    """The plugins of every stage (or of ``--stage``), then the broken ones; exit code 0."""
    registry = installed()
    console = Output()
    lines = []
    for stage in STAGES if args.stage is None else [s for s in STAGES if s.key == args.stage]:
        lines.append(stage.key)
        for info in registry.plugins(stage.key):
            lines.append(f"  {info.name}  ({info.package})")
            if info.summary:
                lines.extend(columns([("", info.summary)], console.width, indent=4))
            lines.extend(columns([(f"{name}:", f"{accepted}, default {default}. {description}") for name, accepted,
                                  default, description in plugin_parameters(info)], console.width, indent=6))
    console.print("\n".join(lines), markup=False, highlight=False, soft_wrap=True)
    for broken in registry.broken(args.stage):
        console.print(f"[bold red]broken[/bold red] {escape(f'{broken.entry_point}  ({broken.package})')}")  # '[/x]' in them
        console.print(f"  {broken.target} failed to load: {broken.reason}", markup=False, highlight=False)
    return 0


def plugin_parameters(info: PluginInfo) -> Iterable[tuple[str, str, str, str]]:
    """``(name, accepted values, default, description)`` of each parameter, for help output."""
    for name, field in info.params_model.model_fields.items():
        default = "required" if field.is_required() else repr(field.get_default(call_default_factory=True))
        yield name, describe_field(field), default, field.description or ""
