"""Physics formulas against published numbers (source named per test; tolerance = half a unit of the
last printed digit unless a comment explains otherwise)."""

from __future__ import annotations

import numpy as np
import pytest

from axisopt.physics import screw

MM, CM = 1e-3, 1e-2


# Seed eq. 7: k_s = 64.7 d_r^2 / L_1 [N/um], d_r in mm, L_1 in cm, E = 2.06e5 N/mm^2 (fixed-fixed
# minimum).
@pytest.mark.published
def test_screw_catalog_coefficient_eq7():
    k = screw.screw_stiffness_catalog(1.0 * MM, 1.0 * CM, "fixed-fixed") / 1e6
    assert k == pytest.approx(64.7, abs=0.05)


# Seed eq. 8 prints 16.8; E*pi/4 gives 16.18 -> 16.2 (vendor-formulas.md sec. 2.5: "16.8 is probably
# a typo").
@pytest.mark.published
def test_screw_catalog_coefficient_eq8_is_16_2_not_16_8():
    k = screw.screw_stiffness_catalog(1.0 * MM, 1.0 * CM, "fixed-free") / 1e6
    assert k == pytest.approx(16.2, abs=0.05)
    assert abs(k - 16.8) > 0.5


def test_screw_stiffness_fixed_fixed_minimum_at_mid_span_equals_catalog():
    x = np.linspace(0.05, 0.95, 181)
    k = screw.screw_stiffness(0.02, x, 1.0, "fixed-fixed")
    assert x[np.argmin(k)] == pytest.approx(0.5)
    assert k.min() == pytest.approx(
        screw.screw_stiffness_catalog(0.02, 1.0, "fixed-fixed"), rel=1e-12
    )


# THK General Catalog: BNF2512, d1 = 21.9 mm, K_S = 776 N/um at L = 100 mm and 111 N/um
# at 700 mm.
@pytest.mark.published
@pytest.mark.parametrize(("length", "ks"), [(0.100, 776), (0.700, 111)])
def test_screw_rigidity_thk_worked_example(length, ks):
    assert screw.screw_stiffness(21.9e-3, length, 1.0, "fixed-supported") / 1e6 == pytest.approx(
        ks, abs=0.5
    )
