"""Command line: ``axisopt evaluate | solve | diagnose | compare | study | parts``.  The only package that prints:
one module per command, shared output helpers in :mod:`.common`.

Exit codes: 0 success, 1 a well-formed question with a negative answer (e.g. an infeasible
problem), 2 bad input (one line on stderr naming the file and key or line).
"""

from __future__ import annotations

import argparse
import sys

from ..errors import InputError
from .common import EXIT_INPUT, EXIT_OK, Parser


def build_parser() -> argparse.ArgumentParser:
    from .. import __version__

    p = Parser(prog="axisopt", description="Size and diagnose machine-tool feed axes.")
    p.add_argument("--version", action="version", version=f"axisopt {__version__}")
    sub = p.add_subparsers(dest="command", required=True, parser_class=Parser)

    for register in _commands():
        register(sub)
    return p


def _commands():
    """One module per subcommand, each with ``register(sub)``; they import their heavy parts lazily."""
    from . import compare, diagnose, evaluate, parts, solve, study

    return [evaluate.register, solve.register, diagnose.register, compare.register, study.register,
            parts.register]


def main(argv=None) -> int:
    try:
        parser = build_parser()
        args = parser.parse_args(argv)
        return args.func(args)
    except InputError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return EXIT_INPUT
    except KeyboardInterrupt:
        print("interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:  # output piped into e.g. `head`: stop quietly
        import os

        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
