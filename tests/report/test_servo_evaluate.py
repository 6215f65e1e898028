"""``evaluate`` reports the servo (text and JSON), ``--ss`` writes the state-space .npz, ``--frf``
carries the motor-held, motor-free and closed-loop curves; ``solve`` on the shipped VMC and
high-speed problems shows Kv."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from axisopt.cli import main

PROBLEMS = Path(__file__).resolve().parents[2] / "problems"


def test_evaluate_servo_ss_and_frf(tmp_path, capsys, monkeypatch):
    js, ss, png = tmp_path / "e.json", tmp_path / "m.npz", tmp_path / "f.png"
    # the output names the files: short relative names keep it within 100 columns
    monkeypatch.chdir(tmp_path)
    rc = main(
        [
            "evaluate",
            str(PROBLEMS / "vmc_x_design.yaml"),
            "--json",
            js.name,
            "--ss",
            ss.name,
            "--frf",
            png.name,
        ]
    )
    assert rc == 0
    text = capsys.readouterr().out
    assert "position-loop gain Kv  83.1 1/s = 4.99 m/min/mm" in text
    assert "following error v/Kv   4.812 mm at 24 m/min rapid" in text
    assert all(len(line) <= 100 for line in text.splitlines())
    out = json.loads(js.read_text())
    s = out["servo"]
    # f1 = f_axial here
    assert s["kv_per_s"] == pytest.approx(out["min_natural_frequency_Hz"], rel=1e-9)
    assert s["following_error_rapid_mm"] == pytest.approx(0.4 / s["kv_per_s"] * 1e3)
    assert all(p["stable"] for p in s["closed_loop"])
    assert min(s["kv_profile_per_s"]) == pytest.approx(s["kv_per_s"])
    frf = out["frf"]
    held = frf["motor_held_positions"]
    assert held[-1]["modes_Hz"][0] == pytest.approx(out["min_natural_frequency_Hz"], rel=1e-3)
    assert frf["positions"][-1]["modes_Hz"][0] == pytest.approx(123.5, abs=0.1)  # motor free
    assert len(frf["closed_loop"]["positions"][1]["magnitude_um_per_N"]) == len(frf["frequency_Hz"])
    # closed here: an open NpzFile collected in a later test is a ResourceWarning there
    with np.load(ss) as npz:
        z = {k: npz[k] for k in npz.files}
    assert z["A"].shape == (3, 6, 6) and z["B"].shape == (3, 6, 2) and z["C"].shape == (3, 3, 6)
    assert list(z["inputs"]) == ["motor_torque", "process_force"]
    assert float(z["kv_per_s"]) == pytest.approx(s["kv_per_s"])
    lam = np.linalg.eigvals(z["A"][2])
    f = np.sort(np.abs(lam[lam.imag > 1.0])) / (2 * np.pi)  # the damped rigid-body pole is real
    assert f[0] == pytest.approx(123.5, rel=2e-3)
    assert png.stat().st_size > 1000


def test_ss_to_unwritable_path_is_an_input_error(tmp_path, capsys):
    (tmp_path / "d.npz").mkdir()
    rc = main(["evaluate", str(PROBLEMS / "vmc_x_design.yaml"), "--ss", str(tmp_path / "d.npz")])
    assert rc == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "d.npz" in err[0]


@pytest.mark.parametrize("name", ["vmc_x_problem.yaml", "highspeed_problem.yaml"])
def test_shipped_problems_report_kv_and_following_error(name, capsys):
    assert main(["solve", str(PROBLEMS / name)]) == 0
    text = capsys.readouterr().out
    assert (
        "position-loop gain Kv" in text and "following error v/Kv" in text and "stable at" in text
    )
