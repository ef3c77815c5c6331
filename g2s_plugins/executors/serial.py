"""One pair after the other, in the process that runs the batch."""

from __future__ import annotations

from collections.abc import Callable, Iterator, Sequence
from typing import Any

from g2s_core.plugin import hookimpl

NAME = "serial"


@hookimpl
def g2s_execute(function: Callable[[Any], dict[str, Any]], items: Sequence[Any]) -> Iterator[dict[str, Any]]:
    """``function`` on each item in turn."""
    return (function(item) for item in items)
