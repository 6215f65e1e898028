"""Carriage physics against vendor worked examples (each test names its source; tolerance: the
example's own rounding, said per test).  Texts: THK General Catalog (English, PDF pages as printed
A-nnn) and HIWIN G99TE20-1808 Linear Guideway Technical Information, as stored in GitHub
ArtemFilin1990/Mar (see catalogs/SOURCES.md, keys T-GC and H-LG)."""

from __future__ import annotations

import casadi as ca
import numpy as np
import pytest

from axisopt.physics import carriage as cr
from axisopt.physics import checks

MM = 1e-3
G_THK = 9.8  # THK's examples use g = 9.8 m/s^2


def _corners(forces, n, c_pitch, c_roll, c_yaw):
    """Radial and lateral loads of the four corners (CORNERS order) for forces [(fx, fy, fn, x, y,
    h), ...]."""
    mp = mr = my = 0.0
    fn = fy = 0.0
    for fx_, fy_, fn_, x, y, h in forces:
        a, b, c = cr.carriage_moments(fx_, fy_, fn_, x, y, h)
        mp, mr, my = mp + a, mr + b, my + c
        fn, fy = fn + fn_, fy + fy_
    rad = {
        (sx, sy): float(cr.block_radial_load(fn, mp, mr, n, c_pitch, c_roll, sx, sy))
        for sx, sy in cr.CORNERS
    }
    lat = {(sx, sy): float(cr.block_lateral_load(fy, my, n, c_yaw, sx)) for sx, sy in cr.CORNERS}
    return rad, lat


# THK General Catalog A-103..A-107, "Example of Calculating the Nominal Life (1) - with Horizontal
# Mount and High-speed Acceleration": HSR35LA2SS, C = 50.2 kN, C0 = 81.4 kN; m1 = 800 kg at l2 = 120
# mm along and l3 = 50 mm across the centre, l5 = 350 mm above the drive; m2 = 500 kg at the centre,
# l4 = 200 mm; block spacing l0 = 600 mm, rail spacing l1 = 400 mm; alpha1 = 10, alpha3 = 3.333
# m/s^2; s1 = 12.5, s2 = 1400, s3 = 37.5 mm; fw = 1.5.  Blocks No.1..No.4 are the corners (-,+),
# (+,+), (+,-), (-,-) (m1 on the +x, +y side).  THK rounds its intermediate sums to 0.1 N: loads
# within 0.5 N (the printed digit), fS within 0.05, Pm within 0.05 N, and lives within 1 % (THK
# prints 3 significant figures of lives it computed from rounded loads: its 20 600 km is (50.2/(1.5
# x 4.4922))^3 x 50 = 20 674 km).
THK1 = dict(
    m1=800.0, m2=500.0, l0=600 * MM, l1=400 * MM, l2=120 * MM, l3=50 * MM, l4=200 * MM, l5=350 * MM
)
THK1_BLOCKS = ((-1.0, 1.0), (1.0, 1.0), (1.0, -1.0), (-1.0, -1.0))


def _thk1_case(accel_force_sign, alpha):
    """Corner loads with the inertia force of the masses pointing along accel_force_sign * x."""
    d = THK1
    fx1, fx2 = accel_force_sign * d["m1"] * alpha, accel_force_sign * d["m2"] * alpha
    forces = [
        (fx1, 0.0, d["m1"] * G_THK, d["l2"], d["l3"], d["l5"]),
        (fx2, 0.0, d["m2"] * G_THK, 0.0, 0.0, d["l4"]),
    ]
    c_p = float(cr.moment_share(2.0, d["l0"], 0.0, 2.0))
    c_r = float(cr.moment_share(2.0, d["l1"], 0.0, 2.0))
    rad, lat = _corners(forces, 4.0, c_p, c_r, c_p)
    return [rad[b] for b in THK1_BLOCKS], [lat[b] for b in THK1_BLOCKS]


@pytest.mark.published
def test_thk_horizontal_block_loads():
    rad, lat = _thk1_case(0.0, 0.0)
    assert rad == pytest.approx([2891, 4459, 3479, 1911], abs=0.5)
    assert lat == pytest.approx([0, 0, 0, 0], abs=1e-9)
    # leftward acceleration: the inertia force points +x (towards blocks No.2, No.3)
    rad, lat = _thk1_case(1.0, 10.0)
    assert rad == pytest.approx([-275.6, 7625.6, 6645.6, -1255.6], abs=0.5)
    assert np.abs(lat) == pytest.approx([333.3] * 4, abs=0.5)
    pe = [float(cr.equivalent_block_load(r, t)) for r, t in zip(rad, lat)]
    assert pe == pytest.approx([608.9, 7958.9, 6978.9, 1588.9], abs=0.5)
    # leftward deceleration, rightward acceleration and deceleration
    pe_ld = [float(cr.equivalent_block_load(r, t)) for r, t in zip(*_thk1_case(-1.0, 3.333))]
    assert pe_ld == pytest.approx([4057.7, 3514.5, 2534.5, 3077.7], abs=0.5)
    pe_ra = [float(cr.equivalent_block_load(r, t)) for r, t in zip(*_thk1_case(-1.0, 10.0))]
    assert pe_ra == pytest.approx([6390.9, 1625.7, 645.7, 5410.9], abs=0.5)
    pe_rd = [float(cr.equivalent_block_load(r, t)) for r, t in zip(*_thk1_case(1.0, 3.333))]
    assert pe_rd == pytest.approx([1946.5, 5625.7, 4645.7, 966.5], abs=0.5)


@pytest.mark.published
def test_thk_horizontal_static_safety_and_life():
    la = _thk1_case(1.0, 10.0)
    # the largest load of every block and case is PE of block No.2 in the leftward acceleration
    c_p = float(cr.moment_share(2.0, THK1["l0"], 0.0, 2.0))
    c_r = float(cr.moment_share(2.0, THK1["l1"], 0.0, 2.0))
    mp = 800 * 10.0 * THK1["l5"] + 500 * 10.0 * THK1["l4"] + 800 * G_THK * THK1["l2"]
    mr = 800 * G_THK * THK1["l3"]
    my = -800 * 10.0 * THK1["l3"]
    p_max = float(cr.max_block_load(1300 * G_THK, 0.0, mp, mr, my, 4.0, c_p, c_r, c_p))
    assert p_max == pytest.approx(max(float(cr.equivalent_block_load(r, t)) for r, t in zip(*la)))
    assert float(cr.static_safety(81.4e3, p_max)) == pytest.approx(10.2, abs=0.05)

    cases = {
        k: [float(cr.equivalent_block_load(r, t)) for r, t in zip(*_thk1_case(*v))]
        for k, v in {
            "u": (0.0, 0.0),
            "la": (1.0, 10.0),
            "ld": (-1.0, 3.333),
            "ra": (-1.0, 10.0),
            "rd": (1.0, 3.333),
        }.items()
    }
    s1, s2, s3 = 12.5 * MM, 1400 * MM, 37.5 * MM
    pm = [
        float(
            cr.mean_load(
                [cases[k][i] for k in ("la", "u", "ld", "ra", "u", "rd")], [s1, s2, s3, s1, s2, s3]
            )
        )
        for i in range(4)
    ]
    assert pm == pytest.approx([2940.1, 4492.2, 3520.4, 1985.5], abs=0.05)
    life_km = [checks.guide_life_distance(50.2e3, p, 1.5) / 1e3 for p in pm]
    assert life_km == pytest.approx([73_700, 20_600, 43_000, 239_000], rel=1e-2)


# THK General Catalog A-108..A-110, "Example of Calculating the Nominal Life (2) - with Vertical
# Mount": HSR25CA2SS, C = 19.9 kN, C0 = 34.4 kN; the masses act along the rail (gravity is the feed
# force) at heights l4 = 150 (m1 = 200 kg), l5 = 250 (m2 = 100 kg), l3 = 280 mm (m0 = 100 kg,
# carried up only) and lateral offsets l2 = 50 mm (m1, m2), l1 = 80 mm (m0); block spacing l0 = 300
# mm; fw = 1.2.  Printed: Pu = 1355.6, Ptu = 375.7, PEu = 1731.3, Pd = 898.3, Ptd = 245, PEd =
# 1143.3 N; fS = 19.9; Pm = 1495.1 N; L = 68 200 km.
@pytest.mark.published
def test_thk_vertical_block_loads_safety_life():
    l0 = 300 * MM
    c = float(cr.moment_share(2.0, l0, 0.0, 2.0))

    def case(masses):
        forces = [(-m * G_THK, 0.0, 0.0, 0.0, y, h) for m, y, h in masses]
        rad, lat = _corners(forces, 4.0, c, c, c)
        return rad, lat

    up = [(200.0, 50 * MM, 150 * MM), (100.0, 50 * MM, 250 * MM), (100.0, 80 * MM, 280 * MM)]
    rad, lat = case(up)
    assert sorted({round(abs(v), 1) for v in rad.values()}) == pytest.approx([1355.7], abs=0.15)
    assert sorted({round(abs(v), 1) for v in lat.values()}) == pytest.approx([375.7], abs=0.05)
    pe_u = max(float(cr.equivalent_block_load(rad[k], lat[k])) for k in rad)
    assert pe_u == pytest.approx(1731.3, abs=0.05)
    rad, lat = case(up[:2])
    pe_d = max(float(cr.equivalent_block_load(rad[k], lat[k])) for k in rad)
    assert abs(rad[(1.0, 1.0)]) == pytest.approx(898.3, abs=0.05)
    assert abs(lat[(1.0, 1.0)]) == pytest.approx(245.0, abs=0.05)
    assert pe_d == pytest.approx(1143.3, abs=0.05)
    assert float(cr.static_safety(34.4e3, pe_u)) == pytest.approx(19.9, abs=0.05)
    pm = float(cr.mean_load([pe_u, pe_d], [1.0, 1.0]))
    assert pm == pytest.approx(1495.1, abs=0.05)
    assert checks.guide_life_distance(19.9e3, pm, 1.2) / 1e3 == pytest.approx(68_200, abs=50)


# THK General Catalog A-87, "[Example of calculation]" with moment-equivalent factors (1/mm): one
# block SSR20XV1, mg = 98 N at l1 = 200 mm along and l2 = 100 mm across the block, KAR1 = 0.275,
# KAL1 = 0.137, KCR = 0.129, KCL = 0.0644: P1 = 6752, P2 = -1323, P3 = -3218, P4 = 4857 N (printed
# to 1 N); two blocks in close contact SNS30R2, mg = 49 N, l1 = 200, l2 = 150 mm, KAR2 = 0.018, KAL2
# = 0.0151, KCR = 0.0842, KCL = 0.0707: P1 = 510.3, P2 = 186, P3 = -383.3, P4 = -58.9 N.  THK's
# radial-type blocks (SSR, SNS) have separate radial (R) and reverse-radial (L) factors: each P_n
# takes the factors of its signs.
@pytest.mark.published
def test_thk_moment_equivalent_factors_single_and_double_block():
    mg, l1, l2 = 98.0, 200 * MM, 100 * MM
    mp, mr, _ = cr.carriage_moments(0.0, 0.0, mg, l1, l2, 0.0)

    def p(ka, kc, sx, sy, n=1.0, per_pitch=1.0, per_roll=1.0, pitch=mp, roll=mr, w=mg):
        c_p = cr.moment_share(1.0, 1.0, ka / MM, per_pitch)
        c_r = cr.moment_share(1.0, 1.0, kc / MM, per_roll)
        return float(cr.block_radial_load(w, pitch, roll, n, c_p, c_r, sx, sy))

    assert p(0.275, 0.129, 1, 1) == pytest.approx(6752, abs=0.5)
    assert p(0.137, 0.129, -1, 1) == pytest.approx(-1323, abs=0.5)
    assert p(0.137, 0.0644, -1, -1) == pytest.approx(-3218, abs=0.5)
    assert p(0.275, 0.0644, 1, -1) == pytest.approx(4857, abs=0.5)
    # two blocks in close contact on one rail: the pair takes the pitch moment with its double
    # rating (KA2), the roll moment is shared by the two blocks (KC / 2)
    mg, l1, l2 = 49.0, 200 * MM, 150 * MM
    mp, mr, _ = cr.carriage_moments(0.0, 0.0, mg, l1, l2, 0.0)
    kw = dict(n=2.0, per_roll=2.0, pitch=mp, roll=mr, w=mg)
    assert p(0.018, 0.0842, 1, 1, **kw) == pytest.approx(510.3, abs=0.05)
    assert p(0.0151, 0.0842, -1, 1, **kw) == pytest.approx(186, abs=0.5)
    assert p(0.0151, 0.0707, -1, -1, **kw) == pytest.approx(-383.3, abs=0.05)
    assert p(0.018, 0.0707, 1, -1, **kw) == pytest.approx(-58.9, abs=0.05)


# HIWIN G99TE20-1808 §1-5-4 Table 1-6 "Calculation Example for Service Life": HGH30CA, C = 38.74 kN,
# preload Z0; block spacing d = 600 mm; weight W = 15 kN acting along the rail at h = 200 mm, force
# F = 1 kN opposing it at l = 250 mm: P1 ~ P4 = W h / (2 d) - F l / (2 d) = 2.29 kN; fh = ft = 1, fw
# = 2: L = 30 258 km (from the rounded 2.29 kN).
@pytest.mark.published
def test_hiwin_life_with_load_factor():
    c = float(cr.moment_share(2.0, 600 * MM, 0.0, 2.0))
    mp, _, _ = cr.carriage_moments(15e3, 0.0, 0.0, 0.0, 0.0, 200 * MM)
    mp2, _, _ = cr.carriage_moments(-1e3, 0.0, 0.0, 0.0, 0.0, 250 * MM)
    loads = cr.corner_block_loads(0.0, 0.0, mp + mp2, 0.0, 0.0, 4.0, c, c, c)
    assert [float(v) / 1e3 for v in loads] == pytest.approx([2.29] * 4, abs=0.005)
    assert checks.guide_life_distance(38.74e3, 2.29e3, 2.0) / 1e3 == pytest.approx(30_258, abs=2)


def test_mean_load_backends_agree():
    loads, dist = (1000.0, 2500.0, 400.0), (0.2, 1.0, 0.3)
    ref = float(cr.mean_load(loads, dist))
    arr = cr.mean_load([np.array([v, 2 * v]) for v in loads], dist)
    np.testing.assert_allclose(arr, [ref, 2 * ref], rtol=1e-12)
    s = [ca.SX.sym(f"p{i}") for i in range(3)]
    f = ca.Function("f", s, [cr.mean_load(s, dist)])
    assert float(f(*loads)) == pytest.approx(ref, rel=1e-12)
