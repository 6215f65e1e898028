"""Drive-sizing formulas (axisopt.physics.drive) against THK's two worked motor-selection examples.

Source: THK General Catalog, ball screw section, "Examples of Selecting a Ball Screw": example 1
(high-speed transfer equipment, horizontal) A-722 to A-735, example 2 (vertical conveyance system)
A-736 to A-746; formulas A-717 to A-720 (eq. 40-49).  THK prints three significant figures and
rounds the angular acceleration before using it (1050 rad/s^2 for 1047.2), so computed torques are
compared at 0.5 %; values THK prints from its own rounded numbers are compared exactly to its
rounding.
"""

from __future__ import annotations

import math

import pytest

from axisopt.physics import drive
from axisopt.physics.screw import screw_rotary_inertia

MM, KG_CM2 = 1e-3, 1e-4
RPM = 2.0 * math.pi / 60.0
G = 9.807  # THK A-725


@pytest.mark.published
@pytest.mark.parametrize(("diameter_mm", "per_mm_kg_cm2"), [(20, 1.23e-3), (15, 3.9e-4)])
def test_screw_inertia_per_length_thk(diameter_mm, per_mm_kg_cm2):
    # THK A-733 (shaft 20 mm: 1.23e-3 kg cm^2/mm) and A-743 (shaft 15 mm: 3.9e-4 kg cm^2/mm)
    j = screw_rotary_inertia(diameter_mm * MM, 1.0) / KG_CM2 * MM  # kg cm^2 per mm
    assert j == pytest.approx(
        per_mm_kg_cm2, abs=0.5 * 10 ** (math.floor(math.log10(per_mm_kg_cm2)) - 2)
    )


@pytest.mark.published
def test_screw_inertia_fanuc_and_mitsubishi():
    # FANUC B-65142E/04 sec. 4 (p. 31): steel shaft (7.8e3 kg/m^3) of 32 mm x 1 m, "Jb = 0.0008 [kg
    # m^2]"
    assert screw_rotary_inertia(0.032, 1.0, density=7.8e3) == pytest.approx(0.0008, abs=0.5e-4)
    # Mitsubishi MDS-B-SVJ2 sec. 11-5 (p. 11-15): 40 mm x 1000 mm, 7.80e-3 kg/cm^3, "JB = 19.6 (kg
    # cm^2)"
    assert screw_rotary_inertia(0.040, 1.0, density=7.8e3) / KG_CM2 == pytest.approx(19.6, abs=0.05)


@pytest.mark.published
def test_thk_example_1_horizontal_transfer():
    # m1 60 + m2 20 kg, Vmax 1 m/s, t1 = t3 = 0.15 s, Jm 1e-3 kg m^2, A = 1, mu 0.003, f 15
    # N; selected WTF2040-2 (lead 40 mm), screw length 1200 mm; eta 0.9
    m, lead, jm, t1 = 80.0, 40 * MM, 1e-3, 0.15
    fa_uniform = 0.003 * m * G + 15.0  # Fa2 = 17 N
    assert fa_uniform == pytest.approx(17, abs=0.5)
    t_friction = drive.force_torque(17.0, lead, 0.9)
    assert t_friction * 1e3 == pytest.approx(120, abs=0.5)  # T1 = 120 N mm
    js = 1.23e-3 * 1200 * KG_CM2  # THK's per-length figure x 1200 mm = 1.48 kg cm^2
    j = drive.reflected_inertia(m, lead, js)
    assert j == pytest.approx(3.39e-3, abs=0.005e-3)
    n_m = drive.motor_speed(1.0, lead)
    assert n_m / RPM == pytest.approx(1500)  # max working speed 1500 min^-1
    t_acc = drive.acceleration_torque(j + jm, n_m, t1)
    assert t_acc == pytest.approx(4.61, rel=5e-3)  # A-733: 4.61 N m (with omega' rounded to 1050)
    t_k, t_g = t_friction + t_acc, t_friction - t_acc
    assert t_k * 1e3 == pytest.approx(4730, rel=5e-3)  # Tmax = 4730 N mm
    assert t_g * 1e3 == pytest.approx(-4490, rel=5e-3)
    # Trms over t1 0.15, t2 0.85, t3 0.15, stop 2.6 s from THK's printed torques = 1305 N mm
    durations = (0.15, 0.85, 0.15, 2.6)
    assert drive.rms_torque((4730, 120, 4490, 0.0), durations) == pytest.approx(1305, abs=1)
    assert drive.rms_torque(
        (t_k * 1e3, t_friction * 1e3, t_g * 1e3, 0.0), durations
    ) == pytest.approx(1305, rel=5e-3)
    # the rotor must be at least one tenth of the load inertia (C = 10 in eq. 49)
    assert j / 10 == pytest.approx(3.39e-4, abs=0.005e-4)
    assert drive.inertia_ratio(j, jm) < 10


@pytest.mark.published
def test_thk_example_2_vertical_conveyance():
    # m1 40 + m2 10 kg vertical, Vmax 0.3 m/s, t1 = t3 = 0.2 s, Jm 5e-5 kg m^2, f 20 N,
    # BLK1510-5.6 (lead 10 mm), screw length 800 mm, eta 0.9
    m, lead, jm, t = 50.0, 10 * MM, 5e-5, 0.2
    up = drive.force_torque(510.0, lead, 0.9)  # Fa2 = 510 N upward uniform
    down = drive.force_torque(470.0, lead, 0.9)  # Fa5 = 470 N downward uniform
    #
    assert up * 1e3 == pytest.approx(900, rel=5e-3) and down * 1e3 == pytest.approx(830, rel=5e-3)
    js = screw_rotary_inertia(15 * MM, 800 * MM)
    assert js / KG_CM2 == pytest.approx(0.31, abs=0.005)  # 0.31 kg cm^2
    j = drive.reflected_inertia(m, lead, js)
    assert j == pytest.approx(1.58e-4, abs=0.005e-4)
    n_m = drive.motor_speed(0.3, lead)
    assert n_m / RPM == pytest.approx(1800)
    t3 = drive.acceleration_torque(j + jm, n_m, t)
    assert t3 == pytest.approx(0.2, abs=0.005)  # 0.2 N m
    # holding torque with the work removed (stationary, A-745): (m1 g - f) P / (2 pi eta) = 658 N mm
    assert drive.force_torque(40 * G - 20.0, lead, 0.9) * 1e3 == pytest.approx(658, abs=0.5)
    # A-745/746: Tmax = 1100 N mm; Trms over the printed cycle = 743 N mm
    torques = (1100, 900, 700, 630, 830, 1030, 658)
    durations = (0.2, 1.8, 0.2, 0.2, 1.8, 0.2, 7.6)
    assert max(torques) == pytest.approx((up + t3) * 1e3, rel=5e-3)
    assert drive.rms_torque(torques, durations) == pytest.approx(743, abs=1)
    assert sum(durations) == pytest.approx(60 / 5)  # five reciprocations per minute


def test_drive_formulas_on_numpy_and_casadi():
    import casadi as ca
    import numpy as np

    m = np.array([50.0, 80.0])
    assert np.allclose(drive.load_inertia(m, 0.01), m * (0.01 / (2 * math.pi)) ** 2)
    x = ca.SX.sym("x")
    f = ca.Function("f", [x], [drive.rms_torque((x, 2 * x), (1.0, 3.0))])
    assert float(f(1.0)) == pytest.approx(math.sqrt((1 + 12) / 4))
    with pytest.raises(ValueError):
        drive.rms_torque((1.0,), (1.0, 2.0))
