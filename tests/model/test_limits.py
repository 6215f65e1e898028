"""The one declaration of limits and checks (model.limits): everything derived from it agrees with
it."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from axisopt import model
from axisopt.model.limits import CHECK_TABLE, LIMITS, preload_direction
from axisopt.problem import LIMITS_SPEC, load_problem
from axisopt.report.evaluation import CHECK_SHORT, CHECK_UNITS
from axisopt.search import solve
from axisopt.search.task.constraints import build_constraints

ROOT = Path(__file__).resolve().parents[2]


def test_every_limit_reads_an_output_the_model_computes():
    ev = model.evaluate(load_problem_design())
    for lim in LIMITS.values():
        assert lim.output in ev.values, lim.key
        assert lim.sense in ("<=", ">=")


def load_problem_design():
    from axisopt.design import load_design

    return load_design(ROOT / "problems" / "vmc_x_design.yaml")


def test_every_check_has_its_margin_and_compared_values():
    ev = model.evaluate(load_problem_design())
    for c in CHECK_TABLE:
        assert f"margin_{c.name}" in ev.values, c.name
        assert f"available_{c.name}" in ev.values and f"needed_{c.name}" in ev.values, c.name
    assert tuple(CHECK_UNITS) == model.CHECKS == tuple(CHECK_SHORT)


def test_problem_schema_and_constraints_derive_from_the_limit_table():
    assert set(LIMITS_SPEC.keys) - {"margins"} == set(LIMITS)
    problem = load_problem(ROOT / "problems" / "teaching_problem.yaml")
    for con in build_constraints(problem):
        if con.name in LIMITS:
            lim = LIMITS[con.name]
            assert (con.key, con.sense, con.unit, con.factor) == (
                lim.output,
                lim.sense,
                lim.unit,
                lim.factor,
            )
        assert con.direction == preload_direction(con.key)


def test_sensitivity_report_covers_every_limit_set_incl_inertia_ratio():
    """The sensitivity map once missed max_inertia_ratio (it skipped the limit silently)."""
    problem = load_problem(ROOT / "problems" / "teaching_problem.yaml")
    base = solve(problem, top=1, sensitivities=False)
    ratio = base.best.outputs["inertia_ratio"]
    assert np.isfinite(ratio) and ratio > 0
    problem = problem.with_limit("max_inertia_ratio", ratio * 1.5)
    res = solve(problem, top=1)
    keys = {b.limit for b in res.binding}
    assert "max_inertia_ratio" in keys
    b = next(b for b in res.binding if b.limit == "max_inertia_ratio")
    assert b.at_optimum == pytest.approx(res.best.outputs["inertia_ratio"])
    assert {k for k, v in problem.limits if v > 0} <= keys
