"""The ``g2s`` command line: run a config on a mesh, and the commands that plugins add (stage ``commands``: ``g2s
batch``, ``g2s demo``, ``g2s plugins``, ``g2s presets``).

Exit codes: 0 success; 2 bad input or config (one line on stderr, no
traceback); 1 a plugin that could not be loaded, raised an exception or
returned a wrong result (one line naming the plugin and its package), memory run out (one line saying where and
under which limit) or an internal error of g2s (``--verbose`` shows the traceback); 130 interrupted (Ctrl-C, or SIGTERM from the console script);
a plugin's command may add its own (``g2s batch``: 4 when some pairs failed).
"""

from __future__ import annotations

import argparse
import json
import logging
import sys
import textwrap
import traceback
import warnings
from collections.abc import Callable, Sequence
from contextlib import nullcontext, suppress
from pathlib import Path
from typing import Any, NoReturn

from rich.console import Console
from rich.markup import escape
from rich.table import Table

from g2s_core import version
from g2s_core.config import parse_assignment, presets, resolve_config
from g2s_core.errors import G2SError, PluginFailure, out_of_memory
from g2s_core.mesh import SAMPLE_PREFIX, SUPPORTED_SUFFIXES, text_of_name
from g2s_core.model import RaisedWarning, RunResult
from g2s_core.outputs import DEFAULT_FORMATS, check_outdir, chosen_formats, writers
from g2s_core.registry import installed
from g2s_core.result_folder import interrupted, interrupts_held, stop_if_interrupted
from g2s_core.lazy import lazy_module
from g2s_core.messages import one_line
from g2s_core.summary import final_graph, metric_lines, outcome, roots_of, stage_rows

# a run needs them (and trimesh, networkx, scipy through them); listing plugins and checking a config do not
api, pipeline = lazy_module("g2s_core.api"), lazy_module("g2s_core.pipeline")

EXIT_CODES = ("exit codes: 0 success, 2 bad input or config, 1 internal error, a failed plugin (named with its package) or out of "
              "memory, 130 interrupted, 141 the reader of the output left early (| head)")
EXIT_READER_LEFT = 141
"""The exit code when the program reading g2s's standard output closes it early, as a shell reports a process that
SIGPIPE ended: neither bad input (2) nor a bug of g2s (1)."""

_NO_LOG = logging.NullHandler()  # on the root logger, it keeps logging's last resort from printing libraries' records


class Output(Console):
    """Standard output (or error) through rich, as :class:`_Stream` writes it; ending the command with
    :data:`EXIT_READER_LEFT` when its reader leaves."""

    def __init__(self, stderr: bool = False) -> None:
        super().__init__(file=_Stream("stderr" if stderr else "stdout"), emoji=False)  # rich turned a name's `:cat:` into a cat

    def on_broken_pipe(self) -> None:
        try:
            super().on_broken_pipe()  # stops writing to the closed pipe, then exits
        except SystemExit:
            raise SystemExit(EXIT_READER_LEFT) from None


class _Stream:
    """``sys.stdout`` or ``sys.stderr`` as it is at each use (pytest replaces them), writing a path that is not UTF-8 as
    the files and ``--json`` do (``o\\xff``; it was Python's ``o\\udcff``, :func:`~g2s_core.mesh.text_of_name`). A
    ``write`` or ``flush`` of standard output that fails (a full disk, the output closed) raises a :class:`G2SError`,
    bad output in one line, not an internal error (a closed pipe is left to rich's :meth:`Console.on_broken_pipe`);
    one of standard error is dropped, nothing can be said there, so that the exit code stands."""

    def __init__(self, name: str) -> None:
        self.name = name

    def __getattr__(self, name: str) -> Any:
        def checked(*text: str) -> Any:
            try:  # a closed stream is None (AttributeError): `g2s plugins >&-` was an internal error
                return getattr(getattr(sys, self.name), name)(*map(text_of_name, text))
            except (OSError, AttributeError) as exc:  # standard error's is dropped: the exit code stands
                if self.name == "stdout":
                    raise exc if isinstance(exc, BrokenPipeError) else G2SError(
                        f"cannot write to standard output ({getattr(exc, 'strerror', None) or 'it is closed'})") from None
        return checked if name in ("write", "flush") else getattr(getattr(sys, self.name), name)


__all__ = ["EXIT_CODES", "EXIT_READER_LEFT", "Output", "add_output_options", "main", "named", "output_folder", "run_command", "stage_table"]


class CommandParser(argparse.ArgumentParser):
    """argparse's parser (its commands' too), whose usage errors are one line, as every other error, with the
    exit code of bad input, and whose help and version are written as every other line (:class:`_Stream`): argparse
    dropped a failed write, and `g2s --help > /dev/full` ended with exit 0, the help lost."""

    def error(self, message: str) -> NoReturn:
        self.exit(2, f"g2s: error: {message} (see {self.prog} --help)\n")

    def _print_message(self, message: str, file: Any = None) -> None:
        try:  # help to a closed output is said so, as any line; both streams closed are both None: help went to stderr's
            print(message, end="", file=_Stream("stdout" if file is sys.stdout else "stderr"), flush=True)
        except G2SError as exc:  # not through exit(), which prints here: an exit's message with both closed came back
            print(f"g2s: error: {exc}", file=_Stream("stderr"), flush=True)
            raise SystemExit(2) from None


def named(what: str, kind: Callable[[str], Any] = str) -> Callable[[str], Any]:
    """The type of an argument naming ``what``, read as ``kind``, refusing an empty one: ``Path("")`` is the working
    folder, which was then named as the config or mesh (``.: expected a config file, got a folder``)."""
    def given(text: str) -> Any:
        if not text.strip():
            raise argparse.ArgumentTypeError(f"expected {what}, got an empty name")
        return kind(text)
    return given


# an ``-o`` argument: an unset shell variable, an empty name, would put the results in the working folder
output_folder = named("a folder", Path)


def _parser() -> tuple[argparse.ArgumentParser, dict[str, Callable[[argparse.Namespace], int] | G2SError | PluginFailure]]:
    """The parser, and the run function of each plugin's command (or why it cannot run)."""
    parser = CommandParser(prog="g2s", epilog=f"{EXIT_CODES}; a plugin's command may add its own (g2s COMMAND --help)",
                           description="Graph2Structure: extract a hierarchical structure of navigable paths from level geometry.")
    _add_main_options(parser)
    # -v is accepted after the command too; SUPPRESS keeps a -v given before it
    common = argparse.ArgumentParser(add_help=False)
    common.add_argument("-v", "--verbose", action="store_true", default=argparse.SUPPRESS,
                        help="show tracebacks of internal errors")
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")

    run = commands.add_parser("run", parents=[common], help="run a config (a preset or a YAML file) on a mesh",
                              description="Run a config (a preset or a YAML file) on a mesh.", formatter_class=argparse.RawDescriptionHelpFormatter,
                              epilog=f"{textwrap.fill(EXIT_CODES, 80)}\n\npresets:\n" + "\n".join(columns(list(presets().items()), width=80, indent=2)))
    run.add_argument("config", type=named("a preset name or a config file"), help="preset name (see `g2s presets`) or YAML config file")
    run.add_argument("mesh", type=named(f"a mesh file or {SAMPLE_PREFIX}NAME"), help=f"mesh file (.obj .glb .gltf .ply .stl .off) or {SAMPLE_PREFIX}NAME[?param=value&...] "
                     "for a level from an installed level generator (see `g2s plugins --stage levels`)")
    run.add_argument("-o", "--outdir", type=output_folder, required=True, help="folder for the results")
    add_output_options(run)

    registry, plugged = installed(), {}
    for info in registry.plugins("commands"):
        if info.name in commands.choices:  # g2s's own commands keep their names
            continue
        command = commands.add_parser(info.name, parents=[common], help=info.summary)
        try:
            plugged[info.name] = registry.call(info, parser=command)
        except (G2SError, PluginFailure) as exc:  # stops only that command, when it is run
            plugged[info.name] = exc
    return parser, plugged


def _add_main_options(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("-v", "--verbose", action="store_true", help="show tracebacks of internal errors")
    parser.add_argument("--version", action="version", version=f"g2s {version()}")


def _answer_version(argv: Sequence[str] | None) -> None:
    """Print the version and exit when ``argv`` asks for it before any command, as the full parser would, but
    before the plugins (whose commands it lists) load; anything else, errors included, is left to the full parser."""
    early = CommandParser(prog="g2s", add_help=False, allow_abbrev=False, exit_on_error=False)
    _add_main_options(early)
    early.add_argument("command", nargs=argparse.REMAINDER)
    with suppress(argparse.ArgumentError):
        early.parse_known_args(argv)


def add_output_options(command: argparse.ArgumentParser) -> None:
    """``g2s run``'s options of what a run writes and how its config is changed, for a command that runs a config as
    it does (``g2s demo``): ``--format``, ``--set``, ``--force``, ``-q``, ``--json``."""
    command.add_argument("--format", metavar="FORMATS", help=f"comma-separated output formats, overriding the config's "
                         f"outputs.formats: any installed writer ({', '.join(writers())}) (default: the config's, else "
                         f"{','.join(DEFAULT_FORMATS)})")
    command.add_argument("--set", action="append", default=[], metavar="KEY=VALUE", dest="overrides",
                         help="override a config value, e.g. --set agent.radius=0.4 --set mesh.scale=0.01 "
                         "(repeatable; the value is read as YAML)")
    command.add_argument("--force", action="store_true", help="replace results already in the output folder")
    command.add_argument("-q", "--quiet", action="store_true", help="no progress, tables or file list")
    command.add_argument("--json", action="store_true", help="print only a JSON summary on stdout")


def main(argv: Sequence[str] | None = None) -> int:
    """Run ``g2s`` with ``argv`` (default: the process's arguments) and return the exit code: 0 done, 2 bad input
    (one line, ``g2s: error: ...``), 130 interrupted, 141 the output's reader left early, 1 an internal error or a
    plugin's failure (one line, ``g2s: error: ... plugin 'X' (package 'P') failed ...``)."""
    _answer_version(argv)
    parser, plugged = _parser()
    args = parser.parse_args(argv)
    errors = Output(stderr=True)  # no emoji: `level:fire:.obj: no such mesh file` named the file with a flame
    if not args.verbose:  # a library's logged warning (matplotlib's, under a HOME it cannot write) added lines to stderr
        logging.getLogger().addHandler(_NO_LOG)
    own = {"run": lambda a: run_command(a, errors)}
    with warnings.catch_warnings(), interrupts_held(hold=False):  # numpy's warnings (a 1e300 coordinate overflowing) would add lines to the one line of stderr
        warnings.simplefilter("default" if args.verbose else "ignore", RuntimeWarning)
        try:
            stop_if_interrupted()  # a Ctrl-C that a plugin's import swallowed while the parser was built
            command = plugged.get(args.command) or own[args.command]  # a plugin's command, or why it cannot run
            if isinstance(command, Exception):
                raise command
            return command(args)
        except (G2SError, PluginFailure, MemoryError) as exc:  # the user, the named plugin's authors or more memory can fix it
            said = out_of_memory(exc) if isinstance(exc, MemoryError) else exc
            errors.print(one_line(f"g2s: error: {said}"), markup=False, highlight=False, soft_wrap=True)
            if args.verbose:
                traceback.print_exc()
            return 2 if isinstance(exc, G2SError) else 1  # a plugin's bug, or memory, is no bad input: scripts must not blame the level
        except (KeyboardInterrupt, Exception) as exc:  # anything but an interrupt is our bug: say so, keep the user's data
            if isinstance(exc, KeyboardInterrupt) or interrupted():  # trimesh swallows one as it loads, then fails (TypeError)
                errors.print("g2s: interrupted", markup=False)
                return 130
            errors.print(one_line(f"g2s: internal error: {type(exc).__name__}: {exc}"), markup=False, highlight=False, soft_wrap=True)
            if args.verbose:
                traceback.print_exc()
            else:
                errors.print("(run again with --verbose for the traceback)", markup=False)
            return 1


def run_command(args: argparse.Namespace, errors: Console, mesh_name: str | None = None) -> int:
    """``g2s run`` (and the ``demo`` command plugin's, which names its generated level ``mesh_name``): ``args`` holds
    ``config``, ``mesh``, ``outdir`` and the options of :func:`add_output_options`; ``errors`` is standard error's."""
    config_files: list[Path] = []
    if Path(args.config).suffix.lower() in SUPPORTED_SUFFIXES:  # read as YAML, it was "expected a mapping ..., got 'v 0 0 0 ...'"
        raise G2SError(f"{args.config}: expected a preset name or a config file, got a mesh file: g2s run takes the config first, then the mesh")
    config, source = resolve_config(args.config, dict(map(parse_assignment, args.overrides)), "--set", config_files)
    formats = chosen_formats(args.format, config, source, "--format")
    inputs = api.input_files(config, config_files, args.mesh)
    check_outdir(args.outdir, formats, args.force, inputs)
    registry = installed()
    plan = pipeline.plan(config, registry, source=source)
    mesh = api.open_mesh(args.mesh, config, name=mesh_name, registry=registry)
    quiet = args.quiet or args.json
    # progress on a terminal only, so that an error stays the one line on stderr that scripts can rely on; the stream's
    # own word, as rich takes FORCE_COLOR (colours, which CI logs ask for) for a terminal: a spinner came before the line
    live = not quiet and errors.is_terminal and getattr(errors.file, "isatty", bool)()
    with errors.status("running") if live else nullcontext() as spinner:
        def say(message: str) -> None:  # the step on the spinner; a warning above it as raised, before a costly step
            stop_if_interrupted()  # a Ctrl-C that a library swallowed (importing trimesh) stops the run at its next step
            if not live:
                return None
            if isinstance(message, RaisedWarning):
                return _warn(errors, message)
            spinner.update(message)
        result = api.execute(plan, registry, mesh, progress=say, config_files=config_files)
        written = api.write_result(result, args.outdir, formats, force=args.force, progress=say, registry=registry)
    if args.json:  # through rich as all other output, so that a reader that leaves early (`| head`) ends it as quietly
        Output().out(json.dumps(_summary(result, args.outdir, formats, written), indent=1, sort_keys=True), highlight=False)
        return 0
    if mesh.cleaning and not quiet:  # after the run, so that an error stays the one line on stderr
        counts = ", ".join(f"{count} {what.replace('_', ' ')}" for what, count in mesh.cleaning.items())
        errors.print(f"cleaning: {counts}", markup=False, highlight=False, soft_wrap=True)
    for warning in () if live else result.warnings:  # else they were shown above the spinner
        _warn(errors, warning)
    if not args.quiet:
        console = Output()
        console.print(stage_table(result, title=mesh.name))
        if said := outcome(result):
            if count := len(result.warnings):  # they stand on stderr above the stage table, where a new user reads past them
                said += f"; {count} warning{'s' * (count > 1)} above"
            console.print(f"{mesh.name}: {said}", markup=False, highlight=False, soft_wrap=True)
        for label, measures in metric_lines(result):
            console.print(f"{label}: {measures}", markup=False, highlight=False, soft_wrap=True)
        for path in written:
            console.print(f"wrote {path}", markup=False, highlight=False, soft_wrap=True)
    return 0


def _warn(errors: Console, message: str) -> None:
    errors.print(f"g2s: warning: {message}", markup=False, highlight=False, soft_wrap=True)


def _summary(result: RunResult, outdir: Path, formats: Sequence[str], written: Sequence[Path]) -> dict[str, Any]:
    """The --json summary; paths as text, as the mesh's name is (a folder whose name is not UTF-8 was a lone
    surrogate, ``"out\\udcff"``, that strict JSON readers refuse)."""
    stage, graph = final_graph(result)
    return {
        "mesh": result.mesh_name,
        "mesh_sha256": result.mesh_sha256,
        "outdir": text_of_name(str(outdir)),
        "formats": list(formats),
        "files": [text_of_name(str(p)) for p in written],
        "stages": [vars(s) for s in result.stages],
        "total_seconds": result.total_seconds,
        "final": {
            "stage": stage,
            "nodes": None if graph is None else graph.number_of_nodes(),
            "edges": None if graph is None else graph.number_of_edges(),
            "roots": roots_of(graph),
            "terminals": None if result.terminals is None else len(result.terminals.without_waypoints),
            "analysis": list(result.analysis),
        },
        "metrics": result.metrics,
        "warnings": result.warnings,
    }


def stage_table(result: RunResult, title: str = "") -> Table:
    """The per-stage table in the paper's form: time in ms, node/edge/terminal counts."""
    table = Table(title=escape(title) or None)  # a level named `[red]x` was titled `x`
    for column in ("step", "", "t (ms)", "#N", "#E"):
        table.add_column(column, justify="left" if column in ("step", "") else "right")
    for row in stage_rows(result.stages):
        table.add_row(*row, style="bold" if row[0] == "total" else None)
    return table


def columns(rows: Sequence[tuple[str, str]], width: int, indent: int) -> list[str]:
    """``(term, text)`` rows as two columns, ``text`` wrapped to ``width`` under itself."""
    left = indent + max((len(term) + 2 for term, _ in rows if term), default=0)
    text_width = max(width - left, 30)
    lines = []
    for term, text in rows:
        wrapped = textwrap.wrap(text, text_width) or [""]
        lines.append((" " * indent + term).ljust(left) + wrapped[0])
        lines.extend(" " * left + line for line in wrapped[1:])
    return lines


if __name__ == "__main__":
    sys.exit(main())
