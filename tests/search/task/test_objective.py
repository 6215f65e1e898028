"""The search's objectives derive from axisopt.problem.OBJECTIVE_TABLE; the tie rule."""

from __future__ import annotations

import numpy as np
import pytest

from axisopt.model.goals import GOALS, Objective
from axisopt.search.task.objective import objective_spec, rank_order


def test_weighted_objective_in_display_units():
    ob = Objective(
        mode="weighted",
        weights=(("stiffness", 1.0), ("frequency", 2.0)),
        scale=(("stiffness", 100e6), ("frequency", 50.0)),
    )
    spec = objective_spec("weighted", _with(ob))
    out = {"k_total": np.array([[200e6, 300e6]]), "f1": np.array([[100.0, 80.0]])}
    assert float(spec.value(out)[0]) == pytest.approx(200 / 100 + 2 * 80 / 50)
    assert GOALS["stiffness"].factor == 1e6


def _with(ob):
    class P:
        objective = ob

    return P()


def test_ties_go_to_lower_cost_then_mass_then_number():
    obj = np.array([10.0, 10.0 * (1 + 1e-9), 9.0, 10.0])
    cost = np.array([5.0, 4.0, 1.0, 4.0])
    mass = np.array([1.0, 2.0, 1.0, 1.0])
    idx = np.array([0, 1, 2, 3])
    assert list(rank_order(obj, cost, mass, idx, 4)) == [3, 1, 0, 2]
