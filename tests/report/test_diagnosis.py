"""Diagnosis report (:mod:`axisopt.report.diagnosis`): residual plots draw categorical factors as
categories; the FRF peak finder with repeated readings (an FRF file with every row twice gave
'invalid value encountered in scalar divide' warnings): repeated frequencies count once, and the
peak of a single-mode magnitude sampled around its resonance is found near the true frequency."""

import warnings

import numpy as np
import pytest

from axisopt.report.diagnosis import frf_peak


def _single_mode(f, fn=120.0, zeta=0.05):
    r = f / fn
    return 1.0 / np.sqrt((1 - r**2) ** 2 + (2 * zeta * r) ** 2)


def test_peak_with_every_reading_twice_equals_the_single_readings():
    f = np.linspace(60.0, 200.0, 29)
    once = frf_peak(f, _single_mode(f))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        twice = frf_peak(np.repeat(f, 2), np.repeat(_single_mode(f), 2))
    assert twice == pytest.approx(once, rel=1e-12)
    # the resonance of a lightly damped mode: fn sqrt(1 - 2 zeta^2), within the 5 Hz sampling
    assert once == pytest.approx(120.0 * np.sqrt(1 - 2 * 0.05**2), abs=2.5)
