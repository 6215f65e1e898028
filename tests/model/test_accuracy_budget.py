"""The positioning-error budget of an evaluated design (model.accuracy, issue 43): its rows against
the grade tables (THK A-678 Table 1) and the model's own outputs, the total as their sum, and the
direction the search relies on (the total does not rise with the nut preload, with the heat balance
on or off)."""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from axisopt import model
from axisopt.design import load_design
from axisopt.model.accuracy import BUDGET_ROWS
from axisopt.model.params import positions
from axisopt.physics import motion

ROOT = Path(__file__).resolve().parents[2]
ARCSEC = math.pi / 180 / 3600


def _design(**axis):
    d = load_design(ROOT / "problems" / "teaching_design.yaml")
    return replace(d, axis=replace(d.axis, **axis)) if axis else d


@pytest.mark.published
@pytest.mark.parametrize(("grade", "um"), [("C0", 8.5), ("C1", 12), ("C3", 23), ("C5", 45)])
def test_lead_row_is_the_grade_tolerance_over_the_travelled_thread(grade, um):
    # the nut travels the 300 mm stroke plus its own length, 90 mm (HIWIN R25-05K4-FDC, H-BS Table
    # 6.5 L): THK A-678 Table 1, band 315-400 mm: C0 5 + 3.5, C1 7 + 5, C3 13 + 10, C5 25 + 20 um
    ev = model.evaluate(replace(_design(), screw_grade=grade))
    assert ev["lead_error"] == pytest.approx(um * 1e-6)


def test_rows_add_up_and_read_the_model():
    d = _design(
        guide_pitch=8 * ARCSEC, guide_yaw=4 * ARCSEC, tool_offset=0.05, temperature_rise=2.0
    )
    ev = model.evaluate(d)
    v = ev.values
    assert v["positioning_error"] == pytest.approx(sum(v[k] for k in BUDGET_ROWS))
    # a stated rise: the model's growth
    assert v["thermal_error"] == pytest.approx(v["thermal_growth"])
    assert v["lost_motion"] == pytest.approx(v["backlash"])
    a = d.axis
    assert v["abbe_error"] == pytest.approx(
        a.tool_height_eff * math.sin(8 * ARCSEC) + 0.05 * math.sin(4 * ARCSEC)
    )
    # the elastic row at the softest point: the process force over the least tool stiffness on a
    # fine grid
    fine = model.evaluate(replace(d, axis=replace(a, positions=401)))
    assert v["elastic_error"] == pytest.approx(a.axial_load / np.min(fine["k_tool"]), rel=1e-6)
    # ISO 230-2: reversal + noise (encoder: 0)
    assert v["repeatability"] == pytest.approx(v["lost_motion"])


@pytest.mark.parametrize("mounting", ["fixed-free", "fixed-supported", "fixed-fixed"])
def test_elastic_row_is_the_softest_point_for_every_mounting(mounting):
    d = _design()
    d = replace(d, axis=replace(d.axis, mounting=mounting, positions=401))
    ev = model.evaluate(d)
    assert len(positions(d.axis)) >= 401
    fine = d.axis.axial_load / np.min(ev["k_tool"])
    # the worst of each term, from two positions: a slight overestimate
    if mounting == "fixed-fixed":
        assert fine * (1 - 1e-9) <= ev["elastic_error"] <= fine * 1.01
    else:
        assert ev["elastic_error"] == pytest.approx(fine, rel=1e-6)


@pytest.mark.parametrize("heat", [False, True])
def test_total_does_not_rise_with_the_preload(heat):
    """model.limits declares positioning_error nonincreasing in the preload: the thermal row is
    taken at the nut's highest preload (the heat balance) or the stated rise, the deflection
    falls."""
    cycle = (
        motion.Segment("move", distance=0.3, speed=0.33, acceleration=2.0),
        motion.Segment("move", distance=-0.3, speed=0.33, acceleration=2.0),
        motion.Segment("dwell", duration=1.0),
    )
    d = _design(duty_cycle=cycle, temperature_rise=None, acceleration=2.0) if heat else _design()
    assert getattr(d.axis.phases, "heat", None) is heat
    p = model.design_params(d)
    x = positions(d.axis)
    lo, hi = float(d.nut["preload_min"]), float(d.nut["preload_max"])
    vals = [
        float(model.axis_response(p, x, d.axis.mounting, pre)["positioning_error"])
        for pre in np.linspace(lo, hi, 7)
    ]
    assert all(b <= a * (1 + 1e-12) for a, b in zip(vals, vals[1:]))
    out = model.axis_response(p, x, d.axis.mounting, hi)
    assert float(out["thermal_error"]) >= float(out["thermal_growth"]) * (1 - 1e-12)
