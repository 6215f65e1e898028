"""Rating life under a duty cycle (axisopt.physics.life) against the vendors' worked examples.

THK General Catalog (ball screw section A-704 to A-746), HIWIN Ballscrews Technical Information
S99TE20 (examples 4.5-1), Bosch Rexroth ball screw catalog R310 (example "service life", p. 119),
NSK super-precision bearings (TAC B ratings).  Published values are compared at their printed
rounding.
"""

import math

import numpy as np
import pytest

from axisopt.physics import checks, life
from axisopt.physics.nut import preloaded_pair_load

pytestmark = pytest.mark.published


def test_thk_a706_mean_load_with_a_sign_change():
    # THK A-706: loads 10, 50, -40, -10 N over 10, 50, 10, 70 mm: Fm1 = 35.5 N (positive), Fm2 =
    # 17.2 N
    plus, minus = life.directional_means([10.0, 50.0, -40.0, -10.0], [10.0, 50.0, 10.0, 70.0])
    assert plus == pytest.approx(35.5, abs=0.05)
    assert minus == pytest.approx(17.2, abs=0.05)


def test_thk_high_speed_transfer_example_life():
    # THK A-725..A-731: Fa 550 / 17 / -516 N forward, -550 / -17 / 516 N back, travel 75 / 850 / 75
    # mm each way: Fm1 = Fm2 = 225 N; WTF2040-2 (Ca 5.4 kN), fW 1.5: L = 4.1e9 rev; Nm = 2 x 8 x
    # 1000 / 40 = 400 rpm; Lh = 171 000 h; LS = 164 000 km
    loads = [550.0, 17.0, -516.0, -550.0, -17.0, 516.0]
    travels = [75.0, 850.0, 75.0, 75.0, 850.0, 75.0]
    plus, minus = life.directional_means(loads, travels)
    assert plus == pytest.approx(225, abs=0.5) and minus == pytest.approx(225, abs=0.5)
    rev = checks.life_revolutions(5400.0, max(plus, minus), 1.5)
    assert rev == pytest.approx(4.1e9, rel=0.01)
    n_mean = 2 * 8 * 1000.0 / 40.0  # rev per minute of clock time
    assert n_mean == 400
    assert rev / (60 * n_mean) == pytest.approx(171_000, rel=0.01)
    assert rev * 40e-3 / 1e3 == pytest.approx(164_000, rel=0.01)  # km


def test_thk_vertical_conveyance_example_life():
    # THK A-739..A-742: all loads upward (gravity), 585 / 510 / 435 N up, 395 / 470 / 545 N down,
    # travel 30 / 540 / 30 mm: Fm = 492 N; BLK1510-5.6 (Ca 9.8 kN), fW 1.5: L = 2.34e9 rev; Nm
    # 600 rpm: Lh 65 000 h
    loads = [585.0, 510.0, 435.0, 395.0, 470.0, 545.0]
    travels = [30.0, 540.0, 30.0] * 2
    plus, minus = life.directional_means(loads, travels)
    assert plus == pytest.approx(492, abs=0.5) and minus == 0.0
    rev = checks.life_revolutions(9800.0, plus, 1.5)
    assert rev == pytest.approx(2.34e9, rel=0.005)
    assert rev / (60 * 600.0) == pytest.approx(65_000, rel=0.005)


def test_rexroth_service_life_example():
    # Rexroth R310 ball screw catalog, example "service life" (p. 119): F 50 000 / 25 000 / 8 000 /
    # 2 000 N at 10 / 30 / 100 / 1000 min^-1 for 6 / 22 / 47 / 25 % of the time: nm = 304 min^-1, Fm
    # = 8757 N; with C = 88 800 N: L = 1042e6 rev, Lh = 57 167 h.  Revolutions n q stand for the
    # travel.
    f = [50_000.0, 25_000.0, 8_000.0, 2_000.0]
    n = [10.0, 30.0, 100.0, 1000.0]
    q = [6.0, 22.0, 47.0, 25.0]
    nm = sum(a * b for a, b in zip(n, q)) / 100.0
    assert nm == pytest.approx(304, abs=0.5)
    fm = life.cubic_mean(f, [a * b for a, b in zip(n, q)])
    assert fm == pytest.approx(8757, abs=2)
    rev = checks.life_revolutions(88_800.0, fm)
    assert rev / 1e6 == pytest.approx(1042, abs=2)
    assert rev / (60 * 304) == pytest.approx(57_167, rel=1e-3)


def test_hiwin_s99te20_example_4_5_1_mean_load():
    # HIWIN S99TE20 example 4.5-1: 100 / 400 / 800 kgf at 1000 / 50 / 100 rpm for 45 / 35 / 20 %,
    # fp 1.1: nav = 487.5 rpm, Fbm = 318.5 kgf (HIWIN rounds; 318.3 recomputed)
    fb = [100.0 * 1.1, 400.0 * 1.1, 800.0 * 1.1]
    n, t = [1000.0, 50.0, 100.0], [45.0, 35.0, 20.0]
    assert sum(a * b for a, b in zip(n, t)) / 100 == pytest.approx(487.5)
    assert life.cubic_mean(fb, [a * b for a, b in zip(n, t)]) == pytest.approx(318.5, rel=1e-3)


def test_nsk_row_group_ratings():
    # NSK TAC B, 25TAC62B: one row loaded 28.5 kN, two rows 46.5 kN, three rows 61.5 kN
    assert life.row_group_rating(46.5, 1, 2) == pytest.approx(28.5, rel=0.01)
    assert life.row_group_rating(28.5, 2, 1) == pytest.approx(46.5, rel=0.01)
    assert life.row_group_rating(28.5, 3, 1) == pytest.approx(61.5, rel=0.01)


def test_preloaded_halves_follow_the_hiwin_flow_chart():
    p = 1000.0
    lift = 2**1.5 * p
    # no load: both halves carry the preload
    assert life.preloaded_halves(p, 0.0) == pytest.approx((p, p))
    for f in (300.0, 1500.0, 2500.0):
        a, b = life.preloaded_halves(p, f)
        assert a == pytest.approx((1 + f / lift) ** 1.5 * p)  # F 3.7, the pressed half
        assert a - b == pytest.approx(f)  # the halves' difference is the external load
        assert life.preloaded_halves(p, -f) == pytest.approx((b, a))  # mirror
    # at and after lift-off the other half is unloaded and the pressed half carries the load
    assert life.preloaded_halves(p, lift)[1] == pytest.approx(0.0, abs=1e-9)
    assert life.preloaded_halves(p, 2 * lift) == pytest.approx((2 * lift, 0.0))
    assert preloaded_pair_load(p, 2 * lift) == pytest.approx(2 * lift)


def test_set_life_weibull_sum():
    # two equal halves: 2^(-9/10) of one (HIWIN F 3.12); one half much weaker: the set is close to
    # it
    assert life.set_life([1e9, 1e9]) == pytest.approx(1e9 * 2 ** (-0.9))
    assert life.set_life([1e7, 1e12]) == pytest.approx(1e7, rel=1e-5)
    # NSK's exponent 1.1 for bearing rows
    assert life.set_life([2.0, 2.0], life.BEARING_SET_EXPONENT) == pytest.approx(
        2.0 * 2 ** (-1 / 1.1)
    )


def test_life_functions_take_arrays():
    loads = [np.array([550.0, 100.0]), np.array([-516.0, -50.0])]
    plus, minus = life.directional_means(loads, [1.0, 1.0])
    assert plus.shape == (2,) and math.isclose(plus[1], 100.0 / 2 ** (1 / 3))
    assert math.isclose(minus[0], 516.0 / 2 ** (1 / 3))


def test_set_equivalent_load_gives_the_set_life():
    # two halves of one rating and two row groups of different ratings: (C1/F_eq)^3 equals the
    # Weibull sum
    for means, ratings, e in (
        ([1200.0, 700.0], (30e3, 30e3), life.NUT_SET_EXPONENT),
        ([3300.0, 3100.0], (46.5e3, 28.5e3), life.BEARING_SET_EXPONENT),
    ):
        lives = [(c / f) ** 3 for f, c in zip(means, ratings)]
        f_eq = life.set_equivalent_load(means, ratings, e)
        assert (ratings[0] / f_eq) ** 3 == pytest.approx(life.set_life(lives, e), rel=1e-12)
