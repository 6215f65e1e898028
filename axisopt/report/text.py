"""Text basics the reports share: the terminal width the tables fit, rad/s to rpm, a physical value
at sensible precision, and prose lines wrapped to the width.  Nothing here prints."""

from __future__ import annotations

import math
import textwrap

RPM = 60.0 / (2.0 * math.pi)  # rad/s -> rpm
WIDTH = 100  # terminal columns the text tables fit


def fmt_value(x) -> str:
    """A physical value at sensible precision: whole numbers from 100 up (with thousands
    separators), else three significant digits; '-' for a missing or non-finite value."""
    if x is None or not math.isfinite(x):
        return "-"
    if abs(x) >= 100:
        return f"{x:,.0f}"
    return f"{x:.3g}"


def fit_lines(text: str, width: int = 100) -> str:
    """Wrap each line longer than ``width`` at spaces, its continuation indented under it (tables
    are built to fit; this catches prose: notes, misses, messages)."""
    out = []
    for line in text.split("\n"):
        if len(line) <= width:
            out.append(line)
            continue
        lead = " " * (len(line) - len(line.lstrip(" ")))
        out.extend(
            textwrap.wrap(
                line,
                width,
                initial_indent="",
                subsequent_indent=lead + "    ",
                break_on_hyphens=False,
                drop_whitespace=True,
            )
            or [line]
        )
    return "\n".join(out)


def wrap_words(text: str, indent: str = "  ", cont: str = "      ") -> list:
    """Prose wrapped to WIDTH, the first line indented by ``indent``, the rest by ``cont``."""
    return textwrap.wrap(
        text, WIDTH, initial_indent=indent, subsequent_indent=cont, break_on_hyphens=False
    )
