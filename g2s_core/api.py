"""The Python API: run a config on a mesh, write the results, read them back.

::

    import g2s_core

    result = g2s_core.run("level.obj", "map_analysis", agent={"radius": 0.4})
    result.structure.nodes[0]["values"]["betweenness"]
    result.write("out")
    again = g2s_core.load_result("out")

The ``g2s`` command is built from the same functions (:func:`open_mesh`,
:func:`execute`, :func:`write_result`), so a run from Python and one from the
command line give the same files. Those are its building blocks and ``g2s
batch``'s, not the Python API (``docs/python.md``; :data:`__all__`): they take
the objects :func:`run` makes (a :class:`~g2s_core.config.RunConfig`, a
:class:`~g2s_core.model.RunResult`) and check only what a user can get wrong
through the command line.
"""

from __future__ import annotations

import gc
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from g2s_core.entry import entry_points_readable
from g2s_core.errors import G2SError, MeshError

with entry_points_readable():  # another package's broken entry_points.txt is named, not importlib's traceback
    import networkx as nx
    import trimesh

    from g2s_core import pipeline
    from g2s_core.config import RunConfig, named_files, resolve_config
    from g2s_core.input_files import given_path
    from g2s_core.mesh import SAMPLE_PREFIX, generate_level, load_mesh, mesh_sha256, prepare_and_clean, text_of_name
    from g2s_core.model import LoadedResult, RunResult
    from g2s_core.outputs import DEFAULT_FORMATS, write_outputs
    from g2s_core.registry import Registry, installed

MeshLike = str | Path | trimesh.Trimesh
ConfigLike = str | Path | Mapping[str, Any] | RunConfig

__all__ = ["load_result", "run"]


@dataclass(frozen=True)
class MeshSource:
    """The mesh a run works on, ready for the pipeline.

    Attributes:
        mesh: the triangle mesh in metres, Y up (the config's ``mesh``
            settings applied).
        name: the file or sample name the outputs record.
        sha256: of the file's bytes; of the vertex and face arrays otherwise.
        path: the file read, which no result may overwrite; ``None`` when the
            mesh did not come from a file.
        cleaning: what ``mesh.clean`` removed (``{"duplicate_faces": 3}``), if it ran.
    """

    mesh: trimesh.Trimesh
    name: str
    sha256: str
    path: Path | None = None
    cleaning: dict[str, int] | None = None


def open_mesh(mesh: MeshLike, config: RunConfig, name: str | None = None, registry: Registry | None = None) -> MeshSource:
    """The mesh of a run from a file path, ``"sample:NAME[?param=value&...]"`` or a ``trimesh.Trimesh``.

    Args:
        mesh: a mesh file (.obj .glb .gltf .ply .stl .off), ``sample:NAME``
            for a level from an installed level generator (``g2s plugins
            --stage levels``, docs/samples.md), or a mesh in the file's units
            and up axis.
        config: its ``mesh`` settings (up axis, scale; cleaning for files and
            in-memory meshes) are applied.
        name: the name recorded for the mesh (default: the file name, the
            sample spec, or ``"mesh"``), made text as a file's name is (:func:`~g2s_core.mesh.text_of_name`).
        registry: the plugins that generate sample levels (default: the installed ones).

    Raises:
        MeshError: ``mesh`` is none of these (an empty name, which is the working folder, too), the file is missing
            or not a usable triangle mesh, or ``name`` is no text.
        ConfigError: no such level generator, or bad parameters for it.
    """
    if not isinstance(mesh, trimesh.Trimesh):  # a Scene is what trimesh.load gives for a glTF
        given_path(mesh, "mesh", f"a mesh file, {SAMPLE_PREFIX}NAME or a trimesh.Trimesh", MeshError)
    if name is not None and not isinstance(name, str):
        raise MeshError(f"mesh_name: expected a text, got {type(name).__name__}")
    name = name and text_of_name(name)  # a name that is not UTF-8 (the Python API's mesh_name) as the outputs hold it
    if isinstance(mesh, trimesh.Trimesh):
        name = name or "mesh"
        prepared, cleaning = prepare_and_clean(mesh, config.mesh, source=name)
        return MeshSource(prepared, name, mesh_sha256(prepared), cleaning=cleaning)
    if isinstance(mesh, str) and mesh.startswith(SAMPLE_PREFIX):
        generated = generate_level(mesh, config.mesh, registry)
        return MeshSource(generated, name or mesh[len(SAMPLE_PREFIX):], mesh_sha256(generated))
    loaded, info = load_mesh(mesh, config.mesh)
    return MeshSource(loaded, name or info.name, info.sha256, Path(mesh), info.cleaning)


def input_files(config: RunConfig, config_files: Sequence[Path] = (), mesh: MeshLike | None = None) -> tuple[Path, ...]:
    """The files a run reads, which its results never overwrite or remove.

    They are ``config_files`` (the config and what it ``extends:``), every
    existing file a stage's parameters name (a points ``file``) and ``mesh``
    when it is a file path.
    """
    mesh_file = isinstance(mesh, (str, Path)) and not str(mesh).startswith(SAMPLE_PREFIX)
    return (*map(Path, config_files), *named_files(config), *([Path(mesh)] if mesh_file else []))


def execute(
    plan: pipeline.Plan,
    registry: Registry,
    source: MeshSource,
    progress: Callable[[str], None] | None = None,
    config_files: Sequence[Path] = (),
) -> RunResult:
    """Run a planned config on a mesh; terminal flags and analysis values go on the graphs' nodes.

    Every node of ``result.graph``, ``steiner``, ``forest`` and ``structure``
    gets ``terminal`` (bool; false for the selector's waypoints, see
    ``Terminals.without_waypoints``); every node of ``result.structure`` gets
    ``values``, a dict of analysis key -> value (also in ``result.analysis``).
    ``result.inputs`` lists the files the run read (:func:`input_files`;
    ``config_files``: the config files ``plan.config`` came from).

    Raises:
        G2SError: bad input met while running, its message led by ``source.name`` (as the mesh's own errors
            are by its path), so that a level among many is found; the step's other errors as they are.
    """
    try:
        result = pipeline.run(plan, registry, source.mesh, source.name, source.sha256, progress=progress)
    except G2SError as exc:  # the stages do not know the file: their errors are named here, once
        if not str(exc).startswith(f"{source.name}: "):  # said once: an in-memory mesh is "mesh", as builders' lines begin
            exc.args = (f"{source.name}: {exc}",)  # the same exception, of a plugin's own G2SError class too
        raise
    # pipeline.run switches CPython's cyclic collector back on with the run's objects all young: the next
    # allocations would scan each of them three times over, in a gen-0, a gen-1 and a full collection (0.9 s
    # after the stages of the 100k-polygon level). A big run's get one full collection now, before anything
    # else is allocated; a small run's few (about 22 per navmesh polygon) are left to the collector's pace,
    # as a full collection also scans the some 100,000 objects of the loaded modules.
    if gc.isenabled() and gc.get_count()[0] > 100_000:
        gc.collect()
    result.mesh_path = source.path
    result.inputs = input_files(plan.config, config_files, source.path)
    terminals = set() if result.terminals is None else set(result.terminals.without_waypoints)
    for graph in filter(None, (result.graph, result.steiner, result.forest, result.structure)):
        for node, attrs in graph.nodes(data=True):
            attrs["terminal"] = node in terminals
    if result.structure is not None:
        _put_values(result.structure, result.analysis)
    return result


def _put_values(graph: nx.Graph, analysis: Mapping[str, Mapping[int, Any]]) -> None:
    """Each node's analysis values as its ``values`` attribute (key -> value)."""
    for node, attrs in graph.nodes(data=True):
        attrs["values"] = {key: values[node] for key, values in analysis.items() if node in values}


def run(
    mesh: MeshLike,
    /,
    config: ConfigLike = "map_analysis",
    *,
    mesh_name: str | None = None,
    progress: Callable[[str], None] | None = None,
    **overrides: Any,
) -> RunResult:
    """Run a config on a mesh and return everything the stages produced.

    Args:
        mesh: a mesh file, ``"sample:NAME"`` or a ``trimesh.Trimesh`` (see :func:`open_mesh`).
        config: a preset name (``g2s presets`` lists them), a YAML file, a
            mapping as a YAML file would hold, or a :class:`~g2s_core.config.RunConfig`.
        mesh_name: the name recorded for an in-memory mesh.
        progress: called with a short message as each stage starts, and with each warning as it is raised
            (a :class:`~g2s_core.model.RaisedWarning`).
        **overrides: config keys and their new values, as ``g2s run --set``
            takes them: ``agent={"radius": 0.4}`` (mappings merge) or dotted,
            ``**{"terminals.params.radius": 8.0}``.

    Returns:
        The :class:`~g2s_core.model.RunResult`: ``graph``, ``terminals``,
        ``steiner``, ``forest``, ``structure`` (networkx graphs, nodes carrying
        ``terminal`` and, on the structure, ``values``), ``analysis``,
        ``stages`` (timings and sizes), ``warnings``; ``result.write(folder)``
        writes the files ``g2s run`` writes.

    Raises:
        ConfigError, MeshError, G2SError: bad input (what ``g2s`` reports with exit code 2).
        PluginFailure: a plugin failed (what ``g2s`` reports with exit code 1, naming the plugin).
    """
    if progress is not None and not callable(progress):
        raise G2SError(f"progress: expected a function of one argument or None, got {type(progress).__name__}")
    config_files: list[Path] = []
    run_config, source = resolve_config(config, overrides, sources=config_files)
    registry = installed()
    plan = pipeline.plan(run_config, registry, source=source)
    opened = open_mesh(mesh, run_config, name=mesh_name, registry=registry)
    return execute(plan, registry, opened, progress=progress, config_files=config_files)


def write_result(
    result: RunResult,
    outdir: str | Path,
    formats: str | Sequence[str] | None = None,
    force: bool = False,
    progress: Callable[[str], None] | None = None,
    registry: Registry | None = None,
) -> list[Path]:
    """Write a run's result files into ``outdir`` (created if missing); the paths written.

    ``formats``: names or a comma-separated string (``"json,glb"``); default:
    the config's ``outputs.formats``. A folder already holding results is
    refused unless ``force`` (then the results of formats not written are
    removed). The files appear all together or not at all; the run's input
    files (``result.inputs``: mesh, configs, points files) are never written
    or removed.

    Raises:
        G2SError: ``outdir`` is no folder path (an empty name, the working folder, too), an unknown format, or the
            folder cannot take the results (checked before anything is written).
    """
    chosen = result.config.get("outputs", {}).get("formats", DEFAULT_FORMATS) if formats is None else formats
    return write_outputs(
        result, given_path(outdir, "outdir", "a folder"), chosen, replace=force, progress=progress, registry=registry, protect=result.inputs
    )


def load_result(path: str | Path, format: str = "json", registry: Registry | None = None) -> LoadedResult:
    """Read back a result folder (or its ``structure.json``) with the ResultReader plugin of ``format``.

    The final structure's nodes carry ``terminal`` and ``values`` as in a
    :class:`~g2s_core.model.RunResult` from :func:`run`.

    Raises:
        G2SError: ``path`` is no path (an empty name too), the file is missing or not a g2s ``structure.json``
            (ConfigError: no reader of ``format`` is installed).
    """
    path = given_path(path, "path", "a result folder or its structure.json")
    registry = registry or installed()
    loaded = registry.call(registry.get("readers", format, key="format"), path=path)
    _put_values(loaded.structure, loaded.analysis)
    return loaded
