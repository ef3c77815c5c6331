"""The g2s command line: exit codes, one-line errors, outputs, plugin listing."""

from __future__ import annotations

import json
import os
import re
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from g2s_core.cli import main
from g2s_core.stages import STAGES
from g2s_plugins.recast import RecastParams
from tests.conftest import PROJECT

G2S = [sys.executable, "-m", "g2s_core.cli"]


def g2s(*args: str, cwd: Path = PROJECT) -> subprocess.CompletedProcess:
    return subprocess.run([*G2S, *args], capture_output=True, text=True, cwd=cwd, env={**os.environ, "COLUMNS": "200"})


def assert_user_error(proc: subprocess.CompletedProcess, fragment: str) -> None:
    assert proc.returncode == 2, proc.stderr
    assert "Traceback" not in proc.stderr
    lines = [line for line in proc.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("g2s: error: ") and fragment in lines[0], proc.stderr


def test_help_lists_the_commands():
    proc = g2s("--help")
    assert proc.returncode == 0
    for command in ("run", "plugins", "demo", "batch"):
        assert command in proc.stdout


def test_a_command_plugin_that_fails_stops_only_its_own_command(monkeypatch, capsys):
    """A command whose hook raises or returns no function, or whose name is g2s's own: the other commands run;
    a command that raises is an internal error, as g2s's own commands are."""
    import types

    from g2s_core import cli, hookimpl
    from g2s_core.registry import Registry

    registry = Registry.from_entry_points()
    hooks = {"broken": lambda parser: parser.no_such_method(), "nothing": lambda parser: None,
             "crashes": lambda parser: lambda args: {}["key"], "run": lambda parser: lambda args: 7}
    for name, hook in hooks.items():
        plugin = types.ModuleType(name, f"the {name} command")
        plugin.NAME, plugin.g2s_command = name, hookimpl(hook)
        registry.register(plugin, package="tests", entry_point=f"commands.{name}")
    monkeypatch.setattr(cli, "installed", lambda: registry)
    assert main(["presets"]) == 0 and "map_analysis" in capsys.readouterr().out
    assert main(["broken"]) == 1  # the plugin's failure (exit 2 before robust9)
    assert capsys.readouterr().err.strip() == ("g2s: error: Command plugin 'broken' (package 'tests') failed: "
                                               "raised AttributeError: 'CommandParser' object has no attribute 'no_such_method'")
    assert main(["nothing"]) == 1
    assert capsys.readouterr().err.strip() == ("g2s: error: Command plugin 'nothing' (package 'tests') failed: "
                                               "returned NoneType, not a function run(args) -> exit code")
    assert main(["crashes"]) == 1  # the command's own exception: an internal error, as in g2s's own commands
    assert capsys.readouterr().err.splitlines() == ["g2s: internal error: KeyError: 'key'",
                                                    "(run again with --verbose for the traceback)"]
    with pytest.raises(SystemExit):  # g2s's own `run` keeps its name and its arguments
        main(["run"])
    assert "the following arguments are required: config, mesh" in capsys.readouterr().err


def test_bad_config_value(tmp_path):
    config = tmp_path / "bad.yaml"
    config.write_text("extends: graph_only\nagent: {radius: ten}\n")
    assert_user_error(g2s("run", str(config), "sample:straight_corridor", "-o", str(tmp_path / "out")),
                      "bad.yaml: agent.radius: expected a number > 0, got 'ten'")
    assert not (tmp_path / "out").exists()


def test_plugin_not_installed(tmp_path):
    config = tmp_path / "c.yaml"
    config.write_text("extends: graph_only\ngraph: {plugin: voxels}\n")
    assert_user_error(g2s("run", str(config), "sample:straight_corridor", "-o", str(tmp_path / "out")),
                      "graph.plugin: GraphBuilder plugin 'voxels' is not installed (installed: ")


def test_bad_plugin_parameter(tmp_path):
    config = tmp_path / "c.yaml"
    config.write_text("extends: graph_only\ngraph: {plugin: navmesh, params: {cell_size: -1}}\n")
    assert_user_error(g2s("run", str(config), "sample:straight_corridor", "-o", str(tmp_path / "out")),
                      "graph.params.cell_size: expected")
    config.write_text("extends: graph_only\ngraph: {plugin: navmesh, params: {partition: spiral}}\n")
    assert_user_error(g2s("run", str(config), "sample:straight_corridor", "-o", str(tmp_path / "out")),
                      "graph.params.partition: expected one of 'auto', 'watershed', 'monotone', 'layers', got 'spiral'")


def test_missing_mesh_and_unknown_sample(tmp_path):
    assert_user_error(g2s("run", "configs/graph_only.yaml", str(tmp_path / "nope.obj"), "-o", str(tmp_path / "o")), "no such mesh file")
    assert_user_error(g2s("run", "configs/graph_only.yaml", "sample:nope", "-o", str(tmp_path / "o")), "unknown sample 'nope'")


def test_argument_errors_exit_2():
    proc = g2s("run")
    assert proc.returncode == 2 and "Traceback" not in proc.stderr


def test_graph_only_run_writes_the_graph_and_refuses_to_overwrite(tmp_path):
    out = tmp_path / "out"
    proc = g2s("run", "configs/graph_only.yaml", "sample:straight_corridor", "-o", str(out))
    assert proc.returncode == 0, proc.stderr
    assert "Step 1" in proc.stdout and "initial graph" in proc.stdout
    graph = json.loads((out / "graph.json").read_text())
    assert len(graph["nodes"]) >= 1 and graph["mesh"]["name"] == "straight_corridor"
    before = (out / "graph.json").read_bytes()
    assert_user_error(g2s("run", "configs/graph_only.yaml", "sample:straight_corridor", "-o", str(out)), "use --force")
    assert (out / "graph.json").read_bytes() == before
    again = g2s("run", "configs/graph_only.yaml", "sample:straight_corridor", "-o", str(out), "--force")
    assert again.returncode == 0 and (out / "graph.json").read_bytes() == before


def test_json_summary_is_the_only_stdout(tmp_path):
    proc = g2s("run", "configs/graph_only.yaml", "sample:straight_corridor", "-o", str(tmp_path / "o"), "--json")
    assert proc.returncode == 0, proc.stderr
    summary = json.loads(proc.stdout)
    assert [s["stage"] for s in summary["stages"]] == ["graph"]


def test_a_reader_that_closes_stdout_early_is_no_internal_error(tmp_path):
    """`g2s run ... --json | head -c 100`: the results are written; stdout's reader left (exit 141, as a shell
    reports a process SIGPIPE ended; nothing on stderr) and g2s does not call it its own bug (exit 1)."""
    run = subprocess.Popen([*G2S, "run", "configs/graph_only.yaml", "sample:straight_corridor", "-o", str(tmp_path / "o"),
                            "--json"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=PROJECT)
    run.stdout.close()
    assert (run.stderr.read(), run.wait()) == ("", 141)
    assert (tmp_path / "o" / "graph.json").is_file()
    listing = subprocess.Popen([*G2S, "plugins"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=PROJECT)
    listing.stdout.close()
    assert (listing.stderr.read(), listing.wait()) == ("", 141)


def test_real_level_graph(tmp_path, shared_data):
    config = tmp_path / "recast_demo.yaml"
    config.write_text("extends: graph_only\nagent: {radius: 0.6, height: 2.0, max_climb: 0.9, max_slope: 45}\n"
                      "graph: {plugin: navmesh, params: {cell_size: 0.3, cell_height: 0.2}}\n")
    proc = g2s("run", str(config), str(shared_data / "nav_test.obj"), "-o", str(tmp_path / "out"), "--quiet")
    assert proc.returncode == 0, proc.stderr
    graph = json.loads((tmp_path / "out" / "graph.json").read_text())
    assert 100 <= len(graph["nodes"]) <= 220 and graph["mesh"]["name"] == "nav_test.obj"


def test_plugins_lists_stage_name_package_and_parameters():
    proc = g2s("plugins", "--stage", "graph")
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.startswith("graph\n  navmesh  (graph2structure)\n")
    assert "cell_size:" in proc.stdout
    # the region partition: its values, default and description (wrapped to the terminal)
    flat = " ".join(proc.stdout.split())
    description = RecastParams.model_fields["partition"].description
    assert f"partition: one of 'auto', 'watershed', 'monotone', 'layers', default 'auto'. {description}" in flat


def test_version_and_verbose_after_the_command(tmp_path):
    version = g2s("--version")
    assert version.returncode == 0 and version.stdout.startswith("g2s "), version.stdout + version.stderr
    config = tmp_path / "bad.yaml"
    config.write_text("extends: graph_only\nagent: {radius: ten}\n")
    for args in (("-v", "run", str(config)), ("run", str(config), "--verbose"), ("run", "-v", str(config))):
        proc = g2s(*args, "sample:straight_corridor", "-o", str(tmp_path / "out"))
        assert proc.returncode == 2 and "Traceback" in proc.stderr and "agent.radius" in proc.stderr, (args, proc.stderr)


def test_presets_by_name_and_listed(tmp_path):
    listing = g2s("presets")
    assert listing.returncode == 0, listing.stderr
    lines = {line.split()[0]: line for line in listing.stdout.splitlines() if line and not line.startswith(" ")}
    assert set(lines) >= {"base", "demo", "graph_only", "map_analysis", "map_piece"}
    assert "map analysis of a whole level" in lines["map_analysis"]
    assert "map_piece" in g2s("run", "--help").stdout

    proc = g2s("run", "graph_only", "sample:straight_corridor", "-o", str(tmp_path / "out"), "--json", cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    assert [s["stage"] for s in json.loads(proc.stdout)["stages"]] == ["graph"]
    assert_user_error(g2s("run", "no_such_preset", "sample:straight_corridor", "-o", str(tmp_path / "o")),
                      "no_such_preset: no such config file or preset (presets: base, demo,")


def test_set_overrides_reach_the_run(tmp_path):
    out = tmp_path / "out"
    proc = g2s("run", "map_piece", "sample:cross_hub", "-o", str(out), "--json", "--set", "agent.radius=0.3",
               "--set", "analyzers.0.key=hops", "--set", "stop_after=analyzers", "--set", "outputs.formats=[json]")
    assert proc.returncode == 0, proc.stderr
    structure = json.loads((out / "structure.json").read_text())
    assert structure["config"]["agent"]["radius"] == 0.3 and structure["analysis_keys"] == ["hops"]
    assert sorted(p.name for p in out.iterdir()) == ["run.json", "structure.json"]


@pytest.mark.parametrize("setting, fragment", [
    ("agent.radiuss=0.4", "--set agent.radiuss: unknown key 'radiuss' (expected one of: radius, height,"),
    ("agnet.radius=0.4", "--set agnet.radius: unknown key 'agnet' (expected one of: mesh, agent,"),
    ("agent.radius", "--set 'agent.radius': expected KEY=VALUE"),
    ("agent.radius=[1", "--set agent.radius: the value '[1' is not valid YAML"),
    ("agent.radius=-1", "map_piece: agent.radius: expected a number > 0, got -1"),
    ("analyzers.3.key=x", "--set analyzers.3.key: analyzers has no item 3 (it lists 1)"),
    # both were internal errors: int() of a 5000-digit index, and of a digit that is not 0-9
    ("analyzers." + "9" * 5000 + ".key=x", "--set 'analyzers." + "9" * 50 + "...' (5,014 characters): unknown key '999"),
    ("analyzers.\u00b2.key=x", "--set analyzers.\u00b2.key: unknown key '\u00b2' (expected one of: plugin, params, key)"),
    ("terminals.params.nope=1", "map_piece: terminals.params.nope: unknown key"),
])
def test_bad_set_is_a_clean_error(tmp_path, capsys, setting, fragment):
    # in this process: the subprocess tests above show the same path ends in one line and exit code 2
    code = main(["run", "map_piece", "sample:cross_hub", "-o", str(tmp_path / "o"), "--set", setting])
    err = capsys.readouterr().err
    assert code == 2 and err.startswith("g2s: error: ") and fragment in err and err.count("\n") == 1, err
    assert not (tmp_path / "o").exists()


def test_plugins_listing_fits_80_columns():
    proc = subprocess.run([*G2S, "plugins"], capture_output=True, text=True, cwd=PROJECT, env={**os.environ, "COLUMNS": "80"})
    assert proc.returncode == 0, proc.stderr
    lines = proc.stdout.splitlines()
    assert max(len(line) for line in lines) <= 80
    assert [line for line in lines if line and not line.startswith(" ")] == [stage.key for stage in STAGES]


@pytest.mark.parametrize(
    "args, says",
    [(["plugins", "--stage", "nope"], "argument --stage: invalid choice: 'nope' (choose from 'graph',"),
     (["frobnicate"], "argument COMMAND: invalid choice: 'frobnicate'"),
     (["run", "graph_only"], "the following arguments are required: mesh, -o/--outdir (see g2s run --help)"),
     (["demo", "--rooms", "x"], "argument --rooms: invalid int value: 'x'")],
    ids=["choice", "command", "missing", "type"],
)
def test_usage_errors_are_one_line_too(args, says):
    # argparse printed its usage line first: two lines, where a script relies on one
    assert_user_error(g2s(*args), says)


@pytest.mark.parametrize("command", [["run", "graph_only", "sample:straight_corridor"], ["batch", "graph_only", "sample:t_hub"]])
def test_an_empty_output_folder_name_is_refused(command, tmp_path):
    # `-o "$OUT"` with OUT unset: Path("") is the working folder, where the results went
    assert_user_error(g2s(*command, "-o", "", cwd=tmp_path), "argument -o/--outdir: expected a folder, got an empty name")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("args, says", [
    (["", "sample:t_hub"], "argument config: expected a preset name or a config file, got an empty name"),
    (["graph_only", " "], "argument mesh: expected a mesh file or sample:NAME, got an empty name")])
def test_an_empty_config_or_mesh_name_is_refused_not_read_as_the_working_folder(args, says, tmp_path):
    # was ".: expected a config file, got a folder" (".: expected a mesh file ..."): Path("") is the working folder
    assert_user_error(g2s("run", *args, "-o", tmp_path / "out", cwd=tmp_path), says)


@pytest.mark.parametrize("items", [["", "sample:t_hub"], ["graph_only", ""], ["graph_only", "sample:t_hub", " "]])
def test_an_empty_batch_config_or_level_is_refused_as_run_refuses_it(items, tmp_path):
    # a config "" was ": expected a preset name or a .yaml/.yml config first ..."; a level "" was the working
    # folder, searched for meshes, whose pairs then ran
    (tmp_path / "floor.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 3 2\n")
    assert_user_error(g2s("batch", *items, "-o", "out", cwd=tmp_path),
                      "argument CONFIG|INPUT: expected a preset, a config file or a level, got an empty name")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["floor.obj"]


def test_a_setting_given_twice_is_refused_not_the_last_one_kept(tmp_path):
    # YAML and URL queries both kept the last value silently: an agent 9 m wide, or a 3-room dungeon
    config = tmp_path / "twice.yaml"
    config.write_text("extends: graph_only\nagent: {radius: 0.3, radius: 9}\n")
    assert_user_error(g2s("run", str(config), "sample:t_hub", "-o", str(tmp_path / "out")),
                      "twice.yaml: invalid YAML at line 2, column 22: duplicate key 'radius' (first at line 2)")
    spec = "sample:dungeon?rooms=2&seed=1&rooms=3"
    assert_user_error(g2s("run", "graph_only", spec, "-o", str(tmp_path / "out")), f"{spec}: rooms is given twice")
    assert not (tmp_path / "out").exists()


def test_ctrl_c_while_the_console_script_loads_is_one_line(tmp_path):
    """Ctrl-C in the first half second of `g2s run` (pydantic, pluggy, rich and YAML loading) printed a traceback.
    The console script is signalled as soon as it has imported pydantic, which the command line needs: its other
    imports are still running (Python's import-time report, on stderr, says when each import ends).

    The script cannot run ahead to its end before the signal, however late this test reads: after pydantic it
    reports some 89 kB of imports, and it blocks once the pipe (64 kB) and this test's read-ahead (8 kB) are full.
    Where the signal lands varies with the load. It failed once under load 15 (robust5's full suite, 4 December
    2026): the Ctrl-C landed in a weakref callback of the import system, where Python can only print it
    ("Exception ignored in ..."), and the run went on and wrote its results; the command now remembers it, and
    test_ctrl_c_that_python_can_only_print_is_not_lost puts a Ctrl-C there every time."""
    script = Path(sys.executable).with_name("g2s")
    proc = subprocess.Popen([script, "run", "graph_only", "sample:straight_corridor", "-o", str(tmp_path / "out")],
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                            env={**os.environ, "PYTHONPROFILEIMPORTTIME": "1"},
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))  # as from a terminal
    imported = []  # "import time: self | cumulative | <indent>module" once each import ends
    for line in proc.stderr:
        imported.append(line.rpartition("|")[2].strip() if line.startswith("import time:") else line)
        if imported[-1] == "pydantic":
            proc.send_signal(signal.SIGINT)
            break
    rest = proc.stderr.read()
    proc.wait(timeout=60)
    assert "g2s_core.entry" in imported and "g2s_core.cli" not in imported  # signalled while the command line loaded
    said = [line.strip() for line in rest.splitlines() if line.strip() and not line.startswith("import time:")]
    assert (proc.returncode, said) == (130, ["g2s: interrupted"]), rest
    assert not (tmp_path / "out").exists()


CTRL_C_IN_A_DESTRUCTOR = """
import os, signal, sys

class Dropped:
    def __del__(self):  # Python can only print what is raised here ("Exception ignored in ...")
        os.kill(os.getpid(), signal.SIGINT)

class Finder:  # the Ctrl-C comes as the module sys.argv[1] starts to load
    def find_spec(self, name, path=None, target=None):
        if name == module:
            sys.meta_path.remove(self)
            Dropped()
        return None

module = sys.argv.pop(1)
sys.meta_path.insert(0, Finder())
from g2s_core.entry import main
sys.exit(main())
"""


@pytest.mark.parametrize("module", ["pydantic", "trimesh"])
def test_ctrl_c_that_python_can_only_print_is_not_lost(module, tmp_path):
    """A Ctrl-C that lands in a destructor or a weakref callback (the import system's, as the command line loads
    pydantic, under load) is one Python cannot raise: it printed "Exception ignored in ..." with a traceback and
    dropped it, and the run went on and wrote its results (exit 0; as trimesh loads, exit 130 after those lines).
    It made test_ctrl_c_while_the_console_script_loads_is_one_line fail once under load 15."""
    proc = subprocess.run([sys.executable, "-c", CTRL_C_IN_A_DESTRUCTOR, module, "run", "graph_only",
                           "sample:straight_corridor", "-o", str(tmp_path / "out"), "-q"],
                          capture_output=True, text=True, timeout=120,
                          preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))  # as from a terminal
    assert (proc.returncode, proc.stderr) == (130, "g2s: interrupted\n")
    assert not (tmp_path / "out").exists()


def test_ctrl_c_that_a_plugins_import_swallows_while_the_commands_load_stops_the_command(monkeypatch, capsys):
    # the console script takes a Ctrl-C from its start; one swallowed before `g2s presets` ran was lost (exit 0)
    from g2s_core import cli, entry

    def installed(real=cli.installed):  # loads the plugins, whose imports may catch BaseException as trimesh's do
        try:
            os.kill(os.getpid(), signal.SIGINT)
        except BaseException:
            pass
        return real()

    monkeypatch.setattr(cli, "installed", installed)
    monkeypatch.setattr(sys, "argv", ["g2s", "presets"])
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)  # as from a terminal
    try:
        code = entry.main()
    finally:
        signal.signal(signal.SIGINT, previous)
    assert (code, capsys.readouterr()) == (130, ("", "g2s: interrupted\n"))


def test_ctrl_c_while_trimesh_imports_is_not_lost(tmp_path, swallowed_ctrl_c, capsys):
    """trimesh's imports catch BaseException (its optional dependencies), a KeyboardInterrupt among them: a Ctrl-C
    in the first second of a run was lost and the run wrote its results. It is remembered, and stops the run at
    its next step."""
    from g2s_core import cli

    swallowed_ctrl_c(cli, "api")
    assert main(["run", "graph_only", "sample:straight_corridor", "-o", str(tmp_path / "out"), "-q"]) == 130
    assert capsys.readouterr().err.strip() == "g2s: interrupted"
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("args, says", [
    (["--format", "x" * 100_000], "--format: unknown output format '" + "x" * 60 + "...' (100,000 characters) (expected some of: "),
    (["--set", "graph.plugin=" + "x" * 100_000],
     "map_piece: graph.plugin: GraphBuilder plugin '" + "x" * 60 + "...' (100,000 characters) is not installed (installed: "),
])
def test_a_name_of_100000_characters_is_cut_short_in_the_message(args, says, tmp_path, capsys):
    # the whole name was repeated: one line of 100 kB
    assert main(["run", "map_piece", "sample:straight_corridor", "-o", str(tmp_path / "out"), *args]) == 2
    error = capsys.readouterr().err
    assert error.startswith(f"g2s: error: {says}") and len(error) < 300 and error.count("\n") == 1


@pytest.mark.parametrize("config", ["loop.yaml", "extends_loop.yaml"])
def test_a_config_that_is_a_link_to_itself_is_a_clean_error(config, tmp_path, capsys, monkeypatch):
    # was exit 1, "internal error: RuntimeError: Symlink loop from '.../loop.yaml'" (Path.resolve)
    monkeypatch.chdir(tmp_path)
    (tmp_path / "loop.yaml").symlink_to("loop.yaml")
    (tmp_path / "extends_loop.yaml").write_text("extends: loop.yaml\n")
    assert main(["run", config, "sample:straight_corridor", "-o", "out"]) == 2
    assert capsys.readouterr().err == "g2s: error: loop.yaml: cannot read config file (Too many levels of symbolic links)\n"


@pytest.mark.parametrize("setting, says", [
    ("agent.rad\nius=1", "--set 'agent.rad\\nius': unknown key 'rad\\nius' (expected one of: radius, height, max_climb, "
                         "max_slope)"),  # the newline itself: two lines
    ("evaluators.0.plugin=traffic", "--set evaluators.0.plugin: evaluators has no item 0 (it lists 0)"),  # was "map_analysis:
    # evaluators: expected a list of mappings, got a mapping": the index made a mapping of the list map_analysis leaves out
])
def test_a_set_key_with_a_newline_or_an_index_into_nothing_is_one_clear_line(setting, says, tmp_path, capsys):
    assert main(["run", "map_analysis", "sample:straight_corridor", "-o", str(tmp_path / "out"), "--set", setting]) == 2
    assert capsys.readouterr().err == f"g2s: error: {says}\n"


@pytest.mark.parametrize("setting", ["agent.max_climb=5", "agent.height=1e-308"])
def test_an_agent_that_climbs_its_own_height_is_run_by_entry_exit(setting, tmp_path, capsys):
    # was "TerminalSelector plugin 'entry_exit' (package 'graph2structure') failed: raised ValueError: cannot reshape
    # array of size 0 into shape (0,newaxis)": no height was left between the climb and the head-room ray to search
    assert main(["run", "map_piece", "sample:straight_corridor", "-o", str(tmp_path / "out"), "-q", "--set", setting]) == 0
    assert all(line.startswith("g2s: warning: ") for line in capsys.readouterr().err.splitlines())  # none found, maybe


def test_a_batch_with_links_to_themselves_is_no_internal_error(tmp_path, capsys, monkeypatch):
    # both were exit 1, "internal error: RuntimeError: Symlink loop from ...": Path.resolve of the config, and of a
    # folder's entries when the output folder lies inside the folder
    monkeypatch.chdir(tmp_path)
    (tmp_path / "levels").mkdir()
    (tmp_path / "levels" / "floor.obj").write_text("v 0 0 0\nv 20 0 0\nv 20 0 20\nv 0 0 20\nf 1 3 2\nf 1 4 3\n")
    (tmp_path / "levels" / "self.obj").symlink_to("self.obj")
    (tmp_path / "loop.yaml").symlink_to("loop.yaml")
    assert main(["batch", "loop.yaml", "levels", "-o", "runs"]) == 2
    assert capsys.readouterr().err == "g2s: error: loop.yaml: cannot read config file (Too many levels of symbolic links)\n"
    assert main(["batch", "graph_only", "levels", "-o", "levels/runs", "-q"]) == 4
    assert capsys.readouterr().err == ("g2s: graph_only on self failed: levels/self.obj: cannot read mesh file "
                                       "(Too many levels of symbolic links)\n")


@pytest.mark.parametrize("preset, level, says", [
    ("map_piece", "sample:straight_corridor", "straight_corridor: 3 structure nodes, 2 openings"),
    ("level_regions", "sample:two_rooms_one_door", "two_rooms_one_door: 6 structure nodes, 1 chokepoint, 2 regions"),
    # truth27: graph_only stops at step 1, and said "83 structure nodes" of the initial graph
    ("graph_only", "sample:dungeon", "dungeon: 83 graph nodes"),
])
def test_run_says_what_came_out_after_the_stage_table(preset, level, says, tmp_path, capsys):
    # robust7: the table gave step counts only; a designer had to open structure.json for a piece's openings
    assert main(["run", preset, level, "-o", str(tmp_path / "out")]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert says in lines and lines.index(says) == lines.index(next(l for l in lines if l.startswith("wrote "))) - 1


def test_the_outcome_line_counts_the_warnings_above_it(tmp_path, capsys):
    # robust8: a heat guarantee short of its target (or any warning) was one stderr line above the stage table, and
    # the last line a new user reads, what came out, did not hint at it
    def outcome(*overrides: str) -> tuple[str, str]:
        assert main(["run", "map_analysis", "sample:dungeon", *overrides, "-o", str(tmp_path / str(len(overrides)))]) == 0
        captured = capsys.readouterr()
        return next(line for line in captured.out.splitlines() if line.startswith("dungeon: ")), captured.err

    said, warned = outcome()
    assert re.fullmatch(r"dungeon: \d+ structure nodes", said) and warned == ""
    said, warned = outcome("--set", "simplify.params.min_heat_rho=1")
    assert warned.count("g2s: warning: the heat map ranks the polygons") == 1 and warned.count("g2s: warning:") == 1
    assert re.fullmatch(r"dungeon: \d+ structure nodes; 1 warning above", said)
