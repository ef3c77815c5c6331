"""Run configuration: YAML files, ``extends:`` presets, and validation.

A config chooses one plugin per stage (analyzers and evaluators: a list) with its parameters,
plus agent, mesh and output settings. Everything is validated before any work
starts; a problem is reported as one line naming the file, the key path and
what was expected, e.g.::

    my.yaml: terminals.params.k: expected an integer >= 1, got 'ten'
"""

from __future__ import annotations

import copy
import functools
import os
import re
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any, Literal

import yaml
from pydantic import BaseModel, ConfigDict, Field, ValidationError, create_model

from g2s_core.errors import ConfigError
from g2s_core.input_files import MAX_NESTING, nesting_depth, parse_nested, read_text
from g2s_core.messages import _field_at, _nested_model, describe_validation_error, show, show_key
from g2s_core.stages import BY_KEY, PIPELINE


_PACKAGE_DIR = Path(__file__).resolve().parent
PRESETS_DIR = _PACKAGE_DIR / "presets" if (_PACKAGE_DIR / "presets").is_dir() else _PACKAGE_DIR.parent / "configs"
"""The preset configs (``extends: map_analysis``, ``g2s run map_analysis ...``).

The repository keeps them in ``configs/``; a wheel ships that folder as
``g2s_core/presets`` (an install rule in CMakeLists.txt). A source checkout
or an editable install has no ``g2s_core/presets`` and reads ``configs/``.
"""


class _Section(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True, allow_inf_nan=False, strict=True)


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
    clean: bool = Field(False, description="merge close vertices, drop duplicate and zero-area faces, wind each body one way, flip inside-out solids")


class StageConfig(_Section):
    """One stage: the plugin's name and its parameters."""

    plugin: str = Field(description="plugin name, see `g2s plugins`")
    params: dict[str, Any] = Field(default_factory=dict, description="the plugin's parameters")


class KeyedStageConfig(StageConfig):
    """One of a list of plugins (analyzers, evaluators); ``key`` names its values in the outputs (default: the plugin name)."""

    key: str | None = Field(None, description="name of the values in the outputs")


class OutputConfig(_Section):
    """What a run writes."""

    formats: list[str] = Field(default_factory=lambda: ["json", "html"], description="output formats")


class _Run(_Section):
    def record(self) -> dict[str, Any]:
        """The config as plain JSON data, for the outputs (optional stages only when set)."""
        unset = {stage.key for stage in PIPELINE if stage.optional and getattr(self, stage.key) is None}
        # numpy values given through the Python API (np.int64(6), an array for a point) as their Python ones
        return self.model_dump(mode="json", exclude=unset or None, fallback=lambda value: getattr(value, "tolist", lambda: value)())

    def stages_to_run(self) -> tuple[str, ...]:
        """The stage sections that run, in order."""
        keys = [stage.key for stage in PIPELINE]
        return tuple(keys[: keys.index(self.stop_after) + 1])


def _stage_field(key: str) -> tuple[Any, Any]:
    """The config section of a stage: one plugin, or a list of them (analyzers, evaluators)."""
    if BY_KEY[key].many:
        return list[KeyedStageConfig], Field(default_factory=list)
    return StageConfig | None, None


RunConfig = create_model(
    "RunConfig",
    __base__=_Run,
    __doc__="A whole run, as read from YAML (after ``extends:`` is resolved): settings and one section per stage.",
    mesh=(MeshConfig, Field(default_factory=MeshConfig)),
    agent=(AgentConfig, Field(default_factory=AgentConfig)),
    **{stage.key: _stage_field(stage.key) for stage in PIPELINE},
    stop_after=(Literal[tuple(stage.key for stage in PIPELINE)], Field(PIPELINE[-1].key, description="last stage to run")),
    outputs=(OutputConfig, Field(default_factory=OutputConfig)),
)


# --- reading -----------------------------------------------------------------


# values (mappings, lists, scalars) a YAML config may hold: 250,000 points of a `points:` list, 23 s of PyYAML and 0.8 GB
# (500,000 points took 47 s of CPU and 1.5 GB)
MAX_YAML_NODES = 1_000_000


# what PyYAML's scanner passes over before a line break or a token: spaces, then a comment to the end of its line
_SPACES_AND_COMMENT = re.compile("[ ]*(?:#[^\0\r\n\x85\u2028\u2029]*)?")


class _Loader(yaml.SafeLoader):
    """``yaml.SafeLoader`` that stops at :data:`MAX_NESTING` levels as soon as it scans them.

    PyYAML takes seconds per thousand levels of brackets before its composer
    gives up with a RecursionError; this stops a deep document at once.
    """

    def fetch_flow_collection_start(self, token_class: Any) -> None:
        self._check_depth(self.flow_level)
        super().fetch_flow_collection_start(token_class)

    def add_indent(self, column: int) -> bool:
        self._check_depth(len(self.indents))
        return super().add_indent(column)

    def scan_to_next_token(self) -> None:
        """PyYAML's, but a comment passed over in one step where PyYAML's moved a character at a time (a config of one
        comment line of 50 MB took 21 s of CPU); the text is all in ``self.buffer`` (:func:`_parse_yaml` reads text)."""
        while True:  # a byte-order mark at the very start, as PyYAML's, then spaces and a comment
            start = self.pointer
            end = _SPACES_AND_COMMENT.match(self.buffer, start + (self.index == 0 and self.peek() == "\uFEFF")).end()
            self.pointer, self.index = end, self.index + end - start
            self.column += end - start - self.buffer.count("\uFEFF", start, end)  # forward() counts no mark in a column
            if not self.scan_line_break():
                return
            self.allow_simple_key = self.allow_simple_key or not self.flow_level  # a new line allows one in a block

    def compose_node(self, parent: yaml.Node | None, index: Any) -> yaml.Node:
        """The next node, refusing the one past :data:`MAX_YAML_NODES` (a list of 16 million numbers, 96 MB, took
        7.3 GB and 9 minutes to read)."""
        self.nodes_read = getattr(self, "nodes_read", 0) + 1
        if self.nodes_read > MAX_YAML_NODES:
            raise yaml.composer.ComposerError(None, None, f"more than {MAX_YAML_NODES:,} values (a config holds hundreds; "
                                              "long lists of points belong in a points file)", self.peek_event().start_mark)
        return super().compose_node(parent, index)

    def construct_mapping(self, node: yaml.MappingNode, deep: bool = False) -> dict[Any, Any]:
        """A mapping, refusing a key written twice (PyYAML would keep the last silently)."""
        seen: dict[tuple[str, str], yaml.Node] = {}
        for key in (key for key, _ in node.value if isinstance(key, yaml.ScalarNode)):  # before ``<<`` merges
            if (first := seen.setdefault((key.tag, key.value), key)) is not key:
                raise yaml.constructor.ConstructorError(
                    None, None, f"duplicate key {key.value!r} (first at line {first.start_mark.line + 1})", key.start_mark)
        return super().construct_mapping(node, deep)

    def _check_depth(self, depth: int) -> None:
        if depth >= MAX_NESTING:
            raise yaml.scanner.ScannerError(
                None, None, f"nested deeper than {MAX_NESTING} levels of mappings and lists", self.get_mark()
            )


# PyYAML reads 1e-3 and +.5 as text; YAML 1.2, JSON and every other reader of a config (and YAML 1.1, +.5) as numbers
_Loader.add_implicit_resolver("tag:yaml.org,2002:float", re.compile(
    r"^(?:[-+]?(?:[0-9][0-9_]*(?:\.[0-9_]*)?|\.[0-9_]+)[eE][-+]?[0-9]+|[-+]\.[0-9_]+)$"), list("-+.0123456789"))
# numbers that YAML 1.1, which PyYAML follows, and YAML 1.2 read differently: 017 is 15 or 17, 1:30 is 90 or text
_AMBIGUOUS = "tag:g2s,2026:ambiguous-number"
for _first in "-+0123456789":  # ahead of PyYAML's int and float resolvers, with their patterns
    _Loader.yaml_implicit_resolvers[_first].insert(0, (_AMBIGUOUS, re.compile(
        r"^[-+]?(?:0[0-7_]+|[1-9][0-9_]*(?::[0-5]?[0-9])+|[0-9][0-9_]*(?::[0-5]?[0-9])+\.[0-9_]*)$")))


def _ambiguous(loader: yaml.SafeLoader, node: yaml.ScalarNode) -> int:
    """The number both YAML versions read (``007``), else a ConstructorError naming the two readings."""
    if ":" in node.value:
        reading = loader.construct_yaml_float(node) if "." in node.value else loader.construct_yaml_int(node)
        problem = f"{node.value} is {reading:g} in YAML 1.1 (base 60) and text in YAML 1.2; write {reading:g}, or quote it as text"
    elif (octal := loader.construct_yaml_int(node)) == (decimal := int(node.value.replace("_", ""))):
        return octal
    else:
        problem = f"{node.value} is {octal} in YAML 1.1 (octal) and {decimal} in YAML 1.2; write {decimal} (or {octal}) without the leading 0"
    raise yaml.constructor.ConstructorError(None, None, problem, node.start_mark)


_Loader.add_constructor(_AMBIGUOUS, _ambiguous)


def _parse_yaml(text: str, source: str) -> Any:
    """The YAML document ``text``, nested at most :data:`MAX_NESTING` levels (else ConfigError naming ``source``)."""
    return parse_nested(text, lambda t: yaml.load(t, Loader=_Loader), source, ConfigError)


def _key_over_limit(text: str, marks: tuple[Any, ...]) -> bool:
    """Whether one of PyYAML's ``marks`` stands at the start or end of a key of more than YAML's 1,024 characters."""
    word = r"[^\s:{}\[\],]*"
    return any(len(re.search(word + "$", text[:m.index])[0]) + len(re.match(word, text[m.index:])[0]) > 1024 for m in marks if m)


def _read_yaml(path: Path) -> dict[str, Any]:
    text = read_text(path, "config file", ConfigError)
    try:
        data = _parse_yaml(text, str(path))
    except yaml.reader.ReaderError as exc:  # it has no line, only a position ("invalid YAML: not valid YAML")
        line = text.count("\n", 0, exc.position) + 1
        raise ConfigError(f"{path}: line {line}: character U+{exc.character:04X} is not allowed in YAML") from None
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        where = f" at line {mark.line + 1}, column {mark.column + 1}" if mark else ""
        problem = getattr(exc, "problem", None) or "not valid YAML"
        if _key_over_limit(text, (getattr(exc, "context_mark", None), mark)):
            problem = "a key of more than 1,024 characters, YAML's limit on a key (no g2s key is that long)"
        elif problem.startswith("but "):  # "but found another document" says what was expected first
            problem = f"{exc.context} {problem}"
        raise ConfigError(f"{path}: invalid YAML{where}: {problem}") from None
    if data is None:
        return {}
    if not isinstance(data, dict):
        raise ConfigError(f"{path}: expected a mapping of settings at the top level, got {show(data)}")
    return data


def find_config(name: str | Path, base_dir: Path = Path()) -> Path:
    """The config file ``name`` names: a file (relative to ``base_dir``), else a preset.

    ``name`` may leave out ``.yaml``; a file of that name wins over a preset. Where no such file is, the relative path
    ``configs/X.yaml`` names the preset ``X``: the repository keeps its presets in
    ``configs/``, and its docs run them so, from an installed package too.
    When neither matches but ``name`` is there as something other than a
    file (a folder, a FIFO, a device), that path is returned for the reader
    to refuse saying what it is.

    Raises:
        ConfigError: neither a file nor a preset has that name.
    """
    given = base_dir / name
    preset = Path(name).name if Path(name).parent == Path("configs") else name  # configs/X.yaml: the repository's, a wheel's presets
    candidates = [given, base_dir / f"{name}.yaml", PRESETS_DIR / preset, PRESETS_DIR / f"{preset}.yaml"]
    for candidate in candidates:
        if _is_file(candidate):  # not Path.is_file: a name too long for the file system raises
            return candidate
    if os.path.lexists(given):
        return given
    raise ConfigError(f"{name}: no such config file or preset (presets: {', '.join(presets())})")


def presets() -> dict[str, str]:
    """Preset name -> its purpose: the first comment line of the YAML file."""
    purposes = {}
    for path in sorted(PRESETS_DIR.glob("*.yaml")):
        comment = next((line for line in path.read_text(encoding="utf-8").splitlines() if line.startswith("#")), "")
        purposes[path.stem] = comment.lstrip("#").strip()
    return purposes


def _resolve_extends(name: Any, base_dir: Path, source: Path, chain: Sequence[Path] = ()) -> Path:
    if not isinstance(name, str) or not name:
        raise ConfigError(f"{source}: extends: expected a config file or preset name, got {show(name)}")
    try:
        found = find_config(name, base_dir)  # not resolved: messages name the file as the user's paths lead to it
    except ConfigError:
        raise ConfigError(
            f"{source}: extends: no config file or preset named {show(name)} (presets: {', '.join(presets())})"
        ) from None
    # a file named after the preset it extends (my/map_analysis.yaml: extends: map_analysis), itself or through the
    # files of its ``chain`` (map_analysis.yaml: extends: shared.yaml; shared.yaml: extends: map_analysis), can only mean the preset
    preset = PRESETS_DIR / f"{Path(name).stem}.yaml"
    return preset if Path(os.path.realpath(found)) in (*chain, Path(os.path.realpath(source))) and preset.is_file() else found


def _deep_merge(base: dict[str, Any], override: dict[str, Any]) -> dict[str, Any]:
    """``override`` on top of ``base``: mappings merge key by key, anything else replaces.

    A stage section that names another ``plugin`` replaces the section it
    overrides, parameters and all: parameters belong to their plugin, so a
    config that extends a preset and picks another terminal selector does
    not inherit the preset's selector parameters.
    """
    merged = dict(base)
    for key, value in override.items():
        merged[key] = _merged_value(merged.get(key), value)
    return merged


def _merged_value(current: Any, value: Any) -> Any:
    """``value`` on top of ``current``: merged when both are mappings naming the same plugin (or none), else ``value``."""
    same = isinstance(current, dict) and isinstance(value, Mapping) and value.get("plugin", current.get("plugin")) == current.get("plugin")
    return _deep_merge(current, dict(value)) if same else value


def load_raw_config(path: str | Path, sources: list[Path] | None = None) -> dict[str, Any]:
    """Read a YAML config and everything it ``extends:``, merged, unvalidated.

    Every file read is appended to ``sources`` when given. The chain of
    ``extends:`` is followed in a loop: followed by recursion, a chain of
    some 500 configs ran out of Python's stack and was said to be nested too
    deeply.
    """
    layers: list[dict[str, Any]] = []  # the config, then what it extends, ...
    chain: list[Path] = []
    while True:
        path = Path(path)
        resolved = Path(os.path.realpath(path))  # not Path.resolve, which raises RuntimeError on a link to itself
        if resolved in chain:
            raise ConfigError(f"{path}: extends: cycle {' -> '.join(p.name for p in (*chain, resolved))}")
        chain.append(resolved)
        layers.append(_read_yaml(path))
        if sources is not None:
            sources.append(path)
        parent = layers[-1].pop("extends", None)
        if parent is None:
            return functools.reduce(_deep_merge, reversed(layers), {})
        path = _resolve_extends(parent, path.parent, path, chain)


def _merge_extends(data: dict[str, Any], base_dir: Path, source: str | Path, sources: list[Path] | None = None) -> dict[str, Any]:
    """``data`` on top of the config its ``extends:`` names (looked up from ``base_dir``)."""
    parent_name = data.pop("extends", None)
    if parent_name is None:
        return data
    return _deep_merge(load_raw_config(_resolve_extends(parent_name, base_dir, source), sources), data)


def load_config(path: str | Path) -> RunConfig:
    """Read, merge and validate a config file (plugin parameters are validated by the registry)."""
    return parse_config(load_raw_config(path), source=str(path))


def named_files(config: RunConfig) -> list[Path]:
    """Existing files named by the stages' parameters (e.g. a points ``file``).

    They are inputs of the run, which a run never overwrites; any string
    parameter naming an existing file counts, so third-party plugins' files
    are covered without declaring them.
    """
    found: list[Path] = []
    sections = [getattr(config, stage.key) for stage in PIPELINE]
    pending: list[Any] = [e.params for s in sections for e in (s if isinstance(s, list) else [s]) if e is not None]
    while pending:
        value = pending.pop()
        if isinstance(value, (dict, list)):
            pending.extend(value.values() if isinstance(value, dict) else value)
        elif isinstance(value, str) and _is_file(Path(value)):
            found.append(Path(value))
    return found


def _is_file(path: Path) -> bool:
    try:
        return path.is_file()
    except (OSError, ValueError):
        return False


def resolve_config(
    config: str | Path | Mapping[str, Any] | RunConfig,
    overrides: Mapping[str, Any] | None = None,
    overrides_source: str = "override",
    sources: list[Path] | None = None,
) -> tuple[RunConfig, str]:
    """A validated config from a file, a preset name, a mapping or a RunConfig, with overrides.

    Args:
        config: a config file, a preset name (``map_analysis``), a mapping as
            a YAML file would hold (``extends:`` looked up from the working
            folder) or a :class:`RunConfig`.
        overrides: config keys, dotted (``agent.radius``, ``terminals.params.k``,
            ``analyzers.0.key``) or not, and the values that replace theirs
            (mappings merge into the mappings they replace).
        overrides_source: how error messages name an override (``--set``).
        sources: every config file read (the file or preset and what it
            ``extends:``) is appended to it when given: inputs a run never overwrites.

    Returns:
        The config and the name error messages use for it (the file or preset
        name as given).

    Raises:
        ConfigError: no such file or preset (an empty name), an override's key is unknown, or
            the result does not validate.
    """
    if isinstance(config, RunConfig):
        source = "RunConfig"
        if not overrides:
            return config, source
        raw = config.model_dump(mode="json", exclude_unset=True)
    elif isinstance(config, Mapping):
        source = "config mapping"
        if nesting_depth(config, MAX_NESTING) > MAX_NESTING:
            raise ConfigError(f"{source}: nested deeper than {MAX_NESTING} levels of mappings and lists")
        raw = _merge_extends(copy.deepcopy(dict(config)), Path.cwd(), source, sources)
    elif isinstance(config, (str, Path)) and str(config).strip():
        source = str(config)
        raw = load_raw_config(find_config(config), sources=sources)
    else:  # an empty name was the working folder (".: expected a config file, got a folder")
        raise ConfigError("config: expected a config file, a preset name, a mapping or a RunConfig, got "
                          + ("an empty name" if isinstance(config, str) else type(config).__name__))
    for key, value in (overrides or {}).items():
        raw = set_key(raw, key, value, source=f"{overrides_source} {show_key(key)}")
    return parse_config(raw, source=source), source


def parse_assignment(text: str, source: str = "--set") -> tuple[str, Any]:
    """``"agent.radius=0.4"`` -> ``("agent.radius", 0.4)``: the value is read as YAML (``0.4``,
    ``true``, ``null``, ``[json, glb]``, ``text``).

    Raises:
        ConfigError: no ``=``, no key, or a value that is not valid YAML.
    """
    key, equals, value = text.partition("=")
    key = key.strip()
    if not equals or not key:
        raise ConfigError(f"{source} {show(text)}: expected KEY=VALUE, e.g. agent.radius=0.4")
    try:
        return key, _parse_yaml(value, f"{source} {show_key(key)}") if value.strip() else None
    except yaml.YAMLError as exc:
        problem = getattr(exc, "problem", None)
        raise ConfigError(
            f"{source} {show_key(key)}: the value {show(value)} is not valid YAML" + (f" ({problem})" if problem else "")
        ) from None


def set_key(data: dict[str, Any], key: str, value: Any, source: str) -> dict[str, Any]:
    """A copy of the raw config ``data`` with the dotted ``key`` set to ``value``.

    A mapping ``value`` merges into a mapping already there (not a stage
    section naming another plugin, which it replaces, as does a stage's
    ``plugin`` set to another one: ``terminals.plugin=metric`` kept
    ``coverage``'s parameters, refused as unknown to ``metric``); list items are
    addressed by index (``analyzers.0.params``). Keys are checked against
    :class:`RunConfig` down to the plugins' ``params``, which the plugin's own
    model checks later.

    Raises:
        ConfigError: the key is unknown, or indexes past a list's end;
            the message starts with ``source``.
    """
    path = tuple(int(part) if re.fullmatch("[0-9]{1,18}", part) else part for part in key.split("."))  # not "²", 5000 digits
    _check_key(path, source)
    if path[-1] == "plugin" and len(path) > 1 and _field_at(RunConfig, path) is not None:
        path, value = path[:-1], {"plugin": value}
    data = copy.deepcopy(data)
    container: Any = data
    for depth, part in enumerate(path):
        last = depth == len(path) - 1
        if isinstance(container, list):
            if not isinstance(part, int) or part >= len(container):
                raise ConfigError(f"{source}: {'.'.join(map(str, path[:depth]))} has no item {part!r} "
                                  f"(it lists {len(container)})")
        else:
            part = str(part)
        current = container[part] if isinstance(container, list) or part in container else None
        if last:
            container[part] = _merged_value(current, value)
        else:
            if not isinstance(current, (dict, list)):  # a list when indexed: analyzers.0 of a config without analyzers
                current = container[part] = [] if isinstance(path[depth + 1], int) else {}
            container = current
    return data


def _check_key(path: tuple[str | int, ...], source: str) -> None:
    for depth, part in enumerate(path, start=1):
        if isinstance(part, int) or _field_at(RunConfig, path[:depth]) is not None:
            continue
        owner = RunConfig if depth == 1 else _nested_model(_field_at(RunConfig, path[: depth - 1]))
        if owner is None:  # free-form mapping: a plugin's params, checked by the plugin's model
            return
        raise ConfigError(f"{source}: unknown key {show(part)} (expected one of: {', '.join(owner.model_fields)})")


def parse_config(data: dict[str, Any], source: str = "<config>") -> RunConfig:
    """Validate an already merged config mapping."""
    try:
        return RunConfig.model_validate(data)
    except ValidationError as exc:
        raise ConfigError(f"{source}: {describe_validation_error(exc, RunConfig)}") from None
