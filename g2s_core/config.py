"""Run configuration: YAML files, ``extends:`` presets, and validation.

A config chooses one plugin per stage (analyzers: a list) with its parameters,
plus agent, mesh and output settings. Everything is validated before any work
starts; a problem is reported as one line naming the file, the key path and
what was expected, e.g.::

    my.yaml: terminals.params.k: expected an integer >= 1, got 'ten'
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Literal

import yaml
from pydantic import BaseModel, ConfigDict, Field, ValidationError, create_model

from g2s_core.errors import ConfigError
from g2s_core.messages import describe_validation_error, show
from g2s_core.stages import PIPELINE


PRESETS_DIR = Path(__file__).resolve().parent.parent / "configs"
"""The project's preset configs (``extends: map_analysis`` finds them here)."""


class _Section(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class AgentConfig(_Section):
    """The agent whose walkable space is extracted."""

    model_config = ConfigDict(allow_inf_nan=False)

    radius: float = Field(0.5, gt=0, description="agent radius, metres")
    height: float = Field(2.0, gt=0, description="agent height (head room needed), metres")
    max_climb: float = Field(0.4, ge=0, description="highest step the agent climbs, metres")
    max_slope: float = Field(45.0, gt=0, lt=90, description="steepest walkable slope, degrees")


class MeshConfig(_Section):
    """How the input mesh is read."""

    model_config = ConfigDict(allow_inf_nan=False)

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


class _Run(_Section):
    def record(self) -> dict[str, Any]:
        """The config as plain JSON data, for the outputs (``loops`` only when set)."""
        return self.model_dump(mode="json", exclude={"loops"} if self.loops is None else None)

    def stages_to_run(self) -> tuple[str, ...]:
        """The stage sections that run, in order."""
        keys = [stage.key for stage in PIPELINE]
        return tuple(keys[: keys.index(self.stop_after) + 1])


def _stage_field(key: str) -> tuple[Any, Any]:
    """The config section of a stage: one plugin, or a list of them for analyzers."""
    if key == "analyzers":
        return list[AnalyzerConfig], Field(default_factory=list)
    return StageConfig | None, None


RunConfig = create_model(
    "RunConfig",
    __base__=_Run,
    __doc__="A whole run, as read from YAML (after ``extends:`` is resolved): settings and one section per stage.",
    mesh=(MeshConfig, Field(default_factory=MeshConfig)),
    agent=(AgentConfig, Field(default_factory=AgentConfig)),
    **{stage.key: _stage_field(stage.key) for stage in PIPELINE},
    loops=(LoopsConfig | None, Field(None, description="loops kept after the Steiner step (absent: the paper's tree)")),
    stop_after=(Literal[tuple(stage.key for stage in PIPELINE)], Field(PIPELINE[-1].key, description="last stage to run")),
    outputs=(OutputConfig, Field(default_factory=OutputConfig)),
)


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
        raise ConfigError(f"{path}: expected a mapping of settings at the top level, got {show(data)}")
    return data


def _resolve_extends(name: Any, base_dir: Path, source: Path) -> Path:
    if not isinstance(name, str) or not name:
        raise ConfigError(f"{source}: extends: expected a config file or preset name, got {show(name)}")
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
