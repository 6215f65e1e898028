"""Drive torque losses (physics.friction) against THK's published forms: the positive efficiency of
a ball screw, the torque to push an axial force (work per revolution) and the drag torque at
constant speed."""

from __future__ import annotations

import math

import casadi as ca
import numpy as np
import pytest

from axisopt.physics import friction as pf


@pytest.mark.published
@pytest.mark.parametrize(
    "d, lead, mu", [(0.032, 0.010, 0.003), (0.020, 0.005, 0.005), (0.050, 0.040, 0.01)]
)
def test_positive_efficiency_thk_form(d, lead, mu):
    # THK General Catalog, ball screw, "Efficiency": eta1 = (1 - mu tan beta) / (1 + mu / tan beta),
    # with the lead angle tan beta = Ph / (pi d); THK: 90 to 95 % or more for a ball screw at mu
    # 0.003-0.01
    tan_b = lead / (math.pi * d)
    eta = (1 - mu * tan_b) / (1 + mu / tan_b)
    assert pf.screw_efficiency(math.atan(tan_b), mu) == pytest.approx(eta, rel=1e-12)
    assert 0.85 < eta < 0.99


def test_axial_force_torque_is_work_per_revolution():
    # one revolution moves the force F by one lead: T 2 pi eta = F Ph
    f, lead, eta = 2500.0, 0.016, 0.92
    assert pf.axial_force_torque(f, lead, eta) * 2 * math.pi * eta == pytest.approx(
        f * lead, rel=1e-14
    )
    assert pf.axial_force_torque(-f, lead, eta) == pytest.approx(
        -pf.axial_force_torque(f, lead, eta)
    )


def test_drag_torque_adds_its_sources():
    # THK A-743..A-746: preload drag + bearings + seals + guide friction through the lead
    t = pf.motor_drag_torque(0.3, 0.12, 40.0, 0.010, 0.9, seal_torque=0.05)
    assert t == pytest.approx(0.3 + 0.12 + 0.05 + 40.0 * 0.010 / (2 * math.pi * 0.9), rel=1e-14)


def test_float_numpy_casadi_agree():
    args = (0.1, 0.004)
    f = pf.screw_efficiency(*args)
    assert float(ca.DM(pf.screw_efficiency(ca.DM(args[0]), ca.DM(args[1])))) == pytest.approx(
        f, rel=1e-14
    )
    arr = pf.screw_efficiency(np.array([0.1, 0.2]), 0.004)
    np.testing.assert_allclose(arr, [f, pf.screw_efficiency(0.2, 0.004)], rtol=1e-14)
    x = ca.SX.sym("x")
    g = ca.Function("g", [x], [pf.motor_drag_torque(x, 0.1, 30.0, 0.01)])
    assert float(g(0.2)) == pytest.approx(pf.motor_drag_torque(0.2, 0.1, 30.0, 0.01), rel=1e-14)
