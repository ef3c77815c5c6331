"""Fuzzing the loaders of user files: meshes, configs, points files.

Each input is a file of the corpus (``tests/fuzz/corpus``) changed by a few
random edits drawn by hypothesis (bit flips, inserted tokens such as ``nan``
or ``1e999``, deletions, duplicated and spliced chunks). A loader may accept
the file or refuse it with a :class:`~g2s_core.errors.G2SError`; any other
exception, or taking more than :data:`TIME_LIMIT` CPU seconds, is a crash: the
input is saved in ``tests/fuzz/crashes/`` and hypothesis reports the
smallest such input it finds.

Run for N minutes (``make fuzz``, ``FUZZ_MINUTES=10``)::

    python -m tests.fuzz.fuzz_loaders --minutes 10 [--target mesh|config|points]

``tests/reliability/test_fuzz.py`` runs a few examples of each target as part of the suite.
"""

from __future__ import annotations

import argparse
import hashlib
import resource
import signal
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from g2s_core.config import load_config
from g2s_core.errors import G2SError
from g2s_core.mesh import load_mesh
from g2s_core.pipeline import plan
from g2s_core.registry import installed
from g2s_plugins.terminals.points import read_points

HERE = Path(__file__).resolve().parent
CORPUS = HERE / "corpus"
CRASHES = HERE / "crashes"
TIME_LIMIT = 30
"""CPU seconds one input may take before it counts as a hang (CPU time, so that a busy machine
starving the fuzzer is not taken for a hang)."""

MEMORY_LIMIT = 4 << 30
"""Address space the fuzzing process may use, bytes: a runaway allocation fails instead of swapping."""

TOKENS = [
    b"nan", b"inf", b"-inf", b".nan", b".inf", b"1e999", b"-1", b"0", b"-0", b"4294967296", b"9" * 40,
    b"\x00", b"\xff\xfe", b"\xe9", b"\n", b"\r", b" ", b",", b"[", b"]", b"{", b"}", b":", b"&a ", b"*a",
    b"!!python/object:os.system", b"extends: ", b"f 1 2 3 4 5", b"f -1 -2 -3", b"v 1e308 1e308 1e308\n",
    b"element vertex 2000000000\n", b"3 0 1 999999\n", b"#", b"/", b"\t",
]


def _mutants(suffixes: tuple[str, ...]) -> st.SearchStrategy[tuple[str, bytes]]:
    seeds = sorted(p for p in CORPUS.iterdir() if p.suffix in suffixes)
    contents = [p.read_bytes() for p in seeds]

    @st.composite
    def mutant(draw) -> tuple[str, bytes]:
        index = draw(st.integers(0, len(seeds) - 1))
        data = bytearray(contents[index])
        for _ in range(draw(st.integers(0, 6))):
            at = draw(st.integers(0, len(data)))
            edit = draw(st.sampled_from(("flip", "token", "delete", "duplicate", "splice", "bytes")))
            if edit == "flip" and at < len(data):
                data[at] ^= 1 << draw(st.integers(0, 7))
            elif edit == "token":
                data[at:at] = draw(st.sampled_from(TOKENS))
            elif edit == "delete":
                del data[at:at + draw(st.integers(1, 16))]
            elif edit == "duplicate":
                chunk = data[at:at + draw(st.integers(1, 64))]
                data[at:at] = chunk * draw(st.integers(1, 50))
            elif edit == "splice":
                other = contents[draw(st.integers(0, len(seeds) - 1))]
                start = draw(st.integers(0, len(other)))
                data[at:at] = other[start:start + draw(st.integers(1, 64))]
            else:
                data[at:at] = draw(st.binary(max_size=16))
        return seeds[index].suffix, bytes(data)

    return mutant()


def _load_mesh(path: Path) -> None:
    load_mesh(path)


def _load_config(path: Path) -> None:
    plan(load_config(path), installed(), source=str(path))


def _read_points(path: Path) -> None:
    read_points(path)


TARGETS: dict[str, tuple[Callable[[Path], None], tuple[str, ...]]] = {
    "mesh": (_load_mesh, (".obj", ".ply", ".stl", ".off", ".glb")),
    "config": (_load_config, (".yaml",)),
    "points": (_read_points, (".csv", ".json")),
}
"""Target name -> (loader, suffixes of its corpus files)."""


class Hang(Exception):
    """An input took longer than :data:`TIME_LIMIT`."""


def _on_time_limit(_signum, _frame):
    raise Hang(f"took more than {TIME_LIMIT} s of CPU time")


def check(target: str, suffix: str, data: bytes) -> None:
    """Run ``target``'s loader on ``data`` saved with ``suffix``; save the input and raise if it crashes."""
    loader, _ = TARGETS[target]
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / f"input{suffix}"
        path.write_bytes(data)
        previous = signal.signal(signal.SIGPROF, _on_time_limit)
        signal.setitimer(signal.ITIMER_PROF, TIME_LIMIT)
        try:
            loader(path)
        except G2SError as exc:
            assert "\n" not in str(exc), f"a message of several lines: {exc!r}"
        except BaseException:
            CRASHES.mkdir(exist_ok=True)
            name = f"{target}-{hashlib.sha256(data).hexdigest()[:16]}{suffix}"
            (CRASHES / name).write_bytes(data)
            raise
        finally:
            signal.setitimer(signal.ITIMER_PROF, 0)
            signal.signal(signal.SIGPROF, previous)


def property_for(target: str, examples: int) -> Callable[[], None]:
    """A hypothesis test running ``examples`` mutated inputs through ``target``'s loader."""
    _, suffixes = TARGETS[target]

    @settings(max_examples=examples, deadline=None, database=None, suppress_health_check=list(HealthCheck))
    @given(_mutants(suffixes))
    def loads_or_refuses(item: tuple[str, bytes]) -> None:
        check(target, *item)

    return loads_or_refuses


def fuzz(minutes: float, targets: list[str]) -> int:
    """Fuzz ``targets`` in turn, 200 inputs at a time, until ``minutes`` have passed; the inputs tried."""
    end = time.monotonic() + minutes * 60
    tried = 0
    while time.monotonic() < end:
        for target in targets:
            if time.monotonic() >= end:
                break
            property_for(target, 200)()
            tried += 200
            print(f"{target}: {tried} inputs, {max(0.0, end - time.monotonic()) / 60:.1f} min left", flush=True)
    return tried


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--minutes", type=float, default=1.0, help="how long to fuzz (default: 1)")
    parser.add_argument("--target", choices=sorted(TARGETS), action="append", help="loader to fuzz (default: all)")
    args = parser.parse_args(argv)
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))
    tried = fuzz(args.minutes, args.target or sorted(TARGETS))
    print(f"no crash in {tried} inputs")
    return 0


if __name__ == "__main__":
    sys.exit(main())
