"""The layering and the stage table, as docs/architecture.md states them."""

from __future__ import annotations

import ast
import re

from g2s_core import hookspecs
from g2s_core.config import RunConfig
from g2s_core.stages import PIPELINE, STAGES
from tests.conftest import PROJECT


def test_core_never_imports_a_plugin():
    for path in sorted((PROJECT / "g2s_core").glob("*.py")):
        for node in ast.walk(ast.parse(path.read_text())):
            names = [a.name for a in node.names] if isinstance(node, ast.Import) else \
                [node.module or ""] if isinstance(node, ast.ImportFrom) else []
            assert not any(n.startswith("g2s_plugins") for n in names), f"{path.name} imports {names}"


def test_every_kind_has_its_hook_and_every_stage_its_config_section():
    specs = {name for name in dir(hookspecs) if name.startswith("g2s_")}
    assert specs == {stage.hook for stage in STAGES}
    sections = [name for name in RunConfig.model_fields if name in {s.key for s in PIPELINE}]
    assert sections == [stage.key for stage in PIPELINE]
    assert RunConfig.model_fields["stop_after"].default == PIPELINE[-1].key


def test_the_documented_stage_table_is_the_code_table():
    text = (PROJECT / "docs" / "architecture.md").read_text()
    rows = re.findall(r"^\| `(\w+)` \| (\w+) \| `(\w+)\(", text, flags=re.MULTILINE)
    assert rows == [(stage.key, stage.title, stage.hook) for stage in STAGES]
