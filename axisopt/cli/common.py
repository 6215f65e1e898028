"""Shared pieces of the command modules: the argument parser, exit codes, JSON output."""

from __future__ import annotations

import argparse
import json
import math

from ..errors import InputError

# 0 success (solve: proven optimum), 1 a proven negative answer (an infeasible problem, a failed
# check with
# --fail-on-check), 2 bad input, 3 no proof either way (Bonmin's unproven point, a time limit, a
# solver failure), 130 interrupted.
EXIT_OK, EXIT_NEGATIVE, EXIT_INPUT, EXIT_UNPROVEN, EXIT_INTERRUPTED = 0, 1, 2, 3, 130


def add_html_report(parser, what: str) -> None:
    """The ``--report FILE.html`` option (a self-contained HTML report) and its ``--plotly``
    choice."""
    parser.add_argument(
        "--report",
        metavar="FILE.html",
        help=f"write {what} as one self-contained HTML file (static SVG figures: offline, small)",
    )
    parser.add_argument("--plotly", choices=("no", "inline", "cdn"), default="no", help=PLOTLY_HELP)


PLOTLY_HELP = (
    "with --report: 'no' (default) draws static SVG figures (no plotly needed, works offline, a "
    "few hundred kB); interactive plotly figures (zoom, hover; needs axisopt[html]) with plotly.js "
    "'inline' (about 5 MB, works offline) or from the plotly 'cdn' (a small file that needs the "
    "network)"
)


def check_html_report(path, plotly: str = "no") -> None:
    """Refuse a --report target before the work starts: not .html, or plotly missing for interactive
    figures (one line, exit 2)."""
    if path is None:
        return
    from ..report.html import check_report_path

    check_report_path(path, interactive=plotly != "no")


def colour_wanted() -> bool:
    """Colour on a terminal (rich installed, NO_COLOR unset); AXISOPT_COLOR=always|never
    overrides."""
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
    """Print a command's text output; on a colour terminal FAIL (and a compare ' !') in red, pass in
    green, the weakest link and binding limits in yellow.  Plain text when piped or redirected."""
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
    Console(
        file=sys.stdout,
        highlight=False,
        soft_wrap=True,
        force_terminal=True,
        color_system="standard",
    ).print(t)


def stdout_taken(*targets) -> bool:
    """True when one of the output paths is standard output ('-' or /dev/stdout): the command's text
    is then not printed, so that stdout holds only that output."""
    from ..fileio import is_stdout

    return any(t is not None and t != "" and is_stdout(t) for t in targets)


MAX_ERROR_CHARS = 400


def one_line(text: str) -> str:
    """An error message as one printable line: line breaks and other control characters shown
    escaped (``\\n``), runs of blanks folded, at most ``MAX_ERROR_CHARS`` characters (the rest
    elided).  The one place every error the CLI prints goes through."""
    out = []
    for ch in str(text):
        if ch in "\n\r":
            out.append("\\n" if ch == "\n" else "\\r")
        elif ch == "\t":
            out.append(" ")
        elif ord(ch) < 32 or ord(ch) == 127 or 0x80 <= ord(ch) < 0xA0 or ch in "\u2028\u2029":
            out.append(f"\\x{ord(ch):02x}" if ord(ch) < 256 else f"\\u{ord(ch):04x}")
        else:
            out.append(ch)
    line = " ".join("".join(out).split())
    if len(line) > MAX_ERROR_CHARS:
        line = line[: MAX_ERROR_CHARS - 25] + f" ... ({len(line):,} characters)"
    return line


def error_line(text: str) -> None:
    """Print ``error: TEXT`` as one line on stderr, on a line of its own (after a progress bar)."""
    import sys

    print(f"error: {one_line(text)}", file=sys.stderr, flush=True)


def wrote(path, quiet: bool) -> None:
    if not quiet:
        print(f"\nreport written to {path}")


def write_html_report(args, quiet: bool, page, *inputs) -> None:
    """Write ``page(*inputs, interactive=...)`` to ``args.report`` as one HTML file, interactive
    unless ``--plotly no``, and say where unless stdout carries data (``quiet``)."""
    from ..report.html import write_page

    write_page(page(*inputs, interactive=args.plotly != "no"), args.report, plotly=args.plotly)
    wrote(args.report, quiet)


class GuardedStdout:
    """sys.stdout for the length of one command: a closed pipe (``axisopt ... | head``) or a full
    device (``> /dev/full``) does not end the command with a traceback or a wrong exit code.  The
    command runs to its end (its other outputs, e.g. ``--json FILE``, are still written) and keeps
    its own exit code; output to the closed pipe is dropped silently, a full device is reported on
    stderr in one line."""

    def __init__(self, stream):
        self._s = stream
        self.lost: OSError | None = None

    def _lose(self, exc: OSError) -> None:
        import errno
        import os

        self.lost = exc
        try:  # Python's own flush at exit must not fail again on the data still buffered
            os.dup2(os.open(os.devnull, os.O_WRONLY), self._s.fileno())
        except (OSError, ValueError, AttributeError):
            pass
        if exc.errno != errno.EPIPE:
            error_line(f"standard output: {exc.strerror or exc}; output lost")

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


# options that name an output file or directory: an empty name is a usage error, never "not given"
OUTPUT_OPTIONS = (
    "--json",
    "--csv",
    "--plot",
    "--out",
    "--report",
    "--save-design",
    "--save-calibration",
    "--frf",
)


def _output_path(text: str) -> str:
    if not text.strip():
        raise argparse.ArgumentTypeError("empty file name")
    return text


class Parser(argparse.ArgumentParser):
    """argparse that reports a usage error as one line (InputError, exit code 2); an output option
    given an empty name (``--save-design ""``) is such an error."""

    def add_argument(self, *names, **kw):
        if (
            any(n in OUTPUT_OPTIONS for n in names)
            and "type" not in kw
            and kw.get("action") in (None, "store")
        ):
            kw["type"] = _output_path
        return super().add_argument(*names, **kw)

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
    """``obj`` with every NaN or infinite float replaced by None (JSON null: no value, never
    NaN)."""
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
    """Write ``obj`` as JSON through :func:`axisopt.fileio.open_output`: a regular file atomically
    (the old file stays whole if writing fails), '-' to stdout, a FIFO or device in place.  A file
    that cannot be written is an InputError naming it."""
    from ..fileio import write_text_atomic

    text = json.dumps(_finite(obj), indent=2, default=json_default, allow_nan=False)

    write_text_atomic(target, text + "\n", what="JSON")
