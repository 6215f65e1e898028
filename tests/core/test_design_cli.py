"""Design YAML and the evaluate command: every bad input is one line naming file and key, exit code 2."""

import json
from pathlib import Path

import pytest

from axisopt.cli import main

ROOT = Path(__file__).resolve().parents[2]
GOOD = (ROOT / "problems" / "vmc_x_design.yaml").read_text()
DESIGNS = sorted((ROOT / "problems").glob("*design*.yaml")) + sorted((ROOT / "problems").glob("paper_*.yaml"))


@pytest.mark.parametrize("path", DESIGNS, ids=lambda p: p.name)
def test_evaluate_runs_on_every_shipped_design(path, capsys):
    assert main(["evaluate", str(path)]) == 0
    out = capsys.readouterr().out
    assert "weakest link" in out and "checks" in out


def test_evaluate_json_and_plot(tmp_path, capsys):
    js, png = tmp_path / "r.json", tmp_path / "r.png"
    assert main(["evaluate", str(ROOT / "problems" / "vmc_x_design.yaml"), "--json", str(js), "--plot", str(png)]) == 0
    data = json.loads(js.read_text())
    for key in ("min_axial_stiffness_N_per_um", "min_natural_frequency_Hz", "moving_mass_kg", "total_mass_kg",
                "cost", "drag_torque_Nm", "positions_mm", "axial_stiffness_N_per_um", "natural_frequency_Hz"):
        assert key in data
    assert len(data["positions_mm"]) == len(data["axial_stiffness_N_per_um"]) >= 3
    assert min(data["axial_stiffness_N_per_um"]) == pytest.approx(data["min_axial_stiffness_N_per_um"])
    assert png.stat().st_size > 1000


def test_evaluate_json_to_stdout_is_pure_json(capsys):
    assert main(["evaluate", str(ROOT / "problems" / "teaching_design.yaml"), "--json", "-"]) == 0
    json.loads(capsys.readouterr().out)


BAD = [
    ("stroke: 800 mm", "stroke: 800", "axis.stroke", "no unit"),
    ("stroke: 800 mm", "strok: 800 mm", "axis.strok", "unknown key"),
    ("  moving_mass: 450 kg", "  moving_mass: 450 kg\n  movingmass: 3 kg", "axis.movingmass", "unknown key"),
    ("nut: HIWIN-R40-10K5-FDC", "nut: HIWIN-R40-10K5-FDX", "parts.nut", "unknown nut id"),
    ("stroke: 800 mm", "stroke: -800 mm", "axis.stroke", "must be positive"),
    ("mounting: fixed-supported", "mounting: fixed-floating", "axis.mounting", "not one of"),
    ("stroke: 800 mm", "stroke: 800 kg", "axis.stroke", "not a unit of length"),
    ("nut_preload: 3000 N", "nut_preload: 90000 N", "parts.nut_preload", "outside"),
    ("nut: HIWIN-R40-10K5-FDC", "nut: HIWIN-R25-05K4-FDC", "parts.nut", "fits screw"),
    ("axis:\n", "axis: [1, 2\n", "line", "malformed YAML"),
    ("  stroke: 800 mm\n", "", "axis", "missing required key 'axis.stroke'"),
    ("guide_blocks: 4", "guide_blocks: four", "axis.guide_blocks", "number"),
]


@pytest.mark.parametrize("old, new, key, words", BAD, ids=[b[3] + "-" + b[2] for b in BAD])
def test_bad_design_is_one_line_error_exit_2(tmp_path, capsys, old, new, key, words):
    assert old in GOOD
    bad = tmp_path / "bad.yaml"
    bad.write_text(GOOD.replace(old, new, 1))
    assert main(["evaluate", str(bad)]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and "Traceback" not in err
    assert str(bad) in err and key in err and words in err, err


def test_missing_file_and_usage_errors(tmp_path, capsys):
    assert main(["evaluate", str(tmp_path / "nope.yaml")]) == 2
    assert "nope.yaml" in capsys.readouterr().err
    assert main(["evaluate"]) == 2
    assert main(["frobnicate"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 2


def test_empty_and_non_mapping_yaml(tmp_path, capsys):
    for text in ("", "- a\n- b\n", "just text\n"):
        p = tmp_path / "x.yaml"
        p.write_text(text)
        assert main(["evaluate", str(p)]) == 2
        assert str(p) in capsys.readouterr().err
