"""``heatmap.png``: the final structure seen from above, nodes coloured by the first analysis value.

View: from above (+Y towards the viewer), X to the right and Z downwards,
i.e. -Z up the page, which keeps the view right-handed; the axes are
labelled in metres. The walkable ground (navmesh triangles, else the mesh's
faces no steeper than the agent's max slope) is light grey underneath.
Edges are grey lines, nodes are dots on viridis (dark purple lowest, yellow
highest), roots are ringed in black, terminals are vermilion squares and
openings vermilion bars. Without analysis values nodes and edges take their
tree-depth colour (an edge its child's: red = depth 1, yellow = 2 ...) and,
before step 4, one grey. Loop edges (a structure with loops, config
``loops:``) are near-black dotted lines. A legend under the panels names the
markers drawn.

Floors (:func:`common.floors`): storeys are height bands holding a real share
of the walkable ground's area (1 % of it in a 0.1 m bin, sloped ground
counted over its height span), at least the agent height apart. Node
heights (Y) are sorted and split wherever two neighbours differ by more than
the agent height, and each such floor is split between the storey bands
within an agent height of it, each node going to the nearest band (the nodes
on stairs and ramps to the storeys they join). Each floor gets its own panel (lowest first),
with the edges that touch it (edges to another floor dashed, as the legend
says), and the terminals and openings whose height is nearest its nodes'. The
colour scale is shared by all panels.

With the ``regions`` analyzer the walkable ground is coloured by region
(:func:`colours.region_colours`: neighbouring regions differ) instead of grey;
with ``chokepoints`` each chokepoint is a near-black bar across its portal and
a white diamond labelled with its id and walkable width. Regions go to floors
as the ground does, chokepoints as the terminals do; the legend names both.

The file is deterministic: matplotlib's Agg canvas (pyplot is not used), fixed size and DPI, no
date or software tag in the PNG metadata. No label, tick label, title, colour bar or legend falls past the
canvas's edges (:func:`_settle_limits`, :func:`_legend_below`).
"""

from __future__ import annotations

import io
import math
from pathlib import Path

import networkx as nx
import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.collections import LineCollection, PolyCollection
from matplotlib.cm import ScalarMappable
from matplotlib.colorbar import Colorbar
from matplotlib.colors import Normalize
from matplotlib.figure import Figure
from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.lines import Line2D
from matplotlib.patches import Patch
from matplotlib.ticker import MaxNLocator

from g2s_core.model import RunResult
from g2s_plugins.outputs import colours
from g2s_plugins.outputs.common import (
    agent_value,
    edge_list,
    feature_records,
    final_graph,
    floors,
    is_loop_edge,
    roots_of,
    terminal_ids,
    triangle_regions,
    value_title,
    whole_numbers,
)
from g2s_plugins.outputs.files import atomic_write

HEATMAP_FILE = "heatmap.png"
GROUND_COLOUR = "#e4e4e4"
REGION_ALPHA = 0.55
PANEL_INCHES = 6.0
DPI = 110


def write(result: RunResult, outdir: Path) -> list[Path]:
    """``heatmap.png`` in ``outdir`` (:func:`render`)."""
    return [atomic_write(outdir / HEATMAP_FILE, render(result))]


def floor_groups(graph: nx.Graph, gap: float, ground: np.ndarray | None = None) -> list[list[int]]:
    """The graph's nodes grouped by floor (see the module doc), lowest floor first; ``ground``: the (T, 3, 3)
    walkable triangles (:func:`_walkable`) whose area tells the storeys apart."""
    nodes = sorted(graph.nodes)
    heights = [float(graph.nodes[n]["pos"][1]) for n in nodes]
    return [[nodes[i] for i in group] for group in floors(heights, gap, ground)]


def render(result: RunResult) -> bytes:
    """The PNG's bytes (:func:`figure_of`)."""
    buffer = io.BytesIO()
    figure_of(result).savefig(buffer, format="png", dpi=DPI, metadata={"Software": None})
    return buffer.getvalue()


def figure_of(result: RunResult) -> Figure:
    """The heatmap's figure on an Agg canvas (see the module doc), not yet drawn."""
    _, graph = final_graph(result)
    keys = list(result.analysis)
    key = keys[0] if keys else None
    walkable = _walkable(result)
    groups = floor_groups(graph, agent_value(result, "height", 2.0), walkable) if graph is not None else []
    count = max(len(groups), 1)
    columns = min(count, 3)
    rows = math.ceil(count / columns)
    figure = Figure(figsize=(PANEL_INCHES * columns + (1.2 if key else 0.0), PANEL_INCHES * rows), dpi=DPI,
                    layout="constrained")
    FigureCanvasAgg(figure)  # Agg only, whatever pyplot's backend is
    axes = figure.subplots(rows, columns, squeeze=False)
    title = f"{result.mesh_name}: " + (f"{key}" if key else "tree depth" if graph is not None and graph.is_directed() else "structure")
    figure.suptitle(title)
    mappable = None
    if graph is None:
        axes[0][0].text(0.5, 0.5, "no graph: the run produced nothing to draw", ha="center", va="center")
    else:
        values = result.analysis[key] if key else {}
        finite = [v for v in values.values() if np.isfinite(v)]
        low, high = (min(finite), max(finite)) if finite else (0.0, 1.0)
        norm = Normalize(vmin=low, vmax=high if high > low else low + 1.0)
        floor_of = {n: i for i, group in enumerate(groups) for n in group}
        roots = set(roots_of(graph))
        ground = _ground(result, graph, groups, walkable)
        terminals, openings = _terminals_by_floor(result, graph, groups)
        regions = _regions_by_floor(result, graph, groups)
        chokepoints = _chokepoints_by_floor(result, graph, groups)
        for index, group in enumerate(groups):
            ax = axes[index // columns][index % columns]
            if len(ground[index]):
                ax.add_collection(PolyCollection(ground[index], facecolors=GROUND_COLOUR, edgecolors=GROUND_COLOUR,
                                             linewidths=0.4, zorder=0))
            _draw_regions(ax, *regions[index])
            mappable = _panel(ax, graph, group, floor_of, index, values, norm, roots) or mappable
            _mark_terminals(ax, terminals[index], openings[index])
            _mark_chokepoints(ax, chokepoints[index])
            heights = [graph.nodes[n]["pos"][1] for n in group]
            if len(groups) > 1:
                low, high = f"{min(heights):.1f}", f"{max(heights):.1f}"
                ax.set_title(f"floor {index + 1} of {len(groups)}: Y {low} m" if low == high else
                             f"floor {index + 1} of {len(groups)}: Y {low} to {high} m")
    for index in range(len(groups), rows * columns):
        if index > 0:
            axes[index // columns][index % columns].set_visible(False)
    for ax_row in axes:
        for ax in ax_row:
            ax.set_xlabel("X (m) →")
            ax.set_ylabel("Z (m), pointing down the page (seen from above)")
            ax.set_aspect("equal", adjustable="datalim")
            if not ax.yaxis_inverted():
                ax.invert_yaxis()
            ax.grid(True, color="#e6e6e6", linewidth=0.6)
            ax.set_axisbelow(True)
    if mappable is not None:
        label = f"{value_title(result, key)} ({colours.VALUE_SCALE_LABEL})"
        colour_bar(figure, mappable, axes.ravel().tolist(), label, finite)
    handles = _legend_handles(result, graph, groups)
    if handles:
        _legend_below(figure, handles)
    _settle_limits(figure, axes.ravel().tolist())
    return figure


def _legend_below(figure: Figure, handles: list[Artist]) -> None:
    """The legend under the panels: its entries in one row, or in the fewest rows that fit the canvas's width
    (one panel cannot hold five entries side by side). At most len(handles) trial layouts of the legend alone."""
    renderer = figure.canvas.get_renderer()
    for columns in range(len(handles), 0, -1):
        legend = figure.legend(handles=handles, loc="outside lower center", ncols=columns, fontsize="small",
                               frameon=False)
        if columns == 1 or legend.get_window_extent(renderer).width <= figure.bbox.width:
            return
        legend.remove()


def _settle_limits(figure: Figure, panels: list[Axes]) -> None:
    """Lay the figure out for the tick labels that will be drawn, then fix the layout and keep each panel's equal
    aspect by shrinking its box inwards.

    With ``adjustable="datalim"`` the limits follow the box's shape, while the constrained layout measures the tick
    labels at one box and then moves it: the new limits can bring a wider tick label into view (a minus sign is
    ~10 px at this size) after the margins were set, pushing the y label past the canvas's edge (the layout does
    not model ``datalim``; matplotlib's maintainers advise against the pair in its issue 30230).
    ``adjustable="box"`` under the layout fails the other way: the layout counts a narrowed box's inset as room
    for the labels. So: one layout pass gives each panel's equal-aspect limits; with those limits fixed (and the
    aspect free) a second pass measures exactly the labels that are drawn; then the layout stops and each box
    shrinks about its centre to equal aspect, moving its labels only inwards, by the few pixels the second pass
    changed it. Two layout passes, O(panels) text measurements each.
    """
    engine = figure.get_layout_engine()
    engine.execute(figure)
    for ax in panels:
        ax.apply_aspect()  # the limits for the box the first pass gave it
        ax.set_xlim(ax.get_xlim())
        ax.set_ylim(ax.get_ylim())
        ax.set_aspect("auto")
    engine.execute(figure)
    figure.set_layout_engine("none")
    for ax in panels:
        ax.set_aspect("equal", adjustable="box", anchor="C")


def colour_bar(figure: Figure, mappable: ScalarMappable, axes: list, label: str, finite: list[float]) -> Colorbar:
    """The value scale beside the panels; whole-number values (depth, degree) get whole-number ticks only."""
    bar = figure.colorbar(mappable, ax=axes, shrink=0.8)
    if whole_numbers(finite):
        bar.ax.yaxis.set_major_locator(MaxNLocator(integer=True))
    bar.set_label(label)
    return bar


def _ground(result: RunResult, graph: nx.Graph, groups: list[list[int]], triangles: np.ndarray) -> list[np.ndarray]:
    """Per floor, the (T, 3, 3) walkable ``triangles`` (:func:`_walkable`) under it as (T, 3, 2) X/Z outlines.

    A triangle goes to the floor whose node heights (widened by the agent
    height) hold its centre height, the nearest such floor if several do,
    none if none does.
    """
    return [triangles[chosen][:, :, [0, 2]] for chosen in _ground_floors(result, graph, groups, triangles)]


def _walkable(result: RunResult) -> np.ndarray:
    """(T, 3, 3) walkable triangles (m): the navmesh's detail triangles when there is a navmesh, else the
    mesh's faces no steeper than the agent's max slope."""
    navmesh = result.context.navmesh
    if navmesh is not None and len(navmesh.detail_triangles):
        triangles = np.asarray(navmesh.detail_vertices, dtype=np.float64)[np.asarray(navmesh.detail_triangles)]
    elif result.context.mesh is not None and len(result.context.mesh.faces):
        mesh = result.context.mesh
        slope = math.radians(agent_value(result, "max_slope", 45.0))
        up = np.asarray(mesh.face_normals)[:, 1] >= math.cos(slope)
        triangles = np.asarray(mesh.triangles)[up]
    else:
        triangles = np.zeros((0, 3, 3))
    return triangles


def _ground_floors(result: RunResult, graph: nx.Graph, groups: list[list[int]], triangles: np.ndarray) -> list[np.ndarray]:
    """Per floor, which of the (T, 3, 3) ``triangles`` lie under it (see :func:`_ground`), as (T,) bool masks."""
    heights = triangles[:, :, 1].mean(axis=1)
    distance = _floor_distances(graph, groups, heights)
    reach = agent_value(result, "height", 2.0)
    return [(distance[:, index] <= reach) & (distance[:, index] == distance.min(axis=1)) for index in range(len(groups))]


def _floor_distances(graph: nx.Graph, groups: list[list[int]], heights: np.ndarray) -> np.ndarray:
    """(H, F) vertical distance (m) from each of ``heights`` to each floor's span of node heights (0 inside it)."""
    spans = np.asarray([(min(graph.nodes[n]["pos"][1] for n in g), max(graph.nodes[n]["pos"][1] for n in g))
                        for g in groups]).reshape(-1, 2)
    return np.maximum(np.maximum(spans[None, :, 0] - heights[:, None], heights[:, None] - spans[None, :, 1]), 0.0)


def _nearest_floor(graph: nx.Graph, groups: list[list[int]], heights: np.ndarray) -> np.ndarray:
    """(H,) index of the floor whose node heights are nearest each of ``heights``."""
    distance = _floor_distances(graph, groups, heights)
    return distance.argmin(axis=1) if len(groups) else np.zeros(len(heights), dtype=int)


def _panel(ax, graph: nx.Graph, group: list[int], floor_of: dict[int, int], index: int,
           values: dict[int, float], norm, roots: set[int]):
    members = set(group)
    by_depth = not values and graph.is_directed()
    solid: list = []
    dashed: list = []
    solid_colours: list = []
    dashed_colours: list = []
    loops: list = []
    for u, v in edge_list(graph):
        if u not in members and v not in members:
            continue
        segment = [(graph.nodes[u]["pos"][0], graph.nodes[u]["pos"][2]), (graph.nodes[v]["pos"][0], graph.nodes[v]["pos"][2])]
        if graph.is_directed() and is_loop_edge(graph, u, v):
            loops.append(segment)
            continue
        colour = colours.unit(colours.depth_colour(int(graph.nodes[v].get("depth", 1)))) if by_depth else (0.47, 0.47, 0.47, 1.0)
        if floor_of[u] == floor_of[v]:
            solid.append(segment)
            solid_colours.append(colour)
        else:
            dashed.append(segment)
            dashed_colours.append(colour)
    if solid:
        ax.add_collection(LineCollection(solid, colors=solid_colours, linewidths=2.0 if by_depth else 1.2, zorder=1))
    if dashed:
        ax.add_collection(LineCollection(dashed, colors=dashed_colours, linewidths=1.0, linestyles="dashed", zorder=1))
    if loops:
        ax.add_collection(LineCollection(loops, colors=[colours.unit(colours.LOOP_COLOUR)], linewidths=1.6,
                                         linestyles="dotted", zorder=1))
    p = np.asarray([graph.nodes[n]["pos"] for n in group], dtype=np.float64).reshape(-1, 3)
    mappable = None
    if values:
        data = np.asarray([values.get(n, np.nan) for n in group], dtype=np.float64)
        order = np.argsort(np.nan_to_num(data, nan=-np.inf), kind="stable")  # hot nodes drawn on top
        mappable = ax.scatter(p[order, 0], p[order, 2], c=data[order], cmap=colours.matplotlib_heat_cmap(), norm=norm,
                              s=28, edgecolors="none", zorder=2, plotnonfinite=True)
    elif graph.is_directed():
        node_colours = [colours.unit(colours.depth_colour(int(graph.nodes[n].get("depth", 0)))) for n in group]
        ax.scatter(p[:, 0], p[:, 2], c=node_colours, s=22, edgecolors="none", zorder=2)
    else:
        ax.scatter(p[:, 0], p[:, 2], color=colours.unit(colours.GRAPH_COLOUR), s=14, edgecolors="none", zorder=2)
    root_nodes = [n for n in group if n in roots]
    if root_nodes:
        r = np.asarray([graph.nodes[n]["pos"] for n in root_nodes], dtype=np.float64)
        ax.scatter(r[:, 0], r[:, 2], **ROOT_STYLE)
    ax.autoscale_view()
    return mappable


ROOT_STYLE = dict(s=90, facecolors="none", edgecolors=colours.unit(colours.ROOT_COLOUR), linewidths=1.5, zorder=3)
TERMINAL_STYLE = dict(s=60, marker="s", facecolors="none", edgecolors=colours.unit(colours.TERMINAL_COLOUR),
                      linewidths=1.4, zorder=4)
OPENING_STYLE = dict(colors=[colours.unit(colours.TERMINAL_COLOUR)], linewidths=4.0, zorder=4)


def _terminals_by_floor(result: RunResult, graph: nx.Graph, groups: list[list[int]]
                        ) -> tuple[list[np.ndarray], list[np.ndarray]]:
    """Per floor, the terminals' (T, 3) positions and the openings' (O, 2, 3) segments nearest its height span."""
    source = result.graph if result.graph is not None else graph
    points = np.asarray([source.nodes[t]["pos"] for t in terminal_ids(result) if t in source],
                        dtype=np.float64).reshape(-1, 3)
    openings = result.terminals.openings if result.terminals is not None else ()
    segments = np.asarray([(o.p0, o.p1) for o in openings], dtype=np.float64).reshape(-1, 2, 3)
    point_floor = _nearest_floor(graph, groups, points[:, 1])
    segment_floor = _nearest_floor(graph, groups, segments[:, :, 1].mean(axis=1))
    return ([points[point_floor == i] for i in range(len(groups))],
            [segments[segment_floor == i] for i in range(len(groups))])


def _mark_terminals(ax, points: np.ndarray, segments: np.ndarray) -> None:
    if len(segments):
        ax.add_collection(LineCollection(segments[:, :, [0, 2]], **OPENING_STYLE))
    if len(points):
        ax.scatter(points[:, 0], points[:, 2], **TERMINAL_STYLE)


def _regions_by_floor(result: RunResult, graph: nx.Graph, groups: list[list[int]]
                      ) -> list[tuple[np.ndarray, list[colours.RGB]]]:
    """Per floor, the (T, 3, 2) X/Z outlines of the navmesh triangles in a region and their region colours
    (none without the ``regions`` analyzer)."""
    regions = triangle_regions(result)
    if regions is None:
        return [(np.zeros((0, 3, 2)), []) for _ in groups]
    navmesh = result.context.navmesh
    inside = regions >= 0
    triangles = np.asarray(navmesh.detail_vertices, dtype=np.float64)[np.asarray(navmesh.detail_triangles)[inside]]
    palette = colours.region_colours(feature_records(result, "regions"))
    colour = [palette[r] for r in regions[inside].tolist()]
    return [(triangles[chosen][:, :, [0, 2]], [c for c, keep in zip(colour, chosen.tolist()) if keep])
            for chosen in _ground_floors(result, graph, groups, triangles)]


def _draw_regions(ax, outlines: np.ndarray, region_colours: list[colours.RGB]) -> None:
    if len(outlines):
        face = [colours.unit(c, REGION_ALPHA) for c in region_colours]
        ax.add_collection(PolyCollection(outlines, facecolors=face, edgecolors=face, linewidths=0.3, zorder=0.5))


def _chokepoints_by_floor(result: RunResult, graph: nx.Graph, groups: list[list[int]]) -> list[list[dict]]:
    """Per floor, the chokepoint records whose height is nearest its nodes' (none without the analyzer)."""
    records = feature_records(result, "chokepoints")
    floor = _nearest_floor(graph, groups, np.asarray([r["position"][1] for r in records], dtype=np.float64))
    return [[r for r, f in zip(records, floor.tolist()) if f == index] for index in range(len(groups))]


CHOKEPOINT_BAR = dict(color=colours.unit(colours.CHOKEPOINT_COLOUR), linewidth=2.5, zorder=4, solid_capstyle="butt")
CHOKEPOINT_MARKER = dict(marker="D", s=40, facecolors="white", edgecolors=colours.unit(colours.CHOKEPOINT_COLOUR),
                         linewidths=1.0, zorder=5)


def _mark_chokepoints(ax, records: list[dict]) -> None:
    """A bar across each chokepoint's portal and a diamond labelled ``id: width m`` (walkable width)."""
    for record in records:
        (x0, _, z0), (x1, _, z1) = record["portal"]
        x, _, z = record["position"]
        ax.plot([x0, x1], [z0, z1], **CHOKEPOINT_BAR)
        ax.scatter([x], [z], **CHOKEPOINT_MARKER)
        ax.annotate(f"{record['id']}: {record['width']:.1f} m", (x, z), xytext=(4, 4), textcoords="offset points",
                    fontsize=7, zorder=5)


def _legend_handles(result: RunResult, graph: nx.Graph | None, groups: list[list[int]]) -> list[Artist]:
    """Legend entries for what the panels show: roots, terminals, openings, regions, chokepoints,
    loop edges, edges to another floor."""
    if graph is None:
        return []
    floor_of = {n: i for i, group in enumerate(groups) for n in group}
    handles = []
    if roots_of(graph):
        handles.append(Line2D([], [], linestyle="none", marker="o", markersize=9, markerfacecolor="none",
                              markeredgecolor=colours.unit(colours.ROOT_COLOUR), label="root"))
    if terminal_ids(result):
        handles.append(Line2D([], [], linestyle="none", marker="s", markersize=7, markerfacecolor="none",
                              markeredgecolor=colours.unit(colours.TERMINAL_COLOUR), label="terminal"))
    if result.terminals is not None and result.terminals.openings:
        handles.append(Line2D([], [], color=colours.unit(colours.TERMINAL_COLOUR), linewidth=4.0, label="opening"))
    if feature_records(result, "regions"):
        handles.append(Patch(facecolor=colours.unit(colours.REGION_COLOURS[0], REGION_ALPHA), edgecolor="none",
                             label="regions (neighbours differ in colour)"))
    if feature_records(result, "chokepoints"):
        handles.append(Line2D([], [], color=CHOKEPOINT_BAR["color"], linewidth=CHOKEPOINT_BAR["linewidth"],
                              marker="D", markersize=6, markerfacecolor="white",
                              markeredgecolor=CHOKEPOINT_MARKER["edgecolors"], label="chokepoint (id: walkable width)"))
    if graph.is_directed() and any(is_loop_edge(graph, u, v) for u, v in graph.edges):
        handles.append(Line2D([], [], color=colours.unit(colours.LOOP_COLOUR), linewidth=1.6, linestyle="dotted",
                              label="loop edge"))
    if any(floor_of[u] != floor_of[v] for u, v in graph.edges):
        handles.append(Line2D([], [], color="0.47", linestyle="dashed",
                              label="edge to another floor (stairs, ramp or drop)"))
    return handles
