"""Recast build parameters and the voxel settings derived from them.

:class:`RecastParams` declares every build parameter (the ``navmesh`` graph
builder's ``graph.params``). :func:`resolve_settings` turns them and the
agent into the world-unit keyword arguments of the extension's ``build``,
and refuses, naming the key at fault, any value Recast cannot use.

Cell size rule (when ``cell_size`` / ``cell_height`` are ``None``)::

    cell_size   = clamp(agent.radius / 2, 0.05, 1.0)
    cell_height = cell_size / 2, capped at agent.max_climb / 2 when max_climb > 0,
                  and at least 0.01
                  (climb: agent) max_climb / k for the least k that makes it at most CLIMB_BAND
                  (:func:`climb_cell_height`)

Voxel values are derived in single precision exactly as Recast's demo does
(:func:`voxel_config`): ``walkableHeight = ceilf(height / ch)`` (at least 3),
``walkableClimb = floorf(max_climb / ch)``, ``walkableRadius = ceilf(radius / cs)``,
``maxEdgeLen = (int)(edge_max_len / cs)``, ``minRegionArea = (int)(region_min_size²)``,
``mergeRegionArea = (int)(region_merge_size²)``,
``detailSampleDist = cs * detail_sample_dist``,
``detailSampleMaxError = ch * detail_sample_max_error``.
"""

from __future__ import annotations

import math
from typing import Any, Literal

import numpy as np
from pydantic import ConfigDict, Field, field_validator, model_validator
from pydantic_core import PydanticCustomError

from g2s_core.plugin import PluginParams

__all__ = ["RecastParams", "SettingsError", "climb_cell_height", "resolve_settings", "voxel_config", "VOXEL_LIMITS",
           "MAX_LEVEL_CELLS"]

MIN_TILE_SIZE = 16
"""Smallest tile side (cells) of a tiled build."""

MAX_GRID_SIDE = (1 << 24) - 1
"""Most cells along one side of the whole xz grid (the extension's vertex keys)."""

MAX_TILES = 1 << 22
"""Most tiles of a tiled build: Detour addresses tiles and polygons with 22 bits together."""

MAX_LEVEL_CELLS = 1_000_000_000
"""Default ``max_level_cells``: twice the largest level benchmarked (4.3e8 cells, docs/performance.md); a flat
generated level builds in about 0.6 µs of CPU a cell (0.9 µs wall on 2 cores), so 1e9 cells is about 10 minutes."""

MAX_SPAN_HEIGHT = (1 << 13) - 1
"""Recast's ``RC_SPAN_MAX_HEIGHT``: the level's height in cell heights."""

CLIMB_BAND = 0.025
"""``climb: agent``'s coarsest cell height, m: a step up to the agent's climb is climbed and one more than this over
it is not, wherever the floors lie between cell boundaries (docs/navmesh.md, "The climb at every alignment")."""

VOXEL_LIMITS = {"walkableHeight": 255, "walkableClimb": 255, "walkableRadius": 127, "maxEdgeLen": 46340}
"""Largest voxel values Recast 1.5.1 handles: compact spans store heights in 8
bits (a taller agent never fits anywhere), erosion compares twice the radius as
an unsigned char, contour simplification squares ``maxEdgeLen`` in an int."""

_MAX_REGION_SIZE = 46340  # its square still fits Recast's int region areas


class SettingsError(ValueError):
    """A setting Recast cannot use; the message starts with the run-config key at fault
    (``agent.radius``, ``graph.params.cell_height``, ``mesh.scale`` ...)."""


class RecastParams(PluginParams):
    """Recast build parameters (defaults: Recast demo's, cell sizes from the agent).

    Sizes are in metres unless noted; region sizes and the detail sample
    distance are in cells, the detail error in cell heights, as in Recast's demo.
    The agent's ``radius``, ``height``, ``max_climb`` and ``max_slope`` come
    from the run's agent config; the ``agent_*`` fields override them.
    """

    model_config = ConfigDict(allow_inf_nan=False)

    cell_size: float | None = Field(
        None, gt=0, description="xz voxel size, m; None: agent radius / 2 clamped to [0.05, 1]"
    )
    cell_height: float | None = Field(
        None, gt=0, description="y voxel size, m; None: cell_size / 2, at most max_climb / 2, at least 0.01"
    )
    agent_height: float | None = Field(None, gt=0, description="override of the agent's height, m")
    agent_radius: float | None = Field(None, ge=0, description="override of the agent's radius, m")
    agent_max_climb: float | None = Field(None, ge=0, description="override of the agent's max step height, m")
    agent_max_slope: float | None = Field(
        None, ge=0, lt=90, description="override of the agent's max walkable slope, degrees"
    )
    region_min_size: float = Field(
        8.0, ge=0, le=_MAX_REGION_SIZE, description="regions smaller than this² cells are removed, cells"
    )
    region_merge_size: float = Field(
        20.0, ge=0, le=_MAX_REGION_SIZE, description="regions smaller than this² cells merge into neighbours, cells"
    )
    edge_max_len: float = Field(12.0, ge=0, description="max contour edge length, m (0: unlimited)")
    edge_max_error: float = Field(1.3, ge=0, description="max contour simplification error, cells")
    verts_per_poly: int = Field(6, ge=3, le=6, description="max vertices per polygon (Detour allows 3..6)")
    detail_sample_dist: float = Field(
        6.0, ge=0.9, description="detail mesh sample spacing, cells (Recast's 'no sampling' below 0.9 crashed the "
        "system Recast library, 1.5.1+git20210215)"
    )
    detail_sample_max_error: float = Field(
        1.0, ge=0, description="max detail mesh height error, cell heights"
    )
    filter_low_hanging_obstacles: bool = Field(
        True, description="Recast's rcFilterLowHangingWalkableObstacles: walk onto obstacles up to max_climb high"
    )
    ledge_filter: Literal["recast", "drops", "off"] = Field(
        "recast",
        description="recast: Recast's rcFilterLedgeSpans, drop spans beside a drop deeper than max_climb and spans "
        "whose walkable neighbours differ by more than max_climb (the second rule also drops stair treads whose "
        "risers are within max_climb, and slopes under max_slope steeper than about atan(max_climb / (2 "
        "cell_size))); drops: the first rule alone (our own filter); off: neither (the navmesh comes up to one cell "
        "closer than the agent's radius to a drop). docs/navmesh.md",
    )
    filter_low_height_spans: bool = Field(
        True, description="Recast's rcFilterWalkableLowHeightSpans: drop spans with less head room than the agent, "
        "in cells (called with one cell less than the agent's height: Recast's own needs a cell more; docs/navmesh.md)"
    )
    climb: Literal["agent", "recast"] = Field(
        "recast",
        description="recast: the cell height rule above, whose climb of floor(max_climb / cell_height) cells walks "
        "a step up to a cell height over or under max_climb by where its floors lie between cell boundaries (0.375-"
        "0.5 m for 0.4 m on 0.125 m cells); agent: when cell_height is None, max_climb / k for the least k that "
        "makes it at most 0.025 m, so that a step up to max_climb is climbed and none 0.025 m higher, at any "
        "alignment (coarser where the level's height or the agent's height with its climb needs it: Recast's spans hold "
        "8191 cells, a span's clearance 255); the detail error keeps the metres of Recast's cell height. docs/navmesh.md, The climb at every "
        "alignment",
    )
    head_room: Literal["agent", "recast"] = Field(
        "agent",
        description="agent: a gap of the agent's height in cells holds floor; recast: the low-height filter as "
        "Recast ships it, one cell more (the paper preset, to build the navmesh the paper's method was measured on; "
        "docs/navmesh.md, Head room a little over the agent's height)",
    )
    erosion: Literal["joined", "recast"] = Field(
        "joined",
        description="joined: after Recast's erosion by the agent's radius, put back the eroded floor between two kept "
        "cells that touch only at a corner when no edge of the floor comes within the agent's radius of it (a "
        "corridor 1.7-1.8 m wide at an angle to the grid, or curved, then holds floor all along), and the floor "
        "across a door or gap between kept floor where the level's triangles stand the agent's radius off (a door "
        "1.4 m wide in a wall up to 0.3 m thick opens at any angle on map_analysis's grid, unless a tile seam cuts "
        "it); recast: Recast's "
        "erosion as shipped (the paper preset); docs/navmesh.md, Curved corridors",
    )
    partition: Literal["auto", "watershed", "monotone", "layers"] = Field(
        "auto",
        description="Recast's region partition: auto (watershed, and a tile where a watershed region overlaps "
        "itself in plan, or where one region's contours total more than 128 vertices, is redone with monotone), "
        "watershed (rcBuildRegions; can make a region of a stairwell over several storeys that overlaps itself in "
        "plan, or one region of a maze's corridors or a pillar field that rcBuildPolyMesh takes seconds to minutes "
        "over), monotone (rcBuildRegionsMonotone: never overlaps, long thin "
        "polygons) or layers (rcBuildLayerRegions: never overlaps, fewer polygons, slower on large levels); "
        "see docs/navmesh.md",
    )
    max_cells: int = Field(
        100_000_000,
        gt=0,
        le=1 << 34,
        description="refuse to rasterise more xz cells at once (the solo grid, or one tile with its border): "
        "memory guard",
    )
    max_level_cells: int = Field(
        MAX_LEVEL_CELLS,
        gt=0,
        description="refuse a level whose whole xz grid has more cells than this: time guard (a flat level "
        "takes about 0.6 µs of CPU a cell, so the default is about 10 minutes; a file read in the wrong units "
        "is the usual cause)",
    )
    tile_size: int | None = Field(
        None,
        ge=0,
        le=MAX_GRID_SIDE,
        description="tile side, cells (>= 16); None: solo up to 512 x 512 cells when it fits, "
        "else tiles of 256; 0: always solo",
    )

    @model_validator(mode="before")
    @classmethod
    def _replaced_keys(cls, data: Any) -> Any:
        if isinstance(data, dict) and "filter_ledge_spans" in data:
            raise PydanticCustomError(
                "replaced_key",
                "filter_ledge_spans was replaced by ledge_filter: write ledge_filter: recast for true, off for "
                "false, or drops for Recast's first rule alone (docs/navmesh.md)",
            )
        return data

    @field_validator("tile_size")
    @classmethod
    def _tile_size_rule(cls, value: int | None) -> int | None:
        if value is not None and 0 < value < MIN_TILE_SIZE:
            raise ValueError(f"tile_size must be 0 (solo) or >= {MIN_TILE_SIZE} cells")
        return value


def voxel_config(settings: dict[str, Any]) -> dict[str, float]:
    """Recast's voxel values from world-unit ``settings`` (:func:`resolve_settings`'s
    output), in float32 arithmetic as Recast's demo computes them; not yet
    truncated to int, so that a value too large for an int can be recognised."""
    f = np.float32
    cs, ch = f(settings["cell_size"]), f(settings["cell_height"])
    with np.errstate(over="ignore"):
        return {
            "cs": cs,
            "ch": ch,
            "walkableHeight": max(np.ceil(f(settings["agent_height"]) / ch), f(3)),
            "walkableClimb": np.floor(f(settings["agent_max_climb"]) / ch),
            "walkableRadius": np.ceil(f(settings["agent_radius"]) / cs),
            "maxEdgeLen": np.trunc(f(settings["edge_max_len"]) / cs),
            "minRegionArea": np.trunc(f(settings["region_min_size"]) * f(settings["region_min_size"])),
            "mergeRegionArea": np.trunc(f(settings["region_merge_size"]) * f(settings["region_merge_size"])),
            "detailSampleDist": cs * f(settings["detail_sample_dist"]),
            "detailSampleMaxError": ch * f(settings["detail_sample_max_error"]),
        }


_PARAMS = "graph.params."


def climb_cell_height(climb: float, height: float, level_height: float | None = None) -> float | None:
    """The cell height ``climb / k`` (m, a float32 value) for the least whole ``k`` that makes it at most
    :data:`CLIMB_BAND`, so that Recast's climb of ``floor(climb / ch)`` cells is ``k`` cells, exactly the climb, and
    a step is climbed up to ``climb`` and refused from ``climb + ch`` whatever the alignment of its floors.

    ``k`` is lowered (the cells made coarser) while the agent's ``height`` and ``climb`` together would need more
    than ``VOXEL_LIMITS["walkableHeight"]`` less one cells (the span clearance Recast's links read, 8 bits) or the level's ``level_height`` (m, ``None``: not known) more than
    :data:`MAX_SPAN_HEIGHT` less two; ``None`` when no ``k`` >= 1 fits, or without a climb.
    """
    if not climb > 0:
        return None
    k = math.ceil(climb / CLIMB_BAND - 1e-9)
    # the coarsest cell each limit allows, a millionth over it for float32's rounding of the quotients; Recast keeps a
    # span's clearance in 8 bits, so a step is linked only where the agent's height and the step fit in them together
    coarsest = (height + climb) / (VOXEL_LIMITS["walkableHeight"] - 1) * (1 + 1e-6)
    if level_height is not None:
        coarsest = max(coarsest, level_height / (MAX_SPAN_HEIGHT - 2) * (1 + 1e-6))
    k = min(k, math.floor(climb / coarsest))
    if k < 1:
        return None
    f = np.float32
    ch = f(climb / k)
    while np.floor(f(climb) / ch) < k:  # the extension divides in float32: a cell an ulp finer gives k cells
        ch = np.nextafter(ch, f(0))
    return float(ch)


def coarse_climb_warning(settings: dict[str, Any], params: RecastParams, level_height: float) -> str | None:
    """The warning for a ``climb: agent`` build whose ``settings`` (:func:`resolve_settings`) have cells coarser than
    :data:`CLIMB_BAND` (a level ``level_height`` m tall, or a tall agent, needs them), so that a step a little over the
    climb may be climbed by where its floors lie; ``None`` when the cells are that fine, or not chosen by the climb."""
    ch, climb = settings["cell_height"], settings["agent_max_climb"]
    if params.climb != "agent" or params.cell_height is not None or not climb > 0 or ch <= CLIMB_BAND * (1 + 1e-6):
        return None
    agent_fits = (climb_cell_height(climb, settings["agent_height"]) or math.inf) <= CLIMB_BAND * (1 + 1e-6)
    cause = (f"the level's {level_height:.4g} m of height in Recast's {MAX_SPAN_HEIGHT} cells" if agent_fits else
             f"the agent's height and climb ({settings['agent_height']:g} + {climb:g} m) in Recast's 8-bit span "
             f"clearance")
    cells = int(voxel_config(settings)["walkableClimb"])
    if cells * ch < climb * (1 - 1e-6):  # Recast's 0.125 m cells, which the climb is no whole number of
        band = (f"a step from {cells * ch:.3g} to {(cells + 1) * ch:.3g} m (the agent's climb is {climb:g} m) may be "
                f"climbed or not")
    else:
        band = f"a step up to {ch:.3g} m over the agent's climb of {climb:g} m may be climbed"
    return (f"graph.params.climb: agent: the navmesh's cells are {ch:.3g} m high, not {CLIMB_BAND:g} m, to hold "
            f"{cause}; {band} by where its floors lie (docs/navmesh.md, \"The climb at every alignment\")")


def resolve_settings(agent: Any, params: RecastParams | None = None,
                     level_height: float | None = None) -> dict[str, Any]:
    """The world-unit settings passed to the extension, with the cell sizes resolved.

    ``agent`` has ``radius``, ``height``, ``max_climb`` (m) and ``max_slope``
    (degrees); ``level_height`` (m) bounds ``climb: agent``'s cell height (:func:`climb_cell_height`).
    Returns a dict of the keyword arguments of ``_recast.build``.

    Raises:
        SettingsError: a voxel value beyond :data:`VOXEL_LIMITS` (the key blamed
            is the cell size when it was set, else the agent's value).
    """
    p = params or RecastParams()
    keys: dict[str, str] = {}

    def pick(override: float | None, name: str) -> float:
        if override is not None:
            keys[name] = f"{_PARAMS}agent_{name}"
            return float(override)
        keys[name] = f"agent.{name}"
        value = float(getattr(agent, name))
        if not np.isfinite(value):
            raise SettingsError(f"agent.{name}: expected a finite number, got {value}")
        return value

    height = pick(p.agent_height, "height")
    radius = pick(p.agent_radius, "radius")
    climb = pick(p.agent_max_climb, "max_climb")
    slope = pick(p.agent_max_slope, "max_slope")
    cs = p.cell_size if p.cell_size is not None else min(max(radius / 2.0, 0.05), 1.0)
    if p.cell_height is not None:
        ch = p.cell_height
    else:
        ch = cs / 2.0
        if climb > 0:
            ch = min(ch, climb / 2.0)
        ch = max(ch, 0.01)
    detail_error = float(p.detail_sample_max_error)
    if p.climb == "agent" and p.cell_height is None:
        fine = climb_cell_height(climb, height, level_height)
        if fine is not None and fine < ch:
            detail_error *= ch / fine  # the detail mesh keeps the error in metres of Recast's cell height
            ch = fine
    settings = dict(
        cell_size=float(cs),
        cell_height=float(ch),
        agent_height=height,
        agent_radius=radius,
        agent_max_climb=climb,
        agent_max_slope=slope,
        region_min_size=float(p.region_min_size),
        region_merge_size=float(p.region_merge_size),
        edge_max_len=float(p.edge_max_len),
        edge_max_error=float(p.edge_max_error),
        verts_per_poly=int(p.verts_per_poly),
        detail_sample_dist=float(p.detail_sample_dist),
        detail_sample_max_error=detail_error,
        max_cells=int(p.max_cells),
        tile_size=None if p.tile_size is None else int(p.tile_size),
        filter_low_hanging_obstacles=bool(p.filter_low_hanging_obstacles),
        ledge_filter=p.ledge_filter,
        filter_low_height_spans=bool(p.filter_low_height_spans),
        partition=p.partition,
        recast_head_room=p.head_room == "recast",
        join_corners=p.erosion == "joined",
    )
    _check_voxels(settings, keys, cs_given=p.cell_size is not None, ch_given=p.cell_height is not None)
    return settings


def _check_voxels(settings: dict[str, Any], keys: dict[str, str], cs_given: bool, ch_given: bool) -> None:
    voxels = voxel_config(settings)
    cs, ch = settings["cell_size"], settings["cell_height"]
    for key, name in (("cell_size", "cs"), ("cell_height", "ch")):
        if not np.isfinite(voxels[name]):  # Recast would build with cells of infinite size
            raise SettingsError(f"{_PARAMS}{key}: {settings[key]:g} m is more than Recast's single precision holds "
                                f"(at most {float(np.finfo(np.float32).max):.4g} m)")
    # voxel value: (agent setting, the cell key, whether that cell size was set, the cell size)
    rows = {
        "walkableHeight": ("height", f"{_PARAMS}cell_height", ch_given, ch),
        "walkableClimb": ("max_climb", f"{_PARAMS}cell_height", ch_given, ch),
        "walkableRadius": ("radius", f"{_PARAMS}cell_size", cs_given, cs),
    }
    for name, (what, cell_key, given, cell) in rows.items():
        cells, limit = float(voxels[name]), VOXEL_LIMITS[name]
        if cells <= limit:
            continue
        value = settings[f"agent_{what}"]
        key = cell_key if given else keys[what]
        raise SettingsError(
            f"{key}: the agent's {what.replace('_', ' ')} of {value:g} m is {cells:.4g} cells of {cell:g} m "
            f"({cell_key}); Recast handles at most {limit}: use cells of at least {value / limit:.4g} m "
            f"or a smaller agent {what.replace('_', ' ')}"
        )
    edge = float(voxels["maxEdgeLen"])
    if edge > VOXEL_LIMITS["maxEdgeLen"]:
        key = f"{_PARAMS}cell_size" if cs_given else f"{_PARAMS}edge_max_len"
        raise SettingsError(
            f"{key}: edge_max_len {settings['edge_max_len']:g} m is {edge:.4g} cells of {cs:g} m; Recast "
            f"handles at most {VOXEL_LIMITS['maxEdgeLen']} (0 means unlimited)"
        )
