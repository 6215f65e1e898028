"""The max_backlash sensitivity is not re-solved when relaxing the limit admits no combination the
search did not have (search.sensitivity.backlash_unmoved): the answer equals the re-solve's, and the
skip holds back wherever a lost motion, or a reduction the limit left out, lies in the relaxed
range."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from axisopt.model.limits import LIMITS
from axisopt.problem import load_problem
from axisopt.search import sensitivity
from axisopt.search.front import build_task, solve
from axisopt.search.parts import build_space
from axisopt.search.sensitivity import backlash_unmoved, limit_sensitivities

ROOT = Path(__file__).resolve().parents[2]


def test_skipped_backlash_sensitivity_equals_the_re_solve(monkeypatch):
    problem = load_problem(ROOT / "problems" / "lathe_z_belt_problem.yaml")
    res = solve(problem, sensitivities=False)
    space = build_task(problem).space
    limit = problem.limit_map["max_backlash"]
    assert backlash_unmoved(space, limit, 1.1 * limit)  # 2 -> 2.2 um admits nothing new
    skipped = limit_sensitivities(problem, res, space=space)
    monkeypatch.setattr(sensitivity, "backlash_unmoved", lambda *a: False)
    re_solved = limit_sensitivities(problem, res, space=space)
    assert [b.limit for b in skipped] == [b.limit for b in re_solved]
    assert skipped == re_solved
    # the optimum's own lost motion inside the relaxed range: re-solved
    at = res.best.outputs[LIMITS["max_backlash"].output]
    assert 0.0 < at < limit
    assert not backlash_unmoved(space, at / 1.05, 1.1 * at / 1.05)
    # a reduction a tighter limit (0.5 um) leaves out comes within the relaxed limit: re-solved
    tight = build_space(problem.with_limit("max_backlash", 0.5e-6))
    least = tight.backlash_left_least
    assert tight.reductions_by_backlash and np.isfinite(least) and least > 0.5e-6
    assert not backlash_unmoved(tight, least / 1.05, 1.1 * least / 1.05)
