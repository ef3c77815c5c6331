"""Regions: the rooms of a level, i.e. the walkable surface split at its chokepoints.

See :mod:`g2s_plugins.decomposition` for the method. Needs the navmesh graph
builder. Value per structure node: the id of the region it stands in (-1 for
nodes that are not navmesh polygons). Features: ``regions``, one record per
region by id (``id``, ``area``, ``polygons``, ``centroid``, ``floor``,
``height_range``, ``neighbours`` with the ids of the chokepoints between
them, as the ``chokepoints`` analyzer with the same parameters numbers them).
Cost: that of :func:`g2s_plugins.decomposition.decompose` (one split per run
for this analyzer and ``chokepoints`` given the same split settings:
:func:`~g2s_plugins.decomposition.shared_decomposition`) plus the
structure's edge betweenness (its chokepoint numbering).
"""

from __future__ import annotations

from g2s_core.lazy import lazy_module
from g2s_core.model import AnalyzerResult, RunContext
from g2s_core.plugin import hookimpl
from g2s_plugins import decomposition

nx = lazy_module("networkx")

NAME = "regions"


class Params(decomposition.DecompositionParams):
    """Region split settings (give ``chokepoints`` the same so that ids agree)."""


@hookimpl
def g2s_analyze(structure: nx.Graph, params: Params, context: RunContext) -> AnalyzerResult:
    """Region records and the region id of every structure node."""
    navmesh = decomposition.require_navmesh(context, NAME)
    split = decomposition.shared_decomposition(navmesh, context.agent, params, context.mesh, context.graph)
    decomposition.score(split, structure)  # numbers the chokepoints the regions' neighbours refer to
    return AnalyzerResult(decomposition.region_values(split, structure), {"regions": split.regions})
