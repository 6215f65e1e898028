"""Issue 26: the heat balance of the screw (friction power -> temperature rise -> thermal
growth)."""

import math

import numpy as np
import pytest

from axisopt.physics import thermal

RPM = 2.0 * math.pi / 60.0


def test_jungnickel_rotating_cylinder_film_coefficient():
    # Jungnickel 2010 (TU Dresden), as in Thermca forced_conv.rot_cyl_in_air: alpha = 3.75 omega^0.7
    # r^0.4; a 40 mm shaft at 1000 rpm: 3.75 x 104.7^0.7 x 0.02^0.4 = 20.3 W/(m^2 K)
    assert thermal.rotating_shaft_heat_transfer(1000 * RPM, 0.02) == pytest.approx(20.3, abs=0.05)


def test_tian_he_heat_generation_is_torque_times_speed():
    # Tian & He (2004), cited in Machines 2023, 11(3), 408 eq. 1: Q [kJ/h] = 0.12 pi n [rpm] tau
    # [N.m]: the friction power T omega the heat balance uses.  1 N.m at 1000 rpm: 377 kJ/h = 104.7
    # W
    power = 1.0 * 1000 * RPM
    assert power * 3.6 == pytest.approx(0.12 * math.pi * 1000 * 1.0, rel=1e-12)
    area = math.pi * 0.04 * 1.0
    h = thermal.rotating_shaft_heat_transfer(1000 * RPM, 0.02)
    assert thermal.friction_temperature_rise(power, h, area) == pytest.approx(power / (h * area))


def test_thk_thermal_displacement_example():
    # THK General Catalog A-732 eq. 38: a 5 degC rise over 1000 mm, rho = 12e-6/degC: 0.06 mm
    assert thermal.thermal_growth(1.0, 5.0, alpha=12e-6) == pytest.approx(0.06e-3, abs=0.005e-3)


def test_heat_balance_is_of_the_order_of_thks_heat_generation_test():
    """THK General Catalog A-821 (wiper ring W heat-generation test): BLK3232 (32 mm shaft, lead 32)
    at 1000 rpm, 32 m/min, 1000 mm stroke, 100 ms time constant: the shaft centre rose 8.9-12.2 degC
    after 90 min.  THK prints no drag torque; with a light-preload drag of 0.1-0.3 N.m (HIWIN Table
    3.16 band 0.2-0.4 N.m) on a 1.4 m shaft the convection-only balance gives the same order (it is
    an upper estimate: no conduction to the housings)."""
    omega = 0.9 * 1000 * RPM  # mean of a 1000 mm reciprocating stroke with 100 ms ramps
    h = thermal.rotating_shaft_heat_transfer(omega, 0.016)
    area = math.pi * 0.032 * 1.4
    rises = [thermal.friction_temperature_rise(t * omega, h, area) for t in (0.1, 0.3)]
    assert rises[0] < 8.9 and 12.2 < 1.1 * rises[1]  # 3.9 and 11.6 K


def test_negative_heat_transfer_is_a_one_line_error(tmp_path, capsys):
    from pathlib import Path

    from axisopt.cli import main

    src = Path(__file__).resolve().parents[2] / "problems" / "duty_cycle_problem.yaml"
    text = src.read_text(encoding="utf-8").replace(
        "  jerk: 100 m/s^3\n", "  jerk: 100 m/s^3\n  heat_transfer: -20 W/(m^2.K)\n"
    )
    p = tmp_path / "p.yaml"
    p.write_text(text, encoding="utf-8")
    assert main(["solve", str(p)]) == 2
    err = capsys.readouterr().err.strip()
    assert "heat_transfer" in err and "positive" in err and len(err.splitlines()) == 1


def test_holman_free_convection_rise_meets_its_own_film():
    # Holman, Heat Transfer, Table 7-2: horizontal cylinder in air, laminar, h = 1.32 (dT/d)^(1/4);
    # the rise it gives back satisfies P = h A dT
    p, d, area = 40.0, 0.04, math.pi * 0.04 * 1.0
    dt = thermal.free_convection_temperature_rise(p, d, area)
    assert 1.32 * (dt / d) ** 0.25 * area * dt == pytest.approx(p, rel=1e-12)


def test_holman_example_7_7_simplified_free_convection():
    """Holman, Heat Transfer (SI units, 9th ed., Tata McGraw-Hill 2002), Example 7-7 "Calculation
    with simplified relations", pp. 338-339 (the pipe of Example 7-5): a horizontal pipe 0.3048 m in
    diameter at 250 degC in room air at 15 degC loses 1.57 kW per metre (laminar relation of Table
    7-2).  The heat balance solved for the rise gives back the 235 K of the example from the
    published 1.57 kW/m, within the rounding of the printed figure (+-5 W/m, i.e. +-0.26 % in the
    rise)."""
    d = 0.3048
    area = math.pi * d * 1.0
    rise = thermal.free_convection_temperature_rise(1570.0, d, area)
    assert rise == pytest.approx(250.0 - 15.0, rel=0.003)


def test_jungnickel_free_convection_agrees_with_holman():
    # Jungnickel 2010 (Thermca free_conv.horiz_cyl) and Holman Table 7-2 (laminar, 1.32 (dT/d)^0.25)
    # for the same 40 mm horizontal cylinder 5 K above the air: 4.11 and 4.41 W/(m^2 K), two
    # published correlations within 10 %
    jung = thermal.horizontal_cylinder_free_film(5.0, 0.04)
    assert jung == pytest.approx(4.11, abs=0.005)
    assert jung == pytest.approx(1.32 * (5.0 / 0.04) ** 0.25, rel=0.10)


def test_mixed_convection_of_transverse_flows():
    # Jungnickel 2010 (Thermca combd_film.mix_conv, transverse: n = 4): (3^4 + 4^4)^(1/4) = 4.28
    assert thermal.mixed_convection_film(3.0, 4.0) == pytest.approx(337.0**0.25, rel=1e-12)


def _fin_mean_by_finite_differences(
    h, d, dr, length, g_end, q_line, theta_end, k=thermal.K_STEEL, n=2001
):
    """Mean rise of a shaft (fin) with heat q' [W/m] along it and ends held through g_end
    to theta_end: the fin equation k A theta'' = h U theta - q' solved on a grid (independent of the
    closed form)."""
    area, perim = math.pi * dr**2 / 4, math.pi * d
    dx = length / (n - 1)
    a = np.zeros((n, n))
    b = np.full(n, q_line * dx)
    for i in range(n):
        a[i, i] = h * perim * dx
        for j in (i - 1, i + 1):
            if 0 <= j < n:
                a[i, i] += k * area / dx
                a[i, j] -= k * area / dx
    for i in (0, n - 1):  # half cells at the ends, plus the end conductance
        a[i, i] -= 0.5 * h * perim * dx
        b[i] = 0.5 * q_line * dx + g_end * theta_end
        a[i, i] += g_end
    theta = np.linalg.solve(a, b)
    return float(np.trapezoid(theta, dx=dx) / length)


@pytest.mark.parametrize("g_end", [0.5, 2.0, 1e6])
def test_shaft_end_fraction_solves_the_fin_equation(g_end):
    """The closed form (Incropera & DeWitt ch. 3.6, a fin with convective ends) against a
    finite-difference solution of the same fin equation: the heated shaft with ends at ambient, and
    the unheated shaft with warm ends.  Ends at ambient (g -> inf): f = tanh(x)/x, the textbook fin
    efficiency."""
    h, d, dr, length = 8.0, 0.04, 0.034, 0.9
    f = thermal.shaft_end_fraction(h, d, dr, length / 2, g_end)
    q_line = 20.0
    theta_inf = q_line / (h * math.pi * d)
    assert _fin_mean_by_finite_differences(h, d, dr, length, g_end, q_line, 0.0) == pytest.approx(
        theta_inf * (1 - f), rel=2e-4
    )
    assert _fin_mean_by_finite_differences(h, d, dr, length, g_end, 0.0, 3.0) == pytest.approx(
        3.0 * f, rel=2e-4
    )
    if g_end > 1e5:
        x = math.sqrt(h * math.pi * d / (thermal.K_STEEL * math.pi * dr**2 / 4)) * length / 2
        assert f == pytest.approx(math.tanh(x) / x, rel=1e-4)
