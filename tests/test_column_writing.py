"""structure.json's values rounded and converted a column at a time (outputs.common, outputs.structure_json):
the same values as the one-value-at-a-time rules they replace."""

from __future__ import annotations

import math
import random
from collections import OrderedDict, namedtuple

import networkx as nx
import numpy as np
import pytest

from g2s_plugins.outputs import common, structure_json
from g2s_plugins.outputs.json_text import dumps_indented

TRICKY_FLOATS = [
    1e-7, 1e21, -0.0, 0.0, float("nan"), float("inf"), -float("inf"), 123456789.123, -123456789.123, 0.1, 1 / 3,
    5e-324, 1e-320, 2.2250738585072014e-308, 1.7976931348623157e308, 1e-14, 1e-15, 1e22, 1e23,
    0.5, 2.5, 123456788.5, 123456789.5, 999999999.5, 9999999995.0, 0.1234567885, 1e9, 1e16,
    9999.99999999, 9999.999995, 1e4, -1e4, 12345.6789012345, 1e7 + 0.123456789, -3456789.1234567, 1e7, 987654321.987654,
    # next to a power of ten, where the exponent read from log10 may be one off
    *(p * f for p in (1e-9, 1e3, 1e8, 1e9, 1e21) for f in (1 - 1e-16, 1 + 2.2e-16, 1 - 5e-10, 0.9999999995, 1 + 5e-9)),
]


def _texts(values):
    """Each value's repr: tells -0.0 from 0.0 and compares nan-free lists exactly."""
    return [repr(v) for v in values]


def test_numbers_round_as_number_does_one_by_one():
    rng = random.Random(3)
    values = TRICKY_FLOATS + [rng.uniform(-1, 1) * 10 ** rng.uniform(-25, 25) for _ in range(20000)]
    values += [float(f"{rng.randint(10**8, 10**9 - 1)}5e{rng.randint(-20, 20)}") for _ in range(5000)]  # halves
    values += [np.float32(0.1), np.float64(-2.5), 7, -(2**60), True]
    assert _texts(common.numbers(values)) == _texts(common.number(v) for v in values)
    assert _texts(common.coordinates(values)) == _texts(common.coordinate(v) for v in values)
    assert common.numbers([1e-7, None, -0.0, float("nan")]) == [1e-07, None, 0.0, None]
    assert _texts(common.coordinates([1e4 + 0.123456789, -1e7 - 0.123456, 9999.123456789])) == \
        ["10000.12346", "-10000000.12346", "9999.12346"]
    assert common.numbers([]) == [] and common.coordinates([None]) == [None]


def test_significant_digits_is_format_g9():
    values = np.array(TRICKY_FLOATS)
    expected = [float(format(v, ".9g")) for v in TRICKY_FLOATS]
    assert _texts(common.significant_digits(values).tolist()) == _texts(expected)


def test_vectors_are_vector_one_by_one():
    cases = [
        [(1.0, 2.0, 3.0), None, (1e4 + 1e-6, -0.0, 5e-324)],
        [np.array([0.1, 0.2, 0.3], dtype=np.float32), [1, 2, 3], (0.5, float("nan"), float("inf"))],
        [(1.0, 2.0), (3.0, 4.0, 5.0)],  # ragged: one by one
        [np.zeros((1, 3)), np.ones(3)],  # a (1, 3) array flattens as vector() flattens it
        [None, None],
        [],
    ]
    for values in cases:
        assert common.vectors(values) == [common.vector(v) for v in values]
    with pytest.raises((TypeError, ValueError)):
        common.vectors([("a", "b", "c")])


def _plain_one_by_one(value):
    """The rule _plain follows, written for one value at a time (as it was before it went column-wise)."""
    if isinstance(value, str):
        return value
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, (int, np.integer)):
        return int(value)
    if isinstance(value, (float, np.floating)):
        return common.number(value)
    if value is None:
        return None
    if isinstance(value, (set, frozenset)):
        try:
            value = sorted(value)
        except TypeError:
            return structure_json._SKIP
    elif isinstance(value, np.ndarray):
        value = value.tolist()
    elif not isinstance(value, (dict, list, tuple)):
        return structure_json._SKIP
    if isinstance(value, dict):
        items = {str(k): _plain_one_by_one(v) for k, v in value.items()}
        return {k: v for k, v in items.items() if v is not structure_json._SKIP}
    if len(value) == 3 and all(type(v) is float for v in value):
        return common.vector(value)
    items = [_plain_one_by_one(v) for v in value]
    return structure_json._SKIP if any(i is structure_json._SKIP for i in items) else items


Point = namedtuple("Point", "x y z")


class Name(str):
    pass


ATTRIBUTES = [
    {"portal": ((1.0, 2.0, 3.0), (4.0, 5.0, 6.0)), "width": 1.3462912345},
    {"portal": [np.array([1e4 + 0.1234567, 0.0, -0.0]), (1.0, 2.0, 3)], "width": np.float32(0.7)},
    {"portal": [(1.0, 2.0, 3.0), (float("nan"), 1.0, 2.0)], "width": None},
    {"tags": {"b", "a"}, "mixed": {1, "a"}, "object": object(), "name": Name("n"), 7: "int key", 7.5: [1, 2.5]},
    {"nested": {"deep": [[0.1, 0.2, 0.3], [0.1, 0.2], [1, 2, 3], []], "skip": [object()]}, "flag": np.bool_(True)},
    {"point": Point(1.0, 2.0, 3.0), "ids": np.arange(3), "ordered": OrderedDict(b=1, a=2), "frozen": frozenset()},
    {"1": "str one", 1: "int one"},  # one key after str(): the last value wins, as dict() keeps it
    {},
    {"portal": ((1.0, 2.0, 3.0), (4.0, 5.0, 6.0)), "width": 2.0},
]


def test_plain_column_is_plain_one_by_one():
    expected = [_plain_one_by_one(a) for a in ATTRIBUTES]
    assert structure_json._plain_column(list(ATTRIBUTES)) == expected
    assert [structure_json._plain(a) for a in ATTRIBUTES] == expected
    assert dumps_indented(structure_json._plain_column(list(ATTRIBUTES))) == dumps_indented(expected)
    assert expected[1]["portal"] == [[10000.12346, 0.0, 0.0], [1.0, 2.0, 3]]
    assert expected[3] == {"tags": ["a", "b"], "name": "n", "7": "int key", "7.5": [1, 2.5]}
    assert "skip" not in expected[4]["nested"] and expected[4]["flag"] is True


def test_node_and_edge_records_hold_each_attribute_of_their_own():
    graph = nx.Graph()
    for node, attrs in enumerate(ATTRIBUTES):
        graph.add_node(node, pos=(float(node), 0.5, -0.0), normal=None if node % 2 else (0.0, 1.0, 0.0),
                       area=None if node == 3 else node / 3, **{str(k): v for k, v in attrs.items()})
    graph.add_edges_from((u, u + 1, ATTRIBUTES[u]) for u in range(len(ATTRIBUTES) - 1))
    flow = {n: n * 0.1 for n in graph if n != 2}
    nodes = structure_json._node_records(graph, {0}, {"flow": flow}, ["flow"])
    for record in nodes:
        node = record["id"]
        assert record["position"] == common.vector(graph.nodes[node]["pos"])
        assert record["normal"] == common.vector(graph.nodes[node]["normal"])
        assert record["values"] == ({} if node == 2 else {"flow": common.number(node * 0.1)})
        assert record["extra"] == _plain_one_by_one({str(k): v for k, v in ATTRIBUTES[node].items()})
        assert record["terminal"] is (node == 0)
    edges = structure_json._edge_records(graph)
    assert [(e["source"], e["target"]) for e in edges] == common.edge_list(graph)
    for edge in edges:
        attrs = ATTRIBUTES[edge["source"]]
        assert edge["weight"] is None
        assert edge["extra"] == _plain_one_by_one(attrs)
    directed = nx.DiGraph([(3, 1, {"weight": 0.25}), (1, 2, {"weight": -0.0})])
    assert [(e["source"], e["target"], e["weight"]) for e in structure_json._edge_records(directed)] == \
        [(1, 2, 0.0), (3, 1, 0.25)]
    assert math.copysign(1.0, structure_json._edge_records(directed)[0]["weight"]) == 1.0
