"""Closed-loop feedback and pitch-error compensation in the positioning budget, and ISO 230-2
repeatability, against the vendors' published figures (grades.SCALE_GRADES, THK A-678 Table 1)."""

import pytest

from axisopt.design import load_design
from axisopt.model import evaluate

AXIS = """name: grinder
axis:
  stroke: 600 mm
  moving_mass: 200 kg
  mounting: fixed-supported
  max_speed: 10 m/min
  axial_load: 500 N
{extra}parts:
  screw: HIWIN-G-40x10-b6p35
  nut: HIWIN-R40-10K5-FDC
  bearing: HIWIN-WBK20-DF
  guide: HIWIN-HG20-ZA
"""


def _eval(tmp_path, extra=""):
    f = tmp_path / "d.yaml"
    f.write_text(AXIS.format(extra=extra), encoding="utf-8")
    return evaluate(load_design(f)).values


@pytest.mark.published
def test_linear_scale_replaces_lead_and_thermal_rows(tmp_path):
    """AMO LMB (amosin.com/lmb-100): +-3 um/m; over a 600 mm stroke the Heidenhain grade definition
    (any section of at most 1 m within +-a) gives 3 um.  HIWIN PMS: +-20 um/m, read head +-3 um (a 6
    um band)."""
    semi = _eval(tmp_path)
    v = _eval(tmp_path, "  feedback: linear_scale\n  scale_grade: AMO-LMB-3\n")
    assert v["lead_error"] == pytest.approx(3e-6)
    assert v["thermal_error"] == 0.0 and semi["thermal_error"] > 0
    assert v["elastic_error"] == pytest.approx(semi["elastic_error"])
    assert v["positioning_error"] == pytest.approx(
        3e-6 + v["elastic_error"] + v["abbe_error"] + v["lost_motion"]
    )
    h = _eval(tmp_path, "  feedback: linear_scale\n  scale_grade: HIWIN-PMS\n")
    assert h["lead_error"] == pytest.approx(20e-6)
    assert h["repeatability"] == pytest.approx(6e-6)


@pytest.mark.published
def test_pitch_compensation_leaves_the_fluctuation(tmp_path):
    """THK A-678 Table 1, grade C5 over 630-800 mm: e_p +-35 um, v_u 25 um.  The nut travels 600 mm
    of stroke plus its own 171 mm (R40-10K5-FDC, H-BS Table 6.5 L) = 771 mm of thread.
    Uncompensated the lead row is e_p + v_u = 60 um; compensation of the representative travel
    leaves v_u = 25 um."""
    v = _eval(tmp_path)
    c = _eval(tmp_path, "  pitch_compensation: yes\n")
    assert v["lead_error"] == pytest.approx(60e-6)
    assert c["lead_error"] == pytest.approx(25e-6)


def test_repeatability_is_iso_scatter_not_thermal(tmp_path):
    """ISO 230-2: the reversal plus the noise band; the thermal drift stays its own row (a preloaded
    nut on a motor encoder: 0)."""
    v = _eval(tmp_path)
    assert v["thermal_error"] > 1e-6
    assert v["repeatability"] == pytest.approx(v["lost_motion"])
