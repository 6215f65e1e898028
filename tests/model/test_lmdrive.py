"""The linear-motor sub-assembly (model.lmdrive): attraction force loads the guides and friction, as the
vendor's sizing steps say (restated here)."""

from __future__ import annotations

import math

import pytest

from axisopt.model.lmdrive import lm_response
from axisopt.model.rackdrive import guide_response
from axisopt.physics.motion import Segment, cycle_phases
from axisopt.physics.rack import cycle_gram

CYCLE = cycle_gram(
    cycle_phases(
        (
            Segment("move", distance=2.0, speed=0.67, acceleration=3.0, force=750.0),
            Segment("move", distance=-2.0, speed=0.67, acceleration=3.0),
            Segment("dwell", duration=0.5),
        )
    )
)


LM = {
    "m_axis": 100.0,
    "m_blocks": 4.0,
    "mu": 0.004,
    "f_seal": 10.0,
    "normal": 0.0,
    "vertical": 0.0,
    "forcers": 2.0,
    "fc": 875.0,
    "fp": 2469.0,
    "kf": 60.0,
    "m_forcer": 14.5,
    "fa": 4375.0,
    "accuracy": 4e-6,
    "t_acc": 0.2,
    "bandwidth": 50.0,
    "k_n": 4e8,
    "blocks": 4.0,
    "thrust": 200.0,
    "mean_thrust": 100.0,
}


GUIDE = {
    "vertical": 0.0,
    "normal": 500.0,
    "blocks": 2.0,
    "c_block": 38e3,
    "c0_block": 52e3,
    "roller": 0.0,
    "rating_distance": 5e4,
    "fw": 1.2,
    "life_needed": 2e7,
    "static_safety": 5.0,
}


def test_linear_motor_attraction_loads_friction_and_guides():
    p = LM
    res = lm_response(p, CYCLE)
    m = p["m_axis"] + p["m_blocks"] + 2 * p["m_forcer"]
    ff = p["mu"] * (m * 9.80665 + 2 * p["fa"]) + p["f_seal"]  # HIWIN: (M g + Fa) mu
    assert res["outputs"]["feed_force"] == pytest.approx(m * 3.0 + ff + 750.0, rel=1e-12)
    assert res["margins"]["motor_peak"] == pytest.approx(
        2 * 2469.0 / (m * 3.0 + ff + 750.0), rel=1e-12
    )
    assert res["outputs"]["stiffness"] == pytest.approx(m * (2 * math.pi * 50.0) ** 2, rel=1e-12)
    g = guide_response(
        {**GUIDE, "normal": 0.0, "blocks": 4.0}, m, res["outputs"]["attraction_force"]
    )
    assert g["outputs"]["block_load"] == pytest.approx((m * 9.80665 + 2 * 4375.0) / 4, rel=1e-12)
