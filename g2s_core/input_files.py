"""Reading the user's text files (configs, points files, structure.json) safely.

Every text input goes through :func:`read_text` and :func:`parse_nested`, so
that whatever path a user gives, the answer is one line naming the file:

* a FIFO, a device (``/dev/zero``) or a folder is refused before it is read
  (the file is opened non-blocking, so opening a FIFO never waits for a writer);
  :func:`check_regular_file` does the same for files other libraries read (meshes);
* a file larger than :data:`MAX_TEXT_BYTES` is refused before it is read;
* bytes that are not UTF-8 are refused with the line they are on;
* a document nested deeper than :data:`MAX_NESTING` levels (or holding
  itself through a YAML alias) is refused instead of exhausting the stack.
"""

from __future__ import annotations

import json
import os
import stat
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

from g2s_core.errors import G2SError

MAX_TEXT_BYTES = 256 * 1024 * 1024
"""Largest text input read, bytes (a structure.json of a 10M-triangle level is well below)."""

MAX_NESTING = 100
"""Deepest nesting of mappings and lists a text input may have (g2s's own files use fewer than 10)."""

_KINDS = (
    (stat.S_ISDIR, "a folder"),
    (stat.S_ISFIFO, "a FIFO"),
    (stat.S_ISCHR, "a character device"),
    (stat.S_ISBLK, "a block device"),
    (stat.S_ISSOCK, "a socket"),
)


def read_text(path: str | Path, what: str, error: type[G2SError] = G2SError) -> str:
    """The UTF-8 text of the regular file ``path`` (a leading byte-order mark is dropped).

    Args:
        path: the file.
        what: what the file is, for messages (``"config file"``).
        error: the exception class raised.

    Raises:
        error: the file is missing, not a regular file, unreadable, larger
            than :data:`MAX_TEXT_BYTES`, or not UTF-8; the message starts with ``path``.
    """
    path = Path(path)
    try:
        # non-blocking: opening a FIFO with no writer would otherwise wait forever
        descriptor = os.open(path, os.O_RDONLY | os.O_NONBLOCK)
    except FileNotFoundError:
        raise error(f"{path}: no such {what}") from None
    except (OSError, ValueError) as exc:  # ValueError: a NUL byte in the path (given from Python)
        raise error(f"{path}: cannot read {what} ({getattr(exc, 'strerror', None) or exc})") from None
    try:
        info = os.fstat(descriptor)
        _require_regular(path, info.st_mode, what, error)
        if info.st_size > MAX_TEXT_BYTES:
            raise error(f"{path}: {info.st_size} bytes is too large for a {what} (at most {MAX_TEXT_BYTES})")
        with open(descriptor, "rb", closefd=False) as handle:  # reads up to the limit or the end, by the MiB: read(limit)
            # took 256 MiB of memory at once, and failed with MemoryError under a `ulimit -v` that the run fits in
            data = b"".join(iter(lambda: handle.read(1 << 20) if handle.tell() <= MAX_TEXT_BYTES else b"", b""))
    except OSError as exc:
        raise error(f"{path}: cannot read {what} ({exc.strerror})") from None
    finally:
        os.close(descriptor)
    if len(data) > MAX_TEXT_BYTES:
        raise error(f"{path}: too large for a {what} (at most {MAX_TEXT_BYTES} bytes)")
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = data[: exc.start].count(b"\n") + 1
        raise error(
            f"{path}: line {line}: byte 0x{data[exc.start]:02x} is not UTF-8 (save the {what} as UTF-8 text)"
        ) from None


def given_path(value: Any, what: str, expected: str, error: type[G2SError] = G2SError) -> Path:
    """``value``, an argument of the Python API named ``what``, as a path: a ``str`` or an ``os.PathLike``, not empty
    (``Path("")`` is the working folder, where results were written).

    Raises:
        error: ``what: expected EXPECTED, got TYPE`` (``got an empty name``), not pathlib's ``TypeError``.
    """
    if not isinstance(value, (str, os.PathLike)) or not str(value).strip():
        raise error(f"{what}: expected {expected}, got {type(value).__name__ if not isinstance(value, str) else 'an empty name'}")
    return Path(value)


def check_regular_file(path: str | Path, what: str, error: type[G2SError] = G2SError) -> None:
    """Refuse a path that is missing or not a regular file (a FIFO, a device, a folder) without opening it.

    Raises:
        error: the message starts with ``path`` and says what it is instead.
    """
    try:
        mode = os.stat(path).st_mode
    except FileNotFoundError:
        raise error(f"{path}: no such {what}") from None
    except (OSError, ValueError) as exc:
        raise error(f"{path}: cannot read {what} ({getattr(exc, 'strerror', None) or exc})") from None
    _require_regular(path, mode, what, error)


def _require_regular(path: str | Path, mode: int, what: str, error: type[G2SError]) -> None:
    if not stat.S_ISREG(mode):
        kind = next((name for test, name in _KINDS if test(mode)), "not a regular file")
        raise error(f"{path}: expected a {what}, got {kind}")


def parse_nested(text: str, parse: Callable[[str], Any], source: str, error: type[G2SError] = G2SError) -> Any:
    """``parse(text)`` (``json.loads``, ``yaml.safe_load``), refusing documents nested too deeply.

    The parser's syntax errors (``json.JSONDecodeError``, ``yaml.YAMLError``)
    pass through for the caller to describe with their line and column.

    Raises:
        error: the document is nested deeper than :data:`MAX_NESTING` levels
            or holds itself (a recursive YAML alias), or holds a value Python
            cannot represent (an integer of more than 4300 digits, a date
            such as 2024-13-45).
    """
    try:
        data = parse(text)
    except RecursionError:
        data = None
        depth = MAX_NESTING + 1
    except json.JSONDecodeError:
        raise
    except (ValueError, OverflowError) as exc:  # Python's words for a long integer advise a call of Python's
        why = f"an integer of more than {sys.get_int_max_str_digits()} digits" if "int_max_str_digits" in str(exc) else exc
        raise error(f"{source}: unreadable value ({why})") from None
    else:
        depth = nesting_depth(data, MAX_NESTING)
    if depth > MAX_NESTING:
        raise error(f"{source}: nested deeper than {MAX_NESTING} levels of mappings and lists")
    return data


def nesting_depth(data: Any, limit: int) -> int:
    """Levels of dicts and lists in ``data`` (0 for a scalar), counted up to ``limit + 1``.

    Runs level by level with each shared object visited once per level, so
    YAML alias bombs and self-referencing documents cost little.
    """
    depth = 0
    level = [data] if isinstance(data, (dict, list)) else []
    while level and depth <= limit:
        depth += 1
        children: dict[int, Any] = {}
        for item in level:
            for child in item.values() if isinstance(item, dict) else item:
                if isinstance(child, (dict, list)):
                    children[id(child)] = child
        level = list(children.values())
    return depth
