"""The drive's parameters (model.driveparams): a reduction's emergency torque against the motor's
peak times the ratio, from the vendors' published rows."""

import pytest

from axisopt.catalog.loading import default_catalog


@pytest.mark.published
def test_reduction_emergency_torque_against_motor_peak_times_ratio():
    """Beckhoff AG3400 NPT035 MF (infosys.beckhoff.com ag3400_ba 9197685643): T2Em.stop 480 N.m, T2B
    220 N.m at i = 8; the SGM7A-70A's instantaneous peak 54 N.m (YSK-S7) through 8:1 gives 432 N.m
    at an emergency stop or a collision (Siemens 1FT7 5.4.1: Mmax,gear >= M0 i f; apexdyna: output
    torque = motor torque x ratio).  A drive torque limit of 40 N.m caps it at 320 N.m (the same
    limit the coupling sees)."""
    from dataclasses import replace

    from axisopt.design import Axis
    from axisopt.model.driveparams import drive_params

    cat = default_catalog()
    motor, red = cat.part("motors", "SGM7A-70A"), cat.part("reductions", "BK-NPT035-MF-8")
    axis = Axis(
        stroke=1.0, moving_mass=100.0, mounting="fixed-supported", max_speed=0.1, axial_load=0.0
    )
    q = drive_params(axis, motor, None, red)
    assert q["reduction_emergency_torque"] == pytest.approx(480.0)
    assert q["motor_peak_torque"] * q["reduction_ratio"] == pytest.approx(432.0)
    q = drive_params(replace(axis, torque_limit=40.0), motor, None, red)
    assert q["motor_peak_torque"] * q["reduction_ratio"] == pytest.approx(320.0)
    # a reduction row without an emergency torque: its T2B stands in (never above the emergency
    # torque)
    row = dict(red)
    row["emergency_torque"] = float("nan")
    assert drive_params(axis, motor, None, row)["reduction_emergency_torque"] == pytest.approx(
        220.0
    )
