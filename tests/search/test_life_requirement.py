"""One life requirement: a problem's ``limits.min_life`` is the life the nut, bearing and guide
checks need unless its axis sets ``required_life`` (before, a hidden 20 000 h default bound beside a
user's 15 000 h limit, and relaxing the limit showed no gain)."""

from __future__ import annotations

from pathlib import Path

import pytest

from axisopt.problem import load_problem
from axisopt.search import solve

ROOT = Path(__file__).resolve().parents[2]
H = 3600.0


def test_required_life_follows_the_life_limit_and_its_relaxation():
    # min_life 12000 h, no required_life
    p = load_problem(ROOT / "problems" / "teaching_problem.yaml")
    assert p.limit_map["min_life"] == 12000 * H
    assert p.axis.required_life == 12000 * H
    # not a default any more: the output does not list it as one
    assert "required_life" not in p.assumed
    assert p.with_limit("min_life", 10800 * H).axis.required_life == 10800 * H


def test_an_explicit_required_life_stands(tmp_path):
    text = (ROOT / "problems" / "teaching_problem.yaml").read_text(encoding="utf-8")
    f = tmp_path / "p.yaml"
    f.write_text(text.replace("axis:\n", "axis:\n  required_life: 30000 h\n", 1), encoding="utf-8")
    p = load_problem(f)
    assert p.axis.required_life == 30000 * H
    assert p.with_limit("min_life", 13500 * H).axis.required_life == 30000 * H


def test_the_bearing_check_needs_the_life_limit(tmp_path):
    # teaching's support-bearing sets live less than 13 000 h at its mean speed and fw 1.5 (the best
    # 12 360 h): a 13 000 h life limit leaves no design once the bearing check needs it too, while
    # with an explicit 12 000 h check requirement the limit holds the nut alone (it binds there) and
    # a design exists
    p = load_problem(ROOT / "problems" / "teaching_problem.yaml")
    assert solve(p.with_limit("min_life", 13000 * H), sensitivities=False).status == "infeasible"
    text = (ROOT / "problems" / "teaching_problem.yaml").read_text(encoding="utf-8")
    f = tmp_path / "p.yaml"
    f.write_text(
        text.replace("axis:\n", "axis:\n  required_life: 12000 h\n", 1).replace(
            "min_life: 12000 h", "min_life: 13000 h"
        ),
        encoding="utf-8",
    )
    res = solve(load_problem(f), sensitivities=False)
    assert res.status == "optimal"
    # the nut's limit binds; the bearings need 12 000 h
    assert res.best.life_h == pytest.approx(13000, rel=1e-6)


def test_the_defaults_line_shows_the_values_the_life_checks_read(capsys):
    from axisopt.cli import main

    # teaching: axial_load 2000 N, no mean axial load given: a third of the load; its mean_speed is
    # given, so it is not a default
    assert (
        main(["solve", str(ROOT / "problems" / "teaching_problem.yaml"), "--no-sensitivity"]) == 0
    )
    out = capsys.readouterr().out
    text = " ".join(out[out.index("defaults used for:") :].split("\n\n")[0].split())
    # THK Table 19 at 30 m/min
    assert "mean_axial_load 666.7 N" in text and "load_factor 1.5" in text
    assert "mean_speed" not in text
    assert "required_life" not in text  # it follows limits.min_life: not a default


def test_the_life_limits_sensitivity_is_the_gain_of_solving_it_relaxed():
    # relaxing min_life relaxes the checks' required life too (a new search space: the parts'
    # parameters carry it); the sensitivity table once re-solved on the old space and showed +0
    # where the life binds
    p = load_problem(ROOT / "problems" / "teaching_problem.yaml")
    res = solve(p)
    row = next(b for b in res.binding if b.limit == "min_life")
    relaxed = solve(p.with_limit("min_life", 10800 * H), sensitivities=False)
    assert row.objective_gain == pytest.approx(
        relaxed.best.objective - res.best.objective, rel=1e-6, abs=1e-9
    )
    assert row.binding and row.objective_gain > 0.0
