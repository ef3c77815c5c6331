"""The output folder under a hostile file system (robust6, 4 December 2026): what :mod:`g2s_core.result_folder`
leaves where the user looks."""

from __future__ import annotations

import os
import stat

from g2s_core.result_folder import staged


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
