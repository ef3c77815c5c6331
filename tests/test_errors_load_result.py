"""``load_result`` on damaged structure.json files, in g2s's words (robust5's fuzzing, 4 December 2026): the
schema checker's messages (``None is not of type 'array'``, ``'name' is a required property``, ``... is not valid
under any of the given schemas``) and the reader's own exception type (``malformed structure file (ValueError: ...)``)
were passed on as they were; ``NaN`` coordinates and ``true`` or ``2.0`` as the schema version were read."""

from __future__ import annotations

import copy
import json

import pytest

from g2s_core.api import run
from g2s_core.errors import G2SError
from g2s_plugins.outputs.json_reader import load_result


@pytest.fixture(scope="module")
def written(tmp_path_factory) -> dict:
    """The structure.json of a whole run on a small level."""
    folder = tmp_path_factory.mktemp("result")
    run("sample:cross_hub", "map_analysis").write(folder)
    return json.loads((folder / "structure.json").read_text())


def _changed(document: dict, change) -> dict:
    document = copy.deepcopy(document)
    change(document)
    return document


@pytest.mark.parametrize("change, says", [
    (lambda d: d.pop("mesh"), "mesh: required key is missing"),
    (lambda d: d["mesh"].pop("name"), "mesh.name: required key is missing"),
    (lambda d: d.__setitem__("nodes", "x"), "nodes: expected a list, got 'x'"),
    (lambda d: d.__setitem__("config", []), "config: expected a mapping, got a list of 0 items"),
    (lambda d: d.__setitem__("directed", 3), "directed: expected true or false, got 3"),
    (lambda d: d.__setitem__("roots", [None]), "roots[0]: expected an integer, got null"),
    (lambda d: d.__setitem__("terminals", "x"), "terminals: expected null or a mapping, got 'x'"),
    (lambda d: d.__setitem__("navmesh", 3), "navmesh: expected a mapping or null, got 3"),
    (lambda d: d.__setitem__("units", "cm"), "units: expected 'm', got 'cm'"),
    (lambda d: d.__setitem__("final_stage", 3),
     "final_stage: expected one of 'simplify', 'roots', 'loops', 'steiner', 'graph', null, got 3"),
    (lambda d: d["nodes"][0].__setitem__("position", [0, 0]), "nodes[0].position: expected a list of at least 3 items, "
                                                              "got a list of 2 items"),
    (lambda d: d["nodes"][0].__setitem__("zzz", 1), "nodes[0].zzz: unknown key (expected one of: id, position, normal, "
                                                    "area, on_navmesh, polygon, terminal, root, depth, parent, values, extra)"),
    # were read: Python's json takes NaN and Infinity, and True == 1, 2.0 == 2
    (lambda d: d["nodes"][0].__setitem__("position", [float("nan"), 0, 0]), "nodes[0].position[0]: expected a finite number, got nan"),
    (lambda d: d["edges"][0].__setitem__("weight", float("inf")), "edges[0].weight: expected a finite number, got inf"),
    (lambda d: d.__setitem__("schema_version", True), "schema_version true is not supported (this g2s reads 1, 2, 3)"),
    (lambda d: d.__setitem__("schema_version", 2.0), "schema_version 2.0 is not supported (this g2s reads 1, 2, 3)"),
    # was "malformed structure file (ValueError: edges[0].target: node 999999 is not in nodes)"
    (lambda d: d["edges"][0].__setitem__("target", 999999), "edges[0].target: node 999999 is not in nodes"),
    # a node given the id of another: named by an edge to the id it hid ("edges[I].target: node N is not in nodes"),
    # or, when an edge could not tell, the two records merged into one node silently
    (lambda d: d["nodes"][2].__setitem__("id", d["nodes"][0]["id"]), "nodes[2].id: id 0 is given twice (first at nodes[0])"),
    (lambda d: d["nodes"].append({**d["nodes"][0], "position": [9.0, 9.0, 9.0]}),
     "nodes[N].id: id 0 is given twice (first at nodes[0])"),
], ids=lambda value: value if isinstance(value, str) else "")
def test_a_damaged_structure_file_is_named_in_g2s_words(change, says, written, tmp_path):
    path = tmp_path / "structure.json"
    path.write_text(json.dumps(_changed(written, change)))
    with pytest.raises(G2SError) as caught:
        load_result(path)
    assert str(caught.value) == f"{path}: {says}".replace("[N]", f"[{len(written['nodes'])}]")


def test_the_written_file_loads(written, tmp_path):
    (tmp_path / "structure.json").write_text(json.dumps(written))
    assert load_result(tmp_path).structure.number_of_nodes() == len(written["nodes"])
