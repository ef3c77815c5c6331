"""One-line messages for values that fail validation, shared by configs and plugin parameters.

A pydantic ``ValidationError`` becomes ``key.path: expected <what the field
accepts>, got <the value as written in YAML>``; the words for a field come
from its type and bounds (:func:`describe_field`), so a parameter declared
once reads the same in errors and in ``g2s plugins``.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal, get_args, get_origin

import annotated_types
from pydantic import BaseModel, ValidationError
from pydantic.fields import FieldInfo

_TYPE_NAMES = {int: "an integer", float: "a number", bool: "true or false", str: "a string", dict: "a mapping"}


_LONGEST = 60  # characters of a text, and digits of an integer, shown in full: a megabyte of text was one line

# the characters that end a line (str.splitlines), each written as its escape in a message of one line
_LINE_BREAKS = {ord(c): repr(c)[1:-1] for c in "\n\r\v\f\x1c\x1d\x1e\x85\u2028\u2029"}


def one_line(message: str) -> str:
    """``message`` as one line of stderr: a line break in it (a file or folder name may hold one) written as its
    escape, ``\\n``."""
    return message.translate(_LINE_BREAKS)


def show(value: Any) -> str:
    """A value as the user wrote it in YAML, a long text or integer cut short (``'xxx...' (1,000,000 characters)``)."""
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return repr(value) if len(value) <= _LONGEST else f"{value[:_LONGEST] + '...'!r} ({len(value):,} characters)"
    if isinstance(value, int) and len(digits := str(abs(value))) > _LONGEST:
        return f"an integer of {len(digits):,} digits"
    if isinstance(value, dict):
        return "a mapping"
    if isinstance(value, (list, set, bytes)):  # YAML's !!set and !!binary too
        kind, unit = {bytes: ("binary data", "byte"), set: ("a set", "item")}.get(type(value), ("a list", "item"))
        return f"{kind} of {len(value)} {unit}{'s' if len(value) != 1 else ''}"
    return str(value)


def show_key(key: Any) -> str:
    """A key as written, quoted as :func:`show` does when it is long or holds a newline or a control character, which
    would break the message's one line."""
    text = str(key)
    return text if text.isprintable() and len(text) <= _LONGEST else show(text)


def _plural(phrase: str) -> str:
    """``an integer`` -> ``integers``, ``a list of 3 numbers`` -> ``lists of 3 numbers``."""
    noun = phrase.split(" ", 1)[1] if phrase.startswith(("a ", "an ")) else phrase
    head, _, rest = noun.partition(" ")
    return f"{head}s {rest}".strip()


def _describe_type(annotation: Any) -> str:
    origin = get_origin(annotation)
    args = get_args(annotation)
    if annotation in _TYPE_NAMES:
        return _TYPE_NAMES[annotation]
    if origin is Annotated:  # an item's own rules, e.g. Strict(False) on a tuple inside a list
        return _describe_type(args[0])
    if origin is Literal:
        return "one of " + ", ".join(show(a) for a in args)
    if origin in (list, tuple, set, frozenset):
        if origin is tuple and args and args[-1] is not Ellipsis:
            return f"a list of {len(args)} {_plural(_describe_type(args[0]))}"
        return f"a list of {_plural(_describe_type(args[0]))}" if args else "a list"
    if origin is dict:
        return "a mapping"
    if args and type(None) in args:
        rest = [a for a in args if a is not type(None)]
        return " or ".join(_describe_type(a) for a in rest) + " or null"
    if args:
        return " or ".join(_describe_type(a) for a in args)
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return "a mapping"
    return getattr(annotation, "__name__", str(annotation))


_BOUNDS = (
    (annotated_types.Ge, "ge", ">="),
    (annotated_types.Gt, "gt", ">"),
    (annotated_types.Le, "le", "<="),
    (annotated_types.Lt, "lt", "<"),
)


def describe_field(info: FieldInfo) -> str:
    """What a field accepts, in words: ``an integer >= 1``."""
    limits = [f"{op} {getattr(bound, attribute)}" for bound in info.metadata for cls, attribute, op in _BOUNDS
              if isinstance(bound, cls)]
    limits += [f"with at least {b.min_length} item{'s' * (b.min_length > 1)}" for b in info.metadata if isinstance(b, annotated_types.MinLen)]
    return " ".join([_describe_type(info.annotation), " and ".join(limits)]).strip()


def _field_at(model: type[BaseModel], loc: tuple[Any, ...]) -> FieldInfo | None:
    """The FieldInfo that ``loc`` points at inside ``model``, if it is a field."""
    current: Any = model
    info = None
    for part in loc:
        if isinstance(part, int):
            args = [a for a in get_args(info.annotation) if a is not type(None)] if info else []
            current = args[0] if args else None
            continue
        if not (isinstance(current, type) and issubclass(current, BaseModel)) or part not in current.model_fields:
            return None
        info = current.model_fields[part]
        annotation = info.annotation
        nested = [a for a in (annotation, *get_args(annotation)) if isinstance(a, type) and issubclass(a, BaseModel)]
        current = nested[0] if nested else annotation
    return info


def describe_validation_error(exc: ValidationError, model: type[BaseModel], prefix: str = "") -> str:
    """The first error of ``exc`` as ``key.path: expected ..., got ...``."""
    error = exc.errors()[0]
    loc = tuple(p for p in error["loc"] if not (isinstance(p, str) and ("[" in p or p in {"function-after"})))
    kind = error["type"]
    bad_key = kind == "invalid_key" or "[key]" in error["loc"]  # a key YAML read as a number or null
    loc = loc[:-1] if bad_key else loc
    path = ".".join(map(show_key, ((prefix,) if prefix else ()) + loc)) or "(top level)"
    if bad_key:  # pydantic's words: "Keys should be strings", "Input should be a valid string"
        return f"{path}: expected names as keys, got {show(error['input'])}"
    if kind == "extra_forbidden":
        owner = model if len(loc) == 1 else _nested_model(_field_at(model, loc[:-1]))
        known = ", ".join(owner.model_fields) if owner else ""
        hint = f"expected one of: {known}" if known else "no keys are accepted here"
        return f"{path}: unknown key ({hint})"
    if kind == "missing" and loc and isinstance(loc[-1], int):  # a tuple given too few items: the list is wrong
        loc, path = loc[:-1], path.rpartition(".")[0]
    elif kind == "missing":
        return f"{path}: required key is missing"
    if kind in {"model_type", "dict_type", "model_attributes_type"}:
        return f"{path}: expected a mapping, got {show(error.get('input'))}"
    if kind == "finite_number":
        return f"{path}: expected a finite number, got {show(error.get('input'))}"
    if kind == "value_error" and loc:  # a field's own rule beyond its type and bounds (tile_size: 0 or >= 16)
        return f"{path}: {error['ctx']['error']}, got {show(error.get('input'))}"
    if (info := _field_at(model, loc)) is not None:
        return f"{path}: expected {describe_field(info)}, got {show(error.get('input'))}"
    got = "" if isinstance(error.get("input"), dict) else f", got {show(error.get('input'))}"  # a check of the whole mapping
    return f"{path}: {error['msg'][0].lower()}{error['msg'][1:]}{got}"


def _nested_model(info: FieldInfo | None) -> type[BaseModel] | None:
    if info is None:
        return None
    for candidate in (info.annotation, *get_args(info.annotation)):
        for inner in (candidate, *get_args(candidate)):
            if isinstance(inner, type) and issubclass(inner, BaseModel):
                return inner
    return None
