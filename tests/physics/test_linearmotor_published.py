"""Linear motors (physics.linearmotor) against HIWIN's worked sizing example (appendix A)."""

from __future__ import annotations

import pytest

from axisopt.physics import linearmotor as lm
from axisopt.physics import rack as pr
from axisopt.physics.motion import Phase


@pytest.mark.published
def test_hiwin_appendix_a_linear_motor_sizing_example():
    # HIWIN MM99TE07-1701 Appendix A, "Linear Motor Sizing Example": payload 5 kg, mu 0.01, X 500
    # mm, T 400 ms, dwell 350 ms, 1/3-1/3-1/3 profile; LMCA6: Fp 187 N, Fc 62 N, Kf 33.8 N/A(rms),
    # Ip 4.5 A, Ic 1.8 A.  Printed: Ip = 70.79 / 33.8 = 2.09 A (< 4.5), Ie = 41.92 / 33.8 = 1.24 A
    # (< 1.8), Ie / Ic = 68.89 %.
    v, a = lm.trapezoid_profile(0.5, 0.4)
    assert (v, a) == (pytest.approx(1.875), pytest.approx(14.0625))
    fp = lm.peak_force(5.0, a, 0.0, 0.01)
    assert fp == pytest.approx(70.79, abs=0.02)
    ff = lm.friction_force(5.0, 0.0, 0.01)
    fe = lm.effective_force(5.0 * a, ff, 0.4 / 3, 0.4 / 3, 0.4 / 3, 0.35)
    assert fe == pytest.approx(41.92, abs=0.02)
    assert lm.current(fp, 33.8) == pytest.approx(2.09, abs=0.005)
    assert lm.current(fe, 33.8) == pytest.approx(1.24, abs=0.005)
    assert lm.current(fe, 33.8) / 1.8 == pytest.approx(0.6889, abs=0.001)
    # the same cycle through the model's integrals (cycle_gram): accelerate, cruise, decelerate,
    # dwell
    t = 0.4 / 3
    phases = [
        Phase(t, a, a, 1.0, 0.0, v),
        Phase(t, 0.0, 0.0, 1.0, 0.0, v, v0=v),
        Phase(t, -a, -a, 1.0, 0.0, v, v0=v),
        Phase(0.35, 0.0, 0.0, 0.0, 0.0, 0.0),
    ]
    cyc = pr.cycle_gram(phases)
    assert pr.rms_linear(cyc, 5.0, ff) == pytest.approx(41.92, abs=0.02)
    assert pr.peak_linear(cyc, 5.0, ff) == pytest.approx(70.79, abs=0.02)
