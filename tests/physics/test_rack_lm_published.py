"""Rack and pinion (physics.rack) and linear motors (physics.linearmotor) against the vendors'
worked examples, and the duty-cycle integrals the drive-type models use against a numerical
integration written here."""

from __future__ import annotations

import math

import casadi as ca
import numpy as np
import pytest

from axisopt.physics import linearmotor as lm
from axisopt.physics import rack as pr
from axisopt.physics.motion import Segment, cycle_phases


@pytest.mark.published
def test_thk_gsr_r_checking_strength_example():
    # THK General Catalog A-241 (GSR-R, "Checking Strength", example): GP6-20A, m = 100 kg, v = 1
    # m/s, T1 = 0.1 s, medium impact: "Fmax = m v / T1 = 1.00 kN", "Pmax = 2.33 / 1.25 = 1.86 kN",
    # Fmax < Pmax
    f = pr.feed_force(100.0, 1.0 / 0.1, 0.0, 0.0, 0.0)
    assert f == pytest.approx(1000.0, rel=1e-12)
    assert pr.OVERLOAD_FACTORS["medium"] == 1.25
    margin = pr.tooth_margin(2330.0, pr.OVERLOAD_FACTORS["medium"], f)
    assert margin * f / 1e3 == pytest.approx(1.86, abs=0.005)  # Pmax in kN, as printed
    assert margin > 1.0  # "it is judged that the subject model number can be used"


@pytest.mark.published
def test_apex_and_yaskawa_rack_formulas():
    # Apex Dynamics: FN = M g mu + M a + F; TN = FN d / 2000 (N m, d in mm); pinion speed NV = v
    # 19100 / d (rpm, v in m/s, d in mm).  Yaskawa Sigma-7 11.2.4: linear-section GD^2 = W
    # (dP/1000)^2 = 4 J.  Our numbers.
    m, mu, a, f, d_mm, v = 500.0, 0.1, 2.0, 800.0, 63.66, 1.0
    fn = m * 9.80665 * mu + m * a + f
    assert pr.feed_force(m, a, mu, 0.0, f) == pytest.approx(fn, rel=1e-12)
    assert pr.pinion_torque(fn, d_mm * 1e-3) == pytest.approx(fn * d_mm / 2000.0, rel=1e-12)
    rpm = pr.pinion_speed(v, d_mm * 1e-3) * 60.0 / (2.0 * math.pi)
    assert rpm == pytest.approx(v * 19100.0 / d_mm, rel=2e-4)  # 19100 is 60000/pi rounded
    assert 4.0 * pr.linear_inertia(m, d_mm * 1e-3) == pytest.approx(
        m * (d_mm / 1000.0) ** 2, rel=1e-12
    )


@pytest.mark.published
def test_iso_6336_mesh_stiffness_guidance():
    # ISO 6336-1 method B: mean mesh stiffness c_gamma ~ 20 N/(mm um) of face width for steel gears
    assert pr.mesh_stiffness(0.020) == pytest.approx(20.0 * 20.0 * 1e6, rel=1e-12)  # 400 N/um
    assert pr.mesh_stiffness(0.020, pinions=2.0) == pytest.approx(800e6, rel=1e-12)


def _numeric_rms(phases, alpha, beta, phi, gamma, n=4000):
    """X(t) = alpha a + beta s + phi F s + gamma integrated by the midpoint rule, phase by phase."""
    total, time = 0.0, 0.0
    for ph in phases:
        ts = (np.arange(n) + 0.5) / n * ph.duration
        acc = ph.a0 + (ph.a1 - ph.a0) * ts / ph.duration
        x = alpha * acc + beta * ph.direction + phi * ph.force * ph.direction + gamma
        total += float(np.sum(x * x)) * ph.duration / n
        time += ph.duration
    return math.sqrt(total / time)


def test_cycle_gram_matches_a_numerical_integration_of_a_jerk_limited_cycle():
    segs = (
        Segment("move", distance=0.8, speed=1.3, acceleration=14.7, jerk=300.0, force=200.0),
        Segment("move", distance=-0.2, speed=0.33, acceleration=14.7, jerk=300.0, force=150.0),
        Segment("move", distance=-0.6, speed=1.3, acceleration=14.7, jerk=300.0),
        Segment("dwell", duration=0.5),
    )
    phases = cycle_phases(segs)
    cyc = pr.cycle_gram(phases)
    for c in [(130.0, 40.0, 1.0, 0.0), (2.0, -3.0, 0.5, 7.0), (0.0, 1.0, 0.0, 0.0)]:
        assert pr.rms_linear(cyc, *c) == pytest.approx(_numeric_rms(phases, *c), rel=1e-5)
    # the peak: the largest |X| of a fine sampling is reached at a phase corner
    sampled = max(
        abs(c * (ph.a0 + (ph.a1 - ph.a0) * s) + 40.0 * ph.direction + ph.force * ph.direction)
        for ph in phases
        for s in np.linspace(0, 1, 50)
        for c in (130.0,)
    )
    assert float(pr.peak_linear(cyc, 130.0, 40.0)) == pytest.approx(sampled, rel=1e-12)


def test_float_numpy_casadi_agree():
    phases = cycle_phases(
        (
            Segment("move", distance=1.0, speed=1.0, acceleration=5.0, force=100.0),
            Segment("move", distance=-1.0, speed=1.0, acceleration=5.0),
            Segment("dwell", duration=0.3),
        )
    )
    cyc = pr.cycle_gram(phases)

    def f(m, mu, d, kt):
        return [
            pr.rms_linear(cyc, m, mu * m * 9.81),
            pr.peak_linear(cyc, m, mu * m * 9.81),
            pr.series(pr.mesh_stiffness(d), pr.torsion_at_rack(kt, d)),
            pr.tooth_margin(5e3, 1.25, m * 5.0),
            lm.effective_force(m * 5.0, mu * m, 0.2, 0.5, 0.2, 0.3),
            lm.servo_stiffness(m, 50.0),
            lm.block_load(m, 3000.0, 100.0, 4.0),
        ]

    args = (300.0, 0.05, 0.04, 2e5)
    floats = [float(v) for v in f(*args)]
    arrs = f(*(np.array([a, 2 * a]) for a in args))
    xs = ca.SX.sym("x", 4)
    fun = ca.Function("f", [xs], [ca.vertcat(*f(xs[0], xs[1], xs[2], xs[3]))])
    sym = np.array(fun(np.array(args))).ravel()
    for fl, ar, sy in zip(floats, arrs, sym):
        assert np.asarray(ar)[0] == pytest.approx(fl, rel=1e-12)
        assert sy == pytest.approx(fl, rel=1e-12)
