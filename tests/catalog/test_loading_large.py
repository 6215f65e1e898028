"""Rows added for large feed axes (issue 39) against the vendors' printed tables, as loaded (SI).

Each test names the table and page its numbers are read from (catalogs/SOURCES.md lists the
documents).  The loader converts vendor units once (N/um -> N/m, kN -> N, mm -> m, kg.cm^2 ->
kg.m^2, rpm -> rad/s).
"""

import math

import pytest

from axisopt.catalog.loading import load_catalogs

pytestmark = pytest.mark.published

N_PER_UM = 1e6


@pytest.fixture(scope="module")
def cat():
    return load_catalogs()


def test_hiwin_80mm_double_nut_matches_h_bs_table_6_7(cat):
    # HIWIN "Ballscrews & Accessories" BS-08-2-EN-1704-K, Table 6.7 (FDI), p. 54: R80-20T4-FDI on an
    # 80 x 20 shaft, ball 9.525, dk 72.47 mm; rigidity 2,480 N/um "calculated for a preload of 10 %
    # of the dynamic load rating", Cdyn 123,750 N, C0 421,620 N, 10.87 kg
    n = cat.nuts.loc["HIWIN-R80-20T4-FDI"]
    assert n["stiffness"] == pytest.approx(2480 * N_PER_UM)
    assert n["dynamic_load_rating"] == pytest.approx(123_750)
    assert n["static_load_rating"] == pytest.approx(421_620)
    assert n["stiffness_preload"] == pytest.approx(0.10 * 123_750, abs=0.5)
    assert n["mass"] == pytest.approx(10.87)
    s = cat.screws.loc[n["screw_id"]]
    assert (s["nominal_diameter"], s["lead"], s["ball_diameter"]) == pytest.approx(
        (0.080, 0.020, 9.525e-3)
    )
    assert s["root_diameter"] == pytest.approx(72.47e-3)


def test_hiwin_80mm_cassette_nut_and_the_c0_misprint(cat):
    # H-BS Table 6.5 (FDC), p. 51: R80-10K5-FDC rigidity 2,230 N/um, Cdyn 86,200 N, C0 379,800 N, dk
    # 74.910 mm
    n = cat.nuts.loc["HIWIN-R80-10K5-FDC"]
    assert (n["stiffness"], n["dynamic_load_rating"], n["static_load_rating"]) == pytest.approx(
        (2230 * N_PER_UM, 86_200, 379_800)
    )
    # R80-10T4: Table 6.6 prints C0 "21,118" for the single nut; Tables 6.7, 6.8 and 6.9 print
    # 211,180 N for the same nut (the FSI cell lost a digit). The row carries 211,180 N, above its
    # Cdyn 55,590 N as every C0 is.
    single, double = cat.nuts.loc["HIWIN-R80-10T4-FSI"], cat.nuts.loc["HIWIN-R80-10T4-FDI"]
    assert single["static_load_rating"] == pytest.approx(211_180) == double["static_load_rating"]
    assert single["stiffness"] == pytest.approx(960 * N_PER_UM)  # Table 6.6
    assert double["stiffness"] == pytest.approx(1900 * N_PER_UM)  # Table 6.7


def test_thk_bnfn_100mm_matches_t_gc_b684_b685(cat):
    # THK General Catalog B-684 (ratings) and B-685 (dimensions, mass), preload type BNFN10020A-5:
    # screw 100 mm, lead 20, dc 92.9 mm, Ca 179.3 kN, C0a 737 kN, rigidity K 4080 N/um (at a preload
    # of 10 % Ca), nut mass 39.99 kg, shaft mass 57.13 kg/m
    n = cat.nuts.loc["THK-BNFN10020A-5"]
    assert n["type"] == "double"
    assert (n["dynamic_load_rating"], n["static_load_rating"]) == pytest.approx((179_300, 737_000))
    assert n["stiffness"] == pytest.approx(4080 * N_PER_UM)
    assert n["stiffness_preload"] == pytest.approx(17_930)
    assert n["mass"] == pytest.approx(39.99)
    s = cat.screws.loc["THK-BNFN-100x20"]
    assert (s["nominal_diameter"], s["lead"], s["root_diameter"]) == pytest.approx(
        (0.100, 0.020, 92.9e-3)
    )
    assert s["mass_per_length"] == pytest.approx(57.13)
    # DN <= 70 000 on the ball centre diameter dp = 102.7 mm, i.e. 681.6 rpm
    rpm = s["dn_limit"] / s["nominal_diameter"] * 60 / (2 * math.pi)
    assert rpm == pytest.approx(70_000 / 102.7, rel=1e-4)


def test_rexroth_fdm_e_s_100mm_matches_br_bs(cat):
    # Bosch Rexroth R310RU 3301, FDM-E-S table p. 44: 100 x 20R x 12.7, C 295,100 N, C0 686,400 N;
    # mass p. 45 24.50 kg; rigidity p. 109: Rnu 2,740 N/um at a preload of 10 % C
    n = cat.nuts.loc["REXROTH-FDMES-100x20x12.7-6-P7-10"]
    assert (n["dynamic_load_rating"], n["static_load_rating"]) == pytest.approx((295_100, 686_400))
    assert n["stiffness"] == pytest.approx(2740 * N_PER_UM)
    assert n["stiffness_preload"] == pytest.approx(29_510)
    assert n["mass"] == pytest.approx(24.5)
    # SNF screw, p. 52: d2 86.9 mm, 52.44 kg/m
    s = cat.screws.loc[n["screw_id"]]
    assert (s["root_diameter"], s["mass_per_length"]) == pytest.approx((86.9e-3, 52.44))


def test_zkln100160_matches_h_bs_table_8_40(cat):
    # Schaeffler ZKLN100160.2Z-XL as reprinted in H-BS Table 8.40 (p. 83) and Table 8.39 (p. 82): d
    # 100, D 160 mm, Cdyn 154,000 N, C0 435,000 N, grease limiting speed 2,150 rpm, M_RL 2.6 N.m,
    # axial rigidity caL 1,900 N/um, 4.90 kg
    b = cat.bearings.loc["SCHAEFFLER-ZKLN100160-DB-M"]
    assert (b["bore"], b["outer_diameter"]) == pytest.approx((0.100, 0.160))
    assert (b["dynamic_load_rating"], b["static_load_rating"]) == pytest.approx((154_000, 435_000))
    assert b["axial_rigidity"] == pytest.approx(1900 * N_PER_UM)
    assert b["starting_torque"] == pytest.approx(2.6)
    assert b["mass"] == pytest.approx(4.90)
    assert b["contact_angle"] == pytest.approx(math.radians(60))  # Table 8.39 footnote
    # preload-class speed rule of SOURCES.md on the printed speed: medium = 0.85 x 2,150 rpm
    assert b["limiting_speed"] * 60 / (2 * math.pi) == pytest.approx(0.85 * 2150, abs=0.5)


def test_nsk_tac03_limiting_load_matches_nsk_sp_p113_p168(cat):
    # NSK super-precision bearings catalog, p. 112 (80TAC03AM: d 80, D 170 mm, 50 deg, limiting
    # speed 2,400 rpm),
    # p. 113 (Ca 274 kN for one row, 445 kN for two; limiting axial load 238 kN for one row, 475 kN
    # for two; footnote: permissible axial load = 0.7 x limiting axial load), p. 168 (DF: preload
    # 7,350 N, rigidity 1,270 N/um, starting torque 1.550 N.m; DFF: 11,500 N, 2,330 N/um, 2.450 N.m)
    df, dff = cat.bearings.loc["NSK-80TAC03AM-DF-M"], cat.bearings.loc["NSK-80TAC03AM-DFF-M"]
    assert (df["bore"], df["outer_diameter"]) == pytest.approx((0.080, 0.170))
    assert df["static_load_rating"] == pytest.approx(238_000)
    assert dff["static_load_rating"] == pytest.approx(475_000)
    assert df["static_load_rating"] / df["static_safety"] == pytest.approx(0.7 * 238_000, rel=1e-6)
    assert (df["dynamic_load_rating"], dff["dynamic_load_rating"]) == pytest.approx(
        (274_000, 445_000)
    )
    assert (df["preload"], df["axial_rigidity"], df["starting_torque"]) == pytest.approx(
        (7350, 1270 * N_PER_UM, 1.55)
    )
    assert (dff["preload"], dff["axial_rigidity"], dff["starting_torque"]) == pytest.approx(
        (11_500, 2330 * N_PER_UM, 2.45)
    )
    assert df["limiting_speed"] * 60 / (2 * math.pi) == pytest.approx(2400)


def test_gwb_ak_800_matches_ringfeder_tech_paper_in_si(cat):
    # RINGFEDER Tech Paper "Metal Bellows Couplings GWB AK", EN 08.2019: size 800, T 800 Nm, nmax
    # 3700 1/min, CTdyn 760 x 10^3 Nm/rad, J 26,10 x 10^-3 kgm^2 (largest bore), Gw 9,978 kg, bores
    # 30-70 mm
    c = cat.table("couplings").loc["RINGFEDER-GWB-AK-800"]
    assert c["rated_torque"] == pytest.approx(800)
    assert c["torsional_stiffness"] == pytest.approx(760e3)
    assert c["inertia"] == pytest.approx(26.10e-3)
    assert c["mass"] == pytest.approx(9.978)
    assert c["max_speed"] == pytest.approx(3700 * 2 * math.pi / 60)
    assert (c["bore_min"], c["bore_max"]) == pytest.approx((0.030, 0.070))


def test_large_screws_fit_a_shipped_support_bearing(cat):
    # H-BS Table 8.2 (p. 60): the S_-60 shaft end of an 80 mm HIWIN screw takes a 60 mm bearing
    # (ZKLN60110, NSK 60TAC03); BR-BS p. 59: Rexroth 80 mm screws take LGNA50110 (50 mm). 100 mm
    # screws have no vendor journal: the derived 70-80 mm (SOURCES.md) takes ZKLN70120/80130 and NSK
    # 80TAC03AM.
    b = cat.bearings[cat.bearings["status"] == "vendor"]
    large = cat.screws[cat.screws["nominal_diameter"] >= 0.080 - 1e-9]
    assert len(large) == 11
    for sid, s in large.iterrows():
        fits = b[
            (b["bore"] >= s["support_bore_min"] - 1e-9)
            & (b["bore"] <= s["support_bore_max"] + 1e-9)
        ]
        assert len(fits) >= 3, sid
    assert cat.screws.loc["HIWIN-G-80x10-b6p35", "support_bore_max"] == pytest.approx(0.060)
    assert cat.screws.loc["REXROTH-SNF-80x20", "support_bore_max"] == pytest.approx(0.050)
