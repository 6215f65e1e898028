"""The independent checker's per-vendor rules (tools/vendor_rules.py, written apart from axisopt)
against the vendors' published rules and numbers."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tools"))
import vendor_procedures as vp  # noqa: E402
import vendor_rules as vr  # noqa: E402


@pytest.mark.published
def test_servo_rules_as_published():
    # Yaskawa Sigma-7 11.2.1 / E-S 2.4.1; Mitsubishi MDS-D-SVJ3 eq. 7-10 and 7-12; FANUC B-65262EN
    # 3.1
    assert vr.servo_rule("Yaskawa")[:2] == (1.0, 1.0)
    assert vr.servo_rule("Mitsubishi Electric")[:2] == (0.8, 0.6)
    assert vr.servo_rule("FANUC")[:2] == (0.9, 0.6)
    assert vr.servo_rule("Yaskawa", 0.8)[0] == 0.8  # a design may ask its own ratio


@pytest.mark.published
def test_misumi_allowable_axial_load_example():
    # MiSUMi Economy catalog p. 1676: d 12.5 mm, fixed-support, l 820 mm, m 10 -> 3 630 N
    assert vr.misumi_buckling(12.5, 820.0)[0] == pytest.approx(3630.0, rel=0.01)


@pytest.mark.published
def test_emergency_torque_beckhoff_npt035():
    # Beckhoff AG3400 NPT035 MF i = 8: T2Em.stop 480 N.m; Yaskawa SGM7A-70A peak 54 N.m -> 432 N.m
    red = {"id": "BK-NPT035-MF-8", "ratio": 8.0, "emergency_torque": 480.0, "accel_torque": 220.0}
    row = vr.emergency_row(red, {"peak_torque": 54.0}, None, {})
    assert (row.vendor, row.limit) == (480.0, pytest.approx(432.0))
    assert vr.emergency_row(red, {"peak_torque": 54.0}, 40.0, {}).limit == pytest.approx(320.0)
    assert (
        vr.emergency_row(dict(red, emergency_torque=None), {"peak_torque": 54.0}, None, {}).vendor
        == 220.0
    )


@pytest.mark.published
def test_lift_off_load_cases_thk_a725():
    # THK A-725 horizontal transfer example: m 60 kg, mu 0.003, f 15 N, 1 m/s in 0.15 s: Fa1 417 N,
    # Fa2 17 N, Fa3 -383 N; each load case its own load: the largest is Fa1
    friction = 0.003 * 60 * 9.807 + 15.0
    phases = vp.move_phases(1.0, 1.0, 1.0 / 0.15, 0.0, 60.0, friction, 0.0)
    ax = type("Ax", (), {"axial_load": 0.0})()
    need, _ = vr.lift_off_need(ax, phases, [], friction, 0.0, 0.0, False)
    assert need == pytest.approx(417.0, abs=1.0)
    ax.axial_load = 2000.0  # a cut at feed speed: its own case, not added to the inertia
    assert vr.lift_off_need(ax, phases, [], friction, 0.0, 0.0, False)[0] == pytest.approx(
        2000.0 + friction
    )
    assert vr.lift_off_need(ax, phases, [], friction, 0.0, 2417.0, True)[0] == 2417.0
