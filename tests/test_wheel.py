"""The wheel as a user gets it: built by `make wheel`, installed into a new
virtual environment with nothing else, run from outside the checkout."""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

from tests.conftest import PROJECT, SHARED_DATA

pytestmark = pytest.mark.wheel

# Run in the new environment: where the extension's Recast/Detour libraries
# were loaded from, read from the process's own memory map.
LOADED_LIBRARIES = """
import json, g2s_core, g2s_plugins.recast._recast as extension
libraries = sorted({line.split()[-1] for line in open("/proc/self/maps") if "libRecast" in line or "libDetour" in line})
print(json.dumps({"libraries": libraries, "package": g2s_core.__file__, "extension": extension.__file__}))
"""

API = """
import g2s_core
import g2s_plugins._trees  # the second extension (the flow's shortest-path trees) ships too
import g2s_plugins._slabs  # and the third (the walk test's body slab)
import g2s_plugins._walks  # and the fourth (the walk test's arithmetic round its rays)
result = g2s_core.run("sample:cross_hub", "map_piece", agent={"radius": 0.4})
assert result.structure.number_of_nodes() > 0
assert sum(terminal for _, terminal in result.structure.nodes(data="terminal")) >= 4
written = result.write("api-out", formats="json")
loaded = g2s_core.load_result("api-out")
assert sorted(loaded.structure.nodes) == sorted(result.structure.nodes)
print(len(written))
"""


def missing_from_wheel(names: set[str]) -> list[str]:
    """What an installed g2s reads by path that a wheel holding ``names`` lacks: each preset of configs/ (as
    g2s_core/presets/), every file of the two packages that is not Python (the JSON schemas), the four extensions."""
    needed = {f"g2s_core/presets/{preset.name}" for preset in (PROJECT / "configs").glob("*.yaml")}
    needed |= {path.relative_to(PROJECT).as_posix() for package in ("g2s_core", "g2s_plugins")
               for path in (PROJECT / package).rglob("*")
               if path.is_file() and path.suffix not in (".py", ".pyc", ".so") and "__pycache__" not in path.parts}
    missing = sorted(needed - names)
    for extension in ("g2s_plugins/_trees", "g2s_plugins/_slabs", "g2s_plugins/_walks", "g2s_plugins/recast/_recast"):
        if not any(name.startswith(f"{extension}.") and name.endswith(".so") for name in names):
            missing.append(f"{extension}.*.so")
    return missing


def readme_glibc_problems(wheel_name: str) -> list[str]:
    """Where README.md's set-up misstates the glibc a wheel built here needs (its manylinux tag)."""
    tag = re.search(r"manylinux_(\d+)_(\d+)", wheel_name)
    readme = (PROJECT / "README.md").read_text(encoding="utf-8")
    glibc = f"{tag.group(1)}.{tag.group(2)}"
    problems = [] if f"glibc {glibc}+" in readme else [f"README.md does not say the wheel needs glibc {glibc}+"]
    debian_12 = Path("/etc/debian_version").read_text().startswith("12")
    if debian_12 and f"`{tag.group(0)}` when built on Debian 12" not in readme:
        problems.append(f"README.md does not name {tag.group(0)} as the tag built on Debian 12")
    return problems


def install_wheel(root: Path) -> Path:
    """`make wheel`, then a new venv holding only that wheel and its PyPI dependencies; its bin folder."""
    dist = root / "dist"
    build = subprocess.run(["make", "-s", "wheel", f"WHEEL_DIR={dist}"], cwd=PROJECT, capture_output=True, text=True)
    assert build.returncode == 0, build.stdout + build.stderr
    wheels = sorted(dist.glob("graph2structure-*.whl"))
    assert len(wheels) == 1 and "manylinux" in wheels[0].name, wheels
    assert readme_glibc_problems(wheels[0].name) == []
    with zipfile.ZipFile(wheels[0]) as wheel:
        assert missing_from_wheel(set(wheel.namelist())) == []
    venv = root / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
    # --no-compile: byte-compiling plotly's thousands of modules would double the install time
    install = subprocess.run([str(venv / "bin" / "python"), "-m", "pip", "install", "-q", "--no-compile", str(wheels[0])],
                             capture_output=True, text=True)
    assert install.returncode == 0, install.stderr
    return venv / "bin"


def run_in(bin_dir: Path, cwd: Path, *args: str) -> subprocess.CompletedProcess:
    env = {key: value for key, value in os.environ.items() if key not in ("PYTHONPATH", "VIRTUAL_ENV")}
    env["PATH"] = f"{bin_dir}{os.pathsep}{env.get('PATH', '')}"
    return subprocess.run(args, cwd=cwd, env=env, capture_output=True, text=True)


def test_wheel_installs_and_runs_on_its_own(tmp_path):
    # one test, so that xdist workers never build the wheel twice at once
    bin_dir = install_wheel(tmp_path)
    work = tmp_path / "work"  # outside the checkout: nothing of it is importable from here
    work.mkdir()

    proc = run_in(bin_dir, work, "python", "-c", LOADED_LIBRARIES)
    assert proc.returncode == 0, proc.stderr
    loaded = json.loads(proc.stdout)
    site = bin_dir.parent / "lib"
    assert Path(loaded["package"]).is_relative_to(site) and Path(loaded["extension"]).is_relative_to(site), loaded
    names = [Path(path).name for path in loaded["libraries"]]
    assert any(n.startswith("libRecast") for n in names) and any(n.startswith("libDetour") for n in names), loaded
    for path in loaded["libraries"]:  # the wheel's copies, not /usr/lib's
        assert Path(path).parent.name == "graph2structure.libs" and Path(path).is_relative_to(site), loaded

    version = run_in(bin_dir, work, "g2s", "--version")
    assert version.returncode == 0 and version.stdout.startswith("g2s 0."), version.stdout + version.stderr

    demo = run_in(bin_dir, work, "g2s", "demo")
    assert demo.returncode == 0, demo.stderr
    assert json.loads((work / "g2s-demo" / "structure.json").read_text())["nodes"]
    assert (work / "g2s-demo" / "heatmap.png").is_file() and (work / "g2s-demo" / "report.html").is_file()

    presets = run_in(bin_dir, work, "g2s", "presets")
    assert presets.returncode == 0 and "map_analysis " in presets.stdout, presets.stdout + presets.stderr

    level = SHARED_DATA / "nav_test.obj"
    if level.is_file():
        proc = run_in(bin_dir, work, "g2s", "run", "map_analysis", str(level), "-o", "out", "--json")
        assert proc.returncode == 0, proc.stderr
        summary = json.loads(proc.stdout)
        assert summary["final"]["stage"] == "simplify" and summary["final"]["nodes"] > 0

    api = run_in(bin_dir, work, "python", "-c", API)
    assert api.returncode == 0, api.stderr
    assert int(api.stdout) == 2


EDITABLE = """
import sys
from scikit_build_core.build import build_editable
print(build_editable(sys.argv[1], {"build-dir": sys.argv[2]}))
"""


def test_an_editable_install_uninstalls_without_a_trace(tmp_path):
    """`pip install -e .`, then `pip uninstall graph2structure`: nothing of it stays in site-packages (robust15: an
    empty g2s_core folder stayed, from a copy of the presets that an editable install never reads, and Python then
    imported g2s_core as an empty package)."""
    # the editable wheel pip would build, from the scikit-build-core of this environment (make setup installs it)
    build = subprocess.run([sys.executable, "-c", EDITABLE, str(tmp_path / "dist"), str(tmp_path / "build")],
                           cwd=PROJECT, capture_output=True, text=True)
    assert build.returncode == 0, build.stdout + build.stderr
    wheel = tmp_path / "dist" / build.stdout.split()[-1]
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
    pip = [str(venv / "bin" / "python"), "-m", "pip", "-q"]
    site = next((venv / "lib").glob("python*/site-packages"))
    before = {path.name for path in site.iterdir()}
    install = subprocess.run([*pip, "install", "--no-deps", "--no-index", str(wheel)], capture_output=True, text=True)
    assert install.returncode == 0, install.stderr
    assert "g2s_plugins" in {path.name for path in site.iterdir()}  # the extensions, in site-packages
    remove = subprocess.run([*pip, "uninstall", "-y", "graph2structure"], capture_output=True, text=True)
    assert remove.returncode == 0, remove.stderr
    assert {path.name for path in site.iterdir()} == before
