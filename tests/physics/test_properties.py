"""Property tests (hypothesis) and model-level consistency checks."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from axisopt.physics import bearings, checks, damping, nut, screw
from axisopt.units import unit_factor

pos = st.floats(min_value=1e5, max_value=1e10, allow_nan=False, allow_infinity=False)


@settings(max_examples=200, deadline=None)
@given(st.lists(pos, min_size=1, max_size=6))
def test_series_stiffness_below_weakest_part(ks):
    k = screw.series_stiffness(*ks)
    assert k <= min(ks) * (1 + 1e-12)
    assert screw.parallel_stiffness(*ks) >= max(ks)


@settings(max_examples=200, deadline=None)
@given(
    st.floats(0.005, 0.1),
    st.floats(0.05, 5.0),
    st.floats(0.2, 5.0),
    st.floats(0.2, 5.0),
    st.sampled_from(screw.MOUNTINGS),
)
def test_screw_stiffness_scales_as_d2_over_l(d, length, a, b, mounting):
    k = screw.screw_stiffness_catalog(d, length, mounting)
    assert screw.screw_stiffness_catalog(a * d, b * length, mounting) == pytest.approx(
        k * a**2 / b, rel=1e-9
    )
    x = 0.3 * length
    ks = screw.screw_stiffness(d, x, length, mounting)
    assert screw.screw_stiffness(a * d, b * x, b * length, mounting) == pytest.approx(
        ks * a**2 / b, rel=1e-9
    )


@settings(max_examples=100, deadline=None)
@given(st.floats(0.0, 10.0), st.floats(0.0, 10.0))
def test_double_nut_stiffness_bounded(f1, f2):
    k1, k2 = (nut.double_nut_stiffness_under_load(1.0, 1.0, f) for f in (f1, f2))
    below = min(f1, f2) < max(f1, f2) <= 2**1.5
    assert 0.7 < k1 <= 1.0 + 1e-12 or f1 > 2**1.5
    if below:  # softens monotonically up to lift-off
        assert (k1 - k2) * (f1 - f2) <= 1e-12


@pytest.mark.parametrize(
    ("func", "args"),
    [
        (screw.screw_stiffness, (0.02, 0.3, 1.0, "fixed-pinned")),
        (checks.critical_speed, (0.02, 1.0, "FIXED-FREE")),
        (checks.buckling_load, (0.02, 1.0, None)),
        (bearings.radial_from_axial, (1.0, 0.3, "catalogue")),
        (damping.damping_ratio_from_log_decrement, (0.3, "approx")),
    ],
)
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


def test_dn_and_life_units():
    # 32 mm at 3000 rpm is 96 000 mm*rpm in vendor units
    assert checks.dn_value(0.032, 3000 * 2 * math.pi / 60) / unit_factor(
        "mm.rpm", "dn"
    ) == pytest.approx(96000)
    n = 1500 * 2 * math.pi / 60
    assert checks.life_time(3e4, 3e3, n) == pytest.approx(1e9 / 25.0, rel=1e-12)
