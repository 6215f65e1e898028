"""Duty-cycle kinematics against closed-form rigid-body motion (written here, not taken from the
code)."""

from __future__ import annotations

import math

import pytest

from axisopt.physics.motion import Segment, cycle_phases, cycle_time, phase_speeds, rapid_cycle


def test_trapezoidal_move_speeds_and_time():
    # 500 mm at 0.4 m/s and 3 m/s^2: ramps of v/a = 0.1333 s over v^2/2a = 26.7 mm, cruise (0.5 -
    # 0.0533)/0.4 s
    phases = cycle_phases([Segment("move", distance=0.5, speed=0.4, acceleration=3.0)])
    assert [round(v, 12) for pair in phase_speeds(phases) for v in pair] == [
        0.0,
        0.4,
        0.4,
        0.4,
        0.4,
        0.0,
    ]
    assert cycle_time(phases) == pytest.approx(2 * 0.4 / 3.0 + (0.5 - 0.4**2 / 3.0) / 0.4)


def test_short_move_is_triangular():
    # 10 mm at 3 m/s^2 never reaches 0.4 m/s: peak speed sqrt(a d) = 0.1732 m/s, time 2 sqrt(d/a)
    phases = cycle_phases([Segment("move", distance=-0.01, speed=0.4, acceleration=3.0)])
    speeds = phase_speeds(phases)
    assert max(v for pair in speeds for v in pair) == pytest.approx(math.sqrt(3.0 * 0.01), rel=1e-9)
    assert cycle_time(phases) == pytest.approx(2 * math.sqrt(0.01 / 3.0), rel=1e-9)


def test_jerk_limited_ramp_reaches_the_speed_and_dwell_stands_still():
    # S-ramp to 0.4 m/s at 3 m/s^2, 50 m/s^3: jerk phases of a/j = 0.06 s each gain a^2/2j = 0.09
    # m/s
    seg = rapid_cycle(0.5, 0.4, 3.0, 50.0)[0]
    phases = cycle_phases([seg, Segment("dwell", duration=1.0)])
    speeds = phase_speeds(phases)
    assert speeds[0][1] == pytest.approx(3.0**2 / (2 * 50.0), rel=1e-9)
    assert speeds[1][1] == pytest.approx(0.4 - 0.09, rel=1e-9)
    assert speeds[2][1] == pytest.approx(0.4, rel=1e-9)
    assert speeds[-1] == (0.0, 0.0) and speeds[-2][1] == pytest.approx(0.0, abs=1e-12)
