"""What is wrong with a damaged mesh file, in a user's words, where trimesh's own error misleads.

trimesh reads a binary STL whose size does not match its header as ASCII STL
and finds no triangles ("the mesh is empty"), reports a GLB cut short by the
JSON error of its cut header chunk, and a glTF file whose JSON is broken as a
missing ``model.gltf`` (it then looks for a zip archive). :func:`describe_damage`
is asked only after trimesh failed or found no triangles.
"""

from __future__ import annotations

import json
from pathlib import Path

STL_HEADER, STL_TRIANGLE, GLB_HEADER = 84, 50, 12
"""Bytes of a binary STL's header (80 free bytes, then the triangle count, uint32) and of each of its
triangles; bytes of a GLB's header (``glTF``, the version, then the file's length in bytes, uint32 each)."""


def describe_damage(path: Path) -> str | None:
    """Why the STL, GLB or glTF file ``path`` holds no mesh (it ends before or after its header says, or its
    JSON is broken), in words; ``None`` when none of this is found (or the file cannot be read at all)."""
    try:
        data = path.read_bytes()  # asked only once reading failed: a good file is never read twice
    except OSError:  # the reader's own error says it better
        return None
    suffix, size = path.suffix.lower(), len(data)
    if suffix == ".stl" and size >= STL_HEADER and (not data.startswith(b"solid") or b"\0" in data[:STL_HEADER]):
        count = int.from_bytes(data[80:STL_HEADER], "little")  # ASCII STL starts with "solid", never holds a NUL
        if size < (expected := STL_HEADER + STL_TRIANGLE * count):
            return f"binary STL ends early: the header announces {count} triangles, the file holds {(size - STL_HEADER) // STL_TRIANGLE}"
        if size > expected:
            return f"binary STL has {size - expected} bytes more than the {count} triangles its header announces"
    announced = int.from_bytes(data[8:GLB_HEADER], "little")
    if suffix == ".glb" and size >= GLB_HEADER and data.startswith(b"glTF") and size < announced:
        return f"the GLB file ends early (its header announces {announced} bytes, the file has {size})"
    if suffix == ".gltf":
        try:
            json.loads(data)
        except (ValueError, RecursionError) as exc:  # json.JSONDecodeError; UnicodeDecodeError for bytes that are not UTF-8
            where = f"line {exc.lineno}, column {exc.colno}: {exc.msg}" if isinstance(exc, json.JSONDecodeError) else \
                "nested too deeply" if isinstance(exc, RecursionError) else "not UTF-8 text"
            return f"not valid glTF JSON ({where})"
    return None
