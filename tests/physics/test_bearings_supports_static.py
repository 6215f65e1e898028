"""Issue 38: the support-bearing set's static check, the mounting-stiffness estimates and the load
factor default, each against the vendors' published numbers (sources in each test)."""

from __future__ import annotations

import pytest

from axisopt.catalog.loading import load_catalogs
from axisopt.model.checks import bearing_static
from axisopt.physics import bearings as pb
from axisopt.physics import checks as pc
from axisopt.physics import nut as pn

KN = 1e3
N_PER_UM = 1e6


def _series(*k):
    return 1.0 / sum(1.0 / x for x in k)


# NSK super-precision bearings (Russian ed.) p. 111, 25TAC62B: limiting axial load 40.5 / 81.5 / 122
# kN with 1 / 2 / 3 rows loaded; Table 1.2 (p. 139): static rating of multi-row sets x 2, 3, 4.
@pytest.mark.published
@pytest.mark.parametrize(("rows", "printed"), [(2, 81.5), (3, 122.0)])
def test_static_rating_grows_with_the_rows_as_nsk_prints(rows, printed):
    assert pb.row_static_rating(40.5 * KN, rows, 1) == pytest.approx(printed * KN, rel=7e-3)
    # NSK Table 1.2 factor (and IBC eq. 2.5, NACHI note 3)
    assert pb.row_static_rating(1.0, rows, 1) == rows


@pytest.mark.published
def test_nsk_permissible_axial_load_is_seven_tenths_of_the_limiting_load():
    """NSK p. 111 footnote (2): permissible axial load = 0.7 x limiting axial load; 25TAC62B DF 0.7
    x 40.5 = 28.35 kN.  The catalog row carries NSK's limiting load and 1/0.7 as its least static
    safety."""
    row = load_catalogs().bearings.loc["NSK-25TAC62B-DF-C10"]
    c0, s0 = float(row["static_load_rating"]), float(row["static_safety"])
    assert c0 == pytest.approx(40.5 * KN)
    assert s0 == pytest.approx(1.0 / pb.NSK_PERMISSIBLE_SHARE, rel=1e-6)
    assert pb.support_static_margin(c0, c0, 28.35 * KN, 28.35 * KN, s0) == pytest.approx(
        1.0, rel=1e-6
    )
    # HIWIN WBK25DF prints NSK's limiting load as its "permissible axial load" (H-BS Table 8.12):
    # same rule
    wbk = load_catalogs().bearings.loc["HIWIN-WBK25-DF"]
    assert float(wbk["static_load_rating"]) == pytest.approx(40.5 * KN)
    assert float(wbk["static_safety"]) == pytest.approx(s0)


@pytest.mark.published
def test_ibc_set_static_rating_and_safety():
    """IBC TI-I-5010.2 eq. 2.5 Cao_set = i Cao_single, eq. 2.6 S0a = Cao / Pao > 2.5; BS25M62 Cao 42
    800 N (p. 8): a tandem pair in the load direction takes 85 600 N / 2.5 = 34 240 N."""
    c0 = pb.row_static_rating(42_800.0, 2, 1)
    assert c0 == pytest.approx(85_600.0)
    assert pb.support_static_margin(
        c0, 42_800.0, 34_240.0, 1.0, pb.STATIC_SAFETY_IBC
    ) == pytest.approx(1.0)


@pytest.mark.published
def test_dfd_set_loaded_against_its_single_row_is_rated_as_the_pair():
    """A DFD set (2 rows one way, 1 the other) is printed with the 2-row limiting load (NSK 25TAC62B
    DFD 81.5 kN); a load against the single row meets NSK's 1-row permissible load 0.7 x 40.5 =
    28.35 kN (within NSK's rounding of 81.5 = 2 x 40.75), and the static set load (pretension) is
    carried by the two rows."""
    row = load_catalogs().bearings.loc["NSK-25TAC62B-DFD-C10"]
    p = {
        "bearing_static_load": float(row["static_load_rating"]),
        "bearing_rows_strong": 2.0,
        "bearing_rows_weak": 1.0,
        "bearing_static_safety": float(row["static_safety"]),
    }
    margin, have, need = bearing_static(p, 28.35 * KN, 0.0)
    assert float(margin) == pytest.approx(1.0, rel=7e-3)
    assert float(have) == pytest.approx(40.75 * KN) and float(need) == pytest.approx(40.5 * KN)
    # 10 kN reversing plus a 20 kN pretension: the two rows take 30 kN (81.5 / (30 / 0.7) = 1.90)
    margin, have, need = bearing_static(p, 10 * KN, 20 * KN)
    assert float(margin) == pytest.approx(81.5 * 0.7 / 30.0)
    assert float(have) == pytest.approx(81.5 * KN)


# IBC TI-I-5010.2: bare duplex sets in O arrangement (p. 9, "Axial stiffness Sax", L/M/H preload)
# against the flange/pillow-block units with the same sets and preloads (p. 22, sec. 4.6), N/um.
IBC_BARE_VS_UNIT = (
    (460, 450),
    (580, 570),
    (740, 730),  # BS 17 (Fv 875/1750/3500 N), BSBU 17 DB 64
    (650, 640),
    (830, 810),
    (1050, 1030),  # BS 25 (1125/2250/4500 N), BSBU 25 DB 88
    (780, 770),
    (990, 970),
    (1260, 1240),  # BS 30-45 (1700/3400/6800 N), BSBU 30-45 DB 98
    (1030, 1020),
    (1310, 1300),
    (1660, 1640),  # BS 55 (1975/3950/7900 N), BSBU 55 DB 113
    # heavy BS 35-50 (3200/6400/12800 N), BSBU 35-50 DB 128
    (1090, 1050),
    (1390, 1360),
    (1760, 1740),
)


@pytest.mark.published
@pytest.mark.parametrize(("bare", "unit"), IBC_BARE_VS_UNIT)
def test_default_housing_is_never_stiffer_than_ibc_units(bare, unit):
    """The set with the default housing reads at most the published unit (never kinder) and within 3
    % of it."""
    k_b = bare * N_PER_UM
    with_housing = _series(k_b, pb.housing_stiffness_default(k_b)) / N_PER_UM
    assert with_housing <= unit + 0.5
    assert with_housing >= 0.97 * unit


@pytest.mark.published
def test_default_bracket_takes_thk_mounting_allowance_once_more():
    """THK A-709: the nut's table rigidity excludes the nut-mounting parts, "roughly 80 %" of it is
    the actual value; the default bracket takes the same share again: nut and bracket in series 0.8
    x the nut."""
    k_n = 0.8 * 1470 * N_PER_UM  # THK BNFN4010-5 table rigidity 1470 N/um (B-670), x 0.8
    assert _series(k_n, pn.bracket_stiffness_default(k_n)) == pytest.approx(0.8 * k_n)


@pytest.mark.published
@pytest.mark.parametrize(
    ("speed", "fw"),
    [
        # THK A-722/A-729 high-speed transfer: Vmax 1 m/s, "Load factor fW = 1.5 (see Table19 on
        # A-704)"
        (1.0, 1.5),
        (0.3, 1.5),  # THK vertical conveyance: Vmax 0.3 m/s, fW = 1.5
        (0.2, 1.2),
        (1.5, 2.0),
        (2.5, 3.5),  # A-704 Table 19, upper ends of the rows
    ],
)
def test_load_factor_default_follows_thk_table_19(speed, fw):
    assert pc.load_factor_default(speed) == fw
