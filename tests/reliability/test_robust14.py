"""Inputs robust14 (5 December 2026) found ending in a lost pair, a dropped Ctrl-C, an empty message or a library's
traceback, each test failing on the code before its fix (docs/errors.md, "The hostile-user pass of robust14")."""

from __future__ import annotations

import ast
import os
import resource
import signal
import subprocess
import sys

import pytest

from g2s_plugins.executors.dask_cluster import NO_WORKERS

from tests.reliability.checks import CORRIDOR, assert_clean_error, run_g2s, tree
from tests.reliability.test_robust12 import third_party
from tests.reliability.test_robust13 import another_package

QUEUED_BEHIND_A_KILLER = """
import os, signal, time
from g2s_plugins.executors import dask_cluster

def work(item):
    if item == "killer":
        os.kill(os.getpid(), signal.SIGKILL)
    time.sleep(0.5)  # as a pair takes time
    return {"item": item, "status": "ok"}

rows = dask_cluster.g2s_execute(function=work, items=["killer", *"abcdefgh"],
                                params=dask_cluster.Params(workers=1), lost=lambda item, why: {"item": item, "status": why})
print(sorted((row["item"], row["status"]) for row in rows))
"""


def test_a_dask_pair_queued_on_a_worker_another_pair_kills_runs_again_and_ends_with_its_own_row():
    # robust12's and robust13's leftover: Dask counts a worker's death against every pair the worker held, those
    # waiting there too, and gives a pair up after 4 deaths (KilledWorker): a sound pair queued behind one that kills
    # its worker failed with it, `every Dask worker that held it died` (here, before the fix: a sound pair lost in 4
    # runs of 4). The pairs Dask gave up on now run again one at a time, alone, where only the killer dies
    # queuing off (Dask's way before 2022.11, a user's setting): every pair is given to the worker at once, as Dask
    # does with the pairs left when a dead worker's replacement joins (which made the failure a matter of timing)
    # and Dask gives the pairs up at the worker's first death, not its fourth: the same pairs to run again alone, with a
    # quarter of the worker's starts
    env = {**os.environ, "DASK_DISTRIBUTED__SCHEDULER__WORKER_SATURATION": "inf",
           "DASK_DISTRIBUTED__SCHEDULER__ALLOWED_FAILURES": "0"}
    ran = subprocess.run([sys.executable, "-c", QUEUED_BEHIND_A_KILLER], capture_output=True, text=True, timeout=300,
                         env=env)
    assert ran.returncode == 0, ran.stderr
    rows = dict(ast.literal_eval(ran.stdout))
    # alone, the killer may leave the cluster without a worker (Dask starts none again that died as it started): it, and
    # the pairs still to run again after it, are then lost with NO_WORKERS's words (at load 8-9, 2 runs of 7)
    assert rows.pop("killer") in ("every Dask worker that held it died", NO_WORKERS)
    assert set(rows) == set("abcdefgh") and set(rows.values()) <= {"ok", NO_WORKERS}, rows


INTERRUPTED_AS_THE_EXECUTOR_FAILS = '''
import os, signal, sys, time
from g2s_plugins.batch import runner

real = runner.run_pair

def failing(pair):
    if pair.level == "cross_hub":
        time.sleep(1.0)  # the corridor's pair is done
        os.kill(int(os.environ["BATCH_PID"]), signal.SIGINT)
        raise ValueError("the executor failed at the same moment")
    return real(pair)

if __name__ == "__main__":
    os.environ["BATCH_PID"] = str(os.getpid())
    runner.run_pair = failing
    from g2s_core.cli import main
    sys.exit(main(["batch", "graph_only", "sample:straight_corridor", "sample:cross_hub", "-o", sys.argv[1],
                   "--workers", "1", "--format", "json", "-q"]))
'''


def test_a_ctrl_c_the_executor_held_is_not_dropped_when_its_iterator_fails_at_the_same_moment(tmp_path):
    # robust13's leftover: the pool holds Ctrl-C back while it waits (interrupts_held) and acted on it once the block
    # ended, but only when it ended well: a Ctrl-C taken as the iterator failed was dropped, and the batch ended as the
    # executor's failure, exit 1 (`Executor plugin 'local' ... failed: its iterator raised ValueError: ...`)
    script = tmp_path / "batch.py"  # a file: the pool's workers import the function from it
    script.write_text(INTERRUPTED_AS_THE_EXECUTOR_FAILS)
    ran = subprocess.run([sys.executable, str(script), str(tmp_path / "out")], capture_output=True, text=True,
                         timeout=300,
                         preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))  # as from a terminal, not a background job
    assert (ran.returncode, ran.stderr) == (130, "g2s: interrupted\n")
    import pandas as pd

    summary = pd.read_csv(tmp_path / "out" / "summary.csv")
    assert list(zip(summary["level"], summary["status"])) == [("straight_corridor", "ok")]


HUNGRY = '''"""An analyzer that runs out of memory, as under a memory limit (`ulimit -v`) Python's allocations do."""
from g2s_core.plugin import hookimpl

NAME = "hungry"


@hookimpl
def g2s_analyze(structure):
    raise MemoryError  # Python's own has no message
'''

LIMIT_KB = 8 << 20
"""A memory limit (``ulimit -v``) the runs fit in, in KB: the message names it."""


def limited() -> None:
    resource.setrlimit(resource.RLIMIT_AS, (LIMIT_KB << 10, resource.getrlimit(resource.RLIMIT_AS)[1]))


@pytest.mark.parametrize("command", ["run", "batch"])
def test_running_out_of_memory_is_said_in_one_line_naming_the_plugin_and_the_limit(command, tmp_path):
    # robust12's and robust13's leftover: under a memory limit a run ended in `g2s: internal error: MemoryError: ` (the
    # message empty, and the --verbose hint), and a batch's pair failed as `internal error: MemoryError: `
    folder = third_party(tmp_path / "site", "hungry-plug", {"analyzers.hungry": "hungry_mod"}, {"hungry_mod": HUNGRY})
    (tmp_path / "hungry.yaml").write_text("extends: map_piece\nanalyzers: [{plugin: hungry}]\n")
    env = {**os.environ, "COLUMNS": "300", "PYTHONPATH": os.pathsep.join([str(folder), *sys.path])}
    out = tmp_path / "out"
    arguments = ["--executor", "serial"] if command == "batch" else []
    ran = subprocess.run([sys.executable, "-m", "g2s_core.cli", command, str(tmp_path / "hungry.yaml"), CORRIDOR, "-o",
                          str(out), "--format", "json", "-q", *arguments], capture_output=True, text=True, env=env,
                         timeout=300, preexec_fn=limited)
    said = (f"out of memory in Analyzer plugin 'hungry' (package 'hungry-plug') under the process's memory limit of "
            f"{LIMIT_KB:,} KB (ulimit -v) (MemoryError)")
    if command == "run":
        assert (ran.returncode, ran.stderr) == (1, f"g2s: error: {said}\n")
        assert tree(out) == []
    else:
        assert (ran.returncode, ran.stderr) == (4, f"g2s: hungry on straight_corridor failed: {said}\n")


def test_running_out_of_memory_outside_any_plugin_says_so_and_the_limit():
    # g2s's own steps and the libraries' imports (trimesh's, under `ulimit -v 450000`) raise Python's MemoryError bare
    from g2s_core.errors import out_of_memory

    script = ("import resource, sys\n"
              f"resource.setrlimit(resource.RLIMIT_AS, ({LIMIT_KB << 10}, resource.RLIM_INFINITY))\n"
              "from g2s_core.errors import out_of_memory\n"
              "print(out_of_memory(MemoryError()))\n")
    ran = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=60)
    assert (ran.returncode, ran.stderr) == (0, "")
    assert ran.stdout == f"out of memory under the process's memory limit of {LIMIT_KB:,} KB (ulimit -v) (MemoryError)\n"
    limitless = str(out_of_memory(MemoryError("Unable to allocate 8 GiB"), " in the test"))
    assert limitless.startswith("out of memory in the test") and limitless.endswith("(MemoryError: Unable to allocate 8 GiB)")


@pytest.mark.parametrize("entry_points, problem", [
    (b"[console_scripts]\nother = other:main\nnoequals\n", "line 3 is not 'name = value'"),
    (b"[console_scripts]\nother = caf\xe9:main\n", "the byte at offset 29 is not UTF-8 text"),
])
@pytest.mark.parametrize("call", ["g2s_core.run('graph_only', 'sample:straight_corridor')",
                                  "__import__('g2s_core.batch').batch.run_batch"])
def test_the_python_api_names_another_packages_broken_entry_points_in_one_exception(entry_points, problem, call, tmp_path):
    # robust13's leftover: the console script names the package (robust13), but the Python API failed in importlib's
    # traceback, `TypeError: Pair.__new__() missing 1 required positional argument: 'value'` (`UnicodeDecodeError`),
    # raised inside networkx (its backends) or pydantic (its plugins) as g2s_core.api or g2s_core.batch was imported
    folder = another_package(tmp_path / "site", entry_points)
    script = f"import g2s_core\nfrom g2s_core.errors import G2SError\ntry:\n    {call}\nexcept G2SError as error:\n    print(error)\n"
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(folder), *sys.path])}
    ran = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=env, timeout=120)
    assert (ran.returncode, ran.stderr) == (0, "")
    assert ran.stdout == (f"installed package 'other' (in {folder}): its entry_points.txt cannot be read: {problem} "
                          "(every package's entry points are read as g2s starts; repair or uninstall that package)\n")


def test_a_summary_that_runs_out_of_memory_says_so_and_that_the_pairs_are_kept(tmp_path, monkeypatch, capsys):
    # under `ulimit -v 700000` every pair of a batch was written, then pyarrow's allocator failed as pandas made the
    # summary's text columns (`ArrowMemoryError: realloc of size 128 failed`, a MemoryError): `g2s: internal error: ...`
    # and the --verbose hint
    from g2s_plugins.batch import runner

    def refuse(_rows):
        raise MemoryError("realloc of size 128 failed")

    monkeypatch.setattr(runner, "_summary", refuse)
    out = tmp_path / "out"
    outcome = run_g2s(capsys, "batch", "graph_only", CORRIDOR, "-o", out, "--executor", "serial", "--format", "json", "-q")
    line = assert_clean_error(outcome, f"out of memory making the summary in {out} (the pairs' results are kept: run the "
                                       "batch again to make it)", code=1)
    assert line.endswith("(MemoryError: realloc of size 128 failed)")
    assert (out / "graph_only" / "straight_corridor" / "structure.json").is_file() and not (out / "summary.csv").exists()


def test_a_local_dask_cluster_starts_no_more_workers_than_the_batch_has_pairs(monkeypatch):
    # a LocalCluster starts every worker process up front: `g2s batch` of 2 pairs with `--executor dask --workers 8` took
    # 7.9-9.9 s against 5.6-5.7 s capped at 2 (and `--workers 1000` would start a thousand processes)
    import dask.distributed

    from g2s_plugins.executors import dask_cluster

    asked = []
    cluster = dask.distributed.LocalCluster

    def recorded(**options):
        asked.append(options["n_workers"])
        return cluster(**options)

    monkeypatch.setattr(dask.distributed, "LocalCluster", recorded)
    rows = dask_cluster.g2s_execute(function=abs, items=[-1, -2], params=dask_cluster.Params(workers=8),
                                    lost=lambda item, reason: (item, reason))
    assert (sorted(rows), asked) == ([1, 2], [2])


def test_a_plugin_whose_import_runs_out_of_memory_is_listed_broken_for_that(tmp_path, monkeypatch):
    # under `ulimit -v 560000` a built-in plugin's import ran out of memory: `GraphBuilder plugin 'navmesh' (package
    # 'graph2structure') failed to load: MemoryError: `, the reason empty
    from tests.reliability.test_robust12 import broken_of

    folder = third_party(tmp_path / "site", "heavy-plug", {"analyzers.heavy": "heavy_mod"},
                         {"heavy_mod": "raise MemoryError  # as an import under a memory limit does\n"})
    reason = broken_of(folder, monkeypatch)["analyzers.heavy"]
    assert reason.startswith("out of memory") and reason.endswith("(MemoryError)"), reason
