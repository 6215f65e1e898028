"""A lead band resting on the nut-length estimate says so (issue 53): the paper's 40x10 double nut
has no length in its table (catalogs/SOURCES.md), so the lead row reads stroke + 5.1 (P + d)
(physics.nut.nut_length_estimate) and the budget prints a line naming it; a nut whose vendor lists
its length prints none, nor does a design on a linear scale (its row does not read the lead)."""

from pathlib import Path

from axisopt.design import load_design
from axisopt.model import evaluate
from axisopt.report.accuracy import budget_lines

ROOT = Path(__file__).resolve().parents[2]


def _lines(path) -> list:
    return budget_lines(evaluate(load_design(path)))


def test_an_estimated_nut_length_is_named_under_the_budget():
    lines = _lines(ROOT / "problems" / "paper_3_1_3_d40.yaml")
    # a double nut on the 40x10 screw: 5.1 x (10 + 40) mm = 255 mm, over the 1800 mm stroke
    assert any("over 1800 + 255 mm nut" in x for x in lines)
    note = [x for x in lines if "rests on an estimate" in x]
    assert note == [
        "  the lead row rests on an estimate: nut length 255 mm = 5.1 (P + d) "
        "(its vendor lists none)"
    ]


def test_a_listed_nut_length_is_not_named():
    assert not any("rests on an estimate" in x for x in _lines(ROOT / "problems/vmc_x_design.yaml"))


def test_a_scale_does_not_rest_on_the_nut_length(tmp_path):
    text = (ROOT / "problems" / "paper_3_1_3_d40.yaml").read_text(encoding="utf-8")
    f = tmp_path / "scale.yaml"
    f.write_text(
        text.replace(
            "\naxis:\n", "\naxis:\n  feedback: linear_scale\n  scale_grade: AMO-LMB-5\n", 1
        ),
        encoding="utf-8",
    )
    lines = _lines(f)
    assert any("linear scale AMO-LMB-5" in x for x in lines)
    assert not any("rests on an estimate" in x for x in lines)
