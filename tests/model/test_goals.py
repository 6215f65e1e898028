"""The goal table (model.goals): every scalar mode has its objective in its unit; Pareto keys,
senses, units and fields come from the table."""

from __future__ import annotations

import pytest

from axisopt.model.goals import OBJECTIVE_MODES, OBJECTIVE_TABLE, PARETO_KEYS
from axisopt.search.pareto import FIELD, SENSE, UNIT
from axisopt.search.task.objective import objective_spec


def test_every_scalar_mode_has_an_objective_in_its_goals_unit():
    for g in OBJECTIVE_TABLE:
        if g.mode:
            spec = objective_spec(g.key)
            # a least cost or mass is maximised as its negative, shown as itself
            # (ObjectiveSpec.sign)
            w = 1.0 if g.sense == "max" else -1.0
            assert spec.terms == ((g.output, w),) and spec.unit == g.unit and spec.sign == w
            assert g.key in OBJECTIVE_MODES
    with pytest.raises(ValueError):
        objective_spec("total_mass")  # a Pareto key, no mode of its own


def test_pareto_keys_senses_units_and_fields_come_from_the_table():
    assert set(SENSE) == {g.key for g in OBJECTIVE_TABLE if g.pareto} == set(PARETO_KEYS) - {"mass"}
    assert SENSE["stiffness"] == "max" and SENSE["cost"] == "min"
    assert UNIT["stiffness"] == "N/um" and FIELD["frequency"] == "min_frequency"
