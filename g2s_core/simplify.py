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
from collections import deque
from collections.abc import Callable

import networkx as nx
import numpy as np

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
    tree = forest.copy()
    children: Links = {node: set() for node in tree}
    loops: Links = {node: set() for node in tree}
    for a, b, loop in tree.edges(data="loop", default=False):
        if loop:
            loops[a].add(b)
            loops[b].add(a)
        else:
            children[a].add(b)
    for root in tree.graph["roots"]:
        _simplify_from(tree, children, loops, root, predicate)
    _shorten_loops(tree, children, loops, predicate)
    pending = [(root, 0) for root in tree.graph["roots"]]
    while pending:
        node, depth = pending.pop()
        tree.nodes[node]["depth"] = depth
        pending.extend((child, depth + 1) for child in children[node])
    return tree


def _simplify_from(tree: nx.DiGraph, children: Links, loops: Links, root: int, predicate: Predicate) -> None:
    pending = [root]
    while pending:
        a = pending.pop()
        queue = deque(sorted(children[a]))
        kept: list[int] = []
        while queue:
            b = queue.popleft()
            grandchildren = sorted(children[b])
            removable = (
                grandchildren
                and not tree.nodes[b].get("terminal", False)
                and not loops[b]
                # a loop edge a - c would be merged with a -> c: the loop a, b, c would vanish
                and not any(tree.has_edge(c, a) or tree.has_edge(a, c) for c in grandchildren)
            )
            if removable and all(predicate(tree, a, b, c) for c in grandchildren):
                tree.remove_node(b)
                children[a].remove(b)
                children[a].update(grandchildren)
                for c in grandchildren:
                    length = float(np.linalg.norm(np.subtract(tree.nodes[a]["pos"], tree.nodes[c]["pos"])))
                    tree.add_edge(a, c, weight=length)
                queue.extend(grandchildren)
            else:
                kept.append(b)
        pending.extend(reversed(kept))


def _shorten_loops(tree: nx.DiGraph, children: Links, loops: Links, predicate: Predicate) -> None:
    """Remove the non-terminal tree leaves whose only other edge is a loop edge, where the predicate allows.

    Candidates are examined by ascending id; the parent of a removed node
    may become a candidate in turn (it is examined again), so a loop path
    is shortened from the point where the spanning tree cut it.
    """
    pending = sorted(tree)  # a heap: the smallest id first
    while pending:
        b = heapq.heappop(pending)
        if b not in tree or tree.nodes[b].get("terminal", False) or children[b] or len(loops[b]) != 1:
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
        length = float(np.linalg.norm(np.subtract(tree.nodes[a]["pos"], tree.nodes[q]["pos"])))
        tree.add_edge(first, second, weight=length, loop=True)
        heapq.heappush(pending, a)
        heapq.heappush(pending, q)
