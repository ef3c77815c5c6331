"""The walking flow's kernel on a graph renumbered for memory locality (g2s_plugins.flow_layout): the same bits."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp

from g2s_core.config import AgentConfig
from g2s_plugins import _trees, traffic
from g2s_plugins._raycasting import AgentShape
from g2s_plugins.flow_layout import renumbered
from g2s_plugins.graph_builders import sampling
from g2s_plugins.samples import levels


def undirected(n: int, edges: list[tuple[int, int, float]]) -> sp.csr_array:
    """Symmetric CSR edge lengths of an undirected graph on nodes 0..n-1."""
    u, v, w = (np.array(column) for column in zip(*edges))
    return sp.csr_array((np.r_[w, w], (np.r_[u, v], np.r_[v, u])), shape=(n, n))


def twinned_grid(side: int) -> sp.csr_array:
    """A grid of unit steps (every pair of nodes many equally short paths apart) and, beside every third node, a twin
    1e-12 m from it and 1 m from the node below it: twin and node tie within the tolerance, so the order in which
    they settle decides which of them the other's shortest paths run through."""
    edges = [(r * side + c, r * side + c + 1, 1.0) for r in range(side) for c in range(side - 1)]
    edges += [(r * side + c, (r + 1) * side + c, 1.0) for r in range(side - 1) for c in range(side)]
    twin = side * side
    for v in range(0, side * side, 3):
        edges.append((v, twin, 1e-12))
        if v + side < side * side:
            edges.append((twin, v + side, 1.0))
        twin += 1
    return undirected(twin, edges)


def test_a_path_renumbered_by_hand():
    # 0 -1 m- 1 -2 m- 2 taken as 2, 0, 1: node 0 is the old 2 (its one edge to the old 1, now 2), node 1 the old 0,
    # node 2 the old 1 with its entries in their order (the old 0, now 1; the old 2, now 0)
    layout = renumbered(undirected(3, [(0, 1, 1.0), (1, 2, 2.0)]), np.array([2, 0, 1]))
    assert layout.indptr.tolist() == [0, 1, 2, 4]
    assert layout.indices.tolist() == [2, 2, 1, 0]
    assert layout.lengths.tolist() == [2.0, 1.0, 1.0, 2.0]
    assert layout.original.tolist() == [2, 0, 1]
    assert (layout.indptr.dtype, layout.indices.dtype, layout.original.dtype) == (np.int32, np.int32, np.int32)


@pytest.mark.parametrize("seed", range(4))
def test_the_renumbered_kernel_gives_the_same_bits_on_a_grid_with_ties(seed):
    adjacency = twinned_grid(7)
    n = adjacency.shape[0]
    values = np.random.default_rng(seed).uniform(0.5, 5.0, n)
    sources = np.arange(n)
    order = np.random.default_rng(100 + seed).permutation(n)
    layout = renumbered(adjacency, order)
    expected = traffic.linear_through(adjacency, sources, values, "split")
    assert traffic.linear_through(adjacency, sources, values, "split", layout).tobytes() == expected.tobytes()
    # what the caller's tie order guards against: the renumbered graph searched in its own numbering moves the flow
    # where twins tie, by far more than rounding
    own = np.empty_like(expected)
    own[:, order] = _trees.linear_path_flow(layout.indptr, layout.indices, layout.lengths,
                                            np.argsort(order)[sources].astype(np.int32), values[order], "split",
                                            traffic.TIE_TOLERANCE, 1)
    assert np.abs(own - expected).max() > 1.0


def test_a_sampled_flow_runs_on_the_renumbered_graph_with_the_same_bits():
    mesh = levels.dungeon(seed=1, rooms=6).mesh
    graph = sampling.build_sampled_graph(mesh, sampling.Params(method="grid"), AgentShape.from_config(AgentConfig()))
    arrays = traffic.surface_arrays(graph)
    layout = traffic.flow_layout(arrays)
    assert layout is not None and np.array_equal(layout.original, traffic.plan_order(graph))
    flow = traffic.walking_flow(graph, max_sources=16, ties="split", scaling="linear", sampling="spread")
    plain, _ = traffic.od_flow(arrays.adjacency, traffic.origin_weight(arrays), 16, 0, "split", "linear",
                               traffic.plan_order(graph), traffic.arrays_exact_areas(arrays, 16))
    assert flow.tobytes() == plain.tobytes()


def test_bad_renumbering_is_refused():
    adjacency = undirected(3, [(0, 1, 1.0), (1, 2, 2.0)])
    csr = traffic.extension_csr(adjacency)
    args = (*csr, np.array([0], dtype=np.int32), np.ones(3))
    with pytest.raises(ValueError, match="every node once"):
        _trees.linear_path_flow(*args, "split", 0.0, 1, None, np.array([0, 0, 1], dtype=np.int32))
    with pytest.raises(ValueError, match="original must be"):
        _trees.linear_path_flow(*args, "split", 0.0, 1, None, np.array([0, 1], dtype=np.int32))
    with pytest.raises(ValueError, match="ties 'split' only"):
        _trees.linear_path_flow(*args, "first", 0.0, 1, None, np.array([2, 0, 1], dtype=np.int32))
