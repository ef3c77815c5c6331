"""What a plugin module is made of: hook markers and the parameter model base.

A plugin is a small module (or any object) registered through the ``g2s``
entry-point group. It declares

* ``NAME``: its name within its stage (``str``),
* ``Params``: a :class:`PluginParams` subclass describing its parameters
  (types, defaults, one-line docs, ranges); omitted means "no parameters",
* exactly one stage hook from :mod:`g2s_core.hookspecs`, marked with
  :data:`hookimpl` (a pipeline stage's plugin may add ``g2s_begin_ahead``).

The module docstring's first line is the plugin's summary in ``g2s plugins``.
"""

from __future__ import annotations

import pluggy
from pydantic import BaseModel, ConfigDict

PROJECT = "g2s"

hookspec = pluggy.HookspecMarker(PROJECT)
hookimpl = pluggy.HookimplMarker(PROJECT)


class PluginParams(BaseModel):
    """Base of every plugin's parameter model.

    Declare each parameter once, as a field with a default and a
    ``Field(description=...)``; the same declaration validates the YAML config
    and produces the ``g2s plugins`` help. Unknown keys are rejected, and so
    are NaN and infinite numbers (a plugin that means to accept them sets
    ``allow_inf_nan=True`` on that field and says so in its description).

    Values are taken as written, as in the config's own sections: ``true``
    and ``'7'`` are not numbers, ``7`` is not a string (an integer is a
    number). YAML has no tuples, so a tuple field says ``Field(strict=False)``
    to take a list; its items stay strict (a tuple inside a list:
    ``list[Annotated[tuple[float, float], Strict(False)]]``). The ``sample:``
    query's values are text, read by pydantic's conversions from text
    (``rooms=5``; ``rooms=abc`` and ``rooms=true`` are refused).
    """

    model_config = ConfigDict(extra="forbid", frozen=True, allow_inf_nan=False, strict=True)
