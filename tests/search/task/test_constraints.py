"""Constraints derived from the model's tables: preload direction, favourable end, scaling for the
solvers."""

from __future__ import annotations

import casadi as ca
import numpy as np
import pytest

from axisopt.model.limits import CONVEX, LIMITS
from axisopt.search.task.constraints import Constraint, End, Preload, limit_constraint


def _c(key="k_total", sense=">=", limit=100e6, direction=1, factor=1e6):
    return Constraint("x", key, sense, limit, direction, "x", "", factor)


@pytest.mark.parametrize(
    "sense, direction, end",
    [
        (">=", 1, End.HIGH),
        ("<=", 1, End.LOW),
        (">=", -1, End.LOW),
        ("<=", -1, End.HIGH),
        (">=", 0, End.LOW),
        (">=", CONVEX, End.INTERVAL),
    ],
)
def test_favourable_end_follows_sense_and_preload_direction(sense, direction, end):
    c = _c(sense=sense, direction=direction)
    assert c.favourable is end
    assert c.convex == (direction == CONVEX)
    assert c.lower_type == (end is End.HIGH) and c.upper_type == (end is End.LOW and direction != 0)


def test_preload_directions_are_the_models():
    assert Preload(LIMITS["min_stiffness"].preload) is Preload.RISES
    assert Preload(LIMITS["min_life"].preload) is Preload.FALLS
    assert Preload(LIMITS["max_cost"].preload) is Preload.INDEPENDENT
    assert _c(key="k_total").profile and not _c(key="cost").profile


def test_scaling_is_the_same_on_numpy_and_casadi_with_a_branch_for_a_zero_limit():
    for c, v in (
        (_c(), 120e6),
        (_c(key="life", limit=3.6e7, direction=-1), 7.2e7),
        (_c(key="backlash", sense="<=", limit=0.0, direction=0, factor=1e-6), 2e-6),
    ):
        x = ca.SX.sym("x")
        f = ca.Function("f", [x], [c.scaled(x)])
        assert float(f(v)) == pytest.approx(float(c.scaled(np.float64(v))))
    assert float(
        _c(key="backlash", sense="<=", limit=0.0, direction=0, factor=1e-6).scaled(2e-6)
    ) == pytest.approx(2.0)
    assert float(_c().scaled(120e6)) == pytest.approx(0.2)


def test_limit_constraint_renames_a_problem_limit():
    c = limit_constraint("min_frequency", 50.0, "lexicographic frequency", "frequency within 0.01")
    assert (c.name, c.key, c.sense, c.limit, c.unit) == (
        "lexicographic frequency",
        "f1",
        ">=",
        50.0,
        "Hz",
    )


def test_a_part_at_its_limit_meets_it_once_both_are_in_si():
    """A nut's 0.05 mm play and a 50 um backlash limit become 5.000000000000001e-05 and
    4.9999999999999996e-05 m; the part at the limit meets it (a generated axis was told to relax 50
    um to 50 um, +2.2e-14 %).  A preload-dependent limit keeps its exact boundary (the preload
    searches find it)."""
    from axisopt.units import parse_quantity

    play = parse_quantity("0.05 mm", "length")
    limit = parse_quantity("50 um", "length")
    assert play > limit  # the rounding this guards against
    c = limit_constraint("max_backlash", limit, "max_backlash", "max backlash")
    assert c.direction == 0 and c.ok(np.asarray(play)) and float(c.violation(np.asarray(play))) == 0
    assert not c.ok(np.asarray(limit * 1.001)) and float(c.violation(np.asarray(limit * 1.001))) > 0
    drag = limit_constraint("max_drag_torque", 0.5, "max_drag_torque", "max drag torque")
    assert drag.direction != 0 and not drag.ok(np.asarray(0.5 * (1 + 1e-12)))
