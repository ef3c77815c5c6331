"""Warnings told as they are raised: kou's before a slow metric closure, every warning through the progress callback
and above the CLI's spinner; after the run when stderr is no terminal."""

from __future__ import annotations

import io

import networkx as nx
import numpy as np
from rich.console import Console

from g2s_core import api, cli
from g2s_core.model import RaisedWarning, RunContext
from g2s_plugins.batch import command as batch_command  # noqa: F401  (imported before cli.Output is patched, it keeps the real one)
from g2s_plugins.steiner import kou

NO_TERMINALS = "the 'entry_exit' terminal selector found no terminals in closed_room"


def test_kou_predicts_a_slow_closure_from_its_counts_only():
    # the most any preset's kou run of the sample levels reached: map_piece_sampling on a 400-room dungeon, 25 s
    assert kou.slow_closure_warning(2918, 16022, 37677) is None
    # a map-piece preset on the whole castle with a 0.1 m agent: 688 s
    warning = kou.slow_closure_warning(9490, 296498, 900000)
    assert warning is not None
    for named in ("9,490 terminals", "296,498 nodes", "900,000 edges", "10-50 min", "mehlhorn", "map_analysis"):
        assert named in warning, named


def test_kou_warns_before_its_closure_is_searched(monkeypatch):
    told: list[str] = []
    context = RunContext(mesh=None, agent=None, centre=np.zeros(3), progress=told.append)
    solved_after: list[int] = []

    def solver(graph, terminals):
        solved_after.append(len(told))
        return nx.empty_graph(terminals)

    monkeypatch.setattr(kou, "SLOW_COST", 1.0)
    monkeypatch.setattr(kou, "kou_steiner_tree", solver)
    kou.g2s_steiner_tree(graph=nx.path_graph(5), terminals=[0, 4, 4], params=kou.Params(), context=context)
    assert solved_after == [1] and isinstance(told[0], RaisedWarning)
    assert "2 terminals on 5 nodes and 4 edges" in told[0] and context.warnings == [told[0]]


def test_kou_is_silent_below_the_cost():
    context = RunContext(mesh=None, agent=None, centre=np.zeros(3))
    kou.g2s_steiner_tree(graph=nx.path_graph(5), terminals=[0, 4], params=kou.Params(), context=context)
    assert context.warnings == []


def test_the_progress_callback_hears_each_warning_as_it_is_raised():
    told: list[str] = []
    result = api.run("sample:closed_room", "map_piece", progress=told.append)
    raised = [message for message in told if isinstance(message, RaisedWarning)]
    assert raised == result.warnings and raised[0].startswith(NO_TERMINALS)
    assert told.index(raised[0]) == told.index("Step 2: terminals") + 1  # during step 2, not after the run


class Terminal(io.StringIO):
    """A stream that is a terminal, as it says."""

    def isatty(self) -> bool:
        return True


def _run_on(errors: Console, monkeypatch, tmp_path, *options: str) -> str:
    """What ``g2s run`` prints on ``errors`` (its stderr console) for a run that warns."""
    monkeypatch.setattr(cli, "Output", lambda stderr=False, **_: errors if stderr else Console(file=io.StringIO()))
    assert cli.main(["run", "map_piece", "sample:closed_room", "-o", str(tmp_path / "out"), *options]) == 0
    return errors.file.getvalue()


def test_a_terminal_shows_the_warning_above_the_spinner_once(monkeypatch, tmp_path):
    shown = _run_on(Console(file=Terminal(), force_terminal=True, width=300), monkeypatch, tmp_path)
    assert shown.count("g2s: warning: " + NO_TERMINALS) == 1


def test_without_a_terminal_the_warning_follows_the_run_once(monkeypatch, tmp_path):
    for options in ((), ("-q",)):
        shown = _run_on(Console(file=io.StringIO(), force_terminal=False, width=300), monkeypatch, tmp_path / str(len(options)), *options)
        assert shown.splitlines() == ["g2s: warning: " + NO_TERMINALS + ": there is nothing to join, so the run stops after step 2"]
