"""Physics formulas against published numbers (source named per test; tolerance = half a unit of the
last printed digit unless a comment explains otherwise)."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from axisopt.physics import checks, screw

ROOT = Path(__file__).resolve().parents[2]

MM, CM = 1e-3, 1e-2
RPM = 2.0 * math.pi / 60.0


# MiSUMi Economy catalog p. 1675 (selection example): Ø15 lead 5, fixed-supported, l = 820 mm, root
# 12.5 mm -> 3630 N.  MiSUMi uses the rounded eta_2 = 10; the exact 0.5 * 2 * pi^3 E / 64 gives
# 9.98, hence 3623.7 N (rel. 1.8e-3).  With the vendor's rounded coefficient the half-unit tolerance
# holds.
@pytest.mark.published
def test_buckling_misumi_example():
    p = checks.buckling_load(root_diameter=12.5 * MM, length=820 * MM, mounting="fixed-supported")
    assert p == pytest.approx(3630, rel=2.5e-3)
    eta2 = 0.5 * 2.0 * math.pi**3 * screw.E_STEEL * 1e-6 / 64.0 / 1e4
    assert p * 10.0 / eta2 == pytest.approx(3630, abs=5)


# THK catalog A15-30 eq. 5: eta_2 = 1.3 / 10 / 20 (and 5 supported-supported, vendor-formulas.md
# [DERIVED]), i.e. P1 [N] = eta_2 d^4 / l^2 * 1e4 with d, l in mm.  Exact values 1.248 / 9.98 /
# 19.96 / 4.99; THK prints 1.248 as 1.3 (rounding up), so that row is checked at 0.06.
@pytest.mark.published
@pytest.mark.parametrize(
    ("mounting", "eta2", "tol"),
    [
        ("fixed-free", 1.3, 0.06),
        ("fixed-supported", 10, 0.5),
        ("fixed-fixed", 20, 0.5),
        ("supported-supported", 5, 0.05),
    ],
)
def test_buckling_thk_eta2(mounting, eta2, tol):
    d, l = 10.0, 1000.0  # [mm]
    p = checks.buckling_load(d * MM, l * MM, mounting)
    assert p * l**2 / d**4 / 1e4 == pytest.approx(eta2, abs=tol)


# MiSUMi Economy catalog p. 1676 (life example): BSS1520, C = 4400 N, Pm = 250 N, 2118 rpm, fw = 1.2
# -> 24 824 h.  The exact formula gives 24 826.6 h (rel. 1.0e-4).  The printed inputs are rounded:
# 2118 rpm
# +-0.5 alone moves the life by +-2.4e-4, so that is the honest tolerance.
@pytest.mark.published
def test_life_misumi_example():
    hours = checks.life_time(4400.0, 250.0, 2118 * RPM, load_factor=1.2) / 3600.0
    assert hours == pytest.approx(24824, rel=2.4e-4)
    assert checks.life_revolutions(4400.0, 250.0, 1.2) == pytest.approx(
        (4400 / 300) ** 3 * 1e6, rel=1e-12
    )


# THK catalog A15-32 eq. 7: N1 = lambda_2 d / l^2 * 1e7 [1/min] (d, l in mm), lambda_2 = 3.4 / 9.7 /
# 15.1 / 21.9 including 0.8.  Derived from lambda_1 = 1.875 / 3.142 / 3.927 / 4.73
# (vendor-formulas.md: 3.44, 9.66, 15.09, 21.89).
@pytest.mark.published
@pytest.mark.parametrize(
    ("mounting", "lambda2"),
    [
        ("fixed-free", 3.4),
        ("supported-supported", 9.7),
        ("fixed-supported", 15.1),
        ("fixed-fixed", 21.9),
    ],
)
def test_critical_speed_thk_lambda2(mounting, lambda2):
    d, l = 20.0, 1500.0  # [mm]
    n_rpm = checks.critical_speed(d * MM, l * MM, mounting) / RPM
    assert n_rpm * l**2 / d / 1e7 == pytest.approx(lambda2, abs=0.05)


# THK LM Guide selection: the dynamic load rating C is the load at which 90 % of blocks reach 50 km
# (balls) or 100 km (rollers); L = (C/P)^3 x 50 km and (C/P)^(10/3) x 100 km.  HIWIN G99TE20 divides
# C by f_w.
@pytest.mark.published
def test_guide_life_definition_thk():
    assert checks.guide_life_distance(30e3, 30e3) == pytest.approx(50e3, rel=1e-12)
    assert checks.guide_life_distance(30e3, 30e3, roller=1.0) == pytest.approx(100e3, rel=1e-12)
    assert checks.guide_life_distance(30e3, 15e3) == pytest.approx(8 * 50e3, rel=1e-12)
    assert checks.guide_life_distance(30e3, 15e3, roller=1.0) == pytest.approx(
        2 ** (10 / 3) * 100e3, rel=1e-12
    )
    assert checks.guide_life_distance(36e3, 15e3, load_factor=1.2) == pytest.approx(
        8 * 50e3, rel=1e-12
    )


# THK General Catalog A-738..A-740, worked example 2 (vertical conveyance): screw d1 = 12.5 mm, the
# section between the nut and the bearing counted "fixed-fixed", l_a = 700 mm: P1 = 20 x 12.5^4 /
# 700^2 x 10^4 = 9960 N. eta_2 = 20 is THK's rounding of 0.5 x 4 pi^2 E / 64 x 1e-4 with E = 206 GPa
# (19.96): 0.3 % allowed.
@pytest.mark.published
def test_buckling_thk_worked_example_nut_counts_as_fixed():
    assert checks.buckling_load(12.5e-3, 0.700, "fixed-fixed") == pytest.approx(9960, rel=3e-3)


def test_model_counts_the_nut_as_a_fixed_end():
    from axisopt.design import load_design
    from axisopt.model import evaluate
    from axisopt.model.checks import BUCKLING_END_CONDITION

    d = load_design(ROOT / "problems" / "vmc_x_design.yaml")  # fixed-supported
    ev = evaluate(d)
    assert BUCKLING_END_CONDITION == "fixed-fixed"
    expected = checks.buckling_load(float(d.screw["root_diameter"]), 0.13 + 0.8, "fixed-fixed")
    assert ev["buckling_load"] == pytest.approx(expected, rel=1e-12)


# A preloaded support-bearing set's life as NSK computes it (super-precision bearings, life of
# preloaded sets: each row group under its share of preload and load, the groups' lives combined
# with e = 1.1), on HIWIN's WBK30DFD (Table 8.12: C_dyn 47.5 kN for the two rows of the stronger
# direction, preload 4.5 kN); the single row of the other direction rated 47.5 x (1/2)^0.7 kN (NSK
# TAC B: 1, 2 rows 28.5 / 46.5 kN; IBC eq. 2.4), L10 = (C / (f_w P))^3 x 1e6 rev.  Written out here
# apart from physics.life.
@pytest.mark.published
def test_support_bearing_life_in_the_model():
    import dataclasses

    from axisopt.catalog.loading import load_catalogs
    from axisopt.design import load_design
    from axisopt.model import evaluate

    d = load_design(ROOT / "problems" / "vmc_x_design.yaml")
    d = dataclasses.replace(d, bearing=load_catalogs().bearings.loc["HIWIN-WBK30-DFD"])
    ev = evaluate(d)
    # the mean load each way (no duty cycle)
    f = d.axis.mean_axial_load_eff + float(ev["guide_friction"])
    pre, c2 = 4500.0, 47.5e3
    c1 = c2 * 0.5**0.7

    # issue 54: a 2-against-1 set's groups by IBC Table 2.2's linear split, from the set's preload
    # (1.36 Fv) to its unloading point: 5.66 Fv pressing the pair, 2.83 Fv pressing the single (Fv =
    # pre / 1.36)
    def split(lift):
        pressed = pre + f * (lift - pre) / lift if f < lift else f
        return pressed, pressed - f

    pair_pressed, single_relieved = split(5.66 / 1.36 * pre)
    single_pressed, pair_relieved = split(2.83 / 1.36 * pre)
    # half the travel each way: each group is pressed half the time and relieved the other half
    means = (
        ((pair_pressed**3 + pair_relieved**3) / 2) ** (1 / 3),
        ((single_pressed**3 + single_relieved**3) / 2) ** (1 / 3),
    )
    rev = [(c / (1.2 * m)) ** 3 * 1e6 for c, m in zip((c2, c1), means)]
    rev_set = (rev[0] ** -1.1 + rev[1] ** -1.1) ** (-1 / 1.1)
    n = (8 / 60) / 0.020  # mean speed 8 m/min, lead 20 mm [rev/s]
    assert ev["bearing_life"] == pytest.approx(rev_set / n, rel=2e-3)  # IBC's factors in 3 digits
    # well below the pair rating, pressed
    assert rev_set < 0.3 * (c2 / (1.2 * pair_pressed)) ** 3 * 1e6
