"""``axisopt compare`` on the shipped designs and a problem (solved to its best design)."""

from __future__ import annotations

import json

from study_helpers import PROBLEMS

from axisopt.cli import main


def test_compare_json_to_stdout_and_errors(tmp_path, capsys):
    assert main(["compare", str(PROBLEMS / "teaching_design.yaml"), "--json", "-"]) == 0
    assert json.loads(capsys.readouterr().out)["designs"][0]["label"] == "teaching axis 25x5"
    bad = tmp_path / "bad.yaml"
    bad.write_text("name: x\naxis: {stroke: 800}\nparts: {}\n")
    assert main(["compare", str(bad)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "stroke" in err


def test_compare_infeasible_problem_exits_1(capsys):
    assert (
        main(
            [
                "compare",
                str(PROBLEMS / "teaching_design.yaml"),
                str(PROBLEMS / "infeasible_problem.yaml"),
            ]
        )
        == 1
    )
    assert "no design to compare" in capsys.readouterr().err
