"""What is wrong with a damaged mesh file, in a user's words, where trimesh's own error misleads.

trimesh reads a binary STL whose size does not match its header as ASCII STL
and finds no triangles ("the mesh is empty"), reports a GLB cut short by the
JSON error of its cut header chunk, and a glTF file whose JSON is broken as a
missing ``model.gltf`` (it then looks for a zip archive). Of a damaged OBJ, OFF
or PLY file it passes numpy's words on ("string or file could not be read to
its end due to unmatched data", "index 8 is out of bounds", "cannot reshape
array of size 6 into shape (3,3)"): here the first line at fault is found, or
the element a binary PLY's data runs short in. :func:`describe_damage` is asked
only after trimesh failed or the mesh it read was refused.
"""

from __future__ import annotations

import base64
import binascii
import codecs
import io
import json
import math
import re
import reprlib
import stat
from collections.abc import Callable, Iterable
from functools import partial
from pathlib import Path
from urllib.parse import unquote

STL_HEADER, STL_TRIANGLE, GLB_HEADER = 84, 50, 12
"""Bytes of a binary STL's header (80 free bytes, then the triangle count, uint32) and of each of its
triangles; bytes of a GLB's header (``glTF``, the version, then the file's length in bytes, uint32 each)."""

OBJ_VALUES = {b"v": "vertex coordinate", b"vt": "texture coordinate", b"vn": "normal coordinate"}
"""The OBJ lines of numbers trimesh reads, and what their values are called in messages."""

OBJ_COMMENT = re.compile(rb"#[^\r\n]*")
"""OBJ's comments, one rule for the check and the reading: a ``#`` to its line's end, wherever it stands (``f 1 3 2#x``)."""

OBJ_INDEXED = {b"v": "vertex", b"vt": "texture coordinate", b"vn": "normal"}
"""What a face corner's ``v/vt/vn`` indices name, in messages."""

GLTF_COMPONENTS = {5120: 1, 5121: 1, 5122: 2, 5123: 2, 5125: 4, 5126: 4}
"""A glTF accessor's ``componentType`` codes and the bytes of each (int8, uint8, int16, uint16, uint32, float32)."""

GLTF_TYPES = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT2": 4, "MAT3": 9, "MAT4": 16}
"""A glTF accessor's ``type`` names and the components of each."""

GLTF_COMPRESSED = ("KHR_draco_mesh_compression", "EXT_meshopt_compression")
"""glTF extensions that compress a mesh's vertices or indices (trimesh reads the uncompressed data only, which a
file that requires them need not hold)."""

GLTF_LISTS = ("scenes", "nodes", "meshes", "accessors", "bufferViews", "buffers")
"""The glTF document's lists of objects that lead from its scene to the vertices' bytes."""

NODE_TRANSFORM_SIZES = {"matrix": 16, "translation": 3, "rotation": 4, "scale": 3}
"""How many numbers each of a glTF node's transform keys holds."""

NODE_KEYS = {"mesh": "the index of one of the file's {meshes}", "children": "a list of indices of the file's {nodes}",
             **{key: f"a list of {size} finite numbers" + (" (a quaternion)" if key == "rotation" else "")
                for key, size in NODE_TRANSFORM_SIZES.items()}}
"""What each of a glTF node's keys that trimesh reads must be (trimesh fails on another kind in numpy's words, or
leaves a mesh it does not find out)."""

GLTF_MAX_TRANSFORMS = 256
"""The most transforms a glTF node holding a mesh may sit under, its own counted: trimesh multiplies those of a mesh's
path with numpy's ``multi_dot``, whose ordering of the product takes time of the cube of their number (0.11 s CPU for
128, 0.88 s for 256, 7.3 s for 512) and recursion as deep (1,000 fail): 10,000 nested would take hours."""

GLTF_IDENTITY = {"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1], "translation": [0, 0, 0], "rotation": [0, 0, 0, 1],
                 "scale": [1, 1, 1]}
"""A glTF node's transform keys at their defaults (trimesh leaves such a transform out of the product)."""

STL_KEYWORDS = (b"solid", b"facet", b"outer", b"vertex", b"endloop", b"endfacet", b"endsolid")
"""The words an ASCII STL line starts with (trimesh reads any case)."""

PLY_TYPES = (b"char", b"uchar", b"short", b"ushort", b"int", b"uint", b"float", b"double", b"int8", b"uint8", b"int16",
             b"uint16", b"int32", b"uint32", b"int64", b"uint64", b"float16", b"float32", b"float64")
"""The PLY property types trimesh reads."""

FORMATS = {".obj": "OBJ", ".glb": "GLB (binary glTF)", ".gltf": "glTF JSON", ".ply": "PLY", ".stl": "STL", ".off": "OFF"}
"""Each mesh file suffix g2s reads and the name of its format in messages."""

SIGNATURES = ((b"glTF", ".glb"), (b"ply", ".ply"), (b"OFF", ".off"), (b"solid", ".stl"), (b"{", ".gltf"))
"""The first bytes of a mesh format's files (an ASCII STL's ``solid``, a glTF's JSON object) and its suffix; a
binary STL, which has none, is told by its size (:func:`_content_format`)."""

OBJ_STATEMENTS = frozenset((b"v", b"vt", b"vn", b"vp", b"f", b"l", b"p", b"o", b"g", b"s", b"mg", b"usemtl", b"mtllib"))
"""The statements of an OBJ file's polygonal geometry, groups and materials: those the exporters write."""

Rows = list[tuple[int, list[bytes]]]
"""A text file's lines as (line number from 1, whitespace-separated values)."""


def describe_damage(path: Path, data: bytes) -> str | None:
    """Why the bytes ``data`` of the mesh file ``path`` hold no mesh, or not the one they should, in words;
    ``None`` when none of the checks below finds it.

    A file whose content is another format's, by its first bytes or a binary STL's size, is named so
    (:func:`_content_format`). Text formats are checked line by line (OBJ, OFF, ASCII PLY: values that
    are not numbers, vertices of fewer than 3 coordinates, faces of fewer than
    3 corners or naming a vertex the file lacks, fewer rows than the header
    declares); binary formats by their size against their header; glTF and
    GLB by their JSON and the buffers it lists (:func:`_gltf_damage`).
    """
    suffix, size = path.suffix.lower(), len(data)
    if size == 0:
        return "the file is empty (0 bytes)"
    if (content := _content_format(data)) and content[0] != suffix:  # read as the suffix says, it was "the mesh is empty"
        return f"the file's content is not {FORMATS[suffix]} but {content[1]}; rename it {path.with_suffix(content[0]).name}"
    if suffix == ".stl" and size < STL_HEADER and not b"solid".startswith(data.lstrip()[:5]):  # read as ASCII STL: "line 1: ..."
        return f"binary STL ends early: the file has {_many(size, 'byte')}, its header alone takes {STL_HEADER}"
    # ASCII STL starts with "solid", never holds a NUL
    if binary_stl := suffix == ".stl" and size >= STL_HEADER and (not data.startswith(b"solid") or b"\0" in data[:STL_HEADER]):
        count = int.from_bytes(data[80:STL_HEADER], "little")
        if size < (expected := STL_HEADER + STL_TRIANGLE * count):
            return f"binary STL ends early: the header announces {count} triangles, the file holds {(size - STL_HEADER) // STL_TRIANGLE}"
        if size > expected:
            return f"binary STL has {size - expected} bytes more than the {count} triangles its header announces"
    announced = int.from_bytes(data[8:GLB_HEADER], "little") if size >= GLB_HEADER else None  # None: cut inside the header
    if suffix == ".glb" and b"glTF".startswith(data[:4]) and (announced is None or size < announced):  # cut in b"glTF" too
        return f"the GLB file ends early (its header {f'is {GLB_HEADER}' if announced is None else f'announces {announced}'} bytes, the file has {size})"
    if suffix == ".glb" and data.startswith(b"glTF") and (version := int.from_bytes(data[4:8], "little")) != 2:
        return f"the GLB header's version is {version}; g2s reads GLB version 2 (glTF 2.0): convert the file to glTF 2.0"
    if suffix == ".glb" and data.startswith(b"glTF"):
        return _glb_damage(data, path.parent)
    if suffix == ".glb":  # else trimesh's "incorrect header on GLB file", named as a ValueError
        return f"not a GLB file: it starts with {data[:4]!r}, not b'glTF'"
    if suffix == ".gltf":
        document = _json(data)
        return f"not valid glTF JSON ({document})" if isinstance(document, str) else _gltf_damage(document, path.parent, None)
    readers: dict[str, Callable[[bytes], str | None]] = {".obj": _obj_damage, ".off": _off_damage, ".ply": _ply_damage,
                                                         ".stl": _stl_ascii_damage}
    return readers[suffix](data) if suffix in readers and not binary_stl else None


def _content_format(data: bytes) -> tuple[str, str] | None:
    """The suffix of the mesh format whose files start as the bytes ``data`` do (:data:`SIGNATURES`), or whose size
    is that of a binary STL by the triangle count in its header, and that format in words; ``None`` for none."""
    if len(data) >= STL_HEADER and len(data) == STL_HEADER + STL_TRIANGLE * (count := int.from_bytes(data[80:STL_HEADER], "little")):
        return ".stl", f"a binary STL, by its size: an 80-byte header, then the {count} triangles it announces"
    head = data[:1024].lstrip()  # a text format's first line may follow blank ones
    found = next((suffix for start, suffix in SIGNATURES if head.startswith(start)), None)
    return (found, f"{'ASCII STL' if found == '.stl' else FORMATS[found]}, by its first bytes {head[:5]!r}") if found else _obj_text(data)


def _obj_text(data: bytes) -> tuple[str, str] | None:
    """``.obj`` and the OBJ statements (:data:`OBJ_STATEMENTS`) that start the lines of the first 64 KiB of ``data``
    (comments and blank lines aside) in words, when every line there starts with one, a ``v`` among them, and a line
    of the file is a face; else ``None``. An OBJ has no first bytes of its own: any statement may come first.
    O(size) for the face search."""
    lines = data[:65536].removeprefix(codecs.BOM_UTF8).splitlines()[:-1 if len(data) > 65536 else None]  # a cut last line
    found = {values[0] for values in (OBJ_COMMENT.sub(b"", line).split() for line in lines) if values}
    is_obj = b"v" in found and found <= OBJ_STATEMENTS and re.search(rb"^\s*f\s", data, re.MULTILINE)
    return (".obj", f"OBJ text, by the statements its lines start with ({b', '.join(sorted(found)).decode()})") if is_obj else None


def nested_transforms(suffix: str, data: bytes) -> str | None:
    """Which mesh node of a glTF (GLB) file's bytes ``data`` sits under more than :data:`GLTF_MAX_TRANSFORMS`
    transforms, in words; ``None`` when none does or the JSON is not readable (:func:`describe_damage` names that).
    O(nodes)."""
    document = _json(_glb_json_chunk(data) if suffix.lower() == ".glb" else data)
    nodes = document.get("nodes") if isinstance(document, dict) else None
    if not (isinstance(nodes, list) and all(isinstance(node, dict) for node in nodes)):
        return None
    children = [[child for child in node["children"] if _is_index(child, len(nodes))]
                if isinstance(node.get("children"), list) else [] for node in nodes]
    below = {child for listed in children for child in listed}
    stack, above = [(number, 0) for number in range(len(nodes)) if number not in below], {}
    while stack:  # depth first from the roots, each node once (a cycle or a second parent is refused elsewhere)
        number, depth = stack.pop()
        if number not in above:
            above[number] = depth + any(nodes[number].get(key, value) != value for key, value in GLTF_IDENTITY.items())
            if "mesh" in nodes[number] and above[number] > GLTF_MAX_TRANSFORMS:
                return (f"nodes[{number}], a mesh's node, sits under {above[number]:,} nested transforms; g2s reads at "
                        f"most {GLTF_MAX_TRANSFORMS} (apply the transforms in the exporter, or flatten the node hierarchy)")
            stack.extend((child, above[number]) for child in children[number])
    return None


def declared_faces(suffix: str, data: bytes) -> int:
    """The faces an OFF or PLY file's header declares (0 for other files, or when the header does not say)."""
    if suffix.lower() == ".ply":  # in the header only, without copying the (binary) rest of the file
        declared = re.compile(rb"^element face (\d+)", re.MULTILINE).search(data, 0, max(data.find(b"end_header"), 0))
    elif suffix.lower() == ".off":  # OFF, then "vertices faces edges" on that line or the next one of values
        declared = re.match(rb"\s*\w*OFF\s+(?:#[^\n]*\s+)*\d+\s+(\d+)", data)
    return int(declared[1]) if suffix.lower() in (".ply", ".off") and declared else 0


def rows_beyond_header(suffix: str, data: bytes) -> bool:
    """Whether an ASCII PLY file has more lines of values than its header declares rows (trimesh drops them unsaid)."""
    header, _, body = data.partition(b"end_header")
    if suffix.lower() != ".ply" or not re.search(rb"^format ascii", header, re.MULTILINE):
        return False
    declared = sum(int(count) for count in re.findall(rb"^element \S+ (\d+)", header, re.MULTILINE))
    return bool(body := body.strip()) and body.count(b"\n") + 1 > declared


def _json(data: bytes) -> object:
    """JSON text's value, or where and why it is not JSON (a string)."""
    try:
        return json.loads(data)
    except (ValueError, RecursionError) as exc:  # json.JSONDecodeError; UnicodeDecodeError for bytes that are not UTF-8
        return f"line {exc.lineno}, column {exc.colno}: {exc.msg}" if isinstance(exc, json.JSONDecodeError) else \
            "nested too deeply" if isinstance(exc, RecursionError) else "not UTF-8 text"


def _glb_json_chunk(data: bytes) -> bytes:
    """A GLB file's first chunk, its JSON: after the 12-byte file header, the chunk's length and type."""
    return data[20:20 + int.from_bytes(data[12:16], "little")]


def _glb_damage(data: bytes, folder: Path) -> str | None:
    """What is wrong with a GLB file's chunks: its JSON chunk (the first), then the glTF it holds, whose buffer
    without a ``uri`` is the binary chunk that follows."""
    length, kind = int.from_bytes(data[12:16], "little"), data[16:20]  # the first chunk's header
    if kind != b"JSON":
        return f"the GLB's first chunk is of type {_text(kind)!r}, expected 'JSON'"
    if len(data) < 20 + length:
        return f"the GLB's JSON chunk announces {length} bytes, the file has {len(data) - 20} after the chunk's header"
    if isinstance(document := _json(_glb_json_chunk(data)), str):
        return f"the GLB's JSON chunk is not valid JSON ({document})"
    binary = data[20 + length:]
    return _gltf_damage(document, folder, int.from_bytes(binary[:4], "little") if binary[4:8] == b"BIN\0" else None)


def _gltf_damage(document: object, folder: Path, binary: int | None) -> str | None:
    """What is wrong with a glTF document (``binary``: a GLB's binary chunk's length): not an object, an ``asset.version``
    other than 2.x, a required extension of :data:`GLTF_COMPRESSED`, a buffer that cannot be read (a file missing beside
    it or shorter than its ``byteLength``, a data URI not in base64, a GLB without its binary chunk), an index to a buffer
    or view the document lacks, its accessors (:func:`_accessor_damage`), its scene's way to its vertices (:func:`_scene_damage`)."""
    if not isinstance(document, dict):
        return "expected a glTF JSON object at the top level"
    asset, required = document.get("asset"), document.get("extensionsRequired")
    if isinstance(version := asset.get("version") if isinstance(asset, dict) else None, str) and not version.startswith("2."):
        return f"asset.version is {version!r}; g2s reads glTF 2.0 (convert the file to glTF 2.0)"
    if compressed := [name for name in (required if isinstance(required, list) else ()) if name in GLTF_COMPRESSED]:
        return f"extensionsRequired lists {compressed[0]}: the mesh is compressed, which g2s cannot read; export it without compression"
    for name in GLTF_LISTS:  # trimesh fails on another kind with a TypeError or AttributeError
        if not isinstance(items := document.get(name, []), list):
            return _expected(name, items, "a list of objects")
        if (wrong := next((number for number, item in enumerate(items) if not isinstance(item, dict)), None)) is not None:
            return _expected(f"{name}[{wrong}]", items[wrong], "an object")
    sizes = []
    for number, buffer in _listed(document, "buffers"):
        uri, needed = buffer.get("uri"), buffer.get("byteLength", 0)
        if uri is None and binary is None:
            return f"buffers[{number}] has no uri and the file no binary chunk"
        if isinstance(uri, str) and uri.startswith("data:"):
            try:
                size = len(base64.b64decode(uri.partition(",")[2], validate=True))
            except binascii.Error:
                return f"buffers[{number}]: its data URI is not valid base64"
        elif isinstance(uri, str):
            name = uri if (folder / uri).exists() else unquote(uri)  # URL-encoded, as mesh._files_beside reads it
            try:
                if not stat.S_ISREG((folder / name).stat().st_mode):
                    return None  # trimesh was refused it by name (a FIFO would wait forever): mesh._files_beside
                with (folder / name).open("rb") as file:
                    size = file.seek(0, io.SEEK_END)
            except (OSError, ValueError) as exc:  # ValueError: a NUL in the name
                return f"buffers[{number}]: cannot read its file {name!r} beside the glTF file ({getattr(exc, 'strerror', None) or exc})"
        else:
            size = binary or 0
        if isinstance(needed, int) and size < needed:
            return f"buffers[{number}]: byteLength is {needed} bytes, its data holds {size}"
        sizes.append(size)
    views = _listed(document, "bufferViews")
    for items, key, target, count in (("bufferViews", "buffer", "buffer", len(sizes)), ("accessors", "bufferView", "bufferView", len(views))):
        for number, item in _listed(document, items):
            if key in item and not (isinstance(item[key], int) and 0 <= item[key] < count):
                return f"{items}[{number}].{key} is {item[key]!r}; the file lists {_many(count, target)}"
    for number, view in views:
        end = sum(value for value in (view.get("byteOffset", 0), view.get("byteLength", 0)) if isinstance(value, int))
        if "buffer" in view and end > sizes[view["buffer"]]:
            return f"bufferViews[{number}] ends at byte {end}, past the {sizes[view['buffer']]} bytes of buffer {view['buffer']}"
    return next(filter(None, (_accessor_damage(number, accessor, document) for number, accessor in _listed(document, "accessors"))), None) \
        or _scene_damage(document)


def _accessor_damage(number: int, accessor: dict, document: dict) -> str | None:
    """What is wrong with the glTF accessor ``accessors[number]``: a count, component type, type or byte offset
    of another kind than the glTF specification's, a buffer view's stride shorter than its elements, data past its buffer
    view's end, or sparse values (trimesh reads the data under them only: the mesh would be read silently wrong)."""
    expected = {"count": "an integer >= 1", "componentType": f"one of {', '.join(map(str, GLTF_COMPONENTS))}",
                "type": f"one of {', '.join(GLTF_TYPES)}", "byteOffset": "an integer >= 0"}
    count, offset = accessor.get("count"), accessor.get("byteOffset", 0)
    wrong = {"count": not (type(count) is int and count >= 1), "componentType": accessor.get("componentType") not in GLTF_COMPONENTS,
             "type": accessor.get("type") not in GLTF_TYPES, "byteOffset": not (type(offset) is int and offset >= 0)}
    if key := next((key for key, is_wrong in wrong.items() if is_wrong), None):
        return f"accessors[{number}].{key} is {accessor.get(key)!r}; expected {expected[key]}"
    if "sparse" in accessor:
        return f"accessors[{number}] is sparse, which g2s cannot read (its values would be read as zeros or the data under them)"
    item = GLTF_COMPONENTS[accessor["componentType"]] * GLTF_TYPES[accessor["type"]]
    view = document["bufferViews"][accessor["bufferView"]] if "bufferView" in accessor else None
    length, stride = (view.get("byteLength"), view.get("byteStride", item)) if isinstance(view, dict) else (None, item)
    if not (type(stride) is int and stride >= item):  # trimesh read overlapping elements (a stride of 4) or failed (0)
        return _expected(f"bufferViews[{accessor['bufferView']}].byteStride", stride, f"an integer >= {item}, the bytes of one "
                         f"element of accessors[{number}] ({accessor['type']} of {GLTF_COMPONENTS[accessor['componentType']]}-byte numbers)")
    if isinstance(length, int) and isinstance(stride, int) and (end := offset + (count - 1) * stride + item) > length:
        return f"accessors[{number}] ends at byte {end} of bufferViews[{accessor['bufferView']}], past its {length} bytes"
    return None


def _listed(document: dict, name: str) -> list[tuple[int, dict]]:
    """A glTF document's list ``name`` (``buffers`` ..., of objects: :func:`_gltf_damage` checks it first): each object's index and the object."""
    return list(enumerate(document.get(name, [])))


def _scene_damage(document: dict) -> str | None:
    """What is wrong on the way from a glTF document's scene to its vertices (trimesh fails on it with a ``TypeError``
    or ``KeyError``): the scene's index, each scene's node indices, each mesh primitive's ``POSITION`` accessor,
    which a valid glTF may leave out but g2s needs, and its mode, then each node's mesh, children and transform."""
    count = {name: len(document.get(name, [])) for name in GLTF_LISTS}
    if "scene" in document and not _is_index(document["scene"], count["scenes"]):
        return _expected("scene", document["scene"], f"the index of one of the file's {_many(count['scenes'], 'scene')}")
    if not count["scenes"] and count["meshes"]:  # a library of meshes: trimesh read "the mesh is empty" (`scenes: []` an IndexError)
        return f"the file lists no scene, so none of its {_many(count['meshes'], 'mesh')} is placed; expected a scene of the level's nodes"
    for number, scene in _listed(document, "scenes"):
        if not (isinstance(nodes := scene.get("nodes", []), list) and all(_is_index(node, count["nodes"]) for node in nodes)):
            return _expected(f"scenes[{number}].nodes", nodes, f"a list of indices of the file's {_many(count['nodes'], 'node')}")
    for number, mesh in _listed(document, "meshes"):
        if not (isinstance(primitives := mesh.get("primitives"), list) and all(isinstance(p, dict) for p in primitives)):
            return _expected(f"meshes[{number}].primitives", primitives, "a list of objects")
        for index, primitive in enumerate(primitives):
            if not isinstance(attributes := primitive.get("attributes"), dict) or "POSITION" not in attributes:
                return f"meshes[{number}].primitives[{index}] has no attributes.POSITION, the accessor of its vertices, which g2s needs"
            if not _is_index(attributes["POSITION"], count["accessors"]):
                return _expected(f"meshes[{number}].primitives[{index}].attributes.POSITION", attributes["POSITION"],
                                 f"the index of one of the file's {_many(count['accessors'], 'accessor')}")
            if (mode := primitive.get("mode", 4)) not in range(6) or type(mode) is not int:  # trimesh leaves such a primitive out
                return _expected(f"meshes[{number}].primitives[{index}].mode", mode, "one of 0-5 (4 triangles, 5 a triangle "
                                 "strip; 0-3, points and lines, are left out); g2s cannot read 6, a triangle fan")
            indices = document["accessors"][primitive["indices"]] if _is_index(primitive.get("indices"), count["accessors"]) else None
            if "indices" in primitive and not (indices and indices["type"] == "SCALAR" and indices["componentType"] in (5121, 5123, 5125)
                                               and (mode != 4 or indices["count"] % 3 == 0)):
                return _expected(f"meshes[{number}].primitives[{index}].indices", primitive["indices"], "the index of an accessor of "
                                 "SCALAR unsigned integers (componentType 5121, 5123 or 5125), 3 a triangle" + (
                                     f"; accessors[{primitive['indices']}] holds {indices['count']} {indices['type']} of "
                                     f"componentType {indices['componentType']}" if indices else ""))
    return _node_damage(document, count)


def _node_damage(document: dict, count: dict[str, int]) -> str | None:
    """The first of a glTF document's nodes whose mesh, children or transform trimesh would fail on (in numpy's
    words) or read as no mesh; ``count``: the length of each of :data:`GLTF_LISTS`."""
    for number, node in _listed(document, "nodes"):
        for key, value in node.items():
            if key == "mesh":
                sound = _is_index(value, count["meshes"])
            elif key == "children":
                sound = isinstance(value, list) and all(_is_index(item, count["nodes"]) for item in value)
            elif key in NODE_TRANSFORM_SIZES:
                sound = isinstance(value, list) and len(value) == NODE_TRANSFORM_SIZES[key] and all(
                    type(item) in (int, float) and math.isfinite(item) for item in value)
            else:
                continue
            if not sound:
                wanted = NODE_KEYS[key].format(nodes=_many(count["nodes"], "node"), meshes=_many(count["meshes"], "mesh"))
                return _expected(f"nodes[{number}].{key}", value, wanted)
    return None


def _is_index(value: object, count: int) -> bool:
    return type(value) is int and 0 <= value < count


def _expected(key: str, value: object, expected: str) -> str:
    """``KEY is VALUE; expected ...``, a long value cut short; a missing one (``None`` from ``dict.get``) named so."""
    return f"{key} is {'missing' if value is None else reprlib.repr(value)}; expected {expected}"


def _obj_damage(data: bytes) -> str | None:
    """The first line of an OBJ file that is wrong. Faces number vertices (texture coordinates, normals) from 1, or
    back from their line when negative; ``f 1 2 9`` in a file of 3 vertices is wrong wherever it stands (trimesh
    reads every vertex first)."""
    rows = _rows(OBJ_COMMENT.sub(b"", data.removeprefix(codecs.BOM_UTF8)).splitlines())
    listed = {key: sum(values[:1] == [key] for _, values in rows) for key in OBJ_VALUES}
    before = dict.fromkeys(OBJ_VALUES, 0)
    for number, line in rows:
        (key, *values), problem = line or [b""], None
        if key in OBJ_VALUES:
            before[key] += 1
            problem = _vertex(values) if key == b"v" else _not_numbers(values, OBJ_VALUES[key])
        elif key == b"f" and len(values) < 3:
            problem = f"a face of {_many(len(values), 'corner')} (at least 3 make a face)"
        elif key == b"f" and (wrong := next((c for c in values if not re.fullmatch(rb"-?\d+(/(-?\d+)?){0,2}", c)), None)):
            problem = f"face corner {_text(wrong)!r} is not a vertex index (expected v, v/vt, v//vn or v/vt/vn)"
        elif key == b"f":
            problem = next((f"a face refers to {OBJ_INDEXED[kind]} {i}{_named_item(i, before[kind], listed[kind], OBJ_INDEXED[kind])}"
                            for corner in values for kind, index in zip(OBJ_VALUES, corner.split(b"/")) if index
                            if not (0 < (i := int(index)) <= listed[kind] or 0 < before[kind] + 1 + i <= before[kind])), None)
        if problem:
            return f"line {number}: {problem}"
    return None


def _named_item(index: int, before: int, listed: int, name: str) -> str:
    """Why the OBJ face index ``index`` names no ``name`` (vertex ...), ``before`` of the file's ``listed`` preceding
    its line."""
    return f"; OBJ numbers {_many(2, name).partition(' ')[2]} from 1" if index == 0 else \
        f"; the file has {_many(listed, name)}" if index > 0 else \
        f", counted back from its line, but the file lists {_many(before, name)} before it"


def _off_damage(data: bytes) -> str | None:
    """The first line of an OFF file that is wrong: ``OFF``, the counts ``vertices faces edges`` (on the same line
    or the next), then a vertex per line (x y z first) and a face per line (its corner count, then indices from 0)."""
    if isinstance(read := _off_rows(data), str):
        return read
    vertices, faces, body = read
    return _declared_rows(body, [("vertex", vertices, _vertex), ("face", faces, partial(_face, vertices=vertices))])


def _off_rows(data: bytes) -> tuple[int, int, Rows] | str:
    """An OFF file's counts of vertices and faces and its rows of values after them, or what is wrong with its header."""
    rows = [(number, values) for number, values in _rows(line.split(b"#")[0] for line in data.splitlines()) if values]
    if not rows or not rows[0][1][0].endswith(b"OFF"):
        return f"expected OFF on the first line, got {_text(b' '.join(rows[0][1])) if rows else 'only comments'!r}"
    (number, (_, *counts)), body = rows[0], rows[1:]
    if not counts and body:
        (number, counts), body = body[0], body[1:]
    if len(counts) < 2 or not all(count.isdigit() for count in counts[:2]):
        return f"line {number}: expected the counts of vertices and faces, got {repr(_text(b' '.join(counts))) if counts else 'nothing'}"
    return int(counts[0]), int(counts[1]), body


def off_polygons(data: bytes) -> tuple[list[list[float]], list[list[int]]]:
    """A sound OFF file's vertices (x y z) and faces (vertex indices from 0, any number of corners each), which
    :func:`~g2s_core.mesh.load_mesh` reads with this when trimesh fails on a polygon of 5 or more corners."""
    vertices, faces, body = _off_rows(data)
    return ([[float(value) for value in values[:3]] for _, values in body[:vertices]],
            [[int(corner) for corner in values[1:1 + int(values[0])]] for _, values in body[vertices:vertices + faces]])


def _stl_ascii_damage(data: bytes) -> str | None:
    """The first line of an ASCII STL file that is wrong: a word the format does not start a line with, a vertex
    that is not 3 finite numbers, a facet of other than 3 vertices, an ``endsolid`` without its ``solid``, or a
    ``solid`` without its ``endsolid``, a file cut short, which trimesh reads as no triangles (trimesh reads every
    ``vertex`` of a solid as one list of numbers, so one bad line failed the whole file)."""
    corners, solid = 0, False
    for number, (word, *values) in ((number, line) for number, line in _rows(data.splitlines()) if line):
        if (key := word.lower()) not in STL_KEYWORDS:
            problem = f"a line starts with {_text(word)!r} (expected one of {_text(b', '.join(STL_KEYWORDS))})"
        elif key == b"vertex":
            corners += 1
            problem = _not_numbers(values, "vertex coordinate", finite=True) or \
                (f"a vertex of {len(values)} coordinates (expected x y z)" if len(values) != 3 else None)
        else:
            problem = f"a facet of {_many(corners, 'vertex')} (expected 3)" if key == b"endloop" and corners != 3 else \
                "endsolid without a solid before it" if key == b"endsolid" and not solid else None
            corners, solid = 0 if key == b"facet" else corners, {b"solid": True, b"endsolid": False}.get(key, solid)
        if problem:
            return f"line {number}: {problem}"
    return "the file ends inside a solid, without its endsolid line (cut short?)" if solid else None


def _ply_damage(data: bytes) -> str | None:
    """Where a PLY file's data disagrees with its header: a vertex element without x, y or z, an ASCII file's first
    line at fault, or the element a binary file's data runs short in (:func:`_ply_binary`)."""
    if isinstance(read := _ply_header(data), str):
        return read
    elements, body, start, order = read
    vertex = next(((count, [p[-1] for p in properties]) for name, count, properties in elements if name == "vertex"), (0, []))
    if vertex[1] and (missing := [_text(axis) for axis in (b"x", b"y", b"z") if axis not in vertex[1]]):
        return f"the vertex element has no property {', '.join(missing)} (expected x, y and z)"
    if order is None:
        rows = _rows(body.splitlines(), start)
        if problem := _declared_rows(rows, [(name, count, partial(_ply_row, properties=properties, name=name, vertices=vertex[0]))
                                            for name, count, properties in elements]):
            return problem
        extra = [number for number, values in rows[sum(count for _, count, _ in elements):] if values]
        return f"ASCII PLY has {_many(len(extra), 'row')} more than its header declares (from line {extra[0]})" if extra else None
    size = _ply_binary(body, elements, order)  # or where its data runs short
    return size if isinstance(size, str) else f"binary PLY has {len(body) - size} bytes more than its header declares" if len(body) > size else None


def _ply_header(data: bytes) -> tuple[list[tuple[str, int, list[list[bytes]]]], bytes, int, str | None] | str:
    """A PLY file's elements (name, count, properties: ``[TYPE, NAME]`` or ``[list, COUNT_TYPE, ITEM_TYPE, NAME]``), the
    bytes after its header, the line they start on, and the byte order of a binary file (``None``: ASCII); or what is
    wrong with the header."""
    header, found, body = data.partition(b"end_header")
    if not found:
        return "the PLY header has no end_header line"
    elements: list[tuple[str, int, list[list[bytes]]]] = []
    for number, line in _rows(header.splitlines()):
        key, *values = line or [b""]
        if key == b"element" and len(values) == 2 and values[1].isdigit():
            elements.append((_text(values[0]), int(values[1]), []))
        elif key == b"property" and elements and len(values) == (4 if values[:1] == [b"list"] else 2):
            if wrong := next((kind for kind in values[values[0] == b"list":-1] if kind not in PLY_TYPES), None):
                return f"header line {number}: unknown property type {_text(wrong)!r} (expected one of {_text(b', '.join(PLY_TYPES))})"
            elements[-1][2].append(values)
        elif key in (b"element", b"property"):
            return f"header line {number}: expected 'element NAME COUNT' or 'property TYPE NAME', got {_text(b' '.join([key, *values]))!r}"
    order = None if re.search(rb"^format ascii", header, re.MULTILINE) else "big" if b"big_endian" in header else "little"
    return elements, body.partition(b"\n")[2], header.count(b"\n") + 2, order


def _ply_binary(body: bytes, elements: list[tuple[str, int, list[list[bytes]]]], order: str) -> int | str:
    """The bytes a binary PLY's elements take, read row by row where rows hold lists (a face element may mix
    triangles and quads, as Blender writes it); or where the data runs short, or a face of fewer than 3 corners.
    O(rows with lists)."""
    offset = 0
    for name, count, properties in elements:
        if all(p[0] != b"list" for p in properties):  # rows of one size
            row = sum(_ply_size(p[0]) for p in properties)
            if (holds := (len(body) - offset) // row if row else count) < count:
                return f"binary PLY ends early: the header declares {_many(count, name)}, the file holds {holds}"
            offset += count * row
            continue
        for number in range(count):
            corners = None  # the row's first list: a face's vertex indices
            for kind, *types in properties:
                if kind != b"list":
                    offset += _ply_size(kind)
                    continue
                length_size, item_size = _ply_size(types[0]), _ply_size(types[1])
                items = int.from_bytes(body[offset:offset + length_size], order)
                corners = items if corners is None else corners
                offset += length_size + items * item_size
            if offset > len(body):
                return f"binary PLY ends early: the header declares {_many(count, name)}, the file holds {number}"
            if name == "face" and corners < 3:
                return f"face {number} (counted from 0) has {_many(corners, 'corner')} (at least 3 make a face)"
    return offset


def _ply_row(values: list[bytes], properties: list[list[bytes]], name: str, vertices: int) -> str | None:
    """What is wrong with an ASCII PLY row of element ``name``: a value that is not a finite number, its length
    against the header's properties, or a face's corners."""
    if problem := _not_numbers(values, "value", finite=True):
        return problem
    length = 0
    for kind, *_ in properties:
        length += 1 + (int(float(values[length])) if kind == b"list" and length < len(values) else 0)
    if len(values) != length:
        return f"{len(values)} values, the header declares {length} for each {name}"
    return _face(values, vertices) if name == "face" and properties[:1] and properties[0][0] == b"list" else None


def _vertex(values: list[bytes]) -> str | None:
    """What is wrong with an OBJ or OFF vertex's values (x y z, then optional values such as a colour)."""
    return _not_numbers(values, "vertex coordinate", finite=True) or \
        (f"a vertex of {len(values)} coordinates (expected x y z)" if len(values) < 3 else None)


def _face(values: list[bytes], vertices: int) -> str | None:
    """What is wrong with an OFF or PLY face row ``N i1 ... iN`` (indices from 0; OFF may add a colour)."""
    if not values[0].isdigit():
        return f"a face's corner count {_text(values[0])!r} is not a whole number"
    count, corners = int(values[0]), values[1:1 + int(values[0])]
    if count < 3 or len(corners) < count:
        return f"a face of {_many(count, 'corner')}" + (" (at least 3 make a face)" if count < 3 else f" lists {len(corners)}")
    if wrong := next((corner for corner in corners if not corner.isdigit()), None):
        return f"face corner {_text(wrong)!r} is not a vertex index"
    return next((f"a face refers to vertex {index}; the file has {_many(vertices, 'vertex')} (numbered from 0)"
                 for index in map(int, corners) if index >= vertices), None)


def _declared_rows(rows: Rows, elements: list[tuple[str, int, Callable[[list[bytes]], str | None]]]) -> str | None:
    """The first of ``rows`` at fault, taken in turn by ``elements`` (name, count the header declares, check of a
    row), or that there are fewer rows than declared."""
    for name, count, check in elements:
        if len(rows) < count:
            return f"the header declares {_many(count, name)}, the file has {len(rows)}"
        if problem := next((f"line {number}: {p}" for number, values in rows[:count] if (p := check(values))), None):
            return problem
        rows = rows[count:]
    return None


def _not_numbers(values: list[bytes], what: str, finite: bool = False) -> str | None:
    """The first of ``values`` that is not a number (or, when ``finite``, not a finite one), in words."""
    for value in values:
        try:
            number = float(value)
        except ValueError:
            return f"{what} {_text(value)!r} is not a number"
        if finite and not math.isfinite(number):
            return f"{what} {_text(value)!r} is not a finite number"
    return None


def _rows(lines: Iterable[bytes], start: int = 1) -> Rows:
    """Each line's number and whitespace-separated values."""
    return [(number, line.split()) for number, line in enumerate(lines, start)]


def _ply_size(kind: bytes) -> int:
    """Bytes of a PLY scalar type: ``char`` ... ``double``, or ``int8`` ... ``float64``."""
    bits = re.sub(rb"\D", b"", kind)
    return int(bits) // 8 if bits else {b"char": 1, b"uchar": 1, b"short": 2, b"ushort": 2, b"double": 8}.get(kind, 4)


def _many(count: int, name: str) -> str:
    """``1 vertex``, ``2 vertices``, ``0 faces``."""
    return f"{count} {name if count == 1 else {'vertex': 'vertices', 'mesh': 'meshes'}.get(name, f'{name}s')}"


def _text(value: bytes) -> str:
    return value.decode("utf-8", errors="replace")
