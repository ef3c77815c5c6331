"""The output folder: refused before any work when it cannot be written; a run's files appear
all together or not at all; --force never replaces an input."""

from __future__ import annotations

import os
import resource
import shutil
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from g2s_core.errors import G2SError
from g2s_core import result_folder
from g2s_core.result_folder import STAGING_MARK, staged
from g2s_plugins.outputs import heatmap
from tests.reliability.checks import CORRIDOR, assert_clean_error, run_g2s, run_g2s_process, snapshot, tree

# --- an output folder that cannot be made -----------------------------------------------------


def _symlink_loop(folder: Path) -> Path:
    (folder / "loop").symlink_to("loop")
    return folder / "loop" / "out"


@pytest.mark.parametrize(
    "where, says",
    [
        (lambda tmp: Path("/proc/g2s-results"), "cannot write results there"),
        (lambda tmp: tmp / "afile" / "sub", "afile is not a folder"),
        (lambda tmp: tmp / "afile", "exists and is not a folder"),
        (lambda tmp: tmp / "afile" / "a" / "b", "afile is not a folder"),
        (lambda tmp: tmp / ("n" * 300), "a name of 300 bytes is too long"),
        (lambda tmp: tmp / "x" / ("é" * 200) / "y", "a name of 400 bytes is too long"),
        (_symlink_loop, "loop is not a folder"),
    ],
    ids=["proc", "below-a-file", "a-file", "deep-below-a-file", "long-name", "long-inner-name", "symlink-loop"],
)
def test_unwritable_outdir_found_before_any_work(where, says, tmp_path, quick_config, capsys):
    (tmp_path / "afile").write_text("mine\n")
    outdir = where(tmp_path)
    # the mesh does not exist: a message about the folder proves it was checked first
    outcome = run_g2s(capsys, "run", quick_config, tmp_path / "missing.obj", "-o", outdir)
    assert_clean_error(outcome, str(outdir), says)
    assert (tmp_path / "afile").read_text() == "mine\n"
    assert not [p for p in tmp_path.iterdir() if p.name not in ("afile", "quick.yaml", "loop")]


def test_unwritable_outdir_demo(tmp_path, capsys):
    (tmp_path / "afile").write_text("")
    assert_clean_error(run_g2s(capsys, "demo", "-o", tmp_path / "afile" / "out"), "afile is not a folder")


# --- all or nothing --------------------------------------------------------------------------------


def _failing_writer(result, outdir):
    (outdir / "half.txt").write_text("half")
    raise OSError(28, "No space left on device")


def _interrupted_writer(result, outdir):
    (outdir / "half.txt").write_text("half")
    raise KeyboardInterrupt


@pytest.mark.parametrize("existing", [False, True], ids=["new-folder", "existing-folder"])
@pytest.mark.parametrize("writer, code", [(_failing_writer, 2), (_interrupted_writer, 130)], ids=["disk-full", "ctrl-c"])
def test_a_failing_writer_leaves_nothing(writer, code, existing, tmp_path, quick_config, capsys, monkeypatch):
    out = tmp_path / "deeper" / "out"
    if existing:
        out.mkdir(parents=True)
        (out / "notes.txt").write_text("mine\n")
    before = tree(tmp_path)
    # json is written first and succeeds; the failing format comes after it
    monkeypatch.setattr(heatmap, "write", writer)
    outcome = run_g2s(capsys, "run", quick_config, CORRIDOR, "-o", out, "--format", "json,png")
    assert outcome.code == code, outcome.stderr
    assert "Traceback" not in outcome.stderr
    if code == 2:
        assert_clean_error(outcome, str(out), "No space left on device", "nothing was written")
    assert tree(tmp_path) == before  # not a file, not a staging folder, not the parent folders


def test_forced_rerun_that_fails_keeps_the_earlier_results(tmp_path, quick_config, capsys, monkeypatch):
    out = tmp_path / "out"
    assert run_g2s(capsys, "run", quick_config, CORRIDOR, "-o", out, "--format", "json,graph").code == 0
    before = snapshot(out.iterdir())
    monkeypatch.setattr(heatmap, "write", _failing_writer)
    outcome = run_g2s(capsys, "run", quick_config, CORRIDOR, "-o", out, "--format", "json,png", "--force")
    assert_clean_error(outcome, str(out))
    assert snapshot(out.iterdir()) == before


def test_a_folder_with_a_result_files_name_is_refused_before_any_work(tmp_path, capsys):
    # with --force, run.json was moved in, then the move of structure.json onto the folder failed: half a result
    out = tmp_path / "out"
    (out / "structure.json").mkdir(parents=True)
    (out / "structure.json" / "mine.txt").write_text("mine\n")
    before = tree(out)
    outcome = run_g2s(capsys, "run", "graph_only", CORRIDOR, "-o", out, "--force")
    assert_clean_error(outcome, f"{out}: structure.json: a folder has the name of a result file")
    assert tree(out) == before


def test_forced_rerun_replaces_all_results_at_once(tmp_path, quick_config, capsys):
    out = tmp_path / "out"
    assert run_g2s(capsys, "run", quick_config, CORRIDOR, "-o", out, "--format", "json,graph").code == 0
    (out / "notes.txt").write_text("mine\n")
    assert run_g2s(capsys, "run", quick_config, CORRIDOR, "-o", out, "--format", "graph", "--force").code == 0
    assert tree(out) == ["graph.json", "notes.txt"]  # the json format's files of the earlier run are gone


def test_file_size_limit_leaves_nothing(tmp_path, quick_config, capsys):
    """``ulimit -f``: the write of the largest file fails (EFBIG), after the others were written."""
    sizes = tmp_path / "sizes"
    assert run_g2s(capsys, "run", quick_config, CORRIDOR, "-o", sizes, "--format", "json,graph").code == 0
    largest = max(p.stat().st_size for p in sizes.iterdir())
    assert sorted(p.stat().st_size for p in sizes.iterdir())[0] < largest
    shutil.rmtree(sizes)
    out = tmp_path / "out"

    def limit_file_size():
        resource.setrlimit(resource.RLIMIT_FSIZE, (largest - 1, largest - 1))

    outcome = run_g2s_process("run", quick_config, CORRIDOR, "-o", out, "--format", "json,graph",
                              preexec_fn=limit_file_size)
    assert_clean_error(outcome, str(out), "File too large", "nothing was written")
    assert tree(tmp_path) == ["quick.yaml"]


SIGINT_WHILE_WRITING = """
import os, signal, sys, time
from g2s_core.cli import main
from g2s_plugins.outputs import heatmap

def write(result, folder):  # the json files are written by now
    os.kill(os.getpid(), signal.SIGINT)
    time.sleep(5)

heatmap.write = write
sys.exit(main(sys.argv[1:]))
"""


def test_ctrl_c_while_writing_leaves_nothing(tmp_path, quick_config):
    """A real SIGINT to a real process, after some of its files were written."""
    out = tmp_path / "out"
    proc = subprocess.run([sys.executable, "-c", SIGINT_WHILE_WRITING, "run", str(quick_config), CORRIDOR,
                           "-o", str(out), "--format", "json,png"], capture_output=True, text=True, timeout=300,
                          preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))  # as from a terminal, not a background job
    assert proc.returncode == 130, proc.stderr
    assert proc.stderr.strip() == "g2s: interrupted"
    assert tree(tmp_path) == ["quick.yaml"]


def test_leftover_staging_folders_never_block_and_are_removed(tmp_path, quick_config, capsys):
    out = tmp_path / "out"
    dead = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"], capture_output=True, text=True)
    pid = int(dead.stdout)  # a process that has ended
    out.mkdir()
    leftover_inside = out / f"{STAGING_MARK}{pid}-abc"
    leftover_beside = tmp_path / f".out{STAGING_MARK}{pid}-def"
    for folder in (leftover_inside, leftover_beside):
        folder.mkdir()
        (folder / "structure.json").write_text("{")
    assert run_g2s(capsys, "run", quick_config, CORRIDOR, "-o", out).code == 0
    assert tree(out) == ["graph.json"]  # the run into an existing folder stages inside it
    assert leftover_beside.is_dir()
    shutil.rmtree(out)
    assert run_g2s(capsys, "run", quick_config, CORRIDOR, "-o", out).code == 0  # a new folder is staged beside
    assert not leftover_beside.exists() and tree(out) == ["graph.json"]


def test_staging_of_a_live_process_is_left_alone(tmp_path):
    live = tmp_path / f".out{STAGING_MARK}{os.getpid()}-xyz"
    live.mkdir()
    with staged(tmp_path / "out") as staging:
        (staging / "a.txt").write_text("a")
    assert live.is_dir() and (tmp_path / "out" / "a.txt").read_text() == "a"


def test_a_parent_folder_made_meanwhile_by_another_run_is_shared(tmp_path, monkeypatch):
    """Two batch pairs of one config write into its folder at once: both may find it missing, one makes it first."""
    out = tmp_path / "config" / "level"
    missing_folders = result_folder._missing_folders

    def racing(folder):
        found = missing_folders(folder)
        if folder == out.parent:
            folder.mkdir()  # the other pair, between this run's look and its mkdir
        return found

    monkeypatch.setattr(result_folder, "_missing_folders", racing)
    with staged(out) as staging:
        (staging / "a.txt").write_text("a")
    assert (out / "a.txt").read_text() == "a" and tree(tmp_path) == ["config", "config/level", "config/level/a.txt"]


def test_staged_api_error_names_the_folder(tmp_path):
    with pytest.raises(G2SError, match="out: cannot write results"):
        with staged(tmp_path / "out") as staging:
            os.mkdir(staging / "x" / "y")
    assert tree(tmp_path) == []


# --- --force never replaces an input ------------------------------------------------------------------------


def _config_named_as_a_result(tmp_path: Path, out: Path) -> tuple[Path, list]:
    config = out / "graph.json"  # YAML is a superset of JSON: a config may have any name
    config.write_text('{"extends": "graph_only"}\n')
    return config, [config, CORRIDOR]


def _extended_config_named_as_a_result(tmp_path: Path, out: Path) -> tuple[Path, list]:
    parent = out / "run.json"
    parent.write_text('{"extends": "graph_only"}\n')
    child = tmp_path / "child.yaml"
    child.write_text(f"extends: {parent}\noutputs: {{formats: [graph, json]}}\n")
    return parent, [child, CORRIDOR]


def _points_file_named_as_a_result(tmp_path: Path, out: Path) -> tuple[Path, list]:
    points = out / "structure.json"
    points.write_text("[[0.5, 0.0, 0.5]]\n")
    config = tmp_path / "points.yaml"
    config.write_text(f"extends: graph_only\nterminals: {{plugin: points, params: {{file: '{points}'}}}}\n"
                      "stop_after: terminals\noutputs: {formats: [json]}\n")
    return points, [config, CORRIDOR]


def _mesh_named_as_a_result(tmp_path: Path, out: Path) -> tuple[Path, list]:
    from g2s_plugins.samples.levels import load_sample

    mesh = out / "structure.glb"
    load_sample("straight_corridor").mesh.export(mesh)
    config = tmp_path / "quick.yaml"
    config.write_text("extends: graph_only\n")
    return mesh, [config, mesh, "--format", "glb"]


@pytest.mark.parametrize(
    "make",
    [_config_named_as_a_result, _extended_config_named_as_a_result, _points_file_named_as_a_result,
     _mesh_named_as_a_result],
    ids=["config", "extended-config", "points-file", "mesh"],
)
def test_force_never_overwrites_an_input(make, tmp_path, capsys):
    out = tmp_path / "out"
    out.mkdir()
    guarded, (config, mesh, *options) = make(tmp_path, out)
    before = snapshot([guarded])
    outcome = run_g2s(capsys, "run", config, mesh, "-o", out, "--force", *options)
    assert_clean_error(outcome, f"the input {guarded} has the name of a result file ({guarded.name})")
    assert snapshot([guarded]) == before and tree(out) == [guarded.name]


@pytest.mark.parametrize("force", [False, True])
def test_a_run_that_another_run_wrote_into_meanwhile_writes_nothing(force, tmp_path, quick_config, capsys):
    """Two runs into one folder at once both passed the check for earlier results; the later one's files then went
    in beside or over the other's: a folder of two runs' files (its graph.json, the other's structure.json)."""
    from g2s_core import api

    out = tmp_path / "out"
    if force:
        assert run_g2s(capsys, "run", quick_config, CORRIDOR, "-o", out, "--format", "json").code == 0
    result = api.run(CORRIDOR, str(quick_config))
    earlier = snapshot(out.glob("*"))

    def another_run_writes(step):
        if step == "writing graph":  # the other run, between this one's check and its move into place
            out.mkdir(exist_ok=True)
            (out / "graph.json").write_text("{}")

    with pytest.raises(G2SError) as refused:
        api.write_result(result, out, "graph", force=force, progress=another_run_writes)
    assert str(refused.value) == f"{out}: another run wrote graph.json there meanwhile; nothing of this run was written"
    assert (out / "graph.json").read_text() == "{}" and snapshot(out.glob("*.json")) == {**earlier, **snapshot([out / "graph.json"])}
    assert not any(STAGING_MARK in path.name for path in tmp_path.rglob("*"))
