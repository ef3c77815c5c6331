"""Inputs robust13 (5 December 2026) found ending in a traceback, a hang, lost pairs or read silently wrong, each test
failing on the code before its fix (docs/errors.md, "The hostile-user pass of robust13")."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from tests.reliability.checks import CORRIDOR, QUICK_CONFIG, assert_clean_error, run_g2s, tree

CONSOLE_SCRIPT = "import sys; from g2s_core.entry import main; sys.exit(main())"
"""``g2s`` as its console script starts it (:func:`g2s_core.entry.main`), for a child process."""


def another_package(folder: Path, entry_points: bytes) -> Path:
    """A distribution that is no g2s plugin, ``other`` 1.0, whose ``entry_points.txt`` holds ``entry_points``, made
    by hand in ``folder`` (to put on the path); ``folder``."""
    info = folder / "other-1.0.dist-info"
    info.mkdir(parents=True)
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: other\nVersion: 1.0\n")
    (info / "entry_points.txt").write_bytes(entry_points)
    return folder


@pytest.mark.parametrize("entry_points, problem", [
    (b"[console_scripts]\nother = other:main\nnoequals\n", "line 3 is not 'name = value'"),
    (b"[console_scripts]\nother = caf\xe9:main\n", "the byte at offset 29 is not UTF-8 text"),
])
@pytest.mark.parametrize("variables", [{}, {"PYDANTIC_DISABLE_PLUGINS": "1"}])
def test_another_packages_broken_entry_points_are_named_in_one_line(entry_points, problem, variables, tmp_path):
    # robust12's leftover: pydantic reads every distribution's entry points as g2s's first model is defined (its own
    # plugins), and the plugin registry does as the command line is built (when pydantic's plugins are off): another
    # package's file of a line without '=' or a byte that is not UTF-8 ended every command, `g2s --help` too, in
    # importlib's traceback (`TypeError: Pair.__new__() missing 1 required positional argument: 'value'`)
    folder = another_package(tmp_path / "site", entry_points)
    env = {**os.environ, "COLUMNS": "300", "PYTHONPATH": os.pathsep.join([str(folder), *sys.path]), **variables}
    started = subprocess.run([sys.executable, "-c", CONSOLE_SCRIPT, "--help"], capture_output=True, text=True, env=env,
                             timeout=120)
    assert (started.returncode, started.stdout) == (2, "")
    assert started.stderr == (f"g2s: error: installed package 'other' (in {folder}): its entry_points.txt cannot be "
                              f"read: {problem} (every package's entry points are read as g2s starts; repair or "
                              "uninstall that package)\n")


THREADLESS_POOL = """
import concurrent.futures.process
import multiprocessing.queues
from g2s_plugins.executors import process_pool

def refuse(thread):
    raise RuntimeError("can't start new thread")

{refused} = refuse  # as under `ulimit -v` with pandas and pyarrow loaded
try:
    list(process_pool.g2s_execute(function=abs, items=[-1, -2, -3], params=process_pool.Params(workers=2),
                                  lost=lambda item, reason: {{}}))
except process_pool.PoolThreadDied as exc:
    print(exc)
"""


@pytest.mark.parametrize("refused", ["multiprocessing.queues.Queue._start_thread",
                                     "concurrent.futures.process._ExecutorManagerThread.start"])
def test_a_pool_that_cannot_start_its_threads_says_so_instead_of_waiting_forever(refused):
    # robust12's leftover: under `ulimit -v 600000` the pool's own thread could not start the thread that feeds its
    # workers (`RuntimeError: can't start new thread`, a traceback on stderr) and died; the batch waited forever for
    # pairs that nobody handed out. A little tighter (560,000), the pool's own thread, started with the first item,
    # cannot start: the shutdown then failed to join it and left the workers it had started
    ran = subprocess.run([sys.executable, "-c", THREADLESS_POOL.format(refused=refused)], capture_output=True, text=True,
                         timeout=60)
    assert (ran.returncode, ran.stderr) == (0, "")
    assert ran.stdout == ("the pool cannot run its threads (RuntimeError: can't start new thread; under a memory limit? "
                          "--executor serial needs none)\n")


@pytest.mark.parametrize("spec", [f"{CORRIDOR}#x", f"{CORRIDOR}?width=4#x", f"{CORRIDOR}#", "sample:file:straight_corridor",
                                  "sample:https://straight_corridor"])
def test_a_sample_spec_of_a_fragment_or_a_scheme_is_refused(spec, tmp_path, capsys):
    # robust12's leftover: a sample spec is read as a URL, whose fragment (`#x`) and scheme (`file:`) were dropped
    # unsaid: `sample:straight_corridor?width=4#x` ran width 4, `sample:file:straight_corridor` the corridor
    config = tmp_path / "quick.yaml"
    config.write_text(QUICK_CONFIG)
    outcome = run_g2s(capsys, "run", config, spec, "-o", tmp_path / "out", "-q")
    assert_clean_error(outcome, f"{spec}: expected sample:NAME?param=value&param=value (no '#', '//' or second ':'; "
                                "a value's '#' is written %23)")
    assert tree(tmp_path / "out") == []


SQUARE_FLOOR = "v 0 0 0\nv 10 0 0\nv 10 0 10\nv 0 0 10\nf 1 3 2\nf 1 4 3\n"
"""A 10 m square floor, facing up (Y up)."""


def test_names_holding_rich_emoji_codes_or_markup_are_printed_as_written(tmp_path, capsys):
    # rich read every printed line for emoji codes: `g2s: error: level:cat:.obj: no such mesh file` named a file
    # `level🐱.obj`, and `wrote .../o:fire:/graph.json` a folder that does not exist; the stage table's title, a level
    # named `[red]x:cat:.obj`, was read as markup too (`x🐱.obj`)
    config = tmp_path / "quick.yaml"
    config.write_text(QUICK_CONFIG)
    missing = run_g2s(capsys, "run", config, tmp_path / "level:cat:.obj", "-o", tmp_path / "out", "-q")
    assert_clean_error(missing, f"{tmp_path}/level:cat:.obj: no such mesh file")
    level = tmp_path / "[red]x:cat:.obj"
    level.write_text(SQUARE_FLOOR)
    written = run_g2s(capsys, "run", config, level, "-o", tmp_path / "o:fire:")
    assert written.code == 0, written.stderr
    assert written.stdout.splitlines()[0].strip() == "[red]x:cat:.obj"
    assert f"wrote {tmp_path}/o:fire:/graph.json" in written.stdout.splitlines()
