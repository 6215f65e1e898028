"""Issue 26: the heat balance of the screw (friction power -> temperature rise -> thermal growth)."""

import math

import pytest

from axisopt.physics import thermal

RPM = 2.0 * math.pi / 60.0


def test_jungnickel_rotating_cylinder_film_coefficient():
    # Jungnickel 2010 (TU Dresden), as in Thermca forced_conv.rot_cyl_in_air: alpha = 3.75 omega^0.7 r^0.4;
    # a 40 mm shaft at 1000 rpm: 3.75 x 104.7^0.7 x 0.02^0.4 = 20.3 W/(m^2 K)
    assert thermal.rotating_shaft_heat_transfer(1000 * RPM, 0.02) == pytest.approx(20.3, abs=0.05)


def test_tian_he_heat_generation_is_torque_times_speed():
    # Tian & He (2004), cited in Machines 2023, 11(3), 408 eq. 1: Q [kJ/h] = 0.12 pi n [rpm] tau [N.m]: the friction
    # power T omega the heat balance uses.  1 N.m at 1000 rpm: 377 kJ/h = 104.7 W
    power = 1.0 * 1000 * RPM
    assert power * 3.6 == pytest.approx(0.12 * math.pi * 1000 * 1.0, rel=1e-12)
    area = math.pi * 0.04 * 1.0
    h = thermal.rotating_shaft_heat_transfer(1000 * RPM, 0.02)
    assert thermal.friction_temperature_rise(power, h, area) == pytest.approx(power / (h * area))


def test_thk_thermal_displacement_example():
    # THK General Catalog A-732 eq. 38: a 5 degC rise over 1000 mm, rho = 12e-6/degC: 0.06 mm
    assert thermal.thermal_growth(1.0, 5.0, alpha=12e-6) == pytest.approx(0.06e-3, abs=0.005e-3)


def test_heat_balance_is_of_the_order_of_thks_heat_generation_test():
    """THK General Catalog A-821 (wiper ring W heat-generation test): BLK3232 (32 mm shaft, lead 32) at 1000 rpm,
    32 m/min, 1000 mm stroke, 100 ms time constant: the shaft centre rose 8.9-12.2 degC after 90 min.  THK prints
    no drag torque; with a light-preload drag of 0.1-0.3 N.m (HIWIN Table 3.16 band 0.2-0.4 N.m) on a 1.4 m shaft
    the convection-only balance gives the same order (it is an upper estimate: no conduction to the housings)."""
    omega = 0.9 * 1000 * RPM  # mean of a 1000 mm reciprocating stroke with 100 ms ramps
    h = thermal.rotating_shaft_heat_transfer(omega, 0.016)
    area = math.pi * 0.032 * 1.4
    rises = [thermal.friction_temperature_rise(t * omega, h, area) for t in (0.1, 0.3)]
    assert rises[0] < 8.9 and 12.2 < 1.1 * rises[1]  # 3.9 and 11.6 K


def test_negative_heat_transfer_is_a_one_line_error(tmp_path, capsys):
    from pathlib import Path

    from axisopt.cli import main

    src = Path(__file__).resolve().parents[2] / "problems" / "duty_cycle_problem.yaml"
    text = src.read_text(encoding="utf-8").replace("  jerk: 100 m/s^3\n",
                                                   "  jerk: 100 m/s^3\n  heat_transfer: -20 W/(m^2.K)\n")
    p = tmp_path / "p.yaml"
    p.write_text(text, encoding="utf-8")
    assert main(["solve", str(p)]) == 2
    err = capsys.readouterr().err.strip()
    assert "heat_transfer" in err and "positive" in err and len(err.splitlines()) == 1


def test_holman_free_convection_rise_meets_its_own_film():
    # Holman, Heat Transfer, Table 7-2: horizontal cylinder in air, laminar, h = 1.32 (dT/d)^(1/4); the rise it
    # gives back satisfies P = h A dT
    p, d, area = 40.0, 0.04, math.pi * 0.04 * 1.0
    dt = thermal.free_convection_temperature_rise(p, d, area)
    assert 1.32 * (dt / d) ** 0.25 * area * dt == pytest.approx(p, rel=1e-12)


def test_holman_example_7_7_simplified_free_convection():
    """Holman, Heat Transfer (SI units, 9th ed., Tata McGraw-Hill 2002), Example 7-7 "Calculation with simplified
    relations", pp. 338-339 (the pipe of Example 7-5): a horizontal pipe 0.3048 m in diameter at 250 degC in
    room air at 15 degC loses 1.57 kW per metre (laminar relation of Table 7-2).  The heat balance solved for the
    rise gives back the 235 K of the example from the published 1.57 kW/m, within the rounding of the
    printed figure (+-5 W/m, i.e. +-0.26 % in the rise)."""
    d = 0.3048
    area = math.pi * d * 1.0
    rise = thermal.free_convection_temperature_rise(1570.0, d, area)
    assert rise == pytest.approx(250.0 - 15.0, rel=0.003)
