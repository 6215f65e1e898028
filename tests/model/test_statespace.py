"""The state-space model (model.statespace) is the model: its eigenfrequencies are the model's modes at every
nut position, its frequency response is ``--frf``'s curve; python-control round trip; the servo rule's
published examples (model.servo, physics.servo)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from axisopt.design import load_design
from axisopt.model import design_params, evaluate
from axisopt.model.frf import chain_at, frf, frf_positions
from axisopt.model.servo import closed_loop, servo_response
from axisopt.model.statespace import second_order, state_space
from axisopt.physics import dynamics as pdy
from axisopt.physics.servo import KV_M_MIN_PER_MM, following_error, kv_rule, yaskawa_gains

PROBLEMS = Path(__file__).resolve().parents[2] / "problems"
DESIGNS = ("vmc_x_design.yaml", "teaching_design.yaml", "custom_parts_design.yaml")


@pytest.fixture(scope="module", params=DESIGNS)
def ev(request):
    return evaluate(load_design(PROBLEMS / request.param))


def test_open_loop_eigenfrequencies_are_the_model_modes_at_every_position(ev):
    for i in range(len(ev.x)):
        free = state_space(ev, i)
        f = free.natural_frequencies()
        assert f == pytest.approx([ev.at("f_axial_torsional", i), ev.at("f_axial_torsional_2", i)], rel=1e-9)
        # the undamped A has the same frequencies as its eigenvalues (and the rigid-body pair at 0)
        lam = np.sort(np.abs(state_space(ev, i, damping_scale=0.0).poles())) / (2 * math.pi)
        assert lam[:2] == pytest.approx([0, 0], abs=1e-3)
        assert lam[2::2] == pytest.approx(f, rel=1e-7)
        held = state_space(ev, i, motor_held=True)
        m = held.mass.diagonal()
        r = held.lead / (2 * math.pi)
        k_c = held.stiffness[0, 0] - ev.at("k_drive", i) * r**2
        want = pdy.axial_torsional_frequencies(m[0], k_c, ev.at("k_drive", i), m[1], held.lead)
        assert held.natural_frequencies() == pytest.approx(want, rel=1e-9)
        # the headline axial mode f_axial (motor held) leaves out the screw's rotary inertia on the coupling:
        # the held model's first mode is at or below it and equal to it without that inertia
        assert held.natural_frequencies()[0] <= ev.at("f_axial", i) * (1 + 1e-12)
        spring = chain_at(ev, design_params(ev.design), i)
        spring["screw_inertia"] = 1e-12 * spring["screw_inertia"]
        mass, stiff, _ = second_order(spring)
        lam = np.linalg.eigvals(np.linalg.solve(mass[1:, 1:], stiff[1:, 1:])).real
        assert math.sqrt(min(lam)) / (2 * math.pi) == pytest.approx(ev.at("f_axial", i), rel=1e-6)


@pytest.mark.parametrize("held", [False, True])
def test_frequency_response_equals_frf_curve(ev, held):
    r = frf(ev, motor_held=held)
    for q, i in zip(r["positions"], frf_positions(ev)):
        ss = state_space(ev, i, motor_held=held)
        h = ss.frequency_response(r["frequency_Hz"], "process_force", "table_position")
        np.testing.assert_allclose(h, q["compliance_m_per_N"], rtol=1e-9)
        assert tuple(ss.natural_frequencies()) == pytest.approx(q["modes_Hz"], rel=1e-9)


def test_python_control_round_trip(ev):
    control = pytest.importorskip("control")
    ss = state_space(ev, 0)
    sys = ss.to_control()
    assert isinstance(sys, control.StateSpace)
    np.testing.assert_array_equal(sys.A, ss.A)
    np.testing.assert_array_equal(sys.B, ss.B)
    assert list(sys.input_labels) == list(ss.inputs) and list(sys.output_labels) == list(ss.outputs)
    f = np.array([20.0, 84.0, 300.0])
    h = np.asarray(sys(2j * math.pi * f))[ss.outputs.index("table_position"), ss.inputs.index("process_force")]
    np.testing.assert_allclose(h, ss.frequency_response(f), rtol=1e-9)
    held = state_space(ev, 0, motor_held=True).to_control()
    assert held.nstates == 4


# Yaskawa Sigma E-S / Sigma-7 product manual, 8.8.1 Manual Tuning: "If Pn100 = 40.0 [Hz], then
# Pn101 = 4,000/(2 pi x 40.0) ~ 15.92 [ms]"; torque reference filter guide Pn401 [ms] <= 1000/(2 pi Pn100 x 4).
@pytest.mark.published
def test_yaskawa_manual_tuning_example():
    y = yaskawa_gains(40.0)
    assert round(y["Pn101_ms"], 2) == 15.92
    assert y["Pn401_ms"] == pytest.approx(1000.0 / (2 * math.pi * 40.0 * 4), rel=1e-12)
    assert round(y["Pn401_ms"], 2) == 0.99


# FANUC AC servo motor alpha-i series descriptions B-65262EN/03, sec. 2 (machine rigidity): "when setting 20
# [sec-1] as the value of position loop gain, natural frequency of machine system must be more than 20 [Hz]".
# Heidenhain iTNC 530 technical manual: following error s_a = v_e / k_v, k_v in (m/min)/mm.
@pytest.mark.published
def test_fanuc_rule_and_heidenhain_following_error():
    assert kv_rule(20.0) == pytest.approx(20.0)
    assert 20.0 / KV_M_MIN_PER_MM == pytest.approx(1.2)
    # 1 (m/min)/mm gives 1 mm lag at 1 m/min
    assert following_error(1.0 / 60.0, 1.0 * KV_M_MIN_PER_MM) == pytest.approx(1e-3)


def test_tuned_servo_is_stable_on_the_model(ev):
    r = servo_response(ev)
    g = r.gains
    assert g.kv == pytest.approx(float(np.min(ev["f_axial"])))
    assert all(r.stable) and min(r.min_damping) > 0
    # the closed position loop is roughly first order at Kv: its -3 dB near Kv / 2 pi
    for bw in r.position_bandwidth_Hz:
        assert 0.8 * g.kv / (2 * math.pi) < bw < 2.0 * g.kv / (2 * math.pi)
    # at constant speed the motor lags v / Kv; the table as much again as the guides' viscous damper deflects
    # the chain (c_g v / k_total): ramp x_ref = v t, z(t) = z1 t + z0 with A z1 = -b v, A z0 = z1
    i = frf_positions(ev)[1]
    A, B, C, D = closed_loop(state_space(ev, i), g)
    v = 0.1
    z1 = -np.linalg.solve(A, B[:, 0] * v)
    z0 = np.linalg.solve(A, z1)
    assert C[0] @ z1 == pytest.approx(v, rel=1e-9)
    assert -C[2] @ z0 == pytest.approx(following_error(v, g.kv), rel=1e-6)
    c_g = float(ev.design.guide["damping"]) * ev.design.axis.guide_blocks
    assert -C[0] @ z0 == pytest.approx(following_error(v, g.kv) + c_g * v / ev.at("k_total", i), rel=1e-3)


def test_servo_formulas_on_float_numpy_and_casadi():
    import casadi as ca

    f, v, k = 84.7, 0.4, 84.7
    assert float(ca.DM(kv_rule(ca.DM(f)))) == pytest.approx(kv_rule(f))
    np.testing.assert_allclose(kv_rule(np.array([f, 2 * f])), [kv_rule(f), kv_rule(2 * f)])
    assert float(ca.DM(following_error(ca.DM(v), ca.DM(k)))) == pytest.approx(following_error(v, k))
