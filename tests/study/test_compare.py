"""``axisopt compare`` on the shipped designs and a problem (solved to its best design)."""

from __future__ import annotations

import json
import re

import pandas as pd
import pytest
from study_helpers import PROBLEMS

from axisopt.cli import main


def test_compare_designs_and_a_problem(tmp_path, capsys):
    files = [
        PROBLEMS / "vmc_x_design.yaml",
        PROBLEMS / "teaching_design.yaml",
        PROBLEMS / "teaching_problem.yaml",
    ]
    js, csv, png = tmp_path / "c.json", tmp_path / "c.csv", tmp_path / "c.png"
    rc = main(
        ["compare", *map(str, files), "--json", str(js), "--csv", str(csv), "--plot", str(png)]
    )
    assert rc == 0
    out = capsys.readouterr().out
    assert "teaching (solved)" in out and "weakest link" in out and "all checks pass" in out
    # each design's weakest component carries the marker exactly once
    comp_rows = [
        ln for ln in out.splitlines() if ln.startswith(("  screw (where", "  nut ", "  bearings "))
    ]
    assert sum(ln.count(" <") for ln in comp_rows) == 3
    d = json.loads(js.read_text())
    assert [x["kind"] for x in d["designs"]] == ["design", "design", "problem"]
    ev = d["designs"][0]["evaluation"]
    assert ev["weakest_link"] == "screw" and ev["min_axial_stiffness_N_per_um"] > 0
    assert d["designs"][2]["solve"]["status"] == "optimal"
    # no float noise (999.9999999999999) in the CSV: at most ten significant digits per number
    numbers = re.findall(r"-?\d+\.\d+(?:e[-+]?\d+)?", csv.read_text(encoding="utf-8"))
    assert numbers and max(len(re.sub(r"e.*|\D", "", n).lstrip("0")) for n in numbers) <= 10
    df = pd.read_csv(csv)
    assert len(df) == 3 and {
        "min_stiffness [N/um]",
        "min_frequency_at [mm]",
        "cost [EUR]",
        "critical_speed margin",
        "critical_speed available [rpm]",
        "critical_speed needed [rpm]",
        "weakest_link",
    } <= set(df.columns)
    # physical values: the VMC screw turns at 24 m/min / 20 mm lead = 1200 rpm (design file), margin
    # = ratio
    r = df.iloc[0]
    assert r["critical_speed needed [rpm]"] == pytest.approx(1200)
    assert r["critical_speed margin"] == pytest.approx(
        r["critical_speed available [rpm]"] / 1200, rel=1e-9
    )
    assert r["nut_life needed [h]"] == pytest.approx(20_000)
    assert "  critical speed [rpm]" in out and "(4,328/1,200)" in out
    assert png.stat().st_size > 10_000


def test_compare_shows_the_drive_side_by_side(tmp_path, capsys):
    """A design with a motor next to one without: motor and coupling rows, the torques needed
    against the motor's catalog values, and the drive figures in the CSV, the same numbers
    ``evaluate`` computes."""
    from axisopt.design import load_design
    from axisopt.model import evaluate

    files = [PROBLEMS / "vmc_x_design.yaml", PROBLEMS / "teaching_design.yaml"]
    csv = tmp_path / "c.csv"
    assert main(["compare", *map(str, files), "--csv", str(csv)]) == 0
    out = capsys.readouterr().out
    ev = evaluate(load_design(PROBLEMS / "vmc_x_design.yaml"))
    motor = ev.design.motor
    rows = {
        ln[:52].strip(): ln[52:].split()
        for ln in out.splitlines()
        if ln.startswith(("motor", "coupling", "  "))
    }
    assert rows["motor"] == [str(motor["id"]), "-"]
    # what the check compares: the peak scaled to the zone
    peak = rows["peak torque (zone-scaled) [N.m]"]
    assert float(peak[0]) == round(float(ev["needed_motor_peak_torque"]), 2)
    assert float(peak[2]) == float(f"{motor['peak_torque']:.3g}")
    assert peak[3:] == ["no", "motor"]
    df = pd.read_csv(csv)
    assert df.loc[0, "motor"] == motor["id"] and pd.isna(df.loc[1, "motor"])
    assert abs(df.loc[0, "drive_rms_torque_Nm"] - ev["rms_torque"]) < 1e-9


def test_a_long_comparison_reports_each_file_done(monkeypatch, caplog):
    import logging

    from axisopt.study import compare

    monkeypatch.setattr(compare, "PROGRESS", 0.0)
    files = [str(PROBLEMS / "vmc_x_design.yaml"), str(PROBLEMS / "teaching_design.yaml")]
    with caplog.at_level(logging.INFO, logger="axisopt"):
        compare.load_compared(files)
    lines = [r.getMessage() for r in caplog.records if "compare:" in r.getMessage()]
    assert (
        lines == [lines[0]]
        and "1 of 2 files done" in lines[0]
        and "teaching_design.yaml" in lines[0]
    )
