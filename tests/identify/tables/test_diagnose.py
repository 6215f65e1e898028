"""Diagnosis of reduced tables (:mod:`axisopt.identify.tables.diagnose`): the CLI end to end, test
types sharing parameters, null cases, implausible fits never accepted, quantities kept, friction
tables (quadratic drag, effects that only help together, per-file gains, unidentifiable parameters).

The friction tables are written here from a friction law of a few lines (sgn(v) levels, a Gaussian
Stribeck rise, viscous, v|v| drag, a constant), apart from the library's measurement model; other
data come from :func:`axisopt.identify.tables.synth.simulate` with hidden effects of known size."""

from __future__ import annotations

import json
import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
import yaml
from identify_helpers import DESIGN, coulomb, dataset_csv, friction_table
from test_diagnose_recovery import BASELINE, frequency_doe, friction_doe

from axisopt.cli import main
from axisopt.design import load_design
from axisopt.identify import diagnose, plant_from_design, read_dataset
from axisopt.identify.calibration import apply_calibration
from axisopt.identify.tables.data import Dataset
from axisopt.identify.tables.synth import simulate
from axisopt.model import evaluate
from axisopt.report.diagnosis import diagnosis_dict, diagnosis_text

DATA = Path(__file__).resolve().parents[3] / "problems" / "data"


STIFF = DATA / "table_x_stiffness.csv"


ROOT = Path(__file__).resolve().parents[3]


def test_cli_shipped_example_end_to_end(tmp_path, capsys):
    cal = tmp_path / "cal.yaml"
    rep = tmp_path / "rep"
    js = tmp_path / "d.json"
    assert (
        main(
            [
                "diagnose",
                str(STIFF),
                "--design",
                str(DESIGN),
                "--report",
                str(rep),
                "--json",
                str(js),
                "--save-calibration",
                str(cal),
            ]
        )
        == 0
    )
    out = capsys.readouterr().out
    assert "verdict: support_condition" in out and "excluded line 42" in out
    d = json.loads(js.read_text())
    assert d["verdict"] == "support_condition"
    a = d["accepted"][0]
    assert a["parameters"][0]["value"] == pytest.approx(90.0, rel=0.1)  # N/um, as generated
    assert a["gain_percent"] > 30 and a["runner_up"]["effect"] == "compliance_offset"
    assert (rep / "report.md").read_text().count("![residuals") == 1 and (
        rep / "residuals_1.png"
    ).exists()
    saved = yaml.safe_load(cal.read_text())
    assert saved["effects"][0]["name"] == "support_condition"
    design = load_design(DESIGN)
    calibrated = apply_calibration(design, cal)
    assert calibrated.axis.mounting == "fixed-fixed"
    assert evaluate(calibrated).minimum("k_total")[0] > evaluate(design).minimum("k_total")[0]
    assert main(["evaluate", str(DESIGN), "--calibration", str(cal)]) == 0


def test_two_test_types_share_parameters():
    plant = plant_from_design(load_design(DESIGN))
    pos = np.repeat(np.linspace(0, 0.8, 8), 8)
    f = np.tile(np.r_[np.linspace(500, 4000, 4), -np.linspace(500, 4000, 4)], 8)
    eff = {"added_mass": {"added_mass": 80.0}}
    st = simulate(
        plant,
        "stiffness",
        dict(position=pos, force=f),
        baseline={"screw_modulus": 190e9},
        noise=0.01,
        seed=8,
    )
    fq = simulate(
        plant,
        "frequency",
        dict(position=np.linspace(0, 0.8, 30)),
        effects=eff,
        baseline={"screw_modulus": 190e9},
        noise=0.01,
        seed=9,
    )
    diag = diagnose([st, fq], plant)
    assert diag.verdict == "added_mass"
    assert diag.final.value("added_mass") == pytest.approx(80.0, rel=0.1)
    assert diag.final.value("screw_modulus") == pytest.approx(190e9, rel=0.03)


def test_correct_fixed_fixed_axis_names_nothing():
    d = load_design(ROOT / "problems" / "vmc_x_design.yaml")
    d = replace(d, axis=replace(d.axis, mounting="fixed-fixed"))
    plant = plant_from_design(d)
    # by hand: WBK30-DFD 1520 N/um at both ends, each in series with the default housing (26.25 x
    # the set: IBC's BSBU 35 DB 128 1050 N/um on its bare 1090 N/um set), root 34.91 mm, E 206 GPa,
    # span 1.1 m; screw torsion G pi d^4/(32 x) and the GWB AKN 60 coupling (75e3 N.m/rad) through
    # the 20 mm lead; nut at its preload (R40-20K4-FDC 0.8 x 1150 N/um x (3000/5130)^(1/3)), linear
    # at these small loads, and the default bracket (4 x 0.8 x 1150 N/um: THK's nut-mounting
    # allowance once more)
    ea = 206e9 * math.pi / 4 * 0.03491**2
    k_b, span, r2 = 1 / (1 / 1520e6 + 40 / (1050 * 1520e6)), 1.1, (0.020 / (2 * math.pi)) ** 2
    k_n = 0.8 * 1150e6 * (3000 / 5130) ** (1 / 3)
    rng = np.random.default_rng(3)
    pos, force, direction = [], [], []
    for p in np.linspace(0.0, 0.8, 9):
        for sign in (1.0, -1.0):
            loads = np.array([200.0, 400.0, 600.0, 800.0])
            seq = np.r_[loads, loads[::-1]]
            pos += [p] * len(seq)
            force += list(sign * seq)
            direction += list(sign * np.r_[np.ones(4), -np.ones(4)])
    pos, force = np.array(pos), np.array(force)
    x = 0.13 + pos
    k_sb = 1 / (1 / k_b + x / ea) + 1 / (1 / k_b + (span - x) / ea)
    c_tors = r2 * 32 * x / (79.3e9 * math.pi * 0.03491**4)
    c = 1 / k_sb + c_tors + r2 / 75e3 + 1 / k_n + 1 / (4 * 0.8 * 1150e6)
    disp = force * c * (1 + 0.005 * rng.standard_normal(len(force)))
    cols = {"position": pos, "force": force, "direction": np.array(direction), "displacement": disp}
    ds = Dataset("stiffness", "hand_two_path.csv", cols, np.arange(2, len(pos) + 2))
    diag = diagnose([ds], plant)
    assert diag.verdict == "none", [e.name for e in diag.effects]


def test_implausible_fit_is_not_accepted(plant):
    """A frequency drop that only an added mass of 3x the table could explain: added_mass is the
    only candidate, its fit leaves the plausible range (up to the table's own mass), so nothing is
    accepted and the diagnosis says what it would need."""
    m = plant.moving_mass
    ds = simulate(
        plant,
        "frequency",
        frequency_doe(),
        effects={"added_mass": {"added_mass": 3.0 * m}},
        noise=0.005,
        seed=3,
    )
    diag = diagnose([ds], plant, candidates=["added_mass"])
    assert diag.verdict == "none"
    d = diagnosis_dict(diag)
    assert d["rejected"] and d["rejected"][0]["effect"] == "added_mass"
    assert "outside" in d["rejected"][0]["would_need"][0]
    assert "not accepted" in diagnosis_text(diag)


def test_plausible_version_of_the_same_is_accepted(plant):
    """Control for the test above: the same effect at half the table's mass is accepted."""
    m = plant.moving_mass
    ds = simulate(
        plant,
        "frequency",
        frequency_doe(),
        effects={"added_mass": {"added_mass": 0.5 * m}},
        noise=0.005,
        seed=3,
    )
    diag = diagnose([ds], plant, candidates=["added_mass"])
    assert diag.verdict == "added_mass"
    assert diag.final.value("added_mass") == pytest.approx(0.5 * m, rel=0.1)


def test_torque_data_keep_their_quantity(plant, tmp_path, capsys):
    """Friction measured as screw torque: the output states the conversion and its efficiency, and
    gives the friction findings in N.m too."""
    ds = simulate(
        plant,
        "friction",
        friction_doe(),
        baseline=BASELINE["friction"],
        noise=0.01,
        seed=9,
        effects={"direction_asymmetry": {"direction_difference": 60.0}},
    )
    data = dataset_csv(
        ds, tmp_path / "torque.csv", torque_lead=plant.lead, efficiency=plant.efficiency
    )
    assert main(["diagnose", str(data), "--design", str(DESIGN)]) == 0
    out = capsys.readouterr().out
    assert (
        "drag torque T fitted as table force" in out
        and f"efficiency eta = {plant.efficiency:g}" in out
    )
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
    """FRFs at four positions with a hidden extra mode: the table gives, per position, the measured
    and the fitted resonance (they agree after the fit), the axial mode's damping as hidden, and the
    extra mode.  The measured peak moves down the stroke (a longer screw in tension is softer)."""
    from test_diagnose_recovery import frf_doe

    ds = simulate(
        plant,
        "frf",
        frf_doe(),
        baseline={"damping_ratio": 0.04},
        noise=0.01,
        seed=1,
        effects={
            "extra_mode": {"mode_frequency": 300.0, "mode_damping": 0.03, "mode_stiffness": 500e6}
        },
    )
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


# ------------------------------------------------------------------------------------ drag and
# unexplained
def test_quadratic_drag_is_named_with_its_coefficient(tmp_path, plant):
    fc = coulomb(plant)
    p = friction_table(
        tmp_path / "drag.csv",
        lambda v: np.sign(v) * fc + plant.viscous * v + 2000.0 * v * np.abs(v),
    )
    diag = diagnose([read_dataset(p)], plant)
    assert diag.verdict == "quadratic_drag"
    assert diag.final.value("drag_coefficient") == pytest.approx(2000.0, rel=0.10)
    assert not diagnosis_dict(diag)["unexplained"][0]["remaining"]


@pytest.mark.parametrize("seed", [1, 2])
def test_null_friction_table_names_nothing_and_leaves_nothing(tmp_path, plant, seed):
    fc = coulomb(plant)
    p = friction_table(
        tmp_path / "null.csv", lambda v: np.sign(v) * 1.1 * fc + plant.viscous * v, seed=seed
    )
    diag = diagnose([read_dataset(p)], plant)
    assert diag.verdict == "none"
    d = diagnosis_dict(diag)
    assert not d["unexplained"][0]["remaining"]
    text = diagnosis_text(diag)
    assert "verdict: none -- " in text and "dBIC" in text  # the reason, not a bare 'none'


def test_effects_that_only_help_together_are_found_as_a_pair(tmp_path, plant):
    """A lead-screw rig's friction curve: a direction difference, a Stribeck rise and a viscous
    slope three times the catalog's.  After the asymmetry, neither Stribeck nor viscous predicts
    held-out speed bands alone (Stribeck's held-out gain is negative); together they do."""
    fc = coulomb(plant)

    def law(v):
        return (
            np.sign(v) * (fc + 0.8 * fc * np.exp(-((v / 0.004) ** 2)))
            + 3 * plant.viscous * v
            + 0.3 * fc
        )

    diag = diagnose([read_dataset(friction_table(tmp_path / "rig.csv", law))], plant, max_effects=3)
    assert diag.verdict == "direction_asymmetry, stribeck, viscous"
    assert [a.together for a in diag.accepted] == ["", "viscous", "stribeck"]
    r2 = diag.rounds[1]
    assert all(c.reason for c in r2)  # each alone fails, with its reason
    assert any("held-out gain" in c.reason for c in r2 if c.effect.name in ("stribeck", "viscous"))
    fin = diag.final
    assert fin.value("stribeck_rise") == pytest.approx(0.8 * fc, rel=0.05)
    assert fin.value("viscous_coefficient") == pytest.approx(3 * plant.viscous, rel=0.10)
    assert fin.value("direction_difference") == pytest.approx(0.6 * fc, rel=0.05)
    assert diag.gain > 90
    assert "accepted, neither passes alone" in diagnosis_text(diag)


# --------------------------------------------------------------------------------- per-file gains,
# identifiability
def test_each_file_gets_its_own_gain(tmp_path, plant, capsys):
    """The gain quoted for one record repeated the pooled gain; each file now has its own."""
    fc = coulomb(plant)

    def law(v):
        return np.sign(v) * fc + plant.viscous * v + 2000.0 * v * np.abs(v)

    fast = friction_table(tmp_path / "fast.csv", law)
    slow = friction_table(tmp_path / "slow.csv", law, speeds=np.geomspace(0.002, 0.03, 10), seed=3)
    assert main(["diagnose", str(fast), str(slow), "--design", str(DESIGN), "--json", "-"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["verdict"] == "quadratic_drag"
    g = {Path(h["file"]).name: h["gain_percent"] for h in d["holdout_rmse_units"]}
    assert g["fast.csv"] > 50 and g["fast.csv"] - g["slow.csv"] > 10, g
    assert max(abs(v - d["gain_percent"]) for v in g.values()) > 5, (g, d["gain_percent"])


def test_single_speed_friction_reports_viscous_as_not_identifiable():
    """The shipped XJTU series is measured at one speed: a viscous slope cannot be told from the
    Coulomb level, and is printed as not identifiable rather than with a zero uncertainty."""
    plant = plant_from_design(load_design(DATA / "xjtu" / "xjtu_rig.yaml"))
    diag = diagnose([read_dataset(DATA / "xjtu" / "xjtu_up_friction.csv")], plant)
    assert diag.verdict == "preload_loss"
    d = diagnosis_dict(diag)
    visc = [
        p
        for rnd in d["candidates"]
        for c in rnd
        if c["effect"] == "viscous"
        for p in c["parameters"]
    ]
    assert visc and all(p["sigma"] is None and "not identifiable" in p["text"] for p in visc)
