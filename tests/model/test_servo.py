"""The state-space model (model.statespace) is the model: its eigenfrequencies are the model's modes at every
nut position, its frequency response is ``--frf``'s curve; python-control round trip; the servo rule's
published examples (model.servo, physics.servo)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from axisopt.design import load_design
from axisopt.model import evaluate
from axisopt.model.frf import frf_positions
from axisopt.model.servo import closed_loop, servo_response
from axisopt.model.statespace import state_space
from axisopt.physics.servo import KV_M_MIN_PER_MM, following_error, kv_rule, yaskawa_gains

PROBLEMS = Path(__file__).resolve().parents[2] / "problems"
DESIGNS = ("vmc_x_design.yaml", "teaching_design.yaml", "custom_parts_design.yaml")


@pytest.fixture(scope="module", params=DESIGNS)
def ev(request):
    return evaluate(load_design(PROBLEMS / request.param))


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
