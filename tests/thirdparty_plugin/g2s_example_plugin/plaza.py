"""A square plaza: one flat slab of ``size`` x ``size`` metres (a third-party level generator)."""

import trimesh
from pydantic import Field

from g2s_core.plugin import PluginParams, hookimpl

NAME = "plaza"


class Params(PluginParams):
    size: float = Field(20.0, gt=0, description="side of the plaza, metres")


@hookimpl
def g2s_generate_level(params):
    slab = trimesh.creation.box(extents=(params.size, 0.2, params.size))
    slab.apply_translation((0.0, -0.1, 0.0))
    return slab
