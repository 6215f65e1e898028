"""Time-record identification (IDIM, LS and IV): baseline recovery, hidden effects named with their
parameters, null cases and decoys, current/torque records, bad-input one-liners.

The records come from :mod:`axisopt.identify.timesynth`, a closed-loop simulator written apart from the
identification code (PD loop, exact stick-slip, 1 um quantisation, force noise, 1 kHz)."""

import json
import math
from pathlib import Path

import numpy as np
import pytest

from axisopt.cli import main
from axisopt.design import load_design
from axisopt.errors import InputError
from axisopt.identify import plant_from_design
from axisopt.identify.idim import diagnose_time_files
from axisopt.identify.timesynth import AxisTruth, LoopSettings, simulate_axis

DESIGN = Path(__file__).resolve().parents[2] / "problems" / "data" / "table_x.yaml"
LEAD = 0.01


@pytest.fixture(scope="module")
def plant():
    p = plant_from_design(load_design(DESIGN))
    assert p.lead == LEAD and p.stroke == pytest.approx(0.8)
    return p


def records(tmp_path, truth, loop=None, seed=0, est_s=12.0, val_s=8.0, **csv):
    est, val = tmp_path / f"est{seed}.csv", tmp_path / f"val{seed}.csv"
    simulate_axis(truth, loop, duration=est_s, seed=seed).write_csv(est, **csv)
    simulate_axis(truth, loop, duration=val_s, seed=seed + 500).write_csv(val, **csv)
    return [est, val]


def baseline_truth(rng, **kw):
    sign = rng.choice([-1.0, 1.0])
    return AxisTruth(mass=rng.uniform(300, 900), viscous=rng.uniform(600, 2500), coulomb=rng.uniform(200, 600),
                     offset=sign * rng.uniform(20, 60), **kw)


def close(est, term, true, rel):
    assert est.value(term) == pytest.approx(true, rel=rel), (term, est.value(term), true)


@pytest.mark.parametrize("seed", [11, 12, 13])
def test_baseline_recovered_by_ls_and_iv_and_null_names_nothing(tmp_path, plant, seed):
    truth = baseline_truth(np.random.default_rng(seed))
    diag = diagnose_time_files(records(tmp_path, truth, seed=seed), plant=plant)
    for est in (diag.baseline_ls, diag.baseline_iv):
        close(est, "M", truth.mass, 0.10)
        close(est, "Fv", truth.viscous, 0.10)
        close(est, "Fc", truth.coulomb, 0.10)
        close(est, "offset", truth.offset, 0.10)
    assert diag.baseline_iv.converged and diag.baseline_iv.iterations >= 2
    assert diag.verdict == []
    assert diag.validation and diag.validation[0].n > 200


def _stribeck(rng):
    fs, vs = rng.uniform(80, 200), rng.uniform(0.003, 0.008)
    return dict(stribeck=fs, stribeck_v=vs), None, {"Fs": (fs, 0.10), "vs": (vs, 0.20)}


def _asym(rng):
    dfv = rng.choice([-1.0, 1.0]) * rng.uniform(400, 900)
    dfc = rng.choice([-1.0, 1.0]) * rng.uniform(20, 80)
    return dict(viscous_asym=dfv, coulomb_asym=dfc), None, {"dFv": (dfv, 0.10)}


def _position(rng):
    c = rng.choice([-1.0, 1.0], 2) * rng.uniform(80, 150, 2)
    return dict(position_coeffs=(c[0], c[1])), None, {"c1": (c[0], 0.10), "c2": (c[1], 0.10)}


def _mode(rng):
    f = rng.uniform(25, 40)
    return dict(mode_hz=f, mode_zeta=0.1, mode_mass=rng.uniform(100, 200)), LoopSettings(bandwidth_hz=3.0), \
        {"f_r": (f, 0.10)}


EFFECT_CASES = {"stribeck": _stribeck, "direction_asymmetry": _asym, "position_friction": _position,
                "extra_mode": _mode}


@pytest.mark.parametrize("name,seed", [(n, s) for n in EFFECT_CASES for s in (21, 22)])
def test_hidden_effect_named_first_with_its_parameter(tmp_path, plant, name, seed):
    rng = np.random.default_rng(seed)
    kw, loop, expect = EFFECT_CASES[name](rng)
    truth = baseline_truth(rng, **kw)
    diag = diagnose_time_files(records(tmp_path, truth, loop, seed=seed), plant=plant)
    assert diag.verdict and diag.verdict[0] == name, diag.verdict
    assert diag.accepted[0].gain >= 30.0
    fin = diag.final
    assert fin.method == "IV"
    for term, (true, rel) in expect.items():
        got = fin.shape["vs"] if term == "vs" else (
            math.sqrt(fin.value("M") / fin.value("beta")) / (2 * math.pi) if term == "f_r" else fin.value(term))
        assert got == pytest.approx(true, rel=rel), (term, got, true)
    close(fin, "M", truth.mass, 0.10)
    if name == "direction_asymmetry":  # the Coulomb half-difference is a constant while moving: in the offset
        close(fin, "offset", truth.offset + truth.coulomb_asym / 2, 0.10)


def test_decoy_offset_is_not_an_asymmetry(tmp_path, plant):
    truth = AxisTruth(offset=150.0)
    diag = diagnose_time_files(records(tmp_path, truth, seed=31), plant=plant)
    assert diag.verdict == []
    close(diag.final, "offset", 150.0, 0.05)


def test_decoy_strong_viscous_is_not_stribeck(tmp_path, plant):
    truth = AxisTruth(viscous=5000.0, coulomb=150.0)
    diag = diagnose_time_files(records(tmp_path, truth, seed=32), plant=plant)
    assert "stribeck" not in diag.verdict
    assert diag.verdict == []
    close(diag.final, "Fv", 5000.0, 0.05)


def test_decoy_stribeck_is_not_viscous_or_position(tmp_path, plant):
    truth = AxisTruth(stribeck=120.0, stribeck_v=0.02, viscous=800.0)  # slow decay over the speed range
    diag = diagnose_time_files(records(tmp_path, truth, seed=33), plant=plant, max_effects=2)
    assert diag.verdict == ["stribeck"]
    close(diag.final, "Fv", 800.0, 0.10)


def test_current_record_with_gain_reports_motor_side_and_table_equivalents(tmp_path, plant, capsys):
    truth = AxisTruth(mass=500.0, viscous=1200.0, coulomb=300.0)
    eff = dict(effort="current", lead=LEAD, efficiency=plant.efficiency, gain=0.85, position_unit="rad")
    est, val = records(tmp_path, truth, seed=41, est_s=10.0, val_s=6.0, **eff)
    out = tmp_path / "d.json"
    assert main(["diagnose", str(est), str(val), "--design", str(DESIGN), "--json", str(out)]) == 0
    text = capsys.readouterr().out
    assert "torque data" in text and "table side through lead 10 mm" in text
    d = json.loads(out.read_text())
    assert d["quantity"] == "torque"
    par = {p["name"]: p for p in d["baseline"]["IV"]["parameters"]}
    assert par["J"]["unit"] == "kg.m^2" and par["Fc"]["unit"] == "N.m"
    g = 2 * math.pi / LEAD
    assert par["J"]["value"] * g * g * plant.efficiency == pytest.approx(500.0, rel=0.10)
    assert par["Fc"]["value"] * g * plant.efficiency == pytest.approx(300.0, rel=0.10)
    # the same record with its gain line removed and the gain given on the command line
    for p in (est, val):
        p.write_text("\n".join(p.read_text().splitlines()[1:]) + "\n")
    assert main(["diagnose", str(est), str(val), "--design", str(DESIGN), "--gain", "0.85 N.m/A", "--json",
                 str(out)]) == 0
    d2 = json.loads(out.read_text())
    assert d2["baseline"]["IV"]["parameters"][0]["value"] == pytest.approx(par["J"]["value"], rel=1e-9)


def test_without_reference_iv_uses_delayed_regressors(tmp_path, plant):
    truth = AxisTruth(mass=400.0, viscous=900.0, coulomb=250.0)
    paths = records(tmp_path, truth, seed=51, columns=("time", "position", "force"))
    diag = diagnose_time_files(paths, plant=plant)
    assert diag.controller is None and "delayed-regressor" in diag.baseline_iv.note
    close(diag.baseline_iv, "M", 400.0, 0.10)
    close(diag.baseline_iv, "Fc", 250.0, 0.10)


# ------------------------------------------------------------------------------------------- bad input
def _good(tmp_path, name="g.csv", n=400, header="time [s],position [mm],force [N]", pre=""):
    t = np.arange(n) / 1000.0
    x = 100 + 20 * np.sin(2 * np.pi * t)
    f = 50 * np.cos(2 * np.pi * t)
    body = "\n".join(f"{a:.4f},{b:.5f},{c:.4f}" for a, b, c in zip(t, x, f))
    p = tmp_path / name
    p.write_text(pre + header + "\n" + body + "\n")
    return p


def _edit(p, line, text):
    lines = p.read_text().splitlines()
    lines[line - 1] = text
    p.write_text("\n".join(lines) + "\n")
    return p


@pytest.mark.parametrize(
    "make,where,what",
    [
        (lambda d: _edit(_good(d), 51, "0.0100,100.1,3"), "line 51, column 1 (time)", "does not increase"),
        (lambda d: _edit(_good(d), 7, "0.0050,nan,3"), "line 7, column 2 (position)", "not a finite number"),
        (lambda d: _good(d, n=150), "g.csv", "150 samples; a time record needs at least 200"),
        (lambda d: _good(d, header="time [s],position [mm],current [A]"), "line 1, column 3", "needs a gain"),
        (lambda d: _good(d, header="time [s],position [mm],current [A]", pre="# gain: 0.85 N.m\n"), "line 1",
         "unit per ampere"),
        (lambda d: _good(d, header="time [s],position [mm],force [N],speed [mm/s]"), "line 1, column 4",
         "unknown column 'speed'"),
        (lambda d: _edit(_good(d), 9, "0.0070,1e308,3"), "line 9, column 2 (position)", "out of range"),
        (lambda d: _edit(_good(d), 12, "0.0100,100,-1e300"), "line 12, column 3 (force)", "out of range"),
    ],
)
def test_bad_input_is_one_line_naming_file_line_column(tmp_path, capsys, make, where, what):
    p = make(tmp_path)
    assert main(["diagnose", str(p), "--design", str(DESIGN)]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and str(p) in err and where in err and what in err, err


def test_malformed_gain_is_refused_on_any_record(tmp_path, capsys):
    """--gain is read only for current records, but a malformed one is still an error, not ignored."""
    assert main(["diagnose", str(_good(tmp_path)), "--design", str(DESIGN), "--gain", "abc"]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and "--gain" in err and "unit per ampere" in err, err


def test_validation_run_with_other_columns_is_refused(tmp_path, capsys):
    est = _good(tmp_path, "est.csv")
    val = _good(tmp_path, "val.csv", header="time [s],position [mm],torque [N.m]")
    assert main(["diagnose", str(est), str(val), "--design", str(DESIGN)]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and str(val) in err and "column 3" in err and "est.csv" in err, err


def test_reader_errors_are_input_errors(tmp_path, plant):
    p = _edit(_good(tmp_path), 3, "0.0010,100,")
    with pytest.raises(InputError, match="line 3, column 3 .force.: empty cell"):
        diagnose_time_files([p], plant=plant)


def test_implausible_time_effect_is_not_accepted(tmp_path, plant):
    """Friction that *drops* at low speed (a negative Stribeck excess, -40 % of Coulomb) fits the Stribeck
    term only with Fs < 0, outside its physical range: with Stribeck the only candidate, nothing is accepted
    and the output says what it would need.  Control: the same record with a positive excess is accepted."""
    rng = np.random.default_rng(7)
    base = dict(mass=500.0, viscous=1200.0, coulomb=400.0, offset=20.0)
    bad = AxisTruth(**base, stribeck=-160.0, stribeck_v=0.005)
    diag = diagnose_time_files(records(tmp_path, bad, seed=int(rng.integers(100))), plant=plant,
                               candidates=["stribeck"])
    assert diag.verdict == []
    assert diag.rejected and diag.rejected[0][1].effect.name == "stribeck" and "Fs" in diag.rejected[0][2]
    good = AxisTruth(**base, stribeck=160.0, stribeck_v=0.005)
    diag = diagnose_time_files(records(tmp_path, good, seed=3), plant=plant, candidates=["stribeck"])
    assert diag.verdict == ["stribeck"]
