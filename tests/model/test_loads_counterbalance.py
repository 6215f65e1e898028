"""A counterbalanced vertical axis through the whole model, on THK's vertical conveyance example
(A-736 to A-746: table 40 kg + work 10 kg, guide resistance f = 20 N, lead 10 mm, eta 0.9; published
without a counterweight: J = 1.58e-4 kg m^2, Tt1 900, Tt2 830, TS 658 N.mm), with a counterweight
added as the servo vendors write it: its weight off the head's (Mitsubishi MR-J2S-A eq. 11-20,
Yaskawa Sigma-7 11.2.1, Fuji ALPHA5 Smart ch. 15 "at a stop"), its mass added to the inertia
(Yaskawa: J_L1 = (M + M_c)(P_B / 2 pi)^2).  No worked example with a counterweight in numbers
was found: the expected values below are those formulas at THK's numbers.
"""

from __future__ import annotations

import math

import casadi as ca
import numpy as np
import pytest
from test_response_duty_mass import THK_CYCLE, _design

from axisopt.design import load_design
from axisopt.model import (
    PARAM_NAMES,
    PROFILE_OUTPUTS,
    SCALAR_OUTPUTS,
    axis_response,
    design_params,
    evaluate,
)
from axisopt.physics import counterbalance as pcb

G = 9.80665
LEAD, ETA = 0.010, 0.9
PER_N = LEAD / (2 * math.pi * ETA)  # motor torque per newton through the screw [N m / N]


def _with(cycle: str, cb: str) -> str:
    return f"  counterbalance: {cb}\n" + cycle


def _thk(tmp_path, cb: str | None, name="d.yaml"):
    """THK's example through the model as tests/model/test_response_duty_mass.py runs it (its screw,
    no coupling, no support-bearing drag, no nut preload), with a counterbalance."""
    cycle = THK_CYCLE if cb is None else _with(THK_CYCLE, cb)
    p = design_params(load_design(_design(tmp_path, cycle, name)))
    p.update(coupling_inertia=0.0, bearing_torque=0.0, span=0.8)
    return p, axis_response(p, np.array([0.1]), "fixed-supported", 0.0)


@pytest.mark.published
def test_counterweight_torques_on_thk_vertical(tmp_path):
    _, base = _thk(tmp_path, None, "a.yaml")
    mc, eta_p = 20.0, 0.9
    _, out = _thk(
        tmp_path, f"{{kind: counterweight, mass: {mc} kg, efficiency: {eta_p}}}", "b.yaml"
    )
    t0 = [float(t[0]) for t in base["duty_torques"]]
    t1 = [float(t[0]) for t in out["duty_torques"]]
    #
    assert t0[1] * 1e3 == pytest.approx(900, abs=3) and t0[4] * 1e3 == pytest.approx(830, abs=3)
    # rising at speed: the counterweight's pull through its chain (eta_p) off the head's: THK's Tt1
    # less it
    assert t1[1] == pytest.approx(t0[1] - mc * G * eta_p * PER_N, rel=1e-9)
    # lowering: the head lifts the counterweight and the chain's friction (/ eta_p)
    assert t1[4] == pytest.approx(t0[4] - mc * G / eta_p * PER_N, rel=1e-9)
    # at the stop (A-745, the work removed): TS with (m1 - m_c), Fuji's "at a stop" (W1 - W2)
    assert t1[-1] == pytest.approx(((40 - mc) * G - 20) * PER_N, rel=1e-9)
    assert t0[-1] * 1e3 == pytest.approx(658, abs=0.5)
    # the brake holds the heaviest stop, the work on: (50 - m_c) g - f
    assert float(out["holding_torque"]) == pytest.approx(((50 - mc) * G - 20) * PER_N, rel=1e-9)
    # Yaskawa's J_L1 = (M + M_c)(P_B / 2 pi)^2: THK's J (A-744, 1.58e-4) plus the counterweight
    assert float(base["load_inertia"]) == pytest.approx(1.58e-4, abs=0.005e-4)
    assert float(out["load_inertia"]) == pytest.approx(
        float(base["load_inertia"]) + pcb.counterweighted_inertia(0.0, mc, LEAD), rel=1e-9
    )
    # accelerating up: the counterweight's mass accelerates too (inertia) -- so the peak falls by
    # less than its weight
    assert t1[0] - t1[1] > t0[0] - t0[1]
    assert float(out["rms_torque"]) < float(base["rms_torque"])
    assert float(out["regen_energy"]) < float(base["regen_energy"])  # less weight lowered


def test_counterweight_unloads_the_nut_and_keeps_the_lift_off(tmp_path):
    p0, base = _thk(tmp_path, None, "a.yaml")
    mc = 30.0
    p1, out = _thk(
        tmp_path,
        f"{{kind: counterweight, mass: {mc} kg, efficiency: 1.0, chain_mass: 2 kg}}",
        "b.yaml",
    )
    acc = p0["acceleration"]
    # the largest axial force: rising and accelerating, the counterweight's weight off and its mass
    # (and the chain's) accelerated with the head
    assert float(out["max_axial_force"]) == pytest.approx(
        float(base["max_axial_force"]) - mc * G + (mc + 2.0) * acc, rel=1e-9
    )
    assert float(out["mean_axial_force"]) == pytest.approx(
        float(base["mean_axial_force"]) - mc * G, rel=1e-9
    )
    assert float(out["life"]) > float(base["life"])


def test_cylinder_takes_its_worst_end(tmp_path):
    _, base = _thk(tmp_path, None, "a.yaml")
    # 300..350 N over the stroke, +/- 5 %: the head (50 kg, 490 N) outweighs it, so 300 x 0.95 = 285
    # N loads most
    _, out = _thk(
        tmp_path, "{kind: cylinder, force: 300 N, force_at_end: 350 N, tolerance: 5 %}", "b.yaml"
    )
    assert float(out["max_axial_force"]) == pytest.approx(
        float(base["max_axial_force"]) - 285.0, rel=1e-9
    )
    # overbalanced: 600..650 N, the largest end (682.5 N) pushes the head up harder than any other
    _, over = _thk(
        tmp_path, "{kind: cylinder, force: 600 N, force_at_end: 650 N, tolerance: 5 %}", "c.yaml"
    )
    t = [float(x[0]) for x in over["duty_torques"]]
    t0 = [float(x[0]) for x in base["duty_torques"]]
    # the stop: the cylinder holds the head up (the motor holds nothing, friction helps)
    assert t[-1] == 0.0
    # lowering: the motor pulls the head down
    assert t[4] == pytest.approx(t0[4] - 682.5 * PER_N, rel=1e-9)
    assert t[4] < 0.0
    # the largest axial force: the cylinder's excess over the head's weight pushing up, with inertia
    # and friction
    w = float(base["moving_mass"]) * G
    assert float(over["max_axial_force"]) == pytest.approx(
        float(base["max_axial_force"]) - w + (682.5 - w), rel=1e-9
    )


@pytest.mark.parametrize(
    "cb",
    [
        "{kind: counterweight, mass: 35 kg, efficiency: 0.93, chain_mass: 3 kg}",
        "{kind: cylinder, force: 400 N, force_at_end: 450 N, tolerance: 5 %, piston_mass: 2 kg}",
    ],
)
def test_float_numpy_casadi_agree(tmp_path, cb):
    d = load_design(_design(tmp_path, _with(THK_CYCLE, cb)))
    ev_np = evaluate(d, use_casadi=False)
    ev_ca = evaluate(d, use_casadi=True)
    for k in PROFILE_OUTPUTS + SCALAR_OUTPUTS:
        assert np.allclose(ev_np[k], ev_ca[k], rtol=1e-10), k
    p = design_params(d)
    sym = ca.SX.sym("p", len(PARAM_NAMES))
    out = axis_response(
        {n: sym[i] for i, n in enumerate(PARAM_NAMES)} | {"duty": p["duty"]},
        ca.DM([0.1]),
        d.axis.mounting,
        d.preload,
    )
    names = ("rms_torque", "holding_torque", "max_axial_force", "margin_nut_life", "regen_power")
    f = ca.Function("f", [sym], [out[n] for n in names])
    for n, v in zip(names, f([p[n] for n in PARAM_NAMES])):
        assert float(v) == pytest.approx(float(np.ravel(ev_np[n])[0]), rel=1e-9), n
