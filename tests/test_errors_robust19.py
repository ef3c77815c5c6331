"""Inputs robust19 (6 December 2026) found breaking docs/errors.md's rules: help and version written to a full disk
(lost, exit 0) or a closed standard output (an internal error for every command that prints); a path that is not
UTF-8 in the lines for a person (Python's ``\\udcff`` where the files write ``\\xff``); ``--set
terminals.plugin=metric`` keeping the other selector's parameters; an in-memory mesh's errors named ``mesh: mesh:``;
a batch of no config or no level from Python, and one level file given by two spellings."""

from __future__ import annotations

import errno
import os
import re
import sys
from pathlib import Path

import pytest
import trimesh

from g2s_core import api, pipeline
from g2s_core.cli import main
from g2s_core.config import resolve_config
from g2s_core.errors import G2SError
from g2s_core.registry import installed
from g2s_plugins.batch.runner import expand_inputs, run_batch
from tests.reliability.checks import CORRIDOR, run_g2s

PROJECT = Path(__file__).resolve().parent.parent


class FullDisk:
    """A standard output on a full disk, as ``> /dev/full`` gives: every write and flush fails."""

    def write(self, text: str) -> int:
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    flush = write


@pytest.mark.parametrize("args", [["--help"], ["run", "--help"], ["--version"]])
def test_help_and_version_that_cannot_be_written_are_said_so(args, monkeypatch, capsys):
    # argparse dropped the failed write: exit 0, nothing said, the help lost
    monkeypatch.setattr(sys, "stdout", FullDisk())
    with pytest.raises(SystemExit) as stopped:
        main(args)
    assert stopped.value.code == 2
    assert capsys.readouterr().err == "g2s: error: cannot write to standard output (No space left on device)\n"


@pytest.mark.parametrize("args", [["presets"], ["--help"]])
def test_a_closed_standard_output_is_bad_output_not_an_internal_error(args, monkeypatch, capsys):
    # `g2s presets >&-` (sys.stdout is None) was "internal error: AttributeError: 'NoneType' object has no attribute
    # 'write'", exit 1; `g2s --help >&-` wrote the help to stderr
    monkeypatch.setattr(sys, "stdout", None)
    try:
        code = main(args)
    except SystemExit as stopped:
        code = stopped.code
    assert code == 2
    assert capsys.readouterr().err == "g2s: error: cannot write to standard output (it is closed)\n"


def test_a_line_for_a_person_writes_a_path_that_is_not_utf8_as_the_files_do(tmp_path, capsys):
    taken = tmp_path / os.fsdecode(b"afile\xff")
    taken.write_text("mine")
    outcome = run_g2s(capsys, "run", "graph_only", CORRIDOR, "-o", taken)
    assert outcome.code == 2
    assert outcome.stderr == f"g2s: error: {tmp_path}/afile\\xff: exists and is not a folder\n", ascii(outcome.stderr)


def test_setting_a_stage_plugin_replaces_the_section_as_a_mapping_naming_it_does():
    # map_analysis's coverage parameters stayed: "terminals.params.traffic_weight: unknown key (expected one of: metric, ...)"
    config, source = resolve_config("map_analysis", {"terminals.plugin": "metric", "terminals.params.top_k": 2})
    assert config.terminals.model_dump() == {"plugin": "metric", "params": {"top_k": 2}}
    pipeline.plan(config, installed(), source=source)  # the metric selector's parameters validate
    same, _ = resolve_config("map_analysis", {"terminals.plugin": "coverage"})  # the same plugin keeps its parameters
    assert same.terminals.params == resolve_config("map_analysis")[0].terminals.params != {}
    kept, _ = resolve_config("map_analysis", {"terminals.params.plugin": 1})  # a parameter named plugin is a parameter
    assert kept.terminals.plugin == "coverage" and kept.terminals.params["plugin"] == 1


def test_an_in_memory_mesh_is_named_once_in_a_builders_error():
    speck = trimesh.creation.box(extents=(0.01, 0.01, 0.01))
    for name, start in ((None, "mesh: the level is less than one"), ("speck", "speck: mesh: the level is less than one")):
        with pytest.raises(G2SError) as raised:
            api.run(speck, "graph_only", mesh_name=name)
        assert str(raised.value).startswith(start), str(raised.value)  # was "mesh: mesh: the level ..."


@pytest.mark.parametrize("configs, inputs, what", [([], [CORRIDOR], "configs"), (["graph_only"], (), "inputs")])
def test_a_batch_of_no_config_or_no_level_is_refused(configs, inputs, what, tmp_path):
    # returned an empty summary, nothing run or said
    with pytest.raises(G2SError, match=f"^{what}: expected a list of .*, got an empty list$"):
        run_batch(configs, inputs, tmp_path / "out")
    assert not (tmp_path / "out").exists()


def test_one_level_file_by_two_spellings_is_one_level(tmp_path, monkeypatch):
    # was "./lv/../slab.obj: level name 'slab' is also that of slab.obj; rename one of the files"
    monkeypatch.chdir(tmp_path)
    (tmp_path / "lv").mkdir()
    (tmp_path / "slab.obj").write_text("v 0 0 0\nv 20 0 0\nv 20 0 20\nf 1 3 2\n")
    assert expand_inputs(["slab.obj", "./lv/../slab.obj", str(tmp_path / "slab.obj")]) == [("slab", "slab.obj")]
    (tmp_path / "lv" / "slab.obj").write_text("v 0 0 0\nv 20 0 0\nv 20 0 20\nf 1 3 2\n")
    with pytest.raises(G2SError, match="level name 'slab' is also that of slab.obj"):  # two files are two levels
        expand_inputs(["slab.obj", "lv/slab.obj"])


def test_every_public_name_of_the_api_module_is_documented():
    # open_mesh, execute, write_result, input_files and MeshSource were in api.__all__ but not in docs/python.md, and
    # ended in an AttributeError given a config or result of another type
    documented = set(re.findall(r"`(?:g2s_core\.)?(\w+)\(", (PROJECT / "docs" / "python.md").read_text()))
    assert set(api.__all__) <= documented, set(api.__all__) - documented
