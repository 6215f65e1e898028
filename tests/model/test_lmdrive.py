"""The linear-motor sub-assembly (model.lmdrive): attraction force loads the guides and friction, as
the vendor's sizing steps say (restated here)."""

from __future__ import annotations

import math

import pytest
from drive_cases import CYCLE, GUIDE, LM

from axisopt.model.lmdrive import lm_response
from axisopt.model.rackdrive import guide_response


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
