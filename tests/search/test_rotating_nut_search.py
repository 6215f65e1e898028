"""The search chooses a driven rotating-nut unit where the catalog offers one and the axis needs it
(a long axis whose turning screw would whirl), and never puts one on a screw not fixed at both
ends."""

from __future__ import annotations

from axisopt.catalog.loading import default_catalog
from axisopt.problem import load_problem
from axisopt.search import solve

LONG = """
name: long-thk
axis: {stroke: 2500 mm, moving_mass: 400 kg, mounting: fixed-fixed, max_speed: 16 m/min, axial_load: 3000 N,
       acceleration: 2 m/s^2, mean_speed: 6 m/min, pretension_rise: 2 K}
objective: stiffness
limits: {max_cost: 9000 EUR, min_life: 10000 h, max_screw_sag: 1 mm}
catalog:
  vendors: [THK, HIWIN]
  mountings: [{mountings}]
  motor_series: [Sigma-7 SGM7G]
  {extra}
continuous:
  nut_preload: {{min: 100 N, max: 10 kN}}
"""  # noqa: E501


def _problem(tmp_path, mountings="fixed-supported, fixed-fixed", extra=""):
    text = (
        LONG.replace("{mountings}", mountings)
        .replace("{extra}", extra)
        .replace("{{", "{")
        .replace("}}", "}")
    )
    path = tmp_path / "long.yaml"
    path.write_text(text, encoding="utf-8")
    return load_problem(path)


def test_a_long_axis_gets_a_rotating_nut_unit(tmp_path):
    """2.5 m stroke at 16 m/min: a turning 40x10 screw over a 2.78 m span may turn at 980 rpm (THK
    A-695, fixed-fixed, 0.8 safety), below the 1 600 rpm the speed asks; the THK DIR unit on a
    standing screw does not
    whirl: the proven optimum is a DIR unit, fixed-fixed."""
    res = solve(_problem(tmp_path), "default", top=1, sensitivities=False)
    assert res.certificate.proven
    best = res.best
    assert best.mounting == "fixed-fixed" and best.nut.startswith("THK-DIR")
    assert default_catalog().nuts.loc[best.nut]["rotating"] == 1


def test_a_required_unit_on_other_mountings_is_never_proposed(tmp_path):
    res = solve(
        _problem(tmp_path, "fixed-free, fixed-supported", "require: {nut: [THK-DIR4010-6]}"),
        "default",
        top=1,
        sensitivities=False,
    )
    assert res.best is None
    why = res.infeasibility
    assert "rotating-nut unit on a screw fixed at both ends" in why.relax_blocked_by
    assert all(r.key != "limits.margins.rotating_mount" for r in why.relax)


def test_a_scale_leaves_offered_units_out(tmp_path):
    """The same long axis with a linear scale on the table (axis.feedback: linear_scale): a driven
    rotating-nut unit takes no scale (evaluate refuses that design), so the search proposes none
    (without the scale its proven optimum is a DIR unit: the test above; with the units left out
    nothing remains)."""
    path = tmp_path / "scale.yaml"
    text = LONG.replace("{mountings}", "fixed-supported, fixed-fixed").replace("{extra}", "")
    text = text.replace("{{", "{").replace("}}", "}")
    text = text.replace(
        "pretension_rise: 2 K}",
        "pretension_rise: 2 K,\n       feedback: linear_scale, scale_grade: AMO-LMB-5}",
    )
    path.write_text(text, encoding="utf-8")
    res = solve(load_problem(path), "default", top=1, sensitivities=False)
    # at 16 m/min over 2.78 m only a unit does not whirl (the test above): with the units left out
    # no design remains
    assert res.best is None, res.best
