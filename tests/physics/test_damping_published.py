"""Physics formulas against published numbers (source named per test; tolerance = half a unit of the
last printed digit unless a comment explains otherwise)."""

from __future__ import annotations

import math

import pytest

from axisopt.physics import damping


# Seed eq. 38-39: d_c = 2 sqrt(mk) = 2 m w0; zeta = d/d_c = Lambda/(2 pi) = delta/w = eta/2.
def test_damping_eq38_eq39_relations():
    m, k, d = 300.0, 2e8, 1.2e4
    w0 = math.sqrt(k / m)
    assert damping.critical_damping(m, k) == pytest.approx(2 * m * w0, rel=1e-12)
    zeta = damping.damping_ratio(d, m, k)
    assert damping.damping_ratio_from_decay_rate(d / (2 * m), w0) == pytest.approx(zeta, rel=1e-12)
    assert damping.damping_ratio_from_loss_factor(2 * zeta) == pytest.approx(zeta, rel=1e-12)
    lam = 2 * math.pi * zeta / math.sqrt(1 - zeta**2)  # exact log decrement of the viscous SDOF
    assert damping.damping_ratio_from_log_decrement(lam, method="exact") == pytest.approx(
        zeta, rel=1e-12
    )
    assert damping.damping_ratio_from_log_decrement(lam) == pytest.approx(zeta, rel=zeta**2)
    assert damping.damping_coefficient(zeta, m, k) == pytest.approx(d, rel=1e-12)
    # Two Table 7 guide dampers (ball 35 mm, lower bound) plus steel structural damping (Table 5).
    c = damping.GUIDE_DAMPING_TABLE7[("ball", 35)][0]
    steel = damping.DAMPING_RATIO_TABLE5["steel"][0]
    assert damping.modal_damping_ratio(m, k, c, c, structural_ratio=steel) == pytest.approx(
        steel + 2 * c / (2 * m * w0), rel=1e-12
    )
