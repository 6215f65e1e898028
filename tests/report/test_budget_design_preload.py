"""The evaluation's thermal row at the design's own preload (issue 53): the heat balance of the nut
at the preload the design states, not at the nut's top catalog preload, which stays the bound the
positioning limit holds (model.accuracy, conservative so the search's preload solve stays exact)."""

import pytest

from axisopt.design import load_design
from axisopt.model import evaluate
from axisopt.physics.thermal import ALPHA_STEEL
from axisopt.report.accuracy import budget_rows

AXIS = """name: grinder
axis:
  stroke: 600 mm
  moving_mass: 200 kg
  mounting: fixed-supported
  max_speed: 10 m/min
  axial_load: 500 N
  rise_without_cycle: balance
parts:
  screw: HIWIN-G-40x10-b6p35
  nut: HIWIN-R40-10K5-FDC
  bearing: HIWIN-WBK20-DF
  guide: HIWIN-HG20-ZA
  nut_preload: {preload}
"""
TOP = 6340.0  # HIWIN-R40-10K5-FDC's highest catalog preload [N] (H-BS Table 6.5)


def _rows(tmp_path, preload, rise="balance"):
    f = tmp_path / f"d{preload:.0f}{rise}.yaml"
    text = AXIS.format(preload=f"{preload:g} N").replace(
        "rise_without_cycle: balance", f"rise_without_cycle: {rise}"
    )
    f.write_text(text, encoding="utf-8")
    ev = evaluate(load_design(f))
    return ev, {label: value for label, value, _ in budget_rows(ev)}


def test_thermal_row_follows_the_designs_preload(tmp_path):
    low, r_low = _rows(tmp_path, 2000.0)
    top, r_top = _rows(tmp_path, TOP)
    thermal = "thermal drift at the nut"
    # at the top preload the design's row and the limit's bound coincide: one total, no bound row
    assert r_top[thermal] == pytest.approx(float(top.values["thermal_error"]), rel=1e-9)
    assert "total the limit holds (thermal at top preload)" not in r_top
    # below it, less friction heat: the row falls with the design's preload, the bound does not
    assert r_low[thermal] < 0.9 * r_top[thermal]
    assert float(low.values["thermal_error"]) == pytest.approx(
        float(top.values["thermal_error"]), rel=1e-9
    )
    # the row is the growth of the rise the design's balance gives: alpha x rise x length scale,
    # bounded by the free growth over the far end's distance from the fixed bearing (A-715: delta_l
    # = rho x theta x l)
    rise = float(low.values["temperature_rise"])
    far = low.design.axis.start_offset + low.design.axis.stroke
    assert 0 < r_low[thermal] <= ALPHA_STEEL * rise * far * (1 + 1e-9)
    # the total shown adds the rows shown; the limit's total (thermal at the top preload) is printed
    # beside it
    shown = [v for k, v in r_low.items() if not k.startswith(("total", "repeatability"))]
    assert r_low["total, arithmetic worst case"] == pytest.approx(sum(shown), rel=1e-12)
    assert r_low["total the limit holds (thermal at top preload)"] == pytest.approx(
        float(low.values["positioning_error"]), rel=1e-12
    )
    assert (
        r_low["total the limit holds (thermal at top preload)"]
        > r_low["total, arithmetic worst case"]
    )


@pytest.mark.published
def test_thermal_warning_at_thk_planning_range(tmp_path):
    """THK A-715: a 2-5 degC rise is planned for with a target travel of -0.02 to -0.06 mm/m; a
    growth beyond 0.06 mm/m over the far end's distance from the fixed bearing is warned of, naming
    the key that bounds it."""
    from axisopt.report.drivetext import thermal_warning

    seen = set()
    for preload, rise in ((2000.0, "balance"), (TOP, "balance"), (2000.0, "practice")):
        ev, _ = _rows(tmp_path, preload, rise)
        growth = float(ev.values["thermal_growth"])
        far = ev.design.axis.start_offset + ev.design.axis.stroke
        warn = thermal_warning(ev)
        assert ("exceeds THK A-715's planning range" in warn) == (growth > 0.06e-3 * far), (
            preload,
            growth,
        )
        seen.add(growth > 0.06e-3 * far)
        if growth > 0.06e-3 * far:
            assert "limits.max_thermal_growth" in warn
    assert seen == {
        True,
        False,
    }  # both sides of the planning range met: 104 / 324 um and the practice 3 K
