"""``axisopt solve`` says on a line of its own when the guides were sized without the cut's normal
or cross component (axis.normal_load, axis.cross_load not given while axial_load is), with the
turning rule of thumb F_f = 0.5 F_c, F_p = 0.25 F_c (E. Isakov, "Calculated Forces When Turning",
Cutting Tool Engineering, 2013) as guidance; the JSON carries the same."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from axisopt.cli import main
from axisopt.problem import load_problem
from axisopt.report.solve import load_components

ROOT = Path(__file__).resolve().parents[2]
TEACHING = (ROOT / "problems" / "teaching_problem.yaml").read_text(encoding="utf-8")
LINE = "guides sized without the cut's"


def _solve(tmp_path, capsys, text, *extra):
    path = tmp_path / "p.yaml"
    path.write_text(text, encoding="utf-8")
    main(["solve", str(path), "--no-sensitivity", "--top", "1", *extra])
    return capsys.readouterr().out


def test_line_names_the_missing_component_with_the_rule_of_thumb(tmp_path, capsys):
    out = _solve(tmp_path, capsys, TEACHING)  # cross_load given, normal_load not
    lines = [ln for ln in out.splitlines() if LINE in ln]
    assert len(lines) == 1 and "normal_load" in lines[0] and "cross_load" not in lines[0]
    flat = " ".join(out.split())
    assert "Isakov, CTE 2013: F_f = 0.5 F_c, F_p = 0.25 F_c" in flat
    # axial_load 2000 N as the feed force: F_c = 2000 / 0.5 = 4000 N, F_p = 0.25 F_c = 1000 N
    assert "tangential force near 4,000 N, the passive near 1,000 N" in flat


def test_line_disappears_when_both_components_are_given(tmp_path, capsys):
    text = TEACHING.replace(
        "  cross_load: 1000 N\n", "  cross_load: 1000 N\n  normal_load: 500 N\n"
    )
    assert text != TEACHING
    assert LINE not in _solve(tmp_path, capsys, text)


def test_line_disappears_without_an_axial_load(tmp_path, capsys):
    text = TEACHING.replace("axial_load: 2000 N", "axial_load: 0 N")
    assert text != TEACHING
    assert LINE not in _solve(tmp_path, capsys, text)


def test_json_carries_it(tmp_path, capsys):
    out = json.loads(_solve(tmp_path, capsys, TEACHING, "--json", "-"))
    comp = out["load_components"]
    assert comp["missing"] == ["normal_load"] and comp["tangential_estimate_N"] == pytest.approx(
        4000.0
    )
    assert comp["passive_estimate_N"] == pytest.approx(1000.0) and "Isakov" in comp["rule"]
    both = TEACHING.replace("  cross_load: 1000 N\n", "")
    assert json.loads(_solve(tmp_path, capsys, both, "--json", "-"))["load_components"][
        "missing"
    ] == ["normal_load", "cross_load"]


def test_shipped_problems_that_give_both_have_no_line():
    for name in ("duty_cycle_problem", "gantry_problem", "vertical_problem", "highspeed_problem"):
        p = load_problem(ROOT / "problems" / f"{name}.yaml")
        assert load_components(p.axis, p.assumed) is None, name
