"""An infeasible answer says what to relax (issue 30): the user's relaxable limits (problem limits and check
margins) by the smallest relative change that frees a closest design, with that design; compatibility rules
(bearing fit, screw length) are never proposed for relaxing."""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import pytest

from axisopt.cli import main
from axisopt.problem import load_problem
from axisopt.search import solve
from axisopt.search.infeasible.relax import rank_relaxations
from axisopt.search.result import Candidate, Infeasibility
from axisopt.search.task.constraints import build_constraints

PROBLEMS = Path(__file__).resolve().parents[3] / "problems"


def test_infeasible_problem_first_lines_name_the_limit_and_the_amount(capsys):
    assert main(["solve", str(PROBLEMS / "infeasible_problem.yaml"), "--no-sensitivity", "--json", "-"]) == 1
    inf = json.loads(capsys.readouterr().out)["infeasibility"]
    relax = inf["relax"]
    assert [r["change"] for r in relax] == sorted(r["change"] for r in relax)  # smallest change first
    keys = [r["key"] for r in relax]
    assert "limits.max_cost" in keys and "limits.min_stiffness" in keys
    assert not any("bearing_fit" in k or "screw_length" in k for k in keys)  # compatibility rules apart
    # a compatibility rule weighs more than any limit (search.explain.RULE_WEIGHT): the proposed design keeps
    # every rule (the THK BLW 40x40 shaft is long enough for the 3 m stroke), so no rule blocks the relaxation
    assert inf["relax_blocked_by"] == []
    assert all(not any(w in m for w in ("bore", "screw max length")) for m in inf["closest"][0]["misses"])
    cost = relax[keys.index("limits.max_cost")]
    assert cost["value"] == 300 and cost["relaxed_to"] == pytest.approx(300 * (1 + cost["change"]))
    assert cost["relaxed_to"] >= inf["unmeetable"][0]["best_achievable"]  # no design is cheaper than that
    assert cost["parts"]["screw"] and cost["design_rank"] in [c["rank"] for c in inf["closest"]]

    assert main(["solve", str(PROBLEMS / "infeasible_problem.yaml"), "--no-sensitivity"]) == 1
    text = capsys.readouterr().out
    first = "\n".join(text.splitlines()[:24])
    assert "relax these" in first and "then meets every limit" in first
    assert f"limits.max_cost from 300 EUR to {cost['relaxed_to']:,.0f} EUR (+{100 * cost['change']:,.0f} %)" in first
    stiff = relax[keys.index("limits.min_stiffness")]
    assert f"limits.min_stiffness from 400 N/um to {stiff['relaxed_to']:.4g} N/um" in first


def test_the_relaxations_free_the_design():
    """The SGM7J motors give no brake torque: the holding-brake check, failed by 100 %, is never proposed at a
    margin of 0; it blocks the relaxation and the answer says which rows lack the value (issue 42).  The other
    relaxations free the design once that check is switched off by hand (what the answer leaves to the user)."""
    problem = load_problem(PROBLEMS / "infeasible_drive_problem.yaml")
    res = solve(problem, sensitivities=False)
    inf = res.infeasibility
    brake = next(c.label for c in build_constraints(problem) if c.name == "margin_brake_holding")
    assert res.status == "infeasible" and inf.relax and inf.relax_blocked_by == [brake]
    assert len(inf.missing) == 1 and "Sigma-7 SGM7J give no brake torque" in inf.missing[0]
    assert {r.key for r in inf.relax} >= {"limits.margins.motor_peak_torque", "limits.margins.inertia_ratio"}
    assert all(r.below_vendor_rule and r.relaxed_to > 0 for r in inf.relax)  # only the motor's checks miss
    margins = dict(problem.margins) | {"brake_holding": 0.0}
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
    return Candidate(rank, rank, "fixed-fixed", "s", "n", "b", "g", 1000.0, 0.0, 50.0, 100.0, 1000.0, 100.0,
                     110.0, 0.5, 1e4, misses=misses)


def test_one_limit_alone_beats_several_and_compatibility_rules_are_left_out():
    problem = load_problem(PROBLEMS / "teaching_problem.yaml")
    cons = build_constraints(problem)
    label = {c.name: c.label for c in cons}
    inf = Infeasibility([], [
        _cand(1, {label["max_cost"]: 0.05, label["margin_bearing_fit"]: 0.2}),  # smallest miss, but a misfit
        _cand(2, {label["max_cost"]: 0.10, label["min_life"]: 0.01}),
        _cand(3, {label["max_drag_torque"]: 0.30}),  # one limit alone frees it
        _cand(4, {"bearing bore fits screw": 1.0}),
    ])
    relax, left_out, blocked = rank_relaxations(cons, inf)
    assert [(r.key, r.design_rank, r.together) for r in relax] == [("limits.max_drag_torque", 3, False)]
    assert relax[0].value == pytest.approx(1.2) and relax[0].relaxed_to == pytest.approx(1.2 * 1.3)
    assert left_out == [(1, [label["margin_bearing_fit"]]), (4, ["bearing bore fits screw"])] and blocked == []


def test_no_margin_is_proposed_at_zero():
    """A check missed by 100 % (its available value is 0) is never a relaxation to a margin of 0 (issue 42): the
    design that misses it is left out like one that breaks a compatibility rule, and the answer says which check
    no margin frees; with every closest design so, the relaxation is blocked by it."""
    from axisopt.search.infeasible.relax import missing_values

    problem = load_problem(PROBLEMS / "teaching_problem.yaml")
    cons = build_constraints(problem)
    label = {c.name: c.label for c in cons}
    zero = _cand(1, {label["margin_nut_life"]: 1.0})
    inf = Infeasibility([], [zero, _cand(2, {label["max_cost"]: 0.4, label["margin_nut_life"]: 0.5})])
    relax, left_out, blocked = rank_relaxations(cons, inf)
    assert [(r.key, r.design_rank) for r in relax] == [("limits.max_cost", 2), ("limits.margins.nut_life", 2)]
    assert relax[1].relaxed_to == pytest.approx(0.5) and relax[1].below_vendor_rule
    assert left_out == [(1, [label["margin_nut_life"]])] and blocked == []
    assert missing_values(cons, inf) == [f"{label['margin_nut_life']} is 0 on design #1: no margin above 0 frees it"]
    relax, _, blocked = rank_relaxations(cons, Infeasibility([], [zero]))
    assert relax == [] and blocked == [label["margin_nut_life"]]
