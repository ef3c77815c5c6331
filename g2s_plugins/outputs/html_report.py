"""``report.html``: one self-contained page that works offline.

The page opens on the interactive 3D view (it fits a 1400 x 1000 window
without scrolling), then the summary, the per-stage table in the paper's form,
the warnings and the config used (YAML, with the formats actually written).
plotly.js is embedded once, gzip-compressed (the browser unpacks it with its
built-in ``DecompressionStream``), and the geometry travels as typed arrays
of 32-bit floats, so a level of a few hundred polygons gives a page of about
2 MB. A level far from the origin is drawn in its local frame
(:mod:`g2s_plugins.local_frame`, the frame of the GLB's meshes): the arrays
hold positions less the local origin, which keep the level's detail in
single precision (1,000 km out, world coordinates would round to 6 cm), an
axis whose origin moved says so in its title (``X − 1,000,000 (m)``), and
every hover shows world positions, to the centimetre; near the origin
nothing is translated. The 3D view's legend entries are layers that a click shows or hides
(a layer may be several plotly traces sharing a legend group):

=================================  ==========================================  =======
layer (legend entry)               traces                                       shown
=================================  ==========================================  =======
Level mesh                         the input mesh, light grey, translucent      yes
Navigation mesh                    detail triangles, green (with a navmesh)     no
Step 1: initial graph              edges, nodes                                 no
Step 2: terminals                  terminals (+ openings when there are some)   yes
Step 3: Steiner tree               edges, nodes                                 no
Step 4: rooted trees               edges by depth [3]_, nodes                   no
Step 5: simplified structure       edges by depth [3]_, nodes                   [1]_
Roots                              a black diamond on each root                 yes
Loop edges                         the final structure's loop edges, near-      yes
                                   black, dotted [4]_
Analysis: <key>                    edges and nodes by value (one per key)       [2]_
Regions                            navmesh triangles coloured by region, a      yes
                                   cross on each region's centroid
Chokepoints                        a bar across each portal, an x sized by      yes
                                   score
=================================  ==========================================  =======

.. [1] shown when the run has no analysis values.
.. [2] the first key is shown, with its colour bar.
.. [3] one trace per depth colour in use (at most ``len(DEPTH_COLOURS)``);
   loop edges drawn dotted near-black in the same layer.
.. [4] with loops kept (config ``loops:``, see :mod:`g2s_plugins.loops.spanner`); the
   analysis layers leave loop edges to this layer.

The Regions and Chokepoints layers appear when the ``regions`` and
``chokepoints`` analyzers ran; neighbouring regions differ in colour
(:func:`colours.region_colours`), chokepoints are near-black. Hovering a
region's cross or a chokepoint's x shows its position in metres as a node's
hover does, then its record: a region's area, floor and neighbours, a
chokepoint's walkable width, score, traffic and the regions it joins.

Depth colours: red = depth 1, yellow = 2, then green, cyan, blue, magenta ...;
analysis values on viridis (dark purple lowest, yellow highest); terminals and
openings vermilion. The initial camera looks down on the level's bounding box
from a fixed direction, far enough that the whole box is in view. Layers of
stages that did not run are left out. Y is up.
"""

from __future__ import annotations

import base64
import gzip
import html
import json
import math
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import networkx as nx
import numpy as np
import plotly.graph_objects as go
import yaml
from plotly.offline import get_plotlyjs

from g2s_core.model import RunResult
from g2s_plugins.local_frame import LocalFrame
from g2s_plugins.outputs import colours
from g2s_plugins.outputs.common import (
    edge_list,
    feature_records,
    final_graph,
    is_loop_edge,
    metric_lines,
    roots_of,
    stage_rows,
    terminal_ids,
    triangle_regions,
    value_title,
    whole_numbers,
)
from g2s_plugins.outputs.files import atomic_write

REPORT_FILE = "report.html"
PLOT_ID = "g2s-plot"

LAYER_MESH = "Level mesh"
LAYER_NAVMESH = "Navigation mesh"
LAYER_GRAPH = "Step 1: initial graph"
LAYER_TERMINALS = "Step 2: terminals"
LAYER_STEINER = "Step 3: Steiner tree"
LAYER_FOREST = "Step 4: rooted trees"
LAYER_STRUCTURE = "Step 5: simplified structure"
LAYER_ROOTS = "Roots"
LAYER_ANALYSIS = "Analysis: {key}"
LAYER_REGIONS = "Regions"
LAYER_CHOKEPOINTS = "Chokepoints"
LAYER_LOOPS = "Loop edges"
LOOP_LINE = dict(width=5, color=colours.css(colours.LOOP_COLOUR), dash="dot")
"""How loop edges are drawn, in the tree layers and in their own layer."""

CAMERA_DIRECTION = (1.0, 1.4, 1.2)
"""Where the initial camera looks from (plotly scene units, Y up): above the level, from one corner."""
CAMERA_FOV_DEGREES = 45.0
"""plotly's perspective field of view (vertical)."""
PLOT_CONFIG = {"displaylogo": False, "responsive": True, "scrollZoom": True}


def write(result: RunResult, outdir: Path) -> list[Path]:
    """``report.html`` in ``outdir`` (:func:`render`)."""
    return [atomic_write(outdir / REPORT_FILE, render(result).encode("utf-8"))]


def render(result: RunResult) -> str:
    """The whole page as a string."""
    title = html.escape(f"g2s report: {result.mesh_name}")
    warnings = "".join(f"<li>{html.escape(w)}</li>" for w in result.warnings) or "<li class=\"none\">none</li>"
    return f"""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{title}</title>
<style>
body {{ font-family: system-ui, sans-serif; margin: 0.6em 1.5em; color: #222; }}
h1 {{ font-size: 1.2em; margin: 0 0 0.2em 0; }}
h2 {{ font-size: 1.15em; margin-top: 1.6em; border-bottom: 1px solid #ddd; }}
table {{ border-collapse: collapse; }}
th, td {{ padding: 0.2em 0.8em; border-bottom: 1px solid #eee; }}
td.n {{ text-align: right; font-variant-numeric: tabular-nums; }}
tr.total td {{ font-weight: bold; border-top: 1px solid #999; }}
dl {{ display: grid; grid-template-columns: max-content auto; gap: 0.15em 1em; }}
dt {{ color: #666; }} dd {{ margin: 0; word-break: break-all; }}
pre {{ background: #f6f6f6; padding: 0.8em; overflow: auto; }}
li.none {{ color: #666; list-style: none; }}
.hint {{ color: #666; font-size: 0.85em; margin: 0.2em 0; }}
#view {{ border: 1px solid #ddd; }}
#{PLOT_ID} {{ width: 100%; height: calc(100vh - 7em); min-height: 420px; }}
</style>
</head>
<body>
<h1>{title}</h1>
<p class="hint">{html.escape(_legend_hint(result))}</p>
<div id="view"><div id="{PLOT_ID}"></div></div>
<h2>Summary</h2>
<dl id="summary">{''.join(f'<dt>{html.escape(k)}</dt><dd>{html.escape(v)}</dd>' for k, v in _summary(result))}</dl>
<h2>Per-stage table</h2>
{_stage_table(result)}
<h2>Warnings</h2>
<ul id="warnings">{warnings}</ul>
<h2>Config</h2>
{_config_section(result)}
{_plot_scripts(build_figure(result))}
</body>
</html>
"""


def _legend_hint(result: RunResult) -> str:
    keys = list(result.analysis)
    values = (f"Analysis: {value_title(result, keys[0])} on viridis ({colours.VALUE_SCALE_LABEL}). " if keys else "")
    return ("Click a legend entry to show or hide that layer, double-click to show it alone; drag to rotate, "
            f"scroll to zoom. {values}Tree edges by depth: red = 1, yellow = 2, then green, cyan, blue, magenta. "
            "Roots: black diamonds; terminals and openings: vermilion. Y is up; lengths in metres.")


def _summary(result: RunResult) -> list[tuple[str, str]]:
    stage, graph = final_graph(result)
    summary = [("mesh", result.mesh_name), ("mesh SHA-256", result.mesh_sha256), ("final stage", stage or "none")]
    if graph is not None:
        summary.append(("final structure", f"{graph.number_of_nodes()} nodes, {graph.number_of_edges()} edges"))
        roots = roots_of(graph)
        if roots:
            summary.append(("trees", f"{len(roots)} (roots {', '.join(map(str, roots[:12]))}{' ...' if len(roots) > 12 else ''})"))
    if result.terminals is not None:
        # a cover's waypoints are joined as terminals are (step 2's #N counts both), so the count says so
        waypoints = len(set(result.terminals.waypoints))
        summary.append(("terminals", str(len(terminal_ids(result)))
                        + (f" (and {waypoints} waypoints the structure also joins)" if waypoints else "")))
    if result.analysis:
        summary.append(("analysis values", ", ".join(result.analysis)))
    return summary + metric_lines(result)


def _config_section(result: RunResult) -> str:
    """The config as YAML, its ``outputs.formats`` being the formats this run wrote."""
    config = dict(result.config)
    note = ""
    if result.formats:
        outputs = dict(config.get("outputs") or {})
        if list(outputs.get("formats") or ()) != list(result.formats):
            note = (f'<p class="hint">outputs.formats shows the formats written ({", ".join(result.formats)}), '
                    f'chosen on the command line instead of the config\'s {outputs.get("formats")}.</p>')
        config["outputs"] = {**outputs, "formats": list(result.formats)}
    text = yaml.safe_dump(config, sort_keys=False, default_flow_style=False, allow_unicode=True)
    return f'{note}<pre id="config">{html.escape(text)}</pre>'


def _plot_scripts(figure: go.Figure) -> str:
    """plotly.js (gzip, base64) and the figure (JSON); a small script unpacks one and draws the other."""
    library = base64.b64encode(gzip.compress(get_plotlyjs().encode("utf-8"), 9, mtime=0)).decode("ascii")
    data = figure.to_json().replace("</", "<\\/")
    config = json.dumps(PLOT_CONFIG)
    return f"""<script id="g2s-plotly" type="application/gzip;base64">{library}</script>
<script id="g2s-figure" type="application/json">{data}</script>
<script>
(async () => {{
  const plot = document.getElementById("{PLOT_ID}");
  if (typeof DecompressionStream === "undefined") {{
    plot.textContent = "This browser cannot unpack the embedded plotly.js (DecompressionStream is missing); " +
      "open the report in a current Firefox, Chrome, Edge or Safari.";
    return;
  }}
  const packed = Uint8Array.from(atob(document.getElementById("g2s-plotly").textContent), c => c.charCodeAt(0));
  const stream = new Blob([packed]).stream().pipeThrough(new DecompressionStream("gzip"));
  const library = document.createElement("script");
  library.textContent = await new Response(stream).text();
  document.head.appendChild(library);
  const figure = JSON.parse(document.getElementById("g2s-figure").textContent);
  await Plotly.newPlot(plot, figure.data, figure.layout, {config});
}})();
</script>"""


def _stage_table(result: RunResult) -> str:
    head = "".join(f"<th>{html.escape(c)}</th>" for c in ("step", "", "t (ms)", "#N", "#E"))
    rows = []
    for step, label, ms, nodes, edges in stage_rows(result.stages):
        css = ' class="total"' if step == "total" else ""
        cells = f"<td>{html.escape(step)}</td><td>{html.escape(label)}</td>" + "".join(
            f'<td class="n">{html.escape(v)}</td>' for v in (ms, nodes, edges))
        rows.append(f"<tr{css}>{cells}</tr>")
    return (f'<table id="stages"><thead><tr>{head}</tr></thead><tbody>{"".join(rows)}</tbody></table>\n'
            '<p class="hint">#N is, for step 2, the number of nodes the Steiner tree joins (the terminals and any '
            'waypoints), of nodes otherwise (as in the paper\'s tables).</p>')


# --- the 3D figure -----------------------------------------------------------------


def build_figure(result: RunResult) -> go.Figure:
    """The 3D view (see the module doc for its layers)."""
    keys = list(result.analysis)
    _, final = final_graph(result)
    traces: list[Any] = []
    mesh = result.context.mesh
    if mesh is not None and len(mesh.faces):
        traces.append(_mesh_trace(np.asarray(mesh.vertices), np.asarray(mesh.faces), LAYER_MESH,
                                  colours.css(colours.MESH_COLOUR), 0.25, True))
    navmesh = result.context.navmesh
    if navmesh is not None and len(navmesh.detail_triangles):
        traces.append(_mesh_trace(np.asarray(navmesh.detail_vertices), np.asarray(navmesh.detail_triangles),
                                  LAYER_NAVMESH, colours.css(colours.NAVMESH_COLOUR), 0.45, False))
    if result.graph is not None:
        traces += _plain_layer(result.graph, LAYER_GRAPH, colours.GRAPH_COLOUR, 1.5, 2, result)
    if result.terminals is not None:
        traces += _terminal_layer(result, terminal_ids(result))
    if result.steiner is not None:
        traces += _plain_layer(result.steiner, LAYER_STEINER, colours.STEINER_COLOUR, 3, 3, result)
    if result.forest is not None:
        traces += _tree_layer(result.forest, LAYER_FOREST, False, result)
    if result.structure is not None:
        traces += _tree_layer(result.structure, LAYER_STRUCTURE, not keys, result)
    if final is not None and roots_of(final):
        traces.append(_node_trace(final, roots_of(final), LAYER_ROOTS, result, 9, colours.css(colours.ROOT_COLOUR),
                                  True, showlegend=True, symbol="diamond"))
    for index, key in enumerate(keys):
        if final is not None:
            traces += _analysis_layer(final, key, result, visible=index == 0)
    if final is not None and final.is_directed():
        traces += _loop_layer(final)
    traces += _region_layer(result) + _chokepoint_layer(result)
    bounds = _level_bounds(result)
    frame = LocalFrame(bounds)
    figure = go.Figure(data=[_in_view(trace, frame) for trace in traces])
    figure.update_layout(
        template="plotly_white",
        margin=dict(l=0, r=0, t=0, b=0),
        legend=dict(groupclick="togglegroup", itemsizing="constant", x=0.0, y=1.0, bgcolor="rgba(255,255,255,0.7)"),
        scene=_scene(frame.to_local(bounds), frame.origin),
        uirevision="g2s",
    )
    return figure


def _level_bounds(result: RunResult) -> np.ndarray:
    """(2, 3) corners of what the view must hold: the mesh, else the graph's nodes."""
    mesh = result.context.mesh
    if mesh is not None and len(mesh.faces):
        return np.asarray(mesh.bounds, dtype=np.float64)
    _, graph = final_graph(result)
    points = np.asarray([p for _, p in graph.nodes(data="pos")] if graph is not None else [], dtype=np.float64)
    return np.stack([points.min(axis=0), points.max(axis=0)]) if len(points) else np.asarray([[-1.0] * 3, [1.0] * 3])


def _in_view(trace: go.Mesh3d | go.Scatter3d, frame: LocalFrame) -> dict[str, Any]:
    """``trace`` (its x, y, z world coordinates, float64, m) as the view draws it: in ``frame``, float32 arrays.

    The one place where positions lose precision: after the subtraction of the local origin, so a level far out
    keeps its detail (near the origin nothing is subtracted, and the arrays are the world's, rounded). Returned as
    a new trace's spec: plotly keeps a trace's old array when given one whose values compare equal, whatever its
    dtype.
    """
    spec = trace.to_plotly_json()
    points = np.stack([np.asarray(spec[axis], dtype=np.float64) for axis in "xyz"], axis=1)
    local = frame.to_local(points).astype(np.float32)
    return {**spec, "x": local[:, 0], "y": local[:, 1], "z": local[:, 2]}


def _axis_title(name: str, origin: float, unit: str) -> str:
    """An axis title; where the view's frame moved along the axis, what its values are: ``X − 1,000,000 (m)``."""
    if origin == 0:
        return f"{name} ({unit})"
    return f"{name} {'−' if origin > 0 else '+'} {abs(origin):,.0f} ({unit})"


def _scene(bounds: np.ndarray, origin: np.ndarray) -> dict[str, Any]:
    """Axes fixed to ``bounds`` (metres, in the view's frame; its (3,) ``origin`` in the world is named in the
    titles of the axes it moved), true proportions, and a camera that sees the whole box.

    plotly draws the box with half-sides ``aspectratio / 2`` around the origin
    and looks at it from ``eye``: the eye stands on :data:`CAMERA_DIRECTION` at
    the distance where the box's bounding sphere fills the vertical field of view.
    """
    extent = np.maximum(bounds[1] - bounds[0], 1e-6)
    aspect = extent / extent.max()
    radius = 0.5 * float(np.linalg.norm(aspect))
    distance = radius / math.sin(math.radians(CAMERA_FOV_DEGREES / 2))
    direction = np.asarray(CAMERA_DIRECTION) / np.linalg.norm(CAMERA_DIRECTION)
    eye = distance * direction
    axes = {f"{axis}axis": dict(range=[float(bounds[0][i]), float(bounds[1][i])],
                                title=_axis_title(axis.upper(), float(origin[i]), unit), autorange=False)
            for i, (axis, unit) in enumerate(zip("xyz", ("m", "m, up", "m")))}
    return dict(
        **axes,
        aspectmode="manual",
        aspectratio=dict(zip("xyz", map(float, aspect))),
        camera=dict(up=dict(x=0, y=1, z=0), center=dict(x=0, y=0, z=0), eye=dict(zip("xyz", map(float, eye)))),
    )


def _visible(shown: bool) -> bool | str:
    return True if shown else "legendonly"


def _mesh_trace(vertices: np.ndarray, faces: np.ndarray, name: str, colour: str | list[str], opacity: float,
                visible: bool) -> go.Mesh3d:
    """Triangles ``faces`` of ``vertices`` (world, m) in one ``colour``, or one colour per face."""
    v = np.asarray(vertices, dtype=np.float64)
    f = np.asarray(faces, dtype=np.int32)
    paint = dict(color=colour) if isinstance(colour, str) else dict(facecolor=colour)
    return go.Mesh3d(
        x=v[:, 0], y=v[:, 1], z=v[:, 2], i=f[:, 0], j=f[:, 1], k=f[:, 2],
        name=name, legendgroup=name, showlegend=True, opacity=opacity, **paint,
        flatshading=True, hoverinfo="skip", visible=_visible(visible),
        lighting=dict(ambient=0.7, diffuse=0.5, specular=0.05),
    )


def _segments(points: Sequence[tuple[Any, Any]]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """x, y, z float64 arrays (world, m) of line segments ``(p, q)``, a NaN after each so plotly leaves a gap."""
    array = np.full((len(points), 3, 3), np.nan, dtype=np.float64)
    for index, (p, q) in enumerate(points):
        array[index, 0], array[index, 1] = p, q
    flat = array.reshape(-1, 3)
    return flat[:, 0], flat[:, 1], flat[:, 2]


def _edge_segments(graph: nx.Graph, edges: Sequence[tuple[int, int]]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    return _segments([(graph.nodes[u]["pos"], graph.nodes[v]["pos"]) for u, v in edges])


def _lines(graph: nx.Graph, edges: Sequence[tuple[int, int]], name: str, visible: bool, showlegend: bool,
           line: dict[str, Any]) -> go.Scatter3d:
    xs, ys, zs = _edge_segments(graph, edges)
    return go.Scatter3d(x=xs, y=ys, z=zs, mode="lines", name=name, legendgroup=name, showlegend=showlegend,
                        line=line, hoverinfo="skip", visible=_visible(visible))


def hover_text(graph: nx.Graph, node: int, result: RunResult, terminals: set[int]) -> str:
    """What hovering ``node`` shows: id and role, position (m), depth and tree, each analysis value once."""
    attrs = graph.nodes[node]
    roles = [role for role, present in (("root", attrs.get("depth") == 0), ("terminal", node in terminals)) if present]
    lines = []
    if attrs.get("depth") is not None:
        lines.append(f"depth {attrs['depth']} in the tree of root {attrs.get('root')}")
    lines += [f"{key}: {values[node]:.4g}" for key, values in result.analysis.items() if node in values]
    return _hover(f"node {node}", roles, attrs["pos"], lines)


def _hover(title: str, roles: Sequence[str], pos: Sequence[float], lines: Sequence[str]) -> str:
    """A marker's hover text: title and roles, position (m), then ``lines``."""
    head = title + (f" ({', '.join(roles)})" if roles else "")
    return "<br>".join([head, f"x {pos[0]:.2f} m, y {pos[1]:.2f} m, z {pos[2]:.2f} m", *lines])


def _node_trace(graph: nx.Graph, nodes: Sequence[int], name: str, result: RunResult, size: float,
                colour: Any, visible: bool, showlegend: bool = False, symbol: str = "circle") -> go.Scatter3d:
    terminals = set(terminal_ids(result))
    p = np.asarray([graph.nodes[n]["pos"] for n in nodes], dtype=np.float64).reshape(-1, 3)
    return go.Scatter3d(
        x=p[:, 0], y=p[:, 1], z=p[:, 2], mode="markers",
        name=name, legendgroup=name, showlegend=showlegend,
        marker=dict(size=size, color=colour, symbol=symbol, line=dict(width=0)),
        text=[hover_text(graph, n, result, terminals) for n in nodes], hoverinfo="text",
        visible=_visible(visible),
    )


def _plain_layer(graph: nx.Graph, name: str, rgb: colours.RGB, width: float, size: float,
                 result: RunResult) -> list[Any]:
    edges = _lines(graph, edge_list(graph), name, False, True, dict(color=colours.css(rgb), width=width))
    return [edges, _node_trace(graph, sorted(graph.nodes), name, result, size, colours.css(rgb), False)]


def _terminal_layer(result: RunResult, terminals: list[int]) -> list[Any]:
    """The terminals (vermilion squares) and the openings' segments."""
    graph = result.graph
    colour = colours.css(colours.TERMINAL_COLOUR)
    traces: list[Any] = []
    if graph is not None:
        present = [t for t in terminals if t in graph]
        traces.append(_node_trace(graph, present, LAYER_TERMINALS, result, 7, colour, True, showlegend=True,
                                  symbol="square-open"))
    openings = result.terminals.openings if result.terminals is not None else ()
    if openings:
        xs, ys, zs = _segments([(o.p0, o.p1) for o in openings])
        texts: list[str | None] = []
        for index, o in enumerate(openings):
            text = _opening_text(index, o)
            texts += [text, text, None]
        traces.append(go.Scatter3d(x=xs, y=ys, z=zs, mode="lines", name=LAYER_TERMINALS, legendgroup=LAYER_TERMINALS,
                                   showlegend=not traces, line=dict(color=colour, width=8),
                                   text=texts, hovertemplate="%{text}<extra></extra>", visible=True))
    return traces


def _opening_text(index: int, opening: Any) -> str:
    """Hover text of an opening: its number, width, score and the reason it was kept."""
    score = "not scored" if opening.score is None else f"score {opening.score:.2f}"
    lines = [f"opening {index}: {opening.width:.2f} m wide, {score}"]
    if opening.reason:
        lines.append(html.escape(opening.reason))
    return "<br>".join(lines)


def _tree_layer(tree: nx.DiGraph, name: str, visible: bool, result: RunResult) -> list[Any]:
    """Edges by depth (one trace per depth colour in use, red = depth 1 first), then the nodes."""
    by_colour: dict[int, list[tuple[int, int]]] = {}
    loops = _loop_edges(tree)
    for parent, child in edge_list(tree):
        if is_loop_edge(tree, parent, child):
            continue
        depth = int(tree.nodes[child].get("depth", 1))
        by_colour.setdefault((max(depth, 1) - 1) % len(colours.DEPTH_COLOURS), []).append((parent, child))
    traces: list[Any] = [
        _lines(tree, by_colour[index], name, visible, index == min(by_colour),
               dict(width=5, color=colours.css(colours.DEPTH_COLOURS[index])))
        for index in sorted(by_colour)
    ]
    if loops:
        traces.append(_lines(tree, loops, name, visible, False, LOOP_LINE))
    nodes = sorted(tree.nodes)
    node_colours = [colours.css(colours.depth_colour(int(tree.nodes[n].get("depth", 0)))) for n in nodes]
    traces.append(_node_trace(tree, nodes, name, result, 3, node_colours, visible, showlegend=not traces))
    return traces


def _value_range(values: Sequence[float]) -> tuple[float, float]:
    finite = [v for v in values if np.isfinite(v)]
    low, high = (min(finite), max(finite)) if finite else (0.0, 1.0)
    return low, high if high > low else low + 1.0


def _analysis_layer(graph: nx.Graph, key: str, result: RunResult, visible: bool) -> list[Any]:
    """The structure's edges (each in its child's value colour) and nodes on the value scale, with a colour bar."""
    name = LAYER_ANALYSIS.format(key=key)
    values = result.analysis[key]
    low, high = _value_range(list(values.values()))
    edges = [(u, v) for u, v in edge_list(graph) if not (graph.is_directed() and is_loop_edge(graph, u, v))]
    # two points and a gap per segment, all in the child's colour
    edge_values = np.repeat(np.asarray([values.get(v, low) for _, v in edges], dtype=np.float32), 3)
    scale = dict(colorscale=colours.plotly_heat_scale(), cmin=low, cmax=high)
    lines = _lines(graph, edges, name, visible, True, dict(color=np.nan_to_num(edge_values, nan=low), width=6, **scale))
    nodes = sorted(n for n in graph.nodes if n in values)
    marker_values = np.asarray([values[n] if np.isfinite(values[n]) else low for n in nodes], dtype=np.float32)
    node_trace = _node_trace(graph, nodes, name, result, 5, marker_values, visible)
    colour_bar = dict(title=dict(text=value_title(result, key)), x=1.0, len=0.6)
    if whole_numbers([v for v in values.values() if np.isfinite(v)]):
        colour_bar.update(tickmode="linear", tick0=0, dtick=max(1, math.ceil((high - low) / 10)))
    node_trace.marker.update(showscale=True, colorbar=colour_bar, **scale)
    return [lines, node_trace]


def _loop_layer(graph: nx.DiGraph) -> list[Any]:
    """The loop edges of a structure with loops, near-black and dotted, with a legend entry of their own."""
    loops = _loop_edges(graph)
    return [_lines(graph, loops, LAYER_LOOPS, True, True, LOOP_LINE)] if loops else []


def _loop_edges(graph: nx.DiGraph) -> list[tuple[int, int]]:
    return [(u, v) for u, v in edge_list(graph) if is_loop_edge(graph, u, v)]


def _record_markers(positions: Sequence[Sequence[float]], name: str, texts: list[str],
                    marker: dict[str, Any]) -> go.Scatter3d:
    """Markers at the (R, 3) ``positions`` (m) with hover ``texts``, in layer ``name`` (no legend entry of their own)."""
    p = np.asarray(positions, dtype=np.float64).reshape(-1, 3)
    return go.Scatter3d(x=p[:, 0], y=p[:, 1], z=p[:, 2], mode="markers", name=name, legendgroup=name,
                        showlegend=False, marker=marker, text=texts, hoverinfo="text")


def _region_layer(result: RunResult) -> list[Any]:
    """The navmesh's detail triangles coloured by region, and a cross on each region's centroid."""
    regions = triangle_regions(result)
    if regions is None:
        return []
    navmesh = result.context.navmesh
    records = feature_records(result, "regions")
    palette = {r: colours.css(c) for r, c in colours.region_colours(records).items()}
    inside = regions >= 0
    surface = _mesh_trace(np.asarray(navmesh.detail_vertices), np.asarray(navmesh.detail_triangles)[inside],
                          LAYER_REGIONS, [palette[r] for r in regions[inside].tolist()], 0.8, True)
    texts = [_hover(f"region {r['id']}", [f"floor {r['floor']}"], r["centroid"],
                    [f"area {r['area']:.1f} m², {len(r['polygons'])} polygons",
                     "neighbours: " + (", ".join(f"{n['region']} (chokepoints {', '.join(map(str, n['chokepoints']))})"
                                                 for n in r["neighbours"]) or "none")])
             for r in records]
    centres = _record_markers([r["centroid"] for r in records], LAYER_REGIONS, texts,
                              dict(size=5, color=[palette[r["id"]] for r in records], symbol="cross"))
    return [surface, centres]


def _chokepoint_layer(result: RunResult) -> list[Any]:
    """Each chokepoint's portal as a thick near-black bar and an x sized by score, its record on hover."""
    records = feature_records(result, "chokepoints")
    if not records:
        return []
    colour = colours.css(colours.CHOKEPOINT_COLOUR)
    xs, ys, zs = _segments([tuple(r["portal"]) for r in records])
    bars = go.Scatter3d(x=xs, y=ys, z=zs, mode="lines", name=LAYER_CHOKEPOINTS, legendgroup=LAYER_CHOKEPOINTS,
                        showlegend=True, line=dict(color=colour, width=8), hoverinfo="skip")
    top = max(max(r["score"] for r in records), 1e-12)
    texts = [_hover(f"chokepoint {r['id']}", ["closing it disconnects the level"] if r["articulation"] else [],
                    r["position"], [f"walkable width {r['width']:.2f} m",
                                    f"score {r['score']:.3g} (traffic {r['traffic']:.3g} / width)",
                                    f"joins regions {r['regions'][0]} and {r['regions'][1]}"])
             for r in records]
    markers = _record_markers([r["position"] for r in records], LAYER_CHOKEPOINTS, texts,
                              dict(size=[6 + 10 * r["score"] / top for r in records], color=colour, symbol="x"))
    return [bars, markers]
