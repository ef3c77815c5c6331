"""Tree simplification (the paper's Algorithm 4).

For every node A, taken from the root down, a non-leaf child B of A is removed
when the predicate P(tree, A, B, C) holds for every child C of B; B's children
then become children of A. A's children are examined in order, children gained
this way go to the end of the list, and A is done when none can be removed.
This is the paper's "restart after each removal" loop without re-testing the
children that already failed (their answer cannot change: A, them and their
children are unchanged).

Terminals (nodes with ``terminal=True``) are never removed: they are the
points the structure exists to join. In the paper's two use cases terminals
are leaves of the tree, which Algorithm 4 never removes anyway; a selector
that picks inner nodes (e.g. by centrality) relies on this rule.

On a structure with loops (:mod:`g2s_core.rooted`) only tree edges are
followed, and a node at the end of a loop edge is never removed by
Algorithm 4, so every loop survives it (its other nodes may still be
dropped: A -> C replaces A -> B -> C inside the loop). A second pass then
shortens the loops where Algorithm 4 cannot reach: a non-terminal tree
leaf B whose only other edge is a loop edge B - Q (the point where the
depth-first spanning tree cut the loop) is removed when P(tree, A, B, Q)
holds for its parent A, and the loop edge A - Q replaces the two edges. A
and Q must not be joined already, so a loop never shrinks below a
triangle and never vanishes. Measured (docs/analysis_quality.md): these
nodes were 7 % of nav_test's and 4 % of a 1k-polygon dungeon's polygons
in the structure.

A predicate may carry a whole-forest path, ``predicate.whole_forest``: a
function of the forest as :class:`ForestArrays` returning what Algorithm 4
and the loop pass above do with the predicate's answers (which nodes stay,
which edges they add, in order), computed in one call (both line-of-sight
predicates do it in C++, src/forest_simplify.hpp). The structure is then
built from that answer, the same graph as the loop below would build: the
kept nodes in the forest's order, each node's successors and predecessors
in the order their edges were made (the forest's first, then the added
ones). This path owes the loop below the same answer on every forest, which
its plugin's tests check.

Complexity: O(n + k) predicate calls, k = number of removals, each call
plus the predicate's own cost.
"""

from __future__ import annotations

import heapq
import itertools
import math
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass

import networkx as nx
import numpy as np

from g2s_core.model import graph_of
from g2s_core.rooted import tree_parent

Predicate = Callable[[nx.DiGraph, int, int, int], bool]
Links = dict[int, set[int]]
"""Each node's tree children, or its partners along loop edges: plain sets kept in step with the tree, because
networkx answers every such question through new view objects, which on a 100k-polygon level cost more than
the predicate itself (docs/performance.md)."""


@dataclass(frozen=True)
class ForestArrays:
    """A rooted forest of n integer-id nodes and m loop edges, a row per node in the forest's node order.

    ``ids`` (n,) int64; ``parent`` (n,) int64 the row of each node's tree parent, -1 for a root; ``depth`` (n,)
    int64; ``fixed`` (n,) bool: never removed (terminals); ``loops`` (m,2) int64 rows of the loop edges u -> v;
    ``roots`` (r,) int64 rows of ``graph["roots"]``; ``points`` (n,3) float64 ``pos``, m; ``data`` each node's own
    attribute dict (read only).
    """

    ids: np.ndarray
    parent: np.ndarray
    depth: np.ndarray
    fixed: np.ndarray
    loops: np.ndarray
    roots: np.ndarray
    points: np.ndarray
    data: list[dict]


WholeForest = Callable[[ForestArrays], tuple[np.ndarray, np.ndarray, np.ndarray]]
"""``predicate.whole_forest(forest)``: (n,) bool the nodes that stay, (k,2) int64 the rows of the edges added
(A -> C, or the loop pass's loop edge), in the order added, and (k,) bool which of them are loop edges."""


def simplify_forest(forest: nx.DiGraph, predicate: Predicate, arrays: Callable[[], ForestArrays] | None = None) -> nx.DiGraph:
    """A simplified copy of a rooted ``forest`` (see :mod:`g2s_core.rooted`).

    New edges A -> C get ``weight`` = Euclidean distance between their ``pos``.
    ``depth`` is recomputed; ``graph["roots"]`` is kept. ``arrays``: :func:`forest_arrays` of ``forest``, when the
    caller keeps them between calls (the pipeline reads a forest once for all the rounds that simplify it: the
    whole-forest path's plugins then key what they derive from it on its identity); else read here.
    """
    whole_forest: WholeForest | None = getattr(predicate, "whole_forest", None)
    if whole_forest is not None:
        return _from_whole_forest(forest, whole_forest, arrays() if arrays is not None else forest_arrays(forest))
    # a copy as DiGraph.copy() makes it (see graph_of), and each node's children and loop partners
    edges = [(a, b, dict(data)) for a, below in forest.adjacency() for b, data in below.items()]
    tree = graph_of(nx.DiGraph(**forest.graph), {node: dict(data) for node, data in forest.nodes(data=True)}, edges)
    terminals = {node for node, data in tree.nodes(data=True) if data.get("terminal", False)}
    children: Links = {a: {b for b, data in below.items() if not data.get("loop", False)} for a, below in forest.adjacency()}
    loops: Links = {node: set() for node in tree}
    for a, b in ((a, b) for a, b, data in edges if data.get("loop", False)):
        loops[a].add(b)
        loops[b].add(a)
    for root in tree.graph["roots"]:
        _simplify_from(tree, children, loops, terminals, root, predicate)
    _shorten_loops(tree, children, loops, terminals, predicate)
    pending, nodes = [(root, 0) for root in tree.graph["roots"]], tree.nodes
    while pending:
        node, depth = pending.pop()
        nodes[node]["depth"] = depth
        pending.extend(zip(children[node], itertools.repeat(depth + 1)))
    return tree


def _simplify_from(tree: nx.DiGraph, children: Links, loops: Links, terminals: set[int], root: int, predicate: Predicate) -> None:
    pending = [root]
    while pending:
        a = pending.pop()
        queue = deque(sorted(children[a]))
        kept: list[int] = []
        while queue:
            b = queue.popleft()
            grandchildren = sorted(children[b])
            # kept: a leaf, a terminal, the end of a loop edge, or the parent of a node c with a loop edge a - c
            # (the only edge a grandchild can have with a), which a -> c would merge, so the loop a, b, c would vanish
            removable = grandchildren and b not in terminals and not loops[b] and loops[a].isdisjoint(grandchildren)
            if removable and all(predicate(tree, a, b, c) for c in grandchildren):
                tree.remove_node(b)
                children[a].remove(b)
                children[a].update(grandchildren)
                for c in grandchildren:
                    tree.add_edge(a, c, weight=_length(tree, a, c))
                queue.extend(grandchildren)
            else:
                kept.append(b)
        pending.extend(reversed(kept))


def _shorten_loops(tree: nx.DiGraph, children: Links, loops: Links, terminals: set[int], predicate: Predicate) -> None:
    """Remove the non-terminal tree leaves whose only other edge is a loop edge, where the predicate allows.

    Candidates are examined by ascending id; the parent of a removed node
    may become a candidate in turn (it is examined again), so a loop path
    is shortened from the point where the spanning tree cut it. Only a
    removal changes a node's children and loop partners, and it puts both
    nodes whose links it changed back on the heap: the other nodes need
    examining once, and only those that are candidates at the start.
    """
    candidates = (b for b in tree if not children[b] and len(loops[b]) == 1 and b not in terminals)
    pending = sorted(candidates)  # a heap: the smallest id first
    while pending:
        b = heapq.heappop(pending)
        if b not in tree or b in terminals or children[b] or len(loops[b]) != 1:
            continue
        a, (q,) = tree_parent(tree, b), loops[b]
        if a is None or tree.has_edge(a, q) or tree.has_edge(q, a) or not predicate(tree, a, b, q):
            continue
        tree.remove_node(b)
        children[a].remove(b)
        loops[q].remove(b)
        loops[a].add(q)
        loops[q].add(a)
        first, second = sorted((a, q), key=lambda node: (tree.nodes[node]["depth"], node))
        tree.add_edge(first, second, weight=_length(tree, a, q), loop=True)
        heapq.heappush(pending, a)
        heapq.heappush(pending, q)


def _length(tree: nx.DiGraph, a: int, c: int) -> float:
    """Distance between the ``pos`` of ``a`` and ``c``, m: the squares summed in order, the bits of
    ``numpy.linalg.norm`` in plain floats (0.2 us a call instead of numpy's 6 us)."""
    (ax, ay, az), (cx, cy, cz) = tree.nodes[a]["pos"], tree.nodes[c]["pos"]
    return math.sqrt((ax - cx) * (ax - cx) + (ay - cy) * (ay - cy) + (az - cz) * (az - cz))


def forest_arrays(forest: nx.DiGraph) -> ForestArrays:
    """``forest`` (integer ids) as :class:`ForestArrays`: its adjacency read by numpy's C loops, O(n + m log n)."""
    succ, data, n = forest._succ, list(forest._node.values()), forest.number_of_nodes()
    ids = np.fromiter(succ, np.int64, n)
    order = np.argsort(ids)
    tails = np.repeat(np.arange(n), np.fromiter(map(len, succ.values()), np.int64, n))
    heads = order[np.searchsorted(ids, np.fromiter(itertools.chain.from_iterable(succ.values()), np.int64, len(tails)),
                                  sorter=order)]
    loop = np.fromiter((e.get("loop", False) for below in succ.values() for e in below.values()), bool, len(tails))
    parent = np.full(n, -1, dtype=np.int64)
    parent[heads[~loop]] = tails[~loop]
    roots = order[np.searchsorted(ids, np.array(forest.graph["roots"], dtype=np.int64), sorter=order)]
    return ForestArrays(
        ids=ids, parent=parent, depth=np.fromiter((d["depth"] for d in data), np.int64, n),
        fixed=np.fromiter((bool(d.get("terminal", False)) for d in data), bool, n),
        loops=np.stack([tails[loop], heads[loop]], axis=1), roots=roots,
        points=np.fromiter(itertools.chain.from_iterable(d["pos"] for d in data), np.float64, 3 * n).reshape(n, 3),
        data=data)


def _from_whole_forest(forest: nx.DiGraph, whole_forest: WholeForest, arrays: ForestArrays) -> nx.DiGraph:
    """The structure :func:`simplify_forest` builds, from the answer of a predicate's whole-forest path on
    ``arrays``, ``forest``'s."""
    kept, added, loop = whole_forest(arrays)
    ids, both = arrays.ids.tolist(), kept[added].all(axis=1)  # both: the added edges whose ends both stay
    keep, added, loop = dict(zip(ids, kept.tolist())), added[both], loop[both]
    # the forest's edges whose ends both stay, in its order, then the added edges whose ends both stay, in theirs
    edges = [(a, b, dict(data)) for a, below in forest._succ.items() if keep[a] for b, data in below.items() if keep[b]]
    offset = arrays.points[added[:, 0]] - arrays.points[added[:, 1]]  # the squares summed in _length's order
    lengths = np.sqrt(offset[:, 0] * offset[:, 0] + offset[:, 1] * offset[:, 1] + offset[:, 2] * offset[:, 2]).tolist()
    edges.extend((a, c, {"weight": length, "loop": True} if is_loop else {"weight": length})
                 for (a, c), length, is_loop in zip(arrays.ids[added].tolist(), lengths, loop.tolist()))
    depth = _depths(arrays.parent, kept).tolist()
    nodes = {node: {**data, "depth": d} for node, data, d in zip(ids, arrays.data, depth) if keep[node]}
    return graph_of(nx.DiGraph(**forest.graph), nodes, edges)


def _depths(parent: np.ndarray, kept: np.ndarray) -> np.ndarray:
    """(n,) each node's depth once the nodes not ``kept`` are gone: its kept ancestors in the forest of ``parent``
    (Algorithm 4 joins a removed node's children to its parent; the loop pass removes leaves). Pointer jumping,
    O(n log n)."""
    # above[i]: an ancestor of i (a root: itself); count[i]: the kept nodes above i up to it, itself included
    rooted = parent >= 0
    above = np.where(rooted, parent, np.arange(len(parent)))
    count = (rooted & kept[above]).astype(np.int64)
    for _ in range(len(parent).bit_length()):  # each doubles the distance covered: enough for a path of n nodes
        above, count = above[above], count + count[above]
    return count
