"""write a level of an installed level generator to a mesh file (a third-party command: g2s level)"""

from pathlib import Path

from g2s_core.errors import G2SError
from g2s_core.mesh import SUPPORTED_SUFFIXES, generate_level
from g2s_core.plugin import hookimpl

NAME = "level"


@hookimpl
def g2s_command(parser):
    parser.add_argument("level", help="sample:NAME?param=value&... (see `g2s plugins --stage levels`)")
    parser.add_argument("file", type=Path, help=f"the mesh file to write ({' '.join(SUPPORTED_SUFFIXES)})")

    def run(args):
        if args.file.suffix.lower() not in SUPPORTED_SUFFIXES:
            raise G2SError(f"{args.file}: expected a mesh file name ({', '.join(SUPPORTED_SUFFIXES)})")
        if args.file.exists():
            raise G2SError(f"{args.file}: exists already; choose another file name")
        mesh = generate_level(args.level)
        mesh.export(args.file)
        print(f"wrote {args.file}: {len(mesh.faces)} triangles")
        return 0

    return run
