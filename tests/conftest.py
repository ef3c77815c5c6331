"""Shared fixtures: paths to the project and to the shared test data."""

from __future__ import annotations

import importlib
import os
import signal
import sys
from pathlib import Path
from types import ModuleType

import pytest
import trimesh

PROJECT = Path(__file__).resolve().parents[1]
SHARED_DATA = PROJECT.parent / "shared" / "data"
BENCHMARKS = PROJECT / "benchmarks"


def benchmark(name: str) -> ModuleType:
    """The script ``benchmarks/<name>.py`` as a module, its imports of the scripts beside it found there."""
    sys.path.insert(0, str(BENCHMARKS))
    try:
        return importlib.import_module(name)
    finally:
        sys.path.remove(str(BENCHMARKS))


def piece_openings(level, preset: str) -> list:
    """The openings the whole pipeline of ``configs/<preset>.yaml`` finds on a sample level (its ``mesh`` and ``name``)."""
    from g2s_core import pipeline
    from g2s_core.config import PRESETS_DIR, load_config
    from g2s_core.mesh import mesh_sha256
    from g2s_core.registry import Registry

    registry = Registry.from_entry_points()
    plan = pipeline.plan(load_config(PRESETS_DIR / f"{preset}.yaml"), registry)
    return list(pipeline.run(plan, registry, level.mesh, level.name, mesh_sha256(level.mesh)).terminals.openings)


def round_openings(round_script: str, kind: str, preset: str = "map_piece", width_tolerance: float = 0.05) -> list:
    """The openings ``preset`` finds on ``kind`` of the piece-kinds round ``benchmarks/<round_script>.py`` at 0 degrees,
    checked to be its known ones, one each (``piece_kinds10.score``, one-to-one), nothing else, within
    ``width_tolerance`` m of their widths."""
    level = getattr(benchmark(round_script), kind)()
    openings = piece_openings(level, preset)
    known = len(level.openings)
    recalled, missed, correct, other, width_error = benchmark("piece_kinds10").score(level, openings, one_to_one=True)
    assert (recalled, missed, correct, other) == (known, 0, known, 0)
    assert width_error < width_tolerance
    return openings


def box(x0: float, x1: float, y0: float, y1: float, z0: float, z1: float) -> trimesh.Trimesh:
    """An axis-aligned box between x0..x1, y0..y1 (up) and z0..z1 metres: the walls and floors of hand-built levels."""
    return trimesh.creation.box(bounds=[(x0, y0, z0), (x1, y1, z1)])


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    """The ``wheel`` tests (over a minute each) first, the others in their order. pytest-xdist's default scheduling
    (3.8) sends each worker a first chunk of consecutive tests (a quarter of its share), then further chunks of those
    left as its queue runs low: both wheel tests go to the first worker at the start, one after the other, while the
    other worker runs the next chunk, and the rest is shared out as the workers' queues empty. As the last two
    collected they went to one worker at the end while the other waited (5 December 2026, ``-n 2``: 87 s and 72 s,
    one after the other)."""
    items.sort(key=lambda item: item.get_closest_marker("wheel") is None)


@pytest.fixture(autouse=True)
def working_folder_kept():
    """Fails the test that leaves the process in another working folder, or in one that no longer exists: tests
    that follow it in the same worker name configs by paths relative to the project."""
    before = os.getcwd()
    yield
    try:
        after = os.getcwd()
    except FileNotFoundError:
        os.chdir(before)
        pytest.fail("the working folder was deleted while this test ran in it")
    if after != before:
        os.chdir(before)
        pytest.fail(f"the test left the working folder at {after}")


@pytest.fixture
def shared_data() -> Path:
    """../shared/data, read in place; tests using it skip when it is absent."""
    if not SHARED_DATA.is_dir():
        pytest.skip(f"shared test data not found at {SHARED_DATA}")
    return SHARED_DATA


@pytest.fixture
def swallowed_ctrl_c(monkeypatch, request):
    """``swallowed_ctrl_c(owner, name)``: ``owner.name`` (a lazily imported module) becomes one whose every use
    sends this process a Ctrl-C and swallows its KeyboardInterrupt, as trimesh's imports catch BaseException.
    Ctrl-C raises KeyboardInterrupt meanwhile, as from a terminal (a shell's background job, how CI may start the
    suite, inherits it ignored)."""
    def swallow(owner: object, name: str) -> None:
        module = getattr(owner, name)

        class Importing:
            def __getattr__(self, attribute: str) -> object:
                try:
                    os.kill(os.getpid(), signal.SIGINT)
                except BaseException:  # as trimesh does
                    pass
                return getattr(module, attribute)

        monkeypatch.setattr(owner, name, Importing())

    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    request.addfinalizer(lambda: signal.signal(signal.SIGINT, previous))
    return swallow


@pytest.fixture(scope="session")
def run_piece():
    """``run_piece(name, yaw=0.0, **kwargs) -> (level, result)``: the ``map_piece`` preset run on the generated
    piece ``pieces.PIECES[name](**kwargs)``, turned by ``yaw`` degrees when not 0; each once per session."""
    from g2s_core import pipeline
    from g2s_core.config import PRESETS_DIR, load_config
    from g2s_core.mesh import mesh_sha256
    from g2s_core.registry import Registry
    from g2s_plugins.samples import pieces

    registry = Registry.from_entry_points()
    plan = pipeline.plan(load_config(PRESETS_DIR / "map_piece.yaml"), registry)
    cache: dict[tuple, tuple] = {}

    def run(name: str, yaw: float = 0.0, **kwargs):
        key = (name, yaw, tuple(sorted(kwargs.items())))
        if key not in cache:
            level = pieces.PIECES[name](**kwargs)
            if yaw:
                level = pieces.turned(level, yaw)
            cache[key] = (level, pipeline.run(plan, registry, level.mesh, name, mesh_sha256(level.mesh)))
        return cache[key]

    return run
