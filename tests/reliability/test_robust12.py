"""Inputs robust12 (5 December 2026) found ending in an internal error, a library's words, a wrong culprit or lost
work, each test failing on the code before its fix (docs/errors.md, "The hostile-user pass of robust12")."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from g2s_core.registry import Registry
from g2s_plugins.executors.dask_cluster import NO_WORKERS

from tests.reliability.checks import CORRIDOR, assert_clean_error, run_g2s, tree

ANALYZER = '''"""A third-party analyzer."""
from g2s_core.plugin import hookimpl

NAME = "{name}"


@hookimpl
def {hook}(structure):
    return {{node: 1.0 for node in structure}}
'''


def third_party(folder: Path, package: str, entry_points: dict[str, str], modules: dict[str, str]) -> Path:
    """A package installed as a user's hand-made one is: ``modules`` and a ``*.dist-info`` folder declaring
    ``entry_points`` (name: value) in the ``g2s`` group, in ``folder`` (to put on the path); ``folder``."""
    folder.mkdir(exist_ok=True)
    for name, source in modules.items():
        (folder / f"{name}.py").write_text(source)
    info = folder / f"{re.sub(r'[^A-Za-z0-9.]', '_', package)}-1.0.dist-info"
    info.mkdir()
    (info / "METADATA").write_text(f"Metadata-Version: 2.1\nName: {package}\nVersion: 1.0\n")
    (info / "entry_points.txt").write_text("[g2s]\n" + "".join(f"{k} = {v}\n" for k, v in entry_points.items()))
    return folder


def g2s_with_path(folder: Path, *args: str, timeout: float = 120, **variables: str) -> subprocess.CompletedProcess:
    """``g2s ARGS`` in a child process whose ``PYTHONPATH`` holds ``folder``, with the environment ``variables``."""
    env = {**os.environ, "COLUMNS": "300", "PYTHONPATH": os.pathsep.join([str(folder), *sys.path]), **variables}
    return subprocess.run([sys.executable, "-m", "g2s_core.cli", *args], capture_output=True, text=True, env=env,
                          timeout=timeout)


def broken_of(folder: Path, monkeypatch: pytest.MonkeyPatch) -> dict[str, str]:
    """``{entry point: reason}`` of every broken plugin once ``folder`` is on the path, the stages loaded as `g2s plugins`
    loads them (the first stage with the entry points named after no stage)."""
    monkeypatch.syspath_prepend(str(folder))
    registry = Registry.from_entry_points()
    registry.plugins("graph")
    return {broken.entry_point: broken.reason for broken in registry.broken()}


def test_a_plugin_whose_hook_is_misspelt_breaks_only_itself(tmp_path, monkeypatch):
    # pluggy's check of a plugin implementing an unknown `g2s_*` hook (`g2s_analyse`) failed, and the plugin stayed
    # registered: every plugin loaded after it failed the same check, `g2s plugins` listed 14 of graph2structure's
    # plugins broken for it, and `g2s run map_analysis` was exit 1 blaming graph2structure's `flow` analyzer
    folder = third_party(tmp_path / "site", "aaa-typo", {"analyzers.typo": "typo_mod"},
                         {"typo_mod": ANALYZER.format(name="typo", hook="g2s_analyse")})
    broken = broken_of(folder, monkeypatch)
    assert list(broken) == ["analyzers.typo"]
    assert "unknown hook 'g2s_analyse' in plugin <module 'typo_mod'" in broken["analyzers.typo"]


def test_entry_points_named_with_colons_or_of_a_value_of_extra_colons_are_told_by_their_names(tmp_path, monkeypatch):
    # review30: the registry took an entry point's name back out of pluggy's name for its plugin,
    # `package:entry point:NAME`, by splitting it at ':', and named `analyzers:odd` as 'analyzers'; a value of two ':'
    # (`mod:Class:extra`) failed inside importlib in its words, `AttributeError: 'NoneType' object has no attribute
    # 'group'`, naming neither what is wrong nor what is expected
    folder = third_party(tmp_path / "site", "colon-plug",
                         {"analyzers:odd": "colon_mod", "analyzers.colon:x": "colon_mod",
                          "analyzers.extra": "colon_mod:NAME:extra", "analyzers.empty": "colon_mod:"},
                         {"colon_mod": ANALYZER.format(name="colon", hook="g2s_analyze")})
    broken = broken_of(folder, monkeypatch)
    where = "entry point {!r} of package 'colon-plug': "
    assert broken == {
        "analyzers.colon:x": where.format("analyzers.colon:x") + "its plugin is also that of entry point 'analyzers:odd'; "
                                                                "each entry point names a plugin of its own",
        "analyzers.empty": where.format("analyzers.empty") + "its value 'colon_mod:' is not of the form 'module' or "
                                                            "'module:attribute' (dotted names)",
        "analyzers.extra": where.format("analyzers.extra") + "its value 'colon_mod:NAME:extra' is not of the form "
                                                            "'module' or 'module:attribute' (dotted names)",
    }


def test_an_entry_point_listing_two_plugins_of_one_name_is_told_in_one_short_line(tmp_path, monkeypatch):
    # pluggy named each plugin `package:entry point:NAME`, the same for both: its ValueError listed every plugin
    # registered, a line of 9 kB (`Plugin name already registered: ... {'graph2structure:analyzers.area:area': ...`)
    twins = ANALYZER.format(name="twin", hook="g2s_analyze") + (
        "\n\nclass Other:\n    NAME = 'twin'\n    g2s_analyze = staticmethod(g2s_analyze)\n\n\n"
        "import sys\n\nPAIR = [sys.modules[__name__], Other]\n")
    folder = third_party(tmp_path / "site", "twin-plug", {"analyzers.twin": "twin_mod:PAIR"}, {"twin_mod": twins})
    broken = broken_of(folder, monkeypatch)
    assert broken == {"analyzers.twin": "two plugins provide Analyzer 'twin': package 'twin-plug' (entry point "
                                        "'analyzers.twin') and package 'twin-plug' (entry point 'analyzers.twin')"}


def test_a_plugin_name_holding_rich_markup_is_listed_as_written(tmp_path):
    # `g2s plugins` printed a broken entry point's name and package through rich's markup: `analyzers.x[/red]` was
    # `internal error: MarkupError: closing tag '[/red]' at position 39 doesn't match any open tag` (exit 1)
    folder = third_party(tmp_path / "site", "m[/b]p", {"analyzers.x[/red]": "no_such_module"}, {})
    listed = g2s_with_path(folder, "plugins", "--stage", "analyzers")
    assert (listed.returncode, listed.stderr) == (0, "")
    assert "broken analyzers.x[/red]  (m[/b]p)\n  no_such_module failed to load: ModuleNotFoundError: No module named " \
        "'no_such_module'" in listed.stdout


DYING = '''"""An analyzer whose process dies as it runs, as one killed for want of memory or crashing in native code does."""
import os
import signal

from pydantic import Field

from g2s_core.plugin import PluginParams, hookimpl

NAME = "dies"


class Params(PluginParams):
    """How it dies."""

    signal: str = Field("SIGKILL", description="the signal it sends itself")


@hookimpl
def g2s_analyze(structure, params):
    os.kill(os.getpid(), getattr(signal, params.signal))
'''


@pytest.mark.parametrize("executor, signal_name", [("local", "SIGKILL"), ("dask", "SIGSEGV")])
def test_a_pair_whose_worker_dies_fails_alone(executor, signal_name, tmp_path):
    # a worker that died (the system's out-of-memory killer, a crash in native code) ended the whole batch, exit 1,
    # `Executor plugin 'local' (package 'graph2structure') failed: its iterator raised BrokenProcessPool: ...` (`'dask'
    # ... KilledWorker: ...`): the pairs not yet finished were lost, and the process pool's other workers, stopped
    # with it, left a half-written pair's staging folder in its result folder
    folder = third_party(tmp_path / "site", "dies-plug", {"analyzers.dies": "dies_mod"}, {"dies_mod": DYING})
    (tmp_path / "good.yaml").write_text("extends: map_piece\n")
    (tmp_path / "dies.yaml").write_text(f"extends: map_piece\nanalyzers: [{{plugin: dies, params: {{signal: {signal_name}}}}}]\n")
    levels = ["sample:straight_corridor", "sample:cross_hub"]
    out = tmp_path / "out"
    # Dask's own allowed-failures (3: a pair is given up at its worker's fourth death), as a user runs it; the other
    # worker-death test (test_robust14) gives up at the first death
    batch = g2s_with_path(folder, "batch", str(tmp_path / "dies.yaml"), str(tmp_path / "good.yaml"), *levels, "-o", str(out),
                          "--executor", executor, "--workers", "2", "--format", "json", "-q", timeout=600)  # dask: 35-114 s
    died = ("its worker process died as it ran" if executor == "local" else "every Dask worker that held it died")
    assert batch.returncode == 4, batch.stderr
    lines = [f"g2s: {config} on {level} failed: sample:{level}: {died} (killed, e.g. by the system for want of memory, "
             "or a crash in native code); the batch's other pairs ran" for config in ("dies", "good")
             for level in ("straight_corridor", "cross_hub")]
    import pandas as pd

    summary = pd.read_csv(out / "summary.csv")
    status = {(config, level): state for config, level, state in zip(summary["config"], summary["level"], summary["status"])}
    # both executors run again alone the pairs that were on a dying worker (robust14), but a local Dask cluster left
    # without any worker loses its pairs left (NO_WORKERS, seen under load)
    sound = [("good", level) for level in ("straight_corridor", "cross_hub") if status[("good", level)] == "ok"]
    assert len(sound) == 2 or NO_WORKERS in batch.stderr, batch.stderr
    assert len(status) == 4 and status[("dies", "cross_hub")] == status[("dies", "straight_corridor")] == "failed"
    # a cluster whose workers all died as they started loses every pair left, seen under load
    stderr = batch.stderr.replace(NO_WORKERS, died)
    assert sorted(stderr.splitlines()) == sorted(
        line for line in lines if tuple(line.split(": ")[1].replace(" failed", "").split(" on ")) not in sound)
    assert [p.name for p in out.rglob("*") if "g2s-staging" in p.name] == []
    assert sorted(p.name for p in (out / "good").glob("*") if p.name in {level for _, level in sound}) == sorted(
        level for _, level in sound)


def test_a_config_of_millions_of_values_is_refused_before_it_fills_the_memory(tmp_path, monkeypatch, capsys):
    # a config of 96 MB holding a list of 16 million numbers took 7.3 GB and 9 minutes of PyYAML before the run
    # refused it; now the value past MAX_YAML_NODES (1,000,000: 23 s and 0.8 GB) stops the reading. Here the limit is
    # 200 values, so that the test reads a small file (the root, `extends` and its value, `outputs`, its mapping,
    # `formats` and its list are 7)
    from g2s_core import config

    monkeypatch.setattr(config, "MAX_YAML_NODES", 200)
    path = tmp_path / "long.yaml"
    # json and 192 empty names, which a format list drops (json twice is refused)
    path.write_text("extends: graph_only\noutputs:\n  formats: [json, " + ", ".join(['""'] * 192) + "]\n")
    assert run_g2s(capsys, "run", path, CORRIDOR, "-o", tmp_path / "out", "-q").code == 0
    path.write_text("extends: graph_only\noutputs:\n  formats: [" + ", ".join(["json"] * 194) + "]\n")
    outcome = run_g2s(capsys, "run", path, CORRIDOR, "-o", tmp_path / "out2", "-q")
    assert_clean_error(outcome, f"{path}: invalid YAML at line 3, column 1171: more than 200 values (a config holds hundreds; "
                                "long lists of points belong in a points file)")
    assert tree(tmp_path / "out2") == []


def test_a_small_config_is_read_under_a_memory_limit_the_run_fits_in(tmp_path):
    # every text input was read with read(256 MiB + 1), which asks for the whole buffer at once: `g2s batch` under
    # `ulimit -v 600000` (pandas and pyarrow loaded) failed on its 30-byte config, `internal error: MemoryError`
    path = tmp_path / "small.yaml"
    path.write_text("extends: graph_only\n")
    script = (
        "import resource, sys\n"
        "from g2s_core.input_files import read_text\n"
        "size = int(next(l for l in open('/proc/self/status') if l.startswith('VmSize:')).split()[1]) * 1024\n"
        "resource.setrlimit(resource.RLIMIT_AS, (size + 128 * 2**20, resource.getrlimit(resource.RLIMIT_AS)[1]))\n"
        "print(read_text(sys.argv[1], 'config file'), end='')\n"
    )
    read = subprocess.run([sys.executable, "-c", script, str(path)], capture_output=True, text=True, timeout=60)
    assert (read.returncode, read.stdout, read.stderr) == (0, "extends: graph_only\n", "")


@pytest.mark.parametrize("given, says", [("", "no evaluator given"), (" , ", "no evaluator given"),
                                         ("traffic,traffic", "traffic is given twice")])
def test_batch_evaluate_of_no_name_or_a_name_twice_is_refused(given, says, tmp_path, capsys):
    # `--evaluate "$EVALUATORS"` with the variable unset ran the batch without evaluators (exit 0), as `-o ""` and
    # `--format ""` are not; `traffic,traffic` was `map_piece: evaluators: two plugins write values named 'traffic';
    # give one a 'key'`, of a config the user never wrote
    outcome = run_g2s(capsys, "batch", "map_piece", CORRIDOR, "-o", tmp_path / "out", "--evaluate", given, "-q")
    assert_clean_error(outcome, f"--evaluate: {says} (expected some of: traffic)")
    assert tree(tmp_path / "out") == []


@pytest.mark.parametrize("command", ["run", "batch"])
def test_a_format_given_twice_is_refused_as_an_evaluator_given_twice_is(command, tmp_path, capsys):
    # names39 (5 December 2026): `json,JSON` wrote json once without a word, where `--evaluate traffic,traffic` is refused
    outcome = run_g2s(capsys, command, "graph_only", CORRIDOR, "-o", tmp_path / "out", "--format", "json,html,JSON", "-q")
    assert_clean_error(outcome, "--format: 'json' is given twice (expected some of: ")
    assert tree(tmp_path / "out") == []
