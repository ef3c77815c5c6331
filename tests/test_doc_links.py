"""README.md and docs/*.md point only at what exists (relative links, their anchors, the repository files they name)
and at no path on a developer's machine, and the reference docs name every built-in plugin."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from tests.conftest import PROJECT

DOCS = [PROJECT / "README.md", *sorted((PROJECT / "docs").glob("*.md"))]
LINK = re.compile(r"\[[^\]]*\]\(([^)\s]+)\)")
FILE_PATH = re.compile(r"`((?:g2s_core|g2s_plugins|configs|benchmarks|tests|tools|docs|src)/[\w./-]*\.\w+)`")


def prose(text: str) -> str:
    """``text`` without its fenced code blocks."""
    return re.sub(r"^```.*?^```", "", text, flags=re.MULTILINE | re.DOTALL)


def anchors(text: str) -> set[str]:
    """The anchors GitHub gives the headings of ``text``: lower case, punctuation dropped, spaces to ``-``, repeats ``-1``, ``-2`` ..."""
    found: set[str] = set()
    for heading in re.findall(r"^#+\s+(.*?)\s*$", prose(text), flags=re.MULTILINE):
        slug = re.sub(r"[^\w\- ]", "", heading.lower()).replace(" ", "-")
        anchor, repeat = slug, 0
        while anchor in found:
            repeat += 1
            anchor = f"{slug}-{repeat}"
        found.add(anchor)
    return found


def test_anchors_follow_githubs_rule():
    assert anchors("# How files are written\n## `entry_exit`: openings (A/B)\n## Notes\n## Notes\n```\n# not a heading\n```\n") \
        == {"how-files-are-written", "entry_exit-openings-ab", "notes", "notes-1"}


@pytest.mark.parametrize("doc", DOCS, ids=lambda path: path.name)
def test_relative_links_and_named_files_exist(doc: Path):
    text = doc.read_text(encoding="utf-8")
    broken = []
    for target in LINK.findall(prose(text)):
        if re.match(r"[a-z]+:", target):
            continue
        path, _, anchor = target.partition("#")
        linked = (doc.parent / path).resolve() if path else doc
        if not linked.exists():
            broken.append(f"{target}: no such file")
        elif anchor and linked.suffix == ".md" and anchor not in anchors(linked.read_text(encoding="utf-8")):
            broken.append(f"{target}: no such heading")
    broken += [f"{path}: no such file" for path in FILE_PATH.findall(text) if not (PROJECT / path).exists()]
    assert not broken, f"{doc.name}: {broken}"


MACHINE_PATH = re.compile(r"(?<![\w.])/(?:work|home|root)\b\S*")
"""A path on some developer's machine: a reader of the project cannot follow it."""


@pytest.mark.parametrize("doc", DOCS, ids=lambda path: path.name)
def test_docs_cite_no_path_outside_the_repository(doc: Path):
    assert not MACHINE_PATH.findall(doc.read_text(encoding="utf-8")), doc.name


def test_the_machine_path_check_finds_them():
    assert MACHINE_PATH.findall("rules (/work/notes/x.md), `/root/.cache`, the `/work` notes, not `g2s_core/rooted.py` "
                                "or /workers") == ["/work/notes/x.md),", "/root/.cache`,", "/work`"]


REFERENCE = {"terminals": "plugins.md", "loops": "plugins.md", "roots": "plugins.md", "simplify": "plugins.md",
             "analyzers": "plugins.md", "evaluators": "plugins.md", "steiner": "steiner.md", "outputs": "outputs.md",
             "executors": "batch.md", "commands": "batch.md"}
"""The doc that describes each kind's built-in plugins (graph builders: navmesh.md and sampling.md, by name in their titles)."""


@pytest.mark.parametrize("stage", sorted(REFERENCE))
def test_the_reference_doc_names_every_built_in_plugin(stage: str):
    from g2s_core import DISTRIBUTION
    from g2s_core.registry import installed

    text = (PROJECT / "docs" / REFERENCE[stage]).read_text(encoding="utf-8")
    missing = [p.name for p in installed().plugins(stage) if p.package == DISTRIBUTION
               and f"`{p.name}`" not in text and f"`--executor {p.name}`" not in text]
    assert not missing, f"docs/{REFERENCE[stage]} does not name the {stage} plugins {missing}"


def test_the_readme_lists_every_doc():
    readme = (PROJECT / "README.md").read_text(encoding="utf-8").split("## Documentation", 1)[1]
    assert [d.name for d in DOCS[1:] if f"`docs/{d.name}`" not in readme] == []


FORMER_NAMES = {"g2s_plugins.traffic.subtree_sums"}
"""Names the docs give as what a thing was called before (docs/performance.md: "then ...; now part of ...")."""


def resolves(dotted: str) -> bool:
    """Whether ``dotted`` (``package.module.attribute...``) names a module or an attribute of one."""
    import importlib

    parts = dotted.split(".")
    for split in range(len(parts), 0, -1):
        try:
            found = importlib.import_module(".".join(parts[:split]))
        except ImportError:
            continue
        for part in parts[split:]:
            if not hasattr(found, part):
                return False
            found = getattr(found, part)
        return True
    return False


def test_the_name_check_finds_what_is_not_there():
    assert resolves("g2s_core.lazy.lazy_module") and resolves("g2s_plugins.batch.runner.run_pair")
    assert not resolves("g2s_plugins.traffic.no_such_function") and not resolves("g2s_core.no_such_module")


@pytest.mark.parametrize("doc", DOCS, ids=lambda path: path.name)
def test_named_modules_and_functions_exist(doc: Path):
    names = set(re.findall(r"`((?:g2s_core|g2s_plugins)(?:\.[A-Za-z_]\w*)+)", doc.read_text(encoding="utf-8")))
    assert sorted(name for name in names - FORMER_NAMES if not resolves(name)) == []


def test_named_make_targets_exist():
    targets = set(re.findall(r"^([a-z][\w-]*):", (PROJECT / "Makefile").read_text(encoding="utf-8"), flags=re.MULTILINE))
    named = {target for doc in DOCS for target in re.findall(r"`make ([a-z][\w-]*)", doc.read_text(encoding="utf-8"))}
    assert named and sorted(named - targets) == []
