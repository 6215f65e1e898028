"""The search's objectives derive from axisopt.problem.OBJECTIVE_TABLE; the tie rule."""

from __future__ import annotations

import numpy as np
import pytest

from axisopt.model.goals import GOALS, OBJECTIVE_MODES, OBJECTIVE_TABLE, PARETO_KEYS, Objective
from axisopt.search.pareto import FIELD, SENSE, UNIT
from axisopt.search.task.objective import objective_spec, rank_order


def test_every_scalar_mode_has_an_objective_in_its_goals_unit():
    for g in OBJECTIVE_TABLE:
        if g.mode:
            spec = objective_spec(g.key)
            # a least cost or mass is maximised as its negative, shown as itself (ObjectiveSpec.sign)
            w = 1.0 if g.sense == "max" else -1.0
            assert spec.terms == ((g.output, w),) and spec.unit == g.unit and spec.sign == w
            assert g.key in OBJECTIVE_MODES
    with pytest.raises(ValueError):
        objective_spec("total_mass")  # a Pareto key, no mode of its own


def test_pareto_keys_senses_units_and_fields_come_from_the_table():
    assert set(SENSE) == {g.key for g in OBJECTIVE_TABLE if g.pareto} == set(PARETO_KEYS) - {"mass"}
    assert SENSE["stiffness"] == "max" and SENSE["cost"] == "min"
    assert UNIT["stiffness"] == "N/um" and FIELD["frequency"] == "min_frequency"


def test_weighted_objective_in_display_units():
    ob = Objective(mode="weighted", weights=(("stiffness", 1.0), ("frequency", 2.0)),
                   scale=(("stiffness", 100e6), ("frequency", 50.0)))
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
