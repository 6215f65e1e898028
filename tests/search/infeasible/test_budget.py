"""An impossible budget (issue 42, item 2): the advice leads with the least budget at which the
catalogs hold a design meeting every other limit, found by its own search (search.budget), whatever
the explanation's closest designs are; checked against the default search on the changed problem (a
design at that budget, none one rounding step below it), and the search itself against every
combination (the exhaustive method) on random catalogs.  No formula is new here: the reference is
the exhaustive enumeration, not a published number."""

import math

import numpy as np
import pytest
from lathe_z import lathe
from test_bounds import _problem

from axisopt.report.solve import relax_lines
from axisopt.search import solve
from axisopt.search.exhaustive import exhaustive_search
from axisopt.search.infeasible.budget import least_cost
from axisopt.search.parts import build_space
from axisopt.search.task.constraints import build_constraints
from axisopt.search.task.objective import objective_spec


def _step_below(v: float) -> float:
    """The three-significant-figure value one step below ``v`` (the advice rounds up to three
    figures)."""
    return v - 10.0 ** (math.floor(math.log10(v)) - 2)


@pytest.mark.slow  # over 10 s on an idle core: run by `pytest -m slow`
def test_impossible_budget_leads_with_the_least_budget(tmp_path):
    res = solve(lathe(tmp_path, "500 EUR"), "default")
    assert res.best is None
    inf = res.infeasibility
    first = inf.design_changes[0]
    assert (
        first.key == "limits.max_cost"
        and first.unit == "EUR"
        and first.value == pytest.approx(500.0)
    )
    v = first.to
    assert relax_lines(inf)[0].startswith(
        f"  change the design: raise limits.max_cost from 500 to {v:,.0f} EUR"
    )
    ok = solve(lathe(tmp_path, f"{v:g} EUR"), "default", sensitivities=False)
    assert ok.best is not None and ok.best.cost <= v
    short = solve(lathe(tmp_path, f"{_step_below(v):g} EUR"), "default", sensitivities=False)
    assert short.best is None and short.certificate.proven


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_least_cost_equals_every_combination(seed):
    """search.budget.least_cost against the cheapest feasible combination of the exhaustive method,
    the problem's own budget left out (random catalogs, with and without a drive search)."""
    p = _problem(seed)
    free = p.with_limit("max_cost", None)
    sp = build_space(p)
    ex, _ = exhaustive_search(sp, build_constraints(free), objective_spec(p.objective.mode, p))
    ok = np.isfinite(ex.objective)
    found = least_cost(p, sp)
    if not ok.any():
        assert found is None
        return
    assert found is not None and found[2]
    assert found[0] == pytest.approx(float(ex.cost[ok].min()), rel=1e-12)
    cut = least_cost(p, sp, max_blocks=1)  # one block screened: a design found then costs no less
    assert cut is None or cut[0] >= found[0] * (1.0 - 1e-12)


def test_a_budget_that_is_not_the_only_problem_gets_no_raise(tmp_path):
    """Without the budget nothing fits either (a first natural frequency of 10 kHz no axis reaches):
    no budget."""
    p = _problem(1).with_limit("min_frequency", 1e4)
    assert least_cost(p, build_space(p)) is None
    res = solve(p, "default")
    assert res.best is None and all(
        c.key != "limits.max_cost" for c in res.infeasibility.design_changes
    )
