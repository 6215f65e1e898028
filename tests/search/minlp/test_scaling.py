"""The one scaling of a limit for the MINLP solvers: a ratio to the limit (compared with 1), the
value in display units for a limit of 0, a logarithm for life and margins; the branch for a limit of
0 follows the number even when the divisor is a symbol."""

from __future__ import annotations

import casadi as ca
import numpy as np
import pytest

from axisopt.search.minlp.scaling import log_scaled, reciprocal_times, scaled_limit
from axisopt.search.task.constraints import Constraint


def _limit(key, sense, limit, factor=1.0):
    return Constraint(key, key, sense, limit, 0, key, "", factor)


def test_ratio_to_the_limit_compared_with_one():
    g, rhs = scaled_limit(_limit("cost", "<=", 3500.0), 7000.0)
    assert (g, rhs) == (2.0, 1.0)


def test_limit_of_zero_is_the_value_in_display_units():
    g, rhs = scaled_limit(_limit("backlash", "<=", 0.0, factor=1e-6), 3e-6)
    assert g == pytest.approx(3.0) and rhs == 0.0


def test_life_and_margins_on_a_log_scale():
    assert log_scaled("life") and log_scaled("margin_buckling") and not log_scaled("cost")
    g, rhs = scaled_limit(_limit("margin_buckling", ">=", 1.0), ca.DM(np.e**2))
    assert float(g) == pytest.approx(2.0) and rhs == 0.0
    g, _ = scaled_limit(_limit("life", ">=", 5.4e7), ca.DM(0.0))  # no -inf at a life of 0
    assert np.isfinite(float(g)) and float(g) < -600
    g, rhs = scaled_limit(_limit("life", ">=", 5.4e7), 1.08e8, log=False)  # SCIP: the ratio
    assert (g, rhs) == (2.0, 1.0)


def test_symbolic_limit_keeps_the_branch_of_the_number():
    lim, v = ca.SX.sym("lim"), ca.SX.sym("v")
    g, rhs = scaled_limit(_limit("cost", "<=", 3500.0), v, lim)
    assert rhs == 1.0 and ca.depends_on(g, lim)
    g, rhs = scaled_limit(_limit("backlash", "<=", 0.0, factor=1e-6), v, lim)
    assert rhs == 0.0 and not ca.depends_on(g, lim)


def test_reciprocal_times_keeps_a_constant_factor_of_a_scip_expression():
    ps = pytest.importorskip("pyscipopt")
    m = ps.Model()
    x = m.addVar("x", lb=1.0)
    e = ps.sqrt(x) * x  # nonlinear: divided, it would gain a constant power node
    g, rhs = scaled_limit(_limit("drag_torque", "<=", 4.0), e, log=False, divide=reciprocal_times)
    assert str(g) == str(0.25 * e) and rhs == 1.0
    assert reciprocal_times(6.0, 4.0) == 1.5
