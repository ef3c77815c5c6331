"""An analyzer with a bug: it raises KeyError, to check that the error names the plugin and its package."""

from g2s_core.plugin import hookimpl

NAME = "explodes"


@hookimpl
def g2s_analyze(structure):
    return {node: structure.nodes[node]["height"] for node in structure}
