"""The screw's lead accuracy grade as a search choice (issue 43): each screw row once per grade it
is made in (screw x grade), the positioning-error limit on the budget; the default search equals
exhaustive enumeration, and a problem without an accuracy limit keeps its search space.  Fixed
seeds."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from search_synthetic import add_drives, assert_same_answer, make_catalog, make_problem

from axisopt import model
from axisopt.catalog.grades import PRECISION_GRADES, grade_table
from axisopt.search import solve
from axisopt.search.parts import build_space

ARCSEC = np.pi / 180 / 3600


def _problem(seed: int):
    rng = np.random.default_rng(700 + seed)
    cat = make_catalog(rng, n_screws=4, nuts_per_screw=3, n_bearings=5, n_guides=4)
    if seed % 3 == 2:
        cat = add_drives(cat, rng)
    limits = {
        "max_cost": float(rng.uniform(3000, 6000)),
        "max_drag_torque": float(rng.uniform(1.0, 2.5)),
        "max_positioning_error": float(rng.uniform(40, 120)) * 1e-6,
    }
    axis = dict(
        guide_pitch=float(rng.uniform(0, 10)) * ARCSEC,
        guide_yaw=float(rng.uniform(0, 5)) * ARCSEC,
        tool_height=float(rng.uniform(0.05, 0.3)),
        tool_offset=float(rng.uniform(0, 0.1)),
        temperature_rise=float(rng.uniform(0.5, 3.0)),
    )
    p = make_problem(
        cat,
        mode=("stiffness", "frequency")[seed % 2],
        limits=limits,
        backlash=5e-5 if seed % 2 else None,
        mountings=("fixed-supported", "fixed-fixed")
        if seed % 3
        else ("fixed-free", "fixed-supported"),
        **axis,
    )
    if seed % 3 == 2:
        p = replace(p, restrictions=replace(p.restrictions, drive=True))
    if seed % 4 == 3:  # the problem names the grades the search may choose among
        p = replace(p, restrictions=replace(p.restrictions, screw_grades=("C3", "C5", "C7")))
    return p


@pytest.mark.parametrize("seed", range(8))
def test_default_equals_exhaustive_with_grade_choice(seed):
    p = _problem(seed)
    d = solve(p, "default", top=3, sensitivities=False)
    e = solve(p, "exhaustive", top=3, sensitivities=False)
    assert_same_answer(d, e)
    if d.best is None:
        return
    assert d.certificate.proven and d.certificate.gap == 0.0
    assert [c.combination for c in d.runners_up] == [c.combination for c in e.runners_up]
    assert d.best.screw_grade == e.best.screw_grade
    # the design names its grade, and its budget meets the limit
    ev = model.evaluate(d.best.design)
    assert d.best.design.grade == d.best.screw_grade
    assert ev["positioning_error"] <= dict(p.limits)["max_positioning_error"] * (1 + 1e-9)
    allowed = p.restrictions.screw_grades or PRECISION_GRADES
    assert d.best.screw_grade in allowed


def test_grade_rows_drop_dominated_and_untoleranced_grades():
    """C7 on a precision shaft costs as much as C5 and is less accurate: never a row; the rows of
    one screw are the grades in order of price with falling lead error; no grade without a tolerance
    over the stroke (C0 beyond 1600 mm, THK A-678 Table 1)."""
    rng = np.random.default_rng(5)
    cat = make_catalog(rng, n_screws=2, nuts_per_screw=1, n_bearings=2, n_guides=2)
    p = make_problem(cat, limits={"max_positioning_error": 1e-3}, backlash=5e-5)
    sp = build_space(p)
    assert sp.grades is not None
    assert sorted(set(sp.grades)) == ["C0", "C1", "C2", "C3", "C5"]
    assert sp.shape[1] == 5 * len(cat.nuts)
    long = make_problem(cat, limits={"max_positioning_error": 1e-3}, backlash=5e-5, stroke=1.8)
    assert "C0" not in set(build_space(long).grades)
    t = grade_table()
    assert t.lead_error("C1", 1.8) < t.lead_error("C2", 1.8)


def test_no_accuracy_limit_keeps_the_space_and_the_catalog_price():
    """Without a positioning limit or catalog.screw_grades every screw takes its cheapest grade (C5:
    the catalog price) and the search space is the catalog's, as before the grades."""
    rng = np.random.default_rng(3)
    cat = make_catalog(rng, n_screws=3, nuts_per_screw=2, n_bearings=3, n_guides=2)
    p = make_problem(cat, limits={"max_cost": 5000.0}, backlash=5e-5)
    sp = build_space(p)
    assert sp.grades is None and sp.shape[1] == len(cat.nuts)
    d = solve(p, "default", top=1, sensitivities=False)
    if d.best is not None:
        assert d.best.screw_grade == "" and d.best.design.grade == "C5"


@pytest.mark.parametrize(
    "keys", [("positioning_error", "cost"), ("positioning_error", "stiffness", "cost")]
)
def test_pareto_with_positioning_error_default_equals_exhaustive(keys):
    """A front of the positioning error against cost (and stiffness): the grade is a choice, every
    point names its grade, and the front is the brute-force non-dominated set of the exact
    per-combination values."""
    from axisopt.model.goals import Objective
    from axisopt.search.exhaustive import exhaustive_search
    from axisopt.search.task.constraints import build_constraints
    from axisopt.search.task.objective import objective_spec

    rng = np.random.default_rng(4)
    cat = make_catalog(rng)
    p = make_problem(
        cat,
        objective=Objective(mode="pareto", pareto=keys),
        limits={"max_drag_torque": 1.5},
        backlash=5e-5,
        guide_pitch=5 * ARCSEC,
        tool_height=0.2,
        temperature_rise=1.0,
    )
    d, e = solve(p, "default"), solve(p, "exhaustive")
    assert d.status == e.status == "optimal"
    assert sorted(c.combination for c in d.pareto.points) == sorted(
        c.combination for c in e.pareto.points
    )
    assert all(c.screw_grade for c in d.pareto.points)
    assert len({c.screw_grade for c in d.pareto.points}) > 1  # the front trades grades against cost
    sp = build_space(p)
    ex, _ = exhaustive_search(sp, build_constraints(p), objective_spec("stiffness"))
    ok = np.nonzero(ex.feasible)[0]
    cols = {
        "positioning_error": -ex.positioning_error[ok],
        "cost": -ex.cost[ok],
        "stiffness": ex.min_stiffness[ok],
    }
    P = np.column_stack([cols[k] for k in keys])
    ge = (P[:, None, :] >= P[None, :, :]).all(-1)
    gt = (P[:, None, :] > P[None, :, :]).any(-1)
    assert sorted(ex.idx[ok][~(ge & gt).any(0)].tolist()) == sorted(
        c.combination for c in d.pareto.points
    )
