"""Support-bearing sets (physics.bearingsets) against the vendors' published numbers (IBC, NSK, SKF)
and the set's split of an axial load checked against the Hertz contact law."""

from __future__ import annotations

import numpy as np
import pytest

from axisopt.physics import bearingsets

# IBC TI-I-5010.2/E Table 2.2: the unloading point Fae > X Fv of each arrangement (bearings loaded
# against the opposite ones; Fv the bearings' preload as a DB pair) and the single bearing's preload
# in a set against one
IBC_X = [
    (1, 1, 2.83),
    (2, 1, 5.66),
    (1, 2, 2.83),
    (3, 1, 8.49),
    (4, 1, 11.30),
    (2, 2, 5.66),
    (3, 2, 8.49),
    (2, 3, 5.66),
]


IBC_SINGLE = [(2, 1.36), (3, 1.57), (4, 1.71)]


# NSK super-precision bearings p. 168, TAC B C10 (Fpre [N], Ka [N/um]): duplex, triplex (DFD),
# quadruplex (DFF)
NSK_168 = {
    "60TAC120B": ((6650, 1810), (9100, 2650), (13200, 3550)),
    "40TAC90B": ((5000, 1320), (6750, 1960), (10300, 2650)),
    "30TAC62B": ((3350, 1030), (4500, 1520), (6650, 2010)),
}


@pytest.mark.published
@pytest.mark.parametrize(("n_load", "n_other", "x"), IBC_X)
def test_lift_off_factor_ibc_table_2_2(n_load, n_other, x):
    """IBC Table 2.2: lift-off X Fv; the set's own preload is set_preload_ratio x Fv."""
    fv = 1000.0
    pre = bearingsets.set_preload_ratio(n_load, n_other) * fv
    assert bearingsets.set_lift_off(pre, n_load, n_other) / fv == pytest.approx(x, abs=0.015)


@pytest.mark.published
@pytest.mark.parametrize(("n", "ratio"), IBC_SINGLE)
def test_single_bearing_preload_ibc_table_2_2(n, ratio):
    """IBC Table 2.2, the single bearing of n against 1 ('B = 1.36 / 1.57 / 1.71 Fv - ...' at Fae =
    0)."""
    assert bearingsets.set_preload_ratio(n, 1) == pytest.approx(ratio, abs=0.006)


@pytest.mark.published
@pytest.mark.parametrize("bearing", sorted(NSK_168))
def test_triplex_quadruplex_from_duplex_nsk_p168(bearing):
    """NSK p. 168: the triplex (2 against 1) and quadruplex (2 against 2) preload and rigidity from
    the duplex's by the Hertz set rule, within 4 % (NSK rounds and grinds to preload classes)."""
    (p2, k2), (p3, k3), (p4, k4) = NSK_168[bearing]
    assert p2 * bearingsets.set_preload_ratio(2, 1) == pytest.approx(p3, rel=0.04)
    assert p2 * bearingsets.set_preload_ratio(2, 2) == pytest.approx(p4, rel=0.04)
    assert k2 * bearingsets.set_rigidity_ratio(2, 1) == pytest.approx(k3, rel=0.04)
    assert k2 * bearingsets.set_rigidity_ratio(2, 2) == pytest.approx(k4, rel=0.04)


@pytest.mark.published
def test_db_pair_lift_off_skf():
    """SKF 'Lifting force': Ka1 = 2.83 F0 for a back-to-back pair."""
    assert bearingsets.set_lift_off(1.0, 1, 1) == pytest.approx(2.83, abs=0.005)


def test_set_split_bounds_hertz():
    """The linear split (IBC's form) against Hertz's exact split of a 3-against-1 set, solved here
    by bisection from delta ~ (Q/n)^(2/3): never below it, at most 8 % above, equal at no load and
    at lift-off."""
    p0 = 1.0e4
    lift = bearingsets.set_lift_off(p0, 3, 1)
    for frac in np.linspace(0.0, 1.0, 11):
        f = frac * lift
        da, db = (p0 / 3) ** (2 / 3), p0 ** (2 / 3)
        lo, hi = 0.0, db  # the single unloads at u = db
        for _ in range(200):
            u = 0.5 * (lo + hi)
            qa, qb = 3 * (da + u) ** 1.5, max(db - u, 0.0) ** 1.5
            lo, hi = (u, hi) if qa - qb < f else (lo, u)
        exact = 3 * (da + 0.5 * (lo + hi)) ** 1.5
        got = float(bearingsets.set_pressed_load(p0, f, 3, 1))
        assert exact * (1 - 1e-9) <= got <= 1.08 * exact, (frac, got, exact)
    plus, minus = bearingsets.set_halves(p0, 2.0e4, 3, 1)
    assert float(plus) - float(minus) == pytest.approx(2.0e4)
