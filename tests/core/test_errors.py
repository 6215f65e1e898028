"""The project's errors (axisopt.errors): an InputError's one line names the file and the place
first."""

from __future__ import annotations

import pytest

from axisopt.errors import AxisoptError, ImplausibleInput, InputError


@pytest.mark.parametrize(
    "source, where, line",
    [
        ("axis.yaml", "line 3", "axis.yaml: line 3: stroke must be positive"),
        ("axis.yaml", None, "axis.yaml: stroke must be positive"),
        (None, "axis.stroke", "axis.stroke: stroke must be positive"),
        (None, None, "stroke must be positive"),
    ],
)
def test_input_error_line(source, where, line):
    e = InputError("stroke must be positive", source=source, where=where)
    assert str(e) == line
    assert (e.source, e.where, e.message) == (source, where, "stroke must be positive")


def test_kinds():
    assert issubclass(InputError, AxisoptError) and issubclass(AxisoptError, Exception)
    assert issubclass(ImplausibleInput, UserWarning) and not issubclass(
        ImplausibleInput, AxisoptError
    )
