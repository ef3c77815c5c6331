"""How well a map-analysis run shows where people walk: coverage, traffic off the
structure, agreement of the heat map with the reference flow.

The measures (all along the initial walkable graph, distances in metres):

``area_within``
    share of the walkable area (sum of node ``area``) whose node lies within
    r metres of the structure, for each r of ``radii``. "The structure" is
    every node of the Steiner stage's forest with its loop paths
    (``RunResult.looped``, else ``steiner``): the final
    structure's edges stand for those chains of polygons.
``traffic_off``
    share of the reference flow (:func:`reference_flow`) through nodes more
    than ``off_distance`` metres from the structure.
``rho``
    Spearman correlation, over the nodes of the initial graph that reach the
    final structure, between the heat map (each node takes the first
    analyzer's value of its nearest final-structure node) and the reference
    flow.
``rho_area_betweenness``
    the same for area-weighted betweenness on the final structure, whatever
    the run's analyzers are (an honest check when the run's heat map is the
    ``flow`` analyzer, which agrees with the reference partly by
    construction).
``rho_ceiling``
    the same when each final-structure node carries the mean percentile
    rank of the reference flow over the initial-graph nodes it stands for
    (the same nearest-node mapping): what the structure's node placement
    allows, whatever the analyzer. The mean rank fits each node's polygons
    best in squares of ranks, which is close to but not exactly the best
    order for a rank correlation, so an analyzer can beat it slightly on
    tiny graphs. The ``flow`` analyzer with ``aggregate: percentile``
    computes these values (from its own source sample on big graphs): its
    rho is this figure by construction.
``structure_share``
    final structure nodes / initial graph nodes.

Cost: two multi-source Dijkstra searches plus the reference flow (see
:func:`g2s_plugins.traffic.od_flow`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy.stats import spearmanr

from g2s_core.model import RunResult
from g2s_plugins import centrality, traffic

RADII = (3.0, 6.0, 10.0)
"""Coverage radii reported by default, metres."""

REFERENCE_SOURCES = 512
"""Graphs with more nodes than this get a sampled reference flow with this many sources."""


@dataclass(frozen=True)
class Quality:
    """The measures of one run (see the module docs); shares are in [0, 1]."""

    area_within: dict[float, float]
    traffic_off: float
    rho: float
    rho_area_betweenness: float
    rho_ceiling: float
    structure_share: float
    polygons: int
    structure_nodes: int
    stage_seconds: dict[str, float] = field(default_factory=dict)

    def measures(self) -> dict[str, float]:
        """The measures by name, as the ``traffic`` evaluator reports them (``area_within_6m``,
        ``traffic_off``, ``rho``, ``rho_area_betweenness``, ``rho_ceiling``, ``structure_share``); NaN ones left out."""
        named = {**{f"area_within_{r:g}m": v for r, v in self.area_within.items()}, "traffic_off": self.traffic_off,
                 "rho": self.rho, "rho_area_betweenness": self.rho_area_betweenness, "rho_ceiling": self.rho_ceiling,
                 "structure_share": self.structure_share}
        return {name.replace(".", "_"): value for name, value in named.items() if math.isfinite(value)}


def reference_flow(result: RunResult, max_sources: int = REFERENCE_SOURCES, seed: int = 0) -> np.ndarray:
    """(n,) area-weighted OD flow through each initial-graph node, in graph node order."""
    return traffic.walking_flow(result.graph, max_sources=max_sources, seed=seed)


def nearest_structure_rows(result: RunResult) -> np.ndarray:
    """(n,) the row of each initial-graph node's nearest final-structure node along the graph (-1: none)."""
    arrays = traffic.surface_arrays(result.graph)
    return traffic.distance_to(arrays, arrays.rows(sorted(result.structure)))[1]


def heat_map(result: RunResult, values: dict, nearest: np.ndarray | None = None) -> np.ndarray:
    """(n,) each initial-graph node's value of its nearest final-structure node (NaN where none).

    ``nearest``: :func:`nearest_structure_rows` of ``result``, when already known.
    """
    arrays = traffic.surface_arrays(result.graph)
    structure = sorted(result.structure)
    if nearest is None:
        nearest = nearest_structure_rows(result)
    by_row = np.full(arrays.n, np.nan)
    by_row[arrays.rows(structure)] = [values[node] for node in structure]
    return np.where(nearest >= 0, by_row[np.maximum(nearest, 0)], np.nan)


def _spearman(heat: np.ndarray, reference: np.ndarray) -> float:
    ok = np.isfinite(heat)
    if ok.sum() < 3 or np.ptp(heat[ok]) == 0 or np.ptp(reference[ok]) == 0:
        return float("nan")
    return float(spearmanr(heat[ok], reference[ok]).statistic)


def evaluate(
    result: RunResult,
    reference: np.ndarray | None = None,
    radii: tuple[float, ...] = RADII,
    off_distance: float = 5.0,
) -> Quality:
    """The measures of a run that got to the analysis (see the module docs).

    Args:
        reference: :func:`reference_flow` of the same graph, when already known
            (it depends only on the graph, not on the preset).
    """
    arrays = traffic.surface_arrays(result.graph)
    if reference is None:
        reference = reference_flow(result)
    area = traffic.origin_weight(arrays)
    if result.structure is None:  # no terminals: nothing was joined
        return Quality({r: 0.0 for r in radii}, 1.0, float("nan"), float("nan"), float("nan"), 0.0, arrays.n, 0,
                       {s.stage: s.seconds for s in result.stages})
    joined = result.looped if result.looped is not None else result.steiner
    distance, _ = traffic.distance_to(arrays, arrays.rows(sorted(joined)))
    within = {r: float(area[distance <= r].sum() / area.sum()) for r in radii}
    total_flow = reference.sum()
    off = float(reference[distance > off_distance].sum() / total_flow) if total_flow > 0 else 0.0
    nearest = nearest_structure_rows(result)
    first = next(iter(result.analysis.values()), None)
    rho = _spearman(heat_map(result, first, nearest), reference) if first is not None else float("nan")
    undirected = result.structure.to_undirected(as_view=True)
    weights = traffic.represented_area(result.graph, undirected)
    betweenness = centrality.betweenness(undirected, weighted=True, node_weight=weights)
    return Quality(
        area_within=within,
        traffic_off=off,
        rho=rho,
        rho_area_betweenness=_spearman(heat_map(result, betweenness, nearest), reference),
        rho_ceiling=_spearman(
            heat_map(result, traffic.gather(result.graph, result.structure, traffic.percentile(reference), mean=True),
                     nearest), reference
        ),
        structure_share=result.structure.number_of_nodes() / arrays.n,
        polygons=arrays.n,
        structure_nodes=result.structure.number_of_nodes(),
        stage_seconds={s.stage: s.seconds for s in result.stages},
    )
