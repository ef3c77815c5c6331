"""Boundary loops of a polygon surface (a navmesh, or the faces of a sampled graph) and loop sampling for ``entry_exit``.

Conventions: metres, Y up, right-handed. A boundary loop is oriented so that
the walkable interior lies on the *left* of the walking direction ``t`` seen
from above, i.e. on the side of ``up x t``; the outward side is ``t x up``.
Outer rims therefore run counter-clockwise seen from above and the rims of
holes clockwise.

Complexity: O(V log V + B log B) to weld the V navmesh vertices by position
and chain the B boundary edges (one sort of each; a pinch vertex's few
edges are compared one by one); sampling O(B + S) for S samples.
"""

from __future__ import annotations

from dataclasses import dataclass
import numpy as np

from g2s_core.errors import G2SError
from g2s_plugins._raycasting import UP

WELD = 1e-4
"""Metres: navmesh vertices closer than this (per axis, rounded) are one vertex when chaining loops."""

MAX_BOUNDARY_SAMPLES = 10_000_000
"""Boundary samples at most (0.24 GB of positions): more means a step far too small for the level (1,250 km of
boundary at the default agent's 0.125 m)."""


# --------------------------------------------------------------------------
# Boundary loops
# --------------------------------------------------------------------------


@dataclass(frozen=True)
class BoundaryLoop:
    """One chain of navmesh boundary edges, walkable interior on the left.

    Attributes:
        points: (n,3) vertex positions; edge ``i`` runs from ``points[i]`` to
            ``points[i + 1]`` (wrapping when ``closed``).
        polygons: (n,) or (n-1,) navmesh polygon owning each edge.
        closed: whether the chain closes on itself (it does on a well-formed navmesh).
    """

    points: np.ndarray
    polygons: np.ndarray
    closed: bool

    @property
    def edge_count(self) -> int:
        return len(self.polygons)


def boundary_edges(
    vertices: np.ndarray, polygons: np.ndarray, neighbours: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The boundary edges of a polygon mesh (neighbour -1), oriented interior-left.

    Returns ``start`` and ``end`` vertex indices and the owning ``polygon``, each (E,).
    """
    vertices = np.asarray(vertices, dtype=np.float64)
    polygons = np.asarray(polygons)
    neighbours = np.asarray(neighbours)
    valid = polygons >= 0
    counts = valid.sum(axis=1)
    i, j = np.nonzero(valid & (neighbours < 0))
    a = polygons[i, j].astype(np.int64)
    b = polygons[i, (j + 1) % np.maximum(counts[i], 1)].astype(np.int64)
    # Polygon centroid (vertex mean) decides which side is inside.
    safe = np.where(valid, polygons, 0)
    centre = (vertices[safe] * valid[..., None]).sum(axis=1) / np.maximum(counts, 1)[:, None]
    d = vertices[b] - vertices[a]
    left = np.cross(UP, d)  # up x d: the left side seen from above
    inside = np.einsum("ij,ij->i", centre[i] - vertices[a], left)
    # A polygon of two corners (single-file samples of a sampled graph) has no inside: its centre lies on its
    # edge and the sign above is rounding noise, which turned both of its edges the same way. Its two edges,
    # one each way, are its two sides, so the loop runs along one, round the line's end and back along the other.
    flip = (inside < 0) & (counts[i] > 2)
    a, b = np.where(flip, b, a), np.where(flip, a, b)
    keep = a != b
    return a[keep], b[keep], i[keep].astype(np.int64)


def _left_turn(d_in: np.ndarray, d_out: np.ndarray) -> float:
    """Signed horizontal turn from ``d_in`` to ``d_out``, radians, positive to the left."""
    cross = float(np.dot(np.cross(d_in, d_out), UP))
    dot = float(d_in[0] * d_out[0] + d_in[2] * d_out[2])
    return float(np.arctan2(cross, dot))


def boundary_loops(vertices: np.ndarray, polygons: np.ndarray, neighbours: np.ndarray) -> list[BoundaryLoop]:
    """Chain the boundary edges of a navmesh into loops (interior on the left).

    Vertices at the same position (to :data:`WELD`) are one vertex, so loops
    run on across the tile borders of a tiled navmesh. Every boundary vertex
    of a well-formed navmesh has as many outgoing as
    incoming boundary edges; the successor of an edge is the one edge leaving
    its end vertex, found with one sorted look-up for all edges. Where several
    edges leave one vertex (two areas touching at a point) the successor is
    the one turning most to the left, which keeps each loop around one area.
    Open chains (only on a malformed navmesh, or where a sampled graph's edges still cross seen from
    above) come first, then closed loops in
    the order of their lowest edge: deterministic for a given navmesh.
    """
    vertices = np.asarray(vertices, dtype=np.float64)
    start, end, owner = boundary_edges(vertices, polygons, neighbours)
    n_edges = len(start)
    if n_edges == 0:
        return []
    # Chain by position, not index: tiles of a tiled navmesh repeat their border vertices.
    _, weld = np.unique(np.round(vertices / WELD).astype(np.int64), axis=0, return_inverse=True)
    weld = weld.reshape(-1)
    start, end = weld[start], weld[end]
    keep = start != end
    start, end, owner = start[keep], end[keep], owner[keep]
    first_of = np.zeros(int(weld.max()) + 1, dtype=np.int64)
    first_of[weld[::-1]] = np.arange(len(weld))[::-1]  # a representative vertex per position
    vertices = vertices[first_of]
    n_edges = len(start)
    if n_edges == 0:
        return []
    order = np.argsort(start, kind="stable")
    sorted_start = start[order]
    lo = np.searchsorted(sorted_start, end, side="left")
    hi = np.searchsorted(sorted_start, end, side="right")
    count = hi - lo
    successor = np.where(count >= 1, order[np.minimum(lo, n_edges - 1)], -1)
    for e in np.nonzero(count > 1)[0]:  # pinch vertices: rare, decided one by one
        candidates = order[lo[e]:hi[e]]
        d_in = vertices[end[e]] - vertices[start[e]]
        turns = [
            -np.inf if end[c] == start[e] else _left_turn(d_in, vertices[end[c]] - vertices[start[c]])
            for c in candidates
        ]  # going straight back is the last resort
        successor[e] = candidates[int(np.argmax(turns))]

    # Each edge is used once: walk successor chains, claiming edges.
    used = np.zeros(n_edges, dtype=bool)
    has_predecessor = np.zeros(n_edges, dtype=bool)
    has_predecessor[successor[successor >= 0]] = True
    loops: list[BoundaryLoop] = []
    # Open chains first start where no edge leads in; then closed loops.
    starts = list(np.nonzero(~has_predecessor)[0]) + list(range(n_edges))
    for first in starts:
        if used[first]:
            continue
        chain = []
        e = int(first)
        while e >= 0 and not used[e]:
            used[e] = True
            chain.append(e)
            e = int(successor[e])
        closed = e == first
        chain_arr = np.asarray(chain, dtype=np.int64)
        if closed:
            pts = vertices[start[chain_arr]]
        else:
            pts = np.concatenate([vertices[start[chain_arr]], vertices[end[chain_arr[-1:]]]])
        loops.append(BoundaryLoop(points=pts, polygons=owner[chain_arr], closed=closed))
    return loops


# --------------------------------------------------------------------------
# Sampling
# --------------------------------------------------------------------------


@dataclass(frozen=True)
class LoopSamples:
    """Points taken at even spacing along boundary loops.

    Attributes:
        position: (M,3) sample points on the loop.
        tangent: (M,3) unit direction of the edge each sample lies on.
        polygon: (M,) navmesh polygon owning that edge.
        loop: (M,) index of the loop the sample belongs to.
        spacing: (L,) the spacing actually used on each loop, metres.
        closed: (L,) bool, whether each loop is closed.
    Samples of one loop are contiguous and in walking order.
    """

    position: np.ndarray
    tangent: np.ndarray
    polygon: np.ndarray
    loop: np.ndarray
    spacing: np.ndarray
    closed: np.ndarray


TIP_TURNS_DEG = (45.0, 90.0, 135.0)
"""Degrees: where a loop goes back along the edge it came (the end of a line of samples in single file on a sampled
surface), :func:`sample_loops` adds samples at the tip whose outward sides turn this far from the incoming side's
towards the outgoing one's, so the tip looks ahead as well as to both sides (docs/entry_exit.md, "A twentieth round
of piece kinds"). Measured against one turn (90) and five (30-150) over rounds 10-21 on the sampling route: one
recalls as many known openings (852 of 876), five two more but as slivers of a revolving drum's mouth, losing a
ledge's end (docs/entry_exit.md, "A twenty-first round of piece kinds")."""


def sample_loops(loops: list[BoundaryLoop], step: float, setting: str = "step", tips: bool = False) -> LoopSamples:
    """Samples every ``step`` metres (rounded so each loop is evenly divided).

    Sample k of a loop of length L with n = max(1, round(L / step)) samples
    lies at arc length (k + 1/2) L / n, so no sample sits on a corner. With
    ``tips``, each point where the loop turns straight back along its last edge
    (a polygon of two corners: samples in single file) also holds one sample per
    :data:`TIP_TURNS_DEG`, in walking order; a navmesh's loops have no such point.

    Raises:
        G2SError: more than :data:`MAX_BOUNDARY_SAMPLES` samples; the message starts with ``setting``, the
            config key that chose ``step``.
    """
    if not loops or step <= 0:
        z = np.zeros((0, 3))
        none = np.zeros(0, np.int64)
        return LoopSamples(z, z.copy(), none, none.copy(), np.zeros(len(loops)), np.zeros(len(loops), bool))
    seg_a, seg_b, seg_poly, seg_loop = [], [], [], []
    for index, lp in enumerate(loops):
        pts = lp.points
        a = pts[: lp.edge_count]
        b = np.roll(pts, -1, axis=0)[: lp.edge_count] if lp.closed else pts[1:]
        seg_a.append(a)
        seg_b.append(b)
        seg_poly.append(lp.polygons)
        seg_loop.append(np.full(lp.edge_count, index, dtype=np.int64))
    A = np.concatenate(seg_a)
    B = np.concatenate(seg_b)
    poly = np.concatenate(seg_poly)
    loop_of_edge = np.concatenate(seg_loop)
    length = np.linalg.norm(B - A, axis=1)
    cum = np.concatenate([[0.0], np.cumsum(length)])  # global arc length over all loops
    n_loops = len(loops)
    loop_start = np.searchsorted(loop_of_edge, np.arange(n_loops), side="left")
    loop_len = np.bincount(loop_of_edge, weights=length, minlength=n_loops)
    if not (wanted := float(loop_len.sum()) / step) <= MAX_BOUNDARY_SAMPLES:
        raise G2SError(f"{setting}: a sample every {step:g} m along the navmesh's {loop_len.sum():.4g} m of boundary "
                       f"makes {wanted:.3g} samples, more than {MAX_BOUNDARY_SAMPLES:,}; use a larger {setting}")
    n_samples = np.maximum(1, np.rint(loop_len / step)).astype(np.int64)
    spacing = loop_len / n_samples
    sample_loop = np.repeat(np.arange(n_loops), n_samples)
    k = np.arange(len(sample_loop)) - np.repeat(np.cumsum(n_samples) - n_samples, n_samples)
    s = cum[loop_start[sample_loop]] + (k + 0.5) * spacing[sample_loop]
    edge = np.searchsorted(cum, s, side="right") - 1
    # stay inside the sample's own loop (zero-length edges at loop ends)
    last_edge = np.r_[loop_start[1:], len(length)] - 1
    edge = np.clip(edge, loop_start[sample_loop], last_edge[sample_loop])
    f = np.clip((s - cum[edge]) / np.where(length[edge] > 0, length[edge], 1.0), 0.0, 1.0)
    position = A[edge] + f[:, None] * (B[edge] - A[edge])
    tangent = (B[edge] - A[edge]) / np.where(length[edge] > 0, length[edge], 1.0)[:, None]
    closed = np.array([lp.closed for lp in loops], dtype=bool)
    polygon = poly[edge]
    if tips:
        # each edge's successor in its loop (the first edge after the last in a closed loop; none in an open one)
        after = np.arange(len(length)) + 1
        ends = last_edge[loop_of_edge] == np.arange(len(length))
        after[ends] = np.where(closed[loop_of_edge[ends]], loop_start[loop_of_edge[ends]], -1)
        back = (after >= 0) & np.all(A[np.maximum(after, 0)] == B, axis=1) & np.all(B[np.maximum(after, 0)] == A, axis=1)
        back &= length > 0
        tip = np.flatnonzero(back)
        if len(tip):
            t = (B[tip] - A[tip]) / length[tip][:, None]
            out = np.cross(t, UP)  # the incoming side's outward (interior on the left)
            turns = np.radians(np.asarray(TIP_TURNS_DEG))
            # the tangent whose outward side (tangent x up) is cos(a) out + sin(a) t: cos(a) t - sin(a) out
            extra = (np.cos(turns)[None, :, None] * t[:, None, :]
                     - np.sin(turns)[None, :, None] * out[:, None, :]).reshape(-1, 3)
            at = np.where(after[tip] > tip, cum[tip + 1], cum[loop_start[loop_of_edge[tip]]])
            order = np.lexsort((np.r_[np.zeros(len(s)), np.tile(1.0 + np.arange(len(turns)), len(tip))],
                                np.r_[s, np.repeat(at, len(turns))]))
            position = np.concatenate([position, np.repeat(B[tip], len(turns), axis=0)])[order]
            tangent = np.concatenate([tangent, extra / np.linalg.norm(extra, axis=1)[:, None]])[order]
            polygon = np.concatenate([polygon, np.repeat(poly[tip], len(turns))])[order]
            sample_loop = np.concatenate([sample_loop, np.repeat(loop_of_edge[tip], len(turns))])[order]
    return LoopSamples(position, tangent, polygon, sample_loop, spacing, closed)


def polygon_components(neighbours: np.ndarray, joined: np.ndarray | None = None) -> np.ndarray:
    """(P,) connected-component label of every navmesh polygon (polygons joined across shared edges).

    ``joined``: (k, 2) further pairs of polygon indices to treat as neighbours.
    """
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    neighbours = np.asarray(neighbours)
    p = len(neighbours)
    i, j = np.nonzero(neighbours >= 0)
    k = neighbours[i, j].astype(np.int64)
    if joined is not None and len(joined):
        pairs = np.asarray(joined, dtype=np.int64).reshape(-1, 2)
        i, k = np.r_[i, pairs[:, 0]], np.r_[k, pairs[:, 1]]
    graph = coo_matrix((np.ones(len(i)), (i, k)), shape=(p, p))
    return connected_components(graph, directed=False)[1].astype(np.int64)
