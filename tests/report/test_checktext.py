"""The check table (report.checktext) judged against the problem's margins: a margin the problem
allowed is no FAIL."""

from pathlib import Path

from axisopt.design import load_design
from axisopt.model import evaluate
from axisopt.report.checktext import check_lines, judged_rows

P = Path(__file__).resolve().parents[2] / "problems"


def test_checks_judged_against_the_problems_margins():
    # fails nut_life, bearing_life, bearing_fit
    ev = evaluate(load_design(P / "teaching_design.yaml"))
    rows = {r["check"]: r for r in ev.check_rows()}
    life, speed = rows["bearing_life"]["margin"], rows["critical_speed"]["margin"]
    assert not rows["bearing_life"]["pass"] and life < 1 and rows["critical_speed"]["pass"]
    judged = {
        r["check"]: r
        for r in judged_rows(
            ev, {"bearing_life": 0.9 * life, "critical_speed": 1.1 * speed, "nut_life": 0.0}
        )
    }
    assert judged["bearing_life"]["pass"] and judged["bearing_life"]["allowed"] == 0.9 * life
    assert not judged["critical_speed"]["pass"]  # a stricter margin the check misses
    assert judged["nut_life"]["pass"]  # switched off
    assert not judged["bearing_fit"]["pass"] and "allowed" not in judged["bearing_fit"]
    assert judged_rows(ev) == ev.check_rows()
    lines = check_lines(ev, {"bearing_life": 0.9 * life})
    line = next(ln for ln in lines if ln.lstrip().startswith("support bearing L10 life"))
    assert (
        line.endswith("pass*")
        and "bearing life" in lines[-1]
        and all(len(ln) <= 100 for ln in lines)
    )
