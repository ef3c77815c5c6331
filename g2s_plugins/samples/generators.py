"""The sample levels of :data:`g2s_plugins.samples.levels.SAMPLES` as level-generator plugins.

One plugin per entry of ``SAMPLES`` (the entry point ``levels.samples`` names
the list :data:`GENERATORS`), so a level added there is a generator without
further work. A generator's parameters are its factory's keyword arguments,
declared once in the factory's signature (types and defaults) and validated
by pydantic: ``sample:dungeon?rooms=600&seed=3``.
"""

from __future__ import annotations

import inspect
import typing
from collections.abc import Callable

import trimesh
from pydantic import Field, create_model

from g2s_core.errors import G2SError
from g2s_core.plugin import PluginParams, hookimpl
from g2s_plugins.samples.levels import SAMPLES, SampleLevel


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
        except ValueError as exc:  # the factories check their arguments' ranges
            given = ", ".join(f"{k}={v!r}" for k, v in params.model_dump(exclude_defaults=True).items())
            raise G2SError(f"sample:{self.NAME}{f' with {given}' if given else ''}: {exc}") from None

    def __repr__(self) -> str:
        return f"SampleGenerator({self.NAME!r})"


def _params_model(name: str, factory: Callable[..., SampleLevel]) -> type[PluginParams]:
    hints = typing.get_type_hints(factory)
    fields = {
        parameter.name: (
            hints.get(parameter.name, typing.Any),
            Field(parameter.default, description=f"argument {parameter.name} of {factory.__module__.rsplit('.', 1)[-1]}.{factory.__name__}(); see docs/samples.md"),
        )
        for parameter in inspect.signature(factory).parameters.values()
        if parameter.default is not inspect.Parameter.empty
    }
    return create_model(f"{name}_params", __base__=PluginParams, **fields)


GENERATORS: list[SampleGenerator] = [SampleGenerator(name, factory) for name, factory in SAMPLES.items()]
"""The plugins, one per sample level, in the order of ``SAMPLES``."""
