"""Lead accuracy grades and the positioning-error rows against THK's General Catalog (T-GC, ball screw section
"Accuracy of the Ball Screw" A-677..A-690, "Studying the Positioning Accuracy" A-712..A-716 and the selection
examples A-723 and A-737) and HIWIN's technical information S99TE20-1610 Table 4.4."""

import math

import pytest

from axisopt.catalog.grades import grade_table
from axisopt.physics import accuracy as pa
from axisopt.physics.screw import screw_stiffness
from axisopt.physics.thermal import thermal_growth

UM = 1e-6


def band(grade, travel_mm):
    t = grade_table()
    for lo, hi, ep, vu in t.grade(grade).bands:
        if lo < travel_mm * 1e-3 <= hi or (lo == 0 and travel_mm * 1e-3 <= hi):
            return round(ep / UM, 3), round(vu / UM, 3)
    return None


# THK A-678 Table 1 "Lead Angle Accuracy (Permissible Value)": representative travel distance error and
# fluctuation [um] by effective thread length [mm]
@pytest.mark.published
@pytest.mark.parametrize("grade,travel,ep,vu", [
    ("C0", 100, 3, 3), ("C1", 150, 4.5, 5), ("C2", 300, 8, 7), ("C3", 900, 21, 15), ("C5", 1000, 40, 27),
    ("C5", 1001, 46, 30), ("C3", 4500, 72, 41), ("C2", 5500, 65, 36), ("C5", 9000, 260, 140), ("C1", 1600, 15, 10),
])
def test_thk_table1_travel_deviation_and_fluctuation(grade, travel, ep, vu):
    assert band(grade, travel) == (ep, vu)


@pytest.mark.published
def test_thk_table1_stops_where_the_grade_stops():
    # THK A-678 Table 1 lists no C0 beyond 1600 mm and no C1 beyond 4000 mm
    assert band("C0", 1700) is None and band("C1", 4100) is None
    assert math.isnan(grade_table().lead_error("C0", 1.7))


@pytest.mark.published
def test_thk_table2_fluctuation_per_300_and_per_turn():
    # THK A-678 Table 2 (um): fluctuation/300 3.5 5 7 8 18, fluctuation/2pi 3 4 5 6 8 for C0 C1 C2 C3 C5
    t = grade_table()
    names = ("C0", "C1", "C2", "C3", "C5")
    assert [round(t.grade(n).variation_300 / UM, 3) for n in names] == [3.5, 5, 7, 8, 18]
    assert [round(t.grade(n).variation_2pi / UM, 3) for n in names] == [3, 4, 5, 6, 8]


@pytest.mark.published
def test_thk_table1_travel_error_per_300_of_c7_c8_c10():
    # THK A-678 Table 1: C7 +-50/300 mm, C8 +-100/300 mm, C10 +-210/300 mm
    t = grade_table()
    assert [round(t.grade(n).travel_error_300 / UM, 3) for n in ("C7", "C8", "C10")] == [50, 100, 210]


@pytest.mark.published
def test_hiwin_standard_axial_play_by_grade():
    # HIWIN S99TE20-1610 Table 4.4 "Standard combination of grade and axial play" (0.001 mm): C0-C2 5, C3 10, C5 20
    t = grade_table()
    assert [round(t.grade(n).axial_play / UM, 3) for n in ("C0", "C1", "C2", "C3", "C5")] == [5, 5, 5, 10, 20]


@pytest.mark.published
def test_thk_a723_selecting_lead_angle_accuracy():
    # THK A-723: positioning accuracy +-0.3 mm/1000 mm -> lead angle accuracy +-0.09 mm/300 mm -> C7 (+-0.05/300)
    assert pa.required_error_per_300(0.3e-3, 1.0) == pytest.approx(0.09e-3)
    assert grade_table().grade_for(0.3e-3, 1.0) == "C7"
    # and C7's lead error over the 1000 mm stays within the +-0.3 mm the example asks for
    assert grade_table().lead_error("C7", 1.0) == pytest.approx(0.05e-3 * 1000 / 300)


@pytest.mark.published
def test_thk_a737_selecting_lead_angle_accuracy_c10():
    # THK A-737: +-0.7 mm/600 mm -> +-0.35 mm/300 mm -> C10 (+-0.21 mm/300 mm)
    assert pa.required_error_per_300(0.7e-3, 0.6) == pytest.approx(0.35e-3)
    assert grade_table().grade_for(0.7e-3, 0.6) == "C10"


@pytest.mark.published
def test_thk_a713_positioning_error_from_axial_rigidity():
    # THK: BNF2512 (d1 = 21.9 mm), fixed-supported, 1000 N + 500 N vertical, L = 100 mm and 700 mm:
    # Ks = 776 and 111 N/um, deflections 1.9 and 13.5 um, positioning error 11.6 um
    k1 = screw_stiffness(21.9e-3, 0.1, 1.0, "fixed-supported")
    k2 = screw_stiffness(21.9e-3, 0.7, 1.0, "fixed-supported")
    assert (k1 / 1e6, k2 / 1e6) == (pytest.approx(776, abs=0.5), pytest.approx(111, abs=0.5))
    assert pa.stiffness_positioning_error(1500.0, k1) / UM == pytest.approx(1.9, abs=0.05)
    assert pa.stiffness_positioning_error(1500.0, k2) / UM == pytest.approx(13.5, abs=0.05)
    assert pa.stiffness_positioning_error(1500.0, k2, k1) / UM == pytest.approx(11.6, abs=0.05)


@pytest.mark.published
def test_thk_a715_thermal_displacement_per_degree():
    # THK A-715 eq. (38): 1 degC rise elongates the screw 12 um per metre (rho = 12e-6 /degC)
    assert thermal_growth(1.0, 1.0, alpha=12e-6) / UM == pytest.approx(12.0)


def test_thk_a716_abbe_error_form():
    # THK A-716 eq. (39), A = l sin(theta) (THK prints no number): 30 degrees at 1 mm is half a millimetre
    assert pa.abbe_error(1e-3, math.radians(30.0)) == pytest.approx(0.5e-3)


def test_worst_case_total_adds_rows():
    assert pa.worst_case_total(1.0, 2.0, 3.5) == 6.5
    assert pa.lead_error_tolerance(40 * UM, 27 * UM) == pytest.approx(67 * UM)
    # a C7 screw keeps its whole +-50 um on a travel under 300 mm
    assert pa.lead_error_per_300(50 * UM, 0.1) == pytest.approx(50 * UM)


@pytest.mark.published
def test_hiwin_table_4_3_jis_row_agrees_with_thk():
    # HIWIN S99TE20-1610 Table 4.3 "International standard of accuracy grade for ballscrews", JIS row, V300p
    # (0.001 mm): C0 3.5, C1 5, C3 8, C5 18, C7 50, C10 210 -- the same figures as THK A-678 (per 300 mm)
    t = grade_table()
    names = ("C0", "C1", "C3", "C5", "C7", "C10")
    assert [round(t.error_per_300(n) / UM, 3) for n in names] == [3.5, 5, 8, 18, 50, 210]
