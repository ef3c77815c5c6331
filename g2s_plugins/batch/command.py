"""run configs over many levels on a process pool or a Dask cluster, with a summary table

The ``g2s batch`` command (a Command plugin, as a third-party package would
add one): its arguments, the progress bar and the totals; the batch itself is
:func:`g2s_plugins.batch.runner.run_batch`.
"""

from __future__ import annotations

import argparse
import itertools
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path

from rich.console import Console
from rich.progress import BarColumn, MofNCompleteColumn, TextColumn
from rich.progress import Progress as RichProgress

from g2s_core.cli import Output, named, output_folder
from g2s_core.config import presets
from g2s_core.errors import G2SError
from g2s_core.mesh import SAMPLE_PREFIX, SUPPORTED_SUFFIXES
from g2s_core.messages import one_line
from g2s_core.outputs import parse_formats
from g2s_core.plugin import hookimpl
from g2s_core.registry import installed
from g2s_plugins.batch.runner import INSTALL_HINT, Progress, missing_extra, run_batch

NAME = "batch"


@hookimpl
def g2s_command(parser: argparse.ArgumentParser) -> Callable[[argparse.Namespace], int]:
    """``g2s batch``'s arguments; its run function."""
    parser.usage = ("g2s batch CONFIG [CONFIG ...] INPUT [INPUT ...] -o OUTDIR [--executor NAME] "
                    "[--workers N] [--scheduler ADDRESS] [--evaluate NAMES] [--format FORMATS] [--force] [-q] [-v]")
    parser.description = (
        "Run every config on every level: one result folder per (config, level) pair, as `g2s run` "
        "writes it, in OUTDIR/CONFIG/LEVEL/, and OUTDIR/summary.parquet and summary.csv with one row per pair "
        "(see docs/batch.md). A level that fails is recorded and the batch goes on; a re-run skips the pairs "
        f"already finished for the same config and mesh. {INSTALL_HINT}.")
    parser.epilog = ("exit codes: 0 every pair ran, 4 some pairs failed (see the summary's error column), "
                     "2 bad config or input, 130 interrupted (finished pairs are kept), 141 the reader of the output left early, "
                     "1 internal error of g2s, or a plugin failed outside the pairs (named with its package)")
    parser.add_argument("items", nargs="+", metavar="CONFIG|INPUT", type=named("a preset, a config file or a level"),
                        help="configs (the leading preset names and .yaml/.yml files), then levels: mesh files, folders "
                        f"(searched recursively for {' '.join(SUPPORTED_SUFFIXES)}), glob patterns, or "
                        f"{SAMPLE_PREFIX}NAME[?param=value&...]")
    parser.add_argument("-o", "--outdir", type=output_folder, required=True, help="folder of the batch's results")
    parser.add_argument("--executor", metavar="NAME", default="local", help="an executor plugin (`g2s plugins --stage "
                        "executors`): local, a process pool (default); dask, a Dask cluster; serial, one by one here")
    parser.add_argument("--workers", type=int, metavar="N",
                        help="processes of the pool or of the Dask LocalCluster (default: the CPU count)")
    parser.add_argument("--scheduler", metavar="ADDRESS",
                        help="with --executor dask: the scheduler to use, e.g. tcp://host:8786 "
                        "(default: start a LocalCluster)")
    parser.add_argument("--evaluate", metavar="NAMES", help="evaluator plugins added to every config, "
                        "e.g. traffic: coverage and flow agreement in metric.* columns (costly: docs/batch.md)")
    parser.add_argument("--format", metavar="FORMATS", help="comma-separated output formats for every pair "
                        "(default: each config's outputs.formats)")
    parser.add_argument("--force", action="store_true", help="recompute the pairs already finished")
    parser.add_argument("-q", "--quiet", action="store_true", help="no progress bar or totals")
    return batch


def batch(args: argparse.Namespace) -> int:
    """``g2s batch``: the batch's summary, a line per failed pair on stderr; exit code 4 when some pairs failed."""
    errors = Output(stderr=True)  # no emoji: a level's `:cat:` was a cat
    names = presets()
    configs = list(itertools.takewhile(
        lambda item: Path(item).suffix.lower() in (".yaml", ".yml") or item in names, args.items))
    inputs = args.items[len(configs):]
    if not configs:  # named, as a misspelt preset is the likely cause
        raise G2SError(f"{args.items[0]}: expected a preset name or a .yaml/.yml config first, then one or more levels "
                       f"(presets: {', '.join(names)})")
    if not inputs:
        raise G2SError(f"batch: expected one or more levels after the configs ({' '.join(configs)})")
    if args.workers is not None and args.workers < 1:
        raise G2SError(f"--workers: expected an integer >= 1, got {args.workers}")
    registry = installed()
    evaluators = [name.strip() for name in (args.evaluate or "").split(",") if name.strip()]
    twice = next((name for name in evaluators if evaluators.count(name) > 1), None)
    # `--evaluate "$EVALUATORS"` of an unset variable ran without them; a name twice was "two plugins write values named"
    if args.evaluate is not None and (not evaluators or twice):
        raise G2SError(f"--evaluate: {f'{twice} is given twice' if twice else 'no evaluator given'} "
                       f"(expected some of: {', '.join(p.name for p in registry.plugins('evaluators'))})")
    # named as the options the user gave (run_batch names its own parameters: "executor", "evaluators", "params.workers")
    executor = registry.get("executors", args.executor, key="--executor")
    for option in ("workers", "scheduler"):
        if getattr(args, option) is not None and option not in executor.params_model.model_fields:
            raise G2SError(f"--{option}: the {executor.name} executor takes no {option} (see g2s plugins --stage executors)")
    for name in evaluators:
        registry.get("evaluators", name, key="--evaluate")
    if args.format is not None:  # run_batch would name its own parameter, "formats"
        parse_formats(args.format, "--format", registry)
    with missing_extra(), _progress_bar(errors, args.quiet) as show:
        summary = run_batch(configs, inputs, args.outdir, args.executor, workers=args.workers,
                            scheduler=args.scheduler, evaluators=evaluators, formats=args.format, force=args.force,
                            progress=show)
    failed = summary[summary["status"] != "ok"]
    for row in failed.itertuples():
        errors.print(one_line(f"g2s: {row.config} on {row.level} failed: {row.error}"), markup=False, highlight=False,
                     soft_wrap=True)
    if not args.quiet:
        reused = int(summary["reused"].sum())
        Output().print(f"{len(summary)} pairs: {len(summary) - len(failed)} ok ({reused} already finished), "
                        f"{len(failed)} failed; summary in {args.outdir / 'summary.csv'} and summary.parquet",
                        markup=False, highlight=False, soft_wrap=True)
    return 4 if len(failed) else 0


@contextmanager
def _progress_bar(errors: Console, quiet: bool) -> Iterator[Callable[[Progress], None]]:
    """A progress bar on stderr (done, failed, remaining, levels per minute), when stderr is a terminal."""
    if quiet or not errors.is_terminal:
        yield lambda _counts: None
        return
    columns = (TextColumn("batch"), BarColumn(), MofNCompleteColumn(), TextColumn("{task.fields[counts]}"))
    with RichProgress(*columns, console=errors) as bar:
        task = bar.add_task("batch", total=None, counts="starting")

        def show(counts: Progress) -> None:
            bar.update(task, total=counts.total, completed=counts.done, counts=(
                f"failed {counts.failed}, remaining {counts.total - counts.done}, "
                f"{counts.per_minute:.1f} levels/min"))

        yield show
