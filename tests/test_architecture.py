"""The layering and the stage table, as docs/architecture.md states them."""

from __future__ import annotations

import ast
import re

from g2s_core import hookspecs
from g2s_core.config import RunConfig
from g2s_core.stages import PIPELINE, STAGES
from tests.conftest import PROJECT


EXEMPT_IMPORTS = {"batch.py": ["g2s_plugins.batch.runner"]}
"""The one exemption: issue 13 documented batch runs from Python as ``g2s_core.batch.run_batch``; the runner now
lives in the ``batch`` command plugin, and ``g2s_core/batch.py`` only re-exports it so that scripts using that path
keep working."""


def test_core_never_imports_a_plugin():
    for path in sorted((PROJECT / "g2s_core").glob("*.py")):
        for node in ast.walk(ast.parse(path.read_text())):
            names = [a.name for a in node.names] if isinstance(node, ast.Import) else \
                [node.module or ""] if isinstance(node, ast.ImportFrom) else []
            if any(n.startswith("g2s_plugins") for n in names):
                assert names == EXEMPT_IMPORTS.get(path.name), f"{path.name} imports {names}"


CORE_CODE_BUDGET = 2889
"""Lines of code g2s_core may hold (docs/architecture.md records the count): the core stays minimal."""


def lines_of_code(path) -> int:
    """Non-blank lines of a Python file that are neither comments nor docstrings."""
    source = path.read_text()
    docstrings: set[int] = set()
    for node in ast.walk(ast.parse(source)):
        body = getattr(node, "body", None)
        if isinstance(node, (ast.Module, ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)) and body and \
                isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant) and isinstance(body[0].value.value, str):
            docstrings.update(range(body[0].lineno, body[0].end_lineno + 1))
    return sum(1 for number, line in enumerate(source.splitlines(), 1)
               if line.strip() and not line.strip().startswith("#") and number not in docstrings)


def test_lines_of_code_counts_only_code(tmp_path):
    sample = tmp_path / "sample.py"
    sample.write_text('"""Module."""\n\n# why\ndef f():\n    """Doc\n    string."""\n    return 1  # one\n')
    assert lines_of_code(sample) == 2


def test_the_core_stays_within_its_code_budget():
    total = sum(lines_of_code(path) for path in (PROJECT / "g2s_core").glob("*.py"))
    assert total <= CORE_CODE_BUDGET, f"g2s_core holds {total} lines of code, over its budget of {CORE_CODE_BUDGET}: " \
        "move implementations to plugins rather than raise the budget"


def test_the_documented_core_size_is_the_core():
    """docs/architecture.md's "The core's size, measured" figures: physical lines, lines of code, and the Python
    API's part of them (`api.py`, `result_folder.py`, `batch.py`), the rest being the minimal core."""
    text = " ".join((PROJECT / "docs" / "architecture.md").read_text().split())
    figures = re.search(r"The core's size, measured: ([\d,]+) physical lines and ([\d,]+) lines of code .*? are "
                        r"([\d,]+) lines of code; the other ([\d,]+) are .*?`api.py` (\d+), `result_folder.py` (\d+) "
                        r".*?`batch.py` (\d+)", text)
    assert figures, "docs/architecture.md no longer states the core's size as this test reads it"
    physical, code, minimal, api_part, api, result_folder, batch = (int(f.replace(",", "")) for f in figures.groups())
    paths = sorted((PROJECT / "g2s_core").glob("*.py"))
    counts = {path.name: lines_of_code(path) for path in paths}
    api_files = [counts["api.py"], counts["result_folder.py"], counts["batch.py"]]
    assert (physical, code) == (sum(len(path.read_text().splitlines()) for path in paths), sum(counts.values()))
    assert [api, result_folder, batch] == api_files and api_part == sum(api_files) and minimal == code - api_part


def test_the_layer_picture_names_every_core_module():
    text = (PROJECT / "docs" / "architecture.md").read_text()
    box = text.split("## Layers", 1)[1].split("\n └", 1)[0]  # the core's box, down to its bottom edge
    words = set(re.findall(r"\w+", box))
    missing = [path.stem for path in sorted((PROJECT / "g2s_core").glob("*.py"))
               if path.stem != "__init__" and path.stem not in words]
    assert not missing, f"docs/architecture.md's layer picture does not name g2s_core's {missing}"


def test_every_kind_has_its_hook_and_every_stage_its_config_section():
    specs = {name for name in dir(hookspecs) if name.startswith("g2s_")}
    # g2s_begin_ahead is no kind's: a pipeline stage's plugin may implement it beside its stage hook
    assert specs == {stage.hook for stage in STAGES} | {hookspecs.g2s_begin_ahead.__name__}
    sections = [name for name in RunConfig.model_fields if name in {s.key for s in PIPELINE}]
    assert sections == [stage.key for stage in PIPELINE]
    assert RunConfig.model_fields["stop_after"].default == PIPELINE[-1].key


def test_the_documented_stage_table_is_the_code_table():
    text = (PROJECT / "docs" / "architecture.md").read_text()
    rows = re.findall(r"^\| `(\w+)` \| (\w+) \| `(\w+)\(", text, flags=re.MULTILINE)
    assert rows == [(stage.key, stage.title, stage.hook) for stage in STAGES]


def test_the_pipeline_picture_names_every_built_in_plugin():
    from g2s_core import DISTRIBUTION
    from g2s_core.registry import installed

    text = (PROJECT / "docs" / "architecture.md").read_text()
    picture = text.split("The pipeline (the paper's Algorithm 1)", 1)[1].split("## The stage table", 1)[0]
    listed = [set(group.split(" | ")) for group in re.findall(r"\(([a-z_]+(?: \| [a-z_]+)*)\)", picture)]
    stages = ["graph", "terminals", "steiner", "loops", "roots", "simplify", "analyzers", "evaluators", "outputs",
              "readers", "executors", "commands"]
    built_in = [{p.name for p in installed().plugins(stage) if p.package == DISTRIBUTION} for stage in stages]
    assert listed == built_in


def test_the_documented_example_plugins_register_and_work(tmp_path, capsys):
    import argparse
    import types

    from g2s_core.model import RunResult
    from g2s_core.registry import Registry

    text = (PROJECT / "docs" / "architecture.md").read_text().split("## Adding a plugin", 1)[1]
    registry = Registry()
    for index, code in enumerate(re.findall(r"```python\n(.*?)```", text, flags=re.DOTALL)):
        module = types.ModuleType(f"doc_example_{index}")
        exec(compile(code, module.__name__, "exec"), module.__dict__)
        registry.register(module, package="docs", entry_point=f"example.{index}")
    kinds = [(p.stage, p.name) for p in registry.plugins()]
    assert kinds == [("graph", "triangles"), ("terminals", "above"), ("steiner", "star"), ("loops", "shortcuts"),
                     ("roots", "lowest"), ("simplify", "straight"), ("analyzers", "height"), ("evaluators", "kept"),
                     ("outputs", "csv"), ("readers", "csv"), ("levels", "plaza"), ("executors", "threads"),
                     ("commands", "size")]

    def call(stage, name, **kwargs):
        info = registry.get(stage, name)
        return registry.call(info, params=info.params_model(), **kwargs)

    mesh = call("levels", "plaza")
    graph = call("graph", "triangles", mesh=mesh, context=None)
    tops = sorted(n for n, p in graph.nodes(data="pos") if p[1] > 0)
    terminals = [tops[0], tops[-1]]
    tree = call("steiner", "star", graph=graph, terminals=terminals, context=None)
    for node in tree:  # as the pipeline does: the tree gets the graph's attributes
        tree.nodes[node].update(graph.nodes[node])
    looped = call("loops", "shortcuts", graph=graph, forest=tree, context=None)
    assert set(tree.edges) <= set(looped.edges) <= set(graph.edges)
    scores = call("roots", "lowest", tree=tree, context=None)
    assert set(scores) == set(tree)
    assert call("terminals", "above", graph=graph, context=None).nodes == ()
    predicate = call("simplify", "straight", context=None, forest=None, simplified=None)
    assert isinstance(predicate(nx_path_with_positions(), 0, 1, 2), bool)
    values = call("analyzers", "height", structure=tree, context=None)
    assert min(values.values()) == 0
    result = RunResult(config={}, mesh_name="plaza", mesh_sha256="", context=None, graph=graph, steiner=tree,
                       structure=tree)
    assert 0 < call("evaluators", "kept", result=result, context=None)["node_share"] <= 1
    written = call("outputs", "csv", result=result, folder=tmp_path)
    assert [p.name for p in written] == ["nodes.csv"] and len(written[0].read_text().splitlines()) == len(tree) + 1
    loaded = call("readers", "csv", path=tmp_path)
    assert dict(loaded.structure.nodes(data="pos")) == dict(tree.nodes(data="pos"))
    rows = [{"config": "c", "level": str(n)} for n in range(5)]
    executed = call("executors", "threads", function=dict, items=rows, lost=lambda row, reason: {**row, "error": reason})
    assert sorted(executed, key=lambda row: row["level"]) == rows
    mesh.export(tmp_path / "plaza.obj")
    parser = argparse.ArgumentParser(prog="g2s size")
    run = registry.call(registry.get("commands", "size"), parser=parser)
    assert run(parser.parse_args([str(tmp_path / "plaza.obj")])) == 0
    assert capsys.readouterr().out == f"{tmp_path / 'plaza.obj'}: 12 triangles, 20.0 x 0.2 x 20.0 m\n"


def nx_path_with_positions():
    import networkx as nx

    tree = nx.DiGraph([(0, 1), (1, 2)])
    for node in tree:
        tree.nodes[node]["pos"] = (float(node), 0.0, 0.0)
    return tree


def test_the_recast_navmesh_provides_the_navmesh_protocol():
    import numpy as np

    from g2s_core.config import AgentConfig
    from g2s_core.model import NavMesh
    from g2s_plugins.recast import build_navmesh
    from g2s_plugins.samples.levels import straight_corridor

    level = straight_corridor()
    navmesh = build_navmesh(level.mesh.vertices, level.mesh.faces, AgentConfig())
    assert isinstance(navmesh, NavMesh)
    members = [name for name in NavMesh.__annotations__] + ["polygon_count"]
    assert all(hasattr(navmesh, name) for name in members)
    assert {"cell_size", "cell_height"} <= set(navmesh.settings)
    portals = navmesh.portals()
    assert portals.pairs.shape[1:] == (2,) and portals.endpoints.shape[1:] == (2, 3) and len(portals.widths) == len(portals.pairs)
    index, point = navmesh.nearest_poly(navmesh.centres[0])
    assert index == 0 and np.allclose(point, navmesh.centres[0], atol=0.5)
    clear, _ = navmesh.raycast(navmesh.centres[0], navmesh.centres[0])
    assert isinstance(clear, bool) and isinstance(navmesh.stats(), dict)


def test_the_documented_navmesh_protocol_names_every_query():
    import inspect

    from g2s_core.model import NavMesh

    text = (PROJECT / "docs" / "architecture.md").read_text()
    queries = [name for name, member in vars(NavMesh).items()
               if inspect.isfunction(member) and not name.startswith("_") and name != "polygon_count"]
    assert queries and [name for name in queries if f"`{name}()`" not in text] == []
