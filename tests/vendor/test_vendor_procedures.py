"""The independent checker's own formulas (tools/vendor_procedures.py) against the vendors' worked
examples.

The checker is written apart from axisopt (it imports nothing of it); these tests show that its
formulas reproduce the printed numbers, so that its verdict on the shipped optima
(test_vendor_check.py) can be trusted.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path
from types import SimpleNamespace

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tools"))
import vendor_procedures as vp  # noqa: E402

G_THK = 9.807


def _life_mean_load(phases, c=1000.0):
    """The cubic-mean load a single-nut life implies (fW 1): F_m = C / (L / 1e6)^(1/3)."""
    hours = vp.nut_life_h(c, 0.0, phases, 1.0, 1.0)[0]
    return c / (hours * 60.0 / 1e6) ** (1 / 3)


@pytest.mark.published
def test_buckling_and_tension_thk_a726():
    # THK General Catalog A-726: d1 17.5 mm, l_a 1100 mm, eta_2 20 -> P1 = 15 500 N; P2 = 116 d1^2 =
    # 35 500 N
    assert vp.buckling_load("THK", 17.5, 1100.0)[0] == pytest.approx(15500, rel=5e-3)
    assert vp.permissible_tension(17.5) == pytest.approx(35500, rel=5e-3)


@pytest.mark.published
@pytest.mark.parametrize(
    "d1, lb, printed", [(17.5, 1100.0, 2180), (26.4, 1100.0, 3294), (12.5, 700.0, 3852)]
)
def test_critical_speed_thk_a727_a738(d1, lb, printed):
    # THK A-727 (fixed-supported, lambda_2 15.1): 2180 and 3294 min^-1; A-738 (vertical example):
    # 3852 min^-1
    assert vp.critical_speed("THK", d1, lb, "fixed-supported")[0] == pytest.approx(printed, abs=5.0)


@pytest.mark.published
def test_critical_speed_hiwin_factors_match_thk_within_their_rounding():
    # H-BS F 3.27/3.28 (0.8 x 2.71e8 x f_n) against THK's lambda_2: fixed-supported 15.00 vs
    # 15.1, fixed-fixed 21.68 vs 21.9 (1 %); fixed-free 3.19 vs 3.4 (HIWIN 6 % lower: its f_n 0.147)
    ratio = {
        m: vp.critical_speed("HIWIN", 30.0, 800.0, m)[0]
        / vp.critical_speed("THK", 30.0, 800.0, m)[0]
        for m in ("fixed-supported", "fixed-fixed", "fixed-free")
    }
    assert ratio["fixed-supported"] == pytest.approx(0.9936, abs=1e-3)
    assert ratio["fixed-fixed"] == pytest.approx(0.9900, abs=1e-3)
    assert ratio["fixed-free"] == pytest.approx(0.9374, abs=1e-3)


@pytest.mark.published
def test_mean_load_sign_rule_thk_a706():
    # THK A-706: loads 10, 50, -40, -10 N over 10, 50, 10, 70 mm -> Fm1 = 35.5 N (adopted), Fm2 =
    # 17.2 N
    phases = [
        vp.Phase(d / 1e3, 1.0, 1.0, 0.0, 1, 0.0, f)
        for f, d in ((10, 10), (50, 50), (-40, 10), (-10, 70))
    ]
    assert _life_mean_load(phases) == pytest.approx(35.5, abs=0.05)


def _horizontal_thk_a722():
    # THK A-722: m1 + m2 = 80 kg, 1 m/s, t1 = 0.15 s (6.67 m/s^2), mu 0.003, f 15 N, stroke 1000 mm
    m, a = 80.0, 1.0 / 0.15
    friction = 0.003 * m * G_THK + 15.0
    return [p for d in (1.0, -1.0) for p in vp.move_phases(d, 1.0, a, 0.0, m, friction, 0.0)]


@pytest.mark.published
def test_horizontal_example_phase_loads_and_life_thk_a725_a730():
    phases = _horizontal_thk_a722()
    # Fa1..Fa6 = 550, 17, -516, -550, -17, 516 N (THK prints 550 for 550.7: within 1 N);
    # travels 75, 850, 75 mm
    assert [p.load for p in phases] == pytest.approx([550, 17, -516, -550, -17, 516], abs=1.0)
    assert [round(p.dist * 1e3) for p in phases[:3]] == [75, 850, 75]
    # Fm = 225 N; WTF2040-2 (Ca 5400 N), fW 1.5: L = 4.1e9 rev; A-730: Nm = 400 min^-1, Lh =
    # 171 000 h
    assert _life_mean_load(phases) == pytest.approx(225, abs=0.5)
    assert vp.nut_life_h(5400.0, 0.0, phases, 1.5, 400.0)[0] == pytest.approx(171000, rel=5e-3)


@pytest.mark.published
def test_vertical_example_phase_loads_and_life_thk_a739_a742():
    # THK A-736: 50 kg, 0.3 m/s, 1.5 m/s^2, f 20 N (no mu term on a vertical axis), stroke 600 mm
    m = 50.0
    phases = [p for d in (0.6, -0.6) for p in vp.move_phases(d, 0.3, 1.5, 0.0, m, 20.0, m * G_THK)]
    # 585, 510, 435 N up; 395, 470, 545 N down; A-741: 30 / 540 / 30 mm
    assert [round(p.load) for p in phases] == [585, 510, 435, 395, 470, 545]
    assert [round(p.dist * 1e3) for p in phases[:3]] == [30, 540, 30]
    # Fm = 492 N; BLK1510-5.6 (Ca 9800 N), fW 1.5, Nm 600 min^-1: Lh = 65 000 h
    assert _life_mean_load(phases) == pytest.approx(492, abs=0.5)
    assert vp.nut_life_h(9800.0, 0.0, phases, 1.5, 600.0)[0] == pytest.approx(65000, rel=5e-3)


@pytest.mark.published
def test_holding_torque_thk_a745():
    # THK A-745: stationary with the work removed (m1 40 kg), f 20 N, Ph 10 mm, eta 0.9: T_s = 658
    # N.mm
    assert vp.holding_torque(40 * G_THK, 20.0, 0.010) == pytest.approx(0.658, abs=5e-4)


@pytest.mark.published
def test_preload_torque_thk_a689():
    # THK A-689: BNFN4010, preload 3000 N, lead 10 mm, ball centre diameter 41.75 mm: T_p = 865 N.mm
    assert vp.preload_torque(3000.0, 10.0, 41.75) == pytest.approx(0.865, abs=5e-4)


@pytest.mark.published
def test_screw_inertia_thk_a733():
    # THK A-733: shaft 20 mm, 1.23e-3 kg.cm^2 per mm, 1200 mm long: Js = 1.48e-4 kg.m^2
    assert vp.screw_inertia(0.020, 1.0e-3) * 1e4 == pytest.approx(1.23e-3, abs=5e-6)
    assert vp.screw_inertia(0.020, 1.200) == pytest.approx(1.48e-4, abs=5e-7)


@pytest.mark.published
def test_guide_life_iko_i21():
    # IKO CAT-1578E p. I-21/22: MXG45 roller C 124 000 N, MHG45 ball C 95 200 N, P 10 000 N, 50
    # km basis: 220 000 km and 43 000 km
    assert vp.guide_rating_life(124000.0, 10000.0, "roller", 50) == pytest.approx(220000, rel=5e-3)
    assert vp.guide_rating_life(95200.0, 10000.0, "ball", 50) == pytest.approx(43000, rel=5e-3)
    assert vp.GUIDE_BASIS[("IKO", "roller")] == 50 and vp.GUIDE_BASIS[("HIWIN", "roller")] == 100


@pytest.mark.published
def test_lift_off_of_preloaded_halves_thk_a687():
    # THK A-687: the preload is lost at Ft = 2^(3/2) Fa0 = 2.8 Fa0; the pressed half then carries Ft
    pressed, other = vp.preloaded_halves(1000.0, 2**1.5 * 1000.0 * (1 - 1e-9))
    assert other == pytest.approx(0.0, abs=1e-3) and pressed == pytest.approx(2828.4, abs=0.1)
    assert vp.preloaded_halves(1000.0, 0.0) == (1000.0, 1000.0)


@pytest.mark.published
def test_support_set_rating_and_preload_nsk_25tac62b():
    # NSK-SP p. 111: 25TAC62B Ca 28.5 kN (1 row), 46.5 kN (2 rows, DFD/DFF): 46.5 / 2^0.7 = 28.6
    # (0.5 %)
    assert 46.5 / 2**0.7 == pytest.approx(28.5, rel=5e-3)
    # NSK-SP p. 168, C10: DF 3150 N, DFD 4300 N.  IBC Table 2.2 puts the single bearing of a 2:1 set
    # at 1.36 Fv: 4300 / 1.36 = 3162 N, the DF pair's preload (0.4 %): the reading of the set
    # preload the checker uses
    assert 4300.0 / vp.IBC_SET_PRELOAD[(2, 1)] == pytest.approx(3150.0, rel=5e-3)


@pytest.mark.published
def test_nsk_split_of_a_db_pair_until_and_after_unloading():
    # NSK-SP p. 140 (DB, no radial load): Fa1 = 2/3 Fae + Fap, Fa2 = Fap - 1/3 Fae; unloaded (Fa2
    # < 0): Fa1 = Fae, Fa2 = 0.  With Fap 1000 N: 1500 N gives 2000 / 500 N, 3000 N the unloading
    # point 3000 / 0 N, 4000 N all on one side
    assert vp.nsk_printed_loads(1000.0, 1500.0) == pytest.approx((2000.0, 500.0))
    assert vp.nsk_printed_loads(1000.0, 3000.0) == pytest.approx((3000.0, 0.0))
    assert vp.nsk_printed_loads(1000.0, 4000.0) == pytest.approx((4000.0, 0.0))


@pytest.mark.published
def test_ibc_split_of_a_db_pair_until_and_after_unloading():
    # IBC TI-I-5010.2/E Table 2.2, eqs. 2.8/2.9: DB pair, A = Fv + 0.67 Fae, B = Fv - 0.33 Fae,
    # unloading at 2.83 Fv
    assert vp.ibc_bearing_loads(1, 1, 1000.0, 1500.0) == pytest.approx((2005.0, 505.0))
    assert vp.ibc_bearing_loads(1, 1, 1000.0, 3000.0) == pytest.approx((3000.0, 0.0))


def test_block_reactions_thk_rule_for_a_centred_table():
    # THK's 4-block case: a vertical load at the centre splits into quarters; an offset one
    # adds
    # +- M / (2 l0) along the rail and +- M / (2 l1) across the rails
    ax = SimpleNamespace(blocks=4, block_spacing=0.4, rail_spacing=0.3)
    loads = vp.block_reactions(ax, [((0, 0, -4000.0), (0.1, 0.05, 0.0))])
    expect = [
        1000 + s1 * 4000 * 0.1 / (2 * 0.4) + s2 * 4000 * 0.05 / (2 * 0.3)
        for s2 in (-1, 1)
        for s1 in (-1, 1)
    ]
    assert sorted(loads) == pytest.approx(sorted(expect))
    assert math.isclose(sum(loads), 4000.0)


@pytest.mark.published
@pytest.mark.parametrize(
    ("n_load", "n_other", "x"), [(1, 1, 2.83), (2, 1, 5.66), (3, 1, 8.49), (2, 2, 5.66)]
)
def test_hertz_group_split_unloads_at_ibc_table_2_2(n_load, n_other, x):
    """The checker's exact Hertz split (issue 54): the opposite group unloads at IBC Table 2.2's X
    Fv, Fv the bearings' preload as a DB pair (the set's preload over 1, 1.36, 1.57, 2 for 1:1, 2:1,
    3:1, 2:2)."""
    fv = 1000.0
    pre = fv * {(1, 1): 1.0, (2, 1): 1.36, (3, 1): 1.57, (2, 2): 2.0}[(n_load, n_other)]
    _, below = vp.hertz_group_loads(pre, n_load, n_other, 0.98 * x * fv)
    _, above = vp.hertz_group_loads(pre, n_load, n_other, 1.02 * x * fv)
    assert below > 0.0 and above == 0.0


def test_lift_off_of_a_3_1_set_against_its_pretension():
    """A DFT set at a fixed-fixed end: three rows against force + pretension (8.49 Fv), the single
    against the force alone (2.83 Fv); the checker's margin is the smaller of the two, the set
    turned the better way."""
    brg = {"arrangement": "DFT", "preload": 1.57 * 6650.0}
    avail, need, margin, _ = vp.bearing_lift_off(brg, 17.0e3, 30.0e3)
    assert margin == pytest.approx(min(8.49 * 6650 / 47.0e3, 2.83 * 6650 / 17.0e3), rel=1e-3)
    assert avail / need == pytest.approx(margin)
