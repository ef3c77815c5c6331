"""The GraphML writer's shortcuts: tuples of floats flatten as their arrays do; two runs write the same bytes."""

from __future__ import annotations

import math

import numpy as np

from g2s_plugins.outputs import graphml

VALUES = {
    "pos": (70.22270122999512, 0.17499999701976776, -98.29064805421966),
    "normal": (0.0, -0.0, 1.0),
    "area": 21.15625,
    "portal": ((73.55000305175781, 0.05, 97.5), (71.3, math.nan, -0.0)),
    "corners": ((0.0, 1.0, 2.0), (3.0, 4.0, 5.0), (6.0, 7.0, math.inf)),
    "mixed": (1.0, 2, 3.5),  # an int among the floats: the array path
    "pair": (1.5, 2.5),
    "empty": (),
}


def test_float_tuples_flatten_as_their_arrays():
    from_tuples = graphml.flatten(VALUES)
    from_arrays = graphml.flatten({name: np.asarray(value, dtype=np.float64) if type(value) is tuple else value
                                   for name, value in VALUES.items()})
    assert list(from_tuples.items()) == list(from_arrays.items())  # the same names, values and order
    assert from_tuples["pos_z"] == -98.2906481 and "portal_1_y" not in from_tuples and "corners_2_z" not in from_tuples
    assert math.copysign(1.0, from_tuples["normal_y"]) == 1.0 and from_tuples["mixed_y"] == 2.0
    assert [k for k in from_tuples if k.startswith(("pair", "empty"))] == ["pair_0", "pair_1"]


def test_two_runs_write_the_same_graphml_bytes(tmp_path):
    from g2s_plugins.samples.levels import load_sample
    from tests.test_regions import run

    level = load_sample("loop_of_four_rooms")
    written = []
    for name in ("a", "b"):
        (tmp_path / name).mkdir()
        written.append(graphml.write(run(level), tmp_path / name))
    assert [p.name for p in written[0]] == ["structure.graphml", "graph.graphml"]
    for first, second in zip(*written):
        assert first.read_bytes() == second.read_bytes()
