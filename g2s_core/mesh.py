"""Reading level geometry: trimesh for I/O, pymeshlab for optional cleaning, level generators for ``sample:``."""

from __future__ import annotations

import codecs
import hashlib
import io
import logging
import os
import re
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from urllib.parse import parse_qsl, unquote, urlsplit

from g2s_core.config import MeshConfig
from g2s_core.errors import ConfigError, MeshError
from g2s_core.input_files import check_regular_file
from g2s_core.lazy import lazy_module
from g2s_core.mesh_damage import FORMATS, OBJ_COMMENT, declared_faces, describe_damage, nested_transforms, off_polygons, rows_beyond_header
from g2s_core.registry import Registry, installed

# loaded with the first mesh read: the CLI and the batch command import this module for its names
np, trimesh = lazy_module("numpy"), lazy_module("trimesh")

SUPPORTED_SUFFIXES = tuple(FORMATS)

SAMPLE_PREFIX = "sample:"
"""A mesh argument ``sample:NAME?param=value&...`` asks the level generator NAME for a level."""

Z_UP_TO_Y_UP = ((1.0, 0.0, 0.0), (0.0, 0.0, 1.0), (0.0, -1.0, 0.0))
"""Rotation taking a Z-up right-handed frame to a Y-up right-handed one: (x, y, z) -> (x, z, -y)."""


@dataclass(frozen=True)
class MeshInfo:
    """Where a mesh came from and what cleaning removed."""

    name: str
    sha256: str
    vertices: int
    faces: int
    cleaning: dict[str, int] | None = None


def text_of_name(name: str) -> str:
    """A file name or path as text that a UTF-8 file (JSON, HTML, GraphML, CSV, Parquet) can hold: its bytes that are
    not UTF-8, which Python keeps as lone surrogates (``'m\\udcff.obj'``), as ``\\xNN`` escapes (``'m\\xff.obj'``);
    other names unchanged. :func:`load_mesh` names a mesh file so, and every result, output and summary line with it;
    so are ``mesh_name`` (:func:`g2s_core.api.open_mesh`), the paths ``g2s run --json`` prints and a batch's rows.
    A lone surrogate that stands for no byte (``'\\ud800'``, from Python code only) is written ``\\ud800``."""
    return _SURROGATE.sub(lambda s: f"\\x{ord(s[0]) - 0xDC00:02x}" if "\udc80" <= s[0] <= "\udcff" else f"\\u{ord(s[0]):04x}", name)


_SURROGATE = re.compile("[\ud800-\udfff]")


def mesh_sha256(mesh: trimesh.Trimesh) -> str:
    """Hex SHA-256 of an in-memory mesh's vertex and face arrays (float64, int64)."""
    digest = hashlib.sha256()
    digest.update(np.ascontiguousarray(mesh.vertices, dtype=np.float64).tobytes())
    digest.update(np.ascontiguousarray(mesh.faces, dtype=np.int64).tobytes())
    return digest.hexdigest()


def load_mesh(path: str | Path, config: MeshConfig | None = None) -> tuple[trimesh.Trimesh, MeshInfo]:
    """Read a triangle mesh file into metres, Y up.

    Scenes (glTF/GLB) are flattened with their node transforms. The file is
    only read, never written.

    Returns:
        The mesh (vertices (N, 3) float64 metres, faces (M, 3) int64) and its
        :class:`MeshInfo`.

    Raises:
        MeshError: the file is missing, unreadable, of an unsupported type,
            damaged (where, when :func:`~g2s_core.mesh_damage.describe_damage`
            finds it), empty, not made of triangles, or has non-finite coordinates.
    """
    config = config or MeshConfig()
    path = Path(path)
    check_regular_file(path, "mesh file", MeshError)
    if path.suffix.lower() not in SUPPORTED_SUFFIXES:
        raise MeshError(f"{path}: unsupported mesh type {path.suffix!r} (expected one of {', '.join(SUPPORTED_SUFFIXES)})")
    try:
        raw = path.read_bytes()
    except OSError as exc:
        raise MeshError(f"{path}: cannot read mesh file ({exc.strerror})") from None
    if path.suffix.lower() in (".gltf", ".glb") and b'"children"' in raw and (deep := nested_transforms(path.suffix, raw)):
        raise MeshError(f"{path}: {deep}")  # trimesh would take hours over 10,000 (a RecursionError at 1,000)
    try:
        with _trimesh_log_silenced():
            text = _as_trimesh_reads_obj(raw) if path.suffix.lower() == ".obj" else raw
            rewritten = text != raw
            file = (io.BytesIO(text), "obj") if rewritten else (path,)
            loaded = (None if rewritten else _read_single_mesh(path)) or \
                trimesh.load(*file, force="mesh", process=False, resolver=_files_beside(path))
            # trimesh reads an OFF or PLY file cut at a line of its face list as the faces it holds
            if len(getattr(loaded, "faces", ())) < (declared := declared_faces(path.suffix, raw)):
                raise ValueError(f"the header declares {declared} faces, trimesh read {len(loaded.faces)}")
            if rows_beyond_header(path.suffix, raw):  # and an ASCII PLY of more rows than declared as the rows declared
                raise ValueError("more rows than the header declares")
    except Exception as exc:  # trimesh raises many exception types for bad files
        damage = describe_damage(path, raw) or (exc if isinstance(exc, MeshError) else None)  # MeshError: _files_beside
        unread = f"cannot read mesh ({type(exc).__name__}: {exc})"
        if damage or path.suffix.lower() not in POLYGON_SUFFIXES:
            raise MeshError(f"{path}: {damage or unread}") from None
        loaded = _read_polygons(path, raw, unread)
    # trimesh reads a sparse accessor's data without its values, leaves a triangle fan out, reads no compressed mesh, reads
    # elements overlapping under a stride shorter than they are: silently wrong
    if path.suffix.lower() in (".gltf", ".glb") and _GLTF_UNREAD.search(raw) and (damage := describe_damage(path, raw)):
        raise MeshError(f"{path}: {damage}")
    try:
        mesh, cleaning = prepare_and_clean(loaded, config, source=str(path))
    except MeshError as exc:  # the file's fault, not mesh.scale's or cleaning's (read as empty, a face past its vertices)
        if str(exc).startswith(f"{path}:") and (damage := describe_damage(path, raw)):
            raise MeshError(f"{path}: {damage}") from None
        raise
    return mesh, MeshInfo(text_of_name(path.name), hashlib.sha256(raw).hexdigest(), len(mesh.vertices), len(mesh.faces), cleaning)


POLYGON_SUFFIXES = (".off", ".ply")
"""Formats whose sound files trimesh may fail to read: an OFF face of 5 or more corners (trimesh 4.x on numpy 2 fans
it from text values: ``TypeError ... string multiply ufunc``) and a binary PLY face list mixing triangles and quads,
as Blender writes it (trimesh reads every row as long as the first: "PLY is unexpected length")."""


def _read_polygons(path: Path, raw: bytes, unread: str) -> trimesh.Trimesh:
    """A sound file of :data:`POLYGON_SUFFIXES` that trimesh could not read, its bytes ``raw``: an OFF file read by
    :func:`~g2s_core.mesh_damage.off_polygons`, a PLY file by pymeshlab; each polygon fanned from its first corner as
    trimesh fans an OBJ's, every vertex kept in the file's order; ``unread``: trimesh's failure, the message when
    pymeshlab fails too."""
    if path.suffix.lower() == ".off":  # pymeshlab 2025.7 numbers an OFF polygon's corners from 0 past 4 corners
        vertices, polygons = off_polygons(raw)
        return trimesh.Trimesh(vertices=vertices, faces=trimesh.geometry.triangulate_quads(polygons), process=False)
    import pymeshlab  # imported here: it takes a second to load and few files need it

    meshset, folder = pymeshlab.MeshSet(), os.getcwd()
    try:
        meshset.load_new_mesh(str(path))
    except pymeshlab.PyMeshLabException:
        raise MeshError(f"{path}: {unread}") from None
    finally:  # pymeshlab 2025.7 moves the process into the file's folder, and stays there when the file fails
        os.chdir(folder)
    read = meshset.current_mesh()
    return trimesh.Trimesh(vertices=read.vertex_matrix(), faces=read.face_matrix(), process=False)


def _as_trimesh_reads_obj(text: bytes) -> bytes:
    """An OBJ file's bytes as trimesh's reader understands them: it takes a UTF-8 byte-order mark for part of the
    first line, splits values on spaces only, lines on ``\\n`` only (an old Mac file ends its lines with ``\\r``),
    reads a line only if it starts with its keyword, reads a comment after a line's values as values and one ending
    in a backslash as going on over the next line (comments: :data:`~g2s_core.mesh_damage.OBJ_COMMENT`), reads a
    face's vertex index 0 (OBJ numbers them from 1) as 1, and takes a negative index for one counted back from the
    file's end, not from the face's line (:func:`_absolute_indices`).

    Raises:
        ValueError: a face names vertex 0 (:func:`~g2s_core.mesh_damage.describe_damage` names its line)."""
    text = text.removeprefix(codecs.BOM_UTF8).replace(b"\t", b" ")
    text = text if b"\n" in text else text.replace(b"\r", b"\n")
    if b"\n " in text:  # trimesh skips an indented line: a "  v" line was lost and every later vertex index shifted
        text = re.sub(rb"\n +", b"\n", text)
    # trimesh skips a comment line, but reads a comment after values as values and joins one ending in "\" to the next line
    if text.count(b"#") > text.count(b"\n#") + text.startswith(b"#") or b"#" in text and b"\\" in text:
        text = OBJ_COMMENT.sub(b"", text)
    last_vertex = text.rfind(b"\nv")
    faces_before = _FACE_LINE.search(text, 0, last_vertex) is not None  # most files list every vertex first
    # a value 0 is mostly an integer coordinate or "s 0": only a face line's is wrong
    if any(text.startswith(b"f ", text.rfind(b"\n", 0, zero.start()) + 1)
           for zero in _ZERO_INDEX.finditer(text, 0 if faces_before else last_vertex)):
        raise ValueError("a face names vertex 0")
    # only faces before the last vertex can be misread: the search took 1 % of reading a file whose faces follow its
    # vertices, 6 % of one of 100 objects each followed by its faces (CPU time, 420k triangles, 3 December 2026)
    return _absolute_indices(text) if faces_before and _RELATIVE_FACE.search(text, 0, last_vertex) else text


_GLTF_UNREAD = re.compile(rb'"sparse"|"mode"\s*:\s*(?![0-5](?![0-9]))|"extensionsRequired"|"byteStride"')
"""A glTF's sparse accessor, a primitive's mode other than 0-5 (a triangle fan, 6), extensions it requires
(compression: the data trimesh reads may be empty), or a stride (one shorter than its elements is read overlapping)."""

_FACE_LINE = re.compile(rb"^f ", re.MULTILINE)

_ZERO_INDEX = re.compile(rb" 0(?![^/\s])")
"""A value 0 on any line: on a face line, a corner's vertex index 0."""

_RELATIVE_FACE = re.compile(rb"\nf [^\n-]*-")
"""A face line with a negative (relative) index."""


def _absolute_indices(text: bytes) -> bytes:
    """OBJ text whose negative face indices (``-1``: the last vertex, texture coordinate or normal listed before
    the face's line) are written as the positive ones they stand for.

    Raises:
        ValueError: an index counts back past the first vertex (:func:`~g2s_core.mesh_damage.describe_damage` names it).
    """
    lines, listed = text.split(b"\n"), dict.fromkeys((b"v", b"vt", b"vn"), 0)
    for number, line in enumerate(lines):
        key, _, values = line.partition(b" ")
        if key in listed:
            listed[key] += 1
        elif key == b"f" and b"-" in values:
            lines[number] = b"f " + b" ".join(b"/".join(_absolute(index, count) for index, count in zip(corner.split(b"/"), listed.values()))
                                              for corner in values.split())
    return b"\n".join(lines)


def _absolute(index: bytes, listed: int) -> bytes:
    """The OBJ index ``index`` counted from 1, ``listed`` items of its kind preceding its line."""
    if not index.startswith(b"-"):
        return index
    if (absolute := listed + 1 + int(index)) < 1:
        raise ValueError(f"index {index.decode()} counts back past the first of {listed}")
    return b"%d" % absolute


@contextmanager
def _trimesh_log_silenced() -> Iterator[None]:
    """Keep trimesh's log (tracebacks of formats it tried and gave up on) off the user's terminal:
    a file g2s cannot read is reported once, as a MeshError."""
    logger = logging.getLogger("trimesh")
    level = logger.level
    logger.setLevel(logging.CRITICAL + 1)
    try:
        yield
    finally:
        logger.setLevel(level)


def _files_beside(path: Path) -> trimesh.resolvers.FilePathResolver:
    """trimesh's reader of the files a mesh file names (a glTF's buffers and images, an OBJ's materials), refusing
    one that is not a regular file: trimesh would open a FIFO and wait forever for a writer. (A class made here,
    not at import: trimesh loads lazily, and a command that reads no mesh must not load it.)"""

    class RegularFiles(trimesh.resolvers.FilePathResolver):
        def absolute(self, name: str) -> Path:
            if (found := super().absolute(name)).exists():
                check_regular_file(found, "file", MeshError)
            return found

        def get(self, name: str) -> bytes:  # a glTF's uri is URL-encoded ("my%20level.bin"); trimesh does not decode it
            return super().get(name if (Path(self.parent) / name).exists() else unquote(name))

    return RegularFiles(path, allow_anywhere=True)  # a buffer in "../buffers/", as glTF allows: trimesh 5 refuses it


_SINGLE_MESH_FORMATS = ("ply", "stl", "off", "obj")
"""Formats whose trimesh reader returns a single mesh's arrays (an OBJ's when its faces share one material)."""


def _read_single_mesh(path: Path) -> trimesh.Trimesh | None:
    """A PLY/STL/OFF file's triangles, or those of an OBJ file whose faces share one material, straight from
    trimesh's format reader.

    ``trimesh.load`` wraps every file in a scene and copies and hashes the
    arrays to flatten it again (2 s per million triangles, 100 times the PLY
    reader itself; about 0.3 s of the 2.5 s of a 1.7M-triangle OBJ); a single mesh needs none of it. ``None``
    when the file is not such a triangle mesh, so that ``trimesh.load`` handles (and reports) it.
    """
    kind = path.suffix.lower().lstrip(".")
    if kind not in _SINGLE_MESH_FORMATS:
        return None
    with path.open("rb") as handle:
        data = trimesh.exchange.load.mesh_loaders[kind](handle, file_type=kind)
    if isinstance(data, dict) and len(data.get("geometry") or ()) == 1:  # an OBJ's meshes, one per material
        data = next(iter(data["geometry"].values()))
    if not isinstance(data, dict) or data.get("vertices") is None or data.get("faces") is None:
        return None
    vertices, faces = np.asarray(data["vertices"]), np.asarray(data["faces"])
    if vertices.ndim != 2 or vertices.shape[1] != 3 or faces.ndim != 2 or faces.shape[1] != 3 or len(faces) == 0:
        return None
    return trimesh.Trimesh(vertices=vertices, faces=faces, process=False)


def generate_level(spec: str, config: MeshConfig | None = None, registry: Registry | None = None) -> trimesh.Trimesh:
    """The level ``sample:NAME?param=value&...`` from the installed level generator NAME.

    The query's values are strings that the generator's parameter model
    validates (and converts); the mesh then gets ``config``'s up axis and scale.

    Raises:
        ConfigError: no such generator, or a parameter is unknown or invalid;
            the message starts with ``spec``.
    """
    text = spec[len(SAMPLE_PREFIX):] if spec.startswith(SAMPLE_PREFIX) else spec
    parts = urlsplit(text)
    if parts.scheme or parts.netloc or "#" in text:  # read as a URL's, they were dropped unsaid: `#x` ran seed 1
        raise ConfigError(f"{spec}: expected sample:NAME?param=value&param=value (no '#', '//' or second ':'; "
                          "a value's '#' is written %23)")
    registry = registry or installed()
    try:
        info = registry.get("levels", parts.path)
    except ConfigError:
        known = ", ".join(p.name for p in registry.plugins("levels"))
        raise ConfigError(f"{spec}: unknown sample {parts.path!r} (expected one of: {known})") from None
    try:
        query = parse_qsl(parts.query, keep_blank_values=True, strict_parsing=bool(parts.query))
    except ValueError:
        raise ConfigError(f"{spec}: expected sample:NAME?param=value&param=value") from None
    names = [name for name, _ in query]
    if (twice := next((name for name in names if names.count(name) > 1), None)) is not None:  # dict() keeps the last
        raise ConfigError(f"{spec}: {twice} is given twice")
    params = registry.validate_params(info, dict(query), key=f"{SAMPLE_PREFIX}{info.name}", text=True)
    return prepare_mesh(registry.call(info, params=params), config or MeshConfig(), source=spec)


def prepare_mesh(loaded: object, config: MeshConfig, source: str) -> trimesh.Trimesh:
    """Check that ``loaded`` is a usable triangle mesh, then apply the up axis and scale."""
    if not isinstance(loaded, trimesh.Trimesh):
        raise MeshError(f"{source}: expected a triangle mesh, got {type(loaded).__name__} (no faces)")
    vertices, faces = np.asarray(loaded.vertices, dtype=np.float64), np.asarray(loaded.faces)
    if len(faces) == 0 or len(vertices) == 0:
        raise MeshError(f"{source}: the mesh is empty (no triangles)")
    if len(vertices) < 3:  # Recast's own precondition, which blamed the graph builder for a file of one degenerate face
        raise MeshError(f"{source}: the faces use {len(vertices)} vertices in all: every face has zero area; export it again")
    if faces.ndim != 2 or faces.shape[1] != 3:
        raise MeshError(f"{source}: expected triangles, got faces with {faces.shape[-1]} corners")
    if vertices.ndim != 2 or vertices.shape[1] != 3:  # an OBJ's "v x y" lines
        raise MeshError(f"{source}: expected vertices of 3 coordinates x, y, z, got {vertices.shape[-1]}")
    if (wrong := faces[(faces < 0) | (faces >= len(vertices))]).size:  # a damaged file; numpy would wrap negative ones
        raise MeshError(f"{source}: a face names vertex {wrong[0]}, but the mesh has {len(vertices)} (numbered from 0)")
    if not np.isfinite(vertices).all():
        raise MeshError(f"{source}: the mesh has NaN or infinite vertex coordinates")
    if config.up_axis == "z":
        vertices = vertices @ np.array(Z_UP_TO_Y_UP).T
    with np.errstate(over="ignore"):
        vertices = vertices * config.scale
    if not np.isfinite(vertices).all():
        raise MeshError(f"mesh.scale: {config.scale:g} makes {source}'s vertex coordinates overflow (infinite)")
    return trimesh.Trimesh(vertices=vertices, faces=faces, process=False)


def prepare_and_clean(loaded: object, config: MeshConfig, source: str) -> tuple[trimesh.Trimesh, dict[str, int] | None]:
    """:func:`prepare_mesh`, then :func:`clean_mesh` when ``config.clean``; the mesh and what cleaning removed."""
    mesh = prepare_mesh(loaded, config, source)
    return clean_mesh(mesh, source) if config.clean else (mesh, None)


def clean_mesh(mesh: trimesh.Trimesh, source: str = "mesh") -> tuple[trimesh.Trimesh, dict[str, int]]:
    """Merge close vertices and drop zero-area faces with pymeshlab, drop duplicate faces (of a two-sided
    face its up-facing side stays), wind each body's faces one way (:func:`wind_bodies_one_way`), then turn closed
    bodies wound inside out the right way (:func:`flip_inside_out_bodies`).

    Returns:
        The cleaned mesh and the count of what each step removed or flipped
        (``merged_vertices``, ``duplicate_faces``, ``zero_area_faces``, ``rewound_faces``, ``flipped_bodies``).

    Raises:
        MeshError: no triangle is left; the message starts with ``source``.
    """
    import pymeshlab  # imported here: it takes a second to load and most runs do not clean

    meshset = pymeshlab.MeshSet()
    meshset.add_mesh(pymeshlab.Mesh(vertex_matrix=mesh.vertices, face_matrix=mesh.faces.astype(np.int32)))

    def removed_by(filter_name: str, count: str) -> int:
        before = getattr(meshset.current_mesh(), count)()
        meshset.apply_filter(filter_name)
        return before - getattr(meshset.current_mesh(), count)()

    merged = removed_by("meshing_merge_close_vertices", "vertex_number")
    zero_area = removed_by("meshing_remove_null_faces", "face_number")
    cleaned = meshset.current_mesh()
    result = trimesh.Trimesh(vertices=cleaned.vertex_matrix(), faces=cleaned.face_matrix(), process=True)
    # Of faces on the same corners the most up-facing stays: pymeshlab's duplicate filter keeps either side of a
    # floor exported two-sided, and neither graph builder walks on its down-facing side.
    order = np.argsort(-result.face_normals[:, 1], kind="stable")
    kept = np.sort(order[np.unique(np.sort(result.faces[order], axis=1), axis=0, return_index=True)[1]])
    result.update_faces(kept)
    if len(result.faces) == 0:
        raise MeshError(f"{source}: mesh.clean removed every triangle (each had zero area, or corners merged into one)")
    result, rewound = wind_bodies_one_way(result)
    result, flipped = flip_inside_out_bodies(result)
    return result, {"merged_vertices": merged, "duplicate_faces": len(order) - len(kept), "zero_area_faces": zero_area, "rewound_faces": rewound, "flipped_bodies": len(flipped)}


def wind_bodies_one_way(mesh: trimesh.Trimesh) -> tuple[trimesh.Trimesh, int]:
    """A copy of ``mesh`` whose faces wound against their neighbours (normals a modeller left flipped) are wound as
    most of their body's area is, and how many faces turned.

    trimesh's ``fix_winding`` winds each body (faces joined by edges of two faces) as its first face in a breadth-first
    walk is; a body most of whose area that turns is turned back whole, so that the file's winding wins its majority
    (an open floor has no volume to tell its up from). O(faces log faces)."""
    trimesh.repair.fix_winding(wound := mesh.copy())
    turned = np.any(wound.faces != mesh.faces, axis=1)
    bodies = trimesh.graph.connected_components(mesh.face_adjacency, nodes=np.arange(len(mesh.faces)))
    back = [face for body in bodies if 2 * mesh.area_faces[body][turned[body]].sum() > mesh.area_faces[body].sum() for face in body]
    turned[back] = ~turned[back]
    return trimesh.Trimesh(mesh.vertices, np.where(turned[:, None], mesh.faces[:, ::-1], mesh.faces), process=False), int(turned.sum())


def flip_inside_out_bodies(mesh: trimesh.Trimesh) -> tuple[trimesh.Trimesh, list[np.ndarray]]:
    """A copy of ``mesh`` whose closed bodies wound against their nesting (:func:`body_nesting`) are wound the
    other way, and the face indices of each such body.

    Recast and the sampler walk only on faces whose normal points up, so an inside-out floor offers its underside. A
    body here is faces joined by shared edges (coincident vertices must be merged) that is closed and wound one way;
    open bodies are left alone, as their inside is not defined. O(F) over trimesh's components, then
    :func:`body_nesting`'s cost.
    """
    edges = mesh.edges.reshape(-1, 6)
    # the bodies closed and wound one way
    bodies = [np.asarray(body) for body in trimesh.graph.connected_components(mesh.face_adjacency, min_len=4) if all(trimesh.graph.is_watertight(edges[body].reshape(-1, 2)))]
    inward, depth = body_nesting(np.asarray(mesh.triangles, dtype=np.float64), bodies)
    turned = [body for body, wound_in, nesting in zip(bodies, inward, depth) if wound_in != nesting % 2]
    flip = np.isin(np.arange(len(mesh.faces)), np.concatenate([np.zeros(0, dtype=np.int64), *turned]))
    return trimesh.Trimesh(mesh.vertices, np.where(flip[:, None], mesh.faces[:, ::-1], mesh.faces), process=False), turned


def body_nesting(triangles: np.ndarray, bodies: list[np.ndarray]) -> tuple[np.ndarray, np.ndarray]:
    """How each closed body wants to be wound: ``(inward, depth)``, (b,) bool (its signed volume is negative) and
    (b,) int64 (how many other bodies of ``bodies`` hold it), for ``bodies``, b arrays of indices into ``triangles``
    ((m, 3, 3), metres), each a closed body wound one way. The one rule of what a closed body inside out is, read by
    :func:`flip_inside_out_bodies` and by the sampling route's closed-solid test
    (``g2s_plugins._raycasting._Scene.winding``).

    A closed body bounds a region. Inside k other such regions it is a solid's outside at even k, wound outward
    (positive signed volume), and the inside of a solid's hollow at odd k, wound inward: a room inside a closed
    building faces into the room, its floor up, and a crate in that room faces out again (nested shells alternate
    so, as CGAL's ``Polygon_mesh_processing::orient_to_bound_a_volume`` orients them); a body is wound right where
    ``inward == depth % 2``. A body is in another when its box is in the other's and the middle of each of its faces
    (of an area), moved just inside it, has a winding number of magnitude 1 about the other (:func:`_winding_number`):
    a pillar through a slab is in no slab, nor a pillar set into a wall slab whose box holds the pillar's (the level
    turned about the vertical). The volumes, boxes and pairs of boxes one in the other are array passes over all
    bodies; only the P pairs whose boxes nest are tested one by one: where no triangle of the outer body holds the
    inner one's highest probe in plan (its box) and rises above it, a ray up from that probe crosses nothing, so it
    is out (a rock sunk into a closed terrain); else all its probes at once, in parts of about 2^18 (probe, face)
    rows, stopping at the first part with a probe outside. O(n + b log b + C + P F + sum f F) for n faces, b bodies,
    C pairs of one starting along x within the other's x range, and f faces of the inner body and F of the outer one
    of each of the P pairs (f = 0 where the ray test says out).
    """
    size = np.array([len(body) for body in bodies], dtype=np.int64)
    if not len(bodies):
        return np.zeros(0, dtype=bool), np.zeros(0, dtype=np.int64)
    first, corners = np.cumsum(size) - size, triangles[np.concatenate(bodies)]
    lo, hi = (bound.reduceat(corners.reshape(-1, 3), 3 * first) for bound in (np.minimum, np.maximum))  # (b, 3) boxes
    middle, inset = (lo.min(axis=0) + hi.max(axis=0)) / 2, 1e-6 * float((hi.max(axis=0) - lo.min(axis=0)).max())  # inset: m, off a face into its body
    # about the middle, where the sums lose less; the boxes as (3, b), each axis's row contiguous
    corners, lo, hi = corners - middle, (lo - middle).T.copy(), (hi - middle).T.copy()
    inward = np.bincount(np.repeat(np.arange(len(bodies)), size), np.einsum("ij,ij->i", corners[:, 0], np.cross(corners[:, 1], corners[:, 2]))) < 0
    # a box in another starts along x within the other's x range, a range of the bodies sorted by their box's start;
    # of those, the boxes that end within it along x, then those within it along y and z
    by_start = np.argsort(lo[0], kind="stable")
    left = np.searchsorted(lo[0, by_start], lo[0] - inset)
    reach = np.searchsorted(lo[0, by_start], hi[0] + inset, side="right") - left
    candidate = np.repeat(left - np.cumsum(reach) + reach, reach) + np.arange(reach.sum())  # the ranges one after another
    held = hi[0, by_start][candidate] <= np.repeat(hi[0] + inset, reach)
    outer, inner = np.repeat(np.arange(len(bodies)), reach)[held], by_start[candidate[held]]
    for axis in (1, 2):  # one axis at a time: the pairs left after y are far fewer than the x sweep's
        held = (inner != outer) & (lo[axis, inner] >= lo[axis, outer] - inset) & (hi[axis, inner] <= hi[axis, outer] + inset)
        outer, inner = outer[held], inner[held]
    depth, low, high = np.zeros(len(bodies), dtype=np.int64), corners.min(axis=1) - inset, corners.max(axis=1) + inset  # triangles' boxes
    for holder, body in zip(outer, inner):
        faces, around = corners[first[body]:first[body] + size[body]], corners[first[holder]:first[holder] + size[holder]]
        normal = np.cross(faces[:, 1] - faces[:, 0], faces[:, 2] - faces[:, 0])  # length: twice the area
        faces, normal = faces[np.any(normal != 0, axis=1)], normal[np.any(normal != 0, axis=1)]  # the faces of an area
        probes = faces.mean(axis=1) + (inset if inward[body] else -inset) * normal / np.linalg.norm(normal, axis=1, keepdims=True)
        # the highest probe is in the holder only if a ray up from it leaves the holder: through a triangle whose box
        # holds it in plan and rises above it; with none (a rock sunk into a closed terrain, its top out) no winding
        # number is asked, which costs F a probe; then the rest in parts of about 2^18 (probe, face) rows, some 50 MB
        # of _winding_number's arrays, to the first part with a probe outside
        top, span = (probes[np.argmax(probes[:, 1])] if len(probes) else np.zeros(3)), slice(first[holder], first[holder] + size[holder])
        roofed = np.any((low[span, 0] <= top[0]) & (high[span, 0] >= top[0]) & (low[span, 2] <= top[2]) & (high[span, 2] >= top[2]) & (high[span, 1] >= top[1]))
        depth[body] += len(probes) > 0 and roofed and all((np.abs(_winding_number(around, part)) > 0.5).all() for part in np.array_split(probes, max(1, len(probes) * len(around) >> 18)))
    return inward, depth


def _winding_number(corners: np.ndarray, points: np.ndarray) -> np.ndarray:
    """(k,) float64: how many times the closed surface of the triangles ``corners`` ((m, 3, 3), metres) winds round
    each of ``points`` ((k, 3)): +-1 inside (the sign of its signed volume), 0 outside. The sum of the solid angles
    the triangles subtend, each by A. van Oosterom and J. Strackee's formula (IEEE Trans. Biomed. Eng. 30(2), 1983),
    over 4 pi. O(k m)."""
    rows = corners[None] - points[:, None, None]  # (k, m, 3, 3)
    (a, b, c), (la, lb, lc) = np.moveaxis(rows, 2, 0), np.moveaxis(np.linalg.norm(rows, axis=3), 2, 0)
    return np.arctan2(np.einsum("...i,...i", a, np.cross(b, c)), la * lb * lc + (a * b).sum(axis=2) * lc + (a * c).sum(axis=2) * lb + (b * c).sum(axis=2) * la).sum(axis=1) / (2 * np.pi)
