"""The sample levels of :data:`g2s_plugins.samples.levels.SAMPLES` as level-generator plugins.

One plugin per entry of ``SAMPLES`` (the entry point ``levels.samples`` names
the list :data:`GENERATORS`), so a level added there is a generator without
further work. A generator's parameters are its factory's keyword arguments,
declared once by the factory: types, bounds (``Annotated`` types such as
``PositiveFloat``) and defaults in its signature, meaning and unit in its
docstring's Google-style ``Args:`` section. They are validated by pydantic
(``sample:dungeon?rooms=600&seed=3``) and listed by ``g2s plugins``.
"""

from __future__ import annotations

import inspect
import re
import typing
from collections.abc import Callable
from typing import TYPE_CHECKING

from pydantic import Field, create_model

from g2s_core.errors import G2SError
from g2s_core.plugin import PluginParams, hookimpl
from g2s_plugins.samples.levels import SAMPLES, SampleLevel

if TYPE_CHECKING:
    import trimesh


class SampleGenerator:
    """A level-generator plugin that calls a factory of :mod:`g2s_plugins.samples.levels`."""

    def __init__(self, name: str, factory: Callable[..., SampleLevel]) -> None:
        self.NAME = name
        self.factory = factory
        self.__doc__ = inspect.getdoc(factory) or f"The {name} sample level."
        self.Params = _params_model(name, factory)

    @hookimpl
    def g2s_generate_level(self, params: PluginParams) -> trimesh.Trimesh:
        try:
            return self.factory(**params.model_dump()).mesh
        except ValueError as exc:  # the factories check how their arguments fit together (block < size, ...)
            given = ", ".join(f"{k}={v!r}" for k, v in params.model_dump(exclude_defaults=True).items())
            raise G2SError(f"sample:{self.NAME}{f' with {given}' if given else ''}: {exc}") from None

    def __repr__(self) -> str:
        return f"SampleGenerator({self.NAME!r})"


_ARG = re.compile(r"\*{0,2}(?P<name>\w+)(?: \([^)]*\))?: (?P<text>.*)")
"""An ``Args:`` entry's first line: ``name: text`` or ``name (type): text``."""


def documented_args(function: Callable[..., typing.Any]) -> dict[str, str]:
    """Parameter name -> its entry in the Google-style ``Args:`` section of ``function``'s
    docstring, continuation lines joined; empty when there is no such section.

    The section runs from the ``Args:`` line to the next line indented no deeper than
    it; entries are indented like its first one, their continuation lines deeper.
    """
    lines = (inspect.getdoc(function) or "").splitlines()
    header = next((i for i, line in enumerate(lines) if line.strip() == "Args:"), None)
    if header is None:
        return {}
    depth = _indent(lines[header])
    entries: dict[str, list[str]] = {}
    entry_depth = None
    for line in filter(str.strip, lines[header + 1:]):
        if _indent(line) <= depth:
            break
        entry_depth = entry_depth or _indent(line)
        entry = _ARG.fullmatch(line.strip()) if _indent(line) == entry_depth else None
        if entry:
            entries[entry["name"]] = [entry["text"]]
        elif entries:
            entries[next(reversed(entries))].append(line.strip())
    return {name: " ".join(text) for name, text in entries.items()}


def _indent(line: str) -> int:
    return len(line) - len(line.lstrip())


def _params_model(name: str, factory: Callable[..., SampleLevel]) -> type[PluginParams]:
    """The factory's keyword arguments as fields: type and bounds from its signature,
    description from its ``Args:`` section (tests check that every argument has one);
    a tuple also as a list, as for every plugin's tuple parameters (:class:`PluginParams`)."""
    hints = typing.get_type_hints(factory, include_extras=True)
    described = documented_args(factory)
    fields = {
        parameter.name: (
            hint := hints.get(parameter.name, typing.Any),
            Field(parameter.default, description=described.get(parameter.name, ""),
                  strict=False if typing.get_origin(hint) is tuple else None),
        )
        for parameter in inspect.signature(factory).parameters.values()
        if parameter.default is not inspect.Parameter.empty
    }
    return create_model(f"{name}_params", __base__=PluginParams, **fields)


GENERATORS: list[SampleGenerator] = [SampleGenerator(name, factory) for name, factory in SAMPLES.items()]
"""The plugins, one per sample level, in the order of ``SAMPLES``."""
