"""print the installed level generators (a command with a bug: its function returns no exit code)"""

from g2s_core.plugin import hookimpl
from g2s_core.registry import installed

NAME = "generators"


@hookimpl
def g2s_command(parser):
    def run(args):
        print(", ".join(info.name for info in installed().plugins("levels")))

    return run
