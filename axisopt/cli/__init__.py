"""Command line: ``axisopt evaluate | solve | diagnose | compare | study | parts | schema | init``.
The only package that prints: one module per command, shared output helpers in :mod:`.common`.

Exit codes: 0 success (solve: a proven optimum), 1 a proven negative answer (an infeasible problem;
a failed check with ``evaluate --fail-on-check``), 2 bad input (one line on stderr naming the file
and key or line), 3 no proof either way (Bonmin's unproven point, a time limit, a solver failure),
130 interrupted.  A closed pipe or a full device on stdout keeps the command's code.
"""

from __future__ import annotations

import argparse
import logging
import sys
import warnings

from ..errors import ImplausibleInput, InputError
from .common import EXIT_INPUT, EXIT_INTERRUPTED, GuardedStdout, Parser, error_line


def build_parser() -> argparse.ArgumentParser:
    from .. import __version__

    p = Parser(prog="axisopt", description="Size and diagnose machine-tool feed axes.")
    p.add_argument("--version", action="version", version=f"axisopt {__version__}")
    sub = p.add_subparsers(dest="command", required=True, parser_class=Parser)

    for register in _commands():
        register(sub)
    return p


def _commands():
    """One module per subcommand, each with ``register(sub)``; they import their heavy parts
    lazily."""
    from . import compare, diagnose, evaluate, init, machine, parts, schema, solve, study

    return [
        evaluate.register,
        solve.register,
        diagnose.register,
        compare.register,
        study.register,
        parts.register,
        schema.register,
        init.register,
        machine.register,
    ]


def _show_progress() -> None:
    """Progress records of the library (logger "axisopt", e.g. a long Bonmin solve) go to a
    terminal's stderr."""
    log = logging.getLogger("axisopt")
    if sys.stderr.isatty() and not log.handlers:
        handler = logging.StreamHandler(sys.stderr)
        handler.setFormatter(logging.Formatter("%(message)s"))
        log.addHandler(handler)
        log.setLevel(logging.INFO)


def _one_output_on_stdout(args) -> None:
    """Two outputs on standard output ('--json - --csv -') would interleave into neither format."""
    from ..fileio import is_stdout
    from .common import OUTPUT_OPTIONS

    taken = [
        o
        for o in OUTPUT_OPTIONS
        if isinstance(getattr(args, o[2:].replace("-", "_"), None), str)
        and is_stdout(getattr(args, o[2:].replace("-", "_")))
    ]
    if len(taken) > 1:
        both = "both" if len(taken) == 2 else "all"
        raise InputError(
            f"{' and '.join(taken)} would {both} write to standard output; give all but one a file "
            "name"
        )


def _warning_lines(other):
    """warnings.showwarning for the CLI: an ImplausibleInput is one 'warning:' line on stderr (file,
    line, key and what is off); any other warning goes to ``other`` (the showwarning in place)."""

    def show(message, category, filename, lineno, file=None, line=None):
        if issubclass(category, ImplausibleInput):
            print(f"warning: {message}", file=sys.stderr)
        else:
            other(message, category, filename, lineno, file, line)

    return show


def main(argv=None) -> int:
    with warnings.catch_warnings():  # the filters and showwarning as they were when main returns
        warnings.simplefilter("always", ImplausibleInput)
        warnings.showwarning = _warning_lines(warnings.showwarning)
        return _main(argv)


def _main(argv) -> int:
    _show_progress()
    saved = sys.stdout
    out = sys.stdout = GuardedStdout(saved)
    try:
        parser = build_parser()
        # `axisopt` alone: the commands and what each does
        if not (sys.argv[1:] if argv is None else argv):
            print(parser.format_help(), end="")
            return 0
        args = parser.parse_args(argv)
        _one_output_on_stdout(args)
        from .outputs import check_outputs

        check_outputs(args)  # every output path before any work: never onto an input
        code = args.func(args)
    except InputError as exc:
        error_line(str(exc))
        code = EXIT_INPUT
    except KeyboardInterrupt:
        print("interrupted", file=sys.stderr)
        code = EXIT_INTERRUPTED
    finally:
        out.flush()
        sys.stdout = saved
    return code


if __name__ == "__main__":
    sys.exit(main())
