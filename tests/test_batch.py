"""Batch runs: the same results as `g2s run` on every executor, failures recorded, resume, one row per pair."""

from __future__ import annotations

import json
import os
import re
import resource
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pandas as pd
import pytest

from g2s_plugins.batch.runner import METRIC_PREFIX, RECORDS, expand_inputs, run_batch
from g2s_core import load_result
from g2s_core.cli import main
from g2s_core.errors import G2SError
from g2s_plugins.samples.levels import dungeon
from tests.conftest import PROJECT

CONFIG = str(PROJECT / "configs" / "map_analysis.yaml")
SAMPLES = ["sample:dungeon?seed=1&rooms=12", "sample:dungeon?seed=2&rooms=14"]
TIMES = [c for c in ("seconds_load", "seconds_graph", "seconds_terminals", "seconds_steiner", "seconds_loops",
                     "seconds_roots", "seconds_simplify", "seconds_analyzers", "seconds_write", "seconds_total")]


@pytest.fixture(scope="module")
def levels(tmp_path_factory) -> Path:
    """A folder of levels: a generated dungeon as OBJ, one in a subfolder as PLY, and a broken OBJ."""
    folder = tmp_path_factory.mktemp("levels")
    dungeon(seed=3, rooms=15).mesh.export(folder / "three.obj")
    (folder / "more").mkdir()
    dungeon(seed=4, rooms=10).mesh.export(folder / "more" / "four.ply")
    (folder / "broken.obj").write_text("v 0 0 0\nv 1 0 nan\nv 0 0 1\nf 1 2 3\n")
    (folder / "notes.txt").write_text("not a level")
    return folder


def g2s(capsys, *args: str) -> tuple[int, str, str]:
    """``g2s ARGS`` in this process (the command's own code, without a second interpreter's start-up)."""
    capsys.readouterr()
    code = main(list(args))
    out, err = capsys.readouterr()
    return code, out, err


def assert_user_error(result: tuple[int, str, str], fragment: str) -> None:
    code, _, err = result
    lines = [line for line in err.splitlines() if line.strip()]
    assert code == 2 and len(lines) == 1 and lines[0].startswith("g2s: error: ") and fragment in lines[0], err


def comparable(summary: pd.DataFrame) -> pd.DataFrame:
    """The summary without wall times and result-folder paths, which differ between runs."""
    return summary.drop(columns=[*TIMES, "folder"]).reset_index(drop=True)


@pytest.fixture(scope="module")
def serial(levels, tmp_path_factory) -> tuple[Path, pd.DataFrame]:
    out = tmp_path_factory.mktemp("serial") / "out"
    return out, run_batch([CONFIG], [str(levels), *SAMPLES], out, "serial", formats="json")


def test_serial_pairs_are_what_g2s_run_writes(serial, levels, tmp_path, capsys):
    out, summary = serial
    assert list(summary["level"]) == ["broken", "more/four", "three", *[
        "dungeon_seed_1_rooms_12", "dungeon_seed_2_rooms_14"]]
    ok = summary[summary["status"] == "ok"]
    assert len(ok) == 4
    for row in ok.itertuples():
        single = tmp_path / row.level.replace("/", "_")
        code, out, err = g2s(capsys, "run", CONFIG, row.input, "-o", str(single), "--format", "json", "--json")
        assert code == 0, err
        assert (Path(row.folder) / "structure.json").read_bytes() == (single / "structure.json").read_bytes()
        stages = {s["stage"]: s for s in json.loads(out)["stages"]}
        assert row.nodes_graph == stages["graph"]["nodes"] and row.edges_graph == stages["graph"]["edges"]
        # both count the terminals without the waypoints, which step 2's count includes
        assert row.terminals == json.loads(out)["final"]["terminals"] <= stages["terminals"]["terminals"]
        assert row.nodes_simplify == stages["simplify"]["nodes"]
        assert row.flow_max > 0 and row.structure_length > 0 and row.openings == 0


def test_a_broken_level_is_recorded_and_the_batch_goes_on(serial):
    out, summary = serial
    broken = summary.set_index("level").loc["broken"]
    assert broken["status"] == "failed" and "broken.obj" in broken["error"] and "'nan' is not a finite number" in broken["error"]
    assert not (out / "map_analysis" / "broken").exists()
    on_disk = pd.read_parquet(out / "summary.parquet")
    pd.testing.assert_frame_equal(on_disk, summary)
    assert len(pd.read_csv(out / "summary.csv")) == len(summary)


@pytest.mark.parametrize("executor", ["local", "dask"])
def test_every_executor_gives_the_serial_rows(executor, serial, levels, tmp_path):
    summary = run_batch([CONFIG], [str(levels), *SAMPLES], tmp_path / "out", executor, workers=2, formats="json")
    pd.testing.assert_frame_equal(comparable(summary), comparable(serial[1]))
    for level in ("three", "more/four", "dungeon_seed_1_rooms_12"):
        made = tmp_path / "out" / "map_analysis" / level / "structure.json"
        assert made.read_bytes() == (serial[0] / "map_analysis" / level / "structure.json").read_bytes()


def test_resume_skips_finished_pairs_and_force_recomputes(levels, tmp_path):
    out = tmp_path / "out"
    first = run_batch([CONFIG], [str(levels)], out, "serial", formats="json")
    structure = out / "map_analysis" / "three" / "structure.json"
    written = structure.stat().st_mtime_ns
    again = run_batch([CONFIG], [str(levels)], out, "serial", formats="json")
    assert list(again["reused"]) == [False, True, True]  # the broken level is tried again
    assert structure.stat().st_mtime_ns == written
    pd.testing.assert_frame_equal(again.drop(columns="reused"), first.drop(columns="reused"), check_exact=False,
                                  rtol=1, atol=100)  # times of the broken level's new try differ
    other_formats = run_batch([CONFIG], [str(levels)], out, "serial", formats="json,graphml")
    assert not other_formats["reused"].any()
    assert (out / "map_analysis" / "three" / "structure.graphml").is_file()
    forced = run_batch([CONFIG], [str(levels)], out, "serial", formats="json,graphml", force=True)
    assert not forced["reused"].any() and structure.stat().st_mtime_ns != written


def test_a_missing_result_file_makes_the_pair_run_again(levels, tmp_path):
    out = tmp_path / "out"
    run_batch([CONFIG], SAMPLES[:1], out, "serial", formats="json")
    (out / "map_analysis" / "dungeon_seed_1_rooms_12" / "structure.json").unlink()
    again = run_batch([CONFIG], SAMPLES[:1], out, "serial", formats="json")
    assert not again["reused"].any()
    assert (out / "map_analysis" / "dungeon_seed_1_rooms_12" / "structure.json").is_file()


def test_two_configs_give_one_row_per_pair(levels, tmp_path):
    predicate = tmp_path / "never.yaml"
    predicate.write_text(f"extends: {CONFIG}\nsimplify:\n  plugin: never\n")
    summary = run_batch([CONFIG, predicate], [str(levels / "three.obj"), *SAMPLES], tmp_path / "out", "local",
                        workers=2, formats="json")
    assert list(zip(summary["config"], summary["level"])) == [
        (config, level) for config in ("map_analysis", "never")
        for level in ("three", "dungeon_seed_1_rooms_12", "dungeon_seed_2_rooms_14")]
    by_config = summary.set_index(["config", "level"])
    assert (by_config.loc["never", "nodes_simplify"].to_numpy() > by_config.loc["map_analysis", "nodes_simplify"]
            .to_numpy()).all()
    assert (tmp_path / "out" / "never" / "three" / "structure.json").is_file()


def test_an_interrupted_batch_keeps_its_finished_pairs(tmp_path):
    out = tmp_path / "out"

    def stop_after_first(counts) -> None:
        if counts.done == 1:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        run_batch([CONFIG], SAMPLES, out, "serial", formats="json", progress=stop_after_first)
    summary = pd.read_csv(out / "summary.csv")
    assert list(summary["level"]) == ["dungeon_seed_1_rooms_12"]
    assert not (out / "map_analysis" / "dungeon_seed_2_rooms_14").exists()
    resumed = run_batch([CONFIG], SAMPLES, out, "serial", formats="json")
    assert list(resumed["reused"]) == [True, False]


def test_inputs_files_folders_globs_and_samples(levels, tmp_path):
    expanded = expand_inputs([str(levels / "*.obj"), str(levels / "more"), "sample:dungeon?rooms=3"])
    assert [name for name, _ in expanded] == ["broken", "three", "four", "dungeon_rooms_3"]
    with pytest.raises(G2SError, match="matches no files"):
        expand_inputs([str(levels / "*.gltf")])
    assert len(expand_inputs([str(levels / "three.obj"), str(levels / "*.obj")])) == 2  # the same file once
    (tmp_path / "three.stl").write_text("solid empty\nendsolid empty\n")
    with pytest.raises(G2SError, match="level name 'three' is also that of"):
        expand_inputs([str(levels / "three.obj"), str(tmp_path / "three.stl")])


def test_a_folder_keeps_what_is_named_like_a_mesh_but_is_no_file(levels, tmp_path, capsys):
    """A link to nothing and a FIFO named like mesh files are levels whose pairs fail with the reader's one line
    (they were left out without a word); a folder named like one is searched, not taken."""
    folder = tmp_path / "levels"
    (folder / "act.obj").mkdir(parents=True)
    (folder / "act.obj" / "three.obj").write_bytes((levels / "three.obj").read_bytes())
    (folder / "gone.obj").symlink_to(tmp_path / "nothing.obj")
    os.mkfifo(folder / "pipe.obj")
    assert [name for name, _ in expand_inputs([str(folder)])] == ["act.obj/three", "gone", "pipe"]
    out = tmp_path / "out"
    code, stdout, stderr = g2s(capsys, "batch", "graph_only", str(folder), "-o", str(out), "--format", "json")
    assert code == 4, stderr
    assert "3 pairs: 1 ok (0 already finished), 2 failed" in stdout
    assert sorted(line.split(": ", 1)[1] for line in stderr.splitlines() if line.strip()) == [
        f"graph_only on gone failed: {folder / 'gone.obj'}: no such mesh file",
        f"graph_only on pipe failed: {folder / 'pipe.obj'}: expected a mesh file, got a FIFO"]


def test_cli_batch_reports_failures_and_writes_the_summary(levels, tmp_path, capsys):
    out = tmp_path / "out"
    code, stdout, stderr = g2s(capsys, "batch", CONFIG, str(levels), "sample:dungeon?rooms=4", "-o", str(out),
                               "--workers", "2", "--format", "json")
    assert code == 4, stderr
    lines = [line for line in stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("g2s: map_analysis on broken failed: ") and "'nan' is not a finite number" in lines[0]
    assert "4 pairs: 3 ok (0 already finished), 1 failed" in stdout
    assert (out / "summary.parquet").is_file() and (out / RECORDS).is_dir()


def test_cli_batch_bad_input_is_one_line(levels, tmp_path, capsys):
    assert_user_error(g2s(capsys, "batch", CONFIG, str(levels / "nothing*.obj"), "-o", str(tmp_path / "a")),
                      "nothing*.obj: the pattern matches no files")
    assert_user_error(g2s(capsys, "batch", CONFIG, "-o", str(tmp_path / "a")),
                      f"batch: expected one or more levels after the configs ({CONFIG})")
    # a misspelt preset was "batch: expected one or more configs ... followed by one or more levels", not named
    assert_user_error(g2s(capsys, "batch", "map_anaylsis", "sample:dungeon", "-o", str(tmp_path / "a")),
                      "map_anaylsis: expected a preset name or a .yaml/.yml config first, then one or more levels (presets: ")
    bad = tmp_path / "bad.yaml"
    bad.write_text("extends: map_analysis\nsimplify: {plugin: nope}\n")
    assert_user_error(g2s(capsys, "batch", str(bad), "sample:dungeon", "-o", str(tmp_path / "a")),
                      "bad.yaml: simplify.plugin")
    (tmp_path / "mine").mkdir()
    (tmp_path / "mine" / "keep.txt").write_text("mine")
    assert_user_error(g2s(capsys, "batch", CONFIG, "sample:dungeon", "-o", str(tmp_path / "mine")),
                      "not a g2s batch's")
    assert (tmp_path / "mine" / "keep.txt").read_text() == "mine"


def test_cli_batch_executor_is_any_installed_one_with_its_own_parameters(tmp_path, capsys):
    # the options are named as given; before 3 December 2026 as run_batch's parameters ("executor: ...",
    # "executor 'local' params.scheduler: unknown key (expected one of: workers)", "evaluators: ...")
    assert_user_error(g2s(capsys, "batch", CONFIG, SAMPLES[0], "-o", str(tmp_path / "a"), "--executor", "ray"),
                      "--executor: Executor plugin 'ray' is not installed (installed: dask, local, serial)")
    assert_user_error(g2s(capsys, "batch", CONFIG, SAMPLES[0], "-o", str(tmp_path / "a"), "--scheduler", "tcp://x:1"),
                      "--scheduler: the local executor takes no scheduler (see g2s plugins --stage executors)")
    assert_user_error(g2s(capsys, "batch", CONFIG, SAMPLES[0], "-o", str(tmp_path / "a"), "--executor", "serial",
                          "--workers", "2"), "--workers: the serial executor takes no workers")
    assert_user_error(g2s(capsys, "batch", CONFIG, SAMPLES[0], "-o", str(tmp_path / "a"), "--evaluate", "traffic,nope"),
                      "--evaluate: Evaluator plugin 'nope' is not installed")
    assert not (tmp_path / "a").exists()
    code, out, _ = g2s(capsys, "plugins", "--stage", "executors")
    assert code == 0 and [line.split()[0] for line in out.splitlines() if line.startswith("  ") and not
                          line.startswith("    ")] == ["dask", "local", "serial"]


def test_evaluated_pairs_get_the_metric_columns_of_their_structure_json(tmp_path):
    out = tmp_path / "out"
    plain = run_batch([CONFIG], SAMPLES, out, "serial", formats="json")
    assert not any(c.startswith(METRIC_PREFIX) for c in plain.columns)
    evaluated = run_batch([CONFIG], SAMPLES, out, "serial", formats="json", evaluators=["traffic"])
    assert not evaluated["reused"].any()  # another config: the evaluator is part of it
    names = ["area_within_10m", "area_within_3m", "area_within_6m", "navmesh_area_left_out", "rho",
             "rho_area", "rho_area_betweenness", "rho_ceiling", "rho_navmesh", "rho_navmesh_ceiling", "rho_within",
             "rho_within_ceiling", "structure_share", "traffic_off"]
    assert [c for c in evaluated.columns if c.startswith(METRIC_PREFIX)] == [f"metric.traffic.{n}" for n in names]
    for row in evaluated.to_dict("records"):
        metrics = json.loads((Path(row["folder"]) / "structure.json").read_text())["metrics"]["traffic"]
        assert {n: row[f"metric.traffic.{n}"] for n in names} == pytest.approx(metrics, rel=1e-8)
        assert row["metric.traffic.area_within_6m"] >= row["metric.traffic.area_within_3m"]
        assert row["seconds_evaluators"] > 0
    assert list(run_batch([CONFIG], SAMPLES, out, "serial", formats="json", evaluators=["traffic"])["reused"]) == [
        True, True]


def test_cli_batch_on_a_running_dask_scheduler(tmp_path, capsys):
    from dask.distributed import LocalCluster

    with LocalCluster(n_workers=1, threads_per_worker=1, processes=False, dashboard_address=":0") as cluster:
        code, stdout, stderr = g2s(capsys, "batch", CONFIG, SAMPLES[0], "-o", str(tmp_path / "out"), "--format", "json",
                                   "--executor", "dask", "--scheduler", cluster.scheduler_address)
    assert code == 0, stderr
    assert pd.read_csv(tmp_path / "out" / "summary.csv")["status"].tolist() == ["ok"]


def test_cli_batch_names_a_scheduler_address_that_is_no_dask_scheduler(tmp_path, capsys):
    assert_user_error(g2s(capsys, "batch", CONFIG, SAMPLES[0], "-o", str(tmp_path / "out"), "--executor", "dask",
                          "--scheduler", "bogus://x"),
                      "--scheduler: expected the address of a running Dask scheduler (tcp://host:8786), got 'bogus://x': "
                      "unknown address scheme 'bogus'")
    assert not (tmp_path / "out").exists()


def test_cli_batch_without_the_extra_says_how_to_install_it(monkeypatch, tmp_path, capsys):
    monkeypatch.setitem(sys.modules, "pandas", None)
    assert_user_error(g2s(capsys, "batch", CONFIG, SAMPLES[0], "-o", str(tmp_path / "out")),
                      "[batch]' (pandas, pyarrow, dask.distributed")
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("executor", ["local", "dask"])
def test_ctrl_c_stops_cleanly_and_keeps_the_finished_pairs(executor, tmp_path):
    """Ctrl-C at a terminal interrupts the whole process group: g2s and its workers."""
    out = tmp_path / "out"
    records = out / RECORDS / "map_analysis"
    levels = [f"sample:dungeon?seed={seed}&rooms=60" for seed in range(30)]
    proc = subprocess.Popen(
        [sys.executable, "-m", "g2s_core.cli", "batch", CONFIG, *levels, "-o", str(out), "--format", "json",
         "--executor", executor, "--workers", "2"],
        cwd=PROJECT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True,
        preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL),  # as from a terminal, not a background job
    )
    deadline = time.monotonic() + 120
    while len(list(records.glob("*.json"))) < 2 and proc.poll() is None and time.monotonic() < deadline:
        time.sleep(0.1)
    os.killpg(proc.pid, signal.SIGINT)
    _, stderr = proc.communicate(timeout=120)
    assert proc.returncode == 130 and stderr.strip() == "g2s: interrupted", stderr
    finished = sorted(p.stem for p in records.glob("*.json"))
    assert 2 <= len(finished) < len(levels)
    assert sorted(pd.read_csv(out / "summary.csv")["level"]) == finished
    folders = sorted(p.name for p in (out / "map_analysis").iterdir())
    # the pool lets its running pairs finish; Dask drops them with their workers (a re-run recomputes them)
    assert folders == finished if executor == "local" else set(finished) <= set(folders)
    resumed = run_batch([CONFIG], levels[:3], out, "serial", formats="json")
    assert list(resumed["reused"]) == [f"dungeon_seed_{seed}_rooms_60" in finished for seed in range(3)]


def test_a_ctrl_c_inside_the_pools_wait_is_acted_on_once_the_pool_has_shut_down(monkeypatch):
    """Raised inside concurrent.futures' wait, a KeyboardInterrupt could leave a lock held and the pool's shutdown
    waited for ever (the Ctrl-C test above hung on CI): the pool takes it between waits."""
    from concurrent.futures import wait

    from g2s_plugins.executors import process_pool

    returned = []

    def wait_interrupted(*args, **kwargs):
        signal.raise_signal(signal.SIGINT)
        returned.append(wait(*args, **kwargs))
        return returned[-1]

    monkeypatch.setattr(process_pool, "wait", wait_interrupted)
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)  # pytest-xdist's workers may ignore SIGINT
    try:
        rows = process_pool.g2s_execute(function=abs, items=[-1, -2, -3], params=process_pool.Params(workers=1),
                                        lost=None)
        with pytest.raises(KeyboardInterrupt):
            list(rows)
    finally:
        signal.signal(signal.SIGINT, previous)
    assert len(returned) == 1


def test_chokepoints_and_regions_are_summed_up(tmp_path):
    summary = run_batch(["level_regions"], ["sample:dungeon?seed=1&rooms=30"], tmp_path / "out", "serial",
                        formats="json")
    row = summary.iloc[0]
    assert row["status"] == "ok" and row["config"] == "level_regions"
    features = json.loads((Path(row["folder"]) / "structure.json").read_text())["features"]
    chokepoints, regions = features["chokepoints"]["chokepoints"], features["regions"]["regions"]
    assert row["chokepoints_count"] == len(chokepoints) > 0 and row["regions_count"] == len(regions) > 1
    assert row["chokepoints_top_score"] == pytest.approx(max(c["score"] for c in chokepoints))
    assert row["chokepoints_top_score"] == pytest.approx(row["chokepoints_max"])  # the score near its nodes
    assert row["regions_largest_area"] == pytest.approx(max(r["area"] for r in regions))


def test_the_python_example_of_docs_batch_md_runs_as_written(tmp_path):
    """The script of docs/batch.md "From Python", as a user saves and runs it, on a folder of small generated levels."""
    (block,) = re.findall(r"^```python\n(.*?)^```$", (PROJECT / "docs" / "batch.md").read_text(), re.MULTILINE | re.DOTALL)
    (tmp_path / "compare.py").write_text(block)
    (tmp_path / "levels").mkdir()
    for seed in (5, 6):
        dungeon(seed=seed, rooms=6).mesh.export(tmp_path / "levels" / f"dungeon{seed}.obj")
    done = subprocess.run([sys.executable, "compare.py"], cwd=tmp_path, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    summary = pd.read_parquet(tmp_path / "predicates" / "summary.parquet")
    assert sorted(zip(summary["config"], summary["level"])) == [
        (config, level) for config in ("mesh_los", "surface") for level in ("dungeon5", "dungeon6")]
    assert (summary["status"] == "ok").all() and summary["metric.traffic.rho"].between(-1, 1).all()
    assert all(word in done.stdout for word in ("dungeon5", "dungeon6", "metric.traffic.rho"))
    last = done.stdout.splitlines()[-2:]  # the means per config close the output
    assert [line.split()[0] for line in last] == ["mesh_los", "surface"] and all(len(line.split()) == 5 for line in last)


def test_issue_13s_python_path_still_imports_the_runner():
    """docs/batch.md: ``g2s_core.batch`` re-exports the batch plugin's runner, so that scripts using it keep working."""
    import g2s_core.batch
    from g2s_plugins.batch import runner

    assert g2s_core.batch.__all__ and all(getattr(g2s_core.batch, name) is getattr(runner, name)
                                          for name in g2s_core.batch.__all__)
    assert {"run_batch", "run_pair", "Pair", "Progress", "COLUMNS", "RECORDS", "METRIC_PREFIX"} <= set(g2s_core.batch.__all__)


def test_an_analyzer_key_like_a_count_column_is_summed_up_as_values(tmp_path):
    """`key: edges` gives the columns edges_max, edges_mean (floats) and edges_top_node, beside the edges_* counts
    (the summary's typing took edges_max for a count: an internal error once every pair had run)."""
    config = tmp_path / "edges.yaml"
    config.write_text("extends: map_analysis\nanalyzers: [{plugin: betweenness, key: edges}]\n")
    summary = run_batch([str(config)], [SAMPLES[0]], tmp_path / "out", "serial", formats="json")
    row = summary.iloc[0]
    values = load_result(row["folder"]).analysis["edges"]
    assert row["status"] == "ok" and row["edges_max"] == pytest.approx(max(values.values()))
    assert str(summary["edges_max"].dtype) == "float64" and str(summary["edges_steiner"].dtype) == "Int64"


def test_cli_batch_outdir_under_a_file_is_one_line(tmp_path, capsys):
    (tmp_path / "level.obj").write_text("v 0 0 0\n")
    assert_user_error(g2s(capsys, "batch", CONFIG, SAMPLES[0], "-o", str(tmp_path / "level.obj" / "out")),
                      "level.obj/out: cannot create the folder, ")


def test_a_config_given_twice_runs_once_as_a_level_given_twice(tmp_path):
    """`map_analysis map_analysis` was refused: 'config name 'map_analysis' is also that of map_analysis; rename one
    of the files'; a level given twice ran once."""
    summary = run_batch(["map_analysis", CONFIG], [SAMPLES[0], SAMPLES[0]], tmp_path / "out", "serial", formats="json")
    assert list(summary["config"]) == ["map_analysis"] and list(summary["status"]) == ["ok"]
    other = tmp_path / "map_analysis.yaml"
    other.write_text("extends: map_analysis\n")
    with pytest.raises(G2SError, match="config name 'map_analysis' is also that of map_analysis; rename one"):
        run_batch(["map_analysis", str(other)], [SAMPLES[0]], tmp_path / "other", "serial", formats="json")


def test_ctrl_c_that_a_library_swallows_still_stops_the_batch(tmp_path, swallowed_ctrl_c, capsys):
    """trimesh's imports catch BaseException, a KeyboardInterrupt among them: a Ctrl-C while the batch's first pair
    loaded them was lost and the batch ran to its end (exit 0; 2,400 rooms: 11 s after a Ctrl-C at 2 s)."""
    from g2s_plugins.batch import runner

    swallowed_ctrl_c(runner, "api")  # the pipeline is taken through the API (robust44)
    out = tmp_path / "out"
    code, _, err = g2s(capsys, "batch", "graph_only", "sample:t_hub", "-o", str(out), "--executor", "serial", "-q")
    assert (code, err.strip()) == (130, "g2s: interrupted")
    assert not (out / "graph_only" / "t_hub").exists() and not (out / "summary.csv").exists()


WRITE_SUMMARY_LIMITED = """
import resource, sys
from pathlib import Path
import pandas as pd
from g2s_core.errors import G2SError
from g2s_plugins.batch.runner import write_summary
resource.setrlimit(resource.RLIMIT_FSIZE, (int(sys.argv[2]), int(sys.argv[2])))
try:
    write_summary(pd.DataFrame({"level": [f"level_{i}" for i in range(3000)], "nodes": range(3000)}), Path(sys.argv[1]))
except G2SError as exc:
    print(exc)
"""


def test_a_summary_the_storage_refuses_is_one_line_and_keeps_the_earlier_one(tmp_path):
    """A full disk or `ulimit -f` while the summary was written was `internal error: OSError: [Errno 28] Error
    writing bytes to file ...` (exit 1), left `.summary.parquet.tmp`, and could replace one summary file of two."""
    from g2s_plugins.batch.runner import write_summary

    sizes = tmp_path / "sizes"
    sizes.mkdir()
    big = pd.DataFrame({"level": [f"level_{i}" for i in range(3000)], "nodes": range(3000)})
    largest = max(path.stat().st_size for path in write_summary(big, sizes))
    out = tmp_path / "out"
    out.mkdir()
    earlier = {path.name: path.read_bytes() for path in write_summary(pd.DataFrame({"level": ["a"], "nodes": [1]}), out)}
    proc = subprocess.run([sys.executable, "-c", WRITE_SUMMARY_LIMITED, str(out), str(largest - 1)],
                          cwd=PROJECT, capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.strip() == f"{out}: cannot write the summary (File too large); the pairs' results are kept: " \
        "run the batch again to write it"
    assert {path.name: path.read_bytes() for path in out.iterdir()} == earlier


def test_a_local_dask_cluster_left_without_workers_loses_its_pairs_instead_of_waiting_for_ever(monkeypatch):
    """Dask does not start a worker again that died as it started: the batch waited on its pairs for ever."""
    import dask.distributed

    from g2s_plugins.executors import dask_cluster

    monkeypatch.setattr(dask_cluster, "NO_WORKERS_LIMIT", 1.0)
    cluster = dask.distributed.LocalCluster
    monkeypatch.setattr(dask.distributed, "LocalCluster", lambda **options: cluster(**{**options, "n_workers": 0}))
    rows = dask_cluster.g2s_execute(function=abs, items=[-1, -2], params=dask_cluster.Params(workers=1),
                                    lost=lambda item, reason: (item, reason))
    assert sorted(rows) == [(-2, dask_cluster.NO_WORKERS), (-1, dask_cluster.NO_WORKERS)]


def test_a_pair_that_finishes_as_the_cluster_is_found_without_workers_keeps_its_row(monkeypatch):
    """The no-worker bound lost the pairs not done and returned: one done after Dask's last batch but before that
    look was neither yielded nor lost, and the batch ended without its row (review33)."""
    import dask.distributed

    from g2s_plugins.executors import dask_cluster

    class Future:
        def __init__(self, done: bool) -> None:
            self._done = done

        def done(self) -> bool:
            return self._done

        def result(self) -> str:
            return "its row"

    class NothingReported:  # Dask's as_completed that has not seen the finished future yet
        def __init__(self, futures) -> None:
            pass

        def is_empty(self) -> bool:
            return False

        def next_batch(self, block: bool) -> list:
            return []

    class WithoutWorkers:
        scheduler_info = {"workers": {}}

    monkeypatch.setattr(dask.distributed, "as_completed", NothingReported)
    monkeypatch.setattr(dask_cluster, "NO_WORKERS_LIMIT", 0.0)
    finished, running = Future(True), Future(False)
    rows = list(dask_cluster._finished({finished: "a", running: "b"}, WithoutWorkers(), [],
                                       lambda item, reason: (item, reason), later=["c"]))
    assert rows == ["its row", ("b", dask_cluster.NO_WORKERS), ("c", dask_cluster.NO_WORKERS)]


@pytest.mark.parametrize("executor, workers, limit", [("local", 2, 16), ("local", 1, 12), ("dask", 2, 32)])
def test_too_small_a_limit_of_open_files_is_one_line_before_any_pair(executor, workers, limit, tmp_path):
    """Under `ulimit -n` 16 the pool's line was followed by its forkserver's traceback, at 12 it said `No usable
    temporary directory found`, and Dask said `Nanny failed to start.` (exit 1; robust14's list)."""
    out = tmp_path / "out"
    done = subprocess.run(
        [sys.executable, "-m", "g2s_core.cli", "batch", "graph_only", *SAMPLES, "-o", str(out), "--executor", executor,
         "--workers", str(workers), "-q"],
        cwd=PROJECT, capture_output=True, text=True, timeout=300,
        preexec_fn=lambda: resource.setrlimit(resource.RLIMIT_NOFILE, (limit, limit)))
    assert_user_error((done.returncode, done.stdout, done.stderr), "ulimit -n: ")
    assert f"more than the process's limit of {limit}" in done.stderr and not out.exists()


def test_a_pair_whose_results_went_with_the_removed_batch_folder_is_not_ok(monkeypatch, tmp_path):
    """The batch's folder removed (`rm -r`) after a pair finished: the summary listed it `ok`, its files gone
    (robust14's list)."""
    import g2s_plugins.batch.runner as runner

    out = tmp_path / "out"
    run = runner.run_pair

    def then_remove(pair):
        row = run(pair)
        if pair.level == "dungeon_seed_1_rooms_12":
            shutil.rmtree(out)
        return row

    monkeypatch.setattr(runner, "run_pair", then_remove)
    summary = run_batch(["graph_only"], SAMPLES, out, "serial")
    assert list(summary["status"]) == ["failed", "ok"]
    assert "its results were removed after the pair finished" in summary["error"][0]
    assert list(pd.read_csv(out / "summary.csv")["status"]) == ["failed", "ok"]
