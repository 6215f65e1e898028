"""Behaviour every search method shares, defined once and run per method (in the style of scipy's
``LinprogCommonTests``); a method skips what its row of ``METHOD_TABLE`` says it cannot do."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from search_synthetic import make_catalog, make_double, make_problem

from axisopt.errors import InputError
from axisopt.model.goals import Objective
from axisopt.search import solve
from axisopt.search.front import METHODS_BY_NAME
from axisopt.search.result import STATUSES


def _problem(seed=5, **kw):
    cat = make_catalog(np.random.default_rng(seed))
    make_double(cat)
    return make_problem(cat, axial_load=800.0, **kw)


class CommonMethodTests:
    method = ""

    @property
    def caps(self):
        return METHODS_BY_NAME[self.method]

    def test_status_is_declared_and_the_best_design_is_feasible(self):
        res = solve(_problem(), self.method, top=1, sensitivities=False)
        assert res.status in STATUSES and res.method == self.method
        assert res.best is not None and res.best.design is not None

    def test_never_beats_the_exhaustive_optimum(self):
        p = _problem()
        ref = solve(p, "exhaustive", top=1, sensitivities=False).objective
        res = solve(p, self.method, top=1, sensitivities=False)
        assert res.objective <= ref * (1 + 1e-6)
        if self.caps.proves and res.status == "optimal":
            assert res.objective == pytest.approx(ref, rel=1e-6)

    def test_runners_up(self):
        if not self.caps.runners_up:
            pytest.skip(f"{self.method} returns the best design only")
        res = solve(_problem(), self.method, top=3, sensitivities=False)
        assert len(res.runners_up) == 2
        objs = [res.best.objective] + [c.objective for c in res.runners_up]
        assert objs == sorted(objs, reverse=True)

    def test_pareto(self):
        p = replace(_problem(), objective=Objective(mode="pareto", pareto=("stiffness", "cost")))
        if not self.caps.pareto:
            with pytest.raises(InputError, match=self.method):
                solve(p, self.method)
            return
        res = solve(p, self.method)
        assert res.pareto is not None and len(res.pareto) >= 1


class TestDefault(CommonMethodTests):
    method = "default"


class TestExhaustive(CommonMethodTests):
    method = "exhaustive"
