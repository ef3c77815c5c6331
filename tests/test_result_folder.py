"""The output folder under a hostile file system (robust6, 4 December 2026): what :mod:`g2s_core.result_folder`
leaves where the user looks."""

from __future__ import annotations

import errno
import os
import shutil
import stat
from pathlib import Path

import pytest

from g2s_core import result_folder
from g2s_core.cli import main
from g2s_core.errors import G2SError
from g2s_core.result_folder import staged
from g2s_plugins.outputs import heatmap


def test_a_new_output_folder_gets_the_umasks_mode_not_a_temporary_folders(tmp_path):
    # the staging folder (tempfile.mkdtemp, mode 0700) was renamed to the output folder: other users, a web server
    # showing report.html, could not read a run's results
    previous = os.umask(0o022)
    try:
        with staged(tmp_path / "results") as folder:
            (folder / "structure.json").write_text("{}\n")
    finally:
        os.umask(previous)
    assert stat.S_IMODE((tmp_path / "results").stat().st_mode) == 0o755
    assert os.listdir(tmp_path) == ["results"]
    assert os.listdir(tmp_path / "results") == ["structure.json"]


def _removing(folder: Path):
    """A png writer that first removes ``folder``, as ``rm -r`` in another shell while the writers run."""
    def write(result, outdir):
        shutil.rmtree(folder)
        (outdir / "heatmap.png").write_bytes(b"")
    return write


@pytest.mark.parametrize("existing", [True, False], ids=["existing-folder", "new-folder-whose-parent-goes"])
def test_an_output_folder_removed_meanwhile_is_said_not_blamed_on_the_writer(existing, tmp_path, monkeypatch, capsys):
    # was "OutputWriter plugin 'png' (package 'graph2structure') failed: raised FileNotFoundError: ...": the user was
    # sent to the plugin's authors
    parent = tmp_path / "results"
    out = parent if existing else parent / "out"
    parent.mkdir()
    monkeypatch.setattr(heatmap, "write", _removing(parent))
    assert main(["run", "map_piece", "sample:straight_corridor", "-o", str(out), "--format", "json,png", "-q"]) == 2
    assert capsys.readouterr().err == f"g2s: error: {out}: cannot write results (its folder was removed meanwhile); nothing was written\n"
    assert not parent.exists()


def test_a_staging_folder_that_cannot_be_removed_is_named(tmp_path, monkeypatch):
    # a file system turned read-only while the writers ran: "nothing was written" hid a staging folder left behind
    monkeypatch.setattr(result_folder.shutil, "rmtree", lambda path, ignore_errors=False: None)
    with pytest.raises(G2SError) as caught, staged(tmp_path / "out") as folder:
        raise OSError(errno.EROFS, os.strerror(errno.EROFS), str(folder / "structure.json"))
    staging = next(tmp_path.iterdir())
    assert str(caught.value) == (f"{tmp_path / 'out'}: cannot write results (Read-only file system); nothing was written "
                                 f"(the staging folder {staging} could not be removed; the next run removes it)")


_KILLED_MID_MOVE = """
import os, signal, sys
from pathlib import Path
from g2s_core.cli import main
out, replace = Path(sys.argv[1]), os.replace
def replace_then_die(source, target):  # SIGKILL (or a power loss) after the first file is in place
    replace(source, target)
    if Path(target).parent == out:
        os.kill(os.getpid(), signal.SIGKILL)
os.replace = replace_then_die
main(["run", "map_piece", "sample:straight_corridor", "-o", str(out), "--format", "json,html", "--force", "-q"])
"""


def test_a_run_killed_between_its_renames_is_said_by_the_next_run(tmp_path, capsys):
    # robust7: the next run removed the killed run's staging folder without a word, and its "already holds results"
    # hid that the folder held part of one run's files beside another's
    import subprocess
    import sys

    out = tmp_path / "out"
    assert main(["run", "map_piece", "sample:straight_corridor", "-o", str(out), "--format", "json,html", "-q"]) == 0
    earlier = {name: (out / name).read_bytes() for name in os.listdir(out)}
    killed = subprocess.run([sys.executable, "-c", _KILLED_MID_MOVE, str(out)], capture_output=True, timeout=600)
    assert killed.returncode == -9
    (moving,) = [name for name in os.listdir(out) if result_folder.STAGING_MARK in name]
    pid = moving.split(result_folder.STAGING_MARK)[1].split("-")[0]
    capsys.readouterr()
    assert main(["run", "map_piece", "sample:straight_corridor", "-o", str(out), "-q"]) == 2
    said = f"{out}: a run killed while moving its results in (process {pid}) left only part of them there"
    assert capsys.readouterr().err == (f"g2s: error: {out}: already holds results ({', '.join(sorted(earlier))}); "
                                       f"{said.split(': ', 1)[1]}; use --force to replace them\n")
    assert main(["run", "map_piece", "sample:straight_corridor", "-o", str(out), "--force", "-q"]) == 0
    assert capsys.readouterr().err == f"g2s: warning: {said}; this run's results replaced them\n"
    assert sorted(os.listdir(out)) == sorted(earlier)  # the staging folder is gone
    assert main(["run", "map_piece", "sample:straight_corridor", "-o", str(out), "--force", "-q"]) == 0
    assert capsys.readouterr().err == ""  # said once
