"""A study over drive types (search.drive_types swept, or a base problem that lists them): each case
solved over its types (study.record), its best design's drive type and parts in the table, its
objective the one solve_drive_types gives the case's problem, the rack-and-pinion and linear-motor
margins as columns, the report without NaN; a study of screw problems keeps its columns."""

from __future__ import annotations

from pathlib import Path

import pandas as pd
import pytest

from axisopt.cli import main
from axisopt.problem import load_problem
from axisopt.search.drivetype import solve_drive_types

ROOT = Path(__file__).resolve().parents[2]
LASER = ROOT / "problems" / "laser_lm_problem.yaml"


@pytest.mark.slow  # over 10 s on an idle core: run by `pytest -m slow`
def test_study_over_drive_types(tmp_path):
    study = tmp_path / "s.yaml"
    study.write_text(
        f"name: laser-types\nbase: {LASER}\nsweep:\n"
        "  axis.max_speed: [60 m/min, 80 m/min]\n"
        "  search.drive_types: [[linear_motor], [screw, linear_motor]]\n",
        encoding="utf-8",
    )
    out = tmp_path / "out"
    assert main(["study", str(study), "--out", str(out), "--workers", "0", "--quiet"]) in (0, 1)
    df = pd.read_csv(out / "results.csv")
    assert len(df) == 4
    for _, r in df.iterrows():
        text = LASER.read_text(encoding="utf-8").replace(
            "max_speed: 80 m/min", f"max_speed: {r['axis.max_speed [m/min]']:g} m/min"
        )
        text = text.replace(
            "drive_types: [linear_motor, rack_pinion]",
            f"drive_types: [{r['search.drive_types'].replace('+', ', ')}]",
        )
        p = tmp_path / f"case{r['index']}.yaml"
        p.write_text(text, encoding="utf-8")
        best = solve_drive_types(load_problem(p), top=1).best
        assert r["status"] == "optimal" and best is not None
        assert r["drive_type"] == best.drive_type
        assert r["objective"] == pytest.approx(best.objective, rel=1e-9)
        assert r["cost [EUR]"] == pytest.approx(best.cost, rel=1e-9)
        if best.drive_type == "linear_motor":
            assert r["linear_motor"] == best.parts["linear_motor"]
            assert int(r["forcers"]) == int(best.parts["forcers"])
            for k, v in best.margins.items():
                assert r[f"drive {k} margin"] == pytest.approx(v, rel=1e-9)
    report = (out / "report.md").read_text(encoding="utf-8")
    assert "nan" not in report and "| drive |" in report
