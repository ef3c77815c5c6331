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
