"""Errors that reach the user as one line at the CLI.

:class:`G2SError` and its subclasses are the user's bad input (exit code 2);
:class:`PluginFailure` is a plugin's own bug (exit code 1, as an internal error, in one line naming the plugin and
its package); :class:`OutOfMemory` is the machine's memory or limit (exit code 1, one line saying where it ran out);
anything else is an internal error of g2s (exit code 1).
"""

class G2SError(Exception):
    """Bad input from the user: a mesh, a config or a request that cannot be honoured.

    The message is one line that names the file or key at fault and what was
    expected. The CLI prints it without a traceback and exits with code 2.
    """


class ConfigError(G2SError):
    """A YAML config that is malformed or does not validate."""


class MeshError(G2SError):
    """A mesh file that cannot be read or is not a usable triangle mesh."""


class PluginError(G2SError):
    """A plugin that is missing, duplicated or cannot do what was asked."""


class PluginFailure(Exception):
    """A plugin that failed to load, raised an exception or returned a wrong result.

    Neither the user's input nor g2s is at fault, so this is not a
    :class:`G2SError`: the message names the plugin, its stage and its
    package (whose authors can fix it); the CLI exits with code 1, as for its own bugs (no input of the user's
    can fix it: exit code 2 would tell a script to blame the level or the config).
    """


class OutOfMemory(MemoryError):
    """Memory ran out, said where: neither the user's input nor a bug, but a memory limit (``ulimit -v``) or the
    machine's memory. Python's own MemoryError mostly has no message: a run under a limit ended in ``internal error:
    MemoryError: `` (robust14)."""


def out_of_memory(exc: MemoryError, where: str = "") -> OutOfMemory:
    """``exc`` as running out of memory ``where`` (e.g. `` in Analyzer plugin 'x' (package 'p')``), and under which
    limit; one that says so already, as it is."""
    if isinstance(exc, OutOfMemory):
        return exc
    import resource  # POSIX only, and read only when memory ran out: not at every command's start

    limit = resource.getrlimit(resource.RLIMIT_AS)[0]
    under = "" if limit == resource.RLIM_INFINITY else f" under the process's memory limit of {limit >> 10:,} KB (ulimit -v)"
    return OutOfMemory(f"out of memory{where}{under} ({type(exc).__name__}{f': {exc}' if str(exc) else ''})")
