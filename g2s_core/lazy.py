"""Heavy libraries imported on first use, so that the answers needing none of them come at once.

``import trimesh`` alone takes about a second (it loads scipy.spatial, networkx
and PIL), networkx a fifth of one: ``g2s --version``, ``--help`` and a config
error need neither. A module that uses such a library only inside its functions
binds it with :func:`lazy_module`; the library is imported when one of its
attributes is first looked up. (Annotations, postponed by ``from __future__
import annotations``, never look one up.)
"""

from __future__ import annotations

import importlib
from typing import Any


class _LazyModule:
    def __init__(self, name: str) -> None:
        self._name, self._module = name, None

    def __getattr__(self, attribute: str) -> Any:
        self._module = self._module or importlib.import_module(self._name)
        return getattr(self._module, attribute)


def lazy_module(name: str) -> Any:
    """The module ``name`` (``"networkx"``, ``"g2s_core.api"``), imported when one of its attributes is first used."""
    return _LazyModule(name)
