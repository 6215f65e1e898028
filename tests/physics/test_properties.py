"""Property tests (hypothesis) and model-level consistency checks."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from axisopt.physics import bearings, checks, damping, dynamics, nut, screw
from axisopt.units import unit_factor

pos = st.floats(min_value=1e5, max_value=1e10, allow_nan=False, allow_infinity=False)


@settings(max_examples=200, deadline=None)
@given(st.lists(pos, min_size=1, max_size=6))
def test_series_stiffness_below_weakest_part(ks):
    k = screw.series_stiffness(*ks)
    assert k <= min(ks) * (1 + 1e-12)
    assert screw.parallel_stiffness(*ks) >= max(ks)


@settings(max_examples=200, deadline=None)
@given(st.floats(0.005, 0.1), st.floats(0.05, 5.0), st.floats(0.2, 5.0), st.floats(0.2, 5.0),
       st.sampled_from(screw.MOUNTINGS))
def test_screw_stiffness_scales_as_d2_over_l(d, length, a, b, mounting):
    k = screw.screw_stiffness_catalog(d, length, mounting)
    assert screw.screw_stiffness_catalog(a * d, b * length, mounting) == pytest.approx(k * a**2 / b, rel=1e-9)
    x = 0.3 * length
    ks = screw.screw_stiffness(d, x, length, mounting)
    assert screw.screw_stiffness(a * d, b * x, b * length, mounting) == pytest.approx(ks * a**2 / b, rel=1e-9)


@settings(max_examples=100, deadline=None)
@given(st.floats(0.0, 10.0), st.floats(0.0, 10.0))
def test_double_nut_stiffness_bounded(f1, f2):
    k1, k2 = (nut.double_nut_stiffness_under_load(1.0, 1.0, f) for f in (f1, f2))
    below = min(f1, f2) < max(f1, f2) <= 2**1.5
    assert 0.7 < k1 <= 1.0 + 1e-12 or f1 > 2**1.5
    if below:  # softens monotonically up to lift-off
        assert (k1 - k2) * (f1 - f2) <= 1e-12


@pytest.mark.parametrize(("func", "args"), [
    (screw.screw_stiffness, (0.02, 0.3, 1.0, "fixed-pinned")),
    (checks.critical_speed, (0.02, 1.0, "FIXED-FREE")),
    (checks.buckling_load, (0.02, 1.0, None)),
    (bearings.radial_from_axial, (1.0, 0.3, "catalogue")),
    (damping.damping_ratio_from_log_decrement, (0.3, "approx")),
])
def test_wrong_selector_names_allowed_values(func, args):
    with pytest.raises(ValueError, match="allowed"):
        func(*args)


def test_bearing_methods_dispatch_and_agree_in_order_of_magnitude():
    kw = dict(radial_load=1000.0, ball_diameter=0.01, n_balls=15.0)
    p = bearings.bearing_radial_stiffness("palmgren", contact_angle=math.radians(15), **kw)
    k = bearings.bearing_radial_stiffness("kramer", **kw)
    assert k == bearings.radial_stiffness_kramer(**kw)
    assert 0.8 < k / p < 1.25  # Palmgren and Kraemer within ~12 % for this 7012-like geometry
    with pytest.raises(ValueError, match="eq20"):
        bearings.bearing_radial_stiffness("stribeck", **kw)


def test_axial_torsional_limits_and_eigen():
    j, kt, ka, m, lead = 2e-3, 3e3, 2e8, 300.0, 0.01
    w1, w2 = dynamics.axial_torsional_eigenvalues(j, kt, ka, m, lead)
    r = lead / (2 * math.pi)
    ev = np.linalg.eigvals(np.linalg.solve(np.diag([j, m]), [[kt + ka * r**2, -ka * r], [-ka * r, ka]]))
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
    assert h2[0].real == pytest.approx(1 / ka + r**2 / kt, rel=1e-9)  # axial and torsion springs in series
    with pytest.raises(ValueError):
        dynamics.dynamic_compliance([1.0], m, ka, ca, rotary_inertia=j)


def test_eq11_matches_lumped_screw_only():
    d, lx, m = 0.04, 0.5, 450.0
    w = dynamics.axial_angular_frequency_eq11(d, lx, m)
    f = dynamics.axial_natural_frequency(screw.screw_stiffness(d, lx, 2.0, "fixed-free"), m)
    assert w / (2 * math.pi) == pytest.approx(f, rel=1e-12)


def test_dn_and_life_units():
    # 32 mm at 3000 rpm is 96 000 mm*rpm in vendor units
    assert checks.dn_value(0.032, 3000 * 2 * math.pi / 60) / unit_factor('mm.rpm', 'dn') == pytest.approx(96000)
    n = 1500 * 2 * math.pi / 60
    assert checks.life_time(3e4, 3e3, n) == pytest.approx(1e9 / 25.0, rel=1e-12)
