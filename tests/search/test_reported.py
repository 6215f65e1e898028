"""The values a result reports (search.reported.REPORTED), declared once: each is a Candidate field
after ``objective``, a column of the candidate tables and of the study table (with its profile
columns after it), and a value the candidate is filled with (a goal's field or a model output)."""

from __future__ import annotations

from dataclasses import fields

from axisopt.model.goals import RESULT_GOALS
from axisopt.model.outputs import OUTPUTS
from axisopt.search.reported import REPORTED
from axisopt.search.result import CANDIDATE_COLUMNS, Candidate
from axisopt.study.table import RESULT_COLUMNS


def test_each_reported_value_is_a_candidate_field_after_the_objective():
    names = [f.name for f in fields(Candidate)]
    at = names.index("objective") + 1
    assert names[at : at + len(REPORTED)] == [r.field for r in REPORTED]
    assert all(
        f.type == "float" for f in fields(Candidate) if f.name in {r.field for r in REPORTED}
    )


def test_each_reported_value_has_its_columns():
    assert [c for _, c in CANDIDATE_COLUMNS[1:]] == [r.column for r in REPORTED]
    study = [c for c, _ in RESULT_COLUMNS]
    for r in REPORTED:
        i = study.index(r.column)
        assert study[i + 1 : i + 1 + len(r.profile)] == [c for c, _ in r.profile]
        assert dict(RESULT_COLUMNS)[r.column] == ("best", r.field)


def test_each_reported_value_has_a_source():
    goals = {g.field for g in RESULT_GOALS}
    for r in REPORTED:
        assert (r.output in OUTPUTS) if r.output else (r.field in goals), r.field
