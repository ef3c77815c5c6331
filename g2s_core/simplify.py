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

Complexity: O(n + k) predicate calls, k = number of removals, each call
plus the predicate's own cost.
"""

from __future__ import annotations

import heapq
import itertools
import math
from collections import deque
from collections.abc import Callable

import networkx as nx

from g2s_core.model import graph_of
from g2s_core.rooted import tree_parent

Predicate = Callable[[nx.DiGraph, int, int, int], bool]
Links = dict[int, set[int]]
"""Each node's tree children, or its partners along loop edges: plain sets kept in step with the tree, because
networkx answers every such question through new view objects, which on a 100k-polygon level cost more than
the predicate itself (docs/performance.md)."""


def simplify_forest(forest: nx.DiGraph, predicate: Predicate) -> nx.DiGraph:
    """A simplified copy of a rooted ``forest`` (see :mod:`g2s_core.rooted`).

    New edges A -> C get ``weight`` = Euclidean distance between their ``pos``.
    ``depth`` is recomputed; ``graph["roots"]`` is kept.
    """
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
