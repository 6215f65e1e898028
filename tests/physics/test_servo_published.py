"""The servo tuning rules (physics.servo) against their published examples: Yaskawa manual tuning,
FANUC position-loop rule, Heidenhain following error; float, numpy and CasADi agree."""

from __future__ import annotations

import math

import numpy as np
import pytest

from axisopt.physics.servo import KV_M_MIN_PER_MM, following_error, kv_rule, yaskawa_gains


# Yaskawa Sigma E-S / Sigma-7 product manual, 8.8.1 Manual Tuning: "If Pn100 = 40.0 [Hz], then Pn101
# = 4,000/(2 pi x 40.0) ~ 15.92 [ms]"; torque reference filter guide Pn401 [ms] <= 1000/(2 pi Pn100
# x 4).
@pytest.mark.published
def test_yaskawa_manual_tuning_example():
    y = yaskawa_gains(40.0)
    assert round(y["Pn101_ms"], 2) == 15.92
    assert y["Pn401_ms"] == pytest.approx(1000.0 / (2 * math.pi * 40.0 * 4), rel=1e-12)
    assert round(y["Pn401_ms"], 2) == 0.99


# FANUC AC servo motor alpha-i series descriptions B-65262EN/03, sec. 2 (machine rigidity): "when
# setting 20 [sec-1] as the value of position loop gain, natural frequency of machine system must be
# more than 20 [Hz]".  Heidenhain iTNC 530 technical manual: following error s_a = v_e / k_v, k_v in
# (m/min)/mm.
@pytest.mark.published
def test_fanuc_rule_and_heidenhain_following_error():
    assert kv_rule(20.0) == pytest.approx(20.0)
    assert 20.0 / KV_M_MIN_PER_MM == pytest.approx(1.2)
    # 1 (m/min)/mm gives 1 mm lag at 1 m/min
    assert following_error(1.0 / 60.0, 1.0 * KV_M_MIN_PER_MM) == pytest.approx(1e-3)


def test_servo_formulas_on_float_numpy_and_casadi():
    import casadi as ca

    f, v, k = 84.7, 0.4, 84.7
    assert float(ca.DM(kv_rule(ca.DM(f)))) == pytest.approx(kv_rule(f))
    np.testing.assert_allclose(kv_rule(np.array([f, 2 * f])), [kv_rule(f), kv_rule(2 * f)])
    assert float(ca.DM(following_error(ca.DM(v), ca.DM(k)))) == pytest.approx(following_error(v, k))
