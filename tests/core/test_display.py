"""axisopt in a notebook (issue 30 item 3): ``import axisopt`` is light, its functions return
results with ``to_frame()`` (units in the column names), a short repr in engineering units and an
HTML table."""

from __future__ import annotations

from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PROBLEMS = ROOT / "problems"


def test_design_and_problem_reprs_are_short_and_in_engineering_units():
    import axisopt

    d = repr(axisopt.load_design(PROBLEMS / "teaching_design.yaml"))
    assert (
        d.startswith(
            "Design('teaching axis 25x5'; fixed-free, horizontal; stroke 300 mm; moving mass 60 "
            "kg; max speed 10 m/min"
        )
        and "nut HIWIN-R25-05K4-FDC" in d
        and len(d) < 400
    )
    p = repr(axisopt.load_problem(PROBLEMS / "vmc_x_problem.yaml"))
    assert p.startswith(
        "Problem('vmc-x'; objective maximise minimum first natural frequency; limits "
    )
    assert (
        "max_cost 7,000 EUR" in p and "min_stiffness 140 N/um" in p and "critical_speed 1.25" in p
    )


def test_tables_show_digits_enough_to_tell_designs_apart():
    # issue 42: the SolveResult table rounded to 3 figures, five designs all "161"
    from axisopt.display import fmt_column, html_table

    assert fmt_column([161.24, 161.38, 161.02]) == ["161.2", "161.4", "161.0"]
    assert fmt_column([71.4818, 71.4818, 71.4612]) == ["71.48", "71.48", "71.46"]
    assert fmt_column([2536.4, 2836.6]) == ["2,536", "2,837"]
    assert fmt_column([1, 2, None, "x"]) == ["1", "2", "-", "x"]
    html = html_table([{"k [N/um]": 161.24}, {"k [N/um]": 161.38}])
    assert "161.2" in html and "161.4" in html
