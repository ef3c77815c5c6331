"""Coverage and flow agreement: the map-analysis evaluation of g2s_plugins.evaluation.

Measures (shares in [0, 1], rho in [-1, 1]; see :mod:`g2s_plugins.evaluation`):
``area_within_<r>m`` for each radius r, ``traffic_off`` (reference flow more
than ``off_distance`` from the structure), ``rho`` (the first analyzer's heat
map against the reference flow; left out without analyzers or when
undefined), ``rho_area`` (the same, each node weighted by its area),
``rho_area_betweenness``, ``rho_ceiling``, ``structure_share``,
and ``rho_navmesh``, ``rho_navmesh_ceiling`` and ``navmesh_area_left_out``
(the heat map against the reference flow on the level's navmesh graph; the
run's own graph on the navmesh route). A run whose graph builder names
``play_points`` is measured over its play space only (its graph is cut
there, :mod:`g2s_plugins.play_space`).
Cost: the reference flow (exact up to
:data:`g2s_plugins.traffic.EXACT_NODES` nodes, one Dijkstra search of the
initial graph per node; above, ``reference_sources`` searches) and two
multi-source searches; off the navmesh route also a navmesh build of the
level and its reference flow.
"""

from __future__ import annotations

from pydantic import Field, model_validator
from pydantic_core import PydanticCustomError

from g2s_core.model import RunContext, RunResult
from g2s_core.plugin import PluginParams, hookimpl
from g2s_plugins import evaluation

NAME = "traffic"


class Params(PluginParams):
    """Radii and the reference flow's sample."""

    radii: list[float] = Field(list(evaluation.RADII), min_length=1, strict=False,
                               description="coverage radii, metres, each > 0 (each gives area_within_<r>m)")
    off_distance: float = Field(5.0, gt=0, description="traffic_off counts the flow farther than this from the structure, metres")
    reference_sources: int = Field(evaluation.REFERENCE_SOURCES, ge=1,
                                   description="graphs with more nodes than this and than traffic.EXACT_NODES (2,000) "
                                               "sample this many area-weighted sources, linearly scaled")
    seed: int = Field(0, description="seed of the source sample")

    @model_validator(mode="after")
    def _positive_radii(self) -> Params:
        if any(r <= 0 for r in self.radii):
            raise PydanticCustomError("radii", "radii: expected numbers > 0 (metres)", {})
        return self


@hookimpl
def g2s_evaluate(result: RunResult, params: Params, context: RunContext) -> dict[str, float]:
    """The measures of a run that got to simplification (the analyzers' first key is the heat map)."""
    radii = tuple(sorted(set(params.radii)))
    return evaluation.evaluate(result, None, radii, params.off_distance, params.reference_sources,
                               params.seed).measures()
