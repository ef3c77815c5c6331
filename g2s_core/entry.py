"""The ``g2s`` console script (``[project.scripts]`` in pyproject.toml).

Loading the command line (:mod:`g2s_core.cli`, with pydantic, pluggy, rich
and YAML) takes about half a second; a Ctrl-C then printed a traceback. This
module, like the package's ``__init__``, imports only the standard library (and
:mod:`g2s_core.result_folder`, which needs no more) and loads the command
line under the command's interrupt handling, so that a Ctrl-C at
any time ends as ``g2s: interrupted``, exit code 130.
"""

import signal
import sys


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
        with interrupts_held(hold=False):
            from g2s_core import cli

            stop_if_interrupted()
            code = cli.main()
    except KeyboardInterrupt:  # cli.main answers it itself once its parser is built
        print("g2s: interrupted", file=sys.stderr)
        code = 130
    # The command is over, its files written or not: a Ctrl-C while the interpreter winds down (1.3 s after a run of
    # 584 polygons) killed it silently with SIGINT after "wrote ..." lines, and its results stood under a status of 130.
    for sig in (signal.SIGINT, signal.SIGTERM):
        signal.signal(sig, signal.SIG_IGN)
    return code
