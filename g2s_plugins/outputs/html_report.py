"""``report.html``: one self-contained page that works offline.

The page holds plotly.js once (embedded, no network), an interactive 3D view,
the per-stage table in the paper's form, the config used (YAML) and the
warnings. The 3D view's legend entries are layers that a click shows or
hides (a layer may be several plotly traces sharing a legend group):

=================================  ==========================================  =======
layer (legend entry)               traces                                       shown
=================================  ==========================================  =======
Level mesh                         the input mesh, light grey, translucent      yes
Navigation mesh                    detail triangles, green (with a navmesh)     no
Step 1: initial graph              edges, nodes                                 no
Step 2: terminals                  terminals (+ openings when there are some)   no
Step 3: Steiner tree               edges, nodes                                 no
Step 4: rooted trees               edges by depth [3]_, nodes, roots            no
Step 5: simplified structure       edges by depth [3]_, nodes, roots            [1]_
Analysis: <key>                    edges, nodes by value (one layer per key)    [2]_
=================================  ==========================================  =======

.. [1] shown when the run has no analysis values.
.. [2] the first key is shown.
.. [3] one trace per depth colour in use (at most ``len(DEPTH_COLOURS)``).

Depth colours: red = depth 1, yellow = 2, then green, cyan, blue, magenta ...;
roots are red. Analysis values: green (lowest) -> yellow -> red (highest).
Layers of stages that did not run are left out. Y is up.
"""

from __future__ import annotations

import html
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import networkx as nx
import numpy as np
import plotly.graph_objects as go
import yaml

from g2s_core.model import RunResult
from g2s_plugins.outputs import colours
from g2s_plugins.outputs.common import edge_list, final_graph, is_loop_edge, number, roots_of, stage_rows, terminal_ids
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
LAYER_ANALYSIS = "Analysis: {key}"


def write(result: RunResult, outdir: Path) -> list[Path]:
    return [atomic_write(outdir / REPORT_FILE, render(result).encode("utf-8"))]


def render(result: RunResult) -> str:
    """The whole page as a string."""
    figure = build_figure(result)
    plot = figure.to_html(
        full_html=False,
        include_plotlyjs=True,
        include_mathjax=False,
        div_id=PLOT_ID,
        default_width="100%",
        default_height="78vh",
        config={"displaylogo": False, "responsive": True, "scrollZoom": True},
    )
    stage, graph = final_graph(result)
    summary = [
        ("mesh", result.mesh_name),
        ("mesh SHA-256", result.mesh_sha256),
        ("final stage", stage or "none"),
    ]
    if graph is not None:
        summary.append(("final structure", f"{graph.number_of_nodes()} nodes, {graph.number_of_edges()} edges"))
        roots = roots_of(graph)
        if roots:
            summary.append(("trees", f"{len(roots)} (roots {', '.join(map(str, roots[:12]))}{' ...' if len(roots) > 12 else ''})"))
    if result.terminals is not None:
        summary.append(("terminals", str(len(result.terminals.nodes))))
    if result.analysis:
        summary.append(("analysis values", ", ".join(result.analysis)))
    config_yaml = yaml.safe_dump(result.config, sort_keys=False, default_flow_style=False, allow_unicode=True)
    warnings = "".join(f"<li>{html.escape(w)}</li>" for w in result.warnings) or "<li class=\"none\">none</li>"
    title = html.escape(f"g2s report: {result.mesh_name}")
    return f"""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{title}</title>
<style>
body {{ font-family: system-ui, sans-serif; margin: 1.2em 2em; color: #222; }}
h1 {{ font-size: 1.5em; margin-bottom: 0.2em; }}
h2 {{ font-size: 1.15em; margin-top: 1.6em; border-bottom: 1px solid #ddd; }}
table {{ border-collapse: collapse; }}
th, td {{ padding: 0.2em 0.8em; border-bottom: 1px solid #eee; }}
td.n {{ text-align: right; font-variant-numeric: tabular-nums; }}
tr.total td {{ font-weight: bold; border-top: 1px solid #999; }}
dl {{ display: grid; grid-template-columns: max-content auto; gap: 0.15em 1em; }}
dt {{ color: #666; }} dd {{ margin: 0; word-break: break-all; }}
pre {{ background: #f6f6f6; padding: 0.8em; overflow: auto; }}
li.none {{ color: #666; list-style: none; }}
.hint {{ color: #666; font-size: 0.9em; }}
#view {{ border: 1px solid #ddd; }}
</style>
</head>
<body>
<h1>{title}</h1>
<dl id="summary">{''.join(f'<dt>{html.escape(k)}</dt><dd>{html.escape(v)}</dd>' for k, v in summary)}</dl>
<h2>3D view</h2>
<p class="hint">Click a legend entry to show or hide that layer, double-click to show it alone.
Drag to rotate, scroll to zoom. Tree edges: red = depth 1, yellow = depth 2, then green, cyan, blue, magenta;
roots are red. Analysis: green (lowest), yellow, red (highest). Y is up; lengths in metres.</p>
<div id="view">{plot}</div>
<h2>Per-stage table</h2>
{_stage_table(result)}
<h2>Warnings</h2>
<ul id="warnings">{warnings}</ul>
<h2>Config</h2>
<pre id="config">{html.escape(config_yaml)}</pre>
</body>
</html>
"""


def _stage_table(result: RunResult) -> str:
    head = "".join(f"<th>{html.escape(c)}</th>" for c in ("step", "", "t (ms)", "#N", "#E"))
    rows = []
    for step, label, ms, nodes, edges in stage_rows(result.stages):
        css = ' class="total"' if step == "total" else ""
        cells = f"<td>{html.escape(step)}</td><td>{html.escape(label)}</td>" + "".join(
            f'<td class="n">{html.escape(v)}</td>' for v in (ms, nodes, edges))
        rows.append(f"<tr{css}>{cells}</tr>")
    return (f'<table id="stages"><thead><tr>{head}</tr></thead><tbody>{"".join(rows)}</tbody></table>\n'
            '<p class="hint">#N is the number of terminals for step 2, of nodes otherwise (as in the paper\'s tables).</p>')


# --- the 3D figure -----------------------------------------------------------------


def build_figure(result: RunResult) -> go.Figure:
    """The 3D view (see the module doc for its layers)."""
    traces: list[Any] = []
    mesh = result.context.mesh
    if mesh is not None and len(mesh.faces):
        traces.append(_mesh_trace(np.asarray(mesh.vertices), np.asarray(mesh.faces), LAYER_MESH,
                                  colours.css(colours.MESH_COLOUR), 0.25, True))
    navmesh = result.context.navmesh
    if navmesh is not None and len(navmesh.detail_triangles):
        traces.append(_mesh_trace(np.asarray(navmesh.detail_vertices), np.asarray(navmesh.detail_triangles),
                                  LAYER_NAVMESH, colours.css(colours.NAVMESH_COLOUR), 0.45, False))
    terminals = terminal_ids(result)
    keys = list(result.analysis)
    if result.graph is not None:
        traces += _plain_layer(result.graph, LAYER_GRAPH, colours.GRAPH_COLOUR, 1.5, 2, False, result)
    if result.terminals is not None:
        traces += _terminal_layer(result, terminals)
    if result.steiner is not None:
        traces += _plain_layer(result.steiner, LAYER_STEINER, colours.STEINER_COLOUR, 3, 3, False, result)
    if result.forest is not None:
        traces += _tree_layer(result.forest, LAYER_FOREST, False, result)
    if result.structure is not None:
        traces += _tree_layer(result.structure, LAYER_STRUCTURE, not keys, result)
    _, graph = final_graph(result)
    for index, key in enumerate(keys):
        if graph is not None:
            traces += _analysis_layer(graph, key, result, visible=index == 0)
    figure = go.Figure(data=traces)
    figure.update_layout(
        margin=dict(l=0, r=0, t=30, b=0),
        legend=dict(groupclick="togglegroup", itemsizing="constant", x=0.0, y=1.0, bgcolor="rgba(255,255,255,0.7)"),
        scene=dict(
            aspectmode="data",
            xaxis_title="X (m)",
            yaxis_title="Y (m, up)",
            zaxis_title="Z (m)",
            camera=dict(up=dict(x=0, y=1, z=0), eye=dict(x=1.1, y=1.5, z=1.1)),
        ),
        uirevision="g2s",
    )
    return figure


def _mesh_trace(vertices: np.ndarray, faces: np.ndarray, name: str, colour: str, opacity: float, visible: bool) -> go.Mesh3d:
    v = np.round(np.asarray(vertices, dtype=np.float64), 5)
    f = np.asarray(faces, dtype=np.int64)
    return go.Mesh3d(
        x=v[:, 0], y=v[:, 1], z=v[:, 2], i=f[:, 0], j=f[:, 1], k=f[:, 2],
        name=name, legendgroup=name, showlegend=True, color=colour, opacity=opacity,
        flatshading=True, hoverinfo="skip", visible=True if visible else "legendonly",
        lighting=dict(ambient=0.7, diffuse=0.5, specular=0.05),
    )


def _segments(graph: nx.Graph, edges: Sequence[tuple[int, int]]) -> tuple[list, list, list]:
    xs: list[float | None] = []
    ys: list[float | None] = []
    zs: list[float | None] = []
    for u, v in edges:
        pu, pv = graph.nodes[u]["pos"], graph.nodes[v]["pos"]
        xs += [number(pu[0]), number(pv[0]), None]
        ys += [number(pu[1]), number(pv[1]), None]
        zs += [number(pu[2]), number(pv[2]), None]
    return xs, ys, zs


def _hover(graph: nx.Graph, node: int, result: RunResult, terminals: set[int]) -> str:
    attrs = graph.nodes[node]
    lines = [f"node {node}"]
    if attrs.get("depth") is not None:
        lines.append(f"depth {attrs['depth']}, root {attrs.get('root')}")
    if node in terminals:
        lines.append("terminal")
    for key, values in result.analysis.items():
        if node in values:
            lines.append(f"{key} {values[node]:.6g}")
    pos = attrs["pos"]
    lines.append(f"({pos[0]:.2f}, {pos[1]:.2f}, {pos[2]:.2f})")
    return "<br>".join(lines)


def _node_trace(graph: nx.Graph, nodes: Sequence[int], name: str, result: RunResult, size: float,
                colour: Any, visible: bool, showlegend: bool = False, symbol: str = "circle") -> go.Scatter3d:
    terminals = set(terminal_ids(result))
    p = np.asarray([graph.nodes[n]["pos"] for n in nodes], dtype=np.float64).reshape(-1, 3)
    return go.Scatter3d(
        x=p[:, 0].tolist(), y=p[:, 1].tolist(), z=p[:, 2].tolist(), mode="markers",
        name=name, legendgroup=name, showlegend=showlegend,
        marker=dict(size=size, color=colour, symbol=symbol, line=dict(width=0)),
        text=[_hover(graph, n, result, terminals) for n in nodes], hoverinfo="text",
        visible=True if visible else "legendonly",
    )


def _plain_layer(graph: nx.Graph, name: str, rgb: colours.RGB, width: float, size: float, visible: bool,
                 result: RunResult) -> list[Any]:
    xs, ys, zs = _segments(graph, edge_list(graph))
    edges = go.Scatter3d(x=xs, y=ys, z=zs, mode="lines", name=name, legendgroup=name, showlegend=True,
                         line=dict(color=colours.css(rgb), width=width), hoverinfo="skip",
                         visible=True if visible else "legendonly")
    nodes = _node_trace(graph, sorted(graph.nodes), name, result, size, colours.css(rgb), visible)
    return [edges, nodes]


def _terminal_layer(result: RunResult, terminals: list[int]) -> list[Any]:
    graph = result.graph
    present = [t for t in terminals if graph is not None and t in graph]
    traces: list[Any] = []
    if graph is not None:
        traces.append(_node_trace(graph, present, LAYER_TERMINALS, result, 5, colours.css(colours.TERMINAL_COLOUR),
                                  False, showlegend=True, symbol="diamond"))
    openings = result.terminals.openings if result.terminals is not None else ()
    if openings:
        xs: list[float | None] = []
        ys: list[float | None] = []
        zs: list[float | None] = []
        for o in openings:
            xs += [o.p0[0], o.p1[0], None]
            ys += [o.p0[1], o.p1[1], None]
            zs += [o.p0[2], o.p1[2], None]
        traces.append(go.Scatter3d(x=xs, y=ys, z=zs, mode="lines", name=LAYER_TERMINALS, legendgroup=LAYER_TERMINALS,
                                   showlegend=not traces, line=dict(color=colours.css(colours.TERMINAL_COLOUR), width=6),
                                   hoverinfo="skip", visible="legendonly"))
    return traces


def _tree_layer(tree: nx.DiGraph, name: str, visible: bool, result: RunResult) -> list[Any]:
    """Edges by depth (one trace per depth colour in use, red = depth 1 first), nodes, roots."""
    edges = edge_list(tree)
    loops = [(u, v) for u, v in edges if is_loop_edge(tree, u, v)]
    by_colour: dict[int, list[tuple[int, int]]] = {}
    for parent, child in edges:
        if is_loop_edge(tree, parent, child):
            continue
        depth = int(tree.nodes[child].get("depth", 1))
        by_colour.setdefault((max(depth, 1) - 1) % len(colours.DEPTH_COLOURS), []).append((parent, child))
    traces: list[Any] = []
    for index in sorted(by_colour):
        xs, ys, zs = _segments(tree, by_colour[index])
        traces.append(go.Scatter3d(
            x=xs, y=ys, z=zs, mode="lines", name=name, legendgroup=name, showlegend=not traces,
            line=dict(width=5, color=colours.css(colours.DEPTH_COLOURS[index])),
            hoverinfo="skip", visible=True if visible else "legendonly",
        ))
    if loops:
        traces.append(_loop_trace(tree, loops, name, visible))
    nodes = sorted(tree.nodes)
    node_colours = [colours.css(colours.depth_colour(int(tree.nodes[n].get("depth", 0)))) for n in nodes]
    traces.append(_node_trace(tree, nodes, name, result, 3, node_colours, visible, showlegend=not traces))
    roots = roots_of(tree)
    traces.append(_node_trace(tree, roots, name, result, 9, colours.css(colours.ROOT_COLOUR), visible))
    return traces


def _loop_trace(graph: nx.Graph, loops: list[tuple[int, int]], name: str, visible: bool) -> Any:
    """The loop edges of a structure with loops: near-black, dotted, in the layer's legend group."""
    xs, ys, zs = _segments(graph, loops)
    return go.Scatter3d(x=xs, y=ys, z=zs, mode="lines", name=name, legendgroup=name, showlegend=False,
                        line=dict(width=5, color=colours.css(colours.LOOP_COLOUR), dash="dot"),
                        hoverinfo="skip", visible=True if visible else "legendonly")


def _analysis_layer(graph: nx.Graph, key: str, result: RunResult, visible: bool) -> list[Any]:
    name = LAYER_ANALYSIS.format(key=key)
    xs, ys, zs = _segments(graph, edge_list(graph))
    edges = go.Scatter3d(x=xs, y=ys, z=zs, mode="lines", name=name, legendgroup=name, showlegend=True,
                         line=dict(color="rgb(120,120,120)", width=3), hoverinfo="skip",
                         visible=True if visible else "legendonly")
    values = result.analysis[key]
    nodes = sorted(n for n in graph.nodes if n in values)
    raw = [values[n] for n in nodes]
    finite = [v for v in raw if np.isfinite(v)]
    low, high = (min(finite), max(finite)) if finite else (0.0, 1.0)
    if high <= low:
        high = low + 1.0
    marker_values = [v if np.isfinite(v) else low for v in raw]
    node_trace = _node_trace(graph, nodes, name, result, 6, marker_values, visible)
    node_trace.marker.update(colorscale=colours.plotly_heat_scale(), cmin=low, cmax=high, showscale=True,
                             colorbar=dict(title=dict(text=key), x=1.0, len=0.6))
    loops = [(u, v) for u, v in edge_list(graph) if graph.is_directed() and is_loop_edge(graph, u, v)]
    return [edges, *([_loop_trace(graph, loops, name, visible)] if loops else []), node_trace]
