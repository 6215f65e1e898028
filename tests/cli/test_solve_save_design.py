"""``axisopt solve --save-design``: the designs written read back through ``evaluate`` and
``compare`` to the numbers the search reported for them."""

import json
from dataclasses import replace
from pathlib import Path

import pytest
import yaml

from axisopt.cli import main
from axisopt.design import load_design
from axisopt.model import evaluate
from axisopt.report.partslist import preload_step

PROBLEMS = Path(__file__).resolve().parents[2] / "problems"


def test_saved_designs_evaluate_to_the_solved_numbers(tmp_path, capsys):
    out_dir, js = tmp_path / "designs", tmp_path / "solve.json"
    rc = main(
        [
            "solve",
            str(PROBLEMS / "teaching_problem.yaml"),
            "--top",
            "3",
            "--no-sensitivity",
            "--json",
            str(js),
            "--save-design",
            str(out_dir),
        ]
    )
    assert rc == 0
    solved = json.loads(js.read_text())
    cands = [solved["best"]] + solved["runners_up"]
    files = sorted(out_dir.glob("*.yaml"))
    assert [f.name for f in files] == ["1.yaml", "2.yaml", "3.yaml"] and len(cands) == 3
    for f, cand in zip(files, cands):
        doc = yaml.safe_load(f.read_text(encoding="utf-8"))
        assert doc["parts"]["screw"] == cand["screw"] and doc["parts"]["nut"] == cand["nut"]
        ev_json = tmp_path / f"{f.stem}.json"
        assert main(["evaluate", str(f), "--json", str(ev_json)]) == 0
        ev = json.loads(ev_json.read_text())
        # the preload is written in round figures (order_preload: within one step, every limit kept,
        # tests/cli/test_solve_saved_preload.py); the rest is the solved design's
        assert abs(ev["nut_preload_N"] - cand["nut_preload"]) < preload_step(cand["nut_preload"])
        ordered = evaluate(replace(load_design(f), nut_preload=cand["nut_preload"]))
        assert ordered.minimum("k_total")[0] / 1e6 == pytest.approx(cand["min_stiffness"], rel=1e-9)
        assert ordered.minimum("f1")[0] == pytest.approx(cand["min_frequency"], rel=1e-9)
        assert ev["cost"] == pytest.approx(cand["cost"], rel=1e-9)
    capsys.readouterr()
    assert main(["compare", *map(str, files)]) == 0
    assert "teaching-1" in capsys.readouterr().out


def test_single_file_gets_the_best(tmp_path, capsys):
    best = tmp_path / "best.yaml"
    assert (
        main(
            [
                "solve",
                str(PROBLEMS / "teaching_problem.yaml"),
                "--no-sensitivity",
                "--json",
                "-",
                "--save-design",
                str(best),
            ]
        )
        == 0
    )
    solved = json.loads(capsys.readouterr().out)
    assert best.read_text(encoding="utf-8").startswith("# written by axisopt solve")
    assert yaml.safe_load(best.read_text(encoding="utf-8"))["parts"]["nut"] == solved["best"]["nut"]


def test_nothing_to_save_and_bad_targets(tmp_path, capsys):
    # an infeasible problem keeps its exit code 1 and says why nothing was saved
    assert (
        main(
            [
                "solve",
                str(PROBLEMS / "infeasible_problem.yaml"),
                "--no-sensitivity",
                "--save-design",
                str(tmp_path / "x.yaml"),
            ]
        )
        == 1
    )
    assert "no design saved" in capsys.readouterr().err
    assert not (tmp_path / "x.yaml").exists()
    # a Pareto front into one file: refused before solving, one line, exit 2
    assert (
        main(
            [
                "solve",
                str(PROBLEMS / "pareto_problem.yaml"),
                "--save-design",
                str(tmp_path / "p.yaml"),
            ]
        )
        == 2
    )
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "--save-design" in err
    # a file in the way of the directory
    (tmp_path / "f").write_text("x")
    assert (
        main(
            [
                "solve",
                str(PROBLEMS / "teaching_problem.yaml"),
                "--no-sensitivity",
                "--save-design",
                str(tmp_path / "f"),
            ]
        )
        == 2
    )
    assert len(capsys.readouterr().err.strip().splitlines()) == 1
