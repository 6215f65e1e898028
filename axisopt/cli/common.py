"""Shared pieces of the command modules: the argument parser, exit codes, JSON output."""

from __future__ import annotations

import argparse
import json
import math

from ..errors import InputError

# 0 success (solve: proven optimum), 1 a proven negative answer (an infeasible problem, a failed check with
# --fail-on-check), 2 bad input, 3 no proof either way (Bonmin's unproven point, a time limit, a solver
# failure), 130 interrupted.
EXIT_OK, EXIT_NEGATIVE, EXIT_INPUT, EXIT_UNPROVEN, EXIT_INTERRUPTED = 0, 1, 2, 3, 130


def add_html_report(parser, what: str) -> None:
    """The ``--report FILE.html`` option (a self-contained HTML report, needs axisopt[html])."""
    parser.add_argument("--report", metavar="FILE.html",
                        help=f"write {what} as one self-contained HTML file (interactive figures; needs plotly)")


def check_html_report(path) -> None:
    """Refuse a --report target before the work starts: not .html, or plotly missing (one line, exit 2)."""
    if path is None:
        return
    from ..report.html import check_report_path

    check_report_path(path)


def colour_wanted() -> bool:
    """Colour on a terminal (rich installed, NO_COLOR unset); AXISOPT_COLOR=always|never overrides."""
    import os
    import sys

    force = os.environ.get("AXISOPT_COLOR", "").lower()
    if force == "never" or (os.environ.get("NO_COLOR") and force != "always"):
        return False
    try:
        import rich  # noqa: F401
    except ImportError:
        return False
    if force == "always":
        return True
    try:
        return bool(sys.stdout.isatty())
    except (AttributeError, ValueError):
        return False


def show(text: str) -> None:
    """Print a command's text output; on a colour terminal FAIL (and a compare ' !') in red, pass in green,
    the weakest link and binding limits in yellow.  Plain text when piped or redirected."""
    if not colour_wanted():
        print(text)
        return
    import sys

    from rich.console import Console
    from rich.text import Text

    t = Text(text)
    t.highlight_regex(r"\bFAIL\b| !(?=\n|$)|\bNO\b$", "bold red")
    t.highlight_regex(r"(?<=  )pass\b", "green")
    t.highlight_regex(r"<- weakest link|\bBINDING\b", "yellow")
    Console(file=sys.stdout, highlight=False, soft_wrap=True,
            force_terminal=True, color_system="standard").print(t)


def wrote(path, quiet: bool) -> None:
    if not quiet:
        print(f"\nreport written to {path}")


class GuardedStdout:
    """sys.stdout for the length of one command: a closed pipe (``axisopt ... | head``) or a full device
    (``> /dev/full``) does not end the command with a traceback or a wrong exit code.  The command runs to
    its end (its other outputs, e.g. ``--json FILE``, are still written) and keeps its own exit code; output
    to the closed pipe is dropped silently, a full device is reported on stderr in one line."""

    def __init__(self, stream):
        self._s = stream
        self.lost: OSError | None = None

    def _lose(self, exc: OSError) -> None:
        import errno
        import os
        import sys

        self.lost = exc
        try:  # Python's own flush at exit must not fail again on the data still buffered
            os.dup2(os.open(os.devnull, os.O_WRONLY), self._s.fileno())
        except (OSError, ValueError, AttributeError):
            pass
        if exc.errno != errno.EPIPE:
            print(f"error: standard output: {exc.strerror or exc}; output lost", file=sys.stderr)

    def write(self, text: str) -> int:
        if self.lost is None:
            try:
                return self._s.write(text)
            except OSError as exc:
                self._lose(exc)
        return len(text)

    def flush(self) -> None:
        if self.lost is None:
            try:
                self._s.flush()
            except OSError as exc:
                self._lose(exc)

    def __getattr__(self, name):  # fileno, isatty, encoding, ... of the real stream
        return getattr(self._s, name)


class Parser(argparse.ArgumentParser):
    """argparse that reports a usage error as one line (InputError, exit code 2)."""

    def error(self, message):
        raise InputError(f"{self.prog}: {message}")


def json_default(o):
    import numpy as np

    if isinstance(o, np.generic):
        return o.item()
    if isinstance(o, np.ndarray):
        return o.tolist()
    raise TypeError(f"not JSON serialisable: {type(o).__name__}")


def _finite(obj):
    """``obj`` with every NaN or infinite float replaced by None (JSON null: no value, never NaN)."""
    if isinstance(obj, float):
        return obj if math.isfinite(obj) else None
    if isinstance(obj, dict):
        return {k: _finite(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_finite(v) for v in obj]
    if hasattr(obj, "dtype") and hasattr(obj, "tolist"):  # numpy scalars and arrays
        return _finite(obj.tolist())
    return obj


def write_json(obj, target: str) -> None:
    """Write ``obj`` as JSON to a file (atomically: the old file stays whole if writing fails), or to stdout
    when ``target`` is '-'.  A file that cannot be written is an InputError naming it."""
    text = json.dumps(_finite(obj), indent=2, default=json_default, allow_nan=False)
    if target == "-":
        print(text)
        return
    from ..fileio import write_text_atomic

    write_text_atomic(target, text + "\n", what="JSON")
