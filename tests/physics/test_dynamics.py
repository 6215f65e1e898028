"""Axis dynamics (physics.dynamics): the axial-torsional modes against a generalised eigensolver and
their stiff limit, the dynamic compliance at zero frequency and at resonance, eq. 11 against the
lumped screw."""

from __future__ import annotations

import math

import numpy as np
import pytest

from axisopt.physics import damping, dynamics, screw


def test_axial_torsional_limits_and_eigen():
    j, kt, ka, m, lead = 2e-3, 3e3, 2e8, 300.0, 0.01
    w1, w2 = dynamics.axial_torsional_eigenvalues(j, kt, ka, m, lead)
    r = lead / (2 * math.pi)
    ev = np.linalg.eigvals(
        np.linalg.solve(np.diag([j, m]), [[kt + ka * r**2, -ka * r], [-ka * r, ka]])
    )
    assert sorted(ev) == pytest.approx([w1, w2], rel=1e-9)
    # Very stiff torsion: the low mode tends to the pure axial mode sqrt(ka/m).
    f1, _ = dynamics.axial_torsional_frequencies(j, 1e12, ka, m, lead)
    assert f1 == pytest.approx(dynamics.axial_natural_frequency(ka, m), rel=1e-3)


def test_dynamic_compliance_static_limit_and_resonance():
    m, ka, ca = 300.0, 2e8, 2e3
    f = np.array([0.0, dynamics.axial_natural_frequency(ka, m)])
    h = dynamics.dynamic_compliance(f, m, ka, ca)
    assert h[0] == pytest.approx(1 / ka)
    zeta = damping.damping_ratio(ca, m, ka)
    assert abs(h[1]) == pytest.approx(1 / (2 * zeta * ka), rel=1e-9)
    j, kt, lead = 2e-3, 3e3, 0.01
    h2 = dynamics.dynamic_compliance([0.0], m, ka, ca, j, kt, 0.0, lead)
    r = lead / (2 * math.pi)
    # axial and torsion springs in series
    assert h2[0].real == pytest.approx(1 / ka + r**2 / kt, rel=1e-9)
    with pytest.raises(ValueError):
        dynamics.dynamic_compliance([1.0], m, ka, ca, rotary_inertia=j)


def test_eq11_matches_lumped_screw_only():
    d, lx, m = 0.04, 0.5, 450.0
    w = dynamics.axial_angular_frequency_eq11(d, lx, m)
    f = dynamics.axial_natural_frequency(screw.screw_stiffness(d, lx, 2.0, "fixed-free"), m)
    assert w / (2 * math.pi) == pytest.approx(f, rel=1e-12)
