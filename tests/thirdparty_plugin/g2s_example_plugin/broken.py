"""A plugin whose module fails to import, to check that it stops only the runs that use it."""

from g2s_example_plugin import no_such_module  # noqa: F401
