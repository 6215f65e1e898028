"""Verdicts a test engineer can trust: the numbers printed are the saved calibration's, implausible fits
are never accepted, the noise floor is the noise (not misfit), torque data keep their quantity.

Data come from :func:`axisopt.identify.synth.simulate` with hidden effects of known size; the noise level
put into the data is the reference for the noise floor."""

import json
import math
from pathlib import Path

import numpy as np
import pytest
import yaml
from test_recovery import BASELINE, frequency_doe, friction_doe, stiffness_doe

from axisopt.cli import main
from axisopt.design import load_design
from axisopt.identify import diagnose, plant_from_design
from axisopt.identify.synth import simulate
from axisopt.report.diagnosis import diagnosis_dict, diagnosis_text

DESIGN = Path(__file__).resolve().parents[2] / "problems" / "data" / "table_x.yaml"


@pytest.fixture(scope="module")
def plant():
    return plant_from_design(load_design(DESIGN))


def _csv(ds, path, torque_lead=None, efficiency=None):
    cols = dict(ds.columns)
    head, data = [], []
    units = {"position": ("mm", 1e3), "force": ("N", 1.0), "displacement": ("um", 1e6), "direction": ("", 1.0),
             "velocity": ("mm/s", 1e3), "normal_load": ("N", 1.0), "friction_force": ("N", 1.0),
             "frequency": ("Hz", 1.0)}
    if torque_lead is not None:  # the same friction measured as screw torque: T = F l / (2 pi eta)
        cols["drag_torque"] = cols.pop("friction_force") * torque_lead / (2 * math.pi * efficiency)
        units["drag_torque"] = ("N.m", 1.0)
    for k, v in cols.items():
        u, f = units[k]
        head.append(f"{k} [{u}]" if u else k)
        data.append(np.asarray(v) * f)
    rows = [",".join(head)] + [",".join(f"{x:.9g}" for x in r) for r in zip(*data)]
    path.write_text("\n".join(rows) + "\n", encoding="utf-8")
    return path


def test_verdict_numbers_are_the_saved_calibration(plant, tmp_path, capsys):
    """Two effects accepted in two rounds: the second round refits the first effect's value, and what the
    verdict and JSON print is what --save-calibration writes."""
    ds = simulate(plant, "friction", friction_doe(), baseline=BASELINE["friction"], noise=0.01, seed=7,
                  effects={"stribeck": {"stribeck_rise": 200.0, "stribeck_velocity": 2e-3},
                           "load_dependent_friction": {"friction_coefficient": 0.005}})
    data = _csv(ds, tmp_path / "fric.csv")
    js, cal = tmp_path / "d.json", tmp_path / "cal.yaml"
    assert main(["diagnose", str(data), "--design", str(DESIGN), "--json", str(js),
                 "--save-calibration", str(cal)]) == 0
    d = json.loads(js.read_text())
    saved = yaml.safe_load(cal.read_text())
    assert len(d["accepted"]) == 2
    saved_params = {n: v for e in saved["effects"] for n, v in e["parameters"].items()}
    for a in d["accepted"]:
        for p in a["parameters"]:
            text = saved_params[p["name"]]["value"]
            value = float(str(text).split()[0])
            assert value == pytest.approx(p["value"], rel=1e-5), p["name"]
    out = capsys.readouterr().out
    assert "values of the final joint fit" in out


def test_implausible_fit_is_not_accepted(plant):
    """A frequency drop that only an added mass of 3x the table could explain: added_mass is the only
    candidate, its fit leaves the plausible range (up to the table's own mass), so nothing is accepted and
    the diagnosis says what it would need."""
    m = plant.moving_mass
    ds = simulate(plant, "frequency", frequency_doe(), effects={"added_mass": {"added_mass": 3.0 * m}},
                  noise=0.005, seed=3)
    diag = diagnose([ds], plant, candidates=["added_mass"])
    assert diag.verdict == "none"
    d = diagnosis_dict(diag)
    assert d["rejected"] and d["rejected"][0]["effect"] == "added_mass"
    assert "outside" in d["rejected"][0]["would_need"][0]
    assert "not accepted" in diagnosis_text(diag)


def test_plausible_version_of_the_same_is_accepted(plant):
    """Control for the test above: the same effect at half the table's mass is accepted."""
    m = plant.moving_mass
    ds = simulate(plant, "frequency", frequency_doe(), effects={"added_mass": {"added_mass": 0.5 * m}},
                  noise=0.005, seed=3)
    diag = diagnose([ds], plant, candidates=["added_mass"])
    assert diag.verdict == "added_mass"
    assert diag.final.value("added_mass") == pytest.approx(0.5 * m, rel=0.1)


@pytest.mark.parametrize(("kind", "doe", "effect", "values"), [
    ("stiffness", stiffness_doe, "friction_hysteresis", {"hysteresis_friction": 300.0}),
    ("friction", friction_doe, "load_dependent_friction", {"friction_coefficient": 0.005}),
    ("stiffness", stiffness_doe, "backlash", {"backlash": 10e-6}),
])
def test_noise_floor_is_the_noise_not_the_misfit(plant, kind, doe, effect, values):
    """The floor is estimated from the baseline's residual, which still holds the hidden effect; it must
    come out within 35 % of the noise put in (it came out 2-3x too high when effects alternate between
    neighbouring rows)."""
    noise = 0.015
    ds = simulate(plant, kind, doe(), effects={effect: values}, baseline=BASELINE[kind], noise=noise, seed=11)
    diag = diagnose([ds], plant)
    o = diag.obs[0]
    true_sigma = noise * float(np.median(o.scale))
    assert diag.noise[0] == pytest.approx(true_sigma, rel=0.35), (diag.noise[0], true_sigma, o.noise_method)
    assert diag.verdict.startswith(effect)


def test_noise_floor_from_replicates(plant):
    """Every reading taken three times: the pooled replicate scatter is used and says so."""
    cols = frequency_doe()  # 20 positions x 3 readings
    ds = simulate(plant, "frequency", cols, noise=0.01, seed=5)
    diag = diagnose([ds], plant)
    assert "replicate" in diag.obs[0].noise_method
    true_sigma = 0.01 * float(np.median(diag.obs[0].scale))
    assert diag.noise[0] == pytest.approx(true_sigma, rel=0.3)


def test_torque_data_keep_their_quantity(plant, tmp_path, capsys):
    """Friction measured as screw torque: the output states the conversion and its efficiency, and gives
    the friction findings in N.m too."""
    ds = simulate(plant, "friction", friction_doe(), baseline=BASELINE["friction"], noise=0.01, seed=9,
                  effects={"direction_asymmetry": {"direction_difference": 60.0}})
    data = _csv(ds, tmp_path / "torque.csv", torque_lead=plant.lead, efficiency=plant.efficiency)
    assert main(["diagnose", str(data), "--design", str(DESIGN)]) == 0
    out = capsys.readouterr().out
    assert "drag torque T fitted as table force" in out and f"efficiency eta = {plant.efficiency:g}" in out
    assert "N.m at the screw" in out
    # the torque given equals the force found, converted back (60 N hidden)
    t_expected = 60.0 * plant.lead / (2 * math.pi * plant.efficiency)
    line = next(ln for ln in out.splitlines() if "direction_difference =" in ln and "N.m" in ln)
    t = float(line.split("(= ")[1].split(" N.m")[0])
    assert t == pytest.approx(t_expected, rel=0.1)


def test_frequency_data_say_there_is_no_baseline_parameter(plant):
    ds = simulate(plant, "frequency", frequency_doe(), noise=0.01, seed=2)
    text = diagnosis_text(diagnose([ds], plant))
    assert "baseline fit: no free parameter" in text
    assert "baseline fit: \n" not in text + "\n"


def test_frf_resonance_by_position(plant):
    """FRFs at four positions with a hidden extra mode: the table gives, per position, the measured and the
    fitted resonance (they agree after the fit), the axial mode's damping as hidden, and the extra mode.  The
    measured peak moves down the stroke (a longer screw in tension is softer)."""
    from test_recovery import frf_doe

    ds = simulate(plant, "frf", frf_doe(), baseline={"damping_ratio": 0.04}, noise=0.01, seed=1,
                  effects={"extra_mode": {"mode_frequency": 300.0, "mode_damping": 0.03, "mode_stiffness": 500e6}})
    diag = diagnose([ds], plant)
    modes = diagnosis_dict(diag)["frf_modes"]
    assert [round(m["position_mm"]) for m in modes] == [0, 267, 533, 800]
    peaks = [m["measured_peak_Hz"] for m in modes]
    assert all(a > b for a, b in zip(peaks, peaks[1:]))
    for m in modes:
        assert m["model_peak_Hz"] == pytest.approx(m["measured_peak_Hz"], rel=0.01)
        assert m["damping_ratio"] == pytest.approx(0.04, rel=0.1)
        assert m["extra_mode_Hz"] == pytest.approx(300.0, rel=0.05)
    assert "resonance by position" in diagnosis_text(diag)
