"""The project's fixed JSON text, written without the standard library's pure-Python indented encoder.

``json.dumps(value, sort_keys=True, indent=1, ensure_ascii=False,
allow_nan=False)`` is the form of ``structure.json`` and ``run.json``
(:func:`g2s_plugins.outputs.structure_json.dumps`). With an indent the
standard library (Python 3.11) cannot use its C encoder and yields every
piece from nested Python generators: 2.6 s of CPU for the 100k-polygon
level's ``structure.json`` (docs/performance.md). :func:`dumps_indented`
gives the same text, character for character, by plain recursion that joins
each container's items once, with the standard library's own C string
escaper and ``int``/``float`` reprs:

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

Cost: O(size of the text), one Python call per container and per scalar
that is not in a list of only ints or only floats.
"""

from __future__ import annotations

import json
import math
from json.encoder import encode_basestring
from typing import Any

__all__ = ["dumps_indented"]

_int_text = int.__repr__
_float_text = float.__repr__


def dumps_indented(value: Any) -> str:
    """``json.dumps(value, sort_keys=True, indent=1, ensure_ascii=False, allow_nan=False)``, the same text.

    Raises what ``json.dumps`` raises for the same value (``TypeError`` for
    what JSON cannot hold, ``ValueError`` for ``nan``/infinities and
    circular references).
    """
    try:
        return _text(value, "\n")
    except RecursionError:
        return _standard(value, "\n")


def _standard(value: Any, newline: str) -> str:
    """The standard library's text of ``value``, its lines indented as at ``newline``'s depth."""
    text = json.dumps(value, sort_keys=True, indent=1, ensure_ascii=False, allow_nan=False)
    return text.replace("\n", newline) if newline != "\n" else text


def _text(value: Any, newline: str) -> str:
    """``value``'s text; ``newline`` is a line break plus the indent of the line ``value`` starts on."""
    kind = type(value)
    if kind is dict:
        return _dict_text(value, newline)
    if kind is list or kind is tuple:
        return _list_text(value, newline)
    if kind is str:
        return encode_basestring(value)
    if kind is float and math.isfinite(value):
        return _float_text(value)
    if kind is int:
        return _int_text(value)
    if value is None:
        return "null"
    if value is True:
        return "true"
    if value is False:
        return "false"
    return _standard(value, newline)


def _dict_text(value: dict, newline: str) -> str:
    if not value:
        return "{}"
    layout = _LAYOUTS.get(tuple(value))
    if layout is None:
        layout = _layout(value)
        if layout is None:  # keys that are not all str: the standard library writes them (or says why not)
            return _standard(value, newline)
    inner = newline + " "
    items = []
    for key, key_text in layout:
        # the scalars of the records inline, without a call each (most of the values of structure.json)
        item = value[key]
        kind = type(item)
        if kind is float and math.isfinite(item):
            text = _float_text(item)
        elif kind is int:
            text = _int_text(item)
        elif kind is str:
            text = encode_basestring(item)
        elif item is None:
            text = "null"
        else:
            text = _text(item, inner)
        items.append(key_text + text)
    return "{" + inner + ("," + inner).join(items) + newline + "}"


_LAYOUTS: dict[tuple, tuple[tuple[str, str], ...]] = {}
"""The keys of a dict (in its own order) -> its keys sorted, each with its text and the ``": "`` after it:
the records of a document repeat a few key sets many times, which are sorted and escaped once."""


def _layout(value: dict) -> tuple[tuple[str, str], ...] | None:
    """``value``'s keys sorted with their texts (remembered for the next dict with the same keys);
    ``None`` when a key is not a ``str``."""
    try:
        keys = sorted(value)
    except TypeError:  # keys of several types
        return None
    if any(type(key) is not str for key in keys):
        return None
    layout = tuple((key, encode_basestring(key) + ": ") for key in keys)
    if len(layout) <= 64 and len(_LAYOUTS) < 4096:  # bounded: records have few keys, plugins' own names too
        _LAYOUTS[tuple(value)] = layout
    return layout


def _list_text(value: list | tuple, newline: str) -> str:
    if not value:
        return "[]"
    inner = newline + " "
    kinds = set(map(type, value))
    if kinds == {int}:
        items = list(map(_int_text, value))
    elif kinds == {float} and all(map(math.isfinite, value)):
        items = list(map(_float_text, value))
    else:
        items = [_text(item, inner) for item in value]
    return "[" + inner + ("," + inner).join(items) + newline + "]"
