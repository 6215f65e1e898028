"""Diagnose, third stage (issue 28): effects the library lacked (a ripple at the lead, a quadratic drag), the
'unexplained' verdict with the residual's signature when the data hold an effect the library does not have,
the true reason for every candidate not accepted, baseline plausibility, the external-force column and
revolution units.

The records come from :mod:`axisopt.identify.timesynth`, the closed-loop simulator written apart from the
identification (its ripple is ``sin(2 pi x / period + phase)`` on the simulated table, its drag ``c v|v|``);
nothing here builds data with the effect columns of the time-record effects (:mod:`axisopt.identify.effects`)."""

import json
import math
from pathlib import Path

import numpy as np
import pytest

from axisopt.cli import main
from axisopt.design import load_design
from axisopt.identify import plant_from_design
from axisopt.identify.estimators import Estimate
from axisopt.identify.idim import baseline_flags, diagnose_time_files
from axisopt.identify.timeresidual import analyse_residual
from axisopt.identify.timesynth import AxisTruth, simulate_axis
from axisopt.report.timediag import time_diagnosis_dict, time_diagnosis_text

DESIGN = Path(__file__).resolve().parents[2] / "problems" / "data" / "table_x.yaml"
LEAD = 0.01
LIBRARY_BEFORE = ["stribeck", "direction_asymmetry", "position_friction", "extra_mode"]


@pytest.fixture(scope="module")
def plant():
    return plant_from_design(load_design(DESIGN))


def truth_for(seed, **kw):
    rng = np.random.default_rng(seed)
    sign = rng.choice([-1.0, 1.0])
    return AxisTruth(mass=rng.uniform(300, 900), viscous=rng.uniform(600, 2500), coulomb=rng.uniform(200, 600),
                     offset=sign * rng.uniform(20, 60), **kw)


def records(tmp_path, truth, seed, **csv):
    est, val = tmp_path / f"est{seed}.csv", tmp_path / f"val{seed}.csv"
    simulate_axis(truth, duration=12.0, seed=seed).write_csv(est, **csv)
    simulate_axis(truth, duration=8.0, seed=seed + 500).write_csv(val, **csv)
    return [est, val]


def unexplained(diag):
    return time_diagnosis_dict(diag)["unexplained"]


# ------------------------------------------------------------------------------ the effects the library lacked
@pytest.mark.parametrize("seed", [1, 2, 3, 4])
def test_lead_ripple_is_named_not_an_extra_mode(tmp_path, plant, seed):
    """A 40 N force ripple with the lead's period (sin(2 pi x / lead)) was named extra_mode in 3 of 4 seeds."""
    truth = truth_for(seed, ripple=40.0, ripple_period=LEAD, ripple_phase=0.7 * seed)
    diag = diagnose_time_files(records(tmp_path, truth, seed), plant=plant)
    assert diag.verdict and diag.verdict[0] == "lead_ripple", diag.verdict
    assert "extra_mode" not in diag.verdict
    fin = diag.final
    assert fin.shape["period"] == pytest.approx(LEAD)
    assert math.hypot(fin.value("rs"), fin.value("rc")) == pytest.approx(40.0, rel=0.10)
    assert math.hypot(fin.value("ks"), fin.value("kc")) < 6.0  # a force, not a friction ripple
    assert diag.accepted[0].gain >= 30.0
    assert not unexplained(diag)["remaining"]


def test_friction_ripple_at_half_the_lead(tmp_path, plant):
    """A friction ripple (follows sgn v) at the second harmonic of the lead: the same effect, its friction
    columns, period lead/2."""
    truth = truth_for(5, ripple=50.0, ripple_period=LEAD / 2, ripple_friction=True)
    diag = diagnose_time_files(records(tmp_path, truth, 5), plant=plant)
    assert diag.verdict[:1] == ["lead_ripple"], diag.verdict
    fin = diag.final
    assert fin.shape["period"] == pytest.approx(LEAD / 2)
    assert math.hypot(fin.value("ks"), fin.value("kc")) == pytest.approx(50.0, rel=0.10)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_quadratic_drag_is_named_not_asymmetry_or_position(tmp_path, plant, seed):
    """A symmetric c v|v| drag was named direction_asymmetry or position_friction, or nothing while the force
    error stayed at 6-9 %."""
    c = 3000.0 * (1 + 0.3 * seed)
    diag = diagnose_time_files(records(tmp_path, truth_for(seed, quadratic_drag=c), seed), plant=plant)
    assert diag.verdict[:1] == ["quadratic_drag"], diag.verdict
    assert not {"direction_asymmetry", "position_friction"} & set(diag.verdict)
    assert diag.final.value("Cq") == pytest.approx(c, rel=0.10)
    assert not unexplained(diag)["remaining"]


# ------------------------------------------------------------------------------------- the unexplained verdict
def test_drag_outside_the_library_is_unexplained_with_its_signature(tmp_path, plant):
    """With the library as it was (no quadratic drag), the verdict says a misfit remains and that it grows
    with v|v|; and the reason for naming nothing is the true one (here Stribeck fits only with an excess
    beyond its range), not 'no effect lowers BIC'."""
    truth = truth_for(2, quadratic_drag=3000.0)
    diag = diagnose_time_files(records(tmp_path, truth, 2), plant=plant, candidates=LIBRARY_BEFORE)
    un = unexplained(diag)
    assert un["remaining"]
    sig = un["signatures"][0]
    assert sig["kind"] == "velocity" and "grows with v|v|" in sig["signature"]
    assert "quadratic drag" in sig["causes"] and sig["share"] > 0.5
    text = time_diagnosis_text(diag)
    assert "unexplained:" in text and "grows with v|v|" in text
    assert "no effect lowers BIC" not in text
    for c in diag.rounds[0]:
        assert c.reason  # every candidate not accepted carries its reason
        if c.dbic < -10 and c.gain >= 5:
            assert c.reason.startswith("would need"), c.reason


def test_ripple_off_the_lead_is_unexplained_with_its_period(tmp_path, plant):
    """A ripple over 25 mm (a recirculation circuit of 2.5 turns) is no harmonic of the 10 mm lead: no effect
    explains it, the verdict names its period and says it is not the lead; no extra_mode."""
    truth = truth_for(3, ripple=40.0, ripple_period=0.025)
    diag = diagnose_time_files(records(tmp_path, truth, 3), plant=plant)
    assert "extra_mode" not in diag.verdict and "lead_ripple" not in diag.verdict
    un = unexplained(diag)
    assert un["remaining"]
    sig = un["signatures"][0]
    assert sig["kind"] == "position_periodic"
    assert sig["period_mm"] == pytest.approx(25.0, rel=0.02)
    assert "the lead is 10 mm" in sig["signature"] and sig["share"] > 0.5


def test_ripple_at_the_lead_outside_the_library_names_the_lead(tmp_path, plant):
    truth = truth_for(4, ripple=40.0, ripple_period=LEAD)
    diag = diagnose_time_files(records(tmp_path, truth, 4), plant=plant, candidates=LIBRARY_BEFORE)
    assert "extra_mode" not in diag.verdict  # the spectral peak follows the position
    sig = unexplained(diag)["signatures"][0]
    assert sig["kind"] == "position_periodic" and "period 10.0 mm = the lead" in sig["signature"]
    assert "lead error or ball recirculation" in sig["causes"]


@pytest.mark.parametrize("seed", [11, 12, 13])
def test_null_names_nothing_and_leaves_nothing_unexplained(tmp_path, plant, seed):
    diag = diagnose_time_files(records(tmp_path, truth_for(seed), seed), plant=plant)
    assert diag.verdict == []
    un = unexplained(diag)
    assert not un["remaining"] and un["signatures"] == []
    assert un["rms"] < 1.6 * un["noise_floor"]
    assert "residual: no structure beyond noise" in time_diagnosis_text(diag)


def test_existing_effect_leaves_nothing_unexplained(tmp_path, plant):
    truth = truth_for(21, stribeck=150.0, stribeck_v=0.005)
    diag = diagnose_time_files(records(tmp_path, truth, 21), plant=plant)
    assert diag.verdict == ["stribeck"]
    assert not unexplained(diag)["remaining"]


def test_residual_tests_are_quiet_on_white_noise(tmp_path, plant):
    """The structure tests on the final fit of a null record find no signature at the 1e-8 level."""
    diag = diagnose_time_files(records(tmp_path, truth_for(14), 14), plant=plant)
    u = analyse_residual([diag.estimation] + diag.validation, diag.final)
    assert all(p.log10_p > -8 for p in u.probes), [(p.kind, p.log10_p) for p in u.probes]


# ----------------------------------------------------------------------------------------------- plausibility
def test_sign_flipped_effort_is_flagged_not_reported_as_a_fit(tmp_path, plant):
    """A force column recorded with the wrong sign gives a negative mass and Coulomb friction: flagged with an
    explanation, never printed as a plain fit."""
    rec = simulate_axis(truth_for(6), duration=8.0, seed=6)
    rec.force = -rec.force
    path = tmp_path / "flipped.csv"
    rec.write_csv(path)
    diag = diagnose_time_files([path], plant=plant)
    flags = " ".join(diag.flags["baseline"])
    assert "M = " in flags and "not positive" in flags and "Fc = " in flags
    assert "! M = " in time_diagnosis_text(diag)


def test_degenerate_term_is_unidentifiable_not_zero_uncertainty():
    est = Estimate("LS", ("M", "Fv", "Fc", "offset"), np.array([500.0, 1000.0, 300.0, 1.0]),
                   np.array([1.0, 0.0, 400.0, 0.5]), {}, 1.0, 100)
    flags = baseline_flags(est, "force")
    assert any(f.startswith("Fv is not identifiable") and "zero" in f for f in flags)
    assert any(f.startswith("Fc = 300 ± 400 N is not identifiable") for f in flags)


# --------------------------------------------------------------------------------------------------- inputs
def test_external_force_column_is_used_in_the_dynamics(tmp_path, plant):
    """A process force of up to 300 N on the table: with the column the baseline is recovered and nothing is
    named; without it the fit is far worse."""
    truth = AxisTruth(mass=500.0, viscous=1200.0, coulomb=300.0, offset=20.0, process_force=300.0)
    cols = ("time", "position", "force", "reference", "external_force")
    paths = records(tmp_path, truth, 7, columns=cols)
    diag = diagnose_time_files(paths, plant=plant)
    for term, true in (("M", 500.0), ("Fv", 1200.0), ("Fc", 300.0)):
        assert diag.final.value(term) == pytest.approx(true, rel=0.05), term
    assert diag.verdict == []
    bare = tmp_path / "bare.csv"
    simulate_axis(truth, duration=12.0, seed=7).write_csv(bare)
    without = diagnose_time_files([bare], plant=plant, candidates=["stribeck"])
    with_col = diagnose_time_files(paths[:1], plant=plant, candidates=["stribeck"])
    from axisopt.identify.estimators import rel_error

    assert rel_error(without.estimation, without.baseline_ls) > 3 * rel_error(with_col.estimation,
                                                                                 with_col.baseline_ls)


def test_external_force_on_a_torque_record(tmp_path, plant):
    truth = AxisTruth(mass=500.0, viscous=1200.0, coulomb=300.0, process_force=300.0)
    path = tmp_path / "torque.csv"
    rec = simulate_axis(truth, duration=12.0, seed=8)
    rec.write_csv(path, columns=("time", "position", "force", "reference", "external_force"), effort="torque",
                  lead=LEAD, efficiency=plant.efficiency, position_unit="rad")
    diag = diagnose_time_files([path], plant=plant)
    g = 2 * math.pi / LEAD
    assert diag.final.value("M") * g * g * plant.efficiency == pytest.approx(500.0, rel=0.05)
    assert diag.final.value("Fc") * g * plant.efficiency == pytest.approx(300.0, rel=0.05)


def _rewrite(src, dst, header=None, cell=None):
    lines = src.read_text().splitlines()
    if header:
        lines[0] = header
    if cell:
        row, col, val = cell
        cells = lines[row].split(",")
        cells[col] = val
        lines[row] = ",".join(cells)
    dst.write_text("\n".join(lines) + "\n")


@pytest.mark.parametrize("header,cell,what", [
    ("time [s],position [mm],force [N],reference [mm],external_force [mm]", None,
     "line 1, column 5.*not a unit of force"),
    (None, (3, 4, "abc"), "line 4, column 5 .external_force.: 'abc' is not a number"),
    (None, (3, 4, ""), "line 4, column 5 .external_force.: empty cell"),
])
def test_bad_external_force_is_one_line_exit_2(tmp_path, capsys, header, cell, what):
    import re

    truth = AxisTruth(process_force=100.0)
    src = tmp_path / "src.csv"
    simulate_axis(truth, duration=1.0, seed=1).write_csv(src, columns=("time", "position", "force", "reference",
                                                                       "external_force"))
    bad = tmp_path / "bad.csv"
    _rewrite(src, bad, header, cell)
    assert main(["diagnose", str(bad), "--design", str(DESIGN)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and re.search(what, err), err


def test_position_in_revolutions_is_accepted(tmp_path, plant):
    """The README lists [rev] for a motor-angle position: read like [rad], through the lead."""
    rec = simulate_axis(truth_for(9), duration=8.0, seed=9)
    rad, rev = tmp_path / "rad.csv", tmp_path / "rev.csv"
    rec.write_csv(rad, position_unit="rad")
    lines = rad.read_text().splitlines()
    head = lines[0].replace("position [rad]", "position [rev]").replace("reference [rad]", "reference [rev]")
    rows = []
    for ln in lines[1:]:
        c = ln.split(",")
        c[1], c[3] = f"{float(c[1]) / (2 * math.pi):.8g}", f"{float(c[3]) / (2 * math.pi):.8g}"
        rows.append(",".join(c))
    rev.write_text("\n".join([head] + rows) + "\n")
    a = diagnose_time_files([rad], plant=plant, candidates=["stribeck"])
    b = diagnose_time_files([rev], plant=plant, candidates=["stribeck"])
    assert b.baseline_ls.value("M") == pytest.approx(a.baseline_ls.value("M"), rel=1e-3)


def test_json_carries_the_unexplained_verdict(tmp_path, plant, capsys):
    truth = truth_for(3, ripple=40.0, ripple_period=0.025)
    paths = records(tmp_path, truth, 3)
    assert main(["diagnose", *map(str, paths), "--design", str(DESIGN), "--json", "-"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["unexplained"]["remaining"] and d["unexplained"]["signatures"][0]["kind"] == "position_periodic"
    assert all(c["reason"] for c in d["not_accepted"])


def test_external_force_at_the_wrong_scale_leaves_a_load_signature(tmp_path, plant):
    """An external_force column recorded at half its true value: the misfit follows the process force, and the
    verdict says so (whatever else is fitted)."""
    truth = AxisTruth(mass=500.0, viscous=1200.0, coulomb=300.0, offset=20.0, process_force=300.0)
    rec = simulate_axis(truth, duration=12.0, seed=7)
    rec.extra["external_force"] = 0.5 * rec.extra["external_force"]
    path = tmp_path / "half.csv"
    rec.write_csv(path, columns=("time", "position", "force", "reference", "external_force"))
    un = unexplained(diagnose_time_files([path], plant=plant))
    assert un["remaining"] and un["signatures"][0]["kind"] == "load"
    assert "external force" in un["signatures"][0]["signature"]
