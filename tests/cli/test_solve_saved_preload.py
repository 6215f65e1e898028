"""``axisopt solve --save-design`` writes the nut preload in round figures (issue 42 item 3): the
value a designer orders, rounded the way that keeps every limit the optimum sits on, read back by
``axisopt evaluate``."""

import json
import math
from dataclasses import replace
from pathlib import Path

import pytest
import yaml

from axisopt.cli import main
from axisopt.design import load_design
from axisopt.model import evaluate
from axisopt.problem import load_problem
from axisopt.report.partslist import parts_list, preload_step
from axisopt.search.task.constraints import build_constraints

PROBLEMS = Path(__file__).resolve().parents[2] / "problems"


def _save_and_reload(tmp_path, name):
    out, js = tmp_path / "best.yaml", tmp_path / "solve.json"
    assert (
        main(
            [
                "solve",
                str(PROBLEMS / name),
                "--no-sensitivity",
                "--json",
                str(js),
                "--save-design",
                str(out),
            ]
        )
        == 0
    )
    exact = json.loads(js.read_text())["best"]["nut_preload"]
    ev_json = tmp_path / "ev.json"
    assert main(["evaluate", str(out), "--json", str(ev_json)]) == 0
    return out, exact, json.loads(ev_json.read_text())


def _missed(problem, design, preload):
    ev = evaluate(replace(design, nut_preload=preload))
    return [c.name for c in build_constraints(problem) if not c.ok(c.value(ev.values))]


def _significant(x: float) -> int:
    digits = f"{x:.12g}".replace(".", "").lstrip("0").rstrip("0")
    return len(digits)


@pytest.mark.parametrize(
    "name", ["precision_problem.yaml", "teaching_problem.yaml", "duty_cycle_problem.yaml"]
)
def test_saved_preload_is_round_and_keeps_every_limit(tmp_path, capsys, name):
    out, exact, ev = _save_and_reload(tmp_path, name)
    problem, design = load_problem(PROBLEMS / name), load_design(out)
    written = yaml.safe_load(out.read_text(encoding="utf-8"))["parts"]["nut_preload"]
    value = float(written.split()[0])
    assert written.endswith(" N") and _significant(value) <= 4 and value == design.preload
    assert abs(value - exact) < preload_step(exact) and ev["nut_preload_N"] == value
    # every vendor check of the reloaded design passes, and every limit of the problem holds at it
    assert ev["all_checks_pass"] and all(c["pass"] for c in ev["checks"].values())
    assert _missed(problem, design, value) == []
    assert problem.preload_min <= value <= problem.preload_max
    capsys.readouterr()


@pytest.mark.parametrize("name", ["teaching_problem.yaml", "duty_cycle_problem.yaml"])
def test_saved_preload_goes_the_safe_way_where_the_nearest_breaks_a_limit(tmp_path, capsys, name):
    # teaching: the nut life binds (min_life 12 000 h) and 1150 N would shorten it; duty cycle: the
    # drag torque binds (2 N.m) and the nearest 10 N would raise it
    out, exact, _ = _save_and_reload(tmp_path, name)
    problem, design = load_problem(PROBLEMS / name), load_design(out)
    step = preload_step(exact)
    nearest = step * round(exact / step)
    assert _missed(problem, design, nearest), (
        "the case must be one where plain rounding breaks a limit"
    )
    value = design.preload
    assert (
        value != nearest
        and abs(value - exact) < step
        and math.isclose(value % step, 0, abs_tol=1e-9)
    )
    assert _missed(problem, design, value) == []
    line = next(ln for ln in out.read_text(encoding="utf-8").splitlines() if "nut_preload:" in ln)
    assert "# " in line and f"{nearest:.6g} N would break" in line
    # the parts list to order shows the same preload
    nut = next(r for r in parts_list(design, problem) if r["part"] == "nut")
    assert nut["order"] == f"preload {value:,.0f} N"
    capsys.readouterr()
