"""The plausibility table (design/plausible.py) and the one docs/assumptions.md shows are the same
table, and a value just outside each range is warned about while one just inside is not."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from axisopt.design.plausible import CYCLE_RANGES, LIMIT_RANGES, RANGES, implausible
from axisopt.display import fmt

DOC = Path(__file__).resolve().parents[2] / "docs" / "assumptions.md"
TABLES = {"axis": RANGES, "duty_cycle": CYCLE_RANGES, "limits": LIMIT_RANGES}
ROW = re.compile(r"^\s*\| (axis|duty_cycle|limits) \| ([^|]+) \| ([^|]+) \| ([^|]+) \|$")


def _doc_rows() -> list:
    return [m.groups() for m in map(ROW.match, DOC.read_text().splitlines()) if m]


def test_the_docs_table_is_the_code_table():
    code = [
        (
            section,
            "largest process force" if r.key == "duty_cycle" else r.key,
            fmt(r.low * r.factor, r.unit),
            fmt(r.high * r.factor, r.unit),
        )
        for section, table in TABLES.items()
        for r in table
    ]
    assert [tuple(c.strip() for c in row) for row in _doc_rows()] == code


@pytest.mark.parametrize("r", [r for t in TABLES.values() for r in t], ids=lambda r: r.key)
def test_each_range_warns_outside_and_not_inside(r):
    ranges = (
        TABLES["limits"] if r in LIMIT_RANGES else CYCLE_RANGES if r in CYCLE_RANGES else RANGES
    )
    assert implausible({r.key: r.high * 1.01}, ranges)[0][0] == r.key
    assert implausible({r.key: r.high * 0.99}, ranges) == []
    if r.low > 0:
        assert "far below" in implausible({r.key: r.low * 0.99}, ranges)[0][1]
    assert implausible({r.key: 0.0}, ranges) == []  # zero means none where allowed
