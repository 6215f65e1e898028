"""A twin-drive gantry's checks per side (report.gantry.side_rows): the limits are checked on the
governing side (nearest the cross carriage at the end of its stroke); the far side at that moment
takes the rest.  The statics of a beam on two supports (written here apart from physics.gantry and
model.gantry): a force F on the cross carriage at y = s/2 splits as F (1/2 +/- s/2L), so the
difference between the sides' largest screw compression is (2r - 1) (F + m_c a), r = 1/2 + s/2L, up
to the guide friction of the mass moved across (a few newtons)."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest

from axisopt.model import evaluate
from axisopt.problem import load_problem
from axisopt.report.gantry import side_rows, twin_dict
from axisopt.search import solve

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def best():
    problem = load_problem(ROOT / "problems" / "gantry_twin_problem.yaml")
    res = solve(problem, "default", top=1, sensitivities=False)
    return problem, res.best.design


def test_sides_differ_by_the_statics_of_the_bridge(best):
    problem, design = best
    a, tw = problem.axis, problem.axis.twin_drive
    r = 0.5 + tw.cross_stroke / (2 * tw.span)
    rows = {row["check"]: row for row in side_rows(evaluate(design))}
    comp = rows["buckling"]
    expected = (2 * r - 1) * (a.axial_load + tw.cross_mass * a.acceleration)  # [N]
    assert (comp["needed_governing"] - comp["needed_far"]) * 1e3 == pytest.approx(
        expected, rel=0.01
    )
    # the governing side binds: every per-side margin is smaller there
    assert all(row["margin_governing"] < row["margin_far"] for row in rows.values())
    assert rows.keys() >= {"nut_life", "motor_rated_torque", "nut_lift_off"}


def test_a_centred_carriage_loads_both_sides_alike(best):
    """No cross stroke: the carriage stays at the centre, both sides carry half: no check
    differs."""
    _, design = best
    tw = design.axis.twin_drive
    centred = replace(design, axis=replace(design.axis, twin_drive=replace(tw, cross_stroke=0.0)))
    assert side_rows(evaluate(centred)) == []


def test_the_json_carries_the_sides(best):
    _, design = best
    d = twin_dict(evaluate(design))["twin_drive"]
    assert (
        d["sides"]
        and {"margin_governing", "margin_far", "needed_governing", "needed_far"}
        <= d["sides"][0].keys()
    )


def test_unknown_side_is_refused(best):
    _, design = best
    with pytest.raises(ValueError, match="side must be"):
        evaluate(design, side="left")


def test_the_long_screw_sag_is_shown(best):
    """The 4.28 m screw's own-weight sag is in the text and the JSON: q L^4 / (384 E I) for the
    fixed-fixed screw (AISC Table 3-23 case 15), written here from the catalog row (mass per metre,
    root diameter) and THK's E = 2.06e5 N/mm^2."""
    import math

    from axisopt.report.evaluation import evaluation_dict, evaluation_table

    _, design = best
    ev = evaluate(design)
    q = float(design.screw["mass_per_length"]) * 9.80665
    d_r = float(design.screw["root_diameter"])
    expected = q * design.axis.span**4 / (384 * 206e9 * math.pi * d_r**4 / 64)
    assert evaluation_dict(ev)["screw_sag_mm"] == pytest.approx(expected * 1e3, rel=1e-6)
    assert f"screw sag under its own weight {expected * 1e3:.2f} mm" in evaluation_table(ev)
