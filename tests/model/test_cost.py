"""The parts cost of an axis (model.cost): a bill of materials added up by hand, for one drive and a
twin drive (the second drive's screw, nut, bearings, motor, coupling and reduction; the guides are
shared)."""

from __future__ import annotations

import casadi as ca
import numpy as np
import pytest

from axisopt.model.cost import cost

# a 1.2 m screw at 80 EUR/m plus 150 EUR end machining in a grade priced 1.5 times the base
PARTS = {
    "screw_price_per_length": 80.0,
    "span": 1.2,
    "screw_price_fixed": 150.0,
    "grade_price_factor": 1.5,
    "nut_price": 210.0,
    "bearing_sets": 2.0,
    "bearing_price": 95.0,
    "guide_blocks": 4.0,
    "guide_block_price": 60.0,
    "rails": 2.0,
    "rail_length": 1.5,
    "guide_rail_price_per_length": 40.0,
    "motor_price": 900.0,
    "coupling_price": 70.0,
    "reduction_price": 0.0,
}
SCREW = (80.0 * 1.2 + 150.0) * 1.5  # 369
ONE_DRIVE = SCREW + 210.0 + 2 * 95.0 + 4 * 60.0 + 2 * 1.5 * 40.0 + 900.0 + 70.0 + 0.0  # 2 099


def test_one_drive_bill_of_materials():
    assert ONE_DRIVE == pytest.approx(2099.0)
    assert float(cost(PARTS)) == pytest.approx(ONE_DRIVE, rel=1e-14)  # no ``twin``: one drive
    assert float(cost({**PARTS, "twin": 0.0})) == pytest.approx(ONE_DRIVE, rel=1e-14)


def test_twin_drive_buys_the_second_drive_not_the_guides():
    second = SCREW + 210.0 + 2 * 95.0 + 900.0 + 70.0
    assert float(cost({**PARTS, "twin": 1.0})) == pytest.approx(ONE_DRIVE + second, rel=1e-14)


def test_arrays_and_symbols():
    prices = np.array([900.0, 1400.0])
    np.testing.assert_allclose(
        cost({**PARTS, "motor_price": prices}), ONE_DRIVE - 900.0 + prices, rtol=1e-14
    )
    m = ca.SX.sym("m")
    f = ca.Function("f", [m], [cost({**PARTS, "motor_price": m})])
    assert float(f(1400.0)) == pytest.approx(ONE_DRIVE + 500.0, rel=1e-14)
