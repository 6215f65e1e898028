"""The no-load drag torque at the motor (model.drag) restated by hand from THK's forms: the nut's
preload drag K F_a0 P_h / (2 pi), K = 0.05 / sqrt(tan beta) (THK / HIWIN / NSK catalog form,
vendor-formulas.md sec. 2.6), the support bearings' starting torque, the guide friction through the
lead at the screw efficiency."""

from __future__ import annotations

import math

import pytest

from axisopt.model.drag import SCREW_EFFICIENCY, drag_torque

P = {
    "max_speed": 0.5,  # m/s
    "lead": 0.010,
    "nominal_diameter": 0.032,
    "bearing_sets": 2.0,
    "bearing_torque": 0.15,  # N*m per set
}


def _nut(preload, lead, d):
    tan_beta = lead / (math.pi * d)
    return 0.05 / math.sqrt(tan_beta) * preload * lead / (2 * math.pi)


def test_drag_by_source_on_a_turning_screw():
    out = drag_torque(P, 1500.0, {"guide_friction": 60.0})
    t_nut = _nut(1500.0, 0.010, 0.032)
    t_guides = 60.0 * 0.010 / (2 * math.pi * SCREW_EFFICIENCY)
    assert out["drag_nut"] == pytest.approx(t_nut, rel=1e-12)
    assert out["drag_bearings"] == pytest.approx(2 * 0.15, rel=1e-12)
    assert out["drag_guides"] == pytest.approx(t_guides, rel=1e-12)
    assert out["drag_torque"] == pytest.approx(t_nut + 0.3 + t_guides, rel=1e-12)
    assert out["screw_speed"] == pytest.approx(0.5 / 0.010 * 2 * math.pi, rel=1e-12)  # 50 rev/s
    assert SCREW_EFFICIENCY == 0.9  # vendor typical (THK, HIWIN: 0.9-0.95)


def test_a_driven_rotating_nut_turns_its_unit_bearing_not_the_end_sets():
    p = {**P, "nut_rotating": 1.0, "unit_bearing_torque": 0.4}
    out = drag_torque(p, 0.0, {"guide_friction": 0.0})
    assert out["drag_bearings"] == pytest.approx(0.4, rel=1e-12)
    assert out["drag_nut"] == 0.0 and out["drag_torque"] == pytest.approx(0.4, rel=1e-12)
