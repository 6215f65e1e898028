"""SCIP's own status words meet the status table (search/minlp/statuses.py) as SCIP returns them: a
model SCIP solves reads PROVED, one stopped by its time or node limit STOPPED, an unbounded one
UNEXPECTED."""

from __future__ import annotations

import pytest

from axisopt.search.minlp.statuses import PROVED, SCIP_STATUSES, STOPPED, UNEXPECTED, scip_outcome

ps = pytest.importorskip("pyscipopt")


def _model(**params):
    m = ps.Model()
    m.hideOutput()
    x = m.addVar("x", vtype="I", lb=0, ub=10)
    y = m.addVar("y", vtype="I", lb=0, ub=10)
    m.addCons(3 * x + 5 * y <= 17)
    m.setObjective(x + 2 * y, "maximize")
    for k, v in params.items():
        m.setParam(k, v)
    return m


def test_a_solved_model_reads_proved():
    m = _model()
    m.optimize()
    assert m.getStatus() == "optimal" and scip_outcome(m.getStatus()) == PROVED


def test_an_infeasible_model_reads_proved():
    m = _model()
    m.addCons(m.getVars()[0] >= 7)
    m.optimize()
    assert m.getStatus() == "infeasible" and scip_outcome(m.getStatus()) == PROVED


def test_a_node_limited_model_reads_stopped():
    m = _model(**{"limits/nodes": 0})
    m.optimize()
    assert m.getStatus() in SCIP_STATUSES and scip_outcome(m.getStatus()) == STOPPED


def test_an_unbounded_model_reads_unexpected():
    m = ps.Model()
    m.hideOutput()
    x = m.addVar("x", lb=0, ub=None)
    m.setObjective(x, "maximize")
    m.optimize()
    assert m.getStatus() not in SCIP_STATUSES and scip_outcome(m.getStatus()) == UNEXPECTED
