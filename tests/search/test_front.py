"""The front door: the method table's capabilities, one status table, the result built in one
place."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from search_synthetic import make_catalog, make_double, make_problem

from axisopt.errors import InputError
from axisopt.model.goals import Objective
from axisopt.search import front, solve
from axisopt.search.result import STATUSES


def test_method_table_names_and_capabilities():
    assert front.METHODS == ("default", "exhaustive", "bonmin", "scip")
    pareto = {m.name for m in front.METHOD_TABLE if m.pareto}
    assert pareto == {"default", "exhaustive"}
    assert {m.name for m in front.METHOD_TABLE if not m.runners_up} == {"bonmin", "scip"}


@pytest.mark.parametrize("method", ["bonmin", "scip"])
def test_a_method_without_pareto_fronts_says_so(method):
    cat = make_catalog(np.random.default_rng(0))
    p = replace(make_problem(cat), objective=Objective(mode="pareto", pareto=("stiffness", "cost")))
    with pytest.raises(
        InputError, match=f"--method {method}.*Pareto front needs --method default or exhaustive"
    ):
        solve(p, method)


def test_unknown_method():
    with pytest.raises(ValueError, match="unknown method"):
        solve(make_problem(make_catalog(np.random.default_rng(0))), "simplex")


def test_top_without_runners_up_is_noted_not_ignored(monkeypatch):
    cat = make_catalog(np.random.default_rng(1))
    make_double(cat)
    p = make_problem(cat)
    one = {
        **front.METHODS_BY_NAME,
        "default": replace(front.METHODS_BY_NAME["default"], runners_up=False),
    }
    monkeypatch.setattr(front, "METHODS_BY_NAME", one)
    res = solve(p, "default", top=3, sensitivities=False)
    assert "returns the best design only (top 3 asked" in res.certificate.notes[-1]
    assert res.status in STATUSES and STATUSES[res.status].found
