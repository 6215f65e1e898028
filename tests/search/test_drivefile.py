"""A rack-and-pinion or linear-motor design saved by `axisopt solve --save-design` evaluates, by
`axisopt evaluate`, to the numbers its solve gave (search.drivefile): the same parts, objective,
cost, moving mass and check margins; a file naming a part its problem does not offer, leaving a slot
out or naming a type the search does not list is a one-line error, exit 2."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from axisopt.cli import main
from axisopt.problem import load_problem
from axisopt.search.drivefile import drive_design_yaml, evaluate_drive_design
from axisopt.search.drivetype import solve_drive_types
from tests.cli.cli_helpers import one_line_error

ROOT = Path(__file__).resolve().parents[2]
LASER = ROOT / "problems" / "laser_lm_problem.yaml"
ROUTER = ROOT / "problems" / "router_rack_problem.yaml"


@pytest.mark.parametrize("path", [LASER, ROUTER], ids=["linear_motor", "rack_pinion"])
def test_saved_design_evaluates_to_the_solve_numbers(tmp_path, path):
    problem = load_problem(path)
    res = solve_drive_types(problem, top=3)
    assert res.best is not None
    for rank, d in enumerate([res.best] + list(res.runners_up), start=1):
        if d.drive_type == "screw":
            continue
        saved = tmp_path / f"{rank}.yaml"
        saved.write_text(drive_design_yaml(path, d, rank), encoding="utf-8")
        again = evaluate_drive_design(load_problem(saved))
        assert again.drive_type == d.drive_type and again.parts == d.parts
        for key in ("objective", "cost", "moving_mass", "stiffness", "frequency"):
            assert getattr(again, key) == pytest.approx(getattr(d, key), rel=1e-12), key
        # the solve's design carries the checks' margins; the evaluation adds the problem's limits
        for k, v in d.margins.items():
            assert again.margins[k] == pytest.approx(v, rel=1e-12), k
        assert set(again.margins) - set(d.margins) == {k for k, _ in problem.limits} & set(
            again.margins
        )


def test_cli_round_trip_save_design_evaluate_json(tmp_path, capsys):
    out = tmp_path / "designs"
    assert (
        main(
            [
                "solve",
                str(LASER),
                "--save-design",
                str(out),
                "--top",
                "2",
                "--json",
                str(tmp_path / "s.json"),
            ]
        )
        == 0
    )
    solved = json.loads((tmp_path / "s.json").read_text())
    files = sorted(out.glob("*.yaml"))
    assert [f.name for f in files] == ["1.yaml", "2.yaml"]
    capsys.readouterr()
    assert main(["evaluate", str(files[0]), "--json", str(tmp_path / "e.json")]) == 0
    ev = json.loads((tmp_path / "e.json").read_text())
    best = solved["best"]
    assert ev["parts"] == best["parts"] and ev["drive_type"] == best["drive_type"]
    assert ev["objective"] == pytest.approx(best["objective"], rel=1e-12)
    assert ev["cost"] == pytest.approx(best["cost"], rel=1e-12)
    text = capsys.readouterr().out
    assert "checks and limits" in text and "FAIL" not in text


def _saved(tmp_path, edit) -> str:
    problem = load_problem(LASER)
    res = solve_drive_types(problem, top=1)
    text = edit(drive_design_yaml(LASER, res.best))
    p = tmp_path / "bad.yaml"
    p.write_text(text, encoding="utf-8")
    return str(p)


@pytest.mark.parametrize(
    "edit, where",
    [
        (lambda t: t.replace("  guide: ", "  guide: NO-SUCH-GUIDE-"), "drive_design.guide"),
        (lambda t: t.replace("  forcers: ", "  forcers: 9 #"), "drive_design.forcers"),
        (lambda t: t.replace("  linear_motor: ", "  nonsense: "), "drive_design"),
        (lambda t: t.replace("type: linear_motor", "type: rack_pinion"), "drive_design"),
        (lambda t: t.replace("  - linear_motor\n", "  - screw\n"), "drive_design.type"),
    ],
    ids=["unknown guide", "forcers 9", "unknown key", "slots of another type", "type not searched"],
)
def test_bad_drive_design_one_line_exit_2(tmp_path, capsys, edit, where):
    path = _saved(tmp_path, edit)
    capsys.readouterr()
    assert main(["evaluate", path]) == 2
    assert where in one_line_error(capsys)


def test_screw_options_refused_on_a_drive_design(tmp_path, capsys):
    path = _saved(tmp_path, lambda t: t)
    capsys.readouterr()
    assert main(["evaluate", path, "--frf", str(tmp_path / "f.png")]) == 2
    assert "--frf" in one_line_error(capsys)
