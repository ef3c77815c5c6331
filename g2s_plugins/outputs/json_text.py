"""The project's fixed JSON text, written without the standard library's pure-Python indented encoder.

``json.dumps(value, sort_keys=True, indent=1, ensure_ascii=False,
allow_nan=False)`` is the form of ``structure.json`` and ``run.json``
(:func:`g2s_plugins.outputs.structure_json.dumps`). With an indent the
standard library (Python 3.11) cannot use its C encoder and yields every
piece from nested Python generators: 2.6 s of CPU for the 100k-polygon
level's ``structure.json`` (docs/performance.md). :func:`dumps_indented`
gives the same text, character for character, with the standard library's
own C string escaper and ``int``/``float`` reprs, a column at a time:

- The values that sit at the same depth are written together, as one
  column: the 52,000 node records of ``structure.json`` make one column of
  records, their positions one column of 3-lists, whose items make one
  column of 157,000 floats, written by one ``map(float.__repr__, ...)``.
  The records of a column that have the same keys are split into a column
  per key; the items of its lists are written as one column and joined
  back. So Python works once per column and per record, not per value.
- ``str``, ``int``, finite ``float``, ``None``, ``True``, ``False``, and
  ``list``, ``tuple`` and ``dict`` with ``str`` keys (exactly these types,
  no subclasses) are written here, in the standard library's layout: each
  item of a non-empty container on its own line, one more space of indent
  per level, ``","`` between items, ``": "`` after a key, keys sorted,
  ``[]`` and ``{}`` for empty containers.
- Anything else (subclasses such as numpy's float64, non-``str`` keys,
  ``nan`` and infinities, objects JSON cannot hold) is handed, with its
  subtree, to ``json.dumps`` itself, whose text is re-indented to its depth
  (its newlines are all layout: strings escape theirs), so that part is the
  standard library's by construction, errors included.
- A circular reference exhausts the recursion; then the whole value goes to
  ``json.dumps``, which reports it as it always does.

Cost: O(size of the text), one Python call per column and a few per
container; the scalars are written by C loops.
"""

from __future__ import annotations

import json
import math
from collections.abc import Sequence
from itertools import chain, repeat
from json.encoder import encode_basestring
from operator import itemgetter
from typing import Any

from g2s_plugins.outputs.columns import by_groups

__all__ = ["dumps_indented"]

_int_text = int.__repr__
_float_text = float.__repr__
_CONSTANT_TEXTS = {None: "null", True: "true", False: "false"}


def dumps_indented(value: Any) -> str:
    """``json.dumps(value, sort_keys=True, indent=1, ensure_ascii=False, allow_nan=False)``, the same text.

    Raises what ``json.dumps`` raises for the same value (``TypeError`` for
    what JSON cannot hold, ``ValueError`` for ``nan``/infinities and
    circular references).
    """
    try:
        return _texts([value], "\n")[0]
    except RecursionError:
        return _standard(value, "\n")


def _standard(value: Any, newline: str) -> str:
    """The standard library's text of ``value``, its lines indented as at ``newline``'s depth."""
    text = json.dumps(value, sort_keys=True, indent=1, ensure_ascii=False, allow_nan=False)
    return text.replace("\n", newline) if newline != "\n" else text


def _texts(values: Sequence[Any], newline: str) -> list[str]:
    """The text of each of ``values``, a column of values that all start on a line indented as at ``newline``
    (a line break plus the indent); a column of several types (a float or ``None`` ...) is written a type at a time."""
    return by_groups(values, type, lambda kind, rows: _texts_of_kind(kind, rows, newline))


def _texts_of_kind(kind: type, values: Sequence[Any], newline: str) -> list[str]:
    """:func:`_texts` of a column whose values are all of type ``kind``."""
    if kind is float:
        if all(map(math.isfinite, values)):
            return list(map(_float_text, values))
        return [_float_text(v) if math.isfinite(v) else _standard(v, newline) for v in values]  # raises as JSON does
    if kind is int:
        return list(map(_int_text, values))
    if kind is str:
        return list(map(encode_basestring, values))
    if kind is bool or kind is type(None):
        return [_CONSTANT_TEXTS[v] for v in values]
    if kind is list or kind is tuple:
        return _list_texts(values, newline)
    if kind is dict:
        return _dict_texts(values, newline)
    return [_standard(v, newline) for v in values]


def _joined(parts: list[str | list[str]]) -> list[str]:
    """Row by row, the concatenation of ``parts``: a ``str`` is the same in every row, a list of texts gives
    each row its own (all lists as long as each other)."""
    return list(map("".join, zip(*(repeat(part) if type(part) is str else part for part in parts))))


_COLUMNS_UP_TO = 16
"""Lists of one length up to this many items are joined as columns (a point's 3 coordinates, an edge's ends);
longer ones, fewer, one by one."""


def _list_texts(values: Sequence[list | tuple], newline: str) -> list[str]:
    """:func:`_texts` of a column of lists (or tuples): their items are written as one column."""
    inner = newline + " "
    separator = "," + inner
    sizes = list(map(len, values))
    items = _texts(list(chain.from_iterable(values)), inner)
    size = sizes[0]
    if 0 < size <= _COLUMNS_UP_TO and sizes.count(size) == len(sizes):  # points, pairs: joined column-wise
        parts: list[str | list[str]] = ["[" + inner]
        for index in range(size):
            parts += [items[index::size], separator if index < size - 1 else newline + "]"]
        return _joined(parts)
    texts = []
    start = 0
    for size in sizes:
        texts.append("[" + inner + separator.join(items[start:start + size]) + newline + "]" if size else "[]")
        start += size
    return texts


def _dict_texts(values: Sequence[dict], newline: str) -> list[str]:
    """:func:`_texts` of a column of dicts: the dicts with the same keys are written a column per key."""
    inner = newline + " "
    return by_groups(values, tuple, lambda keys, rows: _same_keys_texts(keys, rows, newline, inner))


def _same_keys_texts(keys: tuple, values: Sequence[dict], newline: str, inner: str) -> list[str]:
    """:func:`_texts` of dicts whose keys are ``keys``, in this order."""
    if not keys:
        return ["{}"] * len(values)
    layout = _LAYOUTS.get(keys)
    if layout is None:
        layout = _layout(keys)
        if layout is None:  # keys that are not all str: the standard library writes them (or says why not)
            return [_standard(v, newline) for v in values]
    parts: list[str | list[str]] = []
    for index, (key, key_text) in enumerate(layout):
        before = "{" + inner + key_text if index == 0 else "," + inner + key_text
        parts += [before, _texts(list(map(itemgetter(key), values)), inner)]
    return _joined([*parts, newline + "}"])


_LAYOUTS: dict[tuple, tuple[tuple[str, str], ...]] = {}
"""The keys of a dict (in its own order) -> its keys sorted, each with its text and the ``": "`` after it:
the records of a document repeat a few key sets many times, which are sorted and escaped once."""


def _layout(keys: tuple) -> tuple[tuple[str, str], ...] | None:
    """A dict's ``keys`` sorted with their texts (remembered for the next dict with the same keys);
    ``None`` when a key is not a ``str``."""
    if any(type(key) is not str for key in keys):
        return None
    layout = tuple((key, encode_basestring(key) + ": ") for key in sorted(keys))
    if len(layout) <= 64 and len(_LAYOUTS) < 4096:  # bounded: records have few keys, plugins' own names too
        _LAYOUTS[keys] = layout
    return layout
