"""The reports' text basics (report.text): values at sensible precision, rad/s to rpm, long lines
wrapped under their indent; expected strings written by hand."""

from __future__ import annotations

import math

import pytest

from axisopt.report.text import RPM, WIDTH, fit_lines, fmt_value, wrap_words


def test_rad_per_s_to_rpm():
    # one revolution per second is 2 pi rad/s and 60 rpm
    assert 2.0 * math.pi * RPM == pytest.approx(60.0, rel=1e-15)


@pytest.mark.parametrize(
    "x, text",
    [
        (1234.6, "1,235"),
        (100.0, "100"),
        (-2500.4, "-2,500"),
        (3.14159, "3.14"),
        (0.000123456, "0.000123"),
        (99.94, "99.9"),
        (None, "-"),
        (float("nan"), "-"),
        (float("inf"), "-"),
    ],
)
def test_fmt_value(x, text):
    assert fmt_value(x) == text


def test_fit_lines_wraps_only_long_lines_under_their_indent():
    words = [f"word{i}" for i in range(30)]  # 30 words of 5-6 characters: 200 columns on one line
    long = "  " + " ".join(words)
    short = "a short line"
    out = fit_lines(short + "\n" + long, width=60).split("\n")
    assert out[0] == short
    assert all(len(line) <= 60 for line in out)
    assert out[1].startswith("  word0 ")
    assert all(line.startswith("      ") and not line.startswith("       ") for line in out[2:])
    assert " ".join(" ".join(out[1:]).split()) == " ".join(words)  # no word lost or split


def test_wrap_words_fits_the_width():
    lines = wrap_words("x" * 10 + " " + "y " * 80)
    assert lines[0].startswith("  xxxxxxxxxx")
    assert all(len(line) <= WIDTH for line in lines) and len(lines) == 2
    assert lines[1].startswith("      y")
