"""`axisopt compare` takes rack-and-pinion and linear-motor designs beside screw designs
(study.compare, report.compare): a saved drive design and a problem over drive types are each
evaluated or solved to their design, shown side by side on what every type has, in the text, the
JSON, the CSV and the HTML page."""

from __future__ import annotations

import csv
import json
from pathlib import Path

import pytest

from axisopt.cli import main
from axisopt.problem import load_problem
from axisopt.report.drivetype import LABELS
from axisopt.search.drivefile import drive_design_yaml, evaluate_drive_design
from axisopt.search.drivetype import solve_drive_types

ROOT = Path(__file__).resolve().parents[2]
ROUTER = ROOT / "problems" / "router_rack_problem.yaml"
LASER = ROOT / "problems" / "laser_lm_problem.yaml"
TEACHING = ROOT / "problems" / "teaching_design.yaml"


@pytest.fixture(scope="module")
def rack_file(tmp_path_factory):
    best = solve_drive_types(load_problem(ROUTER), top=1).best
    assert best.drive_type == "rack_pinion"
    p = tmp_path_factory.mktemp("rack") / "rack.yaml"
    p.write_text(drive_design_yaml(ROUTER, best), encoding="utf-8")
    return p


def test_side_by_side_text_json_csv_html(tmp_path, capsys, rack_file):
    args = [str(rack_file), str(TEACHING), str(LASER)]
    out = [
        "--json",
        str(tmp_path / "c.json"),
        "--csv",
        str(tmp_path / "c.csv"),
        "--report",
        str(tmp_path / "c.html"),
    ]
    capsys.readouterr()
    assert main(["compare", *args, *out]) == 0
    rack = evaluate_drive_design(load_problem(rack_file))
    laser = solve_drive_types(load_problem(LASER), top=1).best
    js = json.loads((tmp_path / "c.json").read_text())["designs"]
    assert [d.get("drive_design", {}).get("drive_type") for d in js] == [
        "rack_pinion",
        None,
        "linear_motor",
    ]
    assert js[0]["drive_design"]["stiffness"] == pytest.approx(rack.stiffness, rel=1e-12)
    assert js[2]["drive_design"]["objective"] == pytest.approx(laser.objective, rel=1e-12)
    assert "evaluation" in js[1]
    with open(tmp_path / "c.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert [r.get("drive_type") or "" for r in rows] == ["rack_pinion", "", "linear_motor"]
    assert (
        rows[0]["rack"] == rack.parts["rack"]
        and rows[2]["linear_motor"] == laser.parts["linear_motor"]
    )
    html = (tmp_path / "c.html").read_text()
    assert f"{rack.stiffness:,.1f}" in html and f"{laser.stiffness:,.1f}" in html
    # each design's card names its drive type before its stiffness and frequency
    card = f"{LABELS['rack_pinion']}: {rack.stiffness:,.1f} N/um, {rack.frequency:,.1f} Hz"
    assert card in html
    text = (tmp_path / "c.json").read_text() and capsys.readouterr().out
    assert "rack and pinion" in text and "linear motor" in text and "screw" in text
    assert f"{rack.cost:,.0f} EUR" in text and "nut_life)  FAIL" in text
