"""Lost motion (backlash) between motor and table in time records
(:mod:`axisopt.identify.records.lostmotion`): hidden in records simulated by identify/records/synth
(a motor-side mass tied to the table by a spring with a dead zone, closed loop on the table's scale;
written apart from the identification code), measured from a motor_position column beside the
table's position, never named on records without lost motion."""

from __future__ import annotations

import json

import numpy as np
import pytest
from identify_helpers import DESIGN

from axisopt.cli import main
from axisopt.identify.records.idim import diagnose_time_files
from axisopt.identify.records.synth import AxisTruth, LoopSettings, simulate_axis
from axisopt.report.timediag import time_diagnosis_text

COLS = ("time", "position", "force", "reference", "motor_position")


def truth_for(seed, backlash, mode_hz):
    rng = np.random.default_rng(seed)
    return AxisTruth(
        mass=rng.uniform(300, 900),
        viscous=rng.uniform(600, 2500),
        coulomb=rng.uniform(200, 600),
        offset=rng.choice([-1.0, 1.0]) * rng.uniform(20, 60),
        mode_hz=mode_hz,
        mode_zeta=0.1,
        mode_mass=150.0,
        backlash=backlash,
    )


def records(tmp_path, truth, seed, columns=COLS):
    # the loop closes on the table's scale, beyond the lost motion
    loop = LoopSettings(bandwidth_hz=3.0)
    est, val = tmp_path / f"est{seed}.csv", tmp_path / f"val{seed}.csv"
    simulate_axis(truth, loop, duration=12.0, seed=seed, record_motor=True).write_csv(
        est, columns=columns
    )
    simulate_axis(truth, loop, duration=8.0, seed=seed + 500, record_motor=True).write_csv(
        val, columns=columns
    )
    return [est, val]


def _write(tmp_path, header, rows):
    p = tmp_path / "bad.csv"
    p.write_text(header + "\n" + "\n".join(rows) + "\n", encoding="utf-8")
    return p


@pytest.mark.parametrize(
    "seed, backlash, mode_hz", [(1, 30e-6, 30.0), (2, 10e-6, 35.0), (4, 50e-6, 25.0)]
)
def test_hidden_backlash_is_named_with_its_width(tmp_path, plant, seed, backlash, mode_hz):
    truth = truth_for(seed, backlash, mode_hz)
    diag = diagnose_time_files(records(tmp_path, truth, seed), plant=plant)
    assert "backlash" in diag.verdict, time_diagnosis_text(diag)
    assert diag.lost.width == pytest.approx(backlash, rel=0.08)
    w = 2 * np.pi * mode_hz  # the simulated spring, from its resonance: the windup stiffness
    k_true = w**2 * 150.0 * (truth.mass - 150.0) / truth.mass
    assert diag.lost.stiffness == pytest.approx(k_true, rel=0.1)
    text = time_diagnosis_text(diag)
    assert "verdict: backlash" in text and f"b = {diag.lost.width * 1e6:.3g} ±" in text


@pytest.mark.parametrize("seed, mode_hz", [(3, 30.0), (6, 45.0), (7, 0.0)])
def test_no_lost_motion_names_no_backlash(tmp_path, plant, seed, mode_hz):
    """A compliant transmission without a gap (windup only), and a rigid axis whose motor and table
    read the
    same: no backlash."""
    diag = diagnose_time_files(records(tmp_path, truth_for(seed, 0.0, mode_hz), seed), plant=plant)
    assert "backlash" not in diag.verdict
    assert diag.lost is not None and not diag.lost.accepted
    assert "lost motion between motor and table not named" in time_diagnosis_text(diag)


def test_without_a_motor_encoder_backlash_is_not_guessed(tmp_path, plant):
    """The table's position and the force alone do not show the lost motion (the rows inside the gap
    are where the axis stands or turns): not named, and the output says which column would measure
    it."""
    truth = truth_for(1, 30e-6, 30.0)
    diag = diagnose_time_files(records(tmp_path, truth, 1, columns=COLS[:4]), plant=plant)
    assert "backlash" not in diag.verdict and diag.lost is None
    text = time_diagnosis_text(diag)
    assert "motor_position column" in " ".join(text.split())


def test_cli_json_carries_the_lost_motion(tmp_path, plant, capsys):
    paths = records(tmp_path, truth_for(5, 20e-6, 40.0), 5)
    assert main(["diagnose", *map(str, paths), "--design", str(DESIGN), "--json", "-"]) == 0
    out = json.loads(capsys.readouterr().out)
    lm = out["lost_motion"] if "lost_motion" in out else out["files"][0]["lost_motion"]
    assert lm["accepted"] and lm["width_um"] == pytest.approx(20.0, rel=0.08)
    assert "backlash" in (out.get("verdict") or out["files"][0]["verdict"])


@pytest.mark.parametrize(
    "header, cell, what",
    [
        ("time [s],position [mm],force [N],motor_position [N]", None, "motor_position"),
        ("time [s],position [mm],force [N],motor_position [mm]", "nan", "not a finite number"),
        (
            "time [s],position [mm],force [N],motor_position [mm]",
            "const",
            "motor_position column is constant",
        ),
    ],
)
def test_bad_motor_position_is_one_line_exit_2(tmp_path, capsys, header, cell, what):
    rows = []
    for i in range(400):
        x = 100.0 + 50.0 * np.sin(i / 40.0)
        mp = "5" if cell == "const" else ("nan" if cell == "nan" and i == 7 else f"{x + 0.01:.6f}")
        rows.append(f"{i / 1000:.4f},{x:.6f},{100 * np.cos(i / 40.0):.4f},{mp}")
    p = _write(tmp_path, header, rows)
    assert main(["diagnose", str(p), "--design", str(DESIGN)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and what in err and "bad.csv" in err
