"""Nodes of the final structure as CSV: id, x, y, z, depth (a third-party output writer)."""

from pathlib import Path

from g2s_core.plugin import hookimpl
from g2s_core.summary import final_graph

NAME = "csv"
FILES = ("nodes.csv",)


@hookimpl
def g2s_write_output(result, folder: Path):
    _, graph = final_graph(result)
    lines = ["id,x,y,z,depth"]
    for node, data in sorted(graph.nodes(data=True)):
        x, y, z = data["pos"]
        lines.append(f"{node},{x:.6g},{y:.6g},{z:.6g},{data.get('depth', '')}")
    path = folder / "nodes.csv"
    path.write_text("\n".join(lines) + "\n")
    return [path]
