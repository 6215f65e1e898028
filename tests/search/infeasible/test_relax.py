"""An infeasible answer says what to relax (issue 30): the user's relaxable limits (problem limits
and check margins) by the smallest relative change that frees a closest design, with that design;
compatibility rules (bearing fit, screw length) are never proposed for relaxing."""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import pytest

from axisopt.cli import main
from axisopt.problem import load_problem
from axisopt.search import solve
from axisopt.search.infeasible.answer import Infeasibility
from axisopt.search.infeasible.relax import rank_relaxations
from axisopt.search.result import Candidate
from axisopt.search.task.constraints import build_constraints

PROBLEMS = Path(__file__).resolve().parents[3] / "problems"


def test_infeasible_problem_first_lines_name_the_limit_and_the_amount(capsys):
    """The tutorial's infeasible problem: the user's own limits are listed first, and no vendor
    margin is proposed below 0.95 (issue 52): every closest design needs one far lower (a
    support-bearing life at 0.014), so the relaxation is blocked by those rules and says so; the
    cost and stiffness it needs besides are listed."""
    assert (
        main(
            ["solve", str(PROBLEMS / "infeasible_problem.yaml"), "--no-sensitivity", "--json", "-"]
        )
        == 1
    )
    inf = json.loads(capsys.readouterr().out)["infeasibility"]
    relax = inf["relax"]
    keys = [r["key"] for r in relax]
    assert "limits.max_cost" in keys and "limits.min_stiffness" in keys
    assert all(r["relaxed_to"] >= 0.95 for r in relax if r["key"].startswith("limits.margins."))
    margin = [k.startswith("limits.margins.") for k in keys]
    assert margin == sorted(margin)  # the user's own limits first, the vendor margins last
    # compatibility rules apart
    assert not any("bearing_fit" in k or "screw_length" in k for k in keys)
    assert inf["relax_blocked_by"]  # vendor rules no margin down to 0.95 frees
    assert all(
        not any(w in m for w in ("bore", "screw max length")) for m in inf["closest"][0]["misses"]
    )
    cost = relax[keys.index("limits.max_cost")]
    assert cost["value"] == 300 and cost["relaxed_to"] == pytest.approx(300 * (1 + cost["change"]))
    # no design is cheaper than that
    assert cost["relaxed_to"] >= inf["unmeetable"][0]["best_achievable"]
    assert cost["parts"]["screw"] and cost["design_rank"] in [c["rank"] for c in inf["closest"]]

    assert main(["solve", str(PROBLEMS / "infeasible_problem.yaml"), "--no-sensitivity"]) == 1
    text = capsys.readouterr().out
    first = "\n".join(text.splitlines()[:24])
    assert "no relaxation of the limits is enough" in first and "no margin down to 0.95" in first
    assert (
        f"limits.max_cost from 300 EUR to {cost['relaxed_to']:,.0f} EUR "
        f"(+{100 * cost['change']:,.0f} %)" in first
    )
    stiff = relax[keys.index("limits.min_stiffness")]
    assert f"limits.min_stiffness from 400 N/um to {stiff['relaxed_to']:.4g} N/um" in first


def test_the_relaxations_free_the_design():
    """The SGM7J motors give no brake torque: the holding-brake check, failed by 100 %, is never
    proposed at a margin of 0; the motor's torque and inertia checks, missed by far more than 5 %,
    are not proposed below 0.95 either (issue 52): they block the relaxation, the answer says which
    rows lack the brake torque, and the advice is a design change
    (tests/search/infeasible/test_widen.py re-solves it)."""
    problem = load_problem(PROBLEMS / "infeasible_drive_problem.yaml")
    res = solve(problem, sensitivities=False)
    inf = res.infeasibility
    brake = next(c.label for c in build_constraints(problem) if c.name == "margin_brake_holding")
    assert res.status == "infeasible" and brake in inf.relax_blocked_by
    assert len(inf.missing) == 1 and "Sigma-7 SGM7J give no brake torque" in inf.missing[0]
    assert all(r.relaxed_to >= 0.95 for r in inf.relax if r.key.startswith("limits.margins."))
    # what the relaxation lists, with the blocking rules switched off by hand, frees the design it
    # names
    margins = dict(problem.margins) | {
        c.name[len("margin_") :]: 0.0
        for c in build_constraints(problem)
        if c.label in inf.relax_blocked_by
    }
    relaxed = problem
    for r in inf.relax:
        name = r.key.split(".")[-1]
        if r.key.startswith("limits.margins."):
            margins[name] = r.relaxed_to * (1 - 1e-6)
        else:
            relaxed = relaxed.with_limit(name, r.relaxed_to * (1 + 1e-6))
    relaxed = replace(relaxed, margins=tuple(margins.items()))
    again = solve(relaxed, sensitivities=False)
    assert again.status == "optimal"


def _cand(rank, misses):
    return Candidate(
        rank,
        rank,
        "fixed-fixed",
        "s",
        "n",
        "b",
        "g",
        1000.0,
        0.0,
        50.0,
        100.0,
        1000.0,
        100.0,
        110.0,
        0.5,
        1e4,
        misses=misses,
    )


def test_one_limit_alone_beats_several_and_compatibility_rules_are_left_out():
    problem = load_problem(PROBLEMS / "teaching_problem.yaml")
    cons = build_constraints(problem)
    label = {c.name: c.label for c in cons}
    inf = Infeasibility(
        [],
        [
            # smallest miss, but a misfit
            _cand(1, {label["max_cost"]: 0.05, label["margin_bearing_fit"]: 0.2}),
            _cand(2, {label["max_cost"]: 0.10, label["min_life"]: 0.01}),
            _cand(3, {label["max_drag_torque"]: 0.30}),  # one limit alone frees it
            _cand(4, {"bearing bore fits screw": 1.0}),
        ],
    )
    relax, left_out, blocked = rank_relaxations(cons, inf)
    assert [(r.key, r.design_rank, r.together) for r in relax] == [
        ("limits.max_drag_torque", 3, False)
    ]
    assert relax[0].value == pytest.approx(1.2) and relax[0].relaxed_to == pytest.approx(1.2 * 1.3)
    assert (
        left_out == [(1, [label["margin_bearing_fit"]]), (4, ["bearing bore fits screw"])]
        and blocked == []
    )


def test_no_margin_is_proposed_at_zero():
    """A check missed by 100 % (its available value is 0) is never a relaxation to a margin of 0
    (issue 42): the design that misses it is left out like one that breaks a compatibility rule, and
    the answer says which check no margin frees; with every closest design so, the relaxation is
    blocked by it."""
    from axisopt.search.infeasible.relax import missing_values

    problem = load_problem(PROBLEMS / "teaching_problem.yaml")
    cons = build_constraints(problem)
    label = {c.name: c.label for c in cons}
    zero = _cand(1, {label["margin_nut_life"]: 1.0})
    inf = Infeasibility(
        [], [zero, _cand(2, {label["max_cost"]: 0.4, label["margin_nut_life"]: 0.04})]
    )
    relax, left_out, blocked = rank_relaxations(cons, inf)
    assert [(r.key, r.design_rank) for r in relax] == [
        ("limits.max_cost", 2),
        ("limits.margins.nut_life", 2),
    ]
    assert relax[1].relaxed_to == pytest.approx(0.96) and relax[1].below_vendor_rule
    assert left_out == [(1, [label["margin_nut_life"]])] and blocked == []
    assert missing_values(cons, inf) == [
        f"{label['margin_nut_life']} is 0 on design #1: no margin above 0 frees it"
    ]
    relax, _, blocked = rank_relaxations(cons, Infeasibility([], [zero]))
    assert relax == [] and blocked == [label["margin_nut_life"]]


def test_no_margin_is_proposed_below_095_and_own_limits_come_first():
    """Issue 52: a vendor margin is never proposed below 0.95 (MARGIN_FLOOR); a closest design that
    needs one lower is left out like one that breaks a compatibility rule, so a design freed by the
    user's own limits and margins down to 0.95 wins over one that needs less in total; the user's
    own limits are listed first."""
    from axisopt.search.infeasible.relax import MARGIN_FLOOR

    problem = load_problem(PROBLEMS / "teaching_problem.yaml")
    cons = build_constraints(problem)
    label = {c.name: c.label for c in cons}
    # would need 0.88: the 50 um VMC's bearing life
    deep = _cand(1, {label["margin_bearing_life"]: 0.12})
    ok = _cand(2, {label["max_cost"]: 0.2, label["margin_dn"]: 0.03, label["min_life"]: 0.01})
    relax, left_out, blocked = rank_relaxations(cons, Infeasibility([], [deep, ok]))
    assert [r.key for r in relax] == ["limits.min_life", "limits.max_cost", "limits.margins.dn"]
    assert relax[2].relaxed_to == pytest.approx(0.97) and relax[2].relaxed_to >= MARGIN_FLOOR
    assert relax[2].below_vendor_rule
    assert left_out == [(1, [label["margin_bearing_life"]])] and blocked == []
    # a margin the user set above 1 may come down to 0.95, not below
    raised = replace(problem, margins=tuple(dict(problem.margins, critical_speed=1.2).items()))
    cons = build_constraints(raised)
    label = {c.name: c.label for c in cons}
    relax, _, blocked = rank_relaxations(
        cons, Infeasibility([], [_cand(1, {label["margin_critical_speed"]: 0.2})])
    )
    assert relax[0].relaxed_to == pytest.approx(0.96) and blocked == []
    relax, _, blocked = rank_relaxations(
        cons, Infeasibility([], [_cand(1, {label["margin_critical_speed"]: 0.25})])
    )
    assert relax == [] and blocked == [label["margin_critical_speed"]]
