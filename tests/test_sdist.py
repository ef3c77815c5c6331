"""The source distribution a user builds (`python -m build --sdist`) holds what `pip install` of it needs to build
and run: the C++ sources and their CMake file, the presets, the JSON schemas; and none of the checkout's venv,
build folders or shared test data."""

from __future__ import annotations

import subprocess
import sys
import tarfile
from pathlib import Path

from tests.conftest import PROJECT

# scikit-build-core's own sdist builder (the one `python -m build --sdist` calls, without its isolated environment)
BUILD_SDIST = "import sys; from scikit_build_core.build import build_sdist; print(build_sdist(sys.argv[1]))"


def test_the_sdist_holds_the_sources_presets_and_schemas_and_nothing_local(tmp_path):
    proc = subprocess.run([sys.executable, "-c", BUILD_SDIST, str(tmp_path)], cwd=PROJECT, capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    with tarfile.open(tmp_path / proc.stdout.strip().splitlines()[-1]) as sdist:
        top, *_ = sdist.getnames()[0].split("/")
        names = {name.removeprefix(f"{top}/") for name in sdist.getnames()}
    needed = {"pyproject.toml", "CMakeLists.txt", "README.md",
              *(path.relative_to(PROJECT).as_posix() for pattern in ("src/*.cpp", "configs/*.yaml", "g2s_plugins/**/*.json",
                                                                     "g2s_core/*.py")
                for path in PROJECT.glob(pattern))}
    assert len(needed) > 30 and needed <= names, sorted(needed - names)
    local = sorted(name for name in names if name.split("/")[0] in (".venv", "build", "dist", "shared", "g2s-demo"))
    assert local == []
