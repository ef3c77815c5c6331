"""Plugin discovery: the ``g2s`` entry-point group, loaded into a pluggy PluginManager.

Built-in plugins are found exactly as third-party ones are: through the
entry points their distribution declares. A plugin's identity is its stage
(the one stage hook it implements) and its ``NAME``.
"""

from __future__ import annotations

import importlib.metadata
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

import pluggy
from pydantic import ValidationError

from g2s_core import hookspecs
from g2s_core.config import STAGES, describe_field, describe_validation_error
from g2s_core.errors import ConfigError, PluginError
from g2s_core.hookspecs import STAGE_HOOKS, STAGE_TITLES
from g2s_core.plugin import PROJECT, PluginParams

ENTRY_POINT_GROUP = "g2s"

_HOOK_STAGES = {hook: stage for stage, hook in STAGE_HOOKS.items()}


class _NoParams(PluginParams):
    """This plugin takes no parameters."""


@dataclass(frozen=True)
class PluginInfo:
    """One registered plugin.

    Attributes:
        stage: config section of its stage (``graph``, ``terminals``, ...).
        name: its name within the stage.
        package: the distribution that provides it.
        entry_point: the entry point's name.
        plugin: the registered object (usually a module).
        params_model: its :class:`~g2s_core.plugin.PluginParams` subclass.
        summary: one line from its docstring.
    """

    stage: str
    name: str
    package: str
    entry_point: str
    plugin: Any
    params_model: type[PluginParams]
    summary: str

    @property
    def hook_name(self) -> str:
        return STAGE_HOOKS[self.stage]


class Registry:
    """The installed plugins, by stage and name, and the means to call them."""

    def __init__(self) -> None:
        self.manager = pluggy.PluginManager(PROJECT)
        self.manager.add_hookspecs(hookspecs)
        self._plugins: dict[tuple[str, str], PluginInfo] = {}

    @classmethod
    def from_entry_points(cls, group: str = ENTRY_POINT_GROUP) -> Registry:
        """Load every entry point of ``group`` (sorted by package, then name)."""
        registry = cls()
        seen: set[tuple[str, str, str]] = set()
        entries = sorted(
            importlib.metadata.entry_points(group=group),
            key=lambda ep: (ep.dist.name if ep.dist else "", ep.name),
        )
        for ep in entries:
            package = ep.dist.name if ep.dist else "?"
            if (package, ep.name, ep.value) in seen:
                continue
            seen.add((package, ep.name, ep.value))
            try:
                plugin = ep.load()
            except Exception as exc:  # a broken third-party plugin must name itself
                raise PluginError(
                    f"entry point {ep.name!r} ({ep.value}) of package {package!r} failed to load: {exc}"
                ) from exc
            registry.register(plugin, package=package, entry_point=ep.name)
        return registry

    def register(self, plugin: Any, package: str, entry_point: str) -> PluginInfo:
        """Register one plugin object; its stage is the single stage hook it implements."""
        where = f"entry point {entry_point!r} of package {package!r}"
        try:
            self.manager.register(plugin, name=f"{package}:{entry_point}")
            self.manager.check_pending()
        except (pluggy.PluginValidationError, ValueError) as exc:
            raise PluginError(f"{where}: {exc}") from exc
        hooks = sorted(c.name for c in self.manager.get_hookcallers(plugin) or [] if c.name in _HOOK_STAGES)
        if len(hooks) != 1:
            self.manager.unregister(plugin)
            found = ", ".join(hooks) or "none"
            raise PluginError(f"{where}: a plugin implements exactly one stage hook, found {found}")
        stage = _HOOK_STAGES[hooks[0]]
        name = getattr(plugin, "NAME", None)
        if not isinstance(name, str) or not name:
            self.manager.unregister(plugin)
            raise PluginError(f"{where}: the plugin has no NAME string")
        params_model = getattr(plugin, "Params", _NoParams)
        if not (isinstance(params_model, type) and issubclass(params_model, PluginParams)):
            self.manager.unregister(plugin)
            raise PluginError(f"{where}: Params must be a g2s_core.plugin.PluginParams subclass")
        existing = self._plugins.get((stage, name))
        if existing is not None:
            self.manager.unregister(plugin)
            raise PluginError(
                f"two plugins provide {STAGE_TITLES[stage]} {name!r}: package {existing.package!r} "
                f"(entry point {existing.entry_point!r}) and package {package!r} (entry point {entry_point!r})"
            )
        doc = (getattr(plugin, "__doc__", None) or "").strip()
        info = PluginInfo(stage, name, package, entry_point, plugin, params_model, doc.splitlines()[0] if doc else "")
        self._plugins[(stage, name)] = info
        return info

    def plugins(self, stage: str | None = None) -> list[PluginInfo]:
        """Registered plugins in pipeline-stage order, then by name."""
        order = {s: i for i, s in enumerate(STAGES)}
        chosen = (p for p in self._plugins.values() if stage is None or p.stage == stage)
        return sorted(chosen, key=lambda p: (order[p.stage], p.name))

    def get(self, stage: str, name: str, key: str | None = None) -> PluginInfo:
        """The plugin ``name`` of ``stage``; a clear error naming the config ``key`` if absent."""
        info = self._plugins.get((stage, name))
        if info is None:
            installed = ", ".join(p.name for p in self.plugins(stage)) or "none"
            where = f"{key}: " if key else ""
            raise ConfigError(
                f"{where}{STAGE_TITLES[stage]} plugin {name!r} is not installed (installed: {installed})"
            )
        return info

    def validate_params(self, info: PluginInfo, params: dict[str, Any], key: str) -> PluginParams:
        """The plugin's parameter model built from ``params``; one-line error at ``key``."""
        try:
            return info.params_model.model_validate(params)
        except ValidationError as exc:
            raise ConfigError(describe_validation_error(exc, info.params_model, prefix=key)) from None

    def call(self, info: PluginInfo, **kwargs: Any) -> Any:
        """Call ``info``'s stage hook on that plugin alone."""
        others = [p for p in self.manager.get_plugins() if p is not info.plugin]
        caller = self.manager.subset_hook_caller(info.hook_name, remove_plugins=others)
        return caller(**kwargs)


def plugin_parameters(info: PluginInfo) -> Iterable[tuple[str, str, str, str]]:
    """``(name, accepted values, default, description)`` of each parameter, for help output."""
    for name, field in info.params_model.model_fields.items():
        default = "required" if field.is_required() else repr(field.get_default(call_default_factory=True))
        yield name, describe_field(field), default, field.description or ""
