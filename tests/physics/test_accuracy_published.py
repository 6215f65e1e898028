"""Lead accuracy grades and the positioning-error rows against THK's General Catalog (T-GC, ball
screw section "Accuracy of the Ball Screw" A-677..A-690, "Studying the Positioning Accuracy"
A-712..A-716 and the selection examples A-723 and A-737) and HIWIN's technical information
S99TE20-1610 Table 4.4."""

import math

import pytest

from axisopt.catalog.grades import grade_table
from axisopt.physics import accuracy as pa
from axisopt.physics.screw import screw_stiffness
from axisopt.physics.thermal import thermal_growth

UM = 1e-6


@pytest.mark.published
def test_thk_a723_selecting_lead_angle_accuracy():
    # THK A-723: positioning accuracy +-0.3 mm/1000 mm -> lead angle accuracy +-0.09 mm/300 mm -> C7
    # (+-0.05/300)
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
    # THK: BNF2512 (d1 = 21.9 mm), fixed-supported, 1000 N + 500 N vertical, L = 100 mm
    # and 700 mm: Ks = 776 and 111 N/um, deflections 1.9 and 13.5 um, positioning error 11.6 um
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
    # THK A-716 eq. (39), A = l sin(theta) (THK prints no number): 30 degrees at 1 mm is half a
    # millimetre
    assert pa.abbe_error(1e-3, math.radians(30.0)) == pytest.approx(0.5e-3)


def test_worst_case_total_adds_rows():
    assert pa.worst_case_total(1.0, 2.0, 3.5) == 6.5
    assert pa.lead_error_tolerance(40 * UM, 27 * UM) == pytest.approx(67 * UM)
    # a C7 screw keeps its whole +-50 um on a travel under 300 mm
    assert pa.lead_error_per_300(50 * UM, 0.1) == pytest.approx(50 * UM)
