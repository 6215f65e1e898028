"""Bad accuracy inputs refused in one line on stderr, exit 2, naming the file and the key (issue
43): an unknown grade, a grade the screw is not made in, a grade without a tolerance over the
stroke, a negative, NaN, huge or unitless guide pitch or yaw, a negative tool offset, unknown grades
in a problem's catalog.screw_grades, a negative positioning limit; and the good inputs: the budget
printed with its grade."""

from __future__ import annotations

from pathlib import Path

import pytest
from cli_helpers import one_line_error, write_file

from axisopt.cli import main

ROOT = Path(__file__).resolve().parents[2]
DESIGN = (ROOT / "problems" / "teaching_design.yaml").read_text(encoding="utf-8")
PROBLEM = (ROOT / "problems" / "precision_problem.yaml").read_text(encoding="utf-8")


def _design(tmp_path, parts_extra: str = "", axis_extra: str = "") -> str:
    text = DESIGN.replace("parts:\n", "parts:\n" + parts_extra, 1).replace(
        "axis:\n", "axis:\n" + axis_extra, 1
    )
    return write_file(tmp_path, "d.yaml", text)


@pytest.mark.parametrize(
    ("parts", "axis", "needle"),
    [
        ("  screw_grade: C4\n", "", "key 'parts.screw_grade': unknown grade 'C4'"),
        ("  screw_grade: C7\n", "", "is not made in grade C7 (its series: C0 C1 C2 C3 C5"),
        ("  screw_grade: 5\n", "", "key 'parts.screw_grade'"),
        ("", "  guide_pitch: -3 arcsec\n", "key 'axis.guide_pitch': must not be negative"),
        ("", "  guide_pitch: nan arcsec\n", "key 'axis.guide_pitch'"),
        ("", "  guide_pitch: 1e300 arcsec\n", "key 'axis.guide_pitch'"),
        ("", "  guide_pitch: 3\n", "key 'axis.guide_pitch'"),
        ("", "  guide_yaw: 2 mm\n", "key 'axis.guide_yaw'"),
        ("", "  tool_offset: -10 mm\n", "key 'axis.tool_offset': must not be negative"),
    ],
)
def test_bad_accuracy_input_in_a_design_is_a_one_line_error(tmp_path, capsys, parts, axis, needle):
    path = _design(tmp_path, parts, axis)
    assert main(["evaluate", path]) == 2
    err = one_line_error(capsys)
    assert "d.yaml" in err and needle in err, err


def test_a_grade_without_a_tolerance_over_the_stroke_is_refused(tmp_path, capsys):
    # THK A-678 Table 1 lists no C0 beyond 1600 mm of travel
    text = DESIGN.replace("stroke: 300 mm", "stroke: 1700 mm").replace(
        "parts:\n", "parts:\n  screw_grade: C0\n"
    )
    path = write_file(tmp_path, "d.yaml", text)
    assert main(["evaluate", path]) == 2
    err = one_line_error(capsys)
    # judged over the travelled thread: the 1700 mm stroke and the nut's 90 mm
    assert "key 'parts.screw_grade'" in err, err
    assert "no lead tolerance over a 1790 mm travelled" in err, err


@pytest.mark.parametrize(
    ("old", "new", "needle"),
    [
        (
            "  nut_types: [double]\n",
            "  nut_types: [double]\n  screw_grades: [C4]\n",
            "key 'catalog.screw_grades'",
        ),
        (
            "  nut_types: [double]\n",
            "  nut_types: [double]\n  screw_grades: []\n",
            "key 'catalog.screw_grades'",
        ),
        (
            "max_positioning_error: 40 um",
            "max_positioning_error: -40 um",
            "key 'limits.max_positioning_error'",
        ),
        (
            "max_positioning_error: 40 um",
            "max_positioning_error: 40",
            "key 'limits.max_positioning_error'",
        ),
    ],
)
def test_bad_accuracy_input_in_a_problem_is_a_one_line_error(tmp_path, capsys, old, new, needle):
    assert old in PROBLEM
    path = write_file(tmp_path, "p.yaml", PROBLEM.replace(old, new, 1))
    assert main(["solve", path, "--no-sensitivity"]) == 2
    err = one_line_error(capsys)
    assert "p.yaml" in err and needle in err, err


def test_no_screw_in_the_allowed_grades_is_a_one_line_error(tmp_path, capsys):
    # catalog.screw_grades [C8]: no shipped HIWIN or THK shaft is rolled
    text = PROBLEM.replace(
        "  nut_types: [double]\n", "  nut_types: [double]\n  screw_grades: [C8]\n", 1
    )
    path = write_file(tmp_path, "p.yaml", text)
    assert main(["solve", path, "--no-sensitivity"]) == 2
    err = one_line_error(capsys)
    assert "no screw left is made in the grades" in err, err


def test_the_budget_names_its_grade(tmp_path, capsys):
    path = _design(tmp_path, "  screw_grade: C3\n", "  guide_pitch: 10 arcsec\n")
    assert main(["evaluate", path]) in (0, 1)
    out = capsys.readouterr().out
    assert "screw HIWIN-G-25x5-b3p175 grade C3" in out
    # THK A-678 T.1: 13 + 10 um over 315-400 mm (the 300 mm stroke and the nut's 90 mm)
    assert "lead error, grade C3                            23.0" in out
    assert "total, arithmetic worst case" in out and "repeatability (ISO 230-2)" in out
