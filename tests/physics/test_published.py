"""Physics formulas against published numbers (source named per test; tolerance = half a unit of the last
printed digit unless a comment explains otherwise)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from axisopt.physics import bearings, checks, damping, guides, nut, screw

ROOT = Path(__file__).resolve().parents[2]

MM, CM = 1e-3, 1e-2
RPM = 2.0 * math.pi / 60.0


# MiSUMi Economy catalog p. 1675 (selection example): Ø15 lead 5, fixed-supported, l = 820 mm, root 12.5 mm
# -> 3630 N.  MiSUMi uses the rounded eta_2 = 10; the exact 0.5 * 2 * pi^3 E / 64 gives 9.98, hence
# 3623.7 N (rel. 1.8e-3).  With the vendor's rounded coefficient the half-unit tolerance holds.
@pytest.mark.published
def test_buckling_misumi_example():
    p = checks.buckling_load(root_diameter=12.5 * MM, length=820 * MM, mounting="fixed-supported")
    assert p == pytest.approx(3630, rel=2.5e-3)
    eta2 = 0.5 * 2.0 * math.pi**3 * screw.E_STEEL * 1e-6 / 64.0 / 1e4
    assert p * 10.0 / eta2 == pytest.approx(3630, abs=5)


# THK catalog A15-30 eq. 5: eta_2 = 1.3 / 10 / 20 (and 5 supported-supported, vendor-formulas.md [DERIVED]),
# i.e. P1 [N] = eta_2 d^4 / l^2 * 1e4 with d, l in mm.  Exact values 1.248 / 9.98 / 19.96 / 4.99; THK prints
# 1.248 as 1.3 (rounding up), so that row is checked at 0.06.
@pytest.mark.published
@pytest.mark.parametrize(("mounting", "eta2", "tol"), [
    ("fixed-free", 1.3, 0.06), ("fixed-supported", 10, 0.5), ("fixed-fixed", 20, 0.5),
    ("supported-supported", 5, 0.05),
])
def test_buckling_thk_eta2(mounting, eta2, tol):
    d, l = 10.0, 1000.0  # [mm]
    p = checks.buckling_load(d * MM, l * MM, mounting)
    assert p * l**2 / d**4 / 1e4 == pytest.approx(eta2, abs=tol)


# MiSUMi Economy catalog p. 1676 (life example): BSS1520, C = 4400 N, Pm = 250 N, 2118 rpm, fw = 1.2
# -> 24 824 h.  The exact formula gives 24 826.6 h (rel. 1.0e-4).  The printed inputs are rounded: 2118 rpm
# +-0.5 alone moves the life by +-2.4e-4, so that is the honest tolerance.
@pytest.mark.published
def test_life_misumi_example():
    hours = checks.life_time(4400.0, 250.0, 2118 * RPM, load_factor=1.2) / 3600.0
    assert hours == pytest.approx(24824, rel=2.4e-4)
    assert checks.life_revolutions(4400.0, 250.0, 1.2) == pytest.approx((4400 / 300) ** 3 * 1e6, rel=1e-12)


# THK catalog A15-32 eq. 7: N1 = lambda_2 d / l^2 * 1e7 [1/min] (d, l in mm), lambda_2 = 3.4 / 9.7 / 15.1 /
# 21.9 including 0.8.  Derived from lambda_1 = 1.875 / 3.142 / 3.927 / 4.73 (vendor-formulas.md: 3.44, 9.66,
# 15.09, 21.89).
@pytest.mark.published
@pytest.mark.parametrize(("mounting", "lambda2"), [
    ("fixed-free", 3.4), ("supported-supported", 9.7), ("fixed-supported", 15.1), ("fixed-fixed", 21.9),
])
def test_critical_speed_thk_lambda2(mounting, lambda2):
    d, l = 20.0, 1500.0  # [mm]
    n_rpm = checks.critical_speed(d * MM, l * MM, mounting) / RPM
    assert n_rpm * l**2 / d / 1e7 == pytest.approx(lambda2, abs=0.05)


# Seed eq. 7: k_s = 64.7 d_r^2 / L_1 [N/um], d_r in mm, L_1 in cm, E = 2.06e5 N/mm^2 (fixed-fixed minimum).
@pytest.mark.published
def test_screw_catalog_coefficient_eq7():
    k = screw.screw_stiffness_catalog(1.0 * MM, 1.0 * CM, "fixed-fixed") / 1e6
    assert k == pytest.approx(64.7, abs=0.05)


# Seed eq. 8 prints 16.8; E*pi/4 gives 16.18 -> 16.2 (vendor-formulas.md sec. 2.5: "16.8 is probably a typo").
@pytest.mark.published
def test_screw_catalog_coefficient_eq8_is_16_2_not_16_8():
    k = screw.screw_stiffness_catalog(1.0 * MM, 1.0 * CM, "fixed-free") / 1e6
    assert k == pytest.approx(16.2, abs=0.05)
    assert abs(k - 16.8) > 0.5


def test_screw_stiffness_fixed_fixed_minimum_at_mid_span_equals_catalog():
    x = np.linspace(0.05, 0.95, 181)
    k = screw.screw_stiffness(0.02, x, 1.0, "fixed-fixed")
    assert x[np.argmin(k)] == pytest.approx(0.5)
    assert k.min() == pytest.approx(screw.screw_stiffness_catalog(0.02, 1.0, "fixed-fixed"), rel=1e-12)


# Seed Table 1 (Wang et al. [27]): k_n / k_t [N/mm] and the printed ratio column (k_t/k_n, 9 digits).
TABLE1 = [(167, 120, 0.718562874), (156, 112, 0.717948718), (182, 131, 0.71978022)]


@pytest.mark.published
@pytest.mark.parametrize(("kn", "kt", "ratio"), TABLE1)
def test_guide_table1_rows(kn, kt, ratio):
    assert kt / kn == pytest.approx(ratio, abs=5e-10)
    # The text's 0.71 is the ratio truncated to two digits (rounded it would be 0.72): each row lies in
    # [0.71, 0.72), and the 0.71 default therefore under-predicts k_t by 1.1-1.4 %.
    assert math.floor(100 * kt / kn) / 100 == guides.TANGENTIAL_NORMAL_RATIO
    assert guides.guide_tangential_stiffness(kn * 1e3) == pytest.approx(kt * 1e3, rel=0.015)


# Seed eq. 27: k_r = k_a/2 cot^2 alpha, and catalog [12]: c_r = 6 / 3.5 / 2 c_a at 15 / 20 / 25 deg.
# They disagree: eq. 27 gives 6.96 / 3.77 / 2.30, 7-16 % above the catalog.  Each is tested against its own
# statement, and the disagreement is pinned.
@pytest.mark.published
@pytest.mark.parametrize(("deg", "catalog", "eq27"), [(15, 6.0, 6.96), (20, 3.5, 3.77), (25, 2.0, 2.30)])
def test_bearing_radial_axial_ratios(deg, catalog, eq27):
    a = math.radians(deg)
    assert bearings.radial_from_axial(1.0, a, method="catalog") == catalog
    assert bearings.radial_from_axial(1.0, a, method="eq27") == pytest.approx(eq27, abs=0.005)
    assert 1.07 < eq27 / catalog < 1.17


def test_bearing_catalog_ratio_rejects_other_angles():
    with pytest.raises(ValueError, match="15, 20, 25"):
        bearings.radial_from_axial_catalog(1.0, math.radians(30))


# Steinmeyer (kgt_vsdm): "at 2.83 x preload the tensioning nut is released completely"; ISO 3408-5.
@pytest.mark.published
def test_lift_off_is_2_83_times_preload():
    assert nut.lift_off_force(1000.0) == pytest.approx(2830, abs=5)
    assert nut.double_nut_stiffness_under_load(1.0, 1000.0, nut.lift_off_force(1000.0)) == pytest.approx(
        1 / math.sqrt(2), rel=1e-12)


# model-discrepancy.md row 3 (computed): K/K0 = 0.996 @ 0.5 Fa0, 0.931 @ 2, 0.866 @ 2.5, 0.707 @ lift-off,
# 0.79 @ 4, 0.91 @ 6 (K0 = double-nut stiffness at zero external load).
@pytest.mark.parametrize(("f", "ratio", "tol"), [
    (0.5, 0.996, 5e-4), (2.0, 0.931, 5e-4), (2.5, 0.866, 5e-4), (2**1.5, 0.707, 5e-4), (4.0, 0.79, 5e-3),
    (6.0, 0.91, 5e-3), (-2.0, 0.931, 5e-4),
])
def test_double_nut_stiffness_ratio(f, ratio, tol):
    assert nut.double_nut_stiffness_under_load(2.0, 1500.0, f * 1500.0) / 2.0 == pytest.approx(ratio, abs=tol)


def test_double_nut_solves_force_balance():
    f = np.linspace(0.0, 8.0, 81)
    k = nut.double_nut_stiffness_under_load(1.0, 1.0, f)
    assert np.all(k[f > 2**1.5] == pytest.approx(f[f > 2**1.5] ** (1 / 3) / 2, rel=1e-12))
    assert k[0] == pytest.approx(1.0)


# Seed eq. 9: k_n = 0.8 k (P / 0.1 C)^(1/3); at P = 0.1 C it is 0.8 k.
def test_nut_catalog_eq9():
    assert nut.nut_stiffness_catalog(1e9, 3000.0, 30e3) == pytest.approx(0.8e9, rel=1e-12)
    assert nut.nut_stiffness_catalog(1e9, 375.0, 30e3) == pytest.approx(0.4e9, rel=1e-12)


# Johnson, Contact Mechanics eq. 4.23: two steel spheres, delta = (9 Q^2 / (16 R E*^2))^(1/3),
# 1/R = 1/R1 + 1/R2, 1/E* = 2 (1 - nu^2)/E.  The Hamrock-Brewe curve fits are worst in this circular limit
# (kappa 1.034 vs 1, F 1.528 vs pi/2): the approach comes out 5.4 % low, pinned here at 6 %.
def test_hertz_point_deflection_matches_sphere_contact():
    q, r1 = 500.0, 5e-3
    r_eff = r1 / 2.0
    e_star = screw.E_STEEL / (2.0 * (1.0 - 0.3**2))
    exact = (9.0 * q**2 / (16.0 * r_eff * e_star**2)) ** (1.0 / 3.0)
    assert nut.hertz_point_deflection(q, r_eff, r_eff) == pytest.approx(exact, rel=0.06)


# Seed eq. 18 scaling: k_N ~ F_p^(1/3) Z^(2/3).
def test_nut_hertz_scaling_eq18():
    args = dict(ball_diameter=6.35e-3, pitch_diameter=0.04, contact_angle=math.radians(45), lead_angle=0.08)
    k = nut.nut_stiffness_hertz(1000.0, 30.0, **args)
    assert nut.nut_stiffness_hertz(8000.0, 30.0, **args) / k == pytest.approx(2.0, rel=1e-12)
    assert nut.nut_stiffness_hertz(1000.0, 240.0, **args) / k == pytest.approx(4.0, rel=1e-12)
    assert 1e8 < k < 1e9  # a few hundred N/um, the catalog order for a 40 mm nut


# model-discrepancy.md sec. 1.2 (computed from the THK/HIWIN form): Fa0 = 1500 N, p = 8 mm ->
# T_p = 0.30 / 0.34 / 0.38 N*m for d = 25 / 32 / 40 mm.
@pytest.mark.parametrize(("d", "tp"), [(25, 0.30), (32, 0.34), (40, 0.38)])
def test_preload_drag_torque(d, tp):
    assert nut.nut_preload_drag_torque(1500.0, 8 * MM, d * MM) == pytest.approx(tp, abs=0.005)


# Seed eq. 40 by hand: f0 = 2, nu = 20 mm^2/s, n = 3000 rpm, dm = 50 mm, f1 = 0.0003, P = 1000 N:
# 1e-7 * 2 * 60000^(2/3) * 50^3 + 0.0003 * 1000 * 50 = 38.31 + 15 = 53.31 N*mm.
def test_bearing_friction_eq40_hand_value_and_low_speed_branch():
    m = bearings.bearing_friction_torque(2.0, 3e-4, 20e-6, 3000 * RPM, 0.05, 1000.0)
    assert m == pytest.approx(1e-3 * (1e-7 * 2 * 60000 ** (2 / 3) * 50**3 + 15.0), rel=1e-12)
    slow = bearings.bearing_friction_torque(2.0, 0.0, 20e-6, 10 * RPM, 0.05, 0.0)
    assert slow == pytest.approx(1e-3 * 160e-7 * 2 * 50**3, rel=1e-12)
    # The branches meet within 1 % at nu*n = 2000 (2000^(2/3) = 158.7 vs 160).
    edge = bearings.bearing_friction_torque(2.0, 0.0, 20e-6, 100 * RPM, 0.05, 0.0)
    assert edge == pytest.approx(slow, rel=0.01)


# Seed Table 8: angular contact ball bearing f0 = 2-7, f1 = 0.00025-0.00035.
@pytest.mark.published
def test_table8_angular_contact_row():
    assert bearings.FRICTION_COEFFICIENTS_TABLE8["angular contact ball"] == (2.0, 7.0, 0.00025, 0.00035)
    with pytest.raises(TypeError):
        bearings.FRICTION_COEFFICIENTS_TABLE8["x"] = (0, 0, 0, 0)


# Seed Table 9 (after [16]), ball linear guideway 35 mm: friction [N] at block load 0/10/20/30 kN and
# v = 5000 and 40000 mm/min.  F0 + mu N + c_v v fitted (least squares, range midpoints) to 0-20 kN lands in
# every printed range there.  The table grows faster than linearly above 20 kN: at 30 kN the linear model
# under-predicts by ~25 N; that limitation is pinned, not hidden.  Fitted mu is in the 0.001-0.005 band.
TABLE9_BALL35 = {
    5000: [(15, 20), (30, 35), (50, 55), (95, 100)],
    40000: [(30, 45), (40, 55), (60, 75), (100, 115)],
}


@pytest.mark.published
def test_guide_friction_table9_ball35():
    rows, y = [], []
    for v_mm_min, ranges in TABLE9_BALL35.items():
        for load_kn, (lo, hi) in zip((0, 10, 20), ranges[:3], strict=True):
            rows.append((1.0, load_kn * 1e3, v_mm_min / 60e3))
            y.append((lo + hi) / 2)
    f0, mu, cv = np.linalg.lstsq(np.array(rows), np.array(y), rcond=None)[0]
    assert 0.001 < mu < 0.005 and f0 > 0 and cv > 0
    for v_mm_min, ranges in TABLE9_BALL35.items():
        for load_kn, (lo, hi) in zip((0, 10, 20, 30), ranges, strict=True):
            f = guides.guide_friction_force(f0, mu, cv, load_kn * 1e3, v_mm_min / 60e3)
            if load_kn < 30:
                assert lo <= f <= hi
            else:
                assert lo - 35 < f < lo
    mirrored = guides.guide_friction_force(f0, mu, cv, -1e4, -0.5)
    assert mirrored == guides.guide_friction_force(f0, mu, cv, 1e4, 0.5)


# Seed eq. 38-39: d_c = 2 sqrt(mk) = 2 m w0; zeta = d/d_c = Lambda/(2 pi) = delta/w = eta/2.
def test_damping_eq38_eq39_relations():
    m, k, d = 300.0, 2e8, 1.2e4
    w0 = math.sqrt(k / m)
    assert damping.critical_damping(m, k) == pytest.approx(2 * m * w0, rel=1e-12)
    zeta = damping.damping_ratio(d, m, k)
    assert damping.damping_ratio_from_decay_rate(d / (2 * m), w0) == pytest.approx(zeta, rel=1e-12)
    assert damping.damping_ratio_from_loss_factor(2 * zeta) == pytest.approx(zeta, rel=1e-12)
    lam = 2 * math.pi * zeta / math.sqrt(1 - zeta**2)  # exact log decrement of the viscous SDOF
    assert damping.damping_ratio_from_log_decrement(lam, method="exact") == pytest.approx(zeta, rel=1e-12)
    assert damping.damping_ratio_from_log_decrement(lam) == pytest.approx(zeta, rel=zeta**2)
    assert damping.damping_coefficient(zeta, m, k) == pytest.approx(d, rel=1e-12)
    # Two Table 7 guide dampers (ball 35 mm, lower bound) plus steel structural damping (Table 5).
    c = damping.GUIDE_DAMPING_TABLE7[("ball", 35)][0]
    steel = damping.DAMPING_RATIO_TABLE5["steel"][0]
    assert damping.modal_damping_ratio(m, k, c, c, structural_ratio=steel) == pytest.approx(
        steel + 2 * c / (2 * m * w0), rel=1e-12)


# THK LM Guide selection: the dynamic load rating C is the load at which 90 % of blocks reach 50 km (balls)
# or 100 km (rollers); L = (C/P)^3 x 50 km and (C/P)^(10/3) x 100 km.  HIWIN G99TE20 divides C by f_w.
@pytest.mark.published
def test_guide_life_definition_thk():
    assert checks.guide_life_distance(30e3, 30e3) == pytest.approx(50e3, rel=1e-12)
    assert checks.guide_life_distance(30e3, 30e3, roller=1.0) == pytest.approx(100e3, rel=1e-12)
    assert checks.guide_life_distance(30e3, 15e3) == pytest.approx(8 * 50e3, rel=1e-12)
    assert checks.guide_life_distance(30e3, 15e3, roller=1.0) == pytest.approx(2 ** (10 / 3) * 100e3, rel=1e-12)
    assert checks.guide_life_distance(36e3, 15e3, load_factor=1.2) == pytest.approx(8 * 50e3, rel=1e-12)


# THK General Catalog A-738..A-740, worked example 2 (vertical conveyance): screw d1 = 12.5 mm, the section
# between the nut and the bearing counted "fixed-fixed", l_a = 700 mm: P1 = 20 x 12.5^4 / 700^2 x 10^4 = 9960 N.
# eta_2 = 20 is THK's rounding of 0.5 x 4 pi^2 E / 64 x 1e-4 with E = 206 GPa (19.96): 0.3 % allowed.
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


# THK General Catalog: BNF2512, d1 = 21.9 mm, K_S = 776 N/um at L = 100 mm and 111 N/um at 700 mm.
@pytest.mark.published
@pytest.mark.parametrize(("length", "ks"), [(0.100, 776), (0.700, 111)])
def test_screw_rigidity_thk_worked_example(length, ks):
    assert screw.screw_stiffness(21.9e-3, length, 1.0, "fixed-supported") / 1e6 == pytest.approx(ks, abs=0.5)


# HIWIN BS-08-2-EN-1704-K F 3.36: dL = 11.6e-6 x dT x L; THK A-715: 12 um per metre and degC.
@pytest.mark.published
def test_thermal_growth_vendor_coefficients():
    from axisopt.physics import thermal

    assert thermal.thermal_growth(1.0, 1.0) == pytest.approx(11.6e-6, rel=1e-12)
    assert thermal.thermal_growth(1.0, 1.0, alpha=12e-6) == pytest.approx(12e-6, rel=1e-12)
    # the compensating pretension of a 40 mm screw (root 34.91 mm) for 3 K: E A alpha dT = 6.47 kN by hand
    assert thermal.restrained_thermal_force(0.03491, 3.0) == pytest.approx(
        206e9 * 3.141592653589793 / 4 * 0.03491**2 * 11.6e-6 * 3.0, rel=1e-12)


# A preloaded support-bearing set's life as NSK computes it (super-precision bearings, life of preloaded sets:
# each row group under its share of preload and load, the groups' lives combined with e = 1.1), on HIWIN's
# WBK30DFD (Table 8.12: C_dyn 47.5 kN for the two rows of the stronger direction, preload 4.5 kN); the single
# row of the other direction rated 47.5 x (1/2)^0.7 kN (NSK TAC B: 1, 2 rows 28.5 / 46.5 kN; IBC eq. 2.4),
# L10 = (C / (f_w P))^3 x 1e6 rev.  Written out here apart from physics.life.
@pytest.mark.published
def test_support_bearing_life_in_the_model():
    import dataclasses

    from axisopt.catalog.loading import load_catalogs
    from axisopt.design import load_design
    from axisopt.model import evaluate

    d = load_design(ROOT / "problems" / "vmc_x_design.yaml")
    d = dataclasses.replace(d, bearing=load_catalogs().bearings.loc["HIWIN-WBK30-DFD"])
    ev = evaluate(d)
    f = d.axis.mean_axial_load_eff + float(ev["guide_friction"])  # the mean load each way (no duty cycle)
    pre, c2 = 4500.0, 47.5e3
    c1 = c2 * 0.5 ** 0.7
    lift = 2 ** 1.5 * pre
    pressed = pre * (1 + f / lift) ** 1.5 if f < lift else f
    other = pressed - f
    # half the travel each way: each group is pressed half the time and relieved the other half
    mean = ((pressed ** 3 + other ** 3) / 2) ** (1 / 3)
    rev = [(c / (1.2 * mean)) ** 3 * 1e6 for c in (c2, c1)]
    rev_set = (rev[0] ** -1.1 + rev[1] ** -1.1) ** (-1 / 1.1)
    n = (8 / 60) / 0.020  # mean speed 8 m/min, lead 20 mm [rev/s]
    assert ev["bearing_life"] == pytest.approx(rev_set / n, rel=1e-9)
    assert rev_set < 0.3 * (c2 / (1.2 * pressed)) ** 3 * 1e6  # well below the pair rating at the loaded half
