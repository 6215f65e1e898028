"""Lead accuracy grades (catalog.grades) against THK General Catalog A-678 Tables 1 and 2 and HIWIN
technical information S99TE20-1610 Tables 4.3 and 4.4."""

import math

import pytest

from axisopt.catalog.grades import grade_table

UM = 1e-6


def band(grade, travel_mm):
    t = grade_table()
    for lo, hi, ep, vu in t.grade(grade).bands:
        if lo < travel_mm * 1e-3 <= hi or (lo == 0 and travel_mm * 1e-3 <= hi):
            return round(ep / UM, 3), round(vu / UM, 3)
    return None


# THK A-678 Table 1 "Lead Angle Accuracy (Permissible Value)": representative travel distance error
# and fluctuation [um] by effective thread length [mm]
@pytest.mark.published
@pytest.mark.parametrize(
    "grade,travel,ep,vu",
    [
        ("C0", 100, 3, 3),
        ("C1", 150, 4.5, 5),
        ("C2", 300, 8, 7),
        ("C3", 900, 21, 15),
        ("C5", 1000, 40, 27),
        ("C5", 1001, 46, 30),
        ("C3", 4500, 72, 41),
        ("C2", 5500, 65, 36),
        ("C5", 9000, 260, 140),
        ("C1", 1600, 15, 10),
    ],
)
def test_thk_table1_travel_deviation_and_fluctuation(grade, travel, ep, vu):
    assert band(grade, travel) == (ep, vu)


@pytest.mark.published
def test_thk_table1_stops_where_the_grade_stops():
    # THK A-678 Table 1 lists no C0 beyond 1600 mm and no C1 beyond 4000 mm
    assert band("C0", 1700) is None and band("C1", 4100) is None
    assert math.isnan(grade_table().lead_error("C0", 1.7))


@pytest.mark.published
def test_thk_table2_fluctuation_per_300_and_per_turn():
    # THK A-678 Table 2 (um): fluctuation/300 3.5 5 7 8 18, fluctuation/2pi 3 4 5 6 8 for C0 C1 C2
    # C3 C5
    t = grade_table()
    names = ("C0", "C1", "C2", "C3", "C5")
    assert [round(t.grade(n).variation_300 / UM, 3) for n in names] == [3.5, 5, 7, 8, 18]
    assert [round(t.grade(n).variation_2pi / UM, 3) for n in names] == [3, 4, 5, 6, 8]


@pytest.mark.published
def test_thk_table1_travel_error_per_300_of_c7_c8_c10():
    # THK A-678 Table 1: C7 +-50/300 mm, C8 +-100/300 mm, C10 +-210/300 mm
    t = grade_table()
    assert [round(t.grade(n).travel_error_300 / UM, 3) for n in ("C7", "C8", "C10")] == [
        50,
        100,
        210,
    ]


@pytest.mark.published
def test_hiwin_standard_axial_play_by_grade():
    # HIWIN S99TE20-1610 Table 4.4 "Standard combination of grade and axial play" (0.001 mm): C0-C2
    # 5, C3 10, C5 20
    t = grade_table()
    assert [round(t.grade(n).axial_play / UM, 3) for n in ("C0", "C1", "C2", "C3", "C5")] == [
        5,
        5,
        5,
        10,
        20,
    ]


@pytest.mark.published
def test_hiwin_table_4_3_jis_row_agrees_with_thk():
    # HIWIN S99TE20-1610 Table 4.3 "International standard of accuracy grade for ballscrews", JIS
    # row, V300p (0.001 mm): C0 3.5, C1 5, C3 8, C5 18, C7 50, C10 210 -- the same figures as THK
    # A-678 (per 300 mm)
    t = grade_table()
    names = ("C0", "C1", "C3", "C5", "C7", "C10")
    assert [round(t.error_per_300(n) / UM, 3) for n in names] == [3.5, 5, 8, 18, 50, 210]
