"""Errors that reach the user as one line at the CLI (exit code 2)."""


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
