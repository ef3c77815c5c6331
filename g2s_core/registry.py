"""Plugin discovery: the ``g2s`` entry-point group, loaded into a pluggy PluginManager.

Built-in plugins are found exactly as third-party ones are: through the
entry points their distribution declares. An entry point names a plugin (a
module or any object) or a list of them. A plugin's identity is its stage
(the one hook of :mod:`g2s_core.stages` it implements) and its ``NAME``.

A plugin that fails to load is kept aside as broken: ``g2s plugins`` lists
it, and only a run that asks for it (by the entry-point name
``<stage>.<name>``) stops. A plugin that raises or returns a wrong result
fails with :class:`~g2s_core.errors.PluginFailure` naming it and its package.
"""

from __future__ import annotations

import functools
import importlib.metadata
import threading
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import Any

import pluggy
from pydantic import ValidationError

from g2s_core import hookspecs
from g2s_core.errors import ConfigError, G2SError, OutOfMemory, PluginError, PluginFailure, out_of_memory
from g2s_core.messages import describe_validation_error, show
from g2s_core.plugin import PROJECT, PluginParams
from g2s_core.stages import BY_HOOK, BY_KEY, STAGES, Stage

ENTRY_POINT_GROUP = "g2s"


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
    def kind(self) -> Stage:
        """Its row of the stage table."""
        return BY_KEY[self.stage]

    def failure(self, problem: str) -> PluginFailure:
        """The error for this plugin's own fault: ``<Title> plugin 'x' (package 'p') failed: <problem>``."""
        return PluginFailure(f"{self.named} failed: {problem}")

    @property
    def named(self) -> str:
        """``<Title> plugin 'x' (package 'p')``."""
        return f"{self.kind.title} plugin {self.name!r} (package {self.package!r})"


@dataclass(frozen=True)
class BrokenPlugin:
    """An entry point that could not be loaded or registered, and why."""

    package: str
    entry_point: str
    target: str
    reason: str


class Registry:
    """The installed plugins, by stage and name, and the means to call them.

    A registry made by :meth:`from_entry_points` loads an entry point named
    ``<stage>.<anything>`` when that stage's plugins are first asked for, and
    the entry points named otherwise with the first stage asked for: ``g2s
    --help`` loads only the commands (and output writers it names), a config
    error needs no plugin, ``g2s plugins`` and :meth:`broken` load them all (``--stage`` and ``broken(stage)``
    that stage's).
    """

    def __init__(self) -> None:
        self.manager = pluggy.PluginManager(PROJECT)
        self.manager.add_hookspecs(hookspecs)
        self._plugins: dict[tuple[str, str], PluginInfo] = {}
        self._broken: list[tuple[int, BrokenPlugin]] = []  # with the entry point's place among all; a stage's in order
        self._unloaded: dict[str | None, list[tuple[int, str, importlib.metadata.EntryPoint]]] = {}
        self._loading = threading.RLock()  # a stage asked for from two threads is loaded once, by the first

    @classmethod
    def from_entry_points(cls, group: str = ENTRY_POINT_GROUP) -> Registry:
        """The entry points of ``group`` (sorted by package, then name), each loaded when its stage is first asked for."""
        registry = cls()
        def package_of(ep: importlib.metadata.EntryPoint) -> str:  # "?": no distribution, or one whose metadata has no name
            return (ep.dist and ep.dist.name) or "?"
        entries = sorted(importlib.metadata.entry_points(group=group), key=lambda ep: (package_of(ep), ep.name))
        unique = {(package_of(ep), ep.name, ep.value): ep for ep in entries}  # a package found twice
        for order, ((package, _, _), ep) in enumerate(unique.items()):
            stage = ep.name.split(".", 1)[0]
            registry._unloaded.setdefault(stage if stage in BY_KEY else None, []).append((order, package, ep))
        return registry

    def broken(self, stage: str | None = None) -> list[BrokenPlugin]:
        """The entry points named ``<stage>.<anything>`` (every one when ``None``) that could not be loaded or
        registered, in the order of the entry points; only those entry points are loaded."""
        self._load(stage)
        return [broken for _, broken in sorted(self._broken, key=lambda pair: pair[0])
                if stage is None or broken.entry_point.split(".", 1)[0] == stage]

    def _load(self, stage: str | None) -> None:
        """Load the entry points of ``stage`` (of every stage when ``None``) and those named after no stage,
        in the order of the entry points; keep the broken ones aside."""
        keys = [None, *BY_KEY] if stage is None else [None, stage]
        with self._loading:
            pending = sorted(entry for key in keys for entry in self._unloaded.pop(key, []))
            for order, package, ep in pending:
                try:
                    if importlib.metadata.EntryPoint.pattern.match(ep.value) is None:  # ep.load() failed in its words
                        raise PluginError(f"entry point {ep.name!r} of package {package!r}: its value {ep.value!r} is not "
                                          "of the form 'module' or 'module:attribute' (dotted names)")
                    loaded = ep.load()
                    for plugin in loaded if isinstance(loaded, (list, tuple)) else [loaded]:
                        self.register(plugin, package=package, entry_point=ep.name)
                except (Exception, SystemExit) as exc:  # a broken third-party plugin must not stop the others (nor end g2s)
                    reason = str(exc) if isinstance(exc, PluginError) else said(exc)
                    self._broken.append((order, BrokenPlugin(package, ep.name, ep.value, reason)))

    def register(self, plugin: Any, package: str, entry_point: str) -> PluginInfo:
        """Register one plugin object; its stage is the single hook of the stage table it implements."""
        where = f"entry point {entry_point!r} of package {package!r}"
        if self.manager.is_registered(plugin):  # pluggy's ValueError listed every plugin registered, some 4 kB
            other = next(info.entry_point for info in self._plugins.values() if info.plugin is plugin)
            raise PluginError(f"{where}: its plugin is also that of entry point {other!r}; each entry point names a plugin of its own")
        try:
            try:  # under a name unique while it is registered: one made of the names (':' in them too) could be another's
                self.manager.register(plugin, name=str(id(plugin)))
                self.manager.check_pending()
            except (pluggy.PluginValidationError, ValueError) as exc:  # pluggy's words span 3 lines
                raise PluginError(f"{where}: {' / '.join(str(exc).splitlines())}") from exc
            info = self._checked(plugin, package, entry_point, where)
        except PluginError:
            if self.manager.is_registered(plugin):  # left in, its unknown hook failed every later plugin's check_pending
                self.manager.unregister(plugin)
            raise
        self._plugins[(info.stage, info.name)] = info
        return info

    def _checked(self, plugin: Any, package: str, entry_point: str, where: str) -> PluginInfo:
        """The registered ``plugin``'s info once it passes the checks of its stage, else :class:`PluginError`."""
        hooks = sorted(c.name for c in self.manager.get_hookcallers(plugin) or [] if c.name in BY_HOOK)
        if len(hooks) != 1:
            found = ", ".join(hooks) or "none"
            raise PluginError(f"{where}: a plugin implements exactly one stage hook, found {found}")
        stage = BY_HOOK[hooks[0]]
        named = entry_point.split(".", 1)[0]
        if named in BY_KEY and named != stage.key:  # it would be missed by a registry that loaded only its stage
            raise PluginError(f"{where}: the plugin is {'an' if stage.title[0] in 'AEIOU' else 'a'} {stage.title}, whose entry points are named '{stage.key}.<name>'")
        name = getattr(plugin, "NAME", None)
        if not isinstance(name, str) or not name:
            raise PluginError(f"{where}: the plugin has no NAME string")
        params_model = getattr(plugin, "Params", _NoParams)
        if not (isinstance(params_model, type) and issubclass(params_model, PluginParams)):
            raise PluginError(f"{where}: Params must be a g2s_core.plugin.PluginParams subclass")
        undeclared = [a for a in stage.declares if getattr(plugin, a, None) is None]
        if undeclared:
            raise PluginError(f"{where}: {stage.title} plugins declare {', '.join(undeclared)}, this one does not")
        existing = self._plugins.get((stage.key, name))
        if existing is not None:
            raise PluginError(
                f"two plugins provide {stage.title} {name!r}: package {existing.package!r} "
                f"(entry point {existing.entry_point!r}) and package {package!r} (entry point {entry_point!r})"
            )
        doc = (getattr(plugin, "__doc__", None) or "").strip()
        return PluginInfo(stage.key, name, package, entry_point, plugin, params_model, doc.splitlines()[0] if doc else "")

    def plugins(self, stage: str | None = None) -> list[PluginInfo]:
        """Registered plugins in pipeline-stage order, then by name."""
        self._load(stage)
        order = {s.key: i for i, s in enumerate(STAGES)}
        chosen = (p for p in self._plugins.values() if stage is None or p.stage == stage)
        return sorted(chosen, key=lambda p: (order[p.stage], p.name))

    def get(self, stage: str, name: str, key: str | None = None) -> PluginInfo:
        """The plugin ``name`` of ``stage``; a clear error naming the config ``key`` if absent.

        Raises:
            ConfigError: no such plugin is installed.
            PluginFailure: the plugin is installed but failed to load (or another
                package provides a plugin of the same kind and name).
        """
        title = BY_KEY[stage].title
        self._load(stage)
        for _, broken in self._broken:  # also a second plugin of that name: which one is meant is unknown
            if broken.entry_point == f"{stage}.{name}":
                raise PluginFailure(
                    f"{title} plugin {name!r} (package {broken.package!r}) failed to load: {broken.reason}"
                )
        info = self._plugins.get((stage, name))
        if info is not None:
            return info
        installed = ", ".join(p.name for p in self.plugins(stage)) or "none"
        broken = [f"{b.entry_point} of package {b.package!r}" for _, b in self._broken if b.entry_point.startswith(f"{stage}.")]
        also = f"; failed to load: {', '.join(broken)}, see `g2s plugins`" if broken else ""
        where = f"{key}: " if key else ""
        raise ConfigError(f"{where}{title} plugin {show(name)} is not installed (installed: {installed}{also})")

    def validate_params(self, info: PluginInfo, params: dict[str, Any], key: str, text: bool = False) -> PluginParams:
        """The plugin's parameter model built from ``params``; one-line error at ``key``.

        Values are taken as written (strict: ``'7'`` is no number); with ``text`` they are strings to
        convert, as a ``sample:`` query's are (``'7'`` is 7, ``'abc'`` and ``'true'`` are no integers).
        """
        try:
            return info.params_model.model_validate(params, strict=False if text else None)
        except ValidationError as exc:
            raise ConfigError(describe_validation_error(exc, info.params_model, prefix=key)) from None

    def call(self, info: PluginInfo, **kwargs: Any) -> Any:
        """Call ``info``'s hook on that plugin alone and check its result against the stage table.

        A :class:`~g2s_core.errors.G2SError` the plugin raises (bad input it
        found) passes through; any other exception, and a wrong result, becomes
        ``info.failure(...)``. A returned function is wrapped so that its own
        results (and, unless the stage says otherwise, exceptions) are checked the same way; the wrapper
        carries the function's own attributes, each callable one guarded as the function is.
        """
        value = _guarded(info, self._alone(info, info.kind.hook), "raised")(**kwargs)
        problem = info.kind.check(value, kwargs, info.plugin)
        if problem is not None:
            raise info.failure(f"returned {problem}")
        if info.kind.check_each_item is not None:
            return _checked_items(info, value, info.kind.check_each_item)
        each = info.kind.check_each_call
        if each is None or value is None:
            return value
        function = _guarded(info, value, "its function raised") if info.kind.guard_each_call else value

        def checked(*args: Any) -> Any:
            answer = function(*args)
            wrong = each(answer)
            if wrong is not None:
                raise info.failure(f"its function returned {wrong}")
            return answer

        # e.g. a predicate's whole-forest path (g2s_core.simplify)
        checked.__dict__.update({name: _guarded(info, attribute, "its function raised") if callable(attribute) else attribute
                                 for name, attribute in getattr(value, "__dict__", {}).items()})
        return checked

    def begin_ahead(self, info: PluginInfo, **kwargs: Any) -> None:
        """Call ``info``'s ``g2s_begin_ahead`` (:mod:`g2s_core.hookspecs`) if it has one; an exception it raises other
        than a :class:`~g2s_core.errors.G2SError` becomes ``info.failure(...)``, as in :meth:`call`."""
        _guarded(info, self._alone(info, hookspecs.g2s_begin_ahead.__name__), "raised")(**kwargs)

    def _alone(self, info: PluginInfo, hook: str) -> Callable[..., Any]:
        """The caller of ``hook`` with ``info``'s plugin alone."""
        others = [p for p in self.manager.get_plugins() if p is not info.plugin]
        return self.manager.subset_hook_caller(hook, remove_plugins=others)

    def takes(self, info: PluginInfo, argument: str) -> bool:
        """Whether ``info``'s hook implementation takes the named ``argument`` (it may take any subset of them)."""
        caller = getattr(self.manager.hook, info.kind.hook)
        return any(argument in impl.argnames for impl in caller.get_hookimpls() if impl.plugin is info.plugin)


def _guarded(info: PluginInfo, function: Callable[..., Any], what: str) -> Callable[..., Any]:
    """``function`` whose exceptions other than bad input become ``info``'s failure."""

    def call(*args: Any, **kwargs: Any) -> Any:
        try:
            return function(*args, **kwargs)
        except (G2SError, PluginFailure, KeyboardInterrupt, OutOfMemory):
            raise
        except MemoryError as exc:  # the machine's memory or its limit, not the plugin's bug: said where it ran out
            raise out_of_memory(exc, f" in {info.named}") from exc
        except BaseException as exc:  # SystemExit too: sys.exit(0) in a hook ended g2s with exit 0 and nothing written
            raise info.failure(f"{what} {said(exc)}") from exc

    return call


def said(exc: BaseException) -> str:
    """``TYPE: message`` of an exception of a plugin's, in one line of at most about 300 characters (its lines joined
    by ``/``), even when its ``str()`` raises: the rest is in the traceback that ``--verbose`` prints. Memory run out
    is said so (a plugin's import under ``ulimit -v 560000`` failed to load as ``MemoryError: ``)."""
    if isinstance(exc, MemoryError):
        return str(out_of_memory(exc))
    try:
        text = " / ".join(line.strip() for line in str(exc).splitlines() if line.strip())
    except Exception:  # noqa: BLE001 - the plugin's own __str__ failed
        text = "(its message cannot be shown: its str() raised)"
    return f"{type(exc).__name__}: {text if len(text) <= 300 else f'{text[:300]}... ({len(text):,} characters)'}"


def _checked_items(info: PluginInfo, items: Iterator[Any], check: Callable[[Any], str | None]) -> Iterator[Any]:
    """``items`` with each item checked and the exceptions of the iteration made ``info``'s failure;
    closing it closes ``items``."""
    step = _guarded(info, next, "its iterator raised")
    end = object()
    try:
        while (item := step(items, end)) is not end:
            if (wrong := check(item)) is not None:
                raise info.failure(f"its iterator gave {wrong}")
            yield item
    finally:
        getattr(items, "close", lambda: None)()  # a generator's own cleanup (a pool's shutdown) runs now


@functools.cache
def installed() -> Registry:
    """The plugins installed in this environment (entry points are read once per process)."""
    return Registry.from_entry_points()
