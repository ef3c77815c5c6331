"""Run configuration: YAML files, ``extends:`` presets, and validation.

A config chooses one plugin per stage (analyzers: a list) with its parameters,
plus agent, mesh and output settings. Everything is validated before any work
starts; a problem is reported as one line naming the file, the key path and
what was expected, e.g.::

    my.yaml: terminals.params.k: expected an integer >= 1, got 'ten'
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Literal, get_args, get_origin

import annotated_types
import yaml
from pydantic import BaseModel, ConfigDict, Field, ValidationError
from pydantic.fields import FieldInfo

from g2s_core.errors import ConfigError

PRESETS_DIR = Path(__file__).resolve().parent.parent / "configs"
"""The project's preset configs (``extends: map_analysis`` finds them here)."""

STAGES = ("graph", "terminals", "steiner", "roots", "simplify", "analyzers")
"""Config sections of the stages, in pipeline order."""


class _Section(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class AgentConfig(_Section):
    """The agent whose walkable space is extracted."""

    radius: float = Field(0.5, gt=0, description="agent radius, metres")
    height: float = Field(2.0, gt=0, description="agent height (head room needed), metres")
    max_climb: float = Field(0.4, ge=0, description="highest step the agent climbs, metres")
    max_slope: float = Field(45.0, gt=0, lt=90, description="steepest walkable slope, degrees")


class MeshConfig(_Section):
    """How the input mesh is read."""

    up_axis: Literal["y", "z"] = Field("y", description="the file's up axis; z-up files are turned to y-up")
    scale: float = Field(1.0, gt=0, description="factor that converts the file's units to metres")
    clean: bool = Field(False, description="merge close vertices, drop duplicate and zero-area faces (pymeshlab)")


class StageConfig(_Section):
    """One stage: the plugin's name and its parameters."""

    plugin: str = Field(description="plugin name, see `g2s plugins`")
    params: dict[str, Any] = Field(default_factory=dict, description="the plugin's parameters")


class AnalyzerConfig(StageConfig):
    """An analyzer; ``key`` names its values in the outputs (default: the plugin name)."""

    key: str | None = Field(None, description="name of the values in the outputs")


class LoopsConfig(_Section):
    """Loops added back after the Steiner step (see :mod:`g2s_core.loops`)."""

    stretch: float = Field(1.5, ge=1, description="add a path when the structure is more than this many times longer between its ends (inf: the paper's tree)")
    min_gain: float = Field(3.0, ge=0, description="and the structure is longer by more than this, metres")


class OutputConfig(_Section):
    """What a run writes."""

    formats: list[str] = Field(default_factory=lambda: ["json", "html"], description="output formats")


class RunConfig(_Section):
    """A whole run, as read from YAML (after ``extends:`` is resolved)."""

    mesh: MeshConfig = Field(default_factory=MeshConfig)
    agent: AgentConfig = Field(default_factory=AgentConfig)
    graph: StageConfig | None = None
    terminals: StageConfig | None = None
    steiner: StageConfig | None = None
    loops: LoopsConfig | None = Field(None, description="loops kept after the Steiner step (absent: the paper's tree)")
    roots: StageConfig | None = None
    simplify: StageConfig | None = None
    analyzers: list[AnalyzerConfig] = Field(default_factory=list)
    stop_after: Literal["graph", "terminals", "steiner", "roots", "simplify", "analyzers"] = Field(
        "analyzers", description="last stage to run"
    )
    outputs: OutputConfig = Field(default_factory=OutputConfig)

    def record(self) -> dict[str, Any]:
        """The config as plain JSON data, for the outputs (``loops`` only when set)."""
        return self.model_dump(mode="json", exclude={"loops"} if self.loops is None else None)

    def stages_to_run(self) -> tuple[str, ...]:
        """The stage sections that run, in order."""
        return STAGES[: STAGES.index(self.stop_after) + 1]


# --- reading -----------------------------------------------------------------


def _read_yaml(path: Path) -> dict[str, Any]:
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise ConfigError(f"{path}: no such config file") from None
    except OSError as exc:
        raise ConfigError(f"{path}: cannot read config ({exc.strerror})") from None
    try:
        data = yaml.safe_load(text)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        where = f" at line {mark.line + 1}, column {mark.column + 1}" if mark else ""
        problem = getattr(exc, "problem", None) or "not valid YAML"
        raise ConfigError(f"{path}: invalid YAML{where}: {problem}") from None
    if data is None:
        return {}
    if not isinstance(data, dict):
        raise ConfigError(f"{path}: expected a mapping of settings at the top level, got {_show(data)}")
    return data


def _resolve_extends(name: Any, base_dir: Path, source: Path) -> Path:
    if not isinstance(name, str) or not name:
        raise ConfigError(f"{source}: extends: expected a config file or preset name, got {_show(name)}")
    candidates = [base_dir / name, base_dir / f"{name}.yaml", PRESETS_DIR / name, PRESETS_DIR / f"{name}.yaml"]
    for candidate in candidates:
        if candidate.is_file():
            return candidate.resolve()
    presets = ", ".join(sorted(p.stem for p in PRESETS_DIR.glob("*.yaml")))
    raise ConfigError(f"{source}: extends: no config file or preset named {name!r} (presets: {presets})")


def _deep_merge(base: dict[str, Any], override: dict[str, Any]) -> dict[str, Any]:
    """``override`` on top of ``base``: mappings merge key by key, anything else replaces."""
    merged = dict(base)
    for key, value in override.items():
        if isinstance(value, dict) and isinstance(merged.get(key), dict):
            merged[key] = _deep_merge(merged[key], value)
        else:
            merged[key] = value
    return merged


def load_raw_config(path: str | Path, _chain: tuple[Path, ...] = ()) -> dict[str, Any]:
    """Read a YAML config and everything it ``extends:``, merged, unvalidated."""
    path = Path(path)
    resolved = path.resolve()
    if resolved in _chain:
        cycle = " -> ".join(p.name for p in (*_chain, resolved))
        raise ConfigError(f"{path}: extends: cycle {cycle}")
    data = _read_yaml(path)
    parent_name = data.pop("extends", None)
    if parent_name is None:
        return data
    parent_path = _resolve_extends(parent_name, resolved.parent, path)
    return _deep_merge(load_raw_config(parent_path, (*_chain, resolved)), data)


def load_config(path: str | Path) -> RunConfig:
    """Read, merge and validate a config file (plugin parameters are validated by the registry)."""
    return parse_config(load_raw_config(path), source=str(path))


def parse_config(data: dict[str, Any], source: str = "<config>") -> RunConfig:
    """Validate an already merged config mapping."""
    try:
        return RunConfig.model_validate(data)
    except ValidationError as exc:
        raise ConfigError(f"{source}: {describe_validation_error(exc, RunConfig)}") from None


# --- one-line error messages ---------------------------------------------------

_TYPE_NAMES = {int: "an integer", float: "a number", bool: "true or false", str: "a string", dict: "a mapping"}


def _show(value: Any) -> str:
    """A value as the user wrote it in YAML."""
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return repr(value)
    if isinstance(value, dict):
        return "a mapping"
    if isinstance(value, list):
        return "a list"
    return str(value)


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
    if origin is Literal:
        return "one of " + ", ".join(_show(a) for a in args)
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
    limits = []
    for bound in info.metadata:
        for cls, attribute, op in _BOUNDS:
            if isinstance(bound, cls):
                limits.append(f"{op} {getattr(bound, attribute)}")
        if isinstance(bound, annotated_types.MinLen):
            limits.append(f"with at least {bound.min_length} items")
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
    path = ".".join(str(p) for p in ((prefix,) if prefix else ()) + loc) or "(top level)"
    kind = error["type"]
    if kind == "extra_forbidden":
        owner = model if len(loc) == 1 else _nested_model(_field_at(model, loc[:-1]))
        known = ", ".join(owner.model_fields) if owner else ""
        hint = f"expected one of: {known}" if known else "no keys are accepted here"
        return f"{path}: unknown key ({hint})"
    if kind == "missing":
        return f"{path}: required key is missing"
    if kind in {"model_type", "dict_type", "model_attributes_type"}:
        return f"{path}: expected a mapping, got {_show(error.get('input'))}"
    info = _field_at(model, loc)
    if info is not None:
        return f"{path}: expected {describe_field(info)}, got {_show(error.get('input'))}"
    return f"{path}: {error['msg'][0].lower()}{error['msg'][1:]}, got {_show(error.get('input'))}"


def _nested_model(info: FieldInfo | None) -> type[BaseModel] | None:
    if info is None:
        return None
    for candidate in (info.annotation, *get_args(info.annotation)):
        for inner in (candidate, *get_args(candidate)):
            if isinstance(inner, type) and issubclass(inner, BaseModel):
                return inner
    return None
