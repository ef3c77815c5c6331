"""Two-sided floors (each top also wound facing down, at the same place, as exporters write double-sided faces):
the ray caster meets their up-facing side whichever is listed first, so the sampler and line of sight read them as
single-sided floors."""

from __future__ import annotations

import networkx as nx
import numpy as np
import pytest
import trimesh

from g2s_core.config import AgentConfig
from g2s_core.model import RunContext
from g2s_plugins._raycasting import AgentShape, RayCaster
from g2s_plugins.graph_builders import sampling
from g2s_plugins.predicates import mesh_los

AGENT = AgentConfig(radius=0.5, height=2.0, max_climb=0.4, max_slope=45.0)


def two_sided_slab(twin_first: bool) -> trimesh.Trimesh:
    """A 20 x 20 m slab (top at y = 0) whose top is listed again wound the other way, after or before the slab."""
    slab = trimesh.creation.box(bounds=[[0.0, -0.2, 0.0], [20.0, 0.0, 20.0]])
    underside = slab.faces[slab.face_normals[:, 1] > 0.9][:, ::-1]
    faces = np.vstack([underside, slab.faces] if twin_first else [slab.faces, underside])
    return trimesh.Trimesh(slab.vertices, faces, process=False)


@pytest.mark.parametrize("twin_first", [False, True])
def test_rays_down_meet_the_up_facing_side(twin_first):
    mesh = two_sided_slab(twin_first)
    origins = np.column_stack([np.linspace(1, 19, 50), np.ones(50), np.linspace(19, 1, 50)])
    hits = RayCaster(mesh).first_hits(origins, (0.0, -1.0, 0.0))
    assert (mesh.face_normals[hits.face, 1] > 0.9).all()
    assert np.allclose(hits.distance, 1.0)


@pytest.mark.parametrize("twin_first", [False, True])
def test_the_sampler_walks_a_two_sided_floor(twin_first):
    single = trimesh.creation.box(bounds=[[0.0, -0.2, 0.0], [20.0, 0.0, 20.0]])
    params, agent = sampling.Params(), AgentShape.from_config(AGENT)
    expected = sampling.build_sampled_graph(single, params, agent)
    graph = sampling.build_sampled_graph(two_sided_slab(twin_first), params, agent)
    assert graph.number_of_nodes() == expected.number_of_nodes() > 100
    assert graph.number_of_edges() == expected.number_of_edges()


@pytest.mark.parametrize("twin_first", [False, True])
def test_line_of_sight_over_a_two_sided_floor(twin_first):
    context = RunContext(mesh=two_sided_slab(twin_first), agent=AGENT, centre=np.zeros(3))
    clear = mesh_los.g2s_simplify_predicate(params=mesh_los.Params(), context=context, forest=None, simplified=None)
    chain = nx.DiGraph([(0, 1), (1, 2)], roots=[0])
    for node, pos in enumerate([(2.0, 0.0, 2.0), (10.0, 0.0, 12.0), (18.0, 0.0, 3.0)]):
        chain.add_node(node, pos=pos, normal=(0.0, 1.0, 0.0), on_navmesh=True, area=1.0, polygon=-1, depth=node, root=0)
    assert clear(chain, 0, 1, 2) is True
