"""The shipped example studies run end to end through the command line (small ones in full)."""

from __future__ import annotations

from dataclasses import replace

import pandas as pd
import pytest
from study_helpers import STUDIES, study_code

from axisopt.cli import main
from axisopt.study import load_study, run_study


# teaching_random (24 cases, about 18 s on an idle core) is marked slow here: the default run still
# runs it through the HTML report test (tests/report/test_html.py) and docs/howto-dask.md
@pytest.mark.parametrize(
    "name",
    [
        "gantry_weights.yaml",
        "pareto_stroke.yaml",
        pytest.param("teaching_random.yaml", marks=pytest.mark.slow),
    ],
)
def test_example_study_cli(tmp_path, capsys, name):
    out = tmp_path / "out"
    rc = main(["study", str(STUDIES / name), "--out", str(out), "--workers", "0", "--quiet"])
    text = capsys.readouterr().out
    assert "report" in text
    df = pd.read_csv(out / "results.csv")
    # 1 when a case has no design (teaching_random has infeasible cases)
    assert rc == study_code(df)
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


def test_a_study_of_fronts_in_the_positioning_error(tmp_path):
    """A front whose keys include a goal without a JSON field of its own (the positioning error) is
    stored with each point's objective values and drawn (the study's plot read a hand map that
    lacked it)."""
    import json

    from study_helpers import PROBLEMS

    text = (PROBLEMS / "precision_problem.yaml").read_text()
    assert "\nobjective: stiffness\n" in text
    prob = tmp_path / "prec_front.yaml"
    prob.write_text(
        text.replace(
            "\nobjective: stiffness\n",
            "\nobjective:\n  mode: pareto\n  pareto: [stiffness, positioning_error]\n",
        )
    )
    spec = tmp_path / "study.yaml"
    spec.write_text(f"name: prec-front\nbase: {prob}\nsweep:\n  axis.stroke: [450 mm, 500 mm]\n")
    out = tmp_path / "out"
    rc = main(["study", str(spec), "--out", str(out), "--workers", "0", "--quiet"])
    assert rc == 0 and (out / "plots" / "pareto_fronts.png").exists()
    fronts = [
        json.loads(f.read_text())["pareto"]
        for f in sorted(out.rglob("*.json"))
        if "pareto" in json.loads(f.read_text())
    ]
    assert fronts
    for fr in fronts:
        assert fr["keys"] == ["stiffness", "positioning_error"]
        for p in fr["points"]:
            k, err = p["objectives"]
            assert k == p["min_stiffness"] and 0 < err <= 40.0  # um, within the problem's limit
