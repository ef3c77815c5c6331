"""The examples of docs/python.md run as written, in order, in an empty folder."""

from __future__ import annotations

import re

from tests.conftest import PROJECT

DOC = PROJECT / "docs" / "python.md"


def python_blocks(text: str) -> list[str]:
    return re.findall(r"^```python\n(.*?)^```$", text, flags=re.MULTILINE | re.DOTALL)


def test_python_md_examples_run(tmp_path, monkeypatch, capsys):
    blocks = python_blocks(DOC.read_text(encoding="utf-8"))
    assert len(blocks) >= 5
    monkeypatch.chdir(tmp_path)
    namespace: dict = {}
    for index, block in enumerate(blocks):
        exec(compile(block, f"{DOC.name} block {index + 1}", "exec"), namespace)
    printed = capsys.readouterr().out
    assert "already holds results" in printed
    assert (tmp_path / "out" / "structure.json").is_file() and (tmp_path / "out-glb" / "structure.glb").is_file()
