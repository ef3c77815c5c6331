"""A few examples of each fuzz target (``make fuzz`` runs them for minutes)."""

from __future__ import annotations

import pytest

from tests.fuzz.fuzz_loaders import CORPUS, TARGETS, check, property_for


@pytest.mark.parametrize("target", sorted(TARGETS))
def test_fuzz_target_runs(target):
    property_for(target, examples=40)()


@pytest.mark.parametrize("seed", sorted(p.name for p in CORPUS.iterdir()))
def test_every_corpus_file_loads(seed):
    """The seeds themselves are valid inputs of their loader (else the fuzzer mutates garbage)."""
    path = CORPUS / seed
    target = next(name for name, (_, suffixes) in TARGETS.items() if path.suffix in suffixes)
    loader, _ = TARGETS[target]
    loader(path)
    check(target, path.suffix, path.read_bytes())
