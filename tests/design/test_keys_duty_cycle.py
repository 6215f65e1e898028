"""The motion actually commanded (issue 24, item 4): the speed and acceleration the physics checks
read come from the duty cycle's moves; a move faster than axis.max_speed, or a motor without an
acceleration, is an error naming the key."""

from __future__ import annotations

from pathlib import Path

import pytest
from cli_helpers import one_line_error, write_file

from axisopt.cli import main

ROOT = Path(__file__).resolve().parents[2]
PROBLEMS = ROOT / "problems"
VMC = (PROBLEMS / "vmc_x_design.yaml").read_text(encoding="utf-8")


def test_duty_cycle_faster_than_max_speed_is_an_error_naming_the_key(tmp_path, capsys):
    text = VMC.replace(
        "  table_length: 600 mm\n",
        "  table_length: 600 mm\n  duty_cycle:\n"
        "    - {move: 300 mm, speed: 60 m/min}\n    - {move: -300 mm}\n",
    )
    assert main(["evaluate", write_file(tmp_path, "d.yaml", text)]) == 2
    err = one_line_error(capsys)
    assert "d.yaml" in err and "axis.duty_cycle[0].speed" in err and "max_speed" in err


def test_checks_read_the_highest_acceleration_commanded(tmp_path):
    from axisopt.design import load_design
    from axisopt.model.function import design_params

    text = VMC.replace(
        "  table_length: 600 mm\n",
        "  table_length: 600 mm\n  duty_cycle:\n"
        "    - {move: 300 mm, acceleration: 6 m/s^2}\n    - {move: -300 mm}\n",
    )
    d = load_design(write_file(tmp_path, "d.yaml", text))
    assert d.axis.acceleration == 3.0 and d.axis.top_acceleration == 6.0
    assert float(design_params(d)["acceleration"]) == 6.0
    assert float(design_params(d)["max_speed"]) == pytest.approx(0.4)
    base = load_design(PROBLEMS / "vmc_x_design.yaml")
    assert float(design_params(base)["acceleration"]) == 3.0  # unchanged without a faster move


def test_motor_without_acceleration_is_an_error_in_a_design_and_a_problem(tmp_path, capsys):
    design = VMC.replace("  acceleration: 3 m/s^2\n", "")
    assert main(["evaluate", write_file(tmp_path, "d.yaml", design)]) == 2
    assert "acceleration" in one_line_error(capsys)
    problem = (PROBLEMS / "teaching_problem.yaml").read_text(encoding="utf-8")
    problem = (
        "\n".join(ln for ln in problem.splitlines() if not ln.strip().startswith("acceleration:"))
        + "\n"
    )
    assert main(["solve", write_file(tmp_path, "p.yaml", problem)]) == 2
    err = one_line_error(capsys)
    assert "axis.acceleration" in err and "p.yaml" in err
