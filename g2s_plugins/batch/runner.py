"""Batch runs: configs over many levels, on any executor plugin, with one summary table.

This module plans the pairs, resumes, and sums the rows up; an executor plugin
(stage ``executors``: ``local`` process pool, ``dask`` cluster, ``serial``, or
a third-party one) only decides where each pair runs. Every (config, level)
pair is run by :func:`run_pair`, the same function on
every executor; it opens the level, runs it and writes its result folder with
the functions ``g2s run`` uses (:func:`g2s_core.api.open_mesh`,
:func:`~g2s_core.api.execute`, :func:`~g2s_core.api.write_result`), then
records the pair's summary row.
A pair that fails is recorded with its error and the batch goes on.

Layout of ``OUTDIR``::

    OUTDIR/CONFIG/LEVEL/...              the run's result files, as `g2s run -o` writes them
    OUTDIR/.g2s-batch/CONFIG/LEVEL.json  the pair's summary row, written once its folder is complete
    OUTDIR/summary.parquet, summary.csv  one row per pair (see :data:`COLUMNS`)

A row file is what makes a pair finished: a re-run skips the pairs whose row
says ``ok`` for the same config and mesh hash and whose result files are all
there (resume), unless ``force``. Interrupting a batch (Ctrl-C) closes the
executor's iterator (the process pool lets its running pairs finish, pending
ones are dropped) and writes the summary of the finished pairs.

Needs the ``batch`` extra (``pip install 'graph2structure[batch]'``): pandas,
pyarrow and dask.distributed.
"""

from __future__ import annotations

import functools
import glob
import hashlib
import json
import math
import os
import re
import time
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from contextlib import closing, contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from g2s_core import DISTRIBUTION
from g2s_core.config import find_config, load_raw_config, parse_config
from g2s_core.errors import G2SError, PluginFailure, out_of_memory
from g2s_core.input_files import check_regular_file, given_path
from g2s_core.lazy import lazy_module
from g2s_core.mesh import SAMPLE_PREFIX, SUPPORTED_SUFFIXES, text_of_name
from g2s_core.messages import show
from g2s_core.model import RunResult
from g2s_core.outputs import chosen_formats, parse_formats, result_files
from g2s_core.registry import installed
from g2s_core.result_folder import check_writable, stop_if_interrupted
from g2s_core.stages import PIPELINE

if TYPE_CHECKING:
    import pandas as pd

    from g2s_core import api
else:  # a pair's run needs it (and trimesh, networkx, scipy through it); `g2s --help` lists the command without. The
    # pipeline is taken through it (api.pipeline): the API's import names the networkx settings of the environment that
    # networkx refuses as it loads (NETWORKX_BACKEND_PRIORITY=nosuch, exit 2), which the pipeline's own import did not
    api = lazy_module("g2s_core.api")

RECORDS = ".g2s-batch"
"""The folder of ``OUTDIR`` holding one row file per finished pair."""

SUMMARIES = ("summary.parquet", "summary.csv")
"""The summary files of ``OUTDIR``, beside its folder of each config's results."""

INSTALL_HINT = (f"g2s batch needs the 'batch' extra: pip install '{DISTRIBUTION}[batch]' "
                "(pandas, pyarrow, dask.distributed; from a clone: make setup)")

COLUMNS: tuple[str, ...] = (
    "config", "level", "input", "folder", "status", "error", "reused", "mesh_sha256", "config_sha256",
    "seconds_load", *(f"seconds_{s.key}" for s in PIPELINE), "seconds_write", "seconds_total",
    *(f"{what}_{s.key}" for s in PIPELINE if s.key in ("graph", "steiner", "simplify") for what in ("nodes", "edges")),
    "terminals", "openings", "roots", "structure_length", "warnings",
)
"""The summary's fixed columns, in order. Then, per analyzer key K: ``K_max``, ``K_mean``, ``K_top_node``,
for analyzers with records (chokepoints, regions) the columns of :func:`_feature_columns`, and per
evaluator key E and measure M ``metric.E.M`` (:data:`METRIC_PREFIX`); sorted by name.

``seconds_*`` are wall seconds (``seconds_total``: the whole pair, opening to
writing); ``nodes_*``/``edges_*`` the sizes of the initial graph, the Steiner
forest and the simplified structure; ``structure_length`` the sum of the
structure's edge lengths, metres; ``warnings`` how many the run gave.
"""


METRIC_PREFIX = "metric."
"""Start of the evaluators' columns: ``metric.<evaluator key>.<measure>``, empty where not computed."""


@dataclass(frozen=True)
class Pair:
    """One config on one level: what :func:`run_pair` needs, picklable and free of local state but paths.

    Attributes:
        config: the config's name in the batch (its file stem).
        raw_config: the config as read, ``extends:`` merged (validated by the worker).
        source: the config file, for messages.
        formats: the output formats.
        config_sha256: hash of the config and formats: a finished pair is reused only for the same one.
        level: the level's name in the batch.
        spec: the mesh file or ``sample:`` spec.
        folder: the pair's result folder.
        record: the pair's row file.
        force: recompute even when the pair is finished.
    """

    config: str
    raw_config: dict[str, Any]
    source: str
    formats: tuple[str, ...]
    config_sha256: str
    level: str
    spec: str
    folder: str
    record: str
    force: bool = False


def run_pair(pair: Pair) -> dict[str, Any]:
    """Run one pair, write its result folder and its row file; its summary row.

    A finished pair (see the module docs) is not run again: its earlier row is
    returned with ``reused`` set. Errors do not propagate: the row says
    ``failed`` with the one-line message ``g2s run`` would print.
    """
    start = time.perf_counter()
    row = _first_columns(pair)
    try:
        registry = installed()
        config = parse_config(pair.raw_config, source=pair.source)
        plan = api.pipeline.plan(config, registry, source=pair.source)
        mesh = api.open_mesh(pair.spec, config, registry=registry)
        row.update(mesh_sha256=mesh.sha256, seconds_load=time.perf_counter() - start)
        earlier = _finished_row(pair, mesh.sha256)
        if earlier is not None:
            return {**earlier, "reused": True}
        result = api.execute(plan, registry, mesh)
        api.write_result(result, pair.folder, pair.formats, force=True, registry=registry)
        row.update(result_row(result))
        row["seconds_write"] = time.perf_counter() - start - row["seconds_load"] - result.total_seconds
    except (G2SError, PluginFailure) as exc:
        row.update(status="failed", error=str(exc))
    except MemoryError as exc:  # under a memory limit: said where it ran out, as `g2s run` says it
        row.update(status="failed", error=str(out_of_memory(exc)))
    except Exception as exc:  # an internal error of g2s on this level: recorded, the batch goes on
        row.update(status="failed", error=f"internal error: {type(exc).__name__}: {exc}")
    row["seconds_total"] = time.perf_counter() - start
    _write_json(Path(pair.record), row)
    return row


def _first_columns(pair: Pair, error: str | None = None) -> dict[str, Any]:
    """The row's columns that say which pair it is, and whether it failed (``error``)."""
    return {"config": pair.config, "level": pair.level, "input": pair.spec, "folder": pair.folder,
            "status": "ok" if error is None else "failed", "error": error, "reused": False,
            "config_sha256": pair.config_sha256}


def lost_pair(pair: Pair, reason: str) -> dict[str, Any]:
    """The row (written to its row file) of a pair whose process died as it ran, which the executor tells by ``reason``
    (what died: "its worker process died as it ran")."""
    row = _first_columns(pair, error=f"{pair.spec}: {reason} (killed, e.g. by the system for want of memory, or a crash in "
                         "native code); the batch's other pairs ran")
    _write_json(Path(pair.record), row)
    return row


def result_row(result: RunResult) -> dict[str, Any]:
    """A run's summary values (the columns of :data:`COLUMNS` after ``seconds_load``, and the analyzers')."""
    row: dict[str, Any] = {}
    for stage in PIPELINE:
        stats = result.stage(stage.timing)
        row[f"seconds_{stage.key}"] = None if stats is None else stats.seconds
        if stage.key in ("graph", "steiner", "simplify"):
            row[f"nodes_{stage.key}"] = None if stats is None else stats.nodes
            row[f"edges_{stage.key}"] = None if stats is None else stats.edges
    terminals = result.terminals
    row["terminals"] = None if terminals is None else len(terminals.without_waypoints)
    row["openings"] = None if terminals is None else len(terminals.openings)
    structure = result.structure
    row["roots"] = None if structure is None else len(structure.graph["roots"])
    row["structure_length"] = None if structure is None else float(
        math.fsum(w for _, _, w in structure.edges(data="weight", default=0.0)))
    row["warnings"] = len(result.warnings)
    for key, values in result.analysis.items():
        top = max(sorted(values), key=lambda node: values[node]) if values else None
        row[f"{key}_max"] = None if top is None else values[top]
        row[f"{key}_mean"] = math.fsum(values.values()) / len(values) if values else None
        row[f"{key}_top_node"] = top
    for key, features in result.features.items():
        row.update(_feature_columns(key, features))
    for key, measures in result.metrics.items():
        row.update({f"{METRIC_PREFIX}{key}.{name}": value for name, value in measures.items()})
    return row


def _feature_columns(key: str, features: dict[str, Any]) -> dict[str, Any]:
    """An analyzer's records summed up (e.g. ``chokepoints``, ``regions``): for each list of records F,
    ``K_count`` (``K_F_count`` when F is not the analyzer key K), the highest ``score`` and that record's
    ``width`` (``..._top_score``, ``..._top_width``), the largest ``area`` (``..._largest_area``)."""
    row: dict[str, Any] = {}
    for name, records in features.items():
        if not isinstance(records, list):
            continue
        prefix = key if name == key else f"{key}_{name}"
        row[f"{prefix}_count"] = len(records)
        scored = [r for r in records if isinstance(r, dict) and "score" in r]
        if scored:
            top = max(scored, key=lambda record: record["score"])
            row[f"{prefix}_top_score"] = top["score"]
            row[f"{prefix}_top_width"] = top.get("width")
        areas = [r["area"] for r in records if isinstance(r, dict) and "area" in r]
        if areas:
            row[f"{prefix}_largest_area"] = max(areas)
    return row


def _finished_row(pair: Pair, mesh_sha256: str) -> dict[str, Any] | None:
    """The pair's earlier row when it is finished for this config and mesh, else ``None``."""
    if pair.force:
        return None
    try:
        earlier = json.loads(Path(pair.record).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    same = earlier.get("config_sha256") == pair.config_sha256 and earlier.get("mesh_sha256") == mesh_sha256
    return earlier if same and _complete(pair) and earlier.get("status") == "ok" else None


def _complete(pair: Pair) -> bool:
    """Whether every result file of the pair's formats is in its folder."""
    files = result_files()
    return all((Path(pair.folder) / name).is_file() for fmt in pair.formats for name in files.get(fmt, ()))


def _still_there(row: dict[str, Any], pair: Pair) -> dict[str, Any]:
    """``row``, or, when it says ``ok`` but the pair's result files are gone (the batch's folder removed while it ran,
    with the pairs finished before), the row failed saying so: the summary claimed ``ok`` for files that were gone."""
    if row.get("status") != "ok" or _complete(pair):
        return row
    return {**row, "status": "failed", "error": f"{pair.folder}: its results were removed after the pair finished (the "
            "batch's folder removed while it ran?); run the batch again to compute them"}


def _write_json(path: Path, data: dict[str, Any]) -> None:
    """Write ``data`` (its texts as :func:`_as_text` makes them) so that the file is either absent, the old one, or
    complete."""
    path.parent.mkdir(parents=True, exist_ok=True)
    temporary = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    temporary.write_text(json.dumps(_as_text(data), sort_keys=True, allow_nan=True), encoding="utf-8")
    os.replace(temporary, path)


def _as_text(row: Mapping[str, Any]) -> dict[str, Any]:
    """``row`` with each text as :func:`~g2s_core.mesh.text_of_name` makes it: a name or path that is not UTF-8 (a
    level's, a config's, the batch's folder, in the paths and messages) as text that JSON, CSV and Parquet can hold (the
    row file held ``"out\\udcff"``, a lone surrogate strict JSON readers refuse)."""
    return {key: text_of_name(value) if isinstance(value, str) else value for key, value in row.items()}


# --- the pairs of a batch -----------------------------------------------------


def expand_inputs(inputs: Sequence[str], exclude: Path | None = None) -> list[tuple[str, str]]:
    """``(level name, mesh spec)`` for every level of ``inputs``, in input order, files sorted.

    An input is a mesh file (taken whatever its extension: a wrong one fails
    its pairs), a folder (its files with a known mesh extension, recursively,
    except those under ``exclude``), a glob pattern, or a ``sample:`` spec.
    A level's name is its file stem (its path without extension, relative to
    its folder, for a folder's files) or the spec with other characters than
    letters, digits, ``.`` ``_`` ``-`` turned to ``_``.

    Raises:
        G2SError: an input matches nothing, two levels get the same name, a level's name cannot name its results
            folder (:func:`_check_folder_name`), or a folder under an input folder cannot be read.
    """
    levels: dict[str, str] = {}

    def add(name: str, spec: str, origin: str) -> None:
        _check_folder_name(name, "level", origin)
        # one file by two spellings (`slab.obj ./lv/../slab.obj`) runs once, as one spelling given twice does: it was
        # refused as two files of one level name, "rename one of the files"
        if name in levels and os.path.realpath(levels[name]) != os.path.realpath(spec):
            raise G2SError(f"{origin}: level name {name!r} is also that of {levels[name]}; rename one of the files")
        levels.setdefault(name, spec)  # the first spelling is the one the summary shows

    # os.path.realpath, not Path.resolve, which raises RuntimeError on a link to itself
    excluded = None if exclude is None else os.path.realpath(exclude)
    for item in inputs:
        path = Path(item)
        if item.startswith(SAMPLE_PREFIX):
            add(re.sub(r"[^A-Za-z0-9._-]+", "_", item[len(SAMPLE_PREFIX):]).strip("_"), item, item)
        elif path.is_dir():
            found = [p for p in _mesh_files(path)
                     if excluded is None or not Path(os.path.realpath(p)).is_relative_to(excluded)]
            if not found:
                raise G2SError(f"{item}: no mesh files in this folder (expected {', '.join(SUPPORTED_SUFFIXES)})")
            for file in found:
                add(file.relative_to(path).with_suffix("").as_posix(), str(file), item)
        elif path.exists():
            add(path.stem, item, item)
        elif glob.has_magic(item):
            matches = sorted(glob.glob(item, recursive=True))
            files = [Path(m) for m in matches if Path(m).is_file()]
            if not files:
                raise G2SError(f"{item}: the pattern matches no files")
            for file in files:
                add(file.stem, str(file), item)
        elif os.path.lexists(item):  # a link to itself or to nothing: said as g2s run says it
            check_regular_file(item, "mesh file")
        else:
            raise G2SError(f"{item}: no such mesh file, folder or pattern (or {SAMPLE_PREFIX}NAME)")
    return [(name, spec) for name, spec in levels.items()]


def _check_folder_name(name: str, what: str, origin: str, taken: Sequence[str] = ()) -> None:
    """Refuse a config's or level's name that cannot name its results folder: ``..`` (a file ``...obj``, a config
    ``...yaml``) put them beside ``OUTDIR`` or a config's folder, ``.`` into it, and a config named ``summary.csv``
    (``summary.parquet``, ``.g2s-batch``) took the name of the batch's own file (an internal error after every run).
    A folder's level is named by its path in the folder, so each part of it counts (``act1/...obj`` is ``act1/..``)."""
    if not {".", ".."}.isdisjoint(name.split("/")) or name in taken:
        raise G2SError(f"{origin}: {what} name {name!r} cannot name the folder of its results (not "
                       f"{', '.join(repr(n) for n in ('.', '..', *taken))}); rename the file")


def _mesh_files(folder: Path) -> Iterator[Path]:
    """Every entry under ``folder`` named like a mesh file that is not a folder: a link to nothing, a FIFO or a device
    named ``level.obj`` is a level too, whose pairs fail with the reader's message instead of leaving it out unsaid.

    Raises:
        G2SError: ``folder`` or a folder under it cannot be read (``rglob`` leaves its levels out without a word).
    """
    entries = sorted(folder.rglob("*"))
    if unread := next((p for p in (folder, *entries) if p.is_dir() and not os.access(p, os.R_OK | os.X_OK)), None):
        raise G2SError(f"{unread}: cannot read this folder (permission denied): its levels would be left out")
    return iter(p for p in entries if p.suffix.lower() in SUPPORTED_SUFFIXES and not p.is_dir())


def with_evaluators(raw: dict[str, Any], names: Sequence[str]) -> dict[str, Any]:
    """The raw config with each evaluator of ``names`` (``g2s batch --evaluate``; default parameters) added to its
    ``evaluators:`` unless one of that key is listed already (a malformed section is left for validation to report)."""
    listed = raw.get("evaluators") or []
    if not isinstance(listed, list):
        return raw
    keys = {e.get("key") or e.get("plugin") for e in listed if isinstance(e, dict)}
    return {**raw, "evaluators": listed + [{"plugin": name} for name in names if name not in keys]}


def make_pairs(
    configs: Sequence[str | Path],
    inputs: Sequence[str],
    outdir: Path,
    formats: str | Sequence[str] | None = None,
    force: bool = False,
    evaluators: Sequence[str] = (),
) -> list[Pair]:
    """Every (config, level) pair of a batch, configs outer; configs and inputs are checked here.

    Raises:
        ConfigError, G2SError: a config does not validate, two configs (other
            than one file given twice) share a file stem, an input matches nothing, or ``outdir`` cannot take a batch.
    """
    _check_outdir(outdir)
    levels = expand_inputs(inputs, exclude=outdir)
    registry = installed()
    pairs: list[Pair] = []
    seen: dict[str, tuple[str, str]] = {}
    for config_path in configs:
        source = str(config_path)
        name = Path(config_path).stem
        _check_folder_name(name, "config", source, taken=(RECORDS, *SUMMARIES))
        found = find_config(config_path)
        real = os.path.realpath(found)
        if name in seen:
            if seen[name][1] == real:  # the same config twice, as a level given twice: its pairs once
                continue
            raise G2SError(f"{source}: config name {name!r} is also that of {seen[name][0]}; rename one of the files")
        seen[name] = source, real
        raw = with_evaluators(load_raw_config(found), evaluators)
        config = parse_config(raw, source=source)
        api.pipeline.plan(config, registry, source=source)
        chosen = tuple(chosen_formats(formats, config, source))
        digest = hashlib.sha256(json.dumps([config.model_dump(mode="json"), chosen], sort_keys=True).encode()).hexdigest()
        for level, spec in levels:
            pairs.append(Pair(
                name, raw, source, chosen, digest, level, spec,
                folder=str(outdir / name / level), record=str(outdir / RECORDS / name / f"{level}.json"), force=force,
            ))
    return pairs


def _check_outdir(outdir: Path) -> None:
    """A batch writes into a new or empty folder, or into one an earlier batch wrote; one it can create or write."""
    check_writable(outdir)
    if outdir.is_dir() and any(outdir.iterdir()) and not (outdir / RECORDS).is_dir():
        raise G2SError(f"{outdir}: holds files that are not a g2s batch's; choose a new or empty folder")


# --- progress -----------------------------------------------------------------


class Progress:
    """What a batch reports as pairs finish: counts and rate; ``update(row)`` after each pair."""

    def __init__(self, total: int) -> None:
        self.total, self.done, self.failed, self.started = total, 0, 0, time.perf_counter()

    def update(self, row: dict[str, Any]) -> None:
        self.done += 1
        self.failed += row["status"] != "ok"

    @property
    def per_minute(self) -> float:
        elapsed = time.perf_counter() - self.started
        return 60.0 * self.done / elapsed if elapsed > 0 else 0.0


# --- the batch ----------------------------------------------------------------


def run_batch(
    configs: Sequence[str | Path],
    inputs: Sequence[str | Path],
    outdir: str | Path,
    executor: str = "local",
    *,
    workers: int | None = None,
    scheduler: str | None = None,
    executor_params: Mapping[str, Any] | None = None,
    evaluators: Sequence[str] = (),
    formats: str | Sequence[str] | None = None,
    force: bool = False,
    progress: Callable[[Progress], None] | None = None,
) -> pd.DataFrame:
    """Run every config on every level of ``inputs``; the summary, one row per pair.

    Args:
        configs: preset names or YAML config files.
        inputs: mesh files, folders (searched recursively), glob patterns or
            ``sample:NAME?param=value&...`` specs.
        outdir: the batch's folder (see the module docs for its layout).
        executor: an installed executor plugin (``g2s plugins --stage
            executors``): ``"local"`` (a process pool of ``workers``, default
            the CPU count), ``"dask"`` (the dask.distributed scheduler at
            ``scheduler``, else a LocalCluster of ``workers`` processes) or
            ``"serial"``.
        workers, scheduler: the executor's parameters of these names, when given.
        executor_params: any other parameters of the executor.
        evaluators: evaluator plugins added, with their default parameters, to
            every config that does not list them already (e.g. ``["traffic"]``).
        formats: output formats for every pair (default: each config's).
        force: recompute finished pairs.
        progress: called with the counts after each pair.

    Returns:
        The summary (also written to ``outdir/summary.parquet`` and
        ``summary.csv``): :data:`COLUMNS`, then each analyzer's and
        evaluator's columns; rows in config order, then level order. After
        Ctrl-C the files hold the pairs finished so far, then
        ``KeyboardInterrupt`` propagates.

    Raises:
        ConfigError, G2SError: bad configs, inputs, formats or executor parameters, or an argument of the wrong type
            (``configs="map_analysis"``, a text where a list is expected), before any pair runs.
        OutOfMemory: the memory ran out as the summary was made or written (the pairs' results are kept).
    """
    import pandas as pd  # noqa: F401  (the extra is needed before any work starts)

    configs = _listed(configs, "configs", "preset names or config files", "a preset name or a config file")
    inputs = _listed(inputs, "inputs", f"mesh files, folders, patterns or {SAMPLE_PREFIX}NAME",
                     f"a mesh file, a folder, a pattern or {SAMPLE_PREFIX}NAME")
    outdir = given_path(outdir, "outdir", "a folder")
    evaluators = _listed(evaluators, "evaluators", "evaluator names")
    if formats is not None:
        parse_formats(formats, "formats")
    if progress is not None and not callable(progress):
        raise G2SError(f"progress: expected a function of one argument or None, got {type(progress).__name__}")
    registry = installed()
    chosen = registry.get("executors", executor, key="executor")
    given = {"workers": workers, "scheduler": scheduler}
    options = {**(executor_params or {}), **{k: v for k, v in given.items() if v is not None}}
    params = registry.validate_params(chosen, options, f"executor {executor!r} params")
    for name in evaluators:
        registry.get("evaluators", name, key="evaluators")
    pairs = make_pairs(configs, [str(i) for i in inputs], outdir, formats, force, evaluators)
    counts = Progress(len(pairs))
    rows: dict[tuple[str, str], dict[str, Any]] = {}
    started = time.time()
    try:
        with closing(registry.call(chosen, function=run_pair, items=pairs, params=params, lost=lost_pair)) as finished:
            for row in finished:
                stop_if_interrupted()  # a Ctrl-C that a library swallowed here (importing trimesh) stops the batch
                rows[row["config"], row["level"]] = row
                counts.update(row)
                if progress is not None:
                    progress(counts)
    finally:
        for pair in pairs:  # after Ctrl-C: the pairs that finished while the executor stopped
            if (pair.config, pair.level) not in rows and _written_since(Path(pair.record), started):
                rows[pair.config, pair.level] = json.loads(Path(pair.record).read_text(encoding="utf-8"))
        try:
            summary = _summary([_still_there(rows[p.config, p.level], p) for p in pairs if (p.config, p.level) in rows])
            if rows:
                write_summary(summary, outdir)
        except MemoryError as exc:  # pyarrow's allocator (pandas' text columns) under `ulimit -v 700000`, every pair written
            raise out_of_memory(exc, f" making the summary in {outdir} (the pairs' results are kept: run the batch "
                                     "again to make it)") from exc
    return summary


def _listed(given: Any, what: str, each: str, one: str | None = None) -> list[Any]:
    """The Python API's argument ``what``, a list of ``each``, as a list, each item a path or a name (``one``) when
    ``one`` is given, and then not empty (``run_batch([], ...)`` returned an empty summary, nothing run or said, where
    ``g2s batch`` asks for a config and a level); a text refused, which Python reads letter by letter
    (``configs="graph_only"`` ran the config ``g``: ``g: no such config file or preset``)."""
    if isinstance(given, (str, bytes, os.PathLike)) or not isinstance(given, Iterable):
        got = f"the text {show(given)}" if isinstance(given, str) else type(given).__name__
        raise G2SError(f"{what}: expected a list of {each}, got {got}")
    if not (items := list(given)) and one is not None:
        raise G2SError(f"{what}: expected a list of {each}, got an empty list")
    for index, item in enumerate(items):
        if one is not None:
            given_path(item, f"{what}[{index}]", one)  # a dict or a trimesh.Trimesh was pathlib's TypeError, 5 the file '5'
    return items


def _written_since(path: Path, moment: float) -> bool:
    try:
        return path.stat().st_mtime >= moment
    except OSError:
        return False


def _summary(rows: Iterable[dict[str, Any]]) -> pd.DataFrame:
    import pandas as pd

    frame = pd.DataFrame([_as_text(row) for row in rows])
    extra = sorted(c for c in frame.columns if c not in COLUMNS)
    frame = frame.reindex(columns=[*COLUMNS, *extra])
    for column in frame.columns:
        kind = _column_type(column)
        if kind is not None:
            frame[column] = frame[column].astype(kind)
    return frame


_INTEGER_COLUMNS = frozenset(c for c in COLUMNS if c.startswith(("nodes_", "edges_"))) | {
    "terminals", "openings", "roots", "warnings"}


def _column_type(column: str) -> str | None:
    """The summary column's pandas type (``None``: the text columns, kept as they are).

    The fixed columns are typed by name, the others by their form: an analyzer
    key is the user's (``key: edges`` gives ``edges_max``, a float, not one of
    the ``edges_*`` counts), and an evaluator's measure names are its own.
    """
    if column in COLUMNS:
        if column == "reused":
            return "bool"
        if column in _INTEGER_COLUMNS:
            return "Int64"
        return "float64" if column.startswith("seconds_") or column == "structure_length" else None
    if column.startswith(METRIC_PREFIX):
        return "float64"
    return "Int64" if column.endswith(("_top_node", "_count")) else "float64"


def write_summary(summary: pd.DataFrame, outdir: Path) -> list[Path]:
    """``summary.parquet`` and ``summary.csv`` in ``outdir``, both written before either replaces the earlier one.

    Raises:
        G2SError: the storage failed (disk full, file size limit); the earlier summary files are kept and no
            temporary file is left.
    """
    files = {outdir / name: (outdir / f".{name}.tmp", write) for name, write in zip(
        SUMMARIES, (functools.partial(_to_parquet, summary), summary.to_csv))}
    try:
        for temporary, write in files.values():
            write(temporary, index=False)
    except BaseException as exc:
        for temporary, _ in files.values():
            temporary.unlink(missing_ok=True)
        if isinstance(exc, OSError):  # pyarrow's has the errno, and its own words in strerror
            raise G2SError(f"{outdir}: cannot write the summary ({os.strerror(exc.errno) if exc.errno else exc}); "
                           "the pairs' results are kept: run the batch again to write it") from None
        raise
    for path, (temporary, _) in files.items():
        os.replace(temporary, path)
    return list(files)


def _to_parquet(summary: pd.DataFrame, path: Path, **options: Any) -> None:
    """``summary.to_parquet(path)`` through a file Python opens: pyarrow encodes a path as UTF-8, and a batch's folder
    whose name is not UTF-8 (bytes Python keeps as lone surrogates) ended the batch in an internal error."""
    with open(path, "wb") as handle:
        summary.to_parquet(handle, **options)


@contextmanager
def missing_extra() -> Iterator[None]:
    """Turn a missing package of the ``batch`` extra into a :class:`G2SError` saying how to install it."""
    try:
        yield
    except ModuleNotFoundError as exc:
        if exc.name and exc.name.split(".")[0] in ("pandas", "pyarrow", "dask", "distributed"):
            raise G2SError(f"{INSTALL_HINT} ({exc.name} is missing)") from None
        raise
