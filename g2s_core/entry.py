"""The ``g2s`` console script (``[project.scripts]`` in pyproject.toml).

Loading the command line (:mod:`g2s_core.cli`, with pydantic, pluggy, rich
and YAML) takes about half a second; a Ctrl-C then printed a traceback. This
module, like the package's ``__init__``, imports only the standard library (and
:mod:`g2s_core.result_folder` and :mod:`g2s_core.errors`, which need no more) and loads the command
line under the command's interrupt handling, so that a Ctrl-C at
any time ends as ``g2s: interrupted``, exit code 130.
"""

import os
import signal
import sys
from collections.abc import Iterator
from contextlib import contextmanager

from g2s_core.errors import G2SError


def main() -> int:
    """``g2s`` as installed: :func:`g2s_core.cli.main`, and a Ctrl-C while it loads ends as one later does.

    SIGTERM (``kill``, a job scheduler's stop) is taken as a Ctrl-C: killed outright, a run left its staging
    folder behind, half written."""
    signal.signal(signal.SIGTERM, signal.default_int_handler)
    # a name that the terminal's encoding cannot write (LANG of Latin-1, PYTHONIOENCODING=ascii) ended a finished run
    # in an internal error as it printed the files written
    if hasattr(sys.stdout, "reconfigure"):  # None when g2s was started with its standard output closed
        sys.stdout.reconfigure(errors="backslashreplace")
    try:
        from g2s_core.result_folder import interrupts_held, stop_if_interrupted

        # remembered, as in the command: a Ctrl-C that lands in the import system's weakref callback was printed
        # as "Exception ignored in ..." and lost, and the run went on and wrote its results
        with interrupts_held(hold=False), entry_points_readable():
            from g2s_core import cli

            stop_if_interrupted()
            code = cli.main()
    except KeyboardInterrupt:  # cli.main answers it itself once its parser is built
        print("g2s: interrupted", file=sys.stderr)
        code = 130
    except G2SError as exc:  # the environment's, as the command line loads (cli.main answers its own)
        print(f"g2s: error: {exc}", file=sys.stderr)
        code = 2
    # The command is over, its files written or not: a Ctrl-C while the interpreter winds down (1.3 s after a run of
    # 584 polygons) killed it silently with SIGINT after "wrote ..." lines, and its results stood under a status of 130.
    for sig in (signal.SIGINT, signal.SIGTERM):
        signal.signal(sig, signal.SIG_IGN)
    return code


def broken_entry_points() -> str | None:
    """One line naming an installed distribution whose ``entry_points.txt`` importlib cannot read, if any.

    pydantic reads every distribution's entry points as g2s's first model is defined (its plugins), the plugin
    registry as the command line is built: another package's broken file (a line without ``=``, bytes that are not
    UTF-8, which pip never writes) ended every command, ``g2s --help`` too, in importlib's traceback."""
    import importlib.metadata

    for dist in importlib.metadata.distributions():
        try:
            dist.entry_points
            continue
        except UnicodeDecodeError as exc:
            problem = f"the byte at offset {exc.start} is not UTF-8 text"
        except Exception as exc:  # noqa: BLE001 - importlib's words (a TypeError of its Pair) name neither file nor line
            lines = [line.strip() for line in (dist.read_text("entry_points.txt") or "").splitlines()]
            wrong = [n for n, line in enumerate(lines, 1) if line and line[0] not in "#;[" and "=" not in line]
            problem = f"line {wrong[0]} is not 'name = value'" if wrong else f"{type(exc).__name__}: {exc}"
        return (f"installed package {dist.name!r} (in {dist.locate_file('')}): its entry_points.txt cannot be read: "
                f"{problem} (every package's entry points are read as g2s starts; repair or uninstall that package)")
    return None


@contextmanager
def entry_points_readable() -> Iterator[None]:
    """A block importing the command line or the Python API's libraries (networkx reads every installed package's
    entry points for its backends as it loads, pydantic for its plugins): a failure that another package's unreadable
    ``entry_points.txt`` caused is raised as a :class:`~g2s_core.errors.G2SError` naming that package, not in
    importlib's traceback; one that networkx raises for its settings in the environment (``NETWORKX_BACKEND_PRIORITY``
    naming a backend not installed: a ``ValueError``, exit 1 as an internal error) naming them.
    """
    try:
        yield
    except Exception as exc:
        settings = ", ".join(f"{name}={value!r}" for name, value in sorted(os.environ.items()) if name.startswith("NETWORKX_"))
        if not (broken := broken_entry_points() or isinstance(exc, ValueError) and settings and f"{settings}: networkx "
                f"refused the environment's setting as it loaded ({exc}); unset it or give it a value networkx accepts"):
            raise
        raise G2SError(broken) from None
