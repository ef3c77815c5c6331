"""The colours every output uses, as in the paper's figures.

* Tree depth: an edge takes the colour of its child's depth, red for depth 1,
  yellow for 2, then green, cyan, blue, magenta, orange, violet, repeating.
* Roots are black and have their own marker shape in every format, so no
  colour means both "root" and something else; terminals and openings are
  vermilion (Okabe and Ito's colour-blind-safe palette).
* Analysis values: matplotlib's viridis, a perceptually uniform sequential
  scale that colour-blind readers and greyscale prints read the same way:
  dark purple (lowest) -> teal -> yellow (highest), after min-max
  normalisation of the values shown.
* Regions: Okabe and Ito's other six colours (their black and vermilion
  already mean roots and terminals), given so that regions joined by a
  chokepoint differ (:func:`region_colours`); chokepoints are near-black and
  have their own marker shape.
* Loop edges (a structure with loops) are near-black too but dotted in the
  PNG and the report, and in the glTF run along paths in their own ``loops``
  group, where a chokepoint is a short bar across a portal.

Colours are 8-bit RGB tuples.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from typing import TYPE_CHECKING, Any

import networkx as nx
import numpy as np

if TYPE_CHECKING:  # matplotlib loads only when a heat map is drawn
    from matplotlib.colors import Colormap

RGB = tuple[int, int, int]

DEPTH_COLOURS: tuple[RGB, ...] = (
    (220, 30, 30),    # 1 red
    (240, 200, 0),    # 2 yellow
    (40, 170, 60),    # 3 green
    (0, 180, 200),    # 4 cyan
    (40, 80, 220),    # 5 blue
    (190, 50, 190),   # 6 magenta
    (245, 130, 20),   # 7 orange
    (120, 70, 200),   # 8 violet
)
"""Colour of depth d >= 1 is ``DEPTH_COLOURS[(d - 1) % len(DEPTH_COLOURS)]``."""

ROOT_COLOUR: RGB = (0, 0, 0)
TERMINAL_COLOUR: RGB = (213, 94, 0)
MESH_COLOUR: RGB = (170, 170, 170)
NAVMESH_COLOUR: RGB = (60, 200, 90)
NAVMESH_ALPHA = 0.35
GRAPH_COLOUR: RGB = (90, 90, 90)
STEINER_COLOUR: RGB = (150, 60, 200)
LOOP_COLOUR: RGB = (25, 25, 25)
"""Loop edges (a structure with loops, see g2s_plugins.loops.spanner): near-black, dotted where the format allows."""
CHOKEPOINT_COLOUR: RGB = (20, 20, 20)

REGION_COLOURS: tuple[RGB, ...] = (
    (230, 159, 0),    # orange
    (86, 180, 233),   # sky blue
    (0, 158, 115),    # bluish green
    (240, 228, 66),   # yellow
    (0, 114, 178),    # blue
    (204, 121, 167),  # reddish purple
)
"""Okabe and Ito's colour-blind-safe palette less black and vermilion (Okabe & Ito 2008, Color Universal Design)."""

VALUE_COLORMAP = "viridis"
"""The matplotlib colormap of analysis values (low -> high)."""
VALUE_SCALE_LABEL = "dark purple lowest, yellow highest"
PLOTLY_STOPS = 11
"""How many evenly spaced stops approximate the scale in plotly (the steps are invisible)."""


def depth_colour(depth: int) -> RGB:
    """Colour of an edge whose child has ``depth`` (>= 1); depth 0 gives the root colour."""
    if depth <= 0:
        return ROOT_COLOUR
    return DEPTH_COLOURS[(depth - 1) % len(DEPTH_COLOURS)]


def heat_colour(t: float) -> RGB:
    """Colour of a normalised value ``t`` in [0, 1] (clipped) on :data:`VALUE_COLORMAP`."""
    rgba = matplotlib_heat_cmap()(min(max(float(t), 0.0), 1.0))
    return tuple(int(round(c * 255)) for c in rgba[:3])  # type: ignore[return-value]


def normalise(values: Iterable[float]) -> np.ndarray:
    """Min-max normalised copy of ``values``; all 0 when they are all equal (or not finite)."""
    array = np.asarray(list(values), dtype=np.float64)
    finite = np.isfinite(array)
    if not finite.any():
        return np.zeros(len(array))
    low, high = array[finite].min(), array[finite].max()
    if high - low <= 0:
        return np.zeros(len(array))
    return np.where(finite, (array - low) / (high - low), 0.0)


def css(rgb: Sequence[int], alpha: float | None = None) -> str:
    """``rgb(r,g,b)`` or ``rgba(r,g,b,a)`` for plotly and HTML."""
    r, g, b = (int(c) for c in rgb[:3])
    return f"rgb({r},{g},{b})" if alpha is None else f"rgba({r},{g},{b},{alpha:g})"


def unit(rgb: Sequence[int], alpha: float = 1.0) -> tuple[float, float, float, float]:
    """The colour as 0..1 floats with ``alpha`` (matplotlib)."""
    return (rgb[0] / 255.0, rgb[1] / 255.0, rgb[2] / 255.0, alpha)


def plotly_heat_scale() -> list[list]:
    """The analysis scale as a plotly colorscale."""
    stops = np.linspace(0.0, 1.0, PLOTLY_STOPS)
    return [[float(t), css(heat_colour(t))] for t in stops]


def matplotlib_heat_cmap() -> Colormap:
    """The analysis scale as a matplotlib colormap."""
    from matplotlib import colormaps

    return colormaps[VALUE_COLORMAP]


def region_colours(regions: Sequence[Mapping[str, Any]]) -> dict[int, RGB]:
    """Region id -> colour: neighbouring regions (``neighbours`` of a region record) differ, all colours in use.

    Greedy colouring in smallest-last order (Matula and Beck 1983): each
    region, when its turn comes, has at most ``degeneracy`` neighbours
    coloured already, so :data:`REGION_COLOURS` suffices whenever the region
    graph's degeneracy is below 6 (every planar graph: the rooms of one
    floor). Among the colours its neighbours leave free a region takes the
    least used so far, so that rooms far apart spread over the whole palette
    rather than alternating two colours; with no colour free the palette
    repeats. O(R log R + N) for R regions and N neighbour pairs.
    """
    graph = nx.Graph()
    graph.add_nodes_from(sorted(int(r["id"]) for r in regions))
    graph.add_edges_from((int(r["id"]), int(n["region"])) for r in regions for n in r.get("neighbours", ()))
    palette = range(len(REGION_COLOURS))
    used = [0] * len(REGION_COLOURS)
    slot: dict[int, int] = {}
    for region in nx.coloring.strategy_smallest_last(graph, slot):
        taken = {slot[n] for n in graph[region] if n in slot}
        slot[region] = min((c for c in palette if c not in taken), default=min(palette, key=used.__getitem__),
                           key=lambda c: (used[c], c))
        used[slot[region]] += 1
    return {region: REGION_COLOURS[slot[region]] for region in sorted(graph)}
