"""Physics formulas against published numbers (source named per test; tolerance = half a unit of the
last printed digit unless a comment explains otherwise)."""

from __future__ import annotations

import pytest


# HIWIN BS-08-2-EN-1704-K F 3.36: dL = 11.6e-6 x dT x L; THK A-715: 12 um per metre and degC.
@pytest.mark.published
def test_thermal_growth_vendor_coefficients():
    from axisopt.physics import thermal

    assert thermal.thermal_growth(1.0, 1.0) == pytest.approx(11.6e-6, rel=1e-12)
    assert thermal.thermal_growth(1.0, 1.0, alpha=12e-6) == pytest.approx(12e-6, rel=1e-12)
    # the compensating pretension of a 40 mm screw (root 34.91 mm) for 3 K: E A alpha dT = 6.47 kN
    # by hand
    assert thermal.restrained_thermal_force(0.03491, 3.0) == pytest.approx(
        206e9 * 3.141592653589793 / 4 * 0.03491**2 * 11.6e-6 * 3.0, rel=1e-12
    )
