"""The commands and configs README.md and docs/*.md show, and the settings configs/*.yaml show commented out, are
ones g2s takes: every `g2s ...` line of a code block and every inline `g2s ...` names an existing command, options
that command has, presets that exist, installed formats, stages, executors and evaluators, and `--set` keys and
values its config accepts; every YAML block is a valid config; every `sample:NAME?param=value` is a level an installed
generator makes, and every `--set KEY=VALUE` in prose a setting a preset takes; and, the other way, every command
and option g2s takes is shown. (Links and the files the docs name:
tests/test_doc_links.py; the Python examples: tests/test_python_docs.py, tests/test_architecture.py,
tests/test_batch.py, and docs/outputs.md's and docs/samples.md's here.)"""

from __future__ import annotations

import argparse
import re
import shlex
from pathlib import Path

import pytest
import yaml

from tests.conftest import PROJECT

DOCS = [PROJECT / "README.md", *sorted((PROJECT / "docs").glob("*.md"))]
CONFIGS = sorted((PROJECT / "configs").glob("*.yaml"))
PLACEHOLDER = re.compile(r"^[A-Z][A-Z_]*$|\.\.\.|^\S*[A-Z]{2,}")
"""CONFIG, NAMES, FILE.obj, sample:X?...: words the docs put where the user's own value goes."""


def documented_commands(text: str) -> list[str]:
    """Each `g2s <command> ...` of ``text``: the lines of its code blocks that start with it (a trailing `# comment`
    dropped) and its inline code spans that do (which may run over a line break)."""
    found = []
    for block in re.findall(r"^```[a-z]*\n(.*?)^```", text, flags=re.MULTILINE | re.DOTALL):
        found += [re.sub(r"\s+#\s.*$", "", line).strip() for line in block.splitlines() if line.startswith("g2s ")]
    prose = re.sub(r"^```.*?^```", "", text, flags=re.MULTILINE | re.DOTALL)
    found += [" ".join(span.split()) for span in re.findall(r"`(g2s [^`]+)`", prose)]
    return found


def test_documented_commands_are_found():
    text = "```sh\ng2s run map_piece p.glb -o out   # a piece\n```\nThen `g2s plugins\n--stage levels`, not `g2s:`.\n"
    assert documented_commands(text) == ["g2s run map_piece p.glb -o out", "g2s plugins --stage levels"]


def subcommands() -> tuple[argparse.ArgumentParser, dict[str, argparse.ArgumentParser]]:
    from g2s_core.cli import _parser

    parser, _ = _parser()
    action = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return parser, dict(action.choices)


def value_problems(option: str, value: str, config: str | None) -> list[str]:
    """What is wrong with ``option``'s ``value`` (nothing when it is a placeholder)."""
    from g2s_core.config import parse_assignment, resolve_config
    from g2s_core.pipeline import plan
    from g2s_core.registry import installed

    if PLACEHOLDER.search(value):
        return []
    kinds = {"--format": "outputs", "--executor": "executors", "--evaluate": "evaluators"}
    if option in kinds:
        names = {p.name for p in installed().plugins(kinds[option])}
        return [f"{option} {name}: no such {kinds[option]} plugin" for name in value.split(",") if name not in names]
    if option == "--set" and config is not None:
        key, setting = parse_assignment(value)
        if isinstance(setting, str) and PLACEHOLDER.search(setting):
            return []
        try:
            plan(resolve_config(config, {key: setting}, "--set")[0], installed())
        except Exception as exc:
            return [f"--set {value}: {exc}"]
    return []


def without_optional_marks(word: str) -> str:
    """``word`` without the brackets that mark an optional part of a usage line (``[--workers`` ``N]``); the balanced
    brackets of a YAML value (``play_points=[[1,0,2]]``) stay."""
    while word.startswith("[") and word.count("[") > word.count("]"):
        word = word[1:]
    while word.endswith("]") and word.count("]") > word.count("["):
        word = word[:-1]
    return word


def command_problems(command: str) -> list[str]:
    """What the g2s parser, the presets and the installed plugins do not take in ``command``."""
    from g2s_core.config import presets

    parser, commands = subcommands()
    words = [without_optional_marks(word) for word in shlex.split(command)[1:]]
    while words and words[0].startswith("-"):  # g2s's own options, before the command
        if (option := words.pop(0)) not in parser._option_string_actions:
            return [f"g2s has no option {option}"]
    if not words or PLACEHOLDER.search(words[0]):
        return []
    if words[0] not in commands:
        return [f"no command {words[0]!r}"]
    sub, problems, positionals, index = commands[words[0]], [], [], 1
    while index < len(words):
        word = words[index]
        index += 1
        if not word.startswith("-") or word == "-":
            positionals.append(word)
            continue
        option, _, attached = word.partition("=")
        action = sub._option_string_actions.get(option)
        if action is None:
            problems.append(f"g2s {words[0]} has no option {option}")
            continue
        if action.nargs == 0:
            continue
        value = attached or (words[index] if index < len(words) else "")
        index += 0 if attached else 1
        if action.choices is not None and value not in action.choices and not PLACEHOLDER.search(value):
            problems.append(f"{option} {value}: expected one of {sorted(action.choices)}")
        config = positionals[0] if words[0] == "run" and positionals else "demo" if words[0] == "demo" else None
        if config is not None and not (config in presets() or (PROJECT / config).is_file()):
            config = None
        problems += value_problems(option, value, config)
    if words[0] == "run" and positionals and not PLACEHOLDER.search(positionals[0]):
        config = positionals[0]
        if not config.endswith((".yaml", ".yml")) and config not in presets():
            problems.append(f"no preset {config!r}")
        elif config.startswith("configs/") and not (PROJECT / config).is_file():
            problems.append(f"no file {config}")
    return problems


@pytest.mark.parametrize("doc", DOCS, ids=lambda path: path.name)
def test_documented_g2s_commands_are_ones_g2s_takes(doc: Path):
    problems = [f"`{command}`: {problem}" for command in documented_commands(doc.read_text(encoding="utf-8"))
                for problem in command_problems(command)]
    assert not problems, f"{doc.name}: {problems}"


def test_the_check_finds_what_g2s_refuses():
    assert command_problems("g2s run map_analysis level.obj -o out --set agent.radius=0.4 --format json,glb") == []
    assert command_problems("g2s run map_analysis level.obj -o out --quiet --stage x") == [
        "g2s run has no option --stage"]
    assert command_problems("g2s plugins --stage level") != []
    assert command_problems("g2s run map_analyis level.obj -o out") == ["no preset 'map_analyis'"]
    assert command_problems("g2s run map_piece p.glb -o out --set terminals.params.sample_stepp=0.2") != []
    assert command_problems("g2s batch map_analysis levels/ -o runs --executor dusk --evaluate traffic") != []
    assert command_problems("g2s demo --format json,gbl") != []
    assert command_problems("g2s --verbos run map_analysis level.obj -o out") == ["g2s has no option --verbos"]
    assert command_problems("g2s run map_analysis l.obj -o out --set 'graph.params.play_points=[[1,0,2]]'") == []
    assert command_problems("g2s COMMAND --help") == command_problems("g2s batch CONFIG -o OUTDIR [--workers N]") == []


def commented_settings(text: str) -> list[tuple[int, str, object]]:
    """Each commented-out setting of a config's text (a `#` line holding YAML `key: value`): its line number, its
    dotted key (the settings it is indented under, then its own) and its value."""
    found, parents = [], []  # (indentation, key) of the settings the next lines may be under
    for number, line in enumerate(text.splitlines(), 1):
        setting = re.match(r"^(\s*)(\w+):", line)
        commented = re.match(r"^(\s*)#\s{1,3}(\w+): (.*?)\s*(#.*)?$", line)
        if setting:
            indent = len(setting.group(1))
            parents = [(i, key) for i, key in parents if i < indent] + [(indent, setting.group(2))]
        elif commented and not commented.group(2)[0].isupper():
            indent = len(commented.group(1))  # the `#` stands where the key would
            keys = [key for i, key in parents if i < indent] + [commented.group(2)]
            found.append((number, ".".join(keys), yaml.safe_load(commented.group(3))))
    return found


def test_commented_settings_are_found():
    text = "# A preset.\ngraph:\n  params:\n    method: grid\n    # spacing: null     # metres\n#   terminals: {a: 1}\n"
    assert commented_settings(text) == [(5, "graph.params.spacing", None), (6, "terminals", {"a": 1})]


@pytest.mark.parametrize("config", CONFIGS, ids=lambda path: path.name)
def test_settings_commented_out_in_configs_are_valid(config: Path):
    from g2s_core.config import resolve_config
    from g2s_core.pipeline import plan
    from g2s_core.registry import installed

    problems = []
    for number, key, value in commented_settings(config.read_text(encoding="utf-8")):
        try:
            plan(resolve_config(config, {key: value}, "uncommented")[0], installed())
        except Exception as exc:
            problems.append(f"line {number}: {exc}")
    assert not problems, f"{config.name}: {problems}"


@pytest.mark.parametrize("doc", [doc for doc in DOCS if "```yaml" in doc.read_text(encoding="utf-8")],
                         ids=lambda path: path.name)
def test_documented_config_snippets_are_valid(doc: Path):
    """Each YAML block is a config, or a part of one: a part (no `extends:`) is read over `map_analysis`."""
    from g2s_core.config import resolve_config
    from g2s_core.pipeline import plan
    from g2s_core.registry import installed

    problems = []
    for block in re.findall(r"^```yaml\n(.*?)^```", doc.read_text(encoding="utf-8"), flags=re.MULTILINE | re.DOTALL):
        try:
            plan(resolve_config({"extends": "map_analysis", **yaml.safe_load(block)})[0], installed())
        except Exception as exc:
            problems.append(f"{block.splitlines()[0]} ...: {exc}")
    assert not problems, f"{doc.name}: {problems}"


@pytest.mark.parametrize("doc", ["outputs.md", "samples.md"])
def test_documented_python_reading_results_and_samples_runs(doc: str, tmp_path, monkeypatch):
    """docs/outputs.md's snippets read back a run's `out` folder (structure.json, structure.glb, structure.graphml);
    docs/samples.md's builds and exports a sample: each block runs as written, in order, in the folder of that run."""
    from g2s_core.cli import main

    monkeypatch.chdir(tmp_path)
    assert main(["run", "map_analysis", "sample:cross_hub", "-o", "out", "--format", "json,glb,graphml", "-q"]) == 0
    blocks = re.findall(r"^```python\n(.*?)^```$", (PROJECT / "docs" / doc).read_text(encoding="utf-8"),
                        flags=re.MULTILINE | re.DOTALL)
    assert blocks
    namespace: dict = {}
    for index, block in enumerate(blocks):
        exec(compile(block, f"{doc} block {index + 1}", "exec"), namespace)


SAMPLE_SPEC = re.compile(r"sample:([a-z_]+)(\?[^\s`\"')\]]*)?")
"""A level spec the docs show, `sample:NAME` or `sample:NAME?param=value&...`, up to where its code span or quote
ends."""


def sample_spec_problems(text: str) -> list[str]:
    """What the installed level generators do not take among ``text``'s `sample:` specs: an unknown NAME, an unknown
    parameter or a value of the wrong type. Shell expansions (`seed={0..99}`), ranges (`seed=0..199`) and the example
    generators the docs define themselves (`NAME = "plaza"`) are left out."""
    from urllib.parse import parse_qsl

    from g2s_core.registry import installed

    registry, defined = installed(), set(re.findall(r'^NAME = "(\w+)"', text, flags=re.MULTILINE))
    problems = []
    for match in SAMPLE_SPEC.finditer(text):
        name, query = match.group(1), (match.group(2) or "?")[1:]
        if name in defined or "{" in query or ".." in query:
            continue
        try:
            info = registry.get("levels", name)
            registry.validate_params(info, dict(parse_qsl(query)), key=match.group(0), text=True)
        except Exception as exc:
            problems.append(f"{match.group(0)}: {exc}")
    return problems


def test_the_sample_check_finds_what_g2s_refuses():
    assert sample_spec_problems('`g2s run map_analysis "sample:dungeon?rooms=6&seed=3" -o out`') == []
    assert len(sample_spec_problems("`sample:dungoen` and `sample:dungeon?romos=6` and `sample:maze?cells=x`")) == 3
    assert sample_spec_problems('seeds `sample:dungeon?seed=0..199`, `"sample:maze?seed="{0..9}`') == []


@pytest.mark.parametrize("doc", [doc for doc in DOCS if "sample:" in doc.read_text(encoding="utf-8")],
                         ids=lambda path: path.name)
def test_documented_sample_levels_are_ones_g2s_generates(doc: Path):
    problems = sample_spec_problems(doc.read_text(encoding="utf-8"))
    assert not problems, f"{doc.name}: {problems}"


def inline_set_problems(text: str) -> list[str]:
    """What no preset that runs every stage takes among ``text``'s `--set KEY=VALUE` code spans in prose (those in a
    `g2s ...` command are checked against its config above). A value naming a plugin the text registers itself
    (`"terminals.above" = ...`, the how-to's third-party package) is left out."""
    from g2s_core.config import RunConfig, presets, resolve_config

    last = RunConfig.model_fields["stop_after"].default
    full = [name for name in presets() if resolve_config(name)[0].stop_after == last]
    own = set(re.findall(r'^\s*"\w+\.(\w+)" = ', text, flags=re.MULTILINE))
    prose = re.sub(r"^```.*?^```", "", text, flags=re.MULTILINE | re.DOTALL)
    problems = []
    for span in re.findall(r"`([^`]*--set [^`]*)`", prose):
        if span.startswith("g2s "):
            continue
        for quoted, bare in re.findall(r"--set\s+(?:'([^']*)'|(\S+))", span):
            value = quoted or bare
            if "=" not in value or PLACEHOLDER.search(value.partition("=")[0]) or own & set(re.findall(r"\w+", value)):
                continue
            refusals = [problem for preset in full for problem in value_problems("--set", value, preset)]
            if len(refusals) == len(full):
                problems.append(refusals[0])
    return problems


def test_the_inline_set_check_finds_what_g2s_refuses():
    assert inline_set_problems("`--set terminals.params.best=4` keeps four, `--set KEY=VALUE`") == []
    assert len(inline_set_problems("`--set terminals.params.bestt=4`, `--set 'agent={radius: -1}'`")) == 2
    # graph_only, which stops before the terminals, is no excuse
    assert len(inline_set_problems("`--set terminals.plugin=above`")) == 1
    assert inline_set_problems('```toml\n"terminals.above" = "my.above"\n```\n`--set terminals.plugin=above`') == []


SET_DOCS = [doc for doc in DOCS if doc.name != "errors.md" and "--set " in doc.read_text(encoding="utf-8")]
"""The docs with `--set` examples; docs/errors.md shows refused values on purpose."""


@pytest.mark.parametrize("doc", SET_DOCS, ids=lambda path: path.name)
def test_documented_set_examples_are_settings_g2s_takes(doc: Path):
    problems = inline_set_problems(doc.read_text(encoding="utf-8"))
    assert not problems, f"{doc.name}: {problems}"


STAGE_PARAMETER = re.compile(r"\b(graph|terminals|steiner|loops|roots|simplify)\.params\.(\w+)")
"""A plugin parameter named by its config path, in prose or code: `graph.params.cell_size`."""


def unknown_stage_parameters(text: str) -> list[str]:
    """The ``STAGE.params.KEY`` paths of ``text`` whose KEY no installed plugin of that stage takes."""
    from g2s_core.registry import installed

    registry = installed()
    paths = set(STAGE_PARAMETER.findall(text))
    taken = {stage: {name for info in registry.plugins(stage) for name in info.params_model.model_fields}
             for stage in {stage for stage, _ in paths}}
    return sorted(f"{stage}.params.{key}" for stage, key in paths if key not in taken[stage])


def test_the_parameter_path_check_finds_what_no_plugin_takes():
    assert unknown_stage_parameters("`graph.params.cell_size`, terminals.params.traffic_weight") == []
    assert unknown_stage_parameters("`graph.params.cel_size` and `simplify.params.min_heat`") == [
        "graph.params.cel_size", "simplify.params.min_heat"]


@pytest.mark.parametrize("doc", DOCS, ids=lambda path: path.name)
def test_documented_parameter_paths_are_parameters(doc: Path):
    assert unknown_stage_parameters(doc.read_text(encoding="utf-8")) == []


def undocumented_options(text_of: dict[str, str]) -> list[str]:
    """The commands and options of `g2s --help` and each command's `--help` that no doc shows: g2s's own options and
    commands in README.md (``text_of["README.md"]``), a plugin's command's options in the doc of its kind
    (``text_of["batch.md"]``, tests/test_doc_links.py's REFERENCE). An option counts as shown by any of its spellings
    (`-o` or `--outdir`)."""
    from g2s_core.registry import installed

    parser, commands = subcommands()
    plugged = {info.name for info in installed().plugins("commands")} - {"run", "presets", "plugins", "demo"}
    missing = [f"g2s {name}" for name in commands if name not in plugged and f"g2s {name}" not in text_of["README.md"]]
    for name, command in [("g2s", parser), *commands.items()]:
        text = text_of["batch.md" if name in plugged else "README.md"]
        for action in command._actions:
            spellings = [option for option in action.option_strings if option not in ("-h", "--help")]
            if spellings and not any(re.search(rf"(?<![\w-]){re.escape(option)}(?![\w-])", text) for option in spellings):
                missing.append(f"{name} {'/'.join(spellings)}")
    return missing


def test_the_option_check_finds_what_no_doc_shows():
    shown = {"README.md": "`g2s run x.obj -o out --format json` and `g2s presets`", "batch.md": "`--workers N`"}
    missing = undocumented_options(shown)
    assert "run --set" in missing and "demo --rooms" in missing and "g2s plugins" in missing
    assert "run -o/--outdir" not in missing and "run --format" not in missing and "g2s presets" not in missing
    assert "batch --workers" not in missing and "batch --scheduler" in missing


def test_every_command_and_option_g2s_takes_is_documented():
    """README.md's "Use" shows every command and option of `g2s --help` (docs/batch.md those of `g2s batch`)."""
    text_of = {name: (PROJECT / ("README.md" if name == "README.md" else f"docs/{name}")).read_text(encoding="utf-8")
               for name in ("README.md", "batch.md")}
    assert undocumented_options(text_of) == []


def cut_summaries() -> list[str]:
    """The installed plugins whose summary in `g2s plugins` (its docstring's first line, docs/plugins.md "Writing a
    plugin of your own") stops short of the docstring's first paragraph: a sentence cut at the line's end."""
    import inspect

    from g2s_core.registry import installed
    from g2s_core.stages import STAGES

    return [f"{stage.key} {info.name}: {info.summary!r}" for stage in STAGES for info in installed().plugins(stage.key)
            if " ".join((inspect.getdoc(info.plugin) or "").split("\n\n")[0].split()) != info.summary.strip()]


def test_plugin_summaries_are_whole_sentences():
    assert cut_summaries() == []
