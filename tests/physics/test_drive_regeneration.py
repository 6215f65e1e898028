"""Regenerative energy over a duty cycle against the vendors' regeneration formulas (issue 26
review)."""

import math

import pytest

from axisopt.physics.drive import phase_torques, regenerative_energy
from axisopt.physics.motion import Segment, cycle_phases, phase_speeds

LEAD = 0.02  # [m]
J = 2.0e-3  # load + rotor at the motor [kg m^2]
T_L = 1.5  # friction (load torque) at the motor [N m]
K = 2.0 * math.pi / LEAD  # motor rad/s per m/s


def _move(speed, acc, jerk=None, distance=0.6):
    return cycle_phases(
        [Segment("move", distance=distance, speed=speed, acceleration=acc, jerk=jerk)]
    )


def test_a_stop_gives_back_yaskawa_rotational_energy_less_the_load_loss():
    # Yaskawa Sigma-7 manual 12.8.6, a stop from n_M in t_D: E_S = J n^2 / 182 (rotational energy, J
    # in kg m^2, n in rpm) less E_L = (pi / 60) n T_L t_D (load loss); Mitsubishi MR-JE 11.2.2
    # writes the same stop as E_3 = 0.1047 / 2 * N * T_3 * t_psd
    v, acc = 0.5, 5.0
    phases = _move(v, acc)
    torques = phase_torques(phases, J, LEAD, T_L, 0.0)
    e = regenerative_energy(phases, torques, LEAD)
    n = v * K * 60.0 / (2.0 * math.pi)  # 1500 rpm
    t_d = v / acc
    yaskawa = J * n**2 / 182.0 - (math.pi / 60.0) * n * T_L * t_d
    assert e[0] == 0.0 and e[1] == 0.0  # accelerating and cruising: the motor drives
    # Yaskawa's 182 is 2 / (2 pi / 60)^2 = 182.38 rounded
    rounding = J * n**2 * (1 / 182.0 - 1 / 182.38)
    assert e[2] == pytest.approx(yaskawa, abs=1.05 * rounding)
    t3 = -J * (n * 2 * math.pi / 60) / t_d + T_L
    assert e[2] == pytest.approx(-0.1047 / 2 * n * t3 * t_d, rel=1e-3)


def test_lowering_at_constant_speed_returns_gravity_less_friction():
    # Mitsubishi MR-JE 11.2.2 (vertical axis, down at constant speed): T_6 = -T_U + T_F, E_6 =
    # 0.1047 N T_6 t_3
    t_u = 6.0  # unbalanced (gravity) torque [N m]
    phases = _move(0.4, 4.0, distance=-0.5)
    # gravity torque holds the weight (lifting positive)
    torques = phase_torques(phases, J, LEAD, T_L, t_u)
    e = regenerative_energy(phases, torques, LEAD)
    cruise = next(i for i, ph in enumerate(phases) if ph.a0 == 0.0 and ph.a1 == 0.0)
    n = 0.4 * K * 60.0 / (2.0 * math.pi)
    assert e[cruise] == pytest.approx(0.1047 * n * (t_u - T_L) * phases[cruise].duration, rel=1e-3)


def test_s_curve_stop_returns_the_kinetic_energy():
    # energy balance, independent of the phase bookkeeping: without friction a jerk-limited stop
    # returns the rotating kinetic energy J w^2 / 2 (the power is a cubic in each piece: Simpson's
    # rule is exact), and the start returns nothing
    v, acc, jerk = 0.5, 5.0, 100.0
    phases = _move(v, acc, jerk)
    e = regenerative_energy(phases, phase_torques(phases, J, LEAD, 0.0, 0.0), LEAD)
    down = [i for i, ph in enumerate(phases) if ph.a0 < 0.0 or ph.a1 < 0.0]
    assert len(down) == 3 and sum(e[i] for i in down) == pytest.approx(
        0.5 * J * (v * K) ** 2, rel=1e-9
    )
    assert sum(e) == pytest.approx(sum(e[i] for i in down), rel=1e-12)
    speeds = phase_speeds(phases)  # the move starts and ends at rest and reaches its speed
    assert speeds[0][0] == 0.0 and speeds[-1][1] == pytest.approx(0.0, abs=1e-12)
    assert max(s for pair in speeds for s in pair) == pytest.approx(v)
