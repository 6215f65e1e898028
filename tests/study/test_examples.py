"""The shipped example studies run end to end through the command line (small ones in full)."""

from __future__ import annotations

from dataclasses import replace

import pandas as pd
import pytest
from study_helpers import STUDIES, study_code

from axisopt.cli import main
from axisopt.study import load_study, run_study


@pytest.mark.parametrize("name", ["gantry_weights.yaml", "pareto_stroke.yaml", "teaching_random.yaml"])
def test_example_study_cli(tmp_path, capsys, name):
    out = tmp_path / "out"
    rc = main(["study", str(STUDIES / name), "--out", str(out), "--workers", "0", "--quiet"])
    text = capsys.readouterr().out
    assert "report" in text
    df = pd.read_csv(out / "results.csv")
    assert rc == study_code(df)  # 1 when a case has no design (teaching_random has infeasible cases)
    assert len(df) == len(load_study(STUDIES / name).cases)
    assert (df["status"] == "optimal").sum() >= len(df) // 2
    assert (out / "report.md").exists() and list((out / "plots").glob("*.png"))
    if name == "pareto_stroke.yaml":
        assert (out / "plots" / "pareto_fronts.png").exists() and (df["pareto_points"] > 1).all()


@pytest.mark.parametrize("name", ["vmc_stroke_mounting.yaml", "vmc_random_1000.yaml"])
def test_large_examples_first_cases(tmp_path, name):
    st = load_study(STUDIES / name)
    st = replace(st, cases=st.cases[:3])
    s = run_study(st, tmp_path / "o", workers=0)
    assert s.solved == 3 and s.lost == 0
