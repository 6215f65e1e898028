"""Bad input on the vendor-rule keys (axis.torque_limit, axis.cut_while_accelerating): one line,
exit 2; a torque limit below the coupling's need admits the smaller coupling (the limit caps the
motor's torque)."""

import subprocess
import sys
from pathlib import Path

import pytest
from cli_helpers import one_line_error

from axisopt.cli import main

ROOT = Path(__file__).resolve().parents[2]


def _run(tmp_path, line, monkeypatch) -> int:
    """``axisopt solve`` of the teaching problem with ``line`` added under axis:, in this process
    (the real entry point's exit 2 and one stderr line:
    test_scale_on_a_rotating_nut_unit_one_line_exit_2)."""
    text = (ROOT / "problems/teaching_problem.yaml").read_text(encoding="utf-8")
    f = tmp_path / "p.yaml"
    f.write_text(text.replace("\naxis:\n", f"\naxis:\n  {line}\n", 1), encoding="utf-8")
    monkeypatch.chdir(ROOT)
    return main(["solve", str(f)])


def _process_error(command: str, path) -> str:
    """``axisopt COMMAND PATH`` as a process: exit 2 and one stderr line, returned."""
    r = subprocess.run(
        [sys.executable, "-m", "axisopt", command, str(path)],
        capture_output=True,
        text=True,
        cwd=ROOT,
        timeout=300,
    )
    assert r.returncode == 2 and r.stderr.count("\n") == 1, r.stderr
    return r.stderr


@pytest.mark.parametrize(
    "line, word",
    [
        ("torque_limit: -5 N.m", "must be positive"),
        ("torque_limit: 0 N.m", "must be positive"),
        ("torque_limit: 5 kg", "torque_limit"),
        ("cut_while_accelerating: maybe", "cut_while_accelerating"),
        ("buckling_nut_end: clamped", "buckling_nut_end"),
        ("rise_without_cycle: hot", "rise_without_cycle"),
        ("feedback: linear_scale", "scale_grade"),
        ("scale_grade: HEIDENHAIN-1", "scale_grade"),
        ("feedback: glass", "feedback"),
    ],
)
def test_bad_vendor_rule_keys_one_line_exit_2(tmp_path, line, word, monkeypatch, capsys):
    assert _run(tmp_path, line, monkeypatch) == 2
    assert word in one_line_error(capsys)


def test_scale_on_a_rotating_nut_unit_one_line_exit_2(tmp_path):
    text = """name: rotating nut with a scale
axis:
  stroke: 600 mm
  moving_mass: 200 kg
  mounting: fixed-fixed
  max_speed: 10 m/min
  axial_load: 500 N
  feedback: linear_scale
  scale_grade: AMO-LMB-5
parts:
  screw: THK-DIR-40x10
  nut: THK-DIR4010-6
  bearing: THK-BK30
  guide: HIWIN-HG20-ZA
"""
    f = tmp_path / "d.yaml"
    f.write_text(text, encoding="utf-8")
    err = _process_error("evaluate", f)
    assert "rotating-nut" in err and "linear_scale" in err


def test_a_required_unit_with_a_scale_in_a_problem_one_line_exit_2(tmp_path):
    """A problem that requires a driven rotating-nut unit and puts a linear scale on the table: the
    combination evaluate refuses is refused as the problem is read (not proposed as an optimum)."""
    text = """name: long-thk
axis: {stroke: 2500 mm, moving_mass: 400 kg, mounting: fixed-fixed, max_speed: 16 m/min,
       axial_load: 3000 N, feedback: linear_scale, scale_grade: AMO-LMB-5}
objective: stiffness
catalog:
  vendors: [THK, HIWIN]
  require: {nut: [THK-DIR4010-6]}
"""
    f = tmp_path / "p.yaml"
    f.write_text(text, encoding="utf-8")
    err = _process_error("solve", f)
    assert "catalog.require.nut" in err and "linear_scale" in err
