"""The fixed JSON text (g2s_plugins.outputs.json_text): the standard library's indented text, character for character."""

from __future__ import annotations

import enum
import json
import random

import numpy as np
import pytest

from g2s_plugins.outputs.json_text import dumps_indented


def standard(value) -> str:
    return json.dumps(value, sort_keys=True, indent=1, ensure_ascii=False, allow_nan=False)


class Level(enum.IntEnum):
    GROUND = 0
    UPPER = 1


class Name(str):
    pass


TRICKY = [
    {},
    [],
    (),
    "",
    0,
    -0.0,
    0.1,
    1e16,
    1e-7,
    -123456789.123,
    5e-324,
    1.7976931348623157e308,
    2**70,
    -(2**63),
    True,
    False,
    None,
    "plain",
    'quote " backslash \\ slash / tab \t newline \n nul \x00 bell \x07 del \x7f',
    "unicode: é ü 中文 m² \u2028 \u2029 \ud800 😀",
    {"b": 1, "a": [], "c": {}, "A": [[]], "é": {"": None}, "a b": ({},)},
    [True, 1, 1.0, False, 0, 0.0],
    [1, 2, 3],
    [1.5, -2.25, 3.0],
    [1, 2.5],
    [[1, 2], [3, 4]],
    [{"x": [1.0, 2.0, 3.0], "y": None}, {"x": [], "y": {"z": [[], {}]}}],
    (1, (2, (3, ())), [4, [5]]),
    {"deep": [[[[[[[["bottom"]]]]]]]]},
    # types the writer hands to json.dumps: subclasses, non-str keys, numpy scalars that are float/int subclasses
    [Level.UPPER, {"level": Level.GROUND}],
    [Name("sub"), {Name("k"): Name("v")}],
    {10: "int key", 2: "int key"},
    {2.5: "float key", -1e-9: "float key", True: "bool key"},
    {None: "none key"},
    {"scalars": [np.float64(0.1), np.float64(-2.5)]},
    [np.float64(1.0), 2.0],
]


@pytest.mark.parametrize("value", TRICKY, ids=range(len(TRICKY)))
def test_tricky_values_give_the_standard_text(value):
    assert dumps_indented(value) == standard(value)
    # the same value inside nested containers, where every line is indented deeper
    nested = {"outer": [value, {"inner": value}], "z": [[value]]}
    assert dumps_indented(nested) == standard(nested)


def random_value(rng: random.Random, depth: int):
    choice = rng.randrange(10 if depth < 5 else 6)
    if choice == 0:
        return rng.choice([None, True, False])
    if choice == 1:
        return rng.randint(-(10**12), 10**12)
    if choice == 2:
        return rng.choice([rng.uniform(-1e6, 1e6), rng.random() * 1e-9, float(rng.randint(-5, 5)), 1e22])
    if choice == 3:
        return "".join(rng.choice("ab\"\\\n\té中😀 /\x01") for _ in range(rng.randrange(6)))
    if choice == 4:
        return [rng.random() for _ in range(rng.randrange(4))]
    if choice == 5:
        return [rng.randint(0, 99) for _ in range(rng.randrange(4))]
    if choice in (6, 7):
        return [random_value(rng, depth + 1) for _ in range(rng.randrange(4))]
    return {"".join(rng.choice("abcé_ ") for _ in range(rng.randrange(1, 4))): random_value(rng, depth + 1)
            for _ in range(rng.randrange(5))}


def test_random_documents_give_the_standard_text():
    rng = random.Random(7)
    for _ in range(300):
        value = random_value(rng, 0)
        assert dumps_indented(value) == standard(value)


@pytest.mark.parametrize(("value", "error"), [
    (float("nan"), ValueError), ([1.0, float("inf")], ValueError), ({"a": [-float("inf")]}, ValueError),
    ({"k": {1.0: 2}, "nan": {float("nan"): 1}}, ValueError),
    (object(), TypeError), ([1, {"a": {1, 2}}], TypeError), ({"a": np.int64(3)}, TypeError),
    ({(1, 2): "tuple key"}, TypeError), ({"a": {1: "int key", "b": "str key"}}, TypeError),
])
def test_what_json_cannot_write_raises_as_json_does(value, error):
    # non-finite floats (allow_nan=False): ValueError; values JSON cannot hold: TypeError
    with pytest.raises(error) as standard_error:
        standard(value)
    with pytest.raises(error) as ours:
        dumps_indented(value)
    assert str(ours.value) == str(standard_error.value)


def test_circular_reference_raises_as_json_does():
    loop: list = [1]
    loop.append({"back": loop})
    with pytest.raises(ValueError, match="Circular reference detected"):
        dumps_indented(loop)


def test_deep_nesting_gives_the_standard_text():
    value: list = []
    for _ in range(300):
        value = [value, {"k": 1}]
    assert dumps_indented(value) == standard(value)


def test_columns_of_records_give_the_standard_text():
    # the writer works a column at a time: records with the same keys, lists of one length, columns of mixed types
    rng = random.Random(11)
    records = [{
        "id": i,
        "position": [rng.uniform(-1e7, 1e7) for _ in range(3)],
        "area": rng.choice([None, 0.5, 1, "x", True, -0.0, 1e-7, 1e21, np.float64(2.5)]),
        "values": {"flow": rng.random()} if i % 3 else {},
        "extra": rng.choice([{}, {"portal": [[1.0, 2.0, 3.0], (4.0, 5.0, 6.0)]}, {"b": [1, [2]], "a": None}, {2: "k"}]),
    } for i in range(500)]
    mixed = [*records[:50], [1, 2, 3], [[1, 2]] * 20, list(range(40)), "s", 1.5, None, True, {}, [], ()]
    value = {"records": records, "mixed": mixed, "lengths": [list(range(i)) for i in range(30)] * 2,
             "pairs": [(i, i + 1) for i in range(100)], "long rows": [list(range(17))] * 3}
    assert dumps_indented(value) == standard(value)


def test_a_bad_value_deep_in_a_column_raises_as_json_does():
    records = [{"x": [0.5, 1.0]} for _ in range(10)] + [{"x": [0.5, float("nan")]}]
    with pytest.raises(ValueError, match="Out of range float values are not JSON compliant"):
        dumps_indented({"records": records})
    with pytest.raises(TypeError, match="Object of type set is not JSON serializable"):
        dumps_indented([{"x": 1}, {"x": {1}}])
