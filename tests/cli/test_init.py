"""``axisopt init design|problem|study --machine M`` (issue 30): each template loads and solves or
evaluates as written, says where the process force goes, and never overwrites a file unless
asked."""

from __future__ import annotations

import json

import pytest

from axisopt.cli import main
from axisopt.cli.init import MACHINES, template
from axisopt.study.spec import load_study


@pytest.mark.parametrize("machine", MACHINES)
def test_problem_template_solves_with_a_clean_answer(machine, tmp_path, capsys):
    path = tmp_path / "p.yaml"
    assert main(["init", "problem", "--machine", machine, "--out", str(path)]) == 0
    assert f"written to {path}" in capsys.readouterr().out
    code = main(["solve", str(path), "--no-sensitivity", "--top", "1", "--json", "-"])
    out = json.loads(capsys.readouterr().out)
    assert code in (0, 1)
    assert out["status"] == {0: "optimal", 1: "infeasible"}[code]
    assert out["status"] == "optimal"  # the templates were tuned to be feasible
    best = out["best"]
    # a drive-type answer (the laser template wins with a linear motor, offered by default) names
    # the feed stiffness "stiffness" (the position loop's for a linear motor); a screw answer
    # "min_stiffness"
    assert best["min_stiffness" if "drive_type" not in best else "stiffness"] > 10  # N/um


@pytest.mark.parametrize("machine", MACHINES)
def test_design_template_evaluates_with_every_check_passing(machine, tmp_path, capsys):
    path = tmp_path / "d.yaml"
    assert main(["init", "design", "--machine", machine, "--out", str(path)]) == 0
    capsys.readouterr()
    assert main(["evaluate", str(path), "--fail-on-check"]) == 0
    text = capsys.readouterr().out
    assert text.startswith(f"design {machine}-") and "FAIL" not in text


@pytest.mark.parametrize("machine", MACHINES)
def test_study_template_loads_into_cases(machine, tmp_path):
    path = tmp_path / "s.yaml"
    path.write_text(template("study", machine), encoding="utf-8")
    study = load_study(path)
    assert (
        len(study.cases) == 3
        and study.name == f"{template('problem', machine).split('name: ')[1].split()[0]}-study"
    )


# the laser's three cases (the drive types each): over 10 s on an idle core, run by `pytest -m slow`
@pytest.mark.parametrize(
    "machine", [pytest.param(m, marks=pytest.mark.slow) if m == "laser" else m for m in MACHINES]
)
def test_study_template_runs_every_case_to_a_design(machine, tmp_path, capsys):
    path = tmp_path / "s.yaml"
    assert main(["init", "study", "--machine", machine, "--out", str(path)]) == 0
    assert (
        main(["study", str(path), "--out", str(tmp_path / "out"), "--workers", "0", "--quiet"]) == 0
    )
    assert "3 cases; 3 solved now" in capsys.readouterr().out


def test_templates_say_where_the_process_force_goes():
    for machine in MACHINES:
        for kind in ("design", "problem", "study"):
            text = template(kind, machine)
            assert "axial_load:" in text and "LARGEST external axial force" in text
            assert "duty_cycle force: the force during that move or dwell only" in text
            assert "force: 2500 N}" in text  # the example entry, with its unit
            assert all(len(line) <= 100 for line in text.splitlines())


def test_refuses_to_overwrite_unless_forced_and_writes_stdout(tmp_path, capsys):
    path = tmp_path / "p.yaml"
    path.write_text("mine\n", encoding="utf-8")
    assert main(["init", "problem", "--out", str(path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "file exists; use --force" in err and str(path) in err
    assert path.read_text(encoding="utf-8") == "mine\n"
    assert main(["init", "problem", "--out", str(path), "--force"]) == 0
    assert path.read_text(encoding="utf-8") == template("problem", "vmc")
    capsys.readouterr()
    assert main(["init", "design", "--machine", "lathe", "--out", "-"]) == 0
    assert capsys.readouterr().out == template("design", "lathe")
