"""The shipped counterweighted vertical Z (problems/vertical_counterweight_problem.yaml) against the
same axis without its counterweight (problems/vertical_problem.yaml): it solves, and the
counterweight does what the servo vendors' formulas say it does -- less weight on the screw at rest
(a larger nut lift-off margin, less holding torque), less RMS torque and regenerated power, more
inertia."""

from __future__ import annotations

from pathlib import Path

import pytest

from axisopt.model import evaluate
from axisopt.problem import load_problem
from axisopt.search import solve

PROBLEMS = Path(__file__).resolve().parents[2] / "problems"


@pytest.fixture(scope="module")
def optima():
    out = {}
    for name in ("vertical_problem", "vertical_counterweight_problem"):
        r = solve(load_problem(PROBLEMS / f"{name}.yaml"), "default", top=1, sensitivities=False)
        assert r.status == "optimal" and r.best is not None
        out[name] = (r.best, evaluate(r.best.design).values)
    return out


def test_counterweighted_z_solves_and_is_counterbalanced(optima):
    best, v = optima["vertical_counterweight_problem"]
    cb = best.design.axis.counterbalance
    assert (
        cb.kind == "counterweight"
        and cb.mass == 250.0
        and cb.efficiency == 0.95
        and cb.chain_mass == 10.0
    )
    # the motor holds only the net weight at a stop: (head - counterweight) g less the guide
    # friction
    _, plain = optima["vertical_problem"]
    assert float(v["holding_torque"]) < 0.25 * float(plain["holding_torque"])


def test_counterweight_relieves_nut_motor_and_regeneration(optima):
    (b0, v0), (b1, v1) = optima["vertical_problem"], optima["vertical_counterweight_problem"]
    # the counterweight only removes load: the optimum is no worse
    assert b1.objective >= b0.objective
    assert float(v1["margin_nut_lift_off"]) > float(v0["margin_nut_lift_off"])
    assert float(v1["rms_torque"]) < float(v0["rms_torque"])
    assert float(v1["regen_power"]) < 0.5 * float(v0["regen_power"])
